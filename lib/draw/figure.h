/* figure.h -- the figures of wrenchcone draw, each built as a scene from
   exact results (wrenchcone(1), draw).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Every function fills a freshly initialised scene S and returns WC_OK,
   WC_EINPUT (err set, located: a bad problem, a mode invalid for it, too
   many fixels for the analysis) or WC_EINTERNAL.  On failure S holds a
   partial scene the caller clears.  */

#ifndef WC_DRAW_FIGURE_H
#define WC_DRAW_FIGURE_H

#include <flint/fmpq.h>

#include "core/error.h"
#include "core/problem.h"
#include "core/limits.h"
#include "analysis/push.h"
#include "io/print.h"
#include "draw/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The part (polygon, disk, or a dashed frame round the fixels), its
   centre of mass, the fixels with their normals and friction cones.
   Sets S->scale.  */
int _wc_draw_part(_wc_scene_t S, const wc_problem_t P);

/* A pushing region as thick strokes on the boundary of P's shape, moved
   outwards by layer times 4% of S->scale (layer 0 lies on it), with a
   dot at each end: filled for a closed end, hollow for an open one.  */
int _wc_draw_region(_wc_scene_t S, const wc_problem_t P, const wc_push_t R,
                    int layer);

/* The figures.  mode: W(mode) as lines of force.  modes: a rotation
   centre (or translation) per feasible mode.  stability: the pushing
   regions of the stability sets.  plan: those of G_goal.  sweep: those
   of G_goal at each of the k friction values mu[0..k).  graph: the
   contact states of the insertion plan and the transitions it forbids
   and allows; with a wrench g (not NULL), those g admits under the
   complete plan.  */
int _wc_draw_mode(_wc_scene_t S, const wc_problem_t P, const char * mode,
                  wc_error_t err);
int _wc_draw_modes(_wc_scene_t S, const wc_problem_t P, wc_error_t err);
int _wc_draw_stability(_wc_scene_t S, const wc_problem_t P, wc_error_t err);
int _wc_draw_plan(_wc_scene_t S, const wc_problem_t P, wc_error_t err);
int _wc_draw_sweep(_wc_scene_t S, const wc_problem_t P, const fmpq * mu,
                   slong k, wc_error_t err);
int _wc_draw_graph(_wc_scene_t S, const wc_problem_t P, const fmpq * g,
                   wc_error_t err);

/* The problem's name for captions (its file's without one).  */
const char * _wc_draw_name(const wc_problem_t P);

/* P's friction for captions, malloc'd: "1/5", or "1/2 static, 2/5
   kinetic"; NULL when out of memory.  */
char * _wc_draw_friction(const wc_problem_t P);

/* The figure's title, and its caption: "NAME, friction MU" (P's), then
   fmt formatted with the arguments.  */
int _wc_draw_titles(_wc_scene_t S, const wc_problem_t P, const char * title,
                    const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* The HTML page of `wrenchcone report`: every analysis of P with its
   figures, the command lines naming the problem path, the analyses'
   text as o says (its decimals; io/print.h).  An analysis P is too large
   for is named on the page with its limit's message.  Returns WC_OK, or
   WC_EINTERNAL (err set).  */
int _wc_report_fprint(FILE * out, const wc_problem_t P, const char * path,
                      const wc_print_opts * o, wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
