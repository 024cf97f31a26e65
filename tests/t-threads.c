/* t-threads.c -- requests answered by many threads at once are answered
   exactly as by one (lib/api/request.c, lib/api/batch.c, the state the
   library keeps per thread or behind cddlib's lock).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   (a) A seeded mix of requests -- cone (direct, paper, paper in doubles,
   traced), modes, feasible, classify, stability (with and without a
   bias), plan (with and without a wrench), compare (within and beyond
   the tolerance) on the data/ problems and on random problems given as
   problem_text, with random modes, and errors of every kind: a missing
   file, a bad problem, a bad mode, a bad number, bad JSON, an unknown
   key -- is answered once in the main thread; then NTHREADS threads
   answer every request twice, in a seeded shuffled order, and each
   answer must be the same bytes with the same status and the same error
   record.  (b) wc_batch on the same requests as JSON Lines gives the same
   bytes and worst status with 2, 3 and NTHREADS jobs as with 1, and
   those bytes are the single-threaded answers of the lines in order
   (requests located in the batch's file and line).  (c) The progress
   hook is the calling thread's: a hook set in one thread hears nothing
   of another thread's stability request, and hears its own.  */

#include <config.h>

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "wrenchcone.h"
#include "testutil.h"

#define NTHREADS 8

/* The data/ problems and some of their modes (`wrenchcone modes`).  */
static const struct
{
    const char * path;
    const char * modes[4];
}
files[] = {
    { "data/section4.wc", { "na", "ls", "ra", "ss" } },
    { "data/disk-two-fixels.wc", { "ll", "ns", "rr", "sn" } },
    { "data/peg-in-hole.wc", { "lla", "nns", "rna", "rrs" } },
    { "data/three-fixels.wc", { "aaa", "asa", "saa", "sss" } },
    { "data/three-fixels-insert.wc", { "aas", "ass", "sas", "ssa" } },
    { "data/disk-two-fixels-insert.wc", { "aa", "as", "sa", "ss" } }
};
#define NFILES ((slong) (sizeof files / sizeof files[0]))

/* One request and its single-threaded answer.  */
typedef struct
{
    char * req;
    char * out;
    size_t outlen;
    int status;
    char * err;         /* wc_error_format of err, or NULL when unset */
}
item;

static item * items;
static slong nitems;

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

/* A random number as a request writes it: a JSON number or a string.  */
static void
put_number(FILE * f)
{
    slong p = wctest_randint(-6, 6), q = wctest_randint(1, 4);

    if (wctest_chance(1, 3))
        fprintf(f, "%ld", (long) p);
    else if (wctest_chance(1, 20))
        fputs("\"1/0\"", f);            /* a bad number */
    else
        fprintf(f, "\"%ld/%ld\"", (long) p, (long) q);
}

static void
put_wrench(FILE * f, const char * key)
{
    int k;

    fprintf(f, ", \"%s\": [", key);
    for (k = 0; k < 3; k++)
    {
        if (k)
            fputs(", ", f);
        put_number(f);
    }
    putc(']', f);
}

/* A mode: usually the one put_problem chose (one of the problem's
   modes), else Table 2 letters, as many as fixels, now and then one too
   few or a letter no table has.  */
static void
random_mode(char * mode, slong n)
{
    static const char letters[] = "slrnmau";
    slong i;

    if (mode[0] != '\0' && wctest_chance(3, 4))
        return;
    if (wctest_chance(1, 12))
        n = n > 1 ? n - 1 : 2;
    for (i = 0; i < n; i++)
        mode[i] = letters[wctest_randint(0, 6)];
    if (wctest_chance(1, 25))
        mode[0] = 'q';
    mode[n] = '\0';
}

/* The problem: a data/ file, a random problem's text, or the odd
   failure; *n := its fixels (a guess for failures), mode := one of its
   modes, or "" when it has none known.  */
static void
put_problem(FILE * f, slong * n, char * mode)
{
    slong r = wctest_randint(0, 19);

    mode[0] = '\0';
    if (r < 12)
    {
        slong k = wctest_randint(0, NFILES - 1);

        fprintf(f, "\"problem\": \"%s\"", files[k].path);
        strcpy(mode, files[k].modes[wctest_randint(0, 3)]);
        *n = (slong) strlen(mode);
    }
    else if (r < 18)
    {
        wc_problem_t P;
        char * text = NULL, * lit;
        size_t len = 0;
        FILE * g;

        wc_problem_init(P);
        wctest_random_problem(P, 1, 3);
        g = open_memstream(&text, &len);
        if (g == NULL)
            wctest_fail("out of memory");
        wc_problem_fprint(g, P);
        fclose(g);
        lit = json_string(text);
        fprintf(f, "\"problem_text\": %s", lit);
        *n = P->n;
        wctest_random_mode(mode, P);
        free(lit);
        free(text);
        wc_problem_clear(P);
    }
    else if (r == 18)
    {
        fputs("\"problem\": \"data/no-such-file.wc\"", f);
        *n = 2;
    }
    else
    {
        fputs("\"problem_text\": \"mass 1\\nfixel 0 0 normal 0 0 "
              "touching\\n\"", f);
        *n = 1;
    }
}

/* One random request, malloc'd, on one line.  */
static char *
random_request(void)
{
    static const char * const commands[] = {
        "cone", "modes", "feasible", "classify", "stability", "plan",
        "compare"
    };
    char * buf = NULL, mode[8];
    size_t len = 0;
    FILE * f = open_memstream(&buf, &len);
    slong c = wctest_randint(0, 7), n;

    if (f == NULL)
        wctest_fail("out of memory");
    if (c == 7)
    {
        /* The request's own errors.  */
        static const char * const bad[] = {
            "{\"command\": \"cone\", \"problem\": \"data/section4.wc\"",
            "[1, 2]",
            "{\"command\": \"modes\", \"problem\": \"data/section4.wc\", "
            "\"mode\": \"na\"}",
            "{\"command\": \"fly\", \"problem\": \"data/section4.wc\"}",
            "{\"command\": \"classify\", \"problem\": \"data/section4.wc\", "
            "\"wrench\": [1, 2]}"
        };

        fputs(bad[wctest_randint(0, 4)], f);
        fclose(f);
        return buf;
    }
    fprintf(f, "{\"command\": \"%s\", ", commands[c]);
    if (c == 6)
    {
        /* compare: W(sa) of Section 4, given exactly or not.  */
        fputs("\"problem\": \"data/section4.wc\", \"mode\": \"sa\", "
              "\"foreign_text\": \"V-representation\\nlinearity 1 4\\n"
              "begin\\n 4 4 rational\\n 1 0 0 0\\n 0 0 1 0\\n", f);
        fputs(wctest_chance(1, 2) ? " 0 1 0 0\\n" : " 0 1 -1/1000 0\\n", f);
        fputs(" 0 0 0 1\\nend\\n\"", f);
        if (wctest_chance(1, 3))
            fputs(", \"tol\": 0.01", f);
        fputs("}", f);
        fclose(f);
        return buf;
    }
    put_problem(f, &n, mode);
    random_mode(mode, n);
    switch (c)
    {
    case 0:
        fprintf(f, ", \"mode\": \"%s\"", mode);
        switch (wctest_randint(0, 3))
        {
        case 1:
            fputs(", \"method\": \"paper\"", f);
            break;
        case 2:
            fputs(", \"method\": \"paper\", \"arith\": \"double\"", f);
            break;
        case 3:
            fprintf(f, ", \"method\": \"%s\", \"trace\": true",
                    wctest_chance(1, 2) ? "paper" : "direct");
            break;
        }
        break;
    case 1:
        if (wctest_chance(1, 2))
            fputs(", \"witness\": true", f);
        break;
    case 2:
        fprintf(f, ", \"mode\": \"%s\"", mode);
        break;
    case 3:
        put_wrench(f, "wrench");
        if (wctest_chance(1, 4))
            fputs(", \"max_modes\": 2", f);
        break;
    case 4:
        if (wctest_chance(1, 2))
            put_wrench(f, "bias");
        if (wctest_chance(1, 4))
            fputs(", \"length\": \"2\"", f);
        break;
    case 5:
        if (wctest_chance(1, 2))
            put_wrench(f, "wrench");
        if (wctest_chance(1, 3))
            fputs(", \"complete\": true", f);
        break;
    }
    fputs("}", f);
    fclose(f);
    return buf;
}

/* Answer req into *A (req, status, output and error).  */
static void
answer(item * A, const char * req)
{
    wc_error_t err;

    wc_error_init(err);
    A->req = (char *) req;
    A->status = wc_request_json(&A->out, &A->outlen, req, strlen(req), err);
    if (A->out == NULL)
        wctest_fail("%s: no answer", req);
    A->err = err->message != NULL ? wc_error_format(err) : NULL;
    wc_error_clear(err);
}

static void
item_clear(item * A)
{
    free(A->out);
    free(A->err);
}

/* ------------------------------------------------------------------ */
/* (a) threads on wc_request_json                                      */

static slong * order;           /* the work: item indices, shuffled */
static slong norder, next;
static pthread_mutex_t next_lock = PTHREAD_MUTEX_INITIALIZER;

static void *
answer_many(void * arg)
{
    (void) arg;
    for (;;)
    {
        item got;
        const item * want;
        slong k;

        pthread_mutex_lock(&next_lock);
        k = next < norder ? order[next++] : -1;
        pthread_mutex_unlock(&next_lock);
        if (k < 0)
            return NULL;
        want = items + k;
        answer(&got, want->req);
        if (got.status != want->status || got.outlen != want->outlen
            || memcmp(got.out, want->out, got.outlen) != 0
            || (got.err == NULL) != (want->err == NULL)
            || (got.err != NULL && strcmp(got.err, want->err) != 0))
            wctest_fail("request %ld in threads: %s\n got status %d: %s"
                        " (%s)\n want status %d: %s (%s)", (long) k,
                        want->req, got.status, got.out,
                        got.err ? got.err : "no error", want->status,
                        want->out, want->err ? want->err : "no error");
        item_clear(&got);
    }
}

static void
check_threads(void)
{
    pthread_t t[NTHREADS];
    slong i, j;
    int k;

    norder = 2 * nitems;
    order = malloc(norder * sizeof *order);
    if (order == NULL)
        wctest_fail("out of memory");
    for (i = 0; i < norder; i++)
        order[i] = i % nitems;
    for (i = norder - 1; i > 0; i--)
    {
        slong tmp = order[i];

        j = wctest_randint(0, i);
        order[i] = order[j];
        order[j] = tmp;
    }
    next = 0;
    for (k = 0; k < NTHREADS; k++)
        if (pthread_create(t + k, NULL, answer_many, NULL) != 0)
            wctest_fail("pthread_create failed");
    for (k = 0; k < NTHREADS; k++)
        pthread_join(t[k], NULL);
    free(order);
}

/* ------------------------------------------------------------------ */
/* (b) wc_batch                                                        */

/* The batch of the requests (a blank line among them) with jobs; its
   output, malloc'd, and *worst.  */
static char *
run_batch(size_t * len, int * worst, FILE * in, int jobs)
{
    char * buf = NULL;
    FILE * out = open_memstream(&buf, len);
    wc_error_t err;
    int st;

    if (out == NULL)
        wctest_fail("out of memory");
    wc_error_init(err);
    rewind(in);
    st = wc_batch(worst, out, in, "<batch>", jobs, err);
    if (st != WC_OK)
        wctest_fail("wc_batch with %d jobs: status %d, %s", jobs, st,
                    err->message);
    fclose(out);
    wc_error_clear(err);
    return buf;
}

static void
check_batch(void)
{
    static const int jobs[] = { 2, 3, NTHREADS };
    FILE * in = tmpfile(), * f;
    char * one, * many, * want = NULL;
    size_t len1, lenk, wlen = 0;
    int worst1, worstk, w = WC_OK;
    slong i;
    size_t k;

    if (in == NULL)
        wctest_fail("tmpfile failed");
    /* Line 2 is blank: the request of line 3 is located there.  */
    f = open_memstream(&want, &wlen);
    if (f == NULL)
        wctest_fail("out of memory");
    for (i = 0; i < nitems; i++)
    {
        wc_error_t err;
        char * out = NULL;
        size_t olen = 0;
        long line = i + 1 + (i >= 1);
        int st;

        fprintf(in, "%s\n", items[i].req);
        if (i == 0)
            fputs(" \t\r\n", in);
        wc_error_init(err);
        st = wc_request_json_at(&out, &olen, items[i].req,
                                strlen(items[i].req), "<batch>", line, err);
        if (out == NULL)
            wctest_fail("%s: no answer", items[i].req);
        fwrite(out, 1, olen, f);
        free(out);
        wc_error_clear(err);
        /* wrenchcone(1)'s order: an error record outranks a comparison
           beyond its tolerance (4); of errors, the largest status.  */
        if (w == WC_OK || (w == WC_EDISAGREE && st != WC_OK)
            || (st != WC_EDISAGREE && st > w))
            w = st;
    }
    fclose(f);
    one = run_batch(&len1, &worst1, in, 1);
    if (len1 != wlen || memcmp(one, want, wlen) != 0 || worst1 != w)
        wctest_fail("batch with 1 job (worst %d) is not the answers of "
                    "its lines in order (worst %d):\n%s\nwant:\n%s",
                    worst1, w, one, want);
    for (k = 0; k < sizeof jobs / sizeof jobs[0]; k++)
    {
        many = run_batch(&lenk, &worstk, in, jobs[k]);
        if (lenk != len1 || memcmp(many, one, len1) != 0
            || worstk != worst1)
            wctest_fail("batch with %d jobs (worst %d) differs from 1 job "
                        "(worst %d):\n%s\nwant:\n%s", jobs[k], worstk,
                        worst1, many, one);
        free(many);
    }
    free(one);
    free(want);
    fclose(in);
}

/* ------------------------------------------------------------------ */
/* (c) the progress hook is per thread                                 */

static void
count_report(void * ctx, const char * stage, slong done, slong total)
{
    (void) stage;
    (void) done;
    (void) total;
    ++*(long *) ctx;
}

static void *
stability_request(void * arg)
{
    static const char req[] = "{\"command\": \"stability\", \"problem\": "
        "\"data/peg-in-hole.wc\"}";
    char * out = NULL;
    size_t len = 0;
    wc_error_t err;

    (void) arg;
    wc_error_init(err);
    if (wc_request_json(&out, &len, req, strlen(req), err) != WC_OK)
        wctest_fail("%s: %s", req, out);
    free(out);
    wc_error_clear(err);
    return NULL;
}

static void
check_progress(void)
{
    pthread_t t;
    long heard = 0;

    wc_progress_set(count_report, &heard);
    if (pthread_create(&t, NULL, stability_request, NULL) != 0)
        wctest_fail("pthread_create failed");
    pthread_join(t, NULL);
    if (heard != 0)
        wctest_fail("the main thread's hook heard %ld reports of another "
                    "thread", heard);
    stability_request(NULL);
    wc_progress_set(NULL, NULL);
    if (heard == 0)
        wctest_fail("the main thread's hook heard none of its own "
                    "stability request");
}

int
main(void)
{
    const char * top = getenv("top_srcdir");
    slong i;

    wctest_init("t-threads");
    if (top == NULL || chdir(top) != 0)
    {
        fprintf(stderr, "t-threads: top_srcdir is not set or not a "
                "directory: skipped\n");
        return 77;
    }
    nitems = wctest_iters(120);
    items = calloc(nitems, sizeof *items);
    if (items == NULL)
        wctest_fail("out of memory");
    for (i = 0; i < nitems; i++)
        answer(items + i, random_request());
    check_threads();
    check_batch();
    check_progress();
    for (i = 0; i < nitems; i++)
    {
        free(items[i].req);
        item_clear(items + i);
    }
    free(items);
    flint_cleanup_master();
    return 0;
}
