/* direct3.h -- internal: the direct route's fast path, integer vectors
   straight from the model.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  The direct route (wrench.h) builds J, M and the
   friction edges as rational matrices and hands them to the general cone
   operations; this path builds integer rows and generators per fixel
   instead and goes straight to the 3-D fan (fan3.h) when V_x is the
   origin, a ray or a line (equalities of rank 2 or 3) or, with no
   equalities and no strict rows, a pointed cone or the normal line of a
   plane its rows fill; V_x a plane, or an open half-plane with one
   friction edge, and a line whose sum with the edges is not pointed, by
   an H-representation of W written directly; without friction edges it
   converts M V_x from one H-representation.  It gives up on every other
   case, and the general route answers.  Both give the same canonical cone (tests/t-direct3.c
   checks it on random and degenerate problems).  */

#ifndef WC_ANALYSIS_DIRECT3_H
#define WC_ANALYSIS_DIRECT3_H

#include "core/problem.h"
#include "exact/cone.h"
#include "analysis/wrench.h"

/* W := W(x) for a problem and mode that passed wc_mode_check
   (WC_TABLE_CONE), W->d = 3, when the fast path applies: *done := 1.
   Otherwise *done := 0 and W is left empty.  Returns WC_OK or
   WC_EINTERNAL (out of memory, err set; *done = 1, W empty).  */
int _wc_wrench_cone_direct3(wc_cone_t W, int * done, const wc_problem_t P,
                            const char * mode, wc_error_t err);

/* The general direct route (no fast path), for the cross-checks.  Same
   contract as wc_wrench_cone_direct.  */
int _wc_wrench_cone_direct_general(wc_cone_t W, wc_trace_t trace,
                                   const wc_problem_t P, const char * mode,
                                   wc_error_t err);

#endif
