/* number.c -- exact numbers as the problem file writes them.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz.h>

#include "core/lexer.h"
#include "core/limits.h"
#include "core/problem.h"
#include "core/text.h"

static int
is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* f = the decimal digits s[a0..a1) followed by s[b0..b1); at least one
   digit in all.  */
static int
set_digits(fmpz_t f, const char * s, size_t a0, size_t a1, size_t b0,
           size_t b1)
{
    char * buf = malloc(a1 - a0 + b1 - b0 + 1);

    if (buf == NULL)
        return -1;
    memcpy(buf, s + a0, a1 - a0);
    memcpy(buf + (a1 - a0), s + b0, b1 - b0);
    buf[a1 - a0 + b1 - b0] = '\0';
    fmpz_set_str(f, buf, 10);
    free(buf);
    return 0;
}

/* The parts of a number as written: sign, the integer digits (or the
   numerator) s[a0..a1), the fraction digits (or the denominator) s[b0..b1),
   and the exponent.  */
typedef struct
{
    int neg;
    int fraction;       /* p/q rather than a decimal */
    size_t a0, a1, b0, b1;
    int eneg;
    unsigned long e;    /* saturates just above WC_MAX_EXPONENT */
}
wc_numparts;

/* Split s[0..len) into np: 0 when it is a number, 1 when it is not, 2
   when it is but its exponent is out of range.  */
static int
scan_number(wc_numparts * np, const char * s, size_t len)
{
    size_t i = 0, e0;

    memset(np, 0, sizeof *np);
    if (i < len && (s[i] == '+' || s[i] == '-'))
    {
        np->neg = s[i] == '-';
        i++;
    }
    np->a0 = i;
    while (i < len && is_digit(s[i]))
        i++;
    np->a1 = i;
    if (i < len && s[i] == '/')
    {
        np->fraction = 1;
        np->b0 = ++i;
        while (i < len && is_digit(s[i]))
            i++;
        np->b1 = i;
        return np->a1 == np->a0 || np->b1 == np->b0 || i != len;
    }
    if (i < len && s[i] == '.')
    {
        np->b0 = ++i;
        while (i < len && is_digit(s[i]))
            i++;
        np->b1 = i;
    }
    if (np->a1 == np->a0 && np->b1 == np->b0)
        return 1;
    if (i < len && (s[i] == 'e' || s[i] == 'E'))
    {
        i++;
        if (i < len && (s[i] == '+' || s[i] == '-'))
        {
            np->eneg = s[i] == '-';
            i++;
        }
        e0 = i;
        while (i < len && is_digit(s[i]))
        {
            /* saturate: any value above the bound is as bad */
            if (np->e <= WC_MAX_EXPONENT)
                np->e = 10 * np->e + (unsigned long) (s[i] - '0');
            i++;
        }
        if (i == e0)
            return 1;
    }
    if (i != len)
        return 1;
    return np->e > WC_MAX_EXPONENT ? 2 : 0;
}

/* scan_number, its failure set in err as the error of the token s
   (WC_OK, or the status of that error).  */
static int
scan_checked(wc_numparts * np, const char * s, size_t len, wc_error_t err)
{
    int r = scan_number(np, s, len);

    if (r == 0)
        return WC_OK;
    return _wc_error_token(err, WC_EINPUT, NULL, 0, 0, r == 1
                           ? "bad number '%s'"
                           : "exponent out of range in '%s'", s, len);
}

int
wc_parse_number(fmpq_t x, const char * s, size_t len, wc_error_t err)
{
    wc_numparts np;
    fmpz_t num, den;
    size_t nfrac;
    int status = scan_checked(&np, s, len, err);

    if (status != WC_OK)
        return status;
    fmpz_init(num);
    fmpz_init(den);
    if (np.fraction)
    {
        if (set_digits(num, s, np.a0, np.a1, 0, 0) != 0
            || set_digits(den, s, np.b0, np.b1, 0, 0) != 0)
        {
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "out of memory");
            goto cleanup;
        }
        if (fmpz_is_zero(den))
        {
            status = _wc_error_token(err, WC_EINPUT, NULL, 0, 0,
                                     "division by zero in '%s'", s, len);
            goto cleanup;
        }
    }
    else
    {
        if (set_digits(num, s, np.a0, np.a1, np.b0, np.b1) != 0)
        {
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "out of memory");
            goto cleanup;
        }
        /* value = digits * 10^(+-e - nfrac) */
        nfrac = np.b1 - np.b0;
        fmpz_set_ui(den, 10);
        if (np.eneg)
            fmpz_pow_ui(den, den, (ulong) (np.e + nfrac));
        else if (np.e >= nfrac)
        {
            fmpz_pow_ui(den, den, (ulong) (np.e - nfrac));
            fmpz_mul(num, num, den);
            fmpz_one(den);
        }
        else
            fmpz_pow_ui(den, den, (ulong) (nfrac - np.e));
    }
    if (np.neg)
        fmpz_neg(num, num);
    fmpq_set_fmpz_frac(x, num, den);
cleanup:
    fmpz_clear(num);
    fmpz_clear(den);
    return status;
}


/* The significant digits of the digit string s[a0..a1) s[b0..b1): *lead
   leading and *trail trailing zeros; all zero when *lead is the length.  */
static void
count_zeros(const char * s, size_t a0, size_t a1, size_t b0, size_t b1,
            size_t * lead, size_t * trail)
{
    size_t na = a1 - a0, n = na + (b1 - b0), i;

#define DIGIT(i) ((i) < na ? s[a0 + (i)] : s[b0 + (i) - na])
    for (i = 0; i < n && DIGIT(i) == '0'; i++)
        ;
    *lead = i;
    for (i = n; i > *lead && DIGIT(i - 1) == '0'; i--)
        ;
    *trail = n - i;
#undef DIGIT
}

/* f = the digits s[a0..a1) s[b0..b1) without the first lead and the last
   trail of them.  */
static int
set_significant(fmpz_t f, const char * s, size_t a0, size_t a1, size_t b0,
                size_t b1, size_t lead, size_t trail)
{
    size_t na = a1 - a0, n = na + (b1 - b0), lo = lead, hi = n - trail;

    if (lo >= hi)
    {
        fmpz_zero(f);
        return 0;
    }
    /* clip [lo, hi) of the joined string to each part */
    return set_digits(f, s, a0 + (lo < na ? lo : na),
                      a0 + (hi < na ? hi : na),
                      b0 + (lo > na ? lo - na : 0),
                      b0 + (hi > na ? hi - na : 0));
}

/* A fraction p/q with p and q of at most WC_NUMBER_MAX_BITS bits as
   written: 0, 1 when too big, -1 out of memory.  The digit count decides
   before any conversion.  */
static int
bounded_fraction(fmpz_t num, fmpz_t den, const char * s,
                 const wc_numparts * np)
{
    size_t lp, tp, lq, tq;

    count_zeros(s, np->a0, np->a1, 0, 0, &lp, &tp);
    count_zeros(s, np->b0, np->b1, 0, 0, &lq, &tq);
    if (lq == np->b1 - np->b0)
    {
        fmpz_zero(den);         /* division by zero, reported as such */
        return 0;
    }
    if (np->a1 - np->a0 - lp > WC_NUMBER_MAX_DIGITS
        || np->b1 - np->b0 - lq > WC_NUMBER_MAX_DIGITS)
        return 1;
    if (set_significant(num, s, np->a0, np->a1, 0, 0, lp, 0) != 0
        || set_significant(den, s, np->b0, np->b1, 0, 0, lq, 0) != 0)
        return -1;
    return fmpz_bits(num) > WC_NUMBER_MAX_BITS
           || fmpz_bits(den) > WC_NUMBER_MAX_BITS;
}

/* A decimal D 10^E, reduced, with numerator and denominator of at most
   WC_NUMBER_MAX_BITS bits: 0, 1 when too big, -1 out of memory.  With D'
   = D without its trailing zeros (d digits, not a multiple of 10) and E'
   = E plus their number, the two bounds below imply the reduced value is
   too big, so no power of ten beyond 10^WC_NUMBER_MAX_BITS is built:
   E' >= 0: the numerator D' 10^E' >= 10^(d - 1 + E');
   E' = -k < 0: the denominator 10^k / gcd(D', 10^k) keeps all of 2^k or
   all of 5^k, as D' lacks a factor 2 or 5, so it is >= 2^k; the numerator
   is >= D' / 10^k >= 10^(d - 1 - k).  */
static int
bounded_decimal(fmpz_t num, fmpz_t den, const char * s,
                const wc_numparts * np)
{
    size_t lead, trail, n = np->a1 - np->a0 + np->b1 - np->b0;
    slong d, E;

    count_zeros(s, np->a0, np->a1, np->b0, np->b1, &lead, &trail);
    fmpz_one(den);
    if (lead == n)
    {
        fmpz_zero(num);
        return 0;
    }
    d = (slong) (n - lead - trail);
    /* e <= WC_MAX_EXPONENT here; the lengths are those of a text */
    E = (np->eneg ? -(slong) np->e : (slong) np->e)
        - (slong) (np->b1 - np->b0) + (slong) trail;
    if (E >= 0 ? d - 1 + E >= WC_NUMBER_MAX_DIGITS
        : (-E > WC_NUMBER_MAX_BITS || d - 1 + E >= WC_NUMBER_MAX_DIGITS))
        return 1;
    if (set_significant(num, s, np->a0, np->a1, np->b0, np->b1, lead, trail)
        != 0)
        return -1;
    fmpz_set_ui(den, 10);
    if (E >= 0)
    {
        fmpz_pow_ui(den, den, (ulong) E);
        fmpz_mul(num, num, den);
        fmpz_one(den);
    }
    else
    {
        fmpz_t g;

        fmpz_pow_ui(den, den, (ulong) -E);
        fmpz_init(g);
        fmpz_gcd(g, num, den);
        fmpz_divexact(num, num, g);
        fmpz_divexact(den, den, g);
        fmpz_clear(g);
    }
    return fmpz_bits(num) > WC_NUMBER_MAX_BITS
           || fmpz_bits(den) > WC_NUMBER_MAX_BITS;
}

int
wc_parse_number_bounded(fmpq_t x, const char * s, size_t len,
                        wc_error_t err)
{
    wc_numparts np;
    fmpz_t num, den;
    int big;
    int status = scan_checked(&np, s, len, err);

    if (status != WC_OK)
        return status;
    fmpz_init(num);
    fmpz_init(den);
    big = np.fraction ? bounded_fraction(num, den, s, &np)
                      : bounded_decimal(num, den, s, &np);
    if (big < 0)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    else if (big > 0)
        status = _wc_error_token(err, WC_EINPUT, NULL, 0, 0,
                                 "number too big in '%s' (numerator or "
                                 "denominator over 1024 bits)", s, len);
    else if (fmpz_is_zero(den))
        status = _wc_error_token(err, WC_EINPUT, NULL, 0, 0,
                                 "division by zero in '%s'", s, len);
    else
    {
        if (np.neg)
            fmpz_neg(num, num);
        fmpq_set_fmpz_frac(x, num, den);
    }
    fmpz_clear(num);
    fmpz_clear(den);
    return status;
}

/* ------------------------------------------------------------------ */
/* Lists of numbers A,B,C                                              */

int
wc_parse_number_list(fmpq ** v, slong * count, const char * s, slong max,
                     const char * why, const char * noun, const char * what,
                     wc_error_t err)
{
    const char * p = s;
    slong n = 1, i;
    int status = WC_OK;

    *v = NULL;
    *count = 0;
    for (i = 0; s[i] != '\0'; i++)
        if ((n += s[i] == ',') > max)
            return wc_error_set(err, WC_EINPUT, what, 1, i + 2,
                                "at most %ld values%s%s%s", (long) max,
                                why != NULL ? " (" : "",
                                why != NULL ? why : "",
                                why != NULL ? ")" : "");
    *v = flint_malloc(sizeof(fmpq) * n);
    for (i = 0; i < n; i++)
        fmpq_init(*v + i);
    *count = n;
    for (i = 0; i < n && status == WC_OK; i++)
    {
        const char * e = strchr(p, ',');
        size_t len = e != NULL ? (size_t) (e - p) : strlen(p);

        if (wc_parse_number_bounded(*v + i, p, len, err) != WC_OK)
        {
            char * m = wc_error_format(err);

            status = wc_error_set(err, WC_EINPUT, what, 1, p - s + 1, "%s",
                                  m != NULL ? m : "bad number");
            free(m);
        }
        else if (noun != NULL && fmpq_sgn(*v + i) < 0)
            status = wc_error_set(err, WC_EINPUT, what, 1, p - s + 1,
                                  "%s must not be negative", noun);
        p += len + 1;
    }
    return status;
}

void
wc_number_list_clear(fmpq * v, slong n)
{
    slong i;

    for (i = 0; i < n; i++)
        fmpq_clear(v + i);
    flint_free(v);
}
