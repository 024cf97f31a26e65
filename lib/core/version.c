/* version.c -- one-time set-up of the exact backends, and version strings.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   cddlib's global constants must be set exactly once per process:
   forgetting them gives wrong answers silently.  libcddgmp also holds the
   double build (the ddf_ functions), whose constants are separate.  */

#include <config.h>

#include <pthread.h>

#include <gmp.h>
#include <cddlib/setoper.h>
#include <cddlib/cdd.h>
#include <flint/flint.h>

#include "core/version.h"

static pthread_once_t cdd_once = PTHREAD_ONCE_INIT;

static void
cdd_constants(void)
{
    dd_set_global_constants();
    /* ddf_zero, the double build's tolerance, is used by floatcone.c.  */
    ddf_set_global_constants();
}

void
wc_init(void)
{
    pthread_once(&cdd_once, cdd_constants);
}

const char *
wc_version(void)
{
    return PACKAGE_VERSION;
}

const char *
wc_gmp_version(void)
{
    return gmp_version;
}

const char *
wc_flint_version(void)
{
    return flint_version;
}

const char *
wc_cdd_version(void)
{
    return dd_DDVERSION " (" dd_ARITHMETIC ")";
}
