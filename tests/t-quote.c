/* t-quote.c -- input echoed into output: quoted, bounded, valid UTF-8
   (lib/core/text.c, the error records, the request reader, wc_batch).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   (a) _wc_quote on a table of inputs gives exact bytes: UTF-8 as it is,
   control bytes and bytes outside valid UTF-8 as \xNN, C1 controls, the
   line separators and invisible format characters as \uXXXX, cut after 64 bytes on a character
   boundary with "...".  On random byte strings its output is, by this
   file's own UTF-8 reader, valid UTF-8 without control characters,
   within WC_QUOTE_SIZE, unchanged when quoted again, and the input when
   the input needed no quoting.  (b) The JSON string writer writes every
   byte that is not UTF-8 by its code.  (c) An error record's file and
   message are quoted and bounded whatever the caller passes.  (d) The
   answers of requests that echo input (an invalid escape after a raw
   byte, an unknown command or key with control characters, a number cut
   inside a character, a path of 100,000 bytes) are exact bytes; a
   request at line LONG_MAX is located there.  (e) A problem's name is
   UTF-8 without control characters but the tab.  (f) wc_batch's status:
   an error record outranks a comparison beyond its tolerance, and an
   internal failure any other error.  */

#include <config.h>

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "wrenchcone.h"
#include "testutil.h"
#include "core/text.h"
#include "api/batch.h"

/* ------------------------------------------------------------------ */
/* An independent UTF-8 reader: the code point at s[0..n), its length in
   *k; -1 when the bytes there are not a valid UTF-8 character.  */

static long
decode(const unsigned char * s, size_t n, size_t * k)
{
    long c;
    size_t m, i;

    if (s[0] < 0x80)
    {
        *k = 1;
        return s[0];
    }
    if ((s[0] & 0xe0) == 0xc0)
        m = 2, c = s[0] & 0x1f;
    else if ((s[0] & 0xf0) == 0xe0)
        m = 3, c = s[0] & 0x0f;
    else if ((s[0] & 0xf8) == 0xf0)
        m = 4, c = s[0] & 0x07;
    else
        return -1;
    if (n < m)
        return -1;
    for (i = 1; i < m; i++)
    {
        if ((s[i] & 0xc0) != 0x80)
            return -1;
        c = (c << 6) | (s[i] & 0x3f);
    }
    /* shortest form only, no surrogates, nothing above U+10FFFF */
    if ((m == 2 && c < 0x80) || (m == 3 && c < 0x800)
        || (m == 4 && c < 0x10000) || (c >= 0xd800 && c <= 0xdfff)
        || c > 0x10ffff)
        return -1;
    *k = m;
    return c;
}

/* Whether s[0..n) is valid UTF-8 and, with no_controls, holds no control
   character (C0, DEL, C1), no line or paragraph separator and no
   invisible format character (zero-width, bidirectional, U+FEFF).  */
static int
clean_utf8(const char * s, size_t n, int no_controls)
{
    const unsigned char * u = (const unsigned char *) s;
    size_t i = 0, k;

    while (i < n)
    {
        long c = decode(u + i, n - i, &k);

        if (c < 0)
            return 0;
        if (no_controls && (c < 0x20 || (c >= 0x7f && c <= 0x9f)
                            || (c >= 0x200b && c <= 0x200f)
                            || (c >= 0x2028 && c <= 0x202e)
                            || (c >= 0x2060 && c <= 0x2064)
                            || (c >= 0x2066 && c <= 0x2069) || c == 0xfeff))
            return 0;
        i += k;
    }
    return 1;
}

/* ------------------------------------------------------------------ */
/* (a) _wc_quote.  */

static void
expect_quote(const char * s, size_t len, size_t max, const char * want)
{
    char * d = malloc(WC_QUOTE_SIZE(max));
    size_t n;

    n = _wc_quote(d, s, len, max);
    if (n != strlen(want) || strcmp(d, want) != 0)
        wctest_fail("_wc_quote(\"%s\", %lu): got \"%s\", want \"%s\"", want,
                    (unsigned long) max, d, want);
    free(d);
}

static void
check_quote_table(void)
{
    char s[300], want[300];
    int i;

    expect_quote("abc", 3, 64, "abc");
    expect_quote("a\tb\n\x7f", 5, 64, "a\\x09b\\x0a\\x7f");
    expect_quote("\xc3\xa9t\xc3\xa9", 5, 64, "\xc3\xa9t\xc3\xa9");
    /* a lone continuation byte, a lead byte without its tail, an overlong
       form, a surrogate, a byte that never occurs */
    expect_quote("\x80", 1, 64, "\\x80");
    expect_quote("\xe2\x82x", 3, 64, "\\xe2\\x82x");
    expect_quote("\xc0\xaf", 2, 64, "\\xc0\\xaf");
    expect_quote("\xed\xa0\x80", 3, 64, "\\xed\\xa0\\x80");
    expect_quote("\xff\xf5", 2, 64, "\\xff\\xf5");
    /* C1 NEL, U+2028, U+2029: line breaks to some readers */
    expect_quote("a\xc2\x85" "b\xe2\x80\xa8\xe2\x80\xa9", 10, 64,
                 "a\\u0085b\\u2028\\u2029");
    expect_quote("\xf0\x9f\x99\x82", 4, 64, "\xf0\x9f\x99\x82");
    /* a byte order mark, a right-to-left override, a zero-width space */
    expect_quote("\xef\xbb\xbf" "a\xe2\x80\xae" "b\xe2\x80\x8b", 11, 64,
                 "\\ufeffa\\u202eb\\u200b");
    /* cut: 63 bytes and a 2-byte character: the character is left out */
    memset(s, 'a', 63);
    memcpy(s + 63, "\xc3\xa9zz", 4);
    memcpy(want, s, 63);
    strcpy(want + 63, "...");
    expect_quote(s, 67, 64, want);
    /* exactly 64 bytes: no cut */
    memcpy(s + 62, "\xc3\xa9", 2);
    memcpy(want, s, 64);
    want[64] = '\0';
    expect_quote(s, 64, 64, want);
    /* a 4-byte character across the cut, and raw bytes up to it */
    memset(s, 'b', 62);
    memcpy(s + 62, "\xf0\x9f\x99\x82", 4);
    memcpy(want, s, 62);
    strcpy(want + 62, "...");
    expect_quote(s, 66, 64, want);
    for (i = 0; i < 64; i++)
        s[i] = (char) 0xfe;
    for (i = 0; i < 64; i++)
        memcpy(want + 4 * i, "\\xfe", 4);
    strcpy(want + 256, "...");
    expect_quote(s, 65, 64, want);
    expect_quote("", 0, 64, "");
    expect_quote("xy", 2, 0, "...");
}

static void
check_quote_random(void)
{
    slong i, iters = wctest_iters(3000);
    char s[200], d[WC_QUOTE_SIZE(150)], e[WC_QUOTE_SIZE(4 * 150 + 8)];

    for (i = 0; i < iters; i++)
    {
        size_t len, max, n, m, j;

        if (!wctest_iter(i))
            continue;
        len = (size_t) wctest_randint(0, 199);
        max = (size_t) wctest_randint(0, 150);
        for (j = 0; j < len; j++)
        {
            /* mostly the bytes of UTF-8, some controls and stray bytes */
            static const unsigned char pick[] = {
                'a', ' ', '\\', '\n', 0x00, 0x7f, 0x80, 0xbf, 0xc2, 0xc3,
                0xa9, 0x85, 0xe2, 0x80, 0xa8, 0xae, 0x8b, 0xed, 0xa0, 0xef,
                0xbb, 0xf0, 0x9f, 0xf4, 0x90, 0xff };

            s[j] = (char) pick[wctest_randint(0, sizeof pick - 1)];
        }
        n = _wc_quote(d, s, len, max);
        if (n != strlen(d) || n + 1 > WC_QUOTE_SIZE(max))
            wctest_fail("_wc_quote: length %lu, room %lu", (unsigned long) n,
                        (unsigned long) WC_QUOTE_SIZE(max));
        if (!clean_utf8(d, n, 1))
            wctest_fail("_wc_quote: not clean UTF-8: %s", d);
        /* no '.' among the bytes: a "..." is the mark of a cut */
        if ((n >= 3 && strcmp(d + n - 3, "...") == 0) != (len > max))
            wctest_fail("_wc_quote: a cut of %lu bytes to %lu not marked",
                        (unsigned long) len, (unsigned long) max);
        if (len <= max)
        {
            m = _wc_quote(e, d, n, n);
            if (m != n || memcmp(e, d, n) != 0)
                wctest_fail("_wc_quote: quoting again changes %s", d);
            if (clean_utf8(s, len, 1) && (n != len || memcmp(s, d, n) != 0))
                wctest_fail("_wc_quote: clean input changed: %s", d);
        }
    }
}

/* ------------------------------------------------------------------ */
/* (b) The JSON string writer, (c) error records.  */

static void
check_json_string(void)
{
    char * buf = NULL;
    size_t len = 0;
    FILE * f = open_memstream(&buf, &len);
    const char * want = "\"a\\\\x\\\"\\u0001\\n\xc3\xa9\\\\xff\\\\xc3\"";

    _wc_fput_json_string(f, "a\\x\"\x01\n\xc3\xa9\xff\xc3");
    fclose(f);
    if (strcmp(buf, want) != 0)
        wctest_fail("JSON string: got %s, want %s", buf, want);
    free(buf);
}

static void
check_error_record(void)
{
    wc_error_t err;
    char * path = malloc(5001), * want = malloc(1100);

    wc_error_init(err);
    wc_error_set(err, WC_EINPUT, "f\xff.wc", 2, 3, "bad '%s'", "\x01\xc3");
    if (strcmp(err->file, "f\\xff.wc") != 0
        || strcmp(err->message, "bad '\\x01\\xc3'") != 0)
        wctest_fail("error record: file %s, message %s", err->file,
                    err->message);
    /* a path of 5000 bytes: cut after 1024, inside no character */
    memset(path, 'p', 1023);
    memset(path + 1023, 0xc3, 1);
    memset(path + 1024, 0xa9, 1);
    memset(path + 1025, 'q', 3975);
    path[5000] = '\0';
    memcpy(want, path, 1023);
    strcpy(want + 1023, "...");
    wc_error_set(err, WC_EINPUT, path, 0, 0, "cannot open: %s", "x");
    if (strcmp(err->file, want) != 0)
        wctest_fail("error record: a 5000-byte path kept as %lu bytes",
                    (unsigned long) strlen(err->file));
    /* a message of 5000 bytes: cut after WC_MESSAGE_MAX */
    wc_error_set(err, WC_EINPUT, NULL, 0, 0, "%s", path);
    if (strlen(err->message) != WC_MESSAGE_MAX + 3
        || strcmp(err->message + WC_MESSAGE_MAX, "...") != 0)
        wctest_fail("error record: a 5000-byte message kept as %lu bytes",
                    (unsigned long) strlen(err->message));
    wc_error_clear(err);
    free(path);
    free(want);
}

/* ------------------------------------------------------------------ */
/* (d) Requests.  */

/* Answer req[0..len) at line; the answer must be want (after the format
   key) and its status st.  */
static void
expect_request(const char * req, size_t len, long line, int st,
               const char * want)
{
    char * out = NULL;
    size_t outlen = 0, k = strlen(WC_JSON_OPEN);
    wc_error_t err;
    int got;

    wc_error_init(err);
    got = wc_request_json_at(&out, &outlen, req, len, "r.jsonl", line, err);
    if (out == NULL || got != st || strncmp(out, WC_JSON_OPEN, k) != 0
        || strcmp(out + k, want) != 0)
        wctest_fail("request %.60s:\n got %d: %s want %d: %s%s", req, got,
                    out, st, WC_JSON_OPEN, want);
    if (!clean_utf8(out, outlen, 0))
        wctest_fail("request %.60s: the answer is not UTF-8", req);
    free(out);
    wc_error_clear(err);
}

#define REQ(s) s, sizeof s - 1

static void
check_requests(void)
{
    char req[400], want[600];
    size_t n;
    int i;
    char * big, * bigwant;

    /* an invalid escape after a raw byte: quoted by its code */
    expect_request(REQ("{\"command\": \"x\\\xff\"}"), 1, WC_EUSAGE,
                   "\"error\": {\"message\": \"invalid escape '\\\\\\\\xff'\", "
                   "\"file\": \"r.jsonl\", \"line\": 1, \"column\": 15, "
                   "\"status\": 2}}\n");
    expect_request(REQ("{\"command\": \"\\u0\xc3\xa9\x80\"}"), 1, WC_EUSAGE,
                   "\"error\": {\"message\": \"invalid escape '\\\\u0"
                   "\xc3\xa9\\\\x80'\", \"file\": \"r.jsonl\", \"line\": 1, "
                   "\"column\": 14, \"status\": 2}}\n");
    /* a raw byte between the values */
    expect_request(REQ("{\"command\": \"cone\"\xfe}"), 1, WC_EUSAGE,
                   "\"error\": {\"message\": \"expected ',' or '}', found "
                   "'\\\\xfe'\", \"file\": \"r.jsonl\", \"line\": 1, "
                   "\"column\": 19, \"status\": 2}}\n");
    /* an unknown command and key with control characters: one line */
    expect_request(REQ("{\"command\": \"a\\nb\\u2028\"}"), 1, WC_EUSAGE,
                   "\"error\": {\"message\": \"unknown command "
                   "'a\\\\x0ab\\\\u2028' (cone, modes, feasible, classify, "
                   "stability, plan, sweep, verify, compare, random, draw or "
                   "report)\", \"file\": \"r.jsonl\", \"line\": 1, "
                   "\"column\": 13, \"status\": 2}}\n");
    expect_request(REQ("{\"command\": \"modes\", \"problem\": \"p\", "
                       "\"\\t\": 1}"), 2, WC_EUSAGE,
                   "\"error\": {\"message\": \"\\\"\\\\x09\\\" is not a key "
                   "of a modes request\", \"file\": \"r.jsonl\", \"line\": 2, "
                   "\"column\": 38, \"status\": 2}}\n");
    /* a number of 1 + 2 * 40 bytes, cut after 63 (not 64: inside the
       32nd character) */
    n = (size_t) sprintf(req, "{\"command\": \"classify\", \"problem\": "
                         "\"data/section4.wc\", \"wrench\": [\"a");
    for (i = 0; i < 40; i++)
        n += (size_t) sprintf(req + n, "\xc3\xa9");
    n += (size_t) sprintf(req + n, "\", 0, 0]}");
    n = (size_t) sprintf(want, "\"error\": {\"message\": \"bad number 'a");
    for (i = 0; i < 31; i++)
        n += (size_t) sprintf(want + n, "\xc3\xa9");
    sprintf(want + n, "...'\", \"file\": \"<wrench>\", \"line\": 1, "
            "\"column\": 1, \"status\": 1}}\n");
    expect_request(req, strlen(req), 1, WC_EINPUT, want);
    /* the line of a request at LONG_MAX, and an error on its second line:
       no overflow, the largest line there is */
    sprintf(want, "\"error\": {\"message\": \"\\\"x\\\" is not a key of a "
            "modes request\", \"file\": \"r.jsonl\", \"line\": %ld, "
            "\"column\": 1, \"status\": 2}}\n", LONG_MAX);
    expect_request(REQ("{\"command\": \"modes\", \"problem\": \"p\",\n"
                       "\"x\": 1}"), LONG_MAX, WC_EUSAGE, want);
    sprintf(want, "\"error\": {\"message\": \"unexpected end of input\", "
            "\"file\": \"r.jsonl\", \"line\": %ld, \"column\": 1, "
            "\"status\": 2}}\n", LONG_MAX);
    expect_request(REQ("{\n"), LONG_MAX, WC_EUSAGE, want);
    sprintf(want, "\"error\": {\"message\": \"unexpected end of input\", "
            "\"file\": \"r.jsonl\", \"line\": %ld, \"column\": 2, "
            "\"status\": 2}}\n", LONG_MAX);
    expect_request(REQ("{"), LONG_MAX, WC_EUSAGE, want);
    /* a path of 100,000 bytes: the record names its first 1024 */
    big = malloc(100100);
    bigwant = malloc(2000);
    n = (size_t) sprintf(big, "{\"command\": \"modes\", \"problem\": \"");
    memset(big + n, 'd', 100000);
    strcpy(big + n + 100000, "\"}");
    n = (size_t) sprintf(bigwant, "\"error\": {\"message\": \"cannot open: "
                         "File name too long\", \"file\": \"");
    memset(bigwant + n, 'd', 1024);
    strcpy(bigwant + n + 1024, "...\", \"line\": null, \"column\": null, "
           "\"status\": 1}}\n");
    expect_request(big, strlen(big), 1, WC_EINPUT, bigwant);
    free(big);
    free(bigwant);
}

/* ------------------------------------------------------------------ */
/* (e) A problem's name.  */

static void
expect_name_error(const char * text, const char * msg, long col)
{
    wc_problem_t P;
    wc_error_t err;
    int st;

    wc_problem_init(P);
    wc_error_init(err);
    st = wc_problem_parse(P, text, strlen(text), "n.wc", err);
    if (st != WC_EINPUT || strcmp(err->message, msg) != 0 || err->line != 1
        || err->col != col)
        wctest_fail("name %s: status %d, %ld:%ld: %s", text, st, err->line,
                    err->col, err->message);
    wc_problem_clear(P);
    wc_error_clear(err);
}

static void
check_names(void)
{
    static const char rest[] = "\nfixel 0 -1 normal 0 1 touching\n";
    char text[200];
    wc_problem_t P;
    wc_error_t err;

    expect_name_error("name \"a\xff\"", "invalid UTF-8 in string", 8);
    expect_name_error("name \"ab\xc3\"", "invalid UTF-8 in string", 9);
    expect_name_error("name \"a\rb\"", "control character '\\x0d' in string",
                      8);
    expect_name_error("name \"\x7f\"", "control character '\\x7f' in string",
                      7);
    expect_name_error("name \"\\\xc3\xa9\"", "bad escape '\\\xc3\xa9' in "
                      "string", 7);
    /* UTF-8 is a name */
    sprintf(text, "name \"\xc3\xa9t\xc3\xa9\t\\\"1\\\"\"%s", rest);
    wc_problem_init(P);
    wc_error_init(err);
    if (wc_problem_parse(P, text, strlen(text), "n.wc", err) != WC_OK
        || strcmp(P->name, "\xc3\xa9t\xc3\xa9\t\"1\"") != 0)
        wctest_fail("a UTF-8 name: %s", err->message);
    wc_problem_clear(P);
    wc_error_clear(err);
}

/* ------------------------------------------------------------------ */
/* (f) wc_batch's status.  */

static int
batch_status(const char * lines)
{
    FILE * in = fmemopen((void *) lines, strlen(lines), "r");
    FILE * out = fopen("/dev/null", "w");
    wc_error_t err;
    int worst = -1, st;

    wc_error_init(err);
    st = wc_batch(&worst, out, in, "b.jsonl", 1, err);
    if (st != WC_OK)
        wctest_fail("batch: status %d: %s", st, err->message);
    fclose(in);
    fclose(out);
    wc_error_clear(err);
    return worst;
}

#define DISAGREE "{\"command\": \"compare\", \"problem\": " \
    "\"data/section4.wc\", \"mode\": \"sa\", \"foreign_text\": " \
    "\"V-representation\\nbegin\\n1 4 rational\\n0 1 0 -1\\nend\\n\"}\n"
#define BADINPUT "{\"command\": \"cone\", \"problem\": " \
    "\"data/section4.wc\", \"mode\": \"nx\"}\n"
#define BADUSAGE "{\"command\": \"cone\"}\n"
#define OK "{\"command\": \"modes\", \"problem\": \"data/section4.wc\"}\n"
/* a file that fails while it is read: an internal failure (Linux) */
#define INTERNAL "{\"command\": \"modes\", \"problem\": \"/proc/self/mem\"}\n"

static void
check_batch_status(void)
{
    struct { const char * lines; int want; } c[] = {
        { OK OK, WC_OK },
        { OK DISAGREE OK, WC_EDISAGREE },
        { DISAGREE BADINPUT, WC_EINPUT },
        { BADINPUT DISAGREE, WC_EINPUT },
        { BADUSAGE BADINPUT DISAGREE, WC_EUSAGE },
        { DISAGREE INTERNAL, WC_EINTERNAL },
        { INTERNAL DISAGREE BADUSAGE, WC_EINTERNAL },
    };
    size_t i;
    int internal = batch_status(INTERNAL) == WC_EINTERNAL;

    if (!internal)
        printf("t-quote: /proc/self/mem reads without an I/O error here: "
               "the cases of an internal failure are left out\n");
    for (i = 0; i < sizeof c / sizeof c[0]; i++)
    {
        int got;

        if (!internal && strstr(c[i].lines, "/proc/") != NULL)
            continue;
        if ((got = batch_status(c[i].lines)) != c[i].want)
            wctest_fail("batch case %lu: status %d, want %d",
                        (unsigned long) i, got, c[i].want);
    }
}

int
main(void)
{
    const char * top = getenv("top_srcdir");

    wctest_init("t-quote");
    check_quote_table();
    check_quote_random();
    check_json_string();
    check_error_record();
    check_names();
    /* The requests name data/ files as a user in the source tree would.  */
    if (top == NULL || chdir(top) != 0)
    {
        fprintf(stderr, "t-quote: top_srcdir is not set or not a "
                "directory: skipped\n");
        return 77;
    }
    check_requests();
    check_batch_status();
    flint_cleanup_master();
    return 0;
}
