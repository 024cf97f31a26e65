/* batch.h -- a stream of requests, one JSON object a line, answered in
   order, by one thread or several: `wrenchcone batch`.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_API_BATCH_H
#define WC_API_BATCH_H

#include <stdio.h>

#include "core/error.h"
#include "core/limits.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Answer every line of in that is not blank (spaces, tabs, CR) with
   wc_request_json_at, errors located in name at the line's number, and
   write the answers to out in the order of the lines: the answer of line
   k before that of any later line, each flushed as soon as it and every
   earlier answer are done, so that a program can drive the batch through
   pipes, one request and its answer at a time.  jobs threads answer
   (1 <= jobs <= WC_BATCH_MAX_JOBS); with 1, the default of the command
   line, the calling thread does, one line at a time, and reads the next
   line only once the answer is written.  The answers are the same bytes
   whatever jobs is; with jobs > 1 up to 4 * jobs lines are read ahead.
   A request reads regular files only (api/request.h), and never the file
   in reads (by any name: /dev/stdin, its path), so that every line is
   answered; in and out may not be the same regular file (WC_EINPUT, and
   nothing read).

   *worst := the batch's status from the answers written: WC_OK when
   there are none or all are WC_OK; else the largest status of an error
   record (WC_EINPUT, WC_EUSAGE, WC_EINTERNAL) when there is one, so
   WC_EINTERNAL when any line met an internal failure; else WC_EDISAGREE
   (every line answered, some comparison beyond its tolerance).
   Returns WC_OK when every line was read and answered; else WC_EINTERNAL
   with err set, and the answers of the lines before the failure written:
   "NAME: read error: ..." (in), "write error: ..." (out; its error
   indicator is set too), "out of memory".  Writes nothing but the
   answers, to out only; never exits.  */
int wc_batch(int * worst, FILE * out, FILE * in, const char * name,
             int jobs, wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
