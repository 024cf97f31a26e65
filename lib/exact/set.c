/* set.c -- sets of wrenches as pairwise disjoint NNC cones: from the
   cells of an arrangement, sorted, merged.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A set of cells becomes sign boxes (box.c), each box an NNC cone; the
   extreme rays of a box's closure are looked for among all the rays when
   there are few boxes, else among the rays bounding the box's member
   cells (found through the incidences of cells).  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_mat.h>
#include <flint/fmpq.h>

#include "exact/cone.h"
#include "exact/cells.h"
#include "exact/incidence.h"
#include "exact/box.h"

void
wc_set_init(wc_set_t S)
{
    S->empty = 1;
    S->interior = 0;
    S->npieces = 0;
    S->pieces = NULL;
}

void
wc_set_clear(wc_set_t S)
{
    slong i;

    for (i = 0; i < S->npieces; i++)
        wc_cone_clear(S->pieces + i);
    flint_free(S->pieces);
    wc_set_init(S);
}

void
wc_set_swap(wc_set_t S, wc_set_t T)
{
    wc_set_struct t = *S;

    *S = *T;
    *T = t;
}

int
wc_set_contains(const wc_set_t S, const fmpq * g)
{
    slong i;

    for (i = 0; i < S->npieces; i++)
        if (wc_cone_contains(S->pieces + i, g))
            return 1;
    return 0;
}


static int
mat_cmp(const fmpz_mat_t a, const fmpz_mat_t b)
{
    slong ra = fmpz_mat_nrows(a), rb = fmpz_mat_nrows(b), i, j;
    int c;

    for (i = 0; i < ra && i < rb; i++)
        for (j = 0; j < fmpz_mat_ncols(a); j++)
            if ((c = fmpz_cmp(fmpz_mat_entry(a, i, j),
                              fmpz_mat_entry(b, i, j))) != 0)
                return c;
    return (ra > rb) - (ra < rb);
}

/* Pieces: by decreasing dimension, then the canonical form: rays,
   inequalities, equalities (which make up the closure), then the
   included flags of the faces.  The rest only makes the order total on
   any cones.  */
static int
piece_cmp(const void * p, const void * q)
{
    const wc_cone_struct * a = p, * b = q;
    slong f, i;
    int c;

    if (a->dim != b->dim)
        return a->dim > b->dim ? -1 : 1;
    if ((c = mat_cmp(a->rays, b->rays)) != 0
        || (c = mat_cmp(a->ineqs, b->ineqs)) != 0
        || (c = mat_cmp(a->eqs, b->eqs)) != 0)
        return c;
    for (f = 0; f < a->nfaces && f < b->nfaces; f++)
        if (a->faces[f].included != b->faces[f].included)
            return a->faces[f].included < b->faces[f].included ? -1 : 1;
    if (a->d != b->d)
        return a->d < b->d ? -1 : 1;
    if ((c = mat_cmp(a->lines, b->lines)) != 0)
        return c;
    if (a->nfaces != b->nfaces)
        return a->nfaces < b->nfaces ? -1 : 1;
    for (f = 0; f < a->nfaces; f++)
    {
        const wc_face_struct * x = a->faces + f, * y = b->faces + f;

        if (x->dim != y->dim)
            return x->dim < y->dim ? -1 : 1;
        for (i = 0; i < x->nrays && i < y->nrays; i++)
            if (x->rays[i] != y->rays[i])
                return x->rays[i] < y->rays[i] ? -1 : 1;
        if (x->nrays != y->nrays)
            return x->nrays < y->nrays ? -1 : 1;
    }
    return 0;
}

/* The candidates for the extreme rays of a box.  */
typedef struct
{
    slong * cand;
    slong nc;
    slong * mark;           /* count: stamp when in cand */
    slong stamp;
}
ray_cands;

static void
cand_add(ray_cands * R, slong r)
{
    if (R->mark[r] != R->stamp)
    {
        R->mark[r] = R->stamp;
        R->cand[R->nc++] = r;
    }
}

/* R := the rays bounding the member cells of box x (every extreme ray
   of its closure is one), through the incidences I.  */
static void
box_rays(ray_cands * R, const wc_cells_t A, const _wc_incidence_struct * I,
         const _wc_box_list_struct * B, slong x)
{
    slong i, j;

    R->nc = 0;
    R->stamp++;
    for (i = B->head[x]; i >= 0; i = B->link[i])
        if (A->dim[i] == 1)
            cand_add(R, i);
        else if (A->dim[i] == 2)
        {
            cand_add(R, I->ray[2 * i]);
            cand_add(R, I->ray[2 * i + 1]);
        }
        else if (A->dim[i] == 3)
            for (j = I->foff[i]; j < I->foff[i + 1]; j++)
            {
                cand_add(R, I->ray[2 * I->facet[j]]);
                cand_add(R, I->ray[2 * I->facet[j] + 1]);
            }
}

/* S->pieces := the cones of the boxes of B.  Candidates for the extreme
   rays of a box: all the ray cells, when few boxes make that cheap, else
   the rays bounding the box's member cells.  Returns 0 when A is
   inconsistent, else 1 (*status set).  */
static int
box_pieces(wc_set_t S, int * status, const wc_cells_t A,
           _wc_incidence_t I, const _wc_box_list_t B, wc_error_t err)
{
    slong count = A->count, nrays = 0, i, b;
    slong * rays = flint_malloc(sizeof(slong) * (count + 1));
    ray_cands R = {NULL, 0, NULL, 0};

    for (i = 0; i < count; i++)
        if (A->dim[i] == 1)
            rays[nrays++] = i;
    if (I->plane == NULL && B->nalive * nrays > count * A->nplanes
        && !_wc_incidence_build(I, A))
    {
        flint_free(rays);
        return 0;
    }
    if (I->plane != NULL)
    {
        R.cand = flint_malloc(sizeof(slong) * (nrays + 1));
        R.mark = flint_calloc(count + 1, sizeof(slong));
    }
    S->pieces = flint_malloc(sizeof(wc_cone_struct) * (B->nalive + 1));
    *status = WC_OK;
    for (b = 0; b < B->nalive && *status == WC_OK; b++)
    {
        slong x = B->alive[b];

        if (R.cand != NULL)
            box_rays(&R, A, I, B, x);
        wc_cone_init(S->pieces + b, 3);
        S->npieces++;
        *status = _wc_box_cone(S->pieces + b, A, B->set + x * A->nplanes,
                               R.cand != NULL ? R.cand : rays,
                               R.cand != NULL ? R.nc : nrays, err);
    }
    flint_free(rays);
    flint_free(R.cand);
    flint_free(R.mark);
    return 1;
}

int
wc_set_from_cells(wc_set_t S, const wc_cells_t A, const int * member,
                  wc_error_t err)
{
    slong n = 0, i;
    _wc_incidence_t I;
    _wc_box_list_t B;
    int status = WC_OK, ok;

    wc_set_clear(S);
    for (i = 0; i < A->count; i++)
        n += member[i] != 0;
    if (n == 0)
        return WC_OK;
    _wc_incidence_init(I);
    _wc_box_list_init(B, A);
    ok = _wc_box_list_build(B, I, A, member)
        && box_pieces(S, &status, A, I, B, err);
    _wc_incidence_clear(I);
    _wc_box_list_clear(B);
    if (!ok)
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "internal error: the cells are inconsistent (a "
                            "sector without its two chambers or rays)");
    if (status != WC_OK)
    {
        wc_set_clear(S);
        return status;
    }
    qsort(S->pieces, S->npieces, sizeof(wc_cone_struct), piece_cmp);
    S->empty = 0;
    for (i = 0; i < S->npieces; i++)
        S->interior |= S->pieces[i].dim == 3;
    return WC_OK;
}

void
wc_set_sort(wc_set_t S)
{
    if (S->npieces > 1)
        qsort(S->pieces, S->npieces, sizeof(wc_cone_struct), piece_cmp);
}

/* ---------------------------------------------------------------------
   Merging pieces.  */

/* Merge pieces of S whose union is convex, until none is: the pieces
   from sign boxes follow every plane of the arrangement, also where the
   set does not change across it.  P_i u P_j is a convex NNC cone N iff
   (i) every facet of H = cl conv (P_i u P_j) lies on a plane of the
   arrangement (so every cell is inside H or outside it), (ii) the faces of
   H whose relative-interior point lies in P_i u P_j form an up-set (then
   N, those faces' union, is a convex NNC cone), and (iii) every cell lies
   in N iff it lies in P_i u P_j (both are unions of cells).  Then N
   replaces the two; the pieces stay pairwise disjoint with the same
   union.  */
static int
try_merge(wc_cone_t N, const wc_cone_t A, const wc_cone_t B,
          const wc_cells_t cells, int * ok, wc_error_t err)
{
    slong ra = fmpz_mat_nrows(A->rays), rb = fmpz_mat_nrows(B->rays);
    slong la = fmpz_mat_nrows(A->lines), lb = fmpz_mat_nrows(B->lines);
    slong i, j, k, f;
    fmpq_mat_t R, L;
    fmpq g[3];
    int status;

    *ok = 0;
    fmpq_mat_init(R, ra + rb, 3);
    fmpq_mat_init(L, la + lb, 3);
    for (i = 0; i < ra + rb; i++)
        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(fmpq_mat_entry(R, i, k), i < ra
                          ? fmpz_mat_entry(A->rays, i, k)
                          : fmpz_mat_entry(B->rays, i - ra, k));
    for (i = 0; i < la + lb; i++)
        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(fmpq_mat_entry(L, i, k), i < la
                          ? fmpz_mat_entry(A->lines, i, k)
                          : fmpz_mat_entry(B->lines, i - la, k));
    status = wc_cone_set_generators(N, R, L, err);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
    if (status != WC_OK)
        return status;
    for (i = 0; i < fmpz_mat_nrows(N->ineqs); i++)
        if (wc_cells_plane_index(cells, N->ineqs->rows[i]) < 0)
            return WC_OK;
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    for (f = 0; f < N->nfaces; f++)
    {
        const wc_face_struct * F = N->faces + f;

        for (k = 0; k < 3; k++)
        {
            fmpq_zero(g + k);
            for (j = 0; j < F->nrays; j++)
                fmpq_add_fmpz(g + k, g + k,
                              fmpz_mat_entry(N->rays, F->rays[j], k));
        }
        N->faces[f].included = wc_cone_contains(A, g)
            || wc_cone_contains(B, g);
    }
    *ok = 1;
    /* an up-set: no excluded face above an included one */
    for (f = 0; f < N->nfaces && *ok; f++)
    {
        slong h;

        if (!N->faces[f].included)
            continue;
        for (h = 0; h < N->nfaces && *ok; h++)
        {
            const wc_face_struct * F = N->faces + f, * G = N->faces + h;
            slong a = 0, b = 0;

            if (G->included || G->dim <= F->dim)
                continue;
            while (a < F->nrays && b < G->nrays)
            {
                if (F->rays[a] == G->rays[b])
                    a++;
                b++;
            }
            if (a == F->nrays)
                *ok = 0;
        }
    }
    for (i = 0; i < cells->count && *ok; i++)
    {
        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(g + k, fmpz_mat_entry(cells->point, i, k));
        *ok = wc_cone_contains(N, g)
            == (wc_cone_contains(A, g) || wc_cone_contains(B, g));
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    return WC_OK;
}

int
wc_set_merge(wc_set_t S, const wc_cells_t cells, wc_error_t err)
{
    int changed = 1, ok, status = WC_OK;
    slong i, j;
    wc_cone_t N;

    wc_cone_init(N, 3);
    while (changed && status == WC_OK)
    {
        changed = 0;
        for (i = 0; i < S->npieces && status == WC_OK; i++)
            for (j = i + 1; j < S->npieces && status == WC_OK; j++)
            {
                status = try_merge(N, S->pieces + i, S->pieces + j, cells,
                                   &ok, err);
                if (status != WC_OK || !ok)
                    continue;
                wc_cone_swap(S->pieces + i, N);
                wc_cone_clear(S->pieces + j);
                memmove(S->pieces + j, S->pieces + j + 1,
                        sizeof(wc_cone_struct) * (S->npieces - j - 1));
                S->npieces--;
                changed = 1;
                j = i;      /* piece i grew: try it against all again */
            }
    }
    wc_cone_clear(N);
    if (status == WC_OK)
        wc_set_sort(S);
    return status;
}
