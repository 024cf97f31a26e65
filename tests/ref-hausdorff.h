/* ref-hausdorff.h -- an independent reference for the directed angular
   distance between cones (wc_cone_directed_angle, lib/float/compare.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Floating point by nature: the answer is a bracket, not a number.  */

#ifndef WC_REF_HAUSDORFF_H
#define WC_REF_HAUSDORFF_H

#include "wrenchcone.h"

/* The angle from the unit vector x to cl B (min over unit b in cl B of
   angle(x, b)), by brute force over B's faces, in doubles; *near (may be
   NULL) receives a unit vector of cl B where it is attained.  INFINITY
   when cl B is {0}.  B is nonempty, in R^3.  */
double ref_angle_to_cone(double * near, const double * x, const wc_cone_t B);

/* A bracket [*lo, *hi] of the directed distance sup { angle(x, cl B) :
   x in cl A, |x| = 1 } by branch and bound over a triangulation of cl A
   on the sphere, refined until *hi - *lo <= tol or maxeval angles were
   computed (then *hi - *lo may be larger: the bracket stays valid).
   at (3 doubles, may be NULL) receives the best x found.  The bracket
   holds up to double rounding (about 1e-12 here).  Both cones nonempty,
   in R^3.  cl A = {0}: 0; cl B = {0} (and not cl A): INFINITY.  Returns
   the number of angles computed.  */
long ref_directed_angle(double * lo, double * hi, double * at,
                        const wc_cone_t A, const wc_cone_t B, double tol,
                        long maxeval);

#endif
