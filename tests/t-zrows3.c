/* t-zrows3.c -- the integer row helpers of the direct route's fast path
   (lib/analysis/zrows3.c) against plain references.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The references below are the deliberate independent copies: the
   distinct rows by qsort with
   fmpz_cmp and a plain scan; R^3 by the general conversion
   (wc_cone_set_generators).  Rows are random with entries of a few bits,
   near the word limit or past it, with zero, repeated, opposite,
   collinear and coplanar rows.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpz_vec.h>

#include "wrenchcone.h"
#include "testutil.h"
#include "analysis/zrows3.h"

/* x := a random entry: small, near 2^62, or past it.  */
static void
rand_entry(fmpz_t x)
{
    slong kind = wctest_randint(0, 3);

    fmpz_set_si(x, wctest_randint(-3, 3));
    if (kind == 1)
        fmpz_mul_2exp(x, x, wctest_randint(55, 61));
    else if (kind == 2)
        fmpz_mul_2exp(x, x, wctest_randint(62, 90));
    if (kind != 0)
        fmpz_add_si(x, x, wctest_randint(-3, 3));
}

/* k rows: random, or copies, negations, multiples and sums of earlier
   rows, or zero.  */
static void
rand_rows(fmpz * A, slong k, int small)
{
    slong i, j;

    for (i = 0; i < k; i++)
    {
        fmpz * x = A + 3 * i;
        slong kind = i == 0 ? 0 : wctest_randint(0, 5);
        const fmpz * y = A + 3 * wctest_randint(0, FLINT_MAX(i - 1, 0));

        for (j = 0; j < 3; j++)
            if (kind == 0)
            {
                if (small)
                    fmpz_set_si(x + j, wctest_randint(-3, 3));
                else
                    rand_entry(x + j);
            }
            else if (kind == 1)
                fmpz_set(x + j, y + j);
            else if (kind == 2)
                fmpz_neg(x + j, y + j);
            else if (kind == 3)
                fmpz_mul_si(x + j, y + j, wctest_randint(2, 5));
            else if (kind == 4)
                fmpz_add(x + j, y + j, A + j);
            else
                fmpz_zero(x + j);
    }
}

static int
cmp_rows(const void * a, const void * b)
{
    const fmpz * x = a, * y = b;
    int c, j;

    for (j = 0; j < 3; j++)
        if ((c = fmpz_cmp(x + j, y + j)) != 0)
            return c;
    return 0;
}

static void
check_distinct(const fmpz * A, slong k)
{
    fmpz * B = _fmpz_vec_init(3 * k), * C = _fmpz_vec_init(3 * k);
    slong i, m = 0, mb;

    /* The reference: qsort of plain copies (fmpz entries are words that
       may point to GMP integers: copied with fmpz_set, sorted as whole
       rows), then the nonzero rows unlike their predecessor.  */
    _fmpz_vec_set(B, A, 3 * k);
    qsort(B, k, 3 * sizeof(fmpz), cmp_rows);
    for (i = 0; i < k; i++)
        if (!_fmpz_vec_is_zero(B + 3 * i, 3)
            && (m == 0 || cmp_rows(C + 3 * (m - 1), B + 3 * i) != 0))
            _fmpz_vec_set(C + 3 * m++, B + 3 * i, 3);
    _fmpz_vec_set(B, A, 3 * k);
    mb = _wc_zrows3_distinct(B, k);
    if (mb != m || !_fmpz_vec_equal(B, C, 3 * m))
        wctest_fail("_wc_zrows3_distinct: %ld rows, the reference %ld",
                    (long) mb, (long) m);
    _fmpz_vec_clear(B, 3 * k);
    _fmpz_vec_clear(C, 3 * k);
}

/* Returns whether the certificate was found; checks it against the
   general conversion.  */
static int
check_space(const fmpz * A, slong k)
{
    fmpq_mat_t G;
    wc_cone_t C;
    wc_error_t err;
    slong i, m = 0;
    int r = 0;

    for (i = 0; i < k; i++)
        m += !_fmpz_vec_is_zero(A + 3 * i, 3);
    if (m < k)
        return 0;                       /* the rows must not be zero */
    r = _wc_zrows3_span_space(A, k);
    fmpq_mat_init(G, k, 3);
    for (i = 0; i < 3 * k; i++)
        fmpq_set_fmpz(fmpq_mat_entry(G, i / 3, i % 3), A + i);
    wc_cone_init(C, 3);
    wc_error_init(err);
    if (wc_cone_set_generators(C, G, NULL, err) != WC_OK)
        wctest_fail("wc_cone_set_generators: %s", err->message);
    if (r && C->lineality_dim != 3)
        wctest_fail("_wc_zrows3_span_space certified R^3 for a cone of "
                    "lineality %ld", (long) C->lineality_dim);
    fmpq_mat_clear(G);
    wc_cone_clear(C);
    wc_error_clear(err);
    return r;
}

static int
has_zero(const fmpz * A, slong k)
{
    slong i;

    for (i = 0; i < k; i++)
        if (_fmpz_vec_is_zero(A + 3 * i, 3))
            return 1;
    return 0;
}

static int
det_nonzero(const fmpz * a, const fmpz * b, const fmpz * c)
{
    fmpz_t d, t;
    int r;

    fmpz_init(d);
    fmpz_init(t);
    fmpz_mul(t, b + 1, c + 2);
    fmpz_submul(t, b + 2, c + 1);
    fmpz_mul(d, a + 0, t);
    fmpz_mul(t, b + 2, c + 0);
    fmpz_submul(t, b + 0, c + 2);
    fmpz_addmul(d, a + 1, t);
    fmpz_mul(t, b + 0, c + 1);
    fmpz_submul(t, b + 1, c + 0);
    fmpz_addmul(d, a + 2, t);
    r = !fmpz_is_zero(d);
    fmpz_clear(d);
    fmpz_clear(t);
    return r;
}

int
main(void)
{
    slong i, iters, found = 0;

    wctest_init("t-zrows3");
    iters = wctest_iters(400);
    for (i = 0; i < iters; i++)
    {
        slong k = wctest_randint(1, 24);
        fmpz * A;

        if (!wctest_iter(i))
            continue;
        A = _fmpz_vec_init(3 * k);
        rand_rows(A, k, wctest_chance(1, 2));
        check_distinct(A, k);
        check_space(A, k);
        /* a, b, c at the positions tried first and d = -(a + b + c)
           among the other rows: certified whenever a, b, c are
           independent.  */
        if (k >= 4)
        {
            slong j, p[3] = { 0, k / 3, 2 * k / 3 }, q;
            int r;

            do
                q = wctest_randint(0, k - 1);
            while (q == p[0] || q == p[1] || q == p[2]);
            for (j = 0; j < 3; j++)
            {
                fmpz_add(A + 3 * q + j, A + 3 * p[0] + j, A + 3 * p[1] + j);
                fmpz_add(A + 3 * q + j, A + 3 * q + j, A + 3 * p[2] + j);
                fmpz_neg(A + 3 * q + j, A + 3 * q + j);
            }
            r = check_space(A, k);
            found += r;
            if (!r && !has_zero(A, k) && det_nonzero(A + 3 * p[0],
                                                    A + 3 * p[1],
                                                    A + 3 * p[2]))
                wctest_fail("_wc_zrows3_span_space missed a certificate");
        }
        _fmpz_vec_clear(A, 3 * k);
    }
    if (iters >= 400 && found == 0)
        wctest_fail("the R^3 certificate was never found");
    flint_cleanup_master();
    return 0;
}
