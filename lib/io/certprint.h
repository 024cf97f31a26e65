/* certprint.h -- internal: the parts that the certificates of sets print
   alike (wrenchcone-certificate(5)).  Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_CERTPRINT_H
#define WC_CERTPRINT_H

#include <stdio.h>

#include "analysis/setcert.h"

/* v (len) scaled by a positive number to a primitive integer vector (a
   Motzkin certificate or a separator means the same after it).  */
void _wc_fprint_scaled(FILE * out, const fmpq * v, slong len);

/* {"nudot": [..], "c": [..]} of a problem of n fixels.  */
void _wc_fprint_motion(FILE * out, const wc_motion_struct * a, slong n);

/* ",\n   "closure": [..]" and, for a cone that is not closed,
   ",\n   "motions": [..]" (null for a face it does not include).  */
void _wc_fprint_cone_proof(FILE * out, const _wc_cone_proof * cp, slong n);

/* {"static": [..], (when pp->c) "faces": [..]} of a piece against nexcl
   excluding cones, n fixels.  */
void _wc_fprint_piece_proof(FILE * out, const _wc_piece_proof * pp,
                            slong nexcl, slong n);

/* ",\n "planes": [..]" of A.  */
void _wc_fprint_planes(FILE * out, const wc_cells_t A);

/* One cell: its point, "in", and its proof; excluded names the key of
   an excluding cone ("face", "string").  */
void _wc_fprint_cell_proof(FILE * out, const _wc_cell_proof * pf,
                           const fmpz * point, const char * excluded);

/* ",\n "cells": [..]}" and a newline: every cell of C->A proved by
   prove(pf, ctx, i, err) and written, excluded as above.  Returns WC_OK,
   prove's failure (nothing more written), or WC_EINTERNAL on a write
   error.  */
int _wc_fprint_cells(FILE * out, _wc_setcert * C,
                     int (* prove)(_wc_cell_proof *, void *, slong,
                                   wc_error_t),
                     void * ctx, const char * excluded, wc_error_t err);

#endif
