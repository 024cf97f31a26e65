/* print.h -- the printers: every result as readable text, canonical JSON
   (wrenchcone(1), JSON) or, for cones, cddlib's formats.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   One convention for every printer of a result (here, fconeprint.h and
   compareprint.h):

       int wc_X_fprint(FILE * out, X, [what X is read with,]
                       const wc_print_opts * o);

   writes one whole document for X to out -- a JSON value, or lines of
   text -- and nothing else, never a part for its caller to finish; the
   last argument says how (wc_print_opts below).  A printer holds no
   setting of its own: what it writes depends on its arguments alone, so
   threads may print at once, each with options of its own.  It returns
   WC_OK, or WC_EINTERNAL when the stream reports an error.  The writers
   of certificates (wrenchcone-certificate(5)), which have one format,
   are wc_X_certificate_fprint(out, P, X[, err]) instead; the number
   writers take what they use.  */

#ifndef WC_PRINT_H
#define WC_PRINT_H

#include <stdio.h>

#include "exact/cone.h"
#include "analysis/wrench.h"
#include "analysis/kinematics.h"
#include "core/problem.h"
#include "core/limits.h"
#include "analysis/stability.h"
#include "analysis/plan.h"
#include "analysis/sweep.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The formats, in the order of wrenchcone(1)'s --format.  The cddlib
   formats are the cone printers' (wc_cone_fprint, wc_fcone_fprint); the
   other printers write text for them.  */
typedef enum
{
    WC_FORMAT_TEXT = 0,     /* for people */
    WC_FORMAT_JSON = 1,     /* wrenchcone(1), JSON */
    WC_FORMAT_CDD = 2,      /* cddlib's .ine, then .ext */
    WC_FORMAT_INE = 3,      /* the H-representation of the closure */
    WC_FORMAT_EXT = 4       /* the V-representation of the closure */
}
wc_format;

/* How to print.  o == NULL, or a struct of zeros, is text with exact
   numbers only and no indent.

   approx, decimals (text; wrenchcone(1), --decimals=K): when approx is
   set, every rational that is not an integer is followed by
   " (approx. D)", D the rational rounded to `decimals` digits after the
   point (0 to WC_DECIMALS_MAX, core/limits.h; a number outside is taken
   as the nearest of them), half away from zero, computed exactly (no
   floating point).  JSON, cdd, traces and certificates stay exact.

   indent (text of the printers that others nest: cones, sets, pushing
   regions, traces): what each of their lines starts with; NULL is none.
   A printer that nests one passes it the options it was given with the
   indent of the place.  */
typedef struct
{
    wc_format format;
    int approx;
    int decimals;
    const char * indent;
}
wc_print_opts;

/* ------------------------------------------------------------------
   Numbers.  */

/* A rational as text, "p/q" or "p" in lowest terms.  */
void wc_fprint_fmpq(FILE * out, const fmpq_t x);

/* x rounded to K >= 0 digits after the point, half away from zero:
   "-0.333" for -1/3 and K = 3, "2" for 5/3 and K = 0.  */
void wc_fprint_fmpq_decimal(FILE * out, const fmpq_t x, int K);

/* x as text, "p/q", then its approximation when o asks for them and x
   is not an integer (o's format aside).  */
void wc_fprint_fmpq_text(FILE * out, const fmpq_t x, const wc_print_opts * o);

/* A vector of len rationals: "(a, b, c)" as text, or ["a", "b", "c"] as
   JSON.  As text, when o asks for approximations and an entry is not an
   integer, the vector's approximation follows: "(1/3, 1) (approx.
   (0.333, 1.000))".  */
void wc_fprint_qvec(FILE * out, const fmpq * v, slong len,
                    const wc_print_opts * o);

/* s as a JSON string literal, with quotes and escapes.  */
void wc_fprint_json_string(FILE * out, const char * s);

/* ------------------------------------------------------------------
   Cones, traces, modes (print.c, cddwrite.c).  */

/* C: the CONE object of wrenchcone(1), JSON, on one line, no newline; a
   readable description; or cddlib's format with rationals (the closure's
   H-representation (.ine), V-representation (.ext), or both, H first),
   strictness, which cdd files cannot express, given in comment lines
   starting with '*' before the representations.  */
int wc_cone_fprint(FILE * out, const wc_cone_t C, const wc_print_opts * o);

/* A trace as text (a line per matrix, then its rows) or as a JSON array
   of {"name", "note", "rows", "cols", "matrix"} objects.  The text is
   exact whatever o asks.  */
int wc_trace_fprint(FILE * out, const wc_trace_t T, const wc_print_opts * o);

/* The feasible modes: text (one per line, with the witness twist when
   witness is set) or JSON {"fixels", "modes", "count"[, "witnesses"]}
   and a newline.  */
int wc_modes_fprint(FILE * out, const wc_modes_t M, int witness,
                    const wc_print_opts * o);

/* A mode's certificate: text for people, or the self-contained JSON that
   wrenchcone verify checks: {"kind": "mode-feasibility", "mode",
   "feasible", "witness" | "multipliers", "constraints", "problem"}.  */
int wc_certificate_fprint(FILE * out, const wc_certificate_t C,
                          const wc_problem_t P, const wc_print_opts * o);

/* ------------------------------------------------------------------
   classify and stability (stabprint.c, stabcertprint.c).  JSON as
   wrenchcone(1), JSON, with extra keys: classify adds "static_c" or
   "separator", and "paper_witness"; stability adds "paper_in_weak",
   "semantics_differ" and "difference_witness".  */

int wc_classify_fprint(FILE * out, const wc_classify_t R,
                       const wc_print_opts * o);

/* A set: JSON {"empty", "interior", "pieces"} (no newline), or text.  */
int wc_set_fprint(FILE * out, const wc_set_t S, const wc_print_opts * o);

/* Pushing regions: a JSON array (no newline), or text, in which each
   interval of a polygon's also gives its ends as points (x, y) of the
   boundary when P, the problem R was computed for, is not NULL.  */
int wc_push_fprint(FILE * out, const wc_push_t R, const wc_problem_t P,
                   const wc_print_opts * o);

/* The sets of S: one JSON object and a newline, or text (P as for
   wc_push_fprint).  */
int wc_stability_fprint(FILE * out, const wc_stability_t S,
                        const wc_problem_t P, const wc_print_opts * o);

/* Write the classification as a "strong-stability" certificate (see
   wrenchcone-certificate(5)); R must have been computed with
   certificates.  Returns WC_OK or WC_EINTERNAL on a write error.  */
int wc_classify_certificate_fprint(FILE * out, const wc_problem_t P,
                                   const wc_classify_t R);

/* Write the certificate that S->strong is exactly the strongly stable set
   of P (kind "stability-set", wrenchcone-certificate(5)), proving every
   cell of S's arrangement with exact LPs: O(cells x moving faces) LPs.
   S must be wc_stability's result for P.  Returns WC_OK, or
   WC_EINTERNAL (err set) when a proof fails (a bug: the set would be
   wrong) or on a write error; the output is then incomplete.  */
int wc_stability_certificate_fprint(FILE * out, const wc_problem_t P,
                                    const wc_stability_t S, wc_error_t err);

/* ------------------------------------------------------------------
   plan and sweep (planprint.c, sweepprint.c, plancertprint.c).  */

/* A plan: JSON as wrenchcone(1), JSON with extra keys: "fixels",
   "states" (each state's strings, Table 5), "redundant" (each
   syntactically redundant string with one containing it),
   "goal_in_strong_paper", "goal_not_strong" and "goal_not_strong_paper"
   (witnesses), "complete" ({"accepted": SET, "outside_goal": wrench or
   null, "push": REGIONS}), and a newline.  Text is for people.  P gives
   the shape for the (approximate, marked so) lengths of pushing
   regions.  */
int wc_plan_fprint(FILE * out, const wc_plan_t R, const wc_problem_t P,
                   const wc_print_opts * o);

/* {"wrench", "in_goal", "holding", "complete": {"accepted", "verdict",
   "transitions": [{"from", "to", "via"}], "states"}} and a newline, or
   text.  */
int wc_plan_wrench_fprint(FILE * out, const wc_plan_wrench_t W,
                          const wc_print_opts * o);

/* One friction value mu of a sweep, R the plan at mu: a JSON object (no
   newline) or a few lines of text.  */
int wc_plan_sweep_fprint(FILE * out, const wc_plan_t R, const wc_problem_t P,
                         const fmpq_t mu, const wc_print_opts * o);

/* A sweep (wc_sweep's A for P): the plan at each friction value, then
   the critical bracket when it was asked for; one JSON document and its
   newline, or text.  */
int wc_sweep_fprint(FILE * out, const wc_sweep_t A, const wc_problem_t P,
                    const wc_print_opts * o);

/* Write the certificate that R->goal is exactly G_goal for P (kind
   "plan-goal", wrenchcone-certificate(5)): the goal pieces' faces proved
   to miss every needed string's cone, those cones proved to hold their
   generators, every cell of R's arrangement placed.  R must be wc_plan's
   result for P.  Returns WC_OK; WC_EINPUT, nothing written, for more than
   WC_PLAN_CERT_MAX_FIXELS fixels; or WC_EINTERNAL (err set) when a proof
   fails (a bug) or on a write error.  */
int wc_plan_certificate_fprint(FILE * out, const wc_problem_t P,
                               const wc_plan_t R, wc_error_t err);

/* Write the certificate of the critical bracket C of P (kind
   "critical-friction", wrenchcone-certificate(5)): the witness at lo in
   G_goal with multipliers for every string, and a plan-goal certificate
   that G_goal is empty at hi.  Returns as wc_plan_certificate_fprint.  */
int wc_critical_certificate_fprint(FILE * out, const wc_problem_t P,
                                   const wc_critical_t C, wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
