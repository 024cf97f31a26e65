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

size_t
_wc_utf8_length(const unsigned char * s, size_t n)
{
    unsigned char c = s[0];
    unsigned char lo = 0x80, hi = 0xbf;
    size_t k, m;

    if (c < 0x80)
        return 1;
    if (c >= 0xc2 && c <= 0xdf)
        m = 2;
    else if (c >= 0xe0 && c <= 0xef)
    {
        m = 3;
        if (c == 0xe0)
            lo = 0xa0;
        else if (c == 0xed)
            hi = 0x9f;
    }
    else if (c >= 0xf0 && c <= 0xf4)
    {
        m = 4;
        if (c == 0xf0)
            lo = 0x90;
        else if (c == 0xf4)
            hi = 0x8f;
    }
    else
        return 0;
    if (n < m || s[1] < lo || s[1] > hi)
        return 0;
    for (k = 2; k < m; k++)
        if (s[k] < 0x80 || s[k] > 0xbf)
            return 0;
    return m;
}

static const char hex[] = "0123456789abcdef";

/* Characters a message shows by their code: the C1 controls, and those
   that break a line for some readers or are invisible and reorder or
   hide text (zero-width, bidirectional controls, the byte order mark).  */
static int
by_code(unsigned long c)
{
    return (c >= 0x80 && c <= 0x9f) || (c >= 0x200b && c <= 0x200f)
        || (c >= 0x2028 && c <= 0x202e) || (c >= 0x2060 && c <= 0x2064)
        || (c >= 0x2066 && c <= 0x2069) || c == 0xfeff;
}

size_t
_wc_quote(char * d, const char * s, size_t len, size_t max)
{
    const unsigned char * u = (const unsigned char *) s;
    size_t i = 0, j = 0;

    while (i < len)
    {
        size_t k = _wc_utf8_length(u + i, len - i);
        unsigned long c = 0;

        if (i + (k > 0 ? k : 1) > max)
            break;
        if (k == 2)
            c = ((unsigned long) (u[i] & 0x1f) << 6) | (u[i + 1] & 0x3f);
        else if (k == 3)
            c = ((unsigned long) (u[i] & 0x0f) << 12)
                | ((unsigned long) (u[i + 1] & 0x3f) << 6) | (u[i + 2] & 0x3f);
        if (k == 0 || (k == 1 && (u[i] < 0x20 || u[i] == 0x7f)))
        {
            d[j++] = '\\';
            d[j++] = 'x';
            d[j++] = hex[u[i] >> 4];
            d[j++] = hex[u[i] & 15];
            i++;
            continue;
        }
        if (by_code(c))
        {
            d[j++] = '\\';
            d[j++] = 'u';
            d[j++] = hex[c >> 12];
            d[j++] = hex[(c >> 8) & 15];
            d[j++] = hex[(c >> 4) & 15];
            d[j++] = hex[c & 15];
        }
        else
        {
            memcpy(d + j, s + i, k);
            j += k;
        }
        i += k;
    }
    if (i < len)
    {
        memcpy(d + j, "...", 3);
        j += 3;
    }
    d[j] = '\0';
    return j;
}

char *
_wc_show_cut(const char * s, size_t len, size_t max)
{
    char * d = malloc(WC_QUOTE_SIZE(len < max ? len : max)), * t;

    if (d != NULL)
    {
        len = _wc_quote(d, s, len, max);
        if ((t = realloc(d, len + 1)) != NULL)
            d = t;
    }
    return d;
}

char *
_wc_show(const char * s, size_t len)
{
    return _wc_show_cut(s, len, WC_SHOW_MAX);
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
    char * t = _wc_show(s, len);

    if (t == NULL)
        return wc_error_set(err, WC_EINTERNAL, file, 0, 0, "out of memory");
    _wc_error_with(err, status, file, line, col, fmt, t);
    free(t);
    return status;
}

void
_wc_fput_json_string(FILE * out, const char * s)
{
    const unsigned char * u = (const unsigned char *) s;
    size_t n = strlen(s), i = 0;

    putc('"', out);
    while (i < n)
    {
        unsigned char c = u[i];
        size_t k = c < 0x80 ? 1 : _wc_utf8_length(u + i, n - i);

        if (c == '"' || c == '\\')
            fprintf(out, "\\%c", c);
        else if (c == '\n')
            fputs("\\n", out);
        else if (c == '\t')
            fputs("\\t", out);
        else if (c < 0x20)
            fprintf(out, "\\u%04x", c);
        else if (k == 0)
            fprintf(out, "\\\\x%02x", c);   /* not UTF-8: by its code */
        else
            fwrite(s + i, 1, k, out);
        i += k > 0 ? k : 1;
    }
    putc('"', out);
}
