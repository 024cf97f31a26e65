/* bench-cone.c -- time one mode cone by each route, n = 1 .. 8 fixels
   (the paper's Table 4), and the direct route alone up to n = 50.

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

int
main(int argc, char ** argv)
{
    slong maxn = argc > 1 ? atol(argv[1]) : 8, n, m;
    double budget = argc > 2 ? atof(argv[2]) : 0.2, ratio6 = 0;
    static const slong big[] = { 12, 25, 50 };
    char mode[64];

    wc_init();
    printf("One wrench cone, mean time per cone (ms); exact GMP arithmetic.\n");
    printf("%3s  %-6s  %12s  %12s  %9s  %s\n", "n", "mode", "direct ms",
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
            printf("%3ld  %-6.6s  %12.4f  %12.4f  %9.1f  %s\n", (long) n,
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
        printf("%3ld  %-6s  %12.4f  %12s  %9s  %s\n", (long) n, "n..n",
               1e3 * td, "-", "-", ed ? "empty" : "nonempty");
        wc_problem_clear(P);
    }
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
        printf("%3ld  %-6s  %12.4f  %12s  %9s  %s, collinear fixels\n",
               (long) n, "n..n", 1e3 * td, "-", "-",
               ed ? "empty" : "nonempty");
        free(big);
        wc_problem_clear(P);
    }
    if (maxn >= 6)
        printf("direct vs paper at n=6: %.1f x\n", ratio6);
    flint_cleanup_master();
    return 0;
}
