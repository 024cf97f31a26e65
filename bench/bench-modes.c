/* bench-modes.c -- time wc_modes_enumerate (the faces of the arrangement
   of the planes J_k . nu = 0 inside the non-penetration cone) against the
   walk of the whole arrangement it replaced (tests/old-modes.c) and
   against brute force over the 4^n mode strings.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Usage: bench-modes [SECONDS_PER_CELL] [MAXN_BRUTE] [MAXN_WALK]
   Problems: n touching fixels at distinct rational points of the unit
   circle, every normal the inward radial direction tilted by a different
   rational amount, so that the normal lines do not meet in one point and
   the 2n planes are in general position (checked up to n = 100: no three
   columns of J are linearly dependent; the check is O(n^3)).  Each
   wc_modes_enumerate cell is the mean over repeated runs of at least
   SECONDS_PER_CELL (default 0.2 s); the whole-arrangement walk runs up
   to MAXN_WALK (default 500) fixels and brute force (tests/ref-kin.c: one
   exact LP per string) up to MAXN_BRUTE (default 8), each repeated only
   while shorter than the budget.  Where they run, their lists must be
   equal (and the walk's witnesses too; exit 3 otherwise).  Ratios
   measured in this one process are the numbers to compare, not the
   absolute times.  Beyond WC_MODES_MAX_FIXELS the walk is called
   directly (_wc_modes_walk); sizes stop after a call of over 5 s.  The last lines are the growth exponents and "modes
   speed-up over brute force at n=8: X x".  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <flint/flint.h>
#include <flint/fmpz.h>
#include <flint/fmpq.h>

#include "wrenchcone.h"
#include "benchutil.h"
#include "core/randgen.h"
#include "analysis/kinematics.h"
#include "analysis/modeswalk.h"
#include "ref-kin.h"
#include "old-modes.h"

/* Fixel k: t = (k + 1) / (n - k + 1), the circle point
   ((1 - t^2), 2 t) / (1 + t^2), at an angle in (0, pi) increasing with k:
   all on the upper half, so that the part can still move (down, and
   rolling) and the list of modes grows with n instead of collapsing to
   n..n as it would with the part held all round.  The normal is
   -p + c_k p^perp with c_k = (-1)^k / (k + 3).  */
static void
make_problem(wc_problem_t P, slong n)
{
    fmpq_t t, c;
    slong k;

    fmpq_init(t);
    fmpq_init(c);
    fmpq_set_si(P->com + 0, 1, 7);
    fmpq_set_si(P->com + 1, -1, 9);
    for (k = 0; k < n; k++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);
        fmpq * p = f->point, * d = f->normal;

        fmpq_set_si(t, k + 1, (ulong) (n - k + 1));
        _wc_unit_circle_point(p, t);
        /* d = -p + c (-p_y, p_x) */
        fmpq_set_si(c, k % 2 ? -1 : 1, (ulong) (k + 3));
        fmpq_mul(d + 0, c, p + 1);
        fmpq_add(d + 0, d + 0, p + 0);
        fmpq_neg(d + 0, d + 0);
        fmpq_mul(d + 1, c, p + 0);
        fmpq_sub(d + 1, d + 1, p + 1);
        f->state = WC_TOUCHING;
    }
    fmpq_clear(t);
    fmpq_clear(c);
}

/* 1 when no three of the 2n columns of J (read from the constraint rows
   of the mode l..l, which are J_in and J_it up to positive scaling) are
   linearly dependent: the arrangement is in general position.  */
static int
general_position(const wc_problem_t P)
{
    slong n = P->n, m, a, b, c;
    char * mode = malloc(n + 1);
    fmpz_mat_t rows;
    wc_relation * rel = NULL;
    wc_error_t err;
    fmpz_t d, x;
    int ok = 1;

    memset(mode, 'l', n);
    mode[n] = '\0';
    fmpz_mat_init(rows, 0, 3);
    wc_error_init(err);
    fmpz_init(d);
    fmpz_init(x);
    if (wc_mode_constraints(rows, &rel, P, mode, err) != WC_OK)
        ok = 0;
    m = fmpz_mat_nrows(rows);
    for (a = 0; a < m && ok; a++)
        for (b = a + 1; b < m && ok; b++)
        {
            const fmpz * u = rows->rows[a], * v = rows->rows[b];
            fmpz cr[3];

            /* u x v, then its dot with every later row */
            fmpz_init(cr + 0);
            fmpz_init(cr + 1);
            fmpz_init(cr + 2);
            fmpz_mul(cr + 0, u + 1, v + 2);
            fmpz_submul(cr + 0, u + 2, v + 1);
            fmpz_mul(cr + 1, u + 2, v + 0);
            fmpz_submul(cr + 1, u + 0, v + 2);
            fmpz_mul(cr + 2, u + 0, v + 1);
            fmpz_submul(cr + 2, u + 1, v + 0);
            if (fmpz_is_zero(cr + 0) && fmpz_is_zero(cr + 1)
                && fmpz_is_zero(cr + 2))
                ok = 0;
            for (c = b + 1; c < m && ok; c++)
            {
                const fmpz * w = rows->rows[c];

                fmpz_mul(d, cr + 0, w + 0);
                fmpz_mul(x, cr + 1, w + 1);
                fmpz_add(d, d, x);
                fmpz_mul(x, cr + 2, w + 2);
                fmpz_add(d, d, x);
                ok = !fmpz_is_zero(d);
            }
            fmpz_clear(cr + 0);
            fmpz_clear(cr + 1);
            fmpz_clear(cr + 2);
        }
    fmpz_clear(d);
    fmpz_clear(x);
    free(rel);
    fmpz_mat_clear(rows);
    wc_error_clear(err);
    free(mode);
    return ok;
}

/* Mean seconds per wc_modes_enumerate; the last result stays in M.  */
static double
time_enumerate(wc_modes_t M, const wc_problem_t P, double budget)
{
    wc_error_t err;
    double t0 = wcbench_now(), t;
    long reps = 0;

    wc_error_init(err);
    do
    {
        /* beyond the command's limit, the walk itself (the problem is
           valid by construction) */
        if ((P->n <= WC_MODES_MAX_FIXELS ? wc_modes_enumerate(M, P, err)
             : _wc_modes_walk(M, P, err)) != WC_OK)
        {
            fprintf(stderr, "bench-modes: %s\n",
                    err->message ? err->message : "wc_modes_enumerate failed");
            exit(3);
        }
        reps++;
        t = wcbench_now() - t0;
    }
    while (t < budget);
    wc_error_clear(err);
    return t / reps;
}

/* Mean seconds per walk of the whole arrangement; its list must be M's,
   witnesses included.  */
static double
time_walk(const wc_modes_t M, const wc_problem_t P, double budget)
{
    wc_modes_t R;
    wc_error_t err;
    double t0 = wcbench_now(), t;
    long reps = 0;
    slong i;

    wc_modes_init(R);
    wc_error_init(err);
    do
    {
        if (old_modes_walk(R, P, err) != WC_OK)
        {
            fprintf(stderr, "bench-modes: the whole-arrangement walk "
                    "failed\n");
            exit(3);
        }
        reps++;
        t = wcbench_now() - t0;
    }
    while (t < budget);
    if (R->count != M->count)
    {
        fprintf(stderr, "bench-modes: n=%ld: %ld modes, the whole walk "
                "%ld\n", (long) P->n, (long) M->count, (long) R->count);
        exit(3);
    }
    for (i = 0; i < M->count; i++)
        if (strcmp(R->modes[i], M->modes[i]) != 0
            || !_fmpz_vec_equal(R->witness->rows[i], M->witness->rows[i],
                                3))
        {
            fprintf(stderr, "bench-modes: n=%ld: the whole walk differs "
                    "at %s\n", (long) P->n, M->modes[i]);
            exit(3);
        }
    wc_modes_clear(R);
    wc_error_clear(err);
    return t / reps;
}

/* Mean seconds per brute force; the list of the last run is returned.  */
static double
time_brute(char *** modes, slong * count, const wc_problem_t P,
           double budget)
{
    double t0 = wcbench_now(), t;
    long reps = 0;

    *modes = NULL;
    *count = 0;
    do
    {
        ref_modes_free(*modes, *count);
        if (ref_modes_bruteforce(modes, count, P) != 0)
        {
            fprintf(stderr, "bench-modes: the brute-force LP failed\n");
            exit(3);
        }
        reps++;
        t = wcbench_now() - t0;
    }
    while (t < budget);
    return t / reps;
}

int
main(int argc, char ** argv)
{
    static const slong sizes[] = { 5, 6, 7, 8, 10, 20, 50, 100, 200, 500,
                                   1000, 2000, 5000, 10000 };
    const slong nsizes = (slong) (sizeof sizes / sizeof sizes[0]);
    double budget = argc > 1 ? atof(argv[1]) : 0.2;
    slong maxbrute = argc > 2 ? atol(argv[2]) : 8;
    slong maxwalk = argc > 3 ? atol(argv[3]) : 500;
    double xs[16], ys[16], speedup8 = 0;
    slong npts = 0, first1000 = -1, s, i;

    if (budget <= 0 || maxbrute < 0 || maxwalk < 0)
    {
        fprintf(stderr, "usage: bench-modes [SECONDS_PER_CELL] "
                "[MAXN_BRUTE] [MAXN_WALK]\n");
        return 2;
    }
    wc_init();
    printf("Kinematically feasible modes of n touching fixels in general "
           "position:\nwc_modes_enumerate (faces inside the non-penetration "
           "cone) vs the walk of the\nwhole arrangement of the 2n planes "
           "(tests/old-modes.c) vs brute force (one exact LP per string).\n");
    printf("%5s  %6s  %12s  %13s  %8s  %14s  %9s  %s\n", "n", "modes",
           "enumerate ms", "whole walk ms", "walk/enu", "brute force ms",
           "brute/enu", "planes");
    for (s = 0; s < nsizes; s++)
    {
        slong n = sizes[s];
        wc_problem_t P;
        wc_modes_t M;
        double te, tw = 0, tb = 0;
        char wcol[32], rcol[32], bcol[32], scol[32];
        int gp = -1;

        wc_problem_init(P);
        wc_modes_init(M);
        make_problem(P, n);
        if (n <= 100)
            gp = general_position(P);
        te = time_enumerate(M, P, budget);
        strcpy(wcol, "-");
        strcpy(rcol, "-");
        strcpy(bcol, "-");
        strcpy(scol, "-");
        if (n <= maxwalk)
        {
            tw = time_walk(M, P, budget);
            snprintf(wcol, sizeof wcol, "%.3f", 1e3 * tw);
            snprintf(rcol, sizeof rcol, "%.1fx", tw / te);
        }
        if (n <= maxbrute)
        {
            char ** list;
            slong count;

            tb = time_brute(&list, &count, P, budget);
            if (count != M->count)
            {
                fprintf(stderr, "bench-modes: n=%ld: %ld modes enumerated, "
                        "%ld by brute force\n", (long) n, (long) M->count,
                        (long) count);
                return 3;
            }
            for (i = 0; i < count; i++)
                if (strcmp(list[i], M->modes[i]) != 0)
                {
                    fprintf(stderr, "bench-modes: n=%ld: lists differ at "
                            "%s / %s\n", (long) n, M->modes[i], list[i]);
                    return 3;
                }
            ref_modes_free(list, count);
            snprintf(bcol, sizeof bcol, "%.1f", 1e3 * tb);
            snprintf(scol, sizeof scol, "%.0fx", tb / te);
            if (n == 8)
                speedup8 = tb / te;
        }
        printf("%5ld  %6ld  %12.3f  %13s  %8s  %14s  %9s  %s\n", (long) n,
               (long) M->count, 1e3 * te, wcol, rcol, bcol, scol,
               gp < 0 ? "unchecked" : gp ? "general" : "DEGENERATE");
        fflush(stdout);
        if (n >= 10)
        {
            if (n >= 1000 && first1000 < 0)
                first1000 = npts;
            xs[npts] = (double) n;
            ys[npts] = te;
            npts++;
        }
        wc_modes_clear(M);
        wc_problem_clear(P);
        if (te > 5.0 && s + 1 < nsizes)
        {
            printf("(stopped: over 5 s per call; the cone conversion "
                   "dominates)\n");
            break;
        }
    }
    printf("growth exponent of enumerate time (least-squares slope of log "
           "time vs log n): n = 10..%ld: %.2f", (long) xs[npts - 1],
           wcbench_slope(xs, ys, npts));
    if (first1000 >= 0 && npts - first1000 >= 2)
        printf("; n = 1000..%ld: %.2f", (long) xs[npts - 1],
               wcbench_slope(xs + first1000, ys + first1000,
                             npts - first1000));
    printf("\n");
    if (maxbrute >= 8)
        printf("modes speed-up over brute force at n=8: %.0f x\n", speedup8);
    flint_cleanup_master();
    return 0;
}
