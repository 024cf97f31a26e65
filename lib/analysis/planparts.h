/* planparts.h -- the pieces insertion plans are built from.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed): plan.c, plansweep.c and the files below.
   Every set of a plan is a union of cells of one arrangement, the planes
   of every cone it is built from (cellset.h).  */

#ifndef WC_PLANPARTS_H
#define WC_PLANPARTS_H

#include "analysis/plan.h"
#include "analysis/cellset.h"
#include "exact/cells.h"
#include "exact/cone.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Cones of strings (plancones.c).  An array of count cones of dimension
   3, and its release (C may be NULL).  */
wc_cone_struct * _wc_plan_cones_init(slong count);
void _wc_plan_cones_clear(wc_cone_struct * C, slong count);

/* The outcome string of index x (base-3 digits, fixel 0 first), and the
   number of outcomes, 3^n.  */
void _wc_plan_outcome_string(char * s, slong x, slong n);
slong _wc_plan_pow3(slong n);

/* C[k] := W(x) for the plan model of P (mu_s raised to mu_k where that is
   larger, plan.h) and the k-th needed string x of T, or the k-th of the
   3^n outcome strings (count of them).  */
int _wc_plan_needed_cones(wc_cone_struct * C, const wc_plan_strings_t T,
                          const wc_problem_t P, wc_error_t err);
int _wc_plan_outcome_cones(wc_cone_struct * C, slong count,
                           const wc_problem_t P, wc_error_t err);

/* The complete plan's transition graph (plangraph.c).  States are bit
   masks; n <= 6, so a state's successors fit in one ulong.  */
typedef void (* wc_plan_edge_fn)(void * ctx, ulong from, ulong to,
                                 slong outcome);

/* Every transition the outcomes admitted by member[] allow.  */
void _wc_plan_transitions(slong n, const unsigned char * member,
                          wc_plan_edge_fn add, void * ctx);

/* An edge function whose ctx is the adjacency array (ulong per state).  */
void _wc_plan_add_adj(void * ctx, ulong from, ulong to, slong outcome);

/* The verdict of the graph adj; with cycle != NULL, the states of a cycle
   (or the offending state) in cycle[0 .. *ncycle).  */
wc_plan_verdict _wc_plan_graph_verdict(const ulong * adj, slong n,
                                       ulong * cycle, slong * ncycle);

/* Exact redundancy (plan.c): exact[k] := 1 when cone k of count is not
   dropped, in order, as inside the union of the cones still kept; any
   (ncells / FLINT_BITS + 1 words) := the cells of any cone.  cells(out,
   k, ctx) writes the cells of cone k as a bitset (bit i for cell i; bits
   from ncells on are ignored); it is called at most twice per cone.
   Returns 0 when out of memory.  */
typedef void (* _wc_plan_bits_fn)(ulong * out, slong k, void * ctx);
int _wc_plan_exact(int * exact, ulong * any, slong count, slong ncells,
                   _wc_plan_bits_fn cells, void * ctx);

/* wc_problem_check, and at most WC_PLAN_MAX_FIXELS fixels
   (WC_PLAN_MAX_FIXELS_COMPLETE when complete) (plan.c).  */
int _wc_plan_check_size(const wc_problem_t P, int complete, wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
