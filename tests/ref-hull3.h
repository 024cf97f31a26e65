/* ref-hull3.h -- an independent reference for the 3-D cone conversion
   (lib/exact/hull3.h, fan3.h, polar3.h, cone.h in R^3).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Written from SPEC.md section 2.4 and the library's headers only,
   without reading lib/exact or tests/old-hull3.c; it uses FLINT and
   nothing of lib/.  Brute force, O(k^3): every candidate is checked
   against every row.  Outputs are in the canonical form of SPEC 2.4 and
   are (re)initialised here; inputs may be NULL or have no rows.  */

#ifndef WC_REF_HULL3_H
#define WC_REF_HULL3_H

#include <flint/fmpz_mat.h>
#include <flint/fmpq_mat.h>

/* The closure of pos(rays) + lin(lines): E := the reduced row echelon
   basis of the orthogonal complement of its linear hull, H := its facet
   normals (h . g <= 0), projected onto the linear hull; rows primitive,
   H sorted and without repeats.  */
void ref_hull3_facets(fmpz_mat_t E, fmpz_mat_t H, const fmpq_mat_t rays,
                      const fmpq_mat_t lines);

/* { x : E x = 0, H x <= 0 }: L := the reduced row echelon basis of its
   lineality space, R := its extreme rays projected onto the orthogonal
   complement of L; rows primitive, R sorted and without repeats.  */
void ref_hull3_rays(fmpz_mat_t L, fmpz_mat_t R, const fmpq_mat_t E,
                    const fmpq_mat_t H);

/* Someone else's rows in the same form: S := the rows of A projected
   onto the orthogonal complement of the row space of B (B may be NULL),
   primitive, zero rows dropped, sorted, without repeats.  */
void ref_hull3_canon(fmpz_mat_t S, const fmpq_mat_t A, const fmpz_mat_t B);

/* S := the reduced row echelon basis of the row space of A, rows
   primitive (no zero rows).  */
void ref_hull3_span(fmpz_mat_t S, const fmpq_mat_t A);

#endif
