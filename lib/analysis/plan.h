/* plan.h -- sensorless insertion plans (paper Sections 8 and 9, wrenchcone(1), Insertion plans).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A workpiece is to be seated against n fixels by one constant wrench g.
   A contact state S is the set of fixels where contact is achieved (state
   strings: '1' for an achieved contact, in file order); the goal is all
   of them.  In state S the fixels of S are touching and the others near,
   whatever the problem file says.

   The conservative plan (the paper's).  For every state S and every
   nonempty L in S the string with s on L, m on S \ L and u off S
   ("contacts L may be lost"), and for every S other than the goal the
   string with m on S and s off S ("no progress").  G_goal is the set of
   wrenches in the cone of none of them (eq. 21; Table 5 for n = 3).

   The plan model.  A contact the string keeps (m) may stick, its force in
   the static friction cone, or slide, its force on an edge of the kinetic
   one; m stands for both, so every cone of a plan is computed with
   mu_s := max(mu_s, mu_k) at every fixel, |c_t| <= max(mu_s, mu_k) c_n for
   m.  When mu_k <= mu_s that is the paper's static cone and nothing
   changes; when mu_k > mu_s a sliding contact pushes outside the static
   cone, and without the wider one a wrench that slides the part away
   could be accepted.  The letters s, u and a carry no force, so every
   cone depends on the string alone, not on the state it came from, and
   on friction only through max(mu_s, mu_k).  (The goal state's stability
   sets of eq. 25 use the problem's own mu_s and mu_k.)

   Redundancy.  Syntactic: a string is redundant when another has at every
   position the same letter or u where it has s (s is more constrained than
   u, so its cone is contained in the other's).  What remains is every
   string with exactly one s and m or u elsewhere: n 2^(n-1) of them (the
   paper's twelve for n = 3).  Exact: going through the syntactically
   needed strings in ASCII order, a string is dropped when its cone lies in
   the union of the cones of those not dropped (an empty cone always is).

   The complete plan (beyond the paper: its Section 9 asks for the union
   over all acyclic transition graphs).  At state S an outcome is a
   Table 2 string x with s or m on the fixels of S and s or a on the others;
   the wrench admits it when g lies in W(x).  With L the fixels of S with s
   (contacts that may break) and A the others with a (contacts being
   approached), it allows the transitions S -> (S \ L) u A' for every
   subset A' of A, except A' empty when L is empty and A is not (an
   approach achieves some contact); with L and A both empty it is the
   self-loop S -> S (no progress).  The wrench is accepted when, in the
   graph of every transition it allows, the goal has no edge but its
   self-loop, the other states carry no cycle (a self-loop is one) and
   each of them has an edge out.  Then every run reaches the goal and stays
   there, whichever transitions the indeterminate dynamics choose.  The
   m letter relaxes Coulomb friction to the plan model's friction cone
   (any tangential force within it, whatever the sliding direction, which
   holds both the sticking and the sliding forces), so the transitions
   are a superset of the dynamics' and acceptance is sound.  Every wrench
   of G_goal is accepted.  */

#ifndef WC_PLAN_H
#define WC_PLAN_H

#include <flint/fmpq.h>

#include "core/error.h"
#include "core/limits.h"
#include "core/problem.h"
#include "exact/cone.h"
#include "exact/cells.h"
#include "analysis/push.h"
#include "analysis/stability.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Why a wrench is rejected by the complete plan.  */
typedef enum
{
    WC_PLAN_ACCEPTED = 0,
    WC_PLAN_GOAL_LEAVES = 1,    /* the goal state has an edge out */
    WC_PLAN_CYCLE = 2,          /* a cycle through non-goal states */
    WC_PLAN_STUCK = 3           /* a non-goal state without an edge out */
}
wc_plan_verdict;

/* The insertion strings of n fixels, as wrenchcone(1), Insertion plans generates them.  */
typedef struct
{
    slong n;
    slong nstrings;
    char ** strings;        /* every generated string once, ASCII-sorted */
    /* By state, 0 .. 2^n - 1 (bit i set: contact at fixel i achieved):
       the indices into strings of the state's strings, first the lost-
       contact strings in the order of L (as a bit mask), then the
       no-progress string.  */
    slong * state_first;    /* 2^n + 1 offsets into state_str */
    slong * state_str;
    /* Syntactic redundancy: for every string the index of a string
       containing it (-1 for a needed one).  */
    slong * contained_in;
    slong nneeded;
    slong * needed;         /* indices into strings, ASCII order */
}
wc_plan_strings_struct;

typedef wc_plan_strings_struct wc_plan_strings_t[1];

void wc_plan_strings_init(wc_plan_strings_t T);
void wc_plan_strings_clear(wc_plan_strings_t T);

/* T := the strings of n fixels, 1 <= n <= WC_PLAN_MAX_FIXELS.  Returns
   WC_OK or WC_EINPUT (n out of range).  */
int wc_plan_strings(wc_plan_strings_t T, slong n, wc_error_t err);

/* s := the state string of the mask S ('1' achieved, '0' not); s has room
   for n + 1 bytes.  */
void wc_plan_state_string(char * s, ulong S, slong n);

/* A plan, as sets.  */
typedef struct
{
    wc_plan_strings_t T;
    wc_cone_struct * cones;     /* nneeded: W of each needed string */
    int * exact_needed;         /* nneeded: 1 when kept by exact redundancy */
    slong nexact;
    wc_set_t goal;              /* G_goal */
    /* G_goal against the strongly stable sets of the goal state (every
       fixel touching): goal_in_strong (exact semantics) and
       goal_in_strong_paper (eq. 19), each with a wrench of G_goal outside
       the set when it fails.  */
    wc_stability_t stab;
    int goal_in_strong, goal_in_strong_paper;
    fmpq strong_witness[3], paper_witness[3];
    int has_push;
    wc_push_t push_goal;
    /* With complete: the set of wrenches the complete plan accepts, the
       3^n outcome cones (index: base-3 digits s = 0, m = 1, a = 2, fixel 0
       the most significant), and a wrench it accepts outside G_goal when
       there is one.  */
    int complete;
    slong noutcomes;
    wc_cone_struct * outcomes;
    wc_set_t accepted;
    int has_extra;
    fmpq extra[3];
    int has_push_accepted;
    wc_push_t push_accepted;
    wc_cells_t cells;           /* every set here is a union of its cells */
}
wc_plan_struct;

typedef wc_plan_struct wc_plan_t[1];

void wc_plan_init(wc_plan_t R);
void wc_plan_clear(wc_plan_t R);

/* Compute the plan of P: strings, redundancy, G_goal as pieces, the test
   of eq. 25 in both semantics, the pushing regions when P has a shape,
   and with complete != 0 the complete plan's set.  The states of P's
   fixels are ignored.  Returns WC_OK, WC_EINPUT (bad problem, or more
   fixels than WC_PLAN_MAX_FIXELS, or WC_PLAN_MAX_FIXELS_COMPLETE with
   complete), WC_EINTERNAL.  */
int wc_plan(wc_plan_t R, const wc_problem_t P, int complete, wc_error_t err);

/* One wrench against the plans.  */
typedef struct
{
    slong n;
    fmpq g[3];
    int in_goal;            /* in G_goal */
    slong nholding;
    char ** holding;        /* needed strings whose cone holds g */
    /* The complete plan (when asked): the verdict, every transition of
       the graph (from, to as state masks, and the outcome string that
       allows it), and for a rejection the states of a cycle (in order,
       ncycle >= 1) or the state that leaves the goal or is stuck.  */
    int complete;
    wc_plan_verdict verdict;
    slong nedges;
    ulong * from, * to;
    char ** via;
    slong ncycle;
    ulong * cycle;
}
wc_plan_wrench_struct;

typedef wc_plan_wrench_struct wc_plan_wrench_t[1];

void wc_plan_wrench_init(wc_plan_wrench_t W);
void wc_plan_wrench_clear(wc_plan_wrench_t W);

/* Decide g (3 entries) for P: membership in G_goal, and with complete the
   complete plan's verdict with its transition graph.  Each cone is
   computed once (direct route) and g located in it exactly.  Returns as
   wc_plan.  */
int wc_plan_wrench(wc_plan_wrench_t W, const wc_problem_t P, const fmpq * g,
                   int complete, wc_error_t err);

/* The friction sweep: the plan of P with mu_s = mu_k = mu at every
   fixel (the plan model is then P's own friction).  */
int wc_plan_with_friction(wc_plan_t R, const wc_problem_t P,
                          const fmpq_t mu, wc_error_t err);

/* The critical friction: lo < hi with hi - lo <= width (width > 0),
   G_goal nonempty at mu = lo (lo_witness is a wrench in it) and empty at
   mu = hi, G_goal shrinking as mu grows (every cone grows with mu).  The
   search starts at [0, 1] and doubles hi while G_goal is nonempty, up to
   max (then found = 0: nonempty at every mu <= max, lo = max with its
   witness).  When G_goal is empty already at mu = 0, found = 1, lo = hi =
   0 and empty_at_zero = 1.  With max a power of two the ends are dyadic.
   evals counts the plans computed.  Returns as wc_plan.  */
typedef struct
{
    int found, empty_at_zero;
    fmpq_t lo, hi;
    fmpq lo_witness[3];
    slong evals;
}
wc_critical_struct;

typedef wc_critical_struct wc_critical_t[1];

void wc_critical_init(wc_critical_t C);
void wc_critical_clear(wc_critical_t C);

int wc_plan_critical(wc_critical_t C, const wc_problem_t P,
                     const fmpq_t width, const fmpq_t max, wc_error_t err);

/* The bounds that keep the search to at most 2 + 32 + 128 plans
   (WC_CRITICAL_MIN_WIDTH_EXP, WC_CRITICAL_MAX_FRICTION_EXP): the width is
   at least 2^-96 (about 1.3e-29) and max at most 2^32; wc_plan_critical
   refuses others with WC_EINPUT.  The predicates say whether a value is
   within them (and positive).  */
int wc_critical_width_ok(const fmpq_t width);
int wc_critical_max_ok(const fmpq_t max);

/* The printers of plans, sweeps and their certificates are in
   io/print.h.  */

#ifdef __cplusplus
}
#endif

#endif
