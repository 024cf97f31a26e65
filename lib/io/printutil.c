/* printutil.c -- the small writers every printer shares.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <string.h>

#include "core/text.h"
#include "io/print.h"
#include "io/printutil.h"

int
_wc_fprint_done(FILE * out)
{
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

const char *
_wc_tf(int b)
{
    return b ? "true" : "false";
}

const char *
_wc_yes(int b)
{
    return b ? "yes" : "no";
}

void
wc_fprint_fmpq(FILE * out, const fmpq_t x)
{
    char * s = fmpq_get_str(NULL, 10, x);

    fputs(s, out);
    flint_free(s);
}

const wc_print_opts _wc_print_as_json[1] = {
    { WC_FORMAT_JSON, 0, 0, NULL }
};

int
_wc_print_json(const wc_print_opts * o)
{
    return o != NULL && o->format == WC_FORMAT_JSON;
}

int
_wc_print_decimals(const wc_print_opts * o)
{
    if (o == NULL || !o->approx)
        return -1;
    return o->decimals < 0 ? 0 : o->decimals > WC_DECIMALS_MAX
        ? WC_DECIMALS_MAX : o->decimals;
}

const char *
_wc_print_indent(const wc_print_opts * o)
{
    return o != NULL && o->indent != NULL ? o->indent : "";
}

wc_print_opts
_wc_print_indented(const wc_print_opts * o, const char * indent)
{
    wc_print_opts t = { WC_FORMAT_TEXT, 0, 0, NULL };

    if (o != NULL)
        t = *o;
    t.format = WC_FORMAT_TEXT;
    t.indent = indent;
    return t;
}

void
wc_fprint_fmpq_decimal(FILE * out, const fmpq_t x, int K)
{
    fmpz_t n, d;
    char * s;
    size_t len;

    if (K < 0)
        K = 0;
    fmpz_init(n);
    fmpz_init(d);
    /* n = round(|x| 10^K) = floor((2 |p| 10^K + q) / (2 q)).  */
    fmpz_set_ui(n, 10);
    fmpz_pow_ui(n, n, (ulong) K);
    fmpz_mul(n, n, fmpq_numref(x));
    fmpz_abs(n, n);
    fmpz_mul_2exp(n, n, 1);
    fmpz_add(n, n, fmpq_denref(x));
    fmpz_mul_2exp(d, fmpq_denref(x), 1);
    fmpz_fdiv_q(n, n, d);
    s = fmpz_get_str(NULL, 10, n);
    len = strlen(s);
    if (fmpq_sgn(x) < 0 && !fmpz_is_zero(n))
        putc('-', out);
    if (len <= (size_t) K)      /* 0.00ddd */
        fprintf(out, "0%s%.*s%s", K ? "." : "", (int) (K - len),
                "00000000000000000000000000000000000000000000000000", s);
    else
        fprintf(out, "%.*s%s%s", (int) (len - K), s, K ? "." : "",
                s + len - K);
    flint_free(s);
    fmpz_clear(d);
    fmpz_clear(n);
}

void
wc_fprint_fmpq_text(FILE * out, const fmpq_t x, const wc_print_opts * o)
{
    int K = _wc_print_decimals(o);

    wc_fprint_fmpq(out, x);
    if (K >= 0 && !fmpz_is_one(fmpq_denref(x)))
    {
        fputs(" (approx. ", out);
        wc_fprint_fmpq_decimal(out, x, K);
        putc(')', out);
    }
}

void
_wc_fprint_jq(FILE * out, const fmpq_t x)
{
    putc('"', out);
    wc_fprint_fmpq(out, x);
    putc('"', out);
}

void
wc_fprint_qvec(FILE * out, const fmpq * v, slong len,
               const wc_print_opts * o)
{
    int json = _wc_print_json(o), K = json ? -1 : _wc_print_decimals(o);
    slong j;

    putc(json ? '[' : '(', out);
    for (j = 0; j < len; j++)
    {
        if (j)
            fputs(", ", out);
        if (json)
            _wc_fprint_jq(out, v + j);
        else
            wc_fprint_fmpq(out, v + j);
    }
    putc(json ? ']' : ')', out);
    for (j = 0; K >= 0 && j < len; j++)
        if (!fmpz_is_one(fmpq_denref(v + j)))
            break;
    if (K >= 0 && j < len)
    {
        fputs(" (approx. (", out);
        for (j = 0; j < len; j++)
        {
            if (j)
                fputs(", ", out);
            wc_fprint_fmpq_decimal(out, v + j, K);
        }
        fputs("))", out);
    }
}

void
_wc_fprint_zvec(FILE * out, const fmpz * v, slong len, int json)
{
    slong j;

    putc(json ? '[' : '(', out);
    for (j = 0; j < len; j++)
    {
        if (j)
            fputs(", ", out);
        if (json)
            putc('"', out);
        fmpz_fprint(out, v + j);
        if (json)
            putc('"', out);
    }
    putc(json ? ']' : ')', out);
}

void
wc_fprint_json_string(FILE * out, const char * s)
{
    _wc_fput_json_string(out, s);
}
