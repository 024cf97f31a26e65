/* problem.c -- the .wc problem file: parsing, printing, exact numbers.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   SPEC section 3.  The parser reads the file line by line with a lazy
   tokenizer, so the first error in file order is the one reported.  Checks
   that need the whole file (normals derived from a shape given later, two
   fixels alike, no fixel at all) run after the last line; when a line is
   bad they still run on the fixels before it, so an earlier fixel's error
   is not hidden by a later line's.  */

#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpz.h>

#include "core/problem.h"

/* The exponent of a decimal number is bounded so that "1e999999999"
   cannot make us build a gigantic power of ten.  */
#define WC_MAX_EXPONENT 100000

/* Tokens quoted in messages are cut after this many bytes.  */
#define WC_SHOW_MAX 64

static char *
dup_string(const char * s)
{
    size_t n = strlen(s) + 1;
    char * d = malloc(n);

    if (d != NULL)
        memcpy(d, s, n);
    return d;
}

/* A printable copy of s[0..len) for a message: control bytes as \xNN,
   cut after WC_SHOW_MAX bytes with "...".  NULL when out of memory.  */
static char *
show(const char * s, size_t len)
{
    size_t n = len < WC_SHOW_MAX ? len : WC_SHOW_MAX;
    char * d = malloc(4 * n + 4);
    size_t i, j = 0;

    if (d == NULL)
        return NULL;
    for (i = 0; i < n; i++)
    {
        unsigned char c = (unsigned char) s[i];

        if (c < 0x20 || c == 0x7f)
        {
            static const char hex[] = "0123456789abcdef";

            d[j++] = '\\';
            d[j++] = 'x';
            d[j++] = hex[c >> 4];
            d[j++] = hex[c & 15];
        }
        else
            d[j++] = (char) c;
    }
    if (n < len)
    {
        memcpy(d + j, "...", 3);
        j += 3;
    }
    d[j] = '\0';
    return d;
}

/* Set err to the message fmt with its one "%s" replaced by arg (fmt is
   split here rather than passed on, so it is never a non-literal format).  */
static int
error_with(wc_error_t err, int status, const char * file, long line,
           long col, const char * fmt, const char * arg)
{
    const char * p = strstr(fmt, "%s");

    return wc_error_set(err, status, file, line, col, "%.*s%s%s",
                        (int) (p - fmt), fmt, arg, p + 2);
}

/* Set err with a message whose one %s is the token s[0..len).  */
static int
error_token(wc_error_t err, int status, const char * file, long line,
            long col, const char * fmt, const char * s, size_t len)
{
    char * t = show(s, len);

    if (t == NULL)
        return wc_error_set(err, WC_EINTERNAL, file, 0, 0, "out of memory");
    error_with(err, status, file, line, col, fmt, t);
    free(t);
    return status;
}

/* ------------------------------------------------------------------ */
/* Problems.                                                           */

void
wc_problem_init(wc_problem_t P)
{
    P->file = NULL;
    P->name = NULL;
    fmpq_init(P->mass);
    fmpq_one(P->mass);
    fmpq_init(P->inertia);
    fmpq_one(P->inertia);
    fmpq_init(P->com + 0);
    fmpq_init(P->com + 1);
    fmpq_init(P->mu_s);
    fmpq_init(P->mu_k);
    P->shape = WC_SHAPE_NONE;
    P->shape_len = 0;
    P->shape_data = NULL;
    P->shape_line = 0;
    P->n = 0;
    P->fixels = NULL;
}

static void
fixel_clear(wc_fixel_struct * f)
{
    fmpq_clear(f->point + 0);
    fmpq_clear(f->point + 1);
    fmpq_clear(f->normal + 0);
    fmpq_clear(f->normal + 1);
    fmpq_clear(f->mu_s);
    fmpq_clear(f->mu_k);
}

void
wc_problem_clear(wc_problem_t P)
{
    slong i;

    free(P->file);
    free(P->name);
    fmpq_clear(P->mass);
    fmpq_clear(P->inertia);
    fmpq_clear(P->com + 0);
    fmpq_clear(P->com + 1);
    fmpq_clear(P->mu_s);
    fmpq_clear(P->mu_k);
    for (i = 0; i < P->shape_len; i++)
        fmpq_clear(P->shape_data + i);
    free(P->shape_data);
    for (i = 0; i < P->n; i++)
        fixel_clear(P->fixels + i);
    free(P->fixels);
    P->file = NULL;
    P->name = NULL;
    P->shape_data = NULL;
    P->shape_len = 0;
    P->fixels = NULL;
    P->n = 0;
}

/* The fixels array has no capacity field: its capacity is implied by n
   (0, then powers of two from 4), so appending costs amortised O(1).  */
static slong
fixel_capacity(slong n)
{
    slong c = 4;

    if (n == 0)
        return 0;
    while (c < n)
        c *= 2;
    return c;
}

wc_fixel_struct *
wc_problem_add_fixel(wc_problem_t P)
{
    wc_fixel_struct * f;
    slong cap = fixel_capacity(P->n);

    if (P->n == cap)
    {
        slong ncap = cap == 0 ? 4 : 2 * cap;
        wc_fixel_struct * a;

        if ((size_t) ncap > SIZE_MAX / sizeof(wc_fixel_struct))
            return NULL;
        a = realloc(P->fixels, (size_t) ncap * sizeof(wc_fixel_struct));
        if (a == NULL)
            return NULL;
        P->fixels = a;
    }
    f = P->fixels + P->n;
    fmpq_init(f->point + 0);
    fmpq_init(f->point + 1);
    fmpq_init(f->normal + 0);
    fmpq_init(f->normal + 1);
    fmpq_init(f->mu_s);
    fmpq_init(f->mu_k);
    fmpq_set(f->mu_s, P->mu_s);
    fmpq_set(f->mu_k, P->mu_k);
    f->state = WC_TOUCHING;
    f->line = 0;
    f->col = 0;
    P->n++;
    return f;
}

int
wc_problem_set(wc_problem_t Q, const wc_problem_t P)
{
    slong i;

    if (Q == P)
        return WC_OK;
    wc_problem_clear(Q);
    wc_problem_init(Q);
    if ((P->file != NULL && (Q->file = dup_string(P->file)) == NULL)
        || (P->name != NULL && (Q->name = dup_string(P->name)) == NULL))
        goto oom;
    fmpq_set(Q->mass, P->mass);
    fmpq_set(Q->inertia, P->inertia);
    fmpq_set(Q->com + 0, P->com + 0);
    fmpq_set(Q->com + 1, P->com + 1);
    fmpq_set(Q->mu_s, P->mu_s);
    fmpq_set(Q->mu_k, P->mu_k);
    Q->shape = P->shape;
    Q->shape_line = P->shape_line;
    if (P->shape_len > 0)
    {
        if ((Q->shape_data = malloc(sizeof(fmpq) * P->shape_len)) == NULL)
            goto oom;
        for (i = 0; i < P->shape_len; i++)
        {
            fmpq_init(Q->shape_data + i);
            fmpq_set(Q->shape_data + i, P->shape_data + i);
        }
        Q->shape_len = P->shape_len;
    }
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;
        wc_fixel_struct * g = wc_problem_add_fixel(Q);

        if (g == NULL)
            goto oom;
        fmpq_set(g->point + 0, f->point + 0);
        fmpq_set(g->point + 1, f->point + 1);
        fmpq_set(g->normal + 0, f->normal + 0);
        fmpq_set(g->normal + 1, f->normal + 1);
        fmpq_set(g->mu_s, f->mu_s);
        fmpq_set(g->mu_k, f->mu_k);
        g->state = f->state;
        g->line = f->line;
        g->col = f->col;
    }
    return WC_OK;

oom:
    wc_problem_clear(Q);
    wc_problem_init(Q);
    return WC_EINTERNAL;
}

/* ------------------------------------------------------------------ */
/* Numbers.                                                            */

static int
is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* f = the decimal digits s[a0..a1) followed by s[b0..b1); at least one
   digit in all.  */
static int
set_digits(fmpz_t f, const char * s, size_t a0, size_t a1, size_t b0,
           size_t b1)
{
    char * buf = malloc(a1 - a0 + b1 - b0 + 1);

    if (buf == NULL)
        return -1;
    memcpy(buf, s + a0, a1 - a0);
    memcpy(buf + (a1 - a0), s + b0, b1 - b0);
    buf[a1 - a0 + b1 - b0] = '\0';
    fmpz_set_str(f, buf, 10);
    free(buf);
    return 0;
}

/* The parts of a number as written: sign, the integer digits (or the
   numerator) s[a0..a1), the fraction digits (or the denominator) s[b0..b1),
   and the exponent.  */
typedef struct
{
    int neg;
    int fraction;       /* p/q rather than a decimal */
    size_t a0, a1, b0, b1;
    int eneg;
    unsigned long e;    /* saturates just above WC_MAX_EXPONENT */
}
wc_numparts;

/* Split s[0..len) into np: 0 when it is a number, 1 when it is not, 2
   when it is but its exponent is out of range.  */
static int
scan_number(wc_numparts * np, const char * s, size_t len)
{
    size_t i = 0, e0;

    memset(np, 0, sizeof *np);
    if (i < len && (s[i] == '+' || s[i] == '-'))
    {
        np->neg = s[i] == '-';
        i++;
    }
    np->a0 = i;
    while (i < len && is_digit(s[i]))
        i++;
    np->a1 = i;
    if (i < len && s[i] == '/')
    {
        np->fraction = 1;
        np->b0 = ++i;
        while (i < len && is_digit(s[i]))
            i++;
        np->b1 = i;
        return np->a1 == np->a0 || np->b1 == np->b0 || i != len;
    }
    if (i < len && s[i] == '.')
    {
        np->b0 = ++i;
        while (i < len && is_digit(s[i]))
            i++;
        np->b1 = i;
    }
    if (np->a1 == np->a0 && np->b1 == np->b0)
        return 1;
    if (i < len && (s[i] == 'e' || s[i] == 'E'))
    {
        i++;
        if (i < len && (s[i] == '+' || s[i] == '-'))
        {
            np->eneg = s[i] == '-';
            i++;
        }
        e0 = i;
        while (i < len && is_digit(s[i]))
        {
            /* saturate: any value above the bound is as bad */
            if (np->e <= WC_MAX_EXPONENT)
                np->e = 10 * np->e + (unsigned long) (s[i] - '0');
            i++;
        }
        if (i == e0)
            return 1;
    }
    if (i != len)
        return 1;
    return np->e > WC_MAX_EXPONENT ? 2 : 0;
}

int
wc_parse_number(fmpq_t x, const char * s, size_t len, wc_error_t err)
{
    wc_numparts np;
    fmpz_t num, den;
    size_t nfrac;
    int status = WC_OK;
    int r = scan_number(&np, s, len);

    if (r != 0)
        return error_token(err, WC_EINPUT, NULL, 0, 0, r == 1
                           ? "bad number '%s'"
                           : "exponent out of range in '%s'", s, len);
    fmpz_init(num);
    fmpz_init(den);
    if (np.fraction)
    {
        if (set_digits(num, s, np.a0, np.a1, 0, 0) != 0
            || set_digits(den, s, np.b0, np.b1, 0, 0) != 0)
        {
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "out of memory");
            goto cleanup;
        }
        if (fmpz_is_zero(den))
        {
            status = error_token(err, WC_EINPUT, NULL, 0, 0,
                                 "division by zero in '%s'", s, len);
            goto cleanup;
        }
    }
    else
    {
        if (set_digits(num, s, np.a0, np.a1, np.b0, np.b1) != 0)
        {
            status = wc_error_set(err, WC_EINTERNAL, NULL, 0, 0,
                                  "out of memory");
            goto cleanup;
        }
        /* value = digits * 10^(+-e - nfrac) */
        nfrac = np.b1 - np.b0;
        fmpz_set_ui(den, 10);
        if (np.eneg)
            fmpz_pow_ui(den, den, (ulong) (np.e + nfrac));
        else if (np.e >= nfrac)
        {
            fmpz_pow_ui(den, den, (ulong) (np.e - nfrac));
            fmpz_mul(num, num, den);
            fmpz_one(den);
        }
        else
            fmpz_pow_ui(den, den, (ulong) (nfrac - np.e));
    }
    if (np.neg)
        fmpz_neg(num, num);
    fmpq_set_fmpz_frac(x, num, den);
cleanup:
    fmpz_clear(num);
    fmpz_clear(den);
    return status;
}

/* ------------------------------------------------------------------ */
/* Exact plane geometry on points given as two consecutive fmpq.        */

/* sign of (b - a) x (c - a) */
static int
orient(const fmpq * a, const fmpq * b, const fmpq * c)
{
    fmpq_t r, u, w;
    int s;

    fmpq_init(r);
    fmpq_init(u);
    fmpq_init(w);
    fmpq_sub(u, b + 0, a + 0);
    fmpq_sub(w, c + 1, a + 1);
    fmpq_mul(r, u, w);
    fmpq_sub(u, b + 1, a + 1);
    fmpq_sub(w, c + 0, a + 0);
    fmpq_submul(r, u, w);
    s = fmpq_sgn(r);
    fmpq_clear(r);
    fmpq_clear(u);
    fmpq_clear(w);
    return s;
}

static int
point_equal(const fmpq * a, const fmpq * b)
{
    return fmpq_equal(a + 0, b + 0) && fmpq_equal(a + 1, b + 1);
}

/* p in the closed box spanned by a and b; with orient(a, b, p) == 0 this
   is p on the closed segment [a, b].  */
static int
in_box(const fmpq * p, const fmpq * a, const fmpq * b)
{
    int k;

    for (k = 0; k < 2; k++)
    {
        const fmpq * lo = a + k, * hi = b + k;

        if (fmpq_cmp(lo, hi) > 0)
        {
            lo = b + k;
            hi = a + k;
        }
        if (fmpq_cmp(p + k, lo) < 0 || fmpq_cmp(p + k, hi) > 0)
            return 0;
    }
    return 1;
}

/* 0: the closed segments [a, b] and [c, d] are disjoint; 1: they touch;
   2: they cross at one point interior to both.  */
static int
segments_meet(const fmpq * a, const fmpq * b, const fmpq * c, const fmpq * d)
{
    int d1 = orient(c, d, a), d2 = orient(c, d, b);
    int d3 = orient(a, b, c), d4 = orient(a, b, d);

    if (d1 * d2 < 0 && d3 * d4 < 0)
        return 2;
    if ((d1 == 0 && in_box(a, c, d)) || (d2 == 0 && in_box(b, c, d))
        || (d3 == 0 && in_box(c, a, b)) || (d4 == 0 && in_box(d, a, b)))
        return 1;
    return 0;
}

/* Twice the signed area of the polygon v[0..m), as a sign.  */
static int
polygon_orientation(const fmpq * v, slong m)
{
    fmpq_t s;
    slong k;
    int r;

    fmpq_init(s);
    for (k = 0; k < m; k++)
    {
        const fmpq * a = v + 2 * k, * b = v + 2 * ((k + 1) % m);

        fmpq_addmul(s, a + 0, b + 1);
        fmpq_submul(s, a + 1, b + 0);
    }
    r = fmpq_sgn(s);
    fmpq_clear(s);
    return r;
}

/* ------------------------------------------------------------------ */
/* The tokenizer.                                                      */

typedef struct
{
    const char * text;
    size_t len;
    const char * file;
    wc_error_struct * err;
    long line;
    size_t lstart;      /* offset of the current line */
    size_t lend;        /* end of its content (before any \r\n) */
    size_t pos;         /* cursor */
    size_t prev_end;    /* just after the last token read */
}
wc_lexer;

typedef struct
{
    size_t start;
    size_t end;
    long col;
    int quoted;
}
wc_token;

static long
lx_col(const wc_lexer * lx, size_t off)
{
    return (long) (off - lx->lstart) + 1;
}

static int
lx_error(wc_lexer * lx, long col, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int
lx_error(wc_lexer * lx, long col, const char * fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    wc_error_vset(lx->err, WC_EINPUT, lx->file, lx->line, col, fmt, ap);
    va_end(ap);
    return WC_EINPUT;
}

/* An error about a token; fmt has one %s, the token.  */
static int
lx_error_token(wc_lexer * lx, const wc_token * t, const char * fmt)
{
    return error_token(lx->err, WC_EINPUT, lx->file, lx->line, t->col, fmt,
                       lx->text + t->start, t->end - t->start);
}

/* A missing argument is located just after the previous token.  */
static int
lx_missing(wc_lexer * lx, const char * what)
{
    return lx_error(lx, lx_col(lx, lx->prev_end), "%s", what);
}

/* Read the next token of the line: 1 and *t set, 0 at the end of the line
   or at a comment, -1 with err set on an unterminated string.  */
static int
lx_next(wc_lexer * lx, wc_token * t)
{
    const char * s = lx->text;
    size_t i = lx->pos;

    while (i < lx->lend && (s[i] == ' ' || s[i] == '\t'))
        i++;
    lx->pos = i;
    if (i >= lx->lend || s[i] == '#')
        return 0;
    t->start = i;
    t->col = lx_col(lx, i);
    t->quoted = s[i] == '"';
    if (t->quoted)
    {
        for (i++; i < lx->lend && s[i] != '"'; i++)
            if (s[i] == '\\' && i + 1 < lx->lend)
                i++;
        if (i >= lx->lend)
        {
            lx_error(lx, t->col, "unterminated string");
            return -1;
        }
        i++;
    }
    else
        while (i < lx->lend && s[i] != ' ' && s[i] != '\t' && s[i] != '#')
            i++;
    t->end = i;
    lx->pos = i;
    lx->prev_end = i;
    return 1;
}

/* Like lx_next but leaves the cursor where it was.  */
static int
lx_peek(wc_lexer * lx, wc_token * t)
{
    size_t pos = lx->pos, prev = lx->prev_end;
    int r = lx_next(lx, t);

    lx->pos = pos;
    lx->prev_end = prev;
    return r;
}

static int
tok_is(const wc_lexer * lx, const wc_token * t, const char * word)
{
    size_t n = strlen(word);

    return t->end - t->start == n && memcmp(lx->text + t->start, word, n) == 0;
}

/* Could the token be meant as a number?  Decides whether a fixel's
   "friction MUS" is followed by MUK or by the next option.  */
static int
tok_numeric(const wc_lexer * lx, const wc_token * t)
{
    char c = lx->text[t->start];

    return is_digit(c) || c == '+' || c == '-' || c == '.';
}

static int
tok_number(wc_lexer * lx, const wc_token * t, fmpq_t x)
{
    int status = wc_parse_number(x, lx->text + t->start, t->end - t->start,
                                 lx->err);

    if (status == WC_EINPUT)
    {
        /* wc_error_set frees the old message before formatting, so take
           it out first */
        char * m = lx->err->message;

        lx->err->message = NULL;
        lx_error(lx, t->col, "%s", m != NULL ? m : "bad number");
        free(m);
    }
    return status;
}

/* Read a number; missing is the message when there is none.  */
static int
lx_number(wc_lexer * lx, fmpq_t x, wc_token * t, const char * missing)
{
    int r = lx_next(lx, t);

    if (r < 0)
        return WC_EINPUT;
    if (r == 0)
        return lx_missing(lx, missing);
    return tok_number(lx, t, x);
}

static int
lx_end(wc_lexer * lx)
{
    wc_token t = { 0, 0, 0, 0 };
    int r = lx_next(lx, &t);

    if (r < 0)
        return WC_EINPUT;
    if (r > 0)
        return lx_error_token(lx, &t, "unexpected token '%s'");
    return WC_OK;
}

/* ------------------------------------------------------------------ */
/* The parser.                                                         */

typedef struct
{
    long pcol;          /* column of the fixel's point */
    int has_normal;     /* given, or derived after the last line */
    int has_friction;
}
wc_fixinfo;

typedef struct
{
    wc_lexer lx;
    wc_problem_struct * P;
    wc_fixinfo * info;
    slong info_cap;
    long shape_col;
    int poly_orient;    /* +1 counter-clockwise, -1 clockwise */
    int seen_name, seen_mass, seen_inertia, seen_com, seen_friction;
    int seen_shape;
}
wc_parser;

static int
nomem(wc_parser * ps)
{
    return wc_error_set(ps->lx.err, WC_EINTERNAL, ps->lx.file, 0, 0,
                        "out of memory");
}

static int
check_nonneg(wc_parser * ps, const wc_token * t, const fmpq_t x)
{
    if (fmpq_sgn(x) < 0)
        return lx_error(&ps->lx, t->col, "friction must be non-negative");
    return WC_OK;
}

static int
parse_name(wc_parser * ps)
{
    wc_lexer * lx = &ps->lx;
    wc_token t = { 0, 0, 0, 0 };
    const char * s = lx->text;
    char * name = NULL;
    size_t i, j = 0;
    int r, status = WC_OK;

    r = lx_next(lx, &t);
    if (r < 0)
        return WC_EINPUT;
    if (r == 0)
        return lx_missing(lx, "'name' needs a quoted string");
    if (!t.quoted)
        return lx_error_token(lx, &t, "expected a quoted name, got '%s'");
    name = malloc(t.end - t.start);
    if (name == NULL)
        return nomem(ps);
    for (i = t.start + 1; i + 1 < t.end; i++)
    {
        if (s[i] == '\\')
        {
            if (s[i + 1] != '"' && s[i + 1] != '\\')
            {
                status = error_token(lx->err, WC_EINPUT, lx->file, lx->line,
                                     lx_col(lx, i), "bad escape '%s' in string",
                                     s + i, 2);
                goto cleanup;
            }
            i++;
        }
        else if (s[i] == '\0')
        {
            status = lx_error(lx, lx_col(lx, i), "NUL byte in string");
            goto cleanup;
        }
        name[j++] = s[i];
    }
    name[j] = '\0';
    status = lx_end(lx);
    if (status != WC_OK)
        goto cleanup;
    ps->P->name = name;
    name = NULL;
cleanup:
    free(name);
    return status;
}

/* mass or inertia */
static int
parse_positive(wc_parser * ps, fmpq_t x, const char * missing,
               const char * message)
{
    wc_token t = { 0, 0, 0, 0 };
    int status = lx_number(&ps->lx, x, &t, missing);

    if (status != WC_OK)
        return status;
    if (fmpq_sgn(x) <= 0)
        return lx_error(&ps->lx, t.col, "%s", message);
    return lx_end(&ps->lx);
}

static int
parse_com(wc_parser * ps)
{
    wc_token t = { 0, 0, 0, 0 };
    int status = lx_number(&ps->lx, ps->P->com + 0, &t,
                           "'com' needs 2 numbers");

    if (status == WC_OK)
        status = lx_number(&ps->lx, ps->P->com + 1, &t,
                           "'com' needs 2 numbers");
    if (status == WC_OK)
        status = lx_end(&ps->lx);
    return status;
}

static int
parse_friction(wc_parser * ps)
{
    wc_lexer * lx = &ps->lx;
    wc_token t = { 0, 0, 0, 0 };
    int r, status;

    status = lx_number(lx, ps->P->mu_s, &t, "'friction' needs a number");
    if (status == WC_OK)
        status = check_nonneg(ps, &t, ps->P->mu_s);
    if (status != WC_OK)
        return status;
    r = lx_next(lx, &t);
    if (r < 0)
        return WC_EINPUT;
    if (r == 0)
    {
        fmpq_set(ps->P->mu_k, ps->P->mu_s);
        return WC_OK;
    }
    status = tok_number(lx, &t, ps->P->mu_k);
    if (status == WC_OK)
        status = check_nonneg(ps, &t, ps->P->mu_k);
    if (status == WC_OK)
        status = lx_end(lx);
    return status;
}

/* Degenerate or self-intersecting polygons are located at 'shape'.  */
static int
check_polygon(wc_parser * ps, const fmpq * v, slong m)
{
    wc_lexer * lx = &ps->lx;
    long col = ps->shape_col;
    slong i, j;

    for (i = 0; i < m; i++)
        if (point_equal(v + 2 * i, v + 2 * ((i + 1) % m)))
            return lx_error(lx, col,
                            "degenerate polygon: vertices %ld and %ld coincide",
                            (long) i, (long) ((i + 1) % m));
    for (i = 0; i < m; i++)
    {
        slong b = (i + 1) % m, c = (i + 2) % m;

        if (orient(v + 2 * i, v + 2 * b, v + 2 * c) == 0)
            return lx_error(lx, col, "degenerate polygon: vertices %ld, %ld "
                            "and %ld are collinear", (long) i, (long) b,
                            (long) c);
    }
    /* Adjacent edges cannot overlap now that no three consecutive vertices
       are collinear; test every pair of non-adjacent edges.  */
    for (i = 0; i < m; i++)
        for (j = i + 2; j < m; j++)
        {
            int k;

            if (i == 0 && j == m - 1)
                continue;
            k = segments_meet(v + 2 * i, v + 2 * ((i + 1) % m),
                              v + 2 * j, v + 2 * ((j + 1) % m));
            if (k != 0)
                return lx_error(lx, col,
                                "self-intersecting polygon: edges %ld and %ld %s",
                                (long) i, (long) j, k == 2 ? "cross" : "touch");
        }
    /* A simple polygon has nonzero area; kept as a last guard.  */
    ps->poly_orient = polygon_orientation(v, m);
    if (ps->poly_orient == 0)
        return lx_error(lx, col, "degenerate polygon: zero area");
    return WC_OK;
}

static int
parse_shape(wc_parser * ps)
{
    wc_lexer * lx = &ps->lx;
    wc_problem_struct * P = ps->P;
    wc_token t = { 0, 0, 0, 0 };
    fmpq * v = NULL;
    slong n = 0, cap = 0, i;
    int r, status = WC_OK;

    r = lx_next(lx, &t);
    if (r < 0)
        return WC_EINPUT;
    if (r == 0)
        return lx_missing(lx, "'shape' needs 'disk' or 'polygon'");
    if (tok_is(lx, &t, "disk"))
    {
        v = malloc(3 * sizeof(fmpq));
        if (v == NULL)
            return nomem(ps);
        for (i = 0; i < 3; i++)
            fmpq_init(v + i);
        n = 3;
        for (i = 0; i < 3 && status == WC_OK; i++)
            status = lx_number(lx, v + i, &t, "'shape disk' needs 3 numbers");
        if (status == WC_OK && fmpq_sgn(v + 2) <= 0)
            status = lx_error(lx, t.col, "disk radius must be positive");
        if (status == WC_OK)
            status = lx_end(lx);
        if (status != WC_OK)
            goto cleanup;
        P->shape = WC_SHAPE_DISK;
    }
    else if (tok_is(lx, &t, "polygon"))
    {
        for (;;)
        {
            r = lx_next(lx, &t);
            if (r < 0)
            {
                status = WC_EINPUT;
                goto cleanup;
            }
            if (r == 0)
                break;
            if (n == cap)
            {
                slong ncap = cap == 0 ? 8 : 2 * cap;
                fmpq * a;

                if ((size_t) ncap > SIZE_MAX / sizeof(fmpq)
                    || (a = realloc(v, (size_t) ncap * sizeof(fmpq))) == NULL)
                {
                    status = nomem(ps);
                    goto cleanup;
                }
                v = a;
                cap = ncap;
            }
            fmpq_init(v + n);
            n++;
            status = tok_number(lx, &t, v + n - 1);
            if (status != WC_OK)
                goto cleanup;
        }
        if (n % 2 != 0)
            status = lx_missing(lx, n < 6 ?
                                "'shape polygon' needs at least 3 vertices" :
                                "the last polygon vertex needs a y coordinate");
        else if (n < 6)
            status = lx_missing(lx, "'shape polygon' needs at least 3 vertices");
        if (status == WC_OK)
            status = check_polygon(ps, v, n / 2);
        if (status != WC_OK)
            goto cleanup;
        P->shape = WC_SHAPE_POLYGON;
    }
    else
    {
        status = lx_error_token(lx, &t, "unknown shape '%s'");
        goto cleanup;
    }
    P->shape_data = v;
    P->shape_len = n;
    P->shape_line = lx->line;
    v = NULL;
    n = 0;
cleanup:
    for (i = 0; i < n; i++)
        fmpq_clear(v + i);
    free(v);
    return status;
}

static int
parse_fixel(wc_parser * ps, long kwcol)
{
    wc_lexer * lx = &ps->lx;
    wc_fixel_struct * f;
    wc_token t = { 0, 0, 0, 0 };
    fmpq point[2], normal[2];
    fmpq_t mus, muk;
    long pcol;
    int has_normal = 0, has_state = 0, has_friction = 0;
    wc_fixel_state state = WC_TOUCHING;
    int r, status;

    fmpq_init(point + 0);
    fmpq_init(point + 1);
    fmpq_init(normal + 0);
    fmpq_init(normal + 1);
    fmpq_init(mus);
    fmpq_init(muk);

    status = lx_number(lx, point + 0, &t, "'fixel' needs 2 numbers");
    pcol = t.col;
    if (status == WC_OK)
        status = lx_number(lx, point + 1, &t, "'fixel' needs 2 numbers");
    while (status == WC_OK)
    {
        r = lx_next(lx, &t);
        if (r <= 0)
        {
            status = r < 0 ? WC_EINPUT : WC_OK;
            break;
        }
        if (tok_is(lx, &t, "normal"))
        {
            long ncol;

            if (has_normal)
            {
                status = lx_error(lx, t.col, "duplicate 'normal'");
                break;
            }
            has_normal = 1;
            status = lx_number(lx, normal + 0, &t, "'normal' needs 2 numbers");
            ncol = t.col;
            if (status == WC_OK)
                status = lx_number(lx, normal + 1, &t,
                                   "'normal' needs 2 numbers");
            if (status == WC_OK && fmpq_is_zero(normal + 0)
                && fmpq_is_zero(normal + 1))
                status = lx_error(lx, ncol, "zero normal");
        }
        else if (tok_is(lx, &t, "touching") || tok_is(lx, &t, "near"))
        {
            if (has_state)
            {
                status = lx_error_token(lx, &t, "duplicate fixel state '%s'");
                break;
            }
            has_state = 1;
            state = tok_is(lx, &t, "near") ? WC_NEAR : WC_TOUCHING;
        }
        else if (tok_is(lx, &t, "friction"))
        {
            if (has_friction)
            {
                status = lx_error(lx, t.col, "duplicate 'friction'");
                break;
            }
            has_friction = 1;
            status = lx_number(lx, mus, &t, "'friction' needs a number");
            if (status == WC_OK)
                status = check_nonneg(ps, &t, mus);
            if (status != WC_OK)
                break;
            fmpq_set(muk, mus);
            r = lx_peek(lx, &t);
            if (r < 0)
                status = WC_EINPUT;
            else if (r > 0 && tok_numeric(lx, &t))
            {
                lx_next(lx, &t);
                status = tok_number(lx, &t, muk);
                if (status == WC_OK)
                    status = check_nonneg(ps, &t, muk);
            }
        }
        else if (tok_numeric(lx, &t))
            status = lx_error_token(lx, &t, "unexpected token '%s'");
        else
            status = lx_error_token(lx, &t, "unknown fixel option '%s'");
    }
    if (status != WC_OK)
        goto cleanup;

    if (ps->P->n == ps->info_cap)
    {
        slong ncap = ps->info_cap == 0 ? 4 : 2 * ps->info_cap;
        wc_fixinfo * a;

        if ((size_t) ncap > SIZE_MAX / sizeof(wc_fixinfo)
            || (a = realloc(ps->info, (size_t) ncap * sizeof(wc_fixinfo)))
               == NULL)
        {
            status = nomem(ps);
            goto cleanup;
        }
        ps->info = a;
        ps->info_cap = ncap;
    }
    f = wc_problem_add_fixel(ps->P);
    if (f == NULL)
    {
        status = nomem(ps);
        goto cleanup;
    }
    fmpq_swap(f->point + 0, point + 0);
    fmpq_swap(f->point + 1, point + 1);
    fmpq_swap(f->normal + 0, normal + 0);
    fmpq_swap(f->normal + 1, normal + 1);
    fmpq_swap(f->mu_s, mus);
    fmpq_swap(f->mu_k, muk);
    f->state = state;
    f->line = lx->line;
    f->col = kwcol;
    ps->info[ps->P->n - 1].pcol = pcol;
    ps->info[ps->P->n - 1].has_normal = has_normal;
    ps->info[ps->P->n - 1].has_friction = has_friction;
cleanup:
    fmpq_clear(point + 0);
    fmpq_clear(point + 1);
    fmpq_clear(normal + 0);
    fmpq_clear(normal + 1);
    fmpq_clear(mus);
    fmpq_clear(muk);
    return status;
}

static int
parse_line(wc_parser * ps)
{
    wc_lexer * lx = &ps->lx;
    wc_problem_struct * P = ps->P;
    wc_token t = { 0, 0, 0, 0 };
    int * seen = NULL;
    int r = lx_next(lx, &t);

    if (r <= 0)
        return r < 0 ? WC_EINPUT : WC_OK;
    if (tok_is(lx, &t, "fixel"))
        return parse_fixel(ps, t.col);
    if (tok_is(lx, &t, "name"))
        seen = &ps->seen_name;
    else if (tok_is(lx, &t, "mass"))
        seen = &ps->seen_mass;
    else if (tok_is(lx, &t, "inertia"))
        seen = &ps->seen_inertia;
    else if (tok_is(lx, &t, "com"))
        seen = &ps->seen_com;
    else if (tok_is(lx, &t, "friction"))
        seen = &ps->seen_friction;
    else if (tok_is(lx, &t, "shape"))
        seen = &ps->seen_shape;
    else
        return lx_error_token(lx, &t, "unknown keyword '%s'");
    if (*seen)
        return lx_error_token(lx, &t, "duplicate '%s'");
    *seen = 1;

    if (seen == &ps->seen_name)
        return parse_name(ps);
    if (seen == &ps->seen_mass)
        return parse_positive(ps, P->mass, "'mass' needs a number",
                              "mass must be positive");
    if (seen == &ps->seen_inertia)
        return parse_positive(ps, P->inertia, "'inertia' needs a number",
                              "inertia must be positive");
    if (seen == &ps->seen_com)
        return parse_com(ps);
    if (seen == &ps->seen_friction)
        return parse_friction(ps);
    ps->shape_col = t.col;
    return parse_shape(ps);
}

static char *
point_string(const fmpq * p)
{
    char * x = fmpq_get_str(NULL, 10, p + 0);
    char * y = fmpq_get_str(NULL, 10, p + 1);
    char * s = malloc(strlen(x) + strlen(y) + 5);

    if (s != NULL)
    {
        strcpy(s, "(");
        strcat(s, x);
        strcat(s, ", ");
        strcat(s, y);
        strcat(s, ")");
    }
    flint_free(x);
    flint_free(y);
    return s;
}

/* Error about the point of a fixel; fmt has one %s, the point.  */
static int
point_error(wc_error_t e, const char * file, long line, long col,
            const char * fmt, const fmpq * p)
{
    char * s = point_string(p);

    if (s == NULL)
        return wc_error_set(e, WC_EINTERNAL, file, 0, 0, "out of memory");
    error_with(e, WC_EINPUT, file, line, col, fmt, s);
    free(s);
    return WC_EINPUT;
}

/* Derive the inward normal of fixel i from the shape, into f->normal;
   errors go to e (not to the parser's record).  */
static int
derive_normal(wc_parser * ps, slong i, wc_error_t e)
{
    const wc_problem_struct * P = ps->P;
    wc_fixel_struct * f = P->fixels + i;
    const fmpq * p = f->point;
    const fmpq * v = P->shape_data;
    long line = f->line, col = ps->info[i].pcol;
    const char * file = ps->lx.file;
    int status = WC_OK;

    if (P->shape == WC_SHAPE_NONE)
        return wc_error_set(e, WC_EINPUT, file, line, col,
                            "no normal given and no shape to derive it from");
    if (P->shape == WC_SHAPE_DISK)
    {
        fmpq_t d, s;

        fmpq_init(d);
        fmpq_init(s);
        fmpq_sub(d, p + 0, v + 0);
        fmpq_mul(s, d, d);
        fmpq_sub(d, p + 1, v + 1);
        fmpq_addmul(s, d, d);
        fmpq_submul(s, v + 2, v + 2);
        if (fmpq_is_zero(s))
        {
            fmpq_sub(f->normal + 0, v + 0, p + 0);
            fmpq_sub(f->normal + 1, v + 1, p + 1);
        }
        else
            status = point_error(e, file, line, col, "point %s is not on "
                                 "the shape's boundary; give its normal", p);
        fmpq_clear(d);
        fmpq_clear(s);
        return status;
    }
    else
    {
        slong m = P->shape_len / 2, k;

        for (k = 0; k < m; k++)
            if (point_equal(p, v + 2 * k))
                return point_error(e, file, line, col, "point %s is a "
                                   "polygon vertex; give its normal", p);
        for (k = 0; k < m; k++)
        {
            const fmpq * a = v + 2 * k, * b = v + 2 * ((k + 1) % m);

            if (orient(a, b, p) == 0 && in_box(p, a, b))
            {
                /* edge vector b - a turned +90 degrees for a
                   counter-clockwise polygon, -90 for a clockwise one */
                fmpq_sub(f->normal + 0, a + 1, b + 1);
                fmpq_sub(f->normal + 1, b + 0, a + 0);
                if (ps->poly_orient < 0)
                {
                    fmpq_neg(f->normal + 0, f->normal + 0);
                    fmpq_neg(f->normal + 1, f->normal + 1);
                }
                return WC_OK;
            }
        }
        return point_error(e, file, line, col, "point %s is not on the "
                           "shape's boundary; give its normal", p);
    }
}

/* Key for finding two fixels with the same point and the same normal
   direction: the normal as a primitive integer vector.  */
typedef struct
{
    const fmpq * point;
    fmpz dir[2];
    slong index;
}
wc_dupkey;

static int
dupkey_cmp(const void * x, const void * y)
{
    const wc_dupkey * a = x, * b = y;
    int c;

    if ((c = fmpq_cmp(a->point + 0, b->point + 0)) != 0
        || (c = fmpq_cmp(a->point + 1, b->point + 1)) != 0
        || (c = fmpz_cmp(a->dir + 0, b->dir + 0)) != 0
        || (c = fmpz_cmp(a->dir + 1, b->dir + 1)) != 0)
        return c;
    return (a->index > b->index) - (a->index < b->index);
}

static int
dupkey_same(const wc_dupkey * a, const wc_dupkey * b)
{
    return fmpq_equal(a->point + 0, b->point + 0)
        && fmpq_equal(a->point + 1, b->point + 1)
        && fmpz_equal(a->dir + 0, b->dir + 0)
        && fmpz_equal(a->dir + 1, b->dir + 1);
}

/* Among the fixels before 'limit' whose normal is known, find the
   smallest index k of a fixel that repeats an earlier one, j (both -1 when
   there is none).  WC_OK, or WC_EINTERNAL when out of memory.  */
static int
find_duplicate(const wc_parser * ps, slong limit, slong * k, slong * j)
{
    const wc_problem_struct * P = ps->P;
    wc_dupkey * keys = NULL;
    fmpz_t l, g;
    slong i, m = 0;

    *k = -1;
    *j = -1;
    if (limit < 2)
        return WC_OK;
    keys = malloc((size_t) limit * sizeof(wc_dupkey));
    if (keys == NULL)
        return WC_EINTERNAL;
    fmpz_init(l);
    fmpz_init(g);
    for (i = 0; i < limit; i++)
    {
        const fmpq * n = P->fixels[i].normal;
        wc_dupkey * key = keys + m;

        if (!ps->info[i].has_normal)
            continue;
        key->point = P->fixels[i].point;
        key->index = i;
        fmpz_init(key->dir + 0);
        fmpz_init(key->dir + 1);
        fmpz_lcm(l, fmpq_denref(n + 0), fmpq_denref(n + 1));
        fmpz_divexact(g, l, fmpq_denref(n + 0));
        fmpz_mul(key->dir + 0, fmpq_numref(n + 0), g);
        fmpz_divexact(g, l, fmpq_denref(n + 1));
        fmpz_mul(key->dir + 1, fmpq_numref(n + 1), g);
        fmpz_gcd(g, key->dir + 0, key->dir + 1);
        fmpz_divexact(key->dir + 0, key->dir + 0, g);
        fmpz_divexact(key->dir + 1, key->dir + 1, g);
        m++;
    }
    qsort(keys, (size_t) m, sizeof(wc_dupkey), dupkey_cmp);
    /* equal keys are sorted by index, so the first pair of a run has the
       smallest later index of its class */
    for (i = 0; i + 1 < m; i++)
        if (dupkey_same(keys + i, keys + i + 1)
            && (*k < 0 || keys[i + 1].index < *k))
        {
            *k = keys[i + 1].index;
            *j = keys[i].index;
        }
    for (i = 0; i < m; i++)
    {
        fmpz_clear(keys[i].dir + 0);
        fmpz_clear(keys[i].dir + 1);
    }
    fmpz_clear(l);
    fmpz_clear(g);
    free(keys);
    return WC_OK;
}

/* The checks that need the whole file.  status is the result of reading
   the lines: WC_OK, or WC_EINPUT with the line error already in err.  */
static int
finish(wc_parser * ps, int status)
{
    wc_problem_struct * P = ps->P;
    wc_error_t ferr;
    slong i, bad = P->n, k, j;
    int dstatus = WC_OK;

    wc_error_init(ferr);
    for (i = 0; i < P->n; i++)
    {
        if (ps->info[i].has_normal)
            continue;
        /* after a bad line, a shape might have followed it */
        if (status != WC_OK && P->shape == WC_SHAPE_NONE)
            continue;
        dstatus = derive_normal(ps, i, ferr);
        if (dstatus != WC_OK)
        {
            bad = i;
            break;
        }
        ps->info[i].has_normal = 1;
    }
    if (dstatus == WC_EINTERNAL)
    {
        status = nomem(ps);
        goto cleanup;
    }
    if (find_duplicate(ps, bad, &k, &j) != WC_OK)
    {
        status = nomem(ps);
        goto cleanup;
    }
    if (k >= 0)
    {
        status = wc_error_set(ps->lx.err, WC_EINPUT, ps->lx.file,
                              P->fixels[k].line, ps->info[k].pcol,
                              "fixel %ld has the same point and normal as "
                              "fixel %ld", (long) k + 1, (long) j + 1);
        goto cleanup;
    }
    if (bad < P->n)
    {
        wc_error_clear(ps->lx.err);
        *ps->lx.err = *ferr;
        wc_error_init(ferr);
        status = WC_EINPUT;
        goto cleanup;
    }
    if (status != WC_OK)
        goto cleanup;
    if (P->n == 0)
    {
        long col = ps->lx.line == 0 ? 1 : lx_col(&ps->lx, ps->lx.lend);

        status = wc_error_set(ps->lx.err, WC_EINPUT, ps->lx.file,
                              ps->lx.line == 0 ? 1 : ps->lx.line, col,
                              "no fixel in the problem");
        goto cleanup;
    }
    for (i = 0; i < P->n; i++)
        if (!ps->info[i].has_friction)
        {
            fmpq_set(P->fixels[i].mu_s, P->mu_s);
            fmpq_set(P->fixels[i].mu_k, P->mu_k);
        }
cleanup:
    wc_error_clear(ferr);
    return status;
}

int
wc_problem_parse(wc_problem_t P, const char * text, size_t len,
                 const char * file, wc_error_t err)
{
    wc_parser ps;
    size_t start = 0;
    int status = WC_OK;

    memset(&ps, 0, sizeof ps);
    ps.lx.text = text;
    ps.lx.len = len;
    ps.lx.err = err;
    ps.P = P;
    if (file != NULL)
    {
        P->file = dup_string(file);
        if (P->file == NULL)
        {
            status = wc_error_set(err, WC_EINTERNAL, file, 0, 0,
                                  "out of memory");
            goto cleanup;
        }
    }
    ps.lx.file = P->file;

    while (start < len)
    {
        const char * nl = memchr(text + start, '\n', len - start);
        size_t end = nl != NULL ? (size_t) (nl - text) : len;

        ps.lx.line++;
        ps.lx.lstart = start;
        ps.lx.lend = end;
        if (end > start && text[end - 1] == '\r')
            ps.lx.lend--;
        ps.lx.pos = start;
        ps.lx.prev_end = start;
        status = parse_line(&ps);
        if (status != WC_OK || nl == NULL)
            break;
        start = end + 1;
    }
    if (status == WC_OK || status == WC_EINPUT)
        status = finish(&ps, status);
cleanup:
    free(ps.info);
    return status;
}

/* ------------------------------------------------------------------ */
/* Printing.                                                           */

static int
put_q(FILE * out, const char * before, const fmpq_t x)
{
    char * s = fmpq_get_str(NULL, 10, x);
    int r = fputs(before, out) != EOF && fputs(s, out) != EOF;

    flint_free(s);
    return r ? 0 : -1;
}

int
wc_problem_fprint(FILE * out, const wc_problem_t P)
{
    slong i;
    int bad = 0;

    if (P->name != NULL)
    {
        const char * c;

        bad |= fputs("name \"", out) == EOF;
        for (c = P->name; *c != '\0'; c++)
        {
            if (*c == '"' || *c == '\\')
                bad |= putc('\\', out) == EOF;
            bad |= putc(*c, out) == EOF;
        }
        bad |= fputs("\"\n", out) == EOF;
    }
    bad |= put_q(out, "mass ", P->mass) != 0;
    bad |= put_q(out, "\ninertia ", P->inertia) != 0;
    bad |= put_q(out, "\ncom ", P->com + 0) != 0;
    bad |= put_q(out, " ", P->com + 1) != 0;
    bad |= put_q(out, "\nfriction ", P->mu_s) != 0;
    bad |= put_q(out, " ", P->mu_k) != 0;
    bad |= fputs("\n", out) == EOF;
    if (P->shape != WC_SHAPE_NONE)
    {
        bad |= fputs(P->shape == WC_SHAPE_DISK ? "shape disk" : "shape polygon",
                     out) == EOF;
        for (i = 0; i < P->shape_len; i++)
            bad |= put_q(out, " ", P->shape_data + i) != 0;
        bad |= fputs("\n", out) == EOF;
    }
    for (i = 0; i < P->n; i++)
    {
        const wc_fixel_struct * f = P->fixels + i;

        bad |= put_q(out, "fixel ", f->point + 0) != 0;
        bad |= put_q(out, " ", f->point + 1) != 0;
        bad |= put_q(out, " normal ", f->normal + 0) != 0;
        bad |= put_q(out, " ", f->normal + 1) != 0;
        bad |= fputs(f->state == WC_NEAR ? " near" : " touching", out) == EOF;
        bad |= put_q(out, " friction ", f->mu_s) != 0;
        bad |= put_q(out, " ", f->mu_k) != 0;
        bad |= fputs("\n", out) == EOF;
    }
    if (bad || ferror(out))
        return WC_EINTERNAL;
    return WC_OK;
}
