/* facesys.c -- the linear system of one moving face for a wrench, solved
   to a motion or to a Motzkin certificate.

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
   wrenchcone-certificate(5), in the same order.  */

#include <config.h>

#include <flint/fmpq_vec.h>

#include "model/model.h"
#include "exact/lp.h"
#include "exact/vec3.h"
#include "analysis/facesys.h"

typedef struct
{
    fmpq_mat_t A;           /* rows over z = (nudot, lambda, tau) */
    wc_relation * rel;
    slong rows, e;          /* e edges */
    slong * efix;           /* the fixel of edge j */
    fmpq * edir;            /* (e_n, e_t) of edge j; room for 2 alen */
    slong alen;
}
facesys;

static void
facesys_clear(facesys * s)
{
    fmpq_mat_clear(s->A);
    flint_free(s->rel);
    flint_free(s->efix);
    _fmpq_vec_clear(s->edir, 2 * s->alen);
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

/* The friction edges the force letters x allow.  */
static void
facesys_edges(facesys * s, const _wc_stab_model * m, const char * x)
{
    const wc_problem_struct * P = m->P;
    slong n = m->n, i, j, c;
    fmpq ed[4];

    for (j = 0; j < 4; j++)
        fmpq_init(ed + j);
    s->alen = 2 * n + 1;
    s->efix = flint_malloc(sizeof(slong) * s->alen);
    s->edir = _fmpq_vec_init(2 * s->alen);
    s->e = 0;
    for (i = 0; i < n; i++)
    {
        if (P->fixels[i].state != WC_TOUCHING)
            continue;
        c = wc_friction_edges(ed, P->fixels + i, x[i]);
        for (j = 0; j < c; j++, s->e++)
        {
            s->efix[s->e] = i;
            _wc_qvec_set(s->edir + 2 * s->e, ed + 2 * j, 2);
        }
    }
    for (j = 0; j < 4; j++)
        fmpq_clear(ed + j);
}

/* y's rows on nudot: Table 1 signs of a = J^T nudot; with closed, every
   > row as >= (the closure of the face).  */
static void
facesys_motion_rows(facesys * s, const _wc_stab_model * m, const char * y,
                    int rot, int closed)
{
    wc_relation gt = closed ? WC_REL_GE : WC_REL_GT;
    slong i;

    for (i = 0; i < m->n; i++)
    {
        const fmpq * jn = m->Jn + 3 * i, * jt = m->Jt + 3 * i;
        char c = y[i];

        if (m->P->fixels[i].state == WC_NEAR)
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
            put_row(s, jn, 0, gt);
            break;
        case 'l':
            put_row(s, jn, 0, WC_REL_EQ);
            put_row(s, jt, 0, gt);
            break;
        case 'r':
            put_row(s, jn, 0, WC_REL_EQ);
            put_row(s, jt, 1, gt);
            break;
        default:
            put_row(s, jn, 0, WC_REL_EQ);
            put_row(s, jt, 0, WC_REL_EQ);
            break;
        }
    }
    if (rot != 0)
        put_row(s, m->v, rot < 0, gt);
}

/* The system over z = (nudot, lambda, alpha_1 .. alpha_ng) for the
   wrenches sum_i alpha_i G_i, alpha_i > 0 (ng = 1: tau g).  */
static void
facesys_init(facesys * s, const _wc_stab_model * m, const char * y,
             const char * x, int rot, const fmpq * G, slong ng, int closed)
{
    slong j, k, e, nv, i;
    fmpq w[3];

    facesys_edges(s, m, x);
    e = s->e;
    nv = 3 + e + ng;
    fmpq_mat_init(s->A, 3 + 2 * m->n + 1 + e + ng, nv);
    s->rel = flint_malloc(sizeof(wc_relation) * fmpq_mat_nrows(s->A));

    /* M nudot - sum lambda_j w_j - sum alpha_i G_i = 0 */
    for (k = 0; k < 3; k++)
    {
        fmpq_init(w + k);
        fmpq_set(fmpq_mat_entry(s->A, k, k), m->M + k);
        for (i = 0; i < ng; i++)
            fmpq_neg(fmpq_mat_entry(s->A, k, 3 + e + i), G + 3 * i + k);
        s->rel[k] = WC_REL_EQ;
    }
    for (j = 0; j < e; j++)
    {
        _wc_stab_edge_wrench(w, m, s->efix[j], s->edir + 2 * j);
        for (k = 0; k < 3; k++)
            fmpq_neg(fmpq_mat_entry(s->A, k, 3 + j), w + k);
    }
    s->rows = 3;
    facesys_motion_rows(s, m, y, rot, closed);
    for (j = 0; j < e; j++)
    {
        fmpq_one(fmpq_mat_entry(s->A, s->rows, 3 + j));
        s->rel[s->rows++] = WC_REL_GE;
    }
    for (i = 0; i < ng; i++)
    {
        fmpq_one(fmpq_mat_entry(s->A, s->rows, 3 + e + i));
        s->rel[s->rows++] = WC_REL_GT;
    }
    _wc_fmpq_mat_keep_rows(s->A, s->rows);
    for (k = 0; k < 3; k++)
        fmpq_clear(w + k);
}

/* Read a solution z of s (tau > 0) into nudot and c (2n).  */
static void
facesys_motion(fmpq * nudot, fmpq * c, const facesys * s,
               const _wc_stab_model * m, const fmpq * z)
{
    slong n = m->n, j, k;
    const fmpq * tau = z + 3 + s->e;
    fmpq_t q;

    fmpq_init(q);
    for (k = 0; k < 3; k++)
        fmpq_div(nudot + k, z + k, tau);
    _wc_qvec_zero(c, 2 * n);
    for (j = 0; j < s->e; j++)
    {
        slong i = s->efix[j];

        fmpq_div(q, z + 3 + j, tau);
        fmpq_addmul(c + i, q, s->edir + 2 * j);
        fmpq_addmul(c + n + i, q, s->edir + 2 * j + 1);
    }
    fmpq_clear(q);
}

/* 1 when face y forces nudot = 0 -- every touching letter n, no contact
   point shared by all touching fixels, no near row but a_in >= 0 --, or
   nudot on the rotation line with no near row at all: a cone membership
   in R^3 decides it.  */
static int
zero_face(const _wc_stab_model * m, const char * y)
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

/* A zero face: nudot = 0 (or mu v, v the rotation, when every touching
   fixel shares a point), so g = mu M v - sum lambda_j w_j, one cone
   membership.  z (3 + e + 1) := the solution.  */
static int
zero_face_solve(fmpq * z, const facesys * s, const _wc_stab_model * m,
                const fmpq * g, wc_error_t err)
{
    slong k = s->e + (m->shared ? 2 : 0), nv = 3 + s->e + 1, j, i;
    fmpq * G = _fmpq_vec_init(3 * k + 3), * lam = _fmpq_vec_init(k + 1);
    fmpq sep[3];
    int r;

    for (i = 0; i < 3; i++)
        fmpq_init(sep + i);
    for (j = 0; j < s->e; j++)
    {
        _wc_stab_edge_wrench(G + 3 * j, m, s->efix[j], s->edir + 2 * j);
        for (i = 0; i < 3; i++)
            fmpq_neg(G + 3 * j + i, G + 3 * j + i);
    }
    if (m->shared)
        for (i = 0; i < 3; i++)
        {
            fmpq_mul(G + 3 * s->e + i, m->v + i, m->M + i);
            fmpq_neg(G + 3 * (s->e + 1) + i, G + 3 * s->e + i);
        }
    r = _wc_lp_cone3(lam, sep, G, k, g, err);
    if (r == 1)
    {
        _wc_qvec_zero(z, nv);
        _wc_qvec_set(z + 3, lam, s->e);
        if (m->shared)
            for (i = 0; i < 3; i++)
            {
                fmpq_sub(z + i, lam + s->e, lam + s->e + 1);
                fmpq_mul(z + i, z + i, m->v + i);
            }
        fmpq_one(z + nv - 1);
        if (!_wc_lp_rows_hold(s->A, s->rel, z))
            r = (wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal "
                              "error: a zero-face solution fails"), -1);
    }
    for (i = 0; i < 3; i++)
        fmpq_clear(sep + i);
    _fmpq_vec_clear(G, 3 * k + 3);
    _fmpq_vec_clear(lam, k + 1);
    return r;
}

static int face_separate(const facesys * s, const _wc_stab_model * m,
                         const fmpq * g, wc_error_t err);

int
_wc_face_solve(fmpq * nudot, fmpq * c, fmpq ** mult, slong * nmult,
               const _wc_stab_model * m, const char * y, const char * x,
               int rot, const fmpq * g, wc_error_t err)
{
    return _wc_face_solve_cone(nudot, c, mult, nmult, m, y, x, rot, g, 1,
                               0, err);
}

/* Two motions to try before an LP, for the single wrench g: the body
   alone (nudot = M^-1 g, no force), or one friction edge alone (g =
   -lambda w_j, nudot = 0).  1 with z (3 + e + 1) a solution; 0.  */
static int
quick_motion(fmpq * z, const facesys * s, const _wc_stab_model * m,
             const fmpq * g)
{
    fmpq w[3], x[3];
    fmpq_t d;
    slong j, k, nv = 3 + s->e + 1;
    int r;

    _wc_qvec_zero(z, nv);
    for (k = 0; k < 3; k++)
        fmpq_div(z + k, g + k, m->M + k);
    fmpq_one(z + nv - 1);
    if ((r = _wc_lp_rows_hold(s->A, s->rel, z)) == 1)
        return 1;
    fmpq_init(d);
    for (k = 0; k < 3; k++)
    {
        fmpq_init(w + k);
        fmpq_init(x + k);
    }
    for (j = 0; j < s->e && r != 1; j++)
    {
        _wc_stab_edge_wrench(w, m, s->efix[j], s->edir + 2 * j);
        _wc_qvec3_cross(x, w, g);
        _fmpq_vec_dot(d, w, g, 3);
        if (!_wc_qvec_is_zero(x, 3) || fmpq_sgn(d) >= 0)
            continue;
        /* g = -lambda w_j: lambda = -(w . g) / (w . w) */
        _wc_qvec_zero(z, nv);
        fmpq_one(z + nv - 1);
        fmpq_neg(z + 3 + j, d);
        _fmpq_vec_dot(d, w, w, 3);
        fmpq_div(z + 3 + j, z + 3 + j, d);
        r = _wc_lp_rows_hold(s->A, s->rel, z);
    }
    fmpq_clear(d);
    for (k = 0; k < 3; k++)
    {
        fmpq_clear(w + k);
        fmpq_clear(x + k);
    }
    return r == 1;
}

int
_wc_face_solve_cone(fmpq * nudot, fmpq * c, fmpq ** mult, slong * nmult,
                    const _wc_stab_model * m, const char * y,
                    const char * x, int rot, const fmpq * G, slong ng,
                    int closed, wc_error_t err)
{
    facesys s;
    slong nv, k;
    fmpq * z, * y0 = NULL;
    const fmpq * g = G;
    int r, plain = ng == 1 && !closed;

    facesys_init(&s, m, y, x, rot, G, ng, closed);
    nv = 3 + s.e + ng;
    z = _fmpq_vec_init(nv);
    if (plain && mult == NULL && rot == 0 && zero_face(m, y))
        r = zero_face_solve(z, &s, m, g, err);
    else if (plain && s.e == 0 && mult == NULL)
    {
        /* Without a force edge the motion can only be nudot = M^-1 g.  */
        for (k = 0; k < 3; k++)
            fmpq_div(z + k, g + k, m->M + k);
        fmpq_one(z + 3);
        r = _wc_lp_rows_hold(s.A, s.rel, z);
    }
    else if (ng == 1 && mult == NULL && quick_motion(z, &s, m, g))
        r = 1;
    else if (ng == 1 && mult == NULL
             && (r = face_separate(&s, m, g, err)) != 0)
        r = r > 0 ? 0 : -1;
    else
    {
        if (mult != NULL)
            y0 = _fmpq_vec_init(s.rows);
        r = _wc_lp_motzkin(z, y0, s.A, s.rel, err);
        if (r == 0 && mult != NULL)
        {
            *mult = y0;
            *nmult = s.rows;
            y0 = NULL;
        }
        if (y0 != NULL)
            _fmpq_vec_clear(y0, s.rows);
    }
    if (r == 1 && ng == 1 && nudot != NULL)
        facesys_motion(nudot, c, &s, m, z);
    _fmpq_vec_clear(z, nv);
    facesys_clear(&s);
    return r;
}

/* ---------------------------------------------------------------------
   Multipliers from a facet.  When a plane h . g = 0 has the face's cone
   W on its side h . g <= 0 and every G_i on the other, h . G_i >= 0 with
   one > 0, the multipliers need no LP: h on the three = rows (their sum
   is (M h) . nudot - sum_j (h . w_j) lambda_j - sum_i (h . G_i) alpha_i),
   h . w_j on each lambda row and h . G_i on each alpha row (both >= 0:
   -w_j is in W), and on the rows on nudot mu with sum_r mu_r row_r =
   -M h, mu >= 0 off the = rows -- which exists since (M h) . v <= 0 for
   every v of the closed face (Farkas), and is a point of a cone in R^3
   (exact/lp.h's simplex).  When every h . G_i is 0 (the G_i on the plane,
   which then touches the face's cone on its open boundary), Motzkin's
   strict row must be a > row on nudot instead: mu is sought with eps > 0
   on every > row.  */

/* 1 with y (s->rows) filled and checked; 0 when h does not separate or
   the multipliers fail (the caller then solves the LP); -1 on failure.  */
static int
facet_mult(fmpq * y, const facesys * s, const _wc_stab_model * m,
           const fmpq * h, slong ng, wc_error_t err)
{
    slong nv = 3 + s->e + ng, nmot = s->rows - 3 - s->e - ng, r, k, j, q;
    fmpq * gen = _fmpq_vec_init(3 * 2 * nmot + 3);
    fmpq * lam = _fmpq_vec_init(2 * nmot + 1), * sum = _fmpq_vec_init(nv);
    char * isgt = flint_calloc(2 * nmot + 1, 1);
    fmpq t[3], sep[3], sgt[3];
    fmpq_t eps;
    int ok = 1, strict = 0, res, tries, gt = 0;

    fmpq_init(eps);
    for (k = 0; k < 3; k++)
    {
        fmpq_init(t + k);
        fmpq_init(sep + k);
        fmpq_init(sgt + k);
        fmpq_set(y + k, h + k);
    }
    /* h . w_j and h . G_i: minus h times their columns in the = rows */
    for (j = 3; j < nv && ok; j++)
    {
        fmpq_zero(t + 0);
        for (k = 0; k < 3; k++)
            fmpq_submul(t + 0, h + k, fmpq_mat_entry(s->A, k, j));
        ok = fmpq_sgn(t + 0) >= 0;
        strict |= j >= 3 + s->e && fmpq_sgn(t + 0) > 0;
        fmpq_set(y + 3 + nmot + (j - 3), t + 0);
    }
    /* -M h as mu on the rows on nudot: each row, and its negative for =;
       sgt the sum of the > rows */
    for (r = 0, q = 0; ok && r < nmot; r++)
        for (j = 0; j < (s->rel[3 + r] == WC_REL_EQ ? 2 : 1); j++, q++)
            for (k = 0; k < 3; k++)
                if (j == 0)
                {
                    fmpq_set(gen + 3 * q + k,
                             fmpq_mat_entry(s->A, 3 + r, k));
                    if (s->rel[3 + r] == WC_REL_GT)
                        fmpq_add(sgt + k, sgt + k, gen + 3 * q + k);
                    gt |= s->rel[3 + r] == WC_REL_GT;
                    isgt[q] = s->rel[3 + r] == WC_REL_GT;
                }
                else
                    fmpq_neg(gen + 3 * q + k,
                             fmpq_mat_entry(s->A, 3 + r, k));
    for (k = 0; k < 3; k++)
    {
        fmpq_mul(t + k, m->M + k, h + k);
        fmpq_neg(t + k, t + k);
    }
    /* with no G_i off the plane, the strict row of Motzkin's theorem must
       be a > row on nudot: mu = lam + eps on each (then on one at a time),
       for the first eps = 1, 1/2, .. with -M h - eps (their sum) in the
       cone of the rows */
    res = 0;
    for (j = strict ? -2 : gt ? -1 : q;
         ok && res == 0 && j < q && (j == -2 || !strict); j++)
    {
        if (j >= 0 && !isgt[j])
            continue;
        for (k = 0; j >= 0 && k < 3; k++)
            fmpq_set(sgt + k, gen + 3 * j + k);
        fmpq_one(eps);
        for (tries = 0; res == 0 && tries < (j == -2 ? 1 : 6); tries++)
        {
            for (k = 0; j > -2 && k < 3; k++)
                fmpq_submul(t + k, eps, sgt + k);
            res = _wc_lp_cone3(lam, sep, gen, q, t, err);
            for (k = 0; j > -2 && k < 3; k++)
                fmpq_addmul(t + k, eps, sgt + k);
            if (res == 0)
                fmpq_div_2exp(eps, eps, 1);
        }
        for (r = 0; res == 1 && j > -2 && r < q; r++)
            if (j == -1 ? isgt[r] : r == j)
                fmpq_add(lam + r, lam + r, eps);
    }
    for (r = 0, q = 0; res == 1 && r < nmot; r++)
    {
        fmpq_set(y + 3 + r, lam + q++);
        if (s->rel[3 + r] == WC_REL_EQ)
            fmpq_sub(y + 3 + r, y + 3 + r, lam + q++);
    }
    /* the check: every sign, one > row positive, the rows summing to 0 */
    for (r = 0, strict = 0; res == 1 && r < s->rows; r++)
    {
        if (s->rel[r] != WC_REL_EQ && fmpq_sgn(y + r) < 0)
            res = 0;
        strict |= s->rel[r] == WC_REL_GT && fmpq_sgn(y + r) > 0;
        for (j = 0; j < nv; j++)
            fmpq_addmul(sum + j, y + r, fmpq_mat_entry(s->A, r, j));
    }
    if (res == 1 && (!strict || !_wc_qvec_is_zero(sum, nv)))
        res = 0;
    fmpq_clear(eps);
    for (k = 0; k < 3; k++)
    {
        fmpq_clear(t + k);
        fmpq_clear(sep + k);
        fmpq_clear(sgt + k);
    }
    _fmpq_vec_clear(gen, 3 * 2 * nmot + 3);
    _fmpq_vec_clear(lam, 2 * nmot + 1);
    _fmpq_vec_clear(sum, nv);
    flint_free(isgt);
    return res;
}

int
_wc_face_facet_mult(fmpq ** mult, slong * nmult, const _wc_stab_model * m,
                    const char * y, int rot, const fmpq * h,
                    const fmpq * G, slong ng, wc_error_t err)
{
    facesys s;
    fmpq * v;
    int r;

    facesys_init(&s, m, y, y, rot, G, ng, 0);
    v = _fmpq_vec_init(s.rows);
    r = facet_mult(v, &s, m, h, ng, err);
    if (r == 1)
    {
        *mult = v;
        *nmult = s.rows;
    }
    else
        _fmpq_vec_clear(v, s.rows);
    facesys_clear(&s);
    return r;
}

/* ---------------------------------------------------------------------
   A quick proof that a face has no motion for one wrench g.  The closure
   of the face's motions, cl V = { u : the = rows, the > and >= rows as
   >= } (on nudot), is a line or a wedge in a plane whenever an = row is
   there -- always when the face loads a fixel.  Its generators u_k, mapped
   by M, and the -w_j generate the closed cone cl W of the wrenches the
   face holds; when g is outside it, the 3-D simplex separates g by a
   plane h, and facet_mult turns h into Motzkin multipliers checked
   against every row of the system.  The answer is then "no motion",
   exactly what the LP would say; in every other case (g in cl W, no =
   row) the LP decides.  For the cradle's rotation faces this replaces an
   LP of 2t + 4 columns by two 3-D simplex runs.  */

/* The closed 2-D cone in the plane e . u = 0: its state and up to four
   generators (3-vectors in the plane).  */
enum { W_FULL, W_HALF, W_LINE, W_WEDGE, W_RAY, W_ZERO };

typedef struct
{
    int state;
    fmpq r1[3], r2[3];      /* HALF: r1 the inner normal; LINE: r1; WEDGE:
                               r1, r2; RAY: r1 */
    fmpq e[3];              /* the plane's normal */
    fmpq t[3], d;           /* scratch */
}
wedge;

/* c := the projection of r on the plane, times |e|^2.  */
static void
wedge_project(fmpq * c, wedge * W, const fmpq * r)
{
    slong k;

    _fmpq_vec_dot(&W->d, W->e, r, 3);
    for (k = 0; k < 3; k++)
    {
        fmpq_mul(c + k, W->e + k, &W->d);
        fmpq_neg(c + k, c + k);
    }
    _fmpq_vec_dot(&W->d, W->e, W->e, 3);
    for (k = 0; k < 3; k++)
        fmpq_addmul(c + k, r + k, &W->d);
}

/* out := +-(e x c), the sign making s . out > 0 (s . (e x c) != 0).  */
static void
wedge_boundary(fmpq * out, wedge * W, const fmpq * c, const fmpq * s)
{
    slong k;

    _wc_qvec3_cross(out, W->e, c);
    _fmpq_vec_dot(&W->d, s, out, 3);
    if (fmpq_sgn(&W->d) < 0)
        for (k = 0; k < 3; k++)
            fmpq_neg(out + k, out + k);
}

/* Cut the cone by r . u >= 0.  */
static void
wedge_cut(wedge * W, const fmpq * r)
{
    fmpq c[3], b[3];
    fmpq_t s1, s2;
    slong k;

    for (k = 0; k < 3; k++)
    {
        fmpq_init(c + k);
        fmpq_init(b + k);
    }
    fmpq_init(s1);
    fmpq_init(s2);
    wedge_project(c, W, r);
    if (_wc_qvec_is_zero(c, 3) || W->state == W_ZERO)
        ;
    else if (W->state == W_FULL)
    {
        _wc_qvec_set(W->r1, c, 3);
        W->state = W_HALF;
    }
    else if (W->state == W_HALF)
    {
        _wc_qvec3_cross(b, W->r1, c);
        _fmpq_vec_dot(s1, W->r1, c, 3);
        if (!_wc_qvec_is_zero(b, 3))
        {
            /* two rays: e x r1 turned into c >= 0, e x c into r1 >= 0 */
            _wc_qvec_set(b, W->r1, 3);
            wedge_boundary(W->r1, W, b, c);
            wedge_boundary(W->r2, W, c, b);
            W->state = W_WEDGE;
        }
        else if (fmpq_sgn(s1) < 0)
        {
            _wc_qvec3_cross(b, W->e, W->r1);
            _wc_qvec_set(W->r1, b, 3);
            W->state = W_LINE;
        }
    }
    else
    {
        _fmpq_vec_dot(s1, r, W->r1, 3);
        _fmpq_vec_dot(s2, r, W->r2, 3);
        if (W->state == W_LINE && fmpq_sgn(s1) != 0)
        {
            if (fmpq_sgn(s1) < 0)
                for (k = 0; k < 3; k++)
                    fmpq_neg(W->r1 + k, W->r1 + k);
            W->state = W_RAY;
        }
        else if (W->state == W_RAY && fmpq_sgn(s1) < 0)
            W->state = W_ZERO;
        else if (W->state == W_WEDGE && (fmpq_sgn(s1) < 0 || fmpq_sgn(s2) < 0))
        {
            if (fmpq_sgn(s1) <= 0 && fmpq_sgn(s2) <= 0)
            {
                /* both sides out (or on the line): what is left */
                W->state = fmpq_sgn(s1) == 0 ? W_RAY
                    : fmpq_sgn(s2) == 0 ? W_RAY : W_ZERO;
                if (fmpq_sgn(s1) != 0)
                    _wc_qvec_set(W->r1, W->r2, 3);
            }
            else
            {
                /* one ray out: it moves to the line r . u = 0,
                   s_in r_out - s_out r_in */
                fmpq * in = fmpq_sgn(s1) < 0 ? W->r2 : W->r1;
                fmpq * out = fmpq_sgn(s1) < 0 ? W->r1 : W->r2;
                fmpq * si = fmpq_sgn(s1) < 0 ? s2 : s1;
                fmpq * so = fmpq_sgn(s1) < 0 ? s1 : s2;

                for (k = 0; k < 3; k++)
                {
                    fmpq_mul(out + k, out + k, si);
                    fmpq_submul(out + k, in + k, so);
                }
            }
        }
    }
    for (k = 0; k < 3; k++)
    {
        fmpq_clear(c + k);
        fmpq_clear(b + k);
    }
    fmpq_clear(s1);
    fmpq_clear(s2);
}

/* G := the generators of the cone W (in R^3); their number.  */
static slong
wedge_gens(fmpq * G, wedge * W)
{
    slong i, k = 0;

    switch (W->state)
    {
    case W_FULL:
        /* e x a and e x (e x a), a an axis not along e */
        _wc_qvec_zero(W->t, 3);
        fmpq_one(W->t + (fmpq_is_zero(W->e + 1) && fmpq_is_zero(W->e + 2)
                         ? 1 : 0));
        _wc_qvec3_cross(W->r1, W->e, W->t);
        _wc_qvec3_cross(W->r2, W->e, W->r1);
        k = 4;
        break;
    case W_HALF:
        _wc_qvec3_cross(W->r2, W->e, W->r1);
        _wc_qvec_set(G, W->r1, 3);
        _wc_qvec_set(G + 3, W->r2, 3);
        for (i = 0; i < 3; i++)
            fmpq_neg(G + 6 + i, W->r2 + i);
        return 3;
    case W_LINE:
        _wc_qvec_set(G, W->r1, 3);
        for (i = 0; i < 3; i++)
            fmpq_neg(G + 3 + i, W->r1 + i);
        return 2;
    case W_WEDGE:
        _wc_qvec_set(G, W->r1, 3);
        _wc_qvec_set(G + 3, W->r2, 3);
        return 2;
    case W_RAY:
        _wc_qvec_set(G, W->r1, 3);
        return 1;
    default:
        return 0;
    }
    /* the full plane: +-r1, +-r2 */
    _wc_qvec_set(G, W->r1, 3);
    _wc_qvec_set(G + 3, W->r2, 3);
    for (i = 0; i < 3; i++)
    {
        fmpq_neg(G + 6 + i, W->r1 + i);
        fmpq_neg(G + 9 + i, W->r2 + i);
    }
    return k;
}

/* G (room for 4 + e generators) := M times the generators of cl V, then
   the -w_j; *k their number.  0 when the face has no = row on nudot.  */
static int
closure_gens(fmpq * G, slong * k, const facesys * s,
             const _wc_stab_model * m)
{
    slong nmot = s->rows - 3 - s->e - 1, r, i, j, kk = 0;
    const fmpq * e1 = NULL, * row;
    fmpq_t q;
    wedge W;
    int rank = 0, sg, ok;

    fmpq_init(q);
    fmpq_init(&W.d);
    for (i = 0; i < 3; i++)
    {
        fmpq_init(W.r1 + i);
        fmpq_init(W.r2 + i);
        fmpq_init(W.e + i);
        fmpq_init(W.t + i);
    }
    /* the = rows: rank 1 (W.e their normal) or 2 (W.t their line) or 3 */
    for (r = 0; r < nmot && rank < 3; r++)
    {
        row = s->A->rows[3 + r];
        if (s->rel[3 + r] != WC_REL_EQ || _wc_qvec_is_zero(row, 3))
            continue;
        if (rank == 0)
        {
            e1 = row;
            rank = 1;
            continue;
        }
        if (rank == 1)
        {
            _wc_qvec3_cross(W.t, e1, row);
            rank = _wc_qvec_is_zero(W.t, 3) ? 1 : 2;
            continue;
        }
        _fmpq_vec_dot(q, W.t, row, 3);
        rank = fmpq_is_zero(q) ? 2 : 3;
    }
    if (rank == 2)
        for (sg = 1; sg >= -1; sg -= 2)
        {
            for (r = 0, ok = 1; r < nmot && ok; r++)
            {
                if (s->rel[3 + r] == WC_REL_EQ)
                    continue;
                _fmpq_vec_dot(q, s->A->rows[3 + r], W.t, 3);
                ok = fmpq_sgn(q) * sg >= 0;
            }
            for (i = 0; i < 3 && ok; i++)
                fmpq_mul_si(G + 3 * kk + i, W.t + i, sg);
            kk += ok;
        }
    else if (rank == 1)
    {
        _wc_qvec_set(W.e, e1, 3);
        W.state = W_FULL;
        for (r = 0; r < nmot && W.state != W_ZERO; r++)
            if (s->rel[3 + r] != WC_REL_EQ)
                wedge_cut(&W, s->A->rows[3 + r]);
        kk = wedge_gens(G, &W);
    }
    for (j = 0; j < kk; j++)
        for (i = 0; i < 3; i++)
            fmpq_mul(G + 3 * j + i, G + 3 * j + i, m->M + i);
    for (j = 0; j < s->e; j++, kk++)
        for (i = 0; i < 3; i++)
            fmpq_set(G + 3 * kk + i, fmpq_mat_entry(s->A, i, 3 + j));
    *k = kk;
    fmpq_clear(q);
    fmpq_clear(&W.d);
    for (i = 0; i < 3; i++)
    {
        fmpq_clear(W.r1 + i);
        fmpq_clear(W.r2 + i);
        fmpq_clear(W.e + i);
        fmpq_clear(W.t + i);
    }
    return rank > 0;
}

/* 1 when the multipliers of facet_mult, from the plane separating g
   from cl W, prove that the face (one wrench g, s's last column) has no
   motion; 0 when this cannot tell; -1 on failure (err set).  */
static int
face_separate(const facesys * s, const _wc_stab_model * m, const fmpq * g,
              wc_error_t err)
{
    slong k = 0, i, cap = 4 + s->e;
    fmpq * G = _fmpq_vec_init(3 * cap), * lam = _fmpq_vec_init(cap);
    fmpq * y = _fmpq_vec_init(s->rows);
    fmpq sep[3];
    int r = 0;

    for (i = 0; i < 3; i++)
        fmpq_init(sep + i);
    if (closure_gens(G, &k, s, m))
    {
        r = _wc_lp_cone3(lam, sep, G, k, g, err);
        if (r == 0)
            r = facet_mult(y, s, m, sep, 1, err);
        else if (r == 1)
            r = 0;
    }
    for (i = 0; i < 3; i++)
        fmpq_clear(sep + i);
    _fmpq_vec_clear(G, 3 * cap);
    _fmpq_vec_clear(lam, cap);
    _fmpq_vec_clear(y, s->rows);
    return r;
}

int
_wc_face_separate(const _wc_stab_model * m, const char * y, const char * x,
                  int rot, const fmpq * g, wc_error_t err)
{
    facesys s;
    int r;

    facesys_init(&s, m, y, x, rot, g, 1, 0);
    r = face_separate(&s, m, g, err);
    facesys_clear(&s);
    return r;
}
