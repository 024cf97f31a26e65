/* t-refplan.c -- tests of the insertion-plan oracle (tests/ref-plan.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The oracle is checked against facts derived by hand: the string lists
   (every string over {m, s, u} with an s; the needed ones have exactly
   one s), G_goal of one fixel (the open half-space a_n < 0) and of the
   paper's two-fixel disk (a wedge that closes at friction 1), single
   wrenches of the three-fixel box whose verdict a force or an
   acceleration computed below settles, and a frictionless two-fixel part
   that the complete model accepts although G_goal does not hold it.  On
   random problems: a nonempty answer of ref_plan_goal_empty comes with a
   member, an empty one has no member among random wrenches, G_goal agrees
   with the union of the paper-route cones, and every member of G_goal is
   accepted by the complete model (see check_random for why it must be).  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/flint.h>
#include <flint/fmpq.h>

#include "wrenchcone.h"
#include "ref-lp.h"
#include "ref-plan.h"
#include "testutil.h"

/* ---- helpers ------------------------------------------------------- */

static void
set_friction(wc_problem_t P, slong num, slong den)
{
    slong i;

    fmpq_set_si(P->mu_s, num, (ulong) den);
    fmpq_set_si(P->mu_k, num, (ulong) den);
    for (i = 0; i < P->n; i++)
    {
        fmpq_set(P->fixels[i].mu_s, P->mu_s);
        fmpq_set(P->fixels[i].mu_k, P->mu_k);
    }
}

/* data/three-fixels.wc (paper Figure 10) with friction num / den: a 4 x 3
   box, centre (2, 3/2), mass 1, inertia 25/12; fixels 1 and 2 at (1, 0)
   and (3, 0) with normal (0, 1), fixel 3 at (0, 2) with normal (1, 0).  */
static void
three_fixels(wc_problem_t P, slong num, slong den)
{
    static const char text[] =
        "name \"three fixels\"\n"
        "friction 1/5\n"
        "shape polygon 0 0 4 0 4 3 0 3\n"
        "com 2 3/2\n"
        "mass 1\n"
        "inertia 25/12\n"
        "fixel 1 0 near\n"
        "fixel 3 0 near\n"
        "fixel 0 2 near\n";
    wc_error_t err;

    wc_error_init(err);
    if (wc_problem_parse(P, text, sizeof(text) - 1, "three-fixels", err)
        != WC_OK)
        wctest_fail("three-fixels: %s", err->message);
    wc_error_clear(err);
    /* the hand calculations below assume these normal directions (the
       parser derives the normals from the polygon, at whatever scale) */
    if (P->n != 3
        || !fmpq_is_zero(P->fixels[0].normal + 0)
        || fmpq_sgn(P->fixels[0].normal + 1) <= 0
        || !fmpq_is_zero(P->fixels[1].normal + 0)
        || fmpq_sgn(P->fixels[1].normal + 1) <= 0
        || fmpq_sgn(P->fixels[2].normal + 0) <= 0
        || !fmpq_is_zero(P->fixels[2].normal + 1))
        wctest_fail("three-fixels: unexpected fixels");
    set_friction(P, num, den);
}

/* The paper's unit disk, M = I: fixel 1 at (0, -1) with normal (0, 1),
   fixel 2 at (1, 0) with normal (-1, 0).  */
static void
paper_disk(wc_problem_t P, slong num, slong den)
{
    wctest_fixel_si(P, 0, -1, 0, 1, WC_NEAR);
    wctest_fixel_si(P, 1, 0, -1, 0, WC_NEAR);
    set_friction(P, num, den);
}

static int
goal(const wc_problem_t P, const fmpq * g)
{
    int r = ref_plan_goal_contains(P, g);

    if (r < 0)
    {
        char * s = wctest_vec_str(g, 3);

        wctest_fail_problem(P, NULL, "ref_plan_goal_contains failed on %s",
                            s);
    }
    return r;
}

static int
complete(const wc_problem_t P, const fmpq * g)
{
    int r = ref_plan_complete_accepts(P, g);

    if (r < 0)
    {
        char * s = wctest_vec_str(g, 3);

        wctest_fail_problem(P, NULL, "ref_plan_complete_accepts failed on "
                            "%s", s);
    }
    return r;
}

static int
in_cone(const wc_problem_t P, const char * mode, const fmpq * g)
{
    int r = ref_wrench_in_cone(P, mode, g);

    if (r < 0)
        wctest_fail_problem(P, mode, "ref_wrench_in_cone failed");
    return r;
}

/* Assert the verdicts on g of G_goal (goal_expected) and of the complete
   model (complete_expected; -1 to skip it), and that a member of G_goal
   is accepted.  */
static void
expect_verdicts(const wc_problem_t P, const fmpq * g, int goal_expected,
                int complete_expected)
{
    int a = goal(P, g), b;

    if (a != goal_expected)
    {
        char * s = wctest_vec_str(g, 3);

        wctest_fail_problem(P, NULL, "%s in G_goal: got %d, expected %d",
                            s, a, goal_expected);
    }
    if (complete_expected < 0 && a == 0)
        return;
    b = complete(P, g);
    if ((complete_expected >= 0 && b != complete_expected) || (a && !b))
    {
        char * s = wctest_vec_str(g, 3);

        wctest_fail_problem(P, NULL, "%s accepted by the complete model: "
                            "got %d, expected %d (in G_goal: %d)", s, b,
                            complete_expected, a);
    }
}

static void
expect_in(const wc_problem_t P, const char * mode, const fmpq * g,
          int expected)
{
    if (in_cone(P, mode, g) != expected)
    {
        char * s = wctest_vec_str(g, 3);

        wctest_fail_problem(P, mode, "%s in W(%s): expected %d", s, mode,
                            expected);
    }
}

/* 1 when g lies in the cone of some needed string computed by the
   paper's route (cddlib conversion), the other way to G_goal's
   complement.  The route wants m on touching fixels and u on near ones.  */
static int
in_paper_union(const wc_problem_t P, const fmpq * g)
{
    char ** x = NULL;
    slong count = 0, k, i;
    wc_problem_t Q;
    wc_cone_t W;
    wc_error_t err;
    int found = 0;

    wc_problem_init(Q);
    wc_cone_init(W, 3);
    wc_error_init(err);
    x = ref_plan_strings(&count, P->n, 1);
    if (x == NULL || wc_problem_set(Q, P) != WC_OK)
        wctest_fail_problem(P, NULL, "in_paper_union: out of memory");
    for (k = 0; k < count && !found; k++)
    {
        for (i = 0; i < Q->n; i++)
        {
            if (x[k][i] == 'm')
                Q->fixels[i].state = WC_TOUCHING;
            else if (x[k][i] == 'u')
                Q->fixels[i].state = WC_NEAR;
        }
        if (wc_wrench_cone_paper(W, NULL, Q, x[k], err) != WC_OK)
            wctest_fail_problem(Q, x[k], "wc_wrench_cone_paper: %s",
                                err->message);
        found = wc_cone_contains(W, g);
    }
    ref_plan_strings_free(x, count);
    wc_error_clear(err);
    wc_cone_clear(W);
    wc_problem_clear(Q);
    return found;
}

/* ---- strings ------------------------------------------------------- */

static void
expect_list(char ** got, slong count, const char * const * want,
            slong want_count, const char * what)
{
    slong i;

    if (got == NULL || count != want_count)
        wctest_fail("%s: %ld strings, expected %ld", what, (long) count,
                    (long) want_count);
    for (i = 0; i < count; i++)
        if (strcmp(got[i], want[i]) != 0)
            wctest_fail("%s: string %ld is %s, expected %s", what, (long) i,
                        got[i], want[i]);
}

static slong
count_s(const char * x)
{
    slong c = 0;

    for (; *x; x++)
        c += (*x == 's');
    return c;
}

/* Sorted, distinct, of length n, over {m, s, u}, with the number of s in
   [smin, smax].  Together with the count this pins the set down.  */
static void
expect_shape(char ** x, slong count, slong n, slong smin, slong smax,
             const char * what)
{
    slong i, j;

    for (i = 0; i < count; i++)
    {
        if ((slong) strlen(x[i]) != n)
            wctest_fail("%s: %s has the wrong length", what, x[i]);
        for (j = 0; j < n; j++)
            if (x[i][j] != 'm' && x[i][j] != 's' && x[i][j] != 'u')
                wctest_fail("%s: %s has a letter outside msu", what, x[i]);
        if (count_s(x[i]) < smin || count_s(x[i]) > smax)
            wctest_fail("%s: %s has a wrong number of s", what, x[i]);
        if (i > 0 && strcmp(x[i - 1], x[i]) >= 0)
            wctest_fail("%s: %s, %s not strictly ascending", what, x[i - 1],
                        x[i]);
    }
}

/* The first family is every string over {m, s, u} with at least one s
   (S = the non-u positions, L = the s positions); the second family is
   the first's S = all, so it adds nothing: 3^n - 2^n strings.  A string
   is covered by another exactly when it has two or more s (turn one of
   them to u), so the needed ones are those with exactly one s:
   n 2^(n-1) of them.  */
static void
check_strings(void)
{
    static const char * const all1[] = {"s"};
    static const char * const all2[] = {"ms", "sm", "ss", "su", "us"};
    static const char * const needed2[] = {"ms", "sm", "su", "us"};
    static const char * const all3[] =
        {"mms", "msm", "mss", "msu", "mus", "smm", "sms", "smu", "ssm",
         "sss", "ssu", "sum", "sus", "suu", "ums", "usm", "uss", "usu",
         "uus"};
    static const char * const needed3[] =
        {"mms", "msm", "msu", "mus", "smm", "smu", "sum", "suu", "ums",
         "usm", "usu", "uus"};
    char ** x;
    slong count, n, pow2 = 1, pow3 = 1;

    {
        /* n, needed only, the list */
        static const struct
        {
            slong n;
            int needed;
            const char * const * want;
            slong count;
        }
        lists[6] = { { 1, 0, all1, 1 }, { 1, 1, all1, 1 },
                     { 2, 0, all2, 5 }, { 2, 1, needed2, 4 },
                     { 3, 0, all3, 19 }, { 3, 1, needed3, 12 } };
        char what[64];
        slong i;

        for (i = 0; i < 6; i++)
        {
            x = ref_plan_strings(&count, lists[i].n, lists[i].needed);
            snprintf(what, sizeof what, "%s strings, n = %ld",
                     lists[i].needed ? "needed" : "all", (long) lists[i].n);
            expect_list(x, count, lists[i].want, lists[i].count, what);
            ref_plan_strings_free(x, count);
        }
    }

    for (n = 1; n <= 6; n++)
    {
        pow2 *= 2;
        pow3 *= 3;
        x = ref_plan_strings(&count, n, 0);
        if (x == NULL || count != pow3 - pow2)
            wctest_fail("n = %ld: %ld strings, expected %ld", (long) n,
                        (long) count, (long) (pow3 - pow2));
        expect_shape(x, count, n, 1, n, "all strings");
        ref_plan_strings_free(x, count);
        x = ref_plan_strings(&count, n, 1);
        if (x == NULL || count != n * (pow2 / 2))
            wctest_fail("n = %ld: %ld needed strings, expected %ld",
                        (long) n, (long) count, (long) (n * (pow2 / 2)));
        expect_shape(x, count, n, 1, 1, "needed strings");
        ref_plan_strings_free(x, count);
    }
    /* the counts asked for by name */
    x = ref_plan_strings(&count, 4, 1);
    if (count != 32)
        wctest_fail("n = 4: %ld needed strings, expected 32", (long) count);
    ref_plan_strings_free(x, count);
    x = ref_plan_strings(&count, 5, 1);
    if (count != 80)
        wctest_fail("n = 5: %ld needed strings, expected 80", (long) count);
    ref_plan_strings_free(x, count);

    x = ref_plan_strings(&count, 0, 1);
    if (x != NULL || count != 0)
        wctest_fail("n = 0 did not fail");
    x = ref_plan_strings(&count, 9, 0);
    if (x != NULL || count != 0)
        wctest_fail("n = 9 did not fail");
}

/* ---- one fixel ------------------------------------------------------ */

/* an = n . g_xy / m + (r x n) g_t / I: fixel f's free normal
   acceleration under g.  */
static void
free_an(fmpq_t an, const wc_problem_t P, const wc_fixel_struct * f,
        const fmpq * g)
{
    fmpq w[3];
    fmpq_t t;
    int j;

    for (j = 0; j < 3; j++)
        fmpq_init(w + j);
    fmpq_init(t);
    wctest_wrench_of(w, P, f, f->normal);
    fmpq_mul(an, w + 0, g + 0);
    fmpq_addmul(an, w + 1, g + 1);
    fmpq_div(an, an, P->mass);
    fmpq_mul(t, w + 2, g + 2);
    fmpq_div(t, t, P->inertia);
    fmpq_add(an, an, t);
    for (j = 0; j < 3; j++)
        fmpq_clear(w + j);
    fmpq_clear(t);
}

/* With one fixel the only needed string is s, W(s) = { a_n >= 0 } for the
   free acceleration a_n = n . g_xy / m + (r x n) g_t / I, so G_goal is the
   open half-space a_n < 0.  The complete model has the states {} and {1}:
   the goal admits s (a_n >= 0: an edge back to {}) or m; {} admits s (a
   self-loop) or a (a_n < 0: the edge to the goal), so it accepts exactly
   G_goal too.  */
static void
check_one_fixel(void)
{
    slong iter, iters = wctest_iters(20);

    for (iter = 0; iter < iters; iter++)
    {
        wc_problem_t P;
        fmpq g[3], w[3];
        fmpq_t an;
        const wc_fixel_struct * f;
        slong j, k;
        int expected;

        if (!wctest_iter(iter))
            continue;
        wc_problem_init(P);
        for (j = 0; j < 3; j++)
        {
            fmpq_init(g + j);
            fmpq_init(w + j);
        }
        fmpq_init(an);
        wctest_random_problem(P, 1, 1);
        f = P->fixels;

        for (k = 0; k < 4; k++)
        {
            wctest_random_wrench(g);
            free_an(an, P, f, g);
            expected = fmpq_sgn(an) < 0;
            expect_verdicts(P, g, expected, expected);
        }

        /* a half-space is never empty, and its witness has a_n < 0 */
        if (ref_plan_goal_empty(P, w) != 0)
            wctest_fail_problem(P, NULL, "one fixel: G_goal reported empty");
        free_an(an, P, f, w);
        if (fmpq_sgn(an) >= 0)
            wctest_fail_problem(P, NULL, "one fixel: witness with a_n >= 0");

        for (j = 0; j < 3; j++)
        {
            fmpq_clear(g + j);
            fmpq_clear(w + j);
        }
        fmpq_clear(an);
        wc_problem_clear(P);
    }
}

/* ---- the paper's disk ----------------------------------------------- */

/* r x n = 0 at both fixels, so a_1n = nudot_y and a_2n = -nudot_x; the
   torque only feeds the (free) tangential accelerations.  Needed strings:
   W(su) = { g_y >= 0 }, W(us) = { g_x <= 0 }; W(ms): c_1n = -g_y >= 0 and
   a_2n = c_1t - g_x >= 0 with |c_1t| <= mu c_1n, so g_x <= mu |g_y|;
   W(sm): c_2n = g_x >= 0 and a_1n = g_y - c_2t >= 0, so |g_y| <= mu g_x.
   Hence G_goal = { g_x > 0, g_y < 0, mu g_x < |g_y| < g_x / mu }: nonempty
   iff mu < 1.  The complete model's goal must admit none of ss, sm, ms
   (W(ss) = { g_x <= 0 <= g_y }), which leaves exactly that wedge; inside
   it {1} -> goal by ma, {2} -> goal by am, {} -> all three by aa.  So the
   complete model accepts exactly G_goal here, for every mu.  */
static int
disk_formula(const fmpq * g, const fmpq_t mu)
{
    fmpq_t a, b;
    int r;

    if (fmpq_sgn(g + 0) <= 0 || fmpq_sgn(g + 1) >= 0)
        return 0;
    fmpq_init(a);
    fmpq_init(b);
    fmpq_neg(a, g + 1);                 /* |g_y| */
    fmpq_mul(b, mu, g + 0);
    r = fmpq_cmp(b, a) < 0;
    fmpq_mul(b, mu, a);
    r = r && fmpq_cmp(b, g + 0) < 0;
    fmpq_clear(a);
    fmpq_clear(b);
    return r;
}

static void
check_disk(void)
{
    static const slong mus[][2] = {{1, 5}, {0, 1}, {99, 100}, {1, 1},
                                   {1000, 1}};
    static const slong fixed[][3] = {{1, -1, 0}, {1, -1, 7}, {1, -4, -2},
                                     {5, -1, 0}, {1, -5, 0}, {1, -6, 0},
                                     {0, -1, 0}, {1, 0, 0}, {0, 0, 0},
                                     {-1, 1, 0}, {1, 1, 3}};
    slong m, k, iter, iters = wctest_iters(6);
    fmpq g[3];
    int j, e;

    for (j = 0; j < 3; j++)
        fmpq_init(g + j);
    for (m = 0; m < 5; m++)
    {
        wc_problem_t P;

        wc_problem_init(P);
        paper_disk(P, mus[m][0], mus[m][1]);

        for (k = 0; k < 11; k++)
        {
            wctest_vec3_si(g, fixed[k][0], fixed[k][1], fixed[k][2]);
            e = disk_formula(g, P->mu_s);
            expect_verdicts(P, g, e, e);
        }
        for (iter = 0; iter < iters; iter++)
        {
            if (!wctest_iter(iter))
                continue;
            wctest_random_wrench(g);
            if (wctest_chance(1, 2))
            {
                /* aim at the wedge and its edges */
                fmpq_abs(g + 0, g + 0);
                fmpq_abs(g + 1, g + 1);
                fmpq_neg(g + 1, g + 1);
            }
            e = disk_formula(g, P->mu_s);
            expect_verdicts(P, g, e, e);
        }

        /* emptiness exactly at mu >= 1 */
        e = ref_plan_goal_empty(P, g);
        if (e != (fmpq_cmp_si(P->mu_s, 1) >= 0))
            wctest_fail_problem(P, NULL, "disk: ref_plan_goal_empty gave %d",
                                e);
        if (e == 0 && !disk_formula(g, P->mu_s))
        {
            char * s = wctest_vec_str(g, 3);

            wctest_fail_problem(P, NULL, "disk: witness %s outside the "
                                "wedge", s);
        }
        wc_problem_clear(P);
    }
    for (j = 0; j < 3; j++)
        fmpq_clear(g + j);
}

/* ---- the three-fixel box -------------------------------------------- */

/* With a = (a_1n, a_2n, a_3n) and nudot = (ax, ay, alpha) the box gives
   a_1n = ay - alpha, a_2n = ay + alpha, a_3n = ax - alpha / 2 (r x n is
   -1, 1, -1/2); with no force nudot = (g_x, g_y, 12 g_t / 25).  */
static void
check_three_fixels(void)
{
    wc_problem_t P;
    fmpq g[3];
    int j;

    wc_problem_init(P);
    for (j = 0; j < 3; j++)
        fmpq_init(g + j);
    three_fixels(P, 1, 5);

    /* W(suu) holds 0 (a = 0, c = 0); the goal admits sss, so the complete
       model leaves the goal too.  */
    wctest_vec3_si(g, 0, 0, 0);
    expect_in(P, "suu", g, 1);
    expect_verdicts(P, g, 0, 0);

    /* pulling straight up: free a = (1, 1, 0), so suu; at the goal ssm
       (fixel 3 held with no force) leaves it */
    wctest_vec3_si(g, 0, 1, 0);
    expect_in(P, "suu", g, 1);
    expect_in(P, "ssm", g, 1);
    expect_verdicts(P, g, 0, 0);

    /* pulling off fixel 3: free a = (0, 0, 1), so uus and sss */
    wctest_vec3_si(g, 1, 0, 0);
    expect_in(P, "uus", g, 1);
    expect_in(P, "sss", g, 1);
    expect_verdicts(P, g, 0, 0);

    /* pressing straight down never seats against fixel 3: free a_3n = 0
       (uus), and at the goal c_1n = c_2n = 1/2 give nudot = 0 (mms) */
    wctest_vec3_si(g, 0, -1, 0);
    expect_in(P, "uus", g, 1);
    expect_in(P, "mms", g, 1);
    expect_verdicts(P, g, 0, 0);

    /* pressing down and left, no torque: every fixel approaches freely,
       yet smm holds g: c_2 = (117/125, 9/50), c_3 = (551/500, 11/50)
       (normal, tangential; both inside the 1/5 cone) give nudot =
       (-39/500, 39/250, -39/250), so a = (78/250, 0, 0).  The box tips
       off fixel 1 on friction alone.  */
    wctest_vec3_si(g, -1, -1, 0);
    expect_in(P, "uuu", g, 1);
    expect_in(P, "suu", g, 0);
    expect_in(P, "usu", g, 0);
    expect_in(P, "uus", g, 0);
    expect_in(P, "smm", g, 1);
    expect_verdicts(P, g, 0, 0);

    /* Members, from the LPs; confirmed by the paper-route cones below.  */
    wctest_vec3_si(g, -1, -3, 0);
    expect_verdicts(P, g, 1, 1);
    if (in_paper_union(P, g))
        wctest_fail_problem(P, NULL, "(-1, -3, 0): the cones disagree");
    wctest_vec3_si(g, -3, -4, 2);
    expect_verdicts(P, g, 1, 1);
    if (in_paper_union(P, g))
        wctest_fail_problem(P, NULL, "(-3, -4, 2): the cones disagree");

    /* G_goal is not empty; its witness is a member and is accepted */
    if (ref_plan_goal_empty(P, g) != 0)
        wctest_fail_problem(P, NULL, "three fixels: G_goal reported empty");
    expect_verdicts(P, g, 1, 1);
    if (in_paper_union(P, g))
        wctest_fail_problem(P, NULL, "three fixels: the witness is in a "
                            "paper-route cone");

    /* Without friction the complete model accepts more.  g = (-3, -1, 2):
       every fixel approaches freely (a = (-49/25, -1/25, -87/25)), but
       msu holds g: c_1n = 49/37 gives ay = 12/37, alpha = 12/37, so
       a_1n = 0 and a_2n = 24/37 >= 0 (the box rocks on fixel 1).  So g is
       not in G_goal.  The complete model lets the box rock: from {1, 2}
       the only outcome is msa (a_3n = -3 - 6/37 < 0), to {1} or {1, 3};
       {1} -> {1, 3} by msa, {1, 3} -> goal by mam, and the goal admits
       only mmm.  */
    set_friction(P, 0, 1);
    wctest_vec3_si(g, -3, -1, 2);
    expect_in(P, "aaa", g, 1);
    expect_in(P, "msu", g, 1);
    expect_in(P, "msa", g, 1);
    expect_in(P, "mam", g, 1);
    expect_in(P, "mmm", g, 1);
    expect_in(P, "mms", g, 0);
    expect_in(P, "msm", g, 0);
    expect_in(P, "smm", g, 0);
    expect_verdicts(P, g, 0, 1);

    for (j = 0; j < 3; j++)
        fmpq_clear(g + j);
    wc_problem_clear(P);
}

/* ---- the complete model beats G_goal ---------------------------------- */

/* A frictionless part, M = I, centre at the origin: fixel 1 at (1, -1)
   with normal (0, 1), fixel 2 at (-1, 1) with normal (1, 0), so
   a_1n = ay + alpha and a_2n = ax - alpha, and a force c at fixel 2 adds
   (c, 0, -c).  g = (-4, 1, 0): free a = (1, -4), so g is in W(su) and not
   in G_goal (contact 1 may be lost).  The complete model: {} -> {2} (sa);
   {1} -> {} and {1} -> {2} (sa; m at fixel 1 would need c_1n = -1/2);
   {2} -> goal (am: c_2n = 2 gives a_1n = -1); the goal admits mm only
   (c = (2/3, 7/3)): ss and ms fail as free a_2n < 0, sm as a_1n = -1.
   Acyclic, so accepted: the part reaches fixel 2 first, then turns onto
   fixel 1.  */
static void
check_complete_beats_goal(void)
{
    wc_problem_t P;
    fmpq g[3];
    int j;

    wc_problem_init(P);
    for (j = 0; j < 3; j++)
        fmpq_init(g + j);
    wctest_fixel_si(P, 1, -1, 0, 1, WC_NEAR);
    wctest_fixel_si(P, -1, 1, 1, 0, WC_NEAR);
    set_friction(P, 0, 1);

    wctest_vec3_si(g, -4, 1, 0);
    expect_in(P, "su", g, 1);
    expect_in(P, "sa", g, 1);
    expect_in(P, "ma", g, 0);
    expect_in(P, "am", g, 1);
    expect_in(P, "sm", g, 0);
    expect_in(P, "ms", g, 0);
    expect_in(P, "ss", g, 0);
    expect_in(P, "mm", g, 1);
    expect_verdicts(P, g, 0, 1);

    /* g = (-4, 1, 2): now c_2n = 3 at fixel 2 leaves a_1n = 0, so the
       goal admits sm (fixel 1 may be lost) and the complete model
       rejects as well */
    wctest_vec3_si(g, -4, 1, 2);
    expect_in(P, "sm", g, 1);
    expect_verdicts(P, g, 0, 0);

    for (j = 0; j < 3; j++)
        fmpq_clear(g + j);
    wc_problem_clear(P);
}

/* ---- random problems ------------------------------------------------ */

/* Every member of G_goal is accepted by the complete model.  At a state
   S, an outcome losing contacts L != {} lies in W(s on L, m on S \ L,
   u off S), and m on S, s off S (S short of all) in a needed string's
   cone too, so a member admits only outcomes with L = {} and, off the
   goal, A != {}: every edge adds contacts (no cycle) and the goal keeps
   only its self-loop.  Some outcome is always admitted: the frictionless
   contact problem on S (c_t = 0) is a linear complementarity problem
   with the matrix J_S^T M^-1 J_S, positive semidefinite, and always
   feasible (a Farkas certificate y >= 0 with y^T A <= 0 forces
   J_S y = 0 and so y^T q = 0), hence solvable; its solution is an
   outcome.  */
static void
check_random(void)
{
    slong iter, iters = wctest_iters(24);

    for (iter = 0; iter < iters; iter++)
    {
        wc_problem_t P;
        fmpq g[3], w[3];
        slong k;
        int j, empty, a;

        if (!wctest_iter(iter))
            continue;
        wc_problem_init(P);
        for (j = 0; j < 3; j++)
        {
            fmpq_init(g + j);
            fmpq_init(w + j);
        }
        wctest_random_problem(P, 1, 3);

        empty = ref_plan_goal_empty(P, w);
        if (empty < 0)
            wctest_fail_problem(P, NULL, "ref_plan_goal_empty failed");
        if (empty == 0)
        {
            expect_verdicts(P, w, 1, 1);
            if (in_paper_union(P, w))
                wctest_fail_problem(P, NULL, "the witness is in a "
                                    "paper-route cone");
        }

        for (k = 0; k < 3; k++)
        {
            wctest_random_wrench(g);
            a = goal(P, g);
            if (a && empty)
            {
                char * s = wctest_vec_str(g, 3);

                wctest_fail_problem(P, NULL, "%s in G_goal, reported "
                                    "empty", s);
            }
            if (a == in_paper_union(P, g))
            {
                char * s = wctest_vec_str(g, 3);

                wctest_fail_problem(P, NULL, "%s: G_goal by LPs %d, by the "
                                    "paper-route cones %d", s, a, !a);
            }
            if (a && !complete(P, g))
            {
                char * s = wctest_vec_str(g, 3);

                wctest_fail_problem(P, NULL, "%s in G_goal but rejected by "
                                    "the complete model", s);
            }
        }

        for (j = 0; j < 3; j++)
        {
            fmpq_clear(g + j);
            fmpq_clear(w + j);
        }
        wc_problem_clear(P);
    }
}

int
main(void)
{
    wctest_init("t-refplan");
    check_strings();
    check_one_fixel();
    check_disk();
    check_three_fixels();
    check_complete_beats_goal();
    check_random();
    flint_cleanup();
    return 0;
}
