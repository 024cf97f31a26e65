/* region3.h -- internal: relatively open pointed cones of R^3 held by the
   extreme rays of their closures, and cutting them by central planes:
   the regions of a set certificate's tree.  Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A region of dimension 3 is the interior of the cone of its rays, listed
   around the cone; of dimension 2 the relative interior of the cone of
   its two rays; of dimension 1 its open ray; of dimension 0 the origin;
   -1 is empty.  Rays are primitive integer vectors.  */

#ifndef WC_EXACT_REGION3_H
#define WC_EXACT_REGION3_H

#include <flint/fmpz.h>

typedef struct
{
    int dim;
    slong n, cap;
    fmpz * r;           /* 3 cap */
}
_wc_region3;

void _wc_region3_init(_wc_region3 * R);     /* empty */
void _wc_region3_clear(_wc_region3 * R);

/* s := the sum of R's rays, a point of R.  */
void _wc_region3_sum(fmpz * s, const _wc_region3 * R);

/* out[9 (s_1 + 1) + 3 (s_2 + 1) + (s_3 + 1)] := {x : sign(h_i . x) =
   s_i} for the three planes h (9 entries), which must be independent.  */
void _wc_region3_basis(_wc_region3 * out, const fmpz * h);

/* out[0], out[1], out[2] := R cut by h . x < 0, = 0, > 0.  */
void _wc_region3_split(_wc_region3 * out, const _wc_region3 * R,
                       const fmpz * h);

#endif
