/* answerprint.h -- the printers of answers made of several results: a
   mode's cone (with its trace, or in doubles), and the stability sets
   with a biasing wrench's robustness in them.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  Each writes a whole document, as o says
   (print.h).  */

#ifndef WC_IO_ANSWERPRINT_H
#define WC_IO_ANSWERPRINT_H

#include <stdio.h>

#include "io/print.h"
#include "float/floatcone.h"

/* W(mode), with T (NULL: no trace) computed by the route paper or not:
   text, JSON or a cdd format.  */
int _wc_mode_cone_fprint(FILE * out, const char * mode, const wc_cone_t W,
                         const wc_trace_t T, int paper,
                         const wc_print_opts * o);

/* The same for the cone in doubles (--arith=double).  */
int _wc_mode_fcone_fprint(FILE * out, const char * mode, const wc_fcone_t F,
                          const wc_print_opts * o);

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

/* stability's answer: S's sets for P (as wc_stability_fprint writes
   them) and, when B is not NULL, the bias's robustness after them -- in
   JSON, the member "bias": {"wrench", "length", "strong",
   "strong_paper"} of the one object.  */
int _wc_stability_answer_fprint(FILE * out, const wc_stability_t S,
                                const wc_problem_t P, const _wc_bias * B,
                                const wc_print_opts * o);

#endif
