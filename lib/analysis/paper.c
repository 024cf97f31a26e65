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

   Slips of the paper corrected here (SPEC 2.2): S's signs come from
   Table 2 (l: c_t = -mu_k c_n, r: c_t = +mu_k c_n); R divides by mu_s, so
   a rolling or maintained fixel with mu_s = 0 gets c_t = 0 instead.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "exact/cddbridge.h"
#include "model/table2.h"


static void
y_label(char * buf, size_t len, slong k, slong n)
{
    static const char * kind[4] = { "a", "a", "c", "c" };
    static const char * dir[4] = { "n", "t", "n", "t" };

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

int
wc_wrench_cone_paper(wc_cone_t W, wc_trace_t trace, const wc_problem_t P,
                     const char * mode, wc_error_t err)
{
    slong n = P->n, N2 = 2 * n, N4 = 4 * n, i, j, k, r, nz, ne;
    int * flag;
    slong * zcol;
    fmpq_mat_t J, M, A, B, C, E, N, R, S, V, T1, T2, K, Pm, Kt, KFe, KFh,
        KF, F, Fle, Flt, b;
    char * zlab = NULL, * ylab = NULL, * cons = NULL;
    size_t zlen = 0, ylen = 0, clen = 0;
    char lab[64], buf[512];
    int status = WC_OK;

    if ((status = wc_mode_check(P, mode, WC_TABLE_CONE, err)) != WC_OK)
    {
        wc_cone_set_empty(W);
        return status;
    }
    flag = flint_calloc(N4 + 1, sizeof(int));
    zcol = flint_malloc(sizeof(slong) * (N4 + 1));
    /* Every matrix is initialised here, so that cleanup can clear all.  */
    fmpq_mat_init(KF, 0, 0);
    fmpq_mat_init(F, 0, 3);
    fmpq_mat_init(Fle, 0, 3);
    fmpq_mat_init(Flt, 0, 3);
    fmpq_mat_init(b, 0, 1);
    fmpq_mat_init(J, 3, N2);
    fmpq_mat_init(M, 3, 3);
    fmpq_mat_init(A, N2, N2);
    fmpq_mat_init(B, N2, 3);
    fmpq_mat_init(C, N2, N4);
    wc_model_J(J, P);
    wc_model_M(M, P);
    wc_model_A(A, P);
    wc_model_B(B, P);
    wc_model_C(C, P);

    _wc_table2_flags(flag, P, mode);

    /* E: the rows of I_2n of constrained accelerations.  */
    for (k = 0, ne = 0; k < N2; k++)
        ne += (flag[k] & Y_FREE) != 0;
    fmpq_mat_init(E, N2 - ne, N2);
    for (k = 0, r = 0; k < N2; k++)
        if (!(flag[k] & Y_FREE))
            fmpq_one(fmpq_mat_entry(E, r++, k));

    /* N: -1 on entries constrained negative.  */
    fmpq_mat_init(N, N4, N4);
    fmpq_mat_one(N);
    for (k = 0; k < N4; k++)
        if (flag[k] & Y_NEG)
            fmpq_set_si(fmpq_mat_entry(N, k, k), -1, 1);

    /* R: (c_n, c_t) = (w_n + w_t, mu_s (w_t - w_n)), so
       w_n = (mu_s c_n - c_t) / 2 mu_s and w_t = (mu_s c_n + c_t) / 2 mu_s.  */
    fmpq_mat_init(R, N4, N4);
    fmpq_mat_one(R);
    /* S: c_t = -+ mu_k c_n for l and r (Table 2).  */
    fmpq_mat_init(S, N4, N4);
    fmpq_mat_one(S);
    for (i = 0; i < n; i++)
    {
        slong cn = 2 * n + i, ct = 3 * n + i;

        if (flag[ct] & Y_ROLL)
        {
            fmpq_set(fmpq_mat_entry(R, ct, ct), P->fixels[i].mu_s);
            fmpq_one(fmpq_mat_entry(R, cn, ct));
            fmpq_neg(fmpq_mat_entry(R, ct, cn), P->fixels[i].mu_s);
        }
        if (flag[ct] & Y_SLIDE)
        {
            if (mode[i] == 'l')
                fmpq_neg(fmpq_mat_entry(S, ct, cn), P->fixels[i].mu_k);
            else
                fmpq_set(fmpq_mat_entry(S, ct, cn), P->fixels[i].mu_k);
        }
    }

    /* V: drop zero, sliding-eliminated and unconstrained entries.  */
    for (k = 0, nz = 0; k < N4; k++)
        if (!(flag[k] & (Y_ZERO | Y_SLIDE | Y_FREE)))
            zcol[nz++] = k;
    fmpq_mat_init(V, N4, nz);
    for (j = 0; j < nz; j++)
        fmpq_one(fmpq_mat_entry(V, zcol[j], j));

    /* K = E C N R S V, P = E B.  */
    fmpq_mat_init(T1, N2 - ne, N4);
    fmpq_mat_init(T2, N2 - ne, N4);
    fmpq_mat_mul(T1, E, C);
    fmpq_mat_mul(T2, T1, N);
    fmpq_mat_mul(T1, T2, R);
    fmpq_mat_mul(T2, T1, S);
    fmpq_mat_init(K, N2 - ne, nz);
    fmpq_mat_mul(K, T2, V);
    fmpq_mat_init(Pm, N2 - ne, 3);
    fmpq_mat_mul(Pm, E, B);

    /* K^F: facets of pos(K) in R^(2n - |E|), equalities as pairs.  */
    fmpq_mat_init(Kt, nz, N2 - ne);
    fmpq_mat_transpose(Kt, K);
    fmpq_mat_init(KFe, 0, N2 - ne);
    fmpq_mat_init(KFh, 0, N2 - ne);
    if (N2 - ne > 0)
    {
        status = _wc_cdd_v_to_h(KFe, KFh, N2 - ne, Kt, NULL, err);
        if (status != WC_OK)
            goto cleanup;
    }
    {
        slong h = fmpq_mat_nrows(KFh), q = fmpq_mat_nrows(KFe), c = N2 - ne;

        fmpq_mat_clear(KF);
        fmpq_mat_init(KF, h + 2 * q, c);
        for (i = 0; i < h; i++)
            for (j = 0; j < c; j++)
                fmpq_set(fmpq_mat_entry(KF, i, j), fmpq_mat_entry(KFh, i, j));
        for (i = 0; i < q; i++)
            for (j = 0; j < c; j++)
            {
                fmpq_set(fmpq_mat_entry(KF, h + 2 * i, j),
                         fmpq_mat_entry(KFe, i, j));
                fmpq_neg(fmpq_mat_entry(KF, h + 2 * i + 1, j),
                         fmpq_mat_entry(KFe, i, j));
            }
    }
    fmpq_mat_clear(F);
    fmpq_mat_init(F, fmpq_mat_nrows(KF), 3);
    if (fmpq_mat_nrows(KF) > 0 && N2 - ne > 0)
        fmpq_mat_mul(F, KF, Pm);

    /* b = K^F K e_strict decides which rows of F are strict.  */
    fmpq_mat_clear(b);
    fmpq_mat_init(b, fmpq_mat_nrows(KF), 1);
    {
        fmpq_mat_t es, Ke;

        fmpq_mat_init(es, nz, 1);
        fmpq_mat_init(Ke, N2 - ne, 1);
        for (j = 0; j < nz; j++)
            if (flag[zcol[j]] & Y_STRICT)
                fmpq_one(fmpq_mat_entry(es, j, 0));
        if (nz > 0 && N2 - ne > 0)
        {
            fmpq_mat_mul(Ke, K, es);
            if (fmpq_mat_nrows(KF) > 0)
                fmpq_mat_mul(b, KF, Ke);
        }
        fmpq_mat_clear(es);
        fmpq_mat_clear(Ke);
    }
    {
        slong m = fmpq_mat_nrows(F), ns = 0, nl = 0;

        for (i = 0; i < m; i++)
            ns += fmpq_sgn(fmpq_mat_entry(b, i, 0)) < 0;
        fmpq_mat_clear(Fle);
        fmpq_mat_clear(Flt);
        fmpq_mat_init(Fle, m - ns, 3);
        fmpq_mat_init(Flt, ns, 3);
        for (i = 0, ns = 0; i < m; i++)
        {
            int strict = fmpq_sgn(fmpq_mat_entry(b, i, 0)) < 0;
            fmpq_mat_struct * T = strict ? Flt : Fle;
            slong t = strict ? ns++ : nl++;

            for (j = 0; j < 3; j++)
                fmpq_set(fmpq_mat_entry(T, t, j), fmpq_mat_entry(F, i, j));
        }
    }
    status = _wc_cone_set_hrep_kernel(W, NULL, Fle, Flt, 1, err);
    if (status != WC_OK)
        goto cleanup;

    if (trace != NULL)
    {
        for (k = 0; k < N4; k++)
        {
            y_label(lab, sizeof lab, k, n);
            cat(&ylab, &ylen, k == 0 ? "y = (" : ", ");
            cat(&ylab, &ylen, lab);
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
                char cn[64];

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
            cat(&cons, &clen, buf);
        }
        cat(&ylab, &ylen, ")");
        for (j = 0; j < nz; j++)
        {
            slong y = zcol[j];

            y_label(lab, sizeof lab, y, n);
            cat(&zlab, &zlen, j == 0 ? "z = (" : ", ");
            if (flag[y] & Y_ROLL || (y >= N2 && y < 3 * n
                                      && (flag[y + n] & Y_ROLL)))
            {
                char cn[64], ct[64];
                slong f = (y - N2) % n;

                y_label(cn, sizeof cn, N2 + f, n);
                y_label(ct, sizeof ct, 3 * n + f, n);
                snprintf(buf, sizeof buf, "(mu_s %s %s %s)/2mu_s", cn,
                         y < 3 * n ? "-" : "+", ct);
                cat(&zlab, &zlen, buf);
            }
            else
            {
                if (flag[y] & Y_NEG)
                    cat(&zlab, &zlen, "-");
                cat(&zlab, &zlen, lab);
            }
            if (flag[y] & Y_STRICT)
                cat(&zlab, &zlen, " (strict)");
        }
        cat(&zlab, &zlen, nz == 0 ? "z = ()" : ")");

        wc_trace_add(trace, "J", J, "wrench matrix, columns n_1..n_%ld, t_1..t_%ld",
                     (long) n, (long) n);
        wc_trace_add(trace, "M", M, "inertia matrix diag(m, m, I)");
        wc_trace_add(trace, "A", A, "A = J^T M^-1 J");
        wc_trace_add(trace, "B", B, "B = J^T M^-1");
        wc_trace_add(trace, "C", C, "C = [I -A], C y = B g (eq. 7); %s",
                     ylab ? ylab : "");
        wc_trace_add(trace, "E", E, "Table 2 for mode %s: %s", mode,
                     cons ? cons : "");
        wc_trace_add(trace, "N", N, NULL);
        wc_trace_add(trace, "R", R, NULL);
        wc_trace_add(trace, "S", S, "signs from Table 2: l c_t = -mu_k c_n, r c_t = +mu_k c_n");
        wc_trace_add(trace, "V", V, "%s", zlab ? zlab : "");
        wc_trace_add(trace, "K", K, "K = E C N R S V; K z = P g, z >= 0");
        wc_trace_add(trace, "P", Pm, "P = E B");
        wc_trace_add(trace, "K^F", KF, "pos(K) = { x : K^F x <= 0 }");
        wc_trace_add(trace, "K^F K e_strict", b, "rows < 0 make the rows of F strict");
        wc_trace_add(trace, "F", F, "F = K^F P; W = { g : F g <= 0, strict where K^F K e_strict < 0 }");
    }

cleanup:
    if (status != WC_OK)
        wc_cone_set_empty(W);
    flint_free(flag);
    flint_free(zcol);
    free(zlab);
    free(ylab);
    free(cons);
    fmpq_mat_clear(J);
    fmpq_mat_clear(M);
    fmpq_mat_clear(A);
    fmpq_mat_clear(B);
    fmpq_mat_clear(C);
    fmpq_mat_clear(E);
    fmpq_mat_clear(N);
    fmpq_mat_clear(R);
    fmpq_mat_clear(S);
    fmpq_mat_clear(V);
    fmpq_mat_clear(T1);
    fmpq_mat_clear(T2);
    fmpq_mat_clear(K);
    fmpq_mat_clear(Pm);
    fmpq_mat_clear(Kt);
    fmpq_mat_clear(KFe);
    fmpq_mat_clear(KFh);
    fmpq_mat_clear(KF);
    fmpq_mat_clear(F);
    fmpq_mat_clear(Fle);
    fmpq_mat_clear(Flt);
    fmpq_mat_clear(b);
    return status;
}
