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
#include "exact/cddbridge.h"

#include <cddlib/setoper.h>
#include <cddlib/cdd.h>

#define ROW(A, i) ((A)->rows[i])

static void
rand_rows_d(fmpq_mat_t A, slong rows, slong range, slong d)
{
    slong i, j;

    fmpq_mat_clear(A);
    fmpq_mat_init(A, rows, d);
    for (i = 0; i < rows; i++)
        for (j = 0; j < d; j++)
            fmpq_set_si(fmpq_mat_entry(A, i, j),
                        wctest_randint(-range, range), 1);
    /* Degenerate layouts: repeat, negate or combine earlier rows.  */
    for (i = 1; i < rows; i++)
    {
        slong k = wctest_randint(0, i - 1), c = wctest_randint(0, 5);

        for (j = 0; j < d; j++)
        {
            fmpq * x = fmpq_mat_entry(A, i, j);
            const fmpq * y = fmpq_mat_entry(A, k, j);

            if (c == 0)
                fmpq_mul_si(x, y, wctest_randint(1, 3));        /* parallel */
            else if (c == 1)
                fmpq_neg(x, y);                                 /* opposed */
            else if (c == 2 && j == d - 1)
                fmpq_zero(x);                                   /* planar */
        }
    }
}

static fmpq_mat_struct *
to_fmpq(fmpq_mat_t out, const fmpz_mat_t A)
{
    fmpq_mat_init(out, fmpz_mat_nrows(A), fmpz_mat_ncols(A));
    fmpq_mat_set_fmpz_mat(out, A);
    return out;
}

static slong dim = 3;        /* of the cone under test */

static int
dot_sgn(const fmpz * a, const fmpz * b)
{
    fmpz_t s;
    int r;

    fmpz_init(s);
    _fmpz_vec_dot(s, a, b, dim);
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
    for (j = 0; j < dim; j++)
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

        fmpz_mat_init(R, F->nrays + 1, dim);
        for (j = 0; j < F->nrays; j++)
            _fmpz_vec_set(ROW(R, j), ROW(C->rays, F->rays[j]), dim);
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
        _fmpz_vec_content(g, ROW(C->rays, i), dim);
        if (!fmpz_is_one(g))
            wctest_fail("ray %ld not primitive", (long) i);
        if (i > 0 && _fmpz_vec_equal(ROW(C->rays, i), ROW(C->rays, i - 1), dim))
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
    if (C->dim + fmpz_mat_nrows(C->eqs) != dim
        || C->lineality_dim != fmpz_mat_nrows(C->lines))
        wctest_fail("dimensions inconsistent");
    fmpz_clear(g);
}

/* Random H-descriptions with strict rows: membership of face points and
   random points equals evaluating the system; V -> H -> V round trips
   give the same canonical cone.  */
static void
check_random(slong d)
{
    fmpq_mat_t E, H, S, R, L, A, B;
    wc_cone_t C, D;
    wc_error_t err;
    fmpz * p;
    fmpq * g;
    slong i, j, f;

    dim = d;                    /* read by the helpers above */
    p = _fmpz_vec_init(dim);
    g = _fmpq_vec_init(dim);
    fmpq_mat_init(E, 0, dim);
    fmpq_mat_init(H, 0, dim);
    fmpq_mat_init(S, 0, dim);
    fmpq_mat_init(R, 0, dim);
    fmpq_mat_init(L, 0, dim);
    wc_cone_init(C, dim);
    wc_cone_init(D, dim);
    wc_error_init(err);

    /* From generators, then back from the canonical H.  */
    rand_rows_d(R, wctest_randint(0, 6), 3, dim);
    rand_rows_d(L, wctest_chance(1, 4) ? wctest_randint(1, 3) : 0, 2, dim);
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
        fmpq_mat_init(R, k + 1, dim);
        for (i = 0; i < k; i++)
            for (j = 0; j < dim; j++)
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
    rand_rows_d(E, wctest_chance(1, 4) ? wctest_randint(1, 3) : 0, 2, dim);
    rand_rows_d(H, wctest_randint(0, 5), 3, dim);
    rand_rows_d(S, wctest_randint(0, 3), 3, dim);
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
            for (j = 0; j < dim; j++)
                fmpz_set_si(p + j, wctest_randint(-2, 2));
        else
        {
            _fmpz_vec_zero(p, dim);
            for (i = 0; i < D->faces[f].nrays; i++)
                _fmpz_vec_add(p, p, ROW(D->rays, D->faces[f].rays[i]), dim);
        }
        for (i = 0; i < fmpq_mat_nrows(E); i++)
            want &= dot_sgn_q(E, i, p) == 0;
        for (i = 0; i < fmpq_mat_nrows(H); i++)
            want &= dot_sgn_q(H, i, p) <= 0;
        for (i = 0; i < fmpq_mat_nrows(S); i++)
            want &= dot_sgn_q(S, i, p) < 0;
        for (j = 0; j < dim; j++)
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
    _fmpq_vec_clear(g, dim);
    _fmpz_vec_clear(p, dim);
    wc_cone_clear(C);
    wc_cone_clear(D);
    wc_error_clear(err);
}

/* The reference for wc_cone_image_sum: p lies in T V + pos Q, with
   V = { v : E v = 0, H v <= 0, S v < 0 }, iff one exact LP over
   (v, lambda, t) is feasible: T v + Q^T lambda - t p = 0, E v = 0,
   -H v >= 0, -S v >= 1, lambda >= 0, t >= 1 (homogeneous, so the strict
   rows may be scaled to >= 1).  */
static int
oracle_image(const fmpz * p, const fmpq_mat_t T, const fmpq_mat_t E,
             const fmpq_mat_t H, const fmpq_mat_t S, const fmpq_mat_t Q)
{
    slong e = fmpq_mat_ncols(T), q = fmpq_mat_nrows(Q), nv = e + q + 1;
    slong ne = fmpq_mat_nrows(E), nh = fmpq_mat_nrows(H);
    slong ns = fmpq_mat_nrows(S), m = 3 + ne + nh + ns + q + 1, i, j, r = 0;
    dd_MatrixPtr M;
    dd_LPPtr lp;
    dd_ErrorType err = dd_NoError;
    int res;

    wc_init();
    M = dd_CreateMatrix(m, nv + 1);
    M->representation = dd_Inequality;
    M->numbtype = dd_Rational;
    M->objective = dd_LPmax;
    for (i = 0; i < 3; i++, r++)
    {
        for (j = 0; j < e; j++)
            fmpq_get_mpq(M->matrix[r][1 + j], fmpq_mat_entry(T, i, j));
        for (j = 0; j < q; j++)
            fmpq_get_mpq(M->matrix[r][1 + e + j], fmpq_mat_entry(Q, j, i));
        fmpz_get_mpz(mpq_numref(M->matrix[r][nv]), p + i);
        mpq_neg(M->matrix[r][nv], M->matrix[r][nv]);
        set_addelem(M->linset, r + 1);
    }
    for (i = 0; i < ne; i++, r++)
    {
        for (j = 0; j < e; j++)
            fmpq_get_mpq(M->matrix[r][1 + j], fmpq_mat_entry(E, i, j));
        set_addelem(M->linset, r + 1);
    }
    for (i = 0; i < nh + ns; i++, r++)
    {
        const fmpq_mat_struct * A = i < nh ? H : S;
        slong k = i < nh ? i : i - nh;

        for (j = 0; j < e; j++)
        {
            fmpq_get_mpq(M->matrix[r][1 + j], fmpq_mat_entry(A, k, j));
            mpq_neg(M->matrix[r][1 + j], M->matrix[r][1 + j]);
        }
        if (i >= nh)
            mpq_set_si(M->matrix[r][0], -1, 1);
    }
    for (i = 0; i < q; i++, r++)
        mpq_set_si(M->matrix[r][1 + e + i], 1, 1);
    mpq_set_si(M->matrix[r][0], -1, 1);
    mpq_set_si(M->matrix[r][nv], 1, 1);
    lp = dd_Matrix2LP(M, &err);
    if (lp == NULL || err != dd_NoError)
        wctest_fail("oracle: dd_Matrix2LP failed");
    dd_LPSolve(lp, dd_DualSimplex, &err);
    if (err != dd_NoError)
        wctest_fail("oracle: dd_LPSolve failed");
    if (lp->LPS == dd_Optimal)
        res = 1;
    else if (lp->LPS == dd_Inconsistent)
        res = 0;
    else
        wctest_fail("oracle: LP status %d", (int) lp->LPS);
    dd_FreeLPData(lp);
    dd_FreeMatrix(M);
    return res;
}

/* W = T V + pos Q for random V in R^e (e = 1..4, so hull3 and cddlib
   both serve), T of size 3 x e, often singular, and Q with 0..4 rows:
   membership of face points of cl W, of images of V's face points plus
   points of pos Q, and of random points equals the LP.  */
static void
check_image_sum(void)
{
    slong e = wctest_randint(1, 4), i, j, k, f;
    fmpq_mat_t E, H, S, T, Q;
    wc_cone_t V, W;
    wc_error_t err;
    fmpz * p = _fmpz_vec_init(4), * v = _fmpz_vec_init(4);
    fmpq g[3];
    fmpz_t c;

    dim = e;
    fmpq_mat_init(E, 0, e);
    fmpq_mat_init(H, 0, e);
    fmpq_mat_init(S, 0, e);
    fmpq_mat_init(T, 0, e);
    fmpq_mat_init(Q, 0, 3);
    fmpz_init(c);
    for (j = 0; j < 3; j++)
        fmpq_init(g + j);
    wc_cone_init(V, e);
    wc_cone_init(W, 3);
    wc_error_init(err);
    rand_rows_d(E, wctest_chance(1, 4) ? 1 : 0, 2, e);
    rand_rows_d(H, wctest_randint(0, 4), 2, e);
    rand_rows_d(S, wctest_randint(0, 2), 2, e);
    rand_rows_d(T, 3, 2, e);
    if (wctest_chance(1, 3))            /* a singular map */
        for (j = 0; j < e; j++)
            fmpq_set(fmpq_mat_entry(T, 2, j), fmpq_mat_entry(T, 0, j));
    dim = 3;
    rand_rows_d(Q, wctest_randint(0, 4), 2, 3);
    if (wc_cone_set_hrep(V, E, H, S, err) != WC_OK
        || wc_cone_image_sum(W, T, V, Q, err) != WC_OK)
        wctest_fail("image_sum: %s", err->message);
    if (!W->empty)
    {
        check_canonical(W);
        check_faces(W);
    }
    for (f = -6; f < W->nfaces + (V->empty ? 0 : V->nfaces); f++)
    {
        _fmpz_vec_zero(p, 3);
        if (f < 0)
            for (j = 0; j < 3; j++)
                fmpz_set_si(p + j, wctest_randint(-2, 2));
        else if (f < W->nfaces)
        {
            for (i = 0; i < W->faces[f].nrays; i++)
                _fmpz_vec_add(p, p, ROW(W->rays, W->faces[f].rays[i]), 3);
            if (fmpz_mat_nrows(W->lines) > 0 && wctest_chance(1, 2))
                _fmpz_vec_add(p, p, ROW(W->lines, 0), 3);
        }
        else
        {
            /* T (a face point of V) + a point of pos Q, times a common
               denominator to stay integral.  */
            const wc_face_struct * F = V->faces + f - W->nfaces;
            fmpz_mat_t Tz;
            fmpz_t den;

            fmpz_init(den);
            fmpz_mat_init(Tz, 3, e);
            fmpq_mat_get_fmpz_mat_matwise(Tz, den, T);
            _fmpz_vec_zero(v, e);
            for (i = 0; i < F->nrays; i++)
                _fmpz_vec_add(v, v, ROW(V->rays, F->rays[i]), e);
            for (i = 0; i < 3; i++)
                _fmpz_vec_dot(p + i, ROW(Tz, i), v, e);
            for (k = 0; k < fmpq_mat_nrows(Q); k++)
                for (i = 0; i < 3; i++)
                {
                    fmpz_mul_si(c, den, wctest_randint(0, 2));
                    fmpz_mul(c, c, fmpq_numref(fmpq_mat_entry(Q, k, i)));
                    fmpz_divexact(c, c, fmpq_denref(fmpq_mat_entry(Q, k, i)));
                    fmpz_add(p + i, p + i, c);
                }
            fmpz_mat_clear(Tz);
            fmpz_clear(den);
        }
        for (j = 0; j < 3; j++)
            fmpq_set_fmpz(g + j, p + j);
        if (wc_cone_contains(W, g) != oracle_image(p, T, E, H, S, Q))
        {
            char * str = wctest_vec_str(g, 3);

            wctest_fail("image_sum membership of %s (e = %ld): cone says %d",
                        str, (long) e, wc_cone_contains(W, g));
        }
    }
    fmpq_mat_clear(E);
    fmpq_mat_clear(H);
    fmpq_mat_clear(S);
    fmpq_mat_clear(T);
    fmpq_mat_clear(Q);
    fmpz_clear(c);
    for (j = 0; j < 3; j++)
        fmpq_clear(g + j);
    _fmpz_vec_clear(p, 4);
    _fmpz_vec_clear(v, 4);
    wc_cone_clear(V);
    wc_cone_clear(W);
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
    char * buf;
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
    buf = wctest_cone_json(C);
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
        {
            check_random(i % 4 == 3 ? 4 : 3);
            check_image_sum();
        }
    flint_cleanup_master();
    return 0;
}
