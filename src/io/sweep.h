/* Studies over a model's values: the sweep spec (YAML, read like the model files: libyaml events for
 * places, libcyaml for values), the runs' inputs (full-factorial grids, Monte Carlo, Latin hypercube),
 * the statistics of the results (Wilson intervals, Spearman rank correlation) and the outputs
 * (runs.csv, summary.md, summary.json). No threads, MPI or engine runs here: app/sweep.c does those.
 *
 * Every input of run i comes from (seed, i, variable) alone through a counter-based generator, so the
 * samples do not depend on how the runs are shared among threads or ranks. */
#ifndef CS_SWEEP_H
#define CS_SWEEP_H

#include <stdint.h>
#include <stdio.h>

#include "cablesim/cablesim.h"
#include "loader.h"
#include "units.h"

typedef enum cs_sweep_method {
    CS_SWEEP_GRID = 0,
    CS_SWEEP_MONTE_CARLO,
    CS_SWEEP_LATIN_HYPERCUBE
} cs_sweep_method;

typedef enum cs_dist_kind { CS_DIST_UNIFORM = 0, CS_DIST_NORMAL, CS_DIST_LOGNORMAL } cs_dist_kind;

/* A distribution in SI, optionally truncated to [lo, hi]. */
typedef struct cs_dist {
    cs_dist_kind kind;
    double a, b;       /* uniform: min, max; normal: mean, sd; lognormal: mu, sigma of ln x */
    double lo, hi;     /* truncation (-inf / inf: none); uniform: = a, b */
    double p_lo, p_hi; /* the untruncated CDF at lo and hi */
} cs_dist;

enum { CS_SWEEP_MAX_RUNS = 1000000, CS_SWEEP_MAX_VARS = 64 };

/* One varied value of the model. */
typedef struct cs_sweep_var {
    char *path;       /* as --set: "barrier.soil.soil_pressure" */
    int line, col;    /* of its key in the spec */
    int numeric;      /* 1: a quantity or whole number, values in SI; 0: text (grids only) */
    int integer;      /* a whole number */
    cs_quantity q;    /* numeric: what it measures */
    const char *unit; /* SI label ("Pa"; "1" for a pure number; "" for text) */
    /* grid */
    int level_count;
    double *levels;              /* numeric levels, SI */
    char **texts;                /* text levels */
    int *level_line, *level_col; /* where each level is written */
    /* Monte Carlo / Latin hypercube */
    cs_dist dist;
    char desc[256]; /* how it varies, as the spec says it: "normal: mean 8000 psf, sd 1000 psf" */
} cs_sweep_var;

typedef struct cs_sweep_spec {
    char *file;  /* the spec file as given */
    char *model; /* the base model file, relative to the spec's folder (or absolute) */
    int model_line, model_col;
    cs_sweep_method method;
    long runs;
    uint64_t seed;
    char vehicle_class[8]; /* ASTM F2656 class; "" = the class nearest the vehicle's mass */
    int netcdf;            /* also write runs.nc (netcdf: true; or --netcdf) */
    int set_count;
    char **sets; /* "PATH=VALUE" applied to every run, in order */
    int *set_line, *set_col;
    int var_count;
    cs_sweep_var *vars;
    /* errors "file:line:column: what (expected ...)" */
    int error_count, error_capacity;
    char **errors;
} cs_sweep_spec;

/* Read a spec. Always returns a spec (NULL only when memory is short); check error_count. units reads
 * the values' units. */
cs_sweep_spec *cs_sweep_spec_read(const char *path, cs_units *units);
void cs_sweep_spec_free(cs_sweep_spec *spec);
/* Is the file a sweep spec (a YAML mapping with a top-level `vary`) rather than a model? */
int cs_sweep_is_spec(const char *path);
/* Record an error at a place of the spec (line 0: no place). */
void cs_sweep_error(cs_sweep_spec *spec, int line, int col, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* Add a fixed "PATH=VALUE" (from the command line) after the spec's own. 0, or -1 (error recorded). */
int cs_sweep_spec_add_set(cs_sweep_spec *spec, const char *assignment);

/* ---- the runs' inputs ---- */

/* A uniform number in (0, 1) from (seed, a, b, stream): SplitMix64's finaliser over the key. */
double cs_sweep_u01(uint64_t seed, uint64_t a, uint64_t b, uint64_t stream);
/* The standard normal CDF and its inverse (Acklam's rational start and one Halley step on erfc). */
double cs_normal_cdf(double x);
double cs_normal_quantile(double p);
/* Fill the untruncated CDF at the bounds. Returns 0, or -1 if the bounds leave no probability. */
int cs_dist_prepare(cs_dist *d);
/* The value at probability u in (0, 1) of the (truncated) distribution. */
double cs_dist_quantile(const cs_dist *d, double u);

/* The inputs of every run: x[run * var_count + var], SI (text variables: the level index). Grids vary
 * the first variable slowest. NULL if memory is short. */
double *cs_sweep_samples(const cs_sweep_spec *spec, long *run_count);
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
    int status; /* cs_run_status */
    cs_summary summary;
    int event_counts[CS_EVENT_TYPE_COUNT];
    char rating[24]; /* ASTM F2656 label: "M40/P1" or "none" */
    char error[256]; /* status != OK: why */
} cs_sweep_result;

/* One run with inputs xrow (var_count values): load (on loader, reset first; NULL: a loader of its
 * own), build, run, rate. Safe to call from several threads at once, each with its own loader. */
void cs_sweep_run(const cs_sweep_spec *spec, const double *xrow, cs_loader *loader, cs_sweep_result *r);
/* Check the model with the inputs of run 0 (x: its row), and each grid level with the rest of run 0;
 * the loader's problems with a value go into the spec's errors at the place of that value. 0 if none. */
int cs_sweep_check(cs_sweep_spec *spec, const double *x);

/* ASTM F2656 class of a vehicle by its mass: C, PU, M or H, whichever test mass is nearest (ratio). */
const char *cs_astm_class_by_mass(double mass);

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

/* ---- outputs ---- */

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
