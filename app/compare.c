/* SPDX-License-Identifier: MIT */
/* `cablesim compare RUN... [--measured FILE.csv] [-o DIR]`: runs (folders written by `cablesim run`)
 * and optionally a measured history side by side: DIR/compare.csv, compare.md, compare.html and
 * plots/compare-*.png and .svg, through the library's cablesim/compare.h: this file parses the command
 * line. Every input is read before anything is written; a failure leaves nothing. */
#define _POSIX_C_SOURCE 200809L
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/compare.h"
#include "cli.h"
#include "commands.h"

enum { MAX_RUNS = CS_COMPARE_MAX_RUNS };

static const char usage[] =
    "Usage: cablesim compare RUN... [--measured FILE.csv] [-o DIR] [--force]\n"
    "Puts runs (folders written by cablesim run) side by side, and a measured time history if given:\n"
    "DIR/compare.html (one page: the table and the plots), compare.csv and compare.md (the response\n"
    "parameters, each run's difference from the reference in %), plots/compare-*.png and .svg (the\n"
    "deceleration raw and over 50 ms, the speed, the penetration and the largest rope tension against\n"
    "time). The reference is the measured history, else the first run. Default DIR: results/compare.\n"
    "The measured file is a CSV file (cells quoted or not) whose header names each column with its unit,\n"
    "\"name [unit]\" or \"name (unit)\": the time first, then columns known by a word of their names,\n"
    "case aside: decel, a deceleration (g, m/s^2); accel, an acceleration along the travel (read as the\n"
    "deceleration with its sign turned); speed or velocity (mph, km/h, m/s); penetration (ft, m);\n"
    "tension, the rope tension (kip, kN). Any other name, or a unit that does not fit the name, is refused\n"
    "at its place. Its 50-ms deceleration is found from its speed (or its deceleration) as a run's is. A\n"
    "run's own timeseries.csv is read as that run's history.\n"
    "With --measured, each run is scored against it (metrics.csv, the page, the terminal): the\n"
    "Sprague-Geers magnitude, phase and comprehensive errors and the ANOVA mean and standard deviation of\n"
    "the residuals of NCHRP W179, with W179's verdict. At most 12 runs. DIR is kept as cablesim run --help\n"
    "says.\n"
    "  RUN                  a folder written by cablesim run (its summary.json and timeseries.csv)\n"
    "  --measured FILE.csv  a measured time history, the reference\n"
    "  -o, --out DIR        the output folder (default: results/compare)\n"
    "  --force              write into DIR beside files no manifest lists (none of them is removed)\n"
    "Exit status: 0 done, 1 the outputs could not be written, 2 a run folder or measured file that cannot\n"
    "be read, or a bad command line.\n";

static const cs_cli compare_cli = {"compare", usage};

int cs_command_compare(int argc, char **argv) {
    static const struct option options[] = {{"measured", required_argument, NULL, 'm'},
                                            {"out", required_argument, NULL, 'o'},
                                            {"force", no_argument, NULL, 'f'},
                                            {"help", no_argument, NULL, 'h'},
                                            {NULL, 0, NULL, 0}};
    const char *measured = NULL, *dir = "results/compare";
    int force = 0;
    optind = 1;
    for (int c; (c = cs_cli_next(&compare_cli, argc, argv, "o:h", options)) != -1;) {
        if (c == 'h') return cs_cli_help(&compare_cli);
        if (c == 'm')
            measured = optarg;
        else if (c == 'o')
            dir = optarg;
        else if (c == 'f')
            force = 1;
        else
            return CS_EXIT_USAGE;
    }
    int first = 1 + optind, runs = argc - first; /* cs_cli_next: operands from argv[1 + optind] */
    if (runs < 1) return cs_cli_usage_error(&compare_cli, "no run to compare");
    if (runs > MAX_RUNS) return cs_cli_usage_error(&compare_cli, "more than %d runs", MAX_RUNS);
    cs_compare_def def = cs_default_compare_def();
    def.runs = (const char *const *)(argv + first);
    def.run_count = runs;
    def.measured = measured;
    def.force_given = "--force";
    cs_compare *cmp = NULL;
    cs_error err;
    if (cs_compare_create(&def, &cmp, &err) != CS_OK) {
        fprintf(stderr, "cablesim compare: %s\n", err.message);
        return CS_EXIT_USAGE; /* as a run folder or measured file that cannot be read */
    }
    int rc = 0;
    if (cs_compare_write(cmp, dir, force ? CS_COMPARE_FORCE : 0, &err) != CS_OK) {
        fprintf(stderr, "cablesim compare: %s\n", err.message); /* what was written, or "nothing written" */
        rc = 1;
    } else {
        printf("compared %d run%s%s: %s/{compare.html,compare.csv,compare.md,%splots/compare-*.png,.svg}\n",
               runs, runs == 1 ? "" : "s", measured ? " and a measured history" : "", dir,
               measured ? "metrics.csv," : "");
        cs_compare_print_metrics(cmp, stdout);
    }
    cs_compare_free(cmp);
    return rc;
}
