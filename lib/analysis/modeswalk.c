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
   (exact/arrangement.c, and the independent copy tests/ref-modes.c)
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

   Cost: one cone conversion of the n touching rows, then O(g) per plane
   for g generators of K, then O(L (L log L + R)) for L relevant planes of
   R columns, and O(n) per face inside K for the lookup of its mode.  */

#include <config.h>

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
#include "exact/cone.h"
#include "analysis/kinematics.h"
#include "analysis/modeswalk.h"

/* ---------------------------------------------------------------------
   The set of modes found so far: open addressing on the mode strings.  */

typedef struct
{
    slong n;            /* letters per mode */
    slong size;         /* slots, a power of two */
    slong count;
    slong * slot;
    char * letters;     /* count x (n + 1) */
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
    fmpz_mat_init(S->wit, S->alloc, 3);
}

static void
mode_set_clear(mode_set * S)
{
    flint_free(S->slot);
    flint_free(S->letters);
    fmpz_mat_clear(S->wit);
}

/* The slot of mode s: holding it, or empty.  */
static slong
mode_set_find(const mode_set * S, const char * s)
{
    slong i = (slong) (_wc_hash_bytes((const unsigned char *) s, S->n)
                       & (S->size - 1));

    while (S->slot[i] >= 0
           && memcmp(S->letters + S->slot[i] * (S->n + 1), s, S->n) != 0)
        i = (i + 1) & (S->size - 1);
    return i;
}

/* Add s (known to be new) with witness w.  */
static void
mode_set_add(mode_set * S, const char * s, const fmpz * w)
{
    slong i;

    if (S->count == S->alloc)
    {
        fmpz_mat_t big;

        S->alloc *= 2;
        S->letters = flint_realloc(S->letters, S->alloc * (S->n + 1));
        fmpz_mat_init(big, S->alloc, 3);
        for (i = 0; i < S->count; i++)
            _fmpz_vec_set(WC_ROW(big, i), WC_ROW(S->wit, i), 3);
        fmpz_mat_swap(big, S->wit);
        fmpz_mat_clear(big);
    }
    if (2 * (S->count + 1) > S->size)
    {
        S->size *= 2;
        S->slot = flint_realloc(S->slot, sizeof(slong) * S->size);
        for (i = 0; i < S->size; i++)
            S->slot[i] = -1;
        for (i = 0; i < S->count; i++)
            S->slot[mode_set_find(S, S->letters + i * (S->n + 1))] = i;
    }
    memcpy(S->letters + S->count * (S->n + 1), s, S->n);
    S->letters[S->count * (S->n + 1) + S->n] = '\0';
    _fmpz_vec_set(WC_ROW(S->wit, S->count), w, 3);
    S->slot[mode_set_find(S, s)] = S->count;
    S->count++;
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
    unsigned char * relevant;       /* np: the plane meets K beyond 0 */
    slong * rl;                     /* the relevant planes, ascending */
    slong nrl;
    int * sg;                       /* 2n: signs at the current face */
    char * cur;                     /* n letters and a NUL */
    slong pen;                      /* touching fixels with v_in < 0 */
    mode_set S;
    line_ref * ln;                  /* nrl: the lines on the plane */
    fmpz * dirs;                    /* 3 nrl */
    slong * goff;                   /* lines: ln[goff[g] .. goff[g + 1]) */
    slong k;                        /* lines on the current plane */
    fmpz * u, * w, * mid, * ray, * wit;
    fmpz_t t;
}
kwalk;

static void
set_letter(kwalk * W, slong i)
{
    int sn = W->sg[i], st = W->sg[W->n + i];
    int was = W->cur[i] == '-';

    if (W->P->fixels[i].state == WC_NEAR)
        W->cur[i] = sn < 0 ? 'a' : 's';
    else if (sn < 0)
        W->cur[i] = '-';
    else if (sn > 0)
        W->cur[i] = 's';
    else
        W->cur[i] = st > 0 ? 'l' : st < 0 ? 'r' : 'n';
    W->pen += (W->cur[i] == '-') - was;
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
    plane_sign(W, q, _wc_zvec3_dot_sgn(WC_ROW(W->planes, q), x, W->t));
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
        s = _wc_zvec3_dot_sgn(h, WC_ROW(K->rays, i), W->t);
        if (s == 0)
            return 1;
        pos += s > 0;
        neg += s < 0;
        if (pos > 0 && neg > 0)
            return 1;       /* two rays: never a line's two directions */
    }
    for (i = 0; i < nl; i++)
    {
        s = _wc_zvec3_dot_sgn(h, WC_ROW(K->lines, i), W->t);
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
    W->relevant = flint_calloc(W->np + 1, 1);
    W->rl = flint_malloc(sizeof(slong) * (W->np + 1));
    W->nrl = 0;
    for (q = 0; q < W->np && g != NULL; q++)
    {
        if (meets_cone(W, WC_ROW(W->planes, q)))
        {
            W->relevant[q] = 1;
            W->rl[W->nrl++] = q;
        }
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
    W->relevant = NULL;
    W->rl = NULL;
    W->nrl = 0;
    W->sg = flint_calloc(K + 1, sizeof(int));
    W->cur = flint_malloc(n + 1);
    for (i = 0; i < n; i++)
        W->cur[i] = P->fixels[i].state == WC_NEAR ? 's' : 'n';
    W->cur[n] = '\0';
    W->pen = 0;
    mode_set_init(&W->S, n);
    W->ln = NULL;
    W->dirs = NULL;
    W->goff = NULL;
    W->k = 0;
    W->u = _fmpz_vec_init(3);
    W->w = _fmpz_vec_init(3);
    W->mid = _fmpz_vec_init(3);
    W->ray = _fmpz_vec_init(3);
    W->wit = _fmpz_vec_init(3);
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
    flint_free(W->relevant);
    flint_free(W->rl);
    flint_free(W->sg);
    flint_free(W->cur);
    mode_set_clear(&W->S);
    _fmpz_vec_clear(W->u, 3);
    _fmpz_vec_clear(W->w, 3);
    _fmpz_vec_clear(W->mid, 3);
    _fmpz_vec_clear(W->ray, 3);
    _fmpz_vec_clear(W->wit, 3);
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
        && _wc_zvec3_dot_sgn(x, WC_ROW(W->K->rays, 0), W->t) > 0;
    _fmpz_vec_clear(c, 3);
    return on;
}

/* The current face, of dimension dim with point x (for a chamber: the
   point of the sector beside it on plane h, on side side): its mode when
   it lies in K and the mode is new.  */
static void
report(kwalk * W, int dim, const fmpz * x, const fmpz * h, int side)
{
    if (W->pen != 0 || W->S.slot[mode_set_find(&W->S, W->cur)] >= 0
        || !in_cone(W, x))
        return;
    if (dim == 3)
    {
        chamber_witness(W->wit, W, x, h, side);
        mode_set_add(&W->S, W->cur, W->wit);
    }
    else
        mode_set_add(&W->S, W->cur, x);
}

/* ---------------------------------------------------------------------
   Around one relevant plane.  */

/* By angle in [0, pi), then by plane.  */
static int
line_cmp(const void * p, const void * q)
{
    const line_ref * a = p, * b = q;
    fmpz_t c;
    int s;

    fmpz_init(c);
    fmpz_mul(c, a->x, b->y);
    fmpz_submul(c, a->y, b->x);
    s = -fmpz_sgn(c);
    fmpz_clear(c);
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

    sort_lines(W, p);
    if (W->k == 0)
        return;
    ustart = fmpz_is_zero(W->ln[0].y);
    arc_point(W->mid, W, p, 0);
    for (i = 0; i < W->nrl; i++)
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
        /* the origin */
        mode_set_add(&W.S, W.cur, W.ray);
        if (W.K->dim == 1 && W.K->lineality_dim == 1)
            walk_line(&W);
        else
            find_relevant(&W);
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
