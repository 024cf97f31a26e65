/* mode.c -- contact mode strings (paper Tables 1 and 2).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <string.h>

#include "model/mode.h"

#define WC_MODE_FILE "<mode>"

/* The letters a table allows on a touching and on a near fixel.  */
static const char *
allowed(wc_mode_table table, wc_fixel_state state)
{
    if (table == WC_TABLE_KINEMATIC)
        return state == WC_NEAR ? "sa" : "slrn";
    return state == WC_NEAR ? "sau" : "slrnm";
}

static int
in_set(char c, const char * set)
{
    return c != '\0' && strchr(set, c) != NULL;
}

int
wc_mode_check(const wc_problem_t P, const char * mode, wc_mode_table table,
              wc_error_t err)
{
    size_t len = strlen(mode);
    size_t i;
    int status;

    if ((status = wc_problem_check(P, err)) != WC_OK)
        return status;
    if (table == WC_TABLE_CONE
        && (status = wc_problem_check_fixels(P, WC_CONE_MAX_FIXELS, 0,
                                             "a wrench cone", err))
           != WC_OK)
        return status;
    /* The length is checked first: with a letter missing or extra, the
       letters after it would be read against the wrong fixels.  */
    if (len != (size_t) P->n)
        return wc_error_set(err, WC_EINPUT, WC_MODE_FILE, 1,
                            (long) (len < (size_t) P->n ? len : (size_t) P->n)
                            + 1,
                            "mode has %lu letter%s; the problem has %ld "
                            "fixel%s", (unsigned long) len,
                            len == 1 ? "" : "s", (long) P->n,
                            P->n == 1 ? "" : "s");
    for (i = 0; i < len; i++)
    {
        unsigned char c = (unsigned char) mode[i];
        wc_fixel_state state = P->fixels[i].state;
        const char * all = table == WC_TABLE_KINEMATIC ? "slrna" : "saulrnm";

        if (!in_set((char) c, all))
        {
            if (c < 0x20 || c >= 0x7f)
                return wc_error_set(err, WC_EINPUT, WC_MODE_FILE, 1,
                                    (long) i + 1,
                                    "unknown mode letter '\\x%02x'", c);
            return wc_error_set(err, WC_EINPUT, WC_MODE_FILE, 1, (long) i + 1,
                                "unknown mode letter '%c'", c);
        }
        if (!in_set((char) c, allowed(table, state)))
            return wc_error_set(err, WC_EINPUT, WC_MODE_FILE, 1, (long) i + 1,
                                "letter '%c' not allowed on fixel %lu, which "
                                "is %s", c, (unsigned long) i + 1,
                                state == WC_NEAR ? "near" : "touching");
    }
    return WC_OK;
}
