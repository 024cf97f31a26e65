/* direct3.c -- the direct route's fast path: integer vectors straight
   from the model.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   W(x) = M V_x + pos(-J D_x) (direct.c).  Only directions matter, so
   every row and generator is a primitive integer vector: the column of J
   for a direction d at the point p is (d, r x d) with r = p - com, which
   is linear in d, so a positive integer multiple of d and of r gives a
   positive multiple of the column with one content division at the end,
   and the friction edge n +- mu t is (mu_den n +- mu_num t) up to a
   positive factor.  No fraction is ever reduced.

   V_x = { nudot : E nudot = 0, H nudot <= 0, S nudot < 0 } is settled by
   the rank of E: 3, the origin; 2, a subset of the line through u = the
   cross product of two independent rows (the signs of H u and S u say
   which); 0 with no strict rows, the polar of the fan of H, or the
   normal line of H's plane when H has rank 2 and fills it.  Then W is
   the fan of M V_x's generators and the friction edges, written directly
   in canonical form; when V_x is a ray whose apex is excluded (strict
   rows), a face of W is included iff it contains M times that ray (the
   rule of wc_cone_image_sum).  Without friction edges, any other V_x
   gives W = M V_x from the rows times M^-1 in one general conversion.
   Everything else -- equalities of rank 1 with friction edges, cones the
   fan does not settle -- is left to the general route.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "exact/fan3.h"
#include "exact/cone3.h"
#include "analysis/direct3.h"

/* What V_x is.  */
enum { V_EMPTY, V_ORIGIN, V_RAY, V_LINE, V_POLAR, V_OTHER };

typedef struct
{
    slong n;
    fmpz * jn;          /* 3n: primitive positive multiples of J's n columns */
    fmpz * jt;          /* 3n: the t columns (only where the mode needs them) */
    fmpz * H;           /* 3n: rows h . nudot <= 0 */
    fmpz * S;           /* 3n: rows h . nudot < 0 */
    fmpz * Q;           /* 6n: the friction edges mapped by -J */
    fmpz * G;           /* 3 (2n + 2): generators of W */
    fmpz * U;           /* 3 (2n + 2): the same, sorted and without repeats */
    fmpz * t;           /* 8 entries: scratch, see SCRATCH */
    const fmpz ** E;    /* 2n: the equality rows */
    slong * idx;        /* 2n + 2 */
    slong nh, ns, nq, ne, ng;
    fmpz_t ma, mb;      /* M x is a positive multiple of (ma x0, ma x1, mb x2) */
}
ws_struct;

/* The scratch entry of the helpers below (t[4], t[5] hold an edge).  */
#define SCRATCH(w) ((w)->t + 2)

/* x := x / content(x).  */
static void
primitive(fmpz * x, fmpz_t g)
{
    _fmpz_vec_content(g, x, 3);
    if (!fmpz_is_one(g) && !fmpz_is_zero(g))
        _fmpz_vec_scalar_divexact_fmpz(x, x, 3, g);
}

/* (X0, X1) / D := (a0, a1), D > 0 the lcm of the denominators.  */
static void
common_den(fmpz * X, fmpz_t D, const fmpq * a, fmpz_t g)
{
    if (fmpz_equal(fmpq_denref(a + 0), fmpq_denref(a + 1)))
    {
        fmpz_set(D, fmpq_denref(a + 0));
        fmpz_set(X + 0, fmpq_numref(a + 0));
        fmpz_set(X + 1, fmpq_numref(a + 1));
        return;
    }
    fmpz_lcm(D, fmpq_denref(a + 0), fmpq_denref(a + 1));
    fmpz_divexact(g, D, fmpq_denref(a + 0));
    fmpz_mul(X + 0, fmpq_numref(a + 0), g);
    fmpz_divexact(g, D, fmpq_denref(a + 1));
    fmpz_mul(X + 1, fmpq_numref(a + 1), g);
}

/* c := a positive integer multiple of the column of J for the direction
   D (a positive integer multiple of d) at r = (R0, R1) / R2, R2 > 0;
   primitive when prim is set (equality and strict rows need not be).  */
static void
column(fmpz * c, const fmpz * D, const fmpz * R, fmpz_t g, int prim)
{
    fmpz_mul(c + 0, R + 2, D + 0);
    fmpz_mul(c + 1, R + 2, D + 1);
    fmpz_mul(c + 2, R + 0, D + 1);
    fmpz_submul(c + 2, R + 1, D + 0);
    if (prim)
        primitive(c, g);
}

/* Q gets -column(n + sign mu t) for the normal N (integer).  */
static void
edge(ws_struct * w, const fmpz * N, const fmpq_t mu, int sign,
     const fmpz * R)
{
    fmpz * D = w->t + 4, * c = w->Q + 3 * w->nq++;

    fmpz_mul(D + 0, fmpq_denref(mu), N + 0);
    fmpz_mul(D + 1, fmpq_denref(mu), N + 1);
    if (sign > 0)
    {
        fmpz_submul(D + 0, fmpq_numref(mu), N + 1);
        fmpz_addmul(D + 1, fmpq_numref(mu), N + 0);
    }
    else
    {
        fmpz_addmul(D + 0, fmpq_numref(mu), N + 1);
        fmpz_submul(D + 1, fmpq_numref(mu), N + 0);
    }
    column(c, D, R, SCRATCH(w), 1);
    _fmpz_vec_neg(c, c, 3);
}

/* Append the row x (times sign) to the rows A (count *k).  */
static void
put_row(fmpz * A, slong * k, const fmpz * x, int sign)
{
    if (sign > 0)
        _fmpz_vec_set(A + 3 * *k, x, 3);
    else
        _fmpz_vec_neg(A + 3 * *k, x, 3);
    (*k)++;
}

/* The rows of V_x and the generators -J D_x, fixel by fixel.  */
static void
build(ws_struct * w, const wc_problem_t P, const char * mode)
{
    fmpz * O = _fmpz_vec_init(2), * R = _fmpz_vec_init(3);
    fmpz * N = _fmpz_vec_init(3);
    fmpz_t Do, Dn, g;
    slong i;

    fmpz_init(Do);
    fmpz_init(Dn);
    fmpz_init(g);
    w->nh = w->ns = w->nq = w->ne = 0;
    common_den(O, Do, P->com, g);
    for (i = 0; i < w->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;
        fmpz * jn = w->jn + 3 * i, * jt = w->jt + 3 * i;
        char x = mode[i];

        if (x == 'u')
            continue;
        /* r = (P Do - O Dp, ...) / (Dp Do), N = normal times Dn.  */
        common_den(R, R + 2, f->point, g);
        fmpz_mul(R + 0, R + 0, Do);
        fmpz_submul(R + 0, O + 0, R + 2);
        fmpz_mul(R + 1, R + 1, Do);
        fmpz_submul(R + 1, O + 1, R + 2);
        fmpz_mul(R + 2, R + 2, Do);
        common_den(N, Dn, f->normal, g);
        column(jn, N, R, g, x == 's');
        if (x == 'l' || x == 'r' || x == 'n')
        {
            fmpz_neg(N + 2, N + 1);             /* t = (-n_y, n_x) */
            fmpz_swap(N + 1, N + 2);
            fmpz_swap(N + 0, N + 1);
            column(jt, N, R, g, 0);
            fmpz_swap(N + 0, N + 1);            /* N back to the normal */
            fmpz_swap(N + 1, N + 2);
        }
        switch (x)
        {
        case 's': put_row(w->H, &w->nh, jn, -1); break;
        case 'a': put_row(w->S, &w->ns, jn, 1); break;
        case 'l': w->E[w->ne++] = jn;
                  put_row(w->S, &w->ns, jt, -1);
                  edge(w, N, f->mu_k, -1, R); break;
        case 'r': w->E[w->ne++] = jn;
                  put_row(w->S, &w->ns, jt, 1);
                  edge(w, N, f->mu_k, 1, R); break;
        case 'n': w->E[w->ne++] = jn;
                  w->E[w->ne++] = jt;
                  edge(w, N, f->mu_s, -1, R);
                  edge(w, N, f->mu_s, 1, R); break;
        case 'm': w->E[w->ne++] = jn;
                  edge(w, N, f->mu_s, -1, R);
                  edge(w, N, f->mu_s, 1, R); break;
        default: break;
        }
    }
    fmpz_clear(Do);
    fmpz_clear(Dn);
    fmpz_clear(g);
    _fmpz_vec_clear(O, 2);
    _fmpz_vec_clear(R, 3);
    _fmpz_vec_clear(N, 3);
}

/* The rank of the equality rows (0, 1, 2 or 3); for rank 2, u := a
   nonzero vector spanning their null space, primitive.  */
static int
eq_rank(ws_struct * w, fmpz * u)
{
    slong i;
    int r = 0;
    const fmpz * e1 = NULL;

    for (i = 0; i < w->ne && r < 3; i++)
    {
        const fmpz * x = w->E[i];

        if (r == 0)
        {
            if (!_fmpz_vec_is_zero(x, 3))
            {
                e1 = x;
                r = 1;
            }
        }
        else if (r == 1)
        {
            _wc_zvec3_cross(u, e1, x);
            r = _fmpz_vec_is_zero(u, 3) ? 1 : 2;
            if (r == 2)
                primitive(u, SCRATCH(w));
        }
        else if (_wc_zvec3_dot_sgn_fast(u, x, SCRATCH(w)) != 0)
            r = 3;
    }
    return r;
}

/* V_x inside the line through u: the origin, the ray v (primitive), the
   line, or empty; *apex := whether the origin face belongs to V_x.  */
static int
on_line(ws_struct * w, fmpz * u, int * apex)
{
    int pos = 0, neg = 0, s;
    slong i;

    for (i = 0; i < w->nh + w->ns; i++)
    {
        s = _wc_zvec3_dot_sgn_fast(i < w->nh ? w->H + 3 * i
                                   : w->S + 3 * (i - w->nh), u, SCRATCH(w));
        pos |= s > 0;
        neg |= s < 0;
    }
    *apex = w->ns == 0;
    if (pos && neg)
        return w->ns == 0 ? V_ORIGIN : V_EMPTY;
    if (!pos && !neg)
        return w->ns == 0 ? V_LINE : V_EMPTY;
    if (pos)
        _fmpz_vec_neg(u, u, 3);                 /* the ray is -u */
    for (i = 0; i < w->ns; i++)
        if (_wc_zvec3_dot_sgn_fast(w->S + 3 * i, u, SCRATCH(w)) >= 0)
            return V_EMPTY;
    return V_RAY;
}

static int
row_cmp(const fmpz * a, const fmpz * b)
{
    int c, j;

    for (j = 0; j < 3; j++)
        if ((c = fmpz_cmp(a + j, b + j)) != 0)
            return c;
    return 0;
}

/* Heap sort of idx[0..k) by the rows of A (no allocation, no recursion).  */
static void
sift(const fmpz * A, slong * idx, slong root, slong k)
{
    slong c, t;

    while ((c = 2 * root + 1) < k)
    {
        if (c + 1 < k && row_cmp(A + 3 * idx[c], A + 3 * idx[c + 1]) < 0)
            c++;
        if (row_cmp(A + 3 * idx[root], A + 3 * idx[c]) >= 0)
            return;
        t = idx[root];
        idx[root] = idx[c];
        idx[c] = t;
        root = c;
    }
}

/* U := the distinct nonzero rows of A[0..k); returns their number.  */
static slong
distinct(fmpz * U, const fmpz * A, slong k, slong * idx)
{
    slong i, m = 0, t;

    for (i = 0; i < k; i++)
        idx[i] = i;
    for (i = k / 2 - 1; i >= 0; i--)
        sift(A, idx, i, k);
    for (i = k - 1; i > 0; i--)
    {
        t = idx[0];
        idx[0] = idx[i];
        idx[i] = t;
        sift(A, idx, 0, i);
    }
    for (i = 0; i < k; i++)
    {
        const fmpz * x = A + 3 * idx[i];

        if (_fmpz_vec_is_zero(x, 3)
            || (m > 0 && row_cmp(U + 3 * (m - 1), x) == 0))
            continue;
        _fmpz_vec_set(U + 3 * m++, x, 3);
    }
    return m;
}

/* G gets M x (primitive), negated when sign < 0.  */
static void
put_image(ws_struct * w, const fmpz * x, int sign)
{
    fmpz * y = w->G + 3 * w->ng++;

    fmpz_mul(y + 0, w->ma, x + 0);
    fmpz_mul(y + 1, w->ma, x + 1);
    fmpz_mul(y + 2, w->mb, x + 2);
    primitive(y, SCRATCH(w));
    if (sign < 0)
        _fmpz_vec_neg(y, y, 3);
}

/* W's faces when V_x is a ray whose apex is excluded: a face is included
   iff it holds y = M v, i.e. iff it contains the rays of the smallest
   face holding y (those on every facet through y; all rays when none).  */
static int
faces_holding(wc_cone_t W, const fmpz * y, fmpz_t t)
{
    slong m = fmpz_mat_nrows(W->ineqs), k = fmpz_mat_nrows(W->rays);
    slong i, j, f, size = 0, * T = malloc(sizeof(slong) * (m + k + 1));
    slong * in = T + m, nt = 0;

    if (T == NULL)
        return 0;
    for (j = 0; j < m; j++)
        if (_wc_zvec3_dot_sgn_fast(WC_ROW(W->ineqs, j), y, t) == 0)
            T[nt++] = j;
    for (i = 0; i < k; i++)
    {
        in[i] = 1;
        for (j = 0; j < nt && in[i]; j++)
            in[i] = _wc_zvec3_dot_sgn_fast(WC_ROW(W->ineqs, T[j]),
                                           WC_ROW(W->rays, i), t) == 0;
        size += in[i];
    }
    for (f = 0; f < W->nfaces; f++)
    {
        wc_face_struct * F = W->faces + f;
        slong c = 0;

        for (i = 0; i < F->nrays; i++)
            c += in[F->rays[i]];
        F->included = c == size;
    }
    free(T);
    return 1;
}

/* 1 when the rows H have rank 2 and are in no closed half-plane of their
   plane: then pos(H) is that plane, V_x its normal line, and u := the
   normal; 0 for other rows of rank 1 or 2, -1 for rank 3.  Around u, A is the row farthest counterclockwise from the
   first row h, B the farthest clockwise; the rows fill the plane iff
   -h is a row and both sides are used, or the angle from A on to B is
   below a half-turn.  */
static int
plane_of_rows(ws_struct * w, fmpz * u)
{
    const fmpz * h = w->H, * A = NULL, * B = NULL;
    fmpz * c = _fmpz_vec_init(3), * t = SCRATCH(w);
    slong i;
    int opp = 0, r = 0, s;

    for (i = 1; i < w->nh && _fmpz_vec_is_zero(u, 3); i++)
        _wc_zvec3_cross(u, h, w->H + 3 * i);
    if (_fmpz_vec_is_zero(u, 3))
        goto done;
    for (i = 0; i < w->nh; i++)
        if (_wc_zvec3_dot_sgn_fast(u, w->H + 3 * i, t) != 0)
        {
            r = -1;
            goto done;
        }
    primitive(u, t);
    for (i = 1; i < w->nh; i++)
    {
        const fmpz * x = w->H + 3 * i;

        _wc_zvec3_cross(c, h, x);
        s = _wc_zvec3_dot_sgn_fast(u, c, t);
        if (s == 0)
            opp |= _wc_zvec3_dot_sgn_fast(h, x, t) < 0;
        else if (s > 0 && A != NULL)
        {
            _wc_zvec3_cross(c, A, x);
            if (_wc_zvec3_dot_sgn_fast(u, c, t) > 0)
                A = x;
        }
        else if (s < 0 && B != NULL)
        {
            _wc_zvec3_cross(c, B, x);
            if (_wc_zvec3_dot_sgn_fast(u, c, t) < 0)
                B = x;
        }
        else if (s > 0)
            A = x;
        else
            B = x;
    }
    if (A != NULL && B != NULL)
    {
        _wc_zvec3_cross(c, A, B);
        r = opp || _wc_zvec3_dot_sgn_fast(u, c, t) > 0;
    }

done:
    _fmpz_vec_clear(c, 3);
    return r;
}

/* V_x from the rank of the equalities; V_POLAR sets FV (the fan of H,
   whose facet normals are V_x's rays).  */
static int
settle_v(ws_struct * w, _wc_fan3_t FV, fmpz * u, int * apex)
{
    int r = eq_rank(w, u);
    slong k;

    *apex = 1;
    if (r == 3)
        return w->ns == 0 ? V_ORIGIN : V_EMPTY;
    if (r == 2)
        return on_line(w, u, apex);
    if (r == 1 || w->ns > 0 || w->nh == 0)
        return V_OTHER;
    _fmpz_vec_zero(u, 3);
    if ((r = plane_of_rows(w, u)) >= 0)
        return r ? V_LINE : V_OTHER;
    k = distinct(w->U, w->H, w->nh, w->idx);
    r = _wc_fan3(FV, w->U, k);
    if (r == WC_FAN3_NOMEM)
        return -1;
    return r == WC_FAN3_POINTED ? V_POLAR
        : r == WC_FAN3_SPACE ? V_ORIGIN : V_OTHER;
}

/* W := the fan of the generators; *done := 0 when the fan does not
   settle it.  Returns WC_OK, or WC_EINTERNAL when out of memory.  */
static int
set_w(wc_cone_t W, int * done, ws_struct * w, int kind, int apex)
{
    _wc_fan3_t F;
    slong k;
    int r, status = WC_OK;

    k = distinct(w->U, w->G, w->ng, w->idx);
    if (k == 0)
    {
        _wc_cone3_set_origin(W);
        return WC_OK;
    }
    if (k == 2 && kind == V_LINE)       /* M V_x, no friction edges */
    {
        _wc_cone3_set_line(W, w->G);
        return WC_OK;
    }
    _wc_fan3_init(F);
    r = _wc_fan3(F, w->U, k);
    if (r == WC_FAN3_NOMEM)
        status = WC_EINTERNAL;
    else if (r == WC_FAN3_POINTED)
        status = _wc_cone3_set_fan(W, F, 0);
    else if (r == WC_FAN3_SPACE)
        _wc_cone3_set_space(W);
    else
        *done = 0;
    _wc_fan3_clear(F);
    if (status == WC_OK && *done && kind == V_RAY && !apex
        && !faces_holding(W, w->G, SCRATCH(w)))
        status = WC_EINTERNAL;
    return status;
}

/* A := the rows x[0..k) (stride 3, or the pointers X when not NULL)
   times M^-1, up to positive factors: (mb x0, mb x1, ma x2).  */
static void
rows_times_minv(fmpq_mat_t A, const fmpz * x, const fmpz ** X, slong k,
                const ws_struct * w)
{
    slong i;

    fmpq_mat_init(A, k, 3);
    for (i = 0; i < k; i++)
    {
        const fmpz * r = X != NULL ? X[i] : x + 3 * i;

        fmpz_mul(fmpq_mat_entry_num(A, i, 0), w->mb, r + 0);
        fmpz_mul(fmpq_mat_entry_num(A, i, 1), w->mb, r + 1);
        fmpz_mul(fmpq_mat_entry_num(A, i, 2), w->ma, r + 2);
    }
}

/* No friction edges: W = M V_x = { g : E M^-1 g = 0, H M^-1 g <= 0,
   S M^-1 g < 0 }, one conversion (the general one) instead of V_x's and
   then the image's.  */
static int
image_by_hrep(wc_cone_t W, const ws_struct * w, wc_error_t err)
{
    fmpq_mat_t E, H, S;
    int status;

    rows_times_minv(E, NULL, w->E, w->ne, w);
    rows_times_minv(H, w->H, NULL, w->nh, w);
    rows_times_minv(S, w->S, NULL, w->ns, w);
    status = wc_cone_set_hrep(W, E, H, S, err);
    fmpq_mat_clear(E);
    fmpq_mat_clear(H);
    fmpq_mat_clear(S);
    return status;
}

int
_wc_wrench_cone_direct3(wc_cone_t W, int * done, const wc_problem_t P,
                        const char * mode, wc_error_t err)
{
    ws_struct w;
    _wc_fan3_t FV;
    slong n = P->n, i, len = 30 * n + 23;
    fmpz * z = NULL, * u;
    int kind, apex, status = WC_OK, err_set = 0;

    *done = 0;
    wc_cone_set_empty(W);
    if (W->d != 3)
        return WC_OK;
    w.n = n;
    w.E = malloc(sizeof(const fmpz *) * 2 * n);
    w.idx = malloc(sizeof(slong) * (2 * n + 3));
    if (w.E == NULL || w.idx == NULL)
    {
        status = WC_EINTERNAL;
        goto cleanup;
    }
    z = _fmpz_vec_init(len);
    w.jn = z;
    w.jt = w.jn + 3 * n;
    w.H = w.jt + 3 * n;
    w.S = w.H + 3 * n;
    w.Q = w.S + 3 * n;
    w.G = w.Q + 6 * n;
    w.U = w.G + 3 * (2 * n + 2);
    w.t = w.U + 3 * (2 * n + 2);
    u = w.t + 8;
    fmpz_init(w.ma);
    fmpz_init(w.mb);
    _wc_fan3_init(FV);
    /* M = diag(m, m, I): M x is a positive multiple of
       (m_num I_den x0, m_num I_den x1, I_num m_den x2).  */
    fmpz_mul(w.ma, fmpq_numref(P->mass), fmpq_denref(P->inertia));
    fmpz_mul(w.mb, fmpq_numref(P->inertia), fmpq_denref(P->mass));
    build(&w, P, mode);
    kind = settle_v(&w, FV, u, &apex);
    if (kind < 0)
        status = WC_EINTERNAL;
    if (kind == V_OTHER && w.nq == 0)
    {
        *done = 1;
        status = image_by_hrep(W, &w, err);
        err_set = 1;
        goto finish;
    }
    if (kind < 0 || kind == V_OTHER)
        goto finish;
    *done = 1;
    if (kind == V_EMPTY)
        goto finish;
    w.ng = 0;
    if (kind == V_RAY || kind == V_LINE)
        put_image(&w, u, 1);
    if (kind == V_LINE)
        put_image(&w, u, -1);
    for (i = 0; kind == V_POLAR && i < FV->m; i++)
        put_image(&w, FV->facets + 3 * i, 1);
    _fmpz_vec_set(w.G + 3 * w.ng, w.Q, 3 * w.nq);
    w.ng += w.nq;
    status = set_w(W, done, &w, kind, apex);

finish:
    fmpz_clear(w.ma);
    fmpz_clear(w.mb);
    _wc_fan3_clear(FV);
cleanup:
    if (z != NULL)
        _fmpz_vec_clear(z, len);
    free(w.E);
    free(w.idx);
    if (status != WC_OK)
    {
        *done = 1;
        wc_cone_set_empty(W);
        return err_set ? status
            : wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                           "internal error: out of memory in the direct "
                           "route");
    }
    if (!*done)
        wc_cone_set_empty(W);
    return WC_OK;
}
