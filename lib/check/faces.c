/* faces.c -- the moving faces of a problem, from the arrangement of the
   planes J_in . x = 0, J_it . x = 0 of its touching fixels.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The solver enumerates the cells of an arrangement in exact/cells.c with
   FLINT; this is a second, different walk (one point in every cell, found
   from the lines on each plane) in GMP, so that a certificate claiming
   the faces are complete is not checked by the code that wrote it.  */

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check/faces.h"

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

void
_wc_check_strings_clear(wc_check_strings * T)
{
    size_t k;

    for (k = 0; k < T->count; k++)
        free(T->s[k]);
    free(T->s);
    memset(T, 0, sizeof *T);
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

long
_wc_check_strings_find(const wc_check_strings * T, const char * s)
{
    size_t lo = 0, hi = T->count;

    while (lo < hi)
    {
        size_t mid = lo + (hi - lo) / 2;
        int d = strcmp(s, T->s[mid]);

        if (d == 0)
            return (long) mid;
        if (d < 0)
            hi = mid;
        else
            lo = mid + 1;
    }
    return -1;
}

/* ------------------------------------------------------------------ */
/* The walk over the faces of the cone of moving directions.           */

/* The 2-dimensional faces: a wedge cone(p, q) of angle below pi, a
   half-plane span(p) + cone(q), a plane span(p, q).  */
typedef enum
{
    WEDGE,
    HALF,
    PLANE
}
plane_kind;

/* One face of K: the rays of R it holds (interior: all of them, K
   itself with three rays or more) and span(L).  */
typedef struct
{
    size_t nray;
    size_t ray[2];
    int interior;
}
face;

/* The touching fixels' normals h = J_in and g = J_it, made primitive
   (positive multiples: the signs are those of J_in . x and J_it . x), the
   cone K, its faces with the fixels whose h vanishes on each, and the
   scratch of the walk.  */
typedef struct
{
    size_t n;           /* fixels */
    const int * near;
    size_t t;           /* touching fixels */
    size_t * fix;       /* t: the index of each */
    mpz_t * h, * g;     /* 3 t each */
    wc_check_cone K;
    size_t nf;          /* faces */
    face * f;           /* nf */
    size_t * first;     /* nf + 1: face f has elem[first[f] .. first[f+1]) */
    size_t * elem;      /* 3 t: touching fixels (0 .. t) */
    size_t * z;         /* 2 t: the rays where h_k vanishes; SIZE_MAX none */
    size_t maxd;        /* 2 t + 2: directions on one face */
    mpz_t * dir;        /* 3 maxd */
    int * half, * inner;        /* maxd each */
    size_t * idx, * tmp;        /* maxd each */
    mpz_t * nu, * st, * w, * x, * cr;   /* 3 each */
    mpz_t s;
    char * base, * buf; /* n + 1 each */
    int bad;            /* set when K contradicts a cut: never */
    wc_check_strings * out;
}
walk;

static int
wsign(walk * A, mpz_t * a, mpz_t * b)
{
    A->out->work++;
    _wc_check_zdot3(A->s, a, b);
    return mpz_sgn(A->s);
}

static void
wcross(walk * A, mpz_t * r, mpz_t * a, mpz_t * b)
{
    A->out->work++;
    _wc_check_zcross3(r, a, b);
}

static int
is_zero3(mpz_t * v)
{
    return mpz_sgn(v[0]) == 0 && mpz_sgn(v[1]) == 0 && mpz_sgn(v[2]) == 0;
}

/* The sign string of a point x in the relative interior of a face whose
   fixels (those with h . x = 0 on the whole face) are E[0 .. ne): s at
   every other touching fixel, since h > 0 there; into A->out unless it is
   n..n.  x is NULL for the interior of K (then ne is 0).  */
static void
cell(walk * A, mpz_t * x, const size_t * E, size_t ne)
{
    size_t e;
    int moving = ne < A->t;

    memcpy(A->buf, A->base, A->n + 1);
    for (e = 0; e < ne; e++)
    {
        size_t k = E[e];
        int sg;

        if (wsign(A, A->h + 3 * k, x) != 0)
        {
            A->bad = 1;
            return;
        }
        sg = wsign(A, A->g + 3 * k, x);
        A->buf[A->fix[k]] = sg > 0 ? 'l' : sg < 0 ? 'r' : 'n';
        if (sg != 0)
            moving = 1;
    }
    if (moving)
        strings_add(A->out, A->buf, A->n);
}

/* < 0 when direction a comes before b, turning about A->nu from A->st;
   0 when they are the same direction.  */
static int
dir_cmp(walk * A, size_t a, size_t b)
{
    if (A->half[a] != A->half[b])
        return A->half[a] - A->half[b];
    wcross(A, A->cr, A->dir + 3 * a, A->dir + 3 * b);
    return -wsign(A, A->cr, A->nu);
}

/* Merge sort of idx[0..n) by dir_cmp, tmp of n entries.  */
static void
sort_dirs(walk * A, size_t * idx, size_t * tmp, size_t n)
{
    size_t h = n / 2, i = 0, j = h, k = 0;

    if (n < 2)
        return;
    sort_dirs(A, idx, tmp, h);
    sort_dirs(A, idx + h, tmp, n - h);
    while (i < h && j < n)
        tmp[k++] = dir_cmp(A, idx[j], idx[i]) < 0 ? idx[j++] : idx[i++];
    while (i < h)
        tmp[k++] = idx[i++];
    while (j < n)
        tmp[k++] = idx[j++];
    memcpy(idx, tmp, n * sizeof(size_t));
}

/* Append direction v (inner: a cell of its own) to the face's list, with
   its half: 0 for angles in [0, pi) from A->st about A->nu, else 1.  */
static void
add_dir(walk * A, size_t * nd, mpz_t * v, int negate, int inner)
{
    mpz_t * d = A->dir + 3 * *nd;
    int j, sw;

    for (j = 0; j < 3; j++)
        if (negate)
            mpz_neg(d[j], v[j]);
        else
            mpz_set(d[j], v[j]);
    sw = wsign(A, d, A->w);
    A->half[*nd] = sw > 0 || (sw == 0 && wsign(A, d, A->st) > 0) ? 0 : 1;
    A->inner[*nd] = inner;
    A->idx[*nd] = *nd;
    (*nd)++;
}

/* 1 when x is in the relative interior of the face: for a wedge
   cone(p, q), (p x x) . nu > 0 and (x x q) . nu > 0; for a half-plane,
   (p x x) . nu > 0; a plane holds every direction.  */
static int
inside(walk * A, plane_kind kind, mpz_t * p, mpz_t * q, mpz_t * x)
{
    if (kind == PLANE)
        return 1;
    wcross(A, A->cr, p, x);
    if (wsign(A, A->cr, A->nu) <= 0)
        return 0;
    if (kind == HALF)
        return 1;
    wcross(A, A->cr, x, q);
    return wsign(A, A->cr, A->nu) > 0;
}

/* The directions on a 2-dimensional face, sorted, each once, into
   A->idx[0 .. *nd): its boundary rays (p and q for a wedge, p and -p for
   a half-plane) and both directions of the line nu x g of each of its
   fixels that fall in its relative interior.  */
static void
face_dirs(walk * A, plane_kind kind, mpz_t * p, mpz_t * q, const size_t * E,
          size_t ne, size_t * nd)
{
    size_t e, k;
    int sgn;

    *nd = 0;
    if (kind != PLANE)
    {
        add_dir(A, nd, p, 0, 0);
        add_dir(A, nd, kind == WEDGE ? q : p, kind == HALF, 0);
    }
    for (e = 0; e < ne; e++)
    {
        wcross(A, A->x, A->nu, A->g + 3 * E[e]);
        if (is_zero3(A->x))
            continue;   /* g is 0 on the whole face */
        _wc_check_zprimitive(A->x, A->s);
        for (sgn = 0; sgn < 2; sgn++)
        {
            if (sgn)
                for (k = 0; k < 3; k++)
                    mpz_neg(A->x[k], A->x[k]);
            if (inside(A, kind, p, q, A->x))
                add_dir(A, nd, A->x, 0, 1);
        }
    }
    sort_dirs(A, A->idx, A->tmp, *nd);
    for (e = 1, k = *nd > 0; e < *nd; e++)
        if (dir_cmp(A, A->idx[k - 1], A->idx[e]) != 0)
            A->idx[k++] = A->idx[e];
    *nd = k;
}

/* The cells of a 2-dimensional face with fixels E[0 .. ne): nu = p x q,
   the directions sorted from p; each inner direction is a cell, and so is
   the open sector between two consecutive directions (for a plane, also
   between the last and the first), whose point is u + v when the angle
   from u to v is below pi, else nu x u (u turned a right angle towards
   v).  A plane without directions is one cell.  */
static void
plane_cells(walk * A, plane_kind kind, mpz_t * p, mpz_t * q,
            const size_t * E, size_t ne)
{
    size_t nd, k, sectors;
    int j;

    wcross(A, A->nu, p, q);
    _wc_check_zprimitive(A->nu, A->s);
    for (j = 0; j < 3; j++)
        mpz_set(A->st[j], p[j]);
    wcross(A, A->w, A->nu, A->st);
    face_dirs(A, kind, p, q, E, ne, &nd);
    if (nd == 0)
    {
        cell(A, p, E, ne);
        return;
    }
    for (k = 0; k < nd; k++)
        if (A->inner[A->idx[k]])
            cell(A, A->dir + 3 * A->idx[k], E, ne);
    sectors = kind == PLANE ? nd : nd - 1;
    for (k = 0; k < sectors; k++)
    {
        mpz_t * u = A->dir + 3 * A->idx[k];
        mpz_t * v = A->dir + 3 * A->idx[(k + 1) % nd];

        wcross(A, A->cr, u, v);
        if (wsign(A, A->cr, A->nu) > 0)
            for (j = 0; j < 3; j++)
                mpz_add(A->x[j], u[j], v[j]);
        else
            wcross(A, A->x, A->nu, u);
        cell(A, A->x, E, ne);
    }
}

/* The cells of face F with fixels E[0 .. ne).  */
static void
face_cells(walk * A, const face * F, const size_t * E, size_t ne)
{
    wc_check_cone * K = &A->K;
    mpz_t * r0 = F->nray > 0 ? K->r + 3 * F->ray[0] : NULL;
    int dim = F->interior ? 3 : K->dl + (int) F->nray, j;

    if (dim == 3)
    {
        /* the interior of K: h > 0 at every touching fixel */
        if (ne != 0)
            A->bad = 1;
        else
            cell(A, NULL, E, 0);
    }
    else if (dim == 1 && F->nray == 1)
        cell(A, r0, E, ne);
    else if (dim == 1)
    {
        /* the line span(L): both of its directions */
        cell(A, K->L, E, ne);
        for (j = 0; j < 3; j++)
            mpz_neg(A->x[j], K->L[j]);
        cell(A, A->x, E, ne);
    }
    else if (F->nray == 2)
        plane_cells(A, WEDGE, r0, K->r + 3 * F->ray[1], E, ne);
    else if (F->nray == 1)
        plane_cells(A, HALF, K->L, r0, E, ne);
    else
        plane_cells(A, PLANE, K->L, K->L + 3, E, ne);
}

/* The faces of K other than {0}: with L = {} and three rays or more, each
   ray, the wedge between each two neighbours and the interior; else
   span(L) + cone(S) for every subset S of the (at most two) rays.  */
static int
list_faces(walk * A)
{
    wc_check_cone * K = &A->K;
    size_t k, m;

    A->f = _wc_check_alloc(_wc_check_times(2, K->nr) + 4, sizeof(face));
    if (A->f == NULL)
        return WC_EINTERNAL;
    A->nf = 0;
    if (K->dl == 0 && K->nr >= 3)
    {
        for (k = 0; k < K->nr; k++)
        {
            face * F = A->f + A->nf++;

            F->nray = 1;
            F->ray[0] = k;
            F->interior = 0;
        }
        for (k = 0; k < K->nr; k++)
        {
            face * F = A->f + A->nf++;

            F->nray = 2;
            F->ray[0] = k;
            F->ray[1] = (k + 1) % K->nr;
            F->interior = 0;
        }
        A->f[A->nf].nray = 0;
        A->f[A->nf++].interior = 1;
        return WC_OK;
    }
    for (m = 0; m < ((size_t) 1 << K->nr); m++)
    {
        face * F = A->f + A->nf;

        if (m == 0 && K->dl == 0)
            continue;   /* {0} */
        F->nray = 0;
        F->interior = 0;
        for (k = 0; k < K->nr; k++)
            if (m & ((size_t) 1 << k))
                F->ray[F->nray++] = k;
        A->nf++;
    }
    return WC_OK;
}

/* The rays of K where h_k vanishes, into z[2 k], z[2 k + 1]; A->bad when
   h_k is negative on K or vanishes on three rays (then K would lie in
   its plane, and it does not: it has three rays or more only when it is
   3-dimensional, and with two rays or fewer there is no third).  */
static void
zero_rays(walk * A, size_t k)
{
    wc_check_cone * K = &A->K;
    size_t j, nz = 0;
    int sg;

    A->z[2 * k] = A->z[2 * k + 1] = SIZE_MAX;
    for (j = 0; j < (size_t) K->dl; j++)
        if (wsign(A, A->h + 3 * k, K->L + 3 * j) != 0)
            A->bad = 1;
    for (j = 0; j < K->nr; j++)
    {
        sg = wsign(A, A->h + 3 * k, K->r + 3 * j);
        if (sg < 0 || (sg == 0 && nz == 2))
            A->bad = 1;
        else if (sg == 0)
            A->z[2 * k + nz++] = j;
    }
}

/* The position of the face of K numbered by list_faces holding exactly
   the rays of the mask m (bit 0: z0; bit 1: z1) of fixel k; the faces it
   lies on are those of the submasks.  SIZE_MAX when there is none.  */
static size_t
face_of(const walk * A, size_t k, unsigned m)
{
    const wc_check_cone * K = &A->K;
    size_t z0 = A->z[2 * k], z1 = A->z[2 * k + 1];

    if (K->dl == 0 && K->nr >= 3)
    {
        if (m == 1 || m == 2)
            return m == 1 ? z0 : z1;
        if (m == 0)
            return SIZE_MAX;
        if (z1 == (z0 + 1) % K->nr)
            return K->nr + z0;
        return z0 == (z1 + 1) % K->nr ? K->nr + z1 : SIZE_MAX;
    }
    {
        size_t bits = (m & 1 ? (size_t) 1 << z0 : 0)
            | (m & 2 ? (size_t) 1 << z1 : 0);

        /* list_faces skipped mask 0 when L = {} */
        return K->dl == 0 ? bits - 1 : bits;
    }
}

/* The fixels of every face: fixel k lies on the faces of the submasks of
   its zero rays.  */
static int
face_fixels(walk * A)
{
    size_t k, f, * at;
    unsigned m;
    int pass;

    A->first = _wc_check_alloc(A->nf + 1, sizeof(size_t));
    at = _wc_check_alloc(A->nf + 1, sizeof(size_t));
    A->elem = _wc_check_alloc(_wc_check_times(4, A->t), sizeof(size_t));
    if (A->first == NULL || at == NULL || A->elem == NULL)
    {
        free(at);
        return WC_EINTERNAL;
    }
    memset(at, 0, (A->nf + 1) * sizeof(size_t));
    for (k = 0; k < A->t; k++)
        zero_rays(A, k);
    for (pass = 0; pass < 2; pass++)
    {
        for (k = 0; k < A->t; k++)
            for (m = 0; m < 4; m++)
            {
                if (((m & 1) && A->z[2 * k] == SIZE_MAX)
                    || ((m & 2) && A->z[2 * k + 1] == SIZE_MAX))
                    continue;
                f = face_of(A, k, m);
                if (f == SIZE_MAX || f >= A->nf)
                {
                    if (m == 3 || f != SIZE_MAX)
                        A->bad = 1;
                    continue;
                }
                if (pass == 0)
                    at[f + 1]++;
                else
                    A->elem[at[f]++] = k;
            }
        if (pass == 0)
        {
            for (f = 0; f < A->nf; f++)
                at[f + 1] += at[f];
            memcpy(A->first, at, (A->nf + 1) * sizeof(size_t));
        }
    }
    free(at);
    return WC_OK;
}

/* A for the touching fixels of P (t of them, at least one).  WC_OK or
   WC_EINTERNAL; either way walk_clear frees.  */
static int
walk_init(walk * A, const wc_check_problem * P, size_t t,
          wc_check_strings * out)
{
    size_t i;

    memset(A, 0, sizeof *A);
    A->n = P->n;
    A->near = P->near;
    A->t = t;
    A->out = out;
    A->maxd = 2 * t + 2;
    mpz_init(A->s);
    if (_wc_check_cone_init(&A->K, t) != WC_OK)
        return WC_EINTERNAL;
    A->fix = _wc_check_alloc(t, sizeof(size_t));
    A->h = _wc_check_zvec_new(_wc_check_times(3, t));
    A->g = _wc_check_zvec_new(_wc_check_times(3, t));
    A->z = _wc_check_alloc(_wc_check_times(2, t), sizeof(size_t));
    A->dir = _wc_check_zvec_new(_wc_check_times(3, A->maxd));
    A->half = _wc_check_alloc(A->maxd, sizeof(int));
    A->inner = _wc_check_alloc(A->maxd, sizeof(int));
    A->idx = _wc_check_alloc(A->maxd, sizeof(size_t));
    A->tmp = _wc_check_alloc(A->maxd, sizeof(size_t));
    A->nu = _wc_check_zvec_new(15);
    A->base = malloc(P->n + 1);
    A->buf = malloc(P->n + 1);
    if (A->fix == NULL || A->h == NULL || A->g == NULL || A->z == NULL
        || A->dir == NULL || A->half == NULL || A->inner == NULL
        || A->idx == NULL || A->tmp == NULL || A->nu == NULL
        || A->base == NULL || A->buf == NULL)
        return WC_EINTERNAL;
    A->st = A->nu + 3;
    A->w = A->nu + 6;
    A->x = A->nu + 9;
    A->cr = A->nu + 12;
    for (i = 0; i < P->n; i++)
        A->base[i] = P->near[i] ? 'u' : 's';
    A->base[P->n] = '\0';
    return WC_OK;
}

static void
walk_clear(walk * A)
{
    _wc_check_cone_clear(&A->K);
    free(A->fix);
    _wc_check_zvec_free(A->h, 3 * A->t);
    _wc_check_zvec_free(A->g, 3 * A->t);
    free(A->z);
    free(A->f);
    free(A->first);
    free(A->elem);
    _wc_check_zvec_free(A->dir, 3 * A->maxd);
    free(A->half);
    free(A->inner);
    free(A->idx);
    free(A->tmp);
    _wc_check_zvec_free(A->nu, 15);
    free(A->base);
    free(A->buf);
    mpz_clear(A->s);
}

/* The cone K of the directions with h_k . x >= 0 at every touching
   fixel, then its faces and the cells of each.  */
static int
walk_cone(walk * A, const wc_check_problem * P, mpq_t * J)
{
    size_t i, k, f;

    for (i = 0, k = 0; i < P->n; i++)
        if (!P->near[i])
        {
            A->fix[k] = i;
            _wc_check_primitive(A->h + 3 * k, J + 6 * i, A->s);
            _wc_check_primitive(A->g + 3 * k, J + 6 * i + 3, A->s);
            k++;
        }
    for (k = 0; k < A->t && (A->K.dl > 0 || A->K.nr > 0); k++)
        if (_wc_check_cone_cut(&A->K, A->h + 3 * k) != WC_OK)
            return WC_EINTERNAL;
    A->out->work += A->K.work;
    if (A->K.dl == 0 && A->K.nr == 0)
        return WC_OK;   /* K = {0}: nothing moves */
    if (list_faces(A) != WC_OK || face_fixels(A) != WC_OK)
        return WC_EINTERNAL;
    for (f = 0; f < A->nf && !A->bad && !A->out->oom; f++)
        face_cells(A, A->f + f, A->elem + A->first[f],
                   A->first[f + 1] - A->first[f]);
    return A->bad ? WC_EINTERNAL : WC_OK;
}

/* The strings are those of the points x != 0 of K other than n..n.  Every
   such x lies in the relative interior of exactly one face G of K, where
   h_k . x = 0 for the fixels k on G and h_k . x > 0 for the others: its
   string has s at the others, and at the fixels on G the letters l, r, n
   of the signs of g_k . x, which are constant on the cells that the
   lines (planes) g_k . x = 0 of those fixels cut G into.  So one point in
   each such cell, at most 2 m + 1 of them on a face with m fixels, gives
   every string.  K costs O(t h) products, with t touching fixels and h
   the largest number of rays it has while it is cut (h <= t; usually
   small, and 0 once K = {0}), and the faces O(t h) more; then each cell
   costs O(m) products and its string O(n) bytes.  */
int
_wc_check_moving_faces(wc_check_strings * out, const wc_check_problem * P,
                       mpq_t * J)
{
    walk A;
    size_t i, t = 0;
    int status;

    for (i = 0; i < P->n; i++)
        if (!P->near[i])
            t++;
    if (t == 0)
        return WC_OK;
    status = walk_init(&A, P, t, out);
    if (status == WC_OK)
        status = walk_cone(&A, P, J);
    if (status == WC_OK)
    {
        strings_finish(out);
        if (out->oom)
            status = WC_EINTERNAL;
    }
    walk_clear(&A);
    return status;
}
