/* bench-cert.c -- what a certified set costs: computing the strongly
   stable set or a plan's goal set, writing its certificate, checking it,
   and the certificate's size.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Usage: bench-cert [quick]
   Problems, deterministic:
   cradle   n touching fixels on the lower half of the unit circle,
            normals through the centre of mass, friction 1/3 (the
            hard case of bench-stability: many moving faces);
   random   wc_random_problem with n fixels and seed 1 (touching and near
            mixed).
   Stability for n = 2 .. 12, plans for n = 2 .. 6 (quick: up to 8 and 4).
   Each figure is the best of three runs.  The ratios certify/compute and
   check/compute, measured in this one process, are the numbers to read;
   the targets are certify <= 5x compute and check < compute.  A
   certificate that does not hold prints FAIL and the exit status is 3.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <flint/flint.h>
#include <flint/fmpq.h>

#include "wrenchcone.h"
#include "benchutil.h"

static void
make_problem(wc_problem_t P, int cradle, slong n)
{
    slong k;

    if (!cradle)
    {
        wcbench_random_problem(P, n, "bench-cert");
        return;
    }
    fmpq_set_si(P->mu_s, 1, 3);
    fmpq_set_si(P->mu_k, 1, 3);
    for (k = 0; k < n; k++)
        wcbench_circle_fixel(P, k + 1, n - k, -1, WC_TOUCHING);
}

/* The three timings of one problem, best of three, and the size.  */
typedef struct
{
    double compute, certify, check;
    size_t bytes;
    int holds;
}
timing;

static void
measure(timing * T, const wc_problem_t P, int plan)
{
    int rep;

    T->compute = T->certify = T->check = 1e300;
    T->holds = 1;
    for (rep = 0; rep < 3; rep++)
    {
        wc_stability_t S;
        wc_plan_t R;
        wc_error_t err;
        char * text = NULL, * reason = NULL, * summary = NULL;
        size_t len = 0;
        FILE * f;
        double t0, t1, t2, t3;
        int holds = 0;

        wc_stability_init(S);
        wc_plan_init(R);
        wc_error_init(err);
        t0 = wcbench_now();
        if ((plan ? wc_plan(R, P, 0, err) : wc_stability(S, P, err))
            != WC_OK)
            wcbench_die("bench-cert", plan ? "wc_plan" : "wc_stability", err);
        t1 = wcbench_now();
        f = open_memstream(&text, &len);
        if (f == NULL
            || (plan ? wc_plan_certificate_fprint(f, P, R, err)
                : wc_stability_certificate_fprint(f, P, S, err)) != WC_OK)
            wcbench_die("bench-cert", "certificate", err);
        fclose(f);
        t2 = wcbench_now();
        if (wc_verify(&holds, &reason, &summary, text, len, "<cert>", err)
            != WC_OK)
            wcbench_die("bench-cert", "wc_verify", err);
        t3 = wcbench_now();
        T->holds &= holds;
        T->bytes = len;
        if (t1 - t0 < T->compute)
            T->compute = t1 - t0;
        if (t2 - t1 < T->certify)
            T->certify = t2 - t1;
        if (t3 - t2 < T->check)
            T->check = t3 - t2;
        free(text);
        free(reason);
        free(summary);
        wc_stability_clear(S);
        wc_plan_clear(R);
        wc_error_clear(err);
    }
}

static int
table(int plan, int cradle, slong nmax)
{
    slong n;
    int bad = 0;

    printf("\n%s, %s problems\n", plan ? "plan goal set" : "strongly stable "
           "set", cradle ? "cradle" : "random");
    printf("%3s %11s %11s %11s %9s %9s %11s\n", "n", "compute_ms",
           "certify_ms", "check_ms", "cert/cmp", "chk/cmp", "bytes");
    for (n = 2; n <= nmax; n++)
    {
        wc_problem_t P;
        timing T;

        wc_problem_init(P);
        make_problem(P, cradle, n);
        measure(&T, P, plan);
        printf("%3ld %11.2f %11.2f %11.2f %9.2f %9.2f %11lu%s\n", (long) n,
               1e3 * T.compute, 1e3 * T.certify, 1e3 * T.check,
               T.certify / T.compute, T.check / T.compute,
               (unsigned long) T.bytes, T.holds ? "" : "  FAIL");
        bad |= !T.holds;
        wc_problem_clear(P);
        fflush(stdout);
    }
    return bad;
}

int
main(int argc, char ** argv)
{
    int quick = argc > 1 && strcmp(argv[1], "quick") == 0, bad = 0;

    printf("bench-cert: time to compute a set, to write its certificate "
           "and to check it\n(best of three, milliseconds), with the "
           "ratios to computing it and the certificate's size.\n");
    bad |= table(0, 1, quick ? 8 : 12);
    bad |= table(0, 0, quick ? 8 : 12);
    bad |= table(1, 0, quick ? 4 : 6);
    return bad ? 3 : 0;
}
