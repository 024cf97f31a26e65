/* vec3.h -- internal: exact 3-vectors (wrenches, twists, plane normals),
   the small operations every layer above needs once.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  A 3-vector is three consecutive entries (fmpz or fmpq),
   as in a row of a FLINT matrix with three columns.  */

#ifndef WC_EXACT_VEC3_H
#define WC_EXACT_VEC3_H

#include <flint/fmpz.h>
#include <flint/fmpq.h>

/* Row i of a FLINT matrix (fmpz_mat, fmpq_mat), as a vector.  */
#define WC_ROW(A, i) ((A)->rows[i])

/* c := a x b.  c must not alias a or b.  */
void _wc_zvec3_cross(fmpz * c, const fmpz * a, const fmpz * b);
void _wc_qvec3_cross(fmpq * c, const fmpq * a, const fmpq * b);

/* r := h . p for an integer h and a rational p.  */
void _wc_zqvec3_dot(fmpq_t r, const fmpz * h, const fmpq * p);

/* The sign of a . b; t := a . b (callers read it).  */
int _wc_zvec3_dot_sgn(const fmpz * a, const fmpz * b, fmpz_t t);

/* The sign of a . b, in 128-bit integers when no entry is a GMP integer;
   t is scratch only (it does not hold a . b afterwards).  Inline: the
   loops over rows of the 3-dimensional cones call it most.  */
static inline int
_wc_zvec3_dot_sgn_fast(const fmpz * a, const fmpz * b, fmpz_t t)
{
#ifdef __SIZEOF_INT128__
    /* Word entries are below 2^62 in absolute value: each product is
       below 2^124 and the sum below 2^126.  */
    if (!COEFF_IS_MPZ(a[0]) && !COEFF_IS_MPZ(a[1]) && !COEFF_IS_MPZ(a[2])
        && !COEFF_IS_MPZ(b[0]) && !COEFF_IS_MPZ(b[1]) && !COEFF_IS_MPZ(b[2]))
    {
        __int128 s = (__int128) a[0] * b[0] + (__int128) a[1] * b[1]
            + (__int128) a[2] * b[2];

        return (s > 0) - (s < 0);
    }
#endif
    return _wc_zvec3_dot_sgn(a, b, t);
}

/* c := a x b and r := a . b, in 128-bit integers when no entry of a or b
   is a GMP integer (the same values as _wc_zvec3_cross and
   _wc_zvec3_dot_sgn).  c must not alias a or b.  */
void _wc_zvec3_cross_fast(fmpz * c, const fmpz * a, const fmpz * b);
void _wc_zvec3_dot_fast(fmpz_t r, const fmpz * a, const fmpz * b);

/* gcd(a, b) (gcd(a, 0) = a) of words.  */
ulong _wc_gcd_ui(ulong a, ulong b);

/* v := the primitive vector on the ray of v, v divided by the gcd of its
   entries (v zero stays zero), in words when no entry is a GMP integer;
   t is scratch.  */
void _wc_zvec3_primitive(fmpz * v, fmpz_t t);

/* v := the canonical vector of the line of v (or of the plane through the
   origin with normal v): the primitive one whose first nonzero entry is
   positive.  Returns 0 when v is zero, -1 when v was turned around, else
   1.  */
int _wc_zvec3_canonical(fmpz * v, fmpz_t t);

/* Lexicographic order of integer 3-vectors (-1, 0, 1 as fmpz_cmp).  */
int _wc_zvec3_cmp(const fmpz * a, const fmpz * b);

/* v := the primitive integer vector on the ray of the rational vector x
   (len entries, any length: the 3-vectors are the usual case); v zero
   when x is.  v must not alias x.  */
void _wc_qvec_primitive(fmpz * v, const fmpq * x, slong len);

/* The sign of a^2 b - c^2 d (-1, 0, 1; the comparison of two squared
   cosines), in 192-bit words when every argument is a word integer and
   b, d >= 0; l and r are scratch.  */
int _wc_z_sqmul_cmp(const fmpz_t a, const fmpz_t b, const fmpz_t c,
                    const fmpz_t d, fmpz_t l, fmpz_t r);

#endif
