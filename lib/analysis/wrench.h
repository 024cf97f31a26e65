/* wrench.h -- the wrench cone W(x) of a contact mode, by two routes
   (wrenchcone(1), MODES).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   W(x) = { g : exists y = (a; c) with C y = B g and y satisfies the
   Table 2 constraints of x }.  Both routes return the same canonical
   wc_cone_t for every problem and mode.  */

#ifndef WC_WRENCH_H
#define WC_WRENCH_H

#include <flint/fmpq_mat.h>

#include "core/problem.h"
#include "exact/cone.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A trace: the named matrices a route built, in order, each with a note
   (labels of rows or columns, strictness marks).  */
typedef struct
{
    char * name;
    char * note;        /* may be NULL */
    fmpq_mat_t m;
}
wc_trace_entry_struct;

typedef struct
{
    slong len;
    slong alloc;
    wc_trace_entry_struct * entries;
}
wc_trace_struct;

typedef wc_trace_struct wc_trace_t[1];

void wc_trace_init(wc_trace_t T);
void wc_trace_clear(wc_trace_t T);

/* Append a copy of m under name with an optional note (printf format).  */
void wc_trace_add(wc_trace_t T, const char * name, const fmpq_mat_t m,
                  const char * note_fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 4, 5)))
#endif
    ;

typedef enum { WC_METHOD_DIRECT = 0, WC_METHOD_PAPER = 1 } wc_method;

/* The paper's route (Section 5): E, N, R, S, V, then K z = P g, z >= 0
   with strict coordinates, K^F by exact conversion, F = K^F P; the rows of
   F whose K^F K e_strict is negative are strict (Theorem 1 with k -> 0).
   trace may be NULL.  Returns WC_OK; WC_EINPUT when the mode fails
   wc_mode_check (WC_TABLE_CONE), with err set as that function sets it;
   or WC_EINTERNAL.  On failure W is left empty.  */
int wc_wrench_cone_paper(wc_cone_t W, wc_trace_t trace,
                         const wc_problem_t P, const char * mode,
                         wc_error_t err);

/* The direct route: W(x) = M V_x + (-J) D_x, a Minkowski sum in R^3.
   Same contract as wc_wrench_cone_paper.  */
int wc_wrench_cone_direct(wc_cone_t W, wc_trace_t trace,
                          const wc_problem_t P, const char * mode,
                          wc_error_t err);

/* Dispatch on method.  */
int wc_wrench_cone(wc_cone_t W, wc_trace_t trace, const wc_problem_t P,
                   const char * mode, wc_method method, wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
