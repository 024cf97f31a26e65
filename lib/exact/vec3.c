/* vec3.c -- exact 3-vectors.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

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

int
_wc_zvec3_dot_sgn_fast(const fmpz * a, const fmpz * b, fmpz_t t)
{
#ifdef __SIZEOF_INT128__
    /* Word entries are below 2^62 in absolute value: each product is
       below 2^124 and the sum below 2^126.  */
    if (!COEFF_IS_MPZ(a[0]) && !COEFF_IS_MPZ(a[1]) && !COEFF_IS_MPZ(a[2])
        && !COEFF_IS_MPZ(b[0]) && !COEFF_IS_MPZ(b[1]) && !COEFF_IS_MPZ(b[2]))
    {
        __int128 s = (__int128) a[0] * b[0] + (__int128) a[1] * b[1]
            + (__int128) a[2] * b[2];

        return (s > 0) - (s < 0);
    }
#endif
    return _wc_zvec3_dot_sgn(a, b, t);
}
