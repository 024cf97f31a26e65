/* wrenchcone.h -- libwrenchcone: exact wrench cones for planar rigid-body
   contact tasks (Balkcom, Trinkle and Gottlieb, IJRR 2002).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Include this header; it includes the others.  The library never prints
   on its own and never exits: functions return a wc_status and fill a
   caller-supplied wc_error_t.  It is not thread-safe (cddlib is not).  */

#ifndef WRENCHCONE_H
#define WRENCHCONE_H

#include "error.h"
#include "problem.h"
#include "mode.h"
#include "model.h"
#include "cone.h"
#include "wrench.h"
#include "kinematics.h"
#include "verify.h"
#include "random.h"
#include "print.h"
#include "floatcone.h"
#include "compare.h"
#include "cells.h"
#include "push.h"
#include "stability.h"
#include "plan.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Optional one-time set-up of the exact backends (cddlib's global
   constants).  Every library function that needs it calls it; it is
   idempotent, so callers that use cddlib themselves call this instead of
   dd_set_global_constants().  */
void wc_init(void);

/* Version strings: ours, and those of the GMP, FLINT and cddlib we run
   with.  Static storage; never NULL.  */
const char * wc_version(void);
const char * wc_gmp_version(void);
const char * wc_flint_version(void);
const char * wc_cdd_version(void);

#ifdef __cplusplus
}
#endif

#endif
