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

int
cmd_stability(const cli_command * self, int argc, char ** argv)
{
    int status;
    _wc_request R;
    _wc_answer A;
    wc_error_t err;

    if ((status = cli_parse(&R, self, argc, argv)) >= 0)
        return cli_done(&R, status);
    _wc_answer_init(&A);
    wc_error_init(err);
    status = _wc_run(&A, &R, err);
    status = cli_certify(status, R.certificate, CLI_CERT_STABILITY, A.P, A.S,
                         err);
    if (status == WC_OK)
    {
        if (cli_format_of(&R) == FMT_JSON)
            _wc_answer_fprint_json(stdout, &A);
        else
        {
            wc_stability_fprint_text(stdout, A.S, A.P);
            if (R.bias.given)
                print_bias_text(&A);
        }
        status = cli_finish_output();
    }
    wc_error_clear(err);
    _wc_answer_clear(&A);
    return cli_done(&R, status);
}
