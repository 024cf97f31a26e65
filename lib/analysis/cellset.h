/* cellset.h -- internal: sets of wrenches as unions of cells of one
   arrangement, the planes of every cone they are built from, and which
   cells each cone holds (cell by cell, or all cells at once as bitsets).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  The stability sets (stability.c) and the insertion
   plans (plan.c, plansweep.c) are built on it: cellset.c (the planes,
   the cells, the cone keys), cellbits.c (the bitsets).  */

#ifndef WC_ANALYSIS_CELLSET_H
#define WC_ANALYSIS_CELLSET_H

#include <flint/fmpz_mat.h>
#include <flint/fmpq.h>

#include "core/error.h"
#include "exact/cells.h"
#include "exact/cone.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Append the facet and equality normals of C to the rows of A (r used);
   build cells from the first r rows of A (nothing when *status is not
   WC_OK); the point of cell i as a wrench.  */
void _wc_cellset_add_planes(fmpz_mat_t A, slong * r, const wc_cone_t C);
void _wc_cellset_build(wc_cells_t cells, int * status, fmpz_mat_t A,
                       slong r, wc_error_t err);
void _wc_cellset_point(fmpq * g, const wc_cells_t A, slong i);

/* Membership of cells in a cone from the cells' sign vectors: the cone's
   facets and equalities are planes of the arrangement, so a cell is out
   as soon as one sign is wrong, and in when it is strictly inside every
   facet (the relative interior, included unless the cone is a single
   excluded face).  Only the cells on the cone's boundary need the face
   lattice (wc_cone_contains).  This replaces arithmetic by byte lookups
   in the inner loop of every set here.  */
typedef struct
{
    const wc_cone_struct * C;
    slong nf, ne;
    slong * plane;          /* nf facets, then ne equalities; -1: none */
    signed char * orient;   /* the facet's sign relative to its plane */
    int top;                /* the relative interior belongs to C */
    int usable;
}
wc_cone_key;

/* Keys of the count cones C for the cells A, and their release.  */
wc_cone_key * _wc_cone_keys_init(const wc_cone_struct * C, slong count,
                                 const wc_cells_t A);
void _wc_cone_keys_clear(wc_cone_key * K, slong count);

/* 1 when cell i of A (point g) lies in K's cone.  */
int _wc_cone_key_contains(const wc_cone_key * K, const wc_cells_t A,
                          slong i, const fmpq * g);

/* The same for every cell at once (cellbits.c): the cells' signs on
   each plane as two bitsets (-, +) over the cells, bit i of word
   i / FLINT_BITS for cell i (the cells on the plane are the others); a
   cone is a few ANDs of them, and only its boundary cells reach
   wc_cone_contains.  */
typedef struct
{
    slong count, nplanes, words;
    ulong * bits;           /* 2 nplanes words-word bitsets: plane p's -
                               at 2 p, its + at 2 p + 1 */
    ulong * cand, * strict; /* scratch */
    fmpq g[3];
}
wc_cell_bits;

/* The index of the lowest set bit of x != 0.  */
static inline slong
_wc_cellset_ctz(ulong x)
{
#if defined(__GNUC__)
    return (slong) __builtin_ctzll((unsigned long long) x);
#else
    slong c = 0;

    for (; (x & 0xff) == 0; x >>= 8)
        c += 8;
    for (; (x & 1) == 0; x >>= 1)
        c++;
    return c;
#endif
}

/* X := the index of the cells A (kept by reference for nothing: A must
   be passed again below).  Returns 1, or 0 when out of memory (clear X
   in both cases).  */
int _wc_cell_bits_init(wc_cell_bits * X, const wc_cells_t A);
void _wc_cell_bits_clear(wc_cell_bits * X);

/* out (X->words words) := the cells of A in K's cone, bit i for cell i:
   bit i is _wc_cone_key_contains(K, A, i, point of cell i).  */
void _wc_cone_key_cells(ulong * out, const wc_cone_key * K,
                        wc_cell_bits * X, const wc_cells_t A);

/* acc (X->words words) |= the cells of A in any of the count cones of
   K, leaving out cone k when skip != NULL and skip[k] != 0; buf is
   X->words words of scratch.  */
void _wc_cone_keys_union(ulong * acc, const wc_cone_key * K, slong count,
                         const int * skip, wc_cell_bits * X,
                         const wc_cells_t A, ulong * buf);

#ifdef __cplusplus
}
#endif

#endif
