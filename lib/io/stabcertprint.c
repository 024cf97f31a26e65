/* stabcertprint.c -- the certificate of a strong stability set
   (wrenchcone-certificate(5), kind "stability-set").

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The cells are proved one at a time (analysis/stabcert.h) and written as
   they are proved, so memory stays that of one cell.  */

#include <config.h>

#include "core/tick.h"
#include "exact/vec3.h"
#include "analysis/stabcert.h"
#include "io/printutil.h"
#include "io/print.h"

static void
put_motion(FILE * out, const wc_motion_struct * a, slong n)
{
    fputs("{\"nudot\": ", out);
    wc_fprint_qvec(out, a->nudot, 3, 1);
    fputs(", \"c\": ", out);
    wc_fprint_qvec(out, a->c, 2 * n, 1);
    fputc('}', out);
}

static void
put_faces(FILE * out, const _wc_stabcert * C)
{
    const wc_stability_struct * S = C->S;
    slong j;

    fputs(",\n \"moving_faces\": [", out);
    for (j = 0; j < C->nfaces; j++)
    {
        slong f = C->face[j];

        fputs(j > 0 ? ",\n   " : "\n   ", out);
        fputs("{\"sign\": ", out);
        wc_fprint_json_string(out, S->moving_sign[f]);
        if (S->moving_rot[f] != 0)
            fprintf(out, ", \"rotation\": %d", S->moving_rot[f]);
        fputc('}', out);
    }
    fputc(']', out);
}

static void
put_cell(FILE * out, const _wc_cell_proof * pf, const _wc_stabcert * C,
         slong i)
{
    slong n = C->m.n, j;

    fputs("{\"point\": ", out);
    _wc_fprint_zvec(out, WC_ROW(C->S->cells->point, i), 3, 1);
    fprintf(out, ", \"in\": %s", _wc_tf(pf->reason == WC_CELL_STRONG));
    if (pf->weak)
    {
        fputs(", \"static\": ", out);
        wc_fprint_qvec(out, pf->weak_c, 2 * n, 1);
    }
    if (pf->reason == WC_CELL_NOT_WEAK)
    {
        fputs(", \"separator\": ", out);
        wc_fprint_qvec(out, pf->sep, 3, 1);
    }
    else if (pf->reason == WC_CELL_MOVES)
    {
        fprintf(out, ", \"face\": %ld, \"closure\": [", (long) pf->face);
        for (j = 0; j < pf->nrays; j++)
        {
            if (j > 0)
                fputs(", ", out);
            put_motion(out, pf->closure + j, n);
        }
        fputs("], \"motion\": ", out);
        put_motion(out, &pf->motion, n);
    }
    else
    {
        fputs(", \"multipliers\": [", out);
        for (j = 0; j < C->nfaces; j++)
        {
            if (j > 0)
                fputs(", ", out);
            wc_fprint_qvec(out, pf->mult[j], pf->nmult[j], 1);
        }
        fputc(']', out);
    }
    fputc('}', out);
}

int
wc_stability_certificate_fprint(FILE * out, const wc_problem_t P,
                                const wc_stability_t S, wc_error_t err)
{
    const wc_cells_struct * A = S->cells;
    _wc_stabcert C;
    _wc_cell_proof pf;
    slong i;
    int status;

    if ((status = _wc_stabcert_init(&C, P, S, err)) != WC_OK)
    {
        _wc_stabcert_clear(&C);
        return status;
    }
    fputs("{\"kind\": \"stability-set\",\n \"covers\": [\"strong\"],\n"
          " \"problem\": ", out);
    _wc_fprint_dyn_problem(out, P);
    fputs(",\n \"strong\": ", out);
    wc_set_fprint_json(out, S->strong);
    fputs(",\n \"planes\": [", out);
    for (i = 0; i < A->nplanes; i++)
    {
        if (i > 0)
            fputs(", ", out);
        _wc_fprint_zvec(out, WC_ROW(A->planes, i), 3, 1);
    }
    fputc(']', out);
    put_faces(out, &C);
    fputs(",\n \"cells\": [", out);
    _wc_cell_proof_init(&pf, &C);
    for (i = 0; i < A->count && status == WC_OK; i++)
    {
        _wc_tick("cells of the certificate", i, A->count);
        status = _wc_stabcert_cell(&pf, &C, i, err);
        if (status == WC_OK)
        {
            fputs(i > 0 ? ",\n  " : "\n  ", out);
            put_cell(out, &pf, &C, i);
        }
    }
    _wc_cell_proof_clear(&pf, &C);
    _wc_stabcert_clear(&C);
    if (status != WC_OK)
        return status;
    fputs("]}\n", out);
    return ferror(out) ? wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                      "write error") : WC_OK;
}
