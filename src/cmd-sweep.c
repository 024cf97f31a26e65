/* cmd-sweep.c -- wrenchcone sweep: G_goal of the insertion plan against
   the friction coefficient, and the critical friction.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

/* The options: the command's request (R->friction, critical, width,
   max_friction, certificate, format).  */
typedef _wc_request sweep_options;

#define JSON(o) (cli_format_of(o) == FMT_JSON)

/* The critical bracket, with its two certificates: the plan at lo holds
   the witness in G_goal, the plan at hi names the strings whose cones
   cover R^3.  */
typedef struct
{
    wc_critical_t C;
    wc_plan_t H;
    wc_plan_wrench_t W;
}
crit_job;

/* The whole answer: a plan per friction coefficient, and the bracket.  */
typedef struct
{
    slong n;
    fmpq * mu;
    wc_plan_struct * plans;
    fmpq_t width, max;
    crit_job crit;
}
answer;

/* The longest --friction list.  */
#define CLI_MAX_FRICTIONS 1000

/* A comma-separated list of exact numbers, located as <what>:1:COL.  */
static int
parse_list(fmpq ** v, slong * count, const char * s, const char * what,
           const char * noun, wc_error_t err)
{
    const char * p = s;
    slong n = 1, i;
    int status = WC_OK;

    for (i = 0; s[i] != '\0'; i++)
        if ((n += s[i] == ',') > CLI_MAX_FRICTIONS)
        {
            *v = NULL;
            *count = 0;
            return wc_error_set(err, WC_EINPUT, what, 1, i + 2,
                                "at most %d values (each costs a plan)",
                                CLI_MAX_FRICTIONS);
        }
    *v = flint_malloc(sizeof(fmpq) * n);
    for (i = 0; i < n; i++)
        fmpq_init(*v + i);
    *count = n;
    for (i = 0; i < n && status == WC_OK; i++)
    {
        const char * e = strchr(p, ',');
        size_t len = e != NULL ? (size_t) (e - p) : strlen(p);

        if (wc_parse_number_bounded(*v + i, p, len, err) != WC_OK)
        {
            char * why = wc_error_format(err);

            status = wc_error_set(err, WC_EINPUT, what, 1, p - s + 1, "%s",
                                  why != NULL ? why : "bad number");
            free(why);
        }
        else if (fmpq_sgn(*v + i) < 0)
            status = wc_error_set(err, WC_EINPUT, what, 1, p - s + 1,
                                  "%s must not be negative", noun);
        p += len + 1;
    }
    return status;
}

static int
one_positive(fmpq_t x, const char * s, const char * what, const char * noun,
             wc_error_t err)
{
    fmpq * v = NULL;
    slong n = 0, i;
    int status = parse_list(&v, &n, s, what, noun, err);

    if (status == WC_OK && (n != 1 || fmpq_sgn(v) <= 0))
        status = wc_error_set(err, WC_EINPUT, what, 1, 1,
                              "expected one positive number");
    if (status == WC_OK)
        fmpq_set(x, v);
    for (i = 0; i < n; i++)
        fmpq_clear(v + i);
    flint_free(v);
    return status;
}

static void
answer_init(answer * a)
{
    a->n = 0;
    a->mu = NULL;
    a->plans = NULL;
    fmpq_init(a->width);
    fmpq_init(a->max);
    fmpq_set_si(a->width, 1, 1000);
    fmpq_set_si(a->max, 1024, 1);
    wc_critical_init(a->crit.C);
    wc_plan_init(a->crit.H);
    wc_plan_wrench_init(a->crit.W);
}

static void
answer_clear(answer * a)
{
    slong i;

    wc_plan_wrench_clear(a->crit.W);
    wc_plan_clear(a->crit.H);
    wc_critical_clear(a->crit.C);
    for (i = 0; a->plans != NULL && i < a->n; i++)
        wc_plan_clear(a->plans + i);
    flint_free(a->plans);
    for (i = 0; i < a->n; i++)
        fmpq_clear(a->mu + i);
    flint_free(a->mu);
    fmpq_clear(a->width);
    fmpq_clear(a->max);
}

/* The bracket, and the witness at lo checked again, one cone at a
   time.  */
static int
crit_compute(crit_job * j, const wc_problem_t P, const fmpq_t width,
             const fmpq_t max, wc_error_t err)
{
    wc_critical_struct * C = j->C;
    int status = wc_plan_critical(C, P, width, max, err);

    if (status == WC_OK && C->found)
        status = wc_plan_with_friction(j->H, P, C->hi, err);
    if (status == WC_OK && !C->empty_at_zero)
    {
        wc_problem_t Q;
        slong i;

        wc_problem_init(Q);
        status = wc_problem_set(Q, P);
        for (i = 0; i < Q->n && status == WC_OK; i++)
        {
            fmpq_set(Q->fixels[i].mu_s, C->lo);
            fmpq_set(Q->fixels[i].mu_k, C->lo);
        }
        if (status == WC_OK)
            status = wc_plan_wrench(j->W, Q, C->lo_witness, 0, err);
        if (status == WC_OK && !j->W->in_goal)
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "internal error: the witness at lo is not "
                                  "in G_goal");
        wc_problem_clear(Q);
    }
    return status;
}

/* The values of the options, then every plan.  */
static int
compute(answer * a, const wc_problem_t P, const sweep_options * o,
        wc_error_t err)
{
    int status = WC_OK;
    slong i;

    if (o->friction != NULL)
        status = parse_list(&a->mu, &a->n, o->friction, "<friction>",
                            "a friction coefficient", err);
    if (status == WC_OK && o->width != NULL
        && (status = one_positive(a->width, o->width, "<width>",
                                  "the width", err)) == WC_OK
        && !wc_critical_width_ok(a->width))
        status = wc_error_set(err, WC_EINPUT, "<width>", 1, 1,
                              "the width must be at least 2^-%d (about "
                              "1.3e-29): each halving costs a plan",
                              WC_CRITICAL_MIN_WIDTH_EXP);
    if (status == WC_OK && o->max_friction != NULL
        && (status = one_positive(a->max, o->max_friction,
                                  "<max-friction>", "the largest friction",
                                  err)) == WC_OK
        && !wc_critical_max_ok(a->max))
        status = wc_error_set(err, WC_EINPUT, "<max-friction>", 1, 1,
                              "the largest friction must be at most 2^%d "
                              "(4294967296): each doubling costs a plan",
                              WC_CRITICAL_MAX_FRICTION_EXP);
    if (status == WC_OK)
        status = wc_problem_check(P, err);
    if (status == WC_OK && P->n > WC_PLAN_MAX_FIXELS)
    {
        wc_plan_t R;

        wc_plan_init(R);
        status = wc_plan(R, P, 0, err);     /* says why */
        wc_plan_clear(R);
    }
    if (status != WC_OK)
        return status;
    a->plans = flint_malloc(sizeof(wc_plan_struct) * (a->n + 1));
    for (i = 0; i < a->n; i++)
        wc_plan_init(a->plans + i);
    for (i = 0; i < a->n && status == WC_OK; i++)
        status = wc_plan_with_friction(a->plans + i, P, a->mu + i, err);
    if (status == WC_OK && o->critical)
        status = crit_compute(&a->crit, P, a->width, a->max, err);
    return status;
}

static void
print_critical_json(const wc_critical_struct * C, const wc_plan_struct * H,
                    const fmpq_t width)
{
    slong k, m;

    printf("\"critical\": {\"found\": %s, \"lo\": \"",
           C->found ? "true" : "false");
    wc_fprint_fmpq(stdout, C->lo);
    fputs("\", \"hi\": ", stdout);
    if (C->found)
    {
        putchar('"');
        wc_fprint_fmpq(stdout, C->hi);
        putchar('"');
    }
    else
        fputs("null", stdout);
    fputs(", \"width\": \"", stdout);
    wc_fprint_fmpq(stdout, width);
    printf("\", \"plans\": %ld, \"lo_witness\": ", (long) C->evals);
    if (C->empty_at_zero)
        fputs("null", stdout);
    else
        wc_fprint_qvec(stdout, C->lo_witness, 3, 1);
    fputs(", \"hi_cover\": [", stdout);
    for (k = 0, m = 0; C->found && k < H->T->nneeded; k++)
        if (H->exact_needed[k])
            printf("%s\"%s\"", m++ ? ", " : "",
                   H->T->strings[H->T->needed[k]]);
    fputs("]}", stdout);
}

static void
print_critical_text(const wc_critical_struct * C, const wc_plan_struct * H,
                    const fmpq_t width, const fmpq_t max)
{
    slong k;

    fputs("critical friction (mu_s = mu_k = mu at every fixel; G_goal "
          "shrinks as mu grows):\n", stdout);
    if (C->empty_at_zero)
        fputs("  G_goal is empty already at mu = 0\n", stdout);
    else
    {
        fputs("  lo = ", stdout);
        wc_fprint_fmpq_text(stdout, C->lo);
        fputs(": G_goal is not empty; g = ", stdout);
        wc_fprint_qvec(stdout, C->lo_witness, 3, 0);
        fputs(" is in the cone of no needed string\n", stdout);
    }
    if (!C->found)
    {
        fputs("  G_goal is not empty at any mu <= ", stdout);
        wc_fprint_fmpq_text(stdout, max);
        printf(" (%ld plans)\n", (long) C->evals);
        return;
    }
    fputs("  hi = ", stdout);
    wc_fprint_fmpq_text(stdout, C->hi);
    fputs(": G_goal is empty; the cones of", stdout);
    for (k = 0; k < H->T->nneeded; k++)
        if (H->exact_needed[k])
            printf(" %s", H->T->strings[H->T->needed[k]]);
    fputs(" cover R^3\n", stdout);
    if (!C->empty_at_zero)
    {
        fmpq_t w;

        fmpq_init(w);
        fmpq_sub(w, C->hi, C->lo);
        fputs("  hi - lo = ", stdout);
        wc_fprint_fmpq_text(stdout, w);
        fputs(" <= ", stdout);
        wc_fprint_fmpq_text(stdout, width);
        printf(" (%ld plans)\n", (long) C->evals);
        fmpq_clear(w);
    }
}

static void
print_answer(const answer * a, const wc_problem_t P, const sweep_options * o)
{
    slong i;

    if (JSON(o))
        fputs(WC_JSON_OPEN "\"sweep\": [", stdout);
    for (i = 0; i < a->n; i++)
    {
        if (JSON(o) && i)
            fputs(", ", stdout);
        wc_plan_sweep_fprint(stdout, a->plans + i, P, a->mu + i, JSON(o));
    }
    if (JSON(o))
        fputs(o->critical ? "], " : "]", stdout);
    if (o->critical)
    {
        if (!JSON(o) && a->n > 0)
            putchar('\n');
        if (JSON(o))
            print_critical_json(a->crit.C, a->crit.H, a->width);
        else
            print_critical_text(a->crit.C, a->crit.H, a->width, a->max);
    }
    if (JSON(o))
        fputs("}\n", stdout);
}

int
cmd_sweep(const cli_command * self, int argc, char ** argv)
{
    sweep_options o;
    int status;
    wc_problem_t P;
    wc_error_t err;
    answer a;

    if ((status = cli_parse(&o, self, argc, argv)) >= 0)
        return cli_done(&o, status);
    wc_problem_init(P);
    wc_error_init(err);
    answer_init(&a);
    status = _wc_load_problem(P, &o.problem, err);
    if (status == WC_OK && o.certificate != NULL)
        status = wc_problem_check_fixels(P, WC_PLAN_CERT_MAX_FIXELS, 0,
                                         "a plan certificate", err);
    if (status == WC_OK)
        status = compute(&a, P, &o, err);
    status = cli_certify(status, o.certificate, CLI_CERT_CRITICAL, P,
                         a.crit.C, err);
    if (status == WC_OK)
    {
        print_answer(&a, P, &o);
        status = cli_finish_output();
    }
    answer_clear(&a);
    wc_error_clear(err);
    wc_problem_clear(P);
    return cli_done(&o, status);
}
