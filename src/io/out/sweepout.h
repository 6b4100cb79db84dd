/* SPDX-License-Identifier: MIT */
/* A sweep's outputs: runs.csv (one row per run), runs.nc (the same table as netCDF), summary.md and
 * summary.json (outcome probabilities with 95% Wilson intervals, response statistics, Spearman rank
 * correlation of inputs and responses), and the plots the spec asks for. */
#ifndef CS_SWEEPOUT_H
#define CS_SWEEPOUT_H

#include <stdio.h>

#include "study/sweep.h"

/* "grid", "monte_carlo" or "latin_hypercube", as the spec writes it. */
const char *cs_sweep_method_name(cs_sweep_method method);

/* The columns of the table of runs after `run` and the inputs: runs.csv's, and runs.nc's variables. */
typedef enum cs_column_kind { CS_COLUMN_TEXT = 0, CS_COLUMN_REAL, CS_COLUMN_COUNT } cs_column_kind;

typedef struct cs_sweep_column {
    char name[48];        /* the header without its unit, and the netCDF name: "max_50ms_decel" */
    const char *unit;     /* the header's unit ("g", "m/s", "1"); NULL: text, or a count */
    const char *cf_units; /* the unit as UDUNITS reads it where the header's is read otherwise ("g": gram) */
    char long_name[160];  /* what it is, in words */
    cs_column_kind kind;
    int what; /* which value of a result */
} cs_sweep_column;

enum { CS_SWEEP_MAX_COLUMNS = 26 + CS_EVENT_TYPE_COUNT };

/* Fill cols (CS_SWEEP_MAX_COLUMNS) in runs.csv's order: outcome, the ASTM F2656 label as run and the
 * penetration it rests on, the SD-STD-02.01 label as run, the response parameters of the run's summary,
 * the count of each failure event type, the error. Returns how many. */
int cs_sweep_columns(cs_sweep_column *cols);
/* A run's number in a REAL or COUNT column; NaN where it has none (a run that did not run to the end, the
 * stop time of a run that did not stop, the exit speed of one that did not break through). */
double cs_sweep_column_number(const cs_sweep_column *c, const cs_sweep_result *r);
/* A run's text in a TEXT column; "" where it has none. */
const char *cs_sweep_column_text(const cs_sweep_column *c, const cs_sweep_result *r);

/* A path as a name of letters, digits and '_', every run of other characters one '_'
 * ("barrier.posts[0].yield_stress": barrier_posts_0_yield_stress): runs.nc's names of the inputs, and the
 * last key of a plot's x in its file's name. */
void cs_sweep_name(const char *path, char *name, size_t size);

/* Sort n values ascending (no NaN among them). */
void cs_sweep_sort(double *v, long n);
/* The p-quantile of n sorted values, linear between order statistics (the statistics of summary.md). */
double cs_sweep_quantile(const double *sorted, long n, double p);

/* runs.csv: one row per run in run order (a pending run has none). CS_OK, or CS_ERR_IO with err filled
 * ("write error"). */
cs_status cs_sweep_write_runs(FILE *f, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                              long n, cs_error *err);
/* The row of run i (r: its result), as cs_sweep_write_runs writes it: a sweep's journal appends each run's
 * row as it finishes. */
void cs_sweep_write_run_row(FILE *f, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                            long i);
/* The start of a sweep's journal (DIR/.cablesim-journal): one line of JSON, summary.json's "cablesim",
 * "partial" (true), "inputs_hash" and "resume" (what `sweep --resume` reads), then runs.csv with the runs
 * of r done so far (none pending: a resumed sweep's); each run's row is appended as it finishes. CS_OK, or
 * CS_ERR_MEMORY or CS_ERR_IO with err filled. */
cs_status cs_sweep_write_journal_start(FILE *f, const cs_sweep_spec *spec, const double *x,
                                       const cs_sweep_result *r, long n, cs_error *err);
/* runs.csv read back, for `sweep --resume`: each row's run into r[run] (its pending flag cleared), after
 * checking the header and each row's inputs against spec and x (the same study). Rows come in run order,
 * or with any_order (a journal: as the runs finished) in any order, each run once (r's runs pending
 * before); runs with no row are left as they are. Returns the rows read, or -1 with err filled:
 * CS_ERR_INVALID ("NAME:LINE: what", LINE the file's line the row begins on, a quoted cell's line breaks
 * counted; a row the CSV reader cannot read: "NAME:LINE:COL: " and the reader's own message), CS_ERR_IO
 * ("NAME: " and the system's reason) or CS_ERR_MEMORY. */
long cs_sweep_read_runs(FILE *f, const char *name, const cs_sweep_spec *spec, const double *x,
                        cs_sweep_result *r, long n, int any_order, cs_error *err);
/* The libraries the study's outputs load when written (dynlib.h), loaded now, before any run: cairo
 * (plots/study-*.png and the spec's plots, always drawn) and netCDF where spec->netcdf (runs.nc). CS_OK,
 * or the loader's status with err naming the library, its reason and what needs it. */
cs_status cs_sweep_outputs_loadable(const cs_sweep_spec *spec, cs_error *err);
/* runs.nc: the same table as netCDF (CF-1.8; 64-bit offset, the same bytes for the same results), at path
 * (a temporary: a failure leaves it to be removed). CS_OK, or CS_ERR_IO with err filled ("what it was
 * doing: " and nc_strerror's), or the library loader's status. */
cs_status cs_sweep_write_netcdf(const char *path, const cs_sweep_spec *spec, const double *x,
                                const cs_sweep_result *r, long n, cs_error *err);
/* summary.md and summary.json: outcome probabilities with 95% Wilson intervals, response statistics and
 * the Spearman correlation of each numeric input with each response, each response over the runs that
 * have it as runs.csv gives it (the penetration of the runs the barrier held, the penetration beyond of
 * the others, the exit speed of the runs that left it) with their count; forces in kN. CS_OK, or
 * CS_ERR_MEMORY or CS_ERR_IO with err filled. */
cs_status cs_sweep_write_summary_md(FILE *f, const cs_sweep_spec *spec, const double *x,
                                    const cs_sweep_result *r, long n, cs_error *err);
cs_status cs_sweep_write_summary_json(FILE *f, const cs_sweep_spec *spec, const double *x,
                                      const cs_sweep_result *r, long n, cs_error *err);

/* ---- plots (`plot:` in the spec) ---- */

/* Check each plot's y (a number column of runs.csv) and that no two plots share a file; problems go into
 * the spec's errors at their places. 0 if none. */
int cs_sweep_plots_check(cs_sweep_spec *spec);
/* Plot k's file in the output directory: "plots/<y>-vs-<the last key of x's path>.<format>". */
void cs_sweep_plot_file(const cs_sweep_spec *spec, int k, char *buf, size_t size);
/* What plot k shows, how many runs it shows and marks as broken through, and how many it leaves out
 * (those that did not run to the end, those with no value of y), in words. */
void cs_sweep_plot_caption(const cs_sweep_spec *spec, int k, const cs_sweep_result *r, long n, char *buf,
                           size_t size);
/* Draw plot k of the runs to f in its format. CS_OK, or cs_plot_write's status with err filled. */
cs_status cs_sweep_write_plot(FILE *f, const cs_sweep_spec *spec, int k, const double *x,
                              const cs_sweep_result *r, long n, cs_error *err);

#endif
