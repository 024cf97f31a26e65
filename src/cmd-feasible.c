/* cmd-feasible.c -- wrenchcone feasible: one mode's kinematic verdict,
   with a checkable certificate.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "cli.h"
#include "commands.h"

int
cmd_feasible(const cli_command * self, int argc, char ** argv)
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
    status = cli_certify(status, R.certificate, CLI_CERT_FEASIBLE, A.P, A.C,
                         err);
    if (status == WC_OK)
    {
        /* JSON: the certificate itself, as batch prints it.  */
        if (cli_format_of(&R) == FMT_JSON)
            _wc_answer_fprint_json(stdout, &A);
        else
            wc_certificate_fprint(stdout, A.C, A.P, 0);
        status = cli_finish_output();
    }
    wc_error_clear(err);
    _wc_answer_clear(&A);
    return cli_done(&R, status);
}
