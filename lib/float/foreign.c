/* foreign.c -- reading a foreign cone: the representations it gives,
   the JSON reader, and the choice between JSON and cdd.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Numbers are read exactly, as the rationals they spell (compare.h).  */

#include <config.h>

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpq_vec.h>

#include "float/compare.h"
#include "float/foreign.h"
#include "float/angle.h"
#include "core/json.h"
#include "core/text.h"
#include "core/problem.h"
#include "exact/vec3.h"

static void
qv3_swap(fmpq * a, fmpq * b)
{
    fmpq_swap(a, b);
    fmpq_swap(a + 1, b + 1);
    fmpq_swap(a + 2, b + 2);
}

void
_wc_rowbuf_init(_wc_rowbuf * b)
{
    b->v = NULL;
    b->line = NULL;
    b->n = b->alloc = 0;
}

void
_wc_rowbuf_clear(_wc_rowbuf * b)
{
    if (b->v != NULL)
        _fmpq_vec_clear(b->v, 3 * b->alloc);
    flint_free(b->line);
    _wc_rowbuf_init(b);
}

void
_wc_rowbuf_push(_wc_rowbuf * b, fmpq * x, long line)
{
    if (b->n == b->alloc)
    {
        slong a = b->alloc ? 2 * b->alloc : 8, i;

        b->v = flint_realloc(b->v, sizeof(fmpq) * 3 * a);
        for (i = 3 * b->alloc; i < 3 * a; i++)
            fmpq_init(b->v + i);
        b->line = flint_realloc(b->line, sizeof(long) * a);
        b->alloc = a;
    }
    qv3_swap(b->v + 3 * b->n, x);
    b->line[b->n] = line;
    b->n++;
}

/* Move the rows into a matrix and a line array (b keeps zeros).  */
static void
rowbuf_take(fmpq_mat_t M, long ** lines, _wc_rowbuf * b)
{
    slong i;

    fmpq_mat_clear(M);
    fmpq_mat_init(M, b->n, 3);
    for (i = 0; i < b->n; i++)
        qv3_swap(WC_ROW(M, i), b->v + 3 * i);
    flint_free(*lines);
    *lines = flint_malloc(sizeof(long) * (b->n + 1));
    if (b->n > 0)
        memcpy(*lines, b->line, sizeof(long) * b->n);
}

static void
rep_init(wc_rep_struct * R, wc_rep_kind kind, long line)
{
    R->kind = kind;
    R->line = line;
    R->empty = 0;
    fmpq_mat_init(R->rows, 0, 3);
    fmpq_mat_init(R->lin, 0, 3);
    R->row_line = flint_malloc(sizeof(long));
    R->lin_line = flint_malloc(sizeof(long));
}

static void
rep_clear(wc_rep_struct * R)
{
    fmpq_mat_clear(R->rows);
    fmpq_mat_clear(R->lin);
    flint_free(R->row_line);
    flint_free(R->lin_line);
}

void
wc_foreign_init(wc_foreign_t F)
{
    F->json = 0;
    F->arith_double = 0;
    F->mode = NULL;
    F->nreps = 0;
}

void
wc_foreign_clear(wc_foreign_t F)
{
    slong i;

    for (i = 0; i < F->nreps; i++)
        rep_clear(F->reps + i);
    free(F->mode);
    wc_foreign_init(F);
}

/* Add a representation built from the buffers.  */
void
_wc_foreign_add_rep(wc_foreign_t F, wc_rep_kind kind, long line, int empty,
                    _wc_rowbuf * rows, _wc_rowbuf * lin)
{
    wc_rep_struct * R = F->reps + F->nreps++;

    rep_init(R, kind, line);
    R->empty = empty;
    if (rows != NULL)
        rowbuf_take(R->rows, &R->row_line, rows);
    if (lin != NULL)
        rowbuf_take(R->lin, &R->lin_line, lin);
}

int
_wc_located(const _wc_source * s, long line, long col, const char * fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    wc_error_vset(s->err, WC_EINPUT, s->file, line, col, fmt, ap);
    va_end(ap);
    return WC_EINPUT;
}

/* _wc_located() with a message quoting t[0..n) (fmt has one %s).  */
int
_wc_located_quoting(const _wc_source * s, long line, long col,
                    const char * fmt, const char * t, size_t n)
{
    char * q = _wc_show(t, n);

    if (q == NULL)
        return wc_error_set(s->err, WC_EINTERNAL, s->file, 0, 0,
                            "out of memory");
    _wc_located(s, line, col, fmt, q);
    free(q);
    return WC_EINPUT;
}

/* ---- numbers ---- */

/* The fast reading of a plain decimal: [sign] digits [. digits]
   [e|E [sign] digits], the common case of a float code's output.  The
   digits go into machine words, 19 at a time, and the value D 10^E
   (D without its trailing zeros) is set in lowest terms without a gcd:
   D is not a multiple of 10, so gcd(D, 10^k) is the power of 2 or the
   power of 5 that D and 10^k share.  Returns 1 with x set, or 0 with x
   untouched when t[0..n) is anything else (an exponent over the bound, a
   fraction, bad syntax): the general reading below then decides, with
   its messages.  */

#define DIGITS_PER_WORD 19      /* 10^19 < 2^64 */

/* The decimal digits t[i..j) minus the dot at position dot (if inside),
   without leading zeros, into f.  */
static void
digits_value(fmpz_t f, const char * t, size_t i, size_t j, size_t dot)
{
    ulong w = 0, p = 1;
    int c = 0;

    fmpz_zero(f);
    for (; i < j; i++)
    {
        if (i == dot)
            continue;
        w = 10 * w + (ulong) (t[i] - '0');
        p *= 10;
        if (++c == DIGITS_PER_WORD)
        {
            fmpz_mul_ui(f, f, p);
            fmpz_add_ui(f, f, w);
            w = 0;
            p = 1;
            c = 0;
        }
    }
    if (fmpz_is_zero(f))
        fmpz_set_ui(f, w);
    else if (c > 0)
    {
        fmpz_mul_ui(f, f, p);
        fmpz_add_ui(f, f, w);
    }
}

/* num/den := D / 10^k in lowest terms, D > 0 not a multiple of 10.  */
static void
over_power_of_ten(fmpz_t num, fmpz_t den, ulong k)
{
    ulong a = 0, b = 0;

    if (fmpz_is_even(num))
    {
        a = fmpz_val2(num);
        if (a > k)
            a = k;
        fmpz_fdiv_q_2exp(num, num, a);
    }
    else
        while (b < k && fmpz_divisible_si(num, 5))
        {
            fmpz_divexact_ui(num, num, 5);
            b++;
        }
    if (k - b <= 27)                    /* 5^27 < 2^63 */
    {
        ulong p = 1, j;

        for (j = 0; j < k - b; j++)
            p *= 5;
        fmpz_set_ui(den, p);
    }
    else
    {
        fmpz_set_ui(den, 5);
        fmpz_pow_ui(den, den, k - b);
    }
    fmpz_mul_2exp(den, den, k - a);
}

static int
fast_decimal(fmpq_t x, const char * t, size_t n)
{
    size_t i = 0, d0, d1, dot = n, first, last, nfrac = 0;
    ulong e = 0;
    slong E;
    int neg = 0, eneg = 0;

    if (i < n && (t[i] == '+' || t[i] == '-'))
        neg = t[i++] == '-';
    d0 = i;
    while (i < n && t[i] >= '0' && t[i] <= '9')
        i++;
    if (i < n && t[i] == '.')
    {
        dot = i++;
        while (i < n && t[i] >= '0' && t[i] <= '9')
            i++;
        nfrac = i - dot - 1;
    }
    d1 = i;
    if (d1 - d0 == (dot < n ? 1 : 0))
        return 0;                       /* no digit */
    if (i < n && (t[i] == 'e' || t[i] == 'E'))
    {
        size_t e0;

        if (++i < n && (t[i] == '+' || t[i] == '-'))
            eneg = t[i++] == '-';
        for (e0 = i; i < n && t[i] >= '0' && t[i] <= '9'; i++)
            if ((e = 10 * e + (ulong) (t[i] - '0')) > WC_FOREIGN_MAX_EXPONENT)
                return 0;
        if (i == e0)
            return 0;
    }
    if (i != n)
        return 0;
    /* the significant digits t[first..last), skipping the dot */
    for (first = d0; first < d1 && (t[first] == '0' || first == dot); first++)
        ;
    if (first == d1)
    {
        fmpq_zero(x);
        return 1;
    }
    E = (eneg ? -(slong) e : (slong) e) - (slong) nfrac;
    for (last = d1; t[last - 1] == '0' || last - 1 == dot; last--)
        if (last - 1 != dot)
            E++;
    digits_value(fmpq_numref(x), t, first, last, dot);
    if (E >= 0)
    {
        fmpz_one(fmpq_denref(x));
        if (E > 0)
        {
            fmpz_set_ui(fmpq_denref(x), 10);
            fmpz_pow_ui(fmpq_denref(x), fmpq_denref(x), (ulong) E);
            fmpz_mul(fmpq_numref(x), fmpq_numref(x), fmpq_denref(x));
            fmpz_one(fmpq_denref(x));
        }
    }
    else
        over_power_of_ten(fmpq_numref(x), fmpq_denref(x), (ulong) -E);
    if (neg)
        fmpz_neg(fmpq_numref(x), fmpq_numref(x));
    return 1;
}

/* An exact number spelt t[0..n), located at (line, col) on error.  */
int
_wc_foreign_number(fmpq_t x, const _wc_source * s, const char * t,
                   size_t n, long line, long col)
{
    size_t i, e = n;
    long ex = 0;
    int status;

    if (n > WC_FOREIGN_MAX_CHARS)
        return _wc_located(s, line, col, "number too long (over %d "
                           "characters)", WC_FOREIGN_MAX_CHARS);
    if (fast_decimal(x, t, n))
        return WC_OK;
    for (i = 0; i < n; i++)
        if (t[i] == 'e' || t[i] == 'E')
            e = i + 1;
    if (e < n && (t[e] == '+' || t[e] == '-'))
        e++;
    for (i = e; i < n && t[i] >= '0' && t[i] <= '9'; i++)
        if ((ex = 10 * ex + (t[i] - '0')) > WC_FOREIGN_MAX_EXPONENT)
            return _wc_located_quoting(s, line, col, "exponent out of "
                                       "range in '%s' (at most 1000 here)",
                                       t, n);
    status = wc_parse_number(x, t, n, s->err);

    if (status == WC_EINPUT)
    {
        /* relocate the message: wc_parse_number leaves the place to us */
        char * m = s->err->message;

        s->err->message = NULL;
        _wc_located(s, line, col, "%s", m != NULL ? m : "bad number");
        free(m);
    }
    return status;
}

/* ---- JSON ---- */

static int
at_node(const _wc_source * s, const wc_json_node * v, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int
at_node(const _wc_source * s, const wc_json_node * v, const char * fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    wc_error_vset(s->err, WC_EINPUT, s->file, v->line, v->col, fmt, ap);
    va_end(ap);
    return WC_EINPUT;
}

/* The vectors under key in cone object o, if the key is there.  */
static int
json_vectors(_wc_rowbuf * out, const wc_json_node ** present,
             const _wc_source * s, const wc_json_node * o, const char * key)
{
    const wc_json_node * a = _wc_json_object_get(o, key);
    fmpq * x = NULL;
    size_t i, j;
    int status = WC_OK;

    *present = a;
    if (a == NULL)
        return WC_OK;
    if (a->type != WC_JSON_ARRAY)
        return at_node(s, a, "'%s' must be an array", key);
    if (a->len > WC_FOREIGN_MAX_ROWS)
        return at_node(s, a, "too many rows in '%s': %lu (at most %d)", key,
                       (unsigned long) a->len, WC_FOREIGN_MAX_ROWS);
    x = _fmpq_vec_init(3);
    for (i = 0; i < a->len && status == WC_OK; i++)
    {
        const wc_json_node * e = a->items + i;

        if (e->type != WC_JSON_ARRAY || e->len != 3)
        {
            status = at_node(s, e, "each entry of '%s' must be an array of "
                             "3 numbers", key);
            break;
        }
        for (j = 0; j < 3 && status == WC_OK; j++)
        {
            const wc_json_node * v = e->items + j;

            if (v->type == WC_JSON_NUMBER || v->type == WC_JSON_STRING)
                status = _wc_foreign_number(x + j, s, v->text, v->len,
                                            v->line, v->col);
            else
                status = at_node(s, v, "expected a number, found %s",
                                 _wc_json_type_name(v->type));
        }
        if (status == WC_OK)
            _wc_rowbuf_push(out, x, e->line);
    }
    _fmpq_vec_clear(x, 3);
    return status;
}

/* "dim", "lineality_dim" and "faces" (as `wrenchcone cone --format=json`
   writes them) are not read: the dimensions and faces are computed from
   the data, and which faces a float cone includes cannot be trusted.  But
   when present they must be well formed, so that a file that states a
   nonsense is not taken silently: a dimension is a JSON number spelling
   an integer from 0 to 3 (a nonempty cone in R^3; an empty one is
   {"empty": true}), "faces" an array of objects whose "dim" is such a
   dimension, whose "included" is true or false, and whose "rays" are
   indices into the cone's "rays" (from 0).  */

/* x := the JSON number v (exactly), or a located error.  */
static int
json_exact(fmpq_t x, const _wc_source * s, const wc_json_node * v)
{
    return _wc_foreign_number(x, s, v->text, v->len, v->line, v->col);
}

/* v, the value of key, is a dimension (NULL: absent).  */
static int
json_dim(const _wc_source * s, const wc_json_node * v, const char * key)
{
    fmpq_t x;
    int status, ok;

    if (v == NULL)
        return WC_OK;
    if (v->type != WC_JSON_NUMBER)
        return at_node(s, v, "'%s' must be an integer from 0 to 3, found %s",
                       key, _wc_json_type_name(v->type));
    fmpq_init(x);
    status = json_exact(x, s, v);
    ok = fmpz_is_one(fmpq_denref(x)) && fmpq_sgn(x) >= 0
        && fmpz_cmp_si(fmpq_numref(x), 3) <= 0;
    fmpq_clear(x);
    if (status == WC_OK && !ok)
        status = at_node(s, v, "'%s' must be an integer from 0 to 3, not %s",
                         key, v->text);
    return status;
}

/* The ray indices r of a face; the cone has nrays rays (rays: its "rays",
   NULL when absent; empty: it is {"empty": true}).  */
static int
json_face_rays(const _wc_source * s, const wc_json_node * r, size_t nrays,
               const wc_json_node * rays, int empty)
{
    fmpq_t x;
    size_t i;
    int status = WC_OK;

    if (r->type != WC_JSON_ARRAY)
        return at_node(s, r, "a face's 'rays' must be an array");
    fmpq_init(x);
    for (i = 0; i < r->len && status == WC_OK; i++)
    {
        const wc_json_node * v = r->items + i;

        if (v->type != WC_JSON_NUMBER)
            status = at_node(s, v, "a face ray index must be an integer, "
                             "found %s", _wc_json_type_name(v->type));
        else if ((status = json_exact(x, s, v)) != WC_OK)
            break;
        else if (!fmpz_is_one(fmpq_denref(x)))
            status = at_node(s, v, "a face ray index must be an integer, "
                             "not %s", v->text);
        else if (fmpq_sgn(x) < 0 || fmpz_cmp_ui(fmpq_numref(x), (ulong) nrays) >= 0)
        {
            if (nrays == 0)
                status = at_node(s, v, "face ray index %s is out of range: "
                                 "%s", v->text, empty ? "the cone is empty"
                                 : rays == NULL ? "the cone has no 'rays'"
                                 : "'rays' is empty");
            else
                status = at_node(s, v, "face ray index %s is out of range: "
                                 "'rays' has %lu row%s (0 to %lu)", v->text,
                                 (unsigned long) nrays, nrays == 1 ? "" : "s",
                                 (unsigned long) nrays - 1);
        }
    }
    fmpq_clear(x);
    return status;
}

/* The keys of cone object c that are checked but not read (above).  */
static int
json_unread(const _wc_source * s, const wc_json_node * c,
            const wc_json_node * rays, int empty)
{
    const wc_json_node * faces = _wc_json_object_get(c, "faces");
    size_t nrays = empty || rays == NULL ? 0 : rays->len, f;
    int status;

    if ((status = json_dim(s, _wc_json_object_get(c, "dim"), "dim")) != WC_OK
        || (status = json_dim(s, _wc_json_object_get(c, "lineality_dim"),
                              "lineality_dim")) != WC_OK
        || faces == NULL)
        return status;
    if (faces->type != WC_JSON_ARRAY)
        return at_node(s, faces, "'faces' must be an array");
    for (f = 0; f < faces->len && status == WC_OK; f++)
    {
        const wc_json_node * o = faces->items + f, * v;

        if (o->type != WC_JSON_OBJECT)
            return at_node(s, o, "each entry of 'faces' must be an object");
        status = json_dim(s, _wc_json_object_get(o, "dim"), "dim");
        v = _wc_json_object_get(o, "included");
        if (status == WC_OK && v != NULL && v->type != WC_JSON_TRUE
            && v->type != WC_JSON_FALSE)
            status = at_node(s, v, "'included' must be true or false");
        v = _wc_json_object_get(o, "rays");
        if (status == WC_OK && v != NULL)
            status = json_face_rays(s, v, nrays, rays, empty);
    }
    return status;
}

static int
parse_json(wc_foreign_t F, const _wc_source * s)
{
    wc_json_t J;
    const wc_json_node * root, * c, * m, * e, * a, * rays, * lines, * ineqs,
        * eqs;
    _wc_rowbuf R, L, H, E;
    int status;

    _wc_json_init(J);
    _wc_rowbuf_init(&R);
    _wc_rowbuf_init(&L);
    _wc_rowbuf_init(&H);
    _wc_rowbuf_init(&E);
    status = _wc_json_parse(J, s->text, s->len, s->file, s->err);
    if (status != WC_OK)
        goto cleanup;
    root = c = &J->root;
    if (root->type != WC_JSON_OBJECT)
    {
        status = at_node(s, root, "expected a JSON object: a cone, or "
                         "{\"mode\": .., \"cone\": ..}");
        goto cleanup;
    }
    m = _wc_json_object_get(root, "mode");
    if ((a = _wc_json_object_get(root, "cone")) != NULL)
    {
        if (a->type != WC_JSON_OBJECT)
        {
            status = at_node(s, a, "'cone' must be an object");
            goto cleanup;
        }
        if (m != NULL && m->type != WC_JSON_STRING)
        {
            status = at_node(s, m, "'mode' must be a string");
            goto cleanup;
        }
        if (m != NULL)
        {
            F->mode = malloc(m->len + 1);
            if (F->mode == NULL)
            {
                status = wc_error_set(s->err, WC_EINTERNAL, s->file, 0, 0,
                                      "out of memory");
                goto cleanup;
            }
            memcpy(F->mode, m->text, m->len + 1);
        }
        c = a;
    }
    if ((e = _wc_json_object_get(c, "empty")) == NULL)
    {
        status = at_node(s, c, "missing key 'empty'");
        goto cleanup;
    }
    if (e->type != WC_JSON_TRUE && e->type != WC_JSON_FALSE)
    {
        status = at_node(s, e, "'empty' must be true or false");
        goto cleanup;
    }
    if ((a = _wc_json_object_get(c, "arith")) != NULL)
    {
        if (a->type != WC_JSON_STRING)
        {
            status = at_node(s, a, "'arith' must be a string");
            goto cleanup;
        }
        F->arith_double = strcmp(a->text, "double") == 0;
    }
    if (e->type == WC_JSON_TRUE)
    {
        status = json_unread(s, c, NULL, 1);
        if (status == WC_OK)
            _wc_foreign_add_rep(F, WC_REP_STATED, c->line, 1, NULL, NULL);
        goto cleanup;
    }
    if ((status = json_vectors(&R, &rays, s, c, "rays")) != WC_OK
        || (status = json_vectors(&L, &lines, s, c, "lines")) != WC_OK
        || (status = json_vectors(&H, &ineqs, s, c, "inequalities")) != WC_OK
        || (status = json_vectors(&E, &eqs, s, c, "equalities")) != WC_OK
        || (status = json_unread(s, c, rays, 0)) != WC_OK)
        goto cleanup;
    if (rays == NULL && lines == NULL && ineqs == NULL && eqs == NULL)
    {
        status = at_node(s, c, "a nonempty cone needs 'rays' or "
                         "'inequalities'");
        goto cleanup;
    }
    if (rays != NULL || lines != NULL)
        _wc_foreign_add_rep(F, WC_REP_GENERATORS,
                            rays != NULL ? rays->line : lines->line, 0, &R,
                            &L);
    if (ineqs != NULL || eqs != NULL)
        _wc_foreign_add_rep(F, WC_REP_INEQUALITIES,
                            ineqs != NULL ? ineqs->line : eqs->line, 0, &H,
                            &E);

cleanup:
    _wc_rowbuf_clear(&R);
    _wc_rowbuf_clear(&L);
    _wc_rowbuf_clear(&H);
    _wc_rowbuf_clear(&E);
    _wc_json_clear(J);
    return status;
}

int
wc_foreign_parse(wc_foreign_t F, const char * text, size_t len,
                 const char * file, wc_error_t err)
{
    _wc_source s;
    size_t i = 0;
    int status;

    s.text = text;
    s.len = len;
    s.file = file;
    s.err = err;
    wc_foreign_clear(F);
    while (i < len && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r'
                       || text[i] == '\n'))
        i++;
    if (i < len && (text[i] == '{' || text[i] == '['))
    {
        F->json = 1;
        status = parse_json(F, &s);
    }
    else
        status = _wc_foreign_parse_cdd(F, &s);
    if (status != WC_OK)
        wc_foreign_clear(F);
    return status;
}
