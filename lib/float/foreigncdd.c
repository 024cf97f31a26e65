/* foreigncdd.c -- reading a foreign cone from a cddlib .ine or .ext
   file (the format is described at wc_foreign_parse in compare.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpq_vec.h>

#include "float/compare.h"
#include "float/foreign.h"
#include "float/angle.h"

typedef struct
{
    size_t a, b;        /* bytes of the token */
    long col;
}
token;

/* The tokens of the line text[start..end) (blank-separated), at most
   max; returns how many there are in all.  */
static slong
tokenize(token * tok, slong max, const char * text, size_t start,
         size_t end)
{
    size_t i = start;
    slong n = 0;

    for (;;)
    {
        size_t a;

        while (i < end && (text[i] == ' ' || text[i] == '\t'
                           || text[i] == '\r' || text[i] == '\f'
                           || text[i] == '\v'))
            i++;
        if (i >= end)
            return n;
        a = i;
        while (i < end && !(text[i] == ' ' || text[i] == '\t'
                            || text[i] == '\r' || text[i] == '\f'
                            || text[i] == '\v'))
            i++;
        if (n < max)
        {
            tok[n].a = a;
            tok[n].b = i;
            tok[n].col = (long) (a - start) + 1;
        }
        n++;
    }
}

static int
tok_is(const _wc_source * s, const token * t, const char * word)
{
    size_t n = strlen(word);

    return t->b - t->a == n && memcmp(s->text + t->a, word, n) == 0;
}

/* A non-negative decimal integer (digits only) at most max, else -1.  */
static long long
tok_count(const _wc_source * s, const token * t, long long max)
{
    long long x = 0;
    size_t i;

    if (t->a == t->b)
        return -1;
    for (i = t->a; i < t->b; i++)
    {
        char c = s->text[i];

        if (c < '0' || c > '9')
            return -1;
        if (x > (max - (c - '0')) / 10)
            return -1;
        x = 10 * x + (c - '0');
    }
    return x;
}

typedef enum { CDD_BEFORE, CDD_HEADER, CDD_ROWS, CDD_AFTER } cdd_state;

/* One begin..end block and what precedes it.  */
typedef struct
{
    int kind;           /* -1 until a representation keyword */
    long kind_line;
    long lin_line;      /* 0 when no linearity line */
    slong nlin;
    long long * lin;    /* sorted row numbers */
    long * lin_col;     /* column of each, in file order (for messages) */
    long long * lin_raw;    /* in file order */
    long begin_line;
    long header_line;
    long long m;
    int integer;
    long long nread;
    int empty;          /* H: an infeasible row; V: m = 0 */
    _wc_rowbuf rows, lin_rows;
}
cdd_block;

static void
block_init(cdd_block * B)
{
    memset(B, 0, sizeof *B);
    B->kind = -1;
    _wc_rowbuf_init(&B->rows);
    _wc_rowbuf_init(&B->lin_rows);
}

static void
block_clear(cdd_block * B)
{
    flint_free(B->lin);
    flint_free(B->lin_col);
    flint_free(B->lin_raw);
    _wc_rowbuf_clear(&B->rows);
    _wc_rowbuf_clear(&B->lin_rows);
    block_init(B);
}

static int
cmp_ll(const void * a, const void * b)
{
    long long x = *(const long long *) a, y = *(const long long *) b;

    return (x > y) - (x < y);
}

static int
in_linearity(const cdd_block * B, long long row)
{
    return B->nlin > 0
        && bsearch(&row, B->lin, (size_t) B->nlin, sizeof(long long),
                   cmp_ll) != NULL;
}

/* 'linearity k i_1 .. i_k' on line no, tokens t[0..n).  */
static int
cdd_linearity(cdd_block * B, const _wc_source * s, long no, const char * text,
              size_t start, size_t end)
{
    slong n = tokenize(NULL, 0, text, start, end), i;
    token * t = flint_malloc(sizeof(token) * (n + 1));
    long long k = 0;
    int status = WC_OK;

    tokenize(t, n, text, start, end);
    if (B->lin_line != 0)
    {
        status = _wc_located(s, no, t[0].col, "a second 'linearity' line "
                             "(the first is line %ld)", B->lin_line);
        goto cleanup;
    }
    if (n < 2 || (k = tok_count(s, t + 1, WC_FOREIGN_MAX_ROWS)) < 0)
    {
        status = n < 2 ? _wc_located(s, no, (long) (end - start) + 1,
                                     "'linearity' needs a count and row "
                                     "numbers")
            : _wc_located_quoting(s, no, t[1].col, "bad linearity count '%s'",
                                  text + t[1].a, t[1].b - t[1].a);
        goto cleanup;
    }
    if (n - 2 != k)
    {
        status = _wc_located(s, no, n - 2 > k ? t[2 + k].col
                             : (long) (end - start) + 1,
                             "'linearity %lld' needs %lld row numbers, "
                             "found %ld", k, k, (long) (n - 2));
        goto cleanup;
    }
    B->lin_line = no;
    B->nlin = (slong) k;
    B->lin = flint_malloc(sizeof(long long) * (k + 1));
    B->lin_raw = flint_malloc(sizeof(long long) * (k + 1));
    B->lin_col = flint_malloc(sizeof(long) * (k + 1));
    for (i = 0; i < k; i++)
    {
        long long r = tok_count(s, t + 2 + i, LLONG_MAX / 16);

        if (r < 1)
        {
            status = _wc_located_quoting(s, no, t[2 + i].col,
                                         "bad row number '%s' in 'linearity'",
                                         text + t[2 + i].a,
                                         t[2 + i].b - t[2 + i].a);
            goto cleanup;
        }
        B->lin[i] = B->lin_raw[i] = r;
        B->lin_col[i] = t[2 + i].col;
    }
    qsort(B->lin, (size_t) k, sizeof(long long), cmp_ll);
    for (i = 1; i < k; i++)
        if (B->lin[i] == B->lin[i - 1])
        {
            slong j;

            for (j = k - 1; j >= 0 && B->lin_raw[j] != B->lin[i]; j--)
                ;
            status = _wc_located(s, no, B->lin_col[j], "row %lld appears "
                                 "twice in 'linearity'", B->lin[i]);
            goto cleanup;
        }

cleanup:
    flint_free(t);
    return status;
}

/* 'm n numbertype' after begin.  */
static int
cdd_header(cdd_block * B, const _wc_source * s, long no, const char * text,
           size_t start, size_t end)
{
    token t[4];
    slong n = tokenize(t, 4, text, start, end), i;
    long long cols;

    if (n != 3)
        return _wc_located(s, no, n > 3 ? t[3].col : (long) (end - start) + 1,
                           "expected 'm n numbertype' after 'begin' (for "
                           "example '3 4 rational')");
    B->m = tok_count(s, t + 0, LLONG_MAX / 16);
    if (B->m < 0)
        return _wc_located_quoting(s, no, t[0].col, "bad row count '%s'",
                                   text + t[0].a, t[0].b - t[0].a);
    if (B->m > WC_FOREIGN_MAX_ROWS)
        return _wc_located(s, no, t[0].col, "too many rows: %lld (at most %d)",
                           B->m, WC_FOREIGN_MAX_ROWS);
    cols = tok_count(s, t + 1, 1000000);
    if (cols < 0)
        return _wc_located_quoting(s, no, t[1].col, "bad column count '%s'",
                                   text + t[1].a, t[1].b - t[1].a);
    if (cols != 4)
        return _wc_located(s, no, t[1].col, "a cone in R^3 has 4 columns (1 "
                           "homogenizing + 3 coordinates), not %lld", cols);
    if (tok_is(s, t + 2, "integer"))
        B->integer = 1;
    else if (!tok_is(s, t + 2, "rational") && !tok_is(s, t + 2, "real"))
        return _wc_located_quoting(s, no, t[2].col, "unknown number type '%s' "
                                   "(rational, real or integer)",
                                   text + t[2].a, t[2].b - t[2].a);
    for (i = 0; i < B->nlin; i++)
        if (B->lin_raw[i] > B->m)
            return _wc_located(s, B->lin_line, B->lin_col[i], "linearity "
                               "row %lld is beyond the last row of the block "
                               "(%lld)", B->lin_raw[i], B->m);
    B->header_line = no;
    return WC_OK;
}

/* One row of numbers.  */
static int
cdd_row(cdd_block * B, const _wc_source * s, long no, const char * text,
        size_t start, size_t end)
{
    token t[5];
    slong n = tokenize(t, 5, text, start, end), i;
    fmpq x[4];
    long long row = B->nread + 1;
    int status = WC_OK, lin = in_linearity(B, row), zero;

    for (i = 0; i < 4; i++)
        fmpq_init(x + i);
    if (B->nread == B->m)
    {
        status = _wc_located(s, no, t[0].col, "expected 'end': the header "
                             "(line %ld) announces %lld row%s", B->header_line,
                             B->m, B->m == 1 ? "" : "s");
        goto cleanup;
    }
    if (n != 4)
    {
        status = _wc_located(s, no,
                             n > 4 ? t[4].col : (long) (end - start) + 1,
                             "a row has 4 numbers, found %ld", (long) n);
        goto cleanup;
    }
    for (i = 0; i < 4; i++)
    {
        status = _wc_foreign_number(x + i, s, text + t[i].a,
                                    t[i].b - t[i].a, no, t[i].col);
        if (status != WC_OK)
            goto cleanup;
        if (B->integer && !fmpz_is_one(fmpq_denref(x + i)))
        {
            status = _wc_located_quoting(s, no, t[i].col, "'%s' is not an "
                                         "integer (the number type is "
                                         "'integer')", text + t[i].a,
                                         t[i].b - t[i].a);
            goto cleanup;
        }
    }
    B->nread++;
    zero = _wc_qv3_is_zero(x + 1);
    if (B->kind == WC_REP_INEQUALITIES)
    {
        /* b + a.g >= 0 (or = 0 in linearity) */
        if (zero)
        {
            if (lin ? !fmpq_is_zero(x) : fmpq_sgn(x) < 0)
                B->empty = 1;   /* 0 >= b < 0, or 0 = b != 0 */
        }
        else if (!fmpq_is_zero(x))
        {
            char * c = fmpq_get_str(NULL, 10, x);

            status = _wc_located(s, no, t[0].col, "not a cone: the "
                                 "constant term b is %s; the rows 'b -A' "
                                 "(b - A g >= 0) of a cone have b = 0", c);
            flint_free(c);
            goto cleanup;
        }
        else if (lin)
            _wc_rowbuf_push(&B->lin_rows, x + 1, no);
        else
        {
            _wc_qv3_neg(x + 1, x + 1);
            _wc_rowbuf_push(&B->rows, x + 1, no);
        }
    }
    else
    {
        if (fmpq_sgn(x) < 0)
        {
            status = _wc_located(s, no, t[0].col, "a V-representation row "
                                 "starts with 1 (a point) or 0 (a ray), not a "
                                 "negative number");
            goto cleanup;
        }
        if (fmpq_sgn(x) > 0)
        {
            if (!zero)
                status = _wc_located(s, no, t[1].col, "not a cone: a point "
                                     "other than the origin (a cone's one "
                                     "point is its apex, '1 0 0 0')");
            else if (lin)
                status = _wc_located(s, no, t[0].col, "linearity row %lld "
                                     "is a point, not a line", row);
            goto cleanup;
        }
        if (!zero)
            _wc_rowbuf_push(lin ? &B->lin_rows : &B->rows, x + 1, no);
    }

cleanup:
    for (i = 0; i < 4; i++)
        fmpq_clear(x + i);
    return status;
}

static int
cdd_finish(wc_foreign_t F, cdd_block * B, const _wc_source * s, long no,
           long col)
{
    if (B->nread < B->m)
        return _wc_located(s, no, col, "found %lld row%s before 'end', but "
                           "the header (line %ld) announces %lld", B->nread,
                           B->nread == 1 ? "" : "s", B->header_line, B->m);
    if (B->kind == WC_REP_GENERATORS && B->m == 0)
        B->empty = 1;
    if (F->nreps == 2)      /* cdd_kind and cdd_begin see to it */
        return wc_error_set(s->err, WC_EINTERNAL, s->file, no, col,
                            "a third representation");
    _wc_foreign_add_rep(F, (wc_rep_kind) B->kind, B->kind_line, B->empty,
                        &B->rows, &B->lin_rows);
    block_clear(B);
    return WC_OK;
}

/* A NUL byte: an error at its place.  */
static int
cdd_nul(const _wc_source * s, const char * nul)
{
    size_t at = (size_t) (nul - s->text), i, ls = 0;
    long l = 1;

    for (i = 0; i < at; i++)
        if (s->text[i] == '\n')
        {
            l++;
            ls = i + 1;
        }
    return _wc_located(s, l, (long) (at - ls) + 1, "NUL byte in the file");
}

/* Repeated blocks: a file holds at most one representation of each
   kind, an H-representation and a V-representation, in either order (as
   `wrenchcone cone --format=cdd` writes them, H then V), so at most two
   blocks; a block with no representation keyword is an H-representation,
   as in cdd.  A block of a kind already read is an error, located at its
   keyword, or at its 'begin' when it has none; so F->reps never holds
   more than its two.  The line where the earlier block of kind k starts,
   0 when there is none.  */
static long
cdd_seen(const wc_foreign_t F, int k)
{
    slong i;

    for (i = 0; i < F->nreps; i++)
        if ((int) F->reps[i].kind == k)
            return F->reps[i].line;
    return 0;
}

/* 'H-representation' or 'V-representation' (tokens t[0..n)).  */
static int
cdd_kind(cdd_block * B, const wc_foreign_t F, const _wc_source * s,
         long no, const token * t, slong n)
{
    int k = tok_is(s, t, "H-representation")
        ? WC_REP_INEQUALITIES : WC_REP_GENERATORS;

    if (n > 1)
        return _wc_located_quoting(s, no, t[1].col, "unexpected '%s' after "
                                   "the representation", s->text + t[1].a,
                                   t[1].b - t[1].a);
    if (B->kind >= 0)
        return _wc_located(s, no, t[0].col, "a second representation "
                           "keyword (the first is line %ld)", B->kind_line);
    if (cdd_seen(F, k) != 0)
        return _wc_located(s, no, t[0].col, "a second %s",
                           k == WC_REP_INEQUALITIES ? "H-representation"
                           : "V-representation");
    B->kind = k;
    B->kind_line = no;
    return WC_OK;
}

/* 'begin' (tokens t[0..n)); *st becomes CDD_HEADER.  */
static int
cdd_begin(cdd_block * B, cdd_state * st, const wc_foreign_t F,
          const _wc_source * s, long no, const token * t, slong n)
{
    if (n > 1)
        return _wc_located_quoting(s, no, t[1].col, "unexpected '%s' after "
                                   "'begin'", s->text + t[1].a,
                                   t[1].b - t[1].a);
    B->begin_line = no;
    *st = CDD_HEADER;
    if (B->kind >= 0)
        return WC_OK;
    /* cdd's default */
    if (cdd_seen(F, WC_REP_INEQUALITIES) != 0)
        return _wc_located(s, no, t[0].col, "a second H-representation (a "
                           "block with no representation keyword is an "
                           "H-representation, as in cdd; the first is line "
                           "%ld)", cdd_seen(F, WC_REP_INEQUALITIES));
    B->kind = WC_REP_INEQUALITIES;
    B->kind_line = no;
    return WC_OK;
}

/* A line outside begin..end: before the first block or after one.  */
static int
cdd_outside(cdd_block * B, cdd_state * st, const wc_foreign_t F,
            const _wc_source * s, long no, size_t start, size_t end,
            const token * t, slong n, int seen_line)
{
    if (tok_is(s, t, "H-representation") || tok_is(s, t, "V-representation"))
        return cdd_kind(B, F, s, no, t, n);
    if (tok_is(s, t, "linearity"))
        return cdd_linearity(B, s, no, s->text, start, end);
    if (tok_is(s, t, "begin"))
        return cdd_begin(B, st, F, s, no, t, n);
    if (*st == CDD_BEFORE && !seen_line && B->kind < 0 && B->lin_line == 0)
        return WC_OK;   /* a name line, as lrs writes */
    return _wc_located_quoting(s, no, t[0].col, *st == CDD_BEFORE
                               ? "unexpected '%s' before 'begin'"
                               : "unexpected '%s' after 'end'",
                               s->text + t[0].a, t[0].b - t[0].a);
}

/* Where the file ended: an error unless outside a block, after one.  */
static int
cdd_end_of_file(const cdd_block * B, cdd_state st, const wc_foreign_t F,
                const _wc_source * s, long no, long last_col)
{
    /* the position after the last byte */
    if (s->len > 0 && s->text[s->len - 1] == '\n')
    {
        no++;
        last_col = 1;
    }
    if (no == 0)
        no = 1;
    if (st == CDD_HEADER || st == CDD_ROWS)
        return _wc_located(s, no, last_col, "end of file before 'end'");
    if (st == CDD_BEFORE || B->kind >= 0 || B->lin_line != 0)
        return _wc_located(s, no, last_col, F->nreps == 0 && B->kind < 0
                           && B->lin_line == 0
                           ? "no cone here: expected a cdd file "
                           "(H- or V-representation, 'begin' .. 'end') "
                           "or a JSON cone" : "end of file before 'begin'");
    return WC_OK;
}

int
_wc_foreign_parse_cdd(wc_foreign_t F, const _wc_source * s)
{
    const char * text = s->text;
    size_t pos = 0, len = s->len;
    long no = 0, last_col = 1;
    cdd_state st = CDD_BEFORE;
    cdd_block B;
    int status = WC_OK, seen_line = 0;
    const char * nul = memchr(text, '\0', len);

    if (nul != NULL)
        return cdd_nul(s, nul);
    block_init(&B);
    while (pos < len && status == WC_OK)
    {
        size_t start = pos, end;
        const char * nl = memchr(text + pos, '\n', len - pos);
        token t[2];
        slong n;

        end = nl != NULL ? (size_t) (nl - text) : len;
        pos = nl != NULL ? end + 1 : len;
        no++;
        last_col = (long) (end - start) + 1;
        n = tokenize(t, 2, text, start, end);
        if (n == 0 || text[t[0].a] == '*')
            continue;
        switch (st)
        {
        case CDD_AFTER:
        case CDD_BEFORE:
            status = cdd_outside(&B, &st, F, s, no, start, end, t, n,
                                 seen_line);
            seen_line = 1;
            break;
        case CDD_HEADER:
            status = cdd_header(&B, s, no, text, start, end);
            if (status == WC_OK)
                st = CDD_ROWS;
            break;
        case CDD_ROWS:
            if (!tok_is(s, t, "end"))
                status = cdd_row(&B, s, no, text, start, end);
            else if (n > 1)
                status = _wc_located_quoting(s, no, t[1].col, "unexpected "
                                             "'%s' after 'end'",
                                             text + t[1].a, t[1].b - t[1].a);
            else
                status = cdd_finish(F, &B, s, no, t[0].col);
            if (tok_is(s, t, "end"))
                st = CDD_AFTER;
            break;
        }
    }
    if (status == WC_OK)
        status = cdd_end_of_file(&B, st, F, s, no, last_col);
    block_clear(&B);
    return status;
}
