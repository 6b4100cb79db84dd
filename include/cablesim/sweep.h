/* SPDX-License-Identifier: MIT */
/** @file
 * Studies over a model's values, as `cablesim sweep` runs them (docs/sweep.md): a spec names a base model
 * and the values to vary (grids, Monte Carlo or Latin hypercube samples); the study runs every run, on as
 * many threads as the program gives it, writes runs.csv, summary.md, summary.json, the plots, report.html
 * (and runs.nc) together into its folder, and hands back each run's inputs and response parameters. A
 * study stopped by SIGINT or SIGTERM writes the runs done, marked partial, and a later study with
 * `resume` set runs the rest. The runs' inputs depend only on the seed and the run's index, so the
 * results are the same for any thread count. */
#ifndef CABLESIM_SWEEP_H
#define CABLESIM_SWEEP_H

#include <stdio.h>

#include "cablesim/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Runs worker(arg) on `threads` threads at once and returns when each has returned (OpenMP's parallel
 * region is one: `#pragma omp parallel num_threads(threads)` around the call). The worker blocks SIGINT
 * and SIGTERM, for good, on each thread but the study's own, so that the study's handler of a signal
 * runs in the thread that writes its folder. */
typedef void (*cs_sweep_parallel_fn)(int threads, void (*worker)(void *arg), void *arg);

/** How a study's spec draws its runs. */
typedef enum cs_sweep_method {
    CS_SWEEP_GRID = 0,       /**< every combination of the varied values' levels */
    CS_SWEEP_MONTE_CARLO,    /**< independent samples of the varied values' distributions */
    CS_SWEEP_LATIN_HYPERCUBE /**< one sample of each of `runs` equal-probability strata of every value */
} cs_sweep_method;

/** Rank 0 of a study shared among processes: take a run another rank finished (`result`: the bytes that
 * rank's send_run was given). */
typedef void (*cs_sweep_take_fn)(void *take_ctx, long run, const void *result);

/** How the processes of one study share it (an MPI program's ranks: app/sweep_mpi.c): each process calls
 * cs_sweep_study with the same def but for its own rank. Rank 0 reads the spec's files, checks and writes
 * the folder and journals every run as it ends; the runs are dealt round robin among the ranks, and each
 * rank runs its own on def->threads threads. The other ranks need not see rank 0's folder. Start it from
 * cs_default_sweep_ranks(), which sets its size; new fields go at its end. With ranks above 1, every hook
 * is needed. */
typedef struct cs_sweep_ranks_def {
    size_t size; /**< the size of this struct in the program (cs_default_sweep_ranks sets it) */
    int rank;    /**< this process's rank, 0 to ranks - 1 */
    int ranks;   /**< how many processes share the study */
    void *ctx;   /**< passed to every hook */
    /** rank 0's `bytes` bytes at data to every rank (MPI_Bcast from 0) */
    void (*share)(void *ctx, void *data, size_t bytes);
    /** the largest of every rank's v, returned on every rank (MPI_Allreduce with MPI_MAX) */
    int (*largest)(void *ctx, int v);
    /** rank 0: start calling take(take_ctx, ...) with each run the other ranks send (results of `bytes`
     * bytes), one call at a time, until every other rank has sent that it is done; 0, or -1 if it cannot
     * start. Between it and receive_end, rank 0 calls no other hook. */
    int (*receive_start)(void *ctx, size_t bytes, cs_sweep_take_fn take, void *take_ctx);
    /** rank 0: return once every other rank's runs are taken */
    void (*receive_end)(void *ctx);
    /** a rank other than 0: run `run`'s result (`bytes` bytes) to rank 0, as it ends (one call at a time) */
    void (*send_run)(void *ctx, long run, const void *result, size_t bytes);
    /** a rank other than 0, after its last run: that it is done */
    void (*send_done)(void *ctx);
    /** end every rank at once with exit status `status` (MPI_Abort) */
    void (*abort)(void *ctx, int status);
} cs_sweep_ranks_def;

/** A ranks def of one process (rank 0 of 1, no hooks) with its size set (inline: the program's size, def.h).
 */
static inline cs_sweep_ranks_def cs_default_sweep_ranks(void) {
    cs_sweep_ranks_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    d.ranks = 1; /* rank 0 of 1 */
    return d;
}

/** A study to run. Start it from cs_default_sweep_def(), which sets its size; new fields go at its end. The
 * strings and arrays it points to are read during cs_sweep_study alone. */
typedef struct cs_sweep_def {
    size_t size;              /**< the size of this struct in the program (cs_default_sweep_def sets it) */
    const char *spec;         /**< the spec file (a YAML mapping with `vary`); NULL with resume */
    const char *out_dir;      /**< the output folder; NULL: results/<the spec's name> */
    const char *resume;       /**< a stopped study's folder: run the runs it lacks and write the whole
                                   study (the study as its summary.json records it: spec, out_dir,
                                   runs, seed, sets, allow and netcdf are then left unset) */
    long runs;                /**< Monte Carlo and Latin hypercube: the runs, replacing the spec's; 0:
                                   the spec's */
    const char *seed;         /**< the seed, a whole number from 0 to 2^64 - 1, replacing the spec's;
                                   NULL: the spec's */
    const char *const *sets;  /**< "PATH=VALUE" for every run, as `cablesim run --set` (after the
                                   spec's own) */
    int set_count;            /**< how many (at most 256) */
    const char *const *allow; /**< more folders the model and its files may be in, beyond the spec's
                                   folder and the parts library's */
    int allow_count;          /**< how many (at most 64) */
    int netcdf;               /**< 1: also write runs.nc */
    int force;                /**< 1: write into a folder beside files no manifest lists, and start
                                   afresh in one holding a stopped study's runs done, replacing that
                                   study (0: either folder is refused, CS_ERR_IO) */
    int threads;              /**< the threads to run on (with parallel); 0: 1 */
    cs_sweep_parallel_fn parallel; /**< how to run on them; NULL: on the calling thread alone */
    const char *command;           /**< the command line, for summary.json; NULL: none */
    FILE *errors;                  /**< the problems (a spec's, each at its place) as they are found;
                                        NULL: none printed (the first is in the cs_error) */
    FILE *progress;                /**< the progress of the runs (a bar on a terminal); NULL: none */
    FILE *closing;                 /**< the closing lines: the runs done and the files written; NULL: none */
    const cs_sweep_ranks_def *ranks; /**< the processes that share the study (read to its size); NULL:
                                          this process alone */
    const char *const *sets_given;   /**< [set_count] the command-line option each of sets stands for, as
                                          the user gave it ("--dt 2 ms"), which its problems then name; a
                                          NULL entry (or NULL): a --set */
    const char *force_given;         /**< the command-line option that stands for force, as the user gives
                                          it ("--force"), which a refusal of a folder holding files no
                                          manifest lists names as the way to write beside them; NULL: the
                                          refusal names this def's force */
} cs_sweep_def;

/** A study run: its runs' inputs and results (opaque). */
typedef struct cs_sweep cs_sweep;

/** A def with nothing set but its size (inline: the program's size, def.h). */
static inline cs_sweep_def cs_default_sweep_def(void) {
    cs_sweep_def d = CS_ZERO_INIT;
    d.size = sizeof d;
    return d;
}

/** Run a study and write its outputs.
 * @param def the study (read to its size)
 * @param out the study's runs, to free with cs_sweep_free (NULL on failure); on a rank other than 0 of a
 *        study shared among processes (def->ranks), a study without runs (cs_sweep_run_count 0, cs_sweep_dir
 *        "") whose cs_sweep_stopped_by is rank 0's
 * @param err filled on failure (may be NULL)
 * @return CS_OK: done, stopped by a signal (cs_sweep_stopped_by: the runs done are written, partial), or,
 *         with resume, nothing left to run (cs_sweep_ran 0); CS_ERR_INVALID: a def of a size this library
 *         does not know, a spec with problems (each printed to def->errors; the first, or their count, in
 *         err) or a folder that cannot be resumed, nothing run; CS_ERR_IO: the folder could not be taken
 *         (without force: it holds a file no manifest lists, or, without resume, a stopped study's runs
 *         done, which err counts) or the outputs written (the runs done are kept in its journal for a
 *         resume), or the outputs are in place but an earlier study's file there could not be removed
 *         (named in err); CS_ERR_MEMORY. */
CS_API cs_status cs_sweep_study(const cs_sweep_def *def, cs_sweep **out, cs_error *err);
/** Check a study without running it, as `cablesim check SPEC` does: the spec with def's changes, and its
 * model with the inputs of run 0 and with each grid level. Nothing is written, no folder is taken.
 * @param def the study (read to its size; its ranks, threads, parallel, progress and closing unused)
 * @param out the study's runs, none of them run (each CS_SWEEP_RUN_PENDING), with their inputs, to free
 *        with cs_sweep_free (NULL on failure)
 * @param err filled on failure (may be NULL)
 * @return CS_OK; CS_ERR_INVALID: a def this library cannot take, or a spec with problems (each printed to
 *         def->errors; the first, or their count, in err); CS_ERR_IO: the unit database could not be read;
 *         CS_ERR_MEMORY. */
CS_API cs_status cs_sweep_check_study(const cs_sweep_def *def, cs_sweep **out, cs_error *err);
/** Is the file a study's spec (a YAML mapping with a top-level `vary`) rather than a model? 1 or 0 (0 too
 * for a file that cannot be read). */
CS_API int cs_sweep_is_spec(const char *path);

/** Free a study. NULL is allowed. */
CS_API void cs_sweep_free(cs_sweep *sweep);

/** The study's output folder. */
CS_API const char *cs_sweep_dir(const cs_sweep *sweep);
/** The spec file as the def gave it (a resumed study: as its folder records it); "" on a rank other than 0.
 */
CS_API const char *cs_sweep_spec_file(const cs_sweep *sweep);
/** The spec's base model file, as the study opens it (the spec's `model:` found from the spec's folder); ""
 * on a rank other than 0. */
CS_API const char *cs_sweep_model(const cs_sweep *sweep);
/** How the spec draws its runs. */
CS_API cs_sweep_method cs_sweep_method_of(const cs_sweep *sweep);
/** Its number of runs: runs.csv's rows, numbered from 0 as its `run` column. */
CS_API long cs_sweep_run_count(const cs_sweep *sweep);
/** How many runs this call ran (those of a resumed study read back from its folder not counted). */
CS_API long cs_sweep_ran(const cs_sweep *sweep);
/** The signal (SIGINT, SIGTERM) that stopped the study, its outputs then partial; 0 if none did. */
CS_API int cs_sweep_stopped_by(const cs_sweep *sweep);
/** The number of varied values (runs.csv's columns after `run`). */
CS_API int cs_sweep_var_count(const cs_sweep *sweep);
/** Varied value var's path, as --set takes it ("barrier.cables[0].pretension"); NULL out of range. */
CS_API const char *cs_sweep_var_path(const cs_sweep *sweep, int var);
/** Varied value var's SI unit as runs.csv's header gives it ("N", "m/s", "1"; "" for a text value). */
CS_API const char *cs_sweep_var_unit(const cs_sweep *sweep, int var);
/** Run `run`'s input of varied value var, SI, as runs.csv writes it (a text value: its level's index);
 * NAN out of range. */
CS_API double cs_sweep_input(const cs_sweep *sweep, long run, int var);

/** How a run of a study went. */
typedef enum cs_sweep_run_status {
    CS_SWEEP_RUN_OK = 0,    /**< it ran to its end */
    CS_SWEEP_RUN_BAD_MODEL, /**< its model with its inputs was refused (error says why) */
    CS_SWEEP_RUN_FAILED,    /**< it failed on the way (error says why) */
    CS_SWEEP_RUN_PENDING    /**< it was not run: the study was stopped, or it was in the folder resumed */
} cs_sweep_run_status;

/** A run of a study. */
typedef struct cs_sweep_run_info {
    size_t size;                /**< the size of this struct in the program: set it (cs_sweep_run_info r =
                                     {.size = sizeof r}); the library fills only that much */
    cs_sweep_run_status status; /**< how it went */
    char rating[24];            /**< its ASTM F2656 rating as run, as runs.csv's astm_f2656_as_run: "M40/P1",
                                     "none" or "not rated"; "" if it did not run to its end */
    char error[256];            /**< why it did not run to its end; "" if it did */
    double astm_penetration;    /**< m: the penetration its ASTM F2656 rating as run rests on, as that
                                     standard measures it, as runs.csv's astm_f2656_penetration; NAN where
                                     it has none ("none", "not rated", through the barrier, not run) */
    char sd_std_rating[24];     /**< its SD-STD-02.01 rating as run, as runs.csv's sd_std_02_01_as_run:
                                     "K8/L2", "none" or "not rated"; "" if it did not run to its end */
} cs_sweep_run_info;

/** Fill out with run `run`, to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL): no such run, or out's size 0 or larger
 *         than this library's. */
CS_API cs_status cs_sweep_run_of(const cs_sweep *sweep, long run, cs_sweep_run_info *out, cs_error *err);
/** Fill out with run `run`'s response parameters (runs.csv's values are these), to out's size.
 * @return CS_OK, or CS_ERR_INVALID with err filled (may be NULL): no such run, a run without them (not run,
 *         or refused before it ran), or out's size 0 or larger than this library's. */
CS_API cs_status cs_sweep_run_summary(const cs_sweep *sweep, long run, cs_summary *out, cs_error *err);

#ifdef __cplusplus
}
#endif
#endif
