/* figgraph.c -- the contact-state transition graph of an insertion plan
   (the paper's Figures 7 and 9).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   States are the sets of achieved contacts (strings of 0 and 1 in file
   order), by number of contacts from the bottom (none) to the top (the
   goal).  The conservative plan forbids, from every state S, losing any
   nonempty set L of its contacts (the string with s on L, m on the rest
   of S, u off S) and, away from the goal, making no progress (m on S, s
   off S); what remains is progress, drawn as the edges that gain one
   contact.  Positions are exact small rationals; no analysis is run.  */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/plan.h"
#include "draw/figure.h"

#define SPACING 1.6
#define TRIM 0.16

static int
popcount(ulong S)
{
    int c = 0;

    for (; S; S &= S - 1)
        c++;
    return c;
}

/* The position of state S of n fixels.  */
static void
node_xy(double * xy, ulong S, slong n)
{
    ulong T, count = 0, index = 0;
    int level = popcount(S);

    for (T = 0; T < (UWORD(1) << n); T++)
        if (popcount(T) == level)
        {
            if (T < S)
                index++;
            count++;
        }
    /* Odd levels a little to the right, so that no edge runs through a
       node it does not join.  */
    xy[0] = ((double) index - (double) (count - 1) / 2) * SPACING
            + 0.4 * (level % 2);
    xy[1] = level;
}

/* An edge from state A to state B, moved sideways by side, trimmed at
   both ends to leave the nodes free; label at its middle when not NULL.  */
static int
edge(_wc_scene_t S, _wc_draw_tag tag, ulong A, ulong B, slong n,
     double side, const char * label)
{
    double a[2], b[2], dx, dy, len;
    int status;

    node_xy(a, A, n);
    node_xy(b, B, n);
    dx = b[0] - a[0];
    dy = b[1] - a[1];
    len = sqrt(dx * dx + dy * dy);
    dx /= len;
    dy /= len;
    a[0] += TRIM * dx - side * dy, a[1] += TRIM * dy + side * dx;
    b[0] -= TRIM * dx + side * dy, b[1] -= TRIM * dy - side * dx;
    status = _wc_scene_arrow(S, tag, a[0], a[1], b[0], b[1]);
    if (status == WC_OK && label != NULL)
        status = _wc_scene_text(S, (2 * a[0] + b[0]) / 3,
                                (2 * a[1] + b[1]) / 3, 0, 4, 0, label);
    return status;
}

/* The plan's string of state S losing L (L empty: no progress).  */
static void
plan_string(char * s, ulong St, ulong L, slong n)
{
    slong i;

    for (i = 0; i < n; i++)
    {
        int in = (St >> i) & 1, lost = (L >> i) & 1;

        s[i] = L == 0 ? (in ? 'm' : 's') : lost ? 's' : in ? 'm' : 'u';
    }
    s[n] = '\0';
}

static int
node(_wc_scene_t S, ulong St, slong n)
{
    char name[_WC_DRAW_GRAPH_MAX_FIXELS + 1];
    ulong goal = (UWORD(1) << n) - 1;
    double xy[2];
    int status;

    node_xy(xy, St, n);
    wc_plan_state_string(name, St, n);
    status = _wc_scene_dot(S, St == goal ? _WC_TAG_GOAL : _WC_TAG_NODE, 0,
                           xy[0], xy[1]);
    if (status == WC_OK)
        status = _wc_scene_text(S, xy[0], xy[1], 0, 4, 0, name);
    return status;
}

/* A self-loop at state St, labelled.  */
static int
loop(_wc_scene_t S, _wc_draw_tag tag, ulong St, slong n, const char * label)
{
    double xy[2];
    int status;

    node_xy(xy, St, n);
    status = _wc_scene_arc(S, tag, 0, xy[0] + 0.42, xy[1], 0.12, -_WC_PI / 2,
                           3 * _WC_PI / 4);
    if (status == WC_OK)
        status = _wc_scene_text(S, xy[0] + 0.56, xy[1], 2, 4, -1, label);
    return status;
}

static int
state(_wc_scene_t S, ulong St, slong n)
{
    ulong goal = (UWORD(1) << n) - 1, L;
    char str[_WC_DRAW_GRAPH_MAX_FIXELS + 1];
    slong i;
    int status;

    for (i = 0; i < n && St != goal; i++)
        if (!((St >> i) & 1))
            if ((status = edge(S, _WC_TAG_EDGE_PROGRESS, St,
                               St | (UWORD(1) << i), n, 0,
                               NULL)) != WC_OK)
                return status;
    for (L = St; L != 0; L = (L - 1) & St)
    {
        plan_string(str, St, L, n);
        if ((status = edge(S, _WC_TAG_EDGE_FORBIDDEN, St, St & ~L, n, 0.07,
                           str)) != WC_OK)
            return status;
    }
    if (St != goal)
    {
        plan_string(str, St, 0, n);
        if ((status = loop(S, _WC_TAG_EDGE_FORBIDDEN, St, n, str)) != WC_OK)
            return status;
    }
    return node(S, St, n);
}

/* The transitions the wrench g admits (the complete plan).  */
static int
admitted(_wc_scene_t S, const wc_problem_t P, const fmpq * g,
         const char ** verdict, wc_error_t err)
{
    static const char * const words[4] = {
        "accepted: every run reaches the goal and stays",
        "rejected: the goal state can lose a contact",
        "rejected: a cycle through states other than the goal",
        "rejected: a state other than the goal has no transition out" };
    wc_plan_wrench_t W;
    slong e;
    ulong St;
    int status;

    wc_plan_wrench_init(W);
    status = wc_plan_wrench(W, P, g, 1, err);
    for (e = 0; e < W->nedges && status == WC_OK; e++)
        status = W->from[e] == W->to[e]
                 ? loop(S, _WC_TAG_EDGE_ADMITTED, W->from[e], P->n, W->via[e])
                 : edge(S, _WC_TAG_EDGE_ADMITTED, W->from[e], W->to[e], P->n,
                        0, W->via[e]);
    for (St = 0; St < (UWORD(1) << P->n) && status == WC_OK; St++)
        status = node(S, St, P->n);
    if (status == WC_OK)
        *verdict = words[W->verdict];
    wc_plan_wrench_clear(W);
    return status;
}

static int
graph_words(_wc_scene_t S, const wc_problem_t P, const fmpq * g,
            const char * verdict)
{
    char * w[4] = { NULL, NULL, NULL, NULL };
    int status = WC_OK, i;

    if (g == NULL)
        return _wc_scene_caption(S, "%s, %ld fixels. A state lists the "
                                 "achieved contacts in file order. The "
                                 "plan forbids every transition that "
                                 "loses contacts and every self-loop "
                                 "away from the goal: each dashed edge is "
                                 "labelled with the string (s: the "
                                 "contact may break, m: it is kept, u: "
                                 "no contact) whose wrench cone G_goal "
                                 "avoids (eq. 21). What remains is "
                                 "progress; the solid edges gain one "
                                 "contact (several at once are allowed "
                                 "too).", _wc_draw_name(P), (long) P->n);
    for (i = 0; i < 3 && status == WC_OK; i++)
        if ((w[i] = _wc_draw_fmpq_str(g + i)) == NULL)
            status = WC_EINTERNAL;
    if (status == WC_OK && (w[3] = _wc_draw_friction(P)) == NULL)
        status = WC_EINTERNAL;
    if (status == WC_OK)
        status = _wc_scene_caption(S, "%s, %ld fixels, friction %s, the "
                                   "wrench g = (%s, %s, %s): every "
                                   "transition it admits "
                                   "under the complete plan, labelled with "
                                   "an outcome string (s: the contact may "
                                   "break, m: kept, a: being approached) "
                                   "whose cone holds g. Verdict: %s.",
                                   _wc_draw_name(P), (long) P->n, w[3], w[0],
                                   w[1], w[2], verdict);
    for (i = 0; i < 4; i++)
        free(w[i]);
    return status;
}

int
_wc_draw_graph(_wc_scene_t S, const wc_problem_t P, const fmpq * g,
               wc_error_t err)
{
    const char * verdict = NULL;
    ulong St;
    int status;

    if ((status = wc_problem_check(P, err)) != WC_OK)
        return status;
    if ((status = wc_problem_check_fixels(P, _WC_DRAW_GRAPH_MAX_FIXELS, 0,
                                          "the state-transition graph",
                                          err)) != WC_OK)
        return status;
    S->scale = 1;
    if (g != NULL)
        status = admitted(S, P, g, &verdict, err);
    for (St = 0; g == NULL && St < (UWORD(1) << P->n) && status == WC_OK;
         St++)
        status = state(S, St, P->n);
    if (status == WC_OK)
        status = _wc_scene_legend(S, _WC_TAG_NODE, 0, "contact state "
                                  "(1: contact achieved)");
    if (status == WC_OK)
        status = _wc_scene_legend(S, _WC_TAG_GOAL, 0, "goal state");
    if (status == WC_OK && g == NULL)
        status = _wc_scene_legend(S, _WC_TAG_EDGE_PROGRESS, 0, "progress: "
                                  "a contact gained (allowed)");
    if (status == WC_OK && g == NULL)
        status = _wc_scene_legend(S, _WC_TAG_EDGE_FORBIDDEN, 0, "forbidden: "
                                  "contacts lost, or no progress");
    if (status == WC_OK && g != NULL)
        status = _wc_scene_legend(S, _WC_TAG_EDGE_ADMITTED, 0, "a transition "
                                  "the wrench admits");
    if (status == WC_OK)
        status = _wc_scene_title(S, g == NULL ? "State-transition graph of "
                                 "the insertion plan" : "Transitions a "
                                 "wrench admits (complete plan)");
    if (status == WC_OK)
        status = graph_words(S, P, g, verdict);
    return status;
}
