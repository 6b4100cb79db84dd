/* A sweep's outputs: runs.csv (one row per run), runs.nc (the same table as netCDF), summary.md and
 * summary.json (outcome probabilities with 95% Wilson intervals, response statistics, Spearman rank
 * correlation of inputs and responses). */
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
    char long_name[96];   /* what it is, in words */
    cs_column_kind kind;
    int what; /* which value of a result */
} cs_sweep_column;

enum { CS_SWEEP_MAX_COLUMNS = 24 + CS_EVENT_TYPE_COUNT };

/* Fill cols (CS_SWEEP_MAX_COLUMNS) in runs.csv's order: outcome, ASTM F2656 label, the response parameters
 * of the run's summary, the count of each failure event type, the error. Returns how many. */
int cs_sweep_columns(cs_sweep_column *cols);
/* A run's number in a REAL or COUNT column; NaN where it has none (a run that did not run to the end, the
 * stop time of a run that did not stop, the exit speed of one that did not break through). */
double cs_sweep_column_number(const cs_sweep_column *c, const cs_sweep_result *r);
/* A run's text in a TEXT column; "" where it has none. */
const char *cs_sweep_column_text(const cs_sweep_column *c, const cs_sweep_result *r);

/* A path as a name of letters, digits and '_', every run of other characters one '_'
 * ("barrier.posts[0].yield_stress": barrier_posts_0_yield_stress): runs.nc's names of the inputs. */
void cs_sweep_name(const char *path, char *name, size_t size);

/* runs.csv: one row per run in run order. Returns 0, or -1 with why filled. */
int cs_sweep_write_runs(FILE *f, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r, long n,
                        char *why, size_t why_size);
/* runs.nc: the same table as netCDF (CF-1.8; 64-bit offset, the same bytes for the same results), at path
 * (a temporary: a failure leaves it to be removed). Returns 0, or -1 with why filled (nc_strerror's). */
int cs_sweep_write_netcdf(const char *path, const cs_sweep_spec *spec, const double *x,
                          const cs_sweep_result *r, long n, char *why, size_t why_size);
/* summary.md and summary.json: outcome probabilities with 95% Wilson intervals, response statistics,
 * Spearman correlation of each numeric input with each response. */
int cs_sweep_write_summary_md(FILE *f, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                              long n, char *why, size_t why_size);
int cs_sweep_write_summary_json(FILE *f, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                                long n, char *why, size_t why_size);

#endif
