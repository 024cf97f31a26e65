/* bench-plan.c -- time wc_plan (the insertion plan as exact sets) for
   growing n, against G_goal computed without the syntactic reduction, and
   the complete plan.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Usage: bench-plan [quick | LIMIT_SECONDS]
          bench-plan disk|random N [REPEAT]
   The second form times wc_plan alone on one problem (REPEAT times,
   default 1) and prints the CPU seconds of each call (for profiling).
   Problems, exact and deterministic:

   disk     a unit disk (mass 1, inertia 1/2) near n fixels on its lower
            left quarter, at the rational points ((1 - s^2), 2 s) /
            (1 + s^2) reflected into that quarter, s = k / (n + 1) ...,
            normals towards the centre, friction 1/5: Figure 6 with n
            fixels (all normals through one point);
   random   wc_random_problem with n fixels, seed 1, a polygon shape.

   For n = 2, 3, ... it measures wc_plan (strings, cones, the goal state's
   stability sets, the cells, G_goal as pieces, eq. 25, the pushing
   region), until one run exceeds LIMIT (default 10 s; quick: 1 s); and as
   the baseline G_goal from every generated string's cone (3^n - 2^n of
   them, no syntactic reduction), checked against wc_plan's G_goal at a
   point of every cell of its own arrangement (a disagreement prints
   DIFFER and the exit status is 3); and the complete plan (3^n outcome
   cones) while it stays under LIMIT.  Ratios in one process are the
   numbers to compare.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>

#include <flint/flint.h>
#include <flint/fmpq.h>

#include "wrenchcone.h"
#include "benchutil.h"

static void
disk_problem(wc_problem_t P, slong n)
{
    slong k;

    fmpq_set_si(P->inertia, 1, 2);
    fmpq_set_si(P->mu_s, 1, 5);
    fmpq_set_si(P->mu_k, 1, 5);
    P->shape = WC_SHAPE_DISK;
    P->shape_len = 3;
    P->shape_data = malloc(sizeof(fmpq) * 3);
    for (k = 0; k < 3; k++)
        fmpq_init(P->shape_data + k);
    fmpq_one(P->shape_data + 2);
    for (k = 0; k < n; k++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);
        fmpq_t s, d, t;

        /* s in (0, 1): the point (-(1 - s^2), -2 s) / (1 + s^2) runs over
           the open lower-left quarter */
        fmpq_init(s);
        fmpq_init(d);
        fmpq_init(t);
        fmpq_set_si(s, k + 1, n + 1);
        fmpq_mul(t, s, s);
        fmpq_add_si(d, t, 1);
        fmpq_sub_si(t, t, 1);
        fmpq_div(f->point + 0, t, d);       /* -(1 - s^2) / (1 + s^2) */
        fmpq_mul_2exp(t, s, 1);
        fmpq_div(f->point + 1, t, d);
        fmpq_neg(f->point + 1, f->point + 1);
        fmpq_neg(f->normal + 0, f->point + 0);
        fmpq_neg(f->normal + 1, f->point + 1);
        f->state = WC_NEAR;
        fmpq_clear(s);
        fmpq_clear(d);
        fmpq_clear(t);
    }
}

/* G_goal from every generated string: returns the time, sets *differ
   when it disagrees with R's G_goal at some cell point.  */
static double
literal(const wc_problem_t P, const wc_plan_t R, int * differ,
        slong * ncones)
{
    wc_plan_strings_t T;
    wc_problem_t Q;
    wc_error_t err;
    wc_cone_struct * C;
    wc_cells_t A;
    fmpz_mat_t H;
    fmpq g[3];
    slong i, j, k, r = 0, rows = 0;
    double t0 = wcbench_now(), t1;
    int * member;

    wc_error_init(err);
    wc_plan_strings_init(T);
    wc_problem_init(Q);
    wc_cells_init(A);
    if (wc_plan_strings(T, P->n, err) != WC_OK
        || wc_problem_set(Q, P) != WC_OK)
        wcbench_die("bench-plan", "strings", err);
    /* the plan model: an m contact may stick or slide, |c_t| <=
       max(mu_s, mu_k) c_n */
    for (k = 0; k < Q->n; k++)
        if (fmpq_cmp(Q->fixels[k].mu_k, Q->fixels[k].mu_s) > 0)
            fmpq_set(Q->fixels[k].mu_s, Q->fixels[k].mu_k);
    C = malloc(sizeof(wc_cone_struct) * T->nstrings);
    for (i = 0; i < T->nstrings; i++)
    {
        const char * x = T->strings[i];

        for (k = 0; k < P->n; k++)
            Q->fixels[k].state = x[k] == 'm' ? WC_TOUCHING
                : x[k] == 'u' ? WC_NEAR : Q->fixels[k].state;
        wc_cone_init(C + i, 3);
        if (wc_wrench_cone_direct(C + i, NULL, Q, x, err) != WC_OK)
            wcbench_die("bench-plan", "cone", err);
        rows += fmpz_mat_nrows(C[i].ineqs) + fmpz_mat_nrows(C[i].eqs);
    }
    fmpz_mat_init(H, rows, 3);
    for (i = 0; i < T->nstrings; i++)
    {
        const fmpz_mat_struct * M[2] = { C[i].ineqs, C[i].eqs };

        for (j = 0; j < 2; j++)
            for (k = 0; k < fmpz_mat_nrows(M[j]); k++, r++)
                _fmpz_vec_set(H->rows[r], M[j]->rows[k], 3);
    }
    if (wc_cells_build(A, H, err) != WC_OK)
        wcbench_die("bench-plan", "cells", err);
    member = malloc(sizeof(int) * (A->count + 1));
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    for (j = 0; j < A->count; j++)
    {
        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(g + k, fmpz_mat_entry(A->point, j, k));
        member[j] = 1;
        for (i = 0; i < T->nstrings && member[j]; i++)
            member[j] = !wc_cone_contains(C + i, g);
    }
    {
        wc_set_t S;

        wc_set_init(S);
        if (wc_set_from_cells(S, A, member, err) != WC_OK)
            wcbench_die("bench-plan", "set", err);
        wc_set_clear(S);
    }
    t1 = wcbench_now();
    *differ = 0;
    for (j = 0; j < A->count; j++)
    {
        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(g + k, fmpz_mat_entry(A->point, j, k));
        if (member[j] != wc_set_contains(R->goal, g))
            *differ = 1;
    }
    *ncones = T->nstrings;
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    free(member);
    for (i = 0; i < T->nstrings; i++)
        wc_cone_clear(C + i);
    free(C);
    fmpz_mat_clear(H);
    wc_cells_clear(A);
    wc_problem_clear(Q);
    wc_plan_strings_clear(T);
    wc_error_clear(err);
    return t1 - t0;
}

static void
make_problem(wc_problem_t P, const char * family, slong n)
{
    wc_error_t err;

    wc_error_init(err);
    if (strcmp(family, "disk") == 0)
        disk_problem(P, n);
    else
    {
        wc_random_options o;

        wc_random_options_init(&o);
        o.fixels = n;
        o.seed = 1;
        o.shape = WC_SHAPE_POLYGON;
        if (wc_random_problem(P, &o, err) != WC_OK)
            wcbench_die("bench-plan", "random", err);
        wc_random_options_clear(&o);
    }
    wc_error_clear(err);
}

/* CPU seconds of this process, user + system.  */
static double
cpu_now(void)
{
    struct rusage u;

    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec
        + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/* wc_plan alone on one problem, repeat times.  */
static int
one(const char * family, slong n, slong repeat)
{
    wc_problem_t P;
    wc_error_t err;
    slong i;

    wc_problem_init(P);
    wc_error_init(err);
    make_problem(P, family, n);
    for (i = 0; i < repeat; i++)
    {
        wc_plan_t R;
        double t0 = cpu_now(), w0 = wcbench_now();

        wc_plan_init(R);
        if (wc_plan(R, P, 0, err) != WC_OK)
            wcbench_die("bench-plan", "plan", err);
        printf("%s n=%ld: cpu %.3f s, wall %.3f s, cells %ld, planes %ld, "
               "pieces %ld, exactly needed %ld of %ld\n", family, (long) n,
               cpu_now() - t0, wcbench_now() - w0, (long) R->cells->count,
               (long) R->cells->nplanes, (long) R->goal->npieces,
               (long) R->nexact, (long) R->T->nneeded);
        wc_plan_clear(R);
    }
    wc_error_clear(err);
    wc_problem_clear(P);
    return 0;
}

static int
run(const char * family, double limit)
{
    slong n;
    int status = 0, plan_on = 1, lit_on = 1, comp_on = 1;
    double over = 0;

    printf("%-7s %3s %6s %6s %11s %7s %6s %6s %6s %11s %9s %11s\n", "family",
           "n", "strs", "needed", "plan ms", "cells", "planes", "pieces",
           "eq25", "literal ms", "lit/plan", "complete ms");
    for (n = 2; plan_on; n++)
    {
        wc_problem_t P;
        wc_plan_t R;
        wc_error_t err;
        double t0, tp, tl = -1, tc = -1;
        int differ = 0;
        slong ncones = 0;

        wc_problem_init(P);
        wc_error_init(err);
        wc_plan_init(R);
        make_problem(P, family, n);
        t0 = wcbench_now();
        if (wc_plan(R, P, 0, err) != WC_OK)
            wcbench_die("bench-plan", "plan", err);
        tp = wcbench_now() - t0;
        if (lit_on)
        {
            tl = literal(P, R, &differ, &ncones);
            lit_on = tl < limit;
            if (differ)
                status = 3;
        }
        if (comp_on && n <= WC_PLAN_MAX_FIXELS_COMPLETE)
        {
            wc_plan_t C;

            wc_plan_init(C);
            t0 = wcbench_now();
            if (wc_plan(C, P, 1, err) != WC_OK)
                wcbench_die("bench-plan", "complete", err);
            tc = wcbench_now() - t0;
            comp_on = tc < limit;
            wc_plan_clear(C);
        }
        printf("%-7s %3ld %6ld %6ld %11.3f %7ld %6ld %6ld %3s/%-2s", family,
               (long) n, (long) R->T->nstrings, (long) R->T->nneeded,
               1e3 * tp, (long) R->cells->count, (long) R->cells->nplanes,
               (long) R->goal->npieces, R->goal_in_strong ? "yes" : "no",
               R->goal_in_strong_paper ? "y" : "n");
        if (tl >= 0)
            printf(" %11.3f %8.1fx", 1e3 * tl, tl / tp);
        else
            printf(" %11s %9s", "-", "-");
        if (tc >= 0)
            printf(" %11.3f", 1e3 * tc);
        else
            printf(" %11s", "-");
        printf("%s\n", differ ? "  DIFFER" : "");
        if (tp > 1 && over == 0)
            over = (double) n;
        plan_on = tp < limit && n < WC_PLAN_MAX_FIXELS;
        wc_plan_clear(R);
        wc_error_clear(err);
        wc_problem_clear(P);
        (void) ncones;
    }
    if (over > 0)
        printf("%s: wc_plan passes 1 s at n = %.0f\n", family, over);
    else
        printf("%s: wc_plan stays under 1 s up to the last n above\n",
               family);
    return status;
}

int
main(int argc, char ** argv)
{
    double limit = 10;
    int status = 0;

    if (argc > 2)
    {
        wc_init();
        status = one(argv[1], atol(argv[2]), argc > 3 ? atol(argv[3]) : 1);
        flint_cleanup_master();
        return status;
    }
    if (argc > 1)
        limit = strcmp(argv[1], "quick") == 0 ? 1 : atof(argv[1]);
    wc_init();
    printf("Insertion plans: wc_plan (syntactic reduction, n 2^(n-1) cones) "
           "vs G_goal from all 3^n - 2^n strings; complete plan (3^n cones).\n"
           "eq25: G_goal inside G_strong, exact/paper semantics.\n");
    status |= run("disk", limit);
    status |= run("random", limit);
    flint_cleanup_master();
    return status;
}
