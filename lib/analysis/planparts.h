/* planparts.h -- the pieces insertion plans are built from.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed): plan.c, plansweep.c and the files below.
   Every set of a plan is a union of cells of one arrangement, the planes
   of every cone it is built from.  */

#ifndef WC_PLANPARTS_H
#define WC_PLANPARTS_H

#include "analysis/plan.h"
#include "exact/cells.h"
#include "exact/cone.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Cones of strings (plancones.c).  An array of count cones of dimension
   3, and its release (C may be NULL).  */
wc_cone_struct * _wc_plan_cones_init(slong count);
void _wc_plan_cones_clear(wc_cone_struct * C, slong count);

/* The outcome string of index x (base-3 digits, fixel 0 first), and the
   number of outcomes, 3^n.  */
void _wc_plan_outcome_string(char * s, slong x, slong n);
slong _wc_plan_pow3(slong n);

/* C[k] := W(x) for the plan model of P (mu_s raised to mu_k where that is
   larger, plan.h) and the k-th needed string x of T, or the k-th of the
   3^n outcome strings (count of them).  */
int _wc_plan_needed_cones(wc_cone_struct * C, const wc_plan_strings_t T,
                          const wc_problem_t P, wc_error_t err);
int _wc_plan_outcome_cones(wc_cone_struct * C, slong count,
                           const wc_problem_t P, wc_error_t err);

/* Append the facet and equality normals of C to the rows of A (r used);
   build cells from the first r rows of A (nothing when *status is not
   WC_OK); the point of cell i as a wrench.  */
void _wc_plan_add_planes(fmpz_mat_t A, slong * r, const wc_cone_t C);
void _wc_plan_cells_build(wc_cells_t cells, int * status, fmpz_mat_t A,
                          slong r, wc_error_t err);
void _wc_plan_cell_point(fmpq * g, const wc_cells_t A, slong i);

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

/* The same for every cell at once (planbits.c): the cells' signs on
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

/* X := the index of the cells A (kept by reference for nothing: A must
   be passed again below).  Returns 1, or 0 when out of memory (clear X
   in both cases).  */
/* The index of the lowest set bit of x != 0.  */
static inline slong
_wc_plan_ctz(ulong x)
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

/* The complete plan's transition graph (plangraph.c).  States are bit
   masks; n <= 6, so a state's successors fit in one ulong.  */
typedef void (* wc_plan_edge_fn)(void * ctx, ulong from, ulong to,
                                 slong outcome);

/* Every transition the outcomes admitted by member[] allow.  */
void _wc_plan_transitions(slong n, const unsigned char * member,
                          wc_plan_edge_fn add, void * ctx);

/* An edge function whose ctx is the adjacency array (ulong per state).  */
void _wc_plan_add_adj(void * ctx, ulong from, ulong to, slong outcome);

/* The verdict of the graph adj; with cycle != NULL, the states of a cycle
   (or the offending state) in cycle[0 .. *ncycle).  */
wc_plan_verdict _wc_plan_graph_verdict(const ulong * adj, slong n,
                                       ulong * cycle, slong * ncycle);

/* Exact redundancy (plan.c): exact[k] := 1 when cone k of count is not
   dropped, in order, as inside the union of the cones still kept; any
   (ncells / FLINT_BITS + 1 words) := the cells of any cone.  cells(out,
   k, ctx) writes the cells of cone k as a bitset (bit i for cell i; bits
   from ncells on are ignored); it is called at most twice per cone.
   Returns 0 when out of memory.  */
typedef void (* _wc_plan_bits_fn)(ulong * out, slong k, void * ctx);
int _wc_plan_exact(int * exact, ulong * any, slong count, slong ncells,
                   _wc_plan_bits_fn cells, void * ctx);

/* wc_problem_check, and at most WC_PLAN_MAX_FIXELS fixels
   (WC_PLAN_MAX_FIXELS_COMPLETE when complete) (plan.c).  */
int _wc_plan_check_size(const wc_problem_t P, int complete, wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
