/* print.c -- text, JSON and cddlib writers.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include <flint/fmpz_vec.h>

#include "exact/vec3.h"
#include "core/certkind.h"
#include "io/print.h"
#include "io/printutil.h"
#include "io/cddwrite.h"


static void
json_fmpz(FILE * out, const fmpz_t x)
{
    char * s = fmpz_get_str(NULL, 10, x);

    fprintf(out, "\"%s\"", s);
    flint_free(s);
}

static void
json_rows(FILE * out, const fmpz_mat_t A)
{
    slong i, j;

    putc('[', out);
    for (i = 0; i < fmpz_mat_nrows(A); i++)
    {
        fputs(i ? ", [" : "[", out);
        for (j = 0; j < fmpz_mat_ncols(A); j++)
        {
            if (j)
                fputs(", ", out);
            json_fmpz(out, fmpz_mat_entry(A, i, j));
        }
        putc(']', out);
    }
    putc(']', out);
}

static int
cone_json(FILE * out, const wc_cone_t C)
{
    static const char * const key[4] = { "inequalities", "equalities",
                                         "rays", "lines" };
    const fmpz_mat_struct * rows[4] = { C->ineqs, C->eqs, C->rays, C->lines };
    slong f, i;

    if (C->empty)
    {
        fputs("{\"empty\": true}", out);
        return _wc_fprint_done(out);
    }
    fprintf(out, "{\"empty\": false, \"dim\": %ld, \"lineality_dim\": %ld",
            (long) C->dim, (long) C->lineality_dim);
    for (f = 0; f < 4; f++)
    {
        fprintf(out, ", \"%s\": ", key[f]);
        json_rows(out, rows[f]);
    }
    fputs(", \"faces\": [", out);
    for (f = 0; f < C->nfaces; f++)
    {
        const wc_face_struct * F = C->faces + f;

        fprintf(out, "%s{\"dim\": %ld, \"rays\": [", f ? ", " : "",
                (long) F->dim);
        for (i = 0; i < F->nrays; i++)
            fprintf(out, "%s%ld", i ? ", " : "", (long) F->rays[i]);
        fprintf(out, "], \"included\": %s}", _wc_tf(F->included));
    }
    fputs("]}", out);
    return _wc_fprint_done(out);
}

/* The names of the columns of a wrench (and of a facet normal's
   coefficients), when a matrix has three columns.  */
static const char * const wrench_cols[3] = { "fx", "fy", "torque" };

/* Rows of A, right-aligned per column under a header naming the columns
   of a wrench, each line prefixed; mark[i], when mark is not NULL, ends
   row i.  */
static void
text_rows(FILE * out, const fmpz_mat_t A, const char * indent,
          const char * tag, const char * const * mark)
{
    slong m = fmpz_mat_nrows(A), d = fmpz_mat_ncols(A), i, j;
    size_t * w = calloc((size_t) d + 1, sizeof(size_t));
    int named = d == 3;

    for (j = 0; w != NULL && j < d; j++)
        w[j] = named ? strlen(wrench_cols[j]) + 1 : 0;
    for (i = 0; i < m; i++)
        for (j = 0; j < d; j++)
        {
            size_t l = fmpz_sizeinbase(fmpz_mat_entry(A, i, j), 10) + 1;

            if (w != NULL && l > w[j])
                w[j] = l;
        }
    if (m > 0 && named && w != NULL)
    {
        fprintf(out, "%s  %*s", indent, (int) (strlen(tag) + 3), "");
        for (j = 0; j < d; j++)
            fprintf(out, " %*s", (int) w[j], wrench_cols[j]);
        putc('\n', out);
    }
    for (i = 0; i < m; i++)
    {
        fprintf(out, "%s  %s%-3ld", indent, tag, (long) i);
        for (j = 0; j < d; j++)
        {
            char * s = fmpz_get_str(NULL, 10, fmpz_mat_entry(A, i, j));

            fprintf(out, " %*s", w != NULL ? (int) w[j] : 0, s);
            flint_free(s);
        }
        if (mark != NULL && mark[i] != NULL)
            fprintf(out, "   %s", mark[i]);
        putc('\n', out);
    }
    free(w);
}

/* The face of C with dimension dim and exactly the rays whose flag is
   set in on[0..nrays), or NULL.  */
static const wc_face_struct *
find_face(const wc_cone_t C, slong dim, const char * on)
{
    slong f, i, k, nr = fmpz_mat_nrows(C->rays);

    for (f = 0; f < C->nfaces; f++)
    {
        const wc_face_struct * F = C->faces + f;

        if (F->dim != dim)
            continue;
        for (i = 0, k = 0; i < nr; i++)
            if (on[i] && (k >= F->nrays || F->rays[k++] != i))
                break;
        if (i == nr && k == F->nrays)
            return F;
    }
    return NULL;
}

/* Whether each ray (rows 0..nr) and each facet (rows nr..nr+m) of C is
   in C: the words that end their lines ("included", "excluded" for a
   ray; "strict" for a facet whose relative interior is not in C).  NULL
   when out of memory: the lines then go without them.  */
static const char **
row_marks(const wc_cone_t C)
{
    slong nr = fmpz_mat_nrows(C->rays), m = fmpz_mat_nrows(C->ineqs), i, j;
    const char ** mark = calloc((size_t) (nr + m) + 1, sizeof(char *));
    char * on = calloc((size_t) nr + 1, 1);
    const wc_face_struct * F;
    fmpz_t t;

    if (mark == NULL || on == NULL)
    {
        free(on);
        free(mark);
        return NULL;
    }
    fmpz_init(t);
    for (i = 0; i < nr; i++)
    {
        memset(on, 0, (size_t) nr);
        on[i] = 1;
        F = find_face(C, C->lineality_dim + 1, on);
        mark[i] = F == NULL ? NULL : F->included ? "included" : "excluded";
    }
    for (i = 0; i < m; i++)
    {
        for (j = 0; j < nr; j++)
        {
            _fmpz_vec_dot(t, fmpz_mat_entry(C->ineqs, i, 0),
                          fmpz_mat_entry(C->rays, j, 0), C->d);
            on[j] = fmpz_is_zero(t);
        }
        F = find_face(C, C->dim - 1, on);
        mark[nr + i] = F == NULL ? NULL : F->included ? "included"
            : "strict (excluded)";
    }
    fmpz_clear(t);
    free(on);
    return mark;
}

static int
cone_text(FILE * out, const wc_cone_t C, const char * indent)
{
    slong f, i, excl, nr;
    const char ** mark;

    if (C->empty)
    {
        fprintf(out, "%sempty (no wrench is consistent with this mode)\n",
                indent);
        return _wc_fprint_done(out);
    }
    excl = wc_cone_excluded_faces(C);
    nr = fmpz_mat_nrows(C->rays);
    mark = excl > 0 ? row_marks(C) : NULL;
    fprintf(out, "%sdimension %ld, lineality %ld, %s", indent, (long) C->dim,
            (long) C->lineality_dim, excl == 0 ? "closed" : "not closed");
    if (excl > 0)
        fprintf(out, " (%ld of %ld faces excluded)", (long) excl,
                (long) C->nfaces);
    putc('\n', out);
    fprintf(out, "%srays of the closure%s:%s\n", indent,
            excl > 0 ? " (excluded: the open ray is not in the cone)" : "",
            nr ? "" : " none");
    text_rows(out, C->rays, indent, "r", mark);
    if (C->lineality_dim > 0)
    {
        fprintf(out, "%slines:\n", indent);
        text_rows(out, C->lines, indent, "l", NULL);
    }
    fprintf(out, "%sfacets (h . g <= 0%s):%s\n", indent,
            excl > 0 ? "; strict: h . g < 0 inside the facet" : "",
            fmpz_mat_nrows(C->ineqs) ? "" : " none");
    text_rows(out, C->ineqs, indent, "h", mark != NULL ? mark + nr : NULL);
    if (fmpz_mat_nrows(C->eqs) > 0)
    {
        fprintf(out, "%sequalities (e . g = 0):\n", indent);
        text_rows(out, C->eqs, indent, "e", NULL);
    }
    free(mark);
    fprintf(out, "%sfaces (by their rays):\n", indent);
    for (f = 0; f < C->nfaces; f++)
    {
        const wc_face_struct * F = C->faces + f;
        int col = 0;

        col += fprintf(out, "%s  dim %ld  {", indent, (long) F->dim);
        for (i = 0; i < F->nrays; i++)
            col += fprintf(out, "%sr%ld", i ? " " : "", (long) F->rays[i]);
        col += fprintf(out, "}");
        fprintf(out, "%*s%s\n", col < 28 ? 28 - col : 1, "",
                F->included ? "included" : "excluded");
    }
    return _wc_fprint_done(out);
}

int
wc_cone_fprint(FILE * out, const wc_cone_t C, const wc_print_opts * o)
{
    switch (o != NULL ? o->format : WC_FORMAT_TEXT)
    {
    case WC_FORMAT_JSON:
        return cone_json(out, C);
    case WC_FORMAT_CDD:
        return _wc_cone_fprint_cdd(out, C, 3);
    case WC_FORMAT_INE:
        return _wc_cone_fprint_cdd(out, C, 1);
    case WC_FORMAT_EXT:
        return _wc_cone_fprint_cdd(out, C, 2);
    default:
        return cone_text(out, C, _wc_print_indent(o));
    }
}

static int
trace_text(FILE * out, const wc_trace_t T, const char * prefix)
{
    slong e, i, j;

    for (e = 0; e < T->len; e++)
    {
        const wc_trace_entry_struct * t = T->entries + e;
        slong r = fmpq_mat_nrows(t->m), c = fmpq_mat_ncols(t->m);
        size_t * w = calloc((size_t) c + 1, sizeof(size_t));

        fprintf(out, "%s%s (%ld x %ld)%s%s\n", prefix, t->name, (long) r,
                (long) c, t->note ? ": " : "", t->note ? t->note : "");
        for (i = 0; i < r; i++)
            for (j = 0; j < c; j++)
            {
                char * s = fmpq_get_str(NULL, 10, fmpq_mat_entry(t->m, i, j));

                if (w != NULL && strlen(s) > w[j])
                    w[j] = strlen(s);
                flint_free(s);
            }
        for (i = 0; i < r; i++)
        {
            fprintf(out, "%s  [", prefix);
            for (j = 0; j < c; j++)
            {
                char * s = fmpq_get_str(NULL, 10, fmpq_mat_entry(t->m, i, j));

                fprintf(out, " %*s", w != NULL ? (int) w[j] : 0, s);
                flint_free(s);
            }
            fputs(" ]\n", out);
        }
        free(w);
    }
    return _wc_fprint_done(out);
}

static int
trace_json(FILE * out, const wc_trace_t T, const wc_print_opts * o)
{
    slong e, i;

    putc('[', out);
    for (e = 0; e < T->len; e++)
    {
        const wc_trace_entry_struct * t = T->entries + e;
        slong r = fmpq_mat_nrows(t->m), c = fmpq_mat_ncols(t->m);

        fputs(e ? ", {\"name\": " : "{\"name\": ", out);
        wc_fprint_json_string(out, t->name);
        if (t->note != NULL)
        {
            fputs(", \"note\": ", out);
            wc_fprint_json_string(out, t->note);
        }
        fprintf(out, ", \"rows\": %ld, \"cols\": %ld, \"matrix\": [",
                (long) r, (long) c);
        for (i = 0; i < r; i++)
        {
            if (i)
                fputs(", ", out);
            wc_fprint_qvec(out, t->m->rows[i], c, o);
        }
        fputs("]}", out);
    }
    putc(']', out);
    return _wc_fprint_done(out);
}

int
wc_trace_fprint(FILE * out, const wc_trace_t T, const wc_print_opts * o)
{
    return _wc_print_json(o) ? trace_json(out, T, o)
        : trace_text(out, T, _wc_print_indent(o));
}

int
wc_modes_fprint(FILE * out, const wc_modes_t M, int witness,
                const wc_print_opts * o)
{
    int json = _wc_print_json(o);
    slong i;

    if (!json)
    {
        for (i = 0; i < M->count; i++)
        {
            fputs(M->modes[i], out);
            if (witness)
            {
                fputs("  nu = ", out);
                _wc_fprint_zvec(out, WC_ROW(M->witness, i), 3, 0);
            }
            putc('\n', out);
        }
        return _wc_fprint_done(out);
    }
    fprintf(out, WC_JSON_OPEN "\"fixels\": %ld, \"modes\": [",
            (long) M->n);
    for (i = 0; i < M->count; i++)
    {
        if (i)
            fputs(", ", out);
        wc_fprint_json_string(out, M->modes[i]);
    }
    fprintf(out, "], \"count\": %ld", (long) M->count);
    if (witness)
    {
        fputs(", \"witnesses\": [", out);
        for (i = 0; i < M->count; i++)
        {
            if (i)
                fputs(", ", out);
            _wc_fprint_zvec(out, WC_ROW(M->witness, i), 3, 1);
        }
        putc(']', out);
    }
    fputs("}\n", out);
    return _wc_fprint_done(out);
}

int
wc_certificate_fprint(FILE * out, const wc_certificate_t C,
                      const wc_problem_t P, const wc_print_opts * o)
{
    int json = _wc_print_json(o);
    slong m = fmpz_mat_nrows(C->rows), i;

    if (!json)
    {
        fprintf(out, "mode %s: %s\n", C->mode,
                C->feasible ? "kinematically feasible" : "infeasible");
        if (C->feasible)
        {
            fputs("  witness twist nu = ", out);
            _wc_fprint_zvec(out, C->witness, 3, 0);
            fputs("\n  constraints (row . nu REL 0):\n", out);
        }
        else
            fputs("  constraints (row . nu REL 0) and Motzkin multipliers y:\n",
                  out);
        for (i = 0; i < m; i++)
        {
            fputs("    ", out);
            _wc_fprint_zvec(out, WC_ROW(C->rows, i), 3, 0);
            fprintf(out, " %s 0", wc_relation_str(C->rel[i]));
            if (!C->feasible)
            {
                fputs("   y = ", out);
                fmpz_fprint(out, C->mult + i);
            }
            putc('\n', out);
        }
        if (!C->feasible)
            fputs("  sum of y_k row_k is 0, y >= 0 on > and >= rows, y > 0 on a "
                  "> row:\n  no twist satisfies the mode (Motzkin's "
                  "transposition theorem)\n", out);
        return _wc_fprint_done(out);
    }
    fputs(WC_JSON_OPEN "\"kind\": \"" WC_CERT_KIND_MODE "\", \"mode\": ", out);
    wc_fprint_json_string(out, C->mode);
    fprintf(out, ", \"feasible\": %s", _wc_tf(C->feasible));
    if (C->feasible)
    {
        fputs(", \"witness\": ", out);
        _wc_fprint_zvec(out, C->witness, 3, 1);
    }
    fputs(", \"constraints\": [", out);
    for (i = 0; i < m; i++)
    {
        fputs(i ? ", {\"row\": " : "{\"row\": ", out);
        _wc_fprint_zvec(out, WC_ROW(C->rows, i), 3, 1);
        fprintf(out, ", \"relation\": \"%s\"}", wc_relation_str(C->rel[i]));
    }
    putc(']', out);
    if (!C->feasible)
    {
        fputs(", \"multipliers\": ", out);
        _wc_fprint_zvec(out, C->mult, m, 1);
    }
    fputs(", \"problem\": {\"com\": ", out);
    wc_fprint_qvec(out, P->com, 2, o);
    fputs(", \"fixels\": [", out);
    for (i = 0; i < P->n; i++)
    {
        fputs(i ? ", {\"point\": " : "{\"point\": ", out);
        wc_fprint_qvec(out, P->fixels[i].point, 2, o);
        fputs(", \"normal\": ", out);
        wc_fprint_qvec(out, P->fixels[i].normal, 2, o);
        fprintf(out, ", \"state\": \"%s\"}",
                P->fixels[i].state == WC_NEAR ? "near" : "touching");
    }
    fputs("]}}\n", out);
    return _wc_fprint_done(out);
}
