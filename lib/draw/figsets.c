/* figsets.c -- pushing regions of sets of wrenches: the stability sets,
   the goal set of an insertion plan, the goal set against friction.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdlib.h>
#include <string.h>

#include "analysis/plan.h"
#include "analysis/stability.h"
#include "draw/figure.h"

static const char no_shape[] = " The problem gives no shape, so there is "
    "no boundary to push on: only the fixels are drawn.";

static int
ends_legend(_wc_scene_t S)
{
    int status = _wc_scene_legend(S, _WC_TAG_END_CLOSED, 0,
                                  "end in the region (closed)");

    if (status == WC_OK)
        status = _wc_scene_legend(S, _WC_TAG_END_OPEN, 0,
                                  "end not in the region (open)");
    return status;
}

int
_wc_draw_stability(_wc_scene_t S, const wc_problem_t P, wc_error_t err)
{
    const char * words[3] = { "strongly stable (exact semantics)",
                              "strongly stable (paper, eq. 19)",
                              "weakly stable" };
    wc_stability_t T;
    int status, k;

    wc_stability_init(T);
    status = wc_stability(T, P, err);
    if (status == WC_OK)
        status = _wc_draw_part(S, P);
    if (status == WC_OK && T->has_push)
    {
        const wc_push_struct * R[3] = { T->push_strong, T->push_strong_paper,
                                        T->push_weak };

        for (k = 0; k < 3 && status == WC_OK; k++)
        {
            status = _wc_draw_region(S, P, R[k], k);
            if (status == WC_OK)
                status = _wc_scene_legend(S, _WC_TAG_REGION, k, "push here: "
                                          "%s", words[k]);
        }
        if (status == WC_OK)
            status = ends_legend(S);
    }
    if (status == WC_OK)
        status = _wc_draw_titles(S, P, "Stability: where a frictionless "
                                 "finger may push", ". Thick strokes on the "
                                 "boundary: the places where pushing with a "
                                 "frictionless finger gives a wrench in each "
                                 "set, innermost the strongly stable set "
                                 "(exact semantics), then eq. 19's, then the "
                                 "weakly stable set.%s",
                                 T->has_push ? "" : no_shape);
    wc_stability_clear(T);
    return status;
}

int
_wc_draw_plan(_wc_scene_t S, const wc_problem_t P, wc_error_t err)
{
    wc_plan_t R;
    int status;

    wc_plan_init(R);
    status = wc_plan(R, P, 0, err);
    if (status == WC_OK)
        status = _wc_draw_part(S, P);
    if (status == WC_OK && R->has_push)
    {
        status = _wc_draw_region(S, P, R->push_goal, 0);
        if (status == WC_OK)
            status = _wc_scene_legend(S, _WC_TAG_REGION, 0, "push here: "
                                      "G_goal (seats the part from any "
                                      "state)");
        if (status == WC_OK)
            status = ends_legend(S);
    }
    if (status == WC_OK)
        status = _wc_draw_titles(S, P, "Insertion plan: the goal set G_goal",
                                 ". G_goal (eq. 21) is %s; the thick strokes "
                                 "are where pushing with a frictionless "
                                 "finger seats the part against all %ld "
                                 "fixels from any contact state. G_goal %s "
                                 "within the strongly stable set of the goal "
                                 "state (eq. 25, exact semantics).%s",
                                 !R->goal->empty ? "not empty" : "empty",
                                 (long) P->n, R->goal_in_strong ? "lies"
                                 : "does not lie", R->has_push ? "" : no_shape);
    wc_plan_clear(R);
    return status;
}

int
_wc_draw_sweep(_wc_scene_t S, const wc_problem_t P, const fmpq * mu,
               slong k, wc_error_t err)
{
    wc_plan_t R;
    slong i;
    int status = _wc_draw_part(S, P), shape = P->shape != WC_SHAPE_NONE;
    char * m;

    for (i = 0; i < k && status == WC_OK; i++)
    {
        wc_plan_init(R);
        status = wc_plan_with_friction(R, P, mu + i, err);
        if (status == WC_OK && R->has_push)
            status = _wc_draw_region(S, P, R->push_goal, (int) i);
        if (status == WC_OK && (m = _wc_draw_fmpq_str(mu + i)) == NULL)
            status = WC_EINTERNAL;
        if (status == WC_OK)
        {
            status = _wc_scene_legend(S, _WC_TAG_REGION, (int) i,
                                      "G_goal at mu = %s%s", m,
                                      !R->goal->empty ? "" : " (empty)");
            free(m);
        }
        wc_plan_clear(R);
    }
    if (status == WC_OK && shape)
        status = ends_legend(S);
    if (status == WC_OK)
        status = _wc_scene_title(S, "Insertion plan against friction");
    if (status == WC_OK)
        status = _wc_scene_caption(S, "%s: where a frictionless finger may "
                                   "push to seat the part, for each friction "
                                   "value (mu_s = mu_k = mu at every fixel), "
                                   "the first on the boundary, each next one "
                                   "further out. Higher friction: a smaller "
                                   "G_goal.%s", _wc_draw_name(P),
                                   shape ? "" : no_shape);
    return status;
}
