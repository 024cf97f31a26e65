/* t-checkcells.c -- the certificate checker's cells of an arrangement of
   planes (lib/check/arrcells.c) against the solver's (lib/exact/cells.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   1. Hand-counted arrangements: the coordinate planes alone (27 cells),
      with x + y + z = 0 (51 cells), with a pencil of planes through the
      z axis.
   2. Random plane sets, with degenerate layouts: many planes through one
      line, through coordinate axes, through lines of two others, small
      entries with many coincidences, large entries, repeated directions
      (removed here before the call, as the checker asks), the coordinate
      planes only.  The planes are made primitive with their first
      nonzero entry positive and sorted, as wc_cells_build makes them, so
      the two sign vectors are comparable; then: the same planes, the
      same count, the same dimension and sign vector at every index; every
      point primitive with its cell's sign vector, the same point as the
      solver's for every ray; every cell's rays exactly the 1-cells in
      its closure, by a brute-force test over all of them (r lies in the
      closure of c iff sign_r[p] is 0 or sign_c[p] for every plane p).
   3. Parallel planes, or two planes: WC_EINTERNAL and no cells.
   4. Cost: the products counted stay within
      4 m^2 (log2 m + 1) + cells m, up to m = 70 planes, so that a walk
      spending more than O(m) products per cell fails.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpz_vec.h>

#include "wrenchcone.h"
#include "check/checker.h"
#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Plane lists: n planes of 3 fmpz each.                               */

#define MAXP 100

typedef struct
{
    slong n;
    fmpz v[3 * MAXP];
}
planes;

static void
planes_init(planes * P)
{
    slong i;

    P->n = 0;
    for (i = 0; i < 3 * MAXP; i++)
        fmpz_init(P->v + i);
}

static void
planes_clear(planes * P)
{
    slong i;

    for (i = 0; i < 3 * MAXP; i++)
        fmpz_clear(P->v + i);
}

static fmpz *
planes_add(planes * P)
{
    if (P->n == MAXP)
        wctest_fail("too many planes");
    _fmpz_vec_zero(P->v + 3 * P->n, 3);
    return P->v + 3 * P->n++;
}

static void
cross3(fmpz * c, const fmpz * x, const fmpz * y)
{
    slong j;

    for (j = 0; j < 3; j++)
    {
        fmpz_mul(c + j, x + (j + 1) % 3, y + (j + 2) % 3);
        fmpz_submul(c + j, x + (j + 2) % 3, y + (j + 1) % 3);
    }
}

static void
rand_vec(fmpz * v, slong b)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpz_set_si(v + j, wctest_randint(-b, b));
}

static int
vec_cmp(const fmpz * a, const fmpz * b)
{
    slong j;
    int d;

    for (j = 0; j < 3; j++)
        if ((d = fmpz_cmp(a + j, b + j)) != 0)
            return d;
    return 0;
}

/* Drop zero rows, make the rest primitive with first nonzero entry
   positive, add the coordinate planes, sort, drop repeats.  */
static void
planes_canonical(planes * P)
{
    slong i, j, k, n = 0;
    fmpz_t g;

    fmpz_init(g);
    for (j = 0; j < 3; j++)
        fmpz_one(planes_add(P) + j);
    for (i = 0; i < P->n; i++)
    {
        fmpz * h = P->v + 3 * i;

        if (_fmpz_vec_is_zero(h, 3))
            continue;
        _fmpz_vec_content(g, h, 3);
        _fmpz_vec_scalar_divexact_fmpz(h, h, 3, g);
        for (j = 0; fmpz_is_zero(h + j); j++)
            ;
        if (fmpz_sgn(h + j) < 0)
            _fmpz_vec_neg(h, h, 3);
        _fmpz_vec_swap(P->v + 3 * n, h, 3);
        n++;
    }
    for (i = 1; i < n; i++)         /* insertion sort */
        for (k = i; k > 0 && vec_cmp(P->v + 3 * (k - 1), P->v + 3 * k) > 0;
             k--)
            _fmpz_vec_swap(P->v + 3 * (k - 1), P->v + 3 * k, 3);
    P->n = 0;
    for (i = 0; i < n; i++)
        if (P->n == 0 || vec_cmp(P->v + 3 * (P->n - 1), P->v + 3 * i) != 0)
            _fmpz_vec_swap(P->v + 3 * P->n++, P->v + 3 * i, 3);
    fmpz_clear(g);
}

/* A random set of planes, in one of several layouts.  */
static void
random_planes(planes * P)
{
    slong style = wctest_randint(0, 7), n = wctest_randint(0, 18), i;
    fmpz L[3], r[3], s[3];

    for (i = 0; i < 3; i++)
    {
        fmpz_init(L + i);
        fmpz_init(r + i);
        fmpz_init(s + i);
    }
    do
        rand_vec(L, 2);
    while (_fmpz_vec_is_zero(L, 3));
    P->n = 0;
    if (style == 7)             /* the coordinate planes only */
        n = 0;
    for (i = 0; i < n; i++)
    {
        fmpz * h = planes_add(P);
        slong kind = wctest_randint(0, 8);

        if (style == 1 || (style == 2 && kind < 6))
            kind = 1;           /* (mostly) a pencil through L */
        if (style == 3)
            kind = 0;           /* entries in -1 .. 1 */
        if (kind == 0)
            rand_vec(h, 1);
        else if (kind == 1)
        {
            rand_vec(r, 2);
            cross3(h, L, r);
        }
        else if (kind == 2)     /* through a coordinate axis */
        {
            rand_vec(h, 3);
            fmpz_zero(h + wctest_randint(0, 2));
        }
        else if (kind == 3 && P->n >= 3)    /* through two others' line */
        {
            cross3(r, h - 3, h - 6);
            rand_vec(s, 2);
            cross3(h, r, s);
        }
        else if (kind == 4 && P->n >= 2)    /* a repeated direction */
            _fmpz_vec_scalar_mul_si(h, P->v + 3 * wctest_randint(0, i - 1),
                                    3, wctest_randint(-3, 3));
        else if (kind == 5 && P->n >= 3)    /* a combination of two */
        {
            _fmpz_vec_scalar_mul_si(h, h - 3, 3, wctest_randint(-2, 2));
            _fmpz_vec_scalar_addmul_si(h, h - 6, 3, wctest_randint(-2, 2));
        }
        else
            rand_vec(h, style == 4 ? 40 : 4);
        if (style == 5 && wctest_chance(1, 2))  /* large entries */
        {
            rand_vec(r, 2);
            _fmpz_vec_scalar_mul_2exp(h, h, 3, 45);
            _fmpz_vec_add(h, h, r, 3);
        }
    }
    planes_canonical(P);
    for (i = 0; i < 3; i++)
    {
        fmpz_clear(L + i);
        fmpz_clear(r + i);
        fmpz_clear(s + i);
    }
}

/* ------------------------------------------------------------------ */
/* The comparison.                                                     */

static int
ceil_log2(slong m)
{
    int k = 0;

    while ((WORD(1) << k) < m)
        k++;
    return k;
}

/* The bound on the products of the checker's walk.  */
static unsigned long
work_bound(slong m, size_t count)
{
    return 4 * (unsigned long) (m * m) * (ceil_log2(m) + 1)
        + (unsigned long) count * (unsigned long) m;
}

/* Check C, the checker's cells of P, against the solver's A; with
   brute, every ray list against the closure test over all 1-cells.  */
static void
compare(const wc_check_cells * C, const wc_cells_t A, const planes * P,
        int brute)
{
    slong m = P->n, i, p, j, r;
    size_t k, nr;
    mpz_t t, g;
    fmpz_t f;

    mpz_init(t);
    mpz_init(g);
    fmpz_init(f);
    if (A->nplanes != m || (slong) C->nplanes != m)
        wctest_fail("%ld planes, solver %ld, checker %ld", (long) m,
                    (long) A->nplanes, (long) C->nplanes);
    for (i = 0; i < m; i++)
        for (j = 0; j < 3; j++)
            if (!fmpz_equal(fmpz_mat_entry(A->planes, i, j), P->v + 3 * i + j))
                wctest_fail("plane %ld is not the solver's", (long) i);
    if ((slong) C->count != A->count)
        wctest_fail("%lu cells, the solver has %ld (%ld planes)",
                    (unsigned long) C->count, (long) A->count, (long) m);
    if (C->work > work_bound(m, C->count))
        wctest_fail("%lu products for %ld planes and %lu cells, bound %lu",
                    C->work, (long) m, (unsigned long) C->count,
                    work_bound(m, C->count));
    for (i = 0; i < A->count; i++)
    {
        const signed char * s = C->sign + i * m;
        mpz_t * x = C->point + 3 * i;

        if (C->dim[i] != A->dim[i]
            || memcmp(s, A->sign + i * m, (size_t) m) != 0)
            wctest_fail("cell %ld: dim %d, the solver's %ld, or other signs",
                        (long) i, C->dim[i], (long) A->dim[i]);
        mpz_gcd(g, x[0], x[1]);
        mpz_gcd(g, g, x[2]);
        if (mpz_cmp_ui(g, C->dim[i] == 0 ? 0 : 1) != 0)
            wctest_fail("cell %ld: the point is not primitive", (long) i);
        for (p = 0; p < m; p++)
        {
            mpz_set_ui(t, 0);
            for (j = 0; j < 3; j++)
            {
                fmpz_get_mpz(g, P->v + 3 * p + j);
                mpz_addmul(t, g, x[j]);
            }
            if (mpz_sgn(t) != s[p])
                wctest_fail("cell %ld: the point is off its sign vector at "
                            "plane %ld", (long) i, (long) p);
        }
        if (C->dim[i] == 1)
            for (j = 0; j < 3; j++)
            {
                fmpz_set_mpz(f, x[j]);
                if (!fmpz_equal(f, fmpz_mat_entry(A->point, i, j)))
                    wctest_fail("ray %ld: not the solver's direction",
                                (long) i);
            }
        nr = C->rayoff[i + 1] - C->rayoff[i];
        if ((C->dim[i] == 0 && nr != 0) || (C->dim[i] == 1 && nr != 1)
            || (C->dim[i] == 2 && nr != 2) || (C->dim[i] == 3 && nr < 3))
            wctest_fail("cell %ld of dim %d has %lu rays", (long) i,
                        C->dim[i], (unsigned long) nr);
        if (!brute)
        {
            for (k = C->rayoff[i]; k < C->rayoff[i + 1]; k++)
                if (C->ray[k] >= C->count || C->dim[C->ray[k]] != 1
                    || (k > C->rayoff[i] && C->ray[k] <= C->ray[k - 1]))
                    wctest_fail("cell %ld: a bad ray %lu", (long) i,
                                (unsigned long) C->ray[k]);
            continue;
        }
        k = C->rayoff[i];
        for (r = 0; r < A->count; r++)
        {
            const signed char * sr = C->sign + r * m;
            int in = C->dim[r] == 1;

            for (p = 0; p < m && in; p++)
                in = sr[p] == 0 || sr[p] == s[p];
            if (!in)
                continue;
            if (k == C->rayoff[i + 1] || C->ray[k] != (size_t) r)
                wctest_fail("cell %ld: ray %ld missing or out of order",
                            (long) i, (long) r);
            k++;
        }
        if (k != C->rayoff[i + 1])
            wctest_fail("cell %ld: rays outside its closure", (long) i);
    }
    mpz_clear(t);
    mpz_clear(g);
    fmpz_clear(f);
}

/* Build both and compare; returns the count.  */
static slong
check(const planes * P, int brute)
{
    slong m = P->n, i, j;
    mpz_t * H = _wc_check_zvec_new(3 * (size_t) m);
    wc_check_cells C;
    fmpz_mat_t N;
    wc_cells_t A;
    wc_error_t err;
    slong count;

    if (H == NULL)
        wctest_fail("out of memory");
    fmpz_mat_init(N, m, 3);
    for (i = 0; i < m; i++)
        for (j = 0; j < 3; j++)
        {
            fmpz_set(fmpz_mat_entry(N, i, j), P->v + 3 * i + j);
            fmpz_get_mpz(H[3 * i + j], P->v + 3 * i + j);
        }
    wc_cells_init(A);
    wc_error_init(err);
    if (wc_cells_build(A, N, err) != WC_OK)
        wctest_fail("wc_cells_build: %s", err->message);
    _wc_check_cells_init(&C);
    if (_wc_check_cells_build(&C, H, (size_t) m) != WC_OK)
        wctest_fail("_wc_check_cells_build failed on %ld planes", (long) m);
    compare(&C, A, P, brute);
    count = (slong) C.count;
    _wc_check_cells_clear(&C);
    wc_cells_clear(A);
    wc_error_clear(err);
    fmpz_mat_clear(N);
    _wc_check_zvec_free(H, 3 * (size_t) m);
    return count;
}

/* ------------------------------------------------------------------ */
/* The tests.                                                          */

static void
set_plane(planes * P, slong a, slong b, slong c)
{
    fmpz * h = planes_add(P);

    fmpz_set_si(h, a);
    fmpz_set_si(h + 1, b);
    fmpz_set_si(h + 2, c);
}

static void
test_hand(void)
{
    planes P;
    slong n, i;

    planes_init(&P);
    planes_canonical(&P);
    if ((n = check(&P, 1)) != 1 + 6 + 12 + 8)
        wctest_fail("coordinate planes: %ld cells", (long) n);
    P.n = 0;
    set_plane(&P, -1, -1, -1);
    planes_canonical(&P);
    /* 6 lines, 4 planes of 3 lines each, 14 chambers (Euler) */
    if (P.n != 4 || (n = check(&P, 1)) != 1 + 12 + 24 + 14)
        wctest_fail("x + y + z: %ld cells", (long) n);
    /* a pencil of k more planes through the z axis */
    for (i = 1; i <= 8; i++)
    {
        slong k = i, j, rays, sectors, chambers;

        P.n = 0;
        for (j = 1; j <= k; j++)
            set_plane(&P, j, j % 2 ? 1 - 2 * j : 3 * j + 1, 0);
        planes_canonical(&P);
        if (P.n != k + 3)
            wctest_fail("pencil %ld: %ld planes", (long) k, (long) P.n);
        /* lines: the z axis, and z = 0 with each of the k + 2 vertical
           planes; rays 2 (k + 3); sectors: the plane z = 0 has k + 2
           lines (2 (k + 2) sectors), each vertical plane 2 lines (4
           sectors); chambers 2 (2 (k + 2)) */
        rays = 2 * (k + 3);
        sectors = 2 * (k + 2) + 4 * (k + 2);
        chambers = 4 * (k + 2);
        if ((n = check(&P, 1)) != 1 + rays + sectors + chambers)
            wctest_fail("pencil %ld: %ld cells", (long) k, (long) n);
    }
    planes_clear(&P);
}

/* Planes breaking the promise: WC_EINTERNAL, the cells left empty.  */
static void
test_refused(void)
{
    mpz_t * H = _wc_check_zvec_new(12);
    wc_check_cells C;
    int j;

    if (H == NULL)
        wctest_fail("out of memory");
    for (j = 0; j < 3; j++)
        mpz_set_ui(H[4 * j], 1);
    mpz_set_si(H[9], -2);           /* parallel to (1, 0, 0) */
    _wc_check_cells_init(&C);
    if (_wc_check_cells_build(&C, H, 4) != WC_EINTERNAL || C.count != 0)
        wctest_fail("parallel planes accepted");
    if (_wc_check_cells_build(&C, H, 2) != WC_EINTERNAL || C.count != 0)
        wctest_fail("two planes accepted");
    if (_wc_check_cells_build(&C, H, 3) != WC_OK || C.count != 27)
        wctest_fail("the coordinate planes after a refusal");
    _wc_check_cells_clear(&C);
    _wc_check_zvec_free(H, 12);
}

static void
test_random(void)
{
    slong i, iters = wctest_iters(200);
    planes P;

    planes_init(&P);
    for (i = 0; i < iters; i++)
    {
        if (!wctest_iter(i))
            continue;
        random_planes(&P);
        check(&P, 1);
    }
    planes_clear(&P);
}

static void
test_cost(void)
{
    slong i, j, iters = wctest_iters(3);
    planes P;

    planes_init(&P);
    for (i = 0; i < iters; i++)
    {
        if (!wctest_iter(1000 + i))
            continue;
        P.n = 0;
        for (j = 0; j < 67; j++)
            rand_vec(planes_add(&P), i % 3 == 2 ? 3 : 60);
        planes_canonical(&P);
        check(&P, 0);
    }
    planes_clear(&P);
}

int
main(void)
{
    wctest_init("t-checkcells");
    test_hand();
    test_refused();
    test_random();
    test_cost();
    return 0;
}
