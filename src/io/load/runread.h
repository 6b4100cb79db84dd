/* SPDX-License-Identifier: MIT */
/* Results read back for comparison: a run's folder (timeseries.csv and summary.json, as `cablesim run`
 * writes them) or a measured time history (a CSV file whose header gives each column's quantity by its
 * name and its unit), both with cells quoted or not (RFC 4180). Each becomes a trace of the responses
 * compared, in SI, with the response parameters found from it the way a run finds its own. */
#ifndef CS_RUNREAD_H
#define CS_RUNREAD_H

#include <stddef.h>

#include "load/units.h"

/* The time histories compared; NAN where the source has none. */
enum {
    CS_TRACE_DECEL = 0,
    CS_TRACE_DECEL_50MS,
    CS_TRACE_SPEED,
    CS_TRACE_PENETRATION,
    CS_TRACE_TENSION,
    CS_TRACE_COUNT
};

typedef struct cs_trace {
    char label[160]; /* the run's folder or the measured file, as given */
    int measured;    /* 1: read from a measured file */
    size_t n;
    double *t;                 /* s */
    double *y[CS_TRACE_COUNT]; /* m/s^2, m/s^2, m/s, m, N */
    int have[CS_TRACE_COUNT];  /* the source gives this response */
    char outcome[32];          /* the run's outcome; "" for a measured trace */
    /* the response parameters (NAN: not given): the largest 50-ms deceleration, g, and its time, s; the
     * largest penetration, m; the speed at the end, m/s; the largest rope tension, N; the end, s */
    double max_decel_50ms_g, t_max_decel_50ms, max_penetration, final_speed, max_tension, t_end;
    double max_deflection, working_width, exit_speed; /* from a run's summary only, m, m, m/s */
    /* a run that got through (or was still going): how far it had got when the run ended, m, its real
     * penetration beyond it, and max_penetration NAN, as summary.json's penetration_beyond_m and
     * max_dynamic_penetration_m: null; NAN for a run that stopped and for a measured trace */
    double penetration_beyond_m;
} cs_trace;

/* Read the run in folder dir. CS_OK, or with err filled ("dir/timeseries.csv: No such file...")
 * CS_ERR_IO (a file that cannot be read), CS_ERR_INVALID (not a run's) or CS_ERR_MEMORY. */
cs_status cs_trace_load_run(const char *dir, cs_trace *out, cs_error *err);
/* Read a measured history: a CSV file, its first line the header, each cell "name [unit]" or "name
 * (unit)", the first column the time; every other column is known by its name (case and punctuation
 * aside) and its unit checked against it: decel (a deceleration), accel (an acceleration along the
 * travel, read as a deceleration with its sign turned), speed or velocity, penetration, tension (the rope
 * tension); a name of none, two, or one across the travel or averaged is refused. CS_OK, or with err
 * filled as "file:line:column: what and why" CS_ERR_INVALID, or CS_ERR_IO or CS_ERR_MEMORY as
 * cs_trace_load_run. */
cs_status cs_trace_load_measured(const char *path, cs_units *units, cs_trace *out, cs_error *err);
void cs_trace_free(cs_trace *trace);

/* The trailing 50-ms average of a deceleration history over times t (the engine's rule), into avg. */
void cs_trace_average_50ms(const double *t, const double *decel, size_t n, double *avg);

#endif
