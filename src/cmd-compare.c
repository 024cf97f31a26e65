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

static void
print_comparison(const _wc_answer * A)
{
    wc_comparison_fprint(stdout, A->cmp, A->W, A->R->problem.name,
                         A->R->mode, A->R->foreign.name, 0);
}

int
cmd_compare(const cli_command * self, int argc, char ** argv)
{
    _wc_request R;
    int status = cli_parse(&R, self, argc, argv);

    if (status >= 0)
        return cli_done(&R, status);
    if (R.problem.stream != NULL && R.foreign.stream != NULL)
        status = cli_usage_error("compare", "PROBLEM and FILE cannot both be "
                                 "standard input%s", "");
    else
        status = cli_format_of(&R) == FMT_JSON ? cli_run_json(&R)
            : cli_run_print(&R, print_comparison);
    return cli_done(&R, status);
}
