/* run.h -- one computing command, from its parsed arguments to its
   answer and the answer's JSON: the code that `wrenchcone COMMAND
   --format=json`, `wrenchcone batch` and wc_request_json share, so that
   their outputs cannot drift apart.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  The command line fills a _wc_request from
   its options and operands, the request reader (request.c) from a JSON
   request; both then call _wc_run, which reads the inputs, checks and
   computes in the order the command line always has (so the first error
   is the same), and _wc_answer_fprint_json, which writes exactly what
   `COMMAND --format=json` prints.  */

#ifndef WC_API_RUN_H
#define WC_API_RUN_H

#include <stdio.h>

#include "core/problem.h"
#include "core/limits.h"
#include "core/readall.h"
#include "exact/cone.h"
#include "analysis/wrench.h"
#include "analysis/kinematics.h"
#include "analysis/stability.h"
#include "analysis/plan.h"
#include "analysis/sweep.h"
#include "float/floatcone.h"
#include "float/compare.h"
#include "io/answerprint.h"

/* The commands, in the order of the schema's table (schema.c).  */
typedef enum
{
    _WC_CONE = 0,
    _WC_MODES,
    _WC_FEASIBLE,
    _WC_CLASSIFY,
    _WC_STABILITY,
    _WC_PLAN,
    _WC_SWEEP,
    _WC_VERIFY,
    _WC_COMPARE,
    _WC_RANDOM,
    _WC_DRAW,
    _WC_REPORT,
    _WC_BATCH,
    _WC_NCOMMANDS
}
_wc_command;

/* The command's name, "cone" ... "batch"; -1 from _wc_command_find
   when name is none of them.  */
const char * _wc_command_name(_wc_command c);
int _wc_command_find(const char * name);

/* One input text: read from stream when it is not NULL (the command line
   passes stdin for "-"), else from the file path when text is NULL, else
   text[0..len) itself.  name is how errors and reports name it (the
   path, "<stdin>", "<problem_text>").  A path is opened by
   _wc_read_file with flags (_WC_READ_REGULAR for a request's) and
   avoid (a batch's own input, or NULL).  */
typedef struct
{
    const char * name;
    const char * path;
    FILE * stream;
    const char * text;
    size_t len;
    int flags;
    const _wc_file_id * avoid;
}
_wc_input;

/* wc_request_json_at (api/request.h), except that no input the request
   names may be the file avoid names (a batch's own input; NULL: none):
   wc_batch's way (request.c).  */
int _wc_request_json_avoid(char ** out, size_t * outlen,
                           const char * request, size_t len,
                           const char * file, long line,
                           const _wc_file_id * avoid, wc_error_t err);

/* Three numbers FX, FY, TAU as written; given: whether they were.  */
typedef struct
{
    int given;
    const char * v[3];
}
_wc_triple;

/* A command's arguments, every command's in one record: the schema's rows
   (schema.c) name the field each operand and option is read into.
   Numbers are kept as written, read (and their errors located,
   "<wrench>:1:COL") when the command needs them, after the problem, as on
   the command line.  */
typedef struct _wc_request_struct
{
    _wc_command command;
    int from_request;           /* read from a JSON request, not argv */
    int format;                 /* the command line's --format (cli.h) */
    int decimals;               /* the command line's --decimals=K for
                                   text (print.h), -1 without */
    _wc_input problem;
    const char * mode;          /* cone, feasible, compare; draw --mode */
    int method;                 /* cone: a wc_method */
    int trace;                  /* cone */
    int arith_double;           /* cone: --arith=double (with paper) */
    int all_modes;              /* cone */
    int witness;                /* modes */
    long max_modes;             /* classify: 0 is no limit */
    const char * certificate;   /* the command line's --certificate=FILE */
    int want_certificate;       /* a request's "certificate": true */
    int certificates;           /* classify computes the certificates'
                                   data, plan checks the fixel limit of
                                   a plan certificate first */
    int complete;               /* plan */
    _wc_triple wrench;          /* classify, plan; draw --wrench */
    _wc_triple bias;            /* stability --bias */
    const char * length;        /* stability --length, or NULL */
    _wc_input foreign;          /* compare's FILE */
    double tol;                 /* compare */
    _wc_input cert;             /* verify's CERTFILE */
    const char * friction;      /* sweep --friction=LIST; random MU[,MUK] */
    int critical;               /* sweep */
    const char * width;         /* sweep */
    const char * max_friction;  /* sweep */
    long fixels;                /* random */
    unsigned long long seed;    /* random */
    int degenerate;             /* random */
    int shape;                  /* random: none, disk, polygon */
    int fig_modes, fig_stability, fig_plan, fig_graph;  /* draw */
    const char * sweep;         /* draw --sweep=LIST */
    const char * graph_wrench;  /* draw --wrench=FX,FY,TAU, as written */
    const char * output;        /* draw, report: -o FILE */
    const char * batch;         /* batch's FILE, "-" by default */
    long jobs;                  /* batch --jobs */
    char * owned[8];            /* copies this record owns: FX,FY,TAU
                                   cut, names, standard input's text */
}
_wc_request;

/* Defaults: every option as the command line has it without options (the
   schema's defaults).  */
void _wc_request_init(_wc_request * R, _wc_command c);

/* Free what R owns (the split copies of FX,FY,TAU values).  */
void _wc_request_clear(_wc_request * R);

/* What each command computes: its member of _wc_answer's union, and
   nothing of the others'.  */
typedef struct
{
    wc_cone_t W;
    wc_trace_t T;
    wc_fcone_t F;               /* --arith=double */
}
_wc_cone_answer;

typedef struct
{
    fmpq g[3];                  /* the wrench */
    wc_classify_t K;
}
_wc_classify_answer;

typedef struct
{
    wc_stability_t S;
    _wc_bias bias;              /* --bias's robustness, --length */
}
_wc_stability_answer;

typedef struct
{
    fmpq g[3];                  /* the wrench, when given */
    wc_plan_t plan;
    wc_plan_wrench_t pw;
}
_wc_plan_answer;

typedef struct
{
    wc_cone_t W;
    wc_comparison_t cmp;
}
_wc_compare_answer;

/* A document computed whole (verify's report, random's problem, draw's
   SVG, report's HTML): text[0..len), malloc'd; holds: verify's
   verdict.  */
typedef struct
{
    char * text;
    size_t len;
    int holds;
}
_wc_text_answer;

/* The answer of one request.  */
typedef struct _wc_answer_struct
{
    _wc_command command;
    const _wc_request * R;      /* the request answered (not owned) */
    wc_problem_t P;             /* its problem, when it has one */
    union
    {
        _wc_cone_answer cone;
        wc_modes_t modes;
        wc_certificate_t feasible;
        _wc_classify_answer classify;
        _wc_stability_answer stability;
        _wc_plan_answer plan;
        wc_sweep_t sweep;
        _wc_compare_answer compare;
        _wc_text_answer text;
    }
    u;
}
_wc_answer;

/* A command's behaviour: its answer's init and clear, computing it, and
   writing it.  One row per command, in the schema's order (runs.c).  */
typedef struct
{
    void (*init)(_wc_answer * A);
    void (*clear)(_wc_answer * A);
    int (*run)(_wc_answer * A, wc_error_t err);
    /* The answer as `COMMAND --format=json` prints it: one line.  */
    int (*json)(FILE * out, const _wc_answer * A);
    /* The command line's other formats (R->format: text, cdd ...).  */
    int (*print)(FILE * out, const _wc_answer * A);
    /* The certificate document that --certificate=FILE writes (NULL:
       the command has none); WC_EINTERNAL with err set when a proof
       fails.  */
    int (*certificate)(FILE * out, const _wc_answer * A, wc_error_t err);
}
_wc_runner;

/* The rows, indexed by _wc_command; NULL for batch, which is not a
   request.  */
extern const _wc_runner * const _wc_runners[_WC_NCOMMANDS];

/* A for R (R must outlive A): only R's command's member initialised.  */
void _wc_answer_init(_wc_answer * A, const _wc_request * R);
void _wc_answer_clear(_wc_answer * A);

/* Answer A->R into A (freshly initialised).  Returns WC_OK, or WC_EINPUT
   / WC_EINTERNAL with err set as the command line reports it.  A
   comparison that finds a difference, or a certificate that does not
   hold, is WC_OK here: _wc_answer_status says WC_EDISAGREE.  */
int _wc_run(_wc_answer * A, wc_error_t err);

/* The status of a computed answer: WC_EDISAGREE for a comparison beyond
   its tolerance or a certificate that does not hold, else WC_OK.  */
int _wc_answer_status(const _wc_answer * A);

/* How A is printed in format f (a wc_format): A->R's decimals.  */
wc_print_opts _wc_answer_opts(const _wc_answer * A, int f);

/* The answer's JSON, exactly as `COMMAND --format=json` prints it (one
   line and its newline).  WC_OK or WC_EINTERNAL on a write error.  */
int _wc_answer_fprint_json(FILE * out, const _wc_answer * A);

/* The answer in the command line's format (R->format).  */
int _wc_answer_fprint(FILE * out, const _wc_answer * A);

/* The certificate of the answer (the command's row has one).  */
int _wc_answer_fprint_certificate(FILE * out, const _wc_answer * A,
                                  wc_error_t err);

/* cone --all-modes: the cone of every mode that `modes` lists, in its
   order (ASCII-sorted), one `cone --format=json` line each.  R is a cone
   request (its mode unused).  Refuses (WC_EINPUT, nothing written) when
   the problem has more than _WC_ALL_MODES_MAX modes.  */

/* The cone of A->R->mode for P (A's own problem, or the one --all-modes
   shares) into A (a cone answer).  */
int _wc_cone_compute(_wc_answer * A, const wc_problem_t P, wc_error_t err);
int _wc_cone_all_modes(FILE * out, const _wc_request * R, wc_error_t err);

/* The whole of an input into a malloc'd *text of *len bytes (at most
   _WC_MAX_INPUT_BYTES), with the command line's messages: "cannot open:
   ...", "file too large (over N bytes)", "read error: ...".  */
int _wc_input_read(char ** text, size_t * len, const _wc_input * in,
                   wc_error_t err);

/* _wc_input_read with a limit of max bytes of its own (at most
   _WC_MAX_INPUT_BYTES).  */
int _wc_input_read_max(char ** text, size_t * len, const _wc_input * in,
                       size_t max, wc_error_t err);

/* The problem of an input, read (_wc_input_read) and parsed; errors are
   located in in->name.  */
int _wc_load_problem(wc_problem_t P, const _wc_input * in, wc_error_t err);

/* The numbers args[0..k) into v; a bad one is an input error in "what"
   at its column in the arguments joined by single spaces (as the command
   line reads its operands): "<wrench>:1:COL".  */
int _wc_parse_numbers(fmpq * v, const char * const * args, slong k,
                      const char * what, wc_error_t err);

/* An error record as one JSON line:
   {"error": {"message", "file", "line", "column", "status"}}, unknown
   parts null.  */
int _wc_error_fprint_json(FILE * out, const wc_error_t err, int status);

#endif
