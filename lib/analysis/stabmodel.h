/* stabmodel.h -- internal: the problem as the stability analysis reads
   it, once per problem.  Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Shared by classify.c (one wrench), stability.c (the sets) and
   facesys.c (the system of one moving face).  */

#ifndef WC_STABMODEL_H
#define WC_STABMODEL_H

#include <flint/fmpq.h>
#include <flint/fmpq_mat.h>

#include "core/error.h"
#include "core/problem.h"
#include "analysis/kinematics.h"
#include "analysis/stability.h"

typedef struct
{
    const wc_problem_struct * P;
    slong n, t;
    slong * tidx;           /* the touching fixels, in file order */
    fmpq * Jn, * Jt;        /* 3n each: J's columns n_i, t_i */
    fmpq M[3];              /* diag(m, m, I) */
    int shared;             /* t >= 1 and every touching fixel at one point */
    fmpq v[3];              /* Jn x Jt of the first touching fixel: the
                               rotation about the shared point */
}
_wc_stab_model;

void _wc_stab_model_init(_wc_stab_model * m, const wc_problem_t P);
void _wc_stab_model_clear(_wc_stab_model * m);

/* w (3) := e_n J_in + e_t J_it, e = (e_n, e_t) a friction edge of i.  */
void _wc_stab_edge_wrench(fmpq * w, const _wc_stab_model * m, slong i,
                          const fmpq * e);

/* The rows -w over the friction edges of letters x (touching fixels),
   skipping fixel skip (or -1): Q is resized to their number x 3.  */
void _wc_stab_edge_rows(fmpq_mat_t Q, const _wc_stab_model * m,
                        const char * x, slong skip);

/* Call visit(ctx, y, rot) on every moving face of the touching fixels, in
   order: the faces of their arrangement other than n..n (rot = 0, y from
   wc_modes_enumerate's sorted modes, u on near fixels), then, when every
   touching fixel shares a point, the two rotation faces (y = n..n, rot =
   1 then -1).  Stops at the first status other than WC_OK, and returns
   it.  m must have a touching fixel.  */
int _wc_stab_moving_faces(const _wc_stab_model * m,
                          int (* visit)(void * ctx, const char * y, int rot),
                          void * ctx, wc_error_t err);

/* The same over T, the modes of the touching fixels alone (as
   wc_modes_enumerate gives them; when every fixel touches, the
   problem's own modes).  */
int _wc_stab_moving_faces_of(const _wc_stab_model * m, const wc_modes_t T,
                             int (* visit)(void * ctx, const char * y,
                                           int rot),
                             void * ctx, wc_error_t err);

/* The full-length string (malloc'd) of touching-only mode s: u on near
   fixels.  */
char * _wc_stab_expand(const _wc_stab_model * m, const char * s);

/* 1 when y has n on every touching fixel.  */
int _wc_stab_all_n(const _wc_stab_model * m, const char * y);

/* Is g (3) weakly stable?  1 with static forces c (2n: c_1n .. c_nn,
   c_1t .. c_nt) in the mu_s friction cones, g = -J c; 0 with sep (3),
   sep . g > 0 and sep . (J_in +- mu_s J_it) >= 0 at every touching fixel
   (sep = g when none touches); -1 on failure (err set).  */
int _wc_stab_weak(fmpq * c, fmpq * sep, const _wc_stab_model * m,
                  const fmpq * g, wc_error_t err);

/* A motion with room for n fixels' forces (sign NULL); the clear frees
   sign.  */
void _wc_motion_init(wc_motion_struct * a, slong n);
void _wc_motion_clear(wc_motion_struct * a, slong n);

#endif
