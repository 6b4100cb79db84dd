/* SPDX-License-Identifier: MIT */
/* The command's subcommands that live in their own files. */
#ifndef CS_APP_COMMANDS_H
#define CS_APP_COMMANDS_H

#include <stdio.h>

#include "cablesim/cablesim.h"

/* `cablesim rate FILE --standard S [--class C] [--set PATH=VALUE]...`; argv[1] is "rate". Each returns
 * the exit status. */
int cs_command_rate(int argc, char **argv);
/* `cablesim validate [-o DIR] [--examples DIR] [--only PARTS]`; argv[1] is "validate". */
int cs_command_validate(int argc, char **argv);
/* `cablesim compare RUN... [--measured FILE.csv] [-o DIR]`; argv[1] is "compare". */
int cs_command_compare(int argc, char **argv);
/* `cablesim designer [FILE] [-o DIR]`; argv[1] is "designer". */
int cs_command_designer(int argc, char **argv);

#endif
