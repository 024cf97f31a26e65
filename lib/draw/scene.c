/* scene.c -- the primitives of a figure, its legend and caption.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/text.h"
#include "draw/scene.h"

void
_wc_scene_init(_wc_scene_t S)
{
    memset(S, 0, sizeof(*S));
    S->scale = 1.0;
}

void
_wc_scene_clear(_wc_scene_t S)
{
    slong i;

    for (i = 0; i < S->count; i++)
    {
        free(S->prims[i].pts);
        free(S->prims[i].text);
    }
    for (i = 0; i < S->nlegend; i++)
        free(S->legend[i].text);
    free(S->prims);
    free(S->legend);
    free(S->title);
    free(S->caption);
    _wc_scene_init(S);
}

_wc_prim_struct *
_wc_scene_add(_wc_scene_t S, _wc_draw_kind kind, _wc_draw_tag tag)
{
    _wc_prim_struct * p;

    if (S->count == S->alloc)
    {
        slong alloc = S->alloc ? 2 * S->alloc : 64;

        p = realloc(S->prims, alloc * sizeof(*p));
        if (p == NULL)
            return NULL;
        S->prims = p;
        S->alloc = alloc;
    }
    p = S->prims + S->count++;
    memset(p, 0, sizeof(*p));
    p->kind = kind;
    p->tag = tag;
    return p;
}

static int
points(_wc_scene_t S, _wc_draw_kind kind, _wc_draw_tag tag, int layer,
       const double * xy, slong n)
{
    _wc_prim_struct * p = _wc_scene_add(S, kind, tag);

    if (p == NULL)
        return WC_EINTERNAL;
    p->layer = layer;
    if ((p->pts = malloc(2 * n * sizeof(double))) == NULL)
    {
        S->count--;
        return WC_EINTERNAL;
    }
    memcpy(p->pts, xy, 2 * n * sizeof(double));
    p->npts = n;
    return WC_OK;
}

int
_wc_scene_line(_wc_scene_t S, _wc_draw_tag tag, int layer,
               double x0, double y0, double x1, double y1)
{
    double xy[4] = { x0, y0, x1, y1 };

    return points(S, _WC_PRIM_LINE, tag, layer, xy, 2);
}

int
_wc_scene_arrow(_wc_scene_t S, _wc_draw_tag tag,
                double x0, double y0, double x1, double y1)
{
    double xy[4] = { x0, y0, x1, y1 };

    return points(S, _WC_PRIM_ARROW, tag, 0, xy, 2);
}

int
_wc_scene_poly(_wc_scene_t S, _wc_draw_tag tag, int closed,
               const double * xy, slong n)
{
    int status = points(S, _WC_PRIM_LINE, tag, 0, xy, n);

    if (status == WC_OK)
        S->prims[S->count - 1].closed = closed;
    return status;
}

int
_wc_scene_arc(_wc_scene_t S, _wc_draw_tag tag, int layer, double x,
              double y, double r, double a0, double a1)
{
    _wc_prim_struct * p = _wc_scene_add(S, _WC_PRIM_ARC, tag);

    if (p == NULL)
        return WC_EINTERNAL;
    p->layer = layer;
    p->x = x;
    p->y = y;
    p->r = r;
    p->a0 = a0;
    p->a1 = a1;
    return WC_OK;
}

int
_wc_scene_dot(_wc_scene_t S, _wc_draw_tag tag, int layer, double x,
              double y)
{
    _wc_prim_struct * p = _wc_scene_add(S, _WC_PRIM_DOT, tag);

    if (p == NULL)
        return WC_EINTERNAL;
    p->layer = layer;
    p->x = x;
    p->y = y;
    return WC_OK;
}

int
_wc_scene_text(_wc_scene_t S, double x, double y, double dx, double dy,
               int anchor, const char * text)
{
    _wc_prim_struct * p = _wc_scene_add(S, _WC_PRIM_TEXT, _WC_TAG_LABEL);

    if (p == NULL)
        return WC_EINTERNAL;
    if ((p->text = _wc_strdup(text)) == NULL)
    {
        S->count--;
        return WC_EINTERNAL;
    }
    p->x = x;
    p->y = y;
    p->dx = dx;
    p->dy = dy;
    p->anchor = anchor;
    return WC_OK;
}

/* A malloc'd vprintf, or NULL.  */
static char *
vformat(const char * fmt, va_list ap)
{
    va_list aq;
    char * s;
    int len;

    va_copy(aq, ap);
    len = vsnprintf(NULL, 0, fmt, aq);
    va_end(aq);
    if (len < 0 || (s = malloc((size_t) len + 1)) == NULL)
        return NULL;
    vsnprintf(s, (size_t) len + 1, fmt, ap);
    return s;
}

int
_wc_scene_legend(_wc_scene_t S, _wc_draw_tag tag, int layer,
                 const char * fmt, ...)
{
    _wc_legend_struct * l;
    va_list ap;
    slong i;
    char * s;

    for (i = 0; i < S->nlegend; i++)
        if (S->legend[i].tag == tag && S->legend[i].layer == layer)
            return WC_OK;
    va_start(ap, fmt);
    s = vformat(fmt, ap);
    va_end(ap);
    if (s == NULL)
        return WC_EINTERNAL;
    l = realloc(S->legend, (S->nlegend + 1) * sizeof(*l));
    if (l == NULL)
    {
        free(s);
        return WC_EINTERNAL;
    }
    S->legend = l;
    l[S->nlegend].tag = tag;
    l[S->nlegend].layer = layer;
    l[S->nlegend++].text = s;
    return WC_OK;
}

int
_wc_scene_title(_wc_scene_t S, const char * text)
{
    char * s = _wc_strdup(text);

    if (s == NULL)
        return WC_EINTERNAL;
    free(S->title);
    S->title = s;
    return WC_OK;
}

int
_wc_scene_vcaption(_wc_scene_t S, const char * head, const char * fmt,
                   va_list ap)
{
    char * r = vformat(fmt, ap), * s;

    if (r == NULL)
        return WC_EINTERNAL;
    if ((s = malloc(strlen(head) + strlen(r) + 1)) == NULL)
    {
        free(r);
        return WC_EINTERNAL;
    }
    strcpy(s, head);
    strcat(s, r);
    free(r);
    free(S->caption);
    S->caption = s;
    return WC_OK;
}

int
_wc_scene_caption(_wc_scene_t S, const char * fmt, ...)
{
    va_list ap;
    int status;

    va_start(ap, fmt);
    status = _wc_scene_vcaption(S, "", fmt, ap);
    va_end(ap);
    return status;
}

char *
_wc_draw_fmpq_str(const fmpq_t x)
{
    char * f = fmpq_get_str(NULL, 10, x), * s;

    s = f == NULL ? NULL : _wc_strdup(f);
    flint_free(f);
    return s;
}

static void
grow(double * box, double x, double y, int * any)
{
    if (!*any || x < box[0])
        box[0] = x;
    if (!*any || y < box[1])
        box[1] = y;
    if (!*any || x > box[2])
        box[2] = x;
    if (!*any || y > box[3])
        box[3] = y;
    *any = 1;
}

void
_wc_scene_bbox(double * box, const _wc_scene_t S)
{
    int any = 0;
    slong i, k;

    for (i = 0; i < S->count; i++)
    {
        const _wc_prim_struct * p = S->prims + i;

        if (p->kind == _WC_PRIM_LINE || p->kind == _WC_PRIM_ARROW)
            for (k = 0; k < p->npts; k++)
                grow(box, p->pts[2 * k], p->pts[2 * k + 1], &any);
        else if (p->kind == _WC_PRIM_ARC || p->kind == _WC_PRIM_CIRCLE)
        {
            grow(box, p->x - p->r, p->y - p->r, &any);
            grow(box, p->x + p->r, p->y + p->r, &any);
        }
        else if (p->kind == _WC_PRIM_DOT || p->kind == _WC_PRIM_TEXT)
            grow(box, p->x, p->y, &any);
    }
    if (!any)
    {
        box[0] = box[1] = -1;
        box[2] = box[3] = 1;
    }
}
