/* cmd-compare.c -- wrenchcone compare: a cone computed elsewhere against
   the exact one.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

int
cmd_compare(const cli_command * self, int argc, char ** argv)
{
    _wc_request R;
    int status = cli_parse(&R, self, argc, argv);

    if (status >= 0)
        return cli_done(&R, status);
    if (R.problem.stream != NULL && R.foreign.stream != NULL)
        status = cli_usage_said("compare", "PROBLEM and FILE cannot both be "
                                "standard input");
    else
        status = cli_answer(&R);
    return cli_done(&R, status);
}
