/* cddbridge.c -- every cddlib call of the library lives here.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   cddlib traps, all handled here: link -lcddgmp only (GMPRATIONAL);
   setoper.h before cdd.h; dd_set_global_constants() exactly once per
   process (forgetting it gives wrong answers silently), and likewise
   ddf_set_global_constants() for the double build that libcddgmp also
   contains (the ddf_ functions, used by floatcone.c only); dd_NoError is
   not 0; cddlib is not thread-safe.  */

#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <cddlib/setoper.h>
#include <cddlib/cdd.h>
#include <flint/fmpq.h>
#include <flint/fmpq_vec.h>

#include "wrenchcone.h"
#include "exact/cddbridge.h"

static slong
rows_of(const fmpq_mat_t A)
{
    return A == NULL ? 0 : fmpq_mat_nrows(A);
}

/* Write row r of A, scaled by sign, into cdd row dst starting at col 1.  */
static void
put_row(mytype * dst, const fmpq_mat_t A, slong r, int sign, slong d)
{
    slong j;

    for (j = 0; j < d; j++)
    {
        fmpq_get_mpq(dst[j + 1], fmpq_mat_entry(A, r, j));
        if (sign < 0)
            mpq_neg(dst[j + 1], dst[j + 1]);
    }
}

static int
cdd_fail(wc_error_t err, const char * what, dd_ErrorType e)
{
    if (e == dd_NoError)        /* an allocation or copy returned NULL */
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "cddlib failed in %s", what);
    return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                        "cddlib failed in %s (dd_ErrorType %d)", what, (int) e);
}

/* Split the rows of a cdd matrix (homogeneous part, columns 1..d) into
   those in its linearity set and the others, dropping zero rows and rows
   with a nonzero column 0 (the origin vertex cddlib adds to cones).  */
static void
split_rows(fmpq_mat_t lin, fmpq_mat_t other, dd_MatrixPtr M, slong d,
           int negate)
{
    slong i, j, nl = 0, no = 0, m = M->rowsize;
    fmpq_mat_t L, O;

    fmpq_mat_init(L, m, d);
    fmpq_mat_init(O, m, d);
    for (i = 0; i < m; i++)
    {
        int zero = 1, is_lin = set_member(i + 1, M->linset);
        fmpq_mat_struct * T = is_lin ? L : O;
        slong r = is_lin ? nl : no;

        if (mpq_sgn(M->matrix[i][0]) != 0)
            continue;
        for (j = 0; j < d; j++)
        {
            fmpq_set_mpq(fmpq_mat_entry(T, r, j), M->matrix[i][j + 1]);
            if (negate)
                fmpq_neg(fmpq_mat_entry(T, r, j), fmpq_mat_entry(T, r, j));
            if (!fmpq_is_zero(fmpq_mat_entry(T, r, j)))
                zero = 0;
        }
        if (zero)
            continue;           /* row r is overwritten by the next one */
        if (is_lin)
            nl++;
        else
            no++;
    }
    fmpq_mat_clear(lin);
    fmpq_mat_clear(other);
    fmpq_mat_init(lin, nl, d);
    fmpq_mat_init(other, no, d);
    for (i = 0; i < nl; i++)
        for (j = 0; j < d; j++)
            fmpq_set(fmpq_mat_entry(lin, i, j), fmpq_mat_entry(L, i, j));
    for (i = 0; i < no; i++)
        for (j = 0; j < d; j++)
            fmpq_set(fmpq_mat_entry(other, i, j), fmpq_mat_entry(O, i, j));
    fmpq_mat_clear(L);
    fmpq_mat_clear(O);
}

int
_wc_cdd_h_to_v(fmpq_mat_t rays, fmpq_mat_t lines, slong d,
               const fmpq_mat_t E, const fmpq_mat_t H, wc_error_t err)
{
    dd_MatrixPtr A = NULL, G = NULL;
    dd_PolyhedraPtr poly = NULL;
    dd_ErrorType e = dd_NoError;
    slong ne = rows_of(E), nh = rows_of(H), i, r = 0;
    int status = WC_OK;

    wc_init();
    /* Row 0 is the trivial 1 >= 0: cddlib then never sees an empty matrix.
       A row b - a.x >= 0 holds the homogeneous h.x <= 0 as (0, -h).  */
    A = dd_CreateMatrix(1 + ne + nh, d + 1);
    if (A == NULL)
    {
        status = cdd_fail(err, "dd_CreateMatrix", e);
        goto cleanup;
    }
    A->representation = dd_Inequality;
    A->numbtype = dd_Rational;
    mpq_set_ui(A->matrix[0][0], 1, 1);
    r = 1;
    for (i = 0; i < ne; i++, r++)
    {
        put_row(A->matrix[r], E, i, -1, d);
        set_addelem(A->linset, r + 1);
    }
    for (i = 0; i < nh; i++, r++)
        put_row(A->matrix[r], H, i, -1, d);

    poly = dd_DDMatrix2Poly(A, &e);
    if (e != dd_NoError || poly == NULL)
    {
        status = cdd_fail(err, "dd_DDMatrix2Poly", e);
        goto cleanup;
    }
    G = dd_CopyGenerators(poly);
    if (G == NULL)
    {
        status = cdd_fail(err, "dd_CopyGenerators", e);
        goto cleanup;
    }
    split_rows(lines, rays, G, d, 0);

cleanup:
    if (G != NULL)
        dd_FreeMatrix(G);
    if (poly != NULL)
        dd_FreePolyhedra(poly);
    if (A != NULL)
        dd_FreeMatrix(A);
    return status;
}

int
_wc_cdd_v_to_h(fmpq_mat_t E, fmpq_mat_t H, slong d, const fmpq_mat_t rays,
               const fmpq_mat_t lines, wc_error_t err)
{
    dd_MatrixPtr A = NULL, I = NULL;
    dd_PolyhedraPtr poly = NULL;
    dd_ErrorType e = dd_NoError;
    slong nr = rows_of(rays), nl = rows_of(lines), i, r = 0;
    int status = WC_OK;

    wc_init();
    /* Row 0 is the origin, the apex: a generator row (1, 0..0).  */
    A = dd_CreateMatrix(1 + nr + nl, d + 1);
    if (A == NULL)
    {
        status = cdd_fail(err, "dd_CreateMatrix", e);
        goto cleanup;
    }
    A->representation = dd_Generator;
    A->numbtype = dd_Rational;
    mpq_set_ui(A->matrix[0][0], 1, 1);
    r = 1;
    for (i = 0; i < nl; i++, r++)
    {
        put_row(A->matrix[r], lines, i, 1, d);
        set_addelem(A->linset, r + 1);
    }
    for (i = 0; i < nr; i++, r++)
        put_row(A->matrix[r], rays, i, 1, d);

    poly = dd_DDMatrix2Poly(A, &e);
    if (e != dd_NoError || poly == NULL)
    {
        status = cdd_fail(err, "dd_DDMatrix2Poly", e);
        goto cleanup;
    }
    I = dd_CopyInequalities(poly);
    if (I == NULL)
    {
        status = cdd_fail(err, "dd_CopyInequalities", e);
        goto cleanup;
    }
    /* b - a.x >= 0 with b = 0 is our h.x <= 0 with h = a: negate back.
       A row with b != 0 can only be the trivial 1 >= 0; split_rows drops
       it.  */
    split_rows(E, H, I, d, 1);

cleanup:
    if (I != NULL)
        dd_FreeMatrix(I);
    if (poly != NULL)
        dd_FreePolyhedra(poly);
    if (A != NULL)
        dd_FreeMatrix(A);
    return status;
}

int
_wc_cdd_lp_min(fmpq * x, fmpq_t val, const fmpq_mat_t A, const fmpq * b,
               const int * eq, const fmpq * c, wc_error_t err)
{
    slong m = fmpq_mat_nrows(A), nv = fmpq_mat_ncols(A), i, j;
    dd_MatrixPtr M = NULL;
    dd_LPPtr lp = NULL;
    dd_ErrorType e = dd_NoError;
    int res = -1;

    wc_init();
    M = dd_CreateMatrix(m, nv + 1);
    if (M == NULL)
    {
        cdd_fail(err, "dd_CreateMatrix", e);
        goto cleanup;
    }
    M->representation = dd_Inequality;
    M->numbtype = dd_Rational;
    M->objective = dd_LPmin;
    for (i = 0; i < m; i++)
    {
        fmpq_get_mpq(M->matrix[i][0], b + i);
        mpq_neg(M->matrix[i][0], M->matrix[i][0]);
        for (j = 0; j < nv; j++)
            fmpq_get_mpq(M->matrix[i][j + 1], fmpq_mat_entry(A, i, j));
        if (eq[i])
            set_addelem(M->linset, i + 1);
    }
    mpq_set_ui(M->rowvec[0], 0, 1);
    for (j = 0; j < nv; j++)
        fmpq_get_mpq(M->rowvec[j + 1], c + j);
    lp = dd_Matrix2LP(M, &e);
    if (lp == NULL || e != dd_NoError)
    {
        cdd_fail(err, "dd_Matrix2LP", e);
        goto cleanup;
    }
    if (!dd_LPSolve(lp, dd_DualSimplex, &e) || e != dd_NoError)
    {
        cdd_fail(err, "dd_LPSolve", e);
        goto cleanup;
    }
    if (lp->LPS == dd_Optimal)
    {
        for (j = 0; j < nv; j++)
            fmpq_set_mpq(x + j, lp->sol[j + 1]);
        fmpq_set_mpq(val, lp->optvalue);
        res = 1;
    }
    else if (lp->LPS == dd_Inconsistent)
        res = 0;
    else if (lp->LPS == dd_DualInconsistent || lp->LPS == dd_StrucDualInconsistent)
        res = 2;
    else
        wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                     "cddlib LP ended with status %d", (int) lp->LPS);

cleanup:
    if (lp != NULL)
        dd_FreeLPData(lp);
    if (M != NULL)
        dd_FreeMatrix(M);
    return res;
}

int
_wc_cdd_lp_point(fmpq * x, const fmpq_mat_t A, const fmpq * b,
                 const int * eq, wc_error_t err)
{
    slong nv = fmpq_mat_ncols(A);
    fmpq * c = _fmpq_vec_init(nv + 1);
    fmpq_t val;
    int res;

    /* A zero objective: any feasible basic point is optimal.  */
    fmpq_init(val);
    res = _wc_cdd_lp_min(x, val, A, b, eq, c, err);
    if (res == 2)
        res = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "cddlib: a zero "
                            "objective reported unbounded"), -1);
    fmpq_clear(val);
    _fmpq_vec_clear(c, nv + 1);
    return res;
}

/* ---------------------------------------------------------------------
   cddlib's double-precision build (ddf_), for the float baseline.  */

static slong
drows_of(const d_mat_t A)
{
    return A == NULL ? 0 : A->r;
}

static void
dput_row(myfloat * dst, const d_mat_t A, slong r, int sign, slong d)
{
    slong j;

    for (j = 0; j < d; j++)
        ddf_set_d(dst[j + 1], sign < 0 ? -d_mat_entry(A, r, j)
                  : d_mat_entry(A, r, j));
}

/* The double build fails on ill-conditioned input where the GMP build
   cannot; name the two ways it does.  */
static int
cddf_fail(wc_error_t err, const char * what, ddf_ErrorType e)
{
    const char * why = e == ddf_NumericallyInconsistent
        ? ": numerically inconsistent" : e == ddf_LPCycling ? ": LP cycling"
        : "";

    if (e == ddf_NoError)
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "cddlib (double) failed in %s", what);
    return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                        "cddlib (double) failed in %s%s (ddf_ErrorType %d)",
                        what, why, (int) e);
}

/* split_rows for a ddf matrix.  A row is the apex or the trivial 1 >= 0
   row when its column 0 outweighs the rest (exact zero is not a safe test
   in doubles either way), and dropped like a zero row.  */
static void
dsplit_rows(d_mat_t lin, d_mat_t other, ddf_MatrixPtr M, slong d,
            int negate)
{
    slong i, j, nl = 0, no = 0, m = M->rowsize;
    d_mat_t L, O;

    d_mat_init(L, m, d);
    d_mat_init(O, m, d);
    for (i = 0; i < m; i++)
    {
        int is_lin = set_member(i + 1, M->linset);
        double big = 0.0, c0 = ddf_get_d(M->matrix[i][0]);
        d_mat_struct * T = is_lin ? L : O;
        slong r = is_lin ? nl : no;

        for (j = 0; j < d; j++)
        {
            double x = ddf_get_d(M->matrix[i][j + 1]);

            d_mat_entry(T, r, j) = negate ? -x : x;
            if (fabs(x) > big)
                big = fabs(x);
        }
        if (big == 0.0 || fabs(c0) >= big)
            continue;           /* row r is overwritten by the next one */
        if (is_lin)
            nl++;
        else
            no++;
    }
    d_mat_clear(lin);
    d_mat_clear(other);
    d_mat_init(lin, nl, d);
    d_mat_init(other, no, d);
    for (i = 0; i < nl; i++)
        for (j = 0; j < d; j++)
            d_mat_entry(lin, i, j) = d_mat_entry(L, i, j);
    for (i = 0; i < no; i++)
        for (j = 0; j < d; j++)
            d_mat_entry(other, i, j) = d_mat_entry(O, i, j);
    d_mat_clear(L);
    d_mat_clear(O);
}

/* ddf_FreePolyhedra, minus most of a leak of cddlib 0.94 that its double
   build shows on exactly the input this route exists for.  The double
   description (default lexmin order, a "pre-ordered" run) keeps, per row
   still to come, a list of adjacent ray pairs (cone->Edges) and consumes
   a list when it reaches its row; FreePolyhedra frees the array of lists
   but not the lists.  After an exact run they are empty; after a run that
   its 1e-7 tolerance made inconsistent, lists of rows never reached are
   left, and freed here.  What cannot be freed from outside: edges the run
   adds to the very list it is consuming, which it then drops (about 1 in
   2000 degenerate problems, 24 bytes each; tests/lsan.supp names it).
   The dynamic orders (ddf_MaxCutoff, ...) avoid that but print "Equal
   records found !!!!" to stderr on near-duplicate rays, so no.  */
static void
cddf_free_polyhedra(ddf_PolyhedraPtr poly)
{
    ddf_ConePtr cone = poly->child;
    ddf_rowrange k;

    /* cone->Edges has m_alloc entries (cddlib's InitializeConeData);
       NULLing them keeps a cddlib that frees the lists itself safe.  */
    if (cone != NULL && cone->Edges != NULL)
        for (k = 0; k < cone->m_alloc; k++)
            while (cone->Edges[k] != NULL)
            {
                ddf_AdjacencyPtr edge = cone->Edges[k];

                cone->Edges[k] = edge->Next;
                free(edge);
            }
    ddf_FreePolyhedra(poly);
}

int
_wc_cddf_h_to_v(d_mat_t rays, d_mat_t lines, slong d, const d_mat_t E,
                const d_mat_t H, wc_error_t err)
{
    ddf_MatrixPtr A = NULL, G = NULL;
    ddf_PolyhedraPtr poly = NULL;
    ddf_ErrorType e = ddf_NoError;
    slong ne = drows_of(E), nh = drows_of(H), i, r;
    int status = WC_OK;

    wc_init();
    /* As _wc_cdd_h_to_v: row 0 is 1 >= 0, h.x <= 0 is the row (0, -h).  */
    A = ddf_CreateMatrix(1 + ne + nh, d + 1);
    if (A == NULL)
    {
        status = cddf_fail(err, "ddf_CreateMatrix", e);
        goto cleanup;
    }
    A->representation = ddf_Inequality;
    A->numbtype = ddf_Real;
    ddf_set_d(A->matrix[0][0], 1.0);
    r = 1;
    for (i = 0; i < ne; i++, r++)
    {
        dput_row(A->matrix[r], E, i, -1, d);
        set_addelem(A->linset, r + 1);
    }
    for (i = 0; i < nh; i++, r++)
        dput_row(A->matrix[r], H, i, -1, d);

    poly = ddf_DDMatrix2Poly(A, &e);
    if (e != ddf_NoError || poly == NULL)
    {
        status = cddf_fail(err, "ddf_DDMatrix2Poly", e);
        goto cleanup;
    }
    G = ddf_CopyGenerators(poly);
    if (G == NULL)
    {
        status = cddf_fail(err, "ddf_CopyGenerators", e);
        goto cleanup;
    }
    dsplit_rows(lines, rays, G, d, 0);

cleanup:
    if (G != NULL)
        ddf_FreeMatrix(G);
    if (poly != NULL)
        cddf_free_polyhedra(poly);
    if (A != NULL)
        ddf_FreeMatrix(A);
    return status;
}

int
_wc_cddf_v_to_h(d_mat_t E, d_mat_t H, slong d, const d_mat_t rays,
                const d_mat_t lines, wc_error_t err)
{
    ddf_MatrixPtr A = NULL, I = NULL;
    ddf_PolyhedraPtr poly = NULL;
    ddf_ErrorType e = ddf_NoError;
    slong nr = drows_of(rays), nl = drows_of(lines), i, r;
    int status = WC_OK;

    wc_init();
    /* Row 0 is the apex (1, 0..0).  */
    A = ddf_CreateMatrix(1 + nr + nl, d + 1);
    if (A == NULL)
    {
        status = cddf_fail(err, "ddf_CreateMatrix", e);
        goto cleanup;
    }
    A->representation = ddf_Generator;
    A->numbtype = ddf_Real;
    ddf_set_d(A->matrix[0][0], 1.0);
    r = 1;
    for (i = 0; i < nl; i++, r++)
    {
        dput_row(A->matrix[r], lines, i, 1, d);
        set_addelem(A->linset, r + 1);
    }
    for (i = 0; i < nr; i++, r++)
        dput_row(A->matrix[r], rays, i, 1, d);

    poly = ddf_DDMatrix2Poly(A, &e);
    if (e != ddf_NoError || poly == NULL)
    {
        status = cddf_fail(err, "ddf_DDMatrix2Poly", e);
        goto cleanup;
    }
    I = ddf_CopyInequalities(poly);
    if (I == NULL)
    {
        status = cddf_fail(err, "ddf_CopyInequalities", e);
        goto cleanup;
    }
    dsplit_rows(E, H, I, d, 1);

cleanup:
    if (I != NULL)
        ddf_FreeMatrix(I);
    if (poly != NULL)
        cddf_free_polyhedra(poly);
    if (A != NULL)
        ddf_FreeMatrix(A);
    return status;
}

int
_wc_cddf_lp_feasible(const d_mat_t H0, const d_mat_t H1, slong d,
                     wc_error_t err)
{
    slong n0 = drows_of(H0), n1 = drows_of(H1), i, j;
    ddf_MatrixPtr M = NULL;
    ddf_LPPtr lp = NULL;
    ddf_ErrorType e = ddf_NoError;
    int res = -1;

    wc_init();
    /* Row 0 is 1 >= 0, so that cddlib never sees an empty system; then
       (0, -h) for h.x <= 0 and (-1, -h) for h.x <= -1.  Objective 0.  */
    M = ddf_CreateMatrix(1 + n0 + n1, d + 1);
    if (M == NULL)
    {
        cddf_fail(err, "ddf_CreateMatrix", e);
        goto cleanup;
    }
    M->representation = ddf_Inequality;
    M->numbtype = ddf_Real;
    M->objective = ddf_LPmax;
    ddf_set_d(M->matrix[0][0], 1.0);
    for (i = 0; i < n0; i++)
        dput_row(M->matrix[1 + i], H0, i, -1, d);
    for (i = 0; i < n1; i++)
    {
        ddf_set_d(M->matrix[1 + n0 + i][0], -1.0);
        dput_row(M->matrix[1 + n0 + i], H1, i, -1, d);
    }
    for (j = 0; j <= d; j++)
        ddf_set_d(M->rowvec[j], 0.0);
    lp = ddf_Matrix2LP(M, &e);
    if (lp == NULL || e != ddf_NoError)
    {
        cddf_fail(err, "ddf_Matrix2LP", e);
        goto cleanup;
    }
    if (!ddf_LPSolve(lp, ddf_DualSimplex, &e) || e != ddf_NoError)
    {
        cddf_fail(err, "ddf_LPSolve", e);
        goto cleanup;
    }
    switch (lp->LPS)
    {
    case ddf_Optimal:
        res = 1;
        break;
    case ddf_Inconsistent:
    case ddf_StrucInconsistent:
        res = 0;
        break;
    default:
        wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                     "cddlib (double) LP ended with status %d", (int) lp->LPS);
        break;
    }

cleanup:
    if (lp != NULL)
        ddf_FreeLPData(lp);
    if (M != NULL)
        ddf_FreeMatrix(M);
    return res;
}
