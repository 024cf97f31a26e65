/* cli-file.c -- the one writer of the program's output files: -o FILE of
   draw and report, and every --certificate=FILE.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   What the path names decides how it is written (wrenchcone(1), FILES):

   - nothing yet, or a regular file: a temporary file PATH.tmp-XXXXXX
     beside it is written, given the old file's permission bits (or those
     of a new file), and renamed over the path at the end, so that the
     path holds the old file or the new one, never a part of either.  A
     file without write permission for this user, or with none at all
     (0444, even for root), is refused as cp(1) refuses it;
   - a FIFO, a character device, or a symbolic link (followed by the
     kernel, with its checks): written through, in place, as a shell's
     ">" would: a device stays a device, a FIFO's reader gets the output,
     and /dev/stdout is standard output;
   - anything else (a directory, a block device) is refused.

   SIGHUP, SIGINT and SIGTERM while the temporary file exists remove it,
   then end the program as the signal would have; the library installs
   no handler.  The handler is here and only while a file is written.  */

#include <config.h>

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

/* The temporary file being written, or NULL; only changed while the
   caught signals are blocked, so that the handler sees it whole.  */
static char * volatile pending;

static const int caught[] = { SIGHUP, SIGINT, SIGTERM };
#define NCAUGHT ((int) (sizeof caught / sizeof caught[0]))

static void
on_signal(int sig)
{
    char * p = pending;

    if (p != NULL)
        unlink(p);
    signal(sig, SIG_DFL);
    raise(sig);         /* delivered, and fatal, once the handler returns */
}

/* The handler and the blocked signals around the temporary file's life.  */
typedef struct
{
    sigset_t set, prev;
    struct sigaction old[NCAUGHT];
    int installed[NCAUGHT];
}
guard;

static void
guard_block(guard * g)
{
    sigprocmask(SIG_BLOCK, &g->set, NULL);
}

static void
guard_unblock(guard * g)
{
    sigprocmask(SIG_SETMASK, &g->prev, NULL);
}

/* Install the handler, with the signals left blocked.  A signal that was
   ignored (nohup) stays ignored.  */
static void
guard_start(guard * g)
{
    struct sigaction sa;
    int i;

    sigemptyset(&g->set);
    for (i = 0; i < NCAUGHT; i++)
        sigaddset(&g->set, caught[i]);
    sigprocmask(SIG_BLOCK, &g->set, &g->prev);
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sa.sa_mask = g->set;
    for (i = 0; i < NCAUGHT; i++)
        g->installed[i] = sigaction(caught[i], NULL, g->old + i) == 0
            && g->old[i].sa_handler != SIG_IGN
            && sigaction(caught[i], &sa, NULL) == 0;
}

/* With the signals blocked: the old handlers back, then the old mask (a
   signal that came meanwhile is handled as it would have been).  */
static void
guard_end(guard * g)
{
    int i;

    for (i = 0; i < NCAUGHT; i++)
        if (g->installed[i])
            sigaction(caught[i], g->old + i, NULL);
    guard_unblock(g);
}

static int
failed(wc_error_t err, const char * path, const char * what, int e)
{
    return wc_error_set(err, WC_EINTERNAL, path, 0, 0,
                        "cannot write the %s: %s", what, strerror(e));
}

/* A regular file that must not be replaced: none of its write bits set,
   or not writable by this user.  0, or the errno to report.  */
static int
read_only(const char * path, const struct stat * st)
{
    if ((st->st_mode & 0222) == 0)
        return EACCES;
    return access(path, W_OK) != 0 ? errno : 0;
}

/* put(f, data) into f, then f closed.  WC_OK, or put's failure when it is
   not a write error (its error set), or the write error in err.  */
static int
put_and_close(FILE * f, const char * path, const char * what,
              int (*put)(FILE *, const void *), const void * data,
              wc_error_t err)
{
    int status = put(f, data), e = 0;

    if (ferror(f) || fflush(f) != 0)
        e = errno ? errno : EIO;
    if (fclose(f) != 0 && e == 0)
        e = errno ? errno : EIO;
    if (e == 0 && status != WC_OK && err->message == NULL)
        e = EIO;                /* put failed and did not say why */
    if (e != 0)                 /* whatever put said: one line, located */
        return failed(err, path, what, e);
    return status;
}

/* path written through a temporary file renamed over it; old: the regular
   file it replaces, or NULL.  */
static int
replace(const char * path, const char * what, const struct stat * old,
        int (*put)(FILE *, const void *), const void * data, wc_error_t err)
{
    size_t len = strlen(path) + sizeof ".tmp-XXXXXX";
    char * tmp = malloc(len);
    FILE * f = NULL;
    struct stat now;
    mode_t mode;
    guard g;
    int fd, status;

    if (tmp == NULL)
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    snprintf(tmp, len, "%s.tmp-XXXXXX", path);
    if (old != NULL)
        mode = old->st_mode & 0777;
    else
    {
        mode_t mask = umask(0);

        umask(mask);
        mode = 0666 & ~mask;    /* as a file fopen makes */
    }
    guard_start(&g);
    if ((fd = mkstemp(tmp)) >= 0)
        pending = tmp;
    guard_unblock(&g);
    if (fd < 0)
    {
        status = failed(err, path, what, errno);
        guard_block(&g);
        guard_end(&g);
        free(tmp);
        return status;
    }
    /* The old file's owner and group where this user may keep them; a
       group it cannot keep gets no access (it would be another group).  */
    if (old != NULL && fchown(fd, old->st_uid, old->st_gid) != 0
        && fchown(fd, (uid_t) -1, old->st_gid) != 0)
        mode &= ~(mode_t) 070;
    if (fchmod(fd, mode) != 0 || (f = fdopen(fd, "w")) == NULL)
    {
        status = failed(err, path, what, errno);
        close(fd);
    }
    else
        status = put_and_close(f, path, what, put, data, err);
    guard_block(&g);
    /* What the path names may have changed meanwhile: only a regular
       file, or nothing, is replaced.  */
    if (status == WC_OK && lstat(path, &now) == 0 && !S_ISREG(now.st_mode))
        status = wc_error_set(err, WC_EINTERNAL, path, 0, 0, "cannot write "
                              "the %s: no longer a regular file", what);
    if (status == WC_OK && rename(tmp, path) != 0)
        status = failed(err, path, what, errno);
    if (status != WC_OK)
        unlink(tmp);
    pending = NULL;
    guard_end(&g);
    free(tmp);
    return status;
}

/* path written in place: a FIFO, a character device, or what a symbolic
   link names.  */
static int
write_through(const char * path, const char * what,
              int (*put)(FILE *, const void *), const void * data,
              wc_error_t err)
{
    struct stat st;
    FILE * f = NULL;
    int fd = open(path, O_WRONLY | O_NOCTTY | O_CLOEXEC), e = 0;

    if (fd < 0)
        return errno == ENOENT
            ? wc_error_set(err, WC_EINTERNAL, path, 0, 0, "cannot write the "
                           "%s: a symbolic link to no file", what)
            : failed(err, path, what, errno);
    if (fstat(fd, &st) != 0)
        e = errno;
    else if (S_ISREG(st.st_mode))
    {
        if ((st.st_mode & 0222) == 0)
            e = EACCES;
        else if (ftruncate(fd, 0) != 0)
            e = errno;
    }
    else if (!S_ISFIFO(st.st_mode) && !S_ISCHR(st.st_mode))
    {
        close(fd);
        return wc_error_set(err, WC_EINTERNAL, path, 0, 0, "cannot write the "
                            "%s: not a regular file, FIFO or character "
                            "device", what);
    }
    if (e == 0 && (f = fdopen(fd, "w")) == NULL)
        e = errno;
    if (e != 0)
    {
        close(fd);
        return failed(err, path, what, e);
    }
    return put_and_close(f, path, what, put, data, err);
}

int
cli_write_file(const char * path, const char * what,
               int (*put)(FILE *, const void *), const void * data,
               wc_error_t err)
{
    struct stat st;
    int e;

    if (lstat(path, &st) != 0)
        return errno == ENOENT ? replace(path, what, NULL, put, data, err)
            : failed(err, path, what, errno);
    if (S_ISREG(st.st_mode))
        return (e = read_only(path, &st)) != 0
            ? failed(err, path, what, e)
            : replace(path, what, &st, put, data, err);
    if (S_ISDIR(st.st_mode))
        return failed(err, path, what, EISDIR);
    return write_through(path, what, put, data, err);
}
