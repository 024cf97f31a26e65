/* t-compare-fast.c -- the near-linear paths of `compare` against the slow
   ones they replaced, on random cones with degenerate layouts.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   - _wc_cone_project (small faces tested on their own) against
     old_cone_project (every face against every facet): the same |P v|^2
     and nearest point, exactly;
   - wc_cone_directed_angle (facets found through the 2-D faces, separated
     cells skipped) against old_cone_directed_angle (tests/old-hausdorff.c,
     the former code, a regression check): the same distance and
     witness, to the bit;
   - the file lines wc_compare gives to the foreign cone's extreme rays and
     facets and its redundant rows (a binary search among the sorted
     canonical vectors) against a pairwise search done here.
   Cones: up to 12 generators of entries in [-3, 3] with repeated,
   opposite (lines), collinear and coplanar ones, extra lines, lower
   dimensions, and cones given by inequalities (some empty or {0}).  */

#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpq_vec.h>

#include "wrenchcone.h"
#include "float/compare.h"
#include "float/angle.h"
#include "exact/vec3.h"
#include "testutil.h"

int old_cone_directed_angle(double * dist, double * witness,
                            const wc_cone_t A, const wc_cone_t B,
                            wc_error_t err);
void old_cone_project(fmpq_t best, fmpq * q, const fmpq * v,
                      const wc_cone_t C);

/* Random rows into G (r x 3): a layout drawn from a few degenerate ones.  */
static void
random_rows(fmpq_mat_t G, slong r)
{
    slong i, j, layout = wctest_randint(0, 4);

    fmpq_mat_init(G, r, 3);
    for (i = 0; i < r; i++)
    {
        for (j = 0; j < 3; j++)
            fmpq_set_si(fmpq_mat_entry(G, i, j), wctest_randint(-3, 3), 1);
        if (layout == 1)                    /* coplanar: z = 0 */
            fmpq_zero(fmpq_mat_entry(G, i, 2));
        if (i > 0 && layout == 2 && wctest_chance(1, 3))   /* repeated */
            for (j = 0; j < 3; j++)
                fmpq_mul_si(fmpq_mat_entry(G, i, j),
                            fmpq_mat_entry(G, i - 1, j),
                            wctest_randint(1, 3));
        if (i > 0 && layout == 3 && wctest_chance(1, 3))   /* opposite */
            for (j = 0; j < 3; j++)
                fmpq_neg(fmpq_mat_entry(G, i, j),
                         fmpq_mat_entry(G, i - 1, j));
        if (layout == 4 && i > 0)           /* collinear with row 0 */
            for (j = 0; j < 3; j++)
                fmpq_mul_si(fmpq_mat_entry(G, i, j), fmpq_mat_entry(G, 0, j),
                            wctest_randint(-2, 2));
    }
}

/* A random nonempty or empty cone: generators, or inequalities.  */
static void
random_cone(wc_cone_t C, fmpq_mat_t rows, fmpq_mat_t lines, int * hrep)
{
    wc_error_t err;
    int status;

    wc_error_init(err);
    *hrep = wctest_chance(1, 4);
    random_rows(rows, wctest_randint(0, 12));
    random_rows(lines, wctest_chance(1, 3) ? wctest_randint(1, 2) : 0);
    if (*hrep)
        status = wc_cone_set_hrep(C, lines, rows, NULL, err);
    else
        status = wc_cone_set_generators(C, rows, lines, err);
    if (status != WC_OK)
        wctest_fail("random cone: %s", err->message);
    wc_error_clear(err);
}

static void
check_project(const wc_cone_t C)
{
    fmpq * v = _fmpq_vec_init(3), * q = _fmpq_vec_init(3);
    fmpq * qr = _fmpq_vec_init(3);
    fmpq_t b, br;
    slong t, j;

    fmpq_init(b);
    fmpq_init(br);
    for (t = 0; t < 8 && !C->empty; t++)
    {
        for (j = 0; j < 3; j++)
            wctest_rand_fmpq(v + j, 5, 3);
        _wc_cone_project(b, q, v, C);
        old_cone_project(br, qr, v, C);
        if (!fmpq_equal(b, br) || !fmpq_equal(q + 0, qr + 0)
            || !fmpq_equal(q + 1, qr + 1) || !fmpq_equal(q + 2, qr + 2))
        {
            char * s = wctest_vec_str(v, 3);

            wctest_fail("nearest point of %s differs from the reference", s);
        }
    }
    fmpq_clear(b);
    fmpq_clear(br);
    _fmpq_vec_clear(v, 3);
    _fmpq_vec_clear(q, 3);
    _fmpq_vec_clear(qr, 3);
}

static int
same_double(double a, double b)
{
    return (isnan(a) && isnan(b)) || a == b;
}

static void
check_directed(const wc_cone_t A, const wc_cone_t B)
{
    double d = 0, dr = 0, w[3] = { 0, 0, 0 }, wr[3] = { 0, 0, 0 };
    wc_error_t err, errr;
    int s, sr, j;

    wc_error_init(err);
    wc_error_init(errr);
    s = wc_cone_directed_angle(&d, w, A, B, err);
    sr = old_cone_directed_angle(&dr, wr, A, B, errr);
    if (s != sr)
        wctest_fail("directed angle: status %d, reference %d", s, sr);
    if (s == WC_OK)
    {
        if (!same_double(d, dr))
            wctest_fail("directed angle %.17g, reference %.17g", d, dr);
        for (j = 0; j < 3; j++)
            if (!same_double(w[j], wr[j]))
                wctest_fail("witness differs from the reference");
    }
    wc_error_clear(err);
    wc_error_clear(errr);
}

/* 1 when a = s b for some s > 0 (both nonzero): the pairwise test the
   binary search replaced.  */
static int
same_ray(const fmpq * a, const fmpq * b)
{
    fmpq * c = _fmpq_vec_init(3);
    fmpq_t d;
    int r;

    fmpq_init(d);
    _wc_qvec3_cross(c, a, b);
    _wc_qv3_dot(d, a, b);
    r = _wc_qv3_is_zero(c) && fmpq_sgn(d) > 0;
    fmpq_clear(d);
    _fmpq_vec_clear(c, 3);
    return r;
}

/* The file lines of the foreign representation P, by pairwise search:
   want[i] the line of the first row on canonical vector i of X (0 when
   none), red[0..*nred) the lines of the other rows.  */
static void
ref_lines(long * want, long * red, slong * nred, const fmpz_mat_t X,
          const wc_rep_struct * P, const fmpz_mat_t S)
{
    fmpq * dir = _fmpq_vec_init(3), * p = _fmpq_vec_init(3);
    fmpq * x = _fmpq_vec_init(3), * q = _fmpq_vec_init(3);
    slong r = _wc_rows_span(dir, S), i, j, c;

    *nred = 0;
    for (i = 0; i < fmpz_mat_nrows(X); i++)
        want[i] = 0;
    for (j = 0; j < fmpq_mat_nrows(P->rows); j++)
    {
        int on = 0;

        _wc_span_project(q, WC_ROW(P->rows, j), r, dir);
        for (c = 0; c < 3; c++)
            fmpq_sub(p + c, fmpq_mat_entry(P->rows, j, c), q + c);
        for (i = 0; !_wc_qv3_is_zero(p) && i < fmpz_mat_nrows(X); i++)
        {
            _fmpq_vec_set_fmpz_vec(x, WC_ROW(X, i), 3);
            if (!same_ray(x, p))
                continue;
            if (want[i] == 0)
            {
                want[i] = P->row_line[j];
                on = 1;
            }
            break;
        }
        if (!on)
            red[(*nred)++] = P->row_line[j];
    }
    _fmpq_vec_clear(dir, 3);
    _fmpq_vec_clear(p, 3);
    _fmpq_vec_clear(x, 3);
    _fmpq_vec_clear(q, 3);
}

/* rows as a cdd block of the given kind (lines as linearity rows).  */
static char *
cdd_text(const fmpq_mat_t rows, const fmpq_mat_t lines, int hrep)
{
    slong r = fmpq_mat_nrows(rows), l = fmpq_mat_nrows(lines), i, j, v;
    char * t = flint_malloc(64 * (r + l + 4) + 64), * e = t;

    e += sprintf(e, "%s\n", hrep ? "H-representation" : "V-representation");
    if (l > 0)
    {
        e += sprintf(e, "linearity %ld", (long) l);
        for (i = 0; i < l; i++)
            e += sprintf(e, " %ld", (long) (r + i + 1));
        e += sprintf(e, "\n");
    }
    e += sprintf(e, "begin\n%ld 4 rational\n", (long) (r + l));
    for (i = 0; i < r + l; i++)
    {
        const fmpq * row = i < r ? WC_ROW(rows, i)
            : WC_ROW(lines, i - r);

        e += sprintf(e, "0");
        for (j = 0; j < 3; j++)
        {
            /* cdd's H row a means a.g >= 0: our h.g <= 0 is a = -h */
            v = fmpz_get_si(fmpq_numref(row + j)) * (hrep ? -1 : 1);
            e += sprintf(e, " %ld", (long) v);
        }
        e += sprintf(e, "\n");
    }
    sprintf(e, "end\n");
    return t;
}

static void
check_lines(const wc_cone_t W)
{
    fmpq_mat_t rows, lines;
    wc_cone_t C;
    wc_foreign_t F;
    wc_comparison_t R;
    wc_error_t err;
    char * text;
    int hrep;

    wc_cone_init(C, 3);
    random_cone(C, rows, lines, &hrep);
    wc_error_init(err);
    wc_foreign_init(F);
    wc_comparison_init(R);
    text = cdd_text(rows, lines, hrep);
    if (wc_foreign_parse(F, text, strlen(text), "f", err) != WC_OK)
        wctest_fail("foreign cone %s: %s", text, err->message);
    if (wc_compare(R, W, NULL, F, 1e-9, err) != WC_OK)
        wctest_fail("wc_compare: %s", err->message);
    if (R->nreps == 1 && !R->reps[0].cone->empty && !W->empty
        && R->reps[0].rays != NULL)
    {
        const wc_cmp_rep_struct * S = R->reps;
        const fmpz_mat_struct * X = hrep ? S->cone->ineqs : S->cone->rays;
        const wc_cmp_vec * U = hrep ? S->facets : S->rays;
        slong n = fmpz_mat_nrows(X), i, nred;
        long * want = flint_malloc(sizeof(long) * (n + 1));
        long * red = flint_malloc(sizeof(long) * (fmpq_mat_nrows(rows) + 1));

        ref_lines(want, red, &nred, X, F->reps, hrep ? S->cone->eqs
                  : S->cone->lines);
        for (i = 0; i < n; i++)
            if (U[i].line != want[i])
                wctest_fail("%s: vector %ld on line %ld, reference %ld",
                            text, (long) i, U[i].line, want[i]);
        if (nred != S->nredundant)
            wctest_fail("%s: %ld redundant rows, reference %ld", text,
                        (long) S->nredundant, (long) nred);
        for (i = 0; i < nred; i++)
            if (red[i] != S->redundant[i])
                wctest_fail("%s: redundant row %ld differs", text, (long) i);
        flint_free(want);
        flint_free(red);
    }
    flint_free(text);
    wc_comparison_clear(R);
    wc_foreign_clear(F);
    wc_error_clear(err);
    wc_cone_clear(C);
    fmpq_mat_clear(rows);
    fmpq_mat_clear(lines);
}

int
main(void)
{
    slong iters, i;

    wctest_init("t-compare-fast");
    iters = wctest_iters(300);
    for (i = 0; i < iters; i++)
    {
        wc_cone_t A, B;
        fmpq_mat_t ra, la, rb, lb;
        int ha, hb;

        if (!wctest_iter(i))
            continue;
        wc_cone_init(A, 3);
        wc_cone_init(B, 3);
        random_cone(A, ra, la, &ha);
        random_cone(B, rb, lb, &hb);
        check_project(A);
        check_project(B);
        check_directed(A, B);
        check_directed(B, A);
        check_lines(A);
        wc_cone_clear(A);
        wc_cone_clear(B);
        fmpq_mat_clear(ra);
        fmpq_mat_clear(la);
        fmpq_mat_clear(rb);
        fmpq_mat_clear(lb);
    }
    flint_cleanup_master();
    return 0;
}
