/* cli-options.c -- a command line read by the command's schema (rows
   of lib/api/schema.c): options, operands, and moving operands after
   options.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The table given to getopt_long is derived from the command's rows: its
   options, everyone's (--help, --version, --progress, --decimals,
   --print-request), and -- for a shared command -- the options of the
   other shared commands under codes of their own, so that they are
   refused by name ("does not apply here") and an abbreviation is
   ambiguous among all of them, not only among the command's.  Values are
   read by _wc_arg_set_text, as a request's are.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "core/text.h"

/* Codes of the options of other commands: CLI_FOREIGN + their place in
   the table, all distinct, so that getopt_long finds an abbreviation
   ambiguous between two of them.  A command's own option's code is its
   row's place.  */
#define CLI_FOREIGN 0x4000
#define CLI_ROW 0x1000

/* --progress's, --decimals's and --print-request's codes.  */
#define CLI_PROGRESS 0x2000
#define CLI_DECIMALS 0x2001
#define CLI_PRINT_REQUEST 0x2002

static const struct option everyones[] = {
    { "help", no_argument, NULL, 'h' },
    { "version", no_argument, NULL, 'V' },
    { "progress", no_argument, NULL, CLI_PROGRESS },
    { "decimals", required_argument, NULL, CLI_DECIMALS },
    { "print-request", no_argument, NULL, CLI_PRINT_REQUEST },
    { NULL, 0, NULL, 0 }
};

/* --decimals=K: 0 <= K <= WC_DECIMALS_MAX, digits only, into
   p->decimals.  */
static int
set_decimals(cli_options * p, const char * s)
{
    int k = 0;
    const char * c;

    for (c = s; *c >= '0' && *c <= '9' && k <= WC_DECIMALS_MAX; c++)
        k = 10 * k + (*c - '0');
    if (c == s || *c != '\0' || k > WC_DECIMALS_MAX)
        return 0;
    p->decimals = k;
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

/* Append opts to table[0..*n) unless already named there.  0 when the
   table is full.  */
static int
append(struct option * table, int * n, const struct option * opts)
{
    for (; opts->name != NULL; opts++)
    {
        if (listed(table, *n, opts->name))
            continue;
        if (*n == CLI_MAX_OPTIONS)
            return 0;
        table[(*n)++] = *opts;
    }
    return 1;
}

/* Append the option rows of S, under their places (foreign: under codes
   of their own, past the table's end).  */
static int
append_rows(struct option * table, int * n, const _wc_command_schema * S,
            int foreign)
{
    const _wc_arg * a;

    for (a = S->options; a->name != NULL; a++)
    {
        if (listed(table, *n, a->name))
            continue;
        if (*n == CLI_MAX_OPTIONS)
            return 0;
        table[*n].name = a->name;
        table[*n].has_arg = a->kind == _WC_ARG_FLAG ? no_argument
            : required_argument;
        table[*n].flag = NULL;
        table[*n].val = foreign ? CLI_FOREIGN + *n
            : CLI_ROW + (int) (a - S->options);
        ++*n;
    }
    return 1;
}

void
cli_options_init(cli_options * p, const cli_command * cmd)
{
    const cli_command * c;
    unsigned shared = _WC_CMD_SHARED;
    int n = 0, ok;

    p->cmd = cmd;
    p->status = WC_OK;
    p->print_request = 0;
    p->decimals = -1;
    ok = append_rows(p->table, &n, cmd->schema, 0)
        && append(p->table, &n, everyones);
    for (c = cli_commands; ok && c->schema != NULL; c++)
        if ((cmd->schema->flags & shared) && (c->schema->flags & shared)
            && c != cmd)
            ok = append_rows(p->table, &n, c->schema, 1);
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
        p->status = WC_EINTERNAL;
        return CLI_EXIT;
    }
    while ((c = getopt_long(argc, argv, "hV", p->table, &idx))
           == CLI_PROGRESS || c == CLI_DECIMALS || c == CLI_PRINT_REQUEST)
    {
        if (c == CLI_PROGRESS)
            cli_progress_force();
        else if (c == CLI_PRINT_REQUEST)
            p->print_request = 1;
        else if (!set_decimals(p, optarg))
        {
            p->status = cli_usage_error(p->cmd->schema->name, "--decimals wants a "
                                        "whole number from 0 to 50, not "
                                        "'%s'", optarg);
            return CLI_EXIT;
        }
    }
    if (c == -1)
        return CLI_DONE;
    if (c >= CLI_FOREIGN)
        p->status = cli_usage_error(p->cmd->schema->name,
                                    "option '--%s' does not apply here",
                                    p->table[idx].name);
    else if (c == 'h' || c == 'V')
    {
        if (c == 'h')
            _wc_schema_fprint_help(stdout, p->cmd->schema);
        else
            cli_version();
        p->status = cli_finish_output();
    }
    else if (c == '?' || c == ':')
        p->status = cli_usage_error(p->cmd->schema->name,
                                    "unknown or incomplete option '%s'",
                                    argv[optind - 1]);
    else
        return c - CLI_ROW;
    return CLI_EXIT;
}

/* The option row of S that arg names exactly ("--NAME"), or NULL.  */
static const _wc_arg *
named(const _wc_command_schema * S, const char * arg)
{
    if (arg[0] != '-' || arg[1] != '-')
        return NULL;
    return _wc_schema_option(S, arg + 2, 0);
}

/* Whether arg is one of everyone's options that takes a value.  */
static int
everyones_value(const char * arg)
{
    const struct option * o;

    if (arg[0] != '-' || arg[1] != '-')
        return 0;
    for (o = everyones; o->name != NULL; o++)
        if (strcmp(arg + 2, o->name) == 0)
            return o->has_arg == required_argument;
    return 0;
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
cli_operands_last(int * pargc, char ** argv, const _wc_command_schema * S,
                  char ** extra)
{
    int argc = *pargc, i, no = 0, nx = 0;
    char ** opt = malloc(sizeof(char *) * (argc + 2));
    char ** ops = malloc(sizeof(char *) * (argc + 2));
    char ** out = NULL;

    *extra = NULL;
    for (i = 1; opt != NULL && ops != NULL && i < argc; i++)
    {
        const _wc_arg * o = named(S, argv[i]);
        int value = o != NULL ? o->kind != _WC_ARG_FLAG
            : everyones_value(argv[i]);

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
        if (!value)
            continue;
        if (o != NULL && o->kind == _WC_ARG_WRENCH && i + 3 < argc
            && *extra == NULL)
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

/* ------------------------------------------------------------------ */
/* A whole command line into a request                                 */

/* The metavars of S's operands with flag set (or unset) joined as
   "A, B and C" into buf.  */
static void
join_operands(char * buf, size_t size, const _wc_command_schema * S,
              int optional)
{
    const _wc_arg * a;
    int n = 0, k = 0;

    buf[0] = '\0';
    for (a = S->operands; a->name != NULL; a++)
        n += !(a->flags & _WC_ARG_OPTIONAL) == !optional;
    for (a = S->operands; a->name != NULL; a++)
        if (!(a->flags & _WC_ARG_OPTIONAL) == !optional)
            snprintf(buf + strlen(buf), size - strlen(buf), "%s%s",
                     k++ == 0 ? "" : k == n ? " and " : ", ", a->metavar);
}

/* What S takes, for a usage error: "PROBLEM and MODE only", "PROBLEM and
   optionally FX FY TAU".  */
static int
wrong_operands(const _wc_command_schema * S, int few, char ** v, int n)
{
    char need[128], may[128], msg[_WC_ARG_MSG_SIZE];
    char shown[WC_QUOTE_SIZE(WC_SHOW_MAX)];

    join_operands(need, sizeof need, S, 0);
    join_operands(may, sizeof may, S, 1);
    if (S->operands->name == NULL)
    {
        _wc_quote(shown, n > 0 ? v[0] : "", n > 0 ? strlen(v[0]) : 0,
                  WC_SHOW_MAX);
        snprintf(msg, sizeof msg, "%s takes no operands, not '%s'", S->name,
                 shown);
    }
    else if (few)
        snprintf(msg, sizeof msg, "%s needs %s", S->name, need);
    else if (may[0] == '\0')
        snprintf(msg, sizeof msg, "%s takes %s only", S->name, need);
    else if (need[0] == '\0')
        snprintf(msg, sizeof msg, "%s takes %s at most", S->name, may);
    else
        snprintf(msg, sizeof msg, "%s takes %s and optionally %s", S->name,
                 need, may);
    return cli_usage_said(S->name, msg);
}

/* The operands v[0..n) into R.  -1, or the exit status of a usage
   error.  */
static int
operands(_wc_request * R, const _wc_command_schema * S, char ** v, int n)
{
    const _wc_arg * a;
    char msg[_WC_ARG_MSG_SIZE];
    const char * why;
    int k = 0, need = 0;

    for (a = S->operands; a->name != NULL; a++)
        if (!(a->flags & _WC_ARG_OPTIONAL))
            need += a->kind == _WC_ARG_WRENCH ? 3 : 1;
    if (n < need)
        return wrong_operands(S, 1, v, n);
    for (a = S->operands; a->name != NULL && k < n; a++)
    {
        int w = a->kind == _WC_ARG_WRENCH ? 3 : 1;

        if (k + w > n)
            break;
        if (w == 3)
            _wc_arg_set_wrench(R, a, (const char * const *) v + k);
        else if ((why = _wc_arg_set_text(R, a, v[k], msg, sizeof msg))
                 != NULL)
            return cli_usage_said(S->name, why);
        k += w;
    }
    return k == n ? -1 : wrong_operands(S, 0, v, n);
}

/* Inputs named "-" read standard input.  */
static void
stdin_inputs(_wc_request * R, const _wc_command_schema * S)
{
    const _wc_arg * a;

    for (a = S->operands; a->name != NULL; a++)
    {
        _wc_input * in = (_wc_input *) (void *) ((char *) R + a->offset);

        if (a->kind == _WC_ARG_INPUT && in->path != NULL)
            cli_input(in, in->path);
    }
}

/* --print-request: R as a request line; standard input is read into the
   request as KEY_text.  */
static int
print_request(_wc_request * R, const _wc_command_schema * S)
{
    const _wc_arg * a;
    wc_error_t err;
    int status = WC_OK;

    if (!(S->flags & _WC_CMD_REQUEST))
        return cli_usage_error(S->name, "'%s' is not a request: "
                               "--print-request does not apply", S->name);
    wc_error_init(err);
    for (a = S->operands; status == WC_OK && a->name != NULL; a++)
    {
        _wc_input * in = (_wc_input *) (void *) ((char *) R + a->offset);
        char * text = NULL;
        size_t len = 0;

        if (a->kind != _WC_ARG_INPUT || in->stream == NULL)
            continue;
        status = _wc_input_read(&text, &len, in, err);
        if (status == WC_OK)
        {
            text[len] = '\0';
            if (_wc_request_keep(R, text) == NULL)
                status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                      "out of memory");
        }
        else
            free(text);
        if (status == WC_OK)
        {
            in->text = text;
            in->len = len;
            in->stream = NULL;
        }
    }
    if (status != WC_OK)
        cli_report(err, status);
    else
    {
        _wc_request_fprint_json(stdout, R);
        status = cli_finish_output();
    }
    wc_error_clear(err);
    return status;
}

int
cli_parse(_wc_request * R, const cli_command * self, int argc, char ** argv)
{
    const _wc_command_schema * S = self->schema;
    const _wc_arg * culprit;
    cli_options p;
    char msg[_WC_ARG_MSG_SIZE];
    const char * why;
    int c, status;

    _wc_request_init(R, (_wc_command) (S - _wc_schema));
    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        if ((why = _wc_arg_set_text(R, S->options + c,
                                    optarg != NULL ? optarg : "", msg,
                                    sizeof msg)) != NULL)
            return cli_usage_said(S->name, why);
    if (c == CLI_EXIT)
        return p.status;
    R->decimals = p.decimals;
    if ((status = operands(R, S, argv + optind, argc - optind)) >= 0)
        return status;
    stdin_inputs(R, S);
    if (S->check != NULL && (why = S->check(msg, sizeof msg, &culprit, R))
        != NULL)
        return cli_usage_said(S->name, why);
    return p.print_request ? print_request(R, S) : -1;
}

int
cli_done(_wc_request * R, int status)
{
    _wc_request_clear(R);
    return status;
}
