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

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "json.h"
#include "verify.h"
#include "testutil.h"

static int failures = 0;

#define FAIL(...) fail(__LINE__, __VA_ARGS__)

static void
fail(int line, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void
fail(int line, const char * fmt, ...)
{
    va_list ap;

    fprintf(stderr, "t-verify.c:%d: ", line);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    failures++;
}

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

    wc_json_init(J);
    wc_error_init(e);
    status = wc_json_parse(J, doc, sizeof doc - 1, "doc", e);
    if (status != WC_OK)
    {
        FAIL("good document: status %d (%s)", status, e->message);
        goto cleanup;
    }
    r = &J->root;
    node_is(__LINE__, r, WC_JSON_OBJECT, 1, 1);
    if (r->len != 5)
        FAIL("root has %lu members", (unsigned long) r->len);
    node_is(__LINE__, wc_json_object_key(r, 0), WC_JSON_STRING, 1, 2);
    a = wc_json_object_get(r, "a");
    node_is(__LINE__, a, WC_JSON_ARRAY, 1, 7);
    if (a != NULL && a->len != 3)
        FAIL("a has %lu elements", (unsigned long) a->len);
    v = wc_json_array_get(a, 0);
    node_is(__LINE__, v, WC_JSON_NUMBER, 1, 8);
    text_is(__LINE__, v, "1", 1);
    v = wc_json_array_get(a, 1);
    node_is(__LINE__, v, WC_JSON_NUMBER, 1, 11);
    text_is(__LINE__, v, "-2.5e3", 6);
    v = wc_json_array_get(a, 2);
    node_is(__LINE__, v, WC_JSON_STRING, 1, 19);
    text_is(__LINE__, v, "x", 1);
    if (wc_json_array_get(a, 3) != NULL)
        FAIL("element past the end");
    b = wc_json_object_get(r, "b");
    node_is(__LINE__, b, WC_JSON_OBJECT, 2, 7);
    node_is(__LINE__, wc_json_object_key(b, 0), WC_JSON_STRING, 2, 8);
    node_is(__LINE__, wc_json_object_get(b, "c"), WC_JSON_NULL, 2, 13);
    node_is(__LINE__, wc_json_object_get(b, "d"), WC_JSON_TRUE, 2, 24);
    node_is(__LINE__, wc_json_object_get(b, "e"), WC_JSON_FALSE, 2, 35);
    node_is(__LINE__, wc_json_object_value(b, 2), WC_JSON_FALSE, 2, 35);
    if (wc_json_object_get(b, "f") != NULL || wc_json_object_get(a, "a")
        != NULL || wc_json_object_value(b, 3) != NULL)
        FAIL("lookup of what is not there");
    v = wc_json_object_get(r, "");
    node_is(__LINE__, v, WC_JSON_STRING, 3, 5);
    text_is(__LINE__, v, decoded, sizeof decoded - 1);
    v = wc_json_object_get(r, "\xc3\xa9");
    node_is(__LINE__, v, WC_JSON_ARRAY, 3, 56);
    if (v != NULL && (v->len != 0 || v->items != NULL))
        FAIL("empty array not empty");
    v = wc_json_object_get(r, "o");
    node_is(__LINE__, v, WC_JSON_OBJECT, 3, 65);
    if (v != NULL && v->len != 0)
        FAIL("empty object not empty");

    /* scalars alone; parsing again replaces the document */
    if (wc_json_parse(J, " -0 ", 4, "doc", e) != WC_OK)
        FAIL("-0: %s", e->message);
    node_is(__LINE__, &J->root, WC_JSON_NUMBER, 1, 2);
    text_is(__LINE__, &J->root, "-0", 2);
    if (wc_json_parse(J, "\"\"", 2, "doc", e) != WC_OK)
        FAIL("empty string: %s", e->message);
    text_is(__LINE__, &J->root, "", 0);
    if (wc_json_parse(J, "0.5E+10", 7, NULL, e) != WC_OK
        || wc_json_parse(J, "1e-7", 4, NULL, e) != WC_OK
        || wc_json_parse(J, "[[], {}, [{}]]", 14, NULL, e) != WC_OK
        || wc_json_parse(J, "\t\r\n null \n", 10, NULL, e) != WC_OK)
        FAIL("good scalar: %s", e->message);
    node_is(__LINE__, &J->root, WC_JSON_NULL, 2, 2);
    /* keys that differ only after a NUL are different keys */
    if (wc_json_parse(J, "{\"a\\u0000b\": 1, \"a\\u0000c\": 2, \"a\": 3}", 38,
                      NULL, e) != WC_OK)
        FAIL("keys with NUL: %s", e->message);
    else if ((v = wc_json_object_get(&J->root, "a")) == NULL
             || strcmp(v->text, "3") != 0)
        FAIL("key 'a' not found among keys with NULs");
cleanup:
    wc_json_clear(J);
    wc_json_clear(J);   /* clear is safe twice */
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

    wc_json_init(J);
    wc_error_init(e);
    status = wc_json_parse(J, text, len, "f", e);
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
    wc_json_clear(J);
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

    wc_json_init(J);
    wc_error_init(e);

    /* 64 levels are fine, 65 are not, however deep the input goes */
    s = repeat("[", WC_JSON_MAX_DEPTH);
    t = repeat("]", WC_JSON_MAX_DEPTH);
    u = xmalloc(2 * WC_JSON_MAX_DEPTH + 1);
    sprintf(u, "%s%s", s, t);
    if (wc_json_parse(J, u, strlen(u), "f", e) != WC_OK)
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
    status = wc_json_parse(J, t, strlen(t), "f", e);
    if (status != WC_OK || J->root.len != n + 1)
        FAIL("long document: status %d", status);
    else
    {
        const wc_json_node * v = wc_json_array_get(&J->root, n - 1);

        node_is(__LINE__, wc_json_array_get(v, 2), WC_JSON_OBJECT, 1,
                (long) (n - 1) * 21 + 11);
        text_is(__LINE__, wc_json_object_get(wc_json_array_get(v, 2), "k"),
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
    if (wc_json_parse(J, s, 300001, "f", e) != WC_OK || J->root.len != 3
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
    status = wc_json_parse(J, s, n, "f", e);
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

        if (wc_json_parse(J, s + (i % 2), len - (len > 0 && i % 2), "f", e)
            != WC_EINPUT)
            FAIL("garbage parsed");
    }
    /* garbage made of JSON's own characters */
    for (i = 0; i < n; i++)
        s[i] = "[]{}\",:0-1e.tn\\u \n"[wctest_rand() % 19];
    for (i = 0; i < 64; i++)
    {
        size_t len = (size_t) wctest_randint(0, (slong) n);

        status = wc_json_parse(J, s, len, "f", e);
        if (status != WC_EINPUT && status != WC_OK)
            FAIL("JSON characters: status %d", status);
    }
    free(s);
    wc_json_clear(J);
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

/* Run the checker; returns its status and sets the outputs.  */
static int
run_verify(int * holds, char ** reason, char ** mode, int * feasible,
           const char * text, size_t len, char ** msg)
{
    wc_error_t e;
    int status;

    wc_error_init(e);
    status = wc_verify_certificate(holds, reason, mode, feasible, text, len,
                                   "c", e);
    *msg = status != WC_OK ? wc_error_format(e) : NULL;
    wc_error_clear(e);
    return status;
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
    if (status != WC_OK)
        fail(line, "status %d: %s", status, msg);
    else if (reason == NULL && (holds != 1 || why != NULL))
        fail(line, "does not hold: %s", why != NULL ? why : "(no reason)");
    else if (reason != NULL && (holds != 0 || why == NULL
                                || strcmp(why, reason) != 0))
        fail(line, "holds %d, reason '%s', expected '%s'", holds,
             why != NULL ? why : "(none)", reason);
    else if (m == NULL || strcmp(m, mode) != 0 || feas != feasible)
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

/* text is malformed: the message is expect ("c:LINE:COL: ...").  */
static void
malformed_n(int line, const char * text, size_t len, const char * expect)
{
    int holds = -1, feas = -1, status;
    char * why = (char *) "x", * m = (char *) "x", * msg = NULL;

    status = run_verify(&holds, &why, &m, &feas, text, len, &msg);
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

static void
bad_edit_n(int line, const char * base, const char * old, const char * new,
           const char * expect)
{
    char * t = subst(line, base, old, new);

    malformed_n(line, t, strlen(t), expect);
    free(t);
}

#define BAD(base, old, new, expect) \
    bad_edit_n(__LINE__, base, old, new, expect)

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
    malformed_n(__LINE__, text, sizeof(text) - 1, expect)

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
static void
test_fuzz(void)
{
    static const char * const certs[] = { cert_ln, cert_sss };
    static const char bytes[] = { '\0', '"', '}', ']', '1', '-', '/', 'x',
                                  ',', '\\', (char) 0xff, '0', 'a', 's' };
    size_t c, n, i, k;

    for (c = 0; c < 2; c++)
    {
        const char * cert = certs[c];
        char * t;

        n = strlen(cert);
        while (n > 0 && (cert[n - 1] == '\n' || cert[n - 1] == '}'))
            n--;
        for (i = 0; i <= n; i++)
        {
            int holds, feas, status;
            char * why, * m, * msg;

            status = run_verify(&holds, &why, &m, &feas, cert, i, &msg);
            if (status != WC_EINPUT || msg == NULL)
                FAIL("prefix of %lu bytes: status %d", (unsigned long) i,
                     status);
            free(msg);
        }
        n = strlen(cert);
        t = xmalloc(n + 1);
        for (i = 0; i < n; i++)
            for (k = 0; k < sizeof bytes; k++)
            {
                int holds, feas, status;
                char * why, * m, * msg;

                memcpy(t, cert, n + 1);
                if (t[i] == bytes[k])
                    continue;
                t[i] = bytes[k];
                status = run_verify(&holds, &why, &m, &feas, t, n, &msg);
                if (status == WC_OK)
                {
                    if ((holds != 0 && holds != 1) || m == NULL
                        || (holds == 0) != (why != NULL) || msg != NULL)
                        FAIL("mutation at %lu: bad outputs", (unsigned long) i);
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

/* ------------------------------------------------------------------ */
/* Cross-check against the library's certificates.                     */

/* The JSON certificate of C for P, malloc'd, via a temporary file.  */
static char *
certificate_text(size_t * len, const wc_certificate_t C, const wc_problem_t P)
{
    FILE * f = tmpfile();
    long n;
    char * s;

    if (f == NULL)
    {
        perror("t-verify: tmpfile");
        exit(99);
    }
    if (wc_certificate_fprint(f, C, P, 1) != WC_OK || fflush(f) != 0
        || (n = ftell(f)) < 0)
        wctest_fail("cannot write a certificate");
    rewind(f);
    s = xmalloc((size_t) n + 1);
    if (fread(s, 1, (size_t) n, f) != (size_t) n)
        wctest_fail("cannot read a certificate back");
    s[n] = '\0';
    fclose(f);
    *len = (size_t) n;
    return s;
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
    flint_cleanup_master();
    if (failures > 0)
    {
        fprintf(stderr, "t-verify: %d failure(s) (seed %llu)\n", failures,
                (unsigned long long) wctest_seed());
        return 1;
    }
    return 0;
}
