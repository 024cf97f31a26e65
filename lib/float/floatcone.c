/* floatcone.c -- the paper's route in doubles, its printer, and a
   comparison with the exact cone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   This is deliberately the code a careful float implementation of the
   paper's Section 5 would be: the same matrices as paper.c, in doubles,
   with cddlib's double-precision build for K^F, the emptiness LP and the
   closure.  It is not made more robust than that (no exact fallback, no
   rescaling tricks), because its job is to be the honest baseline.  The
   tolerances are documented in floatcone.h.  Every ddf_ call is in
   cddbridge.c.  */

#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "float/floatcone.h"
#include "exact/cddbridge.h"
#include "model/table2.h"

/* ---------------------------------------------------------------------
   Small helpers on double matrices (FLINT's d_mat) and their rows.  */

/* A := a zero r x c matrix.  */
static void
dm_reinit(d_mat_t A, slong r, slong c)
{
    d_mat_clear(A);
    d_mat_init(A, r, c);
    if (r > 0 && c > 0)
        d_mat_zero(A);
}

/* The Euclidean length of v, scaled so that huge or tiny entries neither
   overflow nor underflow in the squares.  */
static double
dvec_norm(const double * v, slong d)
{
    double big = 0.0, s = 0.0;
    slong j;

    for (j = 0; j < d; j++)
        if (fabs(v[j]) > big)
            big = fabs(v[j]);
    if (big == 0.0 || !isfinite(big))
        return big;
    for (j = 0; j < d; j++)
        s += (v[j] / big) * (v[j] / big);
    return big * sqrt(s);
}

static double
dvec_dot(const double * a, const double * b, slong d)
{
    double s = 0.0;
    slong j;

    for (j = 0; j < d; j++)
        s += a[j] * b[j];
    return s;
}

/* Scale v to unit length; returns its former length (v unchanged when
   that is 0).  */
static double
dvec_normalise(double * v, slong d)
{
    double n = dvec_norm(v, d);
    slong j;

    if (n > 0.0)
        for (j = 0; j < d; j++)
            v[j] /= n;
    return n;
}

/* v := v minus its projection onto the span of the orthonormal rows of
   Q.  */
static void
dvec_project_out(double * v, const d_mat_t Q, slong d)
{
    slong i, j;

    for (i = 0; i < Q->r; i++)
    {
        double c = dvec_dot(v, Q->rows[i], d);

        for (j = 0; j < d; j++)
            v[j] -= c * d_mat_entry(Q, i, j);
    }
}

/* The Frobenius norm of A.  */
static double
dm_norm(const d_mat_t A)
{
    double big = 0.0, s = 0.0;
    slong i;

    for (i = 0; i < A->r; i++)
        big = fmax(big, dvec_norm(A->rows[i], A->c));
    if (big == 0.0 || !isfinite(big))
        return big;
    for (i = 0; i < A->r; i++)
    {
        double t = dvec_norm(A->rows[i], A->c) / big;

        s += t * t;
    }
    return big * sqrt(s);
}

static int
dm_is_finite(const d_mat_t A)
{
    slong i, j;

    for (i = 0; i < A->r; i++)
        for (j = 0; j < A->c; j++)
            if (!isfinite(d_mat_entry(A, i, j)))
                return 0;
    return 1;
}

/* Keep the first k rows of A (k <= rows).  */
static void
dm_keep_rows(d_mat_t A, slong k)
{
    slong d = A->c, i, j;
    d_mat_t T;

    d_mat_init(T, k, d);
    for (i = 0; i < k; i++)
        for (j = 0; j < d; j++)
            d_mat_entry(T, i, j) = d_mat_entry(A, i, j);
    d_mat_swap(A, T);
    d_mat_clear(T);
}

/* Replace the rows of A by an orthonormal basis of their span (modified
   Gram-Schmidt); a row whose remainder is shorter than tol times its
   length is taken as dependent and dropped.  */
static void
dm_orthonormalise(d_mat_t A, double tol)
{
    slong d = A->c, i, j, l, k = 0;

    for (i = 0; i < A->r; i++)
    {
        double * v = A->rows[k];

        if (k != i)
            for (j = 0; j < d; j++)
                v[j] = d_mat_entry(A, i, j);
        if (dvec_normalise(v, d) == 0.0)
            continue;
        for (l = 0; l < k; l++)
        {
            double c = dvec_dot(v, A->rows[l], d);

            for (j = 0; j < d; j++)
                v[j] -= c * d_mat_entry(A, l, j);
        }
        if (dvec_normalise(v, d) > tol)
            k++;
    }
    dm_keep_rows(A, k);
}

/* Make every row of A a unit vector orthogonal to the orthonormal rows
   of Q (when Q is not NULL); rows that vanish (below tol after the
   projection) are dropped.  */
static void
dm_unit_rows(d_mat_t A, const d_mat_t Q, double tol)
{
    slong d = A->c, i, j, k = 0;

    for (i = 0; i < A->r; i++)
    {
        double * v = A->rows[k];

        if (k != i)
            for (j = 0; j < d; j++)
                v[j] = d_mat_entry(A, i, j);
        if (dvec_normalise(v, d) == 0.0)
            continue;
        if (Q != NULL)
            dvec_project_out(v, Q, d);
        if (dvec_normalise(v, d) > tol)
            k++;
    }
    dm_keep_rows(A, k);
}

static int
dvec_cmp(const double * a, const double * b, slong d)
{
    slong j;

    for (j = 0; j < d; j++)
        if (a[j] != b[j])
            return a[j] < b[j] ? -1 : 1;
    return 0;
}

/* Sort the rows of A lexicographically, carrying flag[] along (insertion
   sort: cones in R^3 have few rays and facets).  */
static void
dm_sort_rows(d_mat_t A, int * flag)
{
    slong d = A->c, i, k;
    double * t = flint_malloc(sizeof(double) * (d > 0 ? d : 1));

    for (i = 1; i < A->r; i++)
    {
        int f = flag[i];

        memcpy(t, A->rows[i], sizeof(double) * d);
        for (k = i; k > 0 && dvec_cmp(A->rows[k - 1], t, d) > 0; k--)
        {
            memcpy(A->rows[k], A->rows[k - 1], sizeof(double) * d);
            flag[k] = flag[k - 1];
        }
        memcpy(A->rows[k], t, sizeof(double) * d);
        flag[k] = f;
    }
    flint_free(t);
}

/* ---------------------------------------------------------------------
   The cone type.  */

void
wc_fcone_init(wc_fcone_t C, slong d)
{
    C->d = d;
    C->eps = WC_FCONE_EPS;
    d_mat_init(C->ineqs, 0, d);
    d_mat_init(C->eqs, 0, d);
    d_mat_init(C->rays, 0, d);
    d_mat_init(C->lines, 0, d);
    C->strict = NULL;
    C->strict_rays = NULL;
    wc_fcone_set_empty(C);
}

void
wc_fcone_clear(wc_fcone_t C)
{
    d_mat_clear(C->ineqs);
    d_mat_clear(C->eqs);
    d_mat_clear(C->rays);
    d_mat_clear(C->lines);
    flint_free(C->strict);
    flint_free(C->strict_rays);
    C->strict = NULL;
    C->strict_rays = NULL;
}

void
wc_fcone_set_empty(wc_fcone_t C)
{
    slong d = C->d;

    C->empty = 1;
    C->dim = -1;
    C->lineality_dim = 0;
    C->closed = 1;
    dm_reinit(C->ineqs, 0, d);
    dm_reinit(C->eqs, 0, d);
    dm_reinit(C->rays, 0, d);
    dm_reinit(C->lines, 0, d);
    flint_free(C->strict);
    flint_free(C->strict_rays);
    C->strict = NULL;
    C->strict_rays = NULL;
}

/* ---------------------------------------------------------------------
   The route.  */


/* Column col of J for direction (dx, dy) at (rx, ry) = p - o.  */
static void
set_column(d_mat_t J, slong col, double dx, double dy, double rx, double ry)
{
    d_mat_entry(J, 0, col) = dx;
    d_mat_entry(J, 1, col) = dy;
    d_mat_entry(J, 2, col) = rx * dy - ry * dx;
}

/* The error for data beyond double range (or cddlib's results beyond
   it).  */
static int
overflow(wc_error_t err, const wc_problem_t P)
{
    return wc_error_set(err, WC_EINPUT, P->file, 0, 0,
                        "the problem's numbers overflow double precision "
                        "(--arith=double)");
}

/* C := A B; C is re-initialised to the right size.  */
static void
dm_mul(d_mat_t C, const d_mat_t A, const d_mat_t B)
{
    dm_reinit(C, A->r, B->c);
    if (A->r > 0 && B->c > 0)
        d_mat_mul_classical(C, A, B);
}

int
wc_wrench_cone_paper_double(wc_fcone_t W, const wc_problem_t P,
                            const char * mode, double eps, wc_error_t err)
{
    slong n, N2, N4, rc, i, j, k, r, nz, nf;
    int * flag = NULL, * fstrict = NULL;
    slong * zcol = NULL;
    d_mat_t J, Mi, A, B, C, E, N, R, S, V, T1, T2, K, Pm, Kt, KFe, KFh, KF,
        F, es, Ke, b, Fle, Flt, H, rays, lines, eqs, facets;
    double pnorm, kenorm, tol;
    int status = WC_OK, feasible;

    wc_fcone_set_empty(W);
    if ((status = wc_mode_check(P, mode, WC_TABLE_CONE, err)) != WC_OK)
        return status;
    if (!(eps >= 0.0) || !isfinite(eps))
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "the tolerance must be a finite number >= 0, "
                            "not %g", eps);
    W->eps = eps;
    /* Unit vectors are compared at eps, but never below what rounding
       alone produces.  */
    tol = eps > 64 * DBL_EPSILON ? eps : 64 * DBL_EPSILON;

    n = P->n;
    N2 = 2 * n;
    N4 = 4 * n;
    flag = flint_calloc(N4 + 1, sizeof(int));
    zcol = flint_malloc(sizeof(slong) * (N4 + 1));
    /* Every matrix is initialised here, so that cleanup can clear all.  */
    d_mat_init(J, 3, N2);
    d_mat_init(Mi, 3, 3);
    d_mat_zero(J);
    d_mat_zero(Mi);
    d_mat_init(A, 0, 0);
    d_mat_init(B, 0, 0);
    d_mat_init(C, 0, 0);
    d_mat_init(E, 0, 0);
    d_mat_init(N, 0, 0);
    d_mat_init(R, 0, 0);
    d_mat_init(S, 0, 0);
    d_mat_init(V, 0, 0);
    d_mat_init(T1, 0, 0);
    d_mat_init(T2, 0, 0);
    d_mat_init(K, 0, 0);
    d_mat_init(Pm, 0, 0);
    d_mat_init(Kt, 0, 0);
    d_mat_init(KFe, 0, 0);
    d_mat_init(KFh, 0, 0);
    d_mat_init(KF, 0, 0);
    d_mat_init(F, 0, 3);
    d_mat_init(es, 0, 0);
    d_mat_init(Ke, 0, 0);
    d_mat_init(b, 0, 0);
    d_mat_init(Fle, 0, 3);
    d_mat_init(Flt, 0, 3);
    d_mat_init(H, 0, 3);
    d_mat_init(rays, 0, 3);
    d_mat_init(lines, 0, 3);
    d_mat_init(eqs, 0, 3);
    d_mat_init(facets, 0, 3);

    /* The data, rounded once.  */
    {
        double ox = fmpq_get_d(P->com + 0), oy = fmpq_get_d(P->com + 1);

        for (i = 0; i < n; i++)
        {
            const wc_fixel_struct * f = P->fixels + i;
            double nx = fmpq_get_d(f->normal + 0);
            double ny = fmpq_get_d(f->normal + 1);
            double rx = fmpq_get_d(f->point + 0) - ox;
            double ry = fmpq_get_d(f->point + 1) - oy;

            set_column(J, i, nx, ny, rx, ry);
            set_column(J, n + i, -ny, nx, rx, ry);
        }
        d_mat_entry(Mi, 0, 0) = 1.0 / fmpq_get_d(P->mass);
        d_mat_entry(Mi, 1, 1) = 1.0 / fmpq_get_d(P->mass);
        d_mat_entry(Mi, 2, 2) = 1.0 / fmpq_get_d(P->inertia);
    }

    /* B = J^T M^-1, A = B J, C = [I, -A].  */
    d_mat_clear(T1);
    d_mat_init(T1, N2, 3);
    d_mat_transpose(T1, J);
    dm_mul(B, T1, Mi);
    dm_mul(A, B, J);
    dm_reinit(C, N2, N4);
    for (i = 0; i < N2; i++)
    {
        d_mat_entry(C, i, i) = 1.0;
        for (j = 0; j < N2; j++)
            d_mat_entry(C, i, N2 + j) = -d_mat_entry(A, i, j);
    }

    /* Table 2, read exactly as the exact route reads it.  */
    _wc_table2_flags(flag, P, mode);

    /* E, N, R, S, V.  */
    for (k = 0, rc = 0; k < N2; k++)
        rc += !(flag[k] & Y_FREE);
    dm_reinit(E, rc, N2);
    for (k = 0, r = 0; k < N2; k++)
        if (!(flag[k] & Y_FREE))
            d_mat_entry(E, r++, k) = 1.0;
    dm_reinit(N, N4, N4);
    dm_reinit(R, N4, N4);
    dm_reinit(S, N4, N4);
    for (k = 0; k < N4; k++)
    {
        d_mat_entry(N, k, k) = (flag[k] & Y_NEG) ? -1.0 : 1.0;
        d_mat_entry(R, k, k) = 1.0;
        d_mat_entry(S, k, k) = 1.0;
    }
    for (i = 0; i < n; i++)
    {
        slong cn = 2 * n + i, ct = 3 * n + i;
        double mus = fmpq_get_d(P->fixels[i].mu_s);
        double muk = fmpq_get_d(P->fixels[i].mu_k);

        if (flag[ct] & Y_ROLL)
        {
            d_mat_entry(R, ct, ct) = mus;
            d_mat_entry(R, cn, ct) = 1.0;
            d_mat_entry(R, ct, cn) = -mus;
        }
        if (flag[ct] & Y_SLIDE)
            d_mat_entry(S, ct, cn) = mode[i] == 'l' ? -muk : muk;
    }
    for (k = 0, nz = 0; k < N4; k++)
        if (!(flag[k] & (Y_ZERO | Y_SLIDE | Y_FREE)))
            zcol[nz++] = k;
    dm_reinit(V, N4, nz);
    for (j = 0; j < nz; j++)
        d_mat_entry(V, zcol[j], j) = 1.0;

    /* K = E C N R S V, P = E B.  */
    dm_mul(T1, E, C);
    dm_mul(T2, T1, N);
    dm_mul(T1, T2, R);
    dm_mul(T2, T1, S);
    dm_mul(K, T2, V);
    dm_mul(Pm, E, B);
    if (!dm_is_finite(K) || !dm_is_finite(Pm) || !dm_is_finite(Mi))
    {
        status = overflow(err, P);
        goto cleanup;
    }

    /* K^F: cddlib's double V->H of pos(K) in R^rc, rows of unit length,
       each equality as a pair of opposite rows.  */
    if (rc > 0)
    {
        dm_reinit(Kt, nz, rc);
        if (nz > 0)
            d_mat_transpose(Kt, K);
        status = _wc_cddf_v_to_h(KFe, KFh, rc, Kt, NULL, err);
        if (status != WC_OK)
            goto cleanup;
        dm_reinit(KF, KFh->r + 2 * KFe->r, rc);
        for (i = 0; i < KFh->r; i++)
            for (j = 0; j < rc; j++)
                d_mat_entry(KF, i, j) = d_mat_entry(KFh, i, j);
        for (i = 0; i < KFe->r; i++)
            for (j = 0; j < rc; j++)
            {
                double x = d_mat_entry(KFe, i, j);

                d_mat_entry(KF, KFh->r + 2 * i, j) = x;
                d_mat_entry(KF, KFh->r + 2 * i + 1, j) = -x;
            }
        for (i = 0; i < KF->r; i++)
            dvec_normalise(KF->rows[i], rc);
        if (!dm_is_finite(KF))
        {
            status = overflow(err, P);
            goto cleanup;
        }
    }
    else
        dm_reinit(KF, 0, 0);

    /* F = K^F P and b = K^F K e_strict.  */
    dm_mul(F, KF, Pm);
    dm_reinit(es, nz, 1);
    for (j = 0; j < nz; j++)
        if (flag[zcol[j]] & Y_STRICT)
            d_mat_entry(es, j, 0) = 1.0;
    dm_mul(Ke, K, es);
    dm_mul(b, KF, Ke);
    pnorm = dm_norm(Pm);
    kenorm = dm_norm(Ke);
    if (!dm_is_finite(F) || !dm_is_finite(b) || !isfinite(pnorm)
        || !isfinite(kenorm))
    {
        status = overflow(err, P);
        goto cleanup;
    }

    /* Split F into its non-strict and strict rows, of unit length; a zero
       row is dropped, or empties W when strict.  */
    {
        slong nle = 0, nlt = 0;

        dm_reinit(Fle, F->r, 3);
        dm_reinit(Flt, F->r, 3);
        for (i = 0; i < F->r; i++)
        {
            int strict = d_mat_entry(b, i, 0) < -eps * kenorm;
            d_mat_struct * T = strict ? Flt : Fle;
            slong t = strict ? nlt : nle;
            double len;

            for (j = 0; j < 3; j++)
                d_mat_entry(T, t, j) = d_mat_entry(F, i, j);
            len = dvec_normalise(T->rows[t], 3);
            if (len <= eps * pnorm || len == 0.0)
            {
                if (strict)
                    goto cleanup;       /* 0 < 0: W is empty */
                continue;
            }
            if (strict)
                nlt++;
            else
                nle++;
        }
        dm_keep_rows(Fle, nle);
        dm_keep_rows(Flt, nlt);
    }

    /* Emptiness: cddlib's double LP on { F_0 g <= 0, F_+ g <= -1 }.  */
    feasible = _wc_cddf_lp_feasible(Fle, Flt, 3, err);
    if (feasible < 0)
    {
        status = WC_EINTERNAL;
        goto cleanup;
    }
    if (feasible == 0)
        goto cleanup;

    /* The closure: H->V of every row of F, then V->H of the generators
       for its facets and equalities.  */
    dm_reinit(H, Fle->r + Flt->r, 3);
    for (i = 0; i < Fle->r; i++)
        for (j = 0; j < 3; j++)
            d_mat_entry(H, i, j) = d_mat_entry(Fle, i, j);
    for (i = 0; i < Flt->r; i++)
        for (j = 0; j < 3; j++)
            d_mat_entry(H, Fle->r + i, j) = d_mat_entry(Flt, i, j);
    status = _wc_cddf_h_to_v(rays, lines, 3, NULL, H, err);
    if (status != WC_OK)
        goto cleanup;
    status = _wc_cddf_v_to_h(eqs, facets, 3, rays, lines, err);
    if (status != WC_OK)
        goto cleanup;

    /* The exact route's conventions, in doubles.  */
    dm_orthonormalise(lines, tol);
    dm_orthonormalise(eqs, tol);
    dm_unit_rows(rays, lines, tol);
    dm_unit_rows(facets, eqs, tol);

    /* Strictness: a strict row vanishes on a facet when, within the
       linear hull, it is that facet's normal; on a ray when tight.  */
    nf = facets->r;
    fstrict = flint_calloc(nf + 1, sizeof(int));
    W->strict_rays = flint_calloc(rays->r + 1, sizeof(int));
    for (k = 0; k < Flt->r; k++)
    {
        double s[3];
        int everywhere;

        for (j = 0; j < 3; j++)
            s[j] = d_mat_entry(Flt, k, j);
        for (i = 0; i < rays->r; i++)
            if (dvec_dot(s, rays->rows[i], 3) >= -tol)
                W->strict_rays[i] = 1;
        dvec_project_out(s, eqs, 3);
        everywhere = dvec_normalise(s, 3) <= tol;
        for (i = 0; i < nf; i++)
        {
            double dist2 = 0.0;

            for (j = 0; j < 3; j++)
                dist2 += (s[j] - d_mat_entry(facets, i, j))
                    * (s[j] - d_mat_entry(facets, i, j));
            if (everywhere || sqrt(dist2) <= tol)
                fstrict[i] = 1;
        }
    }
    dm_sort_rows(facets, fstrict);
    dm_sort_rows(rays, W->strict_rays);

    W->empty = 0;
    W->closed = Flt->r == 0;
    W->dim = 3 - eqs->r;
    W->lineality_dim = lines->r;
    d_mat_swap(W->ineqs, facets);
    d_mat_swap(W->eqs, eqs);
    d_mat_swap(W->rays, rays);
    d_mat_swap(W->lines, lines);
    W->strict = fstrict;
    fstrict = NULL;

cleanup:
    if (status != WC_OK)
        wc_fcone_set_empty(W);
    flint_free(flag);
    flint_free(zcol);
    flint_free(fstrict);
    d_mat_clear(J);
    d_mat_clear(Mi);
    d_mat_clear(A);
    d_mat_clear(B);
    d_mat_clear(C);
    d_mat_clear(E);
    d_mat_clear(N);
    d_mat_clear(R);
    d_mat_clear(S);
    d_mat_clear(V);
    d_mat_clear(T1);
    d_mat_clear(T2);
    d_mat_clear(K);
    d_mat_clear(Pm);
    d_mat_clear(Kt);
    d_mat_clear(KFe);
    d_mat_clear(KFh);
    d_mat_clear(KF);
    d_mat_clear(F);
    d_mat_clear(es);
    d_mat_clear(Ke);
    d_mat_clear(b);
    d_mat_clear(Fle);
    d_mat_clear(Flt);
    d_mat_clear(H);
    d_mat_clear(rays);
    d_mat_clear(lines);
    d_mat_clear(eqs);
    d_mat_clear(facets);
    return status;
}

/* ---------------------------------------------------------------------
   Printing.  */

/* x with %.17g, which reads back to the same double; -0 prints as 0.  */
static void
put_double(FILE * out, double x)
{
    fprintf(out, "%.17g", x == 0.0 ? 0.0 : x);
}

static void
json_rows_d(FILE * out, const d_mat_t A)
{
    slong i, j;

    putc('[', out);
    for (i = 0; i < A->r; i++)
    {
        fputs(i ? ", [" : "[", out);
        for (j = 0; j < A->c; j++)
        {
            if (j)
                fputs(", ", out);
            put_double(out, d_mat_entry(A, i, j));
        }
        putc(']', out);
    }
    putc(']', out);
}

static void
json_flags(FILE * out, const int * f, slong len)
{
    slong i;

    putc('[', out);
    for (i = 0; i < len; i++)
        fprintf(out, "%s%s", i ? ", " : "", f[i] ? "true" : "false");
    putc(']', out);
}

static void
fprint_json(FILE * out, const wc_fcone_t C)
{
    fputs(C->empty ? "{\"empty\": true" : "{\"empty\": false", out);
    fputs(", \"arith\": \"double\", \"eps\": ", out);
    put_double(out, C->eps);
    if (C->empty)
    {
        putc('}', out);
        return;
    }
    fprintf(out, ", \"dim\": %ld, \"lineality_dim\": %ld, \"closed\": %s, "
            "\"inequalities\": ", (long) C->dim, (long) C->lineality_dim,
            C->closed ? "true" : "false");
    json_rows_d(out, C->ineqs);
    fputs(", \"strict\": ", out);
    json_flags(out, C->strict, C->ineqs->r);
    fputs(", \"equalities\": ", out);
    json_rows_d(out, C->eqs);
    fputs(", \"rays\": ", out);
    json_rows_d(out, C->rays);
    fputs(", \"strict_rays\": ", out);
    json_flags(out, C->strict_rays, C->rays->r);
    fputs(", \"lines\": ", out);
    json_rows_d(out, C->lines);
    putc('}', out);
}

static void
text_rows_d(FILE * out, const d_mat_t A, const char * tag, const int * f,
            const char * yes, const char * no)
{
    slong i, j;

    for (i = 0; i < A->r; i++)
    {
        fprintf(out, "    %s%-3ld", tag, (long) i);
        for (j = 0; j < A->c; j++)
        {
            double x = d_mat_entry(A, i, j);

            fprintf(out, " %24.17g", x == 0.0 ? 0.0 : x);
        }
        if (f != NULL)
            fprintf(out, "  %s", f[i] ? yes : no);
        putc('\n', out);
    }
}

static void
fprint_text(FILE * out, const wc_fcone_t C)
{
    slong i, ns = 0;

    fputs("  floating point, not exact: the paper's route in C doubles with "
          "cddlib's\n  double-precision build", out);
    fprintf(out, " (tolerance %g)\n", C->eps);
    if (C->empty)
    {
        fputs("  empty (no wrench is consistent with this mode)\n", out);
        return;
    }
    for (i = 0; i < C->ineqs->r; i++)
        ns += C->strict[i] != 0;
    fprintf(out, "  dimension %ld, lineality %ld, %s", (long) C->dim,
            (long) C->lineality_dim, C->closed ? "closed" : "not closed");
    if (!C->closed)
        fprintf(out, " (%ld of %ld facets strict)", (long) ns,
                (long) C->ineqs->r);
    putc('\n', out);
    fprintf(out, "  rays of the closure (unit length):%s\n",
            C->rays->r ? "" : " none");
    text_rows_d(out, C->rays, "r", C->strict_rays, "excluded", "included");
    if (C->lineality_dim > 0)
    {
        fputs("  lines (orthonormal basis):\n", out);
        text_rows_d(out, C->lines, "l", NULL, NULL, NULL);
    }
    fprintf(out, "  facets (h . g <= 0, unit normals):%s\n",
            C->ineqs->r ? "" : " none");
    text_rows_d(out, C->ineqs, "h", C->strict, "strict (excluded)",
                "included");
    if (C->eqs->r > 0)
    {
        fputs("  equalities (e . g = 0, orthonormal basis):\n", out);
        text_rows_d(out, C->eqs, "e", NULL, NULL, NULL);
    }
}

static void
cdd_row_d(FILE * out, double lead, const double * v, slong d, int sign)
{
    slong j;

    putc(' ', out);
    put_double(out, lead);
    for (j = 0; j < d; j++)
    {
        putc(' ', out);
        put_double(out, sign * v[j]);
    }
    putc('\n', out);
}

static void
cdd_linearity_d(FILE * out, slong first, slong count)
{
    slong i;

    if (count == 0)
        return;
    fprintf(out, "linearity %ld", (long) count);
    for (i = 0; i < count; i++)
        fprintf(out, " %ld", (long) (first + i));
    putc('\n', out);
}

static void
fprint_cdd(FILE * out, const wc_fcone_t C, int which)
{
    slong d = C->d, m = C->ineqs->r, q = C->eqs->r, k = C->rays->r,
        l = C->lines->r, i;

    fprintf(out, "* floating point, not exact: cddlib's double-precision "
            "build, tolerance %g\n", C->eps);
    if (C->empty)
    {
        fputs("* the cone is empty\n", out);
        if (which & 1)
        {
            fprintf(out, "H-representation\nbegin\n 1 %ld real\n -1",
                    (long) d + 1);
            for (i = 0; i < d; i++)
                fputs(" 0", out);
            fputs("\nend\n", out);
        }
        if (which & 2)
            fprintf(out, "V-representation\nbegin\n 0 %ld real\nend\n",
                    (long) d + 1);
        return;
    }
    if (C->closed)
        fputs("* the cone is closed: it equals the polyhedron below\n", out);
    else
    {
        fputs("* the cone is NOT closed: below is its closure, without the "
              "apex and\n* these (H rows numbered from 1, V rows from 2, "
              "after the apex row):\n", out);
        for (i = 0; i < m; i++)
            if (C->strict[i])
                fprintf(out, "*   strict facet, H row %ld\n", (long) i + 1);
        for (i = 0; i < k; i++)
            if (C->strict_rays[i])
                fprintf(out, "*   excluded ray, V row %ld\n", (long) i + 2);
    }
    if (which & 1)
    {
        fputs("H-representation\n", out);
        cdd_linearity_d(out, m + 1, q);
        fprintf(out, "begin\n %ld %ld real\n", (long) (m + q), (long) d + 1);
        for (i = 0; i < m; i++)
            cdd_row_d(out, 0.0, C->ineqs->rows[i], d, -1);
        for (i = 0; i < q; i++)
            cdd_row_d(out, 0.0, C->eqs->rows[i], d, 1);
        fputs("end\n", out);
    }
    if (which & 2)
    {
        fputs("V-representation\n", out);
        cdd_linearity_d(out, k + 2, l);
        fprintf(out, "begin\n %ld %ld real\n", (long) (1 + k + l),
                (long) d + 1);
        fputs(" 1", out);
        for (i = 0; i < d; i++)
            fputs(" 0", out);
        putc('\n', out);
        for (i = 0; i < k; i++)
            cdd_row_d(out, 0.0, C->rays->rows[i], d, 1);
        for (i = 0; i < l; i++)
            cdd_row_d(out, 0.0, C->lines->rows[i], d, 1);
        fputs("end\n", out);
    }
}

int
wc_fcone_fprint(FILE * out, const wc_fcone_t C, int format)
{
    switch (format)
    {
    case WC_FCONE_TEXT: fprint_text(out, C); break;
    case WC_FCONE_JSON: fprint_json(out, C); break;
    case WC_FCONE_INE: fprint_cdd(out, C, 1); break;
    case WC_FCONE_EXT: fprint_cdd(out, C, 2); break;
    case WC_FCONE_CDD: fprint_cdd(out, C, 3); break;
    default: return WC_EINTERNAL;
    }
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

/* ---------------------------------------------------------------------
   Comparison with the exact cone.  */

/* v := row i of the fmpz matrix A as a unit double vector (entries
   divided by the largest first, exactly, so that huge integers do not
   overflow).  */
static void
unit_from_fmpz(double * v, const fmpz_mat_t A, slong i)
{
    slong d = fmpz_mat_ncols(A), j;
    fmpz_t big;
    fmpq_t q;

    fmpz_init(big);
    fmpq_init(q);
    for (j = 0; j < d; j++)
        if (fmpz_cmpabs(fmpz_mat_entry(A, i, j), big) > 0)
            fmpz_abs(big, fmpz_mat_entry(A, i, j));
    for (j = 0; j < d; j++)
    {
        if (fmpz_is_zero(big))
            v[j] = 0.0;
        else
        {
            fmpq_set_fmpz_frac(q, fmpz_mat_entry(A, i, j), big);
            v[j] = fmpq_get_d(q);
        }
    }
    dvec_normalise(v, d);
    fmpz_clear(big);
    fmpq_clear(q);
}

static double
dvec_dist(const double * a, const double * b, slong d)
{
    double s = 0.0;
    slong j;

    for (j = 0; j < d; j++)
        s += (a[j] - b[j]) * (a[j] - b[j]);
    return sqrt(s);
}

/* Index of the row of A nearest to v, -1 when A has no rows.  */
static slong
nearest_row(const d_mat_t A, const double * v, double * dist)
{
    slong i, best = -1;

    *dist = INFINITY;
    for (i = 0; i < A->r; i++)
    {
        double t = dvec_dist(A->rows[i], v, A->c);

        if (t < *dist)
        {
            *dist = t;
            best = i;
        }
    }
    return best;
}

/* Whether the exact face spanned by the rays in set[] (or the lineality
   space when none) is left out of E: its relative-interior point, the sum
   of those rays, is not in E.  */
static int
exact_excluded(const wc_cone_t E, const int * set)
{
    slong d = E->d, i, j;
    fmpq * g = _fmpq_vec_init(d);
    int out;

    for (i = 0; i < fmpz_mat_nrows(E->rays); i++)
        if (set[i])
            for (j = 0; j < d; j++)
                fmpq_add_fmpz(g + j, g + j, fmpz_mat_entry(E->rays, i, j));
    out = !wc_cone_contains(E, g);
    _fmpq_vec_clear(g, d);
    return out;
}

/* Whether the span of the rows of the fmpz matrix X equals that of the
   orthonormal rows of Q, within tol.  */
static int
same_space(const fmpz_mat_t X, const d_mat_t Q, double tol)
{
    slong d = Q->c, i;
    double * v = flint_malloc(sizeof(double) * (d > 0 ? d : 1));
    int same = fmpz_mat_nrows(X) == Q->r;

    for (i = 0; same && i < fmpz_mat_nrows(X); i++)
    {
        unit_from_fmpz(v, X, i);
        dvec_project_out(v, Q, d);
        same = dvec_norm(v, d) <= tol;
    }
    flint_free(v);
    return same;
}

/* Match the rows of the exact X against the float rows of A both ways;
   returns the bits found: missing (no partner within tol) or strict
   (partners differing in their flags).  xs[i] is the exact flag of row i
   of X.  */
static int
match_rows(const fmpz_mat_t X, const int * xs, const d_mat_t A,
           const int * as, double tol, int missing_bit)
{
    slong d = A->c, i;
    double * v = flint_malloc(sizeof(double) * (d > 0 ? d : 1));
    double dist;
    int bits = 0;

    if (fmpz_mat_nrows(X) != A->r)
        bits |= missing_bit;
    for (i = 0; i < fmpz_mat_nrows(X); i++)
    {
        slong k;

        unit_from_fmpz(v, X, i);
        k = nearest_row(A, v, &dist);
        if (k < 0 || dist > tol)
            bits |= missing_bit;
        else if ((xs[i] != 0) != (as[k] != 0))
            bits |= WC_FDIFF_STRICT;
    }
    for (i = 0; i < A->r; i++)
    {
        slong k, best = -1;
        double bd = INFINITY;

        for (k = 0; k < fmpz_mat_nrows(X); k++)
        {
            unit_from_fmpz(v, X, k);
            dist = dvec_dist(v, A->rows[i], d);
            if (dist < bd)
            {
                bd = dist;
                best = k;
            }
        }
        if (best < 0 || bd > tol)
            bits |= missing_bit;
    }
    flint_free(v);
    return bits;
}

int
wc_fcone_compare_exact(const wc_fcone_t F, const wc_cone_t E, double tol)
{
    slong d = E->d, nr, nh, i, j;
    int * set = NULL, * xs = NULL, bits = 0;
    fmpz_t t;

    if (F->d != E->d)
        return WC_FDIFF_SPACES;
    if (F->empty || E->empty)
        return (F->empty != E->empty) ? WC_FDIFF_EMPTY : 0;
    if (!same_space(E->eqs, F->eqs, tol)
        || !same_space(E->lines, F->lines, tol))
        bits |= WC_FDIFF_SPACES;
    if ((wc_cone_excluded_faces(E) == 0) != (F->closed != 0))
        bits |= WC_FDIFF_STRICT;

    nr = fmpz_mat_nrows(E->rays);
    nh = fmpz_mat_nrows(E->ineqs);
    set = flint_calloc(nr + 1, sizeof(int));
    xs = flint_calloc((nr > nh ? nr : nh) + 1, sizeof(int));
    fmpz_init(t);

    /* Rays: each one's own face.  */
    for (i = 0; i < nr; i++)
    {
        memset(set, 0, sizeof(int) * (nr + 1));
        set[i] = 1;
        xs[i] = exact_excluded(E, set);
    }
    bits |= match_rows(E->rays, xs, F->rays, F->strict_rays, tol,
                       WC_FDIFF_RAYS);

    /* Facets: the face of the rays each one is tight on.  */
    for (i = 0; i < nh; i++)
    {
        for (j = 0; j < nr; j++)
        {
            slong c;

            fmpz_zero(t);
            for (c = 0; c < d; c++)
                fmpz_addmul(t, fmpz_mat_entry(E->ineqs, i, c),
                            fmpz_mat_entry(E->rays, j, c));
            set[j] = fmpz_is_zero(t);
        }
        xs[i] = exact_excluded(E, set);
    }
    bits |= match_rows(E->ineqs, xs, F->ineqs, F->strict, tol,
                       WC_FDIFF_FACETS);

    fmpz_clear(t);
    flint_free(set);
    flint_free(xs);
    return bits;
}
