/* ref-modes.c -- the independent reference for mode enumeration
   (wc_modes_enumerate): every kinematically feasible mode string.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Independent of lib/: written from kinematics.h and SPEC.md section 2.1
   without reading lib/analysis/modeswalk.c or the arrangement code, and
   it uses no arrangement, cone or face at all.  Its method is a search
   over strings: a mode's constraints are one conjunction per fixel, so a
   prefix of letters for fixels 1..k that no twist satisfies has no
   feasible extension.  The search extends feasible prefixes letter by
   letter (s l r n on a touching fixel, s a on a near one) and decides
   each prefix by one exact LP over the first k fixels -- ref_mode_feasible
   of ref-kin.c, which builds J from the problem's fields itself and
   re-checks every cddlib answer exactly (a twist, or Motzkin
   multipliers).  The 4^t 2^(n - t) strings are never all looked at: the
   LPs number at most 4 per fixel per feasible prefix.

   Witnesses are the library's choice (a point of some face); the tests
   check each one with ref_twist_satisfies, not against a list here.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "ref-kin.h"
#include "ref-modes.h"

typedef struct
{
    const wc_problem_struct * P;
    char * prefix;          /* n + 1 bytes */
    char ** list;
    slong count, cap, lps;
    int failed;
}
search_state;

static int
keep(search_state * S)
{
    slong n = S->P->n;

    if (S->count == S->cap)
    {
        slong cap = S->cap < 16 ? 16 : 2 * S->cap;
        char ** l = realloc(S->list, sizeof(char *) * (size_t) cap);

        if (l == NULL)
            return -1;
        S->list = l;
        S->cap = cap;
    }
    S->list[S->count] = malloc((size_t) n + 1);
    if (S->list[S->count] == NULL)
        return -1;
    memcpy(S->list[S->count], S->prefix, (size_t) n + 1);
    S->count++;
    return 0;
}

/* Extend the feasible prefix of k letters.  */
static void
extend(search_state * S, slong k)
{
    const wc_problem_struct * P = S->P;
    const char * letters;
    wc_problem_struct Q;

    if (S->failed)
        return;
    if (k == P->n)
    {
        if (keep(S) != 0)
            S->failed = 1;
        return;
    }
    /* the problem of the first k + 1 fixels: a shallow view of P */
    Q = *P;
    Q.n = k + 1;
    letters = P->fixels[k].state == WC_NEAR ? "as" : "lnrs";
    for (; *letters != '\0' && !S->failed; letters++)
    {
        int r;

        S->prefix[k] = *letters;
        S->prefix[k + 1] = '\0';
        r = ref_mode_feasible(&Q, S->prefix);
        S->lps++;
        if (r < 0)
            S->failed = 1;
        else if (r == 1)
            extend(S, k + 1);
    }
    S->prefix[k] = '\0';
}

static int
cmp_str(const void * a, const void * b)
{
    return strcmp(*(char * const *) a, *(char * const *) b);
}

int
ref_modes_search(char *** modes, slong * count, slong * lps,
                 const wc_problem_t P)
{
    search_state S;

    *modes = NULL;
    *count = 0;
    if (P->n < 1)
        return -1;
    S.P = P;
    S.list = NULL;
    S.count = S.cap = S.lps = 0;
    S.failed = 0;
    S.prefix = calloc((size_t) P->n + 1, 1);
    if (S.prefix == NULL)
        return -1;
    extend(&S, 0);
    free(S.prefix);
    if (lps != NULL)
        *lps = S.lps;
    if (S.failed)
    {
        ref_modes_free(S.list, S.count);
        return -1;
    }
    qsort(S.list, (size_t) S.count, sizeof(char *), cmp_str);
    *modes = S.list;
    *count = S.count;
    return 0;
}
