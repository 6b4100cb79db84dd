/* SPDX-License-Identifier: MIT */
/* report.html (report_html.h): the run's data as one JSON object inside the page built from report/. */
#include "report_html.h"

#include "out/htmltext.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/cablesim.h"
#include "jsondoc.h"
#include "load/schema.h"
#include "status.h"
#include "writers.h"

typedef struct jw {
    cs_wout w;
    char what[96]; /* names the value being written, for the message of a non-finite one */
    int digits;    /* of a named value (knum, kopt): 6, or every digit of the double in "summary" */
} jw;

/* The response parameters ("summary") have every digit of the double, so that the page, rounding them
 * for display, shows what the terminal shows (0.41650000000000004 s is 0.417 s on both; written as 0.4165
 * it would read 0.416). */
enum { SUMMARY_DIGITS = 17, PAGE_DIGITS = 6 };

/* A number to `digits` significant digits, its text kept with it (no "-0"); NaN is null where nullable
 * (absent on purpose). A non-finite one that may not be marks j bad, naming j->what, and is null. */
static json_object *num_digits(jw *j, double v, int digits, int nullable) {
    if (nullable && isnan(v)) return NULL;
    if (!cs_w_finite(&j->w, v, j->what)) return NULL;
    char text[32];
    snprintf(text, sizeof text, "%.*g", digits, v == 0 ? 0.0 : v);
    return json_object_new_double_s(v, text);
}

/* A point of a time history, with 6 significant digits (the data of a page's plots and replay, not of an
 * analysis: the CSV has 10). */
static json_object *num(jw *j, double v) {
    return num_digits(j, v, PAGE_DIGITS, 0);
}

/* A point of a time history that may be absent on purpose (NaN: null). */
static json_object *opt(jw *j, double v) {
    return num_digits(j, v, PAGE_DIGITS, 1);
}

static void knum(jw *j, json_object *o, const char *k, double v) {
    snprintf(j->what, sizeof j->what, "%s", k);
    json_object_object_add(o, k, num_digits(j, v, j->digits, 0));
}

static void kopt(jw *j, json_object *o, const char *k, double v) {
    snprintf(j->what, sizeof j->what, "%s", k);
    json_object_object_add(o, k, num_digits(j, v, j->digits, 1));
}

static void kint(json_object *o, const char *k, int v) {
    json_object_object_add(o, k, json_object_new_int(v));
}

/* A string of the page (NULL: ""). */
static void kstr(json_object *o, const char *k, const char *v) {
    json_object_object_add(o, k, cs_jstr(v ? v : ""));
}

/* n ints as a JSON array. */
static json_object *ints(const int *v, int n) {
    json_object *a = json_object_new_array();
    for (int i = 0; i < n; i++)
        json_object_array_add(a, json_object_new_int(v[i]));
    return a;
}

/* Frames kept: 0, stride, 2 stride, ... and always the last. */
static int kept_count(int n, int stride) {
    return n <= 0 ? 0 : (n - 1) / stride + 1 + ((n - 1) % stride != 0);
}
static int kept_frame(int n, int stride, int k) {
    int f = k * stride;
    return f < n ? f : n - 1;
}

/* A series over the kept frames: value(rec, frame, arg). */
typedef double (*series_fn)(const cs_record *r, const cs_model_input *in, int f, int arg);

/* n numbers of the page as one list (cs_jnums), 6 significant digits, a NaN null where nullable; any
 * other non-finite one marks j bad, naming j->what. */
static json_object *page_nums(jw *j, const double *v, int n, int nullable) {
    for (int i = 0; i < n; i++)
        if (!(nullable && isnan(v[i])) && !cs_w_finite(&j->w, v[i], j->what)) return NULL;
    json_object *a = j->w.bad ? NULL : cs_jnums(v, n, PAGE_DIGITS, nullable);
    if (!a) cs_w_oom(&j->w, j->what);
    return a;
}

static json_object *series(jw *j, const cs_record *r, const cs_model_input *in, int stride, series_fn fn,
                           int arg, int nullable, const char *what) {
    int n = r->frame_count, count = kept_count(n, stride);
    double *v = malloc((size_t)(count > 0 ? count : 1) * sizeof *v);
    snprintf(j->what, sizeof j->what, "%s", what);
    if (!v) {
        cs_w_oom(&j->w, what);
        return NULL;
    }
    for (int k = 0; k < count; k++) {
        int f = kept_frame(n, stride, k);
        v[k] = fn(r, in, f, arg);
        if (!isfinite(v[k]) && !(nullable && isnan(v[k])) && !j->w.bad) /* the message names its time */
            snprintf(j->what, sizeof j->what, "%s at t = %g s", what, r->vehicle[f].t);
    }
    json_object *a = page_nums(j, v, count, nullable);
    free(v);
    return a;
}

static double s_time(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)in, (void)arg;
    return r->vehicle[f].t;
}
static double s_decel(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)arg;
    const double *a = r->vehicle[f].acceleration;
    return -(a[0] * cos(in->scenario.angle) + a[1] * sin(in->scenario.angle)) / CS_G0;
}
/* the 50-ms average exists once a whole window has passed */
static double s_decel50(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)arg;
    return r->vehicle[f].t > 0.05 + 0.5 * in->scenario.dt ? r->vehicle[f].decel_50ms_g : NAN;
}
static double s_speed(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)in, (void)arg;
    return r->vehicle[f].forward_speed;
}
static double s_penetration(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)in, (void)arg;
    return r->vehicle[f].penetration;
}
static double s_face(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)in, (void)arg;
    return fmax(r->vehicle[f].front_corners[0][1], r->vehicle[f].front_corners[1][1]);
}
/* the furthest point of a cable that holds (NaN: none does) */
static double s_deflection(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)in, (void)arg;
    double y = NAN;
    for (int c = 0; c < r->cable_count; c++) {
        size_t k = (size_t)f * (size_t)r->cable_count + (size_t)c;
        if (!cs_cable_status_holds(r->cables[k].status)) continue;
        for (int i = 0; i < r->path_count[k]; i++) {
            double yi = r->path_xyz[(k * (size_t)r->max_nodes + (size_t)i) * 3 + 1];
            if (!(yi <= y)) y = yi;
        }
    }
    return y;
}
/* the vehicle's roll (arg 0), pitch (1) or yaw (2) */
static double s_attitude(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)in;
    const cs_vehicle_view *v = &r->vehicle[f];
    return arg == 0 ? v->roll : arg == 1 ? v->pitch : v->yaw;
}
/* the CG's place in plan: x (arg 0) or y (arg 1) */
static double s_cg(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)in;
    return r->vehicle[f].position[arg];
}
static double s_tension(const cs_record *r, const cs_model_input *in, int f, int c) {
    (void)in;
    return r->cables[(size_t)f * (size_t)r->cable_count + (size_t)c].max_tension;
}
static double s_tilt(const cs_record *r, const cs_model_input *in, int f, int p) {
    (void)in;
    return r->posts[(size_t)f * (size_t)r->post_count + (size_t)p].tilt;
}
static double s_moment(const cs_record *r, const cs_model_input *in, int f, int p) {
    (void)in;
    return r->posts[(size_t)f * (size_t)r->post_count + (size_t)p].base_moment;
}

/* the energy ledger's terms in J, and its balance error, a fraction of the initial kinetic energy */
static const struct {
    const char *key;
    size_t offset;
    const char *unit;
} ledger[] = {
    {"crush", offsetof(cs_energy, crush), "J"},
    {"post_plastic", offsetof(cs_energy, post_plastic), "J"},
    {"post_damping", offsetof(cs_energy, post_damping), "J"},
    {"soil", offsetof(cs_energy, soil), "J"},
    {"cable_plastic", offsetof(cs_energy, cable_plastic), "J"},
    {"friction", offsetof(cs_energy, friction), "J"},
    {"released", offsetof(cs_energy, released), "J"},
    {"post_elastic", offsetof(cs_energy, post_elastic), "J"},
    {"post_kinetic", offsetof(cs_energy, post_kinetic), "J"},
    {"anchor_elastic", offsetof(cs_energy, anchor_elastic), "J"},
    {"anchor_kinetic", offsetof(cs_energy, anchor_kinetic), "J"},
    {"rail_elastic", offsetof(cs_energy, rail_elastic), "J"},
    {"rail_plastic", offsetof(cs_energy, rail_plastic), "J"},
    {"cable_elastic", offsetof(cs_energy, cable_elastic), "J"},
    {"vehicle_potential", offsetof(cs_energy, vehicle_potential), "J"},
    {"vehicle_kinetic", offsetof(cs_energy, vehicle_kinetic), "J"},
    {"balance_error", offsetof(cs_energy, balance_error), "1"},
};
enum { LEDGER_TERMS = sizeof ledger / sizeof ledger[0] };

static double s_energy(const cs_record *r, const cs_model_input *in, int f, int k) {
    (void)in;
    double v;
    memcpy(&v, (const char *)&r->energy[f] + ledger[k].offset, sizeof v);
    return v;
}

enum { NEAR_POSTS = 4 };

/* k's unit into units (a list's: the unit of every number in it). */
static void kunit(json_object *units, const char *k, const char *unit) {
    json_object_object_add(units, k, cs_jstr(unit));
}

/* "series", and its units into units. */
static json_object *write_series(jw *j, const cs_model_input *in, const cs_record *r, int stride,
                                 json_object *units) {
    int idx[NEAR_POSTS];
    int near = cs_nearest_posts(in, idx, r->post_count < NEAR_POSTS ? r->post_count : NEAR_POSTS);
    json_object *o = json_object_new_object();
    kint(o, "stride", stride);
    kunit(units, "stride", "");
    static const struct {
        const char *key, *what;
        series_fn fn;
        int arg, nullable;
        const char *unit;
    } plain[] = {
        {"t", "time", s_time, 0, 0, "s"},
        {"decel", "the deceleration", s_decel, 0, 0, "g"},
        {"decel50", "the 50-ms deceleration", s_decel50, 0, 1, "g"},
        {"speed", "the forward speed", s_speed, 0, 0, "m/s"},
        {"penetration", "the penetration", s_penetration, 0, 0, "m"},
        {"face", "the front face", s_face, 0, 0, "m"},
        {"deflection", "the barrier deflection", s_deflection, 0, 1, "m"},
        {"roll", "the roll", s_attitude, 0, 0, "rad"},
        {"pitch", "the pitch", s_attitude, 1, 0, "rad"},
        {"yaw", "the yaw", s_attitude, 2, 0, "rad"},
        {"cg_x", "the CG's x", s_cg, 0, 0, "m"},
        {"cg_y", "the CG's y", s_cg, 1, 0, "m"},
    };
    for (size_t k = 0; k < sizeof plain / sizeof plain[0]; k++) {
        json_object_object_add(
            o, plain[k].key,
            series(j, r, in, stride, plain[k].fn, plain[k].arg, plain[k].nullable, plain[k].what));
        kunit(units, plain[k].key, plain[k].unit);
    }
    json_object *tension = json_object_new_array();
    for (int c = 0; c < r->cable_count; c++)
        json_object_array_add(tension, series(j, r, in, stride, s_tension, c, 0, "a cable's tension"));
    json_object_object_add(o, "tension", tension);
    kunit(units, "tension", "N");
    json_object_object_add(o, "near_posts", ints(idx, near));
    kunit(units, "near_posts", "");
    static const struct {
        const char *key, *what;
        series_fn fn;
        const char *unit;
    } per_post[] = {{"post_tilt", "a post's tilt", s_tilt, "rad"},
                    {"post_moment", "a post's base moment", s_moment, "N m"}};
    for (int m = 0; m < 2; m++) {
        json_object *a = json_object_new_array();
        for (int k = 0; k < near; k++)
            json_object_array_add(a, series(j, r, in, stride, per_post[m].fn, idx[k], 0, per_post[m].what));
        json_object_object_add(o, per_post[m].key, a);
        kunit(units, per_post[m].key, per_post[m].unit);
    }
    json_object *capacity = json_object_new_array();
    for (int k = 0; k < near && r->frame_count > 0; k++) {
        snprintf(j->what, sizeof j->what, "post %d's moment capacity", idx[k]);
        json_object_array_add(capacity, num(j, r->posts[idx[k]].moment_capacity));
    }
    json_object_object_add(o, "post_capacity", capacity);
    kunit(units, "post_capacity", "N m");
    json_object *limit = json_object_new_array(); /* null: none (a post hinged at grade) */
    for (int k = 0; k < near && r->frame_count > 0; k++) {
        double lim = r->posts[idx[k]].rotation_limit;
        snprintf(j->what, sizeof j->what, "post %d's rotation limit", idx[k]);
        json_object_array_add(limit, opt(j, lim < 0.5 * CS_PI - 1e-9 ? lim : NAN));
    }
    json_object_object_add(o, "post_rotation_limit", limit);
    kunit(units, "post_rotation_limit", "rad");
    json_object *energy = json_object_new_object(), *energy_units = json_object_new_object();
    for (int k = 0; k < LEDGER_TERMS; k++) {
        json_object_object_add(energy, ledger[k].key,
                               series(j, r, in, stride, s_energy, k, 0, "the energy ledger"));
        kunit(energy_units, ledger[k].key, ledger[k].unit);
    }
    json_object_object_add(o, "energy", energy);
    json_object_object_add(units, "energy", energy_units);
    if (r->frame_count > 0) {
        knum(j, o, "initial_kinetic", r->energy[0].initial_kinetic);
        knum(j, o, "initial_total", r->energy[0].initial_total);
        kunit(units, "initial_kinetic", "J");
        kunit(units, "initial_total", "J");
    }
    return o;
}

/* Bytes of one replay frame, roughly (a number ~ 8 characters). */
static double replay_frame_bytes(const cs_record *r) {
    int nodes = 0;
    for (size_t k = 0; k < (size_t)r->frame_count * (size_t)r->cable_count; k++)
        if (r->path_count[k] > nodes) nodes = r->path_count[k];
    return 8.0 * (10 + 4 * r->post_count + r->cable_count * (4 + 4 * nodes));
}

/* n numbers of the page as a JSON array. */
static json_object *nums(jw *j, const double *v, int n) {
    return page_nums(j, v, n, 0);
}

/* frames: [[t, [x, y, z, roll, pitch, yaw, crush, face_force], [top x, y, z, status]*posts,
 * [[status, engaged, [x, y, z]*nodes, [span tension]*(nodes-1)]]*cables], ...], each frame on a line of
 * its own; their units frame_units (a list's units repeated along it: report_html.h) */
static const char frame_units[] = "[[\"s\",[\"m\",\"m\",\"m\",\"rad\",\"rad\",\"rad\",\"m\",\"N\"],"
                                  "[\"m\",\"m\",\"m\",\"\"],[[\"\",\"\",\"m\",\"N\"]]]]";

static json_object *write_frames(jw *j, const cs_record *r, int stride) {
    int n = r->frame_count, count = kept_count(n, stride);
    json_object *frames = json_object_new_array_ext(count > 0 ? count : 1);
    double *tops = malloc((size_t)(4 * r->post_count + 1) * sizeof *tops); /* a frame's posts */
    if (!tops) cs_w_oom(&j->w, "the replay");
    for (int k = 0; k < count && !j->w.bad; k++) {
        int fr = kept_frame(n, stride, k);
        const cs_vehicle_view *v = &r->vehicle[fr];
        snprintf(j->what, sizeof j->what, "the replay frame at t = %g s", v->t);
        const double pose[] = {v->position[0], v->position[1], v->position[2], v->roll,
                               v->pitch,       v->yaw,         v->crush,       v->face_force};
        json_object *frame = json_object_new_array_ext(4),
                    *cables = json_object_new_array_ext(r->cable_count + 1);
        json_object_array_add(frame, num(j, v->t));
        json_object_array_add(frame, nums(j, pose, (int)(sizeof pose / sizeof pose[0])));
        for (int p = 0; p < r->post_count; p++) {
            const cs_post_view *pv = &r->posts[(size_t)fr * (size_t)r->post_count + (size_t)p];
            for (int i = 0; i < 3; i++)
                tops[4 * p + i] = pv->top[i];
            tops[4 * p + 3] = (double)pv->status; /* a small integer: "%.6g" writes it as "%d" would */
        }
        json_object_array_add(frame, page_nums(j, tops, 4 * r->post_count, 0));
        for (int c = 0; c < r->cable_count; c++) {
            size_t ck = (size_t)fr * (size_t)r->cable_count + (size_t)c;
            const cs_cable_view *cv = &r->cables[ck];
            int nodes = r->path_count[ck];
            json_object *cable = json_object_new_array_ext(4);
            json_object_array_add(cable, json_object_new_int((int)cv->status));
            json_object_array_add(cable, json_object_new_int(cv->engaged));
            json_object_array_add(cable, nums(j, r->path_xyz + ck * (size_t)r->max_nodes * 3, 3 * nodes));
            json_object_array_add(
                cable, nums(j, r->path_tension + ck * (size_t)r->max_nodes, nodes > 1 ? nodes - 1 : 0));
            json_object_array_add(cables, cable);
        }
        json_object_array_add(frame, cables);
        json_object_array_add(frames, cs_jline_before(frame));
    }
    free(tops);
    return frames;
}

/* ---- the design as loaded ---- */

/* A capacity that may be a rule instead of a number: key as a number where one is given, else null and
 * key_rule what stands for it. */
static void kcapacity(jw *j, json_object *o, const char *k, double v, const char *rule) {
    char rk[64];
    kopt(j, o, k, isfinite(v) && v > 0 ? v : NAN);
    snprintf(rk, sizeof rk, "%s_rule", k);
    kstr(o, rk, isinf(v) ? "never" : v > 0 ? "" : rule);
}

static void write_footing(jw *j, json_object *o, const cs_footing_def *f, const char *pullout_rule) {
    knum(j, o, "diameter_m", f->diameter);
    knum(j, o, "depth_m", f->depth);
    knum(j, o, "rotation_limit_rad", f->rotation_limit);
    kcapacity(j, o, "pullout_capacity_n", f->pullout_capacity, pullout_rule);
}

/* A struct's doubles by name and place. */
typedef struct field {
    const char *key;
    size_t offset;
} field;

static const field rope_fields[] = {{"diameter_m", offsetof(cs_rope_def, diameter)},
                                    {"area_m2", offsetof(cs_rope_def, area)},
                                    {"strength_n", offsetof(cs_rope_def, nominal_strength)},
                                    {"modulus_pa", offsetof(cs_rope_def, modulus)}};
static const field section_fields[] = {{"plastic_modulus_m3", offsetof(cs_section_def, plastic_modulus)},
                                       {"inertia_m4", offsetof(cs_section_def, inertia)},
                                       {"yield_stress_pa", offsetof(cs_section_def, yield_stress)},
                                       {"modulus_pa", offsetof(cs_section_def, modulus)},
                                       {"mass_per_length_kg_m", offsetof(cs_section_def, mass_per_length)}};
static const field soil_fields[] = {
    {"soil_pressure_pa", offsetof(cs_footing_def, soil_pressure)},
    {"soil_pressure_cap_pa", offsetof(cs_footing_def, soil_pressure_cap)},
    {"coeff_depth", offsetof(cs_footing_def, coeff_depth)},
    {"coeff_height", offsetof(cs_footing_def, coeff_height)},
    {"dynamic_factor", offsetof(cs_footing_def, dynamic_factor)},
    {"friction_angle_rad", offsetof(cs_footing_def, friction_angle)},
    {"residual_friction_angle_rad", offsetof(cs_footing_def, residual_friction_angle)},
    {"unit_weight_n_m3", offsetof(cs_footing_def, unit_weight)}};
/* the scenario's before and after its impact_at_corner, and the vehicle's */
static const field scenario_fields[] = {{"speed", offsetof(cs_scenario_def, speed)},
                                        {"angle", offsetof(cs_scenario_def, angle)},
                                        {"impact_x", offsetof(cs_scenario_def, impact_x)},
                                        {"dt", offsetof(cs_scenario_def, dt)},
                                        {"t_end", offsetof(cs_scenario_def, t_end)},
                                        {"output_interval", offsetof(cs_scenario_def, output_interval)}};
static const field vehicle_fields[] = {
    {"mass", offsetof(cs_vehicle_def, mass)},
    {"cg_height", offsetof(cs_vehicle_def, cg_height)},
    {"cg_to_front", offsetof(cs_vehicle_def, cg_to_front)},
    {"front_width", offsetof(cs_vehicle_def, front_width)},
    {"cg_to_rear", offsetof(cs_vehicle_def, cg_to_rear)},
    {"face_bottom", offsetof(cs_vehicle_def, face_bottom)},
    {"face_top", offsetof(cs_vehicle_def, face_top)},
    {"wheelbase", offsetof(cs_vehicle_def, wheelbase)},
    {"cg_to_front_axle", offsetof(cs_vehicle_def, cg_to_front_axle)},
    {"track", offsetof(cs_vehicle_def, track)},
    {"wheel_radius", offsetof(cs_vehicle_def, wheel_radius)},
    {"tyre_static_deflection", offsetof(cs_vehicle_def, tyre_static_deflection)}};

static void kfields(jw *j, json_object *o, const void *base, const field *fields, size_t count) {
    for (size_t k = 0; k < count; k++) {
        double v;
        memcpy(&v, (const char *)base + fields[k].offset, sizeof v);
        knum(j, o, fields[k].key, v);
    }
}

/* Two posts of one kind: all but their place alike. */
static int same_kind(const cs_post_def *a, const cs_post_def *b) {
    const cs_section_def *s = &a->section, *t = &b->section;
    const cs_footing_def *f = &a->footing, *g = &b->footing;
    return a->height == b->height && a->attachment == b->attachment && a->release_force == b->release_force &&
           a->lateral_release_force == b->lateral_release_force && a->face == b->face &&
           a->rotation_limit == b->rotation_limit && s->plastic_modulus == t->plastic_modulus &&
           s->inertia == t->inertia && s->web_area == t->web_area && s->yield_stress == t->yield_stress &&
           s->modulus == t->modulus && s->mass_per_length == t->mass_per_length &&
           s->fill_strength == t->fill_strength && s->width == t->width && s->depth == t->depth &&
           s->wall == t->wall && f->diameter == g->diameter && f->depth == g->depth &&
           f->rotation_limit == g->rotation_limit && f->pullout_capacity == g->pullout_capacity;
}

/* The barrier's ropes as the design gives them: each one's height, rope and pretension, and the fitting
 * at the start anchor and at the end anchor. */
static json_object *design_ropes(jw *j, const cs_barrier_def *b) {
    json_object *ropes = json_object_new_array();
    for (int c = 0; c < b->cable_count; c++) {
        const cs_cable_def *cd = &b->cables[c];
        json_object *rope = json_object_new_object(), *ends = json_object_new_array();
        knum(j, rope, "height_m", cd->height);
        kfields(j, rope, &cd->rope, rope_fields, sizeof rope_fields / sizeof rope_fields[0]);
        knum(j, rope, "pretension_n", cd->pretension);
        for (int k = 0; k < 2; k++) {
            cs_termination kind;
            double eff = cs_cable_end_efficiency(cd, k, &kind);
            json_object *end = json_object_new_object();
            kstr(end, "termination", cs_termination_word(kind));
            knum(j, end, "termination_efficiency", eff);
            double travel, slip = cs_cable_end_slip(cd, k, &travel);
            if (slip > 0.0) /* a fitting that slips */
                knum(j, end, "slip_load_n", slip), knum(j, end, "slip_travel_m", travel);
            json_object_array_add(ends, end);
        }
        json_object_object_add(rope, "ends", ends);
        json_object_array_add(ropes, rope);
    }
    return ropes;
}

/* The barrier's kinds of post: the posts of each kind, its section, footing and attachment. */
static json_object *design_post_kinds(jw *j, const cs_barrier_def *b) {
    json_object *kinds = json_object_new_array();
    for (int p = 0; p < b->post_count; p++) {
        const cs_post_def *pd = &b->posts[p];
        int seen = 0;
        for (int q = 0; q < p && !seen; q++)
            seen = same_kind(&b->posts[q], pd);
        if (seen) continue;
        json_object *kind = json_object_new_object(), *posts = json_object_new_array(),
                    *footing = json_object_new_object();
        for (int q = p; q < b->post_count; q++)
            if (same_kind(&b->posts[q], pd)) json_object_array_add(posts, json_object_new_int(q));
        json_object_object_add(kind, "posts", posts);
        knum(j, kind, "height_m", pd->height);
        kfields(j, kind, &pd->section, section_fields, sizeof section_fields / sizeof section_fields[0]);
        knum(j, kind, "plastic_moment_nm", cs_section_plastic_moment(&pd->section)); /* the engine's M_p */
        if (pd->section.fill_strength > 0.0) knum(j, kind, "fill_strength_pa", pd->section.fill_strength);
        knum(j, kind, "rotation_limit_rad", pd->rotation_limit);
        kstr(kind, "attachment", cs_attachment_word(pd->attachment));
        double along = cs_post_release_force(pd), off = cs_post_lateral_release_force(pd);
        if (along > 0.0) knum(j, kind, "release_force_n", along); /* a kind that lets its cables go */
        if (off > 0.0) {                                          /* bolted to one face */
            knum(j, kind, "lateral_release_force_n", off);
            kstr(kind, "face", cs_face_word(pd->face));
        }
        write_footing(j, footing, &pd->footing, "skin friction");
        json_object_object_add(kind, "footing", footing);
        json_object_array_add(kinds, kind);
    }
    return kinds;
}

/* "design": the barrier's ropes, its kinds of post (section, footing, where they stand), the posts'
 * spacing, the soil (the first post's footing's) and the anchors, in SI, as the engine gets them. */
static json_object *write_design(jw *j, const cs_barrier_def *b) {
    snprintf(j->what, sizeof j->what, "the design");
    json_object *o = json_object_new_object(), *post_x = json_object_new_array(),
                *soil_o = json_object_new_object(), *anchors = json_object_new_array();
    json_object_object_add(o, "ropes", design_ropes(j, b));
    json_object_object_add(o, "post_kinds", design_post_kinds(j, b));
    for (int p = 0; p < b->post_count; p++)
        json_object_array_add(post_x, num(j, b->posts[p].x));
    json_object_object_add(o, "post_x_m", post_x);
    const cs_footing_def *soil = b->post_count ? &b->posts[0].footing : &b->start_anchor.footing;
    kfields(j, soil_o, soil, soil_fields, sizeof soil_fields / sizeof soil_fields[0]);
    kstr(soil_o, "width_scaling", cs_width_scaling_word(soil->width_scaling));
    knum(j, soil_o, "skin_friction_pa_m", soil->skin_friction);
    json_object_object_add(o, "soil", soil_o);
    for (int k = 0; k < 2; k++) {
        const cs_anchor_def *a = k ? &b->end_anchor : &b->start_anchor;
        json_object *ao = json_object_new_object();
        knum(j, ao, "x_m", a->x);
        knum(j, ao, "z_m", a->z);
        knum(j, ao, "diameter_m", a->footing.diameter);
        knum(j, ao, "depth_m", a->footing.depth);
        knum(j, ao, "length_m", a->length > 0 ? a->length : a->footing.diameter);
        kopt(j, ao, "mass_kg", a->mass > 0 ? a->mass : NAN);
        kcapacity(j, ao, "pullout_capacity_n", a->pullout_capacity, "its weight and skin friction");
        kstr(ao, "width_scaling", cs_width_scaling_word(a->footing.width_scaling));
        json_object_array_add(anchors, ao);
    }
    json_object_object_add(o, "anchors", anchors);
    return o;
}

/* "cablesim": {version, command, overrides, model_hash} and "designations_as_run": [{standard, label,
 * text}]. */
static void write_info(json_object *doc, const cs_run_info *info) {
    json_object *list = json_object_new_array();
    json_object_object_add(doc, "cablesim", cs_json_provenance(info));
    for (int i = 0; info && i < info->rating_count; i++) {
        char text[256];
        json_object *o = json_object_new_object();
        cs_rating_text(&info->ratings[i], text, sizeof text);
        kstr(o, "standard", cs_standard_name(info->ratings[i].standard));
        kstr(o, "label", info->ratings[i].label);
        kstr(o, "vehicle_class", info->ratings[i].vehicle_class);
        kstr(o, "text", text);
        json_object_array_add(list, o);
    }
    json_object_object_add(doc, "designations_as_run", list);
}

/* A number of the summary: every digit of the double (w is a jw's). */
static json_object *summary_num(cs_wout *w, double v, const char *what) {
    jw *j = (jw *)w; /* its first member */
    snprintf(j->what, sizeof j->what, "%s", what);
    return num_digits(j, v, SUMMARY_DIGITS, 0);
}

/* "summary": the response parameters with every digit of the double. */
static json_object *summary_of(jw *j, const cs_state *state, const cs_summary *s) {
    json_object *o = json_object_new_object();
    j->digits = SUMMARY_DIGITS;
    kstr(o, "outcome", cs_outcome_name(s->outcome));
    knum(j, o, "t_end_s", s->t_end_s);
    knum(j, o, "max_50ms_decel_g", s->max_50ms_decel_g);
    knum(j, o, "t_max_50ms_decel_s", s->t_max_50ms_decel_s);
    /* the penetration the vehicle stopped at (null if it got through or was still going), else how far
     * it had got when the run ended: beyond that */
    int final = cs_penetration_is_final(s->outcome);
    kopt(j, o, "max_dynamic_penetration_m", final ? s->max_dynamic_penetration_m : NAN);
    kopt(j, o, "penetration_beyond_m", final ? NAN : s->max_dynamic_penetration_m);
    knum(j, o, "max_barrier_deflection_m", s->max_barrier_deflection_m);
    knum(j, o, "working_width_m", s->working_width_m);
    kopt(j, o, "stop_time_s", s->outcome == CS_STOPPED ? s->stop_time_s : NAN);
    kopt(j, o, "exit_speed_mps", cs_outcome_exits(s->outcome) ? s->exit_speed_mps : NAN);
    kopt(j, o, "exit_angle_deg", cs_outcome_exits(s->outcome) ? s->exit_angle_deg : NAN);
    kopt(j, o, "exit_time_s", cs_outcome_exits(s->outcome) ? s->exit_time_s : NAN);
    kopt(j, o, "first_contact_time_s", s->first_contact_time_s >= 0 ? s->first_contact_time_s : NAN);
    kint(o, "posts_failed_left", s->posts_failed_left);
    kint(o, "posts_failed_right", s->posts_failed_right);
    kint(o, "posts_failed_rotation_left", s->posts_failed_rotation_left);
    kint(o, "posts_failed_rotation_right", s->posts_failed_rotation_right);
    kint(o, "posts_failed_shear_left", s->posts_failed_shear_left);
    kint(o, "posts_failed_shear_right", s->posts_failed_shear_right);
    kint(o, "posts_failed_pullout_left", s->posts_failed_pullout_left);
    kint(o, "posts_failed_pullout_right", s->posts_failed_pullout_right);
    kint(o, "cables_broken", s->cables_broken);
    knum(j, o, "max_cable_tension_n", s->max_cable_tension_n);
    knum(j, o, "initial_kinetic_energy_j", s->initial_kinetic_energy_j);
    knum(j, o, "energy_balance_error", s->energy_balance_error);
    kint(o, "solver_warnings", s->solver_warnings);
    knum(j, o, "max_solver_residual", s->max_solver_residual);
    cs_json_cables_and_losses(&j->w, o, state, s, summary_num);
    j->digits = PAGE_DIGITS;
    return o;
}

/* "scenario" and "vehicle": the inputs the page shows. */
static void scenario_and_vehicle(jw *j, json_object *doc, const cs_model_input *in) {
    json_object *o = json_object_new_object(), *vo = json_object_new_object();
    kfields(j, o, &in->scenario, scenario_fields, 3);
    kint(o, "impact_at_corner", in->scenario.impact_at_corner);
    kfields(j, o, &in->scenario, scenario_fields + 3, sizeof scenario_fields / sizeof scenario_fields[0] - 3);
    json_object_object_add(doc, "scenario", o);
    kfields(j, vo, &in->vehicle, vehicle_fields, sizeof vehicle_fields / sizeof vehicle_fields[0]);
    json_object_object_add(doc, "vehicle", vo);
}

/* "barrier": posts [x, height, rotation limit], cables [height, Fu, pretension], anchors [x, z]; their
 * units barrier_units */
static const char barrier_units[] =
    "{\"posts\":[[\"m\",\"m\"]],\"cables\":[[\"m\",\"N\",\"N\"]],\"anchors\":\"m\"}";
static json_object *barrier_of(jw *j, const cs_barrier_def *b) {
    json_object *o = json_object_new_object(), *posts = json_object_new_array(),
                *cables = json_object_new_array(), *anchors = json_object_new_array();
    snprintf(j->what, sizeof j->what, "the barrier");
    for (int p = 0; p < b->post_count; p++) {
        const cs_post_def *pd = &b->posts[p];
        json_object *a = json_object_new_array_ext(2);
        json_object_array_add(a, num(j, pd->x));
        json_object_array_add(a, num(j, pd->height));
        json_object_array_add(posts, a);
    }
    json_object_object_add(o, "posts", posts);
    for (int c = 0; c < b->cable_count; c++) {
        const double v[] = {b->cables[c].height, b->cables[c].rope.nominal_strength, b->cables[c].pretension};
        json_object_array_add(cables, nums(j, v, 3));
    }
    json_object_object_add(o, "cables", cables);
    for (int k = 0; k < 2; k++) {
        const cs_anchor_def *a = k ? &b->end_anchor : &b->start_anchor;
        const double v[] = {a->x, a->z};
        json_object_array_add(anchors, nums(j, v, 2));
    }
    json_object_object_add(o, "anchors", anchors);
    return o;
}

/* events: [t, type, element kind, element, value (SI)], then a termination event's cable end, the cable a
 * post let go and the post at whose hole a rope broke, as far as one of them is given; each on a line of
 * its own. Each event's units into units: its value's is its type's (events.csv's value_unit). */
static json_object *events_of(jw *j, const cs_state *state, json_object *units) {
    json_object *list = json_object_new_array();
    snprintf(j->what, sizeof j->what, "an event's time or value");
    for (int i = 0; i < cs_state_event_count(state); i++) {
        cs_event e = {.size = sizeof e};
        cs_state_event(state, i, &e, NULL);
        json_object *o = json_object_new_array(), *u = json_object_new_array();
        json_object_array_add(o, num(j, e.t));
        json_object_array_add(o, cs_jstr(cs_event_type_name(e.type)));
        json_object_array_add(o, cs_jstr(cs_element_kind_name(e.element_kind)));
        json_object_array_add(o, json_object_new_int(e.element));
        json_object_array_add(o, num(j, e.value));
        if (e.cable_end >= 0 || e.cable >= 0 || e.post >= 0)
            json_object_array_add(o, json_object_new_int(e.cable_end));
        if (e.cable >= 0 || e.post >= 0) json_object_array_add(o, json_object_new_int(e.cable));
        if (e.post >= 0) json_object_array_add(o, json_object_new_int(e.post));
        json_object_array_add(list, cs_jline_before(o));
        const char *unit[] = {"s", "", "", "", cs_event_value_unit(e.type)}; /* then indices: "" */
        for (size_t k = 0; k < json_object_array_length(o); k++)
            json_object_array_add(u, cs_jstr(k < sizeof unit / sizeof unit[0] ? unit[k] : ""));
        json_object_array_add(units, u);
    }
    return list;
}

/* ---- the units of the data ("units": report_html.h) ---- */

/* The unit of key's value v (a number or null) in a part of the data: NULL for a null that has none. */
typedef const char *(*unit_fn)(const void *ctx, const char *key, json_object *v);

/* The unit a key names by its ending, as summary.json's keys do (docs/tutorial.md: "working_width_m" is
 * in m), written as the CSVs write it; a key without one holds a pure number ("1") where v is a double,
 * a count or an index (no unit, "") where it is an integer. */
static const char *unit_by_ending(const void *ctx, const char *key, json_object *v) {
    (void)ctx;
    static const struct {
        const char *end, *unit;
    } ends[] = {{"_mps", "m/s"}, {"_kmh", "km/h"}, {"_kg_m", "kg/m"}, {"_pa_m", "Pa/m"},
                {"_m2", "m^2"},  {"_m3", "m^3"},   {"_m4", "m^4"},    {"_deg", "deg"},
                {"_rad", "rad"}, {"_pa", "Pa"},    {"_kg", "kg"},     {"_m", "m"},
                {"_s", "s"},     {"_g", "g"},      {"_n", "N"},       {"_j", "J"}};
    size_t n = strlen(key);
    for (size_t k = 0; k < sizeof ends / sizeof ends[0]; k++) {
        size_t e = strlen(ends[k].end);
        if (n > e && strcmp(key + n - e, ends[k].end) == 0) return ends[k].unit;
    }
    return json_object_is_type(v, json_type_int) ? "" : json_object_is_type(v, json_type_double) ? "1" : NULL;
}

/* The unit the model's schema gives key in table ctx (its quantity's SI unit); none for an integer it does
 * not give (a flag: "impact_at_corner"). */
static const char *unit_by_schema(const void *ctx, const char *key, json_object *v) {
    const cs_table *t = ctx;
    for (int i = 0; i < t->count; i++)
        if (t->fields[i].kind == CS_F_QTY && strcmp(t->fields[i].key, key) == 0)
            return cs_quantity_get(t->fields[i].q)->label;
    return json_object_is_type(v, json_type_int) ? "" : NULL;
}

static json_object *value_units(unit_fn unit, const void *ctx, const char *key, json_object *v);

/* The units of object o, keyed as it: each member's by value_units. */
static json_object *object_units(unit_fn unit, const void *ctx, json_object *o) {
    json_object *units = json_object_new_object();
    json_object_object_foreach(o, key, v) {
        json_object *u = value_units(unit, ctx, key, v);
        if (u) json_object_object_add(units, key, u);
    }
    return units;
}

/* The units of member key's value v: a number's unit(key); an object's object_units; a list of numbers'
 * one unit for them all; another list's, each element's; NULL where v holds no number. */
static json_object *value_units(unit_fn unit, const void *ctx, const char *key, json_object *v) {
    json_type type = json_object_get_type(v);
    if (type == json_type_object) return object_units(unit, ctx, v);
    if (type != json_type_array) {
        const char *u = type == json_type_int || type == json_type_double || type == json_type_null
                            ? unit(ctx, key, v)
                            : NULL;
        return u ? cs_jstr(u) : NULL;
    }
    size_t n = json_object_array_length(v), numbers = 0, first = n;
    for (size_t i = 0; i < n; i++) {
        json_type t = json_object_get_type(json_object_array_get_idx(v, i));
        numbers += t == json_type_int || t == json_type_double || t == json_type_null;
        if (first == n && t != json_type_null) first = i;
    }
    if (n == 0 || numbers == n)
        return value_units(unit, ctx, key, json_object_array_get_idx(v, first < n ? first : 0));
    json_object *units = json_object_new_array_ext((int)n);
    for (size_t i = 0; i < n; i++)
        json_object_array_add(units, value_units(unit, ctx, key, json_object_array_get_idx(v, i)));
    return units;
}

/* "units": the units of every number of doc (the series' and the events' as written with them, taken),
 * on the data's last line. */
static json_object *page_units(json_object *doc, json_object *series_units, json_object *event_units) {
    static const struct {
        const char *key;
        unit_fn unit;
        const cs_table *table;
    } by_key[] = {{"evaluation", unit_by_ending, NULL},
                  {"summary", unit_by_ending, NULL},
                  {"scenario", unit_by_schema, &cs_table_scenario},
                  {"vehicle", unit_by_schema, &cs_table_vehicle},
                  {"design", unit_by_ending, NULL}};
    json_object *units = json_object_new_object();
    kunit(units, "format", "");
    for (size_t k = 0; k < sizeof by_key / sizeof by_key[0]; k++) {
        json_object *part = NULL;
        json_object_object_get_ex(doc, by_key[k].key, &part);
        json_object_object_add(units, by_key[k].key, object_units(by_key[k].unit, by_key[k].table, part));
    }
    json_object_object_add(units, "barrier", json_tokener_parse(barrier_units));
    json_object_object_add(units, "events", event_units);
    json_object_object_add(units, "series", series_units);
    kunit(units, "replay_stride", "");
    json_object_object_add(units, "frames", json_tokener_parse(frame_units));
    return units;
}

json_object *cs_report_json(const cs_model_input *in, const cs_state *state, const cs_record *r,
                            const cs_run_info *info, cs_error *err) {
    jw j = {{NULL, 0, ""}, "", PAGE_DIGITS};
    cs_summary s = {.size = sizeof s};
    cs_state_summary(state, &s, NULL);
    json_object *doc = json_object_new_object(), *evaluation = json_object_new_object(),
                *series_units = json_object_new_object(), *event_units = json_object_new_array();
    if (!doc || !evaluation || !series_units || !event_units) {
        json_object_put(doc), json_object_put(evaluation);
        json_object_put(series_units), json_object_put(event_units);
        cs_status_set(err, CS_ERR_MEMORY, "report.html: out of memory");
        return NULL;
    }
    kint(doc, "format", 1);
    kstr(doc, "name", in->name);
    kstr(doc, "file", in->file);
    kstr(doc, "version", CS_VERSION_STRING);
    write_info(doc, info);
    cs_json_evaluation(&j.w, evaluation, info, 0);
    json_object_object_add(doc, "evaluation", evaluation);
    json_object_object_add(doc, "summary", summary_of(&j, state, &s));
    scenario_and_vehicle(&j, doc, in);
    json_object_object_add(doc, "barrier", barrier_of(&j, &in->barrier));
    json_object_object_add(doc, "design", write_design(&j, &in->barrier));
    json_object_object_add(doc, "events", events_of(&j, state, event_units));
    int n = r->frame_count;
    int series_stride = n > CS_REPORT_SERIES_MAX ? (n + CS_REPORT_SERIES_MAX - 1) / CS_REPORT_SERIES_MAX : 1;
    double fit = CS_REPORT_REPLAY_BYTES / replay_frame_bytes(r);
    int replay_max = fit < CS_REPORT_REPLAY_MIN   ? CS_REPORT_REPLAY_MIN
                     : fit > CS_REPORT_REPLAY_MAX ? CS_REPORT_REPLAY_MAX
                                                  : (int)fit;
    int replay_stride = n > replay_max ? (n + replay_max - 1) / replay_max : 1;
    json_object_object_add(doc, "series", write_series(&j, in, r, series_stride, series_units));
    kint(doc, "replay_stride", replay_stride);
    json_object_object_add(doc, "frames", write_frames(&j, r, replay_stride));
    json_object_object_add(doc, "units", cs_jline_before(page_units(doc, series_units, event_units)));
    if (cs_w_status(&j.w, "report.html", err) == CS_OK) return doc;
    json_object_put(doc);
    return NULL;
}

cs_status cs_write_report_json(FILE *f, const cs_model_input *in, const cs_state *state, const cs_record *r,
                               const cs_run_info *info, cs_error *err) {
    cs_error own;
    json_object *doc = cs_report_json(in, state, r, info, err ? err : &own);
    if (!doc) return err ? err->status : own.status;
    int written = cs_json_write(f, doc, 1, "") == 0;
    json_object_put(doc);
    if (!written) return cs_status_set(err, CS_ERR_MEMORY, "report.html: out of memory");
    if (ferror(f)) return cs_status_set(err, CS_ERR_IO, "report.html: write error");
    return CS_OK;
}

cs_status cs_write_page(FILE *f, const unsigned char *page, size_t size, const char *title, const char *what,
                        cs_page_data_fn data, void *user, cs_error *err) {
    char message[CS_MESSAGE_SIZE];
    static const char title_marker[] = "@CS_TITLE@", data_marker[] = "@CS_DATA@";
    const size_t nt = sizeof title_marker - 1, nd = sizeof data_marker - 1;
    size_t i = 0, from = 0;
    int data_written = 0;
    while (i < size) {
        int is_title = i + nt <= size && memcmp(page + i, title_marker, nt) == 0;
        int is_data = i + nd <= size && memcmp(page + i, data_marker, nd) == 0;
        if (!is_title && !is_data) {
            i++;
            continue;
        }
        fwrite(page + from, 1, i - from, f);
        if (is_title) {
            cs_html_text(f, title);
            i += nt;
        } else {
            cs_status st = data(f, user, err);
            if (st != CS_OK) return st;
            data_written = 1;
            i += nd;
        }
        from = i;
    }
    fwrite(page + from, 1, size - from, f);
    if (!data_written) {
        snprintf(message, sizeof message, "%s: the page has no %s marker (a broken build of report/)", what,
                 data_marker);
        return cs_status_set(err, CS_ERR_IO, message);
    }
    if (ferror(f)) {
        snprintf(message, sizeof message, "%s: write error", what);
        return cs_status_set(err, CS_ERR_IO, message);
    }
    return CS_OK;
}

typedef struct report_data {
    const cs_model_input *in;
    const cs_state *state;
    const cs_record *rec;
    const cs_run_info *info;
} report_data;

static cs_status write_report_data(FILE *f, void *user, cs_error *err) {
    const report_data *d = user;
    return cs_write_report_json(f, d->in, d->state, d->rec, d->info, err);
}

cs_status cs_write_report_html(FILE *f, const unsigned char *page, size_t size, const cs_model_input *in,
                               const cs_state *state, const cs_record *rec, const cs_run_info *info,
                               cs_error *err) {
    report_data d = {in, state, rec, info};
    return cs_write_page(f, page, size, in->name, "report.html", write_report_data, &d, err);
}
