/* ref-lp.c -- the test oracle: membership in a wrench cone by one exact LP.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Deliberately naive: every variable of y = (a; c) is kept, every Table 2
   constraint becomes one LP row, and the matrices of eq. (3)-(9) are
   recomputed here in mpq_t from the problem's fields, so that nothing the
   library computes can leak into the answer it is checked against.  cddlib
   is trusted for nothing: a feasible answer comes with a point that is
   substituted back into every row, an infeasible one with a Farkas
   combination of the rows that is summed up again; when either check fails
   the answer is -1, never a guess.  */

#include <stdlib.h>

#include <gmp.h>
#include <flint/flint.h>
#include <flint/fmpq.h>

#ifndef GMPRATIONAL
#define GMPRATIONAL 1
#endif
#include <cddlib/setoper.h>
#include <cddlib/cdd.h>

#include "wrenchcone.h"
#include "ref-lp.h"

/* A row-major array of mpq_t, all initialised to 0.  */
static mpq_t *
qvec_init(slong len)
{
    mpq_t * v = flint_malloc(sizeof(mpq_t) * (len > 0 ? len : 1));
    slong i;

    for (i = 0; i < len; i++)
        mpq_init(v[i]);
    return v;
}

static void
qvec_clear(mpq_t * v, slong len)
{
    slong i;

    if (v == NULL)
        return;
    for (i = 0; i < len; i++)
        mpq_clear(v[i]);
    flint_free(v);
}

/* C (2n x 4n) and B (2n x 3) of eq. (7), from the problem's fields alone.
   Returns 0, or -1 when the mass or the inertia is not positive (the
   caller's problem is then not a valid one).  */
static int
ref_model(mpq_t * C, mpq_t * B, const wc_problem_struct * P)
{
    slong n = P->n, k = 2 * n, i, j, c, side;
    mpq_t * J = qvec_init(3 * k);
    mpq_t minv[3], r[2], d[2], t;
    int status = -1;

    for (c = 0; c < 3; c++)
        mpq_init(minv[c]);
    mpq_init(r[0]);
    mpq_init(r[1]);
    mpq_init(d[0]);
    mpq_init(d[1]);
    mpq_init(t);

    fmpq_get_mpq(minv[0], P->mass);
    fmpq_get_mpq(minv[2], P->inertia);
    if (mpq_sgn(minv[0]) <= 0 || mpq_sgn(minv[2]) <= 0)
        goto cleanup;
    mpq_inv(minv[0], minv[0]);
    mpq_inv(minv[2], minv[2]);
    mpq_set(minv[1], minv[0]);

    /* J: column i is the normal of fixel i, column n + i its tangent (the
       normal turned by +90 degrees); each column is (d_x, d_y, r_i x d).  */
    for (i = 0; i < n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        for (j = 0; j < 2; j++)
        {
            fmpq_get_mpq(r[j], f->point + j);
            fmpq_get_mpq(t, P->com + j);
            mpq_sub(r[j], r[j], t);
        }
        for (side = 0; side < 2; side++)
        {
            slong col = side * n + i;

            if (side == 0)
            {
                fmpq_get_mpq(d[0], f->normal + 0);
                fmpq_get_mpq(d[1], f->normal + 1);
            }
            else
            {
                fmpq_get_mpq(d[0], f->normal + 1);
                mpq_neg(d[0], d[0]);
                fmpq_get_mpq(d[1], f->normal + 0);
            }
            mpq_set(J[0 * k + col], d[0]);
            mpq_set(J[1 * k + col], d[1]);
            mpq_mul(J[2 * k + col], r[0], d[1]);
            mpq_mul(t, r[1], d[0]);
            mpq_sub(J[2 * k + col], J[2 * k + col], t);
        }
    }

    /* B = J^T M^-1; C = [I, -A] with A = J^T M^-1 J = B J.  */
    for (i = 0; i < k; i++)
        for (c = 0; c < 3; c++)
            mpq_mul(B[i * 3 + c], J[c * k + i], minv[c]);
    for (i = 0; i < k; i++)
    {
        for (j = 0; j < k; j++)
        {
            mpq_t * a = &C[i * 2 * k + k + j];

            mpq_set_ui(*a, 0, 1);
            for (c = 0; c < 3; c++)
            {
                mpq_mul(t, B[i * 3 + c], J[c * k + j]);
                mpq_sub(*a, *a, t);
            }
        }
        for (j = 0; j < k; j++)
            mpq_set_ui(C[i * 2 * k + j], i == j, 1);
    }
    status = 0;

cleanup:
    for (c = 0; c < 3; c++)
        mpq_clear(minv[c]);
    mpq_clear(r[0]);
    mpq_clear(r[1]);
    mpq_clear(d[0]);
    mpq_clear(d[1]);
    mpq_clear(t);
    qvec_clear(J, 3 * k);
    return status;
}

/* Rows one Table 2 letter adds; -1 for a letter not in the table.  */
static slong
letter_rows(char x)
{
    switch (x)
    {
        case 's': case 'a': return 3;
        case 'u': return 2;
        case 'l': case 'r': case 'm': return 4;
        case 'n': return 5;
        default: return -1;
    }
}

/* A cddlib H-representation filled row by row: row i reads
   b + sum_j a_j x_j >= 0, or = 0 when it is in the linearity set.
   Variables are 0-based here, column 1 + var in cddlib.  */
typedef struct
{
    dd_MatrixPtr M;
    dd_rowrange next;
}
rows_t;

static dd_rowrange
row_new(rows_t * R, long b, int equality)
{
    dd_rowrange i = R->next++;

    dd_set_si(R->M->matrix[i][0], b);
    if (equality)
        set_addelem(R->M->linset, i + 1);
    return i;
}

static void
row_si(rows_t * R, dd_rowrange i, slong var, long a)
{
    dd_set_si(R->M->matrix[i][1 + var], a);
}

static void
row_q(rows_t * R, dd_rowrange i, slong var, const mpq_t a)
{
    mpq_set(R->M->matrix[i][1 + var], a);
}

/* The Table 2 rows of fixel i under letter x.  Strict inequalities are
   written as >= 1 or <= -1: the whole system is homogeneous in (y, t)
   (resp. (y, g)), so any solution with the strict ones positive can be
   scaled until they are at least 1.  */
static void
letter_write(rows_t * R, slong n, slong i, char x, const mpq_t mu_s,
             const mpq_t mu_k, mpq_t tmp)
{
    slong an = i, at = n + i, cn = 2 * n + i, ct = 3 * n + i;
    dd_rowrange r;

    switch (x)
    {
        case 's':               /* a_in >= 0, c = 0 */
            r = row_new(R, 0, 0); row_si(R, r, an, 1);
            r = row_new(R, 0, 1); row_si(R, r, cn, 1);
            r = row_new(R, 0, 1); row_si(R, r, ct, 1);
            break;
        case 'a':               /* a_in < 0, c = 0 */
            r = row_new(R, -1, 0); row_si(R, r, an, -1);
            r = row_new(R, 0, 1); row_si(R, r, cn, 1);
            r = row_new(R, 0, 1); row_si(R, r, ct, 1);
            break;
        case 'u':               /* c = 0 */
            r = row_new(R, 0, 1); row_si(R, r, cn, 1);
            r = row_new(R, 0, 1); row_si(R, r, ct, 1);
            break;
        case 'l':               /* a_in = 0, a_it > 0, c_it = -mu_k c_in */
        case 'r':               /* a_in = 0, a_it < 0, c_it = +mu_k c_in */
            r = row_new(R, 0, 1); row_si(R, r, an, 1);
            r = row_new(R, -1, 0); row_si(R, r, at, x == 'l' ? 1 : -1);
            r = row_new(R, 0, 0); row_si(R, r, cn, 1);
            r = row_new(R, 0, 1); row_si(R, r, ct, 1);
            if (x == 'l')
                row_q(R, r, cn, mu_k);
            else
            {
                mpq_neg(tmp, mu_k);
                row_q(R, r, cn, tmp);
            }
            break;
        case 'n':               /* a = 0, |c_it| <= mu_s c_in */
        case 'm':               /* a_in = 0, |c_it| <= mu_s c_in */
            r = row_new(R, 0, 1); row_si(R, r, an, 1);
            if (x == 'n')
            {
                r = row_new(R, 0, 1); row_si(R, r, at, 1);
            }
            r = row_new(R, 0, 0); row_si(R, r, cn, 1);
            r = row_new(R, 0, 0); row_q(R, r, cn, mu_s); row_si(R, r, ct, -1);
            r = row_new(R, 0, 0); row_q(R, r, cn, mu_s); row_si(R, r, ct, 1);
            break;
        default:
            break;
    }
}

/* value = b + a . x for row i of M, x_j = sol[j] (cddlib's layout: sol[0]
   is the homogenising coordinate).  */
static void
row_value(mpq_t value, mpq_t tmp, const dd_MatrixPtr M, dd_rowrange i,
          const dd_Arow sol)
{
    dd_colrange j;

    mpq_set(value, M->matrix[i][0]);
    for (j = 1; j < M->colsize; j++)
    {
        mpq_mul(tmp, M->matrix[i][j], sol[j]);
        mpq_add(value, value, tmp);
    }
}

/* 1 when sol satisfies every row of M exactly.  */
static int
check_point(const dd_MatrixPtr M, const dd_Arow sol)
{
    mpq_t value, tmp;
    dd_rowrange i;
    int ok = 1;

    mpq_init(value);
    mpq_init(tmp);
    for (i = 0; i < M->rowsize && ok; i++)
    {
        row_value(value, tmp, M, i, sol);
        if (set_member(i + 1, M->linset))
            ok = (mpq_sgn(value) == 0);
        else
            ok = (mpq_sgn(value) >= 0);
    }
    mpq_clear(value);
    mpq_clear(tmp);
    return ok;
}

/* 1 when cddlib's evidence for an inconsistent LP is a valid Farkas
   certificate: multipliers lambda (1 on the evidence row re, dsol[j] on
   the row that is nonbasic in column j + 1), >= 0 on inequality rows, such
   that sum lambda_i a_i = 0 and sum lambda_i b_i < 0.  The LP's rows are
   M's rows, then the reversed copies of the equalities (inequalities
   themselves), then the objective row, which must take no part.  */
static int
check_farkas(const dd_LPPtr lp, const dd_MatrixPtr M)
{
    mpq_t * sum = qvec_init(lp->d);
    mpq_t tmp;
    dd_colrange j, c;
    int ok = 1;

    mpq_init(tmp);
    for (j = 0; j < lp->d && ok; j++)
    {
        dd_rowrange row = (j == 0) ? lp->re : lp->nbindex[j + 1];
        mpq_srcptr lambda = (j == 0) ? dd_one : lp->dsol[j];

        if (j > 0 && row <= 0)
            continue;           /* column j + 1 holds no row */
        if (row < 1 || row >= lp->objrow)
            ok = 0;
        else if (mpq_sgn(lambda) < 0
                 && !(row <= M->rowsize && set_member(row, M->linset)))
            ok = 0;
        else
            for (c = 0; c < lp->d; c++)
            {
                mpq_mul(tmp, lambda, lp->A[row - 1][c]);
                mpq_add(sum[c], sum[c], tmp);
            }
    }
    if (ok)
        ok = (mpq_sgn(sum[0]) < 0);
    for (c = 1; c < lp->d && ok; c++)
        ok = (mpq_sgn(sum[c]) == 0);
    mpq_clear(tmp);
    qvec_clear(sum, lp->d);
    return ok;
}

/* The LP itself.  Variables: y (4n entries), then t (g given) or g (3
   entries, g == NULL).  Returns 1 feasible, 0 infeasible, -1 failure.  */
static int
ref_lp(const wc_problem_struct * P, const char * mode, const fmpq * g)
{
    slong n = P->n, k = 2 * n, ny = 4 * n, nv, nrows, i, j, c;
    mpq_t * C = NULL, * B = NULL, * Bg = NULL;
    mpq_t mu_s, mu_k, tmp;
    dd_MatrixPtr M = NULL;
    dd_LPPtr lp = NULL;
    dd_ErrorType err = dd_NoError;
    rows_t R;
    int result = -1;

    mpq_init(mu_s);
    mpq_init(mu_k);
    mpq_init(tmp);
    wc_init();

    if (n < 1 || mode == NULL)
        goto cleanup;
    nrows = k + (g != NULL ? 1 : 0);
    for (i = 0; i < n; i++)
    {
        slong r = letter_rows(mode[i]);

        if (r < 0)
            goto cleanup;
        nrows += r;
    }
    if (mode[n] != '\0')
        goto cleanup;
    nv = ny + (g != NULL ? 1 : 3);

    C = qvec_init(k * 2 * k);
    B = qvec_init(k * 3);
    Bg = qvec_init(k);
    if (ref_model(C, B, P) != 0)
        goto cleanup;

    M = dd_CreateMatrix(nrows, 1 + nv);
    if (M == NULL)
        goto cleanup;
    M->representation = dd_Inequality;
    M->numbtype = dd_Rational;
    M->objective = dd_LPmax;
    for (j = 0; j < 1 + nv; j++)
        dd_set_si(M->rowvec[j], 0);
    R.M = M;
    R.next = 0;

    /* Eq. (7): C y = B g, written C y - t (B g) = 0 with g given, so that
       the system stays homogeneous; C y - B g = 0 with g free.  */
    if (g != NULL)
    {
        for (i = 0; i < k; i++)
            for (c = 0; c < 3; c++)
            {
                fmpq_get_mpq(tmp, g + c);
                mpq_mul(tmp, tmp, B[i * 3 + c]);
                mpq_add(Bg[i], Bg[i], tmp);
            }
    }
    for (i = 0; i < k; i++)
    {
        dd_rowrange r = row_new(&R, 0, 1);

        for (j = 0; j < 2 * k; j++)
            row_q(&R, r, j, C[i * 2 * k + j]);
        if (g != NULL)
        {
            mpq_neg(tmp, Bg[i]);
            row_q(&R, r, ny, tmp);
        }
        else
            for (c = 0; c < 3; c++)
            {
                mpq_neg(tmp, B[i * 3 + c]);
                row_q(&R, r, ny + c, tmp);
            }
    }
    if (g != NULL)
    {
        dd_rowrange r = row_new(&R, -1, 0);    /* t >= 1 */

        row_si(&R, r, ny, 1);
    }
    for (i = 0; i < n; i++)
    {
        fmpq_get_mpq(mu_s, P->fixels[i].mu_s);
        fmpq_get_mpq(mu_k, P->fixels[i].mu_k);
        letter_write(&R, n, i, mode[i], mu_s, mu_k, tmp);
    }
    if (R.next != nrows)
        goto cleanup;

    lp = dd_Matrix2LP(M, &err);
    if (lp == NULL || err != dd_NoError)
        goto cleanup;
    if (!dd_LPSolve(lp, dd_DualSimplex, &err) || err != dd_NoError)
        goto cleanup;
    if (lp->LPS == dd_Optimal)
        result = check_point(M, lp->sol) ? 1 : -1;
    else if (lp->LPS == dd_Inconsistent)
        result = check_farkas(lp, M) ? 0 : -1;

cleanup:
    if (lp != NULL)
        dd_FreeLPData(lp);
    if (M != NULL)
        dd_FreeMatrix(M);
    qvec_clear(C, k * 2 * k);
    qvec_clear(B, k * 3);
    qvec_clear(Bg, k);
    mpq_clear(mu_s);
    mpq_clear(mu_k);
    mpq_clear(tmp);
    return result;
}

int
ref_wrench_in_cone(const wc_problem_t P, const char * mode, const fmpq * g)
{
    if (g == NULL)
        return -1;
    return ref_lp(P, mode, g);
}

int
ref_cone_nonempty(const wc_problem_t P, const char * mode)
{
    return ref_lp(P, mode, NULL);
}
