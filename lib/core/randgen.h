/* randgen.h -- the pieces of the random problem generator (random.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  random.h documents the distribution; the
   order of the draws is part of it, so every function here draws in a
   fixed order.  Points and vectors are two consecutive fmpq.  */

#ifndef WC_RANDGEN_H
#define WC_RANDGEN_H

#include <stdint.h>
#include <flint/flint.h>
#include <flint/fmpq.h>

#include "core/problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The generator (rng.c): splitmix64 on a 64-bit state.  */
typedef struct
{
    uint64_t s;
}
wc_rng;

/* Uniform in [lo, hi]; 1 with probability num/den; x := one of the len
   fractions tab[k] = {num, den}.  */
slong _wc_rng_int(wc_rng * r, slong lo, slong hi);
int _wc_rng_chance(wc_rng * r, slong num, slong den);
void _wc_rng_pick(fmpq_t x, wc_rng * r, const slong (*tab)[2], slong len);

#define PICK(x, r, tab) \
    _wc_rng_pick(x, r, tab, (slong) (sizeof(tab) / sizeof(tab[0])))

/* The edge parameters of a polygon's fixels.  */
extern const slong _wc_edge_params[7][2];

/* 10^-9, the tangent of the angle of a near-parallel pair, and the
   parameter t of the circle's parametrisation with 2t/(1-t^2) just above
   it.  */
#define GIGA 1000000000

/* Exact plane vectors (qvec2.c).  */
typedef struct
{
    fmpq v[2];
}
wc_qvec2;

void _wc_qvec2_init(wc_qvec2 * a);
void _wc_qvec2_clear(wc_qvec2 * a);
void _wc_qvec2_set(fmpq * d, const fmpq * a);
void _wc_qvec2_addmul(fmpq * d, const fmpq * a, const fmpq_t s,
                      const fmpq * b);
void _wc_qvec2_scale(fmpq * d, const fmpq * a, const fmpq_t s);
void _wc_qvec2_neg(fmpq * d, const fmpq * a);
void _wc_qvec2_sub(fmpq * d, const fmpq * a, const fmpq * b);
void _wc_qvec2_perp(fmpq * d, const fmpq * a);
int _wc_qvec2_is_zero(const fmpq * a);
int _wc_qvec2_dot_sgn(const fmpq * a, const fmpq * b);
void _wc_fmpq_div_si(fmpq_t x, const fmpq_t y, slong k);
int _wc_random_repeats(const wc_problem_struct * P, slong i);
void _wc_unit_circle_point(fmpq * p, const fmpq_t t);
void _wc_qvec2_rotate(fmpq * d, const fmpq * a, const fmpq * e);

/* The draws every layout uses (rng.c).  */
void _wc_random_coord(fmpq_t x, wc_rng * r, slong lim);
void _wc_random_point(fmpq * p, wc_rng * r, slong widen);
void _wc_random_normal(fmpq * d, wc_rng * r);
void _wc_random_face_com(fmpq * d, wc_rng * r, const fmpq * p, const fmpq * o);
void _wc_random_mu(fmpq_t mu_s, fmpq_t mu_k, wc_rng * r);

/* Shapes and the fixels on them (randshape.c).  */
const fmpq * _wc_random_vertex(const wc_problem_struct * P, slong k);
void _wc_random_edge_normal(fmpq * d, const wc_problem_struct * P, slong k);
void _wc_random_edge_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                           slong k, const fmpq_t s);
void _wc_random_polygon_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                              wc_rng * r, slong widen);
void _wc_random_disk_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                           wc_rng * r, slong widen);
void _wc_random_plain_fixel(wc_fixel_struct * f, const wc_problem_struct * P,
                            wc_rng * r, slong widen);
void _wc_random_generic_fixel(wc_problem_struct * P, slong i, wc_rng * r);
int _wc_random_disk(wc_problem_struct * P, wc_rng * r, int degenerate);
int _wc_random_polygon(wc_problem_struct * P, wc_rng * r);
int _wc_random_bent_box(wc_problem_struct * P, wc_rng * r);
void _wc_random_reverse(wc_problem_struct * P);

/* The degenerate layouts (randdegen.c).  */
slong _wc_random_plant_plain(wc_problem_struct * P, wc_rng * r, fmpq * line);
slong _wc_random_plant_polygon(wc_problem_struct * P, wc_rng * r, fmpq * line);
slong _wc_random_plant_disk(wc_problem_struct * P, wc_rng * r);
void _wc_random_extra_fixel(wc_problem_struct * P, slong i, wc_rng * r,
                            const fmpq * line);

#ifdef __cplusplus
}
#endif

#endif
