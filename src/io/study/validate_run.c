/* SPDX-License-Identifier: MIT */
/* The validation suite and its jobs (validate.h): the values compared with and the output folder, read
 * and checked before anything runs; each job run on a state of its own and its result kept; the report
 * written from the results and its two files committed together. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "study/validate.h"

const char *cs_validate_unknown_part(const char *only, size_t *len) {
    static const char *const parts[] = {"crash",        "readings",    "roadside",   "bogie",
                                        "verification", "convergence", "sensitivity"};
    for (const char *p = only; p && *p;) {
        size_t n = strcspn(p, ","), k = 0;
        while (k < sizeof parts / sizeof parts[0] && !(strlen(parts[k]) == n && strncmp(p, parts[k], n) == 0))
            k++;
        if (k == sizeof parts / sizeof parts[0]) {
            *len = n;
            return p;
        }
        p += n + (p[n] == ',');
    }
    return NULL;
}

/* A post's failure: at its rotation limit, pulled out or sheared. */
static int post_failure(cs_event_type type) {
    return type == CS_EVENT_POST_ROTATION_LIMIT || type == CS_EVENT_POST_PULLOUT ||
           type == CS_EVENT_POST_SHEAR;
}

static void collect(const cs_model *m, const cs_state *s, cs_validate_result *r) {
    r->sm.size = sizeof r->sm;
    cs_state_summary(s, &r->sm, NULL);
    r->dt = cs_model_scenario(m)->dt;
    for (int a = 0; a < 2; a++) {
        cs_anchor_view v = {.size = sizeof v};
        cs_state_anchor(m, s, a, &v, NULL);
        r->slide[a] = v.rigid ? -1.0 : v.slide;
    }
    for (int c = 0; c < 2; c++)
        snprintf(r->how[c], sizeof r->how[c], c < r->sm.cable_count ? "held (peak %.0f kN)" : "-",
                 c < r->sm.cable_count ? r->sm.cables[c].peak_tension_n / 1e3 : 0.0);
    r->cable_break[0] = r->cable_break[1] = -1.0;
    r->post_failure = -1;
    r->post_slide = 0.0;
    r->released = 0;
    for (int i = 0; i < cs_state_event_count(s); i++) {
        cs_event e_held = {.size = sizeof e_held};
        cs_state_event(s, i, &e_held, NULL);
        const cs_event *e = &e_held;
        r->released += e->type == CS_EVENT_CABLE_RELEASE || e->type == CS_EVENT_CABLE_PULLED_OFF ||
                       e->type == CS_EVENT_CABLE_STRUCK_OFF;
        if (r->post_failure < 0 && post_failure(e->type)) {
            r->post_failure = (int)e->type, r->post_failure_t = e->t;
            cs_post_view pv = {.size = sizeof pv};
            r->post_slide = cs_state_post(m, s, e->element, &pv, NULL) == CS_OK ? pv.withdrawal : 0.0;
        }
        if ((e->type == CS_EVENT_CABLE_BREAK || e->type == CS_EVENT_TERMINATION_BREAK) && e->element < 2 &&
            r->cable_break[e->element] < 0.0) {
            r->cable_break[e->element] = e->t;
            char where[32];
            if (e->post >= 0)
                snprintf(where, sizeof where, "at post %d's hole", e->post);
            else
                snprintf(where, sizeof where, "%s",
                         e->type == CS_EVENT_CABLE_BREAK ? "along the rope"
                         : e->cable_end == 0             ? "at its start fitting"
                                                         : "at its end fitting");
            snprintf(r->how[e->element], sizeof r->how[e->element], "%.4g s %s", e->t, where);
        }
    }
    cs_energy en = {.size = sizeof en};
    cs_state_energy(s, &en, NULL);
    r->absorbed = en.initial_kinetic - en.vehicle_kinetic;
}

int cs_validate_job_count(const cs_validate_suite *s) {
    return s->count;
}

/* At each output: the face's penetration where it first bears on something and where the first post
 * failure has just happened (the travel between, to an output interval, is a bogie test's deflection);
 * the two first ropes' tensions where the penetration is largest. */
static void watch_run(const cs_model *m, const cs_state *s, void *user) {
    cs_validate_result *r = user;
    cs_vehicle_view v = {.size = sizeof v};
    cs_state_vehicle(m, s, &v, NULL);
    if (v.penetration > r->peak_pen) {
        r->peak_pen = v.penetration, r->peak_t = v.t;
        for (int c = 0; c < 2; c++) {
            cs_cable_view cv = {.size = sizeof cv};
            r->peak_tension[c] = cs_state_cable(m, s, c, &cv, NULL) == CS_OK ? cv.max_tension : NAN;
        }
    }
    if (isnan(r->contact_pen) && v.face_force > 0.0) r->contact_pen = v.penetration;
    int n = cs_state_event_count(s);
    for (; r->events_seen < n && isnan(r->failure_pen); r->events_seen++) {
        cs_event e = {.size = sizeof e};
        cs_state_event(s, r->events_seen, &e, NULL);
        if (post_failure(e.type)) r->failure_pen = v.penetration;
    }
}

/* Run a job on its own state, then free its model. */
void cs_validate_run(cs_validate_suite *s, int i) {
    cs_validate_job *j = &s->jobs[s->order[i]];
    cs_error err = {0};
    cs_state *st = j->model ? cs_state_create(j->model, &err) : NULL;
    j->r.contact_pen = j->r.failure_pen = NAN, j->r.events_seen = 0;
    j->r.peak_pen = -HUGE_VAL, j->r.peak_tension[0] = j->r.peak_tension[1] = NAN;
    j->r.ok = st && cs_run(j->model, st, watch_run, &j->r, &err) == CS_OK;
    if (j->r.ok)
        collect(j->model, st, &j->r);
    else if (j->model)
        fprintf(s->opts.err, "cablesim validate: a run failed: %s\n", err.message);
    cs_state_free(st);
    cs_model_free(j->model);
    j->model = NULL;
}

/* The jobs, the costliest first: insertion sort, stable, so that ties stay in queue order. */
static void order_jobs(cs_validate_suite *s) {
    for (int i = 0; i < s->count; i++) {
        int j = i;
        for (; j > 0 && s->jobs[s->order[j - 1]].cost < s->jobs[i].cost; j--)
            s->order[j] = s->order[j - 1];
        s->order[j] = i;
    }
}

/* Free the suite and the models of the jobs not run. */
static void suite_free(cs_validate_suite *s) {
    for (int i = 0; i < s->count; i++)
        cs_model_free(s->jobs[i].model);
    cs_loader_free(s->loader);
    free(s);
}

/* A suite with its loader and the values it compares with (data/validation/, beside the loader's parts
 * library). NULL, the reason printed, if either cannot be had. */
static cs_validate_suite *suite_create(const cs_validate_opts *o) {
    char data_dir[1100];
    cs_error err;
    cs_validate_suite *s = calloc(1, sizeof *s);
    if (!s || !(s->loader = cs_loader_create(NULL, &err))) {
        fprintf(o->err, "cablesim validate: %s\n", s ? err.message : "out of memory");
        free(s);
        return NULL;
    }
    s->opts = *o;
    if (!cs_loader_data_dir(s->loader)[0]) {
        fprintf(o->err, "cablesim validate: cannot find the parts library and its validation/ (set "
                        "CABLESIM_DATA to its folder)\n");
        suite_free(s);
        return NULL;
    }
    snprintf(data_dir, sizeof data_dir, "%s/validation", cs_loader_data_dir(s->loader));
    if (cs_validation_read(data_dir, &s->data, &err) == CS_OK) return s;
    fprintf(o->err, "cablesim validate: %s\n", err.message);
    suite_free(s);
    return NULL;
}

cs_validate_suite *cs_validate_begin(const cs_validate_opts *o, int *status) {
    *status = 1;
    cs_validate_suite *s = suite_create(o);
    if (!s) return NULL;
    cs_error err;
    if (cs_out_open(&s->out, o->dir, "validate", o->force ? CS_OUT_FORCE : 0, "--force", &err) != CS_OK) {
        fprintf(o->err, "cablesim validate: nothing run: %s\n", err.message);
        suite_free(s);
        return NULL;
    }
    s->md = cs_out_begin(&s->out, "validation.md", &err);
    s->csv = s->md ? cs_out_begin(&s->out, "validation.csv", &err) : NULL;
    if (!s->md || !s->csv) {
        fprintf(o->err, "cablesim validate: nothing run: %s\n", err.message);
        if (s->md) fclose(s->md);
        cs_out_abort(&s->out);
        suite_free(s);
        return NULL;
    }
    /* The examples: --examples, else those installed with the parts library, else ./examples (a source
     * checkout). */
    struct stat st;
    snprintf(s->installed, sizeof s->installed, "%s/examples", cs_loader_data_dir(s->loader));
    s->examples = o->examples                                           ? o->examples
                  : stat(s->installed, &st) == 0 && S_ISDIR(st.st_mode) ? s->installed
                                                                        : "examples";
    s->t0 = time(NULL);
    cs_validate_plan(s);
    order_jobs(s);
    return s;
}

int cs_validate_finish(cs_validate_suite *s) {
    const cs_validate_opts *o = &s->opts;
    FILE *md = s->md, *csv = s->csv;
    fprintf(md, "# cablesim validation\n\nOne parameter set for every case (docs/assumptions.md); nothing is "
                "tuned to "
                "a test. Written by `cablesim validate`.\n\n");
    fprintf(csv,
            "suite,case,variant,ok,outcome,max_50ms_decel [g],max_dynamic_penetration [m],exit_speed [m/s],"
            "stop_time [s],cable0_break [s],cable1_break [s],posts_failed_left,posts_failed_right,"
            "posts_rotation_left,posts_rotation_right,posts_shear_left,posts_shear_right,posts_pullout_left,"
            "posts_pullout_right,energy_balance_error [1],energy_absorbed [J],max_deflection "
            "[m],working_width [m],"
            "exit_angle [deg],penetration_beyond [m]\n");
    if (cs_validate_wanted(o->only, "crash")) cs_validate_write_crash(md, csv, s);
    if (cs_validate_wanted(o->only, "readings")) cs_validate_write_readings(md, csv, s);
    if (cs_validate_wanted(o->only, "roadside")) cs_validate_write_roadside(md, csv, s);
    if (cs_validate_wanted(o->only, "bogie")) cs_validate_write_bogie(md, csv, s);
    if (cs_validate_wanted(o->only, "verification")) cs_validate_write_verification(md, s->loader, &s->data);
    if (cs_validate_wanted(o->only, "convergence")) cs_validate_write_convergence(md, csv, s);
    if (cs_validate_wanted(o->only, "sensitivity")) cs_validate_write_sensitivity(md, csv, s);
    fprintf(md, "Run time: %.0f s.\n", difftime(time(NULL), s->t0));
    cs_error err;
    int bad = cs_out_end_at(&s->out, 0, md, &err) != CS_OK;
    if (cs_out_end_at(&s->out, 1, csv, &err) != CS_OK) bad = 1;
    if (bad || cs_out_commit(&s->out, &err) != CS_OK) {
        cs_out_fail(&s->out, CS_ERR_IO, &err);
        fprintf(o->err, "cablesim validate: %s\n", err.message);
        suite_free(s);
        return 1;
    }
    fprintf(o->out, "validation written to %s/validation.md and %s/validation.csv (%.0f s)\n", o->dir, o->dir,
            difftime(time(NULL), s->t0));
    if (s->missed)
        fprintf(o->out,
                "cablesim validate: %s: targets missed (APS1's or the bogie tests'; see the report)\n",
                o->report_only ? "reported only" : "exit status 3");
    int status = s->missed && !o->report_only ? 3 : 0;
    suite_free(s);
    return status;
}
