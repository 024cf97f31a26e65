/* scene.h -- a figure as a list of floating-point primitives with
   semantic tags (wrenchcone(1), draw), and its SVG writer.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Floating point is allowed in drawings, and only there.  A figure is
   built from exact results: every position that is rational (a vertex,
   an end of a pushing region, a point on a line of force, a rotation
   centre) is computed in exact arithmetic and converted to double once,
   when its primitive is added; only directions are normalised in
   doubles.  Nothing drawn decides anything.

   Coordinates are those of the part's plane (y up); the SVG writer maps
   them to pixels.  Internal: the functions are _wc_*.  */

#ifndef WC_DRAW_SCENE_H
#define WC_DRAW_SCENE_H

#include <stdarg.h>
#include <stdio.h>

#include <flint/flint.h>
#include <flint/fmpq.h>

#include "core/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* pi, for angles (C11 has no M_PI).  */
#define _WC_PI 3.14159265358979323846

/* What a primitive means; the SVG writer styles by it (dash patterns and
   widths as well as greys, so that a figure prints in grey).  */
typedef enum
{
    _WC_TAG_PART = 0,       /* the part's outline */
    _WC_TAG_FRAME,          /* no shape: a neutral frame round the fixels */
    _WC_TAG_COM,            /* the centre of mass */
    _WC_TAG_TOUCHING,       /* a touching fixel */
    _WC_TAG_NEAR,           /* a fixel about to touch */
    _WC_TAG_NORMAL,         /* a fixel's inward normal */
    _WC_TAG_FRICTION,       /* an edge of a static friction cone */
    _WC_TAG_FRICTION_K,     /* an edge of a kinetic one, when it differs */
    _WC_TAG_FORCE_IN,       /* a generator's line of force, in the cone */
    _WC_TAG_FORCE_OUT,      /* ... of the closure only (excluded) */
    _WC_TAG_TORQUE_IN,      /* a pure torque, as an arc about o */
    _WC_TAG_TORQUE_OUT,
    _WC_TAG_REGION,         /* a pushing region (layer: which set) */
    _WC_TAG_END_CLOSED,     /* a region's end that belongs to it */
    _WC_TAG_END_OPEN,       /* ... that does not */
    _WC_TAG_CENTRE,         /* a mode's rotation centre */
    _WC_TAG_TRANSLATION,    /* a mode's translation */
    _WC_TAG_NODE,           /* a contact state of a plan */
    _WC_TAG_GOAL,           /* the goal state */
    _WC_TAG_EDGE_PROGRESS,  /* a transition the plan allows */
    _WC_TAG_EDGE_FORBIDDEN, /* a transition the plan forbids */
    _WC_TAG_EDGE_ADMITTED,  /* a transition a wrench admits */
    _WC_TAG_LABEL,          /* text */
    _WC_TAG_COUNT
}
_wc_draw_tag;

typedef enum
{
    _WC_PRIM_LINE = 0,      /* a polyline through pts (closed: a polygon) */
    _WC_PRIM_ARROW,         /* from pts[0..1] to pts[2..3], head at the end */
    _WC_PRIM_ARC,           /* centre (x, y), radius r, counter-clockwise
                               from angle a0 to a1 (radians, a0 <= a1) */
    _WC_PRIM_CIRCLE,        /* centre (x, y), radius r (plane units) */
    _WC_PRIM_DOT,           /* a marker at (x, y), a fixed size in pixels */
    _WC_PRIM_TEXT           /* text at (x, y), moved (dx, dy) pixels */
}
_wc_draw_kind;

typedef struct
{
    _wc_draw_kind kind;
    _wc_draw_tag tag;
    int layer;              /* regions: the set (0, 1, ...) */
    int closed;             /* lines: closed; arcs: clockwise (the
                               head at a0); text: the writer may move it
                               off other labels and markers */
    slong npts;
    double * pts;           /* x0 y0 x1 y1 ... */
    double x, y, r, a0, a1;
    double dx, dy;
    int anchor;             /* text: -1 start, 0 middle, 1 end */
    char * text;
}
_wc_prim_struct;

/* A figure: the primitives in drawing order, a legend (one entry per
   tag and layer shown, with its words), a title and a caption.  */
typedef struct
{
    _wc_draw_tag tag;
    int layer;
    char * text;
}
_wc_legend_struct;

typedef struct
{
    slong count, alloc;
    _wc_prim_struct * prims;
    slong nlegend;
    _wc_legend_struct * legend;
    char * title;
    char * caption;
    double scale;           /* the figure's size in plane units (the
                               larger side of the part's bounding box) */
    int nlayers;            /* region layers drawn */
}
_wc_scene_struct;

typedef _wc_scene_struct _wc_scene_t[1];

void _wc_scene_init(_wc_scene_t S);
void _wc_scene_clear(_wc_scene_t S);

/* Append a primitive of kind and tag, zeroed, and return it (NULL when
   out of memory).  The pointer is valid until the next append.  */
_wc_prim_struct * _wc_scene_add(_wc_scene_t S, _wc_draw_kind kind,
                                _wc_draw_tag tag);

/* Shorthands; each returns WC_OK or WC_EINTERNAL (out of memory).  */
int _wc_scene_line(_wc_scene_t S, _wc_draw_tag tag, int layer,
                   double x0, double y0, double x1, double y1);
int _wc_scene_arrow(_wc_scene_t S, _wc_draw_tag tag,
                    double x0, double y0, double x1, double y1);
int _wc_scene_arc(_wc_scene_t S, _wc_draw_tag tag, int layer, double x,
                  double y, double r, double a0, double a1);
int _wc_scene_dot(_wc_scene_t S, _wc_draw_tag tag, int layer, double x,
                  double y);
int _wc_scene_text(_wc_scene_t S, double x, double y, double dx, double dy,
                   int anchor, const char * text);
/* A polyline of n points xy[0..2n) (closed: a polygon).  */
int _wc_scene_poly(_wc_scene_t S, _wc_draw_tag tag, int closed,
                   const double * xy, slong n);

/* A legend entry (once per tag and layer), the title, the caption
   (copied; printf formats).  */
int _wc_scene_legend(_wc_scene_t S, _wc_draw_tag tag, int layer,
                     const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 4, 5)))
#endif
    ;
int _wc_scene_title(_wc_scene_t S, const char * text);
int _wc_scene_caption(_wc_scene_t S, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* The caption: head (as it is), then fmt formatted with ap.  */
int _wc_scene_vcaption(_wc_scene_t S, const char * head, const char * fmt,
                       va_list ap)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 0)))
#endif
    ;

/* s[0..len) as XML character data or an attribute's value: & < > and "
   as entities, tab, newline and CR as they are, valid UTF-8 as it is, and
   any other control byte, DEL and each byte that is not part of valid
   UTF-8 as the text \xNN, so that whatever s holds (a problem's path,
   say) the document stays well-formed UTF-8.  The one text writer of
   the SVG and the HTML report.  */
void _wc_svg_put_text(FILE * out, const char * s, size_t len);

/* A malloc'd decimal string of x ("1/5" as "1/5"), or NULL.  */
char * _wc_draw_fmpq_str(const fmpq_t x);

/* The bounding box of the scene's geometry (text excluded): box[0..4) =
   xmin ymin xmax ymax; a unit box round the origin when it is empty.  */
void _wc_scene_bbox(double * box, const _wc_scene_t S);

/* The map from the plane to the SVG's pixels that _wc_svg_fprint uses:
   px = t[0] + t[2] x, py = t[1] - t[2] y.  */
void _wc_svg_transform(double * t, const _wc_scene_t S);

/* Write S as an SVG document to out (the caller owns the stream):
   standalone, with its XML declaration; else an <svg> element to be
   put inline in HTML.  Positions are printed with 3 decimals, so that
   the same scene gives the same bytes.  Returns WC_OK or WC_EINTERNAL
   on a write error.  */
int _wc_svg_fprint(FILE * out, const _wc_scene_t S, int standalone);

#ifdef __cplusplus
}
#endif

#endif
