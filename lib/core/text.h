/* text.h -- strings for messages: copies, and input quoted printably.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  Plain C and libc only, like json.c, so that
   the certificate checker can use it.  */

#ifndef WC_TEXT_H
#define WC_TEXT_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"
#include "core/limits.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A malloc'd copy of s; NULL when out of memory.  */
char * _wc_strdup(const char * s);

/* Write s to out as a JSON string: only the escapes JSON requires, and
   \n and \t by name; other bytes as they are, so UTF-8 passes through.
   The one writer of strings for every JSON output, the solver's and the
   checker's.  */
void _wc_fput_json_string(FILE * out, const char * s);

/* A printable copy of s[0..len) for a message: control bytes (and DEL)
   as \xNN, cut after WC_SHOW_MAX bytes with "...".  With whole_chars the
   cut moves back to a UTF-8 character boundary (for text known to be
   UTF-8).  malloc'd, caller frees; NULL when out of memory.  */
char * _wc_show(const char * s, size_t len, int whole_chars);

/* Set err to the message fmt with its one "%s" replaced by arg (fmt is
   split here rather than passed on, so it is never a non-literal format).
   Returns status.  */
int _wc_error_with(wc_error_t err, int status, const char * file, long line,
                   long col, const char * fmt, const char * arg);

/* The same with the %s the token s[0..len), shown byte by byte
   (_wc_show).  Returns status, or WC_EINTERNAL when out of memory.  */
int _wc_error_token(wc_error_t err, int status, const char * file,
                    long line, long col, const char * fmt, const char * s,
                    size_t len);

#ifdef __cplusplus
}
#endif

#endif
