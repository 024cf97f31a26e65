/* dmat.h -- internal: the few operations on double vectors and FLINT
   d_mat's that the float route and its comparison with the exact cone
   need.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  A vector is d consecutive doubles, such as a row of a
   d_mat.  */

#ifndef WC_FLOAT_DMAT_H
#define WC_FLOAT_DMAT_H

#include <flint/d_mat.h>

/* The Euclidean length of v, scaled so that huge or tiny entries neither
   overflow nor underflow in the squares.  */
double _wc_dvec_norm(const double * v, slong d);
double _wc_dvec_dot(const double * a, const double * b, slong d);

/* Scale v to unit length; returns its former length (v unchanged when
   that is 0).  */
double _wc_dvec_normalise(double * v, slong d);

/* v := v minus its projection onto the span of the orthonormal rows of
   Q.  */
void _wc_dvec_project_out(double * v, const d_mat_t Q, slong d);

/* A := a zero r x c matrix.  */
void _wc_dm_reinit(d_mat_t A, slong r, slong c);

/* C := A B; C is re-initialised to the right size.  */
void _wc_dm_mul(d_mat_t C, const d_mat_t A, const d_mat_t B);

/* The Frobenius norm of A; whether all its entries are finite.  */
double _wc_dm_norm(const d_mat_t A);
int _wc_dm_is_finite(const d_mat_t A);

/* Keep the first k rows of A (k <= rows).  */
void _wc_dm_keep_rows(d_mat_t A, slong k);

/* Replace the rows of A by an orthonormal basis of their span (modified
   Gram-Schmidt); a row whose remainder is shorter than tol times its
   length is taken as dependent and dropped.  */
void _wc_dm_orthonormalise(d_mat_t A, double tol);

/* Make every row of A a unit vector orthogonal to the orthonormal rows
   of Q (when Q is not NULL); rows that vanish (below tol after the
   projection) are dropped.  */
void _wc_dm_unit_rows(d_mat_t A, const d_mat_t Q, double tol);

/* Sort the rows of A lexicographically, carrying flag[] along.  */
void _wc_dm_sort_rows(d_mat_t A, int * flag);

#endif
