/* SPDX-License-Identifier: MIT */
/* A whole sweep, as `cablesim sweep` runs it: the spec read with the command line's changes, the output
 * folder checked and locked before any run, the runs done of a stopped study read back (--resume), every
 * finished run journalled, the runs shared among processes (an MPI sweep's ranks, through the hooks of
 * cs_sweep_ranks) and, within one, among threads (dynamic, one run at a time), then runs.csv, summary.md,
 * summary.json, the plots, report.html and runs.nc written together. The inputs depend only on the seed
 * and the run index, and each run on nothing else, so the outputs are the same for any thread or rank
 * count.
 * SIGINT or SIGTERM during the runs lets the runs under way finish and starts no other: the outputs then
 * hold the runs done, marked partial, and a resumed sweep reads them back from runs.csv (or from the
 * journal a killed sweep left), runs the rest and writes the whole study (runs.csv the same bytes as a
 * sweep never stopped). Messages go to stderr, the closing lines to stdout, from rank 0 alone. */
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
    /* the problems; the progress; the closing lines (cablesim/sweep.h's def): NULL, none */
    FILE *errors, *progress, *closing;
    char why[512]; /* the first problem said (without "cablesim sweep: "), for a cs_error */
    long runs;
    const char *seed;
    const char *allow[CS_SWEEP_MAX_ALLOW];
    int allow_count;
    const char *sets[CS_SWEEP_MAX_SETS];
    int set_count;
    char set_text[CS_SWEEP_MAX_SETS][1100]; /* --t-end and --dt as sets */
} cs_sweep_options;

/* What rank 0 does with a finished run i of any rank (its journal row and its result). */
typedef void cs_sweep_take(void *ctx, long i, const cs_sweep_result *r);

/* How the processes of a sweep share it; rank 0 reads the spec's files, writes the folder and journals
 * every run. One process: {0, 1} and no hooks. */
typedef struct cs_sweep_ranks {
    int rank, size;
    int local; /* the ranks on this machine, which share its cores */
    void *ctx; /* the hooks' */
    /* rank 0's bytes to every rank */
    void (*share)(void *ctx, void *data, long bytes);
    /* the largest of every rank's v, to every rank */
    int (*largest)(void *ctx, int v);
    /* rank 0: start giving take the runs the other ranks finish (0, or -1); wait for the last of them */
    int (*receive_start)(void *ctx, cs_sweep_take *take, void *take_ctx);
    void (*receive_end)(void *ctx);
    /* a rank other than 0: run i's result to rank 0 (one thread at a time); then that it is done */
    void (*send_run)(void *ctx, long i, const cs_sweep_result *r);
    void (*send_done)(void *ctx);
    /* end every rank at once with status */
    void (*abort)(void *ctx, int status);
    /* the threads of this process for the asked count (0: the default) and the ranks on its machine;
     * NULL: 1 */
    int (*threads)(int asked, int local);
    /* run worker(arg) on `threads` threads at once and return when each has returned (OpenMP's parallel
     * region); NULL: on this thread alone */
    void (*parallel)(int threads, void (*worker)(void *arg), void *arg);
} cs_sweep_ranks;

/* The spec of o->spec with the command line's changes (--set, --runs, --seed, --netcdf, --allow-path);
 * its problems are in its errors. NULL if memory is short (said on stderr when loud). */
cs_sweep_spec *cs_sweep_study_spec(cs_sweep_options *o, int loud);
/* The spec's errors on f (NULL: none), and their count; the first into o->why. */
void cs_sweep_print_errors(const cs_sweep_spec *spec, cs_sweep_options *o);
/* Say a problem: "cablesim sweep: " and it on o->errors (if any), the first one kept in o->why. */
void cs_sweep_say(cs_sweep_options *o, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Run the study of o (command: the command line as typed, for summary.json) on ranks. Returns the exit
 * status: 0 done (or nothing left to run), CS_SWEEP_EXIT_RUN the outputs failed, CS_SWEEP_EXIT_USAGE a bad
 * spec or resume, 128 + the signal that stopped it (partial). */
int cs_sweep_study_run(cs_sweep_options *o, const char *command, const cs_sweep_ranks *ranks);

/* What a study run on one process leaves for cablesim/sweep.h's handle (rank 0): its spec, inputs and
 * results (owned by the handle once handed over), its folder, how many runs it ran and the signal that
 * stopped it. */
struct cs_sweep {
    cs_sweep_spec *spec;
    double *x;
    cs_sweep_result *all;
    long n, ran;
    int stopped_by;
    char dir[1024];
};
/* cs_sweep_study_run, handing the study's runs over to *keep (allocated; NULL if none could be). */
int cs_sweep_study_keep(cs_sweep_options *o, const char *command, const cs_sweep_ranks *ranks,
                        cs_sweep **keep);
/* A public def (cablesim/sweep.h) as options into o (zeroed first; its strings are def's). CS_OK, or
 * CS_ERR_INVALID with err filled (too many sets or folders, runs out of range). */
cs_status cs_sweep_options_of(const cs_sweep_def *def, cs_sweep_options *o, cs_error *err);

#endif
