/* lexer.c -- the tokens of a problem file's line.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Lazy: a token is read only when the parser asks for one, so the first
   error in file order is the one reported.  */

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/lexer.h"
#include "core/problem.h"
#include "core/text.h"

long
_wc_lx_col(const wc_lexer * lx, size_t off)
{
    return (long) (off - lx->lstart) + 1;
}

int
_wc_lx_error(wc_lexer * lx, long col, const char * fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    wc_error_vset(lx->err, WC_EINPUT, lx->file, lx->line, col, fmt, ap);
    va_end(ap);
    return WC_EINPUT;
}

int
_wc_lx_error_token(wc_lexer * lx, const wc_token * t, const char * fmt)
{
    return _wc_error_token(lx->err, WC_EINPUT, lx->file, lx->line, t->col,
                           fmt, lx->text + t->start, t->end - t->start);
}

int
_wc_lx_missing(wc_lexer * lx, const char * what)
{
    return _wc_lx_error(lx, _wc_lx_col(lx, lx->prev_end), "%s", what);
}

int
_wc_lx_next(wc_lexer * lx, wc_token * t)
{
    const char * s = lx->text;
    size_t i = lx->pos;

    while (i < lx->lend && (s[i] == ' ' || s[i] == '\t'))
        i++;
    lx->pos = i;
    if (i >= lx->lend || s[i] == '#')
        return 0;
    t->start = i;
    t->col = _wc_lx_col(lx, i);
    t->quoted = s[i] == '"';
    if (t->quoted)
    {
        for (i++; i < lx->lend && s[i] != '"'; i++)
            if (s[i] == '\\' && i + 1 < lx->lend)
                i++;
        if (i >= lx->lend)
        {
            _wc_lx_error(lx, t->col, "unterminated string");
            return -1;
        }
        i++;
    }
    else
        while (i < lx->lend && s[i] != ' ' && s[i] != '\t' && s[i] != '#')
            i++;
    t->end = i;
    lx->pos = i;
    lx->prev_end = i;
    return 1;
}

int
_wc_lx_peek(wc_lexer * lx, wc_token * t)
{
    size_t pos = lx->pos, prev = lx->prev_end;
    int r = _wc_lx_next(lx, t);

    lx->pos = pos;
    lx->prev_end = prev;
    return r;
}

int
_wc_tok_is(const wc_lexer * lx, const wc_token * t, const char * word)
{
    size_t n = strlen(word);

    return t->end - t->start == n && memcmp(lx->text + t->start, word, n) == 0;
}

int
_wc_tok_numeric(const wc_lexer * lx, const wc_token * t)
{
    char c = lx->text[t->start];

    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
}

int
_wc_tok_number(wc_lexer * lx, const wc_token * t, fmpq_t x)
{
    int status = wc_parse_number_bounded(x, lx->text + t->start,
                                         t->end - t->start, lx->err);

    if (status == WC_EINPUT)
    {
        /* wc_error_set frees the old message before formatting, so take
           it out first */
        char * m = lx->err->message;

        lx->err->message = NULL;
        _wc_lx_error(lx, t->col, "%s", m != NULL ? m : "bad number");
        free(m);
    }
    return status;
}

int
_wc_lx_number(wc_lexer * lx, fmpq_t x, wc_token * t, const char * missing)
{
    int r = _wc_lx_next(lx, t);

    if (r < 0)
        return WC_EINPUT;
    if (r == 0)
        return _wc_lx_missing(lx, missing);
    return _wc_tok_number(lx, t, x);
}

int
_wc_lx_end(wc_lexer * lx)
{
    wc_token t = { 0, 0, 0, 0 };
    int r = _wc_lx_next(lx, &t);

    if (r < 0)
        return WC_EINPUT;
    if (r > 0)
        return _wc_lx_error_token(lx, &t, "unexpected token '%s'");
    return WC_OK;
}

