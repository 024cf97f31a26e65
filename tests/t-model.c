/* t-model.c -- the paper's Section 4 example, exactly: J, A, B, C (eq. 12),
   the paper route's K and P, and the cone W(na) by both routes (the paper's reference results).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "testutil.h"

static const char section4[] =
    "mass 1\ninertia 1\nfriction 1/5\n"
    "fixel 0 -1 normal 0 1 touching\n"
    "fixel 1 0 normal -1 0 near\n";

/* Compare m with the rows x cols rationals given as strings.  */
static void
expect_mat(const char * what, const fmpq_mat_t m, slong rows, slong cols,
           const char * const * want)
{
    slong i, j;
    fmpq_t x;

    if (fmpq_mat_nrows(m) != rows || fmpq_mat_ncols(m) != cols)
        wctest_fail("%s is %ld x %ld, want %ld x %ld", what,
                    (long) fmpq_mat_nrows(m), (long) fmpq_mat_ncols(m),
                    (long) rows, (long) cols);
    fmpq_init(x);
    for (i = 0; i < rows; i++)
        for (j = 0; j < cols; j++)
        {
            if (fmpq_set_str(x, want[i * cols + j], 10) != 0)
                wctest_fail("bad expected value %s", want[i * cols + j]);
            if (!fmpq_equal(x, fmpq_mat_entry(m, i, j)))
            {
                char * s = fmpq_get_str(NULL, 10, fmpq_mat_entry(m, i, j));

                wctest_fail("%s[%ld][%ld] = %s, want %s", what, (long) i,
                            (long) j, s, want[i * cols + j]);
            }
        }
    fmpq_clear(x);
}

static const fmpq_mat_struct *
traced(const wc_trace_t T, const char * name)
{
    slong i;

    for (i = 0; i < T->len; i++)
        if (strcmp(T->entries[i].name, name) == 0)
            return T->entries[i].m;
    wctest_fail("the trace has no matrix %s", name);
}

int
main(void)
{
    static const char * const J[] = {
        "0", "-1", "-1", "0",
        "1", "0", "0", "-1",
        "0", "0", "-1", "-1" };
    /* Eq. (12), left: C = [I, -A].  */
    static const char * const C[] = {
        "1", "0", "0", "0", "-1", "0", "0", "1",
        "0", "1", "0", "0", "0", "-1", "-1", "0",
        "0", "0", "1", "0", "0", "-1", "-2", "-1",
        "0", "0", "0", "1", "1", "0", "-1", "-2" };
    /* Eq. (12), right.  */
    static const char * const B[] = {
        "0", "1", "0",
        "-1", "0", "0",
        "-1", "0", "-1",
        "0", "-1", "-1" };
    /* Section 4, after step 4: K and P, mu_s = 1/5 (the paper's K with
       its columns in V's order).  */
    static const char * const K[] = {
        "0", "-1", "-1",
        "-1", "1/5", "-1/5",
        "0", "2/5", "-2/5" };
    static const char * const Pm[] = {
        "0", "1", "0",
        "-1", "0", "0",
        "-1", "0", "-1" };
    static const char * const want_json =
        "{\"empty\": false, \"dim\": 3, \"lineality_dim\": 0, "
        "\"inequalities\": [[\"-5\", \"2\", \"-5\"], [\"-1\", \"0\", \"1\"], "
        "[\"5\", \"2\", \"5\"]], \"equalities\": [], "
        "\"rays\": [[\"-1\", \"-5\", \"-1\"], [\"1\", \"-5\", \"1\"], "
        "[\"1\", \"0\", \"-1\"]], \"lines\": [], \"faces\": ["
        "{\"dim\": 0, \"rays\": [], \"included\": false}, "
        "{\"dim\": 1, \"rays\": [0], \"included\": false}, "
        "{\"dim\": 1, \"rays\": [1], \"included\": false}, "
        "{\"dim\": 1, \"rays\": [2], \"included\": true}, "
        "{\"dim\": 2, \"rays\": [0, 1], \"included\": false}, "
        "{\"dim\": 2, \"rays\": [0, 2], \"included\": true}, "
        "{\"dim\": 2, \"rays\": [1, 2], \"included\": true}, "
        "{\"dim\": 3, \"rays\": [0, 1, 2], \"included\": true}]}";
    wc_problem_t P;
    wc_error_t err;
    fmpq_mat_t m;
    wc_cone_t Wd, Wp;
    wc_trace_t T;
    char * s;
    int method;

    wctest_init("t-model");
    wc_problem_init(P);
    wc_error_init(err);
    if (wc_problem_parse(P, section4, strlen(section4), "section4", err)
        != WC_OK)
        wctest_fail("parse: %s", err->message);

    fmpq_mat_init(m, 3, 4);
    wc_model_J(m, P);
    expect_mat("J", m, 3, 4, J);
    fmpq_mat_clear(m);
    fmpq_mat_init(m, 4, 8);
    wc_model_C(m, P);
    expect_mat("C", m, 4, 8, C);
    fmpq_mat_clear(m);
    fmpq_mat_init(m, 4, 3);
    wc_model_B(m, P);
    expect_mat("B", m, 4, 3, B);
    fmpq_mat_clear(m);

    /* Both routes: the published generators, facets, faces and strictness,
       byte for byte.  */
    for (method = 0; method < 2; method++)
    {
        wc_cone_init(Wd, 3);
        wc_trace_init(T);
        if (wc_wrench_cone(Wd, T, P, "na", method, err) != WC_OK)
            wctest_fail("route %d: %s", method, err->message);
        s = wctest_cone_json(Wd);
        if (strcmp(s, want_json) != 0)
            wctest_fail("route %d gives\n%s\nwant\n%s", method, s, want_json);
        free(s);
        if (method == WC_METHOD_PAPER)
        {
            expect_mat("K", traced(T, "K"), 3, 3, K);
            expect_mat("P", traced(T, "P"), 3, 3, Pm);
        }
        wc_trace_clear(T);
        wc_cone_clear(Wd);
    }

    /* The library checks modes itself: a short mode or a letter the
       fixel's state forbids is bad input, never a read past the end.  */
    for (method = 0; method < 2; method++)
    {
        static const char * const bad[] = { "n", "nas", "an", "xa" };
        int b;

        for (b = 0; b < 4; b++)
        {
            wc_cone_init(Wd, 3);
            if (wc_wrench_cone(Wd, NULL, P, bad[b], method, err) != WC_EINPUT
                || !Wd->empty || strcmp(err->file, "<mode>") != 0)
                wctest_fail("route %d accepts bad mode '%s'", method, bad[b]);
            wc_cone_clear(Wd);
        }
    }

    /* A problem built through the API is checked, not trusted: no fixel,
       or a zero normal, is bad input for every entry point -- never an
       abort inside FLINT.  */
    {
        wc_problem_t Q;
        wc_modes_t Mo;
        wc_certificate_t Ce;

        wc_problem_init(Q);
        wc_modes_init(Mo);
        wc_certificate_init(Ce);
        wc_cone_init(Wd, 3);
        if (wc_modes_enumerate(Mo, Q, err) != WC_EINPUT
            || wc_feasible(Ce, Q, "", err) != WC_EINPUT
            || wc_wrench_cone(Wd, NULL, Q, "", WC_METHOD_DIRECT, err) != WC_EINPUT)
            wctest_fail("an empty problem is accepted");
        wc_problem_add_fixel(Q);        /* normal (0, 0) */
        if (wc_modes_enumerate(Mo, Q, err) != WC_EINPUT
            || wc_feasible(Ce, Q, "s", err) != WC_EINPUT
            || wc_wrench_cone(Wd, NULL, Q, "s", WC_METHOD_PAPER, err) != WC_EINPUT
            || strstr(err->message, "zero normal") == NULL)
            wctest_fail("a zero normal is accepted");
        wc_cone_clear(Wd);
        wc_certificate_clear(Ce);
        wc_modes_clear(Mo);
        wc_problem_clear(Q);
    }

    /* Scaling a normal by a positive rational changes nothing.  */
    fmpq_set_si(P->fixels[0].normal + 1, 7, 3);
    fmpq_set_si(P->fixels[1].normal + 0, -5, 1);
    wc_cone_init(Wd, 3);
    wc_cone_init(Wp, 3);
    if (wc_wrench_cone_direct(Wd, NULL, P, "na", err) != WC_OK
        || wc_wrench_cone_paper(Wp, NULL, P, "na", err) != WC_OK)
        wctest_fail("scaled normals: %s", err->message);
    s = wctest_cone_json(Wd);
    if (strcmp(s, want_json) != 0 || !wc_cone_equal(Wd, Wp))
        wctest_fail("scaled normals change the cone:\n%s", s);
    free(s);
    wc_cone_clear(Wd);
    wc_cone_clear(Wp);

    wc_error_clear(err);
    wc_problem_clear(P);
    flint_cleanup_master();
    return 0;
}
