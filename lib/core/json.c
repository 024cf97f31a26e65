/* json.c -- a small, strict JSON reader with located values.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Plain C and libc only (see json.h).  Every text (decoded string, number
   literal) lives in an arena of large blocks freed at once, so a document
   of millions of small values costs no malloc per value; the nodes live
   in one array per container.  Duplicate keys are found by sorting the
   keys of each object (O(m log m), whatever the keys), and, when the
   object is cut short by a later error, among the keys read so far, so
   that the first error in file order wins.  */

#include <limits.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/json.h"
#include "core/text.h"

/* ------------------------------------------------------------------ */
/* The arena.                                                          */

#define ARENA_BLOCK 65536

typedef struct arena_block
{
    struct arena_block * next;
    size_t used;
    size_t size;
    char data[];
}
arena_block;

static void
arena_free(arena_block * b)
{
    while (b != NULL)
    {
        arena_block * next = b->next;

        free(b);
        b = next;
    }
}

/* n bytes from the arena at *head; NULL when out of memory.  A request
   larger than a quarter block gets a block of its own, linked behind the
   current one, so the current block keeps filling.  */
static char *
arena_alloc(arena_block ** head, size_t n)
{
    arena_block * b = *head;

    if (b != NULL && b->size - b->used >= n)
    {
        b->used += n;
        return b->data + b->used - n;
    }
    if (n > SIZE_MAX - sizeof(arena_block))
        return NULL;
    if (n > ARENA_BLOCK / 4 && b != NULL)
    {
        arena_block * big = malloc(sizeof(arena_block) + n);

        if (big == NULL)
            return NULL;
        big->size = big->used = n;
        big->next = b->next;
        b->next = big;
        return big->data;
    }
    b = malloc(sizeof(arena_block) + (n > ARENA_BLOCK ? n : ARENA_BLOCK));
    if (b == NULL)
        return NULL;
    b->size = n > ARENA_BLOCK ? n : ARENA_BLOCK;
    b->used = n;
    b->next = *head;
    *head = b;
    return b->data;
}

/* ------------------------------------------------------------------ */
/* Nodes.                                                              */

static void
node_zero(wc_json_node * v)
{
    v->type = WC_JSON_NULL;
    v->line = 0;
    v->col = 0;
    v->len = 0;
    v->text = NULL;
    v->items = NULL;
}

/* Free the containers below v (texts belong to the arena).  The depth is
   bounded by WC_JSON_MAX_DEPTH, so recursion is safe.  */
static void
node_clear(wc_json_node * v)
{
    size_t i;

    if (v->type == WC_JSON_ARRAY)
        for (i = 0; i < v->len; i++)
            node_clear(v->items + i);
    else if (v->type == WC_JSON_OBJECT)
        for (i = 0; i < v->len; i++)
            node_clear(v->items + 2 * i + 1);
    free(v->items);
    node_zero(v);
}

void
_wc_json_init(wc_json_t J)
{
    node_zero(&J->root);
    J->arena = NULL;
}

void
_wc_json_clear(wc_json_t J)
{
    node_clear(&J->root);
    arena_free(J->arena);
    J->arena = NULL;
}

/* ------------------------------------------------------------------ */
/* The reader.                                                         */

typedef struct
{
    const char * s;
    size_t len;
    size_t pos;
    long line;
    size_t lstart;      /* offset of the current line's first byte */
    const char * file;
    wc_error_struct * err;
    long eline;         /* where the recorded error is (0: none) */
    long ecol;
    arena_block * arena;
}
reader;

static long
col_of(const reader * r, size_t off)
{
    size_t c = off - r->lstart + 1;

    return c > (size_t) LONG_MAX ? LONG_MAX : (long) c;
}

static int
fail_at(reader * r, long line, long col, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static int
fail_at(reader * r, long line, long col, const char * fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    wc_error_vset(r->err, WC_EINPUT, r->file, line, col, fmt, ap);
    va_end(ap);
    r->eline = line;
    r->ecol = col;
    return WC_EINPUT;
}

static int
nomem(reader * r)
{
    r->eline = 0;
    return wc_error_set(r->err, WC_EINTERNAL, r->file, 0, 0,
                        "out of memory");
}

/* An error at offset off of the current line whose message quotes
   s[a..b) once (fmt has one %s).  */
static int
fail_quoting(reader * r, size_t off, const char * fmt, size_t a, size_t b)
{
    char * t = _wc_show(r->s + a, b - a);
    int status;

    if (t == NULL)
        return nomem(r);
    status = fail_at(r, r->line, col_of(r, off), fmt, t);
    free(t);
    return status;
}

/* Error about the byte at r->pos, or the end of the input: what is
   "expected ..." (fmt has one %s: the byte found, quoted alone, so a
   byte of a longer character is shown by its code).  */
static int
fail_found(reader * r, const char * fmt)
{
    char shown[WC_QUOTE_SIZE(1)];

    if (r->pos >= r->len)
        return fail_at(r, r->line, col_of(r, r->pos),
                       "unexpected end of input");
    _wc_quote(shown, r->s + r->pos, 1, 1);
    return fail_at(r, r->line, col_of(r, r->pos), fmt, shown);
}

static void
skip_ws(reader * r)
{
    while (r->pos < r->len)
    {
        char c = r->s[r->pos];

        if (c == '\n')
        {
            r->pos++;
            r->line++;
            r->lstart = r->pos;
        }
        else if (c == ' ' || c == '\t' || c == '\r')
            r->pos++;
        else
            break;
    }
}

static int
hex_value(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

/* The four hex digits at s[i..i+4), all before end, as a code unit; -1
   when they are not four hex digits.  */
static long
hex4(const char * s, size_t i, size_t end)
{
    long u = 0;
    size_t k;

    if (end - i < 4)
        return -1;
    for (k = 0; k < 4; k++)
    {
        int h = hex_value(s[i + k]);

        if (h < 0)
            return -1;
        u = 16 * u + h;
    }
    return u;
}

static size_t
put_utf8(char * d, unsigned long u)
{
    if (u < 0x80)
    {
        d[0] = (char) u;
        return 1;
    }
    if (u < 0x800)
    {
        d[0] = (char) (0xc0 | (u >> 6));
        d[1] = (char) (0x80 | (u & 0x3f));
        return 2;
    }
    if (u < 0x10000)
    {
        d[0] = (char) (0xe0 | (u >> 12));
        d[1] = (char) (0x80 | ((u >> 6) & 0x3f));
        d[2] = (char) (0x80 | (u & 0x3f));
        return 3;
    }
    d[0] = (char) (0xf0 | (u >> 18));
    d[1] = (char) (0x80 | ((u >> 12) & 0x3f));
    d[2] = (char) (0x80 | ((u >> 6) & 0x3f));
    d[3] = (char) (0x80 | (u & 0x3f));
    return 4;
}

/* Are the bytes s[a..end) (fewer than 6) the start of an escape \uXXXX?  */
static int
escape_prefix(const char * s, size_t a, size_t end)
{
    size_t k;

    for (k = a; k < end; k++)
        if (k == a ? s[k] != '\\' : k == a + 1 ? s[k] != 'u'
            : hex_value(s[k]) < 0)
            return 0;
    return 1;
}

/* Decode the string body s[a..end) into d (room for end - a bytes), set
   *n to the decoded length.  cut says that the input itself ends the
   body (no closing quote): an escape cut short by the end is then left
   for the caller to report as an unterminated string; otherwise it is an
   invalid escape.  Returns WC_OK or an error.  */
static int
decode_string(reader * r, char * d, size_t * n, size_t a, size_t end,
              int cut)
{
    const unsigned char * s = (const unsigned char *) r->s;
    size_t i = a, j = 0;

    while (i < end)
    {
        if (s[i] != '\\')
        {
            size_t k = _wc_utf8_length(s + i, end - i);

            if (k == 0)
                return fail_at(r, r->line, col_of(r, i),
                               "invalid UTF-8 in string");
            memcpy(d + j, s + i, k);
            i += k;
            j += k;
            continue;
        }
        if (i + 1 >= end)
        {
            if (cut)
                break;
            return fail_quoting(r, i, "invalid escape '%s'", i, end);
        }
        switch (s[i + 1])
        {
        case '"':
        case '\\':
        case '/':
            d[j++] = (char) s[i + 1];
            break;
        case 'b':
            d[j++] = '\b';
            break;
        case 'f':
            d[j++] = '\f';
            break;
        case 'n':
            d[j++] = '\n';
            break;
        case 'r':
            d[j++] = '\r';
            break;
        case 't':
            d[j++] = '\t';
            break;
        case 'u':
        {
            long u = hex4(r->s, i + 2, end), v;
            size_t stop = end - i < 6 ? end : i + 6;

            if (u < 0)
            {
                /* cut short by the end of the input: report that */
                if (cut && end - i < 6 && escape_prefix(r->s, i, end))
                    goto done;
                return fail_quoting(r, i, "invalid escape '%s'", i, stop);
            }
            if (u >= 0xdc00 && u <= 0xdfff)
                return fail_quoting(r, i, "unpaired surrogate '%s'", i,
                                    i + 6);
            if (u >= 0xd800 && u <= 0xdbff)
            {
                if (end - i >= 12 && s[i + 6] == '\\' && s[i + 7] == 'u'
                    && (v = hex4(r->s, i + 8, end)) >= 0xdc00
                    && v <= 0xdfff)
                {
                    u = 0x10000 + ((u - 0xd800) << 10) + (v - 0xdc00);
                    i += 6;
                }
                else if (cut && end - i < 12
                         && escape_prefix(r->s, i + 6, end))
                    goto done;  /* the pair was cut by the end of input */
                else
                    return fail_quoting(r, i, "unpaired surrogate '%s'", i,
                                        i + 6);
            }
            j += put_utf8(d + j, (unsigned long) u);
            i += 6;
            continue;
        }
        default:
        {
            /* show the whole escaped character, however many bytes */
            size_t k = _wc_utf8_length(s + i + 1, end - i - 1);

            return fail_quoting(r, i, "invalid escape '%s'", i,
                                i + 1 + (k == 0 ? 1 : k));
        }
        }
        i += 2;
    }
done:
    *n = j;
    return WC_OK;
}

/* The string starting at the quote at r->pos into v.  */
static int
parse_string(reader * r, wc_json_node * v)
{
    const unsigned char * s = (const unsigned char *) r->s;
    size_t q = r->pos, i = q + 1, n = 0;
    int closed = 0, status;
    char * d;

    v->type = WC_JSON_STRING;
    v->line = r->line;
    v->col = col_of(r, q);
    /* find the end: a quote, a raw control byte or the end of input */
    while (i < r->len)
    {
        if (s[i] == '"')
        {
            closed = 1;
            break;
        }
        if (s[i] < 0x20)
            break;
        i += s[i] == '\\' && i + 1 < r->len ? 2 : 1;
    }
    if (i > r->len)
        i = r->len;
    d = arena_alloc(&r->arena, i - q);
    if (d == NULL)
        return nomem(r);
    status = decode_string(r, d, &n, q + 1, i, !closed && i == r->len);
    if (status != WC_OK)
        return status;
    if (!closed)
    {
        if (i < r->len)
            return fail_quoting(r, i, "control character '%s' in string", i,
                                i + 1);
        return fail_at(r, v->line, v->col, "unterminated string");
    }
    d[n] = '\0';
    v->text = d;
    v->len = n;
    r->pos = i + 1;
    return WC_OK;
}

static int
is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* Does s[a..b) follow RFC 8259's number grammar?  */
static int
number_ok(const char * s, size_t a, size_t b)
{
    size_t i = a, k;

    if (i < b && s[i] == '-')
        i++;
    if (i >= b || !is_digit(s[i]))
        return 0;
    if (s[i] == '0')
        i++;
    else
        while (i < b && is_digit(s[i]))
            i++;
    if (i < b && s[i] == '.')
    {
        k = ++i;
        while (i < b && is_digit(s[i]))
            i++;
        if (i == k)
            return 0;
    }
    if (i < b && (s[i] == 'e' || s[i] == 'E'))
    {
        i++;
        if (i < b && (s[i] == '+' || s[i] == '-'))
            i++;
        k = i;
        while (i < b && is_digit(s[i]))
            i++;
        if (i == k)
            return 0;
    }
    return i == b;
}

static int
parse_number(reader * r, wc_json_node * v)
{
    size_t a = r->pos, b = a;
    char * d;

    v->type = WC_JSON_NUMBER;
    v->line = r->line;
    v->col = col_of(r, a);
    /* the token is the longest run of bytes a number may contain, so
       that "01" or "1.e5" is one bad number rather than two values */
    while (b < r->len && (is_digit(r->s[b]) || r->s[b] == '-'
                          || r->s[b] == '+' || r->s[b] == '.'
                          || r->s[b] == 'e' || r->s[b] == 'E'))
        b++;
    if (!number_ok(r->s, a, b))
        return fail_quoting(r, a, "bad number '%s'", a, b);
    d = arena_alloc(&r->arena, b - a + 1);
    if (d == NULL)
        return nomem(r);
    memcpy(d, r->s + a, b - a);
    d[b - a] = '\0';
    v->text = d;
    v->len = b - a;
    r->pos = b;
    return WC_OK;
}

static int
is_word_char(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || is_digit(c)
        || c == '_';
}

static int
parse_literal(reader * r, wc_json_node * v)
{
    size_t a = r->pos, b = a;

    v->line = r->line;
    v->col = col_of(r, a);
    while (b < r->len && is_word_char(r->s[b]))
        b++;
    if (b - a == 4 && memcmp(r->s + a, "true", 4) == 0)
        v->type = WC_JSON_TRUE;
    else if (b - a == 5 && memcmp(r->s + a, "false", 5) == 0)
        v->type = WC_JSON_FALSE;
    else if (b - a == 4 && memcmp(r->s + a, "null", 4) == 0)
        v->type = WC_JSON_NULL;
    else
        return fail_quoting(r, a, "invalid literal '%s'", a, b);
    r->pos = b;
    return WC_OK;
}

/* Make room for one more element (per = 1) or member (per = 2) in v.  */
static int
grow(reader * r, wc_json_node * v, size_t * cap, size_t per)
{
    size_t need = per * (v->len + 1), ncap;
    wc_json_node * items;

    if (need <= *cap)
        return WC_OK;
    ncap = *cap < 8 ? 8 : *cap;
    while (ncap < need)
    {
        if (ncap > SIZE_MAX / 2 / sizeof(wc_json_node))
            return nomem(r);
        ncap *= 2;
    }
    if (ncap > SIZE_MAX / sizeof(wc_json_node))
        return nomem(r);
    items = realloc(v->items, ncap * sizeof(wc_json_node));
    if (items == NULL)
        return nomem(r);
    v->items = items;
    *cap = ncap;
    return WC_OK;
}

/* Give back the unused tail of a container's array.  */
static void
shrink(wc_json_node * v, size_t used)
{
    wc_json_node * items;

    if (used == 0)
    {
        free(v->items);
        v->items = NULL;
        return;
    }
    items = realloc(v->items, used * sizeof(wc_json_node));
    if (items != NULL)
        v->items = items;
}

typedef struct
{
    const wc_json_node * key;
    size_t index;
}
key_ref;

static int
key_cmp(const void * x, const void * y)
{
    const key_ref * a = x, * b = y;
    size_t n = a->key->len < b->key->len ? a->key->len : b->key->len;
    int c = memcmp(a->key->text, b->key->text, n);

    if (c != 0)
        return c;
    if (a->key->len != b->key->len)
        return a->key->len < b->key->len ? -1 : 1;
    return (a->index > b->index) - (a->index < b->index);
}

/* Among the first m keys of object v, the first (in file order) that
   repeats an earlier one: its index, or m when there is none (or when
   out of memory, with *oom set).  */
static size_t
first_duplicate(const wc_json_node * v, size_t m, int * oom)
{
    key_ref * refs;
    size_t i, best = m;

    *oom = 0;
    if (m < 2)
        return m;
    refs = malloc(m * sizeof(key_ref));
    if (refs == NULL)
    {
        *oom = 1;
        return m;
    }
    for (i = 0; i < m; i++)
    {
        refs[i].key = v->items + 2 * i;
        refs[i].index = i;
    }
    qsort(refs, m, sizeof(key_ref), key_cmp);
    /* equal keys sort by index: the second of a run is its first repeat */
    for (i = 0; i + 1 < m; i++)
        if (refs[i].key->len == refs[i + 1].key->len
            && memcmp(refs[i].key->text, refs[i + 1].key->text,
                      refs[i].key->len) == 0
            && refs[i + 1].index < best)
            best = refs[i + 1].index;
    free(refs);
    return best;
}

/* Report a duplicate among the first m keys of v, when there is one and
   it comes before the error already recorded (if any).  status is the
   status so far; returns the new one.  */
static int
check_duplicates(reader * r, const wc_json_node * v, size_t m, int status)
{
    int oom;
    size_t k;
    const wc_json_node * key;
    char * t;

    if (status == WC_EINTERNAL)
        return status;
    k = first_duplicate(v, m, &oom);
    if (oom)
        return nomem(r);
    if (k == m)
        return status;
    key = v->items + 2 * k;
    if (status != WC_OK && (r->eline < key->line
                            || (r->eline == key->line && r->ecol < key->col)))
        return status;
    t = _wc_show(key->text, key->len);
    if (t == NULL)
        return nomem(r);
    status = fail_at(r, key->line, key->col, "duplicate key '%s'", t);
    free(t);
    return status;
}

static int parse_value(reader * r, wc_json_node * v, int depth);

/* After an item of an array or object: a ',' (more to come, *done = 0)
   or the closing bracket (*done = 1), consumed; anything else fails.  */
static int
next_item(reader * r, char close, int * done)
{
    skip_ws(r);
    *done = 0;
    if (r->pos < r->len && r->s[r->pos] == ',')
    {
        r->pos++;
        return WC_OK;
    }
    if (r->pos < r->len && r->s[r->pos] == close)
    {
        r->pos++;
        *done = 1;
        return WC_OK;
    }
    return close == ']' ? fail_found(r, "expected ',' or ']', found '%s'")
                        : fail_found(r, "expected ',' or '}', found '%s'");
}

/* The array at r->pos ('[') into v; on error v is left clearable.  */
static int
parse_array(reader * r, wc_json_node * v, int depth)
{
    size_t cap = 0;
    int status = WC_OK, done;

    v->type = WC_JSON_ARRAY;
    r->pos++;
    skip_ws(r);
    if (r->pos < r->len && r->s[r->pos] == ']')
    {
        r->pos++;
        goto cleanup;
    }
    for (;;)
    {
        status = grow(r, v, &cap, 1);
        if (status != WC_OK)
            goto cleanup;
        node_zero(v->items + v->len);
        skip_ws(r);
        if (r->pos < r->len && r->s[r->pos] == ']')
        {
            status = fail_found(r, "expected a value, found '%s'");
            goto cleanup;
        }
        status = parse_value(r, v->items + v->len, depth);
        if (status != WC_OK)
        {
            node_clear(v->items + v->len);
            goto cleanup;
        }
        v->len++;
        status = next_item(r, ']', &done);
        if (status != WC_OK || done)
            break;
    }
cleanup:
    shrink(v, v->len);
    return status;
}

/* The object at r->pos ('{') into v; on error v is left clearable.  */
static int
parse_object(reader * r, wc_json_node * v, int depth)
{
    size_t cap = 0, keys = 0;
    int status = WC_OK, done;

    v->type = WC_JSON_OBJECT;
    r->pos++;
    skip_ws(r);
    if (r->pos < r->len && r->s[r->pos] == '}')
    {
        r->pos++;
        goto cleanup;
    }
    for (;;)
    {
        wc_json_node * key, * value;

        status = grow(r, v, &cap, 2);
        if (status != WC_OK)
            goto cleanup;
        key = v->items + 2 * v->len;
        value = key + 1;
        node_zero(key);
        node_zero(value);
        skip_ws(r);
        if (r->pos >= r->len || r->s[r->pos] != '"')
        {
            status = fail_found(r, "expected a string key, found '%s'");
            goto cleanup;
        }
        status = parse_string(r, key);
        if (status != WC_OK)
            goto cleanup;
        keys = v->len + 1;
        skip_ws(r);
        if (r->pos >= r->len || r->s[r->pos] != ':')
        {
            status = fail_found(r, "expected ':', found '%s'");
            goto cleanup;
        }
        r->pos++;
        skip_ws(r);
        status = parse_value(r, value, depth);
        if (status != WC_OK)
        {
            node_clear(value);
            goto cleanup;
        }
        v->len++;
        status = next_item(r, '}', &done);
        if (status != WC_OK || done)
            break;
    }
cleanup:
    status = check_duplicates(r, v, keys, status);
    shrink(v, 2 * v->len);
    return status;
}

/* The value at r->pos (whitespace skipped) into v, which the caller has
   zeroed.  depth is the number of containers around it.  On error v is
   left clearable (its containers hold only complete values).  */
static int
parse_value(reader * r, wc_json_node * v, int depth)
{
    char c;

    if (r->pos >= r->len)
        return fail_found(r, "expected a value, found '%s'");
    c = r->s[r->pos];
    if (c == '{' || c == '[')
    {
        v->line = r->line;
        v->col = col_of(r, r->pos);
        if (depth >= WC_JSON_MAX_DEPTH)
            return fail_at(r, v->line, v->col,
                           "nesting deeper than %d levels",
                           WC_JSON_MAX_DEPTH);
        return c == '{' ? parse_object(r, v, depth + 1)
                        : parse_array(r, v, depth + 1);
    }
    if (c == '"')
        return parse_string(r, v);
    if (c == '-' || is_digit(c))
        return parse_number(r, v);
    if (is_word_char(c))
        return parse_literal(r, v);
    return fail_found(r, "expected a value, found '%s'");
}

int
_wc_json_parse(wc_json_t J, const char * text, size_t len, const char * file,
              wc_error_t err)
{
    reader r;
    int status;

    _wc_json_clear(J);
    r.s = text;
    r.len = len;
    r.pos = 0;
    r.line = 1;
    r.lstart = 0;
    r.file = file;
    r.err = err;
    r.eline = 0;
    r.ecol = 0;
    r.arena = NULL;
    skip_ws(&r);
    status = parse_value(&r, &J->root, 0);
    if (status == WC_OK)
    {
        skip_ws(&r);
        if (r.pos < r.len)
            status = fail_found(&r, "unexpected '%s' after the JSON value");
    }
    J->arena = r.arena;
    if (status != WC_OK)
        _wc_json_clear(J);
    return status;
}
