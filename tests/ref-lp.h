/* ref-lp.h -- the test oracle: membership in a wrench cone by one exact LP.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   These functions are the independent reference the library is tested
   against.  They share nothing with the library's algorithms: they read
   the fields of a wc_problem_t, build J, M, A, B and C of the paper's
   eq. (3)-(9) themselves in GMP rationals, write the Table 2 constraints
   of the mode straight into a cddlib (GMP build) LP over y = (a; c), and
   check cddlib's feasible answers against the constraints exactly.  Slow
   on purpose: one LP per question, never a cone conversion.  */

#ifndef WC_TESTS_REF_LP_H
#define WC_TESTS_REF_LP_H

#include <flint/fmpq.h>

#include "core/problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 1 if the wrench g (3 entries: fx, fy, torque) lies in W(mode) of P, 0 if
   not, -1 on a cddlib failure (or a letter outside Table 2).  W(mode) is
   { g : exists y with C y = B g, y satisfying Table 2 }, eq. (7); strict
   inequalities are decided exactly by homogenising with t >= 1.  mode has
   one Table 2 letter (s a u l r n m) per fixel; which letters a fixel's
   state allows is not checked here.  */
int ref_wrench_in_cone(const wc_problem_t P, const char * mode,
                       const fmpq * g);

/* 1 if W(mode) is nonempty, i.e. the mode is feasible at the acceleration
   level: some y satisfies C y = B g and Table 2 for SOME g (g is a free
   variable of the same LP).  0 if empty, -1 on failure as above.  */
int ref_cone_nonempty(const wc_problem_t P, const char * mode);

#ifdef __cplusplus
}
#endif

#endif
