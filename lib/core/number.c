/* number.c -- exact numbers as the problem file writes them.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz.h>

#include "core/problem.h"
#include "core/text.h"

/* The exponent of a decimal number is bounded so that "1e999999999"
   cannot make us build a gigantic power of ten.  */
#define WC_MAX_EXPONENT 100000

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

int
wc_parse_number(fmpq_t x, const char * s, size_t len, wc_error_t err)
{
    wc_numparts np;
    fmpz_t num, den;
    size_t nfrac;
    int status = WC_OK;
    int r = scan_number(&np, s, len);

    if (r != 0)
        return _wc_error_token(err, WC_EINPUT, NULL, 0, 0, r == 1
                               ? "bad number '%s'"
                               : "exponent out of range in '%s'", s,
                               len);
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

