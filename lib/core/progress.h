/* progress.h -- hearing how far a long computation has got.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_PROGRESS_H
#define WC_PROGRESS_H

#include <flint/flint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Called by the long loops of the library (the walk over an arrangement's
   planes, the moving faces, the cells of the stability sets) with the
   stage's name (static storage), the steps done and the steps in all
   (done <= total; a stage that runs to its end reports done = total
   last).  It must not call back into the library.  The library
   itself never prints: what to show, and how often, is the caller's.  */
typedef void (* wc_progress_fn)(void * ctx, const char * stage, slong done,
                                slong total);

/* Install fn with its ctx for the calling thread (fn NULL: no reports,
   the default of every thread).  A computation reports to the hook of
   the thread that runs it, so threads computing side by side neither see
   each other's reports nor race on the hook; a thread that wc_batch
   starts has none.  */
void wc_progress_set(wc_progress_fn fn, void * ctx);

#ifdef __cplusplus
}
#endif

#endif
