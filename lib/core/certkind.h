/* certkind.h -- internal: the names of the certificate kinds, the value
   of a certificate's "kind" key (wrenchcone-certificate(5)).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  One spelling for the writers (lib/io) and the checker
   (lib/check): string constants only, no FLINT, so that the checker,
   which uses core alone and links with GMP alone, reads the same names
   the solver writes.  */

#ifndef WC_CORE_CERTKIND_H
#define WC_CORE_CERTKIND_H

/* A mode's feasibility or infeasibility (wrenchcone feasible
   --certificate); also a certificate without "kind".  */
#define WC_CERT_KIND_MODE "mode-feasibility"

/* A wrench's strong stability or its failure (wrenchcone classify
   --certificate).  */
#define WC_CERT_KIND_STABILITY "strong-stability"

/* The strong stability set of a problem (wrenchcone stability
   --certificate).  */
#define WC_CERT_KIND_SET "stability-set"

/* A plan's goal (wrenchcone plan --certificate).  */
#define WC_CERT_KIND_PLAN "plan-goal"

/* A bracket of the critical friction (wrenchcone sweep --critical
   --certificate).  */
#define WC_CERT_KIND_CRIT "critical-friction"

#endif
