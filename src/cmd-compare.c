/* cmd-compare.c -- wrenchcone compare: a cone computed elsewhere against
   the exact one.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

const char cmd_compare_usage[] =
    "Usage: " PROG " compare [OPTIONS] PROBLEM MODE FILE\n"
    "Check a cone computed elsewhere, typically in floating point, against the\n"
    "exact W(MODE).  FILE is a cddlib .ext (generators) or .ine (inequalities)\n"
    "with integers, fractions, decimals or exponents, or a JSON cone as\n"
    "'" PROG " cone --format=json' prints it (exact, or with floats).\n"
    "FILE's numbers are read exactly, and the exact side decides emptiness,\n"
    "dimension, lineality, extreme rays and facets; floating point enters only\n"
    "the angles reported (radians): each float ray's angle to the exact closure,\n"
    "each exact ray's angle to the float closure, and the Hausdorff distance\n"
    "between the two closures on the unit sphere.  An extreme ray or facet with\n"
    "none of the other side's within the tolerance is missing (exact) or extra\n"
    "(float).  Strictness cannot be read from a float cone: the report lists\n"
    "the faces the exact cone excludes, to be checked separately.\n"
    "\n"
    "Exit status 0 when FILE is within the tolerance (same emptiness, dimension\n"
    "and lineality, Hausdorff distance <= T, nothing missing or extra), 4 when\n"
    "it is not, 1 when PROBLEM, MODE or FILE is malformed.\n"
    "\n"
    "Options:\n"
    "  --tol=T          tolerance in radians, 0 <= T < pi/2 (default 1e-9)\n"
    "  --format=FMT     text (default) or json\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

enum { OPT_TOL = 256, OPT_FORMAT };

const struct option cmd_compare_options[] = {
    { "tol", required_argument, NULL, OPT_TOL },
    { "format", required_argument, NULL, OPT_FORMAT },
    { NULL, 0, NULL, 0 }
};

/* -1 to go on, or the exit status.  */
static int
parse(double * tol, int * json, const cli_command * self, int argc,
      char ** argv)
{
    cli_options p;
    cli_format fmt = FMT_TEXT;
    char * end;
    int c;

    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        if (c == OPT_TOL)
        {
            *tol = strtod(optarg, &end);
            if (end == optarg || *end != '\0'
                || !(*tol >= 0 && *tol < 1.5707963))
                return cli_usage_error("compare", "--tol must be an angle in "
                                       "radians, at least 0 and below pi/2 "
                                       "(such as 1e-9), not '%s'", optarg);
        }
        else if (!cli_parse_format(&fmt, optarg, "compare", 0))
            return WC_EUSAGE;
    *json = fmt == FMT_JSON;
    return c == CLI_EXIT ? p.status : -1;
}

static void
print_comparison(const _wc_answer * A)
{
    wc_comparison_fprint(stdout, A->cmp, A->W, A->R->problem.name,
                         A->R->mode, A->R->foreign.name, 0);
}

int
cmd_compare(const cli_command * self, int argc, char ** argv)
{
    double tol = WC_COMPARE_TOL;
    int json = 0, status;
    const char * ppath, * mode, * fpath;
    _wc_request R;

    if ((status = parse(&tol, &json, self, argc, argv)) >= 0)
        return status;
    if (argc - optind != 3)
        return cli_usage_error("compare", argc - optind < 3
                               ? "compare needs PROBLEM, MODE and FILE%s"
                               : "compare takes PROBLEM, MODE and FILE only%s",
                               "");
    ppath = argv[optind];
    mode = argv[optind + 1];
    fpath = argv[optind + 2];
    if (strcmp(ppath, "-") == 0 && strcmp(fpath, "-") == 0)
        return cli_usage_error("compare", "PROBLEM and FILE cannot both be "
                               "standard input%s", "");
    _wc_request_init(&R, _WC_COMPARE);
    cli_input(&R.problem, ppath);
    R.mode = mode;
    cli_input(&R.foreign, fpath);
    R.tol = tol;
    return json ? cli_run_json(&R) : cli_run_print(&R, print_comparison);
}
