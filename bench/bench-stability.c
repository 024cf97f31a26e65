/* bench-stability.c -- time wc_classify (one wrench, exact LPs) and
   wc_stability (the exact sets), and eq. 19 of the paper taken literally
   (one wrench cone per Table 2 string) against wc_stability.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Usage: bench-stability [quick | SECONDS_PER_CELL] [LITERAL_LIMIT]
   ("quick": smaller sizes, 0.05 s per cell, literal limit 1 s.)
   Problems, all exact rationals and deterministic; n counts every fixel:

   random          wc_random_problem with n fixels, seed 1, no shape
                   (touching and near mixed, friction drawn, as the
                   generator does);
   one-sided       n touching fixels on the lower half of the unit circle
                   at ((1 - s^2), -2 s) / (1 + s^2), s = (k + 1) / (n - k),
                   k = 0 .. n-1, normal minus the point (towards the
                   centre), friction 1/3, com (0, 0): a part resting in a
                   cradle -- many moving faces, the hard case;
   one-sided+near  the same with ceil(n/2) touching fixels, plus floor(n/2)
                   near fixels on the upper half at
                   ((1 - s^2), 2 s) / (1 + s^2), s = (2k + 1) / (2 (m - k)).

   Measured: (1) wc_classify of the wrenches (0,-1,0), (1,-2,1/3), (0,0,1)
   and (2,1,-1) with max_modes = 1000 (the CLI's default), median and mean
   over repeated calls of at least SECONDS_PER_CELL (default 0.2 s) per
   cell, for n = 10, 20, 50, 100, and with certificates at n = 10;
   (2) wc_stability (exact and paper semantics in one call) for n = 2 ..
   12 on the cradles, with the size of its output; (3) eq. 19 literally on
   the one-sided cradle: wc_wrench_cone(.., WC_METHOD_DIRECT, ..) for
   every string of {s,l,r,n}^t except n..n, counting the nonempty cones,
   for t = 1, 2, .. until one run exceeds LITERAL_LIMIT (default 3 s),
   next to wc_stability on the same problem; (4) the one-sided cradle at
   n = 25, 50, 71, 100 (quick: 12, 25): wc_classify's median per call
   and wc_stability's time, with the growth exponent of each (the
   least-squares slope of log time against log n).  Where it is affordable
   (cells x cones <= 4e7) the literal union is checked against
   wc_stability's paper set at a point of every cell; wc_classify's
   verdicts are checked against the sets in table (2).  A disagreement
   prints DIFFER and the exit status is then 3.  Ratios measured in this
   one process are the numbers to compare, not the absolute times.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <math.h>

#include <flint/flint.h>
#include <flint/fmpz.h>
#include <flint/fmpq.h>

#include "wrenchcone.h"
#include "benchutil.h"

enum { FAM_RANDOM = 0, FAM_ONESIDED = 1, FAM_NEAR = 2, NFAM = 3 };

static const char * const family_name[NFAM] = {
    "random", "one-sided", "one-sided+near" };

/* The wrenches classified, (fx, fy, tau) as num/den pairs.  */
#define NWRENCH 4
static const slong wrench_q[NWRENCH][3][2] = {
    { { 0, 1 }, { -1, 1 }, { 0, 1 } },
    { { 1, 1 }, { -2, 1 }, { 1, 3 } },
    { { 0, 1 }, { 0, 1 }, { 1, 1 } },
    { { 2, 1 }, { 1, 1 }, { -1, 1 } } };

static void
set_wrench(fmpq * g, int w)
{
    int k;

    for (k = 0; k < 3; k++)
        fmpq_set_si(g + k, wrench_q[w][k][0], (ulong) wrench_q[w][k][1]);
}

/* P (freshly initialised) := the problem of family fam with n fixels.  */
static void
make_problem(wc_problem_t P, int fam, slong n)
{
    slong t, m, k;

    if (fam == FAM_RANDOM)
    {
        wcbench_random_problem(P, n, "bench-stability");
        return;
    }
    /* The cradle: friction 1/3 everywhere (set before adding fixels,
       which copy the global coefficients), com at the centre.  */
    fmpq_set_si(P->mu_s, 1, 3);
    fmpq_set_si(P->mu_k, 1, 3);
    fmpq_zero(P->com + 0);
    fmpq_zero(P->com + 1);
    t = fam == FAM_ONESIDED ? n : (n + 1) / 2;
    m = n - t;
    /* s = (k + 1) / (t - k) increases from 1/t to t: the points sweep the
       lower half from near (1, 0) to near (-1, 0).  */
    for (k = 0; k < t; k++)
        wcbench_circle_fixel(P, k + 1, t - k, -1, WC_TOUCHING);
    for (k = 0; k < m; k++)
        wcbench_circle_fixel(P, 2 * k + 1, 2 * (m - k), 1, WC_NEAR);
}

static slong
touching(const wc_problem_t P)
{
    slong i, t = 0;

    for (i = 0; i < P->n; i++)
        t += P->fixels[i].state == WC_TOUCHING;
    return t;
}

static int
cmp_double(const void * a, const void * b)
{
    double x = *(const double *) a, y = *(const double *) b;

    return (x > y) - (x < y);
}

/* One classify cell: rounds over the wrenches until budget has passed
   (at least one round); each call timed alone.  verdicts[w] gets "wsp"
   with '.' for a no (weak, strong, strong_paper); *modes the modes listed
   summed over the wrenches, *complete 0 when some list stopped short.  */
typedef struct
{
    double median, mean, max;
    long calls;
    char verdicts[NWRENCH][4];
    slong modes;
    int complete;
}
classify_cell;

static void
time_classify(classify_cell * c, const wc_problem_t P, int cert,
              double budget)
{
    wc_classify_t R;
    wc_error_t err;
    fmpq g[3];
    double * tm = NULL, t0 = wcbench_now(), t1, sum = 0;
    long alloc = 0, i;
    int w, k, round = 0;

    wc_classify_init(R);
    wc_error_init(err);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    c->calls = 0;
    c->modes = 0;
    c->complete = 1;
    c->max = 0;
    do
    {
        for (w = 0; w < NWRENCH; w++)
        {
            set_wrench(g, w);
            if (c->calls == alloc)
            {
                alloc = 2 * alloc + 64;
                tm = realloc(tm, sizeof(double) * alloc);
            }
            t1 = wcbench_now();
            if (wc_classify(R, P, g, cert, 1000, err) != WC_OK)
                wcbench_die("bench-stability", "wc_classify", err);
            tm[c->calls++] = wcbench_now() - t1;
            if (round == 0)
            {
                c->verdicts[w][0] = R->weak ? 'w' : '.';
                c->verdicts[w][1] = R->strong ? 's' : '.';
                c->verdicts[w][2] = R->strong_paper ? 'p' : '.';
                c->verdicts[w][3] = '\0';
                c->modes += R->nmodes;
                c->complete &= R->modes_complete;
            }
        }
        round++;
    }
    while (wcbench_now() - t0 < budget);
    for (i = 0; i < c->calls; i++)
    {
        sum += tm[i];
        if (tm[i] > c->max)
            c->max = tm[i];
    }
    c->mean = sum / c->calls;
    qsort(tm, c->calls, sizeof(double), cmp_double);
    c->median = c->calls % 2 ? tm[c->calls / 2]
        : 0.5 * (tm[c->calls / 2 - 1] + tm[c->calls / 2]);
    free(tm);
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    wc_error_clear(err);
    wc_classify_clear(R);
}

static void
print_classify_row(const char * fam, slong n, slong t, int cert,
                   const classify_cell * c)
{
    char modes[32];
    int w;

    snprintf(modes, sizeof modes, "%ld%s", (long) c->modes,
             c->complete ? "" : "+");
    printf("%-15s %4ld %4ld  %-4s %10.3f %10.3f %10.3f %6ld  %8s ", fam,
           (long) n, (long) t, cert ? "yes" : "no", 1e3 * c->median,
           1e3 * c->mean, 1e3 * c->max, c->calls, modes);
    for (w = 0; w < NWRENCH; w++)
        printf(" %s", c->verdicts[w]);
    printf("\n");
    fflush(stdout);
}

/* The least-squares slope of log y against log x over k points.  */
static double
growth(const double * x, const double * y, int k)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0, lx, ly;
    int i;

    for (i = 0; i < k; i++)
    {
        lx = log(x[i]);
        ly = log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

/* Mean seconds per wc_stability over repeated runs of at least budget
   (one run when it alone takes longer); the last result stays in S.  */
static double
time_stability(wc_stability_t S, const wc_problem_t P, double budget)
{
    wc_error_t err;
    double t0 = wcbench_now(), t;
    long reps = 0;

    wc_error_init(err);
    do
    {
        if (wc_stability(S, P, err) != WC_OK)
            wcbench_die("bench-stability", "wc_stability", err);
        reps++;
        t = wcbench_now() - t0;
    }
    while (t < budget);
    wc_error_clear(err);
    return t / reps;
}

/* 1 when wc_classify's verdicts on the bench wrenches match membership
   in S's sets.  */
static int
classify_agrees(const wc_stability_t S, const wc_problem_t P)
{
    wc_classify_t R;
    wc_error_t err;
    fmpq g[3];
    int w, k, ok = 1;

    wc_classify_init(R);
    wc_error_init(err);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    for (w = 0; w < NWRENCH && ok; w++)
    {
        set_wrench(g, w);
        if (wc_classify(R, P, g, 0, 1000, err) != WC_OK)
            wcbench_die("bench-stability", "wc_classify", err);
        ok = R->weak == wc_cone_contains(S->weak, g)
            && R->strong == wc_set_contains(S->strong, g)
            && R->strong_paper == wc_set_contains(S->strong_paper, g);
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    wc_error_clear(err);
    wc_classify_clear(R);
    return ok;
}

/* The literal eq. 19: W(x) for every x in {s,l,r,n}^t but n..n (all
   fixels touching).  The nonempty cones are kept in *kept (count
   *nkept) for the check; the caller frees them.  Returns the number of
   strings.  */
static slong
literal_union(wc_cone_struct ** kept, slong * nkept, const wc_problem_t P)
{
    static const char letters[4] = { 's', 'l', 'r', 'n' };
    slong t = P->n, total = 1, x, i, alloc = 0, strings = 0;
    char * mode = malloc(t + 1);
    wc_cone_t W;
    wc_error_t err;

    for (i = 0; i < t; i++)
        total *= 4;
    wc_cone_init(W, 3);
    wc_error_init(err);
    *kept = NULL;
    *nkept = 0;
    mode[t] = '\0';
    for (x = 0; x < total; x++)
    {
        slong r = x;

        for (i = 0; i < t; i++)
        {
            mode[i] = letters[r % 4];
            r /= 4;
        }
        if (x == total - 1)     /* n..n */
            continue;
        strings++;
        if (wc_wrench_cone(W, NULL, P, mode, WC_METHOD_DIRECT, err)
            != WC_OK)
            wcbench_die("bench-stability", mode, err);
        if (!W->empty)
        {
            if (*nkept == alloc)
            {
                alloc = 2 * alloc + 64;
                *kept = flint_realloc(*kept, sizeof(wc_cone_struct) * alloc);
            }
            wc_cone_init(*kept + *nkept, 3);
            wc_cone_swap(*kept + *nkept, W);
            (*nkept)++;
        }
    }
    wc_cone_clear(W);
    wc_error_clear(err);
    free(mode);
    return strings;
}

static void
free_kept(wc_cone_struct * kept, slong nkept)
{
    slong i;

    for (i = 0; i < nkept; i++)
        wc_cone_clear(kept + i);
    flint_free(kept);
}

/* 1 when, at a point of every cell of S's arrangement, "in no kept cone"
   is the same as "in S->strong_paper".  */
static int
literal_agrees(const wc_stability_t S, const wc_cone_struct * kept,
               slong nkept)
{
    fmpq g[3];
    slong i, j;
    int k, ok = 1;

    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    for (i = 0; i < S->cells->count && ok; i++)
    {
        int in_union = 0;

        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(g + k, fmpz_mat_entry(S->cells->point, i, k));
        for (j = 0; j < nkept && !in_union; j++)
            in_union = wc_cone_contains(kept + j, g);
        ok = in_union != wc_set_contains(S->strong_paper, g);
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    return ok;
}

int
main(int argc, char ** argv)
{
    static const slong csizes_full[] = { 10, 20, 50, 100 };
    static const slong csizes_quick[] = { 10, 20 };
    int quick = argc > 1 && strcmp(argv[1], "quick") == 0;
    double budget = quick ? 0.05 : argc > 1 ? atof(argv[1]) : 0.2;
    double limit = argc > 2 ? atof(argv[2]) : quick ? 1.0 : 3.0;
    const slong * csizes = quick ? csizes_quick : csizes_full;
    slong ncsizes = quick ? 2 : 4, smax = quick ? 8 : 12, n, t, i;
    double classify50[NFAM], classify50_median[NFAM], stab12[NFAM];
    static const slong scale_full[] = { 25, 50, 71, 100 };
    static const slong scale_quick[] = { 12, 25 };
    const slong * scale = quick ? scale_quick : scale_full;
    slong nscale = quick ? 2 : 4;
    double scale_n[4], scale_cls[4], scale_stab[4];
    double cradle50 = -1, stab100 = -1;
    double pass_lit = 0, pass_stab = 0;
    slong pass_t = 0;
    int fam, bad = 0;

    if (budget <= 0 || limit <= 0 || argc > 3)
    {
        fprintf(stderr, "usage: bench-stability [quick | SECONDS_PER_CELL] "
                "[LITERAL_LIMIT]\n");
        return 2;
    }
    wc_init();
    for (fam = 0; fam < NFAM; fam++)
        classify50[fam] = stab12[fam] = -1;
    printf("Stability of a fixtured part: wc_classify (one wrench, exact "
           "LPs) and wc_stability\n(the exact sets, exact and paper "
           "semantics in one call), and eq. 19 taken literally\n(one "
           "direct wrench cone per Table 2 string).  Every number computed "
           "is an exact\nrational; the timings are the only floats.  n: "
           "fixels, t: touching ones.\n");

    /* (1) classify.  */
    printf("\n(1) wc_classify, max_modes = 1000; ms per call over the 4 "
           "wrenches\n    (0,-1,0) (1,-2,1/3) (0,0,1) (2,1,-1); "
           "verdicts w = weak, s = strong, p = strong (paper);\n"
           "    modes: Table 2 strings listed, summed over the wrenches "
           "(+: a list stopped at 1000)\n");
    printf("%-15s %4s %4s  %-4s %10s %10s %10s %6s  %8s  %s\n", "family",
           "n", "t", "cert", "median ms", "mean ms", "max ms", "calls",
           "modes", "verdicts");
    for (fam = 0; fam < NFAM; fam++)
        for (i = 0; i < ncsizes; i++)
        {
            wc_problem_t P;
            classify_cell c;

            n = csizes[i];
            wc_problem_init(P);
            make_problem(P, fam, n);
            time_classify(&c, P, 0, budget);
            print_classify_row(family_name[fam], n, touching(P), 0, &c);
            if (n == 50)
            {
                classify50[fam] = c.mean;
                classify50_median[fam] = c.median;
            }
            if (n == 10)
            {
                time_classify(&c, P, 1, budget);
                print_classify_row(family_name[fam], n, touching(P), 1, &c);
            }
            wc_problem_clear(P);
        }

    /* (2) stability on the cradles.  */
    printf("\n(2) wc_stability, mean ms per call; cells and planes of the "
           "arrangement, moving faces,\n    eq. 19's extra cones, pieces "
           "of each set (weak is one closed cone), whether the\n    exact "
           "and paper sets differ, whether wc_classify agrees with the "
           "sets on the 4 wrenches\n");
    printf("%-15s %4s %4s %11s %7s %6s %6s %5s %6s %6s %6s %7s\n", "family",
           "n", "t", "ms", "cells", "planes", "moving", "union", "strong",
           "paper", "differ", "classify");
    for (fam = FAM_ONESIDED; fam < NFAM; fam++)
        for (n = 2; n <= smax; n++)
        {
            wc_problem_t P;
            wc_stability_t S;
            double ts;
            int ok;

            wc_problem_init(P);
            wc_stability_init(S);
            make_problem(P, fam, n);
            ts = time_stability(S, P, budget);
            ok = classify_agrees(S, P);
            bad |= !ok;
            printf("%-15s %4ld %4ld %11.3f %7ld %6ld %6ld %5ld %6ld %6ld "
                   "%6s %7s\n", family_name[fam], (long) n,
                   (long) touching(P), 1e3 * ts, (long) S->cells->count,
                   (long) S->cells->nplanes, (long) S->nmoving,
                   (long) S->nunion, (long) S->strong->npieces,
                   (long) S->strong_paper->npieces, S->differ ? "yes" : "no",
                   ok ? "agrees" : "DIFFER");
            fflush(stdout);
            if (n == 12)
                stab12[fam] = ts;
            wc_stability_clear(S);
            wc_problem_clear(P);
        }

    /* (3) eq. 19 literally on the one-sided cradle.  */
    printf("\n(3) eq. 19 literally on the one-sided cradle (n = t): "
           "wc_wrench_cone DIRECT for the 4^t - 1\n    strings, ms per "
           "run; wc_stability on the same problem; check: the literal "
           "union\n    against wc_stability's paper set at a point of "
           "every cell (- : too costly, skipped)\n");
    printf("%4s %9s %9s %13s %13s %10s %7s\n", "t", "strings", "nonempty",
           "literal ms", "stability ms", "lit/stab", "check");
    for (t = 1; t <= 12; t++)
    {
        wc_problem_t P;
        wc_stability_t S;
        wc_cone_struct * kept = NULL;
        slong nkept = 0, strings = 0;
        double tl, ts, t0 = wcbench_now();
        long reps = 0;
        const char * check = "-";

        wc_problem_init(P);
        wc_stability_init(S);
        make_problem(P, FAM_ONESIDED, t);
        do
        {
            free_kept(kept, nkept);
            strings = literal_union(&kept, &nkept, P);
            reps++;
            tl = wcbench_now() - t0;
        }
        while (tl < budget);
        tl /= reps;
        ts = time_stability(S, P, budget);
        if ((double) S->cells->count * (double) nkept <= 4e7)
        {
            int ok = literal_agrees(S, kept, nkept);

            check = ok ? "agrees" : "DIFFER";
            bad |= !ok;
        }
        printf("%4ld %9ld %9ld %13.3f %13.3f %9.2fx %7s\n", (long) t,
               (long) strings, (long) nkept, 1e3 * tl, 1e3 * ts, tl / ts,
               check);
        fflush(stdout);
        if (pass_t == 0 && tl > 1.0)
        {
            pass_t = t;
            pass_lit = tl;
            pass_stab = ts;
        }
        free_kept(kept, nkept);
        wc_stability_clear(S);
        wc_problem_clear(P);
        if (tl > limit)
            break;
    }

    /* (4) the cradle at scale: classify and stability as t grows.  */
    printf("\n(4) the one-sided cradle at scale (n = t): wc_classify, median "
           "ms per call over the 4\n    wrenches; wc_stability, ms per "
           "call; growth exponents (least-squares slope of\n    log time "
           "vs log n)\n");
    printf("%4s %12s %13s %7s\n", "n", "classify ms", "stability ms",
           "cells");
    for (i = 0; i < nscale; i++)
    {
        wc_problem_t P;
        wc_stability_t S;
        classify_cell c;

        n = scale[i];
        wc_problem_init(P);
        wc_stability_init(S);
        make_problem(P, FAM_ONESIDED, n);
        time_classify(&c, P, 0, budget);
        scale_cls[i] = c.median;
        scale_stab[i] = time_stability(S, P, budget);
        scale_n[i] = (double) n;
        printf("%4ld %12.3f %13.3f %7ld\n", (long) n, 1e3 * c.median,
               1e3 * scale_stab[i], (long) S->cells->count);
        fflush(stdout);
        if (n == 50)
            cradle50 = c.median;
        if (n == 100)
            stab100 = scale_stab[i];
        wc_stability_clear(S);
        wc_problem_clear(P);
    }
    printf("growth exponent, n = %ld..%ld: classify %.2f, stability %.2f\n",
           (long) scale[0], (long) scale[nscale - 1],
           growth(scale_n, scale_cls, (int) nscale),
           growth(scale_n, scale_stab, (int) nscale));

    /* The targets.  */
    printf("\nTargets:\n");
    for (fam = 0; fam < NFAM; fam++)
        if (classify50[fam] >= 0)
            printf("  classify, n = 50, %-15s median %8.3f ms, mean %8.3f "
                   "ms  (target < 100 ms): %s\n", family_name[fam],
                   1e3 * classify50_median[fam], 1e3 * classify50[fam],
                   classify50[fam] < 0.1 ? "met" : "NOT met");
    for (fam = FAM_ONESIDED; fam < NFAM; fam++)
        if (stab12[fam] >= 0)
            printf("  stability, n = 12, %-15s %8.3f ms  (target < 1 s): "
                   "%s\n", family_name[fam], 1e3 * stab12[fam],
                   stab12[fam] < 1.0 ? "met" : "NOT met");
    if (cradle50 >= 0)
        printf("  classify, n = 50, one-sided cradle, median %8.3f ms  "
               "(target < 20 ms): %s\n", 1e3 * cradle50,
               cradle50 < 0.02 ? "met" : "NOT met");
    if (stab100 >= 0)
        printf("  stability, n = 100, one-sided cradle, %8.3f ms  (target "
               "< 5 s): %s\n", 1e3 * stab100, stab100 < 5.0 ? "met"
               : "NOT met");
    if (pass_t > 0)
        printf("  literal eq. 19 passes 1 s at t = %ld: %.3f ms, against "
               "wc_stability %.3f ms (%.0fx)\n", (long) pass_t,
               1e3 * pass_lit, 1e3 * pass_stab, pass_lit / pass_stab);
    else
        printf("  literal eq. 19 stayed under 1 s up to the limit\n");
    flint_cleanup_master();
    return bad ? 3 : 0;
}
