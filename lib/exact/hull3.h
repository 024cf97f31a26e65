/* hull3.h -- exact cone conversion in dimension 3, without cddlib.
   Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Same contract as cddbridge.h, for d = 3 only: outputs are
   (re)initialised by the callee and cleared by the caller.  Redundant
   output rows are possible; callers canonicalise.  */

#ifndef WC_HULL3_H
#define WC_HULL3_H

#include <flint/fmpz_mat.h>
#include <flint/fmpq_mat.h>

#include "core/error.h"

int _wc_hull3_v_to_h(fmpq_mat_t E, fmpq_mat_t H, const fmpq_mat_t rays,
                     const fmpq_mat_t lines, wc_error_t err);
int _wc_hull3_h_to_v(fmpq_mat_t rays, fmpq_mat_t lines, const fmpq_mat_t E,
                     const fmpq_mat_t H, wc_error_t err);

/* G := the rows of lines, each followed by its negative, then the rows
   of rays (either may be NULL), as primitive integer vectors without
   zero rows or repeats (first occurrences, in order): the first *k rows
   of G, which is (re)initialised here with room to spare.  Returns 1, or
   0 when out of memory.  */
int _wc_hull3_generators(fmpz_mat_t G, slong * k, const fmpq_mat_t rays,
                         const fmpq_mat_t lines);

#endif
