/* qvec2.c -- exact plane vectors for the random generator.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <flint/fmpz.h>

#include "core/randgen.h"

void
_wc_qvec2_init(wc_qvec2 * a)
{
    fmpq_init(a->v + 0);
    fmpq_init(a->v + 1);
}

void
_wc_qvec2_clear(wc_qvec2 * a)
{
    fmpq_clear(a->v + 0);
    fmpq_clear(a->v + 1);
}

void
_wc_qvec2_set(fmpq * d, const fmpq * a)
{
    fmpq_set(d + 0, a + 0);
    fmpq_set(d + 1, a + 1);
}

/* d = a + s b (d may alias a or b).  */
void
_wc_qvec2_addmul(fmpq * d, const fmpq * a, const fmpq_t s, const fmpq * b)
{
    fmpq_t x, y;

    fmpq_init(x);
    fmpq_init(y);
    fmpq_mul(x, s, b + 0);
    fmpq_mul(y, s, b + 1);
    fmpq_add(d + 0, a + 0, x);
    fmpq_add(d + 1, a + 1, y);
    fmpq_clear(x);
    fmpq_clear(y);
}

void
_wc_qvec2_scale(fmpq * d, const fmpq * a, const fmpq_t s)
{
    fmpq_mul(d + 0, a + 0, s);
    fmpq_mul(d + 1, a + 1, s);
}

void
_wc_qvec2_neg(fmpq * d, const fmpq * a)
{
    fmpq_neg(d + 0, a + 0);
    fmpq_neg(d + 1, a + 1);
}

void
_wc_qvec2_sub(fmpq * d, const fmpq * a, const fmpq * b)
{
    fmpq_sub(d + 0, a + 0, b + 0);
    fmpq_sub(d + 1, a + 1, b + 1);
}

/* d = a turned by +90 degrees (d must not alias a).  */
void
_wc_qvec2_perp(fmpq * d, const fmpq * a)
{
    fmpq_neg(d + 0, a + 1);
    fmpq_set(d + 1, a + 0);
}

static int
vec2_equal(const fmpq * a, const fmpq * b)
{
    return fmpq_equal(a + 0, b + 0) && fmpq_equal(a + 1, b + 1);
}

int
_wc_qvec2_is_zero(const fmpq * a)
{
    return fmpq_is_zero(a + 0) && fmpq_is_zero(a + 1);
}

/* sign of a . b  */
int
_wc_qvec2_dot_sgn(const fmpq * a, const fmpq * b)
{
    fmpq_t x, y;
    int s;

    fmpq_init(x);
    fmpq_init(y);
    fmpq_mul(x, a + 0, b + 0);
    fmpq_mul(y, a + 1, b + 1);
    fmpq_add(x, x, y);
    s = fmpq_sgn(x);
    fmpq_clear(x);
    fmpq_clear(y);
    return s;
}

/* x = y / k, k != 0 (FLINT 2.9 has no fmpq_div_si).  */
void
_wc_fmpq_div_si(fmpq_t x, const fmpq_t y, slong k)
{
    fmpz_t d;

    fmpz_init_set_si(d, k);
    fmpq_div_fmpz(x, y, d);
    fmpz_clear(d);
}

/* 1 when a and b point the same way (a x b = 0 and a . b > 0).  */
static int
same_direction(const fmpq * a, const fmpq * b)
{
    fmpq_t x, y;
    int par;

    fmpq_init(x);
    fmpq_init(y);
    fmpq_mul(x, a + 0, b + 1);
    fmpq_mul(y, a + 1, b + 0);
    par = fmpq_equal(x, y);
    fmpq_clear(x);
    fmpq_clear(y);
    return par && _wc_qvec2_dot_sgn(a, b) > 0;
}

/* 1 when fixel i repeats the point and normal direction of an earlier
   one: an input error (wrenchcone(5)) that the generator must never make.  */
int
_wc_random_repeats(const wc_problem_struct * P, slong i)
{
    const wc_fixel_struct * f = P->fixels + i;
    slong j;

    for (j = 0; j < i; j++)
        if (vec2_equal(f->point, P->fixels[j].point)
            && same_direction(f->normal, P->fixels[j].normal))
            return 1;
    return 0;
}

/* The point of the unit circle with parameter t:
   ((1 - t^2), 2t) / (1 + t^2).  */
void
_wc_unit_circle_point(fmpq * p, const fmpq_t t)
{
    fmpq_t t2, den;

    fmpq_init(t2);
    fmpq_init(den);
    fmpq_mul(t2, t, t);
    fmpq_add_si(den, t2, 1);
    fmpq_sub_si(t2, t2, 1);
    fmpq_neg(t2, t2);
    fmpq_div(p + 0, t2, den);
    fmpq_mul_si(p + 1, t, 2);
    fmpq_div(p + 1, p + 1, den);
    fmpq_clear(t2);
    fmpq_clear(den);
}

/* d = a rotated by the unit vector e (complex multiplication).  d must
   not alias a or e.  */
void
_wc_qvec2_rotate(fmpq * d, const fmpq * a, const fmpq * e)
{
    fmpq_t x;

    fmpq_init(x);
    fmpq_mul(d + 0, a + 0, e + 0);
    fmpq_mul(x, a + 1, e + 1);
    fmpq_sub(d + 0, d + 0, x);
    fmpq_mul(d + 1, a + 0, e + 1);
    fmpq_mul(x, a + 1, e + 0);
    fmpq_add(d + 1, d + 1, x);
    fmpq_clear(x);
}

