/* cmd-feasible.c -- wrenchcone feasible: one mode's kinematic verdict,
   with a checkable certificate.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "cli.h"
#include "commands.h"

const char cmd_feasible_usage[] =
    "Usage: " PROG " feasible [OPTIONS] PROBLEM MODE\n"
    "Decide whether MODE (paper Table 1 letters) is kinematically feasible and\n"
    "print a certificate: a primitive integer witness twist, or Motzkin\n"
    "multipliers whose combination of the mode's constraint rows is zero,\n"
    "proving that no twist has the mode.  Exit status 0 either way.\n"
    "\n"
    "Options:\n"
    "  --certificate=FILE  also write the self-contained JSON certificate to\n"
    "                      FILE, for '" PROG " verify FILE'\n"
    "  --format=FMT        text (default) or json (the certificate itself)\n"
    "  -h, --help          print this help and exit\n"
    "  -V, --version       print versions and exit\n";

enum { OPT_FORMAT = 256, OPT_CERT };

const struct option cmd_feasible_options[] = {
    { "format", required_argument, NULL, OPT_FORMAT },
    { "certificate", required_argument, NULL, OPT_CERT },
    { NULL, 0, NULL, 0 }
};

int
cmd_feasible(const cli_command * self, int argc, char ** argv)
{
    cli_options p;
    cli_format fmt = FMT_TEXT;
    const char * certificate = NULL;
    int c, status;
    _wc_request R;
    _wc_answer A;
    wc_error_t err;

    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        if (c == OPT_CERT)
            certificate = optarg;
        else if (!cli_parse_format(&fmt, optarg, "feasible", 0))
            return WC_EUSAGE;
    if (c == CLI_EXIT)
        return p.status;
    if (argc - optind != 2)
        return cli_usage_error("feasible", argc - optind < 2
                               ? "feasible needs PROBLEM and MODE%s"
                               : "feasible takes PROBLEM and MODE only%s", "");
    _wc_request_init(&R, _WC_FEASIBLE);
    cli_input(&R.problem, argv[optind]);
    R.mode = argv[optind + 1];
    _wc_answer_init(&A);
    wc_error_init(err);
    status = _wc_run(&A, &R, err);
    status = cli_certify(status, certificate, CLI_CERT_FEASIBLE, A.P, A.C,
                         err);
    if (status == WC_OK)
    {
        /* JSON: the certificate itself, as batch prints it.  */
        if (fmt == FMT_JSON)
            _wc_answer_fprint_json(stdout, &A);
        else
            wc_certificate_fprint(stdout, A.C, A.P, 0);
        status = cli_finish_output();
    }
    wc_error_clear(err);
    _wc_answer_clear(&A);
    return status;
}
