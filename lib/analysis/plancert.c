/* plancert.c -- the proof that a plan's goal set is exact.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   See plancert.h.  The system of a string x for the wrenches
   sum alpha_i G_i is over z = (nudot, lambda, alpha), with the edges w_j
   of the fixels where x has m, in fixel order, each the two edges
   J_in -+ mu J_it of the plan model's cone (mu = max(mu_s, mu_k)):

     M nudot - sum_j lambda_j w_j - sum_i alpha_i G_i = 0   (three rows)
     J_in . nudot >= 0 where x has s, = 0 where it has m    (fixel order)
     lambda_j >= 0,  alpha_i > 0

   exactly as wrenchcone-certificate(5) gives it for the checker.  */

#include <config.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "exact/lp.h"
#include "exact/vec3.h"
#include "analysis/plancert.h"

void
_wc_plan_model_mu(fmpq * mu, const wc_problem_t P)
{
    slong i;

    for (i = 0; i < P->n; i++)
        fmpq_set(mu + i, fmpq_cmp(P->fixels[i].mu_s, P->fixels[i].mu_k)
                 >= 0 ? P->fixels[i].mu_s : P->fixels[i].mu_k);
}

int
_wc_plancert_init(_wc_plancert * C, const wc_problem_t P, const wc_plan_t R,
                  wc_error_t err)
{
    const wc_cone_struct ** Q;
    slong i, nq = R->goal->npieces + R->T->nneeded;

    (void) err;
    C->R = R;
    _wc_stab_model_init(&C->m, P);
    C->mu = _fmpq_vec_init(P->n + 1);
    _wc_plan_model_mu(C->mu, P);
    Q = flint_malloc(sizeof(wc_cone_struct *) * (nq + 1));
    for (i = 0; i < nq; i++)
        Q[i] = i < R->goal->npieces ? R->goal->pieces + i
            : R->cones + (i - R->goal->npieces);
    _wc_setcert_init(&C->base, Q, nq);
    flint_free(Q);
    return WC_OK;
}

void
_wc_plancert_clear(_wc_plancert * C)
{
    _fmpq_vec_clear(C->mu, C->m.n + 1);
    _wc_stab_model_clear(&C->m);
    _wc_setcert_clear(&C->base);
}

static int
bug(wc_error_t err, const char * what)
{
    return _wc_setcert_bug(err, "goal set", what);
}

int
_wc_plan_string_solve(fmpq * nudot, fmpq * c, fmpq ** mult, slong * nmult,
                      const _wc_stab_model * m, const fmpq * mu,
                      const char * x, const fmpq * G, slong ng,
                      wc_error_t err)
{
    slong n = m->n, e = 0, i, j, k, r, nv;
    fmpq_mat_t A;
    wc_relation * rel;
    fmpq * z, * y = NULL, ed[2], w[3];
    int res;

    for (i = 0; i < n; i++)
        e += x[i] == 'm' ? 2 : 0;
    nv = 3 + e + ng;
    fmpq_mat_init(A, 3 + n + e + ng, nv);
    rel = flint_malloc(sizeof(wc_relation) * (3 + n + e + ng));
    z = _fmpq_vec_init(nv);
    for (k = 0; k < 3; k++)
    {
        fmpq_init(w + k);
        fmpq_set(fmpq_mat_entry(A, k, k), m->M + k);
        for (i = 0; i < ng; i++)
            fmpq_neg(fmpq_mat_entry(A, k, 3 + e + i), G + 3 * i + k);
        rel[k] = WC_REL_EQ;
    }
    fmpq_init(ed + 0);
    fmpq_init(ed + 1);
    fmpq_one(ed + 0);
    for (i = 0, j = 0; i < n; i++)
        for (r = 0; x[i] == 'm' && r < 2; r++, j++)
        {
            fmpq_set(ed + 1, mu + i);
            if (r == 0)
                fmpq_neg(ed + 1, ed + 1);
            _wc_stab_edge_wrench(w, m, i, ed);
            for (k = 0; k < 3; k++)
                fmpq_neg(fmpq_mat_entry(A, k, 3 + j), w + k);
        }
    r = 3;
    for (i = 0; i < n; i++)
        if (x[i] == 's' || x[i] == 'm')
        {
            for (k = 0; k < 3; k++)
                fmpq_set(fmpq_mat_entry(A, r, k), m->Jn + 3 * i + k);
            rel[r++] = x[i] == 's' ? WC_REL_GE : WC_REL_EQ;
        }
    for (j = 0; j < e + ng; j++)
    {
        fmpq_one(fmpq_mat_entry(A, r, 3 + j));
        rel[r++] = j < e ? WC_REL_GE : WC_REL_GT;
    }
    _wc_fmpq_mat_keep_rows(A, r);
    if (mult != NULL)
        y = _fmpq_vec_init(r);
    res = _wc_lp_motzkin(z, y, A, rel, err);
    if (res == 0 && mult != NULL)
    {
        *mult = y;
        *nmult = r;
        y = NULL;
    }
    if (y != NULL)
        _fmpq_vec_clear(y, r);
    if (res == 1 && ng == 1 && nudot != NULL)
    {
        /* nudot and c, scaled by alpha_1 */
        for (k = 0; k < 3; k++)
            fmpq_div(nudot + k, z + k, z + nv - 1);
        _wc_qvec_zero(c, 2 * n);
        for (i = 0, j = 0; i < n; i++)
            for (r = 0; x[i] == 'm' && r < 2; r++, j++)
            {
                fmpq_div(ed + 0, z + 3 + j, z + nv - 1);
                fmpq_add(c + i, c + i, ed + 0);
                fmpq_mul(ed + 1, ed + 0, mu + i);
                if (r == 0)
                    fmpq_sub(c + n + i, c + n + i, ed + 1);
                else
                    fmpq_add(c + n + i, c + n + i, ed + 1);
            }
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(w + k);
    fmpq_clear(ed + 0);
    fmpq_clear(ed + 1);
    _fmpq_vec_clear(z, nv);
    flint_free(rel);
    fmpq_mat_clear(A);
    return res;
}

static const char *
needed(const _wc_plancert * C, slong j)
{
    return C->R->T->strings[C->R->T->needed[j]];
}

int
_wc_plancert_cone(_wc_cone_proof * cp, _wc_plancert * C, slong j,
                  wc_error_t err)
{
    const wc_cone_struct * Q = C->R->cones + j;
    slong g;
    int status = WC_OK, r;

    cp->ngen = _wc_setcert_generators(&C->base, Q, -1);
    cp->nfaces = Q->nfaces;
    cp->closure = flint_malloc(sizeof(wc_motion_struct) * (cp->ngen + 1));
    cp->motion = NULL;
    cp->included = NULL;
    for (g = 0; g < cp->ngen; g++)
        _wc_motion_init(cp->closure + g, C->m.n);
    for (g = 0; g < cp->ngen && status == WC_OK; g++)
    {
        r = _wc_plan_string_solve(cp->closure[g].nudot, cp->closure[g].c,
                                  NULL, NULL, &C->m, C->mu, needed(C, j),
                                  C->base.F + 3 * g, 1, err);
        if (r != 1)
            status = r < 0 ? WC_EINTERNAL : bug(err, "has a string cone "
                                                "that its string denies");
    }
    return status;
}

int
_wc_plancert_piece(_wc_piece_proof * pp, _wc_plancert * C, slong k,
                   wc_error_t err)
{
    const wc_cone_struct * Q = C->R->goal->pieces + k;
    slong f, j, ng, ns = C->R->T->nneeded;
    int status = WC_OK, r;

    pp->ngen = 0;
    pp->c = NULL;
    pp->nfaces = Q->nfaces;
    pp->mult = flint_calloc(Q->nfaces + 1, sizeof(fmpq **));
    pp->nmult = flint_calloc(Q->nfaces + 1, sizeof(slong *));
    for (f = 0; f < Q->nfaces && status == WC_OK; f++)
    {
        if (!Q->faces[f].included)
            continue;
        ng = _wc_setcert_generators(&C->base, Q, f);
        pp->mult[f] = flint_calloc(ns + 1, sizeof(fmpq *));
        pp->nmult[f] = flint_calloc(ns + 1, sizeof(slong));
        for (j = 0; j < ns && status == WC_OK; j++)
        {
            r = _wc_plan_string_solve(NULL, NULL, pp->mult[f] + j,
                                      pp->nmult[f] + j, &C->m, C->mu,
                                      needed(C, j), C->base.F, ng, err);
            if (r != 0)
                status = r < 0 ? WC_EINTERNAL : bug(err, "meets a string's "
                                                    "cone");
        }
    }
    return status;
}

/* R in the face of Q that holds s: leaf (kind, owner) or a cut.  */
static int
place(const wc_cone_struct * Q, _wc_node_kind kind, slong owner,
      const fmpq * s, const _wc_region3 * R, _wc_tree_node * leaf,
      fmpz * plane)
{
    leaf->kind = kind;
    leaf->a = owner;
    leaf->b = wc_cone_locate(Q, s);
    return _wc_setcert_in_face(plane, Q, leaf->b, R);
}

int
_wc_plancert_classify(void * ctx, const _wc_region3 * R, const fmpz * sum,
                      _wc_tree_node * leaf, fmpz * sep, fmpz * plane,
                      wc_error_t err)
{
    _wc_plancert * C = ctx;
    const wc_plan_struct * P = C->R;
    slong k, j = 0;
    fmpq s[3];
    int r;

    (void) sep;
    for (k = 0; k < 3; k++)
    {
        fmpq_init(s + k);
        fmpq_set_fmpz(s + k, sum + k);
    }
    for (k = 0; k < P->goal->npieces; k++)
        if (wc_cone_contains(P->goal->pieces + k, s))
            break;
    for (j = 0; k == P->goal->npieces && j < P->T->nneeded; j++)
        if (wc_cone_contains(P->cones + j, s))
            break;
    if (k < P->goal->npieces)
        r = place(P->goal->pieces + k, WC_NODE_IN, k, s, R, leaf, plane);
    else if (j < P->T->nneeded)
        r = place(P->cones + j, WC_NODE_EXCLUDED, j, s, R, leaf, plane);
    else
    {
        bug(err, "leaves out a region");
        r = -1;
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(s + k);
    return r;
}

void
_wc_plancert_prefer(fmpz ** h, slong * n, const _wc_plancert * C)
{
    const wc_plan_struct * P = C->R;
    slong k, i, m = 0, nq = P->goal->npieces + P->T->nneeded;

    for (k = 0; k < nq; k++)
    {
        const wc_cone_struct * Q = k < P->goal->npieces ? P->goal->pieces + k
            : P->cones + (k - P->goal->npieces);

        m += fmpz_mat_nrows(Q->ineqs) + fmpz_mat_nrows(Q->eqs);
    }
    *h = _fmpz_vec_init(3 * m + 3);
    *n = 0;
    for (k = 0; k < nq; k++)
    {
        const wc_cone_struct * Q = k < P->goal->npieces ? P->goal->pieces + k
            : P->cones + (k - P->goal->npieces);

        for (i = 0; i < fmpz_mat_nrows(Q->ineqs); i++)
            _fmpz_vec_set(*h + 3 * (*n)++, WC_ROW(Q->ineqs, i), 3);
        for (i = 0; i < fmpz_mat_nrows(Q->eqs); i++)
            _fmpz_vec_set(*h + 3 * (*n)++, WC_ROW(Q->eqs, i), 3);
    }
}
