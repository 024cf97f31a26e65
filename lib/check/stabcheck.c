/* stabcheck.c -- checking a strong-stability certificate (wrenchcone(1), stability): the
   weak claim (static forces or a separator), the motion of a weakly but
   not strongly stable wrench; the faces are in facecheck.c.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdio.h>
#include <stdlib.h>

#include "check/stabcheck.h"

int
_wc_check_scratch_init(wc_check_scratch * X, const wc_check_stability * S,
                       wc_check_text * why)
{
    size_t i;

    X->S = S;
    X->why = why;
    X->J = _wc_check_qvec_new(_wc_check_times(6, S->P.n));
    X->s = _wc_check_qvec_new(3);
    mpq_init(X->a);
    mpq_init(X->b);
    mpq_init(X->t);
    X->G = S->g;
    X->ng = 1;
    X->closed = 0;
    X->rotation = 0;
    if (X->J == NULL || X->s == NULL)
        return 0;
    for (i = 0; i < S->P.n; i++)
        _wc_check_jacobian(X->J + 6 * i, &S->P, i);
    return 1;
}

void
_wc_check_scratch_clear(wc_check_scratch * X)
{
    _wc_check_qvec_free(X->J, 6 * X->S->P.n);
    _wc_check_qvec_free(X->s, 3);
    X->J = X->s = NULL;
    mpq_clear(X->a);
    mpq_clear(X->b);
    mpq_clear(X->t);
}

/* Names of the quantities of fixel i (0-based) in messages.  */
typedef struct
{
    char an[32], at[32], cn[32], ct[32];
}
fixel_names;

static void
names_of(fixel_names * N, size_t i)
{
    unsigned long k = (unsigned long) i + 1;

    sprintf(N->an, "a_%lun", k);
    sprintf(N->at, "a_%lut", k);
    sprintf(N->cn, "c_%lun", k);
    sprintf(N->ct, "c_%lut", k);
}

int
_wc_check_separates(wc_check_scratch * X, mpq_t * y)
{
    const wc_check_stability * S = X->S;
    wc_check_text * why = X->why;
    size_t i;
    int e;

    for (i = 0; i < S->P.n; i++)
    {
        if (S->P.near[i])
            continue;
        /* y . (J_in -+ mu_s J_it) */
        _wc_check_qdot3(X->a, y, X->J + 6 * i, X->t);
        _wc_check_qdot3(X->b, y, X->J + 6 * i + 3, X->t);
        mpq_mul(X->b, X->b, S->P.fixel[6 * i + 4]);
        for (e = -1; e <= 1; e += 2)
        {
            if (e < 0)
                mpq_sub(X->t, X->a, X->b);
            else
                mpq_add(X->t, X->a, X->b);
            if (mpq_sgn(X->t) < 0)
            {
                _wc_check_put(why, "the separator y = ");
                _wc_check_put_qvec(why, y, 3);
                _wc_check_putf(why, " has y . (J_%lun %c mu_s J_%lut) = ",
                               (unsigned long) i + 1, e < 0 ? '-' : '+',
                               (unsigned long) i + 1);
                _wc_check_put_q(why, X->t);
                _wc_check_put(why, ", not >= 0");
                return 0;
            }
        }
    }
    return 1;
}

/* The separator y of a wrench that is not weakly stable.  1 or 0.  */
static int
check_separator(wc_check_scratch * X)
{
    const wc_check_stability * S = X->S;
    wc_check_text * why = X->why;
    mpq_t * y = S->sep;

    _wc_check_qdot3(X->a, y, S->g, X->t);
    if (mpq_sgn(X->a) <= 0)
    {
        _wc_check_put(why, "the separator y = ");
        _wc_check_put_qvec(why, y, 3);
        _wc_check_put(why, " has y . g = ");
        _wc_check_put_q(why, X->a);
        _wc_check_put(why, ", not > 0");
        return 0;
    }
    return _wc_check_separates(X, y);
}

/* 0 and "the static forces load fixel 2, which is near: c_2n = 1,
   c_2t = 0" (who: "the static forces load", "the motion loads") when c
   (2 n entries) loads the fixel i and it is near; else 1.  */
static int
check_near_unloaded(wc_check_scratch * X, const char * who, mpq_t * c,
                    size_t i)
{
    size_t n = X->S->P.n;
    fixel_names N;

    if (!X->S->P.near[i] || (mpq_sgn(c[i]) == 0 && mpq_sgn(c[n + i]) == 0))
        return 1;
    names_of(&N, i);
    _wc_check_putf(X->why, "%s fixel %lu, which is near: %s = ", who,
                   (unsigned long) i + 1, N.cn);
    _wc_check_put_q(X->why, c[i]);
    _wc_check_putf(X->why, ", %s = ", N.ct);
    _wc_check_put_q(X->why, c[n + i]);
    return 0;
}

/* X->s += c_in J_in + c_it J_it (c of 2 n entries).  */
static void
add_forces(wc_check_scratch * X, mpq_t * c, size_t i)
{
    size_t n = X->S->P.n;
    int j;

    for (j = 0; j < 3; j++)
    {
        _wc_check_qaddmul(X->s[j], c[i], X->J[6 * i + j], X->t);
        _wc_check_qaddmul(X->s[j], c[n + i], X->J[6 * i + 3 + j], X->t);
    }
}

int
_wc_check_static(wc_check_scratch * X)
{
    const wc_check_stability * S = X->S;
    wc_check_text * why = X->why;
    size_t n = S->P.n, i;
    int j;

    for (j = 0; j < 3; j++)
        mpq_set_ui(X->s[j], 0, 1);
    for (i = 0; i < n; i++)
    {
        mpq_t * cn = S->weak_c + i, * ct = S->weak_c + n + i;
        fixel_names N;

        names_of(&N, i);
        if (!check_near_unloaded(X, "the static forces load", S->weak_c,
                                 i))
            return 0;
        if (mpq_sgn(*cn) < 0)
        {
            _wc_check_putf(why, "the static force %s = ", N.cn);
            _wc_check_put_q(why, *cn);
            _wc_check_put(why, " is negative");
            return 0;
        }
        mpq_mul(X->a, S->P.fixel[6 * i + 4], *cn);
        mpq_abs(X->b, *ct);
        if (mpq_cmp(X->b, X->a) > 0)
        {
            _wc_check_putf(why, "the static force at fixel %lu leaves its "
                           "friction cone: |%s| = ", (unsigned long) i + 1,
                           N.ct);
            _wc_check_put_q(why, X->b);
            _wc_check_putf(why, " > mu_s %s = ", N.cn);
            _wc_check_put_q(why, X->a);
            return 0;
        }
        add_forces(X, S->weak_c, i);
    }
    for (j = 0; j < 3; j++)
        mpq_neg(X->s[j], X->s[j]);
    if (!_wc_check_qvec_equal(X->s, S->g, 3))
    {
        _wc_check_put(why, "the static forces give -J c = ");
        _wc_check_put_qvec(why, X->s, 3);
        _wc_check_put(why, ", not the wrench ");
        _wc_check_put_qvec(why, S->g, 3);
        return 0;
    }
    return 1;
}

/* The motion is a solution of M nudot = J c + g with nudot != 0, no force
   at near fixels; Mnu scratch (3).  1 or 0.  */
static int
check_balance(wc_check_scratch * X, mpq_t * Mnu)
{
    const wc_check_stability * S = X->S;
    wc_check_text * why = X->why;
    mpq_t * nu = S->nudot;
    size_t i;
    int j;

    if (!X->closed && _wc_check_qvec_is_zero(nu, 3))
    {
        _wc_check_put(why, "the motion has nudot = 0");
        return 0;
    }
    for (j = 0; j < 3; j++)
        mpq_set(X->s[j], S->g[j]);
    for (i = 0; i < S->P.n; i++)
    {
        if (!check_near_unloaded(X, "the motion loads", S->motion_c, i))
            return 0;
        add_forces(X, S->motion_c, i);
    }
    mpq_mul(Mnu[0], S->P.body[0], nu[0]);
    mpq_mul(Mnu[1], S->P.body[0], nu[1]);
    mpq_mul(Mnu[2], S->P.body[1], nu[2]);
    if (!_wc_check_qvec_equal(Mnu, X->s, 3))
    {
        _wc_check_put(why, "the motion has M nudot = ");
        _wc_check_put_qvec(why, Mnu, 3);
        _wc_check_put(why, ", but J c + g = ");
        _wc_check_put_qvec(why, X->s, 3);
        return 0;
    }
    return 1;
}

/* "the motion's letter l at fixel 1 needs " */
static void
motion_needs(wc_check_text * why, char l, size_t i)
{
    _wc_check_putf(why, "the motion's letter %c at fixel %lu needs ", l,
                   (unsigned long) i + 1);
}

/* The forces of the motion at a touching fixel i with letter l (not s)
   obey its friction law.  1 or 0.  */
static int
check_friction(wc_check_scratch * X, size_t i, char l,
               const fixel_names * N)
{
    const wc_check_stability * S = X->S;
    wc_check_text * why = X->why;
    mpq_t * cn = S->motion_c + i, * ct = S->motion_c + S->P.n + i;
    mpq_t * mu = S->P.fixel + 6 * i + 4;

    if (mpq_sgn(*cn) < 0)
    {
        motion_needs(why, l, i);
        _wc_check_putf(why, "%s >= 0, but %s = ", N->cn, N->cn);
        _wc_check_put_q(why, *cn);
        return 0;
    }
    if (l == 'n')
    {
        mpq_mul(X->a, mu[0], *cn);
        mpq_abs(X->b, *ct);
        if (mpq_cmp(X->b, X->a) <= 0)
            return 1;
        motion_needs(why, l, i);
        _wc_check_putf(why, "|%s| <= mu_s %s = ", N->ct, N->cn);
        _wc_check_put_q(why, X->a);
    }
    else
    {
        /* l: c_it = -mu_k c_in; r: c_it = mu_k c_in */
        mpq_mul(X->a, mu[1], *cn);
        if (l == 'l')
            mpq_neg(X->a, X->a);
        if (mpq_equal(*ct, X->a))
            return 1;
        motion_needs(why, l, i);
        _wc_check_putf(why, "%s = %smu_k %s = ", N->ct, l == 'l' ? "-" : "",
                       N->cn);
        _wc_check_put_q(why, X->a);
    }
    _wc_check_putf(why, ", but %s = ", N->ct);
    _wc_check_put_q(why, *ct);
    return 0;
}

/* The letter of the motion's sign at the touching fixel i holds.  1 or
   0.  */
static int
check_letter(wc_check_scratch * X, size_t i)
{
    const wc_check_stability * S = X->S;
    wc_check_text * why = X->why;
    mpq_t * cn = S->motion_c + i, * ct = S->motion_c + S->P.n + i;
    char l = S->motion_sign->text[i];
    fixel_names N;
    int sn, st;

    names_of(&N, i);
    _wc_check_qdot3(X->a, X->J + 6 * i, S->nudot, X->t);
    _wc_check_qdot3(X->b, X->J + 6 * i + 3, S->nudot, X->t);
    sn = mpq_sgn(X->a);
    st = mpq_sgn(X->b);
    if (l == 's' ? sn < 0 || (sn == 0 && !X->closed) : sn != 0)
    {
        motion_needs(why, l, i);
        _wc_check_putf(why, "%s %s 0, but %s = ", N.an, l != 's' ? "="
                       : X->closed ? ">=" : ">", N.an);
        _wc_check_put_q(why, X->a);
        return 0;
    }
    if (l == 's')
    {
        if (mpq_sgn(*cn) == 0 && mpq_sgn(*ct) == 0)
            return 1;
        motion_needs(why, l, i);
        _wc_check_putf(why, "no force, but %s = ", N.cn);
        _wc_check_put_q(why, *cn);
        _wc_check_putf(why, ", %s = ", N.ct);
        _wc_check_put_q(why, *ct);
        return 0;
    }
    if (l == 'l' ? st < 0 || (st == 0 && !X->closed)
        : l == 'r' ? st > 0 || (st == 0 && !X->closed) : st != 0)
    {
        motion_needs(why, l, i);
        _wc_check_putf(why, "%s %s%s 0, but %s = ", N.at,
                       l == 'l' ? ">" : l == 'r' ? "<" : "=",
                       l != 'n' && X->closed ? "=" : "", N.at);
        _wc_check_put_q(why, X->b);
        return 0;
    }
    return check_friction(X, i, l, &N);
}

/* On a rotation face: rho v . nudot > 0 (>= 0 for the closure), v =
   J_1n x J_1t of the first touching fixel.  1 or 0.  */
static int
check_turn(wc_check_scratch * X, mpq_t * v)
{
    const wc_check_stability * S = X->S;
    size_t i;

    for (i = 0; i < S->P.n && S->P.near[i]; i++)
        ;
    if (X->rotation == 0 || i == S->P.n)
        return 1;
    _wc_check_qcross3(v, X->J + 6 * i, X->J + 6 * i + 3, X->t);
    _wc_check_qdot3(X->a, v, S->nudot, X->t);
    if (X->rotation < 0)
        mpq_neg(X->a, X->a);
    if (mpq_sgn(X->a) > 0 || (X->closed && mpq_sgn(X->a) == 0))
        return 1;
    _wc_check_putf(X->why, "the motion needs rotation %d: rho v . nudot %s "
                   "0, but it is ", X->rotation, X->closed ? ">=" : ">");
    _wc_check_put_q(X->why, X->a);
    return 0;
}

int
_wc_check_motion(wc_check_scratch * X)
{
    mpq_t Mnu[3];
    size_t i;
    int j, holds;

    for (j = 0; j < 3; j++)
        mpq_init(Mnu[j]);
    holds = check_balance(X, Mnu);
    for (i = 0; holds == 1 && i < X->S->P.n; i++)
        if (!X->S->P.near[i])
            holds = check_letter(X, i);
    if (holds == 1)
        holds = check_turn(X, Mnu);
    for (j = 0; j < 3; j++)
        mpq_clear(Mnu[j]);
    return holds;
}

/* What the certificate claims, into what.  */
static void
stability_summary(wc_check_text * what, const wc_check_stability * S)
{
    _wc_check_put(what, "wrench ");
    _wc_check_put_qvec(what, S->g, 3);
    if (S->strong)
        _wc_check_putf(what, " is strongly stable: %lu moving face%s "
                       "excluded", (unsigned long) S->nfaces,
                       S->nfaces == 1 ? "" : "s");
    else if (S->weak)
        _wc_check_putf(what, " is weakly stable but moves in mode %s",
                       S->motion_sign->text);
    else
        _wc_check_put(what, " is not weakly stable");
}

/* Decide whether the strong-stability certificate S (read without error)
   holds; when it does not, write why into why.  what receives what it
   claims.  Returns 1 or 0; -1 when out of memory.  */
static int
check_stability(wc_check_text * why, wc_check_text * what,
                const wc_check_stability * S)
{
    wc_check_scratch X;
    int holds = -1;

    if (!_wc_check_scratch_init(&X, S, why))
        goto cleanup;
    stability_summary(what, S);
    holds = S->weak ? _wc_check_static(&X) : check_separator(&X);
    if (holds == 1 && S->strong && !S->weak)
    {
        _wc_check_put(why, "strongly_stable is true but weakly_stable is "
                      "false");
        holds = 0;
    }
    if (holds == 1 && S->weak && !S->strong)
        holds = _wc_check_motion(&X);
    if (holds == 1 && S->strong)
        holds = _wc_check_faces(&X);
cleanup:
    if (why->oom || what->oom)
        holds = -1;
    _wc_check_scratch_clear(&X);
    return holds;
}

int
_wc_check_stability_certificate(wc_check_reader * c,
                                const wc_json_node * root, int * holds,
                                wc_check_text * why, wc_check_text * what)
{
    wc_check_stability S;
    int h;

    _wc_check_stability_init(&S);
    _wc_check_read_stability(&S, c, root);
    if (c->status == WC_OK)
    {
        h = check_stability(why, what, &S);
        if (h < 0)
            _wc_check_nomem(c);
        else
            *holds = h;
    }
    _wc_check_stability_clear(&S);
    return c->status;
}
