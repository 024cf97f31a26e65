/* model.h -- the exact matrices of the paper's eq. (3)-(9).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Wrenches and twists are ordered (x, y, torque/angular).  Contact
   quantities are ordered (1n .. nn, 1t .. nt); y = (a; c) has 4n entries.
   Every output must be initialised by the caller with the stated size;
   outputs may not alias inputs.  */

#ifndef WC_MODEL_H
#define WC_MODEL_H

#include <flint/fmpq_mat.h>

#include "core/problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Tangent of fixel i: its normal rotated by +90 degrees (t[0], t[1]).  */
void wc_fixel_tangent(fmpq * t, const wc_fixel_struct * f);

/* J (3 x 2n): the column for direction d at fixel i is (d_x, d_y, r_i x d),
   r_i = p_i - o.  */
void wc_model_J(fmpq_mat_t J, const wc_problem_t P);

/* M = diag(m, m, I) and its inverse (3 x 3).  */
void wc_model_M(fmpq_mat_t M, const wc_problem_t P);
void wc_model_Minv(fmpq_mat_t Minv, const wc_problem_t P);

/* B = J^T M^-1 (2n x 3), A = J^T M^-1 J (2n x 2n), C = [I_2n, -A]
   (2n x 4n).  */
void wc_model_B(fmpq_mat_t B, const wc_problem_t P);
void wc_model_A(fmpq_mat_t A, const wc_problem_t P);
void wc_model_C(fmpq_mat_t C, const wc_problem_t P);

/* The friction-cone edges of fixel i under letter x, as contact force
   vectors (c_n, c_t): n, m give (1, -mu_s) and (1, mu_s); l gives
   (1, -mu_k); r gives (1, mu_k); other letters none.  Writes up to two
   edges into e[0..3] (pairs) and returns how many.  */
int wc_friction_edges(fmpq * e, const wc_fixel_struct * f, char x);

#ifdef __cplusplus
}
#endif

#endif
