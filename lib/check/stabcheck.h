/* stabcheck.h -- internal: the check of a strong-stability
   certificate (stabread.c, stabcheck.c, facecheck.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  GMP and lib/core only, as all of lib/check
   (checker.h).  The set certificates (setcheck.h) reuse its
   document and scratch: their problem, family and checks of one wrench.  */

#ifndef WC_CHECK_STABCHECK_H
#define WC_CHECK_STABCHECK_H

#include "check/checker.h"

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

#endif
