/* readall.c -- the whole of an input as one buffer, with a size bound;
   the one place that opens an input file (readall.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/readall.h"

static int
too_large(wc_error_t err, const char * name, size_t max)
{
    return wc_error_set(err, WC_EINPUT, name, 0, 0,
                        "file too large (over %lu bytes)",
                        (unsigned long) max);
}

/* _wc_read_all, the buffer first sized for hint bytes (a regular file's
   size; 0 when unknown).  The buffer never grows past max + 1 bytes, and
   no more than that is read: one byte over the bound is enough to know.  */
static int
read_stream(char ** text, size_t * len, FILE * f, const char * name,
            size_t max, size_t hint, wc_error_t err)
{
    size_t cap = max < (size_t) -1 ? max + 1 : max;
    size_t alloc = hint >= 4096 && hint < cap ? hint + 1 : 4096, n = 0, r;
    char * buf;
    int status = WC_OK;

    if (alloc > cap)
        alloc = cap;
    buf = malloc(alloc);
    *text = NULL;
    *len = 0;
    while (buf != NULL && (r = fread(buf + n, 1, alloc - n, f)) > 0)
    {
        n += r;
        if (n > max)
        {
            status = too_large(err, name, max);
            break;
        }
        if (n == alloc)
        {
            size_t grown = alloc <= cap / 2 ? alloc * 2 : cap;
            char * p = realloc(buf, grown);

            if (p == NULL)
                free(buf);
            buf = p;
            alloc = grown;
        }
    }
    if (status != WC_OK)
        ;
    else if (buf == NULL)
        status = wc_error_set(err, WC_EINTERNAL, name, 0, 0, "out of memory");
    else if (ferror(f))
        /* A directory is a wrong argument; anything else is an I/O
           failure.  */
        status = wc_error_set(err, errno == EISDIR ? WC_EINPUT : WC_EINTERNAL,
                              name, 0, 0, "read error: %s", strerror(errno));
    if (status != WC_OK)
    {
        free(buf);
        return status;
    }
    *text = buf;
    *len = n;
    return WC_OK;
}

int
_wc_read_all(char ** text, size_t * len, FILE * f, const char * name,
             size_t max, wc_error_t err)
{
    return read_stream(text, len, f, name, max, 0, err);
}

void
_wc_file_id_of(_wc_file_id * id, FILE * f)
{
    struct stat st;
    int fd = f != NULL ? fileno(f) : -1;

    memset(id, 0, sizeof *id);
    if (fd >= 0 && fstat(fd, &st) == 0)
    {
        id->set = 1;
        id->regular = S_ISREG(st.st_mode) != 0;
        id->dev = (unsigned long long) st.st_dev;
        id->ino = (unsigned long long) st.st_ino;
    }
}

int
_wc_file_id_same(const _wc_file_id * a, const _wc_file_id * b)
{
    return a != NULL && b != NULL && a->set && b->set && a->dev == b->dev
        && a->ino == b->ino;
}

/* Whether st is the file avoid names.  */
static int
same_file(const struct stat * st, const _wc_file_id * avoid)
{
    _wc_file_id id;

    id.set = 1;
    id.regular = S_ISREG(st->st_mode) != 0;
    id.dev = (unsigned long long) st->st_dev;
    id.ino = (unsigned long long) st->st_ino;
    return _wc_file_id_same(&id, avoid);
}

/* What a request may not read, by st; WC_OK when it may.  */
static int
refuse_for_request(const struct stat * st, const char * name,
                   const _wc_file_id * avoid, wc_error_t err)
{
    if (same_file(st, avoid))
        return wc_error_set(err, WC_EINPUT, name, 0, 0, "the batch's own "
                            "input: a request cannot read it");
    if (S_ISDIR(st->st_mode))
        return wc_error_set(err, WC_EINPUT, name, 0, 0, "read error: %s",
                            strerror(EISDIR));
    if (!S_ISREG(st->st_mode))
        return wc_error_set(err, WC_EINPUT, name, 0, 0, "not a regular "
                            "file (a request reads regular files only)");
    return WC_OK;
}

/* path opened for reading into *fd, its status in *st; see readall.h.  */
static int
open_input(int * fd, struct stat * st, const char * path, const char * name,
           int flags, const _wc_file_id * avoid, wc_error_t err)
{
    int oflags = O_RDONLY | O_NOCTTY | O_CLOEXEC, status;

    *fd = -1;
    if (flags & _WC_READ_REGULAR)
    {
        /* Decided before opening: opening a device or a FIFO can act on
           it (wake a FIFO's writer), and must not block.  */
        if (stat(path, st) != 0)
            return wc_error_set(err, WC_EINPUT, name, 0, 0,
                                "cannot open: %s", strerror(errno));
        if ((status = refuse_for_request(st, name, avoid, err)) != WC_OK)
            return status;
        oflags |= O_NONBLOCK;
    }
    if ((*fd = open(path, oflags)) < 0)
        return wc_error_set(err, WC_EINPUT, name, 0, 0, "cannot open: %s",
                            strerror(errno));
    if (fstat(*fd, st) != 0)
        status = wc_error_set(err, WC_EINTERNAL, name, 0, 0,
                              "read error: %s", strerror(errno));
    else if (flags & _WC_READ_REGULAR)
        /* Again on what was opened: the path may name another file now.  */
        status = refuse_for_request(st, name, avoid, err);
    else if (S_ISDIR(st->st_mode))
        status = wc_error_set(err, WC_EINPUT, name, 0, 0, "read error: %s",
                              strerror(EISDIR));
    else
        status = WC_OK;
    if (status != WC_OK)
    {
        close(*fd);
        *fd = -1;
    }
    return status;
}

int
_wc_read_file(char ** text, size_t * len, const char * path,
              const char * name, size_t max, int flags,
              const _wc_file_id * avoid, wc_error_t err)
{
    struct stat st;
    size_t hint = 0;
    FILE * f;
    int fd, status;

    *text = NULL;
    *len = 0;
    if ((status = open_input(&fd, &st, path, name, flags, avoid, err))
        != WC_OK)
        return status;
    if (S_ISREG(st.st_mode))
    {
        /* Known too large from its size: not a byte read.  (A file of
           /proc says 0 and is read.)  */
        if (st.st_size > 0 && (unsigned long long) st.st_size > max)
        {
            close(fd);
            return too_large(err, name, max);
        }
        hint = (size_t) st.st_size;
    }
    if ((f = fdopen(fd, "rb")) == NULL)
    {
        close(fd);
        return wc_error_set(err, WC_EINTERNAL, name, 0, 0, "out of memory");
    }
    status = read_stream(text, len, f, name, max, hint, err);
    fclose(f);
    return status;
}

int
_wc_open_file(FILE ** f, const char * path, const char * name,
              wc_error_t err)
{
    struct stat st;
    int fd, status = open_input(&fd, &st, path, name, 0, NULL, err);

    *f = NULL;
    if (status != WC_OK)
        return status;
    if ((*f = fdopen(fd, "r")) == NULL)
    {
        close(fd);
        return wc_error_set(err, WC_EINTERNAL, name, 0, 0, "out of memory");
    }
    return WC_OK;
}
