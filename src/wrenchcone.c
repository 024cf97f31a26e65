/* wrenchcone.c -- the command-line program: its usage, its commands, and
   the dispatch to them by full name.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Each command is a file of its own (cmd-NAME.c); cli.c and
   cli-options.c hold what they share.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

static const char usage[] =
    "Usage: " PROG " COMMAND [OPTIONS] PROBLEM [ARGS]\n"
    "Exact wrench cones for planar rigid-body contact tasks.\n"
    "\n"
    "Commands:\n"
    "  cone PROBLEM MODE      the exact cone of external wrenches consistent with\n"
    "                         the contact mode MODE (one letter per fixel)\n"
    "  modes PROBLEM          every kinematically feasible contact mode\n"
    "  feasible PROBLEM MODE  one mode's verdict, with a checkable certificate\n"
    "  classify PROBLEM FX FY TAU\n"
    "                         one wrench: weak and strong stability (exact and\n"
    "                         paper semantics), motions, the modes holding it\n"
    "  stability PROBLEM      the weakly and strongly stable wrench sets, exactly,\n"
    "                         and where a frictionless finger may push\n"
    "  plan PROBLEM [FX FY TAU]\n"
    "                         a sensorless insertion plan: the wrenches that seat\n"
    "                         the part from any contact state (G_goal), exactly;\n"
    "                         with a wrench, its verdict\n"
    "  sweep PROBLEM          G_goal against friction: --friction=LIST, --critical\n"
    "  verify CERTFILE        re-check a certificate with GMP arithmetic alone\n"
    "  compare PROBLEM MODE FILE\n"
    "                         check a cone computed elsewhere (FILE: cdd or JSON,\n"
    "                         floats allowed) against the exact W(MODE)\n"
    "  random [OPTIONS]       print a reproducible random problem (a .wc file)\n"
    "  draw FIGURE PROBLEM    a figure as SVG: --mode=M, --modes, --stability,\n"
    "                         --plan, --sweep=LIST or --graph; -o FILE\n"
    "  report PROBLEM -o FILE.html\n"
    "                         every analysis of PROBLEM on one HTML page, with\n"
    "                         its figures\n"
    "  batch [FILE]           JSON Lines requests in (cone, modes, feasible,\n"
    "                         classify, stability, plan, compare), one JSON\n"
    "                         answer line out per request\n"
    "\n"
    "PROBLEM is a .wc problem file (see wrenchcone(5)); '-' reads standard input.\n"
    "Options of every command: --format=text|json, -h/--help, -V/--version,\n"
    "--progress (progress on stderr, also when it is not a terminal),\n"
    "--decimals=K (text: decimal approximations, K digits, 0..50, next to\n"
    "non-integer exact values).\n"
    "Run '" PROG " COMMAND --help' for a command's options.\n"
    "\n"
    "Exit status: 0 success (an empty cone is an answer), 1 bad input,\n"
    "2 bad usage, 3 internal or I/O failure, 4 disagreement (compare, verify).\n";

#define COMMAND(name, flags) \
    { #name, cmd_##name, cmd_##name##_usage, cmd_##name##_options, flags }

const cli_command cli_commands[] = {
    COMMAND(cone, CLI_SHARED),
    COMMAND(modes, CLI_SHARED),
    COMMAND(feasible, CLI_SHARED),
    COMMAND(verify, CLI_SHARED),
    COMMAND(random, 0),
    COMMAND(compare, 0),
    COMMAND(classify, CLI_SHARED | CLI_OPERANDS_LAST),
    COMMAND(stability, CLI_SHARED | CLI_OPERANDS_LAST),
    COMMAND(plan, CLI_SHARED | CLI_OPERANDS_LAST),
    COMMAND(sweep, CLI_SHARED),
    COMMAND(draw, 0),
    COMMAND(report, 0),
    COMMAND(batch, 0),
    { NULL, NULL, NULL, NULL, 0 }
};

/* Run command c on argv[0..argc) (argv[0] is its name).  */
static int
run(const cli_command * c, int argc, char ** argv)
{
    char * extra = NULL, ** v;
    int status;

    if (!(c->flags & CLI_OPERANDS_LAST))
        return c->run(c, argc, argv);
    if ((v = cli_operands_last(&argc, argv, c->options, &extra)) == NULL)
    {
        fputs(PROG ": out of memory\n", stderr);
        return WC_EINTERNAL;
    }
    status = c->run(c, argc, v);
    free(v);
    free(extra);
    return status;
}

int
main(int argc, char ** argv)
{
    const cli_command * c;
    int status;

    cli_install_memory_handlers();
    if (argc < 2)
    {
        fputs(usage, stderr);
        return WC_EUSAGE;
    }
    if (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0)
    {
        fputs(usage, stdout);
        return cli_finish_output();
    }
    if (strcmp(argv[1], "-V") == 0 || strcmp(argv[1], "--version") == 0)
    {
        cli_version();
        return cli_finish_output();
    }
    for (c = cli_commands; c->name != NULL; c++)
        if (strcmp(argv[1], c->name) == 0)
            break;
    if (c->name == NULL)
        status = cli_usage_error(NULL, "unknown command '%s'", argv[1]);
    else if (c->run == NULL)
        status = cli_usage_error(NULL, "'%s' is not implemented in this "
                                 "version", argv[1]);
    else
    {
        cli_progress_start();
        status = run(c, argc - 1, argv + 1);
        cli_progress_clear();
    }
    flint_cleanup_master();
    return status;
}
