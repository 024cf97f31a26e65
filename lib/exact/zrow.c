/* zrow.c -- rows of integer 3-vectors in lexicographic order.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "exact/zrow.h"

int
_wc_zrow_cmp(const void * a, const void * b)
{
    const fmpz * x = ((const _wc_zrow *) a)->v;
    const fmpz * y = ((const _wc_zrow *) b)->v;
    slong j;
    int c;

    for (j = 0; j < 3; j++)
        if ((c = fmpz_cmp(x + j, y + j)) != 0)
            return c;
    return 0;
}
