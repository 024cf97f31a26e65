/* cmd-verify.c -- wrenchcone verify: re-check a certificate with GMP
   arithmetic alone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>

#include "cli.h"
#include "commands.h"

int
cmd_verify(const cli_command * self, int argc, char ** argv)
{
    int status, holds = 0;
    char * text = NULL;
    size_t len = 0;
    _wc_request R;
    wc_error_t err;

    if ((status = cli_parse(&R, self, argc, argv)) >= 0)
        return cli_done(&R, status);
    wc_error_init(err);
    status = cli_read_all(&text, &len, R.cert.path != NULL ? R.cert.path
                          : "-", CLI_MAX_CERTIFICATE_BYTES, err);
    /* The verdict is the check library's (lib/check/report.c), shared
       with the standalone wrenchcone-verify.  */
    if (status == WC_OK)
        status = wc_verify_fprint(stdout, &holds, text, len,
                                  R.cert.name,
                                  cli_format_of(&R) == FMT_JSON,
                                  err);
    if (status != WC_OK)
        cli_report(err, status);
    else
    {
        status = cli_finish_output();
        if (status == WC_OK && !holds)
            status = WC_EDISAGREE;
    }
    free(text);
    wc_error_clear(err);
    return cli_done(&R, status);
}
