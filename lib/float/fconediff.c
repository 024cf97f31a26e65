/* fconediff.c -- where a float cone and the exact one differ
   (wc_fcone_compare_exact).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <math.h>
#include <string.h>

#include <flint/fmpq_vec.h>

#include "float/floatcone.h"
#include "float/dmat.h"

/* v := row i of the fmpz matrix A as a unit double vector (entries
   divided by the largest first, exactly, so that huge integers do not
   overflow).  */
static void
unit_from_fmpz(double * v, const fmpz_mat_t A, slong i)
{
    slong d = fmpz_mat_ncols(A), j;
    fmpz_t big;
    fmpq_t q;

    fmpz_init(big);
    fmpq_init(q);
    for (j = 0; j < d; j++)
        if (fmpz_cmpabs(fmpz_mat_entry(A, i, j), big) > 0)
            fmpz_abs(big, fmpz_mat_entry(A, i, j));
    for (j = 0; j < d; j++)
    {
        if (fmpz_is_zero(big))
            v[j] = 0.0;
        else
        {
            fmpq_set_fmpz_frac(q, fmpz_mat_entry(A, i, j), big);
            v[j] = fmpq_get_d(q);
        }
    }
    _wc_dvec_normalise(v, d);
    fmpz_clear(big);
    fmpq_clear(q);
}

static double
dvec_dist(const double * a, const double * b, slong d)
{
    double s = 0.0;
    slong j;

    for (j = 0; j < d; j++)
        s += (a[j] - b[j]) * (a[j] - b[j]);
    return sqrt(s);
}

/* Index of the row of A nearest to v, -1 when A has no rows.  */
static slong
nearest_row(const d_mat_t A, const double * v, double * dist)
{
    slong i, best = -1;

    *dist = INFINITY;
    for (i = 0; i < A->r; i++)
    {
        double t = dvec_dist(A->rows[i], v, A->c);

        if (t < *dist)
        {
            *dist = t;
            best = i;
        }
    }
    return best;
}

/* Whether the exact face spanned by the rays in set[] (or the lineality
   space when none) is left out of E: its relative-interior point, the sum
   of those rays, is not in E.  */
static int
exact_excluded(const wc_cone_t E, const int * set)
{
    slong d = E->d, i, j;
    fmpq * g = _fmpq_vec_init(d);
    int out;

    for (i = 0; i < fmpz_mat_nrows(E->rays); i++)
        if (set[i])
            for (j = 0; j < d; j++)
                fmpq_add_fmpz(g + j, g + j, fmpz_mat_entry(E->rays, i, j));
    out = !wc_cone_contains(E, g);
    _fmpq_vec_clear(g, d);
    return out;
}

/* Whether the span of the rows of the fmpz matrix X equals that of the
   orthonormal rows of Q, within tol.  */
static int
same_space(const fmpz_mat_t X, const d_mat_t Q, double tol)
{
    slong d = Q->c, i;
    double * v = flint_malloc(sizeof(double) * (d > 0 ? d : 1));
    int same = fmpz_mat_nrows(X) == Q->r;

    for (i = 0; same && i < fmpz_mat_nrows(X); i++)
    {
        unit_from_fmpz(v, X, i);
        _wc_dvec_project_out(v, Q, d);
        same = _wc_dvec_norm(v, d) <= tol;
    }
    flint_free(v);
    return same;
}

/* Match the rows of the exact X against the float rows of A both ways;
   returns the bits found: missing (no partner within tol) or strict
   (partners differing in their flags).  xs[i] is the exact flag of row i
   of X.  */
static int
match_rows(const fmpz_mat_t X, const int * xs, const d_mat_t A,
           const int * as, double tol, int missing_bit)
{
    slong d = A->c, i;
    double * v = flint_malloc(sizeof(double) * (d > 0 ? d : 1));
    double dist;
    int bits = 0;

    if (fmpz_mat_nrows(X) != A->r)
        bits |= missing_bit;
    for (i = 0; i < fmpz_mat_nrows(X); i++)
    {
        slong k;

        unit_from_fmpz(v, X, i);
        k = nearest_row(A, v, &dist);
        if (k < 0 || dist > tol)
            bits |= missing_bit;
        else if ((xs[i] != 0) != (as[k] != 0))
            bits |= WC_FDIFF_STRICT;
    }
    for (i = 0; i < A->r; i++)
    {
        slong k, best = -1;
        double bd = INFINITY;

        for (k = 0; k < fmpz_mat_nrows(X); k++)
        {
            unit_from_fmpz(v, X, k);
            dist = dvec_dist(v, A->rows[i], d);
            if (dist < bd)
            {
                bd = dist;
                best = k;
            }
        }
        if (best < 0 || bd > tol)
            bits |= missing_bit;
    }
    flint_free(v);
    return bits;
}

int
wc_fcone_compare_exact(const wc_fcone_t F, const wc_cone_t E, double tol)
{
    slong d = E->d, nr, nh, i, j;
    int * set = NULL, * xs = NULL, bits = 0;
    fmpz_t t;

    if (F->d != E->d)
        return WC_FDIFF_SPACES;
    if (F->empty || E->empty)
        return (F->empty != E->empty) ? WC_FDIFF_EMPTY : 0;
    if (!same_space(E->eqs, F->eqs, tol)
        || !same_space(E->lines, F->lines, tol))
        bits |= WC_FDIFF_SPACES;
    if ((wc_cone_excluded_faces(E) == 0) != (F->closed != 0))
        bits |= WC_FDIFF_STRICT;

    nr = fmpz_mat_nrows(E->rays);
    nh = fmpz_mat_nrows(E->ineqs);
    set = flint_calloc(nr + 1, sizeof(int));
    xs = flint_calloc((nr > nh ? nr : nh) + 1, sizeof(int));
    fmpz_init(t);

    /* Rays: each one's own face.  */
    for (i = 0; i < nr; i++)
    {
        memset(set, 0, sizeof(int) * (nr + 1));
        set[i] = 1;
        xs[i] = exact_excluded(E, set);
    }
    bits |= match_rows(E->rays, xs, F->rays, F->strict_rays, tol,
                       WC_FDIFF_RAYS);

    /* Facets: the face of the rays each one is tight on.  */
    for (i = 0; i < nh; i++)
    {
        for (j = 0; j < nr; j++)
        {
            slong c;

            fmpz_zero(t);
            for (c = 0; c < d; c++)
                fmpz_addmul(t, fmpz_mat_entry(E->ineqs, i, c),
                            fmpz_mat_entry(E->rays, j, c));
            set[j] = fmpz_is_zero(t);
        }
        xs[i] = exact_excluded(E, set);
    }
    bits |= match_rows(E->ineqs, xs, F->ineqs, F->strict, tol,
                       WC_FDIFF_FACETS);

    fmpz_clear(t);
    flint_free(set);
    flint_free(xs);
    return bits;
}
