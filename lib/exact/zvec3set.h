/* zvec3set.h -- internal: sets of integer 3-vectors up to scale (lines,
   planes, rays) with ids.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  A ray has one primitive integer vector; a line (or a
   plane through the origin, by its normal) has one canonical vector: the
   primitive one whose first nonzero entry is positive (vec3.h makes both,
   _wc_zvec3_primitive and _wc_zvec3_canonical).  A set gives each
   distinct vector an id, in the order the vectors were first added, so
   that ids do not depend on the hash.  */

#ifndef WC_EXACT_ZVEC3SET_H
#define WC_EXACT_ZVEC3SET_H

#include <flint/fmpz.h>

#include "exact/vec3.h"

typedef struct
{
    slong count;
    slong alloc;        /* vectors v has room for */
    slong size;         /* hash slots, a power of two above 2 count */
    slong * slot;       /* an id or -1 */
    fmpz * v;           /* alloc x 3: vector id at v + 3 id */
}
_wc_zvec3_set_struct;

typedef _wc_zvec3_set_struct _wc_zvec3_set_t[1];

/* An empty set with room for expect vectors before it grows.  */
void _wc_zvec3_set_init(_wc_zvec3_set_t S, slong expect);
void _wc_zvec3_set_clear(_wc_zvec3_set_t S);

/* The id of v, which is added when new.  */
slong _wc_zvec3_set_id(_wc_zvec3_set_t S, const fmpz * v);

/* The vector with id i.  */
#define _wc_zvec3_set_entry(S, i) ((S)->v + 3 * (i))

#endif
