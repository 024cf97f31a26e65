/* thread.h -- what a thread running the library needs of its own.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  The library holds no mutable global state:
   what is per thread is thread-local (the progress hook, FLINT's caches
   of integers and primes), and cddlib, whose functions keep static
   scratch arrays, is called only from exact/cddbridge.c under one lock.
   FLINT asks every thread to call flint_cleanup() before it exits, or
   its caches leak; a thread that enters the library through an entry
   point that threads share (wc_request_json, wc_batch) is registered
   here so that this happens when it exits, without a call its caller
   could forget.  */

#ifndef WC_CORE_THREAD_H
#define WC_CORE_THREAD_H

/* Register the calling thread: when it exits, flint_cleanup() frees its
   FLINT caches (a thread-specific key's destructor; the main thread's
   caches go with flint_cleanup_master() or the process).  Cheap after
   the first call in a thread; never fails in a way that matters (if the
   key cannot be made, the caches leak, as before).  */
void _wc_thread_enter(void);

#endif
