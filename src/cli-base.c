/* cli-base.c -- reading an input, finishing stdout, running out of
   memory: the part of the command line both programs share (cli-base.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   GMP cannot report a failed allocation to its caller: by default it
   prints to stderr and aborts.  The library never prints or exits, so the
   programs take the decision: their allocators say so on stderr and
   leave with status 3 at once.  */

#include <config.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gmp.h>

#include "cli-base.h"
#include "core/readall.h"

void
cli_out_of_memory(void)
{
    static const char m[] = CLI_WHO "out of memory\n";
    ssize_t r = write(2, m, sizeof m - 1);

    (void) r;
    _exit(WC_EINTERNAL);
}

void *
cli_xmalloc(size_t n)
{
    void * p = malloc(n != 0 ? n : 1);

    if (p == NULL)
        cli_out_of_memory();
    return p;
}

void *
cli_xcalloc(size_t k, size_t n)
{
    void * p = calloc(k != 0 ? k : 1, n != 0 ? n : 1);

    if (p == NULL)
        cli_out_of_memory();
    return p;
}

void *
cli_xrealloc(void * q, size_t n)
{
    void * p = realloc(q, n != 0 ? n : 1);

    if (p == NULL)
        cli_out_of_memory();
    return p;
}

static void *
gmp_resize(void * q, size_t old, size_t n)
{
    (void) old;
    return cli_xrealloc(q, n);
}

static void
gmp_release(void * p, size_t n)
{
    (void) n;
    free(p);
}

void
cli_install_gmp_memory(void)
{
    mp_set_memory_functions(cli_xmalloc, gmp_resize, gmp_release);
}

const char *
cli_input_name(const char * path)
{
    return strcmp(path, "-") == 0 ? "<stdin>" : path;
}


/* path "-" is stdin.  */
int
cli_read_all(char ** text, size_t * len, const char * path, size_t max,
             wc_error_t err)
{
    if (strcmp(path, "-") == 0)
        return _wc_read_all(text, len, stdin, cli_input_name(path), max, err);
    return _wc_read_file(text, len, path, path, max, 0, NULL, err);
}

int
cli_finish_output(void)
{
    if (fflush(stdout) != 0 || ferror(stdout))
    {
        fprintf(stderr, CLI_WHO "write error: %s\n", strerror(errno));
        return WC_EINTERNAL;
    }
    return WC_OK;
}
