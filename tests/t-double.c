/* t-double.c -- the paper's route in doubles (lib/floatcone.c) against the
   exact cone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   (a) The Section 4 example, mode na: three unit rays within 1e-12 of the
   normalised exact ones, the one strict facet (the one spanned by the two
   friction edges), the two excluded rays, and the printers' keys, flags
   and cdd headers.  (b) Every Table 2 mode of the Section 4 example and
   of three small hand-made problems (both fixels touching, opposed
   fixels without friction, two fixels at one point) gives the exact
   answer, some of them empty; corner cases -- no constraint at all
   (W = R^3), a bad mode, a bad tolerance, numbers beyond double range --
   give the exact answer or a clean error.  (c) On random well-conditioned
   problems (the generator of lib/random.c without --degenerate: small
   rationals, so every exact quantity is 0 or far from it) and random
   modes, the double cone agrees with the exact one (the direct route, an
   independent algorithm) within 1e-9: emptiness, linear hull, lineality,
   rays, facets and strictness, vectors matched by nearest after
   normalising.

   (d) On degenerate problems (random.h's --degenerate: two fixels at one
   point with normals 10^-9 apart, a polygon edge bent by 10^-9, ...) the
   double route may be wrong -- cddlib's double build decides zero at
   1e-7, so a 10^-9 feature is invisible to it; that is what the double
   route is for -- but not in any way: a refusal must be clean; a double
   cone must be consistent in itself (unit rows, its rays and lines on
   the right side of its own facets and equalities, dimensions matching
   its bases); when wc_fcone_compare_exact calls it equal to the exact
   cone, tests/ref-hausdorff.c (an independent angular distance) must put
   the closures within 1e-7 of each other both ways (also checked in
   (c)); and the double route must be fooled now and then, at least one
   problem in twenty.  With the default seed 91 of the 400 degenerate
   problems (1..4 fixels, one random mode each) differ beyond 1e-9, 2 of
   them because cddlib's double build gives up ("numerically
   inconsistent"); over 20000 problems the share stays near one in four,
   while the 20000 well-conditioned cones of (c) at WC_TEST_MULTIPLIER=50
   never differ.  With WC_TEST_VERBOSE set in the environment the count
   goes to stderr.  */

#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "core/random.h"
#include "testutil.h"
#include "ref-hausdorff.h"

#define BIG "179769313486231590772930519078902473361797697894230657273430" \
    "081157732675805500963132708477322407536021120113879871393357658789" \
    "768814416622492847430639474124377767893424865485276302219601246094" \
    "119453082952085005768838150682342462881473913110540827237163350510" \
    "684586298239947245938479716304835356329624224137215"

static const char section4[] =
    "# data/section4.wc\n"
    "name \"Section 4 example\"\n"
    "mass 1\n"
    "inertia 1\n"
    "com 0 0\n"
    "friction 1/5\n"
    "shape disk 0 0 1\n"
    "fixel 0 -1 normal 0 1 touching\n"
    "fixel 1 0 normal -1 0 near\n";

static void
parse(wc_problem_t P, const char * text)
{
    wc_error_t err;

    wc_error_init(err);
    if (wc_problem_parse(P, text, strlen(text), "test", err) != WC_OK)
        wctest_fail("cannot parse the test problem: %s", err->message);
    wc_error_clear(err);
}

static char *
print_to_string(const wc_fcone_t C, int format)
{
    char * buf = NULL;
    size_t len = 0;
    FILE * f = open_memstream(&buf, &len);
    wc_print_opts o = { WC_FORMAT_TEXT, 0, 0, NULL };

    o.format = (wc_format) format;
    if (f == NULL)
        wctest_fail("open_memstream failed");
    if (wc_fcone_fprint(f, C, &o) != WC_OK)
        wctest_fail("wc_fcone_fprint(format %d) failed", format);
    fclose(f);
    return buf;
}

static void
expect_substring(const char * s, const char * want, const char * what)
{
    if (strstr(s, want) == NULL)
        wctest_fail("%s: expected \"%s\" in:\n%s", what, want, s);
}

static const char *
diff_str(int bits)
{
    static char buf[128];

    snprintf(buf, sizeof buf, "%s%s%s%s%s",
             bits & WC_FDIFF_EMPTY ? " emptiness" : "",
             bits & WC_FDIFF_SPACES ? " hull/lineality" : "",
             bits & WC_FDIFF_RAYS ? " rays" : "",
             bits & WC_FDIFF_FACETS ? " facets" : "",
             bits & WC_FDIFF_STRICT ? " strictness" : "");
    return buf;
}

/* The exact cone (direct route) and the double one of P and mode, and
   their differences at tol; fails on any error.  */
static int
compare_mode(const wc_problem_t P, const char * mode, double tol,
             int fail_on_diff)
{
    wc_cone_t X;
    wc_fcone_t F;
    wc_error_t err;
    int bits, status;

    wc_cone_init(X, 3);
    wc_fcone_init(F, 3);
    wc_error_init(err);
    if (wc_wrench_cone(X, NULL, P, mode, WC_METHOD_DIRECT, err) != WC_OK)
        wctest_fail_problem(P, mode, "exact route failed: %s", err->message);
    status = wc_wrench_cone_paper_double(F, P, mode, WC_FCONE_EPS, err);
    if (status != WC_OK)
    {
        if (fail_on_diff)
            wctest_fail_problem(P, mode, "double route failed (%d): %s",
                                status, err->message);
        bits = -1;
    }
    else
        bits = wc_fcone_compare_exact(F, X, tol);
    if (fail_on_diff && bits != 0)
    {
        wc_print_opts text = { WC_FORMAT_TEXT, 0, 0, "  " };

        fprintf(stderr, "double cone:\n");
        wc_fcone_fprint(stderr, F, NULL);
        fprintf(stderr, "exact cone:\n");
        wc_cone_fprint(stderr, X, &text);
        wctest_fail_problem(P, mode, "double and exact cones differ in:%s",
                            diff_str(bits));
    }
    wc_error_clear(err);
    wc_fcone_clear(F);
    wc_cone_clear(X);
    return bits;
}

/* (a) */
static void
check_section4(void)
{
    static const double ray[3][3] = {
        { -1, -5, -1 }, { 1, -5, 1 }, { 1, 0, -1 } };
    static const double facet[3][3] = {
        { -1, 0, 1 }, { -5, 2, -5 }, { 5, 2, 5 } };
    static const int ray_strict[3] = { 1, 1, 0 };
    static const int facet_strict[3] = { 1, 0, 0 };
    wc_problem_t P;
    wc_fcone_t F;
    wc_cone_t X;
    wc_error_t err;
    slong i, j, k;
    char * s;

    wc_problem_init(P);
    wc_fcone_init(F, 3);
    wc_cone_init(X, 3);
    wc_error_init(err);
    parse(P, section4);
    if (wc_wrench_cone_paper_double(F, P, "na", WC_FCONE_EPS, err) != WC_OK)
        wctest_fail("Section 4, na: %s", err->message);
    if (F->empty || F->dim != 3 || F->lineality_dim != 0 || F->closed
        || F->rays->r != 3 || F->ineqs->r != 3 || F->eqs->r != 0
        || F->lines->r != 0)
        wctest_fail("Section 4, na: empty %d, dim %ld, lineality %ld, "
                    "closed %d, %ld rays, %ld facets", F->empty,
                    (long) F->dim, (long) F->lineality_dim, F->closed,
                    (long) F->rays->r, (long) F->ineqs->r);
    /* Sorted lexicographically, the rows come in the order listed.  */
    for (i = 0; i < 3; i++)
    {
        double nr = 0, nh = 0;

        for (j = 0; j < 3; j++)
        {
            nr += ray[i][j] * ray[i][j];
            nh += facet[i][j] * facet[i][j];
        }
        for (j = 0; j < 3; j++)
        {
            if (fabs(d_mat_entry(F->rays, i, j) - ray[i][j] / sqrt(nr)) > 1e-12)
                wctest_fail("Section 4, na: ray %ld entry %ld is %.17g",
                            (long) i, (long) j, d_mat_entry(F->rays, i, j));
            if (fabs(d_mat_entry(F->ineqs, i, j) - facet[i][j] / sqrt(nh))
                > 1e-12)
                wctest_fail("Section 4, na: facet %ld entry %ld is %.17g",
                            (long) i, (long) j, d_mat_entry(F->ineqs, i, j));
        }
        if (F->strict_rays[i] != ray_strict[i] || F->strict[i] != facet_strict[i])
            wctest_fail("Section 4, na: ray %ld strict %d, facet %ld strict %d",
                        (long) i, F->strict_rays[i], (long) i, F->strict[i]);
    }
    if (wc_wrench_cone_paper(X, NULL, P, "na", err) != WC_OK)
        wctest_fail("Section 4, na, exact: %s", err->message);
    if ((k = wc_fcone_compare_exact(F, X, 1e-12)) != 0)
        wctest_fail("Section 4, na: differs from the exact cone in:%s",
                    diff_str((int) k));

    s = print_to_string(F, WC_FORMAT_JSON);
    if (strncmp(s, "{\"empty\": false, \"arith\": \"double\", \"eps\": ", 43) != 0)
        wctest_fail("Section 4 JSON starts wrongly: %s", s);
    expect_substring(s, "\"dim\": 3, \"lineality_dim\": 0, \"closed\": false, "
                     "\"inequalities\": [[", "JSON");
    expect_substring(s, "\"strict\": [true, false, false], \"equalities\": []",
                     "JSON");
    expect_substring(s, "\"strict_rays\": [true, true, false], \"lines\": []}",
                     "JSON");
    if (s[strlen(s) - 1] != '}')
        wctest_fail("JSON ends with a newline or junk: %s", s);
    free(s);
    s = print_to_string(F, WC_FORMAT_CDD);
    expect_substring(s, "* floating point, not exact", "cdd");
    expect_substring(s, "*   strict facet, H row 1\n*   excluded ray, V row 2\n"
                     "*   excluded ray, V row 3\nH-representation\nbegin\n"
                     " 3 4 real\n 0 0.70710678118654", "cdd");
    expect_substring(s, "V-representation\nbegin\n 4 4 real\n 1 0 0 0\n", "cdd");
    free(s);
    s = print_to_string(F, WC_FORMAT_TEXT);
    expect_substring(s, "floating point, not exact", "text");
    expect_substring(s, "not closed (1 of 3 facets strict)", "text");
    free(s);

    /* An empty cone prints as such in every format.  */
    wc_fcone_set_empty(F);
    s = print_to_string(F, WC_FORMAT_JSON);
    if (strcmp(s, "{\"empty\": true, \"arith\": \"double\", "
               "\"eps\": 1.0000000000000001e-09}") != 0)
        wctest_fail("empty JSON: %s", s);
    free(s);
    s = print_to_string(F, WC_FORMAT_INE);
    expect_substring(s, "* the cone is empty\nH-representation\nbegin\n 1 4 real\n"
                     " -1 0 0 0\nend\n", "empty .ine");
    free(s);
    s = print_to_string(F, WC_FORMAT_EXT);
    expect_substring(s, "V-representation\nbegin\n 0 4 real\nend\n", "empty .ext");
    free(s);

    wc_error_clear(err);
    wc_cone_clear(X);
    wc_fcone_clear(F);
    wc_problem_clear(P);
}

/* Every Table 2 mode of P (touching: s l r n m; near: s a u).  Returns how
   many were empty.  */
static slong
check_all_modes(const wc_problem_t P)
{
    slong n = P->n, total = 1, c, i, empties = 0;
    char * mode = flint_malloc(n + 1);

    for (i = 0; i < n; i++)
        total *= P->fixels[i].state == WC_NEAR ? 3 : 5;
    for (c = 0; c < total; c++)
    {
        slong x = c;
        wc_cone_t X;
        wc_error_t err;

        for (i = 0; i < n; i++)
        {
            const char * set = P->fixels[i].state == WC_NEAR ? "sau" : "slrnm";
            slong len = (slong) strlen(set);

            mode[i] = set[x % len];
            x /= len;
        }
        mode[n] = '\0';
        compare_mode(P, mode, 1e-9, 1);
        wc_cone_init(X, 3);
        wc_error_init(err);
        wc_wrench_cone(X, NULL, P, mode, WC_METHOD_DIRECT, err);
        empties += X->empty;
        wc_cone_clear(X);
        wc_error_clear(err);
    }
    flint_free(mode);
    return empties;
}

/* (b) */
static void
check_corners(void)
{
    static const char * const examples[] = {
        section4,
        /* Figure 5's disk, both fixels touching.  */
        "friction 1/5\nfixel 0 -1 normal 0 1\nfixel 1 0 normal -1 0\n",
        /* Opposed fixels squeezing the part, mu_s = 0 (R's own case).  */
        "fixel 0 -1 normal 0 1\nfixel 0 1 normal 0 -1\nfixel 1 0 normal -1 0 near\n",
        /* Two fixels at one point, mu_s != mu_k, com off the origin.  */
        "com 1/3 -1/2\nmass 2\ninertia 5/12\nfriction 1/2 1/10\n"
        "fixel 0 0 normal 1 1\nfixel 0 0 normal -1 2 friction 1\n"
        "fixel 2 1 normal 0 -3 near\n",
    };
    wc_problem_t P;
    wc_fcone_t F;
    wc_error_t err;
    slong i, empties = 0;

    for (i = 0; i < (slong) (sizeof examples / sizeof examples[0]); i++)
    {
        wc_problem_init(P);
        parse(P, examples[i]);
        empties += check_all_modes(P);
        wc_problem_clear(P);
    }
    if (empties == 0)
        wctest_fail("no example mode has an empty cone: emptiness untested");

    wc_problem_init(P);
    wc_fcone_init(F, 3);
    wc_error_init(err);

    /* No constraint at all: one near fixel, mode u, W = R^3.  */
    parse(P, "fixel 0 0 normal 0 1 near\n");
    if (wc_wrench_cone_paper_double(F, P, "u", WC_FCONE_EPS, err) != WC_OK
        || F->empty || F->dim != 3 || F->lineality_dim != 3 || !F->closed
        || F->rays->r != 0 || F->ineqs->r != 0)
        wctest_fail("mode u of one near fixel is not R^3");
    compare_mode(P, "u", 1e-12, 1);
    compare_mode(P, "a", 1e-12, 1);
    compare_mode(P, "s", 1e-12, 1);

    /* Bad mode, bad tolerance: WC_EINPUT, the cone left empty.  */
    if (wc_wrench_cone_paper_double(F, P, "n", WC_FCONE_EPS, err) != WC_EINPUT
        || !F->empty || err->col != 1)
        wctest_fail("mode n on a near fixel was not refused at column 1");
    if (wc_wrench_cone_paper_double(F, P, "u", -1.0, err) != WC_EINPUT
        || !F->empty)
        wctest_fail("a negative tolerance was accepted");
    if (wc_wrench_cone_paper_double(F, P, "u", NAN, err) != WC_EINPUT
        || !F->empty)
        wctest_fail("a NaN tolerance was accepted");
    if (wc_wrench_cone_paper_double(F, P, "u", 0.0, err) != WC_OK || F->empty)
        wctest_fail("tolerance 0 was refused");
    wc_problem_clear(P);

    /* Beyond double range: a refusal, never inf or NaN fed to cddlib.
       BIG is 2^1024 - 1, the largest integer a problem file may hold
       (1,024 bits), and above the largest double.  */
    wc_problem_init(P);
    parse(P, "fixel 0 0 normal " BIG " 1\nfixel 1 0 normal -1 0\n");
    if (wc_wrench_cone_paper_double(F, P, "nn", WC_FCONE_EPS, err) != WC_EINPUT
        || !F->empty)
        wctest_fail("a normal of 2^1024 - 1 did not give WC_EINPUT");
    wc_problem_clear(P);
    /* A mass of 2^1024 - 1 rounds 1/m to 0: a float answer, not an error.  */
    wc_problem_init(P);
    parse(P, "mass " BIG "\nfixel 0 0 normal 0 1\n");
    if (wc_wrench_cone_paper_double(F, P, "m", WC_FCONE_EPS, err) != WC_OK)
        wctest_fail("a mass of 2^1024 - 1 failed: %s", err->message);
    wc_problem_clear(P);

    wc_error_clear(err);
    wc_fcone_clear(F);
}

/* x := the double a, exactly.  */
static void
fmpq_set_double(fmpq_t x, double a)
{
    int e;
    double m = frexp(a, &e);            /* a = m 2^e, |m| in [1/2, 1) */

    fmpz_set_d(fmpq_numref(x), ldexp(m, 53));
    fmpz_one(fmpq_denref(x));
    e -= 53;
    if (e >= 0)
        fmpz_mul_2exp(fmpq_numref(x), fmpq_numref(x), e);
    else
        fmpz_mul_2exp(fmpq_denref(x), fmpq_denref(x), -e);
    fmpq_canonicalise(x);
}

/* C := the closed cone generated by F's rays and lines, read exactly.  */
static void
fcone_closure(wc_cone_t C, const wc_fcone_t F)
{
    fmpq_mat_t R, L;
    wc_error_t err;
    slong i, j;

    fmpq_mat_init(R, F->rays->r, 3);
    fmpq_mat_init(L, F->lines->r, 3);
    for (i = 0; i < F->rays->r; i++)
        for (j = 0; j < 3; j++)
            fmpq_set_double(fmpq_mat_entry(R, i, j), d_mat_entry(F->rays, i, j));
    for (i = 0; i < F->lines->r; i++)
        for (j = 0; j < 3; j++)
            fmpq_set_double(fmpq_mat_entry(L, i, j), d_mat_entry(F->lines, i, j));
    wc_error_init(err);
    if (wc_cone_set_generators(C, R, L, err) != WC_OK)
        wctest_fail("fcone_closure: %s", err->message);
    wc_error_clear(err);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
}

/* (c) and (d), one problem: returns the difference bits as
   compare_mode (-1 for a refusal).  A refusal must be clean (status
   WC_EINTERNAL or WC_EINPUT, a message, the cone left empty).  A double
   cone must be consistent in itself within SELF_TOL (unit rows, rays and
   lines on the right side of its facets and equalities, dimensions
   matching the bases).  When wc_fcone_compare_exact calls the two cones
   equal, ref-hausdorff.c (independent of it and of the library's angle
   code) must find the closures within AGREE_TOL of each other both ways,
   emptiness aside.  */
#define SELF_TOL 1e-6
#define AGREE_TOL 1e-7

static int
check_double(const wc_problem_t P, const char * mode)
{
    wc_cone_t X, Y;
    wc_fcone_t F;
    wc_error_t err;
    double lo, hi1 = 0, hi2 = 0;
    int status, bits = -1;
    slong i;

    wc_cone_init(X, 3);
    wc_cone_init(Y, 3);
    wc_fcone_init(F, 3);
    wc_error_init(err);
    if (wc_wrench_cone(X, NULL, P, mode, WC_METHOD_DIRECT, err) != WC_OK)
        wctest_fail_problem(P, mode, "exact route failed: %s", err->message);
    status = wc_wrench_cone_paper_double(F, P, mode, WC_FCONE_EPS, err);
    if (status != WC_OK)
    {
        if ((status != WC_EINTERNAL && status != WC_EINPUT)
            || err->message[0] == '\0' || !F->empty)
            wctest_fail_problem(P, mode, "double route: status %d, message "
                                "\"%s\", empty %d", status, err->message,
                                F->empty);
        goto done;
    }
    bits = wc_fcone_compare_exact(F, X, 1e-9);
    if (!F->empty)
    {
        const d_mat_struct * gen[2] = { F->rays, F->lines };
        const d_mat_struct * con[2] = { F->ineqs, F->eqs };
        slong g, c, k;

        if (F->dim != 3 - F->eqs->r || F->lineality_dim != F->lines->r)
            wctest_fail_problem(P, mode, "double cone: dim %ld with %ld "
                                "equalities, lineality %ld with %ld lines",
                                (long) F->dim, (long) F->eqs->r,
                                (long) F->lineality_dim, (long) F->lines->r);
        for (g = 0; g < 2; g++)
            for (i = 0; i < gen[g]->r; i++)
            {
                const double * x = gen[g]->rows[i];

                if (fabs(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 1)
                    > SELF_TOL)
                    wctest_fail_problem(P, mode, "double cone: a ray or line "
                                        "is not a unit vector");
                for (c = 0; c < 2; c++)
                    for (k = 0; k < con[c]->r; k++)
                    {
                        const double * h = con[c]->rows[k];
                        double t = h[0] * x[0] + h[1] * x[1] + h[2] * x[2];

                        /* rays: h . r <= 0 on facets; everything else 0 */
                        if (g == 0 && c == 0 ? t > SELF_TOL
                            : fabs(t) > SELF_TOL)
                            wctest_fail_problem(P, mode, "double cone: "
                                                "%s %ld against %s %ld: %g",
                                                g ? "line" : "ray", (long) i,
                                                c ? "equality" : "facet",
                                                (long) k, t);
                    }
            }
    }
    if (bits == 0 && !F->empty && !X->empty)
    {
        fcone_closure(Y, F);
        ref_directed_angle(&lo, &hi1, NULL, X, Y, AGREE_TOL / 10, 100000);
        ref_directed_angle(&lo, &hi2, NULL, Y, X, AGREE_TOL / 10, 100000);
        if (hi1 > AGREE_TOL || hi2 > AGREE_TOL)
            wctest_fail_problem(P, mode, "double and exact cones called "
                                "equal, yet ref-hausdorff.c puts them %.3g "
                                "and %.3g apart", hi1, hi2);
    }
done:
    wc_error_clear(err);
    wc_fcone_clear(F);
    wc_cone_clear(X);
    wc_cone_clear(Y);
    return bits;
}

/* (c) and (d): a random problem from lib/random.c.  */
static void
random_problem(wc_problem_t P, int degenerate)
{
    wc_random_options opt;
    wc_error_t err;

    wc_random_options_init(&opt);
    wc_error_init(err);
    opt.fixels = wctest_randint(1, 4);
    opt.seed = wctest_rand();
    opt.degenerate = degenerate;
    opt.shape = (wc_shape_kind) wctest_randint(0, 2);
    if (wc_random_problem(P, &opt, err) != WC_OK)
        wctest_fail("wc_random_problem failed: %s", err->message);
    wc_error_clear(err);
    wc_random_options_clear(&opt);
}

int
main(void)
{
    slong iters, i, k, ndeg = 0, disagree = 0, failed = 0;

    wctest_init("t-double");
    check_section4();
    check_corners();

    iters = wctest_iters(200);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;
        char mode[8];

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        random_problem(P, 0);
        for (k = 0; k < 2; k++)
        {
            wctest_random_mode(mode, P);
            compare_mode(P, mode, 1e-9, 1);
            check_double(P, mode);
        }
        wc_problem_clear(P);
    }

    iters = wctest_iters(400);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;
        char mode[8];
        int bits;

        if (!wctest_iter(200 + i))
            continue;
        wc_problem_init(P);
        random_problem(P, 1);
        wctest_random_mode(mode, P);
        bits = check_double(P, mode);
        ndeg++;
        disagree += bits != 0;
        failed += bits < 0;
        wc_problem_clear(P);
    }
    if (getenv("WC_TEST_VERBOSE") != NULL)
        fprintf(stderr, "t-double: degenerate problems: %ld of %ld differ "
                "beyond 1e-9 (%ld of them cddlib failures)\n",
                (long) disagree, (long) ndeg, (long) failed);
    /* The generator must keep making problems that fool doubles (about
       one in four; fewer than one in twenty among 100 or more has
       probability below 1e-10 at that rate), or (c)'s agreement and the
       exact route's reason to exist go unwitnessed.  */
    if (ndeg >= 100 && disagree * 20 < ndeg)
        wctest_fail("only %ld of %ld degenerate problems fool the double "
                    "route: the degenerate generator has gone soft",
                    (long) disagree, (long) ndeg);

    flint_cleanup_master();
    return 0;
}
