/* t-cells.c -- the cells of an arrangement of planes, and sets of cells
   merged into disjoint NNC pieces.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   References, independent of the walk in cells.c: the planes by sorting
   canonical normals here; the cells as the distinct sign vectors of
   candidate points made from pairs of planes (every ray is +-(h_p x h_q);
   every sector of plane p holds the sum of its two bounding rays, both
   of the form h_p x h_q, so all sums of two such rays are tried; every
   chamber has a sector as the relative interior of a facet, and
   K s +- h_p lies in it for a sector point s on p once K > |h_q . h_p|
   for every q, as |h_q . s| >= 1 for integer s); the dimension of a cell
   by a rank; locating points by comparing sign vectors with every cell;
   sets by evaluating every piece on every cell's point and on random
   points, and by building sets that are known cones.

   WC_CELLS_STATS set prints piece counts by kind of set.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>

#include "wrenchcone.h"
#include "exact/vec3.h"
#include "testutil.h"

#define ROW(A, i) ((A)->rows[i])

/* ---------------------------------------------------------------------
   Vectors.  */

static int
sgn_dot(const fmpz * x, const fmpz * y)
{
    fmpz_t t;
    int s;

    fmpz_init(t);
    _fmpz_vec_dot(t, x, y, 3);
    s = fmpz_sgn(t);
    fmpz_clear(t);
    return s;
}

static int
is_zero3(const fmpz * v)
{
    return fmpz_is_zero(v) && fmpz_is_zero(v + 1) && fmpz_is_zero(v + 2);
}

/* Primitive, first nonzero entry positive; 0 for the zero vector.  */
static int
canon3(fmpz * v)
{
    fmpz_t g;
    slong j;

    if (is_zero3(v))
        return 0;
    fmpz_init(g);
    fmpz_gcd(g, v + 0, v + 1);
    fmpz_gcd(g, g, v + 2);
    for (j = 0; j < 3; j++)
        fmpz_divexact(v + j, v + j, g);
    fmpz_clear(g);
    for (j = 0; fmpz_is_zero(v + j); j++)
        ;
    if (fmpz_sgn(v + j) < 0)
        for (j = 0; j < 3; j++)
            fmpz_neg(v + j, v + j);
    return 1;
}

static int
lex3(const fmpz * a, const fmpz * b)
{
    slong j;

    for (j = 0; j < 3; j++)
        if (fmpz_cmp(a + j, b + j) != 0)
            return fmpz_cmp(a + j, b + j);
    return 0;
}

static char *
zvec_str(const fmpz * v)
{
    fmpq * q = _fmpq_vec_init(3);
    char * s;
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_set_fmpz(q + j, v + j);
    s = wctest_vec_str(q, 3);
    _fmpq_vec_clear(q, 3);
    return s;
}

/* ---------------------------------------------------------------------
   Random arrangements.  */

static void
rand_vec(fmpz * v, slong r)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpz_set_si(v + j, wctest_randint(-r, r));
}

/* N := n random normals with degenerate layouts mixed in.  */
static void
random_normals(fmpz_mat_t N)
{
    slong n = wctest_randint(0, 12), style = wctest_randint(0, 5), i, j;
    fmpz * L = _fmpz_vec_init(3), * r = _fmpz_vec_init(3);

    fmpz_mat_clear(N);
    fmpz_mat_init(N, n, 3);
    do
        rand_vec(L, 2);
    while (is_zero3(L));
    for (i = 0; i < n; i++)
    {
        fmpz * h = ROW(N, i);
        slong kind = wctest_randint(0, 9);

        if (style == 1)         /* all through one line */
            kind = 4;
        else if (style == 2 && kind < 5)    /* many axis planes */
            kind = 5;
        if (kind <= 2 || (kind <= 3 && i == 0))
            rand_vec(h, wctest_chance(1, 3) ? 1 : 3);
        else if (kind == 3)     /* a multiple of an earlier one */
            _fmpz_vec_scalar_mul_si(h, ROW(N, wctest_randint(0, i - 1)), 3,
                                    wctest_randint(-3, 3));
        else if (kind == 4)     /* through the common line L */
        {
            rand_vec(r, 2);
            _wc_zvec3_cross(h, L, r);
        }
        else if (kind == 5)     /* holds a coordinate axis */
        {
            rand_vec(h, 2);
            fmpz_zero(h + wctest_randint(0, 2));
        }
        else if (kind == 6 && i >= 2)   /* through the line of two others */
        {
            _wc_zvec3_cross(r, ROW(N, i - 1), ROW(N, i - 2));
            if (is_zero3(r))
                rand_vec(h, 2);
            else
            {
                fmpz * s = _fmpz_vec_init(3);

                rand_vec(s, 2);
                _wc_zvec3_cross(h, r, s);
                _fmpz_vec_clear(s, 3);
            }
        }
        else if (kind == 7)     /* sums of earlier ones: planes through
                                   their common lines */
        {
            if (i >= 2)
            {
                _fmpz_vec_scalar_mul_si(h, ROW(N, i - 1), 3,
                                        wctest_randint(-2, 2));
                _fmpz_vec_scalar_addmul_si(h, ROW(N, i - 2), 3,
                                           wctest_randint(-2, 2));
            }
            else
                rand_vec(h, 3);
        }
        else if (kind == 8)     /* zero */
            _fmpz_vec_zero(h, 3);
        else
            rand_vec(h, 5);
        if (style == 3 && wctest_chance(1, 2))
        {
            /* Large entries (past the word-sized fast path of cells.c):
               a large multiple of the normal plus a small vector; later
               multiples of it stay parallel.  */
            rand_vec(r, 2);
            _fmpz_vec_scalar_mul_si(h, h, 3, WORD(1) << 20);
            _fmpz_vec_add(h, h, r, 3);
        }
    }
    /* Shuffle, so that repeats are not always adjacent.  */
    for (i = n - 1; i > 0; i--)
    {
        j = wctest_randint(0, i);
        _fmpz_vec_swap(ROW(N, i), ROW(N, j), 3);
    }
    _fmpz_vec_clear(L, 3);
    _fmpz_vec_clear(r, 3);
}

/* H := the distinct canonical planes of N and the coordinate planes,
   sorted; by insertion.  */
static void
reference_planes(fmpz_mat_t H, const fmpz_mat_t N)
{
    slong n = fmpz_mat_nrows(N), m = 0, i, j, k;
    fmpz_mat_t T;
    fmpz * v = _fmpz_vec_init(3);

    fmpz_mat_init(T, n + 3, 3);
    for (i = 0; i < n + 3; i++)
    {
        if (i < 3)
        {
            _fmpz_vec_zero(v, 3);
            fmpz_one(v + i);
        }
        else
            _fmpz_vec_set(v, ROW(N, i - 3), 3);
        if (!canon3(v))
            continue;
        for (j = 0; j < m && lex3(ROW(T, j), v) < 0; j++)
            ;
        if (j < m && lex3(ROW(T, j), v) == 0)
            continue;
        for (k = m; k > j; k--)
            _fmpz_vec_set(ROW(T, k), ROW(T, k - 1), 3);
        _fmpz_vec_set(ROW(T, j), v, 3);
        m++;
    }
    fmpz_mat_clear(H);
    fmpz_mat_init(H, m, 3);
    for (i = 0; i < m; i++)
        _fmpz_vec_set(ROW(H, i), ROW(T, i), 3);
    fmpz_mat_clear(T);
    _fmpz_vec_clear(v, 3);
}

static void
signs_of(signed char * s, const fmpz_mat_t H, const fmpz * x)
{
    slong q;

    for (q = 0; q < fmpz_mat_nrows(H); q++)
        s[q] = (signed char) sgn_dot(ROW(H, q), x);
}

/* ---------------------------------------------------------------------
   A growable set of sign vectors (strings over "-0+").  */

typedef struct
{
    slong m;
    slong n;
    slong alloc;
    char * s;       /* n x (m + 1) */
}
sign_bag;

static void
bag_init(sign_bag * B, slong m)
{
    B->m = m;
    B->n = 0;
    B->alloc = 64;
    B->s = malloc(B->alloc * (m + 1));
}

static void
bag_clear(sign_bag * B)
{
    free(B->s);
}

static void
bag_add(sign_bag * B, const signed char * s)
{
    slong q;
    char * t;

    if (B->n == B->alloc)
    {
        B->alloc *= 2;
        B->s = realloc(B->s, B->alloc * (B->m + 1));
    }
    t = B->s + B->n * (B->m + 1);
    for (q = 0; q < B->m; q++)
        t[q] = s[q] < 0 ? '-' : s[q] > 0 ? '+' : '0';
    t[B->m] = '\0';
    B->n++;
}

static int
str_cmp(const void * a, const void * b)
{
    return strcmp(a, b);
}

/* Sort and remove repeats.  */
static void
bag_unique(sign_bag * B)
{
    slong i, k = 0, w = B->m + 1;

    qsort(B->s, B->n, w, str_cmp);
    for (i = 0; i < B->n; i++)
        if (k == 0 || strcmp(B->s + (k - 1) * w, B->s + i * w) != 0)
            memmove(B->s + (k++) * w, B->s + i * w, w);
    B->n = k;
}

/* The candidate points of the reference (see the top of the file), their
   sign vectors added to B.  */
static void
reference_cells(sign_bag * B, const fmpz_mat_t H)
{
    slong m = fmpz_mat_nrows(H), p, q, a, b, i;
    fmpz * v = _fmpz_vec_init(3), * x = _fmpz_vec_init(3),
        * y = _fmpz_vec_init(3);
    fmpz_mat_t on;
    fmpz_t K, t;
    signed char * s = malloc(m + 1);

    fmpz_init(K);
    fmpz_init(t);
    fmpz_mat_init(on, m, 3);
    _fmpz_vec_zero(v, 3);
    signs_of(s, H, v);
    bag_add(B, s);
    for (p = 0; p < m; p++)
    {
        /* K with K |h_q . s| > |h_q . h_p| for integer points s.  */
        fmpz_zero(K);
        for (q = 0; q < m; q++)
        {
            _fmpz_vec_dot(t, ROW(H, q), ROW(H, p), 3);
            fmpz_abs(t, t);
            if (fmpz_cmp(t, K) > 0)
                fmpz_set(K, t);
        }
        fmpz_add_ui(K, K, 1);
        /* Lines on p.  */
        for (q = 0; q < m; q++)
            _wc_zvec3_cross(ROW(on, q), ROW(H, p), ROW(H, q));
        for (a = 0; a < m; a++)
        {
            if (a == p)
                continue;
            for (i = -1; i <= 1; i += 2)
            {
                _fmpz_vec_scalar_mul_si(v, ROW(on, a), 3, i);
                signs_of(s, H, v);
                bag_add(B, s);
            }
            for (b = a + 1; b < m; b++)
            {
                if (b == p)
                    continue;
                _wc_zvec3_cross(v, ROW(on, a), ROW(on, b));
                if (is_zero3(v))
                    continue;       /* the same line */
                for (i = 0; i < 4; i++)
                {
                    slong e, z = 0;
                    int side;

                    _fmpz_vec_scalar_mul_si(x, ROW(on, a), 3,
                                            (i & 1) ? -1 : 1);
                    _fmpz_vec_scalar_addmul_si(x, ROW(on, b), 3,
                                               (i & 2) ? -1 : 1);
                    signs_of(s, H, x);
                    bag_add(B, s);
                    for (e = 0; e < m; e++)
                        z += s[e] == 0;
                    if (z != 1)
                        continue;   /* on a line: not a sector point */
                    for (side = -1; side <= 1; side += 2)
                    {
                        _fmpz_vec_scalar_mul_fmpz(y, x, 3, K);
                        _fmpz_vec_scalar_addmul_si(y, ROW(H, p), 3, side);
                        signs_of(s, H, y);
                        bag_add(B, s);
                    }
                }
            }
        }
    }
    fmpz_mat_clear(on);
    fmpz_clear(K);
    fmpz_clear(t);
    free(s);
    _fmpz_vec_clear(v, 3);
    _fmpz_vec_clear(x, 3);
    _fmpz_vec_clear(y, 3);
}

/* ---------------------------------------------------------------------
   Checks of the cells.  */

static slong
rank_of_zero_planes(const fmpz_mat_t H, const signed char * s)
{
    slong m = fmpz_mat_nrows(H), q, c = 0, r;
    fmpz_mat_t Z;

    for (q = 0; q < m; q++)
        c += s[q] == 0;
    if (c == 0)
        return 0;
    fmpz_mat_init(Z, c, 3);
    for (q = 0, c = 0; q < m; q++)
        if (s[q] == 0)
            _fmpz_vec_set(ROW(Z, c++), ROW(H, q), 3);
    r = fmpz_mat_rank(Z);
    fmpz_mat_clear(Z);
    return r;
}

/* -1, 0, 1 comparing cells i and j of A by dimension, then signs.  */
static int
cell_order(const wc_cells_t A, slong i, slong j)
{
    slong m = A->nplanes, q;

    if (A->dim[i] != A->dim[j])
        return A->dim[i] < A->dim[j] ? -1 : 1;
    for (q = 0; q < m; q++)
        if (_wc_cells_sign(A, i, q) != _wc_cells_sign(A, j, q))
            return _wc_cells_sign(A, i, q) < _wc_cells_sign(A, j, q) ? -1 : 1;
    return 0;
}

/* The point x (integer, scaled by a random positive denominator for the
   fmpq call): A locates it in the one cell with its sign vector.  */
static void
check_locate(const wc_cells_t A, const fmpz * x, const char * what)
{
    slong m = A->nplanes, i, j, found = 0, k;
    signed char * s = malloc(m + 1), * row = malloc(m + 1);
    fmpq * g = _fmpq_vec_init(3);
    fmpz_t den;

    fmpz_init(den);
    fmpz_set_si(den, wctest_randint(1, 6));
    for (j = 0; j < 3; j++)
        fmpq_set_fmpz_frac(g + j, x + j, den);
    signs_of(s, A->planes, x);
    for (i = 0; i < A->count; i++)
    {
        wc_cells_signs(row, A, i);
        if (memcmp(row, s, m) == 0)
        {
            found++;
            k = i;
        }
    }
    if (found != 1)
    {
        char * str = zvec_str(x);

        wctest_fail("%s %s has the signs of %ld cells", what, str,
                    (long) found);
    }
    i = wc_cells_locate(A, g);
    if (i != k)
    {
        char * str = zvec_str(x);

        wctest_fail("%s %s: wc_cells_locate gave %ld, its cell is %ld",
                    what, str, (long) i, (long) k);
    }
    fmpz_clear(den);
    _fmpq_vec_clear(g, 3);
    free(s);
    free(row);
}

static void
check_cells(const wc_cells_t A, const fmpz_mat_t N)
{
    fmpz_mat_t H;
    slong m, i, q, j, nd[4] = {0, 0, 0, 0};
    signed char * s, * y_signs;
    sign_bag ref, got;
    fmpz * x = _fmpz_vec_init(3), * y = _fmpz_vec_init(3);
    fmpz_t c;

    fmpz_init(c);
    fmpz_mat_init(H, 0, 3);
    reference_planes(H, N);
    m = fmpz_mat_nrows(H);
    if (A->nplanes != m || fmpz_mat_nrows(A->planes) != m
        || !fmpz_mat_equal(A->planes, H))
        wctest_fail("planes: %ld of them, expected %ld (or they differ)",
                    (long) A->nplanes, (long) m);
    if (fmpz_mat_nrows(A->point) != A->count)
        wctest_fail("point has %ld rows for %ld cells",
                    (long) fmpz_mat_nrows(A->point), (long) A->count);
    s = malloc(m + 1);
    y_signs = malloc(m + 1);

    /* Every cell: its point, signs, dimension; the order.  */
    for (i = 0; i < A->count; i++)
    {
        const fmpz * p = ROW(A->point, i);
        slong d = A->dim[i];

        if (d < 0 || d > 3)
            wctest_fail("cell %ld: dimension %ld", (long) i, (long) d);
        nd[d]++;
        if (d == 0 ? !is_zero3(p) : is_zero3(p))
            wctest_fail("cell %ld (dim %ld): bad point", (long) i, (long) d);
        fmpz_gcd(c, p + 0, p + 1);
        fmpz_gcd(c, c, p + 2);
        if (d > 0 && !fmpz_is_one(c))
            wctest_fail("cell %ld: the point is not primitive", (long) i);
        signs_of(s, H, p);
        wc_cells_signs(y_signs, A, i);
        if (memcmp(s, y_signs, m) != 0)
            wctest_fail("cell %ld: stored signs differ from its point's",
                        (long) i);
        if (d != 3 - rank_of_zero_planes(H, s) && !(d == 0 && is_zero3(p)))
            wctest_fail("cell %ld: dimension %ld, planes through it of rank "
                        "%ld", (long) i, (long) d,
                        (long) rank_of_zero_planes(H, s));
        if (i > 0 && cell_order(A, i - 1, i) >= 0)
            wctest_fail("cells %ld and %ld out of order or equal",
                        (long) i - 1, (long) i);
    }
    if (nd[0] != 1)
        wctest_fail("%ld origins", (long) nd[0]);
    if (nd[1] - nd[2] + nd[3] != 2)
        wctest_fail("Euler: %ld rays - %ld sectors + %ld chambers != 2",
                    (long) nd[1], (long) nd[2], (long) nd[3]);

    /* The same sign vectors as the reference.  */
    bag_init(&ref, m);
    bag_init(&got, m);
    reference_cells(&ref, H);
    bag_unique(&ref);
    for (i = 0; i < A->count; i++)
    {
        wc_cells_signs(y_signs, A, i);
        bag_add(&got, y_signs);
    }
    bag_unique(&got);
    if (got.n != A->count)
        wctest_fail("repeated sign vectors among %ld cells", (long) A->count);
    if (ref.n != got.n || memcmp(ref.s, got.s, ref.n * (m + 1)) != 0)
        wctest_fail("%ld cells, the reference finds %ld (m = %ld)",
                    (long) A->count, (long) ref.n, (long) m);
    bag_clear(&ref);
    bag_clear(&got);

    /* Locating points: random, on planes, on lines, the origin.  */
    _fmpz_vec_zero(x, 3);
    check_locate(A, x, "the origin");
    for (j = 0; j < 40; j++)
    {
        rand_vec(x, j < 20 ? 4 : 30);
        check_locate(A, x, "random point");
    }
    for (j = 0; j < 15; j++)
    {
        q = wctest_randint(0, m - 1);
        rand_vec(y, 3);
        _wc_zvec3_cross(x, ROW(H, q), y);
        check_locate(A, x, "point on a plane");
        i = wctest_randint(0, m - 1);
        if (i != q)
        {
            _wc_zvec3_cross(x, ROW(H, q), ROW(H, i));
            _fmpz_vec_scalar_mul_si(x, x, 3, wctest_randint(-3, 3));
            check_locate(A, x, "point on a line");
        }
    }

    /* Planes by index, given in any scale and sign.  */
    for (q = 0; q < m; q++)
    {
        slong k;

        do
            k = wctest_randint(-4, 4);
        while (k == 0);
        _fmpz_vec_scalar_mul_si(x, ROW(H, q), 3, k);
        if (wc_cells_plane_index(A, x) != q)
            wctest_fail("plane %ld times %ld: index %ld", (long) q, (long) k,
                        (long) wc_cells_plane_index(A, x));
    }
    for (j = 0; j < 20; j++)
    {
        slong want = -1;

        do
            rand_vec(x, 3);
        while (is_zero3(x));
        _fmpz_vec_set(y, x, 3);
        canon3(y);
        for (q = 0; q < m; q++)
            if (_fmpz_vec_equal(y, ROW(H, q), 3))
                want = q;
        if (wc_cells_plane_index(A, x) != want)
            wctest_fail("plane index of a random normal: %ld, expected %ld",
                        (long) wc_cells_plane_index(A, x), (long) want);
    }

    free(s);
    free(y_signs);
    fmpz_mat_clear(H);
    fmpz_clear(c);
    _fmpz_vec_clear(x, 3);
    _fmpz_vec_clear(y, 3);
}

/* ---------------------------------------------------------------------
   Sets.  */

/* Piece counts by kind of set, printed with WC_CELLS_STATS set.  */
#define NKINDS 8
static const char * kind_name[NKINDS];
static slong kind_sets[NKINDS], kind_pieces[NKINDS], kind_members[NKINDS];

static slong last_npieces = 0, over_bound = 0;

static void
stat_add(const char * what, slong pieces, slong members)
{
    slong k;

    for (k = 0; k < NKINDS && kind_name[k] != NULL
         && strcmp(kind_name[k], what) != 0; k++)
        ;
    if (k == NKINDS)
        return;
    kind_name[k] = what;
    kind_sets[k]++;
    kind_pieces[k] += pieces;
    kind_members[k] += members;
}

/* How many pieces of S hold g; *which := the last of them.  */
static slong
pieces_holding(const wc_set_t S, const fmpq * g, slong * which)
{
    slong k, c = 0;

    *which = -1;
    for (k = 0; k < S->npieces; k++)
        if (wc_cone_contains(S->pieces + k, g))
        {
            c++;
            *which = k;
        }
    return c;
}

static int
zmat_cmp(const fmpz_mat_t a, const fmpz_mat_t b)
{
    slong i, j;

    for (i = 0; i < fmpz_mat_nrows(a) && i < fmpz_mat_nrows(b); i++)
        for (j = 0; j < 3; j++)
            if (fmpz_cmp(fmpz_mat_entry(a, i, j), fmpz_mat_entry(b, i, j)))
                return fmpz_cmp(fmpz_mat_entry(a, i, j),
                                fmpz_mat_entry(b, i, j));
    return (fmpz_mat_nrows(a) > fmpz_mat_nrows(b))
        - (fmpz_mat_nrows(a) < fmpz_mat_nrows(b));
}

/* The documented order of pieces: decreasing dimension, then rays,
   inequalities, equalities, included flags of the faces.  */
static int
piece_order(const wc_cone_struct * a, const wc_cone_struct * b)
{
    slong f;
    int c;

    if (a->dim != b->dim)
        return a->dim > b->dim ? -1 : 1;
    if ((c = zmat_cmp(a->rays, b->rays)) != 0
        || (c = zmat_cmp(a->ineqs, b->ineqs)) != 0
        || (c = zmat_cmp(a->eqs, b->eqs)) != 0)
        return c;
    for (f = 0; f < a->nfaces && f < b->nfaces; f++)
        if (a->faces[f].included != b->faces[f].included)
            return a->faces[f].included - b->faces[f].included;
    return 0;
}

static void
zvec_to_q(fmpq * g, const fmpz * x)
{
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_set_fmpz(g + j, x + j);
}

/* S from member, checked cell by cell and on random points; K, when not
   NULL, is a cone the member cells make up.  */
static void
check_set(const wc_cells_t A, const int * member, const wc_cone_struct * K,
          const char * what)
{
    slong m = A->nplanes, i, j, k, c;
    int any = 0, any3 = 0;
    wc_set_t S, T;
    wc_error_t err;
    fmpq * g = _fmpq_vec_init(3);
    fmpz * x = _fmpz_vec_init(3), * y = _fmpz_vec_init(3);

    wc_error_init(err);
    wc_set_init(S);
    wc_set_init(T);
    if (wc_set_from_cells(S, A, member, err) != WC_OK)
        wctest_fail("%s: wc_set_from_cells failed: %s", what, err->message);

    for (i = 0; i < A->count; i++)
    {
        if (member[i])
        {
            any = 1;
            any3 |= A->dim[i] == 3;
        }
        zvec_to_q(g, ROW(A->point, i));
        c = pieces_holding(S, g, &k);
        if (c != (member[i] != 0))
            wctest_fail("%s: cell %ld (dim %ld, member %d) lies in %ld of "
                        "%ld pieces", what, (long) i, (long) A->dim[i],
                        member[i] != 0, (long) c, (long) S->npieces);
        if (wc_set_contains(S, g) != (member[i] != 0))
            wctest_fail("%s: wc_set_contains wrong on cell %ld", what,
                        (long) i);
        if (K != NULL && wc_cone_contains(K, g) != (member[i] != 0))
            wctest_fail("%s: the members are not the cone's cells", what);
    }
    if (S->empty != !any || (S->npieces == 0) != !any)
        wctest_fail("%s: empty flag %d, %ld pieces, members: %d", what,
                    S->empty, (long) S->npieces, any);
    if (S->interior != any3)
        wctest_fail("%s: interior flag %d, member chambers: %d", what,
                    S->interior, any3);
    for (k = 0; k < S->npieces; k++)
    {
        const wc_cone_struct * P = S->pieces + k;

        if (P->empty || P->d != 3)
            wctest_fail("%s: piece %ld empty or not in R^3", what, (long) k);
        if ((P->dim == 3) && !S->interior)
            wctest_fail("%s: a 3-dimensional piece without interior", what);
        if (k > 0 && piece_order(S->pieces + k - 1, P) >= 0)
            wctest_fail("%s: pieces %ld and %ld out of order", what,
                        (long) k - 1, (long) k);
    }

    /* Random points, on planes and lines too: in the piece of their
       cell's point (pieces are unions of cells).  */
    for (j = 0; j < 30; j++)
    {
        slong cell, in, incell;

        rand_vec(x, 6);
        if (j % 3 == 1)
        {
            rand_vec(y, 3);
            _wc_zvec3_cross(x, ROW(A->planes, wctest_randint(0, m - 1)),
                            y);
        }
        else if (j % 3 == 2)
            _wc_zvec3_cross(x, ROW(A->planes, wctest_randint(0, m - 1)),
                            ROW(A->planes, wctest_randint(0, m - 1)));
        zvec_to_q(g, x);
        cell = wc_cells_locate(A, g);
        if (cell < 0)
            wctest_fail("%s: a point in no cell", what);
        c = pieces_holding(S, g, &in);
        if (c != (member[cell] != 0))
            wctest_fail("%s: a point of cell %ld (member %d) lies in %ld "
                        "pieces", what, (long) cell, member[cell] != 0,
                        (long) c);
        zvec_to_q(g, ROW(A->point, cell));
        pieces_holding(S, g, &incell);
        zvec_to_q(g, x);
        if (in != incell)
            wctest_fail("%s: a point of cell %ld in piece %ld, the cell's "
                        "point in piece %ld", what, (long) cell, (long) in,
                        (long) incell);
        if (K != NULL && wc_cone_contains(K, g) != (c != 0))
            wctest_fail("%s: the set differs from its cone", what);
    }

    /* Deterministic.  */
    if (wc_set_from_cells(T, A, member, err) != WC_OK)
        wctest_fail("%s: wc_set_from_cells failed: %s", what, err->message);
    if (T->npieces != S->npieces || T->empty != S->empty
        || T->interior != S->interior)
        wctest_fail("%s: two builds differ", what);
    for (k = 0; k < S->npieces; k++)
        if (!wc_cone_equal(S->pieces + k, T->pieces + k))
            wctest_fail("%s: two builds differ in piece %ld", what, (long) k);
    wc_set_swap(S, T);
    if (T->npieces != S->npieces)
        wctest_fail("%s: swap", what);

    /* wc_set_sort restores the order.  */
    for (k = 0; k < T->npieces / 2; k++)
        wc_cone_swap(T->pieces + k, T->pieces + T->npieces - 1 - k);
    wc_set_sort(T);
    for (k = 0; k < S->npieces; k++)
        if (!wc_cone_equal(S->pieces + k, T->pieces + k))
            wctest_fail("%s: wc_set_sort gives another order", what);

    /* A cone cut out by planes of the arrangement is a sign box: the
       top-down step finds it whole.  */
    if (K != NULL && any && (S->npieces != 1
                             || !wc_cone_equal(S->pieces, K)))
        wctest_fail("%s: %ld pieces, not the cone itself", what,
                    (long) S->npieces);
    for (i = 0, c = 0; i < A->count; i++)
        c += member[i] != 0;
    stat_add(what, S->npieces, c);
    last_npieces = S->npieces;

    wc_set_clear(S);
    wc_set_clear(T);
    wc_error_clear(err);
    _fmpq_vec_clear(g, 3);
    _fmpz_vec_clear(x, 3);
    _fmpz_vec_clear(y, 3);
}

/* K := a random NNC cone with rows among the planes of A (possibly
   empty, possibly all of R^3).  Returns how many convex pieces its
   complement needs at most: one per inequality, two per equality.  */
static slong
random_cone(wc_cone_t K, const wc_cells_t A)
{
    slong m = A->nplanes, r = wctest_randint(0, 4), i, j;
    fmpq_mat_t M[3];
    wc_error_t err;
    slong n[3] = {0, 0, 0};
    slong q[4], t[4];
    int sg[4];

    for (i = 0; i < r; i++)
    {
        q[i] = wctest_randint(0, m - 1);
        t[i] = wctest_randint(0, 4);
        t[i] = t[i] == 0 ? 0 : t[i] <= 2 ? 1 : 2;   /* eq, ineq, strict */
        sg[i] = wctest_chance(1, 2) ? 1 : -1;
        n[t[i]]++;
    }
    for (i = 0; i < 3; i++)
    {
        fmpq_mat_init(M[i], n[i], 3);
        n[i] = 0;
    }
    for (i = 0; i < r; i++)
    {
        fmpq_mat_struct * D = M[t[i]];

        for (j = 0; j < 3; j++)
        {
            fmpq_set_fmpz(fmpq_mat_entry(D, n[t[i]], j),
                          fmpz_mat_entry(A->planes, q[i], j));
            if (sg[i] < 0)
                fmpq_neg(fmpq_mat_entry(D, n[t[i]], j),
                         fmpq_mat_entry(D, n[t[i]], j));
        }
        n[t[i]]++;
    }
    wc_error_init(err);
    if (wc_cone_set_hrep(K, M[0], M[1], M[2], err) != WC_OK)
        wctest_fail("random cone: %s", err->message);
    for (i = 0; i < 3; i++)
        fmpq_mat_clear(M[i]);
    wc_error_clear(err);
    return 2 * n[0] + n[1] + n[2];
}

static void
check_sets(const wc_cells_t A)
{
    slong n = A->count, i, t, bound;
    int * member = malloc(sizeof(int) * (n + 1));
    wc_cone_t K;

    wc_cone_init(K, 3);

    /* Everything: the whole space, one piece.  */
    for (i = 0; i < n; i++)
        member[i] = 1;
    {
        wc_error_t err;

        wc_error_init(err);
        if (wc_cone_set_hrep(K, NULL, NULL, NULL, err) != WC_OK)
            wctest_fail("R^3: %s", err->message);
        wc_error_clear(err);
    }
    check_set(A, member, K, "all cells");
    for (i = 0; i < n; i++)
        member[i] = 0;
    check_set(A, member, NULL, "no cells");

    /* One cell.  */
    member[wctest_randint(0, n - 1)] = 1;
    check_set(A, member, NULL, "one cell");

    /* Random subsets.  */
    for (t = 0; t < 2; t++)
    {
        slong num = wctest_randint(1, 9);

        for (i = 0; i < n; i++)
            member[i] = wctest_chance(num, 10);
        check_set(A, member, NULL, "random cells");
    }

    /* A convex cone's cells, and its complement.  */
    for (t = 0; t < 3; t++)
    {
        fmpq * g = _fmpq_vec_init(3);

        bound = random_cone(K, A);
        for (i = 0; i < n; i++)
        {
            zvec_to_q(g, ROW(A->point, i));
            member[i] = wc_cone_contains(K, g);
        }
        _fmpq_vec_clear(g, 3);
        check_set(A, member, K, "a convex cone's cells");
        if (t == 0)
        {
            for (i = 0; i < n; i++)
                member[i] = !member[i];
            check_set(A, member, NULL, "the complement of a cone");
            over_bound += last_npieces > bound;
        }
    }
    wc_cone_clear(K);
    free(member);
}

int
main(void)
{
    slong i, iters;
    fmpz_mat_t N;
    wc_cells_t A;
    wc_error_t err;

    wctest_init("t-cells");
    fmpz_mat_init(N, 0, 3);
    wc_cells_init(A);
    wc_error_init(err);

    /* No planes at all: the coordinate octants.  */
    if (wc_cells_build(A, N, err) != WC_OK)
        wctest_fail("no planes: %s", err->message);
    if (A->nplanes != 3 || A->count != 1 + 6 + 12 + 8)
        wctest_fail("no planes: %ld planes, %ld cells", (long) A->nplanes,
                    (long) A->count);
    check_cells(A, N);
    check_sets(A);

    iters = wctest_iters(40);
    for (i = 0; i < iters; i++)
    {
        if (!wctest_iter(i))
            continue;
        random_normals(N);
        if (wc_cells_build(A, N, err) != WC_OK)
            wctest_fail("wc_cells_build: %s", err->message);
        check_cells(A, N);
        check_sets(A);
    }

    if (getenv("WC_CELLS_STATS") != NULL)
        printf("complements of cones in more pieces than their rows "
               "need: %ld\n", (long) over_bound);
    if (getenv("WC_CELLS_STATS") != NULL)
        for (i = 0; i < NKINDS && kind_name[i] != NULL; i++)
            printf("%-28s %5ld sets %8ld member cells %7ld pieces\n",
                   kind_name[i], (long) kind_sets[i], (long) kind_members[i],
                   (long) kind_pieces[i]);

    wc_cells_clear(A);
    fmpz_mat_clear(N);
    wc_error_clear(err);
    return 0;
}
