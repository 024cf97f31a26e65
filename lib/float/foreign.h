/* foreign.h -- internal: what the two readers of a foreign cone (cdd in
   foreigncdd.c, JSON in foreign.c) share.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  */

#ifndef WC_FLOAT_FOREIGN_H
#define WC_FLOAT_FOREIGN_H

#include <stddef.h>

#include <flint/fmpq.h>

#include "core/error.h"
#include "core/limits.h"
#include "float/compare.h"

/* A growing list of rows of 3 rationals, with the file line of each.  */
typedef struct
{
    fmpq * v;
    long * line;
    slong n, alloc;
}
_wc_rowbuf;

void _wc_rowbuf_init(_wc_rowbuf * b);
void _wc_rowbuf_clear(_wc_rowbuf * b);
/* Push the row x, taking its numbers (x is left with others).  */
void _wc_rowbuf_push(_wc_rowbuf * b, fmpq * x, long line);

/* Append to F a representation built from the buffers (either may be
   NULL: no rows), taking their numbers (the buffers keep zeros).  F must
   hold fewer than 2: the readers check it.  */
void _wc_foreign_add_rep(wc_foreign_t F, wc_rep_kind kind, long line,
                         int empty, _wc_rowbuf * rows, _wc_rowbuf * lin);

/* The text being read, and where its errors go.  */
typedef struct
{
    const char * text;
    size_t len;
    const char * file;
    wc_error_struct * err;
}
_wc_source;

/* Set s->err to an input error at (line, col); returns WC_EINPUT.  */
int _wc_located(const _wc_source * s, long line, long col,
                const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* _wc_located with a message quoting t[0..n) (fmt has one %s); returns
   WC_EINPUT, or WC_EINTERNAL when out of memory.  */
int _wc_located_quoting(const _wc_source * s, long line, long col,
                        const char * fmt, const char * t, size_t n);

/* x := the exact number spelt t[0..n), located at (line, col) on error.  */
int _wc_foreign_number(fmpq_t x, const _wc_source * s, const char * t,
                       size_t n, long line, long col);

/* Read s as a cdd file into F (foreigncdd.c).  */
int _wc_foreign_parse_cdd(wc_foreign_t F, const _wc_source * s);

#endif
