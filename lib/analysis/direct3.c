/* direct3.c -- the direct route's fast path: integer vectors straight
   from the model.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   W(x) = M V_x + pos(-J D_x) (direct.c).  Only directions matter, so
   every row and generator is a primitive integer vector: the column of J
   for a direction d at the point p is (d, r x d) with r = p - com, which
   is linear in d, so a positive integer multiple of d and of r gives a
   positive multiple of the column with one content division at the end,
   and the friction edge n +- mu t is (mu_den n +- mu_num t) up to a
   positive factor.  No fraction is ever reduced.

   V_x = { nudot : E nudot = 0, H nudot <= 0, S nudot < 0 } is settled by
   the rank of E: 3, the origin; 2, a subset of the line through u = the
   cross product of two independent rows (the signs of H u and S u say
   which); 0 with no strict rows, the polar of the fan of H, or the
   normal line of H's plane when H has rank 2 and fills it.  Then W is
   the fan of M V_x's generators and the friction edges, written directly
   in canonical form; when V_x is a ray whose apex is excluded (strict
   rows), a face of W is included iff it contains M times that ray (the
   rule of wc_cone_image_sum); edges around the part often span R^3,
   which an O(k) certificate (zrows3.h) settles before the fan.  A line
   V_x whose sum with the edges the fan leaves (it has lineality), and
   rank 1 with no rows (V_x a plane) or one strict row and one edge (an
   open half-plane), give W from an H-representation written directly
   (line_sum, plane_sum) in one general conversion; so does, without
   friction edges, any other V_x: W = M V_x from the rows times M^-1.
   Everything else -- equalities of rank 1 with other rows and edges,
   pointed cones the fan does not settle -- is left to the general route,
   decided from the mode's letters before anything is built when they
   suffice (plan).  Entries that fit a word are computed in 128 bits.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "exact/fan3.h"
#include "exact/cone3.h"
#include "analysis/zrows3.h"
#include "analysis/direct3.h"

/* What V_x is.  */
enum { V_EMPTY, V_ORIGIN, V_RAY, V_LINE, V_POLAR, V_PLANE, V_OTHER };

typedef struct
{
    slong n;
    fmpz * E;           /* 3 ne: the equality rows */
    fmpz * H;           /* 3 nh: rows h . nudot <= 0 */
    fmpz * S;           /* 3 ns: rows h . nudot < 0 */
    fmpz * Q;           /* 3 nq: the friction edges mapped by -J */
    fmpz * G;           /* 3 (gi + nq): generators of W, images first */
    fmpz * t;           /* 9 entries: scratch, see SCRATCH and Y */
    slong nh, ns, nq, ne, ng, gi;
    fmpz_t ma, mb;      /* M x is a positive multiple of (ma x0, ma x1, mb x2) */
}
ws_struct;

/* The scratch entry of the helpers below (t[4], t[5] hold an edge; Y,
   t[6] to t[8], the first image).  */
#define SCRATCH(w) ((w)->t + 2)
#define Y(w) ((w)->t + 6)

/* Integers that fit a word are computed in 128 bits, then stored; every
   other case takes the same formulas in fmpz arithmetic.  Both give the
   same integers.  */
#ifdef __SIZEOF_INT128__
typedef __int128 wide_t;
#define FITS(x) ((x) >= -(wide_t) COEFF_MAX && (x) <= (wide_t) COEFF_MAX)
#endif
#define SMALL(x) (!COEFF_IS_MPZ(*(x)))

#ifdef __SIZEOF_INT128__
/* x[0..k) := a[0..k) when every entry fits a word (then 1; else 0 and x
   untouched).  */
static inline int
set_wide(fmpz * x, const wide_t * a, slong k)
{
    slong j;

    for (j = 0; j < k; j++)
        if (!FITS(a[j]))
            return 0;
    for (j = 0; j < k; j++)
        if (SMALL(x + j))
            x[j] = (slong) a[j];        /* a word entry is its value */
        else
            fmpz_set_si(x + j, (slong) a[j]);
    return 1;
}
#endif

/* (X0, X1) / D := (a0, a1), D > 0 the lcm of the denominators.  */
static void
common_den(fmpz * X, fmpz_t D, const fmpq * a, fmpz_t g)
{
    if (fmpz_equal(fmpq_denref(a + 0), fmpq_denref(a + 1)))
    {
        fmpz_set(D, fmpq_denref(a + 0));
        fmpz_set(X + 0, fmpq_numref(a + 0));
        fmpz_set(X + 1, fmpq_numref(a + 1));
        return;
    }
    fmpz_lcm(D, fmpq_denref(a + 0), fmpq_denref(a + 1));
    fmpz_divexact(g, D, fmpq_denref(a + 0));
    fmpz_mul(X + 0, fmpq_numref(a + 0), g);
    fmpz_divexact(g, D, fmpq_denref(a + 1));
    fmpz_mul(X + 1, fmpq_numref(a + 1), g);
}

/* R := (p - com) as (R0, R1) / R2, R2 > 0, from O / Do = com; N := the
   normal times the lcm of its denominators.  */
static void
point_normal(fmpz * R, fmpz * N, const wc_fixel_struct * f, const fmpz * O,
             const fmpz_t Do, fmpz_t g)
{
#ifdef __SIZEOF_INT128__
    const fmpq * p = f->point, * v = f->normal;
    const fmpz * a0 = fmpq_numref(p), * b0 = fmpq_denref(p),
        * a1 = fmpq_numref(p + 1), * b1 = fmpq_denref(p + 1),
        * c0 = fmpq_numref(v), * d0 = fmpq_denref(v),
        * c1 = fmpq_numref(v + 1), * d1 = fmpq_denref(v + 1);

    if (SMALL(a0) && SMALL(b0) && SMALL(a1) && SMALL(b1) && SMALL(c0)
        && SMALL(d0) && SMALL(c1) && SMALL(d1) && SMALL(O) && SMALL(O + 1)
        && SMALL(Do))
    {
        slong gp = (slong) _wc_gcd_ui(*b0, *b1);
        slong gn = (slong) _wc_gcd_ui(*d0, *d1);
        wide_t r[3], n[2], x0, x1;

        /* Dp = lcm(b0, b1) = (b0 / gp) b1 < 2^124: the products below
           are formed only once it fits a word.  */
        r[2] = (wide_t) (*b0 / gp) * *b1;
        n[0] = (wide_t) *c0 * (*d1 / gn);
        n[1] = (wide_t) *c1 * (*d0 / gn);
        if (FITS(r[2]))
        {
            x0 = (wide_t) *a0 * (*b1 / gp);
            x1 = (wide_t) *a1 * (*b0 / gp);
            if (FITS(x0) && FITS(x1))
            {
                r[0] = x0 * *Do - (wide_t) *O * r[2];
                r[1] = x1 * *Do - (wide_t) O[1] * r[2];
                r[2] *= *Do;
                if (set_wide(R, r, 3) && set_wide(N, n, 2))
                    return;
            }
        }
    }
#endif
    common_den(R, R + 2, f->point, g);
    fmpz_mul(R + 0, R + 0, Do);
    fmpz_submul(R + 0, O + 0, R + 2);
    fmpz_mul(R + 1, R + 1, Do);
    fmpz_submul(R + 1, O + 1, R + 2);
    fmpz_mul(R + 2, R + 2, Do);
    common_den(N, N + 2, f->normal, g);
}

/* c := a positive integer multiple of the column of J for the direction
   D (a positive integer multiple of d) at r = (R0, R1) / R2, R2 > 0;
   primitive when prim is set (equality and strict rows need not be),
   negated when sign < 0.  */
static void
column(fmpz * c, const fmpz * D, const fmpz * R, fmpz_t g, int prim,
       int sign)
{
#ifdef __SIZEOF_INT128__
    if (SMALL(D) && SMALL(D + 1) && SMALL(R) && SMALL(R + 1) && SMALL(R + 2))
    {
        wide_t x[3];

        x[0] = (wide_t) R[2] * D[0];
        x[1] = (wide_t) R[2] * D[1];
        x[2] = (wide_t) R[0] * D[1] - (wide_t) R[1] * D[0];
        if (sign < 0)
        {
            x[0] = -x[0];
            x[1] = -x[1];
            x[2] = -x[2];
        }
        if (set_wide(c, x, 3))
        {
            if (prim)
                _wc_zvec3_primitive(c, g);
            return;
        }
    }
#endif
    fmpz_mul(c + 0, R + 2, D + 0);
    fmpz_mul(c + 1, R + 2, D + 1);
    fmpz_mul(c + 2, R + 0, D + 1);
    fmpz_submul(c + 2, R + 1, D + 0);
    if (prim)
        _wc_zvec3_primitive(c, g);
    if (sign < 0)
        _fmpz_vec_neg(c, c, 3);
}

/* Q gets -column(n + sign mu t) for the normal N (integer).  */
static void
edge(ws_struct * w, const fmpz * N, const fmpq_t mu, int sign,
     const fmpz * R)
{
    fmpz * D = w->t + 4, * c = w->Q + 3 * w->nq++;
    const fmpz * a = fmpq_numref(mu), * b = fmpq_denref(mu);

#ifdef __SIZEOF_INT128__
    if (SMALL(a) && SMALL(b) && SMALL(N) && SMALL(N + 1))
    {
        wide_t x[2];

        x[0] = (wide_t) *b * N[0] - sign * ((wide_t) *a * N[1]);
        x[1] = (wide_t) *b * N[1] + sign * ((wide_t) *a * N[0]);
        if (set_wide(D, x, 2))
        {
            column(c, D, R, SCRATCH(w), 1, -1);
            return;
        }
    }
#endif
    fmpz_mul(D + 0, b, N + 0);
    fmpz_mul(D + 1, b, N + 1);
    if (sign > 0)
    {
        fmpz_submul(D + 0, a, N + 1);
        fmpz_addmul(D + 1, a, N + 0);
    }
    else
    {
        fmpz_addmul(D + 0, a, N + 1);
        fmpz_submul(D + 1, a, N + 0);
    }
    column(c, D, R, SCRATCH(w), 1, -1);
}

/* The rows of V_x and the generators -J D_x, fixel by fixel, each row
   written where it belongs.  */
static void
build(ws_struct * w, const wc_problem_t P, const char * mode)
{
    fmpz * O = _fmpz_vec_init(3), * R = _fmpz_vec_init(3);
    fmpz * N = _fmpz_vec_init(3), * g = O + 2, * s = SCRATCH(w);
    fmpz_t Do;
    slong i;

    fmpz_init(Do);
    w->nh = w->ns = w->nq = w->ne = 0;
    common_den(O, Do, P->com, g);
    for (i = 0; i < w->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;
        char x = mode[i];

        if (x == 'u')
            continue;
        point_normal(R, N, f, O, Do, g);
        /* The column of the normal, then (l, r, n) that of t = (-n_y,
           n_x).  */
        if (x == 's')
            column(w->H + 3 * w->nh++, N, R, s, 1, -1);
        else if (x == 'a')
            column(w->S + 3 * w->ns++, N, R, s, 0, 1);
        else
            column(w->E + 3 * w->ne++, N, R, s, 0, 1);
        if (x == 'l' || x == 'r' || x == 'n')
        {
            fmpz_neg(N + 2, N + 1);
            fmpz_swap(N + 1, N + 2);
            fmpz_swap(N + 0, N + 1);
            column(x == 'n' ? w->E + 3 * w->ne++ : w->S + 3 * w->ns++,
                   N, R, s, 0, x == 'l' ? -1 : 1);
            fmpz_swap(N + 0, N + 1);            /* N back to the normal */
            fmpz_swap(N + 1, N + 2);
        }
        if (x == 'l' || x == 'r')
            edge(w, N, f->mu_k, x == 'l' ? -1 : 1, R);
        else if (x == 'n' || x == 'm')
        {
            edge(w, N, f->mu_s, -1, R);
            edge(w, N, f->mu_s, 1, R);
        }
    }
    fmpz_clear(Do);
    _fmpz_vec_clear(O, 3);
    _fmpz_vec_clear(R, 3);
    _fmpz_vec_clear(N, 3);
}

/* The rank of the equality rows (0, 1, 2 or 3); for rank 2, u := a
   nonzero vector spanning their null space, primitive.  */
static int
eq_rank(ws_struct * w, fmpz * u)
{
    slong i;
    int r = 0;
    const fmpz * e1 = NULL;

    for (i = 0; i < w->ne && r < 3; i++)
    {
        const fmpz * x = w->E + 3 * i;

        if (r == 0)
        {
            if (!_fmpz_vec_is_zero(x, 3))
            {
                e1 = x;
                r = 1;
            }
        }
        else if (r == 1)
        {
            _wc_zvec3_cross(u, e1, x);
            r = _fmpz_vec_is_zero(u, 3) ? 1 : 2;
            if (r == 2)
                _wc_zvec3_primitive(u, SCRATCH(w));
        }
        else if (_wc_zvec3_dot_sgn_fast(u, x, SCRATCH(w)) != 0)
            r = 3;
    }
    return r;
}

/* V_x inside the line through u: the origin, the ray v (primitive), the
   line, or empty; *apex := whether the origin face belongs to V_x.  */
static int
on_line(ws_struct * w, fmpz * u, int * apex)
{
    int pos = 0, neg = 0, s;
    slong i;

    for (i = 0; i < w->nh + w->ns; i++)
    {
        s = _wc_zvec3_dot_sgn_fast(i < w->nh ? w->H + 3 * i
                                   : w->S + 3 * (i - w->nh), u, SCRATCH(w));
        pos |= s > 0;
        neg |= s < 0;
    }
    *apex = w->ns == 0;
    if (pos && neg)
        return w->ns == 0 ? V_ORIGIN : V_EMPTY;
    if (!pos && !neg)
        return w->ns == 0 ? V_LINE : V_EMPTY;
    if (pos)
        _fmpz_vec_neg(u, u, 3);                 /* the ray is -u */
    for (i = 0; i < w->ns; i++)
        if (_wc_zvec3_dot_sgn_fast(w->S + 3 * i, u, SCRATCH(w)) >= 0)
            return V_EMPTY;
    return V_RAY;
}

/* G gets M x (primitive), negated when sign < 0.  */
static void
put_image(ws_struct * w, const fmpz * x, int sign)
{
    fmpz * y = w->G + 3 * w->ng++;

    fmpz_mul(y + 0, w->ma, x + 0);
    fmpz_mul(y + 1, w->ma, x + 1);
    fmpz_mul(y + 2, w->mb, x + 2);
    _wc_zvec3_primitive(y, SCRATCH(w));
    if (sign < 0)
        _fmpz_vec_neg(y, y, 3);
}

/* W's faces when V_x is a ray whose apex is excluded: a face is included
   iff it holds y = M v, i.e. iff it contains the rays of the smallest
   face holding y (those on every facet through y; all rays when none).  */
static int
faces_holding(wc_cone_t W, const fmpz * y, fmpz_t t)
{
    slong m = fmpz_mat_nrows(W->ineqs), k = fmpz_mat_nrows(W->rays);
    slong i, j, f, size = 0, * T = malloc(sizeof(slong) * (m + k + 1));
    slong * in = T + m, nt = 0;

    if (T == NULL)
        return 0;
    for (j = 0; j < m; j++)
        if (_wc_zvec3_dot_sgn_fast(WC_ROW(W->ineqs, j), y, t) == 0)
            T[nt++] = j;
    for (i = 0; i < k; i++)
    {
        in[i] = 1;
        for (j = 0; j < nt && in[i]; j++)
            in[i] = _wc_zvec3_dot_sgn_fast(WC_ROW(W->ineqs, T[j]),
                                           WC_ROW(W->rays, i), t) == 0;
        size += in[i];
    }
    for (f = 0; f < W->nfaces; f++)
    {
        wc_face_struct * F = W->faces + f;
        slong c = 0;

        for (i = 0; i < F->nrays; i++)
            c += in[F->rays[i]];
        F->included = c == size;
    }
    free(T);
    return 1;
}

/* 1 when the rows H have rank 2 and are in no closed half-plane of their
   plane: then pos(H) is that plane, V_x its normal line, and u := the
   normal; 0 for other rows of rank 1 or 2, -1 for rank 3.  Around u, A is the row farthest counterclockwise from the
   first row h, B the farthest clockwise; the rows fill the plane iff
   -h is a row and both sides are used, or the angle from A on to B is
   below a half-turn.  */
static int
plane_of_rows(ws_struct * w, fmpz * u)
{
    const fmpz * h = w->H, * A = NULL, * B = NULL;
    fmpz * c = _fmpz_vec_init(3), * t = SCRATCH(w);
    slong i;
    int opp = 0, r = 0, s;

    for (i = 1; i < w->nh && _fmpz_vec_is_zero(u, 3); i++)
        _wc_zvec3_cross(u, h, w->H + 3 * i);
    if (_fmpz_vec_is_zero(u, 3))
        goto done;
    for (i = 0; i < w->nh; i++)
        if (_wc_zvec3_dot_sgn_fast(u, w->H + 3 * i, t) != 0)
        {
            r = -1;
            goto done;
        }
    _wc_zvec3_primitive(u, t);
    for (i = 1; i < w->nh; i++)
    {
        const fmpz * x = w->H + 3 * i;

        _wc_zvec3_cross(c, h, x);
        s = _wc_zvec3_dot_sgn_fast(u, c, t);
        if (s == 0)
            opp |= _wc_zvec3_dot_sgn_fast(h, x, t) < 0;
        else if (s > 0 && A != NULL)
        {
            _wc_zvec3_cross(c, A, x);
            if (_wc_zvec3_dot_sgn_fast(u, c, t) > 0)
                A = x;
        }
        else if (s < 0 && B != NULL)
        {
            _wc_zvec3_cross(c, B, x);
            if (_wc_zvec3_dot_sgn_fast(u, c, t) < 0)
                B = x;
        }
        else if (s > 0)
            A = x;
        else
            B = x;
    }
    if (A != NULL && B != NULL)
    {
        _wc_zvec3_cross(c, A, B);
        r = opp || _wc_zvec3_dot_sgn_fast(u, c, t) > 0;
    }

done:
    _fmpz_vec_clear(c, 3);
    return r;
}

/* V_x from the rank of the equalities; V_POLAR sets FV (the fan of H,
   whose facet normals are V_x's rays).  */
static int
settle_v(ws_struct * w, _wc_fan3_t FV, fmpz * u, int * apex)
{
    int r = eq_rank(w, u);
    slong k;

    *apex = 1;
    if (r == 3)
        return w->ns == 0 ? V_ORIGIN : V_EMPTY;
    if (r == 2)
        return on_line(w, u, apex);
    if (r == 1 && w->nh == 0 && w->nq > 0
        && (w->ns == 0 || (w->ns == 1 && w->nq == 1)))
        return V_PLANE;
    if (r == 1 || w->ns > 0 || w->nh == 0)
        return V_OTHER;
    _fmpz_vec_zero(u, 3);
    if ((r = plane_of_rows(w, u)) >= 0)
        return r ? V_LINE : V_OTHER;
    _fmpz_vec_set(w->G, w->H, 3 * w->nh);     /* G's room for images */
    k = _wc_zrows3_distinct(w->G, w->nh);
    r = _wc_fan3(FV, w->G, k);
    if (r == WC_FAN3_NOMEM)
        return -1;
    return r == WC_FAN3_POINTED ? V_POLAR
        : r == WC_FAN3_SPACE ? V_ORIGIN : V_OTHER;
}

/* W := { g : e . g = 0, h . g <= 0, s . g < 0 } for the rows e, h, s
   (3 entries each, or NULL), by the general conversion.  */
static int
set_rows(wc_cone_t W, const fmpz * e, const fmpz * h, const fmpz * s,
         wc_error_t err)
{
    const fmpz * x[3] = { e, h, s };
    fmpq_mat_t A[3];
    slong i, j;
    int status;

    for (i = 0; i < 3; i++)
    {
        fmpq_mat_init(A[i], x[i] != NULL, 3);
        for (j = 0; x[i] != NULL && j < 3; j++)
            fmpz_set(fmpq_mat_entry_num(A[i], 0, j), x[i] + j);
    }
    status = wc_cone_set_hrep(W, A[0], A[1], A[2], err);
    for (i = 0; i < 3; i++)
        fmpq_mat_clear(A[i]);
    return status;
}

/* V_x = the plane a . nudot = 0 (a the equality row), or with one strict
   row b the open half-plane b . nudot < 0 in it; M V_x = { g : a' . g =
   0 (, b' . g < 0) } for a', b' the rows times M^-1.  W = M V_x + pos(Q):
   a plane plus edges is the plane, a closed half-space or R^3 by the
   signs of a' . q; an open half-plane plus one edge q is, when a' . q =
   0, itself (b' . q <= 0) or the plane, else (t = a' . g / a' . q >= 0
   and b' . (g - t q) < 0) { g : -s a' . g <= 0, s c . g < 0 } with
   s = sign(a' . q), c = (a' . q) b' - (b' . q) a'.  */
static int
plane_sum(wc_cone_t W, ws_struct * w, wc_error_t err)
{
    fmpz * a = w->G, * b = w->G + 3, * c = w->G + 6, * t = SCRATCH(w);
    fmpz_t aq, bq;
    slong i;
    int pos = 0, neg = 0, sg, status;

    for (i = 0; _fmpz_vec_is_zero(w->E + 3 * i, 3); i++)
        ;
    fmpz_mul(a + 0, w->mb, w->E + 3 * i);
    fmpz_mul(a + 1, w->mb, w->E + 3 * i + 1);
    fmpz_mul(a + 2, w->ma, w->E + 3 * i + 2);
    if (w->ns == 0)
    {
        for (i = 0; i < w->nq; i++)
        {
            sg = _wc_zvec3_dot_sgn_fast(a, w->Q + 3 * i, t);
            pos |= sg > 0;
            neg |= sg < 0;
        }
        if (pos && neg)
        {
            _wc_cone3_set_space(W);
            return WC_OK;
        }
        if (pos)
            _fmpz_vec_neg(a, a, 3);
        return set_rows(W, pos || neg ? NULL : a, pos || neg ? a : NULL,
                        NULL, err);
    }
    fmpz_init(aq);
    fmpz_init(bq);
    fmpz_mul(b + 0, w->mb, w->S + 0);
    fmpz_mul(b + 1, w->mb, w->S + 1);
    fmpz_mul(b + 2, w->ma, w->S + 2);
    _fmpz_vec_dot(aq, a, w->Q, 3);
    _fmpz_vec_dot(bq, b, w->Q, 3);
    if (fmpz_is_zero(aq))
        status = set_rows(W, a, NULL, fmpz_sgn(bq) <= 0 ? b : NULL, err);
    else
    {
        _fmpz_vec_scalar_mul_fmpz(c, b, 3, aq);
        _fmpz_vec_scalar_submul_fmpz(c, a, 3, bq);
        if (fmpz_sgn(aq) > 0)
            _fmpz_vec_neg(a, a, 3);
        else
            _fmpz_vec_neg(c, c, 3);
        status = set_rows(W, NULL, a, c, err);
    }
    fmpz_clear(aq);
    fmpz_clear(bq);
    return status;
}

/* The sign pattern of h . x over the k rows x of A: bit 1 for a positive
   value, bit 2 for a negative one.  */
static int
signs(const fmpz * h, const fmpz * A, slong k, fmpz_t t)
{
    slong j;
    int r = 0, sg;

    for (j = 0; j < k && r != 3; j++)
    {
        sg = _wc_zvec3_dot_sgn_fast(h, A + 3 * j, t);
        r |= sg > 0 ? 1 : sg < 0 ? 2 : 0;
    }
    return r;
}

/* W = span(y) + pos(A) (k rows of A, y among them), closed, when the fan
   did not settle it.  Its facets lie on planes through y and a row x,
   with normal h = y x x (when h . A has one sign); if every such h is
   normal to all rows, W lies in the plane h . g = 0 and is bounded
   there, if at all, by c = h x y.  k^2 sign tests: up to 32 rows, else
   *done := 0.  */
static int
line_sum(wc_cone_t W, int * done, ws_struct * w, const fmpz * y, slong k,
         wc_error_t err)
{
    fmpz * h, * a, * c, * H, * t = SCRATCH(w);
    slong i, m = 0;
    int sg, flat = 1, status = WC_OK;

    if (k > 32)
    {
        *done = 0;
        return WC_OK;
    }
    h = _fmpz_vec_init(3 * k + 9);
    a = h + 3;
    c = h + 6;
    H = h + 9;
    for (i = 0; i < k; i++)
    {
        _wc_zvec3_cross(h, y, w->G + 3 * i);
        if (_fmpz_vec_is_zero(h, 3))
            continue;
        _fmpz_vec_set(a, h, 3);
        sg = signs(h, w->G, k, t);
        flat &= sg == 0;
        if (sg == 1)
            _fmpz_vec_neg(h, h, 3);
        if (sg == 1 || sg == 2)
            _fmpz_vec_set(H + 3 * m++, h, 3);
    }
    if (_fmpz_vec_is_zero(a, 3))
        _wc_cone3_set_line(W, y);
    else if (flat)
    {
        _wc_zvec3_cross(c, a, y);
        sg = signs(c, w->G, k, t);
        if (sg == 1)
            _fmpz_vec_neg(c, c, 3);
        status = set_rows(W, a, sg == 1 || sg == 2 ? c : NULL, NULL, err);
    }
    else if (m == 0)
        _wc_cone3_set_space(W);
    else
    {
        fmpq_mat_t A;

        fmpq_mat_init(A, m, 3);
        for (i = 0; i < 3 * m; i++)
            fmpz_set(fmpq_mat_entry_num(A, i / 3, i % 3), H + i);
        status = wc_cone_set_hrep(W, NULL, A, NULL, err);
        fmpq_mat_clear(A);
    }
    _fmpz_vec_clear(h, 3 * k + 9);
    return status;
}

/* W := the fan of the generators, or for a line V_x line_sum's
   conversion; *done := 0 when neither settles it.  Returns WC_OK, or
   WC_EINTERNAL (*err_set: err set, else out of memory).  */
static int
set_w(wc_cone_t W, int * done, int * err_set, ws_struct * w, int kind,
      int apex, wc_error_t err)
{
    _wc_fan3_t F;
    slong k;
    int r, status = WC_OK;

    k = _wc_zrows3_distinct(w->G, w->ng);
    if (k == 0)
    {
        _wc_cone3_set_origin(W);
        return WC_OK;
    }
    if (k == 2 && kind == V_LINE)       /* M V_x, no friction edges */
    {
        _wc_cone3_set_line(W, Y(w));
        return WC_OK;
    }
    /* A line and at most two edges: not R^3, not pointed.  For V_x the
       origin or a line, the friction edges around the part often span
       R^3: a certificate in O(k) sign tests spares the fan.  */
    r = WC_FAN3_OTHER;
    if ((kind == V_ORIGIN || (kind == V_LINE && k >= 5))
        && _wc_zrows3_span_space(w->G, k))
    {
        _wc_cone3_set_space(W);
        return WC_OK;
    }
    if (kind != V_LINE || k >= 5)
    {
        _wc_fan3_init(F);
        r = _wc_fan3(F, w->G, k);
        if (r == WC_FAN3_NOMEM)
            status = WC_EINTERNAL;
        else if (r == WC_FAN3_POINTED)
            status = _wc_cone3_set_fan(W, F, 0);
        else if (r == WC_FAN3_SPACE)
            _wc_cone3_set_space(W);
        _wc_fan3_clear(F);
    }
    if (r == WC_FAN3_OTHER && kind == V_LINE)
    {
        *err_set = 1;
        return line_sum(W, done, w, Y(w), k, err);
    }
    if (r == WC_FAN3_OTHER)
        *done = 0;
    if (status == WC_OK && *done && kind == V_RAY && !apex
        && !faces_holding(W, Y(w), SCRATCH(w)))
        status = WC_EINTERNAL;
    return status;
}

/* A := the rows x[0..k) times M^-1, up to positive factors: (mb x0,
   mb x1, ma x2).  */
static void
rows_times_minv(fmpq_mat_t A, const fmpz * x, slong k, const ws_struct * w)
{
    slong i;

    fmpq_mat_init(A, k, 3);
    for (i = 0; i < k; i++)
    {
        const fmpz * r = x + 3 * i;

        fmpz_mul(fmpq_mat_entry_num(A, i, 0), w->mb, r + 0);
        fmpz_mul(fmpq_mat_entry_num(A, i, 1), w->mb, r + 1);
        fmpz_mul(fmpq_mat_entry_num(A, i, 2), w->ma, r + 2);
    }
}

/* No friction edges: W = M V_x = { g : E M^-1 g = 0, H M^-1 g <= 0,
   S M^-1 g < 0 }, one conversion (the general one) instead of V_x's and
   then the image's.  */
static int
image_by_hrep(wc_cone_t W, const ws_struct * w, wc_error_t err)
{
    fmpq_mat_t E, H, S;
    int status;

    rows_times_minv(E, w->E, w->ne, w);
    rows_times_minv(H, w->H, w->nh, w);
    rows_times_minv(S, w->S, w->ns, w);
    status = wc_cone_set_hrep(W, E, H, S, err);
    fmpq_mat_clear(E);
    fmpq_mat_clear(H);
    fmpq_mat_clear(S);
    return status;
}

/* From the letters alone: 0 when the fast path cannot answer (then
   nothing is built); else 1 and the row counts, for the sizes.  */
static int
plan(ws_struct * w, const char * mode)
{
    slong i;

    w->ne = w->nh = w->ns = w->nq = 0;
    for (i = 0; i < w->n; i++)
    {
        char x = mode[i];

        w->nh += x == 's';
        w->ns += x == 'a' || x == 'l' || x == 'r';
        w->ne += (x == 'l' || x == 'r' || x == 'm') + 2 * (x == 'n');
        w->nq += (x == 'l' || x == 'r') + 2 * (x == 'n' || x == 'm');
    }
    /* Friction edges and one equality (rank at most 1) with rows other
       than those V_PLANE takes: V_OTHER, left to the general route.  */
    return w->nq == 0 || w->ne > 1
        || (w->nh == 0 && (w->ns == 0 || (w->ns == 1 && w->nq == 1)));
}

/* The images of V_x's generators under M, then the friction edges, into
   G; Y := the first image.  */
static void
generators(ws_struct * w, int kind, const fmpz * u, const _wc_fan3_t FV)
{
    slong i;

    w->ng = 0;
    if (kind == V_RAY || kind == V_LINE)
        put_image(w, u, 1);
    if (kind == V_LINE)
        put_image(w, u, -1);
    for (i = 0; kind == V_POLAR && i < FV->m; i++)
        put_image(w, FV->facets + 3 * i, 1);
    if (w->ng > 0)
        _fmpz_vec_set(Y(w), w->G, 3);
    /* The edges move down to follow the images (swaps, front first).  */
    for (i = 0; w->ng < w->gi && i < 3 * w->nq; i++)
        fmpz_swap(w->G + 3 * w->ng + i, w->Q + i);
    w->ng += w->nq;
}

int
_wc_wrench_cone_direct3(wc_cone_t W, int * done, const wc_problem_t P,
                        const char * mode, wc_error_t err)
{
    ws_struct w;
    _wc_fan3_t FV;
    slong len;
    fmpz * z, * u;
    int kind, apex, status = WC_OK, err_set = 0;

    *done = 0;
    w.n = P->n;
    if (W->d != 3 || !plan(&w, mode))
    {
        wc_cone_set_empty(W);
        return WC_OK;
    }
    /* V_POLAR's images and H's distinct rows need nh rows ahead of the
       edges, a line's images 2, plane_sum's scratch 3.  */
    w.gi = FLINT_MAX(w.nh, 3);
    len = 3 * (w.ne + w.nh + w.ns + w.gi + w.nq) + 12;
    z = _fmpz_vec_init(len);
    w.E = z;
    w.H = w.E + 3 * w.ne;
    w.S = w.H + 3 * w.nh;
    w.G = w.S + 3 * w.ns;
    w.Q = w.G + 3 * w.gi;
    w.t = w.Q + 3 * w.nq;
    u = w.t + 9;
    fmpz_init(w.ma);
    fmpz_init(w.mb);
    _wc_fan3_init(FV);
    /* M = diag(m, m, I): M x is a positive multiple of
       (m_num I_den x0, m_num I_den x1, I_num m_den x2).  */
    fmpz_mul(w.ma, fmpq_numref(P->mass), fmpq_denref(P->inertia));
    fmpz_mul(w.mb, fmpq_numref(P->inertia), fmpq_denref(P->mass));
    build(&w, P, mode);
    kind = settle_v(&w, FV, u, &apex);
    if (kind < 0)
        status = WC_EINTERNAL;
    if (kind == V_OTHER && w.nq == 0)
    {
        *done = 1;
        status = image_by_hrep(W, &w, err);
        err_set = 1;
        goto finish;
    }
    if (kind == V_PLANE)
    {
        *done = 1;
        status = plane_sum(W, &w, err);
        err_set = 1;
        goto finish;
    }
    if (kind < 0 || kind == V_OTHER)
        goto finish;
    *done = 1;
    if (kind == V_EMPTY)
    {
        wc_cone_set_empty(W);
        goto finish;
    }
    generators(&w, kind, u, FV);
    status = set_w(W, done, &err_set, &w, kind, apex, err);

finish:
    fmpz_clear(w.ma);
    fmpz_clear(w.mb);
    _wc_fan3_clear(FV);
    _fmpz_vec_clear(z, len);
    if (status != WC_OK)
    {
        *done = 1;
        wc_cone_set_empty(W);
        return err_set ? status
            : wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                           "internal error: out of memory in the direct "
                           "route");
    }
    if (!*done)
        wc_cone_set_empty(W);
    return WC_OK;
}
