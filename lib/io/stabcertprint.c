/* stabcertprint.c -- the certificate of a strong stability set
   (wrenchcone-certificate(5), kind "stability-set").

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The tree is grown (analysis/stabcert.h) before anything is written, so
   a set the proof contradicts writes nothing.  */

#include <config.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "analysis/stabcert.h"
#include "core/certkind.h"
#include "io/printutil.h"
#include "io/print.h"
#include "io/certprint.h"

/* The moving faces, each with its cone and the motions that prove the
   cone moves.  */
static int
put_faces(FILE * out, _wc_stabcert * C, wc_error_t err)
{
    const wc_stability_struct * S = C->S;
    slong j, n = C->m.n;
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
            wc_cone_fprint(out, S->moving + y, _wc_print_as_json);
            _wc_fprint_cone_proof(out, &cp, n);
            putc('}', out);
        }
        _wc_cone_proof_clear(&cp, C->m.n);
    }
    fputc(']', out);
    return status;
}

/* The proof of every piece: static forces at its generators, and the
   multipliers of each included face against every moving face.  */
static int
put_pieces(FILE * out, _wc_stabcert * C, wc_error_t err)
{
    const wc_set_struct * T = C->S->strong;
    slong k;
    int status = WC_OK;

    fputs(",\n \"proofs\": [", out);
    for (k = 0; k < T->npieces && status == WC_OK; k++)
    {
        _wc_piece_proof pp = { 0, NULL, 0, NULL, NULL };

        status = _wc_stabcert_piece(&pp, C, k, err);
        if (status == WC_OK)
        {
            fputs(k > 0 ? ",\n  " : "\n  ", out);
            _wc_fprint_piece_proof(out, &pp, C->nfaces, C->m.n);
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
    _wc_stabcert C;
    _wc_settree T;
    fmpz * h;
    slong nh;
    int status;

    _wc_settree_init(&T);
    status = _wc_stabcert_init(&C, P, S, err);
    if (status == WC_OK)
    {
        _wc_stabcert_prefer(&h, &nh, &C);
        status = _wc_cert_tree(&T, h, nh, _wc_stabcert_classify, &C, err);
    }
    if (status != WC_OK)
    {
        _wc_settree_clear(&T);
        _wc_stabcert_clear(&C);
        return status;
    }
    fputs("{\"kind\": \"" WC_CERT_KIND_SET "\",\n \"covers\": [\"strong\"],\n"
          " \"problem\": ", out);
    _wc_fprint_dyn_problem(out, P);
    fputs(",\n \"strong\": ", out);
    wc_set_fprint(out, S->strong, _wc_print_as_json);
    _wc_fprint_planes(out, &T);
    status = put_faces(out, &C, err);
    if (status == WC_OK)
        status = put_pieces(out, &C, err);
    if (status == WC_OK)
        status = _wc_fprint_tree(out, &T, "face", err);
    _wc_settree_clear(&T);
    _wc_stabcert_clear(&C);
    return status;
}
