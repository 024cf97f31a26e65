/* stabcertprint.c -- the certificate of a strong stability set
   (wrenchcone-certificate(5), kind "stability-set").

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The cells are proved one at a time (analysis/stabcert.h) and written as
   they are proved, so memory stays that of one cell.  */

#include <config.h>

#include <flint/fmpz_vec.h>

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

/* The moving faces, each with its cone and the motions that prove the
   cone moves.  */
static int
put_faces(FILE * out, _wc_stabcert * C, wc_error_t err)
{
    const wc_stability_struct * S = C->S;
    slong j, g, f, n = C->m.n;
    int status = WC_OK;

    fputs(",\n \"moving_faces\": [", out);
    for (j = 0; j < C->nfaces && status == WC_OK; j++)
    {
        slong y = C->face[j];
        _wc_cone_proof cp = { 0, NULL, 0, NULL, NULL };

        status = _wc_stabcert_cone(&cp, C, j, err);
        if (status == WC_OK)
        {
            fputs(j > 0 ? ",\n  " : "\n  ", out);
            fputs("{\"sign\": ", out);
            wc_fprint_json_string(out, S->moving_sign[y]);
            if (S->moving_rot[y] != 0)
                fprintf(out, ", \"rotation\": %d", S->moving_rot[y]);
            fputs(",\n   \"cone\": ", out);
            wc_cone_fprint_json(out, S->moving + y);
            fputs(",\n   \"closure\": [", out);
            for (g = 0; g < cp.ngen; g++)
            {
                if (g > 0)
                    fputs(", ", out);
                put_motion(out, cp.closure + g, n);
            }
            fputs("],\n   \"motions\": [", out);
            for (f = 0; f < cp.nfaces; f++)
            {
                if (f > 0)
                    fputs(", ", out);
                if (cp.included[f])
                    put_motion(out, cp.motion + f, n);
                else
                    fputs("null", out);
            }
            fputs("]}", out);
        }
        _wc_cone_proof_clear(&cp, C->m.n);
    }
    fputc(']', out);
    return status;
}

/* v (len) scaled by a positive number to a primitive integer vector (a
   Motzkin certificate or a separator means the same after it).  */
static void
put_scaled(FILE * out, const fmpq * v, slong len)
{
    fmpz_t l, g;
    fmpz * z = _fmpz_vec_init(len + 1);
    slong j;

    fmpz_init(l);
    fmpz_init(g);
    fmpz_one(l);
    for (j = 0; j < len; j++)
        fmpz_lcm(l, l, fmpq_denref(v + j));
    for (j = 0; j < len; j++)
    {
        fmpz_divexact(z + j, l, fmpq_denref(v + j));
        fmpz_mul(z + j, z + j, fmpq_numref(v + j));
    }
    _fmpz_vec_content(g, z, len);
    if (!fmpz_is_zero(g))
        _fmpz_vec_scalar_divexact_fmpz(z, z, len, g);
    _wc_fprint_zvec(out, z, len, 1);
    _fmpz_vec_clear(z, len + 1);
    fmpz_clear(l);
    fmpz_clear(g);
}

static void
put_cell(FILE * out, const _wc_cell_proof * pf, const _wc_stabcert * C,
         slong i)
{
    slong j;

    (void) C;
    fputs("{\"point\": ", out);
    _wc_fprint_zvec(out, WC_ROW(C->S->cells->point, i), 3, 1);
    fprintf(out, ", \"in\": %s", _wc_tf(pf->reason == WC_CELL_IN));
    if (pf->reason == WC_CELL_NOT_WEAK)
    {
        fputs(", \"separator\": ", out);
        put_scaled(out, pf->sep, 3);
    }
    else
    {
        fprintf(out, ", \"%s\": %ld, \"%s\": %ld, \"sum\": ",
                pf->reason == WC_CELL_IN ? "piece" : "face",
                (long) pf->owner, pf->reason == WC_CELL_IN
                ? "piece_face" : "cone_face", (long) pf->face);
        wc_fprint_qvec(out, pf->alpha, pf->ngen, 1);
        fputs(", \"rays\": [", out);
        for (j = 0; j < pf->nrays; j++)
        {
            if (j > 0)
                fputs(", ", out);
            wc_fprint_qvec(out, pf->beta + j * pf->ngen, pf->ngen, 1);
        }
        fputc(']', out);
    }
    fputc('}', out);
}

/* The proof of every piece: static forces at its generators, and the
   multipliers of each included face against every moving face.  */
static int
put_pieces(FILE * out, _wc_stabcert * C, wc_error_t err)
{
    const wc_set_struct * T = C->S->strong;
    slong k, g, f, j, n2 = 2 * C->m.n;
    int status = WC_OK;

    fputs(",\n \"proofs\": [", out);
    for (k = 0; k < T->npieces && status == WC_OK; k++)
    {
        _wc_piece_proof pp = { 0, NULL, 0, NULL, NULL };

        status = _wc_stabcert_piece(&pp, C, k, err);
        if (status == WC_OK)
        {
            fputs(k > 0 ? ",\n  " : "\n  ", out);
            fputs("{\"static\": [", out);
            for (g = 0; g < pp.ngen; g++)
            {
                if (g > 0)
                    fputs(", ", out);
                wc_fprint_qvec(out, pp.c + g * n2, n2, 1);
            }
            fputs("],\n   \"faces\": [", out);
            for (f = 0; f < pp.nfaces; f++)
            {
                fputs(f > 0 ? ",\n    " : "\n    ", out);
                if (pp.mult[f] == NULL)
                {
                    fputs("null", out);
                    continue;
                }
                putc('[', out);
                for (j = 0; j < C->nfaces; j++)
                {
                    if (j > 0)
                        fputs(", ", out);
                    put_scaled(out, pp.mult[f][j], pp.nmult[f][j]);
                }
                putc(']', out);
            }
            fputs("]}", out);
        }
        _wc_piece_proof_clear(&pp, C->m.n, C->nfaces);
    }
    fputc(']', out);
    return status;
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
    status = put_faces(out, &C, err);
    if (status == WC_OK)
        status = put_pieces(out, &C, err);
    fputs(",\n \"cells\": [", out);
    _wc_cell_proof_init(&pf, &C.base);
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
    _wc_cell_proof_clear(&pf, &C.base);
    _wc_stabcert_clear(&C);
    if (status != WC_OK)
        return status;
    fputs("]}\n", out);
    return ferror(out) ? wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                      "write error") : WC_OK;
}
