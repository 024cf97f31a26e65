/* stabcert.c -- the proof, cell by cell, that a strong stability set is
   exact.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   See stabcert.h.  Every proof comes from an exact LP (facesys.c,
   exact/lp.c) and is checked there against its rows; an LP that contradicts
   the set (a motion for a cell in it, none for a cell outside it) means a
   wrong set, reported as an internal error rather than written.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpq_vec.h>

#include "model/model.h"
#include "exact/lp.h"
#include "exact/vec3.h"
#include "analysis/facesys.h"
#include "analysis/stabcert.h"

int
_wc_stabcert_init(_wc_stabcert * C, const wc_problem_t P,
                  const wc_stability_t S, wc_error_t err)
{
    slong i, most = 0;

    C->S = S;
    _wc_stab_model_init(&C->m, P);
    C->off = C->ray = NULL;
    C->face = flint_malloc(sizeof(slong) * (S->nmoving + 1));
    C->nfaces = 0;
    for (i = 0; i < S->nmoving; i++)
        if (S->moving_rot[i] != 2)
            C->face[C->nfaces++] = i;
    C->G = NULL;
    C->gcap = 0;
    if (wc_cells_rays(&C->off, &C->ray, S->cells, err) != WC_OK)
        return WC_EINTERNAL;
    for (i = 0; i < S->cells->count; i++)
        if (C->off[i + 1] - C->off[i] > most)
            most = C->off[i + 1] - C->off[i];
    C->gcap = most + 1;
    C->G = _fmpq_vec_init(3 * C->gcap);
    return WC_OK;
}

void
_wc_stabcert_clear(_wc_stabcert * C)
{
    _wc_stab_model_clear(&C->m);
    flint_free(C->off);
    flint_free(C->ray);
    flint_free(C->face);
    if (C->G != NULL)
        _fmpq_vec_clear(C->G, 3 * C->gcap);
}

void
_wc_cell_proof_init(_wc_cell_proof * pf, const _wc_stabcert * C)
{
    slong k, n = C->m.n;

    pf->reason = WC_CELL_STRONG;
    pf->weak = 0;
    pf->weak_c = _fmpq_vec_init(2 * n + 1);
    for (k = 0; k < 3; k++)
        fmpq_init(pf->sep + k);
    pf->face = -1;
    pf->nrays = 0;
    pf->closure = flint_malloc(sizeof(wc_motion_struct) * C->gcap);
    for (k = 0; k < C->gcap; k++)
        _wc_motion_init(pf->closure + k, n);
    _wc_motion_init(&pf->motion, n);
    pf->mult = flint_calloc(C->nfaces + 1, sizeof(fmpq *));
    pf->nmult = flint_calloc(C->nfaces + 1, sizeof(slong));
}

static void
drop_mult(_wc_cell_proof * pf, const _wc_stabcert * C)
{
    slong j;

    for (j = 0; j < C->nfaces; j++)
        if (pf->mult[j] != NULL)
        {
            _fmpq_vec_clear(pf->mult[j], pf->nmult[j]);
            pf->mult[j] = NULL;
            pf->nmult[j] = 0;
        }
}

void
_wc_cell_proof_clear(_wc_cell_proof * pf, const _wc_stabcert * C)
{
    slong k, n = C->m.n;

    drop_mult(pf, C);
    flint_free(pf->mult);
    flint_free(pf->nmult);
    _fmpq_vec_clear(pf->weak_c, 2 * n + 1);
    for (k = 0; k < 3; k++)
        fmpq_clear(pf->sep + k);
    for (k = 0; k < C->gcap; k++)
        _wc_motion_clear(pf->closure + k, n);
    flint_free(pf->closure);
    _wc_motion_clear(&pf->motion, n);
}

static int
bug(wc_error_t err, const char * what)
{
    return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                        "the strong stability set %s", what);
}

/* A cell outside the set but weakly stable: the first moving face whose
   cone holds its point, with the motions.  */
static int
prove_moves(_wc_cell_proof * pf, _wc_stabcert * C, const fmpq * sum,
            wc_error_t err)
{
    const wc_stability_struct * S = C->S;
    slong j, k;
    int r;

    pf->reason = WC_CELL_MOVES;
    for (j = 0; j < C->nfaces; j++)
        if (wc_cone_contains(S->moving + C->face[j], sum))
            break;
    if (j == C->nfaces)
        return bug(err, "leaves out a strongly stable cell");
    pf->face = j;
    j = C->face[j];
    for (k = 0; k < pf->nrays; k++)
    {
        r = _wc_face_solve_cone(pf->closure[k].nudot, pf->closure[k].c, NULL,
                                NULL, &C->m, S->moving_sign[j],
                                S->moving_sign[j], S->moving_rot[j],
                                C->G + 3 * k, 1, 1, err);
        if (r != 1)
            return r < 0 ? WC_EINTERNAL : bug(err, "has a cell outside "
                                              "a moving cone's closure");
    }
    r = _wc_face_solve_cone(pf->motion.nudot, pf->motion.c, NULL, NULL,
                            &C->m, S->moving_sign[j], S->moving_sign[j],
                            S->moving_rot[j], sum, 1, 0, err);
    if (r != 1)
        return r < 0 ? WC_EINTERNAL : bug(err, "has a cell outside the "
                                          "moving cone that holds it");
    return WC_OK;
}

/* A cell that is not weakly stable: pf->sep := y with y . w >= 0 on every
   mu_s edge w of a touching fixel, y . r >= 0 on every ray and y . sum > 0
   (the separator of the sum alone may miss a ray).  */
static int
prove_not_weak(_wc_cell_proof * pf, _wc_stabcert * C, const fmpq * sum,
               wc_error_t err)
{
    const _wc_stab_model * m = &C->m;
    slong rows = 2 * m->t + pf->nrays + 1, i, k, r = 0;
    fmpq_mat_t A;
    wc_relation * rel = flint_malloc(sizeof(wc_relation) * rows);
    fmpq ed[4];
    int ok;

    pf->reason = WC_CELL_NOT_WEAK;
    fmpq_mat_init(A, rows, 3);
    for (k = 0; k < 4; k++)
        fmpq_init(ed + k);
    for (i = 0; i < m->t; i++)
    {
        wc_friction_edges(ed, m->P->fixels + m->tidx[i], 'n');
        _wc_stab_edge_wrench(A->rows[r], m, m->tidx[i], ed);
        rel[r++] = WC_REL_GE;
        _wc_stab_edge_wrench(A->rows[r], m, m->tidx[i], ed + 2);
        rel[r++] = WC_REL_GE;
    }
    for (i = 0; i < pf->nrays; i++)
    {
        _wc_qvec_set(A->rows[r], C->G + 3 * i, 3);
        rel[r++] = WC_REL_GE;
    }
    _wc_qvec_set(A->rows[r], sum, 3);
    rel[r++] = WC_REL_GT;
    ok = _wc_lp_motzkin(pf->sep, NULL, A, rel, err);
    fmpq_mat_clear(A);
    flint_free(rel);
    for (k = 0; k < 4; k++)
        fmpq_clear(ed + k);
    if (ok != 1)
        return ok < 0 ? WC_EINTERNAL : bug(err, "has a cell partly weakly "
                                           "stable");
    return WC_OK;
}

/* A cell in the set: no moving face has a motion anywhere in it.  */
static int
prove_strong(_wc_cell_proof * pf, _wc_stabcert * C, wc_error_t err)
{
    const wc_stability_struct * S = C->S;
    slong j, f;
    int r;

    pf->reason = WC_CELL_STRONG;
    for (j = 0; j < C->nfaces; j++)
    {
        f = C->face[j];
        r = _wc_face_solve_cone(NULL, NULL, pf->mult + j, pf->nmult + j,
                                &C->m, S->moving_sign[f], S->moving_sign[f],
                                S->moving_rot[f], C->G, pf->nrays, 0, err);
        if (r != 0)
            return r < 0 ? WC_EINTERNAL : bug(err, "holds a cell that "
                                              "moves");
    }
    return WC_OK;
}

int
_wc_stabcert_cell(_wc_cell_proof * pf, _wc_stabcert * C, slong i,
                  wc_error_t err)
{
    const wc_stability_struct * S = C->S;
    const wc_cells_struct * A = S->cells;
    slong k, nr = C->off[i + 1] - C->off[i];
    fmpq sum[3];
    int status = WC_OK, weak, in;

    drop_mult(pf, C);
    pf->nrays = nr;
    pf->face = -1;
    pf->weak = 0;
    for (k = 0; k < 3; k++)
        fmpq_init(sum + k);
    for (k = 0; k < nr; k++)
    {
        _fmpq_vec_set_fmpz_vec(C->G + 3 * k,
                               WC_ROW(A->point, C->ray[C->off[i] + k]), 3);
        fmpq_add(sum + 0, sum + 0, C->G + 3 * k + 0);
        fmpq_add(sum + 1, sum + 1, C->G + 3 * k + 1);
        fmpq_add(sum + 2, sum + 2, C->G + 3 * k + 2);
    }
    in = wc_set_contains(S->strong, sum);
    weak = _wc_stab_weak(pf->weak_c, pf->sep, &C->m, sum, err);
    if (weak < 0)
        status = WC_EINTERNAL;
    else if (A->dim[i] == 1)
        pf->weak = weak;
    if (status == WC_OK && !weak)
        status = in ? bug(err, "holds a cell that is not weakly stable")
            : prove_not_weak(pf, C, sum, err);
    else if (status == WC_OK && in)
        status = prove_strong(pf, C, err);
    else if (status == WC_OK)
        status = prove_moves(pf, C, sum, err);
    for (k = 0; k < 3; k++)
        fmpq_clear(sum + k);
    return status;
}
