/* compareprint.h -- the report of a comparison with a foreign cone
   (float/compare.h, `wrenchcone compare`).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_COMPAREPRINT_H
#define WC_COMPAREPRINT_H

#include <stdio.h>

#include "exact/cone.h"
#include "float/compare.h"
#include "io/print.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The report: text for people or one JSON object and a newline, as o
   says (print.h; its decimals and indent are not used).  problem, mode
   and file name the inputs.  Returns WC_OK or WC_EINTERNAL when the
   stream reports an error.  */
int wc_comparison_fprint(FILE * out, const wc_comparison_t R,
                         const wc_cone_t W, const char * problem,
                         const char * mode, const char * file,
                         const wc_print_opts * o);

#ifdef __cplusplus
}
#endif

#endif
