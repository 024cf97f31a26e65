/* hash.c -- the hash functions of the exact layer's tables.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <string.h>

#include "exact/hash.h"

uint64_t
_wc_hash_mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

uint64_t
_wc_hash_bytes(const unsigned char * k, slong len)
{
    uint64_t h = UINT64_C(0x9e3779b97f4a7c15) ^ (uint64_t) len, w;
    slong i;

    for (i = 0; i + 8 <= len; i += 8)
    {
        memcpy(&w, k + i, 8);
        h = _wc_hash_mix64(h ^ w) + UINT64_C(0x9e3779b97f4a7c15);
    }
    if (i < len)
    {
        w = 0;
        memcpy(&w, k + i, len - i);
        h = _wc_hash_mix64(h ^ w) + UINT64_C(0x9e3779b97f4a7c15);
    }
    return _wc_hash_mix64(h);
}

slong
_wc_hash_size(slong n)
{
    slong s = 16;

    while (s < n)
        s *= 2;
    return s;
}
