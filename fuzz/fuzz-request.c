/* fuzz-request.c -- libFuzzer target: the request reader and the batch
   (lib/api/request.c, lib/api/batch.c; `wrenchcone batch`).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Any bytes are a batch file: wc_batch answers every line that is not
   blank with one line, never a crash, a leak or an abort, and its own
   status is WC_OK.  Every answer line is valid UTF-8 JSON (by this file's
   own strict reader, which shares no code with the library's): one
   object opening with the format key, on one line.  An error record
   names a message of one line within WC_MESSAGE_MAX bytes (and "..."), a
   file within WC_SHOW_PATH_MAX (and "...") and a status from 1 to 3;
   when it names the batch file, its line is the request's line.  The
   batch's status is the worst line's by wrenchcone(1)'s rule: an error
   record's status above a disagreement (4: a comparison beyond its
   tolerance, a certificate that does not hold), and of errors the
   largest.

   The requests run in a scratch folder holding a problem, two cone files
   and a certificate; an input naming another file, holding a problem
   text of more than 3 fixels or asking for more than two costly answers
   (plan, stability, sweep, report, draw, random) is left out, so that a
   run stays in memory and time and reads nothing else of the machine
   (/dev/stdin, say).  */

#include "fuzzutil.h"

#include <limits.h>
#include <unistd.h>

#include "api/batch.h"
#include "core/json.h"
#include "core/limits.h"
#include "core/version.h"

#define FILE_NAME "fuzz.jsonl"
#define MAX_LINES 16

static const char * const files[][2] = {
    { "p.wc", "mass 1\ninertia 1\ncom 0 0\nfriction 1/5\n"
      "shape disk 0 0 1\nfixel 0 -1 normal 0 1 touching\n"
      "fixel 1 0 normal -1 0 near\n" },
    { "c.json", "{\"mode\": \"na\", \"cone\": {\"empty\": false, "
      "\"dim\": 3, \"lineality_dim\": 0, \"inequalities\": [[\"-5\", \"2\", "
      "\"-5\"], [\"-1\", \"0\", \"1\"], [\"5\", \"2\", \"5\"]], "
      "\"equalities\": [], \"rays\": [[\"-1\", \"-5\", \"-1\"], [\"1\", "
      "\"-5\", \"1\"], [\"1\", \"0\", \"-1\"]], \"lines\": []}}\n" },
    { "c.ine", "H-representation\nbegin\n 2 4 rational\n 0 1 0 0\n"
      " 0 0 1 0\nend\n" },
    { "cert.json", "{\"format\": \"wrenchcone-json/1\", \"kind\": "
      "\"mode-feasibility\", \"mode\": \"na\", \"feasible\": true, "
      "\"witness\": [\"1\", \"0\", \"-1\"], \"constraints\": [{\"row\": "
      "[\"0\", \"1\", \"0\"], \"relation\": \"=\"}, {\"row\": [\"-1\", "
      "\"0\", \"-1\"], \"relation\": \"=\"}, {\"row\": [\"1\", \"0\", "
      "\"0\"], \"relation\": \">\"}], \"problem\": {\"com\": [\"0\", \"0\"], "
      "\"fixels\": [{\"point\": [\"0\", \"-1\"], \"normal\": [\"0\", \"1\"], "
      "\"state\": \"touching\"}, {\"point\": [\"1\", \"0\"], \"normal\": "
      "[\"-1\", \"0\"], \"state\": \"near\"}]}}\n" },
};
#define NFILES (sizeof files / sizeof files[0])

/* Names a request may give as a path: the files, one that is missing, a
   folder.  */
static int
allowed_path(const char * s)
{
    size_t i;

    for (i = 0; i < NFILES; i++)
        if (strcmp(s, files[i][0]) == 0)
            return 1;
    return strcmp(s, "missing.wc") == 0 || strcmp(s, ".") == 0;
}

static void
setup(void)
{
    char dir[] = "/tmp/fuzz-request.XXXXXX";
    size_t i;

    FUZZ_REQUIRE(mkdtemp(dir) != NULL && chdir(dir) == 0, "scratch folder");
    for (i = 0; i < NFILES; i++)
    {
        FILE * f = fopen(files[i][0], "w");

        FUZZ_REQUIRE(f != NULL && fputs(files[i][1], f) >= 0
                     && fclose(f) == 0, "writing %s", files[i][0]);
    }
}

/* ------------------------------------------------------------------ */
/* A strict JSON reader of its own (RFC 8259, UTF-8 by Unicode's Table
   3-7), for the answers: whether s[*i..n) starts with one value.  */

typedef struct
{
    const unsigned char * s;
    size_t n, i;
    int depth;
}
jr;

static void
ws(jr * r)
{
    while (r->i < r->n && (r->s[r->i] == ' ' || r->s[r->i] == '\t'
                           || r->s[r->i] == '\n' || r->s[r->i] == '\r'))
        r->i++;
}

static int
lit(jr * r, const char * w)
{
    size_t k = strlen(w);

    if (r->n - r->i < k || memcmp(r->s + r->i, w, k) != 0)
        return 0;
    r->i += k;
    return 1;
}

static int
hex4(jr * r, long * u)
{
    size_t k;

    *u = 0;
    if (r->n - r->i < 4)
        return 0;
    for (k = 0; k < 4; k++)
    {
        unsigned char c = r->s[r->i++];
        int h = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f'
            ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;

        if (h < 0)
            return 0;
        *u = 16 * *u + h;
    }
    return 1;
}

/* One UTF-8 character of at least 2 bytes at r->i.  */
static int
utf8(jr * r)
{
    unsigned char c = r->s[r->i];
    size_t m, k;
    unsigned long u;

    if (c >= 0xc2 && c <= 0xdf)
        m = 2, u = c & 0x1f;
    else if (c >= 0xe0 && c <= 0xef)
        m = 3, u = c & 0x0f;
    else if (c >= 0xf0 && c <= 0xf4)
        m = 4, u = c & 0x07;
    else
        return 0;
    if (r->n - r->i < m)
        return 0;
    for (k = 1; k < m; k++)
    {
        if ((r->s[r->i + k] & 0xc0) != 0x80)
            return 0;
        u = (u << 6) | (r->s[r->i + k] & 0x3f);
    }
    if ((m == 3 && (u < 0x800 || (u >= 0xd800 && u <= 0xdfff)))
        || (m == 4 && (u < 0x10000 || u > 0x10ffff)))
        return 0;
    r->i += m;
    return 1;
}

static int
string(jr * r)
{
    if (!lit(r, "\""))
        return 0;
    for (;;)
    {
        unsigned char c;

        if (r->i >= r->n)
            return 0;
        c = r->s[r->i];
        if (c == '"')
        {
            r->i++;
            return 1;
        }
        if (c < 0x20)
            return 0;
        if (c >= 0x80)
        {
            if (!utf8(r))
                return 0;
            continue;
        }
        r->i++;
        if (c != '\\')
            continue;
        if (r->i >= r->n)
            return 0;
        c = r->s[r->i++];
        if (c == 'u')
        {
            long u, v;

            if (!hex4(r, &u) || (u >= 0xdc00 && u <= 0xdfff))
                return 0;
            if (u >= 0xd800 && u <= 0xdbff
                && !(lit(r, "\\u") && hex4(r, &v) && v >= 0xdc00
                     && v <= 0xdfff))
                return 0;
        }
        else if (strchr("\"\\/bfnrt", c) == NULL || c == '\0')
            return 0;
    }
}

static int
digits(jr * r)
{
    size_t a = r->i;

    while (r->i < r->n && r->s[r->i] >= '0' && r->s[r->i] <= '9')
        r->i++;
    return r->i > a;
}

static int
number(jr * r)
{
    lit(r, "-");
    if (lit(r, "0"))
        ;
    else if (r->i < r->n && r->s[r->i] >= '1' && r->s[r->i] <= '9')
        digits(r);
    else
        return 0;
    if (lit(r, ".") && !digits(r))
        return 0;
    if (lit(r, "e") || lit(r, "E"))
    {
        if (!lit(r, "+"))
            lit(r, "-");
        if (!digits(r))
            return 0;
    }
    return 1;
}

static int value(jr * r);

static int
members(jr * r, int object)
{
    char close = object ? '}' : ']';

    if (++r->depth > 200)
        return 0;
    r->i++;
    ws(r);
    if (r->i < r->n && r->s[r->i] == close)
    {
        r->i++;
        r->depth--;
        return 1;
    }
    for (;;)
    {
        ws(r);
        if (object)
        {
            if (!string(r))
                return 0;
            ws(r);
            if (!lit(r, ":"))
                return 0;
        }
        if (!value(r))
            return 0;
        ws(r);
        if (r->i < r->n && r->s[r->i] == close)
        {
            r->i++;
            r->depth--;
            return 1;
        }
        if (!lit(r, ","))
            return 0;
    }
}

static int
value(jr * r)
{
    ws(r);
    if (r->i >= r->n)
        return 0;
    switch (r->s[r->i])
    {
    case '{':
        return members(r, 1);
    case '[':
        return members(r, 0);
    case '"':
        return string(r);
    case 't':
        return lit(r, "true");
    case 'f':
        return lit(r, "false");
    case 'n':
        return lit(r, "null");
    default:
        return number(r);
    }
}

/* Whether s[0..n) is exactly one JSON value, spaces around it allowed.  */
static int
json_ok(const char * s, size_t n)
{
    jr r;

    r.s = (const unsigned char *) s;
    r.n = n;
    r.i = 0;
    r.depth = 0;
    if (!value(&r))
        return 0;
    ws(&r);
    return r.i == n;
}

/* ------------------------------------------------------------------ */
/* The requests: left out, or counted.  */

static int
costly(const char * command)
{
    static const char * const names[] = {
        "plan", "stability", "sweep", "report", "draw", "random"
    };
    size_t i;

    for (i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strcmp(command, names[i]) == 0)
            return 1;
    return 0;
}

static size_t
count(const char * s, size_t n, const char * w)
{
    size_t k = strlen(w), c = 0, i;

    for (i = 0; i + k <= n; i++)
        c += memcmp(s + i, w, k) == 0;
    return c;
}

/* Whether the request s[0..n) may run here; *cost counts the costly.  */
static int
may_run(const char * s, size_t n, int * cost)
{
    static const char * const paths[] = { "problem", "foreign", "certfile" };
    static const char * const texts[] = {
        "problem_text", "foreign_text", "certfile_text"
    };
    wc_json_t J;
    wc_error_t err;
    const wc_json_node * o, * v;
    size_t i;
    int ok = 1;

    wc_error_init(err);
    _wc_json_init(J);
    o = &J->root;
    if (_wc_json_parse(J, s, n, FILE_NAME, err) == WC_OK
        && o->type == WC_JSON_OBJECT)
    {
        for (i = 0; i < 3; i++)
            if ((v = _wc_json_object_get(o, paths[i])) != NULL
                && v->type == WC_JSON_STRING
                && (strlen(v->text) != v->len || !allowed_path(v->text)))
                ok = 0;
        for (i = 0; i < 3; i++)
            if ((v = _wc_json_object_get(o, texts[i])) != NULL
                && v->type == WC_JSON_STRING
                && (v->len > 1024 || count(v->text, v->len, "fixel") > 3))
                ok = 0;
        if ((v = _wc_json_object_get(o, "command")) != NULL
            && v->type == WC_JSON_STRING && costly(v->text))
            ++*cost;
    }
    _wc_json_clear(J);
    wc_error_clear(err);
    return ok && *cost <= 2;
}

/* ------------------------------------------------------------------ */
/* The answers.  */

/* The status that the answer a[0..n) stands for (checked on the way).  */
static int
answer_status(const char * a, size_t n, long lineno)
{
    wc_json_t J;
    wc_error_t err;
    const wc_json_node * e, * v;
    int st = WC_OK;

    wc_error_init(err);
    _wc_json_init(J);
    FUZZ_REQUIRE(_wc_json_parse(J, a, n, "answer", err) == WC_OK
                 && J->root.type == WC_JSON_OBJECT,
                 "the library cannot read its answer: %s", err->message);
    if ((e = _wc_json_object_get(&J->root, "error")) != NULL)
    {
        const wc_json_node * m = _wc_json_object_get(e, "message");
        const wc_json_node * f = _wc_json_object_get(e, "file");
        const wc_json_node * l = _wc_json_object_get(e, "line");
        const wc_json_node * s = _wc_json_object_get(e, "status");

        FUZZ_REQUIRE(m != NULL && m->type == WC_JSON_STRING && m->len > 0
                     && m->len <= WC_MESSAGE_MAX + 3
                     && memchr(m->text, '\n', m->len) == NULL,
                     "line %ld: a bad message: %.*s", lineno, (int) n, a);
        FUZZ_REQUIRE(f != NULL && (f->type == WC_JSON_NULL
                                   || (f->type == WC_JSON_STRING
                                       && f->len <= WC_SHOW_PATH_MAX + 3)),
                     "line %ld: a bad file: %.*s", lineno, (int) n, a);
        FUZZ_REQUIRE(s != NULL && s->type == WC_JSON_NUMBER
                     && strlen(s->text) == 1 && s->text[0] >= '1'
                     && s->text[0] <= '3',
                     "line %ld: a bad status: %.*s", lineno, (int) n, a);
        st = s->text[0] - '0';
        if (f->type == WC_JSON_STRING && strcmp(f->text, FILE_NAME) == 0)
        {
            char want[32];

            snprintf(want, sizeof want, "%ld", lineno);
            FUZZ_REQUIRE(l != NULL && l->type == WC_JSON_NUMBER
                         && strcmp(l->text, want) == 0,
                         "line %ld: the error is located elsewhere: %.*s",
                         lineno, (int) n, a);
        }
    }
    else if (((v = _wc_json_object_get(&J->root, "within_tolerance")) != NULL
              || (v = _wc_json_object_get(&J->root, "holds")) != NULL)
             && v->type == WC_JSON_FALSE)
        st = WC_EDISAGREE;
    _wc_json_clear(J);
    wc_error_clear(err);
    return st;
}

/* wrenchcone(1)'s order: 0, 4, 1, 2, 3.  */
static int
rank(int st)
{
    return st == WC_OK ? 0 : st == WC_EDISAGREE ? 1 : st + 1;
}

int
LLVMFuzzerTestOneInput(const uint8_t * data, size_t size)
{
    static int ready = 0;
    const char * s = (const char *) data;
    size_t i = 0, a = 0, nreq = 0;
    long lineno = 0, lines[MAX_LINES];
    int cost = 0, worst = -1, want = WC_OK, status;
    fuzz_out o;
    FILE * in;
    wc_error_t err;

    if (!ready)
    {
        setup();
        ready = 1;
    }
    /* The lines as the batch cuts them: those that are not blank.  */
    while (i < size)
    {
        size_t e = i, n;

        while (e < size && s[e] != '\n')
            e++;
        lineno++;
        n = e - i;
        if (n > 0 && s[i + n - 1] == '\r')
            n--;
        {
            size_t k = 0;

            while (k < e - i && (s[i + k] == ' ' || s[i + k] == '\t'
                                 || s[i + k] == '\r'))
                k++;
            if (k < e - i)
            {
                if (nreq == MAX_LINES || !may_run(s + i, n, &cost))
                    return -1;
                lines[nreq++] = lineno;
            }
        }
        i = e + 1;
    }

    in = fmemopen((void *) (size > 0 ? s : ""), size > 0 ? size : 1, "r");
    FUZZ_REQUIRE(in != NULL, "fmemopen failed");
    if (size == 0)
        fgetc(in);              /* an empty stream */
    fuzz_out_open(&o);
    wc_error_init(err);
    status = wc_batch(&worst, o.f, in, FILE_NAME, 1, err);
    fclose(in);
    fuzz_out_close(&o);
    FUZZ_REQUIRE(status == WC_OK, "the batch failed: %d %s", status,
                 err->message != NULL ? err->message : "");

    /* One line per request, each valid UTF-8 JSON, a format first.  */
    for (i = 0; i < nreq; i++)
    {
        const char * nl = memchr(o.buf + a, '\n', o.len - a);
        size_t n;
        int st;

        FUZZ_REQUIRE(nl != NULL, "%lu answers for %lu requests",
                     (unsigned long) i, (unsigned long) nreq);
        n = (size_t) (nl - (o.buf + a));
        FUZZ_REQUIRE(json_ok(o.buf + a, n),
                     "the answer of line %ld is not UTF-8 JSON: %.*s",
                     lines[i], (int) n, o.buf + a);
        FUZZ_REQUIRE(n >= strlen(WC_JSON_OPEN)
                     && memcmp(o.buf + a, WC_JSON_OPEN,
                               strlen(WC_JSON_OPEN)) == 0,
                     "the answer of line %ld has no format key", lines[i]);
        st = answer_status(o.buf + a, n, lines[i]);
        if (rank(st) > rank(want))
            want = st;
        a += n + 1;
    }
    FUZZ_REQUIRE(a == o.len, "more answers than the %lu requests",
                 (unsigned long) nreq);
    FUZZ_REQUIRE(worst == want, "the batch's status is %d, not %d", worst,
                 want);
    fuzz_out_free(&o);
    wc_error_clear(err);
    return 0;
}
