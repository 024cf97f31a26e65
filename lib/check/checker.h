/* checker.h -- internal: what the files of the certificate checker
   share.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  Everything here uses GMP and lib/core only (see
   verify.c for why).  Functions that return int return WC_OK,
   WC_EINPUT or WC_EINTERNAL unless they say otherwise; the checks return
   1 (holds), 0 (does not; the reason written) or -1 (out of memory).  */

#ifndef WC_CHECK_CHECKER_H
#define WC_CHECK_CHECKER_H

#include <stddef.h>

#include <gmp.h>

#include "core/error.h"
#include "core/json.h"
#include "core/text.h"

#ifdef __GNUC__
#define WC_CHECK_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define WC_CHECK_PRINTF(f, a)
#endif

/* ------------------------------------------------------------------ */
/* Vectors of GMP numbers (gmpvec.c).                                  */

/* k * n, or SIZE_MAX when that overflows (so the allocation fails).  */
size_t _wc_check_times(size_t k, size_t n);

/* An array of n objects of the given size (at least one byte); NULL when
   out of memory or when the size overflows.  */
void * _wc_check_alloc(size_t n, size_t size);

/* n initialised numbers (n may be 0); NULL when out of memory.  The free
   functions accept NULL.  */
mpq_t * _wc_check_qvec_new(size_t n);
mpz_t * _wc_check_zvec_new(size_t n);
void _wc_check_qvec_free(mpq_t * v, size_t n);
void _wc_check_zvec_free(mpz_t * v, size_t n);

int _wc_check_qvec_is_zero(mpq_t * v, size_t n);
int _wc_check_qvec_equal(mpq_t * a, mpq_t * b, size_t n);

/* 3-vectors.  r = a . b (t scratch for the rationals); r = a x b, r
   distinct from a and b; r += a b.  */
void _wc_check_qdot3(mpq_t r, mpq_t * a, mpq_t * b, mpq_t t);
void _wc_check_zdot3(mpz_t r, mpz_t * a, mpz_t * b);
void _wc_check_qcross3(mpq_t * r, mpq_t * a, mpq_t * b, mpq_t t);
void _wc_check_zcross3(mpz_t * r, mpz_t * a, mpz_t * b);
void _wc_check_qaddmul(mpq_t r, const mpq_t a, const mpq_t b, mpq_t t);

/* z = the primitive integer vector on the ray of the nonzero rational
   3-vector q; t scratch.  */
void _wc_check_primitive(mpz_t * z, mpq_t * q, mpz_t t);

/* ------------------------------------------------------------------ */
/* The text of a reason or a summary (textbuf.c).                      */

/* A growing string; oom once an addition failed (then it stays as it
   was).  Starts all zero.  */
typedef struct
{
    char * s;
    size_t len;
    size_t cap;
    int oom;
}
wc_check_text;

void _wc_check_put_n(wc_check_text * b, const char * s, size_t n);
void _wc_check_put(wc_check_text * b, const char * s);
void _wc_check_putf(wc_check_text * b, const char * fmt, ...)
    WC_CHECK_PRINTF(2, 3);

/* Numbers, cut after 40 digits with "...": z, q, and "(a, b, c)".  */
void _wc_check_put_z(wc_check_text * b, const mpz_t z);
void _wc_check_put_q(wc_check_text * b, const mpq_t q);
void _wc_check_put_zvec(wc_check_text * b, mpz_t * v, size_t n);

/* Cut b back to at (where a step's message began) when the step held
   (holds != 0): a failing step keeps its message.  */
void _wc_check_unmark(wc_check_text * b, size_t at, int holds);
void _wc_check_put_qvec(wc_check_text * b, mpq_t * v, size_t n);

/* ------------------------------------------------------------------ */
/* Motzkin multipliers (motzkin.c).                                    */

typedef enum
{
    WC_CHECK_GT = 0,
    WC_CHECK_GE = 1,
    WC_CHECK_EQ = 2
}
wc_check_rel;

/* ">", ">=" or "=".  */
const char * _wc_check_rel_name(wc_check_rel r);

/* 1 when there are as many multipliers (nmult) as rows; else 0 and why
   says so, after prefix, naming the rows noun ("constraint", "row").  */
int _wc_check_motzkin_count(wc_check_text * why, const char * prefix,
                            const char * noun, size_t nmult, size_t rows);

/* 1 when the multipliers y of rows rows with relations rel prove that
   the rows have no common solution, given s = sum_k y_k row_k (d
   entries); else 0 and why says, after prefix, which condition fails
   first.  */
int _wc_check_motzkin(wc_check_text * why, const char * prefix,
                      const char * noun, const wc_check_rel * rel,
                      mpq_t * y, size_t rows, mpq_t * s, size_t d);

/* ------------------------------------------------------------------ */
/* Reading the JSON of a certificate (read.c).                         */

/* The errors of one reading: the first in file order is kept.  */
typedef struct
{
    const char * file;
    wc_error_struct * err;
    int status;         /* the worst so far: WC_OK, WC_EINPUT, WC_EINTERNAL */
}
wc_check_reader;

typedef enum
{
    WC_CHECK_MODE = 0,          /* "mode-feasibility" or no "kind" */
    WC_CHECK_STABILITY = 1,     /* "strong-stability" */
    WC_CHECK_SET = 2,           /* "stability-set" */
    WC_CHECK_PLAN = 3,          /* "plan-goal" */
    WC_CHECK_CRIT = 4           /* "critical-friction" */
}
wc_check_kind;

typedef enum
{
    WC_CHECK_STRING,
    WC_CHECK_BOOL,
    WC_CHECK_ARRAY,
    WC_CHECK_OBJECT
}
wc_check_want;

/* For _wc_check_qarray: an array of any length.  */
#define WC_CHECK_ANY_LENGTH ((size_t) -1)

/* Records out of memory; returns WC_EINTERNAL.  */
int _wc_check_nomem(wc_check_reader * c);

/* Records an error at the value at, unless one located no later is
   already recorded.  Returns WC_EINPUT.  */
int _wc_check_bad(wc_check_reader * c, const wc_json_node * at,
                  const char * fmt, ...) WC_CHECK_PRINTF(3, 4);

/* _wc_check_bad with a message quoting s[0..len) (fmt has one %s).  */
int _wc_check_bad_quoting(wc_check_reader * c, const wc_json_node * at,
                          const char * fmt, const char * s, size_t len);

/* The member key of object o, of the wanted type, into *v (else NULL).  */
int _wc_check_member(wc_check_reader * c, const wc_json_node * o,
                     const char * key, wc_check_want w,
                     const wc_json_node ** v);

/* An element of an array that must be an object.  */
int _wc_check_want_object(wc_check_reader * c, const wc_json_node * v);

/* The rational at v: a string "p" or "p/q", or a JSON integer.  */
int _wc_check_rational(wc_check_reader * c, const wc_json_node * v,
                       mpq_t q);

/* o[key] is an array of exactly n rationals, into q.  */
int _wc_check_vector(wc_check_reader * c, const wc_json_node * o,
                     const char * key, mpq_t * q, size_t n);

/* o[key] is an array of rationals, of want entries unless want is
   WC_CHECK_ANY_LENGTH; into *q, allocated here with *len entries.  */
int _wc_check_qarray(wc_check_reader * c, const wc_json_node * o,
                     const char * key, size_t want, mpq_t ** q,
                     size_t * len);

/* The storage of an array of n entries: k rationals each, into *q, and
   one object of the given size each, returned.  Both or neither: NULL,
   *q NULL and out of memory recorded.  */
void * _wc_check_entries_new(wc_check_reader * c, mpq_t ** q, size_t k,
                             size_t n, size_t size);

/* The rational o[key] into q, which must be positive (sign 1) or
   non-negative (sign 0).  */
int _wc_check_scalar(wc_check_reader * c, const wc_json_node * o,
                     const char * key, mpq_t q, int sign);

/* The kind of the certificate root (which must be an object).  */
int _wc_check_kind(wc_check_reader * c, const wc_json_node * root,
                   wc_check_kind * kind);

/* ------------------------------------------------------------------ */
/* The problem a certificate states (problem.c).                       */

typedef struct
{
    mpq_t * body;       /* 4: mass, inertia, com x, y */
    size_t n;           /* fixels; 0 until known */
    mpq_t * fixel;      /* 6 n: point x, y, normal x, y, mu_s, mu_k */
    int * near;         /* n: 1 near, 0 touching; -1 until read */
}
wc_check_problem;

void _wc_check_problem_init(wc_check_problem * P);
void _wc_check_problem_clear(wc_check_problem * P);

/* root["problem"] into P: com and fixels (point, normal, state), and
   with dynamics also mass, inertia, mu_s and mu_k.  */
int _wc_check_read_problem(wc_check_problem * P, wc_check_reader * c,
                           const wc_json_node * root, int dynamics);

/* The letters of the string at v against the fixels (as far as they are
   known): one letter per fixel, of a mode (Table 1: s l r n on touching
   fixels, s a on near ones) or, with sign, of a sign string (s l r n,
   u).  */
int _wc_check_letters(wc_check_reader * c, const wc_json_node * v,
                      const wc_check_problem * P, int sign);

/* J[0..3) = J_n = (n_x, n_y, r x n) and J[3..6) = J_t = (t_x, t_y,
   r x t) of fixel i, where r = point - com and t = (-n_y, n_x).  */
void _wc_check_jacobian(mpq_t * J, const wc_check_problem * P, size_t i);

/* ------------------------------------------------------------------ */
/* Mode-feasibility certificates (feasible.c).                         */

/* Check the mode-feasibility certificate at root (its kind read).
   Returns c->status; with WC_OK, *holds, why, *mode (malloc'd: the caller
   frees) and *feasible.  */
int _wc_check_mode_certificate(wc_check_reader * c,
                               const wc_json_node * root, int * holds,
                               wc_check_text * why, char ** mode,
                               int * feasible);

/* ------------------------------------------------------------------ */
/* The cone of the directions x with h . x >= 0 (cone.c).              */

/* K = span(L[0 .. dl)) + cone(r[0 .. nr)), primitive integer vectors;
   with dl = 0 and nr >= 3 the rays go around K in cyclic order.  work
   counts the products h . v computed.  */
typedef struct
{
    int dl;
    mpz_t * L;                  /* 9 */
    size_t nr, cap;
    mpz_t * r, * o;             /* 3 cap each: rays, scratch */
    mpz_t * d;                  /* cap, scratch */
    mpz_t * v;                  /* 3, scratch */
    mpz_t a, c, t;
    unsigned long work;
}
wc_check_cone;

/* v = v / gcd of its entries; t scratch.  */
void _wc_check_zprimitive(mpz_t * v, mpz_t t);

/* K = R^3, with room for cuts cuts.  WC_OK or WC_EINTERNAL; either way
   _wc_check_cone_clear frees.  */
int _wc_check_cone_init(wc_check_cone * K, size_t cuts);
void _wc_check_cone_clear(wc_check_cone * K);

/* K = K cut by h . x >= 0 (h a nonzero integer vector).  WC_OK, or
   WC_EINTERNAL after more cuts than room was made for.  */
int _wc_check_cone_cut(wc_check_cone * K, mpz_t * h);

/* ------------------------------------------------------------------ */
/* The regions of a certificate's tree (region.c).                     */

/* A relatively open pointed cone of R^3: dim 0 .. 3 (-1: empty), and the
   extreme rays of its closure, primitive integer vectors, around the
   cone when dim is 3 (consecutive rays, and the last with the first,
   span its facets).  The origin has no rays; an open ray one; an open
   sector two.  */
typedef struct
{
    int dim;
    size_t n, cap;
    mpz_t * r;              /* 3 cap */
}
wc_check_region;

void _wc_check_region_init(wc_check_region * R);     /* empty */
void _wc_check_region_clear(wc_check_region * R);
/* D := R.  1 or -1.  */
int _wc_check_region_copy(wc_check_region * D, const wc_check_region * R);
/* out[9 (s_1 + 1) + 3 (s_2 + 1) + (s_3 + 1)] := the region where
   sign(h_i . x) = s_i (s_i in -1, 0, 1) for the planes h_1, h_2, h_3 (9
   entries): the 27 relatively open faces of the simplicial fan they cut.
   1, 0 when the planes are dependent, -1 when out of memory.  */
int _wc_check_region_basis(wc_check_region * out, mpz_t * h);
/* out[0], out[1], out[2] := R cut by h . x < 0, = 0, > 0 (dim -1 when
   empty).  1 or -1.  */
int _wc_check_region_split(wc_check_region * out, const wc_check_region * R,
                           mpz_t * h);

/* ------------------------------------------------------------------ */
/* The moving faces (faces.c).                                         */

/* A set of strings of n + 1 bytes each, malloc'd; all zero when empty.
   work: how many products of integer vectors the walk that made the set
   computed (its cost; the tests bound it).  */
typedef struct
{
    size_t count;
    size_t cap;
    char ** s;
    int oom;
    unsigned long work;
}
wc_check_strings;

void _wc_check_strings_clear(wc_check_strings * T);

/* The index of s in the set made by _wc_check_moving_faces, or -1.  */
long _wc_check_strings_find(const wc_check_strings * T, const char * s);

/* Every sign string S(nudot) with a_in >= 0 at every touching fixel of
   P, other than n..n, into out, sorted, each once; J holds J_in and J_it
   of every fixel (6 n).  */
int _wc_check_moving_faces(wc_check_strings * out,
                           const wc_check_problem * P, mpq_t * J);

/* ------------------------------------------------------------------ */
/* Strong-stability certificates (stabread.c, stabcheck.c,
   facecheck.c).                                                       */

/* One entry of "faces".  */
typedef struct
{
    const wc_json_node * sign;          /* NULL until read */
    const wc_json_node * rot_node;      /* NULL when absent */
    int rotation;                       /* 0, 1 or -1 */
    size_t nmult;
    mpq_t * mult;
}
wc_check_face;

/* What a strong-stability certificate says.  */
typedef struct
{
    wc_check_problem P;
    mpq_t * g;                          /* 3 */
    int weak;                           /* -1 until read */
    int strong;                         /* -1 until read */
    size_t nwc;
    mpq_t * weak_c;                     /* 2 n, when weak */
    mpq_t * sep;                        /* 3, when not weak */
    const wc_json_node * motion_sign;   /* when weak and not strong */
    mpq_t * nudot;                      /* 3 */
    size_t nmc;
    mpq_t * motion_c;                   /* 2 n */
    size_t nfaces;                      /* when strong */
    wc_check_face * faces;
}
wc_check_stability;

void _wc_check_stability_init(wc_check_stability * S);
void _wc_check_stability_clear(wc_check_stability * S);

/* Read everything the check of a strong-stability certificate (its kind
   read) needs from the document; errors into c.  */
void _wc_check_read_stability(wc_check_stability * S, wc_check_reader * c,
                              const wc_json_node * root);

/* root[key], an array of faces, into S->faces (with their multipliers
   when mult); errors into c.  */
void _wc_check_read_faces(wc_check_reader * c, wc_check_stability * S,
                          const wc_json_node * root, const char * key,
                          int mult);

/* The sign strings of S (the motion's, the faces') against the problem;
   errors into c.  */
void _wc_check_signs(wc_check_reader * c, const wc_check_stability * S);

/* What the checks of one strong-stability certificate share.  */
typedef struct
{
    const wc_check_stability * S;
    mpq_t * J;          /* 6 n: J_in, J_it of every fixel */
    mpq_t * s;          /* 3 */
    mpq_t a, b, t;
    wc_check_text * why;
    /* The wrenches the checks speak of: sum_i alpha_i G_i, alpha_i > 0
       (S->g alone, ng = 1, for one wrench).  */
    mpq_t * G;
    size_t ng;
    /* The motion checked by _wc_check_motion: of the closure of its face
       (> relaxed to >=, nudot = 0 allowed) when closed; rotation +-1 on
       a rotation face (rho v . nudot > 0), else 0.  */
    int closed;
    int rotation;
}
wc_check_scratch;

/* X->J := the Jacobian columns of X->S->P, the rest initialised (G = S->g,
   ng = 1, closed = rotation = 0).  0 when out of memory (then clear).  */
int _wc_check_scratch_init(wc_check_scratch * X, const wc_check_stability * S,
                           wc_check_text * why);
void _wc_check_scratch_clear(wc_check_scratch * X);

/* The faces claim: exactly the moving faces, each once, each without a
   solution.  */
int _wc_check_faces(wc_check_scratch * X);

/* The faces S->faces are exactly the moving faces, each once (their
   multipliers are not looked at).  1, 0 or -1.  */
int _wc_check_face_list(wc_check_scratch * X);

/* The Motzkin multipliers of face F (number k, 0-based) prove that no
   wrench of X (X->G, X->ng) has a motion of F.  1, 0 or -1.  */
int _wc_check_face(wc_check_scratch * X, size_t k, const wc_check_face * F);

/* The static forces S->weak_c hold the wrench S->g.  1 or 0.  */
int _wc_check_static(wc_check_scratch * X);

/* The motion (S->motion_sign, S->nudot, S->motion_c) moves under the
   wrench S->g, in the mode of its sign (of its closure with X->closed).
   1 or 0.  */
int _wc_check_motion(wc_check_scratch * X);

/* y . (J_in -+ mu_s J_it) >= 0 at every touching fixel: y separates the
   weak cone.  1 or 0 (why written after "the separator y = (..) has").  */
int _wc_check_separates(wc_check_scratch * X, mpq_t * y);

/* Check the strong-stability certificate at root (its kind read).
   Returns c->status; with WC_OK, *holds, why and what (the claim).  */
int _wc_check_stability_certificate(wc_check_reader * c,
                                    const wc_json_node * root,
                                    int * holds, wc_check_text * why,
                                    wc_check_text * what);

/* ------------------------------------------------------------------ */
/* Stability-set certificates (setread.c, setcheck.c).                 */

/* The most work on a tree the checker does: rays of the regions cut, and
   rays times constraints at the leaves (far more than a certificate of
   wrenchcone needs).  */
#define WC_CHECK_TREE_WORK (1UL << 26)

/* One piece of a claimed set (or a moving face's cone): the closure
   {a . x <= 0, e . x = 0}, its rays and lines, its faces (rays, dim,
   included).  */
typedef struct
{
    const wc_json_node * at;
    size_t nineq, neq, nrays, nlines, nfaces;
    mpq_t * ineq, * eq, * rays, * lines;    /* 3 each */
    mpz_t * zineq, * zeq;       /* the same constraints, primitive
                                   integer vectors (set when checked) */
    unsigned char * tight;      /* nfaces x nineq: 1 when inequality a is
                                   tight on face f (set when checked) */
    size_t * foff, * fray;      /* face f: rays fray[foff[f] .. foff[f+1]) */
    int * fincl;
    long * fdim;
    long dim, lin;
}
wc_check_piece;

/* A claimed set, as stability --format=json writes it.  */
typedef struct
{
    const wc_json_node * at;
    int empty, interior;
    size_t npieces;
    wc_check_piece * pc;
}
wc_check_claim;

void _wc_check_claim_clear(wc_check_claim * C);

/* A cone written as stability --format=json writes one, at o, into Q
   (all zero before); _wc_check_piece_clear frees it.  */
int _wc_check_read_piece(wc_check_reader * c, wc_check_piece * Q,
                         const wc_json_node * o);
void _wc_check_piece_clear(wc_check_piece * Q);

/* root[key] into C (all zero before).  */
int _wc_check_read_claim(wc_check_reader * c, wc_check_claim * C,
                         const wc_json_node * root, const char * key);

/* C describes its pieces consistently.  1, 0 (why written) or -1.  */
int _wc_check_claim_valid(wc_check_text * why, wc_check_claim * C);

/* The cones Q[0 .. n) each describe themselves consistently (who names
   them in why: "the cone of moving face"); an empty one (no faces) is
   left alone.  Sets their zineq, zeq and tight.  1, 0 or -1.  */
int _wc_check_cones_valid(wc_check_text * why, wc_check_piece * Q, size_t n,
                          const char * who);


/* A leaf of a certificate's tree: its region lies in a face of a piece
   (in) or of the cone of a member of the family, or is not weakly stable
   (has_sep).  */
typedef struct
{
    int in;
    int has_sep;
    mpq_t * sep;                /* 3 */
    size_t owner, face;         /* the piece (in) or member of the family
                                   (out), and the face of its cone */
}
wc_check_leaf;

/* Everything the check shares.  */
typedef struct
{
    int plan;                   /* a plan-goal certificate, else a
                                   stability-set one */
    wc_check_stability S;       /* the problem and the excluding family:
                                   moving faces, or a plan's strings */
    wc_check_claim claim;
    size_t nplanes;
    mpz_t * H;
    const wc_json_node * tree, * proofs, * moving;
    wc_check_piece * mc;        /* the cone of each of the family */
    size_t basis[3];            /* the tree's first three planes */
    wc_check_leaf leaf;
    size_t leaves;              /* the tree's leaves */
    size_t work;                /* the tree's work so far */
    int too_big;                /* the walk stopped at WC_CHECK_TREE_WORK */
    mpq_t * G;                  /* 3 */
    mpq_t * F;                  /* 3 (the most generators of a face) */
    size_t fcap;
    mpq_t * stat;               /* 2 n */
    mpq_t * mult;
    size_t nmult, multcap;
}
wc_check_set;

void _wc_check_set_init(wc_check_set * K);
void _wc_check_set_clear(wc_check_set * K);

/* Read the whole certificate at root into K (K->plan set); errors into
   c.  */
int _wc_check_set_read(wc_check_reader * c, wc_check_set * K,
                       const wc_json_node * root);

/* The tree of a set certificate (settree.c): read in full (malformed:
   c's error), and walked (1, 0 with why, or -1).  */
int _wc_check_tree_read(wc_check_reader * c, wc_check_set * K);
int _wc_check_tree_walk(wc_check_scratch * X, wc_check_set * K);

/* One leaf of the tree at v into K->leaf; one motion at v into K->S.nudot and
   K->S.motion_c; one array of rationals at v into K->mult (K->nmult).  */
int _wc_check_set_read_leaf(wc_check_reader * c, wc_check_set * K,
                            const wc_json_node * v);
int _wc_check_set_read_motion(wc_check_reader * c, wc_check_set * K,
                              const wc_json_node * v);
int _wc_check_set_read_mult(wc_check_reader * c, wc_check_set * K,
                            const wc_json_node * v);

/* A plan's strings (plansys.c).  S->faces, read from a plan-goal
   certificate, are every string with one s and m or u elsewhere, each
   once.  1, 0 or -1.  */
int _wc_check_plan_strings(wc_check_text * why, const wc_check_stability * S);

/* The multipliers y (ny) prove that no wrench of X (X->G, X->ng) lies in
   the cone of the plan string x (number k).  1, 0 or -1.  */
int _wc_check_plan_face(wc_check_scratch * X, size_t k, const char * x,
                        mpq_t * y, size_t ny);

/* The solution (S->nudot, S->motion_c) puts the wrench S->g in the cone
   of the plan string x.  1 or 0.  */
int _wc_check_plan_motion(wc_check_scratch * X, const char * x);

/* Check the critical-friction certificate at root (its kind read)
   (critcheck.c).  */
int _wc_check_crit_certificate(wc_check_reader * c,
                               const wc_json_node * root, int * holds,
                               wc_check_text * why, wc_check_text * what);

/* Check the stability-set certificate (plan 0) or the plan-goal one
   (plan 1) at root (its kind read).  */
int _wc_check_set_certificate(wc_check_reader * c,
                              const wc_json_node * root, int plan,
                              int * holds, wc_check_text * why,
                              wc_check_text * what);

#endif
