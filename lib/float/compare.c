/* compare.c -- the comparison of a foreign cone with the exact one:
   each representation read exactly, then its extreme rays and facets
   matched against the exact cone's, and the angular distances.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpq_vec.h>
#include <flint/fmpz_vec.h>

#include "float/compare.h"
#include "float/angle.h"
#include "exact/vec3.h"
#include "exact/zrow.h"

static void
cmp_rep_init(wc_cmp_rep_struct * C)
{
    C->kind = WC_REP_GENERATORS;
    C->line = 0;
    wc_cone_init(C->cone, 3);
    C->nrays = C->nfacets = C->nexact_rays = C->nexact_facets = 0;
    C->rays = C->facets = C->exact_rays = C->exact_facets = NULL;
    C->exact_to_float = C->float_to_exact = C->hausdorff = NAN;
    C->nredundant = 0;
    C->redundant = NULL;
    C->differs = 0;
}

static void
cmp_rep_clear(wc_cmp_rep_struct * C)
{
    wc_cone_clear(C->cone);
    flint_free(C->rays);
    flint_free(C->facets);
    flint_free(C->exact_rays);
    flint_free(C->exact_facets);
    flint_free(C->redundant);
}

void
wc_comparison_init(wc_comparison_t R)
{
    R->tol = WC_COMPARE_TOL;
    R->json_file = 0;
    R->nreps = 0;
    R->file_mode = NULL;
    R->differs = 0;
}

void
wc_comparison_clear(wc_comparison_t R)
{
    slong i;

    for (i = 0; i < R->nreps; i++)
        cmp_rep_clear(R->reps + i);
    free(R->file_mode);
    wc_comparison_init(R);
}

static wc_cmp_vec *
new_vecs(slong n)
{
    wc_cmp_vec * V = flint_calloc(n + 1, sizeof(wc_cmp_vec));
    slong i;

    for (i = 0; i < n; i++)
    {
        V[i].angle = NAN;
        V[i].nearest = -1;
        V[i].nearest_angle = INFINITY;
    }
    return V;
}

/* For each row of A its nearest row of B and the other way round (the
   angle between each pair is computed once).  */
static void
match(wc_cmp_vec ** pa, wc_cmp_vec ** pb, const fmpz_mat_t A,
      const fmpz_mat_t B, double tol)
{
    slong a = fmpz_mat_nrows(A), b = fmpz_mat_nrows(B), i, j;
    wc_cmp_vec * U = new_vecs(a), * V = new_vecs(b);
    fmpq_mat_t Aq, Bq;

    fmpq_mat_init(Aq, a, 3);
    fmpq_mat_init(Bq, b, 3);
    fmpq_mat_set_fmpz_mat(Aq, A);
    fmpq_mat_set_fmpz_mat(Bq, B);
    for (i = 0; i < a; i++)
        _wc_qv3_unit_d(U[i].unit, WC_ROW(Aq, i));
    for (j = 0; j < b; j++)
        _wc_qv3_unit_d(V[j].unit, WC_ROW(Bq, j));
    for (i = 0; i < a; i++)
        for (j = 0; j < b; j++)
        {
            double t = wc_angle_vectors(WC_ROW(Aq, i), WC_ROW(Bq, j));

            if (t < U[i].nearest_angle)
            {
                U[i].nearest_angle = t;
                U[i].nearest = j;
            }
            if (t < V[j].nearest_angle)
            {
                V[j].nearest_angle = t;
                V[j].nearest = i;
            }
        }
    for (i = 0; i < a; i++)
        U[i].matched = U[i].nearest_angle <= tol;
    for (j = 0; j < b; j++)
        V[j].matched = V[j].nearest_angle <= tol;
    fmpq_mat_clear(Aq);
    fmpq_mat_clear(Bq);
    *pa = U;
    *pb = V;
}

/* The angle of every row of A to cl C.  */
static void
angles_to(wc_cmp_vec * U, const fmpz_mat_t A, const wc_cone_t C)
{
    fmpq * v = _fmpq_vec_init(3);
    slong i;

    for (i = 0; i < fmpz_mat_nrows(A); i++)
    {
        _fmpq_vec_set_fmpz_vec(v, WC_ROW(A, i), 3);
        U[i].angle = wc_angle_to_cone(v, C);
    }
    _fmpq_vec_clear(v, 3);
}

/* The file line of an input row (of P) on each canonical vector of X:
   the rows are first stripped of their component in span S (the cone's
   lines for rays, its equalities for facets), as the canonical form
   does.  The lines of the input rows on no canonical vector (redundant
   rows) go to C->redundant.  O(k log k) for k rows: each row's ray is
   looked up among X's sorted rows (tests/t-compare-fast.c checks this
   against the pairwise search it replaced).  */
static int
source_lines(wc_cmp_rep_struct * C, wc_cmp_vec * U, const fmpz_mat_t X,
             const fmpq_mat_t P, const long * lines, const fmpz_mat_t S,
             wc_error_t err)
{
    fmpq * dir = _fmpq_vec_init(3), * p = _fmpq_vec_init(3);
    fmpq * q = _fmpq_vec_init(3);
    fmpz * z = _fmpz_vec_init(3);
    slong r = _wc_rows_span(dir, S), nx = fmpz_mat_nrows(X), i, j, c;
    _wc_zrow * sorted = malloc(sizeof(_wc_zrow) * (nx + 1));

    C->redundant = flint_malloc(sizeof(long) * (fmpq_mat_nrows(P) + 1));
    if (sorted == NULL)
    {
        _fmpq_vec_clear(dir, 3);
        _fmpq_vec_clear(p, 3);
        _fmpq_vec_clear(q, 3);
        _fmpz_vec_clear(z, 3);
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    }
    for (i = 0; i < nx; i++)
    {
        sorted[i].v = WC_ROW(X, i);
        sorted[i].i = i;
    }
    qsort(sorted, nx, sizeof(_wc_zrow), _wc_zrow_cmp);
    for (j = 0; j < fmpq_mat_nrows(P); j++)
    {
        _wc_zrow key, * hit = NULL;
        int on = 0;

        _wc_span_project(q, WC_ROW(P, j), r, dir);
        for (c = 0; c < 3; c++)
            fmpq_sub(p + c, fmpq_mat_entry(P, j, c), q + c);
        /* Two vectors are on the same ray iff their primitive vectors
           are equal, and the canonical vectors of a cone are primitive:
           so a vector's ray is found among them by a binary search.  */
        if (!_wc_qv3_is_zero(p))
        {
            _wc_qvec_primitive(z, p, 3);
            key.v = z;
            hit = bsearch(&key, sorted, nx, sizeof(_wc_zrow),
                          _wc_zrow_cmp);
        }
        /* a second row on the same ray is redundant too */
        if (hit != NULL && U[hit->i].line == 0)
        {
            U[hit->i].line = lines[j];
            on = 1;
        }
        if (!on)
            C->redundant[C->nredundant++] = lines[j];
    }
    free(sorted);
    _fmpq_vec_clear(dir, 3);
    _fmpq_vec_clear(p, 3);
    _fmpq_vec_clear(q, 3);
    _fmpz_vec_clear(z, 3);
    return WC_OK;
}

static int
any_unmatched(const wc_cmp_vec * U, slong n)
{
    slong i;

    for (i = 0; i < n; i++)
        if (!U[i].matched)
            return 1;
    return 0;
}

static int
compare_rep(wc_cmp_rep_struct * C, const wc_cone_t W, const wc_rep_struct * P,
            double tol, wc_error_t err)
{
    wc_cone_struct * F = C->cone;
    int status = WC_OK;

    C->kind = P->kind;
    C->line = P->line;
    if (!P->empty && P->kind == WC_REP_GENERATORS)
        status = wc_cone_set_generators(F, P->rows, P->lin, err);
    else if (!P->empty && P->kind == WC_REP_INEQUALITIES)
        status = wc_cone_set_hrep(F, P->lin, P->rows, NULL, err);
    else
        wc_cone_set_empty(F);
    if (status != WC_OK)
        return status;
    if (W->empty != F->empty)
    {
        C->differs |= WC_CMP_EMPTY;
        return WC_OK;
    }
    if (W->empty)
        return WC_OK;
    if (W->dim != F->dim)
        C->differs |= WC_CMP_DIM;
    if (W->lineality_dim != F->lineality_dim)
        C->differs |= WC_CMP_LINEALITY;

    C->nrays = fmpz_mat_nrows(F->rays);
    C->nexact_rays = fmpz_mat_nrows(W->rays);
    match(&C->rays, &C->exact_rays, F->rays, W->rays, tol);
    angles_to(C->rays, F->rays, W);
    angles_to(C->exact_rays, W->rays, F);
    C->nfacets = fmpz_mat_nrows(F->ineqs);
    C->nexact_facets = fmpz_mat_nrows(W->ineqs);
    match(&C->facets, &C->exact_facets, F->ineqs, W->ineqs, tol);
    if (P->kind == WC_REP_GENERATORS)
        status = source_lines(C, C->rays, F->rays, P->rows, P->row_line,
                              F->lines, err);
    else
        status = source_lines(C, C->facets, F->ineqs, P->rows, P->row_line,
                              F->eqs, err);
    if (status != WC_OK)
        return status;

    status = wc_cone_directed_angle(&C->exact_to_float, NULL, W, F, err);
    if (status == WC_OK)
        status = wc_cone_directed_angle(&C->float_to_exact, NULL, F, W, err);
    if (status != WC_OK)
        return status;
    C->hausdorff = C->exact_to_float > C->float_to_exact
        ? C->exact_to_float : C->float_to_exact;
    if (!(C->hausdorff <= tol))
        C->differs |= WC_CMP_DISTANCE;
    if (any_unmatched(C->rays, C->nrays)
        || any_unmatched(C->exact_rays, C->nexact_rays))
        C->differs |= WC_CMP_RAYS;
    if (any_unmatched(C->facets, C->nfacets)
        || any_unmatched(C->exact_facets, C->nexact_facets))
        C->differs |= WC_CMP_FACETS;
    return WC_OK;
}

int
wc_compare(wc_comparison_t R, const wc_cone_t W, const char * mode,
           const wc_foreign_t F, double tol, wc_error_t err)
{
    slong i;
    int status = WC_OK;

    wc_comparison_clear(R);
    if (!(tol >= 0 && tol < WC_PI / 2))
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "the tolerance must "
                            "be an angle in radians, at least 0 and below "
                            "pi/2");
    if (W->d != 3)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "compare works on "
                            "cones in R^3");
    if (F->nreps == 0)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "no foreign cone "
                            "to compare");
    R->tol = tol;
    R->json_file = F->json;
    if (F->mode != NULL && mode != NULL && strcmp(F->mode, mode) != 0)
    {
        R->file_mode = malloc(strlen(F->mode) + 1);
        if (R->file_mode == NULL)
            return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                "out of memory");
        strcpy(R->file_mode, F->mode);
        R->differs |= WC_CMP_MODE;
    }
    for (i = 0; i < F->nreps && status == WC_OK; i++)
    {
        cmp_rep_init(R->reps + i);
        R->nreps++;
        status = compare_rep(R->reps + i, W, F->reps + i, tol, err);
        R->differs |= R->reps[i].differs;
    }
    if (status != WC_OK)
        wc_comparison_clear(R);
    return status;
}
