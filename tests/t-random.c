/* t-random.c -- the seeded problem generator (lib/random.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   (a) The same options give byte-identical problems, different seeds
   different ones, and two pinned problems come out exactly as recorded
   (the generator is a fixed function of its options on every platform).
   (b) Every problem passes wc_problem_check, and wc_problem_fprint then
   wc_problem_parse gives the same problem, field for field and byte for
   byte.  (c) Shapes: every contact point lies on the boundary and its
   normal is the true inward normal, checked here by our own geometry and
   again by the parser, which derives the normal when the file omits it.
   (d) Degenerate problems hold the features random.h promises for their
   shape and size, checked exactly.  (e) The direct and the paper route
   print the same canonical cone for random modes.  (f) Bad options are
   errors that leave the problem alone; the reproducing command line is
   canonical.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "core/random.h"
#include "testutil.h"

/* ------------------------------------------------------------------ */
/* Helpers.                                                            */

/* P as wc_problem_fprint writes it; malloc'd.  With skip_name the name
   line is left out (it names the seed).  */
static char *
print_problem(const wc_problem_t P, int skip_name)
{
    char * buf = NULL, * save = P->name;
    size_t len = 0;
    FILE * f = open_memstream(&buf, &len);
    int status;

    if (f == NULL)
        wctest_fail("open_memstream failed");
    if (skip_name)
        ((wc_problem_struct *) P)->name = NULL;
    status = wc_problem_fprint(f, P);
    ((wc_problem_struct *) P)->name = save;
    if (fclose(f) != 0 || status != WC_OK)
        wctest_fail("wc_problem_fprint failed");
    return buf;
}

static void
opt_set(wc_random_options * o, slong n, uint64_t seed, int degenerate,
        wc_shape_kind shape)
{
    o->fixels = n;
    o->seed = seed;
    o->degenerate = degenerate;
    o->shape = shape;
}

static const char *
shape_name(wc_shape_kind s)
{
    return s == WC_SHAPE_DISK ? "disk" : s == WC_SHAPE_POLYGON ? "polygon"
        : "none";
}

/* Generate into P (freshly initialised); failures name the options.  */
static void
generate(wc_problem_t P, const wc_random_options * o)
{
    wc_error_t err;
    int status;

    wc_error_init(err);
    status = wc_random_problem(P, o, err);
    if (status != WC_OK)
        wctest_fail("wc_random_problem(n=%ld, seed=%llu, degenerate=%d, "
                    "shape=%s) returned %d: %s", (long) o->fixels,
                    (unsigned long long) o->seed, o->degenerate,
                    shape_name(o->shape), status,
                    err->message != NULL ? err->message : "");
    wc_error_clear(err);
}

static int
q_equal_vec(const fmpq * a, const fmpq * b, slong len)
{
    slong i;

    for (i = 0; i < len; i++)
        if (!fmpq_equal(a + i, b + i))
            return 0;
    return 1;
}

/* Field-by-field equality of two problems (file and line numbers
   excepted: they say where a parsed problem came from).  */
static int
problem_equal(const wc_problem_t A, const wc_problem_t B)
{
    slong i;

    if ((A->name == NULL) != (B->name == NULL)
        || (A->name != NULL && strcmp(A->name, B->name) != 0)
        || !fmpq_equal(A->mass, B->mass) || !fmpq_equal(A->inertia, B->inertia)
        || !q_equal_vec(A->com, B->com, 2)
        || !fmpq_equal(A->mu_s, B->mu_s) || !fmpq_equal(A->mu_k, B->mu_k)
        || A->shape != B->shape || A->shape_len != B->shape_len
        || !q_equal_vec(A->shape_data, B->shape_data, A->shape_len)
        || A->n != B->n)
        return 0;
    for (i = 0; i < A->n; i++)
    {
        const wc_fixel_struct * a = A->fixels + i, * b = B->fixels + i;

        if (!q_equal_vec(a->point, b->point, 2)
            || !q_equal_vec(a->normal, b->normal, 2) || a->state != b->state
            || !fmpq_equal(a->mu_s, b->mu_s) || !fmpq_equal(a->mu_k, b->mu_k))
            return 0;
    }
    return 1;
}

/* x = a x b and y = a . b for plane vectors.  */
static void
cross_dot(fmpq_t x, fmpq_t y, const fmpq * a, const fmpq * b)
{
    fmpq_t t;

    fmpq_init(t);
    fmpq_mul(x, a + 0, b + 1);
    fmpq_mul(t, a + 1, b + 0);
    fmpq_sub(x, x, t);
    fmpq_mul(y, a + 0, b + 0);
    fmpq_mul(t, a + 1, b + 1);
    fmpq_add(y, y, t);
    fmpq_clear(t);
}

/* orientation of (a, b, c): sign of (b - a) x (c - a) */
static int
orient(const fmpq * a, const fmpq * b, const fmpq * c)
{
    fmpq u[2], v[2];
    fmpq_t x, y;
    int s;

    fmpq_init(u + 0);
    fmpq_init(u + 1);
    fmpq_init(v + 0);
    fmpq_init(v + 1);
    fmpq_init(x);
    fmpq_init(y);
    fmpq_sub(u + 0, b + 0, a + 0);
    fmpq_sub(u + 1, b + 1, a + 1);
    fmpq_sub(v + 0, c + 0, a + 0);
    fmpq_sub(v + 1, c + 1, a + 1);
    cross_dot(x, y, u, v);
    s = fmpq_sgn(x);
    fmpq_clear(u + 0);
    fmpq_clear(u + 1);
    fmpq_clear(v + 0);
    fmpq_clear(v + 1);
    fmpq_clear(x);
    fmpq_clear(y);
    return s;
}

/* ------------------------------------------------------------------ */
/* (a) reproducibility                                                 */

/* Two problems recorded when the generator was written.  They must never
   change: data/corpus/ and every user's recorded seeds depend on them.  */
static void
check_pinned(void)
{
    static const char * const expect[2] = {
        "name \"random --fixels=3 --seed=7 --degenerate\"\n"
        "mass 3\n"
        "inertia 1\n"
        "com 0 0\n"
        "friction 0 1\n"
        "fixel 13/3 17/6 normal -6 4 near friction 0 1\n"
        "fixel 3 4/3 normal -3 2 near friction 2 2\n"
        "fixel 3 4/3 normal -1499999999/500000000 2000000003/1000000000 "
        "touching friction 0 1\n",
        "name \"random --fixels=2 --seed=42 --shape=disk --friction=1/5,1/10\"\n"
        "mass 1\n"
        "inertia 1\n"
        "com -2 1\n"
        "friction 1/5 1/10\n"
        "shape disk -2 1 3/2\n"
        "fixel -67/26 -5/13 normal 15/26 18/13 touching friction 1/5 1/10\n"
        "fixel -11/10 -1/5 normal -9/10 6/5 touching friction 1/5 1/10\n"
    };
    wc_random_options o;
    slong k;

    wc_random_options_init(&o);
    for (k = 0; k < 2; k++)
    {
        wc_problem_t P;
        char * text;

        wc_problem_init(P);
        if (k == 0)
            opt_set(&o, 3, 7, 1, WC_SHAPE_NONE);
        else
        {
            opt_set(&o, 2, 42, 0, WC_SHAPE_DISK);
            o.friction = 1;
            fmpq_set_si(o.mu_s, 1, 5);
            fmpq_set_si(o.mu_k, 1, 10);
        }
        generate(P, &o);
        text = print_problem(P, 0);
        if (strcmp(text, expect[k]) != 0)
            wctest_fail("pinned problem %ld changed; expected\n%sgot\n%s",
                        (long) k, expect[k], text);
        free(text);
        wc_problem_clear(P);
    }
    wc_random_options_clear(&o);
}

/* Same options, same bytes; another seed, another problem.  */
static void
check_reproducible(const wc_random_options * o)
{
    wc_random_options o2 = *o;      /* shallow: read, never cleared */
    wc_problem_t A, B, C;
    char * a, * b, * c;

    wc_problem_init(A);
    wc_problem_init(B);
    wc_problem_init(C);
    generate(A, o);
    generate(B, o);
    o2.seed = o->seed + 1;
    generate(C, &o2);
    a = print_problem(A, 0);
    b = print_problem(B, 0);
    if (strcmp(a, b) != 0)
        wctest_fail("the same options gave two problems:\n%s---\n%s", a, b);
    free(a);
    free(b);
    a = print_problem(A, 1);
    c = print_problem(C, 1);
    if (strcmp(a, c) == 0)
        wctest_fail("seeds %llu and %llu gave the same problem:\n%s",
                    (unsigned long long) o->seed,
                    (unsigned long long) o2.seed, a);
    free(a);
    free(c);
    wc_problem_clear(A);
    wc_problem_clear(B);
    wc_problem_clear(C);
}

/* ------------------------------------------------------------------ */
/* (b) validity and the round trip through the parser                  */

static void
check_round_trip(const wc_problem_t P)
{
    wc_problem_t Q;
    wc_error_t err;
    char * a, * b;
    int status;

    wc_error_init(err);
    if (wc_problem_check(P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "wc_problem_check: %s", err->message);
    a = print_problem(P, 0);
    wc_problem_init(Q);
    status = wc_problem_parse(Q, a, strlen(a), "<random>", err);
    if (status != WC_OK)
        wctest_fail_problem(P, NULL, "the printed problem does not parse: "
                            "line %ld col %ld: %s", err->line, err->col,
                            err->message);
    if (!problem_equal(P, Q))
        wctest_fail_problem(P, NULL, "the parser read back another problem");
    b = print_problem(Q, 0);
    if (strcmp(a, b) != 0)
        wctest_fail_problem(P, NULL, "printed again, the problem reads\n%s",
                            b);
    free(a);
    free(b);
    wc_problem_clear(Q);
    wc_error_clear(err);
}

/* ------------------------------------------------------------------ */
/* (c) points on the shape, true inward normals                        */

/* The inward normal of edge k of P's polygon, the edge vector turned
   towards the interior: +90 degrees when the polygon runs
   counter-clockwise (positive signed area).  */
static void
edge_inward(fmpq * d, const wc_problem_t P, slong k, int ccw)
{
    slong m = P->shape_len / 2;
    const fmpq * a = P->shape_data + 2 * k;
    const fmpq * b = P->shape_data + 2 * ((k + 1) % m);

    fmpq_sub(d + 0, a + 1, b + 1);
    fmpq_sub(d + 1, b + 0, a + 0);
    if (!ccw)
    {
        fmpq_neg(d + 0, d + 0);
        fmpq_neg(d + 1, d + 1);
    }
}

static int
polygon_ccw(const wc_problem_t P)
{
    slong m = P->shape_len / 2, k;
    fmpq_t area, t;
    int s;

    fmpq_init(area);
    fmpq_init(t);
    for (k = 0; k < m; k++)
    {
        const fmpq * a = P->shape_data + 2 * k;
        const fmpq * b = P->shape_data + 2 * ((k + 1) % m);

        fmpq_mul(t, a + 0, b + 1);
        fmpq_add(area, area, t);
        fmpq_mul(t, a + 1, b + 0);
        fmpq_sub(area, area, t);
    }
    s = fmpq_sgn(area);
    fmpq_clear(area);
    fmpq_clear(t);
    if (s == 0)
        wctest_fail_problem(P, NULL, "polygon of zero area");
    return s > 0;
}

/* 1 when p lies on the closed segment [a, b].  */
static int
on_segment(const fmpq * p, const fmpq * a, const fmpq * b)
{
    slong j;

    if (orient(a, b, p) != 0)
        return 0;
    for (j = 0; j < 2; j++)
    {
        const fmpq * lo = fmpq_cmp(a + j, b + j) <= 0 ? a + j : b + j;
        const fmpq * hi = lo == a + j ? b + j : a + j;

        if (fmpq_cmp(p + j, lo) < 0 || fmpq_cmp(p + j, hi) > 0)
            return 0;
    }
    return 1;
}

/* The polygon must be strictly convex (the generator promises it; the
   parser would accept any simple polygon).  */
static void
check_convex(const wc_problem_t P)
{
    slong m = P->shape_len / 2, k;
    int s0 = 0;

    for (k = 0; k < m; k++)
    {
        int s = orient(P->shape_data + 2 * k,
                       P->shape_data + 2 * ((k + 1) % m),
                       P->shape_data + 2 * ((k + 2) % m));

        if (s == 0 || (s0 != 0 && s != s0))
            wctest_fail_problem(P, NULL, "polygon not strictly convex at "
                                "vertex %ld", (long) (k + 1) % m);
        s0 = s;
    }
}

/* Our own geometry first; then, for every fixel not at a vertex, the
   parser's derivation of the normal from the shape when the file leaves
   it out must give the same vector.  */
static void
check_on_shape(const wc_problem_t P)
{
    slong i, k, m = P->shape_len / 2;
    int ccw = 0;
    fmpq d[2];
    fmpq_t x, y;
    char * text = NULL;
    size_t len = 0;
    FILE * f;
    wc_problem_t Q;
    wc_error_t err;
    int * derived;

    if (P->shape == WC_SHAPE_NONE)
        return;
    fmpq_init(d + 0);
    fmpq_init(d + 1);
    fmpq_init(x);
    fmpq_init(y);
    derived = calloc((size_t) P->n, sizeof(int));
    if (P->shape == WC_SHAPE_POLYGON)
    {
        check_convex(P);
        ccw = polygon_ccw(P);
    }
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * fx = P->fixels + i;

        if (P->shape == WC_SHAPE_DISK)
        {
            const fmpq * c = P->shape_data;

            fmpq_sub(d + 0, c + 0, fx->point + 0);
            fmpq_sub(d + 1, c + 1, fx->point + 1);
            cross_dot(x, y, d, d);
            fmpq_mul(x, c + 2, c + 2);
            if (!fmpq_equal(x, y))
                wctest_fail_problem(P, NULL, "fixel %ld is not on the circle",
                                    (long) i + 1);
            if (!q_equal_vec(d, fx->normal, 2))
                wctest_fail_problem(P, NULL, "fixel %ld: normal is not c - p",
                                    (long) i + 1);
            derived[i] = 1;
            continue;
        }
        {
            int on = 0, match = 0, vertex = 0;

            for (k = 0; k < m; k++)
            {
                if (q_equal_vec(fx->point, P->shape_data + 2 * k, 2))
                    vertex = 1;
                if (!on_segment(fx->point, P->shape_data + 2 * k,
                                P->shape_data + 2 * ((k + 1) % m)))
                    continue;
                on = 1;
                edge_inward(d, P, k, ccw);
                if (q_equal_vec(d, fx->normal, 2))
                    match = 1;
            }
            if (!on)
                wctest_fail_problem(P, NULL, "fixel %ld is not on the polygon",
                                    (long) i + 1);
            if (!match)
                wctest_fail_problem(P, NULL, "fixel %ld: normal is not the "
                                    "inward normal of its edge", (long) i + 1);
            derived[i] = !vertex;
        }
    }

    /* The parser's opinion: the same file with the normals left out. */
    f = open_memstream(&text, &len);
    if (f == NULL)
        wctest_fail("open_memstream failed");
    fputs("shape ", f);
    fputs(P->shape == WC_SHAPE_DISK ? "disk" : "polygon", f);
    for (k = 0; k < P->shape_len; k++)
    {
        fputc(' ', f);
        fmpq_fprint(f, P->shape_data + k);
    }
    fputc('\n', f);
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * fx = P->fixels + i;

        fputs("fixel ", f);
        fmpq_fprint(f, fx->point + 0);
        fputc(' ', f);
        fmpq_fprint(f, fx->point + 1);
        if (!derived[i])
        {
            fputs(" normal ", f);
            fmpq_fprint(f, fx->normal + 0);
            fputc(' ', f);
            fmpq_fprint(f, fx->normal + 1);
        }
        fputc('\n', f);
    }
    fclose(f);
    wc_problem_init(Q);
    wc_error_init(err);
    if (wc_problem_parse(Q, text, len, "<derive>", err) != WC_OK)
        wctest_fail_problem(P, NULL, "with the normals left out the problem "
                            "does not parse: line %ld: %s\n%s", err->line,
                            err->message, text);
    for (i = 0; i < P->n; i++)
        if (!q_equal_vec(Q->fixels[i].normal, P->fixels[i].normal, 2))
            wctest_fail_problem(P, NULL, "fixel %ld: the parser derives "
                                "another normal", (long) i + 1);
    wc_problem_clear(Q);
    wc_error_clear(err);
    free(text);
    free(derived);
    fmpq_clear(d + 0);
    fmpq_clear(d + 1);
    fmpq_clear(x);
    fmpq_clear(y);
}

/* ------------------------------------------------------------------ */
/* (d) the degenerate features                                         */

enum { F_S = 1, F_N = 2, F_P = 4, F_C = 8, F_O = 16, F_N_EXACT = 32 };

/* The features random.h promises for a shape and n.  */
static unsigned
promised(wc_shape_kind shape, slong n)
{
    unsigned f = 0;

    if (shape == WC_SHAPE_DISK)
        return F_O | (n >= 2 ? F_P : 0) | (n >= 3 ? F_N : 0);
    if (n == 1)
        f |= F_O;
    if (n >= 2)
        f |= F_S | F_N | F_N_EXACT;
    if (n >= 3)
        f |= F_P;
    if (n >= 4)
        f |= F_C;
    return f;
}

/* The features P has, looked for among all pairs and triples.  */
static unsigned
features(const wc_problem_t P)
{
    slong n = P->n, i, j, k;
    unsigned f = F_O;
    fmpq_t x, y, lo, hi, t;
    fmpq w[2];

    fmpq_init(x);
    fmpq_init(y);
    fmpq_init(lo);
    fmpq_init(hi);
    fmpq_init(t);
    fmpq_init(w + 0);
    fmpq_init(w + 1);
    fmpq_set_si(lo, 1, 1000000000);
    fmpq_set_si(hi, 2, 1000000000);
    for (i = 0; i < n; i++)
    {
        const wc_fixel_struct * a = P->fixels + i;

        /* O: the normal line through the centre of mass */
        fmpq_sub(w + 0, P->com + 0, a->point + 0);
        fmpq_sub(w + 1, P->com + 1, a->point + 1);
        cross_dot(x, y, a->normal, w);
        if (!fmpq_is_zero(x))
            f &= ~(unsigned) F_O;
        for (j = i + 1; j < n; j++)
        {
            const wc_fixel_struct * b = P->fixels + j;
            int same_point = q_equal_vec(a->point, b->point, 2);

            cross_dot(x, y, a->normal, b->normal);
            if (same_point)
                f |= F_S;
            if (fmpq_is_zero(x) && !same_point)
                f |= F_P;
            if (!fmpq_is_zero(x) && fmpq_sgn(y) > 0)
            {
                /* tan of the angle between them: |x| / y */
                fmpq_abs(x, x);
                fmpq_div(t, x, y);
                if (fmpq_cmp(t, lo) >= 0 && fmpq_cmp(t, hi) < 0)
                    f |= F_N;
                if (fmpq_equal(t, lo))
                    f |= F_N_EXACT;
            }
            for (k = j + 1; k < n && !(f & F_C); k++)
            {
                const wc_fixel_struct * c = P->fixels + k;

                if (!same_point && !q_equal_vec(a->point, c->point, 2)
                    && !q_equal_vec(b->point, c->point, 2)
                    && orient(a->point, b->point, c->point) == 0)
                    f |= F_C;
            }
        }
    }
    fmpq_clear(x);
    fmpq_clear(y);
    fmpq_clear(lo);
    fmpq_clear(hi);
    fmpq_clear(t);
    fmpq_clear(w + 0);
    fmpq_clear(w + 1);
    return f;
}

static void
check_features(const wc_problem_t P, const wc_random_options * o)
{
    unsigned want = promised(o->shape, o->fixels), have = features(P);
    slong i, j;

    if ((want & have) != want)
        wctest_fail_problem(P, NULL, "degenerate %s problem with %ld fixels: "
                            "features %#x promised, %#x found (S=1 N=2 P=4 "
                            "C=8 O=16 N exact=32)", shape_name(o->shape),
                            (long) o->fixels, want, have);
    /* never the same point and the same normal direction */
    for (i = 0; i < P->n; i++)
        for (j = i + 1; j < P->n; j++)
        {
            fmpq_t x, y;
            int bad;

            fmpq_init(x);
            fmpq_init(y);
            cross_dot(x, y, P->fixels[i].normal, P->fixels[j].normal);
            bad = q_equal_vec(P->fixels[i].point, P->fixels[j].point, 2)
                && fmpq_is_zero(x) && fmpq_sgn(y) > 0;
            fmpq_clear(x);
            fmpq_clear(y);
            if (bad)
                wctest_fail_problem(P, NULL, "fixels %ld and %ld repeat a "
                                    "contact", (long) i + 1, (long) j + 1);
        }
}

static void
check_friction(const wc_problem_t P, const wc_random_options * o)
{
    slong i;

    if (!o->friction)
        return;
    if (!fmpq_equal(P->mu_s, o->mu_s) || !fmpq_equal(P->mu_k, o->mu_k))
        wctest_fail_problem(P, NULL, "global friction is not the one given");
    for (i = 0; i < P->n; i++)
        if (!fmpq_equal(P->fixels[i].mu_s, o->mu_s)
            || !fmpq_equal(P->fixels[i].mu_k, o->mu_k))
            wctest_fail_problem(P, NULL, "fixel %ld: friction is not the one "
                                "given", (long) i + 1);
}

/* ------------------------------------------------------------------ */
/* (e) both routes, byte for byte                                      */

static void
check_routes(const wc_problem_t P, slong modes)
{
    char * mode = malloc((size_t) P->n + 1);
    slong k;

    for (k = 0; k < modes; k++)
    {
        wc_cone_t A, B;
        wc_error_t err;
        char * a, * b;

        wctest_random_mode(mode, P);
        wc_cone_init(A, 3);
        wc_cone_init(B, 3);
        wc_error_init(err);
        if (wc_wrench_cone_direct(A, NULL, P, mode, err) != WC_OK)
            wctest_fail_problem(P, mode, "direct route failed: %s",
                                err->message);
        if (wc_wrench_cone_paper(B, NULL, P, mode, err) != WC_OK)
            wctest_fail_problem(P, mode, "paper route failed: %s",
                                err->message);
        a = wctest_cone_json(A);
        b = wctest_cone_json(B);
        if (strcmp(a, b) != 0)
            wctest_fail_problem(P, mode,
                                "routes differ:\ndirect %s\npaper  %s", a, b);
        free(a);
        free(b);
        wc_cone_clear(A);
        wc_cone_clear(B);
        wc_error_clear(err);
    }
    free(mode);
}

/* ------------------------------------------------------------------ */
/* (f) bad options, the reproducing command line                       */

static void
check_bad_options(void)
{
    wc_random_options o;
    wc_problem_t P;
    wc_error_t err;
    slong k;

    wc_random_options_init(&o);
    for (k = 0; k < 5; k++)
    {
        opt_set(&o, 3, 1, 0, WC_SHAPE_NONE);
        o.friction = 0;
        if (k == 0)
            o.fixels = 0;
        else if (k == 1)
            o.fixels = WC_RANDOM_MAX_FIXELS + 1;
        else if (k == 2)
            o.shape = (wc_shape_kind) 7;
        else if (k == 3)
        {
            o.friction = 1;
            fmpq_set_si(o.mu_s, -1, 5);
            fmpq_zero(o.mu_k);
        }
        else
        {
            o.friction = 1;
            fmpq_zero(o.mu_s);
            fmpq_set_si(o.mu_k, -1, 1);
        }
        wc_problem_init(P);
        wc_error_init(err);
        if (wc_random_problem(P, &o, err) != WC_EINPUT)
            wctest_fail("bad options case %ld: not WC_EINPUT", (long) k);
        if (err->message == NULL || P->n != 0 || P->name != NULL
            || P->shape != WC_SHAPE_NONE)
            wctest_fail("bad options case %ld: no message, or the problem "
                        "was touched", (long) k);
        wc_error_clear(err);
        wc_problem_clear(P);
    }
    wc_random_options_clear(&o);
}

static void
str_is(const wc_random_options * o, const char * expect)
{
    char * s = wc_random_options_str(o);

    if (s == NULL || strcmp(s, expect) != 0)
        wctest_fail("wc_random_options_str: expected '%s', got '%s'", expect,
                    s != NULL ? s : "(null)");
    free(s);
}

static void
check_options_str(void)
{
    wc_random_options o;

    wc_random_options_init(&o);
    str_is(&o, "--fixels=3 --seed=1");
    opt_set(&o, 12, UINT64_MAX, 1, WC_SHAPE_POLYGON);
    str_is(&o, "--fixels=12 --seed=18446744073709551615 --degenerate "
           "--shape=polygon");
    opt_set(&o, 1, 0, 0, WC_SHAPE_DISK);
    o.friction = 1;
    fmpq_set_si(o.mu_s, 1, 5);
    fmpq_set_si(o.mu_s, 2, 10);
    fmpq_set(o.mu_k, o.mu_s);
    str_is(&o, "--fixels=1 --seed=0 --shape=disk --friction=1/5");
    fmpq_zero(o.mu_k);
    str_is(&o, "--fixels=1 --seed=0 --shape=disk --friction=1/5,0");
    wc_random_options_clear(&o);
}

/* ------------------------------------------------------------------ */

static void
check_one(const wc_random_options * o, slong route_modes)
{
    wc_problem_t P;

    wc_problem_init(P);
    generate(P, o);
    if (P->n != o->fixels || P->shape != o->shape)
        wctest_fail_problem(P, NULL, "asked for %ld fixels, shape %s",
                            (long) o->fixels, shape_name(o->shape));
    check_round_trip(P);
    check_on_shape(P);
    check_friction(P, o);
    /* the search for features looks at every triple: small n only */
    if (o->degenerate && o->fixels <= 100)
        check_features(P, o);
    if (route_modes > 0)
        check_routes(P, route_modes);
    wc_problem_clear(P);
}

int
main(void)
{
    wc_random_options o;
    slong iters, i, n;
    int degenerate, shape;

    wctest_init("t-random");
    check_pinned();
    check_options_str();
    check_bad_options();

    wc_random_options_init(&o);
    /* every size, shape and switch, a few seeds each */
    iters = wctest_iters(6);
    for (i = 0; i < iters; i++)
    {
        if (!wctest_iter(i))
            continue;
        for (n = 1; n <= 7; n++)
            for (degenerate = 0; degenerate <= 1; degenerate++)
                for (shape = 0; shape <= 2; shape++)
                {
                    opt_set(&o, n, wctest_rand(), degenerate,
                            (wc_shape_kind) shape);
                    o.friction = wctest_chance(1, 4);
                    if (o.friction)
                    {
                        wctest_rand_fmpq_pos(o.mu_s, 3, 4);
                        if (wctest_chance(1, 3))
                            fmpq_zero(o.mu_s);
                        if (wctest_chance(1, 2))
                            fmpq_set(o.mu_k, o.mu_s);
                        else
                            wctest_rand_fmpq_pos(o.mu_k, 3, 4);
                    }
                    check_reproducible(&o);
                    check_one(&o, n <= 4 ? 3 : 0);
                }
    }
    /* many fixels: the redraws must end, the contract must hold */
    for (degenerate = 0; degenerate <= 1; degenerate++)
        for (shape = 0; shape <= 2; shape++)
        {
            opt_set(&o, degenerate ? 60 : WC_RANDOM_MAX_FIXELS, 5,
                    degenerate, (wc_shape_kind) shape);
            check_one(&o, 0);
            o.fixels = WC_RANDOM_MAX_FIXELS;
            o.friction = 0;
            check_one(&o, 0);
        }
    wc_random_options_clear(&o);
    flint_cleanup_master();
    return 0;
}
