/* stabprint.c -- text and JSON for classify and stability (wrenchcone(1), JSON).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <string.h>

#include "core/certkind.h"
#include "io/print.h"
#include "io/printutil.h"

/* The forces of a solution in words: only the loaded fixels.  */
static void
text_forces(FILE * out, const fmpq * c, slong n, const wc_print_opts * o)
{
    slong i;
    int any = 0;

    for (i = 0; i < n; i++)
        if (!fmpq_is_zero(c + i) || !fmpq_is_zero(c + n + i))
        {
            fprintf(out, "%sfixel %ld (", any ? ", " : "", (long) i + 1);
            wc_fprint_fmpq_text(out, c + i, o);
            fputs(", ", out);
            wc_fprint_fmpq_text(out, c + n + i, o);
            putc(')', out);
            any = 1;
        }
    if (!any)
        fputs("none", out);
}

int
wc_classify_fprint(FILE * out, const wc_classify_t R,
                   const wc_print_opts * o)
{
    slong i, n = R->n;

    if (_wc_print_json(o))
    {
        fputs(WC_JSON_OPEN "\"wrench\": ", out);
        wc_fprint_qvec(out, R->g, 3, o);
        fputs(", \"modes\": [", out);
        for (i = 0; i < R->nmodes; i++)
        {
            if (i)
                fputs(", ", out);
            wc_fprint_json_string(out, R->modes[i]);
        }
        fprintf(out, "], \"modes_complete\": %s, \"weakly_stable\": %s, \"strongly_stable\": %s, "
                "\"strongly_stable_paper\": %s, \"paper_vacuous\": %s, "
                "\"motions\": [",
                _wc_tf(R->modes_complete), _wc_tf(R->weak), _wc_tf(R->strong),
                _wc_tf(R->strong_paper), _wc_tf(R->paper_vacuous));
        for (i = 0; i < R->nmotions; i++)
        {
            fputs(i ? ", {\"sign\": " : "{\"sign\": ", out);
            wc_fprint_json_string(out, R->motions[i].sign);
            fputs(", \"nudot\": ", out);
            wc_fprint_qvec(out, R->motions[i].nudot, 3, o);
            fputs(", \"c\": ", out);
            wc_fprint_qvec(out, R->motions[i].c, 2 * n, o);
            putc('}', out);
        }
        fputs("]", out);
        if (R->weak)
        {
            fputs(", \"static_c\": ", out);
            wc_fprint_qvec(out, R->weak_c, 2 * n, o);
        }
        else
        {
            fputs(", \"separator\": ", out);
            wc_fprint_qvec(out, R->weak_sep, 3, o);
        }
        if (!R->strong_paper)
        {
            fputs(", \"paper_witness\": {\"mode\": ", out);
            wc_fprint_json_string(out, R->paper.sign);
            fputs(", \"nudot\": ", out);
            wc_fprint_qvec(out, R->paper.nudot, 3, o);
            fputs(", \"c\": ", out);
            wc_fprint_qvec(out, R->paper.c, 2 * n, o);
            putc('}', out);
        }
        fputs("}\n", out);
        return _wc_fprint_done(out);
    }

    fputs("wrench g = ", out);
    wc_fprint_qvec(out, R->g, 3, o);
    fputs("  (fx, fy, torque)\n", out);
    fprintf(out, "weakly stable: %s\n", _wc_yes(R->weak));
    if (R->weak)
    {
        fputs("  static forces (c_n, c_t): ", out);
        text_forces(out, R->weak_c, n, o);
        fputs("\n", out);
    }
    else
    {
        fputs("  separator y: y . g > 0, y . (-J c) <= 0 for every admissible"
              " force: y = ", out);
        wc_fprint_qvec(out, R->weak_sep, 3, o);
        putc('\n', out);
    }
    fprintf(out, "strongly stable (exact semantics, Pang and Trinkle): %s\n",
            _wc_yes(R->strong));
    if (R->strong)
        fputs("  no moving face admits a solution (every face decided by an"
              " exact LP;\n  --certificate writes a Farkas certificate per"
              " face)\n", out);
    else if (!R->weak)
        fputs("  not weakly stable\n", out);
    fprintf(out, "strongly stable (paper semantics, eq. 19): %s\n",
            _wc_yes(R->strong_paper));
    if (R->paper_vacuous)
        fputs("  vacuously: no fixel touches, so eq. 19 excludes nothing"
              " (its union of cones is empty)\n", out);
    if (!R->strong_paper)
    {
        fprintf(out, "  W(%s) holds the wrench: nudot = ", R->paper.sign);
        wc_fprint_qvec(out, R->paper.nudot, 3, o);
        fputs(", forces ", out);
        text_forces(out, R->paper.c, n, o);
        putc('\n', out);
    }
    if (R->strong != R->strong_paper)
        fprintf(out, "  the semantics differ for this wrench: %s\n",
                R->strong ? "no solution moves, but a mode other than n..n "
                "holds it (eq. 19 also excludes wrenches that a subset of "
                "the fixels holds)"
                : "eq. 19 keeps it, but a solution moves or it is not weakly"
                " stable");
    fprintf(out, "modes whose Table 2 cone holds the wrench (%s%ld):",
            R->modes_complete ? "" : "the first ", (long) R->nmodes);
    for (i = 0; i < R->nmodes; i++)
        fprintf(out, " %s", R->modes[i]);
    if (!R->modes_complete)
        fputs(" ... (the list stops here: --max-modes)", out);
    putc('\n', out);
    fprintf(out, "motions (nudot != 0) (%ld):%s\n", (long) R->nmotions,
            R->nmotions ? "" : " none");
    for (i = 0; i < R->nmotions; i++)
    {
        fprintf(out, "  %s  nudot = ", R->motions[i].sign);
        wc_fprint_qvec(out, R->motions[i].nudot, 3, o);
        fputs("  forces ", out);
        text_forces(out, R->motions[i].c, n, o);
        putc('\n', out);
    }
    return _wc_fprint_done(out);
}

static int
set_json(FILE * out, const wc_set_t S)
{
    slong i;

    fprintf(out, "{\"empty\": %s, \"interior\": %s, \"pieces\": [",
            _wc_tf(S->empty), _wc_tf(S->interior));
    for (i = 0; i < S->npieces; i++)
    {
        if (i)
            fputs(", ", out);
        wc_cone_fprint(out, S->pieces + i, _wc_print_as_json);
    }
    fputs("]}", out);
    return _wc_fprint_done(out);
}

static int
set_text(FILE * out, const wc_set_t S, const wc_print_opts * o)
{
    const char * indent = _wc_print_indent(o);
    slong i;
    char * in2 = malloc(strlen(indent) + 5);
    wc_print_opts t = _wc_print_indented(o, in2);

    if (in2 == NULL)
        return WC_EINTERNAL;
    strcpy(in2, indent);
    strcat(in2, "    ");
    if (S->empty)
        fprintf(out, "%sempty\n", indent);
    else
        fprintf(out, "%s%ld pairwise disjoint piece%s, %s interior\n", indent,
                (long) S->npieces, S->npieces == 1 ? "" : "s",
                S->interior ? "with" : "no");
    for (i = 0; i < S->npieces; i++)
    {
        fprintf(out, "%s  piece %ld:\n", indent, (long) i + 1);
        wc_cone_fprint(out, S->pieces + i, &t);
    }
    free(in2);
    return _wc_fprint_done(out);
}

int
wc_set_fprint(FILE * out, const wc_set_t S, const wc_print_opts * o)
{
    return _wc_print_json(o) ? set_json(out, S) : set_text(out, S, o);
}

/* The point of edge k of P's polygon at parameter s, as text:
   v_k + s (v_k+1 - v_k).  */
static void
edge_point(FILE * out, const wc_problem_t P, slong k, const fmpq_t s,
           const wc_print_opts * o)
{
    slong nv = P->shape_len / 2, j;
    const fmpq * a = P->shape_data + 2 * (k % nv);
    const fmpq * b = P->shape_data + 2 * ((k + 1) % nv);
    fmpq q[2];

    for (j = 0; j < 2; j++)
    {
        fmpq_init(q + j);
        fmpq_sub(q + j, b + j, a + j);
        fmpq_mul(q + j, q + j, s);
        fmpq_add(q + j, q + j, a + j);
    }
    wc_fprint_qvec(out, q, 2, o);
    for (j = 0; j < 2; j++)
        fmpq_clear(q + j);
}

int
wc_push_fprint(FILE * out, const wc_push_t R, const wc_problem_t P,
               const wc_print_opts * o)
{
    int json = _wc_print_json(o);
    const char * indent = _wc_print_indent(o);
    slong i;

    if (P != NULL && (P->shape != WC_SHAPE_POLYGON || P->shape_len < 6))
        P = NULL;

    if (json)
        putc('[', out);
    else if (R->count == 0)
        fprintf(out, "%snowhere\n", indent);
    for (i = 0; i < R->count; i++)
    {
        const wc_push_interval_struct * v = R->iv + i;

        if (json)
        {
            if (i)
                fputs(", ", out);
            if (R->kind == WC_SHAPE_POLYGON)
            {
                fprintf(out, "{\"edge\": %ld, \"from\": \"", (long) v->edge);
                wc_fprint_fmpq(out, v->from);
                fputs("\", \"to\": \"", out);
                wc_fprint_fmpq(out, v->to);
                putc('"', out);
            }
            else
            {
                fputs("{\"from\": ", out);
                _wc_fprint_zvec(out, v->dfrom, 2, 1);
                fputs(", \"to\": ", out);
                _wc_fprint_zvec(out, v->dto, 2, 1);
            }
            fprintf(out, ", \"from_closed\": %s, \"to_closed\": %s",
                    _wc_tf(v->from_closed), _wc_tf(v->to_closed));
            if (v->full)
                fputs(", \"full\": true", out);
            putc('}', out);
            continue;
        }
        if (R->kind == WC_SHAPE_POLYGON)
        {
            fprintf(out, "%sedge %ld: s in %c", indent, (long) v->edge,
                    v->from_closed ? '[' : '(');
            wc_fprint_fmpq_text(out, v->from, o);
            fputs(", ", out);
            wc_fprint_fmpq_text(out, v->to, o);
            fprintf(out, "%c", v->to_closed ? ']' : ')');
            if (P != NULL)
            {
                fputs(", (x, y) from ", out);
                edge_point(out, P, v->edge, v->from, o);
                fputs(" to ", out);
                edge_point(out, P, v->edge, v->to, o);
            }
            putc('\n', out);
        }
        else if (v->full)
            fprintf(out, "%sthe whole circle\n", indent);
        else
        {
            fprintf(out, "%sarc from direction %c", indent,
                    v->from_closed ? '[' : '(');
            _wc_fprint_zvec(out, v->dfrom, 2, 0);
            fputs(" counter-clockwise to ", out);
            _wc_fprint_zvec(out, v->dto, 2, 0);
            fprintf(out, "%c\n", v->to_closed ? ']' : ')');
        }
    }
    if (json)
        putc(']', out);
    return _wc_fprint_done(out);
}

void
_wc_stability_fprint_members(FILE * out, const wc_stability_t S)
{
    const wc_print_opts * o = _wc_print_as_json;

    fputs("\"weak\": ", out);
    wc_cone_fprint(out, S->weak, o);
    fputs(", \"strong\": ", out);
    wc_set_fprint(out, S->strong, o);
    fputs(", \"strong_paper\": ", out);
    wc_set_fprint(out, S->strong_paper, o);
    fprintf(out, ", \"paper_in_weak\": %s, \"paper_vacuous\": %s, "
            "\"semantics_differ\": %s, \"differ_only_at_origin\": %s",
            _wc_tf(S->paper_in_weak), _wc_tf(S->paper_vacuous),
            _wc_tf(S->differ), _wc_tf(S->diff_origin_only));
    if (S->differ)
    {
        fputs(", \"difference_witness\": {\"wrench\": ", out);
        wc_fprint_qvec(out, S->diff_g, 3, o);
        fprintf(out, ", \"strong\": %s, \"strong_paper\": %s}",
                _wc_tf(S->diff_in_exact), _wc_tf(!S->diff_in_exact));
    }
    if (S->has_push)
    {
        fputs(", \"push\": {\"weak\": ", out);
        wc_push_fprint(out, S->push_weak, NULL, o);
        fputs(", \"strong\": ", out);
        wc_push_fprint(out, S->push_strong, NULL, o);
        fputs(", \"strong_paper\": ", out);
        wc_push_fprint(out, S->push_strong_paper, NULL, o);
        putc('}', out);
    }
}

static int
stability_text(FILE * out, const wc_stability_t S, const wc_problem_t P,
               const wc_print_opts * o)
{
    wc_print_opts in2 = _wc_print_indented(o, "  ");
    wc_print_opts in4 = _wc_print_indented(o, "    ");

    fputs("weakly stable wrenches (a static solution exists; closed):\n",
          out);
    wc_cone_fprint(out, S->weak, &in2);
    fputs("strongly stable wrenches, exact semantics (weakly stable, no "
          "solution moves):\n", out);
    wc_set_fprint(out, S->strong, &in2);
    fputs("strongly stable wrenches, paper semantics (eq. 19: in no W(x), "
          "x != n..n):\n", out);
    wc_set_fprint(out, S->strong_paper, &in2);
    if (S->paper_vacuous)
        fputs("note: no fixel touches, so eq. 19 is vacuous (its union of "
              "cones is empty):\n  its set is all of R^3 and says nothing "
              "about stability\n", out);
    if (S->differ && S->diff_origin_only)
        fprintf(out, "the semantics differ only at the origin g = (0, 0, 0),"
                " strongly stable under %s only\n",
                S->diff_in_exact ? "the definition (exact); every W(x) of "
                "eq. 19 holds it" : "eq. 19 (paper)");
    else if (S->differ)
    {
        fputs("the semantics differ: e.g. g = ", out);
        wc_fprint_qvec(out, S->diff_g, 3, o);
        fprintf(out, " is strongly stable under %s only%s\n",
                S->diff_in_exact ? "the definition (exact)"
                : "eq. 19 (paper)",
                S->diff_in_exact ? "; eq. 19 excludes it (a mode other than"
                " n..n holds it)" : "; under the definition it moves or is "
                "not weakly stable");
    }
    else
        fputs("the semantics agree for this problem\n", out);
    if (!S->paper_in_weak)
        fputs("note: eq. 19's set holds wrenches that are not weakly stable "
              "(no solution at all)\n", out);
    if (S->has_push)
    {
        fputs("pushing regions of a frictionless finger:\n  weakly stable:\n",
              out);
        wc_push_fprint(out, S->push_weak, P, &in4);
        fputs("  strongly stable (exact):\n", out);
        wc_push_fprint(out, S->push_strong, P, &in4);
        fputs("  strongly stable (paper):\n", out);
        wc_push_fprint(out, S->push_strong_paper, P, &in4);
    }
    return _wc_fprint_done(out);
}

int
wc_stability_fprint(FILE * out, const wc_stability_t S, const wc_problem_t P,
                    const wc_print_opts * o)
{
    if (!_wc_print_json(o))
        return stability_text(out, S, P, o);
    fputs(WC_JSON_OPEN, out);
    _wc_stability_fprint_members(out, S);
    fputs("}\n", out);
    return _wc_fprint_done(out);
}

/* The problem of a certificate with dynamics: mass, inertia, com and the
   fixels with their friction (wrenchcone-certificate(5)).  */
void
_wc_fprint_dyn_problem(FILE * out, const wc_problem_t P)
{
    slong i;

    fputs("{\"mass\": ", out);
    _wc_fprint_jq(out, P->mass);
    fputs(", \"inertia\": ", out);
    _wc_fprint_jq(out, P->inertia);
    fputs(", \"com\": ", out);
    wc_fprint_qvec(out, P->com, 2, _wc_print_as_json);
    fputs(",\n  \"fixels\": [", out);
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        fputs(i > 0 ? ",\n   " : "\n   ", out);
        fputs("{\"point\": ", out);
        wc_fprint_qvec(out, f->point, 2, _wc_print_as_json);
        fputs(", \"normal\": ", out);
        wc_fprint_qvec(out, f->normal, 2, _wc_print_as_json);
        fprintf(out, ", \"state\": \"%s\", \"mu_s\": ",
                f->state == WC_TOUCHING ? "touching" : "near");
        _wc_fprint_jq(out, f->mu_s);
        fputs(", \"mu_k\": ", out);
        _wc_fprint_jq(out, f->mu_k);
        fputc('}', out);
    }
    fputs("]}", out);
}

/* The certificate (wrenchcone-certificate(5), kind "strong-stability").  */
int
wc_classify_certificate_fprint(FILE * out, const wc_problem_t P,
                               const wc_classify_t R)
{
    slong i;

    fputs("{\"kind\": \"" WC_CERT_KIND_STABILITY "\",\n \"problem\": ", out);
    _wc_fprint_dyn_problem(out, P);
    fputs(",\n \"wrench\": ", out);
    wc_fprint_qvec(out, R->g, 3, _wc_print_as_json);
    fprintf(out, ",\n \"weakly_stable\": %s,\n \"weak\": ",
            R->weak ? "true" : "false");
    if (R->weak)
    {
        fputs("{\"c\": ", out);
        wc_fprint_qvec(out, R->weak_c, 2 * R->n, _wc_print_as_json);
    }
    else
    {
        fputs("{\"separator\": ", out);
        wc_fprint_qvec(out, R->weak_sep, 3, _wc_print_as_json);
    }
    fprintf(out, "},\n \"strongly_stable\": %s", R->strong ? "true" : "false");
    if (R->weak && !R->strong)
    {
        const wc_motion_struct * a = R->motions + 0;

        fputs(",\n \"motion\": {\"sign\": ", out);
        wc_fprint_json_string(out, a->sign);
        fputs(", \"nudot\": ", out);
        wc_fprint_qvec(out, a->nudot, 3, _wc_print_as_json);
        fputs(", \"c\": ", out);
        wc_fprint_qvec(out, a->c, 2 * R->n, _wc_print_as_json);
        fputc('}', out);
    }
    if (R->strong)
    {
        fputs(",\n \"faces\": [", out);
        for (i = 0; i < R->nnofaces; i++)
        {
            const wc_noface_struct * f = R->nofaces + i;

            fputs(i > 0 ? ",\n   " : "\n   ", out);
            fputs("{\"sign\": ", out);
            wc_fprint_json_string(out, f->sign);
            if (f->rotation != 0)
                fprintf(out, ", \"rotation\": %d", f->rotation);
            fputs(", \"multipliers\": ", out);
            wc_fprint_qvec(out, f->mult, f->nmult, _wc_print_as_json);
            fputc('}', out);
        }
        fputc(']', out);
    }
    fputs("}\n", out);
    return ferror(out) ? WC_EINTERNAL : WC_OK;
}

