/* faces.h -- internal: the moving faces of a problem
   (faces.c), found in the cone of the directions x with h . x >= 0
   (cone.c), for the strong-stability and the set certificates.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  GMP and lib/core only, as all of lib/check
   (checker.h).  */

#ifndef WC_CHECK_FACES_H
#define WC_CHECK_FACES_H

#include "check/checker.h"

/* The cone of the directions x with h . x >= 0 (cone.c).  */

/* K = span(L[0 .. dl)) + cone(r[0 .. nr)), primitive integer vectors;
   with dl = 0 and nr >= 3 the rays go around K in cyclic order.  work
   counts the products h . v computed.  */
typedef struct
{
    int dl;
    mpz_t * L;                  /* 9 */
    size_t nr, cap;
    mpz_t * r, * o;             /* 3 cap each: rays, scratch */
    mpz_t * d;                  /* cap, scratch */
    mpz_t * v;                  /* 3, scratch */
    mpz_t a, c, t;
    unsigned long work;
}
wc_check_cone;

/* v = v / gcd of its entries; t scratch.  */
void _wc_check_zprimitive(mpz_t * v, mpz_t t);

/* K = R^3, with room for cuts cuts.  WC_OK or WC_EINTERNAL; either way
   _wc_check_cone_clear frees.  */
int _wc_check_cone_init(wc_check_cone * K, size_t cuts);
void _wc_check_cone_clear(wc_check_cone * K);

/* K = K cut by h . x >= 0 (h a nonzero integer vector).  WC_OK, or
   WC_EINTERNAL after more cuts than room was made for.  */
int _wc_check_cone_cut(wc_check_cone * K, mpz_t * h);

/* The moving faces (faces.c).  */

/* A set of strings of n + 1 bytes each, malloc'd; all zero when empty.
   work: how many products of integer vectors the walk that made the set
   computed (its cost; the tests bound it).  */
typedef struct
{
    size_t count;
    size_t cap;
    char ** s;
    int oom;
    unsigned long work;
}
wc_check_strings;

void _wc_check_strings_clear(wc_check_strings * T);

/* The index of s in the set made by _wc_check_moving_faces, or -1.  */
long _wc_check_strings_find(const wc_check_strings * T, const char * s);

/* Every sign string S(nudot) with a_in >= 0 at every touching fixel of
   P, other than n..n, into out, sorted, each once; J holds J_in and J_it
   of every fixel (6 n).  */
int _wc_check_moving_faces(wc_check_strings * out,
                           const wc_check_problem * P, mpq_t * J);

#endif
