/* cmd-stability.c -- wrenchcone stability: the weakly and strongly stable
   sets, and a biasing wrench's robustness in them.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

const char cmd_stability_usage[] =
    "Usage: " PROG " stability [OPTIONS] PROBLEM\n"
    "Compute exactly the weakly stable cone, and the strongly stable sets under\n"
    "the exact semantics (weakly stable, no moving solution) and the paper's\n"
    "(eq. 19), each as pairwise disjoint NNC cones in canonical form; with a\n"
    "shape, the places a frictionless finger may push for each set.\n"
    "\n"
    "Options:\n"
    "  --bias=FX,FY,TAU  a biasing wrench: report the largest disturbance rho such\n"
    "                   that every disturbance d with ||d|| < rho keeps the\n"
    "                   wrench strongly stable, in the norm\n"
    "                   ||(fx, fy, tau)|| = max(|fx|, |fy|, |tau| / L)\n"
    "                   (also accepted: --bias FX FY TAU)\n"
    "  --length=L       the length L > 0 of that norm (default 1)\n"
    "  --certificate=FILE  also write a certificate (JSON) that the strongly\n"
    "                   stable set is exact, for wrenchcone verify\n"
    "  --format=FMT     text (default) or json\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

/* --bias alone takes a wrench.  */
enum { OPT_FORMAT = 256, OPT_LENGTH, OPT_CERT,
       OPT_BIAS = CLI_WRENCH_VALUE | 1 };

const struct option cmd_stability_options[] = {
    { "format", required_argument, NULL, OPT_FORMAT },
    { "bias", required_argument, NULL, OPT_BIAS },
    { "length", required_argument, NULL, OPT_LENGTH },
    { "certificate", required_argument, NULL, OPT_CERT },
    { NULL, 0, NULL, 0 }
};

/* The robustness of the bias, as text (JSON: the request layer).  */
static void
print_bias_text(const _wc_answer * a)
{
    const char * names[2] = { "exact", "paper" };
    int i;

    fputs("biasing wrench b = (", stdout);
    for (i = 0; i < 3; i++)
    {
        if (i)
            fputs(", ", stdout);
        wc_fprint_fmpq_text(stdout, a->b + i);
    }
    fputs("), disturbances measured by max(|fx|, |fy|, |tau| / ", stdout);
    wc_fprint_fmpq_text(stdout, a->L);
    fputs("):\n", stdout);
    for (i = 0; i < 2; i++)
        if (a->infinite[i])
            printf("  %s: every disturbance keeps it strongly stable (the set "
                   "is all of R^3)\n", names[i]);
        else if (fmpq_is_zero(a->rho[i]))
            printf("  %s: rho = 0: b is %s\n", names[i], a->in_set[i]
                   ? "on the boundary of the strongly stable set"
                   : "not strongly stable");
        else
        {
            printf("  %s: rho = ", names[i]);
            wc_fprint_fmpq_text(stdout, a->rho[i]);
            printf(": every disturbance d with ||d|| %s rho leaves b + d "
                   "strongly stable%s\n", a->closed[i] ? "<=" : "<",
                   a->closed[i] ? "" : " (some d with ||d|| = rho does not)");
        }
}

/* --bias's value split at its commas into bias[0..3), in the malloc'd
   *copy: 1, or 0 when it is not three values, -1 when out of memory.  */
static int
split_bias(char * bias[3], char ** copy, const char * value)
{
    char * p;
    int k;

    if ((*copy = malloc(strlen(value) + 1)) == NULL)
        return -1;
    strcpy(*copy, value);
    bias[0] = *copy;
    for (k = 1, p = *copy; k < 3 && (p = strchr(p, ',')) != NULL; k++)
    {
        *p++ = '\0';
        bias[k] = p;
    }
    return k == 3 && strchr(bias[2], ',') == NULL;
}

/* -1 to go on, or the exit status.  */
static int
parse(cli_format * fmt, const char ** bias, const char ** length,
      const char ** certificate, const cli_command * self, int argc,
      char ** argv)
{
    cli_options p;
    int c;

    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        if (c == OPT_BIAS)
            *bias = optarg;
        else if (c == OPT_LENGTH)
            *length = optarg;
        else if (c == OPT_CERT)
            *certificate = optarg;
        else if (!cli_parse_format(fmt, optarg, "stability", 0))
            return WC_EUSAGE;
    return c == CLI_EXIT ? p.status : -1;
}

int
cmd_stability(const cli_command * self, int argc, char ** argv)
{
    cli_format fmt = FMT_TEXT;
    const char * bias = NULL, * length = NULL, * certificate = NULL;
    char * values[3] = { NULL, NULL, NULL }, * copy = NULL;
    int status, split = 1;
    _wc_request R;
    _wc_answer A;
    wc_error_t err;

    if ((status = parse(&fmt, &bias, &length, &certificate, self, argc,
                        argv)) >= 0)
        return status;
    if (argc - optind != 1)
        return cli_usage_error("stability", argc - optind < 1
                               ? "stability needs PROBLEM%s"
                               : "stability takes PROBLEM only%s", "");
    if (bias != NULL && (split = split_bias(values, &copy, bias)) <= 0)
    {
        free(copy);
        if (split < 0)
        {
            fputs(PROG ": out of memory\n", stderr);
            return WC_EINTERNAL;
        }
        return cli_usage_error("stability", "--bias takes three numbers "
                               "FX,FY,TAU, not '%s'", bias);
    }
    _wc_request_init(&R, _WC_STABILITY);
    cli_input(&R.problem, argv[optind]);
    R.biased = bias != NULL;
    memcpy(R.bias, values, sizeof values);
    R.length = length;
    _wc_answer_init(&A);
    wc_error_init(err);
    status = _wc_run(&A, &R, err);
    status = cli_certify(status, certificate, CLI_CERT_STABILITY, A.P, A.S,
                         err);
    if (status == WC_OK)
    {
        if (fmt == FMT_JSON)
            _wc_answer_fprint_json(stdout, &A);
        else
        {
            wc_stability_fprint_text(stdout, A.S, A.P);
            if (R.biased)
                print_bias_text(&A);
        }
        status = cli_finish_output();
    }
    wc_error_clear(err);
    _wc_answer_clear(&A);
    free(copy);
    return status;
}
