/* polar3.h -- internal: the polar of a cone of dimension 3 in R^3, by an
   exact randomized linear program.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  For generators G spanning R^3, the polar
   P = { d : d . g >= 0 for every g } is a pointed cone whose dimension is
   3 minus the lineality of pos(G): P = { 0 } (pos(G) = R^3), a ray
   (a half-space), a 2-D wedge pos(v1, v2) (lineality 1), or a cone with
   interior (pos(G) pointed).  _wc_polar3 tells which in O(k) expected
   exact integer operations (a few two-variable linear programs, Seidel's
   randomized incremental method in a chart of P), with the rays or an
   interior point, checked before it answers: an interior point d by
   d . g > 0 for every g; a ray or a wedge by the rows on each facet,
   which must span it as a cone (then pos(G) holds the whole cone the
   facets bound); R^3 by at most eight rows whose positive hull is
   already R^3, which no extreme ray of their polar leaves room for.  */

#ifndef WC_EXACT_POLAR3_H
#define WC_EXACT_POLAR3_H

#include <flint/fmpz.h>

#define WC_POLAR3_NOMEM (-1)    /* out of memory */
#define WC_POLAR3_SPACE 0       /* P = { 0 }: pos(G) = R^3 */
#define WC_POLAR3_RAY 1         /* P = pos(V[0..3)): a half-space */
#define WC_POLAR3_WEDGE 2       /* P = pos(V[0..3), V[3..6)): lineality 1 */
#define WC_POLAR3_POINTED 3     /* V[0..3) = d, d . g > 0 for all g */
#define WC_POLAR3_FAILED 4      /* internal inconsistency (a bug) */

/* Classify pos(G) for the k rows of G (3k entries, none zero), which
   must span R^3.  V has room for 6 entries; the vectors set are
   primitive.  The order in which the rows are taken is a fixed
   pseudo-random permutation: the answer does not depend on it.  */
int _wc_polar3(fmpz * V, const fmpz * G, slong k);

#endif
