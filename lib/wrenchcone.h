/* wrenchcone.h -- libwrenchcone: exact wrench cones for planar rigid-body
   contact tasks (Balkcom, Trinkle and Gottlieb, IJRR 2002).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Include this header; it includes the others.  The library never prints
   on its own and never exits: functions return a wc_status and fill a
   caller-supplied wc_error_t.  It holds no mutable global state: several
   threads may call it at once on their own objects (its calls into
   cddlib, which is not thread-safe, take a lock of their own).  */

#ifndef WRENCHCONE_H
#define WRENCHCONE_H

#include "core/error.h"
#include "core/limits.h"
#include "core/problem.h"
#include "model/mode.h"
#include "model/model.h"
#include "exact/cone.h"
#include "exact/relation.h"
#include "analysis/wrench.h"
#include "analysis/kinematics.h"
#include "check/verify.h"
#include "core/random.h"
#include "io/print.h"
#include "float/floatcone.h"
#include "io/fconeprint.h"
#include "float/compare.h"
#include "io/compareprint.h"
#include "exact/cells.h"
#include "analysis/push.h"
#include "analysis/stability.h"
#include "analysis/plan.h"
#include "analysis/sweep.h"
#include "core/version.h"
#include "core/progress.h"
#include "api/request.h"
#include "api/batch.h"

#endif
