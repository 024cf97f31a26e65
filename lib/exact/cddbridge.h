/* cddbridge.h -- the only door to cddlib (GMP build; its double build
   for floatcone.c).  Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Cones here are homogeneous: { x : E x = 0, H x <= 0 } and
   pos(rays) + span(lines), rows of fmpq matrices with d columns.  Outputs
   are (re)initialised by the callee and must be fmpq_mat_clear'ed by the
   caller even on failure.  */

#ifndef WC_CDDBRIDGE_H
#define WC_CDDBRIDGE_H

#include <flint/fmpq_mat.h>
#include <flint/d_mat.h>

#include "core/error.h"
#include "exact/cone.h"

/* rays, lines := a minimal generating system of { x : E x = 0, H x <= 0 }.
   E or H may be NULL.  Returns WC_OK or WC_EINTERNAL.  */
int _wc_cdd_h_to_v(fmpq_mat_t rays, fmpq_mat_t lines, slong d,
                   const fmpq_mat_t E, const fmpq_mat_t H, wc_error_t err);

/* E, H := a minimal description of pos(rays) + span(lines): E x = 0 for
   the linear hull, H x <= 0 for the facets.  rays or lines may be NULL.  */
int _wc_cdd_v_to_h(fmpq_mat_t E, fmpq_mat_t H, slong d,
                   const fmpq_mat_t rays, const fmpq_mat_t lines,
                   wc_error_t err);

/* x := a point (nv = cols(A) entries) of { x : A_i . x >= b_i for rows
   with eq[i] == 0, A_i . x = b_i for rows with eq[i] != 0 } -- cddlib's
   basic solution, exact.  Returns 1 when found, 0 when the set is empty,
   -1 (err set, WC_EINTERNAL) when cddlib fails.  A must have a row.  */
int _wc_cdd_lp_point(fmpq * x, const fmpq_mat_t A, const fmpq * b,
                     const int * eq, wc_error_t err);

/* Minimise c . x over { x : A_i . x >= b_i (eq[i] == 0), A_i . x = b_i
   (eq[i] != 0) } (nv = cols(A) variables).  Returns 1 with x an optimal
   basic solution and *val the optimum, 0 when the set is empty, 2 when
   the objective is unbounded below, -1 (err set) when cddlib fails.  */
int _wc_cdd_lp_min(fmpq * x, fmpq_t val, const fmpq_mat_t A, const fmpq * b,
                   const int * eq, const fmpq * c, wc_error_t err);

/* The same conversions in cddlib's double-precision build (the ddf_
   functions of libcddgmp), for floatcone.c only: rows of d_mat's, which
   the callee re-initialises (the caller inits and clears them, also on
   failure).  Rows that are zero, and the apex or trivial row cddlib adds,
   are dropped.  Nothing exact may depend on these.  */
int _wc_cddf_h_to_v(d_mat_t rays, d_mat_t lines, slong d, const d_mat_t E,
                    const d_mat_t H, wc_error_t err);
int _wc_cddf_v_to_h(d_mat_t E, d_mat_t H, slong d, const d_mat_t rays,
                    const d_mat_t lines, wc_error_t err);

/* Whether { x : H0 x <= 0, H1 x <= -1 } (rows of d entries; either may be
   NULL) has a point, by cddlib's double LP (dual simplex): 1 yes, 0 no,
   -1 when cddlib fails (err set, WC_EINTERNAL).  */
int _wc_cddf_lp_feasible(const d_mat_t H0, const d_mat_t H1, slong d,
                         wc_error_t err);

/* wc_cone_set_hrep and wc_cone_set_generators with the conversion done
   by cddlib even in dimension 3 (where hull3.c is the default): the paper
   route uses cddlib throughout, so that comparing the two routes also
   compares the two conversion kernels.  Defined in cone.c.  */
int _wc_cone_set_hrep_kernel(wc_cone_t C, const fmpq_mat_t eqs,
                             const fmpq_mat_t ineqs, const fmpq_mat_t strict,
                             int use_cdd, wc_error_t err);
int _wc_cone_set_generators_kernel(wc_cone_t C,
                                   const fmpq_mat_t rays,
                                   const fmpq_mat_t lines, int use_cdd,
                                   wc_error_t err);

#endif
