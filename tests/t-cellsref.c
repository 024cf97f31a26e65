/* t-cellsref.c -- wc_cells_build against the independent reference
   ref-cells.c (symbolic perturbation from the lines of pairs of planes).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Exact agreement: the planes (canonical normals, sorted), the number of
   cells, and every cell's dimension and sign vector in the documented
   order; every cell's point is a primitive integer vector (zero for the
   origin) whose signs, computed here, are the cell's.  Hand-counted
   arrangements first (so that the reference itself is checked), then
   seeded random plane sets with repeated, opposite and multiple rows,
   zero rows, coordinate planes, pencils of planes through one line (all
   of them, or most) and large entries, and the planes of J of random
   problems (coincident fixels, parallel and opposed normals, collinear
   points, near fixels).  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "wrenchcone.h"
#include "ref-cells.h"
#include "testutil.h"

static slong total_cells;

static void
print_normals(const fmpz_mat_t N)
{
    slong i;

    for (i = 0; i < N->r; i++)
    {
        fprintf(stderr, "  plane ");
        fmpz_fprint(stderr, fmpz_mat_entry(N, i, 0));
        fprintf(stderr, " ");
        fmpz_fprint(stderr, fmpz_mat_entry(N, i, 1));
        fprintf(stderr, " ");
        fmpz_fprint(stderr, fmpz_mat_entry(N, i, 2));
        fprintf(stderr, "\n");
    }
}

#define FAIL(N, ...) do { print_normals(N); wctest_fail(__VA_ARGS__); } \
    while (0)

/* The library and the reference on the rows of N; when want is not
   NULL, the numbers of cells of dimension 0..3 must be want[0..3].  */
static void
compare(const fmpz_mat_t N, const slong * want, const char * what)
{
    wc_cells_t A;
    ref_cells_t R;
    fmpz_mat_t planes;
    wc_error_t err;
    signed char * s = NULL;
    fmpz_t t, c;
    slong i, p, m, bydim[4] = { 0, 0, 0, 0 };

    wc_cells_init(A);
    ref_cells_init(R);
    fmpz_mat_init(planes, 0, 3);
    wc_error_init(err);
    fmpz_init(t);
    fmpz_init(c);
    if (wc_cells_build(A, N, err) != WC_OK)
        FAIL(N, "%s: wc_cells_build failed", what);
    ref_cells_planes(planes, N);
    if (A->nplanes != planes->r || !fmpz_mat_equal(A->planes, planes))
        FAIL(N, "%s: %ld planes, the reference %ld, or not the same",
             what, (long) A->nplanes, (long) planes->r);
    if (ref_cells_faces(R, planes) != 0)
        FAIL(N, "%s: the reference failed", what);
    m = planes->r;
    if (A->count != R->count)
        FAIL(N, "%s: %ld cells, the reference %ld", what, (long) A->count,
             (long) R->count);
    s = malloc((size_t) m);
    for (i = 0; i < A->count; i++)
    {
        const signed char * r = R->sign + i * m;
        const fmpz * x = A->point->rows[i];

        wc_cells_signs(s, A, i);
        if (A->dim[i] != R->dim[i] || memcmp(s, r, (size_t) m) != 0)
            FAIL(N, "%s: cell %ld: dimension %ld, the reference %ld, or "
                 "another sign vector", what, (long) i, (long) A->dim[i],
                 (long) R->dim[i]);
        _fmpz_vec_content(c, x, 3);
        if (!fmpz_is_one(c) && !(R->dim[i] == 0 && fmpz_is_zero(c)))
            FAIL(N, "%s: cell %ld: the point is not primitive", what,
                 (long) i);
        for (p = 0; p < m; p++)
        {
            _fmpz_vec_dot(t, planes->rows[p], x, 3);
            if (fmpz_sgn(t) != r[p])
                FAIL(N, "%s: cell %ld: its point has sign %d at plane "
                     "%ld, the cell %d", what, (long) i, fmpz_sgn(t),
                     (long) p, r[p]);
        }
        bydim[R->dim[i]]++;
    }
    if (want != NULL)
        for (i = 0; i < 4; i++)
            if (bydim[i] != want[i])
                FAIL(N, "%s: %ld cells of dimension %ld, not %ld", what,
                     (long) bydim[i], (long) i, (long) want[i]);
    total_cells += A->count;
    free(s);
    fmpz_clear(t);
    fmpz_clear(c);
    wc_error_clear(err);
    fmpz_mat_clear(planes);
    ref_cells_clear(R);
    wc_cells_clear(A);
}

static void
set_rows(fmpz_mat_t N, slong m, const slong * e)
{
    slong i, j;

    fmpz_mat_clear(N);
    fmpz_mat_init(N, m, 3);
    for (i = 0; i < m; i++)
        for (j = 0; j < 3; j++)
            fmpz_set_si(fmpz_mat_entry(N, i, j), e[3 * i + j]);
}

/* Arrangements counted by hand.  */
static void
test_known(void)
{
    fmpz_mat_t N;
    /* the coordinate planes alone: the octants */
    static const slong octants[4] = { 1, 6, 12, 8 };
    static const slong coord[] = { 0, 0, 5, -2, 0, 0, 0, 0, 0 };
    /* x + y = 0 added: rays on the axes and on the line (1, -1, 0);
       sectors: 6 in z = 0 (three lines), 4 in each of the other three
       planes (two lines); chambers by Euler on the sphere, V - E + F =
       2 */
    static const slong one[] = { 1, 1, 0 };
    static const slong one_want[4] = { 1, 8, 18, 12 };
    /* x = y and x = -y added: four planes through the z axis and z = 0;
       rays 2 + 8, sectors 8 in z = 0 and 4 in each plane through the
       axis, chambers by Euler */
    static const slong pencil[] = { 1, 1, 0, 1, -1, 0 };
    static const slong pencil_want[4] = { 1, 10, 24, 16 };

    fmpz_mat_init(N, 0, 3);
    compare(N, octants, "no planes");
    set_rows(N, 3, coord);
    compare(N, octants, "coordinate planes and a zero row");
    set_rows(N, 1, one);
    compare(N, one_want, "x + y = 0");
    set_rows(N, 2, pencil);
    compare(N, pencil_want, "a pencil of four planes");
    fmpz_mat_clear(N);
}

/* A random plane set of m rows, in one of several layouts.  */
static void
random_normals(fmpz_mat_t N, slong m)
{
    fmpz v[3], r[3];
    slong i, j, layout = wctest_randint(0, 4);

    fmpz_mat_clear(N);
    fmpz_mat_init(N, m, 3);
    for (j = 0; j < 3; j++)
    {
        fmpz_init(v + j);
        fmpz_init(r + j);
        fmpz_set_si(v + j, wctest_randint(-2, 2));
    }
    for (i = 0; i < m; i++)
    {
        fmpz * h = N->rows[i];
        slong kind = wctest_randint(0, 9);

        for (j = 0; j < 3; j++)
            fmpz_set_si(h + j, wctest_randint(-3, 3));
        if (i > 0 && kind < 2)      /* a multiple of an earlier row */
            _fmpz_vec_scalar_mul_si(h, N->rows[wctest_randint(0, i - 1)],
                                    3, wctest_chance(1, 2)
                                    ? wctest_randint(1, 3)
                                    : -wctest_randint(1, 3));
        else if (kind == 2)         /* a coordinate plane */
        {
            _fmpz_vec_zero(h, 3);
            fmpz_set_si(h + wctest_randint(0, 2), wctest_randint(-2, 2));
        }
        else if (layout == 1 || (layout == 2 && kind < 6))
        {
            /* through the line of v: h = v x r */
            for (j = 0; j < 3; j++)
                fmpz_set_si(r + j, wctest_randint(-3, 3));
            fmpz_mul(h + 0, v + 1, r + 2);
            fmpz_submul(h + 0, v + 2, r + 1);
            fmpz_mul(h + 1, v + 2, r + 0);
            fmpz_submul(h + 1, v + 0, r + 2);
            fmpz_mul(h + 2, v + 0, r + 1);
            fmpz_submul(h + 2, v + 1, r + 0);
        }
        if (layout == 3 && kind == 9)  /* large entries */
            _fmpz_vec_scalar_mul_2exp(h, h, 3, wctest_randint(30, 70));
    }
    for (j = 0; j < 3; j++)
    {
        fmpz_clear(v + j);
        fmpz_clear(r + j);
    }
}

/* The planes of a random problem's contact velocities: J_in and J_it of
   every fixel (coincident fixels, parallel and opposed normals,
   collinear points, normals through one point), cleared to integers.  */
static void
problem_normals(fmpz_mat_t N)
{
    wc_problem_t P;
    fmpq w[3], d[2];
    fmpz_t l;
    slong i, j, k;

    wc_problem_init(P);
    wctest_random_problem(P, 1, 12);
    fmpz_mat_clear(N);
    fmpz_mat_init(N, 2 * P->n, 3);
    fmpz_init(l);
    for (j = 0; j < 3; j++)
        fmpq_init(w + j);
    fmpq_init(d + 0);
    fmpq_init(d + 1);
    for (i = 0; i < 2 * P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i / 2;

        fmpq_set(d + 0, f->normal + 0);
        fmpq_set(d + 1, f->normal + 1);
        if (i % 2 == 1)         /* the tangent (-n_y, n_x) */
        {
            fmpq_neg(d + 0, f->normal + 1);
            fmpq_set(d + 1, f->normal + 0);
        }
        wctest_wrench_of(w, P, f, d);
        fmpz_one(l);
        for (k = 0; k < 3; k++)
            fmpz_lcm(l, l, fmpq_denref(w + k));
        for (k = 0; k < 3; k++)
        {
            fmpz * e = fmpz_mat_entry(N, i, k);

            fmpz_divexact(e, l, fmpq_denref(w + k));
            fmpz_mul(e, e, fmpq_numref(w + k));
        }
    }
    for (j = 0; j < 3; j++)
        fmpq_clear(w + j);
    fmpq_clear(d + 0);
    fmpq_clear(d + 1);
    fmpz_clear(l);
    wc_problem_clear(P);
}

int
main(void)
{
    fmpz_mat_t N;
    slong it, iters;
    char what[64];

    wctest_init("t-cellsref");
    test_known();
    fmpz_mat_init(N, 0, 3);
    iters = wctest_iters(600);
    for (it = 0; it < iters; it++)
    {
        if (!wctest_iter(it))
            continue;
        if (it % 3 == 2)
            problem_normals(N);
        else
            random_normals(N, wctest_randint(0, it % 5 == 0 ? 32 : 12));
        snprintf(what, sizeof what, "%s, %ld planes", it % 3 == 2
                 ? "a random problem's J" : "random", (long) N->r);
        compare(N, NULL, what);
    }
    fmpz_mat_clear(N);
    if (getenv("WC_TEST_VERBOSE") != NULL)
        printf("t-cellsref: %ld iterations, %ld cells, all equal\n",
               (long) iters, (long) total_cells);
    flint_cleanup();
    return 0;
}
