/* old-cells.c -- the previous implementation of wc_cells_build, kept to
   catch regressions; not an independent reference.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The former lib/exact/cells.c build, line for line: every face's key
   written and hashed in full (O(m) per face), its own hash table, the
   chamber multiplier by one division per plane, and a sorted copy of the
   keys.  It walks the same arrangement (lib/exact/arrangement.c) as the
   library, so t-cellsfast compares the new bookkeeping with the old one
   and cannot see an error of the walk itself.  The independent
   reference is ref-cells.c (t-cellsref).  Kept as it was; do not
   "optimise" it.  */

#include <config.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "exact/hash.h"
#include "exact/zvec3set.h"
#include "exact/arrangement.h"
#include "exact/cells.h"
#include "old-cells.h"

/* Planes with entries below 2^16 give lines below 2^33 and sector points
   below 2^34, and the dot products a chamber's point needs fit a 64-bit
   word (below 3 2^50): then they are done in words.  */
#define SMALL_BITS 16

/* ---------------------------------------------------------------------
   The cell list under construction.  Signs are kept as keys: sign + 1
   in a byte, so that memcmp orders them - < 0 < +.  */

typedef struct
{
    slong m;                /* planes */
    slong cap;              /* cells expected (keys have room for one
                               more, the candidate) */
    slong count;
    unsigned char * key;    /* (cap + 1) x m */
    uint64_t * hash;        /* cap + 1 */
    fmpz * pt;              /* (cap + 1) x 3 */
    slong * dim;            /* cap + 1 */
    slong size;             /* hash table slots, a power of two */
    slong * slot;
}
cell_list;

static void
cell_list_init(cell_list * L, slong m, slong cap)
{
    slong i;

    L->m = m;
    L->cap = cap;
    L->count = 0;
    L->key = flint_malloc((cap + 1) * m + 1);
    L->hash = flint_malloc(sizeof(uint64_t) * (cap + 1));
    L->pt = _fmpz_vec_init(3 * (cap + 1));
    L->dim = flint_malloc(sizeof(slong) * (cap + 1));
    L->size = _wc_hash_size(2 * cap + 2);
    L->slot = flint_malloc(sizeof(slong) * L->size);
    for (i = 0; i < L->size; i++)
        L->slot[i] = -1;
}

static void
cell_list_clear(cell_list * L)
{
    flint_free(L->key);
    flint_free(L->hash);
    _fmpz_vec_clear(L->pt, 3 * (L->cap + 1));
    flint_free(L->dim);
    flint_free(L->slot);
}

/* Look the next key (L->key + count m) up: return -1 when it is new (it
   is then added, with dimension d; its point is to be written to L->pt +
   3 * index, the index being returned through *at), else the index of
   the equal cell.  Never called with count > cap.  */
static slong
cell_list_add(cell_list * L, slong d, slong * at)
{
    slong m = L->m, c = L->count, i;
    const unsigned char * k = L->key + c * m;
    uint64_t h = _wc_hash_bytes(k, m);

    for (i = (slong) (h & (L->size - 1)); L->slot[i] >= 0;
         i = (i + 1) & (L->size - 1))
    {
        slong o = L->slot[i];

        if (L->hash[o] == h && memcmp(L->key + o * m, k, m) == 0)
            return o;
    }
    L->slot[i] = c;
    L->hash[c] = h;
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
    slong * h64;            /* H as words when its entries are below
                               2^SMALL_BITS, else NULL */
    slong hplane;           /* the plane hh is for */
    fmpz * hh;              /* h_q . h_p, m entries */
    slong * hh64;           /* the same in words, with h64 */
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
#if FLINT_BITS == 64
    C->h64 = flint_malloc(sizeof(slong) * (3 * m + 1));
    for (i = 0; i < 3 * m && C->h64 != NULL; i++)
    {
        const fmpz * x = fmpz_mat_entry(H, i / 3, i % 3);

        if (fmpz_bits(x) > SMALL_BITS)
        {
            flint_free(C->h64);
            C->h64 = NULL;
        }
        else
            C->h64[i] = fmpz_get_si(x);
    }
#else
    (void) i;
#endif
    C->hplane = -1;
    C->hh = _fmpz_vec_init(m + 1);
    C->hh64 = flint_malloc(sizeof(slong) * (m + 1));
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
    flint_free(C->hh64);
    fmpz_clear(C->k);
    fmpz_clear(C->t);
    fmpz_clear(C->a);
}

/* Check the signs seckey of the sector with point mid on plane p against
   the dot products there, and set C->k to a multiplier for the points of
   the chambers beside it: k |h_q . mid| > |h_q . h_p| for every q != p.
   Returns 0 on a mismatch.  */
static int
chamber_multiplier(collect * C, slong p, const fmpz * mid,
                   const unsigned char * seckey)
{
    const slong * h64 = C->h64;
    slong m = C->L->m, q;

    if (C->hplane != p)
    {
        for (q = 0; q < m; q++)
        {
            _fmpz_vec_dot(C->hh + q, WC_ROW(C->H, q), WC_ROW(C->H, p), 3);
            if (h64 != NULL)
                C->hh64[q] = fmpz_get_si(C->hh + q);
        }
        C->hplane = p;
    }
    if (h64 != NULL)
    {
        slong x = fmpz_get_si(mid), y = fmpz_get_si(mid + 1),
            z = fmpz_get_si(mid + 2), k = 0;

        for (q = 0; q < m; q++)
        {
            slong d = h64[3 * q] * x + h64[3 * q + 1] * y + h64[3 * q + 2] * z;
            slong e = C->hh64[q];

            if ((d > 0) - (d < 0) + 1 != seckey[q])
                return 0;
            if (q == p || e == 0)
                continue;
            e = FLINT_ABS(e) / FLINT_ABS(d);
            if (e > k)
                k = e;
        }
        fmpz_set_si(C->k, k + 1);
        return 1;
    }
    fmpz_zero(C->k);
    for (q = 0; q < m; q++)
    {
        int s = _wc_zvec3_dot_sgn(WC_ROW(C->H, q), mid, C->a);

        if (s + 1 != seckey[q])
            return 0;
        if (q == p || fmpz_is_zero(C->hh + q))
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
                                C->L->key + C->sec * C->L->m))
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
    slong m = L->m, q, at, zeros = 0;
    unsigned char * key;

    if (L->count > L->cap)
        goto euler;
    key = L->key + L->count * m;
    for (q = 0; q < m; q++)
    {
        key[q] = (unsigned char) (F->sign[q] + 1);
        zeros += F->sign[q] == 0;
    }
    if (cell_list_add(L, F->dim, &at) >= 0)
    {
        if (F->dim == 3)
            return WC_OK;       /* a chamber met before */
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "internal error: cells: two cells of dimension "
                            "%d with the same signs", F->dim);
    }
    if (at >= L->cap)
        goto euler;
    if (F->dim == 2)
    {
        if (zeros != 1 || F->sign[F->plane] != 0)
            return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                "internal error: cells: an arc of plane %ld "
                                "lies on %ld planes", (long) F->plane,
                                (long) zeros);
        C->sec = at;
        C->have_k = 0;
    }
    if (F->dim == 3)
        return chamber_point(L->pt + 3 * at, C, F, err);
    _fmpz_vec_set(L->pt + 3 * at, F->point, 3);
    return WC_OK;

euler:
    return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                        "internal error: cells: more cells than Euler's "
                        "relation allows");
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

typedef struct
{
    const unsigned char * key;
    slong len;
    slong dim;
    slong i;
}
key_ref;

/* Cells by dimension, then by key.  */
static int
key_ref_cmp(const void * p, const void * q)
{
    const key_ref * a = p, * b = q;

    if (a->dim != b->dim)
        return a->dim < b->dim ? -1 : 1;
    return memcmp(a->key, b->key, a->len);
}

/* A := the cells of L on the planes H (taken), sorted.  */
static void
cells_sorted(wc_cells_t A, fmpz_mat_t H, const cell_list * L)
{
    slong m = L->m, total = L->count, i, j;
    key_ref * ref = flint_malloc(sizeof(key_ref) * (total + 1));
    signed char * s = malloc(m + 1);

    for (i = 0; i < total; i++)
    {
        ref[i].key = L->key + i * m;
        ref[i].len = m;
        ref[i].dim = L->dim[i];
        ref[i].i = i;
    }
    qsort(ref, total, sizeof(key_ref), key_ref_cmp);
    A->nplanes = m;
    fmpz_mat_swap(A->planes, H);
    A->count = total;
    fmpz_mat_clear(A->point);
    fmpz_mat_init(A->point, total, 3);
    A->dim = flint_malloc(sizeof(slong) * (total + 1));
    A->kw = WC_CELLS_KEY_WORDS(m);
    A->key = malloc(sizeof(uint64_t) * (total * A->kw + 1));
    for (i = 0; i < total; i++)
    {
        slong c = ref[i].i;

        _fmpz_vec_set(WC_ROW(A->point, i), L->pt + 3 * c, 3);
        A->dim[i] = L->dim[c];
        for (j = 0; j < m; j++)
            s[j] = (signed char) (L->key[c * m + j] - 1);
        wc_cells_pack(A->key + i * A->kw, s, m);
    }
    free(s);
    flint_free(ref);
}

int
old_cells_build(wc_cells_t A, const fmpz_mat_t normals, wc_error_t err)
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
    cell_list_init(&L, m, total);
    collect_init(&C, &L, H);
    if (status == WC_OK)
        status = _wc_arrangement_walk(R, collect_face, &C, err);
    if (status == WC_OK && L.count != total)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                              "internal error: cells: Euler's relation "
                              "fails: %ld rays - %ld sectors + %ld chambers "
                              "!= 2", (long) nrays, (long) nsec,
                              (long) (L.count - 1 - nrays - nsec));
    if (status == WC_OK)
        cells_sorted(A, H, &L);
    collect_clear(&C);
    cell_list_clear(&L);
    _wc_arrangement_clear(R);
    fmpz_mat_clear(H);
    return status;
}

