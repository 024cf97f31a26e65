/* modeswalk.c -- the kinematically feasible modes, output-sensitively: the
   faces of the arrangement of the planes J_k . nu = 0 that lie in the
   cone of non-penetrating twists.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The 2n forms v_k = J_k . nu cut R^3 into relatively open faces (the
   origin, rays, arcs of a plane between consecutive rays, chambers); a
   mode is feasible iff some face maps to it, and only faces in

       K = { nu : v_in >= 0 for every touching fixel }

   map to a mode at all.  K is a union of faces (its facets lie on the
   planes), so each face lies in K or outside it.  A plane that meets K
   only at the origin keeps one strict sign on K minus the origin, read
   once at a generator of K; only the planes meeting K beyond the origin
   ("relevant" ones) cut K into faces, and inside K the faces of the whole
   arrangement are those of the relevant planes: a ray inside K lies on a
   relevant plane.  So the walk goes around the relevant planes only,
   among the relevant planes' lines only, and reports the faces inside K.

   What it reports, and in which order, is what the walk of every plane
   (exact/arrangement.c, and the previous implementation kept in
   tests/old-modes.c)
   reports inside K, so that each mode keeps the witness of the first
   face mapping to it there: the origin first; then plane by plane in the
   order of the columns; around plane p counter-clockwise from the
   canonical direction u of its line with plane 0 (plane 1 for plane 0),
   each arc, then the chambers on its - and + sides, then the ray ending
   it; a sector's point is the sum of its two rays, and a chamber's steps
   off it by less than any form allows (chamber_witness).  A face is in K
   iff it penetrates no touching fixel over the relevant planes (the
   relevant half-spaces cut out K unless K is a single ray, where the
   walk tests the face against it).  When K is a line, K minus the origin
   is two rays, on which no sign need be constant: their modes are read
   off directly.

   Cost: one conversion of the n touching rows, O(g) per plane for K's g
   generators, O(L (L log L + R)) for L relevant planes of R columns (when
   K is pointed with few rays, only the lines entering the plane's part
   of K are sorted), O(n) per new mode and O(|D|) per face in K (below).  */

#include <config.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_mat.h>

#include "core/error.h"
#include "core/problem.h"
#include "core/tick.h"
#include "exact/vec3.h"
#include "exact/hash.h"
#include "exact/zvec3set.h"
#include "exact/arrangement.h"
#include "exact/cone.h"
#include "analysis/kinematics.h"
#include "analysis/modeswalk.h"

/* ---------------------------------------------------------------------
   The set of modes found so far.  Most faces inside K repeat a mode found
   before, so the lookup must not read all n letters: a mode is keyed by
   where it differs from a fixed string base (the letters once the signs
   that are constant on K are set), and the walk keeps the current face's
   difference set D and its hash (the exclusive or of a key per fixel and
   letter) up to date one letter at a time.  A stored mode equals the
   current letters iff it has as many differences as D and agrees with
   them on D: a lookup costs O(|D|).  */

typedef struct
{
    slong n;            /* letters per mode */
    slong size;         /* slots, a power of two */
    slong count;
    slong * slot;
    char * letters;     /* count x (n + 1) */
    uint64_t * hash;    /* count: of the differences from base */
    slong * ndiff;      /* count: how many */
    fmpz_mat_t wit;     /* count x 3 */
    slong alloc;
}
mode_set;

static void
mode_set_init(mode_set * S, slong n)
{
    slong i;

    S->n = n;
    S->size = 64;
    S->count = 0;
    S->alloc = 32;
    S->slot = flint_malloc(sizeof(slong) * S->size);
    for (i = 0; i < S->size; i++)
        S->slot[i] = -1;
    S->letters = flint_malloc(S->alloc * (n + 1));
    S->hash = flint_malloc(sizeof(uint64_t) * S->alloc);
    S->ndiff = flint_malloc(sizeof(slong) * S->alloc);
    fmpz_mat_init(S->wit, S->alloc, 3);
}

static void
mode_set_clear(mode_set * S)
{
    flint_free(S->slot);
    flint_free(S->letters);
    flint_free(S->hash);
    flint_free(S->ndiff);
    fmpz_mat_clear(S->wit);
}

/* The key of letter c at fixel i.  */
static uint64_t
letter_key(slong i, char c)
{
    return _wc_hash_mix64(((uint64_t) i << 8) ^ (unsigned char) c
                          ^ UINT64_C(0x9e3779b97f4a7c15));
}

/* The slot of the mode with hash h, nd differences from base at the
   fixels diff[0 .. nd) where it reads cur: holding it, or empty.  */
static slong
mode_set_find(const mode_set * S, uint64_t h, slong nd, const slong * diff,
              const char * cur)
{
    slong i = (slong) (h & (uint64_t) (S->size - 1)), j;

    for (; S->slot[i] >= 0; i = (i + 1) & (S->size - 1))
    {
        slong m = S->slot[i];
        const char * s = S->letters + m * (S->n + 1);

        if (S->hash[m] != h || S->ndiff[m] != nd)
            continue;
        for (j = 0; j < nd && s[diff[j]] == cur[diff[j]]; j++)
            ;
        if (j == nd)
            break;
    }
    return i;
}

/* The slot of stored mode m (present): by its number.  */
static slong
mode_set_slot_of(const mode_set * S, slong m)
{
    slong i = (slong) (S->hash[m] & (uint64_t) (S->size - 1));

    while (S->slot[i] >= 0 && S->slot[i] != m)
        i = (i + 1) & (S->size - 1);
    return i;
}

/* Add s (known to be new) with witness w; base gives its key.  */
static void
mode_set_add(mode_set * S, const char * s, const char * base,
             const fmpz * w)
{
    slong i, m = S->count;
    uint64_t h = 0;
    slong nd = 0;

    if (S->count == S->alloc)
    {
        fmpz_mat_t big;

        S->alloc *= 2;
        S->letters = flint_realloc(S->letters, S->alloc * (S->n + 1));
        S->hash = flint_realloc(S->hash, sizeof(uint64_t) * S->alloc);
        S->ndiff = flint_realloc(S->ndiff, sizeof(slong) * S->alloc);
        fmpz_mat_init(big, S->alloc, 3);
        for (i = 0; i < S->count; i++)
            _fmpz_vec_set(WC_ROW(big, i), WC_ROW(S->wit, i), 3);
        fmpz_mat_swap(big, S->wit);
        fmpz_mat_clear(big);
    }
    for (i = 0; i < S->n; i++)
        if (s[i] != base[i])
        {
            h ^= letter_key(i, s[i]);
            nd++;
        }
    memcpy(S->letters + m * (S->n + 1), s, S->n);
    S->letters[m * (S->n + 1) + S->n] = '\0';
    S->hash[m] = h;
    S->ndiff[m] = nd;
    _fmpz_vec_set(WC_ROW(S->wit, m), w, 3);
    S->count++;
    if (2 * S->count > S->size)
    {
        S->size *= 2;
        S->slot = flint_realloc(S->slot, sizeof(slong) * S->size);
        for (i = 0; i < S->size; i++)
            S->slot[i] = -1;
        for (i = 0; i < S->count - 1; i++)
            S->slot[mode_set_slot_of(S, i)] = i;
    }
    S->slot[mode_set_slot_of(S, m)] = m;
}

typedef struct
{
    const char * s;
    slong i;
}
mode_ref;

static int
mode_ref_cmp(const void * p, const void * q)
{
    return strcmp(((const mode_ref *) p)->s, ((const mode_ref *) q)->s);
}

/* M := the modes of S, sorted.  */
static void
modes_sorted(wc_modes_t M, const mode_set * S)
{
    slong n = S->n, i;
    mode_ref * ref = flint_malloc(sizeof(mode_ref) * (S->count + 1));

    for (i = 0; i < S->count; i++)
    {
        ref[i].s = S->letters + i * (n + 1);
        ref[i].i = i;
    }
    qsort(ref, S->count, sizeof(mode_ref), mode_ref_cmp);
    wc_modes_clear(M);
    M->n = n;
    M->count = S->count;
    M->modes = malloc(sizeof(char *) * (S->count + 1));
    fmpz_mat_clear(M->witness);
    fmpz_mat_init(M->witness, S->count, 3);
    for (i = 0; i < S->count; i++)
    {
        M->modes[i] = malloc(n + 1);
        memcpy(M->modes[i], ref[i].s, n + 1);
        _fmpz_vec_set(WC_ROW(M->witness, i), WC_ROW(S->wit, ref[i].i), 3);
    }
    flint_free(ref);
}

/* ---------------------------------------------------------------------
   The state.  */

/* A line on the current plane, from one relevant plane q through it: its
   canonical direction d and its coordinates (x, y) in the plane's basis
   (u, w), turned into y > 0 or y = 0 < x (o = -1 when turned).  */
typedef struct
{
    fmpz_t x;
    fmpz_t y;
    fmpz * d;
    slong q;
    int o;
}
line_ref;

typedef struct
{
    const wc_problem_struct * P;
    slong n;
    fmpz_mat_t a;                   /* 2n columns, primitive */
    int * sgnf;                     /* 2n: column k is sgnf[k] h_plane */
    slong * coff;                   /* the columns of plane q are */
    slong * col;                    /* col[coff[q] .. coff[q + 1]) */
    fmpz_mat_t planes;              /* the distinct planes, canonical */
    slong np;
    wc_cone_t K;                    /* the non-penetrating twists */
    int kray;                       /* K is one ray: test faces on it */
    slong * rl;                     /* the relevant planes, ascending */
    slong nrl;
    int * sg;                       /* 2n: signs at the current face */
    char * cur;                     /* n letters and a NUL */
    slong pen;                      /* touching fixels with v_in < 0 */
    mode_set S;
    char * base;                    /* n: the letters keys are taken from */
    int track;                      /* keep diff and hash up to date */
    slong * diff;                   /* the fixels where cur != base */
    slong * dpos;                   /* n: i's place in diff, or -1 */
    slong ndiff;
    uint64_t hash;
    line_ref * ln;                  /* nrl: the lines on the plane */
    fmpz * dirs;                    /* 3 nrl */
    slong * goff;                   /* lines: ln[goff[g] .. goff[g + 1]) */
    slong k;                        /* lines on the current plane */
    int fast;                       /* K pointed, 3-D, few rays */
    int sect;                       /* fast: p meets K in the ray b1 (1)
                                       or the sector b1 .. b2 (2) */
    fmpz * b1, * b2;
    unsigned char * keep;           /* np: fast, the plane's line on p
                                       enters the sector */
    fmpz * vecs;                    /* 24: the vectors below */
    fmpz * u, * w, * mid, * ray, * wit, * ray3, * cand;
    const fmpz * hcur;
    slong ncand;
    fmpz_t t;
}
kwalk;

/* Letter i changes from c to d: the difference set and its hash.  */
static void
track_letter(kwalk * W, slong i, char c, char d)
{
    if (c != W->base[i])
        W->hash ^= letter_key(i, c);
    else
    {
        W->dpos[i] = W->ndiff;
        W->diff[W->ndiff++] = i;
    }
    if (d != W->base[i])
        W->hash ^= letter_key(i, d);
    else
    {
        slong last = W->diff[--W->ndiff];

        W->diff[W->dpos[i]] = last;
        W->dpos[last] = W->dpos[i];
        W->dpos[i] = -1;
    }
}

static void
set_letter(kwalk * W, slong i)
{
    int sn = W->sg[i], st = W->sg[W->n + i];
    char c = W->cur[i];
    int was = c == '-';

    if (W->P->fixels[i].state == WC_NEAR)
        W->cur[i] = sn < 0 ? 'a' : 's';
    else if (sn < 0)
        W->cur[i] = '-';
    else if (sn > 0)
        W->cur[i] = 's';
    else
        W->cur[i] = st > 0 ? 'l' : st < 0 ? 'r' : 'n';
    W->pen += (W->cur[i] == '-') - was;
    if (W->track && W->cur[i] != c)
        track_letter(W, i, c, W->cur[i]);
}

/* Plane q takes sign s (its columns sgnf s).  */
static void
plane_sign(kwalk * W, slong q, int s)
{
    slong j;

    for (j = W->coff[q]; j < W->coff[q + 1]; j++)
    {
        slong k = W->col[j];

        W->sg[k] = W->sgnf[k] * s;
        set_letter(W, k % W->n);
    }
}

static void
plane_sign_at(kwalk * W, slong q, const fmpz * x)
{
    plane_sign(W, q, _wc_zvec3_dot_sgn_fast(WC_ROW(W->planes, q), x, W->t));
}

/* The forms of W->a grouped by plane (ids by first column).  */
static void
group_planes(kwalk * W)
{
    slong K = 2 * W->n, k;
    slong * plane_of = flint_malloc(sizeof(slong) * (K + 1));
    fmpz * v = _fmpz_vec_init(3);
    _wc_zvec3_set_t H;

    _wc_zvec3_set_init(H, K);
    for (k = 0; k < K; k++)
    {
        _fmpz_vec_set(v, WC_ROW(W->a, k), 3);
        W->sgnf[k] = _wc_zvec3_canonical(v, W->t) < 0 ? -1 : 1;
        plane_of[k] = _wc_zvec3_set_id(H, v);
    }
    W->np = H->count;
    fmpz_mat_clear(W->planes);
    fmpz_mat_init(W->planes, W->np, 3);
    for (k = 0; k < W->np; k++)
        _fmpz_vec_set(WC_ROW(W->planes, k), _wc_zvec3_set_entry(H, k), 3);
    W->coff = flint_calloc(W->np + 2, sizeof(slong));
    for (k = 0; k < K; k++)
        W->coff[plane_of[k] + 2]++;
    for (k = 0; k < W->np; k++)
        W->coff[k + 2] += W->coff[k + 1];
    for (k = 0; k < K; k++)
        W->col[W->coff[plane_of[k] + 1]++] = k;
    flint_free(plane_of);
    _fmpz_vec_clear(v, 3);
    _wc_zvec3_set_clear(H);
}

/* K := { nu : v_in >= 0, touching }, as rows -J_in . nu <= 0.  */
static int
make_cone(kwalk * W, wc_error_t err)
{
    slong n = W->n, i, m = 0, j;
    fmpq_mat_t H;
    int status;

    for (i = 0; i < n; i++)
        m += W->P->fixels[i].state != WC_NEAR;
    fmpq_mat_init(H, m, 3);
    for (i = 0, m = 0; i < n; i++)
        if (W->P->fixels[i].state != WC_NEAR)
        {
            for (j = 0; j < 3; j++)
            {
                fmpz_neg(fmpq_mat_entry_num(H, m, j),
                         fmpz_mat_entry(W->a, i, j));
                fmpz_one(fmpq_mat_entry_den(H, m, j));
            }
            m++;
        }
    status = wc_cone_set_hrep(W->K, NULL, H, NULL, err);
    fmpq_mat_clear(H);
    W->kray = status == WC_OK && W->K->dim == 1 && W->K->lineality_dim == 0;
    return status;
}

/* Whether plane h meets K beyond the origin: K is generated by its rays
   and its lines both ways; h meets it iff some generator lies on h, or
   two on opposite sides are not a line's two directions.  */
static int
meets_cone(kwalk * W, const fmpz * h)
{
    const wc_cone_struct * K = W->K;
    slong nr = fmpz_mat_nrows(K->rays), nl = fmpz_mat_nrows(K->lines), i;
    slong pos = 0, neg = 0;
    int s;

    for (i = 0; i < nr; i++)
    {
        s = _wc_zvec3_dot_sgn_fast(h, WC_ROW(K->rays, i), W->t);
        if (s == 0)
            return 1;
        pos += s > 0;
        neg += s < 0;
        if (pos > 0 && neg > 0)
            return 1;       /* two rays: never a line's two directions */
    }
    for (i = 0; i < nl; i++)
    {
        s = _wc_zvec3_dot_sgn_fast(h, WC_ROW(K->lines, i), W->t);
        if (s == 0)
            return 1;
        pos++;
        neg++;
    }
    /* pos, neg >= 1 here from lines alone, or a ray and a line */
    return pos > 0 && neg > 0 && (nr > 0 || nl > 1);
}

/* The relevant planes, and every other plane's sign on K minus 0 (read
   at a generator of K) in sg.  */
static void
find_relevant(kwalk * W)
{
    const wc_cone_struct * K = W->K;
    const fmpz * g = NULL;
    slong q;

    if (fmpz_mat_nrows(K->rays) > 0)
        g = WC_ROW(K->rays, 0);
    else if (fmpz_mat_nrows(K->lines) > 0)
        g = WC_ROW(K->lines, 0);
    W->rl = flint_malloc(sizeof(slong) * (W->np + 1));
    W->nrl = 0;
    for (q = 0; q < W->np && g != NULL; q++)
    {
        if (meets_cone(W, WC_ROW(W->planes, q)))
            W->rl[W->nrl++] = q;
        else
            plane_sign_at(W, q, g);
    }
}

static void
kwalk_init(kwalk * W, const wc_problem_t P)
{
    slong n = P->n, K = 2 * n, i;

    W->P = P;
    W->n = n;
    fmpz_mat_init(W->a, K, 3);
    _wc_modes_columns(W->a, P);
    W->sgnf = flint_malloc(sizeof(int) * (K + 1));
    W->col = flint_malloc(sizeof(slong) * (K + 1));
    W->coff = NULL;
    fmpz_mat_init(W->planes, 0, 3);
    wc_cone_init(W->K, 3);
    W->rl = NULL;
    W->nrl = 0;
    W->sg = flint_calloc(K + 1, sizeof(int));
    W->cur = flint_malloc(n + 1);
    for (i = 0; i < n; i++)
        W->cur[i] = P->fixels[i].state == WC_NEAR ? 's' : 'n';
    W->cur[n] = '\0';
    W->pen = 0;
    mode_set_init(&W->S, n);
    W->base = flint_malloc(n + 1);
    W->track = 0;
    W->diff = flint_malloc(sizeof(slong) * (n + 1));
    W->dpos = flint_malloc(sizeof(slong) * (n + 1));
    for (i = 0; i < n; i++)
        W->dpos[i] = -1;
    W->ndiff = 0;
    W->hash = 0;
    W->ln = NULL;
    W->dirs = NULL;
    W->goff = NULL;
    W->k = 0;
    W->vecs = _fmpz_vec_init(24);
    W->u = W->vecs;
    W->w = W->vecs + 3;
    W->mid = W->vecs + 6;
    W->ray = W->vecs + 9;
    W->ray3 = W->vecs + 12;
    W->wit = W->vecs + 15;
    W->b1 = W->vecs + 18;
    W->b2 = W->vecs + 21;
    W->fast = 0;
    W->sect = 0;
    W->keep = NULL;
    W->cand = NULL;
    W->hcur = NULL;
    fmpz_init(W->t);
    group_planes(W);
}

static void
kwalk_clear(kwalk * W)
{
    slong i;

    if (W->ln != NULL)
        for (i = 0; i < W->nrl; i++)
        {
            fmpz_clear(W->ln[i].x);
            fmpz_clear(W->ln[i].y);
        }
    flint_free(W->ln);
    if (W->dirs != NULL)
        _fmpz_vec_clear(W->dirs, 3 * W->nrl + 1);
    flint_free(W->goff);
    fmpz_mat_clear(W->a);
    flint_free(W->sgnf);
    flint_free(W->coff);
    flint_free(W->col);
    fmpz_mat_clear(W->planes);
    wc_cone_clear(W->K);
    flint_free(W->rl);
    flint_free(W->sg);
    flint_free(W->cur);
    mode_set_clear(&W->S);
    flint_free(W->base);
    flint_free(W->keep);
    flint_free(W->diff);
    flint_free(W->dpos);
    if (W->cand != NULL)
        _fmpz_vec_clear(W->cand, W->ncand);
    _fmpz_vec_clear(W->vecs, 24);
    fmpz_clear(W->t);
}

/* ---------------------------------------------------------------------
   Faces.  */

/* Witness of a chamber beside the arc with point m on the plane of
   normal h: m + side t h with t below every |a_k . m| / |a_k . h| (every
   column, relevant or not), so that no sign of m changes but those of the
   plane's own columns.  */
static void
chamber_witness(fmpz * w, kwalk * W, const fmpz * m, const fmpz * h, int side)
{
    slong K = fmpz_mat_nrows(W->a), k;
    fmpz_t num, den, am, ah, c1, c2;

    fmpz_init(num);
    fmpz_init(den);
    fmpz_init(am);
    fmpz_init(ah);
    fmpz_init(c1);
    fmpz_init(c2);
    fmpz_one(num);              /* t = num / den, start at 1 */
    fmpz_one(den);
    for (k = 0; k < K; k++)
    {
        _fmpz_vec_dot(am, WC_ROW(W->a, k), m, 3);
        _fmpz_vec_dot(ah, WC_ROW(W->a, k), h, 3);
        if (fmpz_is_zero(am) || fmpz_is_zero(ah))
            continue;
        fmpz_abs(am, am);
        fmpz_abs(ah, ah);
        fmpz_mul_ui(ah, ah, 2);
        fmpz_mul(c1, am, den);
        fmpz_mul(c2, num, ah);
        if (fmpz_cmp(c1, c2) < 0)
        {
            fmpz_set(num, am);
            fmpz_set(den, ah);
        }
    }
    for (k = 0; k < 3; k++)
    {
        fmpz_mul(w + k, m + k, den);
        fmpz_mul(c1, h + k, num);
        if (side > 0)
            fmpz_add(w + k, w + k, c1);
        else
            fmpz_sub(w + k, w + k, c1);
    }
    _wc_zvec3_primitive(w, W->t);
    fmpz_clear(num);
    fmpz_clear(den);
    fmpz_clear(am);
    fmpz_clear(ah);
    fmpz_clear(c1);
    fmpz_clear(c2);
}

/* Whether x, a point of a face penetrating no touching fixel over the
   relevant planes, lies in K: always, unless K is a single ray.  */
static int
in_cone(kwalk * W, const fmpz * x)
{
    fmpz * c;
    int on;

    if (!W->kray)
        return 1;
    c = _fmpz_vec_init(3);
    _wc_zvec3_cross(c, x, WC_ROW(W->K->rays, 0));
    on = _fmpz_vec_is_zero(c, 3)
        && _wc_zvec3_dot_sgn_fast(x, WC_ROW(W->K->rays, 0), W->t) > 0;
    _fmpz_vec_clear(c, 3);
    return on;
}

/* det(h, a, b) = h . (a x b), its sign.  */
static int
det_sgn(kwalk * W, const fmpz * h, const fmpz * a, const fmpz * b)
{
    _wc_zvec3_cross(W->ray3, a, b);
    return _wc_zvec3_dot_sgn_fast(h, W->ray3, W->t);
}

/* Fast path: whether x (nonzero, on the current plane h) lies in the
   plane's part of K, the ray b1 or the sector from b1 to b2 (below pi,
   counter-clockwise seen from h).  */
static int
in_sector(kwalk * W, const fmpz * x)
{
    const fmpz * h = W->hcur;

    if (W->sect == 1)
    {
        _wc_zvec3_cross(W->ray3, W->b1, x);
        return _fmpz_vec_is_zero(W->ray3, 3)
            && _wc_zvec3_dot_sgn_fast(W->b1, x, W->t) > 0;
    }
    return det_sgn(W, h, W->b1, x) >= 0 && det_sgn(W, h, x, W->b2) >= 0;
}

/* Fast path: the part of K on plane p, from K's rays: the rays on p and
   the points where p crosses the segment of two rays on either side; b1
   and b2 are the extreme ones (K is pointed, so the part is {0}, a ray
   or a sector below pi).  Sets W->sect.  */
static void
sector_of(kwalk * W, slong p)
{
    const fmpz * h = WC_ROW(W->planes, p);
    const fmpz_mat_struct * R = W->K->rays;
    slong nr = fmpz_mat_nrows(R), i, j, nc = 0;
    fmpz * c = W->cand;
    fmpz_t si, sj;
    int first;

    fmpz_init(si);
    fmpz_init(sj);
    for (i = 0; i < nr; i++)
    {
        _fmpz_vec_dot(si, h, WC_ROW(R, i), 3);
        if (fmpz_is_zero(si))
            _fmpz_vec_set(c + 3 * nc++, WC_ROW(R, i), 3);
        else if (fmpz_sgn(si) > 0)
            for (j = 0; j < nr; j++)
            {
                _fmpz_vec_dot(sj, h, WC_ROW(R, j), 3);
                if (fmpz_sgn(sj) >= 0)
                    continue;
                /* si r_j - sj r_i: on p, a positive combination */
                _fmpz_vec_scalar_mul_fmpz(c + 3 * nc, WC_ROW(R, j), 3, si);
                _fmpz_vec_scalar_submul_fmpz(c + 3 * nc, WC_ROW(R, i), 3,
                                             sj);
                _wc_zvec3_primitive(c + 3 * nc, W->t);
                nc++;
            }
    }
    W->sect = 0;
    for (i = 0, first = 1; i < nc; i++)
    {
        if (first || det_sgn(W, h, c + 3 * i, W->b1) > 0)
            _fmpz_vec_set(W->b1, c + 3 * i, 3);
        if (first || det_sgn(W, h, W->b2, c + 3 * i) > 0)
            _fmpz_vec_set(W->b2, c + 3 * i, 3);
        first = 0;
    }
    if (nc > 0)
    {
        _wc_zvec3_cross(W->ray3, W->b1, W->b2);
        W->sect = _fmpz_vec_is_zero(W->ray3, 3) ? 1 : 2;
    }
    fmpz_clear(si);
    fmpz_clear(sj);
}

/* The current face, of dimension dim with point x (for a chamber: the
   point of the sector beside it on plane h, on side side): its mode when
   it lies in K and the mode is new.  */
static void
report(kwalk * W, int dim, const fmpz * x, const fmpz * h, int side)
{
    if (W->pen != 0 || (W->sect && !in_sector(W, x))
        || W->S.slot[mode_set_find(&W->S, W->hash, W->ndiff, W->diff,
                                   W->cur)] >= 0
        || !in_cone(W, x))
        return;
    if (dim == 3)
    {
        chamber_witness(W->wit, W, x, h, side);
        mode_set_add(&W->S, W->cur, W->base, W->wit);
    }
    else
        mode_set_add(&W->S, W->cur, W->base, x);
}

/* ---------------------------------------------------------------------
   Around one relevant plane.  */

/* By angle in [0, pi), then by plane.  */
static int
line_cmp(const void * p, const void * q)
{
    const line_ref * a = p, * b = q;
    int s = _wc_angle_cmp(a->x, a->y, b->x, b->y);

    return s != 0 ? s : (a->q > b->q) - (a->q < b->q);
}

/* The lines of the relevant planes on plane p, in angular order from u,
   the canonical direction of p's line with plane 0 (1 for plane 0).  */
static void
sort_lines(kwalk * W, slong p)
{
    const fmpz * h = WC_ROW(W->planes, p);
    slong i, c = 0, g;

    _wc_zvec3_cross(W->u, h, WC_ROW(W->planes, p == 0 ? 1 : 0));
    _wc_zvec3_canonical(W->u, W->t);
    _wc_zvec3_cross(W->w, h, W->u);
    for (i = 0; i < W->nrl; i++)
    {
        line_ref * r = W->ln + c;

        if (W->rl[i] == p)
            continue;
        if (W->sect)
        {
            const fmpz * hq = WC_ROW(W->planes, W->rl[i]);
            int s1 = _wc_zvec3_dot_sgn_fast(hq, W->b1, W->t);
            int s2 = _wc_zvec3_dot_sgn_fast(hq, W->b2, W->t);

            W->keep[W->rl[i]] = s1 * s2 <= 0;
            if (!W->keep[W->rl[i]])
                continue;
        }
        _wc_zvec3_cross(r->d, h, WC_ROW(W->planes, W->rl[i]));
        _wc_zvec3_canonical(r->d, W->t);
        _fmpz_vec_dot(r->x, r->d, W->u, 3);
        _fmpz_vec_dot(r->y, r->d, W->w, 3);
        r->q = W->rl[i];
        r->o = 1;
        if (fmpz_sgn(r->y) < 0 || (fmpz_is_zero(r->y) && fmpz_sgn(r->x) < 0))
        {
            fmpz_neg(r->x, r->x);
            fmpz_neg(r->y, r->y);
            r->o = -1;
        }
        c++;
    }
    qsort(W->ln, c, sizeof(line_ref), line_cmp);
    for (i = 0, g = 0; i < c; i++)
    {
        if (i > 0)
        {
            fmpz_mul(W->t, W->ln[i - 1].x, W->ln[i].y);
            fmpz_submul(W->t, W->ln[i - 1].y, W->ln[i].x);
            if (fmpz_is_zero(W->t))
                continue;
        }
        W->goff[g++] = i;
    }
    W->goff[g] = c;
    W->k = g;
}

/* v := ray j of the current plane (0 <= j < 2k).  */
static void
ray_vector(fmpz * v, const kwalk * W, slong j)
{
    const line_ref * r = W->ln + W->goff[j % W->k];
    int o = j < W->k ? r->o : -r->o;

    _fmpz_vec_scalar_mul_si(v, r->d, 3, o);
}

/* x := the point of arc j, from ray j to ray j + 1.  */
static void
arc_point(fmpz * x, kwalk * W, slong p, slong j)
{
    ray_vector(x, W, j);
    if (W->k == 1)
    {
        _wc_zvec3_cross(W->ray, WC_ROW(W->planes, p), x);
        _fmpz_vec_set(x, W->ray, 3);
    }
    else
    {
        ray_vector(W->ray, W, (j + 1) % (2 * W->k));
        _fmpz_vec_add(x, x, W->ray, 3);
    }
    _wc_zvec3_primitive(x, W->t);
}

/* The planes of line g but p take sign 0, or their sign at x.  */
static void
line_planes(kwalk * W, slong g, const fmpz * x)
{
    slong i;

    for (i = W->goff[g]; i < W->goff[g + 1]; i++)
        if (x == NULL)
            plane_sign(W, W->ln[i].q, 0);
        else
            plane_sign_at(W, W->ln[i].q, x);
}

/* Ray j: its planes zero, reported, then their signs on arc j.  */
static void
cross_ray(kwalk * W, slong p, slong j)
{
    line_planes(W, j % W->k, NULL);
    ray_vector(W->ray, W, j);
    report(W, 1, W->ray, NULL, 0);
    if (j < 2 * W->k)
    {
        arc_point(W->mid, W, p, j);
        line_planes(W, j % W->k, W->mid);
    }
}

static void
walk_plane(kwalk * W, slong p)
{
    const fmpz * h = WC_ROW(W->planes, p);
    slong i, j;
    int ustart;

    W->hcur = h;
    W->sect = 0;
    if (W->fast)
    {
        sector_of(W, p);
        if (W->sect == 0)
            return;
    }
    sort_lines(W, p);
    if (W->k == 0)
        return;
    ustart = fmpz_is_zero(W->ln[0].y);
    arc_point(W->mid, W, p, 0);
    /* the planes whose line on p misses p's part of K: their sign on it */
    _fmpz_vec_add(W->ray, W->b1, W->b2, 3);
    for (i = 0; i < W->nrl; i++)
        if (W->sect && !W->keep[W->rl[i]] && W->rl[i] != p)
            plane_sign_at(W, W->rl[i], W->ray);
        else
            plane_sign_at(W, W->rl[i], W->mid);
    for (j = 0; j < 2 * W->k; j++)
    {
        if (j > 0 || !ustart)
            cross_ray(W, p, j);
        if (W->pen == 0)
        {
            report(W, 2, W->mid, h, 0);
            plane_sign(W, p, -1);
            report(W, 3, W->mid, h, -1);
            plane_sign(W, p, 1);
            report(W, 3, W->mid, h, 1);
            plane_sign(W, p, 0);
        }
    }
    if (ustart)
    {
        line_planes(W, 0, NULL);
        ray_vector(W->ray, W, 0);
        report(W, 1, W->ray, NULL, 0);
    }
}

/* K a line: K minus 0 is two rays, faces of their own, where no sign is
   constant; their modes are read off directly (they differ unless every
   form vanishes on the line, when both are the origin's mode).  */
static void
walk_line(kwalk * W)
{
    slong q;
    int s;

    for (s = 1; s >= -1; s -= 2)
    {
        _fmpz_vec_set(W->ray, WC_ROW(W->K->lines, 0), 3);
        _wc_zvec3_canonical(W->ray, W->t);
        _fmpz_vec_scalar_mul_si(W->ray, W->ray, 3, s);
        for (q = 0; q < W->np; q++)
            plane_sign_at(W, q, W->ray);
        report(W, 1, W->ray, NULL, 0);
    }
}

int
_wc_modes_walk(wc_modes_t M, const wc_problem_t P, wc_error_t err)
{
    kwalk W;
    slong i;
    int status;

    kwalk_init(&W, P);
    status = make_cone(&W, err);
    if (status == WC_OK)
    {
        char * origin = flint_malloc(W.n + 1);
        int line = W.K->dim == 1 && W.K->lineality_dim == 1;

        /* the origin first; keys from the letters once the constant signs
           are set */
        memcpy(origin, W.cur, W.n + 1);
        if (!line)
            find_relevant(&W);
        memcpy(W.base, W.cur, W.n + 1);
        W.track = 1;
        mode_set_add(&W.S, origin, W.base, W.ray);
        flint_free(origin);
        if (line)
            walk_line(&W);
        W.ncand = fmpz_mat_nrows(W.K->rays);
        W.ncand = 3 * (W.ncand * W.ncand + 1);
        W.fast = W.K->dim == 3 && W.K->lineality_dim == 0
            && fmpz_mat_nrows(W.K->rays) <= 32;
        if (W.fast)
        {
            W.cand = _fmpz_vec_init(W.ncand);
            W.keep = flint_calloc(W.np + 1, 1);
        }
        W.ln = flint_malloc(sizeof(line_ref) * (W.nrl + 1));
        W.dirs = _fmpz_vec_init(3 * W.nrl + 1);
        W.goff = flint_malloc(sizeof(slong) * (W.nrl + 2));
        for (i = 0; i < W.nrl; i++)
        {
            fmpz_init(W.ln[i].x);
            fmpz_init(W.ln[i].y);
            W.ln[i].d = W.dirs + 3 * i;
        }
        for (i = 0; i < W.nrl; i++)
        {
            _wc_tick("modes planes", i, W.nrl);
            walk_plane(&W, W.rl[i]);
        }
        _wc_tick("modes planes", W.nrl, W.nrl);
        modes_sorted(M, &W.S);
    }
    kwalk_clear(&W);
    return status;
}
