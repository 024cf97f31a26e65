/* wrenchcone-verify.c -- the standalone certificate checker: `wrenchcone
   verify` as a program of its own, linked with the check library
   (lib/libwccheck.la) and GMP alone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   For the same certificate it prints the same bytes on stdout and stderr
   and exits with the same status as `wrenchcone verify`: the verdict is
   the library's (wc_verify_fprint), and the messages here are written as
   src/cli.c writes them ("wrenchcone: FILE:LINE:COL: message"), and the
   input, output and memory handling is the programs' common part
   (cli-base.c).  Only the help, the version and the last line of a usage
   error name this program.  It uses neither src/cli.h nor the umbrella
   header, whose FLINT types it could not link: the build makes any FLINT or cddlib
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
#include "core/limits.h"
#include "core/text.h"
#include "cli-base.h"

#define PROG "wrenchcone-verify"

/* The prefix of every diagnostic: `wrenchcone verify`'s (CLI_WHO), so
   that the two programs' messages are byte for byte the same.  */
#define WHO CLI_WHO

static const char usage[] =
    "Usage: " PROG " [OPTIONS] CERTFILE\n"
    "Re-check a certificate with GMP arithmetic alone: 'wrenchcone verify'\n"
    "as a program of its own, linked with GMP and the C library only.\n"
    "CERTFILE is a certificate that 'wrenchcone feasible', 'classify',\n"
    "'stability' or 'plan' wrote with --certificate=FILE; '-' reads\n"
    "standard input.  Exit status 0 when the certificate holds, 4 when it\n"
    "does not, 1 when the file is malformed, 2 bad usage, 3 I/O failure or\n"
    "out of memory.\n"
    "\n"
    "Options:\n"
    "  --format=FMT     text (default) or json\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

/* fmt with its one %s the input token arg, quoted and cut (_wc_quote).  */
static int
usage_error(const char * fmt, const char * arg)
{
    wc_error_t e;

    wc_error_init(e);
    _wc_error_token(e, WC_EUSAGE, NULL, 0, 0, fmt, arg, strlen(arg));
    fprintf(stderr, WHO "%s\nTry '" PROG " --help' for more information.\n",
            e->message != NULL ? e->message : "out of memory");
    wc_error_clear(e);
    return WC_EUSAGE;
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
            return cli_finish_output();
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
            return cli_finish_output();
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

    cli_install_gmp_memory();
    if ((status = options(&json, argc, argv)) >= 0)
        return status;
    path = argv[optind];
    wc_error_init(err);
    status = cli_read_all(&text, &len, path, WC_CERT_MAX_BYTES, err);
    if (status == WC_OK)
        status = wc_verify_fprint(stdout, &holds, text, len,
                                  cli_input_name(path), json, err);
    if (status != WC_OK)
    {
        msg = wc_error_format(err);
        fprintf(stderr, WHO "%s\n", msg != NULL ? msg : "out of memory");
        free(msg);
    }
    else if ((status = cli_finish_output()) == WC_OK && !holds)
        status = WC_EDISAGREE;
    free(text);
    wc_error_clear(err);
    return status;
}
