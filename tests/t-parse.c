/* t-parse.c -- tests of exact numbers, the .wc problem file and mode strings.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Silent on success; every failure is printed to stderr with the line of
   this file that found it, and the exit status is 1.  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "testutil.h"

#define fail(line, ...) wctest_report("t-parse.c", line, __VA_ARGS__)
#define FAIL(...) fail(__LINE__, __VA_ARGS__)

static int
q_is(const fmpq_t x, const char * expect)
{
    char * s = fmpq_get_str(NULL, 10, x);
    int r = strcmp(s, expect) == 0;

    flint_free(s);
    return r;
}

static char *
q_str(const fmpq_t x)
{
    char * s = fmpq_get_str(NULL, 10, x);
    char * d = malloc(strlen(s) + 1);

    strcpy(d, s);
    flint_free(s);
    return d;
}

/* ------------------------------------------------------------------ */
/* Numbers.                                                            */

static void
number_ok(int line, const char * s, const char * expect)
{
    fmpq_t x;
    wc_error_t e;
    int r;

    fmpq_init(x);
    wc_error_init(e);
    fmpq_set_si(x, 77, 3);
    r = wc_parse_number(x, s, strlen(s), e);
    if (r != WC_OK)
        fail(line, "number '%s': status %d (%s)", s, r,
             e->message != NULL ? e->message : "no message");
    else if (!q_is(x, expect))
    {
        char * got = q_str(x);

        fail(line, "number '%s': got %s, expected %s", s, got, expect);
        free(got);
    }
    fmpq_clear(x);
    wc_error_clear(e);
}

static void
number_bad(int line, const char * s, size_t len, const char * message)
{
    fmpq_t x;
    wc_error_t e;
    int r;

    fmpq_init(x);
    wc_error_init(e);
    r = wc_parse_number(x, s, len, e);
    if (r != WC_EINPUT)
        fail(line, "number '%.*s': status %d, expected %d", (int) len, s, r,
             WC_EINPUT);
    else if (e->message == NULL || strcmp(e->message, message) != 0)
        fail(line, "number '%.*s': message '%s', expected '%s'", (int) len, s,
             e->message != NULL ? e->message : "(null)", message);
    else if (e->file != NULL || e->line != 0 || e->col != 0)
        fail(line, "number '%.*s': location set", (int) len, s);
    fmpq_clear(x);
    wc_error_clear(e);
}

#define NUMBER_OK(s, v) number_ok(__LINE__, s, v)
#define NUMBER_BAD(s, m) number_bad(__LINE__, s, strlen(s), m)

static void
test_numbers(void)
{
    char big[200];

    NUMBER_OK("3", "3");
    NUMBER_OK("-2/7", "-2/7");
    NUMBER_OK("0.2", "1/5");
    NUMBER_OK("1.5e-3", "3/2000");
    NUMBER_OK("+4", "4");
    NUMBER_OK("-0.5", "-1/2");
    NUMBER_OK("1e3", "1000");
    NUMBER_OK("2/4", "1/2");
    NUMBER_OK("1E-2", "1/100");
    NUMBER_OK("-0", "0");
    NUMBER_OK("0/5", "0");
    NUMBER_OK("007", "7");
    NUMBER_OK(".5", "1/2");
    NUMBER_OK("5.", "5");
    NUMBER_OK("1.25e+2", "125");
    NUMBER_OK("12.5e-1", "5/4");
    NUMBER_OK("-6/4", "-3/2");
    NUMBER_OK("123456789012345678901234567890123456789012345678901234567890",
              "123456789012345678901234567890123456789012345678901234567890");
    NUMBER_OK("-123456789012345678901234567890/"
              "246913578024691357802469135780", "-1/2");
    NUMBER_OK("0.000000000000000000000000000001",
              "1/1000000000000000000000000000000");

    NUMBER_BAD("1/0", "division by zero in '1/0'");
    NUMBER_BAD("-3/000", "division by zero in '-3/000'");
    NUMBER_BAD("1//2", "bad number '1//2'");
    NUMBER_BAD(".", "bad number '.'");
    NUMBER_BAD("1e", "bad number '1e'");
    NUMBER_BAD("1e+", "bad number '1e+'");
    NUMBER_BAD("abc", "bad number 'abc'");
    NUMBER_BAD("0x10", "bad number '0x10'");
    NUMBER_BAD("1.2.3", "bad number '1.2.3'");
    NUMBER_BAD("", "bad number ''");
    NUMBER_BAD("-", "bad number '-'");
    NUMBER_BAD("+-1", "bad number '+-1'");
    NUMBER_BAD("1/-2", "bad number '1/-2'");
    NUMBER_BAD("1/2e3", "bad number '1/2e3'");
    NUMBER_BAD("1.5/2", "bad number '1.5/2'");
    NUMBER_BAD("/2", "bad number '/2'");
    NUMBER_BAD("1/", "bad number '1/'");
    NUMBER_BAD("1 ", "bad number '1 '");
    NUMBER_BAD("inf", "bad number 'inf'");
    NUMBER_BAD("1e100001", "exponent out of range in '1e100001'");
    NUMBER_BAD("1e-100001", "exponent out of range in '1e-100001'");
    NUMBER_BAD("1e1000000", "exponent out of range in '1e1000000'");
    NUMBER_BAD("1e0000000000000100001",
               "exponent out of range in '1e0000000000000100001'");
    NUMBER_OK("1e-0000000000000000002", "1/100");
    NUMBER_BAD("1_000", "bad number '1_000'");
    NUMBER_BAD("1 000", "bad number '1 000'");
    NUMBER_BAD("1,5", "bad number '1,5'");
    NUMBER_BAD("1e99999999999999999999999999",
               "exponent out of range in '1e99999999999999999999999999'");
    NUMBER_BAD("1e99999999999999999999999999x",
               "bad number '1e99999999999999999999999999x'");
    /* only len bytes are read: "12" of "123" */
    {
        fmpq_t x;
        wc_error_t e;

        fmpq_init(x);
        wc_error_init(e);
        if (wc_parse_number(x, "123", 2, e) != WC_OK || !q_is(x, "12"))
            FAIL("number '123' with len 2 is not 12");
        fmpq_clear(x);
        wc_error_clear(e);
    }
    /* a control byte is shown escaped, a long token is cut */
    number_bad(__LINE__, "1\0012", 3, "bad number '1\\x012'");
    memset(big, 'x', 100);
    big[100] = '\0';
    NUMBER_BAD(big, "bad number 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx"
               "xxxxxxxxxxxxxxxxxxxx...'");
    /* the largest exponents allowed */
    {
        fmpq_t x;
        fmpz_t t;
        wc_error_t e;

        fmpq_init(x);
        fmpz_init(t);
        wc_error_init(e);
        fmpz_set_ui(t, 10);
        fmpz_pow_ui(t, t, 100000);
        if (wc_parse_number(x, "1e100000", 8, e) != WC_OK
            || !fmpz_is_one(fmpq_denref(x)) || !fmpz_equal(fmpq_numref(x), t))
            FAIL("1e100000 is not 10^100000");
        fmpz_divexact_ui(t, t, 10);
        fmpz_mul_ui(t, t, 4);
        if (wc_parse_number(x, "-2.5e-100000", 12, e) != WC_OK
            || fmpz_cmp_si(fmpq_numref(x), -1) != 0
            || !fmpz_equal(fmpq_denref(x), t))
            FAIL("-2.5e-100000 is not -1/(4 10^99999)");
        fmpq_clear(x);
        fmpz_clear(t);
        wc_error_clear(e);
    }
}

/* ------------------------------------------------------------------ */
/* Problem files.                                                      */

static int
parse(wc_problem_t P, const char * text, wc_error_t e)
{
    return wc_problem_parse(P, text, strlen(text), "t.wc", e);
}

/* Parse text, which must succeed, into P (initialised here).  */
static int
parse_ok(int line, wc_problem_t P, const char * text)
{
    wc_error_t e;
    int r;

    wc_problem_init(P);
    wc_error_init(e);
    r = parse(P, text, e);
    if (r != WC_OK)
    {
        char * s = wc_error_format(e);

        fail(line, "parse failed: %s", s);
        free(s);
    }
    wc_error_clear(e);
    return r == WC_OK;
}

static void
parse_bad(int line, const char * text, long eline, long ecol,
          const char * message)
{
    wc_problem_t P;
    wc_error_t e;
    int r;

    wc_problem_init(P);
    wc_error_init(e);
    r = parse(P, text, e);
    if (r != WC_EINPUT)
        fail(line, "status %d, expected %d for error '%s'", r, WC_EINPUT,
             message);
    else if (e->file == NULL || strcmp(e->file, "t.wc") != 0
             || e->line != eline || e->col != ecol || e->message == NULL
             || strcmp(e->message, message) != 0)
        fail(line, "got %s:%ld:%ld: %s\n    expected t.wc:%ld:%ld: %s",
             e->file != NULL ? e->file : "(null)", e->line, e->col,
             e->message != NULL ? e->message : "(null)", eline, ecol,
             message);
    wc_problem_clear(P);
    wc_error_clear(e);
}

#define PARSE_OK(P, text) parse_ok(__LINE__, P, text)
#define PARSE_BAD(text, l, c, m) parse_bad(__LINE__, text, l, c, m)

static void
expect_q(int line, const char * what, const fmpq_t x, const char * v)
{
    if (!q_is(x, v))
    {
        char * s = q_str(x);

        fail(line, "%s is %s, expected %s", what, s, v);
        free(s);
    }
}

#define EXPECT_Q(what, x, v) expect_q(__LINE__, what, x, v)

static void
expect_fixel(int line, const wc_problem_t P, slong i, const char * px,
             const char * py, const char * nx, const char * ny,
             wc_fixel_state state, const char * mus, const char * muk)
{
    const wc_fixel_struct * f;

    if (i >= P->n)
    {
        fail(line, "no fixel %ld", (long) i + 1);
        return;
    }
    f = P->fixels + i;
    expect_q(line, "point x", f->point + 0, px);
    expect_q(line, "point y", f->point + 1, py);
    expect_q(line, "normal x", f->normal + 0, nx);
    expect_q(line, "normal y", f->normal + 1, ny);
    if (f->state != state)
        fail(line, "fixel %ld: state %d, expected %d", (long) i + 1,
             (int) f->state, (int) state);
    expect_q(line, "mu_s", f->mu_s, mus);
    expect_q(line, "mu_k", f->mu_k, muk);
}

#define EXPECT_FIXEL(P, i, px, py, nx, ny, st, mus, muk) \
    expect_fixel(__LINE__, P, i, px, py, nx, ny, st, mus, muk)

static void
test_defaults(void)
{
    wc_problem_t P;

    wc_problem_init(P);
    if (P->file != NULL || P->name != NULL || P->n != 0
        || P->shape != WC_SHAPE_NONE || P->shape_len != 0)
        FAIL("wc_problem_init defaults");
    EXPECT_Q("mass", P->mass, "1");
    EXPECT_Q("inertia", P->inertia, "1");
    EXPECT_Q("com x", P->com + 0, "0");
    EXPECT_Q("com y", P->com + 1, "0");
    EXPECT_Q("mu_s", P->mu_s, "0");
    EXPECT_Q("mu_k", P->mu_k, "0");
    wc_problem_clear(P);
    wc_problem_clear(P);    /* clear twice is safe */

    if (PARSE_OK(P, "fixel 0 -1 normal 0 1\n"))
    {
        if (P->file == NULL || strcmp(P->file, "t.wc") != 0)
            FAIL("file name not copied");
        if (P->name != NULL || P->n != 1 || P->shape != WC_SHAPE_NONE)
            FAIL("defaults of a parsed problem");
        EXPECT_Q("mass", P->mass, "1");
        EXPECT_Q("inertia", P->inertia, "1");
        EXPECT_Q("com x", P->com + 0, "0");
        EXPECT_Q("com y", P->com + 1, "0");
        EXPECT_FIXEL(P, 0, "0", "-1", "0", "1", WC_TOUCHING, "0", "0");
        if (P->fixels[0].line != 1 || P->fixels[0].col != 1)
            FAIL("fixel location %ld:%ld", P->fixels[0].line,
                 P->fixels[0].col);
    }
    wc_problem_clear(P);
}

static void
test_section4(void)
{
    wc_problem_t P;
    const char * text =
        "# The example of Section 4\n"
        "name  \"Section 4 example\"        # optional\n"
        "mass 1\n"
        "inertia 1\n"
        "com 0 0\n"
        "friction 1/5\n"
        "shape disk 0 0 1\n"
        "fixel 0 -1 normal 0 1 touching\n"
        "\n"
        "   \t\n"
        "\tfixel 1 0 normal -1 0 near\n";

    if (PARSE_OK(P, text))
    {
        if (P->name == NULL || strcmp(P->name, "Section 4 example") != 0)
            FAIL("name '%s'", P->name != NULL ? P->name : "(null)");
        if (P->shape != WC_SHAPE_DISK || P->shape_len != 3
            || P->shape_line != 7)
            FAIL("disk shape");
        else
        {
            EXPECT_Q("cx", P->shape_data + 0, "0");
            EXPECT_Q("r", P->shape_data + 2, "1");
        }
        EXPECT_Q("mu_s", P->mu_s, "1/5");
        EXPECT_Q("mu_k", P->mu_k, "1/5");
        if (P->n != 2)
            FAIL("n = %ld", (long) P->n);
        EXPECT_FIXEL(P, 0, "0", "-1", "0", "1", WC_TOUCHING, "1/5", "1/5");
        EXPECT_FIXEL(P, 1, "1", "0", "-1", "0", WC_NEAR, "1/5", "1/5");
        if (P->n == 2 && (P->fixels[1].line != 11 || P->fixels[1].col != 2))
            FAIL("fixel 2 location %ld:%ld", P->fixels[1].line,
                 P->fixels[1].col);
    }
    wc_problem_clear(P);
}

static void
test_friction(void)
{
    wc_problem_t P;

    /* the global friction applies wherever it is written */
    if (PARSE_OK(P, "fixel 0 0 normal 0 1\n"
                    "fixel 1 0 normal 0 1 friction 1/2\n"
                    "fixel 2 0 normal 0 1 near friction 3/4 1/4\n"
                    "fixel 3 0 friction 0 near normal 0 1\n"
                    "friction 1/3 1/6\n"))
    {
        EXPECT_Q("mu_s", P->mu_s, "1/3");
        EXPECT_Q("mu_k", P->mu_k, "1/6");
        EXPECT_FIXEL(P, 0, "0", "0", "0", "1", WC_TOUCHING, "1/3", "1/6");
        EXPECT_FIXEL(P, 1, "1", "0", "0", "1", WC_TOUCHING, "1/2", "1/2");
        EXPECT_FIXEL(P, 2, "2", "0", "0", "1", WC_NEAR, "3/4", "1/4");
        EXPECT_FIXEL(P, 3, "3", "0", "0", "1", WC_NEAR, "0", "0");
    }
    wc_problem_clear(P);
    if (PARSE_OK(P, "friction 0.25\nfixel 0 0 normal 1 0 friction 1 touching\n"
                    "fixel 0 0 normal -1 0\n"))
    {
        EXPECT_Q("mu_k", P->mu_k, "1/4");
        EXPECT_FIXEL(P, 0, "0", "0", "1", "0", WC_TOUCHING, "1", "1");
        EXPECT_FIXEL(P, 1, "0", "0", "-1", "0", WC_TOUCHING, "1/4", "1/4");
    }
    wc_problem_clear(P);
}

static void
test_derived(void)
{
    static const char * const squares[] = {
        "shape polygon 0 0 2 0 2 2 0 2\n"
        "fixel 1 0\nfixel 2 1\nfixel 1 2\nfixel 0 1/2\n",
        "shape polygon 0 0 0 2 2 2 2 0\n"
        "fixel 1 0\nfixel 2 1\nfixel 1 2\nfixel 0 1/2\n" };
    wc_problem_t P;
    int k;

    /* disk: the inward normal is centre - point, exactly */
    if (PARSE_OK(P, "shape disk 1 1 5\n"
                    "fixel 4 5\n"
                    "fixel -2 -3 near\n"
                    "fixel 1 -4 friction 1/2\n"
                    "fixel 6 1 normal 1 0\n"))
    {
        EXPECT_FIXEL(P, 0, "4", "5", "-3", "-4", WC_TOUCHING, "0", "0");
        EXPECT_FIXEL(P, 1, "-2", "-3", "3", "4", WC_NEAR, "0", "0");
        EXPECT_FIXEL(P, 2, "1", "-4", "0", "5", WC_TOUCHING, "1/2", "1/2");
        EXPECT_FIXEL(P, 3, "6", "1", "1", "0", WC_TOUCHING, "0", "0");
    }
    wc_problem_clear(P);
    /* a rational point on the circle, and the shape after the fixel */
    if (PARSE_OK(P, "fixel 3/5 4/5\nshape disk 0 0 1\n"))
        EXPECT_FIXEL(P, 0, "3/5", "4/5", "-3/5", "-4/5", WC_TOUCHING, "0",
                     "0");
    wc_problem_clear(P);

    /* a square counter-clockwise (edge vector turned +90 degrees), then
       the same square clockwise (turned -90 degrees): inward both times */
    for (k = 0; k < 2; k++)
    {
        if (PARSE_OK(P, squares[k]))
        {
            EXPECT_FIXEL(P, 0, "1", "0", "0", "2", WC_TOUCHING, "0", "0");
            EXPECT_FIXEL(P, 1, "2", "1", "-2", "0", WC_TOUCHING, "0", "0");
            EXPECT_FIXEL(P, 2, "1", "2", "0", "-2", WC_TOUCHING, "0", "0");
            EXPECT_FIXEL(P, 3, "0", "1/2", "2", "0", WC_TOUCHING, "0", "0");
        }
        wc_problem_clear(P);
    }
    /* a non-convex polygon (an L), clockwise, on a slanted edge of a
       triangle */
    if (PARSE_OK(P, "shape polygon 0 0 0 2 1 2 1 1 2 1 2 0\n"
                    "fixel 1 3/2\nfixel 3/2 1\n"))
    {
        EXPECT_FIXEL(P, 0, "1", "3/2", "-1", "0", WC_TOUCHING, "0", "0");
        EXPECT_FIXEL(P, 1, "3/2", "1", "0", "-1", WC_TOUCHING, "0", "0");
        if (P->shape != WC_SHAPE_POLYGON || P->shape_len != 12)
            FAIL("polygon shape");
    }
    wc_problem_clear(P);
    if (PARSE_OK(P, "shape polygon 0 0 4 0 0 4\nfixel 1 3\n"))
        EXPECT_FIXEL(P, 0, "1", "3", "-4", "-4", WC_TOUCHING, "0", "0");
    wc_problem_clear(P);
}

static void
test_lexical(void)
{
    wc_problem_t P;

    /* CRLF, comments glued to tokens, tabs, no final newline */
    if (PARSE_OK(P, "# comment\r\n\r\nmass 2#c\r\n\tinertia\t3/2 # x\r\n"
                    "name \"a \\\"b\\\" \\\\ #c\" # d\r\n"
                    "fixel 0 0 normal 0 1\r"))
    {
        EXPECT_Q("mass", P->mass, "2");
        EXPECT_Q("inertia", P->inertia, "3/2");
        if (P->name == NULL || strcmp(P->name, "a \"b\" \\ #c") != 0)
            FAIL("name with escapes: '%s'", P->name ? P->name : "(null)");
        if (P->n != 1 || P->fixels[0].line != 6)
            FAIL("CRLF line count");
    }
    wc_problem_clear(P);
    if (PARSE_OK(P, "name \"\"\nfixel 0 0 normal 0 1"))
        if (P->name == NULL || P->name[0] != '\0')
            FAIL("empty name");
    wc_problem_clear(P);
    /* opposed normals at one point are allowed */
    if (PARSE_OK(P, "fixel 0 0 normal 0 1\nfixel 0 0 normal 0 -1\n"
                    "fixel 0 0 normal 1 1\n"))
        if (P->n != 3)
            FAIL("opposed normals");
    wc_problem_clear(P);
}

static void
test_errors(void)
{
    /* each error class of wrenchcone(5), with its location */
    PARSE_BAD("mas 1\nfixel 0 0 normal 0 1\n", 1, 1, "unknown keyword 'mas'");
    PARSE_BAD("  Mass 1\n", 1, 3, "unknown keyword 'Mass'");
    PARSE_BAD("fixel 0 0 normal 0 1\n\"mass\" 1\n", 2, 1,
              "unknown keyword '\"mass\"'");
    PARSE_BAD("mass x1\n", 1, 6, "bad number 'x1'");
    PARSE_BAD("com 0 1.2.3\n", 1, 7, "bad number '1.2.3'");
    PARSE_BAD("fixel 0 0 normal 0 1\nfixel 1 0 normal 1/0 1\n", 2, 18,
              "division by zero in '1/0'");
    PARSE_BAD("mass 1e200000\n", 1, 6, "exponent out of range in '1e200000'");
    PARSE_BAD("fixel 0 0 normal 0 0\n", 1, 18, "zero normal");
    PARSE_BAD("fixel 0 0 normal 0/3 -0.0\n", 1, 18, "zero normal");
    PARSE_BAD("mass 0\n", 1, 6, "mass must be positive");
    PARSE_BAD("mass -1/2\n", 1, 6, "mass must be positive");
    PARSE_BAD("inertia 0\n", 1, 9, "inertia must be positive");
    PARSE_BAD("friction -1\n", 1, 10, "friction must be non-negative");
    PARSE_BAD("friction 1 -1/10\n", 1, 12, "friction must be non-negative");
    PARSE_BAD("fixel 0 0 normal 0 1 friction -1\n", 1, 31,
              "friction must be non-negative");
    PARSE_BAD("fixel 0 0 normal 0 1 friction 1 -1\n", 1, 33,
              "friction must be non-negative");
    PARSE_BAD("shape disk 0 0 0\n", 1, 16, "disk radius must be positive");
    PARSE_BAD("shape circle 0 0 1\n", 1, 7, "unknown shape 'circle'");
    PARSE_BAD("mass 1\n  shape polygon 0 0 1 0 1 0 0 1\n", 2, 3,
              "degenerate polygon: vertices 1 and 2 coincide");
    PARSE_BAD("shape polygon 0 0 1 0 0 1 0 0\n", 1, 1,
              "degenerate polygon: vertices 3 and 0 coincide");
    PARSE_BAD("shape polygon 0 0 1 0 2 0 0 1\n", 1, 1,
              "degenerate polygon: vertices 0, 1 and 2 are collinear");
    PARSE_BAD("shape polygon 0 0 1 0 2 0\n", 1, 1,
              "degenerate polygon: vertices 0, 1 and 2 are collinear");
    PARSE_BAD("shape polygon 0 0 2 0 2 2 0 2 0 1\n", 1, 1,
              "degenerate polygon: vertices 3, 4 and 0 are collinear");
    /* a spike: adjacent edges overlap */
    PARSE_BAD("shape polygon 0 0 2 0 1 0 1 1\n", 1, 1,
              "degenerate polygon: vertices 0, 1 and 2 are collinear");
    PARSE_BAD("shape polygon 0 0 1 1 1 0 0 1\n", 1, 1,
              "self-intersecting polygon: edges 0 and 2 cross");
    PARSE_BAD("shape polygon 0 0 4 0 4 4 2 0 0 4\n", 1, 1,
              "self-intersecting polygon: edges 0 and 2 touch");
    PARSE_BAD("shape polygon 0 0 2 0 2 2 1 0 0 1\n", 1, 1,
              "self-intersecting polygon: edges 0 and 2 touch");
    /* a vertex repeated, not consecutively: two edges touch there */
    PARSE_BAD("shape polygon 0 0 2 0 1 1 2 2 0 2 1 1\n", 1, 1,
              "self-intersecting polygon: edges 1 and 4 touch");
    PARSE_BAD("shape disk 0 0 1\nfixel 2 0\n", 2, 7,
              "point (2, 0) is not on the shape's boundary; give its normal");
    PARSE_BAD("shape disk 0 0 1\nfixel 1/2 1/2\n", 2, 7,
              "point (1/2, 1/2) is not on the shape's boundary; "
              "give its normal");
    PARSE_BAD("shape polygon 0 0 1 0 1 1 0 1\nfixel 1/2 1/2\n", 2, 7,
              "point (1/2, 1/2) is not on the shape's boundary; "
              "give its normal");
    PARSE_BAD("shape polygon 0 0 1 0 1 1 0 1\nfixel 2 0\n", 2, 7,
              "point (2, 0) is not on the shape's boundary; give its normal");
    PARSE_BAD("shape polygon 0 0 1 0 1 1 0 1\nfixel  1 1\n", 2, 8,
              "point (1, 1) is a polygon vertex; give its normal");
    PARSE_BAD("fixel 1 1\n", 1, 7,
              "no normal given and no shape to derive it from");
    PARSE_BAD("fixel 0 0 normal 0 1\nfixel 1 0 normal 0 1\n"
              "fixel 0 0 normal 0 2\n", 3, 7,
              "fixel 3 has the same point and normal as fixel 1");
    PARSE_BAD("fixel 0 0 normal 1/3 1/2 near\nfixel 0 0 normal 2 3\n", 2, 7,
              "fixel 2 has the same point and normal as fixel 1");
    PARSE_BAD("fixel 1 2 normal 0 1\nfixel 0 0 normal 0 1\n"
              "fixel 1 2 normal 0 1\nfixel 0 0 normal 0 1\n", 3, 7,
              "fixel 3 has the same point and normal as fixel 1");
    PARSE_BAD("fixel 0 0 normal 0 1\nfixel 1 2 normal 0 1\n"
              "fixel 0 0 normal 0 1\nfixel 1 2 normal 0 1\n", 3, 7,
              "fixel 3 has the same point and normal as fixel 1");
    /* a derived normal repeating a given one */
    PARSE_BAD("shape disk 0 0 1\nfixel 0 -1 normal 0 2\nfixel 0 -1\n", 3, 7,
              "fixel 2 has the same point and normal as fixel 1");
    PARSE_BAD("mass 1\nmass 2\n", 2, 1, "duplicate 'mass'");
    PARSE_BAD("name \"a\"\nname \"b\"\n", 2, 1, "duplicate 'name'");
    PARSE_BAD("friction 1\nfriction 1\n", 2, 1, "duplicate 'friction'");
    PARSE_BAD("shape disk 0 0 1\nshape disk 0 0 2\n", 2, 1,
              "duplicate 'shape'");
    PARSE_BAD("com 0 0\ncom 0 0\n", 2, 1, "duplicate 'com'");
    PARSE_BAD("inertia 1\ninertia 1\n", 2, 1, "duplicate 'inertia'");
    PARSE_BAD("fixel 0 0 normal 0 1 normal 0 1\n", 1, 22,
              "duplicate 'normal'");
    PARSE_BAD("fixel 0 0 normal 0 1 near touching\n", 1, 27,
              "duplicate fixel state 'touching'");
    PARSE_BAD("fixel 0 0 friction 1 normal 0 1 friction 1\n", 1, 33,
              "duplicate 'friction'");
    PARSE_BAD("mass\n", 1, 5, "'mass' needs a number");
    PARSE_BAD("mass   # none\n", 1, 5, "'mass' needs a number");
    PARSE_BAD("inertia\r\n", 1, 8, "'inertia' needs a number");
    PARSE_BAD("com 1\n", 1, 6, "'com' needs 2 numbers");
    PARSE_BAD("friction\n", 1, 9, "'friction' needs a number");
    PARSE_BAD("name\n", 1, 5, "'name' needs a quoted string");
    PARSE_BAD("name abc\n", 1, 6, "expected a quoted name, got 'abc'");
    PARSE_BAD("name \"a\\nb\"\n", 1, 8, "bad escape '\\n' in string");
    PARSE_BAD("shape\n", 1, 6, "'shape' needs 'disk' or 'polygon'");
    PARSE_BAD("shape disk 0 0\n", 1, 15, "'shape disk' needs 3 numbers");
    PARSE_BAD("shape polygon 0 0 1 0\n", 1, 22,
              "'shape polygon' needs at least 3 vertices");
    PARSE_BAD("shape polygon 0 0 1 0 1\n", 1, 24,
              "'shape polygon' needs at least 3 vertices");
    PARSE_BAD("shape polygon 0 0 1 0 1 1 0\n", 1, 28,
              "the last polygon vertex needs a y coordinate");
    PARSE_BAD("shape polygon 0 0 1 0 1 1 0 x\n", 1, 29, "bad number 'x'");
    PARSE_BAD("fixel\n", 1, 6, "'fixel' needs 2 numbers");
    PARSE_BAD("fixel 1\n", 1, 8, "'fixel' needs 2 numbers");
    PARSE_BAD("fixel 0 0 normal 1\n", 1, 19, "'normal' needs 2 numbers");
    PARSE_BAD("fixel 0 0 normal\n", 1, 17, "'normal' needs 2 numbers");
    PARSE_BAD("fixel 0 0 normal 0 1 friction\n", 1, 30,
              "'friction' needs a number");
    PARSE_BAD("mass 1 2\n", 1, 8, "unexpected token '2'");
    PARSE_BAD("com 0 0 0\n", 1, 9, "unexpected token '0'");
    PARSE_BAD("friction 1 2 3\n", 1, 14, "unexpected token '3'");
    PARSE_BAD("shape disk 0 0 1 1\n", 1, 18, "unexpected token '1'");
    PARSE_BAD("name \"a\" b\n", 1, 10, "unexpected token 'b'");
    PARSE_BAD("name \"a\"\"b\"\n", 1, 9, "unexpected token '\"b\"'");
    PARSE_BAD("fixel 0 0 normal 0 1 0\n", 1, 22, "unexpected token '0'");
    PARSE_BAD("fixel 0 0 nromal 0 1\n", 1, 11,
              "unknown fixel option 'nromal'");
    PARSE_BAD("fixel 0 0 normal 0 1 friction 1 nera\n", 1, 33,
              "unknown fixel option 'nera'");
    PARSE_BAD("fixel 0 0 normal 0 1 friction 1 2 3\n", 1, 35,
              "unexpected token '3'");
    PARSE_BAD("", 1, 1, "no fixel in the problem");
    PARSE_BAD("\n", 1, 1, "no fixel in the problem");
    PARSE_BAD("mass 1\n", 1, 7, "no fixel in the problem");
    PARSE_BAD("mass 1\ninertia 2 # x", 2, 14, "no fixel in the problem");
    PARSE_BAD("mass 1\r\n\r\n", 2, 1, "no fixel in the problem");
    PARSE_BAD("name \"abc\n", 1, 6, "unterminated string");
    PARSE_BAD("name \"abc\\\"\n", 1, 6, "unterminated string");
    PARSE_BAD("name \"abc\\\n", 1, 6, "unterminated string");
    PARSE_BAD("fixel 0 0 normal 0 1 friction 1 \"x\n", 1, 33,
              "unterminated string");

    /* the first error in file order wins */
    PARSE_BAD("mas 1\nmass 0\n", 1, 1, "unknown keyword 'mas'");
    PARSE_BAD("mass 0 x\n", 1, 6, "mass must be positive");
    PARSE_BAD("mas \"abc\n", 1, 1, "unknown keyword 'mas'");
    PARSE_BAD("shape disk 0 0 1\nfixel 2 0\nmas 1\n", 2, 7,
              "point (2, 0) is not on the shape's boundary; give its normal");
    PARSE_BAD("fixel 0 0 normal 0 1\nfixel 0 0 normal 0 1\nmas 1\n", 2, 7,
              "fixel 2 has the same point and normal as fixel 1");
    PARSE_BAD("fixel 2 0\nshape disk 0 0 1\nmas 1\n", 1, 7,
              "point (2, 0) is not on the shape's boundary; give its normal");
    /* the shape may come after the bad line: nothing to say about fixel 1 */
    PARSE_BAD("fixel 2 0\nmas 1\nshape disk 0 0 1\n", 2, 1,
              "unknown keyword 'mas'");
    PARSE_BAD("fixel 2 0\nshape polygon 0 0 1 0\n", 2, 22,
              "'shape polygon' needs at least 3 vertices");
    PARSE_BAD("shape disk 0 0 1\nfixel 0 0 normal 0 1\nfixel 2 0\n"
              "fixel 0 0 normal 0 1\n", 3, 7,
              "point (2, 0) is not on the shape's boundary; give its normal");
    PARSE_BAD("shape disk 0 0 1\nfixel 0 0 normal 0 1\nfixel 0 0 normal 0 1\n"
              "fixel 2 0\n", 3, 7,
              "fixel 2 has the same point and normal as fixel 1");
    PARSE_BAD("fixel 0 0 normal 0 1\nmass 1 1\nfixel 0 0 normal 0 1\n", 2, 8,
              "unexpected token '1'");
}

/* ------------------------------------------------------------------ */
/* Limits of the reader: numbers of at most 1024 bits, polygons of at   */
/* most 1000 vertices, long numbers cut in messages.                    */

/* A malloc'd "PREFIX<N>SUFFIX" with N = the integer f.  */
static char *
text_with(const char * prefix, const fmpz_t f, const char * suffix)
{
    char * d = fmpz_get_str(NULL, 10, f);
    char * t = malloc(strlen(prefix) + strlen(d) + strlen(suffix) + 1);

    strcpy(t, prefix);
    strcat(t, d);
    strcat(t, suffix);
    flint_free(d);
    return t;
}

/* The first 64 digits of f followed by "...", as messages cut them.  */
static char *
cut64(const fmpz_t f)
{
    char * d = fmpz_get_str(NULL, 10, f);
    char * t = malloc(68);

    memcpy(t, d, 64);
    strcpy(t + 64, "...");
    flint_free(d);
    return t;
}

static void
test_number_limits(void)
{
    wc_problem_t P;
    fmpz_t f;
    char * t, * c, * msg;
    size_t i, n = 1000000;

    fmpz_init(f);
    /* the exponents near the old bound, refused at once */
    PARSE_BAD("fixel 1e100000 0 normal 0 1\n", 1, 7, "number too big in "
              "'1e100000' (numerator or denominator over 1024 bits)");
    PARSE_BAD("fixel 0 -2.5e-100000 normal 0 1\n", 1, 9, "number too big in "
              "'-2.5e-100000' (numerator or denominator over 1024 bits)");
    PARSE_BAD("mass 1e309\n", 1, 6, "number too big in '1e309' (numerator "
              "or denominator over 1024 bits)");
    PARSE_BAD("mass 1e-309\n", 1, 6, "number too big in '1e-309' (numerator "
              "or denominator over 1024 bits)");
    /* 1e308 < 2^1024; 0 with any exponent is 0 */
    if (PARSE_OK(P, "mass 1e308\nfixel 0e100000 0 normal 0 1\n"))
    {
        fmpz_set_ui(f, 10);
        fmpz_pow_ui(f, f, 308);
        if (!fmpz_equal(fmpq_numref(P->mass), f)
            || !fmpq_is_zero(P->fixels[0].point + 0))
            FAIL("1e308 or 0e100000 misread");
    }
    wc_problem_clear(P);

    /* 2^1024 - 1 fits, 2^1024 does not, as an integer and as p/q */
    fmpz_one(f);
    fmpz_mul_2exp(f, f, 1024);
    fmpz_sub_ui(f, f, 1);
    t = text_with("mass 1/", f, "\nfixel 0 0 normal 0 1\n");
    if (PARSE_OK(P, t) && (!fmpz_is_one(fmpq_numref(P->mass))
                           || !fmpz_equal(fmpq_denref(P->mass), f)))
        FAIL("1/(2^1024 - 1) misread");
    wc_problem_clear(P);
    free(t);
    fmpz_add_ui(f, f, 1);
    c = cut64(f);
    t = text_with("mass ", f, "\n");
    msg = malloc(200);
    sprintf(msg, "number too big in '%s' (numerator or denominator over "
            "1024 bits)", c);
    PARSE_BAD(t, 1, 6, msg);
    free(t);
    t = text_with("mass 1/", f, "\n");
    sprintf(msg, "number too big in '1/%.62s...' (numerator or denominator "
            "over 1024 bits)", c);
    PARSE_BAD(t, 1, 6, msg);
    free(t);
    /* a decimal is judged in lowest terms: 2^-1023 = 5^1023 / 10^1023 fits,
       2^-1024 does not */
    fmpz_set_ui(f, 5);
    fmpz_pow_ui(f, f, 1023);
    {
        char * d = fmpz_get_str(NULL, 10, f);
        size_t nd = strlen(d);

        t = malloc(1100 + nd);
        strcpy(t, "mass 0.");
        for (i = 0; i < 1023 - nd; i++)
            strcat(t, "0");
        strcat(t, d);
        strcat(t, "\nfixel 0 0 normal 0 1\n");
        if (PARSE_OK(P, t)
            && (!fmpz_is_one(fmpq_numref(P->mass))
                || fmpz_bits(fmpq_denref(P->mass)) != 1024
                || fmpz_val2(fmpq_denref(P->mass)) != 1023))
            FAIL("0.000..5^1023 is not 1/2^1023");
        wc_problem_clear(P);
        free(t);
        flint_free(d);
    }
    fmpz_mul_ui(f, f, 5);
    free(c);
    {
        char * d = fmpz_get_str(NULL, 10, f);
        size_t nd = strlen(d);

        t = malloc(1100 + nd);
        strcpy(t, "mass 0.");
        for (i = 0; i < 1024 - nd; i++)
            strcat(t, "0");
        strcat(t, d);
        strcat(t, "\n");
        sprintf(msg, "number too big in '%.64s...' (numerator or "
                "denominator over 1024 bits)", t + 5);
        PARSE_BAD(t, 1, 6, msg);
        free(t);
        flint_free(d);
    }
    /* p/q is judged as written: 10^400 / 10^399 is refused */
    fmpz_set_ui(f, 10);
    fmpz_pow_ui(f, f, 399);
    fmpz_mul_ui(f, f, 10);
    t = text_with("com 0 ", f, "/");
    fmpz_divexact_ui(f, f, 10);
    c = text_with(t, f, "\n");
    PARSE_BAD(c, 1, 7, "number too big in '100000000000000000000000000000"
              "0000000000000000000000000000000000...' (numerator or "
              "denominator over 1024 bits)");
    free(t);
    free(c);
    /* a 1 MB coordinate: refused at once, and cut in the message */
    t = malloc(n + 40);
    strcpy(t, "fixel 0 1");
    for (i = 9; i < n + 9; i++)
        t[i] = '0';
    strcpy(t + i, " normal 0 1\n");
    PARSE_BAD(t, 1, 9, "number too big in '1000000000000000000000000000000"
              "000000000000000000000000000000000...' (numerator or "
              "denominator over 1024 bits)");
    /* leading zeros are not significant */
    t[8] = '0';
    t[n + 8] = '7';
    if (PARSE_OK(P, t) && !q_is(P->fixels[0].point + 1, "7"))
        FAIL("000...07 is not 7");
    wc_problem_clear(P);
    free(t);
    /* a point quoted in a message is cut too */
    fmpz_set_ui(f, 10);
    fmpz_pow_ui(f, f, 300);
    t = text_with("shape disk 0 0 1\nfixel ", f, " 0\n");
    PARSE_BAD(t, 2, 7, "point (100000000000000000000000000000000000000000"
              "0000000000000000000000..., 0) is not on the shape's boundary; "
              "give its normal");
    free(t);
    free(msg);
    fmpz_clear(f);
}

/* "shape polygon" with m vertices (i, i^2), a convex polygon, and a
   fixel.  */
static char *
parabola(slong m)
{
    char * t = malloc((size_t) m * 24 + 64);
    size_t pos;
    slong i;

    pos = (size_t) sprintf(t, "shape polygon");
    for (i = 0; i < m; i++)
        pos += (size_t) sprintf(t + pos, " %ld %ld", (long) i, (long) (i * i));
    sprintf(t + pos, "\nfixel 1/2 0 normal 0 1\n");
    return t;
}

static void
test_polygon_limit(void)
{
    wc_problem_t P;
    char * t;
    long col;

    t = parabola(1000);
    if (PARSE_OK(P, t) && P->shape_len != 2000)
        FAIL("1000 vertices: shape_len %ld", (long) P->shape_len);
    wc_problem_clear(P);
    /* the error is at vertex 1000's x (numbered from 0) */
    col = (long) strlen(t) - (long) strlen("\nfixel 1/2 0 normal 0 1\n") + 2;
    free(t);
    t = parabola(1001);
    PARSE_BAD(t, 1, col, "polygon has more than 1000 vertices");
    free(t);
    t = parabola(5000);
    PARSE_BAD(t, 1, col, "polygon has more than 1000 vertices");
    free(t);
}

/* NUL bytes and long lines come from files too.  */
static void
test_binary(void)
{
    wc_problem_t P;
    wc_error_t e;
    static const char text[] = "mass 1\nma\0ss 1\n";
    char * big;
    size_t i, n = 200000;
    int r;

    wc_problem_init(P);
    wc_error_init(e);
    r = wc_problem_parse(P, text, sizeof text - 1, "t.wc", e);
    if (r != WC_EINPUT || e->line != 2 || e->col != 1
        || strcmp(e->message, "unknown keyword 'ma\\x00ss'") != 0)
        FAIL("NUL byte in a keyword: %s", e->message ? e->message : "");
    wc_problem_clear(P);
    wc_error_clear(e);

    /* many fixels: the arrays grow by doubling, and the duplicate check
       (by sorting) finds the earliest repeat among thousands */
    big = malloc(n * 40);
    {
        size_t len = 0;

        for (i = 0; i < n / 40; i++)
            len += (size_t) sprintf(big + len, "fixel %lu 0 normal 0 1\n",
                                    (unsigned long) i);
        wc_problem_init(P);
        wc_error_init(e);
        r = wc_problem_parse(P, big, len, NULL, e);
        if (r != WC_OK || P->n != (slong) (n / 40) || P->file != NULL)
            FAIL("%lu fixels: status %d", (unsigned long) (n / 40), r);
        else if (!fmpz_equal_si(fmpq_numref(P->fixels[n / 40 - 1].point),
                                (slong) (n / 40 - 1)))
            FAIL("last fixel's point");
        wc_problem_clear(P);
        len += (size_t) sprintf(big + len, "fixel 17 0 normal 0 3\n");
        wc_problem_init(P);
        r = wc_problem_parse(P, big, len, NULL, e);
        if (r != WC_EINPUT || e->file != NULL || e->line != (long) n / 40 + 1
            || strcmp(e->message, "fixel 5001 has the same point and normal "
                      "as fixel 18") != 0)
            FAIL("duplicate among many: %s", e->message ? e->message : "");
        wc_problem_clear(P);
        wc_error_clear(e);
    }
    free(big);
}

/* ------------------------------------------------------------------ */
/* Printing.                                                           */

static int
same_problem(int line, const wc_problem_t A, const wc_problem_t B)
{
    slong i;
    int bad = wctest_failures();

    if ((A->name == NULL) != (B->name == NULL)
        || (A->name != NULL && strcmp(A->name, B->name) != 0))
        fail(line, "names differ");
    if (!fmpq_equal(A->mass, B->mass) || !fmpq_equal(A->inertia, B->inertia)
        || !fmpq_equal(A->com + 0, B->com + 0)
        || !fmpq_equal(A->com + 1, B->com + 1)
        || !fmpq_equal(A->mu_s, B->mu_s) || !fmpq_equal(A->mu_k, B->mu_k))
        fail(line, "mass, inertia, com or friction differ");
    if (A->shape != B->shape || A->shape_len != B->shape_len)
        fail(line, "shapes differ");
    else
        for (i = 0; i < A->shape_len; i++)
            if (!fmpq_equal(A->shape_data + i, B->shape_data + i))
                fail(line, "shape number %ld differs", (long) i);
    if (A->n != B->n)
        fail(line, "%ld fixels, then %ld", (long) A->n, (long) B->n);
    else
        for (i = 0; i < A->n; i++)
        {
            const wc_fixel_struct * a = A->fixels + i, * b = B->fixels + i;

            if (!fmpq_equal(a->point + 0, b->point + 0)
                || !fmpq_equal(a->point + 1, b->point + 1)
                || !fmpq_equal(a->normal + 0, b->normal + 0)
                || !fmpq_equal(a->normal + 1, b->normal + 1)
                || a->state != b->state || !fmpq_equal(a->mu_s, b->mu_s)
                || !fmpq_equal(a->mu_k, b->mu_k))
                fail(line, "fixel %ld differs", (long) i + 1);
        }
    return wctest_failures() == bad;
}

static char *
print_to_string(const wc_problem_t P, size_t * len)
{
    FILE * f = tmpfile();
    char * s = NULL;
    long n;

    if (f == NULL)
        return NULL;
    if (wc_problem_fprint(f, P) == WC_OK && (n = ftell(f)) >= 0
        && fseek(f, 0, SEEK_SET) == 0 && (s = malloc((size_t) n + 1)) != NULL)
    {
        *len = fread(s, 1, (size_t) n, f);
        s[*len] = '\0';
    }
    fclose(f);
    return s;
}

static void
round_trip(int line, const wc_problem_t P)
{
    wc_problem_t Q;
    wc_error_t e;
    char * s, * t;
    size_t len = 0, len2 = 0;

    s = print_to_string(P, &len);
    if (s == NULL)
    {
        fail(line, "wc_problem_fprint failed");
        return;
    }
    wc_problem_init(Q);
    wc_error_init(e);
    if (wc_problem_parse(Q, s, len, "printed", e) != WC_OK)
        fail(line, "printed problem does not parse: %ld:%ld: %s\n%s",
             e->line, e->col, e->message, s);
    else if (same_problem(line, P, Q))
    {
        /* printing is a fixed point */
        t = print_to_string(Q, &len2);
        if (t == NULL || len2 != len || memcmp(s, t, len) != 0)
            fail(line, "second print differs");
        free(t);
    }
    wc_problem_clear(Q);
    wc_error_clear(e);
    free(s);
}

static void
test_print(void)
{
    wc_problem_t P;
    wc_fixel_struct * f;
    FILE * f0;
    char * s;
    size_t len = 0;
    slong i;

    if (PARSE_OK(P, "name \"q\\\"uote \\\\ # not a comment\"\n"
                    "mass 3/2\ninertia 1e-2\ncom -1/3 2.5\n"
                    "friction 1/5 1/10\nshape disk 1/2 0 2\n"
                    "fixel 1/2 2\nfixel 5/2 0 near friction 1 1/2\n"
                    "fixel 0 0 normal 0 1/7\n"))
        round_trip(__LINE__, P);
    wc_problem_clear(P);
    if (PARSE_OK(P, "shape polygon 0 0 0 2 1 2 1 1 2 1 2 0\nfixel 1 3/2\n"))
        round_trip(__LINE__, P);
    wc_problem_clear(P);

    /* the exact text printed for a small problem */
    if (PARSE_OK(P, "fixel 0 -1 normal 0 1\nfriction 1/5\n"))
    {
        s = print_to_string(P, &len);
        if (s == NULL || strcmp(s, "mass 1\ninertia 1\ncom 0 0\n"
                                "friction 1/5 1/5\nfixel 0 -1 normal 0 1 "
                                "touching friction 1/5 1/5\n") != 0)
            FAIL("printed text:\n%s", s != NULL ? s : "(null)");
        free(s);
    }
    wc_problem_clear(P);

    /* a problem built with wc_problem_add_fixel */
    wc_problem_init(P);
    fmpq_set_si(P->mu_s, 1, 3);
    fmpq_set_si(P->mu_k, 1, 4);
    for (i = 0; i < 40; i++)
    {
        f = wc_problem_add_fixel(P);
        if (f == NULL)
        {
            FAIL("wc_problem_add_fixel failed");
            break;
        }
        if (!fmpq_is_zero(f->point + 0) || !fmpq_is_zero(f->normal + 1)
            || f->state != WC_TOUCHING || f->line != 0 || f->col != 0
            || !q_is(f->mu_s, i < 20 ? "1/3" : "1/2")
            || !q_is(f->mu_k, i < 20 ? "1/4" : "1/2"))
            FAIL("new fixel %ld", (long) i);
        fmpq_set_si(f->point + 0, i, 7);
        fmpq_set_si(f->point + 1, -i, 1);
        fmpq_set_si(f->normal + 0, 1, 1);
        fmpq_set_si(f->normal + 1, i, 3);
        f->state = i % 2 ? WC_NEAR : WC_TOUCHING;
        if (i == 19)
        {
            fmpq_set_si(P->mu_s, 1, 2);
            fmpq_set_si(P->mu_k, 1, 2);
        }
    }
    if (P->n == 40)
    {
        if (!q_is(P->fixels[39].point + 0, "39/7")
            || !q_is(P->fixels[3].normal + 1, "1"))
            FAIL("fixels lost when the array grew");
        round_trip(__LINE__, P);
    }
    /* a write error is reported */
    f0 = fopen("/dev/full", "w");
    if (f0 != NULL)
    {
        int r;

        setvbuf(f0, NULL, _IONBF, 0);
        r = wc_problem_fprint(f0, P);
        if (r != WC_EINTERNAL)
            FAIL("writing to /dev/full: status %d", r);
        fclose(f0);
    }
    wc_problem_clear(P);
}

/* ------------------------------------------------------------------ */
/* Modes.                                                              */

static void
mode_bad(int line, const wc_problem_t P, const char * mode,
         wc_mode_table table, long col, const char * message)
{
    wc_error_t e;
    int r;

    wc_error_init(e);
    r = wc_mode_check(P, mode, table, e);
    if (r != WC_EINPUT || e->file == NULL || strcmp(e->file, "<mode>") != 0
        || e->line != 1 || e->col != col || e->message == NULL
        || strcmp(e->message, message) != 0)
        fail(line, "mode '%s': status %d, %s:%ld:%ld: %s\n    expected "
             "<mode>:1:%ld: %s", mode, r, e->file ? e->file : "(null)",
             e->line, e->col, e->message ? e->message : "(null)", col,
             message);
    wc_error_clear(e);
}

static void
mode_ok(int line, const wc_problem_t P, const char * mode,
        wc_mode_table table)
{
    wc_error_t e;
    int r;

    wc_error_init(e);
    r = wc_mode_check(P, mode, table, e);
    if (r != WC_OK)
        fail(line, "mode '%s' table %d: %s", mode, (int) table,
             e->message ? e->message : "(null)");
    wc_error_clear(e);
}

#define MODE_OK(P, m, t) mode_ok(__LINE__, P, m, t)
#define MODE_BAD(P, m, t, c, msg) mode_bad(__LINE__, P, m, t, c, msg)

static void
test_modes(void)
{
    wc_problem_t P;
    const char * all = "abcdefghijklmnopqrstuvwxyz";
    const char * l;

    /* fixel 1 touching, fixel 2 near */
    if (!PARSE_OK(P, "fixel 0 -1 normal 0 1\nfixel 1 0 normal -1 0 near\n"))
    {
        wc_problem_clear(P);
        return;
    }
    for (l = all; *l != '\0'; l++)
    {
        char m[3];
        int on_touching_cone = strchr("slrnm", *l) != NULL;
        int on_near_cone = strchr("sau", *l) != NULL;
        int on_touching_kin = strchr("slrn", *l) != NULL;
        int on_near_kin = strchr("sa", *l) != NULL;
        char msg[80];

        /* letter on fixel 1 (touching), s on fixel 2 */
        m[0] = *l;
        m[1] = 's';
        m[2] = '\0';
        if (on_touching_cone)
            MODE_OK(P, m, WC_TABLE_CONE);
        else
        {
            if (on_near_cone)
                sprintf(msg, "letter '%c' not allowed on fixel 1, which is "
                        "touching", *l);
            else
                sprintf(msg, "unknown mode letter '%c'", *l);
            MODE_BAD(P, m, WC_TABLE_CONE, 1, msg);
        }
        if (on_touching_kin)
            MODE_OK(P, m, WC_TABLE_KINEMATIC);
        else
        {
            if (on_near_kin)
                sprintf(msg, "letter '%c' not allowed on fixel 1, which is "
                        "touching", *l);
            else
                sprintf(msg, "unknown mode letter '%c'", *l);
            MODE_BAD(P, m, WC_TABLE_KINEMATIC, 1, msg);
        }
        /* s on fixel 1, letter on fixel 2 (near) */
        m[0] = 's';
        m[1] = *l;
        if (on_near_cone)
            MODE_OK(P, m, WC_TABLE_CONE);
        else
        {
            if (on_touching_cone)
                sprintf(msg, "letter '%c' not allowed on fixel 2, which is "
                        "near", *l);
            else
                sprintf(msg, "unknown mode letter '%c'", *l);
            MODE_BAD(P, m, WC_TABLE_CONE, 2, msg);
        }
        if (on_near_kin)
            MODE_OK(P, m, WC_TABLE_KINEMATIC);
        else
        {
            if (on_touching_kin)
                sprintf(msg, "letter '%c' not allowed on fixel 2, which is "
                        "near", *l);
            else
                sprintf(msg, "unknown mode letter '%c'", *l);
            MODE_BAD(P, m, WC_TABLE_KINEMATIC, 2, msg);
        }
    }
    MODE_OK(P, "na", WC_TABLE_CONE);
    MODE_OK(P, "na", WC_TABLE_KINEMATIC);
    MODE_BAD(P, "NA", WC_TABLE_CONE, 1, "unknown mode letter 'N'");
    MODE_BAD(P, "n\001", WC_TABLE_CONE, 2, "unknown mode letter '\\x01'");
    MODE_BAD(P, "n ", WC_TABLE_CONE, 2, "unknown mode letter ' '");
    MODE_BAD(P, "nas", WC_TABLE_CONE, 3,
             "mode has 3 letters; the problem has 2 fixels");
    MODE_BAD(P, "xyzw", WC_TABLE_KINEMATIC, 3,
             "mode has 4 letters; the problem has 2 fixels");
    MODE_BAD(P, "n", WC_TABLE_CONE, 2,
             "mode has 1 letter; the problem has 2 fixels");
    MODE_BAD(P, "", WC_TABLE_KINEMATIC, 1,
             "mode has 0 letters; the problem has 2 fixels");
    wc_problem_clear(P);

    if (PARSE_OK(P, "fixel 0 -1 normal 0 1 near\n"))
    {
        MODE_OK(P, "u", WC_TABLE_CONE);
        MODE_BAD(P, "u", WC_TABLE_KINEMATIC, 1, "unknown mode letter 'u'");
        MODE_BAD(P, "n", WC_TABLE_CONE, 1,
                 "letter 'n' not allowed on fixel 1, which is near");
        MODE_BAD(P, "ss", WC_TABLE_CONE, 2,
                 "mode has 2 letters; the problem has 1 fixel");
    }
    wc_problem_clear(P);
}


/* ------------------------------------------------------------------ */
/* Randomized checks.                                                  */

/* A random x = N / 10^k, written as a decimal with the point moved t
   places and "e<t>" after it, must parse back to x: the writer here is
   independent of the reader.  */
static void
test_random_decimals(void)
{
    slong i, iters = wctest_iters(2000);
    fmpz_t N;
    fmpq_t x, y;
    wc_error_t e;

    fmpz_init(N);
    fmpq_init(x);
    fmpq_init(y);
    wc_error_init(e);
    for (i = 0; i < iters; i++)
    {
        char * digits, * text;
        slong k, t, f, nd, j, pos = 0;
        int neg;

        if (!wctest_iter(i))
            continue;
        /* N: up to 40 digits */
        fmpz_zero(N);
        nd = wctest_randint(1, 40);
        for (j = 0; j < nd; j++)
        {
            fmpz_mul_ui(N, N, 10);
            fmpz_add_ui(N, N, (ulong) wctest_randint(0, 9));
        }
        neg = wctest_chance(1, 2);
        k = wctest_randint(0, 30);
        t = wctest_chance(1, 2) ? 0 : wctest_randint(-40, 40);
        fmpz_set_ui(fmpq_denref(x), 10);
        fmpz_pow_ui(fmpq_denref(x), fmpq_denref(x), (ulong) k);
        fmpz_set(fmpq_numref(x), N);
        if (neg)
            fmpz_neg(fmpq_numref(x), fmpq_numref(x));
        fmpq_canonicalise(x);

        /* the value is (N 10^-(k+t)) 10^t: f = k + t digits after the
           point */
        digits = fmpz_get_str(NULL, 10, N);
        nd = (slong) strlen(digits);
        f = k + t;
        text = malloc((size_t) (nd + (f < 0 ? -f : f) + 40));
        if (neg)
            text[pos++] = '-';
        else if (wctest_chance(1, 4))
            text[pos++] = '+';
        if (f <= 0)
        {
            memcpy(text + pos, digits, (size_t) nd);
            pos += nd;
            for (j = 0; j < -f; j++)
                text[pos++] = '0';
            if (wctest_chance(1, 3))
                text[pos++] = '.';
        }
        else if (f < nd)
        {
            memcpy(text + pos, digits, (size_t) (nd - f));
            pos += nd - f;
            text[pos++] = '.';
            memcpy(text + pos, digits + nd - f, (size_t) f);
            pos += f;
        }
        else
        {
            if (wctest_chance(2, 3))
                text[pos++] = '0';
            text[pos++] = '.';
            for (j = 0; j < f - nd; j++)
                text[pos++] = '0';
            memcpy(text + pos, digits, (size_t) nd);
            pos += nd;
        }
        if (t != 0 || wctest_chance(1, 4))
            pos += sprintf(text + pos, "%s%s%ld",
                           wctest_chance(1, 2) ? "e" : "E",
                           t >= 0 && wctest_chance(1, 2) ? "+" : "",
                           (long) t);
        text[pos] = '\0';
        if (wc_parse_number(y, text, (size_t) pos, e) != WC_OK)
            wctest_fail("'%s' does not parse: %s", text, e->message);
        if (!fmpq_equal(x, y))
        {
            char * a = q_str(x), * b = q_str(y);

            wctest_fail("'%s' parsed as %s, expected %s", text, b, a);
        }
        free(text);
        flint_free(digits);
    }
    fmpz_clear(N);
    fmpq_clear(x);
    fmpq_clear(y);
    wc_error_clear(e);
}

/* Random problems: print, parse back, compare; printing again gives the
   same text.  */
static void
test_random_round_trip(void)
{
    slong i, iters = wctest_iters(300);

    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        wctest_random_problem(P, 1, 8);
        if (wctest_chance(1, 3))
        {
            static const char * names[] = {
                "", "x", "a \"quoted\" name", "back\\slash", "# not a comment",
                "tab\there", "caf\xc3\xa9"
            };
            const char * nm = names[wctest_randint(0, 6)];

            P->name = malloc(strlen(nm) + 1);
            strcpy(P->name, nm);
        }
        if (wctest_chance(1, 3))
        {
            slong j;

            P->shape = wctest_chance(1, 2) ? WC_SHAPE_DISK : WC_SHAPE_POLYGON;
            P->shape_len = P->shape == WC_SHAPE_DISK ? 3 : 8;
            P->shape_data = malloc((size_t) P->shape_len * sizeof(fmpq));
            for (j = 0; j < P->shape_len; j++)
                fmpq_init(P->shape_data + j);
            if (P->shape == WC_SHAPE_DISK)
            {
                wctest_rand_fmpq(P->shape_data + 0, 5, 3);
                wctest_rand_fmpq(P->shape_data + 1, 5, 3);
                wctest_rand_fmpq_pos(P->shape_data + 2, 5, 3);
            }
            else
            {
                /* a box */
                fmpq_t w;

                fmpq_init(w);
                wctest_rand_fmpq(P->shape_data + 0, 5, 3);
                wctest_rand_fmpq(P->shape_data + 1, 5, 3);
                wctest_rand_fmpq_pos(w, 5, 3);
                fmpq_add(P->shape_data + 2, P->shape_data + 0, w);
                fmpq_set(P->shape_data + 3, P->shape_data + 1);
                fmpq_set(P->shape_data + 4, P->shape_data + 2);
                wctest_rand_fmpq_pos(w, 5, 3);
                fmpq_add(P->shape_data + 5, P->shape_data + 1, w);
                fmpq_set(P->shape_data + 6, P->shape_data + 0);
                fmpq_set(P->shape_data + 7, P->shape_data + 5);
                fmpq_clear(w);
            }
        }
        {
            int before = wctest_failures();

            round_trip(__LINE__, P);
            if (wctest_failures() != before)
                wctest_fail_problem(P, NULL, "round trip failed");
        }
        wc_problem_clear(P);
    }
}

/* Lines of random tokens, good and bad: the parser must answer WC_OK or
   WC_EINPUT with a location inside the text, and whatever it accepts must
   survive a round trip.  Run under valgrind this also checks that no
   error path leaks.  */
static void
test_random_files(void)
{
    static const char * words[] = {
        "name", "mass", "inertia", "com", "friction", "shape", "disk",
        "polygon", "fixel", "normal", "touching", "near", "0", "1", "-1",
        "2", "1/2", "-3/4", "0.5", "1e-1", "1/0", "x", "\"n\"", "\"a\\\"b\"",
        "\"open", "#", "# c", "\t", "\r"
    };
    static const char * lines[] = {
        "fixel 0 0 normal 0 1", "fixel 1 0 normal -1 0 near", "fixel 0 1",
        "fixel 0 -1 friction 1/2", "fixel 1/2 0", "fixel 3/5 4/5",
        "fixel 1 1/2 near", "fixel 0 0 normal 1 1", "fixel 1 0",
        "shape disk 0 0 1", "shape polygon 0 0 1 0 1 1 0 1",
        "shape polygon 0 0 1 1 1 0 0 1", "friction 1/5", "friction 1/5 1/10",
        "mass 2", "inertia 1/3", "com 1/2 0", "name \"n\"", "# comment", "",
        "\t fixel -1 0 normal 1 0 touching friction 0 # left"
    };
    static const char * keywords[] = {
        "name", "mass", "inertia", "com", "friction", "shape", "fixel"
    };
    const slong nlinetypes = (slong) (sizeof lines / sizeof lines[0]);
    const slong nwords = (slong) (sizeof words / sizeof words[0]);
    slong i, iters = wctest_iters(2000);

    for (i = 0; i < iters; i++)
    {
        char text[2048];
        size_t len = 0;
        slong nlines, l, w, nw;
        long linelen[40];
        wc_problem_t P;
        wc_error_t e;
        int r;

        if (!wctest_iter(i))
            continue;
        nlines = wctest_randint(0, 12);
        for (l = 0; l < nlines; l++)
        {
            size_t start = len;

            int kind = (int) wctest_randint(0, 7);
            const char * word;

            nw = 0;
            if (kind <= 6)
            {
                /* a good line, or a keyword, perhaps with more words */
                word = kind <= 4 ? lines[wctest_randint(0, nlinetypes - 1)]
                    : keywords[wctest_randint(0, 6)];
                memcpy(text + len, word, strlen(word));
                len += strlen(word);
                nw = kind <= 3 ? 0 : kind == 4 ? 1 : wctest_randint(0, 5);
            }
            else
                nw = wctest_randint(0, 6);
            for (w = 0; w < nw; w++)
            {
                word = words[wctest_randint(0, nwords - 1)];
                if (len > start)
                    text[len++] = ' ';
                memcpy(text + len, word, strlen(word));
                len += strlen(word);
            }
            linelen[l] = (long) (len - start);
            if (len > start && text[len - 1] == '\r')
                linelen[l]--;
            if (l + 1 < nlines || wctest_chance(1, 2))
                text[len++] = '\n';
        }
        text[len] = '\0';
        wc_problem_init(P);
        wc_error_init(e);
        r = wc_problem_parse(P, text, len, "f", e);
        if (r == WC_EINPUT)
        {
            long lmax = nlines > 0 ? (long) nlines : 1;

            if (e->message == NULL || e->file == NULL
                || strcmp(e->file, "f") != 0 || e->line < 1
                || e->line > lmax || e->col < 1
                || e->col > (nlines > 0 ? linelen[e->line - 1] + 1 : 1))
                wctest_fail("bad error record %s:%ld:%ld: %s for\n%s",
                            e->file ? e->file : "(null)", e->line, e->col,
                            e->message ? e->message : "(null)", text);
        }
        else if (r == WC_OK)
        {
            int before = wctest_failures();

            if (P->n < 1)
                wctest_fail("accepted a problem without fixels:\n%s", text);
            round_trip(__LINE__, P);
            if (wctest_failures() != before)
                wctest_fail("round trip failed for\n%s", text);
        }
        else
            wctest_fail("status %d for\n%s", r, text);
        wc_problem_clear(P);
        wc_error_clear(e);
    }
}

int
main(void)
{
    wctest_init("t-parse");
    test_numbers();
    test_defaults();
    test_section4();
    test_friction();
    test_derived();
    test_lexical();
    test_errors();
    test_number_limits();
    test_polygon_limit();
    test_binary();
    test_print();
    test_modes();
    test_random_decimals();
    test_random_round_trip();
    test_random_files();
    /* return FLINT's cached integers, so valgrind sees no leak */
    flint_cleanup();
    if (wctest_failures() != 0)
    {
        fprintf(stderr, "t-parse: %d failure%s\n", wctest_failures(),
                wctest_failures() == 1 ? "" : "s");
        return 1;
    }
    return 0;
}
