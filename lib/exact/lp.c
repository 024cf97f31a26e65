/* lp.c -- the exact LP layer: homogeneous systems with > / >= / = rows,
   solved to a point or to Motzkin multipliers, and cone membership in
   R^3.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   cddlib's answers are believed only after an exact check of every row:
   a bug in the bridge, or in cddlib, becomes an error, never a wrong
   verdict.  */

#include <config.h>

#include <flint/fmpq_vec.h>

#include "exact/lp.h"
#include "exact/cddbridge.h"

const char *
wc_relation_str(wc_relation r)
{
    return r == WC_REL_GT ? ">" : r == WC_REL_GE ? ">=" : "=";
}

void
_wc_qvec_zero(fmpq * v, slong len)
{
    slong i;

    for (i = 0; i < len; i++)
        fmpq_zero(v + i);
}

void
_wc_qvec_set(fmpq * v, const fmpq * w, slong len)
{
    slong i;

    for (i = 0; i < len; i++)
        fmpq_set(v + i, w + i);
}

int
_wc_qvec_is_zero(const fmpq * v, slong len)
{
    slong i;

    for (i = 0; i < len; i++)
        if (!fmpq_is_zero(v + i))
            return 0;
    return 1;
}

void
_wc_fmpq_mat_keep_rows(fmpq_mat_t A, slong r)
{
    fmpq_mat_t B;
    slong i;

    fmpq_mat_init(B, r, fmpq_mat_ncols(A));
    for (i = 0; i < r; i++)
        _wc_qvec_set(B->rows[i], A->rows[i], fmpq_mat_ncols(A));
    fmpq_mat_swap(A, B);
    fmpq_mat_clear(B);
}

/* ---------------------------------------------------------------------
   Homogeneous systems.  */

int
_wc_lp_rows_hold(const fmpq_mat_t A, const wc_relation * rel,
                 const fmpq * z)
{
    slong m = fmpq_mat_nrows(A), nv = fmpq_mat_ncols(A), i;
    fmpq_t s;
    int ok = 1;

    fmpq_init(s);
    for (i = 0; i < m && ok; i++)
    {
        _fmpq_vec_dot(s, A->rows[i], z, nv);
        ok = rel[i] == WC_REL_GT ? fmpq_sgn(s) > 0
            : rel[i] == WC_REL_GE ? fmpq_sgn(s) >= 0 : fmpq_is_zero(s);
    }
    fmpq_clear(s);
    return ok;
}

/* 1 when y (m entries) are Motzkin multipliers of (A, rel).  */
static int
mult_hold(const fmpq_mat_t A, const wc_relation * rel, const fmpq * y)
{
    slong m = fmpq_mat_nrows(A), nv = fmpq_mat_ncols(A), i, j;
    fmpq_t s;
    int ok = 1, strict = 0;

    fmpq_init(s);
    for (i = 0; i < m && ok; i++)
    {
        if (rel[i] != WC_REL_EQ && fmpq_sgn(y + i) < 0)
            ok = 0;
        if (rel[i] == WC_REL_GT && fmpq_sgn(y + i) > 0)
            strict = 1;
    }
    for (j = 0; j < nv && ok; j++)
    {
        fmpq_zero(s);
        for (i = 0; i < m; i++)
            fmpq_addmul(s, y + i, fmpq_mat_entry(A, i, j));
        ok = fmpq_is_zero(s);
    }
    fmpq_clear(s);
    return ok && strict;
}

/* The multipliers: y with sum y_i A_i = 0, sum of the > multipliers = 1,
   y >= 0 off the = rows.  b and eq have room for nv + 1 + m rows.  */
static int
motzkin_mult(fmpq * mult, const fmpq_mat_t A, const wc_relation * rel,
             fmpq * b, int * eq, wc_error_t err)
{
    slong m = fmpq_mat_nrows(A), nv = fmpq_mat_ncols(A), i, j, ngt = 0;
    fmpq_mat_t D;
    fmpq * y;
    int found;

    fmpq_mat_init(D, nv + 1 + m, m);
    y = _fmpq_vec_init(m);
    for (i = 0; i < nv + 1 + m; i++)
    {
        fmpq_zero(b + i);
        eq[i] = i <= nv;
    }
    for (j = 0; j < nv; j++)
        for (i = 0; i < m; i++)
            fmpq_set(fmpq_mat_entry(D, j, i), fmpq_mat_entry(A, i, j));
    for (i = 0; i < m; i++)
    {
        if (rel[i] == WC_REL_GT)
        {
            fmpq_one(fmpq_mat_entry(D, nv, i));
            ngt++;
        }
        if (rel[i] != WC_REL_EQ)
            fmpq_one(fmpq_mat_entry(D, nv + 1 + i, i));
    }
    fmpq_one(b + nv);
    found = ngt > 0 ? _wc_cdd_lp_point(y, D, b, eq, err) : 0;
    if (found == 1 && mult_hold(A, rel, y))
    {
        _wc_qvec_set(mult, y, m);
        found = 0;
    }
    else if (found >= 0)
        found = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                              "an infeasible system without a Motzkin "
                              "certificate"), -1);
    fmpq_mat_clear(D);
    _fmpq_vec_clear(y, m);
    return found;
}

int
_wc_lp_motzkin(fmpq * z, fmpq * mult, const fmpq_mat_t A,
               const wc_relation * rel, wc_error_t err)
{
    slong m = fmpq_mat_nrows(A), nv = fmpq_mat_ncols(A), i;
    fmpq * b = _fmpq_vec_init(m + nv + 2);
    int * eq = flint_calloc(m + nv + 2, sizeof(int));
    int found;

    /* The system is homogeneous: > rows may be scaled to >= 1.  */
    for (i = 0; i < m; i++)
    {
        if (rel[i] == WC_REL_GT)
            fmpq_one(b + i);
        eq[i] = rel[i] == WC_REL_EQ;
    }
    if (m == 0)
    {
        _wc_qvec_zero(z, nv);
        found = 1;
    }
    else
        found = _wc_cdd_lp_point(z, A, b, eq, err);
    if (found == 1 && !_wc_lp_rows_hold(A, rel, z))
        found = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                              "an LP point fails its rows"), -1);
    if (found == 0 && mult != NULL)
        found = motzkin_mult(mult, A, rel, b, eq, err);
    _fmpq_vec_clear(b, m + nv + 2);
    flint_free(eq);
    return found;
}

/* ---------------------------------------------------------------------
   Cone membership in R^3: g in pos(G_0 .. G_k-1).

   A special case beside _wc_lp_motzkin, for two reasons.  Speed: the
   revised simplex method with a 3 x 3 basis does O(k) work per pivot,
   where cddlib would carry a tableau of k columns, and the stability
   analysis asks this once per wrench and per zero face.  Output: the
   static forces and the separators it finds are printed and written to
   certificates; they are this method's vertices, which another LP would
   not reproduce byte for byte.

   Phase one with Bland's rule (no cycling): artificial column i is
   s_i e_i, s_i the sign of g_i (+1 for 0), at cost 1; the columns G_j
   cost 0.  At the optimum the artificials are zero (g is in the cone) or
   the prices separate g from every G_j.  */

typedef struct
{
    slong k;
    slong basis[3];         /* column indices; k + i is artificial i */
    int sg[3];
    fmpq Binv[9];           /* the inverse basis, row-major */
    fmpq xB[3];             /* the basic values */
    fmpq pi[3];             /* the prices c_B B^-1 */
}
simplex3;

static void
simplex3_init(simplex3 * S, slong k, const fmpq * g)
{
    slong i;

    S->k = k;
    for (i = 0; i < 9; i++)
        fmpq_init(S->Binv + i);
    for (i = 0; i < 3; i++)
    {
        fmpq_init(S->xB + i);
        fmpq_init(S->pi + i);
        S->sg[i] = fmpq_sgn(g + i) < 0 ? -1 : 1;
        S->basis[i] = k + i;
        fmpq_set_si(S->Binv + 4 * i, S->sg[i], 1);
        fmpq_abs(S->xB + i, g + i);
    }
}

static void
simplex3_clear(simplex3 * S)
{
    slong i;

    for (i = 0; i < 9; i++)
        fmpq_clear(S->Binv + i);
    for (i = 0; i < 3; i++)
    {
        fmpq_clear(S->xB + i);
        fmpq_clear(S->pi + i);
    }
}

/* col := column j.  */
static void
simplex3_column(fmpq * col, const simplex3 * S, const fmpq * G, slong j)
{
    slong i;

    for (i = 0; i < 3; i++)
        if (j < S->k)
            fmpq_set(col + i, G + 3 * j + i);
        else
            fmpq_set_si(col + i, i == j - S->k ? S->sg[i] : 0, 1);
}

/* The prices, then the first nonbasic column with a negative reduced
   cost, or -1 at the optimum.  d is scratch.  */
static slong
simplex3_entering(simplex3 * S, const fmpq * G, fmpq_t d)
{
    slong i, j, k = S->k;

    for (j = 0; j < 3; j++)
    {
        fmpq_zero(S->pi + j);
        for (i = 0; i < 3; i++)
            if (S->basis[i] >= k)
                fmpq_add(S->pi + j, S->pi + j, S->Binv + 3 * i + j);
    }
    for (j = 0; j < k + 3; j++)
    {
        if (j == S->basis[0] || j == S->basis[1] || j == S->basis[2])
            continue;
        if (j < k)
        {
            _fmpq_vec_dot(d, S->pi, G + 3 * j, 3);
            fmpq_neg(d, d);
        }
        else
        {
            /* 1 - s_i pi_i */
            fmpq_mul_si(d, S->pi + (j - k), -S->sg[j - k]);
            fmpq_add_si(d, d, 1);
        }
        if (fmpq_sgn(d) < 0)
            return j;
    }
    return -1;
}

/* Bring column enter, u = B^-1 column, into the basis: the ratio test
   (ties to the smallest variable index), then the pivot.  0 when no
   entry of u is positive, which phase one, bounded below, never meets.  */
static int
simplex3_pivot(simplex3 * S, slong enter, const fmpq * u, fmpq_t q,
               fmpq_t best)
{
    slong i, j, r = -1;

    for (i = 0; i < 3; i++)
    {
        if (fmpq_sgn(u + i) <= 0)
            continue;
        fmpq_div(q, S->xB + i, u + i);
        if (r < 0 || fmpq_cmp(q, best) < 0
            || (fmpq_equal(q, best) && S->basis[i] < S->basis[r]))
        {
            r = i;
            fmpq_set(best, q);
        }
    }
    if (r < 0)
        return 0;
    for (i = 0; i < 3; i++)
        if (i != r)
        {
            fmpq_div(q, u + i, u + r);
            for (j = 0; j < 3; j++)
                fmpq_submul(S->Binv + 3 * i + j, q, S->Binv + 3 * r + j);
            fmpq_submul(S->xB + i, q, S->xB + r);
        }
    for (j = 0; j < 3; j++)
        fmpq_div(S->Binv + 3 * r + j, S->Binv + 3 * r + j, u + r);
    fmpq_div(S->xB + r, S->xB + r, u + r);
    S->basis[r] = enter;
    return 1;
}

/* Phase one to the optimum; 1 with lambda when g is in the cone, else 0
   with sep := the prices.  */
static int
cone3_solve(fmpq * lambda, fmpq * sep, const fmpq * G, slong k,
            const fmpq * g)
{
    simplex3 S;
    slong i, j, enter;
    fmpq u[3], col[3];
    fmpq_t d, best;
    int feasible;

    simplex3_init(&S, k, g);
    for (i = 0; i < 3; i++)
    {
        fmpq_init(u + i);
        fmpq_init(col + i);
    }
    fmpq_init(d);
    fmpq_init(best);
    while ((enter = simplex3_entering(&S, G, d)) >= 0)
    {
        simplex3_column(col, &S, G, enter);
        for (i = 0; i < 3; i++)
            _fmpq_vec_dot(u + i, S.Binv + 3 * i, col, 3);
        if (!simplex3_pivot(&S, enter, u, d, best))
            break;
    }
    fmpq_zero(d);
    for (i = 0; i < 3; i++)
        if (S.basis[i] >= k)
            fmpq_add(d, d, S.xB + i);
    feasible = fmpq_is_zero(d);
    if (feasible)
    {
        _wc_qvec_zero(lambda, k);
        for (i = 0; i < 3; i++)
            if (S.basis[i] < k)
                fmpq_set(lambda + S.basis[i], S.xB + i);
    }
    else
        for (j = 0; j < 3; j++)
            fmpq_set(sep + j, S.pi + j);
    for (i = 0; i < 3; i++)
    {
        fmpq_clear(u + i);
        fmpq_clear(col + i);
    }
    fmpq_clear(d);
    fmpq_clear(best);
    simplex3_clear(&S);
    return feasible;
}

/* 1 when cone3_solve's answer checks exactly.  */
static int
cone3_check(int feasible, const fmpq * lambda, const fmpq * sep,
            const fmpq * G, slong k, const fmpq * g)
{
    slong i, j;
    fmpq_t s;
    int ok = 1;

    fmpq_init(s);
    if (feasible)
    {
        for (i = 0; i < 3 && ok; i++)
        {
            fmpq_zero(s);
            for (j = 0; j < k; j++)
                fmpq_addmul(s, lambda + j, G + 3 * j + i);
            ok = fmpq_equal(s, g + i);
        }
        for (j = 0; j < k && ok; j++)
            ok = fmpq_sgn(lambda + j) >= 0;
    }
    else
    {
        _fmpq_vec_dot(s, sep, g, 3);
        ok = fmpq_sgn(s) > 0;
        for (j = 0; j < k && ok; j++)
        {
            _fmpq_vec_dot(s, sep, G + 3 * j, 3);
            ok = fmpq_sgn(s) <= 0;
        }
    }
    fmpq_clear(s);
    return ok;
}

int
_wc_lp_cone3(fmpq * lambda, fmpq * sep, const fmpq * G, slong k,
             const fmpq * g, wc_error_t err)
{
    int r = cone3_solve(lambda, sep, G, k, g);

    if (!cone3_check(r, lambda, sep, G, k, g))
        r = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                          "a cone membership fails its check"), -1);
    return r;
}
