/* benchutil.h -- what the benchmarks share: a clock, a fatal error, the
   fixels of the cradle problems, the problems of the cone benchmarks,
   and growth exponents.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_BENCHUTIL_H
#define WC_BENCHUTIL_H

#include "wrenchcone.h"

/* Seconds on a monotonic clock.  */
double wcbench_now(void);

/* Print "PROG: what: message" on stderr and exit with status 3.  */
void wcbench_die(const char * prog, const char * what, const wc_error_t err);

/* P (freshly initialised) := wc_random_problem's problem of n fixels
   with seed 1; prog names the benchmark should it fail.  */
void wcbench_random_problem(wc_problem_t P, slong n, const char * prog);

/* The problems of bench-cone and bench-ppl: P (initialised, no fixels)
   gets n touching fixels at distinct rational points of the unit circle
   with inward normals, friction 1/5 (mu_k 1/10), mass 3/2, inertia 2/3,
   the centre of mass at (1/7, -1/9).  */
void wcbench_cone_problem(wc_problem_t P, slong n);

/* The least-squares slope of log y against log x over len points (x, y
   positive): the growth exponent of a time y in a size x.  NaN when
   len < 2 or every x is the same.  */
double wcbench_slope(const double * x, const double * y, slong len);

/* Add to P a fixel on the unit circle at ((1 - s^2), 2 sy s) / (1 + s^2),
   s = a/b, its normal towards the centre, in the given state (sy = -1:
   the lower half; sy is 1 or -1).  */
void wcbench_circle_fixel(wc_problem_t P, slong a, slong b, int sy,
                          wc_fixel_state state);

#endif
