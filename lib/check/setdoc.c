/* setdoc.c -- reading a certificate of a set (stability-set, plan-goal):
   everything but the claimed set itself (setread.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Everything is read in full before any of it is checked, so that a
   malformed file is told apart from a false claim; the checks then read
   each leaf, motion and multiplier list again, into storage of one.  */

#include <stdlib.h>
#include <string.h>

#include "check/setcheck.h"
#include "check/verify.h"

void
_wc_check_set_init(wc_check_set * K)
{
    memset(K, 0, sizeof *K);
    _wc_check_stability_init(&K->S);
}

void
_wc_check_set_clear(wc_check_set * K)
{
    size_t n2 = 2 * K->S.P.n, k;

    _wc_check_qvec_free(K->leaf.sep, 3);
    _wc_check_qvec_free(K->G, 3);
    _wc_check_qvec_free(K->mult, K->multcap);
    _wc_check_qvec_free(K->stat, n2);
    _wc_check_qvec_free(K->F, 3 * K->fcap);
    _wc_check_zvec_free(K->H, 3 * K->nplanes);
    _wc_check_claim_clear(&K->claim);
    for (k = 0; K->mc != NULL && k < K->S.nfaces; k++)
        _wc_check_piece_clear(K->mc + k);
    free(K->mc);
    /* the vectors S->g and S->weak_c point into K, not S's own */
    K->S.g = K->S.weak_c = NULL;
    _wc_check_stability_clear(&K->S);
}

/* ------------------------------------------------------------------ */
/* Reading.                                                            */

static int
read_planes(wc_check_reader * c, wc_check_set * K, const wc_json_node * root)
{
    const wc_json_node * a;
    size_t k;
    int j;
    mpq_t q;

    if (_wc_check_member(c, root, "planes", WC_CHECK_ARRAY, &a) != WC_OK)
        return WC_EINPUT;
    if (a->len > WC_CERT_MAX_PLANES)
        return _wc_check_bad(c, a, "a certificate lists at most %d planes",
                             WC_CERT_MAX_PLANES);
    K->H = _wc_check_zvec_new(_wc_check_times(3, a->len));
    if (K->H == NULL)
        return _wc_check_nomem(c);
    K->nplanes = a->len;
    mpq_init(q);
    for (k = 0; k < a->len && c->status == WC_OK; k++)
    {
        const wc_json_node * v = a->items + k;

        if (v->type != WC_JSON_ARRAY || v->len != 3)
            _wc_check_bad(c, v, "expected an array of 3 integers");
        for (j = 0; j < 3 && c->status == WC_OK; j++)
            if (_wc_check_rational(c, v->items + j, q) == WC_OK)
            {
                if (mpz_cmp_ui(mpq_denref(q), 1) != 0)
                    _wc_check_bad(c, v->items + j, "a plane's entries are "
                                  "integers");
                mpz_set(K->H[3 * k + j], mpq_numref(q));
            }
    }
    mpq_clear(q);
    return c->status;
}

/* The motion object at v: nudot and c into S's scratch.  */
int
_wc_check_set_read_motion(wc_check_reader * c, wc_check_set * K, const wc_json_node * v)
{
    if (_wc_check_want_object(c, v) != WC_OK
        || _wc_check_vector(c, v, "nudot", K->S.nudot, 3) != WC_OK)
        return WC_EINPUT;
    return _wc_check_vector(c, v, "c", K->S.motion_c, 2 * K->S.P.n);
}

/* The multipliers at v (an array of rationals) into K->mult.  */
int
_wc_check_set_read_mult(wc_check_reader * c, wc_check_set * K, const wc_json_node * v)
{
    size_t k;

    if (v->type != WC_JSON_ARRAY)
        return _wc_check_bad(c, v, "expected an array of multipliers");
    if (v->len > K->multcap)
    {
        _wc_check_qvec_free(K->mult, K->multcap);
        K->multcap = 0;
        if ((K->mult = _wc_check_qvec_new(v->len)) == NULL)
            return _wc_check_nomem(c);
        K->multcap = v->len;
    }
    K->nmult = v->len;
    for (k = 0; k < v->len; k++)
        if (_wc_check_rational(c, v->items + k, K->mult[k]) != WC_OK)
            return WC_EINPUT;
    return WC_OK;
}

/* The proofs of the pieces: one object per piece, with static (an array
   of force vectors) and faces (one entry per face: null, or an array of
   multiplier lists).  */
static int
read_proofs(wc_check_reader * c, wc_check_set * K, const wc_json_node * root)
{
    size_t k, f, j;

    if (_wc_check_member(c, root, "proofs", WC_CHECK_ARRAY, &K->proofs)
        != WC_OK)
        return WC_EINPUT;
    if (K->proofs->len != K->claim.npieces)
        return _wc_check_bad(c, K->proofs, "'proofs' needs one entry per "
                             "piece of the claim (%lu)",
                             (unsigned long) K->claim.npieces);
    for (k = 0; k < K->proofs->len && c->status == WC_OK; k++)
    {
        const wc_json_node * o = K->proofs->items + k, * st = NULL, * fa;
        const wc_check_piece * Q = K->claim.pc + k;

        if (_wc_check_want_object(c, o) != WC_OK
            || (!K->plan && _wc_check_member(c, o, "static", WC_CHECK_ARRAY,
                                             &st) != WC_OK)
            || _wc_check_member(c, o, "faces", WC_CHECK_ARRAY, &fa) != WC_OK)
            break;
        if (st != NULL && st->len != Q->nrays + 2 * Q->nlines)
            return _wc_check_bad(c, st, "'static' needs one force vector "
                                 "per ray and two per line (%lu)",
                                 (unsigned long) (Q->nrays + 2 * Q->nlines));
        if (fa->len != Q->nfaces)
            return _wc_check_bad(c, fa, "'faces' needs one entry per face "
                                 "of the piece (%lu)",
                                 (unsigned long) Q->nfaces);
        for (j = 0; st != NULL && j < st->len && c->status == WC_OK; j++)
            if (_wc_check_set_read_mult(c, K, st->items + j) == WC_OK
                && K->nmult != 2 * K->S.P.n)
                return _wc_check_bad(c, st->items + j, "static forces have "
                                     "2 n = %lu entries",
                                     (unsigned long) (2 * K->S.P.n));
        for (f = 0; f < fa->len && c->status == WC_OK; f++)
        {
            const wc_json_node * m = fa->items + f;

            if (m->type == WC_JSON_NULL)
                continue;
            if (m->type != WC_JSON_ARRAY)
                return _wc_check_bad(c, m, "a face's proof is null or an "
                                     "array of multiplier lists");
            for (j = 0; j < m->len && c->status == WC_OK; j++)
                _wc_check_set_read_mult(c, K, m->items + j);
        }
    }
    return c->status;
}

/* The cone of each moving face or plan string, with its motions: closure
   (one per generator) and, for a moving face, motions (one per face: null
   or a motion).  */
static int
read_moving(wc_check_reader * c, wc_check_set * K, const wc_json_node * root)
{
    size_t k, j;

    K->moving = _wc_json_object_get(root, K->plan ? "strings"
                                    : "moving_faces");
    K->mc = _wc_check_alloc(K->S.nfaces + 1, sizeof(wc_check_piece));
    if (K->mc == NULL)
        return _wc_check_nomem(c);
    memset(K->mc, 0, (K->S.nfaces > 0 ? K->S.nfaces : 1)
           * sizeof(wc_check_piece));
    for (k = 0; k < K->S.nfaces && c->status == WC_OK; k++)
    {
        const wc_json_node * o = K->moving->items + k, * cone, * cl;
        const wc_json_node * mo = NULL;
        wc_check_piece * Q = K->mc + k;

        if (_wc_check_member(c, o, "cone", WC_CHECK_OBJECT, &cone) != WC_OK
            || _wc_check_read_piece(c, Q, cone) != WC_OK
            || _wc_check_member(c, o, "closure", WC_CHECK_ARRAY, &cl)
            != WC_OK
            || (!K->plan && _wc_check_member(c, o, "motions",
                                             WC_CHECK_ARRAY, &mo) != WC_OK))
            break;
        if (cl->len != Q->nrays + 2 * Q->nlines)
            return _wc_check_bad(c, cl, "'closure' needs one motion per ray "
                                 "and two per line of the cone (%lu)",
                                 (unsigned long) (Q->nrays + 2 * Q->nlines));
        if (mo != NULL && mo->len != Q->nfaces)
            return _wc_check_bad(c, mo, "'motions' needs one entry per face "
                                 "of the cone (%lu)",
                                 (unsigned long) Q->nfaces);
        for (j = 0; j < cl->len && c->status == WC_OK; j++)
            _wc_check_set_read_motion(c, K, cl->items + j);
        for (j = 0; mo != NULL && j < mo->len && c->status == WC_OK; j++)
            if (mo->items[j].type != WC_JSON_NULL)
                _wc_check_set_read_motion(c, K, mo->items + j);
    }
    return c->status;
}

/* The set a certificate covers: "strong" (stability) or "goal" (plan).  */
static const char *
claim_key(const wc_check_set * K)
{
    return K->plan ? "goal" : "strong";
}

static int
read_covers(wc_check_reader * c, wc_check_set * K, const wc_json_node * root)
{
    const wc_json_node * a;

    if (_wc_check_member(c, root, "covers", WC_CHECK_ARRAY, &a) != WC_OK)
        return WC_EINPUT;
    if (a->len != 1 || a->items[0].type != WC_JSON_STRING
        || strcmp(a->items[0].text, claim_key(K)) != 0)
        return _wc_check_bad(c, a, "'covers' must be [\"%s\"]",
                             claim_key(K));
    return WC_OK;
}

/* The strings of a plan into K->S.faces (their letters checked with the
   claim, plansys.c).  */
static int
read_strings(wc_check_reader * c, wc_check_set * K, const wc_json_node * root)
{
    const wc_json_node * a;
    size_t k;

    if (_wc_check_member(c, root, "strings", WC_CHECK_ARRAY, &a) != WC_OK)
        return WC_EINPUT;
    K->S.faces = _wc_check_alloc(a->len + 1, sizeof(wc_check_face));
    if (K->S.faces == NULL)
        return _wc_check_nomem(c);
    memset(K->S.faces, 0, (a->len + 1) * sizeof(wc_check_face));
    K->S.nfaces = a->len;
    for (k = 0; k < a->len; k++)
        if (_wc_check_want_object(c, a->items + k) != WC_OK
            || _wc_check_member(c, a->items + k, "string", WC_CHECK_STRING,
                                &K->S.faces[k].sign) != WC_OK)
            return WC_EINPUT;
    return WC_OK;
}

int
_wc_check_set_read(wc_check_reader * c, wc_check_set * K, const wc_json_node * root)
{
    size_t n2;

    if (_wc_check_read_problem(&K->S.P, c, root, 1) != WC_OK
        || read_covers(c, K, root) != WC_OK
        || _wc_check_read_claim(c, &K->claim, root, claim_key(K)) != WC_OK
        || read_planes(c, K, root) != WC_OK)
        return c->status;
    n2 = 2 * K->S.P.n;
    K->G = _wc_check_qvec_new(3);
    K->stat = _wc_check_qvec_new(n2);
    K->leaf.sep = _wc_check_qvec_new(3);
    K->S.nudot = _wc_check_qvec_new(3);
    K->S.motion_c = _wc_check_qvec_new(n2);
    K->S.nmc = n2;
    if (K->G == NULL || K->stat == NULL || K->leaf.sep == NULL
        || K->S.nudot == NULL || K->S.motion_c == NULL)
        return _wc_check_nomem(c);
    if (K->plan)
        read_strings(c, K, root);
    else
    {
        _wc_check_read_faces(c, &K->S, root, "moving_faces", 0);
        if (c->status == WC_OK)
            _wc_check_signs(c, &K->S);
    }
    if (c->status != WC_OK || read_moving(c, K, root) != WC_OK
        || _wc_check_member(c, root, "tree", WC_CHECK_ARRAY, &K->tree)
        != WC_OK)
        return c->status;
    if (read_proofs(c, K, root) != WC_OK)
        return c->status;
    return _wc_check_tree_read(c, K);
}

