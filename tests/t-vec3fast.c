/* t-vec3fast.c -- the word paths of exact/vec3.c and of the set-up of a
   canonical 3-D cone against the plain fmpz arithmetic.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The references below (ref_cross, ref_dot, ref_primitive) are the
   deliberate independent copies of the fmpz arithmetic the fast paths
   replace: plain fmpz_mul and fmpz_submul, and the content by fmpz_gcd;
   check_sqmul's reference is plain fmpz_mul and fmpz_cmp.  The line's
   canonical vector is checked against the primitive one turned by its
   first nonzero entry, and the primitive vector of a rational vector
   against the one of its numerators times the product of all the
   denominators (not their lcm).
   Entries are drawn of every size: zero, tiny, up to the largest word
   fmpz (2^62 - 1), just past it, and far past a word; vectors repeat,
   negate, scale and share entries (degenerate cross products: zero,
   parallel).  Then the canonical 3-D cone set into a cone that already
   holds an answer (cone3.c keeps its arrays when the shape allows) against
   the same cone set into a fresh one: the same JSON, byte for byte.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "testutil.h"
#include "exact/vec3.h"
#include "exact/cone.h"
#include "exact/cone3.h"

/* x := a random integer of a random size.  */
static void
rand_entry(fmpz_t x)
{
    switch (wctest_randint(0, 6))
    {
    case 0:
        fmpz_zero(x);
        break;
    case 1:
        fmpz_set_si(x, wctest_randint(-3, 3));
        break;
    case 2:
        fmpz_set_si(x, wctest_randint(-(WORD(1) << 30), WORD(1) << 30));
        break;
    case 3:     /* the largest word fmpz and its neighbours */
        fmpz_set_si(x, COEFF_MAX - wctest_randint(0, 2));
        fmpz_add_si(x, x, wctest_randint(0, 2));
        break;
    case 4:
        fmpz_set_ui(x, wctest_rand() >> wctest_randint(0, 63));
        break;
    default:    /* past a word */
        fmpz_set_ui(x, wctest_rand());
        fmpz_mul_2exp(x, x, wctest_randint(0, 100));
        fmpz_add_ui(x, x, wctest_rand() >> 32);
        break;
    }
    if (wctest_chance(1, 2))
        fmpz_neg(x, x);
}

static void
rand_vec(fmpz * v, const fmpz * other)
{
    slong j;

    for (j = 0; j < 3; j++)
        rand_entry(v + j);
    switch (wctest_randint(0, 7))
    {
    case 0:                     /* repeated */
        _fmpz_vec_set(v, other, 3);
        break;
    case 1:                     /* opposite */
        _fmpz_vec_neg(v, other, 3);
        break;
    case 2:                     /* parallel */
        _fmpz_vec_scalar_mul_si(v, other, 3, wctest_randint(-5, 5));
        break;
    case 3:                     /* one shared entry */
        fmpz_set(v + wctest_randint(0, 2), other + wctest_randint(0, 2));
        break;
    default:
        break;
    }
}

static void
ref_cross(fmpz * c, const fmpz * a, const fmpz * b)
{
    slong j;

    for (j = 0; j < 3; j++)
    {
        fmpz_mul(c + j, a + (j + 1) % 3, b + (j + 2) % 3);
        fmpz_submul(c + j, a + (j + 2) % 3, b + (j + 1) % 3);
    }
}

static void
ref_dot(fmpz_t r, const fmpz * a, const fmpz * b)
{
    slong j;

    fmpz_zero(r);
    for (j = 0; j < 3; j++)
        fmpz_addmul(r, a + j, b + j);
}

static void
ref_primitive(fmpz * h)
{
    fmpz_t g;
    slong j;

    fmpz_init(g);
    for (j = 0; j < 3; j++)
        fmpz_gcd(g, g, h + j);
    if (!fmpz_is_zero(g))
        for (j = 0; j < 3; j++)
            fmpz_divexact(h + j, h + j, g);
    fmpz_clear(g);
}

/* _wc_zvec3_canonical of a multiple of the primitive vector h.  */
static void
check_canonical(const fmpz * h)
{
    fmpz * v = _fmpz_vec_init(3), * w = _fmpz_vec_init(3);
    fmpz_t t;
    slong j, s = wctest_randint(-9, 9);
    int got, want;

    fmpz_init(t);
    _fmpz_vec_scalar_mul_si(v, h, 3, s == 0 ? 1 : s);
    _fmpz_vec_set(w, h, 3);
    for (j = 0; j < 3 && fmpz_is_zero(w + j); j++)
        ;
    want = j == 3 ? 0 : fmpz_sgn(v + j) < 0 ? -1 : 1;
    if (j < 3 && fmpz_sgn(w + j) < 0)
        _fmpz_vec_neg(w, w, 3);
    got = _wc_zvec3_canonical(v, t);
    if (got != want || !_fmpz_vec_equal(v, w, 3))
        wctest_fail("canonical vector differs (%d, the reference %d)", got,
                    want);
    _fmpz_vec_clear(v, 3);
    _fmpz_vec_clear(w, 3);
    fmpz_clear(t);
}

/* _wc_qvec_primitive of the rational vector a / b (b's zero entries taken
   as 1).  */
static void
check_qvec(const fmpz * a, const fmpz * b)
{
    fmpq * x = _fmpq_vec_init(3);
    fmpz * v = _fmpz_vec_init(3), * w = _fmpz_vec_init(3);
    fmpz_t p;
    slong j;

    fmpz_init_set_ui(p, 1);
    for (j = 0; j < 3; j++)
    {
        fmpz_set(fmpq_denref(x + j), b + j);
        if (fmpz_is_zero(b + j))
            fmpz_one(fmpq_denref(x + j));
        fmpz_set(fmpq_numref(x + j), a + j);
        fmpq_canonicalise(x + j);
        fmpz_mul(p, p, fmpq_denref(x + j));
    }
    for (j = 0; j < 3; j++)
    {
        fmpz_divexact(w + j, p, fmpq_denref(x + j));
        fmpz_mul(w + j, w + j, fmpq_numref(x + j));
    }
    ref_primitive(w);
    _wc_qvec_primitive(v, x, 3);
    if (!_fmpz_vec_equal(v, w, 3))
        wctest_fail("primitive vector of a rational vector differs");
    _fmpq_vec_clear(x, 3);
    _fmpz_vec_clear(v, 3);
    _fmpz_vec_clear(w, 3);
    fmpz_clear(p);
}

/* _wc_z_sqmul_cmp against fmpz: random sizes, equal sides, and sides
   one multiplier apart.  */
static void
check_sqmul(void)
{
    fmpz_t a, b, c, d, l, r, x, y;
    slong s;
    int got, want;

    fmpz_init(a);
    fmpz_init(b);
    fmpz_init(c);
    fmpz_init(d);
    fmpz_init(l);
    fmpz_init(r);
    fmpz_init(x);
    fmpz_init(y);
    rand_entry(a);
    rand_entry(b);
    rand_entry(c);
    rand_entry(d);
    if (wctest_chance(3, 4))
        fmpz_abs(b, b);
    if (wctest_chance(3, 4))
        fmpz_abs(d, d);
    switch (wctest_randint(0, 3))
    {
    case 0:                     /* equal: (s a)^2 b against a^2 (s^2 b) */
        s = wctest_randint(-3, 3);
        fmpz_mul_si(c, a, s);
        fmpz_mul_si(d, b, s * s);
        fmpz_swap(a, c);
        fmpz_swap(b, d);
        break;
    case 1:                     /* one apart */
        fmpz_set(c, a);
        fmpz_add_si(d, b, wctest_randint(-1, 1));
        break;
    default:
        break;
    }
    got = _wc_z_sqmul_cmp(a, b, c, d, l, r);
    fmpz_mul(x, a, a);
    fmpz_mul(x, x, b);
    fmpz_mul(y, c, c);
    fmpz_mul(y, y, d);
    want = fmpz_cmp(x, y);
    want = (want > 0) - (want < 0);
    if (got != want)
        wctest_fail("_wc_z_sqmul_cmp: %d, the reference %d", got, want);
    fmpz_clear(a);
    fmpz_clear(b);
    fmpz_clear(c);
    fmpz_clear(d);
    fmpz_clear(l);
    fmpz_clear(r);
    fmpz_clear(x);
    fmpz_clear(y);
}

static void
check_one(void)
{
    fmpz * a = _fmpz_vec_init(3), * b = _fmpz_vec_init(3);
    fmpz * c = _fmpz_vec_init(3), * d = _fmpz_vec_init(3);
    fmpz_t r, s, t;

    fmpz_init(r);
    fmpz_init(s);
    fmpz_init(t);
    rand_vec(a, b);
    rand_vec(b, a);
    _wc_zvec3_cross_fast(c, a, b);
    ref_cross(d, a, b);
    if (!_fmpz_vec_equal(c, d, 3))
        wctest_fail("cross product differs");
    _wc_zvec3_dot_fast(r, a, b);
    ref_dot(s, a, b);
    if (!fmpz_equal(r, s))
        wctest_fail("dot product differs");
    /* The content of a cross product (the fan's facets), and of a vector
       times a small multiplier.  */
    if (wctest_chance(1, 2))
        _fmpz_vec_scalar_mul_si(d, a, 3, wctest_randint(-40, 40));
    _fmpz_vec_set(c, d, 3);
    _wc_zvec3_primitive(c, t);
    ref_primitive(d);
    if (!_fmpz_vec_equal(c, d, 3))
        wctest_fail("primitive vector differs");
    check_canonical(d);
    check_qvec(a, b);
    _fmpz_vec_clear(a, 3);
    _fmpz_vec_clear(b, 3);
    _fmpz_vec_clear(c, 3);
    _fmpz_vec_clear(d, 3);
    fmpz_clear(r);
    fmpz_clear(s);
    fmpz_clear(t);
}

/* G := k random generators (rows), small, mostly in the half-space
   z > 0 (pointed cones of few extreme rays, so that consecutive answers
   often share their shape), sometimes anywhere (R^3, planes, lines).  */
static void
rand_gens(fmpq_mat_t G)
{
    slong k = wctest_randint(0, 9), i, j;
    int half = wctest_chance(4, 5);

    fmpq_mat_clear(G);
    fmpq_mat_init(G, k, 3);
    for (i = 0; i < k; i++)
        for (j = 0; j < 3; j++)
            fmpq_set_si(fmpq_mat_entry(G, i, j),
                        j == 2 && half ? wctest_randint(1, 3)
                        : wctest_randint(-3, 3), 1);
}

/* C := the 3-D cone of G by cone3.c's route (generators, or polar: G
   as the inequalities), or by the library's entry when cone3.c declines;
   by the entry alone when entry.  */
static void
set_cone(wc_cone_t C, const fmpq_mat_t G, int polar, int entry)
{
    wc_error_t err;
    int done = 0, r = WC_OK;

    wc_error_init(err);
    if (!entry)
        r = polar ? _wc_cone3_hrep(C, &done, NULL, G, err)
            : _wc_cone3_generators(C, &done, G, NULL, err);
    if (r == WC_OK && !done)
        r = polar ? wc_cone_set_hrep(C, NULL, G, NULL, err)
            : wc_cone_set_generators(C, G, NULL, err);
    if (r != WC_OK)
        wctest_fail("the cone: %s", err->message);
    wc_error_clear(err);
}

/* The kept cone C gets the cone of a random G, compared with a fresh
   one; sometimes C first gets another answer, by the library's entry.  */
static void
check_reuse(wc_cone_t C)
{
    fmpq_mat_t G;
    wc_cone_t D;
    int polar = wctest_chance(1, 4);
    char * a, * b;

    fmpq_mat_init(G, 0, 3);
    if (wctest_chance(1, 4))
    {
        rand_gens(G);
        set_cone(C, G, wctest_chance(1, 2), 1);
    }
    rand_gens(G);
    wc_cone_init(D, 3);
    set_cone(D, G, polar, 0);
    set_cone(C, G, polar, 0);
    a = wctest_cone_json(C);
    b = wctest_cone_json(D);
    if (strcmp(a, b) != 0)
        wctest_fail("a kept cone differs from a fresh one:\n%s\n%s", a, b);
    free(a);
    free(b);
    wc_cone_clear(D);
    fmpq_mat_clear(G);
}

int
main(void)
{
    slong iters, i;
    wc_cone_t C;

    wctest_init("t-vec3fast");
    iters = wctest_iters(20000);
    for (i = 0; i < iters; i++)
    {
        if (!wctest_iter(i))
            continue;
        check_one();
        check_sqmul();
    }
    wc_cone_init(C, 3);
    iters = wctest_iters(3000);
    for (i = 0; i < iters; i++)
    {
        if (!wctest_iter(i))
            continue;
        check_reuse(C);
    }
    wc_cone_clear(C);
    flint_cleanup_master();
    return 0;
}
