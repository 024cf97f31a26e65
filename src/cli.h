/* cli.h -- what the commands of the program share: the command table's
   entry, reading inputs, reporting errors, options, finishing output.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.

   Results go to stdout, only after the whole answer is computed;
   diagnostics go to stderr as "wrenchcone: FILE:LINE:COL: message".
   Exit status: 0 success, 1 bad input, 2 bad usage, 3 internal or I/O
   failure, 4 a check found a disagreement (wrenchcone(1)).  */

#ifndef WC_CLI_H
#define WC_CLI_H

#include <getopt.h>
#include <stdio.h>

#include "wrenchcone.h"
#include "cli-base.h"
#include "api/run.h"
#include "api/args.h"
#include "api/schema.h"

#define PROG "wrenchcone"

typedef struct cli_command cli_command;

/* One command of the program: its row of the schema (lib/api/schema.c:
   name, usage, operands, options) and the function that runs it.  */
struct cli_command
{
    const _wc_command_schema * schema;
    int (*run)(const cli_command * self, int argc, char ** argv);
};

/* The program's commands, in the schema's order, ending with a NULL
   schema (wrenchcone.c).  */
extern const cli_command cli_commands[];



/* --- cli.c: messages, inputs, output --- */

void cli_version(void);

/* Report err on stderr; returns status.  */
int cli_report(const wc_error_t err, int status);

/* "wrenchcone: " fmt with its one %s the input token arg, quoted and
   cut (_wc_quote), then where to find help (the command's when cmd is
   not NULL); returns WC_EUSAGE.  */
int cli_usage_error(const char * cmd, const char * fmt, const char * arg);

/* The same with a whole message, its tokens quoted already (the message
   of _wc_arg_set_text or of a schema check).  */
int cli_usage_said(const char * cmd, const char * msg);

/* "wrenchcone: PATH: " and the message fmt, the path quoted (an error
   record's file, wc_error_set); returns status.  */
int cli_file_error(int status, const char * path, const char * fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;


/* Progress on stderr (cli-progress.c): cli_progress_force for
   --progress, cli_progress_start before a command runs (it installs the
   library's hook when stderr is a terminal or progress is forced), and
   cli_progress_clear to erase a terminal line before anything else is
   written to stderr.  */
void cli_progress_force(void);
void cli_progress_start(void);
void cli_progress_clear(void);

/* GMP's and FLINT's allocators: running out of memory writes
   "wrenchcone: out of memory" to stderr and exits with status 3, never
   aborts or prints on stdout (cli-memory.c).  */
void cli_install_memory_handlers(void);

/* --- cli-file.c: the one writer of output files --- */

/* Write path (-o FILE, --certificate=FILE; what names it in messages:
   "figure", "certificate") with put(f, data): a new path or a regular
   file through a temporary file beside it renamed at the end (the old
   file's permissions kept, a read-only one refused), a FIFO, character
   device or symbolic link written through, anything else refused
   (cli-file.c says why).  WC_OK; or put's own failure, its error in err;
   or a failure to write, in err as one located line "PATH: cannot write
   the WHAT: why" (exit status WC_EINTERNAL).  The caller reports err.
   Nothing is left behind that this call created, also on SIGHUP, SIGINT
   or SIGTERM.  */
int cli_write_file(const char * path, const char * what,
                   int (*put)(FILE *, const void *), const void * data,
                   wc_error_t err);

/* --- cli-output.c: -o FILE --- */

/* argv (argc entries) with -o FILE and -oFILE as --output=FILE: a
   malloc'd, NULL-terminated vector; the new strings are in *owned
   (malloc'd, *nowned of them).  NULL when out of memory.  */
char ** cli_expand_output(int argc, char ** argv, char *** owned,
                          int * nowned);

/* run(self, argc', argv') on argv with -o expanded; out of memory is
   reported (exit status 3).  */
int cli_run_with_output(int (*run)(const cli_command *, int, char **),
                        const cli_command * self, int argc, char ** argv);

/* --- cli-request.c: --format=json through the library --- */

/* An input of the library's request from a command-line path ("-" reads
   stdin, named "<stdin>").  */
void cli_input(_wc_input * in, const char * path);

/* Answer R (parsed) and print the answer in R's format on stdout, or
   to R->output, and write R->certificate; or report the error.  The exit
   status (4 for a comparison beyond its tolerance, or a certificate that
   does not hold).  */
int cli_answer(_wc_request * R);

/* A command that is its request: cli_parse, then cli_answer; _output:
   with -o FILE read as --output=FILE first (cli_run_with_output).  */
int cli_command_run(const cli_command * self, int argc, char ** argv);
int cli_command_run_output(const cli_command * self, int argc,
                           char ** argv);

/* cone --all-modes: every mode's cone JSON, one line each, written once
   all are computed; the exit status.  */
int cli_cone_all_modes(const _wc_request * R);

/* --- cli-options.c: options and operands --- */

#define CLI_MAX_OPTIONS 64

/* Reading a command's options with getopt_long.  */
typedef struct
{
    const cli_command * cmd;
    struct option table[CLI_MAX_OPTIONS + 1];
    int status;         /* the exit status, once CLI_EXIT is returned */
    int print_request;  /* --print-request was given */
    int decimals;       /* --decimals=K, or -1 */
}
cli_options;

enum { CLI_DONE = -1, CLI_EXIT = -2 };

void cli_options_init(cli_options * p, const cli_command * cmd);

/* The next option's row (its place in the command's schema options) with
   its value in optarg; CLI_DONE after the last one (the operands are
   argv[optind..]), or CLI_EXIT when the command is over with status
   p->status: --help and --version printed, or a usage error reported.  */
int cli_option(cli_options * p, int argc, char ** argv);

/* The command line of self into R (freshly declared; the caller
   _wc_request_clear's it whatever the result): every option and operand
   read and checked by the schema's rows, "-" as standard input, the
   command's rules between them.  Returns -1 to go on, or the exit status
   when the command is over: --help, --version or --print-request
   printed, or a usage error reported.  */
int cli_parse(_wc_request * R, const cli_command * self, int argc,
              char ** argv);

/* _wc_request_clear(R), then status.  */
int cli_done(_wc_request * R, int status);

/* argv with the options first, then "--", then the operands, so that
   "-1" is an operand; a wrench option followed by three arguments becomes
   one --NAME=FX,FY,TAU, malloc'd in *extra.  Returns a malloc'd vector of
   argv's strings (and *extra), or NULL when out of memory.  */
char ** cli_operands_last(int * pargc, char ** argv,
                          const _wc_command_schema * S, char ** extra);

#endif
