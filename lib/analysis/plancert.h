/* plancert.h -- internal: the proof that a plan's goal set G_goal is
   exact (wrenchcone-certificate(5), PLAN GOAL SETS).  Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   G_goal is the set of wrenches in the cone of no plan string; the
   strings that matter are those with exactly one s (every other string's
   cone lies in one of theirs), and their cones W(x) are closed.  Each
   included face F of a goal piece is proved to miss every W(x): Motzkin
   multipliers showing that no sum alpha_i G_i, every alpha_i > 0, lies in
   W(x).  Each W(x) is proved to hold its generators: a solution of the
   string's system at each.  Each region of the tree is placed in a face of a goal piece
   or of a W(x) (setcert.h).  */

#ifndef WC_PLANCERT_H
#define WC_PLANCERT_H

#include <flint/fmpq.h>

#include "core/error.h"
#include "analysis/plan.h"
#include "analysis/stabmodel.h"
#include "analysis/setcert.h"

typedef struct
{
    _wc_setcert base;
    const wc_plan_struct * R;
    _wc_stab_model m;           /* J and M of every fixel */
    fmpq * mu;                  /* n: max(mu_s, mu_k), the plan model */
}
_wc_plancert;

/* mu (P->n) := max(mu_s, mu_k) at each fixel: the plan model's
   friction.  */
void _wc_plan_model_mu(fmpq * mu, const wc_problem_t P);

/* The system of string x (plancert.c) for the ng wrenches G, with the
   model m and the friction mu: 1 with a solution (for ng = 1, nudot and
   its forces c, 2 n, when nudot is not NULL), 0 with the multipliers in
   *mult (malloc'd, *nmult of them) when mult is not NULL, -1 on failure
   (err set).  */
int _wc_plan_string_solve(fmpq * nudot, fmpq * c, fmpq ** mult,
                          slong * nmult, const _wc_stab_model * m,
                          const fmpq * mu, const char * x, const fmpq * G,
                          slong ng, wc_error_t err);

int _wc_plancert_init(_wc_plancert * C, const wc_problem_t P,
                      const wc_plan_t R, wc_error_t err);
void _wc_plancert_clear(_wc_plancert * C);

/* cp := the solutions at the generators of needed string j's cone
   (cp->motion NULL: the cone is closed).  */
int _wc_plancert_cone(_wc_cone_proof * cp, _wc_plancert * C, slong j,
                      wc_error_t err);

/* pp := the multipliers of every included face of goal piece k against
   every needed string (pp->c NULL).  */
int _wc_plancert_piece(_wc_piece_proof * pp, _wc_plancert * C, slong k,
                       wc_error_t err);

/* The tree's classifier (setcert.h) for the goal set: a region in a
   goal piece or in a string's cone.  ctx is C.  */
int _wc_plancert_classify(void * ctx, const _wc_region3 * R,
                          const fmpz * sum, _wc_tree_node * leaf,
                          fmpz * sep, fmpz * plane, wc_error_t err);

/* *h := the planes the tree's basis is best taken from (*n of them; free
   with _fmpz_vec_clear(*h, 3 *n + 3)).  */
void _wc_plancert_prefer(fmpz ** h, slong * n, const _wc_plancert * C);

#endif
