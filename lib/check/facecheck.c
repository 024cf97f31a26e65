/* facecheck.c -- the faces claim of a strong-stability certificate: the
   faces listed are exactly the moving faces, and each has Motzkin
   multipliers showing it has no motion (the system of
   wrenchcone-certificate(5)).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdlib.h>
#include <string.h>

#include "check/faces.h"
#include "check/stabcheck.h"

/* "face 3 (ls)" or "face 3 (n, rotation -1)" */
static void
put_face(wc_check_text * b, size_t k, const char * sign, int rotation)
{
    char * shown = _wc_show(sign, strlen(sign));

    if (shown == NULL)
    {
        b->oom = 1;
        return;
    }
    _wc_check_putf(b, "face %lu (%s", (unsigned long) k + 1, shown);
    if (rotation != 0)
        _wc_check_putf(b, ", rotation %d", rotation);
    _wc_check_put(b, ")");
    free(shown);
}

/* The system of one face: e friction edges w (3 e), rows rows with
   relations rel, d unknowns (nudot, lambda, alpha) and s = sum_k y_k
   row_k (d); alpha has one entry per wrench X->G (tau for one wrench).  */
typedef struct
{
    size_t e, rows, d;
    size_t first;       /* the first touching fixel */
    mpq_t * w;
    mpq_t * s;
    wc_check_rel * rel;
}
face_system;

/* The letter of face F at fixel i: n everywhere on a rotation face.  */
static char
face_letter(const wc_check_face * F, size_t i)
{
    return F->rotation != 0 ? 'n' : F->sign->text[i];
}

/* The sizes of the system of F.  */
static void
face_sizes(face_system * Y, const wc_check_problem * P,
           const wc_check_face * F, size_t ng)
{
    size_t i;

    Y->e = 0;
    Y->rows = 3;
    Y->first = P->n;
    for (i = 0; i < P->n; i++)
    {
        char l = face_letter(F, i);

        if (P->near[i])
            continue;
        if (Y->first == P->n)
            Y->first = i;
        Y->e += l == 'n' ? 2 : l == 's' ? 0 : 1;
        Y->rows += l == 's' ? 1 : 2;
    }
    if (F->rotation != 0)
        Y->rows += 1;
    Y->rows += Y->e + ng;
    Y->d = 3 + Y->e + ng;
}

/* The friction edges (1, et), in fixel order: w_j = J_in + et J_it, with
   n: (1, -mu_s) then (1, +mu_s); l: (1, -mu_k); r: (1, +mu_k).  */
static void
face_edges(face_system * Y, wc_check_scratch * X, const wc_check_face * F)
{
    const wc_check_problem * P = &X->S->P;
    size_t i, j = 0;
    int c;

    for (i = 0; i < P->n; i++)
    {
        mpq_t * mu = P->fixel + 6 * i + 4, * Ji = X->J + 6 * i;
        char l = face_letter(F, i);
        int m, ne = l == 'n' ? 2 : l == 's' ? 0 : 1;

        if (P->near[i])
            continue;
        for (m = 0; m < ne; m++, j++)
        {
            mpq_set(X->a, mu[l == 'n' ? 0 : 1]);
            if (l == 'l' || (l == 'n' && m == 0))
                mpq_neg(X->a, X->a);
            for (c = 0; c < 3; c++)
            {
                mpq_mul(Y->w[3 * j + c], X->a, Ji[3 + c]);
                mpq_add(Y->w[3 * j + c], Y->w[3 * j + c], Ji[c]);
            }
        }
    }
}

/* The rows on nudot of the touching fixels, from row r on, multiplied by
   y and summed into s: s: J_in > ; l: J_in =, J_it > ; r: J_in =,
   -J_it > ; n: J_in =, J_it =.  Returns the next row.  */
static size_t
face_contact_rows(face_system * Y, wc_check_scratch * X,
                  const wc_check_face * F, mpq_t * y, size_t r)
{
    const wc_check_problem * P = &X->S->P;
    size_t i;
    int c;

    for (i = 0; i < P->n; i++)
    {
        mpq_t * Ji = X->J + 6 * i;
        char l = face_letter(F, i);

        if (P->near[i])
            continue;
        Y->rel[r] = l == 's' ? WC_CHECK_GT : WC_CHECK_EQ;
        for (c = 0; c < 3; c++)
            _wc_check_qaddmul(Y->s[c], y[r], Ji[c], X->t);
        r++;
        if (l == 's')
            continue;
        Y->rel[r] = l == 'n' ? WC_CHECK_EQ : WC_CHECK_GT;
        for (c = 0; c < 3; c++)
        {
            mpq_mul(X->t, y[r], Ji[3 + c]);
            if (l == 'r')
                mpq_sub(Y->s[c], Y->s[c], X->t);
            else
                mpq_add(Y->s[c], Y->s[c], X->t);
        }
        r++;
    }
    return r;
}

/* Every row of the system of F, multiplied by its multiplier y and
   summed into s, with its relation into rel.  */
static void
face_rows(face_system * Y, wc_check_scratch * X, const wc_check_face * F,
          mpq_t * y)
{
    const wc_check_stability * S = X->S;
    size_t r, j;
    int c;

    /* M nudot - sum_j lambda_j w_j - sum_i alpha_i G_i = 0 */
    for (c = 0; c < 3; c++)
    {
        Y->rel[c] = WC_CHECK_EQ;
        _wc_check_qaddmul(Y->s[c], y[c], S->P.body[c < 2 ? 0 : 1], X->t);
        for (j = 0; j < Y->e; j++)
        {
            mpq_mul(X->t, y[c], Y->w[3 * j + c]);
            mpq_sub(Y->s[3 + j], Y->s[3 + j], X->t);
        }
        for (j = 0; j < X->ng; j++)
        {
            mpq_mul(X->t, y[c], X->G[3 * j + c]);
            mpq_sub(Y->s[3 + Y->e + j], Y->s[3 + Y->e + j], X->t);
        }
    }
    r = face_contact_rows(Y, X, F, y, 3);
    if (F->rotation != 0)
    {
        /* (rho v) . nudot > 0, v = J_1n x J_1t of the first touching
           fixel; X->s holds v */
        mpq_t * J1 = X->J + 6 * Y->first;

        Y->rel[r] = WC_CHECK_GT;
        _wc_check_qcross3(X->s, J1, J1 + 3, X->t);
        for (c = 0; c < 3; c++)
        {
            if (F->rotation < 0)
                mpq_neg(X->s[c], X->s[c]);
            _wc_check_qaddmul(Y->s[c], y[r], X->s[c], X->t);
        }
        r++;
    }
    /* lambda_j >= 0, alpha_i > 0 */
    for (j = 0; j < Y->e; j++, r++)
    {
        Y->rel[r] = WC_CHECK_GE;
        mpq_add(Y->s[3 + j], Y->s[3 + j], y[r]);
    }
    for (j = 0; j < X->ng; j++, r++)
    {
        Y->rel[r] = WC_CHECK_GT;
        mpq_add(Y->s[3 + Y->e + j], Y->s[3 + Y->e + j], y[r]);
    }
}

int
_wc_check_face(wc_check_scratch * X, size_t k, const wc_check_face * F)
{
    wc_check_text * why = X->why, prefix = { NULL, 0, 0, 0 };
    face_system Y;
    int holds = -1;

    face_sizes(&Y, &X->S->P, F, X->ng);
    Y.w = _wc_check_qvec_new(_wc_check_times(3, Y.e));
    Y.s = _wc_check_qvec_new(Y.d);
    Y.rel = _wc_check_alloc(Y.rows, sizeof(wc_check_rel));
    put_face(&prefix, k, F->sign->text, F->rotation);
    _wc_check_put(&prefix, ": ");
    if (Y.w == NULL || Y.s == NULL || Y.rel == NULL || prefix.oom)
        goto cleanup;
    holds = _wc_check_motzkin_count(why, prefix.s, "row", F->nmult, Y.rows);
    if (holds == 1)
    {
        face_edges(&Y, X, F);
        face_rows(&Y, X, F, F->mult);
        holds = _wc_check_motzkin(why, prefix.s, "row", Y.rel, F->mult,
                                  Y.rows, Y.s, Y.d);
    }
cleanup:
    _wc_check_qvec_free(Y.w, 3 * Y.e);
    _wc_check_qvec_free(Y.s, Y.d);
    free(Y.rel);
    free(prefix.s);
    if (why->oom)
        holds = -1;
    return holds;
}

/* 1 when every touching fixel has the point of the first one (and there
   is one).  */
static int
shared_point(const wc_check_problem * P)
{
    size_t i, first = P->n;

    for (i = 0; i < P->n; i++)
    {
        mpq_t * p = P->fixel + 6 * i;

        if (P->near[i])
            continue;
        if (first == P->n)
            first = i;
        else if (!mpq_equal(p[0], P->fixel[6 * first])
                 || !mpq_equal(p[1], P->fixel[6 * first + 1]))
            return 0;
    }
    return first < P->n;
}

/* Each listed face is a moving face (a rotation face only when the
   touching fixels share a point), listed once; seen[at] and rot_seen
   record which face listed it (1-based).  1 or 0.  */
static int
check_listed(wc_check_scratch * X, const wc_check_strings * T,
             size_t * seen, size_t * rot_seen, int shared)
{
    const wc_check_stability * S = X->S;
    wc_check_text * why = X->why;
    size_t k;

    for (k = 0; k < S->nfaces; k++)
    {
        const wc_check_face * F = S->faces + k;
        const char * sign = F->sign->text;
        size_t * mark;
        long at;

        if (F->rotation != 0 && !shared)
        {
            put_face(why, k, sign, F->rotation);
            _wc_check_put(why, " is not a moving face: the touching fixels "
                          "do not share one point");
            return 0;
        }
        at = F->rotation != 0 ? 0 : _wc_check_strings_find(T, sign);
        if (at < 0)
        {
            put_face(why, k, sign, 0);
            _wc_check_put(why, " is not a moving face of the problem");
            return 0;
        }
        mark = F->rotation > 0 ? rot_seen : F->rotation < 0 ? rot_seen + 1
            : seen + at;
        if (*mark != 0)
        {
            put_face(why, k, sign, F->rotation);
            _wc_check_putf(why, " repeats face %lu", (unsigned long) *mark);
            return 0;
        }
        *mark = k + 1;
    }
    return 1;
}

/* No moving face is left out: seen and rot_seen as check_listed left
   them.  1 or 0; -1 when out of memory.  */
static int
check_complete(wc_check_scratch * X, const wc_check_strings * T,
               const size_t * seen, const size_t * rot_seen, int shared)
{
    const wc_check_problem * P = &X->S->P;
    size_t k, i;
    char * nn;

    for (k = 0; k < T->count; k++)
        if (seen[k] == 0)
        {
            _wc_check_putf(X->why, "the faces omit the moving face %s",
                           T->s[k]);
            return 0;
        }
    for (k = 0; shared && k < 2; k++)
        if (rot_seen[k] == 0)
        {
            nn = malloc(P->n + 1);
            if (nn == NULL)
                return -1;
            for (i = 0; i < P->n; i++)
                nn[i] = P->near[i] ? 'u' : 'n';
            nn[P->n] = '\0';
            _wc_check_putf(X->why, "the faces omit the moving face %s, "
                           "rotation %d", nn, k == 0 ? 1 : -1);
            free(nn);
            return 0;
        }
    return 1;
}

int
_wc_check_faces(wc_check_scratch * X)
{
    size_t k;
    int holds = _wc_check_face_list(X);

    for (k = 0; holds == 1 && k < X->S->nfaces; k++)
        holds = _wc_check_face(X, k, X->S->faces + k);
    return holds;
}

int
_wc_check_face_list(wc_check_scratch * X)
{
    const wc_check_stability * S = X->S;
    wc_check_strings T = { 0, 0, NULL, 0, 0 };
    size_t * seen = NULL, rot_seen[2] = { 0, 0 }, k;
    int shared = shared_point(&S->P), holds = -1;

    if (_wc_check_moving_faces(&T, &S->P, X->J) != WC_OK)
        goto cleanup;
    seen = _wc_check_alloc(T.count, sizeof(size_t));
    if (seen == NULL)
        goto cleanup;
    for (k = 0; k < T.count; k++)
        seen[k] = 0;
    holds = check_listed(X, &T, seen, rot_seen, shared);
    if (holds == 1)
        holds = check_complete(X, &T, seen, rot_seen, shared);
cleanup:
    free(seen);
    _wc_check_strings_clear(&T);
    if (X->why->oom)
        holds = -1;
    return holds;
}
