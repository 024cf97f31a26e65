/* cddwrite.h -- internal: the one writer of cddlib's .ine/.ext blocks,
   for exact cones (rationals) and float cones (doubles) alike.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  */

#ifndef WC_IO_CDDWRITE_H
#define WC_IO_CDDWRITE_H

#include <stdio.h>

#include <flint/flint.h>

#include "exact/cone.h"

/* Print sign times entry (i, j) of the matrix A, with no blank before.  */
typedef void (*_wc_cdd_entry_fn)(FILE * out, const void * A, slong i,
                                 slong j, int sign);

/* A cone's closure as cdd sees it: facets h (h.g <= 0), equalities,
   rays and lines, each a matrix of d columns read through entry.  */
typedef struct
{
    slong d;
    const char * numtype;   /* cdd's number type: "rational", "real" */
    _wc_cdd_entry_fn entry;
    const void * ineqs, * eqs, * rays, * lines;
    slong m, q, k, l;       /* their numbers of rows */
}
_wc_cdd_cone;

/* The H-representation (which & 1) and then the V-representation
   (which & 2) of the closure of C, or of the empty set when empty (the
   matrices are not read then).  Comment lines are the caller's.  */
void _wc_cdd_fprint_reps(FILE * out, const _wc_cdd_cone * C, int empty,
                         int which);

/* The exact cone C as wc_cone_fprint writes it in a cdd format: which =
   1 the H-representation (.ine) of the closure, 2 the V-representation
   (.ext), 3 both, H first, after comment lines on its strictness.  */
int _wc_cone_fprint_cdd(FILE * out, const wc_cone_t C, int which);

#endif
