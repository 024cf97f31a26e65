/* stabcert.h -- internal: the proof, cell by cell, that a strong
   stability set is exact (wrenchcone-certificate(5), STABILITY SETS).
   Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The set computed by wc_stability is a union of cells of the
   arrangement of its cones' planes.  Each cell is proved on its own, over
   the extreme rays r_1 .. r_k of its closure: a cell in the set by
   static forces at each ray (so its closure is weakly stable) and, for
   every moving face, Motzkin multipliers showing that no wrench
   sum alpha_i r_i with every alpha_i > 0 has a motion of the face; a cell
   outside it by a separator (not weakly stable), or by one moving face
   with a motion of the closed face at each ray and of the face itself at
   the sum of the rays (the cell lies in that face's cone).  */

#ifndef WC_STABCERT_H
#define WC_STABCERT_H

#include <flint/fmpq.h>

#include "core/error.h"
#include "analysis/stabmodel.h"
#include "analysis/stability.h"

typedef enum
{
    WC_CELL_STRONG = 0,         /* in the set */
    WC_CELL_NOT_WEAK = 1,       /* outside: a separator */
    WC_CELL_MOVES = 2           /* outside: a moving face's cone */
}
wc_cell_reason;

/* The proof of one cell.  */
typedef struct
{
    wc_cell_reason reason;
    int weak;                   /* a ray in the weak cone: weak_c */
    fmpq * weak_c;              /* 2 n */
    fmpq sep[3];                /* WC_CELL_NOT_WEAK */
    slong face;                 /* WC_CELL_MOVES: index in the face list */
    slong nrays;
    wc_motion_struct * closure; /* WC_CELL_MOVES: one per ray */
    wc_motion_struct motion;    /* WC_CELL_MOVES: at the sum of the rays */
    fmpq ** mult;               /* WC_CELL_STRONG: one list per face */
    slong * nmult;
}
_wc_cell_proof;

/* What the proofs of one stability computation share.  */
typedef struct
{
    const wc_stability_struct * S;
    _wc_stab_model m;
    slong * off, * ray;         /* the rays of each cell (wc_cells_rays) */
    slong nfaces;               /* the moving faces: S->moving without */
    slong * face;               /* the pieces of a problem with nothing
                                   touching (index into S->moving) */
    fmpq * G;                   /* 3 * (the most rays of a cell + 1) */
    slong gcap;
}
_wc_stabcert;

int _wc_stabcert_init(_wc_stabcert * C, const wc_problem_t P,
                      const wc_stability_t S, wc_error_t err);
void _wc_stabcert_clear(_wc_stabcert * C);

void _wc_cell_proof_init(_wc_cell_proof * pf, const _wc_stabcert * C);
void _wc_cell_proof_clear(_wc_cell_proof * pf, const _wc_stabcert * C);

/* pf := the proof of cell i (pf initialised for C, reused across cells).
   Returns WC_OK, or WC_EINTERNAL when a proof cannot be found -- the set
   is then wrong, and that is a bug.  */
int _wc_stabcert_cell(_wc_cell_proof * pf, _wc_stabcert * C, slong i,
                      wc_error_t err);

#endif
