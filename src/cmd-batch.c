/* cmd-batch.c -- wrenchcone batch: JSON Lines requests in, one answer
   line out per request, in order, through the library's batch engine
   (api/batch.h), by one thread or several.

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
    "  --jobs=N         answer with N threads (1 to 256; default 1); the\n"
    "                   answers are the same, in the same order, each still\n"
    "                   written once it and all earlier ones are done\n"
    "  -h, --help       print this help and exit\n"
    "  -V, --version    print versions and exit\n";

enum { OPT_JOBS = 256 };

const struct option cmd_batch_options[] = {
    { "jobs", required_argument, NULL, OPT_JOBS },
    { NULL, 0, NULL, 0 }
};

int
cmd_batch(const cli_command * self, int argc, char ** argv)
{
    cli_options p;
    const char * path = "-";
    FILE * f;
    char * end;
    long jobs = 1;
    int c, status, wst, worst;
    wc_error_t err;

    cli_options_init(&p, self);
    while ((c = cli_option(&p, argc, argv)) >= 0)
        if (c == OPT_JOBS)
        {
            errno = 0;
            jobs = strtol(optarg, &end, 10);
            if (*optarg == '\0' || *end != '\0' || errno != 0 || jobs < 1
                || jobs > WC_BATCH_MAX_JOBS)
                return cli_usage_error("batch", "--jobs takes a count from 1 "
                                       "to 256, not '%s'", optarg);
        }
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
    wc_error_init(err);
    status = wc_batch(&worst, stdout, f, cli_input_name(path), (int) jobs,
                      err);
    if (status != WC_OK)
        cli_report(err, status);        /* reading, writing or memory */
    wc_error_clear(err);
    if (f != stdin)
        fclose(f);
    /* A failed write is reported already.  */
    wst = ferror(stdout) ? WC_EINTERNAL : cli_finish_output();
    return wst != WC_OK ? wst : status != WC_OK ? status : worst;
}
