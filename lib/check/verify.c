/* verify.c -- re-check a certificate (mode feasibility, strong
   stability, stability sets) with GMP alone: the public entry points.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Deliberately independent of the rest of libwrenchcone: C, GMP (mpz,
   mpq) and lib/core (errors, the JSON reader) only, so that a bug in the
   code that writes certificates cannot hide in the code that checks
   them.  That is why this folder keeps its own arithmetic (gmpvec.c,
   not exact/vec3.h and FLINT) and its own walk of the arrangement of
   contact planes (faces.c: one point in every cell, from the lines on
   each plane) instead of the solver's cell enumeration (exact/cells.c,
   cddlib): sharing either would let one mistake both write and pass a
   wrong certificate.

   The files: checker.h (what they share), gmpvec.c, textbuf.c,
   motzkin.c, read.c, problem.c; feasible.c (mode feasibility);
   stabread.c, stabcheck.c, faces.c, facecheck.c (strong stability);
   setread.c, setdoc.c, setcheck.c, settree.c, region.c (stability sets:
   the claim, the proofs, the tree of cuts and its regions), plansys.c
   (plan goal sets), critcheck.c (critical friction).  */

#include <stdlib.h>

#include "core/certkind.h"
#include "check/checker.h"
#include "check/feasible.h"
#include "check/stabcheck.h"
#include "check/setcheck.h"
#include "check/critcheck.h"
#include "check/verify.h"

/* Parse text and read the kind of its certificate into *kind, c made
   ready to read the rest.  */
static int
open_certificate(wc_json_t J, wc_check_reader * c, wc_check_kind * kind,
                 const char * text, size_t len, const char * file,
                 wc_error_t err)
{
    int status = _wc_json_parse(J, text, len, file, err);

    if (status != WC_OK)
        return status;
    c->file = file;
    c->err = err;
    c->status = WC_OK;
    if (_wc_check_kind(c, &J->root, kind) != WC_OK)
        return c->status;
    return WC_OK;
}

int
wc_verify_certificate(int * holds, char ** reason, char ** mode,
                      int * feasible, const char * text, size_t len,
                      const char * file, wc_error_t err)
{
    wc_json_t J;
    wc_check_reader c;
    wc_check_text why = { NULL, 0, 0, 0 };
    char * m = NULL;
    wc_check_kind kind;
    int status, h = 0, feas = 0;

    *holds = 0;
    *reason = NULL;
    if (mode != NULL)
        *mode = NULL;
    if (feasible != NULL)
        *feasible = 0;
    _wc_json_init(J);
    status = open_certificate(J, &c, &kind, text, len, file, err);
    if (status != WC_OK)
        goto cleanup;
    if (kind != WC_CHECK_MODE)
    {
        status = _wc_check_bad(&c, _wc_json_object_get(&J->root, "kind"),
                               "expected a " WC_CERT_KIND_MODE
                               " certificate, found kind '%s'", kind == WC_CHECK_SET
                               ? WC_CERT_KIND_SET : kind == WC_CHECK_PLAN
                               ? WC_CERT_KIND_PLAN : kind == WC_CHECK_CRIT
                               ? WC_CERT_KIND_CRIT
                               : WC_CERT_KIND_STABILITY);
        goto cleanup;
    }
    status = _wc_check_mode_certificate(&c, &J->root, &h, &why, &m, &feas);
    if (status != WC_OK)
        goto cleanup;
    *holds = h;
    if (!h)
    {
        *reason = why.s;
        why.s = NULL;
    }
    if (feasible != NULL)
        *feasible = feas;
    if (mode != NULL)
    {
        *mode = m;
        m = NULL;
    }
cleanup:
    free(why.s);
    free(m);
    _wc_json_clear(J);
    return status;
}

int
wc_verify(int * holds, char ** reason, char ** summary, const char * text,
          size_t len, const char * file, wc_error_t err)
{
    wc_json_t J;
    wc_check_reader c;
    wc_check_text why = { NULL, 0, 0, 0 }, what = { NULL, 0, 0, 0 };
    char * m = NULL;
    wc_check_kind kind;
    int status, h = 0, feas = 0;

    *holds = 0;
    *reason = NULL;
    *summary = NULL;
    _wc_json_init(J);
    status = open_certificate(J, &c, &kind, text, len, file, err);
    if (status != WC_OK)
        goto cleanup;
    if (kind == WC_CHECK_MODE)
    {
        status = _wc_check_mode_certificate(&c, &J->root, &h, &why, &m,
                                            &feas);
        if (status == WC_OK)
            _wc_check_putf(&what, "mode %s is %s", m, feas ? "feasible"
                           : "infeasible");
    }
    else if (kind == WC_CHECK_STABILITY)
        status = _wc_check_stability_certificate(&c, &J->root, &h, &why,
                                                 &what);
    else if (kind == WC_CHECK_CRIT)
        status = _wc_check_crit_certificate(&c, &J->root, &h, &why, &what);
    else
        status = _wc_check_set_certificate(&c, &J->root, kind == WC_CHECK_PLAN,
                                           &h, &why, &what);
    if (status != WC_OK)
        goto cleanup;
    if (what.oom || what.s == NULL)
    {
        status = wc_error_set(err, WC_EINTERNAL, file, 0, 0,
                              "out of memory");
        goto cleanup;
    }
    *holds = h;
    if (!h)
    {
        *reason = why.s;
        why.s = NULL;
    }
    *summary = what.s;
    what.s = NULL;
cleanup:
    free(why.s);
    free(what.s);
    free(m);
    _wc_json_clear(J);
    return status;
}
