/* fuzzutil.h -- what the libFuzzer targets in fuzz/ share: capturing a
   printer's output in memory, and stopping with a message when a
   property fails (libFuzzer then keeps the input as a crash).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Not part of the library: only the fuzz targets include it
   (doc/fuzzing.md, tests/fuzz.sh).  */

#ifndef WC_FUZZUTIL_H
#define WC_FUZZUTIL_H

/* open_memstream; include this header first.  */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wrenchcone.h"

/* Stop the run: the property in the message does not hold.  */
#define FUZZ_REQUIRE(cond, ...)                                          \
    do {                                                                 \
        if (!(cond))                                                     \
        {                                                                \
            fprintf(stderr, "%s:%d: property failed: %s: ",              \
                    __FILE__, __LINE__, #cond);                          \
            fprintf(stderr, __VA_ARGS__);                                \
            fputc('\n', stderr);                                         \
            abort();                                                     \
        }                                                                \
    } while (0)

/* A growing in-memory file: open_memstream with its buffer.  */
typedef struct
{
    FILE * f;
    char * buf;
    size_t len;
}
fuzz_out;

static inline void
fuzz_out_open(fuzz_out * o)
{
    o->buf = NULL;
    o->len = 0;
    o->f = open_memstream(&o->buf, &o->len);
    FUZZ_REQUIRE(o->f != NULL, "open_memstream failed");
}

/* Close the stream; o->buf (NUL-terminated, o->len bytes) stays until
   fuzz_out_free.  */
static inline void
fuzz_out_close(fuzz_out * o)
{
    FUZZ_REQUIRE(fclose(o->f) == 0, "fclose failed");
    o->f = NULL;
}

static inline void
fuzz_out_free(fuzz_out * o)
{
    free(o->buf);
    o->buf = NULL;
    o->len = 0;
}

/* An input error must be located: a file, a line and a column, and a
   message.  */
static inline void
fuzz_require_located(const wc_error_t err, const char * file)
{
    FUZZ_REQUIRE(err->message != NULL && err->message[0] != '\0',
                 "an input error without a message");
    FUZZ_REQUIRE(err->file != NULL && strcmp(err->file, file) == 0,
                 "error '%s' names file '%s', not '%s'", err->message,
                 err->file ? err->file : "(null)", file);
    FUZZ_REQUIRE(err->line >= 1 && err->col >= 1,
                 "error '%s' is not located (line %ld, col %ld)",
                 err->message, err->line, err->col);
    FUZZ_REQUIRE(strchr(err->message, '\n') == NULL,
                 "error message '%s' spans lines", err->message);
}

#endif
