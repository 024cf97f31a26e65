/* verify.h -- re-check a mode-feasibility certificate with GMP alone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The checker behind `wrenchcone verify`.  It shares no code with the
   machinery that writes certificates (kinematics.c, FLINT, cddlib): it
   reads the JSON with json.c, recomputes the constraint rows of the mode
   from the problem with GMP rationals (SPEC 2.1, paper Table 1), and
   checks the witness or the Motzkin multipliers with exact arithmetic.

   The certificate (one JSON object; other keys are ignored):
     "kind": "mode-feasibility"          optional, the only kind known
     "mode": "ln"                        Table 1 letters, one per fixel
     "feasible": true | false
     "witness": [vx, vy, w]              when feasible
     "constraints": [{"row": [a, b, c], "relation": ">" | ">=" | "="}, ...]
     "multipliers": [y1, ..., ym]        when not feasible
     "problem": {"com": [x, y], "fixels": [{"point": [x, y],
                 "normal": [x, y], "state": "touching" | "near"}, ...]}
   Numbers are exact rationals: JSON strings "p" or "p/q" (p, q decimal,
   q > 0; not necessarily in lowest terms) or JSON integers.

   It holds when
     - "constraints" is exactly the list the mode implies: for each fixel
       in order, its normal row, then its tangential row when the letter
       constrains it (touching s: J_n >; l: J_n =, J_t >; r: J_n =,
       -J_t >; n: J_n =, J_t =; near a: -J_n >; near s: J_n >=), each row
       the primitive integer vector on its ray, where for r = point - com
       and t = (-n_y, n_x): J_n = (n_x, n_y, r x n), J_t = (t_x, t_y, r x t);
     - feasible: the witness satisfies every row's relation;
     - not feasible: one multiplier per constraint, sum y_k row_k = 0,
       y_k >= 0 on > and >= rows, y_k > 0 on at least one > row (then, by
       Motzkin's transposition theorem, no twist satisfies the rows).  */

#ifndef WC_VERIFY_H
#define WC_VERIFY_H

#include <stddef.h>

#include "error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Check the certificate text[0..len) (any bytes), read from file (the
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

#ifdef __cplusplus
}
#endif

#endif
