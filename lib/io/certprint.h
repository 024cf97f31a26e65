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

/* T := the tree of classify (setcert.h) from the preferred planes h (nh;
   freed here), refused when it would list more planes than verify
   reads.  */
int _wc_cert_tree(_wc_settree * T, fmpz * h, slong nh,
                  _wc_settree_classify classify, void * ctx, wc_error_t err);

/* ",\n "planes": [..]" of T.  */
void _wc_fprint_planes(FILE * out, const _wc_settree * T);

/* ",\n "tree": [..]}" and a newline: T's nodes, a leaf in an excluding
   cone naming it by the key excluded ("face", "string").  */
int _wc_fprint_tree(FILE * out, const _wc_settree * T, const char * excluded,
                    wc_error_t err);

#endif
