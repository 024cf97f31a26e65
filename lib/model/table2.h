/* table2.h -- the paper's Table 2 as flags on the entries of y.  Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   y = (a_1n..a_nn, a_1t..a_nt, c_1n..c_nn, c_1t..c_nt), 0-based indices
   i, n+i, 2n+i, 3n+i.  Both the exact paper route (paper.c) and its
   double-precision twin (floatcone.c) read the mode through this one
   function, so that they cannot drift apart.  */

#ifndef WC_TABLE2_H
#define WC_TABLE2_H

#include "core/problem.h"

enum { Y_FREE = 1, Y_NEG = 2, Y_ZERO = 4, Y_STRICT = 8, Y_ROLL = 16,
       Y_SLIDE = 32 };

/* flag[0..4n) := the constraints mode puts on each entry of y: free
   (eliminated with its equation), negative (N flips it), zero, strict,
   rolling pair (R), sliding (S).  flag must hold 4n zeros on entry.  A
   rolling or maintained fixel with mu_s = 0 (decided exactly) gets
   c_t = 0 instead of R, which would divide by mu_s.  */
void _wc_table2_flags(int * flag, const wc_problem_t P, const char * mode);

#endif
