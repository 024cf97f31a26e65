/* run.c -- one computing command from its parsed arguments to its answer
   and the answer's JSON (run.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "api/run.h"
#include "api/schema.h"
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

void
_wc_answer_init(_wc_answer * A)
{
    int i;

    memset(A, 0, sizeof *A);
    wc_problem_init(A->P);
    wc_cone_init(A->W, 3);
    wc_trace_init(A->T);
    wc_fcone_init(A->F, 3);
    wc_modes_init(A->M);
    wc_certificate_init(A->C);
    wc_classify_init(A->K);
    wc_stability_init(A->S);
    wc_plan_init(A->plan);
    wc_plan_wrench_init(A->pw);
    wc_comparison_init(A->cmp);
    for (i = 0; i < 3; i++)
    {
        fmpq_init(A->g + i);
        fmpq_init(A->b + i);
    }
    fmpq_init(A->L);
    fmpq_one(A->L);
    for (i = 0; i < 2; i++)
        fmpq_init(A->rho[i]);
}

void
_wc_answer_clear(_wc_answer * A)
{
    int i;

    for (i = 0; i < 2; i++)
        fmpq_clear(A->rho[i]);
    fmpq_clear(A->L);
    for (i = 0; i < 3; i++)
    {
        fmpq_clear(A->b + i);
        fmpq_clear(A->g + i);
    }
    wc_comparison_clear(A->cmp);
    wc_plan_wrench_clear(A->pw);
    wc_plan_clear(A->plan);
    wc_stability_clear(A->S);
    wc_classify_clear(A->K);
    wc_certificate_clear(A->C);
    wc_modes_clear(A->M);
    wc_fcone_clear(A->F);
    wc_trace_clear(A->T);
    wc_cone_clear(A->W);
    wc_problem_clear(A->P);
}

/* ------------------------------------------------------------------ */
/* Inputs                                                              */


int
_wc_input_read(char ** text, size_t * len, const _wc_input * in,
               wc_error_t err)
{
    FILE * f;
    int status;

    *text = NULL;
    *len = 0;
    if (in->stream != NULL)
        return _wc_read_all(text, len, in->stream, in->name,
                           _WC_MAX_INPUT_BYTES, err);
    if (in->text != NULL)
    {
        if (in->len > _WC_MAX_INPUT_BYTES)
            return wc_error_set(err, WC_EINPUT, in->name, 0, 0,
                                "file too large (over %lu bytes)",
                                (unsigned long) _WC_MAX_INPUT_BYTES);
        if ((*text = malloc(in->len + 1)) == NULL)
            return wc_error_set(err, WC_EINTERNAL, in->name, 0, 0,
                                "out of memory");
        memcpy(*text, in->text, in->len);
        *len = in->len;
        return WC_OK;
    }
    if ((f = fopen(in->path, "rb")) == NULL)
        return wc_error_set(err, WC_EINPUT, in->path, 0, 0, "cannot open: %s",
                            strerror(errno));
    status = _wc_read_all(text, len, f, in->name, _WC_MAX_INPUT_BYTES, err);
    fclose(f);
    return status;
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
/* The commands                                                        */

/* The cone of R->mode for P (A->P, or the problem --all-modes shares).  */
static int
run_cone(_wc_answer * A, const wc_problem_t P, const _wc_request * R,
         wc_error_t err)
{
    int status;

    if (R->arith_double)
        return wc_wrench_cone_paper_double(A->F, P, R->mode, WC_FCONE_EPS,
                                           err);
    status = wc_mode_check(P, R->mode, WC_TABLE_CONE, err);
    if (status != WC_OK)
        return status;
    return wc_wrench_cone(A->W, R->trace ? A->T : NULL, P, R->mode,
                          R->method, err);
}

/* Both robustness figures of the bias, before anything is printed.  */
static int
robustness(_wc_answer * A, wc_error_t err)
{
    const wc_set_struct * sets[2] = { A->S->strong, A->S->strong_paper };
    int i, status = WC_OK;

    for (i = 0; i < 2 && status == WC_OK; i++)
    {
        status = wc_robustness(A->rho[i], A->closed + i, A->infinite + i,
                               sets[i], A->S->cells, A->b, A->L, err);
        A->in_set[i] = wc_set_contains(sets[i], A->b);
    }
    return status;
}

static int
run_stability(_wc_answer * A, const _wc_request * R, wc_error_t err)
{
    int status = WC_OK;

    if (R->bias.given)
        status = _wc_parse_numbers(A->b, R->bias.v, 3, "<bias>", err);
    if (status == WC_OK && R->length != NULL)
    {
        status = _wc_parse_numbers(A->L, &R->length, 1, "<length>", err);
        if (status == WC_OK && fmpq_sgn(A->L) <= 0)
            status = wc_error_set(err, WC_EINPUT, "<length>", 1, 1,
                                  "the length must be positive");
    }
    if (status == WC_OK)
        status = wc_stability(A->S, A->P, err);
    if (status == WC_OK && R->bias.given)
        status = robustness(A, err);
    return status;
}

static int
run_plan(_wc_answer * A, const _wc_request * R, wc_error_t err)
{
    int status = WC_OK;

    if (R->certificates)
        status = wc_problem_check_fixels(A->P, WC_PLAN_CERT_MAX_FIXELS, 0,
                                         "a plan certificate", err);
    if (status == WC_OK && R->wrench.given)
        status = _wc_parse_numbers(A->g, R->wrench.v, 3, "<wrench>", err);
    if (status == WC_OK)
        status = R->wrench.given
            ? wc_plan_wrench(A->pw, A->P, A->g, R->complete, err)
            : wc_plan(A->plan, A->P, R->complete, err);
    return status;
}

static int
run_compare(_wc_answer * A, const _wc_request * R, wc_error_t err)
{
    wc_foreign_t F;
    char * text = NULL;
    size_t len = 0;
    int status;

    wc_foreign_init(F);
    status = wc_mode_check(A->P, R->mode, WC_TABLE_CONE, err);
    if (status == WC_OK)
        status = _wc_input_read(&text, &len, &R->foreign, err);
    if (status == WC_OK)
        status = wc_foreign_parse(F, text, len, R->foreign.name, err);
    if (status == WC_OK)
        status = wc_wrench_cone(A->W, NULL, A->P, R->mode, WC_METHOD_DIRECT,
                                err);
    if (status == WC_OK)
        status = wc_compare(A->cmp, A->W, R->mode, F, R->tol, err);
    free(text);
    wc_foreign_clear(F);
    return status;
}

int
_wc_run(_wc_answer * A, const _wc_request * R, wc_error_t err)
{
    int status;

    A->command = R->command;
    A->R = R;
    status = _wc_load_problem(A->P, &R->problem, err);
    if (status != WC_OK)
        return status;
    switch (R->command)
    {
    case _WC_CONE:
        return run_cone(A, A->P, R, err);
    case _WC_MODES:
        return wc_modes_enumerate(A->M, A->P, err);
    case _WC_FEASIBLE:
        return wc_feasible(A->C, A->P, R->mode, err);
    case _WC_CLASSIFY:
        status = _wc_parse_numbers(A->g, R->wrench.v, 3, "<wrench>", err);
        if (status == WC_OK)
            status = wc_classify(A->K, A->P, A->g, R->certificates,
                                 R->max_modes, err);
        return status;
    case _WC_STABILITY:
        return run_stability(A, R, err);
    case _WC_PLAN:
        return run_plan(A, R, err);
    case _WC_COMPARE:
        return run_compare(A, R, err);
    default:
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "unknown command %d", (int) R->command);
    }
}

int
_wc_answer_status(const _wc_answer * A)
{
    return A->command == _WC_COMPARE && A->cmp->differs != 0
        ? WC_EDISAGREE : WC_OK;
}

/* ------------------------------------------------------------------ */
/* JSON                                                                */

static void
fprint_cone_json(FILE * out, const _wc_answer * A)
{
    const _wc_request * R = A->R;

    fputs(WC_JSON_OPEN "\"mode\": ", out);
    wc_fprint_json_string(out, R->mode);
    fputs(", \"cone\": ", out);
    if (R->arith_double)
        wc_fcone_fprint(out, A->F, WC_FCONE_JSON);
    else
    {
        wc_cone_fprint_json(out, A->W);
        if (R->trace)
        {
            fprintf(out, ", \"method\": \"%s\", \"trace\": ",
                    R->method == WC_METHOD_PAPER ? "paper" : "direct");
            wc_trace_fprint_json(out, A->T);
        }
    }
    fputs("}\n", out);
}

static void
fprint_bias_json(FILE * out, const _wc_answer * A)
{
    int i;

    fputs(", \"bias\": {\"wrench\": [", out);
    for (i = 0; i < 3; i++)
    {
        fputs(i ? ", \"" : "\"", out);
        wc_fprint_fmpq(out, A->b + i);
        putc('"', out);
    }
    fputs("], \"length\": \"", out);
    wc_fprint_fmpq(out, A->L);
    putc('"', out);
    for (i = 0; i < 2; i++)
    {
        fprintf(out, ", \"%s\": {\"in_set\": %s, ", i == 0 ? "strong"
                : "strong_paper", A->in_set[i] ? "true" : "false");
        if (A->infinite[i])
            fputs("\"rho\": null, \"unbounded\": true}", out);
        else
        {
            fputs("\"rho\": \"", out);
            wc_fprint_fmpq(out, A->rho[i]);
            fprintf(out, "\", \"closed\": %s}",
                    A->closed[i] ? "true" : "false");
        }
    }
    putc('}', out);
}

int
_wc_answer_fprint_json(FILE * out, const _wc_answer * A)
{
    const _wc_request * R = A->R;

    switch (A->command)
    {
    case _WC_CONE:
        fprint_cone_json(out, A);
        break;
    case _WC_MODES:
        wc_modes_fprint(out, A->M, 1, R->witness);
        break;
    case _WC_FEASIBLE:
        wc_certificate_fprint(out, A->C, A->P, 1);
        break;
    case _WC_CLASSIFY:
        wc_classify_fprint(out, A->K, 1);
        break;
    case _WC_STABILITY:
        wc_stability_fprint(out, A->S, 2);
        if (R->bias.given)
            fprint_bias_json(out, A);
        fputs("}\n", out);
        break;
    case _WC_PLAN:
        if (R->wrench.given)
            wc_plan_wrench_fprint(out, A->pw, 1);
        else
            wc_plan_fprint(out, A->plan, A->P, 1);
        break;
    case _WC_COMPARE:
        wc_comparison_fprint(out, A->cmp, A->W, R->problem.name, R->mode,
                             R->foreign.name, 1);
        break;
    default:
        break;
    }
    return ferror(out) ? WC_EINTERNAL : WC_OK;
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
        _wc_answer_init(&A);
        A.command = _WC_CONE;
        A.R = &one;
        one.mode = M->modes[i];
        status = run_cone(&A, P, &one, err);
        if (status == WC_OK)
            status = _wc_answer_fprint_json(out, &A);
        _wc_answer_clear(&A);
    }
    wc_modes_clear(M);
    wc_problem_clear(P);
    return status;
}
