/* old-faces.h -- the previous implementation of the moving faces, kept
   to catch regressions (t-faces); not an independent reference
   (old-faces.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_TESTS_OLD_FACES_H
#define WC_TESTS_OLD_FACES_H

#include "check/faces.h"

/* What _wc_check_moving_faces computes, by walking every cell of the
   arrangement: every sign string S(nudot) with a_in >= 0 at every
   touching fixel of P, other than n..n, into out, sorted, each once; J
   holds J_in and J_it of every fixel (6 n).  WC_OK or WC_EINTERNAL.  */
int old_moving_faces(wc_check_strings * out, const wc_check_problem * P,
                     mpq_t * J);

#endif
