/* ref-plan.c -- the test oracle for insertion plans: strings, G_goal and
   the complete model by brute force.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Every answer is computed the slowest obvious way, so that it can be
   trusted as a reference: the strings by looping over all pairs of
   bitmasks and comparing every pair of strings, membership by one exact LP
   per string, emptiness by visiting one point of every cell of a plane
   arrangement, found plane by plane with exact integer cross products, and
   the complete model by building its whole transition graph.  */

#include <stdlib.h>
#include <string.h>

#include <flint/flint.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpq.h>

#include "wrenchcone.h"
#include "ref-lp.h"
#include "ref-plan.h"

/* ---- strings ------------------------------------------------------- */

/* The strings list holds at most one entry per pair (S, L) plus one per
   S, so 3^n + 2^n bounds it; past n = 8 the pairwise filter would be slow
   for no test's benefit.  */
#define REF_PLAN_MAX_STRINGS_N 8
#define REF_PLAN_MAX_COMPLETE_N 10

static int
string_cmp(const void * a, const void * b)
{
    return strcmp(*(char * const *) a, *(char * const *) b);
}

/* 1 when W(a) lies in W(b) for syntactic reasons: at every position the
   letters agree, or a has s where b has u (W(u) holds W(s)).  */
static int
string_covered_by(const char * a, const char * b, slong n)
{
    slong i;

    for (i = 0; i < n; i++)
        if (b[i] != a[i] && !(a[i] == 's' && b[i] == 'u'))
            return 0;
    return 1;
}

/* A fresh string of n letters: in_L on L, in_S on S \ L, out_S off S
   (L a subset of S).  NULL when out of memory.  */
static char *
string_new(slong n, ulong S, ulong L, char in_L, char in_S, char out_S)
{
    char * x = malloc(n + 1);
    slong i;

    if (x == NULL)
        return NULL;
    for (i = 0; i < n; i++)
    {
        ulong bit = UWORD(1) << i;

        if (L & bit)
            x[i] = in_L;
        else if (S & bit)
            x[i] = in_S;
        else
            x[i] = out_S;
    }
    x[n] = '\0';
    return x;
}

void
ref_plan_strings_free(char ** strings, slong count)
{
    slong i;

    if (strings == NULL)
        return;
    for (i = 0; i < count; i++)
        free(strings[i]);
    free(strings);
}

char **
ref_plan_strings(slong * count, slong n, int needed_only)
{
    char ** all = NULL;
    char * redundant = NULL;
    slong len = 0, cap = 1, kept, i, j;
    ulong full, S, L;
    int ok = 0;

    *count = 0;
    if (n < 1 || n > REF_PLAN_MAX_STRINGS_N)
        return NULL;
    full = (UWORD(1) << n) - 1;
    for (i = 0; i < n; i++)
        cap *= 3;
    cap += full + 1;
    all = malloc(cap * sizeof(char *));
    if (all == NULL)
        goto cleanup;

    /* Contacts L lost from state S: s on L, m on S \ L, u off S.  The
       second family, m on S and s off S for S short of all fixels, repeats
       strings of the first (S' = all, L = the complement of S); it is
       generated anyway, as the definition says, and removed below.  */
    for (S = 0; S <= full; S++)
    {
        for (L = 1; L <= full; L++)
        {
            if ((L & ~S) != 0)
                continue;
            all[len] = string_new(n, S, L, 's', 'm', 'u');
            if (all[len] == NULL)
                goto cleanup;
            len++;
        }
        if (S != full)
        {
            all[len] = string_new(n, S, 0, 's', 'm', 's');
            if (all[len] == NULL)
                goto cleanup;
            len++;
        }
    }

    qsort(all, len, sizeof(char *), string_cmp);
    kept = 0;
    for (i = 0; i < len; i++)
    {
        if (kept > 0 && strcmp(all[kept - 1], all[i]) == 0)
            free(all[i]);
        else
            all[kept++] = all[i];
    }
    for (i = kept; i < len; i++)
        all[i] = NULL;
    len = kept;

    if (needed_only)
    {
        /* Every pair, both ways: a string is dropped only when another,
           different one covers it.  The list is duplicate-free, so i != j
           means different strings.  */
        redundant = calloc(len > 0 ? len : 1, 1);
        if (redundant == NULL)
            goto cleanup;
        for (i = 0; i < len; i++)
            for (j = 0; j < len && !redundant[i]; j++)
                if (j != i && string_covered_by(all[i], all[j], n))
                    redundant[i] = 1;
        kept = 0;
        for (i = 0; i < len; i++)
        {
            if (redundant[i])
                free(all[i]);
            else
                all[kept++] = all[i];
        }
        for (i = kept; i < len; i++)
            all[i] = NULL;
        len = kept;
    }
    ok = 1;

cleanup:
    free(redundant);
    if (!ok)
    {
        ref_plan_strings_free(all, len);
        return NULL;
    }
    *count = len;
    return all;
}

/* ---- G_goal by LPs --------------------------------------------------- */

int
ref_plan_goal_contains(const wc_problem_t P, const fmpq * g)
{
    char ** x = NULL;
    slong count = 0, k;
    int status = -1, r;

    x = ref_plan_strings(&count, P->n, 1);
    if (x == NULL)
        goto cleanup;
    status = 1;
    for (k = 0; k < count; k++)
    {
        r = ref_wrench_in_cone(P, x[k], g);
        if (r != 0)
        {
            status = (r == 1) ? 0 : -1;
            break;
        }
    }

cleanup:
    ref_plan_strings_free(x, count);
    return status;
}

/* ---- integer vectors in R^3 ------------------------------------------ */

/* A growable list of integer 3-vectors, stored one after the other.  */
typedef struct
{
    slong len;
    slong alloc;
    fmpz * v;
}
vlist_struct;

typedef vlist_struct vlist_t[1];

static void
vlist_init(vlist_t L)
{
    L->len = 0;
    L->alloc = 0;
    L->v = NULL;
}

static void
vlist_clear(vlist_t L)
{
    slong i;

    for (i = 0; i < 3 * L->alloc; i++)
        fmpz_clear(L->v + i);
    flint_free(L->v);
    L->v = NULL;
    L->len = L->alloc = 0;
}

static fmpz *
vlist_entry(const vlist_t L, slong i)
{
    return L->v + 3 * i;
}

static int
vec_equal(const fmpz * a, const fmpz * b)
{
    return fmpz_equal(a + 0, b + 0) && fmpz_equal(a + 1, b + 1)
        && fmpz_equal(a + 2, b + 2);
}

static int
vec_is_zero(const fmpz * a)
{
    return fmpz_is_zero(a + 0) && fmpz_is_zero(a + 1) && fmpz_is_zero(a + 2);
}

/* Append v unless an equal vector is already there (linear search: the
   lists are a few hundred long at most).  */
static void
vlist_add_unique(vlist_t L, const fmpz * v)
{
    slong i;

    for (i = 0; i < L->len; i++)
        if (vec_equal(vlist_entry(L, i), v))
            return;
    if (L->len == L->alloc)
    {
        slong a = (L->alloc == 0) ? 16 : 2 * L->alloc;

        L->v = flint_realloc(L->v, 3 * a * sizeof(fmpz));
        for (i = 3 * L->alloc; i < 3 * a; i++)
            fmpz_init(L->v + i);
        L->alloc = a;
    }
    for (i = 0; i < 3; i++)
        fmpz_set(L->v + 3 * L->len + i, v + i);
    L->len++;
}

/* r = a x b; r may not alias a or b.  */
static void
vec_cross(fmpz * r, const fmpz * a, const fmpz * b)
{
    fmpz_mul(r + 0, a + 1, b + 2);
    fmpz_submul(r + 0, a + 2, b + 1);
    fmpz_mul(r + 1, a + 2, b + 0);
    fmpz_submul(r + 1, a + 0, b + 2);
    fmpz_mul(r + 2, a + 0, b + 1);
    fmpz_submul(r + 2, a + 1, b + 0);
}

static void
vec_dot(fmpz_t r, const fmpz * a, const fmpz * b)
{
    fmpz_mul(r, a + 0, b + 0);
    fmpz_addmul(r, a + 1, b + 1);
    fmpz_addmul(r, a + 2, b + 2);
}

/* Divide by the gcd of the entries, so that equal rays (planes) compare
   equal.  Zero stays zero.  */
static void
vec_primitive(fmpz * v)
{
    fmpz_t c;
    slong i;

    fmpz_init(c);
    fmpz_gcd(c, v + 0, v + 1);
    fmpz_gcd(c, c, v + 2);
    if (!fmpz_is_zero(c) && !fmpz_is_one(c))
        for (i = 0; i < 3; i++)
            fmpz_divexact(v + i, v + i, c);
    fmpz_clear(c);
}

/* A plane through the origin is its normal up to a nonzero factor: make
   it primitive with its first nonzero entry positive.  */
static void
vec_plane_normal(fmpz * v)
{
    slong i;

    vec_primitive(v);
    for (i = 0; i < 3; i++)
    {
        if (!fmpz_is_zero(v + i))
        {
            if (fmpz_sgn(v + i) < 0)
                for (i = 0; i < 3; i++)
                    fmpz_neg(v + i, v + i);
            return;
        }
    }
}

/* ---- G_goal emptiness by the cells of an arrangement ------------------ */

/* The cones of the needed strings, and where a found wrench goes.  */
typedef struct
{
    slong ncones;
    wc_cone_struct * cones;
    fmpq * point;       /* 3 entries, scratch */
}
cover_struct;

/* 1 when x lies in no cone (x is then left in C->point), else 0.  */
static int
uncovered(cover_struct * C, const fmpz * x)
{
    slong k, j;

    for (j = 0; j < 3; j++)
        fmpq_set_fmpz(C->point + j, x + j);
    for (k = 0; k < C->ncones; k++)
        if (wc_cone_contains(C->cones + k, C->point))
            return 0;
    return 1;
}

/* Which half of the plane (normal h) the direction d lies in, measuring
   angles from e towards f = h x e: 0 for angles in [0, pi), 1 for
   [pi, 2 pi).  d, e and f are orthogonal to h and nonzero.  */
static int
half_plane(const fmpz * d, const fmpz * e, const fmpz * f)
{
    fmpz_t s;
    int r;

    fmpz_init(s);
    vec_dot(s, d, f);
    if (fmpz_sgn(s) != 0)
        r = fmpz_sgn(s) < 0;
    else
    {
        vec_dot(s, d, e);
        r = fmpz_sgn(s) < 0;
    }
    fmpz_clear(s);
    return r;
}

/* Sign of (a x b) . h: positive when b is turned from a by less than pi
   counterclockwise about h.  */
static int
turn_sign(const fmpz * a, const fmpz * b, const fmpz * h)
{
    fmpz c[3];
    fmpz_t s;
    int r, j;

    for (j = 0; j < 3; j++)
        fmpz_init(c + j);
    fmpz_init(s);
    vec_cross(c, a, b);
    vec_dot(s, c, h);
    r = fmpz_sgn(s);
    for (j = 0; j < 3; j++)
        fmpz_clear(c + j);
    fmpz_clear(s);
    return r;
}

/* 1 when a comes strictly before b counterclockwise about h from e.  */
static int
ccw_before(const fmpz * a, const fmpz * b, const fmpz * h, const fmpz * e,
           const fmpz * f)
{
    int ha = half_plane(a, e, f), hb = half_plane(b, e, f);

    if (ha != hb)
        return ha < hb;
    return turn_sign(a, b, h) > 0;
}

/* Sort the directions (orthogonal to h, nonzero, distinct) by their angle
   about h, counterclockwise from the first one.  Insertion sort: exact
   comparisons only, and the lists are short.  */
static void
sort_by_angle(vlist_t dirs, const fmpz * h)
{
    fmpz e[3], f[3], tmp[3];
    slong i, k;
    int j;

    for (j = 0; j < 3; j++)
    {
        fmpz_init(e + j);
        fmpz_init(f + j);
        fmpz_init(tmp + j);
    }
    if (dirs->len == 0)
        goto cleanup;
    for (j = 0; j < 3; j++)
        fmpz_set(e + j, vlist_entry(dirs, 0) + j);
    vec_cross(f, h, e);
    for (i = 1; i < dirs->len; i++)
    {
        for (j = 0; j < 3; j++)
            fmpz_set(tmp + j, vlist_entry(dirs, i) + j);
        for (k = i; k > 0 && ccw_before(tmp, vlist_entry(dirs, k - 1), h, e, f);
             k--)
            for (j = 0; j < 3; j++)
                fmpz_set(vlist_entry(dirs, k) + j,
                         vlist_entry(dirs, k - 1) + j);
        for (j = 0; j < 3; j++)
            fmpz_set(vlist_entry(dirs, k) + j, tmp + j);
    }

cleanup:
    for (j = 0; j < 3; j++)
    {
        fmpz_clear(e + j);
        fmpz_clear(f + j);
        fmpz_clear(tmp + j);
    }
}

/* Visit every cell of the arrangement of the planes that lies in plane p
   (normal h), or touches it from either side: the rays of the lines
   p n q, the open sectors of p between consecutive rays, and a point on
   each side of every sector.  Returns 1 when some visited point is in no
   cone (left in C->point), 0 when all are covered, -1 when p meets no
   other plane (impossible once the coordinate planes are in).  */
static int
visit_plane(cover_struct * C, const vlist_t planes, slong p)
{
    const fmpz * h = vlist_entry(planes, p);
    vlist_t dirs;
    fmpz d[3], x[3], y[3];
    fmpz_t K, s;
    slong q, i, j, k;
    int status = -1;

    vlist_init(dirs);
    for (j = 0; j < 3; j++)
    {
        fmpz_init(d + j);
        fmpz_init(x + j);
        fmpz_init(y + j);
    }
    fmpz_init(K);
    fmpz_init(s);

    /* Both directions of every line p n q.  Planes are distinct up to
       scale, so the cross product of normals is never zero.  */
    for (q = 0; q < planes->len; q++)
    {
        if (q == p)
            continue;
        vec_cross(d, h, vlist_entry(planes, q));
        if (vec_is_zero(d))
            goto cleanup;
        vec_primitive(d);
        vlist_add_unique(dirs, d);
        for (j = 0; j < 3; j++)
            fmpz_neg(d + j, d + j);
        vlist_add_unique(dirs, d);
    }
    k = dirs->len;
    if (k < 2)
        goto cleanup;

    sort_by_angle(dirs, h);

    /* A nudge by h / K keeps the sign of every plane not zero at x
       (integer x): |q.h| / K < 1 <= |q.x|.  p itself turns to +-|h|^2.  */
    fmpz_zero(K);
    for (q = 0; q < planes->len; q++)
    {
        vec_dot(s, vlist_entry(planes, q), h);
        fmpz_abs(s, s);
        if (fmpz_cmp(s, K) > 0)
            fmpz_set(K, s);
    }
    fmpz_add_ui(K, K, 1);

    status = 0;
    for (i = 0; i < k && status == 0; i++)
    {
        const fmpz * a = vlist_entry(dirs, i);
        const fmpz * b = vlist_entry(dirs, (i + 1) % k);
        int side;

        if (uncovered(C, a))
        {
            status = 1;
            break;
        }

        /* The open sector from a counterclockwise to b: a + b when it is
           narrower than pi; else (a and b opposite, p holding one line)
           the direction a quarter turn from a, h x a.  */
        if (turn_sign(a, b, h) > 0)
            for (j = 0; j < 3; j++)
                fmpz_add(x + j, a + j, b + j);
        else
            vec_cross(x, h, a);
        if (uncovered(C, x))
        {
            status = 1;
            break;
        }

        /* The chambers on either side of the sector.  */
        for (side = -1; side <= 1; side += 2)
        {
            for (j = 0; j < 3; j++)
            {
                fmpz_mul(y + j, x + j, K);
                if (side > 0)
                    fmpz_add(y + j, y + j, h + j);
                else
                    fmpz_sub(y + j, y + j, h + j);
            }
            if (uncovered(C, y))
            {
                status = 1;
                break;
            }
        }
    }

cleanup:
    vlist_clear(dirs);
    for (j = 0; j < 3; j++)
    {
        fmpz_clear(d + j);
        fmpz_clear(x + j);
        fmpz_clear(y + j);
    }
    fmpz_clear(K);
    fmpz_clear(s);
    return status;
}

/* The planes of a cone's closure (facets and equalities) into planes.  */
static void
add_cone_planes(vlist_t planes, const wc_cone_t W)
{
    fmpz v[3];
    slong i, j, m;
    const fmpz_mat_struct * mats[2];

    for (j = 0; j < 3; j++)
        fmpz_init(v + j);
    mats[0] = W->ineqs;
    mats[1] = W->eqs;
    for (m = 0; m < 2; m++)
    {
        for (i = 0; i < fmpz_mat_nrows(mats[m]); i++)
        {
            for (j = 0; j < 3; j++)
                fmpz_set(v + j, fmpz_mat_entry(mats[m], i, j));
            if (vec_is_zero(v))
                continue;
            vec_plane_normal(v);
            vlist_add_unique(planes, v);
        }
    }
    for (j = 0; j < 3; j++)
        fmpz_clear(v + j);
}

int
ref_plan_goal_empty(const wc_problem_t P, fmpq * witness)
{
    char ** x = NULL;
    slong count = 0, ncones = 0, k, i, j;
    wc_problem_t Q;
    wc_error_t err;
    vlist_t planes;
    cover_struct C;
    fmpz v[3];
    fmpq pt[3];
    int status = -1, r, found = 0;

    wc_problem_init(Q);
    wc_error_init(err);
    vlist_init(planes);
    for (j = 0; j < 3; j++)
    {
        fmpz_init(v + j);
        fmpq_init(pt + j);
    }
    C.ncones = 0;
    C.cones = NULL;
    C.point = pt;

    x = ref_plan_strings(&count, P->n, 1);
    if (x == NULL)
        goto cleanup;
    if (wc_problem_set(Q, P) != WC_OK)
        goto cleanup;
    C.cones = flint_malloc(count * sizeof(wc_cone_struct));
    for (k = 0; k < count; k++)
        wc_cone_init(C.cones + k, 3);
    ncones = count;

    /* The paper's route wants m on touching fixels and a, u on near ones;
       s is allowed either way and the cone does not depend on the state
       (Table 2 gives s the same row in both).  */
    for (k = 0; k < count; k++)
    {
        for (i = 0; i < Q->n; i++)
        {
            if (x[k][i] == 'm')
                Q->fixels[i].state = WC_TOUCHING;
            else if (x[k][i] == 'u' || x[k][i] == 'a')
                Q->fixels[i].state = WC_NEAR;
        }
        if (wc_wrench_cone_paper(C.cones + k, NULL, Q, x[k], err) != WC_OK)
            goto cleanup;
        if (!C.cones[k].empty)
            add_cone_planes(planes, C.cones + k);
    }
    C.ncones = count;

    /* The coordinate planes make the arrangement essential (rank 3), so
       that every cell is a pointed cone: every 1-cell is a ray on the
       meet of two planes, every 2-cell an open sector of one plane
       between two such rays, every 3-cell has such a sector on its
       boundary.  */
    for (j = 0; j < 3; j++)
    {
        fmpz_zero(v + 0);
        fmpz_zero(v + 1);
        fmpz_zero(v + 2);
        fmpz_one(v + j);
        vlist_add_unique(planes, v);
    }

    /* The origin, the one 0-cell.  */
    fmpz_zero(v + 0);
    fmpz_zero(v + 1);
    fmpz_zero(v + 2);
    found = uncovered(&C, v);
    for (k = 0; k < planes->len && !found; k++)
    {
        r = visit_plane(&C, planes, k);
        if (r < 0)
            goto cleanup;
        found = r;
    }

    if (!found)
    {
        status = 1;
        goto cleanup;
    }
    for (j = 0; j < 3; j++)
        fmpq_set(witness + j, pt + j);
    /* Trust the cone route for the answer only after the LPs agree.  */
    status = (ref_plan_goal_contains(P, witness) == 1) ? 0 : -1;

cleanup:
    for (k = 0; k < ncones; k++)
        wc_cone_clear(C.cones + k);
    flint_free(C.cones);
    ref_plan_strings_free(x, count);
    vlist_clear(planes);
    for (j = 0; j < 3; j++)
    {
        fmpz_clear(v + j);
        fmpq_clear(pt + j);
    }
    wc_error_clear(err);
    wc_problem_clear(Q);
    return status;
}

/* ---- the complete model --------------------------------------------- */

int
ref_plan_complete_accepts(const wc_problem_t P, const fmpq * g)
{
    slong n = P->n, N, i;
    ulong full, S, T, X, L, A, Ap;
    unsigned char * edge = NULL;        /* edge[S * N + T]: S -> T */
    unsigned char * alive = NULL;
    char * x = NULL;
    int status = -1, r, changed;

    if (n < 1 || n > REF_PLAN_MAX_COMPLETE_N)
        goto cleanup;
    N = WORD(1) << n;
    full = (ulong) N - 1;
    edge = calloc((size_t) N * N, 1);
    alive = calloc((size_t) N, 1);
    x = malloc(n + 1);
    if (edge == NULL || alive == NULL || x == NULL)
        goto cleanup;
    x[n] = '\0';

    /* Every outcome at every state: bit i of X picks s over m on a
       contact, a over s off it.  */
    for (S = 0; S <= full; S++)
    {
        for (X = 0; X <= full; X++)
        {
            for (i = 0; i < n; i++)
            {
                int in_S = (S >> i) & 1, bit = (X >> i) & 1;

                x[i] = in_S ? (bit ? 's' : 'm') : (bit ? 'a' : 's');
            }
            r = ref_wrench_in_cone(P, x, g);
            if (r < 0)
                goto cleanup;
            if (r == 0)
                continue;
            L = X & S;
            A = X & ~S & full;
            if (L == 0 && A == 0)
            {
                edge[S * N + S] = 1;
                continue;
            }
            /* Every subset A' of A, counting down to the empty one.  */
            for (Ap = A; ; Ap = (Ap - 1) & A)
            {
                if (!(Ap == 0 && L == 0))
                    edge[S * N + ((S & ~L) | Ap)] = 1;
                if (Ap == 0)
                    break;
            }
        }
    }

    status = 0;

    /* (i) nothing leaves the goal */
    for (T = 0; T < full; T++)
        if (edge[full * N + T])
            goto cleanup;

    /* (iii) every other state moves */
    for (S = 0; S < full; S++)
    {
        for (T = 0; T <= full && !edge[S * N + T]; T++)
            ;
        if (T > full)
            goto cleanup;
    }

    /* (ii) no cycle off the goal: peel states whose every edge leads to
       the goal or to a peeled state; a cycle (a self-loop included) can
       never be peeled.  */
    for (S = 0; S < full; S++)
        alive[S] = 1;
    do
    {
        changed = 0;
        for (S = 0; S < full; S++)
        {
            if (!alive[S])
                continue;
            for (T = 0; T < full && !(edge[S * N + T] && alive[T]); T++)
                ;
            if (T == full)
            {
                alive[S] = 0;
                changed = 1;
            }
        }
    }
    while (changed);
    for (S = 0; S < full; S++)
        if (alive[S])
            goto cleanup;

    status = 1;

cleanup:
    free(edge);
    free(alive);
    free(x);
    return status;
}

/* ---- the plan model and the rigid-body model ------------------------ */

int
ref_plan_model(wc_problem_t Q, const wc_problem_t P)
{
    slong i;

    if (wc_problem_set(Q, P) != WC_OK)
        return -1;
    for (i = 0; i < Q->n; i++)
        if (fmpq_cmp(Q->fixels[i].mu_k, Q->fixels[i].mu_s) > 0)
            fmpq_set(Q->fixels[i].mu_s, Q->fixels[i].mu_k);
    return 0;
}

/* 6^n LPs a wrench: past 6 fixels no test would wait for it.  */
#define REF_PLAN_MAX_MODEL_N 6

/* The solution of code (base-4 digits, fixel 0 the lowest) at state S:
   s n l r on S, s a off S; 0 when an off-S digit is 2 or 3.  */
static int
model_mode(char * y, slong code, ulong S, slong n)
{
    slong i;

    for (i = 0; i < n; i++, code /= 4)
    {
        if ((S >> i) & 1)
            y[i] = "snlr"[code % 4];
        else if (code % 4 < 2)
            y[i] = "sa"[code % 4];
        else
            return 0;
    }
    y[n] = '\0';
    return 1;
}

static int
model_report(ulong * state, char * mode, ulong S, slong code, slong n)
{
    *state = S;
    model_mode(mode, code, S, n);
    return 1;
}

int
ref_plan_model_breaks(const wc_problem_t P, const fmpq * g, int goal_rule,
                      ulong * state, char * mode)
{
    slong n = P->n, N, code, ncodes, i;
    ulong full, S, T, L, A, Ap;
    slong * via = NULL;         /* via[S * N + T]: a solution for S -> T */
    unsigned char * alive = NULL;
    char * y = NULL;
    int status = -1, r, changed;

    if (n < 1 || n > REF_PLAN_MAX_MODEL_N)
        return -1;
    N = WORD(1) << n;
    full = (ulong) N - 1;
    for (ncodes = 1, i = 0; i < n; i++)
        ncodes *= 4;
    via = malloc(sizeof(slong) * (size_t) N * N);
    alive = calloc((size_t) N, 1);
    y = malloc(n + 1);
    if (via == NULL || alive == NULL || y == NULL)
        goto cleanup;
    for (i = 0; i < N * N; i++)
        via[i] = -1;

    for (S = 0; S <= full; S++)
        for (code = 0; code < ncodes; code++)
        {
            if (!model_mode(y, code, S, n))
                continue;
            r = ref_wrench_in_cone(P, y, g);
            if (r < 0)
                goto cleanup;
            if (r == 0)
                continue;
            for (L = A = 0, i = 0; i < n; i++)
            {
                if (((S >> i) & 1) && y[i] == 's')
                    L |= UWORD(1) << i;
                if (!((S >> i) & 1) && y[i] == 'a')
                    A |= UWORD(1) << i;
            }
            if (goal_rule && (L != 0 || (S != full && A == 0)))
            {
                status = model_report(state, mode, S, code, n);
                goto cleanup;
            }
            for (Ap = A; ; Ap = (Ap - 1) & A)
            {
                if (!(Ap == 0 && L == 0 && A != 0)
                    && via[S * N + ((S & ~L) | Ap)] < 0)
                    via[S * N + ((S & ~L) | Ap)] = code;
                if (Ap == 0)
                    break;
            }
        }
    status = 0;
    if (goal_rule)
        goto cleanup;

    /* nothing leaves the goal */
    for (T = 0; T < full; T++)
        if (via[full * N + T] >= 0)
        {
            status = model_report(state, mode, full, via[full * N + T], n);
            goto cleanup;
        }
    /* no cycle off the goal: peel the states whose every edge leads to
       the goal or to a peeled state; what stays holds a cycle */
    for (S = 0; S < full; S++)
        alive[S] = 1;
    do
    {
        changed = 0;
        for (S = 0; S < full; S++)
        {
            if (!alive[S])
                continue;
            for (T = 0; T < full && !(via[S * N + T] >= 0 && alive[T]); T++)
                ;
            if (T == full)
                alive[S] = 0, changed = 1;
        }
    }
    while (changed);
    for (S = 0; S < full; S++)
        for (T = 0; alive[S] && T < full; T++)
            if (alive[T] && via[S * N + T] >= 0)
            {
                status = model_report(state, mode, S, via[S * N + T], n);
                goto cleanup;
            }

cleanup:
    free(via);
    free(alive);
    free(y);
    return status;
}
