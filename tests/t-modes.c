/* t-modes.c -- kinematic feasibility (lib/kinematics.c) against the
   independent oracle tests/ref-kin.c.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   wc_modes_enumerate (the arrangement of the 2n planes J_k . nu = 0) must
   return exactly the list that brute force over all 4^t 2^(n-t) Table 1
   strings finds with one exact LP each, on the paper's Figure 5, on
   cases worked out by hand, on random problems and on degenerate layouts
   built here to make planes coincide or share a line.  Every witness is
   substituted into the mode's rows (the library's and ours).  wc_feasible
   must agree with the oracle on random modes, feasible and infeasible, and
   its certificates are checked here condition by condition, then tampered
   with to see wc_certificate_check reject them.  Beyond brute force
   (n = 7 .. 14) the list is checked for soundness (every mode's witness),
   for completeness on random strings and on every one-letter neighbour of
   a listed mode, and for invariance under moving the centre of mass,
   rescaling normals and permuting fixels.  */

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
#include "ref-kin.h"
#include "testutil.h"

_Static_assert((int) WC_REL_GT == REF_REL_GT && (int) WC_REL_GE == REF_REL_GE
               && (int) WC_REL_EQ == REF_REL_EQ,
               "ref-kin.h numbers relations as kinematics.h does");

/* ---- problems ------------------------------------------------------ */

/* The paper's unit disk (Sections 4 and 7): fixel 1 touching at (0, -1)
   pushing up, fixel 2 at (1, 0) pushing left, friction 1.  */
static void
paper_disk(wc_problem_t P, wc_fixel_state second)
{
    fmpq_one(P->mu_s);
    fmpq_one(P->mu_k);
    wctest_fixel_si(P, 0, -1, 0, 1, WC_TOUCHING);
    wctest_fixel_si(P, 1, 0, -1, 0, second);
}

/* A nonzero direction with small entries.  */
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

/* Two fixels at one point must not push the same way (wrenchcone(5)): turn the
   later one's normal to a fresh direction until they differ.  */
static void
separate_contacts(wc_problem_t P)
{
    slong i, j;

    for (i = 1; i < P->n; i++)
        for (j = 0; j < i; j++)
            if (wctest_same_contact(P->fixels + i, P->fixels + j))
            {
                rand_dir(P->fixels[i].normal);
                j = -1;
            }
}

/* d = s v, s a random nonzero rational of either sign (or positive).  */
static void
rand_multiple(fmpq * d, const fmpq * v, int either_sign)
{
    fmpq_t s;

    fmpq_init(s);
    wctest_rand_fmpq_pos(s, 3, 3);
    if (either_sign && wctest_chance(1, 2))
        fmpq_neg(s, s);
    fmpq_mul(d + 0, v + 0, s);
    fmpq_mul(d + 1, v + 1, s);
    fmpq_clear(s);
}

enum
{
    DEG_SAME_PLANE,     /* same point, opposite normals: J columns -s J */
    DEG_SAME_LINE,      /* same line of action: parallel J_in columns */
    DEG_PARALLEL,       /* all normals parallel or opposed */
    DEG_AT_POINT,       /* several fixels at one point */
    DEG_ALL_AT_POINT,   /* all at one point: all 2n planes share a line */
    DEG_ALL_AT_COM,     /* all at the centre of mass: planes contain the
                           omega axis */
    DEG_CONCURRENT,     /* all normal lines through one point */
    DEG_ONE_LINE,       /* all on one line, normals along it */
    DEG_SINGLE,         /* one fixel */
    DEG_COUNT
};

static const char * const deg_name[DEG_COUNT] =
{
    "same plane", "same line of action", "parallel normals",
    "several at one point", "all at one point", "all at the com",
    "concurrent normals", "one line of action", "single fixel"
};

/* A problem of kind (DEG_*) with n fixels (1 for DEG_SINGLE).  */
static void
degenerate_problem(wc_problem_t P, int kind, slong n)
{
    fmpq q[2], d[2];
    fmpq_t s;
    slong i;

    fmpq_init(q + 0);
    fmpq_init(q + 1);
    fmpq_init(d + 0);
    fmpq_init(d + 1);
    fmpq_init(s);

    if (kind == DEG_SINGLE)
        n = 1;
    if (wctest_chance(1, 2))
    {
        wctest_rand_fmpq(P->com + 0, 2, 3);
        wctest_rand_fmpq(P->com + 1, 2, 3);
    }
    for (i = 0; i < n; i++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);

        wctest_rand_fmpq(f->point + 0, 3, 2);
        wctest_rand_fmpq(f->point + 1, 3, 2);
        rand_dir(f->normal);
        f->state = wctest_chance(1, 4) ? WC_NEAR : WC_TOUCHING;
    }
    wctest_rand_fmpq(q + 0, 3, 2);
    wctest_rand_fmpq(q + 1, 3, 2);
    rand_dir(d);

    switch (kind)
    {
        case DEG_SAME_PLANE:
        case DEG_SAME_LINE:
            /* fixel 2j + 1 copies fixel 2j's plane(s) */
            for (i = 1; i < n; i += 2)
            {
                wc_fixel_struct * a = P->fixels + i - 1, * b = P->fixels + i;

                if (kind == DEG_SAME_PLANE)
                {
                    fmpq_set(b->point + 0, a->point + 0);
                    fmpq_set(b->point + 1, a->point + 1);
                    rand_multiple(b->normal, a->normal, 0);
                    fmpq_neg(b->normal + 0, b->normal + 0);
                    fmpq_neg(b->normal + 1, b->normal + 1);
                }
                else
                {
                    /* b = a + u n_a, normal +-s n_a */
                    rand_multiple(b->point, a->normal, 1);
                    fmpq_add(b->point + 0, b->point + 0, a->point + 0);
                    fmpq_add(b->point + 1, b->point + 1, a->point + 1);
                    rand_multiple(b->normal, a->normal, 1);
                }
            }
            break;
        case DEG_PARALLEL:
            for (i = 0; i < n; i++)
            {
                rand_multiple(P->fixels[i].normal, d, 1);
                if (i > 0 && wctest_chance(1, 3))
                {
                    /* on fixel 1's line of action: p_1 + u d */
                    rand_multiple(P->fixels[i].point, d, 1);
                    fmpq_add(P->fixels[i].point + 0, P->fixels[i].point + 0,
                             P->fixels[0].point + 0);
                    fmpq_add(P->fixels[i].point + 1, P->fixels[i].point + 1,
                             P->fixels[0].point + 1);
                }
            }
            break;
        case DEG_AT_POINT:
        case DEG_ALL_AT_POINT:
        case DEG_ALL_AT_COM:
            if (kind == DEG_ALL_AT_COM)
            {
                fmpq_set(q + 0, P->com + 0);
                fmpq_set(q + 1, P->com + 1);
            }
            for (i = 0; i < n; i++)
                if (kind != DEG_AT_POINT || i < 2 || wctest_chance(1, 2))
                {
                    fmpq_set(P->fixels[i].point + 0, q + 0);
                    fmpq_set(P->fixels[i].point + 1, q + 1);
                    if (i > 0 && wctest_chance(1, 3))
                    {
                        /* an opposed normal: two planes coincide */
                        rand_multiple(P->fixels[i].normal,
                                      P->fixels[i - 1].normal, 0);
                        fmpq_neg(P->fixels[i].normal + 0,
                                 P->fixels[i].normal + 0);
                        fmpq_neg(P->fixels[i].normal + 1,
                                 P->fixels[i].normal + 1);
                    }
                }
            break;
        case DEG_CONCURRENT:
            for (i = 0; i < n; i++)
            {
                wc_fixel_struct * f = P->fixels + i;

                while (fmpq_equal(f->point + 0, q + 0)
                       && fmpq_equal(f->point + 1, q + 1))
                    fmpq_add_si(f->point + 0, f->point + 0, 1);
                fmpq_sub(f->normal + 0, q + 0, f->point + 0);
                fmpq_sub(f->normal + 1, q + 1, f->point + 1);
                rand_multiple(f->normal, f->normal, 1);
            }
            break;
        case DEG_ONE_LINE:
            for (i = 0; i < n; i++)
            {
                wc_fixel_struct * f = P->fixels + i;

                wctest_rand_fmpq(s, 3, 2);
                fmpq_mul(f->point + 0, d + 0, s);
                fmpq_mul(f->point + 1, d + 1, s);
                fmpq_add(f->point + 0, f->point + 0, q + 0);
                fmpq_add(f->point + 1, f->point + 1, q + 1);
                rand_multiple(f->normal, d, 1);
            }
            break;
        default:
            break;
    }

    separate_contacts(P);
    fmpq_clear(q + 0);
    fmpq_clear(q + 1);
    fmpq_clear(d + 0);
    fmpq_clear(d + 1);
    fmpq_clear(s);
}

/* n fixels at random points with random normals, entries p/q with
   |p|, q up to 60; a quarter of them near.  */
static void
big_problem(wc_problem_t P, slong n)
{
    slong i;

    wctest_rand_fmpq(P->com + 0, 60, 60);
    wctest_rand_fmpq(P->com + 1, 60, 60);
    for (i = 0; i < n; i++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);

        wctest_rand_fmpq(f->point + 0, 60, 60);
        wctest_rand_fmpq(f->point + 1, 60, 60);
        do
        {
            wctest_rand_fmpq(f->normal + 0, 60, 60);
            wctest_rand_fmpq(f->normal + 1, 60, 60);
        }
        while (fmpq_is_zero(f->normal + 0) && fmpq_is_zero(f->normal + 1));
        f->state = wctest_chance(1, 4) ? WC_NEAR : WC_TOUCHING;
    }
    separate_contacts(P);
}

/* Q = P with its fixels in the order perm (Q's fixel i is P's perm[i]),
   the centre of mass moved by shift and every normal scaled by a positive
   rational: the same mechanical situation, so the same modes up to the
   permutation.  Q must be freshly initialised.  */
static void
transformed_problem(wc_problem_t Q, const wc_problem_t P, const slong * perm,
                    const fmpq * shift)
{
    fmpq_t s;
    slong i, j;

    fmpq_init(s);
    fmpq_add(Q->com + 0, P->com + 0, shift + 0);
    fmpq_add(Q->com + 1, P->com + 1, shift + 1);
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + perm[i];
        wc_fixel_struct * g = wc_problem_add_fixel(Q);

        wctest_rand_fmpq_pos(s, 5, 4);
        for (j = 0; j < 2; j++)
        {
            fmpq_set(g->point + j, f->point + j);
            fmpq_mul(g->normal + j, f->normal + j, s);
        }
        g->state = f->state;
        fmpq_set(g->mu_s, f->mu_s);
        fmpq_set(g->mu_k, f->mu_k);
    }
    fmpq_clear(s);
}

/* ---- modes and rows ------------------------------------------------ */

/* 1 when nu = 0 satisfies mode: n on every touching fixel, s on every
   near one.  */
static int
is_zero_mode(const wc_problem_t P, const char * mode)
{
    slong i;

    for (i = 0; i < P->n; i++)
        if (mode[i] != (P->fixels[i].state == WC_NEAR ? 's' : 'n'))
            return 0;
    return 1;
}

static void
fprint_rows(FILE * out, const char * label, const fmpz_mat_t rows,
            const int * rel)
{
    slong k;

    fprintf(out, "%s (%ld rows):\n", label, (long) fmpz_mat_nrows(rows));
    for (k = 0; k < fmpz_mat_nrows(rows); k++)
    {
        fprintf(out, "  (");
        fmpz_fprint(out, fmpz_mat_entry(rows, k, 0));
        fprintf(out, ", ");
        fmpz_fprint(out, fmpz_mat_entry(rows, k, 1));
        fprintf(out, ", ");
        fmpz_fprint(out, fmpz_mat_entry(rows, k, 2));
        fprintf(out, ") . nu %s 0\n",
                rel[k] == REF_REL_GT ? ">" : rel[k] == REF_REL_GE ? ">="
                : rel[k] == REF_REL_EQ ? "=" : "(bad relation)");
    }
}

/* "(a, b, c)", malloc'd; free with flint_free.  */
static char *
twist_str(const fmpz * nu)
{
    char * part[3], * s;
    size_t len = 8;
    int j;

    for (j = 0; j < 3; j++)
    {
        part[j] = fmpz_get_str(NULL, 10, nu + j);
        len += strlen(part[j]) + 2;
    }
    s = flint_malloc(len);
    snprintf(s, len, "(%s, %s, %s)", part[0], part[1], part[2]);
    for (j = 0; j < 3; j++)
        flint_free(part[j]);
    return s;
}

/* 1 when the integer twist nu satisfies every row exactly.  */
static int
rows_hold(const fmpz_mat_t rows, const int * rel, const fmpz * nu)
{
    fmpz_t v;
    slong k;
    int ok = 1;

    fmpz_init(v);
    for (k = 0; k < fmpz_mat_nrows(rows) && ok; k++)
    {
        int sgn;

        fmpz_mul(v, fmpz_mat_entry(rows, k, 0), nu + 0);
        fmpz_addmul(v, fmpz_mat_entry(rows, k, 1), nu + 1);
        fmpz_addmul(v, fmpz_mat_entry(rows, k, 2), nu + 2);
        sgn = fmpz_sgn(v);
        ok = rel[k] == REF_REL_GT ? sgn > 0
            : rel[k] == REF_REL_GE ? sgn >= 0
            : rel[k] == REF_REL_EQ ? sgn == 0 : 0;
    }
    fmpz_clear(v);
    return ok;
}

static int
has_strict(const int * rel, slong m)
{
    slong k;

    for (k = 0; k < m; k++)
        if (rel[k] == REF_REL_GT)
            return 1;
    return 0;
}

/* 1 when y is a Motzkin certificate for the rows: sum_k y_k row_k = 0,
   y_k >= 0 on > and >= rows, y_k > 0 on at least one > row.  */
static int
motzkin_holds(const fmpz_mat_t rows, const int * rel, const fmpz * y)
{
    fmpz_t sum;
    slong k, j, m = fmpz_mat_nrows(rows);
    int ok = 1, strict = 0;

    for (k = 0; k < m; k++)
    {
        if (rel[k] != REF_REL_EQ && fmpz_sgn(y + k) < 0)
            ok = 0;
        if (rel[k] == REF_REL_GT && fmpz_sgn(y + k) > 0)
            strict = 1;
    }
    fmpz_init(sum);
    for (j = 0; j < 3 && ok; j++)
    {
        fmpz_zero(sum);
        for (k = 0; k < m; k++)
            fmpz_addmul(sum, y + k, fmpz_mat_entry(rows, k, j));
        ok = fmpz_is_zero(sum);
    }
    fmpz_clear(sum);
    return ok && strict;
}

/* 1 when the multipliers are those of a basic solution: the rows they
   use, each extended by 1 when strict and 0 otherwise (the normalising
   equation sum of strict y = 1), are linearly independent.  */
static int
support_is_basic(const fmpz_mat_t rows, const int * rel, const fmpz * y)
{
    fmpz_mat_t S;
    slong k, j, m = fmpz_mat_nrows(rows), s = 0;
    int ok;

    for (k = 0; k < m; k++)
        s += !fmpz_is_zero(y + k);
    if (s > 4)
        return 0;
    fmpz_mat_init(S, s, 4);
    s = 0;
    for (k = 0; k < m; k++)
        if (!fmpz_is_zero(y + k))
        {
            for (j = 0; j < 3; j++)
                fmpz_set(fmpz_mat_entry(S, s, j), fmpz_mat_entry(rows, k, j));
            fmpz_set_ui(fmpz_mat_entry(S, s, 3), rel[k] == REF_REL_GT);
            s++;
        }
    ok = (fmpz_mat_rank(S) == s);
    fmpz_mat_clear(S);
    return ok;
}

/* gcd of the entries: 1 for a primitive nonzero vector, 0 for zero.  */
static int
content_is(const fmpz * v, slong len, ulong c)
{
    fmpz_t g;
    int ok;

    fmpz_init(g);
    _fmpz_vec_content(g, v, len);
    ok = fmpz_equal_ui(g, c);
    fmpz_clear(g);
    return ok;
}

/* Our rows of mode must be the library's rows (kinematics.h documents
   them exactly); what names the caller in a failure.  */
static void
check_rows_equal(const wc_problem_t P, const char * mode,
                 const fmpz_mat_t rows, const wc_relation * rel,
                 fmpz_mat_t ours, int ** our_rel, const char * what)
{
    slong k, m;
    int same;

    if (ref_mode_rows(ours, our_rel, P, mode) != 0)
        wctest_fail_problem(P, mode, "%s: ref_mode_rows refused a mode the "
                            "library accepted", what);
    m = fmpz_mat_nrows(ours);
    same = fmpz_mat_nrows(rows) == m && fmpz_mat_ncols(rows) == 3
        && fmpz_mat_equal(rows, ours);
    for (k = 0; k < m && same; k++)
        same = ((int) rel[k] == (*our_rel)[k]);
    if (!same)
    {
        int * lib_rel = flint_malloc(sizeof(int) * (fmpz_mat_nrows(rows) + 1));

        for (k = 0; k < fmpz_mat_nrows(rows); k++)
            lib_rel[k] = (int) rel[k];
        fflush(stdout);
        if (fmpz_mat_ncols(rows) == 3)
            fprint_rows(stderr, "library rows", rows, lib_rel);
        else
            fprintf(stderr, "library rows: %ld x %ld\n",
                    (long) fmpz_mat_nrows(rows), (long) fmpz_mat_ncols(rows));
        fprint_rows(stderr, "reference rows", ours, *our_rel);
        flint_free(lib_rel);
        wctest_fail_problem(P, mode, "%s: the constraint rows differ", what);
    }
}

/* A witness of mode (from wc_modes_enumerate): it satisfies the rows of
   wc_mode_constraints exactly, and our own evaluation of Table 1; it is a
   primitive integer vector, zero exactly for the mode nu = 0 holds.  */
static void
check_witness(const wc_problem_t P, const char * mode, const fmpz * nu,
              const char * what)
{
    fmpz_mat_t rows, ours;
    wc_relation * rel = NULL;
    int * our_rel = NULL;
    wc_error_t err;
    char * s = NULL;

    fmpz_mat_init(rows, 0, 3);
    fmpz_mat_init(ours, 0, 3);
    wc_error_init(err);
    if (wc_mode_constraints(rows, &rel, P, mode, err) != WC_OK)
        wctest_fail_problem(P, mode, "%s: wc_mode_constraints failed on a "
                            "listed mode: %s", what,
                            err->message ? err->message : "(no message)");
    check_rows_equal(P, mode, rows, rel, ours, &our_rel, what);
    s = twist_str(nu);
    if (ref_twist_satisfies(P, mode, nu) != 1)
        wctest_fail_problem(P, mode, "%s: witness %s violates Table 1 "
                            "(reference evaluation)", what, s);
    if (!rows_hold(rows, our_rel, nu))
        wctest_fail_problem(P, mode, "%s: witness %s violates the rows of "
                            "wc_mode_constraints", what, s);
    if (is_zero_mode(P, mode) ? !_fmpz_vec_is_zero(nu, 3)
        : !content_is(nu, 3, 1))
        wctest_fail_problem(P, mode, "%s: witness %s is not %s", what, s,
                            is_zero_mode(P, mode) ? "zero (nu = 0 holds "
                            "this mode)" : "a primitive integer vector");
    flint_free(s);
    free(rel);           /* malloc'd by the library */
    flint_free(our_rel);
    fmpz_mat_clear(rows);
    fmpz_mat_clear(ours);
    wc_error_clear(err);
}

static void
fprint_list(FILE * out, const char * label, char * const * modes,
            slong count)
{
    slong i;

    fprintf(out, "%s (%ld):", label, (long) count);
    for (i = 0; i < count; i++)
        fprintf(out, " %s", modes[i]);
    fputc('\n', out);
}

/* wc_modes_enumerate equals brute force exactly, or equals expect (a
   NULL-terminated list) when that is given; every witness holds.  */
static void
check_enumeration(const wc_problem_t P, const char * const * expect,
                  const char * what)
{
    wc_modes_t M;
    wc_error_t err;
    char ** ref = NULL;
    slong count = 0, i;
    int same;

    wc_modes_init(M);
    wc_error_init(err);
    if (wc_modes_enumerate(M, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "%s: wc_modes_enumerate failed: %s",
                            what, err->message ? err->message : "");
    if (expect != NULL)
    {
        while (expect[count] != NULL)
            count++;
        ref = (char **) expect;
    }
    else if (ref_modes_bruteforce(&ref, &count, P) != 0)
        wctest_fail_problem(P, NULL, "%s: the reference failed", what);

    same = (M->n == P->n && M->count == count);
    for (i = 0; i < count && same; i++)
        same = (M->modes[i] != NULL && strcmp(M->modes[i], ref[i]) == 0);
    if (!same)
    {
        fflush(stdout);
        if (M->n != P->n)
            fprintf(stderr, "modes record n = %ld\n", (long) M->n);
        fprint_list(stderr, "enumerated", M->modes, M->count);
        fprint_list(stderr, expect != NULL ? "expected" : "brute force",
                    ref, count);
        wctest_fail_problem(P, NULL, "%s: the feasible modes differ", what);
    }
    if (fmpz_mat_nrows(M->witness) != count
        || fmpz_mat_ncols(M->witness) != 3)
        wctest_fail_problem(P, NULL, "%s: witness matrix is %ld x %ld for "
                            "%ld modes", what,
                            (long) fmpz_mat_nrows(M->witness),
                            (long) fmpz_mat_ncols(M->witness), (long) count);
    for (i = 0; i < count; i++)
        check_witness(P, M->modes[i], fmpz_mat_entry(M->witness, i, 0), what);

    if (expect == NULL)
        ref_modes_free(ref, count);
    wc_modes_clear(M);
    wc_error_clear(err);
}

/* ---- one mode's certificate ---------------------------------------- */

/* Our verdict on a certificate, from its own fields: the witness
   satisfies the rows, or the multipliers are a Motzkin certificate.  */
static int
our_check(const wc_certificate_t C)
{
    slong m = fmpz_mat_nrows(C->rows), k;
    int * rel = flint_malloc(sizeof(int) * (m + 1));
    int ok = (fmpz_mat_ncols(C->rows) == 3);

    for (k = 0; k < m; k++)
    {
        rel[k] = (int) C->rel[k];
        if (rel[k] != REF_REL_GT && rel[k] != REF_REL_GE
            && rel[k] != REF_REL_EQ)
            ok = 0;
    }
    if (ok)
        ok = C->feasible ? rows_hold(C->rows, rel, C->witness)
            : motzkin_holds(C->rows, rel, C->mult);
    flint_free(rel);
    return ok;
}

/* wc_certificate_check on a tampered C must agree with our_check.  When
   the tampered certificate is still valid but its witness is no longer
   primitive (a witness + e_j may still satisfy every row), the header
   leaves open whether wc_certificate_check insists on primitivity, so
   either verdict is right and the case is skipped.  */
static void
expect_check(const wc_certificate_t C, const wc_problem_t P,
             const char * mode, const char * what, const char * tamper)
{
    int ours = our_check(C), theirs = wc_certificate_check(C);

    if (ours && C->feasible && !content_is(C->witness, 3, 1))
        return;
    if (ours != theirs)
        wctest_fail_problem(P, mode, "%s: after tampering (%s), "
                            "wc_certificate_check says %s, not %s", what,
                            tamper, theirs ? "valid" : "invalid",
                            ours ? "valid" : "invalid");
}

/* Tamper with the valid certificate C in place, one way at a time, each
   undone before the next: every way below but the first is built to break
   exactly one condition, so that a check that forgets any one of them is
   caught.  */
static void
check_tampering(wc_certificate_t C, const wc_problem_t P, const char * mode,
                const char * what)
{
    slong m = fmpz_mat_nrows(C->rows), k, j, npos_gt = 0;
    wc_relation * saved = flint_malloc(sizeof(wc_relation) * (m + 1));
    fmpz_t v;

    fmpz_init(v);
    for (k = 0; k < m; k++)
        saved[k] = C->rel[k];

    if (C->feasible)
    {
        /* one witness entry + 1 */
        j = wctest_randint(0, 2);
        fmpz_add_ui(C->witness + j, C->witness + j, 1);
        expect_check(C, P, mode, what, "witness entry + 1");
        fmpz_sub_ui(C->witness + j, C->witness + j, 1);

        /* a row the witness makes positive declared "=" (breaks the
           equality check only); a row it makes zero declared ">" (breaks
           the strictness check only)  */
        for (k = 0; k < m; k++)
        {
            _fmpz_vec_dot(v, C->rows->rows[k], C->witness, 3);
            C->rel[k] = fmpz_sgn(v) > 0 ? WC_REL_EQ : WC_REL_GT;
            expect_check(C, P, mode, what, fmpz_sgn(v) > 0
                         ? "a positive row made '='"
                         : "a zero row made '>'");
            C->rel[k] = saved[k];
        }
    }
    else
    {
        /* one multiplier + 1 (breaks sum y_k row_k = 0, no row being 0) */
        k = wctest_randint(0, m - 1);
        fmpz_add_ui(C->mult + k, C->mult + k, 1);
        expect_check(C, P, mode, what, "multiplier + 1");
        fmpz_sub_ui(C->mult + k, C->mult + k, 1);

        for (k = 0; k < m; k++)
            npos_gt += (C->rel[k] == WC_REL_GT && fmpz_sgn(C->mult + k) > 0);

        /* a multiplier of an inequality row made negative, its row
           negated: the sum stays zero, and a positive '>' multiplier
           remains (k is '>=' or another '>' is positive), so only the
           sign condition breaks  */
        for (k = 0; k < m; k++)
            if (fmpz_sgn(C->mult + k) > 0
                && (C->rel[k] == WC_REL_GE || npos_gt >= 2))
            {
                fmpz_neg(C->mult + k, C->mult + k);
                _fmpz_vec_neg(C->rows->rows[k], C->rows->rows[k], 3);
                expect_check(C, P, mode, what, "a negative multiplier on "
                             "an inequality");
                fmpz_neg(C->mult + k, C->mult + k);
                _fmpz_vec_neg(C->rows->rows[k], C->rows->rows[k], 3);
                break;
            }

        /* every '>' row declared '>=': nothing strict is left  */
        for (k = 0; k < m; k++)
            if (C->rel[k] == WC_REL_GT)
                C->rel[k] = WC_REL_GE;
        expect_check(C, P, mode, what, "every '>' made '>='");
        for (k = 0; k < m; k++)
            C->rel[k] = saved[k];
    }

    /* the verdict flipped: the other half proves nothing (unless it
       happens to, which expect_check allows for)  */
    C->feasible = !C->feasible;
    expect_check(C, P, mode, what, "verdict flipped");
    C->feasible = !C->feasible;

    if (!wc_certificate_check(C))
        wctest_fail_problem(P, mode, "%s: the restored certificate is "
                            "rejected", what);
    fmpz_clear(v);
    flint_free(saved);
}

static void
check_feasible(const wc_problem_t P, const char * mode, const char * what)
{
    wc_certificate_t C;
    wc_error_t err;
    fmpz_mat_t ours;
    int * rel = NULL;
    slong m;
    int ref, feasible;
    char * s;

    wc_certificate_init(C);
    wc_error_init(err);
    fmpz_mat_init(ours, 0, 3);

    if (wc_feasible(C, P, mode, err) != WC_OK)
        wctest_fail_problem(P, mode, "%s: wc_feasible failed: %s", what,
                            err->message ? err->message : "");
    ref = ref_mode_feasible(P, mode);
    if (ref < 0)
        wctest_fail_problem(P, mode, "%s: the reference LP failed", what);
    feasible = (C->feasible != 0);
    if (feasible != ref)
        wctest_fail_problem(P, mode, "%s: wc_feasible says %s, the "
                            "reference %s", what,
                            feasible ? "feasible" : "infeasible",
                            ref ? "feasible" : "infeasible");
    if (C->mode == NULL || strcmp(C->mode, mode) != 0)
        wctest_fail_problem(P, mode, "%s: certificate names mode %s", what,
                            C->mode ? C->mode : "(null)");
    check_rows_equal(P, mode, C->rows, C->rel, ours, &rel, what);
    m = fmpz_mat_nrows(ours);
    if (!wc_certificate_check(C))
        wctest_fail_problem(P, mode, "%s: wc_certificate_check rejects "
                            "wc_feasible's own certificate", what);

    s = twist_str(C->witness);
    if (feasible)
    {
        if (ref_twist_satisfies(P, mode, C->witness) != 1
            || !rows_hold(ours, rel, C->witness))
            wctest_fail_problem(P, mode, "%s: witness %s does not satisfy "
                                "the mode", what, s);
        if (!content_is(C->witness, 3, 1)
            && !(_fmpz_vec_is_zero(C->witness, 3) && !has_strict(rel, m)))
            wctest_fail_problem(P, mode, "%s: witness %s is not primitive",
                                what, s);
        if (!_fmpz_vec_is_zero(C->mult, m))
            wctest_fail_problem(P, mode, "%s: a feasible certificate with "
                                "nonzero multipliers", what);
    }
    else
    {
        if (!motzkin_holds(ours, rel, C->mult))
            wctest_fail_problem(P, mode, "%s: the multipliers are not a "
                                "Motzkin certificate", what);
        if (!content_is(C->mult, m, 1))
            wctest_fail_problem(P, mode, "%s: the multipliers are not "
                                "primitive integers", what);
        if (!support_is_basic(ours, rel, C->mult))
            wctest_fail_problem(P, mode, "%s: the multipliers are not a "
                                "basic solution (dependent support)", what);
    }

    check_tampering(C, P, mode, what);

    flint_free(s);
    flint_free(rel);
    fmpz_mat_clear(ours);
    wc_certificate_clear(C);
    wc_error_clear(err);
}

/* wc_feasible with a certificate that already holds an answer (FLINT
   style: outputs are initialised objects, refilled): the verdict must be
   the oracle's, the certificate valid and about this mode.  */
static void
check_reused(wc_certificate_t C, const wc_problem_t P, const char * mode,
             const char * what)
{
    wc_error_t err;

    wc_error_init(err);
    if (wc_feasible(C, P, mode, err) != WC_OK)
        wctest_fail_problem(P, mode, "%s: wc_feasible failed on a reused "
                            "certificate: %s", what,
                            err->message ? err->message : "");
    if ((C->feasible != 0) != ref_mode_feasible(P, mode)
        || C->mode == NULL || strcmp(C->mode, mode) != 0
        || fmpz_mat_nrows(C->rows) < P->n || !wc_certificate_check(C))
        wctest_fail_problem(P, mode, "%s: wrong answer on a reused "
                            "certificate", what);
    wc_error_clear(err);
}

/* wc_feasible on some random Table 1 strings of P (mostly infeasible once
   n > 2) and on one listed mode (feasible), each against the oracle; then
   all of them again through one reused certificate, and the enumeration
   again into the same (filled) record.  */
static void
check_random_modes(const wc_problem_t P, slong tries, const char * what)
{
    char * modes = flint_malloc((tries + 1) * (P->n + 1));
    wc_certificate_t C;
    wc_modes_t M;
    wc_error_t err;
    slong t, count = 0;

    for (t = 0; t < tries; t++)
    {
        char * mode = modes + count++ * (P->n + 1);

        wctest_random_mode_kinematic(mode, P);
        check_feasible(P, mode, what);
    }
    wc_modes_init(M);
    wc_error_init(err);
    if (wc_modes_enumerate(M, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "%s: wc_modes_enumerate failed", what);
    if (M->count > 0)
    {
        char * mode = modes + count++ * (P->n + 1);

        strcpy(mode, M->modes[wctest_randint(0, M->count - 1)]);
        check_feasible(P, mode, what);
    }
    if (wc_modes_enumerate(M, P, err) != WC_OK || M->n != P->n
        || fmpz_mat_nrows(M->witness) != M->count)
        wctest_fail_problem(P, NULL, "%s: wc_modes_enumerate into a filled "
                            "record failed", what);

    wc_certificate_init(C);
    for (t = 0; t < count; t++)
        check_reused(C, P, modes + t * (P->n + 1), what);
    wc_certificate_clear(C);

    wc_modes_clear(M);
    wc_error_clear(err);
    flint_free(modes);
}

/* ---- beyond brute force -------------------------------------------- */

static int
in_list(char * const * modes, slong count, const char * mode)
{
    slong lo = 0, hi = count - 1;

    while (lo <= hi)
    {
        slong mid = lo + (hi - lo) / 2;
        int c = strcmp(modes[mid], mode);

        if (c == 0)
            return 1;
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return 0;
}

/* n too large for brute force: the list is sorted and duplicate-free,
   every listed mode has a valid witness, a random string or a one-letter
   neighbour of a listed mode is listed iff the oracle finds it feasible,
   and the same problem moved, rescaled and permuted has the same list.  */
static void
check_large(const wc_problem_t P, const char * what)
{
    wc_modes_t M, N;
    wc_problem_t Q;
    wc_error_t err;
    slong n = P->n, i, j, t;
    slong * perm = flint_malloc(sizeof(slong) * n);
    char * mode = flint_malloc(n + 1), * pm = flint_malloc(n + 1);
    fmpq shift[2];

    wc_modes_init(M);
    wc_modes_init(N);
    wc_error_init(err);
    if (wc_modes_enumerate(M, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "%s: wc_modes_enumerate failed", what);
    if (M->n != n || fmpz_mat_nrows(M->witness) != M->count)
        wctest_fail_problem(P, NULL, "%s: malformed modes record", what);
    for (i = 0; i < M->count; i++)
    {
        if (strlen(M->modes[i]) != (size_t) n
            || (i > 0 && strcmp(M->modes[i - 1], M->modes[i]) >= 0))
            wctest_fail_problem(P, M->modes[i], "%s: list not sorted, "
                                "distinct, of length n", what);
        check_witness(P, M->modes[i], fmpz_mat_entry(M->witness, i, 0),
                      what);
    }

    /* completeness, where it is most likely to fail: next to the list */
    for (t = 0; t < 60; t++)
    {
        int ref;

        if (t % 3 == 0 || M->count == 0)
            wctest_random_mode_kinematic(mode, P);
        else
        {
            const char * set;

            strcpy(mode, M->modes[wctest_randint(0, M->count - 1)]);
            i = wctest_randint(0, n - 1);
            set = P->fixels[i].state == WC_NEAR ? "sa" : "slrn";
            mode[i] = set[wctest_randint(0, (slong) strlen(set) - 1)];
        }
        ref = ref_mode_feasible(P, mode);
        if (ref < 0)
            wctest_fail_problem(P, mode, "%s: the reference LP failed", what);
        if (ref != in_list(M->modes, M->count, mode))
            wctest_fail_problem(P, mode, "%s: the mode is %s", what,
                                ref ? "feasible but not listed"
                                : "infeasible but listed");
    }

    /* invariance */
    for (i = 0; i < n; i++)
        perm[i] = i;
    for (i = n - 1; i > 0; i--)
    {
        slong k = wctest_randint(0, i), x = perm[i];

        perm[i] = perm[k];
        perm[k] = x;
    }
    fmpq_init(shift + 0);
    fmpq_init(shift + 1);
    wctest_rand_fmpq(shift + 0, 3, 2);
    wctest_rand_fmpq(shift + 1, 3, 2);
    wc_problem_init(Q);
    transformed_problem(Q, P, perm, shift);
    if (wc_modes_enumerate(N, Q, err) != WC_OK)
        wctest_fail_problem(Q, NULL, "%s: wc_modes_enumerate failed", what);
    if (N->count != M->count)
        wctest_fail_problem(Q, NULL, "%s: %ld modes after moving the com, "
                            "rescaling normals and permuting fixels; %ld "
                            "before", what, (long) N->count, (long) M->count);
    for (i = 0; i < N->count; i++)
    {
        for (j = 0; j < n; j++)
            pm[perm[j]] = N->modes[i][j];
        pm[n] = '\0';
        if (!in_list(M->modes, M->count, pm))
            wctest_fail_problem(Q, N->modes[i], "%s: transformed problem "
                                "lists a mode whose original %s is not "
                                "listed", what, pm);
    }
    wc_problem_clear(Q);
    fmpq_clear(shift + 0);
    fmpq_clear(shift + 1);

    flint_free(perm);
    flint_free(mode);
    flint_free(pm);
    wc_modes_clear(M);
    wc_modes_clear(N);
    wc_error_clear(err);
}

/* ---- bad modes ----------------------------------------------------- */

static void
check_bad_mode(const wc_problem_t P, const char * mode, long col)
{
    wc_certificate_t C;
    wc_error_t err;
    fmpz_mat_t rows;
    wc_relation * rel = NULL;
    int st;

    wc_certificate_init(C);
    wc_error_init(err);
    st = wc_feasible(C, P, mode, err);
    if (st != WC_EINPUT)
        wctest_fail_problem(P, mode, "wc_feasible returned %d on a bad "
                            "mode, not WC_EINPUT", st);
    if (err->file == NULL || strcmp(err->file, "<mode>") != 0
        || err->line != 1 || err->col != col || err->message == NULL)
        wctest_fail_problem(P, mode, "bad mode located at %s:%ld:%ld, not "
                            "<mode>:1:%ld (%s)",
                            err->file ? err->file : "(null)", err->line,
                            err->col, col,
                            err->message ? err->message : "no message");
    wc_certificate_clear(C);

    fmpz_mat_init(rows, 0, 3);
    st = wc_mode_constraints(rows, &rel, P, mode, err);
    if (st != WC_EINPUT)
        wctest_fail_problem(P, mode, "wc_mode_constraints returned %d on a "
                            "bad mode", st);
    free(rel);
    fmpz_mat_clear(rows);

    if (ref_mode_feasible(P, mode) != -1)
        wctest_fail_problem(P, mode, "the reference accepts a bad mode");
    wc_error_clear(err);
}

static void
test_bad_modes(void)
{
    wc_problem_t P;

    /* fixels: touching, near, touching */
    wc_problem_init(P);
    wctest_fixel_si(P, 0, -1, 0, 1, WC_TOUCHING);
    wctest_fixel_si(P, 1, 0, -1, 0, WC_NEAR);
    wctest_fixel_si(P, -1, 0, 1, 0, WC_TOUCHING);
    check_bad_mode(P, "", 1);
    check_bad_mode(P, "sa", 3);
    check_bad_mode(P, "sasn", 4);
    check_bad_mode(P, "xas", 1);
    check_bad_mode(P, "sAs", 2);
    check_bad_mode(P, "s s", 2);
    check_bad_mode(P, "sam", 3);        /* m: Table 2 only */
    check_bad_mode(P, "sus", 2);        /* u: Table 2 only */
    check_bad_mode(P, "aas", 1);        /* a on a touching fixel */
    check_bad_mode(P, "sla", 2);        /* l on a near fixel */
    check_bad_mode(P, "sna", 2);
    check_bad_mode(P, "ssa", 3);
    /* good ones are accepted and answered */
    check_feasible(P, "sas", "bad-mode problem");
    check_feasible(P, "nsn", "bad-mode problem");
    wc_problem_clear(P);
}

/* ---- fixed cases --------------------------------------------------- */

static void
test_fixed(void)
{
    static const char * const figure5[] =
        { "ll", "ls", "nn", "ns", "rr", "rs", "sl", "sn", "sr", "ss", NULL };
    /* Section 4 (fixel 2 near): v_1n = v_y, v_1t = -v_x - w, v_2n = -v_x;
       every one of the 8 strings has a twist (worked out by hand).  */
    static const char * const section4[] =
        { "la", "ls", "na", "ns", "ra", "rs", "sa", "ss", NULL };
    /* Two fixels at the centre of mass pushing up and down:
       v_1n = v_y = -v_2n, v_1t = -v_x = -v_2t, w free.  */
    static const char * const pinch[] = { "lr", "nn", "rl", NULL };
    static const char * const one_touching[] = { "l", "n", "r", "s", NULL };
    static const char * const one_near[] = { "a", "s", NULL };
    wc_problem_t P;

    wc_problem_init(P);
    paper_disk(P, WC_TOUCHING);
    check_enumeration(P, figure5, "Figure 5");
    check_enumeration(P, NULL, "Figure 5 (brute force)");
    check_feasible(P, "ln", "Figure 5");
    check_feasible(P, "ll", "Figure 5");
    check_feasible(P, "rl", "Figure 5");
    check_feasible(P, "nn", "Figure 5");
    wc_problem_clear(P);

    wc_problem_init(P);
    paper_disk(P, WC_NEAR);
    check_enumeration(P, section4, "Section 4");
    check_enumeration(P, NULL, "Section 4 (brute force)");
    wc_problem_clear(P);

    wc_problem_init(P);
    wctest_fixel_si(P, 0, 0, 0, 1, WC_TOUCHING);
    wctest_fixel_si(P, 0, 0, 0, -2, WC_TOUCHING);
    check_enumeration(P, pinch, "pinch");
    check_enumeration(P, NULL, "pinch (brute force)");
    check_feasible(P, "ss", "pinch");
    check_feasible(P, "ll", "pinch");
    wc_problem_clear(P);

    wc_problem_init(P);
    wctest_fixel_si(P, 2, 1, -1, 3, WC_TOUCHING);
    check_enumeration(P, one_touching, "one touching fixel");
    wc_problem_clear(P);

    wc_problem_init(P);
    wctest_fixel_si(P, 2, 1, -1, 3, WC_NEAR);
    check_enumeration(P, one_near, "one near fixel");
    wc_problem_clear(P);
}

/* ---- main ---------------------------------------------------------- */

int
main(void)
{
    /* Brute force costs 4^n LPs: many small problems, fewer large ones. */
    static const struct { slong nmin, nmax, iters; } plan[] =
        { { 1, 4, 100 }, { 5, 5, 16 }, { 6, 6, 6 } };
    char what[64];
    slong p, i, iters;

    wctest_init("t-modes");
    wc_init();

    test_fixed();
    test_bad_modes();

    for (p = 0; p < (slong) (sizeof plan / sizeof plan[0]); p++)
    {
        iters = wctest_iters(plan[p].iters);
        for (i = 0; i < iters; i++)
        {
            wc_problem_t P;

            if (!wctest_iter(i))
                continue;
            snprintf(what, sizeof what, "random n=%ld..%ld",
                     (long) plan[p].nmin, (long) plan[p].nmax);
            wc_problem_init(P);
            wctest_random_problem(P, plan[p].nmin, plan[p].nmax);
            check_enumeration(P, NULL, what);
            check_random_modes(P, 3, what);
            wc_problem_clear(P);
        }
    }

    iters = wctest_iters(60);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;
        int kind;
        slong n;

        if (!wctest_iter(i))
            continue;
        kind = (int) (i % DEG_COUNT);
        n = (i % 20 == 19) ? 6 : (i % 5 == 4) ? 5 : wctest_randint(2, 4);
        snprintf(what, sizeof what, "degenerate: %s", deg_name[kind]);
        wc_problem_init(P);
        degenerate_problem(P, kind, n);
        check_enumeration(P, NULL, what);
        check_random_modes(P, 3, what);
        wc_problem_clear(P);
    }

    /* Generic positions with large numerators and denominators: long
       primitive rows, and witnesses whose size the chamber step must get
       right.  */
    iters = wctest_iters(12);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        big_problem(P, wctest_randint(2, i % 10 == 9 ? 6 : 5));
        check_enumeration(P, NULL, "large coefficients");
        check_random_modes(P, 3, "large coefficients");
        wc_problem_clear(P);
    }

    iters = wctest_iters(12);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        if (i % 3 == 2)
        {
            int kind = (int) wctest_randint(0, DEG_SINGLE - 1);

            degenerate_problem(P, kind, wctest_randint(7, 14));
            snprintf(what, sizeof what, "large, degenerate: %s",
                     deg_name[kind]);
        }
        else
        {
            wctest_random_problem(P, 7, 14);
            snprintf(what, sizeof what, "large random");
        }
        check_large(P, what);
        wc_problem_clear(P);
    }

    flint_cleanup_master();
    return 0;
}
