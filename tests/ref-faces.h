/* ref-faces.h -- the independent reference for the moving faces of the
   certificate checker (ref-faces.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_TESTS_REF_FACES_H
#define WC_TESTS_REF_FACES_H

#include <stddef.h>

#include "check/faces.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What _wc_check_moving_faces documents: every sign string S(nudot) --
   per touching fixel s (a_in > 0), l (a_in = 0, a_it > 0), r (a_in = 0,
   a_it < 0) or n (both 0), per near fixel u -- of an nudot with
   a_in >= 0 at every touching fixel, other than the zero face's (n on
   every touching fixel), each once, sorted by strcmp, in *out (a malloc'd
   array of *count malloc'd strings; free with ref_faces_free).  J is
   computed here from P's com and fixels.  Returns 0, or -1 when out of
   memory or the enumeration failed.  */
int ref_faces_moving(char *** out, size_t * count,
                     const wc_check_problem * P);

void ref_faces_free(char ** s, size_t count);

#ifdef __cplusplus
}
#endif

#endif
