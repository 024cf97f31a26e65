/* readall.h -- the whole of a stream as one buffer, with a size bound.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  Plain C and libc only, so that the
   certificate checker's program reads its input the same way as the
   request layer reads problems.  */

#ifndef WC_READALL_H
#define WC_READALL_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Read f to its end into a malloc'd buffer (*text, *len bytes, the caller
   frees it), at most max bytes; name locates the errors.  More than max
   bytes is WC_EINPUT ("file too large"), a directory WC_EINPUT, any other
   read failure or exhausted memory WC_EINTERNAL; *text is then NULL.  */
int _wc_read_all(char ** text, size_t * len, FILE * f, const char * name,
                 size_t max, wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
