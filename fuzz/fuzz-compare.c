/* fuzz-compare.c -- libFuzzer target: the foreign-cone reader of
   `wrenchcone compare` (cdd H/V files and the JSON cone format,
   lib/float/foreign*.c) and the comparison with an exact cone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Any bytes: wc_foreign_parse gives a foreign cone (one or two
   representations) or an input error located at FILE:LINE:COL, never a
   crash, a leak or an abort.  A cone read is compared with the exact
   cone of one mode of the paper's Section 4 example (the mode chosen by
   the input's length), and the comparison must succeed and be printed
   as text and as JSON; a representation whose closure is exactly the
   exact cone's closure must be within tolerance, and one of another
   emptiness, dimension or lineality must be flagged so.  */

#include "fuzzutil.h"

#define FILE_NAME "fuzz.cone"

static const char problem_text[] =
    "mass 1\ninertia 1\ncom 0 0\nfriction 1/5\nshape disk 0 0 1\n"
    "fixel 0 -1 normal 0 1 touching\nfixel 1 0 normal -1 0 near\n";

#define NMODES 3
static const char * const modes[NMODES] = { "na", "su", "ma" };

static int ready = 0;
static wc_problem_t P;
static wc_cone_t W[NMODES];         /* the exact cones */
static wc_cone_t closure[NMODES];   /* their closures */

static void
closure_of(wc_cone_t K, const wc_cone_t C)
{
    fmpq_mat_t r, l;
    wc_error_t err;

    wc_error_init(err);
    if (C->empty)
        wc_cone_set_empty(K);
    else
    {
        fmpq_mat_init(r, fmpz_mat_nrows(C->rays), 3);
        fmpq_mat_init(l, fmpz_mat_nrows(C->lines), 3);
        fmpq_mat_set_fmpz_mat(r, C->rays);
        fmpq_mat_set_fmpz_mat(l, C->lines);
        FUZZ_REQUIRE(wc_cone_set_generators(K, r, l, err) == WC_OK,
                     "closure failed");
        fmpq_mat_clear(r);
        fmpq_mat_clear(l);
    }
    wc_error_clear(err);
}

static void
setup(void)
{
    wc_error_t err;
    slong k;

    wc_error_init(err);
    wc_problem_init(P);
    FUZZ_REQUIRE(wc_problem_parse(P, problem_text, sizeof problem_text - 1,
                                  "section4.wc", err) == WC_OK, "setup");
    for (k = 0; k < NMODES; k++)
    {
        wc_cone_init(W[k], 3);
        wc_cone_init(closure[k], 3);
        FUZZ_REQUIRE(wc_wrench_cone(W[k], NULL, P, modes[k],
                                    WC_METHOD_DIRECT, err) == WC_OK, "setup");
        closure_of(closure[k], W[k]);
    }
    wc_error_clear(err);
    ready = 1;
}

static void
check_rep(const wc_cmp_rep_struct * r, const wc_cone_t K)
{
    if (wc_cone_equal(r->cone, K))
        FUZZ_REQUIRE(r->differs == 0, "the exact closure itself differs "
                     "(bits %u)", r->differs);
    if (r->cone->empty != K->empty)
        FUZZ_REQUIRE(r->differs & WC_CMP_EMPTY, "emptiness not flagged");
    else if (!K->empty && r->cone->dim != K->dim)
        FUZZ_REQUIRE(r->differs & WC_CMP_DIM, "dimension not flagged");
    else if (!K->empty && r->cone->lineality_dim != K->lineality_dim)
        FUZZ_REQUIRE(r->differs & WC_CMP_LINEALITY, "lineality not flagged");
}

int LLVMFuzzerTestOneInput(const uint8_t * data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t * data, size_t size)
{
    wc_foreign_t F;
    wc_comparison_t R;
    wc_error_t err;
    fuzz_out o;
    slong k = (slong) (size % NMODES), i;
    int status, json;

    if (!ready)
        setup();
    wc_error_init(err);
    wc_foreign_init(F);
    status = wc_foreign_parse(F, (const char *) data, size, FILE_NAME, err);
    if (status != WC_OK)
    {
        FUZZ_REQUIRE(status == WC_EINPUT, "parse returned %d", status);
        fuzz_require_located(err, FILE_NAME);
        FUZZ_REQUIRE(F->nreps == 0, "a failed read left representations");
        wc_foreign_clear(F);
        wc_error_clear(err);
        return 0;
    }
    FUZZ_REQUIRE(F->nreps == 1 || F->nreps == 2, "%ld representations",
                 (long) F->nreps);

    wc_comparison_init(R);
    status = wc_compare(R, W[k], modes[k], F, WC_COMPARE_TOL, err);
    FUZZ_REQUIRE(status == WC_OK, "compare returned %d: %s", status,
                 err->message ? err->message : "");
    FUZZ_REQUIRE(R->nreps == F->nreps, "compared %ld of %ld",
                 (long) R->nreps, (long) F->nreps);
    for (i = 0; i < R->nreps; i++)
        check_rep(R->reps + i, closure[k]);
    for (json = 0; json <= 1; json++)
    {
        wc_print_opts po = { WC_FORMAT_TEXT, 0, 0, NULL };

        po.format = json ? WC_FORMAT_JSON : WC_FORMAT_TEXT;
        fuzz_out_open(&o);
        FUZZ_REQUIRE(wc_comparison_fprint(o.f, R, W[k], "section4.wc",
                                          modes[k], FILE_NAME, &po) == WC_OK,
                     "printing the report failed");
        fuzz_out_close(&o);
        FUZZ_REQUIRE(o.len > 0, "an empty report");
        fuzz_out_free(&o);
    }
    wc_comparison_clear(R);
    wc_foreign_clear(F);
    wc_error_clear(err);
    return 0;
}
