/* printutil.h -- the small writers every printer shares.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  The public ones (wc_fprint_fmpq,
   wc_fprint_qvec, wc_fprint_json_string) are declared in print.h, with
   the options every printer takes (wc_print_opts).  */

#ifndef WC_PRINTUTIL_H
#define WC_PRINTUTIL_H

#include <stdio.h>
#include <flint/flint.h>
#include <flint/fmpz.h>
#include <flint/fmpq.h>

#include "core/problem.h"
#include "core/version.h"
#include "io/print.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a writer returns: WC_OK, or WC_EINTERNAL when the stream reports
   an error.  */
int _wc_fprint_done(FILE * out);

/* What o asks (o may be NULL): JSON; the digits of the approximations
   (at most WC_DECIMALS_MAX), or -1 for none; the indent ("" for none).  */
int _wc_print_json(const wc_print_opts * o);
int _wc_print_decimals(const wc_print_opts * o);
const char * _wc_print_indent(const wc_print_opts * o);

/* The options of JSON output, for the writers that have no others
   (certificates).  */
extern const wc_print_opts _wc_print_as_json[1];

/* The options of text that a text printer passes a printer it nests:
   o's (or the defaults, for NULL), text, with indent.  */
wc_print_opts _wc_print_indented(const wc_print_opts * o,
                                 const char * indent);

/* "true" / "false", and "yes" / "no".  */
const char * _wc_tf(int b);
const char * _wc_yes(int b);

/* A rational as a JSON string, "p/q".  */
void _wc_fprint_jq(FILE * out, const fmpq_t x);

/* A vector of len integers: "(a, b, c)" as text, or ["a", "b", "c"] as
   JSON.  */
void _wc_fprint_zvec(FILE * out, const fmpz * v, slong len, int json);

#ifdef __cplusplus
}
#endif

/* The problem of a certificate with dynamics (mass, inertia, friction),
   as wrenchcone-certificate(5) gives it: one JSON object.  */
void _wc_fprint_dyn_problem(FILE * out, const wc_problem_t P);

/* The members of wc_stability_fprint's JSON object after WC_JSON_OPEN,
   "weak" to "push": for the printers of whole documents that hold them
   (answerprint.c adds the bias).  */
void _wc_stability_fprint_members(FILE * out, const wc_stability_t S);

#endif
