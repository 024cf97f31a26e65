/* cmd-random.c -- wrenchcone random: a reproducible random problem.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

const char cmd_random_usage[] =
    "Usage: " PROG " random [OPTIONS]\n"
    "Print a random problem as a .wc file, the same bytes for the same options\n"
    "on every platform; the first line is a comment naming the command that\n"
    "reproduces it.\n"
    "\n"
    "Options:\n"
    "  --fixels=N       the number of fixels, 1 to 1000 (default 3)\n"
    "  --seed=S         the seed, a decimal integer below 2^64 (default 1)\n"
    "  --degenerate     plant degenerate features: two fixels at one point,\n"
    "                   normals parallel or opposed, normals 10^-9 apart,\n"
    "                   three collinear contact points\n"
    "  --shape=SHAPE    none (default), disk or polygon: points on the shape's\n"
    "                   boundary, with its exact inward normals\n"
    "  --friction=MU[,MUK]\n"
    "                   use these exact friction coefficients (mu_s, mu_k) at\n"
    "                   every fixel instead of drawing them\n"
    "  --format=FMT     text (default; the .wc file)\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

enum { OPT_FIXELS = 256, OPT_SEED, OPT_DEGENERATE, OPT_SHAPE, OPT_FRICTION,
       OPT_FORMAT };

const struct option cmd_random_options[] = {
    { "fixels", required_argument, NULL, OPT_FIXELS },
    { "seed", required_argument, NULL, OPT_SEED },
    { "degenerate", no_argument, NULL, OPT_DEGENERATE },
    { "shape", required_argument, NULL, OPT_SHAPE },
    { "friction", required_argument, NULL, OPT_FRICTION },
    { "format", required_argument, NULL, OPT_FORMAT },
    { NULL, 0, NULL, 0 }
};

/* 1 when s is a decimal integer (digits only) no larger than max.  */
static int
parse_uint(uint64_t * v, const char * s, uint64_t max)
{
    uint64_t x = 0;

    if (*s == '\0')
        return 0;
    for (; *s != '\0'; s++)
    {
        if (*s < '0' || *s > '9' || x > (max - (uint64_t) (*s - '0')) / 10)
            return 0;
        x = 10 * x + (uint64_t) (*s - '0');
    }
    *v = x;
    return 1;
}

/* MU or MU,MUK: exact non-negative numbers.  */
static int
parse_friction(wc_random_options * ro, const char * s)
{
    const char * comma = strchr(s, ',');
    size_t len = comma != NULL ? (size_t) (comma - s) : strlen(s);
    wc_error_t err;
    int ok;

    wc_error_init(err);
    ok = wc_parse_number_bounded(ro->mu_s, s, len, err) == WC_OK
        && fmpq_sgn(ro->mu_s) >= 0;
    if (ok && comma != NULL)
        ok = wc_parse_number_bounded(ro->mu_k, comma + 1,
                                     strlen(comma + 1), err) == WC_OK
             && fmpq_sgn(ro->mu_k) >= 0;
    else if (ok)
        fmpq_set(ro->mu_k, ro->mu_s);
    wc_error_clear(err);
    ro->friction = 1;
    return ok;
}

/* One option's value into ro: -1 to go on, or the exit status.  */
static int
take_option(wc_random_options * ro, int c, const char * arg)
{
    uint64_t v;

    switch (c)
    {
    case OPT_FIXELS:
        if (!parse_uint(&v, arg, WC_RANDOM_MAX_FIXELS) || v < 1)
            return cli_usage_error("random", "--fixels must be an integer "
                                   "from 1 to 1000, not '%s'", arg);
        ro->fixels = (slong) v;
        break;
    case OPT_SEED:
        if (!parse_uint(&v, arg, UINT64_MAX))
            return cli_usage_error("random", "--seed must be a decimal "
                                   "integer from 0 to 2^64 - 1, not '%s'",
                                   arg);
        ro->seed = v;
        break;
    case OPT_DEGENERATE:
        ro->degenerate = 1;
        break;
    case OPT_SHAPE:
        if (strcmp(arg, "none") == 0)
            ro->shape = WC_SHAPE_NONE;
        else if (strcmp(arg, "disk") == 0)
            ro->shape = WC_SHAPE_DISK;
        else if (strcmp(arg, "polygon") == 0)
            ro->shape = WC_SHAPE_POLYGON;
        else
            return cli_usage_error("random", "unknown shape '%s' (none, disk "
                                   "or polygon)", arg);
        break;
    case OPT_FRICTION:
        if (!parse_friction(ro, arg))
            return cli_usage_error("random", "--friction must be MU or "
                                   "MU,MUK, exact non-negative numbers such "
                                   "as 1/5 or 0.2, not '%s'", arg);
        break;
    case OPT_FORMAT:
        if (strcmp(arg, "text") != 0)
            return cli_usage_error("random", "unknown format '%s' (random "
                                   "prints a .wc file: text only)", arg);
        break;
    }
    return -1;
}

/* -1 to go on, or the exit status.  */
static int
parse(wc_random_options * ro, const cli_command * self, int argc,
      char ** argv)
{
    cli_options p;
    int c, status = -1;

    cli_options_init(&p, self);
    while (status < 0 && (c = cli_option(&p, argc, argv)) != CLI_DONE)
        status = c == CLI_EXIT ? p.status : take_option(ro, c, optarg);
    if (status < 0 && optind < argc)
        status = cli_usage_error("random", "random takes no operands, not "
                                 "'%s'", argv[optind]);
    return status;
}

int
cmd_random(const cli_command * self, int argc, char ** argv)
{
    wc_random_options ro;
    wc_problem_t P;
    wc_error_t err;
    char * line = NULL;
    int status;

    wc_random_options_init(&ro);
    if ((status = parse(&ro, self, argc, argv)) >= 0)
    {
        wc_random_options_clear(&ro);
        return status;
    }
    wc_problem_init(P);
    wc_error_init(err);
    status = wc_random_problem(P, &ro, err);
    if (status == WC_OK && (line = wc_random_options_str(&ro)) == NULL)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    if (status != WC_OK)
        cli_report(err, status);
    else
    {
        printf("# " PROG " random %s\n", line);
        status = wc_problem_fprint(stdout, P);
        if (status == WC_OK)
            status = cli_finish_output();
        else
            fprintf(stderr, PROG ": write error: %s\n", strerror(errno));
    }
    free(line);
    wc_error_clear(err);
    wc_problem_clear(P);
    wc_random_options_clear(&ro);
    return status;
}
