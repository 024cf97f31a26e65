/* wrench.c -- W(x) by the route asked for.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The direct route (direct.c) is the default; the paper's (paper.c)
   exists to be compared with it, and both return the same canonical
   cone.  */

#include <config.h>

#include "analysis/wrench.h"

int
wc_wrench_cone(wc_cone_t W, wc_trace_t trace, const wc_problem_t P,
               const char * mode, wc_method method, wc_error_t err)
{
    if (method == WC_METHOD_PAPER)
        return wc_wrench_cone_paper(W, trace, P, mode, err);
    return wc_wrench_cone_direct(W, trace, P, mode, err);
}
