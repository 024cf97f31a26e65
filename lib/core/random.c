/* random.c -- seeded, reproducible random problems (wrenchcone random).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The distribution is documented in random.h.  Everything here is a
   fixed function of the options: the draws come from our own splitmix64
   and are turned into integers by rejection, never through rand(),
   floating point or anything that differs between platforms.  The order
   of the draws is part of that function, so changing it changes the
   problems every seed names (and the corpus in data/corpus/ says so).  */

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/random.h"

/* ------------------------------------------------------------------ */
/* The generator.                                                      */

typedef struct
{
    uint64_t s;
}
rng_t;

static uint64_t
rng_next(rng_t * r)
{
    uint64_t z = (r->s += UINT64_C(0x9e3779b97f4a7c15));

    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

/* Uniform in [lo, hi], lo <= hi, the span well below 2^63.  The lowest
   2^64 mod span words are rejected, so every value is equally likely.  */
static slong
rng_int(rng_t * r, slong lo, slong hi)
{
    uint64_t span = (uint64_t) (hi - lo) + 1, threshold, x;

    threshold = (0 - span) % span;
    do
        x = rng_next(r);
    while (x < threshold);
    return lo + (slong) (x % span);
}

/* 1 with probability num/den.  */
static int
rng_chance(rng_t * r, slong num, slong den)
{
    return rng_int(r, 0, den - 1) < num;
}

/* x := one of the len fractions tab[k] = {num, den}, uniformly.  */
static void
rng_pick(fmpq_t x, rng_t * r, const slong (*tab)[2], slong len)
{
    slong k = rng_int(r, 0, len - 1);

    fmpq_set_si(x, tab[k][0], (ulong) tab[k][1]);
}

#define PICK(x, r, tab) \
    rng_pick(x, r, tab, (slong) (sizeof(tab) / sizeof(tab[0])))

/* ------------------------------------------------------------------ */
/* Tables of the distribution (random.h).                              */

static const slong MASSES[][2] = {{1, 1}, {1, 1}, {2, 1}, {3, 1}, {1, 2},
                                  {7, 3}};
static const slong INERTIAS[][2] = {{1, 1}, {1, 1}, {1, 2}, {2, 1}, {5, 12},
                                    {25, 12}};
static const slong MUS[][2] = {{0, 1}, {1, 10}, {1, 5}, {1, 2}, {1, 1},
                               {2, 1}};
static const slong NORMAL_SCALES[][2] = {{2, 1}, {3, 1}, {1, 2}, {3, 2},
                                         {1, 3}};
static const slong RADII[][2] = {{1, 1}, {2, 1}, {1, 2}, {3, 2}, {5, 1}};
static const slong SIDES[][2] = {{1, 1}, {2, 1}, {3, 1}, {1, 2}, {3, 2}};
static const slong CIRCLE_SCALES[][2] = {{1, 1}, {2, 1}, {3, 1}, {5, 2}};
static const slong EDGE_PARAMS[][2] = {{1, 2}, {1, 3}, {2, 3}, {1, 4},
                                       {3, 4}, {1, 5}, {2, 5}};
static const slong HALF_WIDTHS[][2] = {{1, 1}, {2, 1}, {3, 2}};
static const slong HALF_HEIGHTS[][2] = {{1, 1}, {1, 2}, {2, 1}};
static const slong SMALL_SCALES[][2] = {{1, 1}, {2, 1}, {1, 2}, {3, 2}};
static const slong LINE_STEPS[][2] = {{-1, 1}, {2, 1}, {1, 2}, {-1, 2},
                                      {3, 1}};
/* The polygon's circle points: t values in increasing order, so that
   their points are in counter-clockwise order; (-1, 0) (t = infinity)
   comes last.  */
static const slong CIRCLE_TS[][2] = {{-3, 1}, {-2, 1}, {-1, 1}, {-1, 2},
                                     {-1, 3}, {0, 1}, {1, 3}, {1, 2},
                                     {1, 1}, {2, 1}, {3, 1}};
#define NCIRCLE ((slong) (sizeof(CIRCLE_TS) / sizeof(CIRCLE_TS[0])) + 1)

/* 10^-9, the tangent of the angle of a near-parallel pair, and the
   parameter t of the circle's parametrisation with 2t/(1-t^2) just above
   it.  */
#define GIGA 1000000000

/* ------------------------------------------------------------------ */
/* Small exact helpers.                                                */

typedef struct
{
    fmpq v[2];
}
vec2;

static void
vec2_init(vec2 * a)
{
    fmpq_init(a->v + 0);
    fmpq_init(a->v + 1);
}

static void
vec2_clear(vec2 * a)
{
    fmpq_clear(a->v + 0);
    fmpq_clear(a->v + 1);
}

static void
vec2_set(fmpq * d, const fmpq * a)
{
    fmpq_set(d + 0, a + 0);
    fmpq_set(d + 1, a + 1);
}

/* d = a + s b (d may alias a or b).  */
static void
vec2_addmul(fmpq * d, const fmpq * a, const fmpq_t s, const fmpq * b)
{
    fmpq_t x, y;

    fmpq_init(x);
    fmpq_init(y);
    fmpq_mul(x, s, b + 0);
    fmpq_mul(y, s, b + 1);
    fmpq_add(d + 0, a + 0, x);
    fmpq_add(d + 1, a + 1, y);
    fmpq_clear(x);
    fmpq_clear(y);
}

static void
vec2_scale(fmpq * d, const fmpq * a, const fmpq_t s)
{
    fmpq_mul(d + 0, a + 0, s);
    fmpq_mul(d + 1, a + 1, s);
}

static void
vec2_neg(fmpq * d, const fmpq * a)
{
    fmpq_neg(d + 0, a + 0);
    fmpq_neg(d + 1, a + 1);
}

static void
vec2_sub(fmpq * d, const fmpq * a, const fmpq * b)
{
    fmpq_sub(d + 0, a + 0, b + 0);
    fmpq_sub(d + 1, a + 1, b + 1);
}

/* d = a turned by +90 degrees (d must not alias a).  */
static void
vec2_perp(fmpq * d, const fmpq * a)
{
    fmpq_neg(d + 0, a + 1);
    fmpq_set(d + 1, a + 0);
}

static int
vec2_equal(const fmpq * a, const fmpq * b)
{
    return fmpq_equal(a + 0, b + 0) && fmpq_equal(a + 1, b + 1);
}

static int
vec2_is_zero(const fmpq * a)
{
    return fmpq_is_zero(a + 0) && fmpq_is_zero(a + 1);
}

/* sign of a . b  */
static int
vec2_dot_sgn(const fmpq * a, const fmpq * b)
{
    fmpq_t x, y;
    int s;

    fmpq_init(x);
    fmpq_init(y);
    fmpq_mul(x, a + 0, b + 0);
    fmpq_mul(y, a + 1, b + 1);
    fmpq_add(x, x, y);
    s = fmpq_sgn(x);
    fmpq_clear(x);
    fmpq_clear(y);
    return s;
}

/* x = y / k, k != 0 (FLINT 2.9 has no fmpq_div_si).  */
static void
q_div_si(fmpq_t x, const fmpq_t y, slong k)
{
    fmpz_t d;

    fmpz_init_set_si(d, k);
    fmpq_div_fmpz(x, y, d);
    fmpz_clear(d);
}

/* 1 when a and b point the same way (a x b = 0 and a . b > 0).  */
static int
same_direction(const fmpq * a, const fmpq * b)
{
    fmpq_t x, y;
    int par;

    fmpq_init(x);
    fmpq_init(y);
    fmpq_mul(x, a + 0, b + 1);
    fmpq_mul(y, a + 1, b + 0);
    par = fmpq_equal(x, y);
    fmpq_clear(x);
    fmpq_clear(y);
    return par && vec2_dot_sgn(a, b) > 0;
}

/* 1 when fixel i repeats the point and normal direction of an earlier
   one: an input error (SPEC 3) that the generator must never make.  */
static int
repeats_earlier(const wc_problem_struct * P, slong i)
{
    const wc_fixel_struct * f = P->fixels + i;
    slong j;

    for (j = 0; j < i; j++)
        if (vec2_equal(f->point, P->fixels[j].point)
            && same_direction(f->normal, P->fixels[j].normal))
            return 1;
    return 0;
}

/* The point of the unit circle with parameter t:
   ((1 - t^2), 2t) / (1 + t^2).  */
static void
circle_point(fmpq * p, const fmpq_t t)
{
    fmpq_t t2, den;

    fmpq_init(t2);
    fmpq_init(den);
    fmpq_mul(t2, t, t);
    fmpq_add_si(den, t2, 1);
    fmpq_sub_si(t2, t2, 1);
    fmpq_neg(t2, t2);
    fmpq_div(p + 0, t2, den);
    fmpq_mul_si(p + 1, t, 2);
    fmpq_div(p + 1, p + 1, den);
    fmpq_clear(t2);
    fmpq_clear(den);
}

/* d = a rotated by the unit vector e (complex multiplication).  d must
   not alias a or e.  */
static void
rotate(fmpq * d, const fmpq * a, const fmpq * e)
{
    fmpq_t x;

    fmpq_init(x);
    fmpq_mul(d + 0, a + 0, e + 0);
    fmpq_mul(x, a + 1, e + 1);
    fmpq_sub(d + 0, d + 0, x);
    fmpq_mul(d + 1, a + 0, e + 1);
    fmpq_mul(x, a + 1, e + 0);
    fmpq_add(d + 1, d + 1, x);
    fmpq_clear(x);
}

/* ------------------------------------------------------------------ */
/* Draws.                                                              */

/* a/b with a in [-lim, lim], b in {1, 2, 3}.  */
static void
draw_coord(fmpq_t x, rng_t * r, slong lim)
{
    slong a, b;

    a = rng_int(r, -lim, lim);
    b = rng_int(r, 1, 3);
    fmpq_set_si(x, a, (ulong) b);
}

/* A point without a shape; widen > 0 after collisions.  */
static void
draw_point(fmpq * p, rng_t * r, slong widen)
{
    draw_coord(p + 0, r, 4 + widen);
    draw_coord(p + 1, r, 4 + widen);
}

/* A nonzero integer vector with entries in [-3, 3], sometimes scaled.  */
static void
draw_normal(fmpq * d, rng_t * r)
{
    fmpq_t s;

    do
    {
        fmpq_set_si(d + 0, rng_int(r, -3, 3), 1);
        fmpq_set_si(d + 1, rng_int(r, -3, 3), 1);
    }
    while (vec2_is_zero(d));
    if (rng_chance(r, 1, 3))
    {
        fmpq_init(s);
        PICK(s, r, NORMAL_SCALES);
        vec2_scale(d, d, s);
        fmpq_clear(s);
    }
}

/* Turn d round, with probability 4/5, when it points away from the
   centre of mass o as seen from p (so that most fixels push into the
   part).  */
static void
face_com(fmpq * d, rng_t * r, const fmpq * p, const fmpq * o)
{
    vec2 w;

    vec2_init(&w);
    vec2_sub(w.v, o, p);
    if (vec2_dot_sgn(d, w.v) < 0 && rng_chance(r, 4, 5))
        vec2_neg(d, d);
    vec2_clear(&w);
}

static void
draw_mu(fmpq_t mu_s, fmpq_t mu_k, rng_t * r)
{
    slong k;

    PICK(mu_s, r, MUS);
    k = rng_int(r, 0, 3);
    if (k <= 1)
        fmpq_set(mu_k, mu_s);
    else if (k == 2)
        q_div_si(mu_k, mu_s, 2);
    else
        PICK(mu_k, r, MUS);
}

/* ------------------------------------------------------------------ */
/* Shapes.                                                             */

/* Allocate P's shape data: len rationals, all zero.  */
static int
shape_alloc(wc_problem_struct * P, wc_shape_kind kind, slong len)
{
    slong i;

    P->shape_data = malloc((size_t) len * sizeof(fmpq));
    if (P->shape_data == NULL)
        return WC_EINTERNAL;
    for (i = 0; i < len; i++)
        fmpq_init(P->shape_data + i);
    P->shape_len = len;
    P->shape = kind;
    return WC_OK;
}

/* Vertex k of the polygon (indices taken modulo the vertex count).  */
static const fmpq *
vertex(const wc_problem_struct * P, slong k)
{
    slong m = P->shape_len / 2;

    return P->shape_data + 2 * (((k % m) + m) % m);
}

/* The polygon's vertices are counter-clockwise while fixels are placed
   (they may be reversed at the very end), so the inward normal of edge k
   is its edge vector turned by +90 degrees.  */
static void
edge_normal(fmpq * d, const wc_problem_struct * P, slong k)
{
    const fmpq * a = vertex(P, k), * b = vertex(P, k + 1);

    fmpq_sub(d + 0, a + 1, b + 1);
    fmpq_sub(d + 1, b + 0, a + 0);
}

/* A fixel inside edge k at parameter s.  */
static void
edge_fixel(wc_fixel_struct * f, const wc_problem_struct * P, slong k,
           const fmpq_t s)
{
    vec2 e;

    vec2_init(&e);
    vec2_sub(e.v, vertex(P, k + 1), vertex(P, k));
    vec2_addmul(f->point, vertex(P, k), s, e.v);
    edge_normal(f->normal, P, k);
    vec2_clear(&e);
}

/* A random edge parameter in (0, 1): from EDGE_PARAMS, or a/b with b up
   to 8 + widen after collisions.  */
static void
draw_edge_param(fmpq_t s, rng_t * r, slong widen)
{
    if (widen == 0)
        PICK(s, r, EDGE_PARAMS);
    else
    {
        slong b = rng_int(r, 2, 8 + widen);

        fmpq_set_si(s, rng_int(r, 1, b - 1), (ulong) b);
    }
}

static void
polygon_generic_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                      rng_t * r, slong widen)
{
    fmpq_t s;
    slong k = rng_int(r, 0, P->shape_len / 2 - 1);

    fmpq_init(s);
    draw_edge_param(s, r, widen);
    edge_fixel(f, P, k, s);
    fmpq_clear(s);
}

/* The disk's point with parameter t (or (-1, 0) when t is NULL), and its
   true inward normal c - p.  */
static void
disk_fixel(wc_fixel_struct * f, const wc_problem_struct * P, const fmpq_t t)
{
    const fmpq * c = P->shape_data;
    const fmpq * rad = P->shape_data + 2;
    vec2 q;

    vec2_init(&q);
    if (t != NULL)
        circle_point(q.v, t);
    else
        fmpq_set_si(q.v + 0, -1, 1);
    vec2_addmul(f->point, c, rad, q.v);
    vec2_sub(f->normal, c, f->point);
    vec2_clear(&q);
}

static void
disk_generic_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                   rng_t * r, slong widen)
{
    fmpq_t t;
    slong a, b;

    if (rng_chance(r, 1, 8))
    {
        disk_fixel(f, P, NULL);
        return;
    }
    fmpq_init(t);
    /* one draw per statement: the order in which a compiler evaluates
       function arguments is unspecified, the order of draws is not */
    a = rng_int(r, -5 - widen, 5 + widen);
    b = rng_int(r, 1, 5 + widen);
    fmpq_set_si(t, a, (ulong) b);
    disk_fixel(f, P, t);
    fmpq_clear(t);
}

static void
plain_generic_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                    rng_t * r, slong widen)
{
    draw_point(f->point, r, widen);
    draw_normal(f->normal, r);
    face_com(f->normal, r, f->point, P->com);
}

/* Fixel i drawn without degeneracy for P's shape, again and again (from
   wider ranges) until it repeats no earlier fixel.  */
static void
generic_fixel(wc_problem_struct * P, slong i, rng_t * r)
{
    slong widen = 0;

    do
    {
        wc_fixel_struct * f = P->fixels + i;

        if (P->shape == WC_SHAPE_DISK)
            disk_generic_fixel(f, P, r, widen);
        else if (P->shape == WC_SHAPE_POLYGON)
            polygon_generic_fixel(f, P, r, widen);
        else
            plain_generic_fixel(f, P, r, widen);
        widen++;
    }
    while (repeats_earlier(P, i));
}

/* A disk: centre, radius; com as random.h says (always the centre when
   degenerate).  */
static int
make_disk(wc_problem_struct * P, rng_t * r, int degenerate)
{
    fmpq * c;
    fmpq_t a;

    if (shape_alloc(P, WC_SHAPE_DISK, 3) != WC_OK)
        return WC_EINTERNAL;
    c = P->shape_data;
    if (rng_chance(r, 1, 2))
        draw_point(c, r, 0);
    PICK(c + 2, r, RADII);
    vec2_set(P->com, c);
    if (!degenerate && rng_chance(r, 1, 2))
    {
        fmpq_init(a);
        q_div_si(a, c + 2, 4);
        fmpq_mul_si(P->com + 0, a, rng_int(r, -1, 1));
        fmpq_mul_si(P->com + 1, a, rng_int(r, -1, 1));
        fmpq_add(P->com + 0, P->com + 0, c + 0);
        fmpq_add(P->com + 1, P->com + 1, c + 1);
        fmpq_clear(a);
    }
    return WC_OK;
}

/* o = the average of the m points v[0..2m).  */
static void
vertex_average(fmpq * o, const fmpq * v, slong m)
{
    fmpq_t x, y;
    fmpz_t d;
    slong i;

    fmpq_init(x);
    fmpq_init(y);
    fmpz_init_set_si(d, m);
    for (i = 0; i < m; i++)
    {
        fmpq_add(x, x, v + 2 * i);
        fmpq_add(y, y, v + 2 * i + 1);
    }
    fmpq_div_fmpz(o + 0, x, d);
    fmpq_div_fmpz(o + 1, y, d);
    fmpq_clear(x);
    fmpq_clear(y);
    fmpz_clear(d);
}

/* A generic convex polygon, counter-clockwise; com the vertex average.  */
static int
make_polygon(wc_problem_struct * P, rng_t * r)
{
    vec2 shift;
    fmpq_t s;
    slong m, i, k;
    int status = WC_OK;

    vec2_init(&shift);
    fmpq_init(s);
    if (rng_chance(r, 1, 3))
    {
        fmpq_t w, h;

        fmpq_init(w);
        fmpq_init(h);
        draw_point(shift.v, r, 0);
        PICK(w, r, SIDES);
        PICK(h, r, SIDES);
        m = 4;
        if (shape_alloc(P, WC_SHAPE_POLYGON, 2 * m) == WC_OK)
        {
            fmpq * v = P->shape_data;

            for (i = 0; i < m; i++)
                vec2_set(v + 2 * i, shift.v);
            fmpq_add(v + 2, v + 2, w);
            fmpq_add(v + 4, v + 4, w);
            fmpq_add(v + 5, v + 5, h);
            fmpq_add(v + 7, v + 7, h);
        }
        else
            status = WC_EINTERNAL;
        fmpq_clear(w);
        fmpq_clear(h);
    }
    else
    {
        slong idx[NCIRCLE], t;

        m = rng_int(r, 3, 6);
        /* the first m of a partial Fisher-Yates shuffle, then sorted:
           distinct circle points in counter-clockwise order */
        for (i = 0; i < NCIRCLE; i++)
            idx[i] = i;
        for (i = 0; i < m; i++)
        {
            k = rng_int(r, i, NCIRCLE - 1);
            t = idx[i];
            idx[i] = idx[k];
            idx[k] = t;
        }
        for (i = 1; i < m; i++)
            for (k = i; k > 0 && idx[k - 1] > idx[k]; k--)
            {
                t = idx[k];
                idx[k] = idx[k - 1];
                idx[k - 1] = t;
            }
        PICK(s, r, CIRCLE_SCALES);
        if (rng_chance(r, 1, 2))
            draw_point(shift.v, r, 0);
        if (shape_alloc(P, WC_SHAPE_POLYGON, 2 * m) == WC_OK)
        {
            fmpq * v = P->shape_data;
            fmpq_t t;

            fmpq_init(t);
            for (i = 0; i < m; i++)
            {
                if (idx[i] < NCIRCLE - 1)
                {
                    fmpq_set_si(t, CIRCLE_TS[idx[i]][0],
                                (ulong) CIRCLE_TS[idx[i]][1]);
                    circle_point(v + 2 * i, t);
                }
                else
                {
                    fmpq_set_si(v + 2 * i, -1, 1);
                    fmpq_zero(v + 2 * i + 1);
                }
                vec2_scale(v + 2 * i, v + 2 * i, s);
                fmpq_add(v + 2 * i, v + 2 * i, shift.v + 0);
                fmpq_add(v + 2 * i + 1, v + 2 * i + 1, shift.v + 1);
            }
            fmpq_clear(t);
        }
        else
            status = WC_EINTERNAL;
    }
    if (status == WC_OK)
        vertex_average(P->com, P->shape_data, m);
    vec2_clear(&shift);
    fmpq_clear(s);
    return status;
}

/* The degenerate polygon, counter-clockwise: a box [-a, a] x [-b, b]
   whose bottom edge bends up by exactly 10^-9 of its run at (0, -b):
   V0 (-a, -b), V1 (0, -b), V2 (a, -b + a/10^9), V3 (a, b), V4 (-a, b).
   com is the origin.  */
static int
make_bent_box(wc_problem_struct * P, rng_t * r)
{
    fmpq_t a, b;
    fmpq * v;

    fmpq_init(a);
    fmpq_init(b);
    PICK(a, r, HALF_WIDTHS);
    PICK(b, r, HALF_HEIGHTS);
    if (shape_alloc(P, WC_SHAPE_POLYGON, 10) != WC_OK)
    {
        fmpq_clear(a);
        fmpq_clear(b);
        return WC_EINTERNAL;
    }
    v = P->shape_data;
    fmpq_neg(v + 0, a);
    fmpq_neg(v + 1, b);
    fmpq_neg(v + 3, b);                         /* V1 = (0, -b) */
    fmpq_set(v + 4, a);
    q_div_si(v + 5, a, GIGA);
    fmpq_sub(v + 5, v + 5, b);
    fmpq_set(v + 6, a);
    fmpq_set(v + 7, b);
    fmpq_neg(v + 8, a);
    fmpq_set(v + 9, b);
    fmpq_zero(P->com + 0);
    fmpq_zero(P->com + 1);
    fmpq_clear(a);
    fmpq_clear(b);
    return WC_OK;
}

/* Reverse the polygon's vertex order (normals, being true inward
   normals, stay as they are).  */
static void
reverse_polygon(wc_problem_struct * P)
{
    slong m = P->shape_len / 2, i;

    for (i = 0; i < m / 2; i++)
    {
        fmpq_swap(P->shape_data + 2 * i, P->shape_data + 2 * (m - 1 - i));
        fmpq_swap(P->shape_data + 2 * i + 1,
                  P->shape_data + 2 * (m - 1 - i) + 1);
    }
}

/* ------------------------------------------------------------------ */
/* Degenerate layouts.  Each plants the features of random.h in fixels
   0, 1, ... and returns how many fixels it used.                      */

/* No shape: S and N at one point q, P at fixel 2, C at fixel 3.  The
   line of C (through q and fixel 2's point) goes to line[0..1] (point)
   and line[2..3] (direction) for the extra fixels.  */
static slong
plant_plain(wc_problem_struct * P, rng_t * r, fmpq * line)
{
    slong n = P->n;
    wc_fixel_struct * f = P->fixels;
    vec2 u, w, d;
    fmpq_t s;

    vec2_init(&u);
    vec2_init(&w);
    vec2_init(&d);
    fmpq_init(s);

    /* fixel 0 at q with normal u */
    draw_point(f[0].point, r, 0);
    do
    {
        fmpq_set_si(u.v + 0, rng_int(r, -3, 3), 1);
        fmpq_set_si(u.v + 1, rng_int(r, -3, 3), 1);
    }
    while (vec2_is_zero(u.v));
    if (n == 1)
    {
        /* O: the normal line through the centre of mass, pushing at it */
        PICK(s, r, SMALL_SCALES);
        fmpq_neg(s, s);
        vec2_addmul(f[0].point, P->com, s, u.v);
        vec2_set(f[0].normal, u.v);
        goto done;
    }
    face_com(u.v, r, f[0].point, P->com);
    PICK(s, r, SMALL_SCALES);
    vec2_scale(f[0].normal, u.v, s);

    /* fixel 1: S and N, the same point, normal s (u + 10^-9 u^perp) */
    vec2_set(f[1].point, f[0].point);
    vec2_perp(w.v, u.v);
    if (rng_chance(r, 1, 2))
        vec2_neg(w.v, w.v);
    fmpq_set_si(s, 1, GIGA);
    vec2_addmul(f[1].normal, u.v, s, w.v);
    PICK(s, r, SMALL_SCALES);
    vec2_scale(f[1].normal, f[1].normal, s);
    if (n == 2)
        goto done;

    /* fixel 2: P, normal +-u at a new point: on the normal line of fixel 0
       (facing it, when opposed) or elsewhere */
    if (rng_chance(r, 1, 2))
    {
        PICK(s, r, SMALL_SCALES);
        vec2_scale(d.v, u.v, s);
    }
    else
        do
            draw_point(d.v, r, 0);
        while (vec2_is_zero(d.v));
    fmpq_one(s);
    vec2_addmul(f[2].point, f[0].point, s, d.v);
    PICK(s, r, SMALL_SCALES);
    if (rng_chance(r, 1, 2))
        fmpq_neg(s, s);
    vec2_scale(f[2].normal, u.v, s);
    vec2_set(line + 0, f[0].point);
    vec2_set(line + 2, d.v);
    if (n == 3)
        goto done;

    /* fixel 3: C, on the line through q and fixel 2, a new point */
    PICK(s, r, LINE_STEPS);
    vec2_addmul(f[3].point, f[0].point, s, d.v);
    draw_normal(f[3].normal, r);
    face_com(f[3].normal, r, f[3].point, P->com);

done:
    vec2_clear(&u);
    vec2_clear(&w);
    vec2_clear(&d);
    fmpq_clear(s);
    return n < 4 ? n : 4;
}

/* The bent box: S and N at the bend V1, P inside the bottom-left edge,
   C at the corner V0.  The line of C is the bottom edge's.  */
static slong
plant_polygon(wc_problem_struct * P, rng_t * r, fmpq * line)
{
    slong n = P->n;
    wc_fixel_struct * f = P->fixels;
    fmpq_t s;

    fmpq_init(s);
    vec2_set(f[0].point, vertex(P, 1));
    edge_normal(f[0].normal, P, 0);
    if (n >= 2)
    {
        vec2_set(f[1].point, vertex(P, 1));
        edge_normal(f[1].normal, P, 1);
    }
    if (n >= 3)
    {
        PICK(s, r, EDGE_PARAMS);
        edge_fixel(f + 2, P, 0, s);
    }
    if (n >= 4)
    {
        vec2_set(f[3].point, vertex(P, 0));
        edge_normal(f[3].normal, P, rng_chance(r, 1, 2) ? 0 : 4);
    }
    vec2_set(line + 0, vertex(P, 0));
    fmpq_one(line + 2);
    fmpq_zero(line + 3);
    fmpq_clear(s);
    return n < 4 ? n : 4;
}

/* The disk: fixel 0 anywhere, P its antipode, N its point turned by the
   parameter 1/(2 10^9).  */
static slong
plant_disk(wc_problem_struct * P, rng_t * r)
{
    slong n = P->n;
    wc_fixel_struct * f = P->fixels;
    const fmpq * c = P->shape_data;

    disk_generic_fixel(f + 0, P, r, 0);
    if (n >= 2)
    {
        vec2_sub(f[1].point, c, f[0].point);
        fmpq_add(f[1].point + 0, f[1].point + 0, c + 0);
        fmpq_add(f[1].point + 1, f[1].point + 1, c + 1);
        vec2_neg(f[1].normal, f[0].normal);
    }
    if (n >= 3)
    {
        vec2 q, e, w;
        fmpq_t t;

        vec2_init(&q);
        vec2_init(&e);
        vec2_init(&w);
        fmpq_init(t);
        fmpq_set_si(t, rng_chance(r, 1, 2) ? 1 : -1, 2 * (ulong) GIGA);
        circle_point(e.v, t);
        vec2_sub(q.v, f[0].point, c);           /* r q0 */
        rotate(w.v, q.v, e.v);                  /* r q2 */
        fmpq_add(f[2].point + 0, c + 0, w.v + 0);
        fmpq_add(f[2].point + 1, c + 1, w.v + 1);
        vec2_neg(f[2].normal, w.v);
        vec2_clear(&q);
        vec2_clear(&e);
        vec2_clear(&w);
        fmpq_clear(t);
    }
    return n < 3 ? n : 3;
}

/* Fixel i (beyond the planted ones) of a degenerate layout: one of four
   kinds (random.h), drawn generically instead if it would repeat an
   earlier fixel.  */
static void
extra_fixel(wc_problem_struct * P, slong i, rng_t * r, const fmpq * line)
{
    wc_fixel_struct * f = P->fixels + i;
    const wc_fixel_struct * g = P->fixels + rng_int(r, 0, i - 1);
    slong kind = rng_int(r, 0, 3);
    fmpq_t s;

    fmpq_init(s);
    if (P->shape == WC_SHAPE_DISK)
    {
        const fmpq * c = P->shape_data;

        if (kind == 0)
        {
            /* the antipode of g */
            vec2_sub(f->point, c, g->point);
            fmpq_add(f->point + 0, f->point + 0, c + 0);
            fmpq_add(f->point + 1, f->point + 1, c + 1);
            vec2_neg(f->normal, g->normal);
        }
        else if (kind == 1)
        {
            /* g turned by +-1/(2 10^9) on the parametrisation */
            vec2 e, w;

            vec2_init(&e);
            vec2_init(&w);
            fmpq_set_si(s, rng_chance(r, 1, 2) ? 1 : -1, 2 * (ulong) GIGA);
            circle_point(e.v, s);
            rotate(w.v, g->normal, e.v);
            vec2_set(f->normal, w.v);
            vec2_sub(f->point, c, w.v);
            vec2_clear(&e);
            vec2_clear(&w);
        }
        else
            disk_generic_fixel(f, P, r, 0);
    }
    else if (P->shape == WC_SHAPE_POLYGON)
    {
        if (kind == 0)
        {
            /* inside the top edge: opposed to the bottom-left edge */
            PICK(s, r, EDGE_PARAMS);
            edge_fixel(f, P, 3, s);
        }
        else if (kind == 1)
        {
            /* a vertex, with the normal of one of its edges */
            slong k = rng_int(r, 0, P->shape_len / 2 - 1);

            vec2_set(f->point, vertex(P, k));
            edge_normal(f->normal, P, rng_chance(r, 1, 2) ? k : k - 1);
        }
        else if (kind == 2)
        {
            /* on the line of C: inside the bottom-left edge */
            PICK(s, r, EDGE_PARAMS);
            edge_fixel(f, P, 0, s);
        }
        else
            polygon_generic_fixel(f, P, r, 0);
    }
    else
    {
        if (kind == 0)
        {
            /* g's normal or its opposite, scaled, at a new point */
            draw_point(f->point, r, 0);
            PICK(s, r, SMALL_SCALES);
            if (rng_chance(r, 1, 2))
                fmpq_neg(s, s);
            vec2_scale(f->normal, g->normal, s);
        }
        else if (kind == 1)
        {
            /* g's point, g's normal turned by 90 or 180 degrees */
            slong turn = rng_int(r, 0, 2);

            vec2_set(f->point, g->point);

            if (turn == 0)
                vec2_neg(f->normal, g->normal);
            else
            {
                vec2_perp(f->normal, g->normal);
                if (turn == 2)
                    vec2_neg(f->normal, f->normal);
            }
        }
        else if (kind == 2)
        {
            /* on the line of C */
            draw_coord(s, r, 4);
            vec2_addmul(f->point, line, s, line + 2);
            draw_normal(f->normal, r);
            face_com(f->normal, r, f->point, P->com);
        }
        else
            plain_generic_fixel(f, P, r, 0);
    }
    fmpq_clear(s);
    if (repeats_earlier(P, i))
        generic_fixel(P, i, r);
}

/* ------------------------------------------------------------------ */
/* The entry points.                                                   */

void
wc_random_options_init(wc_random_options * opt)
{
    opt->fixels = 3;
    opt->seed = 1;
    opt->degenerate = 0;
    opt->shape = WC_SHAPE_NONE;
    opt->friction = 0;
    fmpq_init(opt->mu_s);
    fmpq_init(opt->mu_k);
}

void
wc_random_options_clear(wc_random_options * opt)
{
    fmpq_clear(opt->mu_s);
    fmpq_clear(opt->mu_k);
}

char *
wc_random_options_str(const wc_random_options * opt)
{
    char * mus = NULL, * muk = NULL, * s = NULL;
    size_t len = 128;

    if (opt->friction)
    {
        mus = fmpq_get_str(NULL, 10, opt->mu_s);
        muk = fmpq_get_str(NULL, 10, opt->mu_k);
        len += strlen(mus) + strlen(muk);
    }
    s = malloc(len);
    if (s != NULL)
    {
        int k = snprintf(s, len, "--fixels=%ld --seed=%" PRIu64 "%s%s",
                         (long) opt->fixels, opt->seed,
                         opt->degenerate ? " --degenerate" : "",
                         opt->shape == WC_SHAPE_DISK ? " --shape=disk"
                         : opt->shape == WC_SHAPE_POLYGON ? " --shape=polygon"
                         : "");

        if (opt->friction && k >= 0 && (size_t) k < len)
            snprintf(s + k, len - (size_t) k, " --friction=%s%s%s", mus,
                     fmpq_equal(opt->mu_s, opt->mu_k) ? "" : ",",
                     fmpq_equal(opt->mu_s, opt->mu_k) ? "" : muk);
    }
    flint_free(mus);
    flint_free(muk);
    return s;
}

int
wc_random_problem(wc_problem_t P, const wc_random_options * opt,
                  wc_error_t err)
{
    rng_t rng;
    rng_t * r = &rng;
    slong n, i, planted = 0;
    fmpq line[4];               /* the line of C: a point, a direction */
    char * opts = NULL;
    int status = WC_OK;

    if (opt->fixels < 1 || opt->fixels > WC_RANDOM_MAX_FIXELS)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "the number of "
                            "fixels must be from 1 to %d, not %ld",
                            WC_RANDOM_MAX_FIXELS, (long) opt->fixels);
    if (opt->shape != WC_SHAPE_NONE && opt->shape != WC_SHAPE_DISK
        && opt->shape != WC_SHAPE_POLYGON)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0, "unknown shape %d",
                            (int) opt->shape);
    if (opt->friction && (fmpq_sgn(opt->mu_s) < 0 || fmpq_sgn(opt->mu_k) < 0))
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "friction must not be negative");
    n = opt->fixels;
    r->s = opt->seed;
    for (i = 0; i < 4; i++)
        fmpq_init(line + i);

    opts = wc_random_options_str(opt);
    if (opts == NULL || (P->name = malloc(strlen(opts) + 8)) == NULL)
    {
        status = WC_EINTERNAL;
        goto cleanup;
    }
    strcpy(P->name, "random ");
    strcat(P->name, opts);

    /* Globals first: wc_problem_add_fixel copies the global friction.  */
    PICK(P->mass, r, MASSES);
    PICK(P->inertia, r, INERTIAS);
    if (opt->friction)
    {
        fmpq_set(P->mu_s, opt->mu_s);
        fmpq_set(P->mu_k, opt->mu_k);
    }
    else
        draw_mu(P->mu_s, P->mu_k, r);
    for (i = 0; i < n; i++)
        if (wc_problem_add_fixel(P) == NULL)
        {
            status = WC_EINTERNAL;
            goto cleanup;
        }

    /* The shape and the centre of mass, then the fixels.  */
    if (opt->shape == WC_SHAPE_DISK)
        status = make_disk(P, r, opt->degenerate);
    else if (opt->shape == WC_SHAPE_POLYGON)
        status = opt->degenerate ? make_bent_box(P, r) : make_polygon(P, r);
    else if (rng_chance(r, 1, 2))
        draw_point(P->com, r, 0);
    if (status != WC_OK)
        goto cleanup;
    if (opt->degenerate)
    {
        if (opt->shape == WC_SHAPE_DISK)
            planted = plant_disk(P, r);
        else if (opt->shape == WC_SHAPE_POLYGON)
            planted = plant_polygon(P, r, line);
        else
            planted = plant_plain(P, r, line);
        for (i = planted; i < n; i++)
            extra_fixel(P, i, r, line);
        /* Fisher-Yates: the features anywhere in the fixel order */
        for (i = n - 1; i > 0; i--)
        {
            slong k = rng_int(r, 0, i);
            wc_fixel_struct t = P->fixels[i];

            P->fixels[i] = P->fixels[k];
            P->fixels[k] = t;
        }
    }
    else
        for (i = 0; i < n; i++)
            generic_fixel(P, i, r);
    if (opt->shape == WC_SHAPE_POLYGON && rng_chance(r, 1, 4))
        reverse_polygon(P);

    for (i = 0; i < n; i++)
    {
        wc_fixel_struct * f = P->fixels + i;

        f->state = rng_chance(r, 1, 3) ? WC_NEAR : WC_TOUCHING;
        if (!opt->friction && rng_chance(r, 1, 5))
            draw_mu(f->mu_s, f->mu_k, r);
    }

cleanup:
    if (status != WC_OK)
        wc_error_set(err, status, NULL, 0, 0, "out of memory");
    free(opts);
    for (i = 0; i < 4; i++)
        fmpq_clear(line + i);
    return status;
}
