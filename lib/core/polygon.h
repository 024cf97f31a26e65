/* polygon.h -- exact plane geometry for the problem's shape.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  A point is two consecutive fmpq.  */

#ifndef WC_POLYGON_H
#define WC_POLYGON_H

#include <flint/flint.h>
#include <flint/fmpq.h>

#ifdef __cplusplus
extern "C" {
#endif

/* What _wc_polygon_check found.  */
typedef enum
{
    WC_POLYGON_SIMPLE = 0,
    WC_POLYGON_COINCIDE,        /* vertices i and j = i + 1 coincide */
    WC_POLYGON_COLLINEAR,       /* vertices i, j = i + 1, j + 1 collinear */
    WC_POLYGON_CROSS,           /* edges i and j cross */
    WC_POLYGON_TOUCH,           /* edges i and j touch */
    WC_POLYGON_ZERO_AREA
}
wc_polygon_fault;

int _wc_point_equal(const fmpq * a, const fmpq * b);

/* p on the closed segment [a, b].  */
int _wc_on_segment(const fmpq * p, const fmpq * a, const fmpq * b);

/* Is the polygon v[0..m) (m >= 3) simple?  The first fault in the order
   the enum lists them, with the vertex or edge indices i and j (indices
   taken mod m); *turn := +1 counter-clockwise, -1 clockwise, 0 when not
   simple.  */
int _wc_polygon_check(int * turn, slong * i, slong * j, const fmpq * v,
                      slong m);

#ifdef __cplusplus
}
#endif

#endif
