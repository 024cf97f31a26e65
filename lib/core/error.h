/* error.h -- status codes and located error records of libwrenchcone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_ERROR_H
#define WC_ERROR_H

#include <stdarg.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Every library function that can fail returns one of these.  They equal
   the exit statuses of the wrenchcone program (wrenchcone(1)).  An empty cone or
   an infeasible mode is an answer, never an error.  */
typedef enum
{
    WC_OK = 0,
    WC_EINPUT = 1,      /* bad input: problem file, mode, number */
    WC_EUSAGE = 2,      /* bad usage (used by the program only) */
    WC_EINTERNAL = 3,   /* internal, library (cddlib) or I/O failure */
    WC_EDISAGREE = 4    /* a check found a disagreement */
}
wc_status;

/* A located error.  file and message are owned by the record (malloc'd);
   line and col are 1-based, 0 when unknown.  */
typedef struct
{
    char * file;
    long line;
    long col;
    char * message;
}
wc_error_struct;

typedef wc_error_struct wc_error_t[1];

void wc_error_init(wc_error_t e);
void wc_error_clear(wc_error_t e);

/* Replace the record's contents; file may be NULL.  Returns status, so a
   caller can write  return wc_error_set(e, WC_EINPUT, ...);
   The file and the message are kept quoted for display, whatever the
   caller passes: each byte that is not part of valid UTF-8 and each
   control character written as \xNN (C1 controls, line separators and
   invisible format characters as \uXXXX, _wc_quote), the file cut after WC_SHOW_PATH_MAX bytes and the message
   after WC_MESSAGE_MAX (core/limits.h), with "..." where cut and never
   inside a character.  So a record, formatted or written as JSON, is
   one line of valid UTF-8.  */
int wc_error_set(wc_error_t e, int status, const char * file, long line,
                 long col, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 6, 7)))
#endif
    ;
int wc_error_vset(wc_error_t e, int status, const char * file, long line,
                  long col, const char * fmt, va_list ap);

/* "FILE:LINE:COL: message", "FILE: message" or "message"; malloc'd,
   caller frees.  NULL only when out of memory.  */
char * wc_error_format(const wc_error_t e);

#ifdef __cplusplus
}
#endif

#endif
