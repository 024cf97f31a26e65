/* ref-faces.c -- the independent reference for the moving faces of
   lib/check/faces.c (_wc_check_moving_faces).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Independent of lib/: written from checker.h and SPEC.md section 2.5
   without reading lib/check/faces.c, it uses nothing of the library but
   the wc_check_problem it reads.  J_in = (n, r x n) and J_it = (t, r x t),
   t = (-n_y, n_x), r = p - com, are computed here (GMP rationals, then
   cleared to integers by a positive factor, which keeps every sign); the
   faces of the arrangement of the planes J_in . x = 0, J_it . x = 0 of
   the touching fixels come from ref-cells.c (symbolic perturbation from
   the lines of pairs of planes, no walk of the cone of moving directions
   and no walk around any line), and each face with a_in >= 0 on every
   touching fixel is read as its string.  Near fixels carry no force and
   take no part: their letter is u.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>

#include "ref-cells.h"
#include "ref-faces.h"

void
ref_faces_free(char ** s, size_t count)
{
    size_t i;

    if (s == NULL)
        return;
    for (i = 0; i < count; i++)
        free(s[i]);
    free(s);
}

/* row := a positive multiple of (d, r x d), an integer vector.  */
static void
jrow(fmpz * row, const mpq_t rx, const mpq_t ry, const mpq_t dx,
     const mpq_t dy)
{
    mpq_t v[3], t;
    mpz_t l, z;
    int j;

    mpq_init(t);
    mpz_init(l);
    mpz_init(z);
    for (j = 0; j < 3; j++)
        mpq_init(v[j]);
    mpq_set(v[0], dx);
    mpq_set(v[1], dy);
    mpq_mul(v[2], rx, dy);
    mpq_mul(t, ry, dx);
    mpq_sub(v[2], v[2], t);
    mpz_set_ui(l, 1);
    for (j = 0; j < 3; j++)
        mpz_lcm(l, l, mpq_denref(v[j]));
    for (j = 0; j < 3; j++)
    {
        mpz_divexact(z, l, mpq_denref(v[j]));
        mpz_mul(z, z, mpq_numref(v[j]));
        fmpz_set_mpz(row + j, z);
    }
    for (j = 0; j < 3; j++)
        mpq_clear(v[j]);
    mpz_clear(z);
    mpz_clear(l);
    mpq_clear(t);
}

static int
cmp_str(const void * a, const void * b)
{
    return strcmp(*(char * const *) a, *(char * const *) b);
}

int
ref_faces_moving(char *** out, size_t * count, const wc_check_problem * P)
{
    size_t n = P->n, i, t = 0, k, found = 0;
    size_t * touch = NULL;
    fmpz_mat_t H;
    ref_cells_t C;
    mpq_t rx, ry, tx, ty;
    char ** list = NULL;
    char * s = NULL;
    slong f;
    int status = -1;

    *out = NULL;
    *count = 0;
    mpq_init(rx);
    mpq_init(ry);
    mpq_init(tx);
    mpq_init(ty);
    ref_cells_init(C);
    fmpz_mat_init(H, 0, 3);
    touch = malloc(sizeof(size_t) * (n + 1));
    s = malloc(n + 1);
    if (touch == NULL || s == NULL)
        goto cleanup;
    for (i = 0; i < n; i++)
        if (!P->near[i])
            touch[t++] = i;
    fmpz_mat_clear(H);
    fmpz_mat_init(H, (slong) (2 * t), 3);
    for (k = 0; k < t; k++)
    {
        mpq_t * x = P->fixel + 6 * touch[k];

        mpq_sub(rx, x[0], P->body[2]);
        mpq_sub(ry, x[1], P->body[3]);
        mpq_neg(tx, x[3]);
        mpq_set(ty, x[2]);
        jrow(H->rows[2 * k], rx, ry, x[2], x[3]);
        jrow(H->rows[2 * k + 1], rx, ry, tx, ty);
    }
    if (ref_cells_faces(C, H) != 0)
        goto cleanup;
    list = malloc(sizeof(char *) * (size_t) (C->count > 0 ? C->count : 1));
    if (list == NULL)
        goto cleanup;
    for (f = 0; f < C->count; f++)
    {
        const signed char * sg = C->sign + f * C->m;
        int moving = 0, ok = 1;

        for (i = 0; i < n; i++)
            s[i] = 'u';
        s[n] = '\0';
        for (k = 0; k < t && ok; k++)
        {
            int an = sg[2 * k], at = sg[2 * k + 1];

            if (an < 0)
                ok = 0;
            s[touch[k]] = an > 0 ? 's' : at > 0 ? 'l' : at < 0 ? 'r' : 'n';
            moving |= s[touch[k]] != 'n';
        }
        if (!ok || !moving)
            continue;
        list[found] = malloc(n + 1);
        if (list[found] == NULL)
            goto cleanup;
        memcpy(list[found++], s, n + 1);
    }
    qsort(list, found, sizeof(char *), cmp_str);
    /* s with either sign of a_it is one string: keep each once */
    for (i = 0, k = 0; i < found; i++)
    {
        if (k > 0 && strcmp(list[k - 1], list[i]) == 0)
            free(list[i]);
        else
            list[k++] = list[i];
    }
    found = k;
    status = 0;

cleanup:
    fmpz_mat_clear(H);
    if (status == 0)
    {
        *out = list;
        *count = found;
    }
    else
        ref_faces_free(list, found);
    ref_cells_clear(C);
    free(touch);
    free(s);
    mpq_clear(rx);
    mpq_clear(ry);
    mpq_clear(tx);
    mpq_clear(ty);
    return status;
}
