/* fconeprint.h -- the printer of float cones (float/floatcone.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_FCONEPRINT_H
#define WC_FCONEPRINT_H

#include <stdio.h>

#include "float/floatcone.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Output formats of wc_fcone_fprint.  */
typedef enum
{
    WC_FCONE_TEXT = 0,  /* for people; a header says the numbers are floats */
    WC_FCONE_JSON = 1,  /* the CONE object of wrenchcone(1), JSON where it makes sense */
    WC_FCONE_INE = 2,   /* cddlib .ine of the closure, real numbers */
    WC_FCONE_EXT = 3,   /* cddlib .ext of the closure, real numbers */
    WC_FCONE_CDD = 4    /* .ine then .ext */
}
wc_fcone_format;

/* Write C.  Numbers are printed with %.17g (they read back to the same
   doubles).  JSON, on one line without a newline: {"empty", "arith":
   "double", "eps", "dim", "lineality_dim", "closed", "inequalities",
   "strict" (a bool per inequality), "equalities", "rays", "strict_rays",
   "lines"} with numbers as JSON numbers; an empty cone is {"empty": true,
   "arith": "double", "eps": ...}.  Text: lines indented by two spaces.
   cdd: strictness, which cdd files cannot express, goes into comment lines
   starting with '*'.  Returns WC_OK, or WC_EINTERNAL when the stream
   reports an error (or format is unknown).  */
int wc_fcone_fprint(FILE * out, const wc_fcone_t C, int format);

#ifdef __cplusplus
}
#endif

#endif
