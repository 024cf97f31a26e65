/* benchutil.h -- what the benchmarks share: a clock, a fatal error, and
   the fixels of the cradle problems.

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

/* Add to P a fixel on the unit circle at ((1 - s^2), 2 sy s) / (1 + s^2),
   s = a/b, its normal towards the centre, in the given state (sy = -1:
   the lower half).  */
void wcbench_circle_fixel(wc_problem_t P, slong a, slong b, int sy,
                          wc_fixel_state state);

#endif
