/* SPDX-License-Identifier: MIT */
/* A sweep's outputs: runs.csv (one row per run), summary.md and summary.json (outcome probabilities
 * with 95% Wilson intervals, response statistics, Spearman rank correlation of inputs and responses). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "out/htmltext.h"
#include "out/jsondoc.h"
#include "status.h"
#include "sweepout.h"
#include "sweepout_int.h"
#include "writers.h"

#define Z95 1.959963984540054

static const char *const method_names[] = {"grid", "monte_carlo", "latin_hypercube"};

const char *cs_sweep_method_name(cs_sweep_method method) {
    return method_names[method];
}

/* ---- the columns of the table of runs ---- */

/* Each column but the event counts and the error, at its `what`. */
static const cs_sweep_column summary_columns[C_ERROR] = {
    [C_OUTCOME] = {"outcome", NULL, NULL,
                   "outcome: stopped, breakthrough, override, underride, redirected, time_limit, no_contact, "
                   "did_not_converge or step_limit; bad_model or failed (see error)",
                   CS_COLUMN_TEXT, C_OUTCOME},
    [C_RATING] = {"astm_f2656_as_run", NULL, NULL, "ASTM F2656 designation as run", CS_COLUMN_TEXT, C_RATING},
    [C_ASTM_PEN] = {"astm_f2656_penetration", "m", NULL,
                    "penetration the ASTM F2656 designation as run rests on, as that standard measures it",
                    CS_COLUMN_REAL, C_ASTM_PEN},
    [C_SD_STD] = {"sd_std_02_01_as_run", NULL, NULL, "SD-STD-02.01 designation as run", CS_COLUMN_TEXT,
                  C_SD_STD},
    [C_T] = {"time_reached", "s", NULL, "time reached", CS_COLUMN_REAL, C_T},
    [C_DECEL] = {"max_50ms_decel", "g", "standard_free_fall", "max 50-ms average deceleration",
                 CS_COLUMN_REAL, C_DECEL},
    [C_T_DECEL] = {"t_max_50ms_decel", "s", NULL, "time of the max 50-ms deceleration", CS_COLUMN_REAL,
                   C_T_DECEL},
    [C_PEN] = {"max_dynamic_penetration", "m", NULL,
               "max dynamic penetration past the attack face (a vehicle the barrier held)", CS_COLUMN_REAL,
               C_PEN},
    [C_BEYOND] = {"penetration_beyond", "m", NULL,
                  "penetration beyond this: how far a vehicle not held had got when the run ended",
                  CS_COLUMN_REAL, C_BEYOND},
    [C_DEFL] = {"max_barrier_deflection", "m", NULL, "max barrier deflection", CS_COLUMN_REAL, C_DEFL},
    [C_WIDTH] = {"working_width", "m", NULL,
                 "working width: furthest reach past the barrier line (vehicle, cable or standing post)",
                 CS_COLUMN_REAL, C_WIDTH},
    [C_STOP] = {"stop_time", "s", NULL, "stop time (a run that stopped)", CS_COLUMN_REAL, C_STOP},
    [C_EXIT] = {"exit_speed", "m/s", NULL, "exit speed (a run that broke through or was redirected)",
                CS_COLUMN_REAL, C_EXIT},
    [C_EXIT_ANGLE] = {"exit_angle", "deg", "degree",
                      "exit angle away from the barrier line (a run that broke through or was redirected)",
                      CS_COLUMN_REAL, C_EXIT_ANGLE},
    [C_CONTACT] = {"first_contact_time", "s", NULL, "time of first contact", CS_COLUMN_REAL, C_CONTACT},
    [C_POSTS_LEFT] = {"posts_failed_left", NULL, NULL, "posts failed left of the impact point (lower x)",
                      CS_COLUMN_COUNT, C_POSTS_LEFT},
    [C_POSTS_RIGHT] = {"posts_failed_right", NULL, NULL, "posts failed right of the impact point (higher x)",
                       CS_COLUMN_COUNT, C_POSTS_RIGHT},
    [C_CABLES] = {"cables_broken", NULL, NULL, "cables broken", CS_COLUMN_COUNT, C_CABLES},
    [C_TENSION] = {"max_cable_tension", "N", NULL, "max cable tension", CS_COLUMN_REAL, C_TENSION},
    [C_KE] = {"initial_kinetic_energy", "J", NULL, "initial kinetic energy", CS_COLUMN_REAL, C_KE},
    [C_ENERGY] = {"energy_balance_error", "1", NULL, "largest energy balance error over the run (fraction)",
                  CS_COLUMN_REAL, C_ENERGY},
    [C_WARNINGS] = {"solver_warnings", NULL, NULL, "steps whose barrier solve hit its sweep cap",
                    CS_COLUMN_COUNT, C_WARNINGS},
    [C_RESIDUAL] = {"max_solver_residual", "1", NULL, "largest relative residual such a step left",
                    CS_COLUMN_REAL, C_RESIDUAL},
    [C_X] = {"final_x", "m", NULL, "final x of the vehicle's centre of gravity", CS_COLUMN_REAL, C_X},
    [C_Y] = {"final_y", "m", NULL, "final y of the vehicle's centre of gravity", CS_COLUMN_REAL, C_Y},
    [C_Z] = {"final_z", "m", NULL, "final z of the vehicle's centre of gravity", CS_COLUMN_REAL, C_Z},
};

/* ---- the summary's responses ---- */

/* A response of summary.md and summary.json: runs.csv's column `what` (with column `plus` added, or -1),
 * times scale (SI to the unit its key and label give), over the runs that have it (runs.csv's cell not
 * empty). `over` names those runs where they are not every run that ran to the end. */
typedef struct response_def {
    int what, plus;
    double scale;
    const char *key;   /* summary.json's name, with its unit */
    const char *label; /* summary.md's, with its unit */
    const char *over;
} response_def;

enum { R_COUNT = 9 };
static const response_def responses[R_COUNT] = {
    {C_DECEL, -1, 1.0, "max_50ms_decel_g", "max 50-ms deceleration (g)", NULL},
    {C_PEN, -1, 1.0, "max_dynamic_penetration_m", "max dynamic penetration (m)",
     "the runs the barrier held (stopped, redirected or never touched it)"},
    {C_BEYOND, -1, 1.0, "penetration_beyond_m", "penetration beyond (m)",
     "the runs it did not hold (through it, or still going when the run ended): how far past the attack "
     "face the vehicle had got when the run ended; its penetration is beyond that"},
    {C_DEFL, -1, 1.0, "max_barrier_deflection_m", "max barrier deflection (m)", NULL},
    {C_WIDTH, -1, 1.0, "working_width_m", "working width (m)", NULL},
    {C_TENSION, -1, 1e-3, "max_cable_tension_kn", "max cable tension (kN)", NULL},
    {C_EXIT, -1, 1.0, "exit_speed_mps", "exit speed (m/s)",
     "the runs that left the barrier (broke through, rode over or ran under it, or were redirected)"},
    {C_POSTS_LEFT, C_POSTS_RIGHT, 1.0, "posts_failed", "posts failed", NULL},
    {C_CABLES, -1, 1.0, "cables_broken", "cables broken", NULL},
};

/* Response q of a run that ran to the end; NaN where it has none. */
static double response(const cs_sweep_result *r, int q) {
    const response_def *d = &responses[q];
    double v = cs_sweep_column_number(&summary_columns[d->what], r);
    if (d->plus >= 0) v += cs_sweep_column_number(&summary_columns[d->plus], r);
    return v * d->scale;
}

/* failure events: every event type but those that end a run */
static int is_failure_event(int t) {
    return t != CS_EVENT_STOPPED && t != CS_EVENT_BREAKTHROUGH && t != CS_EVENT_REDIRECTED;
}

/* the summary's columns, a count per event type (but those that end a run) and the error */
_Static_assert(C_ERROR + CS_EVENT_TYPE_COUNT <= CS_SWEEP_MAX_COLUMNS, "runs.csv's columns fit");

int cs_sweep_columns(cs_sweep_column *cols) {
    int n = 0;
    for (int c = 0; c < C_ERROR; c++)
        cols[n++] = summary_columns[c];
    for (int t = 0; t < CS_EVENT_TYPE_COUNT; t++) {
        if (!is_failure_event(t)) continue;
        const char *name = cs_event_type_name((cs_event_type)t);
        cs_sweep_column *e = &cols[n++];
        *e = (cs_sweep_column){.kind = CS_COLUMN_COUNT, .what = C_EVENTS + t};
        snprintf(e->name, sizeof e->name, "events_%s", name);
        snprintf(e->long_name, sizeof e->long_name, "number of %s events", name);
    }
    cols[n++] =
        (cs_sweep_column){"error", NULL, NULL, "why the run did not run to the end", CS_COLUMN_TEXT, C_ERROR};
    return n;
}

double cs_sweep_column_number(const cs_sweep_column *c, const cs_sweep_result *r) {
    const cs_summary *m = &r->summary;
    if (r->status != CS_RUN_OK || r->pending) return NAN;
    if (c->what >= C_EVENTS) return r->event_counts[c->what - C_EVENTS];
    switch (c->what) {
    case C_ASTM_PEN:
        return r->astm_penetration;
    case C_T:
        return m->t_end_s;
    case C_DECEL:
        return m->max_50ms_decel_g;
    case C_T_DECEL:
        return m->t_max_50ms_decel_s;
    case C_PEN:
        return cs_penetration_is_final(m->outcome) ? m->max_dynamic_penetration_m : NAN;
    case C_BEYOND:
        return cs_penetration_is_final(m->outcome) ? NAN : m->max_dynamic_penetration_m;
    case C_DEFL:
        return m->max_barrier_deflection_m;
    case C_WIDTH:
        return m->working_width_m;
    case C_STOP:
        return m->outcome == CS_STOPPED ? m->stop_time_s : NAN;
    case C_EXIT:
        return cs_outcome_exits(m->outcome) ? m->exit_speed_mps : NAN;
    case C_EXIT_ANGLE:
        return cs_outcome_exits(m->outcome) ? m->exit_angle_deg : NAN;
    case C_CONTACT:
        return m->first_contact_time_s >= 0 ? m->first_contact_time_s : NAN;
    case C_POSTS_LEFT:
        return m->posts_failed_left;
    case C_POSTS_RIGHT:
        return m->posts_failed_right;
    case C_CABLES:
        return m->cables_broken;
    case C_TENSION:
        return m->max_cable_tension_n;
    case C_KE:
        return m->initial_kinetic_energy_j;
    case C_ENERGY:
        return m->energy_balance_error;
    case C_WARNINGS:
        return m->solver_warnings;
    case C_RESIDUAL:
        return m->max_solver_residual;
    case C_X:
    case C_Y:
    case C_Z:
        return m->final_position_m[c->what - C_X];
    default:
        return NAN;
    }
}

const char *cs_sweep_column_text(const cs_sweep_column *c, const cs_sweep_result *r) {
    int ok = r->status == CS_RUN_OK;
    if (r->pending) return "";
    switch (c->what) {
    case C_OUTCOME:
        return ok                              ? cs_outcome_name(r->summary.outcome)
               : r->status == CS_RUN_BAD_MODEL ? "bad_model"
                                               : "failed";
    case C_RATING:
        return ok ? r->rating : "";
    case C_SD_STD:
        return ok ? r->sd_std_rating : "";
    case C_ERROR:
        return ok ? "" : r->error;
    default:
        return "";
    }
}

/* ---- runs.csv ---- */

static void csv_text(FILE *f, const char *s) {
    cs_csv_text(f, s, 0);
}

static void csv_num(FILE *f, double v) {
    if (isfinite(v)) fprintf(f, "%.10g", v);
}

int cs_sweep_column_heading(const cs_sweep_column *c, char *buf, size_t size) {
    return snprintf(buf, size, "%.*s%s%s%s", (int)sizeof c->name, c->name, c->unit ? " [" : "",
                    c->unit ? c->unit : "", c->unit ? "]" : "");
}

/* runs.csv's first line. */
static void runs_header(FILE *f, const cs_sweep_spec *s) {
    int k = s->var_count;
    cs_sweep_column cols[CS_SWEEP_MAX_COLUMNS];
    int nc = cs_sweep_columns(cols);
    fprintf(f, "run");
    for (int j = 0; j < k; j++) {
        char head[600];
        const cs_sweep_var *v = &s->vars[j];
        snprintf(head, sizeof head, "%s%s%s%s", v->path, v->unit[0] ? " [" : "", v->unit,
                 v->unit[0] ? "]" : "");
        fputc(',', f);
        csv_text(f, head);
    }
    for (int c = 0; c < nc; c++) {
        char head[80];
        cs_sweep_column_heading(&cols[c], head, sizeof head);
        fprintf(f, ",%s", head);
    }
    fputc('\n', f);
}

void cs_sweep_write_run_row(FILE *f, const cs_sweep_spec *s, const double *x, const cs_sweep_result *r,
                            long i) {
    int k = s->var_count;
    cs_sweep_column cols[CS_SWEEP_MAX_COLUMNS];
    int nc = cs_sweep_columns(cols);
    fprintf(f, "%ld", i);
    for (int j = 0; j < k; j++) {
        char value[256];
        cs_sweep_value_text(&s->vars[j], x[i * k + j], value, sizeof value);
        fputc(',', f);
        csv_text(f, value);
    }
    for (int c = 0; c < nc; c++) {
        fputc(',', f);
        if (cols[c].kind == CS_COLUMN_TEXT)
            csv_text(f, cs_sweep_column_text(&cols[c], r));
        else
            csv_num(f, cs_sweep_column_number(&cols[c], r));
    }
    fputc('\n', f);
}

cs_status cs_sweep_write_runs(FILE *f, const cs_sweep_spec *s, const double *x, const cs_sweep_result *r,
                              long n, cs_error *err) {
    runs_header(f, s);
    for (long i = 0; i < n; i++)
        if (!r[i].pending) cs_sweep_write_run_row(f, s, x, &r[i], i); /* a partial sweep's others: none */
    return ferror(f) ? cs_error_set(err, CS_ERR_IO, "write error") : cs_status_set(err, CS_OK, "");
}

/* ---- the summary ---- */

typedef struct tally {
    char name[48];
    char label[96];
    long count;
} tally;

typedef struct stats {
    long runs; /* with a value */
    double mean, sd, min, p05, p50, p95, max;
} stats;

typedef struct summary {
    const cs_sweep_result *r;            /* the runs' results, for the plots' captions */
    long n, done, ok, bad_model, failed; /* done: run (a partial sweep's others are pending) */
    tally *t;                            /* outcomes, penetration, events, designations */
    int tally_count;
    stats resp[R_COUNT];
    double *rho; /* [var * R_COUNT + response]; NaN: not numeric or constant */
} summary;

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

void cs_sweep_sort(double *v, long n) {
    qsort(v, (size_t)n, sizeof *v, cmp_double);
}

double cs_sweep_quantile(const double *sorted, long n, double p) {
    double h = (double)(n - 1) * p;
    long lo = (long)floor(h);
    if (lo >= n - 1) return sorted[n - 1];
    return sorted[lo] + (h - (double)lo) * (sorted[lo + 1] - sorted[lo]);
}

/* The statistics of m values (sorts them); NaN where m is too small. */
static stats stats_of(double *a, long m) {
    stats st = {m, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
    if (m == 0) return st;
    double sum = 0, ss = 0;
    for (long i = 0; i < m; i++)
        sum += a[i];
    st.mean = sum / (double)m;
    for (long i = 0; i < m; i++)
        ss += (a[i] - st.mean) * (a[i] - st.mean);
    st.sd = m > 1 ? sqrt(ss / (double)(m - 1)) : NAN;
    cs_sweep_sort(a, m);
    st.min = a[0], st.max = a[m - 1];
    st.p05 = cs_sweep_quantile(a, m, 0.05), st.p50 = cs_sweep_quantile(a, m, 0.5);
    st.p95 = cs_sweep_quantile(a, m, 0.95);
    return st;
}

static int add_tally(summary *s, const char *name, const char *label, long count) {
    tally *t = realloc(s->t, (size_t)(s->tally_count + 1) * sizeof *t);
    if (!t) return -1;
    s->t = t;
    tally *e = &t[s->tally_count++];
    snprintf(e->name, sizeof e->name, "%s", name);
    snprintf(e->label, sizeof e->label, "%s", label);
    e->count = count;
    return 0;
}

static int make_summary(summary *s, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                        long n) {
    memset(s, 0, sizeof *s);
    s->r = r;
    s->n = n;
    int k = spec->var_count;
    long *ok = malloc((size_t)(n > 0 ? n : 1) * sizeof *ok);
    double *a = malloc((size_t)(n > 0 ? n : 1) * sizeof *a), *b = malloc((size_t)(n > 0 ? n : 1) * sizeof *b);
    s->rho = malloc((size_t)(k > 0 ? k : 1) * R_COUNT * sizeof *s->rho);
    if (!ok || !a || !b || !s->rho) goto oom;
    for (long i = 0; i < n; i++) {
        if (r[i].pending) continue;
        s->done++;
        if (r[i].status == CS_RUN_OK)
            ok[s->ok++] = i;
        else if (r[i].status == CS_RUN_BAD_MODEL)
            s->bad_model++;
        else
            s->failed++;
    }
    static const cs_outcome outcomes[] = {CS_STOPPED,    CS_BREAKTHROUGH,     CS_OVERRIDE,
                                          CS_UNDERRIDE,  CS_REDIRECTED,       CS_TIME_LIMIT,
                                          CS_NO_CONTACT, CS_DID_NOT_CONVERGE, CS_STEP_LIMIT};
    static const char *const outcome_labels[] = {"stopped",
                                                 "breakthrough",
                                                 "rode over the cables",
                                                 "ran under the cables",
                                                 "redirected",
                                                 "time limit reached (still moving)",
                                                 "never touched the barrier",
                                                 "did not converge (solve budget used up)",
                                                 "step limit reached (scenario.max_steps)"};
    for (size_t o = 0; o < sizeof outcomes / sizeof outcomes[0]; o++) {
        long c = 0;
        for (long i = 0; i < s->ok; i++)
            c += r[ok[i]].summary.outcome == outcomes[o];
        if (add_tally(s, cs_outcome_name(outcomes[o]), outcome_labels[o], c) != 0) goto oom;
    }
    long pen = 0;
    for (long i = 0; i < s->ok; i++)
        pen +=
            cs_outcome_through(r[ok[i]].summary.outcome) || r[ok[i]].summary.max_dynamic_penetration_m > 1.0;
    if (add_tally(s, "penetration_over_1m",
                  "max dynamic penetration > 1 m past the attack face (or the vehicle got through)",
                  pen) != 0)
        goto oom;
    for (int t = 0; t < CS_EVENT_TYPE_COUNT; t++) {
        if (!is_failure_event(t)) continue;
        long c = 0;
        for (long i = 0; i < s->ok; i++)
            c += r[ok[i]].event_counts[t] > 0;
        char name[48], label[96];
        snprintf(name, sizeof name, "event_%s", cs_event_type_name((cs_event_type)t));
        snprintf(label, sizeof label, "at least one %s", cs_event_type_name((cs_event_type)t));
        if (add_tally(s, name, label, c) != 0) goto oom;
    }
    /* each standard's designations as run, in order of first appearance by run: named by runs.csv's
     * column and its label ("astm_f2656_as_run M40/P2"), in words by the column's long name */
    static const int designations[] = {C_RATING, C_SD_STD};
    for (size_t d = 0; d < sizeof designations / sizeof *designations; d++) {
        const cs_sweep_column *c = &summary_columns[designations[d]];
        int first = s->tally_count;
        for (long i = 0; i < s->ok; i++) {
            const char *label = cs_sweep_column_text(c, &r[ok[i]]);
            char name[48], words[96];
            snprintf(name, sizeof name, "%s %s", c->name, label);
            snprintf(words, sizeof words, "%s %s", c->long_name, label);
            int seen = 0;
            for (int t = first; t < s->tally_count && !seen; t++)
                if (strcmp(s->t[t].name, name) == 0) s->t[t].count++, seen = 1;
            if (!seen && add_tally(s, name, words, 1) != 0) goto oom;
        }
    }
    for (int q = 0; q < R_COUNT; q++) {
        long m = 0;
        for (long i = 0; i < s->ok; i++)
            if (isfinite(a[m] = response(&r[ok[i]], q))) m++;
        s->resp[q] = stats_of(a, m);
        for (int j = 0; j < k; j++) { /* over the runs with a value */
            long mj = 0;
            for (long i = 0; i < s->ok; i++)
                if (isfinite(a[mj] = response(&r[ok[i]], q)))
                    b[mj++] = cs_sweep_value_used(&spec->vars[j], x[ok[i] * k + j]);
            s->rho[j * R_COUNT + q] = spec->vars[j].numeric ? cs_spearman(b, a, mj) : NAN;
        }
    }
    free(ok), free(a), free(b);
    return 0;
oom:
    free(ok), free(a), free(b);
    free(s->rho), free(s->t);
    return -1;
}

static void free_summary(summary *s) {
    free(s->rho);
    free(s->t);
}

/* A number in the format, or `missing` where it is not finite (no NaN reaches a file). */
static void put_num(FILE *f, double v, const char *format, const char *missing) {
    if (isfinite(v))
        fprintf(f, format, v);
    else
        fputs(missing, f);
}

static void md_num(FILE *f, double v) {
    put_num(f, v, "%.4g", "n/a");
}

/* The summary's body in one format, from the computed summary. */
typedef cs_status (*summary_writer)(FILE *f, const cs_sweep_spec *spec, long n, const summary *s,
                                    cs_error *err);

/* Compute the summary, write it with `body`, and report a failure to allocate or to write. */
static cs_status write_summary(FILE *f, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                               long n, cs_error *err, summary_writer body) {
    summary s;
    if (make_summary(&s, spec, x, r, n) != 0) return cs_error_set(err, CS_ERR_MEMORY, "out of memory");
    cs_status rc = body(f, spec, n, &s, err);
    free_summary(&s);
    if (rc != CS_OK) return rc;
    return ferror(f) ? cs_error_set(err, CS_ERR_IO, "write error") : cs_status_set(err, CS_OK, "");
}

static cs_status summary_md(FILE *f, const cs_sweep_spec *spec, long n, const summary *s, cs_error *err) {
    (void)err;
    int k = spec->var_count;
    const cs_sweep_origin *o = &spec->origin;
    fprintf(f, "# Sweep ");
    cs_html_text(f, spec->file);
    fprintf(f, "\n\n");
    if (s->done < n)
        fprintf(f,
                "**Partial**: %ld of %ld runs were run before %s stopped the sweep; the tables below are of "
                "those. ",
                s->done, n, o->stopped_by ? o->stopped_by : "a signal");
    if (s->done < n) {
        char resume[1100];
        snprintf(resume, sizeof resume, "cablesim sweep --resume %s", o->dir ? o->dir : "DIR");
        cs_md_code(f, resume);
        fprintf(f, " runs the rest and completes these files.\n\n");
    }
    fprintf(f, "Written by cablesim %s", CS_VERSION_STRING);
    if (o->command) fprintf(f, ": "), cs_md_code(f, o->command);
    if (o->has_model_hash) fprintf(f, "; the base model's hash %016llx", o->model_hash);
    fprintf(f, ".\n\n");
    fprintf(f, "Model "), cs_md_code(f, spec->model);
    fprintf(f, ", method %s, %ld runs", method_names[spec->method], n);
    if (spec->method != CS_SWEEP_GRID) fprintf(f, ", seed %llu", (unsigned long long)spec->seed);
    fprintf(f, ": %ld ran to the end, %ld bad models, %ld failed", s->ok, s->bad_model, s->failed);
    if (s->done < n) fprintf(f, ", %ld not run yet", n - s->done);
    fprintf(f, ".\n\n");
    for (int i = 0; i < spec->set_count; i++)
        fprintf(f, "%s", i ? ", " : "Fixed for every run: "), cs_md_code(f, spec->sets[i]),
            fprintf(f, "%s", i + 1 == spec->set_count ? ".\n\n" : "");
    fprintf(f, "## Inputs\n\n| path | SI unit | varied as |\n| --- | --- | --- |\n");
    for (int j = 0; j < k; j++)
        fprintf(f, "| "), cs_md_code(f, spec->vars[j].path), fprintf(f, " | "),
            cs_html_text(f, spec->vars[j].unit[0] ? spec->vars[j].unit : "-"), fprintf(f, " | "),
            cs_html_text(f, spec->vars[j].desc), fprintf(f, " |\n");
    fprintf(f,
            "\n## Outcomes\n\nProbabilities over the %ld runs that ran to the end, with 95%% Wilson score "
            "intervals.\n\n| outcome | runs | probability | 95%% interval |\n| --- | --- | --- | --- |\n",
            s->ok);
    for (int t = 0; t < s->tally_count; t++) {
        cs_interval w = cs_wilson(s->t[t].count, s->ok, Z95);
        fprintf(f, "| %s | %ld | ", s->t[t].label, s->t[t].count); /* cablesim's words, not the spec's */
        md_num(f, w.p);
        fprintf(f, " | ");
        md_num(f, w.lo);
        fprintf(f, " - ");
        md_num(f, w.hi);
        fprintf(f, " |\n");
    }
    fprintf(f,
            "\n## Responses\n\nOver the %ld runs that ran to the end, each response over those that have it "
            "(`runs`)",
            s->ok);
    for (int q = 0; q < R_COUNT; q++)
        if (responses[q].over) fprintf(f, "; %s only over %s", responses[q].label, responses[q].over);
    fprintf(f, ". Forces in kN.\n\n| response | runs | mean | sd | min | 5%% | median | 95%% | max |\n"
               "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (int q = 0; q < R_COUNT; q++) {
        const stats *st = &s->resp[q];
        const double v[] = {st->mean, st->sd, st->min, st->p05, st->p50, st->p95, st->max};
        fprintf(f, "| %s | %ld |", responses[q].label, st->runs);
        for (int c = 0; c < 7; c++)
            fputc(' ', f), md_num(f, v[c]), fprintf(f, " |");
        fputc('\n', f);
    }
    fprintf(
        f,
        "\n## Input importance\n\nSpearman rank correlation of each input with each response, over the runs "
        "that have it (n/a: a text input, a constant column, or fewer than two runs).\n\n| input |");
    for (int q = 0; q < R_COUNT; q++)
        fprintf(f, " %s |", responses[q].label);
    fprintf(f, "\n| --- |");
    for (int q = 0; q < R_COUNT; q++)
        fprintf(f, " --- |");
    fputc('\n', f);
    for (int j = 0; j < k; j++) {
        fprintf(f, "| "), cs_md_code(f, spec->vars[j].path), fprintf(f, " |");
        for (int q = 0; q < R_COUNT; q++) {
            double rho = s->rho[j * R_COUNT + q];
            fputc(' ', f);
            if (isfinite(rho))
                fprintf(f, "%+.2f", rho);
            else
                fprintf(f, "n/a");
            fprintf(f, " |");
        }
        fputc('\n', f);
    }
    if (spec->plot_count > 0) fprintf(f, "\n## Plots\n\n");
    for (int k = 0; k < spec->plot_count; k++) {
        char file[256], caption[1000];
        cs_sweep_plot_file(spec, k, file, sizeof file);
        cs_sweep_plot_caption(spec, k, s->r, n, caption, sizeof caption);
        fprintf(f, "- "), cs_md_code(f, file), fprintf(f, ": "), cs_html_text(f, caption), fprintf(f, ".\n");
    }
    return CS_OK;
}

cs_status cs_sweep_write_summary_md(FILE *f, const cs_sweep_spec *spec, const double *x,
                                    const cs_sweep_result *r, long n, cs_error *err) {
    return write_summary(f, spec, x, r, n, err, summary_md);
}

/* summary.json's "cablesim" member: the version, the command line and the base model's hash. */
static json_object *origin_json(const cs_sweep_origin *o) {
    json_object *j = json_object_new_object();
    char hash[17];
    snprintf(hash, sizeof hash, "%016llx", o->model_hash);
    json_object_object_add(j, "version", cs_jstr(CS_VERSION_STRING));
    json_object_object_add(j, "command", cs_jstr(o->command));
    json_object_object_add(j, "model_hash", cs_jstr(o->has_model_hash ? hash : NULL));
    return j;
}

/* The members "partial" to "resume" of the journal's first line and of summary.json (lines nonzero: with
 * its line breaks, and "runs_done" and "stopped_by" after "partial"). */
static void origin_members(json_object *j, const cs_sweep_origin *o, int partial, long done, int lines) {
    char hash[17];
    snprintf(hash, sizeof hash, "%016llx", o->inputs_hash);
    json_object *resume = o->resume ? json_tokener_parse(o->resume) : NULL; /* resume_record's JSON */
    json_object_object_add(j, "cablesim", origin_json(o));
    json_object_object_add(j, "partial", json_object_new_boolean(partial));
    if (lines) {
        json_object_object_add(j, "runs_done", json_object_new_int64(done));
        json_object_object_add(j, "stopped_by", cs_jstr(partial ? o->stopped_by : NULL));
        static const char *const new_line[] = {"partial", "resume", "spec", NULL};
        cs_jkeys_on_new_line(j, new_line);
    }
    json_object_object_add(j, "inputs_hash", cs_jstr(hash));
    json_object_object_add(j, "resume", resume);
}

/* j as the file's text and a line break; CS_OK, or CS_ERR_MEMORY with err filled. */
static cs_status put_json(FILE *f, json_object *j, cs_error *err) {
    int ok = j && cs_json_write(f, j, 0, "\n") == 0;
    json_object_put(j);
    return ok ? cs_status_set(err, CS_OK, "") : cs_error_set(err, CS_ERR_MEMORY, "out of memory");
}

cs_status cs_sweep_write_journal_start(FILE *f, const cs_sweep_spec *spec, const double *x,
                                       const cs_sweep_result *r, long n, cs_error *err) {
    json_object *j = json_object_new_object();
    if (j) origin_members(j, &spec->origin, 1, 0, 0);
    cs_status rc = put_json(f, j, err);
    return rc == CS_OK ? cs_sweep_write_runs(f, spec, x, r, n, err) : rc;
}

static cs_status summary_json(FILE *f, const cs_sweep_spec *spec, long n, const summary *s, cs_error *err) {
    int k = spec->var_count;
    json_object *j = json_object_new_object();
    if (!j) return put_json(f, j, err);
    origin_members(j, &spec->origin, s->done < n, s->done, 1);
    json_object_object_add(j, "spec", cs_jstr(spec->file));
    json_object_object_add(j, "model", cs_jstr(spec->model));
    json_object_object_add(j, "method", cs_jstr(method_names[spec->method]));
    json_object_object_add(j, "seed", json_object_new_uint64(spec->seed));
    json_object_object_add(j, "runs", json_object_new_int64(n));
    json_object_object_add(j, "ok", json_object_new_int64(s->ok));
    json_object_object_add(j, "bad_model", json_object_new_int64(s->bad_model));
    json_object_object_add(j, "failed", json_object_new_int64(s->failed));
    json_object *sets = json_object_new_array(), *inputs = json_object_new_array();
    for (int i = 0; i < spec->set_count; i++)
        json_object_array_add(sets, cs_jstr(spec->sets[i]));
    json_object_object_add(j, "set", sets);
    for (int v = 0; v < k; v++) {
        json_object *in = json_object_new_object();
        json_object_object_add(in, "path", cs_jstr(spec->vars[v].path));
        json_object_object_add(in, "unit", cs_jstr(spec->vars[v].unit));
        json_object_object_add(in, "varied_as", cs_jstr(spec->vars[v].desc));
        json_object_array_add(inputs, in);
    }
    json_object_object_add(j, "inputs", inputs);
    json_object *probabilities = json_object_new_object();
    for (int t = 0; t < s->tally_count; t++) {
        cs_interval w = cs_wilson(s->t[t].count, s->ok, Z95);
        json_object *p = json_object_new_object(), *ci = json_object_new_array();
        json_object_object_add(p, "count", json_object_new_int64(s->t[t].count));
        json_object_object_add(p, "p", cs_jnum(w.p));
        json_object_array_add(ci, cs_jnum(w.lo));
        json_object_array_add(ci, cs_jnum(w.hi));
        json_object_object_add(p, "ci95", ci);
        json_object_object_add(probabilities, s->t[t].name, p);
    }
    json_object_object_add(j, "probabilities", probabilities);
    static const char *const stat_names[] = {"mean", "sd", "min", "p05", "median", "p95", "max"};
    json_object *stats_of_responses = json_object_new_object(), *spearman = json_object_new_object();
    for (int q = 0; q < R_COUNT; q++) {
        const stats *st = &s->resp[q];
        const double v[] = {st->mean, st->sd, st->min, st->p05, st->p50, st->p95, st->max};
        json_object *o = json_object_new_object();
        json_object_object_add(o, "runs", json_object_new_int64(st->runs));
        json_object_object_add(
            o, "over", cs_jstr(responses[q].over ? responses[q].over : "the runs that ran to the end"));
        for (int c = 0; c < 7; c++)
            json_object_object_add(o, stat_names[c], cs_jnum(v[c]));
        json_object_object_add(stats_of_responses, responses[q].key, o);
        json_object *rho = json_object_new_object();
        for (int v = 0; v < k; v++)
            json_object_object_add(rho, spec->vars[v].path, cs_jnum(s->rho[v * R_COUNT + q]));
        json_object_object_add(spearman, responses[q].key, rho);
    }
    json_object_object_add(j, "responses", stats_of_responses);
    json_object_object_add(j, "spearman", spearman);
    return put_json(f, j, err);
}

cs_status cs_sweep_write_summary_json(FILE *f, const cs_sweep_spec *spec, const double *x,
                                      const cs_sweep_result *r, long n, cs_error *err) {
    return write_summary(f, spec, x, r, n, err, summary_json);
}
