/* svg.c -- a scene as a standalone SVG document.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Layout, top to bottom: the title, the plane (the scene's geometry,
   scaled to fit), the legend (two columns), the caption (wrapped).
   Every style is a presentation attribute (no CSS), and is told apart
   by dash pattern and width as well as by grey.  */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "draw/scene.h"
#include "core/text.h"

#define WIDTH 640.0
#define MARGIN 30.0
#define PLANE_W (WIDTH - 2 * MARGIN)
#define PLANE_H 440.0
#define TOP 40.0
#define PAD 40.0        /* room for markers and labels beside the plane */
#define LEGEND_ROW 20.0
#define CAPTION_ROW 16.0
#define CAPTION_CHARS 92

typedef struct
{
    const char * stroke;
    double width;
    const char * dash;      /* NULL: solid */
    const char * fill;
}
style;

static const style tag_style[_WC_TAG_COUNT] = {
    { "#777777", 1.5, NULL, "#f0f0f0" },        /* part */
    { "#999999", 1.0, "6 3", "none" },          /* frame */
    { "#000000", 1.5, NULL, "#ffffff" },        /* com */
    { "#000000", 1.5, NULL, "#000000" },        /* touching */
    { "#000000", 1.5, NULL, "#ffffff" },        /* near */
    { "#444444", 1.0, NULL, "none" },           /* normal */
    { "#666666", 1.0, "4 2", "none" },          /* friction */
    { "#666666", 1.0, "1 2", "none" },          /* friction, kinetic */
    { "#000000", 2.0, NULL, "none" },           /* force, included */
    { "#555555", 1.5, "6 3", "none" },          /* force, excluded */
    { "#000000", 2.0, NULL, "none" },           /* torque, included */
    { "#555555", 1.5, "6 3", "none" },          /* torque, excluded */
    { "#000000", 5.0, NULL, "none" },           /* region */
    { "#000000", 1.5, NULL, "#000000" },        /* closed end */
    { "#000000", 1.5, NULL, "#ffffff" },        /* open end */
    { "#000000", 1.5, NULL, "none" },           /* rotation centre */
    { "#000000", 1.5, "2 2", "none" },          /* translation */
    { "#000000", 1.2, NULL, "#ffffff" },        /* state */
    { "#000000", 3.0, NULL, "#ffffff" },        /* goal state */
    { "#000000", 1.5, NULL, "none" },           /* progress */
    { "#777777", 1.2, "5 3", "none" },          /* forbidden */
    { "#000000", 2.5, NULL, "none" },           /* admitted */
    { "#000000", 0.0, NULL, "#000000" }         /* label */
};

/* Regions by layer: grey, dash, width.  */
#define NLAYER_STYLES 5
static const style layer_style[NLAYER_STYLES] = {
    { "#000000", 5.0, NULL, "none" },
    { "#404040", 4.0, "10 3", "none" },
    { "#000000", 3.0, "3 3", "none" },
    { "#606060", 4.0, "14 3 3 3", "none" },
    { "#202020", 2.5, "1 4", "none" }
};

static style
style_of(_wc_draw_tag tag, int layer)
{
    if (tag == _WC_TAG_REGION)
        return layer_style[layer % NLAYER_STYLES];
    return tag_style[tag];
}

void
_wc_svg_transform(double * t, const _wc_scene_t S)
{
    double box[4], bw, bh, s;

    _wc_scene_bbox(box, S);
    bw = box[2] - box[0];
    bh = box[3] - box[1];
    if (bw < 1e-9 * S->scale)
        bw = S->scale;
    if (bh < 1e-9 * S->scale)
        bh = S->scale;
    s = (PLANE_W - 2 * PAD) / bw;
    if (PLANE_H / bh < s)
        s = PLANE_H / bh;
    t[2] = s;
    t[0] = MARGIN + (PLANE_W - s * bw) / 2 - s * box[0];    /* centred */
    t[1] = TOP + 20 + s * box[3];
}

void
_wc_svg_put_text(FILE * out, const char * s, size_t len)
{
    const unsigned char * u = (const unsigned char *) s;
    size_t i = 0;

    while (i < len)
    {
        unsigned char c = u[i];
        size_t k = _wc_utf8_length(u + i, len - i);

        if (c == '&')
            fputs("&amp;", out);
        else if (c == '<')
            fputs("&lt;", out);
        else if (c == '>')
            fputs("&gt;", out);
        else if (c == '"')
            fputs("&quot;", out);
        else if (k == 0 || (c < 0x20 && c != '\t' && c != '\n' && c != '\r')
                 || c == 0x7f)
            fprintf(out, "\\x%02x", c);
        else
        {
            fwrite(s + i, 1, k, out);
            i += k;
            continue;
        }
        i++;
    }
}

static void
put_text(FILE * out, const char * s)
{
    _wc_svg_put_text(out, s, strlen(s));
}

static void
put_style(FILE * out, style st)
{
    fprintf(out, " stroke=\"%s\" stroke-width=\"%.1f\" fill=\"%s\"",
            st.stroke, st.width, st.fill);
    if (st.dash != NULL)
        fprintf(out, " stroke-dasharray=\"%s\"", st.dash);
}

/* Tags' names, for the class attribute (tests find elements by it).  */
static const char * const tag_name[_WC_TAG_COUNT] = {
    "part", "frame", "com", "touching", "near", "normal", "friction",
    "friction-kinetic", "force", "force-excluded", "torque",
    "torque-excluded", "region", "end-closed", "end-open", "centre",
    "translation", "state", "goal", "progress", "forbidden", "admitted",
    "label"
};

static void
open_elem(FILE * out, const char * name, const _wc_prim_struct * p)
{
    fprintf(out, "<%s class=\"%s", name, tag_name[p->tag]);
    if (p->tag == _WC_TAG_REGION || p->tag == _WC_TAG_END_OPEN
        || p->tag == _WC_TAG_END_CLOSED)
        fprintf(out, " layer-%d", p->layer);
    putc('"', out);
}

/* An arrowhead at (x1, y1) (pixels) pointing away from (x0, y0).  */
static void
head(FILE * out, double x0, double y0, double x1, double y1, style st)
{
    double dx = x1 - x0, dy = y1 - y0, len = sqrt(dx * dx + dy * dy);
    double ux, uy, L = 9.0, h = 4.0;

    if (len < 1e-9)
        return;
    ux = dx / len;
    uy = dy / len;
    fprintf(out, "<path d=\"M %.3f %.3f L %.3f %.3f L %.3f %.3f Z\" "
            "fill=\"%s\" stroke=\"none\"/>\n", x1, y1,
            x1 - L * ux - h * uy, y1 - L * uy + h * ux,
            x1 - L * ux + h * uy, y1 - L * uy - h * ux, st.stroke);
}

static void
put_line(FILE * out, const _wc_prim_struct * p, const double * t, style st)
{
    slong k;

    open_elem(out, p->closed ? "polygon" : "polyline", p);
    fputs(" points=\"", out);
    for (k = 0; k < p->npts; k++)
        fprintf(out, "%s%.3f,%.3f", k ? " " : "", t[0] + t[2] * p->pts[2 * k],
                t[1] - t[2] * p->pts[2 * k + 1]);
    putc('"', out);
    if (!p->closed)
        st.fill = "none";
    put_style(out, st);
    fputs(" stroke-linejoin=\"round\"/>\n", out);
    if (p->kind == _WC_PRIM_ARROW)
    {
        double x0 = t[0] + t[2] * p->pts[0], y0 = t[1] - t[2] * p->pts[1];
        double x1 = t[0] + t[2] * p->pts[2], y1 = t[1] - t[2] * p->pts[3];

        head(out, x0, y0, x1, y1, st);
    }
}

static void
put_arc(FILE * out, const _wc_prim_struct * p, const double * t, style st,
        int arrow)
{
    double cx = t[0] + t[2] * p->x, cy = t[1] - t[2] * p->y, r = t[2] * p->r;
    double x0 = cx + r * cos(p->a0), y0 = cy - r * sin(p->a0);
    double x1 = cx + r * cos(p->a1), y1 = cy - r * sin(p->a1);

    if (p->a1 - p->a0 >= 2 * _WC_PI - 1e-12)
    {
        open_elem(out, "circle", p);
        fprintf(out, " cx=\"%.3f\" cy=\"%.3f\" r=\"%.3f\"", cx, cy, r);
        put_style(out, st);
        fputs("/>\n", out);
        return;
    }
    open_elem(out, "path", p);
    fprintf(out, " d=\"M %.3f %.3f A %.3f %.3f 0 %d 0 %.3f %.3f\"", x0, y0,
            r, r, p->a1 - p->a0 > _WC_PI, x1, y1);
    put_style(out, st);
    fputs("/>\n", out);
    if (arrow && p->closed)     /* clockwise: the head at a0 */
        head(out, x0 - sin(p->a0), y0 - cos(p->a0), x0, y0, st);
    else if (arrow)             /* the head along the tangent at a1 */
        head(out, x1 + sin(p->a1), y1 + cos(p->a1), x1, y1, st);
}

static void
put_dot(FILE * out, const _wc_prim_struct * p, const double * t, style st)
{
    double x = t[0] + t[2] * p->x, y = t[1] - t[2] * p->y;

    if (p->tag == _WC_TAG_NODE || p->tag == _WC_TAG_GOAL)
    {
        open_elem(out, "rect", p);
        fprintf(out, " x=\"%.3f\" y=\"%.3f\" width=\"64\" height=\"24\" "
                "rx=\"4\"", x - 32, y - 12);
    }
    else
    {
        open_elem(out, "circle", p);
        fprintf(out, " cx=\"%.3f\" cy=\"%.3f\" r=\"%d\"", x, y,
                p->tag == _WC_TAG_CENTRE ? 6 : 4);
    }
    put_style(out, st);
    fputs("/>\n", out);
    if (p->tag == _WC_TAG_CENTRE || p->tag == _WC_TAG_COM)
        fprintf(out, "<path d=\"M %.3f %.3f H %.3f M %.3f %.3f V %.3f\" "
                "stroke=\"#000000\" stroke-width=\"1\"/>\n", x - 8, y,
                x + 8, x, y - 8, y + 8);
}

static void
put_prim(FILE * out, const _wc_prim_struct * p, const double * t)
{
    style st = style_of(p->tag, p->layer);

    if (p->kind == _WC_PRIM_LINE || p->kind == _WC_PRIM_ARROW)
        put_line(out, p, t, st);
    else if (p->kind == _WC_PRIM_ARC || p->kind == _WC_PRIM_CIRCLE)
        put_arc(out, p, t, st, p->tag == _WC_TAG_TORQUE_IN
                || p->tag == _WC_TAG_TORQUE_OUT
                || p->tag == _WC_TAG_EDGE_FORBIDDEN
                || p->tag == _WC_TAG_EDGE_ADMITTED);
    else if (p->kind == _WC_PRIM_DOT)
        put_dot(out, p, t, st);
    else
    {
        fprintf(out, "<text class=\"label\" x=\"%.3f\" y=\"%.3f\" "
                "font-family=\"sans-serif\" font-size=\"12\" "
                "stroke=\"#ffffff\" stroke-width=\"3\" "
                "paint-order=\"stroke\" text-anchor=\"%s\">", t[0] + t[2] * p->x + p->dx,
                t[1] - t[2] * p->y + p->dy, p->anchor < 0 ? "start"
                : p->anchor > 0 ? "end" : "middle");
        put_text(out, p->text);
        fputs("</text>\n", out);
    }
}

/* Labels that may move (text primitives with closed set): the first of
   a few places round their point where they overlap no label placed
   before them and no marker, by an estimate of the text's box.  */
typedef struct
{
    double x0, y0, x1, y1;
}
box;

static void
text_box(box * b, double x, double y, int anchor, const char * s)
{
    double w = 7.0 * (double) strlen(s);

    b->x0 = anchor < 0 ? x : anchor > 0 ? x - w : x - w / 2;
    b->x1 = b->x0 + w;
    b->y0 = y - 11;
    b->y1 = y + 3;
}

static int
overlaps(const box * a, const box * boxes, slong n)
{
    slong i;

    for (i = 0; i < n; i++)
        if (a->x0 < boxes[i].x1 && boxes[i].x0 < a->x1
            && a->y0 < boxes[i].y1 && boxes[i].y0 < a->y1)
            return 1;
    return 0;
}

/* Write the plane's primitives, moving the movable labels.  */
static void
put_plane(FILE * out, const _wc_scene_t S, const double * t)
{
    static const double place[8][3] = {
        { 9, -8, -1 }, { 9, 18, -1 }, { -9, -8, 1 }, { -9, 18, 1 },
        { 0, -14, 0 }, { 0, 26, 0 }, { 9, -22, -1 }, { 9, 32, -1 } };
    box * boxes = malloc(sizeof(box) * (S->count + 1));
    slong i, n = 0;
    int k;

    for (i = 0; boxes != NULL && i < S->count; i++)
        if (S->prims[i].kind == _WC_PRIM_DOT)
        {
            double x = t[0] + t[2] * S->prims[i].x;
            double y = t[1] - t[2] * S->prims[i].y;
            box b = { x - 6, y - 6, x + 6, y + 6 };

            boxes[n++] = b;
        }
    for (i = 0; i < S->count; i++)
    {
        _wc_prim_struct p = S->prims[i];
        double x = t[0] + t[2] * p.x, y = t[1] - t[2] * p.y;
        box b;

        if (p.kind == _WC_PRIM_TEXT && boxes != NULL)
        {
            for (k = 0; p.closed && k < 8; k++)
            {
                text_box(&b, x + place[k][0], y + place[k][1],
                         (int) place[k][2], p.text);
                if (!overlaps(&b, boxes, n))
                    break;
            }
            if (p.closed)
            {
                k = k == 8 ? 0 : k;
                p.dx = place[k][0];
                p.dy = place[k][1];
                p.anchor = (int) place[k][2];
            }
            text_box(&boxes[n++], x + p.dx, y + p.dy, p.anchor, p.text);
        }
        put_prim(out, &p, t);
    }
    free(boxes);
}

/* A legend entry's sample at (x, y), 36 pixels wide.  */
static void
sample(FILE * out, const _wc_legend_struct * l, double x, double y)
{
    _wc_prim_struct p;
    double t[3] = { 0, 0, 1 };
    double xy[4] = { x, -y, x + 36, -y };

    memset(&p, 0, sizeof(p));
    p.tag = l->tag;
    p.layer = l->layer;
    p.x = l->tag == _WC_TAG_NODE || l->tag == _WC_TAG_GOAL ? x + 32 : x + 18;
    p.y = -y;
    p.pts = xy;
    p.npts = 2;
    switch (l->tag)
    {
    case _WC_TAG_COM: case _WC_TAG_TOUCHING: case _WC_TAG_NEAR:
    case _WC_TAG_END_CLOSED: case _WC_TAG_END_OPEN: case _WC_TAG_CENTRE:
    case _WC_TAG_NODE: case _WC_TAG_GOAL:
        p.kind = _WC_PRIM_DOT;
        break;
    case _WC_TAG_NORMAL: case _WC_TAG_FORCE_IN: case _WC_TAG_FORCE_OUT:
    case _WC_TAG_TRANSLATION: case _WC_TAG_EDGE_PROGRESS:
    case _WC_TAG_EDGE_FORBIDDEN: case _WC_TAG_EDGE_ADMITTED:
    case _WC_TAG_TORQUE_IN: case _WC_TAG_TORQUE_OUT:
        p.kind = _WC_PRIM_ARROW;
        break;
    default:
        p.kind = _WC_PRIM_LINE;
    }
    if (l->tag == _WC_TAG_PART)
    {
        fprintf(out, "<rect x=\"%.3f\" y=\"%.3f\" width=\"36\" "
                "height=\"12\"", x, y - 6);
        put_style(out, style_of(l->tag, 0));
        fputs("/>\n", out);
        return;
    }
    put_prim(out, &p, t);
}

/* The caption's lines, each at most CAPTION_CHARS, broken at spaces;
   returns their number and writes them when out is not NULL.  */
static int
caption_lines(FILE * out, const char * s, double y)
{
    int n = 0;

    while (s != NULL && *s)
    {
        size_t len = strlen(s), cut = len;

        if (len > CAPTION_CHARS)
        {
            for (cut = CAPTION_CHARS; cut > 0 && s[cut] != ' '; cut--)
                ;
            if (cut == 0)
            {
                /* no space: cut between two characters, not in one */
                cut = CAPTION_CHARS;
                while (cut > 1 && ((unsigned char) s[cut] & 0xc0) == 0x80)
                    cut--;
            }
        }
        if (out != NULL)
        {
            char line[CAPTION_CHARS + 1];

            memcpy(line, s, cut);
            line[cut] = '\0';
            fprintf(out, "<text class=\"caption\" x=\"%.1f\" y=\"%.1f\" "
                    "font-family=\"sans-serif\" font-size=\"12\">", MARGIN,
                    y + n * CAPTION_ROW);
            put_text(out, line);
            fputs("</text>\n", out);
        }
        n++;
        s += cut;
        while (*s == ' ')
            s++;
    }
    return n;
}

int
_wc_svg_fprint(FILE * out, const _wc_scene_t S, int standalone)
{
    double t[3], box[4], plane_bottom, legend_top, caption_top, height;
    slong i, columns = 2;

    _wc_svg_transform(t, S);
    _wc_scene_bbox(box, S);
    plane_bottom = t[1] - t[2] * box[1] + 20;
    legend_top = plane_bottom + 10;
    for (i = 0; i < S->nlegend; i++)
        if (strlen(S->legend[i].text) > 34)
            columns = 1;
    caption_top = legend_top + ((S->nlegend + columns - 1) / columns)
                  * LEGEND_ROW + 14;
    height = caption_top + caption_lines(NULL, S->caption, 0) * CAPTION_ROW
             + 10;
    if (standalone)
        fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", out);
    fprintf(out, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" "
            "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n", WIDTH,
            ceil(height), WIDTH, ceil(height));
    fputs("<title>", out);
    put_text(out, S->title != NULL ? S->title : "");
    fputs("</title>\n<desc>", out);
    put_text(out, S->caption != NULL ? S->caption : "");
    fputs("</desc>\n", out);
    fprintf(out, "<rect width=\"100%%\" height=\"100%%\" fill=\"#ffffff\"/>\n"
            "<text x=\"%.1f\" y=\"24\" font-family=\"sans-serif\" "
            "font-size=\"15\" font-weight=\"bold\">", MARGIN);
    put_text(out, S->title != NULL ? S->title : "");
    /* The map from the plane to pixels, for readers of the file.  */
    fprintf(out, "</text>\n<g class=\"plane\" data-x0=\"%.6f\" data-y0=\"%.6f\" "
            "data-scale=\"%.6f\">\n", t[0], t[1], t[2]);
    put_plane(out, S, t);
    fputs("</g>\n<g class=\"legend\">\n", out);
    for (i = 0; i < S->nlegend; i++)
    {
        double x = MARGIN + (i % columns) * (PLANE_W / 2);
        double y = legend_top + (i / columns) * LEGEND_ROW + 6;

        sample(out, S->legend + i, x, y);
        fprintf(out, "<text x=\"%.1f\" y=\"%.1f\" font-family=\"sans-serif\" "
                "font-size=\"12\">", x + 72, y + 4);
        put_text(out, S->legend[i].text);
        fputs("</text>\n", out);
    }
    fputs("</g>\n<g class=\"caption\">\n", out);
    caption_lines(out, S->caption, caption_top);
    fputs("</g>\n</svg>\n", out);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}
