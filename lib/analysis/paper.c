/* paper.c -- the paper's route to W(x) (Section 5), exactly.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   y = (a_1n..a_nn, a_1t..a_nt, c_1n..c_nn, c_1t..c_nt), 0-based indices
   i, n+i, 2n+i, 3n+i.  K = E C N R S V, P = E B, z >= 0 with some
   coordinates strict; K^F is the exact face-normal form of pos(K) and
   F = K^F P.  Theorem 1 with k = eps e_strict gives
   W = union over eps > 0 of { g : F g <= eps K^F K e_strict }; every entry
   of b = K^F K e_strict is <= 0, so W = { F_i g <= 0 where b_i = 0,
   F_i g < 0 where b_i < 0 }: the paper's "k -> 0", decided exactly.

   Slips of the paper corrected here (wrenchcone(1), MODES): S's signs come from
   Table 2 (l: c_t = -mu_k c_n, r: c_t = +mu_k c_n); R divides by mu_s, so
   a rolling or maintained fixel with mu_s = 0 gets c_t = 0 instead.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/mode.h"
#include "model/model.h"
#include "model/table2.h"
#include "exact/cddbridge.h"
#include "exact/lp.h"
#include "analysis/wrench.h"

static void
y_label(char * buf, size_t len, slong k, slong n)
{
    static const char * const kind[4] = { "a", "a", "c", "c" };
    static const char * const dir[4] = { "n", "t", "n", "t" };

    snprintf(buf, len, "%s%ld%s", kind[k / n], (long) (k % n + 1), dir[k / n]);
}

/* Append s to the growing string *buf.  */
static void
cat(char ** buf, size_t * len, const char * s)
{
    size_t l = strlen(s);
    char * p = realloc(*buf, *len + l + 1);

    if (p == NULL)
        return;
    memcpy(p + *len, s, l + 1);
    *buf = p;
    *len += l;
}

void
_wc_table2_flags(int * flag, const wc_problem_t P, const char * mode)
{
    slong n = P->n, i;

    for (i = 0; i < n; i++)
    {
        slong an = i, at = n + i, cn = 2 * n + i, ct = 3 * n + i;
        int roll_ok = !fmpq_is_zero(P->fixels[i].mu_s);

        switch (mode[i])
        {
        case 's': flag[at] = Y_FREE; flag[cn] = flag[ct] = Y_ZERO; break;
        case 'a': flag[an] = Y_NEG | Y_STRICT; flag[at] = Y_FREE;
                  flag[cn] = flag[ct] = Y_ZERO; break;
        case 'u': flag[an] = flag[at] = Y_FREE;
                  flag[cn] = flag[ct] = Y_ZERO; break;
        case 'l': flag[an] = Y_ZERO; flag[at] = Y_STRICT;
                  flag[ct] = Y_SLIDE; break;
        case 'r': flag[an] = Y_ZERO; flag[at] = Y_NEG | Y_STRICT;
                  flag[ct] = Y_SLIDE; break;
        case 'n': flag[an] = flag[at] = Y_ZERO;
                  flag[ct] = roll_ok ? Y_ROLL : Y_ZERO; break;
        case 'm': flag[an] = Y_ZERO; flag[at] = Y_FREE;
                  flag[ct] = roll_ok ? Y_ROLL : Y_ZERO; break;
        default: break;
        }
    }
}

/* The matrices of the route, named as in the paper; K has rows = 2n - |free|
   rows and nz columns, zcol[j] the entry of y behind column j.  */
typedef struct
{
    slong n, rows, nz;
    int * flag;
    slong * zcol;
    fmpq_mat_t J, M, A, B, C, E, N, R, S, V, K, Pm, KF, F, b;
}
route;

static void
route_init(route * Q, const wc_problem_t P)
{
    slong n = P->n;

    Q->n = n;
    Q->rows = Q->nz = 0;
    Q->flag = flint_calloc(4 * n + 1, sizeof(int));
    Q->zcol = flint_malloc(sizeof(slong) * (4 * n + 1));
    fmpq_mat_init(Q->J, 3, 2 * n);
    fmpq_mat_init(Q->M, 3, 3);
    fmpq_mat_init(Q->A, 2 * n, 2 * n);
    fmpq_mat_init(Q->B, 2 * n, 3);
    fmpq_mat_init(Q->C, 2 * n, 4 * n);
    fmpq_mat_init(Q->N, 4 * n, 4 * n);
    fmpq_mat_init(Q->R, 4 * n, 4 * n);
    fmpq_mat_init(Q->S, 4 * n, 4 * n);
    /* resized once their sizes are known */
    fmpq_mat_init(Q->E, 0, 2 * n);
    fmpq_mat_init(Q->V, 4 * n, 0);
    fmpq_mat_init(Q->K, 0, 0);
    fmpq_mat_init(Q->Pm, 0, 3);
    fmpq_mat_init(Q->KF, 0, 0);
    fmpq_mat_init(Q->F, 0, 3);
    fmpq_mat_init(Q->b, 0, 1);
}

static void
route_clear(route * Q)
{
    flint_free(Q->flag);
    flint_free(Q->zcol);
    fmpq_mat_clear(Q->J);
    fmpq_mat_clear(Q->M);
    fmpq_mat_clear(Q->A);
    fmpq_mat_clear(Q->B);
    fmpq_mat_clear(Q->C);
    fmpq_mat_clear(Q->E);
    fmpq_mat_clear(Q->N);
    fmpq_mat_clear(Q->R);
    fmpq_mat_clear(Q->S);
    fmpq_mat_clear(Q->V);
    fmpq_mat_clear(Q->K);
    fmpq_mat_clear(Q->Pm);
    fmpq_mat_clear(Q->KF);
    fmpq_mat_clear(Q->F);
    fmpq_mat_clear(Q->b);
}

/* E, N, R, S, V from the Table 2 flags of mode.  */
static void
route_selectors(route * Q, const wc_problem_t P, const char * mode)
{
    slong n = Q->n, N2 = 2 * n, N4 = 4 * n, i, j, k, r;

    /* E: the rows of I_2n of constrained accelerations.  */
    for (k = 0, Q->rows = N2; k < N2; k++)
        Q->rows -= (Q->flag[k] & Y_FREE) != 0;
    fmpq_mat_clear(Q->E);
    fmpq_mat_init(Q->E, Q->rows, N2);
    for (k = 0, r = 0; k < N2; k++)
        if (!(Q->flag[k] & Y_FREE))
            fmpq_one(fmpq_mat_entry(Q->E, r++, k));

    /* N: -1 on entries constrained negative.  */
    fmpq_mat_one(Q->N);
    for (k = 0; k < N4; k++)
        if (Q->flag[k] & Y_NEG)
            fmpq_set_si(fmpq_mat_entry(Q->N, k, k), -1, 1);

    /* R: (c_n, c_t) = (w_n + w_t, mu_s (w_t - w_n)), so
       w_n = (mu_s c_n - c_t) / 2 mu_s and w_t = (mu_s c_n + c_t) / 2 mu_s.
       S: c_t = -+ mu_k c_n for l and r (Table 2).  */
    fmpq_mat_one(Q->R);
    fmpq_mat_one(Q->S);
    for (i = 0; i < n; i++)
    {
        slong cn = 2 * n + i, ct = 3 * n + i;

        if (Q->flag[ct] & Y_ROLL)
        {
            fmpq_set(fmpq_mat_entry(Q->R, ct, ct), P->fixels[i].mu_s);
            fmpq_one(fmpq_mat_entry(Q->R, cn, ct));
            fmpq_neg(fmpq_mat_entry(Q->R, ct, cn), P->fixels[i].mu_s);
        }
        if (Q->flag[ct] & Y_SLIDE)
        {
            if (mode[i] == 'l')
                fmpq_neg(fmpq_mat_entry(Q->S, ct, cn), P->fixels[i].mu_k);
            else
                fmpq_set(fmpq_mat_entry(Q->S, ct, cn), P->fixels[i].mu_k);
        }
    }

    /* V: drop zero, sliding-eliminated and unconstrained entries.  */
    for (k = 0, Q->nz = 0; k < N4; k++)
        if (!(Q->flag[k] & (Y_ZERO | Y_SLIDE | Y_FREE)))
            Q->zcol[Q->nz++] = k;
    fmpq_mat_clear(Q->V);
    fmpq_mat_init(Q->V, N4, Q->nz);
    for (j = 0; j < Q->nz; j++)
        fmpq_one(fmpq_mat_entry(Q->V, Q->zcol[j], j));
}

/* The model's matrices, the selectors, K = E C N R S V and P = E B.  */
static void
route_system(route * Q, const wc_problem_t P, const char * mode)
{
    slong N4 = 4 * Q->n;
    fmpq_mat_t T1, T2;

    wc_model_J(Q->J, P);
    wc_model_M(Q->M, P);
    wc_model_A(Q->A, P);
    wc_model_B(Q->B, P);
    wc_model_C(Q->C, P);
    _wc_table2_flags(Q->flag, P, mode);
    route_selectors(Q, P, mode);
    fmpq_mat_init(T1, Q->rows, N4);
    fmpq_mat_init(T2, Q->rows, N4);
    fmpq_mat_mul(T1, Q->E, Q->C);
    fmpq_mat_mul(T2, T1, Q->N);
    fmpq_mat_mul(T1, T2, Q->R);
    fmpq_mat_mul(T2, T1, Q->S);
    fmpq_mat_clear(Q->K);
    fmpq_mat_init(Q->K, Q->rows, Q->nz);
    fmpq_mat_mul(Q->K, T2, Q->V);
    fmpq_mat_clear(Q->Pm);
    fmpq_mat_init(Q->Pm, Q->rows, 3);
    fmpq_mat_mul(Q->Pm, Q->E, Q->B);
    fmpq_mat_clear(T1);
    fmpq_mat_clear(T2);
}

/* K^F: the facets of pos(K) in R^rows, its equalities as pairs of
   opposite rows; F = K^F P and b = K^F K e_strict.  */
static int
route_face_normal(route * Q, wc_error_t err)
{
    slong c = Q->rows, h, q, i, j, nz = Q->nz;
    fmpq_mat_t Kt, KFe, KFh, es, Ke;
    int status = WC_OK;

    fmpq_mat_init(Kt, nz, c);
    fmpq_mat_transpose(Kt, Q->K);
    fmpq_mat_init(KFe, 0, c);
    fmpq_mat_init(KFh, 0, c);
    if (c > 0)
        status = _wc_cdd_v_to_h(KFe, KFh, c, Kt, NULL, err);
    if (status == WC_OK)
    {
        h = fmpq_mat_nrows(KFh);
        q = fmpq_mat_nrows(KFe);
        fmpq_mat_clear(Q->KF);
        fmpq_mat_init(Q->KF, h + 2 * q, c);
        for (i = 0; i < h; i++)
            for (j = 0; j < c; j++)
                fmpq_set(fmpq_mat_entry(Q->KF, i, j),
                         fmpq_mat_entry(KFh, i, j));
        for (i = 0; i < q; i++)
            for (j = 0; j < c; j++)
            {
                fmpq_set(fmpq_mat_entry(Q->KF, h + 2 * i, j),
                         fmpq_mat_entry(KFe, i, j));
                fmpq_neg(fmpq_mat_entry(Q->KF, h + 2 * i + 1, j),
                         fmpq_mat_entry(KFe, i, j));
            }
        fmpq_mat_clear(Q->F);
        fmpq_mat_init(Q->F, h + 2 * q, 3);
        if (h + 2 * q > 0 && c > 0)
            fmpq_mat_mul(Q->F, Q->KF, Q->Pm);

        /* b decides which rows of F are strict.  */
        fmpq_mat_clear(Q->b);
        fmpq_mat_init(Q->b, h + 2 * q, 1);
        fmpq_mat_init(es, nz, 1);
        fmpq_mat_init(Ke, c, 1);
        for (j = 0; j < nz; j++)
            if (Q->flag[Q->zcol[j]] & Y_STRICT)
                fmpq_one(fmpq_mat_entry(es, j, 0));
        if (nz > 0 && c > 0)
        {
            fmpq_mat_mul(Ke, Q->K, es);
            if (h + 2 * q > 0)
                fmpq_mat_mul(Q->b, Q->KF, Ke);
        }
        fmpq_mat_clear(es);
        fmpq_mat_clear(Ke);
    }
    fmpq_mat_clear(Kt);
    fmpq_mat_clear(KFe);
    fmpq_mat_clear(KFh);
    return status;
}

/* W := { F_i g <= 0 where b_i = 0, F_i g < 0 where b_i < 0 }.  */
static int
route_cone(wc_cone_t W, const route * Q, wc_error_t err)
{
    slong m = fmpq_mat_nrows(Q->F), ns = 0, nl = 0, i;
    fmpq_mat_t Fle, Flt;
    int status;

    for (i = 0; i < m; i++)
        ns += fmpq_sgn(fmpq_mat_entry(Q->b, i, 0)) < 0;
    fmpq_mat_init(Fle, m - ns, 3);
    fmpq_mat_init(Flt, ns, 3);
    for (i = 0, ns = 0; i < m; i++)
    {
        int strict = fmpq_sgn(fmpq_mat_entry(Q->b, i, 0)) < 0;
        fmpq_mat_struct * T = strict ? Flt : Fle;
        slong t = strict ? ns++ : nl++;

        _wc_qvec_set(T->rows[t], Q->F->rows[i], 3);
    }
    status = _wc_cone_set_hrep_kernel(W, NULL, Fle, Flt, 1, err);
    fmpq_mat_clear(Fle);
    fmpq_mat_clear(Flt);
    return status;
}

/* *ylab := "y = (a1n, ...)", *cons := Table 2's constraints on y.  */
static void
trace_y(char ** ylab, char ** cons, const route * Q, const char * mode)
{
    slong n = Q->n, N2 = 2 * n, k;
    size_t ylen = 0, clen = 0;
    char lab[64], cn[64], buf[512];
    const int * flag = Q->flag;

    for (k = 0; k < 4 * n; k++)
    {
        y_label(lab, sizeof lab, k, n);
        cat(ylab, &ylen, k == 0 ? "y = (" : ", ");
        cat(ylab, &ylen, lab);
        if (k >= N2 && k < 3 * n)
            continue;       /* c_n constraints are stated with c_t */
        if (k < N2)
        {
            const char * rel = (flag[k] & Y_FREE) ? " free"
                : (flag[k] & Y_ZERO) ? " = 0"
                : (flag[k] & Y_NEG) ? " < 0"
                : (flag[k] & Y_STRICT) ? " > 0" : " >= 0";

            snprintf(buf, sizeof buf, "%s%s%s", clen ? ", " : "", lab, rel);
        }
        else
        {
            y_label(cn, sizeof cn, k - n, n);
            if (flag[k] & Y_ROLL)
                snprintf(buf, sizeof buf, ", %s >= 0, |%s| <= mu_s %s",
                         cn, lab, cn);
            else if (flag[k] & Y_SLIDE)
                snprintf(buf, sizeof buf, ", %s >= 0, %s = %smu_k %s", cn,
                         lab, mode[k - 3 * n] == 'l' ? "-" : "", cn);
            else if (flag[k - n] & Y_ZERO)
                snprintf(buf, sizeof buf, ", %s = %s = 0", cn, lab);
            else
                snprintf(buf, sizeof buf, ", %s >= 0, %s = 0", cn, lab);
        }
        cat(cons, &clen, buf);
    }
    cat(ylab, &ylen, ")");
}

/* *zlab := "z = (...)": the entries of y that K's columns stand for.  */
static void
trace_z(char ** zlab, const route * Q)
{
    slong n = Q->n, N2 = 2 * n, j;
    size_t zlen = 0;
    char lab[64], cn[64], ct[64], buf[512];
    const int * flag = Q->flag;

    for (j = 0; j < Q->nz; j++)
    {
        slong y = Q->zcol[j];

        y_label(lab, sizeof lab, y, n);
        cat(zlab, &zlen, j == 0 ? "z = (" : ", ");
        if (flag[y] & Y_ROLL || (y >= N2 && y < 3 * n
                                  && (flag[y + n] & Y_ROLL)))
        {
            slong f = (y - N2) % n;

            y_label(cn, sizeof cn, N2 + f, n);
            y_label(ct, sizeof ct, 3 * n + f, n);
            snprintf(buf, sizeof buf, "(mu_s %s %s %s)/2mu_s", cn,
                     y < 3 * n ? "-" : "+", ct);
            cat(zlab, &zlen, buf);
        }
        else
        {
            if (flag[y] & Y_NEG)
                cat(zlab, &zlen, "-");
            cat(zlab, &zlen, lab);
        }
        if (flag[y] & Y_STRICT)
            cat(zlab, &zlen, " (strict)");
    }
    cat(zlab, &zlen, Q->nz == 0 ? "z = ()" : ")");
}

static void
route_trace(wc_trace_t trace, const route * Q, const char * mode)
{
    char * zlab = NULL, * ylab = NULL, * cons = NULL;
    slong n = Q->n;

    trace_y(&ylab, &cons, Q, mode);
    trace_z(&zlab, Q);
    wc_trace_add(trace, "J", Q->J, "wrench matrix, columns n_1..n_%ld, t_1..t_%ld",
                 (long) n, (long) n);
    wc_trace_add(trace, "M", Q->M, "inertia matrix diag(m, m, I)");
    wc_trace_add(trace, "A", Q->A, "A = J^T M^-1 J");
    wc_trace_add(trace, "B", Q->B, "B = J^T M^-1");
    wc_trace_add(trace, "C", Q->C, "C = [I -A], C y = B g (eq. 7); %s",
                 ylab ? ylab : "");
    wc_trace_add(trace, "E", Q->E, "Table 2 for mode %s: %s", mode,
                 cons ? cons : "");
    wc_trace_add(trace, "N", Q->N, NULL);
    wc_trace_add(trace, "R", Q->R, NULL);
    wc_trace_add(trace, "S", Q->S, "signs from Table 2: l c_t = -mu_k c_n, r c_t = +mu_k c_n");
    wc_trace_add(trace, "V", Q->V, "%s", zlab ? zlab : "");
    wc_trace_add(trace, "K", Q->K, "K = E C N R S V; K z = P g, z >= 0");
    wc_trace_add(trace, "P", Q->Pm, "P = E B");
    wc_trace_add(trace, "K^F", Q->KF, "pos(K) = { x : K^F x <= 0 }");
    wc_trace_add(trace, "K^F K e_strict", Q->b, "rows < 0 make the rows of F strict");
    wc_trace_add(trace, "F", Q->F, "F = K^F P; W = { g : F g <= 0, strict where K^F K e_strict < 0 }");
    free(zlab);
    free(ylab);
    free(cons);
}

int
wc_wrench_cone_paper(wc_cone_t W, wc_trace_t trace, const wc_problem_t P,
                     const char * mode, wc_error_t err)
{
    route Q;
    int status;

    if ((status = wc_mode_check(P, mode, WC_TABLE_CONE, err)) != WC_OK)
    {
        wc_cone_set_empty(W);
        return status;
    }
    route_init(&Q, P);
    route_system(&Q, P, mode);
    status = route_face_normal(&Q, err);
    if (status == WC_OK)
        status = route_cone(W, &Q, err);
    if (status == WC_OK && trace != NULL)
        route_trace(trace, &Q, mode);
    if (status != WC_OK)
        wc_cone_set_empty(W);
    route_clear(&Q);
    return status;
}
