/* runners.h -- each command's row of _wc_runners (run.h): runexact.c,
   runsets.c, rundocs.c.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  */

#ifndef WC_API_RUNNERS_H
#define WC_API_RUNNERS_H

#include "api/run.h"

extern const _wc_runner _wc_run_cone, _wc_run_modes, _wc_run_feasible,
    _wc_run_classify, _wc_run_compare;
extern const _wc_runner _wc_run_stability, _wc_run_plan, _wc_run_sweep;
extern const _wc_runner _wc_run_verify, _wc_run_random, _wc_run_draw,
    _wc_run_report;

#endif
