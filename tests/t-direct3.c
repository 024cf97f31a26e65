/* t-direct3.c -- the direct route's fast path (lib/analysis/direct3.c)
   against the general direct route it short-cuts.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The general route (_wc_wrench_cone_direct_general: J, M and the
   friction edges as rational matrices, wc_cone_set_hrep and
   wc_cone_image_sum) stays in the library as the reference.  For random
   problems (wctest_random_problem's degenerate layouts: parallel and
   opposed normals, coincident and collinear points, normals through one
   point, zero and per-fixel friction, near fixels), for fixels on a
   circle with normals through its centre (V_x on a line), for collinear
   fixels with parallel normals, coincident fixels with opposite normals
   and zero friction, all of them also with numbers past a word, and for
   random and uniform modes (n = 1 included): the fast path,
   where it answers, and wc_wrench_cone_direct give the cone of the
   general route, field for field and byte for byte in JSON, with the same
   status.  _wc_cone3_set_line (the canonical line the fast path writes
   for the modes of s letters around the part) is compared with the
   general conversion of that line.  A quarter of the problems get
   numbers past a word (big_numbers), for the fmpz side of every 128-bit
   shortcut in direct3.c.  The fast path must answer for at least a
   quarter of the cones (it answers about half of them) or the test
   fails.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "testutil.h"
#include "analysis/direct3.h"
#include "exact/cone3.h"

/* Compare the three answers for P and mode; returns whether the fast
   path answered.  */
static int
check(const wc_problem_t P, const char * mode)
{
    wc_cone_t A, B, C;
    wc_error_t ea, eb, ec;
    int sa, sb, sc, done;
    char * ja, * jb;

    wc_cone_init(A, 3);
    wc_cone_init(B, 3);
    wc_cone_init(C, 3);
    wc_error_init(ea);
    wc_error_init(eb);
    wc_error_init(ec);
    sb = _wc_wrench_cone_direct_general(B, NULL, P, mode, eb);
    sc = wc_wrench_cone_direct(C, NULL, P, mode, ec);
    if (sb != sc)
        wctest_fail_problem(P, mode, "status %d, general route %d", sc, sb);
    if (!wc_cone_equal(B, C))
        wctest_fail_problem(P, mode, "wc_wrench_cone_direct differs from "
                            "the general route");
    done = 0;
    if (sb == WC_OK)
    {
        sa = _wc_wrench_cone_direct3(A, &done, P, mode, ea);
        if (sa != WC_OK)
            wctest_fail_problem(P, mode, "fast path status %d", sa);
        if (done && !wc_cone_equal(A, B))
            wctest_fail_problem(P, mode, "the fast path differs from the "
                                "general route");
        if (!done && !A->empty)
            wctest_fail_problem(P, mode, "the fast path gave up but left "
                                "a nonempty cone");
        ja = wctest_cone_json(C);
        jb = wctest_cone_json(B);
        if (strcmp(ja, jb) != 0)
            wctest_fail_problem(P, mode, "JSON differs:\n%s\n%s", ja, jb);
        free(ja);
        free(jb);
    }
    wc_cone_clear(A);
    wc_cone_clear(B);
    wc_cone_clear(C);
    wc_error_clear(ea);
    wc_error_clear(eb);
    wc_error_clear(ec);
    return done;
}

/* One letter for every touching fixel (near ones: s, a or u).  */
static void
uniform_mode(char * mode, const wc_problem_t P, char x)
{
    slong i;

    for (i = 0; i < P->n; i++)
        mode[i] = P->fixels[i].state == WC_TOUCHING ? x
            : "sau"[wctest_randint(0, 2)];
    mode[P->n] = '\0';
}

/* n touching fixels at rational points of the unit circle, normals
   toward the centre (or away from it), friction mu (maybe 0).  */
static void
circle_problem(wc_problem_t P, slong n, int out, slong mu)
{
    slong k;
    fmpq_t t, d;

    fmpq_init(t);
    fmpq_init(d);
    fmpq_set_si(P->mu_s, mu, 5);
    fmpq_set_si(P->mu_k, mu, 10);
    fmpq_set_si(P->com + 0, wctest_randint(-3, 3), 7);
    fmpq_set_si(P->com + 1, wctest_randint(-3, 3), 9);
    for (k = 0; k < n; k++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);
        slong a = wctest_randint(-20, 20), b = wctest_randint(1, 20);

        /* ((b^2 - a^2), 2ab) / (a^2 + b^2) */
        fmpq_set_si(d, a * a + b * b, 1);
        fmpq_set_si(t, b * b - a * a, 1);
        fmpq_div(f->point + 0, t, d);
        fmpq_set_si(t, 2 * a * b, 1);
        fmpq_div(f->point + 1, t, d);
        if (wctest_chance(1, 4))
            fmpq_neg(f->point + 0, f->point + 0);
        fmpq_set(f->normal + 0, f->point + 0);
        fmpq_set(f->normal + 1, f->point + 1);
        if (!out)
        {
            fmpq_neg(f->normal + 0, f->normal + 0);
            fmpq_neg(f->normal + 1, f->normal + 1);
        }
        f->state = WC_TOUCHING;
    }
    fmpq_clear(t);
    fmpq_clear(d);
}

/* Collinear fixels with parallel (or opposite) normals, some of them
   coincident, friction maybe 0.  */
static void
line_problem(wc_problem_t P, slong n)
{
    slong k, mu = wctest_randint(0, 2);

    fmpq_set_si(P->mu_s, mu, 3);
    fmpq_set_si(P->mu_k, mu, 4);
    for (k = 0; k < n; k++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);

        fmpq_set_si(f->point + 0, wctest_randint(-2, 2), 1);
        fmpq_set_si(f->normal + 1, wctest_chance(1, 3) ? -2 : 3, 1);
        if (wctest_chance(1, 5))
            fmpq_set_si(f->normal + 0, 1, 2);
        f->state = WC_TOUCHING;
    }
}

/* One sliding fixel whose friction edge lies in the plane M V_x: with
   n = (0, 1), r = p - com = (1, y), I = m and mu_k = 1/2, the edge's
   component across that plane is a multiple of 2 +- y / 2, zero for
   y = -+4.  Both slide directions and both signs of y, so that the edge
   lies in the plane on either side of the open half-plane, and off it;
   other fixels unconstrained (u) or none.  */
static void
check_in_plane(void)
{
    slong y, k, extra;
    char mode[4];

    for (y = -4; y <= 4; y += 8)
        for (k = 0; k < 2; k++)
            for (extra = 0; extra < 2; extra++)
            {
                wc_problem_t P;
                wc_fixel_struct * f;

                wc_problem_init(P);
                fmpq_set_si(P->mu_s, 1, 2);
                fmpq_set_si(P->mu_k, 1, 2);
                fmpq_set_si(P->mass, 3, 1);
                fmpq_set_si(P->inertia, 3, 1);
                fmpq_set_si(P->com + 0, 1, 3);
                fmpq_set_si(P->com + 1, -2, 5);
                f = wc_problem_add_fixel(P);
                fmpq_set_si(f->point + 0, 4, 3);
                fmpq_set_si(f->point + 1, 5 * y - 2, 5);
                fmpq_set_si(f->normal + 1, 1, 1);
                f->state = WC_TOUCHING;
                mode[0] = "lr"[k];
                mode[1] = '\0';
                if (extra)
                {
                    f = wc_problem_add_fixel(P);
                    fmpq_set_si(f->point + 0, 1, 1);
                    fmpq_set_si(f->normal + 0, 1, 1);
                    f->state = WC_NEAR;
                    mode[1] = 'u';
                    mode[2] = '\0';
                }
                if (!check(P, mode))
                    wctest_fail_problem(P, mode, "the fast path gave up");
                wc_problem_clear(P);
            }
}

/* x := x (2^e + a) / (2^e + b) for a, b in [1, 9]: the same sign, and
   numerators and denominators about 2^e.  */
static void
inflate(fmpq_t x, slong e)
{
    fmpz_t p, q;

    fmpz_init(p);
    fmpz_init(q);
    fmpz_one(p);
    fmpz_mul_2exp(p, p, e);
    fmpz_add_ui(q, p, wctest_randint(1, 9));
    fmpz_add_ui(p, p, wctest_randint(1, 9));
    fmpz_mul(fmpq_numref(x), fmpq_numref(x), p);
    fmpz_mul(fmpq_denref(x), fmpq_denref(x), q);
    fmpq_canonicalise(x);
    fmpz_clear(p);
    fmpz_clear(q);
}

/* Numbers past a word, or whose products are: the points and the centre
   of mass scaled by one factor (collinear points stay collinear), each
   normal by its own positive factor (same direction), the friction
   coefficients, mass and inertia by theirs, with numerators and
   denominators of about 2^e, e in [10, 100] (the 128-bit paths of
   direct3.c give up somewhere in between).  */
static void
big_numbers(wc_problem_t P)
{
    slong e = wctest_randint(10, 100), i, j;
    fmpq_t s, t;

    fmpq_init(s);
    fmpq_init(t);
    fmpq_one(s);
    inflate(s, e);
    for (j = 0; j < 2; j++)
        fmpq_mul(P->com + j, P->com + j, s);
    for (i = 0; i < P->n; i++)
    {
        wc_fixel_struct * f = P->fixels + i;

        for (j = 0; j < 2; j++)
            fmpq_mul(f->point + j, f->point + j, s);
        fmpq_one(t);
        if (wctest_chance(1, 2))
            inflate(t, e);
        for (j = 0; j < 2; j++)
            fmpq_mul(f->normal + j, f->normal + j, t);
    }
    if (wctest_chance(1, 2))
    {
        fmpq_one(t);
        inflate(t, e);
        fmpq_mul(P->mu_s, P->mu_s, t);
        fmpq_mul(P->mu_k, P->mu_k, t);
        inflate(P->mass, e);
        inflate(P->inertia, e);
    }
    fmpq_clear(s);
    fmpq_clear(t);
}

/* _wc_cone3_set_line against the general conversion of one line, for
   vectors with zero, negative and non-coprime entries.  */
static void
check_line(void)
{
    fmpz v[3];
    fmpq_mat_t L;
    wc_cone_t A, B;
    wc_error_t err;
    slong j;

    fmpq_mat_init(L, 1, 3);
    wc_cone_init(A, 3);
    wc_cone_init(B, 3);
    wc_error_init(err);
    for (j = 0; j < 3; j++)
    {
        fmpz_init(v + j);
        fmpz_set_si(v + j, wctest_chance(1, 3) ? 0
                    : 6 * wctest_randint(-4, 4) + wctest_randint(-2, 2));
    }
    if (fmpz_is_zero(v + 0) && fmpz_is_zero(v + 1) && fmpz_is_zero(v + 2))
        fmpz_set_si(v + wctest_randint(0, 2), -12);
    for (j = 0; j < 3; j++)
        fmpq_set_fmpz(fmpq_mat_entry(L, 0, j), v + j);
    _wc_cone3_set_line(A, v);
    if (wc_cone_set_generators(B, NULL, L, err) != WC_OK)
        wctest_fail("wc_cone_set_generators: %s", err->message);
    if (!wc_cone_equal(A, B))
    {
        char * ja = wctest_cone_json(A), * jb = wctest_cone_json(B);

        wctest_fail("the line (%ld, %ld, %ld):\n%s\n%s",
                    (long) fmpz_get_si(v + 0), (long) fmpz_get_si(v + 1),
                    (long) fmpz_get_si(v + 2), ja, jb);
    }
    for (j = 0; j < 3; j++)
        fmpz_clear(v + j);
    fmpq_mat_clear(L);
    wc_cone_clear(A);
    wc_cone_clear(B);
    wc_error_clear(err);
}

int
main(void)
{
    static const char letters[] = "slrnm";
    slong i, iters, fast = 0, total = 0;
    char mode[64];

    wctest_init("t-direct3");
    check_in_plane();
    iters = wctest_iters(1500);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;
        slong kind = i % 5;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        if (kind <= 1)
            wctest_random_problem(P, 1, kind == 0 ? 4 : 9);
        else if (kind == 2)
            circle_problem(P, wctest_randint(1, 12), wctest_chance(1, 4),
                           wctest_randint(0, 2));
        else if (kind == 3)
            line_problem(P, wctest_randint(1, 8));
        else
            wctest_random_problem(P, 2, 6);
        if (wctest_chance(1, 4))
            big_numbers(P);
        if (wctest_chance(1, 2))
            wctest_random_mode(mode, P);
        else
            uniform_mode(mode, P, letters[wctest_randint(0, 4)]);
        fast += check(P, mode);
        check_line();
        total++;
        wc_problem_clear(P);
    }
    if (total >= 100 && fast * 4 < total)
        wctest_fail("the fast path answered only %ld of %ld cones",
                    (long) fast, (long) total);
    flint_cleanup_master();
    return 0;
}
