/* testutil.c -- shared infrastructure of the C tests.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The generator is splitmix64 (Steele, Lea and Flood, 2014): one 64-bit
   word of state, so an iteration is replayed by setting that word alone.  */

#include <config.h>

#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/problem.h"
#include "core/randgen.h"
#include "io/print.h"
#include "testutil.h"

/* The options of JSON output (io/print.h).  */
static const wc_print_opts as_json[1] = { { WC_FORMAT_JSON, 0, 0, NULL } };

#define WCTEST_DEFAULT_SEED UINT64_C(20021212)

static const char * test_name = "test";
static uint64_t test_seed = WCTEST_DEFAULT_SEED;
static slong test_multiplier = 1;
static slong test_only_iter = -1;   /* WC_TEST_ITER, -1 when unset */
static slong test_iter = -1;        /* current iteration, -1 outside */
static uint64_t rng_state = WCTEST_DEFAULT_SEED;

static uint64_t
splitmix64(uint64_t * s)
{
    uint64_t z = (*s += UINT64_C(0x9e3779b97f4a7c15));

    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

/* An environment variable as an unsigned integer; exits 99 when it is set
   but not a number in [min, max].  Returns 0 when unset.  */
static int
env_number(uint64_t * value, const char * var, uint64_t min, uint64_t max)
{
    const char * s = getenv(var);
    char * end = NULL;
    unsigned long long v;

    if (s == NULL || *s == '\0')
        return 0;
    errno = 0;
    v = strtoull(s, &end, 0);
    if (errno != 0 || end == s || *end != '\0' || s[0] == '-'
        || v < min || v > max)
    {
        fprintf(stderr, "ERROR [%s]: %s=%s is not an integer in [%" PRIu64
                ", %" PRIu64 "]\n", test_name, var, s, min, max);
        exit(99);
    }
    *value = (uint64_t) v;
    return 1;
}

void
wctest_init(const char * name)
{
    uint64_t v;

    test_name = (name != NULL) ? name : "test";
    test_seed = WCTEST_DEFAULT_SEED;
    test_multiplier = 1;
    test_only_iter = -1;
    test_iter = -1;
    if (env_number(&v, "WC_TEST_SEED", 0, UINT64_MAX))
        test_seed = v;
    if (env_number(&v, "WC_TEST_MULTIPLIER", 1, 1000000))
        test_multiplier = (slong) v;
    if (env_number(&v, "WC_TEST_ITER", 0, WORD_MAX / 2))
        test_only_iter = (slong) v;
    rng_state = test_seed;
}

uint64_t
wctest_seed(void)
{
    return test_seed;
}

slong
wctest_iters(slong base)
{
    slong n = base * test_multiplier;

    if (test_only_iter >= 0 && n <= test_only_iter)
        n = test_only_iter + 1;
    return n;
}

uint64_t
wctest_iter_seed(slong i)
{
    uint64_t s = test_seed ^ (UINT64_C(0x6a09e667f3bcc909) * (uint64_t) (i + 1));

    return splitmix64(&s);
}

int
wctest_iter(slong i)
{
    test_iter = i;
    rng_state = wctest_iter_seed(i);
    return test_only_iter < 0 || test_only_iter == i;
}

uint64_t
wctest_rand(void)
{
    return splitmix64(&rng_state);
}

slong
wctest_randint(slong lo, slong hi)
{
    uint64_t span, threshold, x;

    if (hi < lo)
        wctest_fail("wctest_randint(%ld, %ld): empty range", (long) lo,
                    (long) hi);
    span = (uint64_t) hi - (uint64_t) lo + 1;
    if (span == 0)
        return (slong) wctest_rand();
    /* Reject the lowest 2^64 mod span words, so that every residue is
       equally likely.  */
    threshold = (0 - span) % span;
    do
        x = wctest_rand();
    while (x < threshold);
    return (slong) ((uint64_t) lo + x % span);
}

int
wctest_chance(slong num, slong den)
{
    return wctest_randint(0, den - 1) < num;
}

void
wctest_rand_fmpq(fmpq_t x, slong maxnum, slong maxden)
{
    slong kind = wctest_randint(0, 7);

    if (kind == 0)
        fmpq_zero(x);
    else if (kind <= 3)
        fmpq_set_si(x, wctest_randint(-maxnum, maxnum), 1);
    else
        fmpq_set_si(x, wctest_randint(-maxnum, maxnum),
                    (ulong) wctest_randint(1, maxden));
}

void
wctest_rand_fmpq_pos(fmpq_t x, slong maxnum, slong maxden)
{
    slong den = wctest_chance(1, 3) ? 1 : wctest_randint(1, maxden);

    fmpq_set_si(x, wctest_randint(1, maxnum), (ulong) den);
}

void
wctest_random_wrench(fmpq * g)
{
    slong j, kind = wctest_randint(0, 9);

    for (j = 0; j < 3; j++)
        fmpq_zero(g + j);
    if (kind == 0)
        return;                 /* the apex */
    if (kind <= 2)
    {
        /* a force along an axis, or a pure torque */
        j = wctest_randint(0, 2);
        fmpq_set_si(g + j, wctest_chance(1, 2) ? 1 : -wctest_randint(1, 3),
                    1);
        return;
    }
    for (j = 0; j < 3; j++)
        wctest_rand_fmpq(g + j, 4, 3);
}

static void
fail_header(void)
{
    fflush(stdout);
    if (test_iter >= 0)
        fprintf(stderr, "FAIL [%s] seed=%" PRIu64 " iter=%ld (iter_seed=%"
                PRIu64 "): ", test_name, test_seed, (long) test_iter,
                wctest_iter_seed(test_iter));
    else
        fprintf(stderr, "FAIL [%s] seed=%" PRIu64 ": ", test_name,
                test_seed);
}

static void
fail_footer(void)
{
    if (test_iter >= 0)
        fprintf(stderr, "replay with: WC_TEST_SEED=%" PRIu64
                " WC_TEST_ITER=%ld\n", test_seed, (long) test_iter);
    else
        fprintf(stderr, "replay with: WC_TEST_SEED=%" PRIu64 "\n",
                test_seed);
    fflush(stderr);
}

static int report_count = 0;

void
wctest_report(const char * file, int line, const char * fmt, ...)
{
    va_list ap;

    fprintf(stderr, "%s:%d: ", file, line);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    report_count++;
}

int
wctest_failures(void)
{
    return report_count;
}

void
wctest_fail(const char * fmt, ...)
{
    va_list ap;

    fail_header();
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    fail_footer();
    exit(1);
}

void
wctest_fail_problem(const wc_problem_t P, const char * mode,
                    const char * fmt, ...)
{
    va_list ap;

    fail_header();
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    if (mode != NULL)
        fprintf(stderr, "mode: %s\n", mode);
    fprintf(stderr, "problem:\n");
    if (wc_problem_fprint(stderr, P) != 0)
        fprintf(stderr, "(could not print the problem)\n");
    fail_footer();
    exit(1);
}

char *
wctest_vec_str(const fmpq * v, slong len)
{
    size_t cap = 3, used = 0;
    char * s;
    slong j;

    for (j = 0; j < len; j++)
        cap += fmpz_sizeinbase(fmpq_numref(v + j), 10)
            + fmpz_sizeinbase(fmpq_denref(v + j), 10) + 5;
    s = flint_malloc(cap);
    s[used++] = '(';
    for (j = 0; j < len; j++)
    {
        char * e = fmpq_get_str(NULL, 10, v + j);
        size_t l = strlen(e);

        if (j > 0)
        {
            s[used++] = ',';
            s[used++] = ' ';
        }
        memcpy(s + used, e, l);
        used += l;
        flint_free(e);
    }
    s[used++] = ')';
    s[used] = '\0';
    return s;
}

/* ---- random problems ---------------------------------------------- */

enum
{
    LAYOUT_GENERIC,
    LAYOUT_PARALLEL,        /* all normals parallel, some antiparallel */
    LAYOUT_OPPOSED,         /* pairs of fixels facing each other */
    LAYOUT_COINCIDENT,      /* several fixels at one point */
    LAYOUT_COLLINEAR,       /* all points on one line */
    LAYOUT_CONCURRENT,      /* all normal lines through one point */
    LAYOUT_DISK,            /* rational points of a circle, radial normals */
    LAYOUT_BOX,             /* points on the sides of a square */
    LAYOUT_PAPER,           /* the paper's disk (Sections 4, 7) and more */
    LAYOUT_COUNT
};

/* A positive scale drawn from values that keep vectors small but break
   unit length and primitivity: 1, 2, 3, 1/2, 1/3, 3/2, 7/3, 5.  */
static void
rand_scale(fmpq_t x)
{
    static const slong tab[8][2] =
        {{1, 1}, {2, 1}, {3, 1}, {1, 2}, {1, 3}, {3, 2}, {7, 3}, {5, 1}};
    slong k = wctest_randint(0, 7);

    fmpq_set_si(x, tab[k][0], (ulong) tab[k][1]);
}

static void
rand_point(fmpq * p)
{
    wctest_rand_fmpq(p + 0, 3, 2);
    wctest_rand_fmpq(p + 1, 3, 2);
}

/* A nonzero direction: often an axis or a diagonal, scaled, else random
   small entries; (0, 3), (2, -4), (1/2, 1/3) are all possible.  */
static void
rand_normal(fmpq * d)
{
    slong kind = wctest_randint(0, 3);
    fmpq_t s;

    fmpq_init(s);
    if (kind == 0)
    {
        slong axis = wctest_randint(0, 3);

        fmpq_set_si(d + 0, axis == 0 ? 1 : axis == 2 ? -1 : 0, 1);
        fmpq_set_si(d + 1, axis == 1 ? 1 : axis == 3 ? -1 : 0, 1);
    }
    else if (kind == 1)
    {
        fmpq_set_si(d + 0, wctest_chance(1, 2) ? 1 : -1, 1);
        fmpq_set_si(d + 1, wctest_chance(1, 2) ? 2 : -1, 1);
    }
    else
    {
        do
        {
            wctest_rand_fmpq(d + 0, 3, 3);
            wctest_rand_fmpq(d + 1, 3, 3);
        }
        while (fmpq_is_zero(d + 0) && fmpq_is_zero(d + 1));
    }
    if (wctest_chance(1, 2))
    {
        rand_scale(s);
        fmpq_mul(d + 0, d + 0, s);
        fmpq_mul(d + 1, d + 1, s);
    }
    fmpq_clear(s);
}

/* A friction coefficient: 0, 1/5, 1/2, 1, 2, 5 or a random one.  */
static void
rand_mu(fmpq_t mu)
{
    static const slong tab[6][2] = {{0, 1}, {1, 5}, {1, 2}, {1, 1}, {2, 1},
                                    {5, 1}};
    slong k = wctest_randint(0, 6);

    if (k < 6)
        fmpq_set_si(mu, tab[k][0], (ulong) tab[k][1]);
    else
        wctest_rand_fmpq_pos(mu, 3, 4);
}

/* mu_s and mu_k: usually equal; else mu_k drawn independently (it may
   even exceed mu_s: the model does not forbid it).  */
static void
rand_friction(fmpq_t mu_s, fmpq_t mu_k)
{
    rand_mu(mu_s);
    if (wctest_chance(2, 3))
        fmpq_set(mu_k, mu_s);
    else if (wctest_chance(2, 3) && !fmpq_is_zero(mu_s))
    {
        fmpq_t h;

        fmpq_init(h);
        fmpq_set_si(h, 1, 2);
        fmpq_mul(mu_k, mu_s, h);        /* the usual mu_k < mu_s */
        fmpq_clear(h);
    }
    else
        rand_mu(mu_k);
}

static void
rand_mass(fmpq_t m)
{
    static const slong tab[4][2] = {{3, 1}, {1, 2}, {7, 3}, {2, 1}};
    slong k = wctest_randint(0, 5);

    if (k < 4)
        fmpq_set_si(m, tab[k][0], (ulong) tab[k][1]);
    else if (k == 4)
        wctest_rand_fmpq_pos(m, 5, 3);
    else
        fmpq_one(m);
}

/* The point of a rational parametrisation of the circle of radius rad
   about c: c + rad ((1 - t^2), 2 t) / (1 + t^2), or an axis point.  The
   inward (radial) normal goes to d.  */
static void
disk_point(fmpq * p, fmpq * d, const fmpq * c, const fmpq_t rad)
{
    fmpq_t t, u;

    fmpq_init(t);
    fmpq_init(u);
    if (wctest_chance(1, 2))
    {
        slong axis = wctest_randint(0, 3);

        fmpq_set_si(p + 0, axis == 0 ? 1 : axis == 2 ? -1 : 0, 1);
        fmpq_set_si(p + 1, axis == 1 ? 1 : axis == 3 ? -1 : 0, 1);
    }
    else
    {
        do
            wctest_rand_fmpq(t, 2, 3);
        while (fmpq_is_zero(t));
        _wc_unit_circle_point(p, t);
    }
    /* p is on the unit circle: the normal is -p, then place it.  */
    fmpq_neg(d + 0, p + 0);
    fmpq_neg(d + 1, p + 1);
    if (wctest_chance(1, 3))
    {
        rand_scale(u);
        fmpq_mul(d + 0, d + 0, u);
        fmpq_mul(d + 1, d + 1, u);
    }
    fmpq_mul(p + 0, p + 0, rad);
    fmpq_mul(p + 1, p + 1, rad);
    fmpq_add(p + 0, p + 0, c + 0);
    fmpq_add(p + 1, p + 1, c + 1);
    fmpq_clear(t);
    fmpq_clear(u);
}

/* d = s v with s drawn by rand_scale, negated with probability neg/den. */
static void
scaled_copy(fmpq * d, const fmpq * v, slong neg, slong den)
{
    fmpq_t s;

    fmpq_init(s);
    rand_scale(s);
    if (wctest_chance(neg, den))
        fmpq_neg(s, s);
    fmpq_mul(d + 0, v + 0, s);
    fmpq_mul(d + 1, v + 1, s);
    fmpq_clear(s);
}

int
wctest_same_contact(const wc_fixel_struct * a, const wc_fixel_struct * b)
{
    fmpq_t x, y;
    int same;

    if (!fmpq_equal(a->point + 0, b->point + 0)
        || !fmpq_equal(a->point + 1, b->point + 1))
        return 0;
    fmpq_init(x);
    fmpq_init(y);
    fmpq_mul(x, a->normal + 0, b->normal + 1);
    fmpq_mul(y, a->normal + 1, b->normal + 0);
    same = fmpq_equal(x, y);                /* parallel ... */
    fmpq_mul(x, a->normal + 0, b->normal + 0);
    fmpq_mul(y, a->normal + 1, b->normal + 1);
    fmpq_add(x, x, y);
    same = same && fmpq_sgn(x) > 0;         /* ... and the same way */
    fmpq_clear(x);
    fmpq_clear(y);
    return same;
}

static void
layout_points(wc_problem_struct * P, int layout)
{
    slong n = P->n, i;
    fmpq q[2], v[2];
    fmpq_t s;

    fmpq_init(q + 0);
    fmpq_init(q + 1);
    fmpq_init(v + 0);
    fmpq_init(v + 1);
    fmpq_init(s);

    for (i = 0; i < n; i++)
    {
        wc_fixel_struct * f = P->fixels + i;

        rand_point(f->point);
        rand_normal(f->normal);
    }

    switch (layout)
    {
        case LAYOUT_PARALLEL:
            rand_normal(v);
            for (i = 0; i < n; i++)
                scaled_copy(P->fixels[i].normal, v, 1, 3);
            break;

        case LAYOUT_OPPOSED:
            /* fixel 2j + 1 faces fixel 2j across the part */
            for (i = 1; i < n; i += 2)
            {
                wc_fixel_struct * a = P->fixels + i - 1, * b = P->fixels + i;

                rand_scale(s);
                fmpq_mul(b->point + 0, a->normal + 0, s);
                fmpq_mul(b->point + 1, a->normal + 1, s);
                if (wctest_chance(1, 4))
                    fmpq_zero(b->point + 0);  /* offset: parallel lines */
                fmpq_add(b->point + 0, b->point + 0, a->point + 0);
                fmpq_add(b->point + 1, b->point + 1, a->point + 1);
                scaled_copy(b->normal, a->normal, 1, 1);
            }
            break;

        case LAYOUT_COINCIDENT:
            rand_point(q);
            for (i = 0; i < n; i++)
            {
                wc_fixel_struct * f = P->fixels + i;

                if (i < 2 || wctest_chance(1, 2))
                {
                    fmpq_set(f->point + 0, q + 0);
                    fmpq_set(f->point + 1, q + 1);
                }
                if (i == 1 && wctest_chance(1, 2))
                    scaled_copy(f->normal, P->fixels[0].normal, 1, 1);
            }
            break;

        case LAYOUT_COLLINEAR:
            rand_point(q);
            rand_normal(v);
            for (i = 0; i < n; i++)
            {
                wc_fixel_struct * f = P->fixels + i;

                wctest_rand_fmpq(s, 3, 2);
                fmpq_mul(f->point + 0, v + 0, s);
                fmpq_mul(f->point + 1, v + 1, s);
                fmpq_add(f->point + 0, f->point + 0, q + 0);
                fmpq_add(f->point + 1, f->point + 1, q + 1);
                if (wctest_chance(1, 3))
                    scaled_copy(f->normal, v, 1, 2);   /* along the line */
                else if (wctest_chance(1, 3))
                {
                    fmpq_neg(f->normal + 0, v + 1);    /* across it */
                    fmpq_set(f->normal + 1, v + 0);
                    scaled_copy(f->normal, f->normal, 1, 2);
                }
            }
            break;

        case LAYOUT_CONCURRENT:
            rand_point(q);
            for (i = 0; i < n; i++)
            {
                wc_fixel_struct * f = P->fixels + i;

                while (fmpq_equal(f->point + 0, q + 0)
                       && fmpq_equal(f->point + 1, q + 1))
                    rand_point(f->point);
                fmpq_sub(v + 0, q + 0, f->point + 0);
                fmpq_sub(v + 1, q + 1, f->point + 1);
                scaled_copy(f->normal, v, 1, 4);
            }
            break;

        case LAYOUT_DISK:
        case LAYOUT_PAPER:
            if (layout == LAYOUT_PAPER || wctest_chance(1, 2))
            {
                fmpq_zero(q + 0);
                fmpq_zero(q + 1);
                fmpq_one(s);
            }
            else
            {
                rand_point(q);
                rand_scale(s);
            }
            for (i = 0; i < n; i++)
                disk_point(P->fixels[i].point, P->fixels[i].normal, q, s);
            if (layout == LAYOUT_PAPER)
            {
                /* fixel 1 at (0, -1) pushing up, fixel 2 at (1, 0)
                   pushing left, as in the paper's figures */
                fmpq_set_si(P->fixels[0].point + 0, 0, 1);
                fmpq_set_si(P->fixels[0].point + 1, -1, 1);
                fmpq_set_si(P->fixels[0].normal + 0, 0, 1);
                fmpq_set_si(P->fixels[0].normal + 1, 1, 1);
                if (n > 1)
                {
                    fmpq_set_si(P->fixels[1].point + 0, 1, 1);
                    fmpq_set_si(P->fixels[1].point + 1, 0, 1);
                    fmpq_set_si(P->fixels[1].normal + 0, -1, 1);
                    fmpq_set_si(P->fixels[1].normal + 1, 0, 1);
                }
            }
            break;

        case LAYOUT_BOX:
            rand_scale(s);
            for (i = 0; i < n; i++)
            {
                wc_fixel_struct * f = P->fixels + i;
                slong side = wctest_randint(0, 3);
                fmpq * along = f->point + (side & 1 ? 0 : 1);
                fmpq * across = f->point + (side & 1 ? 1 : 0);

                /* side 0: x = -s, 1: y = -s, 2: x = +s, 3: y = +s;
                   the inward normal is the axis direction into the box */
                wctest_rand_fmpq(along, 1, 2);
                fmpq_mul(along, along, s);
                if (side < 2)
                    fmpq_neg(across, s);
                else
                    fmpq_set(across, s);
                fmpq_set_si(f->normal + 0, side == 0 ? 1 : side == 2 ? -1 : 0,
                            1);
                fmpq_set_si(f->normal + 1, side == 1 ? 1 : side == 3 ? -1 : 0,
                            1);
                if (wctest_chance(1, 3))
                    scaled_copy(f->normal, f->normal, 0, 1);
            }
            break;

        default:
            break;
    }

    fmpq_clear(q + 0);
    fmpq_clear(q + 1);
    fmpq_clear(v + 0);
    fmpq_clear(v + 1);
    fmpq_clear(s);
}

void
wctest_random_problem(wc_problem_t P, slong nmin, slong nmax)
{
    slong n, i, j, near_style;
    int layout;

    if (nmin < 1 || nmax < nmin)
        wctest_fail("wctest_random_problem: bad range %ld..%ld",
                    (long) nmin, (long) nmax);
    n = wctest_randint(nmin, nmax);

    /* Globals first: wc_problem_add_fixel copies the global friction.  */
    if (wctest_chance(1, 2))
        rand_mass(P->mass);
    if (wctest_chance(1, 2))
        rand_mass(P->inertia);
    if (wctest_chance(1, 2))
        rand_point(P->com);
    rand_friction(P->mu_s, P->mu_k);

    for (i = 0; i < n; i++)
        (void) wc_problem_add_fixel(P);
    if (P->n != n)
        wctest_fail("wctest_random_problem: wc_problem_add_fixel made %ld "
                    "fixels, not %ld", (long) P->n, (long) n);

    layout = (int) wctest_randint(0, LAYOUT_COUNT - 1);
    layout_points(P, layout);

    /* States: all touching, all near, or mixed.  */
    near_style = wctest_randint(0, 5);
    for (i = 0; i < n; i++)
    {
        wc_fixel_struct * f = P->fixels + i;

        if (near_style == 0)
            f->state = WC_NEAR;
        else if (near_style <= 2)
            f->state = WC_TOUCHING;
        else
            f->state = wctest_chance(1, 3) ? WC_NEAR : WC_TOUCHING;
        if (wctest_chance(1, 6))
            rand_friction(f->mu_s, f->mu_k);
    }

    /* Never two fixels at one point with the same normal direction.  */
    for (i = 1; i < n; i++)
        for (j = 0; j < i; j++)
            if (wctest_same_contact(P->fixels + i, P->fixels + j))
            {
                rand_normal(P->fixels[i].normal);
                j = -1;         /* recheck against all */
            }
}

static void
random_mode(char * mode, const wc_problem_struct * P, const char * touching,
            const char * near)
{
    slong i;

    for (i = 0; i < P->n; i++)
    {
        const char * set = (P->fixels[i].state == WC_NEAR) ? near : touching;

        mode[i] = set[wctest_randint(0, (slong) strlen(set) - 1)];
    }
    mode[P->n] = '\0';
}

void
wctest_random_mode(char * mode, const wc_problem_t P)
{
    random_mode(mode, P, "slrnm", "sau");
}

void
wctest_random_mode_kinematic(char * mode, const wc_problem_t P)
{
    random_mode(mode, P, "slrn", "sa");
}

void
wctest_load_data(wc_problem_t P, const char * name)
{
    const char * top = getenv("top_srcdir");
    char path[4096], * text;
    size_t len;
    long size;
    FILE * f;
    wc_error_t err;

    snprintf(path, sizeof path, "%s/data/%s", top != NULL ? top : ".", name);
    if ((f = fopen(path, "rb")) == NULL || fseek(f, 0, SEEK_END) != 0
        || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0)
        wctest_fail("cannot read %s", path);
    if ((text = malloc((size_t) size + 1)) == NULL)
        wctest_fail("out of memory reading %s", path);
    len = fread(text, 1, (size_t) size, f);
    fclose(f);
    if (len != (size_t) size)
        wctest_fail("cannot read %s", path);
    wc_error_init(err);
    if (wc_problem_parse(P, text, len, path, err) != WC_OK)
        wctest_fail("%s does not parse: %s", path, err->message);
    wc_error_clear(err);
    free(text);
}

char *
wctest_cone_json(const wc_cone_t W)
{
    char * buf = NULL;
    size_t len = 0;
    FILE * f = open_memstream(&buf, &len);
    int status;

    if (f == NULL)
        wctest_fail("open_memstream failed");
    status = wc_cone_fprint(f, W, as_json);
    if (fclose(f) != 0 || status != WC_OK)
        wctest_fail("wc_cone_fprint failed");
    return buf;
}

wc_fixel_struct *
wctest_fixel_si(wc_problem_t P, slong px, slong py, slong nx, slong ny,
                wc_fixel_state state)
{
    wc_fixel_struct * f = wc_problem_add_fixel(P);

    fmpq_set_si(f->point + 0, px, 1);
    fmpq_set_si(f->point + 1, py, 1);
    fmpq_set_si(f->normal + 0, nx, 1);
    fmpq_set_si(f->normal + 1, ny, 1);
    f->state = state;
    return f;
}

void
wctest_wrench_of(fmpq * w, const wc_problem_t P, const wc_fixel_struct * f,
                 const fmpq * d)
{
    fmpq_t rx, ry, t;

    fmpq_init(rx);
    fmpq_init(ry);
    fmpq_init(t);
    fmpq_sub(rx, f->point + 0, P->com + 0);
    fmpq_sub(ry, f->point + 1, P->com + 1);
    fmpq_set(w + 0, d + 0);
    fmpq_set(w + 1, d + 1);
    fmpq_mul(w + 2, rx, d + 1);
    fmpq_mul(t, ry, d + 0);
    fmpq_sub(w + 2, w + 2, t);
    fmpq_clear(rx);
    fmpq_clear(ry);
    fmpq_clear(t);
}

void
wctest_vec3_si(fmpq * g, slong x, slong y, slong t)
{
    fmpq_set_si(g + 0, x, 1);
    fmpq_set_si(g + 1, y, 1);
    fmpq_set_si(g + 2, t, 1);
}

int
wctest_vec3_is_zero(const fmpq * v)
{
    return fmpq_is_zero(v + 0) && fmpq_is_zero(v + 1) && fmpq_is_zero(v + 2);
}

void
wctest_dot3(fmpq_t r, const fmpq * a, const fmpq * b)
{
    fmpq_t t;
    int j;

    fmpq_init(t);
    fmpq_zero(r);
    for (j = 0; j < 3; j++)
    {
        fmpq_mul(t, a + j, b + j);
        fmpq_add(r, r, t);
    }
    fmpq_clear(t);
}

int
wctest_dot3_sgn_z(const fmpz * h, const fmpq * g)
{
    fmpq_t s, t;
    slong j;
    int r;

    fmpq_init(s);
    fmpq_init(t);
    for (j = 0; j < 3; j++)
    {
        fmpq_mul_fmpz(t, g + j, h + j);
        fmpq_add(s, s, t);
    }
    r = fmpq_sgn(s);
    fmpq_clear(s);
    fmpq_clear(t);
    return r;
}
