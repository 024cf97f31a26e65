/* ref-kin.c -- the test oracle for kinematic feasibility (wrenchcone(1), MODES).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   One LP per mode, in the twist nu = (v_x, v_y, omega) and one more
   variable s:

       maximise s  subject to   row_k . nu - s >= 0   (strict rows)
                                row_k . nu     >= 0   (non-strict rows)
                                row_k . nu      = 0   (equalities)
                                          1 - s >= 0

   nu = 0, s = 0 is always feasible and s is bounded, so the LP always has
   an optimum, and since the constraints on nu are homogeneous it is 1 when
   some twist makes every strict row positive (scale it until they are all
   at least 1) and 0 when none does.  Optimum 1: cddlib's point nu is
   substituted into every row.  Optimum 0: LP duality gives multipliers
   y >= 0 on the inequality rows with sum_k y_k row_k = 0 and the strict
   rows' y summing to 1 -- exactly a Motzkin certificate that no twist
   satisfies the rows; it is read from cddlib's dual solution and checked
   here.  So cddlib decides, but is trusted for nothing.  */

#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>

#ifndef GMPRATIONAL
#define GMPRATIONAL 1
#endif
#include <cddlib/setoper.h>
#include <cddlib/cdd.h>

#include "wrenchcone.h"
#include "ref-kin.h"

/* The rows of one mode, in GMP rationals: row k is a[3 k .. 3 k + 2].  */
typedef struct
{
    slong m;
    mpq_t * a;
    int * rel;
}
krows_t;

/* 1 when mode has one Table 1 letter per fixel, allowed in its state.  */
static int
mode_valid(const wc_problem_struct * P, const char * mode)
{
    slong i;

    if (mode == NULL || P->n < 1 || strlen(mode) != (size_t) P->n)
        return 0;
    for (i = 0; i < P->n; i++)
    {
        const char * set = P->fixels[i].state == WC_NEAR ? "sa" : "slrn";

        if (mode[i] == '\0' || strchr(set, mode[i]) == NULL)
            return 0;
    }
    return 1;
}

/* jn = (n_x, n_y, r x n), jt = (t_x, t_y, r x t) of fixel f, with
   t = (-n_y, n_x) and r = p - com; tmp is scratch of 4 entries.  */
static void
fixel_rows(mpq_t * jn, mpq_t * jt, mpq_t * tmp, const wc_fixel_struct * f,
           const fmpq * com)
{
    mpq_t * r = tmp, * q = tmp + 2;

    fmpq_get_mpq(r[0], f->point + 0);
    fmpq_get_mpq(q[0], com + 0);
    mpq_sub(r[0], r[0], q[0]);
    fmpq_get_mpq(r[1], f->point + 1);
    fmpq_get_mpq(q[0], com + 1);
    mpq_sub(r[1], r[1], q[0]);

    fmpq_get_mpq(jn[0], f->normal + 0);
    fmpq_get_mpq(jn[1], f->normal + 1);
    mpq_neg(jt[0], jn[1]);
    mpq_set(jt[1], jn[0]);

    /* r x d = r_x d_y - r_y d_x */
    mpq_mul(q[0], r[0], jn[1]);
    mpq_mul(q[1], r[1], jn[0]);
    mpq_sub(jn[2], q[0], q[1]);
    mpq_mul(q[0], r[0], jt[1]);
    mpq_mul(q[1], r[1], jt[0]);
    mpq_sub(jt[2], q[0], q[1]);
}

static void
krows_clear(krows_t * R)
{
    slong k;

    if (R->a != NULL)
    {
        for (k = 0; k < 3 * R->m; k++)
            mpq_clear(R->a[k]);
        free(R->a);
    }
    free(R->rel);
    R->a = NULL;
    R->rel = NULL;
    R->m = 0;
}

/* Append row sign * v with relation rel.  */
static void
krows_push(krows_t * R, const mpq_t * v, int sign, int rel)
{
    slong k = R->m++, j;

    for (j = 0; j < 3; j++)
    {
        mpq_init(R->a[3 * k + j]);
        if (sign < 0)
            mpq_neg(R->a[3 * k + j], v[j]);
        else
            mpq_set(R->a[3 * k + j], v[j]);
    }
    R->rel[k] = rel;
}

/* The Table 1 rows of mode (which must be valid) for P.  */
static void
krows_build(krows_t * R, const wc_problem_struct * P, const char * mode)
{
    mpq_t jn[3], jt[3], tmp[4];
    slong i, j;

    R->m = 0;
    R->a = malloc(sizeof(mpq_t) * 3 * 2 * P->n);
    R->rel = malloc(sizeof(int) * 2 * P->n);
    for (j = 0; j < 3; j++)
    {
        mpq_init(jn[j]);
        mpq_init(jt[j]);
    }
    for (j = 0; j < 4; j++)
        mpq_init(tmp[j]);

    for (i = 0; i < P->n; i++)
    {
        fixel_rows(jn, jt, tmp, P->fixels + i, P->com);
        if (P->fixels[i].state == WC_NEAR)
        {
            if (mode[i] == 'a')
                krows_push(R, jn, -1, REF_REL_GT);      /* v_in < 0 */
            else
                krows_push(R, jn, +1, REF_REL_GE);      /* v_in >= 0 */
            continue;
        }
        switch (mode[i])
        {
            case 's':
                krows_push(R, jn, +1, REF_REL_GT);
                break;
            case 'l':
                krows_push(R, jn, +1, REF_REL_EQ);
                krows_push(R, jt, +1, REF_REL_GT);
                break;
            case 'r':
                krows_push(R, jn, +1, REF_REL_EQ);
                krows_push(R, jt, -1, REF_REL_GT);      /* v_it < 0 */
                break;
            default:    /* 'n' */
                krows_push(R, jn, +1, REF_REL_EQ);
                krows_push(R, jt, +1, REF_REL_EQ);
                break;
        }
    }

    for (j = 0; j < 3; j++)
    {
        mpq_clear(jn[j]);
        mpq_clear(jt[j]);
    }
    for (j = 0; j < 4; j++)
        mpq_clear(tmp[j]);
}

/* value = row_k . x  */
static void
row_dot(mpq_t value, mpq_t tmp, const krows_t * R, slong k,
        const mpq_t * x)
{
    slong j;

    mpq_set_ui(value, 0, 1);
    for (j = 0; j < 3; j++)
    {
        mpq_mul(tmp, R->a[3 * k + j], x[j]);
        mpq_add(value, value, tmp);
    }
}

/* 1 when x satisfies every row exactly (strict ones strictly).  */
static int
krows_satisfied(const krows_t * R, const mpq_t * x)
{
    mpq_t value, tmp;
    slong k;
    int ok = 1;

    mpq_init(value);
    mpq_init(tmp);
    for (k = 0; k < R->m && ok; k++)
    {
        int sgn;

        row_dot(value, tmp, R, k, x);
        sgn = mpq_sgn(value);
        ok = (R->rel[k] == REF_REL_GT) ? sgn > 0
            : (R->rel[k] == REF_REL_GE) ? sgn >= 0 : sgn == 0;
    }
    mpq_clear(value);
    mpq_clear(tmp);
    return ok;
}

/* 1 when y (one entry per row) is a Motzkin certificate for R:
   sum_k y_k row_k = 0, y_k >= 0 on > and >= rows, y_k > 0 on some >.  */
static int
krows_motzkin(const krows_t * R, const mpq_t * y)
{
    mpq_t sum[3], tmp;
    slong k, j;
    int ok = 1, strict = 0;

    for (j = 0; j < 3; j++)
        mpq_init(sum[j]);
    mpq_init(tmp);
    for (k = 0; k < R->m; k++)
    {
        if (R->rel[k] != REF_REL_EQ && mpq_sgn(y[k]) < 0)
            ok = 0;
        if (R->rel[k] == REF_REL_GT && mpq_sgn(y[k]) > 0)
            strict = 1;
        for (j = 0; j < 3; j++)
        {
            mpq_mul(tmp, y[k], R->a[3 * k + j]);
            mpq_add(sum[j], sum[j], tmp);
        }
    }
    for (j = 0; j < 3; j++)
        if (mpq_sgn(sum[j]) != 0)
            ok = 0;
    for (j = 0; j < 3; j++)
        mpq_clear(sum[j]);
    mpq_clear(tmp);
    return ok && strict;
}

/* The LP of the file comment for the rows R.  Returns 1, 0 or -1.  */
static int
krows_decide(const krows_t * R)
{
    const dd_colrange S = 4;            /* cddlib column of s */
    dd_MatrixPtr M = NULL;
    dd_LPPtr lp = NULL;
    dd_ErrorType e = dd_NoError;
    mpq_t * y = NULL;
    mpq_t nu[3];
    slong k, j;
    int result = -1;

    for (j = 0; j < 3; j++)
        mpq_init(nu[j]);
    wc_init();

    /* Rows 1..m: the mode's rows; row m + 1: 1 - s >= 0.  cddlib reads a
       row (b, a) as b + a . x >= 0, x = (nu, s).  */
    M = dd_CreateMatrix(R->m + 1, 5);
    if (M == NULL)
        goto cleanup;
    M->representation = dd_Inequality;
    M->numbtype = dd_Rational;
    M->objective = dd_LPmax;
    for (k = 0; k < R->m; k++)
    {
        for (j = 0; j < 3; j++)
            mpq_set(M->matrix[k][1 + j], R->a[3 * k + j]);
        if (R->rel[k] == REF_REL_GT)
            mpq_set_si(M->matrix[k][S], -1, 1);
        if (R->rel[k] == REF_REL_EQ)
            set_addelem(M->linset, k + 1);
    }
    mpq_set_si(M->matrix[R->m][0], 1, 1);
    mpq_set_si(M->matrix[R->m][S], -1, 1);
    for (j = 0; j < 5; j++)
        mpq_set_si(M->rowvec[j], j == S ? 1 : 0, 1);

    lp = dd_Matrix2LP(M, &e);
    if (lp == NULL || e != dd_NoError)
        goto cleanup;
    if (!dd_LPSolve(lp, dd_DualSimplex, &e) || e != dd_NoError
        || lp->LPS != dd_Optimal)
        goto cleanup;

    if (mpq_cmp_si(lp->optvalue, 1, 1) == 0)
    {
        for (j = 0; j < 3; j++)
            mpq_set(nu[j], lp->sol[1 + j]);
        result = krows_satisfied(R, nu) ? 1 : -1;
    }
    else if (mpq_sgn(lp->optvalue) == 0)
    {
        /* The dual solution: dsol[j] belongs to the row nbindex[j + 1] of
           cddlib's LP, whose rows are M's rows, then the negated copies of
           M's equalities (in order), then the objective.  Optimality of a
           maximum means obj = -sum_j dsol[j] A_row(j) on the variable
           columns, dsol >= 0 on inequality rows; with obj = (0, 0, 0, 1)
           the nu-columns give sum y_k row_k = 0.  A copy of equality k
           carries the negated row, so it adds -dsol to y_k.  */
        slong eq_rank = 0;
        slong * copy_of = flint_malloc(sizeof(slong) * (lp->m + 1));

        y = flint_malloc(sizeof(mpq_t) * (R->m + 1));
        for (k = 0; k <= R->m; k++)
            mpq_init(y[k]);
        for (k = 0; k <= lp->m; k++)
            copy_of[k] = -1;
        for (k = 0; k < R->m; k++)
            if (R->rel[k] == REF_REL_EQ)
                copy_of[M->rowsize + 1 + eq_rank++] = k;
        result = 0;
        for (j = 1; j < lp->d; j++)
        {
            dd_rowrange row = lp->nbindex[j + 1];

            if (row <= 0)
                continue;       /* no row is nonbasic in this column */
            if (row <= M->rowsize)
                mpq_add(y[row - 1], y[row - 1], lp->dsol[j]);
            else if (row < lp->objrow && copy_of[row] >= 0)
                mpq_sub(y[copy_of[row]], y[copy_of[row]], lp->dsol[j]);
            else
                result = -1;
        }
        /* y[R->m] belongs to 1 - s >= 0, which does not involve nu and
           plays no part in the certificate.  */
        if (result == 0 && !krows_motzkin(R, y))
            result = -1;
        for (k = 0; k <= R->m; k++)
            mpq_clear(y[k]);
        flint_free(y);
        flint_free(copy_of);
    }

cleanup:
    if (lp != NULL)
        dd_FreeLPData(lp);
    if (M != NULL)
        dd_FreeMatrix(M);
    for (j = 0; j < 3; j++)
        mpq_clear(nu[j]);
    return result;
}

int
ref_mode_feasible(const wc_problem_t P, const char * mode)
{
    krows_t R = { 0, NULL, NULL };
    int result;

    if (!mode_valid(P, mode))
        return -1;
    krows_build(&R, P, mode);
    result = krows_decide(&R);
    krows_clear(&R);
    return result;
}

static int
cmp_str(const void * a, const void * b)
{
    return strcmp(*(char * const *) a, *(char * const *) b);
}

void
ref_modes_free(char ** modes, slong count)
{
    slong i;

    if (modes == NULL)
        return;
    for (i = 0; i < count; i++)
        free(modes[i]);
    free(modes);
}

int
ref_modes_bruteforce(char *** modes, slong * count, const wc_problem_t P)
{
    slong n = P->n, i, cap = 16, found = 0;
    char ** list = NULL;
    char * mode = NULL;
    slong * digit = NULL;
    int status = -1;

    *modes = NULL;
    *count = 0;
    if (n < 1)
        return -1;
    list = malloc(sizeof(char *) * cap);
    mode = malloc(n + 1);
    digit = calloc(n, sizeof(slong));

    /* An odometer over the letters each fixel allows.  */
    for (;;)
    {
        int r;

        for (i = 0; i < n; i++)
            mode[i] = (P->fixels[i].state == WC_NEAR ? "as"
                       : "lnrs")[digit[i]];
        mode[n] = '\0';
        r = ref_mode_feasible(P, mode);
        if (r < 0)
            goto cleanup;
        if (r == 1)
        {
            if (found == cap)
            {
                cap *= 2;
                list = realloc(list, sizeof(char *) * cap);
            }
            list[found] = malloc(n + 1);
            memcpy(list[found], mode, n + 1);
            found++;
        }
        for (i = n - 1; i >= 0; i--)
        {
            slong base = (P->fixels[i].state == WC_NEAR) ? 2 : 4;

            if (++digit[i] < base)
                break;
            digit[i] = 0;
        }
        if (i < 0)
            break;
    }
    qsort(list, found, sizeof(char *), cmp_str);
    status = 0;

cleanup:
    if (status == 0)
    {
        *modes = list;
        *count = found;
    }
    else
        ref_modes_free(list, found);
    free(mode);
    free(digit);
    return status;
}

int
ref_mode_rows(fmpz_mat_t rows, int ** rel, const wc_problem_t P,
              const char * mode)
{
    krows_t R = { 0, NULL, NULL };
    mpz_t den, g, v;
    slong k, j;

    *rel = NULL;
    if (!mode_valid(P, mode))
        return -1;
    krows_build(&R, P, mode);
    fmpz_mat_clear(rows);
    fmpz_mat_init(rows, R.m, 3);
    if (R.m > 0)
        *rel = flint_malloc(sizeof(int) * R.m);
    mpz_init(den);
    mpz_init(g);
    mpz_init(v);
    for (k = 0; k < R.m; k++)
    {
        /* Clear the denominators, then divide by the gcd of the
           numerators (positive, so that the sign stays).  */
        mpz_set_ui(den, 1);
        for (j = 0; j < 3; j++)
            mpz_lcm(den, den, mpq_denref(R.a[3 * k + j]));
        mpz_set_ui(g, 0);
        for (j = 0; j < 3; j++)
        {
            mpz_divexact(v, den, mpq_denref(R.a[3 * k + j]));
            mpz_mul(v, v, mpq_numref(R.a[3 * k + j]));
            mpz_gcd(g, g, v);
        }
        for (j = 0; j < 3; j++)
        {
            mpz_divexact(v, den, mpq_denref(R.a[3 * k + j]));
            mpz_mul(v, v, mpq_numref(R.a[3 * k + j]));
            if (mpz_sgn(g) != 0)
                mpz_divexact(v, v, g);
            fmpz_set_mpz(fmpz_mat_entry(rows, k, j), v);
        }
        (*rel)[k] = R.rel[k];
    }
    mpz_clear(den);
    mpz_clear(g);
    mpz_clear(v);
    krows_clear(&R);
    return 0;
}

int
ref_twist_satisfies(const wc_problem_t P, const char * mode,
                    const fmpz * nu)
{
    mpq_t jn[3], jt[3], tmp[4], x[3], vn, vt, t;
    slong i, j;
    int ok = 1;

    if (!mode_valid(P, mode))
        return -1;
    for (j = 0; j < 3; j++)
    {
        mpq_init(jn[j]);
        mpq_init(jt[j]);
        mpq_init(x[j]);
        fmpz_get_mpz(mpq_numref(x[j]), nu + j);
    }
    for (j = 0; j < 4; j++)
        mpq_init(tmp[j]);
    mpq_init(vn);
    mpq_init(vt);
    mpq_init(t);

    /* v_in = J_in . nu and v_it = J_it . nu, then Table 1 on their
       signs, letter by letter -- not through the rows above.  */
    for (i = 0; i < P->n && ok; i++)
    {
        int sn, st;

        fixel_rows(jn, jt, tmp, P->fixels + i, P->com);
        mpq_set_ui(vn, 0, 1);
        mpq_set_ui(vt, 0, 1);
        for (j = 0; j < 3; j++)
        {
            mpq_mul(t, jn[j], x[j]);
            mpq_add(vn, vn, t);
            mpq_mul(t, jt[j], x[j]);
            mpq_add(vt, vt, t);
        }
        sn = mpq_sgn(vn);
        st = mpq_sgn(vt);
        if (P->fixels[i].state == WC_NEAR)
            ok = (mode[i] == 'a') ? sn < 0 : sn >= 0;
        else
            switch (mode[i])
            {
                case 's': ok = sn > 0; break;
                case 'l': ok = sn == 0 && st > 0; break;
                case 'r': ok = sn == 0 && st < 0; break;
                default: ok = sn == 0 && st == 0; break;
            }
    }

    for (j = 0; j < 3; j++)
    {
        mpq_clear(jn[j]);
        mpq_clear(jt[j]);
        mpq_clear(x[j]);
    }
    for (j = 0; j < 4; j++)
        mpq_clear(tmp[j]);
    mpq_clear(vn);
    mpq_clear(vt);
    mpq_clear(t);
    return ok;
}
