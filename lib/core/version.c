/* version.c -- version strings.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   wc_init and wc_cdd_version, which version.h declares too, are defined
   in exact/cddbridge.c: every use of cddlib is there.  */

#include <config.h>

#include <gmp.h>
#include <flint/flint.h>

#include "core/version.h"

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
