/* request.c -- a JSON request read into a command's arguments, run, and
   answered as the command's JSON or an error record (request.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/request.h"
#include "api/args.h"
#include "api/run.h"
#include "api/schema.h"
#include "api/runners.h"
#include "core/json.h"
#include "core/text.h"
#include "core/thread.h"

/* Where the request's errors are located.  */
typedef struct
{
    const char * file;
    long line;          /* the request's first line */
    wc_error_struct * err;
    const _wc_file_id * avoid;  /* a batch's own input, or NULL */
}
where;

/* The line of the file where the request's line l (>= 1) is: the
   request's first line is w->line; LONG_MAX beyond.  */
static long
file_line(const where * w, long l)
{
    if (l < 1)
        return w->line;
    return w->line > LONG_MAX - (l - 1) ? LONG_MAX : w->line + (l - 1);
}

/* A usage error at node v (NULL: the request's start).  */
static int
bad(const where * w, const wc_json_node * v, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int
bad(const where * w, const wc_json_node * v, const char * fmt, ...)
{
    va_list ap;
    int status;

    va_start(ap, fmt);
    status = wc_error_vset(w->err, WC_EUSAGE, w->file,
                           file_line(w, v != NULL ? v->line : 1),
                           v != NULL ? v->col : 1, fmt, ap);
    va_end(ap);
    return status;
}

/* The string value of key in o: *s, or NULL when o has no key.  */
static int
get_string(const char ** s, size_t * len, const wc_json_node * o,
           const char * key, const where * w)
{
    const wc_json_node * v = _wc_json_object_get(o, key);

    *s = NULL;
    if (v == NULL)
        return WC_OK;
    if (v->type != WC_JSON_STRING)
        return bad(w, v, "\"%s\" takes a string", key);
    if (len == NULL && strlen(v->text) != v->len)
        return bad(w, v, "\"%s\" holds a NUL character", key);
    *s = v->text;
    if (len != NULL)
        *len = v->len;
    return WC_OK;
}

static int
get_bool(int * b, const wc_json_node * o, const char * key, const where * w)
{
    const wc_json_node * v = _wc_json_object_get(o, key);

    if (v == NULL)
        return WC_OK;
    if (v->type != WC_JSON_TRUE && v->type != WC_JSON_FALSE)
        return bad(w, v, "\"%s\" takes true or false", key);
    *b = v->type == WC_JSON_TRUE;
    return WC_OK;
}

/* A number: a string as written, or a JSON number's literal.  */
static int
number_text(const char ** s, const wc_json_node * v, const char * key,
            const where * w)
{
    if (v->type == WC_JSON_NUMBER
        || (v->type == WC_JSON_STRING && strlen(v->text) == v->len))
    {
        *s = v->text;
        return WC_OK;
    }
    return bad(w, v, "\"%s\" takes numbers, as strings (\"-1/5\") or "
               "JSON numbers", key);
}

/* A wrench [FX, FY, TAU] into *t (t->given when present).  */
static int
get_wrench(_wc_triple * t, const wc_json_node * o, const char * key,
           const where * w)
{
    const wc_json_node * v = _wc_json_object_get(o, key);
    size_t i;
    int status = WC_OK;

    if (v == NULL)
        return WC_OK;
    if (v->type != WC_JSON_ARRAY || v->len != 3)
        return bad(w, v, "\"%s\" takes three numbers [FX, FY, TAU]", key);
    for (i = 0; i < 3 && status == WC_OK; i++)
        status = number_text(t->v + i, _wc_json_array_get(v, i), key, w);
    t->given = 1;
    return status;
}

/* One input: key (a path) or key_text (its text), exactly one of them
   unless optional.  */
static int
get_input(_wc_input * in, const wc_json_node * o, const char * key,
          const char * key_text, const char * text_name, const where * w)
{
    const wc_json_node * p = _wc_json_object_get(o, key);
    const wc_json_node * t = _wc_json_object_get(o, key_text);
    int status;

    if (p != NULL && t != NULL)
        return bad(w, t, "give \"%s\" or \"%s\", not both", key, key_text);
    if (p == NULL && t == NULL)
        return bad(w, NULL, "the request needs \"%s\" (a file) or "
                   "\"%s\"", key, key_text);
    if (p != NULL)
    {
        if ((status = get_string(&in->path, NULL, o, key, w)) != WC_OK)
            return status;
        if (strcmp(in->path, "-") == 0)
            return bad(w, p, "a request reads no standard input: give "
                       "\"%s\"", key_text);
        in->name = in->path;
        in->flags = _WC_READ_REGULAR;
        in->avoid = w->avoid;
        return WC_OK;
    }
    in->name = text_name;
    return get_string(&in->text, &in->len, o, key_text, w);
}

#define FIELD(R, a, T) ((T *) (void *) ((char *) (R) + (a)->offset))

/* Whether key names row a of a request: KEY, or KEY_text for an input.  */
static int
names_row(const char * key, const _wc_arg * a)
{
    char k[64];
    size_t n;

    if (a->flags & _WC_ARG_CLI)
        return 0;
    _wc_arg_key(k, sizeof k, a);
    n = strlen(k);
    return strcmp(key, k) == 0 || (a->kind == _WC_ARG_INPUT
                                   && strncmp(key, k, n) == 0
                                   && strcmp(key + n, "_text") == 0);
}

/* Every key of o is one of S's.  */
static int
check_keys(const wc_json_node * o, const _wc_command_schema * S,
           const where * w)
{
    size_t i;

    for (i = 0; i < o->len; i++)
    {
        const wc_json_node * key = _wc_json_object_key(o, i);
        const _wc_arg * a = NULL;
        int found = strcmp(key->text, "command") == 0
            || (strcmp(key->text, "certificate") == 0
                && _wc_runners[S - _wc_schema] != NULL
                && _wc_runners[S - _wc_schema]->certificate != NULL);

        for (a = S->operands; !found && a->name != NULL; a++)
            found = names_row(key->text, a);
        for (a = S->options; !found && a->name != NULL; a++)
            found = names_row(key->text, a);
        if (!found)
        {
            char shown[WC_QUOTE_SIZE(WC_SHOW_MAX)];

            _wc_quote(shown, key->text, key->len, WC_SHOW_MAX);
            return bad(w, key, "\"%s\" is not a key of a %s request", shown,
                       S->name);
        }
    }
    return WC_OK;
}

/* Row a of the request o into R; operand: a required key unless the row
   says it is optional.  */
static int
read_arg(_wc_request * R, const _wc_arg * a, int operand,
         const wc_json_node * o, const where * w)
{
    const wc_json_node * v;
    const char * s = NULL, * why;
    char key[64], text_key[80], text_name[96], msg[_WC_ARG_MSG_SIZE];
    int status = WC_OK;

    _wc_arg_key(key, sizeof key, a);
    if (a->kind == _WC_ARG_INPUT)
    {
        snprintf(text_key, sizeof text_key, "%s_text", key);
        snprintf(text_name, sizeof text_name, "<%s_text>", key);
        if ((s = _wc_request_own(R, text_name)) == NULL)
            return wc_error_set(w->err, WC_EINTERNAL, NULL, 0, 0,
                                "out of memory");
        return get_input(FIELD(R, a, _wc_input), o, key, text_key, s, w);
    }
    if ((v = _wc_json_object_get(o, key)) == NULL)
        return operand && !(a->flags & _WC_ARG_OPTIONAL)
            ? bad(w, NULL, "a %s request needs \"%s\"",
                  _wc_command_name(R->command), key)
            : WC_OK;
    switch (a->kind)
    {
    case _WC_ARG_FLAG:
        return get_bool(FIELD(R, a, int), o, key, w);
    case _WC_ARG_WRENCH:
        return get_wrench(FIELD(R, a, _wc_triple), o, key, w);
    case _WC_ARG_COUNT:
    case _WC_ARG_SEED:
        if (v->type != WC_JSON_NUMBER && v->type != WC_JSON_STRING)
            return bad(w, v, "\"%s\" %s", key, a->what);
        s = v->text;
        break;
    case _WC_ARG_NUMBER:
    case _WC_ARG_LIST:
    case _WC_ARG_ANGLE:
        status = number_text(&s, v, key, w);
        break;
    default:
        status = get_string(&s, NULL, o, key, w);
        break;
    }
    if (status != WC_OK)
        return status;
    if ((why = _wc_arg_set_text(R, a, s, msg, sizeof msg)) != NULL)
        return bad(w, v, "%s", why);
    return WC_OK;
}

/* The request in J into R.  */
static int
read_request(_wc_request * R, const wc_json_node * o, const where * w)
{
    const _wc_command_schema * S;
    const _wc_arg * a, * culprit = NULL;
    const wc_json_node * v;
    char msg[_WC_ARG_MSG_SIZE], list[256] = "", key[64];
    char shown[WC_QUOTE_SIZE(WC_SHOW_MAX)];
    const char * why;
    int status = WC_OK;

    if (o->type != WC_JSON_OBJECT)
        return bad(w, o, "a request is a JSON object, not %s",
                   _wc_json_type_name(o->type));
    v = _wc_json_object_get(o, "command");
    if (v == NULL)
        return bad(w, o, "the request needs \"command\"");
    if (v->type != WC_JSON_STRING)
        return bad(w, v, "\"command\" takes a string");
    S = _wc_schema_find(v->text);
    if (S == NULL || !(S->flags & _WC_CMD_REQUEST))
    {
        const _wc_command_schema * c;
        int n = 0, k = 0;

        for (c = _wc_schema; c->name != NULL; c++)
            n += (c->flags & _WC_CMD_REQUEST) != 0;
        for (c = _wc_schema; c->name != NULL; c++)
            if (c->flags & _WC_CMD_REQUEST)
                snprintf(list + strlen(list), sizeof list - strlen(list),
                         "%s%s", k++ == 0 ? "" : k == n ? " or " : ", ",
                         c->name);
        _wc_quote(shown, v->text, v->len, WC_SHOW_MAX);
        return bad(w, v, "unknown command '%s' (%s)", shown, list);
    }
    _wc_request_init(R, (_wc_command) (S - _wc_schema));
    R->from_request = 1;
    if ((status = check_keys(o, S, w)) != WC_OK)
        return status;
    for (a = S->operands; status == WC_OK && a->name != NULL; a++)
        status = read_arg(R, a, 1, o, w);
    for (a = S->options; status == WC_OK && a->name != NULL; a++)
        if (!(a->flags & _WC_ARG_CLI))
            status = read_arg(R, a, 0, o, w);
    /* "certificate": true, the answer carries the certificate document
       (what --certificate=FILE writes).  */
    if (status == WC_OK)
        status = get_bool(&R->want_certificate, o, "certificate", w);
    R->certificates = R->want_certificate;
    if (status != WC_OK || S->check == NULL
        || (why = S->check(msg, sizeof msg, &culprit, R)) == NULL)
        return status;
    v = culprit != NULL
        ? _wc_json_object_get(o, _wc_arg_key(key, sizeof key, culprit))
        : NULL;
    return bad(w, v, "%s", why);
}

/* The answer's JSON with the certificate document as its last member
   "certificate".  */
static int
fprint_with_certificate(FILE * out, const _wc_answer * A, wc_error_t err)
{
    char * buf = NULL, * cert = NULL;
    size_t size = 0, csize = 0;
    FILE * f = open_memstream(&buf, &size), * g = open_memstream(&cert,
                                                                 &csize);
    int status = f != NULL && g != NULL ? WC_OK : WC_EINTERNAL;

    if (status == WC_OK)
        status = _wc_answer_fprint_json(f, A);
    if (status == WC_OK)
        status = _wc_answer_fprint_certificate(g, A, err);
    if (f != NULL && fclose(f) != 0)
        status = WC_EINTERNAL;
    if (g != NULL && fclose(g) != 0)
        status = WC_EINTERNAL;
    /* Both are one JSON object and a newline; the certificate's lines
       are joined (a JSON string holds no raw newline, so every newline
       and the indentation after it lie between tokens).  */
    if (status == WC_OK && size >= 2 && csize >= 1)
    {
        size_t i;

        fwrite(buf, 1, size - 2, out);
        fputs(", \"certificate\": ", out);
        for (i = 0; i < csize; i++)
            if (cert[i] == '\n')
                while (i + 1 < csize && cert[i + 1] == ' ')
                    i++;
            else
                putc(cert[i], out);
        fputs("}\n", out);
    }
    free(buf);
    free(cert);
    return status;
}

/* The answer or the error record into a malloc'd *out.  */
static int
write_out(char ** out, size_t * outlen, const _wc_answer * A, int status,
          wc_error_t err)
{
    char * buf = NULL;
    size_t size = 0;
    FILE * f = open_memstream(&buf, &size);
    int wst;

    if (f == NULL)
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    wst = A == NULL ? _wc_error_fprint_json(f, err, status)
        : A->R->want_certificate ? fprint_with_certificate(f, A, err)
        : _wc_answer_fprint_json(f, A);
    if (fclose(f) != 0 || wst != WC_OK)
    {
        free(buf);
        if (err->message == NULL)
            wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
        return WC_EINTERNAL;
    }
    *out = buf;
    *outlen = size;
    return status;
}

int
wc_request_json_at(char ** out, size_t * outlen, const char * request,
                   size_t len, const char * file, long line, wc_error_t err)
{
    return _wc_request_json_avoid(out, outlen, request, len, file, line,
                                  NULL, err);
}

int
_wc_request_json_avoid(char ** out, size_t * outlen, const char * request,
                       size_t len, const char * file, long line,
                       const _wc_file_id * avoid, wc_error_t err)
{
    wc_json_t J;
    _wc_request R;
    _wc_answer A;
    where w;
    int status, have_answer = 0, answered = 0;

    *out = NULL;
    *outlen = 0;
    /* FLINT's caches of this thread are freed when it exits.  */
    _wc_thread_enter();
    w.file = file != NULL ? file : "<request>";
    w.line = line >= 1 ? line : 1;
    w.err = err;
    w.avoid = avoid;
    memset(&R, 0, sizeof R);
    _wc_json_init(J);
    status = _wc_json_parse(J, request, len, w.file, err);
    if (status == WC_EINPUT)
    {
        /* Not JSON: the request's fault, as a bad command line is.  */
        err->line = file_line(&w, err->line);
        status = WC_EUSAGE;
    }
    if (status == WC_OK)
        status = read_request(&R, &J->root, &w);
    if (status == WC_OK)
    {
        _wc_answer_init(&A, &R);
        answered = 1;
        status = _wc_run(&A, err);
    }
    if (status == WC_OK)
    {
        have_answer = 1;
        status = _wc_answer_status(&A);
        if (write_out(out, outlen, &A, status, err) == WC_EINTERNAL)
        {
            have_answer = 0;
            status = WC_EINTERNAL;
        }
    }
    if (!have_answer)
        write_out(out, outlen, NULL, status, err);
    if (answered)
        _wc_answer_clear(&A);
    _wc_request_clear(&R);
    _wc_json_clear(J);
    return status;
}

int
wc_request_json(char ** out, size_t * outlen, const char * request,
                size_t len, wc_error_t err)
{
    return wc_request_json_at(out, outlen, request, len, NULL, 1, err);
}

void
wc_request_free(char * out)
{
    free(out);
}

int
wc_request_schema(char ** out, size_t * outlen)
{
    FILE * f = open_memstream(out, outlen);
    int status;

    if (f == NULL)
    {
        *out = NULL;
        return WC_EINTERNAL;
    }
    status = _wc_schema_fprint_json(f);
    if (fclose(f) != 0 || status != WC_OK)
    {
        free(*out);
        *out = NULL;
        return WC_EINTERNAL;
    }
    return WC_OK;
}
