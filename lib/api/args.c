/* args.c -- a command's arguments read by the schema's rows: defaults,
   one value's check, and the request that a set of arguments is.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The command line (src/cli-options.c) and the request reader
   (request.c) both read every value through _wc_arg_set_text, so that a
   value means the same, and is refused with the same words, wherever it
   is written.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "api/args.h"
#include "core/text.h"
#include "core/version.h"
#include "io/print.h"

#define FIELD(R, a, T) ((T *) (void *) ((char *) (R) + (a)->offset))
#define CFIELD(R, a, T) \
    ((const T *) (const void *) ((const char *) (R) + (a)->offset))

#define SAY(...) (snprintf(msg, size, __VA_ARGS__), msg)

void
_wc_request_init(_wc_request * R, _wc_command c)
{
    const _wc_command_schema * S = _wc_schema + c;
    const _wc_arg * rows[2] = { S->operands, S->options }, * a;
    char msg[16];
    int i;

    memset(R, 0, sizeof *R);
    R->command = c;
    for (i = 0; i < 2; i++)
        for (a = rows[i]; a->name != NULL; a++)
            if (a->def != NULL)
                _wc_arg_set_text(R, a, a->def, msg, sizeof msg);
    R->format = -1;
    R->decimals = -1;
}

void
_wc_request_clear(_wc_request * R)
{
    size_t i;

    for (i = 0; i < sizeof R->owned / sizeof R->owned[0]; i++)
    {
        free(R->owned[i]);
        R->owned[i] = NULL;
    }
}

char *
_wc_request_keep(_wc_request * R, char * p)
{
    size_t i;

    for (i = 0; p != NULL && i < sizeof R->owned / sizeof R->owned[0]; i++)
        if (R->owned[i] == NULL)
            return R->owned[i] = p;
    free(p);
    return NULL;
}

char *
_wc_request_own(_wc_request * R, const char * s)
{
    char * p = malloc(strlen(s) + 1);

    if (p != NULL)
        strcpy(p, s);
    return _wc_request_keep(R, p);
}

/* The place of word in "a|b|c", or -1.  */
static int
choice(const char * values, const char * word)
{
    size_t len = strlen(word);
    const char * p = values;
    int k;

    for (k = 0; p != NULL; k++)
    {
        const char * e = strchr(p, '|');
        size_t n = e != NULL ? (size_t) (e - p) : strlen(p);

        if (n == len && strncmp(p, word, n) == 0)
            return k;
        p = e != NULL ? e + 1 : NULL;
    }
    return -1;
}

/* "a, b or c" from "a|b|c".  */
static void
choices(char * buf, size_t size, const char * values)
{
    size_t i, j = 0, last = strrchr(values, '|') != NULL
        ? (size_t) (strrchr(values, '|') - values) : (size_t) -1;

    for (i = 0; values[i] != '\0' && j + 4 < size; i++)
        if (values[i] != '|')
            buf[j++] = values[i];
        else if (i == last)
        {
            memcpy(buf + j, " or ", 4);
            j += 4;
        }
        else
        {
            memcpy(buf + j, ", ", 2);
            j += 2;
        }
    buf[j] = '\0';
}

/* A decimal integer, digits only, at most max.  */
static int
whole(unsigned long long * v, const char * s, unsigned long long max)
{
    unsigned long long x = 0;

    if (*s == '\0')
        return 0;
    for (; *s != '\0'; s++)
    {
        if (*s < '0' || *s > '9'
            || x > (max - (unsigned long long) (*s - '0')) / 10)
            return 0;
        x = 10 * x + (unsigned long long) (*s - '0');
    }
    *v = x;
    return 1;
}

/* The message for a bad value s of row a.  */
static const char *
say_bad(char * msg, size_t size, const _wc_arg * a, const char * s,
                int json)
{
    char key[64], list[160], shown[WC_QUOTE_SIZE(WC_SHOW_MAX)];

    _wc_quote(shown, s, strlen(s), WC_SHOW_MAX);
    s = shown;
    if (a->kind == _WC_ARG_CHOICE)
    {
        choices(list, sizeof list, a->values);
        return SAY("unknown %s '%s' (%s)", a->what, s, list);
    }
    if (a->kind == _WC_ARG_WRENCH)
        return json ? SAY("\"%s\" takes three numbers [FX, FY, TAU]",
                          _wc_arg_key(key, sizeof key, a))
            : SAY("--%s takes three numbers FX,FY,TAU, not '%s'", a->name, s);
    if (json)
        return SAY("\"%s\" %s, not '%s'", _wc_arg_key(key, sizeof key, a),
                   a->what, s);
    return SAY("--%s %s, not '%s'", a->name, a->what, s);
}

const char *
_wc_arg_set_text(_wc_request * R, const _wc_arg * a, const char * s,
                 char * msg, size_t size)
{
    unsigned long long v;
    double t;
    char * end, * p;
    int k;

    switch (a->kind)
    {
    case _WC_ARG_FLAG:
        *FIELD(R, a, int) = 1;
        return NULL;
    case _WC_ARG_CHOICE:
        if ((k = choice(a->values, s)) < 0)
            break;
        *FIELD(R, a, int) = k;
        return NULL;
    case _WC_ARG_COUNT:
        if (!whole(&v, s, (unsigned long long) a->hi)
            || v < (unsigned long long) a->lo)
            break;
        *FIELD(R, a, long) = (long) v;
        return NULL;
    case _WC_ARG_SEED:
        if (!whole(&v, s, ~0ULL))
            break;
        *FIELD(R, a, unsigned long long) = v;
        return NULL;
    case _WC_ARG_ANGLE:
        /* A report's tolerance only: every decision of the comparison
           is exact.  */
        t = strtod(s, &end);
        if (end == s || *end != '\0' || !(t >= 0 && t < 1.5707963))
            break;
        *FIELD(R, a, double) = t;
        return NULL;
    case _WC_ARG_WRENCH:
        /* FX,FY,TAU in a copy, cut at its commas.  */
        if ((p = _wc_request_own(R, s)) == NULL)
            return SAY("out of memory");
        FIELD(R, a, _wc_triple)->v[0] = p;
        for (k = 1; k < 3 && (p = strchr(p, ',')) != NULL; k++)
        {
            *p++ = '\0';
            FIELD(R, a, _wc_triple)->v[k] = p;
        }
        if (k < 3 || strchr(FIELD(R, a, _wc_triple)->v[2], ',') != NULL)
            break;
        FIELD(R, a, _wc_triple)->given = 1;
        return NULL;
    case _WC_ARG_INPUT:
        memset(FIELD(R, a, _wc_input), 0, sizeof(_wc_input));
        FIELD(R, a, _wc_input)->path = s;
        FIELD(R, a, _wc_input)->name = s;
        return NULL;
    default:
        *FIELD(R, a, const char *) = s;
        return NULL;
    }
    return say_bad(msg, size, a, s, R->from_request);
}

void
_wc_arg_set_wrench(_wc_request * R, const _wc_arg * a,
                   const char * const * v)
{
    _wc_triple * w = FIELD(R, a, _wc_triple);

    w->given = 1;
    memcpy(w->v, v, sizeof w->v);
}

/* ------------------------------------------------------------------ */
/* The request of a set of arguments                                   */

/* Whether row a holds the same in R and D.  */
static int
same(const _wc_request * R, const _wc_request * D, const _wc_arg * a)
{
    switch (a->kind)
    {
    case _WC_ARG_FLAG:
    case _WC_ARG_CHOICE:
        return *CFIELD(R, a, int) == *CFIELD(D, a, int);
    case _WC_ARG_COUNT:
        return *CFIELD(R, a, long) == *CFIELD(D, a, long);
    case _WC_ARG_SEED:
        return *CFIELD(R, a, unsigned long long)
            == *CFIELD(D, a, unsigned long long);
    case _WC_ARG_ANGLE:
        return *CFIELD(R, a, double) == *CFIELD(D, a, double);
    case _WC_ARG_WRENCH:
        return !CFIELD(R, a, _wc_triple)->given;
    case _WC_ARG_INPUT:
        return 0;
    default:
        return *CFIELD(R, a, const char *) == NULL
            || (*CFIELD(D, a, const char *) != NULL
                && strcmp(*CFIELD(R, a, const char *),
                          *CFIELD(D, a, const char *)) == 0);
    }
}

/* The word of place k in "a|b|c".  */
static void
fprint_choice(FILE * out, const char * values, int k)
{
    const char * p = values;
    size_t n;

    for (; k > 0 && strchr(p, '|') != NULL; k--)
        p = strchr(p, '|') + 1;
    n = strchr(p, '|') != NULL ? (size_t) (strchr(p, '|') - p) : strlen(p);
    fprintf(out, "\"%.*s\"", (int) n, p);
}

static void
fprint_value(FILE * out, const _wc_request * R, const _wc_arg * a)
{
    const _wc_input * in;
    int k;

    switch (a->kind)
    {
    case _WC_ARG_FLAG:
        fputs(*CFIELD(R, a, int) ? "true" : "false", out);
        break;
    case _WC_ARG_CHOICE:
        fprint_choice(out, a->values, *CFIELD(R, a, int));
        break;
    case _WC_ARG_COUNT:
        fprintf(out, "%ld", *CFIELD(R, a, long));
        break;
    case _WC_ARG_SEED:
        fprintf(out, "\"%llu\"", *CFIELD(R, a, unsigned long long));
        break;
    case _WC_ARG_ANGLE:
        fprintf(out, "%.17g", *CFIELD(R, a, double));
        break;
    case _WC_ARG_WRENCH:
        for (k = 0; k < 3; k++)
        {
            fputs(k == 0 ? "[" : ", ", out);
            wc_fprint_json_string(out, CFIELD(R, a, _wc_triple)->v[k]);
        }
        putc(']', out);
        break;
    case _WC_ARG_INPUT:
        in = CFIELD(R, a, _wc_input);
        wc_fprint_json_string(out, in->text != NULL ? in->text : in->path);
        break;
    default:
        wc_fprint_json_string(out, *CFIELD(R, a, const char *));
        break;
    }
}

int
_wc_request_fprint_json(FILE * out, const _wc_request * R)
{
    const _wc_command_schema * S = _wc_schema + R->command;
    const _wc_arg * rows[2] = { S->operands, S->options }, * a;
    _wc_request D;
    char key[64];
    int i;

    _wc_request_init(&D, R->command);
    fputs("{\"command\": ", out);
    wc_fprint_json_string(out, S->name);
    for (i = 0; i < 2; i++)
        for (a = rows[i]; a->name != NULL; a++)
        {
            if ((a->flags & _WC_ARG_CLI) || same(R, &D, a))
                continue;
            _wc_arg_key(key, sizeof key, a);
            if (a->kind == _WC_ARG_INPUT
                && CFIELD(R, a, _wc_input)->text != NULL)
                fprintf(out, ", \"%s_text\": ", key);
            else
                fprintf(out, ", \"%s\": ", key);
            fprint_value(out, R, a);
        }
    fputs("}\n", out);
    _wc_request_clear(&D);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}
