/* plan.c -- sensorless insertion plans (paper Sections 8 and 9).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Every set here is a union of cells of one arrangement: the planes of
   every cone it is built from (lib/cells.c).  Membership of a cell is
   read at its point, so the sets, the redundancy test and the test of
   eq. 25 are exact.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"
#include "analysis/plan.h"

/* ---------------------------------------------------------------------
   Strings.  */

void
wc_plan_state_string(char * s, ulong S, slong n)
{
    slong i;

    for (i = 0; i < n; i++)
        s[i] = (S >> i) & 1 ? '1' : '0';
    s[n] = '\0';
}

void
wc_plan_strings_init(wc_plan_strings_t T)
{
    memset(T, 0, sizeof(wc_plan_strings_struct));
}

void
wc_plan_strings_clear(wc_plan_strings_t T)
{
    slong i;

    for (i = 0; i < T->nstrings; i++)
        free(T->strings[i]);
    free(T->strings);
    free(T->state_first);
    free(T->state_str);
    free(T->contained_in);
    free(T->needed);
    memset(T, 0, sizeof(wc_plan_strings_struct));
}

static int
str_ptr_cmp(const void * p, const void * q)
{
    return strcmp(*(char * const *) p, *(char * const *) q);
}

static slong
find_string(const wc_plan_strings_t T, const char * s)
{
    char * const * hit = bsearch(&s, T->strings, T->nstrings, sizeof(char *),
                                 str_ptr_cmp);

    return hit == NULL ? -1 : hit - T->strings;
}

/* The string of state S with lost contacts L (L empty: no progress).  */
static char *
state_string(ulong S, ulong L, slong n)
{
    char * s = malloc(n + 1);
    slong i;

    for (i = 0; i < n; i++)
    {
        ulong b = UWORD(1) << i;

        s[i] = (L & b) ? 's' : (S & b) ? 'm' : L != 0 ? 'u' : 's';
    }
    s[n] = '\0';
    return s;
}

int
wc_plan_strings(wc_plan_strings_t T, slong n, wc_error_t err)
{
    ulong full, S, L, R;
    slong cap, count = 0, k, i, j;
    char ** all;

    wc_plan_strings_clear(T);
    if (n < 1 || n > WC_PLAN_MAX_FIXELS)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "insertion plans take 1 to %d fixels, not %ld",
                            WC_PLAN_MAX_FIXELS, (long) n);
    T->n = n;
    full = (UWORD(1) << n) - 1;
    /* sum over S of 2^|S| = 3^n, plus the no-progress strings */
    for (cap = 1, i = 0; i < n; i++)
        cap *= 3;
    cap += full + 1;
    all = malloc(sizeof(char *) * cap);
    for (S = 0; S <= full; S++)
    {
        for (L = S; L != 0; L = (L - 1) & S)
            all[count++] = state_string(S, L, n);
        if (S != full)
            all[count++] = state_string(S, 0, n);
    }
    /* The same string arises in several states: keep one copy.  */
    qsort(all, count, sizeof(char *), str_ptr_cmp);
    for (i = 0, j = 0; i < count; i++)
    {
        if (j > 0 && strcmp(all[i], all[j - 1]) == 0)
            free(all[i]);
        else
            all[j++] = all[i];
    }
    T->strings = all;
    T->nstrings = j;

    /* By state, in the order the states generate them.  */
    T->state_first = malloc(sizeof(slong) * (full + 2));
    T->state_str = malloc(sizeof(slong) * count);
    for (S = 0, k = 0; S <= full; S++)
    {
        T->state_first[S] = k;
        /* the nonempty submasks of S in ascending order */
        for (L = (UWORD(0) - S) & S; L != 0; L = (L - S) & S)
        {
            char * s = state_string(S, L, n);

            T->state_str[k++] = find_string(T, s);
            free(s);
        }
        if (S != full)
        {
            char * s = state_string(S, 0, n);

            T->state_str[k++] = find_string(T, s);
            free(s);
        }
    }
    T->state_first[full + 1] = k;

    /* Syntactic redundancy: some nonempty set R of s letters turned into
       u gives a string of the list.  */
    T->contained_in = malloc(sizeof(slong) * T->nstrings);
    T->needed = malloc(sizeof(slong) * T->nstrings);
    T->nneeded = 0;
    {
        char * b = malloc(n + 1);

        for (i = 0; i < T->nstrings; i++)
        {
            const char * s = T->strings[i];
            ulong smask = 0;

            for (k = 0; k < n; k++)
                if (s[k] == 's')
                    smask |= UWORD(1) << k;
            T->contained_in[i] = -1;
            /* the submasks R of smask in increasing order, so that the
               string reported as containing it is always the same */
            for (R = 1; R <= smask && T->contained_in[i] < 0; R++)
            {
                if ((R & smask) != R)
                    continue;
                for (k = 0; k < n; k++)
                    b[k] = (R >> k) & 1 ? 'u' : s[k];
                b[n] = '\0';
                T->contained_in[i] = find_string(T, b);
            }
            if (T->contained_in[i] < 0)
                T->needed[T->nneeded++] = i;
        }
        free(b);
    }
    return WC_OK;
}

/* ---------------------------------------------------------------------
   Cones of strings.  */

/* W(x) for P, whose fixel states are set from the letters: m, l, r, n
   touching; a, u near; s leaves the state alone (it means the same in
   both).  Q is a scratch copy of P.  */
static int
string_cone(wc_cone_t W, wc_problem_t Q, const char * x, wc_error_t err)
{
    slong i;

    for (i = 0; i < Q->n; i++)
    {
        if (strchr("mlrn", x[i]) != NULL)
            Q->fixels[i].state = WC_TOUCHING;
        else if (x[i] == 'a' || x[i] == 'u')
            Q->fixels[i].state = WC_NEAR;
    }
    return wc_wrench_cone_direct(W, NULL, Q, x, err);
}

static wc_cone_struct *
cones_init(slong count)
{
    wc_cone_struct * C = flint_malloc(sizeof(wc_cone_struct) * (count + 1));
    slong i;

    for (i = 0; i < count; i++)
        wc_cone_init(C + i, 3);
    return C;
}

static void
cones_clear(wc_cone_struct * C, slong count)
{
    slong i;

    if (C == NULL)
        return;
    for (i = 0; i < count; i++)
        wc_cone_clear(C + i);
    flint_free(C);
}

/* The outcome string of index x (base-3 digits, fixel 0 first).  */
static void
outcome_string(char * s, slong x, slong n)
{
    slong i;

    for (i = n - 1; i >= 0; i--, x /= 3)
        s[i] = "sma"[x % 3];
    s[n] = '\0';
}

static slong
pow3(slong n)
{
    slong p = 1;

    while (n-- > 0)
        p *= 3;
    return p;
}

/* C[k] := W(x[k]) for P, k < count.  */
static int
strings_cones(wc_cone_struct * C, char * const * x, const slong * idx,
              slong count, const wc_problem_t P, wc_error_t err)
{
    wc_problem_t Q;
    slong k;
    int status;

    wc_problem_init(Q);
    if ((status = wc_problem_set(Q, P)) != WC_OK)
        wc_error_set(err, status, NULL, 0, 0, "out of memory");
    for (k = 0; k < count && status == WC_OK; k++)
        status = string_cone(C + k, Q, x[idx != NULL ? idx[k] : k], err);
    wc_problem_clear(Q);
    return status;
}

static int
needed_cones(wc_cone_struct * C, const wc_plan_strings_t T,
             const wc_problem_t P, wc_error_t err)
{
    return strings_cones(C, T->strings, T->needed, T->nneeded, P, err);
}

/* The 3^n outcome strings, in index order.  */
static char **
outcome_strings(slong count, slong n)
{
    char ** x = calloc(count + 1, sizeof(char *));
    slong k;

    for (k = 0; k < count; k++)
    {
        x[k] = malloc(n + 1);
        outcome_string(x[k], k, n);
    }
    return x;
}

static void
strings_free(char ** x, slong count)
{
    slong k;

    for (k = 0; k < count; k++)
        free(x[k]);
    free(x);
}

static int
outcome_cones(wc_cone_struct * C, slong count, const wc_problem_t P,
              wc_error_t err)
{
    char ** x = outcome_strings(count, P->n);
    int status = strings_cones(C, x, NULL, count, P, err);

    strings_free(x, count);
    return status;
}

/* Append the facet and equality normals of C to the rows of A (r used).  */
static void
add_planes(fmpz_mat_t A, slong * r, const wc_cone_t C)
{
    slong i, k, ni = fmpz_mat_nrows(C->ineqs), ne = fmpz_mat_nrows(C->eqs);

    if (*r + ni + ne > fmpz_mat_nrows(A))
    {
        fmpz_mat_t B;
        slong rows = 2 * (*r + ni + ne) + 16;

        fmpz_mat_init(B, rows, 3);
        for (i = 0; i < *r; i++)
            for (k = 0; k < 3; k++)
                fmpz_swap(fmpz_mat_entry(B, i, k), fmpz_mat_entry(A, i, k));
        fmpz_mat_swap(A, B);
        fmpz_mat_clear(B);
    }
    for (i = 0; i < ni + ne; i++, (*r)++)
        for (k = 0; k < 3; k++)
            fmpz_set(fmpz_mat_entry(A, *r, k), i < ni
                     ? fmpz_mat_entry(C->ineqs, i, k)
                     : fmpz_mat_entry(C->eqs, i - ni, k));
}

/* The first r rows of A, as a matrix of their own (for wc_cells_build).  */
static void
planes_build(wc_cells_t cells, int * status, fmpz_mat_t A, slong r,
             wc_error_t err)
{
    fmpz_mat_t B;
    slong i, k;

    if (*status != WC_OK)
        return;
    fmpz_mat_init(B, r, 3);
    for (i = 0; i < r; i++)
        for (k = 0; k < 3; k++)
            fmpz_swap(fmpz_mat_entry(B, i, k), fmpz_mat_entry(A, i, k));
    *status = wc_cells_build(cells, B, err);
    fmpz_mat_clear(B);
}

static void
cell_point(fmpq * g, const wc_cells_t A, slong i)
{
    slong k;

    for (k = 0; k < 3; k++)
        fmpq_set_fmpz(g + k, fmpz_mat_entry(A->point, i, k));
}

/* Membership of cells in a cone from the cells' sign vectors: the cone's
   facets and equalities are planes of the arrangement, so a cell is out
   as soon as one sign is wrong, and in when it is strictly inside every
   facet (the relative interior, included unless the cone is a single
   excluded face).  Only the cells on the cone's boundary need the face
   lattice (wc_cone_contains).  This replaces arithmetic by byte lookups
   in the inner loop of every set here.  */
typedef struct
{
    const wc_cone_struct * C;
    slong nf, ne;
    slong * plane;          /* nf facets, then ne equalities; -1: none */
    signed char * orient;   /* the facet's sign relative to its plane */
    int top;                /* the relative interior belongs to C */
    int usable;
}
cone_key;

static void
key_init(cone_key * K, const wc_cone_struct * C, const wc_cells_t A)
{
    slong i, k;

    K->C = C;
    K->nf = fmpz_mat_nrows(C->ineqs);
    K->ne = fmpz_mat_nrows(C->eqs);
    K->plane = malloc(sizeof(slong) * (K->nf + K->ne + 1));
    K->orient = malloc(K->nf + K->ne + 1);
    K->top = !C->empty && C->nfaces > 0 && C->faces[C->nfaces - 1].included;
    K->usable = !C->empty;
    for (i = 0; i < K->nf + K->ne; i++)
    {
        const fmpz * h = i < K->nf ? C->ineqs->rows[i]
            : C->eqs->rows[i - K->nf];

        K->plane[i] = wc_cells_plane_index(A, h);
        K->usable = K->usable && K->plane[i] >= 0;
        for (k = 0; k < 3 && fmpz_is_zero(h + k); k++)
            ;
        K->orient[i] = (signed char) (k < 3 ? fmpz_sgn(h + k) : 0);
    }
}

static void
key_clear(cone_key * K)
{
    free(K->plane);
    free(K->orient);
}

/* 1 when cell i of A (point g) lies in K's cone.  */
static int
key_contains(const cone_key * K, const wc_cells_t A, slong i, const fmpq * g)
{
    const signed char * s = A->sign + i * A->nplanes;
    slong j;
    int strict = 1;

    if (K->C->empty)
        return 0;
    if (!K->usable)
        return wc_cone_contains(K->C, g);
    for (j = 0; j < K->ne; j++)
        if (s[K->plane[K->nf + j]] != 0)
            return 0;
    for (j = 0; j < K->nf; j++)
    {
        int t = K->orient[j] * s[K->plane[j]];

        if (t > 0)
            return 0;
        strict = strict && t < 0;
    }
    return strict ? K->top : wc_cone_contains(K->C, g);
}

static cone_key *
keys_init(const wc_cone_struct * C, slong count, const wc_cells_t A)
{
    cone_key * K = malloc(sizeof(cone_key) * (count + 1));
    slong i;

    for (i = 0; i < count; i++)
        key_init(K + i, C + i, A);
    return K;
}

static void
keys_clear(cone_key * K, slong count)
{
    slong i;

    if (K == NULL)
        return;
    for (i = 0; i < count; i++)
        key_clear(K + i);
    free(K);
}

/* ---------------------------------------------------------------------
   The complete plan's transition graph.  States are bit masks; n <= 6, so
   a state's successors fit in one ulong.  */

typedef void (* edge_fn)(void * ctx, ulong from, ulong to, slong outcome);

/* Every transition the outcomes admitted by member[] allow.  */
static void
transitions(slong n, const unsigned char * member, edge_fn add, void * ctx)
{
    ulong full = (UWORD(1) << n) - 1, S, B, Ap;
    slong i;

    for (S = 0; S <= full; S++)
        for (B = 0; B <= full; B++)
        {
            /* B: the fixels whose letter is not s (m in S, a off S) */
            ulong L = S & ~B, A = B & ~S;
            slong x = 0;

            for (i = 0; i < n; i++)
                x = 3 * x + (((B >> i) & 1) ? (((S >> i) & 1) ? 1 : 2) : 0);
            if (!member[x])
                continue;
            for (Ap = A;; Ap = (Ap - 1) & A)
            {
                if (!(Ap == 0 && L == 0 && A != 0))
                    add(ctx, S, (S & ~L) | Ap, x);
                if (Ap == 0)
                    break;
            }
        }
}

static void
add_adj(void * ctx, ulong from, ulong to, slong outcome)
{
    ulong * adj = ctx;

    (void) outcome;
    adj[from] |= UWORD(1) << to;
}

/* The verdict of the graph adj; with cycle != NULL, the states of a cycle
   (or the offending state) in cycle[0 .. *ncycle).  */
static wc_plan_verdict
verdict(const ulong * adj, slong n, ulong * cycle, slong * ncycle)
{
    ulong full = (UWORD(1) << n) - 1, S, T;
    slong nst = full + 1, top, i;
    unsigned char * color;
    ulong * stack, * next;
    wc_plan_verdict v = WC_PLAN_ACCEPTED;

    if (ncycle != NULL)
        *ncycle = 0;
    if (adj[full] & ~(UWORD(1) << full))
    {
        if (cycle != NULL)
            cycle[(*ncycle)++] = full;
        return WC_PLAN_GOAL_LEAVES;
    }
    for (S = 0; S < full; S++)
        if (adj[S] == 0)
        {
            if (cycle != NULL)
                cycle[(*ncycle)++] = S;
            return WC_PLAN_STUCK;
        }
    /* Depth-first search over the non-goal states: grey on the stack.  */
    color = calloc(nst, 1);
    stack = malloc(sizeof(ulong) * (nst + 1));
    next = malloc(sizeof(ulong) * (nst + 1));
    for (S = 0; S < full && v == WC_PLAN_ACCEPTED; S++)
    {
        if (color[S])
            continue;
        top = 0;
        stack[0] = S;
        next[0] = 0;
        color[S] = 1;
        while (top >= 0 && v == WC_PLAN_ACCEPTED)
        {
            ulong U = stack[top];

            for (T = next[top]; T < full; T++)
                if ((adj[U] >> T) & 1)
                    break;
            if (T >= full)
            {
                color[U] = 2;
                top--;
                continue;
            }
            next[top] = T + 1;
            if (color[T] == 1)
            {
                v = WC_PLAN_CYCLE;
                if (cycle != NULL)
                {
                    for (i = 0; stack[i] != T; i++)
                        ;
                    for (; i <= top; i++)
                        cycle[(*ncycle)++] = stack[i];
                }
            }
            else if (color[T] == 0)
            {
                color[T] = 1;
                stack[++top] = T;
                next[top] = 0;
            }
        }
    }
    free(color);
    free(stack);
    free(next);
    return v;
}

/* ---------------------------------------------------------------------
   The plan as sets.  */

void
wc_plan_init(wc_plan_t R)
{
    slong k;

    memset(R, 0, sizeof(wc_plan_struct));
    wc_plan_strings_init(R->T);
    wc_set_init(R->goal);
    wc_stability_init(R->stab);
    wc_push_init(R->push_goal);
    wc_set_init(R->accepted);
    wc_push_init(R->push_accepted);
    wc_cells_init(R->cells);
    for (k = 0; k < 3; k++)
    {
        fmpq_init(R->strong_witness + k);
        fmpq_init(R->paper_witness + k);
        fmpq_init(R->extra + k);
    }
}

void
wc_plan_clear(wc_plan_t R)
{
    slong k;

    cones_clear(R->cones, R->T->nneeded);
    free(R->exact_needed);
    wc_plan_strings_clear(R->T);
    wc_set_clear(R->goal);
    wc_stability_clear(R->stab);
    wc_push_clear(R->push_goal);
    cones_clear(R->outcomes, R->noutcomes);
    wc_set_clear(R->accepted);
    wc_push_clear(R->push_accepted);
    wc_cells_clear(R->cells);
    for (k = 0; k < 3; k++)
    {
        fmpq_clear(R->strong_witness + k);
        fmpq_clear(R->paper_witness + k);
        fmpq_clear(R->extra + k);
    }
    memset(R, 0, sizeof(wc_plan_struct));
}

static int
in_set(const fmpq * g, void * ctx)
{
    return wc_set_contains(ctx, g);
}

static int
check_size(const wc_problem_t P, int complete, wc_error_t err)
{
    int status = wc_problem_check(P, err);

    if (status != WC_OK)
        return status;
    if (P->n > WC_PLAN_MAX_FIXELS)
        return wc_error_set(err, WC_EINPUT, P->file, 0, 0,
                            "insertion plans take at most %d fixels, not %ld",
                            WC_PLAN_MAX_FIXELS, (long) P->n);
    if (complete && P->n > WC_PLAN_MAX_FIXELS_COMPLETE)
        return wc_error_set(err, WC_EINPUT, P->file, 0, 0,
                            "the complete plan takes at most %d fixels, "
                            "not %ld", WC_PLAN_MAX_FIXELS_COMPLETE,
                            (long) P->n);
    return WC_OK;
}

/* Bit k of cell i's row of the membership matrix.  */
#define IN(i, k) ((int) ((in[(i) * words + (k) / FLINT_BITS] \
                          >> ((k) % FLINT_BITS)) & 1))
#define IN_SET(i, k) (in[(i) * words + (k) / FLINT_BITS] \
                      |= UWORD(1) << ((k) % FLINT_BITS))

int
wc_plan(wc_plan_t R, const wc_problem_t P, int complete, wc_error_t err)
{
    wc_problem_t Q;
    fmpz_mat_t planes;
    slong np = 0, nn, i, k, ncells, full;
    ulong * in = NULL;
    unsigned char * member = NULL;
    int * goal = NULL, * acc = NULL, status;
    ulong * adj = NULL;
    slong * cnt = NULL, words = 0;
    cone_key * keys = NULL, * okeys = NULL;
    fmpq g[3];

    wc_plan_clear(R);
    wc_plan_init(R);
    if ((status = check_size(P, complete, err)) != WC_OK)
        return status;
    wc_problem_init(Q);
    fmpz_mat_init(planes, 0, 3);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);

    if ((status = wc_plan_strings(R->T, P->n, err)) != WC_OK)
        goto cleanup;
    nn = R->T->nneeded;
    R->cones = cones_init(nn);
    if ((status = needed_cones(R->cones, R->T, P, err)) != WC_OK)
        goto cleanup;
    for (k = 0; k < nn; k++)
        add_planes(planes, &np, R->cones + k);

    /* The goal state: every fixel touching.  */
    if ((status = wc_problem_set(Q, P)) != WC_OK)
        goto cleanup;
    for (i = 0; i < Q->n; i++)
        Q->fixels[i].state = WC_TOUCHING;
    if ((status = wc_stability(R->stab, Q, err)) != WC_OK)
        goto cleanup;
    add_planes(planes, &np, R->stab->weak);
    for (k = 0; k < R->stab->nmoving; k++)
        add_planes(planes, &np, R->stab->moving + k);
    for (k = 0; k < R->stab->nunion; k++)
        add_planes(planes, &np, R->stab->paper_union + k);

    if (complete)
    {
        R->complete = 1;
        R->noutcomes = pow3(P->n);
        R->outcomes = cones_init(R->noutcomes);
        if ((status = outcome_cones(R->outcomes, R->noutcomes, P, err))
            != WC_OK)
            goto cleanup;
        for (k = 0; k < R->noutcomes; k++)
            add_planes(planes, &np, R->outcomes + k);
    }
    planes_build(R->cells, &status, planes, np, err);
    if (status != WC_OK)
        goto cleanup;

    /* Membership of every cell in every needed cone, and how many of the
       cones kept so far hold each cell.  */
    ncells = R->cells->count;
    keys = keys_init(R->cones, nn, R->cells);
    words = (nn + FLINT_BITS - 1) / FLINT_BITS;    /* a bit per cone */
    in = calloc((size_t) ncells * words + 1, sizeof(ulong));
    goal = malloc(sizeof(int) * (ncells + 1));
    cnt = malloc(sizeof(slong) * (ncells + 1));
    if (in == NULL || goal == NULL || cnt == NULL)
    {
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "out of memory (%ld cells, %ld cones)",
                              (long) ncells, (long) nn);
        goto cleanup;
    }
    for (i = 0; i < ncells; i++)
    {
        cell_point(g, R->cells, i);
        cnt[i] = 0;
        for (k = 0; k < nn; k++)
            if (key_contains(keys + k, R->cells, i, g))
            {
                IN_SET(i, k);
                cnt[i]++;
            }
        goal[i] = cnt[i] == 0;
    }

    /* Exact redundancy, in ASCII order: drop a cone inside the union of
       the cones still kept, i.e. every cell of it held by another.  */
    R->exact_needed = malloc(sizeof(int) * (nn + 1));
    R->nexact = nn;
    for (k = 0; k < nn; k++)
    {
        int covered = 1;

        for (i = 0; i < ncells && covered; i++)
            covered = !IN(i, k) || cnt[i] >= 2;
        R->exact_needed[k] = !covered;
        if (covered)
        {
            R->nexact--;
            for (i = 0; i < ncells; i++)
                cnt[i] -= IN(i, k);
        }
    }

    /* Eq. 25 in both semantics.  */
    R->goal_in_strong = R->goal_in_strong_paper = 1;
    for (i = ncells - 1; i >= 0; i--)
    {
        if (!goal[i])
            continue;
        cell_point(g, R->cells, i);
        if (R->goal_in_strong && !wc_set_contains(R->stab->strong, g))
        {
            R->goal_in_strong = 0;
            for (k = 0; k < 3; k++)
                fmpq_set(R->strong_witness + k, g + k);
        }
        if (R->goal_in_strong_paper
            && !wc_set_contains(R->stab->strong_paper, g))
        {
            R->goal_in_strong_paper = 0;
            for (k = 0; k < 3; k++)
                fmpq_set(R->paper_witness + k, g + k);
        }
    }
    if ((status = wc_set_from_cells(R->goal, R->cells, goal, err)) != WC_OK
        || (status = wc_set_merge(R->goal, R->cells, err)) != WC_OK)
        goto cleanup;

    if (complete)
    {
        full = (slong) 1 << P->n;
        member = malloc((size_t) R->noutcomes + 1);
        adj = malloc(sizeof(ulong) * full);
        acc = malloc(sizeof(int) * (ncells + 1));
        if (member == NULL || adj == NULL || acc == NULL)
        {
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "out of memory");
            goto cleanup;
        }
        okeys = keys_init(R->outcomes, R->noutcomes, R->cells);
        R->has_extra = 0;
        for (i = 0; i < ncells; i++)
        {
            cell_point(g, R->cells, i);
            for (k = 0; k < R->noutcomes; k++)
                member[k] = (unsigned char) key_contains(okeys + k, R->cells,
                                                         i, g);
            memset(adj, 0, sizeof(ulong) * full);
            transitions(P->n, member, add_adj, adj);
            acc[i] = verdict(adj, P->n, NULL, NULL) == WC_PLAN_ACCEPTED;
            if (acc[i] && !goal[i])
            {
                /* cells come by dimension: keep the last, a chamber if
                   any */
                R->has_extra = 1;
                for (k = 0; k < 3; k++)
                    fmpq_set(R->extra + k, g + k);
            }
            if (goal[i] && !acc[i])
            {
                status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                      "internal error: a wrench of G_goal "
                                      "is rejected by the complete plan");
                goto cleanup;
            }
        }
        if ((status = wc_set_from_cells(R->accepted, R->cells, acc, err))
            != WC_OK
            || (status = wc_set_merge(R->accepted, R->cells, err)) != WC_OK)
            goto cleanup;
    }

    if (P->shape != WC_SHAPE_NONE)
    {
        R->has_push = 1;
        status = wc_push_regions(R->push_goal, P, R->cells->planes, in_set,
                                 R->goal, err);
        if (status == WC_OK && complete)
        {
            R->has_push_accepted = 1;
            status = wc_push_regions(R->push_accepted, P, R->cells->planes,
                                     in_set, R->accepted, err);
        }
    }

cleanup:
    keys_clear(keys, R->T->nneeded);
    keys_clear(okeys, R->noutcomes);
    free(cnt);
    free(in);
    free(goal);
    free(acc);
    free(member);
    free(adj);
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    fmpz_mat_clear(planes);
    wc_problem_clear(Q);
    if (status != WC_OK)
    {
        wc_plan_clear(R);
        wc_plan_init(R);
    }
    return status;
}

/* ---------------------------------------------------------------------
   One wrench.  */

void
wc_plan_wrench_init(wc_plan_wrench_t W)
{
    slong k;

    memset(W, 0, sizeof(wc_plan_wrench_struct));
    for (k = 0; k < 3; k++)
        fmpq_init(W->g + k);
}

void
wc_plan_wrench_clear(wc_plan_wrench_t W)
{
    slong k;

    for (k = 0; k < 3; k++)
        fmpq_clear(W->g + k);
    for (k = 0; k < W->nholding; k++)
        free(W->holding[k]);
    free(W->holding);
    for (k = 0; k < W->nedges; k++)
        free(W->via[k]);
    free(W->via);
    free(W->from);
    free(W->to);
    free(W->cycle);
    memset(W, 0, sizeof(wc_plan_wrench_struct));
}

typedef struct
{
    wc_plan_wrench_struct * W;
    ulong * adj;
}
edge_ctx;

static void
add_edge(void * p, ulong from, ulong to, slong outcome)
{
    edge_ctx * c = p;
    wc_plan_wrench_struct * W = c->W;

    if ((c->adj[from] >> to) & 1)
        return;     /* one outcome per edge is enough to show it */
    c->adj[from] |= UWORD(1) << to;
    W->from[W->nedges] = from;
    W->to[W->nedges] = to;
    W->via[W->nedges] = malloc(W->n + 1);
    outcome_string(W->via[W->nedges], outcome, W->n);
    W->nedges++;
}

int
wc_plan_wrench(wc_plan_wrench_t W, const wc_problem_t P, const fmpq * g,
               int complete, wc_error_t err)
{
    wc_plan_strings_t T;
    wc_cone_struct * C = NULL;
    slong k, count = 0;
    unsigned char * member = NULL;
    ulong * adj = NULL;
    int status;

    wc_plan_wrench_clear(W);
    wc_plan_wrench_init(W);
    if ((status = check_size(P, complete, err)) != WC_OK)
        return status;
    W->n = P->n;
    for (k = 0; k < 3; k++)
        fmpq_set(W->g + k, g + k);
    wc_plan_strings_init(T);
    if ((status = wc_plan_strings(T, P->n, err)) != WC_OK)
        goto cleanup;
    C = cones_init(count = T->nneeded);
    if ((status = needed_cones(C, T, P, err)) != WC_OK)
        goto cleanup;
    W->in_goal = 1;
    W->holding = malloc(sizeof(char *) * (T->nneeded + 1));
    for (k = 0; k < T->nneeded; k++)
        if (wc_cone_contains(C + k, g))
        {
            W->in_goal = 0;
            W->holding[W->nholding++] = strdup(T->strings[T->needed[k]]);
        }
    if (complete)
    {
        slong nst = (slong) 1 << P->n;
        edge_ctx c;

        cones_clear(C, count);
        count = pow3(P->n);
        C = cones_init(count);
        if ((status = outcome_cones(C, count, P, err)) != WC_OK)
            goto cleanup;
        member = malloc((size_t) count + 1);
        for (k = 0; k < count; k++)
            member[k] = (unsigned char) wc_cone_contains(C + k, g);
        adj = calloc(nst, sizeof(ulong));
        /* at most one edge per pair of states */
        W->from = malloc(sizeof(ulong) * nst * nst);
        W->to = malloc(sizeof(ulong) * nst * nst);
        W->via = malloc(sizeof(char *) * nst * nst);
        c.W = W;
        c.adj = adj;
        transitions(P->n, member, add_edge, &c);
        W->complete = 1;
        W->cycle = malloc(sizeof(ulong) * (nst + 1));
        W->verdict = verdict(adj, P->n, W->cycle, &W->ncycle);
        if (W->in_goal && W->verdict != WC_PLAN_ACCEPTED)
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: a wrench of G_goal is "
                                  "rejected by the complete plan");
    }

cleanup:
    cones_clear(C, count);
    free(member);
    free(adj);
    wc_plan_strings_clear(T);
    if (status != WC_OK)
    {
        wc_plan_wrench_clear(W);
        wc_plan_wrench_init(W);
    }
    return status;
}

/* ---------------------------------------------------------------------
   Friction.  */

/* Q := P with mu_s = mu_k = mu everywhere.  */
static int
with_friction(wc_problem_t Q, const wc_problem_t P, const fmpq_t mu)
{
    slong i;
    int status = wc_problem_set(Q, P);

    if (status != WC_OK)
        return status;
    fmpq_set(Q->mu_s, mu);
    fmpq_set(Q->mu_k, mu);
    for (i = 0; i < Q->n; i++)
    {
        fmpq_set(Q->fixels[i].mu_s, mu);
        fmpq_set(Q->fixels[i].mu_k, mu);
    }
    return WC_OK;
}

int
wc_plan_with_friction(wc_plan_t R, const wc_problem_t P, const fmpq_t mu,
                      wc_error_t err)
{
    wc_problem_t Q;
    int status;

    if (fmpq_sgn(mu) < 0)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "a friction coefficient must not be negative");
    wc_problem_init(Q);
    status = with_friction(Q, P, mu);
    if (status == WC_OK)
        status = wc_plan(R, Q, 0, err);
    else
        wc_error_set(err, status, NULL, 0, 0, "out of memory");
    wc_problem_clear(Q);
    return status;
}

void
wc_critical_init(wc_critical_t C)
{
    slong k;

    memset(C, 0, sizeof(wc_critical_struct));
    fmpq_init(C->lo);
    fmpq_init(C->hi);
    for (k = 0; k < 3; k++)
        fmpq_init(C->lo_witness + k);
}

void
wc_critical_clear(wc_critical_t C)
{
    slong k;

    fmpq_clear(C->lo);
    fmpq_clear(C->hi);
    for (k = 0; k < 3; k++)
        fmpq_clear(C->lo_witness + k);
}

/* Whether G_goal of P at friction mu is empty, with a wrench in it when
   not: the needed cones and their arrangement only.  */
static int
goal_empty(int * empty, fmpq * witness, const wc_plan_strings_t T,
           const wc_problem_t P, const fmpq_t mu, wc_error_t err)
{
    wc_problem_t Q;
    wc_cone_struct * C;
    wc_cells_t cells;
    fmpz_mat_t planes;
    cone_key * keys = NULL;
    slong np = 0, i, k, nn = T->nneeded;
    fmpq g[3];
    int status;

    wc_problem_init(Q);
    wc_cells_init(cells);
    fmpz_mat_init(planes, 0, 3);
    C = cones_init(nn);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    if ((status = with_friction(Q, P, mu)) != WC_OK)
    {
        wc_error_set(err, status, NULL, 0, 0, "out of memory");
        goto cleanup;
    }
    if ((status = needed_cones(C, T, Q, err)) != WC_OK)
        goto cleanup;
    for (k = 0; k < nn; k++)
        add_planes(planes, &np, C + k);
    planes_build(cells, &status, planes, np, err);
    if (status != WC_OK)
        goto cleanup;
    *empty = 1;
    keys = keys_init(C, nn, cells);
    /* the chambers come last; a witness there is the most telling */
    for (i = cells->count - 1; i >= 0 && *empty; i--)
    {
        cell_point(g, cells, i);
        for (k = 0; k < nn; k++)
            if (key_contains(keys + k, cells, i, g))
                break;
        if (k == nn)
        {
            *empty = 0;
            for (k = 0; k < 3; k++)
                fmpq_set(witness + k, g + k);
        }
    }

cleanup:
    keys_clear(keys, nn);
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    cones_clear(C, nn);
    fmpz_mat_clear(planes);
    wc_cells_clear(cells);
    wc_problem_clear(Q);
    return status;
}

int
wc_plan_critical(wc_critical_t C, const wc_problem_t P, const fmpq_t width,
                 const fmpq_t max, wc_error_t err)
{
    wc_plan_strings_t T;
    fmpq_t mid, w, lo, hi;
    fmpq g[3];
    int status, empty = 0;
    slong k;

    if ((status = check_size(P, 0, err)) != WC_OK)
        return status;
    if (fmpq_sgn(width) <= 0 || fmpq_sgn(max) <= 0)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "the width and the largest friction must be "
                            "positive");
    wc_plan_strings_init(T);
    fmpq_init(mid);
    fmpq_init(w);
    fmpq_init(lo);
    fmpq_init(hi);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    C->found = C->empty_at_zero = 0;
    C->evals = 0;
    if ((status = wc_plan_strings(T, P->n, err)) != WC_OK)
        goto cleanup;

    /* mu = 0 */
    fmpq_zero(lo);
    C->evals++;
    if ((status = goal_empty(&empty, C->lo_witness, T, P, lo, err))
        != WC_OK)
        goto cleanup;
    if (empty)
    {
        C->found = C->empty_at_zero = 1;
        fmpq_zero(hi);
        goto cleanup;
    }
    /* hi = 1, 2, 4, ... while nonempty, up to max */
    fmpq_one(hi);
    for (;;)
    {
        if (fmpq_cmp(hi, max) > 0)
            fmpq_set(hi, max);
        C->evals++;
        if ((status = goal_empty(&empty, g, T, P, hi, err)) != WC_OK)
            goto cleanup;
        if (empty)
            break;
        fmpq_set(lo, hi);
        for (k = 0; k < 3; k++)
            fmpq_set(C->lo_witness + k, g + k);
        if (fmpq_equal(hi, max))
            goto cleanup;       /* found = 0 */
        fmpq_mul_2exp(hi, hi, 1);
    }
    C->found = 1;
    /* bisect [lo, hi] */
    for (;;)
    {
        fmpq_sub(w, hi, lo);
        if (fmpq_cmp(w, width) <= 0)
            break;
        fmpq_add(mid, lo, hi);
        fmpq_div_2exp(mid, mid, 1);
        C->evals++;
        if ((status = goal_empty(&empty, g, T, P, mid, err)) != WC_OK)
            goto cleanup;
        if (empty)
            fmpq_set(hi, mid);
        else
        {
            fmpq_set(lo, mid);
            for (k = 0; k < 3; k++)
                fmpq_set(C->lo_witness + k, g + k);
        }
    }

cleanup:
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    /* GCC 12 misreads fmpq_t members of *C as 8 bytes: work on locals */
    fmpq_set(C->lo, lo);
    fmpq_set(C->hi, hi);
    fmpq_clear(lo);
    fmpq_clear(hi);
    fmpq_clear(mid);
    fmpq_clear(w);
    wc_plan_strings_clear(T);
    return status;
}
