/* planstr.c -- the strings of an insertion plan: states, and the contact
   modes it needs.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "analysis/plan.h"

void
wc_plan_state_string(char * s, ulong S, slong n)
{
    slong i;

    for (i = 0; i < n; i++)
        s[i] = (S >> i) & 1 ? '1' : '0';
    s[n] = '\0';
}

void
wc_plan_strings_init(wc_plan_strings_t T)
{
    memset(T, 0, sizeof(wc_plan_strings_struct));
}

void
wc_plan_strings_clear(wc_plan_strings_t T)
{
    slong i;

    for (i = 0; i < T->nstrings; i++)
        free(T->strings[i]);
    free(T->strings);
    free(T->state_first);
    free(T->state_str);
    free(T->contained_in);
    free(T->needed);
    memset(T, 0, sizeof(wc_plan_strings_struct));
}

static int
str_ptr_cmp(const void * p, const void * q)
{
    return strcmp(*(char * const *) p, *(char * const *) q);
}

static slong
find_string(const wc_plan_strings_t T, const char * s)
{
    char * const * hit = bsearch(&s, T->strings, T->nstrings, sizeof(char *),
                                 str_ptr_cmp);

    return hit == NULL ? -1 : hit - T->strings;
}

/* The string of state S with lost contacts L (L empty: no progress).  */
static char *
state_string(ulong S, ulong L, slong n)
{
    char * s = malloc(n + 1);
    slong i;

    for (i = 0; i < n; i++)
    {
        ulong b = UWORD(1) << i;

        s[i] = (L & b) ? 's' : (S & b) ? 'm' : L != 0 ? 'u' : 's';
    }
    s[n] = '\0';
    return s;
}

int
wc_plan_strings(wc_plan_strings_t T, slong n, wc_error_t err)
{
    ulong full, S, L, R;
    slong cap, count = 0, k, i, j;
    char ** all;

    wc_plan_strings_clear(T);
    if (n < 1 || n > WC_PLAN_MAX_FIXELS)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "insertion plans take 1 to %d fixels, not %ld",
                            WC_PLAN_MAX_FIXELS, (long) n);
    T->n = n;
    full = (UWORD(1) << n) - 1;
    /* sum over S of 2^|S| = 3^n, plus the no-progress strings */
    for (cap = 1, i = 0; i < n; i++)
        cap *= 3;
    cap += full + 1;
    all = malloc(sizeof(char *) * cap);
    for (S = 0; S <= full; S++)
    {
        for (L = S; L != 0; L = (L - 1) & S)
            all[count++] = state_string(S, L, n);
        if (S != full)
            all[count++] = state_string(S, 0, n);
    }
    /* The same string arises in several states: keep one copy.  */
    qsort(all, count, sizeof(char *), str_ptr_cmp);
    for (i = 0, j = 0; i < count; i++)
    {
        if (j > 0 && strcmp(all[i], all[j - 1]) == 0)
            free(all[i]);
        else
            all[j++] = all[i];
    }
    T->strings = all;
    T->nstrings = j;

    /* By state, in the order the states generate them.  */
    T->state_first = malloc(sizeof(slong) * (full + 2));
    T->state_str = malloc(sizeof(slong) * count);
    for (S = 0, k = 0; S <= full; S++)
    {
        T->state_first[S] = k;
        /* the nonempty submasks of S in ascending order */
        for (L = (UWORD(0) - S) & S; L != 0; L = (L - S) & S)
        {
            char * s = state_string(S, L, n);

            T->state_str[k++] = find_string(T, s);
            free(s);
        }
        if (S != full)
        {
            char * s = state_string(S, 0, n);

            T->state_str[k++] = find_string(T, s);
            free(s);
        }
    }
    T->state_first[full + 1] = k;

    /* Syntactic redundancy: some nonempty set R of s letters turned into
       u gives a string of the list.  */
    T->contained_in = malloc(sizeof(slong) * T->nstrings);
    T->needed = malloc(sizeof(slong) * T->nstrings);
    T->nneeded = 0;
    {
        char * b = malloc(n + 1);

        for (i = 0; i < T->nstrings; i++)
        {
            const char * s = T->strings[i];
            ulong smask = 0;

            for (k = 0; k < n; k++)
                if (s[k] == 's')
                    smask |= UWORD(1) << k;
            T->contained_in[i] = -1;
            /* the submasks R of smask in increasing order, so that the
               string reported as containing it is always the same */
            for (R = 1; R <= smask && T->contained_in[i] < 0; R++)
            {
                if ((R & smask) != R)
                    continue;
                for (k = 0; k < n; k++)
                    b[k] = (R >> k) & 1 ? 'u' : s[k];
                b[n] = '\0';
                T->contained_in[i] = find_string(T, b);
            }
            if (T->contained_in[i] < 0)
                T->needed[T->nneeded++] = i;
        }
        free(b);
    }
    return WC_OK;
}

