/* gmpvec.c -- the checker's vectors of GMP rationals and integers.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The solver's 3-vectors (exact/vec3.h) are FLINT's; the checker keeps
   GMP's own, so that the two share no arithmetic.  */

#include <stdint.h>
#include <stdlib.h>

#include "check/checker.h"

size_t
_wc_check_times(size_t k, size_t n)
{
    return n != 0 && k > SIZE_MAX / n ? SIZE_MAX : k * n;
}

void *
_wc_check_alloc(size_t n, size_t size)
{
    if (size != 0 && n > (SIZE_MAX - 1) / size)
        return NULL;
    return malloc(n * size + 1);
}

/* Initialise (init) or clear the n numbers of v (none when v is NULL):
   rationals when q, else integers.  */
static void
each_number(void * v, size_t n, int q, int init)
{
    size_t i;

    for (i = 0; v != NULL && i < n; i++)
    {
        if (q)
            (init ? mpq_init : mpq_clear)(((mpq_t *) v)[i]);
        else
            (init ? mpz_init : mpz_clear)(((mpz_t *) v)[i]);
    }
}

mpq_t *
_wc_check_qvec_new(size_t n)
{
    mpq_t * v = _wc_check_alloc(n, sizeof(mpq_t));

    each_number(v, n, 1, 1);
    return v;
}

mpz_t *
_wc_check_zvec_new(size_t n)
{
    mpz_t * v = _wc_check_alloc(n, sizeof(mpz_t));

    each_number(v, n, 0, 1);
    return v;
}

void
_wc_check_qvec_free(mpq_t * v, size_t n)
{
    each_number(v, n, 1, 0);
    free(v);
}

void
_wc_check_zvec_free(mpz_t * v, size_t n)
{
    each_number(v, n, 0, 0);
    free(v);
}

int
_wc_check_qvec_is_zero(mpq_t * v, size_t n)
{
    size_t i;

    for (i = 0; i < n; i++)
        if (mpq_sgn(v[i]) != 0)
            return 0;
    return 1;
}

int
_wc_check_qvec_equal(mpq_t * a, mpq_t * b, size_t n)
{
    size_t i;

    for (i = 0; i < n; i++)
        if (!mpq_equal(a[i], b[i]))
            return 0;
    return 1;
}

void
_wc_check_qdot3(mpq_t r, mpq_t * a, mpq_t * b, mpq_t t)
{
    mpq_mul(r, a[0], b[0]);
    _wc_check_qaddmul(r, a[1], b[1], t);
    _wc_check_qaddmul(r, a[2], b[2], t);
}

void
_wc_check_zdot3(mpz_t r, mpz_t * a, mpz_t * b)
{
    mpz_mul(r, a[0], b[0]);
    mpz_addmul(r, a[1], b[1]);
    mpz_addmul(r, a[2], b[2]);
}

void
_wc_check_qcross3(mpq_t * r, mpq_t * a, mpq_t * b, mpq_t t)
{
    int c;

    for (c = 0; c < 3; c++)
    {
        int c1 = (c + 1) % 3, c2 = (c + 2) % 3;

        mpq_mul(r[c], a[c1], b[c2]);
        mpq_mul(t, a[c2], b[c1]);
        mpq_sub(r[c], r[c], t);
    }
}

void
_wc_check_zcross3(mpz_t * r, mpz_t * a, mpz_t * b)
{
    int c;

    for (c = 0; c < 3; c++)
    {
        int c1 = (c + 1) % 3, c2 = (c + 2) % 3;

        mpz_mul(r[c], a[c1], b[c2]);
        mpz_submul(r[c], a[c2], b[c1]);
    }
}

void
_wc_check_qaddmul(mpq_t r, const mpq_t a, const mpq_t b, mpq_t t)
{
    mpq_mul(t, a, b);
    mpq_add(r, r, t);
}

void
_wc_check_primitive(mpz_t * z, mpq_t * q, mpz_t t)
{
    int j;

    mpz_set(t, mpq_denref(q[0]));
    mpz_lcm(t, t, mpq_denref(q[1]));
    mpz_lcm(t, t, mpq_denref(q[2]));
    for (j = 0; j < 3; j++)
    {
        mpz_divexact(z[j], t, mpq_denref(q[j]));
        mpz_mul(z[j], z[j], mpq_numref(q[j]));
    }
    mpz_gcd(t, z[0], z[1]);
    mpz_gcd(t, t, z[2]);
    if (mpz_sgn(t) != 0)
        for (j = 0; j < 3; j++)
            mpz_divexact(z[j], z[j], t);
}
