/* report.c -- the verdict on a certificate, as one line of text or JSON:
   what `wrenchcone verify` and wrenchcone-verify print.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Both programs call this one function, so that they cannot drift apart.
   It writes to the stream its caller gives, nothing else; like the rest
   of lib/check it uses C and lib/core alone (the JSON string writer is
   lib/core's, the one the solver's outputs use too).  */

#include <stdio.h>
#include <stdlib.h>

#include "core/text.h"
#include "core/version.h"
#include "check/verify.h"

/* The JSON verdict.  A mode-feasibility certificate gives its mode and
   claim as keys; any other kind a summary.  */
static void
put_json(FILE * out, int holds, const char * reason, const char * summary,
         const char * text, size_t len, const char * file)
{
    wc_error_t e2;
    int h2, feasible = 0;
    char * r2 = NULL, * mode = NULL;

    wc_error_init(e2);
    if (wc_verify_certificate(&h2, &r2, &mode, &feasible, text, len, file,
                              e2) != WC_OK)
        mode = NULL;
    free(r2);
    wc_error_clear(e2);
    fprintf(out, WC_JSON_OPEN "\"holds\": %s", holds ? "true" : "false");
    if (mode != NULL)
    {
        fputs(", \"mode\": ", out);
        _wc_fput_json_string(out, mode);
        fprintf(out, ", \"feasible\": %s", feasible ? "true" : "false");
    }
    else
    {
        fputs(", \"summary\": ", out);
        _wc_fput_json_string(out, summary != NULL ? summary : "");
    }
    if (!holds)
    {
        fputs(", \"reason\": ", out);
        _wc_fput_json_string(out, reason != NULL ? reason : "");
    }
    fputs("}\n", out);
    free(mode);
}

int
wc_verify_fprint(FILE * out, int * holds, const char * text, size_t len,
                 const char * file, int json, wc_error_t err)
{
    char * reason = NULL, * summary = NULL;
    int status = wc_verify(holds, &reason, &summary, text, len, file, err);

    if (status != WC_OK)
        return status;
    if (json)
        put_json(out, *holds, reason, summary, text, len, file);
    else if (*holds)
        fprintf(out, "certificate holds: %s\n", summary);
    else
        fprintf(out, "certificate does not hold: %s\n", reason);
    free(reason);
    free(summary);
    return WC_OK;
}
