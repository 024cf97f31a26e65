/* checker.h -- internal: what the files of the certificate checker
   share: vectors of GMP numbers, the text of a reason, Motzkin
   multipliers, reading a certificate's JSON and its problem.  Each kind
   of certificate has a header of its own: feasible.h, stabcheck.h,
   setcheck.h (stability-set and plan-goal), critcheck.h; faces.h and
   region.h hold the geometry they share.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  Everything here uses GMP and lib/core only (see
   verify.c for why).  Functions that return int return WC_OK,
   WC_EINPUT or WC_EINTERNAL unless they say otherwise; the checks return
   1 (holds), 0 (does not; the reason written) or -1 (out of memory).  */

#ifndef WC_CHECK_CHECKER_H
#define WC_CHECK_CHECKER_H

#include <stddef.h>

#include <gmp.h>

#include "core/error.h"
#include "core/json.h"
#include "core/text.h"

#ifdef __GNUC__
#define WC_CHECK_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define WC_CHECK_PRINTF(f, a)
#endif

/* ------------------------------------------------------------------ */
/* Vectors of GMP numbers (gmpvec.c).                                  */

/* k * n, or SIZE_MAX when that overflows (so the allocation fails).  */
size_t _wc_check_times(size_t k, size_t n);

/* An array of n objects of the given size (at least one byte); NULL when
   out of memory or when the size overflows.  */
void * _wc_check_alloc(size_t n, size_t size);

/* n initialised numbers (n may be 0); NULL when out of memory.  The free
   functions accept NULL.  */
mpq_t * _wc_check_qvec_new(size_t n);
mpz_t * _wc_check_zvec_new(size_t n);
void _wc_check_qvec_free(mpq_t * v, size_t n);
void _wc_check_zvec_free(mpz_t * v, size_t n);

int _wc_check_qvec_is_zero(mpq_t * v, size_t n);
int _wc_check_qvec_equal(mpq_t * a, mpq_t * b, size_t n);

/* 3-vectors.  r = a . b (t scratch for the rationals); r = a x b, r
   distinct from a and b; r += a b.  */
void _wc_check_qdot3(mpq_t r, mpq_t * a, mpq_t * b, mpq_t t);
void _wc_check_zdot3(mpz_t r, mpz_t * a, mpz_t * b);
void _wc_check_qcross3(mpq_t * r, mpq_t * a, mpq_t * b, mpq_t t);
void _wc_check_zcross3(mpz_t * r, mpz_t * a, mpz_t * b);
void _wc_check_qaddmul(mpq_t r, const mpq_t a, const mpq_t b, mpq_t t);

/* z = the primitive integer vector on the ray of the nonzero rational
   3-vector q; t scratch.  */
void _wc_check_primitive(mpz_t * z, mpq_t * q, mpz_t t);

/* ------------------------------------------------------------------ */
/* The text of a reason or a summary (textbuf.c).                      */

/* A growing string; oom once an addition failed (then it stays as it
   was).  Starts all zero.  */
typedef struct
{
    char * s;
    size_t len;
    size_t cap;
    int oom;
}
wc_check_text;

void _wc_check_put_n(wc_check_text * b, const char * s, size_t n);
void _wc_check_put(wc_check_text * b, const char * s);
void _wc_check_putf(wc_check_text * b, const char * fmt, ...)
    WC_CHECK_PRINTF(2, 3);

/* Numbers, cut after 40 digits with "...": z, q, and "(a, b, c)".  */
void _wc_check_put_z(wc_check_text * b, const mpz_t z);
void _wc_check_put_q(wc_check_text * b, const mpq_t q);
void _wc_check_put_zvec(wc_check_text * b, mpz_t * v, size_t n);

/* Cut b back to at (where a step's message began) when the step held
   (holds != 0): a failing step keeps its message.  */
void _wc_check_unmark(wc_check_text * b, size_t at, int holds);
void _wc_check_put_qvec(wc_check_text * b, mpq_t * v, size_t n);

/* ------------------------------------------------------------------ */
/* Motzkin multipliers (motzkin.c).                                    */

typedef enum
{
    WC_CHECK_GT = 0,
    WC_CHECK_GE = 1,
    WC_CHECK_EQ = 2
}
wc_check_rel;

/* ">", ">=" or "=".  */
const char * _wc_check_rel_name(wc_check_rel r);

/* 1 when there are as many multipliers (nmult) as rows; else 0 and why
   says so, after prefix, naming the rows noun ("constraint", "row").  */
int _wc_check_motzkin_count(wc_check_text * why, const char * prefix,
                            const char * noun, size_t nmult, size_t rows);

/* 1 when the multipliers y of rows rows with relations rel prove that
   the rows have no common solution, given s = sum_k y_k row_k (d
   entries); else 0 and why says, after prefix, which condition fails
   first.  */
int _wc_check_motzkin(wc_check_text * why, const char * prefix,
                      const char * noun, const wc_check_rel * rel,
                      mpq_t * y, size_t rows, mpq_t * s, size_t d);

/* ------------------------------------------------------------------ */
/* Reading the JSON of a certificate (read.c).                         */

/* The errors of one reading: the first in file order is kept.  */
typedef struct
{
    const char * file;
    wc_error_struct * err;
    int status;         /* the worst so far: WC_OK, WC_EINPUT, WC_EINTERNAL */
}
wc_check_reader;

typedef enum
{
    WC_CHECK_MODE = 0,          /* "mode-feasibility" or no "kind" */
    WC_CHECK_STABILITY = 1,     /* "strong-stability" */
    WC_CHECK_SET = 2,           /* "stability-set" */
    WC_CHECK_PLAN = 3,          /* "plan-goal" */
    WC_CHECK_CRIT = 4           /* "critical-friction" */
}
wc_check_kind;

typedef enum
{
    WC_CHECK_STRING,
    WC_CHECK_BOOL,
    WC_CHECK_ARRAY,
    WC_CHECK_OBJECT
}
wc_check_want;

/* For _wc_check_qarray: an array of any length.  */
#define WC_CHECK_ANY_LENGTH ((size_t) -1)

/* Records out of memory; returns WC_EINTERNAL.  */
int _wc_check_nomem(wc_check_reader * c);

/* Records an error at the value at, unless one located no later is
   already recorded.  Returns WC_EINPUT.  */
int _wc_check_bad(wc_check_reader * c, const wc_json_node * at,
                  const char * fmt, ...) WC_CHECK_PRINTF(3, 4);

/* _wc_check_bad with a message quoting s[0..len) (fmt has one %s).  */
int _wc_check_bad_quoting(wc_check_reader * c, const wc_json_node * at,
                          const char * fmt, const char * s, size_t len);

/* The member key of object o, of the wanted type, into *v (else NULL).  */
int _wc_check_member(wc_check_reader * c, const wc_json_node * o,
                     const char * key, wc_check_want w,
                     const wc_json_node ** v);

/* An element of an array that must be an object.  */
int _wc_check_want_object(wc_check_reader * c, const wc_json_node * v);

/* The rational at v: a string "p" or "p/q", or a JSON integer.  */
int _wc_check_rational(wc_check_reader * c, const wc_json_node * v,
                       mpq_t q);

/* o[key] is an array of exactly n rationals, into q.  */
int _wc_check_vector(wc_check_reader * c, const wc_json_node * o,
                     const char * key, mpq_t * q, size_t n);

/* o[key] is an array of rationals, of want entries unless want is
   WC_CHECK_ANY_LENGTH; into *q, allocated here with *len entries.  */
int _wc_check_qarray(wc_check_reader * c, const wc_json_node * o,
                     const char * key, size_t want, mpq_t ** q,
                     size_t * len);

/* The storage of an array of n entries: k rationals each, into *q, and
   one object of the given size each, returned.  Both or neither: NULL,
   *q NULL and out of memory recorded.  */
void * _wc_check_entries_new(wc_check_reader * c, mpq_t ** q, size_t k,
                             size_t n, size_t size);

/* The rational o[key] into q, which must be positive (sign 1) or
   non-negative (sign 0).  */
int _wc_check_scalar(wc_check_reader * c, const wc_json_node * o,
                     const char * key, mpq_t q, int sign);

/* The kind of the certificate root (which must be an object).  */
int _wc_check_kind(wc_check_reader * c, const wc_json_node * root,
                   wc_check_kind * kind);

/* ------------------------------------------------------------------ */
/* The problem a certificate states (problem.c).                       */

typedef struct
{
    mpq_t * body;       /* 4: mass, inertia, com x, y */
    size_t n;           /* fixels; 0 until known */
    mpq_t * fixel;      /* 6 n: point x, y, normal x, y, mu_s, mu_k */
    int * near;         /* n: 1 near, 0 touching; -1 until read */
}
wc_check_problem;

void _wc_check_problem_init(wc_check_problem * P);
void _wc_check_problem_clear(wc_check_problem * P);

/* root["problem"] into P: com and fixels (point, normal, state), and
   with dynamics also mass, inertia, mu_s and mu_k.  */
int _wc_check_read_problem(wc_check_problem * P, wc_check_reader * c,
                           const wc_json_node * root, int dynamics);

/* The letters of the string at v against the fixels (as far as they are
   known): one letter per fixel, of a mode (Table 1: s l r n on touching
   fixels, s a on near ones) or, with sign, of a sign string (s l r n,
   u).  */
int _wc_check_letters(wc_check_reader * c, const wc_json_node * v,
                      const wc_check_problem * P, int sign);

/* J[0..3) = J_n = (n_x, n_y, r x n) and J[3..6) = J_t = (t_x, t_y,
   r x t) of fixel i, where r = point - com and t = (-n_y, n_x).  */
void _wc_check_jacobian(mpq_t * J, const wc_check_problem * P, size_t i);

#endif
