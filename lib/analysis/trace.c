/* trace.c -- the named matrices a route records for --trace.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/wrench.h"

void
wc_trace_init(wc_trace_t T)
{
    T->len = 0;
    T->alloc = 0;
    T->entries = NULL;
}

void
wc_trace_clear(wc_trace_t T)
{
    slong i;

    for (i = 0; i < T->len; i++)
    {
        free(T->entries[i].name);
        free(T->entries[i].note);
        fmpq_mat_clear(T->entries[i].m);
    }
    free(T->entries);
    wc_trace_init(T);
}

static char *
dup_string(const char * s)
{
    char * t = malloc(strlen(s) + 1);

    if (t != NULL)
        strcpy(t, s);
    return t;
}

void
wc_trace_add(wc_trace_t T, const char * name, const fmpq_mat_t m,
             const char * note_fmt, ...)
{
    wc_trace_entry_struct * e;

    if (T == NULL)
        return;
    if (T->len == T->alloc)
    {
        slong a = T->alloc == 0 ? 16 : 2 * T->alloc;
        wc_trace_entry_struct * p = realloc(T->entries, sizeof(*p) * a);

        if (p == NULL)
            return;             /* a trace is best effort */
        T->entries = p;
        T->alloc = a;
    }
    e = T->entries + T->len++;
    e->name = dup_string(name);
    e->note = NULL;
    if (note_fmt != NULL)
    {
        va_list ap, aq;
        int len;

        va_start(ap, note_fmt);
        va_copy(aq, ap);
        len = vsnprintf(NULL, 0, note_fmt, aq);
        va_end(aq);
        if (len >= 0 && (e->note = malloc((size_t) len + 1)) != NULL)
            vsnprintf(e->note, (size_t) len + 1, note_fmt, ap);
        va_end(ap);
    }
    fmpq_mat_init(e->m, fmpq_mat_nrows(m), fmpq_mat_ncols(m));
    fmpq_mat_set(e->m, m);
}
