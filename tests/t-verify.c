/* t-verify.c -- tests of the JSON reader and of the certificate checker.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Exact trees and exact located messages for good and bad JSON; good,
   tampered and malformed certificates with exact reasons and messages;
   every prefix and many one-byte mutations of a certificate (never a
   crash, never a wrong status); deep nesting, long inputs, huge numbers.
   Then a randomized cross-check: certificates written by wc_feasible and
   wc_certificate_fprint (FLINT, cddlib) always hold, and after random
   tampering of their witness or multipliers wc_verify_certificate (GMP
   alone) agrees with wc_certificate_check.

   Silent on success; every failure is printed to stderr with the line of
   this file that found it, and the exit status is 1.  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "core/json.h"
#include "check/verify.h"
#include "testutil.h"

/* The options of JSON output (io/print.h).  */
static const wc_print_opts as_json[1] = { { WC_FORMAT_JSON, 0, 0, NULL } };

#define fail(line, ...) wctest_report("t-verify.c", line, __VA_ARGS__)
#define FAIL(...) fail(__LINE__, __VA_ARGS__)

static void *
xmalloc(size_t n)
{
    void * p = malloc(n > 0 ? n : 1);

    if (p == NULL)
    {
        fputs("t-verify: out of memory\n", stderr);
        exit(99);
    }
    return p;
}

/* s with the first occurrence of old replaced by new; malloc'd.  */
static char *
subst(int line, const char * s, const char * old, const char * new)
{
    const char * p = strstr(s, old);
    size_t a, b = strlen(old), c = strlen(new), n = strlen(s);
    char * d;

    if (p == NULL)
    {
        fail(line, "test bug: '%s' not found", old);
        p = s + n;
        b = 0;
        c = 0;
    }
    a = (size_t) (p - s);
    d = xmalloc(n - b + c + 1);
    memcpy(d, s, a);
    memcpy(d + a, new, c);
    memcpy(d + a + c, p + b, n - a - b + 1);
    return d;
}

/* s repeated n times; malloc'd.  */
static char *
repeat(const char * s, size_t n)
{
    size_t k = strlen(s), i;
    char * d = xmalloc(k * n + 1);

    for (i = 0; i < n; i++)
        memcpy(d + i * k, s, k);
    d[k * n] = '\0';
    return d;
}

/* ------------------------------------------------------------------ */
/* JSON: good documents.                                                */

static void
node_is(int line, const wc_json_node * v, wc_json_type type, long l, long c)
{
    if (v == NULL)
        fail(line, "node missing");
    else if (v->type != type || v->line != l || v->col != c)
        fail(line, "node: type %d at %ld:%ld, expected type %d at %ld:%ld",
             (int) v->type, v->line, v->col, (int) type, l, c);
}

static void
text_is(int line, const wc_json_node * v, const char * s, size_t n)
{
    if (v == NULL || v->text == NULL)
        fail(line, "no text");
    else if (v->len != n || memcmp(v->text, s, n) != 0 || v->text[n] != '\0')
        fail(line, "text of %lu bytes differs", (unsigned long) v->len);
}

static void
test_json_good(void)
{
    static const char doc[] =
        "{\"a\": [1, -2.5e3, \"x\"],\r\n"
        " \"b\": {\"c\": null, \"d\": true, \"e\": false},\n"
        "\"\": \"\\u00e9\\ud83d\\ude00\\\"\\\\\\/\\b\\f\\n\\r\\t\\u0000z\","
        " \"\xc3\xa9\": [], \"o\": {}}   \n";
    static const char decoded[] =
        "\xc3\xa9\xf0\x9f\x98\x80\"\\/\b\f\n\r\t\0z";
    wc_json_t J;
    wc_error_t e;
    const wc_json_node * r, * a, * b, * v;
    int status;

    _wc_json_init(J);
    wc_error_init(e);
    status = _wc_json_parse(J, doc, sizeof doc - 1, "doc", e);
    if (status != WC_OK)
    {
        FAIL("good document: status %d (%s)", status, e->message);
        goto cleanup;
    }
    r = &J->root;
    node_is(__LINE__, r, WC_JSON_OBJECT, 1, 1);
    if (r->len != 5)
        FAIL("root has %lu members", (unsigned long) r->len);
    node_is(__LINE__, _wc_json_object_key(r, 0), WC_JSON_STRING, 1, 2);
    a = _wc_json_object_get(r, "a");
    node_is(__LINE__, a, WC_JSON_ARRAY, 1, 7);
    if (a != NULL && a->len != 3)
        FAIL("a has %lu elements", (unsigned long) a->len);
    v = _wc_json_array_get(a, 0);
    node_is(__LINE__, v, WC_JSON_NUMBER, 1, 8);
    text_is(__LINE__, v, "1", 1);
    v = _wc_json_array_get(a, 1);
    node_is(__LINE__, v, WC_JSON_NUMBER, 1, 11);
    text_is(__LINE__, v, "-2.5e3", 6);
    v = _wc_json_array_get(a, 2);
    node_is(__LINE__, v, WC_JSON_STRING, 1, 19);
    text_is(__LINE__, v, "x", 1);
    if (_wc_json_array_get(a, 3) != NULL)
        FAIL("element past the end");
    b = _wc_json_object_get(r, "b");
    node_is(__LINE__, b, WC_JSON_OBJECT, 2, 7);
    node_is(__LINE__, _wc_json_object_key(b, 0), WC_JSON_STRING, 2, 8);
    node_is(__LINE__, _wc_json_object_get(b, "c"), WC_JSON_NULL, 2, 13);
    node_is(__LINE__, _wc_json_object_get(b, "d"), WC_JSON_TRUE, 2, 24);
    node_is(__LINE__, _wc_json_object_get(b, "e"), WC_JSON_FALSE, 2, 35);
    node_is(__LINE__, _wc_json_object_value(b, 2), WC_JSON_FALSE, 2, 35);
    if (_wc_json_object_get(b, "f") != NULL || _wc_json_object_get(a, "a")
        != NULL || _wc_json_object_value(b, 3) != NULL)
        FAIL("lookup of what is not there");
    v = _wc_json_object_get(r, "");
    node_is(__LINE__, v, WC_JSON_STRING, 3, 5);
    text_is(__LINE__, v, decoded, sizeof decoded - 1);
    v = _wc_json_object_get(r, "\xc3\xa9");
    node_is(__LINE__, v, WC_JSON_ARRAY, 3, 56);
    if (v != NULL && (v->len != 0 || v->items != NULL))
        FAIL("empty array not empty");
    v = _wc_json_object_get(r, "o");
    node_is(__LINE__, v, WC_JSON_OBJECT, 3, 65);
    if (v != NULL && v->len != 0)
        FAIL("empty object not empty");

    /* scalars alone; parsing again replaces the document */
    if (_wc_json_parse(J, " -0 ", 4, "doc", e) != WC_OK)
        FAIL("-0: %s", e->message);
    node_is(__LINE__, &J->root, WC_JSON_NUMBER, 1, 2);
    text_is(__LINE__, &J->root, "-0", 2);
    if (_wc_json_parse(J, "\"\"", 2, "doc", e) != WC_OK)
        FAIL("empty string: %s", e->message);
    text_is(__LINE__, &J->root, "", 0);
    if (_wc_json_parse(J, "0.5E+10", 7, NULL, e) != WC_OK
        || _wc_json_parse(J, "1e-7", 4, NULL, e) != WC_OK
        || _wc_json_parse(J, "[[], {}, [{}]]", 14, NULL, e) != WC_OK
        || _wc_json_parse(J, "\t\r\n null \n", 10, NULL, e) != WC_OK)
        FAIL("good scalar: %s", e->message);
    node_is(__LINE__, &J->root, WC_JSON_NULL, 2, 2);
    /* keys that differ only after a NUL are different keys */
    if (_wc_json_parse(J, "{\"a\\u0000b\": 1, \"a\\u0000c\": 2, \"a\": 3}", 38,
                      NULL, e) != WC_OK)
        FAIL("keys with NUL: %s", e->message);
    else if ((v = _wc_json_object_get(&J->root, "a")) == NULL
             || strcmp(v->text, "3") != 0)
        FAIL("key 'a' not found among keys with NULs");
cleanup:
    _wc_json_clear(J);
    _wc_json_clear(J);   /* clear is safe twice */
    wc_error_clear(e);
}

/* ------------------------------------------------------------------ */
/* JSON: bad documents, exact located messages.                         */

static void
json_bad_n(int line, const char * text, size_t len, const char * expect)
{
    wc_json_t J;
    wc_error_t e;
    char * got;
    int status;

    _wc_json_init(J);
    wc_error_init(e);
    status = _wc_json_parse(J, text, len, "f", e);
    got = wc_error_format(e);
    if (status != WC_EINPUT)
        fail(line, "status %d, expected %d (%s)", status, WC_EINPUT,
             got != NULL ? got : "");
    else if (strcmp(got, expect) != 0)
        fail(line, "message '%s', expected '%s'", got, expect);
    if (J->root.type != WC_JSON_NULL || J->root.items != NULL
        || J->arena != NULL)
        fail(line, "document not empty after an error");
    free(got);
    _wc_json_clear(J);
    wc_error_clear(e);
}

#define JSON_BAD(text, expect) \
    json_bad_n(__LINE__, text, sizeof(text) - 1, expect)

static void
test_json_bad(void)
{
    char * s, * t;

    JSON_BAD("", "f:1:1: unexpected end of input");
    JSON_BAD("  \n  ", "f:2:3: unexpected end of input");
    JSON_BAD("{", "f:1:2: unexpected end of input");
    JSON_BAD("[1,", "f:1:4: unexpected end of input");
    JSON_BAD("{\"a\":", "f:1:6: unexpected end of input");
    JSON_BAD("[1,]", "f:1:4: expected a value, found ']'");
    JSON_BAD("[,1]", "f:1:2: expected a value, found ','");
    JSON_BAD("[1 2]", "f:1:4: expected ',' or ']', found '2'");
    JSON_BAD("{\"a\" 1}", "f:1:6: expected ':', found '1'");
    JSON_BAD("{\"a\":1,}", "f:1:8: expected a string key, found '}'");
    JSON_BAD("{1:2}", "f:1:2: expected a string key, found '1'");
    JSON_BAD("{'a':2}", "f:1:2: expected a string key, found '''");
    JSON_BAD("{\"a\":1 \"b\":2}", "f:1:8: expected ',' or '}', found '\"'");
    JSON_BAD("{\"a\":1]", "f:1:7: expected ',' or '}', found ']'");
    JSON_BAD("[1}", "f:1:3: expected ',' or ']', found '}'");
    JSON_BAD("01", "f:1:1: bad number '01'");
    JSON_BAD("[-01]", "f:1:2: bad number '-01'");
    JSON_BAD("1.", "f:1:1: bad number '1.'");
    JSON_BAD("1.e5", "f:1:1: bad number '1.e5'");
    JSON_BAD("-", "f:1:1: bad number '-'");
    JSON_BAD("1e", "f:1:1: bad number '1e'");
    JSON_BAD("1e+", "f:1:1: bad number '1e+'");
    JSON_BAD("1-2", "f:1:1: bad number '1-2'");
    JSON_BAD("--1", "f:1:1: bad number '--1'");
    JSON_BAD(".5", "f:1:1: expected a value, found '.'");
    JSON_BAD("+1", "f:1:1: expected a value, found '+'");
    JSON_BAD("[1x]", "f:1:3: expected ',' or ']', found 'x'");
    JSON_BAD("tru", "f:1:1: invalid literal 'tru'");
    JSON_BAD("True", "f:1:1: invalid literal 'True'");
    JSON_BAD("[nulls]", "f:1:2: invalid literal 'nulls'");
    JSON_BAD("NaN", "f:1:1: invalid literal 'NaN'");
    JSON_BAD("[1] x", "f:1:5: unexpected 'x' after the JSON value");
    JSON_BAD("{}{}", "f:1:3: unexpected '{' after the JSON value");
    JSON_BAD("[1]\0", "f:1:4: unexpected '\\x00' after the JSON value");
    JSON_BAD("\0", "f:1:1: expected a value, found '\\x00'");
    JSON_BAD("[\0]", "f:1:2: expected a value, found '\\x00'");
    JSON_BAD("\xef\xbb\xbf{}", "f:1:1: expected a value, found '\\xef'");
    JSON_BAD("\"ab", "f:1:1: unterminated string");
    JSON_BAD("[\"ab\\", "f:1:2: unterminated string");
    JSON_BAD("\"a\nb\"", "f:1:3: control character '\\x0a' in string");
    JSON_BAD("\"a\0b\"", "f:1:3: control character '\\x00' in string");
    JSON_BAD("\"a\tb\"", "f:1:3: control character '\\x09' in string");
    JSON_BAD("\"\\x\"", "f:1:2: invalid escape '\\x'");
    JSON_BAD("\"\\'\"", "f:1:2: invalid escape '\\''");
    JSON_BAD("\"\\\xc3\xa9\"", "f:1:2: invalid escape '\\\xc3\xa9'");
    JSON_BAD("\"\\\n\"", "f:1:2: invalid escape '\\\\x0a'");
    JSON_BAD("\"\\u12G4\"", "f:1:2: invalid escape '\\u12G4'");
    JSON_BAD("\"\\u12\"", "f:1:2: invalid escape '\\u12'");
    JSON_BAD("\"\\u12", "f:1:1: unterminated string");
    JSON_BAD("\"\\u12x", "f:1:2: invalid escape '\\u12x'");
    JSON_BAD("\"\\U0041\"", "f:1:2: invalid escape '\\U'");
    JSON_BAD("\"\\ud800\"", "f:1:2: unpaired surrogate '\\ud800'");
    JSON_BAD("\"\\udc00\\ud800\"", "f:1:2: unpaired surrogate '\\udc00'");
    JSON_BAD("\"\\ud800\\u0041\"", "f:1:2: unpaired surrogate '\\ud800'");
    JSON_BAD("\"\\ud800\\ud800\"", "f:1:2: unpaired surrogate '\\ud800'");
    JSON_BAD("\"x\\ud800", "f:1:1: unterminated string");
    JSON_BAD("\"x\\ud800\\udc", "f:1:1: unterminated string");
    JSON_BAD("\"x\\ud800z", "f:1:3: unpaired surrogate '\\ud800'");
    JSON_BAD("\"\xc3\"", "f:1:2: invalid UTF-8 in string");
    JSON_BAD("\"ab\xc3", "f:1:4: invalid UTF-8 in string");
    JSON_BAD("\"\xed\xa0\x80\"", "f:1:2: invalid UTF-8 in string");
    JSON_BAD("\"\xc0\xaf\"", "f:1:2: invalid UTF-8 in string");
    JSON_BAD("\"\xe0\x80\xaf\"", "f:1:2: invalid UTF-8 in string");
    JSON_BAD("\"\xf0\x80\x80\xaf\"", "f:1:2: invalid UTF-8 in string");
    JSON_BAD("\"\xf4\x90\x80\x80\"", "f:1:2: invalid UTF-8 in string");
    JSON_BAD("\"\xff\"", "f:1:2: invalid UTF-8 in string");
    JSON_BAD("\"\x80\"", "f:1:2: invalid UTF-8 in string");
    JSON_BAD("[\n  1,\n  x]", "f:3:3: invalid literal 'x'");
    JSON_BAD("[1,\r\n %]", "f:2:2: expected a value, found '%'");
    JSON_BAD("[1,\r\n \x7f]", "f:2:2: expected a value, found '\\x7f'");

    /* duplicate keys: the first repeat in file order, whatever comes after */
    JSON_BAD("{\"a\":1,\"a\":2}", "f:1:8: duplicate key 'a'");
    JSON_BAD("{\"a\":1,\"b\":{\"a\":2,\"a\":3},\"b\":4}",
             "f:1:19: duplicate key 'a'");
    JSON_BAD("{\"a\":1,\"a\":2,x}", "f:1:8: duplicate key 'a'");
    JSON_BAD("{\"a\":1,\"a\":{\"b\":x}}", "f:1:8: duplicate key 'a'");
    JSON_BAD("{\"a\":1,\"a\" x}", "f:1:8: duplicate key 'a'");
    JSON_BAD("{\"a\":{\"b\":1,\"b\":2,\"c\":x}}", "f:1:13: duplicate key 'b'");
    JSON_BAD("{\"a\":{\"b\":1,\"b\":2},\"a\":x}", "f:1:13: duplicate key 'b'");
    JSON_BAD("{\"x\":1,\"a\\u0000b\":1,\"a\\u0000b\":2}",
             "f:1:21: duplicate key 'a\\x00b'");
    JSON_BAD("{\"\\u0041\":1,\"A\":2}", "f:1:13: duplicate key 'A'");
    JSON_BAD("[{\"a\":1},{\"a\":1,\"a\":1}]", "f:1:17: duplicate key 'a'");

    /* a long key is cut in the message */
    s = repeat("k", 100);
    t = xmalloc(300);
    sprintf(t, "{\"%s\": 1, \"%s\": 2}", s, s);
    {
        char expect[200];

        sprintf(expect, "f:1:109: duplicate key '%.64s...'", s);
        json_bad_n(__LINE__, t, strlen(t), expect);
    }
    free(s);
    free(t);
}

/* ------------------------------------------------------------------ */
/* JSON: limits.                                                        */

static void
test_json_limits(void)
{
    wc_json_t J;
    wc_error_t e;
    char * s, * t, * u;
    size_t n, i;
    int status;

    _wc_json_init(J);
    wc_error_init(e);

    /* 64 levels are fine, 65 are not, however deep the input goes */
    s = repeat("[", WC_JSON_MAX_DEPTH);
    t = repeat("]", WC_JSON_MAX_DEPTH);
    u = xmalloc(2 * WC_JSON_MAX_DEPTH + 1);
    sprintf(u, "%s%s", s, t);
    if (_wc_json_parse(J, u, strlen(u), "f", e) != WC_OK)
        FAIL("64 levels: %s", e->message);
    free(s);
    free(t);
    free(u);
    s = repeat("{\"a\":", WC_JSON_MAX_DEPTH + 1);
    json_bad_n(__LINE__, s, strlen(s), "f:1:321: nesting deeper than 64 "
               "levels");
    free(s);
    s = repeat("[", 1000000);
    json_bad_n(__LINE__, s, strlen(s), "f:1:65: nesting deeper than 64 "
               "levels");
    free(s);

    /* a long document: many values, long strings across arena blocks */
    n = 200000;
    s = repeat("[0,\"abc\",{\"k\":-1.5}],", n);
    t = xmalloc(strlen(s) + 4);
    sprintf(t, "[%s0]", s);
    status = _wc_json_parse(J, t, strlen(t), "f", e);
    if (status != WC_OK || J->root.len != n + 1)
        FAIL("long document: status %d", status);
    else
    {
        const wc_json_node * v = _wc_json_array_get(&J->root, n - 1);

        node_is(__LINE__, _wc_json_array_get(v, 2), WC_JSON_OBJECT, 1,
                (long) (n - 1) * 21 + 11);
        text_is(__LINE__, _wc_json_object_get(_wc_json_array_get(v, 2), "k"),
                "-1.5", 4);
    }
    free(s);
    free(t);
    s = xmalloc(300003);
    s[0] = '[';
    for (i = 1; i < 300000; i++)
        s[i] = i % 100000 == 0 ? ',' : i % 100000 == 1 ? '"'
             : i % 100000 == 99999 ? '"' : 'a' + (char) (i % 26);
    s[300000] = ']';
    s[300001] = '\0';
    s[1] = '"';
    if (_wc_json_parse(J, s, 300001, "f", e) != WC_OK || J->root.len != 3
        || J->root.items[0].len != 99997 || J->root.items[2].len != 99997)
        FAIL("long strings: %s", e->message);
    free(s);

    /* an object with many keys and one repeat at the end */
    s = xmalloc(20 * 100000 + 64);
    n = 0;
    s[n++] = '{';
    for (i = 0; i < 100000; i++)
        n += (size_t) sprintf(s + n, "\"k%lu\":%lu,", (unsigned long) i,
                              (unsigned long) i);
    n += (size_t) sprintf(s + n, "\"k77\":0}");
    status = _wc_json_parse(J, s, n, "f", e);
    if (status != WC_EINPUT || e->message == NULL
        || strcmp(e->message, "duplicate key 'k77'") != 0
        || e->col != (long) n - 7)
        FAIL("many keys: status %d, %s at %ld", status,
             e->message ? e->message : "", e->col);
    free(s);

    /* garbage: random bytes, never anything but WC_EINPUT */
    n = 1 << 20;
    s = xmalloc(n);
    for (i = 0; i < n; i++)
        s[i] = (char) (wctest_rand() & 0xff);
    s[0] = '[';
    for (i = 0; i < 64; i++)
    {
        size_t len = (size_t) wctest_randint(0, (slong) n);

        if (_wc_json_parse(J, s + (i % 2), len - (len > 0 && i % 2), "f", e)
            != WC_EINPUT)
            FAIL("garbage parsed");
    }
    /* garbage made of JSON's own characters */
    for (i = 0; i < n; i++)
        s[i] = "[]{}\",:0-1e.tn\\u \n"[wctest_rand() % 19];
    for (i = 0; i < 64; i++)
    {
        size_t len = (size_t) wctest_randint(0, (slong) n);

        status = _wc_json_parse(J, s, len, "f", e);
        if (status != WC_EINPUT && status != WC_OK)
            FAIL("JSON characters: status %d", status);
    }
    free(s);
    _wc_json_clear(J);
    wc_error_clear(e);
}

/* ------------------------------------------------------------------ */
/* Certificates.                                                        */

#define P5 "\"problem\": {\"com\": [\"0\", \"0\"], \"fixels\": [{\"point\": " \
    "[\"0\", \"-1\"], \"normal\": [\"0\", \"1\"], \"state\": \"touching\"}, " \
    "{\"point\": [\"1\", \"0\"], \"normal\": [\"-1\", \"0\"], \"state\": " \
    "\"touching\"}]}"

static const char cert_ss[] =
    "{\"kind\": \"mode-feasibility\", \"mode\": \"ss\", \"feasible\": true, "
    "\"witness\": [\"-1\", \"1\", \"0\"], \"constraints\": [{\"row\": "
    "[\"0\", \"1\", \"0\"], \"relation\": \">\"}, {\"row\": [\"-1\", \"0\", "
    "\"0\"], \"relation\": \">\"}], " P5 "}\n";

static const char cert_ll[] =
    "{\"kind\": \"mode-feasibility\", \"mode\": \"ll\", \"feasible\": true, "
    "\"witness\": [\"0\", \"0\", \"-1\"], \"constraints\": [{\"row\": "
    "[\"0\", \"1\", \"0\"], \"relation\": \"=\"}, {\"row\": [\"-1\", \"0\", "
    "\"-1\"], \"relation\": \">\"}, {\"row\": [\"-1\", \"0\", \"0\"], "
    "\"relation\": \"=\"}, {\"row\": [\"0\", \"-1\", \"-1\"], \"relation\": "
    "\">\"}], " P5 "}\n";

static const char cert_ln[] =
    "{\"kind\": \"mode-feasibility\", \"mode\": \"ln\", \"feasible\": false, "
    "\"constraints\": [{\"row\": [\"0\", \"1\", \"0\"], \"relation\": \"=\"}, "
    "{\"row\": [\"-1\", \"0\", \"-1\"], \"relation\": \">\"}, {\"row\": "
    "[\"-1\", \"0\", \"0\"], \"relation\": \"=\"}, {\"row\": [\"0\", \"-1\", "
    "\"-1\"], \"relation\": \"=\"}], \"multipliers\": [\"-1\", \"1\", \"-1\", "
    "\"-1\"], " P5 "}\n";

/* Three fixels with rational data, a near one in the middle: com (1/2, 0);
   (1/3, 1/2) normal (1, 1/2); (3/2, -1) normal (0, 3) near; (-2, 5/7)
   normal (-4, 6).  Rows: J_1n (12, 6, -7), J_1t (-6, 12, 1), J_2n
   (0, 1, 1), J_3n (-28, 42, -85), J_3t (-21, -14, 50).  */
#define PODD "\"problem\": {\"com\": [\"2/4\", 0], \"fixels\": [{\"point\": " \
    "[\"1/3\", \"1/2\"], \"normal\": [\"1\", \"1/2\"], \"state\": " \
    "\"touching\"}, {\"point\": [\"3/2\", \"-1\"], \"normal\": [0, 3], " \
    "\"state\": \"near\"}, {\"point\": [\"-2\", \"5/7\"], \"normal\": " \
    "[\"-4\", \"6\"], \"state\": \"touching\"}]}"

static const char cert_sss[] =
    "{\"mode\": \"sss\", \"feasible\": true, \"witness\": [\"-1\", \"1\", "
    "\"-1\"], \"constraints\": [{\"row\": [\"12\", \"6\", \"-7\"], "
    "\"relation\": \">\"}, {\"row\": [\"0\", \"1\", \"1\"], \"relation\": "
    "\">=\"}, {\"row\": [\"-28\", \"42\", \"-85\"], \"relation\": \">\"}], "
    PODD "}";

static const char cert_nan[] =
    "{\"mode\": \"nan\", \"feasible\": false, \"constraints\": [{\"row\": "
    "[\"12\", \"6\", \"-7\"], \"relation\": \"=\"}, {\"row\": [\"-6\", "
    "\"12\", \"1\"], \"relation\": \"=\"}, {\"row\": [\"0\", \"-1\", \"-1\"], "
    "\"relation\": \">\"}, {\"row\": [\"-28\", \"42\", \"-85\"], "
    "\"relation\": \"=\"}, {\"row\": [\"-21\", \"-14\", \"50\"], "
    "\"relation\": \"=\"}], \"multipliers\": [\"227/8280\", \"118/1035\", "
    "\"1\", \"-7/552\", \"0\"], " PODD "}";

/* Run wc_verify; returns its status and sets the outputs.  */
static int
run_wc_verify(int * holds, char ** reason, char ** summary,
              const char * text, size_t len, char ** msg)
{
    wc_error_t e;
    int status;

    wc_error_init(e);
    status = wc_verify(holds, reason, summary, text, len, "c", e);
    *msg = status != WC_OK ? wc_error_format(e) : NULL;
    wc_error_clear(e);
    return status;
}

/* Run wc_verify_certificate; returns its status and sets the outputs.
   wc_verify must agree: same status, verdict, reason and message, and
   its summary names the mode and the claim.  */
static int
run_verify(int * holds, char ** reason, char ** mode, int * feasible,
           const char * text, size_t len, char ** msg)
{
    wc_error_t e;
    int status, status2, holds2;
    char * reason2, * summary2, * msg2;

    wc_error_init(e);
    status = wc_verify_certificate(holds, reason, mode, feasible, text, len,
                                   "c", e);
    *msg = status != WC_OK ? wc_error_format(e) : NULL;
    wc_error_clear(e);
    status2 = run_wc_verify(&holds2, &reason2, &summary2, text, len, &msg2);
    if (status2 != status
        || (status == WC_OK && (holds2 != *holds
                                || (reason2 == NULL) != (*reason == NULL)
                                || (reason2 != NULL
                                    && strcmp(reason2, *reason) != 0)
                                || summary2 == NULL))
        || (status != WC_OK && (msg2 == NULL || *msg == NULL
                                || strcmp(msg2, *msg) != 0
                                || summary2 != NULL || reason2 != NULL)))
        FAIL("wc_verify disagrees with wc_verify_certificate: status %d/%d,"
             " '%s' / '%s'", status2, status, msg2 != NULL ? msg2
             : reason2 != NULL ? reason2 : "", *msg != NULL ? *msg
             : *reason != NULL ? *reason : "");
    else if (status == WC_OK)
    {
        char expect[200];

        snprintf(expect, sizeof expect, "mode %.150s is %s", *mode,
                 *feasible ? "feasible" : "infeasible");
        if (strcmp(summary2, expect) != 0)
            FAIL("wc_verify summary '%s', expected '%s'", summary2, expect);
    }
    free(reason2);
    free(summary2);
    free(msg2);
    return status;
}

/* Whether a verifier's answer (status, holds, why; msg on error) is that
   the text holds (reason NULL) or not for the reason given; if not, says
   so for line.  */
static int
verdict_as(int line, int status, int holds, const char * why,
           const char * msg, const char * reason)
{
    if (status != WC_OK)
        fail(line, "status %d: %s", status, msg);
    else if (reason == NULL && (holds != 1 || why != NULL))
        fail(line, "does not hold: %s", why != NULL ? why : "(no reason)");
    else if (reason != NULL && (holds != 0 || why == NULL
                                || strcmp(why, reason) != 0))
        fail(line, "holds %d, reason '%s', expected '%s'", holds,
             why != NULL ? why : "(none)", reason);
    else
        return 1;
    return 0;
}

/* text holds (or not: then reason must be as given), claiming mode and
   feasible.  */
static void
verdict_is(int line, const char * text, const char * reason,
           const char * mode, int feasible)
{
    int holds = -1, feas = -1, status;
    char * why = NULL, * m = NULL, * msg = NULL;

    status = run_verify(&holds, &why, &m, &feas, text, strlen(text), &msg);
    if (verdict_as(line, status, holds, why, msg, reason)
        && (m == NULL || strcmp(m, mode) != 0 || feas != feasible))
        fail(line, "claims mode %s, feasible %d", m != NULL ? m : "(none)",
             feas);
    free(why);
    free(m);
    free(msg);
}

#define HOLDS(text, mode, feasible) \
    verdict_is(__LINE__, text, NULL, mode, feasible)

/* The certificate base with old replaced by new does not hold, for the
   given reason.  */
static void
tampered_n(int line, const char * base, const char * old, const char * new,
           const char * reason, const char * mode, int feasible)
{
    char * t = subst(line, base, old, new);

    verdict_is(line, t, reason, mode, feasible);
    free(t);
}

#define TAMPERED(base, old, new, reason, mode, feasible) \
    tampered_n(__LINE__, base, old, new, reason, mode, feasible)

/* text is malformed: the message is expect ("c:LINE:COL: ...").  A mode
   certificate (mode_cert) goes through run_verify, which checks
   wc_verify_certificate and wc_verify agree; any other through
   run_wc_verify, m then standing for wc_verify's summary.  */
static void
malformed_n(int line, const char * text, size_t len, const char * expect,
            int mode_cert)
{
    int holds = -1, feas = mode_cert ? -1 : 0, status;
    char * why = (char *) "x", * m = (char *) "x", * msg = NULL;

    status = mode_cert ? run_verify(&holds, &why, &m, &feas, text, len, &msg)
             : run_wc_verify(&holds, &why, &m, text, len, &msg);
    if (status != WC_EINPUT)
        fail(line, "status %d, expected %d (%s)", status, WC_EINPUT,
             msg != NULL ? msg : why != NULL ? why : "holds");
    else if (msg == NULL || strcmp(msg, expect) != 0)
        fail(line, "message '%s', expected '%s'", msg, expect);
    else if (holds != 0 || why != NULL || m != NULL || feas != 0)
        fail(line, "outputs set on a malformed certificate");
    if (status == WC_OK)
    {
        free(why);
        free(m);
    }
    free(msg);
}

/* The certificate base with old replaced by new is malformed, as
   malformed_n says.  */
static void
bad_edit_n(int line, const char * base, const char * old, const char * new,
           const char * expect, int mode_cert)
{
    char * t = subst(line, base, old, new);

    malformed_n(line, t, strlen(t), expect, mode_cert);
    free(t);
}

#define BAD(base, old, new, expect) \
    bad_edit_n(__LINE__, base, old, new, expect, 1)

static void
test_good(void)
{
    char * t;

    HOLDS(cert_ss, "ss", 1);
    HOLDS(cert_ll, "ll", 1);
    HOLDS(cert_ln, "ln", 0);
    HOLDS(cert_sss, "sss", 1);
    HOLDS(cert_nan, "nan", 0);
    /* the same, written otherwise: JSON integers, other scales, fractions
       not in lowest terms, another key order, unknown keys, no kind */
    t = subst(__LINE__, cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]",
              "[-3, \"6/2\", \"-9/3\", -3], \"note\": {\"x\": [null]}");
    HOLDS(t, "ln", 0);
    free(t);
    t = subst(__LINE__, cert_ss, "[\"-1\", \"1\", \"0\"]",
              "[\"-1/1000\", \"007/1000\", -0]");
    HOLDS(t, "ss", 1);
    free(t);
    t = subst(__LINE__, cert_ss, "\"kind\": \"mode-feasibility\", ", "");
    HOLDS(t, "ss", 1);
    free(t);
    HOLDS("\n{ \"problem\" : {\"fixels\": [{\"state\": \"touching\", \"normal\""
          ": [\"0\", \"5/3\"], \"point\": [\"3\", \"-1\"], \"extra\": 1}], "
          "\"com\": [\"3\", \"0\"]}, \"witness\": [\"1\", \"0\", \"-1\"], "
          "\"feasible\": true, \"constraints\": [{\"relation\": \"=\", \"row\""
          ": [\"0\", \"1\", \"0\"]}, {\"relation\": \"=\", \"row\": [\"-1\", "
          "\"0\", \"-1\"]}], \"mode\": \"n\", \"multipliers\": \"ignored\"}\n",
          "n", 1);
    /* the nu = 0 witness of the all-n mode */
    HOLDS("{\"mode\": \"nn\", \"feasible\": true, \"witness\": [0, 0, 0], "
          "\"constraints\": [{\"row\": [0, 1, 0], \"relation\": \"=\"}, "
          "{\"row\": [-1, 0, -1], \"relation\": \"=\"}, {\"row\": [-1, 0, 0], "
          "\"relation\": \"=\"}, {\"row\": [0, -1, -1], \"relation\": \"=\"}],"
          " " P5 "}", "nn", 1);
    /* near fixels: a (-J_n >) and s (J_n >=); r (-J_t >) */
    t = subst(__LINE__, cert_sss, "\"sss\"", "\"ras\"");
    {
        char * u = subst(__LINE__, t, "[{\"row\": [\"12\", \"6\", \"-7\"], "
                         "\"relation\": \">\"}, {\"row\": [\"0\", \"1\", "
                         "\"1\"], \"relation\": \">=\"}", "[{\"row\": "
                         "[\"12\", \"6\", \"-7\"], \"relation\": \"=\"}, "
                         "{\"row\": [\"6\", \"-12\", \"-1\"], \"relation\": "
                         "\">\"}, {\"row\": [\"0\", \"-1\", \"-1\"], "
                         "\"relation\": \">\"}");
        char * v = subst(__LINE__, u, "[\"-1\", \"1\", \"-1\"]",
                         "[\"-13\", \"-18\", \"12\"]");

        /* (12,6,-7).w = -156-108-84 < 0: the witness fails on row 1 */
        verdict_is(__LINE__, v, "the witness (-13, -18, 12) violates "
                   "constraint 1: (12, 6, -7) . nu = -348, not = 0", "ras",
                   1);
        free(v);
        free(u);
    }
    free(t);
}

static void
test_tampered(void)
{
    char * big, * t;

    TAMPERED(cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]",
             "[\"-1\", \"1\", \"1\", \"-1\"]",
             "the multipliers combine the rows to (-2, 0, 0), not to zero",
             "ln", 0);
    TAMPERED(cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]",
             "[\"-1\", \"1/2\", \"-1\", \"-1\"]",
             "the multipliers combine the rows to (1/2, 0, 1/2), not to zero",
             "ln", 0);
    TAMPERED(cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]",
             "[\"1\", \"-1\", \"1\", \"1\"]",
             "multiplier 2 is -1, negative on a '>' constraint", "ln", 0);
    TAMPERED(cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]",
             "[\"0\", \"0\", \"0\", \"0\"]",
             "no '>' constraint has a positive multiplier", "ln", 0);
    TAMPERED(cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]",
             "[\"-1\", \"1\", \"-1\"]",
             "there are 3 multipliers for 4 constraints", "ln", 0);
    TAMPERED(cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]", "[]",
             "there are 0 multipliers for 4 constraints", "ln", 0);
    TAMPERED(cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]",
             "[\"-1\", \"1\", \"-1\", \"-1\", \"0\"]",
             "there are 5 multipliers for 4 constraints", "ln", 0);
    TAMPERED(cert_nan, "[\"227/8280\", \"118/1035\", \"1\", \"-7/552\", "
             "\"0\"]", "[\"227/8280\", \"118/1035\", \"1\", \"-7/552\", "
             "\"-1\"]", "the multipliers combine the rows to (21, 14, -50), "
             "not to zero", "nan", 0);
    TAMPERED(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"0\", \"1\", \"0\"]",
             "the witness (0, 1, 0) violates constraint 2: (-1, 0, 0) . nu "
             "= 0, not > 0", "ss", 1);
    TAMPERED(cert_ll, "[\"0\", \"0\", \"-1\"]", "[\"0\", \"1/3\", \"-1\"]",
             "the witness (0, 1/3, -1) violates constraint 1: (0, 1, 0) . nu "
             "= 1/3, not = 0", "ll", 1);
    TAMPERED(cert_sss, "[\"-1\", \"1\", \"-1\"]", "[\"-1\", \"1\", \"-2\"]",
             "the witness (-1, 1, -2) violates constraint 2: (0, 1, 1) . nu "
             "= -1, not >= 0", "sss", 1);
    /* the constraints are not those of the mode */
    TAMPERED(cert_ll, "\"-1\"], \"relation\": \">\"}",
             "\"-1\"], \"relation\": \">=\"}",
             "constraint 2 is not the one mode ll implies for fixel 1: "
             "expected (-1, 0, -1) . nu > 0, found (-1, 0, -1) . nu >= 0",
             "ll", 1);
    TAMPERED(cert_ln, "[\"-1\", \"0\", \"0\"]", "[\"-1\", \"0\", \"1\"]",
             "constraint 3 is not the one mode ln implies for fixel 2: "
             "expected (-1, 0, 0) . nu = 0, found (-1, 0, 1) . nu = 0",
             "ln", 0);
    TAMPERED(cert_ln, "[\"-1\", \"0\", \"0\"]", "[\"-2\", \"0\", \"0\"]",
             "constraint 3 is not the one mode ln implies for fixel 2: "
             "expected (-1, 0, 0) . nu = 0, found (-2, 0, 0) . nu = 0",
             "ln", 0);
    TAMPERED(cert_ln, "[\"-1\", \"0\", \"0\"]", "[\"-1/2\", \"0\", \"0\"]",
             "constraint 3 is not the one mode ln implies for fixel 2: "
             "expected (-1, 0, 0) . nu = 0, found (-1/2, 0, 0) . nu = 0",
             "ln", 0);
    TAMPERED(cert_ln, ", {\"row\": [\"0\", \"-1\", \"-1\"], \"relation\": "
             "\"=\"}]", "]", "the certificate lists 3 constraints; mode ln "
             "implies 4", "ln", 0);
    TAMPERED(cert_ln, "\"relation\": \"=\"}]", "\"relation\": \"=\"}, "
             "{\"row\": [0, 0, 0], \"relation\": \">=\"}]",
             "the certificate lists 5 constraints; mode ln implies 4",
             "ln", 0);
    TAMPERED(cert_ln, "\"constraints\": [{\"row\": [\"0\", \"1\", \"0\"], "
             "\"relation\": \"=\"}, ", "\"constraints\": [",
             "constraint 1 is not the one mode ln implies for fixel 1: "
             "expected (0, 1, 0) . nu = 0, found (-1, 0, -1) . nu > 0",
             "ln", 0);
    TAMPERED(cert_ss, "\"com\": [\"0\", \"0\"]", "\"com\": [\"0\", \"1/2\"]",
             "constraint 2 is not the one mode ss implies for fixel 2: "
             "expected (-2, 0, -1) . nu > 0, found (-1, 0, 0) . nu > 0",
             "ss", 1);
    TAMPERED(cert_ss, "\"normal\": [\"-1\", \"0\"]",
             "\"normal\": [\"-1\", \"1\"]",
             "constraint 2 is not the one mode ss implies for fixel 2: "
             "expected (-1, 1, 1) . nu > 0, found (-1, 0, 0) . nu > 0",
             "ss", 1);
    TAMPERED(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"sl\"",
             "constraint 2 is not the one mode sl implies for fixel 2: "
             "expected (-1, 0, 0) . nu = 0, found (-1, 0, 0) . nu > 0",
             "sl", 1);
    TAMPERED(cert_ln, "\"feasible\": false", "\"feasible\": true, "
             "\"witness\": [\"0\", \"0\", \"-1\"]", "the witness (0, 0, -1) "
             "violates constraint 4: (0, -1, -1) . nu = 1, not = 0", "ln", 1);
    TAMPERED(cert_ss, "\"feasible\": true", "\"feasible\": false, "
             "\"multipliers\": [1, 1]", "the multipliers combine the rows to "
             "(-1, 1, 0), not to zero", "ss", 0);
    /* a near fixel's s is >= and its a is -J_n > */
    TAMPERED(cert_sss, "\"relation\": \">=\"", "\"relation\": \">\"",
             "constraint 2 is not the one mode sss implies for fixel 2: "
             "expected (0, 1, 1) . nu >= 0, found (0, 1, 1) . nu > 0", "sss",
             1);
    TAMPERED(cert_sss, "\"sss\"", "\"sas\"",
             "constraint 2 is not the one mode sas implies for fixel 2: "
             "expected (0, -1, -1) . nu > 0, found (0, 1, 1) . nu >= 0",
             "sas", 1);

    /* huge numbers: exact, and cut in the reason */
    big = repeat("9", 5000);
    t = xmalloc(2 * strlen(cert_ss) + 20000);
    sprintf(t, "[\"-%s\", \"1%s\", \"0/%s\"]", big, big, big);
    {
        char * u = subst(__LINE__, cert_ss, "[\"-1\", \"1\", \"0\"]", t);

        HOLDS(u, "ss", 1);
        free(u);
    }
    sprintf(t, "[\"0\", \"%s/7\", \"0\"]", big);
    {
        char * u = subst(__LINE__, cert_ss, "[\"-1\", \"1\", \"0\"]", t);

        verdict_is(__LINE__, u, "the witness (0, 9999999999999999999999999"
                   "999999999999999.../7, 0) violates constraint 2: (-1, 0, "
                   "0) . nu = 0, not > 0", "ss", 1);
        free(u);
    }
    /* multipliers scaled by a huge rational still prove infeasibility */
    sprintf(t, "[\"-%s/3\", \"%s/3\", \"-%s/3\", \"-%s/3\"]", big, big, big,
            big);
    {
        char * u = subst(__LINE__, cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]",
                         t);

        HOLDS(u, "ln", 0);
        free(u);
    }
    free(t);
    free(big);
}

#define MAL(text, expect) \
    malformed_n(__LINE__, text, sizeof(text) - 1, expect, 1)

static void
test_malformed(void)
{
    /* not JSON */
    MAL("", "c:1:1: unexpected end of input");
    MAL("{\"mode\": \"ss\",", "c:1:15: unexpected end of input");
    MAL("{\"mode\": \"ss\"} {}", "c:1:16: unexpected '{' after the JSON value");
    /* not a certificate */
    MAL("[]", "c:1:1: expected a certificate object, found an array");
    MAL("\"ss\"", "c:1:1: expected a certificate object, found a string");
    MAL("{}", "c:1:1: missing key 'mode'");
    MAL("{\"kind\": \"stability\", \"mode\": 1}",
        "c:1:10: unknown certificate kind 'stability'");
    MAL("{\"kind\": 7}", "c:1:10: 'kind' must be a string");
    BAD(cert_ss, "\"mode-feasibility\"", "\"mode-feasibility \"",
        "c:1:10: unknown certificate kind 'mode-feasibility '");
    BAD(cert_ss, "\"mode-feasibility\"", "\"mode-feasibility\\u0000\"",
        "c:1:10: unknown certificate kind 'mode-feasibility\\x00'");
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": [\"ss\"]",
        "c:1:38: 'mode' must be a string");
    BAD(cert_ss, "\"feasible\": true", "\"feasible\": 1",
        "c:1:56: 'feasible' must be true or false");
    BAD(cert_ss, "\"feasible\": true, ", "", "c:1:1: missing key 'feasible'");
    BAD(cert_ss, "\"witness\": [\"-1\", \"1\", \"0\"], ", "",
        "c:1:1: missing key 'witness'");
    BAD(cert_ln, "\"multipliers\": [\"-1\", \"1\", \"-1\", \"-1\"], ", "",
        "c:1:1: missing key 'multipliers'");
    BAD(cert_ss, "\"constraints\"", "\"constraint\"",
        "c:1:1: missing key 'constraints'");
    BAD(cert_ss, P5, "\"problem\": null", "c:1:206: 'problem' must be an "
        "object");
    BAD(cert_ss, ", " P5, "", "c:1:1: missing key 'problem'");
    BAD(cert_ss, "\"witness\": [\"-1\", \"1\", \"0\"]", "\"witness\": "
        "{\"x\": 1}", "c:1:73: 'witness' must be an array");
    BAD(cert_ss, "\"witness\": [\"-1\", \"1\", \"0\"]", "\"witness\": "
        "[\"-1\", \"1\"]", "c:1:73: 'witness' must have 3 entries, not 2");
    BAD(cert_ln, "\"multipliers\": [", "\"multipliers\": [[], ",
        "c:1:273: expected a rational, found an array");
    BAD(cert_ln, "[\"-1\", \"1\", \"-1\", \"-1\"]", "{\"-1\": 1}",
        "c:1:272: 'multipliers' must be an array");
    BAD(cert_ss, "\"constraints\": [", "\"constraints\": [\"x\", ",
        "c:1:107: expected an object, found a string");
    BAD(cert_ss, "\"constraints\": [", "\"constraints\": {}, \"c\": [",
        "c:1:106: 'constraints' must be an array");
    BAD(cert_ss, "{\"row\": [\"0\", \"1\", \"0\"], ", "{",
        "c:1:107: missing key 'row'");
    BAD(cert_ss, ", \"relation\": \">\"}, {", "}, {",
        "c:1:107: missing key 'relation'");
    BAD(cert_ss, "\"relation\": \">\"}]", "\"relation\": \"<\"}]",
        "c:1:188: unknown relation '<'");
    BAD(cert_ss, "\"relation\": \">\"}]", "\"relation\": \"> \"}]",
        "c:1:188: unknown relation '> '");
    BAD(cert_ss, "\"relation\": \">\"}]", "\"relation\": 1}]",
        "c:1:188: 'relation' must be a string");
    BAD(cert_ss, "{\"row\": [\"-1\", \"0\", \"0\"]", "{\"row\": [\"-1\", "
        "\"0\"]", "c:1:158: 'row' must have 3 entries, not 2");
    BAD(cert_ss, "{\"row\": [\"-1\", \"0\", \"0\"]", "{\"row\": \"-1 0 0\"",
        "c:1:158: 'row' must be an array");
    BAD(cert_ss, "\"com\": [\"0\", \"0\"]", "\"com\": [\"0\", \"0\", \"0\"]",
        "c:1:214: 'com' must have 2 entries, not 3");
    BAD(cert_ss, "\"com\": [\"0\", \"0\"], ", "",
        "c:1:206: missing key 'com'");
    BAD(cert_ss, "\"fixels\": [{", "\"fixels\": [], \"f\": [{",
        "c:1:236: no fixel in the problem");
    BAD(cert_ss, "\"fixels\": [{", "\"fixels\": {}, \"f\": [{",
        "c:1:236: 'fixels' must be an array");
    BAD(cert_ss, "\"fixels\": [{", "\"fixels\": [1, {",
        "c:1:237: expected an object, found a number");
    BAD(cert_ss, "\"point\": [\"0\", \"-1\"], ", "",
        "c:1:237: missing key 'point'");
    BAD(cert_ss, "\"normal\": [\"0\", \"1\"], ", "",
        "c:1:237: missing key 'normal'");
    BAD(cert_ss, "\"state\": \"touching\"}, ", "\"s\": 0}, ",
        "c:1:237: missing key 'state'");
    BAD(cert_ss, "\"state\": \"touching\"}, ", "\"state\": \"Touching\"}, ",
        "c:1:291: unknown fixel state 'Touching'");
    BAD(cert_ss, "\"state\": \"touching\"}, ", "\"state\": true}, ",
        "c:1:291: 'state' must be a string");
    BAD(cert_ss, "\"normal\": [\"-1\", \"0\"]", "\"normal\": [\"0\", \"-0\"]",
        "c:1:336: zero normal");
    BAD(cert_ss, "\"normal\": [\"-1\", \"0\"]", "\"normal\": [\"0/5\", 0]",
        "c:1:336: zero normal");
    BAD(cert_ss, "\"normal\": [\"-1\", \"0\"]", "\"normal\": [\"-1\"]",
        "c:1:336: 'normal' must have 2 entries, not 1");
    /* rationals */
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", 0.5, \"0\"]",
        "c:1:80: bad rational '0.5'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", 1.0, \"0\"]",
        "c:1:80: bad rational '1.0'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", 1e2, \"0\"]",
        "c:1:80: bad rational '1e2'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"0.5\", \"0\"]",
        "c:1:80: bad rational '0.5'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"1/0\", \"0\"]",
        "c:1:80: division by zero in '1/0'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"0/000\", \"0\"]",
        "c:1:80: division by zero in '0/000'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"1/-2\", \"0\"]",
        "c:1:80: bad rational '1/-2'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"+1\", \"0\"]",
        "c:1:80: bad rational '+1'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \" 1\", \"0\"]",
        "c:1:80: bad rational ' 1'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"1 \", \"0\"]",
        "c:1:80: bad rational '1 '");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"\", \"0\"]",
        "c:1:80: bad rational ''");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"-\", \"0\"]",
        "c:1:80: bad rational '-'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"1/\", \"0\"]",
        "c:1:80: bad rational '1/'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"/2\", \"0\"]",
        "c:1:80: bad rational '/2'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"1/2/3\", \"0\"]",
        "c:1:80: bad rational '1/2/3'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"0x10\", \"0\"]",
        "c:1:80: bad rational '0x10'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"1\\u0000\", \"0\"]",
        "c:1:80: bad rational '1\\x00'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", \"\\u0031\", \"x\"]",
        "c:1:90: bad rational 'x'");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", null, \"0\"]",
        "c:1:80: expected a rational, found null");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", true, \"0\"]",
        "c:1:80: expected a rational, found true");
    BAD(cert_ss, "[\"-1\", \"1\", \"0\"]", "[\"-1\", {}, \"0\"]",
        "c:1:80: expected a rational, found an object");
    /* the mode against the problem, with the messages of mode strings */
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"s\"",
        "c:1:38: mode has 1 letter; the problem has 2 fixels");
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"\"",
        "c:1:38: mode has 0 letters; the problem has 2 fixels");
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"sss\"",
        "c:1:38: mode has 3 letters; the problem has 2 fixels");
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"as\"",
        "c:1:38: letter 'a' not allowed on fixel 1, which is touching");
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"sx\"",
        "c:1:38: unknown mode letter 'x'");
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"sm\"",
        "c:1:38: unknown mode letter 'm'");
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"S\\u0000\"",
        "c:1:38: unknown mode letter 'S'");
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"s\\u0000\"",
        "c:1:38: unknown mode letter '\\x00'");
    BAD(cert_ss, "\"mode\": \"ss\"", "\"mode\": \"\xc3\xa9\"",
        "c:1:38: unknown mode letter '\\xc3'");
    BAD(cert_sss, "\"sss\"", "\"sls\"",
        "c:1:10: letter 'l' not allowed on fixel 2, which is near");
    BAD(cert_sss, "\"sss\"", "\"sns\"",
        "c:1:10: letter 'n' not allowed on fixel 2, which is near");
    BAD(cert_sss, "\"sss\"", "\"ssa\"",
        "c:1:10: letter 'a' not allowed on fixel 3, which is touching");
    /* the first error in file order wins */
    BAD(cert_ss, "\"witness\": [\"-1\", \"1\", \"0\"]", "\"witness\": "
        "[\"-1\", 1.5, \"0\"]", "c:1:80: bad rational '1.5'");
    {
        char * t = subst(__LINE__, cert_ss, "\"relation\": \">\"}]",
                         "\"relation\": \"<\"}]");

        /* constraints are read before the witness, yet the witness is
           reported: it comes first */
        BAD(t, "[\"-1\", \"1\", \"0\"]", "[\"-1\", 1.5, \"0\"]",
            "c:1:80: bad rational '1.5'");
        free(t);
    }
    BAD(cert_ss, "\"mode\": \"ss\", ", "\"mode\": \"s\", \"x\": [], ",
        "c:1:38: mode has 1 letter; the problem has 2 fixels");
    BAD(cert_ss, "\"state\": \"touching\"}]}", "\"state\": \"far\"}]}",
        "c:1:358: unknown fixel state 'far'");
    BAD(cert_ss, "{\"row\": [\"-1\", \"0\", \"0\"], \"relation\": \">\"}",
        "{\"relation\": \"<\", \"row\": [\"-1\", \"0\", 1.5]}",
        "c:1:163: unknown relation '<'");
    BAD(cert_ss, "{\"point\": [\"1\", \"0\"], \"normal\": [\"-1\", \"0\"], "
        "\"state\": \"touching\"}", "{\"state\": \"x\", \"normal\": [0, 0], "
        "\"point\": [1, 0]}", "c:1:314: unknown fixel state 'x'");
    BAD(cert_ss, "{\"kind\": \"mode-feasibility\", \"mode\": \"ss\"",
        "{\"mode\": \"x\", \"kind\": \"other\"",
        "c:1:23: unknown certificate kind 'other'");
    BAD(cert_ss, "\"feasible\": true", "\"feasible\": true, \"feasible\": 1",
        "c:1:62: duplicate key 'feasible'");
    MAL("{\n  \"mode\": \"ss\",\n  \"feasible\": true,\n  \"witness\": [0, 1,"
        " 0],\n  \"constraints\": [],\n  \"problem\": {\"com\": [0, 0], "
        "\"fixels\": [\n    {\"point\": [0, -1], \"normal\": [0, 0], "
        "\"state\": \"touching\"}]}\n}\n", "c:7:34: zero normal");
}

/* Every proper prefix of a certificate is malformed, and one-byte changes
   give a status of 0 or 1, never anything else, with the outputs set
   accordingly.  */
/* Each certificate cut short (before its trailing newlines) is malformed,
   with nothing else set; with one byte replaced by one of bytes it is
   malformed with a located message, or well formed with a verdict and the
   mode or summary.  A mode certificate (mode_cert) goes through
   run_verify, any other through run_wc_verify, as in malformed_n.  */
static void
fuzz_certs(const char * const * certs, size_t ncerts, const char * bytes,
           size_t nbytes, int mode_cert)
{
    size_t c, n, i, k;

    for (c = 0; c < ncerts; c++)
    {
        const char * cert = certs[c];
        char * t;
        size_t end;

        n = strlen(cert);
        for (end = n; end > 0 && cert[end - 1] == '\n'; end--)
            ;
        t = xmalloc(n + 1);
        for (i = 0; i < end; i++)
        {
            int holds, feas, status;
            char * why, * m, * msg;

            status = mode_cert
                ? run_verify(&holds, &why, &m, &feas, cert, i, &msg)
                : run_wc_verify(&holds, &why, &m, cert, i, &msg);
            if (status != WC_EINPUT || msg == NULL || why != NULL
                || m != NULL)
                FAIL("prefix of %lu bytes: status %d", (unsigned long) i,
                     status);
            free(msg);
        }
        for (i = 0; i < n; i++)
            for (k = 0; k < nbytes; k++)
            {
                int holds, feas, status;
                char * why, * m, * msg;

                memcpy(t, cert, n + 1);
                if (t[i] == bytes[k])
                    continue;
                t[i] = bytes[k];
                status = mode_cert
                    ? run_verify(&holds, &why, &m, &feas, t, n, &msg)
                    : run_wc_verify(&holds, &why, &m, t, n, &msg);
                if (status == WC_OK)
                {
                    if ((holds != 0 && holds != 1) || m == NULL
                        || (holds == 0) != (why != NULL) || msg != NULL)
                        FAIL("mutation at %lu: bad outputs",
                             (unsigned long) i);
                    free(why);
                    free(m);
                }
                else if (status != WC_EINPUT || msg == NULL
                         || strncmp(msg, "c:", 2) != 0)
                    FAIL("mutation at %lu: status %d (%s)", (unsigned long) i,
                         status, msg != NULL ? msg : "");
                free(msg);
            }
        free(t);
    }
}

static void
test_fuzz(void)
{
    static const char * const certs[] = { cert_ln, cert_sss };
    static const char bytes[] = { '\0', '"', '}', ']', '1', '-', '/', 'x',
                                  ',', '\\', (char) 0xff, '0', 'a', 's' };

    fuzz_certs(certs, 2, bytes, sizeof bytes, 1);
}

/* ------------------------------------------------------------------ */
/* Strong-stability certificates.                                      */

/* Figure 5's disk: unit mass and inertia, com (0, 0); fixel 1 at (0, -1)
   normal (0, 1), fixel 2 at (1, 0) normal (-1, 0); mu_s = mu_k = 1 (FIG5),
   fixel 2 near (FIG5N), mu_k = 1/2 (FIG5K).  J_1n = (0, 1, 0),
   J_1t = (-1, 0, -1), J_2n = (-1, 0, 0), J_2t = (0, -1, -1).  */
#define FIX1(mus, muk) "{\"point\": [\"0\", \"-1\"], \"normal\": [\"0\", " \
    "\"1\"], \"state\": \"touching\", \"mu_s\": \"" mus "\", \"mu_k\": \"" \
    muk "\"}"
#define FIX2(state, mus, muk) "{\"point\": [\"1\", \"0\"], \"normal\": " \
    "[\"-1\", \"0\"], \"state\": \"" state "\", \"mu_s\": \"" mus "\", " \
    "\"mu_k\": \"" muk "\"}"
#define BODY "\"problem\": {\"mass\": \"1\", \"inertia\": \"1\", \"com\": " \
    "[\"0\", \"0\"], \"fixels\": ["
#define FIG5 BODY FIX1("1", "1") ", " FIX2("touching", "1", "1") "]}"
#define FIG5N BODY FIX1("1", "1") ", " FIX2("near", "1", "1") "]}"
#define FIG5K BODY FIX1("1", "1/2") ", " FIX2("touching", "1", "1/2") "]}"

/* g = (0, -1, 0) on FIG5: weakly stable with c_1n = 1; strongly stable.
   The moving faces are Table 1's feasible modes but nn (the paper's reference results): ss sl sr
   sn ls rs ns ll rr.  Each face's multipliers are y (on the three
   equality rows, which read M nudot - sum lambda_j w_j - tau g = 0), then
   the fixel rows' (f), then y . w_j (the lambda rows), then y . g (the
   tau row): the sum vanishes when M y + sum f_k row_k = 0, that is
   y = -sum f_k row_k (M = I), with y . w_j >= 0, y . g >= 0, f >= 0 on
   the > rows and some > multiplier positive.  y . g = -y_2.
     ss: rows J_1n >, J_2n >.  f = (1, 0): y = (0, -1, 0), y . g = 1.
     sl: J_1n >, J_2n =, J_2t >; w = J_2n - J_2t = (-1, 1, 1).
         f = (1, -1, 0): y = (-1, -1, 0), y . w = 0, y . g = 1.
     sr: J_1n >, J_2n =, -J_2t >; w = J_2n + J_2t = (-1, -1, -1).
         f = (1, 0, 0): y = (0, -1, 0), y . w = 1, y . g = 1.
     sn: J_1n >, J_2n =, J_2t =; w = (-1, 1, 1), (-1, -1, -1).
         f = (1, -1, 0): y = (-1, -1, 0), y . w = 0, 2; y . g = 1.
     ls: J_1n =, J_1t >, J_2n >; w = J_1n - J_1t = (1, 1, 1).
         f = (1, 0, 1): y = (1, -1, 0), y . w = 0, y . g = 1.
     rs: J_1n =, -J_1t >, J_2n >; w = J_1n + J_1t = (-1, 1, -1).
         f = (1, 1, 0): y = (-1, -1, -1), y . w = 1, y . g = 1.
     ns: J_1n =, J_1t =, J_2n >; w = (1, 1, 1), (-1, 1, -1).  Adding
         the two edge conditions forces y . g = 0, so the strict row is
         J_2n's: f = (0, -1, 2): y = (1, 0, -1), y . w = 0, 0, y . g = 0.
     ll: J_1n =, J_1t >, J_2n =, J_2t >; w = (1, 1, 1), (-1, 1, 1).
         f = (2, 0, 0, 1): y = (0, -1, 1), y . w = 0, 0, y . g = 1.
     rr: J_1n =, -J_1t >, J_2n =, -J_2t >; w = (-1, 1, -1), (-1, -1, -1).
         f = (1, 1, 0, 0): y = (-1, -1, -1), y . w = 1, 3, y . g = 1.  */
static const char stab_strong[] =
    "{\"kind\": \"strong-stability\", " FIG5 ", \"wrench\": [\"0\", \"-1\", "
    "\"0\"], \"weakly_stable\": true, \"weak\": {\"c\": [\"1\", \"0\", \"0\", "
    "\"0\"]}, \"strongly_stable\": true, \"faces\": ["
    "{\"sign\": \"ss\", \"multipliers\": [0, -1, 0, 1, 0, 1]}, "
    "{\"sign\": \"sl\", \"multipliers\": [-1, -1, 0, 1, -1, 0, 0, 1]}, "
    "{\"sign\": \"sr\", \"multipliers\": [0, -1, 0, 1, 0, 0, 1, 1]}, "
    "{\"sign\": \"sn\", \"multipliers\": [-1, -1, 0, 1, -1, 0, 0, 2, 1]}, "
    "{\"sign\": \"ls\", \"multipliers\": [1, -1, 0, 1, 0, 1, 0, 1]}, "
    "{\"sign\": \"rs\", \"multipliers\": [-1, -1, -1, 1, 1, 0, 1, 1]}, "
    "{\"sign\": \"ns\", \"multipliers\": [1, 0, -1, 0, -1, 2, 0, 0, 0]}, "
    "{\"sign\": \"ll\", \"multipliers\": [0, -1, 1, 2, 0, 0, 1, 0, 0, 1]}, "
    "{\"sign\": \"rr\", \"multipliers\": [-1, -1, -1, 1, 1, 0, 0, 1, 3, 1]}"
    "]}\n";

/* g = (0, -1, 0) on FIG5N: one touching fixel, so its point is shared:
   faces su, lu, ru and the rotations about (0, -1), v = J_1n x J_1t =
   (-1, 0, 1).
     su: J_1n >.  f = (1): y = (0, -1, 0), y . g = 1.
     lu: J_1n =, J_1t >; w = (1, 1, 1).  f = (2, 1): y = (1, -2, 1),
         y . w = 0, y . g = 2.
     ru: J_1n =, -J_1t >; w = (-1, 1, -1).  f = (2, 1): y = (-1, -2, -1),
         y . w = 0, y . g = 2.
     nu, rotation rho: J_1n =, J_1t =, rho v >; w = (1, 1, 1),
         (-1, 1, -1).  f = (0, 0, 1): y = -rho v = rho (1, 0, -1),
         y . w = 0, 0, y . g = 0.  */
static const char stab_rotation[] =
    "{\"kind\": \"strong-stability\", " FIG5N ", \"wrench\": [\"0\", \"-1\", "
    "\"0\"], \"weakly_stable\": true, \"weak\": {\"c\": [\"1\", \"0\", \"0\", "
    "\"0\"]}, \"strongly_stable\": true, \"faces\": ["
    "{\"sign\": \"su\", \"multipliers\": [0, -1, 0, 1, 1]}, "
    "{\"sign\": \"lu\", \"multipliers\": [1, -2, 1, 2, 1, 0, 2]}, "
    "{\"sign\": \"ru\", \"multipliers\": [-1, -2, -1, 2, 1, 0, 2]}, "
    "{\"sign\": \"nu\", \"rotation\": 1, \"multipliers\": [1, 0, -1, 0, 0, 1, "
    "0, 0, 0]}, "
    "{\"sign\": \"nu\", \"rotation\": -1, \"multipliers\": [-1, 0, 1, 0, 0, 1, "
    "0, 0, 0]}]}";

/* g = (0, 1, 0) on FIG5N pulls the disk off fixel 1: y = (0, 1, 0) has
   y . g = 1, y . (J_1n -+ J_1t) = y . (1, 1, 1), y . (-1, 1, -1) = 1.  */
static const char stab_separator[] =
    "{\"kind\": \"strong-stability\", " FIG5N ", \"wrench\": [\"0\", \"1\", "
    "\"0\"], \"weakly_stable\": false, \"weak\": {\"separator\": [\"0\", "
    "\"1\", \"0\"]}, \"strongly_stable\": false}";

/* g = (-1, -1, -1) on FIG5K: held by fixel 1 at the edge of its static
   friction cone, c = (1, 0, -1, 0): -J c = -(0, 1, 0) + (-1, 0, -1).  It
   also slides left on fixel 1 and leaves fixel 2: nudot = (-1/2, 0, -1/2)
   has a_1n = 0, a_1t = 1, a_2n = 1/2; c_1n = 1, c_1t = -mu_k c_1n = -1/2,
   and J c + g = (1/2, 1, 1/2) + g = nudot = M nudot.  */
static const char stab_motion[] =
    "{\"kind\": \"strong-stability\", " FIG5K ", \"wrench\": [\"-1\", \"-1\", "
    "\"-1\"], \"weakly_stable\": true, \"weak\": {\"c\": [\"1\", \"0\", "
    "\"-1\", \"0\"]}, \"strongly_stable\": false, \"motion\": {\"sign\": "
    "\"ls\", \"nudot\": [\"-1/2\", \"0\", \"-1/2\"], \"c\": [\"1\", \"0\", "
    "\"-1/2\", \"0\"]}}";

#define SUM_STRONG "wrench (0, -1, 0) is strongly stable: 9 moving faces " \
    "excluded"
#define SUM_ROTATION "wrench (0, -1, 0) is strongly stable: 5 moving faces " \
    "excluded"
#define SUM_SEPARATOR "wrench (0, 1, 0) is not weakly stable"
#define SUM_MOTION "wrench (-1, -1, -1) is weakly stable but moves in mode ls"

/* wc_verify on text: it holds (reason NULL) or not for the reason given,
   and its summary is summary.  */
static void
stab_verdict_is(int line, const char * text, const char * reason,
                const char * summary)
{
    int holds = -1, status;
    char * why = NULL, * sum = NULL, * msg = NULL;

    status = run_wc_verify(&holds, &why, &sum, text, strlen(text), &msg);
    if (verdict_as(line, status, holds, why, msg, reason)
        && (sum == NULL || strcmp(sum, summary) != 0))
        fail(line, "summary '%s', expected '%s'", sum != NULL ? sum
             : "(none)", summary);
    free(why);
    free(sum);
    free(msg);
}

#define SHOLDS(text, summary) \
    stab_verdict_is(__LINE__, text, NULL, summary)

static void
stab_tampered_n(int line, const char * base, const char * old,
                const char * new, const char * reason, const char * summary)
{
    char * t = subst(line, base, old, new);

    stab_verdict_is(line, t, reason, summary);
    free(t);
}

#define STAMPERED(base, old, new, reason, summary) \
    stab_tampered_n(__LINE__, base, old, new, reason, summary)

#define SBAD(base, old, new, expect) \
    bad_edit_n(__LINE__, base, old, new, expect, 0)
#define SMAL(text, expect) \
    malformed_n(__LINE__, text, sizeof(text) - 1, expect, 0)

static void
test_stability_good(void)
{
    char * t, * u;

    SHOLDS(stab_strong, SUM_STRONG);
    SHOLDS(stab_rotation, SUM_ROTATION);
    SHOLDS(stab_separator, SUM_SEPARATOR);
    SHOLDS(stab_motion, SUM_MOTION);
    /* the faces in another order; multipliers scaled; other spellings of
       the numbers; unknown keys; the keys of a face in another order */
    t = subst(__LINE__, stab_strong, "{\"sign\": \"ss\", \"multipliers\": "
              "[0, -1, 0, 1, 0, 1]}, ", "");
    u = subst(__LINE__, t, "]}\n", ", {\"multipliers\": [\"0\", \"-7/3\", "
              "-0, \"14/6\", \"0/5\", \"7/3\"], \"sign\": \"ss\", \"x\": "
              "null}]}\n");
    SHOLDS(u, SUM_STRONG);
    free(t);
    free(u);
    t = subst(__LINE__, stab_motion, "\"mu_k\": \"1/2\"}]}", "\"mu_k\": "
              "\"2/4\"}], \"note\": [1]}, \"version\": 7");
    SHOLDS(t, SUM_MOTION);
    free(t);
    /* the static forces are not unique: here fixel 2 carries some of
       the load, at the edge of its friction cone (c_2t = c_2n) */
    t = subst(__LINE__, stab_strong, "{\"c\": [\"1\", \"0\", \"0\", \"0\"]}",
              "{\"c\": [\"3/2\", \"1/2\", \"-1/2\", \"1/2\"]}");
    SHOLDS(t, SUM_STRONG);
    free(t);
    t = subst(__LINE__, stab_rotation, "\"rotation\": -1",
              "\"rotation\": \"-2/2\"");
    SHOLDS(t, SUM_ROTATION);
    free(t);
    /* a separator for a wrench with only near fixels: y = g */
    SHOLDS("{\"kind\": \"strong-stability\", \"problem\": {\"mass\": 2, "
           "\"inertia\": 3, \"com\": [0, 0], \"fixels\": [" FIX2("near", "1",
           "1") "]}, \"wrench\": [1, 0, \"-1/2\"], \"weakly_stable\": false, "
           "\"weak\": {\"separator\": [1, 0, \"-1/2\"]}, \"strongly_stable\":"
           " false}", "wrench (1, 0, -1/2) is not weakly stable");
    /* no touching fixel: the zero wrench is strongly stable, no face */
    SHOLDS("{\"kind\": \"strong-stability\", \"problem\": {\"mass\": 2, "
           "\"inertia\": 3, \"com\": [0, 0], \"fixels\": [" FIX2("near", "1",
           "1") "]}, \"wrench\": [0, 0, 0], \"weakly_stable\": true, "
           "\"weak\": {\"c\": [0, 0]}, \"strongly_stable\": true, \"faces\": "
           "[]}", "wrench (0, 0, 0) is strongly stable: 0 moving faces "
           "excluded");
    /* a frictionless body tipping over: one fixel at (1, -1) from com
       (0, 0), normal (0, 1), mu = 0; J_1n = (0, 1, 1), so no force holds
       g = (0, -1, 0) without a torque; y = (0, -1, 1) has y . g = 1 and
       y . J_1n = 0, and with mu_s = 0 both edges are J_1n */
    SHOLDS("{\"kind\": \"strong-stability\", \"problem\": {\"mass\": 1, "
           "\"inertia\": 1, \"com\": [0, 0], \"fixels\": [{\"point\": [1, -1],"
           " \"normal\": [0, 1], \"state\": \"touching\", \"mu_s\": 0, "
           "\"mu_k\": 0}]}, \"wrench\": [0, -1, 0], \"weakly_stable\": false, "
           "\"weak\": {\"separator\": [0, -1, 1]}, \"strongly_stable\": "
           "false}", "wrench (0, -1, 0) is not weakly stable");
    /* mode-feasibility certificates through wc_verify */
    SHOLDS(cert_ln, "mode ln is infeasible");
    SHOLDS(cert_sss, "mode sss is feasible");
}

static void
test_stability_tampered(void)
{
    /* the weak claim */
    STAMPERED(stab_strong, "{\"c\": [\"1\", \"0\", \"0\", \"0\"]}",
              "{\"c\": [\"2\", \"0\", \"0\", \"0\"]}", "the static forces "
              "give -J c = (0, -2, 0), not the wrench (0, -1, 0)",
              SUM_STRONG);
    STAMPERED(stab_strong, "{\"c\": [\"1\", \"0\", \"0\", \"0\"]}",
              "{\"c\": [\"1\", \"0\", \"2\", \"0\"]}", "the static force at "
              "fixel 1 leaves its friction cone: |c_1t| = 2 > mu_s c_1n = 1",
              SUM_STRONG);
    STAMPERED(stab_strong, "{\"c\": [\"1\", \"0\", \"0\", \"0\"]}",
              "{\"c\": [\"1\", \"-1\", \"0\", \"0\"]}", "the static force "
              "c_2n = -1 is negative", SUM_STRONG);
    STAMPERED(stab_rotation, "{\"c\": [\"1\", \"0\", \"0\", \"0\"]}",
              "{\"c\": [\"1\", \"0\", \"0\", \"1/3\"]}", "the static forces "
              "load fixel 2, which is near: c_2n = 0, c_2t = 1/3",
              SUM_ROTATION);
    STAMPERED(stab_separator, "{\"separator\": [\"0\", \"1\", \"0\"]}",
              "{\"separator\": [\"1\", \"0\", \"0\"]}", "the separator y = "
              "(1, 0, 0) has y . g = 0, not > 0", SUM_SEPARATOR);
    STAMPERED(stab_separator, "{\"separator\": [\"0\", \"1\", \"0\"]}",
              "{\"separator\": [\"0\", \"1\", \"2\"]}", "the separator y = "
              "(0, 1, 2) has y . (J_1n + mu_s J_1t) = -1, not >= 0",
              SUM_SEPARATOR);
    STAMPERED(stab_separator, "{\"separator\": [\"0\", \"1\", \"0\"]}",
              "{\"separator\": [\"0\", \"1\", \"-2\"]}", "the separator y = "
              "(0, 1, -2) has y . (J_1n - mu_s J_1t) = -1, not >= 0",
              SUM_SEPARATOR);
    /* a weakly stable wrench claimed not to be */
    STAMPERED(stab_separator, "[\"0\", \"1\", \"0\"], \"weakly_stable\"",
              "[\"0\", \"-1\", \"0\"], \"weakly_stable\"", "the separator y = "
              "(0, 1, 0) has y . g = -1, not > 0",
              "wrench (0, -1, 0) is not weakly stable");
    /* the separator must also face the friction cone at fixel 2 once it
       touches: y . (J_2n -+ J_2t) = y . (-1, 1, 1), y . (-1, -1, -1) */
    STAMPERED(stab_separator, FIG5N, FIG5, "the separator y = (0, 1, 0) "
              "has y . (J_2n + mu_s J_2t) = -1, not >= 0", SUM_SEPARATOR);
    STAMPERED(stab_separator, "\"strongly_stable\": false",
              "\"strongly_stable\": true, \"faces\": []",
              "strongly_stable is true but weakly_stable is false",
              "wrench (0, 1, 0) is strongly stable: 0 moving faces "
              "excluded");

    /* the motion */
    STAMPERED(stab_motion, "\"nudot\": [\"-1/2\", \"0\", \"-1/2\"]",
              "\"nudot\": [\"-1/2\", \"0\", \"1/2\"]", "the motion has "
              "M nudot = (-1/2, 0, 1/2), but J c + g = (-1/2, 0, -1/2)",
              SUM_MOTION);
    STAMPERED(stab_motion, "\"nudot\": [\"-1/2\", \"0\", \"-1/2\"]",
              "\"nudot\": [0, 0, 0]", "the motion has nudot = 0",
              SUM_MOTION);
    STAMPERED(stab_motion, "\"sign\": \"ls\"", "\"sign\": \"ss\"",
              "the motion's letter s at fixel 1 needs a_1n > 0, but a_1n = 0",
              "wrench (-1, -1, -1) is weakly stable but moves in mode ss");
    STAMPERED(stab_motion, "\"sign\": \"ls\"", "\"sign\": \"rs\"",
              "the motion's letter r at fixel 1 needs a_1t < 0, but a_1t = 1",
              "wrench (-1, -1, -1) is weakly stable but moves in mode rs");
    STAMPERED(stab_motion, "\"sign\": \"ls\"", "\"sign\": \"ns\"",
              "the motion's letter n at fixel 1 needs a_1t = 0, but a_1t = 1",
              "wrench (-1, -1, -1) is weakly stable but moves in mode ns");
    STAMPERED(stab_motion, "\"sign\": \"ls\"", "\"sign\": \"ll\"",
              "the motion's letter l at fixel 2 needs a_2n = 0, but "
              "a_2n = 1/2",
              "wrench (-1, -1, -1) is weakly stable but moves in mode ll");
    /* kinetic friction is not static friction */
    STAMPERED(stab_motion, FIG5K, FIG5, "the motion's letter l at fixel 1 "
              "needs c_1t = -mu_k c_1n = -1, but c_1t = -1/2", SUM_MOTION);
    /* a strongly stable wrench has no motion */
    STAMPERED(stab_strong, "\"strongly_stable\": true",
              "\"strongly_stable\": false, \"motion\": {\"sign\": \"ss\", "
              "\"nudot\": [0, -1, 0], \"c\": [0, 0, 0, 0]}",
              "the motion's letter s at fixel 1 needs a_1n > 0, but a_1n = -1",
              "wrench (0, -1, 0) is weakly stable but moves in mode ss");

    /* the faces: complete, each once */
    STAMPERED(stab_strong, ", {\"sign\": \"rr\", \"multipliers\": [-1, -1, "
              "-1, 1, 1, 0, 0, 1, 3, 1]}", "", "the faces omit the moving "
              "face rr", "wrench (0, -1, 0) is strongly stable: 8 moving "
              "faces excluded");
    STAMPERED(stab_strong, "]}\n", ", {\"sign\": \"ss\", \"multipliers\": "
              "[0, -1, 0, 1, 0, 1]}]}\n", "face 10 (ss) repeats face 1",
              "wrench (0, -1, 0) is strongly stable: 10 moving faces "
              "excluded");
    STAMPERED(stab_strong, "\"sign\": \"sl\"", "\"sign\": \"ln\"",
              "face 2 (ln) is not a moving face of the problem", SUM_STRONG);
    STAMPERED(stab_strong, "\"sign\": \"ns\"", "\"sign\": \"ss\"",
              "face 7 (ss) repeats face 1", SUM_STRONG);
    STAMPERED(stab_strong, "]}\n", ", {\"sign\": \"nn\", \"multipliers\": "
              "[]}]}\n", "face 10 (nn) is not a moving face of the problem",
              "wrench (0, -1, 0) is strongly stable: 10 moving faces "
              "excluded");
    STAMPERED(stab_strong, "]}\n", ", {\"sign\": \"nn\", \"rotation\": 1, "
              "\"multipliers\": []}]}\n", "face 10 (nn, rotation 1) is not a "
              "moving face: the touching fixels do not share one point",
              "wrench (0, -1, 0) is strongly stable: 10 moving faces "
              "excluded");
    STAMPERED(stab_rotation, ", {\"sign\": \"nu\", \"rotation\": -1, "
              "\"multipliers\": [-1, 0, 1, 0, 0, 1, 0, 0, 0]}", "",
              "the faces omit the moving face nu, rotation -1",
              "wrench (0, -1, 0) is strongly stable: 4 moving faces "
              "excluded");
    STAMPERED(stab_rotation, "\"rotation\": -1", "\"rotation\": 1",
              "face 5 (nu, rotation 1) repeats face 4", SUM_ROTATION);
    STAMPERED(stab_rotation, "\"rotation\": -1, ", "",
              "face 5 (nu) is not a moving face of the problem",
              SUM_ROTATION);
    STAMPERED(stab_rotation, "\"rotation\": -1", "\"rotation\": \"2/2\"",
              "face 5 (nu, rotation 1) repeats face 4", SUM_ROTATION);

    /* the multipliers */
    STAMPERED(stab_strong, "[0, -1, 0, 1, 0, 1]", "[0, -1, 0, 1, 0, 2]",
              "face 1 (ss): the multipliers combine the rows to (0, 0, 0, 1),"
              " not to zero", SUM_STRONG);
    STAMPERED(stab_strong, "[-1, -1, 0, 1, -1, 0, 0, 2, 1]",
              "[-1, -1, 0, 1, -1, 0, 0, 2, 1, 0]", "face 4 (sn): there are 10 "
              "multipliers for 9 rows", SUM_STRONG);
    STAMPERED(stab_strong, "[-1, -1, 0, 1, -1, 0, 0, 2, 1]",
              "[-1, -1, 0, 1, -1, 0, 0, 2]", "face 4 (sn): there are 8 "
              "multipliers for 9 rows", SUM_STRONG);
    STAMPERED(stab_strong, "[0, -1, 0, 1, 0, 1]", "[0]", "face 1 (ss): "
              "there is 1 multiplier for 6 rows", SUM_STRONG);
    STAMPERED(stab_strong, "[0, -1, 0, 1, 0, 1]", "[0, 1, 0, -1, 0, -1]",
              "face 1 (ss): multiplier 4 is -1, negative on a '>' row",
              SUM_STRONG);
    STAMPERED(stab_strong, "[-1, -1, -1, 1, 1, 0, 0, 1, 3, 1]",
              "[-1, -1, -1, 1, 1, 0, 0, -1, 5, 1]", "face 9 (rr): multiplier "
              "8 is -1, negative on a '>=' row", SUM_STRONG);
    STAMPERED(stab_strong, "[0, -1, 0, 1, 0, 1]", "[0, 0, 0, 0, 0, 0]",
              "face 1 (ss): no '>' row has a positive multiplier",
              SUM_STRONG);
    /* an equality row's multiplier may be negative; its row must be the
       one the letter says: sl's J_2t > becomes -J_2t > under sr */
    STAMPERED(stab_strong, "{\"sign\": \"sl\", \"multipliers\": [-1, -1, 0, "
              "1, -1, 0, 0, 1]}, {\"sign\": \"sr\", \"multipliers\": [0, -1, "
              "0, 1, 0, 0, 1, 1]}", "{\"sign\": \"sl\", \"multipliers\": [0, "
              "-1, 0, 1, 0, 0, 1, 1]}, {\"sign\": \"sr\", \"multipliers\": "
              "[-1, -1, 0, 1, -1, 0, 0, 1]}", "face 2 (sl): the multipliers "
              "combine the rows to (0, 0, 0, 2, 0), not to zero",
              SUM_STRONG);
    /* the multipliers are those of one wrench: g = (1, -1, 0), held by
       c = (1, 1, 0, 0), keeps ss's y . g = 1 but makes sl's y . g = 0,
       and its tau row's multiplier 1 is left over */
    {
        char * t = subst(__LINE__, stab_strong, "\"wrench\": [\"0\", "
                         "\"-1\", \"0\"]", "\"wrench\": [1, -1, 0]");

        STAMPERED(t, "{\"c\": [\"1\", \"0\", \"0\", \"0\"]}",
                  "{\"c\": [1, 1, 0, 0]}", "face 2 (sl): the multipliers "
                  "combine the rows to (0, 0, 0, 0, 1), not to zero",
                  "wrench (1, -1, 0) is strongly stable: 9 moving faces "
                  "excluded");
        free(t);
    }
    STAMPERED(stab_rotation, "[1, 0, -1, 0, 0, 1, 0, 0, 0]",
              "[-1, 0, 1, 0, 0, 1, 0, 0, 0]", "face 4 (nu, rotation 1): the "
              "multipliers combine the rows to (-2, 0, 2, 0, 0, 0), not to "
              "zero", SUM_ROTATION);
    /* the problem: mass and inertia scale M (the equality rows) */
    STAMPERED(stab_strong, "\"mass\": \"1\"", "\"mass\": \"2\"",
              "face 1 (ss): the multipliers combine the rows to (0, -1, 0, 0),"
              " not to zero", SUM_STRONG);
    STAMPERED(stab_motion, "\"inertia\": \"1\"", "\"inertia\": \"3\"",
              "the motion has M nudot = (-1/2, 0, -3/2), but J c + g = "
              "(-1/2, 0, -1/2)", SUM_MOTION);
}

static void
test_stability_malformed(void)
{
    /* the kind */
    SMAL("{\"kind\": \"strong stability\"}",
         "c:1:10: unknown certificate kind 'strong stability'");
    SMAL("{\"kind\": \"strong-stability\"}", "c:1:1: missing key 'problem'");
    SMAL("{\"kind\": [\"strong-stability\"]}",
         "c:1:10: 'kind' must be a string");
    SMAL("[]", "c:1:1: expected a certificate object, found an array");
    {
        int holds = -1, feas = -1, status;
        char * why = NULL, * m = NULL;
        wc_error_t e;
        char * msg;

        wc_error_init(e);
        status = wc_verify_certificate(&holds, &why, &m, &feas, stab_strong,
                                       strlen(stab_strong), "c", e);
        msg = wc_error_format(e);
        if (status != WC_EINPUT || strcmp(msg, "c:1:10: expected a "
                                          "mode-feasibility certificate, "
                                          "found kind 'strong-stability'")
            != 0 || why != NULL || m != NULL || holds != 0)
            FAIL("wc_verify_certificate on strong-stability: %d, %s",
                 status, msg);
        free(msg);
        wc_error_clear(e);
    }
    /* the problem */
    SBAD(stab_strong, "\"mass\": \"1\"", "\"mass\": \"0\"",
         "c:1:50: 'mass' must be positive");
    SBAD(stab_strong, "\"mass\": \"1\"", "\"mass\": -1",
         "c:1:50: 'mass' must be positive");
    SBAD(stab_strong, "\"inertia\": \"1\"", "\"inertia\": \"-1/2\"",
         "c:1:66: 'inertia' must be positive");
    SBAD(stab_strong, "\"mass\": \"1\", ", "", "c:1:41: missing key 'mass'");
    SBAD(stab_strong, "\"inertia\": \"1\", ", "",
         "c:1:41: missing key 'inertia'");
    SBAD(stab_strong, "\"mass\": \"1\"", "\"mass\": \"1.5\"",
         "c:1:50: bad rational '1.5'");
    SBAD(stab_strong, "\"mu_s\": \"1\"", "\"mu_s\": \"-1\"",
         "c:1:175: 'mu_s' must not be negative");
    SBAD(stab_strong, "\"mu_s\": \"1\", \"mu_k\": \"1\"}]}",
         "\"mu_s\": \"1\", \"mu_k\": \"-1/3\"}]}",
         "c:1:281: 'mu_k' must not be negative");
    SBAD(stab_strong, ", \"mu_k\": \"1\"}, ", "}, ",
         "c:1:101: missing key 'mu_k'");
    SBAD(stab_strong, "\"normal\": [\"0\", \"1\"]", "\"normal\": [0, \"0/3\"]",
         "c:1:134: zero normal");
    SBAD(stab_strong, "\"state\": \"touching\"", "\"state\": \"Touching\"",
         "c:1:155: unknown fixel state 'Touching'");
    SBAD(stab_strong, "\"fixels\": [{", "\"fixels\": [], \"x\": [{",
         "c:1:100: no fixel in the problem");
    SBAD(stab_strong, "\"com\": [\"0\", \"0\"]", "\"com\": [\"0\"]",
         "c:1:78: 'com' must have 2 entries, not 1");
    /* the claims */
    SBAD(stab_strong, "\"wrench\": [\"0\", \"-1\", \"0\"]",
         "\"wrench\": [\"0\", \"-1\"]", "c:1:299: 'wrench' must have 3 "
         "entries, not 2");
    SBAD(stab_strong, "\"weakly_stable\": true", "\"weakly_stable\": 1",
         "c:1:334: 'weakly_stable' must be true or false");
    SBAD(stab_strong, "\"strongly_stable\": true", "\"strongly_stable\": "
         "\"yes\"", "c:1:396: 'strongly_stable' must be true or false");
    SBAD(stab_strong, "\"weak\": {\"c\"", "\"weak\": {\"x\"",
         "c:1:348: missing key 'c'");
    SBAD(stab_strong, "\"weak\": {\"c\": [\"1\", \"0\", \"0\", \"0\"]}",
         "\"weak\": [\"1\", \"0\", \"0\", \"0\"]",
         "c:1:348: 'weak' must be an object");
    SBAD(stab_strong, "{\"c\": [\"1\", \"0\", \"0\", \"0\"]}",
         "{\"c\": [\"1\", \"0\", \"0\"]}",
         "c:1:354: 'c' must have 4 entries, not 3");
    SBAD(stab_separator, "{\"separator\": [\"0\", \"1\", \"0\"]}",
         "{\"separator\": [\"0\", \"1\", \"0/0\"]}",
         "c:1:369: division by zero in '0/0'");
    SBAD(stab_separator, "{\"separator\": [\"0\", \"1\", \"0\"]}",
         "{\"c\": [\"0\", \"1\", \"0\"]}",
         "c:1:344: missing key 'separator'");
    SBAD(stab_strong, "\"faces\": [", "\"face\": [",
         "c:1:1: missing key 'faces'");
    SBAD(stab_strong, "\"faces\": [", "\"faces\": {}, \"f\": [",
         "c:1:411: 'faces' must be an array");
    SBAD(stab_strong, "\"faces\": [", "\"faces\": [\"ss\", ",
         "c:1:412: expected an object, found a string");
    SBAD(stab_strong, "{\"sign\": \"ss\", ", "{",
         "c:1:412: missing key 'sign'");
    SBAD(stab_strong, "{\"sign\": \"ss\", \"multipliers\": [0, -1, 0, 1, 0, "
         "1]}", "{\"sign\": \"ss\"}", "c:1:412: missing key 'multipliers'");
    SBAD(stab_strong, "[0, -1, 0, 1, 0, 1]", "[0, -1, 0, 1, 0, 1.0]",
         "c:1:459: bad rational '1.0'");
    SBAD(stab_strong, "[0, -1, 0, 1, 0, 1]", "\"0 -1 0 1 0 1\"",
         "c:1:442: 'multipliers' must be an array");
    /* the signs */
    SBAD(stab_strong, "\"sign\": \"sl\"", "\"sign\": \"slr\"",
         "c:1:473: sign has 3 letters; the problem has 2 fixels");
    SBAD(stab_strong, "\"sign\": \"sl\"", "\"sign\": \"sx\"",
         "c:1:473: unknown sign letter 'x'");
    SBAD(stab_strong, "\"sign\": \"sl\"", "\"sign\": \"s\\u0000\"",
         "c:1:473: unknown sign letter '\\x00'");
    SBAD(stab_strong, "\"sign\": \"sl\"", "\"sign\": \"su\"",
         "c:1:473: letter 'u' not allowed on fixel 2, which is touching");
    SBAD(stab_strong, "\"sign\": \"sl\"", "\"sign\": \"sa\"",
         "c:1:473: unknown sign letter 'a'");
    SBAD(stab_rotation, "\"sign\": \"lu\"", "\"sign\": \"ll\"",
         "c:1:466: letter 'l' not allowed on fixel 2, which is near");
    SBAD(stab_motion, "\"sign\": \"ls\"", "\"sign\": \"LS\"",
         "c:1:429: unknown sign letter 'L'");
    SBAD(stab_motion, "\"motion\": {", "\"motion\": {\"x\": 1}, \"y\": {",
         "c:1:420: missing key 'sign'");
    SBAD(stab_motion, "\"nudot\": [\"-1/2\", \"0\", \"-1/2\"]", "\"nudot\": "
         "[\"-1/2\", \"0\"]", "c:1:444: 'nudot' must have 3 entries, not 2");
    SBAD(stab_motion, ", \"motion\": {", ", \"m\": {",
         "c:1:1: missing key 'motion'");
    /* rotation */
    SBAD(stab_rotation, "\"rotation\": -1", "\"rotation\": -2",
         "c:1:672: 'rotation' must be 1 or -1");
    SBAD(stab_rotation, "\"rotation\": -1", "\"rotation\": \"1/2\"",
         "c:1:672: 'rotation' must be 1 or -1");
    SBAD(stab_rotation, "\"rotation\": -1", "\"rotation\": true",
         "c:1:672: expected a rational, found true");
    SBAD(stab_rotation, "{\"sign\": \"su\", \"multipliers\"",
         "{\"sign\": \"su\", \"rotation\": 1, \"multipliers\"",
         "c:1:435: a rotation face has the sign n..n");
    /* the first error in file order wins */
    SBAD(stab_strong, "\"mass\": \"1\", \"inertia\": \"1\"",
         "\"mass\": \"0\", \"inertia\": \"x\"",
         "c:1:50: 'mass' must be positive");
    SBAD(stab_strong, "\"mass\": \"1\", \"inertia\": \"1\"",
         "\"inertia\": \"x\", \"mass\": \"0\"",
         "c:1:53: bad rational 'x'");
    {
        /* a face error before a problem error: the face comes first */
        char * t = subst(__LINE__, stab_strong, "\"faces\": [",
                         "\"faces0\": [");
        char * u = subst(__LINE__, t, "\"kind\": \"strong-stability\", ",
                         "\"kind\": \"strong-stability\", \"faces\": "
                         "[{\"sign\": \"qs\", \"multipliers\": []}], ");

        SBAD(u, "\"mass\": \"1\"", "\"mass\": \"0\"",
             "c:1:49: unknown sign letter 'q'");
        free(t);
        free(u);
    }
    SMAL("{\n  \"kind\": \"strong-stability\",\n  \"wrench\": [0, 0, 0],\n"
         "  \"problem\": {\"mass\": 1, \"inertia\": 1, \"com\": [0, 0],\n"
         "    \"fixels\": [{\"point\": [0, 0], \"normal\": [1, 0],\n"
         "      \"state\": \"touching\", \"mu_s\": 0, \"mu_k\": \"-0/1\"},\n"
         "     {\"point\": [0, 0], \"normal\": [1, 0], \"state\": \"near\", "
         "\"mu_s\": 0, \"mu_k\": -1}]},\n"
         "  \"weakly_stable\": true, \"weak\": {\"c\": [0, 0, 0]},\n"
         "  \"strongly_stable\": true, \"faces\": []\n}\n",
         "c:7:78: 'mu_k' must not be negative");
}

/* Every prefix of a strong-stability certificate is malformed; one-byte
   changes give WC_OK or WC_EINPUT, with the outputs set accordingly.  */
static void
test_stability_fuzz(void)
{
    static const char * const certs[] = { stab_rotation, stab_motion,
                                          stab_separator };
    static const char bytes[] = { '\0', '"', '}', ']', '1', '-', '/', 'x',
                                  ',', '0', 'u', 'n', 's', 'l', 'r', '9' };

    fuzz_certs(certs, sizeof certs / sizeof certs[0], bytes, sizeof bytes,
               0);
}

/* The strong-stability certificates in tests/certs (top_srcdir from the
   environment, as make check sets it; skipped when it is not set): the
   verdict and summary, the reason, or the located message of each.  */
static const struct
{
    const char * file;
    int status;                 /* WC_OK or WC_EINPUT */
    const char * summary;       /* WC_OK */
    const char * text;          /* the reason (NULL: holds), or message */
}
cert_files[] = {
    { "figure5-strongly-stable.json", WC_OK, SUM_STRONG, NULL },
    { "figure5-near-strongly-stable.json", WC_OK, SUM_ROTATION, NULL },
    { "figure5-near-not-weakly-stable.json", WC_OK, SUM_SEPARATOR, NULL },
    { "figure5-kinetic-moves.json", WC_OK, SUM_MOTION, NULL },
    { "tampered-face-missing.json", WC_OK, "wrench (0, -1, 0) is strongly "
      "stable: 8 moving faces excluded", "the faces omit the moving face rr" },
    { "tampered-face-repeated.json", WC_OK, SUM_STRONG,
      "face 7 (ss) repeats face 1" },
    { "tampered-face-sign.json", WC_OK, SUM_STRONG,
      "face 2 (ln) is not a moving face of the problem" },
    { "tampered-face-multiplier.json", WC_OK, SUM_STRONG, "face 1 (ss): the "
      "multipliers combine the rows to (0, 0, 0, 1), not to zero" },
    { "tampered-face-multiplier-count.json", WC_OK, SUM_STRONG,
      "face 4 (sn): there are 8 multipliers for 9 rows" },
    { "tampered-rotation-missing.json", WC_OK, "wrench (0, -1, 0) is "
      "strongly stable: 4 moving faces excluded",
      "the faces omit the moving face nu, rotation -1" },
    { "tampered-kinetic-friction.json", WC_OK, SUM_MOTION, "the motion's "
      "letter l at fixel 1 needs c_1t = -mu_k c_1n = -1, but c_1t = -1/2" },
    { "tampered-separator.json", WC_OK, SUM_SEPARATOR, "the separator y = "
      "(0, 1, 2) has y . (J_1n + mu_s J_1t) = -1, not >= 0" },
    { "tampered-static-forces.json", WC_OK, SUM_STRONG, "the static force at "
      "fixel 1 leaves its friction cone: |c_1t| = 2 > mu_s c_1n = 1" },
    { "bad-sign-letter.json", WC_EINPUT, NULL, "bad-sign-letter.json:12:13: "
      "letter 'u' not allowed on fixel 2, which is touching" },
    { "bad-rotation.json", WC_EINPUT, NULL, "bad-rotation.json:1:435: a "
      "rotation face has the sign n..n" },
    { "bad-mass.json", WC_EINPUT, NULL, "bad-mass.json:1:50: 'mass' must be "
      "positive" },
    { "bad-missing-faces.json", WC_EINPUT, NULL, "bad-missing-faces.json:1:1:"
      " missing key 'faces'" },
    /* the old kind through wc_verify */
    { "figure5-ln-pretty.json", WC_OK, "mode ln is infeasible", NULL },
    { "tampered-mode.json", WC_OK, "mode sl is feasible", "constraint 2 is "
      "not the one mode sl implies for fixel 2: expected (-1, 0, 0) . nu = "
      "0, found (-1, 0, 0) . nu > 0" },
    { "bad-pretty.json", WC_EINPUT, NULL, "bad-pretty.json:20:11: mode has "
      "1 letter; the problem has 2 fixels" }
};

static void
test_cert_files(void)
{
    const char * top = getenv("top_srcdir");
    size_t k;

    if (top == NULL)
        return;
    for (k = 0; k < sizeof cert_files / sizeof cert_files[0]; k++)
    {
        char * path = xmalloc(strlen(top) + strlen(cert_files[k].file) + 20);
        char * text, * why, * sum, * msg = NULL;
        FILE * f;
        long n;
        int holds, status;
        wc_error_t e;

        sprintf(path, "%s/tests/certs/%s", top, cert_files[k].file);
        f = fopen(path, "rb");
        if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0)
        {
            FAIL("cannot read %s", path);
            if (f != NULL)
                fclose(f);
            free(path);
            continue;
        }
        rewind(f);
        text = xmalloc((size_t) n + 1);
        if (fread(text, 1, (size_t) n, f) != (size_t) n)
            FAIL("cannot read %s", path);
        fclose(f);
        wc_error_init(e);
        status = wc_verify(&holds, &why, &sum, text, (size_t) n,
                           cert_files[k].file, e);
        if (status != WC_OK)
            msg = wc_error_format(e);
        if (status != cert_files[k].status)
            FAIL("%s: status %d, expected %d (%s)", path, status,
                 cert_files[k].status, msg != NULL ? msg : "");
        else if (status != WC_OK)
        {
            if (strcmp(msg, cert_files[k].text) != 0)
                FAIL("%s: message '%s', expected '%s'", path, msg,
                     cert_files[k].text);
        }
        else
        {
            if (strcmp(sum, cert_files[k].summary) != 0)
                FAIL("%s: summary '%s', expected '%s'", path, sum,
                     cert_files[k].summary);
            if (cert_files[k].text == NULL ? holds != 1 || why != NULL
                : holds != 0 || why == NULL
                || strcmp(why, cert_files[k].text) != 0)
                FAIL("%s: holds %d, reason '%s'", path, holds,
                     why != NULL ? why : "(none)");
            free(why);
            free(sum);
        }
        free(msg);
        free(text);
        free(path);
        wc_error_clear(e);
    }
}

/* A growing string for certificates built here.  */
typedef struct
{
    char * s;
    size_t len;
    size_t cap;
}
sbuf;

static void
sb_add(sbuf * b, const char * s)
{
    size_t n = strlen(s);

    if (b->len + n + 1 > b->cap)
    {
        size_t cap = b->cap < 256 ? 256 : b->cap;
        char * t;

        while (b->len + n + 1 > cap)
            cap *= 2;
        t = realloc(b->s, cap);
        if (t == NULL)
        {
            fputs("t-verify: out of memory\n", stderr);
            exit(99);
        }
        b->s = t;
        b->cap = cap;
    }
    memcpy(b->s + b->len, s, n + 1);
    b->len += n;
}

static void
sb_q(sbuf * b, const fmpq_t x)
{
    char * t = fmpq_get_str(NULL, 10, x);

    sb_add(b, "\"");
    sb_add(b, t);
    sb_add(b, "\"");
    flint_free(t);
}

static void
sb_qvec(sbuf * b, const fmpq * v, slong n)
{
    slong i;

    sb_add(b, "[");
    for (i = 0; i < n; i++)
    {
        if (i > 0)
            sb_add(b, ", ");
        sb_q(b, v + i);
    }
    sb_add(b, "]");
}

/* "problem": {...} of P.  */
static void
sb_problem(sbuf * b, const wc_problem_t P)
{
    slong i;

    sb_add(b, "\"problem\": {\"mass\": ");
    sb_q(b, P->mass);
    sb_add(b, ", \"inertia\": ");
    sb_q(b, P->inertia);
    sb_add(b, ", \"com\": ");
    sb_qvec(b, P->com, 2);
    sb_add(b, ", \"fixels\": [");
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        sb_add(b, i > 0 ? ", {\"point\": " : "{\"point\": ");
        sb_qvec(b, f->point, 2);
        sb_add(b, ", \"normal\": ");
        sb_qvec(b, f->normal, 2);
        sb_add(b, f->state == WC_NEAR ? ", \"state\": \"near\", \"mu_s\": "
               : ", \"state\": \"touching\", \"mu_s\": ");
        sb_q(b, f->mu_s);
        sb_add(b, ", \"mu_k\": ");
        sb_q(b, f->mu_k);
        sb_add(b, "}");
    }
    sb_add(b, "]}");
}

/* The strong-stability certificate claiming that g = 0 is strongly stable
   for P, with faces signs[0..count) (rotation entries for rot), each
   without multipliers.  malloc'd.  */
static char *
faces_certificate(const wc_problem_t P, char ** signs, slong count,
                  int rot)
{
    sbuf b = { NULL, 0, 0 };
    slong i;
    int r;

    sb_add(&b, "{\"kind\": \"strong-stability\", ");
    sb_problem(&b, P);
    sb_add(&b, ", \"wrench\": [0, 0, 0], \"weakly_stable\": true, \"weak\": "
           "{\"c\": [");
    for (i = 0; i < 2 * P->n; i++)
        sb_add(&b, i > 0 ? ", 0" : "0");
    sb_add(&b, "]}, \"strongly_stable\": true, \"faces\": [");
    for (i = 0; i < count; i++)
    {
        sb_add(&b, i > 0 ? ", {\"sign\": \"" : "{\"sign\": \"");
        sb_add(&b, signs[i]);
        sb_add(&b, "\", \"multipliers\": []}");
    }
    for (r = 1; rot && r >= -1; r -= 2)
    {
        char * nn = xmalloc((size_t) P->n + 1);

        for (i = 0; i < P->n; i++)
            nn[i] = P->fixels[i].state == WC_NEAR ? 'u' : 'n';
        nn[P->n] = '\0';
        sb_add(&b, count > 0 || r < 0 ? ", {\"sign\": \"" : "{\"sign\": \"");
        sb_add(&b, nn);
        sb_add(&b, r > 0 ? "\", \"rotation\": 1, \"multipliers\": []}"
               : "\", \"rotation\": -1, \"multipliers\": []}");
        free(nn);
    }
    sb_add(&b, "]}");
    return b.s;
}

/* wc_verify on text, which is freed: sets *refused when text is well
   formed and does not hold, and returns the reason, or else the message
   (malloc'd; NULL when it holds).  */
static char *
refusal(char * text, int * refused)
{
    int holds, status;
    char * why, * sum, * msg;

    status = run_wc_verify(&holds, &why, &sum, text, strlen(text), &msg);
    free(text);
    free(sum);
    *refused = status == WC_OK && holds == 0;
    if (why == NULL)
        return msg;
    free(msg);
    return why;
}

/* The moving faces verify computes from the arrangement are the Table 1
   modes that wc_modes_enumerate finds feasible for the touching fixels
   alone (the velocity table is the same arrangement), but n..n, with u
   on the near fixels; plus the two rotations when the touching fixels
   share a point.  verify checks the set of faces before any multiplier,
   so a certificate listing them all without multipliers fails on face 1's
   multiplier count, one that misses a face names it, and one with a face
   too many names that.  */
static void
test_faces_cross(void)
{
    slong iters = wctest_iters(300), it;

    for (it = 0; it < iters; it++)
    {
        wc_problem_t P, T;
        wc_modes_t M;
        wc_error_t e;
        char ** signs, * text, * why, * sum, * msg, expect[400];
        slong i, j, k, count = 0, t = 0;
        int holds, status, refused, shared = 1;

        if (!wctest_iter(it))
            continue;
        wc_problem_init(P);
        wc_problem_init(T);
        wc_modes_init(M);
        wc_error_init(e);
        wctest_random_problem(P, 1, 7);
        fmpq_set(T->mass, P->mass);
        fmpq_set(T->inertia, P->inertia);
        fmpq_set(T->com + 0, P->com + 0);
        fmpq_set(T->com + 1, P->com + 1);
        for (i = 0; i < P->n; i++)
        {
            const wc_fixel_struct * f = P->fixels + i;
            wc_fixel_struct * g;

            if (f->state == WC_NEAR)
                continue;
            if (t > 0 && (!fmpq_equal(f->point + 0, T->fixels[0].point + 0)
                          || !fmpq_equal(f->point + 1,
                                         T->fixels[0].point + 1)))
                shared = 0;
            g = wc_problem_add_fixel(T);
            fmpq_set(g->point + 0, f->point + 0);
            fmpq_set(g->point + 1, f->point + 1);
            fmpq_set(g->normal + 0, f->normal + 0);
            fmpq_set(g->normal + 1, f->normal + 1);
            fmpq_set(g->mu_s, f->mu_s);
            fmpq_set(g->mu_k, f->mu_k);
            g->state = WC_TOUCHING;
            t++;
        }
        if (t == 0)
            shared = 0;
        else if (wc_modes_enumerate(M, T, e) != WC_OK)
            wctest_fail_problem(P, NULL, "wc_modes_enumerate: %s",
                                e->message);
        signs = xmalloc((size_t) (t > 0 ? M->count : 0) * sizeof(char *)
                        + 1);
        for (k = 0; t > 0 && k < M->count; k++)
        {
            const char * m = M->modes[k];

            if ((slong) strspn(m, "n") == t)
                continue;
            signs[count] = xmalloc((size_t) P->n + 1);
            for (i = 0, j = 0; i < P->n; i++)
                signs[count][i] = P->fixels[i].state == WC_NEAR ? 'u'
                    : m[j++];
            signs[count][P->n] = '\0';
            count++;
        }

        /* all of them */
        text = faces_certificate(P, signs, count, shared);
        status = run_wc_verify(&holds, &why, &sum, text, strlen(text), &msg);
        if (count == 0 && !shared)
        {
            if (status != WC_OK || holds != 1)
                wctest_fail_problem(P, NULL, "no moving face, yet status %d, "
                                    "holds %d (%s) on %s", status, holds,
                                    why != NULL ? why : msg, text);
        }
        else
        {
            char nn[16];

            /* no face but the rotations: the first is n..n, rotation 1 */
            for (i = 0; i < P->n; i++)
                nn[i] = P->fixels[i].state == WC_NEAR ? 'u' : 'n';
            nn[P->n] = '\0';
            snprintf(expect, sizeof expect, "face 1 (%.200s%s): there are 0 "
                     "multipliers for ", count > 0 ? signs[0] : nn,
                     count > 0 ? "" : ", rotation 1");
            if (status != WC_OK || holds != 0
                || strncmp(why, expect, strlen(expect)) != 0)
                wctest_fail_problem(P, NULL, "the moving faces differ from "
                                    "wc_modes_enumerate's: %s on %s",
                                    why != NULL ? why : msg, text);
        }
        free(text);
        free(why);
        free(sum);
        free(msg);

        /* one missing */
        if (count > 0)
        {
            char * gone;

            k = wctest_randint(0, count - 1);
            gone = signs[k];
            signs[k] = signs[count - 1];
            text = faces_certificate(P, signs, count - 1, shared);
            signs[k] = gone;
            why = refusal(text, &refused);
            snprintf(expect, sizeof expect, "the faces omit the moving face "
                     "%.200s", gone);
            if (!refused || strcmp(why, expect) != 0)
                wctest_fail_problem(P, NULL, "dropped %s: %s", gone, why);
            free(why);
        }

        /* one too many: a string of s l r n (u on near fixels) that
           wc_modes_enumerate calls infeasible */
        if (t > 0 && count + 1 < (1L << (2 * t)) && t <= 6)
        {
            char * extra = xmalloc((size_t) P->n + 1);
            slong tries;

            for (tries = 0; tries < 1000; tries++)
            {
                for (i = 0; i < P->n; i++)
                    extra[i] = P->fixels[i].state == WC_NEAR ? 'u'
                        : "slrn"[wctest_randint(0, 3)];
                extra[P->n] = '\0';
                for (k = 0; k < count; k++)
                    if (strcmp(signs[k], extra) == 0)
                        break;
                if (k == count && (slong) strspn(extra, "nu") != P->n)
                    break;
            }
            if (tries < 1000)
            {
                signs[count] = extra;
                why = refusal(faces_certificate(P, signs, count + 1, shared),
                              &refused);
                snprintf(expect, sizeof expect, "face %ld (%.200s) is not a "
                         "moving face of the problem", (long) count + 1,
                         extra);
                if (!refused || strcmp(why, expect) != 0)
                    wctest_fail_problem(P, NULL, "added %s: %s", extra, why);
                free(why);
            }
            free(extra);
        }
        for (k = 0; k < count; k++)
            free(signs[k]);
        free(signs);
        wc_modes_clear(M);
        wc_problem_clear(T);
        wc_problem_clear(P);
        wc_error_clear(e);
    }
}

/* A temporary file to write a certificate to.  */
static FILE *
cert_file(void)
{
    FILE * f = tmpfile();

    if (f == NULL)
    {
        perror("t-verify: tmpfile");
        exit(99);
    }
    return f;
}

/* What f, from cert_file, holds, malloc'd, its length in *len (when len
   is not NULL); status is the writer's.  Closes f.  */
static char *
cert_read_back(FILE * f, int status, size_t * len)
{
    long n;
    char * s;

    if (status != WC_OK || fflush(f) != 0 || (n = ftell(f)) < 0)
        wctest_fail("cannot write a certificate");
    rewind(f);
    s = xmalloc((size_t) n + 1);
    if (fread(s, 1, (size_t) n, f) != (size_t) n)
        wctest_fail("cannot read a certificate back");
    s[n] = '\0';
    fclose(f);
    if (len != NULL)
        *len = (size_t) n;
    return s;
}

/* The certificate wc_classify_certificate_fprint writes for R, malloc'd,
   via a temporary file.  */
static char *
classify_text(const wc_problem_t P, const wc_classify_t R)
{
    FILE * f = cert_file();

    return cert_read_back(f, wc_classify_certificate_fprint(f, P, R), NULL);
}

/* Certificates written by wc_classify (FLINT, cddlib, exact LPs) hold
   under wc_verify (GMP alone), with the same verdicts; with one face's
   multipliers negated, or one face left out, they do not.  Half the
   wrenches are random, half -J c for forces in the friction cones (weakly
   stable, often on a boundary).  */
static void
test_classify_cross(void)
{
    slong iters = wctest_iters(150), it;

    for (it = 0; it < iters; it++)
    {
        wc_problem_t P;
        wc_classify_t R;
        wc_error_t e;
        fmpq g[3];
        fmpq_t c, d, x;
        char * text, * why, * sum, * msg, expect[400];
        slong i, j;
        int holds, status, refused;

        if (!wctest_iter(it))
            continue;
        wc_problem_init(P);
        wc_classify_init(R);
        wc_error_init(e);
        fmpq_init(c);
        fmpq_init(d);
        fmpq_init(x);
        for (j = 0; j < 3; j++)
            fmpq_init(g + j);
        wctest_random_problem(P, 1, 5);
        if (wctest_chance(1, 2))
            wctest_random_wrench(g);
        else
            for (i = 0; i < P->n; i++)
            {
                const wc_fixel_struct * f = P->fixels + i;
                fmpq r[2];

                if (f->state == WC_NEAR || wctest_chance(1, 3))
                    continue;
                /* c_n >= 0, |c_t| <= mu_s c_n, often on the edge */
                wctest_rand_fmpq_pos(c, 3, 2);
                if (wctest_chance(1, 3))
                    fmpq_mul(d, c, f->mu_s);
                else
                    wctest_rand_fmpq(d, 2, 3);
                fmpq_mul(x, c, f->mu_s);
                fmpq_abs(d, d);
                if (fmpq_cmp(d, x) > 0)
                    fmpq_set(d, x);
                if (wctest_chance(1, 2))
                    fmpq_neg(d, d);
                /* g -= c n + d t, torque r x (c n + d t) */
                fmpq_init(r + 0);
                fmpq_init(r + 1);
                fmpq_sub(r + 0, f->point + 0, P->com + 0);
                fmpq_sub(r + 1, f->point + 1, P->com + 1);
                {
                    fmpq_t fx, fy;

                    fmpq_init(fx);
                    fmpq_init(fy);
                    /* force = c n + d (-n_y, n_x) */
                    fmpq_mul(fx, c, f->normal + 0);
                    fmpq_mul(x, d, f->normal + 1);
                    fmpq_sub(fx, fx, x);
                    fmpq_mul(fy, c, f->normal + 1);
                    fmpq_mul(x, d, f->normal + 0);
                    fmpq_add(fy, fy, x);
                    fmpq_sub(g + 0, g + 0, fx);
                    fmpq_sub(g + 1, g + 1, fy);
                    fmpq_mul(x, r + 0, fy);
                    fmpq_sub(g + 2, g + 2, x);
                    fmpq_mul(x, r + 1, fx);
                    fmpq_add(g + 2, g + 2, x);
                    fmpq_clear(fx);
                    fmpq_clear(fy);
                }
                fmpq_clear(r + 0);
                fmpq_clear(r + 1);
            }
        status = wc_classify(R, P, g, 1, 1, e);
        if (status != WC_OK)
            wctest_fail_problem(P, NULL, "wc_classify: status %d (%s)",
                                status, e->message);
        text = classify_text(P, R);
        status = run_wc_verify(&holds, &why, &sum, text, strlen(text), &msg);
        if (status != WC_OK || holds != 1)
            wctest_fail_problem(P, NULL, "wc_classify's certificate: status "
                                "%d, holds %d (%s) on %s", status, holds,
                                why != NULL ? why : msg != NULL ? msg : "",
                                text);
        {
            char * gs = wctest_vec_str(g, 3);

            if (R->strong)
                snprintf(expect, sizeof expect, "wrench %s is strongly "
                         "stable: %ld moving face%s excluded", gs,
                         (long) R->nnofaces, R->nnofaces == 1 ? "" : "s");
            else if (R->weak)
                snprintf(expect, sizeof expect, "wrench %s is weakly stable "
                         "but moves in mode %s", gs, R->motions[0].sign);
            else
                snprintf(expect, sizeof expect, "wrench %s is not weakly "
                         "stable", gs);
            flint_free(gs);
        }
        if (strcmp(sum, expect) != 0)
            wctest_fail_problem(P, NULL, "summary '%s', expected '%s'", sum,
                                expect);
        free(text);
        free(why);
        free(sum);
        free(msg);
        if (R->strong && R->nnofaces > 0)
        {
            slong k = wctest_randint(0, R->nnofaces - 1);
            wc_noface_struct * F = R->nofaces + k, swap;

            /* one face's multipliers negated: some > row's goes negative */
            for (j = 0; j < F->nmult; j++)
                fmpq_neg(F->mult + j, F->mult + j);
            text = classify_text(P, R);
            for (j = 0; j < F->nmult; j++)
                fmpq_neg(F->mult + j, F->mult + j);
            why = refusal(text, &refused);
            snprintf(expect, sizeof expect, "face %ld (", (long) k + 1);
            if (!refused || strncmp(why, expect, strlen(expect)) != 0
                || strstr(why, ": multiplier ") == NULL)
                wctest_fail_problem(P, NULL, "face %ld negated: %s", (long) k
                                    + 1, why);
            free(why);

            /* one face left out */
            swap = *F;
            *F = R->nofaces[R->nnofaces - 1];
            R->nofaces[R->nnofaces - 1] = swap;
            R->nnofaces--;
            text = classify_text(P, R);
            R->nnofaces++;
            R->nofaces[R->nnofaces - 1] = *F;
            *F = swap;
            why = refusal(text, &refused);
            if (F->rotation != 0)
                snprintf(expect, sizeof expect, "the faces omit the moving "
                         "face %.200s, rotation %d", F->sign, F->rotation);
            else
                snprintf(expect, sizeof expect, "the faces omit the moving "
                         "face %.200s", F->sign);
            if (!refused || strcmp(why, expect) != 0)
                wctest_fail_problem(P, NULL, "face %ld left out: %s", (long) k
                                    + 1, why);
            free(why);
        }
        for (j = 0; j < 3; j++)
            fmpq_clear(g + j);
        fmpq_clear(c);
        fmpq_clear(d);
        fmpq_clear(x);
        wc_classify_clear(R);
        wc_problem_clear(P);
        wc_error_clear(e);
    }
}

/* ------------------------------------------------------------------ */
/* Cross-check against the library's certificates.                     */

/* The JSON certificate of C for P, malloc'd, via a temporary file.  */
static char *
certificate_text(size_t * len, const wc_certificate_t C, const wc_problem_t P)
{
    FILE * f = cert_file();

    return cert_read_back(f, wc_certificate_fprint(f, C, P, as_json), len);
}

static void
test_cross(void)
{
    slong iters = wctest_iters(400), it;
    wc_problem_t P;
    wc_certificate_t C;
    wc_error_t e;
    char * mode = NULL;

    for (it = 0; it < iters; it++)
    {
        char * text, * why, * m, * msg;
        size_t len;
        int holds, feas, status, expect, round;

        if (!wctest_iter(it))
            continue;
        wc_problem_init(P);
        wc_certificate_init(C);
        wc_error_init(e);
        wctest_random_problem(P, 1, 6);
        mode = xmalloc((size_t) P->n + 1);
        wctest_random_mode_kinematic(mode, P);
        status = wc_feasible(C, P, mode, e);
        if (status != WC_OK)
            wctest_fail_problem(P, mode, "wc_feasible: status %d (%s)",
                                status, e->message);
        for (round = 0; round < 4; round++)
        {
            slong mrows = fmpz_mat_nrows(C->rows);

            if (round > 0)
            {
                /* tamper with the witness or one multiplier */
                fmpz * x = C->feasible ? C->witness
                    + wctest_randint(0, 2) : C->mult
                    + wctest_randint(0, mrows - 1);

                if (wctest_chance(1, 3))
                    fmpz_neg(x, x);
                else if (wctest_chance(1, 2))
                    fmpz_add_si(x, x, wctest_randint(-2, 2));
                else
                    fmpz_mul_si(x, x, wctest_randint(0, 3));
            }
            expect = wc_certificate_check(C);
            if (round == 0 && !expect)
                wctest_fail_problem(P, mode, "wc_feasible's certificate "
                                    "fails wc_certificate_check");
            text = certificate_text(&len, C, P);
            status = run_verify(&holds, &why, &m, &feas, text, len, &msg);
            if (status != WC_OK)
                wctest_fail_problem(P, mode, "round %d: verify status %d "
                                    "(%s) on %s", round, status, msg, text);
            if (holds != expect || strcmp(m, mode) != 0
                || feas != C->feasible)
                wctest_fail_problem(P, mode, "round %d: verify says %d "
                                    "(%s), wc_certificate_check %d, on %s",
                                    round, holds, why != NULL ? why : "",
                                    expect, text);
            free(why);
            free(m);
            free(text);
        }
        free(mode);
        mode = NULL;
        wc_certificate_clear(C);
        wc_problem_clear(P);
        wc_error_clear(e);
    }
}

int
main(void)
{
    wctest_init("t-verify");
    test_json_good();
    test_json_bad();
    test_json_limits();
    test_good();
    test_tampered();
    test_malformed();
    test_fuzz();
    test_cross();
    test_stability_good();
    test_stability_tampered();
    test_stability_malformed();
    test_stability_fuzz();
    test_cert_files();
    test_faces_cross();
    test_classify_cross();
    flint_cleanup_master();
    if (wctest_failures() > 0)
    {
        fprintf(stderr, "t-verify: %d failure(s) (seed %llu)\n",
                wctest_failures(), (unsigned long long) wctest_seed());
        return 1;
    }
    return 0;
}
