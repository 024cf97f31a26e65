/* cmd-cone.c -- wrenchcone cone: the exact wrench cone of one contact
   mode, or the paper's route in doubles.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

const char cmd_cone_usage[] =
    "Usage: " PROG " cone [OPTIONS] PROBLEM MODE\n"
    "  or:  " PROG " cone --all-modes [OPTIONS] PROBLEM\n"
    "Print W(MODE), the exact cone of external wrenches (fx, fy, torque)\n"
    "consistent with MODE, in canonical form: closure facets, rays, and every\n"
    "face of the closure with whether it belongs to the cone.\n"
    "\n"
    "MODE has one letter per fixel, in file order (paper Table 2):\n"
    "  touching fixels: s separate, l slide left, r slide right, n roll,\n"
    "                   m maintain contact;\n"
    "  near fixels:     s separate, a approach, u unconstrained.\n"
    "\n"
    "Options:\n"
    "  --format=FMT     text (default), json (see wrenchcone(1)), cdd (cddlib .ine then\n"
    "                   .ext with rationals), ine, or ext\n"
    "  --method=METHOD  direct (default; Minkowski sum in R^3) or paper (the\n"
    "                   paper's Section 5 route); both print the same bytes\n"
    "  --trace          also print every intermediate matrix of the route\n"
    "  --arith=ARITH    exact (default) or double: the paper route in C doubles\n"
    "                   with cddlib's double-precision build, the floating-point\n"
    "                   baseline (needs --method=paper, no --trace; unit-length\n"
    "                   vectors, a strict flag per facet and ray instead of faces)\n"
    "  --all-modes      the cone of every mode that 'modes' lists, in its order,\n"
    "                   one JSON line each (as --format=json prints it); at most\n"
    "                   10000 modes\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

enum { OPT_FORMAT = 256, OPT_METHOD, OPT_TRACE, OPT_ARITH, OPT_ALL };

const struct option cmd_cone_options[] = {
    { "format", required_argument, NULL, OPT_FORMAT },
    { "method", required_argument, NULL, OPT_METHOD },
    { "trace", no_argument, NULL, OPT_TRACE },
    { "arith", required_argument, NULL, OPT_ARITH },
    { "all-modes", no_argument, NULL, OPT_ALL },
    { NULL, 0, NULL, 0 }
};

typedef struct
{
    cli_format fmt;
    wc_method method;
    int trace;
    int arith_double;   /* --arith=double */
    int all_modes;      /* --all-modes */
    int fmt_given;
}
cone_options;

/* -1 to go on, or the exit status.  */
static int
parse(cone_options * o, const cli_command * self, int argc, char ** argv)
{
    cli_options p;
    int c;

    o->fmt = FMT_TEXT;
    o->method = WC_METHOD_DIRECT;
    o->trace = 0;
    o->arith_double = 0;
    o->all_modes = 0;
    o->fmt_given = 0;
    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        switch (c)
        {
        case OPT_FORMAT:
            if (!cli_parse_format(&o->fmt, optarg, "cone", 1))
                return WC_EUSAGE;
            o->fmt_given = 1;
            break;
        case OPT_ALL:
            o->all_modes = 1;
            break;
        case OPT_METHOD:
            if (strcmp(optarg, "direct") == 0)
                o->method = WC_METHOD_DIRECT;
            else if (strcmp(optarg, "paper") == 0)
                o->method = WC_METHOD_PAPER;
            else
                return cli_usage_error("cone", "unknown method '%s' (direct "
                                       "or paper)", optarg);
            break;
        case OPT_TRACE:
            o->trace = 1;
            break;
        case OPT_ARITH:
            if (strcmp(optarg, "exact") != 0 && strcmp(optarg, "double") != 0)
                return cli_usage_error("cone", "unknown arithmetic '%s' "
                                       "(exact or double)", optarg);
            o->arith_double = optarg[0] == 'd';
            break;
        }
    return c == CLI_EXIT ? p.status : -1;
}

/* --method=paper --arith=double: the float baseline, printed by
   fconeprint.c.  */
static void
print_double(cli_format fmt, const char * mode, const wc_fcone_t W)
{
    if (fmt == FMT_TEXT)
    {
        printf("W(%s): wrench cone of mode %s\n", mode, mode);
        wc_fcone_fprint(stdout, W, WC_FCONE_TEXT);
    }
    else
    {
        printf("* wrenchcone: W(%s), the wrench cone of mode %s\n", mode, mode);
        wc_fcone_fprint(stdout, W, fmt == FMT_INE ? WC_FCONE_INE
                        : fmt == FMT_EXT ? WC_FCONE_EXT : WC_FCONE_CDD);
    }
}

/* Print the cone (and its trace) as text or cdd (JSON: cli_run_json);
   title: the cdd formats' title.  */
static void
print_cone(const cone_options * o, const char * mode, const wc_cone_t W,
           const wc_trace_t T, const char * title)
{
    switch (o->fmt)
    {
    case FMT_TEXT:
        if (o->trace)
        {
            printf("trace (%s route):\n", o->method == WC_METHOD_PAPER
                   ? "paper, Section 5" : "direct, M V_x + (-J) D_x");
            wc_trace_fprint_text(stdout, T, "  ");
            putchar('\n');
        }
        printf("W(%s): wrench cone of mode %s\n", mode, mode);
        wc_cone_fprint_text(stdout, W, "  ");
        break;
    default:
        if (o->trace)
            wc_trace_fprint_text(stdout, T, "* ");
        wc_cone_fprint_cdd(stdout, W, title, o->fmt == FMT_INE ? 1
                           : o->fmt == FMT_EXT ? 2 : 3);
        break;
    }
}

/* The title of the cdd formats, malloc'd.  */
static char *
cdd_title(const char * mode)
{
    size_t len = strlen(mode) + 64;
    char * title = malloc(len);

    if (title != NULL)
        snprintf(title, len, "wrenchcone: W(%s), the wrench cone of mode %s",
                 mode, mode);
    return title;
}

/* The request of the options o, for PROBLEM path and mode.  */
static void
request(_wc_request * R, const cone_options * o, const char * path,
        const char * mode)
{
    _wc_request_init(R, _WC_CONE);
    cli_input(&R->problem, path);
    R->mode = mode;
    R->method = o->method;
    R->trace = o->trace;
    R->arith_double = o->arith_double;
}

static int
all_modes(const cone_options * o, int argc, char ** argv)
{
    _wc_request R;

    if (o->fmt_given && o->fmt != FMT_JSON)
        return cli_usage_error("cone", "--all-modes prints JSON lines: "
                               "--format=json or none%s", "");
    if (argc - optind != 1)
        return cli_usage_error("cone", argc - optind < 1
                               ? "cone --all-modes needs PROBLEM%s"
                               : "cone --all-modes takes PROBLEM only%s", "");
    request(&R, o, argv[optind], NULL);
    return cli_cone_all_modes(&R);
}

int
cmd_cone(const cli_command * self, int argc, char ** argv)
{
    cone_options o;
    int status;
    const char * mode;
    char * title = NULL;
    _wc_request R;
    _wc_answer A;
    wc_error_t err;

    if ((status = parse(&o, self, argc, argv)) >= 0)
        return status;
    if (o.arith_double && o.method != WC_METHOD_PAPER)
        return cli_usage_error("cone", "--arith=double needs --method=paper%s", "");
    if (o.arith_double && o.trace)
        return cli_usage_error("cone", "--arith=double does not take --trace%s", "");
    if (o.all_modes)
        return all_modes(&o, argc, argv);
    if (argc - optind != 2)
        return cli_usage_error("cone", argc - optind < 2
                               ? "cone needs PROBLEM and MODE%s"
                               : "cone takes PROBLEM and MODE only%s", "");
    mode = argv[optind + 1];
    request(&R, &o, argv[optind], mode);
    if (o.fmt == FMT_JSON)
        return cli_run_json(&R);
    _wc_answer_init(&A);
    wc_error_init(err);
    status = _wc_run(&A, &R, err);
    if (status == WC_OK && !o.arith_double && o.fmt != FMT_TEXT
        && (title = cdd_title(mode)) == NULL)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    if (status != WC_OK)
        cli_report(err, status);
    else
    {
        if (o.arith_double)
            print_double(o.fmt, mode, A.F);
        else
            print_cone(&o, mode, A.W, A.T, title);
        status = cli_finish_output();
    }
    free(title);
    wc_error_clear(err);
    _wc_answer_clear(&A);
    return status;
}
