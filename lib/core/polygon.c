/* polygon.c -- exact plane geometry for the problem's shape: is a
   polygon simple, which way does it turn, is a point on a segment.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Points are two consecutive fmpq.  */

#include <stdlib.h>

#include "core/polygon.h"

/* sign of (b - a) x (c - a) */
static int
orient(const fmpq * a, const fmpq * b, const fmpq * c)
{
    fmpq_t r, u, w;
    int s;

    fmpq_init(r);
    fmpq_init(u);
    fmpq_init(w);
    fmpq_sub(u, b + 0, a + 0);
    fmpq_sub(w, c + 1, a + 1);
    fmpq_mul(r, u, w);
    fmpq_sub(u, b + 1, a + 1);
    fmpq_sub(w, c + 0, a + 0);
    fmpq_submul(r, u, w);
    s = fmpq_sgn(r);
    fmpq_clear(r);
    fmpq_clear(u);
    fmpq_clear(w);
    return s;
}

int
_wc_point_equal(const fmpq * a, const fmpq * b)
{
    return fmpq_equal(a + 0, b + 0) && fmpq_equal(a + 1, b + 1);
}

/* p in the closed box spanned by a and b; with orient(a, b, p) == 0 this
   is p on the closed segment [a, b].  */
static int
in_box(const fmpq * p, const fmpq * a, const fmpq * b)
{
    int k;

    for (k = 0; k < 2; k++)
    {
        const fmpq * lo = a + k, * hi = b + k;

        if (fmpq_cmp(lo, hi) > 0)
        {
            lo = b + k;
            hi = a + k;
        }
        if (fmpq_cmp(p + k, lo) < 0 || fmpq_cmp(p + k, hi) > 0)
            return 0;
    }
    return 1;
}

/* 0: the closed segments [a, b] and [c, d] are disjoint; 1: they touch;
   2: they cross at one point interior to both.  */
static int
segments_meet(const fmpq * a, const fmpq * b, const fmpq * c, const fmpq * d)
{
    int d1 = orient(c, d, a), d2 = orient(c, d, b);
    int d3 = orient(a, b, c), d4 = orient(a, b, d);

    if (d1 * d2 < 0 && d3 * d4 < 0)
        return 2;
    if ((d1 == 0 && in_box(a, c, d)) || (d2 == 0 && in_box(b, c, d))
        || (d3 == 0 && in_box(c, a, b)) || (d4 == 0 && in_box(d, a, b)))
        return 1;
    return 0;
}

/* Twice the signed area of the polygon v[0..m), as a sign.  */
static int
polygon_orientation(const fmpq * v, slong m)
{
    fmpq_t s;
    slong k;
    int r;

    fmpq_init(s);
    for (k = 0; k < m; k++)
    {
        const fmpq * a = v + 2 * k, * b = v + 2 * ((k + 1) % m);

        fmpq_addmul(s, a + 0, b + 1);
        fmpq_submul(s, a + 1, b + 0);
    }
    r = fmpq_sgn(s);
    fmpq_clear(s);
    return r;
}


int
_wc_on_segment(const fmpq * p, const fmpq * a, const fmpq * b)
{
    return orient(a, b, p) == 0 && in_box(p, a, b);
}

/* box[4 a ..] := the smaller x, larger x, smaller y, larger y of edge a
   (pointers into v).  */
static void
edge_boxes(const fmpq ** box, const fmpq * v, slong m)
{
    slong a;
    int k;

    for (a = 0; a < m; a++)
        for (k = 0; k < 2; k++)
        {
            const fmpq * p = v + 2 * a + k, * q = v + 2 * ((a + 1) % m) + k;
            int lt = fmpq_cmp(p, q) < 0;

            box[4 * a + 2 * k] = lt ? p : q;
            box[4 * a + 2 * k + 1] = lt ? q : p;
        }
}

/* The closed boxes of edges a and b are disjoint, so the edges are.  */
static int
boxes_apart(const fmpq ** box, slong a, slong b)
{
    int k;

    for (k = 0; k < 4; k += 2)
        if (fmpq_cmp(box[4 * a + k], box[4 * b + k + 1]) > 0
            || fmpq_cmp(box[4 * b + k], box[4 * a + k + 1]) > 0)
            return 1;
    return 0;
}

/* The first pair of non-adjacent edges (a < b) that meet, in the order
   of the loops: a fault with *i, *j set, or WC_POLYGON_SIMPLE.  box may
   be NULL (out of memory): every pair is then tested in full.  */
static int
edges_meet(slong * i, slong * j, const fmpq * v, slong m, const fmpq ** box)
{
    slong a, b;

    for (a = 0; a < m; a++)
        for (b = a + 2; b < m; b++)
        {
            int k;

            if ((a == 0 && b == m - 1)
                || (box != NULL && boxes_apart(box, a, b)))
                continue;
            k = segments_meet(v + 2 * a, v + 2 * ((a + 1) % m),
                              v + 2 * b, v + 2 * ((b + 1) % m));
            if (k != 0)
            {
                *i = a;
                *j = b;
                return k == 2 ? WC_POLYGON_CROSS : WC_POLYGON_TOUCH;
            }
        }
    return WC_POLYGON_SIMPLE;
}

int
_wc_polygon_check(int * turn, slong * i, slong * j, const fmpq * v, slong m)
{
    slong a, b;
    const fmpq ** box;
    int fault;

    *turn = 0;
    for (a = 0; a < m; a++)
        if (_wc_point_equal(v + 2 * a, v + 2 * ((a + 1) % m)))
        {
            *i = a;
            *j = (a + 1) % m;
            return WC_POLYGON_COINCIDE;
        }
    for (a = 0; a < m; a++)
    {
        b = (a + 1) % m;
        if (orient(v + 2 * a, v + 2 * b, v + 2 * ((a + 2) % m)) == 0)
        {
            *i = a;
            *j = b;
            return WC_POLYGON_COLLINEAR;
        }
    }
    /* Adjacent edges cannot overlap now that no three consecutive vertices
       are collinear; test every pair of non-adjacent edges, quadratic in m
       (the reader allows at most WC_POLYGON_MAX_VERTICES), the pairs with
       disjoint boxes at the cost of a few comparisons.  */
    box = malloc((size_t) m * 4 * sizeof(const fmpq *));
    if (box != NULL)
        edge_boxes(box, v, m);
    fault = edges_meet(i, j, v, m, box);
    free(box);
    if (fault != WC_POLYGON_SIMPLE)
        return fault;
    /* A simple polygon has nonzero area; kept as a last guard.  */
    *turn = polygon_orientation(v, m);
    return *turn == 0 ? WC_POLYGON_ZERO_AREA : WC_POLYGON_SIMPLE;
}
