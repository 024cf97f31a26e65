/* textbuf.c -- the checker's growing text: the reason a certificate fails,
   the summary of what it claims.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check/checker.h"

/* Numbers quoted in a reason are cut after this many characters: a
   tampered certificate may hold numbers of any size.  */
#define SHOW_DIGITS 40

/* Room for n more bytes and a NUL; 0 (and b->oom) when there is none.  */
static int
reserve(wc_check_text * b, size_t n)
{
    size_t cap;
    char * t;

    if (b->oom)
        return 0;
    if (b->cap - b->len > n)
        return 1;
    cap = b->cap < 64 ? 64 : b->cap;
    while (cap - b->len <= n)
    {
        if (cap > SIZE_MAX / 2)
        {
            b->oom = 1;
            return 0;
        }
        cap *= 2;
    }
    t = realloc(b->s, cap);
    if (t == NULL)
    {
        b->oom = 1;
        return 0;
    }
    b->s = t;
    b->cap = cap;
    return 1;
}

void
_wc_check_put_n(wc_check_text * b, const char * s, size_t n)
{
    if (!reserve(b, n))
        return;
    memcpy(b->s + b->len, s, n);
    b->len += n;
    b->s[b->len] = '\0';
}

void
_wc_check_put(wc_check_text * b, const char * s)
{
    _wc_check_put_n(b, s, strlen(s));
}

/* Formatted straight into the buffer: measured first, then written.  */
void
_wc_check_putf(wc_check_text * b, const char * fmt, ...)
{
    va_list ap;
    int n;

    va_start(ap, fmt);
    n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0)
    {
        b->oom = 1;
        return;
    }
    if (!reserve(b, (size_t) n))
        return;
    va_start(ap, fmt);
    vsnprintf(b->s + b->len, (size_t) n + 1, fmt, ap);
    va_end(ap);
    b->len += (size_t) n;
}

void
_wc_check_put_z(wc_check_text * b, const mpz_t z)
{
    size_t n = mpz_sizeinbase(z, 10) + 2;
    char * t = malloc(n);

    if (t == NULL)
    {
        b->oom = 1;
        return;
    }
    mpz_get_str(t, 10, z);
    n = strlen(t);
    if (n > SHOW_DIGITS)
    {
        _wc_check_put_n(b, t, SHOW_DIGITS);
        _wc_check_put(b, "...");
    }
    else
        _wc_check_put_n(b, t, n);
    free(t);
}

void
_wc_check_put_q(wc_check_text * b, const mpq_t q)
{
    _wc_check_put_z(b, mpq_numref(q));
    if (mpz_cmp_ui(mpq_denref(q), 1) != 0)
    {
        _wc_check_put(b, "/");
        _wc_check_put_z(b, mpq_denref(q));
    }
}

/* "(a, b, c)" of integers (z) or rationals (q): one loop for both.  */
static void
put_vec(wc_check_text * b, mpz_t * z, mpq_t * q, size_t n)
{
    size_t i;

    _wc_check_put(b, "(");
    for (i = 0; i < n; i++)
    {
        if (i > 0)
            _wc_check_put(b, ", ");
        if (z != NULL)
            _wc_check_put_z(b, z[i]);
        else
            _wc_check_put_q(b, q[i]);
    }
    _wc_check_put(b, ")");
}

void
_wc_check_put_zvec(wc_check_text * b, mpz_t * v, size_t n)
{
    put_vec(b, v, NULL, n);
}

void
_wc_check_put_qvec(wc_check_text * b, mpq_t * v, size_t n)
{
    put_vec(b, NULL, v, n);
}

void
_wc_check_unmark(wc_check_text * b, size_t at, int holds)
{
    if (holds == 0 || b->s == NULL)
        return;
    b->len = at;
    b->s[at] = '\0';
}
