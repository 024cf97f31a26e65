/* cli-request.c -- the computing commands' --format=json, and cone
   --all-modes, through the library's request layer (api/run.h): the
   command line, `batch` and wc_request_json print the same bytes because
   they run the same code.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"

void
cli_input(_wc_input * in, const char * path)
{
    memset(in, 0, sizeof *in);
    in->name = cli_input_name(path);
    if (strcmp(path, "-") == 0)
        in->stream = stdin;
    else
        in->path = path;
}

int
cli_run_print(const _wc_request * R, void (*print)(const _wc_answer * A))
{
    _wc_answer A;
    wc_error_t err;
    int status;

    _wc_answer_init(&A);
    wc_error_init(err);
    status = _wc_run(&A, R, err);
    if (status != WC_OK)
        cli_report(err, status);
    else
    {
        print(&A);
        status = cli_finish_output();
        if (status == WC_OK)
            status = _wc_answer_status(&A);
    }
    wc_error_clear(err);
    _wc_answer_clear(&A);
    return status;
}

static void
print_json(const _wc_answer * A)
{
    _wc_answer_fprint_json(stdout, A);
}

int
cli_run_json(const _wc_request * R)
{
    return cli_run_print(R, print_json);
}

/* The lines are gathered in memory and written once all are computed:
   a failure leaves stdout empty, as for every command.  */
int
cli_cone_all_modes(const _wc_request * R)
{
    char * buf = NULL;
    size_t size = 0;
    FILE * f = open_memstream(&buf, &size);
    wc_error_t err;
    int status;

    if (f == NULL)
    {
        fputs(PROG ": out of memory\n", stderr);
        return WC_EINTERNAL;
    }
    wc_error_init(err);
    status = _wc_cone_all_modes(f, R, err);
    if (fclose(f) != 0 && status == WC_OK)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    if (status != WC_OK)
        cli_report(err, status);
    else
    {
        fwrite(buf, 1, size, stdout);
        status = cli_finish_output();
    }
    free(buf);
    wc_error_clear(err);
    return status;
}
