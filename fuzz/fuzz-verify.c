/* fuzz-verify.c -- libFuzzer target: the certificate reader and checker
   behind `wrenchcone verify` (lib/check, verify.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Any bytes: wc_verify gives a verdict (holds or not, with a one-line
   summary, and a one-line reason when not) or an input error located at
   FILE:LINE:COL, never a crash, a leak or an abort.  For a certificate
   wc_verify_certificate reads (mode feasibility), both functions agree
   on the verdict and the reason, as verify.h promises; an input error
   of wc_verify_certificate is one of wc_verify too, unless the text is
   a strong-stability certificate.  */

#include "fuzzutil.h"

#define FILE_NAME "fuzz.json"

static int
str_equal(const char * a, const char * b)
{
    if (a == NULL || b == NULL)
        return a == b;
    return strcmp(a, b) == 0;
}

static void
require_line(const char * s, const char * what)
{
    FUZZ_REQUIRE(s != NULL && s[0] != '\0', "no %s", what);
    FUZZ_REQUIRE(strchr(s, '\n') == NULL, "the %s '%s' spans lines", what, s);
}

int LLVMFuzzerTestOneInput(const uint8_t * data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t * data, size_t size)
{
    const char * text = (const char *) data;
    wc_error_t err, err2;
    char * reason = NULL, * summary = NULL, * reason2 = NULL, * mode = NULL;
    int holds = -1, holds2 = -1, feasible = -1, status, status2;

    wc_error_init(err);
    wc_error_init(err2);
    status = wc_verify(&holds, &reason, &summary, text, size, FILE_NAME, err);
    if (status == WC_OK)
    {
        FUZZ_REQUIRE(holds == 0 || holds == 1, "holds = %d", holds);
        require_line(summary, "summary");
        if (holds)
            FUZZ_REQUIRE(reason == NULL, "a reason for a holding certificate");
        else
            require_line(reason, "reason");
    }
    else
    {
        FUZZ_REQUIRE(status == WC_EINPUT, "wc_verify returned %d", status);
        FUZZ_REQUIRE(holds == 0 && reason == NULL && summary == NULL,
                     "an error with a verdict");
        fuzz_require_located(err, FILE_NAME);
    }

    status2 = wc_verify_certificate(&holds2, &reason2, &mode, &feasible,
                                    text, size, FILE_NAME, err2);
    if (status2 == WC_OK)
    {
        FUZZ_REQUIRE(status == WC_OK, "only wc_verify_certificate reads it");
        FUZZ_REQUIRE(holds2 == holds && str_equal(reason, reason2),
                     "the two checkers disagree: %d '%s' and %d '%s'", holds,
                     reason ? reason : "", holds2, reason2 ? reason2 : "");
        FUZZ_REQUIRE(mode != NULL && (feasible == 0 || feasible == 1),
                     "no claim read");
        FUZZ_REQUIRE(strstr(summary, mode) != NULL,
                     "the summary '%s' does not name mode %s", summary, mode);
    }
    else
    {
        FUZZ_REQUIRE(status2 == WC_EINPUT, "wc_verify_certificate returned %d",
                     status2);
        FUZZ_REQUIRE(holds2 == 0 && reason2 == NULL && mode == NULL,
                     "an error with a verdict");
        fuzz_require_located(err2, FILE_NAME);
    }

    free(reason);
    free(reason2);
    free(summary);
    free(mode);
    wc_error_clear(err);
    wc_error_clear(err2);
    return 0;
}
