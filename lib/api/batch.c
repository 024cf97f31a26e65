/* batch.c -- requests a line each, answered in order by one thread or
   several (batch.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   With jobs > 1 the calling thread reads lines into a ring of 4 * jobs
   slots, the workers take them in order and answer them, and whichever
   worker finds the oldest unwritten answer done writes it, and the ones
   after it that are done, with the lock released while it writes (one
   writer at a time).  So answers leave in the order of the lines, each
   as soon as it and every earlier one are done, while the reader may be
   blocked on a pipe waiting for the next request.  */

#include <config.h>

#include <errno.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

#include "api/batch.h"
#include "api/request.h"
#include "api/run.h"
#include "core/thread.h"

/* A line without its end ("\n", "\r\n"), so that an error at the end of
   the request is located on its line; 0 for a blank line.  */
static size_t
request_length(const char * line, ssize_t n)
{
    if (strspn(line, " \t\r\n") == (size_t) n)
        return 0;
    if (n > 0 && line[n - 1] == '\n')
        n--;
    if (n > 0 && line[n - 1] == '\r')
        n--;
    return (size_t) n;
}

/* The batch's status after an answer of status st (wc_batch): an error
   record (1, 2, 3) outranks a comparison beyond its tolerance (4), which
   is an answer, and of two errors the larger status wins, so that an
   internal failure is never hidden behind a disagreement.  */
static int
worse(int worst, int st)
{
    int rw = worst == WC_EDISAGREE ? 1 : worst == WC_OK ? 0 : worst + 1;
    int rs = st == WC_EDISAGREE ? 1 : st == WC_OK ? 0 : st + 1;

    return rs > rw ? st : worst;
}

static int
write_failed(wc_error_t err)
{
    return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "write error: %s",
                        strerror(errno));
}

static int
read_failed(wc_error_t err, const char * name, int e)
{
    return wc_error_set(err, WC_EINTERNAL, name, 0, 0, "read error: %s",
                        strerror(e));
}

/* jobs == 1: the calling thread, a line at a time.  */
static int
batch_serial(int * worst, FILE * out, FILE * in, const char * name,
             const _wc_file_id * avoid, wc_error_t err)
{
    char * line = NULL, * ans = NULL;
    size_t cap = 0, len, anslen = 0;
    ssize_t n;
    long lineno = 0;
    int status = WC_OK, st;

    while ((n = getline(&line, &cap, in)) >= 0)
    {
        lineno++;
        if ((len = request_length(line, n)) == 0)
            continue;
        st = _wc_request_json_avoid(&ans, &anslen, line, len, name, lineno,
                                    avoid, err);
        if (ans == NULL)
        {
            status = WC_EINTERNAL;      /* err says why */
            break;
        }
        fwrite(ans, 1, anslen, out);
        free(ans);
        ans = NULL;
        if (fflush(out) != 0 || ferror(out))
        {
            status = write_failed(err);
            break;
        }
        *worst = worse(*worst, st);
    }
    if (status == WC_OK && ferror(in))
        status = read_failed(err, name, errno);
    free(line);
    return status;
}

/* ------------------------------------------------------------------ */
/* jobs > 1                                                            */

typedef struct
{
    char * line;        /* the request, owned; NULL once answered */
    size_t len;
    long lineno;
    char * ans;         /* the answer, owned, or NULL (out of memory) */
    size_t anslen;
    char * why;         /* when ans is NULL: the error, formatted */
    int status;
    int done;
}
slot;

typedef struct
{
    pthread_mutex_t lock;
    pthread_cond_t work;        /* a line to answer, or the end */
    pthread_cond_t room;        /* an answer written: a slot is free */
    slot * slots;
    size_t cap;
    size_t nin;                 /* lines read into slots */
    size_t ntake;               /* lines taken by workers */
    size_t nout;                /* answers written */
    int eof;                    /* the reader is done */
    int stop;                   /* a failure: answer and write no more */
    int writing;                /* a worker is writing answers */
    FILE * out;
    const char * name;
    const _wc_file_id * avoid;  /* in's file: no request reads it */
    int worst;
    int status;
    wc_error_struct * err;
}
batch;

/* Write the answers that are next in order and done.  Called with the
   lock held; returns with it held.  */
static void
write_ready(batch * B)
{
    if (B->writing)
        return;                 /* that writer will see ours too */
    B->writing = 1;
    while (!B->stop && B->nout < B->nin && B->slots[B->nout % B->cap].done)
    {
        slot * s = B->slots + B->nout % B->cap;
        char * ans = s->ans, * why = s->why;
        size_t anslen = s->anslen;
        int st = s->status, ok = 1, e = 0;

        s->ans = s->why = NULL;
        s->done = 0;
        pthread_mutex_unlock(&B->lock);
        if (ans != NULL)
        {
            fwrite(ans, 1, anslen, B->out);
            ok = fflush(B->out) == 0 && !ferror(B->out);
            e = errno;
            free(ans);
        }
        pthread_mutex_lock(&B->lock);
        if (ans == NULL)
        {
            B->status = wc_error_set(B->err, WC_EINTERNAL, NULL, 0, 0, "%s",
                                     why != NULL ? why : "out of memory");
            B->stop = 1;
        }
        else if (!ok)
        {
            errno = e;
            B->status = write_failed(B->err);
            B->stop = 1;
        }
        else
        {
            B->worst = worse(B->worst, st);
            B->nout++;
        }
        free(why);
        pthread_cond_broadcast(&B->room);
        if (B->stop)
            pthread_cond_broadcast(&B->work);
    }
    B->writing = 0;
}

static void *
worker(void * arg)
{
    batch * B = arg;
    wc_error_t err;

    _wc_thread_enter();
    wc_error_init(err);
    pthread_mutex_lock(&B->lock);
    for (;;)
    {
        slot * s;
        char * ans = NULL, * why = NULL;
        size_t anslen = 0;
        int st;

        while (!B->stop && !B->eof && B->ntake == B->nin)
            pthread_cond_wait(&B->work, &B->lock);
        if (B->stop || B->ntake == B->nin)
            break;
        s = B->slots + B->ntake++ % B->cap;
        pthread_mutex_unlock(&B->lock);
        /* The slot is this worker's until it is marked done.  */
        st = _wc_request_json_avoid(&ans, &anslen, s->line, s->len,
                                    B->name, s->lineno, B->avoid, err);
        if (ans == NULL)
            why = wc_error_format(err);
        free(s->line);
        s->line = NULL;
        pthread_mutex_lock(&B->lock);
        s->ans = ans;
        s->anslen = anslen;
        s->why = why;
        s->status = st;
        s->done = 1;
        write_ready(B);
    }
    pthread_mutex_unlock(&B->lock);
    wc_error_clear(err);
    return NULL;
}

/* Read the lines into the ring until the end, a read error or a stop;
   then wait for every answer to be written.  Returns errno of a read
   error, else 0.  */
static int
read_lines(batch * B, FILE * in)
{
    char * line = NULL;
    size_t cap = 0, len;
    ssize_t n;
    long lineno = 0;
    int e = 0, stop = 0;

    while (!stop && (n = getline(&line, &cap, in)) >= 0)
    {
        slot * s;

        lineno++;
        if ((len = request_length(line, n)) == 0)
            continue;
        pthread_mutex_lock(&B->lock);
        while (!B->stop && B->nin - B->nout >= B->cap)
            pthread_cond_wait(&B->room, &B->lock);
        if (!(stop = B->stop))
        {
            s = B->slots + B->nin++ % B->cap;
            s->line = line;     /* the slot owns it now */
            s->len = len;
            s->lineno = lineno;
            line = NULL;
            cap = 0;
            pthread_cond_signal(&B->work);
        }
        pthread_mutex_unlock(&B->lock);
    }
    if (!stop && ferror(in))
        e = errno;
    free(line);
    pthread_mutex_lock(&B->lock);
    B->eof = 1;
    pthread_cond_broadcast(&B->work);
    while (!B->stop && B->nout < B->nin)
        pthread_cond_wait(&B->room, &B->lock);
    pthread_mutex_unlock(&B->lock);
    return e;
}

static int
batch_threads(int * worst, FILE * out, FILE * in, const char * name,
              int jobs, const _wc_file_id * avoid, wc_error_t err)
{
    batch B;
    pthread_t * tid = NULL;
    int i, started = 0, e;
    size_t k;

    memset(&B, 0, sizeof B);
    B.cap = 4 * (size_t) jobs;
    B.out = out;
    B.name = name;
    B.avoid = avoid;
    B.worst = *worst;
    B.status = WC_OK;
    B.err = err;
    B.slots = calloc(B.cap, sizeof *B.slots);
    tid = malloc(jobs * sizeof *tid);
    if (B.slots == NULL || tid == NULL)
    {
        free(B.slots);
        free(tid);
        return wc_error_set(err, WC_EINTERNAL, NULL, 0, 0, "out of memory");
    }
    pthread_mutex_init(&B.lock, NULL);
    pthread_cond_init(&B.work, NULL);
    pthread_cond_init(&B.room, NULL);
    for (i = 0; i < jobs; i++)
        if (pthread_create(tid + started, NULL, worker, &B) == 0)
            started++;
    if (started == 0)
        B.status = batch_serial(&B.worst, out, in, name, avoid, err);
    else
    {
        e = read_lines(&B, in);
        for (i = 0; i < started; i++)
            pthread_join(tid[i], NULL);
        if (B.status == WC_OK && e != 0)
            B.status = read_failed(err, name, e);
    }
    /* After a stop: the lines and answers nobody wrote.  */
    for (k = 0; k < B.cap; k++)
    {
        free(B.slots[k].line);
        free(B.slots[k].ans);
        free(B.slots[k].why);
    }
    pthread_cond_destroy(&B.room);
    pthread_cond_destroy(&B.work);
    pthread_mutex_destroy(&B.lock);
    free(B.slots);
    free(tid);
    *worst = B.worst;
    return B.status;
}

int
wc_batch(int * worst, FILE * out, FILE * in, const char * name, int jobs,
         wc_error_t err)
{
    _wc_file_id avoid, outid;

    *worst = WC_OK;
    if (jobs < 1 || jobs > WC_BATCH_MAX_JOBS)
        return wc_error_set(err, WC_EUSAGE, NULL, 0, 0, "jobs must be from "
                            "1 to %d, not %d", WC_BATCH_MAX_JOBS, jobs);
    _wc_thread_enter();
    /* A request naming the batch's own input (/dev/stdin, its path)
       would read the requests after it as its problem.  */
    _wc_file_id_of(&avoid, in);
    /* `batch F >> F` would answer its own answers without end.  */
    _wc_file_id_of(&outid, out);
    if (avoid.regular && _wc_file_id_same(&avoid, &outid))
        return wc_error_set(err, WC_EINPUT, name, 0, 0, "the batch's input "
                            "is also its output");
    return jobs == 1 ? batch_serial(worst, out, in, name, &avoid, err)
        : batch_threads(worst, out, in, name, jobs, &avoid, err);
}
