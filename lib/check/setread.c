/* setread.c -- the claimed set of a stability-set certificate: its
   pieces, read and checked for consistency.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A piece is a convex cone written as wrenchcone stability --format=json
   writes it: the closure C = {x : a . x <= 0 (inequalities), e . x = 0
   (equalities)}, its rays and lines, and its faces, each with the rays it
   holds and whether the piece includes its relative interior.  What the
   certificate proves is read from the generators: the set is the union of
   the included faces, each the relatively open cone of its rays and the
   piece's lines.  The constraints are checked against them (every ray in
   C, every line on every constraint, as many lines as C's lineality space
   has dimensions), and so are the stated dimensions.  */

#include <stdlib.h>
#include <string.h>

#include "check/setcheck.h"

void
_wc_check_piece_clear(wc_check_piece * Q)
{
    _wc_check_qvec_free(Q->ineq, 3 * Q->nineq);
    _wc_check_qvec_free(Q->eq, 3 * Q->neq);
    _wc_check_qvec_free(Q->rays, 3 * Q->nrays);
    _wc_check_qvec_free(Q->lines, 3 * Q->nlines);
    free(Q->foff);
    free(Q->fray);
    free(Q->fincl);
    free(Q->fdim);
    _wc_check_zvec_free(Q->zineq, 3 * Q->nineq);
    _wc_check_zvec_free(Q->zeq, 3 * Q->neq);
    free(Q->tight);
}

void
_wc_check_claim_clear(wc_check_claim * C)
{
    size_t k;

    if (C->pc != NULL)
        for (k = 0; k < C->npieces; k++)
            _wc_check_piece_clear(C->pc + k);
    free(C->pc);
    memset(C, 0, sizeof *C);
}

/* o[key]: an array of vectors of 3 rationals, into *q (*n of them).  */
static int
read_vectors(wc_check_reader * c, const wc_json_node * o, const char * key,
             mpq_t ** q, size_t * n)
{
    const wc_json_node * a;
    size_t k;
    int j;

    if (_wc_check_member(c, o, key, WC_CHECK_ARRAY, &a) != WC_OK)
        return WC_EINPUT;
    *q = _wc_check_qvec_new(_wc_check_times(3, a->len));
    if (*q == NULL)
        return _wc_check_nomem(c);
    *n = a->len;
    for (k = 0; k < a->len; k++)
    {
        const wc_json_node * v = a->items + k;

        if (v->type != WC_JSON_ARRAY || v->len != 3)
            return _wc_check_bad(c, v, "expected an array of 3 numbers");
        for (j = 0; j < 3; j++)
            if (_wc_check_rational(c, v->items + j, (*q)[3 * k + j])
                != WC_OK)
                return WC_EINPUT;
    }
    return WC_OK;
}

/* A non-negative integer below limit at v, into *i.  */
static int
read_index(wc_check_reader * c, const wc_json_node * v, size_t limit,
           size_t * i, const char * what)
{
    mpq_t q;
    int status = WC_OK;

    mpq_init(q);
    if (_wc_check_rational(c, v, q) != WC_OK)
        status = WC_EINPUT;
    else if (mpz_cmp_ui(mpq_denref(q), 1) != 0 || mpq_sgn(q) < 0
             || mpz_cmp_ui(mpq_numref(q), limit) >= 0)
        status = _wc_check_bad(c, v, "%s must be an integer from 0 to %lu",
                               what, (unsigned long) limit - 1);
    else
        *i = mpz_get_ui(mpq_numref(q));
    mpq_clear(q);
    return status;
}

/* o[key], a dimension 0 .. 3, into *d.  */
static int
read_dim(wc_check_reader * c, const wc_json_node * o, const char * key,
         long * d)
{
    const wc_json_node * v = _wc_json_object_get(o, key);
    size_t i = 0;

    if (v == NULL)
        return _wc_check_bad(c, o, "missing key '%s'", key);
    if (read_index(c, v, 4, &i, key) != WC_OK)
        return WC_EINPUT;
    *d = (long) i;
    return WC_OK;
}

/* The faces of Q from the array a.  */
static int
read_piece_faces(wc_check_reader * c, wc_check_piece * Q,
                 const wc_json_node * a)
{
    size_t f, k, total = 0, at = 0;

    for (f = 0; f < a->len; f++)
    {
        const wc_json_node * r;

        if (_wc_check_want_object(c, a->items + f) != WC_OK
            || _wc_check_member(c, a->items + f, "rays", WC_CHECK_ARRAY, &r)
            != WC_OK)
            return WC_EINPUT;
        total += r->len;
    }
    Q->nfaces = a->len;
    Q->foff = _wc_check_alloc(a->len + 1, sizeof(size_t));
    Q->fray = _wc_check_alloc(total, sizeof(size_t));
    Q->fincl = _wc_check_alloc(a->len, sizeof(int));
    Q->fdim = _wc_check_alloc(a->len, sizeof(long));
    if (Q->foff == NULL || Q->fray == NULL || Q->fincl == NULL
        || Q->fdim == NULL)
        return _wc_check_nomem(c);
    for (f = 0; f < a->len; f++)
    {
        const wc_json_node * o = a->items + f, * r, * inc;

        Q->foff[f] = at;
        _wc_check_member(c, o, "rays", WC_CHECK_ARRAY, &r);
        for (k = 0; k < r->len; k++)
            if (read_index(c, r->items + k, Q->nrays, Q->fray + at++,
                           "a face's ray") != WC_OK)
                return WC_EINPUT;
        if (_wc_check_member(c, o, "included", WC_CHECK_BOOL, &inc)
            != WC_OK || read_dim(c, o, "dim", Q->fdim + f) != WC_OK)
            return WC_EINPUT;
        Q->fincl[f] = inc->type == WC_JSON_TRUE;
    }
    Q->foff[a->len] = at;
    return WC_OK;
}

int
_wc_check_read_piece(wc_check_reader * c, wc_check_piece * Q,
                     const wc_json_node * o)
{
    const wc_json_node * a, * e;

    Q->at = o;
    if (_wc_check_want_object(c, o) != WC_OK
        || _wc_check_member(c, o, "empty", WC_CHECK_BOOL, &e) != WC_OK
        || read_dim(c, o, "dim", &Q->dim) != WC_OK
        || read_dim(c, o, "lineality_dim", &Q->lin) != WC_OK
        || read_vectors(c, o, "inequalities", &Q->ineq, &Q->nineq) != WC_OK
        || read_vectors(c, o, "equalities", &Q->eq, &Q->neq) != WC_OK
        || read_vectors(c, o, "rays", &Q->rays, &Q->nrays) != WC_OK
        || read_vectors(c, o, "lines", &Q->lines, &Q->nlines) != WC_OK
        || _wc_check_member(c, o, "faces", WC_CHECK_ARRAY, &a) != WC_OK)
        return c->status;
    if (e->type == WC_JSON_TRUE)
        return _wc_check_bad(c, e, "a piece of a set is never empty");
    return read_piece_faces(c, Q, a);
}

int
_wc_check_read_claim(wc_check_reader * c, wc_check_claim * C,
                     const wc_json_node * root, const char * key)
{
    const wc_json_node * o, * a, * v;
    size_t k;

    if (_wc_check_member(c, root, key, WC_CHECK_OBJECT, &o) != WC_OK)
        return WC_EINPUT;
    C->at = o;
    if (_wc_check_member(c, o, "empty", WC_CHECK_BOOL, &v) != WC_OK)
        return WC_EINPUT;
    C->empty = v->type == WC_JSON_TRUE;
    if (_wc_check_member(c, o, "interior", WC_CHECK_BOOL, &v) != WC_OK)
        return WC_EINPUT;
    C->interior = v->type == WC_JSON_TRUE;
    if (_wc_check_member(c, o, "pieces", WC_CHECK_ARRAY, &a) != WC_OK)
        return WC_EINPUT;
    C->pc = _wc_check_alloc(a->len + 1, sizeof(wc_check_piece));
    if (C->pc == NULL)
        return _wc_check_nomem(c);
    memset(C->pc, 0, (a->len > 0 ? a->len : 1) * sizeof(wc_check_piece));
    C->npieces = a->len;
    for (k = 0; k < a->len; k++)
        if (_wc_check_read_piece(c, C->pc + k, a->items + k) != WC_OK)
            return c->status;
    return WC_OK;
}

/* ------------------------------------------------------------------ */
/* Consistency.                                                        */

/* The rank of the n vectors v (3 each); w (3), d, t scratch.  */
static int
rank3(mpq_t * v, size_t n, mpq_t * w, mpq_t d, mpq_t t)
{
    size_t i, first = n, second = n;

    for (i = 0; i < n && first == n; i++)
        if (!_wc_check_qvec_is_zero(v + 3 * i, 3))
            first = i;
    if (first == n)
        return 0;
    for (i = first + 1; i < n && second == n; i++)
    {
        _wc_check_qcross3(w, v + 3 * first, v + 3 * i, t);
        if (!_wc_check_qvec_is_zero(w, 3))
            second = i;
    }
    if (second == n)
        return 1;
    _wc_check_qcross3(w, v + 3 * first, v + 3 * second, t);
    for (i = 0; i < n; i++)
    {
        _wc_check_qdot3(d, w, v + 3 * i, t);
        if (mpq_sgn(d) != 0)
            return 3;
    }
    return 2;
}

/* Scratch of the consistency checks.  */
typedef struct
{
    mpq_t * w;          /* 3 */
    mpq_t * v;          /* 3 (the most rays + lines of a face or piece) */
    size_t cap;
    mpq_t d, t;
    mpz_t * z;          /* 3 */
    mpz_t g;
    const char * who;   /* "the claimed set's piece" */
}
claim_scratch;

/* "the claimed set's piece 2 " then the message.  */
#define piece_says(why, k) \
    _wc_check_putf(why, "%s %lu ", X->who, (unsigned long) (k) + 1)

/* Every ray in the closure of piece k, every line on every constraint.
   1 or 0.  */
static int
piece_vectors(wc_check_text * why, claim_scratch * X,
              const wc_check_piece * Q, size_t k)
{
    size_t i, j;

    for (i = 0; i < Q->nrays + Q->nlines; i++)
    {
        int line = i >= Q->nrays;
        mpq_t * r = line ? Q->lines + 3 * (i - Q->nrays) : Q->rays + 3 * i;

        for (j = 0; j < Q->nineq + Q->neq; j++)
        {
            int eq = j >= Q->nineq, sg;

            _wc_check_qdot3(X->d, eq ? Q->eq + 3 * (j - Q->nineq)
                            : Q->ineq + 3 * j, r, X->t);
            sg = mpq_sgn(X->d);
            if (sg > 0 || (sg < 0 && (eq || line)))
            {
                piece_says(why, k);
                _wc_check_putf(why, "has the %s ", line ? "line" : "ray");
                _wc_check_put_qvec(why, r, 3);
                _wc_check_putf(why, " off its %s %lu",
                               eq ? "equality" : "inequality",
                               (unsigned long) (eq ? j - Q->nineq : j) + 1);
                return 0;
            }
        }
        if (_wc_check_qvec_is_zero(r, 3))
        {
            piece_says(why, k);
            _wc_check_putf(why, "has a zero %s", line ? "line" : "ray");
            return 0;
        }
    }
    return 1;
}

/* Copy the vectors a (na) and b (nb; NULL: only make room for them) into
   X->v (grown); NULL when out of memory.  */
static mpq_t *
gather(claim_scratch * X, mpq_t * a, size_t na, mpq_t * b, size_t nb)
{
    size_t i, n = na + nb > 0 ? na + nb : 1;

    if (n > X->cap)
    {
        mpq_t * v = _wc_check_qvec_new(_wc_check_times(3, n));

        if (v == NULL)
            return NULL;
        _wc_check_qvec_free(X->v, 3 * X->cap);
        X->v = v;
        X->cap = n;
    }
    for (i = 0; i < 3 * na; i++)
        mpq_set(X->v[i], a[i]);
    for (i = 0; b != NULL && i < 3 * nb; i++)
        mpq_set(X->v[3 * na + i], b[i]);
    return X->v;
}

/* v[k] := the constraint or generator j of Q: inequalities then
   equalities; rays then lines.  */
static mpq_t *
constraint(const wc_check_piece * Q, size_t j)
{
    return j < Q->nineq ? Q->ineq + 3 * j : Q->eq + 3 * (j - Q->nineq);
}

static mpq_t *
generator(const wc_check_piece * Q, size_t j)
{
    return j < Q->nrays ? Q->rays + 3 * j : Q->lines + 3 * (j - Q->nrays);
}

/* The two descriptions agree (the constraints and generators are each
   valid for the other, checked before): every ray is extreme -- the
   constraints tight on it have rank 2 - lineality_dim -- and every
   inequality is a facet -- the generators on it span dim - 1.  In three
   dimensions this makes each list complete: around the cone, each ray
   lies on two listed facets and each facet holds two listed rays.
   Then each face's rays are exactly the rays on the inequalities tight on
   all of them.  1, 0 or -1.  */
static int
piece_incidence(wc_check_text * why, claim_scratch * X, wc_check_piece * Q,
                size_t k)
{
    size_t i, j, n, m = Q->nineq + Q->neq, g = Q->nrays + Q->nlines, f;
    mpq_t * v;
    int rk;

    if ((v = gather(X, NULL, 0, NULL, m > g ? m : g)) == NULL)
        return -1;
    for (i = 0; i < Q->nrays + Q->nineq; i++)
    {
        int ray = i < Q->nrays;
        mpq_t * x = ray ? Q->rays + 3 * i : Q->ineq + 3 * (i - Q->nrays);

        n = 0;
        for (j = 0; j < (ray ? m : g); j++)
        {
            mpq_t * y = ray ? constraint(Q, j) : generator(Q, j);

            _wc_check_qdot3(X->d, x, y, X->t);
            if (mpq_sgn(X->d) == 0)
                for (f = 0; f < 3; f++)
                    mpq_set(v[3 * n + f], y[f]);
            n += mpq_sgn(X->d) == 0;
        }
        rk = rank3(v, n, X->w, X->d, X->t);
        if (ray ? rk != 2 - Q->lin : rk != Q->dim - 1)
        {
            piece_says(why, k);
            _wc_check_putf(why, "has the %s ", ray ? "ray" : "inequality");
            _wc_check_put_qvec(why, x, 3);
            _wc_check_put(why, ray ? ", which is not an extreme ray of it"
                          : ", which is not a facet of it");
            return 0;
        }
    }
    return 1;
}

/* Face f of Q lists exactly the rays on every inequality that vanishes
   on all of its rays (so it is a face of the closure, and all of it).
   1, 0 or -1.  */
static int
face_rays(wc_check_text * why, claim_scratch * X, const wc_check_piece * Q,
          size_t k, size_t f)
{
    size_t a, r, j;
    unsigned char * tight = Q->tight + f * Q->nineq, * listed;
    int holds = 1;

    listed = malloc(Q->nrays + 1);
    if (listed == NULL)
        holds = -1;
    for (a = 0; holds == 1 && a < Q->nineq; a++)
    {
        tight[a] = 1;
        for (j = Q->foff[f]; j < Q->foff[f + 1] && tight[a]; j++)
        {
            _wc_check_qdot3(X->d, Q->ineq + 3 * a, Q->rays + 3 * Q->fray[j],
                            X->t);
            tight[a] = mpq_sgn(X->d) == 0;
        }
    }
    for (r = 0; holds == 1 && r < Q->nrays; r++)
        listed[r] = 0;
    for (j = Q->foff[f]; holds == 1 && j < Q->foff[f + 1]; j++)
        listed[Q->fray[j]] = 1;
    for (r = 0; holds == 1 && r < Q->nrays; r++)
    {
        int on = 1;

        for (a = 0; a < Q->nineq && on; a++)
            if (tight[a])
            {
                _wc_check_qdot3(X->d, Q->ineq + 3 * a, Q->rays + 3 * r,
                                X->t);
                on = mpq_sgn(X->d) == 0;
            }
        if (on != listed[r])
        {
            piece_says(why, k);
            _wc_check_putf(why, "has face %lu, which %s its ray %lu",
                           (unsigned long) f + 1, on ? "leaves out"
                           : "lists, off the face,", (unsigned long) r + 1);
            holds = 0;
        }
    }
    free(listed);
    return holds;
}

/* The lines span the lineality space of the closure, and the dim and
   lineality_dim of the piece and the dim of each face are as stated.
   1, 0 or -1.  */
static int
piece_spaces(wc_check_text * why, claim_scratch * X, wc_check_piece * Q,
             size_t k)
{
    size_t f, i, r, top = 0;
    mpq_t * v;
    int rk;

    Q->zineq = _wc_check_zvec_new(_wc_check_times(3, Q->nineq));
    Q->zeq = _wc_check_zvec_new(_wc_check_times(3, Q->neq));
    Q->tight = malloc(_wc_check_times(Q->nfaces, Q->nineq) + 1);
    if (Q->zineq == NULL || Q->zeq == NULL || Q->tight == NULL)
        return -1;
    for (i = 0; i < Q->nineq + Q->neq; i++)
        _wc_check_primitive(i < Q->nineq ? Q->zineq + 3 * i
                            : Q->zeq + 3 * (i - Q->nineq),
                            constraint(Q, i), X->g);
    if ((v = gather(X, Q->ineq, Q->nineq, Q->eq, Q->neq)) == NULL)
        return -1;
    rk = rank3(v, Q->nineq + Q->neq, X->w, X->d, X->t);
    if ((v = gather(X, Q->lines, Q->nlines, NULL, 0)) == NULL)
        return -1;
    if ((size_t) (3 - rk) != Q->nlines
        || rank3(v, Q->nlines, X->w, X->d, X->t) != (int) Q->nlines
        || Q->lin != (long) Q->nlines)
    {
        piece_says(why, k);
        _wc_check_putf(why, "has %lu line%s (lineality_dim %ld), but its "
                       "constraints leave a lineality space of dimension %d",
                       (unsigned long) Q->nlines, Q->nlines == 1 ? "" : "s",
                       Q->lin, 3 - rk);
        return 0;
    }
    if ((v = gather(X, Q->rays, Q->nrays, Q->lines, Q->nlines)) == NULL)
        return -1;
    if ((rk = rank3(v, Q->nrays + Q->nlines, X->w, X->d, X->t)) != Q->dim)
    {
        piece_says(why, k);
        _wc_check_putf(why, "has dim %ld, but its rays and lines span %d",
                       Q->dim, rk);
        return 0;
    }
    /* the constraints' cone lies in the rays' span only when the
       equalities cut out a space of that dimension; then the incidences
       below make the two descriptions the same cone */
    if ((v = gather(X, Q->eq, Q->neq, NULL, 0)) == NULL)
        return -1;
    if ((rk = rank3(v, Q->neq, X->w, X->d, X->t)) != 3 - Q->dim)
    {
        piece_says(why, k);
        _wc_check_putf(why, "has dim %ld, but its equalities have rank %d",
                       Q->dim, rk);
        return 0;
    }
    if ((rk = piece_incidence(why, X, Q, k)) != 1)
        return rk;
    for (f = 0; f < Q->nfaces; f++)
    {
        size_t nr = Q->foff[f + 1] - Q->foff[f];

        if ((v = gather(X, Q->lines, Q->nlines, NULL, nr)) == NULL)
            return -1;
        for (r = 0; r < nr; r++)
            for (i = 0; i < 3; i++)
                mpq_set(v[3 * (Q->nlines + r) + i],
                        Q->rays[3 * Q->fray[Q->foff[f] + r] + i]);
        rk = rank3(v, Q->nlines + nr, X->w, X->d, X->t);
        if (rk != Q->fdim[f])
        {
            piece_says(why, k);
            _wc_check_putf(why, "has face %lu of dim %ld, but its rays and "
                           "the lines span %d", (unsigned long) f + 1,
                           Q->fdim[f], rk);
            return 0;
        }
        if ((rk = face_rays(why, X, Q, k, f)) != 1)
            return rk;
        /* a nonempty convex set holds the relative interior of its
           closure: the face of all the rays */
        if (Q->foff[f + 1] - Q->foff[f] == Q->nrays && Q->fdim[f] == Q->dim)
            top = f + 1;
    }
    if (top == 0 || !Q->fincl[top - 1])
    {
        piece_says(why, k);
        _wc_check_put(why, top == 0 ? "lists no face of all its rays"
                      : "does not include the relative interior of its "
                      "closure, as a convex set does");
        return 0;
    }
    return 1;
}

int
_wc_check_cones_valid(wc_check_text * why, wc_check_piece * Q, size_t n,
                      const char * who)
{
    claim_scratch X;
    size_t k;
    int holds = 1;

    memset(&X, 0, sizeof X);
    X.who = who;
    X.w = _wc_check_qvec_new(3);
    X.z = _wc_check_zvec_new(3);
    mpq_init(X.d);
    mpq_init(X.t);
    mpz_init(X.g);
    if (X.w == NULL || X.z == NULL)
        holds = -1;
    for (k = 0; holds == 1 && k < n; k++)
    {
        if (Q[k].nfaces == 0 && Q[k].nrays + Q[k].nlines == 0)
            continue;           /* empty */
        holds = piece_vectors(why, &X, Q + k, k);
        if (holds == 1)
            holds = piece_spaces(why, &X, Q + k, k);
    }
    _wc_check_qvec_free(X.w, 3);
    _wc_check_qvec_free(X.v, 3 * X.cap);
    _wc_check_zvec_free(X.z, 3);
    mpq_clear(X.d);
    mpq_clear(X.t);
    mpz_clear(X.g);
    return holds;
}

int
_wc_check_claim_valid(wc_check_text * why, wc_check_claim * C)
{
    size_t k;
    int holds = 1, interior = 0;

    if (C->empty != (C->npieces == 0))
    {
        _wc_check_putf(why, "the claimed set says empty is %s with %lu "
                       "piece%s", C->empty ? "true" : "false",
                       (unsigned long) C->npieces,
                       C->npieces == 1 ? "" : "s");
        return 0;
    }
    for (k = 0; k < C->npieces; k++)
        if (C->pc[k].nfaces == 0)
        {
            _wc_check_putf(why, "the claimed set's piece %lu is empty",
                           (unsigned long) k + 1);
            return 0;
        }
    holds = _wc_check_cones_valid(why, C->pc, C->npieces,
                                  "the claimed set's piece");
    for (k = 0; k < C->npieces; k++)
        interior |= C->pc[k].dim == 3;
    if (holds == 1 && interior != C->interior)
    {
        _wc_check_putf(why, "the claimed set says interior is %s, but %s "
                       "piece has dimension 3", C->interior ? "true"
                       : "false", interior ? "a" : "no");
        holds = 0;
    }
    return holds;
}
