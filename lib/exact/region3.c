/* region3.c -- the regions of a set certificate's tree, cut by planes.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   See region3.h.  A cut keeps the rays on the wanted side, in order, and
   adds on each edge from a to b that the plane crosses the point
   |h.a| b + |h.b| a, made primitive.  The checker (lib/check) cuts its
   regions on its own; a certificate names only the planes, so the two
   need agree only on which regions are empty.  */

#include <config.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "exact/region3.h"

void
_wc_region3_init(_wc_region3 * R)
{
    R->dim = -1;
    R->n = R->cap = 0;
    R->r = NULL;
}

void
_wc_region3_clear(_wc_region3 * R)
{
    if (R->r != NULL)
        _fmpz_vec_clear(R->r, 3 * R->cap);
    _wc_region3_init(R);
}

static void
push(_wc_region3 * R, const fmpz * z)
{
    if (R->n == R->cap)
    {
        slong cap = R->cap < 4 ? 4 : 2 * R->cap, i;
        fmpz * r = _fmpz_vec_init(3 * cap);

        for (i = 0; i < 3 * R->n; i++)
            fmpz_swap(r + i, R->r + i);
        if (R->r != NULL)
            _fmpz_vec_clear(R->r, 3 * R->cap);
        R->r = r;
        R->cap = cap;
    }
    _fmpz_vec_set(R->r + 3 * R->n++, z, 3);
}

void
_wc_region3_sum(fmpz * s, const _wc_region3 * R)
{
    slong i;

    _fmpz_vec_zero(s, 3);
    for (i = 0; i < R->n; i++)
        _fmpz_vec_add(s, s, R->r + 3 * i, 3);
}

void
_wc_region3_basis(_wc_region3 * out, const fmpz * h)
{
    fmpz d[9];
    fmpz_t det, t;
    slong i, k;

    fmpz_init(det);
    fmpz_init(t);
    for (i = 0; i < 9; i++)
        fmpz_init(d + i);
    for (i = 0; i < 3; i++)
    {
        _wc_zvec3_cross(d + 3 * i, h + 3 * ((i + 1) % 3),
                        h + 3 * ((i + 2) % 3));
    }
    _fmpz_vec_dot(det, h, d, 3);
    for (i = 0; i < 3; i++)
    {
        if (fmpz_sgn(det) < 0)
            _fmpz_vec_neg(d + 3 * i, d + 3 * i, 3);
        _wc_zvec3_primitive(d + 3 * i, t);
    }
    for (k = 0; k < 27; k++)
    {
        int s[3] = { (int) (k / 9) - 1, (int) (k / 3 % 3) - 1,
                     (int) (k % 3) - 1 };

        out[k].n = 0;
        out[k].dim = 0;
        for (i = 0; i < 3; i++)
            if (s[i] != 0)
            {
                out[k].dim++;
                push(out + k, d + 3 * i);
                if (s[i] < 0)
                    _fmpz_vec_neg(out[k].r + 3 * (out[k].n - 1),
                                  out[k].r + 3 * (out[k].n - 1), 3);
            }
    }
    for (i = 0; i < 9; i++)
        fmpz_clear(d + i);
    fmpz_clear(det);
    fmpz_clear(t);
}

void
_wc_region3_split(_wc_region3 * out, const _wc_region3 * R, const fmpz * h)
{
    slong i, n = R->n, edges = R->dim == 3 ? n : R->dim == 2 ? 1 : 0;
    fmpz * v = _fmpz_vec_init(n + 1);
    fmpz c[3];
    fmpz_t t;
    int * s = flint_malloc(sizeof(int) * (n + 1)), pos = 0, neg = 0, k;

    fmpz_init(t);
    for (k = 0; k < 3; k++)
        fmpz_init(c + k);
    for (i = 0; i < n; i++)
    {
        _fmpz_vec_dot(v + i, h, R->r + 3 * i, 3);
        s[i] = fmpz_sgn(v + i);
        pos |= s[i] > 0;
        neg |= s[i] < 0;
    }
    for (k = 0; k < 3; k++)
        out[k].n = 0;
    out[0].dim = neg ? R->dim : -1;
    out[2].dim = pos ? R->dim : -1;
    out[1].dim = !pos && !neg ? R->dim : pos && neg ? R->dim - 1 : -1;
    for (i = 0; i < n; i++)
    {
        slong b = (i + 1) % n;

        for (k = 0; k < 3; k++)
            if (out[k].dim >= 0 && (k == 1 ? s[i] == 0 : s[i] * (k - 1) >= 0))
                push(out + k, R->r + 3 * i);
        if (i >= edges || s[i] * s[b] >= 0)
            continue;
        for (k = 0; k < 3; k++)
        {
            fmpz_mul(c + k, R->r + 3 * b + k, v + i);
            fmpz_mul(t, R->r + 3 * i + k, v + b);
            fmpz_sub(c + k, c + k, t);
            if (s[i] < 0)
                fmpz_neg(c + k, c + k);
        }
        _wc_zvec3_primitive(c, t);
        for (k = 0; k < 3; k++)
            if (out[k].dim >= 0)
                push(out + k, c);
    }
    for (k = 0; k < 3; k++)
        fmpz_clear(c + k);
    fmpz_clear(t);
    _fmpz_vec_clear(v, n + 1);
    flint_free(s);
}
