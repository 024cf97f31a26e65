/* part.c -- what every figure of a part shows: its outline, centre of
   mass and fixels; and pushing regions on its boundary.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "draw/figure.h"

const char *
_wc_draw_name(const wc_problem_t P)
{
    return P->name != NULL ? P->name : P->file != NULL ? P->file : "problem";
}

static void
grow(double * box, double x, double y)
{
    if (x < box[0])
        box[0] = x;
    if (x > box[2])
        box[2] = x;
    if (y < box[1])
        box[1] = y;
    if (y > box[3])
        box[3] = y;
}

char *
_wc_draw_friction(const wc_problem_t P)
{
    char * s = _wc_draw_fmpq_str(P->mu_s), * k, * w;

    if (s == NULL || fmpq_equal(P->mu_s, P->mu_k))
        return s;
    if ((k = _wc_draw_fmpq_str(P->mu_k)) == NULL
        || (w = malloc(strlen(s) + strlen(k) + 32)) == NULL)
    {
        free(s);
        free(k);
        return NULL;
    }
    sprintf(w, "%s static, %s kinetic", s, k);
    free(s);
    free(k);
    return w;
}

int
_wc_draw_titles(_wc_scene_t S, const wc_problem_t P, const char * title,
                const char * fmt, ...)
{
    const char * name = _wc_draw_name(P);
    char * mu, * head = NULL;
    va_list ap;
    int status = _wc_scene_title(S, title);

    if (status != WC_OK)
        return status;
    if ((mu = _wc_draw_friction(P)) == NULL
        || (head = malloc(strlen(name) + strlen(mu) + 16)) == NULL)
        status = WC_EINTERNAL;
    else
    {
        sprintf(head, "%s, friction %s", name, mu);
        va_start(ap, fmt);
        status = _wc_scene_vcaption(S, head, fmt, ap);
        va_end(ap);
    }
    free(head);
    free(mu);
    return status;
}

/* The bounding box of the shape, the fixels and the centre of mass.  */
static void
part_box(double * box, const wc_problem_t P)
{
    slong i;

    box[0] = box[2] = fmpq_get_d(P->com + 0);
    box[1] = box[3] = fmpq_get_d(P->com + 1);
#define GROW(X, Y) grow(box, (X), (Y))
    for (i = 0; i < P->n; i++)
        GROW(fmpq_get_d(P->fixels[i].point + 0),
             fmpq_get_d(P->fixels[i].point + 1));
    if (P->shape == WC_SHAPE_DISK)
    {
        double cx = fmpq_get_d(P->shape_data + 0);
        double cy = fmpq_get_d(P->shape_data + 1);
        double r = fmpq_get_d(P->shape_data + 2);

        GROW(cx - r, cy - r);
        GROW(cx + r, cy + r);
    }
    else if (P->shape == WC_SHAPE_POLYGON)
        for (i = 0; i + 1 < P->shape_len; i += 2)
            GROW(fmpq_get_d(P->shape_data + i),
                 fmpq_get_d(P->shape_data + i + 1));
#undef GROW
}

static int
outline(_wc_scene_t S, const wc_problem_t P, const double * box)
{
    slong i, k = P->shape_len / 2;
    double * xy;
    int status;

    if (P->shape == WC_SHAPE_DISK)
    {
        _wc_prim_struct * p = _wc_scene_add(S, _WC_PRIM_CIRCLE, _WC_TAG_PART);

        if (p == NULL)
            return WC_EINTERNAL;
        p->x = fmpq_get_d(P->shape_data + 0);
        p->y = fmpq_get_d(P->shape_data + 1);
        p->r = fmpq_get_d(P->shape_data + 2);
        p->a1 = 2 * _WC_PI;
        return _wc_scene_legend(S, _WC_TAG_PART, 0, "the part (a disk)");
    }
    if (P->shape == WC_SHAPE_POLYGON)
    {
        if ((xy = malloc(2 * k * sizeof(double))) == NULL)
            return WC_EINTERNAL;
        for (i = 0; i < 2 * k; i++)
            xy[i] = fmpq_get_d(P->shape_data + i);
        status = _wc_scene_poly(S, _WC_TAG_PART, 1, xy, k);
        free(xy);
        if (status == WC_OK)
            status = _wc_scene_legend(S, _WC_TAG_PART, 0,
                                      "the part (a polygon)");
        return status;
    }
    {
        double m = 0.15 * S->scale;
        double f[8] = { box[0] - m, box[1] - m, box[2] + m, box[1] - m,
                        box[2] + m, box[3] + m, box[0] - m, box[3] + m };

        status = _wc_scene_poly(S, _WC_TAG_FRAME, 1, f, 4);
        if (status == WC_OK)
            status = _wc_scene_legend(S, _WC_TAG_FRAME, 0,
                                      "no shape given: a frame round the "
                                      "fixels");
        return status;
    }
}

/* Fixel i: the contact point, the inward normal, the friction cone's
   edges (static; kinetic too when it differs), its number.  */
static int
fixel(_wc_scene_t S, const wc_fixel_struct * f, slong i)
{
    double px = fmpq_get_d(f->point + 0), py = fmpq_get_d(f->point + 1);
    double nx = fmpq_get_d(f->normal + 0), ny = fmpq_get_d(f->normal + 1);
    double len = sqrt(nx * nx + ny * ny), L = 0.2 * S->scale;
    double mus = fmpq_get_d(f->mu_s), muk = fmpq_get_d(f->mu_k);
    char label[32];
    int status, k;

    nx /= len;
    ny /= len;
    status = _wc_scene_arrow(S, _WC_TAG_NORMAL, px, py, px + L * nx,
                             py + L * ny);
    for (k = 0; k < 4 && status == WC_OK; k++)
    {
        double mu = k < 2 ? mus : muk, sg = (k % 2) ? -1 : 1;
        double dx = nx - sg * mu * ny, dy = ny + sg * mu * nx;
        double dl = sqrt(dx * dx + dy * dy);

        if (k >= 2 && fmpq_equal(f->mu_s, f->mu_k))
            break;
        status = _wc_scene_line(S, k < 2 ? _WC_TAG_FRICTION
                                : _WC_TAG_FRICTION_K, 0, px, py,
                                px + 1.1 * L * dx / dl,
                                py + 1.1 * L * dy / dl);
    }
    if (status == WC_OK)
        status = _wc_scene_dot(S, f->state == WC_TOUCHING ? _WC_TAG_TOUCHING
                               : _WC_TAG_NEAR, 0, px, py);
    snprintf(label, sizeof(label), "%ld", (long) (i + 1));
    if (status == WC_OK)
        status = _wc_scene_text(S, px, py, -14 * nx, 14 * ny + 4, 0, label);
    if (status == WC_OK && !fmpq_equal(f->mu_s, f->mu_k))
        status = _wc_scene_legend(S, _WC_TAG_FRICTION_K, 0,
                                  "edge of a kinetic friction cone (mu_k)");
    return status;
}

int
_wc_draw_part(_wc_scene_t S, const wc_problem_t P)
{
    double box[4];
    slong i;
    int status;

    part_box(box, P);
    S->scale = box[2] - box[0] > box[3] - box[1] ? box[2] - box[0]
               : box[3] - box[1];
    if (!(S->scale > 0))
        S->scale = 1;
    status = outline(S, P, box);
    if (status == WC_OK)
        status = _wc_scene_dot(S, _WC_TAG_COM, 0, fmpq_get_d(P->com + 0),
                               fmpq_get_d(P->com + 1));
    if (status == WC_OK)
        status = _wc_scene_text(S, fmpq_get_d(P->com + 0),
                                fmpq_get_d(P->com + 1), 8, 16, -1, "o");
    if (status == WC_OK)
        status = _wc_scene_legend(S, _WC_TAG_COM, 0, "centre of mass o");
    for (i = 0; i < P->n && status == WC_OK; i++)
    {
        status = fixel(S, P->fixels + i, i);
        if (status == WC_OK)
            status = _wc_scene_legend(S, P->fixels[i].state == WC_TOUCHING
                                      ? _WC_TAG_TOUCHING : _WC_TAG_NEAR, 0,
                                      P->fixels[i].state == WC_TOUCHING
                                      ? "touching fixel"
                                      : "fixel about to touch (near)");
    }
    if (status == WC_OK)
        status = _wc_scene_legend(S, _WC_TAG_NORMAL, 0, "inward normal");
    if (status == WC_OK)
        status = _wc_scene_legend(S, _WC_TAG_FRICTION, 0,
                                  "edge of a static friction cone (mu_s)");
    return status;
}

/* +1 when the polygon runs counter-clockwise, -1 when clockwise (the
   sign of twice its area, exactly).  */
static int
orientation(const wc_problem_t P)
{
    slong i, k = P->shape_len / 2;
    fmpq_t a, t;
    int s;

    fmpq_init(a);
    fmpq_init(t);
    for (i = 0; i < k; i++)
    {
        const fmpq * u = P->shape_data + 2 * i;
        const fmpq * v = P->shape_data + 2 * ((i + 1) % k);

        fmpq_mul(t, u + 0, v + 1);
        fmpq_add(a, a, t);
        fmpq_mul(t, u + 1, v + 0);
        fmpq_sub(a, a, t);
    }
    s = fmpq_sgn(a) >= 0 ? 1 : -1;
    fmpq_clear(a);
    fmpq_clear(t);
    return s;
}

/* q := u + s (v - u), exactly, as doubles.  */
static void
edge_point(double * q, const fmpq * u, const fmpq * v, const fmpq_t s)
{
    fmpq_t t;
    int j;

    fmpq_init(t);
    for (j = 0; j < 2; j++)
    {
        fmpq_sub(t, v + j, u + j);
        fmpq_mul(t, t, s);
        fmpq_add(t, t, u + j);
        q[j] = fmpq_get_d(t);
    }
    fmpq_clear(t);
}

static int
ends(_wc_scene_t S, int layer, const double * a, const double * b,
     const wc_push_interval_struct * iv)
{
    int status = _wc_scene_dot(S, iv->from_closed ? _WC_TAG_END_CLOSED
                               : _WC_TAG_END_OPEN, layer, a[0], a[1]);

    if (status == WC_OK && b != NULL)
        status = _wc_scene_dot(S, iv->to_closed ? _WC_TAG_END_CLOSED
                               : _WC_TAG_END_OPEN, layer, b[0], b[1]);
    return status;
}

static int
polygon_region(_wc_scene_t S, const wc_problem_t P, const wc_push_t R,
               int layer)
{
    slong k = P->shape_len / 2, i;
    double off = 0.04 * S->scale * layer * orientation(P);
    int status = WC_OK;

    for (i = 0; i < R->count && status == WC_OK; i++)
    {
        const wc_push_interval_struct * iv = R->iv + i;
        const fmpq * u = P->shape_data + 2 * iv->edge;
        const fmpq * v = P->shape_data + 2 * ((iv->edge + 1) % k);
        double a[2], b[2], ex, ey, el, ox, oy;

        edge_point(a, u, v, iv->from);
        edge_point(b, u, v, iv->to);
        ex = fmpq_get_d(v + 0) - fmpq_get_d(u + 0);
        ey = fmpq_get_d(v + 1) - fmpq_get_d(u + 1);
        el = sqrt(ex * ex + ey * ey);
        ox = off * ey / el;     /* outwards: the edge turned by -90 */
        oy = -off * ex / el;    /* degrees for a counter-clockwise one */
        a[0] += ox, a[1] += oy, b[0] += ox, b[1] += oy;
        if (fmpq_equal(iv->from, iv->to))
            status = ends(S, layer, a, NULL, iv);
        else
        {
            status = _wc_scene_line(S, _WC_TAG_REGION, layer, a[0], a[1],
                                    b[0], b[1]);
            if (status == WC_OK)
                status = ends(S, layer, a, b, iv);
        }
    }
    return status;
}

static double
angle(const fmpz * d)
{
    double a = atan2(fmpz_get_d(d + 1), fmpz_get_d(d + 0));

    return a < 0 ? a + 2 * _WC_PI : a;
}

static int
disk_region(_wc_scene_t S, const wc_problem_t P, const wc_push_t R,
            int layer)
{
    double cx = fmpq_get_d(P->shape_data + 0);
    double cy = fmpq_get_d(P->shape_data + 1);
    double r = fmpq_get_d(P->shape_data + 2) + 0.04 * S->scale * layer;
    int status = WC_OK;
    slong i;

    for (i = 0; i < R->count && status == WC_OK; i++)
    {
        const wc_push_interval_struct * iv = R->iv + i;
        double a0 = angle(iv->dfrom), a1 = angle(iv->dto), a[2], b[2];
        int same = fmpz_equal(iv->dfrom + 0, iv->dto + 0)
                   && fmpz_equal(iv->dfrom + 1, iv->dto + 1);

        if (iv->full)
        {
            status = _wc_scene_arc(S, _WC_TAG_REGION, layer, cx, cy, r, 0,
                                   2 * _WC_PI);
            continue;
        }
        a[0] = cx + r * cos(a0);
        a[1] = cy + r * sin(a0);
        b[0] = cx + r * cos(a1);
        b[1] = cy + r * sin(a1);
        if (same && iv->from_closed)
        {
            status = ends(S, layer, a, NULL, iv);
            continue;
        }
        if (a1 <= a0)
            a1 += 2 * _WC_PI;
        status = _wc_scene_arc(S, _WC_TAG_REGION, layer, cx, cy, r, a0, a1);
        if (status == WC_OK)
            status = ends(S, layer, a, b, iv);
    }
    return status;
}

int
_wc_draw_region(_wc_scene_t S, const wc_problem_t P, const wc_push_t R,
                int layer)
{
    if (layer + 1 > S->nlayers)
        S->nlayers = layer + 1;
    if (R->kind == WC_SHAPE_POLYGON)
        return polygon_region(S, P, R, layer);
    return disk_region(S, P, R, layer);
}
