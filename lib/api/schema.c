/* schema.c -- the table of the program's commands: one row per operand
   and option (schema.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A row: name, kind, metavar, choices, what (a choice's noun or what a
   bad value is told), default, a count's bounds, the field, flags, short
   option, help text, help heading.  */

#include <config.h>

#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "api/schema.h"
#include "api/run.h"
#include "core/random.h"
#include "api/batch.h"

/* The rows that many commands share.  */
#define PROBLEM_OPERAND \
    { "problem", _WC_ARG_INPUT, "PROBLEM", NULL, NULL, NULL, 0, 0, \
      offsetof(_wc_request, problem), 0, 0, NULL, NULL }
#define FORMAT_TEXT_JSON \
    { "format", _WC_ARG_CHOICE, "FMT", "text|json", "format", NULL, 0, 0, \
      offsetof(_wc_request, format), _WC_ARG_CLI, 0, \
      "text (default) or json", NULL }

/* The rules between values that no single row can state.  Messages name
   the options as the request or the command line wrote them.  */

#define SAY(...) (snprintf(msg, size, __VA_ARGS__), msg)

static const char *
check_cone(char * msg, size_t size, const _wc_arg ** culprit,
           const _wc_request * R)
{
    const _wc_command_schema * S = _wc_schema + _WC_CONE;
    int json = R->from_request;

    if (R->arith_double && R->method != WC_METHOD_PAPER)
    {
        *culprit = _wc_schema_option(S, "arith", 0);
        return SAY(json ? "\"arith\": \"double\" needs \"method\": \"paper\""
                   : "--arith=double needs --method=paper");
    }
    if (R->arith_double && R->trace)
    {
        *culprit = _wc_schema_option(S, "trace", 0);
        return SAY(json ? "\"arith\": \"double\" does not take \"trace\""
                   : "--arith=double does not take --trace");
    }
    *culprit = NULL;
    if (R->all_modes && R->format >= 0 && R->format != 1)
        return SAY("--all-modes prints JSON lines: --format=json or none");
    if (R->all_modes && R->mode != NULL)
        return SAY("cone --all-modes takes PROBLEM only");
    if (!R->all_modes && R->mode == NULL)
        return SAY(json ? "a cone request needs \"mode\""
                   : "cone needs PROBLEM and MODE");
    return NULL;
}

static const char *
check_plan(char * msg, size_t size, const _wc_arg ** culprit,
           const _wc_request * R)
{
    *culprit = _wc_schema_option(_wc_schema + _WC_PLAN, "certificate", 0);
    if ((R->certificate != NULL || R->want_certificate) && R->wrench.given)
        return SAY(R->from_request ? "\"certificate\" certifies G_goal, not "
                   "one wrench: drop \"wrench\""
                   : "--certificate certifies G_goal, not one wrench: drop "
                   "FX FY TAU");
    return NULL;
}

static const char *
check_sweep(char * msg, size_t size, const _wc_arg ** culprit,
            const _wc_request * R)
{
    *culprit = NULL;
    if (R->friction == NULL && !R->critical)
        return SAY(R->from_request ? "a sweep request needs \"friction\" "
                   "or \"critical\": true"
                   : "sweep needs --friction=LIST or --critical");
    *culprit = _wc_schema_option(_wc_schema + _WC_SWEEP, "certificate", 0);
    if ((R->certificate != NULL || R->want_certificate) && !R->critical)
        return SAY(R->from_request ? "\"certificate\" certifies the bracket "
                   "of \"critical\""
                   : "--certificate certifies the bracket of --critical");
    return NULL;
}

static const char *
check_draw(char * msg, size_t size, const _wc_arg ** culprit,
           const _wc_request * R)
{
    int figures = (R->mode != NULL) + R->fig_modes + R->fig_stability
        + R->fig_plan + (R->sweep != NULL) + R->fig_graph;

    *culprit = NULL;
    if (figures == 0)
        return SAY(R->from_request ? "a draw request needs a figure: "
                   "\"mode\", \"modes\", \"stability\", \"plan\", "
                   "\"sweep\" or \"graph\""
                   : "draw needs a figure: --mode=M, --modes, --stability, "
                   "--plan, --sweep=LIST or --graph");
    if (figures > 1)
        return SAY("draw takes one figure at a time");
    *culprit = _wc_schema_option(_wc_schema + _WC_DRAW, "wrench", 0);
    if (R->graph_wrench != NULL && !R->fig_graph)
        return SAY(R->from_request ? "\"wrench\" goes with \"graph\" only"
                   : "--wrench goes with --graph only");
    return NULL;
}

static const _wc_arg cone_operands[] = {
    PROBLEM_OPERAND,
    { "mode", _WC_ARG_WORD, "MODE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, mode), _WC_ARG_OPTIONAL, 0,
      NULL,
      NULL },
    { NULL }
};

static const _wc_arg cone_options[] = {
    { "format", _WC_ARG_CHOICE, "FMT", "text|json|cdd|ine|ext", "format", NULL, 0, 0,
      offsetof(_wc_request, format), _WC_ARG_CLI, 0,
      "text (default), json (see wrenchcone(1)), cdd (cddlib .ine then\n"
      ".ext with rationals), ine, or ext",
      NULL },
    { "method", _WC_ARG_CHOICE, "METHOD", "direct|paper", "method", NULL, 0, 0,
      offsetof(_wc_request, method), 0, 0,
      "direct (default; Minkowski sum in R^3) or paper (the\n"
      "paper's Section 5 route); both print the same bytes",
      NULL },
    { "trace", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, trace), 0, 0,
      "also print every intermediate matrix of the route",
      NULL },
    { "arith", _WC_ARG_CHOICE, "ARITH", "exact|double", "arithmetic", NULL, 0, 0,
      offsetof(_wc_request, arith_double), 0, 0,
      "exact (default) or double: the paper route in C doubles\n"
      "with cddlib's double-precision build, the floating-point\n"
      "baseline (needs --method=paper, no --trace; unit-length\n"
      "vectors, a strict flag per facet and ray instead of faces)",
      NULL },
    { "all-modes", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, all_modes), _WC_ARG_CLI, 0,
      "the cone of every mode that 'modes' lists, in its order,\n"
      "one JSON line each (as --format=json prints it); at most\n"
      "10000 modes",
      NULL },
    { NULL }
};

static const _wc_arg modes_operands[] = {
    PROBLEM_OPERAND,
    { NULL }
};

static const _wc_arg modes_options[] = {
    { "witness", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, witness), 0, 0,
      "also print, per mode, a primitive integer twist nu\n"
      "(vx, vy, w) that has the mode",
      NULL },
    { "format", _WC_ARG_CHOICE, "FMT", "text|json", "format", NULL, 0, 0,
      offsetof(_wc_request, format), _WC_ARG_CLI, 0,
      "text (default: one mode per line) or json",
      NULL },
    { NULL }
};

static const _wc_arg feasible_operands[] = {
    PROBLEM_OPERAND,
    { "mode", _WC_ARG_WORD, "MODE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, mode), 0, 0,
      NULL,
      NULL },
    { NULL }
};

static const _wc_arg feasible_options[] = {
    { "certificate", _WC_ARG_OUTPUT, "FILE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, certificate), _WC_ARG_CLI, 0,
      "also write the self-contained JSON certificate to\n"
      "FILE, for 'wrenchcone verify FILE'",
      NULL },
    { "format", _WC_ARG_CHOICE, "FMT", "text|json", "format", NULL, 0, 0,
      offsetof(_wc_request, format), _WC_ARG_CLI, 0,
      "text (default) or json (the certificate itself)",
      NULL },
    { NULL }
};

static const _wc_arg classify_operands[] = {
    PROBLEM_OPERAND,
    { "wrench", _WC_ARG_WRENCH, "FX FY TAU", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, wrench), 0, 0,
      NULL,
      NULL },
    { NULL }
};

static const _wc_arg classify_options[] = {
    { "certificate", _WC_ARG_OUTPUT, "FILE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, certificate), _WC_ARG_CLI, 0,
      "write a strong-stability certificate (JSON) that\n"
      "'wrenchcone verify' re-checks with GMP alone: the static\n"
      "forces or a separator, and a motion or a Farkas\n"
      "certificate for every moving face",
      NULL },
    { "max-modes", _WC_ARG_COUNT, "N", NULL, "takes a count >= 0 (0: no limit)", "1000", 0, 999999999,
      offsetof(_wc_request, max_modes), 0, 0,
      "list at most N modes (default 1000; 0: no limit).  The\n"
      "list can be exponentially long: a wrench that three of\n"
      "t touching fixels hold is held by 2^(t-3) strings",
      NULL },
    FORMAT_TEXT_JSON,
    { NULL }
};

static const _wc_arg stability_operands[] = {
    PROBLEM_OPERAND,
    { NULL }
};

static const _wc_arg stability_options[] = {
    { "bias", _WC_ARG_WRENCH, "FX,FY,TAU", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, bias), 0, 0,
      "a biasing wrench: report the largest disturbance rho such\n"
      "that every disturbance d with ||d|| < rho keeps the\n"
      "wrench strongly stable, in the norm\n"
      "||(fx, fy, tau)|| = max(|fx|, |fy|, |tau| / L)\n"
      "(also accepted: --bias FX FY TAU)",
      NULL },
    { "length", _WC_ARG_NUMBER, "L", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, length), 0, 0,
      "the length L > 0 of that norm (default 1)",
      NULL },
    { "certificate", _WC_ARG_OUTPUT, "FILE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, certificate), _WC_ARG_CLI, 0,
      "also write a certificate (JSON) that the strongly\n"
      "stable set is exact, for wrenchcone verify",
      NULL },
    FORMAT_TEXT_JSON,
    { NULL }
};

static const _wc_arg plan_operands[] = {
    PROBLEM_OPERAND,
    { "wrench", _WC_ARG_WRENCH, "FX FY TAU", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, wrench), _WC_ARG_OPTIONAL, 0,
      NULL,
      NULL },
    { NULL }
};

static const _wc_arg plan_options[] = {
    { "complete", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, complete), 0, 0,
      "also the complete plan (beyond the paper): accept a\n"
      "wrench when every transition graph it allows is acyclic\n"
      "with the goal as its only sink (wrenchcone(1) states the\n"
      "transition model); as a set, or for the wrench given,\n"
      "with its transitions.  At most 6 fixels",
      NULL },
    { "certificate", _WC_ARG_OUTPUT, "FILE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, certificate), _WC_ARG_CLI, 0,
      "also write a certificate (JSON) that G_goal is\n"
      "exact, for wrenchcone verify (not with a wrench)",
      NULL },
    FORMAT_TEXT_JSON,
    { NULL }
};

static const _wc_arg sweep_operands[] = {
    PROBLEM_OPERAND,
    { NULL }
};

static const _wc_arg sweep_options[] = {
    { "friction", _WC_ARG_LIST, "LIST", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, friction), 0, 0,
      "the plan for each value of the comma-separated list of\n"
      "exact numbers: the pieces of G_goal, the needed strings,\n"
      "eq. 25, and with a shape the pushing region and its\n"
      "length (approximate, for reading)",
      "Options (at least one of --friction and --critical)" },
    { "critical", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, critical), 0, 0,
      "an exact bracket [lo, hi] of the friction at which G_goal\n"
      "becomes empty: nonempty at lo (with a wrench in it),\n"
      "empty at hi (with the strings whose cones cover R^3)",
      "Options (at least one of --friction and --critical)" },
    { "width", _WC_ARG_NUMBER, "W", NULL, NULL, "1/1000", 0, 0,
      offsetof(_wc_request, width), 0, 0,
      "the bracket's largest width, at least 2^-96\n"
      "(default 1/1000)",
      "Options (at least one of --friction and --critical)" },
    { "max-friction", _WC_ARG_NUMBER, "M", NULL, NULL, "1024", 0, 0,
      offsetof(_wc_request, max_friction), 0, 0,
      "give up above M, at most 2^32 (default 1024):\n"
      "G_goal is then nonempty at every mu <= M",
      "Options (at least one of --friction and --critical)" },
    { "certificate", _WC_ARG_OUTPUT, "FILE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, certificate), _WC_ARG_CLI, 0,
      "with --critical, also write a certificate (JSON)\n"
      "of the bracket, for wrenchcone verify",
      "Options (at least one of --friction and --critical)" },
    { "format", _WC_ARG_CHOICE, "FMT", "text|json", "format", NULL, 0, 0,
      offsetof(_wc_request, format), _WC_ARG_CLI, 0,
      "text (default) or json",
      "Options (at least one of --friction and --critical)" },
    { NULL }
};

static const _wc_arg verify_operands[] = {
    { "certfile", _WC_ARG_INPUT, "CERTFILE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, cert), 0, 0,
      NULL,
      NULL },
    { NULL }
};

static const _wc_arg verify_options[] = {
    FORMAT_TEXT_JSON,
    { NULL }
};

static const _wc_arg compare_operands[] = {
    PROBLEM_OPERAND,
    { "mode", _WC_ARG_WORD, "MODE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, mode), 0, 0,
      NULL,
      NULL },
    { "foreign", _WC_ARG_INPUT, "FILE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, foreign), 0, 0,
      NULL,
      NULL },
    { NULL }
};

static const _wc_arg compare_options[] = {
    { "tol", _WC_ARG_ANGLE, "T", NULL, "must be an angle in radians, at least 0 and below pi/2 (such as 1e-9)", "1e-9", 0, 0,
      offsetof(_wc_request, tol), 0, 0,
      "tolerance in radians, 0 <= T < pi/2 (default 1e-9)",
      NULL },
    FORMAT_TEXT_JSON,
    { NULL }
};

static const _wc_arg random_operands[] = {
    { NULL }
};

static const _wc_arg random_options[] = {
    { "fixels", _WC_ARG_COUNT, "N", NULL, "must be an integer from 1 to 1000", "3", 1, WC_RANDOM_MAX_FIXELS,
      offsetof(_wc_request, fixels), 0, 0,
      "the number of fixels, 1 to 1000 (default 3)",
      NULL },
    { "seed", _WC_ARG_SEED, "S", NULL, "must be a decimal integer from 0 to 2^64 - 1", "1", 0, 0,
      offsetof(_wc_request, seed), 0, 0,
      "the seed, a decimal integer below 2^64 (default 1)",
      NULL },
    { "degenerate", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, degenerate), 0, 0,
      "plant degenerate features: two fixels at one point,\n"
      "normals parallel or opposed, normals 10^-9 apart,\n"
      "three collinear contact points",
      NULL },
    { "shape", _WC_ARG_CHOICE, "SHAPE", "none|disk|polygon", "shape", NULL, 0, 0,
      offsetof(_wc_request, shape), 0, 0,
      "none (default), disk or polygon: points on the shape's\n"
      "boundary, with its exact inward normals",
      NULL },
    { "friction", _WC_ARG_LIST, "MU[,MUK]", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, friction), 0, 0,
      "use these exact friction coefficients (mu_s, mu_k) at\n"
      "every fixel instead of drawing them",
      NULL },
    { "format", _WC_ARG_CHOICE, "FMT", "text|json", "format", NULL, 0, 0,
      offsetof(_wc_request, format), _WC_ARG_CLI, 0,
      "text (default; the .wc file) or json (the file as the\n"
      "string \"problem_text\", for a request's \"problem_text\")",
      NULL },
    { NULL }
};

static const _wc_arg draw_operands[] = {
    PROBLEM_OPERAND,
    { NULL }
};

static const _wc_arg draw_options[] = {
    { "mode", _WC_ARG_WORD, "M", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, mode), 0, 0,
      "the wrench cone W(M): each generator as a line of force,\n"
      "pure torques as arcs about the centre of mass; dashed:\n"
      "a generator of the closure that W(M) excludes",
      "Figures (exactly one)" },
    { "modes", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, fig_modes), 0, 0,
      "a rotation centre (or a translation) per feasible mode",
      "Figures (exactly one)" },
    { "stability", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, fig_stability), 0, 0,
      "where a frictionless finger may push: the strongly\n"
      "stable sets (both semantics) and the weakly stable set",
      "Figures (exactly one)" },
    { "plan", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, fig_plan), 0, 0,
      "where to push to seat the part: the insertion plan's\n"
      "goal set G_goal",
      "Figures (exactly one)" },
    { "sweep", _WC_ARG_LIST, "LIST", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, sweep), 0, 0,
      "G_goal for each friction value of the comma-separated\n"
      "LIST (at most 12), one above the other",
      "Figures (exactly one)" },
    { "graph", _WC_ARG_FLAG, NULL, NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, fig_graph), 0, 0,
      "the insertion plan's state-transition graph (at most\n"
      "4 fixels): the transitions it forbids and allows",
      "Figures (exactly one)" },
    { "wrench", _WC_ARG_LIST, "FX,FY,TAU", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, graph_wrench), 0, 0,
      "with --graph: the transitions the wrench admits under\n"
      "the complete plan (plan --complete), with its verdict",
      "Figures (exactly one)" },
    { "output", _WC_ARG_OUTPUT, "FILE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, output), _WC_ARG_CLI, 'o',
      "write the figure to FILE (a regular file whole or\n"
      "not at all, a FIFO or device written through);\n"
      "default (and -o -) standard output",
      NULL },
    { NULL }
};

static const _wc_arg report_operands[] = {
    PROBLEM_OPERAND,
    { NULL }
};

static const _wc_arg report_options[] = {
    { "output", _WC_ARG_OUTPUT, "FILE", NULL, NULL, NULL, 0, 0,
      offsetof(_wc_request, output), _WC_ARG_CLI, 'o',
      "write the page to FILE (as draw -o writes);\n"
      "default (and -o -) standard output",
      NULL },
    { NULL }
};

static const _wc_arg batch_operands[] = {
    { "batch", _WC_ARG_WORD, "FILE", NULL, NULL, "-", 0, 0,
      offsetof(_wc_request, batch), _WC_ARG_OPTIONAL, 0,
      NULL,
      NULL },
    { NULL }
};

static const _wc_arg batch_options[] = {
    { "jobs", _WC_ARG_COUNT, "N", NULL, "takes a count from 1 to 256", "1",
      1, WC_BATCH_MAX_JOBS,
      offsetof(_wc_request, jobs), _WC_ARG_CLI, 0,
      "answer with N threads (1 to 256; default 1); the\n"
      "answers are the same, in the same order, each still\n"
      "written once it and all earlier ones are done",
      NULL },
    { NULL }
};

const _wc_command_schema _wc_schema[] = {
    { "cone", "cone PROBLEM MODE",
      "the exact cone of external wrenches consistent with\n"
      "the contact mode MODE (one letter per fixel)",
      "Usage: wrenchcone cone [OPTIONS] PROBLEM MODE\n"
      "  or:  wrenchcone cone --all-modes [OPTIONS] PROBLEM",
      "Print W(MODE), the exact cone of external wrenches (fx, fy, torque)\n"
      "consistent with MODE, in canonical form: closure facets, rays, and every\n"
      "face of the closure with whether it belongs to the cone.\n"
      "\n"
      "MODE has one letter per fixel, in file order (paper Table 2):\n"
      "  touching fixels: s separate, l slide left, r slide right, n roll,\n"
      "                   m maintain contact;\n"
      "  near fixels:     s separate, a approach, u unconstrained.",
      NULL,
      cone_operands, cone_options, _WC_CMD_SHARED | _WC_CMD_REQUEST, check_cone },
    { "modes", "modes PROBLEM",
      "every kinematically feasible contact mode",
      "Usage: wrenchcone modes [OPTIONS] PROBLEM",
      "List every kinematically feasible contact mode (paper Table 1: s l r n on\n"
      "touching fixels, s a on near ones), sorted, n..n included.  The modes are\n"
      "read off the faces of the arrangement of the 2n planes J_k . nu = 0 in\n"
      "twist space (O(n^2) faces), never off the 4^n strings.",
      NULL,
      modes_operands, modes_options, _WC_CMD_SHARED | _WC_CMD_REQUEST, NULL },
    { "feasible", "feasible PROBLEM MODE",
      "one mode's verdict, with a checkable certificate",
      "Usage: wrenchcone feasible [OPTIONS] PROBLEM MODE",
      "Decide whether MODE (paper Table 1 letters) is kinematically feasible and\n"
      "print a certificate: a primitive integer witness twist, or Motzkin\n"
      "multipliers whose combination of the mode's constraint rows is zero,\n"
      "proving that no twist has the mode.  Exit status 0 either way.",
      NULL,
      feasible_operands, feasible_options, _WC_CMD_SHARED | _WC_CMD_REQUEST, NULL },
    { "classify", "classify PROBLEM FX FY TAU",
      "one wrench: weak and strong stability (exact and\n"
      "paper semantics), motions, the modes holding it",
      "Usage: wrenchcone classify [OPTIONS] PROBLEM FX FY TAU",
      "Decide one external wrench g = (FX, FY, TAU) (exact numbers) at zero\n"
      "velocity, with exact LPs only (no cone conversion):\n"
      "  - weakly stable: a static solution exists (its forces are printed, or a\n"
      "    separating vector proving none does);\n"
      "  - every moving solution, by the contact mode of the motion, with a\n"
      "    witness (nudot, c);\n"
      "  - strongly stable in the exact sense (weakly stable, no solution moves)\n"
      "    and in the paper's sense (eq. 19: no Table 2 cone other than n..n\n"
      "    holds g), side by side;\n"
      "  - every contact mode (Table 2 letters: s l r n on touching fixels, s a on\n"
      "    near ones) whose wrench cone holds g.",
      NULL,
      classify_operands, classify_options, _WC_CMD_SHARED | _WC_CMD_OPERANDS_LAST | _WC_CMD_REQUEST, NULL },
    { "stability", "stability PROBLEM",
      "the weakly and strongly stable wrench sets, exactly,\n"
      "and where a frictionless finger may push",
      "Usage: wrenchcone stability [OPTIONS] PROBLEM",
      "Compute exactly the weakly stable cone, and the strongly stable sets under\n"
      "the exact semantics (weakly stable, no moving solution) and the paper's\n"
      "(eq. 19), each as pairwise disjoint NNC cones in canonical form; with a\n"
      "shape, the places a frictionless finger may push for each set.",
      NULL,
      stability_operands, stability_options, _WC_CMD_SHARED | _WC_CMD_OPERANDS_LAST | _WC_CMD_REQUEST, NULL },
    { "plan", "plan PROBLEM [FX FY TAU]",
      "a sensorless insertion plan: the wrenches that seat\n"
      "the part from any contact state (G_goal), exactly;\n"
      "with a wrench, its verdict",
      "Usage: wrenchcone plan [OPTIONS] PROBLEM [FX FY TAU]",
      "The sensorless insertion plan of paper Sections 8 and 9 for all fixels of\n"
      "PROBLEM (their touching/near states are ignored: every contact state is\n"
      "considered).  For every state S and nonempty L in S the string s on L,\n"
      "m on S \\ L, u off S; for every S but the goal, m on S, s off S.  Prints\n"
      "the strings of each state (Table 5), which are redundant syntactically and\n"
      "exactly, the goal set G_goal (the complement of the union of their cones)\n"
      "as pairwise disjoint NNC cones, whether G_goal lies in the goal state's\n"
      "strongly stable set (eq. 25, both semantics), and with a shape where a\n"
      "frictionless finger may push.  With a wrench FX FY TAU: whether it is in\n"
      "G_goal and which needed strings hold it.",
      NULL,
      plan_operands, plan_options, _WC_CMD_SHARED | _WC_CMD_OPERANDS_LAST | _WC_CMD_REQUEST, check_plan },
    { "sweep", "sweep PROBLEM",
      "G_goal against friction: --friction=LIST, --critical",
      "Usage: wrenchcone sweep [OPTIONS] PROBLEM",
      "G_goal of the insertion plan against the friction coefficient, with\n"
      "mu_s = mu_k = mu at every fixel.  G_goal shrinks as mu grows.",
      NULL,
      sweep_operands, sweep_options, _WC_CMD_SHARED | _WC_CMD_REQUEST, check_sweep },
    { "verify", "verify CERTFILE",
      "re-check a certificate with GMP arithmetic alone",
      "Usage: wrenchcone verify [OPTIONS] CERTFILE",
      "Re-check a certificate with GMP arithmetic alone (no FLINT, no cddlib).\n"
      "Four kinds: mode-feasibility ('wrenchcone feasible --certificate=FILE'):\n"
      "the constraint rows are derived again from the certificate's problem\n"
      "and mode, then the witness or the Motzkin multipliers are checked;\n"
      "strong-stability ('wrenchcone classify --certificate=FILE'): the static\n"
      "forces or the separator, the motion, or -- for a strongly stable\n"
      "wrench -- Motzkin multipliers for every moving face, the set of moving\n"
      "faces being derived again from the geometry; stability-set ('wrenchcone\n"
      "stability --certificate=FILE') and plan-goal ('wrenchcone plan\n"
      "--certificate=FILE'): the set printed is exactly the strongly stable\n"
      "set or the plan's goal set, every cell of the certificate's planes\n"
      "placed in it or outside it, the cells found again here.  Exit status\n"
      "0 when the certificate holds, 4 when it does not, 1 when the file is\n"
      "malformed.",
      NULL,
      verify_operands, verify_options, _WC_CMD_SHARED | _WC_CMD_REQUEST, NULL },
    { "compare", "compare PROBLEM MODE FILE",
      "check a cone computed elsewhere (FILE: cdd or JSON,\n"
      "floats allowed) against the exact W(MODE)",
      "Usage: wrenchcone compare [OPTIONS] PROBLEM MODE FILE",
      "Check a cone computed elsewhere, typically in floating point, against the\n"
      "exact W(MODE).  FILE is a cddlib .ext (generators) or .ine (inequalities)\n"
      "with integers, fractions, decimals or exponents, or a JSON cone as\n"
      "'wrenchcone cone --format=json' prints it (exact, or with floats).\n"
      "FILE's numbers are read exactly, and the exact side decides emptiness,\n"
      "dimension, lineality, extreme rays and facets; floating point enters only\n"
      "the angles reported (radians): each float ray's angle to the exact closure,\n"
      "each exact ray's angle to the float closure, and the Hausdorff distance\n"
      "between the two closures on the unit sphere.  An extreme ray or facet with\n"
      "none of the other side's within the tolerance is missing (exact) or extra\n"
      "(float).  Strictness cannot be read from a float cone: the report lists\n"
      "the faces the exact cone excludes, to be checked separately.\n"
      "\n"
      "Exit status 0 when FILE is within the tolerance (same emptiness, dimension\n"
      "and lineality, Hausdorff distance <= T, nothing missing or extra), 4 when\n"
      "it is not, 1 when PROBLEM, MODE or FILE is malformed.",
      NULL,
      compare_operands, compare_options, _WC_CMD_REQUEST, NULL },
    { "random", "random [OPTIONS]",
      "print a reproducible random problem (a .wc file)",
      "Usage: wrenchcone random [OPTIONS]",
      "Print a random problem as a .wc file, the same bytes for the same options\n"
      "on every platform; the first line is a comment naming the command that\n"
      "reproduces it.",
      NULL,
      random_operands, random_options, _WC_CMD_REQUEST, NULL },
    { "draw", "draw FIGURE PROBLEM",
      "a figure as SVG: --mode=M, --modes, --stability,\n"
      "--plan, --sweep=LIST or --graph; -o FILE",
      "Usage: wrenchcone draw FIGURE [OPTIONS] PROBLEM",
      "Draw a figure of PROBLEM as an SVG document: the part, its centre of mass,\n"
      "the fixels with their normals and friction cones, and one of",
      "Every position comes from the exact result, converted to floating point\n"
      "once; the legend and the caption say what is drawn.",
      draw_operands, draw_options, _WC_CMD_REQUEST, check_draw },
    { "report", "report PROBLEM -o FILE.html",
      "every analysis of PROBLEM on one HTML page, with\n"
      "its figures",
      "Usage: wrenchcone report [OPTIONS] PROBLEM",
      "Write one self-contained HTML page (inline SVG and CSS, no scripts, works\n"
      "offline, prints well) with every analysis of PROBLEM: the problem, the\n"
      "feasible modes, the stability sets in both semantics, the insertion plan\n"
      "with its goal set and eq. 25, their figures, the pushing regions with\n"
      "their exact ends (and decimal approximations, marked so), and the command\n"
      "lines that reproduce each part.",
      NULL,
      report_operands, report_options, _WC_CMD_REQUEST, NULL },
    { "batch", "batch [FILE]",
      "JSON Lines requests in (cone, modes, feasible,\n"
      "classify, stability, plan, compare), one JSON\n"
      "answer line out per request",
      "Usage: wrenchcone batch [OPTIONS] [FILE]",
      "Answer requests given as JSON Lines (FILE, or standard input when FILE is\n"
      "absent or '-'), one JSON object a line, such as\n"
      "  {\"command\": \"cone\", \"problem\": \"data/section4.wc\", \"mode\": \"na\"}\n"
      "Each answer is one line, in the order of the requests: exactly what the\n"
      "command prints with --format=json, or {\"error\": {\"message\", \"file\",\n"
      "\"line\", \"column\", \"status\"}} and the batch goes on.  Blank lines are\n"
      "skipped.  Each answer is written as soon as it is computed, so a program\n"
      "can send one request and read its answer through pipes.  Every command\n"
      "but batch is a request; the keys of each are in wrenchcone(1), REQUESTS,\n"
      "and 'wrenchcone COMMAND ... --print-request' prints the request of a\n"
      "command line.\n"
      "\n"
      "Exit status: 0 when every request succeeded, else the largest status of\n"
      "a line (1 bad input, 2 bad request, 3 internal, 4 a comparison beyond\n"
      "its tolerance); 1 when FILE cannot be opened, 3 when reading it or\n"
      "writing the answers fails.",
      NULL,
      batch_operands, batch_options, 0, NULL },
    { NULL }
};

const _wc_command_schema *
_wc_schema_find(const char * name)
{
    const _wc_command_schema * S;

    for (S = _wc_schema; S->name != NULL; S++)
        if (strcmp(S->name, name) == 0)
            return S;
    return NULL;
}

const char *
_wc_arg_key(char * buf, size_t size, const _wc_arg * a)
{
    size_t i;

    for (i = 0; i + 1 < size && a->name[i] != '\0'; i++)
        buf[i] = a->name[i] == '-' ? '_' : a->name[i];
    buf[i] = '\0';
    return buf;
}

const _wc_arg *
_wc_schema_option(const _wc_command_schema * S, const char * name, int key)
{
    const _wc_arg * a;
    char buf[64];

    for (a = S->options; a->name != NULL; a++)
        if (strcmp(key ? _wc_arg_key(buf, sizeof buf, a) : a->name, name)
            == 0)
            return a;
    return NULL;
}
