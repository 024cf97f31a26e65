/* kinematics.c -- kinematically feasible modes (the walk itself is in
   modeswalk.c), the constraint rows of a mode, and one mode's
   certificate.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "core/error.h"
#include "core/problem.h"
#include "model/mode.h"
#include "model/model.h"
#include "exact/vec3.h"
#include "exact/cddbridge.h"
#include "exact/lp.h"
#include "analysis/kinematics.h"
#include "analysis/modeswalk.h"


void
_wc_modes_columns(fmpz_mat_t a, const wc_problem_t P)
{
    slong K = 2 * P->n, k;
    fmpq_mat_t J, Jt;

    fmpq_mat_init(J, 3, K);
    fmpq_mat_init(Jt, K, 3);
    wc_model_J(J, P);
    fmpq_mat_transpose(Jt, J);
    for (k = 0; k < K; k++)
        _wc_qvec_primitive(WC_ROW(a, k), WC_ROW(Jt, k), 3);
    fmpq_mat_clear(J);
    fmpq_mat_clear(Jt);
}

int
wc_mode_constraints(fmpz_mat_t rows, wc_relation ** rel,
                    const wc_problem_t P, const char * mode, wc_error_t err)
{
    slong n = P->n, i, m = 0;
    fmpz_mat_t a, R;
    wc_relation * r;
    int status;

    *rel = NULL;
    if ((status = wc_mode_check(P, mode, WC_TABLE_KINEMATIC, err)) != WC_OK)
        return status;
    fmpz_mat_init(a, 2 * n, 3);
    fmpz_mat_init(R, 2 * n, 3);
    r = malloc(sizeof(wc_relation) * (2 * n + 1));
    _wc_modes_columns(a, P);
#define ADD(k, sign, rl) do { \
        _fmpz_vec_scalar_mul_si(WC_ROW(R, m), WC_ROW(a, k), 3, sign); \
        r[m++] = (rl); \
    } while (0)
    for (i = 0; i < n; i++)
    {
        int near = P->fixels[i].state == WC_NEAR;

        switch (mode[i])
        {
        case 's':
            ADD(i, 1, near ? WC_REL_GE : WC_REL_GT);
            break;
        case 'a':
            ADD(i, -1, WC_REL_GT);
            break;
        case 'l':
            ADD(i, 1, WC_REL_EQ);
            ADD(n + i, 1, WC_REL_GT);
            break;
        case 'r':
            ADD(i, 1, WC_REL_EQ);
            ADD(n + i, -1, WC_REL_GT);
            break;
        default:                /* 'n' */
            ADD(i, 1, WC_REL_EQ);
            ADD(n + i, 1, WC_REL_EQ);
            break;
        }
    }
#undef ADD
    fmpz_mat_clear(rows);
    fmpz_mat_init(rows, m, 3);
    for (i = 0; i < m; i++)
        _fmpz_vec_set(WC_ROW(rows, i), WC_ROW(R, i), 3);
    *rel = r;
    fmpz_mat_clear(a);
    fmpz_mat_clear(R);
    return WC_OK;
}

void
wc_modes_init(wc_modes_t M)
{
    M->n = 0;
    M->count = 0;
    M->modes = NULL;
    fmpz_mat_init(M->witness, 0, 3);
}

void
wc_modes_clear(wc_modes_t M)
{
    slong i;

    for (i = 0; i < M->count; i++)
        free(M->modes[i]);
    free(M->modes);
    fmpz_mat_clear(M->witness);
    wc_modes_init(M);
}

/* WC_OK when P has at most WC_MODES_MAX_NEAR near fixels, else
   WC_EINPUT located at the first near fixel beyond it (in the words of
   wc_problem_check_fixels).  */
static int
check_near(const wc_problem_t P, wc_error_t err)
{
    slong i, count = 0;

    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        if (f->state == WC_NEAR && ++count > WC_MODES_MAX_NEAR)
            return wc_error_set(err, WC_EINPUT, P->file, f->line, f->col,
                                "mode enumeration handles at most %ld near "
                                "fixels (this is near fixel %ld)",
                                (long) WC_MODES_MAX_NEAR, (long) count);
    }
    return WC_OK;
}

int
wc_modes_enumerate(wc_modes_t M, const wc_problem_t P, wc_error_t err)
{
    int status = wc_problem_check(P, err);

    if (status == WC_OK)
        status = wc_problem_check_fixels(P, WC_MODES_MAX_FIXELS, 0,
                                         "mode enumeration", err);
    if (status == WC_OK)
        status = check_near(P, err);
    if (status == WC_OK)
        status = _wc_modes_walk(M, P, err);
    return status;
}

/* ---------------------------------------------------------------------
   One mode's certificate.  */

void
wc_certificate_init(wc_certificate_t C)
{
    slong j;

    C->mode = NULL;
    C->feasible = 0;
    for (j = 0; j < 3; j++)
        fmpz_init(C->witness + j);
    fmpz_mat_init(C->rows, 0, 3);
    C->rel = NULL;
    C->mult = NULL;
}

void
wc_certificate_clear(wc_certificate_t C)
{
    slong j;

    if (C->mult != NULL)
        _fmpz_vec_clear(C->mult, fmpz_mat_nrows(C->rows));
    free(C->mode);
    free(C->rel);
    for (j = 0; j < 3; j++)
        fmpz_clear(C->witness + j);
    fmpz_mat_clear(C->rows);
    C->mode = NULL;
    C->rel = NULL;
    C->mult = NULL;
}

int
wc_feasible(wc_certificate_t C, const wc_problem_t P, const char * mode,
            wc_error_t err)
{
    slong m;
    fmpq_mat_t A;
    fmpq * z, * y;
    int status, found;

    wc_certificate_clear(C);
    wc_certificate_init(C);
    status = wc_mode_constraints(C->rows, &C->rel, P, mode, err);
    if (status != WC_OK)
        return status;
    C->mode = malloc(strlen(mode) + 1);
    strcpy(C->mode, mode);
    m = fmpz_mat_nrows(C->rows);
    C->mult = _fmpz_vec_init(m);

    /* A twist, or Motzkin multipliers (m = 0: nu = 0).  */
    fmpq_mat_init(A, m, 3);
    fmpq_mat_set_fmpz_mat(A, C->rows);
    z = _fmpq_vec_init(3);
    y = _fmpq_vec_init(m + 1);
    found = _wc_lp_motzkin(z, y, A, C->rel, err);
    if (found < 0)
        status = WC_EINTERNAL;
    else if (found)
    {
        C->feasible = 1;
        _wc_qvec_primitive(C->witness, z, 3);
        if (!wc_certificate_check(C))
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: the witness of %s fails",
                                  mode);
    }
    else
    {
        _wc_qvec_primitive(C->mult, y, m);
        if (!wc_certificate_check(C))
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: certificate of %s fails",
                                  mode);
    }
    fmpq_mat_clear(A);
    _fmpq_vec_clear(z, 3);
    _fmpq_vec_clear(y, m + 1);
    return status;
}

int
wc_certificate_check(const wc_certificate_t C)
{
    slong m = fmpz_mat_nrows(C->rows), i, j;
    fmpz_t s;
    int ok = 1, strict = 0;

    fmpz_init(s);
    if (C->feasible)
    {
        for (i = 0; i < m && ok; i++)
        {
            _fmpz_vec_dot(s, WC_ROW(C->rows, i), C->witness, 3);
            ok = C->rel[i] == WC_REL_GT ? fmpz_sgn(s) > 0
                : C->rel[i] == WC_REL_GE ? fmpz_sgn(s) >= 0 : fmpz_is_zero(s);
        }
    }
    else
    {
        for (i = 0; i < m && ok; i++)
        {
            if (C->rel[i] != WC_REL_EQ && fmpz_sgn(C->mult + i) < 0)
                ok = 0;
            if (C->rel[i] == WC_REL_GT && fmpz_sgn(C->mult + i) > 0)
                strict = 1;
        }
        for (j = 0; j < 3 && ok; j++)
        {
            fmpz_zero(s);
            for (i = 0; i < m; i++)
                fmpz_addmul(s, C->mult + i, fmpz_mat_entry(C->rows, i, j));
            ok = fmpz_is_zero(s);
        }
        ok = ok && strict;
    }
    fmpz_clear(s);
    return ok;
}
