/* SPDX-License-Identifier: MIT */
/* The validation suite of `cablesim validate`, written to DIR/validation.md and DIR/validation.csv:
 * - the three crash tests (examples/aps*.yaml): APS1 beside the crash test and the paper's simulation
 *   (the paper's Table 3); APS3 and APS4 as blind predictions (their results are withheld);
 * - each crash test under every documented reading of what its design data leaves open (rails, how the
 *   intermediate anchor posts hold the ropes, the dead-men's size or orientation, the end fittings);
 * - the six roadside crash tests (examples/roadside/rs*.yaml) as blind predictions, and their readings;
 * - the ten bogie tests of W6x16 posts in soil (the paper's Table 2), each simulated as the 2,237-lb
 *   bogie striking the post, against the measured energy and failure mode;
 * - verification against closed forms (Eq. 21 against the paper's Table 4);
 * - time-step and solver-tolerance convergence of the crash tests;
 * - sensitivity to what the paper does not give: the band of each response over each input's range alone
 *   and over all of them at once (a Latin hypercube), APS1's measured values against the latter.
 * Every case uses the one parameter set of the model files and docs/assumptions.md. The measured and
 * published values it compares with are read from data/validation/ (load/validation.h), each file with
 * its source.
 *
 * cs_validate_begin checks and locks the output folder and queues every simulation as a job
 * (validate_plan.c); the caller runs the jobs, the costliest first, on as many threads as it likes
 * (cs_validate_run: no threads here, as for a sweep); cs_validate_finish then writes the report from the
 * stored results (validate_crash.c, validate_write.c): the same report for any thread count or order.
 * The files by role: validate_run.c the suite and its jobs, validate_plan.c the cases and their queue,
 * validate_crash.c the crash, bogie and verification parts, validate_write.c the rest and the CSV rows. */
#ifndef CS_VALIDATE_H
#define CS_VALIDATE_H

#include <stddef.h>
#include <stdio.h>
#include <time.h>

#include "cablesim/cablesim.h"
#include "cablesim/loader.h"
#include "load/validation.h"
#include "out/outfile.h"

/* ---- the command's calls ---- */

/* How `cablesim validate` was asked to run. */
typedef struct cs_validate_opts {
    const char *dir;      /* the output folder */
    const char *examples; /* the model files' folder; NULL: the parts library's examples/, else ./examples */
    const char *only;     /* the parts to run, comma-separated (cs_validate_unknown_part); NULL: all */
    int force;            /* write into dir beside files no manifest lists (CS_OUT_FORCE) */
    int report_only;      /* exit 0 even when the targets are missed */
    FILE *out, *err;      /* where it says what it wrote, and what went wrong */
} cs_validate_opts;

typedef struct cs_validate_suite cs_validate_suite;

/* The first part named in a --only list that is none of the suite's (crash, readings, roadside, bogie,
 * verification, convergence, sensitivity), its length in *len; NULL if there is none. */
const char *cs_validate_unknown_part(const char *only, size_t *len);
/* Read the values compared with, open and lock o->dir and its two files, and queue every run the wanted
 * parts need. NULL, the reason on o->err and the exit status in *status (1), if any of it fails. */
cs_validate_suite *cs_validate_begin(const cs_validate_opts *o, int *status);
/* How many jobs were queued. */
int cs_validate_job_count(const cs_validate_suite *s);
/* Run the i-th costliest job (0 <= i < cs_validate_job_count) and keep its result. Each result depends
 * only on its model: jobs may run in any order, on several threads at once, each i once. */
void cs_validate_run(cs_validate_suite *s, int i);
/* Write the report from the results, commit the two files, say so on o->out and free the suite. Returns
 * the exit status: 0, 1 when the files could not be written, 3 when APS1's or the bogie tests' targets
 * were missed (unless report_only). */
int cs_validate_finish(cs_validate_suite *s);

/* ---- within the suite ---- */

typedef struct cs_validate_result {
    int ok;
    cs_summary sm;
    double dt;             /* the run's time step, s */
    double cable_break[2]; /* s, < 0 if not broken (along the rope or at an end fitting) */
    double absorbed;       /* J: initial kinetic energy minus what is left */
    int post_failure;      /* the first post failure's event type, -1 if none */
    int released; /* cables let go by their posts (cable_release, cable_pulled_off, cable_struck_off events)
                   */
    double post_failure_t;  /* its time, s */
    double post_slide;      /* how far the post that failed first had slid out of its footing, m (0: none) */
    char how[2][48];        /* each rope: where and when it broke, or that it held with its peak */
    double slide[2];        /* each dead-man's plough through the soil, m (-1: rigid) */
    double contact_pen;     /* the face's penetration at the first output with a force on it, m (NAN: none) */
    double failure_pen;     /* and at the first output after the first post failure, m (NAN: none) */
    int events_seen;        /* the events the outputs have looked at */
    double peak_pen;        /* the face's largest penetration at an output, m (-HUGE_VAL: none yet) */
    double peak_t;          /* its time, s */
    double peak_tension[2]; /* cables 0 and 1's largest span tension then, N (NAN: no such cable) */
} cs_validate_result;

enum {
    CS_VAL_CRASH = 3,
    CS_VAL_BOGIE = CS_BOGIE_TESTS,
    CS_VAL_REFINE = 2,
    CS_VAL_VALUES = 4,
    CS_VAL_INPUTS = 6,
    CS_VAL_JOINT = 32,
    CS_VAL_JOINT_SEED = 2656
};
enum { CS_VAL_READINGS = 13, CS_VAL_ROAD = 6, CS_VAL_ROAD_READINGS = 10, CS_VAL_ROAD_STEPS = 2 };
enum {
    CS_VAL_MAX_JOBS = CS_VAL_CRASH + CS_VAL_BOGIE + CS_VAL_CRASH * CS_VAL_REFINE * CS_VAL_VALUES +
                      CS_VAL_CRASH * CS_VAL_INPUTS * 2 + CS_VAL_CRASH * CS_VAL_JOINT +
                      CS_VAL_CRASH * CS_VAL_READINGS +
                      CS_VAL_ROAD * (1 + CS_VAL_ROAD_READINGS + CS_VAL_ROAD_STEPS)
};

/* One simulation: its model (NULL: not built, the reason printed), the order's cost estimate, the result. */
typedef struct cs_validate_job {
    cs_model *model;
    double cost;
    cs_validate_result r;
} cs_validate_job;

/* The jobs, and the job each part of the report reads (-1: none). */
struct cs_validate_suite {
    cs_validate_opts opts;
    cs_loader *loader;
    cs_validation_data data; /* what the runs are compared with */
    const char *examples;    /* opts.examples, or installed, or "examples" */
    char installed[1100];    /* the parts library's examples/ */
    cs_outdir out;
    FILE *md, *csv;
    time_t t0;
    int count;
    cs_validate_job jobs[CS_VAL_MAX_JOBS];
    int order[CS_VAL_MAX_JOBS];                                /* the jobs, the costliest first */
    int base[CS_VAL_CRASH];                                    /* each crash test as its file stands */
    int bogie[CS_VAL_BOGIE];                                   /* each of data.bogie */
    int refine[CS_VAL_REFINE][CS_VAL_CRASH][CS_VAL_VALUES];    /* refinements[t], test k, values[d] */
    int sensitivity[CS_VAL_CRASH][CS_VAL_INPUTS][2];           /* test k, inputs[i] at its low, high end */
    int joint[CS_VAL_CRASH][CS_VAL_JOINT];                     /* test k, every input at once (LHS) */
    int reading[CS_VAL_CRASH][CS_VAL_READINGS];                /* test k under readings[r] (-1: none) */
    int road[CS_VAL_ROAD];                                     /* each roadside test as its file stands */
    int road_reading[CS_VAL_ROAD][CS_VAL_ROAD_READINGS];       /* roadside test k under road_readings[r] */
    int road_step[CS_VAL_ROAD][CS_VAL_ROAD_STEPS];             /* roadside test k at road_steps[d] */
    int missed;                                                /* APS1's or the bogie tests' targets */
    double joint_u[CS_VAL_CRASH][CS_VAL_JOINT][CS_VAL_INPUTS]; /* each input's fraction of its range */
    int base_loaded[CS_VAL_CRASH]; /* base_scenario[k]: the scenario crash test k's file loads to */
    cs_scenario_def base_scenario[CS_VAL_CRASH];
};

/* The cases (validate_plan.c). */
extern const char *const cs_validate_crash_names[CS_VAL_CRASH]; /* "aps1", "aps3", "aps4" */
extern const char *const cs_validate_road_names[CS_VAL_ROAD];   /* "rs1" .. "rs6" */
/* The finer time steps each roadside test runs at beside its file's (its convergence), as fractions of its
 * file's step: half of it, then a fifth. */
extern const double cs_validate_road_step_fractions[CS_VAL_ROAD_STEPS];

/* A refinement: each crash test run at every value of one scenario setting (field: its offset in
 * cs_scenario_def, a double). */
typedef struct cs_validate_refinement {
    const char *setting, *label;
    size_t field;
    int count;
    const char *values[CS_VAL_VALUES];
} cs_validate_refinement;
extern const cs_validate_refinement cs_validate_refinements[CS_VAL_REFINE];

/* An input the paper does not give, over its range (in unit); a value of cables[0] is given to
 * cables[1] as well. */
typedef struct cs_validate_input {
    const char *what, *path, *unit;
    double lo, hi;
} cs_validate_input;
extern const cs_validate_input cs_validate_inputs[CS_VAL_INPUTS];

/* A reading of a part the design data leaves open, for the tests named in `tests`. */
typedef struct cs_validate_reading {
    const char *what, *tests;
    int no_rails;         /* the paper's model: posts free of each other */
    const char *sets[13]; /* overrides, NULL-terminated */
} cs_validate_reading;
extern const cs_validate_reading cs_validate_readings[CS_VAL_READINGS];
/* A reading of what the roadside design data leaves open, for the tests named in `tests`. */
typedef struct cs_validate_road_reading {
    const char *what, *tests;
    const char *sets[5]; /* overrides, NULL-terminated */
} cs_validate_road_reading;
extern const cs_validate_road_reading cs_validate_road_readings[CS_VAL_ROAD_READINGS];

/* Is part wanted by --only (NULL: every part)? */
int cs_validate_wanted(const char *only, const char *part);
/* Queue every run the wanted parts read, in the report's order. */
void cs_validate_plan(cs_validate_suite *s);
/* "PATH=VALUE UNIT" of input i at fraction u of its range. */
void cs_validate_input_text(int i, double u, char *buf, size_t n);
/* A footing of width b and depth d in soil of S1 = s1_psf (the default dynamic factor and skin friction,
 * docs/assumptions.md); no pullout capacity given: it pulls out at its skin friction's. */
cs_footing_def cs_validate_soil_footing(double b, double d, double s1_psf);
/* The rig's bogie striking the rig's post (a library part) at speed mph, with the given footing, no
 * cable. NULL with err filled if it cannot be built. */
cs_model *cs_validate_bogie_model(cs_loader *l, const cs_bogie_rig *rig, const cs_footing_def *footing,
                                  double mph, cs_error *err);

/* The report's parts (validate_crash.c, validate_write.c), each to md and its rows to csv. */
void cs_validate_write_crash(FILE *md, FILE *csv, cs_validate_suite *s);
void cs_validate_write_bogie(FILE *md, FILE *csv, cs_validate_suite *s);
void cs_validate_write_verification(FILE *md, cs_loader *l, const cs_validation_data *data);
void cs_validate_write_readings(FILE *md, FILE *csv, const cs_validate_suite *s);
void cs_validate_write_roadside(FILE *md, FILE *csv, const cs_validate_suite *s);
void cs_validate_write_convergence(FILE *md, FILE *csv, const cs_validate_suite *s);
void cs_validate_write_sensitivity(FILE *md, FILE *csv, const cs_validate_suite *s);

/* One CSV row: suite, case, variant, then the run's numbers (validate_write.c). */
void cs_validate_csv_row(FILE *csv, const char *suite, const char *name, const char *variant,
                         const cs_validate_result *r);
/* The largest penetration, "beyond" it for a run that got through. */
const char *cs_validate_penetration_text(const cs_summary *m, char *buf, size_t n);
/* 100 (model - test) / |test|. */
double cs_validate_rel_err(double model, double test);

#endif
