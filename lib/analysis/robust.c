/* robust.c -- the robustness of a biasing wrench in a stable set (paper
   Section 7's figure): the largest disturbance that keeps it in the set.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The complement of the set is a union of NNC cones (pieces of the
   cells); rho is the least distance from b to the closure of one of them,
   one LP each, and the ball of radius rho is closed in the set when no
   included face of a nearest piece meets it.  */

#include <config.h>

#include <flint/fmpq_vec.h>

#include "exact/cddbridge.h"
#include "exact/vec3.h"
#include "analysis/stability.h"

/* The distance from b to cl C in the norm max(|x|, |y|, |tau| / L): min t
   over x in cl C with |x_k - b_k| <= t (k = 1, 2), |x_3 - b_3| <= L t.  */
static int
closure_distance(fmpq_t d, const wc_cone_t C, const fmpq * b,
                 const fmpq_t L, wc_error_t err)
{
    slong ni = fmpz_mat_nrows(C->ineqs), ne = fmpz_mat_nrows(C->eqs);
    slong m = 6 + ni + ne, i, k, r = 0;
    fmpq_mat_t A;
    fmpq * rhs = _fmpq_vec_init(m), * x = _fmpq_vec_init(4),
        * c = _fmpq_vec_init(4);
    int * eq = flint_calloc(m, sizeof(int)), res;

    fmpq_mat_init(A, m, 4);
    for (k = 0; k < 3; k++)
    {
        const fmpq * s = k < 2 ? NULL : L;

        /* t' - (x_k - b_k) >= 0 and t' + (x_k - b_k) >= 0, t' = t or L t */
        fmpq_set_si(fmpq_mat_entry(A, r, k), -1, 1);
        if (s != NULL)
            fmpq_set(fmpq_mat_entry(A, r, 3), s);
        else
            fmpq_one(fmpq_mat_entry(A, r, 3));
        fmpq_neg(rhs + r, b + k);
        r++;
        fmpq_one(fmpq_mat_entry(A, r, k));
        if (s != NULL)
            fmpq_set(fmpq_mat_entry(A, r, 3), s);
        else
            fmpq_one(fmpq_mat_entry(A, r, 3));
        fmpq_set(rhs + r, b + k);
        r++;
    }
    for (i = 0; i < ni; i++, r++)
        for (k = 0; k < 3; k++)
        {
            fmpq_set_fmpz(fmpq_mat_entry(A, r, k),
                          fmpz_mat_entry(C->ineqs, i, k));
            fmpq_neg(fmpq_mat_entry(A, r, k), fmpq_mat_entry(A, r, k));
        }
    for (i = 0; i < ne; i++, r++)
    {
        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(fmpq_mat_entry(A, r, k),
                          fmpz_mat_entry(C->eqs, i, k));
        eq[r] = 1;
    }
    fmpq_one(c + 3);
    res = _wc_cdd_lp_min(x, d, A, rhs, eq, c, err);
    if (res == 0 || res == 2)
        res = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                            "distance LP ended without an optimum"), -1);
    fmpq_mat_clear(A);
    _fmpq_vec_clear(rhs, m);
    _fmpq_vec_clear(x, 4);
    _fmpq_vec_clear(c, 4);
    flint_free(eq);
    return res < 0 ? WC_EINTERNAL : WC_OK;
}

/* *meets := 1 when the included face F of C meets the closed ball of
   radius rho about b: its rays with coefficients >= s > 0 (s maximised
   up to 1), its lines free (each as the difference of two coefficients
   >= 0).  */
static int
face_meets_ball(int * meets, const wc_cone_t C, const wc_face_struct * F,
                const fmpq * b, const fmpq_t rho, const fmpq_t L,
                wc_error_t err)
{
    slong nl = fmpz_mat_nrows(C->lines), nr = F->nrays;
    slong nv = nr + 2 * nl + 1, m = nr + 6 + 1, r = 0, i, j, k;
    fmpq_mat_t A;
    fmpq * rhs = _fmpq_vec_init(m), * x = _fmpq_vec_init(nv),
        * c = _fmpq_vec_init(nv);
    fmpq_t val, lim;
    int * eq = flint_calloc(m, sizeof(int)), res, sg;

    fmpq_mat_init(A, m, nv);
    fmpq_init(val);
    fmpq_init(lim);
    /* mu_i - s >= 0 */
    for (i = 0; i < nr; i++, r++)
    {
        fmpq_one(fmpq_mat_entry(A, r, i));
        fmpq_set_si(fmpq_mat_entry(A, r, nv - 1), -1, 1);
    }
    /* lim -+ (sum mu r + sum (l+ - l-) line - b)_k >= 0 */
    for (k = 0; k < 3; k++)
    {
        if (k < 2)
            fmpq_set(lim, rho);
        else
            fmpq_mul(lim, rho, L);
        for (sg = -1; sg <= 1; sg += 2, r++)
        {
            for (i = 0; i < nr; i++)
                fmpq_set_fmpz(fmpq_mat_entry(A, r, i),
                              fmpz_mat_entry(C->rays, F->rays[i], k));
            for (j = 0; j < nl; j++)
            {
                fmpq_set_fmpz(fmpq_mat_entry(A, r, nr + 2 * j),
                              fmpz_mat_entry(C->lines, j, k));
                fmpq_neg(fmpq_mat_entry(A, r, nr + 2 * j + 1),
                         fmpq_mat_entry(A, r, nr + 2 * j));
            }
            for (i = 0; i < nr + 2 * nl; i++)
                if (sg > 0)
                    fmpq_neg(fmpq_mat_entry(A, r, i),
                             fmpq_mat_entry(A, r, i));
            /* sg = -1: (v - b) >= -lim; sg = +1: -(v - b) >= -lim */
            if (sg < 0)
                fmpq_sub(rhs + r, b + k, lim);
            else
            {
                fmpq_neg(rhs + r, b + k);
                fmpq_sub(rhs + r, rhs + r, lim);
            }
        }
    }
    /* -s >= -1 */
    fmpq_set_si(fmpq_mat_entry(A, r, nv - 1), -1, 1);
    fmpq_set_si(rhs + r, -1, 1);
    fmpq_set_si(c + nv - 1, -1, 1);    /* minimise -s */
    res = _wc_cdd_lp_min(x, val, A, rhs, eq, c, err);
    *meets = res == 1 && fmpq_sgn(val) < 0;
    fmpq_mat_clear(A);
    _fmpq_vec_clear(rhs, m);
    _fmpq_vec_clear(x, nv);
    _fmpq_vec_clear(c, nv);
    flint_free(eq);
    fmpq_clear(val);
    fmpq_clear(lim);
    return res < 0 ? WC_EINTERNAL : WC_OK;
}

/* *meets := 1 when some included face of C meets the closed ball of
   radius rho about b.  */
static int
meets_ball(int * meets, const wc_cone_t C, const fmpq * b, const fmpq_t rho,
           const fmpq_t L, wc_error_t err)
{
    slong f;
    int status = WC_OK;

    *meets = 0;
    for (f = 0; f < C->nfaces && !*meets && status == WC_OK; f++)
        if (C->faces[f].included)
            status = face_meets_ball(meets, C, C->faces + f, b, rho, L, err);
    return status;
}

int
wc_robustness(fmpq_t rho, int * closed, int * infinite, const wc_set_t set,
              const wc_cells_t cells, const fmpq * b, const fmpq_t L,
              wc_error_t err)
{
    wc_set_t C;
    int * out = flint_malloc(sizeof(int) * (cells->count + 1));
    slong i;
    int status, meets;
    fmpq * d;
    fmpq g[3];

    wc_set_init(C);
    for (i = 0; i < 3; i++)
        fmpq_init(g + i);
    for (i = 0; i < cells->count; i++)
    {
        _fmpq_vec_set_fmpz_vec(g, WC_ROW(cells->point, i), 3);
        out[i] = !wc_set_contains(set, g);
    }
    status = wc_set_from_cells(C, cells, out, err);
    *infinite = C->empty;
    *closed = 0;
    fmpq_zero(rho);
    d = _fmpq_vec_init(C->npieces + 1);
    for (i = 0; i < C->npieces && status == WC_OK; i++)
    {
        status = closure_distance(d + i, C->pieces + i, b, L, err);
        if (status == WC_OK && (i == 0 || fmpq_cmp(d + i, rho) < 0))
            fmpq_set(rho, d + i);
    }
    if (status == WC_OK && !C->empty)
    {
        /* closed unless a nearest piece reaches the sphere itself */
        *closed = 1;
        for (i = 0; i < C->npieces && status == WC_OK && *closed; i++)
            if (fmpq_equal(d + i, rho))
            {
                status = meets_ball(&meets, C->pieces + i, b, rho, L, err);
                *closed = !meets;
            }
    }
    _fmpq_vec_clear(d, C->npieces + 1);
    wc_set_clear(C);
    for (i = 0; i < 3; i++)
        fmpq_clear(g + i);
    flint_free(out);
    return status;
}
