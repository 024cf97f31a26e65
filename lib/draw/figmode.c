/* figmode.c -- a mode's wrench cone as lines of force, and the feasible
   modes as rotation centres.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A wrench (fx, fy, tau) about the centre of mass o with f != 0 is a
   force f acting along the line through o + tau / |f|^2 (fy, -fx) (the
   point of the line nearest to o: its moment about it vanishes); with
   f = 0 it is a pure torque, drawn as an arc about o.  A twist
   (vx, vy, w) of o with w != 0 turns about o + (-vy, vx) / w.  */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpq_vec.h>

#include "analysis/kinematics.h"
#include "analysis/wrench.h"
#include "model/mode.h"
#include "draw/figure.h"

/* p := o + tau / |f|^2 (fy, -fx), exactly; g is (fx, fy, tau) with
   f != 0.  */
static void
force_point(double * p, const wc_problem_t P, const fmpz * g, int sign)
{
    fmpz_t n2;
    fmpq_t t, c;

    fmpz_init(n2);
    fmpq_init(t);
    fmpq_init(c);
    fmpz_fmma(n2, g + 0, g + 0, g + 1, g + 1);
    fmpq_set_fmpz_frac(t, g + 2, n2);   /* tau / |f|^2: sign-free in g */
    (void) sign;
    fmpq_mul_fmpz(c, t, g + 1);
    fmpq_add(c, c, P->com + 0);
    p[0] = fmpq_get_d(c);
    fmpq_mul_fmpz(c, t, g + 0);
    fmpq_sub(c, P->com + 1, c);
    p[1] = fmpq_get_d(c);
    fmpq_clear(c);
    fmpq_clear(t);
    fmpz_clear(n2);
}

/* Generator number k, g (sign +-1 times the row), in the cone or not.  */
static int
generator(_wc_scene_t S, const wc_problem_t P, const fmpz * row, int sign,
          int in, int k)
{
    fmpz g[3];
    double p[2], fx, fy, fl, L = 0.3 * S->scale;
    char label[32];
    int status, j;

    for (j = 0; j < 3; j++)
    {
        fmpz_init(g + j);
        fmpz_mul_si(g + j, row + j, sign);
    }
    snprintf(label, sizeof(label), "g%d", k + 1);
    if (fmpz_is_zero(g + 0) && fmpz_is_zero(g + 1))
    {
        double ox = fmpq_get_d(P->com + 0), oy = fmpq_get_d(P->com + 1);
        double r = (0.12 + 0.03 * k) * S->scale;
        _wc_prim_struct * a;

        status = _wc_scene_arc(S, in ? _WC_TAG_TORQUE_IN : _WC_TAG_TORQUE_OUT,
                               0, ox, oy, r, _WC_PI / 4, 7 * _WC_PI / 4);
        if (status == WC_OK)
        {
            a = S->prims + S->count - 1;
            a->closed = fmpz_sgn(g + 2) < 0;    /* clockwise: head at a0 */
            status = _wc_scene_text(S, ox + r * cos(_WC_PI / 4),
                                    oy + r * sin(_WC_PI / 4), 4, -4, -1, label);
        }
    }
    else
    {
        force_point(p, P, g, sign);
        fx = fmpz_get_d(g + 0);
        fy = fmpz_get_d(g + 1);
        fl = sqrt(fx * fx + fy * fy);
        fx /= fl;
        fy /= fl;
        status = _wc_scene_arrow(S, in ? _WC_TAG_FORCE_IN : _WC_TAG_FORCE_OUT,
                                 p[0] - L * fx, p[1] - L * fy, p[0] + L * fx,
                                 p[1] + L * fy);
        if (status == WC_OK)
            status = _wc_scene_text(S, p[0] + L * fx, p[1] + L * fy,
                                    10 * fx, -10 * fy + 4, 0, label);
    }
    for (j = 0; j < 3; j++)
        fmpz_clear(g + j);
    return status;
}

/* Whether the face spanned by the lineality space and ray i (i < 0: the
   lineality space alone) belongs to the cone.  */
static int
ray_included(const wc_cone_t W, slong i)
{
    slong f;

    for (f = 0; f < W->nfaces; f++)
        if (W->faces[f].nrays == (i >= 0)
            && (i < 0 || W->faces[f].rays[0] == i))
            return W->faces[f].included;
    return 0;
}

static int
cone_figure(_wc_scene_t S, const wc_problem_t P, const wc_cone_t W,
            int * nout)
{
    slong i;
    int k = 0, status = WC_OK, in;

    *nout = 0;
    for (i = 0; i < W->rays->r && status == WC_OK; i++, k++)
    {
        in = ray_included(W, i);
        *nout += !in;
        status = generator(S, P, W->rays->rows[i], 1, in, k);
    }
    in = ray_included(W, -1);
    for (i = 0; i < W->lines->r && status == WC_OK; i++, k += 2)
    {
        *nout += 2 * !in;
        status = generator(S, P, W->lines->rows[i], 1, in, k);
        if (status == WC_OK)
            status = generator(S, P, W->lines->rows[i], -1, in, k + 1);
    }
    return status;
}

int
_wc_draw_mode(_wc_scene_t S, const wc_problem_t P, const char * mode,
              wc_error_t err)
{
    wc_cone_t W;
    int status, nout = 0;
    char * mu = NULL;

    if ((status = wc_mode_check(P, mode, WC_TABLE_CONE, err)) != WC_OK)
        return status;
    wc_cone_init(W, 3);
    status = wc_wrench_cone(W, NULL, P, mode, WC_METHOD_DIRECT, err);
    if (status == WC_OK)
        status = _wc_draw_part(S, P);
    if (status == WC_OK && !W->empty)
        status = cone_figure(S, P, W, &nout);
    if (status == WC_OK)
        status = _wc_scene_legend(S, _WC_TAG_FORCE_IN, 0, "generator in "
                                  "W (line of force)");
    if (status == WC_OK && nout > 0)
        status = _wc_scene_legend(S, _WC_TAG_FORCE_OUT, 0, "generator of "
                                  "the closure only (excluded)");
    if (status == WC_OK)
    {
        char title[256];

        snprintf(title, sizeof(title), "W(%.200s): wrench cone of mode %s",
                 mode, strlen(mode) > 200 ? "..." : mode);
        status = _wc_scene_title(S, title);
    }
    if (status == WC_OK && (mu = _wc_draw_friction(P)) == NULL)
        status = WC_EINTERNAL;
    if (status == WC_OK)
        status = _wc_scene_caption(S, "%s, contact mode %s, friction %s. %s",
                                   _wc_draw_name(P), mode, mu, W->empty
                                   ? "The cone is empty: no wrench is "
                                   "consistent with this mode."
                                   : W->rays->r + W->lines->r == 0
                                   ? "Only the zero wrench is consistent "
                                   "with this mode." : "Each generator of the "
                                   "cone is drawn as a force along its line "
                                   "of action, a pure torque as an arc about "
                                   "o; dashed: excluded by a strict "
                                   "inequality (only its limit is in W).");
    free(mu);
    wc_cone_clear(W);
    return status;
}

/* The centre of a twist with w != 0: o + (-vy, vx) / w, exactly.  */
static void
twist_centre(fmpq * c, const wc_problem_t P, const fmpz * nu)
{
    fmpq_t t;

    fmpq_init(t);
    fmpq_set_fmpz_frac(t, nu + 1, nu + 2);
    fmpq_sub(c + 0, P->com + 0, t);
    fmpq_set_fmpz_frac(t, nu + 0, nu + 2);
    fmpq_add(c + 1, P->com + 1, t);
    fmpq_clear(t);
}

/* The modes' marks: a centre per distinct rotation centre (exact), its
   label naming every mode turning there; translations as arrows from o;
   the modes at rest listed in rest.  */
typedef struct
{
    slong n;            /* centres so far */
    fmpq * c;           /* 2 per centre */
    slong * text;       /* the index of each centre's label in S */
    int ntrans;
    char rest[256];
}
marks;

static int
translation(_wc_scene_t S, const wc_problem_t P, const fmpz * nu,
            const char * mode, marks * m)
{
    double ox = fmpq_get_d(P->com + 0), oy = fmpq_get_d(P->com + 1);
    double vx = fmpz_get_d(nu + 0), vy = fmpz_get_d(nu + 1);
    double vl = sqrt(vx * vx + vy * vy);
    double L = (0.25 + 0.04 * m->ntrans) * S->scale;
    int status;

    if (fmpz_is_zero(nu + 0) && fmpz_is_zero(nu + 1))
    {
        size_t used = strlen(m->rest);

        snprintf(m->rest + used, sizeof(m->rest) - used, "%s%s",
                 used ? ", " : "", mode);
        return WC_OK;
    }
    m->ntrans++;
    status = _wc_scene_arrow(S, _WC_TAG_TRANSLATION, ox, oy,
                             ox + L * vx / vl, oy + L * vy / vl);
    if (status == WC_OK)
        status = _wc_scene_text(S, ox + L * vx / vl, oy + L * vy / vl,
                                12 * vx / vl, -12 * vy / vl + 4, 0, mode);
    return status;
}

/* Append ", label" to the text of primitive k.  */
static int
append_label(_wc_scene_t S, slong k, const char * label)
{
    size_t len = strlen(S->prims[k].text);
    char * t = realloc(S->prims[k].text, len + strlen(label) + 3);

    if (t == NULL)
        return WC_EINTERNAL;
    sprintf(t + len, ", %s", label);
    S->prims[k].text = t;
    return WC_OK;
}

static int
mode_mark(_wc_scene_t S, const wc_problem_t P, const fmpz * nu,
          const char * mode, marks * m)
{
    char label[128];
    fmpq * c;
    slong j;
    int status;

    if (fmpz_is_zero(nu + 2))
        return translation(S, P, nu, mode, m);
    snprintf(label, sizeof(label), "%.100s %s", mode,
             fmpz_sgn(nu + 2) > 0 ? "(ccw)" : "(cw)");
    c = m->c + 2 * m->n;
    twist_centre(c, P, nu);
    for (j = 0; j < m->n; j++)
        if (fmpq_equal(m->c + 2 * j, c) && fmpq_equal(m->c + 2 * j + 1, c + 1))
            return append_label(S, m->text[j], label);
    status = _wc_scene_dot(S, _WC_TAG_CENTRE, 0, fmpq_get_d(c + 0),
                           fmpq_get_d(c + 1));
    if (status == WC_OK)
        status = _wc_scene_text(S, fmpq_get_d(c + 0), fmpq_get_d(c + 1), 9,
                                -8, -1, label);
    if (status == WC_OK)
        S->prims[S->count - 1].closed = 1;      /* may move */
    m->text[m->n++] = S->count - 1;
    return status;
}

int
_wc_draw_modes(_wc_scene_t S, const wc_problem_t P, wc_error_t err)
{
    marks m;
    wc_modes_t M;
    slong i;
    int status;

    memset(&m, 0, sizeof(m));
    wc_modes_init(M);
    status = wc_modes_enumerate(M, P, err);
    if (status == WC_OK)
        status = _wc_draw_part(S, P);
    if (status == WC_OK
        && ((m.c = _fmpq_vec_init(2 * M->count + 2)) == NULL
            || (m.text = malloc(sizeof(slong) * (M->count + 1))) == NULL))
        status = WC_EINTERNAL;
    for (i = 0; i < M->count && status == WC_OK; i++)
        status = mode_mark(S, P, M->witness->rows[i], M->modes[i], &m);
    if (status == WC_OK)
        status = _wc_scene_legend(S, _WC_TAG_CENTRE, 0, "rotation centre "
                                  "of a mode (a witness twist)");
    if (status == WC_OK && m.ntrans > 0)
        status = _wc_scene_legend(S, _WC_TAG_TRANSLATION, 0,
                                  "translation of a mode");
    if (status == WC_OK)
        status = _wc_draw_titles(S, P, "Feasible contact modes", " (the "
                                 "modes do not depend on it): %ld "
                                 "kinematically feasible modes, each at the "
                                 "rotation centre of one of its twists (ccw: "
                                 "counter-clockwise), or as the direction of "
                                 "a translation.%s%s%s", (long) M->count,
                                 m.rest[0] ? " At rest (zero twist): " : "",
                                 m.rest, m.rest[0] ? "." : "");
    if (m.c != NULL)
        _fmpq_vec_clear(m.c, 2 * M->count + 2);
    free(m.text);
    wc_modes_clear(M);
    return status;
}
