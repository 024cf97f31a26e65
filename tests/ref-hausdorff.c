/* ref-hausdorff.c -- an independent reference for the directed angular
   distance sup { angle(x, cl B) : x in cl A, |x| = 1 }.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Written from lib/float/compare.h (the contract) and SPEC.md only,
   without reading lib/float or tests/old-hausdorff.c; it reads the two
   canonical cones' fields and uses nothing else of the library.  A
   different method from the library's (which splits R^3 into the cells
   of B's normal fan and maximises exactly on each): global optimisation
   of f(x) = angle(x, cl B) over cl A on the unit sphere by branch and
   bound, in doubles.

   f at one point, brute force: the nearest point of cl B to x is the
   projection of x onto the span of the face holding it in its relative
   interior, spanned by the lines and at most two extreme rays; every
   such projection that is a nonnegative combination lies in cl B, so
   the smallest angle over them, over x itself when x is in cl B and over
   the rays and +-lines (the nearest directions when x is in the polar
   cone) is f(x).

   The domain: cl A on the sphere cut into spherical triangles (the eight
   octants clipped by A's facets, fan-triangulated; for a plane, its four
   quarter circles clipped; for a ray or line, its points).  On a piece S
   with unit vertices v_i and centre c, sup f is bounded above by the
   least of
   - f(c) + max angle(c, v_i): f is 1-Lipschitz on the sphere;
   - asin(max d_B(v_i) / rho), rho = min v_i . c <= |x| on the flat
     simplex: d_B (Euclidean distance to cl B) is convex and homogeneous,
     and sin f = d_B on unit vectors below pi/2;
   - acos(m or m / rho), m = min v_i . b with b the nearest unit vector of
     cl B to c: cos f(y) = max over unit b of y . b is at least y . b.
   The first is tight near peaks, the other two to second order near
   smooth maxima and where f is near 0.  Pieces are refined best-first
   until the largest bound is within tol of the best value found.  */

#include <config.h>

#include <math.h>
#include <stdlib.h>

#include "ref-hausdorff.h"

#define SLACK 1e-12             /* rounding allowance of every bound */

typedef struct
{
    slong nr, nl, nh, ne;
    double * r, * l, * h, * e;  /* unit vectors, 3 doubles each */
}
dcone;

static double
dot(const double * a, const double * b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void
cross(double * c, const double * a, const double * b)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double
norm(const double * a)
{
    return sqrt(dot(a, a));
}

static int
unit(double * a)
{
    double n = norm(a);

    if (!(n > 0))
        return 0;
    a[0] /= n;
    a[1] /= n;
    a[2] /= n;
    return 1;
}

static double
angle(const double * a, const double * b)
{
    double c[3];

    cross(c, a, b);
    return atan2(norm(c), dot(a, b));
}

/* The rows of M as unit doubles; orthonormalised when ortho.  */
static double *
rows_of(slong * n, const fmpz_mat_t M, int ortho)
{
    slong i, j, k;
    double * v = malloc(sizeof(double) * 3 * (fmpz_mat_nrows(M) + 1));

    *n = 0;
    for (i = 0; i < fmpz_mat_nrows(M); i++)
    {
        double * x = v + 3 * *n;

        for (j = 0; j < 3; j++)
            x[j] = fmpz_get_d(fmpz_mat_entry(M, i, j));
        for (k = 0; ortho && k < *n; k++)
        {
            double t = dot(x, v + 3 * k);

            for (j = 0; j < 3; j++)
                x[j] -= t * v[3 * k + j];
        }
        if (unit(x))
            (*n)++;
    }
    return v;
}

static void
dcone_init(dcone * D, const wc_cone_t C)
{
    D->r = rows_of(&D->nr, C->rays, 0);
    D->l = rows_of(&D->nl, C->lines, 1);
    D->h = rows_of(&D->nh, C->ineqs, 0);
    D->e = rows_of(&D->ne, C->eqs, 0);
}

static void
dcone_clear(dcone * D)
{
    free(D->r);
    free(D->l);
    free(D->h);
    free(D->e);
}

/* Keep p (a point of cl B) when it is nearer to x than the best so far.  */
static void
consider(double * best, double * near, const double * x, const double * p)
{
    double a, n = norm(p);

    if (!(n > 1e-300))
        return;
    a = angle(x, p);
    if (a < *best)
    {
        *best = a;
        near[0] = p[0] / n;
        near[1] = p[1] / n;
        near[2] = p[2] / n;
    }
}

static double
dangle_to(double * near, const double * x, const dcone * B)
{
    double best = INFINITY, xl[3] = { 0, 0, 0 }, xp[3], p[3], nb[3];
    slong i, j, k;
    int in = 1;

    if (near == NULL)
        near = nb;
    for (i = 0; i < B->nl; i++)
    {
        double t = dot(x, B->l + 3 * i), m[3];

        for (k = 0; k < 3; k++)
        {
            xl[k] += t * B->l[3 * i + k];
            m[k] = -B->l[3 * i + k];
        }
        consider(&best, near, x, B->l + 3 * i);
        consider(&best, near, x, m);
    }
    for (k = 0; k < 3; k++)
        xp[k] = x[k] - xl[k];
    consider(&best, near, x, xl);
    for (i = 0; i < B->nh; i++)
        in = in && dot(B->h + 3 * i, x) <= 1e-15;
    for (i = 0; i < B->ne; i++)
        in = in && fabs(dot(B->e + 3 * i, x)) <= 1e-15;
    if (in && (B->nr > 0 || B->nl > 0))
        consider(&best, near, x, x);
    for (i = 0; i < B->nr; i++)
    {
        const double * r = B->r + 3 * i;
        double t = dot(xp, r);

        consider(&best, near, x, r);
        if (t > 0)
        {
            for (k = 0; k < 3; k++)
                p[k] = xl[k] + t * r[k];
            consider(&best, near, x, p);
        }
        for (j = i + 1; j < B->nr; j++)
        {
            const double * s = B->r + 3 * j;
            double g = dot(r, s), det = 1 - g * g, b1 = t, b2 = dot(xp, s);
            double a1, a2;

            if (det < 1e-12)
                continue;
            a1 = (b1 - g * b2) / det;
            a2 = (b2 - g * b1) / det;
            if (a1 < 0 || a2 < 0)
                continue;
            for (k = 0; k < 3; k++)
                p[k] = xl[k] + a1 * r[k] + a2 * s[k];
            consider(&best, near, x, p);
        }
    }
    return best;
}

double
ref_angle_to_cone(double * near, const double * x, const wc_cone_t B)
{
    dcone D;
    double f;

    dcone_init(&D, B);
    f = dangle_to(near, x, &D);
    dcone_clear(&D);
    return f;
}

/* ------------------------------------------------------------------ */
/* Branch and bound.  */

typedef struct
{
    int k;                      /* 1, 2 or 3 vertices */
    int depth;                  /* subdivisions from the first pieces */
    double v[3][3], f[3];       /* unit vertices and f there */
    double ub;
}
piece;

typedef struct
{
    const dcone * B;
    double lo, at[3];
    long evals;
    piece * heap;
    slong n, cap;
}
search;

static double
eval(search * S, double * near, const double * x)
{
    double f = dangle_to(near, x, S->B);

    S->evals++;
    if (f > S->lo)
    {
        S->lo = f;
        S->at[0] = x[0];
        S->at[1] = x[1];
        S->at[2] = x[2];
    }
    return f;
}

/* The upper bound of f on the piece (its vertices' f already set).  */
static void
bound(search * S, piece * P)
{
    double c[3] = { 0, 0, 0 }, b[3], fc, R = 0, rho = 1, D = 0, m = 1;
    double ub = INFINITY;
    int i, j;

    if (P->k == 1)
    {
        P->ub = P->f[0];
        return;
    }
    for (i = 0; i < P->k; i++)
        for (j = 0; j < 3; j++)
            c[j] += P->v[i][j];
    if (!unit(c))
    {
        P->ub = INFINITY;       /* never: pieces are small */
        return;
    }
    fc = eval(S, b, c);
    for (i = 0; i < P->k; i++)
    {
        double a = angle(c, P->v[i]), d;

        R = a > R ? a : R;
        rho = fmin(rho, dot(c, P->v[i]));
        d = P->f[i] <= M_PI / 2 ? sin(P->f[i]) : 1;
        D = fmax(D, d);
        m = fmin(m, dot(P->v[i], b));
    }
    if (R < M_PI / 2)
        ub = fc + R;
    if (rho > 0 && D / rho < 1)
        ub = fmin(ub, asin(D / rho));
    if (rho > 0)
    {
        double s = m >= 0 ? m : m / rho;

        ub = fmin(ub, acos(fmax(-1, fmin(1, s))));
    }
    if (S->B->nl > 0)
        ub = fmin(ub, M_PI / 2);    /* x . (+-l) >= 0 for one sign */
    P->ub = ub + SLACK;
}

/* Larger bounds first; among equal ones (pieces along a ridge capped at
   pi/2), the deepest, so that the best value found approaches the ridge
   in a few steps rather than after the whole ridge is refined.  */
static int
before(const piece * P, const piece * Q)
{
    return P->ub > Q->ub || (P->ub == Q->ub && P->depth > Q->depth);
}

static void
heap_push(search * S, const piece * P)
{
    slong i;

    if (S->n == S->cap)
    {
        S->cap = S->cap ? 2 * S->cap : 64;
        S->heap = realloc(S->heap, sizeof(piece) * S->cap);
    }
    i = S->n++;
    while (i > 0 && before(P, &S->heap[(i - 1) / 2]))
    {
        S->heap[i] = S->heap[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    S->heap[i] = *P;
}

static void
heap_pop(search * S, piece * P)
{
    piece last;
    slong i = 0, c;

    *P = S->heap[0];
    last = S->heap[--S->n];
    while ((c = 2 * i + 1) < S->n)
    {
        if (c + 1 < S->n && before(&S->heap[c + 1], &S->heap[c]))
            c++;
        if (!before(&S->heap[c], &last))
            break;
        S->heap[i] = S->heap[c];
        i = c;
    }
    if (S->n > 0)
        S->heap[i] = last;
}

/* A piece from k unit vertices, f evaluated at each.  */
static void
add_piece(search * S, int depth, int k, const double * v0,
          const double * v1, const double * v2)
{
    const double * v[3] = { v0, v1, v2 };
    piece P;
    int i, j;

    P.k = k;
    P.depth = depth;
    for (i = 0; i < k; i++)
    {
        for (j = 0; j < 3; j++)
            P.v[i][j] = v[i][j];
        P.f[i] = eval(S, NULL, P.v[i]);
    }
    bound(S, &P);
    heap_push(S, &P);
}

/* Clip the polygon V (n unit vectors, cyclic) to h . x <= 0; returns the
   new count (vertices normalised).  */
static int
clip(double (*V)[3], int n, const double * h)
{
    double W[16][3], d[16];
    int i, j, m = 0;

    for (i = 0; i < n; i++)
    {
        d[i] = dot(h, V[i]);
        if (fabs(d[i]) <= 1e-15)
            d[i] = 0;
    }
    for (i = 0; i < n; i++)
    {
        int nx = (i + 1) % n;

        if (d[i] <= 0 && m < 16)
        {
            for (j = 0; j < 3; j++)
                W[m][j] = V[i][j];
            m++;
        }
        if (n > 1 && ((d[i] < 0 && d[nx] > 0) || (d[i] > 0 && d[nx] < 0))
            && m < 16 && (n > 2 || i == 0))
        {
            double t = d[i] / (d[i] - d[nx]);

            for (j = 0; j < 3; j++)
                W[m][j] = V[i][j] + t * (V[nx][j] - V[i][j]);
            unit(W[m]);
            m++;
        }
    }
    for (i = 0; i < m; i++)
        for (j = 0; j < 3; j++)
            V[i][j] = W[i][j];
    return m;
}

static void
split(search * S, const piece * P)
{
    double m[3][3];
    int i, j;

    for (i = 0; i < P->k; i++)
    {
        const double * a = P->v[i], * b = P->v[(i + 1) % P->k];

        for (j = 0; j < 3; j++)
            m[i][j] = a[j] + b[j];
        unit(m[i]);
        if (P->k == 2)
            break;
    }
    /* the vertices' f again: cheap next to the search, and simpler */
    if (P->k == 2)
    {
        add_piece(S, P->depth + 1, 2, P->v[0], m[0], NULL);
        add_piece(S, P->depth + 1, 2, m[0], P->v[1], NULL);
        return;
    }
    add_piece(S, P->depth + 1, 3, P->v[0], m[0], m[2]);
    add_piece(S, P->depth + 1, 3, P->v[1], m[1], m[0]);
    add_piece(S, P->depth + 1, 3, P->v[2], m[2], m[1]);
    add_piece(S, P->depth + 1, 3, m[0], m[1], m[2]);
}

long
ref_directed_angle(double * lo, double * hi, double * at, const wc_cone_t A,
                   const wc_cone_t B, double tol, long maxeval)
{
    dcone DA, DB;
    search S;
    double top;
    slong i, j;

    dcone_init(&DA, A);
    dcone_init(&DB, B);
    S.B = &DB;
    S.lo = 0;
    S.at[0] = S.at[1] = S.at[2] = 0;
    S.evals = 0;
    S.heap = NULL;
    S.n = S.cap = 0;
    if (DA.nr == 0 && DA.nl == 0)
        top = 0;                                /* cl A = {0} */
    else if (DB.nr == 0 && DB.nl == 0)
        top = S.lo = INFINITY;                  /* cl B = {0} */
    else
    {
        slong dim = 3 - DA.ne;

        if (dim == 1)
            for (i = 0; i < DA.nr + 2 * DA.nl; i++)
            {
                double x[3];

                for (j = 0; j < 3; j++)
                    x[j] = i < DA.nr ? DA.r[3 * i + j]
                        : (i - DA.nr) % 2 ? -DA.l[3 * ((i - DA.nr) / 2) + j]
                        : DA.l[3 * ((i - DA.nr) / 2) + j];
                add_piece(&S, 0, 1, x, NULL, NULL);
            }
        else if (dim == 2)
        {
            /* the plane's four quarter circles, clipped */
            double u[3] = { 1, 0, 0 }, w[3], arc[4][2][3];
            const double * e = DA.e;

            if (fabs(e[0]) > 0.6)
                u[0] = 0, u[1] = 1;
            top = dot(u, e);
            for (j = 0; j < 3; j++)
                u[j] -= top * e[j];
            unit(u);
            cross(w, e, u);
            for (i = 0; i < 4; i++)
                for (j = 0; j < 3; j++)
                {
                    double c0 = i == 0 ? 1 : i == 2 ? -1 : 0;
                    double s0 = i == 1 ? 1 : i == 3 ? -1 : 0;
                    double c1 = i == 3 ? 1 : i == 1 ? -1 : 0;
                    double s1 = i == 0 ? 1 : i == 2 ? -1 : 0;

                    arc[i][0][j] = c0 * u[j] + s0 * w[j];
                    arc[i][1][j] = c1 * u[j] + s1 * w[j];
                }
            for (i = 0; i < 4; i++)
            {
                int n = 2;

                for (j = 0; j < DA.nh && n > 0; j++)
                    n = clip(arc[i], n, DA.h + 3 * j);
                if (n == 2 && angle(arc[i][0], arc[i][1]) > 0)
                    add_piece(&S, 0, 2, arc[i][0], arc[i][1], NULL);
                else if (n >= 1)
                    add_piece(&S, 0, 1, arc[i][0], NULL, NULL);
            }
        }
        else
            for (i = 0; i < 8; i++)
            {
                /* octant i, clipped to A and fan-triangulated */
                double V[16][3] = { { 0 } };
                int n = 3, t;

                V[0][0] = i & 1 ? -1 : 1;
                V[1][1] = i & 2 ? -1 : 1;
                V[2][2] = i & 4 ? -1 : 1;
                for (j = 0; j < DA.nh && n > 0; j++)
                    n = clip(V, n, DA.h + 3 * j);
                for (t = 1; t + 1 < n; t++)
                {
                    double c[3];

                    cross(c, V[t], V[t + 1]);
                    if (fabs(dot(c, V[0])) > 1e-14)
                        add_piece(&S, 0, 3, V[0], V[t], V[t + 1]);
                    else if (angle(V[0], V[t]) > 0)
                        add_piece(&S, 0, 2, V[0], V[t], NULL);
                }
                if (n == 2 && angle(V[0], V[1]) > 0)
                    add_piece(&S, 0, 2, V[0], V[1], NULL);
                else if (n == 1)
                    add_piece(&S, 0, 1, V[0], NULL, NULL);
            }
        top = S.lo;
        while (S.n > 0)
        {
            piece P;

            top = fmax(S.lo, S.heap[0].ub);
            if (S.heap[0].ub <= S.lo + tol || S.evals >= maxeval)
                break;
            heap_pop(&S, &P);
            if (P.k > 1)
                split(&S, &P);
            top = S.lo;
        }
    }
    *lo = S.lo;
    *hi = top;
    if (at != NULL)
        for (j = 0; j < 3; j++)
            at[j] = S.at[j];
    free(S.heap);
    dcone_clear(&DA);
    dcone_clear(&DB);
    return S.evals;
}
