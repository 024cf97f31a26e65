/* schemaprint.c -- the schema written out: every --help text, and the
   table as a JSON document (schema.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <string.h>

#include "api/schema.h"
#include "api/runners.h"
#include "io/print.h"

static const char program_head[] =
    "Usage: wrenchcone COMMAND [OPTIONS] PROBLEM [ARGS]\n"
    "Exact wrench cones for planar rigid-body contact tasks.\n"
    "\n"
    "Commands:\n";

static const char program_tail[] =
    "\n"
    "PROBLEM is a .wc problem file (see wrenchcone(5)); '-' reads standard input.\n"
    "Options of every command: --format=text|json, -h/--help, -V/--version,\n"
    "--progress (progress on stderr, also when it is not a terminal),\n"
    "--decimals=K (text: decimal approximations, K digits, 0..50, next to\n"
    "non-integer exact values), --print-request (print the JSON request\n"
    "that the command line is, for 'wrenchcone batch', and exit).\n"
    "Run 'wrenchcone COMMAND --help' for a command's options.\n"
    "\n"
    "Exit status: 0 success (an empty cone is an answer), 1 bad input,\n"
    "2 bad usage, 3 internal or I/O failure, 4 disagreement (compare, verify).\n";

/* text's lines, the first after label (padded to width columns, or on a
   line of its own when label is too wide), the others indented as
   much.  */
static void
fprint_lines(FILE * out, const char * label, int width, int slack,
             const char * text)
{
    const char * p = text;
    int len = (int) strlen(label), first = 1;

    if (len < width)
        fprintf(out, "%-*s", width, label);
    else if (len <= width + slack && text != NULL)
        fprintf(out, "%s  ", label);
    else
    {
        fprintf(out, "%s\n", label);
        first = text == NULL;
    }
    while (p != NULL && *p != '\0')
    {
        const char * e = strchr(p, '\n');
        int n = e != NULL ? (int) (e - p) : (int) strlen(p);

        if (!first)
            fprintf(out, "%*s", width, "");
        fprintf(out, "%.*s\n", n, p);
        first = 0;
        p = e != NULL ? e + 1 : NULL;
    }
    if (first && len < width)
        putc('\n', out);
}

static void
fprint_option(FILE * out, const _wc_arg * a)
{
    const char * eq = a->kind == _WC_ARG_FLAG ? "" : "=";
    const char * meta = a->kind == _WC_ARG_FLAG ? "" : a->metavar;
    char label[80];

    if (a->letter)
        snprintf(label, sizeof label, "  -%c, --%s%s%s", a->letter, a->name,
                 eq, meta);
    else
        snprintf(label, sizeof label, "  --%s%s%s", a->name, eq, meta);
    fprint_lines(out, label, 19, 1, a->help);
}

int
_wc_schema_fprint_help(FILE * out, const _wc_command_schema * S)
{
    const _wc_arg * a;
    const char * group = "";

    if (S == NULL)
    {
        fputs(program_head, out);
        for (S = _wc_schema; S->name != NULL; S++)
        {
            char label[80];

            snprintf(label, sizeof label, "  %s", S->synopsis);
            fprint_lines(out, label, 25, 0, S->summary);
        }
        fputs(program_tail, out);
        return ferror(out) ? WC_EINTERNAL : WC_OK;
    }
    fprintf(out, "%s\n", S->usage);
    if (S->about[0] != '\0')
        fprintf(out, "%s\n", S->about);
    for (a = S->options; a->name != NULL; a++)
    {
        const char * g = a->group != NULL ? a->group : "Options";

        if (strcmp(g, group) != 0)
            fprintf(out, "\n%s:\n", g);
        group = g;
        fprint_option(out, a);
    }
    if (strcmp(group, "Options") != 0)
        fputs("\nOptions:\n", out);
    fputs("  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
    if (S->epilog != NULL)
        fprintf(out, "\n%s\n", S->epilog);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

/* ------------------------------------------------------------------ */
/* The table as JSON                                                   */

static const char * const kinds[] = {
    "flag", "choice", "count", "seed", "number", "numbers", "wrench",
    "angle", "string", "input", "output"
};

static void
fprint_str(FILE * out, const char * key, const char * s)
{
    fprintf(out, ", \"%s\": ", key);
    if (s != NULL)
        wc_fprint_json_string(out, s);
    else
        fputs("null", out);
}

static void
fprint_arg(FILE * out, const _wc_arg * a, int option)
{
    char key[64];
    const char * p;

    fputs("{\"key\": ", out);
    wc_fprint_json_string(out, _wc_arg_key(key, sizeof key, a));
    if (option)
        fprint_str(out, "option", a->name);
    fprintf(out, ", \"kind\": \"%s\"", kinds[a->kind]);
    fprint_str(out, "metavar", a->metavar);
    if (a->kind == _WC_ARG_CHOICE)
    {
        fputs(", \"values\": [\"", out);
        for (p = a->values; *p != '\0'; p++)
            if (*p == '|')
                fputs("\", \"", out);
            else
                putc(*p, out);
        fputs("\"]", out);
    }
    if (a->kind == _WC_ARG_COUNT)
        fprintf(out, ", \"min\": %ld, \"max\": %ld", a->lo, a->hi);
    fprint_str(out, "default", a->def);
    fprintf(out, ", \"request\": %s, \"optional\": %s",
            a->flags & _WC_ARG_CLI ? "false" : "true",
            option || (a->flags & _WC_ARG_OPTIONAL) ? "true" : "false");
    fprint_str(out, "help", a->help);
    putc('}', out);
}

int
_wc_schema_fprint_json(FILE * out)
{
    const _wc_command_schema * S;
    const _wc_arg * a;

    fputs("{\"format\": \"wrenchcone-schema/1\", \"commands\": [", out);
    for (S = _wc_schema; S->name != NULL; S++)
    {
        fputs(S == _wc_schema ? "{\"name\": " : ", {\"name\": ", out);
        wc_fprint_json_string(out, S->name);
        fprint_str(out, "synopsis", S->synopsis);
        fprint_str(out, "summary", S->summary);
        fprint_str(out, "about", S->about);
        fprintf(out, ", \"request\": %s, \"certificate\": %s, "
                "\"operands\": [", S->flags & _WC_CMD_REQUEST ? "true"
                : "false", _wc_runners[S - _wc_schema] != NULL
                && _wc_runners[S - _wc_schema]->certificate != NULL
                ? "true" : "false");
        for (a = S->operands; a->name != NULL; a++)
        {
            if (a != S->operands)
                fputs(", ", out);
            fprint_arg(out, a, 0);
        }
        fputs("], \"options\": [", out);
        for (a = S->options; a->name != NULL; a++)
        {
            if (a != S->options)
                fputs(", ", out);
            fprint_arg(out, a, 1);
        }
        fputs("]}", out);
    }
    fputs("]}\n", out);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}
