/* sweepprint.c -- a sweep over friction as text or JSON (print.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "io/print.h"
#include "io/printutil.h"
#include "core/version.h"

static void
critical_json(FILE * out, const wc_sweep_t A, const wc_print_opts * o)
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
        wc_fprint_qvec(out, C->lo_witness, 3, o);
    fputs(", \"hi_cover\": [", out);
    for (k = 0, m = 0; C->found && k < H->T->nneeded; k++)
        if (H->exact_needed[k])
            fprintf(out, "%s\"%s\"", m++ ? ", " : "",
                    H->T->strings[H->T->needed[k]]);
    fputs("]}", out);
}

static void
critical_text(FILE * out, const wc_sweep_t A, const wc_print_opts * o)
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
        wc_fprint_fmpq_text(out, C->lo, o);
        fputs(": G_goal is not empty; g = ", out);
        wc_fprint_qvec(out, C->lo_witness, 3, o);
        fputs(" is in the cone of no needed string\n", out);
    }
    if (!C->found)
    {
        fputs("  G_goal is not empty at any mu <= ", out);
        wc_fprint_fmpq_text(out, A->max, o);
        fprintf(out, " (%ld plans)\n", (long) C->evals);
        return;
    }
    fputs("  hi = ", out);
    wc_fprint_fmpq_text(out, C->hi, o);
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
        wc_fprint_fmpq_text(out, w, o);
        fputs(" <= ", out);
        wc_fprint_fmpq_text(out, A->width, o);
        fprintf(out, " (%ld plans)\n", (long) C->evals);
        fmpq_clear(w);
    }
}

static int
sweep_json(FILE * out, const wc_sweep_t A, const wc_problem_t P,
           const wc_print_opts * o)
{
    slong i;

    fputs(WC_JSON_OPEN "\"sweep\": [", out);
    for (i = 0; i < A->n; i++)
    {
        if (i)
            fputs(", ", out);
        wc_plan_sweep_fprint(out, A->plans + i, P, A->mu + i, o);
    }
    fputs(A->critical ? "], " : "]", out);
    if (A->critical)
        critical_json(out, A, o);
    fputs("}\n", out);
    return _wc_fprint_done(out);
}

static int
sweep_text(FILE * out, const wc_sweep_t A, const wc_problem_t P,
           const wc_print_opts * o)
{
    slong i;

    for (i = 0; i < A->n; i++)
        wc_plan_sweep_fprint(out, A->plans + i, P, A->mu + i, o);
    if (A->critical)
    {
        if (A->n > 0)
            putc('\n', out);
        critical_text(out, A, o);
    }
    return _wc_fprint_done(out);
}

int
wc_sweep_fprint(FILE * out, const wc_sweep_t A, const wc_problem_t P,
                const wc_print_opts * o)
{
    return _wc_print_json(o) ? sweep_json(out, A, P, o)
        : sweep_text(out, A, P, o);
}
