/* tick.h -- the library's side of progress.h: report a step.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_TICK_H
#define WC_TICK_H

#include "core/progress.h"

/* Tell the installed hook, if any, that stage has done of total steps.  */
void _wc_tick(const char * stage, slong done, slong total);

#endif
