/* zrows3.h -- internal: integer rows in R^3 for the direct route's fast
   path (direct3.c): sorting, a cheap certificate of R^3 (their content is
   vec3.h's).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  Rows are 3 consecutive fmpz entries; entries that fit
   a word take word arithmetic, every other entry the same computation in
   fmpz, with the same result.  */

#ifndef WC_ANALYSIS_ZROWS3_H
#define WC_ANALYSIS_ZROWS3_H

#include <flint/fmpz.h>

/* A[0..k) := its distinct nonzero rows, sorted lexicographically, in
   place; returns their number.  */
slong _wc_zrows3_distinct(fmpz * A, slong k);

/* 1 when the k rows of A (none zero) certifiably generate R^3 as a cone:
   three independent rows a, b, c taken at spread positions and a row in
   the interior of -pos(a, b, c), found in O(k) sign tests; 0 when no
   such rows were found (nothing is decided then).  */
int _wc_zrows3_span_space(const fmpz * A, slong k);

#endif
