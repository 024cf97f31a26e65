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

/* The answer: the sets, and the robustness of the biasing wrench b in
   both strong sets (exact, then paper).  */
typedef struct
{
    wc_stability_t S;
    int biased;
    fmpq b[3];
    fmpq_t L;
    fmpq_t rho[2];
    int closed[2], infinite[2], in_set[2];
}
answer;

static void
answer_init(answer * a)
{
    int i;

    wc_stability_init(a->S);
    a->biased = 0;
    for (i = 0; i < 3; i++)
        fmpq_init(a->b + i);
    fmpq_init(a->L);
    fmpq_one(a->L);
    for (i = 0; i < 2; i++)
        fmpq_init(a->rho[i]);
}

static void
answer_clear(answer * a)
{
    int i;

    for (i = 0; i < 2; i++)
        fmpq_clear(a->rho[i]);
    fmpq_clear(a->L);
    for (i = 0; i < 3; i++)
        fmpq_clear(a->b + i);
    wc_stability_clear(a->S);
}

/* Both robustness figures, before anything is printed.  */
static int
robustness(answer * a, wc_error_t err)
{
    const wc_set_struct * sets[2] = { a->S->strong, a->S->strong_paper };
    int i, status = WC_OK;

    for (i = 0; i < 2 && status == WC_OK; i++)
    {
        status = wc_robustness(a->rho[i], a->closed + i, a->infinite + i,
                               sets[i], a->S->cells, a->b, a->L, err);
        a->in_set[i] = wc_set_contains(sets[i], a->b);
    }
    return status;
}

static void
print_bias_json(const answer * a)
{
    int i;

    fputs(", \"bias\": {\"wrench\": [", stdout);
    for (i = 0; i < 3; i++)
    {
        fputs(i ? ", \"" : "\"", stdout);
        wc_fprint_fmpq(stdout, a->b + i);
        putchar('"');
    }
    fputs("], \"length\": \"", stdout);
    wc_fprint_fmpq(stdout, a->L);
    putchar('"');
    for (i = 0; i < 2; i++)
    {
        fprintf(stdout, ", \"%s\": {\"in_set\": %s, ", i == 0 ? "strong"
                : "strong_paper", a->in_set[i] ? "true" : "false");
        if (a->infinite[i])
            fputs("\"rho\": null, \"unbounded\": true}", stdout);
        else
        {
            fputs("\"rho\": \"", stdout);
            wc_fprint_fmpq(stdout, a->rho[i]);
            fprintf(stdout, "\", \"closed\": %s}",
                    a->closed[i] ? "true" : "false");
        }
    }
    putchar('}');
}

static void
print_bias_text(const answer * a)
{
    const char * names[2] = { "exact", "paper" };
    int i;

    fputs("biasing wrench b = (", stdout);
    for (i = 0; i < 3; i++)
    {
        if (i)
            fputs(", ", stdout);
        wc_fprint_fmpq(stdout, a->b + i);
    }
    fputs("), disturbances measured by max(|fx|, |fy|, |tau| / ", stdout);
    wc_fprint_fmpq(stdout, a->L);
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
            wc_fprint_fmpq(stdout, a->rho[i]);
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

/* The whole answer: the problem, --bias and --length read, the sets and
   the robustness computed.  */
typedef struct
{
    const wc_problem_struct * P;
    const wc_stability_struct * S;
    wc_error_struct * err;
}
cert_job;

static int
put_certificate(FILE * f, const void * p)
{
    const cert_job * j = p;

    return wc_stability_certificate_fprint(f, j->P, j->S, j->err);
}

static int
compute(answer * a, const char * path, char ** bias, const char * length,
        const char * certificate, wc_error_t err)
{
    wc_problem_t P;
    int status;

    wc_problem_init(P);
    status = cli_load_problem(P, path, err);
    if (status == WC_OK && a->biased)
        status = cli_parse_numbers(a->b, bias, 3, "<bias>", err);
    if (status == WC_OK && length != NULL)
    {
        status = cli_parse_numbers(a->L, (char **) &length, 1, "<length>",
                                   err);
        if (status == WC_OK && fmpq_sgn(a->L) <= 0)
            status = wc_error_set(err, WC_EINPUT, "<length>", 1, 1,
                                  "the length must be positive");
    }
    if (status == WC_OK)
        status = wc_stability(a->S, P, err);
    if (status == WC_OK && a->biased)
        status = robustness(a, err);
    if (status == WC_OK && certificate != NULL)
    {
        cert_job j = { P, a->S, err };

        status = cli_write_certificate(certificate, put_certificate, &j);
        if (status != WC_OK && err->message == NULL)
            status = -status;       /* reported already */
    }
    wc_problem_clear(P);
    return status;
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
    wc_error_t err;
    answer a;

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
    if (fmt == FMT_JSON && certificate == NULL)
    {
        _wc_request R;

        _wc_request_init(&R, _WC_STABILITY);
        cli_input(&R.problem, argv[optind]);
        R.biased = bias != NULL;
        memcpy(R.bias, values, sizeof values);
        R.length = length;
        status = cli_run_json(&R);
        free(copy);
        return status;
    }
    wc_error_init(err);
    answer_init(&a);
    a.biased = bias != NULL;
    status = compute(&a, argv[optind], values, length, certificate, err);
    if (status < 0)
        status = -status;
    else if (status != WC_OK)
        cli_report(err, status);
    else
    {
        wc_stability_fprint(stdout, a.S, fmt == FMT_JSON ? 2 : 0);
        if (a.biased && fmt == FMT_JSON)
            print_bias_json(&a);
        else if (a.biased)
            print_bias_text(&a);
        if (fmt == FMT_JSON)
            fputs("}\n", stdout);
        status = cli_finish_output();
    }
    answer_clear(&a);
    wc_error_clear(err);
    free(copy);
    return status;
}
