/* old-cells.h -- the previous implementation of wc_cells_build, kept to
   catch regressions (t-cellsfast); not an independent reference
   (old-cells.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_TESTS_OLD_CELLS_H
#define WC_TESTS_OLD_CELLS_H

#include "exact/cells.h"

/* A (initialised) := the cells of the planes normals, as wc_cells_build
   computed them before (same planes, order, points and signs; A is to be
   cleared with wc_cells_clear).  Returns WC_OK or WC_EINTERNAL.  */
int old_cells_build(wc_cells_t A, const fmpz_mat_t normals, wc_error_t err);

#endif
