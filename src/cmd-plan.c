/* cmd-plan.c -- wrenchcone plan: the sensorless insertion plan, or one
   wrench's verdict under it.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "cli.h"
#include "commands.h"

int
cmd_plan(const cli_command * self, int argc, char ** argv)
{
    int status;
    _wc_request R;
    _wc_answer A;
    wc_error_t err;

    if ((status = cli_parse(&R, self, argc, argv)) >= 0)
        return cli_done(&R, status);
    R.certificates = R.certificate != NULL;
    _wc_answer_init(&A);
    wc_error_init(err);
    status = _wc_run(&A, &R, err);
    status = cli_certify(status, R.certificate, CLI_CERT_PLAN, A.P, A.plan,
                         err);
    if (status == WC_OK)
    {
        if (cli_format_of(&R) == FMT_JSON)
            _wc_answer_fprint_json(stdout, &A);
        else if (R.wrench.given)
            wc_plan_wrench_fprint(stdout, A.pw, 0);
        else
            wc_plan_fprint(stdout, A.plan, A.P, 0);
        status = cli_finish_output();
    }
    wc_error_clear(err);
    _wc_answer_clear(&A);
    return cli_done(&R, status);
}
