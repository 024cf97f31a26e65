/* error.c -- located error records.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "core/text.h"

void
wc_error_init(wc_error_t e)
{
    e->file = NULL;
    e->line = 0;
    e->col = 0;
    e->message = NULL;
}

void
wc_error_clear(wc_error_t e)
{
    free(e->file);
    free(e->message);
    wc_error_init(e);
}

static char *
vformat(const char * fmt, va_list ap)
{
    va_list aq;
    int len;
    char * s;

    va_copy(aq, ap);
    len = vsnprintf(NULL, 0, fmt, aq);
    va_end(aq);
    if (len < 0)
        return NULL;
    s = malloc((size_t) len + 1);
    if (s != NULL)
        vsnprintf(s, (size_t) len + 1, fmt, ap);
    return s;
}

int
wc_error_vset(wc_error_t e, int status, const char * file, long line,
              long col, const char * fmt, va_list ap)
{
    char * f = NULL, * m;

    /* Format before freeing: the arguments may point into e itself.  */
    if (file != NULL)
        f = _wc_show_cut(file, strlen(file), WC_SHOW_PATH_MAX);
    m = vformat(fmt, ap);
    if (m != NULL)
    {
        char * q = _wc_show_cut(m, strlen(m), WC_MESSAGE_MAX);

        free(m);
        m = q;
    }
    wc_error_clear(e);
    e->file = f;
    e->line = line;
    e->col = col;
    e->message = m;
    return status;
}

int
wc_error_set(wc_error_t e, int status, const char * file, long line,
             long col, const char * fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    wc_error_vset(e, status, file, line, col, fmt, ap);
    va_end(ap);
    return status;
}

char *
wc_error_format(const wc_error_t e)
{
    const char * msg = e->message != NULL ? e->message : "unknown error";
    size_t len = strlen(msg) + (e->file != NULL ? strlen(e->file) : 0) + 64;
    char * s = malloc(len);

    if (s == NULL)
        return NULL;
    if (e->file != NULL && e->line > 0)
        snprintf(s, len, "%s:%ld:%ld: %s", e->file, e->line,
                 e->col > 0 ? e->col : 1, msg);
    else if (e->file != NULL)
        snprintf(s, len, "%s: %s", e->file, msg);
    else
        snprintf(s, len, "%s", msg);
    return s;
}
