/* answerprint.h -- the printers of answers made of several results: a
   mode's cone (with its trace, or in doubles) and a biasing wrench's
   robustness in the strongly stable sets.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  Each writes a whole document, or (the bias)
   the part the caller places in one.  */

#ifndef WC_IO_ANSWERPRINT_H
#define WC_IO_ANSWERPRINT_H

#include <stdio.h>

#include "io/print.h"
#include "float/floatcone.h"

/* The formats of the command line, in --format's order.  */
enum { _WC_FMT_TEXT, _WC_FMT_JSON, _WC_FMT_CDD, _WC_FMT_INE, _WC_FMT_EXT };

/* W(mode), with T (NULL: no trace) computed by the route paper or not,
   in format fmt.  */
int _wc_mode_cone_fprint(FILE * out, const char * mode, const wc_cone_t W,
                         const wc_trace_t T, int paper, int fmt);

/* The same for the cone in doubles (--arith=double).  */
int _wc_mode_fcone_fprint(FILE * out, const char * mode, const wc_fcone_t F,
                          int fmt);

/* A biasing wrench b and how far it is from leaving the strongly stable
   sets (exact, paper) in the norm max(|fx|, |fy|, |tau| / L).  */
typedef struct
{
    fmpq b[3];
    fmpq_t L;
    fmpq_t rho[2];
    int closed[2], infinite[2], in_set[2];
}
_wc_bias;

void _wc_bias_init(_wc_bias * B);
void _wc_bias_clear(_wc_bias * B);

/* As text (lines), or as JSON: the member ", \"bias\": {...}".  */
int _wc_bias_fprint_text(FILE * out, const _wc_bias * B);
int _wc_bias_fprint_json(FILE * out, const _wc_bias * B);

#endif
