/* plancertprint.c -- the certificate of a plan's goal set
   (wrenchcone-certificate(5), kind "plan-goal").

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The cells are proved one at a time (analysis/plancert.h) and written as
   they are proved.  */

#include <config.h>

#include "core/tick.h"
#include "exact/vec3.h"
#include "analysis/plancert.h"
#include "io/printutil.h"
#include "io/print.h"
#include "io/certprint.h"

/* Every needed string with its cone and the solutions at its
   generators.  */
static int
put_strings(FILE * out, _wc_plancert * C, wc_error_t err)
{
    const wc_plan_struct * R = C->R;
    slong j;
    int status = WC_OK;

    fputs(",\n \"strings\": [", out);
    for (j = 0; j < R->T->nneeded && status == WC_OK; j++)
    {
        _wc_cone_proof cp = { 0, NULL, 0, NULL, NULL };

        status = _wc_plancert_cone(&cp, C, j, err);
        if (status == WC_OK)
        {
            fputs(j > 0 ? ",\n  " : "\n  ", out);
            fputs("{\"string\": ", out);
            wc_fprint_json_string(out, R->T->strings[R->T->needed[j]]);
            fputs(",\n   \"cone\": ", out);
            wc_cone_fprint_json(out, R->cones + j);
            _wc_fprint_cone_proof(out, &cp, C->m.n);
            putc('}', out);
        }
        _wc_cone_proof_clear(&cp, C->m.n);
    }
    fputc(']', out);
    return status;
}

static int
put_pieces(FILE * out, _wc_plancert * C, wc_error_t err)
{
    const wc_set_struct * T = C->R->goal;
    slong k;
    int status = WC_OK;

    fputs(",\n \"proofs\": [", out);
    for (k = 0; k < T->npieces && status == WC_OK; k++)
    {
        _wc_piece_proof pp = { 0, NULL, 0, NULL, NULL };

        status = _wc_plancert_piece(&pp, C, k, err);
        if (status == WC_OK)
        {
            fputs(k > 0 ? ",\n  " : "\n  ", out);
            _wc_fprint_piece_proof(out, &pp, C->R->T->nneeded, C->m.n);
        }
        _wc_piece_proof_clear(&pp, C->m.n, C->R->T->nneeded);
    }
    fputc(']', out);
    return status;
}

int
wc_plan_certificate_fprint(FILE * out, const wc_problem_t P,
                           const wc_plan_t R, wc_error_t err)
{
    const wc_cells_struct * A = R->cells;
    _wc_plancert C;
    _wc_cell_proof pf;
    slong i;
    int status;

    if ((status = _wc_plancert_init(&C, P, R, err)) != WC_OK)
    {
        _wc_plancert_clear(&C);
        return status;
    }
    fputs("{\"kind\": \"plan-goal\",\n \"covers\": [\"goal\"],\n"
          " \"problem\": ", out);
    _wc_fprint_dyn_problem(out, P);
    fputs(",\n \"goal\": ", out);
    wc_set_fprint_json(out, R->goal);
    _wc_fprint_planes(out, A);
    status = put_strings(out, &C, err);
    if (status == WC_OK)
        status = put_pieces(out, &C, err);
    fputs(",\n \"cells\": [", out);
    _wc_cell_proof_init(&pf, &C.base);
    for (i = 0; i < A->count && status == WC_OK; i++)
    {
        _wc_tick("cells of the certificate", i, A->count);
        status = _wc_plancert_cell(&pf, &C, i, err);
        if (status == WC_OK)
        {
            fputs(i > 0 ? ",\n  " : "\n  ", out);
            _wc_fprint_cell_proof(out, &pf, WC_ROW(A->point, i), "string");
        }
    }
    _wc_cell_proof_clear(&pf, &C.base);
    _wc_plancert_clear(&C);
    if (status != WC_OK)
        return status;
    fputs("]}\n", out);
    return ferror(out) ? wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                      "write error") : WC_OK;
}
