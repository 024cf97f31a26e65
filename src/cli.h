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

#define PROG "wrenchcone"

typedef struct cli_command cli_command;

/* One command of the program.  */
struct cli_command
{
    const char * name;          /* dispatched by this full name only */
    int (*run)(const cli_command * self, int argc, char ** argv);
    const char * usage;         /* its --help text */
    const struct option * options;  /* its own options, ending with a NULL
                                       name; --help and --version are
                                       everyone's and not listed */
    unsigned flags;
};

/* The flags of a command.  CLI_SHARED: the command knows the options of
   every other CLI_SHARED command, and refuses them as "does not apply
   here" rather than as unknown (so an abbreviation is read against all
   of them).  CLI_OPERANDS_LAST: operands may be negative numbers, read
   as operands, not options (see cli_operands_last).  */
enum { CLI_SHARED = 1, CLI_OPERANDS_LAST = 2 };

/* An option code with this bit takes one value FX,FY,TAU that may also
   be written as three arguments, --NAME FX FY TAU (CLI_OPERANDS_LAST
   commands only).  */
#define CLI_WRENCH_VALUE 0x1000

/* The program's commands, ending with a NULL name (wrenchcone.c).  A
   NULL run: the command is planned but not implemented.  */
extern const cli_command cli_commands[];

/* Inputs larger than these are refused before they are parsed: a problem
   of a million fixels is far below the first, and a certificate carries
   at most two rows per fixel.  */
#define CLI_MAX_CERTIFICATE_BYTES ((size_t) 64 << 20)

typedef enum { FMT_TEXT, FMT_JSON, FMT_CDD, FMT_INE, FMT_EXT } cli_format;

/* --- cli.c: messages, inputs, output --- */

void cli_version(void);

/* Report err on stderr; returns status.  */
int cli_report(const wc_error_t err, int status);

/* "wrenchcone: " fmt (with arg), then where to find help (the command's
   when cmd is not NULL); returns WC_EUSAGE.  */
int cli_usage_error(const char * cmd, const char * fmt, const char * arg);

int cli_load_problem(wc_problem_t P, const char * path, wc_error_t err);

/* --format's value: 1 when s names a format (cdd, ine and ext only with
   allow_cdd), else 0 after a usage error for command cmd.  */
int cli_parse_format(cli_format * f, const char * s, const char * cmd,
                     int allow_cdd);

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

/* Write a certificate file with put(f, data); never leaves a partial file
   this run created.  A write error is reported here (exit status
   WC_EINTERNAL); any other failure of put is returned for the caller to
   report.  */
int cli_write_certificate(const char * path,
                          int (*put)(FILE *, const void *),
                          const void * data);

/* What a certificate file certifies: answer is a wc_certificate_struct,
   wc_classify_struct, wc_stability_struct, wc_plan_struct or
   wc_critical_struct (kind "mode-feasibility", "strong-stability",
   "stability-set", "plan-goal" or "critical-friction").  */
typedef enum
{
    CLI_CERT_FEASIBLE, CLI_CERT_CLASSIFY, CLI_CERT_STABILITY, CLI_CERT_PLAN,
    CLI_CERT_CRITICAL
}
cli_cert_kind;

/* The end of a command that may write a certificate: status is how
   computing its answer ended.  When that is WC_OK and path is not NULL,
   write the certificate of answer for P to path.  Reports err when
   computing or proving failed.  Returns WC_OK when the command goes on
   to print its answer, else its exit status.  */
int cli_certify(int status, const char * path, cli_cert_kind kind,
                const wc_problem_struct * P, const void * answer,
                wc_error_struct * err);

/* --- cli-output.c: whole output files, -o FILE --- */

/* Write path with put(f, data) through a temporary file in the same
   directory, renamed at the end: path is replaced whole or not at all,
   and nothing is left behind on failure.  A failure is reported here
   ("cannot write the WHAT") with exit status WC_EINTERNAL.  */
int cli_write_whole(const char * path, const char * what,
                    int (*put)(FILE *, const void *), const void * data);

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

/* Answer R and print the answer with print (on stdout), or report its
   error: the exit status (4 for a comparison beyond its tolerance).  */
int cli_run_print(const _wc_request * R,
                  void (*print)(const _wc_answer * A));

/* cli_run_print with the answer's JSON (exactly what batch and
   wc_request_json give).  */
int cli_run_json(const _wc_request * R);

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
}
cli_options;

enum { CLI_DONE = -1, CLI_EXIT = -2 };

void cli_options_init(cli_options * p, const cli_command * cmd);

/* The next option's code from the command's table, its value in optarg;
   CLI_DONE after the last one (the operands are argv[optind..]), or
   CLI_EXIT when the command is over with status p->status: --help and
   --version printed, or a usage error reported.  */
int cli_option(cli_options * p, int argc, char ** argv);

/* argv with the options first, then "--", then the operands, so that
   "-1" is an operand; a CLI_WRENCH_VALUE option followed by three
   arguments becomes one --NAME=FX,FY,TAU, malloc'd in *extra.  Returns a
   malloc'd vector of argv's strings (and *extra), or NULL when out of
   memory.  */
char ** cli_operands_last(int * pargc, char ** argv,
                          const struct option * opts, char ** extra);

#endif
