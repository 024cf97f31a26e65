/* cmd-plan.c -- wrenchcone plan: the sensorless insertion plan, or one
   wrench's verdict under it.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "cli.h"
#include "commands.h"

const char cmd_plan_usage[] =
    "Usage: " PROG " plan [OPTIONS] PROBLEM [FX FY TAU]\n"
    "The sensorless insertion plan of paper Sections 8 and 9 for all fixels of\n"
    "PROBLEM (their touching/near states are ignored: every contact state is\n"
    "considered).  For every state S and nonempty L in S the string s on L,\n"
    "m on S \\ L, u off S; for every S but the goal, m on S, s off S.  Prints\n"
    "the strings of each state (Table 5), which are redundant syntactically and\n"
    "exactly, the goal set G_goal (the complement of the union of their cones)\n"
    "as pairwise disjoint NNC cones, whether G_goal lies in the goal state's\n"
    "strongly stable set (eq. 25, both semantics), and with a shape where a\n"
    "frictionless finger may push.  With a wrench FX FY TAU: whether it is in\n"
    "G_goal and which needed strings hold it.\n"
    "\n"
    "Options:\n"
    "  --complete       also the complete plan (beyond the paper): accept a\n"
    "                   wrench when every transition graph it allows is acyclic\n"
    "                   with the goal as its only sink (wrenchcone(1) states the\n"
    "                   transition model); as a set, or for the wrench given,\n"
    "                   with its transitions.  At most 6 fixels\n"
    "  --certificate=FILE  also write a certificate (JSON) that G_goal is\n"
    "                   exact, for wrenchcone verify (not with a wrench)\n"
    "  --format=FMT     text (default) or json\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

enum { OPT_FORMAT = 256, OPT_COMPLETE, OPT_CERT };

const struct option cmd_plan_options[] = {
    { "format", required_argument, NULL, OPT_FORMAT },
    { "complete", no_argument, NULL, OPT_COMPLETE },
    { "certificate", required_argument, NULL, OPT_CERT },
    { NULL, 0, NULL, 0 }
};

int
cmd_plan(const cli_command * self, int argc, char ** argv)
{
    cli_options p;
    cli_format fmt = FMT_TEXT;
    int c, k, status, with_wrench, complete = 0;
    const char * certificate = NULL;
    _wc_request R;
    _wc_answer A;
    wc_error_t err;

    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        if (c == OPT_COMPLETE)
            complete = 1;
        else if (c == OPT_CERT)
            certificate = optarg;
        else if (!cli_parse_format(&fmt, optarg, "plan", 0))
            return WC_EUSAGE;
    if (c == CLI_EXIT)
        return p.status;
    if (argc - optind != 1 && argc - optind != 4)
        return cli_usage_error("plan", argc - optind < 1
                               ? "plan needs PROBLEM%s"
                               : "plan takes PROBLEM and optionally FX FY TAU%s",
                               "");
    with_wrench = argc - optind == 4;
    if (with_wrench && certificate != NULL)
        return cli_usage_error("plan", "--certificate certifies G_goal, "
                               "not one wrench: drop FX FY TAU%s", "");
    _wc_request_init(&R, _WC_PLAN);
    cli_input(&R.problem, argv[optind]);
    R.nwrench = with_wrench ? 3 : 0;
    for (k = 0; k < R.nwrench; k++)
        R.wrench[k] = argv[optind + 1 + k];
    R.complete = complete;
    R.certificates = certificate != NULL;
    _wc_answer_init(&A);
    wc_error_init(err);
    status = _wc_run(&A, &R, err);
    status = cli_certify(status, certificate, CLI_CERT_PLAN, A.P, A.plan,
                         err);
    if (status == WC_OK)
    {
        if (fmt == FMT_JSON)
            _wc_answer_fprint_json(stdout, &A);
        else if (with_wrench)
            wc_plan_wrench_fprint(stdout, A.pw, 0);
        else
            wc_plan_fprint(stdout, A.plan, A.P, 0);
        status = cli_finish_output();
    }
    wc_error_clear(err);
    _wc_answer_clear(&A);
    return status;
}
