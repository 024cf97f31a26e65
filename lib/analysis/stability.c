/* stability.c -- weak and strong stability (paper Section 7, SPEC 2.5):
   one wrench by exact LPs, or every set exactly, as pieces.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The moving solutions of the complementarity problem at zero velocity are
   grouped by the mode string y of the motion (stability.h).  For a face y
   and a wrench g the question "is there a motion of face y" is the
   homogeneous system in z = (nudot, lambda, tau), tau the homogenising
   variable of g:

     M nudot - sum_j lambda_j w_j - tau g = 0       (three rows)
     y's rows on nudot (Table 1 signs of a = J^T nudot)
     lambda_j >= 0,  tau > 0

   where w_j = e_n J_in + e_t J_it runs over the friction edges (e_n, e_t)
   that y's letters allow (n: both mu_s edges, l: (1, -mu_k), r: (1, mu_k),
   s: none).  A solution with tau > 0 scaled to tau = 1 is a motion
   (nudot, c = sum lambda_j (e_n, e_t) at the edges' fixels).  Without one,
   Motzkin's transposition theorem gives multipliers, the certificate
   verify.c checks: the rows here are exactly the rows documented in
   verify.h, in the same order.

   Every LP is homogeneous: strict rows become >= 1, and a feasible answer
   is checked against every row exactly before it is believed; so are the
   multipliers.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "wrenchcone.h"
#include "analysis/stability.h"
#include "exact/cddbridge.h"

#define ROW(A, i) ((A)->rows[i])

static void
qvec_zero(fmpq * v, slong len)
{
    slong i;

    for (i = 0; i < len; i++)
        fmpq_zero(v + i);
}

static void
qvec_set(fmpq * v, const fmpq * w, slong len)
{
    slong i;

    for (i = 0; i < len; i++)
        fmpq_set(v + i, w + i);
}

/* Keep the first r rows of A.  */
static void
shrink(fmpq_mat_t A, slong r)
{
    fmpq_mat_t B;
    slong i, k;

    fmpq_mat_init(B, r, fmpq_mat_ncols(A));
    for (i = 0; i < r; i++)
        for (k = 0; k < fmpq_mat_ncols(A); k++)
            fmpq_set(fmpq_mat_entry(B, i, k), fmpq_mat_entry(A, i, k));
    fmpq_mat_swap(A, B);
    fmpq_mat_clear(B);
}

static int
qvec_is_zero(const fmpq * v, slong len)
{
    slong i;

    for (i = 0; i < len; i++)
        if (!fmpq_is_zero(v + i))
            return 0;
    return 1;
}

/* ---------------------------------------------------------------------
   The model, once per problem.  */

typedef struct
{
    const wc_problem_struct * P;
    slong n, t;
    slong * tidx;           /* the touching fixels, in file order */
    fmpq * Jn, * Jt;        /* 3n each: J's columns n_i, t_i */
    fmpq M[3];              /* diag(m, m, I) */
    int shared;             /* t >= 1 and every touching fixel at one point */
    fmpq v[3];              /* Jn x Jt of the first touching fixel: the
                               rotation about the shared point */
}
model;

static void
cross3(fmpq * c, const fmpq * a, const fmpq * b)
{
    fmpq_t s;

    fmpq_init(s);
    fmpq_mul(c + 0, a + 1, b + 2);
    fmpq_mul(s, a + 2, b + 1);
    fmpq_sub(c + 0, c + 0, s);
    fmpq_mul(c + 1, a + 2, b + 0);
    fmpq_mul(s, a + 0, b + 2);
    fmpq_sub(c + 1, c + 1, s);
    fmpq_mul(c + 2, a + 0, b + 1);
    fmpq_mul(s, a + 1, b + 0);
    fmpq_sub(c + 2, c + 2, s);
    fmpq_clear(s);
}

static void
model_init(model * m, const wc_problem_t P)
{
    slong n = P->n, i, j;
    fmpq_mat_t J;

    m->P = P;
    m->n = n;
    m->t = 0;
    m->tidx = flint_malloc(sizeof(slong) * (n + 1));
    m->Jn = _fmpq_vec_init(3 * n);
    m->Jt = _fmpq_vec_init(3 * n);
    fmpq_mat_init(J, 3, 2 * n);
    wc_model_J(J, P);
    for (i = 0; i < n; i++)
    {
        for (j = 0; j < 3; j++)
        {
            fmpq_set(m->Jn + 3 * i + j, fmpq_mat_entry(J, j, i));
            fmpq_set(m->Jt + 3 * i + j, fmpq_mat_entry(J, j, n + i));
        }
        if (P->fixels[i].state == WC_TOUCHING)
            m->tidx[m->t++] = i;
    }
    fmpq_mat_clear(J);
    for (j = 0; j < 3; j++)
    {
        fmpq_init(m->M + j);
        fmpq_init(m->v + j);
    }
    fmpq_set(m->M + 0, P->mass);
    fmpq_set(m->M + 1, P->mass);
    fmpq_set(m->M + 2, P->inertia);
    m->shared = m->t >= 1;
    for (i = 1; i < m->t && m->shared; i++)
    {
        const wc_fixel_struct * a = P->fixels + m->tidx[0],
            * b = P->fixels + m->tidx[i];

        m->shared = fmpq_equal(a->point + 0, b->point + 0)
            && fmpq_equal(a->point + 1, b->point + 1);
    }
    if (m->t >= 1)
        cross3(m->v, m->Jn + 3 * m->tidx[0], m->Jt + 3 * m->tidx[0]);
}

static void
model_clear(model * m)
{
    slong j;

    flint_free(m->tidx);
    _fmpq_vec_clear(m->Jn, 3 * m->n);
    _fmpq_vec_clear(m->Jt, 3 * m->n);
    for (j = 0; j < 3; j++)
    {
        fmpq_clear(m->M + j);
        fmpq_clear(m->v + j);
    }
}

/* w := e_n J_in + e_t J_it.  */
static void
edge_wrench(fmpq * w, const model * m, slong i, const fmpq * e)
{
    slong k;
    fmpq_t s;

    fmpq_init(s);
    for (k = 0; k < 3; k++)
    {
        fmpq_mul(w + k, e + 0, m->Jn + 3 * i + k);
        fmpq_mul(s, e + 1, m->Jt + 3 * i + k);
        fmpq_add(w + k, w + k, s);
    }
    fmpq_clear(s);
}

/* ---------------------------------------------------------------------
   Homogeneous systems: rows A (m x nv) with relations; a point z with
   A_i z > 0 / >= 0 / = 0, or Motzkin multipliers.  */

static int
rows_hold(const fmpq_mat_t A, const wc_relation * rel, const fmpq * z)
{
    slong m = fmpq_mat_nrows(A), nv = fmpq_mat_ncols(A), i, j;
    fmpq_t s, p;
    int ok = 1;

    fmpq_init(s);
    fmpq_init(p);
    for (i = 0; i < m && ok; i++)
    {
        fmpq_zero(s);
        for (j = 0; j < nv; j++)
        {
            fmpq_mul(p, fmpq_mat_entry(A, i, j), z + j);
            fmpq_add(s, s, p);
        }
        ok = rel[i] == WC_REL_GT ? fmpq_sgn(s) > 0
            : rel[i] == WC_REL_GE ? fmpq_sgn(s) >= 0 : fmpq_is_zero(s);
    }
    fmpq_clear(s);
    fmpq_clear(p);
    return ok;
}

static int
mult_hold(const fmpq_mat_t A, const wc_relation * rel, const fmpq * y)
{
    slong m = fmpq_mat_nrows(A), nv = fmpq_mat_ncols(A), i, j;
    fmpq_t s, p;
    int ok = 1, strict = 0;

    fmpq_init(s);
    fmpq_init(p);
    for (i = 0; i < m && ok; i++)
    {
        if (rel[i] != WC_REL_EQ && fmpq_sgn(y + i) < 0)
            ok = 0;
        if (rel[i] == WC_REL_GT && fmpq_sgn(y + i) > 0)
            strict = 1;
    }
    for (j = 0; j < nv && ok; j++)
    {
        fmpq_zero(s);
        for (i = 0; i < m; i++)
        {
            fmpq_mul(p, y + i, fmpq_mat_entry(A, i, j));
            fmpq_add(s, s, p);
        }
        ok = fmpq_is_zero(s);
    }
    fmpq_clear(s);
    fmpq_clear(p);
    return ok && strict;
}

/* 1: z (nv entries) satisfies every row; 0: no point does, and mult (m
   entries, when not NULL) proves it; -1: failure (err set).  */
static int
motzkin(fmpq * z, fmpq * mult, const fmpq_mat_t A, const wc_relation * rel,
        wc_error_t err)
{
    slong m = fmpq_mat_nrows(A), nv = fmpq_mat_ncols(A), i, j, ngt = 0;
    fmpq * b = _fmpq_vec_init(m + nv + 2);
    int * eq = flint_calloc(m + nv + 2, sizeof(int));
    int found;
    fmpq_mat_t D;
    fmpq * y;

    for (i = 0; i < m; i++)
    {
        if (rel[i] == WC_REL_GT)
        {
            fmpq_one(b + i);
            ngt++;
        }
        eq[i] = rel[i] == WC_REL_EQ;
    }
    if (m == 0)
    {
        qvec_zero(z, nv);
        found = 1;
    }
    else
        found = _wc_cdd_lp_point(z, A, b, eq, err);
    if (found == 1 && !rows_hold(A, rel, z))
        found = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                              "an LP point fails its rows"), -1);
    if (found != 0 || mult == NULL)
        goto done;

    /* sum y_i A_i = 0, sum of the > multipliers = 1, y >= 0 off the =
       rows.  */
    fmpq_mat_init(D, nv + 1 + m, m);
    y = _fmpq_vec_init(m);
    for (i = 0; i < nv + 1 + m; i++)
    {
        fmpq_zero(b + i);
        eq[i] = i <= nv;
    }
    for (j = 0; j < nv; j++)
        for (i = 0; i < m; i++)
            fmpq_set(fmpq_mat_entry(D, j, i), fmpq_mat_entry(A, i, j));
    for (i = 0; i < m; i++)
    {
        if (rel[i] == WC_REL_GT)
            fmpq_one(fmpq_mat_entry(D, nv, i));
        if (rel[i] != WC_REL_EQ)
            fmpq_one(fmpq_mat_entry(D, nv + 1 + i, i));
    }
    fmpq_one(b + nv);
    found = ngt > 0 ? _wc_cdd_lp_point(y, D, b, eq, err) : 0;
    if (found == 1 && mult_hold(A, rel, y))
    {
        qvec_set(mult, y, m);
        found = 0;
    }
    else if (found >= 0)
        found = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                              "an infeasible system without a Motzkin "
                              "certificate"), -1);
    fmpq_mat_clear(D);
    _fmpq_vec_clear(y, m);

done:
    _fmpq_vec_clear(b, m + nv + 2);
    flint_free(eq);
    return found;
}

/* ---------------------------------------------------------------------
   g in pos(G) for k vectors G_j in R^3, exactly, by the revised simplex
   method (phase one, Bland's rule: no cycling) with a 3 x 3 basis: O(k)
   work per pivot, where cddlib would carry a k-column tableau.  Returns 1
   with lambda >= 0, sum lambda_j G_j = g; or 0 with sep, sep . g > 0 and
   sep . G_j <= 0 for every j (the phase-one prices at the optimum).
   Artificial column i is s_i e_i, s_i the sign of g_i (+1 for 0).  */

static int
cone3(fmpq * lambda, fmpq * sep, const fmpq * G, slong k, const fmpq * g)
{
    slong basis[3], i, j, r, it;
    fmpq Binv[9], xB[3], pi[3], u[3], col[3];
    fmpq_t d, t, best, q;
    int sg[3], feasible;

    for (i = 0; i < 9; i++)
        fmpq_init(Binv + i);
    for (i = 0; i < 3; i++)
    {
        fmpq_init(xB + i);
        fmpq_init(pi + i);
        fmpq_init(u + i);
        fmpq_init(col + i);
        sg[i] = fmpq_sgn(g + i) < 0 ? -1 : 1;
        basis[i] = k + i;
        fmpq_set_si(Binv + 4 * i, sg[i], 1);
        fmpq_abs(xB + i, g + i);
    }
    fmpq_init(d);
    fmpq_init(t);
    fmpq_init(best);
    fmpq_init(q);
    for (it = 0; ; it++)
    {
        slong enter = -1;

        /* prices pi = c_B B^-1: c = 1 on artificials */
        for (j = 0; j < 3; j++)
        {
            fmpq_zero(pi + j);
            for (i = 0; i < 3; i++)
                if (basis[i] >= k)
                    fmpq_add(pi + j, pi + j, Binv + 3 * i + j);
        }
        /* entering: the first column with negative reduced cost */
        for (j = 0; j < k + 3 && enter < 0; j++)
        {
            int inb = 0;

            for (i = 0; i < 3; i++)
                inb |= basis[i] == j;
            if (inb)
                continue;
            if (j < k)
            {
                fmpq_mul(d, pi + 0, G + 3 * j);
                fmpq_addmul(d, pi + 1, G + 3 * j + 1);
                fmpq_addmul(d, pi + 2, G + 3 * j + 2);
                fmpq_neg(d, d);
            }
            else
            {
                fmpq_set_si(d, sg[j - k], 1);
                fmpq_mul(d, d, pi + (j - k));
                fmpq_sub_si(d, d, 1);
                fmpq_neg(d, d);
            }
            if (fmpq_sgn(d) < 0)
                enter = j;
        }
        if (enter < 0)
            break;
        for (i = 0; i < 3; i++)
        {
            if (enter < k)
                fmpq_set(col + i, G + 3 * enter + i);
            else
                fmpq_set_si(col + i, i == enter - k ? sg[i] : 0, 1);
        }
        for (i = 0; i < 3; i++)
        {
            fmpq_mul(u + i, Binv + 3 * i, col + 0);
            fmpq_addmul(u + i, Binv + 3 * i + 1, col + 1);
            fmpq_addmul(u + i, Binv + 3 * i + 2, col + 2);
        }
        /* leaving: min ratio, ties to the smallest variable index */
        r = -1;
        for (i = 0; i < 3; i++)
        {
            if (fmpq_sgn(u + i) <= 0)
                continue;
            fmpq_div(q, xB + i, u + i);
            if (r < 0 || fmpq_cmp(q, best) < 0
                || (fmpq_equal(q, best) && basis[i] < basis[r]))
            {
                r = i;
                fmpq_set(best, q);
            }
        }
        if (r < 0)
            break;      /* cannot happen: phase one is bounded below */
        /* pivot on u_r */
        for (i = 0; i < 3; i++)
            if (i != r)
            {
                fmpq_div(t, u + i, u + r);
                for (j = 0; j < 3; j++)
                    fmpq_submul(Binv + 3 * i + j, t, Binv + 3 * r + j);
                fmpq_submul(xB + i, t, xB + r);
            }
        for (j = 0; j < 3; j++)
            fmpq_div(Binv + 3 * r + j, Binv + 3 * r + j, u + r);
        fmpq_div(xB + r, xB + r, u + r);
        basis[r] = enter;
    }
    fmpq_zero(d);
    for (i = 0; i < 3; i++)
        if (basis[i] >= k)
            fmpq_add(d, d, xB + i);
    feasible = fmpq_is_zero(d);
    if (feasible)
    {
        for (j = 0; j < k; j++)
            fmpq_zero(lambda + j);
        for (i = 0; i < 3; i++)
            if (basis[i] < k)
                fmpq_set(lambda + basis[i], xB + i);
    }
    else if (sep != NULL)
        for (j = 0; j < 3; j++)
            fmpq_set(sep + j, pi + j);
    for (i = 0; i < 9; i++)
        fmpq_clear(Binv + i);
    for (i = 0; i < 3; i++)
    {
        fmpq_clear(xB + i);
        fmpq_clear(pi + i);
        fmpq_clear(u + i);
        fmpq_clear(col + i);
    }
    fmpq_clear(d);
    fmpq_clear(t);
    fmpq_clear(best);
    fmpq_clear(q);
    return feasible;
}

/* 1 when cone3's answer checks exactly.  */
static int
cone3_check(int feasible, const fmpq * lambda, const fmpq * sep,
            const fmpq * G, slong k, const fmpq * g)
{
    slong i, j;
    fmpq_t s;
    int ok = 1;

    fmpq_init(s);
    if (feasible)
    {
        for (i = 0; i < 3 && ok; i++)
        {
            fmpq_zero(s);
            for (j = 0; j < k; j++)
                fmpq_addmul(s, lambda + j, G + 3 * j + i);
            ok = fmpq_equal(s, g + i);
        }
        for (j = 0; j < k && ok; j++)
            ok = fmpq_sgn(lambda + j) >= 0;
    }
    else
    {
        fmpq_mul(s, sep + 0, g + 0);
        fmpq_addmul(s, sep + 1, g + 1);
        fmpq_addmul(s, sep + 2, g + 2);
        ok = fmpq_sgn(s) > 0;
        for (j = 0; j < k && ok; j++)
        {
            fmpq_mul(s, sep + 0, G + 3 * j);
            fmpq_addmul(s, sep + 1, G + 3 * j + 1);
            fmpq_addmul(s, sep + 2, G + 3 * j + 2);
            ok = fmpq_sgn(s) <= 0;
        }
    }
    fmpq_clear(s);
    return ok;
}

/* ---------------------------------------------------------------------
   The system of a face.  */

typedef struct
{
    fmpq_mat_t A;           /* rows over z = (nudot, lambda, tau) */
    wc_relation * rel;
    slong rows, e;          /* e edges */
    slong * efix;           /* the fixel of edge j */
    fmpq * edir;            /* 2e: (e_n, e_t) of edge j */
}
facesys;

static void
facesys_clear(facesys * s)
{
    fmpq_mat_clear(s->A);
    flint_free(s->rel);
    flint_free(s->efix);
    _fmpq_vec_clear(s->edir, 2 * s->e + 2);
}

static void
put_row(facesys * s, const fmpq * r, int neg, wc_relation rel)
{
    slong k;

    for (k = 0; k < 3; k++)
        if (neg)
            fmpq_neg(fmpq_mat_entry(s->A, s->rows, k), r + k);
        else
            fmpq_set(fmpq_mat_entry(s->A, s->rows, k), r + k);
    s->rel[s->rows++] = rel;
}

/* y: one letter per fixel for the rows on nudot (touching s l r n; near u,
   s (a_in >= 0) or a (a_in < 0)); x: the force letters (touching s l r n;
   near ones carry none).  rot != 0: the rotation face (y is ignored).  */
static void
facesys_init(facesys * s, const model * m, const char * y, const char * x,
            int rot, const fmpq * g)
{
    const wc_problem_struct * P = m->P;
    slong n = m->n, i, j, k, e = 0, nv, maxrows;
    fmpq ed[4];
    fmpq * w;

    for (j = 0; j < 4; j++)
        fmpq_init(ed + j);
    s->efix = flint_malloc(sizeof(slong) * (2 * n + 1));
    s->edir = _fmpq_vec_init(4 * n + 2);
    for (i = 0; i < n; i++)
    {
        slong c;

        if (P->fixels[i].state != WC_TOUCHING)
            continue;
        c = wc_friction_edges(ed, P->fixels + i, x[i]);
        for (j = 0; j < c; j++, e++)
        {
            s->efix[e] = i;
            fmpq_set(s->edir + 2 * e, ed + 2 * j);
            fmpq_set(s->edir + 2 * e + 1, ed + 2 * j + 1);
        }
    }
    /* keep edir's length 2e + 2 for the clear */
    {
        fmpq * d = _fmpq_vec_init(2 * e + 2);

        qvec_set(d, s->edir, 2 * e);
        _fmpq_vec_clear(s->edir, 4 * n + 2);
        s->edir = d;
    }
    s->e = e;
    nv = 3 + e + 1;
    maxrows = 3 + 2 * n + 1 + e + 1;
    fmpq_mat_init(s->A, maxrows, nv);
    s->rel = flint_malloc(sizeof(wc_relation) * maxrows);
    s->rows = 0;

    w = _fmpq_vec_init(3);
    for (k = 0; k < 3; k++)
    {
        fmpq_set(fmpq_mat_entry(s->A, k, k), m->M + k);
        fmpq_neg(fmpq_mat_entry(s->A, k, nv - 1), g + k);
    }
    for (j = 0; j < e; j++)
    {
        edge_wrench(w, m, s->efix[j], s->edir + 2 * j);
        for (k = 0; k < 3; k++)
            fmpq_neg(fmpq_mat_entry(s->A, k, 3 + j), w + k);
    }
    for (k = 0; k < 3; k++)
        s->rel[k] = WC_REL_EQ;
    s->rows = 3;

    for (i = 0; i < n; i++)
    {
        const fmpq * jn = m->Jn + 3 * i, * jt = m->Jt + 3 * i;
        char c = y[i];

        if (P->fixels[i].state == WC_NEAR)
        {
            if (c == 'a')
                put_row(s, jn, 1, WC_REL_GT);
            else if (c == 's')
                put_row(s, jn, 0, WC_REL_GE);
            continue;
        }
        if (rot != 0)
            c = 'n';
        switch (c)
        {
        case 's':
            put_row(s, jn, 0, WC_REL_GT);
            break;
        case 'l':
            put_row(s, jn, 0, WC_REL_EQ);
            put_row(s, jt, 0, WC_REL_GT);
            break;
        case 'r':
            put_row(s, jn, 0, WC_REL_EQ);
            put_row(s, jt, 1, WC_REL_GT);
            break;
        default:
            put_row(s, jn, 0, WC_REL_EQ);
            put_row(s, jt, 0, WC_REL_EQ);
            break;
        }
    }
    if (rot != 0)
        put_row(s, m->v, rot < 0, WC_REL_GT);
    for (j = 0; j < e; j++)
    {
        fmpq_one(fmpq_mat_entry(s->A, s->rows, 3 + j));
        s->rel[s->rows++] = WC_REL_GE;
    }
    fmpq_one(fmpq_mat_entry(s->A, s->rows, nv - 1));
    s->rel[s->rows++] = WC_REL_GT;

    shrink(s->A, s->rows);
    _fmpq_vec_clear(w, 3);
    for (j = 0; j < 4; j++)
        fmpq_clear(ed + j);
}

/* Read a solution z of s (tau > 0) into nudot and c (2n).  */
static void
facesys_motion(fmpq * nudot, fmpq * c, const facesys * s, const model * m,
              const fmpq * z)
{
    slong n = m->n, j, k;
    const fmpq * tau = z + 3 + s->e;
    fmpq_t q, p;

    fmpq_init(q);
    fmpq_init(p);
    for (k = 0; k < 3; k++)
        fmpq_div(nudot + k, z + k, tau);
    qvec_zero(c, 2 * n);
    for (j = 0; j < s->e; j++)
    {
        slong i = s->efix[j];

        fmpq_div(q, z + 3 + j, tau);
        fmpq_mul(p, q, s->edir + 2 * j);
        fmpq_add(c + i, c + i, p);
        fmpq_mul(p, q, s->edir + 2 * j + 1);
        fmpq_add(c + n + i, c + n + i, p);
    }
    fmpq_clear(q);
    fmpq_clear(p);
}

/* 1 when face y forces nudot = 0 -- every touching letter n, no contact
   point shared by all touching fixels, no near row but a_in >= 0 --, or
   nudot on the rotation line with no near row at all: cone3 decides it.  */
static int
zero_face(const model * m, const char * y)
{
    slong i;

    if (m->t == 0)
        return 0;
    for (i = 0; i < m->n; i++)
    {
        if (m->P->fixels[i].state == WC_TOUCHING ? y[i] != 'n'
            : (m->shared ? y[i] != 'u' : y[i] == 'a'))
            return 0;
    }
    return 1;
}

/* Solve face (y, x, rot) for g: 1 with a motion (nudot, c), 0 without
   (mult filled when asked: *mult malloc'd with *nmult entries), -1 on
   failure.  Faces without a force edge are decided without an LP: the
   motion can only be nudot = M^-1 g.  */
static int
face_solve(fmpq * nudot, fmpq * c, fmpq ** mult, slong * nmult,
           const model * m, const char * y, const char * x, int rot,
           const fmpq * g, wc_error_t err)
{
    facesys s;
    slong nv;
    fmpq * z;
    int r;

    facesys_init(&s, m, y, x, rot, g);
    nv = 3 + s.e + 1;
    z = _fmpq_vec_init(nv);
    if (mult == NULL && rot == 0 && zero_face(m, y))
    {
        /* nudot = 0 (or mu v, v the rotation, when every touching fixel
           shares a point): g = mu M v - sum lambda_j w_j, one cone3.  */
        slong k = s.e + (m->shared ? 2 : 0), j, i;
        fmpq * G = _fmpq_vec_init(3 * k + 3), * lam = _fmpq_vec_init(k + 1);
        fmpq w[3], sep[3];

        for (i = 0; i < 3; i++)
        {
            fmpq_init(w + i);
            fmpq_init(sep + i);
        }
        for (j = 0; j < s.e; j++)
        {
            edge_wrench(w, m, s.efix[j], s.edir + 2 * j);
            for (i = 0; i < 3; i++)
                fmpq_neg(G + 3 * j + i, w + i);
        }
        if (m->shared)
            for (i = 0; i < 3; i++)
            {
                fmpq_mul(G + 3 * s.e + i, m->v + i, m->M + i);
                fmpq_neg(G + 3 * (s.e + 1) + i, G + 3 * s.e + i);
            }
        r = cone3(lam, sep, G, k, g);
        if (!cone3_check(r, lam, sep, G, k, g))
            r = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal "
                              "error: a cone membership fails its check"), -1);
        if (r == 1)
        {
            qvec_zero(z, nv);
            for (j = 0; j < s.e; j++)
                fmpq_set(z + 3 + j, lam + j);
            if (m->shared)
                for (i = 0; i < 3; i++)
                {
                    fmpq_sub(w + i, lam + s.e, lam + s.e + 1);
                    fmpq_mul(z + i, w + i, m->v + i);
                }
            fmpq_one(z + nv - 1);
            if (!rows_hold(s.A, s.rel, z))
                r = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal "
                                  "error: a zero-face solution fails"), -1);
        }
        for (i = 0; i < 3; i++)
        {
            fmpq_clear(w + i);
            fmpq_clear(sep + i);
        }
        _fmpq_vec_clear(G, 3 * k + 3);
        _fmpq_vec_clear(lam, k + 1);
    }
    else if (s.e == 0 && mult == NULL)
    {
        slong k;

        for (k = 0; k < 3; k++)
            fmpq_div(z + k, g + k, m->M + k);
        fmpq_one(z + 3);
        r = rows_hold(s.A, s.rel, z);
    }
    else
    {
        fmpq * y0 = NULL;

        if (mult != NULL)
            y0 = _fmpq_vec_init(s.rows);
        r = motzkin(z, y0, s.A, s.rel, err);
        if (r == 0 && mult != NULL)
        {
            *mult = y0;
            *nmult = s.rows;
            y0 = NULL;
        }
        if (y0 != NULL)
            _fmpq_vec_clear(y0, s.rows);
    }
    if (r == 1)
        facesys_motion(nudot, c, &s, m, z);
    _fmpq_vec_clear(z, nv);
    facesys_clear(&s);
    return r;
}

/* ---------------------------------------------------------------------
   The touching-only problem and its modes (the moving faces).  */

static int
touching_modes(wc_modes_t T, const model * m, wc_error_t err)
{
    const wc_problem_struct * P = m->P;
    wc_problem_t Q;
    slong i;
    int status;

    wc_problem_init(Q);
    fmpq_set(Q->mass, P->mass);
    fmpq_set(Q->inertia, P->inertia);
    fmpq_set(Q->com + 0, P->com + 0);
    fmpq_set(Q->com + 1, P->com + 1);
    for (i = 0; i < m->t; i++)
    {
        const wc_fixel_struct * f = P->fixels + m->tidx[i];
        wc_fixel_struct * h = wc_problem_add_fixel(Q);

        fmpq_set(h->point + 0, f->point + 0);
        fmpq_set(h->point + 1, f->point + 1);
        fmpq_set(h->normal + 0, f->normal + 0);
        fmpq_set(h->normal + 1, f->normal + 1);
        fmpq_set(h->mu_s, f->mu_s);
        fmpq_set(h->mu_k, f->mu_k);
    }
    status = wc_modes_enumerate(T, Q, err);
    wc_problem_clear(Q);
    return status;
}

/* The full-length string of touching-only mode s: u on near fixels.  */
static char *
expand(const model * m, const char * s)
{
    char * y = malloc(m->n + 1);
    slong i;

    for (i = 0; i < m->n; i++)
        y[i] = 'u';
    y[m->n] = '\0';
    for (i = 0; i < m->t; i++)
        y[m->tidx[i]] = s[i];
    return y;
}

static int
all_n(const model * m, const char * y)
{
    slong i;

    for (i = 0; i < m->t; i++)
        if (y[m->tidx[i]] != 'n')
            return 0;
    return 1;
}

/* ---------------------------------------------------------------------
   classify  */

static void
motion_init(wc_motion_struct * a, slong n)
{
    slong k;

    a->sign = NULL;
    for (k = 0; k < 3; k++)
        fmpq_init(a->nudot + k);
    a->c = _fmpq_vec_init(2 * n + 1);
}

static void
motion_clear(wc_motion_struct * a, slong n)
{
    slong k;

    free(a->sign);
    for (k = 0; k < 3; k++)
        fmpq_clear(a->nudot + k);
    _fmpq_vec_clear(a->c, 2 * n + 1);
}

void
wc_classify_init(wc_classify_t R)
{
    slong k;

    memset(R, 0, sizeof(wc_classify_struct));
    for (k = 0; k < 3; k++)
    {
        fmpq_init(R->g + k);
        fmpq_init(R->weak_sep + k);
    }
    R->weak_c = _fmpq_vec_init(1);
    motion_init(&R->paper, 0);
}

void
wc_classify_clear(wc_classify_t R)
{
    slong i, k;

    for (k = 0; k < 3; k++)
    {
        fmpq_clear(R->g + k);
        fmpq_clear(R->weak_sep + k);
    }
    for (i = 0; i < R->nmodes; i++)
        free(R->modes[i]);
    free(R->modes);
    _fmpq_vec_clear(R->weak_c, 2 * R->n + 1);
    for (i = 0; i < R->nmotions; i++)
        motion_clear(R->motions + i, R->n);
    flint_free(R->motions);
    motion_clear(&R->paper, R->n);
    for (i = 0; i < R->nnofaces; i++)
    {
        free(R->nofaces[i].sign);
        _fmpq_vec_clear(R->nofaces[i].mult, R->nofaces[i].nmult);
    }
    flint_free(R->nofaces);
    memset(R, 0, sizeof(wc_classify_struct));
}

static wc_motion_struct *
add_motion(wc_classify_t R, const char * sign)
{
    wc_motion_struct * a;

    R->motions = flint_realloc(R->motions,
                               sizeof(wc_motion_struct) * (R->nmotions + 1));
    a = R->motions + R->nmotions++;
    motion_init(a, R->n);
    a->sign = malloc(strlen(sign) + 1);
    strcpy(a->sign, sign);
    return a;
}

static void
add_noface(wc_classify_t R, const char * sign, int rot, fmpq * mult,
           slong nmult)
{
    wc_noface_struct * f;

    R->nofaces = flint_realloc(R->nofaces,
                               sizeof(wc_noface_struct) * (R->nnofaces + 1));
    f = R->nofaces + R->nnofaces++;
    f->sign = malloc(strlen(sign) + 1);
    strcpy(f->sign, sign);
    f->rotation = rot;
    f->mult = mult;
    f->nmult = nmult;
}

/* Weak stability: a static solution (R->weak_c) or a separator.  */
static int
classify_weak(wc_classify_t R, const model * m, wc_error_t err)
{
    const wc_problem_struct * P = m->P;
    slong n = m->n, t = m->t, i, j, ne = 2 * t;
    fmpq * z, * w, ed[4];
    int r;

    if (t == 0)
    {
        R->weak = qvec_is_zero(R->g, 3);
        qvec_set(R->weak_sep, R->g, 3);
        return WC_OK;
    }
    for (j = 0; j < 4; j++)
        fmpq_init(ed + j);
    w = _fmpq_vec_init(3 * ne);
    for (i = 0; i < t; i++)
    {
        wc_friction_edges(ed, P->fixels + m->tidx[i], 'n');
        edge_wrench(w + 3 * (2 * i), m, m->tidx[i], ed);
        edge_wrench(w + 3 * (2 * i + 1), m, m->tidx[i], ed + 2);
    }

    /* The static solution: g = sum lambda_j (-w_j), or a separator.  */
    for (j = 0; j < 3 * ne; j++)
        fmpq_neg(w + j, w + j);
    z = _fmpq_vec_init(ne + 1);
    r = cone3(z, R->weak_sep, w, ne, R->g);
    if (!cone3_check(r, z, R->weak_sep, w, ne, R->g))
        r = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                          "the static solution fails its check"), -1);
    if (r == 1)
    {
        fmpq_t p;

        fmpq_init(p);
        R->weak = 1;
        qvec_zero(R->weak_c, 2 * n);
        for (j = 0; j < ne; j++)
        {
            slong f = m->tidx[j / 2];

            wc_friction_edges(ed, P->fixels + f, 'n');
            fmpq_mul(p, z + j, ed + 2 * (j % 2));
            fmpq_add(R->weak_c + f, R->weak_c + f, p);
            fmpq_mul(p, z + j, ed + 2 * (j % 2) + 1);
            fmpq_add(R->weak_c + n + f, R->weak_c + n + f, p);
        }
        fmpq_clear(p);
    }
    else if (r == 0)
        R->weak = 0;
    _fmpq_vec_clear(z, ne + 1);
    _fmpq_vec_clear(w, 3 * ne);
    for (j = 0; j < 4; j++)
        fmpq_clear(ed + j);
    return r < 0 ? WC_EINTERNAL : WC_OK;
}

/* The modes holding g: from each Table 1 face y of P, the Table 2
   strings x that switch some of y's loaded letters (l r n) to s, by a
   search that stops at the first switch set without a solution (a larger
   set only removes forces).  */
typedef struct
{
    char ** s;
    slong len, alloc;
}
strlist;

static void
strlist_add(strlist * L, const char * s)
{
    if (L->len == L->alloc)
    {
        L->alloc = 2 * L->alloc + 8;
        L->s = realloc(L->s, sizeof(char *) * L->alloc);
    }
    L->s[L->len] = malloc(strlen(s) + 1);
    strcpy(L->s[L->len++], s);
}

static int
str_cmp(const void * p, const void * q)
{
    return strcmp(*(char * const *) p, *(char * const *) q);
}

/* What the search of one face has learnt: solutions found (each holds g
   for every switch set that avoids the fixels it loads) and switch sets
   without a solution (so is every larger one).  */
typedef struct
{
    slong n, nsol, nbad, asol, abad;
    fmpq * sol;             /* nsol blocks of 3 + 2n: nudot, c */
    char ** bad;            /* x strings without a solution */
}
memo;

static void
memo_init(memo * M, slong n)
{
    memset(M, 0, sizeof(memo));
    M->n = n;
}

static void
memo_clear(memo * M)
{
    slong i;

    if (M->asol > 0)
        _fmpq_vec_clear(M->sol, M->asol * (3 + 2 * M->n));
    for (i = 0; i < M->nbad; i++)
        free(M->bad[i]);
    free(M->bad);
    memset(M, 0, sizeof(memo));
}

static const fmpq *
memo_add_sol(memo * M, const fmpq * nudot, const fmpq * c)
{
    slong w = 3 + 2 * M->n;
    fmpq * b;

    if (M->nsol == M->asol)
    {
        slong na = 2 * M->asol + 4;
        fmpq * v = _fmpq_vec_init(na * w);

        if (M->asol > 0)
        {
            qvec_set(v, M->sol, M->nsol * w);
            _fmpq_vec_clear(M->sol, M->asol * w);
        }
        M->sol = v;
        M->asol = na;
    }
    b = M->sol + (M->nsol++) * w;
    qvec_set(b, nudot, 3);
    qvec_set(b + 3, c, 2 * M->n);
    return b;
}

/* A stored solution that loads no fixel switched to s in x, or NULL.  */
static const fmpq *
memo_sol(const memo * M, const char * x)
{
    slong k, i, n = M->n, w = 3 + 2 * n;

    for (k = 0; k < M->nsol; k++)
    {
        const fmpq * c = M->sol + k * w + 3;

        for (i = 0; i < n; i++)
            if (x[i] == 's' && (!fmpq_is_zero(c + i) || !fmpq_is_zero(c + n + i)))
                break;
        if (i == n)
            return M->sol + k * w;
    }
    return NULL;
}

/* 1 when x switches every fixel some known failure switched.  */
static int
memo_bad(const memo * M, const char * x, const char * y)
{
    slong k, i;

    for (k = 0; k < M->nbad; k++)
    {
        for (i = 0; i < M->n; i++)
            if (M->bad[k][i] == 's' && y[i] != 's' && x[i] != 's')
                break;
        if (i == M->n)
            return 1;
    }
    return 0;
}

/* x holds g with the solution sol = (nudot, c); try switching each loaded
   letter from position from on to s.  A fixel that carries no force in
   the solution switches with the same solution; otherwise the memo may
   answer, and else an LP does.  */
static int
search_modes(strlist * L, slong max, memo * M, const model * m,
             const char * y, char * x, slong from, const fmpq * g,
             const fmpq * sol, wc_error_t err)
{
    slong i, n = m->n;
    fmpq * own;
    const fmpq * c;
    int r = 1, pass;

    if (max > 0 && L->len >= max)
        return 2;
    strlist_add(L, x);
    /* sol may live in the memo, whose storage moves as it grows */
    own = _fmpq_vec_init(3 + 2 * n);
    qvec_set(own, sol, 3 + 2 * n);
    sol = own;
    c = own + 3;
    /* Unloaded fixels first (pass 0), then the loaded ones: when the list
       is capped, it fills without LPs.  */
    for (pass = 0; pass < 2; pass++)
    for (i = from; i < n && r == 1; i++)
    {
        char was = x[i];
        int rr, unloaded = fmpq_is_zero(c + i) && fmpq_is_zero(c + n + i);
        const fmpq * s2;

        if (m->P->fixels[i].state != WC_TOUCHING || was == 's'
            || unloaded != (pass == 0))
            continue;
        x[i] = 's';
        if (unloaded)
            rr = search_modes(L, max, M, m, y, x, i + 1, g, sol, err);
        else if ((s2 = memo_sol(M, x)) != NULL)
            rr = search_modes(L, max, M, m, y, x, i + 1, g, s2, err);
        else if (memo_bad(M, x, y))
            rr = 0;
        else
        {
            fmpq nu[3];
            fmpq * cc = _fmpq_vec_init(2 * n + 1);
            slong k;

            for (k = 0; k < 3; k++)
                fmpq_init(nu + k);
            rr = face_solve(nu, cc, NULL, NULL, m, y, x, 0, g, err);
            if (rr == 1)
                s2 = memo_add_sol(M, nu, cc);
            else if (rr == 0)
            {
                M->bad = realloc(M->bad, sizeof(char *) * (M->nbad + 1));
                M->bad[M->nbad] = malloc(n + 1);
                strcpy(M->bad[M->nbad++], x);
            }
            for (k = 0; k < 3; k++)
                fmpq_clear(nu + k);
            _fmpq_vec_clear(cc, 2 * n + 1);
            if (rr == 1)
                rr = search_modes(L, max, M, m, y, x, i + 1, g, s2, err);
        }
        x[i] = was;
        if (rr < 0 || rr == 2)
            r = rr;
    }
    _fmpq_vec_clear(own, 3 + 2 * n);
    return r;
}

static int
classify_modes(wc_classify_t R, const model * m, slong max, wc_error_t err)
{
    wc_modes_t T;
    strlist L = { NULL, 0, 0 };
    fmpq nudot[3];
    fmpq * c = _fmpq_vec_init(2 * m->n + 1);
    char * x = malloc(m->n + 1);
    slong i, k;
    int status, r;

    for (k = 0; k < 3; k++)
        fmpq_init(nudot + k);
    wc_modes_init(T);
    status = wc_modes_enumerate(T, m->P, err);
    R->modes_complete = 1;
    for (i = 0; i < T->count && status == WC_OK && R->modes_complete; i++)
    {
        strcpy(x, T->modes[i]);
        r = face_solve(nudot, c, NULL, NULL, m, T->modes[i], x, 0, R->g, err);
        if (r == 1)
        {
            memo M;
            fmpq * own = _fmpq_vec_init(3 + 2 * m->n);

            memo_init(&M, m->n);
            qvec_set(own, nudot, 3);
            qvec_set(own + 3, c, 2 * m->n);
            memo_add_sol(&M, nudot, c);
            r = search_modes(&L, max, &M, m, T->modes[i], x, 0, R->g, own,
                             err);
            memo_clear(&M);
            _fmpq_vec_clear(own, 3 + 2 * m->n);
        }
        if (r < 0)
            status = WC_EINTERNAL;
        else if (r == 2)
            R->modes_complete = 0;
    }
    if (status == WC_OK)
    {
        if (L.len > 1)
            qsort(L.s, L.len, sizeof(char *), str_cmp);
        R->modes = malloc(sizeof(char *) * (L.len + 1));
        R->nmodes = 0;
        for (i = 0; i < L.len; i++)
            if (R->nmodes > 0 && strcmp(R->modes[R->nmodes - 1], L.s[i]) == 0)
                free(L.s[i]);
            else
                R->modes[R->nmodes++] = L.s[i];
        L.len = 0;
    }
    for (i = 0; i < L.len; i++)
        free(L.s[i]);
    free(L.s);
    wc_modes_clear(T);
    for (k = 0; k < 3; k++)
        fmpq_clear(nudot + k);
    _fmpq_vec_clear(c, 2 * m->n + 1);
    free(x);
    return status;
}

int
wc_classify(wc_classify_t R, const wc_problem_t P, const fmpq * g,
            int certificates, slong max_modes, wc_error_t err)
{
    model m;
    wc_modes_t T;
    slong n, i, k, nmult;
    int status, r, rot, paper_found = 0;
    char * y = NULL;
    fmpq * mult;

    wc_classify_clear(R);
    wc_classify_init(R);
    if ((status = wc_problem_check(P, err)) != WC_OK)
        return status;
    n = P->n;
    model_init(&m, P);
    R->n = n;
    _fmpq_vec_clear(R->weak_c, 1);
    R->weak_c = _fmpq_vec_init(2 * n + 1);
    motion_clear(&R->paper, 0);
    motion_init(&R->paper, n);
    for (k = 0; k < 3; k++)
        fmpq_set(R->g + k, g + k);
    wc_modes_init(T);

    if ((status = classify_weak(R, &m, err)) != WC_OK)
        goto cleanup;

    /* Moving faces.  */
    if (m.t == 0)
    {
        /* No contact: the body moves with nudot = M^-1 g unless g = 0.  */
        if (!qvec_is_zero(g, 3))
        {
            wc_motion_struct * a;

            y = expand(&m, "");
            a = add_motion(R, y);
            for (k = 0; k < 3; k++)
                fmpq_div(a->nudot + k, g + k, m.M + k);
        }
    }
    else
    {
        if ((status = touching_modes(T, &m, err)) != WC_OK)
            goto cleanup;
        for (i = 0; i < T->count; i++)
        {
            wc_motion_struct * a;
            fmpq nu[3];
            fmpq * c = _fmpq_vec_init(2 * n + 1);

            free(y);
            y = expand(&m, T->modes[i]);
            if (all_n(&m, y))
            {
                _fmpq_vec_clear(c, 2 * n + 1);
                continue;
            }
            for (k = 0; k < 3; k++)
                fmpq_init(nu + k);
            mult = NULL;
            r = face_solve(nu, c, certificates ? &mult : NULL, &nmult, &m, y,
                           y, 0, g, err);
            if (r == 1)
            {
                a = add_motion(R, y);
                qvec_set(a->nudot, nu, 3);
                qvec_set(a->c, c, 2 * n);
            }
            else if (r == 0 && certificates)
                add_noface(R, y, 0, mult, nmult);
            for (k = 0; k < 3; k++)
                fmpq_clear(nu + k);
            _fmpq_vec_clear(c, 2 * n + 1);
            if (r < 0)
            {
                status = WC_EINTERNAL;
                goto cleanup;
            }
        }
        if (R->nmotions > 0)
        {
            /* a motion of a face other than n..n holds g in W(y) */
            paper_found = 1;
            R->paper.sign = malloc(n + 1);
            strcpy(R->paper.sign, R->motions[0].sign);
            qvec_set(R->paper.nudot, R->motions[0].nudot, 3);
            qvec_set(R->paper.c, R->motions[0].c, 2 * n);
        }
        if (m.shared)
        {
            free(y);
            y = malloc(n + 1);
            for (i = 0; i < n; i++)
                y[i] = P->fixels[i].state == WC_TOUCHING ? 'n' : 'u';
            y[n] = '\0';
            for (rot = 1; rot >= -1; rot -= 2)
            {
                fmpq nu[3];
                fmpq * c = _fmpq_vec_init(2 * n + 1);

                for (k = 0; k < 3; k++)
                    fmpq_init(nu + k);
                mult = NULL;
                r = face_solve(nu, c, certificates ? &mult : NULL, &nmult,
                               &m, y, y, rot, g, err);
                if (r == 1)
                {
                    wc_motion_struct * a = add_motion(R, y);

                    qvec_set(a->nudot, nu, 3);
                    qvec_set(a->c, c, 2 * n);
                }
                else if (r == 0 && certificates)
                    add_noface(R, y, rot, mult, nmult);
                for (k = 0; k < 3; k++)
                    fmpq_clear(nu + k);
                _fmpq_vec_clear(c, 2 * n + 1);
                if (r < 0)
                {
                    status = WC_EINTERNAL;
                    goto cleanup;
                }
            }
        }
    }
    R->strong = R->weak && R->nmotions == 0;

    /* Paper semantics: a string other than n..n whose cone holds g.  Found
       above when a face other than n..n moves; else a static solution
       that leaves a touching fixel unloaded holds g in the string with s
       there; else one LP per touching fixel i: nudot in the null space of
       every touching fixel's rows, no force at i.  */
    if (!paper_found && m.t > 0 && R->weak)
        for (i = 0; i < m.t && !paper_found; i++)
        {
            slong f = m.tidx[i];

            if (fmpq_is_zero(R->weak_c + f) && fmpq_is_zero(R->weak_c + n + f))
            {
                paper_found = 1;
                R->paper.sign = malloc(n + 1);
                for (k = 0; k < n; k++)
                    R->paper.sign[k] = P->fixels[k].state == WC_TOUCHING
                        ? 'n' : 'u';
                R->paper.sign[f] = 's';
                R->paper.sign[n] = '\0';
                qvec_zero(R->paper.nudot, 3);
                qvec_set(R->paper.c, R->weak_c, 2 * n);
            }
        }
    if (!paper_found && m.t > 0 && (R->weak || m.shared))
    {
        char * x = malloc(n + 1);

        free(y);
        y = malloc(n + 1);
        for (k = 0; k < n; k++)
            y[k] = P->fixels[k].state == WC_TOUCHING ? 'n' : 'u';
        y[n] = '\0';
        for (i = 0; i < m.t && !paper_found; i++)
        {
            strcpy(x, y);
            x[m.tidx[i]] = 's';
            r = face_solve(R->paper.nudot, R->paper.c, NULL, NULL, &m, y, x,
                           0, g, err);
            if (r < 0)
            {
                free(x);
                status = WC_EINTERNAL;
                goto cleanup;
            }
            if (r == 1)
            {
                paper_found = 1;
                R->paper.sign = x;
                x = NULL;
            }
        }
        free(x);
    }
    R->strong_paper = !paper_found;

    status = classify_modes(R, &m, max_modes, err);

cleanup:
    free(y);
    wc_modes_clear(T);
    model_clear(&m);
    return status;
}

/* ---------------------------------------------------------------------
   The sets.  */

void
wc_stability_init(wc_stability_t S)
{
    slong k;

    memset(S, 0, sizeof(wc_stability_struct));
    wc_cone_init(S->weak, 3);
    wc_set_init(S->strong);
    wc_set_init(S->strong_paper);
    for (k = 0; k < 3; k++)
        fmpq_init(S->diff_g + k);
    wc_cells_init(S->cells);
    wc_push_init(S->push_weak);
    wc_push_init(S->push_strong);
    wc_push_init(S->push_strong_paper);
}

void
wc_stability_clear(wc_stability_t S)
{
    slong i, k;

    wc_cone_clear(S->weak);
    wc_set_clear(S->strong);
    wc_set_clear(S->strong_paper);
    for (k = 0; k < 3; k++)
        fmpq_clear(S->diff_g + k);
    for (i = 0; i < S->nmoving; i++)
    {
        wc_cone_clear(S->moving + i);
        free(S->moving_sign[i]);
    }
    flint_free(S->moving);
    flint_free(S->moving_sign);
    flint_free(S->moving_rot);
    for (i = 0; i < S->nunion; i++)
        wc_cone_clear(S->paper_union + i);
    flint_free(S->paper_union);
    wc_cells_clear(S->cells);
    wc_push_clear(S->push_weak);
    wc_push_clear(S->push_strong);
    wc_push_clear(S->push_strong_paper);
    memset(S, 0, sizeof(wc_stability_struct));
}

/* Rows of -w over the friction edges of letters x (touching fixels),
   skipping fixel skip (or -1).  */
static void
edge_rows(fmpq_mat_t Q, const model * m, const char * x, slong skip)
{
    const wc_problem_struct * P = m->P;
    slong i, j, k, c, e = 0;
    fmpq ed[4], w[3];

    for (j = 0; j < 4; j++)
        fmpq_init(ed + j);
    for (k = 0; k < 3; k++)
        fmpq_init(w + k);
    fmpq_mat_clear(Q);
    fmpq_mat_init(Q, 2 * m->n, 3);
    for (i = 0; i < m->n; i++)
    {
        if (P->fixels[i].state != WC_TOUCHING || i == skip)
            continue;
        c = wc_friction_edges(ed, P->fixels + i, x[i]);
        for (j = 0; j < c; j++, e++)
        {
            edge_wrench(w, m, i, ed + 2 * j);
            for (k = 0; k < 3; k++)
                fmpq_neg(fmpq_mat_entry(Q, e, k), w + k);
        }
    }
    shrink(Q, e);
    for (j = 0; j < 4; j++)
        fmpq_clear(ed + j);
    for (k = 0; k < 3; k++)
        fmpq_clear(w + k);
}

static void
append_row(fmpq_mat_t A, slong * r, const fmpq * v, int neg)
{
    slong k;

    for (k = 0; k < 3; k++)
        if (neg)
            fmpq_neg(fmpq_mat_entry(A, *r, k), v + k);
        else
            fmpq_set(fmpq_mat_entry(A, *r, k), v + k);
    (*r)++;
}

/* W := M V + (-J) D for the face y (rot: rotation face; y = NULL with
   rot = 1..6: the six pieces of R^3 minus the origin, no contact).  */
static int
face_cone(wc_cone_t W, const model * m, const char * y, int rot,
          wc_error_t err)
{
    slong n = m->n, i, ne = 0, ni = 0, ns = 0;
    fmpq_mat_t E, H, Z, Q, T;
    wc_cone_t V;
    int status;
    fmpq e[3];

    fmpq_mat_init(E, 2 * n + 3, 3);
    fmpq_mat_init(H, 2 * n + 3, 3);
    fmpq_mat_init(Z, 2 * n + 3, 3);
    fmpq_mat_init(Q, 0, 3);
    fmpq_mat_init(T, 3, 3);
    for (i = 0; i < 3; i++)
    {
        fmpq_init(e + i);
        fmpq_set(fmpq_mat_entry(T, i, i), m->M + i);
    }
    wc_cone_init(V, 3);
    if (y == NULL)
    {
        /* piece rot = 2k + 1 or 2k + 2: e_1 .. e_k zero, +-e_{k+1} > 0 */
        slong k = (rot - 1) / 2;

        for (i = 0; i < k; i++)
        {
            qvec_zero(e, 3);
            fmpq_one(e + i);
            append_row(E, &ne, e, 0);
        }
        qvec_zero(e, 3);
        fmpq_one(e + k);
        append_row(Z, &ns, e, (rot - 1) % 2 == 0);
    }
    else
    {
        for (i = 0; i < n; i++)
        {
            const fmpq * jn = m->Jn + 3 * i, * jt = m->Jt + 3 * i;
            char c = rot != 0 ? 'n' : y[i];

            if (m->P->fixels[i].state != WC_TOUCHING)
                continue;
            switch (c)
            {
            case 's':
                append_row(Z, &ns, jn, 1);
                break;
            case 'l':
                append_row(E, &ne, jn, 0);
                append_row(Z, &ns, jt, 1);
                break;
            case 'r':
                append_row(E, &ne, jn, 0);
                append_row(Z, &ns, jt, 0);
                break;
            default:
                append_row(E, &ne, jn, 0);
                append_row(E, &ne, jt, 0);
                break;
            }
        }
        if (rot != 0)
            append_row(Z, &ns, m->v, rot > 0);
        edge_rows(Q, m, y, -1);
    }
    shrink(E, ne);
    shrink(H, ni);
    shrink(Z, ns);
    status = wc_cone_set_hrep(V, E, H, Z, err);
    if (status == WC_OK)
        status = wc_cone_image_sum(W, T, V, Q, err);
    wc_cone_clear(V);
    fmpq_mat_clear(E);
    fmpq_mat_clear(H);
    fmpq_mat_clear(Z);
    fmpq_mat_clear(Q);
    fmpq_mat_clear(T);
    for (i = 0; i < 3; i++)
        fmpq_clear(e + i);
    return status;
}

static wc_cone_struct *
add_moving(wc_stability_t S, const char * sign, int rot)
{
    S->moving = flint_realloc(S->moving,
                              sizeof(wc_cone_struct) * (S->nmoving + 1));
    S->moving_sign = flint_realloc(S->moving_sign,
                                   sizeof(char *) * (S->nmoving + 1));
    S->moving_rot = flint_realloc(S->moving_rot,
                                  sizeof(int) * (S->nmoving + 1));
    wc_cone_init(S->moving + S->nmoving, 3);
    S->moving_sign[S->nmoving] = malloc(strlen(sign) + 1);
    strcpy(S->moving_sign[S->nmoving], sign);
    S->moving_rot[S->nmoving] = rot;
    return S->moving + S->nmoving++;
}

/* Membership in the three sets, straight from the cones.  */
enum { SET_WEAK = 0, SET_STRONG = 1, SET_PAPER = 2 };

typedef struct
{
    const wc_stability_struct * S;
    int which;
}
member_ctx;

static int
in_exact_moving(const wc_stability_struct * S, const fmpq * g)
{
    slong i;

    for (i = 0; i < S->nmoving; i++)
        if (wc_cone_contains(S->moving + i, g))
            return 1;
    return 0;
}

static int
in_paper_union(const wc_stability_struct * S, const fmpq * g)
{
    slong i;

    for (i = 0; i < S->nmoving; i++)
        if (S->moving_rot[i] == 0 && wc_cone_contains(S->moving + i, g))
            return 1;
    for (i = 0; i < S->nunion; i++)
        if (wc_cone_contains(S->paper_union + i, g))
            return 1;
    return 0;
}

static int
member(const fmpq * g, void * p)
{
    const member_ctx * c = p;

    switch (c->which)
    {
    case SET_WEAK:
        return wc_cone_contains(c->S->weak, g);
    case SET_STRONG:
        return wc_cone_contains(c->S->weak, g) && !in_exact_moving(c->S, g);
    default:
        return !in_paper_union(c->S, g);
    }
}

static void
collect_planes(fmpz_mat_t A, slong * r, const wc_cone_t C)
{
    slong i, k, add = fmpz_mat_nrows(C->ineqs) + fmpz_mat_nrows(C->eqs);
    fmpz_mat_t B;

    fmpz_mat_init(B, *r + add, 3);
    for (i = 0; i < *r; i++)
        for (k = 0; k < 3; k++)
            fmpz_set(fmpz_mat_entry(B, i, k), fmpz_mat_entry(A, i, k));
    for (i = 0; i < fmpz_mat_nrows(C->ineqs); i++, (*r)++)
        for (k = 0; k < 3; k++)
            fmpz_set(fmpz_mat_entry(B, *r, k), fmpz_mat_entry(C->ineqs, i, k));
    for (i = 0; i < fmpz_mat_nrows(C->eqs); i++, (*r)++)
        for (k = 0; k < 3; k++)
            fmpz_set(fmpz_mat_entry(B, *r, k), fmpz_mat_entry(C->eqs, i, k));
    fmpz_mat_swap(A, B);
    fmpz_mat_clear(B);
}

int
wc_stability(wc_stability_t S, const wc_problem_t P, wc_error_t err)
{
    model m;
    wc_modes_t T;
    fmpq_mat_t Q, L;
    fmpz_mat_t planes;
    slong n, i, k, np = 0;
    int status, * in_exact = NULL, * in_paper = NULL;
    char * y = NULL;
    fmpq g[3];

    wc_stability_clear(S);
    wc_stability_init(S);
    if ((status = wc_problem_check(P, err)) != WC_OK)
        return status;
    n = P->n;
    model_init(&m, P);
    wc_modes_init(T);
    fmpq_mat_init(Q, 0, 3);
    fmpq_mat_init(L, 0, 3);
    fmpz_mat_init(planes, 0, 3);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);

    /* The weak cone: -J applied to the friction cones.  */
    y = malloc(n + 1);
    for (i = 0; i < n; i++)
        y[i] = 'n';
    y[n] = '\0';
    edge_rows(Q, &m, y, -1);
    if ((status = wc_cone_set_generators(S->weak, Q, NULL, err)) != WC_OK)
        goto cleanup;
    collect_planes(planes, &np, S->weak);

    /* The moving faces.  */
    if (m.t == 0)
    {
        for (i = 0; i < n; i++)
            y[i] = 'u';
        for (k = 1; k <= 6 && status == WC_OK; k++)
            status = face_cone(add_moving(S, y, 2), &m, NULL, (int) k, err);
    }
    else
    {
        if ((status = touching_modes(T, &m, err)) != WC_OK)
            goto cleanup;
        for (i = 0; i < T->count && status == WC_OK; i++)
        {
            free(y);
            y = expand(&m, T->modes[i]);
            if (!all_n(&m, y))
                status = face_cone(add_moving(S, y, 0), &m, y, 0, err);
        }
        if (m.shared)
        {
            free(y);
            y = expand(&m, T->modes[0]);
            for (i = 0; i < m.t; i++)
                y[m.tidx[i]] = 'n';
            for (k = 1; k >= -1 && status == WC_OK; k -= 2)
                status = face_cone(add_moving(S, y, (int) k), &m, y,
                                   (int) k, err);
        }
        /* eq. 19's extra cones: M L0 + (-J) D without fixel i.  */
        if (m.shared)
        {
            fmpq_mat_clear(L);
            fmpq_mat_init(L, 1, 3);
            for (k = 0; k < 3; k++)
                fmpq_mul(fmpq_mat_entry(L, 0, k), m.v + k, m.M + k);
        }
        for (i = 0; i < n; i++)
            y[i] = 'n';
        S->paper_union = flint_malloc(sizeof(wc_cone_struct) * (m.t + 1));
        for (i = 0; i < m.t && status == WC_OK; i++)
        {
            wc_cone_init(S->paper_union + S->nunion++, 3);
            edge_rows(Q, &m, y, m.tidx[i]);
            status = wc_cone_set_generators(S->paper_union + i, Q, L, err);
        }
    }
    if (status != WC_OK)
        goto cleanup;
    for (i = 0; i < S->nmoving; i++)
        collect_planes(planes, &np, S->moving + i);
    for (i = 0; i < S->nunion; i++)
        collect_planes(planes, &np, S->paper_union + i);

    /* The cells of all their planes; each set is a union of cells.  */
    if ((status = wc_cells_build(S->cells, planes, err)) != WC_OK)
        goto cleanup;
    in_exact = flint_malloc(sizeof(int) * (S->cells->count + 1));
    in_paper = flint_malloc(sizeof(int) * (S->cells->count + 1));
    S->paper_in_weak = 1;
    S->differ = 0;
    for (i = 0; i < S->cells->count; i++)
    {
        int w;

        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(g + k, fmpz_mat_entry(S->cells->point, i, k));
        w = wc_cone_contains(S->weak, g);
        in_exact[i] = w && !in_exact_moving(S, g);
        in_paper[i] = !in_paper_union(S, g);
        if (in_paper[i] && !w)
            S->paper_in_weak = 0;
        if (!S->differ && in_exact[i] != in_paper[i])
        {
            S->differ = 1;
            qvec_set(S->diff_g, g, 3);
            S->diff_in_exact = in_exact[i];
        }
    }
    if ((status = wc_set_from_cells(S->strong, S->cells, in_exact, err))
        != WC_OK
        || (status = wc_set_from_cells(S->strong_paper, S->cells, in_paper,
                                       err)) != WC_OK
        || (status = wc_set_merge(S->strong, S->cells, err)) != WC_OK
        || (status = wc_set_merge(S->strong_paper, S->cells, err)) != WC_OK)
        goto cleanup;

    /* Push regions.  */
    if (P->shape != WC_SHAPE_NONE)
    {
        member_ctx c;

        c.S = S;
        S->has_push = 1;
        c.which = SET_WEAK;
        status = wc_push_regions(S->push_weak, P, S->cells->planes, member,
                                 &c, err);
        c.which = SET_STRONG;
        if (status == WC_OK)
            status = wc_push_regions(S->push_strong, P, S->cells->planes,
                                     member, &c, err);
        c.which = SET_PAPER;
        if (status == WC_OK)
            status = wc_push_regions(S->push_strong_paper, P,
                                     S->cells->planes, member, &c, err);
    }

cleanup:
    free(y);
    flint_free(in_exact);
    flint_free(in_paper);
    wc_modes_clear(T);
    fmpq_mat_clear(Q);
    fmpq_mat_clear(L);
    fmpz_mat_clear(planes);
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    model_clear(&m);
    if (status != WC_OK)
    {
        wc_stability_clear(S);
        wc_stability_init(S);
    }
    return status;
}

/* ---------------------------------------------------------------------
   Robustness of a biasing wrench.  */

/* The distance from b to cl C in the norm max(|x|, |y|, |tau| / L): min t
   over x in cl C with |x_k - b_k| <= t (k = 1, 2), |x_3 - b_3| <= L t.  */
static int
closure_distance(fmpq_t d, const wc_cone_t C, const fmpq * b,
                 const fmpq_t L, wc_error_t err)
{
    slong ni = fmpz_mat_nrows(C->ineqs), ne = fmpz_mat_nrows(C->eqs);
    slong m = 6 + ni + ne, i, k, r = 0;
    fmpq_mat_t A;
    fmpq * rhs = _fmpq_vec_init(m), * x = _fmpq_vec_init(4),
        * c = _fmpq_vec_init(4);
    int * eq = flint_calloc(m, sizeof(int)), res;

    fmpq_mat_init(A, m, 4);
    for (k = 0; k < 3; k++)
    {
        const fmpq * s = k < 2 ? NULL : L;

        /* t' - (x_k - b_k) >= 0 and t' + (x_k - b_k) >= 0, t' = t or L t */
        fmpq_set_si(fmpq_mat_entry(A, r, k), -1, 1);
        if (s != NULL)
            fmpq_set(fmpq_mat_entry(A, r, 3), s);
        else
            fmpq_one(fmpq_mat_entry(A, r, 3));
        fmpq_neg(rhs + r, b + k);
        r++;
        fmpq_one(fmpq_mat_entry(A, r, k));
        if (s != NULL)
            fmpq_set(fmpq_mat_entry(A, r, 3), s);
        else
            fmpq_one(fmpq_mat_entry(A, r, 3));
        fmpq_set(rhs + r, b + k);
        r++;
    }
    for (i = 0; i < ni; i++, r++)
        for (k = 0; k < 3; k++)
        {
            fmpq_set_fmpz(fmpq_mat_entry(A, r, k),
                          fmpz_mat_entry(C->ineqs, i, k));
            fmpq_neg(fmpq_mat_entry(A, r, k), fmpq_mat_entry(A, r, k));
        }
    for (i = 0; i < ne; i++, r++)
    {
        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(fmpq_mat_entry(A, r, k),
                          fmpz_mat_entry(C->eqs, i, k));
        eq[r] = 1;
    }
    fmpq_one(c + 3);
    res = _wc_cdd_lp_min(x, d, A, rhs, eq, c, err);
    if (res == 0 || res == 2)
        res = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                            "distance LP ended without an optimum"), -1);
    fmpq_mat_clear(A);
    _fmpq_vec_clear(rhs, m);
    _fmpq_vec_clear(x, 4);
    _fmpq_vec_clear(c, 4);
    flint_free(eq);
    return res < 0 ? WC_EINTERNAL : WC_OK;
}

/* 1 when some included face of C meets the closed ball of radius rho
   about b: the face's rays with coefficients >= s > 0 (s maximised up to
   1), lines free.  */
static int
meets_ball(int * meets, const wc_cone_t C, const fmpq * b, const fmpq_t rho,
           const fmpq_t L, wc_error_t err)
{
    slong f, i, j, k;
    slong nl = fmpz_mat_nrows(C->lines);

    *meets = 0;
    for (f = 0; f < C->nfaces && !*meets; f++)
    {
        const wc_face_struct * F = C->faces + f;
        slong nr = F->nrays, nv = nr + 2 * nl + 1, m = nr + 6 + 1, r = 0;
        fmpq_mat_t A;
        fmpq * rhs, * x, * c;
        fmpq_t val, lim;
        int * eq, res;

        if (!F->included)
            continue;
        fmpq_mat_init(A, m, nv);
        rhs = _fmpq_vec_init(m);
        x = _fmpq_vec_init(nv);
        c = _fmpq_vec_init(nv);
        eq = flint_calloc(m, sizeof(int));
        fmpq_init(val);
        fmpq_init(lim);
        /* mu_i - s >= 0 */
        for (i = 0; i < nr; i++, r++)
        {
            fmpq_one(fmpq_mat_entry(A, r, i));
            fmpq_set_si(fmpq_mat_entry(A, r, nv - 1), -1, 1);
        }
        /* lim -+ (sum mu r + sum (l+ - l-) line - b)_k >= 0 */
        for (k = 0; k < 3; k++)
        {
            int sg;

            if (k < 2)
                fmpq_set(lim, rho);
            else
                fmpq_mul(lim, rho, L);
            for (sg = -1; sg <= 1; sg += 2, r++)
            {
                for (i = 0; i < nr; i++)
                    fmpq_set_fmpz(fmpq_mat_entry(A, r, i),
                                  fmpz_mat_entry(C->rays, F->rays[i], k));
                for (j = 0; j < nl; j++)
                {
                    fmpq_set_fmpz(fmpq_mat_entry(A, r, nr + 2 * j),
                                  fmpz_mat_entry(C->lines, j, k));
                    fmpq_neg(fmpq_mat_entry(A, r, nr + 2 * j + 1),
                             fmpq_mat_entry(A, r, nr + 2 * j));
                }
                for (i = 0; i < nr + 2 * nl; i++)
                    if (sg > 0)
                        fmpq_neg(fmpq_mat_entry(A, r, i),
                                 fmpq_mat_entry(A, r, i));
                /* sg = -1: (v - b) >= -lim; sg = +1: -(v - b) >= -lim */
                if (sg < 0)
                    fmpq_sub(rhs + r, b + k, lim);
                else
                {
                    fmpq_neg(rhs + r, b + k);
                    fmpq_sub(rhs + r, rhs + r, lim);
                }
            }
        }
        for (j = 0; j < 2 * nl; j++)
            ;   /* line coefficients are free in both signs already */
        /* -s >= -1 */
        fmpq_set_si(fmpq_mat_entry(A, r, nv - 1), -1, 1);
        fmpq_set_si(rhs + r, -1, 1);
        r++;
        fmpq_set_si(c + nv - 1, -1, 1);    /* minimise -s */
        res = _wc_cdd_lp_min(x, val, A, rhs, eq, c, err);
        if (res == 1 && fmpq_sgn(val) < 0)
            *meets = 1;
        fmpq_mat_clear(A);
        _fmpq_vec_clear(rhs, m);
        _fmpq_vec_clear(x, nv);
        _fmpq_vec_clear(c, nv);
        flint_free(eq);
        fmpq_clear(val);
        fmpq_clear(lim);
        if (res < 0)
            return WC_EINTERNAL;
    }
    return WC_OK;
}

int
wc_robustness(fmpq_t rho, int * closed, int * infinite, const wc_set_t set,
              const wc_cells_t cells, const fmpq * b, const fmpq_t L,
              wc_error_t err)
{
    wc_set_t C;
    int * out = flint_malloc(sizeof(int) * (cells->count + 1));
    slong i, k;
    int status;
    fmpq_t d;
    fmpq g[3];

    wc_set_init(C);
    fmpq_init(d);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    for (i = 0; i < cells->count; i++)
    {
        for (k = 0; k < 3; k++)
            fmpq_set_fmpz(g + k, fmpz_mat_entry(cells->point, i, k));
        out[i] = !wc_set_contains(set, g);
    }
    status = wc_set_from_cells(C, cells, out, err);
    *infinite = C->empty;
    *closed = 0;
    fmpq_zero(rho);
    for (i = 0; i < C->npieces && status == WC_OK; i++)
    {
        status = closure_distance(d, C->pieces + i, b, L, err);
        if (status == WC_OK && (i == 0 || fmpq_cmp(d, rho) < 0))
            fmpq_set(rho, d);
    }
    if (status == WC_OK && !C->empty)
    {
        *closed = 1;
        for (i = 0; i < C->npieces && status == WC_OK && *closed; i++)
        {
            int meets;

            status = closure_distance(d, C->pieces + i, b, L, err);
            if (status == WC_OK && fmpq_equal(d, rho))
            {
                status = meets_ball(&meets, C->pieces + i, b, rho, L, err);
                *closed = !meets;
            }
        }
    }
    wc_set_clear(C);
    fmpq_clear(d);
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    flint_free(out);
    return status;
}
