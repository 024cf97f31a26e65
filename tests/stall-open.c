/* stall-open.c -- a preloaded library for tests/cli-outfiles.sh: the
   program stops for good in the first fdopen of a temporary output file
   (a name with ".tmp-" in it), after creating the file named by
   WC_STALL_MARK, so that the test knows the temporary file exists and
   the program waits there for its signal.  Not part of the program.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

FILE *
fdopen(int fd, const char * mode)
{
    FILE * (*real)(int, const char *) =
        (FILE * (*)(int, const char *)) dlsym(RTLD_NEXT, "fdopen");
    const char * mark = getenv("WC_STALL_MARK");
    char link[64], name[4096];
    ssize_t n;

    snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    n = readlink(link, name, sizeof name - 1);
    if (mark != NULL && n > 0)
    {
        name[n] = '\0';
        if (strstr(name, ".tmp-") != NULL)
        {
            int m = open(mark, O_WRONLY | O_CREAT | O_TRUNC, 0600);

            if (m >= 0)
                close(m);
            for (;;)
                pause();
        }
    }
    return real(fd, mode);
}
