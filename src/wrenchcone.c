/* wrenchcone.c -- the command-line program: its usage, its commands, and
   the dispatch to them by full name.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Each command is a row of the library's schema (lib/api/schema.c: its
   usage, operands and options) and of its runners (lib/api/run.h: what
   it computes and prints).  Most commands are nothing more here than
   that request (cli_command_run); the few with a command-line rule of
   their own have a file (cmd-NAME.c).
   `wrenchcone --schema` prints the schema as JSON.  */

#include <config.h>

#include <signal.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

const cli_command cli_commands[] = {
    { _wc_schema + _WC_CONE, cmd_cone },
    { _wc_schema + _WC_MODES, cli_command_run },
    { _wc_schema + _WC_FEASIBLE, cli_command_run },
    { _wc_schema + _WC_CLASSIFY, cli_command_run },
    { _wc_schema + _WC_STABILITY, cli_command_run },
    { _wc_schema + _WC_PLAN, cli_command_run },
    { _wc_schema + _WC_SWEEP, cli_command_run },
    { _wc_schema + _WC_VERIFY, cli_command_run },
    { _wc_schema + _WC_COMPARE, cmd_compare },
    { _wc_schema + _WC_RANDOM, cli_command_run },
    { _wc_schema + _WC_DRAW, cli_command_run_output },
    { _wc_schema + _WC_REPORT, cli_command_run_output },
    { _wc_schema + _WC_BATCH, cmd_batch },
    { NULL, NULL }
};

/* Run command c on argv[0..argc) (argv[0] is its name).  */
static int
run(const cli_command * c, int argc, char ** argv)
{
    char * extra = NULL, ** v;
    int status;

    if (!(c->schema->flags & _WC_CMD_OPERANDS_LAST))
        return c->run(c, argc, argv);
    if ((v = cli_operands_last(&argc, argv, c->schema, &extra)) == NULL)
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
    /* A file over the size limit (ulimit -f) is a write error, reported
       and cleaned up, not a core dump.  */
    signal(SIGXFSZ, SIG_IGN);
    if (argc < 2)
    {
        _wc_schema_fprint_help(stderr, NULL);
        return WC_EUSAGE;
    }
    if (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0)
    {
        _wc_schema_fprint_help(stdout, NULL);
        return cli_finish_output();
    }
    if (strcmp(argv[1], "--schema") == 0 && argc == 2)
    {
        _wc_schema_fprint_json(stdout);
        return cli_finish_output();
    }
    if (strcmp(argv[1], "-V") == 0 || strcmp(argv[1], "--version") == 0)
    {
        cli_version();
        return cli_finish_output();
    }
    for (c = cli_commands; c->schema != NULL; c++)
        if (strcmp(argv[1], c->schema->name) == 0)
            break;
    if (c->schema == NULL)
        status = cli_usage_error(NULL, "unknown command '%s'", argv[1]);
    else
    {
        cli_progress_start();
        status = run(c, argc - 1, argv + 1);
        cli_progress_clear();
    }
    flint_cleanup_master();
    return status;
}
