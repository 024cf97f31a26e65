/* answerprint.c -- a mode's cone and a bias's robustness, written
   (answerprint.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "io/answerprint.h"
#include "io/fconeprint.h"
#include "core/version.h"


int
_wc_mode_cone_fprint(FILE * out, const char * mode, const wc_cone_t W,
                     const wc_trace_t T, int paper, int fmt)
{
    switch (fmt)
    {
    case _WC_FMT_JSON:
        fputs(WC_JSON_OPEN "\"mode\": ", out);
        wc_fprint_json_string(out, mode);
        fputs(", \"cone\": ", out);
        wc_cone_fprint_json(out, W);
        if (T != NULL)
        {
            fprintf(out, ", \"method\": \"%s\", \"trace\": ",
                    paper ? "paper" : "direct");
            wc_trace_fprint_json(out, T);
        }
        fputs("}\n", out);
        break;
    case _WC_FMT_TEXT:
        if (T != NULL)
        {
            fprintf(out, "trace (%s route):\n", paper ? "paper, Section 5"
                    : "direct, M V_x + (-J) D_x");
            wc_trace_fprint_text(out, T, "  ");
            putc('\n', out);
        }
        fprintf(out, "W(%s): wrench cone of mode %s\n", mode, mode);
        wc_cone_fprint_text(out, W, "  ");
        break;
    default:
    {
        size_t len = 2 * strlen(mode) + 64;
        char * title = malloc(len);

        if (title == NULL)
            return WC_EINTERNAL;
        snprintf(title, len, "wrenchcone: W(%s), the wrench cone of mode %s",
                 mode, mode);
        if (T != NULL)
            wc_trace_fprint_text(out, T, "* ");
        wc_cone_fprint_cdd(out, W, title, fmt == _WC_FMT_INE ? 1
                           : fmt == _WC_FMT_EXT ? 2 : 3);
        free(title);
        break;
    }
    }
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

int
_wc_mode_fcone_fprint(FILE * out, const char * mode, const wc_fcone_t F,
                      int fmt)
{
    if (fmt == _WC_FMT_JSON)
    {
        fputs(WC_JSON_OPEN "\"mode\": ", out);
        wc_fprint_json_string(out, mode);
        fputs(", \"cone\": ", out);
        wc_fcone_fprint(out, F, WC_FCONE_JSON);
        fputs("}\n", out);
    }
    else if (fmt == _WC_FMT_TEXT)
    {
        fprintf(out, "W(%s): wrench cone of mode %s\n", mode, mode);
        wc_fcone_fprint(out, F, WC_FCONE_TEXT);
    }
    else
    {
        fprintf(out, "* wrenchcone: W(%s), the wrench cone of mode %s\n",
                mode, mode);
        wc_fcone_fprint(out, F, fmt == _WC_FMT_INE ? WC_FCONE_INE
                        : fmt == _WC_FMT_EXT ? WC_FCONE_EXT : WC_FCONE_CDD);
    }
    return ferror(out) ? WC_EINTERNAL : WC_OK;
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

int
_wc_bias_fprint_text(FILE * out, const _wc_bias * B)
{
    const char * names[2] = { "exact", "paper" };
    int i;

    fputs("biasing wrench b = (", out);
    for (i = 0; i < 3; i++)
    {
        if (i)
            fputs(", ", out);
        wc_fprint_fmpq_text(out, B->b + i);
    }
    fputs("), disturbances measured by max(|fx|, |fy|, |tau| / ", out);
    wc_fprint_fmpq_text(out, B->L);
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
            wc_fprint_fmpq_text(out, B->rho[i]);
            fprintf(out, ": every disturbance d with ||d|| %s rho leaves "
                    "b + d strongly stable%s\n", B->closed[i] ? "<=" : "<",
                    B->closed[i] ? "" : " (some d with ||d|| = rho does not)");
        }
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

int
_wc_bias_fprint_json(FILE * out, const _wc_bias * B)
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
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}
