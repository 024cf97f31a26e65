/* relation.h -- the relation of a homogeneous linear row: row . x > 0,
   >= 0 or = 0.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Kinematic certificates (analysis/kinematics.h) and the systems of the
   stability analysis are lists of such rows; the exact LP layer solves
   them.  Lives in the exact layer so that the LP layer and every layer
   above share one type.  */

#ifndef WC_RELATION_H
#define WC_RELATION_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { WC_REL_GT = 0, WC_REL_GE = 1, WC_REL_EQ = 2 } wc_relation;

/* ">", ">=" or "=".  */
const char * wc_relation_str(wc_relation r);

#ifdef __cplusplus
}
#endif

#endif
