/* t-planbits.c -- the cells of a cone all at once (_wc_cone_key_cells, sign
   bitsets and a face lookup) against the cell-by-cell answers it
   replaces.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Random problems of 1 to 6 fixels (testutil.h: degenerate layouts
   included -- normals through one point, collinear fixels, zero friction,
   opposed normals); the cones are a plan's needed cones, for n <= 3 also
   the 3^n outcome cones (strict letters: excluded faces), and a few cones
   of random modes whose planes are not in the arrangement (the fallback).
   The arrangement is that of the needed and outcome cones.  Every bit is
   compared with wc_cone_contains at the cell's point (the face lattice,
   the deliberate independent reference) and with _wc_cone_key_contains,
   at every cell when there are few, else at a seeded sample of them and
   of the lower-dimensional cells the bitset holds; and wc_plan's G_goal
   and exact redundancy against per-cell counts (check_plan, also for 4
   and 5 fixels), and _wc_plan_exact on made-up cones (check_made).  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/flint.h>
#include <flint/fmpq.h>

#include "wrenchcone.h"
#include "analysis/planparts.h"
#include "analysis/wrench.h"
#include "testutil.h"

#define BIT(b, i) ((int) (((b)[(i) / FLINT_BITS] >> ((i) % FLINT_BITS)) & 1))

static slong checked, boundary, plans, stopped, several, made,
    made_needed, made_stopped;

/* Compare the bit of cell i of cone k with both references.  */
static void
check_cell(const wc_problem_t P, const ulong * bits, const wc_cone_key * K,
           const wc_cells_t A, slong i, slong k, fmpq * g)
{
    int want, key, got = BIT(bits, i);

    _wc_cellset_point(g, A, i);
    want = wc_cone_contains(K->C, g);
    key = _wc_cone_key_contains(K, A, i, g);
    checked++;
    if (got != want || key != want)
    {
        char * s = wctest_vec_str(g, 3);

        wctest_fail_problem(P, NULL, "cone %ld, cell %ld at %s (dim %ld): "
                            "bitset %d, key %d, face lattice %d", (long) k,
                            (long) i, s, (long) A->dim[i], got, key, want);
    }
}

static void
check_cones(const wc_problem_t P, const wc_cone_struct * C, slong count,
            const wc_cells_t A)
{
    wc_cone_key * K = _wc_cone_keys_init(C, count, A);
    wc_cell_bits X;
    ulong * bits;
    slong k, i, j;
    fmpq g[3];

    if (!_wc_cell_bits_init(&X, A))
        wctest_fail("out of memory");
    bits = malloc(sizeof(ulong) * (X.words + 1));
    for (j = 0; j < 3; j++)
        fmpq_init(g + j);
    for (k = 0; k < count; k++)
    {
        _wc_cone_key_cells(bits, K + k, &X, A);
        if (A->count <= 2000)
        {
            for (i = 0; i < A->count; i++)
                check_cell(P, bits, K + k, A, i, k, g);
            continue;
        }
        for (j = 0; j < 60; j++)
            check_cell(P, bits, K + k, A, wctest_randint(0, A->count - 1), k,
                       g);
        for (i = 0; i < A->count; i++)
            if (BIT(bits, i) && A->dim[i] < 3 && wctest_chance(1, 40))
            {
                boundary++;
                check_cell(P, bits, K + k, A, i, k, g);
            }
    }
    for (j = 0; j < 3; j++)
        fmpq_clear(g + j);
    free(bits);
    _wc_cell_bits_clear(&X);
    _wc_cone_keys_clear(K, count);
}

/* Cones of random modes of P (their planes need not be in A).  */
static void
check_foreign(const wc_problem_t P, const wc_cells_t A)
{
    wc_cone_struct * C = _wc_plan_cones_init(2);
    wc_error_t err;
    char * mode = malloc(P->n + 1);
    slong k;

    wc_error_init(err);
    for (k = 0; k < 2; k++)
    {
        wctest_random_mode(mode, P);
        if (wc_wrench_cone_direct(C + k, NULL, P, mode, err) != WC_OK)
            wctest_fail_problem(P, mode, "wc_wrench_cone_direct failed");
    }
    check_cones(P, C, 2, A);
    _wc_plan_cones_clear(C, 2);
    free(mode);
    wc_error_clear(err);
}

/* wc_plan's G_goal cells and exact redundancy (bitsets, the cells each
   cone is the last of) against the per-cell counts they replace, here
   from wc_cone_contains (the deliberate independent copy of the old
   path; check_made has the same): cell i is in G_goal iff no needed cone
   holds it; in ASCII order a needed cone is dropped when every cell of
   it is held by another cone still kept.  */
static void
check_plan(const wc_problem_t P, slong limit)
{
    wc_plan_t R;
    wc_error_t err;
    slong i, k, nn, * cnt, first;
    int * in;
    fmpq g[3];

    wc_plan_init(R);
    wc_error_init(err);
    if (wc_plan(R, P, 0, err) != WC_OK)
        wctest_fail_problem(P, NULL, "wc_plan: %s", err->message);
    nn = R->T->nneeded;
    if (R->cells->count * nn > limit)
    {
        wc_plan_clear(R);
        wc_error_clear(err);
        return;
    }
    cnt = calloc(R->cells->count + 1, sizeof(slong));
    in = malloc(sizeof(int) * (R->cells->count * nn + 1));
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    for (i = 0; i < R->cells->count; i++)
    {
        _wc_cellset_point(g, R->cells, i);
        for (k = 0; k < nn; k++)
        {
            in[i * nn + k] = wc_cone_contains(R->cones + k, g);
            cnt[i] += in[i * nn + k];
        }
        if ((cnt[i] == 0) != wc_set_contains(R->goal, g))
            wctest_fail_problem(P, NULL, "cell %ld: G_goal %d, by the "
                                "cones %d", (long) i,
                                wc_set_contains(R->goal, g), cnt[i] == 0);
    }
    /* wc_plan stops computing cones, from the last, once they hold
       every cell: count the plans where it does (the first cone holding
       cell i is not the last) and those it does not */
    first = nn;
    for (i = 0; i < R->cells->count; i++)
    {
        for (k = nn - 1; k >= 0 && !in[i * nn + k]; k--)
            ;
        first = FLINT_MIN(first, k);
    }
    stopped += first > 0;
    several += R->nexact > 1;
    for (k = 0; k < nn; k++)
    {
        int covered = 1;

        for (i = 0; i < R->cells->count && covered; i++)
            covered = !in[i * nn + k] || cnt[i] >= 2;
        if (R->exact_needed[k] != !covered)
            wctest_fail_problem(P, NULL, "needed cone %ld: exactly needed "
                                "%d, by the cones %d", (long) k,
                                R->exact_needed[k], !covered);
        for (i = 0; i < R->cells->count && covered; i++)
            cnt[i] -= in[i * nn + k];
    }
    plans++;
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    free(in);
    free(cnt);
    wc_plan_clear(R);
    wc_error_clear(err);
}

/* _wc_plan_exact on made-up cones: random bitsets of every kind
   (empty, every cell, sparse, dense, runs of cells, copies, subsets and
   unions of earlier cones) over 0 to 2000 cells, up to 300 cones,
   against the per-cell counts it replaces (the same independent copy as
   check_plan's: drop a cone, in order, when each of its cells is held by
   at least one other cone still kept); each cone asked for at most
   twice; half the time with the bits past the last cell set, which
   must not count.  */
typedef struct
{
    const ulong * bits;
    slong words, ncells, * calls;
    int dirty;              /* set the bits past the last cell */
}
made_ctx;

static void
made_cells(ulong * out, slong k, void * p)
{
    made_ctx * c = p;

    memcpy(out, c->bits + k * c->words, sizeof(ulong) * c->words);
    if (c->dirty && c->ncells % FLINT_BITS != 0)
        out[c->words - 1] |= UWORD(0) - (UWORD(1) << (c->ncells % FLINT_BITS));
    c->calls[k]++;
}

static void
made_cone(ulong * b, slong k, slong ncells, slong words, int sparse)
{
    static const slong few[] = { 2, 2, 2, 5, 6, 7, 8 };
    slong kind = sparse ? few[wctest_randint(0, 6)] : wctest_randint(0, 8);
    slong i, lo, hi, j = 0;
    ulong * prev = b - words * (k > 0 ? wctest_randint(1, k) : 0);

    if (k > 0)
        j = wctest_randint(0, k - 1);
    for (i = 0; i < ncells; i++)
    {
        int in = 0;

        if (kind == 1)
            in = 1;
        else if (kind == 2)
            in = wctest_chance(1, sparse ? 6 : 20);
        else if (kind == 3)
            in = wctest_chance(1, 2);
        else if (kind == 4)
            in = !wctest_chance(1, 30);
        else if (kind >= 6 && k > 0)
        {
            in = BIT(prev, i);
            if (kind == 7)
                in = in && wctest_chance(3, 4);
            else if (kind == 8)
                in = in || BIT(b - words * (k - j), i);
        }
        b[i / FLINT_BITS] |= (ulong) in << (i % FLINT_BITS);
    }
    if (kind == 5 && ncells > 0)
    {
        lo = wctest_randint(0, ncells - 1);
        hi = wctest_randint(lo, sparse ? FLINT_MIN(lo + 40, ncells - 1)
                            : ncells - 1);
        for (i = lo; i <= hi; i++)
            b[i / FLINT_BITS] |= UWORD(1) << (i % FLINT_BITS);
    }
}

static void
check_made(void)
{
    static const slong sizes[] = { 0, 1, 2, 63, 64, 65, 127, 128, 129 };
    slong ncells = wctest_chance(1, 2) ? sizes[wctest_randint(0, 8)]
        : wctest_randint(1, 2000);
    slong count = wctest_chance(1, 4) ? wctest_randint(0, 3)
        : wctest_randint(4, 300);
    slong words = (ncells + FLINT_BITS - 1) / FLINT_BITS, i, k, first;
    ulong * bits = calloc(count * words + 1, sizeof(ulong));
    ulong * any = malloc(sizeof(ulong) * (ncells / FLINT_BITS + 1));
    slong * cnt = calloc(ncells + 1, sizeof(slong));
    slong * calls = calloc(count + 1, sizeof(slong));
    int * exact = malloc(sizeof(int) * (count + 1));
    /* sparse: the cells are seen a few at a time, from the last cone */
    int sparse = wctest_chance(1, 2);
    made_ctx c;

    for (k = 0; k < count; k++)
        made_cone(bits + k * words, k, ncells, words, sparse);
    c.bits = bits;
    c.words = words;
    c.ncells = ncells;
    c.calls = calls;
    c.dirty = wctest_chance(1, 2);  /* those bits must be ignored */
    if (!_wc_plan_exact(exact, any, count, ncells, made_cells, &c))
        wctest_fail("_wc_plan_exact: out of memory");
    for (k = 0; k < count; k++)
        for (i = 0; i < ncells; i++)
            cnt[i] += BIT(bits + k * words, i);
    /* the cones from the last hold every cell before the first: count
       the cases where the early stop cuts */
    for (i = 0, first = count; i < ncells; i++)
    {
        for (k = count - 1; k >= 0 && !BIT(bits + k * words, i); k--)
            ;
        first = FLINT_MIN(first, k);
    }
    made_stopped += first > 0;
    for (i = 0; i < ncells; i++)
        if (BIT(any, i) != (cnt[i] > 0))
            wctest_fail("%ld cells, %ld cones: cell %ld in a cone %d, by "
                        "the counts %d", (long) ncells, (long) count,
                        (long) i, BIT(any, i), cnt[i] > 0);
    for (k = 0; k < count; k++)
    {
        const ulong * b = bits + k * words;
        int covered = 1;

        for (i = 0; i < ncells && covered; i++)
            covered = !BIT(b, i) || cnt[i] >= 2;
        if (exact[k] != !covered || calls[k] > 2)
            wctest_fail("%ld cells, %ld cones: cone %ld exactly needed %d, "
                        "by the counts %d (%ld calls)", (long) ncells,
                        (long) count, (long) k, exact[k], !covered,
                        (long) calls[k]);
        for (i = 0; i < ncells && covered; i++)
            cnt[i] -= BIT(b, i);
        made++;
        made_needed += exact[k];
    }
    free(bits);
    free(any);
    free(cnt);
    free(calls);
    free(exact);
}

static void
check_problem(const wc_problem_t P)
{
    wc_plan_strings_t T;
    wc_cone_struct * C, * O = NULL;
    wc_cells_t A;
    wc_error_t err;
    fmpz_mat_t planes;
    slong np = 0, k, no = 0;
    int status;

    wc_error_init(err);
    wc_plan_strings_init(T);
    wc_cells_init(A);
    fmpz_mat_init(planes, 0, 3);
    if (wc_plan_strings(T, P->n, err) != WC_OK)
        wctest_fail_problem(P, NULL, "wc_plan_strings failed");
    C = _wc_plan_cones_init(T->nneeded);
    if (_wc_plan_needed_cones(C, T, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "needed cones: %s", err->message);
    for (k = 0; k < T->nneeded; k++)
        _wc_cellset_add_planes(planes, &np, C + k);
    if (P->n <= 3)
    {
        no = _wc_plan_pow3(P->n);
        O = _wc_plan_cones_init(no);
        if (_wc_plan_outcome_cones(O, no, P, err) != WC_OK)
            wctest_fail_problem(P, NULL, "outcome cones: %s", err->message);
        for (k = 0; k < no; k++)
            _wc_cellset_add_planes(planes, &np, O + k);
    }
    status = WC_OK;
    _wc_cellset_build(A, &status, planes, np, err);
    if (status != WC_OK)
        wctest_fail_problem(P, NULL, "cells: %s", err->message);
    check_cones(P, C, T->nneeded, A);
    if (O != NULL)
        check_cones(P, O, no, A);
    check_foreign(P, A);
    _wc_plan_cones_clear(C, T->nneeded);
    _wc_plan_cones_clear(O, no);
    fmpz_mat_clear(planes);
    wc_cells_clear(A);
    wc_plan_strings_clear(T);
    wc_error_clear(err);
}

int
main(void)
{
    slong iter, iters;

    wctest_init("t-planbits");
    iters = wctest_iters(30);
    for (iter = 0; iter < iters; iter++)
    {
        wc_problem_t P;
        slong nmax;

        if (!wctest_iter(iter))
            continue;
        nmax = wctest_chance(1, 6) ? 6 : wctest_chance(1, 3) ? 4 : 3;
        wc_problem_init(P);
        wctest_random_problem(P, 1, nmax);
        check_problem(P);
        check_plan(P, 200000);
        wc_problem_clear(P);
    }
    /* plans of more cones (4 and 5 fixels: 32 and 80), fewer of them;
       iteration iter's seed again (WC_TEST_ITER runs both) */
    for (iter = 0; iter < iters / 6; iter++)
    {
        wc_problem_t P;

        if (!wctest_iter(iter))
            continue;
        wc_problem_init(P);
        wctest_random_problem(P, 4, 5);
        check_plan(P, 4000000);
        wc_problem_clear(P);
    }
    for (iter = 0; iter < 10 * iters; iter++)
        if (wctest_iter(iter))
            check_made();
    printf("t-planbits: %ld problems, %ld cell memberships checked (%ld on "
           "a boundary), %ld plans recounted (%ld stopped early, %ld with "
           "several cones exactly needed)\n", (long) iters, (long) checked,
           (long) boundary, (long) plans, (long) stopped, (long) several);
    printf("t-planbits: %ld made-up cones, %ld exactly needed, %ld sets "
           "stopped early\n", (long) made, (long) made_needed,
           (long) made_stopped);
    flint_cleanup();
    return 0;
}
