/* region.h -- internal: the regions of a set certificate's
   tree (region.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  GMP only.  */

#ifndef WC_CHECK_REGION_H
#define WC_CHECK_REGION_H

#include <stddef.h>

#include <gmp.h>

/* A relatively open pointed cone of R^3: dim 0 .. 3 (-1: empty), and the
   extreme rays of its closure, primitive integer vectors, around the
   cone when dim is 3 (consecutive rays, and the last with the first,
   span its facets).  The origin has no rays; an open ray one; an open
   sector two.  */
typedef struct
{
    int dim;
    size_t n, cap;
    mpz_t * r;              /* 3 cap */
}
wc_check_region;

void _wc_check_region_init(wc_check_region * R);     /* empty */
void _wc_check_region_clear(wc_check_region * R);
/* D := R.  1 or -1.  */
int _wc_check_region_copy(wc_check_region * D, const wc_check_region * R);
/* out[9 (s_1 + 1) + 3 (s_2 + 1) + (s_3 + 1)] := the region where
   sign(h_i . x) = s_i (s_i in -1, 0, 1) for the planes h_1, h_2, h_3 (9
   entries): the 27 relatively open faces of the simplicial fan they cut.
   1, 0 when the planes are dependent, -1 when out of memory.  */
int _wc_check_region_basis(wc_check_region * out, mpz_t * h);
/* out[0], out[1], out[2] := R cut by h . x < 0, = 0, > 0 (dim -1 when
   empty).  1 or -1.  */
int _wc_check_region_split(wc_check_region * out, const wc_check_region * R,
                           mpz_t * h);

#endif
