/* incidence.c -- incidences between the cells of an arrangement one
   dimension apart.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdint.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "exact/hash.h"
#include "exact/incidence.h"

void
_wc_incidence_init(_wc_incidence_t I)
{
    I->plane = NULL;
    I->side = NULL;
    I->ray = NULL;
    I->off = NULL;
    I->around = NULL;
    I->foff = NULL;
    I->facet = NULL;
}

void
_wc_incidence_clear(_wc_incidence_t I)
{
    flint_free(I->plane);
    flint_free(I->side);
    flint_free(I->ray);
    flint_free(I->off);
    flint_free(I->around);
    flint_free(I->foff);
    flint_free(I->facet);
    _wc_incidence_init(I);
}

/* The hash of cell i's key.  */
static uint64_t
key_hash(const uint64_t * k, slong kw)
{
    return _wc_hash_bytes((const unsigned char *) k,
                          (slong) sizeof(uint64_t) * kw);
}

/* The cell of dimension d with signs t, or -1; slot: a hash table of
   size slots on the cells of dimensions 2 and 3, h their hashes; tk:
   scratch for t's key.  */
static slong
find_cell(const wc_cells_t A, const slong * slot, slong size,
          const uint64_t * h, const signed char * t, uint64_t * tk, slong d)
{
    slong kw = A->kw, j;
    uint64_t g;

    wc_cells_pack(tk, t, A->nplanes);
    g = key_hash(tk, kw);
    for (j = (slong) (g & (size - 1)); slot[j] >= 0; j = (j + 1) & (size - 1))
        if (h[slot[j]] == g && A->dim[slot[j]] == d
            && memcmp(_wc_cells_key(A, slot[j]), tk,
                      sizeof(uint64_t) * kw) == 0)
            return slot[j];
    return -1;
}

/* The chambers beside a sector: its signs with its plane's turned to -
   and +.  The sectors around ray r: on each plane p through r, the two
   beside it have r's signs but for the other planes q through r, where
   they take the sign of h_q . (+-h_p x r).  Returns 0 when some sector
   lacks its two chambers or its two rays (an inconsistent A).  */
int
_wc_incidence_build(_wc_incidence_t I, const wc_cells_t A)
{
    slong m = A->nplanes, count = A->count, size, i, j, q, p, side, n = 0;
    slong alloc = 16;
    slong * slot;
    uint64_t * h = flint_malloc(sizeof(uint64_t) * (count + 1));
    signed char * t = flint_malloc(m + 1);
    signed char * row = flint_malloc(m + 1);
    uint64_t * tk = flint_malloc(sizeof(uint64_t) * (A->kw + 1));
    fmpz * d = _fmpz_vec_init(3);
    fmpz_t x;
    int ok = 1;

    fmpz_init(x);
    I->plane = flint_malloc(sizeof(slong) * (count + 1));
    I->side = flint_malloc(sizeof(slong) * 2 * (count + 1));
    I->ray = flint_malloc(sizeof(slong) * 2 * (count + 1));
    I->off = flint_malloc(sizeof(slong) * (count + 1));
    I->around = flint_malloc(sizeof(slong) * alloc);
    I->foff = flint_calloc(count + 2, sizeof(slong));
    size = _wc_hash_size(2 * count + 2);
    slot = flint_malloc(sizeof(slong) * size);
    for (j = 0; j < size; j++)
        slot[j] = -1;
    for (i = 0; i < count; i++)
        if (A->dim[i] >= 2)
        {
            h[i] = key_hash(_wc_cells_key(A, i), A->kw);
            for (j = (slong) (h[i] & (size - 1)); slot[j] >= 0;
                 j = (j + 1) & (size - 1))
                ;
            slot[j] = i;
        }
    for (i = 0; i < count; i++)
    {
        wc_cells_signs(row, A, i);
        I->side[2 * i] = I->side[2 * i + 1] = I->plane[i] = -1;
        I->ray[2 * i] = I->ray[2 * i + 1] = -1;
        I->off[i] = n;
        if (A->dim[i] == 2)
        {
            memcpy(t, row, m);
            for (q = 0; q < m && t[q] != 0; q++)
                ;
            I->plane[i] = q;
            for (side = 0; side < 2; side++)
            {
                t[q] = (signed char) (2 * side - 1);
                I->side[2 * i + side] = find_cell(A, slot, size, h, t, tk, 3);
                ok &= I->side[2 * i + side] >= 0;
            }
        }
        else if (A->dim[i] == 1)
            for (p = 0; p < m; p++)
            {
                if (row[p] != 0)
                    continue;
                _wc_zvec3_cross(d, WC_ROW(A->planes, p),
                                WC_ROW(A->point, i));
                for (side = -1; side <= 1; side += 2)
                {
                    slong c;

                    memcpy(t, row, m);
                    for (q = 0; q < m; q++)
                        if (row[q] == 0 && q != p)
                            t[q] = (signed char) (side * _wc_zvec3_dot_sgn(
                                WC_ROW(A->planes, q), d, x));
                    c = find_cell(A, slot, size, h, t, tk, 2);
                    if (c < 0)
                    {
                        ok = 0;
                        continue;
                    }
                    if (n == alloc)
                    {
                        alloc *= 2;
                        I->around = flint_realloc(I->around,
                                                  sizeof(slong) * alloc);
                    }
                    I->around[n++] = c;
                }
            }
    }
    I->off[count] = n;

    /* The other way round.  */
    for (i = 0; i < count; i++)
        for (j = I->off[i]; j < I->off[i + 1]; j++)
        {
            slong s = I->around[j];

            if (I->ray[2 * s] < 0)
                I->ray[2 * s] = i;
            else if (I->ray[2 * s + 1] < 0)
                I->ray[2 * s + 1] = i;
            else
                ok = 0;
        }
    for (i = 0; i < count; i++)
        if (A->dim[i] == 2)
        {
            ok &= I->ray[2 * i + 1] >= 0;
            for (side = 0; side < 2 && ok; side++)
                I->foff[I->side[2 * i + side] + 2]++;
        }
    for (i = 0; i < count; i++)
        I->foff[i + 2] += I->foff[i + 1];
    I->facet = flint_malloc(sizeof(slong) * (I->foff[count + 1] + 1));
    for (i = 0; i < count && ok; i++)
        if (A->dim[i] == 2)
            for (side = 0; side < 2; side++)
                I->facet[I->foff[I->side[2 * i + side] + 1]++] = i;

    flint_free(slot);
    flint_free(h);
    flint_free(t);
    flint_free(row);
    flint_free(tk);
    _fmpz_vec_clear(d, 3);
    fmpz_clear(x);
    return ok;
}
