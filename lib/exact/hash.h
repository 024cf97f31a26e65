/* hash.h -- internal: the hash functions of the exact layer's tables.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  The tables use open addressing with linear probing on
   a power-of-two number of slots; keys are always compared in full, so
   the hash only has to spread them.  */

#ifndef WC_EXACT_HASH_H
#define WC_EXACT_HASH_H

#include <stdint.h>

#include <flint/flint.h>

/* A bijective mix of the bits of z (the splitmix64 finaliser).  */
uint64_t _wc_hash_mix64(uint64_t z);

/* A hash of len bytes.  */
uint64_t _wc_hash_bytes(const unsigned char * k, slong len);

/* The number of slots for a table of up to n / 2 keys: a power of two,
   at least n and at least 16.  */
slong _wc_hash_size(slong n);

#endif
