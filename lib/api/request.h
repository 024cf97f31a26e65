/* request.h -- one request, one answer: a computing command of the
   wrenchcone program given as a JSON object, answered with the JSON that
   the command prints with --format=json.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A request is one JSON object (wrenchcone(1), REQUESTS):

     {"command": "cone", "problem": "data/section4.wc", "mode": "na"}

   "command" is cone, modes, feasible, classify, stability, plan or
   compare; the problem is a file ("problem": PATH, read by the library,
   relative to the working directory; a regular file only: anything else
   is refused unread, and never waited for) or the text of one
   ("problem_text": TEXT, named <problem_text> in messages).  The other keys are the
   command's operands and options:

     cone       "mode"; "method": "direct"|"paper"; "trace": bool;
                "arith": "exact"|"double"
     modes      "witness": bool
     feasible   "mode"
     classify   "wrench": [FX, FY, TAU]; "max_modes": N (default 1000)
     stability  "bias": [FX, FY, TAU]; "length": L
     plan       "wrench" (optional); "complete": bool
     compare    "mode"; "foreign": PATH or "foreign_text": TEXT;
                "tol": T

   Numbers are JSON strings as on the command line ("-1/5", "0.25") or
   JSON numbers, read exactly from their digits.  Certificates are not
   written from requests (use the command line's --certificate).  Any
   other key, a missing one, or a value of the wrong kind is a usage
   error located at the key or value in the request.  */

#ifndef WC_API_REQUEST_H
#define WC_API_REQUEST_H

#include <stddef.h>

#include "core/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Answer the request request[0..len) (UTF-8 JSON; it need not be
   NUL-terminated).  *out := a malloc'd, NUL-terminated answer of *outlen
   bytes (not counting the NUL), one line ending with a newline:

   - on success, exactly what `wrenchcone COMMAND --format=json` prints;
     returns WC_OK, or WC_EDISAGREE for a comparison beyond its tolerance
     (the comparison is the answer, as on the command line);
   - on failure, an error record
       {"error": {"message": M, "file": F, "line": L, "column": C,
                  "status": S}}
     with the message and location that the command line prints as
     "wrenchcone: F:L:C: M" (null where it has none) and S its exit
     status, also returned, with err set to the same error: WC_EINPUT
     for a bad problem, mode, number or input file; WC_EUSAGE for a
     request that is not valid JSON, not an object, or has a missing,
     unknown or ill-typed key; WC_EINTERNAL for an internal failure.

   Errors in the request itself are located in "<request>", its first
   line being line 1.  When out of memory, *out may be NULL (status
   WC_EINTERNAL, err says so).  The caller frees *out with free(), or
   with wc_request_free() from code that may not share the library's
   allocator (another language's runtime).
   Never prints, never exits.  Thread-safe: any number of threads may
   answer requests at once, each answer the same bytes as alone (the
   library holds no mutable global state; cddlib, which does, is called
   under one lock, so its share of the work runs one thread at a time).
   A thread's FLINT caches are freed when it exits.  */
int wc_request_json(char ** out, size_t * outlen, const char * request,
                    size_t len, wc_error_t err);

/* The same, errors in the request located in file (NULL: "<request>")
   with the request's first line counted as line `line` (>= 1): a batch
   of JSON Lines names its file and the request's line.  */
int wc_request_json_at(char ** out, size_t * outlen, const char * request,
                       size_t len, const char * file, long line,
                       wc_error_t err);

/* Free an answer of wc_request_json or wc_request_json_at (NULL is
   fine): free() of the allocator the library was linked with.  */
void wc_request_free(char * out);

/* The commands a request may name, with their keys, the kinds of their
   values, defaults and help, as one JSON document in a malloc'd *out of
   *outlen bytes (free with wc_request_free): what `wrenchcone --schema`
   prints, and what the Python module builds its functions from.
   Returns WC_OK, or WC_EINTERNAL when out of memory (*out NULL).  */
int wc_request_schema(char ** out, size_t * outlen);

#ifdef __cplusplus
}
#endif

#endif
