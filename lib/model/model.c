/* model.c -- J, M, A, B, C of the paper's eq. (3)-(9), exactly.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "model/model.h"

void
wc_fixel_tangent(fmpq * t, const wc_fixel_struct * f)
{
    fmpq_neg(t + 0, f->normal + 1);
    fmpq_set(t + 1, f->normal + 0);
}

/* Column (d_x, d_y, r x d) of J for direction d at point p.  */
static void
set_column(fmpq_mat_t J, slong col, const fmpq * d, const fmpq * p,
           const fmpq * o)
{
    fmpq_t rx, ry, s;

    fmpq_init(rx);
    fmpq_init(ry);
    fmpq_init(s);
    fmpq_sub(rx, p + 0, o + 0);
    fmpq_sub(ry, p + 1, o + 1);
    fmpq_set(fmpq_mat_entry(J, 0, col), d + 0);
    fmpq_set(fmpq_mat_entry(J, 1, col), d + 1);
    fmpq_mul(s, rx, d + 1);
    fmpq_submul(s, ry, d + 0);
    fmpq_set(fmpq_mat_entry(J, 2, col), s);
    fmpq_clear(rx);
    fmpq_clear(ry);
    fmpq_clear(s);
}

void
wc_model_J(fmpq_mat_t J, const wc_problem_t P)
{
    slong i, n = P->n;
    fmpq t[2];

    fmpq_init(t + 0);
    fmpq_init(t + 1);
    for (i = 0; i < n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        set_column(J, i, f->normal, f->point, P->com);
        wc_fixel_tangent(t, f);
        set_column(J, n + i, t, f->point, P->com);
    }
    fmpq_clear(t + 0);
    fmpq_clear(t + 1);
}

void
wc_model_M(fmpq_mat_t M, const wc_problem_t P)
{
    fmpq_mat_zero(M);
    fmpq_set(fmpq_mat_entry(M, 0, 0), P->mass);
    fmpq_set(fmpq_mat_entry(M, 1, 1), P->mass);
    fmpq_set(fmpq_mat_entry(M, 2, 2), P->inertia);
}

void
wc_model_Minv(fmpq_mat_t Minv, const wc_problem_t P)
{
    fmpq_mat_zero(Minv);
    fmpq_inv(fmpq_mat_entry(Minv, 0, 0), P->mass);
    fmpq_inv(fmpq_mat_entry(Minv, 1, 1), P->mass);
    fmpq_inv(fmpq_mat_entry(Minv, 2, 2), P->inertia);
}

void
wc_model_B(fmpq_mat_t B, const wc_problem_t P)
{
    fmpq_mat_t J, Jt, Mi;

    fmpq_mat_init(J, 3, 2 * P->n);
    fmpq_mat_init(Jt, 2 * P->n, 3);
    fmpq_mat_init(Mi, 3, 3);
    wc_model_J(J, P);
    fmpq_mat_transpose(Jt, J);
    wc_model_Minv(Mi, P);
    fmpq_mat_mul(B, Jt, Mi);
    fmpq_mat_clear(J);
    fmpq_mat_clear(Jt);
    fmpq_mat_clear(Mi);
}

void
wc_model_A(fmpq_mat_t A, const wc_problem_t P)
{
    fmpq_mat_t J, B;

    fmpq_mat_init(J, 3, 2 * P->n);
    fmpq_mat_init(B, 2 * P->n, 3);
    wc_model_J(J, P);
    wc_model_B(B, P);
    fmpq_mat_mul(A, B, J);
    fmpq_mat_clear(J);
    fmpq_mat_clear(B);
}

void
wc_model_C(fmpq_mat_t C, const wc_problem_t P)
{
    slong m = 2 * P->n, i, j;
    fmpq_mat_t A;

    fmpq_mat_init(A, m, m);
    wc_model_A(A, P);
    fmpq_mat_zero(C);
    for (i = 0; i < m; i++)
    {
        fmpq_one(fmpq_mat_entry(C, i, i));
        for (j = 0; j < m; j++)
            fmpq_neg(fmpq_mat_entry(C, i, m + j), fmpq_mat_entry(A, i, j));
    }
    fmpq_mat_clear(A);
}

int
wc_friction_edges(fmpq * e, const wc_fixel_struct * f, char x)
{
    switch (x)
    {
    case 'n':
    case 'm':
        fmpq_one(e + 0);
        fmpq_neg(e + 1, f->mu_s);
        fmpq_one(e + 2);
        fmpq_set(e + 3, f->mu_s);
        return 2;
    case 'l':
        fmpq_one(e + 0);
        fmpq_neg(e + 1, f->mu_k);
        return 1;
    case 'r':
        fmpq_one(e + 0);
        fmpq_set(e + 1, f->mu_k);
        return 1;
    default:
        return 0;
    }
}
