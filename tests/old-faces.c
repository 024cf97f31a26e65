/* old-faces.c -- the previous implementation of the moving faces of
   lib/check/faces.c (_wc_check_moving_faces), kept to catch regressions;
   not an independent reference.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The walk lib/check/faces.c used before it walked only the faces of the
   cone of moving directions, line for line: one point in every cell of
   the full arrangement of the planes J_in . x = 0, J_it . x = 0 of the
   touching fixels (O(t^2) points, each mapped to its string in O(n)),
   kept so that t-faces can check that the fast walk finds exactly the
   same set of strings.  The independent reference is ref-faces.c
   (t-facesref).  Do not make it faster.  */

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "old-faces.h"

/* ------------------------------------------------------------------ */
/* The set of sign strings.                                            */

static void
strings_add(wc_check_strings * T, const char * s, size_t n)
{
    char * t;

    if (T->oom)
        return;
    if (T->count == T->cap)
    {
        size_t cap = T->cap < 16 ? 16 : T->cap;
        char ** u;

        if (cap > SIZE_MAX / (2 * sizeof(char *)))
        {
            T->oom = 1;
            return;
        }
        cap *= 2;
        u = realloc(T->s, cap * sizeof(char *));
        if (u == NULL)
        {
            T->oom = 1;
            return;
        }
        T->s = u;
        T->cap = cap;
    }
    t = malloc(n + 1);
    if (t == NULL)
    {
        T->oom = 1;
        return;
    }
    memcpy(t, s, n);
    t[n] = '\0';
    T->s[T->count++] = t;
}

static int
str_cmp(const void * a, const void * b)
{
    return strcmp(*(char * const *) a, *(char * const *) b);
}

/* Sort and drop repeats.  */
static void
strings_finish(wc_check_strings * T)
{
    size_t k, m = 0;

    if (T->count == 0)
        return;
    qsort(T->s, T->count, sizeof(char *), str_cmp);
    for (k = 1; k < T->count; k++)
        if (strcmp(T->s[k], T->s[m]) == 0)
            free(T->s[k]);
        else
            T->s[++m] = T->s[k];
    T->count = m + 1;
}

/* ------------------------------------------------------------------ */
/* The walk.                                                           */

/* The arrangement of the planes h . x = 0, h = J_in and J_it of the
   touching fixels, made primitive integer vectors (positive multiples:
   the signs are those of J_in . x and J_it . x), and the walk's scratch.  */
typedef struct
{
    size_t n;           /* fixels */
    const int * near;
    size_t nh;          /* 2 t normals: J_in, J_it of each touching fixel
                           in order */
    mpz_t * h;          /* 3 nh */
    size_t np;          /* distinct planes */
    size_t * plane;     /* np indices into h */
    char * buf;         /* n + 1 */
    mpz_t s, K;         /* scratch */
    mpz_t * x, * m, * w;        /* 3 each, scratch */
    wc_check_strings * out;
}
arrangement;

/* The rays on one plane, in angular order.  */
typedef struct
{
    size_t max;         /* 2 (nh - 1): both directions of every line */
    mpz_t * ray;        /* 3 per ray */
    int * half;         /* 0: angle in [0, pi) from ray 0; 1: [pi, 2 pi) */
    size_t * idx, * tmp;        /* max each */
    mpz_t * hp;
    mpz_t * cr;         /* 3, scratch */
    mpz_t d;
}
ray_order;

/* The sign string of the point x, into A->out when x has a_in >= 0 at
   every touching fixel and is not n..n.  */
static void
candidate(arrangement * A, mpz_t * x)
{
    size_t i, k = 0;
    int moving = 0;

    for (i = 0; i < A->n; i++)
    {
        int sa;

        if (A->near[i])
        {
            A->buf[i] = 'u';
            continue;
        }
        _wc_check_zdot3(A->s, A->h + 6 * k, x);
        sa = mpz_sgn(A->s);
        if (sa < 0)
            return;
        if (sa > 0)
            A->buf[i] = 's';
        else
        {
            _wc_check_zdot3(A->s, A->h + 6 * k + 3, x);
            sa = mpz_sgn(A->s);
            A->buf[i] = sa > 0 ? 'l' : sa < 0 ? 'r' : 'n';
        }
        if (A->buf[i] != 'n')
            moving = 1;
        k++;
    }
    if (moving)
        strings_add(A->out, A->buf, A->n);
}

/* m is a point inside a 2-face (an open sector) of the plane hp: the
   point and its two neighbours K m +- hp off the plane, where
   K = 1 + max |h . hp| over the normals h with h . m != 0.  For such h,
   |h . m| >= 1 (integers), so K |h . m| > |h . hp| and h . (K m +- hp)
   has the sign of h . m; the normals with h . m = 0 are those of the
   plane itself (m lies on no other plane), whose sign the shift sets to
   that of +-h . hp.  Every chamber has a facet on some plane, and that
   facet is the closure of a 2-face (a plane crossing its relative
   interior would cut the chamber), so one of the neighbours of that
   2-face's point lies in the chamber.  */
static void
arc_point(arrangement * A, mpz_t * m, mpz_t * hp)
{
    mpz_t * x = A->x;
    size_t q;
    int j;

    candidate(A, m);
    mpz_set_ui(A->K, 0);
    for (q = 0; q < A->nh; q++)
    {
        _wc_check_zdot3(A->s, A->h + 3 * q, m);
        if (mpz_sgn(A->s) == 0)
            continue;
        _wc_check_zdot3(A->s, A->h + 3 * q, hp);
        if (mpz_cmpabs(A->s, A->K) > 0)
            mpz_abs(A->K, A->s);
    }
    mpz_add_ui(A->K, A->K, 1);
    for (j = 0; j < 3; j++)
    {
        mpz_mul(x[j], A->K, m[j]);
        mpz_add(x[j], x[j], hp[j]);
    }
    candidate(A, x);
    for (j = 0; j < 3; j++)
        mpz_submul_ui(x[j], hp[j], 2);
    candidate(A, x);
}

/* < 0 when ray a comes before ray b, 0 when they are the same
   direction.  */
static int
ray_cmp(ray_order * R, size_t a, size_t b)
{
    if (R->half[a] != R->half[b])
        return R->half[a] - R->half[b];
    /* in one half, a comes first when b is counter-clockwise from a
       about hp: (a x b) . hp > 0 */
    _wc_check_zcross3(R->cr, R->ray + 3 * a, R->ray + 3 * b);
    _wc_check_zdot3(R->d, R->cr, R->hp);
    return -mpz_sgn(R->d);
}

/* Merge sort of idx[0..n) by ray_cmp, tmp of n entries.  */
static void
sort_rays(ray_order * R, size_t * idx, size_t * tmp, size_t n)
{
    size_t h = n / 2, i = 0, j = h, k = 0;

    if (n < 2)
        return;
    sort_rays(R, idx, tmp, h);
    sort_rays(R, idx + h, tmp, n - h);
    while (i < h && j < n)
        tmp[k++] = ray_cmp(R, idx[j], idx[i]) < 0 ? idx[j++] : idx[i++];
    while (i < h)
        tmp[k++] = idx[i++];
    while (j < n)
        tmp[k++] = idx[j++];
    memcpy(idx, tmp, n * sizeof(size_t));
}

/* The distinct directions of the lines on plane p (both directions of
   each) into R->idx[0..*nd), in angular order.  */
static void
lines_on_plane(arrangement * A, ray_order * R, size_t p, size_t * nd)
{
    mpz_t * hp = A->h + 3 * A->plane[p];
    size_t q, nr = 0;

    /* the lines on hp, both directions: ray 2 q + 1 = -ray 2 q */
    for (q = 0; q < A->np; q++)
    {
        mpz_t * r = R->ray + 3 * nr;

        if (q == p)
            continue;
        _wc_check_zcross3(r, hp, A->h + 3 * A->plane[q]);
        mpz_neg(r[3], r[0]);
        mpz_neg(r[4], r[1]);
        mpz_neg(r[5], r[2]);
        nr += 2;
    }
    *nd = 0;
    if (nr == 0)
        return;         /* one plane: never, J_in and J_it differ */
    /* angles from ray 0 towards w = hp x ray 0 */
    _wc_check_zcross3(A->w, hp, R->ray);
    for (q = 0; q < nr; q++)
    {
        int sw, su;

        _wc_check_zdot3(A->s, R->ray + 3 * q, A->w);
        sw = mpz_sgn(A->s);
        _wc_check_zdot3(A->s, R->ray + 3 * q, R->ray);
        su = mpz_sgn(A->s);
        R->half[q] = sw > 0 || (sw == 0 && su > 0) ? 0 : 1;
        R->idx[q] = q;
    }
    R->hp = hp;
    sort_rays(R, R->idx, R->tmp, nr);
    *nd = 1;
    for (q = 1; q < nr; q++)
        if (ray_cmp(R, R->idx[*nd - 1], R->idx[q]) != 0)
            R->idx[(*nd)++] = R->idx[q];
}

/* The cells touching plane p: its rays (1-faces), a point inside each of
   its sectors (2-faces), and the neighbours of those (3-faces).  */
static void
walk_plane(arrangement * A, ray_order * R, size_t p)
{
    mpz_t * hp = A->h + 3 * A->plane[p], * m = A->m;
    size_t q, nd;
    int i;

    lines_on_plane(A, R, p, &nd);
    for (q = 0; q < nd; q++)
        candidate(A, R->ray + 3 * R->idx[q]);
    if (nd == 2)
    {
        /* one line: the two half-planes */
        _wc_check_zcross3(m, hp, R->ray + 3 * R->idx[0]);
        arc_point(A, m, hp);
        for (i = 0; i < 3; i++)
            mpz_neg(m[i], m[i]);
        arc_point(A, m, hp);
    }
    else
        /* two lines or more: consecutive rays are less than pi apart, so
           their sum lies inside the sector between them */
        for (q = 0; q < nd; q++)
        {
            mpz_t * a = R->ray + 3 * R->idx[q];
            mpz_t * b = R->ray + 3 * R->idx[(q + 1) % nd];

            for (i = 0; i < 3; i++)
                mpz_add(m[i], a[i], b[i]);
            arc_point(A, m, hp);
        }
}

/* The normals of the touching fixels, and the distinct planes among
   them: normals not parallel to an earlier one.  */
static void
arrangement_planes(arrangement * A, mpq_t * J)
{
    size_t i, k, p;

    for (i = 0, k = 0; i < A->n; i++)
        if (!A->near[i])
        {
            _wc_check_primitive(A->h + 3 * k, J + 6 * i, A->s);
            _wc_check_primitive(A->h + 3 * k + 3, J + 6 * i + 3, A->s);
            k += 2;
        }
    for (k = 0; k < A->nh; k++)
    {
        for (p = 0; p < A->np; p++)
        {
            _wc_check_zcross3(A->x, A->h + 3 * k, A->h + 3 * A->plane[p]);
            if (mpz_sgn(A->x[0]) == 0 && mpz_sgn(A->x[1]) == 0
                && mpz_sgn(A->x[2]) == 0)
                break;
        }
        if (p == A->np)
            A->plane[A->np++] = k;
    }
}

/* A and R for the touching fixels of P (at least one).  WC_OK or
   WC_EINTERNAL; either way walk_clear frees.  */
static int
walk_init(arrangement * A, ray_order * R, const wc_check_problem * P,
          size_t nh, wc_check_strings * out)
{
    memset(A, 0, sizeof *A);
    memset(R, 0, sizeof *R);
    A->n = P->n;
    A->near = P->near;
    A->nh = nh;
    A->out = out;
    mpz_init(A->s);
    mpz_init(A->K);
    mpz_init(R->d);
    R->max = 2 * (nh - 1);
    A->h = _wc_check_zvec_new(_wc_check_times(3, nh));
    A->plane = _wc_check_alloc(nh, sizeof(size_t));
    A->buf = malloc(P->n + 1);
    A->x = _wc_check_zvec_new(3);
    A->m = _wc_check_zvec_new(3);
    A->w = _wc_check_zvec_new(3);
    R->ray = _wc_check_zvec_new(_wc_check_times(3, R->max));
    R->half = _wc_check_alloc(R->max, sizeof(int));
    R->idx = _wc_check_alloc(R->max, sizeof(size_t));
    R->tmp = _wc_check_alloc(R->max, sizeof(size_t));
    R->cr = _wc_check_zvec_new(3);
    if (A->h == NULL || A->plane == NULL || A->buf == NULL || A->x == NULL
        || A->m == NULL || A->w == NULL || R->ray == NULL
        || R->half == NULL || R->idx == NULL || R->tmp == NULL
        || R->cr == NULL)
        return WC_EINTERNAL;
    return WC_OK;
}

static void
walk_clear(arrangement * A, ray_order * R)
{
    _wc_check_zvec_free(A->h, 3 * A->nh);
    free(A->plane);
    free(A->buf);
    _wc_check_zvec_free(A->x, 3);
    _wc_check_zvec_free(A->m, 3);
    _wc_check_zvec_free(A->w, 3);
    _wc_check_zvec_free(R->ray, 3 * R->max);
    free(R->half);
    free(R->idx);
    free(R->tmp);
    _wc_check_zvec_free(R->cr, 3);
    mpz_clear(A->s);
    mpz_clear(A->K);
    mpz_clear(R->d);
}

/* The strings are constant on the cells of the central arrangement of
   the touching fixels' planes, and every cell but the origin (whose
   string is n..n) holds one of these points:
     - both directions of the line where two planes meet (every 1-face);
     - on each plane, the sum of two angularly consecutive rays of the
       lines on it (inside each 2-face), or +- the vector in the plane
       perpendicular to its one line;
     - beside each such point, one point on either side of the plane (see
       arc_point: every 3-face).
   Coincident planes count once.  With t touching fixels, O(t^2) points
   found in O(t^2 log t) comparisons, each mapped to its string in O(n):
   never the 4^t strings.  */
int
old_moving_faces(wc_check_strings * out, const wc_check_problem * P,
                       mpq_t * J)
{
    arrangement A;
    ray_order R;
    size_t i, p, nh = 0;
    int status;

    for (i = 0; i < P->n; i++)
        if (!P->near[i])
            nh += 2;
    if (nh == 0)
        return WC_OK;
    status = walk_init(&A, &R, P, nh, out);
    if (status == WC_OK)
    {
        arrangement_planes(&A, J);
        for (p = 0; p < A.np && !out->oom; p++)
            walk_plane(&A, &R, p);
        strings_finish(out);
        if (out->oom)
            status = WC_EINTERNAL;
    }
    walk_clear(&A, &R);
    return status;
}
