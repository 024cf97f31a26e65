/* compareprint.c -- the report of `wrenchcone compare`: text for people
   or one JSON object.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/text.h"
#include "core/version.h"
#include "io/compareprint.h"
#include "io/print.h"
#include "float/angle.h"
#include "exact/vec3.h"

static const char *
rep_title(wc_rep_kind k, int json)
{
    if (k == WC_REP_GENERATORS)
        return json ? "generators ('rays', 'lines')"
            : "V-representation (generators)";
    if (k == WC_REP_INEQUALITIES)
        return json ? "inequalities ('inequalities', 'equalities')"
            : "H-representation (inequalities)";
    return "'empty': true";
}

static const char *
rep_key(wc_rep_kind k)
{
    return k == WC_REP_GENERATORS ? "generators"
        : k == WC_REP_INEQUALITIES ? "inequalities" : "statement";
}

static void
text_angle(FILE * out, double a)
{
    if (isnan(a))
        fputs("n/a", out);
    else if (isinf(a))
        fputs("inf (no unit vector on the other side)", out);
    else
        fprintf(out, "%.6g", a);
}

static void
text_unit(FILE * out, const double * u)
{
    fprintf(out, "(%.6g, %.6g, %.6g)", u[0] + 0.0, u[1] + 0.0, u[2] + 0.0);
}

static void
json_double(FILE * out, double a)
{
    if (isfinite(a))
        fprintf(out, "%.17g", a + 0.0);
    else
        fputs("null", out);
}

static void
json_unit(FILE * out, const double * u)
{
    putc('[', out);
    json_double(out, u[0]);
    fputs(", ", out);
    json_double(out, u[1]);
    fputs(", ", out);
    json_double(out, u[2]);
    putc(']', out);
}

/* "r2 r5" for the unmatched entries of U named prefix + index; returns
   how many.  */
static slong
text_unmatched(FILE * out, const wc_cmp_vec * U, slong n, const char * prefix,
               int lines)
{
    slong i, c = 0;

    for (i = 0; i < n; i++)
        if (!U[i].matched)
        {
            fprintf(out, "%s%s%ld", c ? (lines ? ", " : " ") : "", prefix,
                    (long) i);
            if (lines && U[i].line != 0)
                fprintf(out, " (line %ld)", U[i].line);
            c++;
        }
    return c;
}

static slong
count_unmatched(const wc_cmp_vec * U, slong n)
{
    slong i, c = 0;

    for (i = 0; i < n; i++)
        c += !U[i].matched;
    return c;
}

static void
text_vecs(FILE * out, const wc_cmp_vec * U, slong n, const char * name,
          const char * other, int rays)
{
    slong i;

    for (i = 0; i < n; i++)
    {
        char id[32];

        snprintf(id, sizeof id, "%s%ld", name, (long) i);
        fprintf(out, "    %-5s ", id);
        text_unit(out, U[i].unit);
        if (U[i].line != 0)
            fprintf(out, "  line %ld", U[i].line);
        if (rays)
        {
            fputs("  angle ", out);
            text_angle(out, U[i].angle);
        }
        if (U[i].nearest >= 0)
        {
            fprintf(out, "  nearest %s%ld at ", other, (long) U[i].nearest);
            text_angle(out, U[i].nearest_angle);
        }
        else
            fputs("  nearest: none", out);
        putc('\n', out);
    }
}

static void
text_cone_summary(FILE * out, const wc_cone_t C)
{
    if (C->empty)
    {
        fputs("empty", out);
        return;
    }
    fprintf(out, "nonempty, dimension %ld, lineality %ld, %ld extreme "
            "ray%s, %ld facet%s", (long) C->dim, (long) C->lineality_dim,
            (long) fmpz_mat_nrows(C->rays),
            fmpz_mat_nrows(C->rays) == 1 ? "" : "s",
            (long) fmpz_mat_nrows(C->ineqs),
            fmpz_mat_nrows(C->ineqs) == 1 ? "" : "s");
}

/* The reasons a representation is outside the tolerance, "; "-separated,
   each prefixed by prefix.  first says whether none was written yet.  */
static void
text_reasons(FILE * out, const wc_cmp_rep_struct * C, const wc_cone_t W,
             double tol, const char * prefix, int * first)
{
    const wc_cone_struct * F = C->cone;
    const struct
    {
        const wc_cmp_vec * U;
        slong n;
        const char * what, * prefix;
    }
    un[4] = {
        { C->exact_rays, C->nexact_rays, "missing ray", "r" },
        { C->rays, C->nrays, "extra ray", "fr" },
        { C->exact_facets, C->nexact_facets, "missing facet", "h" },
        { C->facets, C->nfacets, "extra facet", "fh" }
    };
    slong c;
    int k;

#define NEXT() (fputs(*first ? "" : "; ", out), *first = 0, \
                fputs(prefix, out))
    if (C->differs & WC_CMP_EMPTY)
    {
        NEXT();
        fprintf(out, "emptiness differs (exact %s, float %s)",
                W->empty ? "empty" : "nonempty",
                F->empty ? "empty" : "nonempty");
    }
    if (C->differs & WC_CMP_DIM)
    {
        NEXT();
        fprintf(out, "dimension differs (exact %ld, float %ld)",
                (long) W->dim, (long) F->dim);
    }
    if (C->differs & WC_CMP_LINEALITY)
    {
        NEXT();
        fprintf(out, "lineality differs (exact %ld, float %ld)",
                (long) W->lineality_dim, (long) F->lineality_dim);
    }
    if (C->differs & WC_CMP_DISTANCE)
    {
        NEXT();
        fputs("Hausdorff distance ", out);
        text_angle(out, C->hausdorff);
        fprintf(out, " > tol %g", tol);
    }
    for (k = 0; k < 4; k++)
        if ((c = count_unmatched(un[k].U, un[k].n)) > 0)
        {
            NEXT();
            fprintf(out, "%ld %s%s (", (long) c, un[k].what,
                    c == 1 ? "" : "s");
            text_unmatched(out, un[k].U, un[k].n, un[k].prefix, 0);
            putc(')', out);
        }
#undef NEXT
}

static void
text_rep(FILE * out, const wc_cmp_rep_struct * C, const wc_cone_t W,
         const char * file, int json_file)
{
    const wc_cone_struct * F = C->cone;

    fprintf(out, "\nfloat cone: %s, %s at line %ld\n", file,
            rep_title(C->kind, json_file), C->line);
    fputs("  read exactly: ", out);
    text_cone_summary(out, F);
    fprintf(out, "\n  emptiness: exact %s, float %s\n",
            W->empty ? "empty" : "nonempty", F->empty ? "empty" : "nonempty");
    if (W->empty || F->empty)
    {
        if (W->empty != F->empty)
            fputs("  (the closures are not compared: one side is empty)\n",
                  out);
        return;
    }
    fprintf(out, "  dimension: exact %ld, float %ld; lineality: exact %ld, "
            "float %ld\n", (long) W->dim, (long) F->dim,
            (long) W->lineality_dim, (long) F->lineality_dim);
    fprintf(out, "  float extreme rays: angle to the exact closure, nearest "
            "exact ray%s\n", C->nrays ? "" : ": none");
    text_vecs(out, C->rays, C->nrays, "fr", "r", 1);
    fprintf(out, "  exact extreme rays: angle to the float closure, nearest "
            "float ray%s\n", C->nexact_rays ? "" : ": none");
    text_vecs(out, C->exact_rays, C->nexact_rays, "r", "fr", 1);
    fprintf(out, "  float facets (unit h, h . g <= 0): nearest exact "
            "facet%s\n", C->nfacets ? "" : ": none");
    text_vecs(out, C->facets, C->nfacets, "fh", "h", 0);
    fprintf(out, "  exact facets: nearest float facet%s\n",
            C->nexact_facets ? "" : ": none");
    text_vecs(out, C->exact_facets, C->nexact_facets, "h", "fh", 0);
    fputs("  Hausdorff distance ", out);
    text_angle(out, C->hausdorff);
    fputs(" (exact to float ", out);
    text_angle(out, C->exact_to_float);
    fputs(", float to exact ", out);
    text_angle(out, C->float_to_exact);
    fputs(")\n  missing rays: ", out);
    if (text_unmatched(out, C->exact_rays, C->nexact_rays, "r", 1) == 0)
        fputs("none", out);
    fputs("\n  extra rays: ", out);
    if (text_unmatched(out, C->rays, C->nrays, "fr", 1) == 0)
        fputs("none", out);
    fputs("\n  missing facets: ", out);
    if (text_unmatched(out, C->exact_facets, C->nexact_facets, "h", 1) == 0)
        fputs("none", out);
    fputs("\n  extra facets: ", out);
    if (text_unmatched(out, C->facets, C->nfacets, "fh", 1) == 0)
        fputs("none", out);
    putc('\n', out);
    if (C->nredundant > 0)
    {
        slong i;

        fprintf(out, "  redundant input rows (on no %s of the float cone): "
                "line", C->kind == WC_REP_GENERATORS ? "extreme ray"
                : "facet");
        for (i = 0; i < C->nredundant; i++)
            fprintf(out, "%s %ld", i ? "," : (C->nredundant > 1 ? "s" : ""),
                    C->redundant[i]);
        putc('\n', out);
    }
}

static void
json_vecs(FILE * out, const wc_cmp_vec * U, slong n, const char * dirkey,
          const char * otherkey, const char * flag, int rays, int foreign)
{
    slong i;

    putc('[', out);
    for (i = 0; i < n; i++)
    {
        fprintf(out, "%s{\"%s\": ", i ? ", " : "", dirkey);
        json_unit(out, U[i].unit);
        if (foreign)
        {
            fputs(", \"line\": ", out);
            if (U[i].line != 0)
                fprintf(out, "%ld", U[i].line);
            else
                fputs("null", out);
        }
        if (rays)
        {
            fprintf(out, ", \"angle_to_%s\": ", foreign ? "exact" : "float");
            json_double(out, U[i].angle);
        }
        fprintf(out, ", \"nearest_%s\": ", otherkey);
        if (U[i].nearest >= 0)
            fprintf(out, "%ld", (long) U[i].nearest);
        else
            fputs("null", out);
        fputs(", \"nearest_angle\": ", out);
        json_double(out, U[i].nearest_angle);
        fprintf(out, ", \"%s\": %s}", flag, U[i].matched ? "false" : "true");
    }
    putc(']', out);
}

static void
json_differences(FILE * out, unsigned d)
{
    static const char * const name[] = {
        "empty", "dimension", "lineality", "distance", "rays", "facets",
        "mode"
    };
    int i, first = 1;

    putc('[', out);
    for (i = 0; i < 7; i++)
        if (d & (1u << i))
        {
            fprintf(out, "%s\"%s\"", first ? "" : ", ", name[i]);
            first = 0;
        }
    putc(']', out);
}

static void
json_rows_unit(FILE * out, const fmpz_mat_t A)
{
    slong i;
    double u[3];

    putc('[', out);
    for (i = 0; i < fmpz_mat_nrows(A); i++)
    {
        fputs(i ? ", " : "", out);
        _wc_zv3_unit_d(u, WC_ROW(A, i));
        json_unit(out, u);
    }
    putc(']', out);
}

static void
json_rep(FILE * out, const wc_cmp_rep_struct * C)
{
    static const char * const vkey[4] = { "rays", "facets", "exact_rays",
                                          "exact_facets" };
    static const char * const dkey[3] = { "hausdorff", "exact_to_float",
                                          "float_to_exact" };
    const wc_cone_struct * F = C->cone;
    const struct
    {
        const wc_cmp_vec * U;
        slong n;
    }
    vecs[4] = {
        { C->rays, C->nrays }, { C->facets, C->nfacets },
        { C->exact_rays, C->nexact_rays }, { C->exact_facets, C->nexact_facets }
    };
    const double dist[3] = { C->hausdorff, C->exact_to_float,
                             C->float_to_exact };
    slong i;
    int k;

    fprintf(out, "{\"representation\": \"%s\", \"line\": %ld, \"empty\": %s",
            rep_key(C->kind), C->line, F->empty ? "true" : "false");
    if (!F->empty)
        fprintf(out, ", \"dim\": %ld, \"lineality_dim\": %ld", (long) F->dim,
                (long) F->lineality_dim);
    for (k = 0; k < 4; k++)
    {
        /* the float cone's vectors first (each extra or not), then the
           exact cone's (each missing or not); rays, then facets */
        int rays = k % 2 == 0, foreign = k < 2;

        fprintf(out, ", \"%s\": ", vkey[k]);
        json_vecs(out, vecs[k].U, vecs[k].n, rays ? "direction" : "normal",
                  foreign ? "exact" : "float", foreign ? "extra" : "missing",
                  rays, foreign);
    }
    fputs(", \"redundant_lines\": [", out);
    for (i = 0; i < C->nredundant; i++)
        fprintf(out, "%s%ld", i ? ", " : "", C->redundant[i]);
    putc(']', out);
    for (k = 0; k < 3; k++)
    {
        fprintf(out, ", \"%s\": ", dkey[k]);
        json_double(out, dist[k]);
    }
    fputs(", \"differences\": ", out);
    json_differences(out, C->differs);
    putc('}', out);
}

/* The faces of cl W that W excludes: "dim 0 (the apex); dim 1 {r0}".  */
static void
text_excluded(FILE * out, const wc_cone_t W)
{
    slong f, i, n = 0;

    for (f = 0; f < W->nfaces; f++)
    {
        const wc_face_struct * F = W->faces + f;

        if (F->included)
            continue;
        fprintf(out, "%sdim %ld ", n ? "; " : "", (long) F->dim);
        if (F->nrays == 0)
            fputs(W->lineality_dim ? "(the lineality space)" : "(the apex)",
                  out);
        else
        {
            putc('{', out);
            for (i = 0; i < F->nrays; i++)
                fprintf(out, "%sr%ld", i ? " " : "", (long) F->rays[i]);
            putc('}', out);
        }
        n++;
    }
}

static const char strict_note[] = "strictness cannot be read from a float "
    "cone; check your handling of strict inequalities";

/* The JSON report: the exact cone, the file, the tolerance and each
   representation's comparison.  */
static void
comparison_fprint_json(FILE * out, const wc_comparison_t R,
                       const wc_cone_t W, const char * problem,
                       const char * mode, const char * file)
{
    slong i, f;

    fputs(WC_JSON_OPEN "\"exact\": {\"arith\": \"gmp\", \"problem\": ", out);
    wc_fprint_json_string(out, problem);
    fputs(", \"mode\": ", out);
    wc_fprint_json_string(out, mode);
    fprintf(out, ", \"empty\": %s", W->empty ? "true" : "false");
    if (!W->empty)
    {
        fprintf(out, ", \"dim\": %ld, \"lineality_dim\": %ld, \"rays\": ",
                (long) W->dim, (long) W->lineality_dim);
        json_rows_unit(out, W->rays);
        fputs(", \"facets\": ", out);
        json_rows_unit(out, W->ineqs);
        fputs(", \"excluded_faces\": [", out);
        for (f = 0, i = 0; f < W->nfaces; f++)
        {
            const wc_face_struct * F = W->faces + f;
            slong j;

            if (F->included)
                continue;
            fprintf(out, "%s{\"dim\": %ld, \"rays\": [", i++ ? ", " : "",
                    (long) F->dim);
            for (j = 0; j < F->nrays; j++)
                fprintf(out, "%s%ld", j ? ", " : "", (long) F->rays[j]);
            fputs("]}", out);
        }
        putc(']', out);
    }
    fputs("}, \"file\": ", out);
    wc_fprint_json_string(out, file);
    fputs(", \"note\": \"the exact side decides emptiness, dimension, "
          "lineality, extreme rays and facets; floating-point numbers "
          "appear only in the angles (radians)\", \"strictness\": ", out);
    wc_fprint_json_string(out, strict_note);
    fputs(", \"tol\": ", out);
    json_double(out, R->tol);
    if (R->file_mode != NULL)
    {
        fputs(", \"file_mode\": ", out);
        wc_fprint_json_string(out, R->file_mode);
    }
    fputs(", \"float\": [", out);
    for (i = 0; i < R->nreps; i++)
    {
        fputs(i ? ", " : "", out);
        json_rep(out, R->reps + i);
    }
    fprintf(out, "], \"within_tolerance\": %s, \"differences\": ",
            R->differs ? "false" : "true");
    json_differences(out, R->differs);
    fputs("}\n", out);
}

int
wc_comparison_fprint(FILE * out, const wc_comparison_t R, const wc_cone_t W,
                     const char * problem, const char * mode,
                     const char * file, const wc_print_opts * o)
{
    slong i, excl = W->empty ? 0 : wc_cone_excluded_faces(W);
    int first = 1;
    char * qfile, * qproblem, * qmode;

    if (o != NULL && o->format == WC_FORMAT_JSON)
    {
        comparison_fprint_json(out, R, W, problem, mode, file);
        return ferror(out) ? WC_EINTERNAL : WC_OK;
    }

    /* The paths and the file's mode are input: quoted in the text (the
       JSON writer quotes what JSON cannot hold).  */
    qfile = _wc_show_cut(file, strlen(file), WC_SHOW_PATH_MAX);
    qproblem = _wc_show_cut(problem, strlen(problem), WC_SHOW_PATH_MAX);
    qmode = R->file_mode != NULL
        ? _wc_show(R->file_mode, strlen(R->file_mode)) : NULL;
    if (qfile == NULL || qproblem == NULL
        || (R->file_mode != NULL && qmode == NULL))
    {
        free(qfile);
        free(qproblem);
        free(qmode);
        return WC_EINTERNAL;
    }
    file = qfile;
    problem = qproblem;
    fprintf(out, "exact (GMP) against %s; distances are floating-point "
            "angles in radians\n", file);
    fputs("(the exact side decides emptiness, dimension, extreme rays and "
          "facets; floats appear only in the angles)\n", out);
    fprintf(out, "exact cone W(%s) of %s: ", mode, problem);
    text_cone_summary(out, W);
    fprintf(out, "\ntolerance %g\n", R->tol);
    if (R->file_mode != NULL)
        fprintf(out, "the file is for mode %s, not %s\n", qmode, mode);
    for (i = 0; i < R->nreps; i++)
        text_rep(out, R->reps + i, W, file, R->json_file);
    fprintf(out, "\n%s:\n", strict_note);
    if (W->empty)
        fputs("  the exact cone is empty: no face to check\n", out);
    else if (excl == 0)
        fputs("  the exact cone is closed: it excludes no face of its "
              "closure\n", out);
    else
    {
        fprintf(out, "  the exact cone excludes %ld of the %ld faces of its "
                "closure: ", (long) excl, (long) W->nfaces);
        text_excluded(out, W);
        putc('\n', out);
    }
    if (R->differs == 0)
        fputs("verdict: within tolerance\n", out);
    else
    {
        fputs("verdict: outside tolerance: ", out);
        if (R->differs & WC_CMP_MODE)
        {
            fprintf(out, "the file is for mode %s, not %s", qmode, mode);
            first = 0;
        }
        for (i = 0; i < R->nreps; i++)
        {
            char prefix[32];

            if (R->nreps > 1)
                snprintf(prefix, sizeof prefix, "%s: ",
                         rep_key(R->reps[i].kind));
            else
                prefix[0] = '\0';
            text_reasons(out, R->reps + i, W, R->tol, prefix, &first);
        }
        putc('\n', out);
    }
    free(qfile);
    free(qproblem);
    free(qmode);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}
