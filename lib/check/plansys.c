/* plansys.c -- a plan's strings for the checker: which strings there are,
   the system of one string, and a solution of it.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The strings of an insertion plan that matter are those with exactly one
   s and m or u elsewhere: every string of the plan (s on the contacts L
   that may be lost or the states not reached, m on the contacts kept, u
   elsewhere) has at least one s, and its cone lies in the cone of the
   string with all its other s turned to u (s asks a_in >= 0 and no force,
   u only no force).  The cone W(x) of a string is closed:

     W(x) = { M nudot - sum_j lambda_j w_j : J_in . nudot >= 0 where x has
              s, = 0 where it has m; lambda_j >= 0 }

   with w_j the two edges J_in -+ mu J_it of every fixel where x has m, in
   fixel order, mu = max(mu_s, mu_k) (the plan model's friction cone).
   Whether the fixels touch does not matter.  */

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check/setcheck.h"

/* 1 when the n-letter string s is a plan string: exactly one s, m or u
   elsewhere.  */
static int
is_plan_string(const char * s, size_t len, size_t n)
{
    size_t i, ns = 0;

    if (len != n)
        return 0;
    for (i = 0; i < n; i++)
    {
        if (s[i] != 's' && s[i] != 'm' && s[i] != 'u')
            return 0;
        ns += s[i] == 's';
    }
    return ns == 1;
}

static int
str_cmp(const void * a, const void * b)
{
    return strcmp(*(const char * const *) a, *(const char * const *) b);
}

int
_wc_check_plan_strings(wc_check_text * why, const wc_check_stability * S)
{
    size_t n = S->P.n, k, want;
    const char ** s;
    int holds = 1;

    want = n < 8 * sizeof(size_t) - 1 ? n << (n - 1) : SIZE_MAX;
    for (k = 0; k < S->nfaces; k++)
        if (!is_plan_string(S->faces[k].sign->text, S->faces[k].sign->len, n))
        {
            _wc_check_putf(why, "string %lu is not a plan string with one s "
                           "and m or u elsewhere", (unsigned long) k + 1);
            return 0;
        }
    if (S->nfaces != want)
    {
        _wc_check_putf(why, "%lu strings, but %lu fixels have %lu with one "
                       "s", (unsigned long) S->nfaces, (unsigned long) n,
                       (unsigned long) want);
        return 0;
    }
    /* as many as there are, each a plan string: all of them iff none
       repeats */
    s = _wc_check_alloc(S->nfaces, sizeof(char *));
    if (s == NULL)
        return -1;
    for (k = 0; k < S->nfaces; k++)
        s[k] = S->faces[k].sign->text;
    qsort(s, S->nfaces, sizeof(char *), str_cmp);
    for (k = 1; k < S->nfaces && holds; k++)
        if (strcmp(s[k - 1], s[k]) == 0)
        {
            _wc_check_putf(why, "the string %s is listed twice", s[k]);
            holds = 0;
        }
    free(s);
    return holds;
}

/* mu = max(mu_s, mu_k) of fixel i.  */
static mpq_t *
plan_mu(const wc_check_problem * P, size_t i)
{
    mpq_t * mu = P->fixel + 6 * i + 4;

    return mpq_cmp(mu[0], mu[1]) >= 0 ? mu : mu + 1;
}

int
_wc_check_plan_face(wc_check_scratch * X, size_t k, const char * x,
                    mpq_t * y, size_t ny)
{
    const wc_check_problem * P = &X->S->P;
    wc_check_text * why = X->why, prefix = { NULL, 0, 0, 0 };
    size_t n = P->n, e = 0, rows, d, i, j, r;
    mpq_t * s = NULL;
    wc_check_rel * rel = NULL;
    int c, m, holds = -1;

    for (i = 0; i < n; i++)
        e += x[i] == 'm' ? 2 : 0;
    rows = 3 + e + X->ng;
    for (i = 0; i < n; i++)
        rows += x[i] != 'u';
    d = 3 + e + X->ng;
    _wc_check_putf(&prefix, "string %lu (%s): ", (unsigned long) k + 1, x);
    s = _wc_check_qvec_new(d);
    rel = _wc_check_alloc(rows, sizeof(wc_check_rel));
    if (s == NULL || rel == NULL || prefix.oom)
        goto cleanup;
    holds = _wc_check_motzkin_count(why, prefix.s, "row", ny, rows);
    if (holds != 1)
        goto cleanup;
    /* M nudot - sum_j lambda_j w_j - sum_i alpha_i G_i = 0 */
    for (c = 0; c < 3; c++)
    {
        rel[c] = WC_CHECK_EQ;
        _wc_check_qaddmul(s[c], y[c], P->body[c < 2 ? 0 : 1], X->t);
        for (i = 0, j = 0; i < n; i++)
            for (m = 0; x[i] == 'm' && m < 2; m++, j++)
            {
                /* w_j[c] = J_in[c] -+ mu J_it[c] */
                mpq_mul(X->a, *plan_mu(P, i), X->J[6 * i + 3 + c]);
                if (m == 0)
                    mpq_neg(X->a, X->a);
                mpq_add(X->a, X->a, X->J[6 * i + c]);
                mpq_mul(X->a, X->a, y[c]);
                mpq_sub(s[3 + j], s[3 + j], X->a);
            }
        for (j = 0; j < X->ng; j++)
        {
            mpq_mul(X->a, y[c], X->G[3 * j + c]);
            mpq_sub(s[3 + e + j], s[3 + e + j], X->a);
        }
    }
    r = 3;
    for (i = 0; i < n; i++)
        if (x[i] != 'u')
        {
            rel[r] = x[i] == 's' ? WC_CHECK_GE : WC_CHECK_EQ;
            for (c = 0; c < 3; c++)
                _wc_check_qaddmul(s[c], y[r], X->J[6 * i + c], X->t);
            r++;
        }
    for (j = 0; j < e + X->ng; j++, r++)
    {
        rel[r] = j < e ? WC_CHECK_GE : WC_CHECK_GT;
        mpq_add(s[3 + j], s[3 + j], y[r]);
    }
    holds = _wc_check_motzkin(why, prefix.s, "row", rel, y, rows, s, d);
cleanup:
    _wc_check_qvec_free(s, d);
    free(rel);
    free(prefix.s);
    if (why->oom)
        holds = -1;
    return holds;
}

int
_wc_check_plan_motion(wc_check_scratch * X, const char * x)
{
    const wc_check_stability * S = X->S;
    const wc_check_problem * P = &S->P;
    wc_check_text * why = X->why;
    mpq_t * nu = S->nudot, * cc = S->motion_c;
    size_t n = P->n, i;
    int j;

    for (j = 0; j < 3; j++)
        mpq_set(X->s[j], S->g[j]);
    for (i = 0; i < n; i++)
    {
        mpq_t * cn = cc + i, * ct = cc + n + i;

        _wc_check_qdot3(X->a, X->J + 6 * i, nu, X->t);
        if (x[i] == 's' ? mpq_sgn(X->a) < 0 : x[i] == 'm' && mpq_sgn(X->a))
        {
            _wc_check_putf(why, "the solution has a_%lun = ",
                           (unsigned long) i + 1);
            _wc_check_put_q(why, X->a);
            _wc_check_putf(why, ", but its letter %c needs %s 0", x[i],
                           x[i] == 's' ? ">=" : "=");
            return 0;
        }
        mpq_mul(X->b, *plan_mu(P, i), *cn);
        mpq_abs(X->a, *ct);
        if (x[i] == 'm' ? mpq_sgn(*cn) < 0 || mpq_cmp(X->a, X->b) > 0
            : mpq_sgn(*cn) != 0 || mpq_sgn(*ct) != 0)
        {
            _wc_check_putf(why, "the solution's force at fixel %lu breaks "
                           "its letter %c: c_%lun = ", (unsigned long) i + 1,
                           x[i], (unsigned long) i + 1);
            _wc_check_put_q(why, *cn);
            _wc_check_putf(why, ", c_%lut = ", (unsigned long) i + 1);
            _wc_check_put_q(why, *ct);
            return 0;
        }
        for (j = 0; j < 3; j++)
        {
            _wc_check_qaddmul(X->s[j], *cn, X->J[6 * i + j], X->t);
            _wc_check_qaddmul(X->s[j], *ct, X->J[6 * i + 3 + j], X->t);
        }
    }
    /* M nudot = g + J c */
    for (j = 0; j < 3; j++)
    {
        mpq_mul(X->a, P->body[j < 2 ? 0 : 1], nu[j]);
        if (!mpq_equal(X->a, X->s[j]))
        {
            _wc_check_put(why, "the solution has M nudot != g + J c");
            return 0;
        }
    }
    return 1;
}
