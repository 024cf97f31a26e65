/* setcert.c -- what the certificates of sets share: room for generators,
   the proofs' storage, and the tree of cuts with its regions' places.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   See setcert.h.  The tree is grown from the basis: a region that the
   classifier cannot place is cut by the plane it names, which has part
   of the region on each side, so no plane cuts a region twice on one path
   and the tree is finite.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpz_vec.h>
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

void
_wc_setcert_init(_wc_setcert * C, const wc_cone_struct * const * Q, slong nq)
{
    slong i, most = 1;

    for (i = 0; i < nq; i++)
    {
        slong g = fmpz_mat_nrows(Q[i]->rays) + 2 * fmpz_mat_nrows(Q[i]->lines);

        most = g > most ? g : most;
    }
    C->fcap = most;
    C->F = _fmpq_vec_init(3 * C->fcap);
}

void
_wc_setcert_clear(_wc_setcert * C)
{
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


/* ---------------------------------------------------------------------
   The tree.  */

void
_wc_settree_init(_wc_settree * T)
{
    T->n = T->cap = 0;
    T->node = NULL;
    T->nplanes = T->pcap = 0;
    T->planes = NULL;
    T->nsep = T->scap = 0;
    T->sep = NULL;
    T->basis[0] = T->basis[1] = T->basis[2] = -1;
}

void
_wc_settree_clear(_wc_settree * T)
{
    flint_free(T->node);
    if (T->planes != NULL)
        _fmpz_vec_clear(T->planes, 3 * T->pcap);
    if (T->sep != NULL)
        _fmpz_vec_clear(T->sep, 3 * T->scap);
    _wc_settree_init(T);
}

static void
push_node(_wc_settree * T, _wc_node_kind kind, slong a, slong b)
{
    if (T->n == T->cap)
    {
        T->cap = T->cap < 64 ? 64 : 2 * T->cap;
        T->node = flint_realloc(T->node, sizeof(_wc_tree_node) * T->cap);
    }
    T->node[T->n].kind = kind;
    T->node[T->n].a = a;
    T->node[T->n++].b = b;
}

/* Append the vector v to the list *list (*n of them, room for *cap).  */
static slong
push_vec(fmpz ** list, slong * n, slong * cap, const fmpz * v)
{
    if (*n == *cap)
    {
        slong cap2 = *cap < 16 ? 16 : 2 * *cap, i;
        fmpz * l = _fmpz_vec_init(3 * cap2);

        for (i = 0; i < 3 * *n; i++)
            fmpz_swap(l + i, *list + i);
        if (*list != NULL)
            _fmpz_vec_clear(*list, 3 * *cap);
        *list = l;
        *cap = cap2;
    }
    _fmpz_vec_set(*list + 3 * *n, v, 3);
    return (*n)++;
}

/* The index of the plane h (made canonical, the way a certificate lists
   a plane) in T's list, added if new.  */
static slong
plane_index(_wc_settree * T, fmpz * h)
{
    fmpz_t t;
    slong i;

    fmpz_init(t);
    _wc_zvec3_canonical(h, t);
    fmpz_clear(t);
    for (i = 0; i < T->nplanes; i++)
        if (_fmpz_vec_equal(T->planes + 3 * i, h, 3))
            return i;
    return push_vec(&T->planes, &T->nplanes, &T->pcap, h);
}

typedef struct
{
    _wc_settree_classify classify;
    void * ctx;
    fmpz * sum, * sep, * plane;         /* 3 each */
}
grower;

static int
grow(_wc_settree * T, grower * G, const _wc_region3 * R, slong depth,
     wc_error_t err)
{
    _wc_tree_node leaf;
    _wc_region3 part[3];
    slong p, k, parts = 0;
    int r, status = WC_OK;

    if (R->dim < 0)
    {
        push_node(T, WC_NODE_EMPTY, 0, 0);
        return WC_OK;
    }
    _wc_region3_sum(G->sum, R);
    r = G->classify(G->ctx, R, G->sum, &leaf, G->sep, G->plane, err);
    if (r < 0)
        return WC_EINTERNAL;
    if (r == 1)
    {
        if (leaf.kind == WC_NODE_NOT_WEAK)
            leaf.a = push_vec(&T->sep, &T->nsep, &T->scap, G->sep);
        push_node(T, leaf.kind, leaf.a, leaf.b);
        return WC_OK;
    }
    p = plane_index(T, G->plane);
    push_node(T, WC_NODE_SPLIT, p, 0);
    for (k = 0; k < 3; k++)
        _wc_region3_init(part + k);
    _wc_region3_split(part, R, T->planes + 3 * p);
    for (k = 0; k < 3; k++)
        parts += part[k].dim >= 0;
    if (parts < 2 || depth > 3 * T->nplanes + 3)
        status = _wc_setcert_bug(err, "certificate", "cuts a region by a "
                                 "plane that misses it");
    for (k = 0; k < 3 && status == WC_OK; k++)
        status = grow(T, G, part + k, depth + 1, err);
    for (k = 0; k < 3; k++)
        _wc_region3_clear(part + k);
    return status;
}

/* T->basis := the first three independent planes of prefer (np), then
   of the coordinate planes.  */
static void
choose_basis(_wc_settree * T, const fmpz * prefer, slong np)
{
    fmpz h[9], w[3];
    fmpz_t d;
    slong i, k = 0, j;

    fmpz_init(d);
    for (j = 0; j < 9; j++)
        fmpz_init(h + j);
    for (j = 0; j < 3; j++)
        fmpz_init(w + j);
    for (i = 0; i < np + 3 && k < 3; i++)
    {
        if (i < np)
            _fmpz_vec_set(h + 3 * k, prefer + 3 * i, 3);
        else
        {
            _fmpz_vec_zero(h + 3 * k, 3);
            fmpz_one(h + 3 * k + (i - np));
        }
        if (k == 0)
            k += !_fmpz_vec_is_zero(h, 3);
        else if (k == 1)
        {
            _wc_zvec3_cross(w, h, h + 3);
            k += !_fmpz_vec_is_zero(w, 3);
        }
        else
        {
            _wc_zvec3_cross(w, h, h + 3);
            _fmpz_vec_dot(d, w, h + 6, 3);
            k += !fmpz_is_zero(d);
        }
    }
    for (k = 0; k < 3; k++)
        T->basis[k] = plane_index(T, h + 3 * k);
    for (j = 0; j < 9; j++)
        fmpz_clear(h + j);
    for (j = 0; j < 3; j++)
        fmpz_clear(w + j);
    fmpz_clear(d);
}

typedef struct
{
    const fmpz * h;
    slong i;
}
listed_plane;

static int
plane_cmp(const void * x, const void * y)
{
    return _wc_zvec3_cmp(((const listed_plane *) x)->h,
                         ((const listed_plane *) y)->h);
}

/* Sort T's planes and renumber the nodes.  */
static void
sort_tree(_wc_settree * T)
{
    listed_plane * by = flint_malloc(sizeof(listed_plane) * (T->nplanes + 1));
    slong * at = flint_malloc(sizeof(slong) * (T->nplanes + 1)), i;
    fmpz * sorted = _fmpz_vec_init(3 * T->pcap);

    for (i = 0; i < T->nplanes; i++)
    {
        by[i].h = T->planes + 3 * i;
        by[i].i = i;
    }
    qsort(by, T->nplanes, sizeof(listed_plane), plane_cmp);
    for (i = 0; i < T->nplanes; i++)
    {
        at[by[i].i] = i;
        _fmpz_vec_set(sorted + 3 * i, by[i].h, 3);
    }
    for (i = 0; i < T->n; i++)
        if (T->node[i].kind == WC_NODE_SPLIT)
            T->node[i].a = at[T->node[i].a];
    for (i = 0; i < 3; i++)
        T->basis[i] = at[T->basis[i]];
    _fmpz_vec_clear(T->planes, 3 * T->pcap);
    T->planes = sorted;
    flint_free(by);
    flint_free(at);
}

int
_wc_settree_build(_wc_settree * T, const fmpz * prefer, slong np,
                  _wc_settree_classify classify, void * ctx, wc_error_t err)
{
    _wc_region3 R[27];
    grower G;
    slong k;
    int status = WC_OK;

    G.classify = classify;
    G.ctx = ctx;
    G.sum = _fmpz_vec_init(9);
    G.sep = G.sum + 3;
    G.plane = G.sum + 6;
    choose_basis(T, prefer, np);
    for (k = 0; k < 27; k++)
        _wc_region3_init(R + k);
    for (k = 0; k < 9; k++)
        fmpz_set(G.sum + k, T->planes + 3 * T->basis[k / 3] + k % 3);
    _wc_region3_basis(R, G.sum);
    for (k = 0; k < 27 && status == WC_OK; k++)
        status = grow(T, &G, R + k, 0, err);
    for (k = 0; k < 27; k++)
        _wc_region3_clear(R + k);
    _fmpz_vec_clear(G.sum, 9);
    if (status == WC_OK)
        sort_tree(T);
    return status;
}

int
_wc_setcert_in_face(fmpz * plane, const wc_cone_struct * Q, slong f,
                    const _wc_region3 * R)
{
    const wc_face_struct * F = Q->faces + f;
    slong m = fmpz_mat_nrows(Q->ineqs), a, i, j;
    fmpz_t d;
    int tight, out = 0;

    fmpz_init(d);
    for (a = 0; a < m + fmpz_mat_nrows(Q->eqs) && !out; a++)
    {
        const fmpz * h = a < m ? WC_ROW(Q->ineqs, a)
            : WC_ROW(Q->eqs, a - m);

        tight = 1;
        for (j = 0; a < m && j < F->nrays && tight; j++)
        {
            _fmpz_vec_dot(d, h, WC_ROW(Q->rays, F->rays[j]), 3);
            tight = fmpz_is_zero(d);
        }
        for (i = 0; i < R->n && !out; i++)
        {
            _fmpz_vec_dot(d, h, R->r + 3 * i, 3);
            out = tight ? !fmpz_is_zero(d) : fmpz_sgn(d) > 0;
        }
        if (out)
            _fmpz_vec_set(plane, h, 3);
    }
    fmpz_clear(d);
    return !out;
}
