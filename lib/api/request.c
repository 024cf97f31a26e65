/* request.c -- a JSON request read into a command's arguments, run, and
   answered as the command's JSON or an error record (request.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/request.h"
#include "api/run.h"
#include "core/json.h"
#include "core/thread.h"

/* Which commands take a key.  */
#define ALL ((1u << _WC_NCOMMANDS) - 1)
#define CMD(c) (1u << (c))

static const struct
{
    const char * key;
    unsigned commands;
}
keys[] = {
    { "command", ALL },
    { "problem", ALL },
    { "problem_text", ALL },
    { "mode", CMD(_WC_CONE) | CMD(_WC_FEASIBLE) | CMD(_WC_COMPARE) },
    { "method", CMD(_WC_CONE) },
    { "trace", CMD(_WC_CONE) },
    { "arith", CMD(_WC_CONE) },
    { "witness", CMD(_WC_MODES) },
    { "wrench", CMD(_WC_CLASSIFY) | CMD(_WC_PLAN) },
    { "max_modes", CMD(_WC_CLASSIFY) },
    { "bias", CMD(_WC_STABILITY) },
    { "length", CMD(_WC_STABILITY) },
    { "complete", CMD(_WC_PLAN) },
    { "foreign", CMD(_WC_COMPARE) },
    { "foreign_text", CMD(_WC_COMPARE) },
    { "tol", CMD(_WC_COMPARE) },
    { NULL, 0 }
};

/* Where the request's errors are located.  */
typedef struct
{
    const char * file;
    long line;          /* the request's first line */
    wc_error_struct * err;
}
where;

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
                           w->line + (v != NULL ? v->line : 1) - 1,
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

/* A wrench [FX, FY, TAU] into s[0..3); *n := 3, or 0 when absent.  */
static int
get_wrench(const char ** s, int * n, const wc_json_node * o,
           const char * key, const where * w)
{
    const wc_json_node * v = _wc_json_object_get(o, key);
    size_t i;
    int status = WC_OK;

    *n = 0;
    if (v == NULL)
        return WC_OK;
    if (v->type != WC_JSON_ARRAY || v->len != 3)
        return bad(w, v, "\"%s\" takes three numbers [FX, FY, TAU]", key);
    for (i = 0; i < 3 && status == WC_OK; i++)
        status = number_text(s + i, _wc_json_array_get(v, i), key, w);
    *n = 3;
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
        return WC_OK;
    }
    in->name = text_name;
    return get_string(&in->text, &in->len, o, key_text, w);
}

/* Every key of o is one of command c's.  */
static int
check_keys(const wc_json_node * o, _wc_command c, const where * w)
{
    size_t i;
    int k;

    for (i = 0; i < o->len; i++)
    {
        const wc_json_node * key = _wc_json_object_key(o, i);

        for (k = 0; keys[k].key != NULL; k++)
            if (strcmp(key->text, keys[k].key) == 0)
                break;
        if (keys[k].key == NULL || !(keys[k].commands & CMD(c)))
        {
            wc_error_set(w->err, WC_EUSAGE, w->file, w->line + key->line - 1,
                         key->col, "\"%s\" is not a key of a %s request",
                         key->text, _wc_command_name(c));
            return WC_EUSAGE;
        }
    }
    return WC_OK;
}

/* cone's options: as cmd-cone.c reads --method, --arith, --trace.  */
static int
read_cone(_wc_request * R, const wc_json_node * o, const where * w)
{
    const char * method = NULL, * arith = NULL;
    int status = get_string(&method, NULL, o, "method", w);

    if (status == WC_OK)
        status = get_string(&arith, NULL, o, "arith", w);
    if (status == WC_OK)
        status = get_bool(&R->trace, o, "trace", w);
    if (status != WC_OK)
        return status;
    if (method != NULL && strcmp(method, "paper") == 0)
        R->method = WC_METHOD_PAPER;
    else if (method != NULL && strcmp(method, "direct") != 0)
        return bad(w, _wc_json_object_get(o, "method"),
                   "unknown method '%s' (direct or paper)", method);
    if (arith != NULL && strcmp(arith, "double") == 0)
        R->arith_double = 1;
    else if (arith != NULL && strcmp(arith, "exact") != 0)
        return bad(w, _wc_json_object_get(o, "arith"),
                   "unknown arithmetic '%s' (exact or double)", arith);
    if (R->arith_double && R->method != WC_METHOD_PAPER)
        return bad(w, _wc_json_object_get(o, "arith"),
                   "\"arith\": \"double\" needs \"method\": \"paper\"");
    if (R->arith_double && R->trace)
        return bad(w, _wc_json_object_get(o, "trace"),
                   "\"arith\": \"double\" does not take \"trace\"");
    return WC_OK;
}

static int
read_max_modes(_wc_request * R, const wc_json_node * o, const where * w)
{
    const wc_json_node * v = _wc_json_object_get(o, "max_modes");

    if (v == NULL)
        return WC_OK;
    if (v->type == WC_JSON_NUMBER && v->text[0] != '-'
        && strspn(v->text, "0123456789") == v->len && v->len <= 9)
    {
        R->max_modes = strtol(v->text, NULL, 10);
        return WC_OK;
    }
    return bad(w, v, "\"max_modes\" takes a count >= 0 (0: no limit)");
}

static int
read_tol(_wc_request * R, const wc_json_node * o, const where * w)
{
    const wc_json_node * v = _wc_json_object_get(o, "tol");
    const char * s = NULL;
    char * end;

    if (v == NULL)
        return WC_OK;
    if (number_text(&s, v, "tol", w) != WC_OK)
        return WC_EUSAGE;
    /* The command line's --tol: strtod, a report's tolerance only (every
       decision of the comparison is exact).  */
    R->tol = strtod(s, &end);
    if (end == s || *end != '\0' || !(R->tol >= 0 && R->tol < 1.5707963))
        return bad(w, v, "\"tol\" must be an angle in radians, at least 0 "
                   "and below pi/2 (such as 1e-9), not '%s'", s);
    return WC_OK;
}

/* The command's own keys.  */
static int
read_options(_wc_request * R, const wc_json_node * o, const where * w)
{
    const wc_json_node * v;
    int n, status = WC_OK;

    if (R->command == _WC_CONE || R->command == _WC_FEASIBLE
        || R->command == _WC_COMPARE)
    {
        status = get_string(&R->mode, NULL, o, "mode", w);
        if (status == WC_OK && R->mode == NULL)
            return bad(w, NULL, "a %s request needs \"mode\"",
                       _wc_command_name(R->command));
    }
    if (status != WC_OK)
        return status;
    switch (R->command)
    {
    case _WC_CONE:
        return read_cone(R, o, w);
    case _WC_MODES:
        return get_bool(&R->witness, o, "witness", w);
    case _WC_CLASSIFY:
        status = get_wrench(R->wrench, &R->nwrench, o, "wrench", w);
        if (status == WC_OK && R->nwrench == 0)
            return bad(w, NULL, "a classify request needs \"wrench\"");
        return status == WC_OK ? read_max_modes(R, o, w) : status;
    case _WC_STABILITY:
        status = get_wrench(R->bias, &n, o, "bias", w);
        R->biased = n == 3;
        if (status == WC_OK && (v = _wc_json_object_get(o, "length")) != NULL)
            status = number_text(&R->length, v, "length", w);
        return status;
    case _WC_PLAN:
        status = get_wrench(R->wrench, &R->nwrench, o, "wrench", w);
        return status == WC_OK ? get_bool(&R->complete, o, "complete", w)
            : status;
    case _WC_COMPARE:
        status = get_input(&R->foreign, o, "foreign", "foreign_text",
                           "<foreign_text>", w);
        return status == WC_OK ? read_tol(R, o, w) : status;
    default:
        return WC_OK;
    }
}

/* The request in J into R.  */
static int
read_request(_wc_request * R, const wc_json_node * o, const where * w)
{
    const wc_json_node * v;
    int c, status;

    if (o->type != WC_JSON_OBJECT)
        return bad(w, o, "a request is a JSON object, not %s",
                   _wc_json_type_name(o->type));
    v = _wc_json_object_get(o, "command");
    if (v == NULL)
        return bad(w, o, "the request needs \"command\"");
    if (v->type != WC_JSON_STRING)
        return bad(w, v, "\"command\" takes a string");
    if ((c = _wc_command_find(v->text)) < 0)
        return bad(w, v, "unknown command '%s' (cone, modes, feasible, "
                   "classify, stability, plan or compare)", v->text);
    _wc_request_init(R, (_wc_command) c);
    if ((status = check_keys(o, R->command, w)) != WC_OK)
        return status;
    status = get_input(&R->problem, o, "problem", "problem_text",
                       "<problem_text>", w);
    return status == WC_OK ? read_options(R, o, w) : status;
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
    wst = A != NULL ? _wc_answer_fprint_json(f, A)
        : _wc_error_fprint_json(f, err, status);
    if (fclose(f) != 0 || wst != WC_OK)
    {
        free(buf);
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    }
    *out = buf;
    *outlen = size;
    return status;
}

int
wc_request_json_at(char ** out, size_t * outlen, const char * request,
                   size_t len, const char * file, long line, wc_error_t err)
{
    wc_json_t J;
    _wc_request R;
    _wc_answer A;
    where w;
    int status, have_answer = 0;

    *out = NULL;
    *outlen = 0;
    /* FLINT's caches of this thread are freed when it exits.  */
    _wc_thread_enter();
    w.file = file != NULL ? file : "<request>";
    w.line = line >= 1 ? line : 1;
    w.err = err;
    _wc_json_init(J);
    _wc_answer_init(&A);
    status = _wc_json_parse(J, request, len, w.file, err);
    if (status == WC_EINPUT)
    {
        /* Not JSON: the request's fault, as a bad command line is.  */
        err->line += w.line - 1;
        status = WC_EUSAGE;
    }
    if (status == WC_OK)
        status = read_request(&R, &J->root, &w);
    if (status == WC_OK)
        status = _wc_run(&A, &R, err);
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
    _wc_answer_clear(&A);
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
