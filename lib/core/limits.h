/* limits.h -- every limit of the library in one place: what each bounds
   and why it has its value.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Installed, and included by the headers whose functions enforce a limit
   (problem.h, mode.h, kinematics.h, stability.h, plan.h, random.h,
   verify.h, ...), so that a caller sees the limit next to the function.
   Macros only, no FLINT: the checker (lib/check, GMP alone) includes it
   too.  The command line documents the user-visible ones in
   wrenchcone(1) and wrenchcone(5), LIMITS; a value changed here must be
   changed there (and in the messages that print it, where said).  Names
   starting with an underscore are internal tuning, not API.  */

#ifndef WC_CORE_LIMITS_H
#define WC_CORE_LIMITS_H

#include <stddef.h>

/* ------------------------------------------------------------------ */
/* Reading input (core).  */

/* The numerator and denominator of every number in a problem file fit in
   this many bits (for p/q those written, for a decimal those of its value
   in lowest terms), and so does every number the program reads from its
   command line; wc_parse_number itself has no such bound.  It keeps every
   command's cost bounded whatever the size of the numbers.  The message
   of a number over the bound says 1024: change it in number.c with the
   value.  */
#define WC_NUMBER_MAX_BITS 1024

/* An integer of WC_NUMBER_MAX_DIGITS decimal digits or more (>= 10^(D-1)
   with D > WC_NUMBER_MAX_DIGITS) has more than WC_NUMBER_MAX_BITS bits:
   ceil(WC_NUMBER_MAX_BITS log10 2) rounded up, as 0.30103 > log10 2.
   Derived, not a choice: number.c rejects longer numbers unread.  */
#define WC_NUMBER_MAX_DIGITS \
    ((WC_NUMBER_MAX_BITS * 30103 + 99999) / 100000)

/* The largest exponent of a decimal number: "1e999999999" must not make
   us build a gigantic power of ten.  */
#define WC_MAX_EXPONENT 100000

/* The most vertices of a polygon in a problem file, so that no command's
   cost grows beyond bounds with the size of the shape (wrenchcone(5)).  */
#define WC_POLYGON_MAX_VERTICES 1000

/* The most fixels of a problem file (each command has a lower limit of
   its own: wc_problem_check_fixels).  */
#define WC_PROBLEM_MAX_FIXELS 10000

/* The most fixels wc_random_problem makes (wrenchcone random).  */
#define WC_RANDOM_MAX_FIXELS 1000

/* JSON arrays and objects nested deeper than this are an error: the
   reader is recursive, and the bound keeps its stack small whatever the
   input.  */
#define WC_JSON_MAX_DEPTH 64

/* Input text quoted in a message is cut after this many bytes: a message
   stays one readable line.  */
#define WC_SHOW_MAX 64

/* An error record's file name is cut after this many bytes, its message
   after this many (wc_error_set): whatever a caller passes, a record
   stays a bounded line of valid UTF-8.  */
#define WC_SHOW_PATH_MAX 1024
#define WC_MESSAGE_MAX 4096

/* ------------------------------------------------------------------ */
/* Commands: the most fixels (or touching or near fixels) each takes.  */

/* The most fixels a wrench cone is computed for: its cost grows as n^2.  */
#define WC_CONE_MAX_FIXELS 2000

/* The most fixels and near fixels of a mode enumeration: with m near
   fixels it lists O(m^2 + n) modes of n letters, m^2 n bytes where every
   fixel is near (wc_modes_enumerate).  */
#define WC_MODES_MAX_FIXELS 1000
#define WC_MODES_MAX_NEAR 150

/* The most touching fixels classify and stability take: the moving faces
   are O(t^2) LPs of size O(t), or cones, for t touching fixels.  */
#define WC_CLASSIFY_MAX_TOUCHING 100
#define WC_STABILITY_MAX_TOUCHING 100

/* The most fixels of an insertion plan: 3^n cones for the complete plan,
   n 2^(n-1) for the conservative one.  */
#define WC_PLAN_MAX_FIXELS 10
#define WC_PLAN_MAX_FIXELS_COMPLETE 6

/* The most fixels a plan's certificate (and a critical bracket's) is
   written for: its cells grow fast with n (about 20 MB at 7 fixels), and
   wrenchcone verify reads at most WC_CERT_MAX_BYTES.  */
#define WC_PLAN_CERT_MAX_FIXELS 7

/* The bounds that keep the critical friction search to at most
   2 + 32 + 128 plans: the width is at least 2^-96 (about 1.3e-29) and the
   largest friction at most 2^32; wc_plan_critical refuses others with
   WC_EINPUT.  */
#define WC_CRITICAL_MIN_WIDTH_EXP 96
#define WC_CRITICAL_MAX_FRICTION_EXP 32

/* The most fixels of a state-transition graph figure: it draws all 2^n
   states (16 at most).  */
#define _WC_DRAW_GRAPH_MAX_FIXELS 4

/* ------------------------------------------------------------------ */
/* Certificates.  */

/* The most bytes of a certificate wrenchcone verify (and
   wrenchcone-verify) reads: the largest one written
   (WC_PLAN_CERT_MAX_FIXELS) is about 20 MB; 64 MB leaves room and still
   keeps a hostile file from exhausting memory.  */
#define WC_CERT_MAX_BYTES ((size_t) 64 << 20)

/* The most planes a certificate of a set (stability-set, plan-goal)
   lists: the checker finds the cells of their arrangement from every
   pair of planes, O(p^2) time and memory (1000 planes: about 0.6 s and
   110 MB), so it refuses more as malformed, and wrenchcone does not write
   more (wrenchcone-certificate(5), LIMITS).  */
#define WC_CERT_MAX_PLANES 1000

/* ------------------------------------------------------------------ */
/* Foreign cones (wrenchcone compare).  */

/* Limits that keep hostile files from taking forever: the comparison is
   near-linear in the k rows of a representation (the 3-D kernel's
   conversion, then O(k log k) matching; doc/benchmarks.md), but grows
   with the size of the numbers, and a float cone in R^3 from real code
   has fewer rows, numbers far shorter: the most rows, characters of one
   number, and decimal exponent.  */
#define WC_FOREIGN_MAX_ROWS 100000
#define WC_FOREIGN_MAX_CHARS 1000
#define WC_FOREIGN_MAX_EXPONENT 1000

/* The directed angle's search where part of one cone lies at pi/2 or
   more from the other (hausdorff.c's minimax_polar) costs k^4 with k
   rays of B: above these many rays it tries fewer candidates (triples,
   then pairs, then the single p_i: k^2 per face of K), and above the
   last only K's generators (k each), and its answer is then only a lower
   bound -- still at least pi/2, so it still exceeds every tolerance
   wc_compare accepts.  compare.h states the 48.  */
#define WC_MINIMAX_TRIPLES 48
#define WC_MINIMAX_PAIRS 400
#define WC_MINIMAX_SINGLES 1000

/* ------------------------------------------------------------------ */
/* Printing (io).  */

/* --decimals=K: at most this many digits of a decimal approximation.  */
#define WC_DECIMALS_MAX 50

/* ------------------------------------------------------------------ */
/* Requests and commands (api).  */

/* An input (a problem, a foreign cone) larger than this is refused
   before it is parsed.  */
#define _WC_MAX_INPUT_BYTES ((size_t) 256 << 20)

/* cone --all-modes computes at most this many cones (one JSON line
   each); more are listed by modes and given to batch.  */
#define _WC_ALL_MODES_MAX 10000

/* sweep --friction: at most this many values, each costs a plan.  */
#define _WC_SWEEP_MAX_FRICTIONS 1000

/* draw --sweep: at most this many values, each a plan and a layer of
   the figure.  */
#define _WC_DRAW_MAX_SWEEP 12

/* batch --jobs: at most this many threads.  */
#define WC_BATCH_MAX_JOBS 256

#endif
