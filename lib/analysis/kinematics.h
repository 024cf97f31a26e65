/* kinematics.h -- kinematic feasibility of contact modes (wrenchcone(1) MODES, paper
   Table 1), with certificates.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A mode string (Table 1 letters: s l r n on touching fixels, s a on near
   ones) constrains the contact velocities v = J^T nu of a twist nu:
     touching s: v_in > 0          touching l: v_in = 0, v_it > 0
     touching r: v_in = 0, v_it < 0   touching n: v_in = 0, v_it = 0
     near a: v_in < 0              near s: v_in >= 0
   It is feasible iff some twist satisfies all of them.  Every constraint
   is a row of the form  row . nu REL 0  with REL one of >, >=, =, where
   row is J_in or J_it (or its negative for < 0), made a primitive integer
   vector.  */

#ifndef WC_KINEMATICS_H
#define WC_KINEMATICS_H

#include <flint/fmpz_mat.h>

#include "core/problem.h"
#include "core/limits.h"
#include "exact/relation.h"

#ifdef __cplusplus
extern "C" {
#endif

/* wc_relation and wc_relation_str: exact/relation.h.  */

/* The constraint rows of mode on the twist, in fixel order (for each
   fixel: its normal row, then its tangential row when the letter
   constrains it).  rows is resized to m x 3; *rel is malloc'd with m
   entries (caller frees with free()).  The mode must pass wc_mode_check with
   WC_TABLE_KINEMATIC; returns WC_EINPUT otherwise.  */
int wc_mode_constraints(fmpz_mat_t rows, wc_relation ** rel,
                        const wc_problem_t P, const char * mode,
                        wc_error_t err);

/* All kinematically feasible modes of P, each with a witness twist. */
typedef struct
{
    slong n;            /* fixels: every mode has n letters */
    slong count;
    char ** modes;      /* sorted (ASCII), each NUL-terminated */
    fmpz_mat_t witness; /* count x 3: a primitive integer twist per mode
                           (zero for the mode holding nu = 0) */
}
wc_modes_struct;

typedef wc_modes_struct wc_modes_t[1];

void wc_modes_init(wc_modes_t M);
void wc_modes_clear(wc_modes_t M);

/* Enumerate the feasible modes by the faces of the central arrangement of
   the 2n planes J_k . nu = 0 in R^3 that lie in the cone K of
   non-penetrating twists (v_in >= 0 on every touching fixel), mapping
   each to its mode: K first (one 3-D conversion of the touching rows),
   then only the planes meeting K beyond the origin are arranged, inside
   K.  Never looks at the 4^n strings, nor at the O(n^2) faces outside K;
   time one conversion plus O(n g) for K's g generators, O(L^2 log L) for
   the L planes meeting K, and O(n) per face inside K.  Each mode's
   witness is a point of the first face mapping to it in the walk of the
   whole arrangement (modeswalk.c).  M may hold an earlier result (it is
   replaced).  Returns WC_OK (M filled) or WC_EINPUT when
   wc_problem_check fails, P has more than WC_MODES_MAX_FIXELS fixels or
   more than WC_MODES_MAX_NEAR of them near.  The m near fixels bound
   the output: O(m^2 + n) modes of n letters (a near fixel's plane may
   cross K anywhere, a touching fixel's tangent plane only K's facet of
   that fixel), m^2 n bytes where every fixel is near.  */
int wc_modes_enumerate(wc_modes_t M, const wc_problem_t P, wc_error_t err);

/* The certificate of one mode: either a witness twist (primitive
   integers) satisfying every constraint row, or Motzkin multipliers y
   (primitive integers, as few nonzero as a basic solution gives) with
   sum_k y_k rows_k = 0, y_k >= 0 on > and >= rows, and y_k > 0 on at
   least one > row -- which proves that no twist satisfies the rows.  */
typedef struct
{
    char * mode;
    int feasible;
    fmpz witness[3];
    fmpz_mat_t rows;    /* m x 3 */
    wc_relation * rel;  /* m */
    fmpz * mult;        /* m multipliers (zero when feasible) */
}
wc_certificate_struct;

typedef wc_certificate_struct wc_certificate_t[1];

void wc_certificate_init(wc_certificate_t C);
void wc_certificate_clear(wc_certificate_t C);

/* Decide mode (Table 1 letters) for P and fill C (which may hold an
   earlier certificate: it is replaced).  The certificate is checked with
   wc_certificate_check before it is returned.  Returns WC_OK, WC_EINPUT
   for a bad problem or mode (err located in "<mode>" for the mode), or
   WC_EINTERNAL.  */
int wc_feasible(wc_certificate_t C, const wc_problem_t P, const char * mode,
                wc_error_t err);

/* 1 when C is internally consistent (exact integer arithmetic), else 0:
   when feasible, the witness satisfies every row (it need not be
   primitive); when not, the multipliers satisfy the three Motzkin
   conditions (the witness is ignored).  It does not check that the rows
   are the ones the mode implies for a problem -- wc_feasible builds them
   so, and wc_verify_certificate re-derives them.  */
int wc_certificate_check(const wc_certificate_t C);

#ifdef __cplusplus
}
#endif

#endif
