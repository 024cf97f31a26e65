/* stabmodel.c -- the problem as the stability analysis reads it: J's
   columns, M, the touching fixels, the shared contact point.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpq_vec.h>

#include "core/tick.h"
#include "model/model.h"
#include "exact/lp.h"
#include "exact/vec3.h"
#include "analysis/stabmodel.h"

void
_wc_stab_model_init(_wc_stab_model * m, const wc_problem_t P)
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
        _wc_qvec3_cross(m->v, m->Jn + 3 * m->tidx[0], m->Jt + 3 * m->tidx[0]);
}

void
_wc_stab_model_clear(_wc_stab_model * m)
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

void
_wc_stab_edge_wrench(fmpq * w, const _wc_stab_model * m, slong i,
                     const fmpq * e)
{
    slong k;

    for (k = 0; k < 3; k++)
    {
        fmpq_mul(w + k, e + 0, m->Jn + 3 * i + k);
        fmpq_addmul(w + k, e + 1, m->Jt + 3 * i + k);
    }
}

void
_wc_stab_edge_rows(fmpq_mat_t Q, const _wc_stab_model * m, const char * x,
                   slong skip)
{
    const wc_problem_struct * P = m->P;
    slong i, j, k, c, e = 0;
    fmpq ed[4];

    for (j = 0; j < 4; j++)
        fmpq_init(ed + j);
    fmpq_mat_clear(Q);
    fmpq_mat_init(Q, 2 * m->n, 3);
    for (i = 0; i < m->n; i++)
    {
        if (P->fixels[i].state != WC_TOUCHING || i == skip)
            continue;
        c = wc_friction_edges(ed, P->fixels + i, x[i]);
        for (j = 0; j < c; j++, e++)
        {
            _wc_stab_edge_wrench(WC_ROW(Q, e), m, i, ed + 2 * j);
            for (k = 0; k < 3; k++)
                fmpq_neg(fmpq_mat_entry(Q, e, k), fmpq_mat_entry(Q, e, k));
        }
    }
    _wc_fmpq_mat_keep_rows(Q, e);
    for (j = 0; j < 4; j++)
        fmpq_clear(ed + j);
}

char *
_wc_stab_expand(const _wc_stab_model * m, const char * s)
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

int
_wc_stab_all_n(const _wc_stab_model * m, const char * y)
{
    slong i;

    for (i = 0; i < m->t; i++)
        if (y[m->tidx[i]] != 'n')
            return 0;
    return 1;
}

/* T := the modes of the touching-only problem.  */
static int
touching_modes(wc_modes_t T, const _wc_stab_model * m, wc_error_t err)
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

        if (h == NULL)
        {
            wc_problem_clear(Q);
            return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                "out of memory");
        }
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

int
_wc_stab_moving_faces_of(const _wc_stab_model * m, const wc_modes_t T,
                         int (* visit)(void * ctx, const char * y, int rot),
                         void * ctx, wc_error_t err)
{
    slong i;
    int status = WC_OK, rot;
    char * y;

    (void) err;
    for (i = 0; i < T->count && status == WC_OK; i++)
    {
        _wc_tick("moving faces", i, T->count);
        y = _wc_stab_expand(m, T->modes[i]);
        if (!_wc_stab_all_n(m, y))
            status = visit(ctx, y, 0);
        free(y);
    }
    _wc_tick("moving faces", T->count, T->count);
    if (status == WC_OK && m->shared)
    {
        y = _wc_stab_expand(m, T->modes[0]);
        for (i = 0; i < m->t; i++)
            y[m->tidx[i]] = 'n';
        for (rot = 1; rot >= -1 && status == WC_OK; rot -= 2)
            status = visit(ctx, y, rot);
        free(y);
    }
    return status;
}

int
_wc_stab_moving_faces(const _wc_stab_model * m,
                      int (* visit)(void * ctx, const char * y, int rot),
                      void * ctx, wc_error_t err)
{
    wc_modes_t T;
    int status;

    wc_modes_init(T);
    status = touching_modes(T, m, err);
    if (status == WC_OK)
        status = _wc_stab_moving_faces_of(m, T, visit, ctx, err);
    wc_modes_clear(T);
    return status;
}

/* ---------------------------------------------------------------------
   Weak stability: a static solution or a separator.  */

/* c (2n) := the forces of lambda over the mu_s edges of the touching
   fixels, two per fixel.  */
static void
static_forces(fmpq * c, const _wc_stab_model * m, const fmpq * lambda)
{
    slong n = m->n, j;
    fmpq ed[4];

    for (j = 0; j < 4; j++)
        fmpq_init(ed + j);
    _wc_qvec_zero(c, 2 * n);
    for (j = 0; j < 2 * m->t; j++)
    {
        slong f = m->tidx[j / 2];

        wc_friction_edges(ed, m->P->fixels + f, 'n');
        fmpq_addmul(c + f, lambda + j, ed + 2 * (j % 2));
        fmpq_addmul(c + n + f, lambda + j, ed + 2 * (j % 2) + 1);
    }
    for (j = 0; j < 4; j++)
        fmpq_clear(ed + j);
}

int
_wc_stab_weak(fmpq * c, fmpq * sep, const _wc_stab_model * m,
              const fmpq * g, wc_error_t err)
{
    const wc_problem_struct * P = m->P;
    slong t = m->t, i, j, ne = 2 * t;
    fmpq * z, * w, ed[4];
    int r;

    if (t == 0)
    {
        _wc_qvec_zero(c, 2 * m->n);
        _wc_qvec_set(sep, g, 3);
        return _wc_qvec_is_zero(g, 3);
    }
    for (j = 0; j < 4; j++)
        fmpq_init(ed + j);
    w = _fmpq_vec_init(3 * ne);
    for (i = 0; i < t; i++)
    {
        wc_friction_edges(ed, P->fixels + m->tidx[i], 'n');
        _wc_stab_edge_wrench(w + 3 * (2 * i), m, m->tidx[i], ed);
        _wc_stab_edge_wrench(w + 3 * (2 * i + 1), m, m->tidx[i], ed + 2);
    }

    /* g = sum lambda_j (-w_j), or a separator.  */
    for (j = 0; j < 3 * ne; j++)
        fmpq_neg(w + j, w + j);
    z = _fmpq_vec_init(ne + 1);
    r = _wc_lp_cone3(z, sep, w, ne, g, err);
    if (r < 0)
        wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "internal error: "
                     "the static solution fails its check");
    else if (r == 1)
        static_forces(c, m, z);
    _fmpq_vec_clear(z, ne + 1);
    _fmpq_vec_clear(w, 3 * ne);
    for (j = 0; j < 4; j++)
        fmpq_clear(ed + j);
    return r;
}

void
_wc_motion_init(wc_motion_struct * a, slong n)
{
    slong k;

    a->sign = NULL;
    for (k = 0; k < 3; k++)
        fmpq_init(a->nudot + k);
    a->c = _fmpq_vec_init(2 * n + 1);
}

void
_wc_motion_clear(wc_motion_struct * a, slong n)
{
    slong k;

    free(a->sign);
    for (k = 0; k < 3; k++)
        fmpq_clear(a->nudot + k);
    _fmpq_vec_clear(a->c, 2 * n + 1);
}
