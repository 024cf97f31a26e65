/* text.c -- strings for messages: copies, and input quoted printably.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdlib.h>
#include <string.h>

#include "core/text.h"

char *
_wc_strdup(const char * s)
{
    size_t n = strlen(s) + 1;
    char * d = malloc(n);

    if (d != NULL)
        memcpy(d, s, n);
    return d;
}

char *
_wc_show(const char * s, size_t len, int whole_chars)
{
    static const char hex[] = "0123456789abcdef";
    size_t n = len, i, j = 0;
    char * d;

    if (n > WC_SHOW_MAX)
    {
        n = WC_SHOW_MAX;
        while (whole_chars && n > 0 && ((unsigned char) s[n] & 0xc0) == 0x80)
            n--;
    }
    d = malloc(4 * n + 4);
    if (d == NULL)
        return NULL;
    for (i = 0; i < n; i++)
    {
        unsigned char c = (unsigned char) s[i];

        if (c < 0x20 || c == 0x7f)
        {
            d[j++] = '\\';
            d[j++] = 'x';
            d[j++] = hex[c >> 4];
            d[j++] = hex[c & 15];
        }
        else
            d[j++] = (char) c;
    }
    if (n < len)
    {
        memcpy(d + j, "...", 3);
        j += 3;
    }
    d[j] = '\0';
    return d;
}

int
_wc_error_with(wc_error_t err, int status, const char * file, long line,
               long col, const char * fmt, const char * arg)
{
    const char * p = strstr(fmt, "%s");

    return wc_error_set(err, status, file, line, col, "%.*s%s%s",
                        (int) (p - fmt), fmt, arg, p + 2);
}

int
_wc_error_token(wc_error_t err, int status, const char * file, long line,
                long col, const char * fmt, const char * s, size_t len)
{
    char * t = _wc_show(s, len, 0);

    if (t == NULL)
        return wc_error_set(err, WC_EINTERNAL, file, 0, 0, "out of memory");
    _wc_error_with(err, status, file, line, col, fmt, t);
    free(t);
    return status;
}

/* Only the escapes JSON requires, and \n and \t by name: the output is
   ASCII-transparent, so UTF-8 passes through unchanged.  */
void
_wc_fput_json_string(FILE * out, const char * s)
{
    putc('"', out);
    for (; *s != '\0'; s++)
    {
        unsigned char c = (unsigned char) *s;

        if (c == '"' || c == '\\')
            fprintf(out, "\\%c", c);
        else if (c == '\n')
            fputs("\\n", out);
        else if (c == '\t')
            fputs("\\t", out);
        else if (c < 0x20)
            fprintf(out, "\\u%04x", c);
        else
            putc(c, out);
    }
    putc('"', out);
}
