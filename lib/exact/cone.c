/* cone.c -- exact NNC cones in canonical form.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   One conversion per cone computes the closure: hull3.c in dimension 3,
   cddlib (cddbridge.c) otherwise or on request; everything else --
   canonical vectors, redundancy removal, a consistency check of the
   conversion, the face lattice and strictness -- is exact linear algebra
   here.  A face
   is identified by the set of closure rays it contains (the lineality
   space lies in every face), and every face is an intersection of facets,
   so the lattice is the closure of the facets' ray sets under
   intersection.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "core/error.h"
#include "exact/vec3.h"
#include "exact/cone.h"
#include "exact/cddbridge.h"
#include "exact/hull3.h"
#include "exact/cone3.h"

/* ---------------------------------------------------------------------
   Small helpers on rows.  */

static slong
nrows(const fmpq_mat_t A)
{
    return A == NULL ? 0 : fmpq_mat_nrows(A);
}

/* out := the rows of A above the rows of B (either may be NULL); out is
   initialised here.  */
static void
vstack(fmpq_mat_t out, const fmpq_mat_t A, const fmpq_mat_t B, slong d)
{
    slong na = nrows(A), nb = nrows(B), i, j;

    fmpq_mat_init(out, na + nb, d);
    for (i = 0; i < na; i++)
        for (j = 0; j < d; j++)
            fmpq_set(fmpq_mat_entry(out, i, j), fmpq_mat_entry(A, i, j));
    for (i = 0; i < nb; i++)
        for (j = 0; j < d; j++)
            fmpq_set(fmpq_mat_entry(out, na + i, j), fmpq_mat_entry(B, i, j));
}

static int
vec_cmp(const fmpz * a, const fmpz * b, slong d)
{
    slong j;
    int c;

    for (j = 0; j < d; j++)
        if ((c = fmpz_cmp(a + j, b + j)) != 0)
            return c;
    return 0;
}

/* Sign of a.b.  */
static int
dot_sgn(const fmpz * a, const fmpz * b, slong d)
{
    fmpz_t s;
    int r;

    fmpz_init(s);
    _fmpz_vec_dot(s, a, b, d);
    r = fmpz_sgn(s);
    fmpz_clear(s);
    return r;
}

/* out := the rows of A in reduced row echelon form (its rank many rows).  */
static slong
rref_rows(fmpq_mat_t out, const fmpq_mat_t A, slong d)
{
    fmpq_mat_t R;
    slong r, i, j;

    if (nrows(A) == 0)
    {
        fmpq_mat_clear(out);
        fmpq_mat_init(out, 0, d);
        return 0;
    }
    fmpq_mat_init(R, fmpq_mat_nrows(A), d);
    r = fmpq_mat_rref(R, A);
    fmpq_mat_clear(out);
    fmpq_mat_init(out, r, d);
    for (i = 0; i < r; i++)
        for (j = 0; j < d; j++)
            fmpq_set(fmpq_mat_entry(out, i, j), fmpq_mat_entry(R, i, j));
    fmpq_mat_clear(R);
    return r;
}

/* out := a basis (rows) of { x : A x = 0 }.  */
static void
nullspace_rows(fmpq_mat_t out, const fmpq_mat_t A, slong d)
{
    fmpq_mat_t R;
    slong r, i, j, k, f;
    slong * pivot = flint_malloc(sizeof(slong) * (d + 1));
    int * is_pivot = flint_calloc(d + 1, sizeof(int));

    fmpq_mat_init(R, 0, d);
    r = rref_rows(R, A, d);
    for (i = 0; i < r; i++)
    {
        for (j = 0; fmpq_is_zero(fmpq_mat_entry(R, i, j)); j++)
            ;
        pivot[i] = j;
        is_pivot[j] = 1;
    }
    fmpq_mat_clear(out);
    fmpq_mat_init(out, d - r, d);
    for (f = 0, k = 0; f < d; f++)
    {
        if (is_pivot[f])
            continue;
        fmpq_one(fmpq_mat_entry(out, k, f));
        for (i = 0; i < r; i++)
            fmpq_neg(fmpq_mat_entry(out, k, pivot[i]),
                     fmpq_mat_entry(R, i, f));
        k++;
    }
    fmpq_mat_clear(R);
    flint_free(pivot);
    flint_free(is_pivot);
}

/* Replace every row a of A by its orthogonal projection onto the
   complement of the row space of U (U's rows independent).  */
static void
project_out(fmpq_mat_t A, const fmpq_mat_t U)
{
    slong k = nrows(U), d = fmpq_mat_ncols(A), i;
    fmpq_mat_t Ut, G, Gi, P, T, Ad;

    if (k == 0 || nrows(A) == 0)
        return;
    fmpq_mat_init(Ut, d, k);
    fmpq_mat_init(G, k, k);
    fmpq_mat_init(Gi, k, k);
    fmpq_mat_init(T, d, k);
    fmpq_mat_init(P, d, d);
    fmpq_mat_init(Ad, nrows(A), d);
    fmpq_mat_transpose(Ut, U);
    fmpq_mat_mul(G, U, Ut);
    fmpq_mat_inv(Gi, G);
    fmpq_mat_mul(T, Ut, Gi);
    fmpq_mat_mul(P, T, U);          /* projector onto the row space of U */
    fmpq_mat_neg(P, P);
    for (i = 0; i < d; i++)
        fmpq_add_si(fmpq_mat_entry(P, i, i), fmpq_mat_entry(P, i, i), 1);
    fmpq_mat_mul(Ad, A, P);         /* P is symmetric */
    fmpq_mat_swap(A, Ad);
    fmpq_mat_clear(Ut);
    fmpq_mat_clear(G);
    fmpq_mat_clear(Gi);
    fmpq_mat_clear(T);
    fmpq_mat_clear(P);
    fmpq_mat_clear(Ad);
}

typedef struct
{
    const fmpz * row;
    slong d;
}
row_ref;

static int
row_ref_cmp(const void * a, const void * b)
{
    const row_ref * x = a, * y = b;

    return vec_cmp(x->row, y->row, x->d);
}

/* out := the rows of A made primitive, zero rows dropped, sorted and
   without repeats.  */
static void
canonical_rows(fmpz_mat_t out, const fmpq_mat_t A, slong d)
{
    slong m = nrows(A), i, j, k = 0;
    fmpz_mat_t V;
    row_ref * ref = flint_malloc(sizeof(row_ref) * (m + 1));

    fmpz_mat_init(V, m, d);
    for (i = 0; i < m; i++)
    {
        _wc_qvec_primitive(WC_ROW(V, i), WC_ROW(A, i),
                           fmpq_mat_ncols(A));
        if (!_fmpz_vec_is_zero(WC_ROW(V, i), d))
        {
            ref[k].row = WC_ROW(V, i);
            ref[k++].d = d;
        }
    }
    qsort(ref, k, sizeof(row_ref), row_ref_cmp);
    for (i = 0, j = 0; i < k; i++)
        if (j == 0 || vec_cmp(ref[j - 1].row, ref[i].row, d) != 0)
            ref[j++] = ref[i];
    fmpz_mat_clear(out);
    fmpz_mat_init(out, j, d);
    for (i = 0; i < j; i++)
        _fmpz_vec_set(WC_ROW(out, i), ref[i].row, d);
    fmpz_mat_clear(V);
    flint_free(ref);
}

/* out := the canonical basis of the row space of A: its RREF with rows
   made primitive (the RREF's leading ones keep the leading entries
   positive).  */
static void
canonical_basis(fmpz_mat_t out, const fmpq_mat_t A, slong d)
{
    fmpq_mat_t R;
    slong r, i;

    fmpq_mat_init(R, 0, d);
    r = rref_rows(R, A, d);
    fmpz_mat_clear(out);
    fmpz_mat_init(out, r, d);
    for (i = 0; i < r; i++)
        _wc_qvec_primitive(WC_ROW(out, i), WC_ROW(R, i),
                           fmpq_mat_ncols(R));
    fmpq_mat_clear(R);
}

static void
fmpz_mat_to_fmpq(fmpq_mat_t out, const fmpz_mat_t A)
{
    fmpq_mat_clear(out);
    fmpq_mat_init(out, fmpz_mat_nrows(A), fmpz_mat_ncols(A));
    fmpq_mat_set_fmpz_mat(out, A);
}

/* Rank of the rows of A selected by sel (NULL: none) stacked with all
   rows of B and of B2 (either may be NULL).  */
static slong
rank_of(const fmpz_mat_t A, const int * sel, const fmpz_mat_t B,
        const fmpz_mat_t B2, slong d)
{
    slong m = 0, i, r = 0;
    fmpz_mat_t S;

    if (sel != NULL)
        for (i = 0; i < fmpz_mat_nrows(A); i++)
            m += sel[i] != 0;
    if (B != NULL)
        m += fmpz_mat_nrows(B);
    if (B2 != NULL)
        m += fmpz_mat_nrows(B2);
    if (m == 0)
        return 0;
    fmpz_mat_init(S, m, d);
    if (sel != NULL)
        for (i = 0; i < fmpz_mat_nrows(A); i++)
            if (sel[i])
                _fmpz_vec_set(WC_ROW(S, r++), WC_ROW(A, i), d);
    if (B != NULL)
        for (i = 0; i < fmpz_mat_nrows(B); i++)
            _fmpz_vec_set(WC_ROW(S, r++), WC_ROW(B, i), d);
    if (B2 != NULL)
        for (i = 0; i < fmpz_mat_nrows(B2); i++)
            _fmpz_vec_set(WC_ROW(S, r++), WC_ROW(B2, i), d);
    r = fmpz_mat_rank(S);
    fmpz_mat_clear(S);
    return r;
}

/* Keep the rows i of A with keep[i].  */
static void
select_rows(fmpz_mat_t A, const int * keep)
{
    slong m = fmpz_mat_nrows(A), d = fmpz_mat_ncols(A), i, k = 0;
    fmpz_mat_t B;

    for (i = 0; i < m; i++)
        k += keep[i] != 0;
    fmpz_mat_init(B, k, d);
    for (i = 0, k = 0; i < m; i++)
        if (keep[i])
            _fmpz_vec_set(WC_ROW(B, k++), WC_ROW(A, i), d);
    fmpz_mat_swap(A, B);
    fmpz_mat_clear(B);
}

/* ---------------------------------------------------------------------
   Bit sets of ray indices.  */

typedef struct
{
    slong words;
    ulong * bits;       /* words per set, sets stored contiguously */
}
bitsets;

#define BIT_TEST(s, j) (((s)[(j) / FLINT_BITS] >> ((j) % FLINT_BITS)) & 1)
#define BIT_SET(s, j) ((s)[(j) / FLINT_BITS] |= UWORD(1) << ((j) % FLINT_BITS))

static int
bits_subset(const ulong * a, const ulong * b, slong words)
{
    slong w;

    for (w = 0; w < words; w++)
        if (a[w] & ~b[w])
            return 0;
    return 1;
}

/* inc (m sets over k rays): ray j is in set i iff H_i . R_j = 0.  */
static ulong *
incidence(const fmpz_mat_t H, const fmpz_mat_t R, slong d, slong words)
{
    slong m = fmpz_mat_nrows(H), k = fmpz_mat_nrows(R), i, j;
    ulong * inc = flint_calloc(m * words + 1, sizeof(ulong));

    for (i = 0; i < m; i++)
        for (j = 0; j < k; j++)
            if (dot_sgn(WC_ROW(H, i), WC_ROW(R, j), d) == 0)
                BIT_SET(inc + i * words, j);
    return inc;
}

/* ---------------------------------------------------------------------
   The cone type.  */

void
wc_cone_init(wc_cone_t C, slong d)
{
    C->d = d;
    C->empty = 1;
    C->dim = -1;
    C->lineality_dim = 0;
    fmpz_mat_init(C->ineqs, 0, d);
    fmpz_mat_init(C->eqs, 0, d);
    fmpz_mat_init(C->rays, 0, d);
    fmpz_mat_init(C->lines, 0, d);
    C->nfaces = 0;
    C->faces = NULL;
}

static void
clear_faces(wc_cone_t C)
{
    slong i;

    for (i = 0; i < C->nfaces; i++)
        flint_free(C->faces[i].rays);
    flint_free(C->faces);
    C->faces = NULL;
    C->nfaces = 0;
}

void
wc_cone_clear(wc_cone_t C)
{
    clear_faces(C);
    fmpz_mat_clear(C->ineqs);
    fmpz_mat_clear(C->eqs);
    fmpz_mat_clear(C->rays);
    fmpz_mat_clear(C->lines);
}

void
wc_cone_set_empty(wc_cone_t C)
{
    slong d = C->d;

    wc_cone_clear(C);
    wc_cone_init(C, d);
}

void
wc_cone_swap(wc_cone_t A, wc_cone_t B)
{
    wc_cone_struct t = *A;

    *A = *B;
    *B = t;
}

static int
face_cmp(const wc_face_struct * a, const wc_face_struct * b)
{
    slong i;

    if (a->dim != b->dim)
        return a->dim < b->dim ? -1 : 1;
    for (i = 0; i < a->nrays && i < b->nrays; i++)
        if (a->rays[i] != b->rays[i])
            return a->rays[i] < b->rays[i] ? -1 : 1;
    if (a->nrays != b->nrays)
        return a->nrays < b->nrays ? -1 : 1;
    return 0;
}

/* The faces of the closure: every intersection of facet ray sets, plus
   the whole cone; all marked included.  */
static void
build_faces(wc_cone_t C)
{
    slong d = C->d, k = fmpz_mat_nrows(C->rays), m = fmpz_mat_nrows(C->ineqs);
    slong words = k / FLINT_BITS + 1, nf = 1, alloc = 16, q, i, j, w;
    ulong * inc = incidence(C->ineqs, C->rays, d, words);
    ulong * faces = flint_calloc(alloc * words, sizeof(ulong));
    ulong * g = flint_malloc(sizeof(ulong) * words);
    int * sel = flint_malloc(sizeof(int) * (k + 1));

    for (j = 0; j < k; j++)
        BIT_SET(faces, j);
    for (q = 0; q < nf; q++)
    {
        for (i = 0; i < m; i++)
        {
            int seen = 0;

            for (w = 0; w < words; w++)
                g[w] = faces[q * words + w] & inc[i * words + w];
            for (j = 0; j < nf && !seen; j++)
                seen = memcmp(g, faces + j * words,
                              sizeof(ulong) * words) == 0;
            if (seen)
                continue;
            if (nf == alloc)
            {
                alloc *= 2;
                faces = flint_realloc(faces, sizeof(ulong) * alloc * words);
            }
            memcpy(faces + nf * words, g, sizeof(ulong) * words);
            nf++;
        }
    }

    clear_faces(C);
    C->faces = flint_malloc(sizeof(wc_face_struct) * nf);
    C->nfaces = nf;
    for (q = 0; q < nf; q++)
    {
        wc_face_struct * F = C->faces + q;
        slong c = 0;

        for (j = 0; j < k; j++)
            c += sel[j] = BIT_TEST(faces + q * words, j);
        F->nrays = c;
        F->rays = flint_malloc(sizeof(slong) * (c + 1));
        for (j = 0, c = 0; j < k; j++)
            if (sel[j])
                F->rays[c++] = j;
        F->dim = C->lineality_dim + rank_of(C->rays, sel, NULL, NULL, d);
        F->included = 1;
    }
    /* Insertion sort: a 3-dimensional cone has at most 2k + 2 faces.  */
    for (q = 1; q < nf; q++)
    {
        wc_face_struct t = C->faces[q];

        for (j = q; j > 0 && face_cmp(C->faces + j - 1, &t) > 0; j--)
            C->faces[j] = C->faces[j - 1];
        C->faces[j] = t;
    }
    flint_free(inc);
    flint_free(faces);
    flint_free(g);
    flint_free(sel);
}

/* 1 when h . x > 0 for a ray x of C, or h . l != 0 for a line l.  */
static int
cuts(const fmpz * h, const wc_cone_t C)
{
    slong j, d = C->d;

    for (j = 0; j < fmpz_mat_nrows(C->rays); j++)
        if (dot_sgn(h, WC_ROW(C->rays, j), d) > 0)
            return 1;
    for (j = 0; j < fmpz_mat_nrows(C->lines); j++)
        if (dot_sgn(h, WC_ROW(C->lines, j), d) != 0)
            return 1;
    return 0;
}

/* Set the closure of C, a nonempty closed cone described completely both
   by generators (rays, lines) and by constraints E x = 0, H x <= 0 (with
   any redundancy).  Its lineality space is { x : E x = 0, H x = 0 } --
   read from the constraints, as generators may span lines without saying
   so -- and its linear hull is the span of the generators.  */
static int
set_closure(wc_cone_t C, const fmpq_mat_t rays, const fmpq_mat_t lines,
            const fmpq_mat_t E, const fmpq_mat_t H, wc_error_t err)
{
    slong d = C->d, nr = nrows(rays), i, j, k, m;
    fmpq_mat_t S, EH, Lq, Eq, R, Hq;
    int * keep, * sel, status = WC_OK;

    vstack(S, rays, lines, d);

    /* Lines and equalities: canonical bases.  */
    vstack(EH, E, H, d);
    fmpq_mat_init(Lq, 0, d);
    nullspace_rows(Lq, EH, d);
    C->lineality_dim = nrows(Lq);   /* a basis: independent rows */
    canonical_basis(C->lines, Lq, d);
    fmpq_mat_init(Eq, 0, d);
    nullspace_rows(Eq, S, d);
    canonical_basis(C->eqs, Eq, d);
    C->dim = d - fmpz_mat_nrows(C->eqs);
    fmpz_mat_to_fmpq(Eq, C->eqs);

    /* Rays onto the complement of the lineality space, facet normals onto
       the linear hull (the complement of the equalities).  */
    fmpq_mat_init(R, nr, d);
    if (nr > 0)
        fmpq_mat_set(R, rays);
    project_out(R, Lq);
    canonical_rows(C->rays, R, d);
    fmpq_mat_init(Hq, nrows(H), d);
    if (nrows(H) > 0)
        fmpq_mat_set(Hq, H);
    project_out(Hq, Eq);
    canonical_rows(C->ineqs, Hq, d);

    /* The conversion is checked, not trusted: every facet holds on every
       generator.  */
    k = fmpz_mat_nrows(C->rays);
    m = fmpz_mat_nrows(C->ineqs);
    for (i = 0; i < m; i++)
        if (cuts(WC_ROW(C->ineqs, i), C))
        {
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: the cone conversion gave "
                                  "an inequality that cuts a generator");
            goto cleanup;
        }

    /* Redundancy: a facet's tight rays span dim - 1 (with the lines); an
       extreme ray's tight facets span d - 1 (with equalities, lines).  */
    keep = flint_malloc(sizeof(int) * (m + 1));
    sel = flint_malloc(sizeof(int) * (k + m + 1));
    for (i = 0; i < m; i++)
    {
        for (j = 0; j < k; j++)
            sel[j] = dot_sgn(WC_ROW(C->ineqs, i),
                             WC_ROW(C->rays, j), d) == 0;
        keep[i] = rank_of(C->rays, sel, C->lines, NULL, d) == C->dim - 1;
    }
    select_rows(C->ineqs, keep);
    m = fmpz_mat_nrows(C->ineqs);
    flint_free(keep);
    keep = flint_malloc(sizeof(int) * (k + 1));
    for (j = 0; j < k; j++)
    {
        for (i = 0; i < m; i++)
            sel[i] = dot_sgn(WC_ROW(C->ineqs, i),
                             WC_ROW(C->rays, j), d) == 0;
        keep[j] = rank_of(C->ineqs, sel, C->eqs, C->lines, d) == d - 1;
    }
    select_rows(C->rays, keep);
    flint_free(keep);
    flint_free(sel);

    C->empty = 0;
    build_faces(C);

cleanup:
    fmpq_mat_clear(S);
    fmpq_mat_clear(EH);
    fmpq_mat_clear(Lq);
    fmpq_mat_clear(Eq);
    fmpq_mat_clear(R);
    fmpq_mat_clear(Hq);
    return status;
}

/* Sum of the rays of face F.  */
static void
face_point(fmpz * p, const wc_cone_t C, const wc_face_struct * F)
{
    slong i;

    _fmpz_vec_zero(p, C->d);
    for (i = 0; i < F->nrays; i++)
        _fmpz_vec_add(p, p, WC_ROW(C->rays, F->rays[i]), C->d);
}

int
wc_cone_set_hrep(wc_cone_t C, const fmpq_mat_t eqs, const fmpq_mat_t ineqs,
                 const fmpq_mat_t strict, wc_error_t err)
{
    return _wc_cone_set_hrep_kernel(C, eqs, ineqs, strict, 0, err);
}

int
_wc_cone_set_hrep_kernel(wc_cone_t C, const fmpq_mat_t eqs,
                         const fmpq_mat_t ineqs, const fmpq_mat_t strict,
                         int use_cdd, wc_error_t err)
{
    slong d = C->d, ns = nrows(strict), i, f;
    fmpq_mat_t H, rays, lines;
    fmpz_mat_t Sz;
    fmpz * p = _fmpz_vec_init(d);
    int status, done = 0;

    vstack(H, ineqs, strict, d);
    fmpq_mat_init(rays, 0, d);
    fmpq_mat_init(lines, 0, d);
    fmpz_mat_init(Sz, ns, d);

    wc_cone_set_empty(C);
    /* d = 3: the fan (pointed cones, the origin) first.  */
    if (d == 3 && !use_cdd
        && (status = _wc_cone3_hrep(C, &done, eqs, H, err)) != WC_OK)
        goto cleanup;
    if (!done)
    {
        status = (d == 3 && !use_cdd)
            ? _wc_hull3_h_to_v(rays, lines, eqs, H, err)
            : _wc_cdd_h_to_v(rays, lines, d, eqs, H, err);
        if (status != WC_OK)
            goto cleanup;
        status = set_closure(C, rays, lines, eqs, H, err);
        if (status != WC_OK)
            goto cleanup;
    }

    /* The strict rows hold strictly on the relative interior of exactly
       the faces they do not vanish on; the cone is empty when they fail
       on the closure's own relative interior.  */
    for (i = 0; i < ns; i++)
        _wc_qvec_primitive(WC_ROW(Sz, i), WC_ROW(strict, i),
                           fmpq_mat_ncols(strict));
    for (f = 0; f < C->nfaces; f++)
    {
        face_point(p, C, C->faces + f);
        for (i = 0; i < ns; i++)
            if (dot_sgn(WC_ROW(Sz, i), p, d) >= 0)
                C->faces[f].included = 0;
    }
    if (!C->faces[C->nfaces - 1].included)
        wc_cone_set_empty(C);

cleanup:
    if (status != WC_OK)
        wc_cone_set_empty(C);
    fmpq_mat_clear(H);
    fmpq_mat_clear(rays);
    fmpq_mat_clear(lines);
    fmpz_mat_clear(Sz);
    _fmpz_vec_clear(p, d);
    return status;
}

int
wc_cone_set_generators(wc_cone_t C, const fmpq_mat_t rays,
                       const fmpq_mat_t lines, wc_error_t err)
{
    return _wc_cone_set_generators_kernel(C, rays, lines, 0, err);
}

int
_wc_cone_set_generators_kernel(wc_cone_t C, const fmpq_mat_t rays,
                               const fmpq_mat_t lines, int use_cdd,
                               wc_error_t err)
{
    slong d = C->d;
    fmpq_mat_t E, H;
    int status, done = 0;

    wc_cone_set_empty(C);
    /* d = 3: the fan (pointed cones, R^3) first.  */
    if (d == 3 && !use_cdd)
    {
        status = _wc_cone3_generators(C, &done, rays, lines, err);
        if (status != WC_OK || done)
            return status;
    }
    fmpq_mat_init(E, 0, d);
    fmpq_mat_init(H, 0, d);
    status = (d == 3 && !use_cdd)
        ? _wc_hull3_v_to_h(E, H, rays, lines, err)
        : _wc_cdd_v_to_h(E, H, d, rays, lines, err);
    if (status == WC_OK)
        status = set_closure(C, rays, lines, E, H, err);
    if (status != WC_OK)
        wc_cone_set_empty(C);
    fmpq_mat_clear(E);
    fmpq_mat_clear(H);
    return status;
}

/* Find the face of C whose ray set is sel (k flags); -1 if none.  */
static slong
find_face(const wc_cone_t C, const int * sel)
{
    slong f, i, c, k = fmpz_mat_nrows(C->rays);

    for (f = 0; f < C->nfaces; f++)
    {
        const wc_face_struct * F = C->faces + f;

        for (i = 0, c = 0; i < k; i++)
            if (sel[i])
            {
                if (c >= F->nrays || F->rays[c] != i)
                    break;
                c++;
            }
        if (i == k && c == F->nrays)
            return f;
    }
    return -1;
}

int
wc_cone_image_sum(wc_cone_t W, const fmpq_mat_t T, const wc_cone_t V,
                  const fmpq_mat_t Q, wc_error_t err)
{
    slong d = W->d, e = V->d;
    slong kv, lv, i, j, f, m, k, words;
    fmpq_mat_t Vr, Vl, TVr, TVl, Tt, G;
    fmpz_mat_t TVz;
    ulong * inc = NULL, * tight = NULL, * tf = NULL;
    int * sel = NULL;
    int status = WC_OK;

    if (V->empty)
    {
        wc_cone_set_empty(W);
        return WC_OK;
    }
    kv = fmpz_mat_nrows(V->rays);
    lv = fmpz_mat_nrows(V->lines);
    fmpq_mat_init(Vr, kv, e);
    fmpq_mat_init(Vl, lv, e);
    fmpq_mat_set_fmpz_mat(Vr, V->rays);
    fmpq_mat_set_fmpz_mat(Vl, V->lines);
    fmpq_mat_init(Tt, e, d);
    fmpq_mat_transpose(Tt, T);
    fmpq_mat_init(TVr, kv, d);
    fmpq_mat_init(TVl, lv, d);
    if (kv > 0)
        fmpq_mat_mul(TVr, Vr, Tt);
    if (lv > 0)
        fmpq_mat_mul(TVl, Vl, Tt);
    vstack(G, TVr, Q, d);
    fmpz_mat_init(TVz, kv, d);

    status = wc_cone_set_generators(W, G, TVl, err);
    if (status != WC_OK)
        goto cleanup;

    /* A face F of cl W, exposed by h, meets T V + pos Q in
       T (V cap G) + (pos Q cap F), where G is the face of cl V that T maps
       into F (exposed by T^T h); its rays are V's rays whose images lie in
       F.  F is included iff G is.  */
    m = fmpz_mat_nrows(W->ineqs);
    k = fmpz_mat_nrows(W->rays);
    words = k / FLINT_BITS + 1;
    inc = incidence(W->ineqs, W->rays, d, words);
    for (i = 0; i < kv; i++)
        _wc_qvec_primitive(WC_ROW(TVz, i), WC_ROW(TVr, i),
                           fmpq_mat_ncols(TVr));
    tight = incidence(W->ineqs, TVz, d, kv / FLINT_BITS + 1);
    tf = flint_calloc(m / FLINT_BITS + 1, sizeof(ulong));
    sel = flint_malloc(sizeof(int) * (kv + 1));
    for (f = 0; f < W->nfaces; f++)
    {
        wc_face_struct * F = W->faces + f;
        ulong * fr = flint_calloc(words, sizeof(ulong));
        slong g;

        for (i = 0; i < F->nrays; i++)
            BIT_SET(fr, F->rays[i]);
        /* tf: the facets of W containing F.  */
        memset(tf, 0, sizeof(ulong) * (m / FLINT_BITS + 1));
        for (i = 0; i < m; i++)
            if (bits_subset(fr, inc + i * words, words))
                BIT_SET(tf, i);
        flint_free(fr);
        /* V's ray j maps into F iff it is tight on every facet in tf.  */
        for (j = 0; j < kv; j++)
        {
            sel[j] = 1;
            for (i = 0; i < m && sel[j]; i++)
                if (BIT_TEST(tf, i)
                    && !BIT_TEST(tight + i * (kv / FLINT_BITS + 1), j))
                    sel[j] = 0;
        }
        g = find_face(V, sel);
        if (g < 0)
        {
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: no face of V maps onto "
                                  "face %ld of the image", (long) f);
            goto cleanup;
        }
        F->included = V->faces[g].included;
    }

cleanup:
    if (status != WC_OK)
        wc_cone_set_empty(W);
    fmpq_mat_clear(Vr);
    fmpq_mat_clear(Vl);
    fmpq_mat_clear(TVr);
    fmpq_mat_clear(TVl);
    fmpq_mat_clear(Tt);
    fmpq_mat_clear(G);
    fmpz_mat_clear(TVz);
    flint_free(inc);
    flint_free(tight);
    flint_free(tf);
    flint_free(sel);
    return status;
}

int
wc_cone_equal(const wc_cone_t A, const wc_cone_t B)
{
    slong f, i;

    if (A->d != B->d || A->empty != B->empty)
        return 0;
    if (A->empty)
        return 1;
    if (A->dim != B->dim || A->lineality_dim != B->lineality_dim
        || A->nfaces != B->nfaces)
        return 0;
    if (fmpz_mat_nrows(A->rays) != fmpz_mat_nrows(B->rays)
        || fmpz_mat_nrows(A->ineqs) != fmpz_mat_nrows(B->ineqs)
        || fmpz_mat_nrows(A->eqs) != fmpz_mat_nrows(B->eqs)
        || fmpz_mat_nrows(A->lines) != fmpz_mat_nrows(B->lines))
        return 0;
    if (!fmpz_mat_equal(A->rays, B->rays) || !fmpz_mat_equal(A->ineqs, B->ineqs)
        || !fmpz_mat_equal(A->eqs, B->eqs) || !fmpz_mat_equal(A->lines, B->lines))
        return 0;
    for (f = 0; f < A->nfaces; f++)
    {
        const wc_face_struct * a = A->faces + f, * b = B->faces + f;

        if (face_cmp(a, b) != 0 || a->included != b->included)
            return 0;
        for (i = 0; i < a->nrays; i++)
            if (a->rays[i] != b->rays[i])
                return 0;
    }
    return 1;
}

slong
wc_cone_locate(const wc_cone_t C, const fmpq * g)
{
    slong d = C->d, i, j, k, m, f = -1;
    fmpz * v;
    int * sel;

    if (C->empty)
        return -1;
    k = fmpz_mat_nrows(C->rays);
    m = fmpz_mat_nrows(C->ineqs);
    v = _fmpz_vec_init(d);
    _wc_qvec_primitive(v, g, d);
    sel = flint_malloc(sizeof(int) * (k + 1));
    for (i = 0; i < fmpz_mat_nrows(C->eqs); i++)
        if (dot_sgn(WC_ROW(C->eqs, i), v, d) != 0)
            goto cleanup;
    for (i = 0; i < m; i++)
        if (dot_sgn(WC_ROW(C->ineqs, i), v, d) > 0)
            goto cleanup;
    /* The smallest face holding g: the rays on every facet tight at g.  */
    for (j = 0; j < k; j++)
        sel[j] = 1;
    for (i = 0; i < m; i++)
        if (dot_sgn(WC_ROW(C->ineqs, i), v, d) == 0)
            for (j = 0; j < k; j++)
                if (dot_sgn(WC_ROW(C->ineqs, i),
                            WC_ROW(C->rays, j), d) != 0)
                    sel[j] = 0;
    f = find_face(C, sel);

cleanup:
    _fmpz_vec_clear(v, d);
    flint_free(sel);
    return f;
}

int
wc_cone_contains(const wc_cone_t C, const fmpq * g)
{
    slong f = wc_cone_locate(C, g);

    return f >= 0 && C->faces[f].included;
}

slong
wc_cone_excluded_faces(const wc_cone_t C)
{
    slong f, c = 0;

    if (C->empty)
        return 0;
    for (f = 0; f < C->nfaces; f++)
        c += !C->faces[f].included;
    return c;
}
