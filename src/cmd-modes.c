/* cmd-modes.c -- wrenchcone modes: every kinematically feasible contact
   mode.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "cli.h"
#include "commands.h"

static void
print_modes(const _wc_answer * A)
{
    wc_modes_fprint(stdout, A->M, 0, A->R->witness);
}

int
cmd_modes(const cli_command * self, int argc, char ** argv)
{
    _wc_request R;
    int status = cli_parse(&R, self, argc, argv);

    if (status < 0)
        status = cli_format_of(&R) == FMT_JSON ? cli_run_json(&R)
            : cli_run_print(&R, print_modes);
    return cli_done(&R, status);
}
