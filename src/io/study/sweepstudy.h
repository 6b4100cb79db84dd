/* SPDX-License-Identifier: MIT */
/* A whole sweep, as `cablesim sweep` runs it: the spec read with the command line's changes, the output
 * folder checked and locked before any run, the runs done of a stopped study read back (--resume), every
 * finished run journalled, the runs shared among processes (an MPI sweep's ranks, through the hooks of
 * cablesim/sweep.h's cs_sweep_ranks_def) and, within one, among threads (dynamic, one run at a time), then
 * runs.csv, summary.md, summary.json, the plots, report.html and runs.nc written together. The inputs depend
 * only on the seed and the run index, and each run on nothing else, so the outputs are the same for any
 * thread or rank count. SIGINT or SIGTERM during the runs lets the runs under way finish and starts no other:
 * the outputs then hold the runs done, marked partial, and a resumed sweep reads them back from runs.csv (or
 * from the journal a killed sweep left), runs the rest and writes the whole study (runs.csv the same bytes as
 * a sweep never stopped). Messages go to stderr, the closing lines to stdout, from rank 0 alone. */
#ifndef CS_SWEEPSTUDY_H
#define CS_SWEEPSTUDY_H

#include <stdio.h>

#include "cablesim/sweep.h"
#include "study/sweep.h"

/* The exit statuses returned, beside 0 and 128 + a signal (stopped, partial): the command's own. */
enum { CS_SWEEP_EXIT_RUN = 1, CS_SWEEP_EXIT_USAGE = 2 };

enum { CS_SWEEP_MAX_ALLOW = 64, CS_SWEEP_MAX_SETS = 256 };

/* The command line of a sweep: the study (spec and its changes) and how to run it. A resumed sweep's
 * study is read back from its folder (cs_sweep_resume_read). */
typedef struct cs_sweep_options {
    const char *spec, *out_dir, *resume;
    int threads, netcdf, force;
    cs_sweep_parallel_fn parallel; /* how to run on the threads; NULL: on the calling one */
    cs_sweep_ranks_def ranks;      /* the processes sharing the study (cs_default_sweep_ranks: this one) */
    /* the problems; the progress; the closing lines (cablesim/sweep.h's def): NULL, none */
    FILE *errors, *progress, *closing;
    char why[512]; /* the first problem said (without "cablesim sweep: "), for a cs_error */
    long runs;
    const char *seed;
    const char *allow[CS_SWEEP_MAX_ALLOW];
    int allow_count;
    const char *sets[CS_SWEEP_MAX_SETS];
    const char *sets_given[CS_SWEEP_MAX_SETS]; /* the option each stands for as given, or NULL: a --set */
    const char *force_given; /* the option that stands for force as given ("--force"), or NULL: the def's */
    int set_count;
    char set_text[CS_SWEEP_MAX_SETS][1100]; /* --t-end and --dt as sets */
} cs_sweep_options;

/* Say a problem: "cablesim sweep: " and it on o->errors (if any), the first one kept in o->why. */
void cs_sweep_say(cs_sweep_options *o, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* What a study leaves for cablesim/sweep.h's handle: its spec, inputs and results (owned by the handle once
 * handed over; none on a rank other than 0), its folder, how many runs this process ran and the signal
 * that stopped it. */
struct cs_sweep {
    cs_sweep_spec *spec;
    double *x;
    cs_sweep_result *all;
    long n, ran;
    int stopped_by;
    char dir[1024];
};
/* Run the study of o (command: the command line as typed, for summary.json) on o->ranks, and hand its runs
 * over to *keep (allocated; NULL if none could be, or keep NULL). Returns the exit status: 0 done (or
 * nothing left to run), CS_SWEEP_EXIT_RUN the outputs failed, CS_SWEEP_EXIT_USAGE a bad spec or resume,
 * 128 + the signal that stopped it (partial). */
int cs_sweep_study_keep(cs_sweep_options *o, const char *command, cs_sweep **keep);
/* Check the study of o without running it (cablesim/sweep.h's cs_sweep_check_study): the exit status as
 * cs_sweep_study_keep's, and its runs' inputs into *keep. */
int cs_sweep_study_check(cs_sweep_options *o, cs_sweep **keep);

#endif
