/* bench-double.c -- what exactness buys: the paper route in doubles
   (cddlib's double build) against the exact route, on random degenerate
   problems.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Usage: bench-double [PROBLEMS] [MODES_PER_PROBLEM] [plain]
   ("plain": the same without --degenerate, the control experiment)
   Problems: `wrenchcone random --fixels=K --seed=S --degenerate` for
   S = 1 .. PROBLEMS (default 1000) and K = 2 + S mod 3 (2 to 4 fixels),
   shapes cycling none / disk / polygon; modes drawn from each problem's
   Table 2 letters by a fixed rule.  For each (problem, mode) the double
   cone is compared with the exact one at tolerance 1e-9
   (wc_fcone_compare_exact): wrong emptiness, a different linear hull or
   lineality space, lost or extra rays, lost or extra facets, different
   strictness; a cddlib failure of the double build counts apart.  Times
   are summed per route in this process; the ratio is the number to read.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "wrenchcone.h"
#include "benchutil.h"

int
main(int argc, char ** argv)
{
    long problems = argc > 1 ? atol(argv[1]) : 1000;
    long per = argc > 2 ? atol(argv[2]) : 3, s, k, i;
    int degenerate = !(argc > 3 && strcmp(argv[3], "plain") == 0);
    long total = 0, differ = 0, failed = 0, count[5] = { 0, 0, 0, 0, 0 };
    double t_exact = 0, t_double = 0, t_direct = 0, t0;
    static const char * const what[5] = {
        "wrong emptiness", "linear hull or lineality differ",
        "rays lost or extra", "facets lost or extra", "strictness differs" };
    uint64_t x = 88172645463325252u;

    wc_init();
    for (s = 1; s <= problems; s++)
    {
        wc_random_options opt;
        wc_problem_t P;
        wc_error_t err;

        wc_random_options_init(&opt);
        opt.fixels = 2 + s % 3;
        opt.seed = (uint64_t) s;
        opt.degenerate = degenerate;
        opt.shape = s % 3 == 0 ? WC_SHAPE_NONE
            : s % 3 == 1 ? WC_SHAPE_DISK : WC_SHAPE_POLYGON;
        wc_problem_init(P);
        wc_error_init(err);
        if (wc_random_problem(P, &opt, err) != WC_OK)
        {
            fprintf(stderr, "bench-double: %s\n", err->message);
            return 3;
        }
        for (k = 0; k < per; k++)
        {
            char mode[8];
            wc_cone_t E, D;
            wc_fcone_t F;
            int st, diff;

            for (i = 0; i < P->n; i++)
            {
                /* xorshift: a fixed, documented draw of letters */
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                mode[i] = P->fixels[i].state == WC_TOUCHING
                    ? "slrnm"[x % 5] : "sau"[x % 3];
            }
            mode[P->n] = '\0';
            wc_cone_init(E, 3);
            wc_cone_init(D, 3);
            wc_fcone_init(F, 3);
            t0 = wcbench_now();
            st = wc_wrench_cone_paper(E, NULL, P, mode, err);
            t_exact += wcbench_now() - t0;
            if (st != WC_OK)
            {
                fprintf(stderr, "bench-double: exact route: %s\n", err->message);
                return 3;
            }
            t0 = wcbench_now();
            wc_wrench_cone_direct(D, NULL, P, mode, err);
            t_direct += wcbench_now() - t0;
            t0 = wcbench_now();
            st = wc_wrench_cone_paper_double(F, P, mode, WC_FCONE_EPS, err);
            t_double += wcbench_now() - t0;
            total++;
            if (st != WC_OK)
                failed++;
            else if ((diff = wc_fcone_compare_exact(F, E, 1e-9)) != 0)
            {
                differ++;
                for (i = 0; i < 5; i++)
                    count[i] += (diff >> i) & 1;
            }
            wc_cone_clear(E);
            wc_cone_clear(D);
            wc_fcone_clear(F);
        }
        wc_error_clear(err);
        wc_problem_clear(P);
        wc_random_options_clear(&opt);
    }
    printf("%ld random %sproblems (2-4 fixels; no shape, disk, polygon) "
           "x %ld modes = %ld cones\n", problems,
           degenerate ? "degenerate " : "non-degenerate ", per, total);
    printf("double route differs from the exact one beyond 1e-9: %ld "
           "(%.1f%%)\n", differ, 100.0 * differ / total);
    for (i = 0; i < 5; i++)
        printf("  %-34s %6ld (%.1f%%)\n", what[i], count[i],
               100.0 * count[i] / total);
    printf("double route failed inside cddlib:  %ld (%.1f%%)\n", failed,
           100.0 * failed / total);
    printf("time per cone: exact paper %.3f ms, double paper %.3f ms, "
           "exact direct %.3f ms\n", 1e3 * t_exact / total,
           1e3 * t_double / total, 1e3 * t_direct / total);
    printf("exact/double time ratio (paper route): %.1f x\n",
           t_exact / t_double);
    flint_cleanup_master();
    return 0;
}
