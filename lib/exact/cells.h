/* cells.h -- the cells of a central arrangement of planes in R^3, and
   sets of wrenches as pairwise disjoint NNC pieces (wrenchcone(1), stability).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Planes through the origin h . x = 0 cut R^3 into relatively open cells:
   the origin, open rays, open two-dimensional sectors and open
   three-dimensional chambers.  The three coordinate planes are always
   added, so that the planes span R^3 and every cell is a pointed cone
   (the origin is a cell of its own).  Two points lie in the same cell iff
   they have the same sign vector (sign(h_p . x) for every plane p).

   Every NNC cone whose facet normals and equalities are among the planes
   is a union of cells; so are unions, intersections and complements of
   such cones.  A set is reported as a list of pieces: pairwise disjoint
   convex NNC cones in canonical form (wc_cone_t).  A piece is a "sign
   box": the points whose sign for each plane p lies in a set A_p that is
   one of {-}, {0}, {+}, {-,0}, {0,+} or {-,0,+} -- a convex NNC cone.
   The boxes come top-down: the tightest box holding the member cells is a
   piece when it holds no other cell, else it is split along a plane where
   a member cell meets a non-member one; then two boxes that differ in one
   plane only, where the union of their sign sets is again one of the six,
   merge.  Every box is exactly the union of the member cells it holds.  A
   convex cone's cells come out as one piece.  */

#ifndef WC_CELLS_H
#define WC_CELLS_H

#include <stdint.h>

#include <flint/fmpz_mat.h>

#include "core/error.h"
#include "exact/cone.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct
{
    slong nplanes;
    fmpz_mat_t planes;      /* nplanes x 3: distinct planes, each the
                               primitive integer normal whose first nonzero
                               entry is positive, sorted lexicographically;
                               the coordinate planes are among them */
    slong count;            /* cells */
    fmpz_mat_t point;       /* count x 3: a primitive integer point in each
                               cell (the zero vector for the origin) */
    slong * dim;            /* count: 0, 1, 2 or 3 */
    slong kw;               /* words per key */
    uint64_t * key;         /* count x kw: the sign vectors as keys */
}
wc_cells_struct;

typedef wc_cells_struct wc_cells_t[1];

/* A cell's sign vector (sign(h_p . point_i) for every plane p) is kept as
   a key: sign + 1 in two bits per plane, WC_CELLS_KEY_PLANES planes to a
   64-bit word, the first plane in the highest bits of the first word, the
   bits past the last plane zero.  Comparing two keys word by word as
   unsigned integers orders them as their sign vectors (- < 0 < +); equal
   keys are equal sign vectors.  Read them with _wc_cells_sign (one plane)
   or wc_cells_signs (the whole vector).  */
#define WC_CELLS_KEY_PLANES 32

/* Words of a key for m planes.  */
#define WC_CELLS_KEY_WORDS(m) \
    (((m) + WC_CELLS_KEY_PLANES - 1) / WC_CELLS_KEY_PLANES)

/* sign(h_p . point_i): -1, 0 or 1.  */
static inline int
_wc_cells_sign(const wc_cells_struct * A, slong i, slong p)
{
    ulong q = (ulong) p;

    return (int) ((A->key[i * A->kw + q / WC_CELLS_KEY_PLANES]
                   >> (62 - 2 * (q % WC_CELLS_KEY_PLANES))) & 3) - 1;
}

/* The key of cell i (A->kw words).  */
static inline const uint64_t *
_wc_cells_key(const wc_cells_struct * A, slong i)
{
    return A->key + i * A->kw;
}

/* s[0 .. nplanes) := the sign vector of cell i.  */
void wc_cells_signs(signed char * s, const wc_cells_t A, slong i);

/* key[0 .. WC_CELLS_KEY_WORDS(m)) := the key of the sign vector s (m
   entries, each -1, 0 or 1).  */
void wc_cells_pack(uint64_t * key, const signed char * s, slong m);

void wc_cells_init(wc_cells_t A);
void wc_cells_clear(wc_cells_t A);

/* A := the cells of the arrangement of the planes normals (rows, m x 3;
   zero rows are ignored, parallel rows give one plane) together with the
   three coordinate planes.  Every cell appears exactly once.  Cells are
   sorted by dimension, then by sign vector (- < 0 < +).  Time
   O(m^3) at worst for m distinct planes.  Returns WC_OK (or WC_EINTERNAL
   when out of memory).  */
int wc_cells_build(wc_cells_t A, const fmpz_mat_t normals, wc_error_t err);

/* Index of the plane with normal h (3 entries, nonzero; any multiple,
   either sign) in A, or -1 when it is not one of A's planes.  */
slong wc_cells_plane_index(const wc_cells_t A, const fmpz * h);

/* Index of the cell holding x (3 entries), by its sign vector.  */
slong wc_cells_locate(const wc_cells_t A, const fmpq * x);

/* Index of the cell of dimension dim with sign vector sign (nplanes
   entries), or -1 when there is none (or, with more than 256 planes,
   when out of memory).  O(nplanes log count).  */
slong wc_cells_find(const wc_cells_t A, slong dim, const signed char * sign);

/* The extreme rays of every cell's closure, as indices of the
   one-dimensional cells holding them, increasing: cell i has
   ray[off[i] .. off[i + 1]) (none for the origin, itself for a ray, the
   two bounding rays for a sector, every ray of its closure for a
   chamber).  *off (count + 1 entries) and *ray are allocated here
   (flint_free them).  O(m) work per sector for m planes, then a sort.
   Returns WC_OK or WC_EINTERNAL.  */
int wc_cells_rays(slong ** off, slong ** ray, const wc_cells_t A,
                  wc_error_t err);

/* A set of wrenches: pairwise disjoint convex NNC cones.  */
typedef struct
{
    int empty;              /* no point at all */
    int interior;           /* some piece has dimension 3 */
    slong npieces;
    wc_cone_struct * pieces;    /* each in canonical form, nonempty */
}
wc_set_struct;

typedef wc_set_struct wc_set_t[1];

void wc_set_init(wc_set_t S);
void wc_set_clear(wc_set_t S);
void wc_set_swap(wc_set_t S, wc_set_t T);

/* 1 when g (3 entries) lies in some piece of S, else 0.  */
int wc_set_contains(const wc_set_t S, const fmpq * g);

/* S := the union of the cells i of A with member[i] != 0, as sign boxes
   (above), each converted to its canonical NNC cone.  Pieces are sorted
   by decreasing dimension, then by their canonical form (rays, then
   inequalities, then equalities, then included faces, compared entry by
   entry), so the output depends only on A and member.  Returns WC_OK or
   WC_EINTERNAL (err set; S left empty).  */
int wc_set_from_cells(wc_set_t S, const wc_cells_t A, const int * member,
                      wc_error_t err);

/* Merge pieces of S whose union is a convex NNC cone, until none is (the
   sign boxes of wc_set_from_cells follow every plane of A, also where the
   set does not change across it).  A must be the arrangement S was built
   from.  The pieces stay pairwise disjoint with the same union, sorted as
   wc_set_from_cells sorts them.  Returns WC_OK or WC_EINTERNAL.  */
int wc_set_merge(wc_set_t S, const wc_cells_t A, wc_error_t err);

/* Sort S's pieces into the order wc_set_from_cells gives (after a
   caller has changed them).  */
void wc_set_sort(wc_set_t S);

#ifdef __cplusplus
}
#endif

#endif
