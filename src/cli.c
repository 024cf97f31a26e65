/* cli.c -- messages, inputs and output for every command of the program.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

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

int
cli_usage_error(const char * cmd, const char * fmt, const char * arg)
{
    fputs(PROG ": ", stderr);
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\nTry '" PROG "%s%s --help' for more information.\n",
            cmd ? " " : "", cmd ? cmd : "");
    return WC_EUSAGE;
}
