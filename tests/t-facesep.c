/* t-facesep.c -- the quick proof that a moving face has no motion
   (lib/analysis/facesys.c, a separating plane turned into checked Motzkin
   multipliers) against the exact LP it stands in front of.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The reference is the slow path kept as it was: _wc_face_solve with
   multipliers asked for always solves the face's whole system with the
   exact LP (cddlib, checked row by row).  On every face tried here:

     - when _wc_face_separate says "no motion", the LP finds none;
     - _wc_face_solve without multipliers (the fast paths first) gives
       the LP's verdict;

   over random problems (degenerate layouts from testutil: normals
   through one point, collinear and coincident points, opposed normals,
   zero friction, near fixels) and cradles (every normal through the
   centre of mass, so that rotation faces load every fixel), the moving
   faces of each, the same faces with loaded letters switched to s (as
   the search for modes does), random kinematic strings, and wrenches on
   the cones' boundaries: single friction edges, sums of two, the
   rotation's M v, and random ones.  The quick proof must also fire on
   the cradles' rotation faces under gravity, the case it exists for.  */

#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpq_vec.h>

#include "wrenchcone.h"
#include "model/model.h"
#include "analysis/stabmodel.h"
#include "analysis/facesys.h"
#include "core/randgen.h"
#include "testutil.h"

typedef struct
{
    char ** y;
    int * rot;
    slong len;
}
facelist;

static int
collect(void * p, const char * y, int rot)
{
    facelist * L = p;

    L->y = realloc(L->y, sizeof(char *) * (L->len + 1));
    L->rot = realloc(L->rot, sizeof(int) * (L->len + 1));
    L->y[L->len] = malloc(strlen(y) + 1);
    strcpy(L->y[L->len], y);
    L->rot[L->len++] = rot;
    return WC_OK;
}

static slong proved = 0, proved_cradle = 0;

/* One face (y, x, rot) and one wrench g: the checks above.  */
static void
check_face(const wc_problem_t P, const _wc_stab_model * m, const char * y,
           const char * x, int rot, const fmpq * g, int cradle)
{
    wc_error_t err;
    fmpq nu[3], nu2[3];
    fmpq * c = _fmpq_vec_init(2 * m->n + 1), * c2 = _fmpq_vec_init(2 * m->n + 1);
    fmpq * mult = NULL;
    slong nmult = 0, k;
    int slow, fast, sep;

    wc_error_init(err);
    for (k = 0; k < 3; k++)
    {
        fmpq_init(nu + k);
        fmpq_init(nu2 + k);
    }
    slow = _wc_face_solve(nu, c, &mult, &nmult, m, y, x, rot, g, err);
    sep = _wc_face_separate(m, y, x, rot, g, err);
    fast = _wc_face_solve(nu2, c2, NULL, NULL, m, y, x, rot, g, err);
    if (slow < 0 || sep < 0 || fast < 0)
        wctest_fail_problem(P, y, "an error (x = %s, rot = %d): %s", x, rot,
                            err->message ? err->message : "?");
    if (sep == 1 && slow != 0)
        wctest_fail_problem(P, y, "the quick proof says no motion, the LP "
                            "finds one (x = %s, rot = %d, g = %s)", x, rot,
                            wctest_vec_str(g, 3));
    if (fast != slow)
        wctest_fail_problem(P, y, "fast verdict %d, LP %d (x = %s, rot = "
                            "%d, g = %s)", fast, slow, x, rot,
                            wctest_vec_str(g, 3));
    proved += sep;
    proved_cradle += sep && cradle;
    if (mult != NULL)
        _fmpq_vec_clear(mult, nmult);
    for (k = 0; k < 3; k++)
    {
        fmpq_clear(nu + k);
        fmpq_clear(nu2 + k);
    }
    _fmpq_vec_clear(c, 2 * m->n + 1);
    _fmpq_vec_clear(c2, 2 * m->n + 1);
    wc_error_clear(err);
}

/* The wrenches tried on P: gravity, random ones, friction edges and sums
   of two (negated: the forces the fixels push with), M v.  G has room for
   3 * 24 entries; returns the count.  */
static slong
wrenches(fmpq * G, const _wc_stab_model * m)
{
    slong k = 0, i, j, a, b, q;
    fmpq ed[4], w[3];

    for (j = 0; j < 4; j++)
        fmpq_init(ed + j);
    for (j = 0; j < 3; j++)
        fmpq_init(w + j);
    fmpq_set_si(G + 1, -1, 1);
    k = 1;
    for (; k < 5; k++)
        wctest_random_wrench(G + 3 * k);
    for (q = 0; q < 12 && m->t > 0; q++, k++)
    {
        a = m->tidx[wctest_randint(0, m->t - 1)];
        b = m->tidx[wctest_randint(0, m->t - 1)];
        for (i = 0; i < (q % 2 ? 2 : 1); i++)
        {
            slong f = i == 0 ? a : b;
            int c = wc_friction_edges(ed, m->P->fixels + f,
                                      "lrn"[wctest_randint(0, 2)]);

            _wc_stab_edge_wrench(w, m, f, ed + 2 * wctest_randint(0, c - 1));
            for (j = 0; j < 3; j++)
                fmpq_sub(G + 3 * k + j, G + 3 * k + j, w + j);
        }
    }
    for (j = 0; j < 3 && m->t > 0; j++)
        fmpq_mul(G + 3 * k + j, m->v + j, m->M + j);
    k += m->t > 0;
    for (j = 0; j < 4; j++)
        fmpq_clear(ed + j);
    for (j = 0; j < 3; j++)
        fmpq_clear(w + j);
    return k;
}

static void
check_problem(const wc_problem_t P, int cradle)
{
    _wc_stab_model m;
    facelist L = { NULL, NULL, 0 };
    wc_error_t err;
    fmpq * G = _fmpq_vec_init(3 * 24);
    char * x = malloc(P->n + 1);
    slong i, j, w, nw;

    wc_error_init(err);
    _wc_stab_model_init(&m, P);
    if (m.t == 0)
        goto done;
    if (_wc_stab_moving_faces(&m, collect, &L, err) != WC_OK)
        wctest_fail_problem(P, NULL, "moving faces: %s", err->message);
    /* random kinematic strings too (near letters u, as in classify's
       faces, but on the first) */
    for (i = 0; i < 3; i++)
    {
        wctest_random_mode_kinematic(x, P);
        for (j = 0; j < P->n && i > 0; j++)
            if (P->fixels[j].state != WC_TOUCHING)
                x[j] = 'u';
        collect(&L, x, 0);
    }
    nw = wrenches(G, &m);
    for (i = 0; i < L.len; i++)
    {
        for (w = 0; w < nw; w++)
        {
            if (!cradle && w > 0 && !wctest_chance(1, 3))
                continue;
            check_face(P, &m, L.y[i], L.y[i], L.rot[i], G + 3 * w, cradle);
            if (L.rot[i] != 0)
                continue;
            /* loaded letters switched to s, one at random each */
            strcpy(x, L.y[i]);
            for (j = 0; j < P->n; j++)
                if (P->fixels[j].state == WC_TOUCHING && x[j] != 's'
                    && wctest_chance(1, 3))
                    x[j] = 's';
            if (strcmp(x, L.y[i]) != 0)
                check_face(P, &m, L.y[i], x, 0, G + 3 * w, cradle);
        }
    }
done:
    for (i = 0; i < L.len; i++)
        free(L.y[i]);
    free(L.y);
    free(L.rot);
    free(x);
    _fmpq_vec_clear(G, 3 * 24);
    _wc_stab_model_clear(&m);
    wc_error_clear(err);
}

/* A cradle: t fixels on the lower half of the unit circle, normals
   through the centre (the centre of mass), friction mu (0 too); with
   near, one more near fixel on top.  */
static void
cradle(wc_problem_t P, slong t, slong mu_num, slong mu_den, int near)
{
    slong k;

    fmpq_set_si(P->mu_s, mu_num, (ulong) mu_den);
    fmpq_set_si(P->mu_k, mu_num, (ulong) mu_den);
    fmpq_zero(P->com + 0);
    fmpq_zero(P->com + 1);
    for (k = 0; k < t + near; k++)
    {
        wc_fixel_struct * f = wc_problem_add_fixel(P);
        fmpq_t s;

        fmpq_init(s);
        /* the parameter -s gives the point below the axis */
        if (k < t)
            fmpq_set_si(s, -(k + 1), (ulong) (t - k));
        else
            fmpq_one(s);
        _wc_unit_circle_point(f->point, s);
        fmpq_neg(f->normal + 0, f->point + 0);
        fmpq_neg(f->normal + 1, f->point + 1);
        f->state = k < t ? WC_TOUCHING : WC_NEAR;
        fmpq_clear(s);
    }
}

int
main(void)
{
    slong i, iters;

    wctest_init("t-facesep");
    wc_init();
    iters = wctest_iters(24);
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        if (i % 4 == 3)
            cradle(P, wctest_randint(1, 7), wctest_randint(0, 2),
                   wctest_randint(1, 3), wctest_chance(1, 2));
        else
            wctest_random_problem(P, 1, 5);
        check_problem(P, i % 4 == 3);
        wc_problem_clear(P);
    }
    if (proved == 0 || proved_cradle == 0)
        wctest_fail("the quick proof never fired (%ld, on cradles %ld)",
                    (long) proved, (long) proved_cradle);
    return 0;
}
