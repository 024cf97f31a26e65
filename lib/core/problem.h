/* problem.h -- a planar workpiece, its fixels, and the .wc problem file.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   wrenchcone(1) and wrenchcone(5).  All numbers are exact rationals (fmpq).  */

#ifndef WC_PROBLEM_H
#define WC_PROBLEM_H

#include <stddef.h>
#include <stdio.h>
#include <gmp.h>
#include <flint/flint.h>
#include <flint/fmpq.h>

#include "core/error.h"
#include "core/limits.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { WC_TOUCHING = 0, WC_NEAR = 1 } wc_fixel_state;

typedef enum { WC_SHAPE_NONE = 0, WC_SHAPE_DISK = 1, WC_SHAPE_POLYGON = 2 }
wc_shape_kind;

/* One fixel: contact point p on the workpiece, inward normal n (nonzero,
   not necessarily unit; the tangent is n rotated by +90 degrees), its
   state, and its own friction coefficients (the global ones when the file
   gives none).  line and col locate the fixel's keyword in the file.  */
typedef struct
{
    fmpq point[2];
    fmpq normal[2];
    wc_fixel_state state;
    fmpq_t mu_s;
    fmpq_t mu_k;
    long line;
    long col;
}
wc_fixel_struct;

/* A problem.  shape holds CX CY R for a disk, X1 Y1 .. Xk Yk (k >= 3, as
   written in the file) for a polygon.  file is the name used in messages
   ("<stdin>" for standard input).  */
typedef struct
{
    char * file;
    char * name;                /* NULL when the file gives none */
    fmpq_t mass;
    fmpq_t inertia;
    fmpq com[2];
    fmpq_t mu_s;                /* global defaults */
    fmpq_t mu_k;
    wc_shape_kind shape;
    slong shape_len;            /* number of fmpq in shape_data */
    fmpq * shape_data;
    long shape_line;
    long mass_line;             /* where mass, inertia and com are written */
    long inertia_line;          /* (0 when not read from a file) */
    long com_line;
    slong n;                    /* number of fixels, >= 1 after parsing */
    wc_fixel_struct * fixels;
}
wc_problem_struct;

typedef wc_problem_struct wc_problem_t[1];

void wc_problem_init(wc_problem_t P);
void wc_problem_clear(wc_problem_t P);

/* Parse the problem text (len bytes, need not be NUL-terminated) read from
   the file called file.  On success returns WC_OK and fills P (which must
   be freshly initialised).  On a malformed file returns WC_EINPUT and sets
   err to the first error, located at its line and column (wrenchcone(5)); P is
   then left initialised but unspecified.  */
int wc_problem_parse(wc_problem_t P, const char * text, size_t len,
                     const char * file, wc_error_t err);

/* Append a fixel to P and return it: point (0, 0), normal (0, 0) (the
   caller must set a nonzero one), touching, friction equal to P's global
   mu_s and mu_k at the time of the call, line = col = 0.  The pointer is
   valid until the next call.  For programs that build problems directly
   (tests, generators).  */
wc_fixel_struct * wc_problem_add_fixel(wc_problem_t P);

/* Q := a copy of P (Q initialised; P may be Q).  Returns WC_OK, or
   WC_EINTERNAL when out of memory (Q is then left empty).  */
int wc_problem_set(wc_problem_t Q, const wc_problem_t P);

/* Write P as a .wc problem file that wc_problem_parse reads back to the
   same problem (every fixel with its normal, state and friction written
   out).  Returns WC_OK or WC_EINTERNAL on a write error.  */
int wc_problem_fprint(FILE * out, const wc_problem_t P);

/* Check a problem built by a program rather than the parser (the parser
   guarantees all this): at least one fixel, nonzero normals, mass and
   inertia positive, friction non-negative, states touching or near.
   Returns WC_OK or WC_EINPUT with err saying which.  Every library entry
   point that takes a problem calls it, so that bad data is an error, never
   an abort.  */
int wc_problem_check(const wc_problem_t P, wc_error_t err);

/* WC_OK when P has at most max fixels (with touching != 0: at most max
   touching fixels); else WC_EINPUT located at the first fixel beyond the
   limit, saying that what ("classify", "insertion plans", ...) handles at
   most max of them.  Every command has such a limit (wrenchcone(1),
   LIMITS), so that no input makes it run for minutes or exhaust memory
   silently.  */
int wc_problem_check_fixels(const wc_problem_t P, slong max, int touching,
                            const char * what, wc_error_t err);

/* Parse one exact number: an optional sign, then an integer, a fraction
   p/q, or a decimal with optional exponent (0.2 = 1/5, 1.5e-3 = 3/2000).
   The whole of s[0..len) must be the number.  Returns WC_OK, or WC_EINPUT
   with a message in err (location fields left 0: the caller knows where
   the token is).  */
int wc_parse_number(fmpq_t x, const char * s, size_t len, wc_error_t err);

/* wc_parse_number refusing, with the message "number too big in ...",
   a number whose numerator or denominator has more than
   WC_NUMBER_MAX_BITS bits (for p/q as written, for a decimal in lowest
   terms), decided before any power of ten beyond 10^WC_NUMBER_MAX_BITS
   is built: its cost is linear in len.  */
int wc_parse_number_bounded(fmpq_t x, const char * s, size_t len,
                            wc_error_t err);

/* A comma-separated list of at most max exact numbers s (each as
   wc_parse_number_bounded reads it) into *v, flint_malloc'd, of *count
   (free with wc_number_list_clear, also after a failure).  Errors are
   located in what ("<friction>") at line 1 and the column of the value;
   over max: "at most MAX values (why)"; with noun set, a negative value
   is refused: "NOUN must not be negative".  */
int wc_parse_number_list(fmpq ** v, slong * count, const char * s,
                         slong max, const char * why, const char * noun,
                         const char * what, wc_error_t err);
void wc_number_list_clear(fmpq * v, slong n);

#ifdef __cplusplus
}
#endif

#endif
