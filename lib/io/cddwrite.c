/* cddwrite.c -- cddlib's .ine/.ext format, written once for exact and
   float cones; wc_cone_fprint_cdd.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   A closure in cdd's homogeneous form: an H row '0 -h' for each facet
   h.g <= 0 (cdd reads b + a.g >= 0) and '0 e' for each equality, in
   linearity; a V block starting with the apex '1 0 .. 0', then '0 r' for
   rays and lines, the lines in linearity.  The empty set is the
   infeasible row '-1 0 .. 0', or a V block with no rows.  */

#include <config.h>

#include <flint/fmpz.h>
#include <flint/fmpz_mat.h>

#include "io/cddwrite.h"
#include "io/print.h"

/* ' 0' then the entries of row i of A times sign.  */
static void
cdd_row(FILE * out, const _wc_cdd_cone * C, const void * A, slong i,
        int sign)
{
    slong j;

    fputs(" 0", out);
    for (j = 0; j < C->d; j++)
    {
        putc(' ', out);
        C->entry(out, A, i, j, sign);
    }
    putc('\n', out);
}

/* 'linearity count first first+1 ..', nothing when count is 0.  */
static void
cdd_linearity(FILE * out, slong first, slong count)
{
    slong i;

    if (count == 0)
        return;
    fprintf(out, "linearity %ld", (long) count);
    for (i = 0; i < count; i++)
        fprintf(out, " %ld", (long) (first + i));
    putc('\n', out);
}

static void
cdd_empty(FILE * out, const _wc_cdd_cone * C, int which)
{
    slong i;

    if (which & 1)
    {
        /* -1 >= 0: no point satisfies it.  */
        fprintf(out, "H-representation\nbegin\n 1 %ld %s\n -1",
                (long) C->d + 1, C->numtype);
        for (i = 0; i < C->d; i++)
            fputs(" 0", out);
        fputs("\nend\n", out);
    }
    if (which & 2)
        fprintf(out, "V-representation\nbegin\n 0 %ld %s\nend\n",
                (long) C->d + 1, C->numtype);
}

void
_wc_cdd_fprint_reps(FILE * out, const _wc_cdd_cone * C, int empty,
                    int which)
{
    slong i;

    if (empty)
    {
        cdd_empty(out, C, which);
        return;
    }
    if (which & 1)
    {
        fputs("H-representation\n", out);
        cdd_linearity(out, C->m + 1, C->q);
        fprintf(out, "begin\n %ld %ld %s\n", (long) (C->m + C->q),
                (long) C->d + 1, C->numtype);
        for (i = 0; i < C->m; i++)
            cdd_row(out, C, C->ineqs, i, -1);
        for (i = 0; i < C->q; i++)
            cdd_row(out, C, C->eqs, i, 1);
        fputs("end\n", out);
    }
    if (which & 2)
    {
        fputs("V-representation\n", out);
        cdd_linearity(out, C->k + 2, C->l);
        fprintf(out, "begin\n %ld %ld %s\n", (long) (1 + C->k + C->l),
                (long) C->d + 1, C->numtype);
        fputs(" 1", out);
        for (i = 0; i < C->d; i++)
            fputs(" 0", out);
        putc('\n', out);
        for (i = 0; i < C->k; i++)
            cdd_row(out, C, C->rays, i, 1);
        for (i = 0; i < C->l; i++)
            cdd_row(out, C, C->lines, i, 1);
        fputs("end\n", out);
    }
}

/* ---------------------------------------------------------------------
   Exact cones.  */

static void
fmpz_entry(FILE * out, const void * A, slong i, slong j, int sign)
{
    fmpz_t t;

    fmpz_init(t);
    fmpz_mul_si(t, fmpz_mat_entry((const fmpz_mat_struct *) A, i, j), sign);
    fmpz_fprint(out, t);
    fmpz_clear(t);
}

int
_wc_cone_fprint_cdd(FILE * out, const wc_cone_t C, int which)
{
    _wc_cdd_cone K;
    slong f, i;

    K.d = C->d;
    K.numtype = "rational";
    K.entry = fmpz_entry;
    K.ineqs = C->ineqs;
    K.eqs = C->eqs;
    K.rays = C->rays;
    K.lines = C->lines;
    K.m = fmpz_mat_nrows(C->ineqs);
    K.q = fmpz_mat_nrows(C->eqs);
    K.k = fmpz_mat_nrows(C->rays);
    K.l = fmpz_mat_nrows(C->lines);
    if (C->empty)
        fputs("* the cone is empty\n", out);
    else if (wc_cone_excluded_faces(C) == 0)
        fputs("* the cone is closed: it equals the polyhedron below\n", out);
    else
    {
        fputs("* the cone is NOT closed: below is its closure; these faces "
              "of the\n* closure are not in the cone (rays numbered 0.. in "
              "V-representation\n* order after the apex row):\n", out);
        for (f = 0; f < C->nfaces; f++)
        {
            const wc_face_struct * F = C->faces + f;

            if (F->included)
                continue;
            fprintf(out, "*   excluded face of dim %ld, rays {",
                    (long) F->dim);
            for (i = 0; i < F->nrays; i++)
                fprintf(out, "%s%ld", i ? " " : "", (long) F->rays[i]);
            fputs("}\n", out);
        }
    }
    _wc_cdd_fprint_reps(out, &K, C->empty, which);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}
