/* kinematics.c -- kinematically feasible modes, by the arrangement of the
   planes J_k . nu = 0, and one mode's certificate.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The 2n linear forms v_k = J_k . nu cut R^3 into relatively open cones,
   the faces of a central arrangement: the origin, the rays where two
   planes meet, the arcs of each plane between consecutive rays, and the
   chambers.  A mode's constraints are sign conditions on the v_k, so its
   feasible set is a union of faces, and it is feasible iff some face's
   sign vector maps to it.  With P distinct planes there are at most
   P (P - 1) rays, as many arcs per plane as rays on it, and two chamber
   sides per arc: O(n^2) faces.  The walk around each plane keeps the sign
   vector, the mode letters and a count of penetrated fixels up to date
   one form at a time (crossing a ray changes only the forms of the planes
   through it), so a penetrating face costs O(1) and only the others pay
   O(n) for the exact lookup of their mode: O(n^2 log n + n F) in all
   (the log from sorting each plane's rays), F the number of
   non-penetrating faces.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "core/problem.h"
#include "model/mode.h"
#include "model/model.h"
#include "exact/lp.h"
#include "exact/vec3.h"
#include "analysis/kinematics.h"

#define ROW(A, i) ((A)->rows[i])

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

int
wc_mode_constraints(fmpz_mat_t rows, wc_relation ** rel,
                    const wc_problem_t P, const char * mode, wc_error_t err)
{
    slong n = P->n, i, m = 0;
    fmpz_mat_t a, R;
    wc_relation * r;
    int status;

    *rel = NULL;
    if ((status = wc_mode_check(P, mode, WC_TABLE_KINEMATIC, err)) != WC_OK)
        return status;
    fmpz_mat_init(a, 2 * n, 3);
    fmpz_mat_init(R, 2 * n, 3);
    r = malloc(sizeof(wc_relation) * (2 * n + 1));
    columns(a, P);
#define ADD(k, sign, rl) do { \
        _fmpz_vec_scalar_mul_si(WC_ROW(R, m), WC_ROW(a, k), 3, sign); \
        r[m++] = (rl); \
    } while (0)
    for (i = 0; i < n; i++)
    {
        int near = P->fixels[i].state == WC_NEAR;

        switch (mode[i])
        {
        case 's':
            ADD(i, 1, near ? WC_REL_GE : WC_REL_GT);
            break;
        case 'a':
            ADD(i, -1, WC_REL_GT);
            break;
        case 'l':
            ADD(i, 1, WC_REL_EQ);
            ADD(n + i, 1, WC_REL_GT);
            break;
        case 'r':
            ADD(i, 1, WC_REL_EQ);
            ADD(n + i, -1, WC_REL_GT);
            break;
        default:                /* 'n' */
            ADD(i, 1, WC_REL_EQ);
            ADD(n + i, 1, WC_REL_EQ);
            break;
        }
    }
#undef ADD
    fmpz_mat_clear(rows);
    fmpz_mat_init(rows, m, 3);
    for (i = 0; i < m; i++)
        _fmpz_vec_set(WC_ROW(rows, i), WC_ROW(R, i), 3);
    *rel = r;
    fmpz_mat_clear(a);
    fmpz_mat_clear(R);
    return WC_OK;
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

static ulong
mode_hash(const char * s, slong n)
{
    ulong h = UWORD(1469598103934665603);
    slong i;

    for (i = 0; i < n; i++)
        h = (h ^ (unsigned char) s[i]) * UWORD(1099511628211);
    return h;
}

/* The slot of mode s: holding it, or empty.  */
static slong
mode_set_find(const mode_set * S, const char * s)
{
    slong i = (slong) (mode_hash(s, S->n) & (S->size - 1));

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
            _fmpz_vec_set(ROW(big, i), ROW(S->wit, i), 3);
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
    _fmpz_vec_set(ROW(S->wit, S->count), w, 3);
    S->slot[mode_set_find(S, s)] = S->count;
    S->count++;
}

static void
cross(fmpz * c, const fmpz * x, const fmpz * y)
{
    fmpz_mul(c + 0, x + 1, y + 2);
    fmpz_submul(c + 0, x + 2, y + 1);
    fmpz_mul(c + 1, x + 2, y + 0);
    fmpz_submul(c + 1, x + 0, y + 2);
    fmpz_mul(c + 2, x + 0, y + 1);
    fmpz_submul(c + 2, x + 1, y + 0);
}

/* v := the primitive vector on its ray; with canon, the first nonzero
   entry is made positive too (the same vector for v and -v), and the
   return value says whether v was negated.  */
static int
primitive(fmpz * v, fmpz_t t, int canon)
{
    slong j;

    _fmpz_vec_content(t, v, 3);
    if (!fmpz_is_zero(t))
        _fmpz_vec_scalar_divexact_fmpz(v, v, 3, t);
    if (!canon)
        return 0;
    for (j = 0; j < 2 && fmpz_is_zero(v + j); j++)
        ;
    if (fmpz_sgn(v + j) >= 0)
        return 0;
    _fmpz_vec_neg(v, v, 3);
    return 1;
}

/* A set of 3-vectors (lines or planes, canonical up to sign) with ids:
   open addressing on a hash of the entries.  */
typedef struct
{
    slong size;         /* a power of two, at least twice count */
    slong count;
    slong * slot;
    fmpz_mat_t v;       /* count rows in use */
}
vec_set;

static void
vec_set_init(vec_set * S, slong expect)
{
    slong i;

    for (S->size = 16; S->size < 2 * expect + 2; S->size *= 2)
        ;
    S->count = 0;
    S->slot = flint_malloc(sizeof(slong) * S->size);
    for (i = 0; i < S->size; i++)
        S->slot[i] = -1;
    fmpz_mat_init(S->v, expect + 1, 3);
}

static void
vec_set_clear(vec_set * S)
{
    flint_free(S->slot);
    fmpz_mat_clear(S->v);
}

/* The id of v, added when new (room for expect entries was made).  */
static slong
vec_set_id(vec_set * S, const fmpz * v)
{
    ulong h = 0;
    slong i, j;

    for (j = 0; j < 3; j++)
        h = h * UWORD(1000003) + fmpz_fdiv_ui(v + j, UWORD(4294967291));
    for (i = (slong) (h & (S->size - 1)); S->slot[i] >= 0;
         i = (i + 1) & (S->size - 1))
        if (_fmpz_vec_equal(ROW(S->v, S->slot[i]), v, 3))
            return S->slot[i];
    _fmpz_vec_set(ROW(S->v, S->count), v, 3);
    S->slot[i] = S->count;
    return S->count++;
}

/* A ray on a plane with its position around the plane's normal: half 0
   or 1 and coordinates (x, y) in an oriented basis of the plane.  */
typedef struct
{
    int half;
    fmpz_t x;
    fmpz_t y;
    slong ray;          /* 2 line + (0 for +line, 1 for -line) */
}
angle_ref;

static int
angle_cmp(const void * p, const void * q)
{
    const angle_ref * a = p, * b = q;
    fmpz_t c;
    int s;

    if (a->half != b->half)
        return a->half - b->half;
    fmpz_init(c);
    fmpz_mul(c, a->x, b->y);
    fmpz_submul(c, a->y, b->x);
    s = -fmpz_sgn(c);           /* a first when b is counter-clockwise */
    fmpz_clear(c);
    return s;
}

/* Growable lists of slong, one per index (CSR built at the end would do
   too; these stay short).  */
typedef struct
{
    slong len;
    slong alloc;
    slong * x;
}
id_list;

static void
id_push(id_list * L, slong v)
{
    if (L->len == L->alloc)
    {
        L->alloc = L->alloc ? 2 * L->alloc : 4;
        L->x = flint_realloc(L->x, sizeof(slong) * L->alloc);
    }
    L->x[L->len++] = v;
}

static int
slong_cmp(const void * p, const void * q)
{
    slong a = *(const slong *) p, b = *(const slong *) q;

    return (a > b) - (a < b);
}

static void
id_sort_unique(id_list * L)
{
    slong i, j;

    qsort(L->x, L->len, sizeof(slong), slong_cmp);
    for (i = 0, j = 0; i < L->len; i++)
        if (j == 0 || L->x[j - 1] != L->x[i])
            L->x[j++] = L->x[i];
    L->len = j;
}

/* The walk's state: the signs of the 2n forms at the current face, the
   mode letters they give, and how many touching fixels they penetrate;
   all kept up to date one sign at a time.  */
typedef struct
{
    const wc_problem_struct * P;
    slong n;
    const fmpz_mat_struct * a;      /* 2n columns, primitive */
    int * sg;
    char * cur;                     /* n letters and a NUL */
    slong pen;                      /* touching fixels with v_in < 0 */
    mode_set * S;
    fmpz_t t;
}
walk;

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

/* 1 when the current face is not penetrating and its mode is new.  */
static int
is_new(walk * W)
{
    return W->pen == 0 && W->S->slot[mode_set_find(W->S, W->cur)] < 0;
}

/* Witness of a chamber beside the arc with midpoint m on the plane of
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
        _fmpz_vec_dot(am, ROW(W->a, k), m, 3);
        _fmpz_vec_dot(ah, ROW(W->a, k), h, 3);
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
    primitive(w, W->t, 0);
    fmpz_clear(num);
    fmpz_clear(den);
    fmpz_clear(am);
    fmpz_clear(ah);
    fmpz_clear(c1);
    fmpz_clear(c2);
}

void
wc_modes_init(wc_modes_t M)
{
    M->n = 0;
    M->count = 0;
    M->modes = NULL;
    fmpz_mat_init(M->witness, 0, 3);
}

void
wc_modes_clear(wc_modes_t M)
{
    slong i;

    for (i = 0; i < M->count; i++)
        free(M->modes[i]);
    free(M->modes);
    fmpz_mat_clear(M->witness);
    wc_modes_init(M);
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

static void
enumerate(wc_modes_t M, const wc_problem_t P)
{
    slong n = P->n, K = 2 * n, np, nl, i, j, k, p, q, c, z;
    int side;
    fmpz_mat_t a;
    fmpz * v = _fmpz_vec_init(3), * u = _fmpz_vec_init(3),
        * w = _fmpz_vec_init(3), * mid = _fmpz_vec_init(3),
        * next = _fmpz_vec_init(3), * wit = _fmpz_vec_init(3);
    int * sgnf = flint_malloc(sizeof(int) * (K + 1)), * done;
    slong * plane_of = flint_malloc(sizeof(slong) * (K + 1));
    id_list * cols, * lines_on, * planes_on;
    angle_ref * ang;
    vec_set planes, lines;
    mode_set S;
    mode_ref * ref;
    walk W;

    mode_set_init(&S, n);
    fmpz_mat_init(a, K, 3);
    columns(a, P);
    W.P = P;
    W.n = n;
    W.a = a;
    W.S = &S;
    W.sg = flint_calloc(K + 1, sizeof(int));
    W.cur = flint_malloc(n + 1);
    W.cur[n] = '\0';
    W.pen = 0;
    fmpz_init(W.t);

    /* The origin: every form is zero.  */
    for (i = 0; i < n; i++)
        W.cur[i] = ' ';
    for (k = 0; k < K; k++)
        set_sign(&W, k, 0);
    if (is_new(&W))
        mode_set_add(&S, W.cur, v);

    /* Distinct planes (a column up to sign) and their columns.  */
    vec_set_init(&planes, K);
    for (k = 0; k < K; k++)
    {
        _fmpz_vec_set(v, ROW(a, k), 3);
        sgnf[k] = primitive(v, W.t, 1) ? -1 : 1;
        plane_of[k] = vec_set_id(&planes, v);
    }
    np = planes.count;
    cols = flint_calloc(np + 1, sizeof(id_list));
    for (k = 0; k < K; k++)
        id_push(cols + plane_of[k], k);

    /* Lines where planes meet (up to sign), with the planes on each line
       and the lines on each plane: O(P^2), however degenerate.  */
    vec_set_init(&lines, np * (np - 1) / 2 + 1);
    lines_on = flint_calloc(np + 1, sizeof(id_list));
    planes_on = flint_calloc(np * (np - 1) / 2 + 1, sizeof(id_list));
    for (p = 0; p < np; p++)
        for (q = p + 1; q < np; q++)
        {
            slong l;

            cross(v, ROW(planes.v, p), ROW(planes.v, q));
            primitive(v, W.t, 1);
            l = vec_set_id(&lines, v);
            id_push(lines_on + p, l);
            id_push(lines_on + q, l);
            id_push(planes_on + l, p);
            id_push(planes_on + l, q);
        }
    nl = lines.count;
    for (p = 0; p < np; p++)
        id_sort_unique(lines_on + p);
    for (i = 0; i < nl; i++)
        id_sort_unique(planes_on + i);
    done = flint_calloc(2 * nl + 1, sizeof(int));

    /* Walk around each plane: its rays in angular order, the arcs between
       them and the chambers on both sides of each arc.  Only the forms of
       the planes through a crossed ray change sign.  Every plane holds at
       least one line (the two columns of a fixel are never parallel).  */
    ang = flint_malloc(sizeof(angle_ref) * (2 * nl + 2));
    for (i = 0; i < 2 * nl + 2; i++)
    {
        fmpz_init(ang[i].x);
        fmpz_init(ang[i].y);
    }
    for (p = 0; p < np; p++)
    {
        const fmpz * h = ROW(planes.v, p);

        c = 0;
        for (i = 0; i < lines_on[p].len; i++)
        {
            ang[c++].ray = 2 * lines_on[p].x[i];
            ang[c++].ray = 2 * lines_on[p].x[i] + 1;
        }
        /* Basis (u, w = h x u) of the plane: counter-clockwise seen from
           h.  */
        _fmpz_vec_set(u, ROW(lines.v, lines_on[p].x[0]), 3);
        cross(w, h, u);
        for (i = 0; i < c; i++)
        {
            const fmpz * r = ROW(lines.v, ang[i].ray / 2);
            int s = (ang[i].ray & 1) ? -1 : 1;

            _fmpz_vec_dot(ang[i].x, r, u, 3);
            _fmpz_vec_dot(ang[i].y, r, w, 3);
            fmpz_mul_si(ang[i].x, ang[i].x, s);
            fmpz_mul_si(ang[i].y, ang[i].y, s);
            ang[i].half = !(fmpz_sgn(ang[i].y) > 0
                            || (fmpz_is_zero(ang[i].y) && fmpz_sgn(ang[i].x) > 0));
        }
        qsort(ang, c, sizeof(angle_ref), angle_cmp);

        for (i = 0; i < c; i++)
        {
            /* mid: a point of arc i, from ray i to ray i + 1.  */
            if (c == 2)
                _fmpz_vec_scalar_mul_si(mid, w, 3, i == 0 ? 1 : -1);
            else
            {
                _fmpz_vec_scalar_mul_si(mid, ROW(lines.v, ang[i].ray / 2), 3,
                                        (ang[i].ray & 1) ? -1 : 1);
                z = ang[(i + 1) % c].ray;
                _fmpz_vec_scalar_addmul_si(mid, ROW(lines.v, z / 2), 3,
                                           (z & 1) ? -1 : 1);
            }
            primitive(mid, W.t, 0);
            if (i == 0)
                for (k = 0; k < K; k++)
                {
                    _fmpz_vec_dot(W.t, ROW(a, k), mid, 3);
                    set_sign(&W, k, fmpz_sgn(W.t));
                }
            if (is_new(&W))
                mode_set_add(&S, W.cur, mid);
            /* The chambers: the plane's own forms leave zero.  */
            for (side = -1; side <= 1; side += 2)
            {
                for (j = 0; j < cols[p].len; j++)
                    set_sign(&W, cols[p].x[j], side * sgnf[cols[p].x[j]]);
                if (is_new(&W))
                {
                    chamber_witness(wit, &W, mid, h, side);
                    mode_set_add(&S, W.cur, wit);
                }
            }
            for (j = 0; j < cols[p].len; j++)
                set_sign(&W, cols[p].x[j], 0);
            if (i + 1 == c)
                break;
            /* Cross ray i + 1: the forms of the planes through it are zero
               there, then take their signs on the next arc.  */
            z = ang[i + 1].ray;
            _fmpz_vec_scalar_mul_si(v, ROW(lines.v, z / 2), 3, (z & 1) ? -1 : 1);
            for (j = 0; j < planes_on[z / 2].len; j++)
            {
                if ((q = planes_on[z / 2].x[j]) == p)
                    continue;
                for (k = 0; k < cols[q].len; k++)
                    set_sign(&W, cols[q].x[k], 0);
            }
            if (!done[z])
            {
                done[z] = 1;
                if (is_new(&W))
                    mode_set_add(&S, W.cur, v);
            }
            if (c == 2)
                _fmpz_vec_scalar_mul_si(next, w, 3, -1);
            else
            {
                _fmpz_vec_set(next, v, 3);
                q = ang[(i + 2) % c].ray;
                _fmpz_vec_scalar_addmul_si(next, ROW(lines.v, q / 2), 3,
                                           (q & 1) ? -1 : 1);
            }
            for (j = 0; j < planes_on[z / 2].len; j++)
            {
                if ((q = planes_on[z / 2].x[j]) == p)
                    continue;
                for (k = 0; k < cols[q].len; k++)
                {
                    _fmpz_vec_dot(W.t, ROW(a, cols[q].x[k]), next, 3);
                    set_sign(&W, cols[q].x[k], fmpz_sgn(W.t));
                }
            }
        }
        /* Ray 0 of this plane, met only as a start: record it too.  */
        z = ang[0].ray;
        if (!done[z])
        {
            done[z] = 1;
            _fmpz_vec_scalar_mul_si(v, ROW(lines.v, z / 2), 3, (z & 1) ? -1 : 1);
            for (k = 0; k < K; k++)
            {
                _fmpz_vec_dot(W.t, ROW(a, k), v, 3);
                set_sign(&W, k, fmpz_sgn(W.t));
            }
            if (is_new(&W))
                mode_set_add(&S, W.cur, v);
        }
    }

    /* Sorted output.  */
    ref = flint_malloc(sizeof(mode_ref) * (S.count + 1));
    for (i = 0; i < S.count; i++)
    {
        ref[i].s = S.letters + i * (n + 1);
        ref[i].i = i;
    }
    qsort(ref, S.count, sizeof(mode_ref), mode_ref_cmp);
    wc_modes_clear(M);
    M->n = n;
    M->count = S.count;
    M->modes = malloc(sizeof(char *) * (S.count + 1));
    fmpz_mat_clear(M->witness);
    fmpz_mat_init(M->witness, S.count, 3);
    for (i = 0; i < S.count; i++)
    {
        M->modes[i] = malloc(n + 1);
        memcpy(M->modes[i], ref[i].s, n + 1);
        _fmpz_vec_set(ROW(M->witness, i), ROW(S.wit, ref[i].i), 3);
    }

    flint_free(ref);
    for (i = 0; i < 2 * nl + 2; i++)
    {
        fmpz_clear(ang[i].x);
        fmpz_clear(ang[i].y);
    }
    flint_free(ang);
    for (p = 0; p < np; p++)
    {
        flint_free(cols[p].x);
        flint_free(lines_on[p].x);
    }
    for (i = 0; i < np * (np - 1) / 2 + 1; i++)
        flint_free(planes_on[i].x);
    flint_free(cols);
    flint_free(lines_on);
    flint_free(planes_on);
    flint_free(done);
    flint_free(sgnf);
    flint_free(plane_of);
    flint_free(W.sg);
    flint_free(W.cur);
    fmpz_clear(W.t);
    _fmpz_vec_clear(v, 3);
    _fmpz_vec_clear(u, 3);
    _fmpz_vec_clear(w, 3);
    _fmpz_vec_clear(mid, 3);
    _fmpz_vec_clear(next, 3);
    _fmpz_vec_clear(wit, 3);
    fmpz_mat_clear(a);
    vec_set_clear(&planes);
    vec_set_clear(&lines);
    mode_set_clear(&S);
}

int
wc_modes_enumerate(wc_modes_t M, const wc_problem_t P, wc_error_t err)
{
    int status = wc_problem_check(P, err);

    if (status == WC_OK)
        enumerate(M, P);
    return status;
}

/* ---------------------------------------------------------------------
   One mode's certificate.  */

void
wc_certificate_init(wc_certificate_t C)
{
    slong j;

    C->mode = NULL;
    C->feasible = 0;
    for (j = 0; j < 3; j++)
        fmpz_init(C->witness + j);
    fmpz_mat_init(C->rows, 0, 3);
    C->rel = NULL;
    C->mult = NULL;
}

void
wc_certificate_clear(wc_certificate_t C)
{
    slong j;

    if (C->mult != NULL)
        _fmpz_vec_clear(C->mult, fmpz_mat_nrows(C->rows));
    free(C->mode);
    free(C->rel);
    for (j = 0; j < 3; j++)
        fmpz_clear(C->witness + j);
    fmpz_mat_clear(C->rows);
    C->mode = NULL;
    C->rel = NULL;
    C->mult = NULL;
}

int
wc_feasible(wc_certificate_t C, const wc_problem_t P, const char * mode,
            wc_error_t err)
{
    slong m;
    fmpq_mat_t A;
    fmpq * z, * y;
    int status, found;

    wc_certificate_clear(C);
    wc_certificate_init(C);
    status = wc_mode_constraints(C->rows, &C->rel, P, mode, err);
    if (status != WC_OK)
        return status;
    C->mode = malloc(strlen(mode) + 1);
    strcpy(C->mode, mode);
    m = fmpz_mat_nrows(C->rows);
    C->mult = _fmpz_vec_init(m);

    /* A twist, or Motzkin multipliers (m = 0: nu = 0).  */
    fmpq_mat_init(A, m, 3);
    fmpq_mat_set_fmpz_mat(A, C->rows);
    z = _fmpq_vec_init(3);
    y = _fmpq_vec_init(m + 1);
    found = _wc_lp_motzkin(z, y, A, C->rel, err);
    if (found < 0)
        status = WC_EINTERNAL;
    else if (found)
    {
        C->feasible = 1;
        fmpq_vec_primitive(C->witness, z, 3);
        if (!wc_certificate_check(C))
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: the witness of %s fails",
                                  mode);
    }
    else
    {
        fmpq_vec_primitive(C->mult, y, m);
        if (!wc_certificate_check(C))
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: certificate of %s fails",
                                  mode);
    }
    fmpq_mat_clear(A);
    _fmpq_vec_clear(z, 3);
    _fmpq_vec_clear(y, m + 1);
    return status;
}

int
wc_certificate_check(const wc_certificate_t C)
{
    slong m = fmpz_mat_nrows(C->rows), i, j;
    fmpz_t s;
    int ok = 1, strict = 0;

    fmpz_init(s);
    if (C->feasible)
    {
        for (i = 0; i < m && ok; i++)
        {
            _fmpz_vec_dot(s, WC_ROW(C->rows, i), C->witness, 3);
            ok = C->rel[i] == WC_REL_GT ? fmpz_sgn(s) > 0
                : C->rel[i] == WC_REL_GE ? fmpz_sgn(s) >= 0 : fmpz_is_zero(s);
        }
    }
    else
    {
        for (i = 0; i < m && ok; i++)
        {
            if (C->rel[i] != WC_REL_EQ && fmpz_sgn(C->mult + i) < 0)
                ok = 0;
            if (C->rel[i] == WC_REL_GT && fmpz_sgn(C->mult + i) > 0)
                strict = 1;
        }
        for (j = 0; j < 3 && ok; j++)
        {
            fmpz_zero(s);
            for (i = 0; i < m; i++)
                fmpz_addmul(s, C->mult + i, fmpz_mat_entry(C->rows, i, j));
            ok = fmpz_is_zero(s);
        }
        ok = ok && strict;
    }
    fmpz_clear(s);
    return ok;
}
