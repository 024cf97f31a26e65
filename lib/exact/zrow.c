/* zrow.c -- rows of integer 3-vectors in lexicographic order.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "exact/vec3.h"
#include "exact/zrow.h"

int
_wc_zrow_cmp(const void * a, const void * b)
{
    return _wc_zvec3_cmp(((const _wc_zrow *) a)->v, ((const _wc_zrow *) b)->v);
}
