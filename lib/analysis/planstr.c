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

    for (i = 0; T->strings != NULL && i < T->nstrings; i++)
        free(T->strings[i]);
    free(T->strings);
    free(T->state_first);
    free(T->state_str);
    free(T->contained_in);
    free(T->needed);
    memset(T, 0, sizeof(wc_plan_strings_struct));
}

/* A string over {m, s, u} as a number: its letters are digits m = 0,
   s = 1, u = 2, the first letter the most significant, so that numbers
   compare as the strings do in ASCII (m < s < u).  digit[i] is the
   weight 3^(n - 1 - i) of letter i.  */
static ulong
state_code(ulong S, ulong L, slong n, const ulong * digit)
{
    ulong c = 0;
    slong i;

    for (i = 0; i < n; i++)
    {
        ulong b = UWORD(1) << i;

        /* lost: s; kept: m; not yet: u, or s when nothing was lost */
        c += digit[i] * ((L & b) ? 1 : (S & b) ? 0 : L != 0 ? 2 : 1);
    }
    return c;
}

static void
code_string(char * s, ulong c, slong n, const ulong * digit)
{
    slong i;

    for (i = 0; i < n; i++)
        s[i] = "msu"[(c / digit[i]) % 3];
    s[n] = '\0';
}

/* The codes' indices among the strings: index[c] for the code c of a
   generated string, -1 for the others.  */
static int
strings_from_codes(wc_plan_strings_t T, const slong * index, ulong pow3,
                   const ulong * digit)
{
    ulong c;
    slong j = 0;

    T->strings = malloc(sizeof(char *) * (T->nstrings + 1));
    if (T->strings == NULL)
        return 0;
    for (c = 0; c < pow3; c++)
        if (index[c] >= 0)
        {
            if ((T->strings[j] = malloc(T->n + 1)) == NULL)
            {
                T->nstrings = j;
                return 0;
            }
            code_string(T->strings[j++], c, T->n, digit);
        }
    return 1;
}

/* Syntactic redundancy: some nonempty set R of s letters turned into u
   gives a string of the list; R runs over the subsets of the s letters
   in increasing order (as a bit mask), so that the string reported as
   containing it is always the same.  */
static void
strings_redundancy(wc_plan_strings_t T, const slong * index,
                   const ulong * code, const ulong * digit)
{
    slong i, k, n = T->n;

    T->nneeded = 0;
    for (i = 0; i < T->nstrings; i++)
    {
        ulong smask = 0, R;

        for (k = 0; k < n; k++)
            if (T->strings[i][k] == 's')
                smask |= UWORD(1) << k;
        T->contained_in[i] = -1;
        for (R = (UWORD(0) - smask) & smask; R != 0
             && T->contained_in[i] < 0; R = (R - smask) & smask)
        {
            ulong c = code[i];

            for (k = 0; k < n; k++)
                if ((R >> k) & 1)
                    c += digit[k];      /* s (1) to u (2) */
            T->contained_in[i] = index[c];
        }
        if (T->contained_in[i] < 0)
            T->needed[T->nneeded++] = i;
    }
}

int
wc_plan_strings(wc_plan_strings_t T, slong n, wc_error_t err)
{
    ulong full, S, L, pow3 = 1, digit[FLINT_BITS], c;
    slong k = 0, i;
    slong * index = NULL;
    ulong * code = NULL;
    int ok;

    wc_plan_strings_clear(T);
    if (n < 1 || n > WC_PLAN_MAX_FIXELS)
        return wc_error_set(err, WC_EINPUT, NULL, 0, 0,
                            "insertion plans take 1 to %d fixels, not %ld",
                            WC_PLAN_MAX_FIXELS, (long) n);
    T->n = n;
    full = (UWORD(1) << n) - 1;
    for (i = n - 1; i >= 0; i--, pow3 *= 3)
        digit[i] = pow3;
    /* every state's strings: sum over S of 2^|S| = 3^n, plus the
       no-progress strings */
    index = malloc(sizeof(slong) * (pow3 + 1));
    T->state_first = malloc(sizeof(slong) * (full + 2));
    T->state_str = malloc(sizeof(slong) * (pow3 + full + 1));
    ok = index != NULL && T->state_first != NULL && T->state_str != NULL;
    for (c = 0; ok && c < pow3; c++)
        index[c] = -1;
    /* By state, in the order the states generate them: first the lost-
       contact strings (the nonempty submasks L of S, ascending), then
       the no-progress string.  state_str holds codes until the strings
       are numbered.  */
    for (S = 0; ok && S <= full; S++)
    {
        T->state_first[S] = k;
        for (L = (UWORD(0) - S) & S; L != 0; L = (L - S) & S)
            T->state_str[k++] = (slong) state_code(S, L, n, digit);
        if (S != full)
            T->state_str[k++] = (slong) state_code(S, 0, n, digit);
    }
    if (ok)
    {
        T->state_first[full + 1] = k;
        for (i = 0; i < k; i++)
            index[T->state_str[i]] = 0;
        T->nstrings = 0;
        for (c = 0; c < pow3; c++)
            if (index[c] >= 0)
                index[c] = T->nstrings++;
        for (i = 0; i < k; i++)
            T->state_str[i] = index[T->state_str[i]];
        code = malloc(sizeof(ulong) * (T->nstrings + 1));
        T->contained_in = malloc(sizeof(slong) * (T->nstrings + 1));
        T->needed = malloc(sizeof(slong) * (T->nstrings + 1));
        ok = code != NULL && T->contained_in != NULL && T->needed != NULL
            && strings_from_codes(T, index, pow3, digit);
    }
    if (ok)
    {
        for (c = 0; c < pow3; c++)
            if (index[c] >= 0)
                code[index[c]] = c;
        strings_redundancy(T, index, code, digit);
    }
    free(index);
    free(code);
    if (!ok)
    {
        wc_plan_strings_clear(T);
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                            "out of memory (the strings of %ld fixels)",
                            (long) n);
    }
    return WC_OK;
}
