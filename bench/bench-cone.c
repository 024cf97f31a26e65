/* bench-cone.c -- time one mode cone by each route, n = 1 .. 8 fixels
   (the paper's Table 4), the direct route alone up to n = 1000 with its
   growth exponent, and the 3-D conversion alone on k random generators
   (the O(k log k) fan against the former O(k^2) kernel, tests/old-hull3.c);
   last, the direct route with its fast path (lib/analysis/direct3.c)
   against the general direct route alone, n = 1, 2 and 50, in CPU time,
   both answers compared in JSON.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Usage: bench-cone [MAXN_PAPER] [SECONDS_PER_CELL]
   Problems: n touching fixels at distinct rational points of a 3:4:5
   circle-like layout with inward normals, friction 1/5 (mu_k 1/10), the
   centre of mass off the origin; modes l..l and n..n.  Each cell is the
   mean over repeated runs of at least SECONDS_PER_CELL (default 0.2 s).
   Ratios are measured in this one process, on this machine: they are the
   numbers to compare, not the absolute times.  The last line is
   "direct vs paper at n=6: RATIO x" (summed over both modes).  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "wrenchcone.h"
#include "benchutil.h"
#include "exact/hull3.h"
#include "analysis/direct3.h"
#include "old-hull3.h"

/* The options of JSON output (io/print.h).  */
static const wc_print_opts as_json[1] = { { WC_FORMAT_JSON, 0, 0, NULL } };

/* Mean seconds per cone.  */
static double
time_cone(const wc_problem_t P, const char * mode, wc_method method,
          double budget, int * empty)
{
    wc_error_t err;
    wc_cone_t W;
    double t0 = wcbench_now(), t;
    long reps = 0;

    wc_error_init(err);
    wc_cone_init(W, 3);
    do
    {
        if (wc_wrench_cone(W, NULL, P, mode, method, err) != WC_OK)
        {
            fprintf(stderr, "bench-cone: %s\n", err->message);
            exit(3);
        }
        reps++;
        t = wcbench_now() - t0;
    }
    while (t < budget);
    *empty = W->empty;
    wc_cone_clear(W);
    wc_error_clear(err);
    return t / reps;
}

/* k random generators, pointed: (x, y, R) with (x, y) uniform in the disc
   of radius R = 2^20 (a random layout with many extreme rays).  */
static void
random_generators(fmpq_mat_t G, slong k, flint_rand_t st)
{
    slong i, R = WORD(1) << 20;

    fmpq_mat_clear(G);
    fmpq_mat_init(G, k, 3);
    for (i = 0; i < k; i++)
    {
        slong x, y;

        do
        {
            x = (slong) n_randint(st, 2 * R + 1) - R;
            y = (slong) n_randint(st, 2 * R + 1) - R;
        }
        while ((double) x * x + (double) y * y > (double) R * R);
        fmpq_set_si(fmpq_mat_entry(G, i, 0), x, 1);
        fmpq_set_si(fmpq_mat_entry(G, i, 1), y, 1);
        fmpq_set_si(fmpq_mat_entry(G, i, 2), R, 1);
    }
}

/* Mean seconds of one V -> H conversion (old: the reference kernel).  */
static double
time_conversion(const fmpq_mat_t G, int old, double budget, slong * facets)
{
    fmpq_mat_t E, H;
    wc_error_t err;
    double t0 = wcbench_now(), t;
    long reps = 0;

    fmpq_mat_init(E, 0, 3);
    fmpq_mat_init(H, 0, 3);
    wc_error_init(err);
    do
    {
        if (old)
            old_hull3_v_to_h(E, H, G, NULL);
        else if (_wc_hull3_v_to_h(E, H, G, NULL, err) != WC_OK)
        {
            fprintf(stderr, "bench-cone: %s\n", err->message);
            exit(3);
        }
        reps++;
        t = wcbench_now() - t0;
    }
    while (t < budget);
    *facets = fmpq_mat_nrows(H);
    fmpq_mat_clear(E);
    fmpq_mat_clear(H);
    wc_error_clear(err);
    return t / reps;
}

static void
conversions(double budget)
{
    static const slong ks[] = { 1000, 10000, 100000 };
    flint_rand_t st;
    fmpq_mat_t G;
    double last_old = 0;
    slong i, kprev = 0;

    flint_randinit(st);
    fmpq_mat_init(G, 0, 3);
    printf("3-D conversion V -> H of k random pointed generators (facets "
           "found), mean ms:\n");
    printf("%7s  %7s  %12s  %12s  %9s\n", "k", "facets", "fan ms",
           "old ms", "old/fan");
    for (i = 0; i < (slong) (sizeof ks / sizeof ks[0]); i++)
    {
        slong k = ks[i], mf, mo;
        double tf, to = -1;

        random_generators(G, k, st);
        tf = time_conversion(G, 0, budget, &mf);
        /* The old kernel is about quadratic: only where it stays under
           about 2 s.  */
        if (i == 0 || last_old * ((double) k / kprev) * ((double) k / kprev)
            < 2.0)
        {
            to = time_conversion(G, 1, budget, &mo);
            if (mo < mf)
            {
                fprintf(stderr, "bench-cone: the kernels disagree\n");
                exit(3);
            }
            last_old = to;
            kprev = k;
        }
        if (to >= 0)
            printf("%7ld  %7ld  %12.3f  %12.3f  %9.1f\n", (long) k, (long) mf,
                   1e3 * tf, 1e3 * to, to / tf);
        else
            printf("%7ld  %7ld  %12.3f  %12s  %9s\n", (long) k, (long) mf,
                   1e3 * tf, "-", "-");
    }
    fmpq_mat_clear(G);
    flint_randclear(st);
}

/* Process CPU seconds (the machine may be shared: wall time counts the
   other jobs too).  */
static double
cpu_now(void)
{
    struct timespec t;

    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Mean CPU seconds per direct-route cone: with its fast path
   (wc_wrench_cone_direct) or the general route alone.  */
static double
time_direct(const wc_problem_t P, const char * mode, int general,
            double budget, char * json, size_t jlen)
{
    wc_error_t err;
    wc_cone_t W;
    double t0 = cpu_now(), t;
    long reps = 0;
    FILE * f;

    wc_error_init(err);
    wc_cone_init(W, 3);
    do
    {
        if ((general ? _wc_wrench_cone_direct_general(W, NULL, P, mode, err)
             : wc_wrench_cone_direct(W, NULL, P, mode, err)) != WC_OK)
        {
            fprintf(stderr, "bench-cone: %s\n", err->message);
            exit(3);
        }
        reps++;
        t = cpu_now() - t0;
    }
    while (t < budget);
    /* The answer as JSON, to check that both give the same cone.  */
    if ((f = fmemopen(json, jlen, "w")) == NULL)
        exit(3);
    wc_cone_fprint(f, W, as_json);
    fclose(f);
    json[jlen - 1] = '\0';
    wc_cone_clear(W);
    wc_error_clear(err);
    return t / reps;
}

/* The fast path of the direct route (lib/analysis/direct3.c) against the
   general direct route it short-cuts, on the problems above.  */
static void
fast_vs_general(double budget)
{
    static const slong ns[] = { 1, 2, 50 };
    static const char * pattern[] = { "l", "r", "n", "m", "s", "nsm",
                                      "nlsr" };
    static const char * names[] = { "l..l", "r..r", "n..n", "m..m", "s..s",
                                    "nsm..", "nlsr.." };
    static char ja[1 << 18], jb[1 << 18];
    char mode[51];
    slong s, m, i;

    printf("The direct route with its fast path against the general route "
           "alone,\nmean CPU time per cone (us):\n");
    printf("%4s  %-6s  %12s  %12s  %9s\n", "n", "mode", "fast us",
           "general us", "gen/fast");
    for (s = 0; s < (slong) (sizeof ns / sizeof ns[0]); s++)
        for (m = 0; m < (slong) (sizeof pattern / sizeof pattern[0]); m++)
        {
            slong n = ns[s];
            wc_problem_t P;
            double tf, tg;

            if (n == 1 && strlen(pattern[m]) > 1)
                continue;               /* the same one letter again */
            for (i = 0; i < n; i++)
                mode[i] = pattern[m][i % strlen(pattern[m])];
            mode[n] = '\0';
            wc_problem_init(P);
            wcbench_cone_problem(P, n);
            tf = time_direct(P, mode, 0, budget, ja, sizeof ja);
            tg = time_direct(P, mode, 1, budget, jb, sizeof jb);
            if (strcmp(ja, jb) != 0)
            {
                fprintf(stderr, "bench-cone: the routes differ at n=%ld, "
                        "mode %s\n", (long) n, mode);
                exit(4);
            }
            printf("%4ld  %-6s  %12.2f  %12.2f  %9.1f\n", (long) n,
                   n == 1 ? mode : names[m], 1e6 * tf, 1e6 * tg, tg / tf);
            wc_problem_clear(P);
        }
}

int
main(int argc, char ** argv)
{
    slong maxn = argc > 1 ? atol(argv[1]) : 8, n, m;
    double budget = argc > 2 ? atof(argv[2]) : 0.2, ratio6 = 0;
    static const slong big[] = { 12, 25, 50, 100, 200, 500, 1000 };
    double xs[sizeof big / sizeof big[0]], ys[sizeof big / sizeof big[0]];
    slong np = 0;
    char * mode = malloc(1001);

    wc_init();
    printf("One wrench cone, mean time per cone (ms); exact GMP arithmetic.\n");
    printf("%4s  %-6s  %12s  %12s  %9s  %s\n", "n", "mode", "direct ms",
           "paper ms", "paper/dir", "cone");
    for (n = 1; n <= maxn; n++)
    {
        double sd = 0, sp = 0;

        for (m = 0; m < 2; m++)
        {
            wc_problem_t P;
            double td, tp;
            int ed, ep;

            memset(mode, m == 0 ? 'l' : 'n', n);
            mode[n] = '\0';
            wc_problem_init(P);
            wcbench_cone_problem(P, n);
            td = time_cone(P, mode, WC_METHOD_DIRECT, budget, &ed);
            tp = time_cone(P, mode, WC_METHOD_PAPER, budget, &ep);
            if (ed != ep)
            {
                fprintf(stderr, "bench-cone: routes disagree on emptiness\n");
                return 3;
            }
            printf("%4ld  %-6.6s  %12.4f  %12.4f  %9.1f  %s\n", (long) n,
                   n <= 6 ? mode : (m == 0 ? "l..l" : "n..n"), 1e3 * td,
                   1e3 * tp, tp / td, ed ? "empty" : "nonempty");
            sd += td;
            sp += tp;
            wc_problem_clear(P);
        }
        if (n == 6)
            ratio6 = sp / sd;
    }
    for (m = 0; m < (slong) (sizeof big / sizeof big[0]); m++)
    {
        wc_problem_t P;
        double td;
        int ed;

        n = big[m];
        memset(mode, 'n', n);
        mode[n] = '\0';
        wc_problem_init(P);
        wcbench_cone_problem(P, n);
        td = time_cone(P, mode, WC_METHOD_DIRECT, budget, &ed);
        printf("%4ld  %-6s  %12.4f  %12s  %9s  %s\n", (long) n, "n..n",
               1e3 * td, "-", "-", ed ? "empty" : "nonempty");
        if (n >= 50)
        {
            xs[np] = (double) n;
            ys[np++] = td;
        }
        wc_problem_clear(P);
    }
    printf("growth exponent of the direct route, n..n, n = 50..1000 "
           "(least-squares slope of log time vs log n): %.2f\n",
           wcbench_slope(xs, ys, np));
    {
        /* Degenerate: 200 collinear fixels with parallel normals, so that
           many generators of -J D_x are coplanar.  */
        wc_problem_t P;
        char * big;
        double td;
        int ed;

        n = 200;
        wc_problem_init(P);
        fmpq_set_si(P->mu_s, 1, 5);
        fmpq_set_si(P->mu_k, 1, 5);
        for (m = 0; m < n; m++)
        {
            wc_fixel_struct * f = wc_problem_add_fixel(P);

            fmpq_set_si(f->point + 0, m, 1);
            fmpq_set_si(f->normal + 1, 1, 1);
        }
        big = malloc(n + 1);
        memset(big, 'n', n);
        big[n] = '\0';
        td = time_cone(P, big, WC_METHOD_DIRECT, budget, &ed);
        printf("%4ld  %-6s  %12.4f  %12s  %9s  %s, collinear fixels\n",
               (long) n, "n..n", 1e3 * td, "-", "-",
               ed ? "empty" : "nonempty");
        free(big);
        wc_problem_clear(P);
    }
    conversions(budget);
    fast_vs_general(budget);
    if (maxn >= 6)
        printf("direct vs paper at n=6: %.1f x\n", ratio6);
    free(mode);
    flint_cleanup_master();
    return 0;
}
