/* json.h -- a small, strict JSON reader (RFC 8259) whose every value
   knows where it was written.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Used by `wrenchcone verify`, which must not depend on FLINT or cddlib:
   this file needs only the C library (and error.h).

   Strict means: one JSON value and nothing else but whitespace (space,
   tab, CR, LF); no NUL byte anywhere; strings in valid UTF-8 without raw
   control characters, escapes exactly those of RFC 8259 (\uXXXX decoded
   to UTF-8, surrogates only in pairs); numbers exactly as RFC 8259 writes
   them; no duplicate key in an object; containers nested at most
   WC_JSON_MAX_DEPTH deep.  The first error in file order is reported, as
   FILE:LINE:COL (1-based; the column counts bytes, a line ends at LF).  */

#ifndef WC_JSON_H
#define WC_JSON_H

#include <stddef.h>

#include "core/error.h"
#include "core/limits.h"
#include "core/text.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum
{
    WC_JSON_NULL = 0,
    WC_JSON_FALSE,
    WC_JSON_TRUE,
    WC_JSON_NUMBER,
    WC_JSON_STRING,
    WC_JSON_ARRAY,
    WC_JSON_OBJECT
}
wc_json_type;

/* One value.  Owned by the document it belongs to; never freed alone.  */
typedef struct wc_json_node_struct
{
    wc_json_type type;
    long line;          /* where the value starts: its first byte */
    long col;
    size_t len;         /* STRING: decoded bytes; NUMBER: bytes of the
                           literal; ARRAY: elements; OBJECT: members */
    const char * text;  /* STRING: the decoded UTF-8, NUL-terminated (it
                           may also hold NULs, from \u0000: use len);
                           NUMBER: the literal as written, NUL-terminated;
                           otherwise NULL */
    struct wc_json_node_struct * items;
                        /* ARRAY: len elements; OBJECT: 2 len nodes, each
                           member's key (a STRING) then its value, in file
                           order; otherwise NULL */
}
wc_json_node;

/* A parsed document.  */
typedef struct
{
    wc_json_node root;  /* WC_JSON_NULL at (0, 0) until a parse succeeds */
    void * arena;       /* private: storage of every text */
}
wc_json_struct;

typedef wc_json_struct wc_json_t[1];

void _wc_json_init(wc_json_t J);

/* Free everything J holds and make it as after _wc_json_init.  */
void _wc_json_clear(wc_json_t J);

/* Parse text[0..len) (any bytes; it need not be NUL-terminated) into J,
   replacing what J held.  file names the text in error records (may be
   NULL).  Returns WC_OK; WC_EINPUT with err located FILE:LINE:COL when
   the text is not one strict JSON value (J is then empty); WC_EINTERNAL
   when out of memory.  */
int _wc_json_parse(wc_json_t J, const char * text, size_t len,
                  const char * file, wc_error_t err);

/* The value of key in object o (the key compared as bytes, so a key
   holding a NUL never matches); NULL when o is not an object or has no
   such key.  Linear in the number of members.  */
const wc_json_node * _wc_json_object_get(const wc_json_node * o,
                                        const char * key);

/* Element i of an array, or the key / value of member i of an object;
   NULL when out of range or of the wrong type.  */
const wc_json_node * _wc_json_array_get(const wc_json_node * a, size_t i);
const wc_json_node * _wc_json_object_key(const wc_json_node * o, size_t i);
const wc_json_node * _wc_json_object_value(const wc_json_node * o,
                                          size_t i);

/* The type as a message names a value: "null", "true", "false",
   "a number", "a string", "an array", "an object".  */
const char * _wc_json_type_name(wc_json_type t);


#ifdef __cplusplus
}
#endif

#endif
