/* region.c -- the regions of a certificate's tree: relatively open
   pointed cones of R^3 held by the extreme rays of their closures, cut by
   planes through the origin.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A region of dimension 3 is the interior of the cone of its rays r_0 ..
   r_{n-1}, listed around the cone (each consecutive pair, and the last
   with the first, spans a facet); of dimension 2 the relative interior of
   the cone of its two rays; of dimension 1 its one open ray; of dimension
   0 the origin.  Cutting one by a plane h keeps the rays on the wanted
   side and adds, on each edge from a to b that the plane crosses, the
   crossing |h.a| b + |h.b| a (made primitive), so that the pieces are
   regions of the same kind with their rays in the same order.  */

#include <stdlib.h>

#include "check/checker.h"
#include "check/region.h"

void
_wc_check_region_init(wc_check_region * R)
{
    R->dim = -1;
    R->n = R->cap = 0;
    R->r = NULL;
}

void
_wc_check_region_clear(wc_check_region * R)
{
    _wc_check_zvec_free(R->r, 3 * R->cap);
    _wc_check_region_init(R);
}

/* Room for one more ray; 1 or -1.  */
static int
room(wc_check_region * R)
{
    size_t cap = R->cap < 4 ? 4 : 2 * R->cap, i;
    mpz_t * r;

    if (R->n < R->cap)
        return 1;
    if ((r = _wc_check_zvec_new(_wc_check_times(3, cap))) == NULL)
        return -1;
    for (i = 0; i < 3 * R->n; i++)
        mpz_swap(r[i], R->r[i]);
    _wc_check_zvec_free(R->r, 3 * R->cap);
    R->r = r;
    R->cap = cap;
    return 1;
}

/* Append the ray z to R; 1 or -1.  */
static int
push(wc_check_region * R, mpz_t * z)
{
    int j;

    if (room(R) < 0)
        return -1;
    for (j = 0; j < 3; j++)
        mpz_set(R->r[3 * R->n + j], z[j]);
    R->n++;
    return 1;
}

static void
make_primitive(mpz_t * z, mpz_t g)
{
    int j;

    mpz_gcd(g, z[0], z[1]);
    mpz_gcd(g, g, z[2]);
    if (mpz_cmp_ui(g, 1) > 0)
        for (j = 0; j < 3; j++)
            mpz_divexact(z[j], z[j], g);
}

int
_wc_check_region_copy(wc_check_region * D, const wc_check_region * R)
{
    size_t i;

    D->n = 0;
    D->dim = R->dim;
    for (i = 0; i < R->n; i++)
        if (push(D, R->r + 3 * i) < 0)
            return -1;
    return 1;
}

int
_wc_check_region_basis(wc_check_region * out, mpz_t * h)
{
    mpz_t * d = _wc_check_zvec_new(9), det, g;
    size_t k;
    int i, j, holds = 1;

    if (d == NULL)
        return -1;
    mpz_init(det);
    mpz_init(g);
    for (i = 0; i < 3; i++)
        _wc_check_zcross3(d + 3 * i, h + 3 * ((i + 1) % 3),
                          h + 3 * ((i + 2) % 3));
    _wc_check_zdot3(det, h, d);
    if (mpz_sgn(det) == 0)
        holds = 0;
    for (i = 0; holds == 1 && i < 3; i++)
    {
        /* h_i . d_i = det, h_j . d_i = 0: point d_i to h_i's side */
        for (j = 0; j < 3 && mpz_sgn(det) < 0; j++)
            mpz_neg(d[3 * i + j], d[3 * i + j]);
        make_primitive(d + 3 * i, g);
    }
    for (k = 0; holds == 1 && k < 27; k++)
    {
        int s[3] = { (int) (k / 9) - 1, (int) (k / 3 % 3) - 1,
                     (int) (k % 3) - 1 };

        out[k].n = 0;
        out[k].dim = 0;
        for (i = 0; i < 3 && holds == 1; i++)
        {
            if (s[i] == 0)
                continue;
            out[k].dim++;
            holds = push(out + k, d + 3 * i);
            for (j = 0; holds == 1 && s[i] < 0 && j < 3; j++)
                mpz_neg(out[k].r[3 * (out[k].n - 1) + j],
                        out[k].r[3 * (out[k].n - 1) + j]);
        }
    }
    mpz_clear(det);
    mpz_clear(g);
    _wc_check_zvec_free(d, 9);
    return holds;
}

/* The crossing c of the plane with the edge from a (h.a = va) to b
   (h.b = vb), va and vb of opposite signs.  */
static void
crossing(mpz_t * c, mpz_t * a, mpz_t va, mpz_t * b, mpz_t vb, mpz_t t)
{
    int j;

    for (j = 0; j < 3; j++)
    {
        mpz_mul(c[j], b[j], va);
        if (mpz_sgn(va) < 0)
            mpz_neg(c[j], c[j]);
        mpz_mul(t, a[j], vb);
        if (mpz_sgn(vb) < 0)
            mpz_neg(t, t);
        mpz_add(c[j], c[j], t);
    }
    make_primitive(c, t);
}

/* Cut R (dimension 2 or 3) by the plane whose values at the rays are v
   (signs s); c scratch (3).  */
static int
cut(wc_check_region * out, const wc_check_region * R, mpz_t * v,
    const int * s, mpz_t * c, mpz_t t)
{
    size_t i, n = R->n, edges = R->dim == 3 ? n : 1;
    int pos = 0, neg = 0, k, ok = 1;

    for (i = 0; i < n; i++)
    {
        pos |= s[i] > 0;
        neg |= s[i] < 0;
    }
    for (k = 0; k < 3; k++)
        out[k].n = 0;
    out[0].dim = neg ? R->dim : -1;
    out[2].dim = pos ? R->dim : -1;
    out[1].dim = !pos && !neg ? R->dim : pos && neg ? R->dim - 1 : -1;
    for (i = 0; i < n && ok > 0; i++)
    {
        size_t b = (i + 1) % n;

        for (k = 0; k < 3 && ok > 0; k++)
            if (out[k].dim >= 0 && (k == 1 ? s[i] == 0 : s[i] * (k - 1) >= 0))
                ok = push(out + k, R->r + 3 * i);
        if (i >= edges || s[i] * s[b] >= 0)
            continue;
        crossing(c, R->r + 3 * i, v[i], R->r + 3 * b, v[b], t);
        for (k = 0; k < 3 && ok > 0; k++)
            if (out[k].dim >= 0)
                ok = push(out + k, c);
    }
    return ok;
}

int
_wc_check_region_split(wc_check_region * out, const wc_check_region * R,
                       mpz_t * h)
{
    mpz_t * v = NULL, * c = _wc_check_zvec_new(3), t;
    int * s = malloc(sizeof(int) * (R->n + 1)), ok = 1, k;
    size_t i;

    v = _wc_check_zvec_new(R->n + 1);
    mpz_init(t);
    if (s == NULL || v == NULL || c == NULL)
        ok = -1;
    for (i = 0; ok > 0 && i < R->n; i++)
    {
        _wc_check_zdot3(v[i], h, R->r + 3 * i);
        s[i] = mpz_sgn(v[i]);
    }
    if (ok > 0 && R->dim >= 2)
        ok = cut(out, R, v, s, c, t);
    else if (ok > 0)
    {
        /* the origin lies on the plane; a ray on the side of its sign */
        k = R->dim == 1 ? s[0] + 1 : 1;
        for (i = 0; i < 3; i++)
        {
            out[i].dim = -1;
            out[i].n = 0;
        }
        ok = _wc_check_region_copy(out + k, R);
    }
    mpz_clear(t);
    _wc_check_zvec_free(v, R->n + 1);
    _wc_check_zvec_free(c, 3);
    free(s);
    return ok;
}
