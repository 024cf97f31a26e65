/* zrow.h -- internal: rows of integer 3-vectors with their index, in
   lexicographic order, to sort them and look vectors up among them.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not installed.  Sort an array of _wc_zrow with qsort(3) and
   _wc_zrow_cmp, then find a vector v by bsearch(3) with the key
   { v, any index }: the index of the row found says which it was.  */

#ifndef WC_EXACT_ZROW_H
#define WC_EXACT_ZROW_H

#include <flint/fmpz.h>

/* A row (3 entries, not owned) and its index.  */
typedef struct
{
    const fmpz * v;
    slong i;
}
_wc_zrow;

/* Lexicographic order of the vectors of two _wc_zrow (qsort, bsearch);
   the indices are not compared.  */
int _wc_zrow_cmp(const void * a, const void * b);

#endif
