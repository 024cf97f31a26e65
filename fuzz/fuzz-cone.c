/* fuzz-cone.c -- libFuzzer target: small problems decoded from the input
   bytes; the two routes to a wrench cone, and the certificates of the
   feasible modes against the independent checker.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The bytes are read as a small problem: 1 to 4 fixels; mass, inertia,
   centre of mass, points, normals and friction small rationals (at most
   a few bits each, so that each run stays fast); each fixel touching or
   near with its own friction; then a Table 2 mode (wrenchcone(1), MODES)
   and a Table 1 mode.  Missing bytes read as zero.  Then:
   - W(mode) by the direct route and by the paper's route prints the same
     bytes as text and as JSON (`wrenchcone cone --method` promises it);
   - every mode wc_modes_enumerate lists is feasible by wc_feasible, and
     its JSON certificate (what `wrenchcone feasible --format=json`
     writes) holds for wc_verify_certificate, which must read back the
     mode and the claim; so does the certificate of the Table 1 mode from
     the input, feasible or not, and the enumeration lists that mode
     exactly when it is feasible.  */

#include "fuzzutil.h"

/* The options of JSON output (io/print.h).  */
static const wc_print_opts as_json[1] = { { WC_FORMAT_JSON, 0, 0, NULL } };

#define MAX_FIXELS 4

typedef struct
{
    const uint8_t * p;
    size_t n;
}
reader;

static unsigned
next(reader * r)
{
    if (r->n == 0)
        return 0;
    r->n--;
    return *r->p++;
}

/* A rational with numerator in [-7, 8] (signed = 1) or [1, 16], and
   denominator in [1, 4].  */
static void
next_q(fmpq_t x, reader * r, int sign)
{
    unsigned b = next(r);
    slong num = sign ? (slong) (b & 15) - 7 : (slong) (b & 15) + 1;

    fmpq_set_si(x, num, (ulong) ((b >> 4) & 3) + 1);
}

static void
decode(wc_problem_t P, char * cone_mode, char * kin_mode, reader * r)
{
    slong n = (slong) (next(r) % MAX_FIXELS) + 1, i;

    P->file = strdup("fuzz.wc");
    next_q(P->mass, r, 0);
    next_q(P->inertia, r, 0);
    next_q(P->com + 0, r, 1);
    next_q(P->com + 1, r, 1);
    for (i = 0; i < n; i++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);
        unsigned b;

        next_q(f->point + 0, r, 1);
        next_q(f->point + 1, r, 1);
        b = next(r);
        fmpz_set_si(fmpq_numref(f->normal + 0), (slong) (b & 7) - 3);
        fmpz_set_si(fmpq_numref(f->normal + 1), (slong) ((b >> 3) & 7) - 3);
        if (fmpq_is_zero(f->normal + 0) && fmpq_is_zero(f->normal + 1))
            fmpq_one(f->normal + 1);
        f->state = (b & 64) ? WC_NEAR : WC_TOUCHING;
        b = next(r);    /* friction: mu_s in {0, 1/4, .., 15/4}, mu_k <= */
        fmpq_set_si(f->mu_s, (slong) (b & 15), 4);
        fmpq_set_si(f->mu_k, (slong) ((b & 15) >> ((b >> 4) & 3)), 4);
        b = next(r);
        cone_mode[i] = f->state == WC_TOUCHING ? "slrnm"[b % 5] : "sau"[b % 3];
        kin_mode[i] = f->state == WC_TOUCHING ? "slrn"[(b >> 3) & 3]
                                              : "as"[(b >> 5) & 1];
    }
    cone_mode[n] = kin_mode[n] = '\0';
}

static void
print_cone(fuzz_out * o, const wc_cone_t W, int json)
{
    wc_print_opts po = { WC_FORMAT_TEXT, 0, 0, "  " };

    po.format = json ? WC_FORMAT_JSON : WC_FORMAT_TEXT;
    fuzz_out_open(o);
    FUZZ_REQUIRE(wc_cone_fprint(o->f, W, &po) == WC_OK,
                 "printing a cone failed");
    fuzz_out_close(o);
}

static void
check_routes(const wc_problem_t P, const char * mode)
{
    wc_cone_t A, B;
    wc_error_t err;
    fuzz_out a, b;
    int json, s;

    wc_error_init(err);
    wc_cone_init(A, 3);
    wc_cone_init(B, 3);
    s = wc_wrench_cone_direct(A, NULL, P, mode, err);
    FUZZ_REQUIRE(s == WC_OK, "direct route, mode %s: %d %s", mode, s,
                 err->message ? err->message : "");
    s = wc_wrench_cone_paper(B, NULL, P, mode, err);
    FUZZ_REQUIRE(s == WC_OK, "paper route, mode %s: %d %s", mode, s,
                 err->message ? err->message : "");
    FUZZ_REQUIRE(wc_cone_equal(A, B), "the routes give other cones, mode %s",
                 mode);
    for (json = 0; json <= 1; json++)
    {
        print_cone(&a, A, json);
        print_cone(&b, B, json);
        FUZZ_REQUIRE(a.len == b.len && memcmp(a.buf, b.buf, a.len) == 0,
                     "mode %s: direct\n%s\npaper\n%s", mode, a.buf, b.buf);
        fuzz_out_free(&a);
        fuzz_out_free(&b);
    }
    wc_cone_clear(A);
    wc_cone_clear(B);
    wc_error_clear(err);
}

/* Decide mode, write its JSON certificate and check it independently.
   Returns the claim (1 feasible).  */
static int
check_certificate(const wc_problem_t P, const char * mode)
{
    wc_certificate_t C;
    wc_error_t err;
    fuzz_out o;
    char * reason = NULL, * claimed = NULL;
    int holds = -1, feasible = -1, s, claim;

    wc_error_init(err);
    wc_certificate_init(C);
    s = wc_feasible(C, P, mode, err);
    FUZZ_REQUIRE(s == WC_OK, "feasible %s: %d %s", mode, s,
                 err->message ? err->message : "");
    claim = C->feasible;
    fuzz_out_open(&o);
    FUZZ_REQUIRE(wc_certificate_fprint(o.f, C, P, as_json) == WC_OK,
                 "printing a certificate failed");
    fuzz_out_close(&o);
    s = wc_verify_certificate(&holds, &reason, &claimed, &feasible, o.buf,
                              o.len, "cert.json", err);
    FUZZ_REQUIRE(s == WC_OK, "the certificate of %s does not read: "
                 "%ld:%ld: %s\n%s", mode, err->line, err->col,
                 err->message ? err->message : "", o.buf);
    FUZZ_REQUIRE(holds == 1, "the certificate of %s does not hold: %s\n%s",
                 mode, reason ? reason : "", o.buf);
    FUZZ_REQUIRE(strcmp(claimed, mode) == 0 && feasible == claim,
                 "the certificate claims %s %d, not %s %d", claimed,
                 feasible, mode, claim);
    free(reason);
    free(claimed);
    fuzz_out_free(&o);
    wc_certificate_clear(C);
    wc_error_clear(err);
    return claim;
}

int LLVMFuzzerTestOneInput(const uint8_t * data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t * data, size_t size)
{
    wc_problem_t P;
    wc_modes_t M;
    wc_error_t err;
    reader r = { data, size };
    char cone_mode[MAX_FIXELS + 1], kin_mode[MAX_FIXELS + 1];
    slong i;
    int listed = 0, s;

    wc_problem_init(P);
    wc_error_init(err);
    decode(P, cone_mode, kin_mode, &r);
    FUZZ_REQUIRE(wc_problem_check(P, err) == WC_OK, "decoded a bad problem");

    check_routes(P, cone_mode);

    wc_modes_init(M);
    s = wc_modes_enumerate(M, P, err);
    FUZZ_REQUIRE(s == WC_OK, "modes: %d", s);
    FUZZ_REQUIRE(M->n == P->n && M->count >= 1, "%ld modes of %ld letters",
                 (long) M->count, (long) M->n);
    for (i = 0; i < M->count; i++)
    {
        FUZZ_REQUIRE(i == 0 || strcmp(M->modes[i - 1], M->modes[i]) < 0,
                     "modes not sorted or repeated");
        FUZZ_REQUIRE(check_certificate(P, M->modes[i]) == 1,
                     "enumerated mode %s is infeasible", M->modes[i]);
        listed |= strcmp(M->modes[i], kin_mode) == 0;
    }
    FUZZ_REQUIRE(check_certificate(P, kin_mode) == listed,
                 "mode %s is %s but %s", kin_mode,
                 listed ? "listed" : "not listed",
                 listed ? "infeasible" : "feasible");

    wc_modes_clear(M);
    wc_problem_clear(P);
    wc_error_clear(err);
    return 0;
}
