/* ref-modes.h -- the independent reference for wc_modes_enumerate
   (ref-modes.c): a depth-first search over mode strings, one exact LP
   per prefix; and the faces of the arrangement by ref-cells.c.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_TESTS_REF_MODES_H
#define WC_TESTS_REF_MODES_H

#include <flint/flint.h>

#include "core/problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Every kinematically feasible mode of P (Table 1 letters: s l r n on
   touching fixels, s a on near ones), in *modes (a malloc'd array of
   *count malloc'd strings, sorted by strcmp; free with ref_modes_free of
   ref-kin.h).  *lps (when not NULL) gets the number of LPs solved.
   Returns 0, or -1 when an LP failed (then *modes is NULL, *count 0).  */
int ref_modes_search(char *** modes, slong * count, slong * lps,
                     const wc_problem_t P);

/* The same list by another method, for problems too large for the
   search: the faces of the arrangement of the 2n planes J_in . nu = 0,
   J_it . nu = 0 (J computed here from P's fields) from ref-cells.c, each
   non-penetrating face read as its mode.  Returns 0 or -1 as above.  */
int ref_modes_faces(char *** modes, slong * count, const wc_problem_t P);

#ifdef __cplusplus
}
#endif

#endif
