/* compare.c -- a foreign (floating-point) cone against the exact one.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Geometry.  For a closed convex cone C and a vector v, the nearest point
   P v of C satisfies v = P v + (v - P v) with the two parts orthogonal
   (Moreau), P v lies in the relative interior of exactly one face F of C
   and is the orthogonal projection of v onto span F.  For any face G
   whose projection q of v onto span G happens to lie in C,
   |v - q|^2 = |v|^2 - |q|^2 >= |v - P v|^2 = |v|^2 - |P v|^2; so |P v|^2
   is the largest |q|^2 over the faces whose q lies in C.  All of this is
   exact (rationals), and so is the angle's tangent squared
   (|v|^2 - |P v|^2) / |P v|^2; only atan(sqrt(.)) is a float.

   The directed distance sup { angle(x, B) : x in A, |x| = 1 } is NOT in
   general attained at an extreme ray of A, even for pointed cones that
   are close: for A = pos((1, 1, e), (1, -1, e)) and the wedge
   B = pos((1, 1, 0), (1, -1, 0)), A's rays are at atan(e / sqrt 2) from
   B but A's middle (1, 0, e) is at atan(e) (on the sphere the distance
   to a great-circle arc is not convex; tests/t-compare.c checks this
   case).  Nor is a vertex rule saved by the facets' normals.  So we split R^3
   into the cells G + N_G of the normal fan of B (G a face of B, N_G its
   normal cone): on G + N_G the nearest point of B is the projection onto
   span G, and the angle to B is the angle to the subspace span G, whose
   maximum over the polyhedral cone K = A cap (G + N_G) is found exactly:
   - span G = R^3: 0;
   - span G a plane with normal n: sin(angle) = |n.x| / |n| |x|, whose
     maximum over unit x in K is |P_K n| / |n| or |P_K (-n)| / |n|
     (|P_K n| is the support function of K cap ball at n);
   - span G a line R r: cos(angle) = |r.x| / |r| |x|; if r.x vanishes at
     some nonzero x of K the maximum is pi/2, else r.x keeps one sign on K
     and x -> |r.x| / |x| is quasi-concave there (its superlevel sets are
     convex circular cones), so its minimum is at a generator of K;
   - G = {0} (B pointed): K lies in the polar cone B°, every angle is at
     least pi/2, and the nearest point of B to x is one of B's extreme
     rays (x.b <= 0 on B, and the same quasi-concavity); the largest
     min_i angle(x, r_i) over K is found by enumerating the finitely many
     candidates (see minimax_polar), in doubles.  */

#include <config.h>

#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpq_vec.h>

#include "float/compare.h"
#include "core/json.h"
#include "io/print.h"
#include "core/problem.h"

#define WC_ROW(A, i) ((A)->rows[i])
#define WC_PI 3.14159265358979323846

/* ------------------------------------------------------------------ */
/* Exact vectors in R^3.  */

static void
vdot(fmpq_t r, const fmpq * a, const fmpq * b)
{
    _fmpq_vec_dot(r, a, b, 3);
}

/* c = a x b; c must not alias a or b.  */
static void
vcross(fmpq * c, const fmpq * a, const fmpq * b)
{
    fmpq_mul(c + 0, a + 1, b + 2);
    fmpq_submul(c + 0, a + 2, b + 1);
    fmpq_mul(c + 1, a + 2, b + 0);
    fmpq_submul(c + 1, a + 0, b + 2);
    fmpq_mul(c + 2, a + 0, b + 1);
    fmpq_submul(c + 2, a + 1, b + 0);
}

static int
vzero(const fmpq * a)
{
    return fmpq_is_zero(a + 0) && fmpq_is_zero(a + 1) && fmpq_is_zero(a + 2);
}

static void
vset(fmpq * a, const fmpq * b)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_set(a + j, b + j);
}

static void
vzero_set(fmpq * a)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_zero(a + j);
}

static void
vswap(fmpq * a, fmpq * b)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_swap(a + j, b + j);
}

static void
vneg(fmpq * a, const fmpq * b)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_neg(a + j, b + j);
}

/* r = h . p for an integer h.  */
static void
dot_zq(fmpq_t r, const fmpz * h, const fmpq * p)
{
    fmpq_t t;
    slong j;

    fmpq_init(t);
    fmpq_zero(r);
    for (j = 0; j < 3; j++)
    {
        fmpq_mul_fmpz(t, p + j, h + j);
        fmpq_add(r, r, t);
    }
    fmpq_clear(t);
}

/* 1 when a = s b for some s > 0 (both nonzero).  */
static int
same_ray(const fmpq * a, const fmpq * b)
{
    fmpq * c = _fmpq_vec_init(3);
    fmpq_t d;
    int r;

    fmpq_init(d);
    vcross(c, a, b);
    vdot(d, a, b);
    r = vzero(c) && fmpq_sgn(d) > 0;
    fmpq_clear(d);
    _fmpq_vec_clear(c, 3);
    return r;
}

/* atan(sqrt(t)) for a rational t >= 0: the angle whose tangent squared is
   t, to double accuracy even when t is tiny.  */
static double
atan_sqrt(const fmpq_t t)
{
    return atan(sqrt(fmpq_get_d(t)));
}

/* v as a unit vector in doubles (zeros when v is zero): each entry is
   sqrt(v_j^2 / |v|^2) with the ratio exact, so it is within an ulp or two
   of the true value however large or small v's numbers are.  */
static void
unit_d(double * u, const fmpq * v)
{
    fmpq_t n, t;
    slong j;

    fmpq_init(n);
    fmpq_init(t);
    vdot(n, v, v);
    for (j = 0; j < 3; j++)
    {
        if (fmpq_is_zero(n))
            u[j] = 0;
        else
        {
            fmpq_mul(t, v + j, v + j);
            fmpq_div(t, t, n);
            u[j] = sqrt(fmpq_get_d(t));
            if (fmpq_sgn(v + j) < 0)
                u[j] = -u[j];
        }
    }
    fmpq_clear(n);
    fmpq_clear(t);
}

static void
unit_z(double * u, const fmpz * v)
{
    fmpq * q = _fmpq_vec_init(3);

    _fmpq_vec_set_fmpz_vec(q, v, 3);
    unit_d(u, q);
    _fmpq_vec_clear(q, 3);
}

static double
ddot(const double * a, const double * b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void
dcross(double * c, const double * a, const double * b)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* Normalise a in place; 0 when it is (numerically) zero.  */
static int
dnormalize(double * a)
{
    double n = sqrt(ddot(a, a));

    if (!(n > 1e-300))
        return 0;
    a[0] /= n;
    a[1] /= n;
    a[2] /= n;
    return 1;
}

/* The angle between a and b (atan2 of |a x b| and a.b: accurate near 0
   and pi, where acos is not).  */
static double
dangle(const double * a, const double * b)
{
    double c[3];

    dcross(c, a, b);
    return atan2(sqrt(ddot(c, c)), ddot(a, b));
}

double
wc_angle_vectors(const fmpq * a, const fmpq * b)
{
    fmpq_t c, aa, bb, x;
    double r;

    if (vzero(a) || vzero(b))
        return NAN;
    fmpq_init(c);
    fmpq_init(aa);
    fmpq_init(bb);
    fmpq_init(x);
    vdot(c, a, b);
    vdot(aa, a, a);
    vdot(bb, b, b);
    /* |a x b|^2 = |a|^2 |b|^2 - (a.b)^2, exactly; tan^2 = that / (a.b)^2 */
    fmpq_mul(x, aa, bb);
    fmpq_submul(x, c, c);
    if (fmpq_is_zero(c))
        r = WC_PI / 2;
    else
    {
        fmpq_mul(aa, c, c);
        fmpq_div(x, x, aa);
        r = atan_sqrt(x);
        if (fmpq_sgn(c) < 0)
            r = WC_PI - r;
    }
    fmpq_clear(c);
    fmpq_clear(aa);
    fmpq_clear(bb);
    fmpq_clear(x);
    return r;
}

/* ------------------------------------------------------------------ */
/* Subspaces and projections.  */

/* The dimension of the row space of G (r x 3); for dimension 1, dir
   spans it; for dimension 2, dir is a normal of it.  */
static slong
span_of(fmpq * dir, const fmpq_mat_t G)
{
    fmpq_mat_t R;
    slong r;

    if (fmpq_mat_nrows(G) == 0)
        return 0;
    fmpq_mat_init(R, fmpq_mat_nrows(G), 3);
    r = fmpq_mat_rref(R, G);
    if (r == 1)
        vset(dir, WC_ROW(R, 0));
    else if (r == 2)
        vcross(dir, WC_ROW(R, 0), WC_ROW(R, 1));
    fmpq_mat_clear(R);
    return r;
}

/* q = the orthogonal projection of v onto the subspace (r, dir) of
   span_of.  q may alias v.  */
static void
span_project(fmpq * q, const fmpq * v, slong r, const fmpq * dir)
{
    fmpq_t s, n;
    slong j;

    if (r == 0)
    {
        vzero_set(q);
        return;
    }
    if (r >= 3)
    {
        vset(q, v);
        return;
    }
    fmpq_init(s);
    fmpq_init(n);
    vdot(s, v, dir);
    vdot(n, dir, dir);
    fmpq_div(s, s, n);
    for (j = 0; j < 3; j++)
    {
        if (r == 1)
            fmpq_mul(q + j, s, dir + j);
        else
        {
            fmpq_mul(n, s, dir + j);
            fmpq_sub(q + j, v + j, n);
        }
    }
    fmpq_clear(s);
    fmpq_clear(n);
}

/* The span of face F of C: its rays and C's lines.  */
static slong
face_span(fmpq * dir, const wc_cone_t C, const wc_face_struct * F)
{
    slong nl = fmpz_mat_nrows(C->lines), i, r;
    fmpq_mat_t G;

    fmpq_mat_init(G, F->nrays + nl, 3);
    for (i = 0; i < F->nrays; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(G, i), WC_ROW(C->rays, F->rays[i]), 3);
    for (i = 0; i < nl; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(G, F->nrays + i), WC_ROW(C->lines, i),
                               3);
    r = span_of(dir, G);
    fmpq_mat_clear(G);
    return r;
}

/* The span of the rows of an integer matrix.  */
static slong
rows_span(fmpq * dir, const fmpz_mat_t A)
{
    fmpq_mat_t G;
    slong r;

    fmpq_mat_init(G, fmpz_mat_nrows(A), 3);
    fmpq_mat_set_fmpz_mat(G, A);
    r = span_of(dir, G);
    fmpq_mat_clear(G);
    return r;
}

/* 1 when p lies in cl C (exactly).  */
static int
in_closure(const wc_cone_t C, const fmpq * p)
{
    fmpq_t s;
    slong i;
    int in = 1;

    fmpq_init(s);
    for (i = 0; in && i < fmpz_mat_nrows(C->ineqs); i++)
    {
        dot_zq(s, WC_ROW(C->ineqs, i), p);
        in = fmpq_sgn(s) <= 0;
    }
    for (i = 0; in && i < fmpz_mat_nrows(C->eqs); i++)
    {
        dot_zq(s, WC_ROW(C->eqs, i), p);
        in = fmpq_is_zero(s);
    }
    fmpq_clear(s);
    return in;
}

/* best = |P v|^2, P the nearest-point map onto cl C (C nonempty); q = P v
   when q is not NULL.  See the comment at the top.  */
static void
cone_project(fmpq_t best, fmpq * q, const fmpq * v, const wc_cone_t C)
{
    fmpq * dir = _fmpq_vec_init(3), * p = _fmpq_vec_init(3);
    fmpq_t n2;
    slong f, r;

    fmpq_init(n2);
    fmpq_zero(best);
    if (q != NULL)
        vzero_set(q);
    for (f = 0; f < C->nfaces; f++)
    {
        r = face_span(dir, C, C->faces + f);
        span_project(p, v, r, dir);
        if (!in_closure(C, p))
            continue;
        vdot(n2, p, p);
        if (fmpq_cmp(n2, best) > 0)
        {
            fmpq_set(best, n2);
            if (q != NULL)
                vset(q, p);
        }
    }
    fmpq_clear(n2);
    _fmpq_vec_clear(dir, 3);
    _fmpq_vec_clear(p, 3);
}

double
wc_angle_to_cone(const fmpq * v, const wc_cone_t C)
{
    fmpq_t best, t;
    fmpq * r;
    double a;
    slong i;

    if (C->d != 3 || vzero(v))
        return NAN;
    if (C->empty || C->dim == 0)
        return INFINITY;
    fmpq_init(best);
    fmpq_init(t);
    cone_project(best, NULL, v, C);
    if (fmpq_sgn(best) > 0)
    {
        /* tan^2 = |v - P v|^2 / |P v|^2 = (|v|^2 - |P v|^2) / |P v|^2 */
        vdot(t, v, v);
        fmpq_sub(t, t, best);
        fmpq_div(t, t, best);
        a = atan_sqrt(t);
    }
    else if (C->lineality_dim > 0)
        a = WC_PI / 2;  /* v is orthogonal to the lines, and polar to C */
    else
    {
        /* v in the polar cone: v.x <= 0 on C, and x -> v.x / |x| is
           quasi-concave there, so the nearest unit vector of C is at an
           extreme ray.  */
        r = _fmpq_vec_init(3);
        a = INFINITY;
        for (i = 0; i < fmpz_mat_nrows(C->rays); i++)
        {
            double b;

            _fmpq_vec_set_fmpz_vec(r, WC_ROW(C->rays, i), 3);
            b = wc_angle_vectors(v, r);
            if (b < a)
                a = b;
        }
        _fmpq_vec_clear(r, 3);
    }
    fmpq_clear(best);
    fmpq_clear(t);
    return a;
}

/* ------------------------------------------------------------------ */
/* The directed distance.  */

/* The generators of cl K as rational rows: its rays, then each line and
   its negative.  */
static void
generators(fmpq_mat_t G, const wc_cone_t K)
{
    slong k = fmpz_mat_nrows(K->rays), l = fmpz_mat_nrows(K->lines), i;

    fmpq_mat_init(G, k + 2 * l, 3);
    for (i = 0; i < k; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(G, i), WC_ROW(K->rays, i), 3);
    for (i = 0; i < l; i++)
    {
        _fmpq_vec_set_fmpz_vec(WC_ROW(G, k + 2 * i), WC_ROW(K->lines, i), 3);
        vneg(WC_ROW(G, k + 2 * i + 1), WC_ROW(G, k + 2 * i));
    }
}

/* The largest angle from a unit x of cl K (nonzero) to the line R r.  */
static double
max_angle_to_line(double * w, const wc_cone_t K, const fmpq * r)
{
    fmpq_mat_t G;
    fmpq * x = _fmpq_vec_init(3);
    fmpq_t s, t;
    int * sg;
    slong n, i, j;
    double best = -1;

    generators(G, K);
    n = fmpq_mat_nrows(G);
    sg = flint_malloc(sizeof(int) * (n + 1));
    fmpq_init(s);
    fmpq_init(t);
    for (i = 0; i < n; i++)
    {
        vdot(s, r, WC_ROW(G, i));
        sg[i] = fmpq_sgn(s);
        if (sg[i] == 0)
        {
            unit_d(w, WC_ROW(G, i));
            best = WC_PI / 2;
            goto cleanup;
        }
    }
    /* r.x changes sign on K: for generators g, h with r.g > 0 > r.h,
       x = (r.g) h - (r.h) g is in K and has r.x = 0 -- nonzero unless g
       and h are opposite (when K is a single line, all such x are 0).  */
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++)
        {
            slong c;

            if (sg[i] <= 0 || sg[j] >= 0)
                continue;
            vdot(s, r, WC_ROW(G, i));
            vdot(t, r, WC_ROW(G, j));
            for (c = 0; c < 3; c++)
            {
                fmpq_mul(x + c, s, fmpq_mat_entry(G, j, c));
                fmpq_submul(x + c, t, fmpq_mat_entry(G, i, c));
            }
            if (!vzero(x))
            {
                unit_d(w, x);
                best = WC_PI / 2;
                goto cleanup;
            }
        }
    for (i = 0; i < n; i++)
    {
        double a = wc_angle_vectors(WC_ROW(G, i), r);

        if (a > WC_PI / 2)
            a = WC_PI - a;      /* the angle to the line, not the ray */
        if (a > best)
        {
            best = a;
            unit_d(w, WC_ROW(G, i));
        }
    }

cleanup:
    fmpq_clear(s);
    fmpq_clear(t);
    flint_free(sg);
    fmpq_mat_clear(G);
    _fmpq_vec_clear(x, 3);
    return best;
}

/* The largest angle from a unit x of cl K (nonzero) to the plane n^perp.  */
static double
max_angle_to_plane(double * w, const wc_cone_t K, const fmpq * n)
{
    fmpq * q1 = _fmpq_vec_init(3), * q2 = _fmpq_vec_init(3);
    fmpq * m = _fmpq_vec_init(3);
    fmpq_t b1, b2, nn;
    fmpq_mat_t G;
    double a;

    fmpq_init(b1);
    fmpq_init(b2);
    fmpq_init(nn);
    cone_project(b1, q1, n, K);
    vneg(m, n);
    cone_project(b2, q2, m, K);
    if (fmpq_cmp(b2, b1) > 0)
    {
        fmpq_swap(b1, b2);
        vswap(q1, q2);
    }
    vdot(nn, n, n);
    if (fmpq_is_zero(b1))
    {
        /* K lies in the plane */
        generators(G, K);
        unit_d(w, WC_ROW(G, 0));
        fmpq_mat_clear(G);
        a = 0;
    }
    else
    {
        unit_d(w, q1);
        /* sin^2 = b1 / |n|^2, tan^2 = b1 / (|n|^2 - b1) */
        fmpq_sub(nn, nn, b1);
        if (fmpq_is_zero(nn))
            a = WC_PI / 2;
        else
        {
            fmpq_div(nn, b1, nn);
            a = atan_sqrt(nn);
        }
    }
    fmpq_clear(b1);
    fmpq_clear(b2);
    fmpq_clear(nn);
    _fmpq_vec_clear(q1, 3);
    _fmpq_vec_clear(q2, 3);
    _fmpq_vec_clear(m, 3);
    return a;
}

/* minimax_polar costs k^4 with k rays of B: above these many rays it
   tries fewer candidates (triples, then pairs), and its answer is then
   only a lower bound -- still at least pi/2, so it still exceeds every
   tolerance wc_compare accepts.  */
#define WC_MINIMAX_TRIPLES 48
#define WC_MINIMAX_PAIRS 400

typedef struct
{
    slong k;            /* rays of B */
    double * p;         /* 3 k: the unit vectors -r_i / |r_i| */
    slong m, q;
    double * h;         /* 3 m: K's unit facet normals */
    double * e;         /* 3 q: K's unit equality normals */
    double best;        /* the smallest max_i angle(x, p_i) so far */
    double w[3];
}
minimax;

static void
minimax_try(minimax * M, const double * x0)
{
    double x[3] = { x0[0], x0[1], x0[2] }, f = 0;
    slong i;

    if (!dnormalize(x))
        return;
    /* candidates lie on faces of K only up to rounding: a small slack */
    for (i = 0; i < M->m; i++)
        if (ddot(M->h + 3 * i, x) > 1e-9)
            return;
    for (i = 0; i < M->q; i++)
        if (fabs(ddot(M->e + 3 * i, x)) > 1e-9)
            return;
    for (i = 0; i < M->k && f < M->best; i++)
    {
        double a = dangle(x, M->p + 3 * i);

        if (a > f)
            f = a;
    }
    if (f < M->best)
    {
        M->best = f;
        memcpy(M->w, x, sizeof M->w);
    }
}

/* cl B pointed, K = cl A cap B° nonzero.  For x in K the angle to B is
   min_i angle(x, r_i) = pi - max_i angle(x, p_i), p_i = -r_i; we want its
   largest value, i.e. the smallest F(x) = max_i angle(x, p_i) over unit x
   of K.  At a minimiser x, in the relative interior of a face K' of K,
   the active p_i (those at the largest angle) are equidistant from x and
   x is stationary for their common distance within span K': x is the
   normalised projection of an active p_i onto the subspace of span K'
   equidistant from all of them (at most dim span K' of them matter:
   Caratheodory on the stationarity condition).  So F's minimum is among:
   the rays of K (dimension-1 faces, and the lines both ways), and on each
   face of dimension 2 or 3 the projections of single p_i, the
   equidistant points of pairs, and on a 3-dimensional face the
   circumcentres of triples.  The answer is at least pi/2 (K lies in B°).  */
static double
minimax_polar(double * w, const wc_cone_t K, const wc_cone_t B)
{
    minimax M;
    fmpq * dir = _fmpq_vec_init(3);
    fmpq_mat_t G;
    slong f, i, j, l;
    double a;

    M.k = fmpz_mat_nrows(B->rays);
    M.m = fmpz_mat_nrows(K->ineqs);
    M.q = fmpz_mat_nrows(K->eqs);
    M.p = flint_malloc(sizeof(double) * 3 * (M.k + 1));
    M.h = flint_malloc(sizeof(double) * 3 * (M.m + 1));
    M.e = flint_malloc(sizeof(double) * 3 * (M.q + 1));
    M.best = INFINITY;
    M.w[0] = M.w[1] = M.w[2] = 0;
    for (i = 0; i < M.k; i++)
    {
        unit_z(M.p + 3 * i, WC_ROW(B->rays, i));
        for (j = 0; j < 3; j++)
            M.p[3 * i + j] = -M.p[3 * i + j];
    }
    for (i = 0; i < M.m; i++)
        unit_z(M.h + 3 * i, WC_ROW(K->ineqs, i));
    for (i = 0; i < M.q; i++)
        unit_z(M.e + 3 * i, WC_ROW(K->eqs, i));

    /* the generators first: when the p_i project to 0 on a face spanned
       by lines, every unit vector of it is as good, and these are some */
    generators(G, K);
    for (i = 0; i < fmpq_mat_nrows(G); i++)
    {
        double g[3];

        unit_d(g, WC_ROW(G, i));
        minimax_try(&M, g);
    }
    fmpq_mat_clear(G);
    for (f = 0; f < K->nfaces; f++)
    {
        slong r = face_span(dir, K, K->faces + f);
        double b[3], x[3], d[3];

        if (r == 0)
            continue;
        unit_d(b, dir);
        if (r == 1)
        {
            minimax_try(&M, b);
            b[0] = -b[0];
            b[1] = -b[1];
            b[2] = -b[2];
            minimax_try(&M, b);
            continue;
        }
        for (i = 0; i < M.k; i++)
        {
            const double * pi = M.p + 3 * i;

            if (r == 2)
            {
                double s = ddot(pi, b);

                for (l = 0; l < 3; l++)
                    x[l] = pi[l] - s * b[l];
                minimax_try(&M, x);
            }
            else
                minimax_try(&M, pi);
            for (j = i + 1; j < M.k && M.k <= WC_MINIMAX_PAIRS; j++)
            {
                const double * pj = M.p + 3 * j;

                for (l = 0; l < 3; l++)
                    d[l] = pi[l] - pj[l];
                if (r == 2)
                {
                    dcross(x, b, d);
                    minimax_try(&M, x);
                    for (l = 0; l < 3; l++)
                        x[l] = -x[l];
                    minimax_try(&M, x);
                }
                else
                {
                    for (l = 0; l < 3; l++)
                        x[l] = pi[l] + pj[l];
                    minimax_try(&M, x);
                    if (M.k > WC_MINIMAX_TRIPLES)
                        continue;
                    for (l = j + 1; l < M.k; l++)
                    {
                        const double * pl = M.p + 3 * l;
                        double e2[3];
                        slong c;

                        for (c = 0; c < 3; c++)
                            e2[c] = pi[c] - pl[c];
                        dcross(x, d, e2);
                        minimax_try(&M, x);
                        for (c = 0; c < 3; c++)
                            x[c] = -x[c];
                        minimax_try(&M, x);
                    }
                }
            }
        }
    }
    a = WC_PI - M.best;
    if (!(a >= WC_PI / 2))
        a = WC_PI / 2;
    if (a > WC_PI)
        a = WC_PI;
    memcpy(w, M.w, sizeof M.w);
    flint_free(M.p);
    flint_free(M.h);
    flint_free(M.e);
    _fmpq_vec_clear(dir, 3);
    return a;
}

/* Stack the rows of A and B (integer, k x 3) into a rational matrix.  */
static void
stack_rows(fmpq_mat_t S, const fmpz_mat_t A, const fmpz_mat_t B)
{
    slong a = fmpz_mat_nrows(A), b = fmpz_mat_nrows(B), i;

    fmpq_mat_init(S, a + b, 3);
    for (i = 0; i < a; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(S, i), WC_ROW(A, i), 3);
    for (i = 0; i < b; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(S, a + i), WC_ROW(B, i), 3);
}

/* 1 when h . r = 0 for every ray r of face F of B.  */
static int
tight(const fmpz * h, const wc_cone_t B, const wc_face_struct * F)
{
    fmpz_t s;
    slong i, j;
    int t = 1;

    fmpz_init(s);
    for (i = 0; t && i < F->nrays; i++)
    {
        fmpz_zero(s);
        for (j = 0; j < 3; j++)
            fmpz_addmul(s, h + j, WC_ROW(B->rays, F->rays[i]) + j);
        t = fmpz_is_zero(s);
    }
    fmpz_clear(s);
    return t;
}

/* 1 when some facet h of A has h.g > 0 on every nonzero row g of R (or
   an equality of A has one strict sign on them all) and L is zero: then
   every nonzero x of pos R has h.x > 0 (resp. != 0) and is not in A.  A
   cheap exact test that spares most cells their cone computations.  */
static int
separated(const wc_cone_t A, const fmpq_mat_t R, const fmpq_mat_t L)
{
    slong m = fmpz_mat_nrows(A->ineqs), q = fmpz_mat_nrows(A->eqs), i, j;
    fmpq_t s;
    int sep = 0;

    for (j = 0; j < fmpq_mat_nrows(L); j++)
        if (!vzero(WC_ROW(L, j)))
            return 0;
    fmpq_init(s);
    for (i = 0; !sep && i < m + q; i++)
    {
        const fmpz * h = i < m ? WC_ROW(A->ineqs, i) : WC_ROW(A->eqs, i - m);
        int sign = 0, any = 0;

        sep = 1;
        for (j = 0; sep && j < fmpq_mat_nrows(R); j++)
        {
            if (vzero(WC_ROW(R, j)))
                continue;
            dot_zq(s, h, WC_ROW(R, j));
            if (i < m)
                sep = fmpq_sgn(s) > 0;
            else
            {
                sep = fmpq_sgn(s) != 0 && (sign == 0 || fmpq_sgn(s) == sign);
                sign = fmpq_sgn(s);
            }
            any = 1;
        }
        sep = sep && any;
    }
    fmpq_clear(s);
    return sep;
}

/* K = cl A cap (G + N_G), G the face F of B.  */
static int
cell(wc_cone_t K, const wc_cone_t A, const wc_cone_t B,
     const wc_face_struct * F, wc_error_t err)
{
    slong m = fmpz_mat_nrows(B->ineqs), nr = 0, i;
    fmpq_mat_t R, L, E, H;
    wc_cone_t C;
    int status = WC_OK, sep;

    fmpq_mat_init(R, F->nrays + m, 3);
    for (i = 0; i < F->nrays; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(R, nr++), WC_ROW(B->rays, F->rays[i]),
                               3);
    for (i = 0; i < m; i++)
        if (tight(WC_ROW(B->ineqs, i), B, F))
            _fmpq_vec_set_fmpz_vec(WC_ROW(R, nr++), WC_ROW(B->ineqs, i), 3);
    /* fmpq_mat has no shrink: zero rows generate nothing */
    stack_rows(L, B->lines, B->eqs);
    wc_cone_init(C, 3);
    sep = separated(A, R, L);
    if (sep)
    {
        /* K = {0}: the cone of no generator */
        fmpq_mat_t Z;

        fmpq_mat_init(Z, 0, 3);
        status = wc_cone_set_generators(K, Z, Z, err);
        fmpq_mat_clear(Z);
    }
    else
        status = wc_cone_set_generators(C, R, L, err);
    if (status == WC_OK && !sep)
    {
        stack_rows(E, A->eqs, C->eqs);
        stack_rows(H, A->ineqs, C->ineqs);
        status = wc_cone_set_hrep(K, E, H, NULL, err);
        fmpq_mat_clear(E);
        fmpq_mat_clear(H);
    }
    wc_cone_clear(C);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
    return status;
}

int
wc_cone_directed_angle(double * dist, double * witness, const wc_cone_t A,
                       const wc_cone_t B, wc_error_t err)
{
    double best = -1, w[3] = { 0, 0, 0 }, x[3];
    fmpq * dir = _fmpq_vec_init(3);
    wc_cone_t K;
    slong f;
    int status = WC_OK;

    wc_cone_init(K, 3);
    if (A->d != 3 || B->d != 3 || A->empty || B->empty)
    {
        status = wc_error_set(err, WC_EINPUT, NULL, 0, 0, "the angular "
                              "distance needs two nonempty cones in R^3");
        goto cleanup;
    }
    if (A->dim == 0)
    {
        best = 0;
        goto cleanup;
    }
    if (B->dim == 0)
    {
        fmpq_mat_t G;

        generators(G, A);
        unit_d(w, WC_ROW(G, 0));
        fmpq_mat_clear(G);
        best = INFINITY;
        goto cleanup;
    }
    for (f = 0; f < B->nfaces; f++)
    {
        const wc_face_struct * F = B->faces + f;
        double a;
        slong r;

        r = face_span(dir, B, F);
        if (r >= 3)
            continue;   /* B itself, full-dimensional: angle 0 there */
        status = cell(K, A, B, F, err);
        if (status != WC_OK)
            goto cleanup;
        if (K->empty || K->dim == 0)
            continue;
        if (r == 2)
            a = max_angle_to_plane(x, K, dir);
        else if (r == 1)
            a = max_angle_to_line(x, K, dir);
        else
            a = minimax_polar(x, K, B);
        if (a > best)
        {
            best = a;
            memcpy(w, x, sizeof w);
        }
    }
    if (best <= 0)
    {
        /* cl A lies in cl B: any of its vectors is a witness */
        fmpq_mat_t G;

        generators(G, A);
        unit_d(w, WC_ROW(G, 0));
        fmpq_mat_clear(G);
        best = 0;
    }

cleanup:
    if (status == WC_OK)
    {
        *dist = best < 0 ? 0 : best;
        if (witness != NULL)
            memcpy(witness, w, sizeof w);
    }
    wc_cone_clear(K);
    _fmpq_vec_clear(dir, 3);
    return status;
}

int
wc_cone_hausdorff_angle(double * dist, const wc_cone_t A, const wc_cone_t B,
                        wc_error_t err)
{
    double a = 0, b = 0;
    int status = wc_cone_directed_angle(&a, NULL, A, B, err);

    if (status == WC_OK)
        status = wc_cone_directed_angle(&b, NULL, B, A, err);
    if (status == WC_OK)
        *dist = a > b ? a : b;
    return status;
}

/* ------------------------------------------------------------------ */
/* Reading the foreign cone.  */

/* Limits that keep hostile files from taking forever: the exact
   conversion of a representation costs about k^3 in its k rows (and
   grows with the size of the numbers), and a float cone in R^3 from real
   code has far fewer rows, numbers far shorter.  */
#define WC_FOREIGN_MAX_ROWS 1000
#define WC_FOREIGN_MAX_CHARS 1000
#define WC_FOREIGN_MAX_EXPONENT 1000

/* A growing list of rows of 3 rationals, with the file line of each.  */
typedef struct
{
    fmpq * v;
    long * line;
    slong n, alloc;
}
rowbuf;

static void
rowbuf_init(rowbuf * b)
{
    b->v = NULL;
    b->line = NULL;
    b->n = b->alloc = 0;
}

static void
rowbuf_clear(rowbuf * b)
{
    if (b->v != NULL)
        _fmpq_vec_clear(b->v, 3 * b->alloc);
    flint_free(b->line);
    rowbuf_init(b);
}

static void
rowbuf_push(rowbuf * b, const fmpq * x, long line)
{
    if (b->n == b->alloc)
    {
        slong a = b->alloc ? 2 * b->alloc : 8, i;

        b->v = flint_realloc(b->v, sizeof(fmpq) * 3 * a);
        for (i = 3 * b->alloc; i < 3 * a; i++)
            fmpq_init(b->v + i);
        b->line = flint_realloc(b->line, sizeof(long) * a);
        b->alloc = a;
    }
    vset(b->v + 3 * b->n, x);
    b->line[b->n] = line;
    b->n++;
}

/* Move the rows into a matrix and a line array.  */
static void
rowbuf_take(fmpq_mat_t M, long ** lines, const rowbuf * b)
{
    slong i;

    fmpq_mat_clear(M);
    fmpq_mat_init(M, b->n, 3);
    for (i = 0; i < b->n; i++)
        vset(WC_ROW(M, i), b->v + 3 * i);
    flint_free(*lines);
    *lines = flint_malloc(sizeof(long) * (b->n + 1));
    if (b->n > 0)
        memcpy(*lines, b->line, sizeof(long) * b->n);
}

static void
rep_init(wc_rep_struct * R, wc_rep_kind kind, long line)
{
    R->kind = kind;
    R->line = line;
    R->empty = 0;
    fmpq_mat_init(R->rows, 0, 3);
    fmpq_mat_init(R->lin, 0, 3);
    R->row_line = flint_malloc(sizeof(long));
    R->lin_line = flint_malloc(sizeof(long));
}

static void
rep_clear(wc_rep_struct * R)
{
    fmpq_mat_clear(R->rows);
    fmpq_mat_clear(R->lin);
    flint_free(R->row_line);
    flint_free(R->lin_line);
}

void
wc_foreign_init(wc_foreign_t F)
{
    F->json = 0;
    F->arith_double = 0;
    F->mode = NULL;
    F->nreps = 0;
}

void
wc_foreign_clear(wc_foreign_t F)
{
    slong i;

    for (i = 0; i < F->nreps; i++)
        rep_clear(F->reps + i);
    free(F->mode);
    wc_foreign_init(F);
}

/* Add a representation built from the buffers.  */
static void
add_rep(wc_foreign_t F, wc_rep_kind kind, long line, int empty,
        const rowbuf * rows, const rowbuf * lin)
{
    wc_rep_struct * R = F->reps + F->nreps++;

    rep_init(R, kind, line);
    R->empty = empty;
    if (rows != NULL)
        rowbuf_take(R->rows, &R->row_line, rows);
    if (lin != NULL)
        rowbuf_take(R->lin, &R->lin_line, lin);
}

typedef struct
{
    const char * text;
    size_t len;
    const char * file;
    wc_error_struct * err;
}
source;

static int
located(const source * s, long line, long col, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static int
located(const source * s, long line, long col, const char * fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    wc_error_vset(s->err, WC_EINPUT, s->file, line, col, fmt, ap);
    va_end(ap);
    return WC_EINPUT;
}

/* located() with a message quoting t[0..n) (fmt has one %s).  */
static int
located_quoting(const source * s, long line, long col, const char * fmt,
                const char * t, size_t n)
{
    char * q = _wc_json_show(t, n);

    if (q == NULL)
        return wc_error_set(s->err, WC_EINTERNAL, s->file, 0, 0,
                            "out of memory");
    located(s, line, col, fmt, q);
    free(q);
    return WC_EINPUT;
}

/* An exact number spelt t[0..n), located at (line, col) on error.  */
static int
number(fmpq_t x, const source * s, const char * t, size_t n, long line,
       long col)
{
    size_t i, e = n;
    long ex = 0;
    int status;

    if (n > WC_FOREIGN_MAX_CHARS)
        return located(s, line, col, "number too long (over %d characters)",
                       WC_FOREIGN_MAX_CHARS);
    for (i = 0; i < n; i++)
        if (t[i] == 'e' || t[i] == 'E')
            e = i + 1;
    if (e < n && (t[e] == '+' || t[e] == '-'))
        e++;
    for (i = e; i < n && t[i] >= '0' && t[i] <= '9'; i++)
        if ((ex = 10 * ex + (t[i] - '0')) > WC_FOREIGN_MAX_EXPONENT)
            return located_quoting(s, line, col, "exponent out of range in "
                                   "'%s' (at most 1000 here)", t, n);
    status = wc_parse_number(x, t, n, s->err);

    if (status == WC_EINPUT)
    {
        /* relocate the message: wc_parse_number leaves the place to us */
        char * m = s->err->message;

        s->err->message = NULL;
        located(s, line, col, "%s", m != NULL ? m : "bad number");
        free(m);
    }
    return status;
}

/* ---- cdd ---- */

typedef struct
{
    size_t a, b;        /* bytes of the token */
    long col;
}
token;

/* The tokens of the line text[start..end) (blank-separated), at most
   max; returns how many there are in all.  */
static slong
tokenize(token * tok, slong max, const char * text, size_t start,
         size_t end)
{
    size_t i = start;
    slong n = 0;

    for (;;)
    {
        size_t a;

        while (i < end && (text[i] == ' ' || text[i] == '\t'
                           || text[i] == '\r' || text[i] == '\f'
                           || text[i] == '\v'))
            i++;
        if (i >= end)
            return n;
        a = i;
        while (i < end && !(text[i] == ' ' || text[i] == '\t'
                            || text[i] == '\r' || text[i] == '\f'
                            || text[i] == '\v'))
            i++;
        if (n < max)
        {
            tok[n].a = a;
            tok[n].b = i;
            tok[n].col = (long) (a - start) + 1;
        }
        n++;
    }
}

static int
tok_is(const source * s, const token * t, const char * word)
{
    size_t n = strlen(word);

    return t->b - t->a == n && memcmp(s->text + t->a, word, n) == 0;
}

/* A non-negative decimal integer (digits only) at most max, else -1.  */
static long long
tok_count(const source * s, const token * t, long long max)
{
    long long x = 0;
    size_t i;

    if (t->a == t->b)
        return -1;
    for (i = t->a; i < t->b; i++)
    {
        char c = s->text[i];

        if (c < '0' || c > '9')
            return -1;
        if (x > (max - (c - '0')) / 10)
            return -1;
        x = 10 * x + (c - '0');
    }
    return x;
}

typedef enum { CDD_BEFORE, CDD_HEADER, CDD_ROWS, CDD_AFTER } cdd_state;

/* One begin..end block and what precedes it.  */
typedef struct
{
    int kind;           /* -1 until a representation keyword */
    long kind_line;
    long lin_line;      /* 0 when no linearity line */
    slong nlin;
    long long * lin;    /* sorted row numbers */
    long * lin_col;     /* column of each, in file order (for messages) */
    long long * lin_raw;    /* in file order */
    long begin_line;
    long header_line;
    long long m;
    int integer;
    long long nread;
    int empty;          /* H: an infeasible row; V: m = 0 */
    rowbuf rows, lin_rows;
}
cdd_block;

static void
block_init(cdd_block * B)
{
    memset(B, 0, sizeof *B);
    B->kind = -1;
    rowbuf_init(&B->rows);
    rowbuf_init(&B->lin_rows);
}

static void
block_clear(cdd_block * B)
{
    flint_free(B->lin);
    flint_free(B->lin_col);
    flint_free(B->lin_raw);
    rowbuf_clear(&B->rows);
    rowbuf_clear(&B->lin_rows);
    block_init(B);
}

static int
cmp_ll(const void * a, const void * b)
{
    long long x = *(const long long *) a, y = *(const long long *) b;

    return (x > y) - (x < y);
}

static int
in_linearity(const cdd_block * B, long long row)
{
    return B->nlin > 0
        && bsearch(&row, B->lin, (size_t) B->nlin, sizeof(long long),
                   cmp_ll) != NULL;
}

/* 'linearity k i_1 .. i_k' on line no, tokens t[0..n).  */
static int
cdd_linearity(cdd_block * B, const source * s, long no, const char * text,
              size_t start, size_t end)
{
    slong n = tokenize(NULL, 0, text, start, end), i;
    token * t = flint_malloc(sizeof(token) * (n + 1));
    long long k = 0;
    int status = WC_OK;

    tokenize(t, n, text, start, end);
    if (B->lin_line != 0)
    {
        status = located(s, no, t[0].col, "a second 'linearity' line "
                         "(the first is line %ld)", B->lin_line);
        goto cleanup;
    }
    if (n < 2 || (k = tok_count(s, t + 1, WC_FOREIGN_MAX_ROWS)) < 0)
    {
        status = n < 2 ? located(s, no, (long) (end - start) + 1,
                                 "'linearity' needs a count and row numbers")
            : located_quoting(s, no, t[1].col, "bad linearity count '%s'",
                              text + t[1].a, t[1].b - t[1].a);
        goto cleanup;
    }
    if (n - 2 != k)
    {
        status = located(s, no, n - 2 > k ? t[2 + k].col
                         : (long) (end - start) + 1,
                         "'linearity %lld' needs %lld row numbers, found %ld",
                         k, k, (long) (n - 2));
        goto cleanup;
    }
    B->lin_line = no;
    B->nlin = (slong) k;
    B->lin = flint_malloc(sizeof(long long) * (k + 1));
    B->lin_raw = flint_malloc(sizeof(long long) * (k + 1));
    B->lin_col = flint_malloc(sizeof(long) * (k + 1));
    for (i = 0; i < k; i++)
    {
        long long r = tok_count(s, t + 2 + i, LLONG_MAX / 16);

        if (r < 1)
        {
            status = located_quoting(s, no, t[2 + i].col,
                                     "bad row number '%s' in 'linearity'",
                                     text + t[2 + i].a,
                                     t[2 + i].b - t[2 + i].a);
            goto cleanup;
        }
        B->lin[i] = B->lin_raw[i] = r;
        B->lin_col[i] = t[2 + i].col;
    }
    qsort(B->lin, (size_t) k, sizeof(long long), cmp_ll);
    for (i = 1; i < k; i++)
        if (B->lin[i] == B->lin[i - 1])
        {
            slong j;

            for (j = k - 1; j >= 0 && B->lin_raw[j] != B->lin[i]; j--)
                ;
            status = located(s, no, B->lin_col[j], "row %lld appears twice "
                             "in 'linearity'", B->lin[i]);
            goto cleanup;
        }

cleanup:
    flint_free(t);
    return status;
}

/* 'm n numbertype' after begin.  */
static int
cdd_header(cdd_block * B, const source * s, long no, const char * text,
           size_t start, size_t end)
{
    token t[4];
    slong n = tokenize(t, 4, text, start, end), i;
    long long cols;

    if (n != 3)
        return located(s, no, n > 3 ? t[3].col : (long) (end - start) + 1,
                       "expected 'm n numbertype' after 'begin' (for "
                       "example '3 4 rational')");
    B->m = tok_count(s, t + 0, LLONG_MAX / 16);
    if (B->m < 0)
        return located_quoting(s, no, t[0].col, "bad row count '%s'",
                               text + t[0].a, t[0].b - t[0].a);
    if (B->m > WC_FOREIGN_MAX_ROWS)
        return located(s, no, t[0].col, "too many rows: %lld (at most %d)",
                       B->m, WC_FOREIGN_MAX_ROWS);
    cols = tok_count(s, t + 1, 1000000);
    if (cols < 0)
        return located_quoting(s, no, t[1].col, "bad column count '%s'",
                               text + t[1].a, t[1].b - t[1].a);
    if (cols != 4)
        return located(s, no, t[1].col, "a cone in R^3 has 4 columns (1 "
                       "homogenizing + 3 coordinates), not %lld", cols);
    if (tok_is(s, t + 2, "integer"))
        B->integer = 1;
    else if (!tok_is(s, t + 2, "rational") && !tok_is(s, t + 2, "real"))
        return located_quoting(s, no, t[2].col, "unknown number type '%s' "
                               "(rational, real or integer)",
                               text + t[2].a, t[2].b - t[2].a);
    for (i = 0; i < B->nlin; i++)
        if (B->lin_raw[i] > B->m)
            return located(s, B->lin_line, B->lin_col[i], "linearity row "
                           "%lld is beyond the last row of the block (%lld)",
                           B->lin_raw[i], B->m);
    B->header_line = no;
    return WC_OK;
}

/* One row of numbers.  */
static int
cdd_row(cdd_block * B, const source * s, long no, const char * text,
        size_t start, size_t end)
{
    token t[5];
    slong n = tokenize(t, 5, text, start, end), i;
    fmpq * x = _fmpq_vec_init(4);
    long long row = B->nread + 1;
    int status = WC_OK, lin = in_linearity(B, row), zero;

    if (B->nread == B->m)
    {
        status = located(s, no, t[0].col, "expected 'end': the header "
                         "(line %ld) announces %lld row%s", B->header_line,
                         B->m, B->m == 1 ? "" : "s");
        goto cleanup;
    }
    if (n != 4)
    {
        status = located(s, no, n > 4 ? t[4].col : (long) (end - start) + 1,
                         "a row has 4 numbers, found %ld", (long) n);
        goto cleanup;
    }
    for (i = 0; i < 4; i++)
    {
        status = number(x + i, s, text + t[i].a, t[i].b - t[i].a, no,
                        t[i].col);
        if (status != WC_OK)
            goto cleanup;
        if (B->integer && !fmpz_is_one(fmpq_denref(x + i)))
        {
            status = located_quoting(s, no, t[i].col, "'%s' is not an "
                                     "integer (the number type is "
                                     "'integer')", text + t[i].a,
                                     t[i].b - t[i].a);
            goto cleanup;
        }
    }
    B->nread++;
    zero = vzero(x + 1);
    if (B->kind == WC_REP_INEQUALITIES)
    {
        /* b + a.g >= 0 (or = 0 in linearity) */
        if (zero)
        {
            if (lin ? !fmpq_is_zero(x) : fmpq_sgn(x) < 0)
                B->empty = 1;   /* 0 >= b < 0, or 0 = b != 0 */
        }
        else if (!fmpq_is_zero(x))
        {
            char * c = fmpq_get_str(NULL, 10, x);

            status = located(s, no, t[0].col, "not a cone: the constant "
                             "term b is %s; the rows 'b -A' (b - A g >= 0) "
                             "of a cone have b = 0", c);
            flint_free(c);
            goto cleanup;
        }
        else if (lin)
            rowbuf_push(&B->lin_rows, x + 1, no);
        else
        {
            vneg(x + 1, x + 1);
            rowbuf_push(&B->rows, x + 1, no);
        }
    }
    else
    {
        if (fmpq_sgn(x) < 0)
        {
            status = located(s, no, t[0].col, "a V-representation row starts "
                             "with 1 (a point) or 0 (a ray), not a negative "
                             "number");
            goto cleanup;
        }
        if (fmpq_sgn(x) > 0)
        {
            if (!zero)
                status = located(s, no, t[1].col, "not a cone: a point other "
                                 "than the origin (a cone's one point is its "
                                 "apex, '1 0 0 0')");
            else if (lin)
                status = located(s, no, t[0].col, "linearity row %lld is a "
                                 "point, not a line", row);
            goto cleanup;
        }
        if (!zero)
            rowbuf_push(lin ? &B->lin_rows : &B->rows, x + 1, no);
    }

cleanup:
    _fmpq_vec_clear(x, 4);
    return status;
}

static int
cdd_finish(wc_foreign_t F, cdd_block * B, const source * s, long no,
           long col)
{
    if (B->nread < B->m)
        return located(s, no, col, "found %lld row%s before 'end', but the "
                       "header (line %ld) announces %lld", B->nread,
                       B->nread == 1 ? "" : "s", B->header_line, B->m);
    if (B->kind == WC_REP_GENERATORS && B->m == 0)
        B->empty = 1;
    add_rep(F, (wc_rep_kind) B->kind, B->kind_line, B->empty, &B->rows,
            &B->lin_rows);
    block_clear(B);
    return WC_OK;
}

static int
parse_cdd(wc_foreign_t F, const source * s)
{
    const char * text = s->text;
    size_t pos = 0, len = s->len;
    long no = 0, last_col = 1;
    cdd_state st = CDD_BEFORE;
    cdd_block B;
    int status = WC_OK, seen_line = 0;
    char * nul = memchr(text, '\0', len);

    block_init(&B);
    if (nul != NULL)
    {
        size_t at = (size_t) (nul - text), i, ls = 0;
        long l = 1;

        for (i = 0; i < at; i++)
            if (text[i] == '\n')
            {
                l++;
                ls = i + 1;
            }
        return located(s, l, (long) (at - ls) + 1, "NUL byte in the file");
    }
    while (pos < len && status == WC_OK)
    {
        size_t start = pos, end;
        const char * nl = memchr(text + pos, '\n', len - pos);
        token t[2];
        slong n;

        end = nl != NULL ? (size_t) (nl - text) : len;
        pos = nl != NULL ? end + 1 : len;
        no++;
        last_col = (long) (end - start) + 1;
        n = tokenize(t, 2, text, start, end);
        if (n == 0 || text[t[0].a] == '*')
            continue;
        switch (st)
        {
        case CDD_AFTER:
        case CDD_BEFORE:
            if (tok_is(s, t, "H-representation")
                || tok_is(s, t, "V-representation"))
            {
                int k = tok_is(s, t, "H-representation")
                    ? WC_REP_INEQUALITIES : WC_REP_GENERATORS;

                if (n > 1)
                    status = located_quoting(s, no, t[1].col, "unexpected "
                                             "'%s' after the representation",
                                             text + t[1].a,
                                             t[1].b - t[1].a);
                else if (B.kind >= 0)
                    status = located(s, no, t[0].col, "a second "
                                     "representation keyword (the first is "
                                     "line %ld)", B.kind_line);
                else if (F->nreps == 2 || (F->nreps == 1
                                           && (int) F->reps[0].kind == k))
                    status = located(s, no, t[0].col, "a second %s",
                                     k == WC_REP_INEQUALITIES
                                     ? "H-representation"
                                     : "V-representation");
                else
                {
                    B.kind = k;
                    B.kind_line = no;
                }
            }
            else if (tok_is(s, t, "linearity"))
                status = cdd_linearity(&B, s, no, text, start, end);
            else if (tok_is(s, t, "begin"))
            {
                if (n > 1)
                    status = located_quoting(s, no, t[1].col, "unexpected "
                                             "'%s' after 'begin'",
                                             text + t[1].a,
                                             t[1].b - t[1].a);
                else
                {
                    if (B.kind < 0)
                    {
                        /* cdd's default */
                        B.kind = WC_REP_INEQUALITIES;
                        B.kind_line = no;
                        if (F->nreps == 1
                            && F->reps[0].kind == WC_REP_INEQUALITIES)
                            status = located(s, no, t[0].col, "a second "
                                             "H-representation");
                    }
                    B.begin_line = no;
                    st = CDD_HEADER;
                }
            }
            else if (st == CDD_BEFORE && !seen_line && B.kind < 0
                     && B.lin_line == 0)
                ;   /* a name line, as lrs writes */
            else
                status = located_quoting(s, no, t[0].col, st == CDD_BEFORE
                                         ? "unexpected '%s' before 'begin'"
                                         : "unexpected '%s' after 'end'",
                                         text + t[0].a, t[0].b - t[0].a);
            seen_line = 1;
            break;
        case CDD_HEADER:
            status = cdd_header(&B, s, no, text, start, end);
            if (status == WC_OK)
                st = CDD_ROWS;
            break;
        case CDD_ROWS:
            if (tok_is(s, t, "end"))
            {
                if (n > 1)
                    status = located_quoting(s, no, t[1].col, "unexpected "
                                             "'%s' after 'end'",
                                             text + t[1].a,
                                             t[1].b - t[1].a);
                else
                    status = cdd_finish(F, &B, s, no, t[0].col);
                st = CDD_AFTER;
            }
            else
                status = cdd_row(&B, s, no, text, start, end);
            break;
        }
    }
    if (status == WC_OK)
    {
        /* the position after the last byte */
        if (len > 0 && text[len - 1] == '\n')
        {
            no++;
            last_col = 1;
        }
        if (no == 0)
            no = 1;
        if (st == CDD_HEADER || st == CDD_ROWS)
            status = located(s, no, last_col, "end of file before 'end'");
        else if (st == CDD_BEFORE || B.kind >= 0 || B.lin_line != 0)
            status = located(s, no, last_col, F->nreps == 0 && B.kind < 0
                             && B.lin_line == 0
                             ? "no cone here: expected a cdd file "
                             "(H- or V-representation, 'begin' .. 'end') "
                             "or a JSON cone" : "end of file before 'begin'");
    }
    block_clear(&B);
    return status;
}

/* ---- JSON ---- */

static int
at_node(const source * s, const wc_json_node * v, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int
at_node(const source * s, const wc_json_node * v, const char * fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    wc_error_vset(s->err, WC_EINPUT, s->file, v->line, v->col, fmt, ap);
    va_end(ap);
    return WC_EINPUT;
}

/* The vectors under key in cone object o, if the key is there.  */
static int
json_vectors(rowbuf * out, const wc_json_node ** present, const source * s,
             const wc_json_node * o, const char * key)
{
    const wc_json_node * a = _wc_json_object_get(o, key);
    fmpq * x = NULL;
    size_t i, j;
    int status = WC_OK;

    *present = a;
    if (a == NULL)
        return WC_OK;
    if (a->type != WC_JSON_ARRAY)
        return at_node(s, a, "'%s' must be an array", key);
    if (a->len > WC_FOREIGN_MAX_ROWS)
        return at_node(s, a, "too many rows in '%s': %lu (at most %d)", key,
                       (unsigned long) a->len, WC_FOREIGN_MAX_ROWS);
    x = _fmpq_vec_init(3);
    for (i = 0; i < a->len && status == WC_OK; i++)
    {
        const wc_json_node * e = a->items + i;

        if (e->type != WC_JSON_ARRAY || e->len != 3)
        {
            status = at_node(s, e, "each entry of '%s' must be an array of "
                             "3 numbers", key);
            break;
        }
        for (j = 0; j < 3 && status == WC_OK; j++)
        {
            const wc_json_node * v = e->items + j;

            if (v->type == WC_JSON_NUMBER || v->type == WC_JSON_STRING)
                status = number(x + j, s, v->text, v->len, v->line, v->col);
            else
                status = at_node(s, v, "expected a number, found %s",
                                 _wc_json_type_name(v->type));
        }
        if (status == WC_OK)
            rowbuf_push(out, x, e->line);
    }
    _fmpq_vec_clear(x, 3);
    return status;
}

static int
parse_json(wc_foreign_t F, const source * s)
{
    wc_json_t J;
    const wc_json_node * root, * c, * m, * e, * a, * rays, * lines, * ineqs,
        * eqs;
    rowbuf R, L, H, E;
    int status;

    _wc_json_init(J);
    rowbuf_init(&R);
    rowbuf_init(&L);
    rowbuf_init(&H);
    rowbuf_init(&E);
    status = _wc_json_parse(J, s->text, s->len, s->file, s->err);
    if (status != WC_OK)
        goto cleanup;
    root = c = &J->root;
    if (root->type != WC_JSON_OBJECT)
    {
        status = at_node(s, root, "expected a JSON object: a cone, or "
                         "{\"mode\": .., \"cone\": ..}");
        goto cleanup;
    }
    m = _wc_json_object_get(root, "mode");
    if ((a = _wc_json_object_get(root, "cone")) != NULL)
    {
        if (a->type != WC_JSON_OBJECT)
        {
            status = at_node(s, a, "'cone' must be an object");
            goto cleanup;
        }
        if (m != NULL && m->type != WC_JSON_STRING)
        {
            status = at_node(s, m, "'mode' must be a string");
            goto cleanup;
        }
        if (m != NULL)
        {
            F->mode = malloc(m->len + 1);
            if (F->mode == NULL)
            {
                status = wc_error_set(s->err, WC_EINTERNAL, s->file, 0, 0,
                                      "out of memory");
                goto cleanup;
            }
            memcpy(F->mode, m->text, m->len + 1);
        }
        c = a;
    }
    if ((e = _wc_json_object_get(c, "empty")) == NULL)
    {
        status = at_node(s, c, "missing key 'empty'");
        goto cleanup;
    }
    if (e->type != WC_JSON_TRUE && e->type != WC_JSON_FALSE)
    {
        status = at_node(s, e, "'empty' must be true or false");
        goto cleanup;
    }
    if ((a = _wc_json_object_get(c, "arith")) != NULL)
    {
        if (a->type != WC_JSON_STRING)
        {
            status = at_node(s, a, "'arith' must be a string");
            goto cleanup;
        }
        F->arith_double = strcmp(a->text, "double") == 0;
    }
    if (e->type == WC_JSON_TRUE)
    {
        add_rep(F, WC_REP_STATED, c->line, 1, NULL, NULL);
        goto cleanup;
    }
    if ((status = json_vectors(&R, &rays, s, c, "rays")) != WC_OK
        || (status = json_vectors(&L, &lines, s, c, "lines")) != WC_OK
        || (status = json_vectors(&H, &ineqs, s, c, "inequalities")) != WC_OK
        || (status = json_vectors(&E, &eqs, s, c, "equalities")) != WC_OK)
        goto cleanup;
    if (rays == NULL && lines == NULL && ineqs == NULL && eqs == NULL)
    {
        status = at_node(s, c, "a nonempty cone needs 'rays' or "
                         "'inequalities'");
        goto cleanup;
    }
    if (rays != NULL || lines != NULL)
        add_rep(F, WC_REP_GENERATORS, rays != NULL ? rays->line : lines->line,
                0, &R, &L);
    if (ineqs != NULL || eqs != NULL)
        add_rep(F, WC_REP_INEQUALITIES,
                ineqs != NULL ? ineqs->line : eqs->line, 0, &H, &E);

cleanup:
    rowbuf_clear(&R);
    rowbuf_clear(&L);
    rowbuf_clear(&H);
    rowbuf_clear(&E);
    _wc_json_clear(J);
    return status;
}

int
wc_foreign_parse(wc_foreign_t F, const char * text, size_t len,
                 const char * file, wc_error_t err)
{
    source s;
    size_t i = 0;
    int status;

    s.text = text;
    s.len = len;
    s.file = file;
    s.err = err;
    wc_foreign_clear(F);
    while (i < len && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r'
                       || text[i] == '\n'))
        i++;
    if (i < len && (text[i] == '{' || text[i] == '['))
    {
        F->json = 1;
        status = parse_json(F, &s);
    }
    else
        status = parse_cdd(F, &s);
    if (status != WC_OK)
        wc_foreign_clear(F);
    return status;
}

/* ------------------------------------------------------------------ */
/* The comparison.  */

static void
cmp_rep_init(wc_cmp_rep_struct * C)
{
    C->kind = WC_REP_GENERATORS;
    C->line = 0;
    wc_cone_init(C->cone, 3);
    C->nrays = C->nfacets = C->nexact_rays = C->nexact_facets = 0;
    C->rays = C->facets = C->exact_rays = C->exact_facets = NULL;
    C->exact_to_float = C->float_to_exact = C->hausdorff = NAN;
    C->nredundant = 0;
    C->redundant = NULL;
    C->differs = 0;
}

static void
cmp_rep_clear(wc_cmp_rep_struct * C)
{
    wc_cone_clear(C->cone);
    flint_free(C->rays);
    flint_free(C->facets);
    flint_free(C->exact_rays);
    flint_free(C->exact_facets);
    flint_free(C->redundant);
}

void
wc_comparison_init(wc_comparison_t R)
{
    R->tol = WC_COMPARE_TOL;
    R->json_file = 0;
    R->nreps = 0;
    R->file_mode = NULL;
    R->differs = 0;
}

void
wc_comparison_clear(wc_comparison_t R)
{
    slong i;

    for (i = 0; i < R->nreps; i++)
        cmp_rep_clear(R->reps + i);
    free(R->file_mode);
    wc_comparison_init(R);
}

static wc_cmp_vec *
new_vecs(slong n)
{
    wc_cmp_vec * V = flint_calloc(n + 1, sizeof(wc_cmp_vec));
    slong i;

    for (i = 0; i < n; i++)
    {
        V[i].angle = NAN;
        V[i].nearest = -1;
        V[i].nearest_angle = INFINITY;
    }
    return V;
}

/* For each row of A its nearest row of B and the other way round (the
   angle between each pair is computed once).  */
static void
match(wc_cmp_vec ** pa, wc_cmp_vec ** pb, const fmpz_mat_t A,
      const fmpz_mat_t B, double tol)
{
    slong a = fmpz_mat_nrows(A), b = fmpz_mat_nrows(B), i, j;
    wc_cmp_vec * U = new_vecs(a), * V = new_vecs(b);
    fmpq_mat_t Aq, Bq;

    fmpq_mat_init(Aq, a, 3);
    fmpq_mat_init(Bq, b, 3);
    fmpq_mat_set_fmpz_mat(Aq, A);
    fmpq_mat_set_fmpz_mat(Bq, B);
    for (i = 0; i < a; i++)
        unit_d(U[i].unit, WC_ROW(Aq, i));
    for (j = 0; j < b; j++)
        unit_d(V[j].unit, WC_ROW(Bq, j));
    for (i = 0; i < a; i++)
        for (j = 0; j < b; j++)
        {
            double t = wc_angle_vectors(WC_ROW(Aq, i), WC_ROW(Bq, j));

            if (t < U[i].nearest_angle)
            {
                U[i].nearest_angle = t;
                U[i].nearest = j;
            }
            if (t < V[j].nearest_angle)
            {
                V[j].nearest_angle = t;
                V[j].nearest = i;
            }
        }
    for (i = 0; i < a; i++)
        U[i].matched = U[i].nearest_angle <= tol;
    for (j = 0; j < b; j++)
        V[j].matched = V[j].nearest_angle <= tol;
    fmpq_mat_clear(Aq);
    fmpq_mat_clear(Bq);
    *pa = U;
    *pb = V;
}

/* The angle of every row of A to cl C.  */
static void
angles_to(wc_cmp_vec * U, const fmpz_mat_t A, const wc_cone_t C)
{
    fmpq * v = _fmpq_vec_init(3);
    slong i;

    for (i = 0; i < fmpz_mat_nrows(A); i++)
    {
        _fmpq_vec_set_fmpz_vec(v, WC_ROW(A, i), 3);
        U[i].angle = wc_angle_to_cone(v, C);
    }
    _fmpq_vec_clear(v, 3);
}

/* The file line of an input row (of P) on each canonical vector of X:
   the rows are first stripped of their component in span S (the cone's
   lines for rays, its equalities for facets), as the canonical form
   does.  The lines of the input rows on no canonical vector (redundant
   rows) go to C->redundant.  */
static void
source_lines(wc_cmp_rep_struct * C, wc_cmp_vec * U, const fmpz_mat_t X,
             const fmpq_mat_t P, const long * lines, const fmpz_mat_t S)
{
    fmpq * dir = _fmpq_vec_init(3), * p = _fmpq_vec_init(3);
    fmpq * x = _fmpq_vec_init(3), * q = _fmpq_vec_init(3);
    slong r = rows_span(dir, S), i, j, c;

    C->redundant = flint_malloc(sizeof(long) * (fmpq_mat_nrows(P) + 1));
    for (j = 0; j < fmpq_mat_nrows(P); j++)
    {
        int on = 0;

        span_project(q, WC_ROW(P, j), r, dir);
        for (c = 0; c < 3; c++)
            fmpq_sub(p + c, fmpq_mat_entry(P, j, c), q + c);
        for (i = 0; !vzero(p) && i < fmpz_mat_nrows(X); i++)
        {
            _fmpq_vec_set_fmpz_vec(x, WC_ROW(X, i), 3);
            if (!same_ray(x, p))
                continue;
            /* a second row on the same ray is redundant too */
            if (U[i].line == 0)
            {
                U[i].line = lines[j];
                on = 1;
            }
            break;
        }
        if (!on)
            C->redundant[C->nredundant++] = lines[j];
    }
    _fmpq_vec_clear(dir, 3);
    _fmpq_vec_clear(p, 3);
    _fmpq_vec_clear(x, 3);
    _fmpq_vec_clear(q, 3);
}

static int
any_unmatched(const wc_cmp_vec * U, slong n)
{
    slong i;

    for (i = 0; i < n; i++)
        if (!U[i].matched)
            return 1;
    return 0;
}

static int
compare_rep(wc_cmp_rep_struct * C, const wc_cone_t W, const wc_rep_struct * P,
            double tol, wc_error_t err)
{
    wc_cone_struct * F = C->cone;
    int status = WC_OK;

    C->kind = P->kind;
    C->line = P->line;
    if (!P->empty && P->kind == WC_REP_GENERATORS)
        status = wc_cone_set_generators(F, P->rows, P->lin, err);
    else if (!P->empty && P->kind == WC_REP_INEQUALITIES)
        status = wc_cone_set_hrep(F, P->lin, P->rows, NULL, err);
    else
        wc_cone_set_empty(F);
    if (status != WC_OK)
        return status;
    if (W->empty != F->empty)
    {
        C->differs |= WC_CMP_EMPTY;
        return WC_OK;
    }
    if (W->empty)
        return WC_OK;
    if (W->dim != F->dim)
        C->differs |= WC_CMP_DIM;
    if (W->lineality_dim != F->lineality_dim)
        C->differs |= WC_CMP_LINEALITY;

    C->nrays = fmpz_mat_nrows(F->rays);
    C->nexact_rays = fmpz_mat_nrows(W->rays);
    match(&C->rays, &C->exact_rays, F->rays, W->rays, tol);
    angles_to(C->rays, F->rays, W);
    angles_to(C->exact_rays, W->rays, F);
    C->nfacets = fmpz_mat_nrows(F->ineqs);
    C->nexact_facets = fmpz_mat_nrows(W->ineqs);
    match(&C->facets, &C->exact_facets, F->ineqs, W->ineqs, tol);
    if (P->kind == WC_REP_GENERATORS)
        source_lines(C, C->rays, F->rays, P->rows, P->row_line, F->lines);
    else
        source_lines(C, C->facets, F->ineqs, P->rows, P->row_line, F->eqs);

    status = wc_cone_directed_angle(&C->exact_to_float, NULL, W, F, err);
    if (status == WC_OK)
        status = wc_cone_directed_angle(&C->float_to_exact, NULL, F, W, err);
    if (status != WC_OK)
        return status;
    C->hausdorff = C->exact_to_float > C->float_to_exact
        ? C->exact_to_float : C->float_to_exact;
    if (!(C->hausdorff <= tol))
        C->differs |= WC_CMP_DISTANCE;
    if (any_unmatched(C->rays, C->nrays)
        || any_unmatched(C->exact_rays, C->nexact_rays))
        C->differs |= WC_CMP_RAYS;
    if (any_unmatched(C->facets, C->nfacets)
        || any_unmatched(C->exact_facets, C->nexact_facets))
        C->differs |= WC_CMP_FACETS;
    return WC_OK;
}

int
wc_compare(wc_comparison_t R, const wc_cone_t W, const char * mode,
           const wc_foreign_t F, double tol, wc_error_t err)
{
    slong i;
    int status = WC_OK;

    wc_comparison_clear(R);
    if (!(tol >= 0 && tol < WC_PI / 2))
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "the tolerance must "
                            "be an angle in radians, at least 0 and below "
                            "pi/2");
    if (W->d != 3)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "compare works on "
                            "cones in R^3");
    if (F->nreps == 0)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "no foreign cone "
                            "to compare");
    R->tol = tol;
    R->json_file = F->json;
    if (F->mode != NULL && mode != NULL && strcmp(F->mode, mode) != 0)
    {
        R->file_mode = malloc(strlen(F->mode) + 1);
        if (R->file_mode == NULL)
            return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                "out of memory");
        strcpy(R->file_mode, F->mode);
        R->differs |= WC_CMP_MODE;
    }
    for (i = 0; i < F->nreps && status == WC_OK; i++)
    {
        cmp_rep_init(R->reps + i);
        R->nreps++;
        status = compare_rep(R->reps + i, W, F->reps + i, tol, err);
        R->differs |= R->reps[i].differs;
    }
    if (status != WC_OK)
        wc_comparison_clear(R);
    return status;
}

/* ------------------------------------------------------------------ */
/* The report.  */

static const char *
rep_title(wc_rep_kind k, int json)
{
    if (k == WC_REP_GENERATORS)
        return json ? "generators ('rays', 'lines')"
            : "V-representation (generators)";
    if (k == WC_REP_INEQUALITIES)
        return json ? "inequalities ('inequalities', 'equalities')"
            : "H-representation (inequalities)";
    return "'empty': true";
}

static const char *
rep_key(wc_rep_kind k)
{
    return k == WC_REP_GENERATORS ? "generators"
        : k == WC_REP_INEQUALITIES ? "inequalities" : "statement";
}

static void
text_angle(FILE * out, double a)
{
    if (isnan(a))
        fputs("n/a", out);
    else if (isinf(a))
        fputs("inf (no unit vector on the other side)", out);
    else
        fprintf(out, "%.6g", a);
}

static void
text_unit(FILE * out, const double * u)
{
    fprintf(out, "(%.6g, %.6g, %.6g)", u[0] + 0.0, u[1] + 0.0, u[2] + 0.0);
}

static void
json_double(FILE * out, double a)
{
    if (isfinite(a))
        fprintf(out, "%.17g", a + 0.0);
    else
        fputs("null", out);
}

static void
json_unit(FILE * out, const double * u)
{
    putc('[', out);
    json_double(out, u[0]);
    fputs(", ", out);
    json_double(out, u[1]);
    fputs(", ", out);
    json_double(out, u[2]);
    putc(']', out);
}

/* "r2 r5" for the unmatched entries of U named prefix + index; returns
   how many.  */
static slong
text_unmatched(FILE * out, const wc_cmp_vec * U, slong n, const char * prefix,
               int lines)
{
    slong i, c = 0;

    for (i = 0; i < n; i++)
        if (!U[i].matched)
        {
            fprintf(out, "%s%s%ld", c ? (lines ? ", " : " ") : "", prefix,
                    (long) i);
            if (lines && U[i].line != 0)
                fprintf(out, " (line %ld)", U[i].line);
            c++;
        }
    return c;
}

static slong
count_unmatched(const wc_cmp_vec * U, slong n)
{
    slong i, c = 0;

    for (i = 0; i < n; i++)
        c += !U[i].matched;
    return c;
}

static void
text_vecs(FILE * out, const wc_cmp_vec * U, slong n, const char * name,
          const char * other, int rays)
{
    slong i;

    for (i = 0; i < n; i++)
    {
        char id[32];

        snprintf(id, sizeof id, "%s%ld", name, (long) i);
        fprintf(out, "    %-5s ", id);
        text_unit(out, U[i].unit);
        if (U[i].line != 0)
            fprintf(out, "  line %ld", U[i].line);
        if (rays)
        {
            fputs("  angle ", out);
            text_angle(out, U[i].angle);
        }
        if (U[i].nearest >= 0)
        {
            fprintf(out, "  nearest %s%ld at ", other, (long) U[i].nearest);
            text_angle(out, U[i].nearest_angle);
        }
        else
            fputs("  nearest: none", out);
        putc('\n', out);
    }
}

static void
text_cone_summary(FILE * out, const wc_cone_t C)
{
    if (C->empty)
    {
        fputs("empty", out);
        return;
    }
    fprintf(out, "nonempty, dimension %ld, lineality %ld, %ld extreme "
            "ray%s, %ld facet%s", (long) C->dim, (long) C->lineality_dim,
            (long) fmpz_mat_nrows(C->rays),
            fmpz_mat_nrows(C->rays) == 1 ? "" : "s",
            (long) fmpz_mat_nrows(C->ineqs),
            fmpz_mat_nrows(C->ineqs) == 1 ? "" : "s");
}

/* The reasons a representation is outside the tolerance, "; "-separated,
   each prefixed by prefix.  first says whether none was written yet.  */
static void
text_reasons(FILE * out, const wc_cmp_rep_struct * C, const wc_cone_t W,
             double tol, const char * prefix, int * first)
{
    const wc_cone_struct * F = C->cone;
    slong c;

#define NEXT() (fputs(*first ? "" : "; ", out), *first = 0, \
                fputs(prefix, out))
    if (C->differs & WC_CMP_EMPTY)
    {
        NEXT();
        fprintf(out, "emptiness differs (exact %s, float %s)",
                W->empty ? "empty" : "nonempty",
                F->empty ? "empty" : "nonempty");
    }
    if (C->differs & WC_CMP_DIM)
    {
        NEXT();
        fprintf(out, "dimension differs (exact %ld, float %ld)",
                (long) W->dim, (long) F->dim);
    }
    if (C->differs & WC_CMP_LINEALITY)
    {
        NEXT();
        fprintf(out, "lineality differs (exact %ld, float %ld)",
                (long) W->lineality_dim, (long) F->lineality_dim);
    }
    if (C->differs & WC_CMP_DISTANCE)
    {
        NEXT();
        fputs("Hausdorff distance ", out);
        text_angle(out, C->hausdorff);
        fprintf(out, " > tol %g", tol);
    }
    if ((c = count_unmatched(C->exact_rays, C->nexact_rays)) > 0)
    {
        NEXT();
        fprintf(out, "%ld missing ray%s (", (long) c, c == 1 ? "" : "s");
        text_unmatched(out, C->exact_rays, C->nexact_rays, "r", 0);
        putc(')', out);
    }
    if ((c = count_unmatched(C->rays, C->nrays)) > 0)
    {
        NEXT();
        fprintf(out, "%ld extra ray%s (", (long) c, c == 1 ? "" : "s");
        text_unmatched(out, C->rays, C->nrays, "fr", 0);
        putc(')', out);
    }
    if ((c = count_unmatched(C->exact_facets, C->nexact_facets)) > 0)
    {
        NEXT();
        fprintf(out, "%ld missing facet%s (", (long) c, c == 1 ? "" : "s");
        text_unmatched(out, C->exact_facets, C->nexact_facets, "h", 0);
        putc(')', out);
    }
    if ((c = count_unmatched(C->facets, C->nfacets)) > 0)
    {
        NEXT();
        fprintf(out, "%ld extra facet%s (", (long) c, c == 1 ? "" : "s");
        text_unmatched(out, C->facets, C->nfacets, "fh", 0);
        putc(')', out);
    }
#undef NEXT
}

static void
text_rep(FILE * out, const wc_cmp_rep_struct * C, const wc_cone_t W,
         const char * file, int json_file)
{
    const wc_cone_struct * F = C->cone;

    fprintf(out, "\nfloat cone: %s, %s at line %ld\n", file,
            rep_title(C->kind, json_file), C->line);
    fputs("  read exactly: ", out);
    text_cone_summary(out, F);
    fprintf(out, "\n  emptiness: exact %s, float %s\n",
            W->empty ? "empty" : "nonempty", F->empty ? "empty" : "nonempty");
    if (W->empty || F->empty)
    {
        if (W->empty != F->empty)
            fputs("  (the closures are not compared: one side is empty)\n",
                  out);
        return;
    }
    fprintf(out, "  dimension: exact %ld, float %ld; lineality: exact %ld, "
            "float %ld\n", (long) W->dim, (long) F->dim,
            (long) W->lineality_dim, (long) F->lineality_dim);
    fprintf(out, "  float extreme rays: angle to the exact closure, nearest "
            "exact ray%s\n", C->nrays ? "" : ": none");
    text_vecs(out, C->rays, C->nrays, "fr", "r", 1);
    fprintf(out, "  exact extreme rays: angle to the float closure, nearest "
            "float ray%s\n", C->nexact_rays ? "" : ": none");
    text_vecs(out, C->exact_rays, C->nexact_rays, "r", "fr", 1);
    fprintf(out, "  float facets (unit h, h . g <= 0): nearest exact "
            "facet%s\n", C->nfacets ? "" : ": none");
    text_vecs(out, C->facets, C->nfacets, "fh", "h", 0);
    fprintf(out, "  exact facets: nearest float facet%s\n",
            C->nexact_facets ? "" : ": none");
    text_vecs(out, C->exact_facets, C->nexact_facets, "h", "fh", 0);
    fputs("  Hausdorff distance ", out);
    text_angle(out, C->hausdorff);
    fputs(" (exact to float ", out);
    text_angle(out, C->exact_to_float);
    fputs(", float to exact ", out);
    text_angle(out, C->float_to_exact);
    fputs(")\n  missing rays: ", out);
    if (text_unmatched(out, C->exact_rays, C->nexact_rays, "r", 1) == 0)
        fputs("none", out);
    fputs("\n  extra rays: ", out);
    if (text_unmatched(out, C->rays, C->nrays, "fr", 1) == 0)
        fputs("none", out);
    fputs("\n  missing facets: ", out);
    if (text_unmatched(out, C->exact_facets, C->nexact_facets, "h", 1) == 0)
        fputs("none", out);
    fputs("\n  extra facets: ", out);
    if (text_unmatched(out, C->facets, C->nfacets, "fh", 1) == 0)
        fputs("none", out);
    putc('\n', out);
    if (C->nredundant > 0)
    {
        slong i;

        fprintf(out, "  redundant input rows (on no %s of the float cone): "
                "line", C->kind == WC_REP_GENERATORS ? "extreme ray"
                : "facet");
        for (i = 0; i < C->nredundant; i++)
            fprintf(out, "%s %ld", i ? "," : (C->nredundant > 1 ? "s" : ""),
                    C->redundant[i]);
        putc('\n', out);
    }
}

static void
json_vecs(FILE * out, const wc_cmp_vec * U, slong n, const char * dirkey,
          const char * otherkey, const char * flag, int rays, int foreign)
{
    slong i;

    putc('[', out);
    for (i = 0; i < n; i++)
    {
        fprintf(out, "%s{\"%s\": ", i ? ", " : "", dirkey);
        json_unit(out, U[i].unit);
        if (foreign)
        {
            fputs(", \"line\": ", out);
            if (U[i].line != 0)
                fprintf(out, "%ld", U[i].line);
            else
                fputs("null", out);
        }
        if (rays)
        {
            fprintf(out, ", \"angle_to_%s\": ", foreign ? "exact" : "float");
            json_double(out, U[i].angle);
        }
        fprintf(out, ", \"nearest_%s\": ", otherkey);
        if (U[i].nearest >= 0)
            fprintf(out, "%ld", (long) U[i].nearest);
        else
            fputs("null", out);
        fputs(", \"nearest_angle\": ", out);
        json_double(out, U[i].nearest_angle);
        fprintf(out, ", \"%s\": %s}", flag, U[i].matched ? "false" : "true");
    }
    putc(']', out);
}

static void
json_differences(FILE * out, unsigned d)
{
    static const char * const name[] = {
        "empty", "dimension", "lineality", "distance", "rays", "facets",
        "mode"
    };
    int i, first = 1;

    putc('[', out);
    for (i = 0; i < 7; i++)
        if (d & (1u << i))
        {
            fprintf(out, "%s\"%s\"", first ? "" : ", ", name[i]);
            first = 0;
        }
    putc(']', out);
}

static void
json_rows_unit(FILE * out, const fmpz_mat_t A)
{
    slong i;
    double u[3];

    putc('[', out);
    for (i = 0; i < fmpz_mat_nrows(A); i++)
    {
        fputs(i ? ", " : "", out);
        unit_z(u, WC_ROW(A, i));
        json_unit(out, u);
    }
    putc(']', out);
}

static void
json_rep(FILE * out, const wc_cmp_rep_struct * C)
{
    const wc_cone_struct * F = C->cone;
    slong i;

    fprintf(out, "{\"representation\": \"%s\", \"line\": %ld, \"empty\": %s",
            rep_key(C->kind), C->line, F->empty ? "true" : "false");
    if (!F->empty)
        fprintf(out, ", \"dim\": %ld, \"lineality_dim\": %ld", (long) F->dim,
                (long) F->lineality_dim);
    fputs(", \"rays\": ", out);
    json_vecs(out, C->rays, C->nrays, "direction", "exact", "extra", 1, 1);
    fputs(", \"facets\": ", out);
    json_vecs(out, C->facets, C->nfacets, "normal", "exact", "extra", 0, 1);
    fputs(", \"exact_rays\": ", out);
    json_vecs(out, C->exact_rays, C->nexact_rays, "direction", "float",
              "missing", 1, 0);
    fputs(", \"exact_facets\": ", out);
    json_vecs(out, C->exact_facets, C->nexact_facets, "normal", "float",
              "missing", 0, 0);
    fputs(", \"redundant_lines\": [", out);
    for (i = 0; i < C->nredundant; i++)
        fprintf(out, "%s%ld", i ? ", " : "", C->redundant[i]);
    fputs("], \"hausdorff\": ", out);
    json_double(out, C->hausdorff);
    fputs(", \"exact_to_float\": ", out);
    json_double(out, C->exact_to_float);
    fputs(", \"float_to_exact\": ", out);
    json_double(out, C->float_to_exact);
    fputs(", \"differences\": ", out);
    json_differences(out, C->differs);
    putc('}', out);
}

/* The faces of cl W that W excludes: "dim 0 (the apex); dim 1 {r0}".  */
static void
text_excluded(FILE * out, const wc_cone_t W)
{
    slong f, i, n = 0;

    for (f = 0; f < W->nfaces; f++)
    {
        const wc_face_struct * F = W->faces + f;

        if (F->included)
            continue;
        fprintf(out, "%sdim %ld ", n ? "; " : "", (long) F->dim);
        if (F->nrays == 0)
            fputs(W->lineality_dim ? "(the lineality space)" : "(the apex)",
                  out);
        else
        {
            putc('{', out);
            for (i = 0; i < F->nrays; i++)
                fprintf(out, "%sr%ld", i ? " " : "", (long) F->rays[i]);
            putc('}', out);
        }
        n++;
    }
}

static const char strict_note[] = "strictness cannot be read from a float "
    "cone; check your handling of strict inequalities";

int
wc_comparison_fprint(FILE * out, const wc_comparison_t R, const wc_cone_t W,
                     const char * problem, const char * mode,
                     const char * file, int json)
{
    slong i, f, excl = W->empty ? 0 : wc_cone_excluded_faces(W);
    int first = 1;

    if (json)
    {
        fputs("{\"exact\": {\"arith\": \"gmp\", \"problem\": ", out);
        wc_fprint_json_string(out, problem);
        fputs(", \"mode\": ", out);
        wc_fprint_json_string(out, mode);
        fprintf(out, ", \"empty\": %s", W->empty ? "true" : "false");
        if (!W->empty)
        {
            fprintf(out, ", \"dim\": %ld, \"lineality_dim\": %ld, \"rays\": ",
                    (long) W->dim, (long) W->lineality_dim);
            json_rows_unit(out, W->rays);
            fputs(", \"facets\": ", out);
            json_rows_unit(out, W->ineqs);
            fputs(", \"excluded_faces\": [", out);
            for (f = 0, i = 0; f < W->nfaces; f++)
            {
                const wc_face_struct * F = W->faces + f;
                slong j;

                if (F->included)
                    continue;
                fprintf(out, "%s{\"dim\": %ld, \"rays\": [", i++ ? ", " : "",
                        (long) F->dim);
                for (j = 0; j < F->nrays; j++)
                    fprintf(out, "%s%ld", j ? ", " : "", (long) F->rays[j]);
                fputs("]}", out);
            }
            putc(']', out);
        }
        fputs("}, \"file\": ", out);
        wc_fprint_json_string(out, file);
        fputs(", \"note\": \"the exact side decides emptiness, dimension, "
              "lineality, extreme rays and facets; floating-point numbers "
              "appear only in the angles (radians)\", \"strictness\": ", out);
        wc_fprint_json_string(out, strict_note);
        fputs(", \"tol\": ", out);
        json_double(out, R->tol);
        if (R->file_mode != NULL)
        {
            fputs(", \"file_mode\": ", out);
            wc_fprint_json_string(out, R->file_mode);
        }
        fputs(", \"float\": [", out);
        for (i = 0; i < R->nreps; i++)
        {
            fputs(i ? ", " : "", out);
            json_rep(out, R->reps + i);
        }
        fprintf(out, "], \"within_tolerance\": %s, \"differences\": ",
                R->differs ? "false" : "true");
        json_differences(out, R->differs);
        fputs("}\n", out);
        return ferror(out) ? WC_EINTERNAL : WC_OK;
    }

    fprintf(out, "exact (GMP) against %s; distances are floating-point "
            "angles in radians\n", file);
    fputs("(the exact side decides emptiness, dimension, extreme rays and "
          "facets; floats appear only in the angles)\n", out);
    fprintf(out, "exact cone W(%s) of %s: ", mode, problem);
    text_cone_summary(out, W);
    fprintf(out, "\ntolerance %g\n", R->tol);
    if (R->file_mode != NULL)
        fprintf(out, "the file is for mode %s, not %s\n", R->file_mode, mode);
    for (i = 0; i < R->nreps; i++)
        text_rep(out, R->reps + i, W, file, R->json_file);
    fprintf(out, "\n%s:\n", strict_note);
    if (W->empty)
        fputs("  the exact cone is empty: no face to check\n", out);
    else if (excl == 0)
        fputs("  the exact cone is closed: it excludes no face of its "
              "closure\n", out);
    else
    {
        fprintf(out, "  the exact cone excludes %ld of the %ld faces of its "
                "closure: ", (long) excl, (long) W->nfaces);
        text_excluded(out, W);
        putc('\n', out);
    }
    if (R->differs == 0)
        fputs("verdict: within tolerance\n", out);
    else
    {
        fputs("verdict: outside tolerance: ", out);
        if (R->differs & WC_CMP_MODE)
        {
            fprintf(out, "the file is for mode %s, not %s", R->file_mode,
                    mode);
            first = 0;
        }
        for (i = 0; i < R->nreps; i++)
        {
            char prefix[32];

            if (R->nreps > 1)
                snprintf(prefix, sizeof prefix, "%s: ",
                         rep_key(R->reps[i].kind));
            else
                prefix[0] = '\0';
            text_reasons(out, R->reps + i, W, R->tol, prefix, &first);
        }
        putc('\n', out);
    }
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}
