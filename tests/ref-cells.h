/* ref-cells.h -- the independent reference for the cells of a central
   arrangement of planes in R^3 (ref-cells.c): sign vectors by symbolic
   perturbation from the lines where two planes meet.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_TESTS_REF_CELLS_H
#define WC_TESTS_REF_CELLS_H

#include <flint/flint.h>
#include <flint/fmpz_mat.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The faces of the arrangement of the planes h . x = 0, h a row of H:
   count distinct sign vectors of m = H->r entries each (sign(h_j . x),
   -1, 0 or 1), sign[i * m .. (i + 1) * m) for face i, and dim[i], the
   dimension of face i (3 minus the rank of the rows with sign 0).  Faces
   are sorted by dimension, then by sign vector (-1 < 0 < 1).  */
typedef struct
{
    slong m;
    slong count;
    signed char * sign;
    slong * dim;
}
ref_cells_struct;

typedef ref_cells_struct ref_cells_t[1];

void ref_cells_init(ref_cells_t C);
void ref_cells_clear(ref_cells_t C);

/* C := every face of the arrangement of the rows of H (zero rows, repeated
   and parallel rows allowed: a zero row has sign 0 everywhere).  Returns 0,
   or -1 when out of memory or when the enumeration contradicts itself
   (a face's constructed dimension not its rank dimension).  */
int ref_cells_faces(ref_cells_t C, const fmpz_mat_t H);

/* planes := the planes wc_cells_build documents for the rows of normals:
   every nonzero row and the three coordinate planes, each as its
   primitive integer normal with first nonzero entry positive, each once,
   sorted lexicographically (entry by entry, as integers).  planes must be
   initialised; it is replaced.  */
void ref_cells_planes(fmpz_mat_t planes, const fmpz_mat_t normals);

#ifdef __cplusplus
}
#endif

#endif
