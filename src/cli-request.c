/* cli-request.c -- a command line answered through the library's request
   layer (api/run.h): the command line, `batch` and wc_request_json print
   the same bytes because they run the same code.

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

typedef struct
{
    const _wc_answer * A;
    wc_error_struct * err;
}
cert_job;

static int
put_certificate(FILE * f, const void * p)
{
    const cert_job * j = p;

    return _wc_answer_fprint_certificate(f, j->A, j->err);
}

static int
put_answer(FILE * f, const void * A)
{
    return _wc_answer_fprint(f, A);
}

int
cli_answer(_wc_request * R)
{
    _wc_answer A;
    wc_error_t err;
    int status, reported = 0;

    R->certificates = R->certificate != NULL;
    _wc_answer_init(&A, R);
    wc_error_init(err);
    status = _wc_run(&A, err);
    if (status == WC_OK && R->certificate != NULL)
    {
        cert_job j = { &A, err };

        status = cli_write_file(R->certificate, "certificate",
                                put_certificate, &j, err);
    }
    if (status == WC_OK && R->output != NULL && strcmp(R->output, "-") != 0)
        status = cli_write_file(R->output, R->command == _WC_DRAW ? "figure"
                                : _wc_command_name(R->command), put_answer,
                                &A, err);
    else if (status == WC_OK)
    {
        _wc_answer_fprint(stdout, &A);
        reported = (status = cli_finish_output()) != WC_OK;
    }
    if (status != WC_OK && !reported)
        cli_report(err, status);
    if (status == WC_OK)
        status = _wc_answer_status(&A);
    wc_error_clear(err);
    _wc_answer_clear(&A);
    return status;
}

int
cli_command_run(const cli_command * self, int argc, char ** argv)
{
    _wc_request R;
    int status = cli_parse(&R, self, argc, argv);

    return cli_done(&R, status >= 0 ? status : cli_answer(&R));
}

int
cli_command_run_output(const cli_command * self, int argc, char ** argv)
{
    return cli_run_with_output(cli_command_run, self, argc, argv);
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
