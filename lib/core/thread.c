/* thread.c -- FLINT's per-thread caches freed when a thread leaves
   (thread.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <pthread.h>

#include <flint/flint.h>

#include "core/thread.h"

/* Written once, under pthread_once, and only read after.  */
static pthread_once_t key_once = PTHREAD_ONCE_INIT;
static pthread_key_t key;
static int have_key;

/* Run at the thread's exit, while its thread-local storage (where FLINT
   keeps the caches) is still there.  */
static void
thread_exit(void * value)
{
    (void) value;
    flint_cleanup();
}

static void
make_key(void)
{
    have_key = pthread_key_create(&key, thread_exit) == 0;
}

void
_wc_thread_enter(void)
{
    pthread_once(&key_once, make_key);
    /* A non-NULL value is what makes the destructor run.  */
    if (have_key && pthread_getspecific(key) == NULL)
        pthread_setspecific(key, &key_once);
}
