/* schema.h -- the commands of wrenchcone as data: each command's name,
   summary, usage, operands and options, one row per operand or option.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  This table is the one definition of the
   program's interface.  From it come the command-line parser (src/), the
   request reader (request.c), every --help text, the bash completion
   (built from --help), the schema document that the Python module builds
   its functions from (_wc_schema_fprint_json), and the checks that
   wrenchcone(1) lists the same options (tests/schema.sh).  Adding an
   option is one row here, a field in _wc_request (run.h), and what the
   command does with it.

   A row is read into the _wc_request field at its offset: the same value
   check, the same default and the same message for the command line and
   for a request.  An option --max-modes is the request key "max_modes";
   an operand's key is its row's name (problem, mode, wrench, foreign).  */

#ifndef WC_API_SCHEMA_H
#define WC_API_SCHEMA_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"

/* How a value is written and what it is read into.  */
typedef enum
{
    _WC_ARG_FLAG,       /* --NAME, or true/false: int */
    _WC_ARG_CHOICE,     /* one word of values ("a|b|c"): int, its place */
    _WC_ARG_COUNT,      /* a whole number from lo to hi: long */
    _WC_ARG_SEED,       /* a decimal integer below 2^64: unsigned long long */
    _WC_ARG_NUMBER,     /* an exact number, kept as written: const char * */
    _WC_ARG_LIST,       /* exact numbers A,B,...: const char *, as written */
    _WC_ARG_WRENCH,     /* FX,FY,TAU, or three operands: _wc_triple */
    _WC_ARG_ANGLE,      /* radians, 0 <= T < pi/2: double */
    _WC_ARG_WORD,       /* a string such as a mode: const char * */
    _WC_ARG_INPUT,      /* an input file ("-": stdin on the command line),
                           in a request KEY (a path) or KEY_text: _wc_input */
    _WC_ARG_OUTPUT      /* an output file (command line only): const char * */
}
_wc_arg_kind;

/* Row flags.  _WC_ARG_CLI: the command line only (not a request key).
   _WC_ARG_OPTIONAL: an operand that may be left out (with those after
   it).  _WC_ARG_REQUIRED: a request must give this key.  */
enum { _WC_ARG_CLI = 1, _WC_ARG_OPTIONAL = 2, _WC_ARG_REQUIRED = 4 };

/* One operand or option.  */
typedef struct
{
    const char * name;      /* option: its long name ("max-modes"); operand:
                               its request key ("problem") */
    _wc_arg_kind kind;
    const char * metavar;   /* "N", "FX,FY,TAU"; operands: as in the usage
                               ("PROBLEM", "FX FY TAU"); NULL for a flag */
    const char * values;    /* a choice's words, "direct|paper" */
    const char * what;      /* a choice's noun ("unknown method 'x'"), or
                               what a bad value is told ("must be ...") */
    const char * def;       /* the default, as it would be written (NULL:
                               none, or false, or the first choice) */
    long lo, hi;            /* a count's bounds */
    size_t offset;          /* its field in _wc_request */
    unsigned flags;
    char letter;            /* its short option, or 0 */
    const char * help;      /* --help's text, lines joined by '\n' */
    const char * group;     /* --help's heading (NULL: "Options") */
}
_wc_arg;

struct _wc_request_struct;

/* One command.  */
typedef struct
{
    const char * name;
    const char * synopsis;  /* the main --help's line: "cone PROBLEM MODE" */
    const char * summary;   /* its description there, lines joined by '\n' */
    const char * usage;     /* "Usage: ..." lines of its --help */
    const char * about;     /* the paragraph after them */
    const char * epilog;    /* after the options, or NULL */
    const _wc_arg * operands;  /* each list ends with a NULL name */
    const _wc_arg * options;
    unsigned flags;
    /* Rules between the values, once all are read (NULL: none): NULL when
       R is fine, else the message, the culprit's row in *culprit.  The
       message names options as R was given (_wc_spell).  */
    const char * (*check)(char * msg, size_t size, const _wc_arg ** culprit,
                          const struct _wc_request_struct * R);
}
_wc_command_schema;

/* Command flags.  _WC_CMD_SHARED: the command line knows the options of
   every other shared command, and refuses them as "does not apply here".
   _WC_CMD_OPERANDS_LAST: operands may be negative numbers.  _WC_CMD_REQUEST:
   a request may name the command.  */
enum { _WC_CMD_SHARED = 1, _WC_CMD_OPERANDS_LAST = 2, _WC_CMD_REQUEST = 4 };

/* The commands, in the order of the main --help, ending with a NULL name.  */
extern const _wc_command_schema _wc_schema[];

/* The command named name, or NULL.  */
const _wc_command_schema * _wc_schema_find(const char * name);

/* The option of S named name (its long name, or its request key when key
   is set), or NULL.  */
const _wc_arg * _wc_schema_option(const _wc_command_schema * S,
                                  const char * name, int key);

/* A row's request key ("max_modes") into buf.  */
const char * _wc_arg_key(char * buf, size_t size, const _wc_arg * a);

/* The whole table as one JSON document (the commands, their operands and
   options with kinds, defaults and help): what the Python module builds
   its functions from.  WC_OK, or WC_EINTERNAL on a write error.  */
int _wc_schema_fprint_json(FILE * out);

/* The --help text of command S, or of the program when S is NULL.  */
int _wc_schema_fprint_help(FILE * out, const _wc_command_schema * S);

#endif
