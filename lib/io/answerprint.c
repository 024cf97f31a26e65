/* answerprint.c -- a mode's cone, and stability with a bias's
   robustness, written (answerprint.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include "io/answerprint.h"
#include "io/fconeprint.h"
#include "io/printutil.h"
#include "core/version.h"


int
_wc_mode_cone_fprint(FILE * out, const char * mode, const wc_cone_t W,
                     const wc_trace_t T, int paper, const wc_print_opts * o)
{
    wc_format f = o != NULL ? o->format : WC_FORMAT_TEXT;
    wc_print_opts in2 = _wc_print_indented(o, "  ");
    wc_print_opts star = _wc_print_indented(o, "* ");

    switch (f)
    {
    case WC_FORMAT_JSON:
        fputs(WC_JSON_OPEN "\"mode\": ", out);
        wc_fprint_json_string(out, mode);
        fputs(", \"cone\": ", out);
        wc_cone_fprint(out, W, o);
        if (T != NULL)
        {
            fprintf(out, ", \"method\": \"%s\", \"trace\": ",
                    paper ? "paper" : "direct");
            wc_trace_fprint(out, T, o);
        }
        fputs("}\n", out);
        break;
    case WC_FORMAT_CDD:
    case WC_FORMAT_INE:
    case WC_FORMAT_EXT:
        if (T != NULL)
            wc_trace_fprint(out, T, &star);
        fprintf(out, "* wrenchcone: W(%s), the wrench cone of mode %s\n",
                mode, mode);
        wc_cone_fprint(out, W, o);
        break;
    default:
        if (T != NULL)
        {
            fprintf(out, "trace (%s route):\n", paper ? "paper, Section 5"
                    : "direct, M V_x + (-J) D_x");
            wc_trace_fprint(out, T, &in2);
            putc('\n', out);
        }
        fprintf(out, "W(%s): wrench cone of mode %s\n", mode, mode);
        wc_cone_fprint(out, W, &in2);
        break;
    }
    return _wc_fprint_done(out);
}

int
_wc_mode_fcone_fprint(FILE * out, const char * mode, const wc_fcone_t F,
                      const wc_print_opts * o)
{
    wc_format f = o != NULL ? o->format : WC_FORMAT_TEXT;

    if (f == WC_FORMAT_JSON)
    {
        fputs(WC_JSON_OPEN "\"mode\": ", out);
        wc_fprint_json_string(out, mode);
        fputs(", \"cone\": ", out);
        wc_fcone_fprint(out, F, o);
        fputs("}\n", out);
    }
    else if (f == WC_FORMAT_CDD || f == WC_FORMAT_INE || f == WC_FORMAT_EXT)
    {
        fprintf(out, "* wrenchcone: W(%s), the wrench cone of mode %s\n",
                mode, mode);
        wc_fcone_fprint(out, F, o);
    }
    else
    {
        fprintf(out, "W(%s): wrench cone of mode %s\n", mode, mode);
        wc_fcone_fprint(out, F, o);
    }
    return _wc_fprint_done(out);
}

void
_wc_bias_init(_wc_bias * B)
{
    int i;

    for (i = 0; i < 3; i++)
        fmpq_init(B->b + i);
    fmpq_init(B->L);
    fmpq_one(B->L);
    for (i = 0; i < 2; i++)
    {
        fmpq_init(B->rho[i]);
        B->closed[i] = B->infinite[i] = B->in_set[i] = 0;
    }
}

void
_wc_bias_clear(_wc_bias * B)
{
    int i;

    for (i = 0; i < 3; i++)
        fmpq_clear(B->b + i);
    fmpq_clear(B->L);
    for (i = 0; i < 2; i++)
        fmpq_clear(B->rho[i]);
}

/* The robustness of the bias as text: lines.  */
static void
bias_text(FILE * out, const _wc_bias * B, const wc_print_opts * o)
{
    const char * names[2] = { "exact", "paper" };
    int i;

    fputs("biasing wrench b = (", out);
    for (i = 0; i < 3; i++)
    {
        if (i)
            fputs(", ", out);
        wc_fprint_fmpq_text(out, B->b + i, o);
    }
    fputs("), disturbances measured by max(|fx|, |fy|, |tau| / ", out);
    wc_fprint_fmpq_text(out, B->L, o);
    fputs("):\n", out);
    for (i = 0; i < 2; i++)
        if (B->infinite[i])
            fprintf(out, "  %s: every disturbance keeps it strongly stable "
                    "(the set is all of R^3)\n", names[i]);
        else if (fmpq_is_zero(B->rho[i]))
            fprintf(out, "  %s: rho = 0: b is %s\n", names[i], B->in_set[i]
                    ? "on the boundary of the strongly stable set"
                    : "not strongly stable");
        else
        {
            fprintf(out, "  %s: rho = ", names[i]);
            wc_fprint_fmpq_text(out, B->rho[i], o);
            fprintf(out, ": every disturbance d with ||d|| %s rho leaves "
                    "b + d strongly stable%s\n", B->closed[i] ? "<=" : "<",
                    B->closed[i] ? "" : " (some d with ||d|| = rho does not)");
        }
}

/* The robustness of the bias as JSON: the member ", \"bias\": {...}"
   of the stability answer's object.  */
static void
bias_json(FILE * out, const _wc_bias * B)
{
    int i;

    fputs(", \"bias\": {\"wrench\": [", out);
    for (i = 0; i < 3; i++)
    {
        fputs(i ? ", \"" : "\"", out);
        wc_fprint_fmpq(out, B->b + i);
        putc('"', out);
    }
    fputs("], \"length\": \"", out);
    wc_fprint_fmpq(out, B->L);
    putc('"', out);
    for (i = 0; i < 2; i++)
    {
        fprintf(out, ", \"%s\": {\"in_set\": %s, ", i == 0 ? "strong"
                : "strong_paper", B->in_set[i] ? "true" : "false");
        if (B->infinite[i])
            fputs("\"rho\": null, \"unbounded\": true}", out);
        else
        {
            fputs("\"rho\": \"", out);
            wc_fprint_fmpq(out, B->rho[i]);
            fprintf(out, "\", \"closed\": %s}",
                    B->closed[i] ? "true" : "false");
        }
    }
    putc('}', out);
}

int
_wc_stability_answer_fprint(FILE * out, const wc_stability_t S,
                            const wc_problem_t P, const _wc_bias * B,
                            const wc_print_opts * o)
{
    if (!_wc_print_json(o))
    {
        wc_stability_fprint(out, S, P, o);
        if (B != NULL)
            bias_text(out, B, o);
        return _wc_fprint_done(out);
    }
    fputs(WC_JSON_OPEN, out);
    _wc_stability_fprint_members(out, S);
    if (B != NULL)
        bias_json(out, B);
    fputs("}\n", out);
    return _wc_fprint_done(out);
}
