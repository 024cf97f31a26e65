/* cli-output.c -- -o FILE of draw and report, read as --output=FILE
   (cli-file.c writes the file).

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
