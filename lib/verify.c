/* verify.c -- re-check a mode-feasibility certificate with GMP alone.

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

#include "json.h"
#include "verify.h"

#define KIND "mode-feasibility"

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
    char * t = wc_json_show(s, len);

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
    const wc_json_node * x = wc_json_object_get(o, key);
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
                   wc_json_type_name(v->type));
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
                   wc_json_type_name(v->type));
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
    const wc_json_node * v = wc_json_object_get(o, key);

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
        nv = wc_json_object_get(f, "normal");
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

/* Read everything the check needs from the document; errors into c.  */
static void
read_certificate(checker * c, certificate * C, const wc_json_node * root)
{
    const wc_json_node * kind, * mode, * feas;
    int problem_ok;

    if (root->type != WC_JSON_OBJECT)
    {
        bad(c, root, "expected a certificate object, found %s",
            wc_json_type_name(root->type));
        return;
    }
    kind = wc_json_object_get(root, "kind");
    if (kind != NULL && kind->type != WC_JSON_STRING)
    {
        bad(c, kind, "'kind' must be a string");
        return;
    }
    /* another kind is another format: nothing else is worth reading */
    if (kind != NULL && (kind->len != strlen(KIND)
                         || memcmp(kind->text, KIND, kind->len) != 0))
    {
        bad_quoting(c, kind, "unknown certificate kind '%s'", kind->text,
                    kind->len);
        return;
    }
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

        /* J[0..3): (n_x, n_y, r x n); J[3..6): (t_x, t_y, r x t) with
           r = p - com, t = (-n_y, n_x); J[5] holds r_x until the end */
        mpq_sub(J[5], p[0], C->com[0]);
        mpq_sub(J[4], p[1], C->com[1]);
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
    char * shown = wc_json_show(mode, strlen(mode));  /* a long mode cut */

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

int
wc_verify_certificate(int * holds, char ** reason, char ** mode,
                      int * feasible, const char * text, size_t len,
                      const char * file, wc_error_t err)
{
    wc_json_t J;
    certificate C;
    checker c;
    text_buf why = { NULL, 0, 0, 0 };
    char * m = NULL;
    int status, h;

    *holds = 0;
    *reason = NULL;
    if (mode != NULL)
        *mode = NULL;
    if (feasible != NULL)
        *feasible = 0;
    wc_json_init(J);
    cert_init(&C);
    status = wc_json_parse(J, text, len, file, err);
    if (status != WC_OK)
        goto cleanup;
    c.file = file;
    c.err = err;
    c.status = WC_OK;
    read_certificate(&c, &C, &J->root);
    status = c.status;
    if (status != WC_OK)
        goto cleanup;
    /* checked: the mode is Table 1 letters, one per fixel, no NUL */
    m = malloc(C.mode_node->len + 1);
    if (m == NULL)
    {
        status = wc_error_set(err, WC_EINTERNAL, file, 0, 0,
                              "out of memory");
        goto cleanup;
    }
    memcpy(m, C.mode_node->text, C.mode_node->len + 1);
    h = check(&why, &C, m);
    if (h < 0)
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
    if (feasible != NULL)
        *feasible = C.feasible;
    if (mode != NULL)
    {
        *mode = m;
        m = NULL;
    }
cleanup:
    free(why.s);
    free(m);
    cert_clear(&C);
    wc_json_clear(J);
    return status;
}
