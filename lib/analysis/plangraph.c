/* plangraph.c -- the complete plan's transition graph and its verdict.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "analysis/planparts.h"

/* Every transition the outcomes admitted by member[] allow.  */
void
_wc_plan_transitions(slong n, const unsigned char * member,
                     wc_plan_edge_fn add, void * ctx)
{
    ulong full = (UWORD(1) << n) - 1, S, B, Ap;
    slong i;

    for (S = 0; S <= full; S++)
        for (B = 0; B <= full; B++)
        {
            /* B: the fixels whose letter is not s (m in S, a off S) */
            ulong L = S & ~B, A = B & ~S;
            slong x = 0;

            for (i = 0; i < n; i++)
                x = 3 * x + (((B >> i) & 1) ? (((S >> i) & 1) ? 1 : 2) : 0);
            if (!member[x])
                continue;
            for (Ap = A;; Ap = (Ap - 1) & A)
            {
                if (!(Ap == 0 && L == 0 && A != 0))
                    add(ctx, S, (S & ~L) | Ap, x);
                if (Ap == 0)
                    break;
            }
        }
}

void
_wc_plan_add_adj(void * ctx, ulong from, ulong to, slong outcome)
{
    ulong * adj = ctx;

    (void) outcome;
    adj[from] |= UWORD(1) << to;
}

/* The verdict of the graph adj; with cycle != NULL, the states of a cycle
   (or the offending state) in cycle[0 .. *ncycle).  */
wc_plan_verdict
_wc_plan_graph_verdict(const ulong * adj, slong n, ulong * cycle,
                       slong * ncycle)
{
    ulong full = (UWORD(1) << n) - 1, S, T;
    slong nst = full + 1, top, i;
    unsigned char * color;
    ulong * stack, * next;
    wc_plan_verdict v = WC_PLAN_ACCEPTED;

    if (ncycle != NULL)
        *ncycle = 0;
    if (adj[full] & ~(UWORD(1) << full))
    {
        if (cycle != NULL)
            cycle[(*ncycle)++] = full;
        return WC_PLAN_GOAL_LEAVES;
    }
    for (S = 0; S < full; S++)
        if (adj[S] == 0)
        {
            if (cycle != NULL)
                cycle[(*ncycle)++] = S;
            return WC_PLAN_STUCK;
        }
    /* Depth-first search over the non-goal states: grey on the stack.  */
    color = calloc(nst, 1);
    stack = malloc(sizeof(ulong) * (nst + 1));
    next = malloc(sizeof(ulong) * (nst + 1));
    for (S = 0; S < full && v == WC_PLAN_ACCEPTED; S++)
    {
        if (color[S])
            continue;
        top = 0;
        stack[0] = S;
        next[0] = 0;
        color[S] = 1;
        while (top >= 0 && v == WC_PLAN_ACCEPTED)
        {
            ulong U = stack[top];

            for (T = next[top]; T < full; T++)
                if ((adj[U] >> T) & 1)
                    break;
            if (T >= full)
            {
                color[U] = 2;
                top--;
                continue;
            }
            next[top] = T + 1;
            if (color[T] == 1)
            {
                v = WC_PLAN_CYCLE;
                if (cycle != NULL)
                {
                    for (i = 0; stack[i] != T; i++)
                        ;
                    for (; i <= top; i++)
                        cycle[(*ncycle)++] = stack[i];
                }
            }
            else if (color[T] == 0)
            {
                color[T] = 1;
                stack[++top] = T;
                next[top] = 0;
            }
        }
    }
    free(color);
    free(stack);
    free(next);
    return v;
}

