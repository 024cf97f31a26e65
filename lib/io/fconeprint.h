/* fconeprint.h -- the printer of float cones (float/floatcone.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_FCONEPRINT_H
#define WC_FCONEPRINT_H

#include <stdio.h>

#include "float/floatcone.h"
#include "io/print.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Write C as o says (print.h): text for people, lines indented by two
   spaces, a header saying the numbers are floats; JSON, the CONE object
   of wrenchcone(1), JSON where it makes sense, on one line without a
   newline: {"empty", "arith": "double", "eps", "dim", "lineality_dim",
   "closed", "inequalities", "strict" (a bool per inequality),
   "equalities", "rays", "strict_rays", "lines"} with numbers as JSON
   numbers, an empty cone {"empty": true, "arith": "double", "eps": ...};
   or cddlib's formats of the closure with real numbers, strictness,
   which cdd files cannot express, in comment lines starting with '*'.
   Numbers are printed with %.17g (they read back to the same doubles);
   o's decimals and indent are not used.  Returns WC_OK, or WC_EINTERNAL
   when the stream reports an error (or the format is unknown).  */
int wc_fcone_fprint(FILE * out, const wc_fcone_t C, const wc_print_opts * o);

#ifdef __cplusplus
}
#endif

#endif
