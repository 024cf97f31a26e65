/* randshape.c -- random shapes, and fixels drawn on them in general position.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdlib.h>

#include "core/randgen.h"

static const slong RADII[][2] = {{1, 1}, {2, 1}, {1, 2}, {3, 2}, {5, 1}};
static const slong SIDES[][2] = {{1, 1}, {2, 1}, {3, 1}, {1, 2}, {3, 2}};
static const slong CIRCLE_SCALES[][2] = {{1, 1}, {2, 1}, {3, 1}, {5, 2}};
static const slong HALF_WIDTHS[][2] = {{1, 1}, {2, 1}, {3, 2}};
static const slong HALF_HEIGHTS[][2] = {{1, 1}, {1, 2}, {2, 1}};
/* The polygon's circle points: t values in increasing order, so that
   their points are in counter-clockwise order; (-1, 0) (t = infinity)
   comes last.  */
static const slong CIRCLE_TS[][2] = {{-3, 1}, {-2, 1}, {-1, 1}, {-1, 2},
                                     {-1, 3}, {0, 1}, {1, 3}, {1, 2},
                                     {1, 1}, {2, 1}, {3, 1}};
#define NCIRCLE ((slong) (sizeof(CIRCLE_TS) / sizeof(CIRCLE_TS[0])) + 1)

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
const fmpq *
_wc_random_vertex(const wc_problem_struct * P, slong k)
{
    slong m = P->shape_len / 2;

    return P->shape_data + 2 * (((k % m) + m) % m);
}

/* The polygon's vertices are counter-clockwise while fixels are placed
   (they may be reversed at the very end), so the inward normal of edge k
   is its edge vector turned by +90 degrees.  */
void
_wc_random_edge_normal(fmpq * d, const wc_problem_struct * P, slong k)
{
    const fmpq * a = _wc_random_vertex(P, k);
    const fmpq * b = _wc_random_vertex(P, k + 1);

    fmpq_sub(d + 0, a + 1, b + 1);
    fmpq_sub(d + 1, b + 0, a + 0);
}

/* A fixel inside edge k at parameter s.  */
void
_wc_random_edge_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                      slong k, const fmpq_t s)
{
    wc_qvec2 e;

    _wc_qvec2_init(&e);
    _wc_qvec2_sub(e.v, _wc_random_vertex(P, k + 1), _wc_random_vertex(P, k));
    _wc_qvec2_addmul(f->point, _wc_random_vertex(P, k), s, e.v);
    _wc_random_edge_normal(f->normal, P, k);
    _wc_qvec2_clear(&e);
}

/* A random edge parameter in (0, 1): from _wc_edge_params, or a/b with b up
   to 8 + widen after collisions.  */
static void
draw_edge_param(fmpq_t s, wc_rng * r, slong widen)
{
    if (widen == 0)
        PICK(s, r, _wc_edge_params);
    else
    {
        slong b = _wc_rng_int(r, 2, 8 + widen);

        fmpq_set_si(s, _wc_rng_int(r, 1, b - 1), (ulong) b);
    }
}

void
_wc_random_polygon_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                         wc_rng * r, slong widen)
{
    fmpq_t s;
    slong k = _wc_rng_int(r, 0, P->shape_len / 2 - 1);

    fmpq_init(s);
    draw_edge_param(s, r, widen);
    _wc_random_edge_fixel(f, P, k, s);
    fmpq_clear(s);
}

/* The disk's point with parameter t (or (-1, 0) when t is NULL), and its
   true inward normal c - p.  */
static void
disk_fixel(wc_fixel_struct * f, const wc_problem_struct * P, const fmpq_t t)
{
    const fmpq * c = P->shape_data;
    const fmpq * rad = P->shape_data + 2;
    wc_qvec2 q;

    _wc_qvec2_init(&q);
    if (t != NULL)
        _wc_unit_circle_point(q.v, t);
    else
        fmpq_set_si(q.v + 0, -1, 1);
    _wc_qvec2_addmul(f->point, c, rad, q.v);
    _wc_qvec2_sub(f->normal, c, f->point);
    _wc_qvec2_clear(&q);
}

void
_wc_random_disk_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                      wc_rng * r, slong widen)
{
    fmpq_t t;
    slong a, b;

    if (_wc_rng_chance(r, 1, 8))
    {
        disk_fixel(f, P, NULL);
        return;
    }
    fmpq_init(t);
    /* one draw per statement: the order in which a compiler evaluates
       function arguments is unspecified, the order of draws is not */
    a = _wc_rng_int(r, -5 - widen, 5 + widen);
    b = _wc_rng_int(r, 1, 5 + widen);
    fmpq_set_si(t, a, (ulong) b);
    disk_fixel(f, P, t);
    fmpq_clear(t);
}

void
_wc_random_plain_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                       wc_rng * r, slong widen)
{
    _wc_random_point(f->point, r, widen);
    _wc_random_normal(f->normal, r);
    _wc_random_face_com(f->normal, r, f->point, P->com);
}

/* Fixel i drawn without degeneracy for P's shape, again and again (from
   wider ranges) until it repeats no earlier fixel.  */
void
_wc_random_generic_fixel(wc_problem_struct * P, slong i, wc_rng * r)
{
    slong widen = 0;

    do
    {
        wc_fixel_struct * f = P->fixels + i;

        if (P->shape == WC_SHAPE_DISK)
            _wc_random_disk_fixel(f, P, r, widen);
        else if (P->shape == WC_SHAPE_POLYGON)
            _wc_random_polygon_fixel(f, P, r, widen);
        else
            _wc_random_plain_fixel(f, P, r, widen);
        widen++;
    }
    while (_wc_random_repeats(P, i));
}

/* A disk: centre, radius; com as random.h says (always the centre when
   degenerate).  */
int
_wc_random_disk(wc_problem_struct * P, wc_rng * r, int degenerate)
{
    fmpq * c;
    fmpq_t a;

    if (shape_alloc(P, WC_SHAPE_DISK, 3) != WC_OK)
        return WC_EINTERNAL;
    c = P->shape_data;
    if (_wc_rng_chance(r, 1, 2))
        _wc_random_point(c, r, 0);
    PICK(c + 2, r, RADII);
    _wc_qvec2_set(P->com, c);
    if (!degenerate && _wc_rng_chance(r, 1, 2))
    {
        fmpq_init(a);
        _wc_fmpq_div_si(a, c + 2, 4);
        fmpq_mul_si(P->com + 0, a, _wc_rng_int(r, -1, 1));
        fmpq_mul_si(P->com + 1, a, _wc_rng_int(r, -1, 1));
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
int
_wc_random_polygon(wc_problem_struct * P, wc_rng * r)
{
    wc_qvec2 shift;
    fmpq_t s;
    slong m, i, k;
    int status = WC_OK;

    _wc_qvec2_init(&shift);
    fmpq_init(s);
    if (_wc_rng_chance(r, 1, 3))
    {
        fmpq_t w, h;

        fmpq_init(w);
        fmpq_init(h);
        _wc_random_point(shift.v, r, 0);
        PICK(w, r, SIDES);
        PICK(h, r, SIDES);
        m = 4;
        if (shape_alloc(P, WC_SHAPE_POLYGON, 2 * m) == WC_OK)
        {
            fmpq * v = P->shape_data;

            for (i = 0; i < m; i++)
                _wc_qvec2_set(v + 2 * i, shift.v);
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

        m = _wc_rng_int(r, 3, 6);
        /* the first m of a partial Fisher-Yates shuffle, then sorted:
           distinct circle points in counter-clockwise order */
        for (i = 0; i < NCIRCLE; i++)
            idx[i] = i;
        for (i = 0; i < m; i++)
        {
            k = _wc_rng_int(r, i, NCIRCLE - 1);
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
        if (_wc_rng_chance(r, 1, 2))
            _wc_random_point(shift.v, r, 0);
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
                    _wc_unit_circle_point(v + 2 * i, t);
                }
                else
                {
                    fmpq_set_si(v + 2 * i, -1, 1);
                    fmpq_zero(v + 2 * i + 1);
                }
                _wc_qvec2_scale(v + 2 * i, v + 2 * i, s);
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
    _wc_qvec2_clear(&shift);
    fmpq_clear(s);
    return status;
}

/* The degenerate polygon, counter-clockwise: a box [-a, a] x [-b, b]
   whose bottom edge bends up by exactly 10^-9 of its run at (0, -b):
   V0 (-a, -b), V1 (0, -b), V2 (a, -b + a/10^9), V3 (a, b), V4 (-a, b).
   com is the origin.  */
int
_wc_random_bent_box(wc_problem_struct * P, wc_rng * r)
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
    _wc_fmpq_div_si(v + 5, a, GIGA);
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
void
_wc_random_reverse(wc_problem_struct * P)
{
    slong m = P->shape_len / 2, i;

    for (i = 0; i < m / 2; i++)
    {
        fmpq_swap(P->shape_data + 2 * i, P->shape_data + 2 * (m - 1 - i));
        fmpq_swap(P->shape_data + 2 * i + 1,
                  P->shape_data + 2 * (m - 1 - i) + 1);
    }
}

