/* verify.h -- re-check a certificate with GMP alone: mode feasibility
   and strong stability.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The checker behind `wrenchcone verify`.  It shares no code with the
   machinery that writes certificates (kinematics.c, stability.c, FLINT,
   cddlib): it reads the JSON with json.c, recomputes everything the
   certificate's claim rests on from the problem with GMP rationals, and
   checks the witnesses and Motzkin multipliers with exact arithmetic.

   The two formats (kind "mode-feasibility", written by `wrenchcone
   feasible --certificate`, and kind "strong-stability", written by
   `wrenchcone classify --certificate`), every condition checked, what is
   computed again from the problem rather than trusted (the rows of a
   mode, the Jacobian, the set of moving faces), the verdict lines and
   the exit statuses are described in man/wrenchcone-certificate.5, the
   manual page wrenchcone-certificate(5).  Change that page with the
   code.  */

#ifndef WC_VERIFY_H
#define WC_VERIFY_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"
#include "core/limits.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Check the mode-feasibility certificate text[0..len) (any bytes; a
   strong-stability certificate is bad input here), read from file (the
   name used in error records; may be NULL).  Returns WC_OK and sets
   *holds to 1 or 0; when 0, *reason (malloc'd, caller frees; else NULL)
   says in one line why.  *mode and *feasible (when not NULL) receive what
   the certificate claims (*mode malloc'd, caller frees).  Returns
   WC_EINPUT with err located FILE:LINE:COL at the offending JSON value
   when the text is not a well-formed certificate (the first such error in
   file order), WC_EINTERNAL when out of memory; then *holds is 0 and
   *reason and *mode are NULL.  Uses GMP only.  */
int wc_verify_certificate(int * holds, char ** reason, char ** mode,
                          int * feasible, const char * text, size_t len,
                          const char * file, wc_error_t err);

/* Check a certificate of any kind: text, len and file as above.
   Returns WC_OK and sets *holds to 1 or 0; *summary (malloc'd, caller
   frees) to a one-line account of what the certificate claims, which is
   what it proves when *holds is 1:
     "mode ln is infeasible", "mode ss is feasible";
     "wrench (0, -1, 0) is strongly stable: 9 moving faces excluded",
     "wrench (-1, -1, -1) is weakly stable but moves in mode ls",
     "wrench (0, 1, 0) is not weakly stable";
     "the strongly stable set is exact: 1 piece, 9 moving faces, 267
     cells";
   and when *holds is 0, *reason (malloc'd, caller frees; else NULL) to
   one line saying what failed.  Returns WC_EINPUT, located as
   wc_verify_certificate does, when the text is not a well-formed
   certificate (an unknown kind included), WC_EINTERNAL when out of
   memory; then *holds is 0 and *reason and *summary are NULL.  A
   mode-feasibility certificate gets the same verdict and reason from
   both functions.  Uses GMP only.  */
int wc_verify(int * holds, char ** reason, char ** summary,
              const char * text, size_t len, const char * file,
              wc_error_t err);

/* Check a certificate of any kind (text, len and file as above) and
   write the verdict to out in one line: "certificate holds: SUMMARY" or
   "certificate does not hold: REASON" (wc_verify's summary and reason),
   or with json nonzero the JSON object {"holds": true|false, then for a
   mode-feasibility certificate "mode" and "feasible" (its claim), for
   any other kind "summary"; then "reason" when it does not hold}.  Sets
   *holds.  Returns WC_OK once the line is written (a failed write is left
   to the caller to find, with fflush or ferror on out), or else what
   wc_verify returns, err set and nothing written.  What `wrenchcone
   verify` and wrenchcone-verify print (wrenchcone-verify(1)).  */
int wc_verify_fprint(FILE * out, int * holds, const char * text,
                     size_t len, const char * file, int json,
                     wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
