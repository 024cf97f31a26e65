/* commands.h -- the commands of the program, one file each (cmd-NAME.c):
   its function (its usage and options are its row of the
   schema, lib/api/schema.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_COMMANDS_H
#define WC_COMMANDS_H

#include "cli.h"

int cmd_cone(const cli_command * self, int argc, char ** argv);

int cmd_modes(const cli_command * self, int argc, char ** argv);

int cmd_feasible(const cli_command * self, int argc, char ** argv);

int cmd_verify(const cli_command * self, int argc, char ** argv);

int cmd_random(const cli_command * self, int argc, char ** argv);

int cmd_compare(const cli_command * self, int argc, char ** argv);

int cmd_classify(const cli_command * self, int argc, char ** argv);

int cmd_stability(const cli_command * self, int argc, char ** argv);

int cmd_plan(const cli_command * self, int argc, char ** argv);

int cmd_sweep(const cli_command * self, int argc, char ** argv);

int cmd_draw(const cli_command * self, int argc, char ** argv);

int cmd_report(const cli_command * self, int argc, char ** argv);

int cmd_batch(const cli_command * self, int argc, char ** argv);

#endif
