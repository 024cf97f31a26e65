/* ref-stab.c -- the test oracle for stability: one exact LP per sign
   pattern of the complementarity problem.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Nothing here comes from the library but the problem record and the
   one-time cddlib set-up (wc_init): J and M are rebuilt in mpq_t from the
   problem's fields, every question is one cddlib (GMP) LP written row by
   row, and cddlib's answers are checked exactly before they are believed:
   a feasible answer comes with a point that is substituted back into every
   row, an infeasible one with a Farkas combination of the rows that is
   summed up again.  When a check fails the answer is -1, never a guess.

   Every question is an LP over (nudot, c), written here from wrenchcone(1), MODES
   and 2.5 (nudot the acceleration, c = (c_1n .. c_nn, c_1t .. c_nt) the
   forces, a = J^T nudot):

     weak:    J c = -g, c_in >= 0, |c_it| <= mu_s c_in (touching),
              c_i = 0 (near);
     pattern: M nudot - J c - t g = 0, t >= 1, and per fixel the rows of
              its letter:
                s   a_in >= 1 (a moving solution's sign pattern) or
                    a_in >= 0 (Table 2),        c_in = c_it = 0
                l   a_in = 0, a_it >= 1,        c_in >= 0, c_it = -mu_k c_in
                r   a_in = 0, -a_it >= 1,       c_in >= 0, c_it = +mu_k c_in
                n   a_in = a_it = 0,            c_in >= 0, |c_it| <= mu_s c_in
                a   -a_in >= 1 (near),          c_in = c_it = 0
                u   (near)                      c_in = c_it = 0

   A Table 2 cone W(x) = { g : C y = B g, y = (a; c) satisfying x } of
   eq. (7) is the same set: C y = B g says a = J^T M^-1 (J c + g), i.e.
   a = J^T nudot for nudot = M^-1 (J c + g).  ref-lp.c decides it over
   y = (a; c); the LP here, with two fewer equality rows per fixel, takes
   about half the time, and t-stability checks ref_wrench_in_cone on the
   library's witnesses besides.

   The pattern rows are homogeneous in (nudot, c, t), so a solution with
   t = 1 and the strict rows (a_in > 0, +-a_it > 0, -a_in > 0) positive
   scales to one with t >= 1 and the strict rows >= 1, and back: the
   strict inequalities are decided exactly.  For ref_has_motion, a pattern
   with some s, l or r on a touching fixel has a strict row on
   a = J^T nudot, which forces nudot != 0; the pattern n..n (every
   touching fixel n, or no touching fixel at all) asks for nudot != 0
   explicitly, as the six LPs +-nudot_k >= 1 (again by homogeneity).

   Exponential on purpose: 4^t patterns for t touching fixels.  To keep the
   tests fast, the patterns whose rows cannot hold for any wrench are
   remembered per problem: the kinematic part of a pattern's LP, its rows
   on nudot alone (s read as a_in > 0 for motions, as a_in >= 0 for
   Table 2 strings), is a relaxation of the LP for any g, so a pattern it
   rejects is rejected for every g (for Table 2 strings this is exactly
   "W(x) is empty", wrenchcone(1), MODES).  And for the last wrench, whether W(x)
   with u on the near fixels holds it: ref_in_paper_union asks exactly
   that, and ref_modes_holding needs the refinements (s or a on each near
   fixel, subsets of it) only where it does.  The memo is keyed by the
   whole problem written out as text, so a different problem never reuses
   it.  */

#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <flint/flint.h>
#include <flint/fmpq.h>

#ifndef GMPRATIONAL
#define GMPRATIONAL 1
#endif
#include <cddlib/setoper.h>
#include <cddlib/cdd.h>

#include "wrenchcone.h"
#include "ref-stab.h"

/* ---- the model ------------------------------------------------------ */

/* J (3 x 2n, row-major, columns n_1 .. n_n, t_1 .. t_n) and the diagonal
   of M, from the problem's fields alone.  */
typedef struct
{
    slong n;
    mpq_t * J;
    mpq_t m[3];
    mpq_t * mu_s;
    mpq_t * mu_k;
    int * near;
    slong t;                /* touching fixels */
}
model_t;

static mpq_t *
qvec_init(slong len)
{
    mpq_t * v = flint_malloc(sizeof(mpq_t) * (len > 0 ? len : 1));
    slong i;

    for (i = 0; i < len; i++)
        mpq_init(v[i]);
    return v;
}

static void
qvec_clear(mpq_t * v, slong len)
{
    slong i;

    if (v == NULL)
        return;
    for (i = 0; i < len; i++)
        mpq_clear(v[i]);
    flint_free(v);
}

/* Returns 0, or -1 for a problem that is not a valid one (no fixel, a
   zero normal, mass or inertia not positive, negative friction).  */
static int
model_init(model_t * W, const wc_problem_struct * P)
{
    slong n = P->n, k = 2 * n, i, side, j;
    mpq_t r[2], d[2], tmp;
    int ok = 1;

    W->n = n;
    W->J = qvec_init(3 * k);
    for (j = 0; j < 3; j++)
        mpq_init(W->m[j]);
    W->mu_s = qvec_init(n);
    W->mu_k = qvec_init(n);
    W->near = flint_calloc(n > 0 ? n : 1, sizeof(int));
    W->t = 0;
    mpq_init(r[0]);
    mpq_init(r[1]);
    mpq_init(d[0]);
    mpq_init(d[1]);
    mpq_init(tmp);

    if (n < 1)
        ok = 0;
    fmpq_get_mpq(W->m[0], P->mass);
    fmpq_get_mpq(W->m[1], P->mass);
    fmpq_get_mpq(W->m[2], P->inertia);
    if (mpq_sgn(W->m[0]) <= 0 || mpq_sgn(W->m[2]) <= 0)
        ok = 0;

    for (i = 0; i < n && ok; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        if (fmpq_is_zero(f->normal + 0) && fmpq_is_zero(f->normal + 1))
            ok = 0;
        W->near[i] = (f->state == WC_NEAR);
        if (!W->near[i])
            W->t++;
        fmpq_get_mpq(W->mu_s[i], f->mu_s);
        fmpq_get_mpq(W->mu_k[i], f->mu_k);
        if (mpq_sgn(W->mu_s[i]) < 0 || mpq_sgn(W->mu_k[i]) < 0)
            ok = 0;
        for (j = 0; j < 2; j++)
        {
            fmpq_get_mpq(r[j], f->point + j);
            fmpq_get_mpq(tmp, P->com + j);
            mpq_sub(r[j], r[j], tmp);
        }
        /* Column side * n + i: (d_x, d_y, r x d), d the normal or the
           tangent (the normal turned by +90 degrees).  */
        for (side = 0; side < 2; side++)
        {
            slong col = side * n + i;

            if (side == 0)
            {
                fmpq_get_mpq(d[0], f->normal + 0);
                fmpq_get_mpq(d[1], f->normal + 1);
            }
            else
            {
                fmpq_get_mpq(d[0], f->normal + 1);
                mpq_neg(d[0], d[0]);
                fmpq_get_mpq(d[1], f->normal + 0);
            }
            mpq_set(W->J[0 * k + col], d[0]);
            mpq_set(W->J[1 * k + col], d[1]);
            mpq_mul(W->J[2 * k + col], r[0], d[1]);
            mpq_mul(tmp, r[1], d[0]);
            mpq_sub(W->J[2 * k + col], W->J[2 * k + col], tmp);
        }
    }

    mpq_clear(r[0]);
    mpq_clear(r[1]);
    mpq_clear(d[0]);
    mpq_clear(d[1]);
    mpq_clear(tmp);
    return ok ? 0 : -1;
}

static void
model_clear(model_t * W)
{
    slong j;

    qvec_clear(W->J, 3 * 2 * W->n);
    for (j = 0; j < 3; j++)
        mpq_clear(W->m[j]);
    qvec_clear(W->mu_s, W->n);
    qvec_clear(W->mu_k, W->n);
    flint_free(W->near);
}

/* ---- LPs ------------------------------------------------------------ */

/* A cddlib H-representation filled row by row: row i reads
   b + sum_j a_j x_j >= 0, or = 0 when it is in the linearity set.
   Variables are 0-based here, column 1 + var in cddlib.  */
typedef struct
{
    dd_MatrixPtr M;
    dd_rowrange next;
}
lp_rows_t;

static int
rows_init(lp_rows_t * R, slong nrows, slong nvars)
{
    dd_colrange j;

    R->next = 0;
    R->M = dd_CreateMatrix(nrows, 1 + nvars);
    if (R->M == NULL)
        return -1;
    R->M->representation = dd_Inequality;
    R->M->numbtype = dd_Rational;
    R->M->objective = dd_LPmax;
    for (j = 0; j < 1 + nvars; j++)
        dd_set_si(R->M->rowvec[j], 0);
    return 0;
}

static dd_rowrange
row_new(lp_rows_t * R, long b, int equality)
{
    dd_rowrange i = R->next++;

    dd_set_si(R->M->matrix[i][0], b);
    if (equality)
        set_addelem(R->M->linset, i + 1);
    return i;
}

static void
row_si(lp_rows_t * R, dd_rowrange i, slong var, long a)
{
    dd_set_si(R->M->matrix[i][1 + var], a);
}

static void
row_q(lp_rows_t * R, dd_rowrange i, slong var, const mpq_t a)
{
    mpq_set(R->M->matrix[i][1 + var], a);
}

/* 1 when sol (cddlib's layout: sol[j] is variable j - 1) satisfies every
   row of M exactly.  */
static int
point_ok(const dd_MatrixPtr M, const dd_Arow sol)
{
    mpq_t value, tmp;
    dd_rowrange i;
    dd_colrange j;
    int ok = 1;

    mpq_init(value);
    mpq_init(tmp);
    for (i = 0; i < M->rowsize && ok; i++)
    {
        mpq_set(value, M->matrix[i][0]);
        for (j = 1; j < M->colsize; j++)
        {
            mpq_mul(tmp, M->matrix[i][j], sol[j]);
            mpq_add(value, value, tmp);
        }
        if (set_member(i + 1, M->linset))
            ok = (mpq_sgn(value) == 0);
        else
            ok = (mpq_sgn(value) >= 0);
    }
    mpq_clear(value);
    mpq_clear(tmp);
    return ok;
}

/* 1 when cddlib's evidence of inconsistency is a Farkas certificate:
   multipliers lambda (1 on the evidence row lp->re, dsol[j] on the row
   nonbasic in column j + 1), non-negative on inequality rows, such that
   sum lambda_i a_i = 0 and sum lambda_i b_i < 0 (so that
   0 = sum lambda_i (b_i + a_i x) - sum lambda_i b_i > 0 would follow).
   The LP's rows are M's rows, then the reversed copies of M's equalities
   (inequalities themselves), then the objective row, which must not
   take part.  */
static int
farkas_ok(const dd_LPPtr lp, const dd_MatrixPtr M)
{
    mpq_t * sum = qvec_init(lp->d);
    mpq_t tmp;
    dd_colrange j, c;
    int ok = 1;

    mpq_init(tmp);
    for (j = 0; j < lp->d && ok; j++)
    {
        dd_rowrange row = (j == 0) ? lp->re : lp->nbindex[j + 1];
        mpq_srcptr lambda = (j == 0) ? dd_one : lp->dsol[j];

        if (j > 0 && row <= 0)
            continue;
        if (row < 1 || row >= lp->objrow)
            ok = 0;
        else if (mpq_sgn(lambda) < 0
                 && !(row <= M->rowsize && set_member(row, M->linset)))
            ok = 0;
        else
            for (c = 0; c < lp->d; c++)
            {
                mpq_mul(tmp, lambda, lp->A[row - 1][c]);
                mpq_add(sum[c], sum[c], tmp);
            }
    }
    if (ok)
        ok = (mpq_sgn(sum[0]) < 0);
    for (c = 1; c < lp->d && ok; c++)
        ok = (mpq_sgn(sum[c]) == 0);
    mpq_clear(tmp);
    qvec_clear(sum, lp->d);
    return ok;
}

/* Solve the feasibility problem of R (all rows written) and free it.
   1 feasible, 0 infeasible, -1 on any failure or unchecked answer.  */
static int
rows_solve(lp_rows_t * R)
{
    dd_LPPtr lp = NULL;
    dd_ErrorType err = dd_NoError;
    int result = -1;

    if (R->M == NULL || R->next != R->M->rowsize)
        goto cleanup;
    lp = dd_Matrix2LP(R->M, &err);
    if (lp == NULL || err != dd_NoError)
        goto cleanup;
    if (!dd_LPSolve(lp, dd_DualSimplex, &err) || err != dd_NoError)
        goto cleanup;
    if (lp->LPS == dd_Optimal)
        result = point_ok(R->M, lp->sol) ? 1 : -1;
    else if (lp->LPS == dd_Inconsistent)
        result = farkas_ok(lp, R->M) ? 0 : -1;

cleanup:
    if (lp != NULL)
        dd_FreeLPData(lp);
    if (R->M != NULL)
        dd_FreeMatrix(R->M);
    R->M = NULL;
    return result;
}

/* Rows c_in = c_it = 0 of fixel i; forces start at variable c0.  */
static void
rows_no_force(lp_rows_t * R, const model_t * W, slong c0, slong i)
{
    dd_rowrange r;

    r = row_new(R, 0, 1);
    row_si(R, r, c0 + i, 1);
    r = row_new(R, 0, 1);
    row_si(R, r, c0 + W->n + i, 1);
}

/* Rows c_in >= 0, mu c_in - c_it >= 0, mu c_in + c_it >= 0: the friction
   cone of fixel i with coefficient mu.  */
static void
rows_friction_cone(lp_rows_t * R, const model_t * W, slong c0, slong i,
                   const mpq_t mu)
{
    dd_rowrange r;

    r = row_new(R, 0, 0);
    row_si(R, r, c0 + i, 1);
    r = row_new(R, 0, 0);
    row_q(R, r, c0 + i, mu);
    row_si(R, r, c0 + W->n + i, -1);
    r = row_new(R, 0, 0);
    row_q(R, r, c0 + i, mu);
    row_si(R, r, c0 + W->n + i, 1);
}

/* The row -b + s (J_col . nudot) >= 0, or = 0 when equality: with
   b = 1 it is the strict s a_col > 0 written as >= 1, with b = 0 and
   equality a_col = 0.  nudot is at variables 0..2.  */
static void
row_accel(lp_rows_t * R, const model_t * W, slong col, long s, long b,
          int equality)
{
    dd_rowrange r = row_new(R, -b, equality);
    slong k = 2 * W->n, j;
    mpq_t tmp;

    mpq_init(tmp);
    for (j = 0; j < 3; j++)
    {
        mpq_set(tmp, W->J[j * k + col]);
        if (s < 0)
            mpq_neg(tmp, tmp);
        row_q(R, r, j, tmp);
    }
    mpq_clear(tmp);
}

/* ---- weak stability ------------------------------------------------- */

static int
weak_lp(const model_t * W, const fmpq * g)
{
    slong n = W->n, k = 2 * n, i, j;
    lp_rows_t R;
    mpq_t tmp;

    /* Variables c (2n); rows J c + g = 0 (3), then 3 per touching fixel
       and 2 per near one.  */
    if (rows_init(&R, 3 + 3 * W->t + 2 * (n - W->t), k) != 0)
        return -1;
    mpq_init(tmp);
    for (j = 0; j < 3; j++)
    {
        dd_rowrange r = row_new(&R, 0, 1);

        fmpq_get_mpq(tmp, g + j);
        mpq_set(R.M->matrix[r][0], tmp);
        for (i = 0; i < k; i++)
            row_q(&R, r, i, W->J[j * k + i]);
    }
    mpq_clear(tmp);
    for (i = 0; i < n; i++)
    {
        if (W->near[i])
            rows_no_force(&R, W, 0, i);
        else
            rows_friction_cone(&R, W, 0, i, W->mu_s[i]);
    }
    return rows_solve(&R);
}

int
ref_weakly_stable(const wc_problem_t P, const fmpq * g)
{
    model_t W;
    int result = -1;

    wc_init();
    if (g == NULL)
        return -1;
    if (model_init(&W, P) == 0)
        result = weak_lp(&W, g);
    model_clear(&W);
    return result;
}

/* ---- moving solutions ----------------------------------------------- */

/* Rows the pattern LP spends on fixel i under letter x (the kinematic
   part alone when forces == 0).  */
static slong
pattern_rows(char x, int forces)
{
    switch (x)
    {
        case 's': case 'a': return 1 + (forces ? 2 : 0);
        case 'l': case 'r': return 2 + (forces ? 2 : 0);
        case 'n': return 2 + (forces ? 3 : 0);
        case 'u': return forces ? 2 : 0;
        default: return -1;
    }
}

/* The LP of the pattern x (one letter per fixel), with dir = 0 (no
   explicit nudot != 0) or +-(k + 1) for the row +-nudot_k >= 1.  The
   letters read as in the comment at the top; a (near, a_in < 0, c = 0)
   is written as -a_in >= 1.  strict_s = 1 reads s as a_in > 0 (a moving
   solution's sign pattern), strict_s = 0 as Table 2 does, a_in >= 0.
   With g == NULL only the kinematic rows (on nudot) are written: a
   relaxation, infeasible whenever the full LP is infeasible for every g.
   Variables: nudot (3), then c (2n), then t.  */
static int
pattern_lp(const model_t * W, const char * x, int strict_s, int dir,
           const fmpq * g)
{
    slong n = W->n, k = 2 * n, c0 = 3, tv = 3 + k, nrows, i, j;
    int forces = (g != NULL);
    lp_rows_t R;
    dd_rowrange r;
    mpq_t tmp;

    nrows = (forces ? 4 : 0) + (dir != 0 ? 1 : 0);
    for (i = 0; i < n; i++)
    {
        slong m = pattern_rows(x[i], forces);

        if (m < 0)
            return -1;
        nrows += m;
    }
    if (nrows == 0)
        return 1;               /* no row at all: nudot = 0 would do */
    if (rows_init(&R, nrows, forces ? 4 + k : 3) != 0)
        return -1;
    mpq_init(tmp);

    if (forces)
    {
        /* M nudot - J c - t g = 0, t >= 1.  */
        for (j = 0; j < 3; j++)
        {
            r = row_new(&R, 0, 1);
            row_q(&R, r, j, W->m[j]);
            for (i = 0; i < k; i++)
            {
                mpq_neg(tmp, W->J[j * k + i]);
                row_q(&R, r, c0 + i, tmp);
            }
            fmpq_get_mpq(tmp, g + j);
            mpq_neg(tmp, tmp);
            row_q(&R, r, tv, tmp);
        }
        r = row_new(&R, -1, 0);
        row_si(&R, r, tv, 1);
    }

    for (i = 0; i < n; i++)
    {
        switch (x[i])
        {
            case 's':
                row_accel(&R, W, i, 1, strict_s, 0);    /* a_in >= 1, 0 */
                if (forces)
                    rows_no_force(&R, W, c0, i);
                break;
            case 'a':
                row_accel(&R, W, i, -1, 1, 0);          /* -a_in >= 1 */
                if (forces)
                    rows_no_force(&R, W, c0, i);
                break;
            case 'l':
            case 'r':
                row_accel(&R, W, i, 1, 0, 1);           /* a_in = 0 */
                row_accel(&R, W, n + i, x[i] == 'l' ? 1 : -1, 1, 0);
                if (forces)
                {
                    r = row_new(&R, 0, 0);              /* c_in >= 0 */
                    row_si(&R, r, c0 + i, 1);
                    /* c_it + mu_k c_in = 0 (l), c_it - mu_k c_in = 0 (r) */
                    r = row_new(&R, 0, 1);
                    row_si(&R, r, c0 + n + i, 1);
                    mpq_set(tmp, W->mu_k[i]);
                    if (x[i] == 'r')
                        mpq_neg(tmp, tmp);
                    row_q(&R, r, c0 + i, tmp);
                }
                break;
            case 'n':
                row_accel(&R, W, i, 1, 0, 1);           /* a_in = 0 */
                row_accel(&R, W, n + i, 1, 0, 1);       /* a_it = 0 */
                if (forces)
                    rows_friction_cone(&R, W, c0, i, W->mu_s[i]);
                break;
            case 'u':
                if (forces)
                    rows_no_force(&R, W, c0, i);
                break;
            default:
                break;
        }
    }

    if (dir != 0)
    {
        slong v = (dir > 0 ? dir : -dir) - 1;

        r = row_new(&R, -1, 0);
        row_si(&R, r, v, dir > 0 ? 1 : -1);
    }
    mpq_clear(tmp);
    return rows_solve(&R);
}

/* ---- the memo of patterns no wrench can satisfy ----------------------- */

/* The problem written out as text: every field the oracle reads.  */
static char *
problem_key(const wc_problem_struct * P)
{
    size_t len = 0, cap = 256;
    char * s = flint_malloc(cap);
    slong i, j;

    s[0] = '\0';
#define KEY_ADD(str)                                                    \
    do {                                                                \
        const char * add_ = (str);                                      \
        size_t l_ = strlen(add_);                                       \
        while (len + l_ + 2 > cap)                                      \
        {                                                               \
            cap *= 2;                                                   \
            s = flint_realloc(s, cap);                                  \
        }                                                               \
        memcpy(s + len, add_, l_);                                      \
        len += l_;                                                      \
        s[len++] = ' ';                                                 \
        s[len] = '\0';                                                  \
    } while (0)
#define KEY_Q(q)                                                        \
    do {                                                                \
        char * qs_ = fmpq_get_str(NULL, 10, (q));                       \
        KEY_ADD(qs_);                                                   \
        flint_free(qs_);                                                \
    } while (0)

    KEY_Q(P->mass);
    KEY_Q(P->inertia);
    KEY_Q(P->com + 0);
    KEY_Q(P->com + 1);
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        KEY_ADD("|");
        for (j = 0; j < 2; j++)
        {
            KEY_Q(f->point + j);
            KEY_Q(f->normal + j);
        }
        KEY_Q(f->mu_s);
        KEY_Q(f->mu_k);
        KEY_ADD(f->state == WC_NEAR ? "near" : "touching");
    }
#undef KEY_Q
#undef KEY_ADD
    return s;
}

/* For the last problem seen: which strings can hold at all.  Patterns are
   numbered by their touching letters in base 4 ("lnrs", first touching
   fixel most significant) and, for the Table 2 strings of
   ref_modes_holding, the near letters in base 2 ("as") below them.
   -1: not yet known; 0: never; 1: maybe.  */
typedef struct
{
    char * key;
    slong npat;             /* 4^t */
    slong nmodes;           /* 4^t 2^(n - t) */
    signed char * motion;   /* npat (the n..n entry unused: see dir) */
    signed char * dir;      /* 6: n..n with +-nudot_k >= 1 */
    signed char * uni;      /* npat: W(x), u on near fixels, nonempty */
    signed char * modes;    /* nmodes: W(x) nonempty */
    /* For the last wrench asked about: whether W(x) holds it, x with u on
       near fixels (shared by ref_in_paper_union and ref_modes_holding:
       W(x) with s or a on a near fixel lies in W(x) with u there).  */
    int have_g;
    fmpq g[3];
    signed char * holds;    /* npat */
}
memo_t;

static memo_t memo;

static void
memo_reset(void)
{
    flint_free(memo.key);
    flint_free(memo.motion);
    flint_free(memo.dir);
    flint_free(memo.uni);
    flint_free(memo.modes);
    flint_free(memo.holds);
    if (memo.have_g)
    {
        fmpq_clear(memo.g + 0);
        fmpq_clear(memo.g + 1);
        fmpq_clear(memo.g + 2);
    }
    memset(&memo, 0, sizeof memo);
}

/* Make the memo the one of P (t touching fixels, n in all).  Returns 0,
   or -1 when t is too large for 4^t patterns.  */
static int
memo_for(const wc_problem_struct * P, slong t)
{
    char * key = problem_key(P);
    slong i;

    if (memo.key != NULL && strcmp(memo.key, key) == 0)
    {
        flint_free(key);
        return 0;
    }
    memo_reset();
    if (t > 12 || P->n - t > 20)
    {
        flint_free(key);
        return -1;
    }
    memo.key = key;
    memo.npat = WORD(1) << (2 * t);
    memo.nmodes = memo.npat << (P->n - t);
    memo.motion = flint_malloc(memo.npat);
    memo.uni = flint_malloc(memo.npat);
    memo.modes = flint_malloc(memo.nmodes);
    memo.dir = flint_malloc(6);
    memo.holds = flint_malloc(memo.npat);
    memset(memo.motion, -1, memo.npat);
    memset(memo.uni, -1, memo.npat);
    memset(memo.modes, -1, memo.nmodes);
    for (i = 0; i < 6; i++)
        memo.dir[i] = -1;
    return 0;
}

/* The string of pattern number p (touching letters from "lnrs", base 4)
   and near number q (near letters from near_letters, base 2; NULL: u on
   every near fixel).  */
static void
pattern_string(char * x, const model_t * W, slong p, slong q,
               const char * near_letters)
{
    slong i;

    for (i = W->n - 1; i >= 0; i--)
    {
        if (W->near[i])
        {
            x[i] = (near_letters == NULL) ? 'u' : near_letters[q & 1];
            q >>= 1;
        }
        else
        {
            x[i] = "lnrs"[p & 3];
            p >>= 2;
        }
    }
    x[W->n] = '\0';
}

/* Number of the all-n pattern: "n" is letter 1 of "lnrs".  */
static slong
pattern_all_n(slong t)
{
    slong p = 0, i;

    for (i = 0; i < t; i++)
        p = 4 * p + 1;
    return p;
}

/* 1 when some solution of pattern x (number p) has nudot != 0 for g; 0
   when none; -1 on failure.  The memo spares the LPs of patterns that no
   wrench satisfies.  */
static int
pattern_moves(const model_t * W, const char * x, slong p, const fmpq * g)
{
    int res, d;

    if (p != pattern_all_n(W->t))
    {
        if (memo.motion[p] < 0)
        {
            res = pattern_lp(W, x, 1, 0, NULL);
            if (res < 0)
                return -1;
            memo.motion[p] = (signed char) res;
        }
        if (memo.motion[p] == 0)
            return 0;
        return pattern_lp(W, x, 1, 0, g);
    }

    /* n..n: a_i = 0 on every touching fixel does not force nudot != 0;
       ask for it one coordinate and sign at a time.  */
    for (d = 0; d < 6; d++)
    {
        int dir = (d / 2 + 1) * (d % 2 ? -1 : 1);

        if (memo.dir[d] < 0)
        {
            res = pattern_lp(W, x, 1, dir, NULL);
            if (res < 0)
                return -1;
            memo.dir[d] = (signed char) res;
        }
        if (memo.dir[d] == 0)
            continue;
        res = pattern_lp(W, x, 1, dir, g);
        if (res != 0)
            return res;
    }
    return 0;
}

int
ref_has_motion(const wc_problem_t P, const fmpq * g)
{
    model_t W;
    char * x = NULL;
    slong p;
    int result = -1, res;

    wc_init();
    if (g == NULL)
        return -1;
    if (model_init(&W, P) != 0 || memo_for(P, W.t) != 0)
        goto cleanup;
    x = flint_malloc(W.n + 1);
    result = 0;
    for (p = 0; p < memo.npat && result == 0; p++)
    {
        pattern_string(x, &W, p, 0, NULL);
        res = pattern_moves(&W, x, p, g);
        if (res != 0)
            result = res;       /* 1: found; -1: failure */
    }

cleanup:
    flint_free(x);
    model_clear(&W);
    return result;
}

/* ---- Table 2 cones -------------------------------------------------- */

/* 1 when W(x) holds g (x a Table 2 string: s l r n on touching fixels,
   s a u on near ones): the pattern LP with s read as a_in >= 0, over
   (nudot, c, t), since g = M nudot - J c with a = J^T nudot is eq. (7)
   solved for g (see the top of the file).  The LP is skipped when the memo entry *known says W(x) is empty (and
   filled first): W(x) is empty iff no nudot satisfies x's rows on
   a = J^T nudot, since such a nudot with c = 0 gives g = M nudot in
   W(x).  */
static int
in_cone_memo(const model_t * W, const char * x, signed char * known,
             const fmpq * g)
{
    if (*known < 0)
    {
        int res = pattern_lp(W, x, 0, 0, NULL);

        if (res < 0)
            return -1;
        *known = (signed char) res;
    }
    if (*known == 0)
        return 0;
    return pattern_lp(W, x, 0, 0, g);
}

/* Whether W(x) holds g for the touching pattern p with u on every near
   fixel (x receives that string), remembered for the last g.  */
static int
holds_u(char * x, const model_t * W, slong p, const fmpq * g)
{
    slong j;

    if (!memo.have_g)
    {
        for (j = 0; j < 3; j++)
            fmpq_init(memo.g + j);
        memo.have_g = 1;
        memset(memo.holds, -1, memo.npat);
    }
    for (j = 0; j < 3; j++)
        if (!fmpq_equal(memo.g + j, g + j))
            break;
    if (j < 3)
    {
        for (j = 0; j < 3; j++)
            fmpq_set(memo.g + j, g + j);
        memset(memo.holds, -1, memo.npat);
    }
    pattern_string(x, W, p, 0, NULL);
    if (memo.holds[p] < 0)
    {
        int res = in_cone_memo(W, x, memo.uni + p, g);

        if (res < 0)
            return -1;
        memo.holds[p] = (signed char) res;
    }
    return memo.holds[p];
}

int
ref_in_paper_union(const wc_problem_t P, const fmpq * g)
{
    model_t W;
    char * x = NULL;
    slong p, alln;
    int result = -1, res;

    wc_init();
    if (g == NULL)
        return -1;
    if (model_init(&W, P) != 0 || memo_for(P, W.t) != 0)
        goto cleanup;
    x = flint_malloc(W.n + 1);
    alln = pattern_all_n(W.t);
    result = 0;
    for (p = 0; p < memo.npat && result == 0; p++)
    {
        if (p == alln)
            continue;           /* eq. 19 leaves out n..n */
        res = holds_u(x, &W, p, g);
        if (res != 0)
            result = res;
    }

cleanup:
    flint_free(x);
    model_clear(&W);
    return result;
}

/* qsort on the fixed-size, NUL-terminated entries of the mode list.  */
static int
string_cmp(const void * a, const void * b)
{
    return strcmp((const char *) a, (const char *) b);
}

char *
ref_modes_holding(slong * count, const wc_problem_t P, const fmpq * g)
{
    model_t W;
    char * x = NULL, * out = NULL;
    slong p, q, nnear, found = 0, idx;
    int ok = 0, res;

    wc_init();
    if (count != NULL)
        *count = 0;
    if (g == NULL || count == NULL)
        return NULL;
    if (model_init(&W, P) != 0 || memo_for(P, W.t) != 0)
        goto cleanup;
    nnear = W.n - W.t;
    x = flint_malloc(W.n + 1);
    out = malloc((size_t) (memo.nmodes * (W.n + 1) + 1));
    if (out == NULL)
        goto cleanup;
    /* Every string with s l r n on touching and s a on near fixels; near
       and touching fixels interleave, so the list is sorted afterwards.  */
    for (p = 0; p < memo.npat; p++)
    {
        /* W(x) with s or a on near fixels lies in W(x) with u there: no
           LP for the refinements when that does not hold g, and none when
           there is no near fixel (the string is the same).  */
        res = holds_u(x, &W, p, g);
        if (res < 0)
            goto cleanup;
        if (res == 0)
            continue;
        for (q = 0; q < (WORD(1) << nnear); q++)
        {
            idx = (p << nnear) + q;
            pattern_string(x, &W, p, q, "as");
            res = (nnear == 0) ? 1
                : in_cone_memo(&W, x, memo.modes + idx, g);
            if (res < 0)
                goto cleanup;
            if (res)
            {
                memcpy(out + found * (W.n + 1), x, W.n + 1);
                found++;
            }
        }
    }
    qsort(out, (size_t) found, (size_t) (W.n + 1), string_cmp);
    *count = found;
    ok = 1;

cleanup:
    flint_free(x);
    model_clear(&W);
    if (!ok)
    {
        free(out);
        out = NULL;
    }
    return out;
}
