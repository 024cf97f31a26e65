/* critcheck.c -- checking a critical-friction certificate: the bracket
   [lo, hi] of the friction at which a plan's goal set becomes empty.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   With mu_s = mu_k = mu at every fixel, every cone of a plan grows with mu
   (its friction edges widen), so G_goal shrinks as mu grows.  The lower
   end is proved by one wrench of G_goal at mu = lo: for every string with
   one s, Motzkin multipliers showing the wrench is not in its cone
   (plansys.c); the upper end by a plan-goal certificate at mu = hi whose
   goal set is empty (setcheck.c), checked against the problem with its
   friction set to hi.  */

#include <stdlib.h>
#include <string.h>

#include "check/setcheck.h"
#include "check/critcheck.h"

typedef struct
{
    wc_check_stability S;       /* the problem at lo, the lower strings */
    wc_check_problem top;       /* the problem as the certificate gives it */
    int found, at_zero;
    mpq_t lo, hi;
    mpq_t * g;                  /* 3: the witness */
    const wc_json_node * lower, * upper, * strings;
}
crit_check;

/* Q := P with mu_s = mu_k = mu at every fixel.  0 when out of memory.  */
static int
at_friction(wc_check_problem * Q, const wc_check_problem * P, mpq_t mu)
{
    size_t i;

    Q->n = P->n;
    Q->body = _wc_check_qvec_new(4);
    Q->fixel = _wc_check_qvec_new(_wc_check_times(6, P->n));
    Q->near = _wc_check_alloc(P->n, sizeof(int));
    if (Q->body == NULL || Q->fixel == NULL || Q->near == NULL)
        return 0;
    for (i = 0; i < 4; i++)
        mpq_set(Q->body[i], P->body[i]);
    for (i = 0; i < 6 * P->n; i++)
        mpq_set(Q->fixel[i], i % 6 >= 4 ? mu : P->fixel[i]);
    memcpy(Q->near, P->near, P->n * sizeof(int));
    return 1;
}

/* The rational o[key] into q, or null when nullable; 1 when a number.  */
static int
read_end(wc_check_reader * c, const wc_json_node * o, const char * key,
         mpq_t q, int nullable)
{
    const wc_json_node * v = _wc_json_object_get(o, key);

    if (v != NULL && v->type == WC_JSON_NULL && nullable)
        return 0;
    if (_wc_check_scalar(c, o, key, q, 0) != WC_OK)
        return 0;
    return 1;
}

static int
read_crit(wc_check_reader * c, crit_check * K, const wc_json_node * root)
{
    const wc_json_node * v;
    size_t k;

    if (_wc_check_read_problem(&K->top, c, root, 1) != WC_OK
        || _wc_check_member(c, root, "found", WC_CHECK_BOOL, &v) != WC_OK)
        return c->status;
    K->found = v->type == WC_JSON_TRUE;
    if (_wc_check_member(c, root, "empty_at_zero", WC_CHECK_BOOL, &v)
        != WC_OK)
        return c->status;
    K->at_zero = v->type == WC_JSON_TRUE;
    if (K->at_zero && !K->found)
        return _wc_check_bad(c, v, "'empty_at_zero' needs 'found' true: the "
                             "empty goal set at 0 is proved at hi = 0");
    read_end(c, root, "lo", K->lo, 0);
    if (read_end(c, root, "hi", K->hi, 1) != K->found && c->status == WC_OK)
        return _wc_check_bad(c, root, "'hi' is a number exactly when "
                             "'found' is true");
    K->lower = _wc_json_object_get(root, "lower");
    K->upper = _wc_json_object_get(root, "upper");
    if (c->status != WC_OK)
        return c->status;
    if (K->lower == NULL || K->upper == NULL)
        return _wc_check_bad(c, root, "missing key '%s'", K->lower == NULL
                             ? "lower" : "upper");
    if ((K->lower->type == WC_JSON_NULL) != K->at_zero)
        return _wc_check_bad(c, K->lower, "'lower' is null exactly when "
                             "'empty_at_zero' is true");
    if ((K->upper->type == WC_JSON_NULL) == K->found)
        return _wc_check_bad(c, K->upper, "'upper' is null exactly when "
                             "'found' is false");
    if (K->upper->type != WC_JSON_NULL
        && _wc_check_want_object(c, K->upper) != WC_OK)
        return c->status;
    if (K->at_zero)
        return WC_OK;
    if (_wc_check_want_object(c, K->lower) != WC_OK
        || (K->g = _wc_check_qvec_new(3)) == NULL
        || _wc_check_vector(c, K->lower, "wrench", K->g, 3) != WC_OK
        || _wc_check_member(c, K->lower, "strings", WC_CHECK_ARRAY,
                            &K->strings) != WC_OK)
        return c->status != WC_OK ? c->status : _wc_check_nomem(c);
    K->S.faces = _wc_check_alloc(K->strings->len + 1, sizeof(wc_check_face));
    if (K->S.faces == NULL)
        return _wc_check_nomem(c);
    memset(K->S.faces, 0, (K->strings->len + 1) * sizeof(wc_check_face));
    K->S.nfaces = K->strings->len;
    for (k = 0; k < K->strings->len && c->status == WC_OK; k++)
    {
        wc_check_face * F = K->S.faces + k;
        const wc_json_node * o = K->strings->items + k;

        if (_wc_check_want_object(c, o) == WC_OK
            && _wc_check_member(c, o, "string", WC_CHECK_STRING, &F->sign)
            == WC_OK)
            _wc_check_qarray(c, o, "multipliers", WC_CHECK_ANY_LENGTH,
                             &F->mult, &F->nmult);
    }
    return c->status;
}

/* The lower end: the witness in the cone of no string.  1, 0 or -1.  */
static int
check_lower(wc_check_text * why, crit_check * K)
{
    wc_check_scratch X;
    size_t k;
    int holds = -1;

    if (!at_friction(&K->S.P, &K->top, K->lo)
        || !_wc_check_scratch_init(&X, &K->S, why))
        return -1;
    X.G = K->g;
    X.ng = 1;
    holds = _wc_check_plan_strings(why, &K->S);
    for (k = 0; holds == 1 && k < K->S.nfaces; k++)
        holds = _wc_check_plan_face(&X, k, K->S.faces[k].sign->text,
                                    K->S.faces[k].mult, K->S.faces[k].nmult);
    _wc_check_scratch_clear(&X);
    return holds;
}

/* The upper certificate states the problem at friction hi.  1, 0, -1.  */
static int
check_upper_problem(wc_check_reader * c, wc_check_text * why, crit_check * K)
{
    wc_check_problem U, H;
    size_t i;
    int holds = 1;

    _wc_check_problem_init(&U);
    _wc_check_problem_init(&H);
    if (_wc_check_read_problem(&U, c, K->upper, 1) != WC_OK)
        holds = 0;
    else if (!at_friction(&H, &K->top, K->hi))
        holds = -1;
    else if (U.n != H.n)
        holds = 0;
    for (i = 0; holds == 1 && i < 4; i++)
        holds = mpq_equal(U.body[i], H.body[i]) != 0;
    for (i = 0; holds == 1 && i < 6 * H.n; i++)
        holds = mpq_equal(U.fixel[i], H.fixel[i]) != 0;
    if (holds == 0)
    {
        _wc_check_put(why, "the certificate at hi = ");
        _wc_check_put_q(why, K->hi);
        _wc_check_put(why, " is not about the problem with mu_s = mu_k = hi "
                      "at every fixel");
    }
    _wc_check_problem_clear(&U);
    _wc_check_problem_clear(&H);
    return holds;
}

/* The upper end: a plan-goal certificate at hi with an empty goal set
   that holds.  1, 0 or -1 (c->status set when it is malformed).  */
static int
check_upper(wc_check_reader * c, wc_check_text * why, crit_check * K)
{
    wc_check_text sub = { NULL, 0, 0, 0 }, claim = { NULL, 0, 0, 0 };
    const wc_json_node * goal, * e;
    wc_check_kind kind;
    int h = 0;

    if (_wc_check_kind(c, K->upper, &kind) != WC_OK)
        return 0;
    if (kind != WC_CHECK_PLAN)
        return _wc_check_bad(c, K->upper, "'upper' is a plan-goal "
                             "certificate"), 0;
    h = check_upper_problem(c, why, K);
    goal = _wc_json_object_get(K->upper, "goal");
    e = goal != NULL ? _wc_json_object_get(goal, "empty") : NULL;
    if (h == 1 && e != NULL && e->type != WC_JSON_TRUE)
    {
        _wc_check_put(why, "the certificate at hi does not claim an empty "
                      "goal set");
        h = 0;
    }
    if (h == 1 && _wc_check_set_certificate(c, K->upper, 1, &h, &sub,
                                            &claim) == WC_OK && h == 0)
    {
        _wc_check_put(why, "at mu = hi: ");
        _wc_check_put(why, sub.s != NULL ? sub.s : "");
    }
    if (sub.oom || claim.oom)
        h = -1;
    free(sub.s);
    free(claim.s);
    return c->status == WC_OK ? h : 0;
}

static void
crit_summary(wc_check_text * what, const crit_check * K)
{
    if (K->at_zero)
        _wc_check_put(what, "G_goal is empty at mu = 0, so at every mu");
    else if (!K->found)
    {
        _wc_check_put(what, "G_goal is nonempty at every mu <= ");
        _wc_check_put_q(what, K->lo);
    }
    else
    {
        _wc_check_put(what, "the critical friction lies in [");
        _wc_check_put_q(what, K->lo);
        _wc_check_put(what, ", ");
        _wc_check_put_q(what, K->hi);
        _wc_check_put(what, "]: G_goal is nonempty at mu = lo and empty at "
                      "mu = hi");
    }
}

int
_wc_check_crit_certificate(wc_check_reader * c, const wc_json_node * root,
                           int * holds, wc_check_text * why,
                           wc_check_text * what)
{
    crit_check K;
    int h = 1;

    memset(&K, 0, sizeof K);
    _wc_check_stability_init(&K.S);
    _wc_check_problem_init(&K.top);
    mpq_init(K.lo);
    mpq_init(K.hi);
    if (read_crit(c, &K, root) != WC_OK)
        goto cleanup;
    crit_summary(what, &K);
    if (K.found && (K.at_zero ? mpq_sgn(K.lo) != 0 || mpq_sgn(K.hi) != 0
                    : mpq_cmp(K.lo, K.hi) >= 0))
    {
        _wc_check_put(why, K.at_zero ? "empty at zero needs lo = hi = 0"
                      : "lo is not below hi");
        h = 0;
    }
    if (h == 1 && !K.at_zero)
        h = check_lower(why, &K);
    if (h == 1 && K.found)
        h = check_upper(c, why, &K);
    if (c->status == WC_OK && h < 0)
        _wc_check_nomem(c);
    else if (c->status == WC_OK)
        *holds = h;
cleanup:
    _wc_check_qvec_free(K.g, 3);
    mpq_clear(K.lo);
    mpq_clear(K.hi);
    _wc_check_problem_clear(&K.top);
    _wc_check_stability_clear(&K.S);
    return c->status;
}
