/* t-decimals.c -- decimal approximations of text output (print.h,
   --decimals): wc_fprint_fmpq_decimal against a reference written here
   on GMP's mpz alone (the deliberate independent copy: long division
   and a digit string, not the library's rounding formula), on hand
   cases (halves, negatives that round to zero, K = 0 and the maximum)
   and on seeded random rationals, large and small, for every K; then
   wc_fprint_fmpq_text and wc_fprint_qvec with decimals on and off, as
   their options (wc_print_opts) say; then three threads printing one
   stability answer at once, to 2 decimals, to 7 and without, each
   getting its own bytes every time (the setting is an argument, held by
   no thread).  */

#include <config.h>

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>

#include "wrenchcone.h"
#include "testutil.h"

/* What f prints to a string (malloc'd).  */
#define CAPTURE(buf, len, call)                                         \
    do {                                                                \
        FILE * f_ = open_memstream(&(buf), &(len));                     \
        if (f_ == NULL)                                                 \
            wctest_fail("open_memstream failed");                       \
        call;                                                           \
        if (fclose(f_) != 0)                                            \
            wctest_fail("fclose failed");                               \
    } while (0)

/* x = p/q rounded to K digits, half away from zero, by long division:
   integer part, then K digits, then the next digit and the remainder
   decide the rounding, carried through the digit string.  */
static char *
reference(const fmpq_t x, int K)
{
    mpz_t p, q, ip, r;
    char * digits, * out;
    size_t n, i;
    int k, neg = fmpq_sgn(x) < 0, up, zero = 1;

    mpz_inits(p, q, ip, r, NULL);
    fmpz_get_mpz(p, fmpq_numref(x));
    fmpz_get_mpz(q, fmpq_denref(x));
    mpz_abs(p, p);
    mpz_tdiv_qr(ip, r, p, q);
    n = mpz_sizeinbase(ip, 10) + (size_t) K + 4;
    digits = malloc(n + 2);
    mpz_get_str(digits, 10, ip);
    i = strlen(digits);
    for (k = 0; k < K; k++)
    {
        mpz_mul_ui(r, r, 10);
        mpz_tdiv_qr(ip, r, r, q);
        digits[i++] = (char) ('0' + mpz_get_ui(ip));
    }
    digits[i] = '\0';
    mpz_mul_ui(r, r, 2);
    up = mpz_cmp(r, q) >= 0;
    /* digits + 1 with carries, from the last.  */
    for (k = (int) i - 1; up && k >= 0; k--)
    {
        if (digits[k] == '9')
            digits[k] = '0';
        else
        {
            digits[k]++;
            up = 0;
        }
    }
    out = malloc(n + 8);
    i = 0;
    for (k = 0; digits[k] != '\0'; k++)
        zero &= digits[k] == '0';
    if (neg && !(zero && !up))
        out[i++] = '-';
    if (up)
        out[i++] = '1';
    n = strlen(digits);
    memcpy(out + i, digits, n - (size_t) K);
    i += n - (size_t) K;
    if (K > 0)
    {
        out[i++] = '.';
        memcpy(out + i, digits + n - K, (size_t) K);
        i += (size_t) K;
    }
    out[i] = '\0';
    free(digits);
    mpz_clears(p, q, ip, r, NULL);
    return out;
}

static void
check_one(const fmpq_t x, int K)
{
    char * got = NULL, * want = reference(x, K);
    size_t len = 0;

    CAPTURE(got, len, wc_fprint_fmpq_decimal(f_, x, K));
    if (strcmp(got, want) != 0)
    {
        char * s = fmpq_get_str(NULL, 10, x);

        wctest_fail("%s to %d digits: got %s, want %s", s, K, got, want);
    }
    free(got);
    free(want);
}

static void
hand(const char * q, int K, const char * want)
{
    fmpq_t x;
    char * got = NULL;
    size_t len = 0;

    fmpq_init(x);
    if (fmpq_set_str(x, q, 10) != 0)
        wctest_fail("bad rational %s", q);
    fmpq_canonicalise(x);
    CAPTURE(got, len, wc_fprint_fmpq_decimal(f_, x, K));
    if (strcmp(got, want) != 0)
        wctest_fail("%s to %d digits: got %s, want %s", q, K, got, want);
    check_one(x, K);
    free(got);
    fmpq_clear(x);
}

static void
test_hand(void)
{
    hand("-1/3", 3, "-0.333");
    hand("2/3", 3, "0.667");
    hand("5/3", 0, "2");
    hand("-5/3", 0, "-2");
    hand("1/8", 2, "0.13");
    hand("-1/8", 2, "-0.13");
    hand("1/2", 0, "1");
    hand("-1/2", 0, "-1");
    hand("-1/3000", 2, "0.00");
    hand("1/3000", 2, "0.00");
    hand("0", 3, "0.000");
    hand("7", 2, "7.00");
    hand("-7", 0, "-7");
    hand("999/1000", 2, "1.00");
    hand("-9995/1000", 2, "-10.00");
    hand("1/7", 50, "0.14285714285714285714285714285714285714285714285714");
    hand("123456789123456789/10", 1, "12345678912345678.9");
}

static void
test_random(void)
{
    slong i, iters = wctest_iters(4000);
    fmpq_t x;
    fmpz_t big;

    fmpq_init(x);
    fmpz_init(big);
    for (i = 0; i < iters; i++)
    {
        int K;

        if (!wctest_iter(i))
            continue;
        K = (int) wctest_randint(0, WC_DECIMALS_MAX);
        if (wctest_chance(1, 4))
        {
            /* Large numerators and denominators, and exact halves.  */
            fmpz_set_ui(big, wctest_rand());
            fmpz_mul_ui(big, big, (ulong) wctest_randint(1, 1000000));
            if (wctest_chance(1, 2))
                fmpz_neg(big, big);
            fmpz_set(fmpq_numref(x), big);
            fmpz_set_ui(fmpq_denref(x), 1);
            fmpz_mul_2exp(fmpq_denref(x), fmpq_denref(x),
                          (ulong) wctest_randint(0, 40));
            if (wctest_chance(1, 2))
                fmpz_mul_ui(fmpq_denref(x), fmpq_denref(x),
                            (ulong) wctest_randint(1, 100000));
            fmpq_canonicalise(x);
        }
        else
            wctest_rand_fmpq(x, 100000, 5000);
        check_one(x, K);
    }
    fmpz_clear(big);
    fmpq_clear(x);
}

static void
expect_text(const char * what, const char * got, const char * want)
{
    if (strcmp(got, want) != 0)
        wctest_fail("%s: got '%s', want '%s'", what, got, want);
}

static void
test_text(void)
{
    fmpq v[3];
    char * got = NULL, * want = NULL;
    size_t len = 0;
    wc_print_opts two = { WC_FORMAT_TEXT, 1, 2, NULL };
    wc_print_opts json = { WC_FORMAT_JSON, 1, 2, NULL };
    wc_print_opts zero = { WC_FORMAT_TEXT, 0, 0, NULL };
    wc_print_opts off = { WC_FORMAT_TEXT, 0, 5, NULL };
    wc_print_opts over = { WC_FORMAT_TEXT, 1, WC_DECIMALS_MAX + 7, NULL };
    wc_print_opts max = { WC_FORMAT_TEXT, 1, WC_DECIMALS_MAX, NULL };
    int j;

    for (j = 0; j < 3; j++)
        fmpq_init(v + j);
    fmpq_set_si(v + 0, -1, 3);
    fmpq_set_si(v + 1, 1, 1);
    fmpq_set_si(v + 2, 5, 8);
    CAPTURE(got, len, wc_fprint_qvec(f_, v, 3, NULL));
    expect_text("no options", got, "(-1/3, 1, 5/8)");
    free(got);
    CAPTURE(got, len, wc_fprint_qvec(f_, v, 3, &zero));
    expect_text("zeroed options", got, "(-1/3, 1, 5/8)");
    free(got);
    CAPTURE(got, len, wc_fprint_qvec(f_, v, 3, &two));
    expect_text("vector", got,
                "(-1/3, 1, 5/8) (approx. (-0.33, 1.00, 0.63))");
    free(got);
    CAPTURE(got, len, wc_fprint_qvec(f_, v, 3, &json));
    expect_text("JSON", got, "[\"-1/3\", \"1\", \"5/8\"]");
    free(got);
    CAPTURE(got, len, wc_fprint_qvec(f_, v + 1, 1, &two));
    expect_text("integers", got, "(1)");
    free(got);
    CAPTURE(got, len, wc_fprint_fmpq_text(f_, v + 0, &two));
    expect_text("scalar", got, "-1/3 (approx. -0.33)");
    free(got);
    CAPTURE(got, len, wc_fprint_fmpq_text(f_, v + 1, &two));
    expect_text("integer", got, "1");
    free(got);
    CAPTURE(got, len, wc_fprint_fmpq_text(f_, v + 0, &off));
    expect_text("approx unset", got, "-1/3");
    free(got);
    CAPTURE(got, len, wc_fprint_fmpq_text(f_, v + 0, &over));
    CAPTURE(want, len, wc_fprint_fmpq_text(f_, v + 0, &max));
    expect_text("decimals above the maximum", got, want);
    if (strlen(want) != strlen("-1/3 (approx. -0.)") + WC_DECIMALS_MAX)
        wctest_fail("%d decimals: '%s'", WC_DECIMALS_MAX, want);
    free(want);
    free(got);
    for (j = 0; j < 3; j++)
        fmpq_clear(v + j);
}

/* ------------------------------------------------------------------ */
/* Threads printing one answer with decimals of their own              */

/* Paper Figure 10's square with its three fixels touching: pushing
   regions whose ends are rationals (tests/cli-text.sh).  */
static const char touch[] =
    "friction 1/5\nshape polygon 0 0 4 0 4 3 0 3\ncom 2 3/2\nmass 1\n"
    "inertia 25/12\nfixel 1 0 touching\nfixel 3 0 touching\n"
    "fixel 0 2 touching\n";

#define NPRINTERS 3
#define REPEAT 200

typedef struct
{
    const wc_stability_struct * S;
    const wc_problem_struct * P;
    wc_print_opts o;
    const char * want;          /* its bytes, printed alone */
    long bad;                   /* the prints that differ from want */
}
printer;

static char *
stability_text(const wc_stability_t S, const wc_problem_t P,
               const wc_print_opts * o)
{
    char * buf = NULL;
    size_t len = 0;

    CAPTURE(buf, len, if (wc_stability_fprint(f_, S, P, o) != WC_OK)
                wctest_fail("wc_stability_fprint failed"));
    return buf;
}

static void *
print_many(void * arg)
{
    printer * p = arg;
    int i;

    for (i = 0; i < REPEAT; i++)
    {
        char * buf = NULL;
        size_t len = 0;
        FILE * f = open_memstream(&buf, &len);

        if (f == NULL || wc_stability_fprint(f, p->S, p->P, &p->o) != WC_OK
            || fclose(f) != 0 || strcmp(buf, p->want) != 0)
            p->bad++;
        free(buf);
    }
    flint_cleanup();            /* this thread's FLINT caches */
    return NULL;
}

/* A line of text, exactly.  */
static void
expect_line(const char * what, const char * text, const char * line)
{
    const char * s = text;
    size_t n = strlen(line);

    while (s != NULL && !(strncmp(s, line, n) == 0 && s[n] == '\n'))
        if ((s = strchr(s, '\n')) != NULL)
            s++;
    if (s == NULL)
        wctest_fail("%s: no line '%s' in:\n%s", what, line, text);
}

static void
test_threads(void)
{
    static const char * const edge1[NPRINTERS] = {
        "    edge 1: s in [35/78 (approx. 0.45), 2/3 (approx. 0.67)], "
        "(x, y) from (4, 35/26) (approx. (4.00, 1.35)) to (4, 2)",
        "    edge 1: s in [35/78 (approx. 0.4487179), 2/3 (approx. "
        "0.6666667)], (x, y) from (4, 35/26) (approx. (4.0000000, "
        "1.3461538)) to (4, 2)",
        "    edge 1: s in [35/78, 2/3], (x, y) from (4, 35/26) to (4, 2)"
    };
    wc_problem_t P;
    wc_stability_t S;
    wc_error_t err;
    printer p[NPRINTERS];
    pthread_t t[NPRINTERS];
    int i;

    wc_problem_init(P);
    wc_stability_init(S);
    wc_error_init(err);
    if (wc_problem_parse(P, touch, strlen(touch), "touch", err) != WC_OK
        || wc_stability(S, P, err) != WC_OK)
        wctest_fail("stability of the touching square: %s", err->message);
    for (i = 0; i < NPRINTERS; i++)
    {
        wc_print_opts o = { WC_FORMAT_TEXT, i < 2, i == 0 ? 2 : 7, NULL };

        p[i].S = S;
        p[i].P = P;
        p[i].o = o;
        p[i].want = stability_text(S, P, &o);
        p[i].bad = 0;
        expect_line("alone", p[i].want, edge1[i]);
    }
    for (i = 0; i < NPRINTERS; i++)
        if (pthread_create(t + i, NULL, print_many, p + i) != 0)
            wctest_fail("pthread_create failed");
    for (i = 0; i < NPRINTERS; i++)
        pthread_join(t[i], NULL);
    for (i = 0; i < NPRINTERS; i++)
    {
        if (p[i].bad != 0)
            wctest_fail("printer %d (approx %d, %d decimals): %ld of %d "
                        "prints differ from its own bytes", i, p[i].o.approx,
                        p[i].o.decimals, p[i].bad, REPEAT);
        free((char *) p[i].want);
    }
    wc_error_clear(err);
    wc_stability_clear(S);
    wc_problem_clear(P);
}

int
main(void)
{
    wctest_init("t-decimals");
    test_hand();
    test_random();
    test_text();
    test_threads();
    flint_cleanup_master();
    return 0;
}
