/* SPDX-License-Identifier: MIT */
/* The command line conventions every subcommand shares: options parsed by getopt_long (GNU: options and
 * operands in any order, "--opt=value" or "--opt value", unambiguous abbreviations), --help on stdout with
 * exit 0, a usage error on stderr naming what was wrong with exit 2, and the command line recorded as the
 * outputs give it (shell-quoted, with the overrides as given). */
#ifndef CS_APP_CLI_H
#define CS_APP_CLI_H

#include <getopt.h>
#include <stddef.h>

enum { CS_EXIT_RUN = 1, CS_EXIT_USAGE = 2 };

typedef struct cs_cli {
    const char *command; /* "run", "rate", ...: "cablesim run: ..." */
    const char *usage;   /* the subcommand's usage (its --help) */
} cs_cli;

/* The next option of argv (argv[1] is the subcommand): its val, -1 after the last, or '?' after printing
 * a usage error (an unknown option, an option without its value). Operands are at argv[optind..argc)
 * once it has returned -1. Start each command line with optind = 1. */
int cs_cli_next(const cs_cli *c, int argc, char **argv, const char *shortopts, const struct option *longopts);
/* Print "cablesim COMMAND: what" (printf-style) and the usage lines on stderr; returns CS_EXIT_USAGE. */
int cs_cli_usage_error(const cs_cli *c, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* The command's --help: the usage on stdout; returns 0. */
int cs_cli_help(const cs_cli *c);

/* SIGINT (Ctrl-C) and SIGTERM end the command by that signal, as the system would (exit status 128 + the
 * signal), its output folders first left as they were before it (cs_out_signal_cleanup). A signal the
 * command was started ignoring (a shell's background job ignores SIGINT) stays ignored. Every command but
 * sweep, which catches them itself. */
void cs_cli_catch_signals(void);
/* This thread takes neither SIGINT nor SIGTERM (it blocks them): the command's main thread, which writes
 * its outputs, does. For the threads a command starts. */
void cs_cli_leave_signals(void);

/* argv[0..argc) joined by spaces, each word shell-quoted when it needs to be ('it'\''s'); cut short with
 * "..." if it does not fit in size. */
void cs_cli_command_line(int argc, char *const *argv, char *buf, size_t size);

/* The overrides a command line gives (--set, --dt, --t-end), in order, as given: "--set PATH=VALUE",
 * "--dt 0.2 ms". */
typedef struct cs_overrides {
    int count;
    char text[64][1100];
} cs_overrides;
/* Record one; returns 0, or -1 (and prints why) past 64. */
int cs_overrides_add(cs_overrides *o, const char *option, const char *value);

#endif
