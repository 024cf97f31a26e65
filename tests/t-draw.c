/* t-draw.c -- the figures of wrenchcone draw: their geometry against the
   exact results they are drawn from.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   On the data files and on seeded random problems with a disk or a
   polygon (degenerate layouts included): the ends of every drawn pushing
   region equal the doubles of the exact interval ends (within 1e-6 of
   the figure's scale), one dot per end, filled exactly for the closed
   ones (the stability sets, G_goal, the first set of a sweep); every
   drawn line of force passes through the point where its
   generator's moment vanishes and points along the force, one per
   generator (a pure torque: an arc about o); every rotation centre lies
   where its witness twist puts it, labelled with the mode; a wrench's
   graph has one edge per transition it admits; and the SVG is a whole
   document.  */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/kinematics.h"
#include "analysis/plan.h"
#include "analysis/stability.h"
#include "analysis/wrench.h"
#include "core/random.h"
#include "draw/figure.h"
#include "testutil.h"

static double
dist(double ax, double ay, double bx, double by)
{
    return hypot(ax - bx, ay - by);
}

/* The exact ends of R's intervals as doubles, with their closedness:
   xy[2k], xy[2k + 1], closed[k]; returns the number of ends.  */
static slong
exact_ends(double * xy, int * closed, const wc_problem_t P,
           const wc_push_t R)
{
    slong i, m = 0, k = P->shape_len / 2;
    int e, j;
    fmpq_t t;

    fmpq_init(t);
    for (i = 0; i < R->count; i++)
    {
        const wc_push_interval_struct * iv = R->iv + i;

        if (iv->full)
            continue;
        for (e = 0; e < 2; e++)
        {
            int single = R->kind == WC_SHAPE_POLYGON
                ? fmpq_equal(iv->from, iv->to)
                : fmpz_equal(iv->dfrom + 0, iv->dto + 0)
                  && fmpz_equal(iv->dfrom + 1, iv->dto + 1) && iv->from_closed;

            if (e == 1 && single)
                break;
            closed[m] = e ? iv->to_closed : iv->from_closed;
            if (R->kind == WC_SHAPE_POLYGON)
            {
                const fmpq * u = P->shape_data + 2 * iv->edge;
                const fmpq * v = P->shape_data + 2 * ((iv->edge + 1) % k);

                for (j = 0; j < 2; j++)
                {
                    fmpq_sub(t, v + j, u + j);
                    fmpq_mul(t, t, e ? iv->to : iv->from);
                    fmpq_add(t, t, u + j);
                    xy[2 * m + j] = fmpq_get_d(t);
                }
            }
            else
            {
                const fmpz * d = e ? iv->dto : iv->dfrom;
                double dx = fmpz_get_d(d + 0), dy = fmpz_get_d(d + 1);
                double r = fmpq_get_d(P->shape_data + 2) / hypot(dx, dy);

                xy[2 * m] = fmpq_get_d(P->shape_data + 0) + r * dx;
                xy[2 * m + 1] = fmpq_get_d(P->shape_data + 1) + r * dy;
            }
            m++;
        }
    }
    fmpq_clear(t);
    return m;
}

/* The ends drawn on layer 0 of S are those of R, dot for dot; returns
   the number of dots on layer 1 (for the next set's count).  */
static slong
check_layer(const wc_problem_t P, const _wc_scene_t S, const wc_push_t R,
            const char * what)
{
    double * xy = malloc(sizeof(double) * (4 * R->count + 2));
    int * closed = malloc(sizeof(int) * (2 * R->count + 1));
    int * used = calloc(2 * R->count + 1, sizeof(int));
    slong m, i, j, dots = 0, next = 0;

    m = exact_ends(xy, closed, P, R);
    for (i = 0; i < S->count; i++)
    {
        const _wc_prim_struct * p = S->prims + i;

        if (p->kind != _WC_PRIM_DOT
            || (p->tag != _WC_TAG_END_OPEN && p->tag != _WC_TAG_END_CLOSED))
            continue;
        if (p->layer != 0)
        {
            next += p->layer == 1;
            continue;
        }
        dots++;
        for (j = 0; j < m; j++)
            if (!used[j] && dist(p->x, p->y, xy[2 * j], xy[2 * j + 1])
                <= 1e-6 * S->scale
                && closed[j] == (p->tag == _WC_TAG_END_CLOSED))
                break;
        if (j == m)
            wctest_fail_problem(P, NULL, "%s: a region end at (%g, %g) is "
                                "no exact end", what, p->x, p->y);
        used[j] = 1;
    }
    if (dots != m)
        wctest_fail_problem(P, NULL, "%s: %ld ends drawn, %ld exact", what,
                            (long) dots, (long) m);
    free(xy);
    free(closed);
    free(used);
    return next;
}

/* The stability figure: layer 0 is the strongly stable set (exact
   semantics), layer 1 eq. 19's.  */
static void
check_regions(const wc_problem_t P, const char * what)
{
    _wc_scene_t S;
    wc_stability_t T;
    wc_error_t err;
    slong next;

    wc_error_init(err);
    wc_stability_init(T);
    _wc_scene_init(S);
    if (wc_stability(T, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "%s: stability fails", what);
    if (_wc_draw_stability(S, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "%s: the stability figure fails", what);
    if (!T->has_push)
        wctest_fail_problem(P, NULL, "%s: no pushing regions", what);
    next = check_layer(P, S, T->push_strong, what);
    {
        double * e = malloc(sizeof(double) * (4 * T->push_strong_paper->count + 2));
        int * c = malloc(sizeof(int) * (2 * T->push_strong_paper->count + 1));

        if (next != exact_ends(e, c, P, T->push_strong_paper))
            wctest_fail_problem(P, NULL, "%s: eq. 19's ends miscounted", what);
        free(e);
        free(c);
    }
    _wc_scene_clear(S);
    wc_stability_clear(T);
    wc_error_clear(err);
}

/* The plan figure's region is G_goal's; the sweep's first layer is the
   plan's at its first friction value.  */
static void
check_plan(const wc_problem_t P, const char * what)
{
    _wc_scene_t S;
    wc_plan_t R;
    wc_error_t err;
    fmpq mu[2];

    wc_error_init(err);
    wc_plan_init(R);
    _wc_scene_init(S);
    if (wc_plan(R, P, 0, err) != WC_OK || _wc_draw_plan(S, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "%s: the plan figure fails", what);
    if (R->has_push)
        check_layer(P, S, R->push_goal, what);
    _wc_scene_clear(S);
    wc_plan_clear(R);
    fmpq_init(mu + 0);
    fmpq_init(mu + 1);
    fmpq_set_si(mu + 0, 1, 10);
    fmpq_set_si(mu + 1, 1, 2);
    wc_plan_init(R);
    _wc_scene_init(S);
    if (wc_plan_with_friction(R, P, mu + 0, err) != WC_OK
        || _wc_draw_sweep(S, P, mu, 2, err) != WC_OK)
        wctest_fail_problem(P, NULL, "%s: the sweep figure fails", what);
    if (R->has_push)
        check_layer(P, S, R->push_goal, what);
    _wc_scene_clear(S);
    wc_plan_clear(R);
    fmpq_clear(mu + 0);
    fmpq_clear(mu + 1);
    wc_error_clear(err);
}

/* The graph of a wrench: one admitted edge (or loop) per transition.  */
static void
check_graph(const wc_problem_t P, const fmpq * g)
{
    _wc_scene_t S;
    wc_plan_wrench_t W;
    wc_error_t err;
    slong i, edges = 0, nodes = 0;

    wc_error_init(err);
    wc_plan_wrench_init(W);
    _wc_scene_init(S);
    if (wc_plan_wrench(W, P, g, 1, err) != WC_OK
        || _wc_draw_graph(S, P, g, err) != WC_OK)
        wctest_fail_problem(P, NULL, "the graph figure fails");
    for (i = 0; i < S->count; i++)
    {
        edges += S->prims[i].tag == _WC_TAG_EDGE_ADMITTED;
        nodes += S->prims[i].tag == _WC_TAG_NODE
                 || S->prims[i].tag == _WC_TAG_GOAL;
    }
    if (edges != W->nedges || nodes != (1 << P->n))
        wctest_fail_problem(P, NULL, "the graph has %ld edges and %ld "
                            "states, not %ld and %d", (long) edges,
                            (long) nodes, (long) W->nedges, 1 << (int) P->n);
    _wc_scene_clear(S);
    wc_plan_wrench_clear(W);
    wc_error_clear(err);
}

/* Does some generator g of W (rays, +-lines) have the arrow p as its line
   of force, or (f = 0) the arc p as its torque?  */
static int
matches(const _wc_prim_struct * p, const wc_problem_t P, const fmpz * row,
        int sign, double scale)
{
    double ox = fmpq_get_d(P->com + 0), oy = fmpq_get_d(P->com + 1);
    double fx = sign * fmpz_get_d(row + 0), fy = sign * fmpz_get_d(row + 1);
    double tau = sign * fmpz_get_d(row + 2), f = hypot(fx, fy);

    if (p->kind == _WC_PRIM_ARC)
        return f == 0 && fabs(p->x - ox) + fabs(p->y - oy) <= 1e-12 * scale
               && p->closed == (tau < 0);
    if (f == 0)
        return 0;
    {
        double qx = (p->pts[0] + p->pts[2]) / 2, qy = (p->pts[1] + p->pts[3]) / 2;
        double dx = p->pts[2] - p->pts[0], dy = p->pts[3] - p->pts[1];
        double d = hypot(dx, dy);
        /* the moment about q: tau - (q - o) x f, zero on the line */
        double mq = tau - ((qx - ox) * fy - (qy - oy) * fx);

        return fabs(mq) <= 1e-9 * f * scale
               && fabs(dx / d - fx / f) + fabs(dy / d - fy / f) <= 1e-9;
    }
}

static void
check_mode(const wc_problem_t P, const char * mode)
{
    _wc_scene_t S;
    wc_cone_t W;
    wc_error_t err;
    slong i, j, drawn = 0;

    wc_error_init(err);
    wc_cone_init(W, 3);
    _wc_scene_init(S);
    if (wc_wrench_cone(W, NULL, P, mode, WC_METHOD_DIRECT, err) != WC_OK
        || _wc_draw_mode(S, P, mode, err) != WC_OK)
        wctest_fail_problem(P, mode, "the mode figure fails");
    for (i = 0; i < S->count; i++)
    {
        const _wc_prim_struct * p = S->prims + i;
        int found = 0;

        if (p->tag != _WC_TAG_FORCE_IN && p->tag != _WC_TAG_FORCE_OUT
            && p->tag != _WC_TAG_TORQUE_IN && p->tag != _WC_TAG_TORQUE_OUT)
            continue;
        drawn++;
        for (j = 0; j < W->rays->r && !found; j++)
            found = matches(p, P, W->rays->rows[j], 1, S->scale);
        for (j = 0; j < W->lines->r && !found; j++)
            found = matches(p, P, W->lines->rows[j], 1, S->scale)
                    || matches(p, P, W->lines->rows[j], -1, S->scale);
        if (!found)
            wctest_fail_problem(P, mode, "a drawn generator is none of W's");
    }
    if (drawn != (W->empty ? 0 : W->rays->r + 2 * W->lines->r))
        wctest_fail_problem(P, mode, "%ld generators drawn for %ld rays and "
                            "%ld lines", (long) drawn, (long) W->rays->r,
                            (long) W->lines->r);
    _wc_scene_clear(S);
    wc_cone_clear(W);
    wc_error_clear(err);
}

/* Every mode with w != 0 has a centre drawn where its witness puts it,
   and its name on that centre's label; every centre drawn is some
   mode's.  */
static void
check_modes(const wc_problem_t P)
{
    _wc_scene_t S;
    wc_modes_t M;
    wc_error_t err;
    slong i, k;
    double ox = fmpq_get_d(P->com + 0), oy = fmpq_get_d(P->com + 1);

    wc_error_init(err);
    wc_modes_init(M);
    _wc_scene_init(S);
    if (wc_modes_enumerate(M, P, err) != WC_OK
        || _wc_draw_modes(S, P, err) != WC_OK)
        wctest_fail_problem(P, NULL, "the modes figure fails");
    for (k = 0; k < S->count; k++)
    {
        const _wc_prim_struct * p = S->prims + k;
        int found = 0;

        if (p->tag != _WC_TAG_CENTRE)
            continue;
        for (i = 0; i < M->count && !found; i++)
        {
            const fmpz * nu = M->witness->rows[i];
            double vx = fmpz_get_d(nu + 0), vy = fmpz_get_d(nu + 1);
            double w = fmpz_get_d(nu + 2), cx = ox - vy / w, cy = oy + vx / w;

            found = w != 0 && dist(p->x, p->y, cx, cy)
                    <= 1e-9 * (S->scale + hypot(cx - ox, cy - oy));
        }
        if (!found)
            wctest_fail_problem(P, NULL, "a centre at (%g, %g) is no mode's",
                                p->x, p->y);
    }
    for (i = 0; i < M->count; i++)
    {
        const fmpz * nu = M->witness->rows[i];
        double vx = fmpz_get_d(nu + 0), vy = fmpz_get_d(nu + 1);
        double w = fmpz_get_d(nu + 2), cx = ox - vy / w, cy = oy + vx / w;
        int found = 0;

        for (k = 0; k + 1 < S->count && !found && w != 0; k++)
            found = S->prims[k].tag == _WC_TAG_CENTRE
                    && dist(S->prims[k].x, S->prims[k].y, cx, cy)
                       <= 1e-9 * (S->scale + hypot(cx - ox, cy - oy))
                    && S->prims[k + 1].text != NULL
                    && strstr(S->prims[k + 1].text, M->modes[i]) != NULL;
        if (w != 0 && !found)
            wctest_fail_problem(P, NULL, "mode %s: no centre labelled with "
                                "it at (%g, %g)",
                                M->modes[i], cx, cy);
    }
    _wc_scene_clear(S);
    wc_modes_clear(M);
    wc_error_clear(err);
}

/* The SVG of a figure is one whole document.  */
static void
check_svg(const wc_problem_t P)
{
    _wc_scene_t S;
    wc_error_t err;
    char * buf = NULL;
    size_t len = 0;
    FILE * f;

    wc_error_init(err);
    _wc_scene_init(S);
    if (_wc_draw_stability(S, P, err) != WC_OK || (f = tmpfile()) == NULL)
        wctest_fail_problem(P, NULL, "no figure");
    if (_wc_svg_fprint(f, S, 1) != WC_OK || (len = ftell(f)) < 8
        || (buf = calloc(len + 1, 1)) == NULL || fseek(f, 0, SEEK_SET) != 0
        || fread(buf, 1, len, f) != len || fclose(f) != 0)
        wctest_fail_problem(P, NULL, "the SVG writer fails");
    if (strncmp(buf, "<?xml", 5) != 0 || len < 8
        || strcmp(buf + len - 7, "</svg>\n") != 0
        || strstr(buf, "nan") != NULL || strstr(buf, "inf") != NULL)
        wctest_fail_problem(P, NULL, "the SVG is not a whole document");
    free(buf);
    _wc_scene_clear(S);
    wc_error_clear(err);
}

int
main(void)
{
    const char * files[] = { "section4.wc", "disk-two-fixels.wc",
                             "disk-two-fixels-insert.wc", "three-fixels.wc",
                             "three-fixels-insert.wc", "peg-in-hole.wc" };
    slong i, iters;
    char mode[16];

    wctest_init("t-draw");
    for (i = 0; i < 6; i++)
    {
        wc_problem_t P;

        wc_problem_init(P);
        wctest_load_data(P, files[i]);
        if (P->shape != WC_SHAPE_NONE)
            check_regions(P, files[i]);
        check_plan(P, files[i]);
        check_modes(P);
        check_svg(P);
        wc_problem_clear(P);
    }
    {
        wc_problem_t P;

        wc_problem_init(P);
        wctest_load_data(P, "section4.wc");
        check_mode(P, "na");
        check_mode(P, "ss");
        check_mode(P, "nu");
        wc_problem_clear(P);
    }
    {
        wc_problem_t P;
        fmpq g[3];

        wc_problem_init(P);
        wctest_load_data(P, "disk-two-fixels-insert.wc");
        for (i = 0; i < 3; i++)
            fmpq_init(g + i);
        fmpq_set_si(g + 0, -1, 1);
        fmpq_set_si(g + 1, -1, 1);
        check_graph(P, g);          /* accepted: five transitions */
        fmpq_set_si(g + 0, 1, 1);
        fmpq_set_si(g + 1, 1, 1);
        check_graph(P, g);          /* rejected */
        for (i = 0; i < 3; i++)
            fmpq_clear(g + i);
        wc_problem_clear(P);
    }
    iters = wctest_iters(40);
    for (i = 0; i < iters; i++)
    {
        wc_random_options opt;
        wc_problem_t P;
        wc_error_t err;

        if (!wctest_iter(i))
            continue;
        wc_random_options_init(&opt);
        opt.fixels = wctest_randint(1, 3);
        opt.seed = wctest_rand();
        opt.degenerate = wctest_chance(1, 2);
        opt.shape = wctest_chance(1, 2) ? WC_SHAPE_DISK : WC_SHAPE_POLYGON;
        wc_problem_init(P);
        wc_error_init(err);
        if (wc_random_problem(P, &opt, err) != WC_OK)
            wctest_fail("wc_random_problem fails");
        check_regions(P, "random");
        if (i % 4 == 0)
            check_plan(P, "random");
        check_modes(P);
        wctest_random_mode(mode, P);
        check_mode(P, mode);
        wc_error_clear(err);
        wc_problem_clear(P);
        wc_random_options_clear(&opt);
    }
    return 0;
}
