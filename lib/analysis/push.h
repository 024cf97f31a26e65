/* push.h -- pushing regions of a frictionless finger (wrenchcone(1), push regions).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A frictionless finger pushing the workpiece at a boundary point q along
   the inward normal d applies the wrench lambda (d, (q - o) x d),
   lambda > 0, o the centre of mass.  For a set of wrenches given by a
   membership test, the pushing region is the set of boundary points whose
   push wrench lies in the set.

   Polygon (vertices as in the file, either orientation): edge k runs from
   vertex k to vertex k + 1 (cyclically), q = v_k + s (v_{k+1} - v_k),
   s in [0, 1], d the inward normal of the edge.  The push wrench is an
   affine function of s, so each plane h . w = 0 of the arrangement is
   crossed at most once per edge, at a rational s; between crossings
   membership is constant.  The region on an edge is a union of maximal
   intervals [from, to] with rational ends, each end open or closed; a
   single point is an interval with from = to, both closed.  Vertices
   belong to both edges but have no normal: an edge's interval ends at a
   vertex are decided by the edge's own push wrench there (the limit
   along the edge), so a vertex may be in the region of one edge and not
   of the other.

   Disk (centre c, radius R): q = c + R u, d = -u for a unit direction u.
   The push wrench -(u_x, u_y, (c - o) x u) is linear in u, so every
   crossing is at a rational direction (a primitive integer vector).  The
   region is a union of maximal counter-clockwise arcs from one direction
   to another, each end open or closed.  A single direction is an arc
   with from = to, both closed.  The whole circle is one arc with
   full = 1, from = to = (1, 0), both ends closed.  The circle minus one
   direction d is one arc from d to d with both ends open (full = 0).  */

#ifndef WC_PUSH_H
#define WC_PUSH_H

#include <flint/fmpz_mat.h>
#include <flint/fmpq.h>

#include "core/error.h"
#include "core/problem.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct
{
    slong edge;             /* polygon: 0-based edge; disk: -1 */
    fmpq_t from, to;        /* polygon: parameters, 0 <= from <= to <= 1 */
    fmpz dfrom[2], dto[2];  /* disk: primitive integer directions */
    int from_closed, to_closed;
    int full;               /* disk: the whole circle */
}
wc_push_interval_struct;

typedef struct
{
    wc_shape_kind kind;     /* WC_SHAPE_POLYGON or WC_SHAPE_DISK */
    slong count;
    wc_push_interval_struct * iv;   /* polygon: by edge, then by from;
                                       disk: by the angle of from in
                                       [0, 2 pi) measured from (1, 0) */
}
wc_push_struct;

typedef wc_push_struct wc_push_t[1];

void wc_push_init(wc_push_t R);
void wc_push_clear(wc_push_t R);

/* Membership test: 1 when the wrench g (3 entries) lies in the set, 0
   when not, negative on failure (which wc_push_regions passes on as
   WC_EINTERNAL).  */
typedef int (* wc_member_fn)(const fmpq * g, void * ctx);

/* R := the pushing region of the set tested by in (with ctx) for the
   shape of P (a polygon or a disk).  planes (m x 3, integer normals) must
   be such that the set is a union of cells of their arrangement (every
   facet and equality normal of every cone the set is built from), so that
   membership can only change where the push wrench crosses one of them.
   The set is a cone: membership of lambda w does not depend on
   lambda > 0.  Returns WC_OK, WC_EINPUT (err set) when P has no shape,
   WC_EINTERNAL when in fails.  */
int wc_push_regions(wc_push_t R, const wc_problem_t P,
                    const fmpz_mat_t planes, wc_member_fn in, void * ctx,
                    wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
