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

   ref_modes_faces, for problems too large for the search, is a second
   method that shares nothing with the first: J_in = (n, r x n) and J_it
   = (t, r x t) computed here, the faces of the arrangement of their 2n
   planes from ref-cells.c (symbolic perturbation, no walk), and each face
   with v_in >= 0 on every touching fixel read as its mode by Table 1.

   Witnesses are the library's choice (a point of some face); the tests
   check each one with ref_twist_satisfies, not against a list here.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpq.h>
#include <flint/fmpz_mat.h>

#include "ref-cells.h"
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

/* row := a positive multiple of (d, r x d), an integer vector.  */
static void
jrow(fmpz * row, const fmpq * r, const fmpq * d)
{
    fmpq v[3];
    fmpq_t t;
    fmpz_t l;
    int j;

    fmpq_init(t);
    fmpz_init(l);
    for (j = 0; j < 3; j++)
        fmpq_init(v + j);
    fmpq_set(v + 0, d + 0);
    fmpq_set(v + 1, d + 1);
    fmpq_mul(v + 2, r + 0, d + 1);
    fmpq_mul(t, r + 1, d + 0);
    fmpq_sub(v + 2, v + 2, t);
    fmpz_one(l);
    for (j = 0; j < 3; j++)
        fmpz_lcm(l, l, fmpq_denref(v + j));
    for (j = 0; j < 3; j++)
    {
        fmpz_divexact(row + j, l, fmpq_denref(v + j));
        fmpz_mul(row + j, row + j, fmpq_numref(v + j));
    }
    for (j = 0; j < 3; j++)
        fmpq_clear(v + j);
    fmpz_clear(l);
    fmpq_clear(t);
}

int
ref_modes_faces(char *** modes, slong * count, const wc_problem_t P)
{
    slong n = P->n, i, f, found = 0, k;
    fmpz_mat_t H;
    ref_cells_t C;
    fmpq r[2], d[2];
    char ** list = NULL;
    int status = -1;

    *modes = NULL;
    *count = 0;
    if (n < 1)
        return -1;
    ref_cells_init(C);
    fmpz_mat_init(H, 2 * n, 3);
    for (i = 0; i < 2; i++)
    {
        fmpq_init(r + i);
        fmpq_init(d + i);
    }
    for (i = 0; i < n; i++)
    {
        const wc_fixel_struct * x = P->fixels + i;

        fmpq_sub(r + 0, x->point + 0, P->com + 0);
        fmpq_sub(r + 1, x->point + 1, P->com + 1);
        jrow(H->rows[2 * i], r, x->normal);
        fmpq_neg(d + 0, x->normal + 1);
        fmpq_set(d + 1, x->normal + 0);
        jrow(H->rows[2 * i + 1], r, d);
    }
    if (ref_cells_faces(C, H) != 0)
        goto cleanup;
    list = malloc(sizeof(char *) * (size_t) (C->count > 0 ? C->count : 1));
    if (list == NULL)
        goto cleanup;
    for (f = 0; f < C->count; f++)
    {
        const signed char * s = C->sign + f * C->m;
        char * m = malloc((size_t) n + 1);
        int ok = 1;

        if (m == NULL)
            goto cleanup;
        for (i = 0; i < n && ok; i++)
        {
            int vn = s[2 * i], vt = s[2 * i + 1];

            if (P->fixels[i].state == WC_NEAR)
                m[i] = vn < 0 ? 'a' : 's';
            else if (vn < 0)
                ok = 0;
            else
                m[i] = vn > 0 ? 's' : vt > 0 ? 'l' : vt < 0 ? 'r' : 'n';
        }
        m[n] = '\0';
        if (ok)
            list[found++] = m;
        else
            free(m);
    }
    qsort(list, (size_t) found, sizeof(char *), cmp_str);
    /* faces differing only where a letter ignores a sign give one mode */
    for (i = 0, k = 0; i < found; i++)
    {
        if (k > 0 && strcmp(list[k - 1], list[i]) == 0)
            free(list[i]);
        else
            list[k++] = list[i];
    }
    found = k;
    status = 0;

cleanup:
    if (status == 0)
    {
        *modes = list;
        *count = found;
    }
    else
        ref_modes_free(list, found);
    for (i = 0; i < 2; i++)
    {
        fmpq_clear(r + i);
        fmpq_clear(d + i);
    }
    fmpz_mat_clear(H);
    ref_cells_clear(C);
    return status;
}
