/* settree.c -- the completeness half of a set certificate: a tree of
   cuts that splits R^3 into regions, each with its reason.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The tree is listed in preorder.  Its first entry {"basis": [i, j, k]}
   names three independent planes, which cut R^3 into the 27 relatively
   open faces of a simplicial fan; 27 subtrees follow, one per face in the
   order of region.c.  A subtree is null (its region is empty), a cut
   {"split": p} followed by three subtrees (the region's parts with
   h_p . x < 0, = 0, > 0), or a leaf.  Each region is a relatively open
   cone, computed here from the planes alone, so the leaves partition R^3
   whatever the certificate says; a null for a region that is not empty,
   or a node for one that is, fails, and so does a cut by a plane that
   leaves the region on one side (so a path cuts by each plane at most
   once, and a region has at most planes + 3 rays).  The rays of the
   regions cut, and rays times constraints at the leaves, may come to
   WC_CHECK_TREE_WORK in all; a larger tree is refused.

   A leaf says where its region R lies, over the extreme rays r_1 .. r_k
   of its closure and their sum s, a point of R:
   - in face F of a piece of the claim, or of the cone of a moving face or
     plan string: every r_j in the closure of F (on each inequality of the
     cone, tight on the inequalities tight on F) and s in F itself (strict
     on the others).  R is then inside the relatively open F.
   - not weakly stable: y . r_j >= 0, y . s > 0 and y separates the weak
     cone.  */

#include <stdlib.h>
#include <string.h>

#include "check/region.h"
#include "check/setcheck.h"

/* ------------------------------------------------------------------ */
/* Reading.                                                            */

/* An index below limit at x (named key), into *i.  */
static int
index_at(wc_check_reader * c, const wc_json_node * x, const char * key,
         size_t limit, size_t * i)
{
    mpq_t q;
    int bad;

    mpq_init(q);
    bad = _wc_check_rational(c, x, q) != WC_OK;
    if (!bad && (mpz_cmp_ui(mpq_denref(q), 1) != 0 || mpq_sgn(q) < 0
                 || mpz_cmp_ui(mpq_numref(q), limit) >= 0))
        bad = _wc_check_bad(c, x, "'%s' must be an integer from 0 to %ld",
                            key, (long) limit - 1) != WC_OK;
    if (!bad)
        *i = mpz_get_ui(mpq_numref(q));
    mpq_clear(q);
    return bad ? WC_EINPUT : WC_OK;
}

/* An index below limit at o[key], into *i.  */
static int
read_index(wc_check_reader * c, const wc_json_node * o, const char * key,
           size_t limit, size_t * i)
{
    const wc_json_node * x = _wc_json_object_get(o, key);

    if (x == NULL)
        return _wc_check_bad(c, o, "missing key '%s'", key);
    return index_at(c, x, key, limit, i);
}

int
_wc_check_set_read_leaf(wc_check_reader * c, wc_check_set * K,
                        const wc_json_node * v)
{
    wc_check_leaf * L = &K->leaf;
    const wc_json_node * x;
    const wc_check_piece * Q;

    if (_wc_check_want_object(c, v) != WC_OK
        || _wc_check_member(c, v, "in", WC_CHECK_BOOL, &x) != WC_OK)
        return WC_EINPUT;
    L->in = x->type == WC_JSON_TRUE;
    L->has_sep = !L->in && !K->plan
        && _wc_json_object_get(v, "separator") != NULL;
    if (L->has_sep)
        return _wc_check_vector(c, v, "separator", L->sep, 3);
    if (read_index(c, v, L->in ? "piece" : K->plan ? "string" : "face",
                   L->in ? K->claim.npieces : K->S.nfaces, &L->owner)
        != WC_OK)
        return WC_EINPUT;
    Q = L->in ? K->claim.pc + L->owner : K->mc + L->owner;
    if (Q->nfaces == 0)
        return _wc_check_bad(c, v, "a leaf names an empty cone");
    return read_index(c, v, L->in ? "piece_face" : "cone_face", Q->nfaces,
                      &L->face);
}

/* A cut {"split": p}: 1, with p; 0 when v is not one.  */
static int
is_split(wc_check_reader * c, const wc_check_set * K,
         const wc_json_node * v, size_t * p)
{
    if (v->type != WC_JSON_OBJECT || _wc_json_object_get(v, "split") == NULL)
        return 0;
    return read_index(c, v, "split", K->nplanes, p) == WC_OK;
}

int
_wc_check_tree_read(wc_check_reader * c, wc_check_set * K)
{
    const wc_json_node * t = K->tree, * b;
    size_t k, p;

    if (t->len == 0 || t->items[0].type != WC_JSON_OBJECT)
        return _wc_check_bad(c, t, "the tree starts with {\"basis\": [i, j, "
                             "k]}");
    if (_wc_check_member(c, t->items, "basis", WC_CHECK_ARRAY, &b) != WC_OK)
        return WC_EINPUT;
    if (b->len != 3)
        return _wc_check_bad(c, b, "a basis names three planes");
    for (k = 0; k < 3; k++)
        if (index_at(c, b->items + k, "basis", K->nplanes, K->basis + k)
            != WC_OK)
            return WC_EINPUT;
    for (k = 1; k < t->len && c->status == WC_OK; k++)
    {
        const wc_json_node * v = t->items + k;

        if (v->type == WC_JSON_NULL || is_split(c, K, v, &p))
            continue;
        if (c->status == WC_OK && _wc_check_set_read_leaf(c, K, v) == WC_OK)
            K->leaves++;
    }
    return c->status;
}

/* ------------------------------------------------------------------ */
/* The leaves.                                                         */

/* "tree entry 12 (a region of dim 2, rays (1, 0, 0), (0, 1, 0)): " */
static size_t
mark(wc_check_text * why, size_t entry, const wc_check_region * R)
{
    size_t at = why->len, i;

    _wc_check_putf(why, "tree entry %lu (a region of dim %d", (unsigned long)
                   entry + 1, R->dim);
    for (i = 0; i < R->n; i++)
    {
        _wc_check_put(why, i == 0 ? ", rays " : ", ");
        _wc_check_put_zvec(why, R->r + 3 * i, 3);
    }
    _wc_check_put(why, "): ");
    return at;
}

/* s := the sum of R's rays.  */
static void
ray_sum(mpz_t * s, const wc_check_region * R)
{
    size_t i;
    int j;

    for (j = 0; j < 3; j++)
        mpz_set_ui(s[j], 0);
    for (i = 0; i < R->n; i++)
        for (j = 0; j < 3; j++)
            mpz_add(s[j], s[j], R->r[3 * i + j]);
}

/* The leaf puts R in face f of Q: the rays in its closure, their sum s
   in the face.  1 or 0.  */
static int
in_face(wc_check_text * why, const wc_check_piece * Q, size_t f,
        const wc_check_region * R, mpz_t * s, mpz_t d)
{
    const unsigned char * tight = Q->tight + f * Q->nineq;
    size_t i, a;

    for (i = 0; i <= R->n; i++)
    {
        mpz_t * x = i < R->n ? R->r + 3 * i : s;

        for (a = 0; a < Q->nineq + Q->neq; a++)
        {
            int eq = a >= Q->nineq, sg;

            _wc_check_zdot3(d, eq ? Q->zeq + 3 * (a - Q->nineq)
                            : Q->zineq + 3 * a, x);
            sg = mpz_sgn(d);
            if (eq || tight[a] ? sg == 0 : i < R->n ? sg <= 0 : sg < 0)
                continue;
            _wc_check_put(why, i < R->n ? "its ray " : "the sum of its "
                          "rays ");
            _wc_check_put_zvec(why, x, 3);
            _wc_check_putf(why, " is %s %s %lu of the cone", i < R->n
                           && !eq && !tight[a] ? "outside" : "off",
                           eq ? "equality" : "inequality", (unsigned long)
                           (eq ? a - Q->nineq : a) + 1);
            if (!eq && tight[a])
                _wc_check_put(why, ", tight on the face");
            return 0;
        }
    }
    return 1;
}

/* Check the leaf read into K->leaf on the region R.  1, 0 or -1.  */
static int
check_leaf(wc_check_scratch * X, wc_check_set * K, size_t entry,
           const wc_check_region * R)
{
    const wc_check_leaf * L = &K->leaf;
    mpz_t * s = _wc_check_zvec_new(3), * y = _wc_check_zvec_new(3), d;
    size_t at = mark(X->why, entry, R), i;
    int holds = 1;

    mpz_init(d);
    if (s == NULL || y == NULL)
        holds = -1;
    else
        ray_sum(s, R);
    if (holds == 1 && L->has_sep)
    {
        _wc_check_primitive(y, L->sep, d);
        for (i = 0; i <= R->n && holds == 1; i++)
        {
            _wc_check_zdot3(d, y, i < R->n ? R->r + 3 * i : s);
            if (i < R->n ? mpz_sgn(d) >= 0 : mpz_sgn(d) > 0)
                continue;
            _wc_check_put(X->why, "the separator y = ");
            _wc_check_put_qvec(X->why, L->sep, 3);
            _wc_check_put(X->why, i < R->n ? " has y . r < 0 at its ray "
                          : " has y . (the sum of its rays) <= 0: ");
            _wc_check_put_zvec(X->why, i < R->n ? R->r + 3 * i : s, 3);
            holds = 0;
        }
        if (holds == 1)
            holds = _wc_check_separates(X, L->sep);
    }
    else if (holds == 1)
    {
        const wc_check_piece * Q = L->in ? K->claim.pc + L->owner
            : K->mc + L->owner;

        _wc_check_putf(X->why, "in face %lu of %s %lu: ",
                       (unsigned long) L->face + 1, L->in ? "piece" : K->plan
                       ? "the cone of string" : "the cone of moving face",
                       (unsigned long) L->owner + 1);
        K->work += (R->n + 1) * (Q->nineq + Q->neq);
        if (K->work > WC_CHECK_TREE_WORK)
        {
            K->too_big = 1;
            holds = 0;
        }
        else if (!Q->fincl[L->face])
        {
            _wc_check_put(X->why, "the cone does not include that face");
            holds = 0;
        }
        else
            holds = in_face(X->why, Q, L->face, R, s, d);
    }
    _wc_check_unmark(X->why, at, holds);
    mpz_clear(d);
    _wc_check_zvec_free(s, 3);
    _wc_check_zvec_free(y, 3);
    return holds;
}

/* ------------------------------------------------------------------ */
/* The walk.                                                           */

/* The regions waiting for their subtrees below one node.  */
typedef struct
{
    wc_check_region ch[27];
    int n, next;
}
frame;

/* Room for one more frame on the stack st (depth d, room *cap).  */
static frame *
push_frame(frame ** st, size_t d, size_t * cap)
{
    size_t k;
    int i;

    if (d == *cap)
    {
        size_t cap2 = *cap < 8 ? 8 : 2 * *cap;
        frame * s = realloc(*st, _wc_check_times(cap2, sizeof(frame)));

        if (s == NULL)
            return NULL;
        for (k = *cap; k < cap2; k++)
            for (i = 0; i < 27; i++)
                _wc_check_region_init(s[k].ch + i);
        *st = s;
        *cap = cap2;
    }
    return *st + d;
}

/* The node at entry e for the region R (empty: dim -1).  Returns 1 (a
   leaf that holds, or a cut pushed as frame *d, for which st has room),
   0, or -1.  */
static int
visit(wc_check_scratch * X, wc_check_set * K, size_t e,
      const wc_check_region * R, frame * st, size_t * d)
{
    const wc_json_node * v = K->tree->items + e;
    wc_check_reader quiet = { NULL, NULL, WC_OK };
    wc_error_t err;
    frame * F;
    size_t p;
    int ok;

    if ((v->type == WC_JSON_NULL) != (R->dim < 0))
    {
        mark(X->why, e, R);
        _wc_check_put(X->why, R->dim < 0 ? "the region is empty, but the "
                      "tree has a node for it" : "the tree has null for "
                      "this region, which is not empty");
        return 0;
    }
    if (R->dim < 0)
        return 1;
    wc_error_init(err);
    quiet.err = err;
    if (is_split(&quiet, K, v, &p))
    {
        F = st + *d;
        K->work += R->n + 1;
        if (K->work > WC_CHECK_TREE_WORK)
        {
            K->too_big = 1;
            ok = 0;
        }
        else
            ok = _wc_check_region_split(F->ch, R, K->H + 3 * p);
        if (ok == 1 && (F->ch[0].dim >= 0) + (F->ch[1].dim >= 0)
            + (F->ch[2].dim >= 0) < 2)
        {
            /* so no plane cuts twice on a path: depth <= planes */
            mark(X->why, e, R);
            _wc_check_putf(X->why, "plane %lu does not cut the region",
                           (unsigned long) p + 1);
            ok = 0;
        }
        if (ok == 1)
        {
            F->n = 3;
            F->next = 0;
            ++*d;
        }
    }
    else if (_wc_check_set_read_leaf(&quiet, K, v) != WC_OK)
        ok = -1;
    else
        ok = check_leaf(X, K, e, R);
    wc_error_clear(err);
    return ok;
}

int
_wc_check_tree_walk(wc_check_scratch * X, wc_check_set * K)
{
    frame * st = NULL, * F;
    mpz_t * h = _wc_check_zvec_new(9);
    size_t d = 0, cap = 0, e = 1, k;
    int holds = -1, i, j;

    if (h != NULL && push_frame(&st, 0, &cap) != NULL)
    {
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++)
                mpz_set(h[3 * i + j], K->H[3 * K->basis[i] + j]);
        holds = _wc_check_region_basis(st->ch, h);
    }
    _wc_check_zvec_free(h, 9);
    if (holds == 0)
        _wc_check_put(X->why, "the tree's basis planes are dependent");
    if (holds == 1)
    {
        st->n = 27;
        st->next = 0;
        d = 1;
    }
    while (holds == 1 && d > 0)
    {
        if (push_frame(&st, d, &cap) == NULL)
        {
            holds = -1;
            break;
        }
        F = st + d - 1;

        if (F->next == F->n)
        {
            d--;
            continue;
        }
        if (e == K->tree->len)
        {
            _wc_check_put(X->why, "the tree ends before every region has "
                          "its node");
            holds = 0;
            break;
        }
        holds = visit(X, K, e, F->ch + F->next++, st, &d);
        e++;
    }
    if (holds == 1 && e != K->tree->len)
    {
        _wc_check_putf(X->why, "the tree has %lu entries after its last "
                       "region", (unsigned long) (K->tree->len - e));
        holds = 0;
    }
    for (k = 0; k < cap; k++)
        for (i = 0; i < 27; i++)
            _wc_check_region_clear(st[k].ch + i);
    free(st);
    return holds;
}
