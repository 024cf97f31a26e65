/* t-plansound.c -- the insertion plans against the rigid-body model, with
   kinetic friction above static friction.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A plan is sound when no wrench it accepts lets the part do what its rule
   forbids.  The oracle (ref_plan_model_breaks in ref-plan.c) asks, by one
   exact LP per Table 2 mode with the problem's own mu_s for rolling and
   mu_k for sliding contacts, whether at some contact state a solution of
   the model loses a contact or makes no progress (G_goal's rule), or
   gives a transition out of the goal or round a cycle (the complete
   plan's).  A sliding contact pushes on the edge of the kinetic friction
   cone, so with mu_k > mu_s a plan that read the m letter with mu_s alone
   would accept such wrenches: the Figure 6 disk below is one.  Every
   wrench tested here is a point of a cell of the plan's own arrangement,
   so every piece of both sets, boundaries included, gets its turn.  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/flint.h>
#include <flint/fmpq.h>

#include "wrenchcone.h"
#include "analysis/plan.h"
#include "ref-plan.h"
#include "testutil.h"

static void
fail_g(const wc_problem_t P, const fmpq * g, const char * msg)
{
    char * s = g != NULL ? wctest_vec_str(g, 3) : NULL;

    wctest_fail_problem(P, NULL, "%s%s%s", s != NULL ? s : "",
                        s != NULL ? ": " : "", msg);
}

/* The oracle must find nothing wrong with g under the rule.  */
static void
expect_sound(const wc_problem_t P, const fmpq * g, int goal_rule)
{
    char mode[8], state[8], msg[160];
    ulong S = 0;
    int r = ref_plan_model_breaks(P, g, goal_rule, &S, mode);

    if (r < 0)
        fail_g(P, g, "the rigid-body oracle failed");
    if (r == 1)
    {
        wc_plan_state_string(state, S, P->n);
        snprintf(msg, sizeof msg, "%s by the plan, yet at state %s the "
                 "solution %s breaks its rule", goal_rule ? "in G_goal"
                 : "accepted", state, mode);
        fail_g(P, g, msg);
    }
}

/* Paper Figure 6 with mu_s = 1/10 < mu_k = 1/2.  g = (-2, -10, -10) with
   fixel 1 touching: sticking needs |c_t| <= c_n / 10, sliding (l) gives
   c = (10, -5), and the part slides off without approaching fixel 2.  */
static void
test_disk(void)
{
    static const char text[] =
        "friction 1/10 1/2\nmass 1\ninertia 1/2\nshape disk 0 0 1\n"
        "fixel 0 -1 near\nfixel -1 0 near\n";
    wc_problem_t P;
    wc_plan_wrench_t W;
    wc_plan_t R;
    wc_error_t err;
    fmpq g[3];
    char mode[4];
    ulong S = 0;
    slong k;

    wc_problem_init(P);
    wc_plan_wrench_init(W);
    wc_plan_init(R);
    wc_error_init(err);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    if (wc_problem_parse(P, text, strlen(text), "<fig6>", err) != WC_OK)
        wctest_fail("fig6: %s", err->message);
    fmpq_set_si(g + 0, -2, 1);
    fmpq_set_si(g + 1, -10, 1);
    fmpq_set_si(g + 2, -10, 1);

    /* The oracle, on its own: at the goal fixel 1 slides and fixel 2
       separates (11 -> 10); at state 10 fixel 1 slides and fixel 2 is
       not approached (no progress).  */
    if (ref_plan_model_breaks(P, g, 0, &S, mode) != 1 || S != 3
        || strcmp(mode, "ls") != 0)
        fail_g(P, g, "the oracle does not find the slide off the goal");
    if (ref_plan_model_breaks(P, g, 1, &S, mode) != 1 || S != 1
        || strcmp(mode, "ls") != 0)
        fail_g(P, g, "the oracle does not find the slide at state 10");

    if (wc_plan_wrench(W, P, g, 1, err) != WC_OK)
        fail_g(P, g, err->message);
    if (W->in_goal)
        fail_g(P, g, "in G_goal, yet fixel 1 slides away");
    if (W->verdict == WC_PLAN_ACCEPTED)
        fail_g(P, g, "accepted by the complete plan, yet fixel 1 slides "
               "away");
    if (W->verdict != WC_PLAN_GOAL_LEAVES || W->ncycle != 1
        || W->cycle[0] != 3 || W->nholding != 1
        || strcmp(W->holding[0], "ms") != 0)
        fail_g(P, g, "want the goal 11 to leave, and the string ms");

    /* The whole plan: G_goal is the wedge of the plan model (mu = 1/2),
       forces strictly between (-1, -2) and (-2, -1) with any torque.  */
    if (wc_plan(R, P, 1, err) != WC_OK)
        fail_g(P, NULL, err->message);
    if (R->goal->npieces != 1
        || fmpz_mat_nrows(R->goal->pieces[0].rays) != 2
        || fmpz_mat_nrows(R->goal->pieces[0].lines) != 1)
        fail_g(P, NULL, "G_goal is not one open wedge");
    fmpq_set_si(g + 0, -3, 1);
    fmpq_set_si(g + 1, -3, 1);
    fmpq_set_si(g + 2, 7, 1);
    if (!wc_set_contains(R->goal, g))
        fail_g(P, g, "not in G_goal");
    expect_sound(P, g, 1);
    fmpq_set_si(g + 0, -2, 1);
    fmpq_set_si(g + 1, -1, 1);
    if (wc_set_contains(R->goal, g) || wc_set_contains(R->accepted, g))
        fail_g(P, g, "on the kinetic cone's edge, yet accepted");

    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    wc_error_clear(err);
    wc_plan_clear(R);
    wc_plan_wrench_clear(W);
    wc_problem_clear(P);
}

/* mu_k > mu_s at every fixel: mu_k := mu_s + t, t in (0, 5], and now and
   then mu_s := 0.  */
static void
kinetic_above_static(wc_problem_t P)
{
    fmpq_t t;
    slong i;

    fmpq_init(t);
    for (i = 0; i < P->n; i++)
    {
        wc_fixel_struct * f = P->fixels + i;

        if (wctest_chance(1, 4))
            fmpq_zero(f->mu_s);
        wctest_rand_fmpq_pos(t, 5, 5);
        fmpq_add(f->mu_k, f->mu_s, t);
    }
    fmpq_clear(t);
}

/* Up to max accepted cells of R (every step-th one from the chambers
   down), each against the oracle and against wc_plan_wrench.  */
static void
check_cells(const wc_problem_t P, const wc_plan_t R, slong max,
            slong * naccepted, slong * ngoal)
{
    wc_plan_wrench_t W;
    wc_error_t err;
    fmpq g[3];
    slong i, k, nacc = 0, step, tested = 0;

    wc_plan_wrench_init(W);
    wc_error_init(err);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    for (i = 0; i < R->cells->count; i++)
    {
        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(g + k, fmpz_mat_entry(R->cells->point, i, k));
        nacc += wc_set_contains(R->accepted, g);
    }
    step = nacc / max + 1;
    for (i = R->cells->count - 1, k = 0; i >= 0 && tested < max; i--)
    {
        slong j;
        int goal;

        for (j = 0; j < 3; j++)
            fmpq_set_fmpz(g + j, fmpz_mat_entry(R->cells->point, i, j));
        if (!wc_set_contains(R->accepted, g) || k++ % step != 0)
            continue;
        tested++;
        goal = wc_set_contains(R->goal, g);
        if (wc_plan_wrench(W, P, g, 1, err) != WC_OK)
            fail_g(P, g, err->message);
        if (W->verdict != WC_PLAN_ACCEPTED || W->in_goal != goal)
            fail_g(P, g, "wc_plan_wrench disagrees with the plan's sets");
        expect_sound(P, g, 0);
        (*naccepted)++;
        if (goal)
        {
            expect_sound(P, g, 1);
            (*ngoal)++;
        }
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    wc_error_clear(err);
    wc_plan_wrench_clear(W);
}

static void
test_random(void)
{
    slong i, iters = wctest_iters(16), naccepted = 0, ngoal = 0;

    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;
        wc_plan_t R;
        wc_error_t err;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        wc_plan_init(R);
        wc_error_init(err);
        wctest_random_problem(P, 1, 3);
        kinetic_above_static(P);
        if (wc_plan(R, P, 1, err) != WC_OK)
            fail_g(P, NULL, err->message);
        check_cells(P, R, P->n <= 2 ? 8 : 4, &naccepted, &ngoal);
        wc_error_clear(err);
        wc_plan_clear(R);
        wc_problem_clear(P);
    }
    /* not vacuous: the default run tests wrenches of both sets */
    if (iters >= 16 && getenv("WC_TEST_ITER") == NULL
        && (naccepted == 0 || ngoal == 0))
        wctest_fail("only %ld accepted wrenches, %ld of G_goal, tested",
                    (long) naccepted, (long) ngoal);
}

int
main(void)
{
    wctest_init("t-plansound");
    wc_init();
    test_disk();
    test_random();
    flint_cleanup();
    return 0;
}
