/* t-push.c -- pushing regions of a frictionless finger (push.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Hand cases with known exact answers (a unit square and a triangle with
   torque and ray oracles, disks with half-plane, ray, full and empty
   oracles), then random polygons (convex and not, both orientations) and
   disks (centre of mass off the centre) with random oracles: unions of
   intersections of sign conditions on 1-4 planes, sometimes complemented,
   sometimes a single ray.  The reported regions are checked for form
   (sorted, disjoint, maximal, exact single points and full circles) and
   against the oracle applied to the push wrench computed from its
   definition, at every crossing, at every reported end, at rationals
   just beside them and at random places.  Membership in the reported
   regions is decided here independently (relative angles from an arc's
   start, not the library's absolute order).  The push wrench (wrench_at,
   cross2) and primitive3 are deliberate independent copies of push.c's
   push_wrench and compare.c's primitive; the plain vector operations
   come from the library (vec3.h, randgen.h).  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "wrenchcone.h"
#include "core/randgen.h"
#include "exact/vec3.h"
#include "testutil.h"

#define ROW(A, i) ((A)->rows[i])

/* ---------------------------------------------------------------------
   Oracles: the complement (when negate) of a union of terms, each the
   intersection of sign conditions sign(h_p . g) in mask (bit 0: -,
   bit 1: 0, bit 2: +).  Every such set is a union of cells of the
   arrangement of its planes.  */

#define MAXTERM 4
#define MAXLIT 4
#define M_NEG 1
#define M_ZERO 2
#define M_POS 4

typedef struct
{
    fmpz_mat_struct * H;        /* the oracle's planes */
    slong nterms;
    slong nlit[MAXTERM];
    slong pl[MAXTERM][MAXLIT];
    int mask[MAXTERM][MAXLIT];
    int negate;
    slong fail_after;           /* fail on call fail_after + 1; -1 never */
    slong calls;
}
oracle;

static void
oracle_init(oracle * O, fmpz_mat_struct * H)
{
    O->H = H;
    O->nterms = 0;
    O->negate = 0;
    O->fail_after = -1;
    O->calls = 0;
}

/* One term of one literal.  */
static void
oracle_add1(oracle * O, slong p, int mask)
{
    O->nlit[O->nterms] = 1;
    O->pl[O->nterms][0] = p;
    O->mask[O->nterms][0] = mask;
    O->nterms++;
}

static int
oracle_eval(const oracle * O, const fmpq * g)
{
    slong t, l;
    int any = 0;

    for (t = 0; t < O->nterms && !any; t++)
    {
        int all = 1;

        for (l = 0; l < O->nlit[t] && all; l++)
        {
            int s = wctest_dot3_sgn_z(ROW(O->H, O->pl[t][l]), g);

            all = (O->mask[t][l] >> (s + 1)) & 1;
        }
        any = all;
    }
    return any ^ O->negate;
}

static int
oracle_fn(const fmpq * g, void * ctx)
{
    oracle * O = ctx;

    if (O->fail_after >= 0 && O->calls >= O->fail_after)
        return -1;
    O->calls++;
    return oracle_eval(O, g);
}

static void
print_mat(FILE * f, const fmpz_mat_t A)
{
    slong i;

    for (i = 0; i < fmpz_mat_nrows(A); i++)
    {
        fprintf(f, "  plane %ld: (", (long) i);
        fmpz_fprint(f, fmpz_mat_entry(A, i, 0));
        fprintf(f, ", ");
        fmpz_fprint(f, fmpz_mat_entry(A, i, 1));
        fprintf(f, ", ");
        fmpz_fprint(f, fmpz_mat_entry(A, i, 2));
        fprintf(f, ")\n");
    }
}

static void
print_oracle(FILE * f, const oracle * O)
{
    slong t, l;

    fprintf(f, "oracle: %s", O->negate ? "not (" : "(");
    if (O->nterms == 0)
        fprintf(f, "false");
    for (t = 0; t < O->nterms; t++)
    {
        fprintf(f, "%s[", t ? " or " : "");
        for (l = 0; l < O->nlit[t]; l++)
            fprintf(f, "%ssign(h%ld.g) in {%s%s%s}", l ? " and " : "",
                    (long) O->pl[t][l], (O->mask[t][l] & M_NEG) ? "-" : "",
                    (O->mask[t][l] & M_ZERO) ? "0" : "",
                    (O->mask[t][l] & M_POS) ? "+" : "");
        fprintf(f, "]");
    }
    fprintf(f, ")\n");
    print_mat(f, O->H);
}

static void
print_push(FILE * f, const wc_push_t R)
{
    slong i;

    fprintf(f, "regions (%ld):\n", (long) R->count);
    for (i = 0; i < R->count; i++)
    {
        const wc_push_interval_struct * I = R->iv + i;

        fprintf(f, "  edge %ld %c", (long) I->edge, I->from_closed ? '[' : '(');
        if (R->kind == WC_SHAPE_POLYGON)
        {
            fmpq_fprint(f, I->from);
            fprintf(f, ", ");
            fmpq_fprint(f, I->to);
        }
        else
        {
            fprintf(f, "(");
            fmpz_fprint(f, I->dfrom + 0);
            fprintf(f, ", ");
            fmpz_fprint(f, I->dfrom + 1);
            fprintf(f, "), (");
            fmpz_fprint(f, I->dto + 0);
            fprintf(f, ", ");
            fmpz_fprint(f, I->dto + 1);
            fprintf(f, ")");
        }
        fprintf(f, "%c%s\n", I->to_closed ? ']' : ')',
                I->full ? " full" : "");
    }
}

/* Everything about a failing case, then the failure.  */
static const oracle * cur_oracle;
static const wc_push_struct * cur_push;
static const wc_problem_struct * cur_problem;

#define FAIL(...)                                                       \
    do {                                                                \
        fflush(stdout);                                                 \
        if (cur_oracle != NULL)                                         \
            print_oracle(stderr, cur_oracle);                           \
        if (cur_push != NULL)                                           \
            print_push(stderr, cur_push);                               \
        if (cur_problem != NULL)                                        \
            wctest_fail_problem(cur_problem, NULL, __VA_ARGS__);        \
        wctest_fail(__VA_ARGS__);                                       \
    } while (0)

/* ---------------------------------------------------------------------
   Shapes.  */

static void
set_shape(wc_problem_t P, wc_shape_kind kind, const fmpq * v, slong len)
{
    slong i;

    for (i = 0; i < P->shape_len; i++)
        fmpq_clear(P->shape_data + i);
    free(P->shape_data);
    P->shape = kind;
    P->shape_len = len;
    P->shape_data = malloc(sizeof(fmpq) * len);
    for (i = 0; i < len; i++)
    {
        fmpq_init(P->shape_data + i);
        fmpq_set(P->shape_data + i, v + i);
    }
}

/* Shapes from small integer data: vertices (num / den each).  */
static void
set_shape_si(wc_problem_t P, wc_shape_kind kind, const slong * num,
             slong den, slong len)
{
    fmpq * v = _fmpq_vec_init(len);
    slong i;

    for (i = 0; i < len; i++)
        fmpq_set_si(v + i, num[i], den);
    set_shape(P, kind, v, len);
    _fmpq_vec_clear(v, len);
}

static void
set_com_si(wc_problem_t P, slong xn, slong xd, slong yn, slong yd)
{
    fmpq_set_si(P->com + 0, xn, xd);
    fmpq_set_si(P->com + 1, yn, yd);
}

static void
set_planes_si(fmpz_mat_t H, const slong * rows, slong m)
{
    slong i, j;

    fmpz_mat_clear(H);
    fmpz_mat_init(H, m, 3);
    for (i = 0; i < m; i++)
        for (j = 0; j < 3; j++)
            fmpz_set_si(fmpz_mat_entry(H, i, j), rows[3 * i + j]);
}

/* ---------------------------------------------------------------------
   The push wrench, from its definition (d, (q - o) x d).  */

static void
cross2(fmpq_t r, const fmpq * a, const fmpq * b)
{
    fmpq_t t;

    fmpq_init(t);
    fmpq_mul(r, a + 0, b + 1);
    fmpq_mul(t, a + 1, b + 0);
    fmpq_sub(r, r, t);
    fmpq_clear(t);
}

static void
wrench_at(fmpq * w, const fmpq * q, const fmpq * d, const fmpq * o)
{
    fmpq rel[2];

    fmpq_init(rel + 0);
    fmpq_init(rel + 1);
    fmpq_sub(rel + 0, q + 0, o + 0);
    fmpq_sub(rel + 1, q + 1, o + 1);
    fmpq_set(w + 0, d + 0);
    fmpq_set(w + 1, d + 1);
    cross2(w + 2, rel, d);
    fmpq_clear(rel + 0);
    fmpq_clear(rel + 1);
}

/* Polygon edge k at parameter s; ccw is the orientation the test knows
   from how it built the polygon.  */
static void
poly_wrench(fmpq * w, const wc_problem_t P, int ccw, slong k, const fmpq_t s)
{
    slong m = P->shape_len / 2;
    const fmpq * a = P->shape_data + 2 * k;
    const fmpq * b = P->shape_data + 2 * ((k + 1) % m);
    fmpq e[2], d[2], q[2];
    slong j;

    for (j = 0; j < 2; j++)
    {
        fmpq_init(e + j);
        fmpq_init(d + j);
        fmpq_init(q + j);
        fmpq_sub(e + j, b + j, a + j);
        fmpq_mul(q + j, e + j, s);
        fmpq_add(q + j, q + j, a + j);
    }
    if (ccw)
    {
        fmpq_neg(d + 0, e + 1);     /* e turned by +90 degrees */
        fmpq_set(d + 1, e + 0);
    }
    else
    {
        fmpq_set(d + 0, e + 1);     /* e turned by -90 degrees */
        fmpq_neg(d + 1, e + 0);
    }
    wrench_at(w, q, d, P->com);
    for (j = 0; j < 2; j++)
    {
        fmpq_clear(e + j);
        fmpq_clear(d + j);
        fmpq_clear(q + j);
    }
}

/* Disk, direction u (any nonzero rational vector): pushing at
   c + R u along -u (a positive multiple of the push wrench at the unit
   direction, the radius part cancelling).  */
static void
disk_wrench(fmpq * w, const wc_problem_t P, const fmpq * u)
{
    const fmpq * c = P->shape_data;
    fmpq q[2], d[2];
    slong j;

    for (j = 0; j < 2; j++)
    {
        fmpq_init(q + j);
        fmpq_init(d + j);
        fmpq_mul(q + j, c + 2, u + j);
        fmpq_add(q + j, q + j, c + j);
        fmpq_neg(d + j, u + j);
    }
    wrench_at(w, q, d, P->com);
    for (j = 0; j < 2; j++)
    {
        fmpq_clear(q + j);
        fmpq_clear(d + j);
    }
}

/* ---------------------------------------------------------------------
   Membership in the reported regions, decided independently.  */

static int
in_interval(const wc_push_interval_struct * I, const fmpq_t s)
{
    int a = fmpq_cmp(s, I->from), b = fmpq_cmp(s, I->to);

    return (a > 0 || (a == 0 && I->from_closed))
        && (b < 0 || (b == 0 && I->to_closed));
}

static int
in_polygon_regions(const wc_push_t R, slong edge, const fmpq_t s)
{
    slong i, n = 0;

    for (i = 0; i < R->count; i++)
        if (R->iv[i].edge == edge && in_interval(R->iv + i, s))
            n++;
    if (n > 1)
        FAIL("parameter in %ld intervals of edge %ld", (long) n, (long) edge);
    return n == 1;
}

static int
sgn_cross(const fmpq * a, const fmpq * b)
{
    fmpq_t r;
    int s;

    fmpq_init(r);
    cross2(r, a, b);
    s = fmpq_sgn(r);
    fmpq_clear(r);
    return s;
}

static int
same_dir(const fmpq * a, const fmpq * b)
{
    return sgn_cross(a, b) == 0 && _wc_qvec2_dot_sgn(a, b) > 0;
}

/* 0 when x is within the half turn [0, pi) counter-clockwise from f
   (x != f assumed: (0, pi)), 1 for [pi, 2 pi).  */
static int
rel_half(const fmpq * f, const fmpq * x)
{
    return sgn_cross(f, x) > 0 ? 0 : 1;
}

/* Is u strictly before t going counter-clockwise from f (u, t not in
   the direction of f, not the same direction)?  */
static int
rel_before(const fmpq * f, const fmpq * u, const fmpq * t)
{
    int hu = rel_half(f, u), ht = rel_half(f, t);

    if (hu != ht)
        return hu < ht;
    return sgn_cross(u, t) > 0;
}

static void
arc_ends(fmpq * f, fmpq * t, const wc_push_interval_struct * I)
{
    fmpq_set_fmpz(f + 0, I->dfrom + 0);
    fmpq_set_fmpz(f + 1, I->dfrom + 1);
    fmpq_set_fmpz(t + 0, I->dto + 0);
    fmpq_set_fmpz(t + 1, I->dto + 1);
}

static int
in_arc(const wc_push_interval_struct * I, const fmpq * u)
{
    fmpq f[2], t[2];
    int r;

    if (I->full)
        return 1;
    fmpq_init(f + 0);
    fmpq_init(f + 1);
    fmpq_init(t + 0);
    fmpq_init(t + 1);
    arc_ends(f, t, I);
    if (same_dir(f, t))
    {
        /* a single direction (both closed) or all but one (both open) */
        r = same_dir(f, u) ? I->from_closed : !I->from_closed;
    }
    else if (same_dir(f, u))
        r = I->from_closed;
    else if (same_dir(t, u))
        r = I->to_closed;
    else
        r = rel_before(f, u, t);
    fmpq_clear(f + 0);
    fmpq_clear(f + 1);
    fmpq_clear(t + 0);
    fmpq_clear(t + 1);
    return r;
}

static int
in_disk_regions(const wc_push_t R, const fmpq * u)
{
    slong i, n = 0;

    for (i = 0; i < R->count; i++)
        if (in_arc(R->iv + i, u))
            n++;
    if (n > 1)
    {
        char * s = wctest_vec_str(u, 2);

        FAIL("direction %s in %ld arcs", s, (long) n);
    }
    return n == 1;
}

/* ---------------------------------------------------------------------
   The form of a result.  */

static void
check_form_polygon(const wc_push_t R, slong m)
{
    slong i;

    if (R->kind != WC_SHAPE_POLYGON)
        FAIL("polygon result has kind %d", (int) R->kind);
    for (i = 0; i < R->count; i++)
    {
        const wc_push_interval_struct * I = R->iv + i;
        const fmpq * from = I->from, * to = I->to;

        if (I->edge < 0 || I->edge >= m)
            FAIL("interval %ld: edge %ld out of range", (long) i,
                 (long) I->edge);
        if (I->full || !fmpz_is_zero(I->dfrom + 0)
            || !fmpz_is_zero(I->dfrom + 1) || !fmpz_is_zero(I->dto + 0)
            || !fmpz_is_zero(I->dto + 1))
            FAIL("interval %ld: disk fields set on a polygon", (long) i);
        if (fmpq_sgn(from) < 0 || fmpq_cmp(from, to) > 0
            || fmpq_cmp_si(to, 1) > 0)
            FAIL("interval %ld: not 0 <= from <= to <= 1", (long) i);
        if (fmpq_equal(I->from, I->to) && !(I->from_closed && I->to_closed))
            FAIL("interval %ld: a point not closed at both ends", (long) i);
        if ((I->from_closed != 0 && I->from_closed != 1)
            || (I->to_closed != 0 && I->to_closed != 1))
            FAIL("interval %ld: flags not 0 or 1", (long) i);
        if (i > 0)
        {
            const wc_push_interval_struct * J = R->iv + i - 1;
            const fmpq * jto = J->to;
            int c;

            if (J->edge > I->edge)
                FAIL("intervals %ld, %ld: edges not sorted", (long) i - 1,
                     (long) i);
            if (J->edge < I->edge)
                continue;
            /* same edge: J ends before I starts, or they meet at a point
               that neither contains (otherwise they would overlap, or
               their union would be one interval) */
            c = fmpq_cmp(jto, from);
            if (c > 0 || (c == 0 && (J->to_closed || I->from_closed)))
                FAIL("intervals %ld, %ld: overlapping, unsorted or not "
                     "maximal", (long) i - 1, (long) i);
        }
    }
}

static void
check_form_disk(const wc_push_t R)
{
    slong i, n = R->count;
    fmpq f[2], t[2], g[2], h[2];

    if (R->kind != WC_SHAPE_DISK)
        FAIL("disk result has kind %d", (int) R->kind);
    for (i = 0; i < 2; i++)
    {
        fmpq_init(f + i);
        fmpq_init(t + i);
        fmpq_init(g + i);
        fmpq_init(h + i);
    }
    for (i = 0; i < n; i++)
    {
        const wc_push_interval_struct * I = R->iv + i;
        fmpz_t c;

        if (I->edge != -1)
            FAIL("arc %ld: edge %ld, not -1", (long) i, (long) I->edge);
        if (!fmpq_is_zero(I->from) || !fmpq_is_zero(I->to))
            FAIL("arc %ld: polygon parameters set on a disk", (long) i);
        fmpz_init(c);
        fmpz_gcd(c, I->dfrom + 0, I->dfrom + 1);
        if (!fmpz_is_one(c))
            FAIL("arc %ld: from not a primitive nonzero vector", (long) i);
        fmpz_gcd(c, I->dto + 0, I->dto + 1);
        if (!fmpz_is_one(c))
            FAIL("arc %ld: to not a primitive nonzero vector", (long) i);
        fmpz_clear(c);
        if (I->full)
        {
            if (n != 1 || !fmpz_is_one(I->dfrom + 0)
                || !fmpz_is_zero(I->dfrom + 1) || !fmpz_is_one(I->dto + 0)
                || !fmpz_is_zero(I->dto + 1) || !I->from_closed
                || !I->to_closed || I->full != 1)
                FAIL("arc %ld: bad full circle", (long) i);
            continue;
        }
        arc_ends(f, t, I);
        if (same_dir(f, t))
        {
            if (I->from_closed != I->to_closed)
                FAIL("arc %ld: from = to with one end open", (long) i);
            if (!I->from_closed && n != 1)
                FAIL("arc %ld: circle minus a point among other arcs",
                     (long) i);
        }
        if ((I->from_closed != 0 && I->from_closed != 1)
            || (I->to_closed != 0 && I->to_closed != 1))
            FAIL("arc %ld: flags not 0 or 1", (long) i);
    }
    /* Sorted by the angle of from in [0, 2 pi), strictly: half plane
       (y > 0 or y = 0 < x first), then the cross product.  */
    for (i = 1; i < n; i++)
    {
        int ha, hb;

        arc_ends(f, t, R->iv + i - 1);
        arc_ends(g, h, R->iv + i);
        ha = !(fmpq_sgn(f + 1) > 0 || (fmpq_sgn(f + 1) == 0
                                       && fmpq_sgn(f + 0) > 0));
        hb = !(fmpq_sgn(g + 1) > 0 || (fmpq_sgn(g + 1) == 0
                                       && fmpq_sgn(g + 0) > 0));
        if (ha > hb || (ha == hb && sgn_cross(f, g) <= 0))
            FAIL("arcs %ld, %ld: not sorted by the angle of from",
                 (long) i - 1, (long) i);
    }
    /* Disjoint and maximal: going counter-clockwise from arc i's from,
       arc i ends before the next arc (cyclically) starts, or they meet
       at a direction neither contains.  */
    for (i = 0; i < n && n >= 2; i++)
    {
        const wc_push_interval_struct * A = R->iv + i;
        const wc_push_interval_struct * B = R->iv + (i + 1) % n;

        arc_ends(f, t, A);
        arc_ends(g, h, B);
        if (same_dir(f, g))
            FAIL("arcs %ld, %ld: same start", (long) i, (long) (i + 1) % n);
        if (same_dir(t, g))
        {
            if (A->to_closed || B->from_closed)
                FAIL("arcs %ld, %ld: touch with a closed end",
                     (long) i, (long) (i + 1) % n);
        }
        else if (!same_dir(f, t) && !rel_before(f, t, g))
            FAIL("arcs %ld, %ld: overlap", (long) i, (long) (i + 1) % n);
    }
    for (i = 0; i < 2; i++)
    {
        fmpq_clear(f + i);
        fmpq_clear(t + i);
        fmpq_clear(g + i);
        fmpq_clear(h + i);
    }
}

/* ---------------------------------------------------------------------
   Sampling against the oracle.  */

static void
check_param(const wc_problem_t P, int ccw, const oracle * O,
            const wc_push_t R, slong k, const fmpq_t s)
{
    fmpq w[3];
    slong j;
    int want, got;

    if (fmpq_sgn(s) < 0 || fmpq_cmp_si(s, 1) > 0)
        return;
    for (j = 0; j < 3; j++)
        fmpq_init(w + j);
    poly_wrench(w, P, ccw, k, s);
    want = oracle_eval(O, w);
    got = in_polygon_regions(R, k, s);
    if (want != got)
    {
        char * ws = wctest_vec_str(w, 3), * ss = wctest_vec_str(s, 1);

        FAIL("edge %ld, s = %s, wrench %s: oracle says %d, regions %d",
             (long) k, ss, ws, want, got);
    }
    for (j = 0; j < 3; j++)
        fmpq_clear(w + j);
}

/* s, and s +- 1/10^6, s +- 1/10^12.  */
static void
check_param_around(const wc_problem_t P, int ccw, const oracle * O,
                   const wc_push_t R, slong k, const fmpq_t s)
{
    static const slong eps[2] = { 6, 12 };
    fmpq_t e, t;
    slong i;

    fmpq_init(e);
    fmpq_init(t);
    check_param(P, ccw, O, R, k, s);
    for (i = 0; i < 2; i++)
    {
        fmpz_set_ui(fmpq_denref(e), 10);
        fmpz_pow_ui(fmpq_denref(e), fmpq_denref(e), (ulong) eps[i]);
        fmpz_one(fmpq_numref(e));
        fmpq_add(t, s, e);
        check_param(P, ccw, O, R, k, t);
        fmpq_sub(t, s, e);
        check_param(P, ccw, O, R, k, t);
    }
    fmpq_clear(e);
    fmpq_clear(t);
}

static void
verify_polygon(const wc_problem_t P, int ccw, const oracle * O,
               const fmpz_mat_t planes, const wc_push_t R, slong nrand)
{
    slong m = P->shape_len / 2, k, i;
    fmpq w0[3], w1[3];
    fmpq_t s, a, b;

    check_form_polygon(R, m);
    for (i = 0; i < 3; i++)
    {
        fmpq_init(w0 + i);
        fmpq_init(w1 + i);
    }
    fmpq_init(s);
    fmpq_init(a);
    fmpq_init(b);
    for (k = 0; k < m; k++)
    {
        fmpq_zero(s);
        check_param_around(P, ccw, O, R, k, s);
        fmpq_one(s);
        check_param_around(P, ccw, O, R, k, s);
        /* where each plane is crossed: h.w is affine in s */
        poly_wrench(w0, P, ccw, k, s);
        fmpq_zero(s);
        poly_wrench(w1, P, ccw, k, s);
        for (i = 0; i < fmpz_mat_nrows(planes); i++)
        {
            const fmpz * h = ROW(planes, i);
            fmpq_t t;
            slong j;

            fmpq_init(t);
            fmpq_zero(a);
            fmpq_zero(b);
            for (j = 0; j < 3; j++)
            {
                fmpq_mul_fmpz(t, w1 + j, h + j);    /* at s = 0 */
                fmpq_add(a, a, t);
                fmpq_mul_fmpz(t, w0 + j, h + j);    /* at s = 1 */
                fmpq_add(b, b, t);
            }
            fmpq_clear(t);
            if (!fmpq_equal(a, b))
            {
                fmpq_sub(b, a, b);
                fmpq_div(s, a, b);
                check_param_around(P, ccw, O, R, k, s);
            }
        }
        /* the reported ends */
        for (i = 0; i < R->count; i++)
            if (R->iv[i].edge == k)
            {
                check_param_around(P, ccw, O, R, k, R->iv[i].from);
                check_param_around(P, ccw, O, R, k, R->iv[i].to);
            }
        /* random places */
        for (i = 0; i < nrand; i++)
        {
            slong den = wctest_randint(1, 1000);

            fmpq_set_si(s, wctest_randint(0, den), (ulong) den);
            check_param(P, ccw, O, R, k, s);
        }
    }
    for (i = 0; i < 3; i++)
    {
        fmpq_clear(w0 + i);
        fmpq_clear(w1 + i);
    }
    fmpq_clear(s);
    fmpq_clear(a);
    fmpq_clear(b);
}

static void
check_dir(const wc_problem_t P, const oracle * O, const wc_push_t R,
          const fmpq * u)
{
    fmpq w[3];
    slong j;
    int want, got;

    if (fmpq_is_zero(u + 0) && fmpq_is_zero(u + 1))
        return;
    for (j = 0; j < 3; j++)
        fmpq_init(w + j);
    disk_wrench(w, P, u);
    want = oracle_eval(O, w);
    got = in_disk_regions(R, u);
    if (want != got)
    {
        char * ws = wctest_vec_str(w, 3), * us = wctest_vec_str(u, 2);

        FAIL("direction %s, wrench %s: oracle says %d, regions %d", us, ws,
             want, got);
    }
    for (j = 0; j < 3; j++)
        fmpq_clear(w + j);
}

/* u, and u turned slightly either way: u +- (u turned by 90 degrees)
   / 10^6 and / 10^12.  */
static void
check_dir_around(const wc_problem_t P, const oracle * O, const wc_push_t R,
                 const fmpq * u)
{
    static const slong eps[2] = { 6, 12 };
    fmpq v[2];
    fmpq_t e, t;
    slong i;

    fmpq_init(v + 0);
    fmpq_init(v + 1);
    fmpq_init(e);
    fmpq_init(t);
    check_dir(P, O, R, u);
    for (i = 0; i < 2; i++)
    {
        fmpz_set_ui(fmpq_denref(e), 10);
        fmpz_pow_ui(fmpq_denref(e), fmpq_denref(e), (ulong) eps[i]);
        fmpz_one(fmpq_numref(e));
        /* v = u + e (-u_y, u_x) */
        fmpq_mul(t, e, u + 1);
        fmpq_sub(v + 0, u + 0, t);
        fmpq_mul(t, e, u + 0);
        fmpq_add(v + 1, u + 1, t);
        check_dir(P, O, R, v);
        /* v = u - e (-u_y, u_x) */
        fmpq_mul(t, e, u + 1);
        fmpq_add(v + 0, u + 0, t);
        fmpq_mul(t, e, u + 0);
        fmpq_sub(v + 1, u + 1, t);
        check_dir(P, O, R, v);
    }
    fmpq_clear(v + 0);
    fmpq_clear(v + 1);
    fmpq_clear(e);
    fmpq_clear(t);
}

static void
verify_disk(const wc_problem_t P, const oracle * O, const fmpz_mat_t planes,
            const wc_push_t R, slong nrand)
{
    fmpq u[2], a[2], w[3];
    slong i, j;

    check_form_disk(R);
    for (j = 0; j < 2; j++)
    {
        fmpq_init(u + j);
        fmpq_init(a + j);
    }
    for (j = 0; j < 3; j++)
        fmpq_init(w + j);
    /* the axes */
    for (i = 0; i < 4; i++)
    {
        fmpq_set_si(u + 0, i == 0 ? 1 : (i == 2 ? -1 : 0), 1);
        fmpq_set_si(u + 1, i == 1 ? 1 : (i == 3 ? -1 : 0), 1);
        check_dir_around(P, O, R, u);
    }
    /* each plane's crossings: h.w(u) is linear in u, = a . u with
       a = (h.w((1, 0)), h.w((0, 1))); zero at +-(-a_y, a_x) */
    for (i = 0; i < fmpz_mat_nrows(planes); i++)
    {
        const fmpz * h = ROW(planes, i);

        for (j = 0; j < 2; j++)
        {
            fmpq_t t;
            slong l;

            fmpq_set_si(u + 0, j == 0, 1);
            fmpq_set_si(u + 1, j == 1, 1);
            disk_wrench(w, P, u);
            fmpq_init(t);
            fmpq_zero(a + j);
            for (l = 0; l < 3; l++)
            {
                fmpq_mul_fmpz(t, w + l, h + l);
                fmpq_add(a + j, a + j, t);
            }
            fmpq_clear(t);
        }
        if (fmpq_is_zero(a + 0) && fmpq_is_zero(a + 1))
            continue;
        fmpq_neg(u + 0, a + 1);
        fmpq_set(u + 1, a + 0);
        check_dir_around(P, O, R, u);
        fmpq_neg(u + 0, u + 0);
        fmpq_neg(u + 1, u + 1);
        check_dir_around(P, O, R, u);
    }
    /* the reported ends */
    for (i = 0; i < R->count; i++)
    {
        fmpq_set_fmpz(u + 0, R->iv[i].dfrom + 0);
        fmpq_set_fmpz(u + 1, R->iv[i].dfrom + 1);
        check_dir_around(P, O, R, u);
        fmpq_set_fmpz(u + 0, R->iv[i].dto + 0);
        fmpq_set_fmpz(u + 1, R->iv[i].dto + 1);
        check_dir_around(P, O, R, u);
    }
    /* random directions */
    for (i = 0; i < nrand; i++)
    {
        wctest_rand_fmpq(u + 0, 20, 7);
        wctest_rand_fmpq(u + 1, 20, 7);
        check_dir(P, O, R, u);
    }
    for (j = 0; j < 2; j++)
    {
        fmpq_clear(u + j);
        fmpq_clear(a + j);
    }
    for (j = 0; j < 3; j++)
        fmpq_clear(w + j);
}

/* Run the library and check its status.  */
static void
run(wc_push_t R, const wc_problem_t P, const fmpz_mat_t planes, oracle * O)
{
    wc_error_t err;
    int status;

    wc_error_init(err);
    cur_oracle = O;
    cur_push = NULL;
    cur_problem = P;
    status = wc_push_regions(R, P, planes, oracle_fn, O, err);
    if (status != WC_OK)
        FAIL("wc_push_regions returned %d (%s)", status,
             err->message ? err->message : "no message");
    cur_push = R;
    wc_error_clear(err);
}

/* ---------------------------------------------------------------------
   Hand cases.  */

/* Polygon intervals: edge, from (num, den), closed, to (num, den),
   closed.  */
typedef struct
{
    slong edge, fn, fd;
    int fc;
    slong tn, td;
    int tc;
}
pexp;

static void
expect_polygon(const wc_push_t R, const pexp * e, slong n, const char * what)
{
    slong i;

    if (R->count != n)
        FAIL("%s: %ld intervals, expected %ld", what, (long) R->count,
             (long) n);
    for (i = 0; i < n; i++)
    {
        const wc_push_interval_struct * I = R->iv + i;
        fmpq_t f, t;

        fmpq_init(f);
        fmpq_init(t);
        fmpq_set_si(f, e[i].fn, e[i].fd);
        fmpq_set_si(t, e[i].tn, e[i].td);
        if (I->edge != e[i].edge || !fmpq_equal(I->from, f)
            || !fmpq_equal(I->to, t) || I->from_closed != e[i].fc
            || I->to_closed != e[i].tc || I->full)
            FAIL("%s: interval %ld differs from the expected one", what,
                 (long) i);
        fmpq_clear(f);
        fmpq_clear(t);
    }
}

/* Disk arcs: from (x, y), closed, to (x, y), closed, full.  */
typedef struct
{
    slong fx, fy;
    int fc;
    slong tx, ty;
    int tc, full;
}
dexp;

static void
expect_disk(const wc_push_t R, const dexp * e, slong n, const char * what)
{
    slong i;

    if (R->count != n)
        FAIL("%s: %ld arcs, expected %ld", what, (long) R->count, (long) n);
    for (i = 0; i < n; i++)
    {
        const wc_push_interval_struct * I = R->iv + i;

        if (I->edge != -1 || fmpz_cmp_si(I->dfrom + 0, e[i].fx) != 0
            || fmpz_cmp_si(I->dfrom + 1, e[i].fy) != 0
            || fmpz_cmp_si(I->dto + 0, e[i].tx) != 0
            || fmpz_cmp_si(I->dto + 1, e[i].ty) != 0
            || I->from_closed != e[i].fc || I->to_closed != e[i].tc
            || I->full != e[i].full)
            FAIL("%s: arc %ld differs from the expected one", what,
                 (long) i);
    }
}

/* One literal oracle on plane 0 with the given mask (0: empty set, 7:
   everything), checked against expectations and by sampling.  */
/* O, on H, is the ray h_0 . g = 0, h_1 . g = 0, h_2 . g > 0.  */
static void
oracle_ray(oracle * O, fmpz_mat_struct * H)
{
    oracle_init(O, H);
    O->nterms = 1;
    O->nlit[0] = 3;
    O->pl[0][0] = 0;
    O->mask[0][0] = M_ZERO;
    O->pl[0][1] = 1;
    O->mask[0][1] = M_ZERO;
    O->pl[0][2] = 2;
    O->mask[0][2] = M_POS;
}

#define DISK (-1)

/* Push P (a polygon, ccw as verify_polygon takes it, or a disk when ccw
   is DISK) under O, checked against the expected edges pe or arcs de and
   by sampling.  */
static void
hand_check(const wc_problem_t P, int ccw, oracle * O, const fmpz_mat_t H,
           const pexp * pe, const dexp * de, slong n, const char * what)
{
    wc_push_t R;

    wc_push_init(R);
    run(R, P, H, O);
    if (ccw == DISK)
    {
        expect_disk(R, de, n, what);
        verify_disk(P, O, H, R, 50);
    }
    else
    {
        expect_polygon(R, pe, n, what);
        verify_polygon(P, ccw, O, H, R, 10);
    }
    wc_push_clear(R);
    cur_push = NULL;
}

/* One literal oracle on plane 0 with the given mask (0: empty set, 7:
   everything), checked against expectations and by sampling.  */
static void
hand(const wc_problem_t P, int ccw, const fmpz_mat_t H, int mask,
     int negate, const pexp * pe, const dexp * de, slong n, const char * what)
{
    oracle O;

    oracle_init(&O, (fmpz_mat_struct *) H);
    if (mask != 0)
        oracle_add1(&O, 0, mask);
    O.negate = negate;
    hand_check(P, ccw, &O, H, pe, de, n, what);
}

static void
hand_polygon(const wc_problem_t P, int ccw, const fmpz_mat_t H, int mask,
             int negate, const pexp * e, slong n, const char * what)
{
    hand(P, ccw, H, mask, negate, e, NULL, n, what);
}

static void
hand_disk(const wc_problem_t P, const fmpz_mat_t H, int mask, int negate,
          const dexp * e, slong n, const char * what)
{
    hand(P, DISK, H, mask, negate, NULL, e, n, what);
}

static void
test_hand_polygons(void)
{
    static const slong sq[8] = { 0, 0, 1, 0, 1, 1, 0, 1 };
    static const slong sqcw[8] = { 0, 1, 1, 1, 1, 0, 0, 0 };
    static const slong tri[6] = { 0, 0, 3, 0, 0, 3 };
    static const slong torque[3] = { 0, 0, 1 };
    static const slong ray[9] = { 1, 0, 0, 0, 0, 1, 0, 1, 0 };
    wc_problem_t P;
    fmpz_mat_t H;

    wc_problem_init(P);
    fmpz_mat_init(H, 0, 3);

    /* Unit square, com at its centre: on every edge the push wrench is
       (d, s - 1/2) with d the edge's inward unit normal.  */
    set_shape_si(P, WC_SHAPE_POLYGON, sq, 1, 8);
    set_com_si(P, 1, 2, 1, 2);
    set_planes_si(H, torque, 1);
    {
        static const pexp le[4] = {
            { 0, 0, 1, 1, 1, 2, 1 }, { 1, 0, 1, 1, 1, 2, 1 },
            { 2, 0, 1, 1, 1, 2, 1 }, { 3, 0, 1, 1, 1, 2, 1 } };
        static const pexp lt[4] = {
            { 0, 0, 1, 1, 1, 2, 0 }, { 1, 0, 1, 1, 1, 2, 0 },
            { 2, 0, 1, 1, 1, 2, 0 }, { 3, 0, 1, 1, 1, 2, 0 } };
        static const pexp eq[4] = {
            { 0, 1, 2, 1, 1, 2, 1 }, { 1, 1, 2, 1, 1, 2, 1 },
            { 2, 1, 2, 1, 1, 2, 1 }, { 3, 1, 2, 1, 1, 2, 1 } };
        static const pexp gt[4] = {
            { 0, 1, 2, 0, 1, 1, 1 }, { 1, 1, 2, 0, 1, 1, 1 },
            { 2, 1, 2, 0, 1, 1, 1 }, { 3, 1, 2, 0, 1, 1, 1 } };
        static const pexp ne[8] = {
            { 0, 0, 1, 1, 1, 2, 0 }, { 0, 1, 2, 0, 1, 1, 1 },
            { 1, 0, 1, 1, 1, 2, 0 }, { 1, 1, 2, 0, 1, 1, 1 },
            { 2, 0, 1, 1, 1, 2, 0 }, { 2, 1, 2, 0, 1, 1, 1 },
            { 3, 0, 1, 1, 1, 2, 0 }, { 3, 1, 2, 0, 1, 1, 1 } };
        static const pexp all[4] = {
            { 0, 0, 1, 1, 1, 1, 1 }, { 1, 0, 1, 1, 1, 1, 1 },
            { 2, 0, 1, 1, 1, 1, 1 }, { 3, 0, 1, 1, 1, 1, 1 } };

        hand_polygon(P, 1, H, M_NEG | M_ZERO, 0, le, 4, "square, t <= 0");
        hand_polygon(P, 1, H, M_NEG, 0, lt, 4, "square, t < 0");
        hand_polygon(P, 1, H, M_ZERO, 0, eq, 4, "square, t = 0");
        hand_polygon(P, 1, H, M_POS, 0, gt, 4, "square, t > 0");
        hand_polygon(P, 1, H, M_NEG | M_POS, 0, ne, 8, "square, t != 0");
        hand_polygon(P, 1, H, M_NEG | M_ZERO | M_POS, 0, all, 4,
                     "square, everything");
        hand_polygon(P, 1, H, 0, 0, NULL, 0, "square, nothing");
        hand_polygon(P, 1, H, M_ZERO, 1, ne, 8, "square, not t = 0");
    }
    /* The ray (0, 1, 0): only the middle of the bottom edge.  */
    set_planes_si(H, ray, 3);
    {
        static const pexp e[1] = { { 0, 1, 2, 1, 1, 2, 1 } };
        oracle O;

        oracle_ray(&O, H);
        hand_check(P, 1, &O, H, e, NULL, 1, "square, a ray");
    }

    /* The same square clockwise: the torque is now 1/2 - s.  */
    set_shape_si(P, WC_SHAPE_POLYGON, sqcw, 1, 8);
    set_planes_si(H, torque, 1);
    {
        static const pexp le[4] = {
            { 0, 1, 2, 1, 1, 1, 1 }, { 1, 1, 2, 1, 1, 1, 1 },
            { 2, 1, 2, 1, 1, 1, 1 }, { 3, 1, 2, 1, 1, 1, 1 } };

        hand_polygon(P, 0, H, M_NEG | M_ZERO, 0, le, 4,
                     "clockwise square, t <= 0");
    }

    /* Square with com (0, 1/2), the middle of the left edge: torques s,
       s - 1/2, s - 1, s - 1/2 on edges 0..3, so the vertex (0, 0) is in
       edge 0's region for t <= 0 and the vertex (1, 0) in edge 1's
       only.  */
    set_shape_si(P, WC_SHAPE_POLYGON, sq, 1, 8);
    set_com_si(P, 0, 1, 1, 2);
    {
        static const pexp le[4] = {
            { 0, 0, 1, 1, 0, 1, 1 }, { 1, 0, 1, 1, 1, 2, 1 },
            { 2, 0, 1, 1, 1, 1, 1 }, { 3, 0, 1, 1, 1, 2, 1 } };
        static const pexp lt[3] = {
            { 1, 0, 1, 1, 1, 2, 0 }, { 2, 0, 1, 1, 1, 1, 0 },
            { 3, 0, 1, 1, 1, 2, 0 } };
        static const pexp ge[4] = {
            { 0, 0, 1, 1, 1, 1, 1 }, { 1, 1, 2, 1, 1, 1, 1 },
            { 2, 1, 1, 1, 1, 1, 1 }, { 3, 1, 2, 1, 1, 1, 1 } };
        static const pexp gt[3] = {
            { 0, 0, 1, 0, 1, 1, 1 }, { 1, 1, 2, 0, 1, 1, 1 },
            { 3, 1, 2, 0, 1, 1, 1 } };

        hand_polygon(P, 1, H, M_NEG | M_ZERO, 0, le, 4,
                     "square off centre, t <= 0");
        hand_polygon(P, 1, H, M_NEG, 0, lt, 3, "square off centre, t < 0");
        hand_polygon(P, 1, H, M_NEG, 1, ge, 4,
                     "square off centre, not t < 0");
        hand_polygon(P, 1, H, M_POS, 0, gt, 3, "square off centre, t > 0");
    }

    /* Triangle (0,0) (3,0) (0,3), com (1, 0): torques 9s - 3, 18s - 6,
       9s - 9.  */
    set_shape_si(P, WC_SHAPE_POLYGON, tri, 1, 6);
    set_com_si(P, 1, 1, 0, 1);
    {
        static const pexp gt[2] = {
            { 0, 1, 3, 0, 1, 1, 1 }, { 1, 1, 3, 0, 1, 1, 1 } };
        static const pexp ge[3] = {
            { 0, 1, 3, 1, 1, 1, 1 }, { 1, 1, 3, 1, 1, 1, 1 },
            { 2, 1, 1, 1, 1, 1, 1 } };

        hand_polygon(P, 1, H, M_POS, 0, gt, 2, "triangle, t > 0");
        hand_polygon(P, 1, H, M_POS | M_ZERO, 0, ge, 3, "triangle, t >= 0");
    }

    /* Errors: no shape; a failing membership test (R left empty).  */
    {
        wc_problem_t Q;
        wc_error_t err;
        wc_push_t R;
        oracle O;
        int status;

        wc_problem_init(Q);
        wc_error_init(err);
        wc_push_init(R);
        oracle_init(&O, H);
        oracle_add1(&O, 0, M_POS);
        cur_oracle = NULL;
        cur_push = NULL;
        cur_problem = NULL;
        status = wc_push_regions(R, Q, H, oracle_fn, &O, err);
        if (status != WC_EINPUT || err->message == NULL || R->count != 0)
            wctest_fail("no shape: status %d, expected WC_EINPUT", status);
        /* fill R, then fail: R must come back empty */
        status = wc_push_regions(R, P, H, oracle_fn, &O, err);
        if (status != WC_OK || R->count != 2)
            wctest_fail("triangle again: status %d, %ld intervals", status,
                        (long) R->count);
        O.fail_after = 3;
        O.calls = 0;
        status = wc_push_regions(R, P, H, oracle_fn, &O, err);
        if (status != WC_EINTERNAL || R->count != 0 || R->iv != NULL)
            wctest_fail("failing test: status %d, expected WC_EINTERNAL "
                        "and no region", status);
        set_shape_si(Q, WC_SHAPE_DISK, tri, 1, 3);
        O.calls = 0;
        O.fail_after = 0;
        status = wc_push_regions(R, Q, H, oracle_fn, &O, err);
        if (status != WC_EINTERNAL || R->count != 0)
            wctest_fail("failing test on a disk: status %d", status);
        wc_push_clear(R);
        wc_error_clear(err);
        wc_problem_clear(Q);
    }

    fmpz_mat_clear(H);
    wc_problem_clear(P);
    cur_problem = NULL;
    cur_oracle = NULL;
}

static void
test_hand_disks(void)
{
    static const slong unit[3] = { 0, 0, 1 };
    static const slong fx[3] = { 1, 0, 0 };
    static const slong ray[9] = { 0, 1, 0, 0, 0, 1, -1, 0, 0 };
    static const slong torque[3] = { 0, 0, 1 };
    static const slong f24[3] = { 2, 4, 0 };
    static const slong zero[6] = { 0, 0, 0, 0, 0, 1 };
    static const slong off[3] = { 2, 0, 4 };        /* / 2: (1, 0), 2 */
    static const slong rat[3] = { 3, 2, 3 };        /* / 6 */
    wc_problem_t P;
    fmpz_mat_t H;

    wc_problem_init(P);
    fmpz_mat_init(H, 0, 3);

    /* Unit disk, com at the centre: w(u) = -(u, 0); h = (1, 0, 0):
       h.w <= 0 iff u_x >= 0, the closed right half, which crosses
       (1, 0) and is reported once, from (0, -1) to (0, 1).  */
    set_shape_si(P, WC_SHAPE_DISK, unit, 1, 3);
    set_com_si(P, 0, 1, 0, 1);
    set_planes_si(H, fx, 1);
    {
        static const dexp le[1] = { { 0, -1, 1, 0, 1, 1, 0 } };
        static const dexp lt[1] = { { 0, -1, 0, 0, 1, 0, 0 } };
        static const dexp ge[1] = { { 0, 1, 1, 0, -1, 1, 0 } };
        static const dexp eq[2] = { { 0, 1, 1, 0, 1, 1, 0 },
                                    { 0, -1, 1, 0, -1, 1, 0 } };
        static const dexp ne[2] = { { 0, 1, 0, 0, -1, 0, 0 },
                                    { 0, -1, 0, 0, 1, 0, 0 } };
        static const dexp full[1] = { { 1, 0, 1, 1, 0, 1, 1 } };

        hand_disk(P, H, M_NEG | M_ZERO, 0, le, 1, "disk, u_x >= 0");
        hand_disk(P, H, M_NEG, 0, lt, 1, "disk, u_x > 0");
        hand_disk(P, H, M_POS | M_ZERO, 0, ge, 1, "disk, u_x <= 0");
        hand_disk(P, H, M_ZERO, 0, eq, 2, "disk, u_x = 0");
        hand_disk(P, H, M_NEG | M_POS, 0, ne, 2, "disk, u_x != 0");
        hand_disk(P, H, M_ZERO, 1, ne, 2, "disk, not u_x = 0");
        hand_disk(P, H, M_NEG | M_ZERO | M_POS, 0, full, 1, "disk, all");
        hand_disk(P, H, 0, 0, NULL, 0, "disk, nothing");
        hand_disk(P, H, 0, 1, full, 1, "disk, not nothing");
    }
    /* A single ray g ~ (-1, 0, 0): pushing at (-1, 0) along (1, 0), the
       direction (1, 0).  The torque plane never separates directions
       here (a = 0).  Its complement is the circle minus (1, 0).  */
    set_planes_si(H, ray, 3);
    {
        static const dexp one[1] = { { 1, 0, 1, 1, 0, 1, 0 } };
        static const dexp allbut[1] = { { 1, 0, 0, 1, 0, 0, 0 } };
        oracle O;
        int neg;

        for (neg = 0; neg <= 1; neg++)
        {
            oracle_ray(&O, H);
            O.negate = neg;
            hand_check(P, DISK, &O, H, NULL, neg ? allbut : one, 1,
                       neg ? "disk, all but a ray" : "disk, a ray");
        }
    }
    /* No planes, or only zero rows and a plane with a = 0: full or
       empty.  */
    {
        static const dexp full[1] = { { 1, 0, 1, 1, 0, 1, 1 } };

        set_planes_si(H, NULL, 0);
        hand_disk(P, H, 0, 1, full, 1, "disk, no planes, all");
        hand_disk(P, H, 0, 0, NULL, 0, "disk, no planes, nothing");
        set_planes_si(H, zero, 2);
        hand_disk(P, H, M_NEG, 1, full, 1, "disk, zero plane, all");
        hand_disk(P, H, M_NEG, 0, NULL, 0, "disk, zero plane, nothing");
    }
    /* h = (2, 4, 0): h.w <= 0 iff u_x + 2 u_y >= 0, from (2, -1) to
       (-2, 1).  */
    set_planes_si(H, f24, 1);
    {
        static const dexp le[1] = { { 2, -1, 1, -2, 1, 1, 0 } };
        static const dexp gt[1] = { { -2, 1, 0, 2, -1, 0, 0 } };

        hand_disk(P, H, M_NEG | M_ZERO, 0, le, 1, "disk, u_x + 2 u_y >= 0");
        hand_disk(P, H, M_POS, 0, gt, 1, "disk, u_x + 2 u_y < 0");
    }
    /* Centre (1, 0), radius 2, com the origin: w(u) = -(u_x, u_y, u_y),
       torque <= 0 iff u_y >= 0.  */
    set_shape_si(P, WC_SHAPE_DISK, off, 2, 3);
    set_planes_si(H, torque, 1);
    {
        static const dexp le[1] = { { 1, 0, 1, -1, 0, 1, 0 } };

        hand_disk(P, H, M_NEG | M_ZERO, 0, le, 1, "off-centre disk");
    }
    /* Centre (1/2, 1/3): torque <= 0 iff 2 u_x <= 3 u_y, from (3, 2) to
       (-3, -2).  */
    set_shape_si(P, WC_SHAPE_DISK, rat, 6, 3);
    {
        static const dexp le[1] = { { 3, 2, 1, -3, -2, 1, 0 } };
        static const dexp eq[2] = { { 3, 2, 1, 3, 2, 1, 0 },
                                    { -3, -2, 1, -3, -2, 1, 0 } };

        hand_disk(P, H, M_NEG | M_ZERO, 0, le, 1, "rational disk, t <= 0");
        hand_disk(P, H, M_ZERO, 0, eq, 2, "rational disk, t = 0");
    }

    fmpz_mat_clear(H);
    wc_problem_clear(P);
    cur_problem = NULL;
    cur_oracle = NULL;
}

/* ---------------------------------------------------------------------
   Random cases.  */

/* out := a primitive integer vector along the nonzero rational v (3).  */
static void
primitive3(fmpz * out, const fmpq * v)
{
    fmpz_t l, g;
    slong j;

    fmpz_init(l);
    fmpz_init(g);
    fmpz_one(l);
    for (j = 0; j < 3; j++)
        fmpz_lcm(l, l, fmpq_denref(v + j));
    for (j = 0; j < 3; j++)
    {
        fmpz_divexact(out + j, l, fmpq_denref(v + j));
        fmpz_mul(out + j, out + j, fmpq_numref(v + j));
    }
    _fmpz_vec_content(g, out, 3);
    if (!fmpz_is_zero(g))
        _fmpz_vec_scalar_divexact_fmpz(out, out, 3, g);
    fmpz_clear(l);
    fmpz_clear(g);
}

static void
rand_int_vec(fmpz * h, slong range)
{
    slong j;

    do
        for (j = 0; j < 3; j++)
            fmpz_set_si(h + j, wctest_randint(-range, range));
    while (_fmpz_vec_is_zero(h, 3));
}

/* A random push wrench of the shape (its path), for planes through it.  */
static void
rand_shape_wrench(fmpq * w, const wc_problem_t P, int ccw)
{
    if (P->shape == WC_SHAPE_POLYGON)
    {
        slong m = P->shape_len / 2, k = wctest_randint(0, m - 1);
        fmpq_t s;

        fmpq_init(s);
        if (wctest_chance(1, 2))
            fmpq_set_si(s, wctest_randint(0, 1), 1);        /* a vertex */
        else
            fmpq_set_si(s, wctest_randint(0, 6), 6);
        poly_wrench(w, P, ccw, k, s);
        fmpq_clear(s);
    }
    else
    {
        fmpq u[2];

        fmpq_init(u + 0);
        fmpq_init(u + 1);
        do
        {
            wctest_rand_fmpq(u + 0, 4, 3);
            wctest_rand_fmpq(u + 1, 4, 3);
        }
        while (fmpq_is_zero(u + 0) && fmpq_is_zero(u + 1));
        disk_wrench(w, P, u);
        fmpq_clear(u + 0);
        fmpq_clear(u + 1);
    }
}

/* The oracle's planes (rows 0 .. np - 1 of H) and formula.  */
static void
rand_oracle(oracle * O, fmpz_mat_t H, const wc_problem_t P, int ccw)
{
    slong np = wctest_randint(1, 4), i, t, l;
    fmpq w[3], w2[3];
    fmpz a[3], b[3];

    for (i = 0; i < 3; i++)
    {
        fmpq_init(w + i);
        fmpq_init(w2 + i);
        fmpz_init(a + i);
        fmpz_init(b + i);
    }
    fmpz_mat_clear(H);
    fmpz_mat_init(H, np, 3);
    oracle_init(O, H);

    if (wctest_chance(1, 6))
    {
        /* A single ray along a push wrench (a single point of the
           region), or its complement, or its negative.  */
        fmpz_mat_clear(H);
        fmpz_mat_init(H, 3, 3);
        rand_shape_wrench(w, P, ccw);
        primitive3(a, w);
        do
            rand_int_vec(b, 2);
        while (_wc_zvec3_cross(ROW(H, 0), a, b),
               _fmpz_vec_is_zero(ROW(H, 0), 3));
        _wc_zvec3_cross(ROW(H, 1), a, ROW(H, 0));
        _fmpz_vec_set(ROW(H, 2), a, 3);
        O->nterms = 1;
        O->nlit[0] = 3;
        for (l = 0; l < 3; l++)
        {
            O->pl[0][l] = l;
            O->mask[0][l] = M_ZERO;
        }
        O->mask[0][2] = wctest_chance(1, 4) ? M_NEG : M_POS;
        O->negate = wctest_chance(1, 3);
        goto done;
    }

    for (i = 0; i < np; i++)
    {
        fmpz * h = ROW(H, i);
        slong kind = wctest_randint(0, 5);

        if (kind <= 1)
            rand_int_vec(h, 3);
        else if (kind == 2 || kind == 3)
        {
            /* through a push wrench (a vertex, often) */
            rand_shape_wrench(w, P, ccw);
            primitive3(a, w);
            do
            {
                rand_int_vec(b, 2);
                _wc_zvec3_cross(h, a, b);
            }
            while (_fmpz_vec_is_zero(h, 3));
        }
        else if (kind == 4 && P->shape == WC_SHAPE_POLYGON)
        {
            /* containing a whole edge's path: h = w(0) x w(1) */
            slong m = P->shape_len / 2, k = wctest_randint(0, m - 1);
            fmpq_t s;

            fmpq_init(s);
            poly_wrench(w, P, ccw, k, s);
            fmpq_one(s);
            poly_wrench(w2, P, ccw, k, s);
            primitive3(a, w);
            primitive3(b, w2);
            _wc_zvec3_cross(h, a, b);
            fmpq_clear(s);
            if (_fmpz_vec_is_zero(h, 3))
                rand_int_vec(h, 3);
        }
        else if (kind == 4)
        {
            /* a plane no direction of the disk crosses:
               (r_y, -r_x, 1), r = c - o */
            fmpq_sub(w + 1, P->shape_data + 0, P->com + 0);
            fmpq_neg(w + 1, w + 1);
            fmpq_sub(w + 0, P->shape_data + 1, P->com + 1);
            fmpq_one(w + 2);
            primitive3(h, w);
        }
        else
        {
            /* a multiple or the negative of an earlier plane */
            if (i == 0)
                rand_int_vec(h, 3);
            else
                _fmpz_vec_scalar_mul_si(h, ROW(H, wctest_randint(0, i - 1)),
                                        3, wctest_chance(1, 2) ? -1 : 2);
        }
    }
    O->nterms = wctest_randint(0, 3) == 0 ? 1 : wctest_randint(1, 3);
    for (t = 0; t < O->nterms; t++)
    {
        O->nlit[t] = wctest_randint(1, MAXLIT);
        for (l = 0; l < O->nlit[t]; l++)
        {
            O->pl[t][l] = wctest_randint(0, np - 1);
            O->mask[t][l] = (int) wctest_randint(1, 6);
        }
    }
    O->negate = wctest_chance(1, 4);

done:
    for (i = 0; i < 3; i++)
    {
        fmpq_clear(w + i);
        fmpq_clear(w2 + i);
        fmpz_clear(a + i);
        fmpz_clear(b + i);
    }
}

/* The planes given to the library: the oracle's, sometimes with zero
   rows, repeats, negatives and unrelated extra planes, shuffled.  */
static void
rand_planes(fmpz_mat_t Q, const fmpz_mat_t H)
{
    slong n = fmpz_mat_nrows(H), extra = 0, i, j;

    if (wctest_chance(1, 2))
        extra = wctest_randint(1, 3);
    fmpz_mat_clear(Q);
    fmpz_mat_init(Q, n + extra, 3);
    for (i = 0; i < n; i++)
        _fmpz_vec_set(ROW(Q, i), ROW(H, i), 3);
    for (i = n; i < n + extra; i++)
    {
        slong kind = wctest_randint(0, 3);

        if (kind == 0)
            continue;                               /* zero row */
        else if (kind == 1)
            _fmpz_vec_neg(ROW(Q, i), ROW(H, wctest_randint(0, n - 1)), 3);
        else if (kind == 2)
            _fmpz_vec_set(ROW(Q, i), ROW(H, wctest_randint(0, n - 1)), 3);
        else
            rand_int_vec(ROW(Q, i), 3);
    }
    for (i = n + extra - 1; i > 0; i--)
    {
        j = wctest_randint(0, i);
        if (j != i)
            _fmpz_vec_swap(ROW(Q, i), ROW(Q, j), 3);
    }
}

/* A random simple polygon: a star around a centre, vertices at rational
   points t -> ((1 - t^2), 2 t) / (1 + t^2) of the unit circle (in
   angular order by sorted t), scaled by one radius (convex) or each by
   its own (not convex in general); every angular gap below pi, so each
   edge stays in its own sector and the polygon is simple and
   counter-clockwise.  Sometimes a rectangle.  Returns 1 for
   counter-clockwise; clockwise polygons are the reversed lists.  Edge 0
   starts at a random vertex.  */
static int
rand_polygon(wc_problem_t P)
{
    slong m, i, j, start;
    fmpq * v, * tv;
    fmpq c[2], rad;
    int ccw;

    fmpq_init(c + 0);
    fmpq_init(c + 1);
    fmpq_init(&rad);
    wctest_rand_fmpq(c + 0, 3, 2);
    wctest_rand_fmpq(c + 1, 3, 2);
    if (wctest_chance(1, 5))
    {
        fmpq_t wd, ht;

        m = 4;
        v = _fmpq_vec_init(8);
        fmpq_init(wd);
        fmpq_init(ht);
        wctest_rand_fmpq_pos(wd, 3, 2);
        wctest_rand_fmpq_pos(ht, 3, 2);
        for (i = 0; i < 4; i++)
        {
            fmpq_set(v + 2 * i, c + 0);
            fmpq_set(v + 2 * i + 1, c + 1);
        }
        fmpq_add(v + 2, v + 2, wd);
        fmpq_add(v + 4, v + 4, wd);
        fmpq_add(v + 5, v + 5, ht);
        fmpq_add(v + 7, v + 7, ht);
        fmpq_clear(wd);
        fmpq_clear(ht);
    }
    else
    {
        int convex = wctest_chance(1, 2), ok;

        m = wctest_randint(3, 8);
        v = _fmpq_vec_init(2 * m);
        tv = _fmpq_vec_init(m);
        do
        {
            /* distinct sorted t */
            for (i = 0; i < m; i++)
            {
                int dup;

                do
                {
                    fmpq_set_si(tv + i, wctest_randint(-12, 12),
                                (ulong) wctest_randint(1, 4));
                    for (dup = 0, j = 0; j < i; j++)
                        dup |= fmpq_equal(tv + i, tv + j);
                }
                while (dup);
            }
            for (i = 1; i < m; i++)
                for (j = i; j > 0 && fmpq_cmp(tv + j - 1, tv + j) > 0; j--)
                    fmpq_swap(tv + j - 1, tv + j);
            wctest_rand_fmpq_pos(&rad, 3, 2);
            for (i = 0; i < m; i++)
            {
                fmpq_t d, x;

                fmpq_init(d);
                fmpq_init(x);
                if (!convex)
                    wctest_rand_fmpq_pos(&rad, 3, 2);
                fmpq_mul(x, tv + i, tv + i);
                fmpq_add_si(d, x, 1);               /* 1 + t^2 */
                fmpq_sub_si(x, x, 1);
                fmpq_neg(x, x);                     /* 1 - t^2 */
                fmpq_div(v + 2 * i, x, d);
                fmpq_mul_si(x, tv + i, 2);
                fmpq_div(v + 2 * i + 1, x, d);
                for (j = 0; j < 2; j++)
                {
                    fmpq_mul(v + 2 * i + j, v + 2 * i + j, &rad);
                    fmpq_add(v + 2 * i + j, v + 2 * i + j, c + j);
                }
                fmpq_clear(d);
                fmpq_clear(x);
            }
            /* every gap below pi: (p_i - c) x (p_{i+1} - c) > 0 */
            ok = 1;
            for (i = 0; i < m && ok; i++)
            {
                fmpq a[2], b[2];
                fmpq_t cr;

                fmpq_init(cr);
                for (j = 0; j < 2; j++)
                {
                    fmpq_init(a + j);
                    fmpq_init(b + j);
                    fmpq_sub(a + j, v + 2 * i + j, c + j);
                    fmpq_sub(b + j, v + 2 * ((i + 1) % m) + j, c + j);
                }
                cross2(cr, a, b);
                ok = fmpq_sgn(cr) > 0;
                for (j = 0; j < 2; j++)
                {
                    fmpq_clear(a + j);
                    fmpq_clear(b + j);
                }
                fmpq_clear(cr);
            }
        }
        while (!ok);
        _fmpq_vec_clear(tv, m);
    }

    ccw = wctest_chance(1, 2);
    if (!ccw)
        for (i = 0; i < m / 2; i++)
        {
            fmpq_swap(v + 2 * i, v + 2 * (m - 1 - i));
            fmpq_swap(v + 2 * i + 1, v + 2 * (m - 1 - i) + 1);
        }
    start = wctest_randint(0, m - 1);
    {
        fmpq * r = _fmpq_vec_init(2 * m);

        for (i = 0; i < 2 * m; i++)
            fmpq_set(r + i, v + (2 * start + i) % (2 * m));
        set_shape(P, WC_SHAPE_POLYGON, r, 2 * m);
        _fmpq_vec_clear(r, 2 * m);
    }
    _fmpq_vec_clear(v, 2 * m);

    /* com anywhere, sometimes a vertex */
    if (wctest_chance(1, 6))
    {
        i = wctest_randint(0, m - 1);
        fmpq_set(P->com + 0, P->shape_data + 2 * i);
        fmpq_set(P->com + 1, P->shape_data + 2 * i + 1);
    }
    else
    {
        wctest_rand_fmpq(P->com + 0, 4, 3);
        wctest_rand_fmpq(P->com + 1, 4, 3);
    }
    fmpq_clear(c + 0);
    fmpq_clear(c + 1);
    fmpq_clear(&rad);
    return ccw;
}

static void
rand_disk(wc_problem_t P)
{
    fmpq d[3];
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_init(d + j);
    wctest_rand_fmpq(d + 0, 3, 3);
    wctest_rand_fmpq(d + 1, 3, 3);
    wctest_rand_fmpq_pos(d + 2, 5, 2);
    set_shape(P, WC_SHAPE_DISK, d, 3);
    /* com: the centre sometimes, else moved off it */
    fmpq_set(P->com + 0, d + 0);
    fmpq_set(P->com + 1, d + 1);
    if (!wctest_chance(1, 5))
        for (j = 0; j < 2; j++)
        {
            wctest_rand_fmpq(d + 2, 3, 4);
            fmpq_add(P->com + j, P->com + j, d + 2);
        }
    for (j = 0; j < 3; j++)
        fmpq_clear(d + j);
}

static void
test_random(void)
{
    slong iters = wctest_iters(2000), it;
    fmpz_mat_t H, Q;

    fmpz_mat_init(H, 0, 3);
    fmpz_mat_init(Q, 0, 3);
    for (it = 0; it < iters; it++)
    {
        wc_problem_t P;
        wc_push_t R;
        oracle O;
        int ccw = 1, disk;

        if (!wctest_iter(it))
            continue;
        wc_problem_init(P);
        wc_push_init(R);
        disk = wctest_chance(1, 2);
        if (disk)
            rand_disk(P);
        else
            ccw = rand_polygon(P);
        cur_problem = P;
        rand_oracle(&O, H, P, ccw);
        rand_planes(Q, H);
        run(R, P, Q, &O);
        if (disk)
            verify_disk(P, &O, Q, R, 40);
        else
            verify_polygon(P, ccw, &O, Q, R, 4);
        cur_push = NULL;
        cur_oracle = NULL;
        cur_problem = NULL;
        wc_push_clear(R);
        wc_problem_clear(P);
    }
    fmpz_mat_clear(H);
    fmpz_mat_clear(Q);
}

int
main(void)
{
    wctest_init("t-push");
    test_hand_polygons();
    test_hand_disks();
    test_random();
    flint_cleanup_master();
    return 0;
}
