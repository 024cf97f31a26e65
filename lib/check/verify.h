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

   A certificate is one JSON object; keys not named here are ignored.
   Numbers are exact rationals: JSON strings "p" or "p/q" (p, q decimal,
   q > 0; not necessarily in lowest terms) or JSON integers.  Its "kind"
   says which of the two formats below it has (no "kind": the first).
   For both, with r = point - com and t = (-n_y, n_x) at each fixel
   (a x b = a_x b_y - a_y b_x):
     J_n = (n_x, n_y, r x n),  J_t = (t_x, t_y, r x t).

   1. "kind": "mode-feasibility" (paper Table 1, wrenchcone(1), MODES)
     "mode": "ln"                        Table 1 letters, one per fixel
     "feasible": true | false
     "witness": [vx, vy, w]              when feasible
     "constraints": [{"row": [a, b, c], "relation": ">" | ">=" | "="}, ...]
     "multipliers": [y1, ..., ym]        when not feasible
     "problem": {"com": [x, y], "fixels": [{"point": [x, y],
                 "normal": [x, y], "state": "touching" | "near"}, ...]}
   It holds when
     - "constraints" is exactly the list the mode implies: for each fixel
       in order, its normal row, then its tangential row when the letter
       constrains it (touching s: J_n >; l: J_n =, J_t >; r: J_n =,
       -J_t >; n: J_n =, J_t =; near a: -J_n >; near s: J_n >=), each row
       the primitive integer vector on its ray;
     - feasible: the witness satisfies every row's relation;
     - not feasible: one multiplier per constraint, sum y_k row_k = 0,
       y_k >= 0 on > and >= rows, y_k > 0 on at least one > row (then, by
       Motzkin's transposition theorem, no twist satisfies the rows).

   2. "kind": "strong-stability" (wrenchcone(1), stability; exact semantics)
     "problem": {"mass": m, "inertia": I, "com": [x, y],
                 "fixels": [{"point": [x, y], "normal": [x, y],
                             "state": "touching" | "near",
                             "mu_s": ms, "mu_k": mk}, ...]}
     "wrench": [gx, gy, gtau]
     "weakly_stable": true | false
     "weak": {"c": [c_1n, .., c_nn, c_1t, .., c_nt]}   when weakly stable
             {"separator": [y1, y2, y3]}               when not
     "strongly_stable": true | false
     "motion": {"sign": "ls", "nudot": [a, b, c], "c": [2 n forces]}
                                  when weakly but not strongly stable
     "faces": [{"sign": "ss", "multipliers": [...]},
               {"sign": "nn", "rotation": 1 | -1, "multipliers": [...]},
               ...]               when strongly stable
   m > 0, I > 0, normals nonzero, mu_s, mu_k >= 0 (else malformed);
   M = diag(m, m, I).  A sign string has one letter per fixel, in file
   order: s, l, r or n on a touching fixel, u on a near one; "rotation"
   (a rational equal to 1 or -1) only with the sign n..n (n on every
   touching fixel); a sign or rotation breaking these rules is malformed.
   For an acceleration nudot, a_in = J_in . nudot and a_it = J_it . nudot;
   its sign string S(nudot) has at touching fixel i s when a_in > 0, else
   l, r or n as a_it is > 0, < 0 or = 0 (and u at near fixels).
   It holds when
     - weakly stable: c is 0 at near fixels; at touching ones c_in >= 0,
       |c_it| <= mu_s c_in; and g = -J c, g = -sum_i (c_in J_in +
       c_it J_it).
     - not weakly stable: y . g > 0 and y . (J_in - mu_s J_it) >= 0,
       y . (J_in + mu_s J_it) >= 0 at every touching fixel (then
       y . (-J c) <= 0 < y . g for every admissible c).
     - strongly stable is claimed only with weakly stable.
     - weakly but not strongly stable: the motion is a moving solution:
       nudot != 0, M nudot = J c + g, c = 0 at near fixels, and at each
       touching fixel the letter of the sign holds:
         s: a_in > 0, c_in = c_it = 0;
         l: a_in = 0, a_it > 0, c_in >= 0, c_it = -mu_k c_in;
         r: a_in = 0, a_it < 0, c_in >= 0, c_it = +mu_k c_in;
         n: a_in = 0, a_it = 0, c_in >= 0, |c_it| <= mu_s c_in.
     - strongly stable: "faces" is complete, each face once: its signs
       without "rotation" are exactly the strings S(nudot) over the
       nudot with a_in >= 0 at every touching fixel, other than n..n
       (computed here from the arrangement of the planes J_in . x = 0,
       J_it . x = 0 of the touching fixels, in polynomial time); and when
       every touching fixel has the same point (and one fixel touches),
       two more entries n..n with "rotation" 1 and -1, else none.  No
       touching fixel: no face at all.  And every face has no solution,
       by Motzkin multipliers for this system in the unknowns
       z = (nudot_1, nudot_2, nudot_3, lambda_1, .., lambda_e, tau).
       Its friction edges e_1 .. e_e are, for the touching fixels in
       order, by letter: n: (1, -mu_s) then (1, +mu_s); l: (1, -mu_k);
       r: (1, +mu_k); s: none; the edge (en, et) at fixel i is the
       wrench w = en J_in + et J_it.  Its rows, in this order:
         3 rows =: row k is (M_k1, M_k2, M_k3, -w_1[k], .., -w_e[k],
           -g[k]), that is M nudot - sum_j lambda_j w_j - tau g = 0;
         for each touching fixel in order, rows on nudot (0 elsewhere):
           s: J_in > ; l: J_in =, J_it > ; r: J_in =, -J_it > ;
           n: J_in =, J_it =;
         instead for a rotation face: J_in =, J_it = at every touching
           fixel, then rho v > with v = J_1n x J_1t (the 3-D cross
           product of the first touching fixel's columns) and rho the
           rotation; v = |n_1|^2 (r_1y, -r_1x, 1) is the rotation about
           the shared point, so rho = 1 turns the body counter-clockwise;
         lambda_j >= 0 for j = 1 .. e (unit rows); tau > 0 (unit row).
       Rows are exact, never rescaled.  There is one multiplier per row;
       sum_k y_k row_k = 0, y_k >= 0 on > and >= rows, y_k > 0 on at
       least one > row.  Then no (nudot, lambda, tau) with tau > 0 solves
       the system, and dividing by tau, no motion of the face exists
       for g.
   A wrench with no touching fixel is weakly stable only when g = 0,
   and then strongly stable (M nudot = 0).  */

#ifndef WC_VERIFY_H
#define WC_VERIFY_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"

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

/* Check a certificate of either kind: text, len and file as above.
   Returns WC_OK and sets *holds to 1 or 0; *summary (malloc'd, caller
   frees) to a one-line account of what the certificate claims, which is
   what it proves when *holds is 1:
     "mode ln is infeasible", "mode ss is feasible";
     "wrench (0, -1, 0) is strongly stable: 9 moving faces excluded",
     "wrench (-1, -1, -1) is weakly stable but moves in mode ls",
     "wrench (0, 1, 0) is not weakly stable";
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

/* Check a certificate of either kind (text, len and file as above) and
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
