/* benchutil.c -- what the benchmarks share (benchutil.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <flint/fmpq.h>

#include "benchutil.h"

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
    fmpq_t s, s2, den;

    fmpq_init(s);
    fmpq_init(s2);
    fmpq_init(den);
    fmpq_set_si(s, a, (ulong) b);
    fmpq_mul(s2, s, s);
    fmpq_add_si(den, s2, 1);
    fmpq_neg(f->point + 0, s2);
    fmpq_add_si(f->point + 0, f->point + 0, 1);
    fmpq_div(f->point + 0, f->point + 0, den);
    fmpq_mul_si(f->point + 1, s, 2 * sy);
    fmpq_div(f->point + 1, f->point + 1, den);
    fmpq_neg(f->normal + 0, f->point + 0);
    fmpq_neg(f->normal + 1, f->point + 1);
    f->state = state;
    fmpq_clear(s);
    fmpq_clear(s2);
    fmpq_clear(den);
}
