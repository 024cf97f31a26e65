/* setcert.c -- what the certificates of sets share: the cells with their
   rays, and a cell's place in a face of a cone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   See setcert.h.  The combinations come from a 3-D simplex
   (_wc_lp_cone3), which checks its answer exactly.  */

#include <config.h>

#include <flint/fmpq_vec.h>

#include "exact/lp.h"
#include "exact/vec3.h"
#include "analysis/stabmodel.h"
#include "analysis/setcert.h"

int
_wc_setcert_bug(wc_error_t err, const char * set, const char * what)
{
    return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                        "the %s %s", set, what);
}

int
_wc_setcert_init(_wc_setcert * C, const wc_cells_t A,
                 const wc_cone_struct * const * Q, slong nq, wc_error_t err)
{
    slong i, most = 0;

    C->A = A;
    C->off = C->ray = NULL;
    C->G = C->F = NULL;
    C->gcap = C->fcap = 0;
    if (wc_cells_rays(&C->off, &C->ray, A, err) != WC_OK)
        return WC_EINTERNAL;
    for (i = 0; i < A->count; i++)
        if (C->off[i + 1] - C->off[i] > most)
            most = C->off[i + 1] - C->off[i];
    C->gcap = most + 1;
    C->G = _fmpq_vec_init(3 * C->gcap);
    most = 1;
    for (i = 0; i < nq; i++)
    {
        slong g = fmpz_mat_nrows(Q[i]->rays) + 2 * fmpz_mat_nrows(Q[i]->lines);

        most = g > most ? g : most;
    }
    C->fcap = most;
    C->F = _fmpq_vec_init(3 * C->fcap);
    return WC_OK;
}

void
_wc_setcert_clear(_wc_setcert * C)
{
    flint_free(C->off);
    flint_free(C->ray);
    if (C->G != NULL)
        _fmpq_vec_clear(C->G, 3 * C->gcap);
    if (C->F != NULL)
        _fmpq_vec_clear(C->F, 3 * C->fcap);
}

slong
_wc_setcert_generators(_wc_setcert * C, const wc_cone_struct * Q, slong f)
{
    slong j, l, g = 0, nr = f < 0 ? fmpz_mat_nrows(Q->rays)
        : Q->faces[f].nrays;

    for (j = 0; j < nr; j++, g++)
        _fmpq_vec_set_fmpz_vec(C->F + 3 * g, WC_ROW(Q->rays,
                               f < 0 ? j : Q->faces[f].rays[j]), 3);
    for (l = 0; l < fmpz_mat_nrows(Q->lines); l++, g += 2)
    {
        _fmpq_vec_set_fmpz_vec(C->F + 3 * g, WC_ROW(Q->lines, l), 3);
        for (j = 0; j < 3; j++)
            fmpq_neg(C->F + 3 * (g + 1) + j, C->F + 3 * g + j);
    }
    return g;
}

slong
_wc_setcert_rays(_wc_setcert * C, slong i, fmpq * sum)
{
    slong k, j, nr = C->off[i + 1] - C->off[i];

    for (j = 0; j < 3; j++)
        fmpq_zero(sum + j);
    for (k = 0; k < nr; k++)
    {
        _fmpq_vec_set_fmpz_vec(C->G + 3 * k,
                               WC_ROW(C->A->point, C->ray[C->off[i] + k]), 3);
        for (j = 0; j < 3; j++)
            fmpq_add(sum + j, sum + j, C->G + 3 * k + j);
    }
    return nr;
}

void
_wc_piece_proof_clear(_wc_piece_proof * pp, slong n, slong nexcl)
{
    slong f, j;

    if (pp->c != NULL)
        _fmpq_vec_clear(pp->c, pp->ngen * 2 * n + 1);
    for (f = 0; pp->mult != NULL && f < pp->nfaces; f++)
    {
        for (j = 0; pp->mult[f] != NULL && j < nexcl; j++)
            if (pp->mult[f][j] != NULL)
                _fmpq_vec_clear(pp->mult[f][j], pp->nmult[f][j]);
        flint_free(pp->mult[f]);
        flint_free(pp->nmult[f]);
    }
    flint_free(pp->mult);
    flint_free(pp->nmult);
}

void
_wc_cone_proof_clear(_wc_cone_proof * cp, slong n)
{
    slong k;

    for (k = 0; cp->closure != NULL && k < cp->ngen; k++)
        _wc_motion_clear(cp->closure + k, n);
    for (k = 0; cp->motion != NULL && k < cp->nfaces; k++)
        _wc_motion_clear(cp->motion + k, n);
    flint_free(cp->closure);
    flint_free(cp->motion);
    flint_free(cp->included);
}

void
_wc_cell_proof_init(_wc_cell_proof * pf, const _wc_setcert * C)
{
    slong k;

    pf->reason = WC_CELL_IN;
    for (k = 0; k < 3; k++)
        fmpq_init(pf->sep + k);
    pf->owner = pf->face = -1;
    pf->nrays = 0;
    pf->ngen = 0;
    pf->alpha = _fmpq_vec_init(C->fcap);
    pf->beta = _fmpq_vec_init(C->gcap * C->fcap);
}

void
_wc_cell_proof_clear(_wc_cell_proof * pf, const _wc_setcert * C)
{
    slong k;

    for (k = 0; k < 3; k++)
        fmpq_clear(pf->sep + k);
    _fmpq_vec_clear(pf->alpha, C->fcap);
    _fmpq_vec_clear(pf->beta, C->gcap * C->fcap);
}

/* alpha (ng) with every entry > 0 and sum alpha_i F_i = x, x known to lie
   in relint pos(F): x - t s is in pos(F) for s = sum F_i and some t > 0,
   found by halving t from 1 (a 3-D simplex each, exact/lp.h), and then
   alpha = (its coefficients) + t.  1, or -1 on failure.  */
static int
strictly_inside(fmpq * alpha, const fmpq * F, slong ng, const fmpq * x,
                wc_error_t err)
{
    fmpq y[3], s[3], sep[3];
    fmpq_t t;
    slong i, k, tries;
    int r = 0;

    fmpq_init(t);
    for (k = 0; k < 3; k++)
    {
        fmpq_init(y + k);
        fmpq_init(s + k);
        fmpq_init(sep + k);
        for (i = 0; i < ng; i++)
            fmpq_add(s + k, s + k, F + 3 * i + k);
    }
    fmpq_one(t);
    for (tries = 0; tries < 200 && r == 0; tries++)
    {
        for (k = 0; k < 3; k++)
        {
            fmpq_mul(y + k, t, s + k);
            fmpq_sub(y + k, x + k, y + k);
        }
        r = _wc_lp_cone3(alpha, sep, F, ng, y, err);
        if (r == 0)
            fmpq_div_2exp(t, t, 1);
    }
    for (i = 0; r == 1 && i < ng; i++)
        fmpq_add(alpha + i, alpha + i, t);
    if (r == 0)
    {
        wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: a "
                     "cell's point is not inside its face");
        r = -1;
    }
    fmpq_clear(t);
    for (k = 0; k < 3; k++)
    {
        fmpq_clear(y + k);
        fmpq_clear(s + k);
        fmpq_clear(sep + k);
    }
    return r;
}

int
_wc_setcert_locate(_wc_cell_proof * pf, _wc_setcert * C,
                   const wc_cone_struct * Q, slong owner, const fmpq * sum,
                   wc_error_t err)
{
    fmpq sep[3];
    slong f = wc_cone_locate(Q, sum), j;
    int r;

    if (f < 0 || !Q->faces[f].included)
        return _wc_setcert_bug(err, "set", "misses a cell");
    pf->owner = owner;
    pf->face = f;
    pf->ngen = _wc_setcert_generators(C, Q, f);
    r = strictly_inside(pf->alpha, C->F, pf->ngen, sum, err);
    for (j = 0; j < 3; j++)
        fmpq_init(sep + j);
    for (j = 0; r == 1 && j < pf->nrays; j++)
        r = _wc_lp_cone3(pf->beta + j * pf->ngen, sep, C->F, pf->ngen,
                         C->G + 3 * j, err);
    for (j = 0; j < 3; j++)
        fmpq_clear(sep + j);
    if (r != 1)
        return r < 0 ? WC_EINTERNAL : _wc_setcert_bug(err, "set", "has a "
                                                      "cell across a face");
    return WC_OK;
}
