/* t-checkregion.c -- the regions of a set certificate's tree, cut by
   the checker (lib/check/region.c) and by the solver (lib/exact/
   region3.c), against the cells of the arrangement (lib/exact/cells.c,
   a different algorithm: a walk over the arrangement's lines).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The full tree -- the 27 regions of the coordinate planes, each cut by
   every other plane in turn -- has the arrangement's cells as leaves.
   Checked, for hand-counted arrangements (the coordinate planes alone:
   27 cells; with x + y + z = 0: 51; pencils of planes through the z axis)
   and for random plane sets with degenerate layouts (many planes through
   one line, through coordinate axes, through the lines of two others,
   small entries with many coincidences, large entries): the checker's
   and the solver's regions are the same at every cut (dimension and
   rays, in order); there are as many leaves as cells; each leaf's point
   (the sum of its rays) has the sign vector of one cell, whose dimension
   it has and whose 1-cells are its rays.  Dependent basis planes are
   refused.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpz_vec.h>

#include "wrenchcone.h"
#include "exact/vec3.h"
#include "exact/region3.h"
#include "check/checker.h"
#include "check/region.h"
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
            _wc_zvec3_cross(h, L, r);
        }
        else if (kind == 2)     /* through a coordinate axis */
        {
            rand_vec(h, 3);
            fmpz_zero(h + wctest_randint(0, 2));
        }
        else if (kind == 3 && P->n >= 3)    /* through two others' line */
        {
            _wc_zvec3_cross(r, h - 3, h - 6);
            rand_vec(s, 2);
            _wc_zvec3_cross(h, r, s);
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

/* The leaves of the full tree over P: the 27 regions of the coordinate
   planes (the first of P's basis), each cut by every other plane in
   turn; by the checker (Z) and by the solver's region3 (F), in lockstep.
   The leaves are the cells of the arrangement.  */
typedef struct
{
    slong n, cap;
    wc_check_region * Z;
    _wc_region3 * F;
}
leaves;

static void
leaves_add(leaves * L, const wc_check_region * z, const _wc_region3 * f)
{
    slong i, j;

    if (L->n == L->cap)
    {
        L->cap = L->cap < 64 ? 64 : 2 * L->cap;
        L->Z = realloc(L->Z, sizeof(wc_check_region) * L->cap);
        L->F = realloc(L->F, sizeof(_wc_region3) * L->cap);
        if (L->Z == NULL || L->F == NULL)
            wctest_fail("out of memory");
    }
    _wc_check_region_init(L->Z + L->n);
    _wc_region3_init(L->F + L->n);
    if (_wc_check_region_copy(L->Z + L->n, z) != 1)
        wctest_fail("out of memory");
    L->F[L->n].dim = f->dim;
    for (i = 0; i < f->n; i++)
    {
        _wc_region3 * g = L->F + L->n;

        if (g->n == g->cap)
        {
            slong cap = g->cap < 4 ? 4 : 2 * g->cap;
            fmpz * r = _fmpz_vec_init(3 * cap);

            for (j = 0; j < 3 * g->n; j++)
                fmpz_swap(r + j, g->r + j);
            if (g->r != NULL)
                _fmpz_vec_clear(g->r, 3 * g->cap);
            g->r = r;
            g->cap = cap;
        }
        _fmpz_vec_set(g->r + 3 * g->n++, f->r + 3 * i, 3);
    }
    L->n++;
}

static void
leaves_clear(leaves * L)
{
    slong i;

    for (i = 0; i < L->n; i++)
    {
        _wc_check_region_clear(L->Z + i);
        _wc_region3_clear(L->F + i);
    }
    free(L->Z);
    free(L->F);
}

/* The checker's and the solver's regions agree: dim and rays.  */
static void
same_region(const wc_check_region * z, const _wc_region3 * f)
{
    slong i, j;
    fmpz_t x;

    fmpz_init(x);
    if (z->dim != f->dim || (slong) z->n != f->n)
        wctest_fail("checker region dim %d with %lu rays, solver's dim %d "
                    "with %ld", z->dim, (unsigned long) z->n, f->dim,
                    (long) f->n);
    for (i = 0; i < f->n; i++)
        for (j = 0; j < 3; j++)
        {
            fmpz_set_mpz(x, z->r[3 * i + j]);
            if (!fmpz_equal(x, f->r + 3 * i + j))
                wctest_fail("checker and solver differ at ray %ld", (long) i);
        }
    fmpz_clear(x);
}

/* L := the full tree's leaves over P (basis: the coordinate planes).  */
static void
full_tree(leaves * L, const planes * P, mpz_t * H)
{
    wc_check_region z[27], zs[3];
    _wc_region3 f[27], fs[3];
    leaves cur = { 0, 0, NULL, NULL }, next;
    fmpz basis[9];
    slong i, k, p, unit[3] = { -1, -1, -1 };

    for (p = 0; p < P->n; p++)
        for (k = 0; k < 3; k++)
            if (fmpz_is_one(P->v + 3 * p + k)
                && _fmpz_vec_is_zero(P->v + 3 * p, k)
                && _fmpz_vec_is_zero(P->v + 3 * p + k + 1, 2 - k))
                unit[k] = p;
    for (k = 0; k < 9; k++)
    {
        fmpz_init(basis + k);
        fmpz_set_ui(basis + k, k % 4 == 0);
    }
    for (k = 0; k < 27; k++)
    {
        _wc_check_region_init(z + k);
        _wc_region3_init(f + k);
    }
    for (k = 0; k < 3; k++)
    {
        _wc_check_region_init(zs + k);
        _wc_region3_init(fs + k);
    }
    {
        mpz_t * B = _wc_check_zvec_new(9);

        for (k = 0; k < 9; k++)
            fmpz_get_mpz(B[k], basis + k);
        if (B == NULL || _wc_check_region_basis(z, B) != 1)
            wctest_fail("the coordinate planes are not a basis");
        _wc_check_zvec_free(B, 9);
    }
    _wc_region3_basis(f, basis);
    for (k = 0; k < 27; k++)
    {
        same_region(z + k, f + k);
        leaves_add(&cur, z + k, f + k);
    }
    for (p = 0; p < P->n; p++)
    {
        if (p == unit[0] || p == unit[1] || p == unit[2])
            continue;
        next.n = next.cap = 0;
        next.Z = NULL;
        next.F = NULL;
        for (i = 0; i < cur.n; i++)
        {
            if (_wc_check_region_split(zs, cur.Z + i, H + 3 * p) != 1)
                wctest_fail("out of memory");
            _wc_region3_split(fs, cur.F + i, P->v + 3 * p);
            for (k = 0; k < 3; k++)
            {
                same_region(zs + k, fs + k);
                if (zs[k].dim >= 0)
                    leaves_add(&next, zs + k, fs + k);
            }
        }
        leaves_clear(&cur);
        cur = next;
    }
    *L = cur;
    for (k = 0; k < 27; k++)
    {
        _wc_check_region_clear(z + k);
        _wc_region3_clear(f + k);
    }
    for (k = 0; k < 3; k++)
    {
        _wc_check_region_clear(zs + k);
        _wc_region3_clear(fs + k);
    }
    for (k = 0; k < 9; k++)
        fmpz_clear(basis + k);
}

static const signed char * sort_sign;
static slong sort_m;

static int
by_sign(const void * x, const void * y)
{
    return memcmp(sort_sign + *(const slong *) x * sort_m,
                  sort_sign + *(const slong *) y * sort_m, (size_t) sort_m);
}

/* The leaves L are the cells A: as many, and each leaf, by the sign
   vector of its point (the sum of its rays), the cell of that sign
   vector with its dimension and its rays (the same primitive directions
   as the cell's 1-cells).  */
static void
compare(const leaves * L, const wc_cells_t A, const planes * P)
{
    slong m = P->n, i, p, j, k, * order, * off, * ray;
    signed char * sign = malloc((size_t) (m + 1)), * table;
    fmpz s[3];
    fmpz_t d;
    wc_error_t err;

    wc_error_init(err);
    fmpz_init(d);
    for (j = 0; j < 3; j++)
        fmpz_init(s + j);
    if (L->n != A->count)
        wctest_fail("%ld leaves, the solver has %ld cells (%ld planes)",
                    (long) L->n, (long) A->count, (long) m);
    if (wc_cells_rays(&off, &ray, A, err) != WC_OK)
        wctest_fail("wc_cells_rays: %s", err->message);
    order = malloc(sizeof(slong) * (A->count + 1));
    for (i = 0; i < A->count; i++)
        order[i] = i;
    sort_sign = table = malloc((size_t) A->count * m + 1);
    for (i = 0; i < A->count; i++)
        wc_cells_signs(table + i * m, A, i);
    sort_m = m;
    qsort(order, A->count, sizeof(slong), by_sign);
    for (i = 0; i < L->n; i++)
    {
        const _wc_region3 * f = L->F + i;
        slong lo = 0, hi = A->count, c;

        _wc_region3_sum(s, f);
        for (p = 0; p < m; p++)
        {
            _fmpz_vec_dot(d, P->v + 3 * p, s, 3);
            sign[p] = (signed char) fmpz_sgn(d);
        }
        while (lo < hi)         /* the first cell with sign >= the leaf's */
        {
            slong mid = (lo + hi) / 2;

            if (memcmp(table + order[mid] * m, sign, (size_t) m) < 0)
                lo = mid + 1;
            else
                hi = mid;
        }
        if (lo == A->count || memcmp(table + order[lo] * m, sign,
                                     (size_t) m) != 0)
            wctest_fail("leaf %ld: no cell has its sign vector", (long) i);
        c = order[lo];
        if (A->dim[c] != f->dim || off[c + 1] - off[c] != f->n)
            wctest_fail("leaf %ld: dim %d with %ld rays, the cell's %ld with "
                        "%ld", (long) i, f->dim, (long) f->n,
                        (long) A->dim[c], (long) (off[c + 1] - off[c]));
        for (j = 0; j < f->n; j++)
        {
            for (k = off[c]; k < off[c + 1]; k++)
                if (_fmpz_vec_equal(f->r + 3 * j, WC_ROW(A->point, ray[k]),
                                    3))
                    break;
            if (k == off[c + 1])
                wctest_fail("leaf %ld: ray %ld is not one of the cell's",
                            (long) i, (long) j);
        }
    }
    free(order);
    free(sign);
    free(table);
    flint_free(off);
    flint_free(ray);
    for (j = 0; j < 3; j++)
        fmpz_clear(s + j);
    fmpz_clear(d);
    wc_error_clear(err);
}

/* Build the tree and the cells and compare; returns the count.  */
static slong
check(const planes * P)
{
    slong m = P->n, i, j, count;
    mpz_t * H = _wc_check_zvec_new(3 * (size_t) m);
    fmpz_mat_t N;
    wc_cells_t A;
    wc_error_t err;
    leaves L;

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
    full_tree(&L, P, H);
    compare(&L, A, P);
    count = L.n;
    leaves_clear(&L);
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
    if ((n = check(&P)) != 1 + 6 + 12 + 8)
        wctest_fail("coordinate planes: %ld cells", (long) n);
    P.n = 0;
    set_plane(&P, -1, -1, -1);
    planes_canonical(&P);
    /* 6 lines, 4 planes of 3 lines each, 14 chambers (Euler) */
    if (P.n != 4 || (n = check(&P)) != 1 + 12 + 24 + 14)
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
        if ((n = check(&P)) != 1 + rays + sectors + chambers)
            wctest_fail("pencil %ld: %ld cells", (long) k, (long) n);
    }
    planes_clear(&P);
}

/* Dependent basis planes: refused.  */
static void
test_refused(void)
{
    mpz_t * H = _wc_check_zvec_new(9);
    wc_check_region R[27];
    int j;

    if (H == NULL)
        wctest_fail("out of memory");
    for (j = 0; j < 27; j++)
        _wc_check_region_init(R + j);
    mpz_set_ui(H[0], 1);
    mpz_set_ui(H[4], 1);
    mpz_set_si(H[6], 3);            /* (3, -2, 0): in the span of the two */
    mpz_set_si(H[7], -2);
    if (_wc_check_region_basis(R, H) != 0)
        wctest_fail("dependent basis planes accepted");
    mpz_set_ui(H[8], 1);
    if (_wc_check_region_basis(R, H) != 1 || R[26].dim != 3 || R[13].dim != 0)
        wctest_fail("an independent basis refused");
    for (j = 0; j < 27; j++)
        _wc_check_region_clear(R + j);
    _wc_check_zvec_free(H, 9);
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
        check(&P);
    }
    planes_clear(&P);
}

int
main(void)
{
    wctest_init("t-checkregion");
    test_hand();
    test_refused();
    test_random();
    return 0;
}
