/* testutil.h -- shared infrastructure of the C tests: a seeded generator,
   failure reports that name the seed, random problems and modes.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Environment:
     WC_TEST_SEED        the seed (decimal or 0x hex; default 20021212)
     WC_TEST_MULTIPLIER  scales every iteration count (positive; default 1)
     WC_TEST_ITER        run only this iteration of each randomized loop
                         (replays a failure reported as iter=I)
   Tests are silent on success.  A failure prints
     FAIL [name] seed=S iter=I (iter_seed=X): message
   and a line telling how to replay it, then exits with status 1.  A bad
   environment variable is a hard error (exit status 99).  */

#ifndef WC_TESTS_TESTUTIL_H
#define WC_TESTS_TESTUTIL_H

#include <stdint.h>
#include <flint/flint.h>
#include <flint/fmpq.h>

#include "core/problem.h"
#include "exact/cone.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifdef __GNUC__
#define WCTEST_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define WCTEST_PRINTF(f, a)
#endif

/* Read the environment and seed the generator; name appears in failure
   messages.  Call first.  */
void wctest_init(const char * name);

uint64_t wctest_seed(void);

/* base * WC_TEST_MULTIPLIER (and at least WC_TEST_ITER + 1 when that is
   set, so that the iteration asked for is reached).  */
slong wctest_iters(slong base);

/* The seed of iteration i: a fixed function of (wctest_seed(), i).  */
uint64_t wctest_iter_seed(slong i);

/* Start iteration i of a randomized loop: reseed the generator with
   wctest_iter_seed(i), so that iteration i draws the same numbers however
   the earlier ones went, and name i in failure messages.  Returns 0 when
   WC_TEST_ITER asks for another iteration; use it as
     for (i = 0; i < iters; i++) { if (!wctest_iter(i)) continue; ... }  */
int wctest_iter(slong i);

/* Uniform 64-bit words; integers uniform in [lo, hi] (lo <= hi); 1 with
   probability num/den.  */
uint64_t wctest_rand(void);
slong wctest_randint(slong lo, slong hi);
int wctest_chance(slong num, slong den);

/* Small rationals: numerator in [-maxnum, maxnum], denominator in
   [1, maxden]; zero about 1/8 of the time, an integer about 3/8.  */
void wctest_rand_fmpq(fmpq_t x, slong maxnum, slong maxden);

/* A positive small rational: numerator in [1, maxnum], denominator in
   [1, maxden], an integer about 1/3 of the time.  */
void wctest_rand_fmpq_pos(fmpq_t x, slong maxnum, slong maxden);

/* A random wrench (3 entries): small rationals, sometimes axis-aligned,
   sometimes zero.  */
void wctest_random_wrench(fmpq * g);

/* Report a failure and exit 1.  wctest_fail_problem also writes P (as a
   .wc file, with wc_problem_fprint) and, when not NULL, the mode.  */
_Noreturn void wctest_fail(const char * fmt, ...) WCTEST_PRINTF(1, 2);
_Noreturn void wctest_fail_problem(const wc_problem_t P, const char * mode,
                                   const char * fmt, ...)
    WCTEST_PRINTF(3, 4);

/* For tests that go on after a failure: write "FILE:LINE: message" on
   stderr and count it.  wctest_failures says how many so far.  */
void wctest_report(const char * file, int line, const char * fmt, ...)
    WCTEST_PRINTF(3, 4);
int wctest_failures(void);

/* "(1, -2/3, 0)": a malloc'd string for messages; free with flint_free.  */
char * wctest_vec_str(const fmpq * v, slong len);

/* Fill P, freshly initialised by wc_problem_init, with a random problem of
   nmin..nmax fixels (1 <= nmin <= nmax).  Layouts include degenerate ones:
   parallel and opposed normals, coincident points (never with the same
   normal direction), collinear points, normals through one point, fixels
   on a disk or a box; friction 0, mu_s != mu_k, large mu, per-fixel
   friction; near fixels mixed with touching ones; the centre of mass off
   the origin; mass and inertia other than 1; non-unit, non-primitive
   normals.  Coordinates stay small rationals.  */
void wctest_random_problem(wc_problem_t P, slong nmin, slong nmax);

/* A random mode string for P, mode having room for P->n + 1 bytes.
   Table 2 letters: s l r n m on touching fixels, s a u on near ones.  */
void wctest_random_mode(char * mode, const wc_problem_t P);

/* Table 1 letters: s l r n on touching fixels, s a on near ones.  */
void wctest_random_mode_kinematic(char * mode, const wc_problem_t P);

/* data/NAME into P, freshly initialised (top_srcdir from the environment,
   as make check sets it; "." without it); fails the test when it cannot
   be read or parsed.  */
void wctest_load_data(wc_problem_t P, const char * name);

/* W as wc_cone_fprint writes it in JSON: a string to free with free();
   fails the test when it cannot be written.  */
char * wctest_cone_json(const wc_cone_t W);

/* Add to P a fixel at (px, py) with normal (nx, ny), in the given state
   (friction as wc_problem_add_fixel sets it); returns it.  */
wc_fixel_struct * wctest_fixel_si(wc_problem_t P, slong px, slong py,
                                  slong nx, slong ny, wc_fixel_state state);

/* 1 when fixels a and b are at the same point with normals pointing the
   same way: an invalid problem (wrenchcone(5)).  */
int wctest_same_contact(const wc_fixel_struct * a, const wc_fixel_struct * b);

/* w = (d_x, d_y, (p - com) x d): the wrench of a unit force along d at
   fixel f of P (a column of J).  d may alias w.  */
void wctest_wrench_of(fmpq * w, const wc_problem_t P,
                      const wc_fixel_struct * f, const fmpq * d);

/* g = (x, y, t).  */
void wctest_vec3_si(fmpq * g, slong x, slong y, slong t);

/* Whether v[0..3) is zero.  */
int wctest_vec3_is_zero(const fmpq * v);

/* r = a . b, over three entries; r may not alias a or b.  */
void wctest_dot3(fmpq_t r, const fmpq * a, const fmpq * b);

/* The sign of h . g, over three entries, h integer.  */
int wctest_dot3_sgn_z(const fmpz * h, const fmpq * g);

#ifdef __cplusplus
}
#endif

#endif
