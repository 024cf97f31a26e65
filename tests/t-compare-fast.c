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
#include "ref-hausdorff.h"

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

/* Against the independent reference (ref-hausdorff.c, branch and bound
   in doubles): the library's distance must lie in the reference's
   bracket, refined to REF_TOL wide, up to REF_EPS of rounding; its
   witness must be a unit vector of cl A (within REF_EPS) at which the
   reference's angle to cl B is the distance (within REF_EPS).  A bracket
   wider than REF_MAXGAP after REF_MAXEVAL angles fails the test: the
   reference would then check too little.  */
#define REF_TOL 1e-7
#define REF_EPS 1e-9
#define REF_MAXGAP 1e-5
#define REF_MAXEVAL 200000

static long ref_evals_max, ref_calls, ref_capped;
static double ref_gap_max;

static void
check_ref_directed(const wc_cone_t A, const wc_cone_t B)
{
    double d = 0, w[3] = { 0, 0, 0 }, lo, hi, fa, fb;
    wc_error_t err;
    long n;

    wc_error_init(err);
    if (wc_cone_directed_angle(&d, w, A, B, err) != WC_OK)
        wctest_fail("directed angle: %s", err->message);
    wc_error_clear(err);
    n = ref_directed_angle(&lo, &hi, NULL, A, B, REF_TOL, REF_MAXEVAL);
    ref_evals_max = n > ref_evals_max ? n : ref_evals_max;
    ref_calls++;
    ref_capped += n >= REF_MAXEVAL;
    if (hi - lo > ref_gap_max && !isinf(lo))
        ref_gap_max = hi - lo;
    if (isinf(lo) || isinf(d))
    {
        if (!(isinf(lo) && isinf(d)))
            wctest_fail("directed angle %.17g, ref-hausdorff.c %.17g", d, lo);
        return;
    }
    if (!(d >= lo - REF_EPS && d <= hi + REF_EPS))
        wctest_fail("directed angle %.17g outside ref-hausdorff.c's "
                    "bracket [%.17g, %.17g]", d, lo, hi);
    if (hi - lo > REF_MAXGAP)
        wctest_fail("ref-hausdorff.c: bracket [%.17g, %.17g] after %ld "
                    "angles", lo, hi, n);
    if (fmpz_mat_nrows(A->rays) + fmpz_mat_nrows(A->lines) == 0)
    {
        if (d != 0 || w[0] != 0 || w[1] != 0 || w[2] != 0)
            wctest_fail("cl A = {0}: distance %.17g, nonzero witness", d);
        return;
    }
    if (fabs(w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - 1) > REF_EPS)
        wctest_fail("witness (%g, %g, %g) is not a unit vector", w[0], w[1],
                    w[2]);
    fa = ref_angle_to_cone(NULL, w, A);
    fb = ref_angle_to_cone(NULL, w, B);
    if (fa > REF_EPS || fabs(fb - d) > REF_EPS)
        wctest_fail("witness (%.17g, %.17g, %.17g): at %.3g from cl A and "
                    "%.17g from cl B, distance %.17g", w[0], w[1], w[2], fa,
                    fb, d);
}

/* The cone of the given integer generators (nr rays, then nl lines).  */
static void
cone_si(wc_cone_t C, const slong (*g)[3], slong nr, slong nl)
{
    fmpq_mat_t R, L;
    wc_error_t err;
    slong i, j;

    fmpq_mat_init(R, nr, 3);
    fmpq_mat_init(L, nl, 3);
    for (i = 0; i < nr + nl; i++)
        for (j = 0; j < 3; j++)
            fmpq_set_si(i < nr ? fmpq_mat_entry(R, i, j)
                        : fmpq_mat_entry(L, i - nr, j), g[i][j], 1);
    wc_error_init(err);
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("cone_si: %s", err->message);
    wc_error_clear(err);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
}

/* Degenerate pairs with the distance known in closed form: library and
   reference must both give it.  */
static void
check_known(void)
{
    static const slong e3[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    static const slong ray[1][3] = { { 0, 0, 1 } };
    static const slong half[3][3] = { { 0, 0, -1 }, { 1, 0, 0 },
        { 0, 1, 0 } };
    static const slong plane[2][3] = { { 1, 0, 0 }, { 0, 1, 0 } };
    static const slong sector[2][3] = { { 1, 1, 0 }, { 1, -1, 0 } };
    static const slong lifted[2][3] = { { 1, 1, 1 }, { 1, -1, 1 } };
    static const slong two[2][3] = { { 1, 0, 0 }, { 0, 1, 0 } };
    static const struct
    {
        const slong (*a)[3];
        slong ar, al;
        const slong (*b)[3];
        slong br, bl;
        double want;
    }
    T[] = {
        { e3, 0, 3, ray, 1, 0, M_PI },          /* R^3 to a ray */
        { e3, 0, 3, ray, 0, 1, M_PI / 2 },      /* R^3 to a line */
        { plane, 0, 2, ray, 0, 1, M_PI / 2 },   /* plane to its normal */
        { e3, 0, 3, half, 1, 2, M_PI / 2 },     /* R^3 to a half-space */
        { lifted, 2, 0, sector, 2, 0, M_PI / 4 },   /* not at a ray */
        { e3, 0, 3, two, 2, 0, M_PI - M_PI / 4 },   /* -(1,1,0) / sqrt 2 */
        { ray, 1, 0, plane, 0, 2, M_PI / 2 },
    };
    size_t t;

    for (t = 0; t < sizeof(T) / sizeof(T[0]); t++)
    {
        wc_cone_t A, B;
        wc_error_t err;
        double d, lo, hi;

        wc_cone_init(A, 3);
        wc_cone_init(B, 3);
        wc_error_init(err);
        cone_si(A, T[t].a, T[t].ar, T[t].al);
        cone_si(B, T[t].b, T[t].br, T[t].bl);
        if (wc_cone_directed_angle(&d, NULL, A, B, err) != WC_OK)
            wctest_fail("known case %ld: %s", (long) t, err->message);
        ref_directed_angle(&lo, &hi, NULL, A, B, REF_TOL, REF_MAXEVAL);
        if (fabs(d - T[t].want) > REF_EPS || lo > T[t].want + REF_EPS
            || hi < T[t].want - REF_EPS || hi - lo > REF_MAXGAP)
            wctest_fail("known case %ld: %.17g, library %.17g, "
                        "ref-hausdorff.c [%.17g, %.17g]", (long) t,
                        T[t].want, d, lo, hi);
        check_ref_directed(A, B);
        wc_cone_clear(A);
        wc_cone_clear(B);
        wc_error_clear(err);
    }
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
    check_known();
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
        check_ref_directed(A, B);
        check_ref_directed(B, A);
        check_lines(A);
        wc_cone_clear(A);
        wc_cone_clear(B);
        fmpq_mat_clear(ra);
        fmpq_mat_clear(la);
        fmpq_mat_clear(rb);
        fmpq_mat_clear(lb);
    }
    if (getenv("WC_TEST_VERBOSE") != NULL)
        printf("ref-hausdorff.c: %ld distances, at most %ld angles each, "
               "%ld stopped early, widest bracket %.3g\n", ref_calls,
               ref_evals_max, ref_capped, ref_gap_max);
    flint_cleanup_master();
    return 0;
}
