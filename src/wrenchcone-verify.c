/* wrenchcone-verify.c -- the standalone certificate checker: `wrenchcone
   verify` as a program of its own, linked with the check library
   (lib/libwccheck.la) and GMP alone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   For the same certificate it prints the same bytes on stdout and stderr
   and exits with the same status as `wrenchcone verify`: the verdict is
   the library's (wc_verify_fprint), and the messages here are written as
   src/cli.c writes them ("wrenchcone: FILE:LINE:COL: message").  Only
   the help, the version and the last line of a usage error name this
   program.  It uses neither src/cli.h nor the umbrella header, whose
   FLINT types it could not link: the build makes any FLINT or cddlib
   call in the checker a link error (tests/verify-standalone.sh).  */

#include <config.h>

#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gmp.h>

#include "check/verify.h"

#define PROG "wrenchcone-verify"

/* The prefix of every diagnostic: `wrenchcone verify`'s, so that the
   two programs' messages are byte for byte the same.  */
#define WHO "wrenchcone: "

/* As `wrenchcone verify` (src/cli.h): a certificate carries at most two
   rows per fixel.  */
#define MAX_CERTIFICATE_BYTES ((size_t) 64 << 20)

static const char usage[] =
    "Usage: " PROG " [OPTIONS] CERTFILE\n"
    "Re-check a certificate with GMP arithmetic alone: 'wrenchcone verify'\n"
    "as a program of its own, linked with GMP and the C library only.\n"
    "CERTFILE is a certificate that 'wrenchcone feasible --certificate=FILE'\n"
    "(mode feasibility) or 'wrenchcone classify --certificate=FILE' (strong\n"
    "stability) wrote; '-' reads standard input.  Exit status 0 when the\n"
    "certificate holds, 4 when it does not, 1 when the file is malformed,\n"
    "2 bad usage, 3 I/O failure or out of memory.\n"
    "\n"
    "Options:\n"
    "  --format=FMT     text (default) or json\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

/* Running out of memory in GMP: one line on stderr, status 3, at once
   (the stdout buffer holds no complete answer), as `wrenchcone` does.  */
static void
out_of_memory(void)
{
    static const char m[] = WHO "out of memory\n";
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
resize(void * q, size_t old, size_t n)
{
    void * p = realloc(q, n != 0 ? n : 1);

    (void) old;
    if (p == NULL)
        out_of_memory();
    return p;
}

static void
release(void * p, size_t n)
{
    (void) n;
    free(p);
}

static int
usage_error(const char * fmt, const char * arg)
{
    fputs(WHO, stderr);
    fprintf(stderr, fmt, arg);
    fputs("\nTry '" PROG " --help' for more information.\n", stderr);
    return WC_EUSAGE;
}

static int
finish_output(void)
{
    if (fflush(stdout) != 0 || ferror(stdout))
    {
        fprintf(stderr, WHO "write error: %s\n", strerror(errno));
        return WC_EINTERNAL;
    }
    return WC_OK;
}

/* The whole of path ("-": stdin) into a malloc'd buffer, at most max
   bytes.  */
static int
read_all(char ** text, size_t * len, const char * path, size_t max,
         wc_error_t err)
{
    FILE * f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    size_t alloc = 4096, n = 0, r;
    char * buf;
    int status = WC_OK;

    if (f == NULL)
        return wc_error_set(err, WC_EINPUT, path, 0, 0, "cannot open: %s",
                            strerror(errno));
    buf = malloc(alloc);
    while (buf != NULL && (r = fread(buf + n, 1, alloc - n, f)) > 0)
    {
        if ((n += r) > max)
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
    if (f != stdin)
        fclose(f);
    if (status != WC_OK)
        free(buf);
    else
    {
        *text = buf;
        *len = n;
    }
    return status;
}

/* --format, -h, -V: 0 and *json set to go on, else the exit status
   (after the help, the version or a usage error).  */
static int
options(int * json, int argc, char ** argv)
{
    static const struct option table[] = {
        { "format", required_argument, NULL, 'f' },
        { "help", no_argument, NULL, 'h' },
        { "version", no_argument, NULL, 'V' },
        { NULL, 0, NULL, 0 }
    };
    int c;

    opterr = 0;
    while ((c = getopt_long(argc, argv, "hV", table, NULL)) != -1)
        if (c == 'f' && strcmp(optarg, "text") == 0)
            *json = 0;
        else if (c == 'f' && strcmp(optarg, "json") == 0)
            *json = 1;
        else if (c == 'f')
            return usage_error("unknown format '%s' (text or json)", optarg);
        else if (c == 'h')
        {
            fputs(usage, stdout);
            return finish_output();
        }
        else if (c == 'V')
        {
            printf(PROG " %s\nGMP %s\n"
                   "Copyright (C) 2026 the wrenchcone authors.\n"
                   "License GPLv2+: GNU GPL version 2 or later.\n"
                   "This is free software: you are free to change and "
                   "redistribute it.\n"
                   "There is NO WARRANTY, to the extent permitted by law.\n",
                   PACKAGE_VERSION, gmp_version);
            return finish_output();
        }
        else
            return usage_error("unknown or incomplete option '%s'",
                               argv[optind - 1]);
    if (argc - optind != 1)
        return usage_error(argc - optind < 1 ? "verify needs CERTFILE%s"
                           : "verify takes CERTFILE only%s", "");
    return -1;
}

int
main(int argc, char ** argv)
{
    int json = 0, holds = 0, status;
    char * text = NULL, * msg;
    const char * path;
    size_t len = 0;
    wc_error_t err;

    mp_set_memory_functions(get, resize, release);
    if ((status = options(&json, argc, argv)) >= 0)
        return status;
    path = argv[optind];
    wc_error_init(err);
    status = read_all(&text, &len, path, MAX_CERTIFICATE_BYTES, err);
    if (status == WC_OK)
        status = wc_verify_fprint(stdout, &holds, text, len,
                                  strcmp(path, "-") == 0 ? "<stdin>" : path,
                                  json, err);
    if (status != WC_OK)
    {
        msg = wc_error_format(err);
        fprintf(stderr, WHO "%s\n", msg != NULL ? msg : "out of memory");
        free(msg);
    }
    else if ((status = finish_output()) == WC_OK && !holds)
        status = WC_EDISAGREE;
    free(text);
    wc_error_clear(err);
    return status;
}
