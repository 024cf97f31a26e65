/* cmd-batch.c -- wrenchcone batch: JSON Lines requests in, one answer
   line out per request, in order, through the library's batch engine
   (api/batch.h), by one thread or several.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

int
cmd_batch(const cli_command * self, int argc, char ** argv)
{
    const char * path;
    _wc_request R;
    FILE * f;
    int status, wst, worst;
    wc_error_t err;

    if ((status = cli_parse(&R, self, argc, argv)) >= 0)
        return cli_done(&R, status);
    path = R.batch;
    f = strcmp(path, "-") == 0 ? stdin : fopen(path, "r");
    if (f == NULL)
    {
        return cli_done(&R, cli_file_error(WC_EINPUT, path, "cannot open: "
                                           "%s", strerror(errno)));
    }
    wc_error_init(err);
    status = wc_batch(&worst, stdout, f, cli_input_name(path), (int) R.jobs,
                      err);
    if (status != WC_OK)
        cli_report(err, status);        /* reading, writing or memory */
    wc_error_clear(err);
    if (f != stdin)
        fclose(f);
    /* A failed write is reported already.  */
    wst = ferror(stdout) ? WC_EINTERNAL : cli_finish_output();
    return cli_done(&R, wst != WC_OK ? wst : status != WC_OK ? status
                    : worst);
}
