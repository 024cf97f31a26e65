/* arrangement.c -- the faces of a central arrangement of planes in R^3,
   by a walk around each plane.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The planes meet pairwise in lines.  On plane p the k lines through it
   give 2k rays, which cut p into 2k arcs; with k >= 2 each arc has an
   angle below pi and the sum of its two rays lies in it, with k = 1 the
   two arcs are half-planes, whose points are +-(h_p x u) for the line's
   direction u.  Every chamber has a facet, whose relative interior is one
   sector (a plane that cut it would cut the chamber), so going around
   every plane meets every face.

   The sign vector changes little from face to face: on the arc, plane p
   is zero and the others keep one sign (each meets p in one of p's lines,
   whose rays are not inside the arc); a chamber beside it differs in p
   only; the ray ending the arc differs in the planes through it, which
   take new signs on the next arc.  So each plane costs m dot products at
   its first arc and then one per plane through each ray it crosses: 2m in
   all, as each other plane meets p in one line.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "core/tick.h"
#include "exact/vec3.h"
#include "exact/arrangement.h"

static int
slong_cmp(const void * p, const void * q)
{
    slong a = *(const slong *) p, b = *(const slong *) q;

    return (a > b) - (a < b);
}

/* Sort each of the n lists x[off[i] .. off[i] + len[i]) and drop repeats;
   len[i] becomes the number kept.  */
static void
sort_unique(slong * x, const slong * off, slong * len, slong n)
{
    slong i, j, c;

    for (i = 0; i < n; i++)
    {
        slong * y = x + off[i];

        qsort(y, len[i], sizeof(slong), slong_cmp);
        for (j = 0, c = 0; j < len[i]; j++)
            if (c == 0 || y[c - 1] != y[j])
                y[c++] = y[j];
        len[i] = c;
    }
}

/* off := the offsets of lists of lengths len (compacting x, whose list i
   starts at old[i]).  */
static void
compact(slong * x, slong * off, const slong * old, const slong * len,
        slong n)
{
    slong i;

    off[0] = 0;
    for (i = 0; i < n; i++)
    {
        memmove(x + off[i], x + old[i], sizeof(slong) * len[i]);
        off[i + 1] = off[i] + len[i];
    }
}

int
_wc_arrangement_init(_wc_arrangement_t A, const fmpz_mat_t planes,
                     wc_error_t err)
{
    slong m = fmpz_mat_nrows(planes), npair = m * (m - 1) / 2;
    slong p, q, i, e = 0, nl;
    slong * pl = flint_malloc(sizeof(slong) * (npair + 1));
    slong * old = flint_malloc(sizeof(slong) * (npair + m + 1));
    slong * len = flint_calloc(npair + m + 1, sizeof(slong));
    fmpz * v = _fmpz_vec_init(3);
    fmpz_t t;
    int status = WC_OK;

    fmpz_init(t);
    A->m = m;
    A->planes = planes;
    _wc_zvec3_set_init(A->lines, npair);
    A->loff = flint_malloc(sizeof(slong) * (m + 1));
    A->lon = flint_malloc(sizeof(slong) * (2 * npair + 1));
    for (p = 0; p < m; p++)
        old[p] = p * (m - 1);
    for (p = 0; p < m && status == WC_OK; p++)
        for (q = p + 1; q < m; q++)
        {
            _wc_zvec3_cross(v, WC_ROW(planes, p), WC_ROW(planes, q));
            if (!_wc_zvec3_canonical(v, t))
            {
                status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                      "internal error: arrangement: planes "
                                      "%ld and %ld are parallel", (long) p,
                                      (long) q);
                break;
            }
            pl[e] = _wc_zvec3_set_id(A->lines, v);
            A->lon[old[p] + len[p]++] = pl[e];
            A->lon[old[q] + len[q]++] = pl[e];
            e++;
        }
    sort_unique(A->lon, old, len, m);
    compact(A->lon, A->loff, old, len, m);

    /* The planes through each line, from the pairs meeting in it.  */
    nl = A->lines->count;
    A->poff = flint_malloc(sizeof(slong) * (nl + 1));
    A->pon = flint_malloc(sizeof(slong) * (2 * e + 1));
    memset(len, 0, sizeof(slong) * (nl + 1));
    for (i = 0; i < e; i++)
        len[pl[i]] += 2;
    for (i = 0, old[0] = 0; i < nl; i++)
        old[i + 1] = old[i] + len[i];
    memset(len, 0, sizeof(slong) * (nl + 1));
    for (p = 0, i = 0; p < m && i < e; p++)
        for (q = p + 1; q < m && i < e; q++, i++)
        {
            A->pon[old[pl[i]] + len[pl[i]]++] = p;
            A->pon[old[pl[i]] + len[pl[i]]++] = q;
        }
    sort_unique(A->pon, old, len, nl);
    compact(A->pon, A->poff, old, len, nl);

    flint_free(pl);
    flint_free(old);
    flint_free(len);
    _fmpz_vec_clear(v, 3);
    fmpz_clear(t);
    return status;
}

void
_wc_arrangement_clear(_wc_arrangement_t A)
{
    _wc_zvec3_set_clear(A->lines);
    flint_free(A->loff);
    flint_free(A->lon);
    flint_free(A->poff);
    flint_free(A->pon);
}

/* ---------------------------------------------------------------------
   The walk.  */

/* A line on a plane with its direction in the plane's coordinates
   (x, y), turned into the half-plane y > 0 or y = 0 < x; o says whether
   the line's canonical direction was turned.  */
typedef struct
{
    fmpz_t x;
    fmpz_t y;
    slong line;
    int o;
}
angle_ref;

int
_wc_angle_cmp(const fmpz_t ax, const fmpz_t ay, const fmpz_t bx,
              const fmpz_t by)
{
    fmpz_t c;
    int s;

#ifdef __SIZEOF_INT128__
    if (!COEFF_IS_MPZ(*ax) && !COEFF_IS_MPZ(*ay) && !COEFF_IS_MPZ(*bx)
        && !COEFF_IS_MPZ(*by))
    {
        /* below 2^62 each: the products below 2^124 */
        __int128 d = (__int128) *ax * *by - (__int128) *ay * *bx;

        return (d < 0) - (d > 0);
    }
#endif
    fmpz_init(c);
    fmpz_mul(c, ax, by);
    fmpz_submul(c, ay, bx);
    s = -fmpz_sgn(c);
    fmpz_clear(c);
    return s;
}

/* By angle in [0, pi): a before b when b is counter-clockwise of a.  */
static int
angle_cmp(const void * p, const void * q)
{
    const angle_ref * a = p, * b = q;

    return _wc_angle_cmp(a->x, a->y, b->x, b->y);
}

typedef struct
{
    const _wc_arrangement_struct * A;
    _wc_face_fn visit;
    void * data;
    _wc_face_struct F;
    signed char * sign;         /* m */
    slong * changed;            /* m */
    unsigned char * dirty;      /* m: in changed */
    unsigned char * done;       /* 2 lines: ray reported */
    angle_ref * ang;            /* m: the lines on the current plane */
    slong k;                    /* how many */
    fmpz * u;                   /* the plane's basis (u, w = h x u) */
    fmpz * w;
    fmpz * mid;                 /* the current arc's point */
    fmpz * next;                /* the next arc's point */
    fmpz * ray;
    fmpz_t t;
}
walker;

static void
set_sign(walker * W, slong q, int s)
{
    if (W->sign[q] == s)
        return;
    W->sign[q] = (signed char) s;
    if (!W->dirty[q])
    {
        W->dirty[q] = 1;
        W->changed[W->F.nchanged++] = q;
    }
}

/* The sign of plane q at x.  */
static void
update_sign(walker * W, slong q, const fmpz * x)
{
    set_sign(W, q, _wc_zvec3_dot_sgn_fast(WC_ROW(W->A->planes, q), x, W->t));
}

static int
report(walker * W, int dim, const fmpz * point, slong p, int side,
       wc_error_t err)
{
    slong i;
    int status;

    W->F.dim = dim;
    W->F.point = point;
    W->F.plane = dim >= 2 ? p : -1;
    W->F.normal = dim >= 2 ? WC_ROW(W->A->planes, p) : NULL;
    W->F.side = dim == 3 ? side : 0;
    status = W->visit(W->data, &W->F, err);
    for (i = 0; i < W->F.nchanged; i++)
        W->dirty[W->changed[i]] = 0;
    W->F.nchanged = 0;
    return status;
}

/* Ray j of the current plane (0 <= j < 2k): line j mod k, turned for
   j >= k.  Its id is 2 line + (1 when it is the line's canonical
   direction turned).  */
static slong
ray_id(const walker * W, slong j)
{
    const angle_ref * r = W->ang + (j % W->k);
    int o = j < W->k ? r->o : -r->o;

    return 2 * r->line + (o < 0);
}

static void
ray_vector(fmpz * v, const walker * W, slong id)
{
    const fmpz * d = _wc_zvec3_set_entry(W->A->lines, id / 2);

    if (id & 1)
        _fmpz_vec_neg(v, d, 3);
    else
        _fmpz_vec_set(v, d, 3);
}

/* The lines on plane p in angular order.  */
static void
sort_lines(walker * W, slong p)
{
    const _wc_arrangement_struct * A = W->A;
    const fmpz * h = WC_ROW(A->planes, p);
    const slong * lines = A->lon + A->loff[p];
    slong i;

    W->k = _wc_arrangement_nlines_on(A, p);
    _fmpz_vec_set(W->u, _wc_zvec3_set_entry(A->lines, lines[0]), 3);
    _wc_zvec3_cross(W->w, h, W->u);
    for (i = 0; i < W->k; i++)
    {
        angle_ref * r = W->ang + i;
        const fmpz * v = _wc_zvec3_set_entry(A->lines, lines[i]);

        _fmpz_vec_dot(r->x, v, W->u, 3);
        _fmpz_vec_dot(r->y, v, W->w, 3);
        r->line = lines[i];
        r->o = 1;
        if (fmpz_sgn(r->y) < 0 || (fmpz_is_zero(r->y) && fmpz_sgn(r->x) < 0))
        {
            fmpz_neg(r->x, r->x);
            fmpz_neg(r->y, r->y);
            r->o = -1;
        }
    }
    qsort(W->ang, W->k, sizeof(angle_ref), angle_cmp);
}

/* x := the point of arc j, from ray j to ray j + 1.  */
static void
arc_point(fmpz * x, walker * W, slong j)
{
    if (W->k == 1)
        _fmpz_vec_scalar_mul_si(x, W->w, 3, j == 0 ? 1 : -1);
    else
    {
        ray_vector(x, W, ray_id(W, j));
        ray_vector(W->ray, W, ray_id(W, (j + 1) % (2 * W->k)));
        _fmpz_vec_add(x, x, W->ray, 3);
    }
    _wc_zvec3_primitive(x, W->t);
}

/* Step from arc j over the ray ending it: the planes through the ray but
   p are zero on it, and take their signs on arc j + 1 after it.  */
static int
cross_ray(walker * W, slong p, slong j, wc_error_t err)
{
    const _wc_arrangement_struct * A = W->A;
    slong c = 2 * W->k, r = ray_id(W, (j + 1) % c), i;
    const slong * on = A->pon + A->poff[r / 2];
    slong non = A->poff[r / 2 + 1] - A->poff[r / 2];
    fmpz * swap;
    int status = WC_OK;

    for (i = 0; i < non; i++)
        if (on[i] != p)
            set_sign(W, on[i], 0);
    if (!W->done[r])
    {
        W->done[r] = 1;
        ray_vector(W->ray, W, r);
        status = report(W, 1, W->ray, -1, 0, err);
    }
    if (status != WC_OK || j + 1 == c)
        return status;
    arc_point(W->next, W, j + 1);
    for (i = 0; i < non; i++)
        if (on[i] != p)
            update_sign(W, on[i], W->next);
    swap = W->mid;
    W->mid = W->next;
    W->next = swap;
    return WC_OK;
}

static int
walk_plane(walker * W, slong p, wc_error_t err)
{
    slong m = W->A->m, q, j;
    int side, status = WC_OK;

    sort_lines(W, p);
    arc_point(W->mid, W, 0);
    for (q = 0; q < m; q++)
        update_sign(W, q, W->mid);
    for (j = 0; j < 2 * W->k && status == WC_OK; j++)
    {
        status = report(W, 2, W->mid, p, 0, err);
        for (side = -1; side <= 1 && status == WC_OK; side += 2)
        {
            set_sign(W, p, side);
            status = report(W, 3, W->mid, p, side, err);
        }
        set_sign(W, p, 0);
        if (status == WC_OK)
            status = cross_ray(W, p, j, err);
    }
    return status;
}

int
_wc_arrangement_walk(const _wc_arrangement_t A, _wc_face_fn visit,
                     void * data, wc_error_t err)
{
    slong m = A->m, nl = A->lines->count, p, i;
    walker W;
    int status = WC_OK;

    W.A = A;
    W.visit = visit;
    W.data = data;
    W.sign = flint_malloc(m + 1);
    W.changed = flint_malloc(sizeof(slong) * (m + 1));
    W.dirty = flint_calloc(m + 1, 1);
    W.done = flint_calloc(2 * nl + 1, 1);
    W.ang = flint_malloc(sizeof(angle_ref) * (m + 1));
    for (i = 0; i < m; i++)
    {
        fmpz_init(W.ang[i].x);
        fmpz_init(W.ang[i].y);
    }
    W.u = _fmpz_vec_init(3);
    W.w = _fmpz_vec_init(3);
    W.mid = _fmpz_vec_init(3);
    W.next = _fmpz_vec_init(3);
    W.ray = _fmpz_vec_init(3);
    fmpz_init(W.t);
    W.F.sign = W.sign;
    W.F.changed = W.changed;
    W.F.nchanged = 0;

    /* The origin, every plane changed (from no sign at all).  */
    memset(W.sign, 2, m + 1);
    for (p = 0; p < m; p++)
        set_sign(&W, p, 0);
    _fmpz_vec_zero(W.ray, 3);
    status = report(&W, 0, W.ray, -1, 0, err);

    for (p = 0; p < m && status == WC_OK; p++)
    {
        _wc_tick("arrangement planes", p, m);
        if (_wc_arrangement_nlines_on(A, p) == 0)
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: arrangement: plane %ld "
                                  "holds no line", (long) p);
        else
            status = walk_plane(&W, p, err);
    }
    _wc_tick("arrangement planes", m, m);

    for (i = 0; i < m; i++)
    {
        fmpz_clear(W.ang[i].x);
        fmpz_clear(W.ang[i].y);
    }
    flint_free(W.ang);
    flint_free(W.sign);
    flint_free(W.changed);
    flint_free(W.dirty);
    flint_free(W.done);
    _fmpz_vec_clear(W.u, 3);
    _fmpz_vec_clear(W.w, 3);
    _fmpz_vec_clear(W.mid, 3);
    _fmpz_vec_clear(W.next, 3);
    _fmpz_vec_clear(W.ray, 3);
    fmpz_clear(W.t);
    return status;
}
