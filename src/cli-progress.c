/* cli-progress.c -- showing the library's progress reports on stderr.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   On a terminal, a run that lasts over a second shows one line that it
   rewrites at most four times a second and erases when the stage ends or
   anything else is written to stderr.  With --progress the reports go to
   stderr whatever it is, from the start: the first and the last report of
   each stage always, others at most four times a second, one per line
   when stderr is not a terminal.  Nothing is ever written to stdout, and
   nothing here decides anything about the answer.  */

#include <config.h>

#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"

static struct
{
    int forced;         /* --progress */
    int tty;            /* stderr is a terminal */
    int shown;          /* a terminal line is on screen */
    long long start, last;      /* milliseconds */
    const char * stage;
}
progress;

static long long
now_ms(void)
{
    struct timespec t;

    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long) t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

static void
report(void * ctx, const char * stage, slong done, slong total)
{
    long long t = now_ms();
    int first = progress.stage == NULL || strcmp(stage, progress.stage) != 0;
    int last = done >= total;
    long pct = total > 0 ? (long) (done * 100 / total) : 100;

    (void) ctx;
    if (!progress.forced && t - progress.start < 1000)
        return;
    /* The hook is installed only when forced or on a terminal, and both
       show the first and the last report of a stage.  */
    if (!first && !last && t - progress.last < 250)
        return;
    progress.last = t;
    progress.stage = stage;
    if (progress.tty && last)
        cli_progress_clear();
    else if (progress.tty)
    {
        fprintf(stderr, "\r" PROG ": %s: %ld/%ld (%ld%%)\033[K", stage,
                (long) done, (long) total, pct);
        progress.shown = 1;
    }
    else
        fprintf(stderr, PROG ": %s: %ld/%ld (%ld%%)\n", stage, (long) done,
                (long) total, pct);
    fflush(stderr);
}

/* Options are read after cli_progress_start: --progress installs the
   hook itself.  */
void
cli_progress_force(void)
{
    progress.forced = 1;
    wc_progress_set(report, NULL);
}

void
cli_progress_start(void)
{
    progress.tty = isatty(2);
    progress.start = progress.last = now_ms();
    if (progress.tty)
        wc_progress_set(report, NULL);
}

void
cli_progress_clear(void)
{
    if (progress.shown)
        fputs("\r\033[K", stderr);
    progress.shown = 0;
}
