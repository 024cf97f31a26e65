/* critcheck.h -- internal: the check of a critical-friction
   certificate (critcheck.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  GMP and lib/core only, as all of lib/check
   (checker.h).  The check runs set certificates' checks
   (setcheck.h).  */

#ifndef WC_CHECK_CRITCHECK_H
#define WC_CHECK_CRITCHECK_H

#include "check/checker.h"

/* Check the critical-friction certificate at root (its kind
   read).  */
int _wc_check_crit_certificate(wc_check_reader * c,
                               const wc_json_node * root, int * holds,
                               wc_check_text * why, wc_check_text * what);

#endif
