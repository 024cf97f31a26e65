/* modeswalk.h -- internal: the walk behind wc_modes_enumerate.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  */

#ifndef WC_MODESWALK_H
#define WC_MODESWALK_H

#include <flint/fmpz_mat.h>

#include "core/error.h"
#include "core/problem.h"
#include "analysis/kinematics.h"

/* a (2n x 3, allocated by the caller): row k is column k of J as a
   primitive integer vector (kinematics.c).  */
void _wc_modes_columns(fmpz_mat_t a, const wc_problem_t P);

/* M := every kinematically feasible mode of P (checked already), sorted,
   with its witness (modeswalk.c).  Returns WC_OK or WC_EINTERNAL.  */
int _wc_modes_walk(wc_modes_t M, const wc_problem_t P, wc_error_t err);

#endif
