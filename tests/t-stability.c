/* t-stability.c -- weak and strong stability (lib/stability.c) against
   the independent oracle tests/ref-stab.c.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   wc_classify decides one wrench with LPs over the faces of the
   arrangement; ref-stab.c decides the same questions with one LP per sign
   pattern (4^t of them) and ref-lp.c's Table 2 LP, sharing nothing with
   the library's stability, kinematics or cone code.  The verdicts must
   agree on random wrenches and, above all, on the wrenches where the sets
   change: the rays and the relative-interior points of every face of
   every piece of the weak cone, of both strong sets, of every moving
   face's cone and of every cone of eq. 19's union, the zero wrench, and
   small perturbations of those.  Every witness the library gives (static
   forces, a separating vector, a motion (nudot, c) with its sign string,
   the paper semantics' solution) is substituted back here, with J and M
   rebuilt from the problem's fields.  The sets of wc_stability must hold
   exactly the wrenches classify calls weak / strong / strong in the
   paper's sense, with pieces pairwise disjoint, and with certificates on
   the moving faces with and without a solution must add up to the faces
   of the arrangement, counted here by ref-kin.c's Table 1 LPs.  */

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>

#include "wrenchcone.h"
#include "analysis/stability.h"
#include "exact/cells.h"
#include "ref-lp.h"
#include "ref-kin.h"
#include "ref-stab.h"
#include "testutil.h"

/* ---- vectors and the model, from the problem's fields ----------------- */

/* Column of J for fixel i: its normal (side 0) or its tangent, the normal
   turned by +90 degrees (side 1): (d_x, d_y, (p_i - o) x d).  */
static void
jcol(fmpq * col, const wc_problem_struct * P, slong i, int side)
{
    const wc_fixel_struct * f = P->fixels + i;

    if (side == 0)
    {
        fmpq_set(col + 0, f->normal + 0);
        fmpq_set(col + 1, f->normal + 1);
    }
    else
    {
        fmpq_neg(col + 0, f->normal + 1);
        fmpq_set(col + 1, f->normal + 0);
    }
    wctest_wrench_of(col, P, f, col);
}

static slong
touching_count(const wc_problem_struct * P)
{
    slong i, t = 0;

    for (i = 0; i < P->n; i++)
        t += (P->fixels[i].state == WC_TOUCHING);
    return t;
}

/* 1 when every touching fixel has the same contact point (and there is
   at least one): then, and only then, nudot != 0 with a = 0 on every
   touching fixel exists (rotation about the point; two fixels at
   different points leave only nudot = 0, since (J_in, J_it) of one fixel
   pin the point's acceleration).  */
static int
touching_share_point(const wc_problem_struct * P)
{
    slong i, first = -1;

    for (i = 0; i < P->n; i++)
    {
        if (P->fixels[i].state != WC_TOUCHING)
            continue;
        if (first < 0)
            first = i;
        else if (!fmpq_equal(P->fixels[i].point + 0,
                             P->fixels[first].point + 0)
                 || !fmpq_equal(P->fixels[i].point + 1,
                                P->fixels[first].point + 1))
            return 0;
    }
    return first >= 0;
}

/* ---- failures ------------------------------------------------------- */

typedef struct
{
    const wc_problem_struct * P;
    const wc_stability_struct * S;  /* NULL: classify only */
    slong faces;                    /* moving faces of the arrangement */
    const char * what;
}
ctx_t;

static _Noreturn void
fail_at(const ctx_t * X, const fmpq * g, const char * fmt, ...)
    WCTEST_PRINTF(3, 4);

static _Noreturn void
fail_at(const ctx_t * X, const fmpq * g, const char * fmt, ...)
{
    char msg[1024];
    char * gs = (g != NULL) ? wctest_vec_str(g, 3) : NULL;
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    wctest_fail_problem(X->P, NULL, "%s: wrench %s: %s", X->what,
                        gs != NULL ? gs : "-", msg);
}

/* ---- solutions ------------------------------------------------------ */

/* Check a solution (nudot, c) for g with the string x.  motion = 1: x is
   the sign string of a moving solution, derived here from a = J^T nudot
   (touching: s when a_in > 0, else l, r, n by the sign of a_it; a_in < 0
   is penetration; near: u) and nudot != 0.  motion = 0: x is a Table 2
   string (s with a_in >= 0), u on near fixels.  Forces: s and u none,
   l c_it = -mu_k c_in, r c_it = +mu_k c_in, n |c_it| <= mu_s c_in, and
   c_in >= 0; and M nudot = J c + g.  Returns NULL or what is wrong.  */
static const char *
solution_error(const wc_problem_struct * P, const char * x,
               const fmpq * nudot, const fmpq * c, const fmpq * g,
               int motion)
{
    slong n = P->n, i, j;
    fmpq col[3], net[3];
    fmpq_t an, at, tmp;
    const char * bad = NULL;

    if (x == NULL || (slong) strlen(x) != n)
        return "the string has the wrong length";
    if (motion && wctest_vec3_is_zero(nudot))
        return "nudot = 0 in a moving solution";
    for (j = 0; j < 3; j++)
    {
        fmpq_init(col + j);
        fmpq_init(net + j);
        fmpq_set(net + j, g + j);
    }
    fmpq_init(an);
    fmpq_init(at);
    fmpq_init(tmp);

    for (i = 0; i < n && bad == NULL; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;
        const fmpq * cn = c + i, * ct = c + n + i;
        char want;

        /* net := g + J c, column by column.  */
        for (j = 0; j < 2; j++)
        {
            slong k;

            jcol(col, P, i, j);
            for (k = 0; k < 3; k++)
            {
                fmpq_mul(tmp, col + k, c + j * n + i);
                fmpq_add(net + k, net + k, tmp);
            }
        }
        jcol(col, P, i, 0);
        wctest_dot3(an, col, nudot);
        jcol(col, P, i, 1);
        wctest_dot3(at, col, nudot);

        if (f->state == WC_NEAR)
        {
            if (x[i] != 'u')
                bad = "a near fixel's letter is not u";
            else if (!fmpq_is_zero(cn) || !fmpq_is_zero(ct))
                bad = "force at a near fixel";
            continue;
        }
        if (fmpq_sgn(an) < 0)
        {
            bad = "penetration: a_in < 0 at a touching fixel";
            continue;
        }
        if (motion)
        {
            want = fmpq_sgn(an) > 0 ? 's' : fmpq_sgn(at) > 0 ? 'l'
                : fmpq_sgn(at) < 0 ? 'r' : 'n';
            if (x[i] != want)
            {
                bad = "the sign string is not that of a = J^T nudot";
                continue;
            }
        }
        else
        {
            int ok = (x[i] == 's')
                || (x[i] == 'l' && fmpq_is_zero(an) && fmpq_sgn(at) > 0)
                || (x[i] == 'r' && fmpq_is_zero(an) && fmpq_sgn(at) < 0)
                || (x[i] == 'n' && fmpq_is_zero(an) && fmpq_is_zero(at));

            if (!ok)
            {
                bad = "a = J^T nudot violates the Table 2 letter";
                continue;
            }
        }
        if (fmpq_sgn(cn) < 0)
            bad = "c_in < 0";
        else if (x[i] == 's')
        {
            if (!fmpq_is_zero(cn) || !fmpq_is_zero(ct))
                bad = "force at a separating (s) fixel";
        }
        else if (x[i] == 'l' || x[i] == 'r')
        {
            fmpq_mul(tmp, f->mu_k, cn);
            if (x[i] == 'l')
                fmpq_neg(tmp, tmp);
            if (!fmpq_equal(tmp, ct))
                bad = "sliding force off the kinetic friction edge";
        }
        else if (x[i] == 'n')
        {
            fmpq_mul(tmp, f->mu_s, cn);
            fmpq_abs(an, ct);
            if (fmpq_cmp(an, tmp) > 0)
                bad = "force outside the static friction cone";
        }
        else
            bad = "a touching fixel's letter is not s, l, r or n";
    }

    /* M nudot = J c + g.  */
    for (j = 0; j < 3 && bad == NULL; j++)
    {
        fmpq_mul(tmp, j < 2 ? P->mass : P->inertia, nudot + j);
        if (!fmpq_equal(tmp, net + j))
            bad = "M nudot != J c + g";
    }

    for (j = 0; j < 3; j++)
    {
        fmpq_clear(col + j);
        fmpq_clear(net + j);
    }
    fmpq_clear(an);
    fmpq_clear(at);
    fmpq_clear(tmp);
    return bad;
}

/* 1 when x has n on every touching fixel.  */
static int
string_all_n(const wc_problem_struct * P, const char * x)
{
    slong i;

    for (i = 0; i < P->n; i++)
        if (P->fixels[i].state == WC_TOUCHING && x[i] != 'n')
            return 0;
    return 1;
}

/* ---- one wrench ----------------------------------------------------- */

/* Number of the pieces of S holding g.  */
static slong
pieces_holding(const wc_set_struct * T, const fmpq * g)
{
    slong i, k = 0;

    for (i = 0; i < T->npieces; i++)
        k += wc_cone_contains(T->pieces + i, g);
    return k;
}

/* Everything about g.  oracle: compare with ref-stab (weak, motion,
   union); modes: also the Table 2 list; certificates: classify with
   them.  */
static void
check_wrench(const ctx_t * X, const fmpq * g, int oracle, int modes,
             int certificates)
{
    const wc_problem_struct * P = X->P;
    const wc_stability_struct * S = X->S;
    slong n = P->n, i, j, t = touching_count(P), max_modes;
    wc_classify_t R;
    wc_error_t err;
    const char * bad;
    fmpq * zero;
    int ref_weak = -2, ref_motion = -2, ref_union = -2;

    /* Now and then a cap on the mode list, checked against the oracle's
       full list below.  */
    max_modes = (modes && wctest_chance(1, 4)) ? wctest_randint(1, 3) : 0;
    wc_classify_init(R);
    if (wc_classify(R, P, g, certificates, max_modes, err) != WC_OK)
        fail_at(X, g, "wc_classify failed: %s", err->message);
    if (R->n != n)
        fail_at(X, g, "R->n = %ld, not %ld", (long) R->n, (long) n);
    for (j = 0; j < 3; j++)
        if (!fmpq_equal(R->g + j, g + j))
            fail_at(X, g, "R->g is not the wrench classified");
    if (R->strong && !R->weak)
        fail_at(X, g, "strong but not weak");

    /* The weak verdict's evidence: static forces, or y with y . g > 0 and
       y . (J_in +- mu_s J_it) >= 0 at every touching fixel, so that
       y . (-J c) <= 0 for every c in the friction cones.  */
    zero = _fmpq_vec_init(3);
    if (R->weak)
    {
        char * x = flint_malloc(n + 1);

        for (i = 0; i < n; i++)
            x[i] = P->fixels[i].state == WC_TOUCHING ? 'n' : 'u';
        x[n] = '\0';
        bad = solution_error(P, x, zero, R->weak_c, g, 0);
        flint_free(x);
        if (bad != NULL)
            fail_at(X, g, "weak_c is not a static solution: %s", bad);
    }
    else
    {
        fmpq col[3];
        fmpq_t v, w, tmp;

        for (j = 0; j < 3; j++)
            fmpq_init(col + j);
        fmpq_init(v);
        fmpq_init(w);
        fmpq_init(tmp);
        wctest_dot3(v, R->weak_sep, g);
        if (fmpq_sgn(v) <= 0)
            fail_at(X, g, "weak_sep . g <= 0");
        for (i = 0; i < n; i++)
        {
            if (P->fixels[i].state != WC_TOUCHING)
                continue;
            jcol(col, P, i, 0);
            wctest_dot3(v, R->weak_sep, col);
            jcol(col, P, i, 1);
            wctest_dot3(w, R->weak_sep, col);
            fmpq_mul(w, w, P->fixels[i].mu_s);
            fmpq_add(tmp, v, w);
            fmpq_sub(v, v, w);
            if (fmpq_sgn(tmp) < 0 || fmpq_sgn(v) < 0)
                fail_at(X, g, "weak_sep does not separate at fixel %ld",
                        (long) i + 1);
        }
        for (j = 0; j < 3; j++)
            fmpq_clear(col + j);
        fmpq_clear(v);
        fmpq_clear(w);
        fmpq_clear(tmp);
    }

    /* Motions: witnesses, distinct sign strings except the rotation
       faces n..n (twice at most, only when the touching fixels share a
       point, or once for a free body).  */
    for (i = 0; i < R->nmotions; i++)
    {
        const wc_motion_struct * a = R->motions + i;
        slong same = 0;

        bad = solution_error(P, a->sign, a->nudot, a->c, g, 1);
        if (bad != NULL)
            fail_at(X, g, "motion %ld (%s): %s", (long) i,
                    a->sign != NULL ? a->sign : "NULL", bad);
        for (j = 0; j < R->nmotions; j++)
            same += (strcmp(R->motions[j].sign, a->sign) == 0);
        if (string_all_n(P, a->sign))
        {
            if (t > 0 && !touching_share_point(P))
                fail_at(X, g, "a rotation motion although the touching "
                        "fixels do not share a point");
            if (same > (t > 0 ? 2 : 1))
                fail_at(X, g, "the n..n face listed %ld times", (long) same);
        }
        else if (same != 1)
            fail_at(X, g, "the face %s listed %ld times", a->sign,
                    (long) same);
    }
    if (R->strong && R->nmotions != 0)
        fail_at(X, g, "strong with %ld motions", (long) R->nmotions);
    if (R->weak && R->nmotions == 0 && !R->strong)
        fail_at(X, g, "weak, no motion, yet not strong");

    /* The paper semantics' witness.  */
    if (!R->strong_paper)
    {
        if (R->paper.sign == NULL || string_all_n(P, R->paper.sign))
            fail_at(X, g, "not strong (paper) without a string other "
                    "than n..n");
        bad = solution_error(P, R->paper.sign, R->paper.nudot, R->paper.c,
                             g, 0);
        if (bad != NULL)
            fail_at(X, g, "paper witness %s: %s", R->paper.sign, bad);
        if (ref_wrench_in_cone(P, R->paper.sign, g) != 1)
            fail_at(X, g, "paper witness %s: ref-lp says g is not in its "
                    "cone", R->paper.sign);
    }

    /* Certificates: every moving face is listed, with a solution or
       without.  */
    if (certificates && (X->faces >= 0 || t == 0))
    {
        /* With no touching fixel the one face is R^3 minus the origin,
           which moves unless g = 0 (then nothing is listed: there is no
           linear system to certify).  */
        slong expect = (t == 0) ? !wctest_vec3_is_zero(g) : X->faces;

        if (R->nmotions + R->nnofaces != expect)
            fail_at(X, g, "%ld faces with a motion + %ld without != %ld "
                    "moving faces", (long) R->nmotions, (long) R->nnofaces,
                    (long) expect);
        for (i = 0; i < R->nnofaces; i++)
        {
            const wc_noface_struct * f = R->nofaces + i;

            for (j = 0; j < R->nmotions; j++)
                if (strcmp(R->motions[j].sign, f->sign) == 0
                    && !string_all_n(P, f->sign))
                    fail_at(X, g, "face %s listed with and without a "
                            "solution", f->sign);
            if ((f->rotation != 0) != string_all_n(P, f->sign))
                fail_at(X, g, "face %s: rotation flag %d", f->sign,
                        f->rotation);
        }
    }
    if (!certificates && R->nnofaces != 0)
        fail_at(X, g, "nofaces filled without certificates");

    /* The oracle.  */
    if (oracle)
    {
        ref_weak = ref_weakly_stable(P, g);
        ref_motion = ref_has_motion(P, g);
        ref_union = ref_in_paper_union(P, g);
        if (ref_weak < 0 || ref_motion < 0 || ref_union < 0)
            fail_at(X, g, "the oracle failed (%d %d %d)", ref_weak,
                    ref_motion, ref_union);
        if (R->weak != ref_weak)
            fail_at(X, g, "weak: library %d, oracle %d", R->weak, ref_weak);
        if ((R->nmotions > 0) != ref_motion)
            fail_at(X, g, "a moving solution: library %d (%ld faces), "
                    "oracle %d", R->nmotions > 0, (long) R->nmotions,
                    ref_motion);
        if (R->strong != (ref_weak && !ref_motion))
            fail_at(X, g, "strong: library %d, oracle %d", R->strong,
                    ref_weak && !ref_motion);
        if (R->strong_paper != !ref_union)
            fail_at(X, g, "strong (paper): library %d, oracle %d",
                    R->strong_paper, !ref_union);
    }
    if (modes)
    {
        slong count;
        char * list = ref_modes_holding(&count, P, g);

        if (list == NULL)
            fail_at(X, g, "ref_modes_holding failed");
        if (max_modes <= 0 || count < max_modes)
        {
            /* The whole list, in the same order.  */
            if (!R->modes_complete)
                fail_at(X, g, "the mode list is incomplete (cap %ld, %ld "
                        "modes)", (long) max_modes, (long) count);
            if (count != R->nmodes)
                fail_at(X, g, "%ld modes hold g, the oracle finds %ld",
                        (long) R->nmodes, (long) count);
            for (i = 0; i < count; i++)
                if (strcmp(R->modes[i], list + i * (n + 1)) != 0)
                    fail_at(X, g, "mode %ld: library %s, oracle %s",
                            (long) i, R->modes[i], list + i * (n + 1));
        }
        else
        {
            /* Capped: max_modes of the oracle's strings, sorted; complete
               only when that is all of them.  */
            if (R->nmodes != max_modes)
                fail_at(X, g, "%ld modes listed with the cap %ld (the "
                        "oracle finds %ld)", (long) R->nmodes,
                        (long) max_modes, (long) count);
            if (R->modes_complete && count != max_modes)
                fail_at(X, g, "modes_complete with %ld of %ld modes",
                        (long) R->nmodes, (long) count);
            for (i = 0; i < R->nmodes; i++)
            {
                for (j = 0; j < count; j++)
                    if (strcmp(R->modes[i], list + j * (n + 1)) == 0)
                        break;
                if (j == count)
                    fail_at(X, g, "mode %s is listed; the oracle says its "
                            "cone does not hold g", R->modes[i]);
                if (i > 0 && strcmp(R->modes[i - 1], R->modes[i]) >= 0)
                    fail_at(X, g, "the capped mode list is not sorted");
            }
        }
        /* eq. 19's union, read off the list: u = s or a on near fixels.  */
        if (ref_union >= 0)
        {
            int any = 0;

            for (i = 0; i < count; i++)
                any |= !string_all_n(P, list + i * (n + 1));
            if (any != ref_union)
                fail_at(X, g, "oracle: the union %d, the mode list %d",
                        ref_union, any);
        }
        free(list);
    }

    /* The sets.  */
    if (S != NULL)
    {
        slong k;

        if (wc_cone_contains(S->weak, g) != R->weak)
            fail_at(X, g, "S->weak holds g: %d, classify: weak %d",
                    wc_cone_contains(S->weak, g), R->weak);
        if (wc_set_contains(S->strong, g) != R->strong)
            fail_at(X, g, "S->strong holds g: %d, classify: strong %d",
                    wc_set_contains(S->strong, g), R->strong);
        if (wc_set_contains(S->strong_paper, g) != R->strong_paper)
            fail_at(X, g, "S->strong_paper holds g: %d, classify: %d",
                    wc_set_contains(S->strong_paper, g), R->strong_paper);
        if ((k = pieces_holding(S->strong, g)) > 1)
            fail_at(X, g, "%ld pieces of the strong set hold g", (long) k);
        if ((k = pieces_holding(S->strong_paper, g)) > 1)
            fail_at(X, g, "%ld pieces of the strong (paper) set hold g",
                    (long) k);
        if (S->paper_in_weak && R->strong_paper && !R->weak)
            fail_at(X, g, "paper_in_weak, yet strong (paper) and not weak");
        if (!S->differ && R->strong != R->strong_paper)
            fail_at(X, g, "the sets do not differ, yet strong %d and "
                    "strong (paper) %d", R->strong, R->strong_paper);

        /* Each moving face's cone holds g iff classify found a solution
           on that face (the rotation faces by count).  */
        for (i = 0; i < S->nmoving; i++)
        {
            slong cones = 0, found = 0;

            for (j = 0; j < i; j++)
                if (strcmp(S->moving_sign[j], S->moving_sign[i]) == 0)
                    break;
            if (j < i)
                continue;       /* that sign was done */
            for (j = i; j < S->nmoving; j++)
                if (strcmp(S->moving_sign[j], S->moving_sign[i]) == 0)
                    cones += wc_cone_contains(S->moving + j, g);
            for (j = 0; j < R->nmotions; j++)
                found += (strcmp(R->motions[j].sign, S->moving_sign[i])
                          == 0);
            if (cones != found)
                fail_at(X, g, "face %s: %ld of its cones hold g, classify "
                        "found %ld solutions", S->moving_sign[i],
                        (long) cones, (long) found);
        }
        for (j = 0; j < R->nmotions; j++)
        {
            for (i = 0; i < S->nmoving; i++)
                if (strcmp(R->motions[j].sign, S->moving_sign[i]) == 0)
                    break;
            if (i == S->nmoving)
                fail_at(X, g, "classify moves on face %s, which "
                        "S->moving lacks", R->motions[j].sign);
        }
        /* Eq. 19's union: the moving cones other than the rotation
           faces (moving_rot 0), and S->paper_union.  */
        k = 0;
        for (i = 0; i < S->nmoving; i++)
            if (S->moving_rot[i] == 0)
                k |= wc_cone_contains(S->moving + i, g);
        for (i = 0; i < S->nunion; i++)
            k |= wc_cone_contains(S->paper_union + i, g);
        if (k != !R->strong_paper)
            fail_at(X, g, "eq. 19's cones hold g: %ld, classify strong "
                    "(paper) %d", (long) k, R->strong_paper);
    }

    if (certificates && wctest_chance(1, 4))
    {
        FILE * out = tmpfile();

        if (out == NULL)
            wctest_fail("tmpfile failed");
        if (wc_classify_certificate_fprint(out, P, R) != WC_OK)
            fail_at(X, g, "wc_classify_certificate_fprint failed");
        fclose(out);
    }

    _fmpq_vec_clear(zero, 3);
    wc_classify_clear(R);
}

/* ---- wrenches where the sets change ---------------------------------- */

/* A list of distinct primitive integer wrenches.  */
typedef struct
{
    slong len, cap;
    fmpz * v;               /* 3 per point */
}
points_t;

static void
points_init(points_t * L)
{
    L->len = 0;
    L->cap = 16;
    L->v = _fmpz_vec_init(3 * L->cap);
}

static void
points_clear(points_t * L)
{
    _fmpz_vec_clear(L->v, 3 * L->cap);
}

/* Add the ray of p (3 entries) unless it is there.  */
static void
points_add(points_t * L, const fmpz * p)
{
    fmpz q[3];
    fmpz_t gcd;
    slong i, j;

    fmpz_init(gcd);
    for (j = 0; j < 3; j++)
        fmpz_init_set(q + j, p + j);
    fmpz_gcd(gcd, q + 0, q + 1);
    fmpz_gcd(gcd, gcd, q + 2);
    if (!fmpz_is_zero(gcd))
        for (j = 0; j < 3; j++)
            fmpz_divexact(q + j, q + j, gcd);
    for (i = 0; i < L->len; i++)
        if (_fmpz_vec_equal(L->v + 3 * i, q, 3))
            break;
    if (i == L->len)
    {
        if (L->len == L->cap)
        {
            fmpz * w = _fmpz_vec_init(6 * L->cap);

            _fmpz_vec_set(w, L->v, 3 * L->len);
            _fmpz_vec_clear(L->v, 3 * L->cap);
            L->v = w;
            L->cap *= 2;
        }
        _fmpz_vec_set(L->v + 3 * L->len, q, 3);
        L->len++;
    }
    for (j = 0; j < 3; j++)
        fmpz_clear(q + j);
    fmpz_clear(gcd);
}

/* The rays, both directions of every line, and the relative-interior
   point (sum of the rays) of every face of cl C.  */
static void
points_add_cone(points_t * L, const wc_cone_struct * C)
{
    fmpz p[3];
    slong i, j, k;

    if (C->empty)
        return;
    for (j = 0; j < 3; j++)
        fmpz_init(p + j);
    for (i = 0; i < C->rays->r; i++)
        points_add(L, C->rays->rows[i]);
    for (i = 0; i < C->lines->r; i++)
    {
        points_add(L, C->lines->rows[i]);
        _fmpz_vec_neg(p, C->lines->rows[i], 3);
        points_add(L, p);
    }
    for (i = 0; i < C->nfaces; i++)
    {
        _fmpz_vec_zero(p, 3);
        for (k = 0; k < C->faces[i].nrays; k++)
            _fmpz_vec_add(p, p, C->rays->rows[C->faces[i].rays[k]], 3);
        points_add(L, p);
    }
    for (j = 0; j < 3; j++)
        fmpz_clear(p + j);
}

static void
points_add_stability(points_t * L, const wc_stability_struct * S)
{
    fmpz z[3] = { 0, 0, 0 };    /* small fmpz: plain words */
    slong i;

    points_add(L, z);
    points_add_cone(L, S->weak);
    for (i = 0; i < S->strong->npieces; i++)
        points_add_cone(L, S->strong->pieces + i);
    for (i = 0; i < S->strong_paper->npieces; i++)
        points_add_cone(L, S->strong_paper->pieces + i);
    for (i = 0; i < S->nmoving; i++)
        points_add_cone(L, S->moving + i);
    for (i = 0; i < S->nunion; i++)
        points_add_cone(L, S->paper_union + i);
}

/* g := point i of L, or (K p + r) / K for a random r in {-1, 0, 1}^3 and
   K in 8..128 when perturb: a nearby wrench off the boundary.  */
static void
points_get(fmpq * g, const points_t * L, slong i, int perturb)
{
    slong j, K = wctest_randint(8, 128);

    for (j = 0; j < 3; j++)
    {
        fmpq_set_fmpz(g + j, L->v + 3 * i + j);
        if (perturb)
        {
            fmpq_t r;

            fmpq_init(r);
            fmpq_set_si(r, wctest_randint(-1, 1), (ulong) K);
            fmpq_add(g + j, g + j, r);
            fmpq_clear(r);
        }
    }
}

/* g := M nudot - J c for an acceleration and forces built to sit on the
   strata where verdicts change: nudot zero, random, a rotation about a
   touching fixel's contact point (a_i = 0 there), in the null space of
   two fixels' normal rows (a_in = a_jn = 0) or of one; each touching
   fixel's force zero, on an edge of its static or kinetic friction cone,
   along its normal, or random inside.  */
static void
constructed_wrench(fmpq * g, const wc_problem_struct * P)
{
    slong n = P->n, i, j, k, kind = wctest_randint(0, 4);
    slong fi = wctest_randint(0, n - 1), fj = wctest_randint(0, n - 1);
    fmpq nudot[3], a[3], b[3];
    fmpq_t s, tmp;

    for (j = 0; j < 3; j++)
    {
        fmpq_init(nudot + j);
        fmpq_init(a + j);
        fmpq_init(b + j);
    }
    fmpq_init(s);
    fmpq_init(tmp);

    switch (kind)
    {
        case 0:
            break;
        case 1:
            for (j = 0; j < 3; j++)
                wctest_rand_fmpq(nudot + j, 4, 3);
            break;
        case 2:                 /* (w r_y, -w r_x, w), r = p_i - o */
            wctest_rand_fmpq(s, 3, 2);
            fmpq_sub(tmp, P->fixels[fi].point + 1, P->com + 1);
            fmpq_mul(nudot + 0, s, tmp);
            fmpq_sub(tmp, P->fixels[fi].point + 0, P->com + 0);
            fmpq_mul(nudot + 1, s, tmp);
            fmpq_neg(nudot + 1, nudot + 1);
            fmpq_set(nudot + 2, s);
            break;
        case 3:                 /* J_in x J_jn */
            jcol(a, P, fi, 0);
            jcol(b, P, fj, 0);
            fmpq_mul(nudot + 0, a + 1, b + 2);
            fmpq_submul(nudot + 0, a + 2, b + 1);
            fmpq_mul(nudot + 1, a + 2, b + 0);
            fmpq_submul(nudot + 1, a + 0, b + 2);
            fmpq_mul(nudot + 2, a + 0, b + 1);
            fmpq_submul(nudot + 2, a + 1, b + 0);
            if (wctest_chance(1, 2))
                for (j = 0; j < 3; j++)
                    fmpq_neg(nudot + j, nudot + j);
            break;
        default:                /* v - (J_in . v / |J_in|^2) J_in */
            for (j = 0; j < 3; j++)
                wctest_rand_fmpq(nudot + j, 4, 3);
            jcol(a, P, fi, 0);
            wctest_dot3(s, a, nudot);
            wctest_dot3(tmp, a, a);
            fmpq_div(s, s, tmp);
            for (j = 0; j < 3; j++)
                fmpq_submul(nudot + j, s, a + j);
            break;
    }

    fmpq_mul(g + 0, P->mass, nudot + 0);
    fmpq_mul(g + 1, P->mass, nudot + 1);
    fmpq_mul(g + 2, P->inertia, nudot + 2);
    for (i = 0; i < n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;
        slong how = wctest_randint(0, 5);

        if (f->state != WC_TOUCHING || how == 0)
            continue;
        wctest_rand_fmpq_pos(s, 3, 2);                  /* c_in */
        switch (how)
        {
            case 1: fmpq_mul(tmp, s, f->mu_s); break;
            case 2: fmpq_mul(tmp, s, f->mu_s); fmpq_neg(tmp, tmp); break;
            case 3: fmpq_mul(tmp, s, f->mu_k);
                    if (wctest_chance(1, 2))
                        fmpq_neg(tmp, tmp);
                    break;
            case 4: fmpq_zero(tmp); break;
            default:                                    /* |c_it| < mu_s c_in */
                fmpq_set_si(tmp, wctest_randint(-3, 3), 4);
                fmpq_mul(tmp, tmp, s);
                fmpq_mul(tmp, tmp, f->mu_s);
                break;
        }
        /* g -= J_in c_in + J_it c_it */
        jcol(a, P, i, 0);
        jcol(b, P, i, 1);
        for (k = 0; k < 3; k++)
        {
            fmpq_submul(g + k, a + k, s);
            fmpq_submul(g + k, b + k, tmp);
        }
    }

    for (j = 0; j < 3; j++)
    {
        fmpq_clear(nudot + j);
        fmpq_clear(a + j);
        fmpq_clear(b + j);
    }
    fmpq_clear(s);
    fmpq_clear(tmp);
}

/* ---- the sets themselves --------------------------------------------- */

static void
check_cone_faces(const ctx_t * X, const wc_cone_struct * C, const char * name)
{
    fmpz p[3];
    fmpq g[3];
    slong i, j, k;

    for (j = 0; j < 3; j++)
    {
        fmpz_init(p + j);
        fmpq_init(g + j);
    }
    for (i = 0; i < C->nfaces; i++)
    {
        _fmpz_vec_zero(p, 3);
        for (k = 0; k < C->faces[i].nrays; k++)
            _fmpz_vec_add(p, p, C->rays->rows[C->faces[i].rays[k]], 3);
        for (j = 0; j < 3; j++)
            fmpq_set_fmpz(g + j, p + j);
        if (wc_cone_contains(C, g) != (C->faces[i].included != 0))
            fail_at(X, g, "%s: face %ld's point: contains %d, included %d",
                    name, (long) i, wc_cone_contains(C, g),
                    C->faces[i].included);
    }
    for (j = 0; j < 3; j++)
    {
        fmpz_clear(p + j);
        fmpq_clear(g + j);
    }
}

static void
check_set_flags(const ctx_t * X, const wc_set_struct * T, const char * name)
{
    slong i;
    int interior = 0;
    char buf[64];

    if (T->empty != (T->npieces == 0))
        fail_at(X, NULL, "%s: empty = %d with %ld pieces", name, T->empty,
                (long) T->npieces);
    for (i = 0; i < T->npieces; i++)
    {
        if (T->pieces[i].empty)
            fail_at(X, NULL, "%s: piece %ld is empty", name, (long) i);
        if (T->pieces[i].d != 3)
            fail_at(X, NULL, "%s: piece %ld in R^%ld", name, (long) i,
                    (long) T->pieces[i].d);
        interior |= (T->pieces[i].dim == 3);
        snprintf(buf, sizeof buf, "%s piece %ld", name, (long) i);
        check_cone_faces(X, T->pieces + i, buf);
    }
    if (T->interior != interior)
        fail_at(X, NULL, "%s: interior = %d, pieces say %d", name,
                T->interior, interior);
}

static void
check_sets(const ctx_t * X)
{
    const wc_stability_struct * S = X->S;
    slong i;

    if (S->weak->empty)
        fail_at(X, NULL, "the weak cone is empty (it holds 0)");
    if (wc_cone_excluded_faces(S->weak) != 0)
        fail_at(X, NULL, "the weak cone is not closed");
    check_cone_faces(X, S->weak, "weak");
    check_set_flags(X, S->strong, "strong");
    check_set_flags(X, S->strong_paper, "strong (paper)");
    for (i = 0; i < S->nmoving; i++)
    {
        if (S->moving_sign == NULL || S->moving_sign[i] == NULL
            || (slong) strlen(S->moving_sign[i]) != X->P->n)
            fail_at(X, NULL, "moving cone %ld has no proper sign", (long) i);
        check_cone_faces(X, S->moving + i, S->moving_sign[i]);
    }
    for (i = 0; i < S->nunion; i++)
        check_cone_faces(X, S->paper_union + i, "paper union");
    if (S->differ)
    {
        wc_classify_t R;
        wc_error_t err;

        wc_classify_init(R);
        if (wc_classify(R, X->P, S->diff_g, 0, 0, err) != WC_OK)
            fail_at(X, S->diff_g, "wc_classify failed: %s", err->message);
        if (R->strong == R->strong_paper || R->strong != S->diff_in_exact)
            fail_at(X, S->diff_g, "diff_g: strong %d, strong (paper) %d, "
                    "diff_in_exact %d", R->strong, R->strong_paper,
                    S->diff_in_exact);
        wc_classify_clear(R);
    }
}

/* The moving faces of the arrangement: Table 1 strings of the touching
   fixels alone (near fixels constrain nothing) other than n..n that some
   twist satisfies, by ref-kin.c, plus the two rotations when the
   touching fixels share a point.  -1 when there is no touching fixel.  */
static slong
moving_faces(const wc_problem_struct * P)
{
    wc_problem_t T;
    slong t = touching_count(P), i, k, p, count = 0;
    char * x;

    if (t == 0)
        return -1;
    wc_problem_init(T);
    fmpq_set(T->mass, P->mass);
    fmpq_set(T->inertia, P->inertia);
    fmpq_set(T->com + 0, P->com + 0);
    fmpq_set(T->com + 1, P->com + 1);
    for (i = 0; i < P->n; i++)
    {
        wc_fixel_struct * f;

        if (P->fixels[i].state != WC_TOUCHING)
            continue;
        f = wc_problem_add_fixel(T);
        for (k = 0; k < 2; k++)
        {
            fmpq_set(f->point + k, P->fixels[i].point + k);
            fmpq_set(f->normal + k, P->fixels[i].normal + k);
        }
        fmpq_set(f->mu_s, P->fixels[i].mu_s);
        fmpq_set(f->mu_k, P->fixels[i].mu_k);
        f->state = WC_TOUCHING;
    }
    x = flint_malloc(t + 1);
    for (p = 0; p < (WORD(1) << (2 * t)); p++)
    {
        slong q = p;
        int alln = 1, r;

        for (i = t - 1; i >= 0; i--, q >>= 2)
        {
            x[i] = "slrn"[q & 3];
            alln &= (x[i] == 'n');
        }
        x[t] = '\0';
        if (alln)
            continue;
        r = ref_mode_feasible(T, x);
        if (r < 0)
            wctest_fail_problem(P, x, "ref_mode_feasible failed");
        count += r;
    }
    if (touching_share_point(P))
        count += 2;
    flint_free(x);
    wc_problem_clear(T);
    return count;
}

/* ---- the tests ------------------------------------------------------ */

/* The paper's unit disk with both fixels touching (Figure 5): fixel 1 at
   (0, -1) pushing up, fixel 2 at (1, 0) pushing left, friction mu.  */
static void
figure5(wc_problem_t P, slong mu_num, slong mu_den)
{
    wc_fixel_struct * f;

    fmpq_set_si(P->mu_s, mu_num, (ulong) mu_den);
    fmpq_set_si(P->mu_k, mu_num, (ulong) mu_den);
    f = wc_problem_add_fixel(P);
    fmpq_set_si(f->point + 1, -1, 1);
    fmpq_set_si(f->normal + 1, 1, 1);
    f = wc_problem_add_fixel(P);
    fmpq_set_si(f->point + 0, 1, 1);
    fmpq_set_si(f->normal + 0, -1, 1);
}

/* Compute the sets of P and check them, and classify on nrandom random
   and nrandom constructed wrenches, on boundary wrenches (all of them when
   nboundary < 0, else that many drawn at random) and on nperturb
   perturbations of those; the oracle on the random and constructed ones,
   on the first noracle boundary ones and the first noracle perturbed
   ones; the mode list on every modes-th wrench the oracle sees.  */
static void
check_problem(const wc_problem_struct * P, const char * what, slong nrandom,
              slong nboundary, slong nperturb, slong noracle, slong modes)
{
    wc_stability_t S;
    wc_error_t err;
    ctx_t X;
    points_t L;
    fmpq g[3];
    slong i, j, count = 0;

    X.P = P;
    X.S = NULL;
    X.faces = moving_faces(P);
    X.what = what;
    for (j = 0; j < 3; j++)
        fmpq_init(g + j);

    wc_stability_init(S);
    if (wc_stability(S, P, err) != WC_OK)
        fail_at(&X, NULL, "wc_stability failed: %s", err->message);
    X.S = S;
    check_sets(&X);

    for (i = 0; i < 2 * nrandom; i++)
    {
        if (i % 2)
            constructed_wrench(g, P);
        else
            wctest_random_wrench(g);
        check_wrench(&X, g, 1, count++ % modes == 0, wctest_chance(1, 2));
    }

    points_init(&L);
    points_add_stability(&L, S);

    /* Without classify, at every boundary wrench: pieces disjoint, the
       strong set inside the weak cone.  */
    for (i = 0; i < L.len; i++)
    {
        slong k;

        points_get(g, &L, i, 0);
        if ((k = pieces_holding(S->strong, g)) > 1)
            fail_at(&X, g, "%ld pieces of the strong set hold g", (long) k);
        if ((k = pieces_holding(S->strong_paper, g)) > 1)
            fail_at(&X, g, "%ld pieces of the strong (paper) set hold g",
                    (long) k);
        if (wc_set_contains(S->strong, g) && !wc_cone_contains(S->weak, g))
            fail_at(&X, g, "in the strong set, not in the weak cone");
    }

    if (nboundary < 0 || nboundary > L.len)
        nboundary = L.len;
    for (i = 0; i < nboundary; i++)
    {
        /* Draw without replacement: swap a random later point in.  */
        slong k = wctest_randint(i, L.len - 1);

        _fmpz_vec_swap(L.v + 3 * i, L.v + 3 * k, 3);
        points_get(g, &L, i, 0);
        check_wrench(&X, g, i < noracle, i < noracle && count++ % modes == 0,
                     wctest_chance(1, 2));
    }
    for (i = 0; i < nperturb && L.len > 0; i++)
    {
        points_get(g, &L, wctest_randint(0, L.len - 1), 1);
        check_wrench(&X, g, i < noracle, 0, 0);
    }
    points_clear(&L);

    wc_stability_clear(S);
    for (j = 0; j < 3; j++)
        fmpq_clear(g + j);
}

/* g := (0, -1, 0) on Figure 5's disk (X): weakly and strongly stable,
   not strongly stable in the paper's sense (eq. 19), and so for every
   route check_wrench tries.  */
static void
figure5_down(const ctx_t * X, fmpq * g)
{
    wc_classify_t R;
    wc_error_t err;

    wctest_vec3_si(g, 0, -1, 0);
    wc_error_init(err);
    wc_classify_init(R);
    if (wc_classify(R, X->P, g, 1, 0, err) != WC_OK)
        fail_at(X, g, "wc_classify failed: %s", err->message);
    if (!R->weak || !R->strong || R->strong_paper)
        fail_at(X, g, "weak %d strong %d strong (paper) %d, not 1 1 0",
                R->weak, R->strong, R->strong_paper);
    wc_classify_clear(R);
    wc_error_clear(err);
    check_wrench(X, g, 1, 1, 1);
}

static void
test_figure5(void)
{
    wc_problem_t P;
    wc_stability_t S;
    wc_error_t err;
    ctx_t X;
    fmpq g[3];
    slong j;

    for (j = 0; j < 3; j++)
        fmpq_init(g + j);

    /* Friction 2: each fixel lies strictly inside the other's friction
       cone, so the friction cone edges span R^3 positively (force
       closure) and the weak set is everything.  With friction exactly 1
       the line joining the contacts is an edge of both friction cones;
       the weak cone is then a closed wedge around the line through
       (1, 1, 1), missing e.g. (0, 0, 1) -- not all of R^3.  */
    wc_problem_init(P);
    figure5(P, 2, 1);
    X.P = P;
    X.S = NULL;
    X.faces = moving_faces(P);
    X.what = "figure 5, friction 2";
    if (X.faces != 10 - 1)
        fail_at(&X, NULL, "%ld moving faces, not the 9 of Section 7",
                (long) X.faces);
    wc_stability_init(S);
    if (wc_stability(S, P, err) != WC_OK)
        fail_at(&X, NULL, "wc_stability failed: %s", err->message);
    if (S->weak->empty || S->weak->dim != 3 || S->weak->lineality_dim != 3)
        fail_at(&X, NULL, "the weak cone is not R^3 (dim %ld, lineality "
                "%ld)", (long) S->weak->dim, (long) S->weak->lineality_dim);
    wc_stability_clear(S);

    figure5_down(&X, g);
    check_problem(P, X.what, 30, -1, 60, 40, 3);
    wc_problem_clear(P);

    /* Friction 1, as drawn: the same verdicts for (0, -1, 0); the weak
       cone is the wedge described above.  */
    wc_problem_init(P);
    figure5(P, 1, 1);
    X.P = P;
    X.faces = moving_faces(P);
    X.what = "figure 5, friction 1";
    figure5_down(&X, g);
    wctest_vec3_si(g, 0, 0, 1);
    if (ref_weakly_stable(P, g) != 0)
        fail_at(&X, g, "the oracle calls a pure torque weakly stable");
    check_problem(P, X.what, 30, -1, 60, 40, 3);
    wc_problem_clear(P);

    /* Section 4's friction 1/5, both touching: the friction cones miss
       each other; many wrenches are not weakly stable.  */
    wc_problem_init(P);
    figure5(P, 1, 5);
    check_problem(P, "figure 5, friction 1/5", 20, -1, 30, 30, 3);
    wc_problem_clear(P);

    for (j = 0; j < 3; j++)
        fmpq_clear(g + j);
}

int
main(void)
{
    slong i, iters;
    char what[64];

    wctest_init("t-stability");
    wc_init();

    test_figure5();

    iters = wctest_iters(12);     /* 36 in CI's widened run */
    for (i = 0; i < iters; i++)
    {
        wc_problem_t P;

        if (!wctest_iter(i))
            continue;
        wc_problem_init(P);
        wctest_random_problem(P, 1, 4);
        snprintf(what, sizeof what, "random problem, n = %ld", (long) P->n);
        /* Every boundary wrench on every sixth problem, a sample on the
           others.  */
        if (i % 6 == 0)
            check_problem(P, what, 6, -1, 8, 12, 4);
        else
            check_problem(P, what, 6, 12, 4, 6, 4);
        wc_problem_clear(P);
    }
    return 0;
}
