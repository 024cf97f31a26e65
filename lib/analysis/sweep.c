/* sweep.c -- G_goal at several friction coefficients, and the critical
   one (sweep.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "analysis/sweep.h"

void
wc_sweep_init(wc_sweep_t A)
{
    A->n = 0;
    A->mu = NULL;
    A->plans = NULL;
    A->critical = 0;
    fmpq_init(A->width);
    fmpq_init(A->max);
    wc_critical_init(A->C);
    wc_plan_init(A->H);
    wc_plan_wrench_init(A->W);
}

void
wc_sweep_clear(wc_sweep_t A)
{
    slong i;

    wc_plan_wrench_clear(A->W);
    wc_plan_clear(A->H);
    wc_critical_clear(A->C);
    for (i = 0; A->plans != NULL && i < A->n; i++)
        wc_plan_clear(A->plans + i);
    flint_free(A->plans);
    for (i = 0; i < A->n; i++)
        fmpq_clear(A->mu + i);
    flint_free(A->mu);
    fmpq_clear(A->width);
    fmpq_clear(A->max);
}

/* The bracket, and the witness at lo checked again, one cone at a
   time: the plan at lo holds the witness in G_goal, the plan at hi names
   the strings whose cones cover R^3.  */
static int
bracket(wc_sweep_struct * A, const wc_problem_t P, const fmpq_t width,
        const fmpq_t max, wc_error_t err)
{
    wc_critical_struct * C = A->C;
    int status = wc_plan_critical(C, P, width, max, err);

    if (status == WC_OK && C->found)
        status = wc_plan_with_friction(A->H, P, C->hi, err);
    if (status == WC_OK && !C->empty_at_zero)
    {
        wc_problem_t Q;
        slong i;

        wc_problem_init(Q);
        status = wc_problem_set(Q, P);
        for (i = 0; i < Q->n && status == WC_OK; i++)
        {
            fmpq_set(Q->fixels[i].mu_s, C->lo);
            fmpq_set(Q->fixels[i].mu_k, C->lo);
        }
        if (status == WC_OK)
            status = wc_plan_wrench(A->W, Q, C->lo_witness, 0, err);
        if (status == WC_OK && !A->W->in_goal)
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: the witness at lo is not "
                                  "in G_goal");
        wc_problem_clear(Q);
    }
    return status;
}

int
wc_sweep(wc_sweep_t A, const wc_problem_t P, const fmpq * mu, slong n,
         int critical, const fmpq_t width, const fmpq_t max, wc_error_t err)
{
    int status = wc_problem_check(P, err);
    slong i;

    A->critical = critical;
    fmpq_set(A->width, width);
    fmpq_set(A->max, max);
    if (status == WC_OK && P->n > WC_PLAN_MAX_FIXELS)
    {
        wc_plan_t R;

        wc_plan_init(R);
        status = wc_plan(R, P, 0, err);     /* says why */
        wc_plan_clear(R);
    }
    if (status != WC_OK)
        return status;
    A->mu = flint_malloc(sizeof(fmpq) * (n + 1));
    A->plans = flint_malloc(sizeof(wc_plan_struct) * (n + 1));
    for (i = 0; i < n; i++)
    {
        fmpq_init(A->mu + i);
        fmpq_set(A->mu + i, mu + i);
        wc_plan_init(A->plans + i);
    }
    A->n = n;
    for (i = 0; i < n && status == WC_OK; i++)
        status = wc_plan_with_friction(A->plans + i, P, A->mu + i, err);
    if (status == WC_OK && critical)
        status = bracket(A, P, width, max, err);
    return status;
}
