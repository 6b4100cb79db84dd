/* SPDX-License-Identifier: MIT */
/* Studies over a model's values: the runs' inputs (full-factorial grids, Monte Carlo, Latin hypercube)
 * from a sweep spec (load/sweepspec.h), one run and its result, and the statistics of the results
 * (Wilson intervals, Spearman rank correlation). No threads, MPI or output files here: sweepstudy.h runs
 * a whole study, out/sweepout.h writes its outputs.
 *
 * Every input of run i comes from (seed, i, variable) alone through a counter-based generator, so the
 * samples do not depend on how the runs are shared among threads or ranks. */
#ifndef CS_SWEEP_H
#define CS_SWEEP_H

#include <stddef.h>
#include <stdint.h>

#include "cablesim/cablesim.h"
#include "cablesim/loader.h"
#include "load/sweepspec.h"

/* ---- the runs' inputs ---- */

/* A uniform number in (0, 1) from (seed, a, b, stream): SplitMix64's finaliser over the key. */
double cs_sweep_u01(uint64_t seed, uint64_t a, uint64_t b, uint64_t stream);

/* The inputs of every run: x[run * var_count + var], SI (text variables: the level index). Grids vary
 * the first variable slowest. NULL if memory is short. */
double *cs_sweep_samples(const cs_sweep_spec *spec, long *run_count);
/* The level of variable var in run `run` of a grid (the first variable varies slowest). */
int cs_sweep_grid_level(const cs_sweep_spec *spec, long run, int var);
/* The probabilities (u in (0,1)) of a Latin hypercube of n runs and k variables: u[run * k + var]. Each
 * variable's column holds one point in each stratum [s/n, (s+1)/n). NULL if memory is short. */
double *cs_latin_hypercube(uint64_t seed, long n, int k);
/* The --set value of variable v for an input x: "%.12g" SI for numbers (what runs.csv shows), the
 * level's text for text. */
void cs_sweep_value_text(const cs_sweep_var *v, double x, char *buf, size_t size);
/* The same value back as used (rounded as written). */
double cs_sweep_value_used(const cs_sweep_var *v, double x);

/* ---- results ---- */

typedef enum cs_run_status { CS_RUN_OK = 0, CS_RUN_BAD_MODEL, CS_RUN_FAILED } cs_run_status;

/* One run's result: plain data, so ranks can send it as bytes. */
typedef struct cs_sweep_result {
    int status;  /* cs_run_status */
    int pending; /* not run (yet): a sweep stopped by a signal; its outputs leave it out */
    cs_summary summary;
    int event_counts[CS_EVENT_TYPE_COUNT];
    char rating[24]; /* ASTM F2656 label as run (cs_rate_as_run): "M40/P1", "none" or "not rated"; "" if
                      * status != OK */
    double astm_penetration; /* m: the penetration that label rests on (cs_rating_penetration); NaN if none */
    char
        sd_std_rating[24]; /* SD-STD-02.01 label as run: "K8/L2", "none" or "not rated"; "" if status != OK */
    char error[256];       /* status != OK: why */
} cs_sweep_result;

/* A loader for the spec's runs: it may read the model's files from the folders of spec->allow. NULL
 * with err filled when memory is short (CS_ERR_MEMORY) or the unit database cannot be read (CS_ERR_IO). */
cs_loader *cs_sweep_loader(const cs_sweep_spec *spec, cs_error *err);
/* One run with inputs xrow (var_count values): load (on loader, reset first; NULL: a loader of its
 * own), build, run, rate. Safe to call from several threads at once, each with its own loader. */
void cs_sweep_run(const cs_sweep_spec *spec, const double *xrow, cs_loader *loader, cs_sweep_result *r);
/* Check the model with the inputs of run 0 (x: its row), and each grid level with the rest of run 0;
 * the loader's problems with a value go into the spec's errors at the place of that value. 0 if none. */
int cs_sweep_check(cs_sweep_spec *spec, const double *x);

/* The hash of the spec's model with its fixed values (set:, --set) and none of the varied ones
 * (cs_model_input_hash): 0, or -1 if it cannot be loaded so. */
int cs_sweep_model_hash(const cs_sweep_spec *spec, unsigned long long *hash);
/* 64-bit FNV-1a of a study's runs: their count, the varied paths and every run's inputs, the fixed
 * values and the rating's vehicle class: what runs.csv's rows depend on beside the model. */
unsigned long long cs_sweep_inputs_hash(const cs_sweep_spec *spec, const double *x, long n);

/* ---- statistics ---- */

typedef struct cs_interval {
    double p, lo, hi;
} cs_interval;

/* Wilson score interval of k successes in n trials at normal quantile z (1.959963984540054: 95%). */
cs_interval cs_wilson(long k, long n, double z);
/* Average ranks (1-based; ties share the mean rank) of n values into rank. 0, or -1 if memory is short. */
int cs_ranks(const double *x, long n, double *rank);
/* Spearman's rank correlation of n pairs (Pearson's r of the average ranks); NaN if either is constant
 * or n < 2. */
double cs_spearman(const double *x, const double *y, long n);

#endif
