/* t-compare.c -- angles between vectors and cones, angular distances
   between cones, and the reader of foreign cones (compare.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   References: angles worked out by hand (each case says how); for the
   directed distance, on random cones, the witness it returns (a unit
   vector of A at exactly that angle from B) and random vectors of A
   (none farther from B than the distance).  */

#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpq_vec.h>

#include "wrenchcone.h"
#include "float/compare.h"
#include "testutil.h"

#define ROW(A, i) ((A)->rows[i])
#define PI 3.14159265358979323846

/* Rows "a b c;a b c;..." of exact numbers into M (r x 3).  */
static void
rows(fmpq_mat_t M, const char * s)
{
    slong r = 0, i, j;
    const char * p;
    wc_error_t err;

    for (p = s; *p != '\0'; p++)
        r += *p == ';';
    fmpq_mat_init(M, r, 3);
    wc_error_init(err);
    for (i = 0; i < r; i++)
        for (j = 0; j < 3; j++)
        {
            size_t n;

            while (*s == ' ')
                s++;
            n = strcspn(s, " ;");
            if (wc_parse_number(fmpq_mat_entry(M, i, j), s, n, err) != WC_OK)
                wctest_fail("bad test row '%s'", s);
            s += n;
            while (*s == ' ' || (j == 2 && *s == ';'))
                s++;
        }
    wc_error_clear(err);
}

/* C = pos(rays) + span(lines).  */
static void
gens(wc_cone_t C, const char * r, const char * l)
{
    fmpq_mat_t R, L;
    wc_error_t err;

    rows(R, r);
    rows(L, l);
    wc_error_init(err);
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("set_generators(%s | %s): %s", r, l, err->message);
    wc_error_clear(err);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
}

/* C = { eqs g = 0, ineqs g <= 0 }.  */
static void
hrep(wc_cone_t C, const char * e, const char * h)
{
    fmpq_mat_t E, H;
    wc_error_t err;

    rows(E, e);
    rows(H, h);
    wc_error_init(err);
    if (wc_cone_set_hrep(C, E, H, NULL, err) != WC_OK)
        wctest_fail("set_hrep(%s | %s): %s", e, h, err->message);
    wc_error_clear(err);
    fmpq_mat_clear(E);
    fmpq_mat_clear(H);
}

static int
close_to(double got, double want)
{
    if (isinf(want) || want == 0)
        return got == want;
    return fabs(got - want) <= 1e-14 * (want > 1 ? want : 1);
}

/* The angle from v (a row "x y z;") to C must be want (0 and INFINITY
   exactly).  */
static void
check_angle(const char * name, const wc_cone_t C, const char * v,
            double want)
{
    fmpq_mat_t V;
    double got;

    rows(V, v);
    got = wc_angle_to_cone(ROW(V, 0), C);
    if (!close_to(got, want))
        wctest_fail("angle %s: v = %s: got %.17g, want %.17g", name, v, got,
                    want);
    fmpq_mat_clear(V);
}

static void
check_directed(const char * name, const wc_cone_t A, const wc_cone_t B,
               double want)
{
    double got;
    wc_error_t err;

    wc_error_init(err);
    if (wc_cone_directed_angle(&got, NULL, A, B, err) != WC_OK)
        wctest_fail("directed %s: %s", name, err->message);
    if (!(close_to(got, want) || fabs(got - want) <= 1e-12))
        wctest_fail("directed %s: got %.17g, want %.17g", name, got, want);
    wc_error_clear(err);
}

static void
hand_angles(void)
{
    wc_cone_t C;

    wc_cone_init(C, 3);

    /* The positive orthant.  */
    gens(C, "1 0 0;0 1 0;0 0 1;", "");
    check_angle("orthant, inside", C, "1 2 3;", 0);
    check_angle("orthant, on a facet", C, "1 2 0;", 0);
    check_angle("orthant, on an edge", C, "0 0 5;", 0);
    /* nearest: the facet z = 0, at (1, 1, 0): tan = 1 / sqrt 2 */
    check_angle("orthant, to a facet", C, "1 1 -1;", atan(sqrt(0.5)));
    /* nearest: the edge e1, at (1, 0, 0): cos = 1 / sqrt 3 */
    check_angle("orthant, to an edge", C, "1 -1 -1;", acos(1 / sqrt(3)));
    /* nearest: the edge e2 at (0, 2, 0): tan = 1/2 */
    check_angle("orthant, to an edge (2)", C, "-1 2 0;", atan(0.5));
    /* polar: the nearest unit vectors are the rays, cos = -1 / sqrt 3 */
    check_angle("orthant, polar", C, "-1 -1 -1;", PI - acos(1 / sqrt(3)));
    check_angle("orthant, polar axis", C, "-1 0 0;", PI / 2);
    check_angle("orthant, tiny", C, "1 1 -1/1000000000000000000000;",
                atan(1e-21 / sqrt(2)));

    /* A square pyramid { |x| + |y| <= z }.  */
    gens(C, "1 0 1;-1 0 1;0 1 1;0 -1 1;", "");
    /* the facet x + y = z: q = v - (2/3)(1, 1, -1) = (1/3, 1/3, 2/3),
       inside the facet; sin^2 = |v - q|^2 / |v|^2 = 2/3 */
    check_angle("pyramid, to a facet", C, "1 1 0;", asin(sqrt(2.0 / 3)));
    /* both facet projections fall outside: the edge (1, 0, 1) is
       nearest, cos = 1 / (sqrt 5 sqrt 2) */
    check_angle("pyramid, to an edge", C, "2 0 -1;", acos(1 / sqrt(10)));
    check_angle("pyramid, inside", C, "1/3 -1/3 1;", 0);

    /* A 2-D wedge pos(e1, e2) in the plane z = 0.  */
    gens(C, "1 0 0;0 1 0;", "");
    check_angle("wedge, above", C, "1 1 1;", atan(sqrt(0.5)));
    check_angle("wedge, normal", C, "0 0 1;", PI / 2);
    check_angle("wedge, polar in the plane", C, "-1 -1 0;", 3 * PI / 4);
    check_angle("wedge, in the plane", C, "3 1 0;", 0);

    /* A single ray.  */
    gens(C, "2 0 0;", "");
    check_angle("ray, at 45 degrees", C, "1 1 0;", PI / 4);
    check_angle("ray, opposite", C, "-1 0 0;", PI);
    check_angle("ray, on it", C, "7 0 0;", 0);

    /* Lineality: a half-space z <= 0.  */
    hrep(C, "", "0 0 1;");
    check_angle("half-space, normal", C, "0 0 1;", PI / 2);
    check_angle("half-space, 45", C, "1 0 1;", PI / 4);
    check_angle("half-space, inside", C, "1 0 -1;", 0);

    /* A half-plane: line e1, ray e2.  */
    gens(C, "0 1 0;", "1 0 0;");
    /* nearest: the line, at (5, 0, 0) */
    check_angle("half-plane, to the line", C, "5 -1 0;", atan(0.2));
    check_angle("half-plane, polar", C, "0 -1 1;", PI / 2);
    /* nearest: (3, 4, 0) in the relative interior: tan = 12 / 5 */
    check_angle("half-plane, above", C, "3 4 12;", atan(12.0 / 5));

    /* A plane z = 0 (lineality 2) and a line.  */
    gens(C, "", "1 0 0;0 1 0;");
    check_angle("plane, 45", C, "1 0 1;", PI / 4);
    check_angle("plane, normal", C, "0 0 -1;", PI / 2);
    gens(C, "", "1 1 0;");
    check_angle("line, 45", C, "1 0 0;", PI / 4);
    check_angle("line, other way", C, "-1 -1 1;", atan(1 / sqrt(2.0)));

    /* The whole space, {0} and the empty cone.  */
    hrep(C, "", "");
    check_angle("R^3", C, "-1 2 -3;", 0);
    gens(C, "", "");
    check_angle("origin", C, "1 0 0;", INFINITY);
    wc_cone_set_empty(C);
    check_angle("empty", C, "1 0 0;", INFINITY);

    wc_cone_clear(C);
}

static void
hand_distances(void)
{
    wc_cone_t A, B;
    double d;
    wc_error_t err;

    wc_cone_init(A, 3);
    wc_cone_init(B, 3);
    wc_error_init(err);

    gens(A, "1 0 0;0 1 0;0 0 1;", "");
    check_directed("same", A, A, 0);

    /* The extreme rays are not enough: A's rays (1, +-1, e) are at
       atan(e / sqrt 2) from the wedge B = pos((1, 1, 0), (1, -1, 0)), but
       A's middle (1, 0, e) is at atan(e); and B's middle is at atan(e)
       from A's plane z = e x, with its foot inside A.  */
    gens(A, "1 1 1/1000;1 -1 1/1000;", "");
    gens(B, "1 1 0;1 -1 0;", "");
    check_directed("bulge A to B", A, B, atan(1e-3));
    check_directed("bulge B to A", B, A, atan(1e-3));
    if (wc_cone_hausdorff_angle(&d, A, B, err) != WC_OK
        || !close_to(d, atan(1e-3)))
        wctest_fail("bulge: Hausdorff %.17g", d);

    /* A ray against the orthant: one way in, the other way the far edge
       of the orthant is at a right angle.  */
    gens(A, "1 0 0;0 1 0;0 0 1;", "");
    gens(B, "1 0 0;", "");
    check_directed("orthant to ray", A, B, PI / 2);
    check_directed("ray to orthant", B, A, 0);

    /* Antipodal rays.  */
    gens(A, "-1 0 0;", "");
    check_directed("antipodal", A, B, PI);

    /* The negative orthant (= the polar of the positive one): its centre
       is farthest from the positive orthant, at the angle between
       -(1, 1, 1) and a coordinate axis; a vertex of it is only at pi/2.  */
    gens(A, "-1 0 0;0 -1 0;0 0 -1;", "");
    gens(B, "1 0 0;0 1 0;0 0 1;", "");
    check_directed("negative orthant", A, B, PI - acos(1 / sqrt(3)));

    /* Half-spaces tilted by atan(1/10): their distance is the tilt.  */
    hrep(A, "", "0 0 1;");
    hrep(B, "", "1/10 0 1;");
    check_directed("half-spaces", A, B, atan(0.1));
    check_directed("half-spaces back", B, A, atan(0.1));

    /* Planes tilted by atan(1/3).  */
    hrep(A, "0 0 1;", "");
    hrep(B, "1 0 3;", "");
    check_directed("planes", A, B, atan(1.0 / 3));

    /* {0}: nothing of it to be far; everything of the other is
       infinitely far from it.  */
    gens(A, "", "");
    check_directed("origin to plane", A, B, 0);
    check_directed("plane to origin", B, A, INFINITY);
    check_directed("origin to origin", A, A, 0);

    /* A lower-dimensional cone against a full one containing it, and a
       half-plane against the same half-plane rotated in its plane.  */
    gens(A, "1 0 0;0 1 0;", "");
    gens(B, "1 0 0;0 1 0;0 0 1;", "");
    check_directed("wedge into orthant", A, B, 0);
    check_directed("orthant onto wedge", B, A, PI / 2);
    gens(A, "0 1 0;", "1 0 0;");
    gens(B, "-1 10 0;", "10 1 0;");
    check_directed("half-planes", A, B, atan(0.1));

    wc_error_clear(err);
    wc_cone_clear(A);
    wc_cone_clear(B);
}

/* A random cone: 0 to 6 generators with entries in [-3, 3], sometimes a
   line, sometimes all in one plane.  */
static void
random_cone(wc_cone_t C)
{
    slong k = wctest_randint(0, 6), l = wctest_chance(1, 5), i, j;
    int planar = wctest_chance(1, 4);
    fmpq_mat_t R, L;
    wc_error_t err;

    fmpq_mat_init(R, k, 3);
    fmpq_mat_init(L, l, 3);
    for (i = 0; i < k; i++)
        for (j = 0; j < 3; j++)
            fmpq_set_si(fmpq_mat_entry(R, i, j),
                        planar && j == 2 ? 0 : wctest_randint(-3, 3), 1);
    for (i = 0; i < l; i++)
        for (j = 0; j < 3; j++)
            fmpq_set_si(fmpq_mat_entry(L, i, j),
                        planar && j == 2 ? 0 : wctest_randint(-3, 3), 1);
    wc_error_init(err);
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("random cone: %s", err->message);
    wc_error_clear(err);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
}

/* A random nonzero vector of cl C (C nonzero).  */
static void
random_point(fmpq * x, const wc_cone_t C)
{
    slong k = fmpz_mat_nrows(C->rays), l = fmpz_mat_nrows(C->lines), i, j;
    fmpq_t c, t;

    fmpq_init(c);
    fmpq_init(t);
    do
    {
        for (j = 0; j < 3; j++)
            fmpq_zero(x + j);
        for (i = 0; i < k + l; i++)
        {
            const fmpz * g = i < k ? ROW(C->rays, i) : ROW(C->lines, i - k);

            if (i < k)
                fmpq_set_si(c, wctest_chance(1, 3) ? 0 : wctest_randint(0, 50),
                            wctest_randint(1, 7));
            else
                fmpq_set_si(c, wctest_randint(-50, 50), wctest_randint(1, 7));
            for (j = 0; j < 3; j++)
            {
                fmpq_mul_fmpz(t, c, g + j);
                fmpq_add(x + j, x + j, t);
            }
        }
    }
    while (fmpq_is_zero(x + 0) && fmpq_is_zero(x + 1) && fmpq_is_zero(x + 2));
    fmpq_clear(c);
    fmpq_clear(t);
}

/* w (doubles, unit) lies in cl C up to rounding.  */
static int
near_cone(const double * w, const wc_cone_t C)
{
    slong i, j;

    for (i = 0; i < fmpz_mat_nrows(C->ineqs) + fmpz_mat_nrows(C->eqs); i++)
    {
        int eq = i >= fmpz_mat_nrows(C->ineqs);
        const fmpz * h = eq ? ROW(C->eqs, i - fmpz_mat_nrows(C->ineqs))
            : ROW(C->ineqs, i);
        double s = 0, n = 0;

        for (j = 0; j < 3; j++)
        {
            s += fmpz_get_d(h + j) * w[j];
            n += fmpz_get_d(h + j) * fmpz_get_d(h + j);
        }
        if (eq ? fabs(s) > 1e-12 * sqrt(n) : s > 1e-12 * sqrt(n))
            return 0;
    }
    return 1;
}

static void
random_distances(void)
{
    slong iters = wctest_iters(300), it, s;
    wc_cone_t A, B;
    fmpq * x = _fmpq_vec_init(3);
    mpq_t m;
    wc_error_t err;

    wc_cone_init(A, 3);
    wc_cone_init(B, 3);
    wc_error_init(err);
    mpq_init(m);
    for (it = 0; it < iters; it++)
    {
        double d, d2, w[3], a;

        if (!wctest_iter(it))
            continue;
        random_cone(A);
        random_cone(B);
        if (wc_cone_directed_angle(&d, w, A, B, err) != WC_OK)
            wctest_fail("directed: %s", err->message);
        if (wc_cone_directed_angle(&d2, NULL, A, A, err) != WC_OK || d2 != 0)
            wctest_fail("directed from a cone to itself: %g", d2);
        if (A->dim == 0)
        {
            if (d != 0)
                wctest_fail("from {0}: %g", d);
            continue;
        }
        if (B->dim == 0)
        {
            if (!isinf(d))
                wctest_fail("to {0}: %g", d);
            continue;
        }
        /* The witness is in A, at the distance from B.  */
        if (!near_cone(w, A))
            wctest_fail("witness (%g, %g, %g) not in A", w[0], w[1], w[2]);
        for (s = 0; s < 3; s++)
        {
            mpq_set_d(m, w[s]);
            fmpq_set_mpq(x + s, m);
        }
        a = wc_angle_to_cone(x, B);
        if (!(fabs(a - d) <= 1e-9))
            wctest_fail("witness at %.17g from B, distance %.17g", a, d);
        /* Nothing of A is farther.  */
        for (s = 0; s < 200; s++)
        {
            random_point(x, A);
            a = wc_angle_to_cone(x, B);
            if (!(a <= d + 1e-12))
            {
                char * t = wctest_vec_str(x, 3);

                wctest_fail("%s at %.17g from B, beyond the distance %.17g",
                            t, a, d);
            }
        }
        /* The angle to a cone is the least angle to its vectors.  */
        for (s = 0; s < 50; s++)
        {
            fmpq * y = _fmpq_vec_init(3);
            double b;

            random_point(x, A);
            random_point(y, B);
            a = wc_angle_to_cone(x, B);
            b = wc_angle_vectors(x, y);
            _fmpq_vec_clear(y, 3);
            if (!(a <= b + 1e-12))
                wctest_fail("angle to B %.17g above the angle %.17g to one of "
                            "its vectors", a, b);
        }
    }
    mpq_clear(m);
    wc_error_clear(err);
    wc_cone_clear(A);
    wc_cone_clear(B);
    _fmpq_vec_clear(x, 3);
}

/* The reader keeps every number exact.  */
static void
reader(void)
{
    static const char ext[] =
        "name\n* a comment\nV-representation\nlinearity 1 3\nbegin\n"
        " 3 4 real\n 1 0 0 0\n 0 0.1 -1e-3 2E2\n 0 -3/4 +5 0.000\nend\n";
    static const char ine[] =
        "H-representation\nbegin\n 2 4 rational\n 0 1 2 3\n 5 0 0 0\nend\n";
    static const char json[] =
        "{\"mode\": \"na\", \"cone\": {\"empty\": false, \"arith\": \"double\","
        " \"rays\": [[0.5, \"-1/3\", 1e2]], \"inequalities\": [[-1, 0, 0]]}}";
    static const char bad[] = "V-representation\nbegin\n 1 4 real\n 0 1 x 0\n";
    static const char nul[] = "V-representation\nbegin\n 1 4 real\n 0 1\0 2 3\n";
    wc_foreign_t F;
    wc_error_t err;
    fmpq_mat_t W;

    wc_foreign_init(F);
    wc_error_init(err);
    if (wc_foreign_parse(F, ext, strlen(ext), "x.ext", err) != WC_OK)
        wctest_fail("ext: %s", err->message);
    rows(W, "1/10 -1/1000 200;");
    if (F->nreps != 1 || F->reps[0].kind != WC_REP_GENERATORS
        || F->reps[0].empty || !fmpq_mat_equal(F->reps[0].rows, W)
        || fmpq_mat_nrows(F->reps[0].lin) != 1
        || !fmpq_equal_si(fmpq_mat_entry(F->reps[0].lin, 0, 1), 5)
        || F->reps[0].row_line[0] != 8 || F->reps[0].lin_line[0] != 9)
        wctest_fail("ext read wrong");
    fmpq_mat_clear(W);

    if (wc_foreign_parse(F, ine, strlen(ine), "x.ine", err) != WC_OK)
        wctest_fail("ine: %s", err->message);
    rows(W, "-1 -2 -3;");   /* 0 + a.g >= 0 is (-a).g <= 0 */
    if (F->nreps != 1 || F->reps[0].kind != WC_REP_INEQUALITIES
        || F->reps[0].empty || !fmpq_mat_equal(F->reps[0].rows, W))
        wctest_fail("ine read wrong");
    fmpq_mat_clear(W);

    if (wc_foreign_parse(F, json, strlen(json), "x.json", err) != WC_OK)
        wctest_fail("json: %s", err->message);
    rows(W, "1/2 -1/3 100;");
    if (F->nreps != 2 || !F->json || !F->arith_double || F->mode == NULL
        || strcmp(F->mode, "na") != 0 || !fmpq_mat_equal(F->reps[0].rows, W)
        || F->reps[1].kind != WC_REP_INEQUALITIES)
        wctest_fail("json read wrong");
    fmpq_mat_clear(W);

    /* Errors are located and leave F empty.  */
    if (wc_foreign_parse(F, bad, strlen(bad), "bad.ext", err) != WC_EINPUT
        || err->line != 4 || err->col != 6 || F->nreps != 0)
        wctest_fail("bad number: %ld:%ld %s", err->line, err->col,
                    err->message);
    /* a NUL byte, hostile bytes and a row count that could not be
       allocated are errors too */
    if (wc_foreign_parse(F, nul, sizeof nul - 1, "nul.ext", err) != WC_EINPUT
        || err->line != 4 || err->col != 5
        || strcmp(err->message, "NUL byte in the file") != 0)
        wctest_fail("NUL: %ld:%ld %s", err->line, err->col, err->message);
    if (wc_foreign_parse(F, "\xff\xfe{\n", 4, "bin", err) != WC_EINPUT
        || err->line != 2 || err->col != 1)
        wctest_fail("binary: %ld:%ld %s", err->line, err->col, err->message);
    if (wc_foreign_parse(F, "begin\n 1000000000000 4 real\n", 28, "big", err)
        != WC_EINPUT || err->line != 2 || err->col != 2)
        wctest_fail("big: %ld:%ld %s", err->line, err->col, err->message);
    wc_error_clear(err);
    wc_foreign_clear(F);
}

/* Every sequence of 1 to 4 cdd blocks, each with no representation
   keyword (cdd's default, H), 'H-representation' or 'V-representation':
   read as one representation per block when no kind repeats, else an
   error at the first block of a kind already seen (at its keyword, or at
   its 'begin' when it has none).  Worked out block by block here.  */
static void
reader_blocks(void)
{
    static const char * kw[3] = { "", "H-representation\n",
                                  "V-representation\n" };
    wc_foreign_t F;
    wc_error_t err;
    char text[512], want[200];
    slong k, code, j, ncodes;

    wc_foreign_init(F);
    wc_error_init(err);
    for (k = 1, ncodes = 3; k <= 4; k++, ncodes *= 3)
        for (code = 0; code < ncodes; code++)
        {
            int c[4], status;
            long line = 1, first[2] = { 0, 0 }, bad_line = 0;
            slong x = code, nreps = 0;
            size_t n = 0;

            want[0] = '\0';
            for (j = 0; j < k; j++, x /= 3)
            {
                int kind;
                long at;

                c[j] = (int) (x % 3);
                kind = c[j] == 2 ? WC_REP_GENERATORS : WC_REP_INEQUALITIES;
                at = line;
                n += (size_t) sprintf(text + n, "%s", kw[c[j]]);
                line += c[j] != 0;
                n += (size_t) sprintf(text + n, "begin\n 1 4 rational\n"
                                      " 0 1 0 0\nend\n");
                if (c[j] == 0)
                    at = line;
                line += 4;
                if (bad_line != 0)
                    continue;
                if (first[kind] != 0)
                {
                    bad_line = at;
                    if (c[j] == 0)
                        sprintf(want, "a second H-representation (a block "
                                "with no representation keyword is an "
                                "H-representation, as in cdd; the first "
                                "is line %ld)", first[kind]);
                    else
                        sprintf(want, "a second %s-representation",
                                c[j] == 1 ? "H" : "V");
                }
                else
                {
                    first[kind] = at;
                    nreps++;
                }
            }
            status = wc_foreign_parse(F, text, n, "b.ine", err);
            if (bad_line != 0
                ? status != WC_EINPUT || err->line != bad_line
                  || err->col != 1 || strcmp(err->message, want) != 0
                  || F->nreps != 0
                : status != WC_OK || F->nreps != nreps)
                wctest_fail("blocks %ld/%ld: status %d at %ld:%ld '%s' "
                            "(%ld reps); want %s at %ld:1 '%s'", (long) k,
                            (long) code, status, err->line, err->col,
                            status == WC_OK ? "" : err->message,
                            (long) F->nreps, bad_line ? "an error" : "OK",
                            bad_line, want);
            for (j = 0; bad_line == 0 && j < nreps; j++)
                if (F->reps[j].kind != (c[j] == 2 ? WC_REP_GENERATORS
                                        : WC_REP_INEQUALITIES)
                    || fmpq_mat_nrows(F->reps[j].rows) != 1)
                    wctest_fail("blocks %ld/%ld: representation %ld wrong",
                                (long) k, (long) code, (long) j);
        }
    wc_error_clear(err);
    wc_foreign_clear(F);
}

/* A JSON cone's "dim", "lineality_dim" and "faces" need not agree with
   its data (that is computed), but must be well formed.  */
static void
reader_json_keys(void)
{
    static const struct
    {
        const char * text;
        long line, col;
        const char * message;   /* NULL: read without error */
    }
    cases[] = {
        { "{\"empty\": false, \"dim\": 2, \"lineality_dim\": 0, \"rays\": "
          "[[1, 0, 0], [0, 1, 0]], \"faces\": [{\"dim\": 0, \"rays\": [], "
          "\"included\": true}, {\"dim\": 2, \"rays\": [0, 1], "
          "\"included\": false}]}", 0, 0, NULL },
        { "{\"empty\": true, \"faces\": []}", 0, 0, NULL },
        { "{\"empty\": false, \"dim\": 3.5, \"rays\": [[1, 0, 0]]}", 1, 25,
          "'dim' must be an integer from 0 to 3, not 3.5" },
        { "{\"empty\": false, \"dim\": -1, \"rays\": [[1, 0, 0]]}", 1, 25,
          "'dim' must be an integer from 0 to 3, not -1" },
        { "{\"empty\": true,\n \"dim\": -1}", 2, 9,
          "'dim' must be an integer from 0 to 3, not -1" },
        { "{\"empty\": false, \"dim\": \"3\", \"rays\": [[1, 0, 0]]}", 1, 25,
          "'dim' must be an integer from 0 to 3, found a string" },
        { "{\"empty\": false, \"lineality_dim\": 4, \"rays\": [[1, 0, 0]]}",
          1, 35, "'lineality_dim' must be an integer from 0 to 3, not 4" },
        { "{\"empty\": false, \"rays\": [[1, 0, 0], [0, 1, 0]],\n"
          " \"faces\": [{\"dim\": 1, \"rays\": [1]}, {\"dim\": 1, "
          "\"rays\": [2]}]}", 2, 57,
          "face ray index 2 is out of range: 'rays' has 2 rows (0 to 1)" },
        { "{\"empty\": false, \"inequalities\": [[1, 0, 0]],\n"
          " \"faces\": [{\"dim\": 1, \"rays\": [0]}]}", 2, 32,
          "face ray index 0 is out of range: the cone has no 'rays'" },
        { "{\"empty\": true, \"faces\": [{\"rays\": [0]}]}", 1, 37,
          "face ray index 0 is out of range: the cone is empty" },
        { "{\"empty\": false, \"rays\": [], \"lines\": [[1, 0, 0]], "
          "\"faces\": [{\"rays\": [0]}]}", 1, 72,
          "face ray index 0 is out of range: 'rays' is empty" },
        { "{\"empty\": false, \"rays\": [[1, 0, 0]], \"faces\": [{\"rays\": "
          "[-1]}]}", 1, 59,
          "face ray index -1 is out of range: 'rays' has 1 row (0 to 0)" },
        { "{\"empty\": false, \"rays\": [[1, 0, 0]], \"faces\": [{\"rays\": "
          "[0.5]}]}", 1, 59,
          "a face ray index must be an integer, not 0.5" },
        { "{\"empty\": false, \"rays\": [[1, 0, 0]], \"faces\": [{\"rays\": "
          "[0]}, [0]]}", 1, 64, "each entry of 'faces' must be an object" },
        { "{\"empty\": false, \"rays\": [[1, 0, 0]], \"faces\": {}}", 1, 48,
          "'faces' must be an array" },
        { "{\"empty\": false, \"rays\": [[1, 0, 0]], \"faces\": [{\"rays\": "
          "0}]}", 1, 58, "a face's 'rays' must be an array" },
        { "{\"empty\": false, \"rays\": [[1, 0, 0]], \"faces\": [{\"dim\": "
          "7, \"rays\": [0]}]}", 1, 57,
          "'dim' must be an integer from 0 to 3, not 7" },
        { "{\"empty\": false, \"rays\": [[1, 0, 0]], \"faces\": [{\"rays\": "
          "[0], \"included\": 1}]}", 1, 75,
          "'included' must be true or false" },
    };
    wc_foreign_t F;
    wc_error_t err;
    size_t i;

    wc_foreign_init(F);
    wc_error_init(err);
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
    {
        int status = wc_foreign_parse(F, cases[i].text, strlen(cases[i].text),
                                      "c.json", err);

        if (cases[i].message == NULL ? status != WC_OK
            : status != WC_EINPUT || err->line != cases[i].line
              || err->col != cases[i].col
              || strcmp(err->message, cases[i].message) != 0
              || F->nreps != 0)
            wctest_fail("json keys %ld: status %d at %ld:%ld '%s'", (long) i,
                        status, err->line, err->col,
                        status == WC_OK ? "" : err->message);
    }
    wc_error_clear(err);
    wc_foreign_clear(F);
}

int
main(void)
{
    wctest_init("t-compare");
    hand_angles();
    hand_distances();
    reader();
    reader_blocks();
    reader_json_keys();
    random_distances();
    flint_cleanup_master();
    return 0;
}
