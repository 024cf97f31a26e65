/* plan.c -- sensorless insertion plans (paper Sections 8 and 9).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Every set here is a union of cells of one arrangement: the planes of
   every cone it is built from (planparts.h).  Membership of a cell is
   read at its point, so the sets, the redundancy test and the test of
   eq. 25 are exact.  */

#include <config.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/planparts.h"
#include "analysis/push.h"
#include "analysis/stability.h"

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

    _wc_plan_cones_clear(R->cones, R->T->nneeded);
    free(R->exact_needed);
    wc_plan_strings_clear(R->T);
    wc_set_clear(R->goal);
    wc_stability_clear(R->stab);
    wc_push_clear(R->push_goal);
    _wc_plan_cones_clear(R->outcomes, R->noutcomes);
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

int
_wc_plan_check_size(const wc_problem_t P, int complete, wc_error_t err)
{
    int status = wc_problem_check(P, err);

    if (status != WC_OK)
        return status;
    if ((status = wc_problem_check_fixels(P, WC_PLAN_MAX_FIXELS, 0,
                                          "an insertion plan", err))
        != WC_OK)
        return status;
    if (complete)
        return wc_problem_check_fixels(P, WC_PLAN_MAX_FIXELS_COMPLETE, 0,
                                       "the complete plan", err);
    return WC_OK;
}

/* R->cells := the arrangement of every cone the plan is built from: the
   needed cones (R->cones), the goal state's stability cones (R->stab)
   and, for the complete plan, the outcome cones (R->outcomes).  */
static int
plan_cells(wc_plan_t R, const wc_problem_t P, int complete, wc_error_t err)
{
    wc_problem_t Q;
    fmpz_mat_t planes;
    slong np = 0, nn, i, k;
    int status;

    wc_problem_init(Q);
    fmpz_mat_init(planes, 0, 3);
    if ((status = wc_plan_strings(R->T, P->n, err)) != WC_OK)
        goto cleanup;
    nn = R->T->nneeded;
    R->cones = _wc_plan_cones_init(nn);
    if ((status = _wc_plan_needed_cones(R->cones, R->T, P, err)) != WC_OK)
        goto cleanup;
    for (k = 0; k < nn; k++)
        _wc_cellset_add_planes(planes, &np, R->cones + k);

    /* The goal state: every fixel touching.  */
    if ((status = wc_problem_set(Q, P)) != WC_OK)
        goto cleanup;
    for (i = 0; i < Q->n; i++)
        Q->fixels[i].state = WC_TOUCHING;
    if ((status = wc_stability(R->stab, Q, err)) != WC_OK)
        goto cleanup;
    _wc_cellset_add_planes(planes, &np, R->stab->weak);
    for (k = 0; k < R->stab->nmoving; k++)
        _wc_cellset_add_planes(planes, &np, R->stab->moving + k);
    for (k = 0; k < R->stab->nunion; k++)
        _wc_cellset_add_planes(planes, &np, R->stab->paper_union + k);

    if (complete)
    {
        R->complete = 1;
        R->noutcomes = _wc_plan_pow3(P->n);
        R->outcomes = _wc_plan_cones_init(R->noutcomes);
        if ((status = _wc_plan_outcome_cones(R->outcomes, R->noutcomes, P,
                                             err)) != WC_OK)
            goto cleanup;
        for (k = 0; k < R->noutcomes; k++)
            _wc_cellset_add_planes(planes, &np, R->outcomes + k);
    }
    _wc_cellset_build(R->cells, &status, planes, np, err);
cleanup:
    fmpz_mat_clear(planes);
    wc_problem_clear(Q);
    return status;
}

/* Eq. 25 in both semantics: is every cell of G_goal (goal[i]) in the
   strong stability set?  The last cell that is not is the witness.  */
static void
plan_eq25(wc_plan_t R, const int * goal, fmpq * g)
{
    slong i, k;

    R->goal_in_strong = R->goal_in_strong_paper = 1;
    for (i = R->cells->count - 1; i >= 0; i--)
    {
        if (!goal[i])
            continue;
        _wc_cellset_point(g, R->cells, i);
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
}

/* Exact redundancy drops cone k, in ASCII order, when every cell of it
   is held by another cone still kept: by a kept cone before k or by any
   cone after k (all of them are still there).  So only the cells whose
   last cone is k can make k needed, and k is needed iff one of them is
   in no cone kept before it.  Each cone is computed once, from the last
   to the first, to find the cells it is the last of (those not seen yet:
   disjoint, so at most ncells entries), and again only when it is kept,
   to add its cells to the union of the kept cones.  */
typedef struct
{
    slong count, words, ncells;
    _wc_plan_bits_fn cells;
    void * ctx;
    ulong * buf;            /* the current cone's cells */
    ulong * seen;           /* the cells of the cones after it, then
                               those of the kept cones before it */
    slong * word;           /* the cells whose last cone is k: bits[e] */
    ulong * bits;           /* of word word[e], off[k + 1] <= e < off[k] */
    slong * off;            /* count + 1 */
}
members;

/* The bits of word w that are cells: all but in the last word.  */
static ulong
valid(const members * M, slong w)
{
    slong n = M->ncells - w * FLINT_BITS;

    return n >= FLINT_BITS ? ~UWORD(0) : (UWORD(1) << n) - 1;
}

/* M->seen := the cells of every cone, and for every cone k the cells it
   is the last of: the entries word[e], bits[e] for off[k + 1] <= e <
   off[k].  Bits past the last cell are not cells: masked off.  */
static void
members_last(members * M)
{
    slong k, w, e = 0, left = M->words;     /* words not all seen */

    M->off[M->count] = 0;
    /* once every cell is seen (often soon: a cone late in ASCII order
       holds them all), the cones before are the last of none */
    for (k = M->count - 1; k >= 0 && left != 0; k--)
    {
        M->cells(M->buf, k, M->ctx);
        for (w = 0; w < M->words; w++)
        {
            ulong x = M->buf[w] & ~M->seen[w] & valid(M, w);

            if (x != 0)
            {
                M->word[e] = w;
                M->bits[e++] = x;
                M->seen[w] |= x;
                left -= (M->seen[w] | ~valid(M, w)) == ~UWORD(0);
            }
        }
        M->off[k] = e;
    }
    for (; k >= 0; k--)
        M->off[k] = e;
}

/* 1 when cone k is exactly needed: a cell whose last cone is k is in no
   kept cone before it (M->seen, the union of those, then gets k's).  */
static int
members_keep(members * M, slong k)
{
    slong e, w;

    for (e = M->off[k + 1]; e < M->off[k]; e++)
        if ((M->bits[e] & ~M->seen[M->word[e]]) != 0)
            break;
    if (e == M->off[k])
        return 0;
    M->cells(M->buf, k, M->ctx);
    for (w = 0; w < M->words; w++)
        M->seen[w] |= M->buf[w];
    return 1;
}

int
_wc_plan_exact(int * exact, ulong * any, slong count, slong ncells,
               _wc_plan_bits_fn cells, void * ctx)
{
    members M;
    slong k, n = ncells + 1;
    int ok;

    M.count = count;
    M.ncells = ncells;
    M.words = (ncells + FLINT_BITS - 1) / FLINT_BITS;
    M.cells = cells;
    M.ctx = ctx;
    M.buf = malloc(sizeof(ulong) * (M.words + 1));
    M.seen = calloc(M.words + 1, sizeof(ulong));
    M.word = malloc(sizeof(slong) * n);
    M.bits = malloc(sizeof(ulong) * n);
    M.off = malloc(sizeof(slong) * (count + 1));
    ok = M.buf != NULL && M.seen != NULL && M.word != NULL && M.bits != NULL
        && M.off != NULL;
    if (ok)
    {
        members_last(&M);
        memcpy(any, M.seen, sizeof(ulong) * M.words);
        memset(M.seen, 0, sizeof(ulong) * M.words);
        for (k = 0; k < count; k++)
            exact[k] = members_keep(&M, k);
    }
    free(M.buf);
    free(M.seen);
    free(M.word);
    free(M.bits);
    free(M.off);
    return ok;
}

/* The needed cones' cells for _wc_plan_exact (cellbits.c).  */
typedef struct
{
    wc_cone_key * keys;
    wc_cell_bits X;
    const wc_cells_struct * A;
}
needed_ctx;

static void
needed_cells(ulong * out, slong k, void * p)
{
    needed_ctx * c = p;

    _wc_cone_key_cells(out, c->keys + k, &c->X, c->A);
}

/* Membership of every cell in every needed cone: goal[i] (malloc'd into
   *goalp) when cell i is in none, i.e. in G_goal; the needed cones that
   are exactly needed; eq. 25; and R->goal as a set.  */
static int
plan_goal(wc_plan_t R, int ** goalp, wc_error_t err)
{
    slong nn = R->T->nneeded, ncells = R->cells->count, i, k;
    int * goal = *goalp = malloc(sizeof(int) * (ncells + 1));
    ulong * any = malloc(sizeof(ulong) * (ncells / FLINT_BITS + 1));
    needed_ctx c;
    int status = WC_OK, ok;
    fmpq g[3];

    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    c.A = R->cells;
    c.keys = _wc_cone_keys_init(R->cones, nn, R->cells);
    ok = _wc_cell_bits_init(&c.X, R->cells);
    R->exact_needed = malloc(sizeof(int) * (nn + 1));
    if (!ok || goal == NULL || any == NULL || R->exact_needed == NULL
        || c.keys == NULL
        || !_wc_plan_exact(R->exact_needed, any, nn, ncells, needed_cells,
                           &c))
    {
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "out of memory (%ld cells, %ld cones)",
                              (long) ncells, (long) nn);
        goto cleanup;
    }
    for (i = 0; i < ncells; i++)
        goal[i] = ((any[i / FLINT_BITS] >> (i % FLINT_BITS)) & 1) == 0;
    for (R->nexact = k = 0; k < nn; k++)
        R->nexact += R->exact_needed[k];

    plan_eq25(R, goal, g);
    if ((status = wc_set_from_cells(R->goal, R->cells, goal, err)) == WC_OK)
        status = wc_set_merge(R->goal, R->cells, err);
cleanup:
    free(any);
    _wc_cell_bits_clear(&c.X);
    _wc_cone_keys_clear(c.keys, nn);
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    return status;
}

/* obits := the cells of each outcome cone (X->words words per cone).  */
static int
outcome_bits(ulong ** obits, slong * words, const wc_plan_t R)
{
    wc_cone_key * okeys = _wc_cone_keys_init(R->outcomes, R->noutcomes,
                                             R->cells);
    wc_cell_bits X;
    slong k;
    int ok = _wc_cell_bits_init(&X, R->cells);

    *words = X.words;
    if (ok)
        *obits = malloc(sizeof(ulong) * ((size_t) X.words * R->noutcomes
                                         + 1));
    ok = ok && *obits != NULL && okeys != NULL;
    for (k = 0; k < R->noutcomes && ok; k++)
        _wc_cone_key_cells(*obits + k * X.words, okeys + k, &X, R->cells);
    _wc_cell_bits_clear(&X);
    _wc_cone_keys_clear(okeys, R->noutcomes);
    return ok;
}

/* The complete plan: R->accepted, the cells whose outcomes make a graph
   the plan accepts, and R->extra, one of them outside G_goal.  */
static int
plan_accepted(wc_plan_t R, const wc_problem_t P, const int * goal,
              wc_error_t err)
{
    slong ncells = R->cells->count, full = (slong) 1 << P->n, i, k, words;
    unsigned char * member = malloc((size_t) R->noutcomes + 1);
    ulong * adj = malloc(sizeof(ulong) * full);
    int * acc = malloc(sizeof(int) * (ncells + 1));
    ulong * obits = NULL;
    int status = WC_OK;

    if (member == NULL || adj == NULL || acc == NULL
        || !outcome_bits(&obits, &words, R))
    {
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "out of memory");
        goto cleanup;
    }
    R->has_extra = 0;
    for (i = 0; i < ncells; i++)
    {
        for (k = 0; k < R->noutcomes; k++)
            member[k] = (unsigned char)
                ((obits[k * words + i / FLINT_BITS] >> (i % FLINT_BITS)) & 1);
        memset(adj, 0, sizeof(ulong) * full);
        _wc_plan_transitions(P->n, member, _wc_plan_add_adj, adj);
        acc[i] = _wc_plan_graph_verdict(adj, P->n, NULL, NULL)
            == WC_PLAN_ACCEPTED;
        if (acc[i] && !goal[i])
        {
            /* cells come by dimension: keep the last, a chamber if any */
            R->has_extra = 1;
            _wc_cellset_point(R->extra, R->cells, i);
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
        == WC_OK)
        status = wc_set_merge(R->accepted, R->cells, err);
cleanup:
    free(obits);
    free(acc);
    free(member);
    free(adj);
    return status;
}

int
wc_plan(wc_plan_t R, const wc_problem_t P, int complete, wc_error_t err)
{
    int * goal = NULL;
    int status;

    wc_plan_clear(R);
    wc_plan_init(R);
    if ((status = _wc_plan_check_size(P, complete, err)) != WC_OK)
        return status;
    if ((status = plan_cells(R, P, complete, err)) != WC_OK
        || (status = plan_goal(R, &goal, err)) != WC_OK
        || (complete && (status = plan_accepted(R, P, goal, err)) != WC_OK))
        goto cleanup;
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
    free(goal);
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
    _wc_plan_outcome_string(W->via[W->nedges], outcome, W->n);
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
    if ((status = _wc_plan_check_size(P, complete, err)) != WC_OK)
        return status;
    W->n = P->n;
    for (k = 0; k < 3; k++)
        fmpq_set(W->g + k, g + k);
    wc_plan_strings_init(T);
    if ((status = wc_plan_strings(T, P->n, err)) != WC_OK)
        goto cleanup;
    C = _wc_plan_cones_init(count = T->nneeded);
    if ((status = _wc_plan_needed_cones(C, T, P, err)) != WC_OK)
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

        _wc_plan_cones_clear(C, count);
        count = _wc_plan_pow3(P->n);
        C = _wc_plan_cones_init(count);
        if ((status = _wc_plan_outcome_cones(C, count, P, err)) != WC_OK)
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
        _wc_plan_transitions(P->n, member, add_edge, &c);
        W->complete = 1;
        W->cycle = malloc(sizeof(ulong) * (nst + 1));
        W->verdict = _wc_plan_graph_verdict(adj, P->n, W->cycle, &W->ncycle);
        if (W->in_goal && W->verdict != WC_PLAN_ACCEPTED)
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: a wrench of G_goal is "
                                  "rejected by the complete plan");
    }

cleanup:
    _wc_plan_cones_clear(C, count);
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

