/* mode.h -- contact mode strings (paper Tables 1 and 2).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_MODE_H
#define WC_MODE_H

#include "core/problem.h"
#include "core/limits.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Which table a mode string is read against.  Table 2 (acceleration
   level, wrench cones): s on any fixel, a and u on near fixels, l r n m on
   touching ones.  Table 1 (velocity level, kinematic feasibility): s l r n
   on touching fixels, s a on near ones.  */
typedef enum { WC_TABLE_CONE = 2, WC_TABLE_KINEMATIC = 1 } wc_mode_table;

/* Check P (wc_problem_check), for Table 2 that P has at most
   WC_CONE_MAX_FIXELS fixels, and that mode has one letter per fixel of P,
   each allowed in that fixel's state under the given table.  Returns WC_OK, or WC_EINPUT with
   err located in the mode string itself: file "<mode>", line 1, col the
   1-based position of the offending letter (or one past the end for a
   short mode).  */
int wc_mode_check(const wc_problem_t P, const char * mode,
                  wc_mode_table table, wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
