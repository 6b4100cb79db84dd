/* SPDX-License-Identifier: MIT */
/* `cablesim validate [-o DIR] [--examples DIR] [--only PARTS] [--report-only]`: the validation suite
 * (study/validate.h: what it runs and writes), its jobs run on OpenMP threads, the costliest first. Every
 * result depends only on its own model, so the report is the same for any thread count. */
#include <stddef.h>
#include <stdio.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "cli.h"
#include "commands.h"
#include "study/validate.h"

static const char validate_usage[] =
    "Usage: cablesim validate [-o DIR] [--force] [--examples DIR] [--only PARTS] [--report-only]\n"
    "Runs the validation suite and writes DIR/validation.md and DIR/validation.csv (default DIR:\n"
    "results/validation): the crash tests beside their measurements (APS1) or as blind predictions (APS3,\n"
    "APS4), each under every documented reading of its design, the roadside predictions, the bogie tests of\n"
    "posts in soil, the closed forms, time-step convergence and sensitivity. DIR is checked and locked\n"
    "before anything runs; the two files appear together at the end (outputs as cablesim run --help says).\n"
    "  -o, --out DIR        the output folder\n"
    "  --force              write into DIR beside files no manifest lists (none of them is removed)\n"
    "  --examples DIR       where the crash tests' model files are (default: examples)\n"
    "  --only PARTS         some of crash,readings,roadside,bogie,verification,convergence,sensitivity\n"
    "  --report-only        exit 0 even when APS1's or the bogie tests' targets are missed\n"
    "Exit status: 0 done, 1 it could not run or write, 2 a bad command line, 3 targets missed (the\n"
    "targets are APS1's and the bogie tests', checked when the crash or bogie part runs).\n";

int cs_command_validate(int argc, char **argv) {
    static const cs_cli cli = {"validate", validate_usage};
    static const struct option longopts[] = {{"out", required_argument, NULL, 'o'},
                                             {"examples", required_argument, NULL, 'e'},
                                             {"only", required_argument, NULL, 'n'},
                                             {"report-only", no_argument, NULL, 'r'},
                                             {"force", no_argument, NULL, 'f'},
                                             {"help", no_argument, NULL, 'h'},
                                             {NULL, 0, NULL, 0}};
    cs_validate_opts o = {.dir = "results/validation", .out = stdout, .err = stderr};
    int v;
    optind = 1;
    while ((v = cs_cli_next(&cli, argc, argv, "ho:", longopts)) != -1) {
        if (v == 'h') return cs_cli_help(&cli);
        if (v == 'o')
            o.dir = optarg;
        else if (v == 'e')
            o.examples = optarg;
        else if (v == 'n')
            o.only = optarg;
        else if (v == 'r')
            o.report_only = 1;
        else if (v == 'f')
            o.force = 1;
        else
            return CS_EXIT_USAGE;
    }
    if (argc - 1 > optind) return cs_cli_usage_error(&cli, "takes no file ('%s')", argv[1 + optind]);
    size_t n;
    const char *bad = cs_validate_unknown_part(o.only, &n);
    if (bad)
        return cs_cli_usage_error(&cli,
                                  "--only: unknown part '%.*s' (expected some of crash, readings, roadside, "
                                  "bogie, verification, convergence, sensitivity)",
                                  (int)n, bad);
    int status;
    cs_validate_suite *s = cs_validate_begin(&o, &status);
    if (!s) return status;
    int count = cs_validate_job_count(s);
#ifdef _OPENMP
#pragma omp parallel
#endif
    {
#ifdef _OPENMP
        if (omp_get_thread_num() > 0) cs_cli_leave_signals(); /* a signal's cleanup in the writing thread */
#pragma omp for schedule(dynamic, 1)
#endif
        for (int i = 0; i < count; i++) /* dynamic: one job at a time per thread */
            cs_validate_run(s, i);
    }
    return cs_validate_finish(s);
}
