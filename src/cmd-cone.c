/* cmd-cone.c -- wrenchcone cone: the exact wrench cone of one contact
   mode, or with --all-modes of every mode, one JSON line each.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

int
cmd_cone(const cli_command * self, int argc, char ** argv)
{
    _wc_request R;
    int status = cli_parse(&R, self, argc, argv);

    if (status < 0)
        status = R.all_modes ? cli_cone_all_modes(&R) : cli_answer(&R);
    return cli_done(&R, status);
}
