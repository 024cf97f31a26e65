/* cmd-modes.c -- wrenchcone modes: every kinematically feasible contact
   mode.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "cli.h"
#include "commands.h"

const char cmd_modes_usage[] =
    "Usage: " PROG " modes [OPTIONS] PROBLEM\n"
    "List every kinematically feasible contact mode (paper Table 1: s l r n on\n"
    "touching fixels, s a on near ones), sorted, n..n included.  The modes are\n"
    "read off the faces of the arrangement of the 2n planes J_k . nu = 0 in\n"
    "twist space (O(n^2) faces), never off the 4^n strings.\n"
    "\n"
    "Options:\n"
    "  --witness        also print, per mode, a primitive integer twist nu\n"
    "                   (vx, vy, w) that has the mode\n"
    "  --format=FMT     text (default: one mode per line) or json\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

enum { OPT_FORMAT = 256, OPT_WITNESS };

const struct option cmd_modes_options[] = {
    { "format", required_argument, NULL, OPT_FORMAT },
    { "witness", no_argument, NULL, OPT_WITNESS },
    { NULL, 0, NULL, 0 }
};

static void
print_modes(const _wc_answer * A)
{
    wc_modes_fprint(stdout, A->M, 0, A->R->witness);
}

int
cmd_modes(const cli_command * self, int argc, char ** argv)
{
    cli_options p;
    cli_format fmt = FMT_TEXT;
    int c, witness = 0;
    _wc_request R;

    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        if (c == OPT_WITNESS)
            witness = 1;
        else if (!cli_parse_format(&fmt, optarg, "modes", 0))
            return WC_EUSAGE;
    if (c == CLI_EXIT)
        return p.status;
    if (argc - optind != 1)
        return cli_usage_error("modes", argc - optind < 1
                               ? "modes needs PROBLEM%s"
                               : "modes takes PROBLEM only%s", "");
    _wc_request_init(&R, _WC_MODES);
    cli_input(&R.problem, argv[optind]);
    R.witness = witness;
    return fmt == FMT_JSON ? cli_run_json(&R)
        : cli_run_print(&R, print_modes);
}
