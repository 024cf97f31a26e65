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

/* The options of R into ro: -1 to go on, or the exit status.  */
static int
options(wc_random_options * ro, const _wc_request * R)
{
    static const wc_shape_kind shapes[3] = {
        WC_SHAPE_NONE, WC_SHAPE_DISK, WC_SHAPE_POLYGON
    };

    ro->fixels = (slong) R->fixels;
    ro->seed = (uint64_t) R->seed;
    ro->degenerate = R->degenerate;
    ro->shape = shapes[R->shape];
    if (R->friction != NULL && !parse_friction(ro, R->friction))
        return cli_usage_error("random", "--friction must be MU or "
                               "MU,MUK, exact non-negative numbers such "
                               "as 1/5 or 0.2, not '%s'", R->friction);
    return -1;
}

int
cmd_random(const cli_command * self, int argc, char ** argv)
{
    wc_random_options ro;
    wc_problem_t P;
    wc_error_t err;
    _wc_request R;
    char * line = NULL;
    int status;

    if ((status = cli_parse(&R, self, argc, argv)) >= 0)
        return cli_done(&R, status);
    wc_random_options_init(&ro);
    if ((status = options(&ro, &R)) >= 0)
    {
        wc_random_options_clear(&ro);
        return cli_done(&R, status);
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
    return cli_done(&R, status);
}
