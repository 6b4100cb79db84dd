/* SPDX-License-Identifier: MIT */
/* The sweep spec: a YAML file read through the same tree as the model files (yamltree.h): the base model,
 * the method (full-factorial grid, Monte Carlo, Latin hypercube), the values set for every run, the
 * values varied and the plots of the runs, each with its place in the file for messages. */
#ifndef CS_SWEEPSPEC_H
#define CS_SWEEPSPEC_H

#include <stddef.h>
#include <stdint.h>

#include "cablesim/sweep.h" /* cs_sweep_method, cs_sweep_is_spec */
#include "confine.h"
#include "units.h"

typedef enum cs_dist_kind { CS_DIST_UNIFORM = 0, CS_DIST_NORMAL, CS_DIST_LOGNORMAL } cs_dist_kind;

/* A distribution in SI, optionally truncated to [lo, hi]. */
typedef struct cs_dist {
    cs_dist_kind kind;
    double a, b;       /* uniform: min, max; normal: mean, sd; lognormal: mu, sigma of ln x */
    double lo, hi;     /* truncation (-inf / inf: none); uniform: = a, b */
    double p_lo, p_hi; /* the untruncated CDF at lo and hi */
} cs_dist;

/* The standard normal CDF and its inverse (Acklam's rational start and one Halley step on erfc)
 * (sweepdist.c). */
double cs_normal_cdf(double x);
double cs_normal_quantile(double p);
/* Fill the untruncated CDF at the bounds. Returns 0, or -1 if the bounds leave no probability. */
int cs_dist_prepare(cs_dist *d);
/* The value at probability u in (0, 1) of the (truncated) distribution. */
double cs_dist_quantile(const cs_dist *d, double u);

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
    /* numeric: the unit of its first value as the spec writes it ("psf"; for a bare number or a unit
     * with an offset the SI label, kN for a force) and how much one of it is in SI (0: none yet, a whole
     * number: SI): the study's page shows the input in it, SI / shown_scale */
    char shown_unit[32];
    double shown_scale;
} cs_sweep_var;

enum { CS_SWEEP_MAX_PLOTS = 16, CS_SWEEP_MAX_LINES = 10 };

/* A plot of the runs (`plot:`): a response against a varied value, one line per level of another varied
 * value (grids), or the runs as points (Monte Carlo, Latin hypercube). */
typedef struct cs_sweep_plot {
    int line, col; /* of the plot's mapping */
    int x;         /* the varied value along x (a number) */
    int lines;     /* the varied value with a line per level (grids); -1: none */
    char *y;       /* a number column of runs.csv ("max_barrier_deflection"); out/sweepout.h checks it */
    int y_line, y_col;
    char format[4]; /* "png" (the default), "svg" or "pdf" */
} cs_sweep_plot;

/* Where a sweep's outputs come from, as summary.md and summary.json record it: set by the command, not
 * read from the spec. */
typedef struct cs_sweep_origin {
    const char *command;            /* the command line, shell-quoted; NULL: none */
    const char *dir;                /* the output folder (for `sweep --resume DIR`); NULL: none */
    const char *resume;             /* how `sweep --resume` remakes the study: a JSON object; NULL: none */
    int has_model_hash;             /* model_hash is known */
    unsigned long long model_hash;  /* the base model with the fixed values (cs_model_input_hash) */
    unsigned long long inputs_hash; /* 64-bit FNV-1a of every run's inputs and the fixed values */
    const char *stopped_by;         /* a partial sweep: the signal that stopped it ("SIGINT"); NULL */
} cs_sweep_origin;

typedef struct cs_sweep_spec {
    char *file;  /* the spec file as given */
    char *model; /* the base model file, relative to the spec's folder (or absolute) */
    int model_line, model_col;
    cs_allow allow; /* more folders its model's files may be in (cs_sweep_spec_confine): none, the model's */
    cs_sweep_method method;
    long runs;
    uint64_t seed;
    char vehicle_class[8]; /* ASTM F2656 class; "": the class within 5% of the vehicle's mass, if any */
    int netcdf;            /* also write runs.nc (netcdf: true; or --netcdf) */
    int set_count;
    char **sets;      /* "PATH=VALUE" applied to every run, in order */
    char **set_given; /* the command-line option each stands for as given ("--dt 2 ms"), or NULL */
    int *set_line, *set_col;
    int var_count;
    cs_sweep_var *vars;
    int plot_count;
    cs_sweep_plot *plots;
    cs_sweep_origin origin;
    /* errors "file:line:column: what (expected ...)" */
    int error_count, error_capacity;
    char **errors;
} cs_sweep_spec;

/* Read a spec. Always returns a spec (NULL only when memory is short); check error_count. units reads
 * the values' units. */
cs_sweep_spec *cs_sweep_spec_read(const char *path, cs_units *units);
/* The same from a buffer standing for the file at path (whose folder the model is found from). */
cs_sweep_spec *cs_sweep_spec_read_buffer(const char *path, const char *data, size_t size, cs_units *units);
void cs_sweep_spec_free(cs_sweep_spec *spec);
/* Hold the spec to the rule of the files it names: its model must be in the spec's folder (or below), the
 * parts library's, or one of the folders of allow (--allow-path), and every run's loader may read the
 * model's files from any of them. Errors recorded: at the model's place, or a folder of allow that is
 * not one. */
void cs_sweep_spec_confine(cs_sweep_spec *spec, const char *const *allow, int count);
/* Record an error at a place of the spec (line 0: no place). */
void cs_sweep_error(cs_sweep_spec *spec, int line, int col, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* Add a fixed "PATH=VALUE" (from the command line) after the spec's own. 0, or -1 (error recorded). */
int cs_sweep_spec_add_set(cs_sweep_spec *spec, const char *assignment, const char *given);

#endif
