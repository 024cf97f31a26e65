/* setcheck.h -- internal: the check of a stability-set or
   plan-goal certificate (one format: setread.c, setdoc.c, settree.c,
   setcheck.c; a plan's strings, plansys.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  GMP and lib/core only, as all of lib/check
   (checker.h).  */

#ifndef WC_CHECK_SETCHECK_H
#define WC_CHECK_SETCHECK_H

#include "check/checker.h"
#include "check/stabcheck.h"

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

/* Check the stability-set certificate (plan 0) or the plan-goal one
   (plan 1) at root (its kind read).  */
int _wc_check_set_certificate(wc_check_reader * c,
                              const wc_json_node * root, int plan,
                              int * holds, wc_check_text * why,
                              wc_check_text * what);

#endif
