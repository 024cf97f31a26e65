/* t-plan.c -- insertion plans (lib/plan.c) against the independent oracle
   tests/ref-plan.c.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The library builds G_goal from the cells of one plane arrangement; the
   oracle, on the plan model (ref_plan_model), decides membership with one
   exact LP per needed string (strings it generates itself from wrenchcone(1), Insertion plans),
   emptiness from its own naive cell enumeration over paper-route cones,
   and the complete plan from one LP per outcome.  They must agree on random wrenches and above all on the
   wrenches where the sets change: the rays and face points of every piece
   and of every needed cone, their negatives and small perturbations.  */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpq_mat.h>

#include "wrenchcone.h"
#include "analysis/plan.h"
#include "ref-lp.h"
#include "ref-stab.h"
#include "ref-plan.h"
#include "testutil.h"

static void
fail_g(const wc_problem_t P, const char * what, const fmpq * g,
       const char * msg)
{
    char * s = g != NULL ? wctest_vec_str(g, 3) : NULL;

    wctest_fail_problem(P, NULL, "%s: %s%s%s", what, msg,
                        s != NULL ? " at g = " : "", s != NULL ? s : "");
}

/* ---- strings ----------------------------------------------------------- */

static int
cmp_str(const void * a, const void * b)
{
    return strcmp(*(char * const *) a, *(char * const *) b);
}

/* The strings of state S of T, sorted, joined by spaces.  */
static void
state_strings(char * out, const wc_plan_strings_t T, ulong S)
{
    const char * v[64];
    slong i, k = 0;

    for (i = T->state_first[S]; i < T->state_first[S + 1]; i++)
        v[k++] = T->strings[T->state_str[i]];
    qsort(v, k, sizeof(char *), cmp_str);
    out[0] = '\0';
    for (i = 0; i < k; i++)
    {
        if (i)
            strcat(out, " ");
        strcat(out, v[i]);
    }
}

/* The index of string b among T's (ASCII-sorted), or -1.  */
static slong
string_index(const wc_plan_strings_t T, const char * b)
{
    char * const * hit = bsearch(&b, T->strings, T->nstrings,
                                 sizeof(char *), cmp_str);

    return hit == NULL ? -1 : hit - T->strings;
}

/* State S's string k of T is that of lost contacts L.  */
static void
check_state_string(const wc_plan_strings_t T, slong n, ulong S, ulong L,
                   slong k)
{
    char b[FLINT_BITS + 1];
    slong j;

    for (j = 0; j < n; j++)
        b[j] = (L >> j) & 1 ? 's' : (S >> j) & 1 ? 'm' : L != 0 ? 'u' : 's';
    b[n] = '\0';
    if (k >= T->state_first[S + 1]
        || strcmp(T->strings[T->state_str[k]], b) != 0)
        wctest_fail("n = %ld, state %lu: string %ld is not %s", (long) n,
                    S, (long) k, b);
}

/* state_str and contained_in read from their definitions: state S's
   strings, lost contacts L the nonempty subsets of S in increasing order
   (as bit masks), then no progress (L empty) unless S is full; a
   string's witness, the first string made by turning a nonempty subset R
   of its s letters into u, R in increasing order.  */
static void
check_string_tables(const wc_plan_strings_t T, slong n)
{
    ulong full = (UWORD(1) << n) - 1, S, L, R;
    slong i, k = 0, j;
    char b[FLINT_BITS + 1];

    b[n] = '\0';
    for (S = 0; S <= full; S++)
    {
        if (T->state_first[S] != k)
            wctest_fail("n = %ld, state %lu: strings from %ld, expected %ld",
                        (long) n, S, (long) T->state_first[S], (long) k);
        for (L = 1; L <= S; L++)
            if ((L & S) == L)
                check_state_string(T, n, S, L, k++);
        if (S != full)
            check_state_string(T, n, S, 0, k++);
    }
    if (T->state_first[full + 1] != k)
        wctest_fail("n = %ld: %ld state strings, expected %ld", (long) n,
                    (long) T->state_first[full + 1], (long) k);
    for (i = 0; i < T->nstrings; i++)
    {
        const char * s = T->strings[i];
        ulong smask = 0;
        slong want = -1;

        for (j = 0; j < n; j++)
            smask |= (ulong) (s[j] == 's') << j;
        for (R = 1; R <= smask && want < 0; R++)
        {
            if ((R & smask) != R)
                continue;
            for (j = 0; j < n; j++)
                b[j] = (R >> j) & 1 ? 'u' : s[j];
            want = string_index(T, b);
        }
        if (T->contained_in[i] != want)
            wctest_fail("n = %ld: %s is contained in string %ld, expected "
                        "%ld", (long) n, s, (long) T->contained_in[i],
                        (long) want);
    }
}

static void
test_strings(void)
{
    /* Table 5 with its slip mended (the second mss of state 111 is ssm);
       states written with fixel 1 first.  */
    static const char * const table5[8][2] = {
        { "000", "sss" }, { "100", "mss suu" }, { "010", "sms usu" },
        { "110", "mms msu smu ssu" }, { "001", "ssm uus" },
        { "101", "msm mus sum sus" }, { "011", "smm ums usm uss" },
        { "111", "mms msm mss smm sms ssm sss" }
    };
    static const char * const twelve =
        "mms msm msu mus smm smu sum suu ums usm usu uus";
    wc_plan_strings_t T;
    wc_error_t err;
    slong n, i, count, pow3 = 1;
    char buf[256], st[16];

    wc_error_init(err);
    wc_plan_strings_init(T);
    for (n = 1; n <= WC_PLAN_MAX_FIXELS; n++)
    {
        pow3 *= 3;
        if (wc_plan_strings(T, n, err) != WC_OK)
            wctest_fail("wc_plan_strings(%ld) failed", (long) n);
        if (T->nstrings != pow3 - (1L << n)
            || T->nneeded != n * (1L << (n - 1)))
            wctest_fail("n = %ld: %ld strings, %ld needed; expected 3^n - 2^n"
                        " = %ld and n 2^(n-1) = %ld", (long) n,
                        (long) T->nstrings, (long) T->nneeded,
                        (long) (pow3 - (1L << n)), (long) (n << (n - 1)));
        check_string_tables(T, n);
        /* each needed string has exactly one s */
        for (i = 0; i < T->nneeded; i++)
        {
            const char * s = T->strings[T->needed[i]];
            slong k, c = 0;

            for (k = 0; k < n; k++)
                c += s[k] == 's';
            if (c != 1)
                wctest_fail("n = %ld: needed string %s", (long) n, s);
        }
        /* a redundant string's witness really contains it */
        for (i = 0; i < T->nstrings; i++)
        {
            slong j = T->contained_in[i], k;

            if (j < 0)
                continue;
            for (k = 0; k < n; k++)
                if (T->strings[j][k] != T->strings[i][k]
                    && !(T->strings[i][k] == 's' && T->strings[j][k] == 'u'))
                    wctest_fail("n = %ld: %s is not in %s", (long) n,
                                T->strings[i], T->strings[j]);
        }
        if (n <= 6)
        {
            int needed;

            for (needed = 0; needed <= 1; needed++)
            {
                char ** ref = ref_plan_strings(&count, n, needed);
                slong mine = needed ? T->nneeded : T->nstrings;

                if (ref == NULL || count != mine)
                    wctest_fail("n = %ld: %ld %s strings, the reference %ld",
                                (long) n, (long) mine, needed ? "needed" :
                                "generated", (long) count);
                for (i = 0; i < count; i++)
                    if (strcmp(ref[i], T->strings[needed ? T->needed[i]
                                                  : i]) != 0)
                        wctest_fail("n = %ld: string %ld is %s, the "
                                    "reference says %s", (long) n, (long) i,
                                    T->strings[needed ? T->needed[i] : i],
                                    ref[i]);
                ref_plan_strings_free(ref, count);
            }
        }
        if (n == 3)
        {
            ulong S;

            buf[0] = '\0';
            for (i = 0; i < T->nneeded; i++)
            {
                if (i)
                    strcat(buf, " ");
                strcat(buf, T->strings[T->needed[i]]);
            }
            if (strcmp(buf, twelve) != 0)
                wctest_fail("n = 3: needed %s, not the paper's twelve", buf);
            for (S = 0; S < 8; S++)
            {
                wc_plan_state_string(st, S, 3);
                for (i = 0; i < 8; i++)
                    if (strcmp(table5[i][0], st) == 0)
                        break;
                state_strings(buf, T, S);
                if (i == 8 || strcmp(buf, table5[i][1]) != 0)
                    wctest_fail("n = 3, state %s: %s, not Table 5's %s", st,
                                buf, i < 8 ? table5[i][1] : "?");
            }
        }
        if (n == 2)
        {
            buf[0] = '\0';
            for (i = 0; i < T->nneeded; i++)
            {
                strcat(buf, T->strings[T->needed[i]]);
                strcat(buf, " ");
            }
            if (strcmp(buf, "ms sm su us ") != 0)
                wctest_fail("n = 2: needed %s, not eq. 21's su us sm ms", buf);
        }
    }
    if (wc_plan_strings(T, 0, err) != WC_EINPUT
        || wc_plan_strings(T, WC_PLAN_MAX_FIXELS + 1, err) != WC_EINPUT)
        wctest_fail("wc_plan_strings accepts n out of range");
    wc_plan_strings_clear(T);
    wc_error_clear(err);
}

/* ---- wrenches to test -------------------------------------------------- */

typedef struct
{
    slong len, alloc;
    fmpq * g;       /* 3 len entries */
}
wlist;

static fmpq *
wl_add(wlist * L)
{
    slong k;

    if (L->len == L->alloc)
    {
        slong a = 2 * L->alloc + 16, i;

        L->g = flint_realloc(L->g, sizeof(fmpq) * 3 * a);
        for (i = 3 * L->alloc; i < 3 * a; i++)
            fmpq_init(L->g + i);
        L->alloc = a;
    }
    for (k = 0; k < 3; k++)
        fmpq_zero(L->g + 3 * L->len + k);
    return L->g + 3 * L->len++;
}

static void
wl_clear(wlist * L)
{
    slong i;

    for (i = 0; i < 3 * L->alloc; i++)
        fmpq_clear(L->g + i);
    flint_free(L->g);
}

/* The rays of C and the point of every face (sum of its rays, or a line
   when it has none), each also negated and nudged by a small random
   step.  */
static void
wl_add_cone(wlist * L, const wc_cone_t C)
{
    slong f, r, k;
    fmpq_t t;

    if (C->empty)
        return;
    fmpq_init(t);
    for (f = 0; f < C->nfaces; f++)
    {
        const wc_face_struct * F = C->faces + f;
        fmpq * g = wl_add(L), * h;

        for (r = 0; r < F->nrays; r++)
            for (k = 0; k < 3; k++)
                fmpq_add_fmpz(g + k, g + k,
                              fmpz_mat_entry(C->rays, F->rays[r], k));
        if (F->nrays == 0 && fmpz_mat_nrows(C->lines) > 0)
            for (k = 0; k < 3; k++)
                fmpq_set_fmpz(g + k, fmpz_mat_entry(C->lines, 0, k));
        h = wl_add(L);
        g = L->g + 3 * (L->len - 2);
        for (k = 0; k < 3; k++)
            fmpq_neg(h + k, g + k);
        h = wl_add(L);
        g = L->g + 3 * (L->len - 3);
        for (k = 0; k < 3; k++)
        {
            wctest_rand_fmpq(t, 1, 1000);
            fmpq_add(h + k, g + k, t);
        }
    }
    fmpq_clear(t);
}

/* ---- one problem ------------------------------------------------------- */

/* Every fixel's normals span R^3 (the contact normals' wrench columns have
   rank 3) and mu_k <= mu_s: then G_goal lies in both strongly stable sets
   (a wrench of G_goal has, in every solution at the goal state, a force at
   every fixel, hence zero normal accelerations, hence no motion).  */
static int
eq25_guaranteed(const wc_problem_t P)
{
    fmpq_mat_t N;
    slong i, r;

    for (i = 0; i < P->n; i++)
        if (fmpq_cmp(P->fixels[i].mu_k, P->fixels[i].mu_s) > 0)
            return 0;
    fmpq_mat_init(N, P->n, 3);
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;
        fmpq_t a, b;

        fmpq_init(a);
        fmpq_init(b);
        fmpq_set(fmpq_mat_entry(N, i, 0), f->normal + 0);
        fmpq_set(fmpq_mat_entry(N, i, 1), f->normal + 1);
        /* (p - o) x n */
        fmpq_sub(a, f->point + 0, P->com + 0);
        fmpq_mul(a, a, f->normal + 1);
        fmpq_sub(b, f->point + 1, P->com + 1);
        fmpq_mul(b, b, f->normal + 0);
        fmpq_sub(fmpq_mat_entry(N, i, 2), a, b);
        fmpq_clear(a);
        fmpq_clear(b);
    }
    {
        fmpq_mat_t E;

        fmpq_mat_init(E, P->n, 3);
        r = fmpq_mat_rref(E, N);
        fmpq_mat_clear(E);
    }
    fmpq_mat_clear(N);
    return r == 3;
}

/* Strongly stable at the goal state (every fixel touching), by the
   oracle: exact semantics, and the paper's.  */
static void
ref_strong(int * exact, int * paper, const wc_problem_t P, const fmpq * g,
           const char * what)
{
    wc_problem_t Q;
    slong i;
    int w, m, u;

    wc_problem_init(Q);
    wc_problem_set(Q, P);
    for (i = 0; i < Q->n; i++)
        Q->fixels[i].state = WC_TOUCHING;
    w = ref_weakly_stable(Q, g);
    m = ref_has_motion(Q, g);
    u = ref_in_paper_union(Q, g);
    if (w < 0 || m < 0 || u < 0)
        fail_g(P, what, g, "the stability oracle failed");
    *exact = w && !m;
    *paper = !u;
    wc_problem_clear(Q);
}

static void
check_problem(const wc_problem_t P, const char * what, int complete,
              slong nrand)
{
    wc_plan_t R;
    wc_plan_wrench_t W;
    wc_error_t err;
    wlist L = { 0, 0, NULL };
    wc_problem_t O;         /* the oracle's: the plan model of P */
    slong i, j, k, nn;
    int guaranteed = eq25_guaranteed(P);
    /* The complete plan's oracle costs 3^n LPs a wrench: every sixth
       wrench by default, every second one in widened runs.  */
    slong every = wctest_iters(1) >= 3 ? 2 : 6;
    /* The face points of the cones are many: every seventh one by default
       (prime to the strides below, so that each check still sees its
       share; the same points, with the same checks, as in a widened
       run), all of them in widened runs.  The random wrenches and the
       zero wrench always.  */
    slong thin = wctest_iters(1) >= 3 ? 1 : 7;

    complete = complete && P->n <= 3;
    wc_problem_init(O);
    if (ref_plan_model(O, P) != 0)
        fail_g(P, what, NULL, "out of memory");
    wc_plan_init(R);
    wc_plan_wrench_init(W);
    wc_error_init(err);
    if (wc_plan(R, P, complete, err) != WC_OK)
        fail_g(P, what, NULL, err->message);
    nn = R->T->nneeded;

    for (i = 0; i < nrand; i++)
        wctest_random_wrench(wl_add(&L));
    wl_add(&L);     /* the zero wrench */
    for (i = 0; i < R->goal->npieces; i++)
        wl_add_cone(&L, R->goal->pieces + i);
    for (i = 0; i < nn; i++)
        wl_add_cone(&L, R->cones + i);
    for (i = 0; complete && i < R->accepted->npieces; i++)
        wl_add_cone(&L, R->accepted->pieces + i);
    if (R->has_extra)
        for (k = 0; k < 3; k++)
            fmpq_set(wl_add(&L) + k, R->extra + k);

    for (i = 0; i < L.len; i++)
    {
        const fmpq * g = L.g + 3 * i;
        int lib, ref;
        slong hits = 0;

        if (i > nrand && i % thin != 0)
            continue;
        lib = wc_set_contains(R->goal, g);
        ref = ref_plan_goal_contains(O, g);

        if (ref < 0)
            fail_g(P, what, g, "the oracle failed");
        if (lib != ref)
            fail_g(P, what, g, lib ? "in the library's G_goal, not the "
                   "oracle's" : "in the oracle's G_goal, not the library's");
        for (j = 0; j < R->goal->npieces; j++)
            hits += wc_cone_contains(R->goal->pieces + j, g);
        if (hits > 1)
            fail_g(P, what, g, "in two pieces of G_goal");
        /* the needed cones, one at a time, against the oracle's LP */
        for (j = 0; j < nn && i % 4 == 0; j++)
        {
            const char * x = R->T->strings[R->T->needed[j]];

            if (wc_cone_contains(R->cones + j, g)
                != ref_wrench_in_cone(O, x, g))
                fail_g(P, what, g, "a needed cone disagrees with the LP");
        }
        if (i % 5 == 0 || (complete && i % every == 0))
        {
            int acc = -1;

            if (wc_plan_wrench(W, P, g, complete, err) != WC_OK)
                fail_g(P, what, g, err->message);
            if (W->in_goal != ref)
                fail_g(P, what, g, "wc_plan_wrench disagrees on G_goal");
            if (complete)
            {
                acc = ref_plan_complete_accepts(O, g);
                if (acc < 0)
                    fail_g(P, what, g, "the complete oracle failed");
                if ((W->verdict == WC_PLAN_ACCEPTED) != acc)
                    fail_g(P, what, g, acc ? "the complete plan rejects a "
                           "wrench the oracle accepts" : "the complete plan "
                           "accepts a wrench the oracle rejects");
                if (wc_set_contains(R->accepted, g) != acc)
                    fail_g(P, what, g, "the accepted set disagrees with "
                           "the oracle");
                if (ref && !acc)
                    fail_g(P, what, g, "in G_goal but not accepted");
            }
        }
        /* eq. 25: every wrench of G_goal tested is strongly stable when
           the plan says so */
        if (ref && (R->goal_in_strong || R->goal_in_strong_paper)
            && i % 3 == 0)
        {
            int ex, pa;

            ref_strong(&ex, &pa, P, g, what);
            if ((R->goal_in_strong && !ex) || (R->goal_in_strong_paper && !pa))
                fail_g(P, what, g, "in G_goal, not strongly stable, yet "
                       "eq. 25 is said to hold");
        }
    }

    /* eq. 25's witnesses */
    if (!R->goal_in_strong || !R->goal_in_strong_paper)
    {
        int ex, pa;

        for (k = 0; k < 2; k++)
        {
            const fmpq * g = k == 0 ? R->strong_witness : R->paper_witness;

            if (k == 0 ? R->goal_in_strong : R->goal_in_strong_paper)
                continue;
            if (ref_plan_goal_contains(O, g) != 1)
                fail_g(P, what, g, "eq. 25's witness is not in G_goal");
            ref_strong(&ex, &pa, P, g, what);
            if (k == 0 ? ex : pa)
                fail_g(P, what, g, "eq. 25's witness is strongly stable");
        }
        if (guaranteed)
            fail_g(P, what, NULL, "eq. 25 fails with normals of rank 3 and "
                   "mu_k <= mu_s");
    }
    if (R->has_extra)
    {
        if (ref_plan_complete_accepts(O, R->extra) != 1
            || ref_plan_goal_contains(O, R->extra) != 0)
            fail_g(P, what, R->extra, "the complete plan's extra wrench is "
                   "not accepted outside G_goal");
    }

    /* Exact redundancy: a dropped cone's face points lie in a kept cone.  */
    for (j = 0; j < nn; j++)
    {
        const wc_cone_struct * C = R->cones + j;
        wlist F = { 0, 0, NULL };

        if (R->exact_needed[j])
            continue;
        wl_add_cone(&F, C);
        for (i = 0; i < F.len; i += 3 * thin)  /* face points, thinned */
        {
            const fmpq * g = F.g + 3 * i;
            slong m;

            if (!wc_cone_contains(C, g))
                continue;
            for (m = 0; m < nn; m++)
                if (R->exact_needed[m]
                    && ref_wrench_in_cone(O, R->T->strings[R->T->needed[m]], g)
                    == 1)
                    break;
            if (m == nn)
                fail_g(P, what, g, "a point of an exactly redundant cone "
                       "lies in no kept cone");
        }
        wl_clear(&F);
    }

    /* ... and a kept cone has a cell that no other kept cone holds (the
       oracle's LPs confirm it).  */
    for (j = 0; j < nn; j++)
    {
        fmpq g[3];
        slong c, m;
        int found = 0;

        if (!R->exact_needed[j])
            continue;
        for (k = 0; k < 3; k++)
            fmpq_init(g + k);
        for (c = R->cells->count - 1; c >= 0 && !found; c--)
        {
            for (k = 0; k < 3; k++)
                fmpq_set_fmpz(g + k, fmpz_mat_entry(R->cells->point, c, k));
            if (!wc_cone_contains(R->cones + j, g))
                continue;
            for (m = 0; m < nn; m++)
                if (m != j && R->exact_needed[m]
                    && wc_cone_contains(R->cones + m, g))
                    break;
            found = m == nn;
        }
        if (!found)
            fail_g(P, what, NULL, "a cone kept by exact redundancy is "
                   "covered by the others");
        for (m = 0; m < nn; m++)
            if (R->exact_needed[m]
                && ref_wrench_in_cone(O, R->T->strings[R->T->needed[m]], g)
                != (m == j))
                fail_g(P, what, g, "the oracle disagrees on a point of a "
                       "kept cone alone");
        for (k = 0; k < 3; k++)
            fmpq_clear(g + k);
    }

    /* Pushing regions: sample points of every edge or direction.  */
    if (R->has_push && P->shape == WC_SHAPE_POLYGON)
    {
        slong m = P->shape_len / 2, e;
        fmpq_t s;
        fmpq g[3], q[2], d[2];

        fmpq_init(s);
        for (k = 0; k < 3; k++)
            fmpq_init(g + k);
        for (k = 0; k < 2; k++)
        {
            fmpq_init(q + k);
            fmpq_init(d + k);
        }
        for (e = 0; e < m; e++)
            for (i = 1; i < 16; i++)
            {
                const fmpq * a = P->shape_data + 2 * e;
                const fmpq * b = P->shape_data + 2 * ((e + 1) % m);
                int in = 0, ref;
                slong v;
                fmpq_t t;

                fmpq_init(t);
                fmpq_set_si(s, i, 16);
                for (k = 0; k < 2; k++)
                {
                    fmpq_sub(d + k, b + k, a + k);
                    fmpq_mul(q + k, d + k, s);
                    fmpq_add(q + k, q + k, a + k);
                }
                /* inward normal: the edge rotated towards the inside (the
                   centre of mass is inside) */
                fmpq_neg(g + 0, d + 1);
                fmpq_set(g + 1, d + 0);
                fmpq_sub(t, P->com + 0, q + 0);
                fmpq_mul(t, t, g + 0);
                fmpq_sub(g + 2, P->com + 1, q + 1);     /* scratch */
                fmpq_addmul(t, g + 2, g + 1);
                if (fmpq_sgn(t) < 0)
                {
                    fmpq_neg(g + 0, g + 0);
                    fmpq_neg(g + 1, g + 1);
                }
                /* torque (q - o) x d */
                fmpq_sub(q + 0, q + 0, P->com + 0);
                fmpq_sub(q + 1, q + 1, P->com + 1);
                fmpq_mul(g + 2, q + 0, g + 1);
                fmpq_mul(t, q + 1, g + 0);
                fmpq_sub(g + 2, g + 2, t);
                fmpq_clear(t);
                ref = ref_plan_goal_contains(O, g);
                for (v = 0; v < R->push_goal->count; v++)
                {
                    const wc_push_interval_struct * iv = R->push_goal->iv + v;
                    int c0 = fmpq_cmp(s, iv->from), c1 = fmpq_cmp(s, iv->to);

                    if (iv->edge == e && (c0 > 0 || (c0 == 0
                                                     && iv->from_closed))
                        && (c1 < 0 || (c1 == 0 && iv->to_closed)))
                        in = 1;
                }
                if (in != ref)
                    fail_g(P, what, g, "the pushing region disagrees with "
                           "the oracle");
            }
        fmpq_clear(s);
        for (k = 0; k < 3; k++)
            fmpq_clear(g + k);
        for (k = 0; k < 2; k++)
        {
            fmpq_clear(q + k);
            fmpq_clear(d + k);
        }
    }

    wl_clear(&L);
    wc_error_clear(err);
    wc_plan_wrench_clear(W);
    wc_plan_clear(R);
    wc_problem_clear(O);
}

/* ---- the critical friction --------------------------------------------- */

static void
at_friction(wc_problem_t Q, const wc_problem_t P, const fmpq_t mu)
{
    slong i;

    wc_problem_set(Q, P);
    for (i = 0; i < Q->n; i++)
    {
        fmpq_set(Q->fixels[i].mu_s, mu);
        fmpq_set(Q->fixels[i].mu_k, mu);
    }
}

static void
check_critical(const wc_problem_t P, const char * what)
{
    wc_critical_t C;
    wc_problem_t Q;
    wc_error_t err;
    fmpq_t width, max, w;
    fmpq g[3];
    slong k;

    wc_critical_init(C);
    wc_problem_init(Q);
    wc_error_init(err);
    fmpq_init(width);
    fmpq_init(max);
    fmpq_init(w);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    fmpq_set_si(width, 1, 64);
    fmpq_set_si(max, 16, 1);
    if (wc_plan_critical(C, P, width, max, err) != WC_OK)
        fail_g(P, what, NULL, err->message);
    if (C->empty_at_zero)
    {
        at_friction(Q, P, C->hi);
        if (ref_plan_goal_empty(Q, g) != 1)
            fail_g(P, what, g, "G_goal is said empty at mu = 0; the oracle "
                   "finds this wrench in it");
    }
    else
    {
        at_friction(Q, P, C->lo);
        if (ref_plan_goal_contains(Q, C->lo_witness) != 1)
            fail_g(P, what, C->lo_witness, "the witness at lo is not in "
                   "the oracle's G_goal");
        if (C->found)
        {
            fmpq_sub(w, C->hi, C->lo);
            if (fmpq_sgn(w) <= 0 || fmpq_cmp(w, width) > 0)
                fail_g(P, what, NULL, "the bracket is not of width in "
                       "(0, 1/64]");
            at_friction(Q, P, C->hi);
            if (ref_plan_goal_empty(Q, g) != 1)
                fail_g(P, what, g, "G_goal is said empty at hi; the oracle "
                       "finds this wrench in it");
        }
        else if (!fmpq_equal(C->lo, max))
            fail_g(P, what, NULL, "not found, yet lo is not the maximum");
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    fmpq_clear(width);
    fmpq_clear(max);
    fmpq_clear(w);
    wc_error_clear(err);
    wc_problem_clear(Q);
    wc_critical_clear(C);
}

/* ---- reference results ------------------------------------------------- */

/* Paper Figure 6: G_goal of the disk is exactly the open wedge of forces
   strictly between the two fixels' friction cones (outside both), with
   any torque: rays (-5, -1, 0), (-1, -5, 0), line (0, 0, 1), only the
   interior included.  Eq. 25 fails: a large torque spins the seated disk
   with both contacts loaded.  */
static void
test_disk(void)
{
    wc_problem_t P;
    wc_plan_t R;
    wc_error_t err;
    const wc_cone_struct * C;
    slong i;
    static const slong rays[2][3] = { { -5, -1, 0 }, { -1, -5, 0 } };

    wc_problem_init(P);
    wc_plan_init(R);
    wc_error_init(err);
    wctest_load_data(P, "disk-two-fixels-insert.wc");
    if (wc_plan(R, P, 1, err) != WC_OK)
        wctest_fail("disk: %s", err->message);
    if (R->goal->npieces != 1)
        wctest_fail("disk: G_goal has %ld pieces, not 1",
                    (long) R->goal->npieces);
    C = R->goal->pieces;
    if (C->dim != 3 || C->lineality_dim != 1 || fmpz_mat_nrows(C->rays) != 2
        || fmpz_mat_nrows(C->lines) != 1
        || !fmpz_is_zero(fmpz_mat_entry(C->lines, 0, 0))
        || !fmpz_is_zero(fmpz_mat_entry(C->lines, 0, 1))
        || !fmpz_is_one(fmpz_mat_entry(C->lines, 0, 2))
        || wc_cone_excluded_faces(C) != 3 || C->nfaces != 4)
        wctest_fail("disk: G_goal is not the open wedge with the torque "
                    "axis as its line");
    for (i = 0; i < 2; i++)
        if (fmpz_cmp_si(fmpz_mat_entry(C->rays, i, 0), rays[i][0]) != 0
            || fmpz_cmp_si(fmpz_mat_entry(C->rays, i, 1), rays[i][1]) != 0
            || fmpz_cmp_si(fmpz_mat_entry(C->rays, i, 2), rays[i][2]) != 0)
            wctest_fail("disk: ray %ld of G_goal is wrong", (long) i);
    if (R->goal_in_strong || R->goal_in_strong_paper)
        wctest_fail("disk: eq. 25 is said to hold");
    if (R->has_extra || R->accepted->npieces != 1
        || !wc_cone_equal(R->accepted->pieces, C))
        wctest_fail("disk: the complete plan should accept exactly G_goal");
    if (R->T->nneeded != 4 || R->nexact != 3 || R->exact_needed[2])
        wctest_fail("disk: su should be exactly redundant, nothing else");
    /* the pushing region: directions strictly between (5, 1) and (1, 5) */
    if (R->push_goal->count != 1 || R->push_goal->iv->from_closed
        || R->push_goal->iv->to_closed
        || fmpz_cmp_si(R->push_goal->iv->dfrom + 0, 5) != 0
        || fmpz_cmp_si(R->push_goal->iv->dfrom + 1, 1) != 0
        || fmpz_cmp_si(R->push_goal->iv->dto + 0, 1) != 0
        || fmpz_cmp_si(R->push_goal->iv->dto + 1, 5) != 0)
        wctest_fail("disk: the pushing region is not the open arc from "
                    "(5, 1) to (1, 5)");
    check_problem(P, "disk-two-fixels-insert.wc", 1, wctest_iters(3));
    check_critical(P, "disk-two-fixels-insert.wc");
    wc_error_clear(err);
    wc_plan_clear(R);
    wc_problem_clear(P);
}

/* The three-fixel block: twelve needed strings, eq. 25 holds, G_goal
   shrinks with friction, and the complete plan accepts (-7, -5, 5), which
   msu holds (the man page's example): from 110 it may lose fixel 2 while
   approaching fixel 3, and every such run still ends seated.  */
static void
test_three(void)
{
    static const slong mus[4][2] = { { 1, 100 }, { 1, 5 }, { 2, 5 },
                                     { 3, 5 } };
    wc_problem_t P;
    wc_plan_t R[4];
    wc_plan_wrench_t W;
    wc_error_t err;
    fmpq_t mu;
    fmpq g[3];
    slong i, j, k;

    wc_problem_init(P);
    wc_error_init(err);
    fmpq_init(mu);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    /* the plain block of wrenchcone(5) */
    wctest_load_data(P, "three-fixels.wc");
    check_problem(P, "three-fixels.wc", 1, wctest_iters(2));
    wc_problem_clear(P);
    wc_problem_init(P);
    wctest_load_data(P, "three-fixels-insert.wc");
    check_problem(P, "three-fixels-insert.wc", 1, wctest_iters(2));
    check_critical(P, "three-fixels-insert.wc");

    wc_plan_wrench_init(W);
    wctest_vec3_si(g, -7, -5, 5);
    if (wc_plan_wrench(W, P, g, 1, err) != WC_OK)
        wctest_fail("three-fixels: %s", err->message);
    if (W->in_goal || W->verdict != WC_PLAN_ACCEPTED || W->nholding != 1
        || strcmp(W->holding[0], "msu") != 0)
        wctest_fail("three-fixels: (-7, -5, 5) should be accepted by the "
                    "complete plan only, held by msu alone");
    wc_plan_wrench_clear(W);

    for (i = 0; i < 4; i++)
    {
        wc_plan_init(R[i]);
        fmpq_set_si(mu, mus[i][0], mus[i][1]);
        if (wc_plan_with_friction(R[i], P, mu, err) != WC_OK)
            wctest_fail("three-fixels sweep: %s", err->message);
        if (!R[i]->goal_in_strong || !R[i]->goal_in_strong_paper)
            wctest_fail("three-fixels at mu = %ld/%ld: eq. 25 fails",
                        (long) mus[i][0], (long) mus[i][1]);
    }
    if (R[0]->goal->empty || R[1]->goal->empty || !R[2]->goal->empty
        || !R[3]->goal->empty)
        wctest_fail("three-fixels sweep: G_goal should be nonempty at 1/100 "
                    "and 1/5, empty at 2/5 and 3/5");
    /* smaller with more friction: every face point at mu_{i+1} is in the
       set at mu_i */
    for (i = 0; i + 1 < 4; i++)
    {
        wlist L = { 0, 0, NULL };

        for (j = 0; j < R[i + 1]->goal->npieces; j++)
            wl_add_cone(&L, R[i + 1]->goal->pieces + j);
        for (j = 0; j < L.len; j++)
            if (wc_set_contains(R[i + 1]->goal, L.g + 3 * j)
                && !wc_set_contains(R[i]->goal, L.g + 3 * j))
                wctest_fail("three-fixels sweep: G_goal grows with friction");
        wl_clear(&L);
    }
    if (R[0]->push_goal->count != 1 || R[0]->push_goal->iv->edge != 2
        || R[2]->push_goal->count != 0)
        wctest_fail("three-fixels sweep: the pushing region should lie on "
                    "the chamfer (edge 2) at 1/100 and vanish at 2/5");
    for (i = 0; i < 4; i++)
        wc_plan_clear(R[i]);
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    fmpq_clear(mu);
    wc_error_clear(err);
    wc_problem_clear(P);
}

/* The complete plan at n = 4 (64-state graphs of the ulong adjacency):
   a disk with four fixels on its lower left quarter, a few wrenches
   against the oracle (4^4 LPs each).  */
static void
test_complete4(void)
{
    static const slong pts[4][2][2] = {
        { { -15, 17 }, { -8, 17 } }, { { -4, 5 }, { -3, 5 } },
        { { -3, 5 }, { -4, 5 } }, { { -8, 17 }, { -15, 17 } } };
    static const slong ws[6][3] = {
        { -1, -1, 0 }, { -3, -1, 1 }, { -1, -4, -1 }, { 0, 1, 0 },
        { -2, -3, 5 }, { 1, -1, 0 } };
    wc_problem_t P;
    wc_plan_t R;
    wc_plan_wrench_t W;
    wc_error_t err;
    fmpq g[3];
    slong i, k;
    /* every other wrench by default, all six in widened runs */
    slong thin = wctest_iters(1) >= 3 ? 1 : 2;

    wc_problem_init(P);
    wc_plan_init(R);
    wc_plan_wrench_init(W);
    wc_error_init(err);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    fmpq_set_si(P->inertia, 1, 2);
    for (i = 0; i < 4; i++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);

        fmpq_set_si(f->point + 0, pts[i][0][0], pts[i][0][1]);
        fmpq_set_si(f->point + 1, pts[i][1][0], pts[i][1][1]);
        fmpq_neg(f->normal + 0, f->point + 0);
        fmpq_neg(f->normal + 1, f->point + 1);
        fmpq_set_si(f->mu_s, 1, 5);
        fmpq_set_si(f->mu_k, 1, 5);
        f->state = WC_NEAR;
    }
    if (wc_plan(R, P, 1, err) != WC_OK)
        wctest_fail("four fixels: %s", err->message);
    for (i = 0; i < 7; i++)
    {
        int acc;

        if (i < 6)
            wctest_vec3_si(g, ws[i][0], ws[i][1], ws[i][2]);
        else if (R->has_extra)
            for (k = 0; k < 3; k++)
                fmpq_set(g + k, R->extra + k);
        else
            break;
        if (i < 6 && i % thin != 0)
            continue;
        acc = ref_plan_complete_accepts(P, g);
        if (wc_plan_wrench(W, P, g, 1, err) != WC_OK)
            fail_g(P, "four fixels", g, err->message);
        if (acc < 0 || (W->verdict == WC_PLAN_ACCEPTED) != acc
            || wc_set_contains(R->accepted, g) != acc
            || W->in_goal != ref_plan_goal_contains(P, g))
            fail_g(P, "four fixels", g, "the complete plan disagrees with "
                   "the oracle");
    }
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    wc_error_clear(err);
    wc_plan_wrench_clear(W);
    wc_plan_clear(R);
    wc_problem_clear(P);
}

static void
test_errors(void)
{
    wc_problem_t P;
    wc_plan_t R;
    wc_error_t err;
    slong i;

    wc_problem_init(P);
    wc_plan_init(R);
    wc_error_init(err);
    if (wc_plan(R, P, 0, err) != WC_EINPUT)
        wctest_fail("a problem without fixels is accepted");
    for (i = 0; i <= WC_PLAN_MAX_FIXELS_COMPLETE; i++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);

        fmpq_set_si(f->point + 0, i, 1);
        fmpq_set_si(f->normal + 1, 1, 1);
    }
    if (wc_plan(R, P, 1, err) != WC_EINPUT || err->message == NULL
        || strstr(err->message, "at most") == NULL)
        wctest_fail("the complete plan accepts %d fixels",
                    WC_PLAN_MAX_FIXELS_COMPLETE + 1);
    wc_error_clear(err);
    wc_plan_clear(R);
    wc_problem_clear(P);
}

int
main(void)
{
    slong i, iters;
    char what[64];

    wctest_init("t-plan");
    wc_init();

    test_strings();
    test_errors();
    test_disk();
    test_three();
    test_complete4();

    /* 3 by default, 9 in CI's widened run (at least the 8 this test once
       ran by default); the wrench counts above scale the same way.  */
    iters = wctest_iters(3);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        wctest_random_problem(P, 1, 3);
        snprintf(what, sizeof what, "random problem, n = %ld", (long) P->n);
        check_problem(P, what, i % 2 == 0, 6);
        if (i % 4 == 0)
            check_critical(P, what);
        wc_problem_clear(P);
    }
    return 0;
}
