/* ref-stab.h -- the test oracle for stability: one exact LP per sign
   pattern of the complementarity problem.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Independent of the library's stability code (lib/stability.c): no
   arrangement, no cone, no face enumeration.  Exponential on purpose
   (4^t LPs for t touching fixels); for t <= 4 or so.

   The model (wrenchcone(1), stability).  At zero velocity, for a wrench g, a solution is
   (nudot, c) with M nudot = J c + g, near fixels carrying no force, and
   for every touching fixel i, with a = J^T nudot:
     0 <= c_in, a_in >= 0, c_in a_in = 0;
     a_it > 0 => c_it = -mu_k c_in;  a_it < 0 => c_it = +mu_k c_in;
     a_it = 0 => |c_it| <= mu_s c_in.  */

#ifndef WC_TESTS_REF_STAB_H
#define WC_TESTS_REF_STAB_H

#include <flint/fmpq.h>

#include "core/problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 1 when g is weakly stable: g = -J c for forces c in the friction cones
   (mu_s) of the touching fixels and zero at near ones.  0 when not, -1 on
   an LP failure.  */
int ref_weakly_stable(const wc_problem_t P, const fmpq * g);

/* 1 when some solution has nudot != 0 (exact semantics: g then is not
   strongly stable).  One LP per sign pattern in {s, l, r, n}^t of the
   touching fixels (s: a_in > 0, c = 0; l: a_in = 0, a_it > 0, c on the
   -mu_k edge; r: a_in = 0, a_it < 0, c on the +mu_k edge; n: a_i = 0,
   c in the mu_s cone), with nudot != 0 split into the six LPs
   (J c + g)_k > 0 or < 0.  0 when none, -1 on failure.  */
int ref_has_motion(const wc_problem_t P, const fmpq * g);

/* 1 when g lies in W(x) (paper Table 2, eq. 7 as in ref-lp.c) for some
   string x with s, l, r or n on every touching fixel, u on near fixels,
   other than n on all touching fixels: eq. 19's union.  0 when in none,
   -1 on failure.  */
int ref_in_paper_union(const wc_problem_t P, const fmpq * g);

/* The Table 2 strings (s l r n on touching fixels, s a on near ones)
   whose cone W(x) holds g, ASCII-sorted, as one malloc'd string of
   count * (n + 1) bytes, each string NUL-terminated; *count receives how
   many.  NULL on failure.  */
char * ref_modes_holding(slong * count, const wc_problem_t P,
                         const fmpq * g);

#ifdef __cplusplus
}
#endif

#endif
