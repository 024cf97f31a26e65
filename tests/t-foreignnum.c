/* t-foreignnum.c -- the exact reading of a foreign cone's numbers
   (_wc_foreign_number, whose plain decimals go through a fast path of
   machine words and one power of ten) against the former reading, kept
   below as ref_number: the deliberate independent copy (the length and
   exponent checks, then the core's wc_parse_number and its message
   relocated).  Both must give the same status, the same rational, and
   on error the same message at the same place, byte for byte.  The
   values of accepted plain decimals are also checked against a third
   reading written here on GMP's mpz alone (digits, then a power of ten,
   then mpq_canonicalize).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Tokens: hand cases (signs, leading and trailing zeros, a lone dot,
   exponents 0, 1000 and 1001, "1e-300", huge exponents, fractions,
   junk), %.17g and %.3e of random doubles, and seeded random strings
   drawn from the pieces of a number (sign, zeros, digits, dot,
   exponent) with now and then a piece broken or a long mantissa (up to
   the 1,000-character limit and just beyond).  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>

#include "wrenchcone.h"
#include "float/foreign.h"
#include "testutil.h"

/* The former _wc_foreign_number, as it was before the fast path.  */
static int
ref_number(fmpq_t x, const _wc_source * s, const char * t, size_t n,
           long line, long col)
{
    size_t i, e = n;
    long ex = 0;
    int status;

    if (n > WC_FOREIGN_MAX_CHARS)
        return _wc_located(s, line, col, "number too long (over %d "
                           "characters)", WC_FOREIGN_MAX_CHARS);
    for (i = 0; i < n; i++)
        if (t[i] == 'e' || t[i] == 'E')
            e = i + 1;
    if (e < n && (t[e] == '+' || t[e] == '-'))
        e++;
    for (i = e; i < n && t[i] >= '0' && t[i] <= '9'; i++)
        if ((ex = 10 * ex + (t[i] - '0')) > WC_FOREIGN_MAX_EXPONENT)
            return _wc_located_quoting(s, line, col, "exponent out of "
                                       "range in '%s' (at most 1000 here)",
                                       t, n);
    status = wc_parse_number(x, t, n, s->err);
    if (status == WC_EINPUT)
    {
        char * m = s->err->message;

        s->err->message = NULL;
        _wc_located(s, line, col, "%s", m != NULL ? m : "bad number");
        free(m);
    }
    return status;
}

/* A third reading of a plain decimal [sign] digits [. digits] [e|E
   [sign] digits], on mpz alone: 1 and q set, or 0 when t is not one
   (or is over the length or exponent limit).  */
static int
gmp_number(mpq_t q, const char * t, size_t n)
{
    char * d = malloc(n + 2);
    size_t i = 0, nd = 0, nfrac = 0;
    long e = 0, ten;
    int neg = 0, eneg = 0, dot = 0, ok = 1;
    mpz_t p;

    if (d == NULL)
        wctest_fail("out of memory");
    if (n > WC_FOREIGN_MAX_CHARS)
        ok = 0;
    if (i < n && (t[i] == '+' || t[i] == '-'))
        neg = t[i++] == '-';
    for (; i < n && ((t[i] >= '0' && t[i] <= '9') || (t[i] == '.' && !dot));
         i++)
        if (t[i] == '.')
            dot = 1;
        else
        {
            d[nd++] = t[i];
            nfrac += dot;
        }
    if (nd == 0)
        ok = 0;
    if (ok && i < n && (t[i] == 'e' || t[i] == 'E'))
    {
        size_t e0;

        i++;
        if (i < n && (t[i] == '+' || t[i] == '-'))
            eneg = t[i++] == '-';
        /* past the bound, the digits are skipped, not accumulated */
        for (e0 = i; i < n && t[i] >= '0' && t[i] <= '9'; i++)
            if (ok && (e = 10 * e + (t[i] - '0')) > WC_FOREIGN_MAX_EXPONENT)
                ok = 0;
        if (i == e0)
            ok = 0;
    }
    if (i != n)
        ok = 0;
    if (ok)
    {
        d[nd] = '\0';
        mpz_init(p);
        mpz_set_str(mpq_numref(q), d, 10);
        ten = (eneg ? -e : e) - (long) nfrac;
        mpz_ui_pow_ui(p, 10, (unsigned long) (ten < 0 ? -ten : ten));
        if (ten >= 0)
        {
            mpz_mul(mpq_numref(q), mpq_numref(q), p);
            mpz_set_ui(mpq_denref(q), 1);
        }
        else
            mpz_set(mpq_denref(q), p);
        mpq_canonicalize(q);
        if (neg)
            mpq_neg(q, q);
        mpz_clear(p);
    }
    free(d);
    return ok;
}

static long nfast;

/* Read t both ways (and the third way) and compare everything.  */
static void
check(const char * t, size_t n)
{
    wc_error_t e1, e2;
    _wc_source s1 = { t, n, "f.ine", e1 }, s2 = { t, n, "f.ine", e2 };
    fmpq_t x1, x2;
    mpq_t q;
    int r1, r2;

    wc_error_init(e1);
    wc_error_init(e2);
    fmpq_init(x1);
    fmpq_init(x2);
    mpq_init(q);
    fmpq_set_si(x1, 77, 5);     /* stale values must not matter */
    fmpq_set_si(x2, -3, 7);
    r1 = _wc_foreign_number(x1, &s1, t, n, 12, 34);
    r2 = ref_number(x2, &s2, t, n, 12, 34);
    if (r1 != r2)
        wctest_fail("'%.*s': status %d, the former reading %d", (int) n, t,
                    r1, r2);
    if (r1 == WC_OK && (!fmpq_equal(x1, x2) || !fmpq_is_canonical(x1)))
        wctest_fail("'%.*s': a value other than the former reading's",
                    (int) n, t);
    if (r1 != WC_OK)
    {
        char * f1 = wc_error_format(e1), * f2 = wc_error_format(e2);

        if (f1 == NULL || f2 == NULL || strcmp(f1, f2) != 0)
            wctest_fail("'%.*s': message '%s', the former '%s'", (int) n, t,
                        f1 ? f1 : "(null)", f2 ? f2 : "(null)");
        free(f1);
        free(f2);
    }
    if (gmp_number(q, t, n))
    {
        mpq_t y;

        if (r1 != WC_OK)
            wctest_fail("'%.*s': a plain decimal refused", (int) n, t);
        mpq_init(y);
        fmpq_get_mpq(y, x1);
        if (!mpq_equal(q, y))
            wctest_fail("'%.*s': a value other than the GMP reading's",
                        (int) n, t);
        mpq_clear(y);
        nfast++;
    }
    mpq_clear(q);
    fmpq_clear(x1);
    fmpq_clear(x2);
    wc_error_clear(e1);
    wc_error_clear(e2);
}

static void
check_str(const char * t)
{
    check(t, strlen(t));
}

static const char * hand[] = {
    "0", "-0", "+0", "00", "0.", ".0", "-.0", "0.000", "000.000e5", "1",
    "-1", "+1", "10", "100", "1000000000000000000", "10000000000000000000",
    "18446744073709551615", "18446744073709551616", "9999999999999999999",
    "99999999999999999999", "1234567890123456789", "12345678901234567890",
    "0.1", "-0.1", "0.5", "0.25", "0.125", "0.2", "0.04", "0.008",
    "1.5e-3", "1.5E-3", "1.5e+3", "1.5E3", "1e0", "1e-0", "1e+0",
    "1e1000", "1e-1000", "1e1001", "1e-1001", "-2.5e1000", "7e-1001",
    "1e0001000", "1e00001001", "1e-300", "1e300", "-1e-300", "4.9e-324",
    "1.7976931348623157e308", "2.2250738585072014e-308",
    "0.30000000000000004", "-0.12345678901234567", "1.2345678901234567e-05",
    "123456789012345678.90", "5e-27", "5e-28", "2e-62", "2e-63", "3e-64",
    "0.0000000000000000000000000000625", "1.0000000000000000000000000000001",
    "1e99999999999999999999", "1e-99999999999999999999", "1e100001",
    "1e", "1e+", "1e-", "e5", ".", "-", "+", "", " 1", "1 ", "1..2",
    "1.2.3", "1e5e5", "1e5.5", "0x10", "inf", "-inf", "nan", "1/3",
    "-2/4", "1/0", "0/5", "1/", "/2", "++1", "--1", "1-", "1,5", "1e1000/3",
    "3/1e5", "1.5/2", "١", "1\x00" "2", "9e999", "12e-1000", "0e1001",
    "0.0e-1001", "-0e1000",
};

/* Random pieces of a number, or of something like one.  */
static size_t
random_token(char * b, size_t cap)
{
    size_t n = 0, i, len;
    static const char junk[] = "+-.eE/ x0";

#define PUT(c) do { if (n < cap) b[n++] = (c); } while (0)
    if (wctest_chance(1, 2))
        PUT(wctest_chance(1, 2) ? '-' : '+');
    for (i = wctest_chance(1, 3) ? wctest_randint(1, 5) : 0; i > 0; i--)
        PUT('0');
    len = wctest_chance(1, 20) ? (size_t) wctest_randint(0, 1000)
                               : (size_t) wctest_randint(0, 22);
    for (i = 0; i < len; i++)
        PUT((char) ('0' + wctest_randint(0, 9)));
    if (wctest_chance(2, 3))
    {
        PUT('.');
        len = wctest_chance(1, 20) ? (size_t) wctest_randint(0, 1000)
                                   : (size_t) wctest_randint(0, 22);
        for (i = 0; i < len; i++)
            PUT((char) ('0' + wctest_randint(0, 9)));
        for (i = wctest_chance(1, 3) ? wctest_randint(1, 5) : 0; i > 0; i--)
            PUT('0');
    }
    if (wctest_chance(1, 2))
    {
        slong e = wctest_chance(1, 4) ? wctest_randint(990, 1010)
                                      : wctest_randint(0, 400);

        PUT(wctest_chance(1, 2) ? 'e' : 'E');
        if (wctest_chance(2, 3))
            PUT(wctest_chance(1, 2) ? '-' : '+');
        for (i = wctest_chance(1, 4) ? wctest_randint(1, 3) : 0; i > 0; i--)
            PUT('0');
        n += (size_t) snprintf(b + n, cap - n, "%ld", (long) e);
        if (n > cap)
            n = cap;
    }
    if (n > 0 && wctest_chance(1, 15))       /* one character broken */
        b[wctest_randint(0, (slong) n - 1)] = junk[wctest_randint(0, 8)];
#undef PUT
    return n;
}

int
main(void)
{
    slong i, iters;
    char b[1100];
    static char big[1200];

    wctest_init("t-foreignnum");
    for (i = 0; i < (slong) (sizeof hand / sizeof hand[0]); i++)
        check_str(hand[i]);
    check("1\0" "2", 3);
    /* the length limit, on both sides */
    for (i = 999; i <= 1001; i++)
    {
        memset(big, '7', (size_t) i);
        big[1] = '.';
        check(big, (size_t) i);
        big[0] = '-';
        check(big, (size_t) i);
        memcpy(big + i - 5, "e-999", 5);
        check(big, (size_t) i);
    }
    iters = wctest_iters(20000);
    for (i = 0; i < iters; i++)
    {
        size_t n;

        if (!wctest_iter(i))
            continue;
        if (wctest_chance(1, 4))
        {
            double v = (double) (wctest_rand() >> 11) / 9007199254740992.0;
            int sc = (int) wctest_randint(-320, 300);

            while (sc > 0)
                v *= 10, sc--;
            while (sc < 0)
                v /= 10, sc++;
            if (wctest_chance(1, 2))
                v = -v;
            n = (size_t) snprintf(b, sizeof b, wctest_chance(1, 2) ? "%.17g"
                                  : "%.3e", v);
        }
        else
            n = random_token(b, sizeof b);
        check(b, n);
    }
    if (nfast < iters / 4)
        wctest_fail("only %ld plain decimals in %ld tokens", nfast,
                    (long) iters);
    printf("t-foreignnum: %ld tokens, %ld plain decimals, as the former "
           "reading\n", (long) iters, nfast);
    return 0;
}
