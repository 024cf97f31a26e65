/* bench-compare.c -- time `compare` (wc_foreign_parse and wc_compare) on
   a foreign cone of k = 1,000, 10,000 and 100,000 rays.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Usage: bench-compare [MAXK] [MAX_SECONDS]
   The exact cone: bench-cone's problem with n = 6 and the first of the
   modes l..l, nsmnsm, s..s whose cone is pointed with 3 or more rays.  The
   foreign cone, a cdd V-representation written in doubles (%.17g) as a
   float code would: the exact extreme rays, then positive combinations
   of them with pseudo-random weights (fixed seed) up to k rows -- inside
   the cone but for rounding, so that most rows are redundant and the
   verdict is "within tolerance".  A size whose time, extrapolated
   quadratically from the previous one, would exceed MAX_SECONDS (default
   120) is skipped and says so.  Wall-clock times, and the process's CPU
   time (clock(3)) of the parse alone and of parse and compare together,
   which a shared machine disturbs less.  The last line of that table is
   "compare, k=K: T s" (wall clock) for the largest k timed.

   Then the layouts that made the former 3-D kernel cubic, as exact
   integer cdd files: a wedge of the plane z = 0 times the line of e3
   (lineality 1; rows (i - k/2, 1000 + i^2 mod 997, 0)) of k = 500,
   1,000, 2,000 and 100,000 rows, and a pointed cone of 13,000 rows whose
   row farthest from the rows' sum is not extreme (most near the chart
   point (-1000, 0), three at x = 1000); CPU seconds of parse and
   compare, or the reader's refusal.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "wrenchcone.h"
#include "benchutil.h"

/* A fixed linear congruential generator: weights in (0, 1].  */
static double
weight(unsigned long long * s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return ((*s >> 11) + 1) * (1.0 / 9007199254740992.0);
}

/* The foreign cone's text: k rows around the rays of W.  */
static char *
foreign_text(const wc_cone_t W, slong k)
{
    slong r = fmpz_mat_nrows(W->rays), i, j, c;
    size_t cap = 100 * (size_t) (k + 4);
    char * t = malloc(cap), * e = t;
    unsigned long long s = 20261125;

    if (t == NULL)
        return NULL;
    e += sprintf(e, "V-representation\nbegin\n%ld 4 real\n", (long) k);
    for (i = 0; i < k; i++)
    {
        double v[3] = { 0, 0, 0 };

        for (j = 0; j < r; j++)
        {
            double w = i < r ? (i == j) : weight(&s);

            for (c = 0; c < 3; c++)
                v[c] += w * fmpz_get_d(fmpz_mat_entry(W->rays, j, c));
        }
        e += sprintf(e, "0 %.17g %.17g %.17g\n", v[0], v[1], v[2]);
    }
    sprintf(e, "end\n");
    return t;
}

/* A hostile foreign cone: a wedge times the line of e3 (k rows, the
   line first) when wedge is set, else the pointed 13,000-row cone.  */
static char *
hostile_text(slong k, int wedge)
{
    char * t = malloc(64 * (size_t) (k + 4)), * e = t;
    slong i;

    if (t == NULL)
        return NULL;
    e += sprintf(e, "V-representation\n%sbegin\n%ld 4 rational\n",
                 wedge ? "linearity 1 1\n" : "", (long) k);
    if (wedge)
        e += sprintf(e, "0 0 0 1\n");
    for (i = 0; i < k - wedge; i++)
        if (wedge)
            e += sprintf(e, "0 %ld %ld 0\n", (long) (i - k / 2),
                         (long) (1000 + (i * i) % 997));
        else if (i < k - 3)
            e += sprintf(e, "0 %ld %ld 1\n", (long) (-1000 + i % 97),
                         (long) ((i * 37) % 101 - 50));
        else
            e += sprintf(e, "0 1000 %ld 1\n", (long) ((i - (k - 2)) * 500));
    sprintf(e, "end\n");
    return t;
}

static void
hostile(const wc_cone_t W, const char * mode)
{
    static const slong sizes[] = { 500, 1000, 2000, 100000, 13000 };
    slong s;
    wc_error_t err;

    wc_error_init(err);
    printf("hostile layouts (exact integers), CPU s\n");
    printf("%-14s  %7s  %11s  %10s  %s\n", "layout", "k", "parse CPU s",
           "CPU s", "verdict");
    for (s = 0; s < 5; s++)
    {
        slong k = sizes[s];
        int wedge = s < 4;
        char * text = hostile_text(k, wedge);
        wc_foreign_t F;
        wc_comparison_t R;
        clock_t c0, c1;

        if (text == NULL)
            return;
        wc_foreign_init(F);
        wc_comparison_init(R);
        c0 = clock();
        if (wc_foreign_parse(F, text, strlen(text), "bench", err) != WC_OK)
        {
            char * m = wc_error_format(err);

            printf("%-14s  %7ld  refused: %s\n", wedge ? "wedge x line"
                   : "pointed obtuse", (long) k, m != NULL ? m : "?");
            free(m);
        }
        else
        {
            c1 = clock();
            if (wc_compare(R, W, mode, F, WC_COMPARE_TOL, err) != WC_OK)
                wcbench_die("bench-compare", "wc_compare", err);
            printf("%-14s  %7ld  %11.3f  %10.3f  %s\n", wedge ? "wedge x line"
                   : "pointed obtuse", (long) k,
                   (double) (c1 - c0) / CLOCKS_PER_SEC,
                   (double) (clock() - c0) / CLOCKS_PER_SEC,
                   R->differs == 0 ? "within tolerance" : "outside tolerance");
        }
        fflush(stdout);
        wc_comparison_clear(R);
        wc_foreign_clear(F);
        free(text);
    }
    wc_error_clear(err);
}

int
main(int argc, char ** argv)
{
    static const slong sizes[] = { 1000, 10000, 100000 };
    slong maxk = argc > 1 ? atol(argv[1]) : 100000, s, last = 0;
    double cap = argc > 2 ? atof(argv[2]) : 120, prev = 0, tlast = 0;
    wc_problem_t P;
    wc_cone_t W;
    wc_error_t err;
    static const char * modes[] = { "llllll", "nsmnsm", "ssssss" };
    char mode[7];
    slong m;

    wc_init();
    wc_error_init(err);
    wc_problem_init(P);
    wcbench_cone_problem(P, 6);
    wc_cone_init(W, 3);
    for (m = 0; m < 3; m++)
    {
        strcpy(mode, modes[m]);
        if (wc_wrench_cone_direct(W, NULL, P, mode, err) != WC_OK)
            wcbench_die("bench-compare", "wc_wrench_cone_direct", err);
        if (!W->empty && W->lineality_dim == 0
            && fmpz_mat_nrows(W->rays) >= 3)
            break;
    }
    printf("compare: the exact cone of %s (n = 6, %ld rays) against a "
           "float cone of k rows\n", mode, (long) fmpz_mat_nrows(W->rays));
    printf("%7s  %10s  %10s  %11s  %10s  %s\n", "k", "parse s",
           "compare s", "parse CPU s", "CPU s", "verdict");
    for (s = 0; s < (slong) (sizeof sizes / sizeof sizes[0]); s++)
    {
        slong k = sizes[s];
        wc_foreign_t F;
        wc_comparison_t R;
        char * text;
        double t0, t1, t2;
        clock_t c0, c1;

        if (k > maxk)
            break;
        if (prev > 0 && prev * ((double) k / sizes[s - 1])
            * ((double) k / sizes[s - 1]) > cap)
        {
            printf("%7ld  %10s  %10s  %11s  %10s  skipped: about %.0f s if "
                   "quadratic (over %.0f s)\n", (long) k, "-", "-", "-", "-",
                   prev
                   * ((double) k / sizes[s - 1]) * ((double) k / sizes[s - 1]),
                   cap);
            break;
        }
        if ((text = foreign_text(W, k)) == NULL)
            return 3;
        wc_foreign_init(F);
        wc_comparison_init(R);
        c0 = clock();
        t0 = wcbench_now();
        if (wc_foreign_parse(F, text, strlen(text), "bench", err) != WC_OK)
            wcbench_die("bench-compare", "wc_foreign_parse", err);
        t1 = wcbench_now();
        c1 = clock();
        if (wc_compare(R, W, mode, F, WC_COMPARE_TOL, err) != WC_OK)
            wcbench_die("bench-compare", "wc_compare", err);
        t2 = wcbench_now();
        printf("%7ld  %10.3f  %10.3f  %11.3f  %10.3f  %s\n", (long) k,
               t1 - t0, t2 - t1, (double) (c1 - c0) / CLOCKS_PER_SEC,
               (double) (clock() - c0) / CLOCKS_PER_SEC,
               R->differs == 0 ? "within tolerance" : "outside tolerance");
        fflush(stdout);
        prev = t2 - t0;
        last = k;
        tlast = prev;
        wc_comparison_clear(R);
        wc_foreign_clear(F);
        free(text);
    }
    if (last > 0)
        printf("compare, k=%ld: %.3f s\n", (long) last, tlast);
    hostile(W, mode);
    wc_cone_clear(W);
    wc_problem_clear(P);
    wc_error_clear(err);
    flint_cleanup_master();
    return 0;
}
