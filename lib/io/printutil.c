/* printutil.c -- the small writers every printer shares.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

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

void
_wc_fprint_jq(FILE * out, const fmpq_t x)
{
    putc('"', out);
    wc_fprint_fmpq(out, x);
    putc('"', out);
}

void
wc_fprint_qvec(FILE * out, const fmpq * v, slong len, int json)
{
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
