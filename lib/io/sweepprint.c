/* sweepprint.c -- a sweep over friction as text or JSON (print.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "io/print.h"
#include "core/version.h"

static void
critical_json(FILE * out, const wc_sweep_t A)
{
    const wc_critical_struct * C = A->C;
    const wc_plan_struct * H = A->H;
    slong k, m;

    fprintf(out, "\"critical\": {\"found\": %s, \"lo\": \"",
            C->found ? "true" : "false");
    wc_fprint_fmpq(out, C->lo);
    fputs("\", \"hi\": ", out);
    if (C->found)
    {
        putc('"', out);
        wc_fprint_fmpq(out, C->hi);
        putc('"', out);
    }
    else
        fputs("null", out);
    fputs(", \"width\": \"", out);
    wc_fprint_fmpq(out, A->width);
    fprintf(out, "\", \"plans\": %ld, \"lo_witness\": ", (long) C->evals);
    if (C->empty_at_zero)
        fputs("null", out);
    else
        wc_fprint_qvec(out, C->lo_witness, 3, 1);
    fputs(", \"hi_cover\": [", out);
    for (k = 0, m = 0; C->found && k < H->T->nneeded; k++)
        if (H->exact_needed[k])
            fprintf(out, "%s\"%s\"", m++ ? ", " : "",
                    H->T->strings[H->T->needed[k]]);
    fputs("]}", out);
}

static void
critical_text(FILE * out, const wc_sweep_t A)
{
    const wc_critical_struct * C = A->C;
    const wc_plan_struct * H = A->H;
    slong k;

    fputs("critical friction (mu_s = mu_k = mu at every fixel; G_goal "
          "shrinks as mu grows):\n", out);
    if (C->empty_at_zero)
        fputs("  G_goal is empty already at mu = 0\n", out);
    else
    {
        fputs("  lo = ", out);
        wc_fprint_fmpq_text(out, C->lo);
        fputs(": G_goal is not empty; g = ", out);
        wc_fprint_qvec(out, C->lo_witness, 3, 0);
        fputs(" is in the cone of no needed string\n", out);
    }
    if (!C->found)
    {
        fputs("  G_goal is not empty at any mu <= ", out);
        wc_fprint_fmpq_text(out, A->max);
        fprintf(out, " (%ld plans)\n", (long) C->evals);
        return;
    }
    fputs("  hi = ", out);
    wc_fprint_fmpq_text(out, C->hi);
    fputs(": G_goal is empty; the cones of", out);
    for (k = 0; k < H->T->nneeded; k++)
        if (H->exact_needed[k])
            fprintf(out, " %s", H->T->strings[H->T->needed[k]]);
    fputs(" cover R^3\n", out);
    if (!C->empty_at_zero)
    {
        fmpq_t w;

        fmpq_init(w);
        fmpq_sub(w, C->hi, C->lo);
        fputs("  hi - lo = ", out);
        wc_fprint_fmpq_text(out, w);
        fputs(" <= ", out);
        wc_fprint_fmpq_text(out, A->width);
        fprintf(out, " (%ld plans)\n", (long) C->evals);
        fmpq_clear(w);
    }
}

int
wc_sweep_fprint_json(FILE * out, const wc_sweep_t A, const wc_problem_t P)
{
    slong i;

    fputs(WC_JSON_OPEN "\"sweep\": [", out);
    for (i = 0; i < A->n; i++)
    {
        if (i)
            fputs(", ", out);
        wc_plan_sweep_fprint(out, A->plans + i, P, A->mu + i, 1);
    }
    fputs(A->critical ? "], " : "]", out);
    if (A->critical)
        critical_json(out, A);
    fputs("}\n", out);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

int
wc_sweep_fprint_text(FILE * out, const wc_sweep_t A, const wc_problem_t P)
{
    slong i;

    for (i = 0; i < A->n; i++)
        wc_plan_sweep_fprint(out, A->plans + i, P, A->mu + i, 0);
    if (A->critical)
    {
        if (A->n > 0)
            putc('\n', out);
        critical_text(out, A);
    }
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}
