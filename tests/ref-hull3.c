/* ref-hull3.c -- an independent reference for the 3-D cone conversion.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Written from SPEC.md section 2.4 and the headers only, without reading
   lib/exact or tests/old-hull3.c (the library's former kernel); it uses
   FLINT's integer and rational matrices and nothing of lib/.

   Both directions are brute force over candidates, each checked exactly
   against every row, with the candidates chosen by the dimension r of
   the relevant row space (generators for V to H, constraint rows for H
   to V), so that every face sought is found by some candidate:
   - V to H, r = 3: a facet holds two independent generators, so its
     normal is +-(g_i x g_j); r = 2: the facet of a sector in the plane
     with normal n holds one generator g, its normal is +-(n x g);
     r = 1: +-g.  A valid candidate (h . g <= 0 for every g) that is not
     zero on every generator is a facet.
   - H to V, with l = 3 - r the dimension of the lineality space: r = 3
     (pointed), an extreme ray is tight on two independent rows, so it is
     +-(a_i x a_j); r = 2 (one line u), an extreme ray of the quotient is
     tight on one row and orthogonal to u: +-(u x a_i); r = 1: +-a_i.
     A nonzero feasible candidate is then extreme.
   Every candidate is orthogonal to the space the canonical form projects
   off, so only gcd, sorting and deduplication remain.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpq_vec.h>
#include <flint/fmpq_mat.h>

#include "ref-hull3.h"

/* A growable list of integer 3-vectors.  */
typedef struct
{
    fmpz * v;
    slong n, cap;
}
vlist;

static void
vl_init(vlist * L)
{
    L->v = NULL;
    L->n = L->cap = 0;
}

static void
vl_clear(vlist * L)
{
    if (L->v != NULL)
        _fmpz_vec_clear(L->v, 3 * L->cap);
    vl_init(L);
}

static fmpz *
vl_row(const vlist * L, slong i)
{
    return L->v + 3 * i;
}

static void
vl_push(vlist * L, const fmpz * x)
{
    if (L->n == L->cap)
    {
        slong cap = L->cap ? 2 * L->cap : 16;
        fmpz * w = _fmpz_vec_init(3 * cap);

        if (L->v != NULL)
        {
            _fmpz_vec_swap(w, L->v, 3 * L->n);
            _fmpz_vec_clear(L->v, 3 * L->cap);
        }
        L->v = w;
        L->cap = cap;
    }
    _fmpz_vec_set(vl_row(L, L->n), x, 3);
    L->n++;
}

/* x := x / gcd(x) (sign kept); 0 stays 0.  */
static void
make_primitive(fmpz * x)
{
    fmpz_t g;

    fmpz_init(g);
    fmpz_gcd(g, x + 0, x + 1);
    fmpz_gcd(g, g, x + 2);
    if (!fmpz_is_zero(g) && !fmpz_is_one(g))
    {
        fmpz_divexact(x + 0, x + 0, g);
        fmpz_divexact(x + 1, x + 1, g);
        fmpz_divexact(x + 2, x + 2, g);
    }
    fmpz_clear(g);
}

static int
is_zero3(const fmpz * x)
{
    return fmpz_is_zero(x) && fmpz_is_zero(x + 1) && fmpz_is_zero(x + 2);
}

static void
dot3(fmpz_t d, const fmpz * a, const fmpz * b)
{
    fmpz_mul(d, a, b);
    fmpz_addmul(d, a + 1, b + 1);
    fmpz_addmul(d, a + 2, b + 2);
}

static void
cross3(fmpz * c, const fmpz * a, const fmpz * b)
{
    fmpz_mul(c + 0, a + 1, b + 2);
    fmpz_submul(c + 0, a + 2, b + 1);
    fmpz_mul(c + 1, a + 2, b + 0);
    fmpz_submul(c + 1, a + 0, b + 2);
    fmpz_mul(c + 2, a + 0, b + 1);
    fmpz_submul(c + 2, a + 1, b + 0);
}

/* Append the rows of A (times sign), denominators cleared, as primitive
   integer vectors; zero rows are skipped.  */
static void
push_rows(vlist * L, const fmpq_mat_t A, int sign)
{
    fmpz * x = _fmpz_vec_init(3);
    fmpz_t m;
    slong i, j;

    fmpz_init(m);
    for (i = 0; A != NULL && i < fmpq_mat_nrows(A); i++)
    {
        fmpz_one(m);
        for (j = 0; j < 3; j++)
            fmpz_lcm(m, m, fmpq_denref(fmpq_mat_entry(A, i, j)));
        for (j = 0; j < 3; j++)
        {
            fmpz_divexact(x + j, m, fmpq_denref(fmpq_mat_entry(A, i, j)));
            fmpz_mul(x + j, x + j, fmpq_numref(fmpq_mat_entry(A, i, j)));
            if (sign < 0)
                fmpz_neg(x + j, x + j);
        }
        make_primitive(x);
        if (!is_zero3(x))
            vl_push(L, x);
    }
    fmpz_clear(m);
    _fmpz_vec_clear(x, 3);
}

static void
set_q_z(fmpq * x, const fmpz * a)
{
    fmpz_set(fmpq_numref(x), a);
    fmpz_one(fmpq_denref(x));
}

static int
cmp3(const void * pa, const void * pb)
{
    const fmpz * a = pa, * b = pb;
    int j, c;

    for (j = 0; j < 3; j++)
        if ((c = fmpz_cmp(a + j, b + j)) != 0)
            return c;
    return 0;
}

/* S := the rows of L, sorted, repeats removed.  */
static void
vl_to_sorted_mat(fmpz_mat_t S, vlist * L)
{
    slong i, n = 0;

    if (L->n > 0)
        qsort(L->v, L->n, 3 * sizeof(fmpz), cmp3);
    for (i = 0; i < L->n; i++)
        if (n == 0 || cmp3(vl_row(L, n - 1), vl_row(L, i)) != 0)
        {
            if (n != i)
                _fmpz_vec_swap(vl_row(L, n), vl_row(L, i), 3);
            n++;
        }
    fmpz_mat_clear(S);
    fmpz_mat_init(S, n, 3);
    for (i = 0; i < n; i++)
        _fmpz_vec_set(S->rows[i], vl_row(L, i), 3);
}

/* The rank of the rows of L.  */
static slong
vl_rank(const vlist * L)
{
    fmpz_mat_t A;
    slong i, r;

    if (L->n == 0)
        return 0;
    fmpz_mat_init(A, L->n, 3);
    for (i = 0; i < L->n; i++)
        _fmpz_vec_set(A->rows[i], vl_row(L, i), 3);
    r = fmpz_mat_rank(A);
    fmpz_mat_clear(A);
    return r;
}

/* S := the canonical basis of the orthogonal complement of the row space
   of the rows of L (the null space of L as a matrix).  */
static void
vl_complement(fmpz_mat_t S, const vlist * L)
{
    fmpz_mat_t A, X;
    fmpq_mat_t B;
    slong i, j, nul;

    fmpz_mat_init(A, L->n > 0 ? L->n : 1, 3);      /* a zero row if none */
    for (i = 0; i < L->n; i++)
        _fmpz_vec_set(A->rows[i], vl_row(L, i), 3);
    fmpz_mat_init(X, 3, 3);
    nul = fmpz_mat_nullspace(X, A);                 /* basis in columns */
    fmpq_mat_init(B, nul, 3);
    for (i = 0; i < nul; i++)
        for (j = 0; j < 3; j++)
            set_q_z(fmpq_mat_entry(B, i, j),
                               fmpz_mat_entry(X, j, i));
    ref_hull3_span(S, B);
    fmpq_mat_clear(B);
    fmpz_mat_clear(X);
    fmpz_mat_clear(A);
}

void
ref_hull3_span(fmpz_mat_t S, const fmpq_mat_t A)
{
    fmpq_mat_t R;
    fmpz_t m;
    slong r, i, j;

    r = 0;
    fmpq_mat_init(R, A != NULL ? fmpq_mat_nrows(A) : 0, 3);
    if (A != NULL && fmpq_mat_nrows(A) > 0)
        r = fmpq_mat_rref(R, A);
    fmpz_mat_clear(S);
    fmpz_mat_init(S, r, 3);
    fmpz_init(m);
    for (i = 0; i < r; i++)
    {
        fmpz_one(m);
        for (j = 0; j < 3; j++)
            fmpz_lcm(m, m, fmpq_denref(fmpq_mat_entry(R, i, j)));
        for (j = 0; j < 3; j++)
        {
            fmpz_divexact(fmpz_mat_entry(S, i, j), m,
                          fmpq_denref(fmpq_mat_entry(R, i, j)));
            fmpz_mul(fmpz_mat_entry(S, i, j), fmpz_mat_entry(S, i, j),
                     fmpq_numref(fmpq_mat_entry(R, i, j)));
        }
        make_primitive(S->rows[i]);
    }
    fmpz_clear(m);
    fmpq_mat_clear(R);
}

/* Test +c and -c against the rows: each row a of T must have a . x = 0
   ("tight" rows: equalities), each row of V a . x <= 0.  Push every
   feasible sign of c (primitive) onto out; skip c = 0 and candidates
   zero on all of V when zero_ok is 0.  */
static void
try_candidate(vlist * out, fmpz * c, const vlist * T, const vlist * V,
              int zero_ok)
{
    fmpz_t d;
    slong i;
    int pos = 0, neg = 0;

    if (is_zero3(c))
        return;
    fmpz_init(d);
    for (i = 0; i < T->n; i++)
    {
        dot3(d, c, vl_row(T, i));
        if (!fmpz_is_zero(d))
            goto done;
    }
    for (i = 0; i < V->n && !(pos && neg); i++)
    {
        dot3(d, c, vl_row(V, i));
        pos |= fmpz_sgn(d) > 0;
        neg |= fmpz_sgn(d) < 0;
    }
    if (!pos && !neg && !zero_ok)
        goto done;
    make_primitive(c);
    if (!pos)
        vl_push(out, c);                /* c . v <= 0 everywhere */
    if (!neg)
    {
        _fmpz_vec_neg(c, c, 3);
        vl_push(out, c);
        _fmpz_vec_neg(c, c, 3);
    }
done:
    fmpz_clear(d);
}

void
ref_hull3_facets(fmpz_mat_t E, fmpz_mat_t H, const fmpq_mat_t rays,
                 const fmpq_mat_t lines)
{
    vlist G, none, out;
    fmpz * c = _fmpz_vec_init(3);
    slong r, i, j;

    vl_init(&G);
    vl_init(&none);
    vl_init(&out);
    push_rows(&G, rays, 1);
    push_rows(&G, lines, 1);
    push_rows(&G, lines, -1);
    r = vl_rank(&G);
    vl_complement(E, &G);
    for (i = 0; i < G.n; i++)
    {
        if (r == 1)
        {
            _fmpz_vec_set(c, vl_row(&G, i), 3);
            try_candidate(&out, c, &none, &G, 0);
        }
        else if (r == 2)
        {
            cross3(c, E->rows[0], vl_row(&G, i));
            try_candidate(&out, c, &none, &G, 0);
        }
        else if (r == 3)
            for (j = i + 1; j < G.n; j++)
            {
                cross3(c, vl_row(&G, i), vl_row(&G, j));
                try_candidate(&out, c, &none, &G, 0);
            }
    }
    vl_to_sorted_mat(H, &out);
    _fmpz_vec_clear(c, 3);
    vl_clear(&G);
    vl_clear(&none);
    vl_clear(&out);
}

void
ref_hull3_rays(fmpz_mat_t L, fmpz_mat_t R, const fmpq_mat_t E,
               const fmpq_mat_t H)
{
    vlist T, V, A, out;
    fmpz * c = _fmpz_vec_init(3);
    slong r, i, j;

    vl_init(&T);
    vl_init(&V);
    vl_init(&A);
    vl_init(&out);
    push_rows(&T, E, 1);
    push_rows(&V, H, 1);
    push_rows(&A, E, 1);
    push_rows(&A, H, 1);
    r = vl_rank(&A);
    vl_complement(L, &A);
    for (i = 0; i < A.n; i++)
    {
        if (r == 1)
        {
            _fmpz_vec_set(c, vl_row(&A, i), 3);
            try_candidate(&out, c, &T, &V, 1);
        }
        else if (r == 2)
        {
            cross3(c, L->rows[0], vl_row(&A, i));
            try_candidate(&out, c, &T, &V, 1);
        }
        else if (r == 3)
            for (j = i + 1; j < A.n; j++)
            {
                cross3(c, vl_row(&A, i), vl_row(&A, j));
                try_candidate(&out, c, &T, &V, 1);
            }
    }
    vl_to_sorted_mat(R, &out);
    _fmpz_vec_clear(c, 3);
    vl_clear(&T);
    vl_clear(&V);
    vl_clear(&A);
    vl_clear(&out);
}

void
ref_hull3_canon(fmpz_mat_t S, const fmpq_mat_t A, const fmpz_mat_t B)
{
    vlist in, out;
    fmpq * q = _fmpq_vec_init(9);       /* an orthogonal basis of B */
    fmpq * x = _fmpq_vec_init(3);
    fmpq_t t, u;
    fmpz * z = _fmpz_vec_init(3);
    slong nq = 0, i, j, k;

    fmpq_init(t);
    fmpq_init(u);
    vl_init(&in);
    vl_init(&out);
    /* Gram-Schmidt on the rows of B, in rationals.  */
    for (i = 0; B != NULL && i < fmpz_mat_nrows(B); i++)
    {
        for (j = 0; j < 3; j++)
            set_q_z(x + j, fmpz_mat_entry(B, i, j));
        for (k = 0; k < nq; k++)
        {
            _fmpq_vec_dot(t, x, q + 3 * k, 3);
            _fmpq_vec_dot(u, q + 3 * k, q + 3 * k, 3);
            fmpq_div(t, t, u);
            for (j = 0; j < 3; j++)
                fmpq_submul(x + j, t, q + 3 * k + j);
        }
        if (!(fmpq_is_zero(x) && fmpq_is_zero(x + 1) && fmpq_is_zero(x + 2))
            && nq < 3)
        {
            for (j = 0; j < 3; j++)
                fmpq_set(q + 3 * nq + j, x + j);
            nq++;
        }
    }
    push_rows(&in, A, 1);
    for (i = 0; i < in.n; i++)
    {
        for (j = 0; j < 3; j++)
            set_q_z(x + j, vl_row(&in, i) + j);
        for (k = 0; k < nq; k++)
        {
            _fmpq_vec_dot(t, x, q + 3 * k, 3);
            _fmpq_vec_dot(u, q + 3 * k, q + 3 * k, 3);
            fmpq_div(t, t, u);
            for (j = 0; j < 3; j++)
                fmpq_submul(x + j, t, q + 3 * k + j);
        }
        /* clear denominators: the numerators times lcm / den */
        fmpz_one(fmpq_numref(u));
        for (j = 0; j < 3; j++)
            fmpz_lcm(fmpq_numref(u), fmpq_numref(u), fmpq_denref(x + j));
        for (j = 0; j < 3; j++)
        {
            fmpz_divexact(z + j, fmpq_numref(u), fmpq_denref(x + j));
            fmpz_mul(z + j, z + j, fmpq_numref(x + j));
        }
        make_primitive(z);
        if (!is_zero3(z))
            vl_push(&out, z);
    }
    vl_to_sorted_mat(S, &out);
    fmpq_clear(t);
    fmpq_clear(u);
    _fmpz_vec_clear(z, 3);
    _fmpq_vec_clear(q, 9);
    _fmpq_vec_clear(x, 3);
    vl_clear(&in);
    vl_clear(&out);
}
