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
    "Two kinds: mode-feasibility ('" PROG " feasible --certificate=FILE'): the\n"
    "constraint rows are derived again from the certificate's problem and\n"
    "mode, then the witness or the Motzkin multipliers are checked exactly;\n"
    "strong-stability ('" PROG " classify --certificate=FILE'): the static\n"
    "forces or the separator, the motion, or -- for a strongly stable\n"
    "wrench -- a Farkas certificate for every moving face, the set of moving\n"
    "faces being derived again from the geometry.  Exit status 0 when the\n"
    "certificate holds, 4 when it does not, 1 when the file is malformed.\n"
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

/* What verify found.  */
typedef struct
{
    int holds;
    char * reason;      /* why not, when it does not hold */
    char * summary;     /* what holds */
    char * mode;        /* a mode-feasibility certificate's mode, or NULL */
    int feasible;       /* and its verdict */
}
verdict;

/* A mode-feasibility certificate also gives its mode and verdict as keys
   of the JSON answer; any other kind has no mode.  */
static void
find_mode(verdict * v, const char * text, size_t len, const char * path)
{
    wc_error_t e2;
    int h2;
    char * r2 = NULL;

    wc_error_init(e2);
    if (wc_verify_certificate(&h2, &r2, &v->mode, &v->feasible, text, len,
                              path, e2) != WC_OK)
        v->mode = NULL;
    free(r2);
    wc_error_clear(e2);
}

static void
print_json(const verdict * v)
{
    fprintf(stdout, "{\"holds\": %s", v->holds ? "true" : "false");
    if (v->mode != NULL)
    {
        fputs(", \"mode\": ", stdout);
        wc_fprint_json_string(stdout, v->mode);
        fprintf(stdout, ", \"feasible\": %s", v->feasible ? "true" : "false");
    }
    else
    {
        fputs(", \"summary\": ", stdout);
        wc_fprint_json_string(stdout, v->summary != NULL ? v->summary : "");
    }
    if (!v->holds)
    {
        fputs(", \"reason\": ", stdout);
        wc_fprint_json_string(stdout, v->reason != NULL ? v->reason : "");
    }
    fputs("}\n", stdout);
}

int
cmd_verify(const cli_command * self, int argc, char ** argv)
{
    cli_options p;
    cli_format fmt = FMT_TEXT;
    int c, status;
    char * text = NULL;
    const char * path;
    size_t len = 0;
    wc_error_t err;
    verdict v = { 0, NULL, NULL, NULL, 0 };

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
    if (status == WC_OK)
        status = wc_verify(&v.holds, &v.reason, &v.summary, text, len,
                           cli_input_name(path), err);
    if (status != WC_OK)
        cli_report(err, status);
    else
    {
        if (fmt == FMT_JSON)
        {
            find_mode(&v, text, len, path);
            print_json(&v);
        }
        else if (v.holds)
            printf("certificate holds: %s\n", v.summary);
        else
            printf("certificate does not hold: %s\n", v.reason);
        status = cli_finish_output();
        if (status == WC_OK && !v.holds)
            status = WC_EDISAGREE;
    }
    free(text);
    free(v.reason);
    free(v.mode);
    free(v.summary);
    wc_error_clear(err);
    return status;
}
