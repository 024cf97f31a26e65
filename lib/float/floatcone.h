/* floatcone.h -- the paper's route in floating point: the baseline that
   exactness is measured against.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Everything here is C doubles and cddlib's double-precision build (the
   ddf_ functions that libcddgmp also contains).  Nothing in this file is
   exact and no exact answer of the library depends on it: it exists so
   that users can see, in numbers, what a careful float implementation of
   the paper's Section 5 gets wrong on their problems (wrenchcone cone
   --method=paper --arith=double, and the benchmarks).

   A wc_fcone_t mirrors a wc_cone_t (cone.h) in doubles, with the same
   conventions: facets are rows h with h.g <= 0, rays are generators of
   the closure, rays are projected onto the orthogonal complement of the
   lineality space and facet normals onto the linear hull before they are
   normalised to unit length; rays and facets are sorted lexicographically
   by their (rounded) entries.  Lines and equalities are orthonormal bases
   of the lineality space and of the orthogonal complement of the linear
   hull.  Instead of the exact face lattice it records, per facet and per
   ray, whether its relative interior is left out of the cone (strict).  */

#ifndef WC_FLOATCONE_H
#define WC_FLOATCONE_H

#include <flint/d_mat.h>

#include "core/error.h"
#include "core/problem.h"
#include "exact/cone.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The default tolerance of the double route (see
   wc_wrench_cone_paper_double).  */
#define WC_FCONE_EPS 1e-9

typedef struct
{
    slong d;            /* ambient dimension */
    int empty;
    double eps;         /* the tolerance it was computed with */
    slong dim;          /* dimension of the closure's linear hull */
    slong lineality_dim;
    int closed;         /* no strict inequality: the cone is its closure */
    d_mat_t ineqs;      /* facets of the closure, unit h, h.g <= 0 */
    int * strict;       /* per facet: its relative interior is not in W */
    d_mat_t eqs;        /* orthonormal basis, complement of the hull */
    d_mat_t rays;       /* extreme rays of the closure, unit length */
    int * strict_rays;  /* per ray: the ray (minus the apex) is not in W */
    d_mat_t lines;      /* orthonormal basis of the lineality space */
}
wc_fcone_struct;

typedef wc_fcone_struct wc_fcone_t[1];

/* An empty cone in R^d, d >= 1, eps WC_FCONE_EPS.  clear is safe on any
   initialised cone; set_empty keeps d and eps.  */
void wc_fcone_init(wc_fcone_t C, slong d);
void wc_fcone_clear(wc_fcone_t C);
void wc_fcone_set_empty(wc_fcone_t C);

/* W := W(mode), computed by the paper's route entirely in doubles.

   The problem's exact data are rounded once (fmpq_get_d); J, M, A, B, C,
   the Table 2 matrices E, N, R, S, V, K = E C N R S V and P = E B are then
   double matrices; K^F comes from cddlib's double V->H conversion of
   pos(K), rows scaled to unit length; F = K^F P and b = K^F K e_strict.
   eps (finite, >= 0; WC_FCONE_EPS is the default) is the one tolerance of
   our own decisions, each taken on unit or relative quantities:

   - row i of F is strict when b_i < -eps |K e_strict|;
   - row i of F is zero when |F_i| <= eps ||P|| (Frobenius): a zero
     non-strict row is dropped, a zero strict row (0 < 0) empties W;
   - W is empty when cddlib's double LP finds { F_0 g <= 0, F_+ g <= -1 }
     (rows of unit length; homogeneity turns < 0 into <= -1) infeasible --
     the decision a float implementation makes, at cddlib's own internal
     tolerance (1e-7 in its double build), not at eps;
   - otherwise the closure's rays and lines come from cddlib's double
     H->V conversion of { F g <= 0 }, its facets and equalities from the
     V->H conversion of those generators;
   - a facet is strict when some strict row of F, projected onto the
     linear hull and normalised, lies within eps of its normal; a ray is
     strict when some strict unit row s has s.r >= -eps; unit vectors
     closer than eps are dependent (lines, equalities).  In these three
     comparisons of unit vectors eps counts as at least 64 DBL_EPSILON,
     what rounding alone produces.

   Returns WC_OK; WC_EINPUT when the mode fails wc_mode_check
   (WC_TABLE_CONE, err set as that function sets it), when eps is negative
   or not finite, or when the data overflow doubles; WC_EINTERNAL when
   cddlib's double build fails (it may, on ill-conditioned input: that too
   is part of what this route shows).  On failure W is left empty.  */
int wc_wrench_cone_paper_double(wc_fcone_t W, const wc_problem_t P,
                                const char * mode, double eps,
                                wc_error_t err);

/* The printer, wc_fcone_fprint, is in io/fconeprint.h.  */

/* Where a float cone F and an exact cone E (both in R^d) differ beyond
   tol, as a bitmask; 0 when they agree.  The exact vectors are normalised
   to unit length (its canonical rays and facets are already projected like
   F's), and vectors are matched by nearest Euclidean distance.  */
enum
{
    WC_FDIFF_EMPTY = 1,     /* one is empty and the other is not */
    WC_FDIFF_SPACES = 2,    /* linear hull or lineality space differ */
    WC_FDIFF_RAYS = 4,      /* a ray of one has no ray of the other */
    WC_FDIFF_FACETS = 8,    /* a facet of one has no facet of the other */
    WC_FDIFF_STRICT = 16    /* a matched ray or facet, or the apex, differs
                               in strictness */
};
int wc_fcone_compare_exact(const wc_fcone_t F, const wc_cone_t E, double tol);

#ifdef __cplusplus
}
#endif

#endif
