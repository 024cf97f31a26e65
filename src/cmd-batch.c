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

const char cmd_batch_usage[] =
    "Usage: " PROG " batch [OPTIONS] [FILE]\n"
    "Answer requests given as JSON Lines (FILE, or standard input when FILE is\n"
    "absent or '-'), one JSON object a line, such as\n"
    "  {\"command\": \"cone\", \"problem\": \"data/section4.wc\", \"mode\": \"na\"}\n"
    "Each answer is one line, in the order of the requests: exactly what the\n"
    "command prints with --format=json, or {\"error\": {\"message\", \"file\",\n"
    "\"line\", \"column\", \"status\"}} and the batch goes on.  Blank lines are\n"
    "skipped.  Each answer is written as soon as it is computed, so a program\n"
    "can send one request and read its answer through pipes.  Commands: cone,\n"
    "modes, feasible, classify, stability, plan, compare; the keys of each are\n"
    "in wrenchcone(1), REQUESTS.\n"
    "\n"
    "Exit status: 0 when every request succeeded, else the largest status of\n"
    "a line (1 bad input, 2 bad request, 3 internal, 4 a comparison beyond\n"
    "its tolerance); 1 when FILE cannot be opened, 3 when reading it or\n"
    "writing the answers fails.\n"
    "\n"
    "Options:\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

const struct option cmd_batch_options[] = {
    { NULL, 0, NULL, 0 }
};

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
    cli_options p;
    const char * path = "-";
    FILE * f;
    int c, status, wst;

    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        ;
    if (c == CLI_EXIT)
        return p.status;
    if (argc - optind > 1)
        return cli_usage_error("batch", "batch takes one FILE at most%s", "");
    if (argc - optind == 1)
        path = argv[optind];
    f = strcmp(path, "-") == 0 ? stdin : fopen(path, "r");
    if (f == NULL)
    {
        fprintf(stderr, PROG ": %s: cannot open: %s\n", path,
                strerror(errno));
        return WC_EINPUT;
    }
    status = answer_lines(f, cli_input_name(path));
    if (f != stdin)
        fclose(f);
    wst = cli_finish_output();
    return wst != WC_OK ? wst : status;
}
