/* stabcert.c -- the proof that a strong stability set is exact: its
   pieces' included faces one by one, and a place for every region of
   the tree.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   See stabcert.h.  Every proof comes from an exact LP (facesys.c,
   exact/lp.c) and is checked there against its rows; an LP that contradicts
   the set (a motion in an included face, none for a region outside it)
   means a wrong set, reported as an internal error rather than written.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpz_vec.h>
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
    const wc_cone_struct ** Q;
    slong i, nq = S->strong->npieces + S->nmoving;

    (void) err;
    C->S = S;
    _wc_stab_model_init(&C->m, P);
    C->face = flint_malloc(sizeof(slong) * (S->nmoving + 1));
    C->nfaces = 0;
    for (i = 0; i < S->nmoving; i++)
        if (S->moving_rot[i] != 2)
            C->face[C->nfaces++] = i;
    Q = flint_malloc(sizeof(wc_cone_struct *) * (nq + 1));
    for (i = 0; i < nq; i++)
        Q[i] = i < S->strong->npieces ? S->strong->pieces + i
            : S->moving + (i - S->strong->npieces);
    _wc_setcert_init(&C->base, Q, nq);
    flint_free(Q);
    return WC_OK;
}

void
_wc_stabcert_clear(_wc_stabcert * C)
{
    _wc_stab_model_clear(&C->m);
    flint_free(C->face);
    _wc_setcert_clear(&C->base);
}

static int
bug(wc_error_t err, const char * what)
{
    return _wc_setcert_bug(err, "strong stability set", what);
}

/* ---------------------------------------------------------------------
   The pieces.  */


/* Does h separate: h . r <= 0 on every ray of W's closure, = 0 on its
   lines, h . G_i >= 0 on the ng generators G?  (facesys.c then needs
   one > 0, or a strict row of the face.)  */
static int
separates(const fmpq * h, const wc_cone_struct * W, const fmpq * G, slong ng,
          fmpq_t d)
{
    slong i;

    if (_wc_qvec_is_zero(h, 3))
        return 0;
    for (i = 0; i < fmpz_mat_nrows(W->rays); i++)
    {
        _wc_zqvec3_dot(d, WC_ROW(W->rays, i), h);
        if (fmpq_sgn(d) > 0)
            return 0;
    }
    for (i = 0; i < fmpz_mat_nrows(W->lines); i++)
    {
        _wc_zqvec3_dot(d, WC_ROW(W->lines, i), h);
        if (!fmpq_is_zero(d))
            return 0;
    }
    for (i = 0; i < ng; i++)
    {
        _fmpq_vec_dot(d, G + 3 * i, h, 3);
        if (fmpq_sgn(d) < 0)
            return 0;
    }
    return 1;
}

/* Multipliers for moving face y against the generators C->base.F (ng)
   without an LP (facesys.c), from a plane h with W = y's cone on its side
   h . g <= 0 and the generators on the other: first W's facets and
   equalities, then the edges of the cone of all such h -- it is cut by
   the planes r . h = 0 of W's rays and lines and G_i . h = 0, so each
   edge is the cross product of two of these.  1 with them, 0 when no h
   serves (then an LP decides), -1.  */
static int
facet_proof(fmpq ** mult, slong * nmult, _wc_stabcert * C, slong y, slong ng,
            wc_error_t err)
{
    const wc_cone_struct * W = C->S->moving + y;
    slong ni = fmpz_mat_nrows(W->ineqs), ne = fmpz_mat_nrows(W->eqs), r, k;
    slong nr = fmpz_mat_nrows(W->rays), nl = fmpz_mat_nrows(W->lines);
    slong nc = nr + nl + ng, a, b;
    fmpq h[3], * c = _fmpq_vec_init(3 * nc + 3);
    fmpq_t d;
    int res = 0, sg;

    fmpq_init(d);
    for (k = 0; k < 3; k++)
        fmpq_init(h + k);
    for (r = 0; r < ni + 2 * ne && res == 0; r++)
    {
        const fmpz * row = r < ni ? WC_ROW(W->ineqs, r)
            : WC_ROW(W->eqs, (r - ni) / 2);

        for (k = 0; k < 3; k++)
        {
            fmpq_set_fmpz(h + k, row + k);
            if (r >= ni && (r - ni) % 2 == 1)
                fmpq_neg(h + k, h + k);
        }
        res = _wc_face_facet_mult(mult, nmult, &C->m, C->S->moving_sign[y],
                                  C->S->moving_rot[y], h, C->base.F, ng,
                                  err);
    }
    /* the sum of W's facet normals: inside the cone of such planes, where
       the origin's proof needs its plane */
    for (k = 0; k < 3; k++)
        fmpq_zero(h + k);
    for (r = 0; r < ni; r++)
        for (k = 0; k < 3; k++)
            fmpz_add(fmpq_numref(h + k), fmpq_numref(h + k),
                     fmpz_mat_entry(W->ineqs, r, k));
    if (res == 0 && ni > 1 && separates(h, W, C->base.F, ng, d))
        res = _wc_face_facet_mult(mult, nmult, &C->m, C->S->moving_sign[y],
                                  C->S->moving_rot[y], h, C->base.F, ng,
                                  err);
    for (a = 0; a < nc; a++)
        if (a < nr + nl)
            _fmpq_vec_set_fmpz_vec(c + 3 * a, a < nr ? WC_ROW(W->rays, a)
                                   : WC_ROW(W->lines, a - nr), 3);
        else
            _wc_qvec_set(c + 3 * a, C->base.F + 3 * (a - nr - nl), 3);
    for (a = 0; a < nc && res == 0; a++)
        for (b = a + 1; b < nc && res == 0; b++)
        {
            _wc_qvec3_cross(h, c + 3 * a, c + 3 * b);
            for (sg = 0; sg < 2 && res == 0; sg++)
            {
                for (k = 0; sg == 1 && k < 3; k++)
                    fmpq_neg(h + k, h + k);
                if (separates(h, W, C->base.F, ng, d))
                    res = _wc_face_facet_mult(mult, nmult, &C->m,
                                              C->S->moving_sign[y],
                                              C->S->moving_rot[y], h,
                                              C->base.F, ng, err);
            }
        }
    for (k = 0; k < 3; k++)
        fmpq_clear(h + k);
    fmpq_clear(d);
    _fmpq_vec_clear(c, 3 * nc + 3);
    return res;
}

/* The multipliers of every moving face for the included face f.  */
static int
prove_face(_wc_piece_proof * pp, _wc_stabcert * C, slong k, slong f,
           wc_error_t err)
{
    const wc_stability_struct * S = C->S;
    slong j, y, ng = _wc_setcert_generators(&C->base, S->strong->pieces + k, f);
    int r;

    pp->mult[f] = flint_calloc(C->nfaces + 1, sizeof(fmpq *));
    pp->nmult[f] = flint_calloc(C->nfaces + 1, sizeof(slong));
    for (j = 0; j < C->nfaces; j++)
    {
        y = C->face[j];
        r = facet_proof(pp->mult[f] + j, pp->nmult[f] + j, C, y, ng, err);
        if (r == 0)
            r = _wc_face_solve_cone(NULL, NULL, pp->mult[f] + j,
                                    pp->nmult[f] + j, &C->m,
                                    S->moving_sign[y], S->moving_sign[y],
                                    S->moving_rot[y], C->base.F, ng, 0,
                                    err);
        else if (r == 1)
            r = 0;
        if (r != 0)
            return r < 0 ? WC_EINTERNAL : bug(err, "holds wrenches that "
                                              "move");
    }
    return WC_OK;
}

int
_wc_stabcert_piece(_wc_piece_proof * pp, _wc_stabcert * C, slong k,
                   wc_error_t err)
{
    const wc_cone_struct * Q = C->S->strong->pieces + k;
    slong n2 = 2 * C->m.n, g, f, j;
    fmpq sep[3];
    int status = WC_OK, r;

    pp->ngen = _wc_setcert_generators(&C->base, Q, -1);
    pp->c = _fmpq_vec_init(pp->ngen * n2 + 1);
    pp->nfaces = Q->nfaces;
    pp->mult = flint_calloc(Q->nfaces + 1, sizeof(fmpq **));
    pp->nmult = flint_calloc(Q->nfaces + 1, sizeof(slong *));
    for (j = 0; j < 3; j++)
        fmpq_init(sep + j);
    for (g = 0; g < pp->ngen && status == WC_OK; g++)
    {
        r = _wc_stab_weak(pp->c + g * n2, sep, &C->m, C->base.F + 3 * g, err);
        if (r != 1)
            status = r < 0 ? WC_EINTERNAL : bug(err, "has a piece that is "
                                                "not weakly stable");
    }
    for (f = 0; f < Q->nfaces && status == WC_OK; f++)
        if (Q->faces[f].included)
            status = prove_face(pp, C, k, f, err);
    for (j = 0; j < 3; j++)
        fmpq_clear(sep + j);
    return status;
}

/* ---------------------------------------------------------------------
   The moving cones.  */


/* A motion of face y (of its closure when closed) for the wrench g.  */
static int
face_motion(wc_motion_struct * a, _wc_stabcert * C, slong y,
            const fmpq * g, int closed, wc_error_t err)
{
    const wc_stability_struct * S = C->S;
    int r = _wc_face_solve_cone(a->nudot, a->c, NULL, NULL, &C->m,
                                S->moving_sign[y], S->moving_sign[y],
                                S->moving_rot[y], g, 1, closed, err);

    if (r != 1)
        return r < 0 ? WC_EINTERNAL : bug(err, "has a moving cone that "
                                          "does not move");
    return WC_OK;
}

int
_wc_stabcert_cone(_wc_cone_proof * cp, _wc_stabcert * C, slong j,
                  wc_error_t err)
{
    slong y = C->face[j], g, f, k;
    const wc_cone_struct * Q = C->S->moving + y;
    fmpq sum[3];
    int status = WC_OK;

    cp->ngen = _wc_setcert_generators(&C->base, Q, -1);
    cp->nfaces = Q->nfaces;
    cp->closure = flint_malloc(sizeof(wc_motion_struct) * (cp->ngen + 1));
    cp->motion = flint_malloc(sizeof(wc_motion_struct) * (cp->nfaces + 1));
    cp->included = flint_calloc(cp->nfaces + 1, sizeof(int));
    for (g = 0; g < cp->ngen; g++)
        _wc_motion_init(cp->closure + g, C->m.n);
    for (f = 0; f < cp->nfaces; f++)
        _wc_motion_init(cp->motion + f, C->m.n);
    for (g = 0; g < cp->ngen && status == WC_OK; g++)
        status = face_motion(cp->closure + g, C, y, C->base.F + 3 * g, 1, err);
    for (k = 0; k < 3; k++)
        fmpq_init(sum + k);
    for (f = 0; f < cp->nfaces && status == WC_OK; f++)
    {
        slong ng;

        if (!(cp->included[f] = Q->faces[f].included))
            continue;
        ng = _wc_setcert_generators(&C->base, Q, f);
        for (k = 0; k < 3; k++)
            fmpq_zero(sum + k);
        for (g = 0; g < ng; g++)
            for (k = 0; k < 3; k++)
                fmpq_add(sum + k, sum + k, C->base.F + 3 * g + k);
        status = face_motion(cp->motion + f, C, y, sum, 0, err);
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(sum + k);
    return status;
}

/* ---------------------------------------------------------------------
   The regions.  */

/* R (its rays summing to s) is outside the closed weak cone W: one of
   W's facets or equalities has s on its open outer side.  Its normal y
   (y . x <= 0 on W, so y . w >= 0 on every friction edge w, whose
   negatives generate W) is a separator when every ray is on that side
   too; else R is cut by the first such plane.  */
static int
not_weak(_wc_stabcert * C, const _wc_region3 * R, const fmpq * s,
         _wc_tree_node * leaf, fmpz * sep, fmpz * plane, wc_error_t err)
{
    const wc_cone_struct * W = C->S->weak;
    slong r, j, m = fmpz_mat_nrows(W->ineqs), cut = -1;
    fmpq_t d;
    fmpz_t e;
    int ok = 0, side = 1;

    fmpq_init(d);
    fmpz_init(e);
    for (r = 0; r < m + 2 * fmpz_mat_nrows(W->eqs) && !ok; r++)
    {
        const fmpz * h = r < m ? WC_ROW(W->ineqs, r)
            : WC_ROW(W->eqs, (r - m) / 2);

        side = r < m || (r - m) % 2 == 0 ? 1 : -1;
        _wc_zqvec3_dot(d, h, s);
        if (fmpq_sgn(d) * side <= 0)
            continue;
        cut = cut < 0 ? r : cut;
        ok = 1;
        for (j = 0; j < R->n && ok; j++)
        {
            _fmpz_vec_dot(e, h, R->r + 3 * j, 3);
            ok = fmpz_sgn(e) * side >= 0;
        }
        if (ok)
        {
            _fmpz_vec_scalar_mul_si(sep, h, 3, side);
            leaf->kind = WC_NODE_NOT_WEAK;
        }
    }
    if (!ok && cut >= 0)
        _fmpz_vec_set(plane, cut < m ? WC_ROW(W->ineqs, cut)
                      : WC_ROW(W->eqs, (cut - m) / 2), 3);
    fmpq_clear(d);
    fmpz_clear(e);
    if (!ok && cut < 0)
        bug(err, "has a region off the weak cone but on no side of it");
    return ok ? 1 : cut >= 0 ? 0 : -1;
}

/* R in the face of Q that holds s: leaf (kind, owner) or a cut.  */
static int
place(const wc_cone_struct * Q, _wc_node_kind kind, slong owner,
      const fmpq * s, const _wc_region3 * R, _wc_tree_node * leaf,
      fmpz * plane)
{
    slong f = wc_cone_locate(Q, s);

    leaf->kind = kind;
    leaf->a = owner;
    leaf->b = f;
    return _wc_setcert_in_face(plane, Q, f, R);
}

int
_wc_stabcert_classify(void * ctx, const _wc_region3 * R, const fmpz * sum,
                      _wc_tree_node * leaf, fmpz * sep, fmpz * plane,
                      wc_error_t err)
{
    _wc_stabcert * C = ctx;
    const wc_stability_struct * S = C->S;
    slong k, j;
    fmpq s[3];
    int r;

    for (k = 0; k < 3; k++)
    {
        fmpq_init(s + k);
        fmpq_set_fmpz(s + k, sum + k);
    }
    for (k = 0; k < S->strong->npieces; k++)
        if (wc_cone_contains(S->strong->pieces + k, s))
            break;
    for (j = 0; k == S->strong->npieces && j < C->nfaces; j++)
        if (wc_cone_contains(S->moving + C->face[j], s))
            break;
    if (k < S->strong->npieces)
        r = place(S->strong->pieces + k, WC_NODE_IN, k, s, R, leaf, plane);
    else if (!wc_cone_contains(S->weak, s))
        r = not_weak(C, R, s, leaf, sep, plane, err);
    else if (j < C->nfaces)
        r = place(S->moving + C->face[j], WC_NODE_EXCLUDED, j, s, R, leaf,
                  plane);
    else
    {
        bug(err, "leaves out a strongly stable region");
        r = -1;
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(s + k);
    return r;
}

void
_wc_stabcert_prefer(fmpz ** h, slong * n, const _wc_stabcert * C)
{
    const wc_stability_struct * S = C->S;
    slong k, i, m = 0;

    for (k = -1; k < S->strong->npieces; k++)
    {
        const wc_cone_struct * Q = k < 0 ? S->weak : S->strong->pieces + k;

        m += fmpz_mat_nrows(Q->ineqs) + fmpz_mat_nrows(Q->eqs);
    }
    *h = _fmpz_vec_init(3 * m + 3);
    *n = 0;
    for (k = -1; k < S->strong->npieces; k++)
    {
        const wc_cone_struct * Q = k < 0 ? S->weak : S->strong->pieces + k;

        for (i = 0; i < fmpz_mat_nrows(Q->ineqs); i++)
            _fmpz_vec_set(*h + 3 * (*n)++, WC_ROW(Q->ineqs, i), 3);
        for (i = 0; i < fmpz_mat_nrows(Q->eqs); i++)
            _fmpz_vec_set(*h + 3 * (*n)++, WC_ROW(Q->eqs, i), 3);
    }
}
