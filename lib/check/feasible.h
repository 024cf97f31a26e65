/* feasible.h -- internal: the check of a mode-feasibility
   certificate (feasible.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  GMP and lib/core only, as all of lib/check
   (checker.h).  */

#ifndef WC_CHECK_FEASIBLE_H
#define WC_CHECK_FEASIBLE_H

#include "check/checker.h"

/* Check the mode-feasibility certificate at root (its kind read).
   Returns c->status; with WC_OK, *holds, why, *mode (malloc'd: the caller
   frees) and *feasible.  */
int _wc_check_mode_certificate(wc_check_reader * c,
                               const wc_json_node * root, int * holds,
                               wc_check_text * why, char ** mode,
                               int * feasible);

#endif
