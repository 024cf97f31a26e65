/* ref-plan.h -- the test oracle for insertion plans (wrenchcone(1), Insertion plans, paper
   Sections 8 and 9): the constraint strings, the goal set G_goal and the
   complete transition-graph model, all by brute force.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Independent of the library's plan, cell, hull and direct-route code
   (lib/plan.c, lib/cells.c, lib/hull3.c, lib/direct.c): strings come from
   bitmask loops and pairwise comparison, membership from one exact LP per
   string (ref-lp.h), emptiness from every cell of a plane arrangement
   found by the naive method.  Exponential on purpose; for n <= 5 or so.

   The strings, for n fixels numbered 0..n-1 (one Table 2 letter each):
   for every contact state S (the achieved contacts) and every nonempty
   L in S, s on L, m on S \ L, u off S (contacts L lost); and for every
   S other than all fixels, m on S, s off S (no progress).  A string A is
   syntactically redundant when another string B of the list has, at
   every position, B_i == A_i or (A_i == s and B_i == u): W(u) contains
   W(s), so W(A) lies in W(B).  G_goal is the set of wrenches g in R^3
   lying in W(x) for none of the needed (not redundant) strings x.  */

#ifndef WC_TESTS_REF_PLAN_H
#define WC_TESTS_REF_PLAN_H

#include <flint/flint.h>
#include <flint/fmpq.h>

#include "core/problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The strings for n fixels (1 <= n <= 8), deduplicated and ASCII-sorted;
   only the needed ones when needed_only is nonzero.  Returns a malloc'd
   array of *count malloc'd NUL-terminated strings, to be released with
   ref_plan_strings_free; NULL (and *count = 0) when n is out of range or
   memory runs out.  */
char ** ref_plan_strings(slong * count, slong n, int needed_only);

/* Free what ref_plan_strings returned (NULL is allowed).  */
void ref_plan_strings_free(char ** strings, slong count);

/* 1 if g (3 entries: fx, fy, torque) lies in G_goal of P, 0 if not, -1 on
   failure (an LP failure, or P->n outside 1..8).  One ref_wrench_in_cone
   per needed string; fixel states of P are ignored.  */
int ref_plan_goal_contains(const wc_problem_t P, const fmpq * g);

/* Decide exactly whether G_goal of P is empty: 1 empty, 0 nonempty, -1 on
   failure.  When 0, witness[0..2] (3 initialised fmpq) receives a wrench
   of G_goal, already confirmed by ref_plan_goal_contains; otherwise the
   witness is left unspecified.  Method: the cone of every needed string
   by the paper's route (wc_wrench_cone_paper, fixel states set from the
   letters on a copy of P), then one point of every cell of the central
   arrangement of all their facet and equality planes plus the coordinate
   planes, each tested with wc_cone_contains.  (The letters s, m, u are
   all non-strict, so every such W(x) is closed and G_goal is open: it is
   nonempty iff it holds a 3-cell.  The lower cells are visited anyway.)  */
int ref_plan_goal_empty(const wc_problem_t P, fmpq * witness);

/* The complete insertion model (plan --complete): 1 when g is accepted, 0
   when rejected, -1 on failure (an LP failure, or P->n outside 1..10).
   States are the subsets S of fixels (achieved contacts), the goal is all
   fixels.  At S an outcome is a string x with x_i in {s, m} on S and x_j
   in {s, a} off S; g admits it when g lies in W(x).  An admitted outcome
   with L = { i in S : x_i = s } and A = { j off S : x_j = a } gives the
   edges S -> (S \ L) u A' for every A' in A, but not A' = {} when L = {}
   and A != {} (an approach achieves some contact); L = A = {} gives the
   self-loop S -> S.  g is accepted iff the goal has no edge but its
   self-loop, the graph on the other states has no cycle (a self-loop
   there is one), and every other state has an out-edge.  4^n LPs.  */
int ref_plan_complete_accepts(const wc_problem_t P, const fmpq * g);

/* The plan model of P: Q := P with mu_s := max(mu_s, mu_k) at every
   fixel (Q initialised).  The plans read the m letter as "the contact is
   maintained, sticking or sliding", so its force may lie in either
   friction cone; the oracle functions above take P's friction as given
   and are called on Q to decide the plans.  0, or -1 out of memory.  */
int ref_plan_model(wc_problem_t Q, const wc_problem_t P);

/* Soundness against the rigid-body model itself.  At a state S (bit i
   set: fixel i touching, the others near) a solution for g is a mode y
   with y_i in {s, n, l, r} on S and y_j in {s, a} off S whose Table 2
   cone, with P's own mu_s for n and mu_k for l and r, holds g (one
   ref_wrench_in_cone each): every motion the dynamics can start.  Its
   transitions are those of an outcome (ref_plan_complete_accepts, with
   n, l, r read as keeping the contact).  Returns 1 when some solution
   breaks the rule, 0 when none does, -1 on failure or n outside 1..6.
   goal_rule != 0: G_goal's rule, no solution at any state loses a contact
   (has s on S) and off the goal every one approaches a fixel (has a off
   S).  goal_rule == 0: the complete plan's, in the graph of every
   solution's transitions nothing leaves the goal and no cycle avoids it.
   On 1, *state and mode (n + 1 bytes) receive the state and one solution
   that breaks the rule (for a cycle: one giving an edge of it).  */
int ref_plan_model_breaks(const wc_problem_t P, const fmpq * g,
                          int goal_rule, ulong * state, char * mode);

#ifdef __cplusplus
}
#endif

#endif
