/* readall.c -- the whole of a stream as one buffer, with a size bound.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "core/readall.h"

int
_wc_read_all(char ** text, size_t * len, FILE * f, const char * name,
             size_t max, wc_error_t err)
{
    size_t alloc = 4096, n = 0, r;
    char * buf = malloc(alloc);
    int status = WC_OK;

    *text = NULL;
    *len = 0;
    while (buf != NULL && (r = fread(buf + n, 1, alloc - n, f)) > 0)
    {
        n += r;
        if (n > max)
        {
            status = wc_error_set(err, WC_EINPUT, name, 0, 0,
                                  "file too large (over %lu bytes)",
                                  (unsigned long) max);
            break;
        }
        if (n == alloc)
        {
            char * p = realloc(buf, alloc *= 2);

            if (p == NULL)
                free(buf);
            buf = p;
        }
    }
    if (status != WC_OK)
        ;
    else if (buf == NULL)
        status = wc_error_set(err, WC_EINTERNAL, name, 0, 0, "out of memory");
    else if (ferror(f))
        /* A directory is a wrong argument; anything else is an I/O
           failure.  */
        status = wc_error_set(err, errno == EISDIR ? WC_EINPUT : WC_EINTERNAL,
                              name, 0, 0, "read error: %s", strerror(errno));
    if (status != WC_OK)
    {
        free(buf);
        return status;
    }
    *text = buf;
    *len = n;
    return WC_OK;
}
