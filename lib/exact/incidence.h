/* incidence.h -- internal: incidences between the cells of an
   arrangement (cells.h) one dimension apart.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  The two chambers beside every sector, the sectors
   around every ray, and the other way round, the two rays bounding every
   sector and the facets of every chamber; all by cell index.  */

#ifndef WC_EXACT_INCIDENCE_H
#define WC_EXACT_INCIDENCE_H

#include "exact/cells.h"

typedef struct
{
    slong * plane;      /* count: a sector's plane, else -1; NULL until
                           built */
    slong * side;       /* 2 count: a sector's chambers on the - and the
                           + side of its plane */
    slong * ray;        /* 2 count: the rays bounding a sector */
    slong * off;        /* count + 1: the sectors around ray r are */
    slong * around;     /* around[off[r] .. off[r + 1]) */
    slong * foff;       /* count + 1: the facets of chamber c are */
    slong * facet;      /* facet[foff[c] .. foff[c + 1]) */
}
_wc_incidence_struct;

typedef _wc_incidence_struct _wc_incidence_t[1];

/* I := nothing built.  */
void _wc_incidence_init(_wc_incidence_t I);
void _wc_incidence_clear(_wc_incidence_t I);

/* I := the incidences of the cells of A.  Returns 0 when some sector
   lacks its two chambers or its two rays (an inconsistent A), else 1.
   Time O(m) per incidence, expected.  */
int _wc_incidence_build(_wc_incidence_t I, const wc_cells_t A);

#endif
