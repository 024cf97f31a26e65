/* cmd-verify.c -- wrenchcone verify: re-check a certificate with GMP
   arithmetic alone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>

#include "cli.h"
#include "commands.h"

const char cmd_verify_usage[] =
    "Usage: " PROG " verify [OPTIONS] CERTFILE\n"
    "Re-check a certificate with GMP arithmetic alone (no FLINT, no cddlib).\n"
    "Four kinds: mode-feasibility ('" PROG " feasible --certificate=FILE'):\n"
    "the constraint rows are derived again from the certificate's problem\n"
    "and mode, then the witness or the Motzkin multipliers are checked;\n"
    "strong-stability ('" PROG " classify --certificate=FILE'): the static\n"
    "forces or the separator, the motion, or -- for a strongly stable\n"
    "wrench -- Motzkin multipliers for every moving face, the set of moving\n"
    "faces being derived again from the geometry; stability-set ('" PROG "\n"
    "stability --certificate=FILE') and plan-goal ('" PROG " plan\n"
    "--certificate=FILE'): the set printed is exactly the strongly stable\n"
    "set or the plan's goal set, every cell of the certificate's planes\n"
    "placed in it or outside it, the cells found again here.  Exit status\n"
    "0 when the certificate holds, 4 when it does not, 1 when the file is\n"
    "malformed.\n"
    "\n"
    "Options:\n"
    "  --format=FMT     text (default) or json\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

enum { OPT_FORMAT = 256 };

const struct option cmd_verify_options[] = {
    { "format", required_argument, NULL, OPT_FORMAT },
    { NULL, 0, NULL, 0 }
};

int
cmd_verify(const cli_command * self, int argc, char ** argv)
{
    cli_options p;
    cli_format fmt = FMT_TEXT;
    int c, status, holds = 0;
    char * text = NULL;
    const char * path;
    size_t len = 0;
    wc_error_t err;

    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        if (!cli_parse_format(&fmt, optarg, "verify", 0))
            return WC_EUSAGE;
    if (c == CLI_EXIT)
        return p.status;
    if (argc - optind != 1)
        return cli_usage_error("verify", argc - optind < 1
                               ? "verify needs CERTFILE%s"
                               : "verify takes CERTFILE only%s", "");
    path = argv[optind];
    wc_error_init(err);
    status = cli_read_all(&text, &len, path, CLI_MAX_CERTIFICATE_BYTES, err);
    /* The verdict is the check library's (lib/check/report.c), shared
       with the standalone wrenchcone-verify.  */
    if (status == WC_OK)
        status = wc_verify_fprint(stdout, &holds, text, len,
                                  cli_input_name(path), fmt == FMT_JSON,
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
    return status;
}
