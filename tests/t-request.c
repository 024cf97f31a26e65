/* t-request.c -- the library's request entry point (lib/api/request.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   (a) The request of the issue, as written, answers exactly the Section 4
   cone W(na) that `cone --format=json` prints; inline problem text,
   wrenches as strings or JSON numbers answer the same.  (b) Errors are
   exact records with the message, file, line and column the command line
   prints, the status returned and err set alike; a request's own errors
   are located in it, shifted by wc_request_json_at's line.  (c) A
   comparison beyond its tolerance returns 4 with the comparison as the
   answer.  (d) On seeded random problems (degenerate layouts included)
   and random Table 2 modes, a cone request of the problem's text answers
   {"mode", "cone"} around wc_cone_fprint_json of wc_wrench_cone, or the
   error of wc_mode_check; a modes request wc_modes_fprint's JSON.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "wrenchcone.h"
#include "testutil.h"

static const char section4_na[] =
    "{\"mode\": \"na\", \"cone\": {\"empty\": false, \"dim\": 3, "
    "\"lineality_dim\": 0, \"inequalities\": [[\"-5\", \"2\", \"-5\"], "
    "[\"-1\", \"0\", \"1\"], [\"5\", \"2\", \"5\"]], \"equalities\": [], "
    "\"rays\": [[\"-1\", \"-5\", \"-1\"], [\"1\", \"-5\", \"1\"], "
    "[\"1\", \"0\", \"-1\"]], \"lines\": [], \"faces\": [{\"dim\": 0, "
    "\"rays\": [], \"included\": false}, {\"dim\": 1, \"rays\": [0], "
    "\"included\": false}, {\"dim\": 1, \"rays\": [1], \"included\": false}, "
    "{\"dim\": 1, \"rays\": [2], \"included\": true}, {\"dim\": 2, "
    "\"rays\": [0, 1], \"included\": false}, {\"dim\": 2, \"rays\": [0, 2], "
    "\"included\": true}, {\"dim\": 2, \"rays\": [1, 2], \"included\": true}, "
    "{\"dim\": 3, \"rays\": [0, 1, 2], \"included\": true}]}}\n";

#define SECTION4_TEXT \
    "mass 1\\ninertia 1\\ncom 0 0\\nfriction 1/5\\nshape disk 0 0 1\\n" \
    "fixel 0 -1 normal 0 1 touching\\nfixel 1 0 normal -1 0 near\\n"

/* Answer req (with wc_request_json_at when file is not NULL); its answer
   must be want (with or without the opening format key, which the answer
   must have) and its status st.  */
static void
expect_at(const char * req, const char * file, long line, int st,
          const char * want)
{
    char * out = NULL;
    const char * w;
    size_t len = 0, k = strlen(WC_JSON_OPEN);
    wc_error_t err;
    int got;

    wc_error_init(err);
    got = file != NULL
        ? wc_request_json_at(&out, &len, req, strlen(req), file, line, err)
        : wc_request_json(&out, &len, req, strlen(req), err);
    if (out == NULL)
        wctest_fail("%s: no answer", req);
    /* Every answer opens with the format key; want may leave it out.  */
    if (strncmp(out, WC_JSON_OPEN, k) != 0)
        wctest_fail("%s: the answer does not open with %s: %s", req,
                    WC_JSON_OPEN, out);
    w = strncmp(want, WC_JSON_OPEN, k) == 0 ? want + k : want + 1;
    if (got != st || strcmp(out + k, w) != 0 || len != k + strlen(w))
        wctest_fail("%s:\n got status %d: %s want status %d: %s", req, got,
                    out, st, want);
    if (st != WC_OK && st != WC_EDISAGREE && err->message == NULL)
        wctest_fail("%s: status %d without err set", req, st);
    free(out);
    wc_error_clear(err);
}

static void
expect(const char * req, int st, const char * want)
{
    expect_at(req, NULL, 1, st, want);
}

static void
check_answers(void)
{
    /* the request as the issue writes it */
    expect("{\"command\": \"cone\", \"problem\": \"data/section4.wc\", "
           "\"mode\": \"na\"}", WC_OK, section4_na);
    expect("{\"mode\": \"na\", \"problem_text\": \"" SECTION4_TEXT "\",\n"
           " \"command\": \"cone\", \"method\": \"paper\"}", WC_OK,
           section4_na);
    expect("{\"command\": \"classify\", \"problem\": \"data/section4.wc\", "
           "\"wrench\": [\"0\", \"-1\", \"0\"]}", WC_OK,
           "{\"wrench\": [\"0\", \"-1\", \"0\"], \"modes\": [\"ns\"], "
           "\"modes_complete\": true, \"weakly_stable\": true, "
           "\"strongly_stable\": true, \"strongly_stable_paper\": true, "
           "\"paper_vacuous\": false, \"motions\": [], "
           "\"static_c\": [\"1\", \"0\", \"0\", \"0\"]}\n");
    expect("{\"command\": \"classify\", \"problem\": \"data/section4.wc\", "
           "\"wrench\": [0, -1.0, 0e3]}", WC_OK,
           "{\"wrench\": [\"0\", \"-1\", \"0\"], \"modes\": [\"ns\"], "
           "\"modes_complete\": true, \"weakly_stable\": true, "
           "\"strongly_stable\": true, \"strongly_stable_paper\": true, "
           "\"paper_vacuous\": false, \"motions\": [], "
           "\"static_c\": [\"1\", \"0\", \"0\", \"0\"]}\n");
    expect("{\"command\": \"modes\", \"problem\": \"data/section4.wc\"}",
           WC_OK, "{\"fixels\": 2, \"modes\": [\"la\", \"ls\", \"na\", "
           "\"ns\", \"ra\", \"rs\", \"sa\", \"ss\"], \"count\": 8}\n");
    expect("{\"command\": \"feasible\", \"problem\": \"data/section4.wc\", "
           "\"mode\": \"na\"}", WC_OK, "{\"kind\": \"mode-feasibility\", "
           "\"mode\": \"na\", \"feasible\": true, \"witness\": [\"1\", \"0\", "
           "\"-1\"], \"constraints\": [{\"row\": [\"0\", \"1\", \"0\"], "
           "\"relation\": \"=\"}, {\"row\": [\"-1\", \"0\", \"-1\"], "
           "\"relation\": \"=\"}, {\"row\": [\"1\", \"0\", \"0\"], "
           "\"relation\": \">\"}], \"problem\": {\"com\": [\"0\", \"0\"], "
           "\"fixels\": [{\"point\": [\"0\", \"-1\"], \"normal\": [\"0\", "
           "\"1\"], \"state\": \"touching\"}, {\"point\": [\"1\", \"0\"], "
           "\"normal\": [\"-1\", \"0\"], \"state\": \"near\"}]}}\n");
}

static void
check_errors(void)
{
    expect("{\"command\": \"cone\", \"problem\": \"data/section4.wc\", "
           "\"mode\": \"nx\"}", WC_EINPUT,
           "{\"error\": {\"message\": \"unknown mode letter 'x'\", "
           "\"file\": \"<mode>\", \"line\": 1, \"column\": 2, "
           "\"status\": 1}}\n");
    expect("{\"command\": \"cone\", \"problem\": \"data/no-such.wc\", "
           "\"mode\": \"na\"}", WC_EINPUT,
           "{\"error\": {\"message\": \"cannot open: No such file or "
           "directory\", \"file\": \"data/no-such.wc\", \"line\": null, "
           "\"column\": null, \"status\": 1}}\n");
    expect("{\"command\": \"modes\", \"problem_text\": \"mass 1\\nbogus\"}",
           WC_EINPUT, "{\"error\": {\"message\": \"unknown keyword 'bogus'\", "
           "\"file\": \"<problem_text>\", \"line\": 2, \"column\": 1, "
           "\"status\": 1}}\n");
    expect("{\"command\": \"classify\", \"problem\": \"data/section4.wc\", "
           "\"wrench\": [\"0\", \"1/0\", \"0\"]}", WC_EINPUT,
           "{\"error\": {\"message\": \"division by zero in '1/0'\", "
           "\"file\": \"<wrench>\", \"line\": 1, \"column\": 3, "
           "\"status\": 1}}\n");
    expect("{\"command\": \"cone\",\n \"mode\": \"na\"}", WC_EUSAGE,
           "{\"error\": {\"message\": \"the request needs \\\"problem\\\" "
           "(a file) or \\\"problem_text\\\"\", \"file\": \"<request>\", "
           "\"line\": 1, \"column\": 1, \"status\": 2}}\n");
    expect_at("{\"command\": \"cone\",\n \"mode\": \"na\", \"bias\": 1}",
              "f.jsonl", 7, WC_EUSAGE,
              "{\"error\": {\"message\": \"\\\"bias\\\" is not a key of a "
              "cone request\", \"file\": \"f.jsonl\", \"line\": 8, "
              "\"column\": 16, \"status\": 2}}\n");
    expect_at("\n{\"command\": ", "f.jsonl", 3, WC_EUSAGE,
              "{\"error\": {\"message\": \"unexpected end of input\", "
              "\"file\": \"f.jsonl\", \"line\": 4, \"column\": 13, "
              "\"status\": 2}}\n");
    expect("\"cone\"", WC_EUSAGE, "{\"error\": {\"message\": \"a request is "
           "a JSON object, not a string\", \"file\": \"<request>\", "
           "\"line\": 1, \"column\": 1, \"status\": 2}}\n");
    expect("{\"command\": \"plan\", \"problem\": \"data/section4.wc\", "
           "\"complete\": 1}", WC_EUSAGE, "{\"error\": {\"message\": "
           "\"\\\"complete\\\" takes true or false\", \"file\": "
           "\"<request>\", \"line\": 1, \"column\": 64, \"status\": 2}}\n");
    expect("{\"command\": \"cone\", \"problem\": \"data/section4.wc\", "
           "\"mode\": \"na\", \"arith\": \"double\"}", WC_EUSAGE,
           "{\"error\": {\"message\": \"\\\"arith\\\": \\\"double\\\" needs "
           "\\\"method\\\": \\\"paper\\\"\", \"file\": \"<request>\", "
           "\"line\": 1, \"column\": 75, \"status\": 2}}\n");
}

/* The comparison is the answer, with status 4.  */
static void
check_disagree(void)
{
    const char * req = "{\"command\": \"compare\", \"problem\": "
        "\"data/section4.wc\", \"mode\": \"sa\", \"foreign_text\": "
        "\"V-representation\\nbegin\\n1 4 rational\\n0 1 0 -1\\nend\\n\"}";
    char * out = NULL;
    size_t len = 0;
    wc_error_t err;
    int st;

    wc_error_init(err);
    st = wc_request_json(&out, &len, req, strlen(req), err);
    if (st != WC_EDISAGREE || out == NULL
        || strncmp(out, WC_JSON_OPEN "\"exact\": {\"arith\": \"gmp\", "
                   "\"problem\": \"data/section4.wc\", \"mode\": \"sa\"",
                   strlen(WC_JSON_OPEN) + 67) != 0
        || strstr(out, "\"file\": \"<foreign_text>\"") == NULL
        || strstr(out, "\"within_tolerance\": false") == NULL
        || out[len - 1] != '\n' || err->message != NULL)
        wctest_fail("compare beyond tolerance: status %d, %s", st, out);
    free(out);
    wc_error_clear(err);
}

/* s as a JSON string literal, malloc'd.  */
static char *
json_string(const char * s)
{
    char * buf = NULL;
    size_t len = 0;
    FILE * f = open_memstream(&buf, &len);

    if (f == NULL)
        wctest_fail("out of memory");
    wc_fprint_json_string(f, s);
    fclose(f);
    return buf;
}

/* One random problem: a cone request and a modes request against the
   library's own calls.  */
static void
check_random(slong i)
{
    wc_problem_t P, Q;
    wc_cone_t W;
    wc_modes_t M;
    wc_error_t err;
    char mode[16], * text = NULL, * lit, * req = NULL, * want = NULL;
    size_t tlen = 0, rlen = 0, wlen = 0;
    FILE * f;
    int st;

    wc_problem_init(P);
    wc_problem_init(Q);
    wc_cone_init(W, 3);
    wc_modes_init(M);
    wc_error_init(err);
    wctest_random_problem(P, 1, 4);
    wctest_random_mode(mode, P);
    f = open_memstream(&text, &tlen);
    wc_problem_fprint(f, P);
    fclose(f);
    lit = json_string(text);
    if (wc_problem_parse(Q, text, tlen, "<problem_text>", err) != WC_OK)
        wctest_fail_problem(P, mode, "iteration %ld: no round trip", (long) i);

    f = open_memstream(&want, &wlen);
    st = wc_mode_check(Q, mode, WC_TABLE_CONE, err);
    if (st == WC_OK)
        st = wc_wrench_cone(W, NULL, Q, mode, WC_METHOD_DIRECT, err);
    if (st == WC_OK)
    {
        fprintf(f, WC_JSON_OPEN "\"mode\": \"%s\", \"cone\": ", mode);
        wc_cone_fprint_json(f, W);
        fputs("}\n", f);
    }
    else
    {
        char * m = json_string(err->message);

        fprintf(f, "{\"error\": {\"message\": %s, \"file\": \"%s\", "
                "\"line\": %ld, \"column\": %ld, \"status\": %d}}\n", m,
                err->file, err->line, err->col, st);
        free(m);
    }
    fclose(f);
    f = open_memstream(&req, &rlen);
    fprintf(f, "{\"command\": \"cone\", \"mode\": \"%s\", \"problem_text\": "
            "%s}", mode, lit);
    fclose(f);
    expect(req, st, want);
    free(req);
    free(want);

    f = open_memstream(&want, &wlen);
    st = wc_modes_enumerate(M, Q, err);
    if (st != WC_OK)
        wctest_fail_problem(P, mode, "iteration %ld: modes failed", (long) i);
    wc_modes_fprint(f, M, 1, 1);
    fclose(f);
    f = open_memstream(&req, &rlen);
    fprintf(f, "{\"witness\": true, \"problem_text\": %s, \"command\": "
            "\"modes\"}", lit);
    fclose(f);
    expect(req, WC_OK, want);
    free(req);
    free(want);
    free(lit);
    free(text);
    wc_error_clear(err);
    wc_modes_clear(M);
    wc_cone_clear(W);
    wc_problem_clear(Q);
    wc_problem_clear(P);
}

int
main(void)
{
    const char * top = getenv("top_srcdir");
    slong i, iters;

    wctest_init("t-request");
    /* The requests name data/ files as a user in the source tree would.  */
    if (top == NULL || chdir(top) != 0)
    {
        fprintf(stderr, "t-request: top_srcdir is not set or not a "
                "directory: skipped\n");
        return 77;
    }
    check_answers();
    check_errors();
    check_disagree();
    iters = wctest_iters(60);
    for (i = 0; i < iters; i++)
        if (wctest_iter(i))
            check_random(i);
    flint_cleanup_master();
    return 0;
}
