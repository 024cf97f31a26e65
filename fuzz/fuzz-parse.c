/* fuzz-parse.c -- libFuzzer target: the .wc problem reader (wrenchcone(5)).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Any bytes: wc_problem_parse gives a problem or an input error located
   at FILE:LINE:COL, never a crash, a leak or an abort.  A problem passes
   wc_problem_check, and round-trips: wc_problem_fprint writes it, the
   text parses again to an equal problem (every number, state, friction
   and the shape), and printing that one gives the same bytes.  */

#include "fuzzutil.h"

#define FILE_NAME "fuzz.wc"

static int
qvec_equal(const fmpq * a, const fmpq * b, slong n)
{
    slong i;

    for (i = 0; i < n; i++)
        if (!fmpq_equal(a + i, b + i))
            return 0;
    return 1;
}

/* Where P and Q differ, or NULL when they are equal (locations aside).  */
static const char *
problem_diff(const wc_problem_t P, const wc_problem_t Q)
{
    slong i;

    if ((P->name == NULL) != (Q->name == NULL)
        || (P->name != NULL && strcmp(P->name, Q->name) != 0))
        return "name";
    if (!fmpq_equal(P->mass, Q->mass) || !fmpq_equal(P->inertia, Q->inertia))
        return "mass or inertia";
    if (!qvec_equal(P->com, Q->com, 2))
        return "com";
    if (!fmpq_equal(P->mu_s, Q->mu_s) || !fmpq_equal(P->mu_k, Q->mu_k))
        return "global friction";
    if (P->shape != Q->shape || P->shape_len != Q->shape_len
        || !qvec_equal(P->shape_data, Q->shape_data, P->shape_len))
        return "shape";
    if (P->n != Q->n)
        return "number of fixels";
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i, * g = Q->fixels + i;

        if (!qvec_equal(f->point, g->point, 2)
            || !qvec_equal(f->normal, g->normal, 2) || f->state != g->state
            || !fmpq_equal(f->mu_s, g->mu_s) || !fmpq_equal(f->mu_k, g->mu_k))
            return "a fixel";
    }
    return NULL;
}

static void
print_problem(fuzz_out * o, const wc_problem_t P)
{
    fuzz_out_open(o);
    FUZZ_REQUIRE(wc_problem_fprint(o->f, P) == WC_OK, "print failed");
    fuzz_out_close(o);
}

int LLVMFuzzerTestOneInput(const uint8_t * data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t * data, size_t size)
{
    wc_problem_t P, Q, R;
    wc_error_t err;
    fuzz_out a, b;
    const char * diff;
    int status;

    wc_problem_init(P);
    wc_error_init(err);
    status = wc_problem_parse(P, (const char *) data, size, FILE_NAME, err);
    if (status != WC_OK)
    {
        FUZZ_REQUIRE(status == WC_EINPUT, "parse returned %d", status);
        fuzz_require_located(err, FILE_NAME);
        wc_problem_clear(P);
        wc_error_clear(err);
        return 0;
    }
    status = wc_problem_check(P, err);
    FUZZ_REQUIRE(status == WC_OK, "a parsed problem fails the check: %s",
                 err->message);

    print_problem(&a, P);
    wc_problem_init(Q);
    status = wc_problem_parse(Q, a.buf, a.len, FILE_NAME, err);
    FUZZ_REQUIRE(status == WC_OK, "the printed problem does not parse: "
                 "%ld:%ld: %s\n%s", err->line, err->col, err->message, a.buf);
    diff = problem_diff(P, Q);
    FUZZ_REQUIRE(diff == NULL, "the round trip changes the %s", diff);
    print_problem(&b, Q);
    FUZZ_REQUIRE(a.len == b.len && memcmp(a.buf, b.buf, a.len) == 0,
                 "printing the re-read problem gives other bytes");

    /* A copy is the same problem.  */
    wc_problem_init(R);
    FUZZ_REQUIRE(wc_problem_set(R, P) == WC_OK, "wc_problem_set failed");
    diff = problem_diff(P, R);
    FUZZ_REQUIRE(diff == NULL, "wc_problem_set changes the %s", diff);

    fuzz_out_free(&a);
    fuzz_out_free(&b);
    wc_problem_clear(R);
    wc_problem_clear(Q);
    wc_problem_clear(P);
    wc_error_clear(err);
    return 0;
}
