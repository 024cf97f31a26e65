/* cone.c -- the cone of velocity directions x with h . x >= 0 for a list
   of normals h in R^3, cut one half-space at a time.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The cone is held as K = span(L) + cone(R): a basis L of its lineality
   space and the extreme rays R of what is left, all primitive integer
   vectors.  A cut by h . x >= 0 is the double description step in three
   dimensions:
     - when some l in L has h . l != 0, that l (turned so that h . l > 0)
       leaves L and becomes a ray, and every other generator v becomes
       (h . l) v - (h . v) l, on the plane h . x = 0;
     - otherwise, with no more than two rays (a ray, or a wedge of angle
       below pi modulo L), the rays are kept, dropped or, for a wedge cut
       between its rays, the negative one is moved onto the plane;
     - otherwise L is empty and K is pointed with three rays or more, in
       cyclic order around it: the polygon they make on the sphere is
       clipped by the half-space (Sutherland and Hodgman), which keeps
       the rays with h . r >= 0 and puts a new ray on the plane wherever
       an edge between neighbours r, s has h . r and h . s of strict
       opposite signs; the rays stay in cyclic order.
   Each cut costs O(|L| + |R|) products, and |R| grows by one at most a
   cut.  Once K is {0} the cuts cost nothing.  */

#include <stdlib.h>
#include <string.h>

#include "check/faces.h"

/* h . v, counted.  */
static int
sign_dot(wc_check_cone * K, mpz_t r, mpz_t * h, mpz_t * v)
{
    K->work++;
    _wc_check_zdot3(r, h, v);
    return mpz_sgn(r);
}

/* v = v / gcd of its entries (v nonzero).  */
void
_wc_check_zprimitive(mpz_t * v, mpz_t t)
{
    int j;

    mpz_gcd(t, v[0], v[1]);
    mpz_gcd(t, t, v[2]);
    if (mpz_sgn(t) != 0)
        for (j = 0; j < 3; j++)
            mpz_divexact(v[j], v[j], t);
}

/* out = a v - c l, made primitive: v moved along l onto the plane of h,
   where a = h . l and c = h . v.  out may be v.  */
static void
combine(wc_check_cone * K, mpz_t * out, mpz_t * v, mpz_t * l,
        const mpz_t a, const mpz_t c)
{
    int j;

    for (j = 0; j < 3; j++)
    {
        mpz_mul(K->v[j], a, v[j]);
        mpz_submul(K->v[j], c, l[j]);
    }
    for (j = 0; j < 3; j++)
        mpz_set(out[j], K->v[j]);
    _wc_check_zprimitive(out, K->t);
}

int
_wc_check_cone_init(wc_check_cone * K, size_t cuts)
{
    int j;

    memset(K, 0, sizeof *K);
    mpz_init(K->a);
    mpz_init(K->c);
    mpz_init(K->t);
    K->cap = cuts + 4;
    K->L = _wc_check_zvec_new(9);
    K->v = _wc_check_zvec_new(3);
    K->r = _wc_check_zvec_new(_wc_check_times(3, K->cap));
    K->o = _wc_check_zvec_new(_wc_check_times(3, K->cap));
    K->d = _wc_check_zvec_new(K->cap);
    if (K->L == NULL || K->v == NULL || K->r == NULL || K->o == NULL
        || K->d == NULL)
        return WC_EINTERNAL;
    K->dl = 3;
    for (j = 0; j < 3; j++)
        mpz_set_ui(K->L[4 * j], 1);
    return WC_OK;
}

void
_wc_check_cone_clear(wc_check_cone * K)
{
    _wc_check_zvec_free(K->L, 9);
    _wc_check_zvec_free(K->v, 3);
    _wc_check_zvec_free(K->r, 3 * K->cap);
    _wc_check_zvec_free(K->o, 3 * K->cap);
    _wc_check_zvec_free(K->d, K->cap);
    mpz_clear(K->a);
    mpz_clear(K->c);
    mpz_clear(K->t);
    memset(K, 0, sizeof *K);
}

static void
copy3(mpz_t * to, mpz_t * from)
{
    mpz_set(to[0], from[0]);
    mpz_set(to[1], from[1]);
    mpz_set(to[2], from[2]);
}

/* The cut when h . L[j0] != 0.  */
static void
cut_lineality(wc_check_cone * K, mpz_t * h, int j0)
{
    mpz_t * l0 = K->L + 3 * j0;
    size_t k;
    int j;

    if (sign_dot(K, K->a, h, l0) < 0)
    {
        for (j = 0; j < 3; j++)
            mpz_neg(l0[j], l0[j]);
        mpz_neg(K->a, K->a);
    }
    for (j = 0; j < K->dl; j++)
        if (j != j0)
        {
            sign_dot(K, K->c, h, K->L + 3 * j);
            combine(K, K->L + 3 * j, K->L + 3 * j, l0, K->a, K->c);
        }
    for (k = 0; k < K->nr; k++)
    {
        sign_dot(K, K->c, h, K->r + 3 * k);
        combine(K, K->r + 3 * k, K->r + 3 * k, l0, K->a, K->c);
    }
    copy3(K->r + 3 * K->nr++, l0);
    K->dl--;
    if (j0 != K->dl)
        copy3(l0, K->L + 3 * K->dl);
}

/* The cut of one ray or of a wedge (at most two rays), h . L = 0.  */
static void
cut_wedge(wc_check_cone * K, mpz_t * h)
{
    int s0, s1;

    if (K->nr == 0)
        return;
    s0 = sign_dot(K, K->d[0], h, K->r);
    if (K->nr == 1)
    {
        if (s0 < 0)
            K->nr = 0;
        return;
    }
    s1 = sign_dot(K, K->d[1], h, K->r + 3);
    if (s0 >= 0 && s1 >= 0)
        return;
    if (s0 <= 0 && s1 <= 0)
    {
        /* keep the rays on the plane */
        if (s0 < 0)
        {
            if (s1 == 0)
                copy3(K->r, K->r + 3);
            K->nr = s1 == 0 ? 1 : 0;
        }
        else
            K->nr = 1;
        return;
    }
    /* one ray on each side: the negative one onto the plane */
    if (s0 < 0)
        combine(K, K->r, K->r, K->r + 3, K->d[1], K->d[0]);
    else
        combine(K, K->r + 3, K->r + 3, K->r, K->d[0], K->d[1]);
}

/* The cut of a pointed cone with three rays or more, in cyclic order.  */
static void
cut_polygon(wc_check_cone * K, mpz_t * h)
{
    size_t k, m = 0, nr = K->nr;
    mpz_t * swap;

    for (k = 0; k < nr; k++)
        sign_dot(K, K->d[k], h, K->r + 3 * k);
    for (k = 0; k < nr; k++)
        if (mpz_sgn(K->d[k]) < 0)
            break;
    if (k == nr)
        return;
    for (k = 0; k < nr; k++)
    {
        size_t k1 = (k + 1) % nr;
        int s = mpz_sgn(K->d[k]), s1 = mpz_sgn(K->d[k1]);

        if (s >= 0)
            copy3(K->o + 3 * m++, K->r + 3 * k);
        if (s > 0 && s1 < 0)
            combine(K, K->o + 3 * m++, K->r + 3 * k1, K->r + 3 * k,
                    K->d[k], K->d[k1]);
        else if (s < 0 && s1 > 0)
            combine(K, K->o + 3 * m++, K->r + 3 * k, K->r + 3 * k1,
                    K->d[k1], K->d[k]);
    }
    swap = K->r;
    K->r = K->o;
    K->o = swap;
    K->nr = m;
}

int
_wc_check_cone_cut(wc_check_cone * K, mpz_t * h)
{
    int j;

    if (K->dl == 0 && K->nr == 0)
        return WC_OK;
    /* a cut adds one ray at most; cap was sized for the cuts */
    if (K->nr + 1 >= K->cap)
        return WC_EINTERNAL;
    for (j = 0; j < K->dl; j++)
        if (sign_dot(K, K->a, h, K->L + 3 * j) != 0)
        {
            cut_lineality(K, h, j);
            return WC_OK;
        }
    if (K->nr <= 2)
        cut_wedge(K, h);
    else
        cut_polygon(K, h);
    return WC_OK;
}
