/* cli.c -- messages, inputs and output for every command of the program.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "core/text.h"

void
cli_version(void)
{
    printf(PROG " %s\n"
           "GMP %s, FLINT %s, cddlib %s\n"
           "Copyright (C) 2026 the wrenchcone authors.\n"
           "License GPLv2+: GNU GPL version 2 or later.\n"
           "This is free software: you are free to change and redistribute it.\n"
           "There is NO WARRANTY, to the extent permitted by law.\n",
           wc_version(), wc_gmp_version(), wc_flint_version(),
           wc_cdd_version());
}

int
cli_report(const wc_error_t err, int status)
{
    char * s = wc_error_format(err);

    cli_progress_clear();
    fprintf(stderr, PROG ": %s\n", s != NULL ? s : "out of memory");
    free(s);
    return status;
}

/* The usage error in e, and where to find help.  */
static int
usage(const char * cmd, wc_error_t e)
{
    cli_progress_clear();
    fprintf(stderr, PROG ": %s\nTry '" PROG "%s%s --help' for more "
            "information.\n", e->message != NULL ? e->message
            : "out of memory", cmd ? " " : "", cmd ? cmd : "");
    wc_error_clear(e);
    return WC_EUSAGE;
}

int
cli_usage_error(const char * cmd, const char * fmt, const char * arg)
{
    wc_error_t e;

    wc_error_init(e);
    _wc_error_token(e, WC_EUSAGE, NULL, 0, 0, fmt, arg, strlen(arg));
    return usage(cmd, e);
}

int
cli_usage_said(const char * cmd, const char * msg)
{
    wc_error_t e;

    wc_error_init(e);
    wc_error_set(e, WC_EUSAGE, NULL, 0, 0, "%s", msg);
    return usage(cmd, e);
}

int
cli_file_error(int status, const char * path, const char * fmt, ...)
{
    wc_error_t e;
    va_list ap;

    wc_error_init(e);
    va_start(ap, fmt);
    wc_error_vset(e, status, path, 0, 0, fmt, ap);
    va_end(ap);
    cli_report(e, status);
    wc_error_clear(e);
    return status;
}
