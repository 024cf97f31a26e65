/* cellrays.c -- the extreme rays of the cells of an arrangement of
   central planes.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A sector lies on one plane p and is bounded by two of the lines
   h_p x h_q on it: the ones nearest to its point x turning either way
   about h_p.  Turning counter-clockwise about h_p from x, every line
   meets the open half-plane ahead in one direction u_q (the sign of
   (x x u_q) . h_p decides which); the nearest of them is one bound, and
   the farthest, reversed, the other.  A chamber's closure is bounded by
   sectors, each a facet of the two chambers on its sides, so a
   chamber's rays are the union of the rays of the sectors next to it.
   O(m) products per sector for m planes, O(m log count) per lookup.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "exact/cells.h"

/* (a x b) . h > 0: b is counter-clockwise from a about h.  */
static int
turns(const fmpz * a, const fmpz * b, const fmpz * h, fmpz * c, fmpz_t t)
{
    _wc_zvec3_cross(c, a, b);
    return _wc_zvec3_dot_sgn(c, h, t);
}

/* The one-dimensional cell holding the direction d, or -1.  */
static slong
ray_of(const wc_cells_t A, const fmpz * d, signed char * s, fmpz_t t)
{
    slong q;

    for (q = 0; q < A->nplanes; q++)
        s[q] = (signed char) _wc_zvec3_dot_sgn(WC_ROW(A->planes, q), d, t);
    return wc_cells_find(A, 1, s);
}

/* The two rays of sector i into r[0], r[1] (either order); 0 when they
   are not found (a broken arrangement).  */
static int
sector_rays(slong * r, const wc_cells_t A, slong i, signed char * s,
            fmpz * w)
{
    slong m = A->nplanes, p, q;
    const fmpz * x = WC_ROW(A->point, i), * h;
    fmpz * u = w, * lo = w + 3, * hi = w + 6, * c = w + 9, * t = w + 12;
    int have = 0;

    for (p = 0; p < m && _wc_cells_sign(A, i, p) != 0; p++)
        ;
    if (p == m)
        return 0;
    h = WC_ROW(A->planes, p);
    for (q = 0; q < m; q++)
    {
        if (q == p)
            continue;
        _wc_zvec3_cross(u, h, WC_ROW(A->planes, q));
        if (turns(x, u, h, c, t) < 0)
            _fmpz_vec_neg(u, u, 3);
        if (!have || turns(u, lo, h, c, t) > 0)
            _fmpz_vec_set(lo, u, 3);
        if (!have || turns(hi, u, h, c, t) > 0)
            _fmpz_vec_set(hi, u, 3);
        have = 1;
    }
    if (!have)
        return 0;
    _fmpz_vec_neg(hi, hi, 3);
    r[0] = ray_of(A, lo, s, t);
    r[1] = ray_of(A, hi, s, t);
    return r[0] >= 0 && r[1] >= 0;
}

static int
pair_cmp(const void * a, const void * b)
{
    const slong * x = a, * y = b;

    if (x[0] != y[0])
        return x[0] < y[0] ? -1 : 1;
    return x[1] < y[1] ? -1 : x[1] > y[1];
}

static void
put_pair(slong * pr, slong * k, slong cell, const slong * r, slong nr)
{
    slong j;

    for (j = 0; j < nr; j++, (*k)++)
    {
        pr[2 * *k] = cell;
        pr[2 * *k + 1] = r[j];
    }
}

/* Every (cell, ray) pair: rays and sectors directly, each chamber from
   the sectors on its two sides.  Returns the number of pairs, or -1 on a
   broken arrangement.  */
static slong
ray_pairs(slong * pr, const wc_cells_t A, signed char * s, fmpz * w)
{
    slong m = A->nplanes, i, k = 0, p, c, r[2];
    int side;

    for (i = 0; i < A->count; i++)
    {
        if (A->dim[i] == 1)
            put_pair(pr, &k, i, &i, 1);
        if (A->dim[i] != 2)
            continue;
        if (!sector_rays(r, A, i, s, w))
            return -1;
        put_pair(pr, &k, i, r, 2);
        wc_cells_signs(s, A, i);
        for (p = 0; p < m && s[p] != 0; p++)
            ;
        if (p == m)
            return -1;
        for (side = -1; side <= 1; side += 2)
        {
            s[p] = (signed char) side;
            c = wc_cells_find(A, 3, s);
            if (c < 0)
                return -1;
            put_pair(pr, &k, c, r, 2);
        }
    }
    return k;
}

int
wc_cells_rays(slong ** off, slong ** ray, const wc_cells_t A,
              wc_error_t err)
{
    slong n2 = 0, n1 = 0, i, k, j, total, * pr;
    signed char * s;
    fmpz * w;
    int status = WC_OK;

    for (i = 0; i < A->count; i++)
    {
        n1 += A->dim[i] == 1;
        n2 += A->dim[i] == 2;
    }
    pr = flint_malloc(sizeof(slong) * 2 * (n1 + 6 * n2 + 1));
    s = flint_malloc(A->nplanes + 1);
    w = _fmpz_vec_init(15);
    total = ray_pairs(pr, A, s, w);
    *off = flint_malloc(sizeof(slong) * (A->count + 1));
    *ray = flint_malloc(sizeof(slong) * (total > 0 ? total : 1));
    if (total < 0)
    {
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal "
                              "error: a sector's rays are not cells");
        total = 0;
    }
    qsort(pr, total, 2 * sizeof(slong), pair_cmp);
    for (i = 0, k = 0, j = 0; i < A->count; i++)
    {
        (*off)[i] = j;
        for (; k < total && pr[2 * k] == i; k++)
            if (j == (*off)[i] || (*ray)[j - 1] != pr[2 * k + 1])
                (*ray)[j++] = pr[2 * k + 1];
    }
    (*off)[A->count] = j;
    flint_free(pr);
    flint_free(s);
    _fmpz_vec_clear(w, 15);
    return status;
}
