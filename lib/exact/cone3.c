/* cone3.c -- canonical cones in R^3 straight from the fan.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The canonical form is cone.h's, field for field: primitive rays and
   facet normals sorted lexicographically, faces sorted by dimension and
   then by their ray index lists.  A pointed 3-dimensional cone has no
   lines or equalities, so nothing is projected; its 2-faces are the
   pairs of cyclically consecutive extreme rays.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "core/error.h"
#include "exact/vec3.h"
#include "exact/hull3.h"
#include "exact/cone3.h"

typedef struct
{
    const fmpz * row;
    slong idx;
}
ref3;

static int
ref3_cmp(const ref3 * x, const ref3 * y)
{
    slong j;
    int c;

    for (j = 0; j < 3; j++)
    {
        fmpz a = x->row[j], b = y->row[j];

        /* Two word integers compare as words (what fmpz_cmp does, without
           the call).  */
        if (!COEFF_IS_MPZ(a) && !COEFF_IS_MPZ(b))
            c = (a > b) - (a < b);
        else
            c = fmpz_cmp(x->row + j, y->row + j);
        if (c != 0)
            return c;
    }
    return 0;
}

/* Bottom-up merge sort of r[0..m) (tmp: m slots), without qsort's
   indirect calls.  */
static void
sort_refs(ref3 * r, ref3 * tmp, slong m)
{
    slong w, i;

    for (w = 1; w < m; w *= 2)
    {
        for (i = 0; i < m; i += 2 * w)
        {
            slong mid = FLINT_MIN(i + w, m), hi = FLINT_MIN(i + 2 * w, m);
            slong a = i, b = mid, o = i;

            while (a < mid && b < hi)
                tmp[o++] = ref3_cmp(r + b, r + a) < 0 ? r[b++] : r[a++];
            while (a < mid)
                tmp[o++] = r[a++];
            while (b < hi)
                tmp[o++] = r[b++];
        }
        memcpy(r, tmp, sizeof(ref3) * m);
    }
}

/* d := s, word entries copied as words.  */
static void
set3(fmpz * d, const fmpz * s)
{
    slong j;

    for (j = 0; j < 3; j++)
        if (!COEFF_IS_MPZ(d[j]) && !COEFF_IS_MPZ(s[j]))
            d[j] = s[j];
        else
            fmpz_set(d + j, s + j);
}

/* A := the m rows V (3m entries) sorted; pos[i] := the sorted index of
   row i (when pos is not NULL).  */
static int
sorted_rows(fmpz_mat_t A, const fmpz * V, slong m, slong * pos)
{
    ref3 * r = malloc(sizeof(ref3) * (2 * m + 1));
    slong i;

    if (r == NULL)
        return 0;
    for (i = 0; i < m; i++)
    {
        r[i].row = V + 3 * i;
        r[i].idx = i;
    }
    sort_refs(r, r + m, m);
    if (fmpz_mat_nrows(A) != m || fmpz_mat_ncols(A) != 3)
    {
        fmpz_mat_clear(A);
        fmpz_mat_init(A, m, 3);
    }
    for (i = 0; i < m; i++)
    {
        set3(WC_ROW(A, i), r[i].row);
        if (pos != NULL)
            pos[r[i].idx] = i;
    }
    free(r);
    return 1;
}

/* The face of C's fan of m rays at index f: 0, the m rays, the m 2-faces,
   the cone.  */
static slong
face_nrays(slong f, slong m)
{
    return f == 0 ? 0 : f <= m ? 1 : f <= 2 * m ? 2 : m;
}

/* 1 when C already has the shape of a pointed 3-D fan of m rays (the
   previous answer, often): its matrices and face arrays are then kept and
   every entry set again, instead of freed and allocated.  A face of
   nrays rays has room for nrays indices, whoever set it.  */
static int
fan_shaped(const wc_cone_t C, slong m)
{
    slong f;

    if (C->d != 3 || C->nfaces != 2 * m + 2 || C->faces == NULL
        || fmpz_mat_nrows(C->rays) != m || fmpz_mat_nrows(C->ineqs) != m
        || fmpz_mat_ncols(C->rays) != 3 || fmpz_mat_ncols(C->ineqs) != 3
        || fmpz_mat_nrows(C->eqs) != 0 || fmpz_mat_nrows(C->lines) != 0)
        return 0;
    for (f = 0; f < C->nfaces; f++)
        if (C->faces[f].nrays != face_nrays(f, m)
            || (f > 0 && C->faces[f].rays == NULL))
            return 0;
    return 1;
}

/* Face F of dimension dim and n rays (a, b when n <= 2, else 0 .. n-1),
   its index array allocated unless keep.  */
static int
put_face(wc_face_struct * F, int keep, slong dim, slong n, slong a,
         slong b)
{
    slong i;

    F->dim = dim;
    F->nrays = n;
    F->included = 1;
    if (!keep && (F->rays = flint_malloc(sizeof(slong) * (n + 1))) == NULL)
        return 0;
    if (n == 1)
        F->rays[0] = a;
    else if (n == 2)
    {
        F->rays[0] = a;
        F->rays[1] = b;
    }
    else
        for (i = 0; i < n; i++)
            F->rays[i] = i;
    return 1;
}

/* The 2-faces of C, faces m + 1 .. 2m: the pairs of cyclically
   consecutive rays (sorted indices pos), in lexicographic order, in
   O(m): each index is the smaller of at most two pairs.  nb: 2m slots.  */
static int
put_edges(wc_cone_t C, int keep, const slong * pos, slong m, slong * nb)
{
    slong i, a, f = m + 1;
    int ok = 1;

    for (i = 0; i < 2 * m; i++)
        nb[i] = -1;
    for (i = 0; i < m; i++)
    {
        slong x = pos[i], y = pos[(i + 1) % m];

        a = FLINT_MIN(x, y);
        nb[2 * a + (nb[2 * a] >= 0)] = FLINT_MAX(x, y);
    }
    for (a = 0; a < m && ok; a++)
    {
        slong b0 = nb[2 * a], b1 = nb[2 * a + 1];

        if (b1 >= 0 && b1 < b0)
        {
            b1 = b0;
            b0 = nb[2 * a + 1];
        }
        if (b0 >= 0)
            ok = put_face(C->faces + f++, keep, 2, 2, a, b0);
        if (b1 >= 0 && ok)
            ok = put_face(C->faces + f++, keep, 2, 2, a, b1);
    }
    return ok;
}

int
_wc_cone3_set_fan(wc_cone_t C, const _wc_fan3_t F, int polar)
{
    slong m = F->m, i, f = 0;
    slong * pos = malloc(sizeof(slong) * (3 * m + 1));
    int keep = fan_shaped(C, m), ok = pos != NULL;

    if (!keep)
        wc_cone_set_empty(C);
    /* Cone: rays R_i, facet i holds R_i and R_{i+1}.  Polar: rays F's
       facets, and facet F.rays_{i+1} holds F.facets_i and F.facets_{i+1}:
       the same cyclic pairs.  */
    ok = ok && sorted_rows(C->rays, polar ? F->facets : F->rays, m, pos)
        && sorted_rows(C->ineqs, polar ? F->rays : F->facets, m, NULL);
    if (ok && !keep)
        C->faces = flint_calloc(2 * m + 2, sizeof(wc_face_struct));
    if (!ok || C->faces == NULL)
        goto fail;
    C->nfaces = 2 * m + 2;
    ok = put_face(C->faces + f++, keep, 0, 0, 0, 0);
    for (i = 0; i < m && ok; i++)
        ok = put_face(C->faces + f++, keep, 1, 1, i, 0);
    ok = ok && put_edges(C, keep, pos, m, pos + m);
    f = 2 * m + 1;
    ok = ok && put_face(C->faces + f, keep, 3, m, 0, 0);
    if (!ok)
        goto fail;
    C->empty = 0;
    C->dim = 3;
    C->lineality_dim = 0;
    free(pos);
    return WC_OK;

fail:
    wc_cone_set_empty(C);
    free(pos);
    return WC_EINTERNAL;
}

/* One face of dimension dim and no rays.  */
static void
one_face(wc_cone_t C, slong dim)
{
    C->faces = flint_malloc(sizeof(wc_face_struct));
    C->nfaces = 1;
    put_face(C->faces, 0, dim, 0, 0, 0);
    C->empty = 0;
}

/* C := R^3 (space = 1: the identity as its lines) or { 0 } (the
   identity as its equalities); one face of dimension 3 or 0.  */
static void
set_whole(wc_cone_t C, int space)
{
    fmpz_mat_struct * basis;

    wc_cone_set_empty(C);
    basis = space ? C->lines : C->eqs;
    fmpz_mat_clear(basis);
    fmpz_mat_init(basis, 3, 3);
    fmpz_mat_one(basis);
    C->dim = space ? 3 : 0;
    C->lineality_dim = space ? 3 : 0;
    one_face(C, C->dim);
}

void
_wc_cone3_set_space(wc_cone_t C)
{
    set_whole(C, 1);
}

void
_wc_cone3_set_origin(wc_cone_t C)
{
    set_whole(C, 0);
}

/* Row i of A := (a, b, c) made primitive.  */
static void
set_row(fmpz_mat_t A, slong i, const fmpz_t a, const fmpz_t b,
        const fmpz_t c)
{
    fmpz * r = WC_ROW(A, i);
    fmpz_t g;

    fmpz_set(r + 0, a);
    fmpz_set(r + 1, b);
    fmpz_set(r + 2, c);
    fmpz_init(g);
    _wc_zvec3_primitive(r, g);
    fmpz_clear(g);
}

void
_wc_cone3_set_line(wc_cone_t C, const fmpz * v)
{
    fmpz * l;
    fmpz_t zero, one, t, z;
    slong j;
    int s;

    wc_cone_set_empty(C);
    fmpz_init(zero);
    fmpz_init_set_ui(one, 1);
    fmpz_init(t);
    fmpz_init(z);
    /* The line: v made primitive, its leading entry positive (the RREF
       row made primitive).  */
    fmpz_mat_clear(C->lines);
    fmpz_mat_init(C->lines, 1, 3);
    l = WC_ROW(C->lines, 0);
    set_row(C->lines, 0, v + 0, v + 1, v + 2);
    for (j = 0; fmpz_is_zero(l + j); j++)
        ;
    if (fmpz_sgn(l + j) < 0)
        _fmpz_vec_neg(l, l, 3);
    /* The equalities: the RREF basis of the plane l . x = 0, rows made
       primitive.  l_2 != 0: pivots 0 and 1, rows (1, 0, -l_0 / l_2) and
       (0, 1, -l_1 / l_2), times |l_2|; l_2 = 0 != l_1: pivots 0 and 2,
       (1, -l_0 / l_1, 0) times |l_1| and (0, 0, 1); else (0, 1, 0) and
       (0, 0, 1).  */
    fmpz_mat_clear(C->eqs);
    fmpz_mat_init(C->eqs, 2, 3);
    j = !fmpz_is_zero(l + 2) ? 2 : 1;
    s = fmpz_sgn(l + j);
    fmpz_abs(t, l + j);
    if (s != 0)
    {
        fmpz_mul_si(z, l + 0, -s);
        if (j == 2)
            set_row(C->eqs, 0, t, zero, z);
        else
            set_row(C->eqs, 0, t, z, zero);
    }
    else
        set_row(C->eqs, 0, zero, one, zero);
    if (j == 2)
    {
        fmpz_mul_si(z, l + 1, -s);
        set_row(C->eqs, 1, zero, t, z);
    }
    else
        set_row(C->eqs, 1, zero, zero, one);
    fmpz_clear(zero);
    fmpz_clear(one);
    fmpz_clear(t);
    fmpz_clear(z);
    C->dim = 1;
    C->lineality_dim = 1;
    one_face(C, 1);
}

static int
nomem(wc_error_t err)
{
    return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                        "internal error: out of memory in the 3-D kernel");
}

/* The fan of the first k rows of G into C.  */
static int
from_fan(wc_cone_t C, int * done, const fmpz_mat_t G, slong k, int polar,
         wc_error_t err)
{
    _wc_fan3_t F;
    int r, status = WC_OK;

    _wc_fan3_init(F);
    r = k == 0 ? WC_FAN3_OTHER : _wc_fan3(F, WC_ROW(G, 0), k);
    *done = r != WC_FAN3_OTHER;
    if (r == WC_FAN3_NOMEM)
        status = nomem(err);
    else if (r == WC_FAN3_POINTED)
        status = _wc_cone3_set_fan(C, F, polar);
    else if (r == WC_FAN3_SPACE && polar)
        _wc_cone3_set_origin(C);
    else if (r == WC_FAN3_SPACE)
        _wc_cone3_set_space(C);
    if (status != WC_OK)
        wc_cone_set_empty(C);
    _wc_fan3_clear(F);
    return status;
}

int
_wc_cone3_generators(wc_cone_t C, int * done, const fmpq_mat_t rays,
                     const fmpq_mat_t lines, wc_error_t err)
{
    fmpz_mat_t G;
    slong k;
    int status;

    *done = 0;
    fmpz_mat_init(G, 0, 3);
    if (!_wc_hull3_generators(G, &k, rays, lines))
        status = nomem(err);
    else
        status = from_fan(C, done, G, k, 0, err);
    fmpz_mat_clear(G);
    return status;
}

/* 1 when the rows of E span R^3; reads rows only until three
   independent ones are found (each scaled to integers).  */
static int
spans3(const fmpq_mat_t E)
{
    fmpz * v = _fmpz_vec_init(9), * w = _fmpz_vec_init(3);
    fmpz_t den, t;
    slong i, r = 0;

    fmpz_init(den);
    fmpz_init(t);
    for (i = 0; E != NULL && i < fmpq_mat_nrows(E) && r < 3; i++)
    {
        fmpz * x = v + 3 * r;

        _fmpq_vec_get_fmpz_vec_fmpz(x, den, WC_ROW(E, i), 3);
        if (r == 0)
            r = !_fmpz_vec_is_zero(x, 3);
        else if (r == 1)
        {
            _wc_zvec3_cross(w, v, x);
            r = _fmpz_vec_is_zero(w, 3) ? 1 : 2;
        }
        else
            r = _wc_zvec3_dot_sgn(w, x, t) != 0 ? 3 : 2;
    }
    _fmpz_vec_clear(v, 9);
    _fmpz_vec_clear(w, 3);
    fmpz_clear(den);
    fmpz_clear(t);
    return r == 3;
}

int
_wc_cone3_hrep(wc_cone_t C, int * done, const fmpq_mat_t eqs,
               const fmpq_mat_t H, wc_error_t err)
{
    fmpz_mat_t G;
    slong k;
    int status = WC_OK;

    *done = 0;
    fmpz_mat_init(G, 0, 3);
    if (spans3(eqs))
    {
        _wc_cone3_set_origin(C);
        *done = 1;
    }
    else if (!_wc_hull3_generators(G, &k, eqs, NULL))
        status = nomem(err);
    else if (k == 0)    /* (equalities of rank 1 or 2: the general route) */
    {
        if (!_wc_hull3_generators(G, &k, H, NULL))
            status = nomem(err);
        else
            status = from_fan(C, done, G, k, 1, err);
    }
    fmpz_mat_clear(G);
    return status;
}
