/* cmd-classify.c -- wrenchcone classify: one wrench's stability, motions
   and the modes holding it.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <errno.h>
#include <stdlib.h>

#include "cli.h"
#include "commands.h"

const char cmd_classify_usage[] =
    "Usage: " PROG " classify [OPTIONS] PROBLEM FX FY TAU\n"
    "Decide one external wrench g = (FX, FY, TAU) (exact numbers) at zero\n"
    "velocity, with exact LPs only (no cone conversion):\n"
    "  - weakly stable: a static solution exists (its forces are printed, or a\n"
    "    separating vector proving none does);\n"
    "  - every moving solution, by the contact mode of the motion, with a\n"
    "    witness (nudot, c);\n"
    "  - strongly stable in the exact sense (weakly stable, no solution moves)\n"
    "    and in the paper's sense (eq. 19: no Table 2 cone other than n..n\n"
    "    holds g), side by side;\n"
    "  - every contact mode (Table 2 letters: s l r n on touching fixels, s a on\n"
    "    near ones) whose wrench cone holds g.\n"
    "\n"
    "Options:\n"
    "  --certificate=FILE  write a strong-stability certificate (JSON) that\n"
    "                   '" PROG " verify' re-checks with GMP alone: the static\n"
    "                   forces or a separator, and a motion or a Farkas\n"
    "                   certificate for every moving face\n"
    "  --max-modes=N    list at most N modes (default 1000; 0: no limit).  The\n"
    "                   list can be exponentially long: a wrench that three of\n"
    "                   t touching fixels hold is held by 2^(t-3) strings\n"
    "  --format=FMT     text (default) or json\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

enum { OPT_FORMAT = 256, OPT_CERT, OPT_MAXMODES };

const struct option cmd_classify_options[] = {
    { "format", required_argument, NULL, OPT_FORMAT },
    { "certificate", required_argument, NULL, OPT_CERT },
    { "max-modes", required_argument, NULL, OPT_MAXMODES },
    { NULL, 0, NULL, 0 }
};

typedef struct
{
    cli_format fmt;
    const char * certificate;
    long max_modes;
}
classify_options;

/* -1 to go on, or the exit status.  */
static int
parse(classify_options * o, const cli_command * self, int argc,
      char ** argv)
{
    cli_options p;
    char * end;
    int c;

    o->fmt = FMT_TEXT;
    o->certificate = NULL;
    o->max_modes = 1000;
    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        switch (c)
        {
        case OPT_FORMAT:
            if (!cli_parse_format(&o->fmt, optarg, "classify", 0))
                return WC_EUSAGE;
            break;
        case OPT_CERT:
            o->certificate = optarg;
            break;
        case OPT_MAXMODES:
            errno = 0;
            o->max_modes = strtol(optarg, &end, 10);
            if (*optarg == '\0' || *end != '\0' || errno != 0
                || o->max_modes < 0)
                return cli_usage_error("classify", "--max-modes takes a "
                                       "count >= 0 (0: no limit), not '%s'",
                                       optarg);
            break;
        }
    return c == CLI_EXIT ? p.status : -1;
}

int
cmd_classify(const cli_command * self, int argc, char ** argv)
{
    classify_options o;
    int status, k;
    _wc_request R;
    _wc_answer A;
    wc_error_t err;

    if ((status = parse(&o, self, argc, argv)) >= 0)
        return status;
    if (argc - optind != 4)
        return cli_usage_error("classify", argc - optind < 4
                               ? "classify needs PROBLEM FX FY TAU%s"
                               : "classify takes PROBLEM FX FY TAU only%s", "");
    _wc_request_init(&R, _WC_CLASSIFY);
    cli_input(&R.problem, argv[optind]);
    R.nwrench = 3;
    for (k = 0; k < 3; k++)
        R.wrench[k] = argv[optind + 1 + k];
    R.max_modes = o.max_modes;
    R.certificates = o.certificate != NULL;
    _wc_answer_init(&A);
    wc_error_init(err);
    status = _wc_run(&A, &R, err);
    status = cli_certify(status, o.certificate, CLI_CERT_CLASSIFY, A.P, A.K,
                         err);
    if (status == WC_OK)
    {
        if (o.fmt == FMT_JSON)
            _wc_answer_fprint_json(stdout, &A);
        else
            wc_classify_fprint(stdout, A.K, 0);
        status = cli_finish_output();
    }
    wc_error_clear(err);
    _wc_answer_clear(&A);
    return status;
}
