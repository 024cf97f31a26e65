/* corpus-check.c -- check one problem of data/corpus/ in one process.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Usage: corpus-check PROBLEM.wc CONES.json
          corpus-check --modes PROBLEM.wc

   The first form checks that CONES.json holds one line per Table 2 mode
   of the problem (s l r n m on touching fixels, s a u on near ones), in
   ASCII order, each exactly what `wrenchcone cone --format=json PROBLEM
   MODE` prints -- built here the way the program builds it -- and that
   both routes, direct and paper, print it.  The second prints the modes,
   one a line, in that order (for regenerating the corpus).

   Silent on success.  Exit status 0 when everything matches, 1 on the
   first difference (named by file, line and mode), 99 on a hard error
   (a missing or malformed file).  tests/corpus.sh runs it; running all
   modes of a problem in one process keeps the corpus check fast under
   the sanitizers too.  */

#include <config.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"

/* The options of JSON output (io/print.h).  */
static const wc_print_opts as_json[1] = { { WC_FORMAT_JSON, 0, 0, NULL } };

#define ME "corpus-check"

/* The whole of path into a malloc'd, NUL-terminated buffer.  */
static char *
slurp(const char * path, size_t * len)
{
    FILE * f = fopen(path, "rb");
    char * buf = NULL;
    size_t cap = 0, n = 0, r;

    if (f == NULL)
        return NULL;
    do
    {
        if (n + 1 >= cap)
        {
            char * b = realloc(buf, cap = cap == 0 ? 65536 : 2 * cap);

            if (b == NULL)
            {
                free(buf);
                fclose(f);
                return NULL;
            }
            buf = b;
        }
        r = fread(buf + n, 1, cap - n - 1, f);
        n += r;
    }
    while (r > 0);
    if (ferror(f))
    {
        free(buf);
        fclose(f);
        return NULL;
    }
    fclose(f);
    buf[n] = '\0';
    *len = n;
    return buf;
}

/* Advance mode to the next string in ASCII order over the letters each
   fixel allows; 0 after the last.  */
static int
next_mode(char * mode, const wc_problem_t P)
{
    slong i;

    for (i = P->n - 1; i >= 0; i--)
    {
        const char * set = P->fixels[i].state == WC_NEAR ? "asu" : "lmnrs";
        const char * at = strchr(set, mode[i]);

        if (at[1] != '\0')
        {
            mode[i] = at[1];
            return 1;
        }
        mode[i] = set[0];
    }
    return 0;
}

static void
first_mode(char * mode, const wc_problem_t P)
{
    slong i;

    for (i = 0; i < P->n; i++)
        mode[i] = P->fixels[i].state == WC_NEAR ? 'a' : 'l';
    mode[P->n] = '\0';
}

/* The line `wrenchcone cone --format=json` prints for mode, by method;
   malloc'd, NULL on failure (reported).  */
static char *
cone_line(const wc_problem_t P, const char * mode, wc_method method)
{
    wc_cone_t W;
    wc_error_t err;
    char * buf = NULL;
    size_t len = 0;
    FILE * f;
    int status;

    wc_cone_init(W, 3);
    wc_error_init(err);
    status = wc_wrench_cone(W, NULL, P, mode, method, err);
    if (status != WC_OK)
    {
        char * s = wc_error_format(err);

        fprintf(stderr, ME ": mode %s: %s route failed: %s\n", mode,
                method == WC_METHOD_PAPER ? "paper" : "direct",
                s != NULL ? s : "out of memory");
        free(s);
    }
    else if ((f = open_memstream(&buf, &len)) != NULL)
    {
        fputs(WC_JSON_OPEN "\"mode\": ", f);
        wc_fprint_json_string(f, mode);
        fputs(", \"cone\": ", f);
        wc_cone_fprint(f, W, as_json);
        fputs("}\n", f);
        if (fclose(f) != 0)
        {
            free(buf);
            buf = NULL;
        }
    }
    wc_cone_clear(W);
    wc_error_clear(err);
    return buf;
}

/* Check the cones file against P; returns the exit status.  */
static int
check(const wc_problem_t P, const char * path)
{
    size_t len = 0, lineno = 0;
    char * text = slurp(path, &len), * at, * mode = NULL;
    int status = 0, more = 1;

    if (text == NULL)
    {
        fprintf(stderr, ME ": %s: cannot read: %s\n", path, strerror(errno));
        return 99;
    }
    mode = malloc((size_t) P->n + 1);
    if (mode == NULL)
    {
        free(text);
        return 99;
    }
    first_mode(mode, P);
    at = text;
    for (; more && status == 0; more = next_mode(mode, P))
    {
        char * nl = strchr(at, '\n');
        size_t l = nl != NULL ? (size_t) (nl - at) + 1 : strlen(at);
        int m;

        lineno++;
        if (l == 0)
        {
            fprintf(stderr, ME ": %s: ends after line %zu; mode %s is "
                    "missing\n", path, lineno - 1, mode);
            status = 1;
            break;
        }
        for (m = 0; m < 2 && status == 0; m++)
        {
            wc_method method = m == 0 ? WC_METHOD_DIRECT : WC_METHOD_PAPER;
            char * got = cone_line(P, mode, method);

            if (got == NULL)
                status = 99;
            else if (strlen(got) != l || memcmp(got, at, l) != 0)
            {
                fprintf(stderr, ME ": %s:%zu: mode %s: the %s route prints\n"
                        "%sthe corpus has\n%.*s%s", path, lineno, mode,
                        method == WC_METHOD_PAPER ? "paper" : "direct", got,
                        (int) l, at, nl == NULL ? "\n" : "");
                status = 1;
            }
            free(got);
        }
        at += l;
    }
    if (status == 0 && *at != '\0')
    {
        fprintf(stderr, ME ": %s:%zu: a line after the last mode\n", path,
                lineno + 1);
        status = 1;
    }
    free(mode);
    free(text);
    return status;
}

int
main(int argc, char ** argv)
{
    int list = argc == 3 && strcmp(argv[1], "--modes") == 0;
    const char * path;
    char * text = NULL;
    size_t len = 0;
    wc_problem_t P;
    wc_error_t err;
    int status;

    if (argc != 3)
    {
        fputs("usage: " ME " PROBLEM.wc CONES.json\n"
              "       " ME " --modes PROBLEM.wc\n", stderr);
        return 99;
    }
    path = argv[list ? 2 : 1];
    text = slurp(path, &len);
    if (text == NULL)
    {
        fprintf(stderr, ME ": %s: cannot read: %s\n", path, strerror(errno));
        return 99;
    }
    wc_problem_init(P);
    wc_error_init(err);
    if (wc_problem_parse(P, text, len, path, err) != WC_OK)
    {
        char * s = wc_error_format(err);

        fprintf(stderr, ME ": %s\n", s != NULL ? s : "out of memory");
        free(s);
        status = 99;
    }
    else if (list)
    {
        char * mode = malloc((size_t) P->n + 1);

        status = mode == NULL ? 99 : 0;
        if (mode != NULL)
        {
            first_mode(mode, P);
            do
                printf("%s\n", mode);
            while (next_mode(mode, P));
            free(mode);
        }
        if (fflush(stdout) != 0)
            status = 99;
    }
    else
        status = check(P, argv[2]);
    wc_error_clear(err);
    wc_problem_clear(P);
    free(text);
    flint_cleanup_master();
    return status;
}
