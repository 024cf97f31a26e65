/* runexact.c -- the rows of _wc_runners for the commands about one mode
   or one wrench: cone, modes, feasible, classify, compare (run.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>

#include "api/runners.h"
#include "io/answerprint.h"
#include "io/compareprint.h"
#include "model/mode.h"

/* cone */

static void
cone_init(_wc_answer * A)
{
    wc_cone_init(A->u.cone.W, 3);
    wc_trace_init(A->u.cone.T);
    wc_fcone_init(A->u.cone.F, 3);
}

static void
cone_clear(_wc_answer * A)
{
    wc_fcone_clear(A->u.cone.F);
    wc_trace_clear(A->u.cone.T);
    wc_cone_clear(A->u.cone.W);
}

int
_wc_cone_compute(_wc_answer * A, const wc_problem_t P, wc_error_t err)
{
    const _wc_request * R = A->R;
    int status;

    if (R->arith_double)
        return wc_wrench_cone_paper_double(A->u.cone.F, P, R->mode,
                                           WC_FCONE_EPS, err);
    status = wc_mode_check(P, R->mode, WC_TABLE_CONE, err);
    if (status != WC_OK)
        return status;
    return wc_wrench_cone(A->u.cone.W, R->trace ? A->u.cone.T : NULL, P,
                          R->mode, (wc_method) R->method, err);
}

static int
cone_run(_wc_answer * A, wc_error_t err)
{
    int status = _wc_load_problem(A->P, &A->R->problem, err);

    return status == WC_OK ? _wc_cone_compute(A, A->P, err) : status;
}

static int
cone_fprint_as(FILE * out, const _wc_answer * A, int fmt)
{
    const _wc_request * R = A->R;
    wc_print_opts o = _wc_answer_opts(A, fmt);

    if (R->arith_double)
        return _wc_mode_fcone_fprint(out, R->mode, A->u.cone.F, &o);
    return _wc_mode_cone_fprint(out, R->mode, A->u.cone.W,
                                R->trace ? A->u.cone.T : NULL,
                                R->method == WC_METHOD_PAPER, &o);
}

static int
cone_json(FILE * out, const _wc_answer * A)
{
    return cone_fprint_as(out, A, WC_FORMAT_JSON);
}

static int
cone_print(FILE * out, const _wc_answer * A)
{
    return cone_fprint_as(out, A, A->R->format < 0 ? WC_FORMAT_TEXT
                          : A->R->format);
}

const _wc_runner _wc_run_cone = {
    cone_init, cone_clear, cone_run, cone_json, cone_print, NULL
};

/* modes */

static void
modes_init(_wc_answer * A)
{
    wc_modes_init(A->u.modes);
}

static void
modes_clear(_wc_answer * A)
{
    wc_modes_clear(A->u.modes);
}

static int
modes_run(_wc_answer * A, wc_error_t err)
{
    int status = _wc_load_problem(A->P, &A->R->problem, err);

    return status == WC_OK ? wc_modes_enumerate(A->u.modes, A->P, err)
        : status;
}

static int
modes_fprint_as(FILE * out, const _wc_answer * A, int fmt)
{
    wc_print_opts o = _wc_answer_opts(A, fmt);

    return wc_modes_fprint(out, A->u.modes, A->R->witness, &o);
}

static int
modes_json(FILE * out, const _wc_answer * A)
{
    return modes_fprint_as(out, A, WC_FORMAT_JSON);
}

static int
modes_print(FILE * out, const _wc_answer * A)
{
    return modes_fprint_as(out, A, WC_FORMAT_TEXT);
}

const _wc_runner _wc_run_modes = {
    modes_init, modes_clear, modes_run, modes_json, modes_print, NULL
};

/* feasible: the JSON answer is the certificate itself.  */

static void
feasible_init(_wc_answer * A)
{
    wc_certificate_init(A->u.feasible);
}

static void
feasible_clear(_wc_answer * A)
{
    wc_certificate_clear(A->u.feasible);
}

static int
feasible_run(_wc_answer * A, wc_error_t err)
{
    int status = _wc_load_problem(A->P, &A->R->problem, err);

    return status == WC_OK ? wc_feasible(A->u.feasible, A->P, A->R->mode,
                                         err) : status;
}

static int
feasible_fprint_as(FILE * out, const _wc_answer * A, int fmt)
{
    wc_print_opts o = _wc_answer_opts(A, fmt);

    return wc_certificate_fprint(out, A->u.feasible, A->P, &o);
}

static int
feasible_json(FILE * out, const _wc_answer * A)
{
    return feasible_fprint_as(out, A, WC_FORMAT_JSON);
}

static int
feasible_print(FILE * out, const _wc_answer * A)
{
    return feasible_fprint_as(out, A, WC_FORMAT_TEXT);
}

static int
feasible_certificate(FILE * out, const _wc_answer * A, wc_error_t err)
{
    (void) err;
    return feasible_fprint_as(out, A, WC_FORMAT_JSON);
}

const _wc_runner _wc_run_feasible = {
    feasible_init, feasible_clear, feasible_run, feasible_json,
    feasible_print, feasible_certificate
};

/* classify */

static void
classify_init(_wc_answer * A)
{
    int i;

    for (i = 0; i < 3; i++)
        fmpq_init(A->u.classify.g + i);
    wc_classify_init(A->u.classify.K);
}

static void
classify_clear(_wc_answer * A)
{
    int i;

    wc_classify_clear(A->u.classify.K);
    for (i = 0; i < 3; i++)
        fmpq_clear(A->u.classify.g + i);
}

static int
classify_run(_wc_answer * A, wc_error_t err)
{
    const _wc_request * R = A->R;
    int status = _wc_load_problem(A->P, &R->problem, err);

    if (status == WC_OK)
        status = _wc_parse_numbers(A->u.classify.g, R->wrench.v, 3,
                                   "<wrench>", err);
    if (status == WC_OK)
        status = wc_classify(A->u.classify.K, A->P, A->u.classify.g,
                             R->certificates, R->max_modes, err);
    return status;
}

static int
classify_fprint_as(FILE * out, const _wc_answer * A, int fmt)
{
    wc_print_opts o = _wc_answer_opts(A, fmt);

    return wc_classify_fprint(out, A->u.classify.K, &o);
}

static int
classify_json(FILE * out, const _wc_answer * A)
{
    return classify_fprint_as(out, A, WC_FORMAT_JSON);
}

static int
classify_print(FILE * out, const _wc_answer * A)
{
    return classify_fprint_as(out, A, WC_FORMAT_TEXT);
}

static int
classify_certificate(FILE * out, const _wc_answer * A, wc_error_t err)
{
    (void) err;
    return wc_classify_certificate_fprint(out, A->P, A->u.classify.K);
}

const _wc_runner _wc_run_classify = {
    classify_init, classify_clear, classify_run, classify_json,
    classify_print, classify_certificate
};

/* compare */

static void
compare_init(_wc_answer * A)
{
    wc_cone_init(A->u.compare.W, 3);
    wc_comparison_init(A->u.compare.cmp);
}

static void
compare_clear(_wc_answer * A)
{
    wc_comparison_clear(A->u.compare.cmp);
    wc_cone_clear(A->u.compare.W);
}

static int
compare_run(_wc_answer * A, wc_error_t err)
{
    const _wc_request * R = A->R;
    wc_foreign_t F;
    char * text = NULL;
    size_t len = 0;
    int status = _wc_load_problem(A->P, &R->problem, err);

    wc_foreign_init(F);
    if (status == WC_OK)
        status = wc_mode_check(A->P, R->mode, WC_TABLE_CONE, err);
    if (status == WC_OK)
        status = _wc_input_read(&text, &len, &R->foreign, err);
    if (status == WC_OK)
        status = wc_foreign_parse(F, text, len, R->foreign.name, err);
    if (status == WC_OK)
        status = wc_wrench_cone(A->u.compare.W, NULL, A->P, R->mode,
                                WC_METHOD_DIRECT, err);
    if (status == WC_OK)
        status = wc_compare(A->u.compare.cmp, A->u.compare.W, R->mode, F,
                            R->tol, err);
    free(text);
    wc_foreign_clear(F);
    return status;
}

static int
compare_fprint_as(FILE * out, const _wc_answer * A, int fmt)
{
    const _wc_request * R = A->R;
    wc_print_opts o = _wc_answer_opts(A, fmt);

    return wc_comparison_fprint(out, A->u.compare.cmp, A->u.compare.W,
                                R->problem.name, R->mode, R->foreign.name,
                                &o);
}

static int
compare_json(FILE * out, const _wc_answer * A)
{
    return compare_fprint_as(out, A, WC_FORMAT_JSON);
}

static int
compare_print(FILE * out, const _wc_answer * A)
{
    return compare_fprint_as(out, A, WC_FORMAT_TEXT);
}

const _wc_runner _wc_run_compare = {
    compare_init, compare_clear, compare_run, compare_json, compare_print,
    NULL
};
