/* dmat.c -- double vectors and matrices: norms, projections,
   orthonormal bases and sorting, for the float route.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <math.h>
#include <string.h>

#include "float/dmat.h"

/* A := a zero r x c matrix.  */
void
_wc_dm_reinit(d_mat_t A, slong r, slong c)
{
    d_mat_clear(A);
    d_mat_init(A, r, c);
    if (r > 0 && c > 0)
        d_mat_zero(A);
}

/* The Euclidean length of v, scaled so that huge or tiny entries neither
   overflow nor underflow in the squares.  */
double
_wc_dvec_norm(const double * v, slong d)
{
    double big = 0.0, s = 0.0;
    slong j;

    for (j = 0; j < d; j++)
        if (fabs(v[j]) > big)
            big = fabs(v[j]);
    if (big == 0.0 || !isfinite(big))
        return big;
    for (j = 0; j < d; j++)
        s += (v[j] / big) * (v[j] / big);
    return big * sqrt(s);
}

double
_wc_dvec_dot(const double * a, const double * b, slong d)
{
    double s = 0.0;
    slong j;

    for (j = 0; j < d; j++)
        s += a[j] * b[j];
    return s;
}

/* Scale v to unit length; returns its former length (v unchanged when
   that is 0).  */
double
_wc_dvec_normalise(double * v, slong d)
{
    double n = _wc_dvec_norm(v, d);
    slong j;

    if (n > 0.0)
        for (j = 0; j < d; j++)
            v[j] /= n;
    return n;
}

/* v := v minus its projection onto the span of the orthonormal rows of
   Q.  */
void
_wc_dvec_project_out(double * v, const d_mat_t Q, slong d)
{
    slong i, j;

    for (i = 0; i < Q->r; i++)
    {
        double c = _wc_dvec_dot(v, Q->rows[i], d);

        for (j = 0; j < d; j++)
            v[j] -= c * d_mat_entry(Q, i, j);
    }
}

/* The Frobenius norm of A.  */
double
_wc_dm_norm(const d_mat_t A)
{
    double big = 0.0, s = 0.0;
    slong i;

    for (i = 0; i < A->r; i++)
        big = fmax(big, _wc_dvec_norm(A->rows[i], A->c));
    if (big == 0.0 || !isfinite(big))
        return big;
    for (i = 0; i < A->r; i++)
    {
        double t = _wc_dvec_norm(A->rows[i], A->c) / big;

        s += t * t;
    }
    return big * sqrt(s);
}

int
_wc_dm_is_finite(const d_mat_t A)
{
    slong i, j;

    for (i = 0; i < A->r; i++)
        for (j = 0; j < A->c; j++)
            if (!isfinite(d_mat_entry(A, i, j)))
                return 0;
    return 1;
}

/* Keep the first k rows of A (k <= rows).  */
void
_wc_dm_keep_rows(d_mat_t A, slong k)
{
    slong d = A->c, i, j;
    d_mat_t T;

    d_mat_init(T, k, d);
    for (i = 0; i < k; i++)
        for (j = 0; j < d; j++)
            d_mat_entry(T, i, j) = d_mat_entry(A, i, j);
    d_mat_swap(A, T);
    d_mat_clear(T);
}

/* Row i of A copied to row k (k <= i: the rows kept so far) and scaled
   to a unit vector: that row, or NULL when it is zero.  */
static double *
unit_row_to(d_mat_t A, slong i, slong k)
{
    double * v = A->rows[k];
    slong j;

    if (k != i)
        for (j = 0; j < A->c; j++)
            v[j] = d_mat_entry(A, i, j);
    return _wc_dvec_normalise(v, A->c) == 0.0 ? NULL : v;
}

/* Replace the rows of A by an orthonormal basis of their span (modified
   Gram-Schmidt); a row whose remainder is shorter than tol times its
   length is taken as dependent and dropped.  */
void
_wc_dm_orthonormalise(d_mat_t A, double tol)
{
    slong d = A->c, i, j, l, k = 0;

    for (i = 0; i < A->r; i++)
    {
        double * v = unit_row_to(A, i, k);

        if (v == NULL)
            continue;
        for (l = 0; l < k; l++)
        {
            double c = _wc_dvec_dot(v, A->rows[l], d);

            for (j = 0; j < d; j++)
                v[j] -= c * d_mat_entry(A, l, j);
        }
        if (_wc_dvec_normalise(v, d) > tol)
            k++;
    }
    _wc_dm_keep_rows(A, k);
}

/* Make every row of A a unit vector orthogonal to the orthonormal rows
   of Q (when Q is not NULL); rows that vanish (below tol after the
   projection) are dropped.  */
void
_wc_dm_unit_rows(d_mat_t A, const d_mat_t Q, double tol)
{
    slong d = A->c, i, k = 0;

    for (i = 0; i < A->r; i++)
    {
        double * v = unit_row_to(A, i, k);

        if (v == NULL)
            continue;
        if (Q != NULL)
            _wc_dvec_project_out(v, Q, d);
        if (_wc_dvec_normalise(v, d) > tol)
            k++;
    }
    _wc_dm_keep_rows(A, k);
}

static int
dvec_cmp(const double * a, const double * b, slong d)
{
    slong j;

    for (j = 0; j < d; j++)
        if (a[j] != b[j])
            return a[j] < b[j] ? -1 : 1;
    return 0;
}

/* Sort the rows of A lexicographically, carrying flag[] along (insertion
   sort: cones in R^3 have few rays and facets).  */
void
_wc_dm_sort_rows(d_mat_t A, int * flag)
{
    slong d = A->c, i, k;
    double * t = flint_malloc(sizeof(double) * (d > 0 ? d : 1));

    for (i = 1; i < A->r; i++)
    {
        int f = flag[i];

        memcpy(t, A->rows[i], sizeof(double) * d);
        for (k = i; k > 0 && dvec_cmp(A->rows[k - 1], t, d) > 0; k--)
        {
            memcpy(A->rows[k], A->rows[k - 1], sizeof(double) * d);
            flag[k] = flag[k - 1];
        }
        memcpy(A->rows[k], t, sizeof(double) * d);
        flag[k] = f;
    }
    flint_free(t);
}

/* C := A B; C is re-initialised to the right size.  */
void
_wc_dm_mul(d_mat_t C, const d_mat_t A, const d_mat_t B)
{
    _wc_dm_reinit(C, A->r, B->c);
    if (A->r > 0 && B->c > 0)
        d_mat_mul_classical(C, A, B);
}
