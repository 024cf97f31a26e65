/* arrangement.h -- internal: a central arrangement of planes in R^3, its
   lines, and a walk over all its faces.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  Planes h . x = 0 through the origin cut R^3 into
   relatively open faces: the origin, the rays where two planes meet, the
   sectors (open arcs of a plane between consecutive rays on it) and the
   chambers.  The walk goes around each plane in turn and reports every
   face with its sign vector (sign(h_q . x) for every plane q) and the
   planes whose sign changed since the previous report, so that a caller
   keeping something up to date per plane pays only for those.

   Order of the reports, which callers' outputs depend on: the origin;
   then for each plane p in order, for each arc j = 0, 1, ... of p: its
   sector, the chamber beside it on the - side of h_p, the chamber on the
   + side, then the ray ending the arc, unless reported before.  The rays
   of p, in counter-clockwise order seen from h_p, start at the
   canonical direction of the line of p with the smallest id.  The origin,
   every ray and every sector are reported once; a chamber once beside
   each of its facets.  */

#ifndef WC_EXACT_ARRANGEMENT_H
#define WC_EXACT_ARRANGEMENT_H

#include <flint/fmpz_mat.h>

#include "core/error.h"
#include "exact/zvec3set.h"

typedef struct
{
    slong m;                            /* planes */
    const fmpz_mat_struct * planes;     /* m x 3, the caller's */
    _wc_zvec3_set_t lines;              /* the canonical directions of
                                           the lines where two planes
                                           meet; ids by first meeting
                                           (plane pairs p < q in order) */
    slong * loff;                       /* m + 1 */
    slong * lon;                        /* the lines on plane p:
                                           lon[loff[p] .. loff[p + 1]),
                                           ascending */
    slong * poff;                       /* lines + 1 */
    slong * pon;                        /* the planes through line l:
                                           pon[poff[l] .. poff[l + 1]),
                                           ascending */
}
_wc_arrangement_struct;

typedef _wc_arrangement_struct _wc_arrangement_t[1];

/* A := the arrangement of the rows of planes (nonzero, pairwise not
   parallel, any scale; kept by reference until A is cleared).  Time
   O(m^2 log m).  Returns WC_OK, or WC_EINTERNAL (err set) when two rows
   are parallel or zero; A must be cleared either way.  */
int _wc_arrangement_init(_wc_arrangement_t A, const fmpz_mat_t planes,
                         wc_error_t err);
void _wc_arrangement_clear(_wc_arrangement_t A);

#define _wc_arrangement_nlines(A) ((A)->lines->count)
#define _wc_arrangement_nlines_on(A, p) ((A)->loff[(p) + 1] - (A)->loff[p])

/* The order by angle in [0, pi) of two directions (ax, ay) and (bx, by)
   in a plane's coordinates, each turned into y > 0 or y = 0 < x:
   negative when b is counter-clockwise of a, positive when a is
   counter-clockwise of b, 0 when they are parallel.  Words when the
   entries are small, else fmpz.  */
int _wc_angle_cmp(const fmpz_t ax, const fmpz_t ay, const fmpz_t bx,
                  const fmpz_t by);

/* One face, as reported by the walk; valid during the report only.  */
typedef struct
{
    int dim;                    /* 0 origin, 1 ray, 2 sector, 3 chamber */
    const fmpz * point;         /* dimensions 0 to 2: a primitive integer
                                   point of the face (the sum of the rays
                                   bounding a sector); dimension 3: the
                                   point of the sector beside it (how far
                                   to step off it is the caller's) */
    slong plane;                /* dimensions 2, 3: the sector's plane p,
                                   else -1 */
    const fmpz * normal;        /* dimensions 2, 3: h_p */
    int side;                   /* dimension 3: the sign of h_p on it */
    const signed char * sign;   /* m: the sign vector of the face */
    const slong * changed;      /* the planes whose sign changed since the
                                   previous report (all at the first),
                                   each once */
    slong nchanged;
}
_wc_face_struct;

/* A report; a status other than WC_OK ends the walk with it.  */
typedef int (* _wc_face_fn)(void * data, const _wc_face_struct * F,
                            wc_error_t err);

/* Report every face of A to visit, in the order above.  Time O(m^2 log m)
   besides the reports; O(m) sign updates per plane.  Returns WC_OK, the
   first other status of visit, or WC_EINTERNAL (err set) when a plane
   holds no line.  */
int _wc_arrangement_walk(const _wc_arrangement_t A, _wc_face_fn visit,
                         void * data, wc_error_t err);

#endif
