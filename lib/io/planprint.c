/* planprint.c -- text and JSON for plan and sweep (wrenchcone(1), JSON).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   The only floating point here is the approximate length of a pushing
   region, a reading aid that says it is approximate; every decision is
   made exactly in plan.c.  */

#include <config.h>

#include <math.h>
#include <string.h>

#include "analysis/plan.h"
#include "io/print.h"
#include "io/printutil.h"

/* The strings with the given indices: a JSON array or a spaced list.  */
static void
strlist(FILE * out, char * const * s, const slong * idx, slong count,
        int json)
{
    slong i;

    if (json)
        putc('[', out);
    for (i = 0; i < count; i++)
    {
        const char * x = s[idx != NULL ? idx[i] : i];

        if (json)
            fprintf(out, "%s\"%s\"", i ? ", " : "", x);
        else
            fprintf(out, "%s%s", i ? " " : "", x);
    }
    if (json)
        putc(']', out);
    else if (count == 0)
        fputs("none", out);
}

static void
state(FILE * out, ulong S, slong n, int json)
{
    char s[WC_PLAN_MAX_FIXELS + 1];

    wc_plan_state_string(s, S, n);
    fprintf(out, json ? "\"%s\"" : "%s", s);
}

/* needed_exact as indices into T->strings.  */
static slong *
exact_list(const wc_plan_t R)
{
    slong * idx = flint_malloc(sizeof(slong) * (R->T->nneeded + 1));
    slong k, m = 0;

    for (k = 0; k < R->T->nneeded; k++)
        if (R->exact_needed[k])
            idx[m++] = R->T->needed[k];
    return idx;
}

/* The length of a pushing region, approximately (edge lengths and arcs
   are irrational in general); *total gets the boundary's length.  */
static double
push_length(const wc_push_t R, const wc_problem_t P, double * total)
{
    double len = 0;
    slong i, k = P->shape_len / 2;

    *total = 0;
    if (P->shape == WC_SHAPE_DISK)
    {
        double r = fmpq_get_d(P->shape_data + 2);

        *total = 2 * M_PI * r;
        for (i = 0; i < R->count; i++)
        {
            const wc_push_interval_struct * v = R->iv + i;
            double a0 = atan2(fmpz_get_d(v->dfrom + 1), fmpz_get_d(v->dfrom));
            double a1 = atan2(fmpz_get_d(v->dto + 1), fmpz_get_d(v->dto));
            double d = a1 - a0;

            if (v->full)
                d = 2 * M_PI;
            else if (d < 0 || (d == 0 && !(v->from_closed && v->to_closed)))
                d += 2 * M_PI;
            len += r * d;
        }
        return len;
    }
    for (i = 0; i < k; i++)
    {
        slong j = (i + 1) % k;
        double dx = fmpq_get_d(P->shape_data + 2 * j)
            - fmpq_get_d(P->shape_data + 2 * i);
        double dy = fmpq_get_d(P->shape_data + 2 * j + 1)
            - fmpq_get_d(P->shape_data + 2 * i + 1);

        *total += sqrt(dx * dx + dy * dy);
    }
    for (i = 0; i < R->count; i++)
    {
        const wc_push_interval_struct * v = R->iv + i;
        slong a = v->edge, b = (v->edge + 1) % k;
        double dx = fmpq_get_d(P->shape_data + 2 * b)
            - fmpq_get_d(P->shape_data + 2 * a);
        double dy = fmpq_get_d(P->shape_data + 2 * b + 1)
            - fmpq_get_d(P->shape_data + 2 * a + 1);

        len += (fmpq_get_d(v->to) - fmpq_get_d(v->from))
            * sqrt(dx * dx + dy * dy);
    }
    return len;
}

static void
text_witness(FILE * out, const char * what, const fmpq * g,
             const wc_print_opts * o)
{
    fprintf(out, "%s", what);
    wc_fprint_qvec(out, g, 3, o);
}

/* The plan as JSON; ex lists the exactly needed strings.  */
static void
plan_json(FILE * out, const wc_plan_t R, const slong * ex,
          const wc_print_opts * o)
{
    const wc_plan_strings_struct * T = R->T;
    slong n = T->n, i, k;
    ulong S, full = (UWORD(1) << n) - 1;

    fprintf(out, WC_JSON_OPEN "\"fixels\": %ld, \"states\": [", (long) n);
    for (S = 0; S <= full; S++)
    {
        fputs(S ? ", {\"state\": " : "{\"state\": ", out);
        state(out, S, n, 1);
        fputs(", \"strings\": ", out);
        strlist(out, T->strings, T->state_str + T->state_first[S],
                T->state_first[S + 1] - T->state_first[S], 1);
        putc('}', out);
    }
    fputs("], \"strings\": ", out);
    strlist(out, T->strings, NULL, T->nstrings, 1);
    fputs(", \"needed\": ", out);
    strlist(out, T->strings, T->needed, T->nneeded, 1);
    fputs(", \"needed_exact\": ", out);
    strlist(out, T->strings, ex, R->nexact, 1);
    fputs(", \"redundant\": [", out);
    for (i = 0, k = 0; i < T->nstrings; i++)
        if (T->contained_in[i] >= 0)
            fprintf(out, "%s{\"string\": \"%s\", \"in\": \"%s\"}",
                    k++ ? ", " : "", T->strings[i],
                    T->strings[T->contained_in[i]]);
    fputs("], \"goal\": ", out);
    wc_set_fprint(out, R->goal, o);
    fprintf(out, ", \"goal_in_strong\": %s", _wc_tf(R->goal_in_strong));
    if (!R->goal_in_strong)
    {
        fputs(", \"goal_not_strong\": ", out);
        wc_fprint_qvec(out, R->strong_witness, 3, o);
    }
    fprintf(out, ", \"goal_in_strong_paper\": %s",
            _wc_tf(R->goal_in_strong_paper));
    if (!R->goal_in_strong_paper)
    {
        fputs(", \"goal_not_strong_paper\": ", out);
        wc_fprint_qvec(out, R->paper_witness, 3, o);
    }
    if (R->has_push)
    {
        fputs(", \"push\": {\"goal\": ", out);
        wc_push_fprint(out, R->push_goal, NULL, o);
        putc('}', out);
    }
    if (R->complete)
    {
        fputs(", \"complete\": {\"accepted\": ", out);
        wc_set_fprint(out, R->accepted, o);
        fputs(", \"outside_goal\": ", out);
        if (R->has_extra)
            wc_fprint_qvec(out, R->extra, 3, o);
        else
            fputs("null", out);
        if (R->has_push_accepted)
        {
            fputs(", \"push\": ", out);
            wc_push_fprint(out, R->push_accepted, NULL, o);
        }
        putc('}', out);
    }
    fputs("}\n", out);
}

/* The plan as text; ex lists the exactly needed strings.  */
static void
plan_text(FILE * out, const wc_plan_t R, const wc_problem_t P,
          const slong * ex, const wc_print_opts * o)
{
    const wc_plan_strings_struct * T = R->T;
    slong n = T->n, i, k;
    ulong S, full = (UWORD(1) << n) - 1;
    wc_print_opts in2 = _wc_print_indented(o, "  ");
    wc_print_opts in4 = _wc_print_indented(o, "    ");

    fprintf(out, "insertion plan for %ld fixel%s (a state marks each "
            "achieved contact with 1):\n", (long) n, n == 1 ? "" : "s");
    fputs("  state  strings consistent with leaving it or staying "
          "(* needed)\n", out);
    for (S = 0; S <= full; S++)
    {
        fputs("  ", out);
        state(out, S, n, 0);
        fprintf(out, "%*s", (int) (7 - n), "");
        for (i = T->state_first[S]; i < T->state_first[S + 1]; i++)
        {
            slong j = T->state_str[i];

            fprintf(out, " %s%s", T->strings[j],
                    T->contained_in[j] < 0 ? "*" : "");
        }
        putc('\n', out);
    }
    fprintf(out, "  %ld distinct strings; %ld needed after syntactic "
            "reduction; %ld after exact containment\n", (long) T->nstrings,
            (long) T->nneeded, (long) R->nexact);
    fputs("  redundant, syntactically (each lies in the string after it):",
          out);
    for (i = 0, k = 0; i < T->nstrings; i++)
        if (T->contained_in[i] >= 0)
            fprintf(out, "%s%s in %s", k++ % 6 ? ", " : "\n    ",
                    T->strings[i], T->strings[T->contained_in[i]]);
    fputs(k ? "\n" : " none\n", out);
    fputs("  redundant, exactly (a cone inside the union of those kept):",
          out);
    for (k = 0, i = 0; k < T->nneeded; k++)
        if (!R->exact_needed[k])
            fprintf(out, "%s%s", i++ ? " " : " ", T->strings[T->needed[k]]);
    fputs(i ? "\n" : " none\n", out);
    fputs("  needed, exactly: ", out);
    strlist(out, T->strings, ex, R->nexact, 0);
    fputs("\nG_goal (wrenches in the cone of no needed string):\n", out);
    wc_set_fprint(out, R->goal, &in2);
    fputs("G_goal inside G_strong (eq. 25), the goal state's strongly stable "
          "wrenches:\n", out);
    if (R->goal_in_strong)
        fputs("  exact semantics: yes\n", out);
    else
        text_witness(out, "  exact semantics: no, e.g. g = ",
                     R->strong_witness, o);
    if (!R->goal_in_strong)
        fputs(" is in G_goal but not strongly stable\n", out);
    if (R->goal_in_strong_paper)
        fputs("  paper semantics: yes\n", out);
    else
    {
        text_witness(out, "  paper semantics: no, e.g. g = ",
                     R->paper_witness, o);
        fputs(" is in G_goal and in some W(x), x != n..n\n", out);
    }
    if (R->has_push)
    {
        double total, len = push_length(R->push_goal, P, &total);

        fputs("where a frictionless finger seats the part from any "
              "state:\n", out);
        wc_push_fprint(out, R->push_goal, P, &in2);
        fprintf(out, "  length %.4g of %.4g (floating point, for reading "
                "only)\n", len, total);
    }
    if (R->complete)
    {
        fputs("complete plan (every transition graph the wrench allows "
              "reaches the goal):\n", out);
        wc_set_fprint(out, R->accepted, &in2);
        if (R->has_extra)
        {
            text_witness(out, "  accepted outside G_goal, e.g. g = ",
                         R->extra, o);
            putc('\n', out);
        }
        else
            fputs("  it accepts nothing outside G_goal here\n", out);
        if (R->has_push_accepted)
        {
            fputs("  where a frictionless finger seats the part:\n", out);
            wc_push_fprint(out, R->push_accepted, P, &in4);
        }
    }
}

int
wc_plan_fprint(FILE * out, const wc_plan_t R, const wc_problem_t P,
               const wc_print_opts * o)
{
    slong * ex = exact_list(R);

    if (_wc_print_json(o))
        plan_json(out, R, ex, o);
    else
        plan_text(out, R, P, ex, o);
    flint_free(ex);
    return _wc_fprint_done(out);
}

static const char *
verdict_name(wc_plan_verdict v)
{
    switch (v)
    {
    case WC_PLAN_ACCEPTED:
        return "accepted";
    case WC_PLAN_GOAL_LEAVES:
        return "goal_leaves";
    case WC_PLAN_CYCLE:
        return "cycle";
    default:
        return "stuck";
    }
}

int
wc_plan_wrench_fprint(FILE * out, const wc_plan_wrench_t W,
                      const wc_print_opts * o)
{
    int json = _wc_print_json(o);
    slong i, n = W->n;

    if (json)
    {
        fputs(WC_JSON_OPEN "\"wrench\": ", out);
        wc_fprint_qvec(out, W->g, 3, o);
        fprintf(out, ", \"in_goal\": %s, \"holding\": ", _wc_tf(W->in_goal));
        strlist(out, W->holding, NULL, W->nholding, 1);
        if (W->complete)
        {
            fprintf(out, ", \"complete\": {\"accepted\": %s, \"verdict\": "
                    "\"%s\", \"transitions\": [",
                    _wc_tf(W->verdict == WC_PLAN_ACCEPTED),
                    verdict_name(W->verdict));
            for (i = 0; i < W->nedges; i++)
            {
                fputs(i ? ", {\"from\": " : "{\"from\": ", out);
                state(out, W->from[i], n, 1);
                fputs(", \"to\": ", out);
                state(out, W->to[i], n, 1);
                fprintf(out, ", \"via\": \"%s\"}", W->via[i]);
            }
            fputs("], \"states\": [", out);
            for (i = 0; i < W->ncycle; i++)
            {
                if (i)
                    fputs(", ", out);
                state(out, W->cycle[i], n, 1);
            }
            fputs("]}", out);
        }
        fputs("}\n", out);
        return _wc_fprint_done(out);
    }
    fputs("wrench g = ", out);
    wc_fprint_qvec(out, W->g, 3, o);
    fputs(W->in_goal ? "\n  in G_goal: in the cone of no needed string\n"
          : "\n  not in G_goal: held by ", out);
    if (!W->in_goal)
    {
        strlist(out, W->holding, NULL, W->nholding, 0);
        putc('\n', out);
    }
    if (!W->complete)
        return _wc_fprint_done(out);
    fprintf(out, "  complete plan: %s", W->verdict == WC_PLAN_ACCEPTED
            ? "accepted: every run reaches the goal and stays\n"
            : "rejected: ");
    switch (W->verdict)
    {
    case WC_PLAN_GOAL_LEAVES:
        fputs("the goal state can lose a contact\n", out);
        break;
    case WC_PLAN_STUCK:
        fputs("state ", out);
        state(out, W->cycle[0], n, 0);
        fputs(" has no transition\n", out);
        break;
    case WC_PLAN_CYCLE:
        fputs("a cycle ", out);
        for (i = 0; i < W->ncycle; i++)
        {
            state(out, W->cycle[i], n, 0);
            fputs(" -> ", out);
        }
        state(out, W->cycle[0], n, 0);
        putc('\n', out);
        break;
    default:
        break;
    }
    fputs("  transitions (from -> to, by an outcome string g admits):\n",
          out);
    for (i = 0; i < W->nedges; i++)
    {
        fputs("    ", out);
        state(out, W->from[i], n, 0);
        fputs(" -> ", out);
        state(out, W->to[i], n, 0);
        fprintf(out, "  %s%s\n", W->via[i], W->from[i] == W->to[i]
                ? "  (stays)" : "");
    }
    return _wc_fprint_done(out);
}

int
wc_plan_sweep_fprint(FILE * out, const wc_plan_t R, const wc_problem_t P,
                     const fmpq_t mu, const wc_print_opts * o)
{
    int json = _wc_print_json(o);
    const wc_set_struct * G = R->goal;
    slong i, k, * ex = exact_list(R);
    double total = 0, len = 0;

    if (R->has_push)
        len = push_length(R->push_goal, P, &total);
    if (json)
    {
        fputs("{\"friction\": \"", out);
        wc_fprint_fmpq(out, mu);
        fputs("\", \"needed_exact\": ", out);
        strlist(out, R->T->strings, ex, R->nexact, 1);
        fputs(", \"goal\": ", out);
        wc_set_fprint(out, G, o);
        fprintf(out, ", \"goal_in_strong\": %s, \"goal_in_strong_paper\": %s",
                _wc_tf(R->goal_in_strong), _wc_tf(R->goal_in_strong_paper));
        if (R->has_push)
        {
            fputs(", \"push\": {\"goal\": ", out);
            wc_push_fprint(out, R->push_goal, NULL, o);
            fprintf(out, "}, \"push_length_approx\": %.6g, "
                    "\"boundary_length_approx\": %.6g", len, total);
        }
        putc('}', out);
        flint_free(ex);
        return _wc_fprint_done(out);
    }
    fputs("mu = ", out);
    wc_fprint_fmpq_text(out, mu, o);
    if (G->empty)
        fputs(": G_goal empty", out);
    else
    {
        for (i = 0, k = 0; i < G->npieces; i++)
            k += G->pieces[i].dim == 3;
        fprintf(out, ": G_goal %ld piece%s (%ld with interior)",
                (long) G->npieces, G->npieces == 1 ? "" : "s", (long) k);
    }
    fputs("; needed exactly: ", out);
    strlist(out, R->T->strings, ex, R->nexact, 0);
    fprintf(out, "; inside G_strong (exact, paper semantics): %s, %s\n",
            R->goal_in_strong ? "yes" : "no",
            R->goal_in_strong_paper ? "yes" : "no");
    for (i = 0; i < G->npieces; i++)
    {
        const wc_cone_struct * C = G->pieces + i;
        slong r;

        fprintf(out, "  piece %ld: dim %ld, rays", (long) i + 1,
                (long) C->dim);
        for (r = 0; r < fmpz_mat_nrows(C->rays); r++)
        {
            fputs(" (", out);
            for (k = 0; k < 3; k++)
            {
                if (k)
                    fputs(", ", out);
                fmpz_fprint(out, fmpz_mat_entry(C->rays, r, k));
            }
            putc(')', out);
        }
        if (fmpz_mat_nrows(C->lines) > 0)
        {
            fputs(", lines", out);
            for (r = 0; r < fmpz_mat_nrows(C->lines); r++)
            {
                fputs(" (", out);
                for (k = 0; k < 3; k++)
                {
                    if (k)
                        fputs(", ", out);
                    fmpz_fprint(out, fmpz_mat_entry(C->lines, r, k));
                }
                putc(')', out);
            }
        }
        fprintf(out, ", %ld of %ld faces excluded\n",
                (long) wc_cone_excluded_faces(C), (long) C->nfaces);
    }
    if (R->has_push)
    {
        wc_print_opts push = _wc_print_indented(o, "  push ");

        wc_push_fprint(out, R->push_goal, P, &push);
        fprintf(out, "  push length %.4g of %.4g (%.1f%%; floating point, "
                "for reading only)\n", len, total,
                total > 0 ? 100 * len / total : 0.0);
    }
    flint_free(ex);
    return _wc_fprint_done(out);
}
