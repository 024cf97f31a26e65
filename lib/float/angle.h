/* angle.h -- internal: the exact 3-vector operations and the projections
   onto cones that the angle code (angle.c, hausdorff.c), the comparison
   and its report share.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  Vectors are three consecutive fmpq (or fmpz) entries,
   as in exact/vec3.h; cones are canonical wc_cone_t in R^3.  */

#ifndef WC_FLOAT_ANGLE_H
#define WC_FLOAT_ANGLE_H

#include <flint/fmpq.h>
#include <flint/fmpq_mat.h>
#include <flint/fmpz_mat.h>

#include "exact/cone.h"

#define WC_PI 3.14159265358979323846

/* r := a . b.  */
void _wc_qv3_dot(fmpq_t r, const fmpq * a, const fmpq * b);

int _wc_qv3_is_zero(const fmpq * a);
void _wc_qv3_set(fmpq * a, const fmpq * b);
void _wc_qv3_zero(fmpq * a);
void _wc_qv3_swap(fmpq * a, fmpq * b);
void _wc_qv3_neg(fmpq * a, const fmpq * b);

/* atan(sqrt(t)) for a rational t >= 0: the angle whose tangent squared is
   t, to double accuracy even when t is tiny.  */
double _wc_atan_sqrt(const fmpq_t t);

/* v as a unit vector in doubles (zeros when v is zero), each entry within
   an ulp or two of the true value however large or small v's numbers
   are.  */
void _wc_qv3_unit_d(double * u, const fmpq * v);
void _wc_zv3_unit_d(double * u, const fmpz * v);

/* A subspace of R^3 as (r, dir): its dimension r, and for r = 1 a vector
   spanning it, for r = 2 a normal of it.  The span of face F of C (its
   rays and C's lines), and the span of the rows of A.  */
slong _wc_face_span(fmpq * dir, const wc_cone_t C, const wc_face_struct * F);
slong _wc_rows_span(fmpq * dir, const fmpz_mat_t A);

/* q := the orthogonal projection of v onto the subspace (r, dir).  q may
   alias v.  */
void _wc_span_project(fmpq * q, const fmpq * v, slong r, const fmpq * dir);

/* best := |P v|^2, P the nearest-point map onto cl C (C nonempty); q := P v
   when q is not NULL.  */
void _wc_cone_project(fmpq_t best, fmpq * q, const fmpq * v,
                      const wc_cone_t C);

/* G := the generators of cl K as rational rows (G uninitialised on
   entry): its rays, then each line and its negative.  */
void _wc_cone_generators(fmpq_mat_t G, const wc_cone_t K);

#endif
