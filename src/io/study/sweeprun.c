/* SPDX-License-Identifier: MIT */
/* One run of a sweep, and the check of a spec against its model before any run. Each thread has a
 * loader of its own (the loader serialises its calls into udunits2), so runs may go in parallel threads;
 * between runs it keeps the files it has parsed and drops the rest (cs_loader_reuse). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/loader.h"
#include "fnv.h"
#include "rating.h"
#include "sweep.h"

/* The --set value of variable v for an input x: its text (runs.csv's), with the SI unit of a quantity,
 * which a model takes only with its unit. */
static void set_value(const cs_sweep_var *v, double x, char *buf, size_t size) {
    char value[256];
    cs_sweep_value_text(v, x, value, sizeof value);
    int unit = v->numeric && !v->integer && v->q != CS_Q_NUMBER;
    snprintf(buf, size, "%s%s%s", value, unit ? " " : "", unit ? cs_quantity_get(v->q)->si : "");
}

/* Queue the fixed sets, then the inputs of a run (var < 0: all; else all of xrow but var at value
 * x_var), and load. */
static int load_run(cs_loader *l, const cs_sweep_spec *s, const double *xrow, int var, double x_var,
                    cs_model_input *in) {
    for (int k = 0; k < s->set_count; k++)
        cs_loader_set(l, s->sets[k]);
    for (int j = 0; j < s->var_count; j++) {
        char value[300], set[1024];
        set_value(&s->vars[j], j == var ? x_var : xrow[j], value, sizeof value);
        snprintf(set, sizeof set, "%s=%s", s->vars[j].path, value);
        cs_loader_set(l, set);
    }
    return cs_loader_load(l, s->model, in);
}

cs_loader *cs_sweep_loader(const cs_sweep_spec *s, cs_error *err) {
    cs_loader *l = cs_loader_create(NULL, err);
    for (int i = 0; l && i < s->allow.count; i++)
        cs_loader_allow_path(l, s->allow.dirs[i], NULL); /* canonical folders: each is one */
    return l;
}

void cs_sweep_run(const cs_sweep_spec *s, const double *xrow, cs_loader *loader, cs_sweep_result *r) {
    memset(r, 0, sizeof *r);
    r->astm_penetration = NAN;
    cs_error err = {0};
    cs_loader *l = loader ? loader : cs_sweep_loader(s, &err);
    if (loader) cs_loader_reuse(loader); /* the model file and the library are parsed once per loader */
    if (!l) {
        r->status = CS_RUN_BAD_MODEL;
        snprintf(r->error, sizeof r->error, "%s", err.message);
        return;
    }
    cs_model_input in = {.size = sizeof in};
    cs_model *m = NULL;
    if (load_run(l, s, xrow, -1, 0, &in) != 0 || !(m = cs_loader_build(l, &in))) {
        r->status = CS_RUN_BAD_MODEL;
        snprintf(r->error, sizeof r->error, "%s",
                 cs_loader_error_count(l) ? cs_loader_error(l, 0) : "bad model");
        if (!loader) cs_loader_free(l);
        return;
    }
    cs_vehicle_def vehicle = in.vehicle;
    double speed = in.scenario.speed, angle = in.scenario.angle;
    if (!loader) cs_loader_free(l);
    cs_state *state = cs_state_create(m, &err);
    if (!state) {
        r->status = CS_RUN_FAILED;
        snprintf(r->error, sizeof r->error, "%s", err.message);
        cs_model_free(m);
        return;
    }
    if (cs_run(m, state, NULL, NULL, &err) != CS_OK) {
        r->status = CS_RUN_FAILED;
        snprintf(r->error, sizeof r->error, "%s", err.message);
    }
    r->summary.size = sizeof r->summary;
    cs_state_summary(state, &r->summary, NULL);
    for (int i = 0; i < cs_state_event_count(state); i++) {
        cs_event e = {.size = sizeof e};
        cs_state_event(state, i, &e, NULL);
        if (e.type >= 0 && e.type < CS_EVENT_TYPE_COUNT) r->event_counts[e.type]++;
    }
    if (r->status == CS_RUN_OK) {
        cs_rating_rules rules = cs_default_rating_rules();
        const char *klass = s->vehicle_class[0] ? s->vehicle_class : NULL;
        cs_rating astm = cs_rate_as_run(CS_ASTM_F2656, klass, &vehicle, speed, angle, &r->summary, &rules);
        cs_rating sd = cs_rate_as_run(CS_SD_STD_02_01, klass, &vehicle, speed, angle, &r->summary, &rules);
        snprintf(r->rating, sizeof r->rating, "%s", astm.label);
        r->astm_penetration = cs_rating_penetration(&astm);
        snprintf(r->sd_std_rating, sizeof r->sd_std_rating, "%s", sd.label);
    }
    cs_state_free(state);
    cs_model_free(m);
}

/* Put a loader's problems into the spec: those of a --set at the place in the spec that made it. */
static void map_errors(cs_sweep_spec *s, cs_loader *l, const double *xrow, int var, double x_var, int line,
                       int col) {
    for (int i = 0; i < cs_loader_error_count(l); i++) {
        const char *e = cs_loader_error(l, i);
        char text[1400] = "";
        int at_line = 0, at_col = 0;
        for (int j = 0; j < s->var_count && !text[0]; j++) {
            char value[300], prefix[1024];
            set_value(&s->vars[j], j == var ? x_var : xrow[j], value, sizeof value);
            int n = snprintf(prefix, sizeof prefix, "--set %s=%s: ", s->vars[j].path, value);
            if (strncmp(e, prefix, (size_t)n) != 0) continue;
            snprintf(text, sizeof text, "vary: %s = %s: %s", s->vars[j].path, value, e + n);
            at_line = j == var ? line : s->vars[j].line;
            at_col = j == var ? col : s->vars[j].col;
        }
        for (int k = 0; k < s->set_count && !text[0]; k++) {
            char prefix[1024];
            int n = snprintf(prefix, sizeof prefix, "--set %s: ", s->sets[k]);
            if (strncmp(e, prefix, (size_t)n) != 0) continue;
            if (s->set_line[k] > 0)
                snprintf(text, sizeof text, "set: %s: %s", s->sets[k], e + n);
            else if (s->set_given[k]) /* --dt or --t-end, named as the user gave it */
                snprintf(text, sizeof text, "%s: %s", s->set_given[k], e + n);
            else
                snprintf(text, sizeof text, "%s", e);
            at_line = s->set_line[k], at_col = s->set_col[k];
        }
        if (!text[0]) snprintf(text, sizeof text, "%s", e);
        char full[1600];
        if (at_line > 0)
            snprintf(full, sizeof full, "%s:%d:%d: %s", s->file, at_line, at_col, text);
        else
            snprintf(full, sizeof full, "%s", text);
        int seen = 0;
        for (int k = 0; k < s->error_count && !seen; k++)
            seen = strcmp(s->errors[k], full) == 0;
        if (!seen) cs_sweep_error(s, 0, 0, "%s", full);
    }
}

static int check_one(cs_sweep_spec *s, const double *xrow, int var, double x_var, int line, int col) {
    cs_error err;
    cs_loader *l = cs_sweep_loader(s, &err);
    if (!l) {
        cs_sweep_error(s, 0, 0, "%s", err.message);
        return -1;
    }
    cs_model_input in = {.size = sizeof in};
    cs_model *m = NULL;
    int rc = load_run(l, s, xrow, var, x_var, &in) == 0 && (m = cs_loader_build(l, &in)) ? 0 : -1;
    if (rc != 0) map_errors(s, l, xrow, var, x_var, line, col);
    cs_model_free(m);
    cs_loader_free(l);
    return rc;
}

int cs_sweep_check(cs_sweep_spec *s, const double *x) {
    if (s->error_count) return -1;
    if (check_one(s, x, -1, 0, 0, 0) != 0) return -1;
    /* each grid level with the other values of run 0, at the level's place in the spec */
    for (int j = 0; j < s->var_count; j++) {
        const cs_sweep_var *v = &s->vars[j];
        for (int k = 1; s->method == CS_SWEEP_GRID && k < v->level_count && k < 1000; k++)
            check_one(s, x, j, v->numeric ? v->levels[k] : k, v->level_line[k], v->level_col[k]);
    }
    return s->error_count ? -1 : 0;
}

int cs_sweep_model_hash(const cs_sweep_spec *s, unsigned long long *hash) {
    cs_loader *l = cs_sweep_loader(s, NULL);
    if (!l) return -1;
    for (int k = 0; k < s->set_count; k++)
        cs_loader_set(l, s->sets[k]);
    cs_model_input in = {.size = sizeof in};
    int rc = cs_loader_load(l, s->model, &in);
    if (rc == 0) *hash = cs_model_input_hash(&in);
    cs_loader_free(l);
    return rc == 0 ? 0 : -1;
}

unsigned long long cs_sweep_inputs_hash(const cs_sweep_spec *s, const double *x, long n) {
    unsigned long long h = CS_IO_FNV_BASIS;
    h = cs_io_fnv(h, &n, sizeof n);
    h = cs_io_fnv(h, &s->var_count, sizeof s->var_count);
    for (int j = 0; j < s->var_count; j++)
        h = cs_io_fnv(h, s->vars[j].path, strlen(s->vars[j].path) + 1);
    h = cs_io_fnv(h, x, (size_t)n * (size_t)s->var_count * sizeof *x);
    for (int k = 0; k < s->set_count; k++)
        h = cs_io_fnv(h, s->sets[k], strlen(s->sets[k]) + 1);
    return cs_io_fnv(h, s->vehicle_class, strlen(s->vehicle_class) + 1);
}
