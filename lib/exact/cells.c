/* cells.c -- the cells of a central arrangement of planes in R^3.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   With the coordinate planes among them, the planes meet pairwise in
   lines, every plane holds at least two distinct lines (if all the others
   met plane p in one line L, every normal would be orthogonal to L, and
   e1, e2, e3 are not), and every cell but the origin is a pointed cone.
   The walk of arrangement.c reports every cell with its sign vector: the
   origin, the rays (both directions of every line), the sectors (the
   arcs between consecutive rays on a plane, each of angle below pi, as
   there are at least four rays) and the chambers beside them.

   A chamber beside the arc with point mid on plane p has the arc's signs
   but for p.  Its point is k mid + side h_p with k |h_q . mid| >
   |h_q . h_p| for every q != p, so that no other sign changes; this costs
   O(m) dot products, paid once per chamber (its sign vector is looked up
   first), and checks the arc's signs on the way.

   With m planes there are at most m (m - 1) rays, as many sectors as
   rays counted on their planes (at most 2 m (m - 1)) and, by Euler's
   relation on the sphere (rays - sectors + chambers = 2), fewer chambers
   than sectors: O(m^2) cells with sign vectors of m entries, found in
   O(m^3) time (and sorted in O(m^3 log m) at worst).  Duplicates are
   found by a hash table on the sign vectors, compared in full.  */

#include <config.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "exact/vec3.h"
#include "exact/hash.h"
#include "exact/zvec3set.h"
#include "exact/arrangement.h"
#include "exact/cells.h"

/* Planes whose entries are word fmpz (below 2^62 in absolute value) and
   a sector point whose entries are too give dot products below 2^126:
   then the chamber multiplier is found in 128-bit words.  */
#if defined(__SIZEOF_INT128__) && FLINT_BITS == 64
#define WIDE 1
typedef __int128 wide;
#else
#define WIDE 0
#endif

/* ---------------------------------------------------------------------
   The cell list under construction.  Signs are kept as keys (cells.h),
   the cells' own form: sign + 1 in two bits per plane.  The key of
   the current face and its hash are kept up to date from the planes the
   walk says have changed: the hash is the XOR of one random word per
   plane and sign (Zobrist hashing), so a face costs O(changed) before
   its lookup, and a chamber met again one comparison of its key.  The
   keys are copied once, in the sorted order, at the end.  */

#define KEY_PLANES WC_CELLS_KEY_PLANES
#define KEY_SHIFT(q) (62 - 2 * ((q) % KEY_PLANES))

/* The sign + 1 of plane q in key k.  */
static inline unsigned int
key_get(const uint64_t * k, slong q)
{
    return (unsigned int) (k[q / KEY_PLANES] >> KEY_SHIFT(q)) & 3;
}

/* The low half of a slot of the hash table: a cell's index + 1.  */
#define SLOT_INDEX UINT64_C(0xFFFFFFFF)

typedef struct
{
    slong m;                /* planes */
    slong kw;               /* words per key */
    slong cap;              /* cells expected */
    slong count;
    uint64_t * key;         /* cap x kw */
    fmpz_mat_struct * pt;   /* cap x 3: the points */
    slong * dim;            /* cap */
    slong size;             /* hash table slots, a power of two */
    uint64_t * slot;        /* 0, or the high half of a cell's hash and
                               its index + 1 in the low half */
    uint64_t * cur;         /* kw: the current face's key */
    uint64_t curhash;
    uint64_t * zob;         /* 3 m: the word of plane q and sign + 1 b at
                               3 q + b */
}
cell_list;

/* L := an empty list for cap cells on m planes, their points to go to
   P (cap x 3).  */
static int
cell_list_init(cell_list * L, slong m, slong cap, fmpz_mat_t P)
{
    slong i;

    L->m = m;
    L->kw = WC_CELLS_KEY_WORDS(m);
    L->cap = cap;
    L->count = 0;
    L->pt = P;
    L->key = malloc(sizeof(uint64_t) * ((size_t) cap * L->kw + 1));
    L->dim = flint_malloc(sizeof(slong) * (cap + 1));
    L->size = _wc_hash_size(2 * cap + 2);
    L->slot = calloc(L->size, sizeof(uint64_t));
    L->cur = flint_malloc(sizeof(uint64_t) * (L->kw + 1));
    L->zob = flint_malloc(sizeof(uint64_t) * (3 * m + 1));
    if (L->key == NULL || L->dim == NULL || L->slot == NULL
        || L->cur == NULL || L->zob == NULL || (uint64_t) cap >= SLOT_INDEX)
        return 0;
    L->curhash = 0;
    for (i = 0; i < 3 * m; i++)
        L->zob[i] = _wc_hash_mix64(UINT64_C(0x9e3779b97f4a7c15) * (i + 1));
    memset(L->cur, 0, sizeof(uint64_t) * L->kw);
    for (i = 0; i < m; i++)
    {
        L->cur[i / KEY_PLANES] |= UINT64_C(1) << KEY_SHIFT(i);
        L->curhash ^= L->zob[3 * i + 1];
    }
    return 1;
}

static void
cell_list_clear(cell_list * L)
{
    free(L->key);
    flint_free(L->dim);
    free(L->slot);
    flint_free(L->cur);
    flint_free(L->zob);
}

/* Bring the current key up to the face F.  */
static void
cell_list_update(cell_list * L, const _wc_face_struct * F)
{
    slong i;

    for (i = 0; i < F->nchanged; i++)
    {
        slong q = F->changed[i];
        uint64_t b = (uint64_t) (F->sign[q] + 1);
        uint64_t * w = L->cur + q / KEY_PLANES;

        L->curhash ^= L->zob[3 * q + key_get(L->cur, q)] ^ L->zob[3 * q + b];
        *w = (*w & ~(UINT64_C(3) << KEY_SHIFT(q))) | (b << KEY_SHIFT(q));
    }
}

/* Look the current key up: return the index of the equal cell, or -1
   when it is new (it is then added, with dimension d, at index *at; its
   point is to be written to row *at of L->pt), or -2 when there is no
   room.  */
static slong
cell_list_add(cell_list * L, slong d, slong * at)
{
    slong kw = L->kw, c = L->count, i, j;
    const uint64_t * k = L->cur;
    uint64_t h = L->curhash, tag = h & ~SLOT_INDEX;

    for (i = (slong) (h & (L->size - 1)); L->slot[i] != 0;
         i = (i + 1) & (L->size - 1))
    {
        if ((L->slot[i] & ~SLOT_INDEX) == tag)
        {
            slong o = (slong) (L->slot[i] & SLOT_INDEX) - 1;
            const uint64_t * ko = L->key + o * kw;

            for (j = 0; j < kw && ko[j] == k[j]; j++)
                ;
            if (j == kw)
                return o;
        }
    }
    if (c >= L->cap)
        return -2;
    memcpy(L->key + c * kw, k, sizeof(uint64_t) * kw);
    L->slot[i] = tag | (uint64_t) (c + 1);
    L->dim[c] = d;
    *at = c;
    L->count++;
    return -1;
}

/* ---------------------------------------------------------------------
   Collecting the cells of the walk.  */

typedef struct
{
    cell_list * L;
    const fmpz_mat_struct * H;
    slong * h64;            /* H as words when WIDE and its entries are
                               word fmpz, else NULL */
    slong hplane;           /* the plane hh is for */
    fmpz * hh;              /* h_q . h_p, m entries */
#if WIDE
    wide * hh128;           /* the same in 128-bit words, with h64 */
#endif
    slong sec;              /* the current sector's cell */
    int have_k;             /* k is set for it */
    fmpz_t k;
    fmpz_t t;
    fmpz_t a;
}
collect;

static void
collect_init(collect * C, cell_list * L, const fmpz_mat_t H)
{
    slong m = fmpz_mat_nrows(H), i;

    C->L = L;
    C->H = H;
    C->h64 = NULL;
#if WIDE
    C->h64 = flint_malloc(sizeof(slong) * (3 * m + 1));
    for (i = 0; i < 3 * m && C->h64 != NULL; i++)
    {
        const fmpz * x = fmpz_mat_entry(H, i / 3, i % 3);

        if (COEFF_IS_MPZ(*x))
        {
            flint_free(C->h64);
            C->h64 = NULL;
        }
        else
            C->h64[i] = *x;
    }
    C->hh128 = flint_malloc(sizeof(wide) * (m + 1));
#else
    (void) i;
#endif
    C->hplane = -1;
    C->hh = _fmpz_vec_init(m + 1);
    C->sec = -1;
    C->have_k = 0;
    fmpz_init(C->k);
    fmpz_init(C->t);
    fmpz_init(C->a);
}

static void
collect_clear(collect * C)
{
    flint_free(C->h64);
    _fmpz_vec_clear(C->hh, C->L->m + 1);
#if WIDE
    flint_free(C->hh128);
#endif
    fmpz_clear(C->k);
    fmpz_clear(C->t);
    fmpz_clear(C->a);
}

#if WIDE
/* chamber_multiplier in 128-bit words: h64 set, mid's entries words.  */
static int
multiplier_wide(collect * C, slong p, const fmpz * mid,
                const uint64_t * seckey)
{
    const slong * h = C->h64;
    slong m = C->L->m, q;
    wide x = mid[0], y = mid[1], z = mid[2], k = 1;

    for (q = 0; q < m; q++)
    {
        wide d = h[3 * q] * x + h[3 * q + 1] * y + h[3 * q + 2] * z;
        wide e = C->hh128[q];

        if ((unsigned int) ((d > 0) - (d < 0) + 1) != key_get(seckey, q))
            return 0;
        d = d < 0 ? -d : d;
        e = e < 0 ? -e : e;
        /* d > 0 but on p (the sector's signs, checked); a division only
           when |h_q . h_p| >= |h_q . mid| */
        if (q != p && e >= d && e / d >= k)
            k = e / d + 1;
    }
    fmpz_set_uiui(C->k, (ulong) (k >> 64), (ulong) k);
    return 1;
}
#endif

/* Check the signs seckey of the sector with point mid on plane p against
   the dot products there, and set C->k to a multiplier for the points of
   the chambers beside it: the least k with k |h_q . mid| > |h_q . h_p|
   for every q != p.  Returns 0 on a mismatch.  */
static int
chamber_multiplier(collect * C, slong p, const fmpz * mid,
                   const uint64_t * seckey)
{
    slong m = C->L->m, q;

    if (C->hplane != p)
    {
        for (q = 0; q < m; q++)
        {
            _fmpz_vec_dot(C->hh + q, WC_ROW(C->H, q), WC_ROW(C->H, p), 3);
#if WIDE
            if (C->h64 != NULL)
                C->hh128[q] = (wide) C->h64[3 * q] * C->h64[3 * p]
                    + (wide) C->h64[3 * q + 1] * C->h64[3 * p + 1]
                    + (wide) C->h64[3 * q + 2] * C->h64[3 * p + 2];
#endif
        }
        C->hplane = p;
    }
#if WIDE
    if (C->h64 != NULL && !COEFF_IS_MPZ(mid[0]) && !COEFF_IS_MPZ(mid[1])
        && !COEFF_IS_MPZ(mid[2]))
        return multiplier_wide(C, p, mid, seckey);
#endif
    fmpz_zero(C->k);
    for (q = 0; q < m; q++)
    {
        int s = _wc_zvec3_dot_sgn(WC_ROW(C->H, q), mid, C->a);

        if ((unsigned int) (s + 1) != key_get(seckey, q))
            return 0;
        /* a quotient below 1 cannot raise k: no division */
        if (q == p || fmpz_is_zero(C->hh + q)
            || fmpz_cmpabs(C->hh + q, C->a) < 0)
            continue;
        fmpz_abs(C->a, C->a);
        fmpz_abs(C->t, C->hh + q);
        fmpz_fdiv_q(C->t, C->t, C->a);
        if (fmpz_cmp(C->t, C->k) > 0)
            fmpz_set(C->k, C->t);
    }
    fmpz_add_ui(C->k, C->k, 1);
    return 1;
}

/* A chamber's point (see the top of the file), once per sector.  */
static int
chamber_point(fmpz * pc, collect * C, const _wc_face_struct * F,
              wc_error_t err)
{
    if (!C->have_k)
    {
        if (!chamber_multiplier(C, F->plane, F->point,
                                C->L->key + C->sec * C->L->kw))
            return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                "internal error: cells: the signs of a "
                                "sector are wrong");
        C->have_k = 1;
    }
    _fmpz_vec_scalar_mul_fmpz(pc, F->point, 3, C->k);
    if (F->side > 0)
        _fmpz_vec_add(pc, pc, F->normal, 3);
    else
        _fmpz_vec_sub(pc, pc, F->normal, 3);
    _wc_zvec3_primitive(pc, C->t);
    return WC_OK;
}

static int
collect_face(void * data, const _wc_face_struct * F, wc_error_t err)
{
    collect * C = data;
    cell_list * L = C->L;
    slong m = L->m, q, at = -1, zeros = 0, o;

    cell_list_update(L, F);
    o = cell_list_add(L, F->dim, &at);
    if (o == -2)
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "internal error: cells: more cells than Euler's "
                            "relation allows");
    if (o >= 0)
    {
        if (F->dim == 3)
            return WC_OK;       /* a chamber met before */
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "internal error: cells: two cells of dimension "
                            "%d with the same signs", F->dim);
    }
    if (F->dim == 2)
    {
        for (q = 0; q < m; q++)
            zeros += F->sign[q] == 0;
        if (zeros != 1 || F->sign[F->plane] != 0)
            return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                "internal error: cells: an arc of plane %ld "
                                "lies on %ld planes", (long) F->plane,
                                (long) zeros);
        C->sec = at;
        C->have_k = 0;
    }
    if (F->dim == 3)
        return chamber_point(WC_ROW(L->pt, at), C, F, err);
    _fmpz_vec_set(WC_ROW(L->pt, at), F->point, 3);
    return WC_OK;
}

/* ---------------------------------------------------------------------
   The cells.  */

void
wc_cells_init(wc_cells_t A)
{
    A->nplanes = 0;
    fmpz_mat_init(A->planes, 0, 3);
    A->count = 0;
    fmpz_mat_init(A->point, 0, 3);
    A->dim = NULL;
    A->kw = 0;
    A->key = NULL;
}

void
wc_cells_clear(wc_cells_t A)
{
    fmpz_mat_clear(A->planes);
    fmpz_mat_clear(A->point);
    flint_free(A->dim);
    free(A->key);
    wc_cells_init(A);
}

static int
vec_ptr_cmp(const void * p, const void * q)
{
    return _wc_zvec3_cmp(*(const fmpz * const *) p, *(const fmpz * const *) q);
}

/* H := the distinct canonical planes of the nonzero rows of N and the
   coordinate planes, sorted.  */
static void
collect_planes(fmpz_mat_t H, const fmpz_mat_t N)
{
    slong n = fmpz_mat_nrows(N), c = 0, m = 0, i;
    fmpz * v = _fmpz_vec_init(3 * (n + 3));
    fmpz ** ref = flint_malloc(sizeof(fmpz *) * (n + 3));
    fmpz_t t;

    fmpz_init(t);
    for (i = 0; i < 3; i++)
    {
        fmpz_one(v + 3 * c + i);
        c++;
    }
    for (i = 0; i < n; i++)
    {
        _fmpz_vec_set(v + 3 * c, WC_ROW(N, i), 3);
        if (_wc_zvec3_canonical(v + 3 * c, t))
            c++;
    }
    for (i = 0; i < c; i++)
        ref[i] = v + 3 * i;
    qsort(ref, c, sizeof(fmpz *), vec_ptr_cmp);
    for (i = 0; i < c; i++)
        if (m == 0 || _wc_zvec3_cmp(ref[m - 1], ref[i]) != 0)
            ref[m++] = ref[i];
    fmpz_mat_clear(H);
    fmpz_mat_init(H, m, 3);
    for (i = 0; i < m; i++)
        _fmpz_vec_set(WC_ROW(H, i), ref[i], 3);
    fmpz_clear(t);
    flint_free(ref);
    _fmpz_vec_clear(v, 3 * (n + 3));
}

/* A cell to sort: the first word of its key and its index.  */
typedef struct
{
    uint64_t k0;
    slong i;
}
key_ref;

/* a < b for the keys (kw words each, from key) of two cells.  */
static inline int
key_ref_less(const key_ref * a, const key_ref * b, const uint64_t * key,
             slong kw)
{
    const uint64_t * x, * y;
    slong j;

    if (a->k0 != b->k0)
        return a->k0 < b->k0;
    x = key + a->i * kw;
    y = key + b->i * kw;
    for (j = 1; j < kw && x[j] == y[j]; j++)
        ;
    return j < kw && x[j] < y[j];
}

/* Sort r[0 .. n) by key (all keys distinct), with n entries of scratch
   tmp: a merge sort, runs of 2^k doubling.  Returns the array holding
   the result (r or tmp).  */
static key_ref *
key_sort(key_ref * r, key_ref * tmp, slong n, const uint64_t * key,
         slong kw)
{
    slong run, lo;

    for (run = 1; run < n; run *= 2)
    {
        for (lo = 0; lo < n; lo += 2 * run)
        {
            slong mid = FLINT_MIN(lo + run, n), hi = FLINT_MIN(lo + 2 * run, n);
            slong i = lo, j = mid, o = lo;

            while (i < mid && j < hi)
                tmp[o++] = key_ref_less(r + j, r + i, key, kw) ? r[j++]
                    : r[i++];
            while (i < mid)
                tmp[o++] = r[i++];
            while (j < hi)
                tmp[o++] = r[j++];
        }
        {
            key_ref * t = r;

            r = tmp;
            tmp = t;
        }
    }
    return r;
}

/* key[i] := key[src[i]] (kw words each) and row i of P := row src[i],
   for i < n, src a permutation, in place: cycle by cycle, with one key
   of scratch (tmp) and the rows swapped along the cycle; src is left
   the identity.  */
static void
permute_cells(uint64_t * key, fmpz_mat_t P, slong * src, slong n, slong kw,
              uint64_t * tmp)
{
    slong i, j, k;

    for (i = 0; i < n; i++)
    {
        if (src[i] == i)
            continue;
        memcpy(tmp, key + i * kw, sizeof(uint64_t) * kw);
        for (j = i; src[j] != i; j = k)
        {
            k = src[j];
            memcpy(key + j * kw, key + k * kw, sizeof(uint64_t) * kw);
            /* row j gets row k's; row k then holds row i's */
            _fmpz_vec_swap(WC_ROW(P, j), WC_ROW(P, k), 3);
            src[j] = j;
        }
        memcpy(key + j * kw, tmp, sizeof(uint64_t) * kw);
        src[j] = j;
    }
}

/* A := the cells of L on the planes H (taken), sorted by dimension
   (bucketed), then by key; A takes L's keys and points (already A's
   point matrix), put in that order.
   Returns 0 when out of memory.  */
static int
cells_sorted(wc_cells_t A, fmpz_mat_t H, cell_list * L)
{
    slong kw = L->kw, total = L->count, i, d, start[5] = {0};
    key_ref * ref = flint_malloc(sizeof(key_ref) * (2 * total + 1));
    slong * src = flint_malloc(sizeof(slong) * (total + 1));
    slong * dim = flint_malloc(sizeof(slong) * (total + 1));

    if (ref == NULL || src == NULL || dim == NULL)
    {
        flint_free(ref);
        flint_free(src);
        flint_free(dim);
        return 0;
    }
    for (i = 0; i < total; i++)
        start[L->dim[i] + 1]++;
    for (d = 0; d < 4; d++)
        start[d + 1] += start[d];
    for (i = 0; i < total; i++)
    {
        key_ref * r = ref + start[L->dim[i]]++;

        r->k0 = L->key[i * kw];
        r->i = i;
    }
    A->nplanes = L->m;
    fmpz_mat_swap(A->planes, H);
    A->count = total;
    for (d = 0, i = 0; d < 4; d++)
    {
        /* start[d] is now the end of dimension d's cells */
        slong lo = d == 0 ? 0 : start[d - 1], n = start[d] - lo, j;
        key_ref * r = key_sort(ref + lo, ref + total + lo, n, L->key, kw);

        for (j = 0; j < n; j++, i++)
        {
            src[i] = r[j].i;
            dim[i] = d;
        }
    }
    /* the scratch key: L->cur, the walk is over */
    permute_cells(L->key, L->pt, src, total, kw, L->cur);
    A->dim = dim;
    A->kw = kw;
    A->key = L->key;
    L->key = NULL;
    flint_free(ref);
    flint_free(src);
    return 1;
}

int
wc_cells_build(wc_cells_t A, const fmpz_mat_t normals, wc_error_t err)
{
    fmpz_mat_t H;
    slong m, p, nrays, nsec = 0, total;
    _wc_arrangement_t R;
    cell_list L;
    collect C;
    int status;

    wc_cells_clear(A);
    if (fmpz_mat_nrows(normals) > 0 && fmpz_mat_ncols(normals) != 3)
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "internal error: cells: normals with %ld "
                            "columns", (long) fmpz_mat_ncols(normals));
    fmpz_mat_init(H, 0, 3);
    collect_planes(H, normals);
    m = fmpz_mat_nrows(H);
    status = _wc_arrangement_init(R, H, err);
    for (p = 0; p < m && status == WC_OK; p++)
    {
        if (_wc_arrangement_nlines_on(R, p) < 2)
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: cells: plane %ld holds "
                                  "%ld lines", (long) p,
                                  (long) _wc_arrangement_nlines_on(R, p));
        nsec += 2 * _wc_arrangement_nlines_on(R, p);
    }
    nrays = 2 * _wc_arrangement_nlines(R);
    total = 1 + nrays + nsec + (2 - nrays + nsec);  /* Euler, checked */
    if (status == WC_OK && (uint64_t) total >= SLOT_INDEX)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "%ld cells: more than this build can index",
                              (long) total);
    if (status != WC_OK)
        total = 0;      /* nothing to walk */
    fmpz_mat_clear(A->point);
    fmpz_mat_init(A->point, total, 3);
    if (!cell_list_init(&L, m, total, A->point) && status == WC_OK)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "out of memory (%ld cells)", (long) total);
    collect_init(&C, &L, H);
    if (status == WC_OK)
        status = _wc_arrangement_walk(R, collect_face, &C, err);
    if (status == WC_OK && L.count != total)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "internal error: cells: Euler's relation "
                              "fails: %ld rays - %ld sectors + %ld chambers "
                              "!= 2", (long) nrays, (long) nsec,
                              (long) (L.count - 1 - nrays - nsec));
    if (status == WC_OK && !cells_sorted(A, H, &L))
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "out of memory (%ld cells)", (long) total);
    collect_clear(&C);
    cell_list_clear(&L);
    _wc_arrangement_clear(R);
    fmpz_mat_clear(H);
    if (status != WC_OK)
        wc_cells_clear(A);
    return status;
}

slong
wc_cells_plane_index(const wc_cells_t A, const fmpz * h)
{
    slong r = -1;
    fmpz * v = _fmpz_vec_init(3);
    fmpz * const * hit = NULL;
    fmpz_t t;

    fmpz_init(t);
    _fmpz_vec_set(v, h, 3);
    if (_wc_zvec3_canonical(v, t) && A->nplanes > 0)
        hit = bsearch(&v, A->planes->rows, A->nplanes, sizeof(fmpz *),
                      vec_ptr_cmp);
    if (hit != NULL)
        r = hit - A->planes->rows;
    fmpz_clear(t);
    _fmpz_vec_clear(v, 3);
    return r;
}

void
wc_cells_signs(signed char * s, const wc_cells_t A, slong i)
{
    const uint64_t * k = _wc_cells_key(A, i);
    slong q;

    for (q = 0; q < A->nplanes; q++)
        s[q] = (signed char) ((int) key_get(k, q) - 1);
}

void
wc_cells_pack(uint64_t * key, const signed char * s, slong m)
{
    slong q;

    memset(key, 0, sizeof(uint64_t) * WC_CELLS_KEY_WORDS(m));
    for (q = 0; q < m; q++)
        key[q / KEY_PLANES] |= (uint64_t) (s[q] + 1) << KEY_SHIFT(q);
}

/* A cell to look for: its dimension and key, among the cells of A.  */
typedef struct
{
    const wc_cells_struct * A;
    slong dim;
    const uint64_t * key;
}
cell_key;

/* Order of cells: dimension, then keys.  q points into A->dim.  */
static int
cell_key_cmp(const void * p, const void * q)
{
    const cell_key * k = p;
    const wc_cells_struct * A = k->A;
    slong i = (const slong *) q - A->dim, j;
    const uint64_t * x = _wc_cells_key(A, i);

    if (A->dim[i] != k->dim)
        return k->dim < A->dim[i] ? -1 : 1;
    for (j = 0; j < A->kw; j++)
        if (x[j] != k->key[j])
            return k->key[j] < x[j] ? -1 : 1;
    return 0;
}

slong
wc_cells_find(const wc_cells_t A, slong dim, const signed char * sign)
{
    const slong * hit;
    cell_key key;
    uint64_t small[8];
    uint64_t * k;

    if (A->count == 0)
        return -1;
    k = A->kw <= 8 ? small : malloc(sizeof(uint64_t) * (A->kw + 1));
    if (k == NULL)
        return -1;      /* out of memory: not found */
    wc_cells_pack(k, sign, A->nplanes);
    key.A = A;
    key.dim = dim;
    key.key = k;
    hit = bsearch(&key, A->dim, A->count, sizeof(slong), cell_key_cmp);
    if (k != small)
        free(k);
    return hit == NULL ? -1 : hit - A->dim;
}

slong
wc_cells_locate(const wc_cells_t A, const fmpq * x)
{
    slong m = A->nplanes, q, zeros = 0, r = -1;
    signed char * s;
    fmpz * v;
    fmpz_t den, t;
    int nonzero;

    if (A->count == 0)
        return -1;
    s = flint_malloc(m + 1);
    v = _fmpz_vec_init(3);
    fmpz_init(den);
    fmpz_init(t);

    /* x times the (positive) common denominator: the same signs.  */
    _fmpq_vec_get_fmpz_vec_fmpz(v, den, x, 3);
    nonzero = !_fmpz_vec_is_zero(v, 3);
    for (q = 0; q < m; q++)
    {
        s[q] = (signed char) _wc_zvec3_dot_sgn(WC_ROW(A->planes, q), v, t);
        zeros += s[q] == 0;
    }
    /* Distinct planes through a nonzero point: one for a sector, two or
       more for a ray.  */
    r = wc_cells_find(A, !nonzero ? 0 : zeros == 0 ? 3 : zeros == 1 ? 2 : 1,
                      s);
    flint_free(s);
    _fmpz_vec_clear(v, 3);
    fmpz_clear(den);
    fmpz_clear(t);
    return r;
}
