/* motzkin.c -- Motzkin multipliers: the proof, shared by both kinds of
   certificate, that a system of linear rows has no solution.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Rows a_k . x rel_k 0 with rel_k one of >, >=, = have no solution when
   multipliers y_k exist with sum_k y_k a_k = 0, y_k >= 0 on the > and >=
   rows and y_k > 0 on at least one > row (Motzkin's transposition
   theorem: such a combination of the rows would read 0 > 0).  */

#include "check/checker.h"

const char *
_wc_check_rel_name(wc_check_rel r)
{
    return r == WC_CHECK_GT ? ">" : r == WC_CHECK_GE ? ">=" : "=";
}

int
_wc_check_motzkin_count(wc_check_text * why, const char * prefix,
                        const char * noun, size_t nmult, size_t rows)
{
    if (nmult == rows)
        return 1;
    _wc_check_put(why, prefix);
    _wc_check_putf(why, "there %s %lu multiplier%s for %lu %s%s",
                   nmult == 1 ? "is" : "are", (unsigned long) nmult,
                   nmult == 1 ? "" : "s", (unsigned long) rows, noun,
                   rows == 1 ? "" : "s");
    return 0;
}

int
_wc_check_motzkin(wc_check_text * why, const char * prefix,
                  const char * noun, const wc_check_rel * rel, mpq_t * y,
                  size_t rows, mpq_t * s, size_t d)
{
    size_t k;

    for (k = 0; k < rows; k++)
        if (rel[k] != WC_CHECK_EQ && mpq_sgn(y[k]) < 0)
        {
            _wc_check_put(why, prefix);
            _wc_check_putf(why, "multiplier %lu is ", (unsigned long) k + 1);
            _wc_check_put_q(why, y[k]);
            _wc_check_putf(why, ", negative on a '%s' %s",
                           _wc_check_rel_name(rel[k]), noun);
            return 0;
        }
    if (!_wc_check_qvec_is_zero(s, d))
    {
        _wc_check_put(why, prefix);
        _wc_check_put(why, "the multipliers combine the rows to ");
        _wc_check_put_qvec(why, s, d);
        _wc_check_put(why, ", not to zero");
        return 0;
    }
    for (k = 0; k < rows; k++)
        if (rel[k] == WC_CHECK_GT && mpq_sgn(y[k]) > 0)
            return 1;
    _wc_check_put(why, prefix);
    _wc_check_putf(why, "no '>' %s has a positive multiplier", noun);
    return 0;
}
