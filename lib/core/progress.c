/* progress.c -- the progress hook (progress.h, tick.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stddef.h>

#include "core/tick.h"

/* The calling thread's hook: threads computing side by side report to
   hooks of their own, or to none.  */
static _Thread_local wc_progress_fn hook = NULL;
static _Thread_local void * hook_ctx = NULL;

void
wc_progress_set(wc_progress_fn fn, void * ctx)
{
    hook = fn;
    hook_ctx = ctx;
}

void
_wc_tick(const char * stage, slong done, slong total)
{
    if (hook != NULL)
        hook(hook_ctx, stage, done, total);
}
