/* cddbridge.c -- every cddlib call of the library lives here.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   cddlib traps, all handled here: link -lcddgmp only (GMPRATIONAL);
   setoper.h before cdd.h; dd_set_global_constants() exactly once per
   process (forgetting it gives wrong answers silently), and likewise
   ddf_set_global_constants() for the double build that libcddgmp also
   contains (the ddf_ functions, used by floatcone.c only); dd_NoError is
   not 0; cddlib is not thread-safe.

   Threads.  dd_set_global_constants() writes cddlib's constants (dd_zero,
   dd_one, ..., the choice of LP solver), which are only read after: it
   runs once, under pthread_once (wc_init).  But the LP and the double
   description keep scratch arrays in static variables of their functions
   (dd_LPSolve's and dd_AddNewHalfspace's, among others, reallocated when
   the dimension changes) and count pivots in globals (dd_statBApivots,
   ...): two threads inside cddlib free each other's arrays.  So every
   entry point here holds one lock, cdd_lock, from its first cddlib call
   to its last; the work around cddlib (our kernels, FLINT, the rest of a
   request) runs in parallel.  A program that calls cddlib itself, beside
   the library, must not do so while library calls run in other threads.

   The two conversions are written once, in cddconv.inc, and included
   here for each build; the LPs differ between the builds and are
   written out.  */

#include <config.h>

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <cddlib/setoper.h>
#include <cddlib/cdd.h>
#include <flint/fmpq.h>
#include <flint/fmpq_vec.h>

#include "core/version.h"
#include "exact/cddbridge.h"

/* Set once by wc_init, read only after.  */
static pthread_once_t cdd_once = PTHREAD_ONCE_INIT;
/* Held by whoever is inside cddlib.  */
static pthread_mutex_t cdd_lock = PTHREAD_MUTEX_INITIALIZER;

static void
cdd_constants(void)
{
    dd_set_global_constants();
    /* ddf_zero, the double build's tolerance, is used by floatcone.c (the
       GMP build's dd_set_global_constants sets it too, in cddlib 0.94m;
       once more is harmless).  */
    ddf_set_global_constants();
}

void
wc_init(void)
{
    pthread_once(&cdd_once, cdd_constants);
}

const char *
wc_cdd_version(void)
{
    return dd_DDVERSION " (" dd_ARITHMETIC ")";
}

/* Into cddlib, and out of it: every entry point below, around all of
   its cddlib calls.  */
static void
cdd_enter(void)
{
    wc_init();
    pthread_mutex_lock(&cdd_lock);
}

static void
cdd_leave(void)
{
    pthread_mutex_unlock(&cdd_lock);
}

/* The error record of a failed cddlib call; build names the arithmetic
   (" (double)" or ""), why the failure when known.  */
static int
fail_in(wc_error_t err, const char * build, const char * type,
        const char * what, int no_error, int e, const char * why)
{
    if (no_error)               /* an allocation or copy returned NULL */
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "cddlib%s failed in %s", build, what);
    return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                        "cddlib%s failed in %s%s (%s %d)", build, what, why,
                        type, e);
}

/* ---------------------------------------------------------------------
   The GMP build (dd_): exact.  */

static int
cdd_fail(wc_error_t err, const char * what, dd_ErrorType e)
{
    return fail_in(err, "", "dd_ErrorType", what, e == dd_NoError, (int) e,
                   "");
}

/* A row of ours: column 0 zero (not the apex nor 1 >= 0), the rest not.  */
static int
keep_mpq(mytype * row, slong d)
{
    slong j;

    if (mpq_sgn(row[0]) != 0)
        return 0;
    for (j = 0; j < d; j++)
        if (mpq_sgn(row[j + 1]) != 0)
            return 1;
    return 0;
}

#define CDDC(x) dd_ ## x
#define CDDC_WC(x) _wc_cdd_ ## x
#define CDDC_LOCAL(x) x ## _mpq
#define CDDC_MAT fmpq_mat_struct
#define CDDC_MAT_T fmpq_mat_t
#define CDDC_NROWS(A) fmpq_mat_nrows(A)
#define CDDC_MAT_INIT(A, r, c) fmpq_mat_init(A, r, c)
#define CDDC_MAT_CLEAR(A) fmpq_mat_clear(A)
#define CDDC_NUMBTYPE dd_Rational
#define CDDC_PUT(x, A, i, j, sign) \
    do { \
        fmpq_get_mpq(x, fmpq_mat_entry(A, i, j)); \
        if ((sign) < 0) \
            mpq_neg(x, x); \
    } while (0)
#define CDDC_GET(A, i, j, x, neg) \
    do { \
        fmpq_set_mpq(fmpq_mat_entry(A, i, j), x); \
        if (neg) \
            fmpq_neg(fmpq_mat_entry(A, i, j), fmpq_mat_entry(A, i, j)); \
    } while (0)
#define CDDC_KEEP(row, d) keep_mpq(row, d)
#define CDDC_FAIL(err, what, e) cdd_fail(err, what, e)
#define CDDC_FREE_POLY(p) dd_FreePolyhedra(p)
#include "exact/cddconv.inc"

int
_wc_cdd_lp_min(fmpq * x, fmpq_t val, const fmpq_mat_t A, const fmpq * b,
               const int * eq, const fmpq * c, wc_error_t err)
{
    slong m = fmpq_mat_nrows(A), nv = fmpq_mat_ncols(A), i, j;
    dd_MatrixPtr M = NULL;
    dd_LPPtr lp = NULL;
    dd_ErrorType e = dd_NoError;
    int res = -1;

    cdd_enter();
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
    cdd_leave();
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

/* The double build fails on ill-conditioned input where the GMP build
   cannot; name the two ways it does.  */
static int
cddf_fail(wc_error_t err, const char * what, ddf_ErrorType e)
{
    return fail_in(err, " (double)", "ddf_ErrorType", what, e == ddf_NoError,
                   (int) e, e == ddf_NumericallyInconsistent
                   ? ": numerically inconsistent" : e == ddf_LPCycling
                   ? ": LP cycling" : "");
}

/* A row is the apex or the trivial 1 >= 0 row when its column 0
   outweighs the rest (exact zero is not a safe test in doubles either
   way), and dropped like a zero row.  */
static int
keep_double(myfloat * row, slong d)
{
    double big = 0.0, c0 = ddf_get_d(row[0]);
    slong j;

    for (j = 0; j < d; j++)
        if (fabs(ddf_get_d(row[j + 1])) > big)
            big = fabs(ddf_get_d(row[j + 1]));
    return !(big == 0.0 || fabs(c0) >= big);
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

#define CDDC(x) ddf_ ## x
#define CDDC_WC(x) _wc_cddf_ ## x
#define CDDC_LOCAL(x) x ## _double
#define CDDC_MAT d_mat_struct
#define CDDC_MAT_T d_mat_t
#define CDDC_NROWS(A) ((A)->r)
#define CDDC_MAT_INIT(A, r, c) d_mat_init(A, r, c)
#define CDDC_MAT_CLEAR(A) d_mat_clear(A)
#define CDDC_NUMBTYPE ddf_Real
#define CDDC_PUT(x, A, i, j, sign) \
    ddf_set_d(x, (sign) < 0 ? -d_mat_entry(A, i, j) : d_mat_entry(A, i, j))
#define CDDC_GET(A, i, j, x, neg) \
    (d_mat_entry(A, i, j) = (neg) ? -ddf_get_d(x) : ddf_get_d(x))
#define CDDC_KEEP(row, d) keep_double(row, d)
#define CDDC_FAIL(err, what, e) cddf_fail(err, what, e)
#define CDDC_FREE_POLY(p) cddf_free_polyhedra(p)
#include "exact/cddconv.inc"

/* cdd row dst := (., -row r of A), our h.x <= .. as cdd's b - h.x >= 0.  */
static void
put_rows_double(myfloat * dst, const d_mat_t A, slong r, slong d)
{
    slong j;

    for (j = 0; j < d; j++)
        ddf_set_d(dst[j + 1], -d_mat_entry(A, r, j));
}

int
_wc_cddf_lp_feasible(const d_mat_t H0, const d_mat_t H1, slong d,
                     wc_error_t err)
{
    slong n0 = (H0 == NULL ? 0 : H0->r), n1 = (H1 == NULL ? 0 : H1->r), i, j;
    ddf_MatrixPtr M = NULL;
    ddf_LPPtr lp = NULL;
    ddf_ErrorType e = ddf_NoError;
    int res = -1;

    cdd_enter();
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
        put_rows_double(M->matrix[1 + i], H0, i, d);
    for (i = 0; i < n1; i++)
    {
        ddf_set_d(M->matrix[1 + n0 + i][0], -1.0);
        put_rows_double(M->matrix[1 + n0 + i], H1, i, d);
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
    cdd_leave();
    return res;
}
