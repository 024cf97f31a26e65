/* cellset.c -- the arrangement of the planes of some cones, and which
   of its cells lie in each cone (cell by cell; cellbits.c does all the
   cells at once).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Membership of a cell is read at its point, so the sets built on it are
   exact.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "analysis/cellset.h"

/* Append the facet and equality normals of C to the rows of A (r used).  */
void
_wc_cellset_add_planes(fmpz_mat_t A, slong * r, const wc_cone_t C)
{
    slong i, k, ni = fmpz_mat_nrows(C->ineqs), ne = fmpz_mat_nrows(C->eqs);

    if (*r + ni + ne > fmpz_mat_nrows(A))
    {
        fmpz_mat_t B;
        slong rows = 2 * (*r + ni + ne) + 16;

        fmpz_mat_init(B, rows, 3);
        for (i = 0; i < *r; i++)
            for (k = 0; k < 3; k++)
                fmpz_swap(fmpz_mat_entry(B, i, k), fmpz_mat_entry(A, i, k));
        fmpz_mat_swap(A, B);
        fmpz_mat_clear(B);
    }
    for (i = 0; i < ni + ne; i++, (*r)++)
        for (k = 0; k < 3; k++)
            fmpz_set(fmpz_mat_entry(A, *r, k), i < ni
                     ? fmpz_mat_entry(C->ineqs, i, k)
                     : fmpz_mat_entry(C->eqs, i - ni, k));
}

/* The first r rows of A, as a matrix of their own (for wc_cells_build).  */
void
_wc_cellset_build(wc_cells_t cells, int * status, fmpz_mat_t A, slong r,
                  wc_error_t err)
{
    fmpz_mat_t B;
    slong i, k;

    if (*status != WC_OK)
        return;
    fmpz_mat_init(B, r, 3);
    for (i = 0; i < r; i++)
        for (k = 0; k < 3; k++)
            fmpz_swap(fmpz_mat_entry(B, i, k), fmpz_mat_entry(A, i, k));
    *status = wc_cells_build(cells, B, err);
    fmpz_mat_clear(B);
}

void
_wc_cellset_point(fmpq * g, const wc_cells_t A, slong i)
{
    slong k;

    for (k = 0; k < 3; k++)
        fmpq_set_fmpz(g + k, fmpz_mat_entry(A->point, i, k));
}

static void
key_init(wc_cone_key * K, const wc_cone_struct * C, const wc_cells_t A)
{
    slong i, k;

    K->C = C;
    K->nf = fmpz_mat_nrows(C->ineqs);
    K->ne = fmpz_mat_nrows(C->eqs);
    K->plane = malloc(sizeof(slong) * (K->nf + K->ne + 1));
    K->orient = malloc(K->nf + K->ne + 1);
    K->top = !C->empty && C->nfaces > 0 && C->faces[C->nfaces - 1].included;
    K->usable = !C->empty;
    if (K->plane == NULL || K->orient == NULL)
    {
        /* out of memory: every cell goes through the face lattice */
        K->nf = K->ne = 0;
        K->usable = 0;
        return;
    }
    for (i = 0; i < K->nf + K->ne; i++)
    {
        const fmpz * h = i < K->nf ? C->ineqs->rows[i]
            : C->eqs->rows[i - K->nf];

        K->plane[i] = wc_cells_plane_index(A, h);
        K->usable = K->usable && K->plane[i] >= 0;
        for (k = 0; k < 3 && fmpz_is_zero(h + k); k++)
            ;
        K->orient[i] = (signed char) (k < 3 ? fmpz_sgn(h + k) : 0);
    }
}

static void
key_clear(wc_cone_key * K)
{
    free(K->plane);
    free(K->orient);
}

/* 1 when cell i of A (point g) lies in K's cone.  */
int
_wc_cone_key_contains(const wc_cone_key * K, const wc_cells_t A, slong i,
                      const fmpq * g)
{
    slong j;
    int strict = 1;

    if (K->C->empty)
        return 0;
    if (!K->usable)
        return wc_cone_contains(K->C, g);
    for (j = 0; j < K->ne; j++)
        if (_wc_cells_sign(A, i, K->plane[K->nf + j]) != 0)
            return 0;
    for (j = 0; j < K->nf; j++)
    {
        int t = K->orient[j] * _wc_cells_sign(A, i, K->plane[j]);

        if (t > 0)
            return 0;
        strict = strict && t < 0;
    }
    return strict ? K->top : wc_cone_contains(K->C, g);
}

wc_cone_key *
_wc_cone_keys_init(const wc_cone_struct * C, slong count, const wc_cells_t A)
{
    wc_cone_key * K = malloc(sizeof(wc_cone_key) * (count + 1));
    slong i;

    if (K == NULL)
        return NULL;
    for (i = 0; i < count; i++)
        key_init(K + i, C + i, A);
    return K;
}

void
_wc_cone_keys_clear(wc_cone_key * K, slong count)
{
    slong i;

    if (K == NULL)
        return;
    for (i = 0; i < count; i++)
        key_clear(K + i);
    free(K);
}

