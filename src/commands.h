/* commands.h -- the commands of the program that do more on the command
   line than answer their request (cli_command_run): their files
   (cmd-NAME.c).  The usage and options of every command are its row of
   the schema (lib/api/schema.c).

   Copyright (C) 2026 the wrenchcone authors.
   This file is part of wrenchcone, free software under the GNU General
   Public License, version 2 or (at your option) any later version.  */

#ifndef WC_COMMANDS_H
#define WC_COMMANDS_H

#include "cli.h"

int cmd_cone(const cli_command * self, int argc, char ** argv);
int cmd_compare(const cli_command * self, int argc, char ** argv);
int cmd_batch(const cli_command * self, int argc, char ** argv);

#endif
