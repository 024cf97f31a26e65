/* args.h -- a command's arguments read by the schema's rows (schema.h):
   the defaults, one value and its check, and the JSON request that a set
   of arguments is.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  _wc_request_init and _wc_request_clear are
   declared in run.h.  */

#ifndef WC_API_ARGS_H
#define WC_API_ARGS_H

#include <stdio.h>

#include "api/run.h"
#include "api/schema.h"

/* Room for any message of _wc_arg_set_text or of a schema check: a
   value quoted (_wc_quote, at most WC_QUOTE_SIZE(WC_SHOW_MAX) bytes) and
   the words around it.  */
#define _WC_ARG_MSG_SIZE 512

/* Read s, the value of row a as written, into R's field.  NULL, or the
   message of a usage error in msg[0..size) (size at least
   _WC_ARG_MSG_SIZE; the value quoted, _wc_quote; the words depend on
   R->from_request: "--tol must be ...", or "\"tol\" must be ...").  A
   wrench "FX,FY,TAU" is cut into a copy that R owns.  An input is the
   file s (the command line turns "-" into standard input).  */
const char * _wc_arg_set_text(_wc_request * R, const _wc_arg * a,
                              const char * s, char * msg, size_t size);

/* A copy of s that R owns (freed by _wc_request_clear), or NULL when out
   of memory or when R owns too many.  _keep: p itself (malloc'd), freed
   at once when R cannot keep it.  */
char * _wc_request_own(_wc_request * R, const char * s);
char * _wc_request_keep(_wc_request * R, char * p);

/* A wrench given as three values v[0..3) (operands, or a JSON array).  */
void _wc_arg_set_wrench(_wc_request * R, const _wc_arg * a,
                        const char * const * v);

/* R as one JSON request line: the command, its operands, and the options
   that differ from their defaults (the command line's own options, such
   as --format, left out).  An input given as text is written as
   KEY_text.  WC_OK, or WC_EINTERNAL on a write error.  */
int _wc_request_fprint_json(FILE * out, const _wc_request * R);

#endif
