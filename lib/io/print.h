/* print.h -- writers: readable text, canonical JSON (wrenchcone(1), JSON), cddlib.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Writers write only to the stream they are given.  Each returns WC_OK,
   or WC_EINTERNAL when the stream reports an error.  */

#ifndef WC_PRINT_H
#define WC_PRINT_H

#include <stdio.h>

#include "exact/cone.h"
#include "analysis/wrench.h"
#include "analysis/kinematics.h"
#include "core/problem.h"
#include "core/limits.h"
#include "analysis/stability.h"
#include "analysis/sweep.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A rational as text, "p/q" or "p" in lowest terms.  */
void wc_fprint_fmpq(FILE * out, const fmpq_t x);

/* Decimal approximations in text output (wrenchcone(1), --decimals=K):
   after K is set to 0 <= K <= WC_DECIMALS_MAX, the text writers follow
   every rational that is not an integer by " (approx. D)", D the rational
   rounded to K digits after the point, half away from zero, computed
   exactly (no floating point); K < 0, the default, adds none.  The
   setting is the calling thread's and leaves JSON, cdd and certificates
   exact and unchanged.  WC_DECIMALS_MAX is in core/limits.h.  */
void wc_print_set_decimals(int K);
int wc_print_decimals(void);

/* x rounded to K >= 0 digits after the point, half away from zero:
   "-0.333" for -1/3 and K = 3, "2" for 5/3 and K = 0.  */
void wc_fprint_fmpq_decimal(FILE * out, const fmpq_t x, int K);

/* x as text, "p/q", then its approximation when decimals are on and x is
   not an integer.  */
void wc_fprint_fmpq_text(FILE * out, const fmpq_t x);

/* A vector of len rationals: "(a, b, c)" as text, or ["a", "b", "c"] as
   JSON.  As text, when decimals are on and an entry is not an integer,
   the vector's approximation follows: "(1/3, 1) (approx. (0.333, 1.000))".  */
void wc_fprint_qvec(FILE * out, const fmpq * v, slong len, int json);

/* s as a JSON string literal, with quotes and escapes.  */
void wc_fprint_json_string(FILE * out, const char * s);

/* The CONE object of wrenchcone(1), JSON, on one line, no newline.  */
int wc_cone_fprint_json(FILE * out, const wc_cone_t C);

/* A readable description of C, each line starting with indent.  */
int wc_cone_fprint_text(FILE * out, const wc_cone_t C, const char * indent);

/* C in cddlib's format with rationals: which = 1 the H-representation
   (.ine) of the closure, 2 the V-representation (.ext), 3 both, H first.
   Strictness, which cdd files cannot express, is given in comment lines
   (starting with '*') before the representations; title goes there too.  */
int wc_cone_fprint_cdd(FILE * out, const wc_cone_t C, const char * title,
                       int which);

/* A trace as text (each line starting with prefix) or as a JSON array
   of {"name", "note", "rows", "cols", "matrix"} objects.  */
int wc_trace_fprint_text(FILE * out, const wc_trace_t T, const char * prefix);
int wc_trace_fprint_json(FILE * out, const wc_trace_t T);

/* The feasible modes: text (one per line, with the witness twist when
   witness is set) or JSON {"fixels", "modes", "count"[, "witnesses"]}.  */
int wc_modes_fprint(FILE * out, const wc_modes_t M, int json, int witness);

/* A mode's certificate: text for people, or the self-contained JSON that
   wrenchcone verify checks: {"kind": "mode-feasibility", "mode",
   "feasible", "witness" | "multipliers", "constraints", "problem"}.  */
int wc_certificate_fprint(FILE * out, const wc_certificate_t C,
                          const wc_problem_t P, int json);

/* classify and stability (stabprint.c).  JSON as wrenchcone(1), JSON, with extra
   keys: classify adds "static_c" or "separator", and "paper_witness";
   stability adds "paper_in_weak", "semantics_differ" and
   "difference_witness".  A set is {"empty", "interior", "pieces"}.  */
int wc_classify_fprint(FILE * out, const wc_classify_t R, int json);
int wc_set_fprint_json(FILE * out, const wc_set_t S);
int wc_set_fprint_text(FILE * out, const wc_set_t S, const char * indent);
int wc_push_fprint(FILE * out, const wc_push_t R, int json,
                   const char * indent);
/* The pushing regions R as text, as wc_push_fprint, and for a polygon
   each interval's ends also as points (x, y) of P's boundary.  P is the
   problem R was computed for, or NULL (no points).  */
int wc_push_fprint_text(FILE * out, const wc_push_t R, const wc_problem_t P,
                        const char * indent);
/* json: 0 text, 1 a JSON object and a newline, 2 the same object left
   open (no closing brace) for the caller to add members to.  */
int wc_stability_fprint(FILE * out, const wc_stability_t S, int json);
/* The text of wc_stability_fprint, with the pushing regions' ends as
   points of P's polygon (P as for wc_push_fprint_text).  */
int wc_stability_fprint_text(FILE * out, const wc_stability_t S,
                             const wc_problem_t P);

/* Write the certificate that S->strong is exactly the strongly stable set
   of P (kind "stability-set", wrenchcone-certificate(5)), proving every
   cell of S's arrangement with exact LPs: O(cells x moving faces) LPs.
   S must be wc_stability's result for P.  Returns WC_OK, or
   WC_EINTERNAL (err set) when a proof fails (a bug: the set would be
   wrong) or on a write error; the output is then incomplete.  */
int wc_stability_certificate_fprint(FILE * out, const wc_problem_t P,
                                    const wc_stability_t S, wc_error_t err);

/* A sweep (wc_sweep's A for P): the plan at each friction value, then
   the critical bracket when it was asked for; one JSON document and its
   newline, or text.  */
int wc_sweep_fprint_json(FILE * out, const wc_sweep_t A, const wc_problem_t P);
int wc_sweep_fprint_text(FILE * out, const wc_sweep_t A, const wc_problem_t P);

#ifdef __cplusplus
}
#endif

#endif
