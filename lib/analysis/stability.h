/* stability.h -- weak and strong stability of a fixtured workpiece
   (paper Section 7, wrenchcone(1), stability), one wrench at a time or as exact sets.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Weakly stable: a static solution exists, g = -J c with every touching
   fixel's force in its friction cone (mu_s) and no force at near fixels.

   Moving solutions (nudot != 0) at zero velocity are grouped by the
   contact mode of the motion, a string with one letter per fixel: for a
   touching fixel s (a_in > 0), l (a_in = 0, a_it > 0), r (a_in = 0,
   a_it < 0) or n (a_in = 0, a_it = 0), where a = J^T nudot; u for a near
   fixel (no force, no constraint).  The strings that occur are those of
   the faces of the arrangement of the touching fixels' planes
   J_k . nudot = 0 (wrenchcone(1), stability), found with wc_modes_enumerate: O(n^2) of
   them, never 4^n.  The string n..n holds nudot != 0 only when every
   touching fixel has the same contact point (rotation about it); it then
   counts as two faces, rotating either way.

   Strongly stable (exact semantics, Pang and Trinkle): weakly stable and
   no moving solution.  Paper semantics (eq. 19): g lies in no W(x) for a
   Table 2 string x with s, l, r or n on each touching fixel (u on near
   ones) other than n on all of them.  The two differ; they are never
   mixed.  */

#ifndef WC_STABILITY_H
#define WC_STABILITY_H

#include <flint/fmpq.h>
#include <flint/fmpz_mat.h>

#include "core/error.h"
#include "core/limits.h"
#include "core/problem.h"
#include "exact/cone.h"
#include "exact/cells.h"
#include "analysis/push.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A solution with its mode string: nudot (3) and the forces c (2n:
   c_1n .. c_nn, c_1t .. c_nt) with M nudot = J c + g.  */
typedef struct
{
    char * sign;
    fmpq nudot[3];
    fmpq * c;
}
wc_motion_struct;

/* A moving face without a solution for the wrench, with the Motzkin
   multipliers proving it (wrenchcone-certificate(5) gives the rows),
   filled only when
   certificates are asked for.  */
typedef struct
{
    char * sign;
    int rotation;           /* 0, or +1 / -1 for the rotation faces */
    slong nmult;
    fmpq * mult;
}
wc_noface_struct;

typedef struct
{
    slong n;
    fmpq g[3];
    /* Table 2 strings (s l r n on touching, s a on near fixels) whose
       cone holds g, ASCII-sorted.  */
    slong nmodes;
    char ** modes;
    int modes_complete;     /* 0 when the list stopped at max_modes */
    int weak;
    fmpq * weak_c;          /* 2n forces of a static solution (weak) */
    fmpq weak_sep[3];       /* y with y . g > 0 and y . (J_in +- mu_s J_it)
                               >= 0 for every touching fixel (not weak) */
    int strong;             /* exact semantics */
    int strong_paper;       /* eq. 19 */
    int paper_vacuous;      /* no fixel touches: eq. 19 excludes nothing */
    /* Every moving face with a solution, by sign string (rotation faces
       as two entries "n..n"), with a witness.  */
    slong nmotions;
    wc_motion_struct * motions;
    /* When !strong_paper: a string x != n..n (Table 2, u on near fixels)
       whose cone holds g, with a solution of it.  */
    wc_motion_struct paper;
    /* With certificates: every moving face without a solution.  */
    slong nnofaces;
    wc_noface_struct * nofaces;
}
wc_classify_struct;

typedef wc_classify_struct wc_classify_t[1];

void wc_classify_init(wc_classify_t R);
void wc_classify_clear(wc_classify_t R);

/* Classify the wrench g (3 entries) for P with exact LPs only (no cone
   conversion).  The verdicts and the motions take O(n^2) LPs of O(n)
   size at most (one per moving face).  The list of modes holding g can be
   exponentially long (a wrench held by three of t touching fixels is held
   by every string that leaves any of the others unloaded: 2^(t-3) of
   them); it is searched output-sensitively -- a fixel that carries no
   force in the solution at hand is unloaded without an LP -- and stops
   after max_modes strings (max_modes <= 0: no limit), clearing
   modes_complete.  certificates != 0 also fills nofaces.  Returns WC_OK,
   WC_EINPUT (bad problem), WC_EINTERNAL.  */
int wc_classify(wc_classify_t R, const wc_problem_t P, const fmpq * g,
                int certificates, slong max_modes, wc_error_t err);

/* The printers of classifications, sets and their certificates are in
   io/print.h.  */

/* The sets.  */
typedef struct
{
    wc_cone_t weak;         /* closed: -J (friction cones) */
    wc_set_t strong;        /* exact semantics */
    wc_set_t strong_paper;  /* eq. 19 */
    int paper_in_weak;      /* strong_paper is a subset of weak */
    int paper_vacuous;      /* no fixel touches: eq. 19's union is empty,
                               so strong_paper is R^3 and says nothing */
    /* A wrench in one set and not the other (in the symmetric
       difference), when they differ, with which set holds it: a nonzero
       one whenever there is one; diff_origin_only when the origin is the
       only wrench in the difference.  */
    int differ;
    int diff_origin_only;
    fmpq diff_g[3];
    int diff_in_exact;
    /* The cones the sets are built from, and the planes of their
       arrangement (for push regions and robustness).  */
    slong nmoving;
    wc_cone_struct * moving;        /* exact: the moving faces' cones,
                                       W_y = M V_y + (-J) D_y */
    char ** moving_sign;
    int * moving_rot;               /* 0; +-1 for the rotation faces; 2
                                       for the six pieces of R^3 minus
                                       the origin when no fixel touches */
    slong nunion;
    wc_cone_struct * paper_union;   /* eq. 19's union is the moving cones
                                       other than the rotation faces, and
                                       these: for each touching fixel i,
                                       M L0 + (-J) D with no force at i
                                       (L0: nudot with a = 0 at every
                                       touching fixel) */
    wc_cells_t cells;
    int has_push;
    wc_push_t push_weak, push_strong, push_strong_paper;
}
wc_stability_struct;

typedef wc_stability_struct wc_stability_t[1];

void wc_stability_init(wc_stability_t S);
void wc_stability_clear(wc_stability_t S);

/* Compute every set exactly (and the push regions when P has a shape).
   Returns WC_OK, WC_EINPUT, WC_EINTERNAL.  */
int wc_stability(wc_stability_t S, const wc_problem_t P, wc_error_t err);

/* Robustness of a biasing wrench b in a set (the paper's figure, Section
   7): the largest rho such that every disturbance delta with
   ||delta|| < rho keeps b + delta in the set, where
   ||(fx, fy, tau)|| = max(|fx|, |fy|, |tau| / L) (L > 0, a length that
   makes torque comparable with force).  rho is rational: the smallest
   distance, in that norm, from b to the closure of a piece of the
   complement.  rho = 0 when b is not in the interior of the set.
   closed is 1 when even ||delta|| <= rho keeps b + delta in the set.
   Returns WC_OK or WC_EINTERNAL.  rho may be infinite only when the set
   is all of R^3: then *infinite = 1.  */
int wc_robustness(fmpq_t rho, int * closed, int * infinite,
                  const wc_set_t set, const wc_cells_t cells,
                  const fmpq * b, const fmpq_t L, wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
