/* push.c -- pushing regions of a frictionless finger (wrenchcone(1), push regions).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The set of wrenches is a union of cells of the central arrangement of
   the given planes.  Along one polygon edge, or round the disk, the push
   wrench moves on a path on which each plane h . g = 0 is crossed at
   isolated, rational places; between two consecutive crossings the sign
   vector with respect to every plane is constant, hence so is membership.
   So it suffices to ask the membership test at every crossing and at one
   sample strictly between two consecutive crossings, and to glue the
   answers into maximal intervals (arcs).

   Polygon edge k: q(s) = v_k + s e, e = v_{k+1} - v_k, d the inward
   normal (e turned by +90 degrees for a counter-clockwise polygon, -90
   for a clockwise one; not unit, which is harmless because the set is a
   cone).  w(s) = (d, (q(s) - o) x d) is affine in s, so
   h . w(s) = h . w(0) + s (h . w(1) - h . w(0)) changes sign at most
   once, at s = h.w(0) / (h.w(0) - h.w(1)) when h.w(0) and h.w(1) have
   strictly opposite signs (a zero at an end is the end itself).

   Disk: q = c + R u, d = -u, so w(u) = -(u_x, u_y, (c - o) x u), linear
   in u (R cancels).  With r = c - o and (c - o) x u = r_x u_y - r_y u_x,

     h . w(u) = -((h_x - h_t r_y) u_x + (h_y + h_t r_x) u_y) = a . u,
     a = -(h_x - h_t r_y, h_y + h_t r_x),

   so the plane is crossed at the two directions perpendicular to a,
   +-(-a_y, a_x), rational because c, o and h are; a = 0 means the plane
   never separates two directions.  A direction is kept as a primitive
   integer vector; directions are ordered by their angle in [0, 2 pi)
   measured counter-clockwise from (1, 0), compared exactly (half plane,
   then the sign of a cross product).  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "core/error.h"
#include "core/problem.h"
#include "exact/vec3.h"
#include "analysis/push.h"

/* ---------------------------------------------------------------------
   The result type.  */

static void
interval_init(wc_push_interval_struct * I)
{
    I->edge = -1;
    fmpq_init(I->from);
    fmpq_init(I->to);
    fmpz_init(I->dfrom + 0);
    fmpz_init(I->dfrom + 1);
    fmpz_init(I->dto + 0);
    fmpz_init(I->dto + 1);
    I->from_closed = 0;
    I->to_closed = 0;
    I->full = 0;
}

static void
interval_clear(wc_push_interval_struct * I)
{
    fmpq_clear(I->from);
    fmpq_clear(I->to);
    fmpz_clear(I->dfrom + 0);
    fmpz_clear(I->dfrom + 1);
    fmpz_clear(I->dto + 0);
    fmpz_clear(I->dto + 1);
}

void
wc_push_init(wc_push_t R)
{
    R->kind = WC_SHAPE_NONE;
    R->count = 0;
    R->iv = NULL;
}

void
wc_push_clear(wc_push_t R)
{
    slong i;

    for (i = 0; i < R->count; i++)
        interval_clear(R->iv + i);
    flint_free(R->iv);
    R->iv = NULL;
    R->count = 0;
    R->kind = WC_SHAPE_NONE;
}

/* A growing array of intervals (the result being built).  */
typedef struct
{
    slong count, alloc;
    wc_push_interval_struct * iv;
}
ivlist;

static wc_push_interval_struct *
ivlist_add(ivlist * L)
{
    if (L->count == L->alloc)
    {
        L->alloc = L->alloc < 4 ? 4 : 2 * L->alloc;
        L->iv = flint_realloc(L->iv, sizeof(wc_push_interval_struct)
                              * L->alloc);
    }
    interval_init(L->iv + L->count);
    return L->iv + L->count++;
}

static void
ivlist_clear(ivlist * L)
{
    slong i;

    for (i = 0; i < L->count; i++)
        interval_clear(L->iv + i);
    flint_free(L->iv);
    L->iv = NULL;
    L->count = L->alloc = 0;
}

/* Ask the test about g: 1 in, 0 out, -1 failure.  */
static int
ask(wc_member_fn in, void * ctx, const fmpq * g)
{
    int r = in(g, ctx);

    return r < 0 ? -1 : (r > 0);
}

/* ---------------------------------------------------------------------
   Polygons.  */

static int
fmpq_cmp_qsort(const void * a, const void * b)
{
    return fmpq_cmp((const fmpq *) a, (const fmpq *) b);
}

/* v[0..len) initialised; cleared.  */
static void
qv_init(fmpq * v, slong len)
{
    slong j;

    for (j = 0; j < len; j++)
        fmpq_init(v + j);
}

static void
qv_clear(fmpq * v, slong len)
{
    slong j;

    for (j = 0; j < len; j++)
        fmpq_clear(v + j);
}

/* g := w0 + s (w1 - w0), with dw = w1 - w0.  */
static void
affine_point(fmpq * g, const fmpq * w0, const fmpq * dw, const fmpq_t s)
{
    slong j;

    for (j = 0; j < 3; j++)
    {
        fmpq_mul(g + j, dw + j, s);
        fmpq_add(g + j, g + j, w0 + j);
    }
}

/* (x, y) x (u, v) = x v - y u.  */
static void
cross_q(fmpq_t r, const fmpq * a, const fmpq * b)
{
    fmpq_t t;

    fmpq_init(t);
    fmpq_mul(r, a + 0, b + 1);
    fmpq_mul(t, a + 1, b + 0);
    fmpq_sub(r, r, t);
    fmpq_clear(t);
}

/* The push wrench (d, (p - o) x d) at the point p.  */
static void
push_wrench(fmpq * w, const fmpq * p, const fmpq * o, const fmpq * d)
{
    fmpq rel[2];

    fmpq_init(rel + 0);
    fmpq_init(rel + 1);
    fmpq_sub(rel + 0, p + 0, o + 0);
    fmpq_sub(rel + 1, p + 1, o + 1);
    fmpq_set(w + 0, d + 0);
    fmpq_set(w + 1, d + 1);
    cross_q(w + 2, rel, d);
    fmpq_clear(rel + 0);
    fmpq_clear(rel + 1);
}

/* The regions of one edge, appended to L.  v0, v1 are its ends, sigma
   the orientation (+1 counter-clockwise, -1 clockwise).  bp has room for
   nrows + 2 breakpoints (initialised, scratch).  */
static int
polygon_edge(ivlist * L, slong edge, const fmpq * v0, const fmpq * v1,
             int sigma, const fmpq * o, const fmpz_mat_t planes,
             wc_member_fn in, void * ctx, fmpq * bp)
{
    fmpq d[2], w0[3], dw[3], g[3];
    fmpq_t a, b, s;
    slong i, j, nb, natoms, start;
    int * atom = NULL;
    int status = WC_OK;

    qv_init(d, 2);
    qv_init(w0, 3);
    qv_init(dw, 3);
    qv_init(g, 3);
    fmpq_init(a);
    fmpq_init(b);
    fmpq_init(s);

    /* d = e turned by +90 degrees (-90 when clockwise): (-e_y, e_x).  */
    fmpq_sub(d + 0, v0 + 1, v1 + 1);
    fmpq_sub(d + 1, v1 + 0, v0 + 0);
    if (sigma < 0)
    {
        fmpq_neg(d + 0, d + 0);
        fmpq_neg(d + 1, d + 1);
    }
    /* w(0) and w(1) - w(0); only the torque changes along the edge.  */
    push_wrench(w0, v0, o, d);
    push_wrench(dw, v1, o, d);
    for (j = 0; j < 3; j++)
        fmpq_sub(dw + j, dw + j, w0 + j);

    /* Breakpoints: the ends, and every strict sign change of h . w(s)
       between them, at s = h.w(0) / (h.w(0) - h.w(1)).  */
    nb = 0;
    fmpq_zero(bp + nb++);
    fmpq_one(bp + nb++);
    for (i = 0; i < fmpz_mat_nrows(planes); i++)
    {
        const fmpz * h = WC_ROW(planes, i);

        if (_fmpz_vec_is_zero(h, 3))
            continue;
        _wc_zqvec3_dot(a, h, w0);       /* h . w(0) */
        _wc_zqvec3_dot(b, h, dw);       /* h . (w(1) - w(0)) */
        fmpq_add(s, a, b);      /* h . w(1) */
        if (fmpq_sgn(a) * fmpq_sgn(s) < 0)
        {
            fmpq_div(bp + nb, a, b);
            fmpq_neg(bp + nb, bp + nb);
            nb++;
        }
    }
    qsort(bp, nb, sizeof(fmpq), fmpq_cmp_qsort);
    for (i = 1, j = 1; i < nb; i++)
        if (!fmpq_equal(bp + i, bp + j - 1))
            fmpq_swap(bp + j++, bp + i);
    nb = j;

    /* Membership at each breakpoint (even atoms) and at the midpoint of
       each open piece between two of them (odd atoms).  */
    natoms = 2 * nb - 1;
    atom = flint_malloc(sizeof(int) * natoms);
    for (i = 0; i < natoms && status == WC_OK; i++)
    {
        if (i % 2 == 0)
            fmpq_set(s, bp + i / 2);
        else
        {
            fmpq_add(s, bp + i / 2, bp + i / 2 + 1);
            fmpq_div_2exp(s, s, 1);
        }
        affine_point(g, w0, dw, s);
        atom[i] = ask(in, ctx, g);
        if (atom[i] < 0)
            status = WC_EINTERNAL;
    }

    /* Maximal runs of "in" atoms.  A run from atom i to atom j starts at
       breakpoint i / 2 (closed when i is a breakpoint, open when it is
       the piece after it) and ends at breakpoint j / 2 (closed) or
       j / 2 + 1 (open, j a piece).  */
    for (i = 0; i < natoms && status == WC_OK; )
    {
        wc_push_interval_struct * I;

        if (!atom[i])
        {
            i++;
            continue;
        }
        start = i;
        while (i + 1 < natoms && atom[i + 1])
            i++;
        I = ivlist_add(L);
        I->edge = edge;
        fmpq_set(I->from, bp + start / 2);
        I->from_closed = (start % 2 == 0);
        fmpq_set(I->to, bp + i / 2 + (i % 2));
        I->to_closed = (i % 2 == 0);
        i++;
    }

    flint_free(atom);
    qv_clear(d, 2);
    qv_clear(w0, 3);
    qv_clear(dw, 3);
    qv_clear(g, 3);
    fmpq_clear(a);
    fmpq_clear(b);
    fmpq_clear(s);
    return status;
}

static int
polygon_regions(ivlist * L, const wc_problem_t P, const fmpz_mat_t planes,
                wc_member_fn in, void * ctx, wc_error_t err)
{
    const fmpq * v = P->shape_data;
    slong m = P->shape_len / 2, k, nbp = fmpz_mat_nrows(planes) + 2;
    fmpq_t area, t;
    fmpq * bp;
    int sigma, status = WC_OK;

    if (P->shape_len % 2 != 0 || m < 3)
        return wc_error_set(err, WC_EINPUT, P->file, P->shape_line, 0,
                            "a polygon needs at least 3 vertices");
    for (k = 0; k < m; k++)
        if (fmpq_equal(v + 2 * k, v + 2 * ((k + 1) % m))
            && fmpq_equal(v + 2 * k + 1, v + 2 * ((k + 1) % m) + 1))
            return wc_error_set(err, WC_EINPUT, P->file, P->shape_line, 0,
                                "degenerate polygon: edge %ld has length 0",
                                (long) k);

    /* Orientation: the sign of twice the signed area, sum v_k x v_{k+1}.  */
    fmpq_init(area);
    fmpq_init(t);
    for (k = 0; k < m; k++)
    {
        cross_q(t, v + 2 * k, v + 2 * ((k + 1) % m));
        fmpq_add(area, area, t);
    }
    sigma = fmpq_sgn(area);
    fmpq_clear(area);
    fmpq_clear(t);
    if (sigma == 0)
        return wc_error_set(err, WC_EINPUT, P->file, P->shape_line, 0,
                            "degenerate polygon: zero area");

    bp = _fmpq_vec_init(nbp);
    for (k = 0; k < m && status == WC_OK; k++)
        status = polygon_edge(L, k, v + 2 * k, v + 2 * ((k + 1) % m), sigma,
                              P->com, planes, in, ctx, bp);
    _fmpq_vec_clear(bp, nbp);
    if (status != WC_OK)
        wc_error_set(err, status, P->file, 0, 0,
                     "push regions: the membership test failed");
    return status;
}

/* ---------------------------------------------------------------------
   Disks.  Directions are primitive integer vectors (struct dir).  */

typedef struct
{
    fmpz x, y;
}
dir;

/* 0 for angles in [0, pi) (y > 0, or y = 0 and x > 0), 1 for [pi, 2 pi). */
static int
dir_half(const dir * u)
{
    int sy = fmpz_sgn(&u->y);

    return !(sy > 0 || (sy == 0 && fmpz_sgn(&u->x) > 0));
}

/* The sign of u x v.  */
static int
dir_cross_sgn(const dir * u, const dir * v)
{
    fmpz_t a, b;
    int r;

    fmpz_init(a);
    fmpz_init(b);
    fmpz_mul(a, &u->x, &v->y);
    fmpz_mul(b, &u->y, &v->x);
    r = fmpz_cmp(a, b);
    fmpz_clear(a);
    fmpz_clear(b);
    return r < 0 ? -1 : (r > 0);
}

/* Compare the angles of u and v in [0, 2 pi) from (1, 0).  Within one
   half plane the angle difference is below pi, so the cross product
   decides; it is zero only for the same direction (opposite directions
   lie in different halves).  */
static int
dir_cmp(const dir * u, const dir * v)
{
    int hu = dir_half(u), hv = dir_half(v);

    if (hu != hv)
        return hu - hv;
    return -dir_cross_sgn(u, v);
}

static int
dir_cmp_qsort(const void * a, const void * b)
{
    return dir_cmp((const dir *) a, (const dir *) b);
}

/* u := the primitive integer vector of the direction of the nonzero
   rational vector (x, y).  */
static void
dir_set_primitive(dir * u, const fmpq_t x, const fmpq_t y)
{
    fmpz_t l, g;

    fmpz_init(l);
    fmpz_init(g);
    fmpz_lcm(l, fmpq_denref(x), fmpq_denref(y));
    fmpz_divexact(&u->x, l, fmpq_denref(x));
    fmpz_mul(&u->x, &u->x, fmpq_numref(x));
    fmpz_divexact(&u->y, l, fmpq_denref(y));
    fmpz_mul(&u->y, &u->y, fmpq_numref(y));
    fmpz_gcd(g, &u->x, &u->y);
    fmpz_divexact(&u->x, &u->x, g);
    fmpz_divexact(&u->y, &u->y, g);
    fmpz_clear(l);
    fmpz_clear(g);
}

/* g := w(u) = -(u_x, u_y, r x u), for any vector u on the ray.  */
static void
disk_wrench(fmpq * g, const fmpz_t ux, const fmpz_t uy, const fmpq * r)
{
    fmpq_t t;

    fmpq_init(t);
    fmpq_set_fmpz(g + 0, ux);
    fmpq_neg(g + 0, g + 0);
    fmpq_set_fmpz(g + 1, uy);
    fmpq_neg(g + 1, g + 1);
    fmpq_mul_fmpz(g + 2, r + 1, ux);        /* r_y u_x - r_x u_y */
    fmpq_mul_fmpz(t, r + 0, uy);
    fmpq_sub(g + 2, g + 2, t);
    fmpq_clear(t);
}

/* The whole circle: full, from = to = (1, 0), both ends closed.  */
static void
add_full_circle(ivlist * L)
{
    wc_push_interval_struct * I = ivlist_add(L);

    I->full = 1;
    fmpz_one(I->dfrom + 0);
    fmpz_one(I->dto + 0);
    I->from_closed = I->to_closed = 1;
}

/* The breakpoints of the disk's boundary: for each plane, the two
   directions u where h . w(u) changes sign, primitive, sorted by angle,
   without repeats.  bp holds 2 nrows entries; returns how many are set.
   r is the centre minus the centre of mass; a and t are scratch.  */
static slong
disk_breakpoints(dir * bp, const fmpz_mat_t planes, const fmpq * r,
                 fmpq * a, fmpq_t t)
{
    slong nrows = fmpz_mat_nrows(planes), i, j, nb;

    /* Breakpoints: for each plane, a = -(h_x - h_t r_y, h_y + h_t r_x);
       h . w(u) = a . u vanishes at +-(-a_y, a_x).  */
    nb = 0;
    for (i = 0; i < nrows; i++)
    {
        const fmpz * h = WC_ROW(planes, i);

        fmpq_mul_fmpz(t, r + 1, h + 2);
        fmpq_sub_fmpz(a + 0, t, h + 0);         /* h_t r_y - h_x */
        fmpq_mul_fmpz(t, r + 0, h + 2);
        fmpq_add_fmpz(t, t, h + 1);
        fmpq_neg(a + 1, t);                     /* -(h_y + h_t r_x) */
        if (fmpq_is_zero(a + 0) && fmpq_is_zero(a + 1))
            continue;
        fmpq_neg(t, a + 1);
        dir_set_primitive(bp + nb, t, a + 0);   /* (-a_y, a_x) */
        fmpz_neg(&bp[nb + 1].x, &bp[nb].x);
        fmpz_neg(&bp[nb + 1].y, &bp[nb].y);
        nb += 2;
    }
    qsort(bp, nb, sizeof(dir), dir_cmp_qsort);
    if (nb > 0)
    {
        for (i = 1, j = 1; i < nb; i++)
            if (!fmpz_equal(&bp[i].x, &bp[j - 1].x)
                || !fmpz_equal(&bp[i].y, &bp[j - 1].y))
            {
                fmpz_swap(&bp[j].x, &bp[i].x);
                fmpz_swap(&bp[j].y, &bp[i].y);
                j++;
            }
        nb = j;
    }
    return nb;
}

/* atom[i] for the 2 nb atoms round the circle (see disk_regions): 1 in,
   0 out; returns WC_EINTERNAL when the membership test fails.  */
static int
disk_atoms(int * atom, const dir * bp, slong nb, const fmpq * r,
           wc_member_fn in, void * ctx)
{
    slong i, natoms = 2 * nb;
    fmpq g[3];
    fmpz_t sx, sy;
    int status = WC_OK;

    for (i = 0; i < 3; i++)
        fmpq_init(g + i);
    fmpz_init(sx);
    fmpz_init(sy);
    for (i = 0; i < natoms && status == WC_OK; i++)
    {
        const dir * u = bp + i / 2, * v = bp + (i / 2 + 1) % nb;

        if (i % 2 == 0)
        {
            fmpz_set(sx, &u->x);
            fmpz_set(sy, &u->y);
        }
        else
        {
            int cr = dir_cross_sgn(u, v);

            if (cr == 0 && nb > 1)
            {
                /* v = -u: the half circle to the left of u.  */
                fmpz_neg(sx, &u->y);
                fmpz_set(sy, &u->x);
            }
            else
            {
                fmpz_add(sx, &u->x, &v->x);
                fmpz_add(sy, &u->y, &v->y);
                if (cr <= 0)
                {
                    fmpz_neg(sx, sx);
                    fmpz_neg(sy, sy);
                }
            }
        }
        disk_wrench(g, sx, sy, r);
        atom[i] = ask(in, ctx, g);
        if (atom[i] < 0)
            status = WC_EINTERNAL;
    }
    for (i = 0; i < 3; i++)
        fmpq_clear(g + i);
    fmpz_clear(sx);
    fmpz_clear(sy);
    return status;
}

/* Append to L the maximal cyclic runs of atoms that are in, walking once
   round from just after atom first_out, which is out.  */
static void
disk_runs(ivlist * L, const int * atom, slong first_out, const dir * bp,
          slong nb)
{
    slong natoms = 2 * nb, i, j;

    /* Maximal cyclic runs, walking once round from just after an "out"
       atom, so that no run is cut at the wrap-around.  A run from atom i
       to atom j starts at breakpoint i / 2 (closed when i is a
       breakpoint, open when it is the arc after it) and ends at
       breakpoint j / 2 (closed) or the one after it (open).  A run of
       every atom but breakpoint k is the circle minus k: from k to k,
       both open, as push.h asks.  */
    for (i = 1; i <= natoms; )
    {
        slong ai = (first_out + i) % natoms, start, end;
        wc_push_interval_struct * I;

        if (!atom[ai])
        {
            i++;
            continue;
        }
        start = ai;
        while (i + 1 <= natoms && atom[(first_out + i + 1) % natoms])
            i++;
        end = (first_out + i) % natoms;
        I = ivlist_add(L);
        I->edge = -1;
        fmpz_set(I->dfrom + 0, &bp[start / 2].x);
        fmpz_set(I->dfrom + 1, &bp[start / 2].y);
        I->from_closed = (start % 2 == 0);
        j = (end % 2 == 0) ? end / 2 : (end / 2 + 1) % nb;
        fmpz_set(I->dto + 0, &bp[j].x);
        fmpz_set(I->dto + 1, &bp[j].y);
        I->to_closed = (end % 2 == 0);
        i++;
    }
}

/* Sort L's intervals by the angle of their from direction.  */
static void
sort_by_from(ivlist * L)
{
    slong i, j;

    /* Sort by the angle of from (the starts are distinct directions: two
       maximal runs cannot both begin at one breakpoint).  Insertion sort
       on swaps of whole structs; the counts are small.  */
    for (i = 1; i < L->count; i++)
        for (j = i; j > 0; j--)
        {
            dir u, v;
            wc_push_interval_struct tmp;

            u.x = L->iv[j - 1].dfrom[0];
            u.y = L->iv[j - 1].dfrom[1];
            v.x = L->iv[j].dfrom[0];
            v.y = L->iv[j].dfrom[1];
            if (dir_cmp(&u, &v) <= 0)
                break;
            tmp = L->iv[j - 1];
            L->iv[j - 1] = L->iv[j];
            L->iv[j] = tmp;
        }
}

static int
disk_regions(ivlist * L, const wc_problem_t P, const fmpz_mat_t planes,
             wc_member_fn in, void * ctx, wc_error_t err)
{
    const fmpq * c = P->shape_data;
    slong nrows = fmpz_mat_nrows(planes), i, nb, natoms, first_out;
    fmpq r[2], a[2], g[3];
    fmpq_t t;
    fmpz_t sx, sy;
    dir * bp;
    int * atom = NULL;
    int status = WC_OK;

    if (P->shape_len != 3)
        return wc_error_set(err, WC_EINPUT, P->file, P->shape_line, 0,
                            "a disk needs 3 numbers: CX CY R");
    if (fmpq_sgn(c + 2) <= 0)
        return wc_error_set(err, WC_EINPUT, P->file, P->shape_line, 0,
                            "disk radius must be positive");

    qv_init(r, 2);
    qv_init(a, 2);
    qv_init(g, 3);
    fmpq_init(t);
    fmpz_init(sx);
    fmpz_init(sy);
    bp = flint_malloc(sizeof(dir) * (2 * nrows + 1));
    for (i = 0; i < 2 * nrows + 1; i++)
    {
        fmpz_init(&bp[i].x);
        fmpz_init(&bp[i].y);
    }

    fmpq_sub(r + 0, c + 0, P->com + 0);
    fmpq_sub(r + 1, c + 1, P->com + 1);

    nb = disk_breakpoints(bp, planes, r, a, t);

    if (nb == 0)
    {
        /* No plane separates two directions: all or nothing.  */
        int isin;

        fmpz_one(sx);
        fmpz_zero(sy);
        disk_wrench(g, sx, sy, r);
        isin = ask(in, ctx, g);
        if (isin < 0)
            status = WC_EINTERNAL;
        else if (isin)
            add_full_circle(L);
        goto cleanup;
    }

    /* Atoms round the circle: 2 i is breakpoint i, 2 i + 1 the open arc
       from breakpoint i counter-clockwise to breakpoint i + 1 (mod nb).
       A direction strictly inside that arc: if its angle is below pi,
       the sum of its ends; if exactly pi, the first end turned by +90
       degrees; if above pi (or 2 pi: one breakpoint), minus the sum of
       the ends, which bisects the arc's complement and so points into
       the arc's middle.  */
    natoms = 2 * nb;
    atom = flint_malloc(sizeof(int) * natoms);
    status = disk_atoms(atom, bp, nb, r, in, ctx);
    if (status != WC_OK)
        goto cleanup;

    for (first_out = 0; first_out < natoms && atom[first_out]; first_out++)
        ;
    if (first_out == natoms)
    {
        /* Every atom in: the whole circle.  */
        add_full_circle(L);
        goto cleanup;
    }

    /* Maximal cyclic runs, walking once round from just after an "out"
       atom, so that no run is cut at the wrap-around.  A run from atom i
       to atom j starts at breakpoint i / 2 (closed when i is a
       breakpoint, open when it is the arc after it) and ends at
       breakpoint j / 2 (closed) or the one after it (open).  A run of
       every atom but breakpoint k is the circle minus k: from k to k,
       both open, as push.h asks.  */
    disk_runs(L, atom, first_out, bp, nb);
    sort_by_from(L);

cleanup:
    flint_free(atom);
    for (i = 0; i < 2 * nrows + 1; i++)
    {
        fmpz_clear(&bp[i].x);
        fmpz_clear(&bp[i].y);
    }
    flint_free(bp);
    qv_clear(r, 2);
    qv_clear(a, 2);
    qv_clear(g, 3);
    fmpq_clear(t);
    fmpz_clear(sx);
    fmpz_clear(sy);
    if (status != WC_OK)
        wc_error_set(err, status, P->file, 0, 0,
                     "push regions: the membership test failed");
    return status;
}

/* ---------------------------------------------------------------------
   Entry point.  R's old contents are dropped first; on failure R is left
   empty (count 0, kind WC_SHAPE_NONE).  Only the shape is checked here
   (not wc_problem_check: pushing regions need no fixels).  */

int
wc_push_regions(wc_push_t R, const wc_problem_t P,
                const fmpz_mat_t planes, wc_member_fn in, void * ctx,
                wc_error_t err)
{
    ivlist L;
    int status;

    wc_push_clear(R);
    if (P->shape != WC_SHAPE_POLYGON && P->shape != WC_SHAPE_DISK)
        return wc_error_set(err, WC_EINPUT, P->file, 0, 0,
                            "push regions need a shape (disk or polygon)");
    if (P->shape_data == NULL)
        return wc_error_set(err, WC_EINPUT, P->file, P->shape_line, 0,
                            "the shape has no data");
    if (fmpz_mat_nrows(planes) > 0 && fmpz_mat_ncols(planes) != 3)
        return wc_error_set(err, WC_EINPUT, P->file, 0, 0,
                            "push regions: planes must have 3 columns");
    if (in == NULL)
        return wc_error_set(err, WC_EINPUT, P->file, 0, 0,
                            "push regions: no membership test");

    L.count = L.alloc = 0;
    L.iv = NULL;
    if (P->shape == WC_SHAPE_POLYGON)
        status = polygon_regions(&L, P, planes, in, ctx, err);
    else
        status = disk_regions(&L, P, planes, in, ctx, err);
    if (status != WC_OK)
    {
        ivlist_clear(&L);
        return status;
    }
    R->kind = P->shape;
    R->count = L.count;
    R->iv = L.iv;
    return WC_OK;
}
