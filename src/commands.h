/* commands.h -- the commands of the program, one file each (cmd-NAME.c):
   its function, its usage text, its options.

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_COMMANDS_H
#define WC_COMMANDS_H

#include "cli.h"

int cmd_cone(const cli_command * self, int argc, char ** argv);
extern const char cmd_cone_usage[];
extern const struct option cmd_cone_options[];

int cmd_modes(const cli_command * self, int argc, char ** argv);
extern const char cmd_modes_usage[];
extern const struct option cmd_modes_options[];

int cmd_feasible(const cli_command * self, int argc, char ** argv);
extern const char cmd_feasible_usage[];
extern const struct option cmd_feasible_options[];

int cmd_verify(const cli_command * self, int argc, char ** argv);
extern const char cmd_verify_usage[];
extern const struct option cmd_verify_options[];

int cmd_random(const cli_command * self, int argc, char ** argv);
extern const char cmd_random_usage[];
extern const struct option cmd_random_options[];

int cmd_compare(const cli_command * self, int argc, char ** argv);
extern const char cmd_compare_usage[];
extern const struct option cmd_compare_options[];

int cmd_classify(const cli_command * self, int argc, char ** argv);
extern const char cmd_classify_usage[];
extern const struct option cmd_classify_options[];

int cmd_stability(const cli_command * self, int argc, char ** argv);
extern const char cmd_stability_usage[];
extern const struct option cmd_stability_options[];

int cmd_plan(const cli_command * self, int argc, char ** argv);
extern const char cmd_plan_usage[];
extern const struct option cmd_plan_options[];

int cmd_sweep(const cli_command * self, int argc, char ** argv);
extern const char cmd_sweep_usage[];
extern const struct option cmd_sweep_options[];

int cmd_draw(const cli_command * self, int argc, char ** argv);
extern const char cmd_draw_usage[];
extern const struct option cmd_draw_options[];

int cmd_report(const cli_command * self, int argc, char ** argv);
extern const char cmd_report_usage[];
extern const struct option cmd_report_options[];

int cmd_batch(const cli_command * self, int argc, char ** argv);
extern const char cmd_batch_usage[];
extern const struct option cmd_batch_options[];

#endif
