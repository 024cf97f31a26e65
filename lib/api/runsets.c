/* runsets.c -- the rows of _wc_runners for the commands about sets of
   wrenches: stability, plan, sweep (run.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "api/runners.h"
#include "io/answerprint.h"

/* stability */

static void
stability_init(_wc_answer * A)
{
    wc_stability_init(A->u.stability.S);
    _wc_bias_init(&A->u.stability.bias);
}

static void
stability_clear(_wc_answer * A)
{
    _wc_bias_clear(&A->u.stability.bias);
    wc_stability_clear(A->u.stability.S);
}

/* Both robustness figures of the bias, before anything is printed.  */
static int
robustness(_wc_answer * A, wc_error_t err)
{
    _wc_bias * B = &A->u.stability.bias;
    const wc_stability_struct * S = A->u.stability.S;
    const wc_set_struct * sets[2] = { S->strong, S->strong_paper };
    int i, status = WC_OK;

    for (i = 0; i < 2 && status == WC_OK; i++)
    {
        status = wc_robustness(B->rho[i], B->closed + i, B->infinite + i,
                               sets[i], S->cells, B->b, B->L, err);
        B->in_set[i] = wc_set_contains(sets[i], B->b);
    }
    return status;
}

static int
stability_run(_wc_answer * A, wc_error_t err)
{
    const _wc_request * R = A->R;
    _wc_bias * B = &A->u.stability.bias;
    int status = _wc_load_problem(A->P, &R->problem, err);

    if (status == WC_OK && R->bias.given)
        status = _wc_parse_numbers(B->b, R->bias.v, 3, "<bias>", err);
    if (status == WC_OK && R->length != NULL)
    {
        status = _wc_parse_numbers(B->L, &R->length, 1, "<length>", err);
        if (status == WC_OK && fmpq_sgn(B->L) <= 0)
            status = wc_error_set(err, WC_EINPUT, "<length>", 1, 1,
                                  "the length must be positive");
    }
    if (status == WC_OK)
        status = wc_stability(A->u.stability.S, A->P, err);
    if (status == WC_OK && R->bias.given)
        status = robustness(A, err);
    return status;
}

static int
stability_fprint_as(FILE * out, const _wc_answer * A, int fmt)
{
    wc_print_opts o = _wc_answer_opts(A, fmt);

    return _wc_stability_answer_fprint(out, A->u.stability.S, A->P,
                                       A->R->bias.given
                                       ? &A->u.stability.bias : NULL, &o);
}

static int
stability_json(FILE * out, const _wc_answer * A)
{
    return stability_fprint_as(out, A, WC_FORMAT_JSON);
}

static int
stability_print(FILE * out, const _wc_answer * A)
{
    return stability_fprint_as(out, A, WC_FORMAT_TEXT);
}

static int
stability_certificate(FILE * out, const _wc_answer * A, wc_error_t err)
{
    return wc_stability_certificate_fprint(out, A->P, A->u.stability.S, err);
}

const _wc_runner _wc_run_stability = {
    stability_init, stability_clear, stability_run, stability_json,
    stability_print, stability_certificate
};

/* plan */

static void
plan_init(_wc_answer * A)
{
    int i;

    for (i = 0; i < 3; i++)
        fmpq_init(A->u.plan.g + i);
    wc_plan_init(A->u.plan.plan);
    wc_plan_wrench_init(A->u.plan.pw);
}

static void
plan_clear(_wc_answer * A)
{
    int i;

    wc_plan_wrench_clear(A->u.plan.pw);
    wc_plan_clear(A->u.plan.plan);
    for (i = 0; i < 3; i++)
        fmpq_clear(A->u.plan.g + i);
}

static int
plan_run(_wc_answer * A, wc_error_t err)
{
    const _wc_request * R = A->R;
    int status = _wc_load_problem(A->P, &R->problem, err);

    if (status == WC_OK && R->certificates)
        status = wc_problem_check_fixels(A->P, WC_PLAN_CERT_MAX_FIXELS, 0,
                                         "a plan certificate", err);
    if (status == WC_OK && R->wrench.given)
        status = _wc_parse_numbers(A->u.plan.g, R->wrench.v, 3, "<wrench>",
                                   err);
    if (status == WC_OK)
        status = R->wrench.given
            ? wc_plan_wrench(A->u.plan.pw, A->P, A->u.plan.g, R->complete,
                             err)
            : wc_plan(A->u.plan.plan, A->P, R->complete, err);
    return status;
}

static int
plan_fprint_as(FILE * out, const _wc_answer * A, int fmt)
{
    wc_print_opts o = _wc_answer_opts(A, fmt);

    return A->R->wrench.given ? wc_plan_wrench_fprint(out, A->u.plan.pw, &o)
        : wc_plan_fprint(out, A->u.plan.plan, A->P, &o);
}

static int
plan_json(FILE * out, const _wc_answer * A)
{
    return plan_fprint_as(out, A, WC_FORMAT_JSON);
}

static int
plan_print(FILE * out, const _wc_answer * A)
{
    return plan_fprint_as(out, A, WC_FORMAT_TEXT);
}

static int
plan_certificate(FILE * out, const _wc_answer * A, wc_error_t err)
{
    return wc_plan_certificate_fprint(out, A->P, A->u.plan.plan, err);
}

const _wc_runner _wc_run_plan = {
    plan_init, plan_clear, plan_run, plan_json, plan_print, plan_certificate
};

/* sweep */

static void
sweep_init(_wc_answer * A)
{
    wc_sweep_init(A->u.sweep);
}

static void
sweep_clear(_wc_answer * A)
{
    wc_sweep_clear(A->u.sweep);
}

/* The one positive number s into x, located in what.  */
static int
one_positive(fmpq_t x, const char * s, const char * what, const char * noun,
             wc_error_t err)
{
    fmpq * v = NULL;
    slong n = 0;
    int status = wc_parse_number_list(&v, &n, s, _WC_SWEEP_MAX_FRICTIONS, NULL,
                                      noun, what, err);

    if (status == WC_OK && (n != 1 || fmpq_sgn(v) <= 0))
        status = wc_error_set(err, WC_EINPUT, what, 1, 1,
                              "expected one positive number");
    if (status == WC_OK)
        fmpq_set(x, v);
    wc_number_list_clear(v, n);
    return status;
}

static int
sweep_run(_wc_answer * A, wc_error_t err)
{
    const _wc_request * R = A->R;
    fmpq * mu = NULL;
    slong n = 0;
    fmpq_t width, max;
    int status = _wc_load_problem(A->P, &R->problem, err);

    fmpq_init(width);
    fmpq_init(max);
    if (status == WC_OK && R->certificates)
        status = wc_problem_check_fixels(A->P, WC_PLAN_CERT_MAX_FIXELS, 0,
                                         "a plan certificate", err);
    if (status == WC_OK && R->friction != NULL)
        status = wc_parse_number_list(&mu, &n, R->friction,
                                      _WC_SWEEP_MAX_FRICTIONS,
                                      "each costs a plan",
                                      "a friction coefficient", "<friction>",
                                      err);
    if (status == WC_OK
        && (status = one_positive(width, R->width, "<width>", "the width",
                                  err)) == WC_OK
        && !wc_critical_width_ok(width))
        status = wc_error_set(err, WC_EINPUT, "<width>", 1, 1,
                              "the width must be at least 2^-%d (about "
                              "1.3e-29): each halving costs a plan",
                              WC_CRITICAL_MIN_WIDTH_EXP);
    if (status == WC_OK
        && (status = one_positive(max, R->max_friction, "<max-friction>",
                                  "the largest friction", err)) == WC_OK
        && !wc_critical_max_ok(max))
        status = wc_error_set(err, WC_EINPUT, "<max-friction>", 1, 1,
                              "the largest friction must be at most 2^%d "
                              "(4294967296): each doubling costs a plan",
                              WC_CRITICAL_MAX_FRICTION_EXP);
    if (status == WC_OK)
        status = wc_sweep(A->u.sweep, A->P, mu, n, R->critical, width, max,
                          err);
    wc_number_list_clear(mu, n);
    fmpq_clear(max);
    fmpq_clear(width);
    return status;
}

static int
sweep_fprint_as(FILE * out, const _wc_answer * A, int fmt)
{
    wc_print_opts o = _wc_answer_opts(A, fmt);

    return wc_sweep_fprint(out, A->u.sweep, A->P, &o);
}

static int
sweep_json(FILE * out, const _wc_answer * A)
{
    return sweep_fprint_as(out, A, WC_FORMAT_JSON);
}

static int
sweep_print(FILE * out, const _wc_answer * A)
{
    return sweep_fprint_as(out, A, WC_FORMAT_TEXT);
}

static int
sweep_certificate(FILE * out, const _wc_answer * A, wc_error_t err)
{
    return wc_critical_certificate_fprint(out, A->P, A->u.sweep->C, err);
}

const _wc_runner _wc_run_sweep = {
    sweep_init, sweep_clear, sweep_run, sweep_json, sweep_print,
    sweep_certificate
};
