/* polar3.c -- the polar of a cone of dimension 3, by exact randomized
   linear programming.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Three independent generators a, b, c (det(a, b, c) > 0) give the
   simplicial cone pos(b x c, c x a, a x b) around the polar P, and
   p = a + b + c is positive on it but at 0: the chart p . d = 1 meets P
   in a bounded convex polygon, cut by one half-plane d . g >= 0 per
   generator.  Seidel's method finds the optimum of a linear objective on
   it: the generators are added in random order, the optimum kept while
   it satisfies the new one, else moved onto the new one's line, a
   one-dimensional program over the generators already added; each step
   moves it with probability at most 2/i, so the expected work is O(k).
   Objectives are lexicographic pairs, with p independent of both, so
   every optimum is unique (one vertex).  Points of the chart are rays,
   compared as (e . u)(p . w) against (e . w)(p . u): integers only.

   The lexicographic maximum v1 and minimum v2 are the polygon's ends
   along one direction: none (P = { 0 }), one point (v1 = v2: a ray), or
   two; then the optimum of n = v1 x v2 and of -n, which vanishes on the
   chord, says whether P leaves the chord (interior: v1 + v2 + v3 is an
   interior point) or is the chord (a wedge).

   Every answer is checked before it is given.  P = { 0 } comes with at
   most eight rows whose positive hull is already R^3: a, b, c; the two
   rows that fix the optimum v before the row g that empties the chart;
   g; and the one or two rows that leave g's line empty (if a point x of
   the polygon of these rows had g . x >= 0, the segment from v to x
   would cross g's line inside it).  pos(S) = R^3 is then checked on its
   own: S spans R^3 and no h = s x s' (s, s' in S) nor -h is <= 0 on all
   of S, for an extreme ray of the polar of S would be one of them.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "exact/polar3.h"

typedef struct
{
    const fmpz * G;
    slong k;
    slong * ord;        /* k + 3: a, b, c, then the k rows shuffled */
    fmpz * p;           /* a + b + c */
    fmpz * t;           /* the line's direction in the chart */
    fmpz * o;           /* a point (ray) of the line */
    fmpz * w, * lo, * hi;
    fmpz_t s, x, y;
    slong ilo, ihi;     /* the positions of the rows giving lo and hi */
    slong bas[2];       /* the rows besides a, b, c that fix v (-1: none) */
    slong wit[3];       /* the rows that emptied the chart (-1: none) */
}
lp_ctx;

#define ROW(c, i) ((c)->G + 3 * (c)->ord[i])

/* The sign of f(u) - f(w), f(x) = (e . x) / (p . x), where p . u > 0 and
   p . w > 0.  */
static int
ratio_cmp(lp_ctx * c, const fmpz * e, const fmpz * u, const fmpz * w)
{
    _fmpz_vec_dot(c->x, e, u, 3);
    _fmpz_vec_dot(c->s, c->p, w, 3);
    fmpz_mul(c->x, c->x, c->s);
    _fmpz_vec_dot(c->y, e, w, 3);
    _fmpz_vec_dot(c->s, c->p, u, 3);
    fmpz_mul(c->y, c->y, c->s);
    return fmpz_cmp(c->x, c->y);
}

/* > 0 when u is better than w for the objective (e1, then e2).  */
static int
better(lp_ctx * c, const fmpz * e1, const fmpz * e2, const fmpz * u,
       const fmpz * w)
{
    int r = ratio_cmp(c, e1, u, w);

    return r != 0 ? r : ratio_cmp(c, e2, u, w);
}

/* v := the optimum of the region of rows ord[0..n) on the line
   g . d = 0 of the chart, g = ROW(c, n).  Returns 1 (c->bas := the rows
   fixing v), 0 when that is empty (c->wit := the rows that say so), -1
   when the line is not bounded there (impossible: a, b, c bound it).  On
   the line, d = o + s t (p . t = 0, so p . d = p . o), and row h bounds s
   from below (h . t > 0) or above (h . t < 0) at the ray g x h.  */
static int
on_line(lp_ctx * c, fmpz * v, slong n, const fmpz * e1, const fmpz * e2)
{
    const fmpz * g = ROW(c, n);
    slong i;
    int have_lo = 0, have_hi = 0, s;

    c->wit[0] = n;
    c->wit[1] = c->wit[2] = -1;
    _wc_zvec3_cross(c->t, g, c->p);
    if (_fmpz_vec_is_zero(c->t, 3))
        return 0;               /* g = -p up to scale: nothing is left */
    _wc_zvec3_cross(c->o, c->t, g);
    for (i = 0; i < n; i++)
    {
        const fmpz * h = ROW(c, i);

        s = _wc_zvec3_dot_sgn_fast(h, c->t, c->s);
        if (s == 0)
        {
            if (_wc_zvec3_dot_sgn_fast(h, c->o, c->s) < 0)
            {
                c->wit[1] = i;
                return 0;
            }
            continue;
        }
        _wc_zvec3_cross(c->w, g, h);
        if (_wc_zvec3_dot_sgn_fast(c->p, c->w, c->s) < 0)
            _fmpz_vec_neg(c->w, c->w, 3);
        if (s > 0 && (!have_lo || ratio_cmp(c, c->t, c->w, c->lo) > 0))
        {
            _fmpz_vec_swap(c->lo, c->w, 3);
            c->ilo = i;
            have_lo = 1;
        }
        else if (s < 0 && (!have_hi || ratio_cmp(c, c->t, c->w, c->hi) < 0))
        {
            _fmpz_vec_swap(c->hi, c->w, 3);
            c->ihi = i;
            have_hi = 1;
        }
    }
    if (!have_lo || !have_hi)
        return -1;
    if (ratio_cmp(c, c->t, c->lo, c->hi) > 0)
    {
        c->wit[1] = c->ilo;
        c->wit[2] = c->ihi;
        return 0;
    }
    s = _wc_zvec3_dot_sgn_fast(e1, c->t, c->s);
    if (s == 0)
        s = _wc_zvec3_dot_sgn_fast(e2, c->t, c->s);
    _fmpz_vec_set(v, s > 0 ? c->hi : c->lo, 3);
    c->bas[0] = n;
    c->bas[1] = s > 0 ? c->ihi : c->ilo;
    return 1;
}

/* v := the optimum of (e1, then e2) on P.  Returns 1, 0 when P = { 0 },
   -1 on an inconsistency.  */
static int
solve(lp_ctx * c, fmpz * v, const fmpz * e1, const fmpz * e2)
{
    slong i;
    int r;

    c->bas[0] = c->bas[1] = -1;
    for (i = 0; i < 3; i++)
    {
        _wc_zvec3_cross(c->w, ROW(c, (i + 1) % 3), ROW(c, (i + 2) % 3));
        if (i == 0 || better(c, e1, e2, c->w, v) > 0)
            _fmpz_vec_set(v, c->w, 3);
    }
    for (i = 3; i < c->k + 3; i++)
    {
        const fmpz * g = ROW(c, i);

        if (_wc_zvec3_dot_sgn_fast(v, g, c->s) >= 0)
            continue;
        if ((r = on_line(c, v, i, e1, e2)) != 1)
            return r;
    }
    return 1;
}

/* ord[0..3) := three independent rows, det > 0; 0 when there are none.  */
static int
basis(lp_ctx * c, fmpz * w)
{
    const fmpz * G = c->G;
    slong i, j = -1, l = -1;
    int s = 0;

    for (i = 1; i < c->k && j < 0; i++)
    {
        _wc_zvec3_cross(w, G, G + 3 * i);
        if (!_fmpz_vec_is_zero(w, 3))
            j = i;
    }
    for (i = j + 1; j > 0 && i < c->k && l < 0; i++)
        if ((s = _wc_zvec3_dot_sgn(w, G + 3 * i, c->s)) != 0)
            l = i;
    if (l < 0)
        return 0;
    c->ord[0] = 0;
    c->ord[1] = s > 0 ? j : l;
    c->ord[2] = s > 0 ? l : j;
    return 1;
}

/* ord[3..k+3) := 0..k-1 in a fixed pseudo-random order (xorshift).  */
static void
shuffle(lp_ctx * c)
{
    unsigned long long z = 0x9e3779b97f4a7c15ULL;
    slong i, j, y, * x = c->ord + 3;

    for (i = 0; i < c->k; i++)
        x[i] = i;
    for (i = c->k - 1; i > 0; i--)
    {
        z ^= z << 13;
        z ^= z >> 7;
        z ^= z << 17;
        j = (slong) (z % (unsigned long long) (i + 1));
        y = x[i];
        x[i] = x[j];
        x[j] = y;
    }
}

/* 1 when d . g > 0 (strict) or >= 0 (not strict) for every row g.  */
static int
holds(lp_ctx * c, const fmpz * d, int strict)
{
    slong i;
    int s;

    for (i = 0; i < c->k; i++)
    {
        s = _wc_zvec3_dot_sgn_fast(d, c->G + 3 * i, c->s);
        if (s < 0 || (strict && s == 0))
            return 0;
    }
    return 1;
}

/* 1 when y lies in pos(T), T the rows g with g . e = 0 (y . e = 0, e not
   0): y is a positive multiple of one of them, or lies strictly between
   the nearest counterclockwise and clockwise ones about e, which are less
   than a half-turn apart.  O(k).  w: 3 entries of scratch.  */
static int
plane_holds(lp_ctx * c, const fmpz * e, const fmpz * y, fmpz * w)
{
    const fmpz * A = NULL, * B = NULL, * g;
    slong i;
    int s;

    for (i = 0; i < c->k; i++)
    {
        g = c->G + 3 * i;
        if (_wc_zvec3_dot_sgn_fast(g, e, c->s) != 0)
            continue;
        _wc_zvec3_cross(w, y, g);
        s = _wc_zvec3_dot_sgn_fast(w, e, c->s);
        if (s == 0 && _wc_zvec3_dot_sgn_fast(y, g, c->s) > 0)
            return 1;
        if (s > 0 && A != NULL)
            _wc_zvec3_cross(w, A, g);
        if (s > 0 && (A == NULL || _wc_zvec3_dot_sgn_fast(w, e, c->s) < 0))
            A = g;
        if (s < 0 && B != NULL)
            _wc_zvec3_cross(w, B, g);
        if (s < 0 && (B == NULL || _wc_zvec3_dot_sgn_fast(w, e, c->s) > 0))
            B = g;
    }
    if (A == NULL || B == NULL)
        return 0;
    _wc_zvec3_cross(w, B, A);
    return _wc_zvec3_dot_sgn_fast(w, e, c->s) > 0;
}

/* 1 when the rows on the plane v . x = 0 span, as a cone, the half-plane
   of it where u . x >= 0 (u not 0: u . x = 0 is then the line n = v x u)
   or, u = NULL, the whole plane: that part of the boundary of
   { x : v . x >= 0 } is then in pos(G).  e: 9 entries of scratch.  */
static int
face_held(lp_ctx * c, const fmpz * v, const fmpz * u, fmpz * e)
{
    fmpz * n = e, * m = e + 3, * w = e + 6;
    slong i;
    int j, ok = 1;

    if (u != NULL)
        _wc_zvec3_cross(n, v, u);
    for (j = 0; u == NULL && j < 3; j++)
    {
        _fmpz_vec_zero(w, 3);
        fmpz_one(w + j);
        _wc_zvec3_cross(n, v, w);
        if (!_fmpz_vec_is_zero(n, 3))
            break;
    }
    _wc_zvec3_cross(m, v, n);
    for (j = 0; j < (u == NULL ? 4 : 2) && ok; j++)
    {
        ok = plane_holds(c, v, j < 2 ? n : m, w);
        _fmpz_vec_neg(j < 2 ? n : m, j < 2 ? n : m, 3);
    }
    for (i = 0, j = u == NULL; i < c->k && ok && !j; i++)
        j = _wc_zvec3_dot_sgn_fast(v, c->G + 3 * i, c->s) == 0
            && _wc_zvec3_dot_sgn_fast(u, c->G + 3 * i, c->s) > 0;
    return ok && j;
}

/* With v1 the lexicographic maximum and v2 the minimum on P (not one
   ray): pointed (V := an interior point) or a wedge.  e: 9 entries of
   scratch.  */
static int
chord(lp_ctx * c, fmpz * V, const fmpz * v1, const fmpz * v2, fmpz * e)
{
    fmpz * n = e, * m = e + 3, * v = e + 6;
    int side;

    _wc_zvec3_cross(n, v1, v2);
    _wc_zvec3_cross(m, n, c->p);
    for (side = 0; side < 2; side++)
    {
        if (solve(c, v, n, m) != 1)
            return WC_POLAR3_FAILED;
        if (_wc_zvec3_dot_sgn(n, v, c->s) > 0)
        {
            _fmpz_vec_add(V, v1, v2, 3);
            _fmpz_vec_add(V, V, v, 3);
            return holds(c, V, 1) ? WC_POLAR3_POINTED : WC_POLAR3_FAILED;
        }
        _fmpz_vec_neg(n, n, 3);
    }
    /* Certified: the rows hold on both facets, which pos(G) contains.  */
    _fmpz_vec_set(V, v1, 3);
    _fmpz_vec_set(V + 3, v2, 3);
    return holds(c, V, 0) && holds(c, V + 3, 0) && face_held(c, v1, v2, e)
        && face_held(c, v2, v1, e) ? WC_POLAR3_WEDGE : WC_POLAR3_FAILED;
}

/* 1 when pos(S) = R^3 for the rows S at positions P[0..m) (see the top).
   e: 3 entries of scratch.  */
static int
space_held(lp_ctx * c, const slong * P, int m, fmpz * e)
{
    int i, j, l, rank3 = 0, pos, neg;

    for (i = 0; i < m; i++)
        for (j = i + 1; j < m; j++)
        {
            _wc_zvec3_cross(e, ROW(c, P[i]), ROW(c, P[j]));
            if (_fmpz_vec_is_zero(e, 3))
                continue;
            for (l = pos = neg = 0; l < m; l++)
            {
                int s = _wc_zvec3_dot_sgn_fast(e, ROW(c, P[l]), c->s);

                pos |= s > 0;
                neg |= s < 0;
            }
            if (!pos || !neg)
                return 0;       /* e or -e is in the polar of S */
            rank3 = 1;          /* a row off the plane of P[i], P[j] */
        }
    return rank3;
}

/* The certificate of P = { 0 } after the first program found the chart
   empty: a, b, c, c->bas and c->wit.  */
static int
space_certified(lp_ctx * c, fmpz * e)
{
    slong P[8];
    int i, m = 0;

    for (i = 0; i < 3; i++)
        P[m++] = i;
    for (i = 0; i < 2; i++)
        if (c->bas[i] >= 0)
            P[m++] = c->bas[i];
    for (i = 0; i < 3; i++)
        if (c->wit[i] >= 0)
            P[m++] = c->wit[i];
    return space_held(c, P, m, e);
}

int
_wc_polar3(fmpz * V, const fmpz * G, slong k)
{
    lp_ctx c;
    fmpz * e = _fmpz_vec_init(30);      /* e1, e2, v1, v2, chord's 9 */
    fmpz * e1 = e, * e2 = e + 3, * v1 = e + 6, * v2 = e + 9;
    slong j;
    int r = WC_POLAR3_FAILED;

    c.G = G;
    c.k = k;
    c.ord = malloc(sizeof(slong) * (k + 3));
    c.p = _fmpz_vec_init(18);
    c.t = c.p + 3;
    c.o = c.p + 6;
    c.w = c.p + 9;
    c.lo = c.p + 12;
    c.hi = c.p + 15;
    fmpz_init(c.s);
    fmpz_init(c.x);
    fmpz_init(c.y);
    if (c.ord == NULL)
    {
        r = WC_POLAR3_NOMEM;
        goto cleanup;
    }
    if (!basis(&c, c.w))
        goto cleanup;
    shuffle(&c);
    for (j = 0; j < 3; j++)
        _fmpz_vec_add(c.p, c.p, ROW(&c, j), 3);
    /* e1: a unit vector off the line of p; e2 := e1 x p */
    for (j = 0; j < 3; j++)
    {
        _fmpz_vec_zero(e1, 3);
        fmpz_one(e1 + j);
        _wc_zvec3_cross(e2, e1, c.p);
        if (!_fmpz_vec_is_zero(e2, 3))
            break;
    }
    r = solve(&c, v1, e1, e2);
    if (r == 0)
    {
        r = space_certified(&c, e + 12) ? WC_POLAR3_SPACE : WC_POLAR3_FAILED;
        goto cleanup;
    }
    _fmpz_vec_neg(e1, e1, 3);
    _fmpz_vec_neg(e2, e2, 3);
    if (r != 1 || solve(&c, v2, e1, e2) != 1)
    {
        r = WC_POLAR3_FAILED;
        goto cleanup;
    }
    _wc_zvec3_cross(e1, v1, v2);
    if (_fmpz_vec_is_zero(e1, 3))
    {
        _fmpz_vec_set(V, v1, 3);
        r = holds(&c, V, 0) && face_held(&c, V, NULL, e + 12)
            ? WC_POLAR3_RAY : WC_POLAR3_FAILED;
    }
    else
        r = chord(&c, V, v1, v2, e + 12);
    _wc_zvec3_primitive(V, c.s);
    _wc_zvec3_primitive(V + 3, c.s);

cleanup:
    free(c.ord);
    _fmpz_vec_clear(e, 30);
    _fmpz_vec_clear(c.p, 18);
    fmpz_clear(c.s);
    fmpz_clear(c.x);
    fmpz_clear(c.y);
    return r;
}
