/* plansweep.c -- plans over friction: one coefficient everywhere, and the
   critical one.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "analysis/planparts.h"

/* Q := P with mu_s = mu_k = mu everywhere.  */
static int
with_friction(wc_problem_t Q, const wc_problem_t P, const fmpq_t mu)
{
    slong i;
    int status = wc_problem_set(Q, P);

    if (status != WC_OK)
        return status;
    fmpq_set(Q->mu_s, mu);
    fmpq_set(Q->mu_k, mu);
    for (i = 0; i < Q->n; i++)
    {
        fmpq_set(Q->fixels[i].mu_s, mu);
        fmpq_set(Q->fixels[i].mu_k, mu);
    }
    return WC_OK;
}

int
wc_plan_with_friction(wc_plan_t R, const wc_problem_t P, const fmpq_t mu,
                      wc_error_t err)
{
    wc_problem_t Q;
    int status;

    if (fmpq_sgn(mu) < 0)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "a friction coefficient must not be negative");
    wc_problem_init(Q);
    status = with_friction(Q, P, mu);
    if (status == WC_OK)
        status = wc_plan(R, Q, 0, err);
    else
        wc_error_set(err, status, NULL, 0, 0, "out of memory");
    wc_problem_clear(Q);
    return status;
}

void
wc_critical_init(wc_critical_t C)
{
    slong k;

    memset(C, 0, sizeof(wc_critical_struct));
    fmpq_init(C->lo);
    fmpq_init(C->hi);
    for (k = 0; k < 3; k++)
        fmpq_init(C->lo_witness + k);
}

void
wc_critical_clear(wc_critical_t C)
{
    slong k;

    fmpq_clear(C->lo);
    fmpq_clear(C->hi);
    for (k = 0; k < 3; k++)
        fmpq_clear(C->lo_witness + k);
}

/* *inside := the cells of A in one of the count cones of K (a bitset,
   malloc'd).  */
static int
cones_union(ulong ** inside, const wc_cone_key * K, slong count,
            const wc_cells_t A, wc_error_t err)
{
    wc_cell_bits X;
    ulong * buf = NULL;
    int ok = _wc_cell_bits_init(&X, A);

    if (ok)
    {
        buf = malloc(sizeof(ulong) * (X.words + 1));
        *inside = calloc(X.words + 1, sizeof(ulong));
    }
    ok = ok && buf != NULL && *inside != NULL && K != NULL;
    if (ok)
        _wc_cone_keys_union(*inside, K, count, NULL, &X, A, buf);
    free(buf);
    _wc_cell_bits_clear(&X);
    return ok ? WC_OK : wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                     "out of memory (%ld cells)",
                                     (long) A->count);
}

/* Whether G_goal of P at friction mu is empty, with a wrench in it when
   not: the needed cones and their arrangement only.  */
static int
goal_empty(int * empty, fmpq * witness, const wc_plan_strings_t T,
           const wc_problem_t P, const fmpq_t mu, wc_error_t err)
{
    wc_problem_t Q;
    wc_cone_struct * C;
    wc_cells_t cells;
    fmpz_mat_t planes;
    wc_cone_key * keys = NULL;
    ulong * inside = NULL;
    slong np = 0, i, k, nn = T->nneeded;
    int status;

    wc_problem_init(Q);
    wc_cells_init(cells);
    fmpz_mat_init(planes, 0, 3);
    C = _wc_plan_cones_init(nn);
    if ((status = with_friction(Q, P, mu)) != WC_OK)
    {
        wc_error_set(err, status, NULL, 0, 0, "out of memory");
        goto cleanup;
    }
    if ((status = _wc_plan_needed_cones(C, T, Q, err)) != WC_OK)
        goto cleanup;
    for (k = 0; k < nn; k++)
        _wc_cellset_add_planes(planes, &np, C + k);
    _wc_cellset_build(cells, &status, planes, np, err);
    if (status != WC_OK)
        goto cleanup;
    keys = _wc_cone_keys_init(C, nn, cells);
    if ((status = cones_union(&inside, keys, nn, cells, err)) != WC_OK)
        goto cleanup;
    /* the chambers come last; a witness there is the most telling */
    *empty = 1;
    for (i = cells->count - 1; i >= 0 && *empty; i--)
        if (((inside[i / FLINT_BITS] >> (i % FLINT_BITS)) & 1) == 0)
        {
            *empty = 0;
            _wc_cellset_point(witness, cells, i);
        }

cleanup:
    free(inside);
    _wc_cone_keys_clear(keys, nn);
    _wc_plan_cones_clear(C, nn);
    fmpz_mat_clear(planes);
    wc_cells_clear(cells);
    wc_problem_clear(Q);
    return status;
}

/* The sign of x - 2^e.  */
static int
cmp_pow2(const fmpq_t x, slong e)
{
    fmpq_t b;
    int c;

    fmpq_init(b);
    fmpq_one(b);
    if (e >= 0)
        fmpq_mul_2exp(b, b, e);
    else
        fmpq_div_2exp(b, b, -e);
    c = fmpq_cmp(x, b);
    fmpq_clear(b);
    return c;
}

int
wc_critical_width_ok(const fmpq_t width)
{
    return fmpq_sgn(width) > 0
           && cmp_pow2(width, -WC_CRITICAL_MIN_WIDTH_EXP) >= 0;
}

int
wc_critical_max_ok(const fmpq_t max)
{
    return fmpq_sgn(max) > 0
           && cmp_pow2(max, WC_CRITICAL_MAX_FRICTION_EXP) <= 0;
}

int
wc_plan_critical(wc_critical_t C, const wc_problem_t P, const fmpq_t width,
                 const fmpq_t max, wc_error_t err)
{
    wc_plan_strings_t T;
    fmpq_t mid, w, lo, hi;
    fmpq g[3];
    int status, empty = 0;
    slong k;

    if ((status = _wc_plan_check_size(P, 0, err)) != WC_OK)
        return status;
    if (!wc_critical_width_ok(width) || !wc_critical_max_ok(max))
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "the width must be in [2^-%d, oo) and the "
                            "largest friction in (0, 2^%d]",
                            WC_CRITICAL_MIN_WIDTH_EXP,
                            WC_CRITICAL_MAX_FRICTION_EXP);
    wc_plan_strings_init(T);
    fmpq_init(mid);
    fmpq_init(w);
    fmpq_init(lo);
    fmpq_init(hi);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    C->found = C->empty_at_zero = 0;
    C->evals = 0;
    if ((status = wc_plan_strings(T, P->n, err)) != WC_OK)
        goto cleanup;

    /* mu = 0 */
    fmpq_zero(lo);
    C->evals++;
    if ((status = goal_empty(&empty, C->lo_witness, T, P, lo, err))
        != WC_OK)
        goto cleanup;
    if (empty)
    {
        C->found = C->empty_at_zero = 1;
        fmpq_zero(hi);
        goto cleanup;
    }
    /* hi = 1, 2, 4, ... while nonempty, up to max */
    fmpq_one(hi);
    for (;;)
    {
        if (fmpq_cmp(hi, max) > 0)
            fmpq_set(hi, max);
        C->evals++;
        if ((status = goal_empty(&empty, g, T, P, hi, err)) != WC_OK)
            goto cleanup;
        if (empty)
            break;
        fmpq_set(lo, hi);
        for (k = 0; k < 3; k++)
            fmpq_set(C->lo_witness + k, g + k);
        if (fmpq_equal(hi, max))
            goto cleanup;       /* found = 0 */
        fmpq_mul_2exp(hi, hi, 1);
    }
    C->found = 1;
    /* bisect [lo, hi] */
    for (;;)
    {
        fmpq_sub(w, hi, lo);
        if (fmpq_cmp(w, width) <= 0)
            break;
        fmpq_add(mid, lo, hi);
        fmpq_div_2exp(mid, mid, 1);
        C->evals++;
        if ((status = goal_empty(&empty, g, T, P, mid, err)) != WC_OK)
            goto cleanup;
        if (empty)
            fmpq_set(hi, mid);
        else
        {
            fmpq_set(lo, mid);
            for (k = 0; k < 3; k++)
                fmpq_set(C->lo_witness + k, g + k);
        }
    }

cleanup:
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    /* GCC 12 misreads fmpq_t members of *C as 8 bytes: work on locals */
    fmpq_set(C->lo, lo);
    fmpq_set(C->hi, hi);
    fmpq_clear(lo);
    fmpq_clear(hi);
    fmpq_clear(mid);
    fmpq_clear(w);
    wc_plan_strings_clear(T);
    return status;
}
