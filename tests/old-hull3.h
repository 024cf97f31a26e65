/* old-hull3.h -- the previous implementation, kept to catch regressions;
   not an independent reference (that is tests/ref-hull3.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The library's former O(k^2) kernel.
   V to H: E := a basis of the null space of rays and lines, H := the
   facet normals (h . g <= 0), possibly repeated.  H to V: the rays and a
   spanning set of the lines of { x : E x = 0, H x <= 0 }.  Outputs are
   (re)initialised here; any input may be NULL.  */

#ifndef WC_OLD_HULL3_H
#define WC_OLD_HULL3_H

#include <flint/fmpq_mat.h>

void old_hull3_v_to_h(fmpq_mat_t E, fmpq_mat_t H, const fmpq_mat_t rays,
                      const fmpq_mat_t lines);
void old_hull3_h_to_v(fmpq_mat_t rays, fmpq_mat_t lines, const fmpq_mat_t E,
                      const fmpq_mat_t H);

#endif
