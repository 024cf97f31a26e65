/* cli-options.c -- reading a command's options, and moving its operands
   after them.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Each command lists its own options once (cli_command.options); the
   table given to getopt_long is derived from it: the command's options,
   --help and --version, and -- for a CLI_SHARED command -- the options of
   the other shared commands under codes of their own, so that they are
   refused by name ("does not apply here") and an abbreviation is
   ambiguous among all of them, not only among the command's.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* Codes of the options of other commands: CLI_FOREIGN + their place in
   the table, all distinct, so that getopt_long finds an abbreviation
   ambiguous between two of them.  */
#define CLI_FOREIGN 0x4000

/* --progress's and --decimals's codes.  */
#define CLI_PROGRESS 0x2000
#define CLI_DECIMALS 0x2001

static const struct option everyones[] = {
    { "help", no_argument, NULL, 'h' },
    { "version", no_argument, NULL, 'V' },
    { "progress", no_argument, NULL, CLI_PROGRESS },
    { "decimals", required_argument, NULL, CLI_DECIMALS },
    { NULL, 0, NULL, 0 }
};

/* --decimals=K: 0 <= K <= WC_DECIMALS_MAX, digits only.  */
static int
set_decimals(const char * s)
{
    int k = 0;
    const char * p;

    for (p = s; *p >= '0' && *p <= '9' && k <= WC_DECIMALS_MAX; p++)
        k = 10 * k + (*p - '0');
    if (p == s || *p != '\0' || k > WC_DECIMALS_MAX)
        return 0;
    wc_print_set_decimals(k);
    return 1;
}

static int
listed(const struct option * table, int n, const char * name)
{
    int i;

    for (i = 0; i < n; i++)
        if (strcmp(table[i].name, name) == 0)
            return 1;
    return 0;
}

/* Append opts to table[0..*n) unless already named there; foreign: under
   codes of their own.  0 when the table is full.  */
static int
append(struct option * table, int * n, const struct option * opts,
       int foreign)
{
    for (; opts->name != NULL; opts++)
    {
        if (listed(table, *n, opts->name))
            continue;
        if (*n == CLI_MAX_OPTIONS)
            return 0;
        table[*n] = *opts;
        if (foreign)
            table[*n].val = CLI_FOREIGN + *n;
        ++*n;
    }
    return 1;
}

void
cli_options_init(cli_options * p, const cli_command * cmd)
{
    const cli_command * c;
    int n = 0, ok;

    p->cmd = cmd;
    p->status = WC_OK;
    ok = append(p->table, &n, cmd->options, 0)
        && append(p->table, &n, everyones, 0);
    for (c = cli_commands; ok && c->name != NULL; c++)
        if ((cmd->flags & CLI_SHARED) && (c->flags & CLI_SHARED) && c != cmd)
            ok = append(p->table, &n, c->options, 1);
    if (!ok)
        p->status = WC_EINTERNAL;
    memset(p->table + n, 0, sizeof(struct option));
    opterr = 0;
    optind = 1;
}

int
cli_option(cli_options * p, int argc, char ** argv)
{
    int c, idx = 0;

    if (p->status != WC_OK)
    {
        fputs(PROG ": internal error: too many options\n", stderr);
        return CLI_EXIT;
    }
    while ((c = getopt_long(argc, argv, "hV", p->table, &idx))
           == CLI_PROGRESS || c == CLI_DECIMALS)
    {
        if (c == CLI_PROGRESS)
            cli_progress_force();
        else if (!set_decimals(optarg))
        {
            p->status = cli_usage_error(p->cmd->name, "--decimals wants a "
                                        "whole number from 0 to 50, not "
                                        "'%s'", optarg);
            return CLI_EXIT;
        }
    }
    if (c == -1)
        return CLI_DONE;
    if (c >= CLI_FOREIGN)
        p->status = cli_usage_error(p->cmd->name,
                                    "option '--%s' does not apply here",
                                    p->table[idx].name);
    else if (c == 'h' || c == 'V')
    {
        if (c == 'h')
            fputs(p->cmd->usage, stdout);
        else
            cli_version();
        p->status = cli_finish_output();
    }
    else if (c == '?' || c == ':')
        p->status = cli_usage_error(p->cmd->name,
                                    "unknown or incomplete option '%s'",
                                    argv[optind - 1]);
    else
        return c;
    return CLI_EXIT;
}

/* The option of opts that arg names exactly ("--NAME"), or NULL.  */
static const struct option *
named(const struct option * opts, const char * arg)
{
    if (arg[0] != '-' || arg[1] != '-')
        return NULL;
    for (; opts->name != NULL; opts++)
        if (strcmp(arg + 2, opts->name) == 0)
            return opts;
    return NULL;
}

/* "--NAME=A,B,C" in a malloc'd string.  */
static char *
joined(const char * name, char ** v)
{
    size_t len = strlen("--=,,") + strlen(name) + strlen(v[0])
        + strlen(v[1]) + strlen(v[2]) + 1;
    char * s = malloc(len);

    if (s != NULL)
        snprintf(s, len, "--%s=%s,%s,%s", name, v[0], v[1], v[2]);
    return s;
}

/* A number such as -1 or -.5 is an operand, not an option.  */
static int
is_operand(const char * a)
{
    return a[0] != '-' || a[1] == '\0' || (a[1] >= '0' && a[1] <= '9')
        || a[1] == '.';
}

char **
cli_operands_last(int * pargc, char ** argv, const struct option * opts,
                  char ** extra)
{
    int argc = *pargc, i, no = 0, nx = 0;
    char ** opt = malloc(sizeof(char *) * (argc + 2));
    char ** ops = malloc(sizeof(char *) * (argc + 2));
    char ** out = NULL;

    *extra = NULL;
    for (i = 1; opt != NULL && ops != NULL && i < argc; i++)
    {
        const struct option * o = named(opts, argv[i]);

        if (o == NULL)
            o = named(everyones, argv[i]);

        if (strcmp(argv[i], "--") == 0)
        {
            for (i++; i < argc; i++)
                ops[nx++] = argv[i];
            break;
        }
        if (is_operand(argv[i]))
        {
            ops[nx++] = argv[i];
            continue;
        }
        opt[no++] = argv[i];
        if (o == NULL || o->has_arg != required_argument)
            continue;
        if ((o->val & CLI_WRENCH_VALUE) && i + 3 < argc && *extra == NULL)
        {
            if ((*extra = joined(o->name, argv + i + 1)) == NULL)
                break;
            opt[no - 1] = *extra;
            i += 3;
        }
        else if (i + 1 < argc)
            opt[no++] = argv[++i];
    }
    if (opt != NULL && ops != NULL && i >= argc)
        out = malloc(sizeof(char *) * (no + nx + 3));
    if (out != NULL)
    {
        out[0] = argv[0];
        memcpy(out + 1, opt, sizeof(char *) * no);
        out[1 + no] = (char *) "--";
        memcpy(out + 2 + no, ops, sizeof(char *) * nx);
        out[2 + no + nx] = NULL;
        *pargc = 2 + no + nx;
    }
    free(opt);
    free(ops);
    return out;
}
