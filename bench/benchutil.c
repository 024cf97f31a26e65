/* benchutil.c -- what the benchmarks share (benchutil.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <flint/fmpq.h>

#include "benchutil.h"
#include "core/randgen.h"

double
wcbench_now(void)
{
    struct timespec t;

    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

void
wcbench_die(const char * prog, const char * what, const wc_error_t err)
{
    fprintf(stderr, "%s: %s: %s\n", prog, what,
            err->message ? err->message : "failed");
    exit(3);
}

void
wcbench_circle_fixel(wc_problem_t P, slong a, slong b, int sy,
                     wc_fixel_state state)
{
    wc_fixel_struct * f = wc_problem_add_fixel(P);
    fmpq_t s;

    fmpq_init(s);
    fmpq_set_si(s, sy * a, (ulong) b);  /* the point at -s is (x, -y) */
    _wc_unit_circle_point(f->point, s);
    fmpq_neg(f->normal + 0, f->point + 0);
    fmpq_neg(f->normal + 1, f->point + 1);
    f->state = state;
    fmpq_clear(s);
}

/* Rational points on the unit circle from Pythagorean parametrisation,
   t = (k + 1) / (k + 4): ((1 - t^2) / (1 + t^2), 2t / (1 + t^2)); the
   inward normal is minus the point.  Rotated by k quarter turns so that
   the fixels surround the part.  */
void
wcbench_cone_problem(wc_problem_t P, slong n)
{
    slong k;

    fmpq_set_si(P->mu_s, 1, 5);
    fmpq_set_si(P->mu_k, 1, 10);
    fmpq_set_si(P->com + 0, 1, 7);
    fmpq_set_si(P->com + 1, -1, 9);
    fmpq_set_si(P->mass, 3, 2);
    fmpq_set_si(P->inertia, 2, 3);
    for (k = 0; k < n; k++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);
        fmpq_t t, den, x, y;
        slong q = k % 4;

        fmpq_init(t);
        fmpq_init(den);
        fmpq_init(x);
        fmpq_init(y);
        fmpq_set_si(t, k + 1, k + 4);
        fmpq_mul(den, t, t);
        fmpq_add_si(den, den, 1);
        fmpq_mul(x, t, t);
        fmpq_sub_si(x, x, 1);
        fmpq_neg(x, x);
        fmpq_div(x, x, den);
        fmpq_mul_si(y, t, 2);
        fmpq_div(y, y, den);
        /* rotate by q quarter turns */
        while (q-- > 0)
        {
            fmpq_swap(x, y);
            fmpq_neg(x, x);
        }
        fmpq_set(f->point + 0, x);
        fmpq_set(f->point + 1, y);
        fmpq_neg(f->normal + 0, x);
        fmpq_neg(f->normal + 1, y);
        f->state = WC_TOUCHING;
        fmpq_clear(t);
        fmpq_clear(den);
        fmpq_clear(x);
        fmpq_clear(y);
    }
}

double
wcbench_slope(const double * x, const double * y, slong len)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    slong i;

    if (len < 2)
        return NAN;
    for (i = 0; i < len; i++)
    {
        double lx = log(x[i]), ly = log(y[i]);

        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    if (len * sxx - sx * sx == 0)
        return NAN;
    return (len * sxy - sx * sy) / (len * sxx - sx * sx);
}

void
wcbench_random_problem(wc_problem_t P, slong n, const char * prog)
{
    wc_random_options opt;
    wc_error_t err;

    wc_random_options_init(&opt);
    wc_error_init(err);
    opt.fixels = n;
    opt.seed = 1;
    if (wc_random_problem(P, &opt, err) != WC_OK)
        wcbench_die(prog, "wc_random_problem", err);
    wc_error_clear(err);
    wc_random_options_clear(&opt);
}
