/* lexer.h -- the tokens of a problem file's line.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  A token is a run of bytes other than space,
   tab and '#', or a quoted string; '#' starts a comment.  Errors go to
   the lexer's record, located at the current line.  */

#ifndef WC_LEXER_H
#define WC_LEXER_H

#include <stddef.h>
#include <flint/flint.h>
#include <flint/fmpq.h>

#include "core/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The caller sets text, len, file and err once, and line, lstart, lend,
   pos = prev_end = lstart for each line.  */
typedef struct
{
    const char * text;
    size_t len;
    const char * file;
    wc_error_struct * err;
    long line;
    size_t lstart;      /* offset of the current line */
    size_t lend;        /* end of its content (before any \r\n) */
    size_t pos;         /* cursor */
    size_t prev_end;    /* just after the last token read */
}
wc_lexer;

typedef struct
{
    size_t start;
    size_t end;
    long col;
    int quoted;
}
wc_token;

/* The 1-based column of offset off of the current line.  */
long _wc_lx_col(const wc_lexer * lx, size_t off);

/* Set the error at column col of the current line; returns WC_EINPUT.  */
int _wc_lx_error(wc_lexer * lx, long col, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* An error about a token; fmt has one %s, the token.  */
int _wc_lx_error_token(wc_lexer * lx, const wc_token * t, const char * fmt);

/* A missing argument is located just after the previous token.  */
int _wc_lx_missing(wc_lexer * lx, const char * what);

/* Read the next token of the line: 1 and *t set, 0 at the end of the line
   or at a comment, -1 with err set on an unterminated string.  */
int _wc_lx_next(wc_lexer * lx, wc_token * t);

/* Like _wc_lx_next but leaves the cursor where it was.  */
int _wc_lx_peek(wc_lexer * lx, wc_token * t);

/* Is the token exactly word?  */
int _wc_tok_is(const wc_lexer * lx, const wc_token * t, const char * word);

/* Could the token be meant as a number?  Decides whether a fixel's
   "friction MUS" is followed by MUK or by the next option.  */
int _wc_tok_numeric(const wc_lexer * lx, const wc_token * t);

/* x := the token as a number (wc_parse_number_bounded), the error
   located at it.  */
int _wc_tok_number(wc_lexer * lx, const wc_token * t, fmpq_t x);

/* Read a number into x; missing is the message when there is none.  */
int _wc_lx_number(wc_lexer * lx, fmpq_t x, wc_token * t,
                  const char * missing);

/* WC_OK when the line has no token left, else an error at the first.  */
int _wc_lx_end(wc_lexer * lx);

#ifdef __cplusplus
}
#endif

#endif
