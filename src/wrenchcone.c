/* wrenchcone.c -- the command-line program.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Results go to stdout, only after the whole answer is computed;
   diagnostics go to stderr as "wrenchcone: FILE:LINE:COL: message".
   Exit status: 0 success, 1 bad input, 2 bad usage, 3 internal or I/O
   failure, 4 a check found a disagreement (SPEC 4).  */

#include <config.h>

#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "wrenchcone.h"

#define PROG "wrenchcone"

typedef enum { FMT_TEXT, FMT_JSON, FMT_CDD, FMT_INE, FMT_EXT } out_format;

static void
usage(FILE * out)
{
    fputs("Usage: " PROG " COMMAND [OPTIONS] PROBLEM [ARGS]\n"
          "Exact wrench cones for planar rigid-body contact tasks.\n"
          "\n"
          "Commands:\n"
          "  cone PROBLEM MODE      the exact cone of external wrenches consistent with\n"
          "                         the contact mode MODE (one letter per fixel)\n"
          "  modes PROBLEM          every kinematically feasible contact mode\n"
          "  feasible PROBLEM MODE  one mode's verdict, with a checkable certificate\n"
          "  classify PROBLEM FX FY TAU\n"
          "                         one wrench: weak and strong stability (exact and\n"
          "                         paper semantics), motions, the modes holding it\n"
          "  stability PROBLEM      the weakly and strongly stable wrench sets, exactly,\n"
          "                         and where a frictionless finger may push\n"
          "  plan PROBLEM [FX FY TAU]\n"
          "                         a sensorless insertion plan: the wrenches that seat\n"
          "                         the part from any contact state (G_goal), exactly;\n"
          "                         with a wrench, its verdict\n"
          "  sweep PROBLEM          G_goal against friction: --friction=LIST, --critical\n"
          "  verify CERTFILE        re-check a certificate with GMP arithmetic alone\n"
          "  compare PROBLEM MODE FILE\n"
          "                         check a cone computed elsewhere (FILE: cdd or JSON,\n"
          "                         floats allowed) against the exact W(MODE)\n"
          "  random [OPTIONS]       print a reproducible random problem (a .wc file)\n"
          "\n"
          "PROBLEM is a .wc problem file (see wrenchcone(5)); '-' reads standard input.\n"
          "Options of every command: --format=text|json, -h/--help, -V/--version.\n"
          "Run '" PROG " COMMAND --help' for a command's options.\n"
          "\n"
          "Exit status: 0 success (an empty cone is an answer), 1 bad input,\n"
          "2 bad usage, 3 internal or I/O failure, 4 disagreement (compare, verify).\n",
          out);
}

static void
usage_cone(FILE * out)
{
    fputs("Usage: " PROG " cone [OPTIONS] PROBLEM MODE\n"
          "Print W(MODE), the exact cone of external wrenches (fx, fy, torque)\n"
          "consistent with MODE, in canonical form: closure facets, rays, and every\n"
          "face of the closure with whether it belongs to the cone.\n"
          "\n"
          "MODE has one letter per fixel, in file order (paper Table 2):\n"
          "  touching fixels: s separate, l slide left, r slide right, n roll,\n"
          "                   m maintain contact;\n"
          "  near fixels:     s separate, a approach, u unconstrained.\n"
          "\n"
          "Options:\n"
          "  --format=FMT     text (default), json (SPEC 4.1), cdd (cddlib .ine then\n"
          "                   .ext with rationals), ine, or ext\n"
          "  --method=METHOD  direct (default; Minkowski sum in R^3) or paper (the\n"
          "                   paper's Section 5 route); both print the same bytes\n"
          "  --trace          also print every intermediate matrix of the route\n"
          "  --arith=ARITH    exact (default) or double: the paper route in C doubles\n"
          "                   with cddlib's double-precision build, the floating-point\n"
          "                   baseline (needs --method=paper, no --trace; unit-length\n"
          "                   vectors, a strict flag per facet and ray instead of faces)\n"
          "  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
}

static void
usage_modes(FILE * out)
{
    fputs("Usage: " PROG " modes [OPTIONS] PROBLEM\n"
          "List every kinematically feasible contact mode (paper Table 1: s l r n on\n"
          "touching fixels, s a on near ones), sorted, n..n included.  The modes are\n"
          "read off the faces of the arrangement of the 2n planes J_k . nu = 0 in\n"
          "twist space (O(n^2) faces), never off the 4^n strings.\n"
          "\n"
          "Options:\n"
          "  --witness        also print, per mode, a primitive integer twist nu\n"
          "                   (vx, vy, w) that has the mode\n"
          "  --format=FMT     text (default: one mode per line) or json\n"
          "  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
}

static void
usage_feasible(FILE * out)
{
    fputs("Usage: " PROG " feasible [OPTIONS] PROBLEM MODE\n"
          "Decide whether MODE (paper Table 1 letters) is kinematically feasible and\n"
          "print a certificate: a primitive integer witness twist, or Motzkin\n"
          "multipliers whose combination of the mode's constraint rows is zero,\n"
          "proving that no twist has the mode.  Exit status 0 either way.\n"
          "\n"
          "Options:\n"
          "  --certificate=FILE  also write the self-contained JSON certificate to\n"
          "                      FILE, for '" PROG " verify FILE'\n"
          "  --format=FMT        text (default) or json (the certificate itself)\n"
          "  -h, --help          print this help and exit\n"
          "  -V, --version       print versions and exit\n", out);
}

static void
usage_verify(FILE * out)
{
    fputs("Usage: " PROG " verify [OPTIONS] CERTFILE\n"
          "Re-check a certificate with GMP arithmetic alone (no FLINT, no cddlib).\n"
          "Two kinds: mode-feasibility ('" PROG " feasible --certificate=FILE'): the\n"
          "constraint rows are derived again from the certificate's problem and\n"
          "mode, then the witness or the Motzkin multipliers are checked exactly;\n"
          "strong-stability ('" PROG " classify --certificate=FILE'): the static\n"
          "forces or the separator, the motion, or -- for a strongly stable\n"
          "wrench -- a Farkas certificate for every moving face, the set of moving\n"
          "faces being derived again from the geometry.  Exit status 0 when the\n"
          "certificate holds, 4 when it does not, 1 when the file is malformed.\n"
          "\n"
          "Options:\n"
          "  --format=FMT     text (default) or json\n"
          "  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
}

static void
usage_random(FILE * out)
{
    fputs("Usage: " PROG " random [OPTIONS]\n"
          "Print a random problem as a .wc file, the same bytes for the same options\n"
          "on every platform; the first line is a comment naming the command that\n"
          "reproduces it.\n"
          "\n"
          "Options:\n"
          "  --fixels=N       the number of fixels, 1 to 1000 (default 3)\n"
          "  --seed=S         the seed, a decimal integer below 2^64 (default 1)\n"
          "  --degenerate     plant degenerate features: two fixels at one point,\n"
          "                   normals parallel or opposed, normals 10^-9 apart,\n"
          "                   three collinear contact points\n"
          "  --shape=SHAPE    none (default), disk or polygon: points on the shape's\n"
          "                   boundary, with its exact inward normals\n"
          "  --friction=MU[,MUK]\n"
          "                   use these exact friction coefficients (mu_s, mu_k) at\n"
          "                   every fixel instead of drawing them\n"
          "  --format=FMT     text (default; the .wc file)\n"
          "  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
}

static void
usage_compare(FILE * out)
{
    fputs("Usage: " PROG " compare [OPTIONS] PROBLEM MODE FILE\n"
          "Check a cone computed elsewhere, typically in floating point, against the\n"
          "exact W(MODE).  FILE is a cddlib .ext (generators) or .ine (inequalities)\n"
          "with integers, fractions, decimals or exponents, or a JSON cone as\n"
          "'" PROG " cone --format=json' prints it (exact, or with floats).\n"
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
          "it is not, 1 when PROBLEM, MODE or FILE is malformed.\n"
          "\n"
          "Options:\n"
          "  --tol=T          tolerance in radians, 0 <= T < pi/2 (default 1e-9)\n"
          "  --format=FMT     text (default) or json\n"
          "  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
}

static void
usage_classify(FILE * out)
{
    fputs("Usage: " PROG " classify [OPTIONS] PROBLEM FX FY TAU\n"
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
          "    near ones) whose wrench cone holds g.\n"
          "\n"
          "Options:\n"
          "  --certificate=FILE  write a strong-stability certificate (JSON) that\n"
          "                   '" PROG " verify' re-checks with GMP alone: the static\n"
          "                   forces or a separator, and a motion or a Farkas\n"
          "                   certificate for every moving face\n"
          "  --max-modes=N    list at most N modes (default 1000; 0: no limit).  The\n"
          "                   list can be exponentially long: a wrench that three of\n"
          "                   t touching fixels hold is held by 2^(t-3) strings\n"
          "  --format=FMT     text (default) or json\n"
          "  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
}

static void
usage_stability(FILE * out)
{
    fputs("Usage: " PROG " stability [OPTIONS] PROBLEM\n"
          "Compute exactly the weakly stable cone, and the strongly stable sets under\n"
          "the exact semantics (weakly stable, no moving solution) and the paper's\n"
          "(eq. 19), each as pairwise disjoint NNC cones in canonical form; with a\n"
          "shape, the places a frictionless finger may push for each set.\n"
          "\n"
          "Options:\n"
          "  --bias=FX,FY,TAU  a biasing wrench: report the largest disturbance rho such\n"
          "                   that every disturbance d with ||d|| < rho keeps the\n"
          "                   wrench strongly stable, in the norm\n"
          "                   ||(fx, fy, tau)|| = max(|fx|, |fy|, |tau| / L)\n"
          "                   (also accepted: --bias FX FY TAU)\n"
          "  --length=L       the length L > 0 of that norm (default 1)\n"
          "  --format=FMT     text (default) or json\n"
          "  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
}

static void
usage_plan(FILE * out)
{
    fputs("Usage: " PROG " plan [OPTIONS] PROBLEM [FX FY TAU]\n"
          "The sensorless insertion plan of paper Sections 8 and 9 for all fixels of\n"
          "PROBLEM (their touching/near states are ignored: every contact state is\n"
          "considered).  For every state S and nonempty L in S the string s on L,\n"
          "m on S \\ L, u off S; for every S but the goal, m on S, s off S.  Prints\n"
          "the strings of each state (Table 5), which are redundant syntactically and\n"
          "exactly, the goal set G_goal (the complement of the union of their cones)\n"
          "as pairwise disjoint NNC cones, whether G_goal lies in the goal state's\n"
          "strongly stable set (eq. 25, both semantics), and with a shape where a\n"
          "frictionless finger may push.  With a wrench FX FY TAU: whether it is in\n"
          "G_goal and which needed strings hold it.\n"
          "\n"
          "Options:\n"
          "  --complete       also the complete plan (beyond the paper): accept a\n"
          "                   wrench when every transition graph it allows is acyclic\n"
          "                   with the goal as its only sink (wrenchcone(1) states the\n"
          "                   transition model); as a set, or for the wrench given,\n"
          "                   with its transitions.  At most 6 fixels\n"
          "  --format=FMT     text (default) or json\n"
          "  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
}

static void
usage_sweep(FILE * out)
{
    fputs("Usage: " PROG " sweep [OPTIONS] PROBLEM\n"
          "G_goal of the insertion plan against the friction coefficient, with\n"
          "mu_s = mu_k = mu at every fixel.  G_goal shrinks as mu grows.\n"
          "\n"
          "Options (at least one of --friction and --critical):\n"
          "  --friction=LIST  the plan for each value of the comma-separated list of\n"
          "                   exact numbers: the pieces of G_goal, the needed strings,\n"
          "                   eq. 25, and with a shape the pushing region and its\n"
          "                   length (approximate, for reading)\n"
          "  --critical       an exact bracket [lo, hi] of the friction at which G_goal\n"
          "                   becomes empty: nonempty at lo (with a wrench in it),\n"
          "                   empty at hi (with the strings whose cones cover R^3)\n"
          "  --width=W        the bracket's largest width (default 1/1000)\n"
          "  --max-friction=M give up above M (default 1024): G_goal is then\n"
          "                   nonempty at every mu <= M\n"
          "  --format=FMT     text (default) or json\n"
          "  -h, --help       print this help and exit\n"
          "  -V, --version    print versions and exit\n", out);
}

static void
version(void)
{
    printf(PROG " %s\n"
           "GMP %s, FLINT %s, cddlib %s\n"
           "Copyright (C) 2026 the wrenchcone authors.\n"
           "License GPLv2+: GNU GPL version 2 or later.\n"
           "This is free software: you are free to change and redistribute it.\n"
           "There is NO WARRANTY, to the extent permitted by law.\n",
           wc_version(), wc_gmp_version(), wc_flint_version(),
           wc_cdd_version());
}

/* Report err on stderr and return its status.  */
static int
report(const wc_error_t err, int status)
{
    char * s = wc_error_format(err);

    fprintf(stderr, PROG ": %s\n", s != NULL ? s : "out of memory");
    free(s);
    return status;
}

static int
usage_error(const char * cmd, const char * fmt, const char * arg)
{
    fputs(PROG ": ", stderr);
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\nTry '" PROG "%s%s --help' for more information.\n",
            cmd ? " " : "", cmd ? cmd : "");
    return WC_EUSAGE;
}

/* Inputs larger than these are refused before they are parsed: a problem
   of a million fixels is far below the first, and a certificate carries
   at most two rows per fixel.  */
#define MAX_PROBLEM_BYTES ((size_t) 256 << 20)
#define MAX_CERTIFICATE_BYTES ((size_t) 64 << 20)

/* Read the whole of path ("-": stdin), at most max bytes, into a malloc'd
   buffer.  */
static int
read_all(char ** text, size_t * len, const char * path, size_t max,
         wc_error_t err)
{
    FILE * f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    size_t alloc = 4096, n = 0, r;
    char * buf = NULL;
    int status = WC_OK;

    if (f == NULL)
        return wc_error_set(err, WC_EINPUT, path, 0, 0, "cannot open: %s",
                            strerror(errno));
    buf = malloc(alloc);
    while (buf != NULL && (r = fread(buf + n, 1, alloc - n, f)) > 0)
    {
        n += r;
        if (n > max)
        {
            status = wc_error_set(err, WC_EINPUT, path, 0, 0,
                                  "file too large (over %lu bytes)",
                                  (unsigned long) max);
            break;
        }
        if (n == alloc)
        {
            char * p = realloc(buf, alloc *= 2);

            if (p == NULL)
                free(buf);
            buf = p;
        }
    }
    if (status != WC_OK)
        ;
    else if (buf == NULL)
        status = wc_error_set(err, WC_EINTERNAL, path, 0, 0, "out of memory");
    else if (ferror(f))
        /* A directory is a wrong argument; anything else is an I/O
           failure.  */
        status = wc_error_set(err, errno == EISDIR ? WC_EINPUT : WC_EINTERNAL,
                              path, 0, 0, "read error: %s", strerror(errno));
    if (f != stdin)
        fclose(f);
    if (status != WC_OK)
    {
        free(buf);
        return status;
    }
    *text = buf;
    *len = n;
    return WC_OK;
}

static int
load_problem(wc_problem_t P, const char * path, wc_error_t err)
{
    char * text = NULL;
    size_t len = 0;
    int status = read_all(&text, &len, path, MAX_PROBLEM_BYTES, err);

    if (status == WC_OK)
        status = wc_problem_parse(P, text, len,
                                  strcmp(path, "-") == 0 ? "<stdin>" : path,
                                  err);
    free(text);
    return status;
}

static int
parse_format(out_format * f, const char * s, int allow_cdd)
{
    if (strcmp(s, "text") == 0)
        *f = FMT_TEXT;
    else if (strcmp(s, "json") == 0)
        *f = FMT_JSON;
    else if (allow_cdd && strcmp(s, "cdd") == 0)
        *f = FMT_CDD;
    else if (allow_cdd && strcmp(s, "ine") == 0)
        *f = FMT_INE;
    else if (allow_cdd && strcmp(s, "ext") == 0)
        *f = FMT_EXT;
    else
        return 0;
    return 1;
}

/* Flush stdout; a failed write is an I/O failure (exit 3).  */
static int
finish_output(void)
{
    if (fflush(stdout) != 0 || ferror(stdout))
    {
        fprintf(stderr, PROG ": write error: %s\n", strerror(errno));
        return WC_EINTERNAL;
    }
    return WC_OK;
}

enum { OPT_FORMAT = 256, OPT_METHOD, OPT_TRACE, OPT_WITNESS, OPT_CERT,
       OPT_ARITH, OPT_BIAS, OPT_LENGTH, OPT_MAXMODES, OPT_COMPLETE,
       OPT_FRICTION, OPT_CRITICAL, OPT_WIDTH, OPT_MAXFRICTION };

/* Which options a command takes, beyond --format, --help, --version.  */
enum { TAKES_CDD = 1, TAKES_METHOD = 2, TAKES_TRACE = 4, TAKES_WITNESS = 8,
       TAKES_CERT = 16, TAKES_ARITH = 32, TAKES_BIAS = 64,
       TAKES_MAXMODES = 128, TAKES_COMPLETE = 256, TAKES_SWEEP = 512 };

typedef struct
{
    out_format fmt;
    wc_method method;
    int trace;
    int witness;
    const char * certificate;
    int arith_double;   /* --arith=double */
    const char * bias;  /* --bias=FX,FY,TAU */
    const char * length;    /* --length=L */
    long max_modes;     /* --max-modes=N */
    int complete;       /* --complete */
    const char * friction;  /* --friction=LIST */
    int critical;       /* --critical */
    const char * width;     /* --width=W */
    const char * max_friction;  /* --max-friction=M */
}
options;

/* Parse the options of command cmd; operands are left in argv[optind..].
   Returns -1 to go on, or the exit status (help and version print and
   return 0; bad usage returns 2).  */
static int
parse_options(options * o, int argc, char ** argv, const char * cmd,
              unsigned takes, void (*help)(FILE *))
{
    static const struct option opts[] = {
        { "format", required_argument, NULL, OPT_FORMAT },
        { "method", required_argument, NULL, OPT_METHOD },
        { "trace", no_argument, NULL, OPT_TRACE },
        { "witness", no_argument, NULL, OPT_WITNESS },
        { "certificate", required_argument, NULL, OPT_CERT },
        { "arith", required_argument, NULL, OPT_ARITH },
        { "bias", required_argument, NULL, OPT_BIAS },
        { "length", required_argument, NULL, OPT_LENGTH },
        { "max-modes", required_argument, NULL, OPT_MAXMODES },
        { "complete", no_argument, NULL, OPT_COMPLETE },
        { "friction", required_argument, NULL, OPT_FRICTION },
        { "critical", no_argument, NULL, OPT_CRITICAL },
        { "width", required_argument, NULL, OPT_WIDTH },
        { "max-friction", required_argument, NULL, OPT_MAXFRICTION },
        { "help", no_argument, NULL, 'h' },
        { "version", no_argument, NULL, 'V' },
        { NULL, 0, NULL, 0 }
    };
    int c, idx = 0;

    o->fmt = FMT_TEXT;
    o->method = WC_METHOD_DIRECT;
    o->trace = 0;
    o->witness = 0;
    o->certificate = NULL;
    o->arith_double = 0;
    o->bias = NULL;
    o->length = NULL;
    o->max_modes = 1000;
    o->complete = 0;
    o->friction = NULL;
    o->critical = 0;
    o->width = NULL;
    o->max_friction = NULL;
    opterr = 0;
    optind = 1;
    while ((c = getopt_long(argc, argv, "hV", opts, &idx)) != -1)
    {
        if ((c == OPT_METHOD && !(takes & TAKES_METHOD))
            || (c == OPT_TRACE && !(takes & TAKES_TRACE))
            || (c == OPT_WITNESS && !(takes & TAKES_WITNESS))
            || (c == OPT_CERT && !(takes & TAKES_CERT))
            || (c == OPT_ARITH && !(takes & TAKES_ARITH))
            || ((c == OPT_BIAS || c == OPT_LENGTH) && !(takes & TAKES_BIAS))
            || (c == OPT_MAXMODES && !(takes & TAKES_MAXMODES))
            || (c == OPT_COMPLETE && !(takes & TAKES_COMPLETE))
            || ((c == OPT_FRICTION || c == OPT_CRITICAL || c == OPT_WIDTH
                 || c == OPT_MAXFRICTION) && !(takes & TAKES_SWEEP)))
            return usage_error(cmd, "option '--%s' does not apply here",
                               opts[idx].name);
        switch (c)
        {
        case OPT_FORMAT:
            if (!parse_format(&o->fmt, optarg, (takes & TAKES_CDD) != 0))
                return usage_error(cmd, (takes & TAKES_CDD)
                                   ? "unknown format '%s' (text, json, cdd, ine or ext)"
                                   : "unknown format '%s' (text or json)", optarg);
            break;
        case OPT_METHOD:
            if (strcmp(optarg, "direct") == 0)
                o->method = WC_METHOD_DIRECT;
            else if (strcmp(optarg, "paper") == 0)
                o->method = WC_METHOD_PAPER;
            else
                return usage_error(cmd, "unknown method '%s' (direct or paper)",
                                   optarg);
            break;
        case OPT_TRACE:
            o->trace = 1;
            break;
        case OPT_WITNESS:
            o->witness = 1;
            break;
        case OPT_CERT:
            o->certificate = optarg;
            break;
        case OPT_ARITH:
            if (strcmp(optarg, "exact") == 0 || strcmp(optarg, "double") == 0)
                o->arith_double = optarg[0] == 'd';
            else
                return usage_error(cmd, "unknown arithmetic '%s' (exact or double)",
                                   optarg);
            break;
        case OPT_BIAS:
            o->bias = optarg;
            break;
        case OPT_LENGTH:
            o->length = optarg;
            break;
        case OPT_MAXMODES:
        {
            char * end;

            errno = 0;
            o->max_modes = strtol(optarg, &end, 10);
            if (*optarg == '\0' || *end != '\0' || errno != 0
                || o->max_modes < 0)
                return usage_error(cmd, "--max-modes takes a count >= 0 "
                                   "(0: no limit), not '%s'", optarg);
            break;
        }
        case OPT_COMPLETE:
            o->complete = 1;
            break;
        case OPT_FRICTION:
            o->friction = optarg;
            break;
        case OPT_CRITICAL:
            o->critical = 1;
            break;
        case OPT_WIDTH:
            o->width = optarg;
            break;
        case OPT_MAXFRICTION:
            o->max_friction = optarg;
            break;
        case 'h':
            help(stdout);
            return finish_output();
        case 'V':
            version();
            return finish_output();
        default:
            return usage_error(cmd, "unknown or incomplete option '%s'",
                               argv[optind - 1]);
        }
    }
    return -1;
}

/* cone --method=paper --arith=double: the float baseline, printed by
   floatcone.c.  */
static int
cone_double(const options * o, const char * path, const char * mode)
{
    wc_problem_t P;
    wc_error_t err;
    wc_fcone_t W;
    int status;

    wc_problem_init(P);
    wc_error_init(err);
    wc_fcone_init(W, 3);
    status = load_problem(P, path, err);
    if (status == WC_OK)
        status = wc_wrench_cone_paper_double(W, P, mode, WC_FCONE_EPS, err);
    if (status != WC_OK)
    {
        report(err, status);
        goto cleanup;
    }
    switch (o->fmt)
    {
    case FMT_TEXT:
        printf("W(%s): wrench cone of mode %s\n", mode, mode);
        wc_fcone_fprint(stdout, W, WC_FCONE_TEXT);
        break;
    case FMT_JSON:
        fputs("{\"mode\": ", stdout);
        wc_fprint_json_string(stdout, mode);
        fputs(", \"cone\": ", stdout);
        wc_fcone_fprint(stdout, W, WC_FCONE_JSON);
        fputs("}\n", stdout);
        break;
    default:
        printf("* wrenchcone: W(%s), the wrench cone of mode %s\n", mode, mode);
        wc_fcone_fprint(stdout, W, o->fmt == FMT_INE ? WC_FCONE_INE
                        : o->fmt == FMT_EXT ? WC_FCONE_EXT : WC_FCONE_CDD);
        break;
    }
    status = finish_output();

cleanup:
    wc_fcone_clear(W);
    wc_error_clear(err);
    wc_problem_clear(P);
    return status;
}

static int
cmd_cone(int argc, char ** argv)
{
    options o;
    int status;
    const char * path, * mode;
    wc_problem_t P;
    wc_error_t err;
    wc_cone_t W;
    wc_trace_t T;

    if ((status = parse_options(&o, argc, argv, "cone",
                                TAKES_CDD | TAKES_METHOD | TAKES_TRACE
                                | TAKES_ARITH, usage_cone)) >= 0)
        return status;
    if (o.arith_double && o.method != WC_METHOD_PAPER)
        return usage_error("cone", "--arith=double needs --method=paper%s", "");
    if (o.arith_double && o.trace)
        return usage_error("cone", "--arith=double does not take --trace%s", "");
    if (argc - optind != 2)
        return usage_error("cone", argc - optind < 2
                           ? "cone needs PROBLEM and MODE%s"
                           : "cone takes PROBLEM and MODE only%s", "");
    path = argv[optind];
    mode = argv[optind + 1];
    if (o.arith_double)
        return cone_double(&o, path, mode);

    wc_problem_init(P);
    wc_error_init(err);
    wc_cone_init(W, 3);
    wc_trace_init(T);
    status = load_problem(P, path, err);
    if (status == WC_OK)
        status = wc_mode_check(P, mode, WC_TABLE_CONE, err);
    if (status == WC_OK)
        status = wc_wrench_cone(W, o.trace ? T : NULL, P, mode, o.method, err);
    if (status != WC_OK)
    {
        report(err, status);
        goto cleanup;
    }

    switch (o.fmt)
    {
    case FMT_TEXT:
        if (o.trace)
        {
            printf("trace (%s route):\n", o.method == WC_METHOD_PAPER
                   ? "paper, Section 5" : "direct, M V_x + (-J) D_x");
            wc_trace_fprint_text(stdout, T, "  ");
            putchar('\n');
        }
        printf("W(%s): wrench cone of mode %s\n", mode, mode);
        wc_cone_fprint_text(stdout, W, "  ");
        break;
    case FMT_JSON:
        fputs("{\"mode\": ", stdout);
        wc_fprint_json_string(stdout, mode);
        fputs(", \"cone\": ", stdout);
        wc_cone_fprint_json(stdout, W);
        if (o.trace)
        {
            fprintf(stdout, ", \"method\": \"%s\", \"trace\": ",
                    o.method == WC_METHOD_PAPER ? "paper" : "direct");
            wc_trace_fprint_json(stdout, T);
        }
        fputs("}\n", stdout);
        break;
    default:
        {
            size_t len = strlen(mode) + 64;
            char * title = malloc(len);

            if (title != NULL)
                snprintf(title, len, "wrenchcone: W(%s), the wrench cone of mode %s",
                         mode, mode);
            if (o.trace)
                wc_trace_fprint_text(stdout, T, "* ");
            wc_cone_fprint_cdd(stdout, W, title, o.fmt == FMT_INE ? 1
                               : o.fmt == FMT_EXT ? 2 : 3);
            free(title);
        }
        break;
    }
    status = finish_output();

cleanup:
    wc_trace_clear(T);
    wc_cone_clear(W);
    wc_error_clear(err);
    wc_problem_clear(P);
    return status;
}

static int
cmd_modes(int argc, char ** argv)
{
    options o;
    int status;
    wc_problem_t P;
    wc_error_t err;
    wc_modes_t M;

    if ((status = parse_options(&o, argc, argv, "modes", TAKES_WITNESS,
                                usage_modes)) >= 0)
        return status;
    if (argc - optind != 1)
        return usage_error("modes", argc - optind < 1
                           ? "modes needs PROBLEM%s"
                           : "modes takes PROBLEM only%s", "");
    wc_problem_init(P);
    wc_error_init(err);
    wc_modes_init(M);
    status = load_problem(P, argv[optind], err);
    if (status == WC_OK)
        status = wc_modes_enumerate(M, P, err);
    if (status != WC_OK)
        report(err, status);
    else
    {
        wc_modes_fprint(stdout, M, o.fmt == FMT_JSON, o.witness);
        status = finish_output();
    }
    wc_modes_clear(M);
    wc_error_clear(err);
    wc_problem_clear(P);
    return status;
}

/* Write a certificate to path with put(f, data): no partial file is
   left, but only a file this run created is ever removed -- never a
   device or someone's file.  */
static int
write_certificate(const char * path, int (*put)(FILE *, const void *),
                  const void * data)
{
    struct stat st;
    int existed = stat(path, &st) == 0;
    FILE * f = fopen(path, "w");
    int bad = f == NULL;

    if (f != NULL)
    {
        bad = put(f, data) != WC_OK;
        bad |= fclose(f) != 0;
        if (bad && !existed)
            remove(path);
    }
    if (bad)
    {
        fprintf(stderr, PROG ": %s: cannot write the certificate: %s\n",
                path, strerror(errno));
        return WC_EINTERNAL;
    }
    return WC_OK;
}

typedef struct
{
    const wc_problem_struct * P;
    const void * C;
}
cert_job;

static int
put_feasibility(FILE * f, const void * p)
{
    const cert_job * j = p;

    return wc_certificate_fprint(f, j->C, j->P, 1);
}

static int
put_stability(FILE * f, const void * p)
{
    const cert_job * j = p;

    return wc_classify_certificate_fprint(f, j->P, j->C);
}

static int
cmd_feasible(int argc, char ** argv)
{
    options o;
    int status;
    wc_problem_t P;
    wc_error_t err;
    wc_certificate_t C;

    if ((status = parse_options(&o, argc, argv, "feasible", TAKES_CERT,
                                usage_feasible)) >= 0)
        return status;
    if (argc - optind != 2)
        return usage_error("feasible", argc - optind < 2
                           ? "feasible needs PROBLEM and MODE%s"
                           : "feasible takes PROBLEM and MODE only%s", "");
    wc_problem_init(P);
    wc_error_init(err);
    wc_certificate_init(C);
    status = load_problem(P, argv[optind], err);
    if (status == WC_OK)
        status = wc_feasible(C, P, argv[optind + 1], err);
    if (status != WC_OK)
    {
        report(err, status);
        goto cleanup;
    }
    if (o.certificate != NULL)
    {
        cert_job j = { P, C };

        if ((status = write_certificate(o.certificate, put_feasibility, &j))
            != WC_OK)
            goto cleanup;
    }
    wc_certificate_fprint(stdout, C, P, o.fmt == FMT_JSON);
    status = finish_output();

cleanup:
    wc_certificate_clear(C);
    wc_error_clear(err);
    wc_problem_clear(P);
    return status;
}

static int
cmd_verify(int argc, char ** argv)
{
    options o;
    int status, holds = 0, feasible = 0;
    char * text = NULL, * reason = NULL, * mode = NULL, * summary = NULL;
    const char * path;
    size_t len = 0;
    wc_error_t err;

    if ((status = parse_options(&o, argc, argv, "verify", 0,
                                usage_verify)) >= 0)
        return status;
    if (argc - optind != 1)
        return usage_error("verify", argc - optind < 1
                           ? "verify needs CERTFILE%s"
                           : "verify takes CERTFILE only%s", "");
    path = argv[optind];
    wc_error_init(err);
    status = read_all(&text, &len, path, MAX_CERTIFICATE_BYTES, err);
    if (status == WC_OK)
        status = wc_verify(&holds, &reason, &summary, text, len,
                           strcmp(path, "-") == 0 ? "<stdin>" : path, err);
    if (status != WC_OK)
    {
        report(err, status);
        goto cleanup;
    }
    if (o.fmt == FMT_JSON)
    {
        wc_error_t e2;
        int h2;
        char * r2 = NULL;

        /* A mode-feasibility certificate also gives its mode and verdict
           as keys.  */
        wc_error_init(e2);
        if (wc_verify_certificate(&h2, &r2, &mode, &feasible, text, len,
                                  path, e2) != WC_OK)
            mode = NULL;
        free(r2);
        wc_error_clear(e2);
        fprintf(stdout, "{\"holds\": %s", holds ? "true" : "false");
        if (mode != NULL)
        {
            fputs(", \"mode\": ", stdout);
            wc_fprint_json_string(stdout, mode);
            fprintf(stdout, ", \"feasible\": %s", feasible ? "true" : "false");
        }
        else
        {
            fputs(", \"summary\": ", stdout);
            wc_fprint_json_string(stdout, summary != NULL ? summary : "");
        }
        if (!holds)
        {
            fputs(", \"reason\": ", stdout);
            wc_fprint_json_string(stdout, reason != NULL ? reason : "");
        }
        fputs("}\n", stdout);
    }
    else if (holds)
        printf("certificate holds: %s\n", summary);
    else
        printf("certificate does not hold: %s\n", reason);
    status = finish_output();
    if (status == WC_OK && !holds)
        status = WC_EDISAGREE;

cleanup:
    free(text);
    free(reason);
    free(mode);
    free(summary);
    wc_error_clear(err);
    return status;
}

/* 1 when s is a decimal integer (digits only) no larger than max.  */
static int
parse_uint(uint64_t * v, const char * s, uint64_t max)
{
    uint64_t x = 0;

    if (*s == '\0')
        return 0;
    for (; *s != '\0'; s++)
    {
        if (*s < '0' || *s > '9' || x > (max - (uint64_t) (*s - '0')) / 10)
            return 0;
        x = 10 * x + (uint64_t) (*s - '0');
    }
    *v = x;
    return 1;
}

/* MU or MU,MUK: exact non-negative numbers.  */
static int
parse_friction_arg(wc_random_options * ro, const char * s)
{
    const char * comma = strchr(s, ',');
    size_t len = comma != NULL ? (size_t) (comma - s) : strlen(s);
    wc_error_t err;
    int ok;

    wc_error_init(err);
    ok = wc_parse_number(ro->mu_s, s, len, err) == WC_OK
        && fmpq_sgn(ro->mu_s) >= 0;
    if (ok && comma != NULL)
        ok = wc_parse_number(ro->mu_k, comma + 1, strlen(comma + 1), err)
            == WC_OK && fmpq_sgn(ro->mu_k) >= 0;
    else if (ok)
        fmpq_set(ro->mu_k, ro->mu_s);
    wc_error_clear(err);
    ro->friction = 1;
    return ok;
}

static int
cmd_random(int argc, char ** argv)
{
    enum { R_FIXELS = 256, R_SEED, R_DEGENERATE, R_SHAPE, R_FRICTION,
           R_FORMAT };
    static const struct option opts[] = {
        { "fixels", required_argument, NULL, R_FIXELS },
        { "seed", required_argument, NULL, R_SEED },
        { "degenerate", no_argument, NULL, R_DEGENERATE },
        { "shape", required_argument, NULL, R_SHAPE },
        { "friction", required_argument, NULL, R_FRICTION },
        { "format", required_argument, NULL, R_FORMAT },
        { "help", no_argument, NULL, 'h' },
        { "version", no_argument, NULL, 'V' },
        { NULL, 0, NULL, 0 }
    };
    wc_random_options ro;
    wc_problem_t P;
    wc_error_t err;
    char * line = NULL;
    uint64_t v;
    int c, status = -1;

    wc_random_options_init(&ro);
    opterr = 0;
    optind = 1;
    while (status < 0 && (c = getopt_long(argc, argv, "hV", opts, NULL)) != -1)
    {
        switch (c)
        {
        case R_FIXELS:
            if (!parse_uint(&v, optarg, WC_RANDOM_MAX_FIXELS) || v < 1)
                status = usage_error("random", "--fixels must be an integer "
                                     "from 1 to 1000, not '%s'", optarg);
            else
                ro.fixels = (slong) v;
            break;
        case R_SEED:
            if (!parse_uint(&v, optarg, UINT64_MAX))
                status = usage_error("random", "--seed must be a decimal "
                                     "integer from 0 to 2^64 - 1, not '%s'",
                                     optarg);
            else
                ro.seed = v;
            break;
        case R_DEGENERATE:
            ro.degenerate = 1;
            break;
        case R_SHAPE:
            if (strcmp(optarg, "none") == 0)
                ro.shape = WC_SHAPE_NONE;
            else if (strcmp(optarg, "disk") == 0)
                ro.shape = WC_SHAPE_DISK;
            else if (strcmp(optarg, "polygon") == 0)
                ro.shape = WC_SHAPE_POLYGON;
            else
                status = usage_error("random", "unknown shape '%s' (none, disk "
                                     "or polygon)", optarg);
            break;
        case R_FRICTION:
            if (!parse_friction_arg(&ro, optarg))
                status = usage_error("random", "--friction must be MU or MU,MUK, "
                                     "exact non-negative numbers such as 1/5 "
                                     "or 0.2, not '%s'", optarg);
            break;
        case R_FORMAT:
            if (strcmp(optarg, "text") != 0)
                status = usage_error("random", "unknown format '%s' (random "
                                     "prints a .wc file: text only)", optarg);
            break;
        case 'h':
            usage_random(stdout);
            status = finish_output();
            break;
        case 'V':
            version();
            status = finish_output();
            break;
        default:
            status = usage_error("random", "unknown or incomplete option '%s'",
                                 argv[optind - 1]);
            break;
        }
    }
    if (status < 0 && optind < argc)
        status = usage_error("random", "random takes no operands, not '%s'",
                             argv[optind]);
    if (status >= 0)
    {
        wc_random_options_clear(&ro);
        return status;
    }

    wc_problem_init(P);
    wc_error_init(err);
    status = wc_random_problem(P, &ro, err);
    if (status == WC_OK && (line = wc_random_options_str(&ro)) == NULL)
        status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    if (status != WC_OK)
        report(err, status);
    else
    {
        printf("# " PROG " random %s\n", line);
        status = wc_problem_fprint(stdout, P);
        if (status == WC_OK)
            status = finish_output();
        else
            fprintf(stderr, PROG ": write error: %s\n", strerror(errno));
    }
    free(line);
    wc_error_clear(err);
    wc_problem_clear(P);
    wc_random_options_clear(&ro);
    return status;
}

static int
cmd_compare(int argc, char ** argv)
{
    enum { C_TOL = 256, C_FORMAT };
    static const struct option opts[] = {
        { "tol", required_argument, NULL, C_TOL },
        { "format", required_argument, NULL, C_FORMAT },
        { "help", no_argument, NULL, 'h' },
        { "version", no_argument, NULL, 'V' },
        { NULL, 0, NULL, 0 }
    };
    double tol = WC_COMPARE_TOL;
    int json = 0, c, status = -1;
    const char * ppath, * mode, * fpath, * pname, * fname;
    char * text = NULL, * end;
    size_t len = 0;
    wc_problem_t P;
    wc_error_t err;
    wc_cone_t W;
    wc_foreign_t F;
    wc_comparison_t R;

    opterr = 0;
    optind = 1;
    while (status < 0 && (c = getopt_long(argc, argv, "hV", opts, NULL)) != -1)
    {
        switch (c)
        {
        case C_TOL:
            tol = strtod(optarg, &end);
            if (end == optarg || *end != '\0' || !(tol >= 0 && tol < 1.5707963))
                status = usage_error("compare", "--tol must be an angle in "
                                     "radians, at least 0 and below pi/2 "
                                     "(such as 1e-9), not '%s'", optarg);
            break;
        case C_FORMAT:
            if (strcmp(optarg, "text") == 0 || strcmp(optarg, "json") == 0)
                json = strcmp(optarg, "json") == 0;
            else
                status = usage_error("compare", "unknown format '%s' (text "
                                     "or json)", optarg);
            break;
        case 'h':
            usage_compare(stdout);
            status = finish_output();
            break;
        case 'V':
            version();
            status = finish_output();
            break;
        default:
            status = usage_error("compare", "unknown or incomplete option '%s'",
                                 argv[optind - 1]);
            break;
        }
    }
    if (status >= 0)
        return status;
    if (argc - optind != 3)
        return usage_error("compare", argc - optind < 3
                           ? "compare needs PROBLEM, MODE and FILE%s"
                           : "compare takes PROBLEM, MODE and FILE only%s", "");
    ppath = argv[optind];
    mode = argv[optind + 1];
    fpath = argv[optind + 2];
    if (strcmp(ppath, "-") == 0 && strcmp(fpath, "-") == 0)
        return usage_error("compare", "PROBLEM and FILE cannot both be "
                           "standard input%s", "");
    pname = strcmp(ppath, "-") == 0 ? "<stdin>" : ppath;
    fname = strcmp(fpath, "-") == 0 ? "<stdin>" : fpath;

    wc_problem_init(P);
    wc_error_init(err);
    wc_cone_init(W, 3);
    wc_foreign_init(F);
    wc_comparison_init(R);
    status = load_problem(P, ppath, err);
    if (status == WC_OK)
        status = wc_mode_check(P, mode, WC_TABLE_CONE, err);
    if (status == WC_OK)
        status = read_all(&text, &len, fpath, MAX_PROBLEM_BYTES, err);
    if (status == WC_OK)
        status = wc_foreign_parse(F, text, len, fname, err);
    if (status == WC_OK)
        status = wc_wrench_cone(W, NULL, P, mode, WC_METHOD_DIRECT, err);
    if (status == WC_OK)
        status = wc_compare(R, W, mode, F, tol, err);
    if (status != WC_OK)
        report(err, status);
    else
    {
        wc_comparison_fprint(stdout, R, W, pname, mode, fname, json);
        status = finish_output();
        if (status == WC_OK && R->differs != 0)
            status = WC_EDISAGREE;
    }
    free(text);
    wc_comparison_clear(R);
    wc_foreign_clear(F);
    wc_cone_clear(W);
    wc_error_clear(err);
    wc_problem_clear(P);
    return status;
}


/* Parse the exact numbers of argv[0..k) as one vector; a bad one is an
   input error located in "<what>" by its column in the operands joined
   with single spaces.  */
static int
parse_numbers(fmpq * v, char ** args, slong k, const char * what,
              wc_error_t err)
{
    slong i, col = 1;

    for (i = 0; i < k; i++)
    {
        if (wc_parse_number(v + i, args[i], strlen(args[i]), err) != WC_OK)
        {
            char * why = wc_error_format(err);
            int st = wc_error_set(err, WC_EINPUT, what, 1, col, "%s",
                                  why != NULL ? why : "bad number");

            free(why);
            return st;
        }
        col += strlen(args[i]) + 1;
    }
    return WC_OK;
}

static int
cmd_classify(int argc, char ** argv)
{
    options o;
    int status;
    wc_problem_t P;
    wc_error_t err;
    wc_classify_t R;
    fmpq g[3];
    slong k;

    if ((status = parse_options(&o, argc, argv, "classify",
                                TAKES_CERT | TAKES_MAXMODES,
                                usage_classify)) >= 0)
        return status;
    if (argc - optind != 4)
        return usage_error("classify", argc - optind < 4
                           ? "classify needs PROBLEM FX FY TAU%s"
                           : "classify takes PROBLEM FX FY TAU only%s", "");
    wc_problem_init(P);
    wc_error_init(err);
    wc_classify_init(R);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    status = load_problem(P, argv[optind], err);
    if (status == WC_OK)
        status = parse_numbers(g, argv + optind + 1, 3, "<wrench>", err);
    if (status == WC_OK)
        status = wc_classify(R, P, g, o.certificate != NULL, o.max_modes,
                             err);
    if (status != WC_OK)
    {
        report(err, status);
        goto cleanup;
    }
    if (o.certificate != NULL)
    {
        cert_job j = { P, R };

        if ((status = write_certificate(o.certificate, put_stability, &j))
            != WC_OK)
            goto cleanup;
    }
    wc_classify_fprint(stdout, R, o.fmt == FMT_JSON);
    status = finish_output();

cleanup:
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    wc_classify_clear(R);
    wc_error_clear(err);
    wc_problem_clear(P);
    return status;
}

/* The robustness of the biasing wrench b in both strong sets.  */
static int
print_bias(const wc_stability_t S, const fmpq * b, const fmpq_t L, int json,
           wc_error_t err)
{
    const wc_set_struct * sets[2] = { S->strong, S->strong_paper };
    const char * names[2] = { "exact", "paper" };
    fmpq_t rho;
    int i, closed, infinite, status = WC_OK;

    fmpq_init(rho);
    if (json)
    {
        fputs(", \"bias\": {\"wrench\": [", stdout);
        for (i = 0; i < 3; i++)
        {
            fputs(i ? ", \"" : "\"", stdout);
            wc_fprint_fmpq(stdout, b + i);
            putchar('"');
        }
        fputs("], \"length\": \"", stdout);
        wc_fprint_fmpq(stdout, L);
        putchar('"');
    }
    else
    {
        fputs("biasing wrench b = (", stdout);
        for (i = 0; i < 3; i++)
        {
            if (i)
                fputs(", ", stdout);
            wc_fprint_fmpq(stdout, b + i);
        }
        fputs("), disturbances measured by max(|fx|, |fy|, |tau| / ", stdout);
        wc_fprint_fmpq(stdout, L);
        fputs("):\n", stdout);
    }
    for (i = 0; i < 2 && status == WC_OK; i++)
    {
        status = wc_robustness(rho, &closed, &infinite, sets[i], S->cells, b,
                               L, err);
        if (status != WC_OK)
            break;
        if (json)
        {
            fprintf(stdout, ", \"%s\": {\"in_set\": %s, ", i == 0 ? "strong"
                    : "strong_paper", wc_set_contains(sets[i], b)
                    ? "true" : "false");
            if (infinite)
                fputs("\"rho\": null, \"unbounded\": true}", stdout);
            else
            {
                fputs("\"rho\": \"", stdout);
                wc_fprint_fmpq(stdout, rho);
                fprintf(stdout, "\", \"closed\": %s}",
                        closed ? "true" : "false");
            }
        }
        else if (infinite)
            printf("  %s: every disturbance keeps it strongly stable (the set "
                   "is all of R^3)\n", names[i]);
        else if (fmpq_is_zero(rho))
            printf("  %s: rho = 0: b is %s\n", names[i],
                   wc_set_contains(sets[i], b)
                   ? "on the boundary of the strongly stable set"
                   : "not strongly stable");
        else
        {
            printf("  %s: rho = ", names[i]);
            wc_fprint_fmpq(stdout, rho);
            printf(": every disturbance d with ||d|| %s rho leaves b + d "
                   "strongly stable%s\n", closed ? "<=" : "<",
                   closed ? "" : " (some d with ||d|| = rho does not)");
        }
    }
    if (json && status == WC_OK)
        putchar('}');
    fmpq_clear(rho);
    return status;
}

static int
cmd_stability(int argc, char ** argv)
{
    options o;
    int status;
    wc_problem_t P;
    wc_error_t err;
    wc_stability_t S;
    fmpq b[3];
    fmpq_t L;
    slong k;
    char * bias[3] = { NULL, NULL, NULL }, * copy = NULL;

    if ((status = parse_options(&o, argc, argv, "stability", TAKES_BIAS,
                                usage_stability)) >= 0)
        return status;
    if (argc - optind != 1)
        return usage_error("stability", argc - optind < 1
                           ? "stability needs PROBLEM%s"
                           : "stability takes PROBLEM only%s", "");
    if (o.bias != NULL)
    {
        char * p;

        copy = malloc(strlen(o.bias) + 1);
        strcpy(copy, o.bias);
        bias[0] = copy;
        for (k = 1, p = copy; k < 3 && (p = strchr(p, ',')) != NULL; k++)
        {
            *p++ = '\0';
            bias[k] = p;
        }
        if (k < 3 || strchr(bias[2], ',') != NULL)
        {
            free(copy);
            return usage_error("stability", "--bias takes three numbers "
                               "FX,FY,TAU, not '%s'", o.bias);
        }
    }
    wc_problem_init(P);
    wc_error_init(err);
    wc_stability_init(S);
    for (k = 0; k < 3; k++)
        fmpq_init(b + k);
    fmpq_init(L);
    fmpq_one(L);
    status = load_problem(P, argv[optind], err);
    if (status == WC_OK && o.bias != NULL)
        status = parse_numbers(b, bias, 3, "<bias>", err);
    if (status == WC_OK && o.length != NULL)
    {
        status = parse_numbers(L, (char **) &o.length, 1, "<length>", err);
        if (status == WC_OK && fmpq_sgn(L) <= 0)
            status = wc_error_set(err, WC_EINPUT, "<length>", 1, 1,
                                  "the length must be positive");
    }
    if (status == WC_OK)
        status = wc_stability(S, P, err);
    if (status != WC_OK)
    {
        report(err, status);
        goto cleanup;
    }
    /* Everything is computed before anything is printed.  */
    if (o.bias != NULL)
    {
        fmpq_t rho;
        int closed, infinite;

        fmpq_init(rho);
        status = wc_robustness(rho, &closed, &infinite, S->strong, S->cells,
                               b, L, err);
        fmpq_clear(rho);
        if (status != WC_OK)
        {
            report(err, status);
            goto cleanup;
        }
    }
    if (o.fmt == FMT_JSON)
    {
        wc_stability_fprint(stdout, S, 2);
        if (o.bias != NULL && (status = print_bias(S, b, L, 1, err)) != WC_OK)
        {
            report(err, status);
            goto cleanup;
        }
        fputs("}\n", stdout);
    }
    else
    {
        wc_stability_fprint(stdout, S, 0);
        if (o.bias != NULL && (status = print_bias(S, b, L, 0, err)) != WC_OK)
        {
            report(err, status);
            goto cleanup;
        }
    }
    status = finish_output();

cleanup:
    free(copy);
    for (k = 0; k < 3; k++)
        fmpq_clear(b + k);
    fmpq_clear(L);
    wc_stability_clear(S);
    wc_error_clear(err);
    wc_problem_clear(P);
    return status;
}

static int
cmd_plan(int argc, char ** argv)
{
    options o;
    int status, with_wrench;
    wc_problem_t P;
    wc_error_t err;
    wc_plan_t R;
    wc_plan_wrench_t W;
    fmpq g[3];
    slong k;

    if ((status = parse_options(&o, argc, argv, "plan", TAKES_COMPLETE,
                                usage_plan)) >= 0)
        return status;
    if (argc - optind != 1 && argc - optind != 4)
        return usage_error("plan", argc - optind < 1
                           ? "plan needs PROBLEM%s"
                           : "plan takes PROBLEM and optionally FX FY TAU%s",
                           "");
    with_wrench = argc - optind == 4;
    wc_problem_init(P);
    wc_error_init(err);
    wc_plan_init(R);
    wc_plan_wrench_init(W);
    for (k = 0; k < 3; k++)
        fmpq_init(g + k);
    status = load_problem(P, argv[optind], err);
    if (status == WC_OK && with_wrench)
        status = parse_numbers(g, argv + optind + 1, 3, "<wrench>", err);
    if (status == WC_OK)
        status = with_wrench ? wc_plan_wrench(W, P, g, o.complete, err)
            : wc_plan(R, P, o.complete, err);
    if (status != WC_OK)
    {
        report(err, status);
        goto cleanup;
    }
    if (with_wrench)
        wc_plan_wrench_fprint(stdout, W, o.fmt == FMT_JSON);
    else
        wc_plan_fprint(stdout, R, P, o.fmt == FMT_JSON);
    status = finish_output();

cleanup:
    for (k = 0; k < 3; k++)
        fmpq_clear(g + k);
    wc_plan_wrench_clear(W);
    wc_plan_clear(R);
    wc_error_clear(err);
    wc_problem_clear(P);
    return status;
}

/* A comma-separated list of exact numbers, located as <what>:1:COL.  */
static int
parse_list(fmpq ** v, slong * count, const char * s, const char * what,
           const char * noun, wc_error_t err)
{
    const char * p = s;
    slong n = 1, i;
    int status = WC_OK;

    for (i = 0; s[i] != '\0'; i++)
        n += s[i] == ',';
    *v = flint_malloc(sizeof(fmpq) * n);
    for (i = 0; i < n; i++)
        fmpq_init(*v + i);
    *count = n;
    for (i = 0; i < n && status == WC_OK; i++)
    {
        const char * e = strchr(p, ',');
        size_t len = e != NULL ? (size_t) (e - p) : strlen(p);

        if (wc_parse_number(*v + i, p, len, err) != WC_OK)
        {
            char * why = wc_error_format(err);

            status = wc_error_set(err, WC_EINPUT, what, 1, p - s + 1, "%s",
                                  why != NULL ? why : "bad number");
            free(why);
        }
        else if (fmpq_sgn(*v + i) < 0)
            status = wc_error_set(err, WC_EINPUT, what, 1, p - s + 1,
                                  "%s must not be negative", noun);
        p += len + 1;
    }
    return status;
}

static int
one_positive(fmpq_t x, const char * s, const char * what, const char * noun,
             wc_error_t err)
{
    fmpq * v = NULL;
    slong n = 0, i;
    int status = parse_list(&v, &n, s, what, noun, err);

    if (status == WC_OK && (n != 1 || fmpq_sgn(v) <= 0))
        status = wc_error_set(err, WC_EINPUT, what, 1, 1,
                              "expected one positive number");
    if (status == WC_OK)
        fmpq_set(x, v);
    for (i = 0; i < n; i++)
        fmpq_clear(v + i);
    flint_free(v);
    return status;
}

/* The critical bracket, with its two certificates: the plan at lo holds
   the witness in G_goal, the plan at hi names the strings whose cones
   cover R^3.  Computed in full before anything is printed.  */
typedef struct
{
    wc_critical_t C;
    wc_plan_t H;
    wc_plan_wrench_t W;
}
crit_job;

static void
crit_init(crit_job * j)
{
    wc_critical_init(j->C);
    wc_plan_init(j->H);
    wc_plan_wrench_init(j->W);
}

static void
crit_clear(crit_job * j)
{
    wc_plan_wrench_clear(j->W);
    wc_plan_clear(j->H);
    wc_critical_clear(j->C);
}

static int
crit_compute(crit_job * j, const wc_problem_t P, const fmpq_t width,
             const fmpq_t max, wc_error_t err)
{
    wc_critical_struct * C = j->C;
    int status = wc_plan_critical(C, P, width, max, err);

    if (status == WC_OK && C->found)
        status = wc_plan_with_friction(j->H, P, C->hi, err);
    if (status == WC_OK && !C->empty_at_zero)
    {
        wc_problem_t Q;
        slong i;

        /* re-check the witness at lo, one cone at a time */
        wc_problem_init(Q);
        status = wc_problem_set(Q, P);
        for (i = 0; i < Q->n && status == WC_OK; i++)
        {
            fmpq_set(Q->fixels[i].mu_s, C->lo);
            fmpq_set(Q->fixels[i].mu_k, C->lo);
        }
        if (status == WC_OK)
            status = wc_plan_wrench(j->W, Q, C->lo_witness, 0, err);
        if (status == WC_OK && !j->W->in_goal)
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: the witness at lo is not "
                                  "in G_goal");
        wc_problem_clear(Q);
    }
    return status;
}

static void
crit_print(const crit_job * j, const fmpq_t width, const fmpq_t max,
           int json)
{
    const wc_critical_struct * C = j->C;
    const wc_plan_struct * H = j->H;
    slong k, m;

    if (json)
    {
        printf("\"critical\": {\"found\": %s, \"lo\": \"",
               C->found ? "true" : "false");
        wc_fprint_fmpq(stdout, C->lo);
        fputs("\", \"hi\": ", stdout);
        if (C->found)
        {
            putchar('"');
            wc_fprint_fmpq(stdout, C->hi);
            putchar('"');
        }
        else
            fputs("null", stdout);
        fputs(", \"width\": \"", stdout);
        wc_fprint_fmpq(stdout, width);
        printf("\", \"plans\": %ld, \"lo_witness\": ", (long) C->evals);
        if (C->empty_at_zero)
            fputs("null", stdout);
        else
            wc_fprint_qvec(stdout, C->lo_witness, 3, 1);
        fputs(", \"hi_cover\": [", stdout);
        for (k = 0, m = 0; C->found && k < H->T->nneeded; k++)
            if (H->exact_needed[k])
                printf("%s\"%s\"", m++ ? ", " : "",
                       H->T->strings[H->T->needed[k]]);
        fputs("]}", stdout);
        return;
    }
    fputs("critical friction (mu_s = mu_k = mu at every fixel; G_goal "
          "shrinks as mu grows):\n", stdout);
    if (C->empty_at_zero)
        fputs("  G_goal is empty already at mu = 0\n", stdout);
    else
    {
        fputs("  lo = ", stdout);
        wc_fprint_fmpq(stdout, C->lo);
        fputs(": G_goal is not empty; g = ", stdout);
        wc_fprint_qvec(stdout, C->lo_witness, 3, 0);
        fputs(" is in the cone of no needed string\n", stdout);
    }
    if (C->found)
    {
        fputs("  hi = ", stdout);
        wc_fprint_fmpq(stdout, C->hi);
        fputs(": G_goal is empty; the cones of", stdout);
        for (k = 0; k < H->T->nneeded; k++)
            if (H->exact_needed[k])
                printf(" %s", H->T->strings[H->T->needed[k]]);
        fputs(" cover R^3\n", stdout);
        if (!C->empty_at_zero)
        {
            fmpq_t w;

            fmpq_init(w);
            fmpq_sub(w, C->hi, C->lo);
            fputs("  hi - lo = ", stdout);
            wc_fprint_fmpq(stdout, w);
            fputs(" <= ", stdout);
            wc_fprint_fmpq(stdout, width);
            printf(" (%ld plans)\n", (long) C->evals);
            fmpq_clear(w);
        }
    }
    else
    {
        fputs("  G_goal is not empty at any mu <= ", stdout);
        wc_fprint_fmpq(stdout, max);
        printf(" (%ld plans)\n", (long) C->evals);
    }
}

static int
cmd_sweep(int argc, char ** argv)
{
    options o;
    int status;
    wc_problem_t P;
    wc_error_t err;
    wc_plan_t R;
    wc_plan_struct * plans = NULL;
    crit_job crit;
    fmpq * mu = NULL;
    fmpq_t width, max;
    slong n = 0, i;
    int json;

    if ((status = parse_options(&o, argc, argv, "sweep", TAKES_SWEEP,
                                usage_sweep)) >= 0)
        return status;
    if (argc - optind != 1)
        return usage_error("sweep", argc - optind < 1
                           ? "sweep needs PROBLEM%s"
                           : "sweep takes PROBLEM only%s", "");
    if (o.friction == NULL && !o.critical)
        return usage_error("sweep", "sweep needs --friction=LIST or "
                           "--critical%s", "");
    json = o.fmt == FMT_JSON;
    wc_problem_init(P);
    wc_error_init(err);
    wc_plan_init(R);
    fmpq_init(width);
    fmpq_init(max);
    fmpq_set_si(width, 1, 1000);
    fmpq_set_si(max, 1024, 1);
    status = load_problem(P, argv[optind], err);
    crit_init(&crit);
    if (status == WC_OK && o.friction != NULL)
        status = parse_list(&mu, &n, o.friction, "<friction>",
                            "a friction coefficient", err);
    if (status == WC_OK && o.width != NULL)
        status = one_positive(width, o.width, "<width>", "the width", err);
    if (status == WC_OK && o.max_friction != NULL)
        status = one_positive(max, o.max_friction, "<max-friction>",
                              "the largest friction", err);
    if (status == WC_OK)
        status = wc_problem_check(P, err);
    if (status == WC_OK && P->n > WC_PLAN_MAX_FIXELS)
        status = wc_plan(R, P, 0, err);     /* says why */
    if (status != WC_OK)
    {
        report(err, status);
        goto cleanup;
    }
    /* Every plan is computed before anything is printed.  */
    plans = flint_malloc(sizeof(wc_plan_struct) * (n + 1));
    for (i = 0; i < n; i++)
        wc_plan_init(plans + i);
    for (i = 0; i < n && status == WC_OK; i++)
        status = wc_plan_with_friction(plans + i, P, mu + i, err);
    if (status == WC_OK && o.critical)
        status = crit_compute(&crit, P, width, max, err);
    if (status != WC_OK)
    {
        report(err, status);
        goto cleanup;
    }
    if (json)
        fputs("{\"sweep\": [", stdout);
    for (i = 0; i < n; i++)
    {
        if (json && i)
            fputs(", ", stdout);
        wc_plan_sweep_fprint(stdout, plans + i, P, mu + i, json);
    }
    if (json)
        fputs(o.critical ? "], " : "]", stdout);
    if (o.critical)
    {
        if (!json && n > 0)
            putchar('\n');
        crit_print(&crit, width, max, json);
    }
    if (json)
        fputs("}\n", stdout);
    status = finish_output();

cleanup:
    crit_clear(&crit);
    for (i = 0; plans != NULL && i < n; i++)
        wc_plan_clear(plans + i);
    flint_free(plans);
    for (i = 0; i < n; i++)
        fmpq_clear(mu + i);
    flint_free(mu);
    fmpq_clear(width);
    fmpq_clear(max);
    wc_plan_clear(R);
    wc_error_clear(err);
    wc_problem_clear(P);
    return status;
}

/* Operands of classify and stability may be negative numbers ("-1"),
   which getopt would take for options: move every argument that is not an
   option (or an option's value) after a "--".  --bias FX FY TAU becomes
   --bias=FX,FY,TAU.  Returns a malloc'd argv (the strings are argv's or
   the one malloc'd *extra).  */
static char **
operands_last(int * pargc, char ** argv, char ** extra)
{
    static const char * const valued[] = {
        "--format", "--certificate", "--length", "--bias", "--max-modes",
        "--friction", "--width", "--max-friction", NULL
    };
    int argc = *pargc, i, j, no = 0, nx = 0, k;
    char ** opt = malloc(sizeof(char *) * (argc + 2));
    char ** ops = malloc(sizeof(char *) * (argc + 2));
    char ** out;

    *extra = NULL;
    for (i = 1; i < argc; i++)
    {
        const char * a = argv[i];

        if (strcmp(a, "--") == 0)
        {
            for (i++; i < argc; i++)
                ops[nx++] = argv[i];
            break;
        }
        if (a[0] != '-' || a[1] == '\0' || (a[1] >= '0' && a[1] <= '9')
            || a[1] == '.')
        {
            ops[nx++] = argv[i];
            continue;
        }
        opt[no++] = argv[i];
        for (k = 0; valued[k] != NULL; k++)
            if (strcmp(a, valued[k]) == 0)
                break;
        if (valued[k] == NULL)
            continue;
        if (strcmp(a, "--bias") == 0 && i + 3 < argc && *extra == NULL)
        {
            size_t len = strlen("--bias=") + strlen(argv[i + 1])
                + strlen(argv[i + 2]) + strlen(argv[i + 3]) + 3;

            *extra = malloc(len);
            snprintf(*extra, len, "--bias=%s,%s,%s", argv[i + 1],
                     argv[i + 2], argv[i + 3]);
            opt[no - 1] = *extra;
            i += 3;
        }
        else if (i + 1 < argc)
            opt[no++] = argv[++i];
    }
    out = malloc(sizeof(char *) * (no + nx + 3));
    out[0] = argv[0];
    for (j = 0; j < no; j++)
        out[1 + j] = opt[j];
    out[1 + no] = (char *) "--";
    for (j = 0; j < nx; j++)
        out[2 + no + j] = ops[j];
    out[2 + no + nx] = NULL;
    *pargc = 2 + no + nx;
    free(opt);
    free(ops);
    return out;
}

static const char * const planned[] = {
    "draw", NULL
};

int
main(int argc, char ** argv)
{
    int status, i;

    if (argc < 2)
    {
        usage(stderr);
        return WC_EUSAGE;
    }
    if (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0)
    {
        usage(stdout);
        return finish_output();
    }
    if (strcmp(argv[1], "-V") == 0 || strcmp(argv[1], "--version") == 0)
    {
        version();
        return finish_output();
    }
    if (strcmp(argv[1], "cone") == 0)
        status = cmd_cone(argc - 1, argv + 1);
    else if (strcmp(argv[1], "modes") == 0)
        status = cmd_modes(argc - 1, argv + 1);
    else if (strcmp(argv[1], "feasible") == 0)
        status = cmd_feasible(argc - 1, argv + 1);
    else if (strcmp(argv[1], "verify") == 0)
        status = cmd_verify(argc - 1, argv + 1);
    else if (strcmp(argv[1], "random") == 0)
        status = cmd_random(argc - 1, argv + 1);
    else if (strcmp(argv[1], "compare") == 0)
        status = cmd_compare(argc - 1, argv + 1);
    else if (strcmp(argv[1], "sweep") == 0)
        status = cmd_sweep(argc - 1, argv + 1);
    else if (strcmp(argv[1], "classify") == 0
             || strcmp(argv[1], "stability") == 0
             || strcmp(argv[1], "plan") == 0)
    {
        int n = argc - 1;
        char * extra, ** v = operands_last(&n, argv + 1, &extra);

        status = argv[1][0] == 'p' ? cmd_plan(n, v)
            : argv[1][1] == 'l' ? cmd_classify(n, v) : cmd_stability(n, v);
        free(v);
        free(extra);
    }
    else
    {
        for (i = 0; planned[i] != NULL; i++)
            if (strcmp(argv[1], planned[i]) == 0)
                break;
        status = usage_error(NULL, planned[i] != NULL
                             ? "'%s' is not implemented in this version"
                             : "unknown command '%s'", argv[1]);
    }
    flint_cleanup_master();
    return status;
}
