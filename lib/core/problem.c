/* problem.c -- the problem: its life cycle, its check, and its writer.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The reader is parse.c; exact numbers are number.c.  */

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/problem.h"
#include "core/text.h"

void
wc_problem_init(wc_problem_t P)
{
    P->file = NULL;
    P->name = NULL;
    fmpq_init(P->mass);
    fmpq_one(P->mass);
    fmpq_init(P->inertia);
    fmpq_one(P->inertia);
    fmpq_init(P->com + 0);
    fmpq_init(P->com + 1);
    fmpq_init(P->mu_s);
    fmpq_init(P->mu_k);
    P->shape = WC_SHAPE_NONE;
    P->shape_len = 0;
    P->shape_data = NULL;
    P->shape_line = 0;
    P->n = 0;
    P->fixels = NULL;
}

static void
fixel_clear(wc_fixel_struct * f)
{
    fmpq_clear(f->point + 0);
    fmpq_clear(f->point + 1);
    fmpq_clear(f->normal + 0);
    fmpq_clear(f->normal + 1);
    fmpq_clear(f->mu_s);
    fmpq_clear(f->mu_k);
}

void
wc_problem_clear(wc_problem_t P)
{
    slong i;

    free(P->file);
    free(P->name);
    fmpq_clear(P->mass);
    fmpq_clear(P->inertia);
    fmpq_clear(P->com + 0);
    fmpq_clear(P->com + 1);
    fmpq_clear(P->mu_s);
    fmpq_clear(P->mu_k);
    for (i = 0; i < P->shape_len; i++)
        fmpq_clear(P->shape_data + i);
    free(P->shape_data);
    for (i = 0; i < P->n; i++)
        fixel_clear(P->fixels + i);
    free(P->fixels);
    P->file = NULL;
    P->name = NULL;
    P->shape_data = NULL;
    P->shape_len = 0;
    P->fixels = NULL;
    P->n = 0;
}

/* The fixels array has no capacity field: its capacity is implied by n
   (0, then powers of two from 4), so appending costs amortised O(1).  */
static slong
fixel_capacity(slong n)
{
    slong c = 4;

    if (n == 0)
        return 0;
    while (c < n)
        c *= 2;
    return c;
}

wc_fixel_struct *
wc_problem_add_fixel(wc_problem_t P)
{
    wc_fixel_struct * f;
    slong cap = fixel_capacity(P->n);

    if (P->n == cap)
    {
        slong ncap = cap == 0 ? 4 : 2 * cap;
        wc_fixel_struct * a;

        if ((size_t) ncap > SIZE_MAX / sizeof(wc_fixel_struct))
            return NULL;
        a = realloc(P->fixels, (size_t) ncap * sizeof(wc_fixel_struct));
        if (a == NULL)
            return NULL;
        P->fixels = a;
    }
    f = P->fixels + P->n;
    fmpq_init(f->point + 0);
    fmpq_init(f->point + 1);
    fmpq_init(f->normal + 0);
    fmpq_init(f->normal + 1);
    fmpq_init(f->mu_s);
    fmpq_init(f->mu_k);
    fmpq_set(f->mu_s, P->mu_s);
    fmpq_set(f->mu_k, P->mu_k);
    f->state = WC_TOUCHING;
    f->line = 0;
    f->col = 0;
    P->n++;
    return f;
}

int
wc_problem_set(wc_problem_t Q, const wc_problem_t P)
{
    slong i;

    if (Q == P)
        return WC_OK;
    wc_problem_clear(Q);
    wc_problem_init(Q);
    if ((P->file != NULL && (Q->file = _wc_strdup(P->file)) == NULL)
        || (P->name != NULL && (Q->name = _wc_strdup(P->name)) == NULL))
        goto oom;
    fmpq_set(Q->mass, P->mass);
    fmpq_set(Q->inertia, P->inertia);
    fmpq_set(Q->com + 0, P->com + 0);
    fmpq_set(Q->com + 1, P->com + 1);
    fmpq_set(Q->mu_s, P->mu_s);
    fmpq_set(Q->mu_k, P->mu_k);
    Q->shape = P->shape;
    Q->shape_line = P->shape_line;
    Q->mass_line = P->mass_line;
    Q->inertia_line = P->inertia_line;
    Q->com_line = P->com_line;
    if (P->shape_len > 0)
    {
        if ((Q->shape_data = malloc(sizeof(fmpq) * P->shape_len)) == NULL)
            goto oom;
        for (i = 0; i < P->shape_len; i++)
        {
            fmpq_init(Q->shape_data + i);
            fmpq_set(Q->shape_data + i, P->shape_data + i);
        }
        Q->shape_len = P->shape_len;
    }
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;
        wc_fixel_struct * g = wc_problem_add_fixel(Q);

        if (g == NULL)
            goto oom;
        fmpq_set(g->point + 0, f->point + 0);
        fmpq_set(g->point + 1, f->point + 1);
        fmpq_set(g->normal + 0, f->normal + 0);
        fmpq_set(g->normal + 1, f->normal + 1);
        fmpq_set(g->mu_s, f->mu_s);
        fmpq_set(g->mu_k, f->mu_k);
        g->state = f->state;
        g->line = f->line;
        g->col = f->col;
    }
    return WC_OK;

oom:
    wc_problem_clear(Q);
    wc_problem_init(Q);
    return WC_EINTERNAL;
}


int
wc_problem_check(const wc_problem_t P, wc_error_t err)
{
    slong i;

    if (P->n < 1 || P->fixels == NULL)
        return wc_error_set(err, WC_EINPUT, P->file, 0, 0,
                            "no fixel in the problem");
    if (fmpq_sgn(P->mass) <= 0)
        return wc_error_set(err, WC_EINPUT, P->file, 0, 0,
                            "mass must be positive");
    if (fmpq_sgn(P->inertia) <= 0)
        return wc_error_set(err, WC_EINPUT, P->file, 0, 0,
                            "inertia must be positive");
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        if (fmpq_is_zero(f->normal + 0) && fmpq_is_zero(f->normal + 1))
            return wc_error_set(err, WC_EINPUT, P->file, f->line, f->col,
                                "fixel %ld has a zero normal", (long) i + 1);
        if (fmpq_sgn(f->mu_s) < 0 || fmpq_sgn(f->mu_k) < 0)
            return wc_error_set(err, WC_EINPUT, P->file, f->line, f->col,
                                "fixel %ld has negative friction", (long) i + 1);
        if (f->state != WC_TOUCHING && f->state != WC_NEAR)
            return wc_error_set(err, WC_EINPUT, P->file, f->line, f->col,
                                "fixel %ld has an unknown state", (long) i + 1);
    }
    return WC_OK;
}

int
wc_problem_check_fixels(const wc_problem_t P, slong max, int touching,
                        const char * what, wc_error_t err)
{
    slong i, count = 0;

    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        if (touching && f->state != WC_TOUCHING)
            continue;
        if (++count > max)
            return wc_error_set(err, WC_EINPUT, P->file, f->line, f->col,
                                "%s handles at most %ld %sfixels (this is "
                                "%sfixel %ld)", what, (long) max,
                                touching ? "touching " : "",
                                touching ? "touching " : "", (long) count);
    }
    return WC_OK;
}

/* Printing.                                                           */

static int
put_q(FILE * out, const char * before, const fmpq_t x)
{
    char * s = fmpq_get_str(NULL, 10, x);
    int r = fputs(before, out) != EOF && fputs(s, out) != EOF;

    flint_free(s);
    return r ? 0 : -1;
}

int
wc_problem_fprint(FILE * out, const wc_problem_t P)
{
    slong i;
    int bad = 0;

    if (P->name != NULL)
    {
        const char * c;

        bad |= fputs("name \"", out) == EOF;
        for (c = P->name; *c != '\0'; c++)
        {
            if (*c == '"' || *c == '\\')
                bad |= putc('\\', out) == EOF;
            bad |= putc(*c, out) == EOF;
        }
        bad |= fputs("\"\n", out) == EOF;
    }
    bad |= put_q(out, "mass ", P->mass) != 0;
    bad |= put_q(out, "\ninertia ", P->inertia) != 0;
    bad |= put_q(out, "\ncom ", P->com + 0) != 0;
    bad |= put_q(out, " ", P->com + 1) != 0;
    bad |= put_q(out, "\nfriction ", P->mu_s) != 0;
    bad |= put_q(out, " ", P->mu_k) != 0;
    bad |= fputs("\n", out) == EOF;
    if (P->shape != WC_SHAPE_NONE)
    {
        bad |= fputs(P->shape == WC_SHAPE_DISK ? "shape disk" : "shape polygon",
                     out) == EOF;
        for (i = 0; i < P->shape_len; i++)
            bad |= put_q(out, " ", P->shape_data + i) != 0;
        bad |= fputs("\n", out) == EOF;
    }
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        bad |= put_q(out, "fixel ", f->point + 0) != 0;
        bad |= put_q(out, " ", f->point + 1) != 0;
        bad |= put_q(out, " normal ", f->normal + 0) != 0;
        bad |= put_q(out, " ", f->normal + 1) != 0;
        bad |= fputs(f->state == WC_NEAR ? " near" : " touching", out) == EOF;
        bad |= put_q(out, " friction ", f->mu_s) != 0;
        bad |= put_q(out, " ", f->mu_k) != 0;
        bad |= fputs("\n", out) == EOF;
    }
    if (bad || ferror(out))
        return WC_EINTERNAL;
    return WC_OK;
}
