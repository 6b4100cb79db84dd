/* SPDX-License-Identifier: MIT */
#include "cli.h"

#include <ctype.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "out/outfile.h"

int cs_cli_usage_error(const cs_cli *c, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "cablesim %s: ", c->command);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    /* the usage lines themselves (GNU's: "Usage: ", another form "  or:  ", a long one wrapped under
     * itself); the rest is the command's --help */
    for (const char *line = c->usage; *line;) {
        size_t n = strcspn(line, "\n");
        if (strncmp(line, "Usage: ", 7) != 0 && strncmp(line, "  or:  ", 7) != 0 &&
            strncmp(line, "       ", 7) != 0)
            break;
        fprintf(stderr, "%.*s\n", (int)n, line);
        line += n + (line[n] == '\n');
    }
    fprintf(stderr, "(cablesim %s --help: what it does and its options)\n", c->command);
    return CS_EXIT_USAGE;
}

int cs_cli_help(const cs_cli *c) {
    fputs(c->usage, stdout);
    return 0;
}

int cs_cli_next(const cs_cli *c, int argc, char **argv, const char *shortopts,
                const struct option *longopts) {
    char opts[64];
    snprintf(opts, sizeof opts, ":%s", shortopts); /* a missing value returned as ':' */
    opterr = 0;
    /* argv[1], the subcommand, stands where getopt expects the program's name */
    int index = -1;
    int v = getopt_long(argc - 1, argv + 1, opts, longopts, &index);
    /* a value that is another option ("--measured -o DIR"): the value was left out */
    if (v != '?' && v != ':' && optarg && optarg[0] == '-' &&
        isalpha((unsigned char)optarg[1 + (optarg[1] == '-')])) {
        char name[128];
        if (index >= 0)
            snprintf(name, sizeof name, "--%s", longopts[index].name);
        else
            snprintf(name, sizeof name, "-%c", v);
        cs_cli_usage_error(c, "option '%s' needs a value, and '%s' is an option", name, optarg);
        return '?';
    }
    if (v != '?' && v != ':') return v;
    const char *arg = argv[optind]; /* argv + 1 shifted: argv[1 + optind - 1] */
    char name[128];
    if (optopt && !(arg && arg[0] == '-' && arg[1] == '-'))
        snprintf(name, sizeof name, "-%c", optopt);
    else
        snprintf(name, sizeof name, "%.*s", (int)strcspn(arg ? arg : "?", "="), arg ? arg : "?");
    if (v == ':')
        cs_cli_usage_error(c, "option '%s' needs a value", name);
    else
        cs_cli_usage_error(c, "unknown option '%s'", name);
    return '?';
}

/* SIGINT and SIGTERM into set. */
static void both_signals(sigset_t *set) {
    sigemptyset(set);
    sigaddset(set, SIGINT);
    sigaddset(set, SIGTERM);
}

void cs_cli_catch_signals(void) {
    struct sigaction sa, was;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = cs_out_end_by_signal;
    both_signals(&sa.sa_mask); /* one cleanup: the other signal waits for it */
    static const int signals[] = {SIGINT, SIGTERM};
    for (int i = 0; i < 2; i++)
        if (sigaction(signals[i], NULL, &was) == 0 && was.sa_handler != SIG_IGN)
            sigaction(signals[i], &sa, NULL);
}

void cs_cli_leave_signals(void) {
    sigset_t set;
    both_signals(&set);
    pthread_sigmask(SIG_BLOCK, &set, NULL);
}

/* A word the shell reads as itself. */
static int plain(const char *s) {
    if (!*s) return 0;
    for (; *s; s++)
        if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_@%+=:,./-", *s)) return 0;
    return 1;
}

void cs_cli_command_line(int argc, char *const *argv, char *buf, size_t size) {
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < argc && n + 4 < size; i++) {
        char word[4096];
        size_t w = 0;
        if (plain(argv[i])) {
            w = (size_t)snprintf(word, sizeof word, "%s", argv[i]);
        } else {
            word[w++] = '\'';
            for (const char *s = argv[i]; *s && w + 6 < sizeof word; s++) {
                if (*s == '\'') {
                    memcpy(word + w, "'\\''", 4);
                    w += 4;
                } else {
                    word[w++] = *s;
                }
            }
            word[w++] = '\'';
            word[w] = '\0';
        }
        if (w >= sizeof word) w = sizeof word - 1;
        if (n + (i ? 1 : 0) + w + 4 > size) {
            snprintf(buf + n, size - n, "%s...", i ? " " : "");
            return;
        }
        n += (size_t)snprintf(buf + n, size - n, "%s%s", i ? " " : "", word);
    }
}

int cs_overrides_add(cs_overrides *o, const char *option, const char *value) {
    int max = (int)(sizeof o->text / sizeof o->text[0]);
    if (o->count >= max) {
        fprintf(stderr, "cablesim: more than %d overrides (--set, --dt, --t-end)\n", max);
        return -1;
    }
    snprintf(o->text[o->count++], sizeof o->text[0], "%s %s", option, value);
    return 0;
}
