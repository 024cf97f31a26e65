/* t-hull3.c -- the O(k log k) 3-D kernel (fan3.c, polar3.c, cone3.c)
   against an independent brute-force reference (ref-hull3.c), the former
   O(k^2) kernel (old-hull3.c, a regression check) and cddlib.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Seeded random generator sets, k = 0 .. a few hundred, in many layouts:
   general, pointed, repeated and parallel generators, opposite pairs,
   all coplanar, on one plane through the origin, lines, lineality 1 and
   2, the whole R^3, many generators on one facet or one half-plane
   through the axis, pointed cones whose generators make obtuse angles
   with their sum (the fan's angular scan then needs the linear program),
   huge and tiny coordinates.  Both conversions
   (V -> H and H -> V) must give the reference's rows as sets; the whole
   canonical cone (fast path) must equal the one through cddlib and the
   general route, field for field; the fan and the linear program must
   classify the cone as the reference's facets do.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>

#include <flint/fmpz_vec.h>

#include "wrenchcone.h"
#include "testutil.h"
#include "old-hull3.h"
#include "ref-hull3.h"
#include "exact/hull3.h"
#include "exact/vec3.h"
#include "exact/zvec3set.h"
#include "exact/fan3.h"
#include "exact/polar3.h"
#include "exact/cddbridge.h"

/* ref-hull3.c is cubic in the number of rows: beyond this it is skipped
   (the former kernel and cddlib still check those).  */
#define REF_MAXK 80

enum { GENERAL, POINTED, DEGENERATE, COPLANAR, HALFSPACE, WEDGE, SPACE,
       FACETRUN, AXISRUN, OBTUSE, LAYOUTS };

static const char * layout_name[] = { "general", "pointed", "degenerate",
    "coplanar", "half-space", "wedge", "space", "facet-run", "axis-run",
    "obtuse" };

static slong
rnd(slong r)
{
    return wctest_randint(-r, r);
}

/* Row i of A := (x, y, z) / den, times 2^shift (huge) when shift > 0.  */
static void
set_row(fmpq_mat_t A, slong i, const slong * v, slong den, int shift)
{
    slong j;

    for (j = 0; j < 3; j++)
    {
        fmpq * x = fmpq_mat_entry(A, i, j);

        fmpq_set_si(x, v[j], den);
        if (shift > 0)
            fmpz_mul_2exp(fmpq_numref(x), fmpq_numref(x), shift);
    }
}

/* Random generators R (k rows) and lines L in the given layout.  */
static void
make(fmpq_mat_t R, fmpq_mat_t L, int layout, slong k)
{
    slong i, j, r = wctest_chance(1, 3) ? 3 : 1000, nl = 0;
    slong c[3], u[3], w[3], v[3], den = 1;
    int shift = 0;

    if (wctest_chance(1, 8))
        shift = 100;                            /* huge */
    else if (wctest_chance(1, 8))
        den = 1000003;                          /* tiny */
    for (j = 0; j < 3; j++)
    {
        c[j] = rnd(5);
        u[j] = rnd(5);
        w[j] = rnd(5);
    }
    if (c[0] == 0 && c[1] == 0 && c[2] == 0)
        c[2] = 1;
    if (layout == HALFSPACE)
        nl = 2;
    else if (layout == WEDGE)
        nl = 1;
    fmpq_mat_clear(R);
    fmpq_mat_init(R, k, 3);
    fmpq_mat_clear(L);
    fmpq_mat_init(L, wctest_chance(1, 3) ? nl : 0, 3);
    for (i = 0; i < fmpq_mat_nrows(L); i++)
        set_row(L, i, i == 0 ? u : w, den, shift);
    for (i = 0; i < k; i++)
    {
        slong a = rnd(r), b = rnd(r), t = wctest_randint(1, 4);

        for (j = 0; j < 3; j++)
            v[j] = rnd(r);
        switch (layout)
        {
        case POINTED:
        case FACETRUN:
        case AXISRUN:
            /* v . c > 0: flip, or push along c.  */
            if (v[0] * c[0] + v[1] * c[1] + v[2] * c[2] < 0)
                for (j = 0; j < 3; j++)
                    v[j] = -v[j];
            if (v[0] * c[0] + v[1] * c[1] + v[2] * c[2] == 0)
                for (j = 0; j < 3; j++)
                    v[j] += c[j];
            if (layout == FACETRUN && i % 2 == 1)
                for (j = 0; j < 3; j++)         /* on a segment a..b */
                    v[j] = t * c[j] + (a > 0 ? 2 : 1) * u[j];
            if (layout == AXISRUN && i % 2 == 1)
                for (j = 0; j < 3; j++)         /* one half-plane */
                    v[j] = t * c[j] + (a > 0 ? 3 : 1) * u[j];
            break;
        case COPLANAR:
            for (j = 0; j < 3; j++)
                v[j] = a * u[j] + b * w[j];
            break;
        case HALFSPACE:
        case WEDGE:
            /* one side of the plane of u and w (a wedge: of u) */
            if (v[0] * c[0] + v[1] * c[1] + v[2] * c[2] < 0)
                for (j = 0; j < 3; j++)
                    v[j] = -v[j];
            break;
        case OBTUSE:
            /* chart points (x, y) of the basis u, w, c: most near
               (-8, 0), a few near (8, 0), far from the sum's side */
            for (j = 0; j < 3; j++)
                v[j] = (i % 5 == 0 ? 8 : -8 + rnd(1)) * u[j]
                    + rnd(i % 5 == 0 ? 6 : 2) * w[j] + c[j];
            break;
        case SPACE:
            if (i < 4)
                for (j = 0; j < 3; j++)
                    v[j] = (i == 3 ? -1 : (j == i)) * (r == 3 ? 1 : 5);
            break;
        default:
            break;
        }
        set_row(R, i, v, den, shift);
        if (layout == DEGENERATE && i > 0 && wctest_chance(1, 2))
        {
            slong s = wctest_randint(0, i - 1), m = wctest_randint(-3, 3);

            for (j = 0; j < 3; j++)
                fmpq_mul_si(fmpq_mat_entry(R, i, j),
                            fmpq_mat_entry(R, s, j), m == 0 ? 1 : m);
        }
    }
}

/* S := the rows of A as sorted distinct primitive integer rows.  */
static void
row_set(fmpz_mat_t S, const fmpq_mat_t A)
{
    slong k;

    if (!_wc_hull3_generators(S, &k, A, NULL))
        wctest_fail("out of memory");
    {
        fmpz_mat_t T;
        slong i, j;

        fmpz_mat_init(T, k, 3);
        for (i = 0; i < k; i++)
            _fmpz_vec_set(T->rows[i], S->rows[i], 3);
        /* insertion sort: fine for these sizes */
        for (i = 1; i < k; i++)
            for (j = i; j > 0 && _wc_zvec3_cmp(T->rows[j - 1], T->rows[j]) > 0; j--)
                _fmpz_vec_swap(T->rows[j - 1], T->rows[j], 3);
        fmpz_mat_swap(S, T);
        fmpz_mat_clear(T);
    }
}

/* 1 when A and B have the same row space.  */
static int
same_span(const fmpq_mat_t A, const fmpq_mat_t B)
{
    fmpq_mat_t RA, RB;
    slong ra, rb, i, j;
    int eq;

    fmpq_mat_init(RA, fmpq_mat_nrows(A), 3);
    fmpq_mat_init(RB, fmpq_mat_nrows(B), 3);
    ra = fmpq_mat_nrows(A) ? fmpq_mat_rref(RA, A) : 0;
    rb = fmpq_mat_nrows(B) ? fmpq_mat_rref(RB, B) : 0;
    eq = ra == rb;
    for (i = 0; i < ra && eq; i++)
        for (j = 0; j < 3; j++)
            eq = eq && fmpq_equal(fmpq_mat_entry(RA, i, j),
                                  fmpq_mat_entry(RB, i, j));
    fmpq_mat_clear(RA);
    fmpq_mat_clear(RB);
    return eq;
}

static void
same_rows(const fmpq_mat_t A, const fmpq_mat_t B, const char * what,
          int layout, slong k)
{
    fmpz_mat_t SA, SB;

    fmpz_mat_init(SA, 0, 3);
    fmpz_mat_init(SB, 0, 3);
    row_set(SA, A);
    row_set(SB, B);
    if (!fmpz_mat_equal(SA, SB) || fmpz_mat_nrows(SA) != fmpz_mat_nrows(SB))
        wctest_fail("%s differs from the reference (%s, k = %ld)", what,
                    layout_name[layout], (long) k);
    fmpz_mat_clear(SA);
    fmpz_mat_clear(SB);
}

static slong
rank_q(const fmpq_mat_t A)
{
    fmpq_mat_t B;
    slong r;

    fmpq_mat_init(B, fmpq_mat_nrows(A), 3);
    r = fmpq_mat_nrows(A) ? fmpq_mat_rref(B, A) : 0;
    fmpq_mat_clear(B);
    return r;
}

/* _wc_fan3 and _wc_polar3 on the generators against the reference's
   E2 and H2: dimension 3 (no equalities) with facets of rank 3 is
   pointed, of rank 2 a wedge times a line, 1 a half-space, 0 R^3.  */
static void
classify(const fmpq_mat_t R, const fmpq_mat_t L, const fmpq_mat_t E2,
         const fmpq_mat_t H2, int layout, slong k)
{
    static const int polar_of[] = { WC_POLAR3_SPACE, WC_POLAR3_RAY,
        WC_POLAR3_WEDGE, WC_POLAR3_POINTED };
    fmpz_mat_t G;
    fmpz * V = _fmpz_vec_init(6);
    _wc_fan3_t F;
    slong n, i, h = rank_q(H2);
    int want, got;
    fmpz_t t;

    fmpz_init(t);
    fmpz_mat_init(G, 0, 3);
    _wc_fan3_init(F);
    if (!_wc_hull3_generators(G, &n, R, L))
        wctest_fail("out of memory");
    want = fmpq_mat_nrows(E2) > 0 ? WC_FAN3_OTHER
        : h == 3 ? WC_FAN3_POINTED : h == 0 ? WC_FAN3_SPACE : WC_FAN3_OTHER;
    got = n == 0 ? WC_FAN3_OTHER : _wc_fan3(F, G->rows[0], n);
    if (got != want)
        wctest_fail("fan3 says %d, the reference %d (%s, k = %ld)", got,
                    want, layout_name[layout], (long) k);
    if (got == WC_FAN3_POINTED && F->m != fmpq_mat_nrows(H2))
        wctest_fail("fan3: %ld facets, the reference %ld (%s, k = %ld)",
                    (long) F->m, (long) fmpq_mat_nrows(H2),
                    layout_name[layout], (long) k);
    if (fmpq_mat_nrows(E2) == 0 && n > 0)
    {
        got = _wc_polar3(V, G->rows[0], n);
        if (got != polar_of[h])
            wctest_fail("polar3 says %d, the reference %d (%s, k = %ld)",
                        got, polar_of[h], layout_name[layout], (long) k);
        for (i = 0; i < n && got == WC_POLAR3_POINTED; i++)
            if (_wc_zvec3_dot_sgn(V, G->rows[i], t) <= 0)
                wctest_fail("polar3: d . g <= 0 (%s, k = %ld)",
                            layout_name[layout], (long) k);
    }
    _wc_fan3_clear(F);
    fmpz_mat_clear(G);
    _fmpz_vec_clear(V, 6);
    fmpz_clear(t);
}

static void
want_equal(const fmpz_mat_t got, const fmpz_mat_t want, const char * what,
           int layout, slong k)
{
    if (fmpz_mat_nrows(got) != fmpz_mat_nrows(want)
        || (fmpz_mat_nrows(got) > 0 && !fmpz_mat_equal(got, want)))
        wctest_fail("%s differs from ref-hull3.c (%s, k = %ld)", what,
                    layout_name[layout], (long) k);
}

/* Against the independent reference: the kernel's V -> H and H -> V in
   canonical form, and the canonical cones from generators and from
   constraints, field for field.  */
static void
check_ref(const fmpq_mat_t R, const fmpq_mat_t L, int layout, slong k)
{
    fmpq_mat_t E1, H1, R1, L1, Q, P;
    fmpz_mat_t E, H, LL, RR, X;
    wc_cone_t C;
    wc_error_t err;

    fmpq_mat_init(E1, 0, 3);
    fmpq_mat_init(H1, 0, 3);
    fmpq_mat_init(R1, 0, 3);
    fmpq_mat_init(L1, 0, 3);
    fmpz_mat_init(E, 0, 3);
    fmpz_mat_init(H, 0, 3);
    fmpz_mat_init(LL, 0, 3);
    fmpz_mat_init(RR, 0, 3);
    fmpz_mat_init(X, 0, 3);
    wc_cone_init(C, 3);
    wc_error_init(err);

    /* V -> H */
    ref_hull3_facets(E, H, R, L);
    if (_wc_hull3_v_to_h(E1, H1, R, L, err) != WC_OK)
        wctest_fail("v_to_h: %s", err->message);
    ref_hull3_span(X, E1);
    want_equal(X, E, "v_to_h: equalities", layout, k);
    ref_hull3_canon(X, H1, E);
    want_equal(X, H, "v_to_h: facets", layout, k);
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("set_generators: %s", err->message);
    /* the reference's own round trip gives the rays and lines */
    fmpq_mat_init(Q, fmpz_mat_nrows(E), 3);
    fmpq_mat_init(P, fmpz_mat_nrows(H), 3);
    fmpq_mat_set_fmpz_mat(Q, E);
    fmpq_mat_set_fmpz_mat(P, H);
    ref_hull3_rays(LL, RR, Q, P);
    if (C->empty || C->dim != 3 - fmpz_mat_nrows(E)
        || C->lineality_dim != fmpz_mat_nrows(LL))
        wctest_fail("cone from generators: dimensions differ from "
                    "ref-hull3.c (%s, k = %ld)", layout_name[layout],
                    (long) k);
    want_equal(C->eqs, E, "cone from generators: equalities", layout, k);
    want_equal(C->ineqs, H, "cone from generators: facets", layout, k);
    want_equal(C->lines, LL, "cone from generators: lines", layout, k);
    want_equal(C->rays, RR, "cone from generators: rays", layout, k);
    /* the reference's rays generate the input cone: V -> H -> V -> H */
    fmpq_mat_clear(Q);
    fmpq_mat_clear(P);
    fmpq_mat_init(Q, fmpz_mat_nrows(RR), 3);
    fmpq_mat_init(P, fmpz_mat_nrows(LL), 3);
    fmpq_mat_set_fmpz_mat(Q, RR);
    fmpq_mat_set_fmpz_mat(P, LL);
    ref_hull3_facets(X, LL, Q, P);
    want_equal(X, E, "ref-hull3.c round trip: equalities", layout, k);
    want_equal(LL, H, "ref-hull3.c round trip: facets", layout, k);
    fmpq_mat_clear(Q);
    fmpq_mat_clear(P);

    /* H -> V: the generators read as constraints, L as equalities */
    ref_hull3_rays(LL, RR, L, R);
    if (_wc_hull3_h_to_v(R1, L1, L, R, err) != WC_OK)
        wctest_fail("h_to_v: %s", err->message);
    ref_hull3_span(X, L1);
    want_equal(X, LL, "h_to_v: lines", layout, k);
    ref_hull3_canon(X, R1, LL);
    want_equal(X, RR, "h_to_v: rays", layout, k);
    if (wc_cone_set_hrep(C, L, R, NULL, err) != WC_OK)
        wctest_fail("set_hrep: %s", err->message);
    want_equal(C->lines, LL, "cone from constraints: lines", layout, k);
    want_equal(C->rays, RR, "cone from constraints: rays", layout, k);
    fmpq_mat_init(Q, fmpz_mat_nrows(RR), 3);
    fmpq_mat_init(P, fmpz_mat_nrows(LL), 3);
    fmpq_mat_set_fmpz_mat(Q, RR);
    fmpq_mat_set_fmpz_mat(P, LL);
    ref_hull3_facets(E, H, Q, P);
    want_equal(C->eqs, E, "cone from constraints: equalities", layout, k);
    want_equal(C->ineqs, H, "cone from constraints: facets", layout, k);
    fmpq_mat_clear(Q);
    fmpq_mat_clear(P);

    fmpq_mat_clear(E1);
    fmpq_mat_clear(H1);
    fmpq_mat_clear(R1);
    fmpq_mat_clear(L1);
    fmpz_mat_clear(E);
    fmpz_mat_clear(H);
    fmpz_mat_clear(LL);
    fmpz_mat_clear(RR);
    fmpz_mat_clear(X);
    wc_cone_clear(C);
    wc_error_clear(err);
}

/* One random set: both conversions against the reference, the whole cone
   against cddlib (use_cdd) and H -> V -> H round trips.  */
static void
check_one(int layout, slong k, int use_cdd)
{
    fmpq_mat_t R, L, E1, H1, E2, H2, R1, L1, R2, L2, S;
    wc_cone_t C, D;
    wc_error_t err;
    slong i, j;

    fmpq_mat_init(R, 0, 3);
    fmpq_mat_init(L, 0, 3);
    fmpq_mat_init(E1, 0, 3);
    fmpq_mat_init(H1, 0, 3);
    fmpq_mat_init(E2, 0, 3);
    fmpq_mat_init(H2, 0, 3);
    fmpq_mat_init(R1, 0, 3);
    fmpq_mat_init(L1, 0, 3);
    fmpq_mat_init(R2, 0, 3);
    fmpq_mat_init(L2, 0, 3);
    fmpq_mat_init(S, 0, 3);
    wc_cone_init(C, 3);
    wc_cone_init(D, 3);
    wc_error_init(err);
    make(R, L, layout, k);
    if (k <= REF_MAXK)
        check_ref(R, L, layout, k);

    /* V -> H (the former kernel).  */
    if (_wc_hull3_v_to_h(E1, H1, R, L, err) != WC_OK)
        wctest_fail("v_to_h: %s", err->message);
    old_hull3_v_to_h(E2, H2, R, L);
    if (!same_span(E1, E2))
        wctest_fail("v_to_h: equalities differ (%s, k = %ld)",
                    layout_name[layout], (long) k);
    same_rows(H1, H2, "v_to_h: facets", layout, k);
    classify(R, L, E2, H2, layout, k);

    /* H -> V, the generators read as constraints (no equalities, and
       with L as equalities).  */
    if (_wc_hull3_h_to_v(R1, L1, NULL, R, err) != WC_OK)
        wctest_fail("h_to_v: %s", err->message);
    old_hull3_h_to_v(R2, L2, NULL, R);
    if (!same_span(L1, L2))
        wctest_fail("h_to_v: lines differ (%s, k = %ld)",
                    layout_name[layout], (long) k);
    same_rows(R1, R2, "h_to_v: rays", layout, k);
    if (_wc_hull3_h_to_v(R1, L1, L, R, err) != WC_OK)
        wctest_fail("h_to_v: %s", err->message);
    old_hull3_h_to_v(R2, L2, L, R);
    if (!same_span(L1, L2))
        wctest_fail("h_to_v with equalities: lines differ (%s, k = %ld)",
                    layout_name[layout], (long) k);
    same_rows(R1, R2, "h_to_v with equalities: rays", layout, k);

    /* The whole canonical cone, fast path against cddlib (or, for large
       k, against the general route from the reference's H).  */
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("set_generators: %s", err->message);
    if (use_cdd)
    {
        if (_wc_cone_set_generators_kernel(D, R, L, 1, err) != WC_OK)
            wctest_fail("set_generators (cddlib): %s", err->message);
        if (!wc_cone_equal(C, D))
            wctest_fail("fast kernel and cddlib disagree on a cone from "
                        "generators (%s, k = %ld)", layout_name[layout],
                        (long) k);
        /* The constraint side, with some rows strict.  */
        fmpq_mat_init(S, 0, 3);
        fmpq_mat_clear(S);
        fmpq_mat_init(S, k > 0 ? wctest_randint(0, 2) : 0, 3);
        for (i = 0; i < fmpq_mat_nrows(S); i++)
            for (j = 0; j < 3; j++)
                fmpq_set(fmpq_mat_entry(S, i, j),
                         fmpq_mat_entry(R, wctest_randint(0, k - 1), j));
        if (wc_cone_set_hrep(C, NULL, R, S, err) != WC_OK)
            wctest_fail("set_hrep: %s", err->message);
        if (_wc_cone_set_hrep_kernel(D, NULL, R, S, 1, err) != WC_OK)
            wctest_fail("set_hrep (cddlib): %s", err->message);
        if (!wc_cone_equal(C, D))
            wctest_fail("fast kernel and cddlib disagree on a cone from "
                        "constraints (%s, k = %ld)", layout_name[layout],
                        (long) k);
    }
    else
    {
        /* cl pos(R) from the reference's constraints, the general
           route's lineality and faces included: the same set.  */
        if (wc_cone_set_hrep(D, E2, H2, NULL, err) != WC_OK)
            wctest_fail("set_hrep: %s", err->message);
        if (!wc_cone_equal(C, D))
            wctest_fail("V -> H -> V changes the cone (%s, k = %ld)",
                        layout_name[layout], (long) k);
    }

    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
    fmpq_mat_clear(E1);
    fmpq_mat_clear(H1);
    fmpq_mat_clear(E2);
    fmpq_mat_clear(H2);
    fmpq_mat_clear(R1);
    fmpq_mat_clear(L1);
    fmpq_mat_clear(R2);
    fmpq_mat_clear(L2);
    fmpq_mat_clear(S);
    wc_cone_clear(C);
    wc_cone_clear(D);
    wc_error_clear(err);
}

/* The layouts that made the former kernel cubic, at sizes it could not
   take, with their answers known in closed form: a wedge times the line
   of e3 (rays (i - 1500, 1000 + i^2 mod 997, i mod 13 - 6)), whose two
   extreme rays in the quotient are the rows of smallest and largest
   x / y; and a pointed cone of 13,000 rows, most near the chart point
   (-1000, 0), three at x = 1000 -- the middle one, (1000, 0), farthest
   from the rows' sum yet not extreme.  */
static void
check_hostile(void)
{
    static const slong want[4][3] = { { -1000, -50, 1 }, { -1000, 50, 1 },
        { 1000, -500, 1 }, { 1000, 500, 1 } };
    fmpq_mat_t R, L;
    wc_cone_t C;
    wc_error_t err;
    slong n = 3000, i, lo = 0, hi = 0, j;

    wc_cone_init(C, 3);
    wc_error_init(err);
    fmpq_mat_init(R, n, 3);
    fmpq_mat_init(L, 1, 3);
    fmpq_set_si(fmpq_mat_entry(L, 0, 2), 1, 1);
    for (i = 0; i < n; i++)
    {
        slong x = i - 1500, y = 1000 + (i * i) % 997;

        fmpq_set_si(fmpq_mat_entry(R, i, 0), x, 1);
        fmpq_set_si(fmpq_mat_entry(R, i, 1), y, 1);
        fmpq_set_si(fmpq_mat_entry(R, i, 2), i % 13 - 6, 1);
        /* x / y against the best so far: x y' < x' y */
        if (x * fmpz_get_si(fmpq_numref(fmpq_mat_entry(R, lo, 1)))
            < fmpz_get_si(fmpq_numref(fmpq_mat_entry(R, lo, 0))) * y)
            lo = i;
        if (x * fmpz_get_si(fmpq_numref(fmpq_mat_entry(R, hi, 1)))
            > fmpz_get_si(fmpq_numref(fmpq_mat_entry(R, hi, 0))) * y)
            hi = i;
    }
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("hostile wedge: %s", err->message);
    if (C->dim != 3 || C->lineality_dim != 1 || fmpz_mat_nrows(C->rays) != 2
        || fmpz_mat_nrows(C->ineqs) != 2)
        wctest_fail("hostile wedge: dim %ld, lineality %ld, %ld rays, %ld "
                    "facets", (long) C->dim, (long) C->lineality_dim,
                    (long) fmpz_mat_nrows(C->rays),
                    (long) fmpz_mat_nrows(C->ineqs));
    /* the rays, projected off e3 and made primitive: rows lo and hi,
       x < 0 first */
    for (i = 0; i < 2; i++)
    {
        slong r = i == 0 ? lo : hi;
        fmpz_t g;

        fmpz_init(g);
        fmpz_gcd(g, fmpq_numref(fmpq_mat_entry(R, r, 0)),
                 fmpq_numref(fmpq_mat_entry(R, r, 1)));
        for (j = 0; j < 3; j++)
            if (fmpz_get_si(fmpz_mat_entry(C->rays, i, j)) * fmpz_get_si(g)
                != (j == 2 ? 0
                    : fmpz_get_si(fmpq_numref(fmpq_mat_entry(R, r, j)))))
                wctest_fail("hostile wedge: wrong extreme ray %ld", i);
        fmpz_clear(g);
    }

    n = 13000;
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
    fmpq_mat_init(R, n, 3);
    fmpq_mat_init(L, 0, 3);
    for (i = 0; i < n; i++)
    {
        slong x = i < n - 3 ? -1000 + i % 97 : 1000;
        slong y = i < n - 3 ? (i * 37) % 101 - 50 : (i - (n - 2)) * 500;

        fmpq_set_si(fmpq_mat_entry(R, i, 0), x, 1);
        fmpq_set_si(fmpq_mat_entry(R, i, 1), y, 1);
        fmpq_set_si(fmpq_mat_entry(R, i, 2), 1, 1);
    }
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("hostile pointed: %s", err->message);
    if (C->lineality_dim != 0 || fmpz_mat_nrows(C->rays) != 4)
        wctest_fail("hostile pointed: %ld rays, lineality %ld",
                    (long) fmpz_mat_nrows(C->rays), (long) C->lineality_dim);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 3; j++)
            if (fmpz_get_si(fmpz_mat_entry(C->rays, i, j)) != want[i][j])
                wctest_fail("hostile pointed: wrong extreme ray %ld", i);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
    wc_cone_clear(C);
    wc_error_clear(err);
}

int
main(void)
{
    slong iters, i;

    wc_init();
    wctest_init("t-hull3");
    check_hostile();
    iters = wctest_iters(300);    /* 900 in CI's widened run */
    for (i = 0; i < iters; i++)
    {
        int layout;
        slong k;

        if (!wctest_iter(i))
            continue;
        layout = (int) (i % LAYOUTS);
        k = wctest_chance(1, 10) ? wctest_randint(40, 300)
            : wctest_randint(0, 24);
        check_one(layout, k, k <= 60 || i % 7 == 0);
    }
    flint_cleanup_master();
    return 0;
}
