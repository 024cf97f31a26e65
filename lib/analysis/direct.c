/* direct.c -- the direct route to W(x): a Minkowski sum in R^3.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Table 2 never couples a with c, and g = M nudot - J c, so
   W(x) = M V_x + (-J) D_x with V_x = { nudot : J^T nudot satisfies the
   a-constraints of x } (an NNC cone in R^3) and D_x the closed cone of
   the friction-cone edges of x.  All work is in dimension 3, whatever n.  */

#include <config.h>

#include "model/mode.h"
#include "model/model.h"
#include "exact/cone.h"
#include "exact/lp.h"
#include "analysis/wrench.h"
#include "analysis/direct3.h"

/* Set row (*r)++ of A (allocated with room) to column col of J, times
   sign.  */
static void
append_row(fmpq_mat_t A, slong * r, const fmpq_mat_t J, slong col, int sign)
{
    slong j;

    for (j = 0; j < 3; j++)
    {
        fmpq_set(fmpq_mat_entry(A, *r, j), fmpq_mat_entry(J, j, col));
        if (sign < 0)
            fmpq_neg(fmpq_mat_entry(A, *r, j), fmpq_mat_entry(A, *r, j));
    }
    (*r)++;
}

static int general(wc_cone_t W, wc_trace_t trace, const wc_problem_t P,
                   const char * mode, wc_error_t err);

int
wc_wrench_cone_direct(wc_cone_t W, wc_trace_t trace, const wc_problem_t P,
                      const char * mode, wc_error_t err)
{
    int status, done = 0;

    /* The mode is checked once.  Integer rows and generators straight
       from the model when V_x is simple (direct3.c); the general route
       below otherwise, and always for a trace, which shows its rational
       matrices.  */
    if ((status = wc_mode_check(P, mode, WC_TABLE_CONE, err)) != WC_OK)
    {
        wc_cone_set_empty(W);
        return status;
    }
    if (trace == NULL && W->d == 3)
    {
        status = _wc_wrench_cone_direct3(W, &done, P, mode, err);
        if (status != WC_OK || done)
            return status;
    }
    return general(W, trace, P, mode, err);
}

int
_wc_wrench_cone_direct_general(wc_cone_t W, wc_trace_t trace,
                               const wc_problem_t P, const char * mode,
                               wc_error_t err)
{
    int status;

    if ((status = wc_mode_check(P, mode, WC_TABLE_CONE, err)) != WC_OK)
    {
        wc_cone_set_empty(W);
        return status;
    }
    return general(W, trace, P, mode, err);
}

/* The general route, for a mode that passed wc_mode_check.  */
static int
general(wc_cone_t W, wc_trace_t trace, const wc_problem_t P,
        const char * mode, wc_error_t err)
{
    slong n = P->n, i, j, q = 0, re = 0, rl = 0, rt = 0;
    fmpq_mat_t J, M, Eq, Le, Lt, Q, Vr;
    fmpq e[4];
    wc_cone_t V;
    int status;

    fmpq_mat_init(J, 3, 2 * n);
    fmpq_mat_init(M, 3, 3);
    fmpq_mat_init(Eq, 2 * n, 3);       /* trimmed below */
    fmpq_mat_init(Le, n, 3);
    fmpq_mat_init(Lt, n, 3);
    fmpq_mat_init(Q, 2 * n, 3);
    for (j = 0; j < 4; j++)
        fmpq_init(e + j);
    wc_cone_init(V, 3);
    wc_model_J(J, P);
    wc_model_M(M, P);

    /* V_x in the convention h . nudot <= 0 (or = 0, or < 0), with
       a_in = J_in . nudot and a_it = J_it . nudot.  */
    for (i = 0; i < n; i++)
    {
        slong cn = i, ct = n + i, k, ne;

        switch (mode[i])
        {
        case 's': append_row(Le, &rl, J, cn, -1); break;        /* a_n >= 0 */
        case 'a': append_row(Lt, &rt, J, cn, 1); break;         /* a_n < 0 */
        case 'u': break;
        case 'l': append_row(Eq, &re, J, cn, 1);
                  append_row(Lt, &rt, J, ct, -1); break;        /* a_t > 0 */
        case 'r': append_row(Eq, &re, J, cn, 1);
                  append_row(Lt, &rt, J, ct, 1); break;         /* a_t < 0 */
        case 'n': append_row(Eq, &re, J, cn, 1);
                  append_row(Eq, &re, J, ct, 1); break;
        case 'm': append_row(Eq, &re, J, cn, 1); break;
        default: break;
        }
        /* D_x: friction-cone edges (c_n, c_t), mapped by -J.  */
        ne = wc_friction_edges(e, P->fixels + i, mode[i]);
        for (k = 0; k < ne; k++, q++)
            for (j = 0; j < 3; j++)
            {
                fmpq * x = fmpq_mat_entry(Q, q, j);

                fmpq_mul(x, e + 2 * k, fmpq_mat_entry(J, j, cn));
                fmpq_addmul(x, e + 2 * k + 1, fmpq_mat_entry(J, j, ct));
                fmpq_neg(x, x);
            }
    }
    _wc_fmpq_mat_keep_rows(Q, q);
    _wc_fmpq_mat_keep_rows(Eq, re);
    _wc_fmpq_mat_keep_rows(Le, rl);
    _wc_fmpq_mat_keep_rows(Lt, rt);

    status = wc_cone_set_hrep(V, Eq, Le, Lt, err);
    if (status != WC_OK)
        goto cleanup;
    status = wc_cone_image_sum(W, M, V, Q, err);
    if (status != WC_OK)
        goto cleanup;

    if (trace != NULL)
    {
        wc_trace_add(trace, "J", J, "wrench matrix, columns n_1..n_%ld, t_1..t_%ld",
                     (long) n, (long) n);
        wc_trace_add(trace, "M", M, "inertia matrix diag(m, m, I)");
        wc_trace_add(trace, "V_x equalities", Eq,
                     "rows h: h . nudot = 0 (a_in = 0, a_it = 0 rows of J^T)");
        wc_trace_add(trace, "V_x inequalities", Le, "rows h: h . nudot <= 0");
        wc_trace_add(trace, "V_x strict", Lt, "rows h: h . nudot < 0");
        fmpq_mat_init(Vr, fmpz_mat_nrows(V->rays), 3);
        fmpq_mat_set_fmpz_mat(Vr, V->rays);
        wc_trace_add(trace, "cl V_x rays", Vr, V->empty ? "V_x is empty"
                     : "%ld of %ld faces of cl V_x belong to V_x",
                     (long) (V->nfaces - wc_cone_excluded_faces(V)),
                     (long) V->nfaces);
        fmpq_mat_clear(Vr);
        fmpq_mat_init(Vr, fmpz_mat_nrows(V->lines), 3);
        fmpq_mat_set_fmpz_mat(Vr, V->lines);
        wc_trace_add(trace, "cl V_x lines", Vr, NULL);
        fmpq_mat_clear(Vr);
        wc_trace_add(trace, "-J D_x", Q, "rows: friction-cone edges as wrenches; W = M V_x + pos(-J D_x)");
    }

cleanup:
    if (status != WC_OK)
        wc_cone_set_empty(W);
    fmpq_mat_clear(J);
    fmpq_mat_clear(M);
    fmpq_mat_clear(Eq);
    fmpq_mat_clear(Le);
    fmpq_mat_clear(Lt);
    fmpq_mat_clear(Q);
    for (j = 0; j < 4; j++)
        fmpq_clear(e + j);
    wc_cone_clear(V);
    return status;
}
