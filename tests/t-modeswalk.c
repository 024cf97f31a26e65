/* t-modeswalk.c -- the output-sensitive mode walk (lib/analysis/
   modeswalk.c) against the independent reference ref-modes.c (a search
   over mode strings, one exact LP per prefix), and against the walk of
   the whole arrangement it replaced (tests/old-modes.c, a regression
   check).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   On every problem wc_modes_enumerate must return exactly the modes of
   the independent ref-modes.c -- read from the faces of the arrangement
   (ref_modes_faces), and up to REF_MAX_FIXELS fixels also by its LP
   search over strings (ref_modes_search), up to 3 by brute force over
   all strings (ref-kin.c) -- and each witness must be a primitive
   integer twist that satisfies its mode (ref_twist_satisfies, from the
   problem's fields), zero exactly for the mode nu = 0 holds (n on
   touching fixels, s on near ones).  On every problem it must return the very list of the old
   walk, mode for mode and witness for witness (the output of modes
   --witness is byte-identical).  Problems: random problems of 1 to 40 fixels from the library's
   generator (plain and --degenerate, every shape), from the test
   generator, and on layouts built here: all fixels near, all touching
   with every normal line through one point (a cradle: the rotation about
   it moves no fixel), collinear points, repeated points, opposite
   normals, and mixes of them.  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpz_vec.h>

#include "wrenchcone.h"
#include "analysis/kinematics.h"
#include "old-modes.h"
#include "ref-kin.h"
#include "ref-modes.h"
#include "testutil.h"

/* The LP search of ref-modes.c is run up to this many fixels.  */
#define REF_MAX_FIXELS 6

static slong checked, total_modes, ref_checked;

/* M's modes are the count strings of ref, by the reference name.  */
static void
same_list(const wc_modes_t M, char ** ref, slong count, const char * name,
          const wc_problem_t P, const char * what)
{
    slong i;

    for (i = 0; i < M->count || i < count; i++)
        if (i >= M->count || i >= count || strcmp(M->modes[i], ref[i]) != 0)
            wctest_fail_problem(P, NULL, "%s: %ld modes, %s %ld; first "
                                "difference at %ld: %s, the reference %s",
                                what, (long) M->count, name, (long) count,
                                (long) i, i < M->count ? M->modes[i] : "-",
                                i < count ? ref[i] : "-");
}

/* M against the independent references: the LP search up to
   REF_MAX_FIXELS fixels, the faces of the arrangement (ref-cells.c)
   always, brute force up to 3; every witness.  */
static void
check_ref(const wc_modes_t M, const wc_problem_t P, const char * what)
{
    char ** ref = NULL, * zero;
    slong count = 0, i, j;
    fmpz_t c;

    if (ref_modes_faces(&ref, &count, P) != 0)
        wctest_fail_problem(P, NULL, "%s: ref_modes_faces failed", what);
    same_list(M, ref, count, "ref_modes_faces", P, what);
    ref_modes_free(ref, count);
    if (P->n <= REF_MAX_FIXELS)
    {
        if (ref_modes_search(&ref, &count, NULL, P) != 0)
            wctest_fail_problem(P, NULL, "%s: ref_modes_search failed",
                                what);
        same_list(M, ref, count, "ref_modes_search", P, what);
        ref_modes_free(ref, count);
        ref_checked++;
    }
    if (P->n <= 3)
    {
        if (ref_modes_bruteforce(&ref, &count, P) != 0)
            wctest_fail_problem(P, NULL, "%s: brute force failed", what);
        same_list(M, ref, count, "brute force", P, what);
        ref_modes_free(ref, count);
    }
    zero = flint_malloc(P->n + 1);
    for (j = 0; j < P->n; j++)
        zero[j] = P->fixels[j].state == WC_NEAR ? 's' : 'n';
    zero[P->n] = '\0';
    fmpz_init(c);
    for (i = 0; i < M->count; i++)
    {
        const fmpz * w = M->witness->rows[i];
        int is_zero_mode = strcmp(M->modes[i], zero) == 0;

        _fmpz_vec_content(c, w, 3);
        if (is_zero_mode ? !fmpz_is_zero(c) : !fmpz_is_one(c))
            wctest_fail_problem(P, M->modes[i], "%s: the witness of %s is "
                                "not %s", what, M->modes[i], is_zero_mode
                                ? "zero" : "a primitive nonzero twist");
        if (ref_twist_satisfies(P, M->modes[i], w) != 1)
            wctest_fail_problem(P, M->modes[i], "%s: the witness of %s "
                                "does not satisfy it", what, M->modes[i]);
    }
    fmpz_clear(c);
    flint_free(zero);
}

static void
check(const wc_problem_t P, const char * what)
{
    wc_modes_t M, R;
    wc_error_t err;
    slong i;

    wc_modes_init(M);
    wc_modes_init(R);
    wc_error_init(err);
    if (wc_modes_enumerate(M, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "%s: wc_modes_enumerate failed: %s",
                            what, err->message ? err->message : "?");
    check_ref(M, P, what);
    if (old_modes_walk(R, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "%s: the reference failed", what);
    if (M->n != R->n || M->count != R->count)
    {
        for (i = 0; i < M->count; i++)
            fprintf(stderr, "new: %s\n", M->modes[i]);
        for (i = 0; i < R->count; i++)
            fprintf(stderr, "ref: %s\n", R->modes[i]);
    }
    if (M->n != R->n || M->count != R->count)
        wctest_fail_problem(P, NULL, "%s: %ld modes, the reference %ld",
                            what, (long) M->count, (long) R->count);
    for (i = 0; i < M->count; i++)
    {
        if (strcmp(M->modes[i], R->modes[i]) != 0)
            wctest_fail_problem(P, M->modes[i], "%s: mode %ld is %s, the "
                                "reference's %s", what, (long) i,
                                M->modes[i], R->modes[i]);
        if (!_fmpz_vec_equal(M->witness->rows[i], R->witness->rows[i], 3))
            wctest_fail_problem(P, M->modes[i], "%s: the witness of %s "
                                "differs from the reference's", what,
                                M->modes[i]);
    }
    checked++;
    total_modes += M->count;
    wc_modes_clear(M);
    wc_modes_clear(R);
    wc_error_clear(err);
}

static wc_fixel_struct *
fixel(wc_problem_t P, const fmpq * p, const fmpq * d, wc_fixel_state st)
{
    wc_fixel_struct * f = wc_problem_add_fixel(P);

    fmpq_set(f->point + 0, p + 0);
    fmpq_set(f->point + 1, p + 1);
    fmpq_set(f->normal + 0, d + 0);
    fmpq_set(f->normal + 1, d + 1);
    f->state = st;
    return f;
}

static void
rand_point(fmpq * p)
{
    wctest_rand_fmpq(p + 0, 4, 3);
    wctest_rand_fmpq(p + 1, 4, 3);
}

static void
rand_dir(fmpq * d)
{
    do
    {
        wctest_rand_fmpq(d + 0, 3, 2);
        wctest_rand_fmpq(d + 1, 3, 2);
    }
    while (fmpq_is_zero(d + 0) && fmpq_is_zero(d + 1));
}

/* 1 when fixel i repeats an earlier one's point and normal direction.  */
static int
repeats(const wc_problem_t P, slong i)
{
    const wc_fixel_struct * a = P->fixels + i;
    fmpq_t x, y;
    slong j;
    int same = 0;

    fmpq_init(x);
    fmpq_init(y);
    for (j = 0; j < i && !same; j++)
    {
        const wc_fixel_struct * b = P->fixels + j;

        if (!fmpq_equal(a->point + 0, b->point + 0)
            || !fmpq_equal(a->point + 1, b->point + 1))
            continue;
        fmpq_mul(x, a->normal + 0, b->normal + 1);
        fmpq_mul(y, a->normal + 1, b->normal + 0);
        if (!fmpq_equal(x, y))
            continue;
        fmpq_mul(x, a->normal + 0, b->normal + 0);
        fmpq_mul(y, a->normal + 1, b->normal + 1);
        fmpq_add(x, x, y);
        same = fmpq_sgn(x) > 0;
    }
    fmpq_clear(x);
    fmpq_clear(y);
    return same;
}

enum
{
    L_NEAR,         /* every fixel near */
    L_CRADLE,       /* all touching, every normal line through c */
    L_COLLINEAR,    /* points on one line */
    L_REPEATED,     /* few distinct points */
    L_OPPOSITE,     /* pairs of opposite normals */
    L_MIXED,        /* a bit of everything */
    L_COUNT
};

static const char * layout_name[L_COUNT] =
    { "all near", "cradle", "collinear", "repeated points",
      "opposite normals", "mixed" };

/* A layout of n fixels of kind L.  */
static void
layout(wc_problem_t P, int L, slong n)
{
    fmpq p[2], d[2], c[2], q[2];
    slong i, j;

    for (j = 0; j < 2; j++)
    {
        fmpq_init(p + j);
        fmpq_init(d + j);
        fmpq_init(c + j);
        fmpq_init(q + j);
    }
    rand_point(c);
    rand_dir(q);
    if (wctest_chance(1, 2))
        rand_point(P->com);
    for (i = 0; i < n; i++)
    {
        int kind = L == L_MIXED ? (int) wctest_randint(0, L_MIXED - 1) : L;
        wc_fixel_state st = kind == L_NEAR || wctest_chance(1, 6)
            ? WC_NEAR : WC_TOUCHING;
        wc_fixel_struct * f;

        rand_point(p);
        rand_dir(d);
        switch (kind)
        {
        case L_CRADLE:      /* normal along c - p, either way */
            st = WC_TOUCHING;
            fmpq_sub(d + 0, c + 0, p + 0);
            fmpq_sub(d + 1, c + 1, p + 1);
            if (fmpq_is_zero(d + 0) && fmpq_is_zero(d + 1))
            {
                fmpq_add_si(p + 0, c + 0, 1);
                fmpq_set_si(d + 0, -1, 1);
            }
            if (wctest_chance(1, 5))
            {
                fmpq_neg(d + 0, d + 0);
                fmpq_neg(d + 1, d + 1);
            }
            break;
        case L_COLLINEAR:   /* p = c + t q */
            wctest_rand_fmpq(p + 0, 3, 2);
            fmpq_mul(p + 1, q + 1, p + 0);
            fmpq_mul(p + 0, q + 0, p + 0);
            fmpq_add(p + 0, p + 0, c + 0);
            fmpq_add(p + 1, p + 1, c + 1);
            if (wctest_chance(1, 3))
            {
                fmpq_set(d + 0, q + 1);
                fmpq_neg(d + 1, q + 0);
            }
            break;
        case L_REPEATED:
            if (i > 0 && wctest_chance(2, 3))
            {
                j = wctest_randint(0, i - 1);
                fmpq_set(p + 0, P->fixels[j].point + 0);
                fmpq_set(p + 1, P->fixels[j].point + 1);
            }
            break;
        case L_OPPOSITE:
            if (i > 0 && wctest_chance(2, 3))
            {
                j = wctest_randint(0, i - 1);
                fmpq_neg(d + 0, P->fixels[j].normal + 0);
                fmpq_neg(d + 1, P->fixels[j].normal + 1);
                if (wctest_chance(1, 2))
                {
                    fmpq_set(p + 0, P->fixels[j].point + 0);
                    fmpq_set(p + 1, P->fixels[j].point + 1);
                }
            }
            break;
        default:
            break;
        }
        f = fixel(P, p, d, st);
        while (repeats(P, P->n - 1))
            rand_dir(f->normal);
    }
    for (j = 0; j < 2; j++)
    {
        fmpq_clear(p + j);
        fmpq_clear(d + j);
        fmpq_clear(c + j);
        fmpq_clear(q + j);
    }
}

static void
library_random(slong i)
{
    wc_random_options opt;
    wc_problem_t P;
    wc_error_t err;
    char what[96];

    wc_random_options_init(&opt);
    opt.fixels = wctest_randint(1, i % 4 == 0 ? 40 : 12);
    opt.seed = wctest_rand();
    opt.degenerate = wctest_chance(1, 2);
    opt.shape = (wc_shape_kind) (i % 3 == 0 ? WC_SHAPE_NONE
                                 : i % 3 == 1 ? WC_SHAPE_DISK
                                 : WC_SHAPE_POLYGON);
    wc_problem_init(P);
    wc_error_init(err);
    if (wc_random_problem(P, &opt, err) != WC_OK)
        wctest_fail("wc_random_problem failed");
    snprintf(what, sizeof what, "random n=%ld seed=%llu%s shape %d",
             (long) opt.fixels, (unsigned long long) opt.seed,
             opt.degenerate ? " degenerate" : "", (int) opt.shape);
    check(P, what);
    wc_problem_clear(P);
    wc_error_clear(err);
    wc_random_options_clear(&opt);
}

/* SPEC.md section 5: the unit disk touched at (0, -1) and (1, 0) has
   exactly these feasible modes; the library and ref-modes.c agree on
   them (check), and they are these.  */
static void
test_section5(void)
{
    static const char * const want[] = {
        "ll", "ls", "nn", "ns", "rr", "rs", "sl", "sn", "sr", "ss"
    };
    wc_problem_t P;
    wc_modes_t M;
    wc_error_t err;
    slong i;

    wc_problem_init(P);
    wc_modes_init(M);
    wc_error_init(err);
    wctest_fixel_si(P, 0, -1, 0, 1, WC_TOUCHING);
    wctest_fixel_si(P, 1, 0, -1, 0, WC_TOUCHING);
    check(P, "section 5");
    if (wc_modes_enumerate(M, P, err) != WC_OK || M->count != 10)
        wctest_fail_problem(P, NULL, "section 5: not 10 modes");
    for (i = 0; i < 10; i++)
        if (strcmp(M->modes[i], want[i]) != 0)
            wctest_fail_problem(P, NULL, "section 5: mode %ld is %s, not "
                                "%s", (long) i, M->modes[i], want[i]);
    wc_error_clear(err);
    wc_modes_clear(M);
    wc_problem_clear(P);
}

int
main(void)
{
    slong i, iters;
    char what[64];

    wctest_init("t-modeswalk");
    wc_init();
    test_section5();

    iters = wctest_iters(150);
    for (i = 0; i < iters; i++)
        if (wctest_iter(i))
            library_random(i);

    iters = wctest_iters(100);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        wctest_random_problem(P, 1, i % 5 == 0 ? 30 : 8);
        check(P, "test generator");
        wc_problem_clear(P);
    }

    iters = wctest_iters(120);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;
        int L = (int) (i % L_COUNT);
        slong n = i % 6 == 5 ? wctest_randint(20, 40) : wctest_randint(1, 9);

        if (!wctest_iter(i))
            continue;
        snprintf(what, sizeof what, "%s n=%ld", layout_name[L], (long) n);
        wc_problem_init(P);
        layout(P, L, n);
        check(P, what);
        wc_problem_clear(P);
    }

    printf("t-modeswalk: %ld problems, %ld modes, all equal to ref-modes.c "
           "and to the old walk, %ld also to its LP search\n", (long) checked,
           (long) total_modes, (long) ref_checked);
    flint_cleanup_master();
    return 0;
}
