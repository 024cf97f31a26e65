/* box.h -- internal: sign boxes, the pieces of a union of cells of an
   arrangement (cells.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  A box has a sign set per plane, a mask of bits
   1 << (sign + 1), one of {-}, {0}, {+}, {-,0}, {0,+} or {-,0,+}; it is
   a convex NNC cone.  A box list keeps every box exactly the union of the
   member cells whose sign vectors it holds, so that the boxes are
   pairwise disjoint and cover the members.  */

#ifndef WC_EXACT_BOX_H
#define WC_EXACT_BOX_H

#include <stdint.h>

#include "core/error.h"
#include "exact/cone.h"
#include "exact/cells.h"
#include "exact/incidence.h"

typedef struct
{
    slong m;
    slong n;                /* boxes made */
    slong alloc;
    unsigned char * set;    /* n x m: the sign sets */
    uint64_t * hash;        /* n: the sum of one word per (plane, set) */
    slong * head;           /* n: the first member cell of each box */
    slong * tail;           /* n: the last one */
    slong * link;           /* count: the next member cell of its box */
    uint64_t * word;        /* 8 m: the word of (plane q, set s) at 8q + s */
    slong * alive;          /* the boxes in use, in creation order */
    slong nalive;
}
_wc_box_list_struct;

typedef _wc_box_list_struct _wc_box_list_t[1];

void _wc_box_list_init(_wc_box_list_t B, const wc_cells_t A);
void _wc_box_list_clear(_wc_box_list_t B);

/* B := boxes for the cells i of A with member[i] != 0 (at least one),
   split top-down and merged bottom-up (see box.c); B->alive lists them.
   I is built when needed (I->plane != NULL then).  Returns 0 when A is
   inconsistent, else 1.  */
int _wc_box_list_build(_wc_box_list_t B, _wc_incidence_t I,
                       const wc_cells_t A, const int * member);

/* C := the box of A with sign sets set, as an NNC cone.  cand[0 .. nc):
   ray cells among which are all the rays of the arrangement on two
   constraining planes in the closed box (the extreme rays of its
   closure); others are filtered out.  Returns WC_OK, or WC_EINTERNAL
   (err set).  */
int _wc_box_cone(wc_cone_t C, const wc_cells_t A, const unsigned char * set,
                 const slong * cand, slong nc, wc_error_t err);

#endif
