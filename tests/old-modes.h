/* old-modes.h -- the previous implementation of mode enumeration,
   kept to catch regressions; not an independent reference (old-modes.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_TESTS_OLD_MODES_H
#define WC_TESTS_OLD_MODES_H

#include "core/error.h"
#include "core/problem.h"
#include "analysis/kinematics.h"

/* M := the feasible modes of P (checked by the caller), sorted, each with
   the witness of its first face in the walk of the whole arrangement.
   Returns WC_OK or WC_EINTERNAL.  */
int old_modes_walk(wc_modes_t M, const wc_problem_t P, wc_error_t err);

#endif
