/* report.c -- every analysis of a problem on one self-contained HTML
   page, figures inline (figure.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The page is also well-formed XML (XHTML syntax), so that XML tools can
   read it; it fetches nothing and runs no script.  An analysis the
   problem is too large for is named, with the limit's message, and the
   others go on.  Floating point appears only in the decimal
   approximations and angles the page marks as such.  */

#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "draw/figure.h"
#include "draw/scene.h"
#include "io/print.h"
#include "analysis/plan.h"
#include "analysis/stability.h"
#include "core/version.h"

static const char style[] =
    "body { font-family: sans-serif; max-width: 52em; margin: 1em auto; "
    "padding: 0 1em; color: #000; background: #fff; line-height: 1.4; }\n"
    "h1 { font-size: 1.5em; } h2 { font-size: 1.25em; border-bottom: 1px "
    "solid #888; margin-top: 2em; }\n"
    "pre { background: #f4f4f4; border: 1px solid #ccc; padding: 0.5em; "
    "overflow-x: auto; font-size: 0.85em; }\n"
    "figure { margin: 1em 0; } figure svg { max-width: 100%; height: auto; }\n"
    "table { border-collapse: collapse; margin: 0.5em 0; } "
    "td, th { border: 1px solid #999; padding: 0.2em 0.5em; text-align: left; }\n"
    "code { background: #f4f4f4; } .note { font-style: italic; }\n"
    "@media print { body { max-width: none; } pre { white-space: pre-wrap; "
    "font-size: 8pt; } figure { break-inside: avoid; } h2 { "
    "break-after: avoid; } }\n";

static void
escape0(FILE * out, const char * s)
{
    _wc_svg_put_text(out, s, strlen(s));
}

/* What a printer writes as o says, escaped, in a <pre>.  */
typedef int (* printer)(FILE *, const void *, const wc_print_opts *);

static int
pre(FILE * out, printer p, const void * data, const wc_print_opts * o)
{
    char * buf = NULL;
    size_t len = 0;
    FILE * m = open_memstream(&buf, &len);
    int status;

    if (m == NULL)
        return WC_EINTERNAL;
    status = p(m, data, o);
    if (fclose(m) != 0 && status == WC_OK)
        status = WC_EINTERNAL;
    if (status == WC_OK)
    {
        fputs("<pre>", out);
        _wc_svg_put_text(out, buf, len);
        fputs("</pre>\n", out);
    }
    free(buf);
    return status;
}

/* "Reproduce with" and the command line.  */
static void
command(FILE * out, const char * args, const char * path)
{
    fputs("<p>Reproduce: <code>wrenchcone ", out);
    escape0(out, args);
    putc(' ', out);
    escape0(out, path);
    fputs("</code></p>\n", out);
}

/* An error the problem caused (a limit): said on the page, not fatal.  */
static int
note(FILE * out, int status, wc_error_t err, const char * what)
{
    char * msg;

    if (status != WC_EINPUT)
        return status;
    msg = wc_error_format(err);
    fprintf(out, "<p class=\"note\">%s: not computed for this problem (",
            what);
    escape0(out, msg != NULL ? msg : "bad input");
    fputs(").</p>\n", out);
    free(msg);
    wc_error_clear(err);
    wc_error_init(err);
    return WC_OK;
}

typedef enum { FIG_MODES, FIG_STABILITY, FIG_PLAN, FIG_GRAPH } fig_kind;

static int
figure(FILE * out, fig_kind kind, const wc_problem_t P, wc_error_t err)
{
    _wc_scene_t S;
    int status;

    _wc_scene_init(S);
    status = kind == FIG_MODES ? _wc_draw_modes(S, P, err)
             : kind == FIG_STABILITY ? _wc_draw_stability(S, P, err)
             : kind == FIG_PLAN ? _wc_draw_plan(S, P, err)
             : _wc_draw_graph(S, P, NULL, err);
    if (status == WC_OK)
    {
        fputs("<figure>\n", out);
        status = _wc_svg_fprint(out, S, 0);
        fputs("</figure>\n", out);
    }
    _wc_scene_clear(S);
    return note(out, status, err, "The figure");
}

static void
number(FILE * out, const fmpq_t x)
{
    fmpq_fprint(out, x);
    fprintf(out, " (&#8776; %.6g)", fmpq_get_d(x));
}

static void
direction(FILE * out, const fmpz * d)
{
    double a = atan2(fmpz_get_d(d + 1), fmpz_get_d(d + 0)) * 180 / 3.14159265358979323846;

    fputc('(', out);
    fmpz_fprint(out, d + 0);
    fputs(", ", out);
    fmpz_fprint(out, d + 1);
    fprintf(out, ") (&#8776; %.4g&#176;)", a < 0 ? a + 360 : a);
}

/* A pushing region as a table: exact ends, decimals marked as such.  */
static void
push_table(FILE * out, const wc_push_t R, const char * what)
{
    slong i;

    fprintf(out, "<p><b>%s</b></p>\n<table>\n", what);
    if (R->count == 0)
        fputs("<tr><td>nowhere</td></tr>\n", out);
    else if (R->kind == WC_SHAPE_POLYGON)
        fputs("<tr><th>edge</th><th>from s =</th><th>to s =</th></tr>\n",
              out);
    else
        fputs("<tr><th>arc</th><th>from direction</th>"
              "<th>counter-clockwise to</th></tr>\n", out);
    for (i = 0; i < R->count; i++)
    {
        const wc_push_interval_struct * iv = R->iv + i;

        if (R->kind == WC_SHAPE_POLYGON)
        {
            fprintf(out, "<tr><td>%ld</td><td>%s ", (long) iv->edge + 1,
                    iv->from_closed ? "[" : "(");
            number(out, iv->from);
            fputs("</td><td>", out);
            number(out, iv->to);
            fprintf(out, " %s</td></tr>\n", iv->to_closed ? "]" : ")");
        }
        else if (iv->full)
            fputs("<tr><td colspan=\"3\">the whole circle</td></tr>\n", out);
        else
        {
            fprintf(out, "<tr><td>%ld</td><td>%s ", (long) i + 1,
                    iv->from_closed ? "[" : "(");
            direction(out, iv->dfrom);
            fputs("</td><td>", out);
            direction(out, iv->dto);
            fprintf(out, " %s</td></tr>\n", iv->to_closed ? "]" : ")");
        }
    }
    fputs("</table>\n", out);
}

static int
put_problem(FILE * f, const void * P, const wc_print_opts * o)
{
    (void) o;
    return wc_problem_fprint(f, P);
}

static int
put_modes(FILE * f, const void * M, const wc_print_opts * o)
{
    return wc_modes_fprint(f, M, 1, o);
}

static int
put_stability(FILE * f, const void * S, const wc_print_opts * o)
{
    return wc_stability_fprint(f, S, NULL, o);
}

typedef struct
{
    const wc_plan_struct * R;
    const wc_problem_struct * P;
}
plan_job;

static int
put_plan(FILE * f, const void * j, const wc_print_opts * o)
{
    const plan_job * p = j;

    return wc_plan_fprint(f, p->R, p->P, o);
}

/* A section's end: the answer (put(data), as o says) when status is
   WC_OK, the commands that reproduce it (the NULL ones left out), and
   the note when the problem made it fail.  */
static int
section_end(FILE * out, int status, printer put, const void * data,
            const wc_print_opts * o, const char * const cmds[3],
            const char * path, wc_error_t err, const char * what)
{
    int k;

    if (status == WC_OK)
        status = pre(out, put, data, o);
    for (k = 0; k < 3; k++)
        if (cmds[k] != NULL)
            command(out, cmds[k], path);
    return note(out, status, err, what);
}

static int
section_modes(FILE * out, const wc_problem_t P, const char * path,
              const wc_print_opts * o, wc_error_t err)
{
    static const char * const cmds[3] = { "modes --witness",
                                          "draw --modes -o modes.svg", NULL };
    wc_modes_t M;
    int status;

    fputs("<h2>Feasible contact modes</h2>\n<p>Every kinematically "
          "feasible mode (paper Table 1), each with a witness twist "
          "(vx, vy, w) of the centre of mass; the figure puts each at the "
          "centre its twist turns about.</p>\n", out);
    wc_modes_init(M);
    status = wc_modes_enumerate(M, P, err);
    if (status == WC_OK)
        status = figure(out, FIG_MODES, P, err);
    status = section_end(out, status, put_modes, M, o, cmds, path, err,
                         "The modes");
    wc_modes_clear(M);
    return status;
}

static int
section_stability(FILE * out, const wc_problem_t P, const char * path,
                  const wc_print_opts * o, wc_error_t err)
{
    static const char * const cmds[3] = {
        "stability", "draw --stability -o stability.svg", NULL };
    wc_stability_t T;
    int status;

    fputs("<h2>Stability</h2>\n<p>The weakly stable wrenches (a static "
          "solution exists) and the strongly stable ones under the exact "
          "semantics (weakly stable, and no solution moves) and the paper's "
          "(eq. 19); the two strong sets differ in general.  With a shape, "
          "the places where a frictionless finger may push.</p>\n", out);
    wc_stability_init(T);
    status = wc_stability(T, P, err);
    if (status == WC_OK)
        status = figure(out, FIG_STABILITY, P, err);
    if (status == WC_OK && T->has_push)
    {
        push_table(out, T->push_strong, "Pushing region: strongly stable, "
                   "exact semantics");
        push_table(out, T->push_strong_paper, "Pushing region: strongly "
                   "stable, paper semantics (eq. 19)");
        push_table(out, T->push_weak, "Pushing region: weakly stable");
    }
    status = section_end(out, status, put_stability, T, o, cmds, path, err,
                         "The stability sets");
    wc_stability_clear(T);
    return status;
}

static int
section_plan(FILE * out, const wc_problem_t P, const char * path,
             const wc_print_opts * o, wc_error_t err)
{
    const char * const cmds[3] = {
        "plan", "draw --plan -o goal.svg",
        P->n <= _WC_DRAW_GRAPH_MAX_FIXELS ? "draw --graph -o graph.svg" : NULL
    };
    plan_job j = { NULL, P };
    wc_plan_t R;
    int status;

    fputs("<h2>Insertion plan</h2>\n<p>The wrenches G_goal that seat the "
          "part against every fixel from any contact state (eq. 21), the "
          "strings whose cones it avoids, and eq. 25: whether G_goal lies "
          "in the strongly stable set of the goal state.</p>\n", out);
    wc_plan_init(R);
    status = wc_plan(R, P, 0, err);
    if (status == WC_OK)
        status = figure(out, FIG_PLAN, P, err);
    if (status == WC_OK && R->has_push)
        push_table(out, R->push_goal, "Pushing region: G_goal");
    if (status == WC_OK && P->n <= _WC_DRAW_GRAPH_MAX_FIXELS)
        status = figure(out, FIG_GRAPH, P, err);
    j.R = R;
    status = section_end(out, status, put_plan, &j, o, cmds, path, err,
                         "The insertion plan");
    wc_plan_clear(R);
    return status;
}

int
_wc_report_fprint(FILE * out, const wc_problem_t P, const char * path,
                  const wc_print_opts * o, wc_error_t err)
{
    const char * name = _wc_draw_name(P);
    int status;

    fputs("<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" "
          "lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>", out);
    escape0(out, name);
    fprintf(out, " &#8212; wrenchcone report</title>\n<style>\n%s</style>\n"
            "</head>\n<body>\n<h1>", style);
    escape0(out, name);
    fprintf(out, "</h1>\n<p>A report by wrenchcone %s. Every result is exact "
            "(rational arithmetic); a decimal marked &#8776; is an "
            "approximation, for reading only, and the figures are drawn in "
            "floating point from the exact results.</p>\n", wc_version());
    fputs("<h2>The problem</h2>\n", out);
    status = pre(out, put_problem, P, o);
    command(out, "report -o report.html", path);
    if (status == WC_OK)
        status = section_modes(out, P, path, o, err);
    if (status == WC_OK)
        status = section_stability(out, P, path, o, err);
    if (status == WC_OK)
        status = section_plan(out, P, path, o, err);
    fputs("</body>\n</html>\n", out);
    if (status == WC_OK && ferror(out))
        status = WC_EINTERNAL;
    return status;
}

typedef struct
{
    const char * buf;
    size_t len;
}
bytes;

