/* angle.c -- angles between exact vectors, and from a vector to a cone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   For a closed convex cone C and a vector v, the nearest point P v of C
   satisfies v = P v + (v - P v) with the two parts orthogonal (Moreau),
   P v lies in the relative interior of exactly one face F of C and is the
   orthogonal projection of v onto span F.  For any face G whose
   projection q of v onto span G happens to lie in C,
   |v - q|^2 = |v|^2 - |q|^2 >= |v - P v|^2 = |v|^2 - |P v|^2; so |P v|^2
   is the largest |q|^2 over the faces whose q lies in C.  All of this is
   exact (rationals), and so is the angle's tangent squared
   (|v|^2 - |P v|^2) / |P v|^2; only atan(sqrt(.)) is a float.  */

#include <config.h>

#include <math.h>

#include <flint/fmpq_vec.h>

#include "float/compare.h"
#include "float/angle.h"
#include "exact/vec3.h"

/* ------------------------------------------------------------------ */
/* Exact vectors in R^3.  */

void
_wc_qv3_dot(fmpq_t r, const fmpq * a, const fmpq * b)
{
    _fmpq_vec_dot(r, a, b, 3);
}

int
_wc_qv3_is_zero(const fmpq * a)
{
    return fmpq_is_zero(a + 0) && fmpq_is_zero(a + 1) && fmpq_is_zero(a + 2);
}

void
_wc_qv3_set(fmpq * a, const fmpq * b)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_set(a + j, b + j);
}

void
_wc_qv3_zero(fmpq * a)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_zero(a + j);
}

void
_wc_qv3_swap(fmpq * a, fmpq * b)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_swap(a + j, b + j);
}

void
_wc_qv3_neg(fmpq * a, const fmpq * b)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_neg(a + j, b + j);
}

/* atan(sqrt(t)) for a rational t >= 0: the angle whose tangent squared is
   t, to double accuracy even when t is tiny.  */
double
_wc_atan_sqrt(const fmpq_t t)
{
    return atan(sqrt(fmpq_get_d(t)));
}

/* v as a unit vector in doubles (zeros when v is zero): each entry is
   sqrt(v_j^2 / |v|^2) with the ratio exact, so it is within an ulp or two
   of the true value however large or small v's numbers are.  */
void
_wc_qv3_unit_d(double * u, const fmpq * v)
{
    fmpq_t n, t;
    slong j;

    fmpq_init(n);
    fmpq_init(t);
    _wc_qv3_dot(n, v, v);
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

void
_wc_zv3_unit_d(double * u, const fmpz * v)
{
    fmpq * q = _fmpq_vec_init(3);

    _fmpq_vec_set_fmpz_vec(q, v, 3);
    _wc_qv3_unit_d(u, q);
    _fmpq_vec_clear(q, 3);
}

double
wc_angle_vectors(const fmpq * a, const fmpq * b)
{
    fmpq_t c, aa, bb, x;
    double r;

    if (_wc_qv3_is_zero(a) || _wc_qv3_is_zero(b))
        return NAN;
    fmpq_init(c);
    fmpq_init(aa);
    fmpq_init(bb);
    fmpq_init(x);
    _wc_qv3_dot(c, a, b);
    _wc_qv3_dot(aa, a, a);
    _wc_qv3_dot(bb, b, b);
    /* |a x b|^2 = |a|^2 |b|^2 - (a.b)^2, exactly; tan^2 = that / (a.b)^2 */
    fmpq_mul(x, aa, bb);
    fmpq_submul(x, c, c);
    if (fmpq_is_zero(c))
        r = WC_PI / 2;
    else
    {
        fmpq_mul(aa, c, c);
        fmpq_div(x, x, aa);
        r = _wc_atan_sqrt(x);
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
        _wc_qv3_set(dir, WC_ROW(R, 0));
    else if (r == 2)
        _wc_qvec3_cross(dir, WC_ROW(R, 0), WC_ROW(R, 1));
    fmpq_mat_clear(R);
    return r;
}

/* q = the orthogonal projection of v onto the subspace (r, dir) of
   span_of.  q may alias v.  */
void
_wc_span_project(fmpq * q, const fmpq * v, slong r, const fmpq * dir)
{
    fmpq_t s, n;
    slong j;

    if (r == 0)
    {
        _wc_qv3_zero(q);
        return;
    }
    if (r >= 3)
    {
        _wc_qv3_set(q, v);
        return;
    }
    fmpq_init(s);
    fmpq_init(n);
    _wc_qv3_dot(s, v, dir);
    _wc_qv3_dot(n, dir, dir);
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
slong
_wc_face_span(fmpq * dir, const wc_cone_t C, const wc_face_struct * F)
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
slong
_wc_rows_span(fmpq * dir, const fmpz_mat_t A)
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
        _wc_zqvec3_dot(s, WC_ROW(C->ineqs, i), p);
        in = fmpq_sgn(s) <= 0;
    }
    for (i = 0; in && i < fmpz_mat_nrows(C->eqs); i++)
    {
        _wc_zqvec3_dot(s, WC_ROW(C->eqs, i), p);
        in = fmpq_is_zero(s);
    }
    fmpq_clear(s);
    return in;
}

/* p := the projection of v onto span F, F a face of cl C.  Returns the
   dimension of span F when p lies in cl C, else -1.  span F meets cl C in
   F alone (F is cl C cut by a supporting plane that contains span F), so
   p is in cl C iff p is in F, which a face of at most two rays and no
   lines tells in O(1): for one ray r (C's rays are orthogonal to its
   lines) iff p.r >= 0; for two, iff p lies between them.  Only larger
   faces are tested against every facet, so that the nearest point of a
   cone with k rays costs O(k), not O(k^2) (tests/t-compare-fast.c checks
   this against the facet test on every face).  */
static slong
face_project(fmpq * p, fmpq * dir, const fmpq * v, const wc_cone_t C,
             const wc_face_struct * F)
{
    slong nl = fmpz_mat_nrows(C->lines), r;
    fmpq * a, * b;
    int in;

    if (nl > 0 || F->nrays == 0 || F->nrays > 2)
    {
        r = _wc_face_span(dir, C, F);
        _wc_span_project(p, v, r, dir);
        return in_closure(C, p) ? r : -1;
    }
    a = _fmpq_vec_init(3);
    b = _fmpq_vec_init(3);
    _fmpq_vec_set_fmpz_vec(a, WC_ROW(C->rays, F->rays[0]), 3);
    if (F->nrays == 1)
    {
        /* the projection onto R r is independent of r's scale */
        r = 1;
        _wc_span_project(p, v, r, a);
        _wc_qv3_dot(b + 0, p, a);
        in = fmpq_sgn(b + 0) >= 0;
    }
    else
    {
        fmpq * c = _fmpq_vec_init(3);
        fmpq_t s;

        fmpq_init(s);
        _fmpq_vec_set_fmpz_vec(b, WC_ROW(C->rays, F->rays[1]), 3);
        r = 2;
        _wc_qvec3_cross(dir, a, b);         /* a normal of span F */
        _wc_span_project(p, v, r, dir);
        /* p in pos(a, b) iff (a x p) and (p x b) point along a x b */
        _wc_qvec3_cross(c, a, p);
        _wc_qv3_dot(s, c, dir);
        in = fmpq_sgn(s) >= 0;
        if (in)
        {
            _wc_qvec3_cross(c, p, b);
            _wc_qv3_dot(s, c, dir);
            in = fmpq_sgn(s) >= 0;
        }
        fmpq_clear(s);
        _fmpq_vec_clear(c, 3);
    }
    _fmpq_vec_clear(a, 3);
    _fmpq_vec_clear(b, 3);
    return in ? r : -1;
}

/* best = |P v|^2, P the nearest-point map onto cl C (C nonempty); q = P v
   when q is not NULL.  See the comment at the top.  */
void
_wc_cone_project(fmpq_t best, fmpq * q, const fmpq * v, const wc_cone_t C)
{
    fmpq * dir = _fmpq_vec_init(3), * p = _fmpq_vec_init(3);
    fmpq_t n2;
    slong f, r;

    fmpq_init(n2);
    fmpq_zero(best);
    if (q != NULL)
        _wc_qv3_zero(q);
    for (f = 0; f < C->nfaces; f++)
    {
        r = face_project(p, dir, v, C, C->faces + f);
        if (r < 0)
            continue;
        _wc_qv3_dot(n2, p, p);
        if (fmpq_cmp(n2, best) > 0)
        {
            fmpq_set(best, n2);
            if (q != NULL)
                _wc_qv3_set(q, p);
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

    if (C->d != 3 || _wc_qv3_is_zero(v))
        return NAN;
    if (C->empty || C->dim == 0)
        return INFINITY;
    fmpq_init(best);
    fmpq_init(t);
    _wc_cone_project(best, NULL, v, C);
    if (fmpq_sgn(best) > 0)
    {
        /* tan^2 = |v - P v|^2 / |P v|^2 = (|v|^2 - |P v|^2) / |P v|^2 */
        _wc_qv3_dot(t, v, v);
        fmpq_sub(t, t, best);
        fmpq_div(t, t, best);
        a = _wc_atan_sqrt(t);
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
void
_wc_cone_generators(fmpq_mat_t G, const wc_cone_t K)
{
    slong k = fmpz_mat_nrows(K->rays), l = fmpz_mat_nrows(K->lines), i;

    fmpq_mat_init(G, k + 2 * l, 3);
    for (i = 0; i < k; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(G, i), WC_ROW(K->rays, i), 3);
    for (i = 0; i < l; i++)
    {
        _fmpq_vec_set_fmpz_vec(WC_ROW(G, k + 2 * i), WC_ROW(K->lines, i), 3);
        _wc_qv3_neg(WC_ROW(G, k + 2 * i + 1), WC_ROW(G, k + 2 * i));
    }
}
