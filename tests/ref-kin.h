/* ref-kin.h -- the test oracle for kinematic feasibility (wrenchcone(1) MODES, paper
   Table 1): one exact LP per mode, and brute force over all mode strings.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The independent reference that lib/kinematics.c is tested against.  It
   shares nothing with the library's algorithms (neither model.h nor
   kinematics.h is used): J_in = (n_x, n_y, r x n) and J_it = (t_x, t_y,
   r x t), t = (-n_y, n_x), r = p - com, are rebuilt here in GMP rationals
   from the problem's fields, the Table 1 constraints of the mode are written
   straight into one cddlib (GMP build) LP, and every answer cddlib gives is
   re-checked exactly: a feasible answer by substituting its twist into
   every constraint, an infeasible one by checking the Motzkin multipliers
   read from the LP's dual solution.  When a check fails the answer is -1,
   never a guess.  Slow on purpose.  */

#ifndef WC_TESTS_REF_KIN_H
#define WC_TESTS_REF_KIN_H

#include <flint/flint.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>

#include "core/problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Relations of the rows of ref_mode_rows; the same numbering as the
   library's wc_relation (>, >=, =), so that rows can be compared, but
   defined here so that this oracle does not include kinematics.h.  */
enum { REF_REL_GT = 0, REF_REL_GE = 1, REF_REL_EQ = 2 };

/* 1 if some twist nu satisfies every Table 1 constraint of mode for P
   (touching s: v_in > 0; l: v_in = 0, v_it > 0; r: v_in = 0, v_it < 0;
   n: v_in = 0, v_it = 0; near a: v_in < 0; near s: v_in >= 0), 0 if none
   does, -1 when mode is not a Table 1 string for P (wrong length, a letter
   not allowed in its fixel's state) or cddlib fails or its answer does
   not check out.  */
int ref_mode_feasible(const wc_problem_t P, const char * mode);

/* Every Table 1 string of P (4^t 2^(n - t) of them for t touching
   fixels), one ref_mode_feasible LP each; the feasible ones are returned
   in *modes (a malloc'd array of *count malloc'd NUL-terminated strings,
   sorted by strcmp; free with ref_modes_free).  Returns 0, or -1 when an
   LP failed (then *modes is NULL and *count 0).  */
int ref_modes_bruteforce(char *** modes, slong * count, const wc_problem_t P);

void ref_modes_free(char ** modes, slong count);

/* The constraint rows of mode as the library documents them
   (kinematics.h), computed independently: in fixel order, for each fixel
   its normal row, then its tangential row when the letter constrains it
   (l, r, n); each row is J_in or J_it, negated for a "< 0" constraint
   (touching r, near a), scaled to a primitive integer vector.  rows (an
   initialised matrix) is replaced by an m x 3 matrix; *rel gets a
   flint_malloc'd array of m REF_REL_* values (flint_free it; NULL when m
   is 0).  Returns 0, or -1 when mode is not a Table 1 string for P.  */
int ref_mode_rows(fmpz_mat_t rows, int ** rel, const wc_problem_t P,
                  const char * mode);

/* 1 if the twist nu (3 entries) satisfies every Table 1 constraint of
   mode, evaluated directly as v = J^T nu in GMP rationals; 0 if not; -1
   when mode is not a Table 1 string for P.  */
int ref_twist_satisfies(const wc_problem_t P, const char * mode,
                        const fmpz * nu);

#ifdef __cplusplus
}
#endif

#endif
