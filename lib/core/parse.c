/* parse.c -- the .wc problem file reader.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   wrenchcone(5).  The parser reads the file line by line with a lazy
   tokenizer, so the first error in file order is the one reported.  Checks
   that need the whole file (normals derived from a shape given later, two
   fixels alike, no fixel at all) run after the last line; when a line is
   bad they still run on the fixels before it, so an earlier fixel's error
   is not hidden by a later line's.  */

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <flint/fmpz.h>

#include "core/problem.h"
#include "core/lexer.h"
#include "core/polygon.h"
#include "core/text.h"

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
        return _wc_lx_error(&ps->lx, t->col, "friction must be non-negative");
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

    r = _wc_lx_next(lx, &t);
    if (r < 0)
        return WC_EINPUT;
    if (r == 0)
        return _wc_lx_missing(lx, "'name' needs a quoted string");
    if (!t.quoted)
        return _wc_lx_error_token(lx, &t, "expected a quoted name, got '%s'");
    name = malloc(t.end - t.start);
    if (name == NULL)
        return nomem(ps);
    /* A label goes into every output, JSON and SVG too: UTF-8 text
       without control characters (a tab is fine).  */
    for (i = t.start + 1; i + 1 < t.end; i++)
    {
        size_t k = _wc_utf8_length((const unsigned char *) s + i,
                                   t.end - 1 - i);

        if (s[i] == '\\')
        {
            if (s[i + 1] != '"' && s[i + 1] != '\\')
            {
                k = _wc_utf8_length((const unsigned char *) s + i + 1,
                                    t.end - 2 - i);
                status = _wc_error_token(lx->err, WC_EINPUT, lx->file,
                                         lx->line, _wc_lx_col(lx, i),
                                         "bad escape '%s' in string", s + i,
                                         1 + (k > 0 ? k : 1));
                goto cleanup;
            }
            i++;
        }
        else if (s[i] == '\0')
        {
            status = _wc_lx_error(lx, _wc_lx_col(lx, i), "NUL byte in string");
            goto cleanup;
        }
        else if (k == 0)
        {
            status = _wc_lx_error(lx, _wc_lx_col(lx, i),
                                  "invalid UTF-8 in string");
            goto cleanup;
        }
        else if (((unsigned char) s[i] < 0x20 && s[i] != '\t')
                 || s[i] == 0x7f)
        {
            status = _wc_error_token(lx->err, WC_EINPUT, lx->file, lx->line,
                                     _wc_lx_col(lx, i), "control character "
                                     "'%s' in string", s + i, 1);
            goto cleanup;
        }
        else
        {
            memcpy(name + j, s + i, k);
            j += k;
            i += k - 1;
            continue;
        }
        name[j++] = s[i];
    }
    name[j] = '\0';
    status = _wc_lx_end(lx);
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
    int status = _wc_lx_number(&ps->lx, x, &t, missing);

    if (status != WC_OK)
        return status;
    if (fmpq_sgn(x) <= 0)
        return _wc_lx_error(&ps->lx, t.col, "%s", message);
    return _wc_lx_end(&ps->lx);
}

static int
parse_com(wc_parser * ps)
{
    wc_token t = { 0, 0, 0, 0 };
    int status = _wc_lx_number(&ps->lx, ps->P->com + 0, &t,
                               "'com' needs 2 numbers");

    if (status == WC_OK)
        status = _wc_lx_number(&ps->lx, ps->P->com + 1, &t,
                               "'com' needs 2 numbers");
    if (status == WC_OK)
        status = _wc_lx_end(&ps->lx);
    return status;
}

static int
parse_friction(wc_parser * ps)
{
    wc_lexer * lx = &ps->lx;
    wc_token t = { 0, 0, 0, 0 };
    int r, status;

    status = _wc_lx_number(lx, ps->P->mu_s, &t, "'friction' needs a number");
    if (status == WC_OK)
        status = check_nonneg(ps, &t, ps->P->mu_s);
    if (status != WC_OK)
        return status;
    r = _wc_lx_next(lx, &t);
    if (r < 0)
        return WC_EINPUT;
    if (r == 0)
    {
        fmpq_set(ps->P->mu_k, ps->P->mu_s);
        return WC_OK;
    }
    status = _wc_tok_number(lx, &t, ps->P->mu_k);
    if (status == WC_OK)
        status = check_nonneg(ps, &t, ps->P->mu_k);
    if (status == WC_OK)
        status = _wc_lx_end(lx);
    return status;
}

/* Degenerate or self-intersecting polygons are located at 'shape'.  */
static int
check_polygon(wc_parser * ps, const fmpq * v, slong m)
{
    wc_lexer * lx = &ps->lx;
    long col = ps->shape_col;
    slong i = 0, j = 0;
    int fault = _wc_polygon_check(&ps->poly_orient, &i, &j, v, m);

    switch (fault)
    {
    case WC_POLYGON_COINCIDE:
        return _wc_lx_error(lx, col, "degenerate polygon: vertices %ld and "
                            "%ld coincide", (long) i, (long) j);
    case WC_POLYGON_COLLINEAR:
        return _wc_lx_error(lx, col, "degenerate polygon: vertices %ld, %ld "
                            "and %ld are collinear", (long) i, (long) j,
                            (long) ((j + 1) % m));
    case WC_POLYGON_CROSS:
    case WC_POLYGON_TOUCH:
        return _wc_lx_error(lx, col,
                            "self-intersecting polygon: edges %ld and %ld %s",
                            (long) i, (long) j,
                            fault == WC_POLYGON_CROSS ? "cross" : "touch");
    case WC_POLYGON_ZERO_AREA:
        return _wc_lx_error(lx, col, "degenerate polygon: zero area");
    }
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

    r = _wc_lx_next(lx, &t);
    if (r < 0)
        return WC_EINPUT;
    if (r == 0)
        return _wc_lx_missing(lx, "'shape' needs 'disk' or 'polygon'");
    if (_wc_tok_is(lx, &t, "disk"))
    {
        v = malloc(3 * sizeof(fmpq));
        if (v == NULL)
            return nomem(ps);
        for (i = 0; i < 3; i++)
            fmpq_init(v + i);
        n = 3;
        for (i = 0; i < 3 && status == WC_OK; i++)
            status = _wc_lx_number(lx, v + i, &t,
                                   "'shape disk' needs 3 numbers");
        if (status == WC_OK && fmpq_sgn(v + 2) <= 0)
            status = _wc_lx_error(lx, t.col, "disk radius must be positive");
        if (status == WC_OK)
            status = _wc_lx_end(lx);
        if (status != WC_OK)
            goto cleanup;
        P->shape = WC_SHAPE_DISK;
    }
    else if (_wc_tok_is(lx, &t, "polygon"))
    {
        for (;;)
        {
            r = _wc_lx_next(lx, &t);
            if (r < 0)
            {
                status = WC_EINPUT;
                goto cleanup;
            }
            if (r == 0)
                break;
            if (n == 2 * WC_POLYGON_MAX_VERTICES)
            {
                /* the simplicity test is quadratic: refuse at once */
                status = _wc_lx_error(lx, t.col, "polygon has more than "
                                      "%d vertices", WC_POLYGON_MAX_VERTICES);
                goto cleanup;
            }
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
            status = _wc_tok_number(lx, &t, v + n - 1);
            if (status != WC_OK)
                goto cleanup;
        }
        if (n % 2 != 0)
            status = _wc_lx_missing(lx, n < 6
                                    ? "'shape polygon' needs at least 3 "
                                      "vertices"
                                    : "the last polygon vertex needs a y "
                                      "coordinate");
        else if (n < 6)
            status = _wc_lx_missing(lx, "'shape polygon' needs at least 3 "
                                    "vertices");
        if (status == WC_OK)
            status = check_polygon(ps, v, n / 2);
        if (status != WC_OK)
            goto cleanup;
        P->shape = WC_SHAPE_POLYGON;
    }
    else
    {
        status = _wc_lx_error_token(lx, &t, "unknown shape '%s'");
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

    if (ps->P->n >= WC_PROBLEM_MAX_FIXELS)
        return _wc_lx_error(lx, kwcol, "a problem holds at most %d fixels",
                            WC_PROBLEM_MAX_FIXELS);
    fmpq_init(point + 0);
    fmpq_init(point + 1);
    fmpq_init(normal + 0);
    fmpq_init(normal + 1);
    fmpq_init(mus);
    fmpq_init(muk);

    status = _wc_lx_number(lx, point + 0, &t, "'fixel' needs 2 numbers");
    pcol = t.col;
    if (status == WC_OK)
        status = _wc_lx_number(lx, point + 1, &t, "'fixel' needs 2 numbers");
    while (status == WC_OK)
    {
        r = _wc_lx_next(lx, &t);
        if (r <= 0)
        {
            status = r < 0 ? WC_EINPUT : WC_OK;
            break;
        }
        if (_wc_tok_is(lx, &t, "normal"))
        {
            long ncol;

            if (has_normal)
            {
                status = _wc_lx_error(lx, t.col, "duplicate 'normal'");
                break;
            }
            has_normal = 1;
            status = _wc_lx_number(lx, normal + 0, &t,
                                   "'normal' needs 2 numbers");
            ncol = t.col;
            if (status == WC_OK)
                status = _wc_lx_number(lx, normal + 1, &t,
                                       "'normal' needs 2 numbers");
            if (status == WC_OK && fmpq_is_zero(normal + 0)
                && fmpq_is_zero(normal + 1))
                status = _wc_lx_error(lx, ncol, "zero normal");
        }
        else if (_wc_tok_is(lx, &t, "touching") || _wc_tok_is(lx, &t, "near"))
        {
            if (has_state)
            {
                status = _wc_lx_error_token(lx, &t,
                                            "duplicate fixel state '%s'");
                break;
            }
            has_state = 1;
            state = _wc_tok_is(lx, &t, "near") ? WC_NEAR : WC_TOUCHING;
        }
        else if (_wc_tok_is(lx, &t, "friction"))
        {
            if (has_friction)
            {
                status = _wc_lx_error(lx, t.col, "duplicate 'friction'");
                break;
            }
            has_friction = 1;
            status = _wc_lx_number(lx, mus, &t, "'friction' needs a number");
            if (status == WC_OK)
                status = check_nonneg(ps, &t, mus);
            if (status != WC_OK)
                break;
            fmpq_set(muk, mus);
            r = _wc_lx_peek(lx, &t);
            if (r < 0)
                status = WC_EINPUT;
            else if (r > 0 && _wc_tok_numeric(lx, &t))
            {
                _wc_lx_next(lx, &t);
                status = _wc_tok_number(lx, &t, muk);
                if (status == WC_OK)
                    status = check_nonneg(ps, &t, muk);
            }
        }
        else if (_wc_tok_numeric(lx, &t))
            status = _wc_lx_error_token(lx, &t, "unexpected token '%s'");
        else
            status = _wc_lx_error_token(lx, &t, "unknown fixel option '%s'");
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
    int r = _wc_lx_next(lx, &t);

    if (r <= 0)
        return r < 0 ? WC_EINPUT : WC_OK;
    if (_wc_tok_is(lx, &t, "fixel"))
        return parse_fixel(ps, t.col);
    if (_wc_tok_is(lx, &t, "name"))
        seen = &ps->seen_name;
    else if (_wc_tok_is(lx, &t, "mass"))
        seen = &ps->seen_mass;
    else if (_wc_tok_is(lx, &t, "inertia"))
        seen = &ps->seen_inertia;
    else if (_wc_tok_is(lx, &t, "com"))
        seen = &ps->seen_com;
    else if (_wc_tok_is(lx, &t, "friction"))
        seen = &ps->seen_friction;
    else if (_wc_tok_is(lx, &t, "shape"))
        seen = &ps->seen_shape;
    else
        return _wc_lx_error_token(lx, &t, "unknown keyword '%s'");
    if (*seen)
        return _wc_lx_error_token(lx, &t, "duplicate '%s'");
    *seen = 1;
    if (seen == &ps->seen_mass)
        P->mass_line = lx->line;
    else if (seen == &ps->seen_inertia)
        P->inertia_line = lx->line;
    else if (seen == &ps->seen_com)
        P->com_line = lx->line;

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

/* "(x, y)", each coordinate cut like quoted input (_wc_show), so that a
   long number does not fill the message.  */
static char *
point_string(const fmpq * p)
{
    char * x = fmpq_get_str(NULL, 10, p + 0);
    char * y = fmpq_get_str(NULL, 10, p + 1);
    char * sx = _wc_show(x, strlen(x));
    char * sy = _wc_show(y, strlen(y));
    char * s = NULL;

    if (sx != NULL && sy != NULL)
        s = malloc(strlen(sx) + strlen(sy) + 5);
    if (s != NULL)
    {
        strcpy(s, "(");
        strcat(s, sx);
        strcat(s, ", ");
        strcat(s, sy);
        strcat(s, ")");
    }
    flint_free(x);
    flint_free(y);
    free(sx);
    free(sy);
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
    _wc_error_with(e, WC_EINPUT, file, line, col, fmt, s);
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
            if (_wc_point_equal(p, v + 2 * k))
                return point_error(e, file, line, col, "point %s is a "
                                   "polygon vertex; give its normal", p);
        for (k = 0; k < m; k++)
        {
            const fmpq * a = v + 2 * k, * b = v + 2 * ((k + 1) % m);

            if (_wc_on_segment(p, a, b))
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
        long col = ps->lx.line == 0 ? 1 : _wc_lx_col(&ps->lx, ps->lx.lend);

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
        P->file = _wc_strdup(file);
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
