/* problem.c -- the problem a certificate states: reading it, the letters
   of modes and sign strings against its fixels, its Jacobian.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Both kinds of certificate carry the problem they speak of; the checker
   reads it here rather than with core/problem.h, whose reader takes the
   .wc text format, not JSON.  */

#include <stdlib.h>
#include <string.h>

#include "check/checker.h"

void
_wc_check_problem_init(wc_check_problem * P)
{
    memset(P, 0, sizeof *P);
}

void
_wc_check_problem_clear(wc_check_problem * P)
{
    _wc_check_qvec_free(P->body, 4);
    _wc_check_qvec_free(P->fixel, 6 * P->n);
    free(P->near);
    _wc_check_problem_init(P);
}

/* Fixel i at the value f.  */
static int
read_fixel(wc_check_problem * P, wc_check_reader * c,
           const wc_json_node * f, size_t i, int dynamics)
{
    const wc_json_node * st;
    mpq_t * q = P->fixel + 6 * i;
    int status = _wc_check_want_object(c, f);

    if (status != WC_OK)
        return status;
    /* its members are independent: check them all */
    status = _wc_check_vector(c, f, "point", q, 2);
    if (_wc_check_vector(c, f, "normal", q + 2, 2) != WC_OK)
        status = WC_EINPUT;
    else if (mpq_sgn(q[2]) == 0 && mpq_sgn(q[3]) == 0)
        status = _wc_check_bad(c, _wc_json_object_get(f, "normal"),
                               "zero normal");
    if (_wc_check_member(c, f, "state", WC_CHECK_STRING, &st) != WC_OK)
        status = WC_EINPUT;
    else if (st->len == 8 && memcmp(st->text, "touching", 8) == 0)
        P->near[i] = 0;
    else if (st->len == 4 && memcmp(st->text, "near", 4) == 0)
        P->near[i] = 1;
    else
        status = _wc_check_bad_quoting(c, st, "unknown fixel state '%s'",
                                       st->text, st->len);
    if (dynamics && _wc_check_scalar(c, f, "mu_s", q[4], 0) != WC_OK)
        status = WC_EINPUT;
    if (dynamics && _wc_check_scalar(c, f, "mu_k", q[5], 0) != WC_OK)
        status = WC_EINPUT;
    return status;
}

int
_wc_check_read_problem(wc_check_problem * P, wc_check_reader * c,
                       const wc_json_node * root, int dynamics)
{
    const wc_json_node * p, * fx;
    size_t i;
    int status = WC_OK;

    if (_wc_check_member(c, root, "problem", WC_CHECK_OBJECT, &p) != WC_OK)
        return WC_EINPUT;
    P->body = _wc_check_qvec_new(4);
    if (P->body == NULL)
        return _wc_check_nomem(c);
    /* the body and the fixels are independent: check them all */
    if (dynamics && _wc_check_scalar(c, p, "mass", P->body[0], 1) != WC_OK)
        status = WC_EINPUT;
    if (dynamics
        && _wc_check_scalar(c, p, "inertia", P->body[1], 1) != WC_OK)
        status = WC_EINPUT;
    if (_wc_check_vector(c, p, "com", P->body + 2, 2) != WC_OK)
        status = WC_EINPUT;
    if (_wc_check_member(c, p, "fixels", WC_CHECK_ARRAY, &fx) != WC_OK)
        return WC_EINPUT;
    if (fx->len == 0)
        return _wc_check_bad(c, fx, "no fixel in the problem");
    P->near = _wc_check_entries_new(c, &P->fixel, 6, fx->len, sizeof(int));
    if (P->near == NULL)
        return WC_EINTERNAL;
    P->n = fx->len;
    for (i = 0; i < fx->len; i++)
        P->near[i] = -1;
    for (i = 0; i < fx->len; i++)
    {
        int fstatus = read_fixel(P, c, fx->items + i, i, dynamics);

        /* a later fixel is later in the file */
        if (fstatus != WC_OK)
            return fstatus;
    }
    return status;
}

int
_wc_check_letters(wc_check_reader * c, const wc_json_node * v,
                  const wc_check_problem * P, int sign)
{
    const char * word = sign ? "sign" : "mode";
    const char * on_near = sign ? "u" : "sa";
    size_t len = v->len, i;

    if (P->n > 0 && len != P->n)
        return _wc_check_bad(c, v, "%s has %lu letter%s; the problem has "
                             "%lu fixel%s", word, (unsigned long) len,
                             len == 1 ? "" : "s", (unsigned long) P->n,
                             P->n == 1 ? "" : "s");
    for (i = 0; i < len; i++)
    {
        unsigned char l = (unsigned char) v->text[i];

        if (l == '\0' || strchr(sign ? "slrnu" : "slrna", l) == NULL)
        {
            if (l < 0x20 || l >= 0x7f)
                return _wc_check_bad(c, v, "unknown %s letter '\\x%02x'",
                                     word, l);
            return _wc_check_bad(c, v, "unknown %s letter '%c'", word, l);
        }
        if (i < P->n && P->near[i] >= 0
            && strchr(P->near[i] ? on_near : "slrn", l) == NULL)
            return _wc_check_bad(c, v, "letter '%c' not allowed on fixel "
                                 "%lu, which is %s", l,
                                 (unsigned long) i + 1,
                                 P->near[i] ? "near" : "touching");
    }
    return WC_OK;
}

void
_wc_check_jacobian(mpq_t * J, const wc_check_problem * P, size_t i)
{
    mpq_t * com = P->body + 2, * p = P->fixel + 6 * i, * nrm = p + 2;

    /* J[5] holds r_x until the end */
    mpq_sub(J[5], p[0], com[0]);
    mpq_sub(J[4], p[1], com[1]);
    mpq_set(J[0], nrm[0]);
    mpq_set(J[1], nrm[1]);
    mpq_mul(J[2], J[5], nrm[1]);
    mpq_mul(J[3], J[4], nrm[0]);
    mpq_sub(J[2], J[2], J[3]);
    /* r x t = r_x n_x + r_y n_y */
    mpq_mul(J[5], J[5], nrm[0]);
    mpq_mul(J[4], J[4], nrm[1]);
    mpq_add(J[5], J[5], J[4]);
    mpq_neg(J[3], nrm[1]);
    mpq_set(J[4], nrm[0]);
}
