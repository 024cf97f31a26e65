/* cone3.h -- internal: canonical cones in R^3 straight from the fan.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  A pointed cone of dimension 3 with m extreme rays has
   exactly 2m + 2 faces (the origin, the rays, the facets between
   consecutive rays, itself); these functions write that canonical form
   (cone.h) directly, without the general route's redundancy checks and
   face-lattice closure.  Used by cone.c for d = 3.  */

#ifndef WC_EXACT_CONE3_H
#define WC_EXACT_CONE3_H

#include "exact/cone.h"
#include "exact/fan3.h"

/* C := pos(F's rays) (polar = 0), or its polar { x : h . x <= 0 for the
   rays h of F } (polar = 1).  Returns WC_OK or WC_EINTERNAL (out of
   memory; C left empty).  C->d must be 3.  */
int _wc_cone3_set_fan(wc_cone_t C, const _wc_fan3_t F, int polar);

/* C := R^3, and C := { 0 }.  */
void _wc_cone3_set_space(wc_cone_t C);
void _wc_cone3_set_origin(wc_cone_t C);

/* C := the line through v (3 entries, not all zero).  */
void _wc_cone3_set_line(wc_cone_t C, const fmpz * v);

/* The fast routes of cone.c for d = 3: C := pos(rays) + span(lines), or
   C := { x : eqs x = 0, H x <= 0 }, when the cone is pointed of
   dimension 3, R^3 or (H-representation) the origin; *done is then set
   to 1.  Otherwise *done := 0 and C is untouched (the general route
   applies).  Returns WC_OK or WC_EINTERNAL (err set, out of memory).  */
int _wc_cone3_generators(wc_cone_t C, int * done, const fmpq_mat_t rays,
                         const fmpq_mat_t lines, wc_error_t err);
int _wc_cone3_hrep(wc_cone_t C, int * done, const fmpq_mat_t eqs,
                   const fmpq_mat_t H, wc_error_t err);

#endif
