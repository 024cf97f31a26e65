/* fconeprint.c -- a float cone (wc_fcone_t) as text, JSON or cdd.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <string.h>

#include "io/fconeprint.h"
#include "io/cddwrite.h"

/* x with %.17g, which reads back to the same double; -0 prints as 0.  */
static void
put_double(FILE * out, double x)
{
    fprintf(out, "%.17g", x == 0.0 ? 0.0 : x);
}

static void
json_rows_d(FILE * out, const d_mat_t A)
{
    slong i, j;

    putc('[', out);
    for (i = 0; i < A->r; i++)
    {
        fputs(i ? ", [" : "[", out);
        for (j = 0; j < A->c; j++)
        {
            if (j)
                fputs(", ", out);
            put_double(out, d_mat_entry(A, i, j));
        }
        putc(']', out);
    }
    putc(']', out);
}

static void
json_flags(FILE * out, const int * f, slong len)
{
    slong i;

    putc('[', out);
    for (i = 0; i < len; i++)
        fprintf(out, "%s%s", i ? ", " : "", f[i] ? "true" : "false");
    putc(']', out);
}

static void
fprint_json(FILE * out, const wc_fcone_t C)
{
    fputs(C->empty ? "{\"empty\": true" : "{\"empty\": false", out);
    fputs(", \"arith\": \"double\", \"eps\": ", out);
    put_double(out, C->eps);
    if (C->empty)
    {
        putc('}', out);
        return;
    }
    fprintf(out, ", \"dim\": %ld, \"lineality_dim\": %ld, \"closed\": %s, "
            "\"inequalities\": ", (long) C->dim, (long) C->lineality_dim,
            C->closed ? "true" : "false");
    json_rows_d(out, C->ineqs);
    fputs(", \"strict\": ", out);
    json_flags(out, C->strict, C->ineqs->r);
    fputs(", \"equalities\": ", out);
    json_rows_d(out, C->eqs);
    fputs(", \"rays\": ", out);
    json_rows_d(out, C->rays);
    fputs(", \"strict_rays\": ", out);
    json_flags(out, C->strict_rays, C->rays->r);
    fputs(", \"lines\": ", out);
    json_rows_d(out, C->lines);
    putc('}', out);
}

static void
text_rows_d(FILE * out, const d_mat_t A, const char * tag, const int * f,
            const char * yes, const char * no)
{
    static const char * const cols[3] = { "fx", "fy", "torque" };
    slong i, j;

    /* The columns of a wrench (a normal's coefficients of them).  */
    if (A->r > 0 && A->c == 3)
    {
        fprintf(out, "    %*s", (int) strlen(tag) + 3, "");
        for (j = 0; j < 3; j++)
            fprintf(out, " %24s", cols[j]);
        putc('\n', out);
    }
    for (i = 0; i < A->r; i++)
    {
        fprintf(out, "    %s%-3ld", tag, (long) i);
        for (j = 0; j < A->c; j++)
        {
            double x = d_mat_entry(A, i, j);

            fprintf(out, " %24.17g", x == 0.0 ? 0.0 : x);
        }
        if (f != NULL)
            fprintf(out, "  %s", f[i] ? yes : no);
        putc('\n', out);
    }
}

static void
fprint_text(FILE * out, const wc_fcone_t C)
{
    slong i, ns = 0;

    fputs("  floating point, not exact: the paper's route in C doubles with "
          "cddlib's\n  double-precision build", out);
    fprintf(out, " (tolerance %g)\n", C->eps);
    if (C->empty)
    {
        fputs("  empty (no wrench is consistent with this mode)\n", out);
        return;
    }
    for (i = 0; i < C->ineqs->r; i++)
        ns += C->strict[i] != 0;
    fprintf(out, "  dimension %ld, lineality %ld, %s", (long) C->dim,
            (long) C->lineality_dim, C->closed ? "closed" : "not closed");
    if (!C->closed)
        fprintf(out, " (%ld of %ld facets strict)", (long) ns,
                (long) C->ineqs->r);
    putc('\n', out);
    fprintf(out, "  rays of the closure (unit length):%s\n",
            C->rays->r ? "" : " none");
    text_rows_d(out, C->rays, "r", C->strict_rays, "excluded", "included");
    if (C->lineality_dim > 0)
    {
        fputs("  lines (orthonormal basis):\n", out);
        text_rows_d(out, C->lines, "l", NULL, NULL, NULL);
    }
    fprintf(out, "  facets (h . g <= 0, unit normals):%s\n",
            C->ineqs->r ? "" : " none");
    text_rows_d(out, C->ineqs, "h", C->strict, "strict (excluded)",
                "included");
    if (C->eqs->r > 0)
    {
        fputs("  equalities (e . g = 0, orthonormal basis):\n", out);
        text_rows_d(out, C->eqs, "e", NULL, NULL, NULL);
    }
}

static void
double_entry(FILE * out, const void * A, slong i, slong j, int sign)
{
    put_double(out, sign * d_mat_entry((const d_mat_struct *) A, i, j));
}

static void
fprint_cdd(FILE * out, const wc_fcone_t C, int which)
{
    slong m = C->ineqs->r, k = C->rays->r, i;
    _wc_cdd_cone K;

    K.d = C->d;
    K.numtype = "real";
    K.entry = double_entry;
    K.ineqs = C->ineqs;
    K.eqs = C->eqs;
    K.rays = C->rays;
    K.lines = C->lines;
    K.m = m;
    K.q = C->eqs->r;
    K.k = k;
    K.l = C->lines->r;
    fprintf(out, "* floating point, not exact: cddlib's double-precision "
            "build, tolerance %g\n", C->eps);
    if (C->empty)
    {
        fputs("* the cone is empty\n", out);
        _wc_cdd_fprint_reps(out, &K, 1, which);
        return;
    }
    if (C->closed)
        fputs("* the cone is closed: it equals the polyhedron below\n", out);
    else
    {
        fputs("* the cone is NOT closed: below is its closure, without the "
              "apex and\n* these (H rows numbered from 1, V rows from 2, "
              "after the apex row):\n", out);
        for (i = 0; i < m; i++)
            if (C->strict[i])
                fprintf(out, "*   strict facet, H row %ld\n", (long) i + 1);
        for (i = 0; i < k; i++)
            if (C->strict_rays[i])
                fprintf(out, "*   excluded ray, V row %ld\n", (long) i + 2);
    }
    _wc_cdd_fprint_reps(out, &K, 0, which);
}

int
wc_fcone_fprint(FILE * out, const wc_fcone_t C, const wc_print_opts * o)
{
    switch (o != NULL ? o->format : WC_FORMAT_TEXT)
    {
    case WC_FORMAT_TEXT: fprint_text(out, C); break;
    case WC_FORMAT_JSON: fprint_json(out, C); break;
    case WC_FORMAT_INE: fprint_cdd(out, C, 1); break;
    case WC_FORMAT_EXT: fprint_cdd(out, C, 2); break;
    case WC_FORMAT_CDD: fprint_cdd(out, C, 3); break;
    default: return WC_EINTERNAL;
    }
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

