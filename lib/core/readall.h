/* readall.h -- the whole of an input as one buffer, with a size bound;
   the one place that opens an input file.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Internal (not installed).  Plain C and POSIX only, so that the
   certificate checker's program reads its input the same way as the
   request layer reads problems.

   Two kinds of reader open files here.  The command line reads what its
   user names: a regular file, or a FIFO or character device such as
   /dev/stdin or a shell's <(...), blocking until a FIFO has a writer.
   A request (a batch line, wc_request_json, the Python module) reads
   regular files only: it is opened without blocking, and anything else
   is refused before a byte is read, so that no request can read the
   stream its batch reads, wait forever on a FIFO, or read a device
   without end.  */

#ifndef WC_READALL_H
#define WC_READALL_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Which file an open stream is: set is 0 when it is none (a memory
   stream); regular when it is a regular file.  */
typedef struct
{
    int set, regular;
    unsigned long long dev, ino;
}
_wc_file_id;

/* *id := the file f reads or writes; id->set 0 when f has no file
   descriptor or fstat fails.  */
void _wc_file_id_of(_wc_file_id * id, FILE * f);

/* Whether a and b are set and the same file.  */
int _wc_file_id_same(const _wc_file_id * a, const _wc_file_id * b);

/* _wc_read_file's flags.  */
enum
{
    _WC_READ_REGULAR = 1        /* a request's: a regular file only */
};

/* Read f to its end into a malloc'd buffer (*text, *len bytes, the caller
   frees it), at most max bytes: it reads no more than max + 1 bytes and
   holds no more than max + 1 in memory; name locates the errors.  More
   than max bytes is WC_EINPUT ("file too large"), a directory WC_EINPUT,
   any other read failure or exhausted memory WC_EINTERNAL; *text is then
   NULL.  */
int _wc_read_all(char ** text, size_t * len, FILE * f, const char * name,
                 size_t max, wc_error_t err);

/* The file path, opened (the command line's way, or with
   _WC_READ_REGULAR a request's, see above), and read with _wc_read_all;
   errors are located at name.  A regular file larger than max is refused
   from its size, unread.  A file that cannot be opened, a directory, and
   with _WC_READ_REGULAR anything but a regular file or the file avoid
   names (a batch's own input; NULL or unset: none) are WC_EINPUT.  */
int _wc_read_file(char ** text, size_t * len, const char * path,
                  const char * name, size_t max, int flags,
                  const _wc_file_id * avoid, wc_error_t err);

/* The file path opened for reading the command line's way (a FIFO or
   device is fine; a directory is refused): *f, the caller fcloses it.
   For a stream read line by line, such as a batch's FILE.  */
int _wc_open_file(FILE ** f, const char * path, const char * name,
                  wc_error_t err);

#ifdef __cplusplus
}
#endif

#endif
