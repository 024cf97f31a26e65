/* sweep.h -- the insertion plan against friction: G_goal at each of a
   list of friction coefficients, and the critical one, bracketed.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_ANALYSIS_SWEEP_H
#define WC_ANALYSIS_SWEEP_H

#include "core/problem.h"
#include "analysis/plan.h"

/* What `wrenchcone sweep` computes.  */
typedef struct
{
    slong n;                    /* the plans at mu[0..n) */
    fmpq * mu;
    wc_plan_struct * plans;
    int critical;               /* whether the bracket was asked for */
    fmpq_t width, max;          /* its largest width, the largest mu */
    wc_critical_t C;            /* the bracket [lo, hi] */
    wc_plan_t H;                /* the plan at hi: the strings that cover */
    wc_plan_wrench_t W;         /* the witness at lo, checked in G_goal */
}
wc_sweep_struct;

typedef wc_sweep_struct wc_sweep_t[1];

void wc_sweep_init(wc_sweep_t A);
void wc_sweep_clear(wc_sweep_t A);

/* The plan of P with mu_s = mu_k = mu[i] at every fixel, for each i < n
   (mu is copied), and with critical the bracket of the friction at which
   G_goal becomes empty, no wider than width, up to max (A's width and max
   are set from them).  Returns WC_OK, WC_EINPUT (P too large for a plan)
   or WC_EINTERNAL, err set.  */
int wc_sweep(wc_sweep_t A, const wc_problem_t P, const fmpq * mu, slong n,
             int critical, const fmpq_t width, const fmpq_t max,
             wc_error_t err);

#endif
