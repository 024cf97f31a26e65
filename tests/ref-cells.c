/* ref-cells.c -- the independent reference for the cells of a central
   arrangement of planes in R^3 (wc_cells_build), and through it for the
   faces that mode enumeration and the moving faces are made of.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Independent of lib/: written from cells.h and SPEC.md without reading
   lib/exact/cells.c or lib/exact/arrangement.c, it uses nothing of the
   library (FLINT integers only) and no walk around any plane or line.
   Its method is symbolic perturbation, one dimension at a time:

   - every open ray of the arrangement is +-(h_p x h_q) for two planes
     that are not parallel: all such pairs are tried;
   - every open sector lies in one plane p and has a bounding ray u; the
     points u + e w, w = +-(h_p x u) (in plane p, off the line of u), are
     in the sectors of plane p beside u for every small e > 0, and their
     sign for plane j is sign(h_j . u) when that is not zero, else
     sign(h_j . w): no e is ever chosen;
   - every open chamber has a sector s on its boundary, in plane p, and
     s + e h_p, s - e h_p are in the two chambers beside s: their sign
     for plane j is that of s, or sign(+-h_j . h_p) where s has sign 0.
   Every sign vector so written is a face's (each is the limit sign of a
   real point), and every face is reached (the three coordinate planes
   are added inside, so that every plane meets at least two others in
   distinct lines, every sector is narrower than a half-plane, and every
   face is pointed).  Then the sign vectors are cut down to the planes
   asked for, sorted and made unique; each face's dimension is checked
   against the rank of its zero planes.  O(m^3) sign entries for m
   planes.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpz_vec.h>

#include "ref-cells.h"

/* ---------------------------------------------------------------------
   Integer 3-vectors.  */

static void
cross(fmpz * r, const fmpz * a, const fmpz * b)
{
    fmpz_mul(r + 0, a + 1, b + 2);
    fmpz_submul(r + 0, a + 2, b + 1);
    fmpz_mul(r + 1, a + 2, b + 0);
    fmpz_submul(r + 1, a + 0, b + 2);
    fmpz_mul(r + 2, a + 0, b + 1);
    fmpz_submul(r + 2, a + 1, b + 0);
}

static int
dot_sgn(const fmpz * a, const fmpz * b)
{
    fmpz_t t;
    int s;

    fmpz_init(t);
    fmpz_mul(t, a + 0, b + 0);
    fmpz_addmul(t, a + 1, b + 1);
    fmpz_addmul(t, a + 2, b + 2);
    s = fmpz_sgn(t);
    fmpz_clear(t);
    return s;
}

static int
is_zero3(const fmpz * a)
{
    return fmpz_is_zero(a) && fmpz_is_zero(a + 1) && fmpz_is_zero(a + 2);
}

/* The rank of the k rows of G listed in idx (3 at most).  */
static int
rank_rows(const fmpz_mat_t G, const slong * idx, slong k)
{
    fmpz w[3];
    slong i, a = -1, b = -1;
    int r = 0;

    for (i = 0; i < 3; i++)
        fmpz_init(w + i);
    for (i = 0; i < k && r < 3; i++)
    {
        const fmpz * h = G->rows[idx[i]];

        if (is_zero3(h))
            continue;
        if (a < 0)
        {
            a = idx[i];
            r = 1;
            continue;
        }
        if (b < 0)
        {
            cross(w, G->rows[a], h);
            if (!is_zero3(w))
            {
                b = idx[i];
                r = 2;
            }
            continue;
        }
        /* w = h_a x h_b: h is outside their plane iff h . w != 0 */
        if (dot_sgn(w, h) != 0)
            r = 3;
    }
    for (i = 0; i < 3; i++)
        fmpz_clear(w + i);
    return r;
}

/* ---------------------------------------------------------------------
   Lists of sign vectors, each with an optional integer 3-vector.  */

typedef struct
{
    slong len;          /* entries of a sign vector */
    slong count, cap;
    signed char * sign;
    fmpz * pt;          /* 3 per vector */
    slong * dim;
}
flist;

static void
flist_init(flist * L, slong len)
{
    L->len = len;
    L->count = L->cap = 0;
    L->sign = NULL;
    L->pt = NULL;
    L->dim = NULL;
}

static void
flist_clear(flist * L)
{
    if (L->pt != NULL)
        _fmpz_vec_clear(L->pt, 3 * L->cap);
    free(L->sign);
    free(L->dim);
    flist_init(L, L->len);
}

/* Room for one more; returns its index, or -1 when out of memory.  */
static slong
flist_push(flist * L)
{
    if (L->count == L->cap)
    {
        slong cap = L->cap < 16 ? 32 : 2 * L->cap, i;
        signed char * s = realloc(L->sign, (size_t) (cap * (L->len + 1)));
        slong * d;
        fmpz * p;

        if (s == NULL)
            return -1;
        L->sign = s;
        d = realloc(L->dim, sizeof(slong) * (size_t) cap);
        if (d == NULL)
            return -1;
        L->dim = d;
        p = _fmpz_vec_init(3 * cap);
        for (i = 0; i < 3 * L->count; i++)
            fmpz_swap(p + i, L->pt + i);
        if (L->pt != NULL)
            _fmpz_vec_clear(L->pt, 3 * L->cap);
        L->pt = p;
        L->cap = cap;
    }
    return L->count++;
}

static signed char *
flist_sign(const flist * L, slong i)
{
    return L->sign + i * (L->len + 1);
}

static int
sign_cmp(const signed char * a, const signed char * b, slong len)
{
    slong j;

    for (j = 0; j < len; j++)
        if (a[j] != b[j])
            return a[j] < b[j] ? -1 : 1;
    return 0;
}

/* qsort has no context argument: the list being sorted.  */
static const flist * sorting;

static int
index_cmp(const void * p, const void * q)
{
    slong i = *(const slong *) p, j = *(const slong *) q;
    int c;

    if (sorting->dim[i] != sorting->dim[j])
        return sorting->dim[i] < sorting->dim[j] ? -1 : 1;
    c = sign_cmp(flist_sign(sorting, i), flist_sign(sorting, j),
                 sorting->len);
    if (c != 0)
        return c;
    return i < j ? -1 : (i > j);
}

/* Sort L by (dim, sign vector) and keep the first of equal sign vectors.
   Returns 0 or -1 (out of memory).  */
static int
flist_unique(flist * L)
{
    slong * idx, i, k = 0;
    flist U;

    if (L->count == 0)
        return 0;
    idx = malloc(sizeof(slong) * (size_t) L->count);
    if (idx == NULL)
        return -1;
    for (i = 0; i < L->count; i++)
        idx[i] = i;
    sorting = L;
    qsort(idx, (size_t) L->count, sizeof(slong), index_cmp);
    flist_init(&U, L->len);
    for (i = 0; i < L->count; i++)
    {
        slong a = idx[i], b;

        if (k > 0 && sign_cmp(flist_sign(&U, k - 1), flist_sign(L, a),
                              L->len) == 0)
            continue;
        b = flist_push(&U);
        if (b < 0)
        {
            free(idx);
            flist_clear(&U);
            return -1;
        }
        memcpy(flist_sign(&U, b), flist_sign(L, a), (size_t) L->len);
        U.dim[b] = L->dim[a];
        _fmpz_vec_set(U.pt + 3 * b, L->pt + 3 * a, 3);
        k++;
    }
    free(idx);
    flist_clear(L);
    *L = U;
    return 0;
}

/* ---------------------------------------------------------------------
   The enumeration.  */

void
ref_cells_init(ref_cells_t C)
{
    C->m = 0;
    C->count = 0;
    C->sign = NULL;
    C->dim = NULL;
}

void
ref_cells_clear(ref_cells_t C)
{
    free(C->sign);
    free(C->dim);
    ref_cells_init(C);
}

/* Append to L the vector of signs s_j if nonzero, else side *
   sign(G_j . d), with dimension dim.  Returns 0 or -1.  */
static int
push_perturbed(flist * L, const fmpz_mat_t G, const signed char * s,
               const fmpz * d, int side, slong dim)
{
    slong i = flist_push(L), j;
    signed char * t;

    if (i < 0)
        return -1;
    t = flist_sign(L, i);
    for (j = 0; j < G->r; j++)
        t[j] = (signed char) (s != NULL && s[j] != 0 ? s[j]
                              : side * dot_sgn(G->rows[j], d));
    L->dim[i] = dim;
    return 0;
}

int
ref_cells_faces(ref_cells_t C, const fmpz_mat_t H)
{
    slong m = H->r, mt = m + 3, p, q, i, j;
    fmpz_mat_t G;
    fmpz u[3], w[3];
    flist rays, sectors, chambers, all;
    slong * zero = NULL;
    int side, status = -1;

    ref_cells_clear(C);
    fmpz_mat_init(G, mt, 3);
    for (i = 0; i < m; i++)
        for (j = 0; j < 3; j++)
            fmpz_set(fmpz_mat_entry(G, i, j), fmpz_mat_entry(H, i, j));
    for (j = 0; j < 3; j++)
        fmpz_one(fmpz_mat_entry(G, m + j, j));
    for (i = 0; i < 3; i++)
    {
        fmpz_init(u + i);
        fmpz_init(w + i);
    }
    flist_init(&rays, mt);
    flist_init(&sectors, mt);
    flist_init(&chambers, mt);
    flist_init(&all, m);
    zero = malloc(sizeof(slong) * (size_t) mt);
    if (zero == NULL)
        goto cleanup;

    /* rays: +-(h_p x h_q) */
    for (p = 0; p < mt; p++)
        for (q = p + 1; q < mt; q++)
        {
            cross(u, G->rows[p], G->rows[q]);
            if (is_zero3(u))
                continue;
            for (side = 1; side >= -1; side -= 2)
            {
                if (push_perturbed(&rays, G, NULL, u, side, 1) != 0)
                    goto cleanup;
                _fmpz_vec_scalar_mul_si(rays.pt + 3 * (rays.count - 1),
                                        u, 3, side);
            }
        }
    if (flist_unique(&rays) != 0)
        goto cleanup;

    /* sectors: u + e w, w = +-(h_p x u), for every plane p through u */
    for (i = 0; i < rays.count; i++)
    {
        const signed char * s = flist_sign(&rays, i);

        for (p = 0; p < mt; p++)
        {
            if (s[p] != 0 || is_zero3(G->rows[p]))
                continue;
            cross(w, G->rows[p], rays.pt + 3 * i);
            for (side = 1; side >= -1; side -= 2)
                if (push_perturbed(&sectors, G, s, w, side, 2) != 0)
                    goto cleanup;
        }
    }
    if (flist_unique(&sectors) != 0)
        goto cleanup;

    /* chambers: s +- e h_p, p a plane holding the sector */
    for (i = 0; i < sectors.count; i++)
    {
        const signed char * s = flist_sign(&sectors, i);

        for (p = 0; p < mt && (s[p] != 0 || is_zero3(G->rows[p])); p++)
            ;
        if (p == mt)
            goto cleanup;   /* a sector on no plane */
        for (side = 1; side >= -1; side -= 2)
            if (push_perturbed(&chambers, G, s, G->rows[p], side, 3) != 0)
                goto cleanup;
    }
    if (flist_unique(&chambers) != 0)
        goto cleanup;

    /* every face, its dimension checked, cut down to the rows of H */
    {
        const flist * part[3] = { &rays, &sectors, &chambers };
        slong k, a;

        a = flist_push(&all);
        if (a < 0)
            goto cleanup;
        memset(flist_sign(&all, a), 0, (size_t) m);
        all.dim[a] = 0;
        for (k = 0; k < 3; k++)
            for (i = 0; i < part[k]->count; i++)
            {
                const signed char * s = flist_sign(part[k], i);
                slong nz = 0;

                for (j = 0; j < mt; j++)
                    if (s[j] == 0)
                        zero[nz++] = j;
                if (3 - rank_rows(G, zero, nz) != part[k]->dim[i])
                    goto cleanup;
                nz = 0;
                for (j = 0; j < m; j++)
                    if (s[j] == 0)
                        zero[nz++] = j;
                a = flist_push(&all);
                if (a < 0)
                    goto cleanup;
                memcpy(flist_sign(&all, a), s, (size_t) m);
                all.dim[a] = 3 - rank_rows(H, zero, nz);
            }
    }
    if (flist_unique(&all) != 0)
        goto cleanup;

    C->m = m;
    C->count = all.count;
    C->sign = malloc((size_t) (all.count * (m > 0 ? m : 1)));
    C->dim = malloc(sizeof(slong) * (size_t) all.count);
    if (C->sign == NULL || C->dim == NULL)
    {
        ref_cells_clear(C);
        goto cleanup;
    }
    for (i = 0; i < all.count; i++)
    {
        memcpy(C->sign + i * m, flist_sign(&all, i), (size_t) m);
        C->dim[i] = all.dim[i];
    }
    status = 0;

cleanup:
    free(zero);
    flist_clear(&rays);
    flist_clear(&sectors);
    flist_clear(&chambers);
    flist_clear(&all);
    for (i = 0; i < 3; i++)
    {
        fmpz_clear(u + i);
        fmpz_clear(w + i);
    }
    fmpz_mat_clear(G);
    return status;
}

/* ---------------------------------------------------------------------
   The planes.  */

static int
row_cmp(const fmpz * a, const fmpz * b)
{
    int j, c;

    for (j = 0; j < 3; j++)
        if ((c = fmpz_cmp(a + j, b + j)) != 0)
            return c;
    return 0;
}

void
ref_cells_planes(fmpz_mat_t planes, const fmpz_mat_t normals)
{
    slong m = normals->r, k = 0, i, j;
    fmpz_mat_t T;
    fmpz_t g;

    fmpz_init(g);
    fmpz_mat_init(T, m + 3, 3);
    for (i = 0; i < m + 3; i++)
    {
        fmpz * t = T->rows[k];

        if (i < m)
            _fmpz_vec_set(t, normals->rows[i], 3);
        else
        {
            _fmpz_vec_zero(t, 3);
            fmpz_one(t + (i - m));
        }
        if (is_zero3(t))
            continue;
        fmpz_gcd(g, t + 0, t + 1);
        fmpz_gcd(g, g, t + 2);
        for (j = 0; j < 3; j++)
            fmpz_divexact(t + j, t + j, g);
        for (j = 0; j < 3 && fmpz_is_zero(t + j); j++)
            ;
        if (fmpz_sgn(t + j) < 0)
            _fmpz_vec_neg(t, t, 3);
        k++;
    }
    /* insertion sort, dropping repeats: k is small */
    fmpz_mat_clear(planes);
    fmpz_mat_init(planes, k, 3);
    {
        slong n = 0, a;

        for (i = 0; i < k; i++)
        {
            for (a = 0; a < n && row_cmp(planes->rows[a], T->rows[i]) < 0;
                 a++)
                ;
            if (a < n && row_cmp(planes->rows[a], T->rows[i]) == 0)
                continue;
            for (j = n; j > a; j--)
                _fmpz_vec_set(planes->rows[j], planes->rows[j - 1], 3);
            _fmpz_vec_set(planes->rows[a], T->rows[i], 3);
            n++;
        }
        if (n < k)
        {
            fmpz_mat_t S;

            fmpz_mat_init(S, n, 3);
            for (i = 0; i < n; i++)
                _fmpz_vec_set(S->rows[i], planes->rows[i], 3);
            fmpz_mat_swap(S, planes);
            fmpz_mat_clear(S);
        }
    }
    fmpz_mat_clear(T);
    fmpz_clear(g);
}
