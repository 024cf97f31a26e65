/* plancertprint.c -- the certificate of a plan's goal set
   (wrenchcone-certificate(5), kind "plan-goal").

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The tree is grown (analysis/plancert.h) before anything is written, so
   a set the proof contradicts writes nothing.  */

#include <config.h>

#include "exact/vec3.h"
#include "analysis/plancert.h"
#include "core/certkind.h"
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
            wc_cone_fprint(out, R->cones + j, _wc_print_as_json);
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
    _wc_plancert C;
    _wc_settree T;
    fmpz * h;
    slong nh;
    int status;

    if ((status = wc_problem_check_fixels(P, WC_PLAN_CERT_MAX_FIXELS, 0,
                                          "a plan certificate", err))
        != WC_OK)
        return status;
    _wc_settree_init(&T);
    status = _wc_plancert_init(&C, P, R, err);
    if (status == WC_OK)
    {
        _wc_plancert_prefer(&h, &nh, &C);
        status = _wc_cert_tree(&T, h, nh, _wc_plancert_classify, &C, err);
    }
    if (status != WC_OK)
    {
        _wc_settree_clear(&T);
        _wc_plancert_clear(&C);
        return status;
    }
    fputs("{\"kind\": \"" WC_CERT_KIND_PLAN "\",\n \"covers\": [\"goal\"],\n"
          " \"problem\": ", out);
    _wc_fprint_dyn_problem(out, P);
    fputs(",\n \"goal\": ", out);
    wc_set_fprint(out, R->goal, _wc_print_as_json);
    _wc_fprint_planes(out, &T);
    status = put_strings(out, &C, err);
    if (status == WC_OK)
        status = put_pieces(out, &C, err);
    if (status == WC_OK)
        status = _wc_fprint_tree(out, &T, "string", err);
    _wc_settree_clear(&T);
    _wc_plancert_clear(&C);
    return status;
}

/* Q := P with mu_s = mu_k = mu at every fixel (the sweep's problem).  */
static int
at_friction(wc_problem_t Q, const wc_problem_t P, const fmpq_t mu)
{
    slong i;
    int status = wc_problem_set(Q, P);

    for (i = 0; i < Q->n && status == WC_OK; i++)
    {
        fmpq_set(Q->fixels[i].mu_s, mu);
        fmpq_set(Q->fixels[i].mu_k, mu);
    }
    return status;
}

/* "lower": the witness at lo and, for every string with one s, the
   multipliers showing it is not in the string's cone.  */
static int
put_lower(FILE * out, const wc_problem_t Q, const fmpq * g, wc_error_t err)
{
    wc_plan_strings_t T;
    _wc_stab_model m;
    fmpq * mu = _fmpq_vec_init(Q->n + 1), * mult = NULL;
    slong j, nmult = 0;
    int status, r;

    wc_plan_strings_init(T);
    _wc_stab_model_init(&m, Q);
    _wc_plan_model_mu(mu, Q);
    status = wc_plan_strings(T, Q->n, err);
    fputs("{\"wrench\": ", out);
    wc_fprint_qvec(out, g, 3, _wc_print_as_json);
    fputs(",\n  \"strings\": [", out);
    for (j = 0; j < T->nneeded && status == WC_OK; j++)
    {
        const char * x = T->strings[T->needed[j]];

        r = _wc_plan_string_solve(NULL, NULL, &mult, &nmult, &m, mu, x, g, 1,
                                  err);
        if (r != 0)
        {
            status = r < 0 ? WC_EINTERNAL : _wc_setcert_bug(err, "critical "
                                                            "friction's "
                                                            "witness", "is "
                                                            "in a string's "
                                                            "cone");
            break;
        }
        fputs(j > 0 ? ",\n   " : "\n   ", out);
        fputs("{\"string\": ", out);
        wc_fprint_json_string(out, x);
        fputs(", \"multipliers\": ", out);
        _wc_fprint_scaled(out, mult, nmult);
        fputc('}', out);
        _fmpq_vec_clear(mult, nmult);
        mult = NULL;
    }
    fputs("]}", out);
    _fmpq_vec_clear(mu, Q->n + 1);
    _wc_stab_model_clear(&m);
    wc_plan_strings_clear(T);
    return status;
}

int
wc_critical_certificate_fprint(FILE * out, const wc_problem_t P,
                               const wc_critical_t C, wc_error_t err)
{
    wc_problem_t Q;
    wc_plan_t R;
    int status;

    if ((status = wc_problem_check_fixels(P, WC_PLAN_CERT_MAX_FIXELS, 0,
                                          "a plan certificate", err))
        != WC_OK)
        return status;
    wc_problem_init(Q);
    wc_plan_init(R);
    fputs("{\"kind\": \"" WC_CERT_KIND_CRIT "\",\n \"problem\": ", out);
    _wc_fprint_dyn_problem(out, P);
    fprintf(out, ",\n \"found\": %s, \"empty_at_zero\": %s, \"lo\": ",
            _wc_tf(C->found), _wc_tf(C->empty_at_zero));
    _wc_fprint_jq(out, C->lo);
    fputs(", \"hi\": ", out);
    if (C->found)
        _wc_fprint_jq(out, C->hi);
    else
        fputs("null", out);
    fputs(",\n \"lower\": ", out);
    status = WC_OK;
    if (C->empty_at_zero)
        fputs("null", out);
    else if ((status = at_friction(Q, P, C->lo)) == WC_OK)
        status = put_lower(out, Q, C->lo_witness, err);
    if (status == WC_OK)
        fputs(",\n \"upper\": ", out);
    if (status == WC_OK && !C->found)
        fputs("null}\n", out);
    else if (status == WC_OK
             && (status = at_friction(Q, P, C->hi)) == WC_OK
             && (status = wc_plan(R, Q, 0, err)) == WC_OK
             && (status = wc_plan_certificate_fprint(out, Q, R, err))
             == WC_OK)
        fputs("}\n", out);
    wc_plan_clear(R);
    wc_problem_clear(Q);
    if (status != WC_OK)
        return status;
    return ferror(out) ? wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                      "write error") : WC_OK;
}
