/* random.h -- seeded, reproducible random problems (wrenchcone random).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The contract: the problem is a fixed function of the options.  The
   generator is splitmix64 (Steele, Lea and Flood, 2014) on a 64-bit state
   set to the seed, integers are drawn by rejection (no modulo bias, no
   floating point), and every number is an exact rational, so the same
   options give the same problem -- and wc_problem_fprint the same bytes --
   on every platform, compiler and build.  Changing what a seed produces
   is an incompatible change: the test corpus (data/corpus/) pins it.

   Every problem passes wc_problem_check, and wc_problem_fprint writes it
   as a file that wc_problem_parse reads back to the same problem: no two
   fixels share both their point and their normal direction, polygons are
   strictly convex, all normals are nonzero.

   Distribution (each choice uniform among the values listed unless said
   otherwise):

   - name: "random " followed by wc_random_options_str.
   - mass from {1, 1, 2, 3, 1/2, 7/3}; inertia from {1, 1, 1/2, 2, 5/12,
     25/12}; com as below.
   - friction: with opt->friction set, mu_s and mu_k are the given ones,
     globally and at every fixel.  Otherwise mu_s is drawn from {0, 1/10,
     1/5, 1/2, 1, 2}; mu_k equals mu_s with probability 1/2, is mu_s / 2
     with probability 1/4, and is drawn from the same set otherwise (it may
     exceed mu_s); each fixel then gets its own mu_s, mu_k drawn the same
     way with probability 1/5.
   - states: each fixel is near with probability 1/3, else touching.

   Without --degenerate:

   - shape none: coordinates of points are a/b, a in [-4, 4], b in
     {1, 2, 3}; normals are integer vectors with entries in [-3, 3], not
     both zero, multiplied with probability 1/3 by one of 2, 3, 1/2, 3/2,
     1/3; a normal pointing away from the centre of mass is turned round
     with probability 4/5, so that most fixels push into the part.  com is
     the origin with probability 1/2, else a point drawn like the fixels.
   - shape disk: centre the origin with probability 1/2, else drawn like a
     point; radius from {1, 2, 1/2, 3/2, 5}; each fixel at the point of
     the circle c + r ((1 - t^2), 2 t) / (1 + t^2) with t = a/b, a in
     [-5, 5], b in [1, 5], or with probability 1/8 at c + (-r, 0); the
     normal is exactly c - p (what the parser derives).  com is the centre
     with probability 1/2, else the centre moved by (a r/4, b r/4), a, b
     in [-1, 1].
   - shape polygon: with probability 1/3 an axis-parallel rectangle
     (corner drawn like a point, sides from {1, 2, 3, 1/2, 3/2}), else 3
     to 6 distinct points of the unit circle, t from {-3, -2, -1, -1/2,
     -1/3, 0, 1/3, 1/2, 1, 2, 3} and the point (-1, 0), in angular order,
     scaled by {1, 2, 3, 5/2} and moved like the disk's centre; the vertex
     order is reversed (clockwise) with probability 1/4.  Each fixel lies
     inside an edge drawn uniformly, at v_k + s (v_k+1 - v_k), s from
     {1/2, 1/3, 2/3, 1/4, 3/4, 1/5, 2/5}, with the exact inward normal
     of that edge (the edge vector turned by +90 degrees, -90 for a
     clockwise polygon: what the parser derives).  com is the average of
     the vertices.
   - A fixel that would repeat another's point and normal direction is
     drawn again, from ranges that widen with each retry (so that any
     number of fixels fits).  General position is likely, not promised.

   With --degenerate, these features are planted, then the fixels are
   put in a random order (Fisher-Yates); what is planted depends only on
   the shape and on n = opt->fixels:

     feature                                       none  polygon  disk
     S  two fixels at one point (normals of         n>=2  n>=2     never
        different directions)
     N  a near-parallel pair: normals u, v with     n>=2  n>=2     n>=3
        u.v > 0 and 10^-9 <= (u x v)/(u.v) < 2 10^-9
        (exactly 10^-9 without a shape or on the polygon: v is u plus
        10^-9 u turned by 90 degrees, scaled; on a disk the two points are
        t = 1/(2 10^9) apart on the circle's parametrisation)
     P  two fixels with exactly parallel or          n>=3  n>=3     n>=2
        opposed normals at different points
     C  three distinct collinear contact points     n>=4  n>=4     never
     O  every fixel's normal line passes through    n=1   n=1      always
        the centre of mass

   On a disk S and C cannot happen with true inward normals (a circle
   meets a line twice; one point has one normal), so the disk's com is its
   centre and P is an antipodal pair.  Without a shape, S and N are the
   same pair (one point q, normals 10^-9 apart: a floating-point code
   would call them duplicates); P repeats or opposes that normal at a new
   point, on the first normal's line with probability 1/2 (the two fixels
   then squeeze the part when opposed); C puts a fourth fixel on the line
   through q and P's point.  For n = 1 the fixel sits at com - s u
   pushing along u.  The degenerate polygon is a box [-a, a] x [-b, b], a
   from {1, 2, 3/2}, b from {1, 1/2, 2}, com the origin, whose bottom edge
   bends up at (0, -b) by exactly 10^-9 of its run: vertices (-a, -b),
   (0, -b), (a, -b + a/10^9), (a, b), (-a, b).  S and N are two fixels at
   the bend with the normals of its two edges, P a fixel inside the
   bottom-left edge (parallel to the first), C a fixel at the corner
   (-a, -b) with the normal of the bottom or of the left edge, collinear
   with the other bottom points.

   Fixels beyond those (n >= 5; n >= 4 on a disk) are drawn one of four
   ways with probability 1/4 each.  Without a shape: the normal of an
   earlier fixel (or its opposite, scaled) at a new point; the point of an
   earlier fixel with that fixel's normal turned by 90 or 180 degrees; a
   point on the line of C; a fixel drawn as without --degenerate.  On the
   polygon: inside the top edge (opposed to the bottom one); at a vertex,
   with the normal of one of its two edges; inside the bottom-left edge
   (on the line of C); inside an edge drawn uniformly.  On a disk: the
   antipode of an earlier fixel; an earlier fixel turned by t = +-1/(2
   10^9); twice, a point drawn as without --degenerate.  A fixel that would
   repeat an earlier one is drawn as without --degenerate instead.  */

#ifndef WC_RANDOM_H
#define WC_RANDOM_H

#include <stdint.h>
#include <flint/flint.h>
#include <flint/fmpq.h>

#include "core/error.h"
#include "core/limits.h"
#include "core/problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The options.  Initialise with wc_random_options_init (the defaults of
   wrenchcone random: 3 fixels, seed 1, not degenerate, no shape, friction
   drawn) and clear with wc_random_options_clear.  */
typedef struct
{
    slong fixels;           /* 1 .. WC_RANDOM_MAX_FIXELS */
    uint64_t seed;
    int degenerate;         /* plant the features listed above */
    wc_shape_kind shape;    /* WC_SHAPE_NONE, _DISK or _POLYGON */
    int friction;           /* 1: use mu_s, mu_k below; 0: draw them */
    fmpq_t mu_s;            /* >= 0, used when friction is set */
    fmpq_t mu_k;            /* >= 0, used when friction is set */
}
wc_random_options;

void wc_random_options_init(wc_random_options * opt);
void wc_random_options_clear(wc_random_options * opt);

/* Fill P, which must be freshly initialised (wc_problem_init), with the
   problem the options name.  Returns WC_OK; WC_EINPUT with err set when
   an option is out of range (fixels, shape, negative friction), P then
   left as it was; WC_EINTERNAL when out of memory.  */
int wc_random_problem(wc_problem_t P, const wc_random_options * opt,
                      wc_error_t err);

/* The options as the command line that reproduces them, in a fixed order
   and leaving out defaults other than --fixels and --seed, e.g.
   "--fixels=3 --seed=7 --degenerate --shape=disk --friction=1/5,1/10"
   (mu_k written only when it differs from mu_s).  malloc'd; the caller
   frees it.  NULL when out of memory.  */
char * wc_random_options_str(const wc_random_options * opt);

#ifdef __cplusplus
}
#endif

#endif
