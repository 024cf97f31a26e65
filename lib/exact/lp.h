/* lp.h -- internal: the exact LP layer over cddlib's GMP build.  Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A homogeneous system is a matrix A (m x nv, rows A_i) with a relation
   per row: A_i . z > 0, >= 0 or = 0.  Either a point z satisfies every
   row, or Motzkin's transposition theorem gives multipliers y (m) with
   sum_i y_i A_i = 0, y_i >= 0 on the > and >= rows and y_i > 0 on some >
   row, which prove that none does.  Every answer here is checked against
   the rows exactly before it is returned.  */

#ifndef WC_LP_H
#define WC_LP_H

#include <flint/fmpq.h>
#include <flint/fmpq_mat.h>

#include "core/error.h"
#include "exact/relation.h"

/* Rational vectors (FLINT 2.9 has these for fmpz only).  */
void _wc_qvec_zero(fmpq * v, slong len);
void _wc_qvec_set(fmpq * v, const fmpq * w, slong len);
int _wc_qvec_is_zero(const fmpq * v, slong len);

/* Keep the first r rows of A (systems are built in a matrix of the
   largest size, then cut to the rows used).  */
void _wc_fmpq_mat_keep_rows(fmpq_mat_t A, slong r);

/* 1 when z (nv entries) satisfies every row of (A, rel).  */
int _wc_lp_rows_hold(const fmpq_mat_t A, const wc_relation * rel,
                     const fmpq * z);

/* Solve the homogeneous system (A, rel): 1 with z (nv entries) satisfying
   every row; 0 when no point does, with the Motzkin multipliers in mult
   (m entries) when mult is not NULL; -1 on failure (err set).  The point
   is cddlib's basic solution with the > rows as >= 1 (m = 0: z = 0); the
   multipliers its basic solution of sum y_i A_i = 0, y >= 0 off the =
   rows, the > multipliers summing to 1: as sparse as a vertex is.  */
int _wc_lp_motzkin(fmpq * z, fmpq * mult, const fmpq_mat_t A,
                   const wc_relation * rel, wc_error_t err);

/* g in pos(G_0 .. G_k-1), G_j = G + 3 j in R^3: 1 with lambda (k entries)
   >= 0 and sum lambda_j G_j = g; 0 with sep (3 entries), sep . g > 0 and
   sep . G_j <= 0 for every j; -1 when the answer fails its exact check
   (err set).  */
int _wc_lp_cone3(fmpq * lambda, fmpq * sep, const fmpq * G, slong k,
                 const fmpq * g, wc_error_t err);

#endif
