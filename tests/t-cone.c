/* t-cone.c -- the NNC cone type: canonical form, face lattice, strictness.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   References: the face lattice by brute force over all subsets of facets;
   membership of an NNC cone by evaluating its defining system directly;
   canonical form by recomputing the same set from the other side (H from
   V, V from H) and from scaled, shuffled, redundant descriptions.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "wrenchcone.h"
#include "testutil.h"
#include "cddbridge.h"

#define ROW(A, i) ((A)->rows[i])

static void
rand_rows(fmpq_mat_t A, slong rows, slong range)
{
    slong i, j;

    fmpq_mat_clear(A);
    fmpq_mat_init(A, rows, 3);
    for (i = 0; i < rows; i++)
        for (j = 0; j < 3; j++)
            fmpq_set_si(fmpq_mat_entry(A, i, j),
                        wctest_randint(-range, range), 1);
    /* Degenerate layouts: repeat, negate or combine earlier rows.  */
    for (i = 1; i < rows; i++)
    {
        slong k = wctest_randint(0, i - 1), c = wctest_randint(0, 5);

        for (j = 0; j < 3; j++)
        {
            fmpq * x = fmpq_mat_entry(A, i, j);
            const fmpq * y = fmpq_mat_entry(A, k, j);

            if (c == 0)
                fmpq_mul_si(x, y, wctest_randint(1, 3));        /* parallel */
            else if (c == 1)
                fmpq_neg(x, y);                                 /* opposed */
            else if (c == 2 && j == 2)
                fmpq_zero(x);                                   /* planar */
        }
    }
}

static fmpq_mat_struct *
to_fmpq(fmpq_mat_t out, const fmpz_mat_t A)
{
    fmpq_mat_init(out, fmpz_mat_nrows(A), 3);
    fmpq_mat_set_fmpz_mat(out, A);
    return out;
}

static int
dot_sgn(const fmpz * a, const fmpz * b)
{
    fmpz_t s;
    int r;

    fmpz_init(s);
    _fmpz_vec_dot(s, a, b, 3);
    r = fmpz_sgn(s);
    fmpz_clear(s);
    return r;
}

static int
dot_sgn_q(const fmpq_mat_t A, slong i, const fmpz * p)
{
    fmpq_t s, t;
    slong j;
    int r;

    fmpq_init(s);
    fmpq_init(t);
    for (j = 0; j < 3; j++)
    {
        fmpq_mul_fmpz(t, fmpq_mat_entry(A, i, j), p + j);
        fmpq_add(s, s, t);
    }
    r = fmpq_sgn(s);
    fmpq_clear(s);
    fmpq_clear(t);
    return r;
}

/* The face lattice of C's closure by brute force: the ray sets of every
   intersection of a subset of facets, with C itself.  */
static void
check_faces(const wc_cone_t C)
{
    slong m = fmpz_mat_nrows(C->ineqs), k = fmpz_mat_nrows(C->rays);
    slong sub, i, j, f, found = 0;
    int * in = malloc(sizeof(int) * (k + 1));
    int * seen = calloc(C->nfaces + 1, sizeof(int));

    if (m > 12)
        wctest_fail("too many facets for the brute force: %ld", (long) m);
    for (sub = 0; sub < (WORD(1) << m); sub++)
    {
        for (j = 0; j < k; j++)
        {
            in[j] = 1;
            for (i = 0; i < m; i++)
                if (((sub >> i) & 1)
                    && dot_sgn(ROW(C->ineqs, i), ROW(C->rays, j)) != 0)
                    in[j] = 0;
        }
        for (f = 0; f < C->nfaces; f++)
        {
            const wc_face_struct * F = C->faces + f;
            slong c = 0;

            for (j = 0; j < k; j++)
                if (in[j] && (c >= F->nrays || F->rays[c++] != j))
                    break;
            if (j == k && c == F->nrays)
                break;
        }
        if (f == C->nfaces)
            wctest_fail("an intersection of facets is missing from the "
                        "face list");
        if (!seen[f])
            found++;
        seen[f] = 1;
    }
    if (found != C->nfaces)
        wctest_fail("%ld faces listed, %ld found by brute force",
                    (long) C->nfaces, (long) found);
    for (f = 0; f < C->nfaces; f++)
    {
        const wc_face_struct * F = C->faces + f;
        fmpz_mat_t R;

        fmpz_mat_init(R, F->nrays + 1, 3);
        for (j = 0; j < F->nrays; j++)
            _fmpz_vec_set(ROW(R, j), ROW(C->rays, F->rays[j]), 3);
        if (F->dim != C->lineality_dim + fmpz_mat_rank(R))
            wctest_fail("face %ld has dim %ld", (long) f, (long) F->dim);
        fmpz_mat_clear(R);
        if (f > 0 && F->dim < F[-1].dim)
            wctest_fail("faces not sorted by dimension");
    }
    if (C->faces[C->nfaces - 1].dim != C->dim)
        wctest_fail("the last face is not the cone itself");
    free(in);
    free(seen);
}

/* Canonical form: primitive vectors, sorted, rays orthogonal to lines,
   facets orthogonal to equalities, rays satisfy every constraint.  */
static void
check_canonical(const wc_cone_t C)
{
    slong i, j;
    fmpz_t g;

    fmpz_init(g);
    for (i = 0; i < fmpz_mat_nrows(C->rays); i++)
    {
        _fmpz_vec_content(g, ROW(C->rays, i), 3);
        if (!fmpz_is_one(g))
            wctest_fail("ray %ld not primitive", (long) i);
        if (i > 0 && _fmpz_vec_equal(ROW(C->rays, i), ROW(C->rays, i - 1), 3))
            wctest_fail("repeated ray");
        for (j = 0; j < fmpz_mat_nrows(C->lines); j++)
            if (dot_sgn(ROW(C->rays, i), ROW(C->lines, j)) != 0)
                wctest_fail("ray %ld not orthogonal to the lines", (long) i);
        for (j = 0; j < fmpz_mat_nrows(C->ineqs); j++)
            if (dot_sgn(ROW(C->ineqs, j), ROW(C->rays, i)) > 0)
                wctest_fail("ray %ld violates facet %ld", (long) i, (long) j);
        for (j = 0; j < fmpz_mat_nrows(C->eqs); j++)
            if (dot_sgn(ROW(C->eqs, j), ROW(C->rays, i)) != 0)
                wctest_fail("ray %ld violates equality %ld", (long) i, (long) j);
    }
    for (i = 0; i < fmpz_mat_nrows(C->ineqs); i++)
        for (j = 0; j < fmpz_mat_nrows(C->eqs); j++)
            if (dot_sgn(ROW(C->ineqs, i), ROW(C->eqs, j)) != 0)
                wctest_fail("facet %ld not in the linear hull", (long) i);
    if (C->dim + fmpz_mat_nrows(C->eqs) != 3
        || C->lineality_dim != fmpz_mat_nrows(C->lines))
        wctest_fail("dimensions inconsistent");
    fmpz_clear(g);
}

/* Random H-descriptions with strict rows: membership of face points and
   random points equals evaluating the system; V -> H -> V round trips
   give the same canonical cone.  */
static void
check_random(void)
{
    fmpq_mat_t E, H, S, R, L, A, B;
    wc_cone_t C, D;
    wc_error_t err;
    fmpz * p = _fmpz_vec_init(3);
    fmpq g[3];
    slong i, j, f;

    fmpq_mat_init(E, 0, 3);
    fmpq_mat_init(H, 0, 3);
    fmpq_mat_init(S, 0, 3);
    fmpq_mat_init(R, 0, 3);
    fmpq_mat_init(L, 0, 3);
    for (j = 0; j < 3; j++)
        fmpq_init(g + j);
    wc_cone_init(C, 3);
    wc_cone_init(D, 3);
    wc_error_init(err);

    /* From generators, then back from the canonical H.  */
    rand_rows(R, wctest_randint(0, 6), 3);
    rand_rows(L, wctest_chance(1, 4) ? 1 : 0, 2);
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("set_generators: %s", err->message);
    check_canonical(C);
    check_faces(C);
    if (C->empty || wc_cone_excluded_faces(C) != 0)
        wctest_fail("a cone from generators is empty or not closed");
    for (i = 0; i < fmpq_mat_nrows(R); i++)
        if (!wc_cone_contains(C, fmpq_mat_entry(R, i, 0)))
            wctest_fail("generator %ld is not in its cone", (long) i);
    if (wc_cone_set_hrep(D, to_fmpq(A, C->eqs), to_fmpq(B, C->ineqs), NULL,
                         err) != WC_OK)
        wctest_fail("set_hrep: %s", err->message);
    if (!wc_cone_equal(C, D))
        wctest_fail("V -> H -> V changes the cone");
    /* The two conversion kernels, hull3.c and cddlib, agree.  */
    if (_wc_cone_set_generators_kernel(D, R, L, 1, err) != WC_OK)
        wctest_fail("set_generators (cddlib): %s", err->message);
    if (!wc_cone_equal(C, D))
        wctest_fail("hull3 and cddlib disagree on a cone from generators");
    fmpq_mat_clear(A);
    fmpq_mat_clear(B);
    /* The same cone from its canonical rays, each scaled, plus redundant
       sums of rays: still equal.  */
    {
        slong k = fmpz_mat_nrows(C->rays);

        fmpq_mat_clear(R);
        fmpq_mat_init(R, k + 1, 3);
        for (i = 0; i < k; i++)
            for (j = 0; j < 3; j++)
            {
                fmpq_set_fmpz(fmpq_mat_entry(R, k - 1 - i, j),
                              ROW(C->rays, i) + j);
                fmpq_mul_si(fmpq_mat_entry(R, k - 1 - i, j),
                            fmpq_mat_entry(R, k - 1 - i, j), i + 2);
                fmpq_add_fmpz(fmpq_mat_entry(R, k, j),
                              fmpq_mat_entry(R, k, j), ROW(C->rays, i) + j);
            }
        if (wc_cone_set_generators(D, R, to_fmpq(A, C->lines), err) != WC_OK)
            wctest_fail("set_generators: %s", err->message);
        fmpq_mat_clear(A);
        if (!wc_cone_equal(C, D))
            wctest_fail("scaled, reordered, redundant generators change the cone");
    }

    /* NNC from random constraints.  */
    rand_rows(E, wctest_chance(1, 5) ? 1 : 0, 2);
    rand_rows(H, wctest_randint(0, 5), 3);
    rand_rows(S, wctest_randint(0, 3), 3);
    if (wc_cone_set_hrep(C, E, H, S, err) != WC_OK)
        wctest_fail("set_hrep: %s", err->message);
    if (_wc_cone_set_hrep_kernel(D, E, H, S, 1, err) != WC_OK)
        wctest_fail("set_hrep (cddlib): %s", err->message);
    if (!wc_cone_equal(C, D))
        wctest_fail("hull3 and cddlib disagree on an NNC cone");
    if (!C->empty)
    {
        check_canonical(C);
        check_faces(C);
    }
    /* Points: every face point of the closure of the non-strict system,
       and random ones.  */
    if (wc_cone_set_hrep(D, E, H, NULL, err) != WC_OK)
        wctest_fail("set_hrep: %s", err->message);
    for (f = -8; f < D->nfaces; f++)
    {
        int want = 1;

        if (f < 0)
            for (j = 0; j < 3; j++)
                fmpz_set_si(p + j, wctest_randint(-2, 2));
        else
        {
            _fmpz_vec_zero(p, 3);
            for (i = 0; i < D->faces[f].nrays; i++)
                _fmpz_vec_add(p, p, ROW(D->rays, D->faces[f].rays[i]), 3);
        }
        for (i = 0; i < fmpq_mat_nrows(E); i++)
            want &= dot_sgn_q(E, i, p) == 0;
        for (i = 0; i < fmpq_mat_nrows(H); i++)
            want &= dot_sgn_q(H, i, p) <= 0;
        for (i = 0; i < fmpq_mat_nrows(S); i++)
            want &= dot_sgn_q(S, i, p) < 0;
        for (j = 0; j < 3; j++)
            fmpq_set_fmpz(g + j, p + j);
        if (wc_cone_contains(C, g) != want)
            wctest_fail("NNC membership of a point: cone says %d, the "
                        "system %d", !want, want);
    }

    fmpq_mat_clear(E);
    fmpq_mat_clear(H);
    fmpq_mat_clear(S);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
    for (j = 0; j < 3; j++)
        fmpq_clear(g + j);
    _fmpz_vec_clear(p, 3);
    wc_cone_clear(C);
    wc_cone_clear(D);
    wc_error_clear(err);
}

/* Hand-checked cones: exact canonical JSON.  */
static void
check_json(const char * what, const char * rays, const char * lines,
           const char * want)
{
    fmpq_mat_t R, L;
    wc_cone_t C;
    wc_error_t err;
    char * buf = NULL;
    size_t len = 0;
    FILE * f;
    slong nr = 0, nl = 0, i;
    const char * s;
    char * end;

    for (s = rays; *s; s++)
        nr += *s == ';';
    for (s = lines; *s; s++)
        nl += *s == ';';
    fmpq_mat_init(R, nr, 3);
    fmpq_mat_init(L, nl, 3);
    for (s = rays, i = 0; i < 3 * nr; i++, s = end + (*end == ';'))
        fmpq_set_si(fmpq_mat_entry(R, i / 3, i % 3), strtol(s, &end, 10), 1);
    for (s = lines, i = 0; i < 3 * nl; i++, s = end + (*end == ';'))
        fmpq_set_si(fmpq_mat_entry(L, i / 3, i % 3), strtol(s, &end, 10), 1);
    wc_cone_init(C, 3);
    wc_error_init(err);
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("%s: %s", what, err->message);
    f = open_memstream(&buf, &len);
    wc_cone_fprint_json(f, C);
    fclose(f);
    if (strcmp(buf, want) != 0)
        wctest_fail("%s:\n got  %s\n want %s", what, buf, want);
    free(buf);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
    wc_cone_clear(C);
    wc_error_clear(err);
}

int
main(void)
{
    slong i, iters;

    wctest_init("t-cone");
    check_json("apex", "", "",
               "{\"empty\": false, \"dim\": 0, \"lineality_dim\": 0, "
               "\"inequalities\": [], \"equalities\": [[\"1\", \"0\", \"0\"], "
               "[\"0\", \"1\", \"0\"], [\"0\", \"0\", \"1\"]], \"rays\": [], "
               "\"lines\": [], \"faces\": [{\"dim\": 0, \"rays\": [], "
               "\"included\": true}]}");
    check_json("ray", "2 4 6;", "",
               "{\"empty\": false, \"dim\": 1, \"lineality_dim\": 0, "
               "\"inequalities\": [[\"-1\", \"-2\", \"-3\"]], "
               "\"equalities\": [[\"3\", \"0\", \"-1\"], [\"0\", \"3\", \"-2\"]], "
               "\"rays\": [[\"1\", \"2\", \"3\"]], \"lines\": [], \"faces\": ["
               "{\"dim\": 0, \"rays\": [], \"included\": true}, "
               "{\"dim\": 1, \"rays\": [0], \"included\": true}]}");
    check_json("half-plane from opposed rays", "1 0 0;-3 0 0;0 5 0;", "",
               "{\"empty\": false, \"dim\": 2, \"lineality_dim\": 1, "
               "\"inequalities\": [[\"0\", \"-1\", \"0\"]], "
               "\"equalities\": [[\"0\", \"0\", \"1\"]], "
               "\"rays\": [[\"0\", \"1\", \"0\"]], \"lines\": [[\"1\", \"0\", \"0\"]], "
               "\"faces\": [{\"dim\": 1, \"rays\": [], \"included\": true}, "
               "{\"dim\": 2, \"rays\": [0], \"included\": true}]}");
    check_json("whole space", "1 0 0;0 1 0;0 0 1;-1 -1 -1;", "",
               "{\"empty\": false, \"dim\": 3, \"lineality_dim\": 3, "
               "\"inequalities\": [], \"equalities\": [], \"rays\": [], "
               "\"lines\": [[\"1\", \"0\", \"0\"], [\"0\", \"1\", \"0\"], "
               "[\"0\", \"0\", \"1\"]], \"faces\": [{\"dim\": 3, \"rays\": [], "
               "\"included\": true}]}");
    check_json("half-space, ray projected off the lines", "1 1 1;", "1 0 0;0 1 0;",
               "{\"empty\": false, \"dim\": 3, \"lineality_dim\": 2, "
               "\"inequalities\": [[\"0\", \"0\", \"-1\"]], \"equalities\": [], "
               "\"rays\": [[\"0\", \"0\", \"1\"]], \"lines\": [[\"1\", \"0\", \"0\"], "
               "[\"0\", \"1\", \"0\"]], \"faces\": [{\"dim\": 2, \"rays\": [], "
               "\"included\": true}, {\"dim\": 3, \"rays\": [0], \"included\": true}]}");

    iters = wctest_iters(400);
    for (i = 0; i < iters; i++)
        if (wctest_iter(i))
            check_random();
    flint_cleanup_master();
    return 0;
}
