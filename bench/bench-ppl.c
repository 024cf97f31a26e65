/* bench-ppl.c -- the same mode cones by the Parma Polyhedra Library (PPL)
   and by our direct route, side by side in one process.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Usage: bench-ppl [MAXN] [SECONDS_PER_CELL]
   Problems: those of bench-cone (wcbench_cone_problem: n touching fixels
   on a circle, inward normals), n = 1, 2, 4, 6, 8, 12, 16, 25, 50, 100,
   200 up to MAXN (default 200), modes l..l, n..n, s..s and two mixed
   ones, nsm and nlsr repeated (the last is infeasible from n = 2 on: an
   empty cone, decided by both).

   PPL gets the problem as a user who knows only Table 2 would write it:
   an NNC polyhedron over (g, nudot, c) in R^(6+2n) with the wrench
   equation g - M nudot + J c = 0, the mode's constraints on a = J^T nudot
   (equalities, non-strict and strict inequalities) and on the contact
   forces c (c_n >= 0, the friction equalities of l and r, the friction
   cone of n and m, c = 0 for s, a, u), all scaled to integer rows; then
   it removes the 6 + 2n - 3 dimensions other than g and asks for the
   minimized constraints and minimized generators.  The PPL time starts
   from those integer rows (their making, from J and M, is not timed) and
   ends with both minimized systems; ours is one wc_wrench_cone_direct
   call from the problem to the canonical cone with its faces.  Each cell
   is the mean over repeated runs of at least SECONDS_PER_CELL (default
   0.2 s, at least one run).

   Every pair is checked to be the same cone: emptiness, then the closure
   (PPL's minimized closure generators made into a wc_cone_t and compared
   field for field with ours: facets, equalities, rays, lines), then for
   every face of the closure whether its relative-interior point lies in
   PPL's polyhedron exactly when we say the face is included.  A mismatch
   is printed and the program exits with status 4.  Ratios measured in
   this one process are the numbers to compare, not the absolute times.
   The last line is "direct vs PPL: N x at n=50, MIN x at least for
   n >= 4".  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <ppl_c.h>

#include "wrenchcone.h"
#include "benchutil.h"

#define PPL_OK(call) do { if ((call) < 0) ppl_die(#call); } while (0)

static void
ppl_die(const char * what)
{
    fprintf(stderr, "bench-ppl: PPL call failed: %s\n", what);
    exit(3);
}

/* The integer constraint system handed to PPL: rows x dim coefficients
   and a relation per row (row . (g, nudot, c) REL 0).  */
typedef struct
{
    slong rows;
    slong dim;
    mpz_t * coef;
    enum ppl_enum_Constraint_Type * rel;
}
sys_struct;

/* Append the row R (one fmpq_mat row of dim entries) scaled to coprime
   integers.  */
static void
sys_add(sys_struct * S, const fmpq_mat_t R, enum ppl_enum_Constraint_Type rel)
{
    fmpz_mat_t Z;
    fmpz_t den;
    slong j;

    fmpz_mat_init(Z, 1, S->dim);
    fmpz_init(den);
    fmpq_mat_get_fmpz_mat_rowwise(Z, den, R);
    S->coef = realloc(S->coef, (S->rows + 1) * S->dim * sizeof(mpz_t));
    S->rel = realloc(S->rel, (S->rows + 1) * sizeof(*S->rel));
    if (S->coef == NULL || S->rel == NULL)
    {
        fprintf(stderr, "bench-ppl: out of memory\n");
        exit(3);
    }
    for (j = 0; j < S->dim; j++)
    {
        mpz_init(S->coef[S->rows * S->dim + j]);
        fmpz_get_mpz(S->coef[S->rows * S->dim + j], fmpz_mat_entry(Z, 0, j));
    }
    S->rel[S->rows++] = rel;
    fmpz_mat_clear(Z);
    fmpz_clear(den);
}

/* One row: coefficient a on variable u (and b on v when v >= 0).  */
static void
sys_add2(sys_struct * S, slong u, const fmpq_t a, slong v, const fmpq_t b,
         enum ppl_enum_Constraint_Type rel)
{
    fmpq_mat_t R;

    fmpq_mat_init(R, 1, S->dim);
    fmpq_set(fmpq_mat_entry(R, 0, u), a);
    if (v >= 0)
        fmpq_set(fmpq_mat_entry(R, 0, v), b);
    sys_add(S, R, rel);
    fmpq_mat_clear(R);
}

/* (J^T nudot)_col REL 0.  */
static void
sys_add_a(sys_struct * S, const fmpq_mat_t J, slong col,
          enum ppl_enum_Constraint_Type rel)
{
    fmpq_mat_t R;
    slong k;

    fmpq_mat_init(R, 1, S->dim);
    for (k = 0; k < 3; k++)
        fmpq_set(fmpq_mat_entry(R, 0, 3 + k), fmpq_mat_entry(J, k, col));
    sys_add(S, R, rel);
    fmpq_mat_clear(R);
}

/* The system of the mode cone of mode over (g, nudot, c), c = (c_n, c_t),
   straight from Table 2 (it shares nothing with direct.c but J and M).  */
static void
sys_build(sys_struct * S, const wc_problem_t P, const char * mode)
{
    slong n = P->n, i, j, k;
    fmpq_mat_t J, M, R;
    fmpq_t one, mu;

    S->rows = 0;
    S->dim = 6 + 2 * n;
    S->coef = NULL;
    S->rel = NULL;
    fmpq_mat_init(J, 3, 2 * n);
    fmpq_mat_init(M, 3, 3);
    fmpq_init(one);
    fmpq_init(mu);
    fmpq_one(one);
    wc_model_J(J, P);
    wc_model_M(M, P);
    for (j = 0; j < 3; j++)             /* g - M nudot + J c = 0 */
    {
        fmpq_mat_init(R, 1, S->dim);
        fmpq_one(fmpq_mat_entry(R, 0, j));
        for (k = 0; k < 3; k++)
            fmpq_neg(fmpq_mat_entry(R, 0, 3 + k), fmpq_mat_entry(M, j, k));
        for (k = 0; k < 2 * n; k++)
            fmpq_set(fmpq_mat_entry(R, 0, 6 + k), fmpq_mat_entry(J, j, k));
        sys_add(S, R, PPL_CONSTRAINT_TYPE_EQUAL);
        fmpq_mat_clear(R);
    }
    for (i = 0; i < n; i++)
    {
        slong cn = 6 + i, ct = 6 + n + i;
        const wc_fixel_struct * f = P->fixels + i;

        switch (mode[i])
        {
        case 's': sys_add_a(S, J, i, PPL_CONSTRAINT_TYPE_GREATER_OR_EQUAL);
                  break;
        case 'a': sys_add_a(S, J, i, PPL_CONSTRAINT_TYPE_LESS_THAN); break;
        case 'l': sys_add_a(S, J, i, PPL_CONSTRAINT_TYPE_EQUAL);
                  sys_add_a(S, J, n + i, PPL_CONSTRAINT_TYPE_GREATER_THAN);
                  break;
        case 'r': sys_add_a(S, J, i, PPL_CONSTRAINT_TYPE_EQUAL);
                  sys_add_a(S, J, n + i, PPL_CONSTRAINT_TYPE_LESS_THAN);
                  break;
        case 'n': sys_add_a(S, J, i, PPL_CONSTRAINT_TYPE_EQUAL);
                  sys_add_a(S, J, n + i, PPL_CONSTRAINT_TYPE_EQUAL); break;
        case 'm': sys_add_a(S, J, i, PPL_CONSTRAINT_TYPE_EQUAL); break;
        default: break;
        }
        switch (mode[i])
        {
        case 'l':                       /* c_t + mu_k c_n = 0 */
        case 'r':                       /* c_t - mu_k c_n = 0 */
            sys_add2(S, cn, one, -1, one, PPL_CONSTRAINT_TYPE_GREATER_OR_EQUAL);
            if (mode[i] == 'l')
                fmpq_set(mu, f->mu_k);
            else
                fmpq_neg(mu, f->mu_k);
            sys_add2(S, ct, one, cn, mu, PPL_CONSTRAINT_TYPE_EQUAL);
            break;
        case 'n':                       /* mu_s c_n -+ c_t >= 0 */
        case 'm':
            sys_add2(S, cn, one, -1, one, PPL_CONSTRAINT_TYPE_GREATER_OR_EQUAL);
            sys_add2(S, cn, f->mu_s, ct, one,
                     PPL_CONSTRAINT_TYPE_GREATER_OR_EQUAL);
            fmpq_neg(mu, one);
            sys_add2(S, cn, f->mu_s, ct, mu,
                     PPL_CONSTRAINT_TYPE_GREATER_OR_EQUAL);
            break;
        default:                        /* s, a, u: no contact force */
            sys_add2(S, cn, one, -1, one, PPL_CONSTRAINT_TYPE_EQUAL);
            sys_add2(S, ct, one, -1, one, PPL_CONSTRAINT_TYPE_EQUAL);
            break;
        }
    }
    fmpq_mat_clear(J);
    fmpq_mat_clear(M);
    fmpq_clear(one);
    fmpq_clear(mu);
}

static void
sys_clear(sys_struct * S)
{
    slong i;

    for (i = 0; i < S->rows * S->dim; i++)
        mpz_clear(S->coef[i]);
    free(S->coef);
    free(S->rel);
}

/* The timed PPL work: build the NNC polyhedron, project onto g, minimize
   both representations.  The caller deletes *ph.  */
static void
ppl_cone(ppl_Polyhedron_t * ph, const sys_struct * S, ppl_Coefficient_t k)
{
    ppl_Constraint_System_t cs;
    ppl_const_Constraint_System_t mc;
    ppl_const_Generator_System_t mg;
    slong r, j;

    PPL_OK(ppl_new_Constraint_System(&cs));
    for (r = 0; r < S->rows; r++)
    {
        ppl_Linear_Expression_t le;
        ppl_Constraint_t c;

        PPL_OK(ppl_new_Linear_Expression_with_dimension(&le, S->dim));
        for (j = 0; j < S->dim; j++)
            if (mpz_sgn(S->coef[r * S->dim + j]) != 0)
            {
                PPL_OK(ppl_assign_Coefficient_from_mpz_t(k,
                                                 S->coef[r * S->dim + j]));
                PPL_OK(ppl_Linear_Expression_add_to_coefficient(le, j, k));
            }
        PPL_OK(ppl_new_Constraint(&c, le, S->rel[r]));
        PPL_OK(ppl_Constraint_System_insert_Constraint(cs, c));
        PPL_OK(ppl_delete_Constraint(c));
        PPL_OK(ppl_delete_Linear_Expression(le));
    }
    PPL_OK(ppl_new_NNC_Polyhedron_recycle_Constraint_System(ph, cs));
    PPL_OK(ppl_delete_Constraint_System(cs));
    PPL_OK(ppl_Polyhedron_remove_higher_space_dimensions(*ph, 3));
    PPL_OK(ppl_Polyhedron_get_minimized_constraints(*ph, &mc));
    PPL_OK(ppl_Polyhedron_get_minimized_generators(*ph, &mg));
}

/* Read the closure generators of ph into rays and lines (3 columns).
   Returns 0, or 1 when a point other than the origin shows up (then the
   projection is not a cone: a mismatch).  */
static int
ppl_closure_generators(fmpq_mat_t rays, fmpq_mat_t lines,
                       ppl_const_Polyhedron_t ph)
{
    ppl_Polyhedron_t cl;
    ppl_const_Generator_System_t gs;
    ppl_Generator_System_const_iterator_t it, end;
    ppl_Coefficient_t k;
    mpz_t z;
    fmpq_mat_t R, L;
    slong nr = 0, nl = 0, j;
    int bad = 0;

    mpz_init(z);
    fmpq_mat_init(R, 0, 3);
    fmpq_mat_init(L, 0, 3);
    PPL_OK(ppl_new_Coefficient(&k));
    PPL_OK(ppl_new_NNC_Polyhedron_from_NNC_Polyhedron(&cl, ph));
    PPL_OK(ppl_Polyhedron_topological_closure_assign(cl));
    PPL_OK(ppl_Polyhedron_get_minimized_generators(cl, &gs));
    PPL_OK(ppl_new_Generator_System_const_iterator(&it));
    PPL_OK(ppl_new_Generator_System_const_iterator(&end));
    PPL_OK(ppl_Generator_System_begin(gs, it));
    PPL_OK(ppl_Generator_System_end(gs, end));
    while (!ppl_Generator_System_const_iterator_equal_test(it, end))
    {
        ppl_const_Generator_t g;
        int type;
        fmpz v[3];

        PPL_OK(ppl_Generator_System_const_iterator_dereference(it, &g));
        type = ppl_Generator_type(g);
        for (j = 0; j < 3; j++)
        {
            fmpz_init(v + j);
            PPL_OK(ppl_Generator_coefficient(g, j, k));
            PPL_OK(ppl_Coefficient_to_mpz_t(k, z));
            fmpz_set_mpz(v + j, z);
        }
        if (type == PPL_GENERATOR_TYPE_RAY || type == PPL_GENERATOR_TYPE_LINE)
        {
            fmpq_mat_t T, * X = type == PPL_GENERATOR_TYPE_RAY ? &R : &L;
            slong * cnt = type == PPL_GENERATOR_TYPE_RAY ? &nr : &nl, i;

            fmpq_mat_init(T, *cnt + 1, 3);
            for (i = 0; i < *cnt; i++)
                for (j = 0; j < 3; j++)
                    fmpq_set(fmpq_mat_entry(T, i, j),
                             fmpq_mat_entry(*X, i, j));
            for (j = 0; j < 3; j++)
            {
                fmpz_set(fmpq_numref(fmpq_mat_entry(T, *cnt, j)), v + j);
                fmpz_one(fmpq_denref(fmpq_mat_entry(T, *cnt, j)));
            }
            fmpq_mat_swap(*X, T);
            fmpq_mat_clear(T);
            (*cnt)++;
        }
        else if (!fmpz_is_zero(v) || !fmpz_is_zero(v + 1)
                 || !fmpz_is_zero(v + 2))
            bad = 1;
        for (j = 0; j < 3; j++)
            fmpz_clear(v + j);
        PPL_OK(ppl_Generator_System_const_iterator_increment(it));
    }
    fmpq_mat_swap(rays, R);
    fmpq_mat_swap(lines, L);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
    PPL_OK(ppl_delete_Generator_System_const_iterator(it));
    PPL_OK(ppl_delete_Generator_System_const_iterator(end));
    PPL_OK(ppl_delete_Polyhedron(cl));
    PPL_OK(ppl_delete_Coefficient(k));
    mpz_clear(z);
    return bad;
}

/* 1 when the point p (3 integers) lies in ph.  */
static int
ppl_contains(ppl_const_Polyhedron_t ph, const fmpz * p)
{
    ppl_Linear_Expression_t le;
    ppl_Generator_t g;
    ppl_Coefficient_t k;
    mpz_t z;
    slong j;
    int rel;

    mpz_init(z);
    PPL_OK(ppl_new_Coefficient(&k));
    PPL_OK(ppl_new_Linear_Expression_with_dimension(&le, 3));
    for (j = 0; j < 3; j++)
    {
        fmpz_get_mpz(z, p + j);
        PPL_OK(ppl_assign_Coefficient_from_mpz_t(k, z));
        PPL_OK(ppl_Linear_Expression_add_to_coefficient(le, j, k));
    }
    mpz_set_ui(z, 1);
    PPL_OK(ppl_assign_Coefficient_from_mpz_t(k, z));
    PPL_OK(ppl_new_Generator(&g, le, PPL_GENERATOR_TYPE_POINT, k));
    rel = ppl_Polyhedron_relation_with_Generator(ph, g);
    if (rel < 0)
        ppl_die("ppl_Polyhedron_relation_with_Generator");
    PPL_OK(ppl_delete_Generator(g));
    PPL_OK(ppl_delete_Linear_Expression(le));
    PPL_OK(ppl_delete_Coefficient(k));
    mpz_clear(z);
    return (rel & PPL_POLY_GEN_RELATION_SUBSUMES) != 0;
}

/* NULL when ph and W are the same NNC cone, else what differs.  */
static const char *
same_cone(ppl_const_Polyhedron_t ph, const wc_cone_t W)
{
    fmpq_mat_t rays, lines;
    wc_cone_t C;
    wc_error_t err;
    const char * why = NULL;
    slong f, i, j;
    fmpz p[3];

    if (ppl_Polyhedron_is_empty(ph) != W->empty)
        return "emptiness";
    if (W->empty)
        return NULL;
    fmpq_mat_init(rays, 0, 3);
    fmpq_mat_init(lines, 0, 3);
    wc_cone_init(C, 3);
    wc_error_init(err);
    for (j = 0; j < 3; j++)
        fmpz_init(p + j);
    if (ppl_closure_generators(rays, lines, ph))
        why = "PPL's projection has a point other than the origin";
    else if (wc_cone_set_generators(C, rays, lines, err) != WC_OK)
        wcbench_die("bench-ppl", "wc_cone_set_generators", err);
    else if (C->dim != W->dim || C->lineality_dim != W->lineality_dim
             || !fmpz_mat_equal(C->ineqs, W->ineqs)
             || !fmpz_mat_equal(C->eqs, W->eqs)
             || !fmpz_mat_equal(C->rays, W->rays)
             || !fmpz_mat_equal(C->lines, W->lines)
             || fmpq_mat_nrows(rays) != fmpz_mat_nrows(W->rays)
             || fmpq_mat_nrows(lines) != fmpz_mat_nrows(W->lines))
        why = "closure";
    for (f = 0; why == NULL && f < W->nfaces; f++)
    {
        const wc_face_struct * F = W->faces + f;

        for (j = 0; j < 3; j++)
            fmpz_zero(p + j);
        for (i = 0; i < F->nrays; i++)
            for (j = 0; j < 3; j++)
                fmpz_add(p + j, p + j, fmpz_mat_entry(W->rays, F->rays[i], j));
        if (ppl_contains(ph, p) != F->included)
            why = "strictness (a face included by one and not the other)";
    }
    for (j = 0; j < 3; j++)
        fmpz_clear(p + j);
    wc_error_clear(err);
    wc_cone_clear(C);
    fmpq_mat_clear(rays);
    fmpq_mat_clear(lines);
    return why;
}

/* Mean seconds per PPL cone; *last gets the polyhedron of the last run.  */
static double
time_ppl(ppl_Polyhedron_t * last, const sys_struct * S, double budget)
{
    ppl_Coefficient_t k;
    double t0 = wcbench_now(), t;
    long reps = 0;

    PPL_OK(ppl_new_Coefficient(&k));
    *last = NULL;
    do
    {
        if (*last != NULL)
            PPL_OK(ppl_delete_Polyhedron(*last));
        ppl_cone(last, S, k);
        reps++;
        t = wcbench_now() - t0;
    }
    while (t < budget);
    PPL_OK(ppl_delete_Coefficient(k));
    return t / reps;
}

/* Mean seconds per direct-route cone; W gets the cone.  */
static double
time_direct(wc_cone_t W, const wc_problem_t P, const char * mode,
            double budget)
{
    wc_error_t err;
    double t0 = wcbench_now(), t;
    long reps = 0;

    wc_error_init(err);
    do
    {
        if (wc_wrench_cone_direct(W, NULL, P, mode, err) != WC_OK)
            wcbench_die("bench-ppl", "wc_wrench_cone_direct", err);
        reps++;
        t = wcbench_now() - t0;
    }
    while (t < budget);
    wc_error_clear(err);
    return t / reps;
}

int
main(int argc, char ** argv)
{
    static const slong sizes[] = { 1, 2, 4, 6, 8, 12, 16, 25, 50, 100, 200 };
    static const char * names[] = { "l..l", "n..n", "s..s", "nsm..",
                                    "nlsr.." };
    static const char * pattern[] = { "l", "n", "s", "nsm", "nlsr" };
    slong maxn = argc > 1 ? atol(argv[1]) : 200, s, m, i, npts = 0;
    double budget = argc > 2 ? atof(argv[2]) : 0.2, ratio50 = 0,
           minratio = 0, xs[16], yd[16], yp[16];
    const char * version = "?";

    /* PPL first: it may set GMP's memory functions.  */
    PPL_OK(ppl_initialize());
    wc_init();
    PPL_OK(ppl_version(&version));
    printf("One mode cone, mean time per cone (ms), exact arithmetic both: "
           "PPL %s NNC_Polyhedron\n(constraints over (g, nudot, c), "
           "projected onto g, minimized constraints and generators)\n"
           "against wc_wrench_cone_direct.\n", version);
    printf("%4s  %-6s  %12s  %12s  %10s  %s\n", "n", "mode", "PPL ms",
           "direct ms", "PPL/direct", "cone");
    for (s = 0; s < (slong) (sizeof sizes / sizeof sizes[0]); s++)
    {
        slong n = sizes[s];
        double sp = 0, sd = 0;
        char * mode;

        if (n > maxn)
            break;
        mode = malloc(n + 1);
        if (mode == NULL)
            return 3;
        for (m = 0; m < 5; m++)
        {
            wc_problem_t P;
            sys_struct S;
            ppl_Polyhedron_t ph;
            wc_cone_t W;
            const char * why;
            double tp, td;

            for (i = 0; i < n; i++)
                mode[i] = pattern[m][i % strlen(pattern[m])];
            mode[n] = '\0';
            wc_problem_init(P);
            wcbench_cone_problem(P, n);
            wc_cone_init(W, 3);
            sys_build(&S, P, mode);
            tp = time_ppl(&ph, &S, budget);
            td = time_direct(W, P, mode, budget);
            if ((why = same_cone(ph, W)) != NULL)
            {
                fprintf(stderr, "bench-ppl: MISMATCH at n=%ld, mode %s: PPL "
                        "and the direct route differ in %s\n", (long) n,
                        mode, why);
                return 4;
            }
            printf("%4ld  %-6s  %12.4f  %12.4f  %10.1f  %s\n", (long) n,
                   names[m], 1e3 * tp, 1e3 * td, tp / td,
                   W->empty ? "empty" : "same cone");
            fflush(stdout);
            sp += tp;
            sd += td;
            PPL_OK(ppl_delete_Polyhedron(ph));
            sys_clear(&S);
            wc_cone_clear(W);
            wc_problem_clear(P);
        }
        free(mode);
        printf("%4ld  %-6s  %12.4f  %12.4f  %10.1f  (all five modes)\n",
               (long) n, "sum", 1e3 * sp, 1e3 * sd, sp / sd);
        if (n == 50)
            ratio50 = sp / sd;
        if (n >= 4 && (minratio == 0 || sp / sd < minratio))
            minratio = sp / sd;
        if (n >= 8)
        {
            xs[npts] = n;
            yp[npts] = sp;
            yd[npts++] = sd;
        }
    }
    if (npts >= 2)
        printf("growth exponent, n = 8..%ld (least-squares slope of log time "
               "vs log n): PPL %.2f, direct %.2f\n", (long) xs[npts - 1],
               wcbench_slope(xs, yp, npts), wcbench_slope(xs, yd, npts));
    if (maxn >= 50)
        printf("direct vs PPL: %.1f x at n=50, %.1f x at least for n >= 4\n",
               ratio50, minratio);
    flint_cleanup_master();
    ppl_finalize();
    return 0;
}
