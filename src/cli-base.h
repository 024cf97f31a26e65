/* cli-base.h -- what both programs (wrenchcone and wrenchcone-verify)
   share: reading an input, finishing stdout, running out of memory.  GMP
   and the C library only, so that the standalone checker can use it.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_CLI_BASE_H
#define WC_CLI_BASE_H

#include <stddef.h>

#include "core/error.h"

/* The prefix of every diagnostic of both programs.  */
#define CLI_WHO "wrenchcone: "

/* The name under which path is reported: "-" is "<stdin>".  */
const char * cli_input_name(const char * path);

/* The whole of path ("-": stdin) into a malloc'd *text of *len bytes, at
   most max, read as the command line reads (core/readall.h: a FIFO or a
   device too); a file that cannot be opened, a directory or a file too
   large is WC_EINPUT, any other read failure WC_EINTERNAL, located at
   path.  */
int cli_read_all(char ** text, size_t * len, const char * path, size_t max,
                 wc_error_t err);

/* Flush stdout; a failed write is reported, and is an I/O failure.  */
int cli_finish_output(void);

/* "wrenchcone: out of memory" on stderr and exit status 3 at once
   (_exit: whatever sits in the stdout buffer is an incomplete answer).  */
#ifdef __GNUC__
__attribute__((noreturn))
#endif
void cli_out_of_memory(void);

/* malloc, calloc and realloc that never return NULL (cli_out_of_memory
   instead), a zero size counting as one byte.  */
void * cli_xmalloc(size_t n);
void * cli_xcalloc(size_t k, size_t n);
void * cli_xrealloc(void * p, size_t n);

/* GMP's allocators: the ones above.  */
void cli_install_gmp_memory(void);

#endif
