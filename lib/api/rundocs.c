/* rundocs.c -- the rows of _wc_runners for the commands whose answer is
   a document: verify (its report), random (a problem file), draw (an SVG
   figure), report (an HTML page) (run.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Each is computed whole into memory; the command line prints it as it
   is (or writes it to -o FILE), and its JSON answer carries it as a
   string: {"problem_text": ...}, {"svg": ...}, {"html": ...}, or verify's
   own JSON report.  */

#include <config.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "api/runners.h"
#include "check/verify.h"
#include "core/random.h"
#include "core/version.h"
#include "draw/figure.h"
#include "draw/scene.h"
#include "io/print.h"

static void
text_init(_wc_answer * A)
{
    A->u.text.text = NULL;
    A->u.text.len = 0;
    A->u.text.holds = 0;
}

static void
text_clear(_wc_answer * A)
{
    free(A->u.text.text);
}

/* The document as it is.  */
static int
text_print(FILE * out, const _wc_answer * A)
{
    return fwrite(A->u.text.text, 1, A->u.text.len, out) == A->u.text.len
        ? WC_OK : WC_EINTERNAL;
}

/* The document as the one member key of a JSON answer.  */
static int
text_json_as(FILE * out, const _wc_answer * A, const char * key)
{
    fprintf(out, WC_JSON_OPEN "\"%s\": ", key);
    wc_fprint_json_string(out, A->u.text.text);
    fputs("}\n", out);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

/* A memory stream the document is written to.  */
typedef struct
{
    FILE * f;
    char * buf;
    size_t size;
}
sink;

static int
sink_open(sink * s, wc_error_t err)
{
    s->buf = NULL;
    s->size = 0;
    s->f = open_memstream(&s->buf, &s->size);
    return s->f != NULL ? WC_OK
        : wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
}

/* Close s; on success the document is A's.  */
static int
sink_close(sink * s, _wc_answer * A, int status, wc_error_t err)
{
    if (fclose(s->f) != 0 && status == WC_OK)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    if (status == WC_OK)
    {
        A->u.text.text = s->buf;
        A->u.text.len = s->size;
    }
    else
        free(s->buf);
    return status;
}

/* verify: the report in JSON for a request or --format=json, else in
   text; its verdict is the answer's status.  */

static int
verify_run(_wc_answer * A, wc_error_t err)
{
    const _wc_request * R = A->R;
    char * cert = NULL;
    size_t len = 0;
    sink s;
    int status = _wc_input_read_max(&cert, &len, &R->cert,
                                    WC_CERT_MAX_BYTES, err);

    if (status == WC_OK && (status = sink_open(&s, err)) == WC_OK)
    {
        status = wc_verify_fprint(s.f, &A->u.text.holds, cert, len,
                                  R->cert.name, R->from_request
                                  || R->format == 1, err);
        status = sink_close(&s, A, status, err);
    }
    free(cert);
    return status;
}

const _wc_runner _wc_run_verify = {
    text_init, text_clear, verify_run, text_print, text_print, NULL
};

/* random */

/* MU or MU,MUK: exact non-negative numbers.  */
static int
random_friction(wc_random_options * ro, const char * s, wc_error_t err)
{
    fmpq * v = NULL;
    slong n = 0;
    int ok = wc_parse_number_list(&v, &n, s, 2, NULL, "mu", "<friction>",
                                  err) == WC_OK;

    if (ok)
    {
        fmpq_set(ro->mu_s, v);
        fmpq_set(ro->mu_k, v + (n - 1));
        ro->friction = 1;
    }
    wc_number_list_clear(v, n);
    return ok;
}

static int
random_run(_wc_answer * A, wc_error_t err)
{
    static const wc_shape_kind shapes[3] = {
        WC_SHAPE_NONE, WC_SHAPE_DISK, WC_SHAPE_POLYGON
    };
    const _wc_request * R = A->R;
    wc_random_options ro;
    char * line = NULL;
    sink s;
    int status = WC_OK;

    wc_random_options_init(&ro);
    ro.fixels = (slong) R->fixels;
    ro.seed = (uint64_t) R->seed;
    ro.degenerate = R->degenerate;
    ro.shape = shapes[R->shape];
    if (R->friction != NULL && !random_friction(&ro, R->friction, err))
        status = wc_error_set(err, WC_EUSAGE, NULL, 0, 0, "%s must be MU or "
                              "MU,MUK, exact non-negative numbers such as "
                              "1/5 or 0.2, not '%s'", R->from_request
                              ? "\"friction\"" : "--friction", R->friction);
    if (status == WC_OK)
        status = wc_random_problem(A->P, &ro, err);
    if (status == WC_OK && (line = wc_random_options_str(&ro)) == NULL)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    if (status == WC_OK && (status = sink_open(&s, err)) == WC_OK)
    {
        fprintf(s.f, "# wrenchcone random %s\n", line);
        status = wc_problem_fprint(s.f, A->P);
        status = sink_close(&s, A, status, err);
    }
    free(line);
    wc_random_options_clear(&ro);
    return status;
}

static int
random_json(FILE * out, const _wc_answer * A)
{
    return text_json_as(out, A, "problem_text");
}

const _wc_runner _wc_run_random = {
    text_init, text_clear, random_run, random_json, text_print, NULL
};

/* draw */

static int
draw_scene(_wc_scene_t S, const _wc_request * R, const wc_problem_t P,
           wc_error_t err)
{
    fmpq * mu = NULL, g[3];
    slong k = 0;
    int i, status = WC_OK;

    for (i = 0; i < 3; i++)
        fmpq_init(g + i);
    if (R->sweep != NULL)
        status = wc_parse_number_list(&mu, &k, R->sweep, _WC_DRAW_MAX_SWEEP,
                                      NULL, "a friction coefficient",
                                      "<sweep>", err);
    if (status == WC_OK && R->graph_wrench != NULL)
    {
        fmpq * v = NULL;
        slong n = 0;

        status = wc_parse_number_list(&v, &n, R->graph_wrench, 3, NULL, NULL,
                                      "<wrench>", err);
        if (status == WC_OK && n != 3)
            status = wc_error_set(err, WC_EINPUT, "<wrench>", 1, 1,
                                  "a wrench is three numbers FX,FY,TAU");
        for (i = 0; status == WC_OK && i < 3; i++)
            fmpq_set(g + i, v + i);
        wc_number_list_clear(v, n);
    }
    if (status == WC_OK)
        status = R->mode != NULL ? _wc_draw_mode(S, P, R->mode, err)
            : R->fig_modes ? _wc_draw_modes(S, P, err)
            : R->fig_stability ? _wc_draw_stability(S, P, err)
            : R->fig_plan ? _wc_draw_plan(S, P, err)
            : R->sweep != NULL ? _wc_draw_sweep(S, P, mu, k, err)
            : _wc_draw_graph(S, P, R->graph_wrench != NULL ? g : NULL, err);
    wc_number_list_clear(mu, k);
    for (i = 0; i < 3; i++)
        fmpq_clear(g + i);
    return status;
}

static int
draw_run(_wc_answer * A, wc_error_t err)
{
    _wc_scene_t S;
    sink s;
    int status = _wc_load_problem(A->P, &A->R->problem, err);

    _wc_scene_init(S);
    if (status == WC_OK)
        status = draw_scene(S, A->R, A->P, err);
    if (status == WC_OK && (status = sink_open(&s, err)) == WC_OK)
    {
        status = _wc_svg_fprint(s.f, S, 1);
        status = sink_close(&s, A, status, err);
    }
    _wc_scene_clear(S);
    return status;
}

static int
draw_json(FILE * out, const _wc_answer * A)
{
    return text_json_as(out, A, "svg");
}

const _wc_runner _wc_run_draw = {
    text_init, text_clear, draw_run, draw_json, text_print, NULL
};

/* report */

static int
report_run(_wc_answer * A, wc_error_t err)
{
    const _wc_input * in = &A->R->problem;
    wc_print_opts o = _wc_answer_opts(A, WC_FORMAT_TEXT);
    sink s;
    int status = _wc_load_problem(A->P, in, err);

    if (status == WC_OK && (status = sink_open(&s, err)) == WC_OK)
    {
        status = _wc_report_fprint(s.f, A->P, in->stream != NULL ? "-"
                                   : in->text != NULL ? in->name : in->path,
                                   &o, err);
        status = sink_close(&s, A, status, err);
    }
    return status;
}

static int
report_json(FILE * out, const _wc_answer * A)
{
    return text_json_as(out, A, "html");
}

const _wc_runner _wc_run_report = {
    text_init, text_clear, report_run, report_json, text_print, NULL
};
