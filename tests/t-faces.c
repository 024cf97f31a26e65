/* t-faces.c -- the certificate checker's moving faces: the same set as
   the independent reference ref-faces.c (the faces of the arrangement by
   symbolic perturbation, ref-cells.c) and as the previous brute-force
   walk old-faces.c (a regression check), at a cost linear in the fixels.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   1. Hand-made layouts that give the cone of moving directions each of
      its shapes ({0}, a ray, a line, a wedge, a half-plane, a plane, a
      half-space, a wedge times a line, a pointed cone), with many fixels
      on one face: exact sets, and the same as ref-faces.c and
      old-faces.c.
   2. Random problems (tests/testutil.c, degenerate layouts included) and
      wc_random_problem --degenerate, near fixels made touching or not:
      _wc_check_moving_faces equals ref_faces_moving and
      old_moving_faces.
   3. Cost: on 3,000 fixels the walk's count of products stays below a
      linear bound, and wc_verify checks a 3,000-fixel strongly stable
      certificate with no faces under a 20-second CPU limit (the walk
      before it took minutes).  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "wrenchcone.h"
#include "check/checker.h"
#include "check/faces.h"
#include "check/verify.h"
#include "old-faces.h"
#include "ref-faces.h"
#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Problems.                                                           */

static void
problem_new(wc_check_problem * C, size_t n)
{
    _wc_check_problem_init(C);
    C->n = n;
    C->body = _wc_check_qvec_new(4);
    C->fixel = _wc_check_qvec_new(6 * n);
    C->near = calloc(n > 0 ? n : 1, sizeof(int));
    if (C->body == NULL || C->fixel == NULL || C->near == NULL)
        wctest_fail("out of memory");
    mpq_set_ui(C->body[0], 1, 1);
    mpq_set_ui(C->body[1], 1, 1);
}

/* Fixel i: point (x, y), normal (nx, ny), mu_s = mu_k = 1/2.  */
static void
fixel_set(wc_check_problem * C, size_t i, long x, long y, long nx, long ny,
          int near)
{
    mpq_t * f = C->fixel + 6 * i;

    mpq_set_si(f[0], x, 1);
    mpq_set_si(f[1], y, 1);
    mpq_set_si(f[2], nx, 1);
    mpq_set_si(f[3], ny, 1);
    mpq_set_ui(f[4], 1, 2);
    mpq_set_ui(f[5], 1, 2);
    C->near[i] = near;
}

static void
from_problem(wc_check_problem * C, const wc_problem_struct * P,
             int all_touching)
{
    slong i;
    int j;

    problem_new(C, (size_t) P->n);
    fmpq_get_mpq(C->body[0], P->mass);
    fmpq_get_mpq(C->body[1], P->inertia);
    fmpq_get_mpq(C->body[2], P->com);
    fmpq_get_mpq(C->body[3], P->com + 1);
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        for (j = 0; j < 2; j++)
        {
            fmpq_get_mpq(C->fixel[6 * i + j], f->point + j);
            fmpq_get_mpq(C->fixel[6 * i + 2 + j], f->normal + j);
        }
        fmpq_get_mpq(C->fixel[6 * i + 4], f->mu_s);
        fmpq_get_mpq(C->fixel[6 * i + 5], f->mu_k);
        C->near[i] = !all_touching && f->state == WC_NEAR;
    }
}

static mpq_t *
jacobian(const wc_check_problem * C)
{
    mpq_t * J = _wc_check_qvec_new(6 * C->n);
    size_t i;

    if (J == NULL)
        wctest_fail("out of memory");
    for (i = 0; i < C->n; i++)
        _wc_check_jacobian(J + 6 * i, C, i);
    return J;
}

/* ------------------------------------------------------------------ */
/* The comparison.                                                     */

static void
write_problem(const wc_check_problem * C)
{
    size_t i;
    int j;

    fprintf(stderr, "com %s %s\n", mpq_get_str(NULL, 10, C->body[2]),
            mpq_get_str(NULL, 10, C->body[3]));
    for (i = 0; i < C->n; i++)
    {
        fprintf(stderr, "fixel");
        for (j = 0; j < 4; j++)
            fprintf(stderr, " %s",
                    mpq_get_str(NULL, 10, C->fixel[6 * i + j]));
        fprintf(stderr, " %s\n", C->near[i] ? "near" : "touching");
    }
}

/* The set of the fast walk, checked against ref_faces_moving and
   old_moving_faces; returned (the caller clears it).  */
static wc_check_strings
compare(const char * what, const wc_check_problem * C)
{
    wc_check_strings T = { 0, 0, NULL, 0, 0 }, R = { 0, 0, NULL, 0, 0 };
    mpq_t * J = jacobian(C);
    char ** ind = NULL;
    size_t k, nind = 0;

    if (_wc_check_moving_faces(&T, C, J) != WC_OK)
    {
        write_problem(C);
        wctest_fail("%s: _wc_check_moving_faces failed", what);
    }
    if (ref_faces_moving(&ind, &nind, C) != 0)
        wctest_fail("%s: ref_faces_moving failed", what);
    for (k = 0; k < T.count || k < nind; k++)
        if (k >= T.count || k >= nind || strcmp(T.s[k], ind[k]) != 0)
        {
            write_problem(C);
            wctest_fail("%s: %lu faces, ref-faces.c %lu; first difference "
                        "at %lu: %s, the reference %s", what,
                        (unsigned long) T.count, (unsigned long) nind,
                        (unsigned long) k, k < T.count ? T.s[k] : "-",
                        k < nind ? ind[k] : "-");
        }
    ref_faces_free(ind, nind);
    if (old_moving_faces(&R, C, J) != WC_OK)
        wctest_fail("%s: old_moving_faces failed", what);
    for (k = 0; k < T.count || k < R.count; k++)
        if (k >= T.count || k >= R.count || strcmp(T.s[k], R.s[k]) != 0)
        {
            write_problem(C);
            wctest_fail("%s: %lu faces, the reference %lu; first "
                        "difference at %lu: %s, the reference %s", what,
                        (unsigned long) T.count, (unsigned long) R.count,
                        (unsigned long) k, k < T.count ? T.s[k] : "-",
                        k < R.count ? R.s[k] : "-");
        }
    _wc_check_strings_clear(&R);
    _wc_check_qvec_free(J, 6 * C->n);
    return T;
}

/* compare, and the set is exactly the count strings of want.  */
static void
expect(const char * what, const wc_check_problem * C,
       const char * const * want, size_t count)
{
    wc_check_strings T = compare(what, C);
    size_t k;

    if (T.count != count)
        wctest_fail("%s: %lu faces, not %lu", what,
                    (unsigned long) T.count, (unsigned long) count);
    for (k = 0; k < count; k++)
        if (strcmp(T.s[k], want[k]) != 0)
            wctest_fail("%s: face %lu is %s, not %s", what,
                        (unsigned long) k, T.s[k], want[k]);
    _wc_check_strings_clear(&T);
}

/* ------------------------------------------------------------------ */
/* 1. The shapes of the cone.                                          */

/* compare only */
static void
same(const char * what, const wc_check_problem * C)
{
    wc_check_strings T = compare(what, C);

    _wc_check_strings_clear(&T);
}

static void
test_shapes(void)
{
    wc_check_problem C;
    static const char * const one[] = { "l", "r", "s" };
    static const char * const opposed[] = {
        "ll", "ln", "lr", "nl", "nr", "rl", "rn", "rr"
    };
    static const char * const table[] = {
        "lll", "lss", "nss", "rrr", "rss", "ssl", "ssn", "ssr", "sss"
    };
    size_t i;

    /* one fixel: a half-space */
    problem_new(&C, 1);
    fixel_set(&C, 0, 0, -1, 0, 1, 0);
    expect("one fixel", &C, one, 3);
    _wc_check_problem_clear(&C);

    /* a fixel and its opposite on one line through the centre: the
       plane vy = 0 */
    problem_new(&C, 2);
    fixel_set(&C, 0, 0, -1, 0, 1, 0);
    fixel_set(&C, 1, 0, 1, 0, -1, 0);
    expect("opposed", &C, opposed, 8);
    _wc_check_problem_clear(&C);

    /* a table under three points: the wedge vy >= |w| times the line of
       vx */
    problem_new(&C, 3);
    for (i = 0; i < 3; i++)
        fixel_set(&C, i, (long) i - 1, -1, 0, 1, 0);
    expect("table", &C, table, 9);
    _wc_check_problem_clear(&C);

    /* a box held at two corners above, two below and the middle of both
       sides: {0}; without the sides, the line of vx; the corners held
       sideways: the pointed cone w >= |vx|, |vy| */
    problem_new(&C, 6);
    fixel_set(&C, 0, 1, -1, 0, 1, 0);
    fixel_set(&C, 1, -1, -1, 0, 1, 0);
    fixel_set(&C, 2, 1, 1, 0, -1, 0);
    fixel_set(&C, 3, -1, 1, 0, -1, 0);
    fixel_set(&C, 4, -1, 0, 1, 0, 0);
    fixel_set(&C, 5, 1, 0, -1, 0, 0);
    expect("box", &C, NULL, 0);
    C.near[4] = C.near[5] = 1;
    same("box without sides", &C);
    fixel_set(&C, 1, -1, 1, 0, -1, 0);
    fixel_set(&C, 2, -1, -1, 1, 0, 0);
    fixel_set(&C, 3, 1, 1, -1, 0, 0);
    same("box turning", &C);
    _wc_check_problem_clear(&C);

    /* many fixels on one face: five under the body at the same x (their
       J_in coincide), one pushing from the side; and all at one point
       (the rotation about it moves none of them) */
    problem_new(&C, 6);
    for (i = 0; i < 5; i++)
        fixel_set(&C, i, 1, -1 - (long) i, 0, 1, 0);
    fixel_set(&C, 5, 2, 0, -1, 0, 0);
    same("stacked", &C);
    for (i = 0; i < 6; i++)
        fixel_set(&C, i, 1, 1, i % 3 == 0 ? 1 : -1, (long) i - 2, 0);
    same("one point", &C);
    _wc_check_problem_clear(&C);
}

/* ------------------------------------------------------------------ */
/* 2. Random problems.                                                 */

static void
random_problem(wc_problem_t P)
{
    wc_random_options opt;
    wc_error_t e;
    static const wc_shape_kind shapes[] = {
        WC_SHAPE_NONE, WC_SHAPE_DISK, WC_SHAPE_POLYGON
    };

    if (wctest_chance(1, 2))
    {
        wctest_random_problem(P, 1, 10);
        return;
    }
    wc_random_options_init(&opt);
    opt.fixels = wctest_randint(1, 24);
    opt.seed = wctest_rand();
    opt.degenerate = wctest_chance(3, 4);
    opt.shape = shapes[wctest_randint(0, 2)];
    wc_error_init(e);
    if (wc_random_problem(P, &opt, e) != WC_OK)
        wctest_fail("wc_random_problem failed");
    wc_error_clear(e);
    wc_random_options_clear(&opt);
}

static void
test_random(void)
{
    slong it, iters = wctest_iters(400);

    for (it = 0; it < iters; it++)
    {
        wc_problem_t P;
        wc_check_problem C;

        if (!wctest_iter(it))
            continue;
        wc_problem_init(P);
        random_problem(P);
        from_problem(&C, P, wctest_chance(1, 2));
        same("random", &C);
        _wc_check_problem_clear(&C);
        wc_problem_clear(P);
    }
}

/* ------------------------------------------------------------------ */
/* 3. The cost.                                                        */

#define BIG 3000

/* The products the walk computed on C, which must give count faces.  */
static unsigned long
work_of(const char * what, const wc_check_problem * C, size_t count)
{
    wc_check_strings T = { 0, 0, NULL, 0, 0 };
    mpq_t * J = jacobian(C);
    unsigned long work;

    if (_wc_check_moving_faces(&T, C, J) != WC_OK)
        wctest_fail("%s: _wc_check_moving_faces failed", what);
    if (T.count != count)
        wctest_fail("%s: %lu faces, not %lu", what, (unsigned long) T.count,
                    (unsigned long) count);
    work = T.work;
    _wc_check_strings_clear(&T);
    _wc_check_qvec_free(J, 6 * C->n);
    return work;
}

/* Three random problems of 1,000 fixels each (seeds 3, 4, 5; the second
   degenerate), every fixel touching, about the first one's centre.  */
static void
big_random(wc_check_problem * C)
{
    wc_check_problem part;
    uint64_t seed;
    size_t k = 0, i;
    int j;

    problem_new(C, BIG);
    for (seed = 3; seed <= 5; seed++)
    {
        wc_random_options opt;
        wc_problem_t P;
        wc_error_t e;

        wc_random_options_init(&opt);
        opt.fixels = BIG / 3;
        opt.seed = seed;
        opt.degenerate = seed == 4;
        wc_problem_init(P);
        wc_error_init(e);
        if (wc_random_problem(P, &opt, e) != WC_OK)
            wctest_fail("wc_random_problem failed");
        from_problem(&part, P, 1);
        if (seed == 3)
            for (j = 0; j < 4; j++)
                mpq_set(C->body[j], part.body[j]);
        for (i = 0; i < part.n; i++, k++)
            for (j = 0; j < 6; j++)
                mpq_set(C->fixel[6 * k + j], part.fixel[6 * i + j]);
        _wc_check_problem_clear(&part);
        wc_problem_clear(P);
        wc_error_clear(e);
        wc_random_options_clear(&opt);
    }
}

static void
put(char ** s, size_t * len, size_t * cap, const char * t)
{
    size_t n = strlen(t);

    if (*len + n + 1 > *cap)
    {
        *cap = 2 * (*len + n + 1);
        *s = realloc(*s, *cap);
        if (*s == NULL)
            wctest_fail("out of memory");
    }
    memcpy(*s + *len, t, n + 1);
    *len += n;
}

static void
putq(char ** s, size_t * len, size_t * cap, const mpq_t q)
{
    char * t = mpq_get_str(NULL, 10, q);

    put(s, len, cap, "\"");
    put(s, len, cap, t);
    put(s, len, cap, "\"");
    free(t);
}

/* The certificate that the wrench -J_1n is strongly stable with no
   moving face: static forces c_1n = 1, nothing else.  */
static char *
big_certificate(const wc_check_problem * C, size_t * len)
{
    char * s = NULL;
    size_t cap = 0, i;
    mpq_t J[6];
    int j;

    *len = 0;
    put(&s, len, &cap, "{\"kind\": \"strong-stability\", \"problem\": "
        "{\"mass\": ");
    putq(&s, len, &cap, C->body[0]);
    put(&s, len, &cap, ", \"inertia\": ");
    putq(&s, len, &cap, C->body[1]);
    put(&s, len, &cap, ", \"com\": [");
    putq(&s, len, &cap, C->body[2]);
    put(&s, len, &cap, ", ");
    putq(&s, len, &cap, C->body[3]);
    put(&s, len, &cap, "], \"fixels\": [");
    for (i = 0; i < C->n; i++)
    {
        const mpq_t * f = C->fixel + 6 * i;

        put(&s, len, &cap, i > 0 ? ",\n{\"point\": [" : "\n{\"point\": [");
        putq(&s, len, &cap, f[0]);
        put(&s, len, &cap, ", ");
        putq(&s, len, &cap, f[1]);
        put(&s, len, &cap, "], \"normal\": [");
        putq(&s, len, &cap, f[2]);
        put(&s, len, &cap, ", ");
        putq(&s, len, &cap, f[3]);
        put(&s, len, &cap, "], \"state\": \"touching\", \"mu_s\": ");
        putq(&s, len, &cap, f[4]);
        put(&s, len, &cap, ", \"mu_k\": ");
        putq(&s, len, &cap, f[5]);
        put(&s, len, &cap, "}");
    }
    put(&s, len, &cap, "]},\n\"wrench\": [");
    for (j = 0; j < 6; j++)
        mpq_init(J[j]);
    _wc_check_jacobian(J, C, 0);
    for (j = 0; j < 3; j++)
    {
        mpq_neg(J[j], J[j]);
        put(&s, len, &cap, j > 0 ? ", " : "");
        putq(&s, len, &cap, J[j]);
    }
    for (j = 0; j < 6; j++)
        mpq_clear(J[j]);
    put(&s, len, &cap, "],\n\"weakly_stable\": true, \"weak\": {\"c\": "
        "[\"1\"");
    for (i = 1; i < 2 * C->n; i++)
        put(&s, len, &cap, ", \"0\"");
    put(&s, len, &cap, "]},\n\"strongly_stable\": true, \"faces\": []}\n");
    return s;
}

static void
test_cost(void)
{
    wc_check_problem C;
    unsigned long work;
    int holds;
    char * reason = NULL, * summary = NULL, * text;
    const char * tail = ": 0 moving faces excluded";
    size_t i, len;
    wc_error_t e;

    /* the table under BIG points: the 9 faces of the table above */
    problem_new(&C, BIG);
    for (i = 0; i < BIG; i++)
        fixel_set(&C, i, (long) i - BIG / 2, -1, 0, 1, 0);
    work = work_of("big table", &C, 9);
    if (work > 40 * (unsigned long) BIG)
        wctest_fail("big table: %lu products, more than 40 per fixel", work);
    _wc_check_problem_clear(&C);

    /* a random grasp of BIG fixels: no moving face */
    big_random(&C);
    work = work_of("big random", &C, 0);
    if (work > 40 * (unsigned long) BIG)
        wctest_fail("big random: %lu products, more than 40 per fixel",
                    work);
    text = big_certificate(&C, &len);
    wc_error_init(e);
    if (wc_verify(&holds, &reason, &summary, text, len, "big", e) != WC_OK)
        wctest_fail("big certificate: %s", wc_error_format(e));
    if (holds != 1 || summary == NULL || strlen(summary) < strlen(tail)
        || strcmp(summary + strlen(summary) - strlen(tail), tail) != 0)
        wctest_fail("big certificate: holds %d, %s, %s", holds,
                    summary != NULL ? summary : "-",
                    reason != NULL ? reason : "-");
    wc_error_clear(e);
    free(reason);
    free(summary);
    free(text);
    _wc_check_problem_clear(&C);
}

int
main(void)
{
    struct rlimit rl;

    wctest_init("t-faces");
    /* the walk before the cone took minutes on test_cost: stop it */
    if (getrlimit(RLIMIT_CPU, &rl) == 0
        && (rl.rlim_max == RLIM_INFINITY || rl.rlim_max > 60))
    {
        rl.rlim_cur = 60;
        setrlimit(RLIMIT_CPU, &rl);
    }
    test_shapes();
    test_random();
    test_cost();
    flint_cleanup_master();     /* ref-faces.c's integers */
    return 0;
}
