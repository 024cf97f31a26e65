/* t-cellsfast.c -- wc_cells_build (incremental keys, Zobrist hashes, the
   chamber multiplier without divisions, signs sorted in place) against
   the former build kept in old-cells.c, _wc_angle_cmp against the fmpz
   cross product, and the sign bitsets of the plan
   (cellbits.c, built a word of cells at a time) against the signs.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The two builds must agree byte for byte: the planes, the number of
   cells, and every cell's dimension, point and sign vector.  Layouts:
   small random normals (repeated, opposite and multiple rows, zero rows,
   coordinate planes; also more than 64 planes, for the bitsets' blocks
   of 64 planes), pencils of planes (also more than 64) through one or a few common
   lines, large entries (sector points past a word: the fmpz path; plane
   entries past 2^62: no word path at all; alone or mixed with small
   rows), no rows at all, and the planes of real plans of random
   problems (testutil.h: coincident and collinear fixels, normals through
   one point, opposed normals).  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/flint.h>
#include <flint/fmpz_vec.h>

#include "wrenchcone.h"
#include "analysis/planparts.h"
#include "exact/arrangement.h"
#include "testutil.h"
#include "old-cells.h"

static void
rand_vec(fmpz * v, slong r)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpz_set_si(v + j, wctest_randint(-r, r));
}

static void
cross(fmpz * c, const fmpz * x, const fmpz * y)
{
    fmpz_mul(c + 0, x + 1, y + 2);
    fmpz_submul(c + 0, x + 2, y + 1);
    fmpz_mul(c + 1, x + 2, y + 0);
    fmpz_submul(c + 1, x + 0, y + 2);
    fmpz_mul(c + 2, x + 0, y + 1);
    fmpz_submul(c + 2, x + 1, y + 0);
}

/* N := a random layout of n rows in one of the styles above.  */
static void
layout(fmpz_mat_t N, slong style)
{
    slong n = style == 5 ? 0 : style >= 7 ? wctest_randint(70, 90)
        : wctest_randint(1, style == 0 ? 40 : 16), i;
    fmpz * axis = _fmpz_vec_init(9), * a = _fmpz_vec_init(3);
    slong naxes = wctest_randint(1, 3);

    fmpz_mat_clear(N);
    fmpz_mat_init(N, n, 3);
    for (i = 0; i < 3; i++)
        rand_vec(axis + 3 * i, 2);
    for (i = 0; i < n; i++)
    {
        fmpz * h = fmpz_mat_entry(N, i, 0);
        slong kind = wctest_randint(0, 9);

        if (style == 0 || style == 7 || kind == 0)
            rand_vec(h, style == 7 ? 9 : wctest_chance(1, 2) ? 1
                     : wctest_randint(2, 5));
        else if (style == 1 || style == 2 || style == 8)
        {
            /* through one of naxes common lines (style 1: one) */
            rand_vec(a, style == 8 ? 9 : 3);
            cross(h, a, axis + 3 * (style == 1 ? 0
                                    : wctest_randint(0, naxes - 1)));
        }
        else
        {
            /* large entries, sometimes only in some rows */
            rand_vec(h, 4);
            if (style == 3 || wctest_chance(1, 3))
            {
                fmpz_mul_2exp(h + wctest_randint(0, 2),
                              h + wctest_randint(0, 2),
                              wctest_randint(14, 70));
                fmpz_add_si(h, h, wctest_randint(-9, 9));
            }
        }
        if (i > 0 && kind == 1)     /* a multiple of an earlier row */
            _fmpz_vec_scalar_mul_si(h, fmpz_mat_entry(N,
                                        wctest_randint(0, i - 1), 0), 3,
                                    wctest_randint(-3, 3));
        if (kind == 2)
            fmpz_zero(h + wctest_randint(0, 2));
    }
    _fmpz_vec_clear(axis, 9);
    _fmpz_vec_clear(a, 3);
}

static void
same_cells(const wc_cells_t A, const wc_cells_t B, const char * what)
{
    slong i, p, m = A->nplanes;
    fmpz_t t;

    fmpz_init(t);
    if (A->nplanes != B->nplanes || !fmpz_mat_equal(A->planes, B->planes))
        wctest_fail("%s: the planes differ (%ld, %ld of them)", what,
                    (long) A->nplanes, (long) B->nplanes);
    if (A->count != B->count)
        wctest_fail("%s: %ld cells, the reference %ld", what,
                    (long) A->count, (long) B->count);
    for (i = 0; i < A->count; i++)
    {
        if (A->dim[i] != B->dim[i])
            wctest_fail("%s: cell %ld has dimension %ld, the reference %ld",
                        what, (long) i, (long) A->dim[i], (long) B->dim[i]);
        if (!_fmpz_vec_equal(A->point->rows[i], B->point->rows[i], 3))
            wctest_fail("%s: cell %ld: the points differ", what, (long) i);
        if (A->kw != B->kw
            || memcmp(_wc_cells_key(A, i), _wc_cells_key(B, i),
                      sizeof(uint64_t) * A->kw) != 0)
            wctest_fail("%s: cell %ld: the signs differ", what, (long) i);
        for (p = 0; p < m; p++)
        {
            _fmpz_vec_dot(t, A->planes->rows[p], A->point->rows[i], 3);
            if (fmpz_sgn(t) != _wc_cells_sign(A, i, p))
                wctest_fail("%s: cell %ld: the sign on plane %ld is not "
                            "that of its point", what, (long) i, (long) p);
        }
    }
    fmpz_clear(t);
}

/* The bitsets of X against the signs of A, bit by bit.  */
static void
check_bits(const wc_cells_t A)
{
    wc_cell_bits X;
    slong i, p, s, m = A->nplanes;

    if (!_wc_cell_bits_init(&X, A))
        wctest_fail("bits: out of memory");
    for (p = 0; p < m; p++)
    {
        for (s = -1; s <= 1; s++)
        {
            const ulong * neg = X.bits + 2 * p * X.words;
            const ulong * pos = neg + X.words;

            for (i = 0; i < X.words * FLINT_BITS; i++)
            {
                slong w = i / FLINT_BITS;
                ulong b = s < 0 ? neg[w] : s > 0 ? pos[w]
                    : ~(neg[w] | pos[w]);
                int bit = (int) ((b >> (i % FLINT_BITS)) & 1);
                int want = i < A->count ? _wc_cells_sign(A, i, p) == s
                    : s == 0;   /* past the last cell: off - and + */

                if (bit != want)
                    wctest_fail("bits: plane %ld sign %ld cell %ld: %d, "
                                "expected %d", (long) p, (long) s, (long) i,
                                bit, want);
            }
        }
    }
    _wc_cell_bits_clear(&X);
}

static void
compare(const fmpz_mat_t N, const char * what)
{
    wc_cells_t A, B;
    wc_error_t err;
    int sa, sb;

    wc_cells_init(A);
    wc_cells_init(B);
    wc_error_init(err);
    sa = wc_cells_build(A, N, err);
    sb = old_cells_build(B, N, err);
    if (sa != WC_OK || sb != WC_OK)
        wctest_fail("%s: status %d, the reference %d", what, sa, sb);
    same_cells(A, B, what);
    check_bits(A);
    wc_cells_clear(A);
    wc_cells_clear(B);
    wc_error_clear(err);
}

/* A random entry: small, near the limit of a word fmpz (2^62), or
   multiprecision, either sign.  */
static void
rand_entry(fmpz_t x)
{
    slong k = wctest_randint(0, 3);

    fmpz_set_si(x, wctest_randint(-5, 5));
    if (k == 1)
        fmpz_set_si(x, COEFF_MAX - wctest_randint(0, 3));
    else if (k == 2)
        fmpz_set_ui(x, (ulong) wctest_rand() >> wctest_randint(1, 40));
    else if (k == 3)
        fmpz_mul_2exp(x, x, wctest_randint(60, 70));
    if (wctest_chance(1, 2))
        fmpz_neg(x, x);
}

/* _wc_angle_cmp (words when it can) against the cross product in fmpz.  */
static void
check_angle_cmp(void)
{
    fmpz_t a[4], c, d;
    slong j;
    int got, want;

    fmpz_init(c);
    fmpz_init(d);
    for (j = 0; j < 4; j++)
    {
        fmpz_init(a[j]);
        rand_entry(a[j]);
    }
    if (wctest_chance(1, 4))    /* parallel */
    {
        fmpz_mul_si(a[2], a[0], 3);
        fmpz_mul_si(a[3], a[1], 3);
    }
    fmpz_mul(c, a[0], a[3]);
    fmpz_mul(d, a[1], a[2]);
    want = -fmpz_cmp(c, d);
    want = (want > 0) - (want < 0);
    got = _wc_angle_cmp(a[0], a[1], a[2], a[3]);
    if (got != want)
        wctest_fail("angle_cmp: %d, expected %d", got, want);
    for (j = 0; j < 4; j++)
        fmpz_clear(a[j]);
    fmpz_clear(c);
    fmpz_clear(d);
}

/* The planes of the plan of a random problem (as wc_plan gathers them).  */
static void
plan_planes(void)
{
    wc_problem_t P;
    wc_plan_t R;
    wc_error_t err;

    wc_problem_init(P);
    wc_plan_init(R);
    wc_error_init(err);
    wctest_random_problem(P, 1, 3);
    if (wc_plan(R, P, 0, err) == WC_OK)
        compare(R->cells->planes, "plan planes");
    wc_plan_clear(R);
    wc_problem_clear(P);
    wc_error_clear(err);
}

int
main(void)
{
    slong i, iters;
    fmpz_mat_t N;

    wctest_init("t-cellsfast");
    fmpz_mat_init(N, 0, 3);
    iters = wctest_iters(300);
    for (i = 0; i < iters; i++)
    {
        char what[32];
        slong style;

        if (!wctest_iter(i))
            continue;
        for (style = 0; style < 50; style++)
            check_angle_cmp();
        /* a few layouts of more than 64 planes (slow in old-cells.c) */
        style = i % 50 == 7 ? 7 : i % 50 == 8 ? 8 : i % 7;
        if (style == 6)
        {
            plan_planes();
            continue;
        }
        layout(N, style);
        snprintf(what, sizeof(what), "style %ld", (long) style);
        compare(N, what);
    }
    fmpz_mat_clear(N);
    flint_cleanup_master();
    printf("t-cellsfast: %ld iterations, OK\n", (long) iters);
    return 0;
}
