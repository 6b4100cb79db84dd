/* SPDX-License-Identifier: MIT */
/* A state's memory, allocated once per model with its workspace (the step never allocates), created for a
 * run and freed, and read through views. */
#include "core/vec3.h"
#include "run/run.h"
#include "run/sized.h"
#include "solver/work.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The state's memory: cables and posts; with_workspace, also events, the speed ring and the workspace
 * (whose step-start and trial copies need only cables and posts). Returns 0, or -1 out of memory. */
static int allocate(const cs_model *model, cs_state *s, int with_workspace) {
    int nc = model->cable_count, np = model->post_count, nn = model->max_nodes;
    s->cables = calloc((size_t)(nc ? nc : 1), sizeof *s->cables);
    s->posts = calloc((size_t)(np ? np : 1), sizeof *s->posts);
    if (!s->cables || !s->posts) return -1;
    s->cable_count_alloc = nc;
    s->rail_plastic = calloc((size_t)model->rail_count * (size_t)np + 1, sizeof *s->rail_plastic);
    if (!s->rail_plastic) return -1;
    for (int c = 0; c < nc; c++) {
        cs_cable_state *cs = &s->cables[c];
        cs->node = calloc((size_t)nn, sizeof *cs->node);
        cs->where = calloc((size_t)(np ? np : 1), sizeof *cs->where);
        cs->m = calloc((size_t)nn, sizeof *cs->m);
        cs->m_commit = calloc((size_t)nn, sizeof *cs->m_commit);
        cs->ep = calloc((size_t)nn, sizeof *cs->ep);
        cs->tension = calloc((size_t)nn, sizeof *cs->tension);
        cs->pos = calloc((size_t)nn * 3, sizeof *cs->pos);
        if (!cs->node || !cs->where || !cs->m || !cs->m_commit || !cs->ep || !cs->tension || !cs->pos)
            return -1;
    }
    if (!with_workspace) return 0;
    s->events = calloc((size_t)model->event_capacity, sizeof *s->events);
    s->speed_ring = calloc((size_t)model->window_steps + 1, sizeof *s->speed_ring);
    s->loss_ring = calloc(2 * (size_t)model->loss_steps, sizeof *s->loss_ring);
    s->work = calloc(1, sizeof *s->work);
    if (!s->events || !s->speed_ring || !s->loss_ring || !s->work) return -1;
    s->rail_pos = calloc((size_t)model->rail_count * (size_t)np * 3 + 1, sizeof *s->rail_pos);
    s->rail_tilt = calloc((size_t)np * 3 + 1, sizeof *s->rail_tilt);
    if (!s->rail_pos || !s->rail_tilt) return -1;
    cs_work *w = s->work;
    for (int k = 0; k < CS_PATH_LEVELS; k++) {
        w->step_start[k] = calloc(1, sizeof *w->step_start[k]);
        if (!w->step_start[k] || allocate(model, w->step_start[k], 0) != 0) return -1;
    }
    w->trial = calloc(1, sizeof *w->trial);
    if (!w->trial || allocate(model, w->trial, 0) != 0) return -1;
    return cs_system_init(model, &w->sys);
}

/* A state's memory and its workspace, not yet set for a run (cs_state_create resets it: cs_state_reset,
 * step.c). NULL with err set if out of memory. */
static cs_state *state_allocate(const cs_model *model, cs_error *err) {
    cs_state *s = calloc(1, sizeof *s);
    if (!s || allocate(model, s, 1) != 0) {
        cs_state_free(s);
        cs_error_set(err, CS_ERR_MEMORY, "out of memory allocating the state");
        return NULL;
    }
    return s;
}

cs_state *cs_state_create(const cs_model *model, cs_error *err) {
    cs_state *s = state_allocate(model, err);
    if (s) cs_state_reset(model, s);
    return s;
}

void cs_state_free(cs_state *s) {
    if (!s) return;
    if (s->cables) {
        for (int c = 0; c < s->cable_count_alloc; c++) {
            cs_cable_state *cs = &s->cables[c];
            free(cs->node), free(cs->where), free(cs->m), free(cs->m_commit), free(cs->ep), free(cs->tension);
            free(cs->pos);
        }
    }
    if (s->work) {
        cs_system_free(&s->work->sys);
        for (int k = 0; k < CS_PATH_LEVELS; k++)
            cs_state_free(s->work->step_start[k]);
        cs_state_free(s->work->trial);
        free(s->work);
    }
    free(s->cables), free(s->posts), free(s->events), free(s->speed_ring), free(s->loss_ring);
    free(s->rail_plastic), free(s->rail_pos), free(s->rail_tilt);
    free(s);
}

cs_status cs_state_summary(const cs_state *s, cs_summary *out, cs_error *err) {
    cs_summary full = s->summary;
    full.size = sizeof full;
    full.penetration_beyond_m = cs_penetration_is_final(full.outcome) ? NAN : full.max_dynamic_penetration_m;
    return cs_sized_put(out, &full, sizeof full, "cs_summary", err);
}

cs_status cs_state_energy(const cs_state *s, cs_energy *out, cs_error *err) {
    cs_energy full = s->energy;
    full.size = sizeof full;
    return cs_sized_put(out, &full, sizeof full, "cs_energy", err);
}

cs_status cs_state_event(const cs_state *s, int i, cs_event *out, cs_error *err) {
    if (i < 0 || i >= s->event_count) {
        char why[64];
        snprintf(why, sizeof why, "no event %d (the run has %d)", i, s->event_count);
        return cs_sized_refuse(err, "cs_event", why);
    }
    cs_event full = s->events[i];
    full.size = sizeof full;
    return cs_sized_put(out, &full, sizeof full, "cs_event", err);
}

/* Refuse element i of a model's n of a kind, naming the struct that was to hold it. */
static cs_status no_such(cs_error *err, const char *name, const char *kind, int i, int n) {
    char why[64];
    snprintf(why, sizeof why, "no %s %d (the model has %d)", kind, i, n);
    return cs_sized_refuse(err, name, why);
}

cs_status cs_state_vehicle(const cs_model *model, const cs_state *s, cs_vehicle_view *view, cs_error *err) {
    cs_vehicle_view full = {.size = sizeof full}, *out = &full;
    out->t = s->t;
    v3_copy(out->position, s->pos);
    v3_copy(out->velocity, s->vel);
    v3_copy(out->acceleration, s->acc);
    v3_copy(out->angular_velocity, s->omega);
    quat_to_euler(s->quat, &out->roll, &out->pitch, &out->yaw);
    out->forward_speed = v3_dot(s->vel, model->dir);
    out->decel_50ms_g = s->decel_50ms_g;
    out->crush = s->crush;
    out->face_force = s->face_force;
    out->penetration = s->summary.max_dynamic_penetration_m;
    v3_copy(out->barrier_force, s->force);
    for (int k = 0; k < CS_OUTLINE_CORNERS; k++) {
        double lo, hi;
        cs_vehicle_corner_band(model, k, &lo, &hi);
        cs_vehicle_corner_point(model, s, s->crush, k, 0.5 * (lo + hi),
                                cs_corner_front(k) ? out->front_corners[k] : out->rear_corners[k - 2]);
    }
    return cs_sized_put(view, &full, sizeof full, "cs_vehicle_view", err);
}

cs_status cs_state_cable(const cs_model *model, const cs_state *s, int c, cs_cable_view *view,
                         cs_error *err) {
    if (c < 0 || c >= model->cable_count)
        return no_such(err, "cs_cable_view", "cable", c, model->cable_count);
    const cs_cable_state *cs = &s->cables[c];
    cs_cable_view full = {.size = sizeof full}, *out = &full;
    out->status = cs->status == CS_CABLE_INTACT && cs->passed ? CS_CABLE_SLIPPED : cs->status;
    out->engaged = cs->engaged;
    out->node_count = cs->node_count;
    for (int i = 0; cs->status == CS_CABLE_INTACT && i + 1 < cs->node_count; i++) {
        if (cs->tension[i] > out->max_tension) out->max_tension = cs->tension[i];
        double sm = cs->m[i + 1] - cs->m[i];
        double e = sm > 0.0 ? cs_span_length(cs, i) / sm - 1.0 : 0.0;
        if (e > out->max_strain) out->max_strain = e;
    }
    return cs_sized_put(view, &full, sizeof full, "cs_cable_view", err);
}

int cs_state_cable_path(const cs_model *model, const cs_state *s, int c, double *xyz, double *tension,
                        int capacity) {
    (void)model;
    const cs_cable_state *cs = &s->cables[c];
    int n = cs->node_count < capacity ? cs->node_count : capacity;
    for (int i = 0; i < n; i++) {
        if (xyz) v3_copy(xyz + 3 * i, cs->pos + 3 * i);
        if (tension && i + 1 < n) tension[i] = cs->status == CS_CABLE_INTACT ? cs->tension[i] : 0.0;
    }
    return n;
}

cs_status cs_state_anchor(const cs_model *model, const cs_state *s, int a, cs_anchor_view *view,
                          cs_error *err) {
    if (a < 0 || a > 1) return no_such(err, "cs_anchor_view", "anchor", a, 2);
    const cs_anchor_model *am = &model->anchors[a];
    const cs_anchor_state *as = &s->anchors[a];
    cs_anchor_view full = {.size = sizeof full}, *out = &full;
    out->rigid = am->rigid, out->yielded = as->yielded, out->failed = as->failed;
    for (int k = 0; k < 2; k++)
        out->displacement[k] = as->u[k], out->force[k] = as->force[k];
    out->capacity = am->capacity, out->residual = am->residual, out->slide = as->slide;
    out->uplift = as->uplift, out->uplift_capacity = am->uplift_capacity, out->peak_pull = as->peak_pull;
    out->lift = as->lift;
    return cs_sized_put(view, &full, sizeof full, "cs_anchor_view", err);
}

const char *cs_anchor_status_name(const cs_anchor_view *a) {
    return a->rigid        ? "rigid"
           : a->failed     ? "pulled_out"
           : a->lift > 0.0 ? "rising"
           : a->yielded    ? "sliding"
                           : "holding";
}

cs_status cs_state_post(const cs_model *model, const cs_state *s, int p, cs_post_view *view, cs_error *err) {
    if (p < 0 || p >= model->post_count) return no_such(err, "cs_post_view", "post", p, model->post_count);
    const cs_post_state *ps = &s->posts[p];
    const cs_post_model *pm = &model->posts[p];
    cs_post_view full = {.size = sizeof full}, *out = &full;
    out->status = ps->status;
    out->tilt = hypot(ps->tilt[0], ps->tilt[1]);
    if (out->tilt > 0.0)
        out->tilt_dir[0] = ps->tilt[0] / out->tilt, out->tilt_dir[1] = ps->tilt[1] / out->tilt;
    out->base_moment = hypot(ps->moment[0], ps->moment[1]);
    out->base_shear = ps->shear;
    out->axial_pull = ps->axial;
    out->withdrawal = ps->withdrawing ? ps->pull : 0.0;
    out->moment_capacity = cs_post_moment_cap(pm, ps);
    out->rotation_limit = pm->rot_limit;
    cs_post_attachment(model, p, ps->tilt, ps->pull, cs_post_upright(&model->posts[p]), pm->height, out->top);
    return cs_sized_put(view, &full, sizeof full, "cs_post_view", err);
}
