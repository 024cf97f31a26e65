/* box.c -- sign boxes: the pieces of a union of cells, and their cones.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A set is a union of cells, given by member flags, and its pieces are
   sign boxes.  Both steps below keep every box exactly the union of the
   member cells whose sign vectors it holds, so that the boxes are
   pairwise disjoint and cover the set.

   Top-down: the tightest box holding the members (per plane, the signs
   they take) is a piece when it holds no non-member cell; else the
   members are split along one plane, between two convex parts of their
   signs there, and each part is treated alike.  A set that is itself a
   box (the whole space, any convex cone cut out by planes of the
   arrangement) thus comes out as one piece, and the split planes are
   chosen among the walls of the set, so that a set bounded by a few
   planes usually comes out as a few pieces.  This costs O(m) per cell
   and level.

   Bottom-up: boxes that agree on all planes but one, where their sign
   sets are disjoint with a convex union, merge (their union is the box
   with the union of their sets), plane after plane until a round over
   all planes merges nothing.  Started from the cells alone, this rule
   gets stuck: after a merge along p a box remembers whether p cut it,
   and boxes that differ in two planes never merge (on random
   arrangements, all the cells came out as one piece about once in nine,
   and a convex cone's cells in up to 79 pieces).  After the top-down
   step it still joins some pieces.  A box hashes as a sum of one random
   word per (plane, set), so the hash with a plane left out costs O(1)
   and a round costs O(m) per box.  */

#include <config.h>

#include <stdint.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_mat.h>

#include "exact/vec3.h"
#include "exact/hash.h"
#include "exact/box.h"

/* Sign sets on one plane, as bit masks: bit 0 for -, 1 for 0, 2 for +.
   5 = {-, +} is the only nonempty set that is not convex.  */
#define SET_ALL 7
#define SET_BAD 5

void
_wc_box_list_init(_wc_box_list_t B, const wc_cells_t A)
{
    slong m = A->nplanes, i;

    B->m = m;
    B->n = 0;
    B->alloc = 16;
    B->set = flint_malloc(B->alloc * m);
    B->hash = flint_malloc(sizeof(uint64_t) * B->alloc);
    B->head = flint_malloc(sizeof(slong) * B->alloc);
    B->tail = flint_malloc(sizeof(slong) * B->alloc);
    B->link = flint_malloc(sizeof(slong) * (A->count + 1));
    B->word = flint_malloc(sizeof(uint64_t) * 8 * m);
    for (i = 0; i < 8 * m; i++)
        B->word[i] = _wc_hash_mix64(UINT64_C(0x243f6a8885a308d3)
                                    + (uint64_t) i);
    B->alive = NULL;
    B->nalive = 0;
}

void
_wc_box_list_clear(_wc_box_list_t B)
{
    flint_free(B->set);
    flint_free(B->hash);
    flint_free(B->head);
    flint_free(B->tail);
    flint_free(B->link);
    flint_free(B->word);
    flint_free(B->alive);
}

/* A new box with sets T holding the member cells among idx[0 .. len).  */
static void
box_list_add(_wc_box_list_struct * B, const unsigned char * T,
             const slong * idx, slong len, const int * member)
{
    slong m = B->m, b = B->n, i, q;

    if (b == B->alloc)
    {
        B->alloc *= 2;
        B->set = flint_realloc(B->set, B->alloc * m);
        B->hash = flint_realloc(B->hash, sizeof(uint64_t) * B->alloc);
        B->head = flint_realloc(B->head, sizeof(slong) * B->alloc);
        B->tail = flint_realloc(B->tail, sizeof(slong) * B->alloc);
    }
    memcpy(B->set + b * m, T, m);
    B->hash[b] = 0;
    for (q = 0; q < m; q++)
        B->hash[b] += B->word[8 * q + T[q]];
    B->head[b] = B->tail[b] = -1;
    for (i = 0; i < len; i++)
        if (member[idx[i]])
        {
            if (B->tail[b] < 0)
                B->head[b] = idx[i];
            else
                B->link[B->tail[b]] = idx[i];
            B->tail[b] = idx[i];
            B->link[idx[i]] = -1;
        }
    B->n++;
}

/* Merge along plane p every group of boxes equal off p whose sets on p
   unite to a convex set.  tab (size slots, a power of two, at least twice
   nalive), next and last: scratch.  Returns the number of merges.  */
static slong
merge_plane(_wc_box_list_struct * B, slong p, slong * tab, slong size,
            slong * next, slong * last)
{
    slong m = B->m, i, j, c, merged = 0;

    for (i = 0; i < size; i++)
        tab[i] = -1;
    for (i = 0; i < B->nalive; i++)
    {
        slong b = B->alive[i];
        const unsigned char * sb = B->set + b * m;
        uint64_t h = B->hash[b] - B->word[8 * p + sb[p]];

        next[b] = -1;
        last[b] = b;
        for (j = (slong) (h & (size - 1)); tab[j] >= 0;
             j = (j + 1) & (size - 1))
        {
            slong g = tab[j];
            const unsigned char * sg = B->set + g * m;

            if (B->hash[g] - B->word[8 * p + sg[p]] == h
                && memcmp(sb, sg, p) == 0
                && memcmp(sb + p + 1, sg + p + 1, m - p - 1) == 0)
                break;
        }
        if (tab[j] < 0)
            tab[j] = b;
        else
        {
            slong g = tab[j];

            next[last[g]] = b;
            last[g] = b;
            last[b] = -2;       /* not a group's first box */
        }
    }

    /* Merge each group into its first box: at most three boxes, with
       disjoint sets on p (the boxes are disjoint and tight: a sign on p
       shared by two of them would be a cell's, in both); two or three
       boxes with disjoint sets merge pairwise, in some order, into their
       union unless that is {-, +}.  */
    for (i = 0; i < B->nalive; i++)
    {
        slong b = B->alive[i], g;
        unsigned char u = 0;
        int overlap = 0;

        if (last[b] == -2 || next[b] < 0)
            continue;
        for (g = b; g >= 0; g = next[g])
        {
            overlap |= (u & B->set[g * m + p]) != 0;
            u |= B->set[g * m + p];
        }
        if (u == SET_BAD || overlap)
            continue;
        B->hash[b] += B->word[8 * p + u] - B->word[8 * p + B->set[b * m + p]];
        B->set[b * m + p] = u;
        for (g = next[b]; g >= 0; g = next[g])
        {
            B->link[B->tail[b]] = B->head[g];
            B->tail[b] = B->tail[g];
            last[g] = -3;       /* gone */
            merged++;
        }
    }
    for (i = 0, c = 0; i < B->nalive; i++)
        if (last[B->alive[i]] != -3)
            B->alive[c++] = B->alive[i];
    B->nalive = c;
    return merged;
}

/* The tightest box holding a list of cells: per plane, the signs they
   take.  */
static void
tight_box(unsigned char * T, const wc_cells_t A, const slong * idx,
          slong len, const int * member)
{
    slong m = A->nplanes, i, q;

    memset(T, 0, m);
    for (i = 0; i < len; i++)
        if (member[idx[i]])
            for (q = 0; q < m; q++)
                T[q] |= (unsigned char) (1 << (_wc_cells_sign(A, idx[i], q)
                                               + 1));
}

/* 1 when cell i lies in the box T.  */
static int
in_box(const unsigned char * T, const wc_cells_t A, slong i)
{
    slong q;

    for (q = 0; q < A->nplanes; q++)
        if (!(T[q] & (1 << (_wc_cells_sign(A, i, q) + 1))))
            return 0;
    return 1;
}

/* The scratch of the top-down split.  */
typedef struct
{
    const wc_cells_struct * A;
    const int * member;
    _wc_incidence_struct * I;
    slong * idx;            /* count: the cells, regions as ranges */
    slong * tmp;            /* count */
    slong * stack;          /* 2 (count + 1): ranges to do */
    slong * cm;             /* 3 m: members by plane and sign */
    slong * cb;             /* 3 m: non-members alike */
    slong * wall;           /* m */
    slong * cp;             /* m: candidate planes */
    slong * mark;           /* count: cells of the current region, with
                               I */
    slong stamp;
    unsigned char * T;      /* m: the current tight box */
}
splitter;

static void
splitter_init(splitter * S, _wc_incidence_struct * I, const wc_cells_t A,
              const int * member)
{
    slong m = A->nplanes, count = A->count, i;

    S->A = A;
    S->member = member;
    S->I = I;
    S->idx = flint_malloc(sizeof(slong) * (count + 1));
    S->tmp = flint_malloc(sizeof(slong) * (count + 1));
    S->stack = flint_malloc(sizeof(slong) * 2 * (count + 1));
    S->cm = flint_malloc(sizeof(slong) * (3 * m + 1));
    S->cb = flint_malloc(sizeof(slong) * (3 * m + 1));
    S->wall = flint_malloc(sizeof(slong) * (m + 1));
    S->cp = flint_malloc(sizeof(slong) * (m + 1));
    S->mark = NULL;
    S->stamp = 0;
    S->T = flint_malloc(m + 1);
    for (i = 0; i < count; i++)
        S->idx[i] = i;
}

static void
splitter_clear(splitter * S)
{
    flint_free(S->idx);
    flint_free(S->tmp);
    flint_free(S->stack);
    flint_free(S->cm);
    flint_free(S->cb);
    flint_free(S->wall);
    flint_free(S->cp);
    flint_free(S->mark);
    flint_free(S->T);
}

/* Walls of the region idx[lo .. hi): a chamber and a sector beside it,
   one a member and the other not, both in the region, are separated by
   the sector's plane.  Failing those, a sector and a ray on its boundary,
   separated by the planes through the ray but the sector's.  S->wall[q]
   counts them; returns the number of planes with walls.  */
static slong
find_walls(splitter * S, slong lo, slong hi)
{
    const wc_cells_struct * A = S->A;
    const _wc_incidence_struct * I = S->I;
    const int * member = S->member;
    slong m = A->nplanes, walls = 0, i, q;

    S->stamp++;
    for (i = lo; i < hi; i++)
        S->mark[S->idx[i]] = S->stamp;
    memset(S->wall, 0, sizeof(slong) * m);
    for (i = lo; i < hi; i++)
    {
        slong c = S->idx[i], k;

        for (k = 0; k < 2 && I->plane[c] >= 0; k++)
        {
            slong e = I->side[2 * c + k];

            if (S->mark[e] == S->stamp
                && (member[e] != 0) != (member[c] != 0))
            {
                walls += S->wall[I->plane[c]] == 0;
                S->wall[I->plane[c]]++;
            }
        }
    }
    for (i = lo; i < hi && walls == 0; i++)
    {
        slong c = S->idx[i], k;

        for (k = I->off[c]; k < I->off[c + 1]; k++)
        {
            slong e = I->around[k];

            if (S->mark[e] != S->stamp
                || (member[e] != 0) == (member[c] != 0))
                continue;
            for (q = 0; q < m; q++)
                if (_wc_cells_sign(A, c, q) == 0 && q != I->plane[e])
                    S->wall[q]++;
        }
    }
    for (q = 0; q < m && walls == 0; q++)
        walls += S->wall[q] > 0;
    return walls;
}

/* The plane to split the region idx[lo .. hi) along (nm members, nb
   non-members, all in the box S->T), and through *part the sign set
   that goes first.  */
static slong
best_split(unsigned char * part, splitter * S, slong lo, slong hi,
           slong nm, slong nb, slong walls)
{
    const unsigned char * T = S->T;
    slong m = S->A->nplanes, p = -1, bp = -1, bmis = 0, ncp, i, j, q;

    /* Members and non-members by sign on the candidate planes: the walls
       (else all), where the members take two signs or more.  */
    for (q = 0, ncp = 0; q < m; q++)
        if ((walls == 0 || S->wall[q] > 0)
            && T[q] != 1 && T[q] != 2 && T[q] != 4)
            S->cp[ncp++] = q;
    memset(S->cm, 0, sizeof(slong) * 3 * m);
    memset(S->cb, 0, sizeof(slong) * 3 * m);
    for (i = lo; i < hi; i++)
    {
        slong * c3 = S->member[S->idx[i]] ? S->cm : S->cb;

        for (j = 0; j < ncp; j++)
            c3[3 * S->cp[j] + _wc_cells_sign(S->A, S->idx[i], S->cp[j])
               + 1]++;
    }
    for (j = 0; j < ncp; j++)
    {
        unsigned char cand[2];
        slong nc = 0, k;

        q = S->cp[j];
        if (T[q] == SET_ALL)
        {
            cand[nc++] = 1;     /* {-} | {0, +} */
            cand[nc++] = 3;     /* {-, 0} | {+} */
        }
        else if (T[q] == 3)
            cand[nc++] = 1;     /* {-} | {0} */
        else if (T[q] == 6)
            cand[nc++] = 2;     /* {0} | {+} */
        for (k = 0; k < nc; k++)
        {
            slong m1 = 0, b1 = 0, m2, b2, pure, mis, s;

            for (s = 0; s < 3; s++)
                if (cand[k] & (1 << s))
                {
                    m1 += S->cm[3 * q + s];
                    b1 += S->cb[3 * q + s];
                }
            m2 = nm - m1;
            b2 = nb - b1;
            pure = (b1 == 0 ? m1 : 0) + (b2 == 0 ? m2 : 0);
            mis = FLINT_MIN(m1, b1) + FLINT_MIN(m2, b2);
            if (p < 0 || pure > bp || (pure == bp && mis < bmis))
            {
                p = q;
                *part = cand[k];
                bp = pure;
                bmis = mis;
            }
        }
    }
    return p;
}

/* Top-down: the member cells of a region (a node: a range of idx, with
   the non-members of the region that might matter) go into the tightest
   box T holding them.  When T holds no non-member, T is a piece: it is
   exactly the union of the member cells in it.  Otherwise the region is
   split along one plane p into two convex parts of T's sign set on p, so
   that every member goes to one part and each part holds fewer members.
   The plane is a wall of the set, when there is one: it holds one of two
   incident cells of the region (a sector and a chamber beside it, else a
   ray and a sector around it) but not the other, one a member and the
   other not; cutting along other planes only cuts pieces apart.  The
   plane and the parts are chosen to leave as many members as possible in
   parts without non-members, then to leave the fewest cells of the
   minority kind in each part.  The pieces go to B; I is set up when
   needed (I->plane != NULL then).  Returns 0 when A is inconsistent.  */
static int
split_boxes(_wc_box_list_struct * B, _wc_incidence_struct * I,
            const wc_cells_t A, const int * member)
{
    slong m = A->nplanes, i, q, top = 0;
    splitter S;
    int ok = 1;

    splitter_init(&S, I, A, member);
    S.stack[top++] = 0;
    S.stack[top++] = A->count;
    while (top > 0 && ok)
    {
        slong hi = S.stack[--top], lo = S.stack[--top], nb = 0;
        slong p = -1, n1 = 0, n2 = 0, c;
        unsigned char part = 0;
        const unsigned char * T = S.T;

        tight_box(S.T, A, S.idx + lo, hi - lo, member);
        for (q = 0; q < m && p < 0; q++)
            if (T[q] == SET_BAD)
            {
                p = q;          /* T is no box: split into - and + */
                part = 1;
            }
        if (p < 0)
        {
            /* The non-members in T.  */
            for (i = lo, c = lo; i < hi; i++)
                if (member[S.idx[i]] || in_box(T, A, S.idx[i]))
                {
                    nb += !member[S.idx[i]];
                    S.idx[c++] = S.idx[i];
                }
            hi = c;
            if (nb == 0)
            {
                box_list_add(B, T, S.idx + lo, hi - lo, member);
                continue;
            }
            if (I->plane == NULL)
            {
                ok = _wc_incidence_build(I, A);
                S.mark = flint_calloc(A->count + 1, sizeof(slong));
                if (!ok)
                    break;
            }
            p = best_split(&part, &S, lo, hi, hi - lo - nb, nb,
                           find_walls(&S, lo, hi));
        }

        /* Split: part first, the rest of T's set on p next; cells with
           other signs on p are non-members and go.  */
        for (i = lo; i < hi; i++)
        {
            int bit = 1 << (_wc_cells_sign(A, S.idx[i], p) + 1);

            c = S.idx[i];
            if (part & bit)
                S.idx[lo + n1++] = c;
            else if (T[p] & bit)
                S.tmp[n2++] = c;
        }
        memcpy(S.idx + lo + n1, S.tmp, sizeof(slong) * n2);
        S.stack[top++] = lo + n1;
        S.stack[top++] = lo + n1 + n2;
        S.stack[top++] = lo;
        S.stack[top++] = lo + n1;
    }
    splitter_clear(&S);
    return ok;
}

int
_wc_box_list_build(_wc_box_list_t B, _wc_incidence_t I, const wc_cells_t A,
                   const int * member)
{
    slong m = B->m, n, i, q, since, size;
    slong * tab, * next, * last;

    if (!split_boxes(B, I, A, member))
        return 0;
    n = B->n;
    flint_free(B->alive);
    B->alive = flint_malloc(sizeof(slong) * (n + 1));
    B->nalive = n;
    for (i = 0; i < n; i++)
        B->alive[i] = i;
    size = _wc_hash_size(2 * n + 2);
    tab = flint_malloc(sizeof(slong) * size);
    next = flint_malloc(sizeof(slong) * (n + 1));
    last = flint_malloc(sizeof(slong) * (n + 1));
    for (q = 0, since = 0; since < m && B->nalive > 1; q = (q + 1) % m)
    {
        if (merge_plane(B, q, tab, size, next, last) > 0)
            since = 0;
        else
            since++;
    }
    flint_free(tab);
    flint_free(next);
    flint_free(last);
    return 1;
}

/* Rows for a box: h_q for the sets {-, 0} (non-strict) and {-}
   (strict), -h_q for {0, +} and {+}, h_q as an equality for {0}; all
   others constrain nothing.  */
static void
direct_rows(fmpq_mat_t E, fmpq_mat_t I, fmpq_mat_t S, const wc_cells_t A,
            const unsigned char * set)
{
    slong m = A->nplanes, q, ne = 0, ni = 0, ns = 0, j;

    for (q = 0; q < m; q++)
    {
        ne += set[q] == 2;
        ni += set[q] == 3 || set[q] == 6;
        ns += set[q] == 1 || set[q] == 4;
    }
    fmpq_mat_clear(E);
    fmpq_mat_clear(I);
    fmpq_mat_clear(S);
    fmpq_mat_init(E, ne, 3);
    fmpq_mat_init(I, ni, 3);
    fmpq_mat_init(S, ns, 3);
    ne = ni = ns = 0;
    for (q = 0; q < m; q++)
    {
        fmpq_mat_struct * M;
        slong r;
        int neg = set[q] == 6 || set[q] == 4;

        if (set[q] == 2)
            M = E, r = ne++;
        else if (set[q] == 3 || set[q] == 6)
            M = I, r = ni++;
        else if (set[q] == 1 || set[q] == 4)
            M = S, r = ns++;
        else
            continue;
        for (j = 0; j < 3; j++)
        {
            fmpq_set_fmpz(fmpq_mat_entry(M, r, j),
                          fmpz_mat_entry(A->planes, q, j));
            if (neg)
                fmpq_neg(fmpq_mat_entry(M, r, j), fmpq_mat_entry(M, r, j));
        }
    }
}

static void
fmpz_mat_to_fmpq_mat(fmpq_mat_t out, const fmpz_mat_t A)
{
    fmpq_mat_clear(out);
    fmpq_mat_init(out, fmpz_mat_nrows(A), fmpz_mat_ncols(A));
    if (fmpz_mat_nrows(A) > 0)
        fmpq_mat_set_fmpz_mat(out, A);
}

/* The planes constraining a box (cons, nn of them) and its closed sets;
   returns 1 when their normals span R^3.  */
static int
constraints(slong * cons, slong * nn, unsigned char * closed,
            const wc_cells_t A, const unsigned char * set)
{
    slong m = A->nplanes, q, i;
    fmpz * c = _fmpz_vec_init(3);
    fmpz_t t;
    int pointed = 0;

    fmpz_init(t);
    *nn = 0;
    for (q = 0; q < m; q++)
    {
        closed[q] = set[q] | ((set[q] & SET_BAD) ? 2 : 0);
        if (set[q] != SET_ALL)
            cons[(*nn)++] = q;
    }
    if (*nn >= 3)
    {
        _wc_zvec3_cross(c, WC_ROW(A->planes, cons[0]),
                        WC_ROW(A->planes, cons[1]));
        for (i = 2; i < *nn && !pointed; i++)
            pointed = _wc_zvec3_dot_sgn(WC_ROW(A->planes, cons[i]), c, t) != 0;
    }
    _fmpz_vec_clear(c, 3);
    fmpz_clear(t);
    return pointed;
}

/* R := the extreme rays of the closure: the ray cells among cand in the
   closed box on at least two constraining planes.  At most m of them;
   returns their number, or -1 when there are more.  */
static slong
extreme_rays(fmpq_mat_t R, const wc_cells_t A, const unsigned char * closed,
             const slong * cons, slong nn, const slong * cand, slong nc)
{
    slong m = A->nplanes, ne = 0, i, j, k, q;
    slong * ext = flint_malloc(sizeof(slong) * (m + 1));

    for (k = 0; k < nc && ne >= 0; k++)
    {
        slong z = 0;

        for (j = 0; j < nn; j++)
        {
            int sq = _wc_cells_sign(A, cand[k], cons[j]);

            q = cons[j];
            if (!(closed[q] & (1 << (sq + 1))))
                break;
            z += sq == 0;
        }
        if (j == nn && z >= 2)
        {
            if (ne == m)
                ne = -1;
            else
                ext[ne++] = cand[k];
        }
    }
    fmpq_mat_clear(R);
    fmpq_mat_init(R, FLINT_MAX(ne, 0), 3);
    for (i = 0; i < ne; i++)
        for (j = 0; j < 3; j++)
            fmpq_set_fmpz(fmpq_mat_entry(R, i, j),
                          fmpz_mat_entry(A->point, ext[i], j));
    flint_free(ext);
    return ne;
}

/* S := the strict planes of a box whose closure is C0: one for each
   maximal set of closure rays they vanish on (a face of the closure lies
   on a strict plane iff its rays do).  */
static void
strict_rows(fmpq_mat_t S, const wc_cells_t A, const unsigned char * set,
            const wc_cone_t C0)
{
    slong m = A->nplanes, k = fmpz_mat_nrows(C0->rays);
    slong words = k / FLINT_BITS + 1, ns = 0, i, j, q;
    slong * st = flint_malloc(sizeof(slong) * (m + 1));
    ulong * bits;
    int * keep;
    fmpz_t t;

    fmpz_init(t);
    for (q = 0; q < m; q++)
        if (set[q] == 1 || set[q] == 4)
            st[ns++] = q;
    bits = flint_calloc(ns * words + 1, sizeof(ulong));
    keep = flint_malloc(sizeof(int) * (ns + 1));
    for (i = 0; i < ns; i++)
        for (j = 0; j < k; j++)
            if (_wc_zvec3_dot_sgn(WC_ROW(A->planes, st[i]),
                                  WC_ROW(C0->rays, j), t) == 0)
                bits[i * words + j / FLINT_BITS]
                    |= UWORD(1) << (j % FLINT_BITS);
    for (i = 0; i < ns; i++)
    {
        /* Drop i when some j vanishes on more rays, or on the same rays
           and comes first.  */
        keep[i] = 1;
        for (j = 0; j < ns && keep[i]; j++)
        {
            slong w;
            int sub = 1, same = 1;

            if (j == i)
                continue;
            for (w = 0; w < words; w++)
            {
                ulong a = bits[i * words + w], b = bits[j * words + w];

                sub &= (a & ~b) == 0;
                same &= a == b;
            }
            if (sub && (!same || j < i))
                keep[i] = 0;
        }
    }
    for (i = 0, j = 0; i < ns; i++)
        j += keep[i];
    fmpq_mat_clear(S);
    fmpq_mat_init(S, j, 3);
    for (i = 0, j = 0; i < ns; i++)
        if (keep[i])
        {
            slong e;

            for (e = 0; e < 3; e++)
            {
                fmpq_set_fmpz(fmpq_mat_entry(S, j, e),
                              fmpz_mat_entry(A->planes, st[i], e));
                if (set[st[i]] == 4)
                    fmpq_neg(fmpq_mat_entry(S, j, e), fmpq_mat_entry(S, j, e));
            }
            j++;
        }
    flint_free(st);
    flint_free(bits);
    flint_free(keep);
    fmpz_clear(t);
}

/* Each box becomes an NNC cone.  Its closure is the closed box (the box
   is nonempty), and when the planes constraining it span R^3, the closure
   is pointed and generated by its extreme rays: the rays of the
   arrangement in the closed box that lie on two constraining planes (two
   distinct planes through a point make its tight constraints rank 2).
   That gives the closure with only its facets; the strict rows are then
   needed only on the maximal faces they vanish on.  This keeps the exact
   conversion small when many planes constrain a box.  */
int
_wc_box_cone(wc_cone_t C, const wc_cells_t A, const unsigned char * set,
             const slong * cand, slong nc, wc_error_t err)
{
    slong m = A->nplanes, nn, ne;
    slong * cons = flint_malloc(sizeof(slong) * (m + 1));
    unsigned char * closed = flint_malloc(m + 1);
    fmpq_mat_t E, I, S, R;
    wc_cone_t C0;
    int status = WC_OK;

    fmpq_mat_init(E, 0, 3);
    fmpq_mat_init(I, 0, 3);
    fmpq_mat_init(S, 0, 3);
    fmpq_mat_init(R, 0, 3);
    wc_cone_init(C0, 3);
    if (!constraints(cons, &nn, closed, A, set))
        direct_rows(E, I, S, A, set);
    else if ((ne = extreme_rays(R, A, closed, cons, nn, cand, nc)) < 0)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "internal error: a sign box has more "
                              "extreme rays than planes");
    else if (ne == 0)
    {
        /* The closure is the origin, and so is the box.  */
        fmpq_mat_clear(E);
        fmpq_mat_init(E, 3, 3);
        fmpq_mat_one(E);
    }
    else if ((status = wc_cone_set_generators(C0, R, NULL, err)) == WC_OK)
    {
        fmpz_mat_to_fmpq_mat(E, C0->eqs);
        fmpz_mat_to_fmpq_mat(I, C0->ineqs);
        strict_rows(S, A, set, C0);
    }
    if (status == WC_OK)
        status = wc_cone_set_hrep(C, E, I, S, err);
    if (status == WC_OK && C->empty)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "internal error: a sign box with a member "
                              "cell came out empty");
    fmpq_mat_clear(E);
    fmpq_mat_clear(I);
    fmpq_mat_clear(S);
    fmpq_mat_clear(R);
    wc_cone_clear(C0);
    flint_free(cons);
    flint_free(closed);
    return status;
}
