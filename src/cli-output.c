/* cli-output.c -- writing a whole output file: figures and reports are
   written to a temporary file beside their destination and renamed at
   the end, so that no partial file is ever left; and -o FILE.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

int
cli_write_whole(const char * path, const char * what,
                int (*put)(FILE *, const void *), const void * data)
{
    size_t len = strlen(path);
    char * tmp = malloc(len + 16);
    FILE * f = NULL;
    int fd = -1, bad = 1, saved = 0;
    mode_t mask;

    if (tmp == NULL)
    {
        fputs(PROG ": out of memory\n", stderr);
        return WC_EINTERNAL;
    }
    snprintf(tmp, len + 16, "%s.tmp-XXXXXX", path);
    mask = umask(0);            /* mkstemp makes 0600; the file is for */
    umask(mask);                /* everyone, as one that fopen makes */
    if ((fd = mkstemp(tmp)) >= 0 && fchmod(fd, 0666 & ~mask) == 0
        && (f = fdopen(fd, "w")) != NULL)
    {
        bad = put(f, data) != WC_OK;
        saved = errno;
        bad |= fclose(f) != 0;
        if (!bad && rename(tmp, path) != 0)
            bad = 1;
        saved = errno;
        if (bad)
            remove(tmp);
    }
    else
    {
        saved = errno;
        if (fd >= 0)
        {
            close(fd);
            remove(tmp);
        }
    }
    free(tmp);
    if (bad)
    {
        return cli_file_error(WC_EINTERNAL, path, "cannot write the %s: %s",
                              what, strerror(saved ? saved : EIO));
    }
    return WC_OK;
}

char **
cli_expand_output(int argc, char ** argv, char *** owned, int * nowned)
{
    char ** v = malloc(sizeof(char *) * (argc + 1));
    int i, j = 0;

    *nowned = 0;
    *owned = malloc(sizeof(char *) * (argc + 1));
    if (v == NULL || *owned == NULL)
    {
        free(v);
        return NULL;
    }
    for (i = 0; i < argc; i++)
    {
        const char * file = NULL;

        if (strcmp(argv[i], "--") == 0)
        {
            while (i < argc)
                v[j++] = argv[i++];
            break;
        }
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
            file = argv[++i];
        else if (strncmp(argv[i], "-o", 2) == 0 && argv[i][2] != '\0')
            file = argv[i] + 2;
        if (file == NULL)
            v[j++] = argv[i];
        else
        {
            char * s = malloc(strlen(file) + 10);

            if (s == NULL)
                break;
            sprintf(s, "--output=%s", file);
            (*owned)[(*nowned)++] = s;
            v[j++] = s;
        }
    }
    v[j] = NULL;
    if (i < argc)
    {
        free(v);
        return NULL;
    }
    return v;
}

int
cli_run_with_output(int (*run)(const cli_command *, int, char **),
                    const cli_command * self, int argc, char ** argv)
{
    char ** v, ** owned = NULL;
    int status, nowned = 0, i;

    if ((v = cli_expand_output(argc, argv, &owned, &nowned)) == NULL)
    {
        for (i = 0; owned != NULL && i < nowned; i++)
            free(owned[i]);
        free(owned);
        fputs(PROG ": out of memory\n", stderr);
        return WC_EINTERNAL;
    }
    for (i = 0; v[i] != NULL; i++)
        ;
    status = run(self, i, v);
    for (i = 0; i < nowned; i++)
        free(owned[i]);
    free(owned);
    free(v);
    return status;
}
