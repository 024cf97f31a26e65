/* verify.c -- re-check a certificate (mode feasibility, strong
   stability) with GMP alone.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Deliberately independent of the rest of libwrenchcone: C, GMP (mpz,
   mpq), json.c and error.c only, so that a bug in the code that writes
   certificates cannot hide in the code that checks them.

   Reading collects the first error in file order: the parts of the
   certificate that do not depend on each other are all checked, and
   bad() keeps the error located earliest.  */

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>

#include "core/json.h"
#include "check/verify.h"

#define KIND "mode-feasibility"
#define KIND_STRONG "strong-stability"

typedef enum { KIND_MODE = 0, KIND_STABILITY = 1 } cert_kind;

/* Numbers quoted in a reason are cut after this many characters.  */
#define SHOW_DIGITS 40

typedef enum { REL_GT = 0, REL_GE = 1, REL_EQ = 2 } relation;

static const char * const rel_name[] = { ">", ">=", "=" };

/* ------------------------------------------------------------------ */
/* Vectors of rationals and integers.                                  */

/* n initialised rationals (n may be 0); NULL when out of memory.  */
static mpq_t *
qvec_new(size_t n)
{
    mpq_t * v;
    size_t i;

    if (n > SIZE_MAX / sizeof(mpq_t) - 1)
        return NULL;
    v = malloc((n + 1) * sizeof(mpq_t));
    if (v == NULL)
        return NULL;
    for (i = 0; i < n; i++)
        mpq_init(v[i]);
    return v;
}

static void
qvec_free(mpq_t * v, size_t n)
{
    size_t i;

    if (v == NULL)
        return;
    for (i = 0; i < n; i++)
        mpq_clear(v[i]);
    free(v);
}

static mpz_t *
zvec_new(size_t n)
{
    mpz_t * v;
    size_t i;

    if (n > SIZE_MAX / sizeof(mpz_t) - 1)
        return NULL;
    v = malloc((n + 1) * sizeof(mpz_t));
    if (v == NULL)
        return NULL;
    for (i = 0; i < n; i++)
        mpz_init(v[i]);
    return v;
}

static void
zvec_free(mpz_t * v, size_t n)
{
    size_t i;

    if (v == NULL)
        return;
    for (i = 0; i < n; i++)
        mpz_clear(v[i]);
    free(v);
}

/* k * n, or SIZE_MAX when that overflows (so the allocation fails).  */
static size_t
times(size_t k, size_t n)
{
    return n != 0 && k > SIZE_MAX / n ? SIZE_MAX : k * n;
}

/* An array of n objects of the given size (at least one byte); NULL when
   out of memory or when the size overflows.  */
static void *
alloc_array(size_t n, size_t size)
{
    if (size != 0 && n > (SIZE_MAX - 1) / size)
        return NULL;
    return malloc(n * size + 1);
}

/* ------------------------------------------------------------------ */
/* The reason: a growing string.                                       */

typedef struct
{
    char * s;
    size_t len;
    size_t cap;
    int oom;
}
text_buf;

static void
tb_add_n(text_buf * b, const char * s, size_t n)
{
    if (b->oom)
        return;
    if (b->cap - b->len <= n)
    {
        size_t cap = b->cap < 64 ? 64 : b->cap;
        char * t;

        while (cap - b->len <= n)
        {
            if (cap > SIZE_MAX / 2)
            {
                b->oom = 1;
                return;
            }
            cap *= 2;
        }
        t = realloc(b->s, cap);
        if (t == NULL)
        {
            b->oom = 1;
            return;
        }
        b->s = t;
        b->cap = cap;
    }
    memcpy(b->s + b->len, s, n);
    b->len += n;
    b->s[b->len] = '\0';
}

static void
tb_add(text_buf * b, const char * s)
{
    tb_add_n(b, s, strlen(s));
}

static void
tb_addf(text_buf * b, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void
tb_addf(text_buf * b, const char * fmt, ...)
{
    va_list ap;
    int n;
    char * t;

    va_start(ap, fmt);
    n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0)
    {
        b->oom = 1;
        return;
    }
    t = malloc((size_t) n + 1);
    if (t == NULL)
    {
        b->oom = 1;
        return;
    }
    va_start(ap, fmt);
    vsnprintf(t, (size_t) n + 1, fmt, ap);
    va_end(ap);
    tb_add_n(b, t, (size_t) n);
    free(t);
}

/* An integer, cut after SHOW_DIGITS characters with "...".  */
static void
tb_z(text_buf * b, const mpz_t z)
{
    size_t n = mpz_sizeinbase(z, 10) + 2;
    char * t = malloc(n);

    if (t == NULL)
    {
        b->oom = 1;
        return;
    }
    mpz_get_str(t, 10, z);
    n = strlen(t);
    if (n > SHOW_DIGITS)
    {
        tb_add_n(b, t, SHOW_DIGITS);
        tb_add(b, "...");
    }
    else
        tb_add_n(b, t, n);
    free(t);
}

static void
tb_q(text_buf * b, const mpq_t q)
{
    tb_z(b, mpq_numref(q));
    if (mpz_cmp_ui(mpq_denref(q), 1) != 0)
    {
        tb_add(b, "/");
        tb_z(b, mpq_denref(q));
    }
}

/* "(a, b, c)" */
static void
tb_zvec(text_buf * b, mpz_t * v, size_t n)
{
    size_t i;

    tb_add(b, "(");
    for (i = 0; i < n; i++)
    {
        if (i > 0)
            tb_add(b, ", ");
        tb_z(b, v[i]);
    }
    tb_add(b, ")");
}

static void
tb_qvec(text_buf * b, mpq_t * v, size_t n)
{
    size_t i;

    tb_add(b, "(");
    for (i = 0; i < n; i++)
    {
        if (i > 0)
            tb_add(b, ", ");
        tb_q(b, v[i]);
    }
    tb_add(b, ")");
}

/* ------------------------------------------------------------------ */
/* Reading the certificate.                                            */

typedef struct
{
    const char * file;
    wc_error_struct * err;
    int status;         /* the worst so far: WC_OK, WC_EINPUT, WC_EINTERNAL */
}
checker;

static int
nomem(checker * c)
{
    c->status = wc_error_set(c->err, WC_EINTERNAL, c->file, 0, 0,
                             "out of memory");
    return WC_EINTERNAL;
}

/* Record an error at the value at, unless one located no later is
   already recorded.  Returns WC_EINPUT.  */
static int
bad(checker * c, const wc_json_node * at, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int
bad(checker * c, const wc_json_node * at, const char * fmt, ...)
{
    va_list ap;

    if (c->status == WC_EINTERNAL)
        return WC_EINPUT;
    if (c->status == WC_EINPUT
        && (c->err->line < at->line
            || (c->err->line == at->line && c->err->col <= at->col)))
        return WC_EINPUT;
    va_start(ap, fmt);
    wc_error_vset(c->err, WC_EINPUT, c->file, at->line, at->col, fmt, ap);
    va_end(ap);
    c->status = WC_EINPUT;
    return WC_EINPUT;
}

/* bad() with a message quoting s[0..len) (fmt has one %s).  */
static int
bad_quoting(checker * c, const wc_json_node * at, const char * fmt,
            const char * s, size_t len)
{
    char * t = _wc_json_show(s, len);

    if (t == NULL)
        return nomem(c);
    bad(c, at, fmt, t);
    free(t);
    return WC_EINPUT;
}

typedef enum { WANT_STRING, WANT_BOOL, WANT_ARRAY, WANT_OBJECT } want;

/* The member key of object o, of the wanted type, into *v.  */
static int
member(checker * c, const wc_json_node * o, const char * key, want w,
       const wc_json_node ** v)
{
    static const char * const name[] = {
        "a string", "true or false", "an array", "an object"
    };
    const wc_json_node * x = _wc_json_object_get(o, key);
    int ok;

    *v = NULL;
    if (x == NULL)
        return bad(c, o, "missing key '%s'", key);
    switch (w)
    {
    case WANT_STRING:
        ok = x->type == WC_JSON_STRING;
        break;
    case WANT_BOOL:
        ok = x->type == WC_JSON_TRUE || x->type == WC_JSON_FALSE;
        break;
    case WANT_ARRAY:
        ok = x->type == WC_JSON_ARRAY;
        break;
    default:
        ok = x->type == WC_JSON_OBJECT;
        break;
    }
    if (!ok)
        return bad(c, x, "'%s' must be %s", key, name[w]);
    *v = x;
    return WC_OK;
}

/* An element of an array that must be an object.  */
static int
want_object(checker * c, const wc_json_node * v)
{
    if (v->type != WC_JSON_OBJECT)
        return bad(c, v, "expected an object, found %s",
                   _wc_json_type_name(v->type));
    return WC_OK;
}

static int
all_digits(const char * s, size_t a, size_t b)
{
    size_t i;

    if (a >= b)
        return 0;
    for (i = a; i < b; i++)
        if (s[i] < '0' || s[i] > '9')
            return 0;
    return 1;
}

/* The rational written at v: a string "p" or "p/q", or a JSON integer.  */
static int
read_rational(checker * c, const wc_json_node * v, mpq_t q)
{
    const char * s = v->text;
    size_t n = v->len, i, slash = n, a;

    if (v->type == WC_JSON_NUMBER)
    {
        /* the reader has checked the grammar: an integer has no . e E */
        for (i = 0; i < n; i++)
            if (s[i] == '.' || s[i] == 'e' || s[i] == 'E')
                return bad_quoting(c, v, "bad rational '%s'", s, n);
        mpz_set_str(mpq_numref(q), s, 10);
        mpz_set_ui(mpq_denref(q), 1);
        return WC_OK;
    }
    if (v->type != WC_JSON_STRING)
        return bad(c, v, "expected a rational, found %s",
                   _wc_json_type_name(v->type));
    a = n > 0 && s[0] == '-' ? 1 : 0;
    for (i = a; i < n; i++)
        if (s[i] == '/')
        {
            slash = i;
            break;
        }
    if (!all_digits(s, a, slash)
        || (slash < n && !all_digits(s, slash + 1, n)))
        return bad_quoting(c, v, "bad rational '%s'", s, n);
    if (slash < n)
    {
        for (i = slash + 1; i < n && s[i] == '0'; i++)
            ;
        if (i == n)
            return bad_quoting(c, v, "division by zero in '%s'", s, n);
    }
    /* s is NUL-terminated at n and holds only what mpq_set_str reads */
    if (mpq_set_str(q, s, 10) != 0)
        return bad_quoting(c, v, "bad rational '%s'", s, n);
    mpq_canonicalize(q);
    return WC_OK;
}

/* v (the value of key) is an array of exactly n rationals, into q.  */
static int
read_vector_node(checker * c, const wc_json_node * v, const char * key,
                 mpq_t * q, size_t n)
{
    size_t i;

    if (v->type != WC_JSON_ARRAY)
        return bad(c, v, "'%s' must be an array", key);
    if (v->len != n)
        return bad(c, v, "'%s' must have %lu entries, not %lu", key,
                   (unsigned long) n, (unsigned long) v->len);
    for (i = 0; i < n; i++)
        if (read_rational(c, v->items + i, q[i]) != WC_OK)
            return WC_EINPUT;
    return WC_OK;
}

static int
read_vector(checker * c, const wc_json_node * o, const char * key,
            mpq_t * q, size_t n)
{
    const wc_json_node * v = _wc_json_object_get(o, key);

    if (v == NULL)
        return bad(c, o, "missing key '%s'", key);
    return read_vector_node(c, v, key, q, n);
}

/* What the certificate says.  */
typedef struct
{
    const wc_json_node * mode_node;     /* NULL until read */
    int feasible;                       /* -1 until read */
    size_t m;                           /* constraints */
    mpq_t * rows;                       /* 3 m */
    relation * rel;                     /* m */
    mpq_t * witness;                    /* 3, when feasible */
    size_t nmult;
    mpq_t * mult;                       /* nmult, when not feasible */
    mpq_t * com;                        /* 2 */
    size_t n;                           /* fixels */
    mpq_t * fixel;                      /* 4 n: point x, y, normal x, y */
    int * near;                         /* n */
}
certificate;

static void
cert_init(certificate * C)
{
    memset(C, 0, sizeof *C);
    C->feasible = -1;
}

static void
cert_clear(certificate * C)
{
    qvec_free(C->rows, 3 * C->m);
    free(C->rel);
    qvec_free(C->witness, 3);
    qvec_free(C->mult, C->nmult);
    qvec_free(C->com, 2);
    qvec_free(C->fixel, 4 * C->n);
    free(C->near);
    cert_init(C);
}

static int
read_constraints(checker * c, certificate * C, const wc_json_node * root)
{
    const wc_json_node * a;
    size_t k;

    if (member(c, root, "constraints", WANT_ARRAY, &a) != WC_OK)
        return WC_EINPUT;
    C->rows = qvec_new(times(3, a->len));
    C->rel = alloc_array(a->len, sizeof(relation));
    if (C->rows == NULL || C->rel == NULL)
    {
        /* keep the counts in step with what was initialised */
        qvec_free(C->rows, C->rows != NULL ? 3 * a->len : 0);
        C->rows = NULL;
        return nomem(c);
    }
    C->m = a->len;
    for (k = 0; k < a->len; k++)
    {
        const wc_json_node * e = a->items + k, * r;
        int status = want_object(c, e);

        if (status != WC_OK)
            return status;
        /* row and relation are independent: check both */
        status = read_vector(c, e, "row", C->rows + 3 * k, 3);
        if (member(c, e, "relation", WANT_STRING, &r) != WC_OK)
            status = WC_EINPUT;
        else if (r->len == 1 && r->text[0] == '>')
            C->rel[k] = REL_GT;
        else if (r->len == 2 && memcmp(r->text, ">=", 2) == 0)
            C->rel[k] = REL_GE;
        else if (r->len == 1 && r->text[0] == '=')
            C->rel[k] = REL_EQ;
        else
            status = bad_quoting(c, r, "unknown relation '%s'", r->text,
                                 r->len);
        if (status != WC_OK)
            return status;
    }
    return WC_OK;
}

static int
read_multipliers(checker * c, certificate * C, const wc_json_node * root)
{
    const wc_json_node * a;
    size_t k;

    if (member(c, root, "multipliers", WANT_ARRAY, &a) != WC_OK)
        return WC_EINPUT;
    C->mult = qvec_new(a->len);
    if (C->mult == NULL)
        return nomem(c);
    C->nmult = a->len;
    for (k = 0; k < a->len; k++)
        if (read_rational(c, a->items + k, C->mult[k]) != WC_OK)
            return WC_EINPUT;
    return WC_OK;
}

static int
read_problem(checker * c, certificate * C, const wc_json_node * root)
{
    const wc_json_node * p, * fx;
    size_t i;
    int status;

    if (member(c, root, "problem", WANT_OBJECT, &p) != WC_OK)
        return WC_EINPUT;
    C->com = qvec_new(2);
    if (C->com == NULL)
        return nomem(c);
    /* com and fixels are independent: check both */
    status = read_vector(c, p, "com", C->com, 2);
    if (member(c, p, "fixels", WANT_ARRAY, &fx) != WC_OK)
        return WC_EINPUT;
    if (fx->len == 0)
        return bad(c, fx, "no fixel in the problem");
    C->fixel = qvec_new(times(4, fx->len));
    C->near = alloc_array(fx->len, sizeof(int));
    if (C->fixel == NULL || C->near == NULL)
    {
        qvec_free(C->fixel, C->fixel != NULL ? 4 * fx->len : 0);
        C->fixel = NULL;
        return nomem(c);
    }
    C->n = fx->len;
    for (i = 0; i < fx->len; i++)
    {
        const wc_json_node * f = fx->items + i, * nv, * st;
        mpq_t * q = C->fixel + 4 * i;
        int fstatus = want_object(c, f);

        if (fstatus != WC_OK)
            return fstatus;
        fstatus = read_vector(c, f, "point", q, 2);
        nv = _wc_json_object_get(f, "normal");
        if (nv == NULL)
            fstatus = bad(c, f, "missing key 'normal'");
        else if (read_vector_node(c, nv, "normal", q + 2, 2) != WC_OK)
            fstatus = WC_EINPUT;
        else if (mpq_sgn(q[2]) == 0 && mpq_sgn(q[3]) == 0)
            fstatus = bad(c, nv, "zero normal");
        if (member(c, f, "state", WANT_STRING, &st) != WC_OK)
            fstatus = WC_EINPUT;
        else if (st->len == 8 && memcmp(st->text, "touching", 8) == 0)
            C->near[i] = 0;
        else if (st->len == 4 && memcmp(st->text, "near", 4) == 0)
            C->near[i] = 1;
        else
            fstatus = bad_quoting(c, st, "unknown fixel state '%s'",
                                  st->text, st->len);
        /* a later fixel is later in the file */
        if (fstatus != WC_OK)
            return fstatus;
    }
    return status;
}

/* The mode against the fixels (Table 1), with the messages of mode.c.  */
static int
check_mode(checker * c, const certificate * C)
{
    const wc_json_node * v = C->mode_node;
    size_t len = v->len, i;

    if (len != C->n)
        return bad(c, v, "mode has %lu letter%s; the problem has %lu "
                   "fixel%s", (unsigned long) len, len == 1 ? "" : "s",
                   (unsigned long) C->n, C->n == 1 ? "" : "s");
    for (i = 0; i < len; i++)
    {
        unsigned char l = (unsigned char) v->text[i];

        if (l == '\0' || strchr("slrna", l) == NULL)
        {
            if (l < 0x20 || l >= 0x7f)
                return bad(c, v, "unknown mode letter '\\x%02x'", l);
            return bad(c, v, "unknown mode letter '%c'", l);
        }
        if (strchr(C->near[i] ? "sa" : "slrn", l) == NULL)
            return bad(c, v, "letter '%c' not allowed on fixel %lu, which "
                       "is %s", l, (unsigned long) i + 1,
                       C->near[i] ? "near" : "touching");
    }
    return WC_OK;
}

/* The kind of the certificate root into *kind (no "kind": a
   mode-feasibility certificate).  Another kind is another format: when
   this fails, nothing else is worth reading.  */
static int
read_kind(checker * c, const wc_json_node * root, cert_kind * kind)
{
    const wc_json_node * k;

    if (root->type != WC_JSON_OBJECT)
        return bad(c, root, "expected a certificate object, found %s",
                   _wc_json_type_name(root->type));
    k = _wc_json_object_get(root, "kind");
    *kind = KIND_MODE;
    if (k == NULL)
        return WC_OK;
    if (k->type != WC_JSON_STRING)
        return bad(c, k, "'kind' must be a string");
    if (k->len == strlen(KIND) && memcmp(k->text, KIND, k->len) == 0)
        return WC_OK;
    if (k->len == strlen(KIND_STRONG)
        && memcmp(k->text, KIND_STRONG, k->len) == 0)
    {
        *kind = KIND_STABILITY;
        return WC_OK;
    }
    return bad_quoting(c, k, "unknown certificate kind '%s'", k->text,
                       k->len);
}

/* Read everything the check of a mode-feasibility certificate (its kind
   read) needs from the document; errors into c.  */
static void
read_certificate(checker * c, certificate * C, const wc_json_node * root)
{
    const wc_json_node * mode, * feas;
    int problem_ok;

    if (member(c, root, "mode", WANT_STRING, &mode) == WC_OK)
        C->mode_node = mode;
    if (member(c, root, "feasible", WANT_BOOL, &feas) == WC_OK)
        C->feasible = feas->type == WC_JSON_TRUE;
    if (c->status == WC_EINTERNAL)
        return;
    read_constraints(c, C, root);
    if (c->status == WC_EINTERNAL)
        return;
    if (C->feasible == 1)
    {
        C->witness = qvec_new(3);
        if (C->witness == NULL)
        {
            nomem(c);
            return;
        }
        read_vector(c, root, "witness", C->witness, 3);
    }
    else if (C->feasible == 0)
        read_multipliers(c, C, root);
    if (c->status == WC_EINTERNAL)
        return;
    problem_ok = read_problem(c, C, root) == WC_OK;
    if (c->status == WC_EINTERNAL)
        return;
    if (problem_ok && C->mode_node != NULL)
        check_mode(c, C);
}

/* ------------------------------------------------------------------ */
/* The check.                                                          */

/* z = the primitive integer vector on the ray of the nonzero rational
   vector q (3 entries).  */
static void
primitive(mpz_t * z, mpq_t * q, mpz_t t)
{
    int j;

    mpz_set(t, mpq_denref(q[0]));
    mpz_lcm(t, t, mpq_denref(q[1]));
    mpz_lcm(t, t, mpq_denref(q[2]));
    for (j = 0; j < 3; j++)
    {
        mpz_divexact(z[j], t, mpq_denref(q[j]));
        mpz_mul(z[j], z[j], mpq_numref(q[j]));
    }
    mpz_gcd(t, z[0], z[1]);
    mpz_gcd(t, t, z[2]);
    if (mpz_sgn(t) != 0)
        for (j = 0; j < 3; j++)
            mpz_divexact(z[j], z[j], t);
}

/* J[0..3) = J_n = (n_x, n_y, r x n) and J[3..6) = J_t = (t_x, t_y,
   r x t) of the fixel at point p with normal nrm, where r = p - com and
   t = (-n_y, n_x).  */
static void
jacobian(mpq_t * J, mpq_t * com, mpq_t * p, mpq_t * nrm)
{
    /* J[5] holds r_x until the end */
    mpq_sub(J[5], p[0], com[0]);
    mpq_sub(J[4], p[1], com[1]);
    mpq_set(J[0], nrm[0]);
    mpq_set(J[1], nrm[1]);
    mpq_mul(J[2], J[5], nrm[1]);
    mpq_mul(J[3], J[4], nrm[0]);
    mpq_sub(J[2], J[2], J[3]);
    /* r x t = r_x n_x + r_y n_y */
    mpq_mul(J[5], J[5], nrm[0]);
    mpq_mul(J[4], J[4], nrm[1]);
    mpq_add(J[5], J[5], J[4]);
    mpq_neg(J[3], nrm[1]);
    mpq_set(J[4], nrm[0]);
}

/* The rows mode implies: rows (3 m), rel, fixel of each (0-based).  */
typedef struct
{
    size_t m;
    mpz_t * rows;
    relation * rel;
    size_t * fixel;
}
implied;

static size_t
rows_of_letter(char l, int near)
{
    return near || l == 's' ? 1 : 2;
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
    for (i = 0; i < C->n; i++)
        m += rows_of_letter(mode[i], C->near[i]);
    I->rows = zvec_new(times(3, m));
    I->rel = alloc_array(m, sizeof(relation));
    I->fixel = alloc_array(m, sizeof(size_t));
    J = qvec_new(6);
    if (I->rows == NULL || I->rel == NULL || I->fixel == NULL || J == NULL)
    {
        zvec_free(I->rows, I->rows != NULL ? 3 * m : 0);
        I->rows = NULL;
        status = WC_EINTERNAL;
        goto cleanup;
    }
    I->m = m;
    for (i = 0; i < C->n; i++)
    {
        mpq_t * p = C->fixel + 4 * i, * nrm = p + 2;
        char l = mode[i];
        mpz_t * zn = I->rows + 3 * k;

        jacobian(J, C->com, p, nrm);
        primitive(zn, J, t);
        I->fixel[k] = i;
        if (C->near[i] && l == 'a')
        {
            mpz_neg(zn[0], zn[0]);
            mpz_neg(zn[1], zn[1]);
            mpz_neg(zn[2], zn[2]);
            I->rel[k] = REL_GT;
        }
        else if (C->near[i])
            I->rel[k] = REL_GE;
        else
            I->rel[k] = l == 's' ? REL_GT : REL_EQ;
        k++;
        if (rows_of_letter(l, C->near[i]) == 2)
        {
            mpz_t * zt = I->rows + 3 * k;

            primitive(zt, J + 3, t);
            I->fixel[k] = i;
            if (l == 'r')
            {
                mpz_neg(zt[0], zt[0]);
                mpz_neg(zt[1], zt[1]);
                mpz_neg(zt[2], zt[2]);
            }
            I->rel[k] = l == 'n' ? REL_EQ : REL_GT;
            k++;
        }
    }
cleanup:
    qvec_free(J, 6);
    mpz_clear(t);
    return status;
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
satisfies(int sign, relation r)
{
    return r == REL_GT ? sign > 0 : r == REL_GE ? sign >= 0 : sign == 0;
}

/* Decide whether the certificate C (read without error) holds; when it
   does not, write why into why.  Returns 1 or 0; -1 when out of memory.  */
static int
check(text_buf * why, const certificate * C, const char * mode)
{
    implied I = { 0, NULL, NULL, NULL };
    mpq_t * s = NULL;
    mpq_t t;
    size_t k, common = C->m;
    int holds = 0, j;
    char * shown = _wc_json_show(mode, strlen(mode));  /* a long mode cut */

    mpq_init(t);
    s = qvec_new(3);
    if (s == NULL || shown == NULL || implied_rows(&I, C, mode) != WC_OK)
    {
        holds = -1;
        goto cleanup;
    }
    if (I.m < common)
        common = I.m;
    for (k = 0; k < common; k++)
        if (!row_equal(C->rows + 3 * k, I.rows + 3 * k)
            || C->rel[k] != I.rel[k])
        {
            tb_addf(why, "constraint %lu is not the one mode %s implies for "
                    "fixel %lu: expected ", (unsigned long) k + 1, shown,
                    (unsigned long) I.fixel[k] + 1);
            tb_zvec(why, I.rows + 3 * k, 3);
            tb_addf(why, " . nu %s 0, found ", rel_name[I.rel[k]]);
            tb_qvec(why, C->rows + 3 * k, 3);
            tb_addf(why, " . nu %s 0", rel_name[C->rel[k]]);
            goto cleanup;
        }
    if (C->m != I.m)
    {
        tb_addf(why, "the certificate lists %lu constraint%s; mode %s "
                "implies %lu", (unsigned long) C->m, C->m == 1 ? "" : "s",
                shown, (unsigned long) I.m);
        goto cleanup;
    }
    if (C->feasible)
    {
        for (k = 0; k < I.m; k++)
        {
            mpq_set_ui(s[0], 0, 1);
            for (j = 0; j < 3; j++)
            {
                mpq_set_z(t, I.rows[3 * k + j]);
                mpq_mul(t, t, C->witness[j]);
                mpq_add(s[0], s[0], t);
            }
            if (!satisfies(mpq_sgn(s[0]), I.rel[k]))
            {
                tb_add(why, "the witness ");
                tb_qvec(why, C->witness, 3);
                tb_addf(why, " violates constraint %lu: ",
                        (unsigned long) k + 1);
                tb_zvec(why, I.rows + 3 * k, 3);
                tb_add(why, " . nu = ");
                tb_q(why, s[0]);
                tb_addf(why, ", not %s 0", rel_name[I.rel[k]]);
                goto cleanup;
            }
        }
        holds = 1;
        goto cleanup;
    }
    if (C->nmult != I.m)
    {
        tb_addf(why, "there %s %lu multiplier%s for %lu constraint%s",
                C->nmult == 1 ? "is" : "are", (unsigned long) C->nmult,
                C->nmult == 1 ? "" : "s", (unsigned long) I.m,
                I.m == 1 ? "" : "s");
        goto cleanup;
    }
    for (k = 0; k < I.m; k++)
        if (I.rel[k] != REL_EQ && mpq_sgn(C->mult[k]) < 0)
        {
            tb_addf(why, "multiplier %lu is ", (unsigned long) k + 1);
            tb_q(why, C->mult[k]);
            tb_addf(why, ", negative on a '%s' constraint",
                    rel_name[I.rel[k]]);
            goto cleanup;
        }
    for (j = 0; j < 3; j++)
    {
        mpq_set_ui(s[j], 0, 1);
        for (k = 0; k < I.m; k++)
        {
            mpq_set_z(t, I.rows[3 * k + j]);
            mpq_mul(t, t, C->mult[k]);
            mpq_add(s[j], s[j], t);
        }
    }
    if (mpq_sgn(s[0]) != 0 || mpq_sgn(s[1]) != 0 || mpq_sgn(s[2]) != 0)
    {
        tb_add(why, "the multipliers combine the rows to ");
        tb_qvec(why, s, 3);
        tb_add(why, ", not to zero");
        goto cleanup;
    }
    for (k = 0; k < I.m; k++)
        if (I.rel[k] == REL_GT && mpq_sgn(C->mult[k]) > 0)
            break;
    if (k == I.m)
    {
        tb_add(why, "no '>' constraint has a positive multiplier");
        goto cleanup;
    }
    holds = 1;
cleanup:
    if (why->oom)
        holds = -1;
    zvec_free(I.rows, 3 * I.m);
    free(I.rel);
    free(I.fixel);
    qvec_free(s, 3);
    mpq_clear(t);
    free(shown);
    return holds;
}

/* ------------------------------------------------------------------ */
/* Strong stability: reading.                                          */

/* For read_qarray: an array of any length.  */
#define ANY_LENGTH ((size_t) -1)

/* One entry of "faces".  */
typedef struct
{
    const wc_json_node * sign;          /* NULL until read */
    const wc_json_node * rot_node;      /* NULL when absent */
    int rotation;                       /* 0, 1 or -1 */
    size_t nmult;
    mpq_t * mult;
}
stab_face;

/* What a strong-stability certificate says.  */
typedef struct
{
    mpq_t * body;                       /* 4: mass, inertia, com */
    size_t n;                           /* fixels; 0 until known */
    mpq_t * fixel;                      /* 6 n: point x, y, normal x, y,
                                           mu_s, mu_k */
    int * near;                         /* n: 1, 0; -1 until read */
    mpq_t * g;                          /* 3 */
    int weak;                           /* -1 until read */
    int strong;                         /* -1 until read */
    size_t nwc;
    mpq_t * weak_c;                     /* 2 n, when weak */
    mpq_t * sep;                        /* 3, when not weak */
    const wc_json_node * motion_sign;   /* when weak and not strong */
    mpq_t * nudot;                      /* 3 */
    size_t nmc;
    mpq_t * motion_c;                   /* 2 n */
    size_t nfaces;                      /* when strong */
    stab_face * faces;
}
stab_cert;

static void
stab_init(stab_cert * S)
{
    memset(S, 0, sizeof *S);
    S->weak = -1;
    S->strong = -1;
}

static void
stab_clear(stab_cert * S)
{
    size_t k;

    qvec_free(S->body, 4);
    qvec_free(S->fixel, 6 * S->n);
    free(S->near);
    qvec_free(S->g, 3);
    qvec_free(S->weak_c, S->nwc);
    qvec_free(S->sep, 3);
    qvec_free(S->nudot, 3);
    qvec_free(S->motion_c, S->nmc);
    if (S->faces != NULL)
        for (k = 0; k < S->nfaces; k++)
            qvec_free(S->faces[k].mult, S->faces[k].nmult);
    free(S->faces);
    stab_init(S);
}

/* v (the value of key) is an array of rationals, of want entries unless
   want is ANY_LENGTH; into *q, allocated here with *len entries.  */
static int
read_qarray(checker * c, const wc_json_node * v, const char * key,
            size_t want, mpq_t ** q, size_t * len)
{
    size_t i;

    if (v->type != WC_JSON_ARRAY)
        return bad(c, v, "'%s' must be an array", key);
    if (want != ANY_LENGTH && v->len != want)
        return bad(c, v, "'%s' must have %lu entries, not %lu", key,
                   (unsigned long) want, (unsigned long) v->len);
    *q = qvec_new(v->len);
    if (*q == NULL)
        return nomem(c);
    *len = v->len;
    for (i = 0; i < v->len; i++)
        if (read_rational(c, v->items + i, (*q)[i]) != WC_OK)
            return WC_EINPUT;
    return WC_OK;
}

static int
read_qarray_member(checker * c, const wc_json_node * o, const char * key,
                   size_t want, mpq_t ** q, size_t * len)
{
    const wc_json_node * v = _wc_json_object_get(o, key);

    if (v == NULL)
        return bad(c, o, "missing key '%s'", key);
    return read_qarray(c, v, key, want, q, len);
}

/* The rational o[key] into q, which must be positive (sign 1) or
   non-negative (sign 0).  */
static int
read_scalar(checker * c, const wc_json_node * o, const char * key,
            mpq_t q, int sign)
{
    const wc_json_node * v = _wc_json_object_get(o, key);

    if (v == NULL)
        return bad(c, o, "missing key '%s'", key);
    if (read_rational(c, v, q) != WC_OK)
        return WC_EINPUT;
    if (sign > 0 && mpq_sgn(q) <= 0)
        return bad(c, v, "'%s' must be positive", key);
    if (sign == 0 && mpq_sgn(q) < 0)
        return bad(c, v, "'%s' must not be negative", key);
    return WC_OK;
}

static int
read_stab_problem(checker * c, stab_cert * S, const wc_json_node * root)
{
    const wc_json_node * p, * fx;
    size_t i;
    int status = WC_OK;

    if (member(c, root, "problem", WANT_OBJECT, &p) != WC_OK)
        return WC_EINPUT;
    S->body = qvec_new(4);
    if (S->body == NULL)
        return nomem(c);
    /* mass, inertia, com and fixels are independent: check them all */
    if (read_scalar(c, p, "mass", S->body[0], 1) != WC_OK)
        status = WC_EINPUT;
    if (read_scalar(c, p, "inertia", S->body[1], 1) != WC_OK)
        status = WC_EINPUT;
    if (read_vector(c, p, "com", S->body + 2, 2) != WC_OK)
        status = WC_EINPUT;
    if (member(c, p, "fixels", WANT_ARRAY, &fx) != WC_OK)
        return WC_EINPUT;
    if (fx->len == 0)
        return bad(c, fx, "no fixel in the problem");
    S->fixel = qvec_new(times(6, fx->len));
    S->near = alloc_array(fx->len, sizeof(int));
    if (S->fixel == NULL || S->near == NULL)
    {
        qvec_free(S->fixel, S->fixel != NULL ? 6 * fx->len : 0);
        S->fixel = NULL;
        return nomem(c);
    }
    S->n = fx->len;
    for (i = 0; i < fx->len; i++)
        S->near[i] = -1;
    for (i = 0; i < fx->len; i++)
    {
        const wc_json_node * f = fx->items + i, * nv, * st;
        mpq_t * q = S->fixel + 6 * i;
        int fstatus = want_object(c, f);

        if (fstatus != WC_OK)
            return fstatus;
        fstatus = read_vector(c, f, "point", q, 2);
        nv = _wc_json_object_get(f, "normal");
        if (nv == NULL)
            fstatus = bad(c, f, "missing key 'normal'");
        else if (read_vector_node(c, nv, "normal", q + 2, 2) != WC_OK)
            fstatus = WC_EINPUT;
        else if (mpq_sgn(q[2]) == 0 && mpq_sgn(q[3]) == 0)
            fstatus = bad(c, nv, "zero normal");
        if (member(c, f, "state", WANT_STRING, &st) != WC_OK)
            fstatus = WC_EINPUT;
        else if (st->len == 8 && memcmp(st->text, "touching", 8) == 0)
            S->near[i] = 0;
        else if (st->len == 4 && memcmp(st->text, "near", 4) == 0)
            S->near[i] = 1;
        else
            fstatus = bad_quoting(c, st, "unknown fixel state '%s'",
                                  st->text, st->len);
        if (read_scalar(c, f, "mu_s", q[4], 0) != WC_OK)
            fstatus = WC_EINPUT;
        if (read_scalar(c, f, "mu_k", q[5], 0) != WC_OK)
            fstatus = WC_EINPUT;
        /* a later fixel is later in the file */
        if (fstatus != WC_OK)
            return fstatus;
    }
    return status;
}

/* A sign string against the fixels (as far as they are known): one
   letter per fixel, s l r n on touching ones, u on near ones.  */
static int
check_sign(checker * c, const wc_json_node * v, const stab_cert * S)
{
    size_t len = v->len, i;

    if (S->n > 0 && len != S->n)
        return bad(c, v, "sign has %lu letter%s; the problem has %lu "
                   "fixel%s", (unsigned long) len, len == 1 ? "" : "s",
                   (unsigned long) S->n, S->n == 1 ? "" : "s");
    for (i = 0; i < len; i++)
    {
        unsigned char l = (unsigned char) v->text[i];

        if (l == '\0' || strchr("slrnu", l) == NULL)
        {
            if (l < 0x20 || l >= 0x7f)
                return bad(c, v, "unknown sign letter '\\x%02x'", l);
            return bad(c, v, "unknown sign letter '%c'", l);
        }
        if (i < S->n && S->near[i] >= 0
            && strchr(S->near[i] ? "u" : "slrn", l) == NULL)
            return bad(c, v, "letter '%c' not allowed on fixel %lu, which "
                       "is %s", l, (unsigned long) i + 1,
                       S->near[i] ? "near" : "touching");
    }
    return WC_OK;
}

/* The entries of 2 n forces: 2 n when n is known.  */
static size_t
forces_length(const stab_cert * S)
{
    return S->n > 0 ? times(2, S->n) : ANY_LENGTH;
}

static int
read_motion(checker * c, stab_cert * S, const wc_json_node * root)
{
    const wc_json_node * o, * sign;
    int status = WC_OK;

    if (member(c, root, "motion", WANT_OBJECT, &o) != WC_OK)
        return WC_EINPUT;
    if (member(c, o, "sign", WANT_STRING, &sign) == WC_OK)
        S->motion_sign = sign;
    else
        status = WC_EINPUT;
    S->nudot = qvec_new(3);
    if (S->nudot == NULL)
        return nomem(c);
    if (read_vector(c, o, "nudot", S->nudot, 3) != WC_OK)
        status = WC_EINPUT;
    if (read_qarray_member(c, o, "c", forces_length(S), &S->motion_c,
                           &S->nmc) != WC_OK)
        status = WC_EINPUT;
    return status;
}

static int
read_faces(checker * c, stab_cert * S, const wc_json_node * root)
{
    const wc_json_node * a;
    size_t k;

    if (member(c, root, "faces", WANT_ARRAY, &a) != WC_OK)
        return WC_EINPUT;
    S->faces = alloc_array(a->len, sizeof(stab_face));
    if (S->faces == NULL)
        return nomem(c);
    if (a->len > 0)
        memset(S->faces, 0, a->len * sizeof(stab_face));
    S->nfaces = a->len;
    for (k = 0; k < a->len; k++)
    {
        const wc_json_node * f = a->items + k, * v;
        stab_face * F = S->faces + k;
        int status = want_object(c, f);

        if (status != WC_OK)
            return status;
        if (member(c, f, "sign", WANT_STRING, &v) == WC_OK)
            F->sign = v;
        else
            status = WC_EINPUT;
        v = _wc_json_object_get(f, "rotation");
        if (v != NULL)
        {
            mpq_t r;

            mpq_init(r);
            F->rot_node = v;
            if (read_rational(c, v, r) != WC_OK)
                status = WC_EINPUT;
            else if (mpz_cmp_ui(mpq_denref(r), 1) != 0
                     || mpz_cmpabs_ui(mpq_numref(r), 1) != 0)
                status = bad(c, v, "'rotation' must be 1 or -1");
            else
                F->rotation = mpq_sgn(r);
            mpq_clear(r);
        }
        if (read_qarray_member(c, f, "multipliers", ANY_LENGTH, &F->mult,
                               &F->nmult) != WC_OK)
            status = WC_EINPUT;
        /* a later face is later in the file */
        if (status != WC_OK)
            return status;
    }
    return WC_OK;
}

/* Read everything the check of a strong-stability certificate (its kind
   read) needs from the document; errors into c.  */
static void
read_stability(checker * c, stab_cert * S, const wc_json_node * root)
{
    const wc_json_node * v, * w;
    size_t k;

    read_stab_problem(c, S, root);
    if (c->status == WC_EINTERNAL)
        return;
    S->g = qvec_new(3);
    if (S->g == NULL)
    {
        nomem(c);
        return;
    }
    read_vector(c, root, "wrench", S->g, 3);
    if (member(c, root, "weakly_stable", WANT_BOOL, &v) == WC_OK)
        S->weak = v->type == WC_JSON_TRUE;
    if (member(c, root, "strongly_stable", WANT_BOOL, &v) == WC_OK)
        S->strong = v->type == WC_JSON_TRUE;
    if (S->weak >= 0 && member(c, root, "weak", WANT_OBJECT, &w) == WC_OK)
    {
        if (S->weak)
            read_qarray_member(c, w, "c", forces_length(S), &S->weak_c,
                               &S->nwc);
        else
        {
            S->sep = qvec_new(3);
            if (S->sep == NULL)
            {
                nomem(c);
                return;
            }
            read_vector(c, w, "separator", S->sep, 3);
        }
    }
    if (c->status == WC_EINTERNAL)
        return;
    if (S->weak == 1 && S->strong == 0)
        read_motion(c, S, root);
    if (c->status == WC_EINTERNAL)
        return;
    if (S->strong == 1)
        read_faces(c, S, root);
    if (c->status == WC_EINTERNAL)
        return;
    /* the signs against the problem */
    if (S->motion_sign != NULL)
        check_sign(c, S->motion_sign, S);
    for (k = 0; k < S->nfaces; k++)
    {
        const stab_face * F = S->faces + k;

        if (F->sign == NULL)
            break;
        check_sign(c, F->sign, S);
        if (F->rot_node != NULL && F->rotation != 0
            && strspn(F->sign->text, "nu") != F->sign->len)
            bad(c, F->rot_node, "a rotation face has the sign n..n");
    }
}

/* ------------------------------------------------------------------ */
/* Strong stability: the moving faces, from the arrangement.           */

/* The sign strings found: n + 1 bytes each, malloc'd.  */
typedef struct
{
    size_t count;
    size_t cap;
    char ** s;
    int oom;
}
string_set;

static void
sset_add(string_set * T, const char * s, size_t n)
{
    char * t;

    if (T->oom)
        return;
    if (T->count == T->cap)
    {
        size_t cap = T->cap < 16 ? 16 : T->cap;
        char ** u;

        if (cap > SIZE_MAX / (2 * sizeof(char *)))
        {
            T->oom = 1;
            return;
        }
        cap *= 2;
        u = realloc(T->s, cap * sizeof(char *));
        if (u == NULL)
        {
            T->oom = 1;
            return;
        }
        T->s = u;
        T->cap = cap;
    }
    t = malloc(n + 1);
    if (t == NULL)
    {
        T->oom = 1;
        return;
    }
    memcpy(t, s, n);
    t[n] = '\0';
    T->s[T->count++] = t;
}

static void
sset_clear(string_set * T)
{
    size_t k;

    for (k = 0; k < T->count; k++)
        free(T->s[k]);
    free(T->s);
    memset(T, 0, sizeof *T);
}

static int
str_cmp(const void * a, const void * b)
{
    return strcmp(*(char * const *) a, *(char * const *) b);
}

/* Sort and drop repeats.  */
static void
sset_finish(string_set * T)
{
    size_t k, m = 0;

    if (T->count == 0)
        return;
    qsort(T->s, T->count, sizeof(char *), str_cmp);
    for (k = 1; k < T->count; k++)
        if (strcmp(T->s[k], T->s[m]) == 0)
            free(T->s[k]);
        else
            T->s[++m] = T->s[k];
    T->count = m + 1;
}

/* The index of s in the finished set, or -1.  */
static long
sset_find(const string_set * T, const char * s)
{
    size_t lo = 0, hi = T->count;

    while (lo < hi)
    {
        size_t mid = lo + (hi - lo) / 2;
        int d = strcmp(s, T->s[mid]);

        if (d == 0)
            return (long) mid;
        if (d < 0)
            hi = mid;
        else
            lo = mid + 1;
    }
    return -1;
}

static void
zdot3(mpz_t r, mpz_t * a, mpz_t * b)
{
    mpz_mul(r, a[0], b[0]);
    mpz_addmul(r, a[1], b[1]);
    mpz_addmul(r, a[2], b[2]);
}

/* r = a x b (r distinct from a and b).  */
static void
zcross3(mpz_t * r, mpz_t * a, mpz_t * b)
{
    mpz_mul(r[0], a[1], b[2]);
    mpz_submul(r[0], a[2], b[1]);
    mpz_mul(r[1], a[2], b[0]);
    mpz_submul(r[1], a[0], b[2]);
    mpz_mul(r[2], a[0], b[1]);
    mpz_submul(r[2], a[1], b[0]);
}

/* The arrangement of the planes h . x = 0, h = J_in and J_it of the
   touching fixels, made primitive integer vectors (positive multiples:
   the signs are those of J_in . x and J_it . x).  */
typedef struct
{
    size_t n;           /* fixels */
    const int * near;
    size_t nh;          /* 2 t normals: J_in, J_it of each touching fixel
                           in order */
    mpz_t * h;          /* 3 nh */
    size_t np;          /* distinct planes */
    size_t * plane;     /* np indices into h */
    char * buf;         /* n + 1 */
    mpz_t s;            /* scratch */
    string_set * out;
}
arrangement;

/* The sign string of the point x, into A->out when x has a_in >= 0 at
   every touching fixel and is not n..n.  */
static void
candidate(arrangement * A, mpz_t * x)
{
    size_t i, k = 0;
    int moving = 0;

    for (i = 0; i < A->n; i++)
    {
        int sa;

        if (A->near[i])
        {
            A->buf[i] = 'u';
            continue;
        }
        zdot3(A->s, A->h + 6 * k, x);
        sa = mpz_sgn(A->s);
        if (sa < 0)
            return;
        if (sa > 0)
            A->buf[i] = 's';
        else
        {
            zdot3(A->s, A->h + 6 * k + 3, x);
            sa = mpz_sgn(A->s);
            A->buf[i] = sa > 0 ? 'l' : sa < 0 ? 'r' : 'n';
        }
        if (A->buf[i] != 'n')
            moving = 1;
        k++;
    }
    if (moving)
        sset_add(A->out, A->buf, A->n);
}

/* m is a point inside a 2-face (an open sector) of the plane hp: the
   point and its two neighbours K m +- hp off the plane, where
   K = 1 + max |h . hp| over the normals h with h . m != 0.  For such h,
   |h . m| >= 1 (integers), so K |h . m| > |h . hp| and h . (K m +- hp)
   has the sign of h . m; the normals with h . m = 0 are those of the
   plane itself (m lies on no other plane), whose sign the shift sets to
   that of +-h . hp.  Every chamber has a facet on some plane, and that
   facet is the closure of a 2-face (a plane crossing its relative
   interior would cut the chamber), so one of the neighbours of that
   2-face's point lies in the chamber.  */
static void
arc_point(arrangement * A, mpz_t * m, mpz_t * hp, mpz_t * x, mpz_t K)
{
    size_t q;
    int j;

    candidate(A, m);
    mpz_set_ui(K, 0);
    for (q = 0; q < A->nh; q++)
    {
        zdot3(A->s, A->h + 3 * q, m);
        if (mpz_sgn(A->s) == 0)
            continue;
        zdot3(A->s, A->h + 3 * q, hp);
        if (mpz_cmpabs(A->s, K) > 0)
            mpz_abs(K, A->s);
    }
    mpz_add_ui(K, K, 1);
    for (j = 0; j < 3; j++)
    {
        mpz_mul(x[j], K, m[j]);
        mpz_add(x[j], x[j], hp[j]);
    }
    candidate(A, x);
    for (j = 0; j < 3; j++)
        mpz_submul_ui(x[j], hp[j], 2);
    candidate(A, x);
}

/* The rays on one plane, in angular order.  */
typedef struct
{
    mpz_t * ray;        /* 3 per ray */
    int * half;         /* 0: angle in [0, pi) from ray 0; 1: [pi, 2 pi) */
    mpz_t * hp;
    mpz_t * cr;         /* 3, scratch */
    mpz_t d;
}
ray_order;

/* < 0 when ray a comes before ray b, 0 when they are the same
   direction.  */
static int
ray_cmp(ray_order * R, size_t a, size_t b)
{
    if (R->half[a] != R->half[b])
        return R->half[a] - R->half[b];
    /* in one half, a comes first when b is counter-clockwise from a
       about hp: (a x b) . hp > 0 */
    zcross3(R->cr, R->ray + 3 * a, R->ray + 3 * b);
    zdot3(R->d, R->cr, R->hp);
    return -mpz_sgn(R->d);
}

/* Merge sort of idx[0..n) by ray_cmp, tmp of n entries.  */
static void
sort_rays(ray_order * R, size_t * idx, size_t * tmp, size_t n)
{
    size_t h = n / 2, i = 0, j = h, k = 0;

    if (n < 2)
        return;
    sort_rays(R, idx, tmp, h);
    sort_rays(R, idx + h, tmp, n - h);
    while (i < h && j < n)
        tmp[k++] = ray_cmp(R, idx[j], idx[i]) < 0 ? idx[j++] : idx[i++];
    while (i < h)
        tmp[k++] = idx[i++];
    while (j < n)
        tmp[k++] = idx[j++];
    memcpy(idx, tmp, n * sizeof(size_t));
}

/* Every sign string S(nudot) with a_in >= 0 at every touching fixel,
   other than n..n, into out (finished: sorted, no repeats).  J holds J_in
   and J_it of every fixel (6 n).  The strings are constant on the cells
   of the central arrangement of the touching fixels' planes, and every
   cell but the origin (whose string is n..n) holds one of these points:
     - both directions of the line where two planes meet (every 1-face);
     - on each plane, the sum of two angularly consecutive rays of the
       lines on it (inside each 2-face), or +- the vector in the plane
       perpendicular to its one line;
     - beside each such point, one point on either side of the plane (see
       arc_point: every 3-face).
   Coincident planes count once.  With t touching fixels, O(t^2) points
   found in O(t^2 log t) comparisons, each mapped to its string in O(n):
   never the 4^t strings.  Returns WC_OK or WC_EINTERNAL.  */
static int
moving_faces(string_set * out, const stab_cert * S, mpq_t * J)
{
    arrangement A;
    ray_order R;
    mpz_t * x = NULL, * m = NULL, * w = NULL, K, t;
    size_t * idx = NULL, * tmp = NULL;
    size_t i, k, p, nr, maxr;
    int status = WC_OK;

    memset(&A, 0, sizeof A);
    memset(&R, 0, sizeof R);
    A.n = S->n;
    A.near = S->near;
    A.out = out;
    for (i = 0; i < S->n; i++)
        if (!S->near[i])
            A.nh += 2;
    if (A.nh == 0)
        return WC_OK;
    mpz_init(A.s);
    mpz_init(K);
    mpz_init(t);
    mpz_init(R.d);
    maxr = 2 * (A.nh - 1);
    A.h = zvec_new(times(3, A.nh));
    A.plane = alloc_array(A.nh, sizeof(size_t));
    A.buf = malloc(S->n + 1);
    R.ray = zvec_new(times(3, maxr));
    R.half = alloc_array(maxr, sizeof(int));
    R.cr = zvec_new(3);
    idx = alloc_array(maxr, sizeof(size_t));
    tmp = alloc_array(maxr, sizeof(size_t));
    x = zvec_new(3);
    m = zvec_new(3);
    w = zvec_new(3);
    if (A.h == NULL || A.plane == NULL || A.buf == NULL || R.ray == NULL
        || R.half == NULL || R.cr == NULL || idx == NULL || tmp == NULL
        || x == NULL || m == NULL || w == NULL)
    {
        status = WC_EINTERNAL;
        goto cleanup;
    }
    for (i = 0, k = 0; i < S->n; i++)
        if (!S->near[i])
        {
            primitive(A.h + 3 * k, J + 6 * i, t);
            primitive(A.h + 3 * k + 3, J + 6 * i + 3, t);
            k += 2;
        }
    /* the distinct planes: normals not parallel to an earlier one */
    for (k = 0; k < A.nh; k++)
    {
        for (p = 0; p < A.np; p++)
        {
            zcross3(x, A.h + 3 * k, A.h + 3 * A.plane[p]);
            if (mpz_sgn(x[0]) == 0 && mpz_sgn(x[1]) == 0
                && mpz_sgn(x[2]) == 0)
                break;
        }
        if (p == A.np)
            A.plane[A.np++] = k;
    }
    for (p = 0; p < A.np; p++)
    {
        mpz_t * hp = A.h + 3 * A.plane[p];
        size_t q, nd;

        /* the lines on hp, both directions: ray 2 q + 1 = -ray 2 q */
        nr = 0;
        for (q = 0; q < A.np; q++)
        {
            mpz_t * r = R.ray + 3 * nr;

            if (q == p)
                continue;
            zcross3(r, hp, A.h + 3 * A.plane[q]);
            mpz_neg(r[3], r[0]);
            mpz_neg(r[4], r[1]);
            mpz_neg(r[5], r[2]);
            nr += 2;
        }
        if (nr == 0)
            continue;       /* one plane: never, J_in and J_it differ */
        /* angles from ray 0 towards w = hp x ray 0 */
        zcross3(w, hp, R.ray);
        for (q = 0; q < nr; q++)
        {
            int sw, su;

            zdot3(A.s, R.ray + 3 * q, w);
            sw = mpz_sgn(A.s);
            zdot3(A.s, R.ray + 3 * q, R.ray);
            su = mpz_sgn(A.s);
            R.half[q] = sw > 0 || (sw == 0 && su > 0) ? 0 : 1;
            idx[q] = q;
        }
        R.hp = hp;
        sort_rays(&R, idx, tmp, nr);
        /* the distinct rays, in order */
        nd = 1;
        for (q = 1; q < nr; q++)
            if (ray_cmp(&R, idx[nd - 1], idx[q]) != 0)
                idx[nd++] = idx[q];
        for (q = 0; q < nd; q++)
            candidate(&A, R.ray + 3 * idx[q]);
        if (nd == 2)
        {
            /* one line: the two half-planes */
            zcross3(m, hp, R.ray + 3 * idx[0]);
            arc_point(&A, m, hp, x, K);
            for (i = 0; i < 3; i++)
                mpz_neg(m[i], m[i]);
            arc_point(&A, m, hp, x, K);
        }
        else
            /* two lines or more: consecutive rays are less than pi
               apart, so their sum lies inside the sector between them */
            for (q = 0; q < nd; q++)
            {
                mpz_t * a = R.ray + 3 * idx[q];
                mpz_t * b = R.ray + 3 * idx[(q + 1) % nd];

                for (i = 0; i < 3; i++)
                    mpz_add(m[i], a[i], b[i]);
                arc_point(&A, m, hp, x, K);
            }
        if (out->oom)
            break;
    }
    sset_finish(out);
    if (out->oom)
        status = WC_EINTERNAL;
cleanup:
    zvec_free(A.h, 3 * A.nh);
    free(A.plane);
    free(A.buf);
    zvec_free(R.ray, 3 * maxr);
    free(R.half);
    zvec_free(R.cr, 3);
    free(idx);
    free(tmp);
    zvec_free(x, 3);
    zvec_free(m, 3);
    zvec_free(w, 3);
    mpz_clear(A.s);
    mpz_clear(K);
    mpz_clear(t);
    mpz_clear(R.d);
    return status;
}

/* ------------------------------------------------------------------ */
/* Strong stability: the check.                                        */

/* r = a . b (3 entries); t scratch.  */
static void
qdot3(mpq_t r, mpq_t * a, mpq_t * b, mpq_t t)
{
    mpq_mul(r, a[0], b[0]);
    mpq_mul(t, a[1], b[1]);
    mpq_add(r, r, t);
    mpq_mul(t, a[2], b[2]);
    mpq_add(r, r, t);
}

/* r += a b; t scratch.  */
static void
qaddmul(mpq_t r, const mpq_t a, const mpq_t b, mpq_t t)
{
    mpq_mul(t, a, b);
    mpq_add(r, r, t);
}

static int
qvec_is_zero(mpq_t * v, size_t n)
{
    size_t i;

    for (i = 0; i < n; i++)
        if (mpq_sgn(v[i]) != 0)
            return 0;
    return 1;
}

static int
qvec_equal(mpq_t * a, mpq_t * b, size_t n)
{
    size_t i;

    for (i = 0; i < n; i++)
        if (!mpq_equal(a[i], b[i]))
            return 0;
    return 1;
}

/* The scratch of the check.  */
typedef struct
{
    const stab_cert * S;
    mpq_t * J;          /* 6 n: J_in, J_it of every fixel */
    mpq_t * s;          /* 3 */
    mpq_t a, b, t;
    text_buf * why;
}
stab_check;

/* Names of the quantities of fixel i (0-based) in messages.  */
typedef struct
{
    char an[32], at[32], cn[32], ct[32];
}
fixel_names;

static void
names_of(fixel_names * N, size_t i)
{
    unsigned long k = (unsigned long) i + 1;

    sprintf(N->an, "a_%lun", k);
    sprintf(N->at, "a_%lut", k);
    sprintf(N->cn, "c_%lun", k);
    sprintf(N->ct, "c_%lut", k);
}

/* The weak claim: static forces, or a separator.  1 or 0.  */
static int
check_weak(stab_check * X)
{
    const stab_cert * S = X->S;
    text_buf * why = X->why;
    size_t n = S->n, i;
    int j;

    if (!S->weak)
    {
        mpq_t * y = S->sep;
        int e;

        qdot3(X->a, y, S->g, X->t);
        if (mpq_sgn(X->a) <= 0)
        {
            tb_add(why, "the separator y = ");
            tb_qvec(why, y, 3);
            tb_add(why, " has y . g = ");
            tb_q(why, X->a);
            tb_add(why, ", not > 0");
            return 0;
        }
        for (i = 0; i < n; i++)
        {
            if (S->near[i])
                continue;
            /* y . (J_in -+ mu_s J_it) */
            qdot3(X->a, y, X->J + 6 * i, X->t);
            qdot3(X->b, y, X->J + 6 * i + 3, X->t);
            mpq_mul(X->b, X->b, S->fixel[6 * i + 4]);
            for (e = -1; e <= 1; e += 2)
            {
                if (e < 0)
                    mpq_sub(X->t, X->a, X->b);
                else
                    mpq_add(X->t, X->a, X->b);
                if (mpq_sgn(X->t) < 0)
                {
                    tb_add(why, "the separator y = ");
                    tb_qvec(why, y, 3);
                    tb_addf(why, " has y . (J_%lun %c mu_s J_%lut) = ",
                            (unsigned long) i + 1, e < 0 ? '-' : '+',
                            (unsigned long) i + 1);
                    tb_q(why, X->t);
                    tb_add(why, ", not >= 0");
                    return 0;
                }
            }
        }
        return 1;
    }
    for (j = 0; j < 3; j++)
        mpq_set_ui(X->s[j], 0, 1);
    for (i = 0; i < n; i++)
    {
        mpq_t * cn = S->weak_c + i, * ct = S->weak_c + n + i;
        fixel_names N;

        names_of(&N, i);
        if (S->near[i] && (mpq_sgn(*cn) != 0 || mpq_sgn(*ct) != 0))
        {
            tb_addf(why, "the static forces load fixel %lu, which is near: "
                    "%s = ", (unsigned long) i + 1, N.cn);
            tb_q(why, *cn);
            tb_addf(why, ", %s = ", N.ct);
            tb_q(why, *ct);
            return 0;
        }
        if (mpq_sgn(*cn) < 0)
        {
            tb_addf(why, "the static force %s = ", N.cn);
            tb_q(why, *cn);
            tb_add(why, " is negative");
            return 0;
        }
        mpq_mul(X->a, S->fixel[6 * i + 4], *cn);
        mpq_abs(X->b, *ct);
        if (mpq_cmp(X->b, X->a) > 0)
        {
            tb_addf(why, "the static force at fixel %lu leaves its friction "
                    "cone: |%s| = ", (unsigned long) i + 1, N.ct);
            tb_q(why, X->b);
            tb_addf(why, " > mu_s %s = ", N.cn);
            tb_q(why, X->a);
            return 0;
        }
        for (j = 0; j < 3; j++)
        {
            qaddmul(X->s[j], *cn, X->J[6 * i + j], X->t);
            qaddmul(X->s[j], *ct, X->J[6 * i + 3 + j], X->t);
        }
    }
    for (j = 0; j < 3; j++)
        mpq_neg(X->s[j], X->s[j]);
    if (!qvec_equal(X->s, S->g, 3))
    {
        tb_add(why, "the static forces give -J c = ");
        tb_qvec(why, X->s, 3);
        tb_add(why, ", not the wrench ");
        tb_qvec(why, S->g, 3);
        return 0;
    }
    return 1;
}

/* "the motion's letter l at fixel 1 needs " */
static void
motion_needs(text_buf * why, char l, size_t i)
{
    tb_addf(why, "the motion's letter %c at fixel %lu needs ", l,
            (unsigned long) i + 1);
}

/* The motion: a moving solution in the mode of its sign.  1 or 0.  */
static int
check_motion(stab_check * X)
{
    const stab_cert * S = X->S;
    text_buf * why = X->why;
    mpq_t * nu = S->nudot, * c = S->motion_c;
    mpq_t Mnu[3];
    const char * sign = S->motion_sign->text;
    size_t n = S->n, i;
    int j, holds = 0;

    for (j = 0; j < 3; j++)
        mpq_init(Mnu[j]);
    if (qvec_is_zero(nu, 3))
    {
        tb_add(why, "the motion has nudot = 0");
        goto done;
    }
    for (j = 0; j < 3; j++)
        mpq_set(X->s[j], S->g[j]);
    for (i = 0; i < n; i++)
    {
        fixel_names N;

        names_of(&N, i);
        if (S->near[i] && (mpq_sgn(c[i]) != 0 || mpq_sgn(c[n + i]) != 0))
        {
            tb_addf(why, "the motion loads fixel %lu, which is near: %s = ",
                    (unsigned long) i + 1, N.cn);
            tb_q(why, c[i]);
            tb_addf(why, ", %s = ", N.ct);
            tb_q(why, c[n + i]);
            goto done;
        }
        for (j = 0; j < 3; j++)
        {
            qaddmul(X->s[j], c[i], X->J[6 * i + j], X->t);
            qaddmul(X->s[j], c[n + i], X->J[6 * i + 3 + j], X->t);
        }
    }
    mpq_mul(Mnu[0], S->body[0], nu[0]);
    mpq_mul(Mnu[1], S->body[0], nu[1]);
    mpq_mul(Mnu[2], S->body[1], nu[2]);
    if (!qvec_equal(Mnu, X->s, 3))
    {
        tb_add(why, "the motion has M nudot = ");
        tb_qvec(why, Mnu, 3);
        tb_add(why, ", but J c + g = ");
        tb_qvec(why, X->s, 3);
        goto done;
    }
    for (i = 0; i < n; i++)
    {
        mpq_t * cn = c + i, * ct = c + n + i, * mu = S->fixel + 6 * i + 4;
        char l = sign[i];
        fixel_names N;
        int sn, st;

        if (S->near[i])
            continue;
        names_of(&N, i);
        qdot3(X->a, X->J + 6 * i, nu, X->t);
        qdot3(X->b, X->J + 6 * i + 3, nu, X->t);
        sn = mpq_sgn(X->a);
        st = mpq_sgn(X->b);
        if (l == 's' ? sn <= 0 : sn != 0)
        {
            motion_needs(why, l, i);
            tb_addf(why, "%s %s 0, but %s = ", N.an, l == 's' ? ">" : "=",
                    N.an);
            tb_q(why, X->a);
            goto done;
        }
        if (l == 's')
        {
            if (mpq_sgn(*cn) != 0 || mpq_sgn(*ct) != 0)
            {
                motion_needs(why, l, i);
                tb_addf(why, "no force, but %s = ", N.cn);
                tb_q(why, *cn);
                tb_addf(why, ", %s = ", N.ct);
                tb_q(why, *ct);
                goto done;
            }
            continue;
        }
        if (l == 'l' ? st <= 0 : l == 'r' ? st >= 0 : st != 0)
        {
            motion_needs(why, l, i);
            tb_addf(why, "%s %s 0, but %s = ", N.at,
                    l == 'l' ? ">" : l == 'r' ? "<" : "=", N.at);
            tb_q(why, X->b);
            goto done;
        }
        if (mpq_sgn(*cn) < 0)
        {
            motion_needs(why, l, i);
            tb_addf(why, "%s >= 0, but %s = ", N.cn, N.cn);
            tb_q(why, *cn);
            goto done;
        }
        if (l == 'n')
        {
            mpq_mul(X->a, mu[0], *cn);
            mpq_abs(X->b, *ct);
            if (mpq_cmp(X->b, X->a) > 0)
            {
                motion_needs(why, l, i);
                tb_addf(why, "|%s| <= mu_s %s = ", N.ct, N.cn);
                tb_q(why, X->a);
                tb_addf(why, ", but %s = ", N.ct);
                tb_q(why, *ct);
                goto done;
            }
            continue;
        }
        /* l: c_it = -mu_k c_in; r: c_it = mu_k c_in */
        mpq_mul(X->a, mu[1], *cn);
        if (l == 'l')
            mpq_neg(X->a, X->a);
        if (!mpq_equal(*ct, X->a))
        {
            motion_needs(why, l, i);
            tb_addf(why, "%s = %smu_k %s = ", N.ct, l == 'l' ? "-" : "",
                    N.cn);
            tb_q(why, X->a);
            tb_addf(why, ", but %s = ", N.ct);
            tb_q(why, *ct);
            goto done;
        }
    }
    holds = 1;
done:
    for (j = 0; j < 3; j++)
        mpq_clear(Mnu[j]);
    return holds;
}

/* "face 3 (ls)" or "face 3 (n, rotation -1)" */
static void
tb_face(text_buf * b, size_t k, const char * sign, int rotation)
{
    char * shown = _wc_json_show(sign, strlen(sign));

    if (shown == NULL)
    {
        b->oom = 1;
        return;
    }
    tb_addf(b, "face %lu (%s", (unsigned long) k + 1, shown);
    if (rotation != 0)
        tb_addf(b, ", rotation %d", rotation);
    tb_add(b, ")");
    free(shown);
}

/* The Motzkin multipliers of face F (number k, 0-based) for the system of
   verify.h.  1 or 0; -1 when out of memory.  */
static int
check_face(stab_check * X, size_t k, const stab_face * F)
{
    const stab_cert * S = X->S;
    text_buf * why = X->why;
    const char * sign = F->sign->text;
    size_t n = S->n, i, e = 0, rows = 3, D, r, j, first = n;
    mpq_t * w = NULL, * s = NULL, * y = F->mult, * Ji;
    relation * rel = NULL;
    int holds = 0, c;

    /* the sizes: e friction edges, rows rows, D unknowns */
    for (i = 0; i < n; i++)
    {
        char l = F->rotation != 0 ? 'n' : sign[i];

        if (S->near[i])
            continue;
        if (first == n)
            first = i;
        e += l == 'n' ? 2 : l == 's' ? 0 : 1;
        rows += l == 's' ? 1 : 2;
    }
    if (F->rotation != 0)
        rows += 1;
    rows += e + 1;
    D = 3 + e + 1;
    if (F->nmult != rows)
    {
        tb_face(why, k, sign, F->rotation);
        tb_addf(why, ": there %s %lu multiplier%s for %lu rows",
                F->nmult == 1 ? "is" : "are", (unsigned long) F->nmult,
                F->nmult == 1 ? "" : "s", (unsigned long) rows);
        return why->oom ? -1 : 0;
    }
    w = qvec_new(times(3, e));
    s = qvec_new(D);
    rel = alloc_array(rows, sizeof(relation));
    if (w == NULL || s == NULL || rel == NULL)
    {
        holds = -1;
        goto cleanup;
    }
    /* the friction edges (1, et), in fixel order: w_j = J_in + et J_it */
    for (i = 0, j = 0; i < n; i++)
    {
        mpq_t * mu = S->fixel + 6 * i + 4;
        char l = F->rotation != 0 ? 'n' : sign[i];
        int m, ne = l == 'n' ? 2 : l == 's' ? 0 : 1;

        if (S->near[i])
            continue;
        Ji = X->J + 6 * i;
        for (m = 0; m < ne; m++, j++)
        {
            /* n: (1, -mu_s) then (1, +mu_s); l: (1, -mu_k); r: (1, +mu_k) */
            mpq_set(X->a, mu[l == 'n' ? 0 : 1]);
            if (l == 'l' || (l == 'n' && m == 0))
                mpq_neg(X->a, X->a);
            for (c = 0; c < 3; c++)
            {
                mpq_mul(w[3 * j + c], X->a, Ji[3 + c]);
                mpq_add(w[3 * j + c], w[3 * j + c], Ji[c]);
            }
        }
    }
    /* the rows, multiplied by their multipliers, summed into s */
    for (c = 0; c < 3; c++)
    {
        rel[c] = REL_EQ;
        mpq_mul(X->t, y[c], S->body[c < 2 ? 0 : 1]);
        mpq_add(s[c], s[c], X->t);
        for (j = 0; j < e; j++)
        {
            mpq_mul(X->t, y[c], w[3 * j + c]);
            mpq_sub(s[3 + j], s[3 + j], X->t);
        }
        mpq_mul(X->t, y[c], S->g[c]);
        mpq_sub(s[D - 1], s[D - 1], X->t);
    }
    r = 3;
    for (i = 0; i < n; i++)
    {
        char l = F->rotation != 0 ? 'n' : sign[i];

        if (S->near[i])
            continue;
        Ji = X->J + 6 * i;
        /* the normal row: J_in . nudot > 0 (s) or = 0 */
        rel[r] = l == 's' ? REL_GT : REL_EQ;
        for (c = 0; c < 3; c++)
            qaddmul(s[c], y[r], Ji[c], X->t);
        r++;
        if (l == 's')
            continue;
        /* the tangential row: J_it . nudot > 0 (l), -J_it . nudot > 0
           (r), J_it . nudot = 0 (n) */
        rel[r] = l == 'n' ? REL_EQ : REL_GT;
        for (c = 0; c < 3; c++)
        {
            mpq_mul(X->t, y[r], Ji[3 + c]);
            if (l == 'r')
                mpq_sub(s[c], s[c], X->t);
            else
                mpq_add(s[c], s[c], X->t);
        }
        r++;
    }
    if (F->rotation != 0)
    {
        /* (rho v) . nudot > 0, v = J_1n x J_1t of the first touching
           fixel */
        mpq_t * J1 = X->J + 6 * first;

        rel[r] = REL_GT;
        for (c = 0; c < 3; c++)
        {
            int c1 = (c + 1) % 3, c2 = (c + 2) % 3;

            mpq_mul(X->a, J1[c1], J1[3 + c2]);
            mpq_mul(X->b, J1[c2], J1[3 + c1]);
            mpq_sub(X->a, X->a, X->b);
            if (F->rotation < 0)
                mpq_neg(X->a, X->a);
            qaddmul(s[c], y[r], X->a, X->t);
        }
        r++;
    }
    for (j = 0; j < e; j++, r++)
    {
        rel[r] = REL_GE;
        mpq_add(s[3 + j], s[3 + j], y[r]);
    }
    rel[r] = REL_GT;
    mpq_add(s[D - 1], s[D - 1], y[r]);
    for (r = 0; r < rows; r++)
        if (rel[r] != REL_EQ && mpq_sgn(y[r]) < 0)
        {
            tb_face(why, k, sign, F->rotation);
            tb_addf(why, ": multiplier %lu is ", (unsigned long) r + 1);
            tb_q(why, y[r]);
            tb_addf(why, ", negative on a '%s' row", rel_name[rel[r]]);
            goto cleanup;
        }
    if (!qvec_is_zero(s, D))
    {
        tb_face(why, k, sign, F->rotation);
        tb_add(why, ": the multipliers combine the rows to ");
        tb_qvec(why, s, D);
        tb_add(why, ", not to zero");
        goto cleanup;
    }
    for (r = 0; r < rows; r++)
        if (rel[r] == REL_GT && mpq_sgn(y[r]) > 0)
            break;
    if (r == rows)
    {
        tb_face(why, k, sign, F->rotation);
        tb_add(why, ": no '>' row has a positive multiplier");
        goto cleanup;
    }
    holds = 1;
cleanup:
    qvec_free(w, 3 * e);
    qvec_free(s, D);
    free(rel);
    if (why->oom)
        holds = -1;
    return holds;
}

/* 1 when every touching fixel has the point of the first one (and there
   is one).  */
static int
shared_point(const stab_cert * S)
{
    size_t i, first = S->n;

    for (i = 0; i < S->n; i++)
    {
        mpq_t * p = S->fixel + 6 * i;

        if (S->near[i])
            continue;
        if (first == S->n)
            first = i;
        else if (!mpq_equal(p[0], S->fixel[6 * first])
                 || !mpq_equal(p[1], S->fixel[6 * first + 1]))
            return 0;
    }
    return first < S->n;
}

/* The faces: exactly the moving faces, each once, each without a
   solution.  1 or 0; -1 when out of memory.  */
static int
check_faces(stab_check * X)
{
    const stab_cert * S = X->S;
    text_buf * why = X->why;
    string_set T = { 0, 0, NULL, 0 };
    size_t * seen = NULL, rot_seen[2] = { 0, 0 }, k;
    int shared = shared_point(S), holds = 0;
    char * nn = NULL;

    if (moving_faces(&T, S, X->J) != WC_OK)
    {
        holds = -1;
        goto cleanup;
    }
    seen = alloc_array(T.count, sizeof(size_t));
    if (seen == NULL)
    {
        holds = -1;
        goto cleanup;
    }
    for (k = 0; k < T.count; k++)
        seen[k] = 0;
    for (k = 0; k < S->nfaces; k++)
    {
        const stab_face * F = S->faces + k;
        const char * sign = F->sign->text;
        size_t * mark;
        long at;

        if (F->rotation != 0)
        {
            if (!shared)
            {
                tb_face(why, k, sign, F->rotation);
                tb_add(why, " is not a moving face: the touching fixels do "
                       "not share one point");
                goto cleanup;
            }
            mark = rot_seen + (F->rotation > 0 ? 0 : 1);
        }
        else
        {
            at = sset_find(&T, sign);
            if (at < 0)
            {
                tb_face(why, k, sign, 0);
                tb_add(why, " is not a moving face of the problem");
                goto cleanup;
            }
            mark = seen + at;
        }
        if (*mark != 0)
        {
            tb_face(why, k, sign, F->rotation);
            tb_addf(why, " repeats face %lu", (unsigned long) *mark);
            goto cleanup;
        }
        *mark = k + 1;
    }
    for (k = 0; k < T.count; k++)
        if (seen[k] == 0)
        {
            tb_addf(why, "the faces omit the moving face %s", T.s[k]);
            goto cleanup;
        }
    for (k = 0; shared && k < 2; k++)
        if (rot_seen[k] == 0)
        {
            size_t i;

            nn = malloc(S->n + 1);
            if (nn == NULL)
            {
                holds = -1;
                goto cleanup;
            }
            for (i = 0; i < S->n; i++)
                nn[i] = S->near[i] ? 'u' : 'n';
            nn[S->n] = '\0';
            tb_addf(why, "the faces omit the moving face %s, rotation %d",
                    nn, k == 0 ? 1 : -1);
            goto cleanup;
        }
    for (k = 0; k < S->nfaces; k++)
    {
        holds = check_face(X, k, S->faces + k);
        if (holds != 1)
            goto cleanup;
    }
    holds = 1;
cleanup:
    free(seen);
    free(nn);
    sset_clear(&T);
    if (why->oom)
        holds = -1;
    return holds;
}

/* What the certificate claims, into what.  */
static void
stability_summary(text_buf * what, const stab_cert * S)
{
    tb_add(what, "wrench ");
    tb_qvec(what, S->g, 3);
    if (S->strong)
        tb_addf(what, " is strongly stable: %lu moving face%s excluded",
                (unsigned long) S->nfaces, S->nfaces == 1 ? "" : "s");
    else if (S->weak)
        tb_addf(what, " is weakly stable but moves in mode %s",
                S->motion_sign->text);
    else
        tb_add(what, " is not weakly stable");
}

/* Decide whether the strong-stability certificate S (read without error)
   holds; when it does not, write why into why.  what receives what it
   claims.  Returns 1 or 0; -1 when out of memory.  */
static int
check_stability(text_buf * why, text_buf * what, const stab_cert * S)
{
    stab_check X;
    size_t i;
    int holds = -1;

    X.S = S;
    X.why = why;
    X.J = qvec_new(times(6, S->n));
    X.s = qvec_new(3);
    mpq_init(X.a);
    mpq_init(X.b);
    mpq_init(X.t);
    if (X.J == NULL || X.s == NULL)
        goto cleanup;
    for (i = 0; i < S->n; i++)
        jacobian(X.J + 6 * i, S->body + 2, S->fixel + 6 * i,
                 S->fixel + 6 * i + 2);
    stability_summary(what, S);
    holds = check_weak(&X);
    if (holds == 1 && S->strong && !S->weak)
    {
        tb_add(why, "strongly_stable is true but weakly_stable is false");
        holds = 0;
    }
    if (holds == 1 && S->weak && !S->strong)
        holds = check_motion(&X);
    if (holds == 1 && S->strong)
        holds = check_faces(&X);
cleanup:
    if (why->oom || what->oom)
        holds = -1;
    qvec_free(X.J, 6 * S->n);
    qvec_free(X.s, 3);
    mpq_clear(X.a);
    mpq_clear(X.b);
    mpq_clear(X.t);
    return holds;
}

/* ------------------------------------------------------------------ */
/* The entry points.                                                   */

/* Check the mode-feasibility certificate at root (its kind read).
   Returns the status; with WC_OK, *holds, why, *mode (malloc'd: the
   caller frees) and *feasible.  */
static int
verify_mode(checker * c, const wc_json_node * root, int * holds,
            text_buf * why, char ** mode, int * feasible)
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
        nomem(c);
        goto cleanup;
    }
    memcpy(m, C.mode_node->text, C.mode_node->len + 1);
    h = check(why, &C, m);
    if (h < 0)
    {
        nomem(c);
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

/* Check the strong-stability certificate at root (its kind read).
   Returns the status; with WC_OK, *holds, why and what.  */
static int
verify_stability(checker * c, const wc_json_node * root, int * holds,
                 text_buf * why, text_buf * what)
{
    stab_cert S;
    int h;

    stab_init(&S);
    read_stability(c, &S, root);
    if (c->status == WC_OK)
    {
        h = check_stability(why, what, &S);
        if (h < 0)
            nomem(c);
        else
            *holds = h;
    }
    stab_clear(&S);
    return c->status;
}

int
wc_verify_certificate(int * holds, char ** reason, char ** mode,
                      int * feasible, const char * text, size_t len,
                      const char * file, wc_error_t err)
{
    wc_json_t J;
    checker c;
    text_buf why = { NULL, 0, 0, 0 };
    char * m = NULL;
    cert_kind kind;
    int status, h = 0, feas = 0;

    *holds = 0;
    *reason = NULL;
    if (mode != NULL)
        *mode = NULL;
    if (feasible != NULL)
        *feasible = 0;
    _wc_json_init(J);
    status = _wc_json_parse(J, text, len, file, err);
    if (status != WC_OK)
        goto cleanup;
    c.file = file;
    c.err = err;
    c.status = WC_OK;
    if (read_kind(&c, &J->root, &kind) != WC_OK)
    {
        status = c.status;
        goto cleanup;
    }
    if (kind != KIND_MODE)
    {
        status = bad(&c, _wc_json_object_get(&J->root, "kind"), "expected "
                     "a mode-feasibility certificate, found kind '%s'",
                     KIND_STRONG);
        goto cleanup;
    }
    status = verify_mode(&c, &J->root, &h, &why, &m, &feas);
    if (status != WC_OK)
        goto cleanup;
    *holds = h;
    if (!h)
    {
        *reason = why.s;
        why.s = NULL;
    }
    if (feasible != NULL)
        *feasible = feas;
    if (mode != NULL)
    {
        *mode = m;
        m = NULL;
    }
cleanup:
    free(why.s);
    free(m);
    _wc_json_clear(J);
    return status;
}

int
wc_verify(int * holds, char ** reason, char ** summary, const char * text,
          size_t len, const char * file, wc_error_t err)
{
    wc_json_t J;
    checker c;
    text_buf why = { NULL, 0, 0, 0 }, what = { NULL, 0, 0, 0 };
    char * m = NULL;
    cert_kind kind;
    int status, h = 0, feas = 0;

    *holds = 0;
    *reason = NULL;
    *summary = NULL;
    _wc_json_init(J);
    status = _wc_json_parse(J, text, len, file, err);
    if (status != WC_OK)
        goto cleanup;
    c.file = file;
    c.err = err;
    c.status = WC_OK;
    if (read_kind(&c, &J->root, &kind) != WC_OK)
    {
        status = c.status;
        goto cleanup;
    }
    if (kind == KIND_MODE)
    {
        status = verify_mode(&c, &J->root, &h, &why, &m, &feas);
        if (status == WC_OK)
            tb_addf(&what, "mode %s is %s", m, feas ? "feasible"
                    : "infeasible");
    }
    else
        status = verify_stability(&c, &J->root, &h, &why, &what);
    if (status != WC_OK)
        goto cleanup;
    if (what.oom || what.s == NULL)
    {
        status = wc_error_set(err, WC_EINTERNAL, file, 0, 0,
                              "out of memory");
        goto cleanup;
    }
    *holds = h;
    if (!h)
    {
        *reason = why.s;
        why.s = NULL;
    }
    *summary = what.s;
    what.s = NULL;
cleanup:
    free(why.s);
    free(what.s);
    free(m);
    _wc_json_clear(J);
    return status;
}
