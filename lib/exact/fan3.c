/* fan3.c -- the O(k log k) exact conversion of a cone in R^3.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   q, the sum of the generators, lies in the interior of pos(G) when G
   spans R^3.  Sorted by angle around the axis q (a half-plane split, then
   the sign of det(q, a, b)), keeping on each half-plane through q only
   the generator farthest from q, the generators form a star-shaped
   polygon in the central projection; its convex hull, by Graham's scan
   from the generator farthest from q (a hull vertex when every generator
   makes an acute angle with q; not always otherwise), gives the extreme
   rays in order, with orientation predicate sign det(a, b, c).  The
   answer is certified, not assumed: every generator must lie inside the
   hull's edge in its sector around q (O(k), see contained), and c, the
   sum of the inward facet normals, must satisfy c . g > 0 for every
   generator, which proves the cone pointed.  When that fails, -q in the
   cone of three generators proves R^3.  When neither settles the cone,
   polar3.c's exact linear program decides: R^3, not pointed
   (left to the general kernel), or pointed with a direction d,
   d . g > 0 for every generator; then the hull in the chart d . x = 1
   (Andrew's monotone chain, with the same orientation predicate) is the
   fan, exact by construction.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "exact/fan3.h"
#include "exact/polar3.h"

typedef struct
{
    const fmpz * G;
    fmpz * qx;                  /* 3k: q x g_i */
#ifdef __SIZEOF_INT128__
    __int128 * qw;              /* the same in 128 bits, or NULL */
#endif
    unsigned char * half;       /* 0: angle in [0, pi), 1: [pi, 2 pi) */
    fmpz_t t, u;
}
fan_ctx;

#define GV(c, i) ((c)->G + 3 * (i))

void
_wc_fan3_init(_wc_fan3_t F)
{
    F->m = 0;
    F->rays = NULL;
    F->facets = NULL;
}

void
_wc_fan3_clear(_wc_fan3_t F)
{
    if (F->rays != NULL)
        _fmpz_vec_clear(F->rays, 3 * F->m);
    if (F->facets != NULL)
        _fmpz_vec_clear(F->facets, 3 * F->m);
    _wc_fan3_init(F);
}

#define SMALL40(x) (!COEFF_IS_MPZ(x) && (x) < (WORD(1) << 40) \
                    && (x) > -(WORD(1) << 40))

/* sign det(a, b, c): in 128-bit integers when every entry is below 2^40
   in absolute value (minors below 2^81, products below 2^121).  */
static int
det_sgn(const fmpz * a, const fmpz * b, const fmpz * c, fmpz_t t, fmpz_t u)
{
#ifdef __SIZEOF_INT128__
    if (SMALL40(a[0]) && SMALL40(a[1]) && SMALL40(a[2]) && SMALL40(b[0])
        && SMALL40(b[1]) && SMALL40(b[2]) && SMALL40(c[0]) && SMALL40(c[1])
        && SMALL40(c[2]))
    {
        __int128 s = a[0] * ((__int128) b[1] * c[2] - (__int128) b[2] * c[1])
            + a[1] * ((__int128) b[2] * c[0] - (__int128) b[0] * c[2])
            + a[2] * ((__int128) b[0] * c[1] - (__int128) b[1] * c[0]);

        return (s > 0) - (s < 0);
    }
#endif
    fmpz_mul(u, b + 1, c + 2);
    fmpz_submul(u, b + 2, c + 1);
    fmpz_mul(t, a + 0, u);
    fmpz_mul(u, b + 2, c + 0);
    fmpz_submul(u, b + 0, c + 2);
    fmpz_addmul(t, a + 1, u);
    fmpz_mul(u, b + 0, c + 1);
    fmpz_submul(u, b + 1, c + 0);
    fmpz_addmul(t, a + 2, u);
    return fmpz_sgn(t);
}

/* sign (q x g_a) . g_b, from the 128-bit copy when there is one.  */
static int
qx_sgn(fan_ctx * c, slong a, slong b)
{
#ifdef __SIZEOF_INT128__
    if (c->qw != NULL)
    {
        const __int128 * x = c->qw + 3 * a;
        const fmpz * g = GV(c, b);
        __int128 s = x[0] * g[0] + x[1] * g[1] + x[2] * g[2];

        return (s > 0) - (s < 0);
    }
#endif
    return _wc_zvec3_dot_sgn_fast(c->qx + 3 * a, GV(c, b), c->t);
}

/* The 128-bit copy of q x g_i when every entry of q has at most 62 bits,
   every generator entry at most 62, and bits(q) + 2 bits(g) <= 122: then
   each entry of q x g is below 2^123 and each (q x g_a) . g_b below
   2^125.  Returns 0 when out of memory.  */
static int
set_qw(fan_ctx * c, const fmpz * q, slong k)
{
#ifdef __SIZEOF_INT128__
    flint_bitcnt_t bq = 0, bg = 0;
    slong i, j;

    c->qw = NULL;
    for (j = 0; j < 3; j++)
        bq = FLINT_MAX(bq, fmpz_bits(q + j));
    for (i = 0; i < 3 * k && bg <= 62; i++)
        bg = FLINT_MAX(bg, fmpz_bits(c->G + i));
    if (bq > 62 || bg > 62 || bq + 2 * bg > 122)
        return 1;
    c->qw = malloc(sizeof(__int128) * 3 * k);
    if (c->qw == NULL)
        return 0;
    for (i = 0; i < k; i++)
    {
        const fmpz * g = GV(c, i);
        __int128 * x = c->qw + 3 * i;

        x[0] = (__int128) q[1] * g[2] - (__int128) q[2] * g[1];
        x[1] = (__int128) q[2] * g[0] - (__int128) q[0] * g[2];
        x[2] = (__int128) q[0] * g[1] - (__int128) q[1] * g[0];
    }
#endif
    return 1;
}

/* Counterclockwise order around q.  */
static int
ang_cmp(void * ctx, slong a, slong b)
{
    fan_ctx * c = ctx;

    if (c->half[a] != c->half[b])
        return c->half[a] < c->half[b] ? -1 : 1;
    return -qx_sgn(c, a, b);
}

/* Stable bottom-up merge sort of x[0..n) by cmp; tmp has n slots.  */
static void
sort_idx(int (* cmp)(void *, slong, slong), void * c, slong * x,
         slong * tmp, slong n)
{
    slong w, i;

    for (w = 1; w < n; w *= 2)
    {
        for (i = 0; i < n; i += 2 * w)
        {
            slong mid = FLINT_MIN(i + w, n), hi = FLINT_MIN(i + 2 * w, n);
            slong a = i, b = mid, o = i;

            while (a < mid && b < hi)
                tmp[o++] = cmp(c, x[b], x[a]) < 0 ? x[b++] : x[a++];
            while (a < mid)
                tmp[o++] = x[a++];
            while (b < hi)
                tmp[o++] = x[b++];
        }
        memcpy(x, tmp, sizeof(slong) * n);
    }
}

/* 1 when x lies in pos(q, y), x and y on one half-plane through q.  */
static int
inner(fan_ctx * c, slong x, slong y, fmpz * w)
{
    _wc_zvec3_cross_fast(w, GV(c, x), GV(c, y));
    return _wc_zvec3_dot_sgn_fast(w, c->qx + 3 * y, c->t) > 0;
}

/* The generator of x[0..p) that makes the largest angle with q (the first
   of equals): the largest -(q . a) / |a| when some q . a < 0, else the
   smallest (q . a) / |a| over the smallest sign; compared as
   (q . a)^2 |b|^2 against (q . b)^2 |a|^2, with the best's two values
   kept.  */
static slong
farthest(fan_ctx * c, const fmpz * q, const slong * x, slong p)
{
    fmpz_t qa, na, qs, ns, l, r;
    slong i, s = 0;
    int sa, ss;

    fmpz_init(qa);
    fmpz_init(na);
    fmpz_init(qs);
    fmpz_init(ns);
    fmpz_init(l);
    fmpz_init(r);
    _wc_zvec3_dot_fast(qs, q, GV(c, x[0]));
    _wc_zvec3_dot_fast(ns, GV(c, x[0]), GV(c, x[0]));
    ss = fmpz_sgn(qs);
    for (i = 1; i < p; i++)
    {
        int far, have = 0;

        _wc_zvec3_dot_fast(qa, q, GV(c, x[i]));
        sa = fmpz_sgn(qa);
        if (sa != ss)
            far = sa < ss;
        else if (sa == 0)
            far = 0;
        else
        {
            have = 1;
            _wc_zvec3_dot_fast(na, GV(c, x[i]), GV(c, x[i]));
            int cm = _wc_z_sqmul_cmp(qa, ns, qs, na, l, r);

            far = sa > 0 ? cm < 0 : cm > 0;
        }
        if (far)
        {
            s = i;
            ss = sa;
            fmpz_swap(qs, qa);
            if (have)
                fmpz_swap(ns, na);
            else
                _wc_zvec3_dot_fast(ns, GV(c, x[i]), GV(c, x[i]));
        }
    }
    fmpz_clear(qa);
    fmpz_clear(na);
    fmpz_clear(qs);
    fmpz_clear(ns);
    fmpz_clear(l);
    fmpz_clear(r);
    return s;
}

/* 1 when the k generators span R^3 (q = their sum is 0 here).  */
static int
spans(const fmpz * G, slong k, fmpz * w, fmpz_t t)
{
    slong i;

    for (i = 1; i < k; i++)
    {
        _wc_zvec3_cross_fast(w, G, G + 3 * i);
        if (!_fmpz_vec_is_zero(w, 3))
            break;
    }
    for (i++; i < k; i++)
        if (_wc_zvec3_dot_sgn_fast(w, G + 3 * i, t) != 0)
            return 1;
    return 0;
}

/* 1 when -q lies in pos(a, b, c).  */
static int
holds_minus_q(fan_ctx * c, const fmpz * q, const fmpz * a, const fmpz * b,
              const fmpz * d)
{
    int s = det_sgn(a, b, d, c->t, c->u);

    return s != 0 && s * det_sgn(q, b, d, c->t, c->u) <= 0
        && s * det_sgn(a, q, d, c->t, c->u) <= 0
        && s * det_sgn(a, b, q, c->t, c->u) <= 0;
}

/* The R^3 certificate: among the generators x with q . x < 0 (P, in
   angular order), a = the first, b = the last within a half-turn of a,
   d = the next; R^3 when -q lies in pos(a, b, d).  */
static int
space_by_triple(fan_ctx * c, const fmpz * q, const slong * P, slong p,
                slong * L)
{
    slong n = 0, i, j;

    for (i = 0; i < p; i++)
        if (_wc_zvec3_dot_sgn_fast(q, GV(c, P[i]), c->t) < 0)
            L[n++] = P[i];
    if (n < 3)
        return 0;
    for (j = 1; j < n && qx_sgn(c, L[0], L[j]) > 0; j++)
        ;
    if (j == 1 || j == n)
        return 0;
    return holds_minus_q(c, q, GV(c, L[0]), GV(c, L[j - 1]), GV(c, L[j]));
}

/* Keep, of each run of generators on one half-plane through q in the
   sorted x[0..n), the one farthest from q; returns the new length.  */
static slong
outermost(fan_ctx * c, slong * x, slong n, fmpz * w)
{
    slong i, p = 0;

    for (i = 0; i < n; i++)
    {
        if (p > 0 && c->half[x[p - 1]] == c->half[x[i]]
            && qx_sgn(c, x[p - 1], x[i]) == 0)
        {
            if (inner(c, x[p - 1], x[i], w))
                x[p - 1] = x[i];
            continue;
        }
        x[p++] = x[i];
    }
    return p;
}

/* Graham's scan of the cyclic polygon P[0..p) from P[s] (a hull vertex
   when the cone is pointed) into S; returns the hull's size, or 0 when
   the result is not a strictly convex polygon winding once around q.  */
static slong
scan(fan_ctx * c, const fmpz * q, const slong * P, slong p, slong s,
     slong * S)
{
    slong i, m = 0;

    for (i = 0; i < p; i++)
    {
        slong v = P[(s + i) % p];

        while (m >= 2 && det_sgn(GV(c, S[m - 2]), GV(c, S[m - 1]), GV(c, v),
                                 c->t, c->u) <= 0)
            m--;
        S[m++] = v;
    }
    while (m >= 3 && det_sgn(GV(c, S[m - 2]), GV(c, S[m - 1]), GV(c, S[0]),
                             c->t, c->u) <= 0)
        m--;
    if (m < 3)
        return 0;
    for (i = 0; i < m; i++)
    {
        const fmpz * a = GV(c, S[i]), * b = GV(c, S[(i + 1) % m]);

        if (det_sgn(q, a, b, c->t, c->u) <= 0
            || det_sgn(GV(c, S[(i + m - 1) % m]), a, b, c->t, c->u) <= 0)
            return 0;
    }
    return m;
}

/* 1 when every point of the sorted polygon x[0..p) lies on the inner
   side of the hull edge S[j] S[j+1] whose sector around q holds it.  The
   hull, a subsequence of x from x[s] = S[0], turns once around q with
   sectors below a half-turn (scan checked), so this proves
   pos(G) = pos(S) whatever the start: every generator is in some
   pos(S[j], S[j+1], q), and q is inside every edge.  O(p).  */
static int
contained(fan_ctx * c, const slong * x, slong p, slong s, const slong * S,
          slong m)
{
    slong i, j = 0;

    for (i = 1; i < p; i++)
    {
        slong v = x[(s + i) % p];

        if (j + 1 < m && v == S[j + 1])
            j++;
        else if (det_sgn(GV(c, S[j]), GV(c, S[(j + 1) % m]), GV(c, v), c->t,
                         c->u) < 0)
            return 0;
    }
    return 1;
}

/* F := the fan of the rays G[S[0..m)], each consecutive triple turning
   left (det > 0): facet i outward, -(S_i x S_{i+1}), primitive.  */
static void
fill(_wc_fan3_t F, const fmpz * G, const slong * S, slong m, fmpz_t t)
{
    slong i;

    _wc_fan3_clear(F);
    F->m = m;
    F->rays = _fmpz_vec_init(3 * m);
    F->facets = _fmpz_vec_init(3 * m);
    for (i = 0; i < m; i++)
    {
        fmpz * h = F->facets + 3 * i, * r = F->rays + 3 * i;
        const fmpz * g = G + 3 * S[i];

        /* r is 0 (fresh): word entries copy as words.  */
        if (!COEFF_IS_MPZ(g[0]) && !COEFF_IS_MPZ(g[1]) && !COEFF_IS_MPZ(g[2]))
        {
            r[0] = g[0];
            r[1] = g[1];
            r[2] = g[2];
        }
        else
            _fmpz_vec_set(r, g, 3);
        _wc_zvec3_cross_fast(h, G + 3 * S[(i + 1) % m], G + 3 * S[i]);
        _wc_zvec3_primitive(h, t);
    }
}

/* The fan of the hull S[0..m), set in F when w . g > 0 for every
   generator, w the sum of the inward facet normals (the certificate).  */
static int
certify(_wc_fan3_t F, fan_ctx * c, const slong * S, slong m, slong k,
        fmpz * w)
{
    slong i;
    int ok = 1;

    fill(F, c->G, S, m, c->t);
    _fmpz_vec_zero(w, 3);
    for (i = 0; i < m; i++)
        _fmpz_vec_sub(w, w, F->facets + 3 * i, 3);
    for (i = 0; i < k && ok; i++)
        ok = _wc_zvec3_dot_sgn_fast(w, GV(c, i), c->t) > 0;
    if (!ok)
        _wc_fan3_clear(F);
    return ok;
}

/* The chart d . x = 1 of a cone with d . g > 0 for every generator:
   coordinates (g_j1, g_j2) / (d . g) for the two indices other than one
   where d is not 0.  */
typedef struct
{
    const fmpz * G;
    fmpz * dg;                  /* k: d . g_i */
    int j1, j2, s;              /* s: the sign of det(e_j1, e_j2, d) */
    fmpz_t t, u;
}
chart_ctx;

/* Lexicographic order of the chart points.  */
static int
chart_cmp(void * ctx, slong a, slong b)
{
    chart_ctx * c = ctx;
    int j, r = 0;

    for (j = 0; j < 2 && r == 0; j++)
    {
        int i = j == 0 ? c->j1 : c->j2;

        fmpz_mul(c->t, c->G + 3 * a + i, c->dg + b);
        fmpz_mul(c->u, c->G + 3 * b + i, c->dg + a);
        r = fmpz_cmp(c->t, c->u);
    }
    return r;
}

/* 1 when the chart points a, b, x turn left.  */
static int
chart_left(chart_ctx * c, slong a, slong b, slong x)
{
    return c->s * det_sgn(c->G + 3 * a, c->G + 3 * b, c->G + 3 * x, c->t,
                          c->u) > 0;
}

/* Andrew's monotone chain over the sorted chart points x[0..k) into H
   (2k slots): the hull, counterclockwise in the chart, without points on
   its edges.  Returns its size.  */
static slong
chain(chart_ctx * c, const slong * x, slong k, slong * H)
{
    slong i, m = 0, low;

    for (i = 0; i < k; i++)
    {
        while (m >= 2 && !chart_left(c, H[m - 2], H[m - 1], x[i]))
            m--;
        H[m++] = x[i];
    }
    low = m + 1;
    for (i = k - 2; i >= 0; i--)
    {
        while (m >= low && !chart_left(c, H[m - 2], H[m - 1], x[i]))
            m--;
        H[m++] = x[i];
    }
    return m - 1;
}

/* F := the fan of pos(G), which d proves pointed (d . g > 0 for every
   generator; G spans R^3).  O(k log k).  */
static int
chart_fan(_wc_fan3_t F, const fmpz * G, slong k, const fmpz * d)
{
    chart_ctx c;
    slong * x = malloc(sizeof(slong) * 4 * k), i, m;
    int j, res = x == NULL ? WC_FAN3_NOMEM : WC_FAN3_POINTED;

    c.G = G;
    c.dg = _fmpz_vec_init(k);
    fmpz_init(c.t);
    fmpz_init(c.u);
    for (j = 0; fmpz_is_zero(d + j); j++)
        ;
    c.j1 = (j + 1) % 3;
    c.j2 = (j + 2) % 3;
    c.s = fmpz_sgn(d + j);      /* det(e_j+1, e_j+2, d) = d_j */
    if (x != NULL)
    {
        for (i = 0; i < k; i++)
        {
            _wc_zvec3_dot_fast(c.dg + i, d, G + 3 * i);
            x[i] = i;
        }
        sort_idx(chart_cmp, &c, x, x + k, k);
        m = chain(&c, x, k, x + k);
        if (c.s < 0)            /* det > 0 along the fan */
            for (i = 0; i < m / 2; i++)
            {
                slong y = x[k + i];

                x[k + i] = x[k + m - 1 - i];
                x[k + m - 1 - i] = y;
            }
        fill(F, G, x + k, m, c.t);
    }
    _fmpz_vec_clear(c.dg, k);
    fmpz_clear(c.t);
    fmpz_clear(c.u);
    free(x);
    return res;
}

/* When the angular scan does not settle a cone spanning R^3: the exact
   linear program of polar3.c says pointed (then the chart's hull), R^3,
   or neither.  */
static int
by_polar(_wc_fan3_t F, const fmpz * G, slong k)
{
    fmpz * V = _fmpz_vec_init(6);
    int r = _wc_polar3(V, G, k);

    r = r == WC_POLAR3_NOMEM ? WC_FAN3_NOMEM
        : r == WC_POLAR3_SPACE ? WC_FAN3_SPACE
        : r == WC_POLAR3_POINTED ? chart_fan(F, G, k, V) : WC_FAN3_OTHER;
    _fmpz_vec_clear(V, 6);
    return r;
}

/* q != 0, the generators span R^3, c->qx is set: the angular sort and
   the scan.  x, y, z: k slots each.  */
static int
fan_axis(_wc_fan3_t F, fan_ctx * c, const fmpz * q, slong k, slong * x,
         slong * y, slong * z, fmpz * w)
{
    fmpz * n = _fmpz_vec_init(3), * r = _fmpz_vec_init(3);
    slong i, p = 0, g0 = -1, s, m;
    int res = WC_FAN3_OTHER;

    for (i = 0; i < k && g0 < 0; i++)
        if (!_fmpz_vec_is_zero(c->qx + 3 * i, 3))
            g0 = i;
    _fmpz_vec_set(n, c->qx + 3 * g0, 3);
    _wc_zvec3_cross(r, n, q);           /* toward g0 in the plane (q, g0) */
    for (i = 0; i < k; i++)
    {
        int sg;

        if (_fmpz_vec_is_zero(c->qx + 3 * i, 3))
        {
            if (_wc_zvec3_dot_sgn_fast(q, GV(c, i), c->t) < 0)
            {
                res = WC_FAN3_SPACE;    /* -q in the cone, q interior */
                goto done;
            }
            continue;                   /* on the axis: not extreme */
        }
        sg = _wc_zvec3_dot_sgn_fast(n, GV(c, i), c->t);
        c->half[i] = !(sg > 0
                       || (sg == 0
                           && _wc_zvec3_dot_sgn_fast(r, GV(c, i), c->t) > 0));
        x[p++] = i;
    }
    sort_idx(ang_cmp, c, x, y, p);
    p = outermost(c, x, p, w);
    if (p < 3)
        goto done;
    s = farthest(c, q, x, p);
    m = scan(c, q, x, p, s, z);
    if (m >= 3 && !contained(c, x, p, s, z, m))
        m = 0;
    if (m >= 3 && certify(F, c, z, m, k, w))
        res = WC_FAN3_POINTED;
    else if (space_by_triple(c, q, x, p, y))
        res = WC_FAN3_SPACE;

done:
    _fmpz_vec_clear(n, 3);
    _fmpz_vec_clear(r, 3);
    return res;
}

int
_wc_fan3(_wc_fan3_t F, const fmpz * G, slong k)
{
    fan_ctx c;
    fmpz * q, * w;
    slong i, * x = NULL;
    int res = WC_FAN3_OTHER, planar = 1;

    if (k < 3)
        return WC_FAN3_OTHER;
    q = _fmpz_vec_init(3);
    w = _fmpz_vec_init(3);
    c.G = G;
    c.qx = _fmpz_vec_init(3 * k);
#ifdef __SIZEOF_INT128__
    c.qw = NULL;
#endif
    c.half = malloc(k);
    x = malloc(sizeof(slong) * 3 * k);
    fmpz_init(c.t);
    fmpz_init(c.u);
    if (c.half == NULL || x == NULL)
    {
        res = WC_FAN3_NOMEM;
        goto cleanup;
    }
    for (i = 0; i < k; i++)
        _fmpz_vec_add(q, q, G + 3 * i, 3);
    if (_fmpz_vec_is_zero(q, 3))
    {
        res = spans(G, k, w, c.t) ? WC_FAN3_SPACE : WC_FAN3_OTHER;
        goto cleanup;
    }
    /* Rank 3 iff some generator leaves the plane of q and g0.  */
    for (i = 0; i < k; i++)
        _wc_zvec3_cross_fast(c.qx + 3 * i, q, G + 3 * i);
    for (i = 0; i < k && _fmpz_vec_is_zero(c.qx + 3 * i, 3); i++)
        ;
    if (i < k)
    {
        const fmpz * n = c.qx + 3 * i;

        for (i = 0; i < k && planar; i++)
            planar = _wc_zvec3_dot_sgn_fast(n, G + 3 * i, c.t) == 0;
    }
    if (!planar && !set_qw(&c, q, k))
        res = WC_FAN3_NOMEM;
    else if (!planar)
        res = fan_axis(F, &c, q, k, x, x + k, x + 2 * k, w);
    if (res == WC_FAN3_OTHER && !planar)
        res = by_polar(F, G, k);

cleanup:
    _fmpz_vec_clear(q, 3);
    _fmpz_vec_clear(w, 3);
    _fmpz_vec_clear(c.qx, 3 * k);
#ifdef __SIZEOF_INT128__
    free(c.qw);
#endif
    free(c.half);
    free(x);
    fmpz_clear(c.t);
    fmpz_clear(c.u);
    return res;
}
