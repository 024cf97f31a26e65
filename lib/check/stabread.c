/* stabread.c -- reading a strong-stability certificate (wrenchcone(1), stability): the
   problem, the wrench, the weak claim, the motion or the faces.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdlib.h>
#include <string.h>

#include "check/stabcheck.h"

void
_wc_check_stability_init(wc_check_stability * S)
{
    memset(S, 0, sizeof *S);
    _wc_check_problem_init(&S->P);
    S->weak = -1;
    S->strong = -1;
}

void
_wc_check_stability_clear(wc_check_stability * S)
{
    size_t k;

    _wc_check_problem_clear(&S->P);
    _wc_check_qvec_free(S->g, 3);
    _wc_check_qvec_free(S->weak_c, S->nwc);
    _wc_check_qvec_free(S->sep, 3);
    _wc_check_qvec_free(S->nudot, 3);
    _wc_check_qvec_free(S->motion_c, S->nmc);
    if (S->faces != NULL)
        for (k = 0; k < S->nfaces; k++)
            _wc_check_qvec_free(S->faces[k].mult, S->faces[k].nmult);
    free(S->faces);
    _wc_check_stability_init(S);
}

/* The entries of 2 n forces: 2 n when n is known.  */
static size_t
forces_length(const wc_check_stability * S)
{
    return S->P.n > 0 ? _wc_check_times(2, S->P.n) : WC_CHECK_ANY_LENGTH;
}

/* v into *q, when it is a new vector of 3 rationals; errors into c.  */
static void
read_vector3(wc_check_reader * c, const wc_json_node * o, const char * key,
             mpq_t ** q)
{
    *q = _wc_check_qvec_new(3);
    if (*q == NULL)
        _wc_check_nomem(c);
    else
        _wc_check_vector(c, o, key, *q, 3);
}

static void
read_motion(wc_check_reader * c, wc_check_stability * S,
            const wc_json_node * root)
{
    const wc_json_node * o, * sign;

    if (_wc_check_member(c, root, "motion", WC_CHECK_OBJECT, &o) != WC_OK)
        return;
    if (_wc_check_member(c, o, "sign", WC_CHECK_STRING, &sign) == WC_OK)
        S->motion_sign = sign;
    read_vector3(c, o, "nudot", &S->nudot);
    if (c->status != WC_EINTERNAL)
        _wc_check_qarray(c, o, "c", forces_length(S), &S->motion_c,
                         &S->nmc);
}

/* The face at f into F, with its multipliers when mult.  */
static int
read_face(wc_check_reader * c, wc_check_face * F, const wc_json_node * f,
          int mult)
{
    const wc_json_node * v;
    int status = _wc_check_want_object(c, f);

    if (status != WC_OK)
        return status;
    if (_wc_check_member(c, f, "sign", WC_CHECK_STRING, &v) == WC_OK)
        F->sign = v;
    else
        status = WC_EINPUT;
    v = _wc_json_object_get(f, "rotation");
    if (v != NULL)
    {
        mpq_t r;

        mpq_init(r);
        F->rot_node = v;
        if (_wc_check_rational(c, v, r) != WC_OK)
            status = WC_EINPUT;
        else if (mpz_cmp_ui(mpq_denref(r), 1) != 0
                 || mpz_cmpabs_ui(mpq_numref(r), 1) != 0)
            status = _wc_check_bad(c, v, "'rotation' must be 1 or -1");
        else
            F->rotation = mpq_sgn(r);
        mpq_clear(r);
    }
    if (mult && _wc_check_qarray(c, f, "multipliers", WC_CHECK_ANY_LENGTH,
                                 &F->mult, &F->nmult) != WC_OK)
        status = WC_EINPUT;
    return status;
}

void
_wc_check_read_faces(wc_check_reader * c, wc_check_stability * S,
                     const wc_json_node * root, const char * key, int mult)
{
    const wc_json_node * a;
    size_t k;

    if (_wc_check_member(c, root, key, WC_CHECK_ARRAY, &a) != WC_OK)
        return;
    S->faces = _wc_check_alloc(a->len, sizeof(wc_check_face));
    if (S->faces == NULL)
    {
        _wc_check_nomem(c);
        return;
    }
    if (a->len > 0)
        memset(S->faces, 0, a->len * sizeof(wc_check_face));
    S->nfaces = a->len;
    /* a later face is later in the file */
    for (k = 0; k < a->len; k++)
        if (read_face(c, S->faces + k, a->items + k, mult) != WC_OK)
            return;
}

/* The weak claim's object: static forces or a separator.  */
static void
read_weak(wc_check_reader * c, wc_check_stability * S,
          const wc_json_node * root)
{
    const wc_json_node * w;

    if (_wc_check_member(c, root, "weak", WC_CHECK_OBJECT, &w) != WC_OK)
        return;
    if (S->weak)
        _wc_check_qarray(c, w, "c", forces_length(S), &S->weak_c, &S->nwc);
    else
        read_vector3(c, w, "separator", &S->sep);
}

void
_wc_check_signs(wc_check_reader * c, const wc_check_stability * S)
{
    size_t k;

    if (S->motion_sign != NULL)
        _wc_check_letters(c, S->motion_sign, &S->P, 1);
    for (k = 0; k < S->nfaces; k++)
    {
        const wc_check_face * F = S->faces + k;

        if (F->sign == NULL)
            break;
        _wc_check_letters(c, F->sign, &S->P, 1);
        if (F->rot_node != NULL && F->rotation != 0
            && strspn(F->sign->text, "nu") != F->sign->len)
            _wc_check_bad(c, F->rot_node,
                          "a rotation face has the sign n..n");
    }
}

void
_wc_check_read_stability(wc_check_stability * S, wc_check_reader * c,
                         const wc_json_node * root)
{
    const wc_json_node * v;

    _wc_check_read_problem(&S->P, c, root, 1);
    if (c->status == WC_EINTERNAL)
        return;
    read_vector3(c, root, "wrench", &S->g);
    if (c->status == WC_EINTERNAL)
        return;
    if (_wc_check_member(c, root, "weakly_stable", WC_CHECK_BOOL, &v)
        == WC_OK)
        S->weak = v->type == WC_JSON_TRUE;
    if (_wc_check_member(c, root, "strongly_stable", WC_CHECK_BOOL, &v)
        == WC_OK)
        S->strong = v->type == WC_JSON_TRUE;
    if (S->weak >= 0)
        read_weak(c, S, root);
    if (c->status == WC_EINTERNAL)
        return;
    if (S->weak == 1 && S->strong == 0)
        read_motion(c, S, root);
    if (c->status == WC_EINTERNAL)
        return;
    if (S->strong == 1)
        _wc_check_read_faces(c, S, root, "faces", 1);
    if (c->status == WC_EINTERNAL)
        return;
    _wc_check_signs(c, S);
}
