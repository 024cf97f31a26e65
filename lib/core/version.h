/* version.h -- one-time set-up of the exact backends, and version strings.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_VERSION_H
#define WC_VERSION_H

#ifdef __cplusplus
extern "C" {
#endif

/* Optional one-time set-up of the exact backends (cddlib's global
   constants).  Every library function that needs it calls it; it is
   idempotent and safe from any thread (pthread_once), so callers that use
   cddlib themselves call this instead of dd_set_global_constants().
   Defined, with wc_cdd_version, in exact/cddbridge.c.  */
void wc_init(void);

/* Version strings: ours, and those of the GMP, FLINT and cddlib we run
   with.  Static storage; never NULL.  */
const char * wc_version(void);
const char * wc_gmp_version(void);
const char * wc_flint_version(void);
const char * wc_cdd_version(void);

/* Every JSON document the programs print (a command's --format=json, a
   batch line, an error record, a verdict of verify) opens with the key
   "format" and this value, the version of wrenchcone(1)'s JSON: it
   changes only when a key changes meaning or goes away (added keys keep
   it).  WC_JSON_OPEN is the document's first bytes, up to the next key.  */
#define WC_JSON_FORMAT "wrenchcone-json/1"
#define WC_JSON_OPEN "{\"format\": \"" WC_JSON_FORMAT "\", "

#ifdef __cplusplus
}
#endif

#endif
