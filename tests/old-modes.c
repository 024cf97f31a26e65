/* old-modes.c -- the previous implementation of mode enumeration
   (wc_modes_enumerate), kept to catch regressions; not an independent
   reference.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The enumeration the library used before it walked only the faces
   inside the cone of non-penetrating twists (lib/analysis/modeswalk.c),
   line for line: it walks every face of the whole arrangement with the
   library's own exact/arrangement.c, maps each non-penetrating face to
   its mode, and keeps the witness of the first face of each mode.  It
   shares the arrangement walk and helpers with lib/ (and held a verbatim
   copy of chamber_witness), so it checks that the faster walk still gives
   the same modes and the same witnesses (t-modeswalk), and is the
   "before" of bench/bench-modes; it cannot find an error the two share.
   The independent reference is ref-modes.c.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "core/error.h"
#include "core/problem.h"
#include "model/model.h"
#include "exact/vec3.h"
#include "exact/hash.h"
#include "exact/zvec3set.h"
#include "exact/arrangement.h"
#include "analysis/kinematics.h"
#include "old-modes.h"

/* v (len entries) := the primitive integer vector on the ray of x.  */
static void
fmpq_vec_primitive(fmpz * v, const fmpq * x, slong len)
{
    fmpz_t den, c;
    slong j;

    fmpz_init(den);
    fmpz_init(c);
    fmpz_one(den);
    for (j = 0; j < len; j++)
        fmpz_lcm(den, den, fmpq_denref(x + j));
    for (j = 0; j < len; j++)
    {
        fmpz_divexact(c, den, fmpq_denref(x + j));
        fmpz_mul(v + j, fmpq_numref(x + j), c);
    }
    _fmpz_vec_content(c, v, len);
    if (!fmpz_is_zero(c))
        _fmpz_vec_scalar_divexact_fmpz(v, v, len, c);
    fmpz_clear(den);
    fmpz_clear(c);
}

/* a (2n x 3): row k is J's column k as a primitive integer vector.  */
static void
columns(fmpz_mat_t a, const wc_problem_t P)
{
    slong K = 2 * P->n, k;
    fmpq_mat_t J, Jt;

    fmpq_mat_init(J, 3, K);
    fmpq_mat_init(Jt, K, 3);
    wc_model_J(J, P);
    fmpq_mat_transpose(Jt, J);
    for (k = 0; k < K; k++)
        fmpq_vec_primitive(WC_ROW(a, k), WC_ROW(Jt, k), 3);
    fmpq_mat_clear(J);
    fmpq_mat_clear(Jt);
}

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

/* ---------------------------------------------------------------------
   The walk over the faces.  */

/* The walk's state: the signs of the 2n forms at the current face, the
   mode letters they give, and how many touching fixels they penetrate;
   all kept up to date one sign at a time.  The forms are the columns of
   J, each a sign times the canonical normal of its plane.  */
typedef struct
{
    const wc_problem_struct * P;
    slong n;
    fmpz_mat_t a;                   /* 2n columns, primitive */
    int * sgnf;                     /* 2n: column k is sgnf[k] h_plane */
    slong * coff;                   /* the columns of plane q are */
    slong * col;                    /* col[coff[q] .. coff[q + 1]) */
    fmpz_mat_t planes;              /* the distinct planes, canonical */
    int * sg;
    char * cur;                     /* n letters and a NUL */
    slong pen;                      /* touching fixels with v_in < 0 */
    mode_set S;
    fmpz * wit;
    fmpz_t t;
}
walk;

/* The forms of W->a grouped by plane.  */
static void
walk_planes(walk * W)
{
    slong K = 2 * W->n, np, k;
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
    np = H->count;
    fmpz_mat_clear(W->planes);
    fmpz_mat_init(W->planes, np, 3);
    for (k = 0; k < np; k++)
        _fmpz_vec_set(WC_ROW(W->planes, k), _wc_zvec3_set_entry(H, k), 3);
    W->coff = flint_calloc(np + 2, sizeof(slong));
    for (k = 0; k < K; k++)
        W->coff[plane_of[k] + 2]++;
    for (k = 0; k < np; k++)
        W->coff[k + 2] += W->coff[k + 1];
    for (k = 0; k < K; k++)
        W->col[W->coff[plane_of[k] + 1]++] = k;
    flint_free(plane_of);
    _fmpz_vec_clear(v, 3);
    _wc_zvec3_set_clear(H);
}

static void
walk_init(walk * W, const wc_problem_t P)
{
    slong n = P->n, K = 2 * n;

    W->P = P;
    W->n = n;
    fmpz_mat_init(W->a, K, 3);
    columns(W->a, P);
    W->sgnf = flint_malloc(sizeof(int) * (K + 1));
    W->col = flint_malloc(sizeof(slong) * (K + 1));
    fmpz_mat_init(W->planes, 0, 3);
    W->sg = flint_calloc(K + 1, sizeof(int));
    W->cur = flint_malloc(n + 1);
    memset(W->cur, ' ', n);
    W->cur[n] = '\0';
    W->pen = 0;
    mode_set_init(&W->S, n);
    W->wit = _fmpz_vec_init(3);
    fmpz_init(W->t);
    walk_planes(W);
}

static void
walk_clear(walk * W)
{
    fmpz_mat_clear(W->a);
    flint_free(W->sgnf);
    flint_free(W->coff);
    flint_free(W->col);
    fmpz_mat_clear(W->planes);
    flint_free(W->sg);
    flint_free(W->cur);
    mode_set_clear(&W->S);
    _fmpz_vec_clear(W->wit, 3);
    fmpz_clear(W->t);
}

static void
set_letter(walk * W, slong i)
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

static void
set_sign(walk * W, slong k, int s)
{
    W->sg[k] = s;
    set_letter(W, k % W->n);
}

/* Witness of a chamber beside the arc with point m on the plane of
   normal h: m + side t h with t below every |a_k . m| / |a_k . h|, so
   that no sign of m changes but those of the plane's own columns.  */
static void
chamber_witness(fmpz * w, walk * W, const fmpz * m, const fmpz * h, int side)
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

/* A face of the arrangement: update the forms of the planes whose sign
   changed; a face that penetrates no touching fixel and has a new mode
   adds it.  Only the non-penetrating faces pay for the lookup.  */
static int
visit_face(void * data, const _wc_face_struct * F, wc_error_t err)
{
    walk * W = data;
    slong i, j;

    (void) err;
    for (i = 0; i < F->nchanged; i++)
    {
        slong q = F->changed[i];

        for (j = W->coff[q]; j < W->coff[q + 1]; j++)
            set_sign(W, W->col[j], W->sgnf[W->col[j]] * F->sign[q]);
    }
    if (W->pen != 0 || W->S.slot[mode_set_find(&W->S, W->cur)] >= 0)
        return WC_OK;
    if (F->dim == 3)
    {
        chamber_witness(W->wit, W, F->point, F->normal, F->side);
        mode_set_add(&W->S, W->cur, W->wit);
    }
    else
        mode_set_add(&W->S, W->cur, F->point);
    return WC_OK;
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

/* The walk of arrangement.c over the planes of the columns of J: every
   plane holds at least one line (the two columns of a fixel are never
   parallel).  */
int
old_modes_walk(wc_modes_t M, const wc_problem_t P, wc_error_t err)
{
    _wc_arrangement_t R;
    walk W;
    int status;

    walk_init(&W, P);
    status = _wc_arrangement_init(R, W.planes, err);
    if (status == WC_OK)
        status = _wc_arrangement_walk(R, visit_face, &W, err);
    if (status == WC_OK)
        modes_sorted(M, &W.S);
    _wc_arrangement_clear(R);
    walk_clear(&W);
    return status;
}

