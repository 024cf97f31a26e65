/* plancones.c -- the cones of a plan's strings (their arrangement and
   which cells lie in which cone: cellset.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "analysis/planparts.h"
#include "analysis/wrench.h"

/* W(x) for P, whose fixel states are set from the letters: m, l, r, n
   touching; a, u near; s leaves the state alone (it means the same in
   both).  Q is a scratch copy of P.  */
static int
string_cone(wc_cone_t W, wc_problem_t Q, const char * x, wc_error_t err)
{
    slong i;

    for (i = 0; i < Q->n; i++)
    {
        if (strchr("mlrn", x[i]) != NULL)
            Q->fixels[i].state = WC_TOUCHING;
        else if (x[i] == 'a' || x[i] == 'u')
            Q->fixels[i].state = WC_NEAR;
    }
    return wc_wrench_cone_direct(W, NULL, Q, x, err);
}

wc_cone_struct *
_wc_plan_cones_init(slong count)
{
    wc_cone_struct * C = flint_malloc(sizeof(wc_cone_struct) * (count + 1));
    slong i;

    for (i = 0; i < count; i++)
        wc_cone_init(C + i, 3);
    return C;
}

void
_wc_plan_cones_clear(wc_cone_struct * C, slong count)
{
    slong i;

    if (C == NULL)
        return;
    for (i = 0; i < count; i++)
        wc_cone_clear(C + i);
    flint_free(C);
}

/* The outcome string of index x (base-3 digits, fixel 0 first).  */
void
_wc_plan_outcome_string(char * s, slong x, slong n)
{
    slong i;

    for (i = n - 1; i >= 0; i--, x /= 3)
        s[i] = "sma"[x % 3];
    s[n] = '\0';
}

slong
_wc_plan_pow3(slong n)
{
    slong p = 1;

    while (n-- > 0)
        p *= 3;
    return p;
}

/* C[k] := W(x[k]) for the plan model of P, k < count.  A maintained
   contact (m) either sticks, with its force in the static friction cone,
   or slides, with its force on an edge of the kinetic one; m stands for
   both, so the plan model takes the wider cone, |c_t| <= max(mu_s, mu_k)
   c_n, at every fixel.  The other letters of plan strings (s, u, a) carry
   no force, so raising mu_s changes the m letter only; when mu_k <= mu_s
   nothing changes.  */
static int
strings_cones(wc_cone_struct * C, char * const * x, const slong * idx,
              slong count, const wc_problem_t P, wc_error_t err)
{
    wc_problem_t Q;
    slong k;
    int status;

    wc_problem_init(Q);
    if ((status = wc_problem_set(Q, P)) != WC_OK)
        wc_error_set(err, status, NULL, 0, 0, "out of memory");
    for (k = 0; k < Q->n && status == WC_OK; k++)
        if (fmpq_cmp(Q->fixels[k].mu_k, Q->fixels[k].mu_s) > 0)
            fmpq_set(Q->fixels[k].mu_s, Q->fixels[k].mu_k);
    for (k = 0; k < count && status == WC_OK; k++)
        status = string_cone(C + k, Q, x[idx != NULL ? idx[k] : k], err);
    wc_problem_clear(Q);
    return status;
}

int
_wc_plan_needed_cones(wc_cone_struct * C, const wc_plan_strings_t T,
                      const wc_problem_t P, wc_error_t err)
{
    return strings_cones(C, T->strings, T->needed, T->nneeded, P, err);
}

/* The 3^n outcome strings, in index order.  */
static char **
outcome_strings(slong count, slong n)
{
    char ** x = calloc(count + 1, sizeof(char *));
    slong k;

    for (k = 0; k < count; k++)
    {
        x[k] = malloc(n + 1);
        _wc_plan_outcome_string(x[k], k, n);
    }
    return x;
}

static void
strings_free(char ** x, slong count)
{
    slong k;

    for (k = 0; k < count; k++)
        free(x[k]);
    free(x);
}

int
_wc_plan_outcome_cones(wc_cone_struct * C, slong count, const wc_problem_t P,
                       wc_error_t err)
{
    char ** x = outcome_strings(count, P->n);
    int status = strings_cones(C, x, NULL, count, P, err);

    strings_free(x, count);
    return status;
}
