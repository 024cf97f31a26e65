/* cli-memory.c -- what the program does when memory runs out.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   GMP and FLINT cannot report a failed allocation to their caller: by
   default GMP prints to stderr and aborts, and FLINT prints to stdout and
   aborts (exit 134 with a message on the wrong stream).  The library
   never prints or exits, so the program takes the decision: it installs
   allocators that, when the system refuses memory, write one line to
   stderr and leave with status 3 at once (_exit: whatever sits in the
   stdout buffer is an incomplete answer and must not be written).  The
   library's own allocations are checked and return WC_EINTERNAL, and its
   commands refuse sizes beyond their limits before allocating
   (wrenchcone(1), LIMITS), so this is the last line of defence.  */

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gmp.h>
#include <flint/flint.h>

#include "cli.h"

FLINT_NORETURN static void
out_of_memory(void)
{
    static const char m[] = PROG ": out of memory\n";
    ssize_t r = write(2, m, sizeof m - 1);

    (void) r;
    _exit(WC_EINTERNAL);
}

static void *
get(size_t n)
{
    void * p = malloc(n != 0 ? n : 1);

    if (p == NULL)
        out_of_memory();
    return p;
}

static void *
get_zero(size_t k, size_t n)
{
    void * p = calloc(k != 0 ? k : 1, n != 0 ? n : 1);

    if (p == NULL)
        out_of_memory();
    return p;
}

static void *
resize(void * q, size_t n)
{
    void * p = realloc(q, n != 0 ? n : 1);

    if (p == NULL)
        out_of_memory();
    return p;
}

static void *
gmp_resize(void * q, size_t old, size_t n)
{
    (void) old;
    return resize(q, n);
}

static void
gmp_release(void * p, size_t n)
{
    (void) n;
    free(p);
}

/* Any other FLINT exception is a bug of ours (a division by zero, say),
   reported as an internal failure.  FLINT has printed its own line by
   then.  */
FLINT_NORETURN static void
flint_failed(void)
{
    static const char m[] = PROG ": internal error (FLINT exception)\n";
    ssize_t r = write(2, m, sizeof m - 1);

    (void) r;
    _exit(WC_EINTERNAL);
}

void
cli_install_memory_handlers(void)
{
    mp_set_memory_functions(get, gmp_resize, gmp_release);
    __flint_set_memory_functions(get, get_zero, resize, free);
    flint_set_abort(flint_failed);
}
