/* floatcone.c -- the paper's route in doubles: the float cone type and
   wc_wrench_cone_paper_double.

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

#include "float/floatcone.h"
#include "float/dmat.h"
#include "exact/cddbridge.h"
#include "model/mode.h"
#include "model/table2.h"

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
    _wc_dm_reinit(C->ineqs, 0, d);
    _wc_dm_reinit(C->eqs, 0, d);
    _wc_dm_reinit(C->rays, 0, d);
    _wc_dm_reinit(C->lines, 0, d);
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

/* Keep in *e the line and column of x when its binary exponent is the
   farthest from 0 so far.  */
static void
farthest(slong * e, long * line, long * col, const fmpq_t x, long xl,
         long xc)
{
    slong b = fmpz_bits(fmpq_numref(x)) - fmpz_bits(fmpq_denref(x));

    if (b < 0)
        b = -b;
    if (!fmpq_is_zero(x) && b > *e)
    {
        *e = b;
        *line = xl;
        *col = xc;
    }
}

/* The error for data beyond double range (or cddlib's results beyond
   it), located at the number of the problem farthest from 1 in
   magnitude: the one that makes the products overflow.  */
static int
overflow(wc_error_t err, const wc_problem_t P)
{
    slong e = -1, i, k;
    long line = 0, col = 0;

    farthest(&e, &line, &col, P->mass, P->mass_line, 1);
    farthest(&e, &line, &col, P->inertia, P->inertia_line, 1);
    for (k = 0; k < 2; k++)
        farthest(&e, &line, &col, P->com + k, P->com_line, 1);
    for (i = 0; i < P->n; i++)
        for (k = 0; k < 2; k++)
        {
            const wc_fixel_struct * f = P->fixels + i;

            farthest(&e, &line, &col, f->point + k, f->line, f->col);
            farthest(&e, &line, &col, f->normal + k, f->line, f->col);
        }
    return wc_error_set(err, WC_EINPUT, P->file, line > 0 ? line : 0,
                        line > 0 ? col : 0, "numbers this far from 1 "
                        "overflow double precision in the paper's system "
                        "(--arith=double); the exact route has no such "
                        "limit");
}

/* J (3 x 2n) and M^-1 (3 x 3, both zero on entry) from the problem's
   data, rounded once.  */
static void
problem_data(d_mat_t J, d_mat_t Mi, const wc_problem_t P)
{
    double ox = fmpq_get_d(P->com + 0), oy = fmpq_get_d(P->com + 1);
    slong n = P->n, i;

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

/* Table 2's E, N, R, S and V for the flags of mode, and es, the strict
   entries among V's columns (a column vector).  */
static void
table2_matrices(d_mat_t E, d_mat_t N, d_mat_t R, d_mat_t S, d_mat_t V,
                d_mat_t es, const wc_problem_t P, const char * mode,
                const int * flag)
{
    slong n = P->n, N2 = 2 * n, N4 = 4 * n, rc, nz, i, j, k, r;
    slong * zcol = flint_malloc(sizeof(slong) * (N4 + 1));

    for (k = 0, rc = 0; k < N2; k++)
        rc += !(flag[k] & Y_FREE);
    _wc_dm_reinit(E, rc, N2);
    for (k = 0, r = 0; k < N2; k++)
        if (!(flag[k] & Y_FREE))
            d_mat_entry(E, r++, k) = 1.0;
    _wc_dm_reinit(N, N4, N4);
    _wc_dm_reinit(R, N4, N4);
    _wc_dm_reinit(S, N4, N4);
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
    _wc_dm_reinit(V, N4, nz);
    _wc_dm_reinit(es, nz, 1);
    for (j = 0; j < nz; j++)
    {
        d_mat_entry(V, zcol[j], j) = 1.0;
        if (flag[zcol[j]] & Y_STRICT)
            d_mat_entry(es, j, 0) = 1.0;
    }
    flint_free(zcol);
}

/* K = E C N R S V, P = E B and the strict column vector es of the mode
   (flag from Table 2), with B = J^T M^-1, A = B J and C = [I, -A].
   Returns 0 when a number overflows doubles.  */
static int
paper_system(d_mat_t K, d_mat_t Pm, d_mat_t es, const wc_problem_t P,
             const char * mode, const int * flag)
{
    slong N2 = 2 * P->n, i, j;
    d_mat_t J, Mi, A, B, C, E, N, R, S, V, T1, T2;
    int finite;

    d_mat_init(J, 3, N2);
    d_mat_init(Mi, 3, 3);
    d_mat_zero(J);
    d_mat_zero(Mi);
    d_mat_init(T1, N2, 3);
    d_mat_init(T2, 0, 0);
    d_mat_init(A, 0, 0);
    d_mat_init(B, 0, 0);
    d_mat_init(C, 0, 0);
    d_mat_init(E, 0, 0);
    d_mat_init(N, 0, 0);
    d_mat_init(R, 0, 0);
    d_mat_init(S, 0, 0);
    d_mat_init(V, 0, 0);
    problem_data(J, Mi, P);
    d_mat_transpose(T1, J);
    _wc_dm_mul(B, T1, Mi);
    _wc_dm_mul(A, B, J);
    _wc_dm_reinit(C, N2, 2 * N2);
    for (i = 0; i < N2; i++)
    {
        d_mat_entry(C, i, i) = 1.0;
        for (j = 0; j < N2; j++)
            d_mat_entry(C, i, N2 + j) = -d_mat_entry(A, i, j);
    }
    table2_matrices(E, N, R, S, V, es, P, mode, flag);
    _wc_dm_mul(T1, E, C);
    _wc_dm_mul(T2, T1, N);
    _wc_dm_mul(T1, T2, R);
    _wc_dm_mul(T2, T1, S);
    _wc_dm_mul(K, T2, V);
    _wc_dm_mul(Pm, E, B);
    finite = _wc_dm_is_finite(K) && _wc_dm_is_finite(Pm)
        && _wc_dm_is_finite(Mi);
    d_mat_clear(J);
    d_mat_clear(Mi);
    d_mat_clear(T1);
    d_mat_clear(T2);
    d_mat_clear(A);
    d_mat_clear(B);
    d_mat_clear(C);
    d_mat_clear(E);
    d_mat_clear(N);
    d_mat_clear(R);
    d_mat_clear(S);
    d_mat_clear(V);
    return finite;
}

/* K^F: cddlib's double V->H of pos(K) in R^rc (rc = rows of K), rows of
   unit length, each equality as a pair of opposite rows.  */
static int
facets_of_k(d_mat_t KF, const d_mat_t K, const wc_problem_t P,
            wc_error_t err)
{
    slong rc = K->r, nz = K->c, i, j;
    d_mat_t Kt, KFe, KFh;
    int status = WC_OK;

    if (rc == 0)
    {
        _wc_dm_reinit(KF, 0, 0);
        return WC_OK;
    }
    d_mat_init(Kt, 0, 0);
    d_mat_init(KFe, 0, 0);
    d_mat_init(KFh, 0, 0);
    _wc_dm_reinit(Kt, nz, rc);
    if (nz > 0)
        d_mat_transpose(Kt, K);
    status = _wc_cddf_v_to_h(KFe, KFh, rc, Kt, NULL, err);
    if (status != WC_OK)
        goto cleanup;
    _wc_dm_reinit(KF, KFh->r + 2 * KFe->r, rc);
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
        _wc_dvec_normalise(KF->rows[i], rc);
    if (!_wc_dm_is_finite(KF))
        status = overflow(err, P);

cleanup:
    d_mat_clear(Kt);
    d_mat_clear(KFe);
    d_mat_clear(KFh);
    return status;
}

/* Split the rows of F into the non-strict Fle and the strict Flt (row i
   is strict when b_i < -eps kenorm), of unit length; a zero row (at most
   eps pnorm long) is dropped, or empties W when strict: then returns 0.  */
static int
split_strict(d_mat_t Fle, d_mat_t Flt, const d_mat_t F, const d_mat_t b,
             double eps, double kenorm, double pnorm)
{
    slong nle = 0, nlt = 0, i, j;

    _wc_dm_reinit(Fle, F->r, 3);
    _wc_dm_reinit(Flt, F->r, 3);
    for (i = 0; i < F->r; i++)
    {
        int strict = d_mat_entry(b, i, 0) < -eps * kenorm;
        d_mat_struct * T = strict ? Flt : Fle;
        slong t = strict ? nlt : nle;
        double len;

        for (j = 0; j < 3; j++)
            d_mat_entry(T, t, j) = d_mat_entry(F, i, j);
        len = _wc_dvec_normalise(T->rows[t], 3);
        if (len <= eps * pnorm || len == 0.0)
        {
            if (strict)
                return 0;       /* 0 < 0: W is empty */
            continue;
        }
        if (strict)
            nlt++;
        else
            nle++;
    }
    _wc_dm_keep_rows(Fle, nle);
    _wc_dm_keep_rows(Flt, nlt);
    return 1;
}

/* Which facets and rays of the closure the strict rows exclude: a strict
   row vanishes on a facet when, within the linear hull, it is that
   facet's normal; on a ray when tight.  */
static void
strictness(int * fstrict, int * rstrict, const d_mat_t Flt,
           const d_mat_t facets, const d_mat_t rays, const d_mat_t eqs,
           double tol)
{
    slong i, j, k;

    for (k = 0; k < Flt->r; k++)
    {
        double s[3];
        int everywhere;

        for (j = 0; j < 3; j++)
            s[j] = d_mat_entry(Flt, k, j);
        for (i = 0; i < rays->r; i++)
            if (_wc_dvec_dot(s, rays->rows[i], 3) >= -tol)
                rstrict[i] = 1;
        _wc_dvec_project_out(s, eqs, 3);
        everywhere = _wc_dvec_normalise(s, 3) <= tol;
        for (i = 0; i < facets->r; i++)
        {
            double dist2 = 0.0;

            for (j = 0; j < 3; j++)
                dist2 += (s[j] - d_mat_entry(facets, i, j))
                    * (s[j] - d_mat_entry(facets, i, j));
            if (everywhere || sqrt(dist2) <= tol)
                fstrict[i] = 1;
        }
    }
}

/* W := the nonempty cone { Fle g <= 0, Flt g < 0 }: the closure by
   cddlib's H->V of every row, then V->H of the generators for its facets
   and equalities, in the exact route's conventions; then strictness.  */
static int
closure(wc_fcone_t W, const d_mat_t Fle, const d_mat_t Flt, double tol,
        wc_error_t err)
{
    d_mat_t H, rays, lines, eqs, facets;
    slong i, j;
    int status;

    d_mat_init(H, Fle->r + Flt->r, 3);
    d_mat_init(rays, 0, 3);
    d_mat_init(lines, 0, 3);
    d_mat_init(eqs, 0, 3);
    d_mat_init(facets, 0, 3);
    for (i = 0; i < Fle->r; i++)
        for (j = 0; j < 3; j++)
            d_mat_entry(H, i, j) = d_mat_entry(Fle, i, j);
    for (i = 0; i < Flt->r; i++)
        for (j = 0; j < 3; j++)
            d_mat_entry(H, Fle->r + i, j) = d_mat_entry(Flt, i, j);
    status = _wc_cddf_h_to_v(rays, lines, 3, NULL, H, err);
    if (status == WC_OK)
        status = _wc_cddf_v_to_h(eqs, facets, 3, rays, lines, err);
    if (status == WC_OK)
    {
        _wc_dm_orthonormalise(lines, tol);
        _wc_dm_orthonormalise(eqs, tol);
        _wc_dm_unit_rows(rays, lines, tol);
        _wc_dm_unit_rows(facets, eqs, tol);
        W->strict = flint_calloc(facets->r + 1, sizeof(int));
        W->strict_rays = flint_calloc(rays->r + 1, sizeof(int));
        strictness(W->strict, W->strict_rays, Flt, facets, rays, eqs, tol);
        _wc_dm_sort_rows(facets, W->strict);
        _wc_dm_sort_rows(rays, W->strict_rays);
        W->empty = 0;
        W->closed = Flt->r == 0;
        W->dim = 3 - eqs->r;
        W->lineality_dim = lines->r;
        d_mat_swap(W->ineqs, facets);
        d_mat_swap(W->eqs, eqs);
        d_mat_swap(W->rays, rays);
        d_mat_swap(W->lines, lines);
    }
    d_mat_clear(H);
    d_mat_clear(rays);
    d_mat_clear(lines);
    d_mat_clear(eqs);
    d_mat_clear(facets);
    return status;
}

int
wc_wrench_cone_paper_double(wc_fcone_t W, const wc_problem_t P,
                            const char * mode, double eps, wc_error_t err)
{
    int * flag = NULL;
    d_mat_t K, Pm, es, KF, F, Ke, b, Fle, Flt;
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

    flag = flint_calloc(4 * P->n + 1, sizeof(int));
    d_mat_init(K, 0, 0);
    d_mat_init(Pm, 0, 0);
    d_mat_init(es, 0, 0);
    d_mat_init(KF, 0, 0);
    d_mat_init(F, 0, 3);
    d_mat_init(Ke, 0, 0);
    d_mat_init(b, 0, 0);
    d_mat_init(Fle, 0, 3);
    d_mat_init(Flt, 0, 3);

    /* Table 2, read exactly as the exact route reads it.  */
    _wc_table2_flags(flag, P, mode);
    if (!paper_system(K, Pm, es, P, mode, flag))
    {
        status = overflow(err, P);
        goto cleanup;
    }
    status = facets_of_k(KF, K, P, err);
    if (status != WC_OK)
        goto cleanup;

    /* F = K^F P and b = K^F K e_strict.  */
    _wc_dm_mul(F, KF, Pm);
    _wc_dm_mul(Ke, K, es);
    _wc_dm_mul(b, KF, Ke);
    pnorm = _wc_dm_norm(Pm);
    kenorm = _wc_dm_norm(Ke);
    if (!_wc_dm_is_finite(F) || !_wc_dm_is_finite(b) || !isfinite(pnorm)
        || !isfinite(kenorm))
    {
        status = overflow(err, P);
        goto cleanup;
    }
    if (!split_strict(Fle, Flt, F, b, eps, kenorm, pnorm))
        goto cleanup;

    /* Emptiness: cddlib's double LP on { F_0 g <= 0, F_+ g <= -1 }.  */
    feasible = _wc_cddf_lp_feasible(Fle, Flt, 3, err);
    if (feasible < 0)
        status = WC_EINTERNAL;
    else if (feasible > 0)
        status = closure(W, Fle, Flt, tol, err);

cleanup:
    if (status != WC_OK)
        wc_fcone_set_empty(W);
    flint_free(flag);
    d_mat_clear(K);
    d_mat_clear(Pm);
    d_mat_clear(es);
    d_mat_clear(KF);
    d_mat_clear(F);
    d_mat_clear(Ke);
    d_mat_clear(b);
    d_mat_clear(Fle);
    d_mat_clear(Flt);
    return status;
}
