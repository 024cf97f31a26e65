/* facesys.h -- internal: is there a motion of one moving face for a
   wrench, or a certificate that there is none.  Private.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_FACESYS_H
#define WC_FACESYS_H

#include <flint/fmpq.h>

#include "core/error.h"
#include "analysis/stabmodel.h"

/* Solve the face (y, x, rot) for the wrench g: y has one letter per fixel
   for the rows on nudot (touching s l r n; near u, s (a_in >= 0) or a
   (a_in < 0)), x the force letters (touching s l r n; near ones carry
   none), rot != 0 the rotation face (y is then ignored on touching
   fixels).  Returns 1 with a motion, nudot (3) and forces c (2n); 0
   without, with the Motzkin multipliers of the face's rows
   (wrenchcone-certificate(5)) in
   *mult (malloc'd, *nmult entries) when mult is not NULL; -1 on failure
   (err set).  */
int _wc_face_solve(fmpq * nudot, fmpq * c, fmpq ** mult, slong * nmult,
                   const _wc_stab_model * m, const char * y, const char * x,
                   int rot, const fmpq * g, wc_error_t err);

/* The same for the cone of wrenches sum_i alpha_i G_i with every
   alpha_i > 0 (G: ng wrenches, 3 entries each; ng = 0 the zero wrench):
   the system's last ng columns are the alpha_i, each with a row
   alpha_i > 0 (ng = 1 is the system above, alpha_1 its tau).  closed
   relaxes y's > rows on nudot to >= (the closure of the face).  A motion
   is filled in only for ng = 1 and nudot not NULL.  */
int _wc_face_solve_cone(fmpq * nudot, fmpq * c, fmpq ** mult,
                        slong * nmult, const _wc_stab_model * m,
                        const char * y, const char * x, int rot,
                        const fmpq * G, slong ng, int closed,
                        wc_error_t err);

/* The multipliers of the face (y, rot) (force letters y too) for the
   wrenches sum alpha_i G_i, alpha_i > 0, built from a plane h . g = 0
   with the face's cone on the side h . g <= 0 and the G_i on the other
   (h . G_i >= 0, one > 0, or all 0 and a strict row of the face to
   carry the weight), without an LP: 1 with *mult (malloc'd,
   *nmult entries, checked against the rows); 0 when h does not serve;
   -1 on failure (err set).  */
int _wc_face_facet_mult(fmpq ** mult, slong * nmult,
                        const _wc_stab_model * m, const char * y, int rot,
                        const fmpq * h, const fmpq * G, slong ng,
                        wc_error_t err);

/* 1 when a plane separating g from the closure of the face's wrench
   cone, turned into Motzkin multipliers checked against the face's rows,
   proves that the face (y, x, rot) has no motion for g; 0 when that
   cannot tell (g in the closure, or no = row on nudot); -1 on failure
   (err set).  The quick proof _wc_face_solve tries before an LP, here
   for the tests.  */
int _wc_face_separate(const _wc_stab_model * m, const char * y,
                      const char * x, int rot, const fmpq * g,
                      wc_error_t err);

#endif
