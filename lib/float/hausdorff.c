/* hausdorff.c -- the directed and the Hausdorff angular distance between
   two cones in R^3.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The directed distance sup { angle(x, B) : x in A, |x| = 1 } is NOT in
   general attained at an extreme ray of A, even for pointed cones that
   are close: for A = pos((1, 1, e), (1, -1, e)) and the wedge
   B = pos((1, 1, 0), (1, -1, 0)), A's rays are at atan(e / sqrt 2) from
   B but A's middle (1, 0, e) is at atan(e) (on the sphere the distance
   to a great-circle arc is not convex; tests/t-compare.c checks this
   case).  Nor is a vertex rule saved by the facets' normals.  So we split R^3
   into the cells G + N_G of the normal fan of B (G a face of B, N_G its
   normal cone): on G + N_G the nearest point of B is the projection onto
   span G, and the angle to B is the angle to the subspace span G, whose
   maximum over the polyhedral cone K = A cap (G + N_G) is found exactly:
   - span G = R^3: 0;
   - span G a plane with normal n: sin(angle) = |n.x| / |n| |x|, whose
     maximum over unit x in K is |P_K n| / |n| or |P_K (-n)| / |n|
     (|P_K n| is the support function of K cap ball at n);
   - span G a line R r: cos(angle) = |r.x| / |r| |x|; if r.x vanishes at
     some nonzero x of K the maximum is pi/2, else r.x keeps one sign on K
     and x -> |r.x| / |x| is quasi-concave there (its superlevel sets are
     convex circular cones), so its minimum is at a generator of K;
   - G = {0} (B pointed): K lies in the polar cone B°, every angle is at
     least pi/2, and the nearest point of B to x is one of B's extreme
     rays (x.b <= 0 on B, and the same quasi-concavity); the largest
     min_i angle(x, r_i) over K is found by enumerating the finitely many
     candidates (see minimax_polar), in doubles.  */

#include <config.h>

#include <math.h>
#include <string.h>

#include <stdlib.h>

#include <flint/fmpq_vec.h>
#include <flint/fmpz_vec.h>

#include "core/limits.h"
#include "float/compare.h"
#include "float/angle.h"
#include "exact/vec3.h"
#include "exact/zrow.h"

/* ------------------------------------------------------------------ */
/* Unit vectors in doubles, for the candidates of minimax_polar.  */

static double
ddot(const double * a, const double * b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void
dcross(double * c, const double * a, const double * b)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* Normalise a in place; 0 when it is (numerically) zero.  */
static int
dnormalize(double * a)
{
    double n = sqrt(ddot(a, a));

    if (!(n > 1e-300))
        return 0;
    a[0] /= n;
    a[1] /= n;
    a[2] /= n;
    return 1;
}

/* The angle between a and b (atan2 of |a x b| and a.b: accurate near 0
   and pi, where acos is not).  */
static double
dangle(const double * a, const double * b)
{
    double c[3];

    dcross(c, a, b);
    return atan2(sqrt(ddot(c, c)), ddot(a, b));
}

/* ------------------------------------------------------------------ */
/* The largest angle from a cell to a face's span.  */

/* The largest angle from a unit x of cl K (nonzero) to the line R r.  */
static double
max_angle_to_line(double * w, const wc_cone_t K, const fmpq * r)
{
    fmpq_mat_t G;
    fmpq * x = _fmpq_vec_init(3);
    fmpq_t s, t;
    int * sg;
    slong n, i, j;
    double best = -1;

    _wc_cone_generators(G, K);
    n = fmpq_mat_nrows(G);
    sg = flint_malloc(sizeof(int) * (n + 1));
    fmpq_init(s);
    fmpq_init(t);
    for (i = 0; i < n; i++)
    {
        _wc_qv3_dot(s, r, WC_ROW(G, i));
        sg[i] = fmpq_sgn(s);
        if (sg[i] == 0)
        {
            _wc_qv3_unit_d(w, WC_ROW(G, i));
            best = WC_PI / 2;
            goto cleanup;
        }
    }
    /* r.x changes sign on K: for generators g, h with r.g > 0 > r.h,
       x = (r.g) h - (r.h) g is in K and has r.x = 0 -- nonzero unless g
       and h are opposite (when K is a single line, all such x are 0).  */
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++)
        {
            slong c;

            if (sg[i] <= 0 || sg[j] >= 0)
                continue;
            _wc_qv3_dot(s, r, WC_ROW(G, i));
            _wc_qv3_dot(t, r, WC_ROW(G, j));
            for (c = 0; c < 3; c++)
            {
                fmpq_mul(x + c, s, fmpq_mat_entry(G, j, c));
                fmpq_submul(x + c, t, fmpq_mat_entry(G, i, c));
            }
            if (!_wc_qv3_is_zero(x))
            {
                _wc_qv3_unit_d(w, x);
                best = WC_PI / 2;
                goto cleanup;
            }
        }
    for (i = 0; i < n; i++)
    {
        double a = wc_angle_vectors(WC_ROW(G, i), r);

        if (a > WC_PI / 2)
            a = WC_PI - a;      /* the angle to the line, not the ray */
        if (a > best)
        {
            best = a;
            _wc_qv3_unit_d(w, WC_ROW(G, i));
        }
    }

cleanup:
    fmpq_clear(s);
    fmpq_clear(t);
    flint_free(sg);
    fmpq_mat_clear(G);
    _fmpq_vec_clear(x, 3);
    return best;
}

/* The largest angle from a unit x of cl K (nonzero) to the plane n^perp.  */
static double
max_angle_to_plane(double * w, const wc_cone_t K, const fmpq * n)
{
    fmpq * q1 = _fmpq_vec_init(3), * q2 = _fmpq_vec_init(3);
    fmpq * m = _fmpq_vec_init(3);
    fmpq_t b1, b2, nn;
    fmpq_mat_t G;
    double a;

    fmpq_init(b1);
    fmpq_init(b2);
    fmpq_init(nn);
    _wc_cone_project(b1, q1, n, K);
    _wc_qv3_neg(m, n);
    _wc_cone_project(b2, q2, m, K);
    if (fmpq_cmp(b2, b1) > 0)
    {
        fmpq_swap(b1, b2);
        _wc_qv3_swap(q1, q2);
    }
    _wc_qv3_dot(nn, n, n);
    if (fmpq_is_zero(b1))
    {
        /* K lies in the plane */
        _wc_cone_generators(G, K);
        _wc_qv3_unit_d(w, WC_ROW(G, 0));
        fmpq_mat_clear(G);
        a = 0;
    }
    else
    {
        _wc_qv3_unit_d(w, q1);
        /* sin^2 = b1 / |n|^2, tan^2 = b1 / (|n|^2 - b1) */
        fmpq_sub(nn, nn, b1);
        if (fmpq_is_zero(nn))
            a = WC_PI / 2;
        else
        {
            fmpq_div(nn, b1, nn);
            a = _wc_atan_sqrt(nn);
        }
    }
    fmpq_clear(b1);
    fmpq_clear(b2);
    fmpq_clear(nn);
    _fmpq_vec_clear(q1, 3);
    _fmpq_vec_clear(q2, 3);
    _fmpq_vec_clear(m, 3);
    return a;
}

typedef struct
{
    slong k;            /* rays of B */
    double * p;         /* 3 k: the unit vectors -r_i / |r_i| */
    slong m, q;
    double * h;         /* 3 m: K's unit facet normals */
    double * e;         /* 3 q: K's unit equality normals */
    double best;        /* the smallest max_i angle(x, p_i) so far */
    double w[3];
}
minimax;

static void
minimax_try(minimax * M, const double * x0)
{
    double x[3] = { x0[0], x0[1], x0[2] }, f = 0;
    slong i;

    if (!dnormalize(x))
        return;
    /* candidates lie on faces of K only up to rounding: a small slack */
    for (i = 0; i < M->m; i++)
        if (ddot(M->h + 3 * i, x) > 1e-9)
            return;
    for (i = 0; i < M->q; i++)
        if (fabs(ddot(M->e + 3 * i, x)) > 1e-9)
            return;
    for (i = 0; i < M->k && f < M->best; i++)
    {
        double a = dangle(x, M->p + 3 * i);

        if (a > f)
            f = a;
    }
    if (f < M->best)
    {
        M->best = f;
        memcpy(M->w, x, sizeof M->w);
    }
}

/* cl B pointed, K = cl A cap B° nonzero.  For x in K the angle to B is
   min_i angle(x, r_i) = pi - max_i angle(x, p_i), p_i = -r_i; we want its
   largest value, i.e. the smallest F(x) = max_i angle(x, p_i) over unit x
   of K.  At a minimiser x, in the relative interior of a face K' of K,
   the active p_i (those at the largest angle) are equidistant from x and
   x is stationary for their common distance within span K': x is the
   normalised projection of an active p_i onto the subspace of span K'
   equidistant from all of them (at most dim span K' of them matter:
   Caratheodory on the stationarity condition).  So F's minimum is among:
   the rays of K (dimension-1 faces, and the lines both ways), and on each
   face of dimension 2 or 3 the projections of single p_i, the
   equidistant points of pairs, and on a 3-dimensional face the
   circumcentres of triples.  The answer is at least pi/2 (K lies in B°).  */
static double
minimax_polar(double * w, const wc_cone_t K, const wc_cone_t B)
{
    minimax M;
    fmpq * dir = _fmpq_vec_init(3);
    fmpq_mat_t G;
    slong f, i, j, l;
    double a;

    M.k = fmpz_mat_nrows(B->rays);
    M.m = fmpz_mat_nrows(K->ineqs);
    M.q = fmpz_mat_nrows(K->eqs);
    M.p = flint_malloc(sizeof(double) * 3 * (M.k + 1));
    M.h = flint_malloc(sizeof(double) * 3 * (M.m + 1));
    M.e = flint_malloc(sizeof(double) * 3 * (M.q + 1));
    M.best = INFINITY;
    M.w[0] = M.w[1] = M.w[2] = 0;
    for (i = 0; i < M.k; i++)
    {
        _wc_zv3_unit_d(M.p + 3 * i, WC_ROW(B->rays, i));
        for (j = 0; j < 3; j++)
            M.p[3 * i + j] = -M.p[3 * i + j];
    }
    for (i = 0; i < M.m; i++)
        _wc_zv3_unit_d(M.h + 3 * i, WC_ROW(K->ineqs, i));
    for (i = 0; i < M.q; i++)
        _wc_zv3_unit_d(M.e + 3 * i, WC_ROW(K->eqs, i));

    /* the generators first: when the p_i project to 0 on a face spanned
       by lines, every unit vector of it is as good, and these are some */
    _wc_cone_generators(G, K);
    for (i = 0; i < fmpq_mat_nrows(G); i++)
    {
        double g[3];

        _wc_qv3_unit_d(g, WC_ROW(G, i));
        minimax_try(&M, g);
    }
    fmpq_mat_clear(G);
    for (f = 0; f < K->nfaces && M.k <= WC_MINIMAX_SINGLES; f++)
    {
        slong r = _wc_face_span(dir, K, K->faces + f);
        double b[3], x[3], d[3];

        if (r == 0)
            continue;
        _wc_qv3_unit_d(b, dir);
        if (r == 1)
        {
            minimax_try(&M, b);
            b[0] = -b[0];
            b[1] = -b[1];
            b[2] = -b[2];
            minimax_try(&M, b);
            continue;
        }
        for (i = 0; i < M.k; i++)
        {
            const double * pi = M.p + 3 * i;

            if (r == 2)
            {
                double s = ddot(pi, b);

                for (l = 0; l < 3; l++)
                    x[l] = pi[l] - s * b[l];
                minimax_try(&M, x);
            }
            else
                minimax_try(&M, pi);
            for (j = i + 1; j < M.k && M.k <= WC_MINIMAX_PAIRS; j++)
            {
                const double * pj = M.p + 3 * j;

                for (l = 0; l < 3; l++)
                    d[l] = pi[l] - pj[l];
                if (r == 2)
                {
                    dcross(x, b, d);
                    minimax_try(&M, x);
                    for (l = 0; l < 3; l++)
                        x[l] = -x[l];
                    minimax_try(&M, x);
                }
                else
                {
                    for (l = 0; l < 3; l++)
                        x[l] = pi[l] + pj[l];
                    minimax_try(&M, x);
                    if (M.k > WC_MINIMAX_TRIPLES)
                        continue;
                    for (l = j + 1; l < M.k; l++)
                    {
                        const double * pl = M.p + 3 * l;
                        double e2[3];
                        slong c;

                        for (c = 0; c < 3; c++)
                            e2[c] = pi[c] - pl[c];
                        dcross(x, d, e2);
                        minimax_try(&M, x);
                        for (c = 0; c < 3; c++)
                            x[c] = -x[c];
                        minimax_try(&M, x);
                    }
                }
            }
        }
    }
    a = WC_PI - M.best;
    if (!(a >= WC_PI / 2))
        a = WC_PI / 2;
    if (a > WC_PI)
        a = WC_PI;
    memcpy(w, M.w, sizeof M.w);
    flint_free(M.p);
    flint_free(M.h);
    flint_free(M.e);
    _fmpq_vec_clear(dir, 3);
    return a;
}

/* Stack the rows of A and B (integer, k x 3) into a rational matrix.  */
static void
stack_rows(fmpq_mat_t S, const fmpz_mat_t A, const fmpz_mat_t B)
{
    slong a = fmpz_mat_nrows(A), b = fmpz_mat_nrows(B), i;

    fmpq_mat_init(S, a + b, 3);
    for (i = 0; i < a; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(S, i), WC_ROW(A, i), 3);
    for (i = 0; i < b; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(S, a + i), WC_ROW(B, i), 3);
}

/* 1 when h . r = 0 for every ray r of face F of B.  */
static int
tight(const fmpz * h, const wc_cone_t B, const wc_face_struct * F)
{
    fmpz_t s;
    slong i, j;
    int t = 1;

    fmpz_init(s);
    for (i = 0; t && i < F->nrays; i++)
    {
        fmpz_zero(s);
        for (j = 0; j < 3; j++)
            fmpz_addmul(s, h + j, WC_ROW(B->rays, F->rays[i]) + j);
        t = fmpz_is_zero(s);
    }
    fmpz_clear(s);
    return t;
}

/* 1 when some facet h of A has h.g > 0 on every nonzero row g of R (or
   an equality of A has one strict sign on them all) and L is zero: then
   every nonzero x of pos R has h.x > 0 (resp. != 0) and is not in A.  A
   cheap exact test that spares most cells their cone computations.  */
static int
separated(const wc_cone_t A, const fmpq_mat_t R, const fmpq_mat_t L)
{
    slong m = fmpz_mat_nrows(A->ineqs), q = fmpz_mat_nrows(A->eqs), i, j;
    fmpq_t s;
    int sep = 0;

    for (j = 0; j < fmpq_mat_nrows(L); j++)
        if (!_wc_qv3_is_zero(WC_ROW(L, j)))
            return 0;
    fmpq_init(s);
    for (i = 0; !sep && i < m + q; i++)
    {
        const fmpz * h = i < m ? WC_ROW(A->ineqs, i) : WC_ROW(A->eqs, i - m);
        int sign = 0, any = 0;

        sep = 1;
        for (j = 0; sep && j < fmpq_mat_nrows(R); j++)
        {
            if (_wc_qv3_is_zero(WC_ROW(R, j)))
                continue;
            _wc_zqvec3_dot(s, h, WC_ROW(R, j));
            if (i < m)
                sep = fmpq_sgn(s) > 0;
            else
            {
                sep = fmpq_sgn(s) != 0 && (sign == 0 || fmpq_sgn(s) == sign);
                sign = fmpq_sgn(s);
            }
            any = 1;
        }
        sep = sep && any;
    }
    fmpq_clear(s);
    return sep;
}

/* Which facets of B contain each face, found without testing every facet
   against every face (O(k^2) for k rays): for a pointed 3-dimensional B,
   each 2-dimensional face (two rays a, b) lies on the facet whose normal
   is the primitive vector on +-(a x b), found by a binary search among
   B's sorted facet normals, and a ray lies on the facets of the
   2-dimensional faces that contain it.  Other cones (few facets) keep
   the direct test (tight).  tests/t-compare-fast.c checks both ways.  */
typedef struct
{
    int on;             /* the map is built */
    slong * facet;      /* per face of B: its facet's row, or -1 */
    slong * start;      /* per ray i: its facets' rows are */
    slong * rows;       /* rows[start[i] .. start[i + 1]) */
}
tightmap;

static void
tightmap_clear(tightmap * T)
{
    flint_free(T->facet);
    flint_free(T->start);
    flint_free(T->rows);
    T->on = 0;
}

/* The facet row of the 2-dimensional face F of B (pointed, dim 3), or -1
   when the search fails (it cannot, for a canonical cone).  */
static slong
face_facet(const wc_cone_t B, const wc_face_struct * F,
           const _wc_zrow * sorted, fmpz * h, fmpz_t t)
{
    const fmpz * a = WC_ROW(B->rays, F->rays[0]);
    const fmpz * b = WC_ROW(B->rays, F->rays[1]);
    slong j, c;
    _wc_zrow key, * hit;

    _wc_zvec3_cross(h, a, b);
    if (_fmpz_vec_is_zero(h, 3))
        return -1;
    _wc_zvec3_primitive(h, t);
    /* the sign: h.x <= 0 on B, and < 0 at a ray off F */
    for (c = 0; c < fmpz_mat_nrows(B->rays); c++)
        if (c != F->rays[0] && c != F->rays[1])
        {
            fmpz_zero(t);
            for (j = 0; j < 3; j++)
                fmpz_addmul(t, h + j, WC_ROW(B->rays, c) + j);
            if (fmpz_sgn(t) != 0)
                break;
        }
    if (fmpz_sgn(t) > 0)
        _fmpz_vec_neg(h, h, 3);
    key.v = h;
    hit = bsearch(&key, sorted, fmpz_mat_nrows(B->ineqs),
                  sizeof(_wc_zrow), _wc_zrow_cmp);
    return hit == NULL ? -1 : hit->i;
}

/* Build T for B when B is pointed and 3-dimensional; else T->on = 0.
   Returns 0, or -1 when out of memory.  */
static int
tightmap_init(tightmap * T, const wc_cone_t B)
{
    slong m = fmpz_mat_nrows(B->ineqs), k = fmpz_mat_nrows(B->rays), f, i;
    _wc_zrow * sorted;
    fmpz * h;
    fmpz_t t;

    T->on = 0;
    T->facet = T->start = T->rows = NULL;
    if (B->dim != 3 || B->lineality_dim != 0 || k < 3)
        return 0;
    sorted = flint_malloc(sizeof(_wc_zrow) * (m + 1));
    T->facet = flint_malloc(sizeof(slong) * (B->nfaces + 1));
    T->start = flint_calloc(k + 2, sizeof(slong));
    T->rows = flint_malloc(sizeof(slong) * (2 * B->nfaces + 1));
    h = _fmpz_vec_init(3);
    fmpz_init(t);
    for (i = 0; i < m; i++)
    {
        sorted[i].v = WC_ROW(B->ineqs, i);
        sorted[i].i = i;
    }
    qsort(sorted, m, sizeof(_wc_zrow), _wc_zrow_cmp);
    T->on = 1;
    for (f = 0; f < B->nfaces; f++)
    {
        const wc_face_struct * F = B->faces + f;

        T->facet[f] = -1;
        if (F->dim != 2)
            continue;
        if (F->nrays != 2 || (T->facet[f] = face_facet(B, F, sorted, h, t)) < 0)
            T->on = 0;  /* not as expected: keep the direct test */
        else
        {
            T->start[F->rays[0] + 2]++;
            T->start[F->rays[1] + 2]++;
        }
    }
    /* counting sort of (ray, facet) pairs into rows[] */
    for (i = 0; i < k; i++)
        T->start[i + 2] += T->start[i + 1];
    for (f = 0; T->on && f < B->nfaces; f++)
        if (B->faces[f].dim == 2)
            for (i = 0; i < 2; i++)
                T->rows[T->start[B->faces[f].rays[i] + 1]++] = T->facet[f];
    flint_free(sorted);
    _fmpz_vec_clear(h, 3);
    fmpz_clear(t);
    if (!T->on)
        tightmap_clear(T);
    return 0;
}

static int
slong_cmp(const void * a, const void * b)
{
    slong x = *(const slong *) a, y = *(const slong *) b;

    return (x > y) - (x < y);
}

/* idx[0..) := the rows of B's facets that contain face f, ascending;
   returns how many.  */
static slong
tight_rows(slong * idx, const tightmap * T, const wc_cone_t B, slong f)
{
    const wc_face_struct * F = B->faces + f;
    slong m = fmpz_mat_nrows(B->ineqs), n = 0, i;

    if (!T->on || F->nrays == 0)
    {
        for (i = 0; i < m; i++)
            if (F->nrays == 0 || tight(WC_ROW(B->ineqs, i), B, F))
                idx[n++] = i;
        return n;
    }
    if (F->dim == 2)
    {
        idx[0] = T->facet[f];
        return 1;
    }
    /* a ray: its facets (F->dim is 1; B itself is never asked) */
    for (i = T->start[F->rays[0]]; i < T->start[F->rays[0] + 1]; i++)
        idx[n++] = T->rows[i];
    qsort(idx, n, sizeof(slong), slong_cmp);
    return n;
}

/* K = cl A cap (G + N_G), G the face f of B; *none := 1 (K untouched)
   when a facet of A separates the cell, so that K = {0}.  */
static int
cell(wc_cone_t K, int * none, const wc_cone_t A, const wc_cone_t B,
     slong f, const tightmap * T, wc_error_t err)
{
    const wc_face_struct * F = B->faces + f;
    slong m = fmpz_mat_nrows(B->ineqs), nr = 0, i, nt;
    slong * idx = flint_malloc(sizeof(slong) * (m + 1));
    fmpq_mat_t R, L, E, H;
    wc_cone_t C;
    int status = WC_OK;

    nt = tight_rows(idx, T, B, f);
    fmpq_mat_init(R, F->nrays + nt, 3);
    for (i = 0; i < F->nrays; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(R, nr++), WC_ROW(B->rays, F->rays[i]),
                               3);
    for (i = 0; i < nt; i++)
        _fmpq_vec_set_fmpz_vec(WC_ROW(R, nr++), WC_ROW(B->ineqs, idx[i]), 3);
    flint_free(idx);
    stack_rows(L, B->lines, B->eqs);
    wc_cone_init(C, 3);
    *none = separated(A, R, L);
    if (!*none)
        status = wc_cone_set_generators(C, R, L, err);
    if (status == WC_OK && !*none)
    {
        stack_rows(E, A->eqs, C->eqs);
        stack_rows(H, A->ineqs, C->ineqs);
        status = wc_cone_set_hrep(K, E, H, NULL, err);
        fmpq_mat_clear(E);
        fmpq_mat_clear(H);
    }
    wc_cone_clear(C);
    fmpq_mat_clear(R);
    fmpq_mat_clear(L);
    return status;
}

int
wc_cone_directed_angle(double * dist, double * witness, const wc_cone_t A,
                       const wc_cone_t B, wc_error_t err)
{
    double best = -1, w[3] = { 0, 0, 0 }, x[3];
    fmpq * dir = _fmpq_vec_init(3);
    wc_cone_t K;
    tightmap T = { 0, NULL, NULL, NULL };
    slong f;
    int status = WC_OK;

    wc_cone_init(K, 3);
    if (A->d != 3 || B->d != 3 || A->empty || B->empty)
    {
        status = wc_error_set(err, WC_EINPUT, NULL, 0, 0, "the angular "
                              "distance needs two nonempty cones in R^3");
        goto cleanup;
    }
    if (A->dim == 0)
    {
        best = 0;
        goto cleanup;
    }
    if (B->dim == 0)
    {
        fmpq_mat_t G;

        _wc_cone_generators(G, A);
        _wc_qv3_unit_d(w, WC_ROW(G, 0));
        fmpq_mat_clear(G);
        best = INFINITY;
        goto cleanup;
    }
    tightmap_init(&T, B);
    for (f = 0; f < B->nfaces; f++)
    {
        const wc_face_struct * F = B->faces + f;
        double a;
        slong r;
        int none;

        r = _wc_face_span(dir, B, F);
        if (r >= 3)
            continue;   /* B itself, full-dimensional: angle 0 there */
        status = cell(K, &none, A, B, f, &T, err);
        if (status != WC_OK)
            goto cleanup;
        if (none || K->empty || K->dim == 0)
            continue;
        if (r == 2)
            a = max_angle_to_plane(x, K, dir);
        else if (r == 1)
            a = max_angle_to_line(x, K, dir);
        else
            a = minimax_polar(x, K, B);
        if (a > best)
        {
            best = a;
            memcpy(w, x, sizeof w);
        }
    }
    if (best <= 0)
    {
        /* cl A lies in cl B: any of its vectors is a witness */
        fmpq_mat_t G;

        _wc_cone_generators(G, A);
        _wc_qv3_unit_d(w, WC_ROW(G, 0));
        fmpq_mat_clear(G);
        best = 0;
    }

cleanup:
    if (status == WC_OK)
    {
        *dist = best < 0 ? 0 : best;
        if (witness != NULL)
            memcpy(witness, w, sizeof w);
    }
    tightmap_clear(&T);
    wc_cone_clear(K);
    _fmpq_vec_clear(dir, 3);
    return status;
}

int
wc_cone_hausdorff_angle(double * dist, const wc_cone_t A, const wc_cone_t B,
                        wc_error_t err)
{
    double a = 0, b = 0;
    int status = wc_cone_directed_angle(&a, NULL, A, B, err);

    if (status == WC_OK)
        status = wc_cone_directed_angle(&b, NULL, B, A, err);
    if (status == WC_OK)
        *dist = a > b ? a : b;
    return status;
}
