/* jsontree.c -- looking up values in a parsed JSON document.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Plain C and libc only (see json.h).  */

#include <string.h>

#include "core/json.h"

const wc_json_node *
_wc_json_array_get(const wc_json_node * a, size_t i)
{
    if (a == NULL || a->type != WC_JSON_ARRAY || i >= a->len)
        return NULL;
    return a->items + i;
}

const wc_json_node *
_wc_json_object_key(const wc_json_node * o, size_t i)
{
    if (o == NULL || o->type != WC_JSON_OBJECT || i >= o->len)
        return NULL;
    return o->items + 2 * i;
}

const wc_json_node *
_wc_json_object_value(const wc_json_node * o, size_t i)
{
    if (o == NULL || o->type != WC_JSON_OBJECT || i >= o->len)
        return NULL;
    return o->items + 2 * i + 1;
}

const wc_json_node *
_wc_json_object_get(const wc_json_node * o, const char * key)
{
    size_t n, i;

    if (o == NULL || o->type != WC_JSON_OBJECT)
        return NULL;
    n = strlen(key);
    for (i = 0; i < o->len; i++)
    {
        const wc_json_node * k = o->items + 2 * i;

        if (k->len == n && memcmp(k->text, key, n) == 0)
            return o->items + 2 * i + 1;
    }
    return NULL;
}

const char *
_wc_json_type_name(wc_json_type t)
{
    switch (t)
    {
    case WC_JSON_NULL:
        return "null";
    case WC_JSON_FALSE:
        return "false";
    case WC_JSON_TRUE:
        return "true";
    case WC_JSON_NUMBER:
        return "a number";
    case WC_JSON_STRING:
        return "a string";
    case WC_JSON_ARRAY:
        return "an array";
    case WC_JSON_OBJECT:
        return "an object";
    }
    return "a value";
}
