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

/* The length of the UTF-8 character that s[0..n) (n >= 1) begins
   with: 1 to 4, or 0 when its bytes are not one valid character
   (Unicode 3.9, Table 3-7: no overlong form, no surrogate, nothing
   above U+10FFFF).  */
size_t _wc_utf8_length(const unsigned char * s, size_t n);

/* Write s to out as a JSON string: the escapes JSON requires, \n and \t
   by name, every other control character as \uXXXX; valid UTF-8 as it
   is, and a byte that is not part of valid UTF-8 as the six characters
   \\xNN (a backslash, x and two hex digits), so that whatever s holds
   the output is valid UTF-8 JSON.  The one writer of strings for every
   JSON output, the solver's and the checker's.  */
void _wc_fput_json_string(FILE * out, const char * s);

/* Room _wc_quote needs for max input bytes, the NUL included.  */
#define WC_QUOTE_SIZE(max) (4 * (size_t) (max) + 4)

/* Input quoted for a message, into d (room for WC_QUOTE_SIZE(max)
   bytes): each valid UTF-8 character as it is, except that a control
   byte or DEL is written \xNN, and a C1 control, a line or paragraph
   separator (line breaks to some readers) or an invisible character that
   hides or reorders text (zero-width, bidirectional controls, U+FEFF)
   \uXXXX; each byte that is not part of a valid UTF-8 character \xNN.  Only characters within the first max bytes of
   s[0..len) are shown, then "..." when some are left out, so a character
   is never cut.  The result is valid UTF-8, one line of at most
   WC_QUOTE_SIZE(max) - 1 bytes, and quoting it again changes nothing
   (when it is not cut).  Returns its length; d is NUL-terminated.
   The one quoting of input for messages: every message that shows input
   (a token, a key, a path, a value) shows it through this.  */
size_t _wc_quote(char * d, const char * s, size_t len, size_t max);

/* s[0..len) quoted (_wc_quote) and cut after max bytes, in a malloc'd
   string (caller frees); NULL when out of memory.  _wc_show cuts after
   WC_SHOW_MAX bytes, as every token in a message is.  */
char * _wc_show_cut(const char * s, size_t len, size_t max);
char * _wc_show(const char * s, size_t len);

/* Set err to the message fmt with its one "%s" replaced by arg (fmt is
   split here rather than passed on, so it is never a non-literal format).
   Returns status.  */
int _wc_error_with(wc_error_t err, int status, const char * file, long line,
                   long col, const char * fmt, const char * arg);

/* The same with the %s the token s[0..len), shown (_wc_show).
   Returns status, or WC_EINTERNAL when out of memory.  */
int _wc_error_token(wc_error_t err, int status, const char * file,
                    long line, long col, const char * fmt, const char * s,
                    size_t len);

#ifdef __cplusplus
}
#endif

#endif
