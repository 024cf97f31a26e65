/* read.c -- reading the JSON of a certificate: members, rationals,
   vectors, the kind; the first error in file order.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The parts of a certificate that do not depend on each other are all
   read, and _wc_check_bad keeps the error located earliest: the message
   does not depend on the order in which the checker looks.  */

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/certkind.h"
#include "check/checker.h"

int
_wc_check_nomem(wc_check_reader * c)
{
    c->status = wc_error_set(c->err, WC_EINTERNAL, c->file, 0, 0,
                             "out of memory");
    return WC_EINTERNAL;
}

int
_wc_check_bad(wc_check_reader * c, const wc_json_node * at,
              const char * fmt, ...)
{
    va_list ap;

    if (c->status == WC_EINTERNAL)
        return WC_EINPUT;
    if (c->status == WC_EINPUT
        && (c->err->line < at->line
            || (c->err->line == at->line && c->err->col <= at->col)))
        return WC_EINPUT;
    va_start(ap, fmt);
    wc_error_vset(c->err, WC_EINPUT, c->file, at->line, at->col, fmt, ap);
    va_end(ap);
    c->status = WC_EINPUT;
    return WC_EINPUT;
}

int
_wc_check_bad_quoting(wc_check_reader * c, const wc_json_node * at,
                      const char * fmt, const char * s, size_t len)
{
    char * t = _wc_show(s, len);

    if (t == NULL)
        return _wc_check_nomem(c);
    _wc_check_bad(c, at, fmt, t);
    free(t);
    return WC_EINPUT;
}

int
_wc_check_member(wc_check_reader * c, const wc_json_node * o,
                 const char * key, wc_check_want w, const wc_json_node ** v)
{
    static const char * const name[] = {
        "a string", "true or false", "an array", "an object"
    };
    const wc_json_node * x = _wc_json_object_get(o, key);
    int ok;

    *v = NULL;
    if (x == NULL)
        return _wc_check_bad(c, o, "missing key '%s'", key);
    switch (w)
    {
    case WC_CHECK_STRING:
        ok = x->type == WC_JSON_STRING;
        break;
    case WC_CHECK_BOOL:
        ok = x->type == WC_JSON_TRUE || x->type == WC_JSON_FALSE;
        break;
    case WC_CHECK_ARRAY:
        ok = x->type == WC_JSON_ARRAY;
        break;
    default:
        ok = x->type == WC_JSON_OBJECT;
        break;
    }
    if (!ok)
        return _wc_check_bad(c, x, "'%s' must be %s", key, name[w]);
    *v = x;
    return WC_OK;
}

int
_wc_check_want_object(wc_check_reader * c, const wc_json_node * v)
{
    if (v->type != WC_JSON_OBJECT)
        return _wc_check_bad(c, v, "expected an object, found %s",
                             _wc_json_type_name(v->type));
    return WC_OK;
}

static int
all_digits(const char * s, size_t a, size_t b)
{
    size_t i;

    if (a >= b)
        return 0;
    for (i = a; i < b; i++)
        if (s[i] < '0' || s[i] > '9')
            return 0;
    return 1;
}

int
_wc_check_rational(wc_check_reader * c, const wc_json_node * v, mpq_t q)
{
    const char * s = v->text;
    size_t n = v->len, i, slash = n, a;

    if (v->type == WC_JSON_NUMBER)
    {
        /* the reader has checked the grammar: an integer has no . e E */
        for (i = 0; i < n; i++)
            if (s[i] == '.' || s[i] == 'e' || s[i] == 'E')
                return _wc_check_bad_quoting(c, v, "bad rational '%s'", s,
                                             n);
        mpz_set_str(mpq_numref(q), s, 10);
        mpz_set_ui(mpq_denref(q), 1);
        return WC_OK;
    }
    if (v->type != WC_JSON_STRING)
        return _wc_check_bad(c, v, "expected a rational, found %s",
                             _wc_json_type_name(v->type));
    a = n > 0 && s[0] == '-' ? 1 : 0;
    for (i = a; i < n; i++)
        if (s[i] == '/')
        {
            slash = i;
            break;
        }
    if (!all_digits(s, a, slash)
        || (slash < n && !all_digits(s, slash + 1, n)))
        return _wc_check_bad_quoting(c, v, "bad rational '%s'", s, n);
    if (slash < n)
    {
        for (i = slash + 1; i < n && s[i] == '0'; i++)
            ;
        if (i == n)
            return _wc_check_bad_quoting(c, v, "division by zero in '%s'",
                                         s, n);
    }
    /* s is NUL-terminated at n and holds only what mpq_set_str reads */
    if (mpq_set_str(q, s, 10) != 0)
        return _wc_check_bad_quoting(c, v, "bad rational '%s'", s, n);
    mpq_canonicalize(q);
    return WC_OK;
}

/* o[key] is an array, of want entries unless want is WC_CHECK_ANY_LENGTH,
   into *v.  */
static int
array_member(wc_check_reader * c, const wc_json_node * o, const char * key,
             size_t want, const wc_json_node ** v)
{
    if (_wc_check_member(c, o, key, WC_CHECK_ARRAY, v) != WC_OK)
        return WC_EINPUT;
    if (want != WC_CHECK_ANY_LENGTH && (*v)->len != want)
        return _wc_check_bad(c, *v, "'%s' must have %lu entries, not %lu",
                             key, (unsigned long) want,
                             (unsigned long) (*v)->len);
    return WC_OK;
}

/* The entries of the array v into q.  */
static int
read_entries(wc_check_reader * c, const wc_json_node * v, mpq_t * q)
{
    size_t i;

    for (i = 0; i < v->len; i++)
        if (_wc_check_rational(c, v->items + i, q[i]) != WC_OK)
            return WC_EINPUT;
    return WC_OK;
}

int
_wc_check_vector(wc_check_reader * c, const wc_json_node * o,
                 const char * key, mpq_t * q, size_t n)
{
    const wc_json_node * v;

    if (array_member(c, o, key, n, &v) != WC_OK)
        return WC_EINPUT;
    return read_entries(c, v, q);
}

int
_wc_check_qarray(wc_check_reader * c, const wc_json_node * o,
                 const char * key, size_t want, mpq_t ** q, size_t * len)
{
    const wc_json_node * v;

    if (array_member(c, o, key, want, &v) != WC_OK)
        return WC_EINPUT;
    *q = _wc_check_qvec_new(v->len);
    if (*q == NULL)
        return _wc_check_nomem(c);
    *len = v->len;
    return read_entries(c, v, *q);
}

void *
_wc_check_entries_new(wc_check_reader * c, mpq_t ** q, size_t k, size_t n,
                      size_t size)
{
    void * side;

    *q = _wc_check_qvec_new(_wc_check_times(k, n));
    side = _wc_check_alloc(n, size);
    if (*q != NULL && side != NULL)
        return side;
    _wc_check_qvec_free(*q, *q != NULL ? k * n : 0);
    free(side);
    *q = NULL;
    _wc_check_nomem(c);
    return NULL;
}

int
_wc_check_scalar(wc_check_reader * c, const wc_json_node * o,
                 const char * key, mpq_t q, int sign)
{
    const wc_json_node * v = _wc_json_object_get(o, key);

    if (v == NULL)
        return _wc_check_bad(c, o, "missing key '%s'", key);
    if (_wc_check_rational(c, v, q) != WC_OK)
        return WC_EINPUT;
    if (sign > 0 && mpq_sgn(q) <= 0)
        return _wc_check_bad(c, v, "'%s' must be positive", key);
    if (sign == 0 && mpq_sgn(q) < 0)
        return _wc_check_bad(c, v, "'%s' must not be negative", key);
    return WC_OK;
}

/* s[0..len) is the string word.  */
static int
is_word(const char * s, size_t len, const char * word)
{
    return len == strlen(word) && memcmp(s, word, len) == 0;
}

/* Another kind is another format: when this fails, nothing else is worth
   reading.  */
int
_wc_check_kind(wc_check_reader * c, const wc_json_node * root,
               wc_check_kind * kind)
{
    const wc_json_node * k;

    if (root->type != WC_JSON_OBJECT)
        return _wc_check_bad(c, root, "expected a certificate object, "
                             "found %s", _wc_json_type_name(root->type));
    k = _wc_json_object_get(root, "kind");
    *kind = WC_CHECK_MODE;
    if (k == NULL)
        return WC_OK;
    if (k->type != WC_JSON_STRING)
        return _wc_check_bad(c, k, "'kind' must be a string");
    if (is_word(k->text, k->len, WC_CERT_KIND_MODE))
        return WC_OK;
    if (is_word(k->text, k->len, WC_CERT_KIND_STABILITY))
    {
        *kind = WC_CHECK_STABILITY;
        return WC_OK;
    }
    if (is_word(k->text, k->len, WC_CERT_KIND_SET))
    {
        *kind = WC_CHECK_SET;
        return WC_OK;
    }
    if (is_word(k->text, k->len, WC_CERT_KIND_PLAN))
    {
        *kind = WC_CHECK_PLAN;
        return WC_OK;
    }
    if (is_word(k->text, k->len, WC_CERT_KIND_CRIT))
    {
        *kind = WC_CHECK_CRIT;
        return WC_OK;
    }
    return _wc_check_bad_quoting(c, k, "unknown certificate kind '%s'",
                                 k->text, k->len);
}
