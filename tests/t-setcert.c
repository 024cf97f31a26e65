/* t-setcert.c -- the certificates of sets, stability-set and plan-goal
   (lib/analysis/stabcert.c, plancert.c, lib/io/stabcertprint.c,
   plancertprint.c), round-trip through the checker (lib/check/).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   On random problems of 1 to 4 fixels (degenerate layouts included, see
   testutil.h) and on the example problems:

   1. wc_stability_certificate_fprint and wc_plan_certificate_fprint write
      certificates that wc_verify accepts (holds), whose claimed set is
      byte for byte the "strong" or "goal" object of the command's JSON;
   2. the same certificate with the weakly stable cone claimed in place of
      the strongly stable set is never accepted, whenever the two differ
      (the checker finds a piece face with a motion, or a region it cannot
      place, or a leaf naming a piece the claim no longer has);
   3. a certificate cut short, or with its first leaf dropped, does not
      hold or is malformed, never accepted; one with a static force vector
      an entry short is malformed;
   4. on the first few random problems (1 to 4 fixels), the certificate
      of the critical friction bracket holds, and with lo moved above hi
      it is not accepted.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "analysis/stability.h"
#include "analysis/plan.h"
#include "check/verify.h"
#include "io/print.h"
#include "testutil.h"

/* The options of JSON output (io/print.h).  */
static const wc_print_opts as_json[1] = { { WC_FORMAT_JSON, 0, 0, NULL } };

static char *
print_to_string(int (*put)(FILE *, const void *), const void * data,
                size_t * len)
{
    char * s = NULL;
    size_t n = 0;
    FILE * f = open_memstream(&s, &n);

    if (f == NULL || put(f, data) != WC_OK)
    {
        if (f != NULL)
            fclose(f);
        free(s);
        return NULL;
    }
    fclose(f);
    *len = n;
    return s;
}

/* A certificate to write: of S's strong set, or of R's goal set.  */
typedef struct
{
    const wc_problem_struct * P;
    const wc_stability_struct * S;
    const wc_plan_struct * R;
    const wc_critical_struct * C;
}
job;

static int
put_cert(FILE * f, const void * p)
{
    const job * j = p;
    wc_error_t err;
    int st;

    wc_error_init(err);
    st = j->R != NULL ? wc_plan_certificate_fprint(f, j->P, j->R, err)
        : wc_stability_certificate_fprint(f, j->P, j->S, err);
    if (st != WC_OK)
    {
        char * m = wc_error_format(err);

        fprintf(stderr, "certificate: %s\n", m != NULL ? m : "?");
        free(m);
    }
    wc_error_clear(err);
    return st;
}

static int
put_goal(FILE * f, const void * p)
{
    return wc_set_fprint(f, ((const wc_plan_struct *) p)->goal, as_json);
}

static int
put_strong(FILE * f, const void * p)
{
    return wc_set_fprint(f, ((const wc_stability_struct *) p)->strong,
                         as_json);
}

static int
put_weak_as_set(FILE * f, const void * p)
{
    const wc_stability_struct * S = p;

    fprintf(f, "{\"empty\": false, \"interior\": %s, \"pieces\": [",
            S->weak->dim == 3 ? "true" : "false");
    wc_cone_fprint(f, S->weak, as_json);
    fputs("]}", f);
    return WC_OK;
}

/* Verify text: 1 holds, 0 does not, -1 malformed or failed.  */
static int
verify(const char * text, size_t len)
{
    wc_error_t err;
    char * reason = NULL, * summary = NULL;
    int holds = 0, st;

    wc_error_init(err);
    st = wc_verify(&holds, &reason, &summary, text, len, "<cert>", err);
    free(reason);
    free(summary);
    wc_error_clear(err);
    return st != WC_OK ? -1 : holds;
}

/* j's certificate (kind names it in messages), which must hold:
   malloc'd, its length in *len.  */
static char *
holding_cert(const job * j, const char * kind, const char * what, slong it,
             size_t * len)
{
    char * cert = print_to_string(put_cert, j, len);
    int r;

    if (cert == NULL)
        wctest_fail("%s %ld: no %s", what, (long) it, kind);
    r = verify(cert, *len);
    if (r != 1)
        wctest_fail("%s %ld: the %s %s:\n%s", what, (long) it, kind,
                    r < 0 ? "is malformed" : "does not hold", cert);
    return cert;
}

/* text with [at, at + cut) replaced by ins (malloc'd).  */
static char *
splice(const char * text, size_t len, size_t at, size_t cut,
       const char * ins, size_t * out)
{
    size_t n = strlen(ins);
    char * s = malloc(len - cut + n + 1);

    memcpy(s, text, at);
    memcpy(s + at, ins, n);
    memcpy(s + at + n, text + at + cut, len - at - cut);
    *out = len - cut + n;
    s[*out] = '\0';
    return s;
}

/* Where the claim starts in cert, just after key; the test fails unless
   it is set[0..len) (the set as printed).  */
static const char *
claim_at(const char * cert, const char * key, const char * set, size_t len,
         const char * what, slong it)
{
    const char * at = strstr(cert, key);

    if (at == NULL || strncmp(at + strlen(key), set, len) != 0)
        wctest_fail("%s %ld: the claim is not the set as printed", what,
                    (long) it);
    return at + strlen(key);
}

static void
check_problem(const wc_problem_t P, const char * what, slong it)
{
    wc_stability_t S;
    wc_error_t err;
    job j;
    char * cert, * strong, * weak, * t;
    size_t clen = 0, slen = 0, wlen = 0, tlen = 0;
    const char * at;

    wc_stability_init(S);
    wc_error_init(err);
    if (wc_stability(S, P, err) != WC_OK)
        goto done;              /* the problem is refused: nothing to do */
    j = (job) { P, S, NULL, NULL };
    cert = holding_cert(&j, "certificate", what, it, &clen);
    strong = print_to_string(put_strong, S, &slen);
    at = claim_at(cert, "\n \"strong\": ", strong, slen, what, it);

    /* the weak cone claimed as the strong set */
    weak = print_to_string(put_weak_as_set, S, &wlen);
    if (wlen != slen || memcmp(weak, strong, slen) != 0)
    {
        t = splice(cert, clen, (size_t) (at - cert), slen, weak, &tlen);
        /* (malformed when a cell names a piece the weak cone lacks) */
        if (verify(t, tlen) == 1)
            wctest_fail("%s %ld: claiming the weak cone holds", what,
                        (long) it);
        free(t);
    }

    /* cut short: malformed */
    if (verify(cert, clen / 2) >= 0)
        wctest_fail("%s %ld: half a certificate is read", what, (long) it);
    /* the first node after the basis dropped */
    at = strstr(cert, "\"tree\": [{\"basis\"");
    if (at != NULL && (at = strstr(at, ",\n  ")) != NULL)
    {
        const char * end = strstr(at + 4, ",\n  ");

        if (end != NULL)
        {
            size_t from = (size_t) (at - cert);

            t = splice(cert, clen, from, (size_t) (end - cert) - from, "",
                       &tlen);
            if (verify(t, tlen) == 1)
                wctest_fail("%s %ld: a certificate without its first leaf "
                            "holds", what, (long) it);
            free(t);
        }
    }
    /* the first static force vector one entry short: malformed */
    at = strstr(cert, "\"static\": [[\"");
    if (at != NULL)
    {
        const char * comma = strstr(at, "\", \"");
        const char * close = strchr(at, ']');

        if (comma != NULL && close != NULL && comma < close)
        {
            size_t from = (size_t) (at + 12 - cert);

            t = splice(cert, clen, from, (size_t) (comma + 3 - cert) - from,
                       "", &tlen);
            if (verify(t, tlen) >= 0)
                wctest_fail("%s %ld: a short static force vector is read",
                            what, (long) it);
            free(t);
        }
    }
    free(cert);
    free(strong);
    free(weak);
done:
    wc_stability_clear(S);
    wc_error_clear(err);
}

/* data/NAME into P (top_srcdir from the environment, as make check sets
   it); 0 when it is not set.  */
static int
load_data(wc_problem_t P, const char * name)
{
    if (getenv("top_srcdir") == NULL)
        return 0;
    wctest_load_data(P, name);
    return 1;
}

/* The plan of P: its certificate holds and claims the goal set as
   printed; with the goal claimed empty when it is not, it does not.  */
static void
check_plan(const wc_problem_t P, const char * what, slong it)
{
    wc_plan_t R;
    wc_error_t err;
    job j;
    char * cert, * goal, * t;
    size_t clen = 0, glen = 0, tlen = 0;
    const char * at;

    wc_plan_init(R);
    wc_error_init(err);
    if (wc_plan(R, P, 0, err) != WC_OK)
        goto done;
    j = (job) { P, NULL, R, NULL };
    cert = holding_cert(&j, "plan certificate", what, it, &clen);
    goal = print_to_string(put_goal, R, &glen);
    at = claim_at(cert, "\n \"goal\": ", goal, glen, what, it);
    if (!R->goal->empty)
    {
        t = splice(cert, clen, (size_t) (at - cert), glen,
                   "{\"empty\": true, \"interior\": false, \"pieces\": []}",
                   &tlen);
        if (verify(t, tlen) == 1)
            wctest_fail("%s %ld: claiming an empty goal holds", what,
                        (long) it);
        free(t);
    }
    free(cert);
    free(goal);
done:
    wc_plan_clear(R);
    wc_error_clear(err);
}

/* How many critical brackets were certified.  */
static slong ncritical = 0;

/* The critical bracket of P at width 1/4 (friction at most 4): its
   certificate holds, and with lo moved above hi it does not.  */
static int
put_crit(FILE * f, const void * p)
{
    const job * j = p;
    wc_error_t err;
    int st;

    wc_error_init(err);
    st = wc_critical_certificate_fprint(f, j->P, j->C, err);
    wc_error_clear(err);
    return st;
}

static void
check_critical(const wc_problem_t P, const char * what, slong it)
{
    wc_critical_t C;
    wc_error_t err;
    fmpq_t width, max;
    job j;
    char * cert, * t, * at, * hi;
    size_t clen = 0, tlen = 0;
    int r;

    wc_critical_init(C);
    wc_error_init(err);
    fmpq_init(width);
    fmpq_init(max);
    fmpq_set_si(width, 1, 4);
    fmpq_set_si(max, 4, 1);
    if (wc_plan_critical(C, P, width, max, err) != WC_OK)
        goto done;
    j = (job) { P, NULL, NULL, C };
    cert = print_to_string(put_crit, &j, &clen);
    if (cert == NULL)
        wctest_fail("%s %ld: no critical certificate", what, (long) it);
    if ((r = verify(cert, clen)) != 1)
        wctest_fail("%s %ld: the critical certificate %s:\n%s", what,
                    (long) it, r < 0 ? "is malformed" : "does not hold",
                    cert);
    at = strstr(cert, "\"lo\": \"");
    if (C->found && !C->empty_at_zero && at != NULL)
    {
        const char * end = strchr(at + 7, '"');

        /* lo := hi + 1, beyond hi: the witness no longer proves it */
        fmpq_add_si(width, C->hi, 1);
        hi = fmpq_get_str(NULL, 10, width);
        t = splice(cert, clen, (size_t) (at + 7 - cert),
                   (size_t) (end - (at + 7)), hi, &tlen);
        if (verify(t, tlen) == 1)
            wctest_fail("%s %ld: a critical certificate with lo above hi "
                        "holds", what, (long) it);
        flint_free(hi);
        free(t);
    }
    ncritical++;
    free(cert);
done:
    fmpq_clear(width);
    fmpq_clear(max);
    wc_critical_clear(C);
    wc_error_clear(err);
}

int
main(void)
{
    static const char * const files[] = {
        "disk-two-fixels.wc", "disk-two-fixels-insert.wc", "section4.wc",
        "three-fixels.wc", "three-fixels-insert.wc", "peg-in-hole.wc"
    };
    slong i, n = wctest_iters(30);
    size_t k;

    wctest_init("t-setcert");
    for (k = 0; k < sizeof files / sizeof files[0]; k++)
    {
        wc_problem_t P;

        wc_problem_init(P);
        if (load_data(P, files[k]))
        {
            check_problem(P, files[k], 0);
            check_plan(P, files[k], 0);
        }
        wc_problem_clear(P);
    }
    for (i = 0; i < n; i++)
    {
        wc_problem_t P;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        wctest_random_problem(P, 1, 4);
        check_problem(P, "random problem", i);
        check_plan(P, "random plan", i);
        if (ncritical < 6)
            check_critical(P, "random critical bracket", i);
        wc_problem_clear(P);
    }
    return 0;
}
