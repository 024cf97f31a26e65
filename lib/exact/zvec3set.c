/* zvec3set.c -- integer 3-vectors up to scale, and sets of them.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdint.h>

#include <flint/fmpz_vec.h>

#include "exact/hash.h"
#include "exact/zvec3set.h"

static uint64_t
zvec3_hash(const fmpz * v)
{
    uint64_t h = 0;
    slong j;

    for (j = 0; j < 3; j++)
        h = _wc_hash_mix64(h ^ (uint64_t) fmpz_fdiv_ui(v + j,
                                                       UWORD(4294967291)));
    return h;
}

/* The slot holding v, or the empty slot where it belongs.  */
static slong
zvec3_set_find(const _wc_zvec3_set_t S, const fmpz * v)
{
    slong i;

    for (i = (slong) (zvec3_hash(v) & (S->size - 1)); S->slot[i] >= 0;
         i = (i + 1) & (S->size - 1))
        if (_fmpz_vec_equal(_wc_zvec3_set_entry(S, S->slot[i]), v, 3))
            break;
    return i;
}

void
_wc_zvec3_set_init(_wc_zvec3_set_t S, slong expect)
{
    slong i;

    S->count = 0;
    S->alloc = FLINT_MAX(expect, 1);
    S->size = _wc_hash_size(2 * S->alloc + 2);
    S->slot = flint_malloc(sizeof(slong) * S->size);
    for (i = 0; i < S->size; i++)
        S->slot[i] = -1;
    S->v = _fmpz_vec_init(3 * S->alloc);
}

void
_wc_zvec3_set_clear(_wc_zvec3_set_t S)
{
    flint_free(S->slot);
    _fmpz_vec_clear(S->v, 3 * S->alloc);
}

/* Twice the room, the table rebuilt.  */
static void
zvec3_set_grow(_wc_zvec3_set_t S)
{
    slong i;
    fmpz * v = _fmpz_vec_init(6 * S->alloc);

    _fmpz_vec_swap(v, S->v, 3 * S->count);
    _fmpz_vec_clear(S->v, 3 * S->alloc);
    S->v = v;
    S->alloc *= 2;
    flint_free(S->slot);
    S->size = _wc_hash_size(2 * S->alloc + 2);
    S->slot = flint_malloc(sizeof(slong) * S->size);
    for (i = 0; i < S->size; i++)
        S->slot[i] = -1;
    for (i = 0; i < S->count; i++)
        S->slot[zvec3_set_find(S, _wc_zvec3_set_entry(S, i))] = i;
}

slong
_wc_zvec3_set_id(_wc_zvec3_set_t S, const fmpz * v)
{
    slong i = zvec3_set_find(S, v);

    if (S->slot[i] >= 0)
        return S->slot[i];
    if (S->count == S->alloc)
    {
        zvec3_set_grow(S);
        i = zvec3_set_find(S, v);
    }
    _fmpz_vec_set(_wc_zvec3_set_entry(S, S->count), v, 3);
    S->slot[i] = S->count;
    return S->count++;
}
