/* rng.c -- the seeded generator and the draws every layout uses.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Our own splitmix64 (Steele, Lea and Flood, 2014), turned into integers
   by rejection: never rand(), floating point or anything that differs
   between platforms.  */

#include "core/randgen.h"

static const slong MUS[][2] = {{0, 1}, {1, 10}, {1, 5}, {1, 2}, {1, 1},
                               {2, 1}};
static const slong NORMAL_SCALES[][2] = {{2, 1}, {3, 1}, {1, 2}, {3, 2},
                                         {1, 3}};
/* The edge parameters of a polygon's fixels.  */
const slong _wc_edge_params[7][2] = {{1, 2}, {1, 3}, {2, 3}, {1, 4},
                                     {3, 4}, {1, 5}, {2, 5}};

static uint64_t
rng_next(wc_rng * r)
{
    uint64_t z = (r->s += UINT64_C(0x9e3779b97f4a7c15));

    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

/* Uniform in [lo, hi], lo <= hi, the span well below 2^63.  The lowest
   2^64 mod span words are rejected, so every value is equally likely.  */
slong
_wc_rng_int(wc_rng * r, slong lo, slong hi)
{
    uint64_t span = (uint64_t) (hi - lo) + 1, threshold, x;

    threshold = (0 - span) % span;
    do
        x = rng_next(r);
    while (x < threshold);
    return lo + (slong) (x % span);
}

/* 1 with probability num/den.  */
int
_wc_rng_chance(wc_rng * r, slong num, slong den)
{
    return _wc_rng_int(r, 0, den - 1) < num;
}

/* x := one of the len fractions tab[k] = {num, den}, uniformly.  */
void
_wc_rng_pick(fmpq_t x, wc_rng * r, const slong (*tab)[2], slong len)
{
    slong k = _wc_rng_int(r, 0, len - 1);

    fmpq_set_si(x, tab[k][0], (ulong) tab[k][1]);
}

/* a/b with a in [-lim, lim], b in {1, 2, 3}.  */
void
_wc_random_coord(fmpq_t x, wc_rng * r, slong lim)
{
    slong a, b;

    a = _wc_rng_int(r, -lim, lim);
    b = _wc_rng_int(r, 1, 3);
    fmpq_set_si(x, a, (ulong) b);
}

/* A point without a shape; widen > 0 after collisions.  */
void
_wc_random_point(fmpq * p, wc_rng * r, slong widen)
{
    _wc_random_coord(p + 0, r, 4 + widen);
    _wc_random_coord(p + 1, r, 4 + widen);
}

/* A nonzero integer vector with entries in [-3, 3], sometimes scaled.  */
void
_wc_random_normal(fmpq * d, wc_rng * r)
{
    fmpq_t s;

    do
    {
        fmpq_set_si(d + 0, _wc_rng_int(r, -3, 3), 1);
        fmpq_set_si(d + 1, _wc_rng_int(r, -3, 3), 1);
    }
    while (_wc_qvec2_is_zero(d));
    if (_wc_rng_chance(r, 1, 3))
    {
        fmpq_init(s);
        PICK(s, r, NORMAL_SCALES);
        _wc_qvec2_scale(d, d, s);
        fmpq_clear(s);
    }
}

/* Turn d round, with probability 4/5, when it points away from the
   centre of mass o as seen from p (so that most fixels push into the
   part).  */
void
_wc_random_face_com(fmpq * d, wc_rng * r, const fmpq * p, const fmpq * o)
{
    wc_qvec2 w;

    _wc_qvec2_init(&w);
    _wc_qvec2_sub(w.v, o, p);
    if (_wc_qvec2_dot_sgn(d, w.v) < 0 && _wc_rng_chance(r, 4, 5))
        _wc_qvec2_neg(d, d);
    _wc_qvec2_clear(&w);
}

void
_wc_random_mu(fmpq_t mu_s, fmpq_t mu_k, wc_rng * r)
{
    slong k;

    PICK(mu_s, r, MUS);
    k = _wc_rng_int(r, 0, 3);
    if (k <= 1)
        fmpq_set(mu_k, mu_s);
    else if (k == 2)
        _wc_fmpq_div_si(mu_k, mu_s, 2);
    else
        PICK(mu_k, r, MUS);
}

