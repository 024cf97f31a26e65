/* feasible.c -- mode-feasibility certificates (paper Table 1, wrenchcone(1), MODES):
   the rows a mode implies, and the witness or the Motzkin multipliers.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <stdlib.h>
#include <string.h>

#include "check/feasible.h"

/* What the certificate says.  */
typedef struct
{
    const wc_json_node * mode_node;     /* NULL until read */
    int feasible;                       /* -1 until read */
    size_t m;                           /* constraints */
    mpq_t * rows;                       /* 3 m */
    wc_check_rel * rel;                 /* m */
    mpq_t * witness;                    /* 3, when feasible */
    size_t nmult;
    mpq_t * mult;                       /* nmult, when not feasible */
    wc_check_problem P;
}
certificate;

static void
cert_init(certificate * C)
{
    memset(C, 0, sizeof *C);
    C->feasible = -1;
    _wc_check_problem_init(&C->P);
}

static void
cert_clear(certificate * C)
{
    _wc_check_qvec_free(C->rows, 3 * C->m);
    free(C->rel);
    _wc_check_qvec_free(C->witness, 3);
    _wc_check_qvec_free(C->mult, C->nmult);
    _wc_check_problem_clear(&C->P);
    cert_init(C);
}

/* The relation at r into *rel.  */
static int
read_relation(wc_check_reader * c, const wc_json_node * r,
              wc_check_rel * rel)
{
    if (r->len == 1 && r->text[0] == '>')
        *rel = WC_CHECK_GT;
    else if (r->len == 2 && memcmp(r->text, ">=", 2) == 0)
        *rel = WC_CHECK_GE;
    else if (r->len == 1 && r->text[0] == '=')
        *rel = WC_CHECK_EQ;
    else
        return _wc_check_bad_quoting(c, r, "unknown relation '%s'",
                                     r->text, r->len);
    return WC_OK;
}

static int
read_constraints(wc_check_reader * c, certificate * C,
                 const wc_json_node * root)
{
    const wc_json_node * a;
    size_t k;

    if (_wc_check_member(c, root, "constraints", WC_CHECK_ARRAY, &a)
        != WC_OK)
        return WC_EINPUT;
    C->rel = _wc_check_entries_new(c, &C->rows, 3, a->len,
                                   sizeof(wc_check_rel));
    if (C->rel == NULL)
        return WC_EINTERNAL;
    C->m = a->len;
    for (k = 0; k < a->len; k++)
    {
        const wc_json_node * e = a->items + k, * r;
        int status = _wc_check_want_object(c, e);

        if (status != WC_OK)
            return status;
        /* row and relation are independent: check both */
        status = _wc_check_vector(c, e, "row", C->rows + 3 * k, 3);
        if (_wc_check_member(c, e, "relation", WC_CHECK_STRING, &r)
            != WC_OK
            || read_relation(c, r, C->rel + k) != WC_OK)
            status = WC_EINPUT;
        if (status != WC_OK)
            return status;
    }
    return WC_OK;
}

/* Read everything the check of a mode-feasibility certificate (its kind
   read) needs from the document; errors into c.  */
static void
read_certificate(wc_check_reader * c, certificate * C,
                 const wc_json_node * root)
{
    const wc_json_node * mode, * feas;
    int problem_ok;

    if (_wc_check_member(c, root, "mode", WC_CHECK_STRING, &mode) == WC_OK)
        C->mode_node = mode;
    if (_wc_check_member(c, root, "feasible", WC_CHECK_BOOL, &feas)
        == WC_OK)
        C->feasible = feas->type == WC_JSON_TRUE;
    if (c->status == WC_EINTERNAL)
        return;
    read_constraints(c, C, root);
    if (c->status == WC_EINTERNAL)
        return;
    if (C->feasible == 1)
    {
        C->witness = _wc_check_qvec_new(3);
        if (C->witness == NULL)
        {
            _wc_check_nomem(c);
            return;
        }
        _wc_check_vector(c, root, "witness", C->witness, 3);
    }
    else if (C->feasible == 0)
        _wc_check_qarray(c, root, "multipliers", WC_CHECK_ANY_LENGTH,
                         &C->mult, &C->nmult);
    if (c->status == WC_EINTERNAL)
        return;
    problem_ok = _wc_check_read_problem(&C->P, c, root, 0) == WC_OK;
    if (c->status == WC_EINTERNAL)
        return;
    if (problem_ok && C->mode_node != NULL)
        _wc_check_letters(c, C->mode_node, &C->P, 0);
}

/* The rows mode implies: rows (3 m), rel, fixel of each (0-based).  */
typedef struct
{
    size_t m;
    mpz_t * rows;
    wc_check_rel * rel;
    size_t * fixel;
}
implied;

static size_t
rows_of_letter(char l, int near)
{
    return near || l == 's' ? 1 : 2;
}

/* Row k of I: the primitive vector of J, negated with neg, for fixel i.  */
static void
implied_row(implied * I, size_t k, mpq_t * J, int neg, wc_check_rel rel,
            size_t i, mpz_t t)
{
    mpz_t * z = I->rows + 3 * k;
    int j;

    _wc_check_primitive(z, J, t);
    for (j = 0; neg && j < 3; j++)
        mpz_neg(z[j], z[j]);
    I->rel[k] = rel;
    I->fixel[k] = i;
}

/* Fill I from the problem and the (checked) mode.  WC_OK or
   WC_EINTERNAL.  */
static int
implied_rows(implied * I, const certificate * C, const char * mode)
{
    mpq_t * J = NULL;
    mpz_t t;
    size_t i, m = 0, k = 0;
    int status = WC_OK;

    mpz_init(t);
    for (i = 0; i < C->P.n; i++)
        m += rows_of_letter(mode[i], C->P.near[i]);
    I->rows = _wc_check_zvec_new(_wc_check_times(3, m));
    I->rel = _wc_check_alloc(m, sizeof(wc_check_rel));
    I->fixel = _wc_check_alloc(m, sizeof(size_t));
    J = _wc_check_qvec_new(6);
    if (I->rows == NULL || I->rel == NULL || I->fixel == NULL || J == NULL)
    {
        _wc_check_zvec_free(I->rows, I->rows != NULL ? 3 * m : 0);
        I->rows = NULL;
        status = WC_EINTERNAL;
        goto cleanup;
    }
    I->m = m;
    for (i = 0; i < C->P.n; i++)
    {
        char l = mode[i];
        int near = C->P.near[i];

        _wc_check_jacobian(J, &C->P, i);
        /* near a: -J_n >; near s: J_n >=; touching s: J_n >; else = */
        implied_row(I, k++, J, near && l == 'a',
                    near ? (l == 'a' ? WC_CHECK_GT : WC_CHECK_GE)
                    : l == 's' ? WC_CHECK_GT : WC_CHECK_EQ, i, t);
        /* l: J_t >; r: -J_t >; n: J_t = */
        if (rows_of_letter(l, near) == 2)
            implied_row(I, k++, J + 3, l == 'r',
                        l == 'n' ? WC_CHECK_EQ : WC_CHECK_GT, i, t);
    }
cleanup:
    _wc_check_qvec_free(J, 6);
    mpz_clear(t);
    return status;
}

static void
implied_clear(implied * I)
{
    _wc_check_zvec_free(I->rows, 3 * I->m);
    free(I->rel);
    free(I->fixel);
}

static int
row_equal(mpq_t * q, mpz_t * z)
{
    int j;

    for (j = 0; j < 3; j++)
        if (mpz_cmp_ui(mpq_denref(q[j]), 1) != 0
            || mpz_cmp(mpq_numref(q[j]), z[j]) != 0)
            return 0;
    return 1;
}

static int
satisfies(int sign, wc_check_rel r)
{
    return r == WC_CHECK_GT ? sign > 0 : r == WC_CHECK_GE ? sign >= 0
        : sign == 0;
}

/* The constraints are exactly the rows I of mode (shown: cut).  1 or
   0.  */
static int
check_constraints(wc_check_text * why, const certificate * C,
                  const implied * I, const char * shown)
{
    size_t k, common = C->m < I->m ? C->m : I->m;

    for (k = 0; k < common; k++)
        if (!row_equal(C->rows + 3 * k, I->rows + 3 * k)
            || C->rel[k] != I->rel[k])
        {
            _wc_check_putf(why, "constraint %lu is not the one mode %s "
                           "implies for fixel %lu: expected ",
                           (unsigned long) k + 1, shown,
                           (unsigned long) I->fixel[k] + 1);
            _wc_check_put_zvec(why, I->rows + 3 * k, 3);
            _wc_check_putf(why, " . nu %s 0, found ",
                           _wc_check_rel_name(I->rel[k]));
            _wc_check_put_qvec(why, C->rows + 3 * k, 3);
            _wc_check_putf(why, " . nu %s 0",
                           _wc_check_rel_name(C->rel[k]));
            return 0;
        }
    if (C->m != I->m)
    {
        _wc_check_putf(why, "the certificate lists %lu constraint%s; mode "
                       "%s implies %lu", (unsigned long) C->m,
                       C->m == 1 ? "" : "s", shown, (unsigned long) I->m);
        return 0;
    }
    return 1;
}

/* The witness satisfies every row of I; s scratch.  1 or 0.  */
static int
check_witness(wc_check_text * why, const certificate * C,
              const implied * I, mpq_t s, mpq_t t)
{
    size_t k;
    int j;

    for (k = 0; k < I->m; k++)
    {
        mpq_set_ui(s, 0, 1);
        for (j = 0; j < 3; j++)
        {
            mpq_set_z(t, I->rows[3 * k + j]);
            _wc_check_qaddmul(s, t, C->witness[j], t);
        }
        if (!satisfies(mpq_sgn(s), I->rel[k]))
        {
            _wc_check_put(why, "the witness ");
            _wc_check_put_qvec(why, C->witness, 3);
            _wc_check_putf(why, " violates constraint %lu: ",
                           (unsigned long) k + 1);
            _wc_check_put_zvec(why, I->rows + 3 * k, 3);
            _wc_check_put(why, " . nu = ");
            _wc_check_put_q(why, s);
            _wc_check_putf(why, ", not %s 0",
                           _wc_check_rel_name(I->rel[k]));
            return 0;
        }
    }
    return 1;
}

/* The multipliers prove the rows of I have no solution; s (3) scratch.
   1 or 0.  */
static int
check_multipliers(wc_check_text * why, const certificate * C,
                  const implied * I, mpq_t * s, mpq_t t)
{
    size_t k;
    int j;

    if (!_wc_check_motzkin_count(why, "", "constraint", C->nmult, I->m))
        return 0;
    for (j = 0; j < 3; j++)
    {
        mpq_set_ui(s[j], 0, 1);
        for (k = 0; k < I->m; k++)
        {
            mpq_set_z(t, I->rows[3 * k + j]);
            _wc_check_qaddmul(s[j], t, C->mult[k], t);
        }
    }
    return _wc_check_motzkin(why, "", "constraint", I->rel, C->mult, I->m,
                             s, 3);
}

/* Decide whether the certificate C (read without error) holds; when it
   does not, write why into why.  Returns 1 or 0; -1 when out of memory.  */
static int
check(wc_check_text * why, const certificate * C, const char * mode)
{
    implied I = { 0, NULL, NULL, NULL };
    mpq_t * s = NULL;
    mpq_t t;
    int holds = -1;
    char * shown = _wc_show(mode, strlen(mode));  /* a long mode cut */

    mpq_init(t);
    s = _wc_check_qvec_new(3);
    if (s == NULL || shown == NULL || implied_rows(&I, C, mode) != WC_OK)
        goto cleanup;
    holds = check_constraints(why, C, &I, shown);
    if (holds == 1)
        holds = C->feasible ? check_witness(why, C, &I, s[0], t)
            : check_multipliers(why, C, &I, s, t);
cleanup:
    if (why->oom)
        holds = -1;
    implied_clear(&I);
    _wc_check_qvec_free(s, 3);
    mpq_clear(t);
    free(shown);
    return holds;
}

int
_wc_check_mode_certificate(wc_check_reader * c, const wc_json_node * root,
                           int * holds, wc_check_text * why, char ** mode,
                           int * feasible)
{
    certificate C;
    char * m = NULL;
    int h;

    cert_init(&C);
    read_certificate(c, &C, root);
    if (c->status != WC_OK)
        goto cleanup;
    /* checked: the mode is Table 1 letters, one per fixel, no NUL */
    m = malloc(C.mode_node->len + 1);
    if (m == NULL)
    {
        _wc_check_nomem(c);
        goto cleanup;
    }
    memcpy(m, C.mode_node->text, C.mode_node->len + 1);
    h = check(why, &C, m);
    if (h < 0)
    {
        _wc_check_nomem(c);
        goto cleanup;
    }
    *holds = h;
    *feasible = C.feasible;
    *mode = m;
    m = NULL;
cleanup:
    free(m);
    cert_clear(&C);
    return c->status;
}
