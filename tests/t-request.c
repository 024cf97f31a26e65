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
   and random Table 2 modes, by routes independent of the request's: a
   cone request of the problem's text answers what the program prints for
   the same problem in a file (`cone --format=json`, or its error line
   and exit status as an error record) and, for a cone, the paper route's
   cone written out by this file's own printer; a modes request with
   witnesses answers what `modes --witness --format=json` prints, one
   without lists exactly the modes ref-kin.c's brute force finds.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/wait.h>

#include "wrenchcone.h"
#include "testutil.h"
#include "ref-kin.h"

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

/* (d) computes its expected answers by other routes than the request's:
   the cone by the paper's route (the request takes the direct one)
   printed from the cone's fields by cone_json below, not by the
   library's printer; the modes by ref-kin.c's brute force; and the whole
   answers as the program prints them (`$WRENCHCONE cone|modes
   --format=json FILE`), errors included.  */

/* The program runs on one iteration in PROG_EVERY (and on errors).  */
#define PROG_EVERY 5

/* W in SPEC 4.1's JSON, written here from the fields.  */
static void
cone_json(FILE * f, const wc_cone_t W)
{
    const fmpz_mat_struct * M[4] = { W->ineqs, W->eqs, W->rays, W->lines };
    static const char * key[4] = { "inequalities", "equalities", "rays",
        "lines" };
    slong m, i, j;

    if (W->empty)
    {
        fputs("{\"empty\": true}", f);
        return;
    }
    fprintf(f, "{\"empty\": false, \"dim\": %ld, \"lineality_dim\": %ld",
            (long) W->dim, (long) W->lineality_dim);
    for (m = 0; m < 4; m++)
    {
        fprintf(f, ", \"%s\": [", key[m]);
        for (i = 0; i < fmpz_mat_nrows(M[m]); i++)
        {
            fputs(i ? ", [" : "[", f);
            for (j = 0; j < fmpz_mat_ncols(M[m]); j++)
            {
                fputs(j ? ", \"" : "\"", f);
                fmpz_fprint(f, fmpz_mat_entry(M[m], i, j));
                fputc('"', f);
            }
            fputc(']', f);
        }
        fputc(']', f);
    }
    fputs(", \"faces\": [", f);
    for (i = 0; i < W->nfaces; i++)
    {
        const wc_face_struct * F = W->faces + i;

        fprintf(f, "%s{\"dim\": %ld, \"rays\": [", i ? ", " : "",
                (long) F->dim);
        for (j = 0; j < F->nrays; j++)
            fprintf(f, "%s%ld", j ? ", " : "", (long) F->rays[j]);
        fprintf(f, "], \"included\": %s}", F->included ? "true" : "false");
    }
    fputs("]}", f);
}

/* Run the program with the arguments args (shell words): *out := its
   stdout, *errout := its stderr (malloc'd); returns its exit status.  */
static int
run_program(char ** out, char ** errout, const char * args)
{
    const char * prog = getenv("WRENCHCONE");
    char ename[] = "/tmp/t-request-err-XXXXXX", * cmd = NULL, buf[4096];
    size_t clen = 0, olen = 0, n;
    FILE * c, * p, * o;
    int fd, st;

    if (prog == NULL)
        wctest_fail("WRENCHCONE is not set (make check sets it)");
    if ((fd = mkstemp(ename)) < 0)
        wctest_fail("mkstemp failed");
    close(fd);
    c = open_memstream(&cmd, &clen);
    fprintf(c, "'%s' %s 2>'%s'", prog, args, ename);
    fclose(c);
    o = open_memstream(out, &olen);
    if ((p = popen(cmd, "r")) == NULL)
        wctest_fail("cannot run %s", cmd);
    while ((n = fread(buf, 1, sizeof buf, p)) > 0)
        fwrite(buf, 1, n, o);
    st = pclose(p);
    fclose(o);
    o = open_memstream(errout, &olen);
    if ((p = fopen(ename, "r")) != NULL)
    {
        while ((n = fread(buf, 1, sizeof buf, p)) > 0)
            fwrite(buf, 1, n, o);
        fclose(p);
    }
    fclose(o);
    unlink(ename);
    free(cmd);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* The error record of the program's "wrenchcone: F:L:C: M" line.  */
static char *
error_record(const char * line, int st)
{
    const char * p = line, * c[3];
    char * rec = NULL, * file, * m, * msg;
    size_t len = 0;
    FILE * f;
    int i;

    if (strncmp(p, "wrenchcone: ", 12) != 0)
        wctest_fail("the program's message is not located: %s", line);
    p += 12;
    for (i = 0; i < 3; i++)
    {
        if ((c[i] = strchr(i ? c[i - 1] + 1 : p, ':')) == NULL)
            wctest_fail("the program's message is not located: %s", line);
    }
    file = strndup(p, c[0] - p);
    msg = strndup(c[2] + 2, strcspn(c[2] + 2, "\n"));
    m = json_string(msg);
    f = open_memstream(&rec, &len);
    fprintf(f, "{\"error\": {\"message\": %s, \"file\": \"%s\", \"line\": %ld, "
            "\"column\": %ld, \"status\": %d}}\n", m, file,
            strtol(c[0] + 1, NULL, 10), strtol(c[1] + 1, NULL, 10), st);
    fclose(f);
    free(file);
    free(msg);
    free(m);
    return rec;
}

/* One random problem: a cone request and two modes requests.  */
static void
check_random(slong i)
{
    wc_problem_t P, Q;
    wc_cone_t W;
    wc_error_t err;
    char mode[16], name[] = "/tmp/t-request-XXXXXX", ** modes = NULL;
    char * text = NULL, * lit, * req = NULL, * want = NULL, * out, * eout;
    char * args = NULL;
    size_t tlen = 0, rlen = 0, wlen = 0, alen = 0;
    slong count, k;
    FILE * f;
    int st, fd;

    wc_problem_init(P);
    wc_problem_init(Q);
    wc_cone_init(W, 3);
    wc_error_init(err);
    wctest_random_problem(P, 1, 4);
    wctest_random_mode(mode, P);
    f = open_memstream(&text, &tlen);
    wc_problem_fprint(f, P);
    fclose(f);
    lit = json_string(text);
    if (wc_problem_parse(Q, text, tlen, "<problem_text>", err) != WC_OK)
        wctest_fail_problem(P, mode, "iteration %ld: no round trip", (long) i);
    if ((fd = mkstemp(name)) < 0 || write(fd, text, tlen) != (ssize_t) tlen
        || close(fd) != 0)
        wctest_fail("cannot write %s", name);

    /* cone: the paper route's cone; the program's answer every
       PROG_EVERY iterations (it costs a process) and for every error */
    f = open_memstream(&req, &rlen);
    fprintf(f, "{\"command\": \"cone\", \"mode\": \"%s\", \"problem_text\": "
            "%s}", mode, lit);
    fclose(f);
    st = wc_wrench_cone(W, NULL, Q, mode, WC_METHOD_PAPER, err);
    if (st == WC_OK)
    {
        f = open_memstream(&want, &wlen);
        fprintf(f, "{\"mode\": \"%s\", \"cone\": ", mode);
        cone_json(f, W);
        fputs("}\n", f);
        fclose(f);
        expect(req, WC_OK, want);
        free(want);
    }
    if (st != WC_OK || i % PROG_EVERY == 0)
    {
        f = open_memstream(&args, &alen);
        fprintf(f, "cone --format=json '%s' %s", name, mode);
        fclose(f);
        st = run_program(&out, &eout, args);
        if (st == 0)
            expect(req, WC_OK, out);
        else
        {
            want = error_record(eout, st);
            expect(req, st, want);
            free(want);
        }
        free(out);
        free(eout);
        free(args);
    }
    free(req);

    /* a mode one letter too long: the program's error line */
    if (i % (2 * PROG_EVERY) == 0)
    {
        args = NULL;
        f = open_memstream(&args, &alen);
        fprintf(f, "cone --format=json '%s' %ss", name, mode);
        fclose(f);
        st = run_program(&out, &eout, args);
        if (st == 0)
            wctest_fail_problem(P, mode, "iteration %ld: the program took "
                                "mode %ss", (long) i, mode);
        want = error_record(eout, st);
        f = open_memstream(&req, &rlen);
        fprintf(f, "{\"command\": \"cone\", \"mode\": \"%ss\", "
                "\"problem_text\": %s}", mode, lit);
        fclose(f);
        expect(req, st, want);
        free(want);
        free(out);
        free(eout);
        free(req);
        free(args);
    }

    /* modes with witnesses: the program's answer */
    if (i % PROG_EVERY == 0)
    {
        args = NULL;
        f = open_memstream(&args, &alen);
        fprintf(f, "modes --witness --format=json '%s'", name);
        fclose(f);
        if (run_program(&out, &eout, args) != 0)
            wctest_fail_problem(P, mode, "iteration %ld: modes failed: %s",
                                (long) i, eout);
        f = open_memstream(&req, &rlen);
        fprintf(f, "{\"witness\": true, \"problem_text\": %s, \"command\": "
                "\"modes\"}", lit);
        fclose(f);
        expect(req, WC_OK, out);
        free(out);
        free(eout);
        free(req);
        free(args);
    }

    /* modes without: ref-kin.c's brute force */
    if (ref_modes_bruteforce(&modes, &count, Q) != 0)
        wctest_fail_problem(P, mode, "iteration %ld: ref-kin.c failed",
                            (long) i);
    f = open_memstream(&want, &wlen);
    fprintf(f, "{\"fixels\": %ld, \"modes\": [", (long) Q->n);
    for (k = 0; k < count; k++)
        fprintf(f, "%s\"%s\"", k ? ", " : "", modes[k]);
    fprintf(f, "], \"count\": %ld}\n", (long) count);
    fclose(f);
    f = open_memstream(&req, &rlen);
    fprintf(f, "{\"problem_text\": %s, \"command\": \"modes\"}", lit);
    fclose(f);
    expect(req, WC_OK, want);
    ref_modes_free(modes, count);
    free(req);
    free(want);

    unlink(name);
    free(lit);
    free(text);
    wc_error_clear(err);
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
