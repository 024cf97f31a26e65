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

/* Read the whole of f into a malloc'd buffer, at most max bytes.  */
static int
read_stream(char ** text, size_t * len, FILE * f, const char * path,
            size_t max, wc_error_t err)
{
    size_t alloc = 4096, n = 0, r;
    char * buf = malloc(alloc);
    int status = WC_OK;

    while (buf != NULL && (r = fread(buf + n, 1, alloc - n, f)) > 0)
    {
        n += r;
        if (n > max)
        {
            status = wc_error_set(err, WC_EINPUT, path, 0, 0,
                                  "file too large (over %lu bytes)",
                                  (unsigned long) max);
            break;
        }
        if (n == alloc)
        {
            char * p = realloc(buf, alloc *= 2);

            if (p == NULL)
                free(buf);
            buf = p;
        }
    }
    if (status != WC_OK)
        ;
    else if (buf == NULL)
        status = wc_error_set(err, WC_EINTERNAL, path, 0, 0, "out of memory");
    else if (ferror(f))
        /* A directory is a wrong argument; anything else is an I/O
           failure.  */
        status = wc_error_set(err, errno == EISDIR ? WC_EINPUT : WC_EINTERNAL,
                              path, 0, 0, "read error: %s", strerror(errno));
    if (status != WC_OK)
    {
        free(buf);
        return status;
    }
    *text = buf;
    *len = n;
    return WC_OK;
}

/* path "-" is stdin.  */
int
cli_read_all(char ** text, size_t * len, const char * path, size_t max,
             wc_error_t err)
{
    FILE * f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    int status;

    if (f == NULL)
        return wc_error_set(err, WC_EINPUT, path, 0, 0, "cannot open: %s",
                            strerror(errno));
    status = read_stream(text, len, f, cli_input_name(path), max, err);
    if (f != stdin)
        fclose(f);
    return status;
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
