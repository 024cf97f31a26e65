/* vec3.c -- exact 3-vectors.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <flint/ulong_extras.h>
#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "exact/vec3.h"

void
_wc_zvec3_cross(fmpz * c, const fmpz * a, const fmpz * b)
{
    fmpz_mul(c + 0, a + 1, b + 2);
    fmpz_submul(c + 0, a + 2, b + 1);
    fmpz_mul(c + 1, a + 2, b + 0);
    fmpz_submul(c + 1, a + 0, b + 2);
    fmpz_mul(c + 2, a + 0, b + 1);
    fmpz_submul(c + 2, a + 1, b + 0);
}

void
_wc_qvec3_cross(fmpq * c, const fmpq * a, const fmpq * b)
{
    fmpq_mul(c + 0, a + 1, b + 2);
    fmpq_submul(c + 0, a + 2, b + 1);
    fmpq_mul(c + 1, a + 2, b + 0);
    fmpq_submul(c + 1, a + 0, b + 2);
    fmpq_mul(c + 2, a + 0, b + 1);
    fmpq_submul(c + 2, a + 1, b + 0);
}

void
_wc_zqvec3_dot(fmpq_t r, const fmpz * h, const fmpq * p)
{
    fmpq_t t;
    slong j;

    fmpq_init(t);
    fmpq_zero(r);
    for (j = 0; j < 3; j++)
    {
        fmpq_mul_fmpz(t, p + j, h + j);
        fmpq_add(r, r, t);
    }
    fmpq_clear(t);
}

int
_wc_zvec3_dot_sgn(const fmpz * a, const fmpz * b, fmpz_t t)
{
    fmpz_mul(t, a + 0, b + 0);
    fmpz_addmul(t, a + 1, b + 1);
    fmpz_addmul(t, a + 2, b + 2);
    return fmpz_sgn(t);
}

#ifdef __SIZEOF_INT128__
/* f := v, |v| < 2^127.  */
static void
set_i128(fmpz_t f, __int128 v)
{
    unsigned __int128 u = (unsigned __int128) v;

    fmpz_set_signed_uiui(f, (ulong) (u >> 64), (ulong) u);
}

#define WORDS3(a) (!COEFF_IS_MPZ((a)[0]) && !COEFF_IS_MPZ((a)[1]) \
                   && !COEFF_IS_MPZ((a)[2]))
#endif

void
_wc_zvec3_cross_fast(fmpz * c, const fmpz * a, const fmpz * b)
{
#ifdef __SIZEOF_INT128__
    /* Word entries are below 2^62 in absolute value: each product is
       below 2^124 and each difference below 2^125.  */
    if (WORDS3(a) && WORDS3(b))
    {
        set_i128(c + 0, (__int128) a[1] * b[2] - (__int128) a[2] * b[1]);
        set_i128(c + 1, (__int128) a[2] * b[0] - (__int128) a[0] * b[2]);
        set_i128(c + 2, (__int128) a[0] * b[1] - (__int128) a[1] * b[0]);
        return;
    }
#endif
    _wc_zvec3_cross(c, a, b);
}

void
_wc_zvec3_dot_fast(fmpz_t r, const fmpz * a, const fmpz * b)
{
#ifdef __SIZEOF_INT128__
    /* As in _wc_zvec3_dot_sgn_fast: the sum is below 2^126.  */
    if (WORDS3(a) && WORDS3(b))
    {
        set_i128(r, (__int128) a[0] * b[0] + (__int128) a[1] * b[1]
                 + (__int128) a[2] * b[2]);
        return;
    }
#endif
    _wc_zvec3_dot_sgn(a, b, r);
}

/* Stein's binary algorithm (shifts and subtractions) where the compiler
   counts trailing zeros.  */
ulong
_wc_gcd_ui(ulong a, ulong b)
{
#if defined(__GNUC__) && FLINT_BITS == 64
    int k;

    if (a == 0 || b == 0)
        return a | b;
    k = __builtin_ctzll(a | b);
    a >>= __builtin_ctzll(a);
    do
    {
        b >>= __builtin_ctzll(b);
        if (a > b)
        {
            ulong x = a;

            a = b;
            b = x;
        }
        b -= a;
    }
    while (b != 0);
    return a << k;
#else
    return n_gcd(a, b);
#endif
}

void
_wc_zvec3_primitive(fmpz * v, fmpz_t t)
{
    /* Word entries: their gcd in words, each quotient a word.  */
    if (!COEFF_IS_MPZ(v[0]) && !COEFF_IS_MPZ(v[1]) && !COEFF_IS_MPZ(v[2]))
    {
        ulong g = _wc_gcd_ui(FLINT_ABS(v[0]), FLINT_ABS(v[1]));
        slong j;

        g = _wc_gcd_ui(g, FLINT_ABS(v[2]));
        if (g > 1)
            for (j = 0; j < 3; j++)
                fmpz_set_si(v + j, v[j] / (slong) g);
        return;
    }
    _fmpz_vec_content(t, v, 3);
    if (!fmpz_is_zero(t) && !fmpz_is_one(t))
        _fmpz_vec_scalar_divexact_fmpz(v, v, 3, t);
}

int
_wc_zvec3_canonical(fmpz * v, fmpz_t t)
{
    slong j;

    for (j = 0; j < 3 && fmpz_is_zero(v + j); j++)
        ;
    if (j == 3)
        return 0;
    _wc_zvec3_primitive(v, t);
    if (fmpz_sgn(v + j) > 0)
        return 1;
    _fmpz_vec_neg(v, v, 3);
    return -1;
}

int
_wc_zvec3_cmp(const fmpz * a, const fmpz * b)
{
    slong j;
    int c;

    for (j = 0; j < 3; j++)
        if ((c = fmpz_cmp(a + j, b + j)) != 0)
            return c;
    return 0;
}

void
_wc_qvec_primitive(fmpz * v, const fmpq * x, slong len)
{
    fmpz_t t;

    fmpz_init(t);
    _fmpq_vec_get_fmpz_vec_fmpz(v, t, x, len);
    _fmpz_vec_content(t, v, len);
    if (!fmpz_is_zero(t) && !fmpz_is_one(t))
        _fmpz_vec_scalar_divexact_fmpz(v, v, len, t);
    fmpz_clear(t);
}

#ifdef __SIZEOF_INT128__
/* The 192-bit product x y as hi (128 bits) and lo (64), for x < 2^124 and
   y < 2^62: with x = x1 2^64 + x0, x0 y < 2^128 and
   x1 y + (x0 y >> 64) < 2^60 2^62 + 2^64 < 2^128.  */
static void
mul_192(unsigned __int128 * hi, ulong * lo, unsigned __int128 x, ulong y)
{
    unsigned __int128 p0 = (unsigned __int128) (ulong) x * y;

    *hi = (unsigned __int128) (ulong) (x >> 64) * y + (p0 >> 64);
    *lo = (ulong) p0;
}
#endif

int
_wc_z_sqmul_cmp(const fmpz_t a, const fmpz_t b, const fmpz_t c,
                const fmpz_t d, fmpz_t l, fmpz_t r)
{
    int s;

#ifdef __SIZEOF_INT128__
    /* Word integers are below 2^62 in absolute value: the squares are
       below 2^124, b and d (>= 0) below 2^62, as mul_192 needs.  */
    if (!COEFF_IS_MPZ(*a) && !COEFF_IS_MPZ(*b) && !COEFF_IS_MPZ(*c)
        && !COEFF_IS_MPZ(*d) && *b >= 0 && *d >= 0)
    {
        unsigned __int128 a2 = (unsigned __int128) ((__int128) *a * *a);
        unsigned __int128 c2 = (unsigned __int128) ((__int128) *c * *c);
        unsigned __int128 lh, rh;
        ulong ll, rl;

        mul_192(&lh, &ll, a2, (ulong) *b);
        mul_192(&rh, &rl, c2, (ulong) *d);
        if (lh != rh)
            return lh < rh ? -1 : 1;
        return (ll > rl) - (ll < rl);
    }
#endif
    fmpz_mul(l, a, a);
    fmpz_mul(l, l, b);
    fmpz_mul(r, c, c);
    fmpz_mul(r, r, d);
    s = fmpz_cmp(l, r);
    return (s > 0) - (s < 0);
}
