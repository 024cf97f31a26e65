/* zrows3.c -- integer rows in R^3 for the direct route's fast path.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "analysis/zrows3.h"

#define SMALL(x) (!COEFF_IS_MPZ(*(x)))

static int
row_cmp(const fmpz * a, const fmpz * b)
{
    int c, j;

    for (j = 0; j < 3; j++)
        if (SMALL(a + j) && SMALL(b + j))
        {
            if (a[j] != b[j])
                return a[j] < b[j] ? -1 : 1;
        }
        else if ((c = fmpz_cmp(a + j, b + j)) != 0)
            return c;
    return 0;
}

static void
row_swap(fmpz * a, fmpz * b)
{
    fmpz_swap(a + 0, b + 0);
    fmpz_swap(a + 1, b + 1);
    fmpz_swap(a + 2, b + 2);
}

/* Heap sort of the rows A[0..k) (no allocation, no recursion).  */
static void
sift(fmpz * A, slong root, slong k)
{
    slong c;

    while ((c = 2 * root + 1) < k)
    {
        if (c + 1 < k && row_cmp(A + 3 * c, A + 3 * (c + 1)) < 0)
            c++;
        if (row_cmp(A + 3 * root, A + 3 * c) >= 0)
            return;
        row_swap(A + 3 * root, A + 3 * c);
        root = c;
    }
}

/* Rows of words, ordered as row_cmp orders them.  */
typedef struct
{
    slong x[3];
}
wrow;

static int
wrow_less(const wrow * a, const wrow * b)
{
    if (a->x[0] != b->x[0])
        return a->x[0] < b->x[0];
    if (a->x[1] != b->x[1])
        return a->x[1] < b->x[1];
    return a->x[2] < b->x[2];
}

static void
wsift(wrow * B, slong root, slong k)
{
    slong c;
    wrow t;

    while ((c = 2 * root + 1) < k)
    {
        if (c + 1 < k && wrow_less(B + c, B + c + 1))
            c++;
        if (!wrow_less(B + root, B + c))
            return;
        t = B[root];
        B[root] = B[c];
        B[c] = t;
        root = c;
    }
}

/* distinct (below) when every entry is a word: the rows sorted as plain
   words, then written back (every entry of A a word, so a plain
   assignment).  -1 when some entry is not a word, or out of memory (the
   fmpz sort then runs).  */
static slong
distinct_words(fmpz * A, slong k)
{
    wrow * B, t;
    slong i, m = 0;

    for (i = 0; i < 3 * k; i++)
        if (!SMALL(A + i))
            return -1;
    if ((B = malloc(sizeof(wrow) * (k + 1))) == NULL)
        return -1;
    for (i = 0; i < 3 * k; i++)
        B[i / 3].x[i % 3] = A[i];
    for (i = k / 2 - 1; i >= 0; i--)
        wsift(B, i, k);
    for (i = k - 1; i > 0; i--)
    {
        t = B[0];
        B[0] = B[i];
        B[i] = t;
        wsift(B, 0, i);
    }
    for (i = 0; i < k; i++)
    {
        if ((B[i].x[0] == 0 && B[i].x[1] == 0 && B[i].x[2] == 0)
            || (m > 0 && !wrow_less(B + m - 1, B + i)))
            continue;
        B[m++] = B[i];
    }
    for (i = 0; i < 3 * m; i++)
        A[i] = B[i / 3].x[i % 3];
    free(B);
    return m;
}

slong
_wc_zrows3_distinct(fmpz * A, slong k)
{
    slong i, m = distinct_words(A, k);

    if (m >= 0)
        return m;
    m = 0;
    for (i = k / 2 - 1; i >= 0; i--)
        sift(A, i, k);
    for (i = k - 1; i > 0; i--)
    {
        row_swap(A, A + 3 * i);
        sift(A, 0, i);
    }
    for (i = 0; i < k; i++)
    {
        fmpz * x = A + 3 * i;

        if (_fmpz_vec_is_zero(x, 3)
            || (m > 0 && row_cmp(A + 3 * (m - 1), x) == 0))
            continue;
        if (m < i)
            row_swap(A + 3 * m, x);
        m++;
    }
    return m;
}

/* The certificate with a = A[i0], b = A[i1], c = A[i2]: d = x a + y b +
   z c with x, y, z of the sign of -det(a, b, c) times det(d, b, c),
   det(a, d, c), det(a, b, d); d is in -int pos(a, b, c) iff all three
   are negative, and then 0 is a positive combination of a, b, c, d,
   which span R^3: their cone is R^3.  */
static int
span_try(const fmpz * A, slong k, slong i0, slong i1, slong i2, fmpz * t)
{
    const fmpz * a = A + 3 * i0, * b = A + 3 * i1, * c = A + 3 * i2;
    fmpz * bc = t, * ca = t + 3, * ab = t + 6, * s = t + 9;
    slong i;
    int D;

    _wc_zvec3_cross(bc, b, c);
    if ((D = _wc_zvec3_dot_sgn_fast(a, bc, s)) == 0)
        return 0;
    _wc_zvec3_cross(ca, c, a);
    _wc_zvec3_cross(ab, a, b);
    for (i = 0; i < k; i++)
    {
        const fmpz * d = A + 3 * i;

        if (_wc_zvec3_dot_sgn_fast(d, bc, s) == -D
            && _wc_zvec3_dot_sgn_fast(d, ca, s) == -D
            && _wc_zvec3_dot_sgn_fast(d, ab, s) == -D)
            return 1;
    }
    return 0;
}

int
_wc_zrows3_span_space(const fmpz * A, slong k)
{
    fmpz * t;
    int r;

    if (k < 4)
        return 0;
    t = _fmpz_vec_init(10);
    r = span_try(A, k, 0, k / 3, 2 * k / 3, t)
        || span_try(A, k, k / 6, k / 2, 5 * k / 6, t);
    _fmpz_vec_clear(t, 10);
    return r;
}
