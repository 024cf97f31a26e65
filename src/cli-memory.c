/* cli-memory.c -- what the program does when memory runs out in GMP or
   FLINT.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   FLINT, like GMP, cannot report a failed allocation to its caller: by
   default it prints to stdout and aborts (exit 134 with a message on the
   wrong stream).  The program gives both the allocators of cli-base.c,
   which say so on stderr and exit with status 3.  The library's own
   allocations are checked and return WC_EINTERNAL, and its commands
   refuse sizes beyond their limits before allocating (wrenchcone(1),
   LIMITS), so this is the last line of defence.  */

#include <config.h>

#include <stdlib.h>
#include <unistd.h>

#include <flint/flint.h>

#include "cli.h"

/* Any other FLINT exception is a bug of ours (a division by zero, say),
   reported as an internal failure.  FLINT has printed its own line by
   then.  */
FLINT_NORETURN static void
flint_failed(void)
{
    static const char m[] = CLI_WHO "internal error (FLINT exception)\n";
    ssize_t r = write(2, m, sizeof m - 1);

    (void) r;
    _exit(WC_EINTERNAL);
}

void
cli_install_memory_handlers(void)
{
    cli_install_gmp_memory();
    __flint_set_memory_functions(cli_xmalloc, cli_xcalloc, cli_xrealloc,
                                 free);
    flint_set_abort(flint_failed);
}
