/* cmd-draw.c -- wrenchcone draw: the paper's figures, as SVG, from exact
   results.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "draw/figure.h"

/* The figures.  */
enum { OPT_MODE = 1, OPT_MODES, OPT_STABILITY, OPT_PLAN, OPT_SWEEP,
       OPT_GRAPH };

/* The longest --sweep list: each value is a plan and a layer.  */
#define DRAW_MAX_SWEEP 12

typedef struct
{
    int kind;               /* OPT_MODE .. OPT_GRAPH, 0 for none */
    int kinds;              /* how many were given */
    const char * value;     /* --mode's or --sweep's */
    const char * output;
    const char * wrench;    /* --wrench's FX,FY,TAU */
}
draw_options;

/* --sweep's list into mu[0..*k), located as <sweep>:1:COL.  */
static int
parse_sweep(fmpq * mu, slong * k, const char * s, wc_error_t err)
{
    const char * p = s;
    int status = WC_OK;

    for (*k = 0; status == WC_OK; p++)
    {
        const char * e = strchr(p, ',');
        size_t len = e != NULL ? (size_t) (e - p) : strlen(p);

        if (*k == DRAW_MAX_SWEEP)
            return wc_error_set(err, WC_EINPUT, "<sweep>", 1, p - s + 1,
                                "at most %d friction values",
                                DRAW_MAX_SWEEP);
        if (wc_parse_number_bounded(mu + *k, p, len, err) != WC_OK)
        {
            char * why = wc_error_format(err);

            status = wc_error_set(err, WC_EINPUT, "<sweep>", 1, p - s + 1,
                                  "%s", why != NULL ? why : "bad number");
            free(why);
        }
        else if (fmpq_sgn(mu + *k) < 0)
            status = wc_error_set(err, WC_EINPUT, "<sweep>", 1, p - s + 1,
                                  "a friction coefficient must not be "
                                  "negative");
        ++*k;
        if (e == NULL)
            break;
        p = e;
    }
    return status;
}

/* --wrench's FX,FY,TAU into g[0..3), located as <wrench>:1:COL.  */
static int
parse_wrench(fmpq * g, const char * s, wc_error_t err)
{
    char * copy = malloc(strlen(s) + 1), * v[3], * p;
    int k, status;

    if (copy == NULL)
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    strcpy(copy, s);
    v[0] = copy;
    for (k = 1, p = copy; k < 3 && (p = strchr(p, ',')) != NULL; k++)
    {
        *p++ = '\0';
        v[k] = p;
    }
    if (k < 3 || strchr(v[2], ',') != NULL)
        status = wc_error_set(err, WC_EINPUT, "<wrench>", 1, 1,
                              "a wrench is three numbers FX,FY,TAU");
    else
        status = _wc_parse_numbers(g, (const char * const *) v, 3,
                                   "<wrench>", err);
    free(copy);
    return status;
}

static int
build(_wc_scene_t S, const draw_options * o, const _wc_input * in,
      wc_error_t err)
{
    fmpq mu[DRAW_MAX_SWEEP];
    wc_problem_t P;
    slong k = 0, i;
    int status;

    for (i = 0; i < DRAW_MAX_SWEEP; i++)
        fmpq_init(mu + i);
    wc_problem_init(P);
    status = _wc_load_problem(P, in, err);
    if (status == WC_OK && o->kind == OPT_SWEEP)
        status = parse_sweep(mu, &k, o->value, err);
    if (status == WC_OK && o->wrench != NULL)
        status = parse_wrench(mu, o->wrench, err);
    if (status == WC_OK)
        switch (o->kind)
        {
        case OPT_MODE:
            status = _wc_draw_mode(S, P, o->value, err);
            break;
        case OPT_MODES:
            status = _wc_draw_modes(S, P, err);
            break;
        case OPT_STABILITY:
            status = _wc_draw_stability(S, P, err);
            break;
        case OPT_PLAN:
            status = _wc_draw_plan(S, P, err);
            break;
        case OPT_SWEEP:
            status = _wc_draw_sweep(S, P, mu, k, err);
            break;
        default:
            status = _wc_draw_graph(S, P, o->wrench != NULL ? mu : NULL, err);
        }
    wc_problem_clear(P);
    for (i = 0; i < DRAW_MAX_SWEEP; i++)
        fmpq_clear(mu + i);
    return status;
}

static int
put_svg(FILE * f, const void * S)
{
    return _wc_svg_fprint(f, S, 1);
}

/* The figure that R asks for (cli_parse has checked that it asks for
   one).  */
static void
from_request(draw_options * o, const _wc_request * R)
{
    o->kind = R->mode != NULL ? OPT_MODE : R->fig_modes ? OPT_MODES
        : R->fig_stability ? OPT_STABILITY : R->fig_plan ? OPT_PLAN
        : R->sweep != NULL ? OPT_SWEEP : OPT_GRAPH;
    o->kinds = 1;
    o->value = R->mode != NULL ? R->mode : R->sweep;
    o->output = R->output;
    o->wrench = R->graph_wrench;
}

static int
run(const cli_command * self, int argc, char ** argv)
{
    draw_options o = { 0, 0, NULL, NULL, NULL };
    _wc_scene_t S;
    _wc_request R;
    wc_error_t err;
    int status;

    if ((status = cli_parse(&R, self, argc, argv)) >= 0)
        return cli_done(&R, status);
    from_request(&o, &R);
    wc_error_init(err);
    _wc_scene_init(S);
    status = build(S, &o, &R.problem, err);
    if (status != WC_OK)
        cli_report(err, status);
    else if (o.output != NULL && strcmp(o.output, "-") != 0)
        status = cli_write_whole(o.output, "figure", put_svg, S);
    else
    {
        _wc_svg_fprint(stdout, S, 1);
        status = cli_finish_output();
    }
    _wc_scene_clear(S);
    wc_error_clear(err);
    return cli_done(&R, status);
}

int
cmd_draw(const cli_command * self, int argc, char ** argv)
{
    return cli_run_with_output(run, self, argc, argv);
}
