/* run.c -- one computing command from its parsed arguments to its answer
   and the answer's JSON (run.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "api/run.h"
#include "api/schema.h"
#include "api/runners.h"
#include "core/readall.h"
#include "core/version.h"
#include "io/print.h"
#include "io/fconeprint.h"
#include "io/compareprint.h"
#include "model/mode.h"

const char *
_wc_command_name(_wc_command c)
{
    return (unsigned) c < _WC_NCOMMANDS ? _wc_schema[c].name : "?";
}

int
_wc_command_find(const char * name)
{
    const _wc_command_schema * S = _wc_schema_find(name);

    return S != NULL ? (int) (S - _wc_schema) : -1;
}

/* ------------------------------------------------------------------ */
/* Inputs                                                              */


int
_wc_input_read(char ** text, size_t * len, const _wc_input * in,
               wc_error_t err)
{
    return _wc_input_read_max(text, len, in, _WC_MAX_INPUT_BYTES, err);
}

int
_wc_input_read_max(char ** text, size_t * len, const _wc_input * in,
                   size_t max, wc_error_t err)
{
    *text = NULL;
    *len = 0;
    if (in->stream != NULL)
        return _wc_read_all(text, len, in->stream, in->name,
                           max, err);
    if (in->text != NULL)
    {
        if (in->len > max)
            return wc_error_set(err, WC_EINPUT, in->name, 0, 0,
                                "file too large (over %lu bytes)",
                                (unsigned long) max);
        if ((*text = malloc(in->len + 1)) == NULL)
            return wc_error_set(err, WC_EINTERNAL, in->name, 0, 0,
                                "out of memory");
        memcpy(*text, in->text, in->len);
        *len = in->len;
        return WC_OK;
    }
    return _wc_read_file(text, len, in->path, in->name, max, in->flags,
                         in->avoid, err);
}

int
_wc_load_problem(wc_problem_t P, const _wc_input * in, wc_error_t err)
{
    char * text = NULL;
    size_t len = 0;
    int status = _wc_input_read(&text, &len, in, err);

    if (status == WC_OK)
        status = wc_problem_parse(P, text, len, in->name, err);
    free(text);
    return status;
}

int
_wc_parse_numbers(fmpq * v, const char * const * args, slong k,
                  const char * what, wc_error_t err)
{
    slong i, col = 1;

    for (i = 0; i < k; i++)
    {
        if (wc_parse_number_bounded(v + i, args[i], strlen(args[i]), err)
            != WC_OK)
        {
            char * why = wc_error_format(err);
            int st = wc_error_set(err, WC_EINPUT, what, 1, col, "%s",
                                  why != NULL ? why : "bad number");

            free(why);
            return st;
        }
        col += strlen(args[i]) + 1;
    }
    return WC_OK;
}

/* ------------------------------------------------------------------ */
/* Answers: the command's row of _wc_runners                           */

const _wc_runner * const _wc_runners[_WC_NCOMMANDS] = {
    &_wc_run_cone, &_wc_run_modes, &_wc_run_feasible, &_wc_run_classify,
    &_wc_run_stability, &_wc_run_plan, &_wc_run_sweep, &_wc_run_verify,
    &_wc_run_compare, &_wc_run_random, &_wc_run_draw, &_wc_run_report, NULL
};

void
_wc_answer_init(_wc_answer * A, const _wc_request * R)
{
    memset(A, 0, sizeof *A);
    A->command = R->command;
    A->R = R;
    wc_problem_init(A->P);
    if (_wc_runners[R->command] != NULL)
        _wc_runners[R->command]->init(A);
}

void
_wc_answer_clear(_wc_answer * A)
{
    if (_wc_runners[A->command] != NULL)
        _wc_runners[A->command]->clear(A);
    wc_problem_clear(A->P);
}

int
_wc_run(_wc_answer * A, wc_error_t err)
{
    if (_wc_runners[A->command] == NULL)
        return wc_error_set(err, WC_EUSAGE, NULL, 0, 0, "%s is not a request",
                            _wc_command_name(A->command));
    return _wc_runners[A->command]->run(A, err);
}

int
_wc_answer_status(const _wc_answer * A)
{
    if (A->command == _WC_COMPARE)
        return A->u.compare.cmp->differs ? WC_EDISAGREE : WC_OK;
    if (A->command == _WC_VERIFY)
        return A->u.text.holds ? WC_OK : WC_EDISAGREE;
    return WC_OK;
}

wc_print_opts
_wc_answer_opts(const _wc_answer * A, int f)
{
    wc_print_opts o = { WC_FORMAT_TEXT, 0, 0, NULL };

    o.format = (wc_format) f;
    o.approx = A->R->decimals >= 0;
    o.decimals = A->R->decimals;
    return o;
}

int
_wc_answer_fprint_json(FILE * out, const _wc_answer * A)
{
    int status = _wc_runners[A->command]->json(out, A);

    return status == WC_OK && ferror(out) ? WC_EINTERNAL : status;
}

int
_wc_answer_fprint(FILE * out, const _wc_answer * A)
{
    int status = A->R->format == 1 ? _wc_runners[A->command]->json(out, A)
        : _wc_runners[A->command]->print(out, A);

    return status == WC_OK && ferror(out) ? WC_EINTERNAL : status;
}

int
_wc_answer_fprint_certificate(FILE * out, const _wc_answer * A,
                              wc_error_t err)
{
    if (_wc_runners[A->command]->certificate == NULL)
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "%s writes no certificate",
                            _wc_command_name(A->command));
    return _wc_runners[A->command]->certificate(out, A, err);
}

int
_wc_error_fprint_json(FILE * out, const wc_error_t err, int status)
{
    fputs(WC_JSON_OPEN "\"error\": {\"message\": ", out);
    wc_fprint_json_string(out, err->message != NULL ? err->message
                          : "out of memory");
    fputs(", \"file\": ", out);
    if (err->file != NULL)
        wc_fprint_json_string(out, err->file);
    else
        fputs("null", out);
    if (err->line > 0)
        fprintf(out, ", \"line\": %ld", err->line);
    else
        fputs(", \"line\": null", out);
    if (err->col > 0)
        fprintf(out, ", \"column\": %ld", err->col);
    else
        fputs(", \"column\": null", out);
    fprintf(out, ", \"status\": %d}}\n", status);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

/* ------------------------------------------------------------------ */
/* cone --all-modes                                                    */

int
_wc_cone_all_modes(FILE * out, const _wc_request * R, wc_error_t err)
{
    wc_problem_t P;
    wc_modes_t M;
    _wc_request one = *R;
    _wc_answer A;
    slong i;
    int status;

    wc_problem_init(P);
    wc_modes_init(M);
    status = _wc_load_problem(P, &R->problem, err);
    if (status == WC_OK)
        status = wc_modes_enumerate(M, P, err);
    if (status == WC_OK && M->count > _WC_ALL_MODES_MAX)
        status = wc_error_set(err, WC_EINPUT, R->problem.name, 0, 0,
                              "%ld modes, over the %d that --all-modes "
                              "computes: list them with 'modes' and give "
                              "them to 'batch'", (long) M->count,
                              _WC_ALL_MODES_MAX);
    for (i = 0; status == WC_OK && i < M->count; i++)
    {
        one.mode = M->modes[i];
        _wc_answer_init(&A, &one);
        status = _wc_cone_compute(&A, P, err);
        if (status == WC_OK)
            status = _wc_answer_fprint_json(out, &A);
        _wc_answer_clear(&A);
    }
    wc_modes_clear(M);
    wc_problem_clear(P);
    return status;
}
