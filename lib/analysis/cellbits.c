/* cellbits.c -- which cells of an arrangement lie in a cone, for all
   cells at once, as a bitset.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The cells are indexed by their sign on every plane: for plane p, two
   bitsets over the cells (sign - and +; the cells on p are in neither).
   A cone whose facets and equalities are planes of the arrangement holds
   no cell outside the AND, over its facets and equalities, of the cells
   not on the wrong side (in neither, for an equality), and every cell
   strictly inside each facet when its relative interior belongs to it;
   so a cone costs a few passes over count / FLINT_BITS words, and the
   face lattice (wc_cone_contains) is asked about the cells on its
   boundary only.  The
   answers are those of _wc_cone_key_contains, cell by cell.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "analysis/cellset.h"

/* The bitset of the cells with sign s (-1 or 1) on plane p.  */
#define BITS(X, p, s) ((X)->bits + (2 * (p) + ((s) > 0)) * (X)->words)

/* Word w of the bitset of the cells on plane p (and bits past the last
   cell: callers mask them).  */
#define ZERO(X, p, w) (~(BITS(X, p, -1)[w] | BITS(X, p, 1)[w]))

#if FLINT_BITS == 64
#define FAST_BITS 1

/* A[j] bit i := A[i] bit j, a 64 x 64 bit matrix in place: six rounds
   of swapping blocks of bits across the diagonal.  */
static void
transpose64(ulong * A)
{
    ulong m = UWORD(0x00000000FFFFFFFF), t;
    slong j, k;

    for (j = 32; j != 0; j >>= 1, m ^= m << j)
        for (k = 0; k < 64; k = ((k | j) + 1) & ~j)
        {
            t = ((A[k] >> j) ^ A[k | j]) & m;
            A[k] ^= t << j;
            A[k | j] ^= t;
        }
}

/* Bit t of x := bit 2 t of x (the odd bits of x zero).  */
static inline ulong
even_bits(ulong x)
{
    x = (x | (x >> 1)) & UWORD(0x3333333333333333);
    x = (x | (x >> 2)) & UWORD(0x0F0F0F0F0F0F0F0F);
    x = (x | (x >> 4)) & UWORD(0x00FF00FF00FF00FF);
    x = (x | (x >> 8)) & UWORD(0x0000FFFF0000FFFF);
    return (x | (x >> 16)) & UWORD(0x00000000FFFFFFFF);
}

/* neg, pos := the planes p .. p + 63 (p a multiple of 64) where the n
   (at most 64) cells from cell lo are - and +, transposed: bit i of
   neg[63 - j] for cell lo + i and plane p + j.  A key word holds 32
   planes, sign + 1 in two bits, plane j's low bit at bit 62 - 2 j: its
   - are the fields 00, its + the fields 10; gathering the even bits puts
   plane j at bit 31 - j, and the two words of the 64 planes make one
   row, plane j at bit 63 - j.  */
static void
block_bits(ulong * neg, ulong * pos, const wc_cells_t A, slong lo, slong n,
           slong p)
{
    const ulong even = UWORD(0x5555555555555555);
    slong i, kw = A->kw, w0 = p / WC_CELLS_KEY_PLANES;

    for (i = 0; i < 64; i++)
    {
        ulong rn = 0, rp = 0;

        if (i < n)
        {
            const uint64_t * k = _wc_cells_key(A, lo + i) + w0;
            ulong k0 = k[0], k1 = w0 + 1 < kw ? k[1] : 0;
            ulong l0 = k0 & even, h0 = (k0 >> 1) & even;
            ulong l1 = k1 & even, h1 = (k1 >> 1) & even;

            rn = (even_bits(~(l0 | h0) & even) << 32)
                | even_bits(~(l1 | h1) & even);
            rp = (even_bits(h0) << 32) | even_bits(h1);
        }
        neg[i] = rn;
        pos[i] = rp;
    }
    transpose64(neg);
    transpose64(pos);
}
#else
#define FAST_BITS 0
#endif

/* Words of cells done together by _wc_cell_bits_init: a cache line.  */
#define GROUP 8

int
_wc_cell_bits_init(wc_cell_bits * X, const wc_cells_t A)
{
    slong i, p, np = A->nplanes, k, w;

    memset(X, 0, sizeof(wc_cell_bits));
    X->count = A->count;
    X->nplanes = np;
    X->words = (A->count + FLINT_BITS - 1) / FLINT_BITS;
    for (k = 0; k < 3; k++)
        fmpq_init(X->g + k);
    X->bits = malloc(sizeof(ulong) * ((size_t) 2 * np * X->words + 1));
    X->cand = malloc(sizeof(ulong) * (X->words + 1));
    X->strict = malloc(sizeof(ulong) * (X->words + 1));
    if (X->bits == NULL || X->cand == NULL || X->strict == NULL)
        return 0;
#if FAST_BITS
    /* GROUP words of cells at a time (their keys are near in memory),
       so that each plane's bitsets get whole cache lines */
    for (w = 0; w < X->words; w += GROUP)
    {
        slong nw = FLINT_MIN(GROUP, X->words - w), t, j;
        ulong neg[GROUP][64], pos[GROUP][64];

        for (p = 0; p < np; p += 64)
        {
            for (t = 0; t < nw; t++)
            {
                slong lo = (w + t) * FLINT_BITS;

                block_bits(neg[t], pos[t], A,
                           lo, FLINT_MIN(A->count - lo, FLINT_BITS), p);
            }
            for (j = 0; j < FLINT_MIN(64, np - p); j++)
            {
                ulong * bn = BITS(X, p + j, -1) + w;
                ulong * bp = BITS(X, p + j, 1) + w;

                for (t = 0; t < nw; t++)
                {
                    bn[t] = neg[t][63 - j];
                    bp[t] = pos[t][63 - j];
                }
            }
        }
    }
    (void) i;
#else
    for (w = 0; w < X->words; w++)
    {
        slong lo = w * FLINT_BITS, n = FLINT_MIN(A->count - lo, FLINT_BITS);

        for (p = 0; p < np; p++)
        {
            ulong neg = 0, pos = 0;

            for (i = 0; i < n; i++)
            {
                int s = _wc_cells_sign(A, lo + i, p);

                neg |= (ulong) (s < 0) << i;
                pos |= (ulong) (s > 0) << i;
            }
            BITS(X, p, -1)[w] = neg;
            BITS(X, p, 1)[w] = pos;
        }
    }
#endif
    return 1;
}

void
_wc_cell_bits_clear(wc_cell_bits * X)
{
    slong k;

    for (k = 0; k < 3; k++)
        fmpq_clear(X->g + k);
    free(X->bits);
    free(X->cand);
    free(X->strict);
    memset(X, 0, sizeof(wc_cell_bits));
}

/* cand &= the cells on the side orient * sign <= 0 of plane p (sign 0
   for an equality: eq != 0); strict &= the cells strictly inside (cand
   and strict hold cells only).  */
static void
and_facet(wc_cell_bits * X, slong p, int orient, int eq)
{
    const ulong * in = orient > 0 ? BITS(X, p, -1) : BITS(X, p, 1);
    const ulong * out = orient > 0 ? BITS(X, p, 1) : BITS(X, p, -1);
    slong w;

    if (eq)
    {
        for (w = 0; w < X->words; w++)
        {
            X->cand[w] &= ZERO(X, p, w);
            X->strict[w] &= ZERO(X, p, w);
        }
        return;
    }
    if (orient == 0)
    {
        /* a zero normal: every cell is on it, none strictly inside */
        memset(X->strict, 0, sizeof(ulong) * X->words);
        return;
    }
    for (w = 0; w < X->words; w++)
    {
        X->cand[w] &= ~out[w];
        X->strict[w] &= in[w];
    }
}

/* out := cand & the cells of the bitset that lie in K's cone by the face
   lattice, one wc_cone_contains per cell.  */
static void
by_lattice(ulong * out, const ulong * cand, const wc_cone_key * K,
           wc_cell_bits * X, const wc_cells_t A)
{
    slong w;

    for (w = 0; w < X->words; w++)
    {
        ulong x = cand[w];

        while (x != 0)
        {
            slong i = w * FLINT_BITS + _wc_cellset_ctz(x);

            x &= x - 1;
            _wc_cellset_point(X->g, A, i);
            if (wc_cone_contains(K->C, X->g))
                out[w] |= UWORD(1) << (i % FLINT_BITS);
        }
    }
}

/* tab[f * fw ..] := the facets of K's cone (bits, fw words) that hold
   face f of it: those orthogonal to every ray of the face.  */
static void
face_facets(ulong * tab, slong fw, const wc_cone_key * K)
{
    const wc_cone_struct * C = K->C;
    slong f, j, r;
    fmpz_t t;

    fmpz_init(t);
    memset(tab, 0, sizeof(ulong) * fw * C->nfaces);
    for (f = 0; f < C->nfaces; f++)
        for (j = 0; j < K->nf; j++)
        {
            const wc_face_struct * F = C->faces + f;

            for (r = 0; r < F->nrays; r++)
            {
                _fmpz_vec_dot(t, C->ineqs->rows[j], C->rays->rows[F->rays[r]],
                              3);
                if (!fmpz_is_zero(t))
                    break;
            }
            if (r == F->nrays)
                tab[f * fw + j / FLINT_BITS] |= UWORD(1) << (j % FLINT_BITS);
        }
    fmpz_clear(t);
}

/* out |= the cells of cand (in the closure of K's cone) whose face is
   included: the face holding a point of the closure is the one whose
   facets are exactly those the point lies on (wc_cone_locate finds the
   same face by its rays); the first such face in K's list decides.  A
   word of cells at a time: the cells of face f are those on each of its
   facets (sign 0) and off every other, a few ANDs of the planes' zero
   bitsets.  Returns 0 when out of memory.  */
static int
by_faces(ulong * out, const ulong * cand, const wc_cone_key * K,
         wc_cell_bits * X)
{
    slong fw = K->nf / FLINT_BITS + 1, nfaces = K->C->nfaces, nf = K->nf;
    slong w, j, f;
    ulong * tab = malloc(sizeof(ulong) * (fw * (nfaces + 1) + nf + 1));
    ulong * z;

    if (tab == NULL)
        return 0;
    face_facets(tab, fw, K);
    z = tab + fw * nfaces;
    for (w = 0; w < X->words; w++)
    {
        ulong left = cand[w];

        if (left == 0)
            continue;
        for (j = 0; j < nf; j++)
            z[j] = ZERO(X, K->plane[j], w);     /* left masks it */
        for (f = 0; f < nfaces && left != 0; f++)
        {
            const ulong * t = tab + f * fw;
            ulong x = left;

            for (j = 0; j < nf && x != 0; j++)
                x &= ((t[j / FLINT_BITS] >> (j % FLINT_BITS)) & 1)
                    ? z[j] : ~z[j];
            left &= ~x;
            if (K->C->faces[f].included)
                out[w] |= x;
        }
    }
    free(tab);
    return 1;
}

/* out := the cells strictly inside every facet of K's cone when its
   relative interior belongs to it (else none), and cand (X) := the other
   cells of its closure (its boundary): the ANDs of and_facet in one pass
   over the words when K has at most FUSED facets and equalities.  A
   word's ANDs stop once no cell is left in it (those strictly inside are
   among them).  Returns 0 when it has more (nothing done).  */
#define FUSED 64
static int
fused_facets(ulong * out, wc_cell_bits * X, const wc_cone_key * K)
{
    const ulong * zn[FUSED], * zp[FUSED], * beyond[FUSED], * in[FUSED];
    slong nz = 0, nin = 0, j, w, last = X->count % FLINT_BITS;
    int open = 1;

    if (K->nf + K->ne > FUSED)
        return 0;
    for (j = 0; j < K->ne; j++)
    {
        zn[nz] = BITS(X, K->plane[K->nf + j], -1);
        zp[nz++] = BITS(X, K->plane[K->nf + j], 1);
    }
    for (j = 0; j < K->nf; j++)
    {
        slong p = K->plane[j];

        if (K->orient[j] == 0)
            open = 0;   /* a zero normal: none strictly inside */
        else
        {
            beyond[nin] = K->orient[j] > 0 ? BITS(X, p, 1) : BITS(X, p, -1);
            in[nin++] = K->orient[j] > 0 ? BITS(X, p, -1) : BITS(X, p, 1);
        }
    }
    for (w = 0; w < X->words; w++)
    {
        ulong c = ~UWORD(0), st;

        if (w == X->words - 1 && last != 0)
            c = (UWORD(1) << last) - 1;
        for (j = 0; j < nz && c != 0; j++)
            c &= ~(zn[j][w] | zp[j][w]);
        st = open ? c : 0;
        for (j = 0; j < nin && c != 0; j++)
        {
            c &= ~beyond[j][w];
            st &= in[j][w];
        }
        out[w] = K->top ? st : 0;
        X->cand[w] = c & ~st;
    }
    return 1;
}

void
_wc_cone_key_cells(ulong * out, const wc_cone_key * K, wc_cell_bits * X,
                   const wc_cells_t A)
{
    slong j, w, words = X->words;

    if (K->C->empty || X->count == 0)
    {
        memset(out, 0, sizeof(ulong) * words);
        return;
    }
    if (!K->usable || !fused_facets(out, X, K))
    {
        memset(out, 0, sizeof(ulong) * words);
        for (w = 0; w < words; w++)
            X->cand[w] = ~UWORD(0);
        if (X->count % FLINT_BITS != 0)
            X->cand[words - 1] = (UWORD(1) << (X->count % FLINT_BITS)) - 1;
        if (!K->usable)
        {
            by_lattice(out, X->cand, K, X, A);
            return;
        }
        memcpy(X->strict, X->cand, sizeof(ulong) * words);
        for (j = 0; j < K->ne; j++)
            and_facet(X, K->plane[K->nf + j], 0, 1);
        for (j = 0; j < K->nf; j++)
            and_facet(X, K->plane[j], K->orient[j], 0);
        /* the boundary: candidates not strictly inside every facet */
        for (w = 0; w < words; w++)
        {
            if (K->top)
                out[w] = X->strict[w];
            X->cand[w] &= ~X->strict[w];
        }
    }
    if (!by_faces(out, X->cand, K, X))
        by_lattice(out, X->cand, K, X, A);
}

void
_wc_cone_keys_union(ulong * acc, const wc_cone_key * K, slong count,
                    const int * skip, wc_cell_bits * X, const wc_cells_t A,
                    ulong * buf)
{
    slong k, w;

    for (k = 0; k < count; k++)
        if (skip == NULL || skip[k] == 0)
        {
            _wc_cone_key_cells(buf, K + k, X, A);
            for (w = 0; w < X->words; w++)
                acc[w] |= buf[w];
        }
}
