/* cmd-batch.c -- wrenchcone batch: JSON Lines requests in, one answer
   line out per request, in order, through the library's request entry
   point (api/request.h).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#include <config.h>

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "commands.h"

/* Answer every line of f (named name); the exit status.  */
static int
answer_lines(FILE * f, const char * name)
{
    char * line = NULL, * out = NULL;
    size_t cap = 0, outlen = 0;
    ssize_t n;
    long lineno = 0;
    int worst = WC_OK, status;
    wc_error_t err;

    wc_error_init(err);
    while ((n = getline(&line, &cap, f)) >= 0)
    {
        lineno++;
        if (strspn(line, " \t\r\n") == (size_t) n)
            continue;
        /* The line without its end, so that an error at the end of the
           request is located on its line.  */
        if (n > 0 && line[n - 1] == '\n')
            n--;
        if (n > 0 && line[n - 1] == '\r')
            n--;
        status = wc_request_json_at(&out, &outlen, line, (size_t) n, name,
                                    lineno, err);
        if (out == NULL)
        {
            worst = cli_report(err, WC_EINTERNAL);
            break;
        }
        fwrite(out, 1, outlen, stdout);
        free(out);
        out = NULL;
        if (status > worst)
            worst = status;
        /* Each answer leaves at once, so that a program can drive the
           batch through pipes, one request and its answer at a time; a
           failed write ends the batch (cmd_batch reports it).  */
        if (fflush(stdout) != 0)
            break;
    }
    if (ferror(f))
    {
        cli_progress_clear();
        fprintf(stderr, PROG ": %s: read error: %s\n", name, strerror(errno));
        worst = WC_EINTERNAL;
    }
    free(line);
    wc_error_clear(err);
    return worst;
}

int
cmd_batch(const cli_command * self, int argc, char ** argv)
{
    const char * path;
    _wc_request R;
    FILE * f;
    int status, wst;

    if ((status = cli_parse(&R, self, argc, argv)) >= 0)
        return cli_done(&R, status);
    path = R.batch;
    f = strcmp(path, "-") == 0 ? stdin : fopen(path, "r");
    if (f == NULL)
    {
        fprintf(stderr, PROG ": %s: cannot open: %s\n", path,
                strerror(errno));
        return cli_done(&R, WC_EINPUT);
    }
    status = answer_lines(f, cli_input_name(path));
    if (f != stdin)
        fclose(f);
    wst = cli_finish_output();
    return cli_done(&R, wst != WC_OK ? wst : status);
}
