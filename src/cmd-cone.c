/* cmd-cone.c -- wrenchcone cone: the exact wrench cone of one contact
   mode, or the paper's route in doubles.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

/* --method=paper --arith=double: the float baseline, printed by
   fconeprint.c.  */
static void
print_double(cli_format fmt, const char * mode, const wc_fcone_t W)
{
    if (fmt == FMT_TEXT)
    {
        printf("W(%s): wrench cone of mode %s\n", mode, mode);
        wc_fcone_fprint(stdout, W, WC_FCONE_TEXT);
    }
    else
    {
        printf("* wrenchcone: W(%s), the wrench cone of mode %s\n", mode, mode);
        wc_fcone_fprint(stdout, W, fmt == FMT_INE ? WC_FCONE_INE
                        : fmt == FMT_EXT ? WC_FCONE_EXT : WC_FCONE_CDD);
    }
}

/* Print the cone (and its trace) as text or cdd (JSON: cli_run_json);
   title: the cdd formats' title.  */
static void
print_cone(const _wc_request * R, const char * mode, const wc_cone_t W,
           const wc_trace_t T, const char * title)
{
    cli_format fmt = cli_format_of(R);

    switch (fmt)
    {
    case FMT_TEXT:
        if (R->trace)
        {
            printf("trace (%s route):\n", R->method == WC_METHOD_PAPER
                   ? "paper, Section 5" : "direct, M V_x + (-J) D_x");
            wc_trace_fprint_text(stdout, T, "  ");
            putchar('\n');
        }
        printf("W(%s): wrench cone of mode %s\n", mode, mode);
        wc_cone_fprint_text(stdout, W, "  ");
        break;
    default:
        if (R->trace)
            wc_trace_fprint_text(stdout, T, "* ");
        wc_cone_fprint_cdd(stdout, W, title, fmt == FMT_INE ? 1
                           : fmt == FMT_EXT ? 2 : 3);
        break;
    }
}

/* The title of the cdd formats, malloc'd.  */
static char *
cdd_title(const char * mode)
{
    size_t len = strlen(mode) + 64;
    char * title = malloc(len);

    if (title != NULL)
        snprintf(title, len, "wrenchcone: W(%s), the wrench cone of mode %s",
                 mode, mode);
    return title;
}

int
cmd_cone(const cli_command * self, int argc, char ** argv)
{
    int status;
    char * title = NULL;
    cli_format fmt;
    _wc_request R;
    _wc_answer A;
    wc_error_t err;

    if ((status = cli_parse(&R, self, argc, argv)) >= 0)
    {
        _wc_request_clear(&R);
        return status;
    }
    fmt = cli_format_of(&R);
    if (R.all_modes)
        status = cli_cone_all_modes(&R);
    else if (fmt == FMT_JSON)
        status = cli_run_json(&R);
    if (R.all_modes || fmt == FMT_JSON)
    {
        _wc_request_clear(&R);
        return status;
    }
    _wc_answer_init(&A);
    wc_error_init(err);
    status = _wc_run(&A, &R, err);
    if (status == WC_OK && !R.arith_double && fmt != FMT_TEXT
        && (title = cdd_title(R.mode)) == NULL)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    if (status != WC_OK)
        cli_report(err, status);
    else
    {
        if (R.arith_double)
            print_double(fmt, R.mode, A.F);
        else
            print_cone(&R, R.mode, A.W, A.T, title);
        status = cli_finish_output();
    }
    free(title);
    wc_error_clear(err);
    _wc_answer_clear(&A);
    _wc_request_clear(&R);
    return status;
}
