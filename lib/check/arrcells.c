/* arrcells.c -- the cells of a central arrangement of planes in R^3, the
   checker's own enumeration, in GMP.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The solver enumerates the same cells in exact/cells.c with FLINT; this
   is a second walk, written apart from it, so that the cells a
   stability-set certificate lists are checked by other code than the
   code that wrote them.  The planes span R^3 (the coordinate planes are
   among them), so every cell is a pointed cone:
     1. Lines.  Every line of the arrangement is h_p x h_q for some pair
        p < q; the m (m - 1) / 2 cross products, primitive with their
        first nonzero entry positive, are sorted and the repeats merged.
        Line l gives the rays 2 l (along it) and 2 l + 1 (against it),
        the one-dimensional cells; their signs are sign(h_q . l).
     2. Sectors.  The lines on plane p (at least two: the coordinate
        planes cut it in two lines) are turned to one side of the first
        one, u: sign det(h_p, u, d) > 0, and sorted by angle with
        det(h_p, a, b) > 0 meaning a before b, exact and strict inside
        the open half-plane.  Then u, the sorted lines and their
        opposites go once around the plane, and two neighbours a, b,
        at an angle below pi, bound an open sector, a two-dimensional
        cell, with the point a + b.  No plane q crosses the sector
        (its line on p would come between a and b), so the sector's
        sign for q is that of a, or that of b where a's is 0.
     3. Chambers.  The sector of plane p with the sign vector s is a
        facet of the two chambers whose sign vectors are s with entry p
        set to +1 and to -1.  Every chamber is pointed, so it has
        facets, and its extreme rays -- the rays in its closure -- are
        the rays of its facets.  The 2 (number of sectors) sign vectors
        are sorted and the equal ones merged into one chamber each, with
        the union of their rays and their sum as its point.
     4. Order.  The origin, the rays, the sectors and the chambers are
        sorted by dimension, then by sign vector (- < 0 < +), and every
        cell's rays renamed to their places in that order.
   The cost: m (m - 1) / 2 cross products, two products for every
   comparison of the angular sorts (O(m^2 log m) in all), and one
   product for each line and plane; the sign vectors of the sectors and
   chambers take no products.  Planes that break the promise of
   checker.h (parallel ones, or too few to span R^3) give WC_EINTERNAL,
   as running out of memory does.  */

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check/checker.h"

/* ------------------------------------------------------------------ */
/* Sorting indices.                                                    */

/* < 0, 0 or > 0 as a comes before, with or after b.  */
typedef int (*order_fn)(void * ctx, size_t a, size_t b);

/* Sort ix[0 .. n) by cmp (a stable bottom-up merge sort); tmp has room
   for n entries.  */
static void
merge_sort(size_t * ix, size_t * tmp, size_t n, order_fn cmp, void * ctx)
{
    size_t * from = ix, * to = tmp, * x;
    size_t w, i;

    for (w = 1; w < n; w = n - w > w ? 2 * w : n)
    {
        for (i = 0; i < n; )
        {
            size_t mid = n - i > w ? i + w : n;
            size_t hi = n - mid > w ? mid + w : n;
            size_t a = i, b = mid;

            while (a < mid && b < hi)
                to[i++] = cmp(ctx, from[b], from[a]) < 0
                    ? from[b++] : from[a++];
            while (a < mid)
                to[i++] = from[a++];
            while (b < hi)
                to[i++] = from[b++];
        }
        x = from;
        from = to;
        to = x;
    }
    if (from != ix)
        memcpy(ix, from, n * sizeof(size_t));
}

static int
sort_index(size_t * ix, size_t n, order_fn cmp, void * ctx)
{
    size_t * tmp = _wc_check_alloc(n, sizeof(size_t));

    if (tmp == NULL)
        return WC_EINTERNAL;
    merge_sort(ix, tmp, n, cmp, ctx);
    free(tmp);
    return WC_OK;
}

static int
size_cmp(const void * a, const void * b)
{
    size_t x = *(const size_t *) a, y = *(const size_t *) b;

    return x < y ? -1 : x > y;
}

/* Sort v[0 .. n) and drop repeats; returns how many are left.  */
static size_t
sort_unique(size_t * v, size_t n)
{
    size_t i, k = 0;

    if (n == 0)
        return 0;
    qsort(v, n, sizeof(size_t), size_cmp);
    for (i = 1; i < n; i++)
        if (v[i] != v[k])
            v[++k] = v[i];
    return k + 1;
}

/* Sign vectors entry by entry, - < 0 < +.  */
static int
sign_cmp(const signed char * a, const signed char * b, size_t m)
{
    size_t p;

    for (p = 0; p < m; p++)
        if (a[p] != b[p])
            return a[p] < b[p] ? -1 : 1;
    return 0;
}

/* ------------------------------------------------------------------ */
/* The cells, as arrays.                                               */

void
_wc_check_cells_init(wc_check_cells * A)
{
    memset(A, 0, sizeof *A);
}

void
_wc_check_cells_clear(wc_check_cells * A)
{
    _wc_check_zvec_free(A->point, 3 * A->count);
    free(A->dim);
    free(A->sign);
    free(A->rayoff);
    free(A->ray);
    memset(A, 0, sizeof *A);
}

/* A (empty) := room for count cells of nplanes planes with nray rays in
   all.  */
static int
cells_alloc(wc_check_cells * A, size_t count, size_t nplanes, size_t nray)
{
    A->point = _wc_check_zvec_new(_wc_check_times(3, count));
    A->dim = _wc_check_alloc(count, 1);
    A->sign = _wc_check_alloc(_wc_check_times(count, nplanes), 1);
    A->rayoff = _wc_check_alloc(count + 1, sizeof(size_t));
    A->ray = _wc_check_alloc(nray, sizeof(size_t));
    A->nplanes = nplanes;
    A->count = count;
    if (A->point == NULL)
        A->count = 0;
    if (A->point == NULL || A->dim == NULL || A->sign == NULL
        || A->rayoff == NULL || A->ray == NULL)
    {
        _wc_check_cells_clear(A);
        return WC_EINTERNAL;
    }
    A->rayoff[0] = 0;
    return WC_OK;
}

/* ------------------------------------------------------------------ */
/* The walk.                                                           */

typedef struct
{
    size_t m;
    mpz_t * H;              /* 3 m */
    unsigned long work;
    size_t npairs;
    mpz_t * pv;             /* 3 npairs: h_p x h_q, primitive, canonical */
    size_t * pairline;      /* npairs: the line of each pair */
    size_t nline;
    size_t * linerep;       /* nline: a pair of each line */
    signed char * lsign;    /* nline m: sign(h_q . line) */
    size_t * pl;            /* m (m - 1): the lines on plane p from
                               pl[p (m - 1)], kp[p] of them */
    size_t * kp;            /* m */
    size_t nsec;
    size_t * secplane;      /* nsec */
    size_t * secray;        /* 2 nsec: the rays bounding each sector */
    signed char * ssign;    /* nsec m */
    size_t ncand;
    signed char * csign;    /* ncand m, ncand = 2 nsec: the chambers'
                               sign vectors, one per facet */
    size_t * cand;          /* ncand: the candidates, sorted */
    size_t ncham;
    size_t * chamrep;       /* ncham: a candidate of each chamber */
    size_t * chamoff;       /* ncham + 1 */
    size_t * chamray;       /* 2 ncand at most */
    mpz_t * c;              /* 3, scratch */
    mpz_t t;
}
walk;

static void
walk_clear(walk * W)
{
    _wc_check_zvec_free(W->pv, 3 * W->npairs);
    free(W->pairline);
    free(W->linerep);
    free(W->lsign);
    free(W->pl);
    free(W->kp);
    free(W->secplane);
    free(W->secray);
    free(W->ssign);
    free(W->csign);
    free(W->cand);
    free(W->chamrep);
    free(W->chamoff);
    free(W->chamray);
    _wc_check_zvec_free(W->c, 3);
    mpz_clear(W->t);
}

/* The vector of line l.  */
static mpz_t *
line_vec(const walk * W, size_t l)
{
    return W->pv + 3 * W->linerep[l];
}

/* sign(h_q . r) for the ray r.  */
static int
ray_sign(const walk * W, size_t r, size_t q)
{
    int s = W->lsign[(r >> 1) * W->m + q];

    return (r & 1) ? -s : s;
}

/* out += the vector of ray r.  */
static void
add_ray(const walk * W, mpz_t * out, size_t r)
{
    mpz_t * d = line_vec(W, r >> 1);
    int j;

    for (j = 0; j < 3; j++)
        if (r & 1)
            mpz_sub(out[j], out[j], d[j]);
        else
            mpz_add(out[j], out[j], d[j]);
}

/* sign(h . (a x b)), counted.  */
static int
det_sign(walk * W, mpz_t * h, mpz_t * a, mpz_t * b)
{
    W->work += 2;
    _wc_check_zcross3(W->c, a, b);
    _wc_check_zdot3(W->t, h, W->c);
    return mpz_sgn(W->t);
}

static int
pair_order(void * ctx, size_t a, size_t b)
{
    const walk * W = ctx;
    int j, d;

    for (j = 0; j < 3; j++)
        if ((d = mpz_cmp(W->pv[3 * a + j], W->pv[3 * b + j])) != 0)
            return d;
    return 0;
}

/* Step 1: the cross products of all pairs, their lines, the lines'
   signs.  */
static int
find_lines(walk * W)
{
    size_t m = W->m, p, q, k, l, * ix;
    int j;

    W->npairs = m * (m - 1) / 2;
    W->pv = _wc_check_zvec_new(_wc_check_times(3, W->npairs));
    W->pairline = _wc_check_alloc(W->npairs, sizeof(size_t));
    W->linerep = _wc_check_alloc(W->npairs, sizeof(size_t));
    if (W->pv == NULL)
        W->npairs = 0;
    if (W->pv == NULL || W->pairline == NULL || W->linerep == NULL)
        return WC_EINTERNAL;
    for (p = 0, k = 0; p < m; p++)
        for (q = p + 1; q < m; q++, k++)
        {
            mpz_t * v = W->pv + 3 * k;

            W->work++;
            _wc_check_zcross3(v, W->H + 3 * p, W->H + 3 * q);
            for (j = 0; j < 3 && mpz_sgn(v[j]) == 0; j++)
                ;
            if (j == 3)
                return WC_EINTERNAL;        /* parallel planes */
            _wc_check_zprimitive(v, W->t);
            if (mpz_sgn(v[j]) < 0)
                for (j = 0; j < 3; j++)
                    mpz_neg(v[j], v[j]);
        }
    ix = W->linerep;                /* the sorted pairs, for now */
    for (k = 0; k < W->npairs; k++)
        ix[k] = k;
    if (sort_index(ix, W->npairs, pair_order, W) != WC_OK)
        return WC_EINTERNAL;
    for (k = 0, l = 0; k < W->npairs; k++)
    {
        if (k > 0 && pair_order(W, ix[k - 1], ix[k]) != 0)
            l++;
        W->pairline[ix[k]] = l;
    }
    W->nline = W->npairs > 0 ? l + 1 : 0;
    for (k = 0; k < W->npairs; k++)
        ix[W->pairline[k]] = k;
    W->lsign = _wc_check_alloc(_wc_check_times(W->nline, m), 1);
    if (W->lsign == NULL)
        return WC_EINTERNAL;
    for (l = 0; l < W->nline; l++)
        for (q = 0; q < m; q++)
        {
            W->work++;
            _wc_check_zdot3(W->t, W->H + 3 * q, line_vec(W, l));
            W->lsign[l * m + q] = (signed char) mpz_sgn(W->t);
        }
    return WC_OK;
}

/* The lines on each plane, each once.  */
static int
plane_lines(walk * W)
{
    size_t m = W->m, p, q, k;

    W->pl = _wc_check_alloc(_wc_check_times(m, m - 1), sizeof(size_t));
    W->kp = _wc_check_alloc(m, sizeof(size_t));
    if (W->pl == NULL || W->kp == NULL)
        return WC_EINTERNAL;
    memset(W->kp, 0, m * sizeof(size_t));
    for (p = 0, k = 0; p < m; p++)
        for (q = p + 1; q < m; q++, k++)
        {
            W->pl[p * (m - 1) + W->kp[p]++] = W->pairline[k];
            W->pl[q * (m - 1) + W->kp[q]++] = W->pairline[k];
        }
    W->nsec = 0;
    for (p = 0; p < m; p++)
    {
        W->kp[p] = sort_unique(W->pl + p * (m - 1), W->kp[p]);
        if (W->kp[p] < 2)
            return WC_EINTERNAL;            /* the planes do not span */
        W->nsec += 2 * W->kp[p];
    }
    return WC_OK;
}

/* The angular order on one plane: entries of list, turned by sig.  */
typedef struct
{
    walk * W;
    mpz_t * h;
    const size_t * list;
    const signed char * sig;
}
angle_ctx;

static int
angle_order(void * ctx, size_t a, size_t b)
{
    angle_ctx * X = ctx;
    int s = det_sign(X->W, X->h, line_vec(X->W, X->list[a]),
                     line_vec(X->W, X->list[b]));

    return -s * X->sig[a] * X->sig[b];
}

/* Step 2 on plane p: the rays around it into dir[0 .. 2 k), k = kp[p];
   ix and sig have room for k entries.  */
static int
plane_rays(walk * W, size_t p, size_t * dir, size_t * ix,
           signed char * sig)
{
    size_t k = W->kp[p], i;
    angle_ctx X;

    X.W = W;
    X.h = W->H + 3 * p;
    X.list = W->pl + p * (W->m - 1);
    X.sig = sig;
    sig[0] = 1;
    for (i = 1; i < k; i++)
    {
        sig[i] = (signed char) det_sign(W, X.h, line_vec(W, X.list[0]),
                                        line_vec(W, X.list[i]));
        if (sig[i] == 0)
            return WC_EINTERNAL;            /* a line off the plane */
        ix[i - 1] = i;
    }
    if (sort_index(ix, k - 1, angle_order, &X) != WC_OK)
        return WC_EINTERNAL;
    dir[0] = 2 * X.list[0];
    for (i = 1; i < k; i++)
        dir[i] = 2 * X.list[ix[i - 1]] + (sig[ix[i - 1]] < 0);
    for (i = 0; i < k; i++)
        dir[k + i] = dir[i] ^ 1;
    return WC_OK;
}

/* Step 2: the sectors of every plane, with their sign vectors.  */
static int
find_sectors(walk * W)
{
    size_t m = W->m, p, q, i, s = 0;
    size_t * ix = _wc_check_alloc(m, sizeof(size_t));
    size_t * dir = _wc_check_alloc(_wc_check_times(2, m), sizeof(size_t));
    signed char * sig = _wc_check_alloc(m, 1);
    int status = WC_OK;

    W->secplane = _wc_check_alloc(W->nsec, sizeof(size_t));
    W->secray = _wc_check_alloc(_wc_check_times(2, W->nsec),
                                sizeof(size_t));
    W->ssign = _wc_check_alloc(_wc_check_times(W->nsec, m), 1);
    if (ix == NULL || dir == NULL || sig == NULL || W->secplane == NULL
        || W->secray == NULL || W->ssign == NULL)
        status = WC_EINTERNAL;
    for (p = 0; p < m && status == WC_OK; p++)
    {
        size_t k = W->kp[p];

        status = plane_rays(W, p, dir, ix, sig);
        for (i = 0; i < 2 * k && status == WC_OK; i++, s++)
        {
            size_t a = dir[i], b = dir[(i + 1) % (2 * k)];

            W->secplane[s] = p;
            W->secray[2 * s] = a;
            W->secray[2 * s + 1] = b;
            for (q = 0; q < m; q++)
            {
                int sa = ray_sign(W, a, q);

                W->ssign[s * m + q] =
                    (signed char) (sa != 0 ? sa : ray_sign(W, b, q));
            }
        }
    }
    free(ix);
    free(dir);
    free(sig);
    return status;
}

static int
cand_order(void * ctx, size_t a, size_t b)
{
    const walk * W = ctx;

    return memcmp(W->csign + a * W->m, W->csign + b * W->m, W->m);
}

/* Step 3: the chambers, each with its rays.  */
static int
find_chambers(walk * W)
{
    size_t m = W->m, c, i, j, n = 0, g;

    W->ncand = 2 * W->nsec;
    W->csign = _wc_check_alloc(_wc_check_times(W->ncand, m), 1);
    W->cand = _wc_check_alloc(W->ncand, sizeof(size_t));
    W->chamrep = _wc_check_alloc(W->ncand, sizeof(size_t));
    W->chamoff = _wc_check_alloc(W->ncand + 1, sizeof(size_t));
    W->chamray = _wc_check_alloc(_wc_check_times(2, W->ncand),
                                 sizeof(size_t));
    if (W->csign == NULL || W->cand == NULL || W->chamrep == NULL
        || W->chamoff == NULL || W->chamray == NULL)
        return WC_EINTERNAL;
    for (c = 0; c < W->ncand; c++)
    {
        size_t s = c >> 1;

        memcpy(W->csign + c * m, W->ssign + s * m, m);
        W->csign[c * m + W->secplane[s]] = (c & 1) ? -1 : 1;
        W->cand[c] = c;
    }
    if (sort_index(W->cand, W->ncand, cand_order, W) != WC_OK)
        return WC_EINTERNAL;
    W->ncham = 0;
    W->chamoff[0] = 0;
    for (i = 0; i < W->ncand; i = j)
    {
        for (j = i, g = n; j < W->ncand
             && cand_order(W, W->cand[i], W->cand[j]) == 0; j++)
        {
            size_t s = W->cand[j] >> 1;

            W->chamray[n++] = W->secray[2 * s];
            W->chamray[n++] = W->secray[2 * s + 1];
        }
        n = g + sort_unique(W->chamray + g, n - g);
        W->chamrep[W->ncham++] = W->cand[i];
        W->chamoff[W->ncham] = n;
    }
    return WC_OK;
}

/* ------------------------------------------------------------------ */
/* Putting the cells together.                                         */

/* Step 4, first half: the cells in the walk's order into T (empty): the
   origin, ray r as 1 + r, sector s as 1 + 2 nline + s, chamber c after
   the sectors.  */
static int
unsorted_cells(wc_check_cells * T, walk * W)
{
    size_t m = W->m, r0 = 1, s0 = 1 + 2 * W->nline, c0 = s0 + W->nsec;
    size_t count = c0 + W->ncham, i, j, n = 0;

    if (cells_alloc(T, count, m, 2 * W->nline + 2 * W->nsec
                    + W->chamoff[W->ncham]) != WC_OK)
        return WC_EINTERNAL;
    memset(T->sign, 0, m);
    T->dim[0] = 0;
    T->rayoff[1] = 0;
    for (i = 0; i < 2 * W->nline; i++)
    {
        T->dim[r0 + i] = 1;
        for (j = 0; j < m; j++)
            T->sign[(r0 + i) * m + j] = (signed char) ray_sign(W, i, j);
        add_ray(W, T->point + 3 * (r0 + i), i);
        T->ray[n++] = r0 + i;
        T->rayoff[r0 + i + 1] = n;
    }
    for (i = 0; i < W->nsec; i++)
    {
        mpz_t * x = T->point + 3 * (s0 + i);

        T->dim[s0 + i] = 2;
        memcpy(T->sign + (s0 + i) * m, W->ssign + i * m, m);
        for (j = 0; j < 2; j++)
        {
            add_ray(W, x, W->secray[2 * i + j]);
            T->ray[n++] = r0 + W->secray[2 * i + j];
        }
        _wc_check_zprimitive(x, W->t);
        T->rayoff[s0 + i + 1] = n;
    }
    for (i = 0; i < W->ncham; i++)
    {
        mpz_t * x = T->point + 3 * (c0 + i);

        T->dim[c0 + i] = 3;
        memcpy(T->sign + (c0 + i) * m, W->csign + W->chamrep[i] * m, m);
        for (j = W->chamoff[i]; j < W->chamoff[i + 1]; j++)
        {
            add_ray(W, x, W->chamray[j]);
            T->ray[n++] = r0 + W->chamray[j];
        }
        _wc_check_zprimitive(x, W->t);
        T->rayoff[c0 + i + 1] = n;
    }
    return WC_OK;
}

static int
cell_order(void * ctx, size_t a, size_t b)
{
    const wc_check_cells * T = ctx;

    if (T->dim[a] != T->dim[b])
        return T->dim[a] < T->dim[b] ? -1 : 1;
    return sign_cmp(T->sign + a * T->nplanes, T->sign + b * T->nplanes,
                    T->nplanes);
}

/* Step 4, second half: A (empty) := the cells of T in order.  */
static int
sorted_cells(wc_check_cells * A, wc_check_cells * T)
{
    size_t n = T->count, m = T->nplanes, i, j, k = 0;
    size_t * perm = _wc_check_alloc(n, sizeof(size_t));
    size_t * place = _wc_check_alloc(n, sizeof(size_t));
    int status = WC_EINTERNAL;

    if (perm == NULL || place == NULL)
        goto done;
    for (i = 0; i < n; i++)
        perm[i] = i;
    if (sort_index(perm, n, cell_order, T) != WC_OK)
        goto done;
    for (i = 0; i < n; i++)
        place[perm[i]] = i;
    if (cells_alloc(A, n, m, T->rayoff[n]) != WC_OK)
        goto done;
    for (i = 0; i < n; i++)
    {
        size_t o = perm[i];

        A->dim[i] = T->dim[o];
        memcpy(A->sign + i * m, T->sign + o * m, m);
        for (j = 0; j < 3; j++)
            mpz_swap(A->point[3 * i + j], T->point[3 * o + j]);
        for (j = T->rayoff[o]; j < T->rayoff[o + 1]; j++)
            A->ray[k++] = place[T->ray[j]];
        qsort(A->ray + A->rayoff[i], k - A->rayoff[i], sizeof(size_t),
              size_cmp);
        A->rayoff[i + 1] = k;
    }
    status = WC_OK;
done:
    free(perm);
    free(place);
    return status;
}

int
_wc_check_cells_build(wc_check_cells * A, mpz_t * H, size_t nplanes)
{
    wc_check_cells T;
    walk W;
    int status;

    _wc_check_cells_clear(A);
    _wc_check_cells_init(&T);
    memset(&W, 0, sizeof W);
    mpz_init(W.t);
    W.m = nplanes;
    W.H = H;
    W.c = _wc_check_zvec_new(3);
    status = W.c == NULL || nplanes < 3 ? WC_EINTERNAL
        : find_lines(&W);
    if (status == WC_OK)
        status = plane_lines(&W);
    if (status == WC_OK)
        status = find_sectors(&W);
    if (status == WC_OK)
        status = find_chambers(&W);
    if (status == WC_OK)
        status = unsorted_cells(&T, &W);
    if (status == WC_OK)
        status = sorted_cells(A, &T);
    A->work = W.work;
    walk_clear(&W);
    _wc_check_cells_clear(&T);
    return status;
}
