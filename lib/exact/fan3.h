/* fan3.h -- internal: the O(k log k) exact conversion of a cone in R^3.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  A pointed cone of dimension 3 is a fan around an
   interior point: its m extreme rays, in counterclockwise order around
   that point, and the m facets between cyclically consecutive rays.
   _wc_fan3 finds them, or recognises R^3, in O(k log k) exact integer
   predicates (signs of 3x3 determinants), whatever the angles between
   the generators; every other cone (lower dimension, lineality 1 or 2)
   is left to the general kernel.  */

#ifndef WC_EXACT_FAN3_H
#define WC_EXACT_FAN3_H

#include <flint/fmpz.h>

typedef struct
{
    slong m;
    fmpz * rays;        /* 3m entries, primitive, counterclockwise */
    fmpz * facets;      /* 3m: facet i spans rays i and i + 1 (mod m),
                           primitive outward normals (h . g <= 0) */
}
_wc_fan3_struct;

typedef _wc_fan3_struct _wc_fan3_t[1];

#define WC_FAN3_POINTED 1   /* pointed, dimension 3: the fan is set */
#define WC_FAN3_SPACE 2     /* the cone is R^3 */
#define WC_FAN3_OTHER 0     /* anything else: use the general kernel */
#define WC_FAN3_NOMEM (-1)  /* out of memory */

void _wc_fan3_init(_wc_fan3_t F);
void _wc_fan3_clear(_wc_fan3_t F);

/* Classify pos(G) for the k rows of G (3k entries, primitive integer
   vectors, none zero, no two equal).  Sets F when the answer is
   WC_FAN3_POINTED.  */
int _wc_fan3(_wc_fan3_t F, const fmpz * G, slong k);

#endif
