/* t-routes.c -- both routes to W(x) agree byte for byte, and membership
   read from the canonical cone equals the independent LP on eq. (7).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   For random problems (1-4 fixels, degenerate layouts included) and random
   modes: (a) the direct and the paper route print the same canonical JSON;
   (b) for random wrenches and boundary wrenches -- every closure ray and
   its negative, the sum of every face's rays, every friction-cone edge of
   every touching fixel and sums of pairs of them -- membership read from
   the cone's faces equals ref_wrench_in_cone (tests/ref-lp.c), and so
   does wc_cone_contains; (c) emptiness equals ref_cone_nonempty.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "testutil.h"
#include "ref-lp.h"

#define ROW(A, i) ((A)->rows[i])

/* Membership read from the canonical output, face by face: g lies in the
   relative interior of face F iff it satisfies the equalities, is tight on
   exactly the facets that contain all of F's rays, and strictly inside the
   others; g is in W iff that face is included.  (A different reading from
   wc_cone_locate's, on purpose.)  */
static int
member_from_faces(const wc_cone_t W, const fmpq * g)
{
    slong f, i, j, m, hits = 0;
    int in = 0;

    if (W->empty)
        return 0;
    for (i = 0; i < fmpz_mat_nrows(W->eqs); i++)
        if (wctest_dot3_sgn_z(ROW(W->eqs, i), g) != 0)
            return 0;
    m = fmpz_mat_nrows(W->ineqs);
    for (f = 0; f < W->nfaces; f++)
    {
        const wc_face_struct * F = W->faces + f;
        int ok = 1;

        for (i = 0; i < m && ok; i++)
        {
            int contains = 1, s = wctest_dot3_sgn_z(ROW(W->ineqs, i), g);

            for (j = 0; j < F->nrays && contains; j++)
            {
                fmpz_t d;
                slong k;

                fmpz_init(d);
                for (k = 0; k < 3; k++)
                    fmpz_addmul(d, ROW(W->ineqs, i) + k,
                                ROW(W->rays, F->rays[j]) + k);
                contains = fmpz_is_zero(d);
                fmpz_clear(d);
            }
            /* A face with no rays, the lineality space, lies in every
               facet.  */
            if (contains ? s != 0 : s >= 0)
                ok = 0;
        }
        if (ok)
        {
            hits++;
            in = F->included;
        }
    }
    if (hits > 1)
        wctest_fail("a wrench lies in the relative interior of %ld faces",
                    (long) hits);
    return in;
}

static void
check_wrench(const wc_problem_t P, const char * mode, const wc_cone_t W,
             const fmpq * g, const char * what)
{
    int ref = ref_wrench_in_cone(P, mode, g);
    int faces = member_from_faces(W, g);
    int lib = wc_cone_contains(W, g);

    if (ref < 0)
        wctest_fail_problem(P, mode, "reference LP failed");
    if (ref != faces || ref != lib)
    {
        char * s = wctest_vec_str(g, 3);

        wctest_fail_problem(P, mode, "%s wrench %s: reference LP says %d, "
                            "the cone's faces say %d, wc_cone_contains %d",
                            what, s, ref, faces, lib);
    }
}

static void
set_vec_fmpz(fmpq * g, const fmpz * v)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_set_fmpz(g + j, v + j);
}

/* Every boundary and random wrench of (b) for one problem and mode.  */
static void
check_members(const wc_problem_t P, const char * mode, const wc_cone_t W)
{
    slong n = P->n, i, j, f, k, ne = 0;
    fmpq g[3], h[3], e[4];
    fmpq_mat_t J;
    fmpq * edges = _fmpq_vec_init(3 * 4 * n);
    fmpz_t sixtyfour;

    for (j = 0; j < 3; j++)
    {
        fmpq_init(g + j);
        fmpq_init(h + j);
    }
    for (j = 0; j < 4; j++)
        fmpq_init(e + j);
    fmpq_mat_init(J, 3, 2 * n);
    wc_model_J(J, P);
    fmpz_init(sixtyfour);

    for (i = 0; i < 4; i++)
    {
        wctest_random_wrench(g);
        check_wrench(P, mode, W, g, "random");
    }
    if (!W->empty)
    {
        for (i = 0; i < fmpz_mat_nrows(W->rays); i++)
        {
            set_vec_fmpz(g, ROW(W->rays, i));
            check_wrench(P, mode, W, g, "ray");
            for (j = 0; j < 3; j++)
                fmpq_neg(g + j, g + j);
            check_wrench(P, mode, W, g, "negated ray");
        }
        for (i = 0; i < fmpz_mat_nrows(W->lines); i++)
        {
            set_vec_fmpz(g, ROW(W->lines, i));
            check_wrench(P, mode, W, g, "line");
        }
        for (f = 0; f < W->nfaces; f++)
        {
            for (j = 0; j < 3; j++)
                fmpq_zero(g + j);
            for (k = 0; k < W->faces[f].nrays; k++)
                for (j = 0; j < 3; j++)
                    fmpq_add_fmpz(g + j, g + j,
                                  ROW(W->rays, W->faces[f].rays[k]) + j);
            check_wrench(P, mode, W, g, "face point");
            /* A face point nudged along a random direction: near the
               boundary, often just outside.  */
            wctest_random_wrench(h);
            fmpz_set_si(sixtyfour, 64);
            for (j = 0; j < 3; j++)
            {
                fmpq_div_fmpz(h + j, h + j, sixtyfour);
                fmpq_add(h + j, h + j, g + j);
            }
            check_wrench(P, mode, W, h, "nudged face point");
        }
    }
    /* Friction-cone edges of every touching fixel, as wrenches -J d.  */
    for (i = 0; i < n; i++)
    {
        slong c;

        if (P->fixels[i].state != WC_TOUCHING)
            continue;
        c = wc_friction_edges(e, P->fixels + i, 'n');
        for (k = 0; k < c; k++, ne++)
            for (j = 0; j < 3; j++)
            {
                fmpq * x = edges + 3 * ne + j;

                fmpq_mul(x, e + 2 * k, fmpq_mat_entry(J, j, i));
                fmpq_addmul(x, e + 2 * k + 1, fmpq_mat_entry(J, j, n + i));
                fmpq_neg(x, x);
            }
    }
    for (i = 0; i < ne; i++)
    {
        check_wrench(P, mode, W, edges + 3 * i, "friction edge");
        for (j = 0; j < 3; j++)
            fmpq_neg(g + j, edges + 3 * i + j);
        check_wrench(P, mode, W, g, "negated friction edge");
        for (k = i + 1; k < ne; k++)
        {
            for (j = 0; j < 3; j++)
                fmpq_add(g + j, edges + 3 * i + j, edges + 3 * k + j);
            check_wrench(P, mode, W, g, "sum of friction edges");
        }
    }

    for (j = 0; j < 3; j++)
    {
        fmpq_clear(g + j);
        fmpq_clear(h + j);
    }
    for (j = 0; j < 4; j++)
        fmpq_clear(e + j);
    fmpq_mat_clear(J);
    _fmpq_vec_clear(edges, 3 * 4 * n);
    fmpz_clear(sixtyfour);
}

static void
check_mode(const wc_problem_t P, const char * mode, int members)
{
    wc_cone_t A, B;
    wc_error_t err;
    char * ja, * jb;
    int ref;

    wc_cone_init(A, 3);
    wc_cone_init(B, 3);
    wc_error_init(err);
    if (wc_mode_check(P, mode, WC_TABLE_CONE, err) != WC_OK)
        wctest_fail_problem(P, mode, "generated mode rejected: %s", err->message);
    if (wc_wrench_cone_direct(A, NULL, P, mode, err) != WC_OK)
        wctest_fail_problem(P, mode, "direct route failed: %s", err->message);
    if (wc_wrench_cone_paper(B, NULL, P, mode, err) != WC_OK)
        wctest_fail_problem(P, mode, "paper route failed: %s", err->message);
    ja = wctest_cone_json(A);
    jb = wctest_cone_json(B);
    if (strcmp(ja, jb) != 0 || !wc_cone_equal(A, B))
        wctest_fail_problem(P, mode, "routes differ:\n direct %s\n paper  %s",
                            ja, jb);
    ref = ref_cone_nonempty(P, mode);
    if (ref < 0 || ref == A->empty)
        wctest_fail_problem(P, mode, "emptiness: reference %d, cone %s", ref,
                            ja);
    if (members)
        check_members(P, mode, A);
    free(ja);
    free(jb);
    wc_error_clear(err);
    wc_cone_clear(A);
    wc_cone_clear(B);
}

/* Every Table 2 mode of a small problem, both routes.  */
static void
check_all_modes(const wc_problem_t P)
{
    slong n = P->n, i, total = 1;
    char * mode = malloc(n + 1);
    slong * digit = calloc(n + 1, sizeof(slong));

    for (i = 0; i < n; i++)
        total *= P->fixels[i].state == WC_TOUCHING ? 5 : 3;
    for (; total > 0; total--)
    {
        for (i = 0; i < n; i++)
            mode[i] = (P->fixels[i].state == WC_TOUCHING
                       ? "slrnm" : "sau")[digit[i]];
        mode[n] = '\0';
        check_mode(P, mode, 0);
        for (i = 0; i < n; i++)
        {
            if (++digit[i] < (P->fixels[i].state == WC_TOUCHING ? 5 : 3))
                break;
            digit[i] = 0;
        }
    }
    free(mode);
    free(digit);
}

int
main(void)
{
    slong iters, i, k;

    wctest_init("t-routes");
    iters = wctest_iters(34);     /* 102 in CI's widened run */
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;
        char mode[8];

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        wctest_random_problem(P, 1, 4);
        for (k = 0; k < 2; k++)
        {
            wctest_random_mode(mode, P);
            check_mode(P, mode, 1);
        }
        if (P->n <= 2 || (P->n == 3 && i % 10 == 0))
            check_all_modes(P);
        wc_problem_clear(P);
    }
    flint_cleanup_master();
    return 0;
}
