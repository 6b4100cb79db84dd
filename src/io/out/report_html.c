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
#include "writers.h"

typedef struct jw {
    cs_wout w;
    char what[96]; /* names the value being written, for the message of a non-finite one */
    int digits;    /* of a named value (knum, kopt): 6, or every digit of the double in "summary" */
} jw;

void cs_json_page_string(FILE *f, const char *s) {
    fputc('"', f);
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c < 0x20 || c == '<' || c == '>' || c == '&')
            fprintf(f, "\\u%04x", c);
        else
            fputc(c, f);
    }
    fputc('"', f);
}

/* The response parameters ("summary") have every digit of the double, so that the page, rounding them
 * for display, shows what the terminal shows (0.41650000000000004 s is 0.417 s on both; written as 0.4165
 * it would read 0.416). */
enum { SUMMARY_DIGITS = 17, PAGE_DIGITS = 6 };

/* A number to `digits` significant digits; NaN is null where nullable (absent on purpose). */
static void num_digits(jw *j, double v, int digits, int nullable) {
    if (nullable && isnan(v)) {
        fputs("null", j->w.f);
        return;
    }
    if (j->w.bad) return;
    if (!isfinite(v)) {
        j->w.bad = 1;
        snprintf(j->w.why, sizeof j->w.why, "%s is %s", j->what, isnan(v) ? "NaN" : "infinite");
        return;
    }
    fprintf(j->w.f, "%.*g", digits, v == 0 ? 0.0 : v); /* no "-0" */
}

/* A point of a time history, with 6 significant digits (the data of a page's plots and replay, not of an
 * analysis: the CSV has 10). */
static void num(jw *j, double v) {
    num_digits(j, v, PAGE_DIGITS, 0);
}

/* A point of a time history that may be absent on purpose (NaN: null). */
static void opt(jw *j, double v) {
    num_digits(j, v, PAGE_DIGITS, 1);
}

static void key(jw *j, int *first, const char *k) {
    fprintf(j->w.f, "%s\"%s\":", *first ? "" : ",", k);
    *first = 0;
}

static void knum(jw *j, int *first, const char *k, double v) {
    key(j, first, k);
    snprintf(j->what, sizeof j->what, "%s", k);
    num_digits(j, v, j->digits, 0);
}

static void kopt(jw *j, int *first, const char *k, double v) {
    key(j, first, k);
    snprintf(j->what, sizeof j->what, "%s", k);
    num_digits(j, v, j->digits, 1);
}

static void kint(jw *j, int *first, const char *k, int v) {
    key(j, first, k);
    fprintf(j->w.f, "%d", v);
}

static void kstr(jw *j, int *first, const char *k, const char *v) {
    key(j, first, k);
    cs_json_page_string(j->w.f, v);
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

static void series(jw *j, const cs_record *r, const cs_model_input *in, int stride, series_fn fn, int arg,
                   int nullable, const char *what) {
    int n = r->frame_count, count = kept_count(n, stride);
    fputc('[', j->w.f);
    for (int k = 0; k < count && !j->w.bad; k++) {
        int f = kept_frame(n, stride, k);
        if (k) fputc(',', j->w.f);
        snprintf(j->what, sizeof j->what, "%s at t = %g s", what, r->vehicle[f].t);
        double v = fn(r, in, f, arg);
        if (nullable)
            opt(j, v);
        else
            num(j, v);
    }
    fputc(']', j->w.f);
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
/* the furthest point of an intact cable (NaN: none intact) */
static double s_deflection(const cs_record *r, const cs_model_input *in, int f, int arg) {
    (void)in, (void)arg;
    double y = NAN;
    for (int c = 0; c < r->cable_count; c++) {
        size_t k = (size_t)f * (size_t)r->cable_count + (size_t)c;
        if (r->cables[k].status != CS_CABLE_INTACT) continue;
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

static const struct {
    const char *key;
    size_t offset;
} ledger[] = {
    {"crush", offsetof(cs_energy, crush)},
    {"post_plastic", offsetof(cs_energy, post_plastic)},
    {"post_damping", offsetof(cs_energy, post_damping)},
    {"soil", offsetof(cs_energy, soil)},
    {"cable_plastic", offsetof(cs_energy, cable_plastic)},
    {"friction", offsetof(cs_energy, friction)},
    {"released", offsetof(cs_energy, released)},
    {"post_elastic", offsetof(cs_energy, post_elastic)},
    {"post_kinetic", offsetof(cs_energy, post_kinetic)},
    {"anchor_elastic", offsetof(cs_energy, anchor_elastic)},
    {"anchor_kinetic", offsetof(cs_energy, anchor_kinetic)},
    {"rail_elastic", offsetof(cs_energy, rail_elastic)},
    {"rail_plastic", offsetof(cs_energy, rail_plastic)},
    {"cable_elastic", offsetof(cs_energy, cable_elastic)},
    {"vehicle_potential", offsetof(cs_energy, vehicle_potential)},
    {"vehicle_kinetic", offsetof(cs_energy, vehicle_kinetic)},
    {"balance_error", offsetof(cs_energy, balance_error)},
};
enum { LEDGER_TERMS = sizeof ledger / sizeof ledger[0] };

static double s_energy(const cs_record *r, const cs_model_input *in, int f, int k) {
    (void)in;
    double v;
    memcpy(&v, (const char *)&r->energy[f] + ledger[k].offset, sizeof v);
    return v;
}

enum { NEAR_POSTS = 4 };

static void write_series(jw *j, const cs_model_input *in, const cs_record *r, int stride) {
    FILE *f = j->w.f;
    int first = 1, idx[NEAR_POSTS];
    int near = cs_nearest_posts(in, idx, r->post_count < NEAR_POSTS ? r->post_count : NEAR_POSTS);
    fputc('{', f);
    kint(j, &first, "stride", stride);
    static const struct {
        const char *key, *what;
        series_fn fn;
        int arg, nullable;
    } plain[] = {
        {"t", "time", s_time, 0, 0},
        {"decel", "the deceleration", s_decel, 0, 0},
        {"decel50", "the 50-ms deceleration", s_decel50, 0, 1},
        {"speed", "the forward speed", s_speed, 0, 0},
        {"penetration", "the penetration", s_penetration, 0, 0},
        {"face", "the front face", s_face, 0, 0},
        {"deflection", "the barrier deflection", s_deflection, 0, 1},
        {"roll", "the roll", s_attitude, 0, 0},
        {"pitch", "the pitch", s_attitude, 1, 0},
        {"yaw", "the yaw", s_attitude, 2, 0},
        {"cg_x", "the CG's x", s_cg, 0, 0},
        {"cg_y", "the CG's y", s_cg, 1, 0},
    };
    for (size_t k = 0; k < sizeof plain / sizeof plain[0]; k++) {
        key(j, &first, plain[k].key);
        series(j, r, in, stride, plain[k].fn, plain[k].arg, plain[k].nullable, plain[k].what);
    }
    key(j, &first, "tension");
    fputc('[', f);
    for (int c = 0; c < r->cable_count; c++) {
        if (c) fputc(',', f);
        series(j, r, in, stride, s_tension, c, 0, "a cable's tension");
    }
    fputc(']', f);
    key(j, &first, "near_posts");
    fputc('[', f);
    for (int k = 0; k < near; k++)
        fprintf(f, "%s%d", k ? "," : "", idx[k]);
    fputc(']', f);
    static const struct {
        const char *key, *what;
        series_fn fn;
    } per_post[] = {{"post_tilt", "a post's tilt", s_tilt},
                    {"post_moment", "a post's base moment", s_moment}};
    for (int m = 0; m < 2; m++) {
        key(j, &first, per_post[m].key);
        fputc('[', f);
        for (int k = 0; k < near; k++) {
            if (k) fputc(',', f);
            series(j, r, in, stride, per_post[m].fn, idx[k], 0, per_post[m].what);
        }
        fputc(']', f);
    }
    key(j, &first, "post_capacity");
    fputc('[', f);
    for (int k = 0; k < near && r->frame_count > 0; k++) {
        if (k) fputc(',', f);
        snprintf(j->what, sizeof j->what, "post %d's moment capacity", idx[k]);
        num(j, r->posts[idx[k]].moment_capacity);
    }
    fputc(']', f);
    key(j, &first, "energy");
    fputc('{', f);
    int ef = 1;
    for (int k = 0; k < LEDGER_TERMS; k++) {
        key(j, &ef, ledger[k].key);
        series(j, r, in, stride, s_energy, k, 0, "the energy ledger");
    }
    fputc('}', f);
    if (r->frame_count > 0) {
        knum(j, &first, "initial_kinetic", r->energy[0].initial_kinetic);
        knum(j, &first, "initial_total", r->energy[0].initial_total);
    }
    fputc('}', f);
}

/* Bytes of one replay frame, roughly (a number ~ 8 characters). */
static double replay_frame_bytes(const cs_record *r) {
    int nodes = 0;
    for (size_t k = 0; k < (size_t)r->frame_count * (size_t)r->cable_count; k++)
        if (r->path_count[k] > nodes) nodes = r->path_count[k];
    return 8.0 * (10 + 4 * r->post_count + r->cable_count * (4 + 4 * nodes));
}

/* frames: [[t, [x, y, z, roll, pitch, yaw, crush, face_force], [top x, y, z, status]*posts,
 * [[status, engaged, [x, y, z]*nodes, [span tension]*(nodes-1)]]*cables], ...] */
static void write_frames(jw *j, const cs_record *r, int stride) {
    FILE *f = j->w.f;
    int n = r->frame_count, count = kept_count(n, stride);
    fputc('[', f);
    for (int k = 0; k < count && !j->w.bad; k++) {
        int fr = kept_frame(n, stride, k);
        const cs_vehicle_view *v = &r->vehicle[fr];
        snprintf(j->what, sizeof j->what, "the replay frame at t = %g s", v->t);
        fprintf(f, "%s\n[", k ? "," : "");
        num(j, v->t);
        const double pose[] = {v->position[0], v->position[1], v->position[2], v->roll,
                               v->pitch,       v->yaw,         v->crush,       v->face_force};
        fputs(",[", f);
        for (size_t i = 0; i < sizeof pose / sizeof pose[0]; i++) {
            if (i) fputc(',', f);
            num(j, pose[i]);
        }
        fputs("],[", f);
        for (int p = 0; p < r->post_count; p++) {
            const cs_post_view *pv = &r->posts[(size_t)fr * (size_t)r->post_count + (size_t)p];
            fputs(p ? "," : "", f);
            for (int i = 0; i < 3; i++) {
                num(j, pv->top[i]);
                fputc(',', f);
            }
            fprintf(f, "%d", (int)pv->status);
        }
        fputs("],[", f);
        for (int c = 0; c < r->cable_count; c++) {
            size_t ck = (size_t)fr * (size_t)r->cable_count + (size_t)c;
            const cs_cable_view *cv = &r->cables[ck];
            const double *xyz = r->path_xyz + ck * (size_t)r->max_nodes * 3,
                         *ten = r->path_tension + ck * (size_t)r->max_nodes;
            int nodes = r->path_count[ck];
            fprintf(f, "%s[%d,%d,[", c ? "," : "", (int)cv->status, cv->engaged);
            for (int i = 0; i < 3 * nodes; i++) {
                if (i) fputc(',', f);
                num(j, xyz[i]);
            }
            fputs("],[", f);
            for (int i = 0; i + 1 < nodes; i++) {
                if (i) fputc(',', f);
                num(j, ten[i]);
            }
            fputs("]]", f);
        }
        fputs("]]", f);
    }
    fputc(']', f);
}

/* ---- the design as loaded ---- */

/* A capacity that may be a rule instead of a number: key as a number where one is given, else null and
 * key_rule what stands for it. */
static void kcapacity(jw *j, int *first, const char *k, double v, const char *rule) {
    char rk[64];
    kopt(j, first, k, isfinite(v) && v > 0 ? v : NAN);
    snprintf(rk, sizeof rk, "%s_rule", k);
    kstr(j, first, rk, isinf(v) ? "never" : v > 0 ? "" : rule);
}

static void write_footing(jw *j, int *first, const cs_footing_def *f, const char *pullout_rule) {
    knum(j, first, "diameter_m", f->diameter);
    knum(j, first, "depth_m", f->depth);
    knum(j, first, "rotation_limit_rad", f->rotation_limit);
    kcapacity(j, first, "pullout_capacity_n", f->pullout_capacity, pullout_rule);
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

static void kfields(jw *j, int *first, const void *base, const field *fields, size_t count) {
    for (size_t k = 0; k < count; k++) {
        double v;
        memcpy(&v, (const char *)base + fields[k].offset, sizeof v);
        knum(j, first, fields[k].key, v);
    }
}

/* Two posts of one kind: all but their place alike. */
static int same_kind(const cs_post_def *a, const cs_post_def *b) {
    const cs_section_def *s = &a->section, *t = &b->section;
    const cs_footing_def *f = &a->footing, *g = &b->footing;
    return a->height == b->height && a->attachment == b->attachment && a->release_force == b->release_force &&
           a->rotation_limit == b->rotation_limit && s->plastic_modulus == t->plastic_modulus &&
           s->inertia == t->inertia && s->web_area == t->web_area && s->yield_stress == t->yield_stress &&
           s->modulus == t->modulus && s->mass_per_length == t->mass_per_length &&
           f->diameter == g->diameter && f->depth == g->depth && f->rotation_limit == g->rotation_limit &&
           f->pullout_capacity == g->pullout_capacity;
}

/* "design": the barrier's ropes, its kinds of post (section, footing, where they stand), the posts'
 * spacing, the soil (the first post's footing's) and the anchors, in SI, as the engine gets them. */
static void write_design(jw *j, int *first, const cs_barrier_def *b) {
    FILE *f = j->w.f;
    snprintf(j->what, sizeof j->what, "the design");
    key(j, first, "design");
    fputs("{\"ropes\":[", f);
    for (int c = 0; c < b->cable_count; c++) {
        const cs_cable_def *cd = &b->cables[c];
        int rf = 1;
        fputs(c ? ",{" : "{", f);
        knum(j, &rf, "height_m", cd->height);
        kfields(j, &rf, &cd->rope, rope_fields, sizeof rope_fields / sizeof rope_fields[0]);
        knum(j, &rf, "pretension_n", cd->pretension);
        key(j, &rf, "ends"); /* the fitting at the start anchor, at the end anchor */
        for (int k = 0; k < 2; k++) {
            cs_termination kind;
            double eff = cs_cable_end_efficiency(cd, k, &kind);
            int ef = 1;
            fputs(k ? ",{" : "[{", f);
            kstr(j, &ef, "termination", cs_termination_word(kind));
            knum(j, &ef, "termination_efficiency", eff);
            double travel, slip = cs_cable_end_slip(cd, k, &travel);
            if (slip > 0.0) /* a fitting that slips */
                knum(j, &ef, "slip_load_n", slip), knum(j, &ef, "slip_travel_m", travel);
            fputc('}', f);
        }
        fputs("]}", f);
    }
    fputs("],\"post_kinds\":[", f);
    int kinds = 0;
    for (int p = 0; p < b->post_count; p++) {
        const cs_post_def *pd = &b->posts[p];
        int seen = 0, count = 0, pf = 1;
        for (int q = 0; q < p && !seen; q++)
            seen = same_kind(&b->posts[q], pd);
        if (seen) continue;
        fputs(kinds++ ? ",{\"posts\":[" : "{\"posts\":[", f);
        for (int q = p; q < b->post_count; q++)
            if (same_kind(&b->posts[q], pd)) fprintf(f, "%s%d", count++ ? "," : "", q);
        fputc(']', f);
        pf = 0;
        knum(j, &pf, "height_m", pd->height);
        kfields(j, &pf, &pd->section, section_fields, sizeof section_fields / sizeof section_fields[0]);
        knum(j, &pf, "rotation_limit_rad", pd->rotation_limit);
        kstr(j, &pf, "attachment", cs_attachment_word(pd->attachment));
        key(j, &pf, "footing");
        int ff = 1;
        fputc('{', f);
        write_footing(j, &ff, &pd->footing, "skin friction");
        fputs("}}", f);
    }
    fputs("],\"post_x_m\":[", f);
    for (int p = 0; p < b->post_count; p++) {
        if (p) fputc(',', f);
        num(j, b->posts[p].x);
    }
    fputs("],\"soil\":{", f);
    const cs_footing_def *soil = b->post_count ? &b->posts[0].footing : &b->start_anchor.footing;
    int sf = 1;
    knum(j, &sf, "soil_pressure_pa", soil->soil_pressure);
    knum(j, &sf, "soil_pressure_cap_pa", soil->soil_pressure_cap);
    knum(j, &sf, "coeff_depth", soil->coeff_depth);
    knum(j, &sf, "coeff_height", soil->coeff_height);
    knum(j, &sf, "dynamic_factor", soil->dynamic_factor);
    knum(j, &sf, "friction_angle_rad", soil->friction_angle);
    knum(j, &sf, "residual_friction_angle_rad", soil->residual_friction_angle);
    kstr(j, &sf, "width_scaling", cs_width_scaling_word(soil->width_scaling));
    knum(j, &sf, "skin_friction_pa_m", soil->skin_friction);
    fputs("},\"anchors\":[", f);
    for (int k = 0; k < 2; k++) {
        const cs_anchor_def *a = k ? &b->end_anchor : &b->start_anchor;
        int af = 1;
        fputs(k ? ",{" : "{", f);
        knum(j, &af, "x_m", a->x);
        knum(j, &af, "z_m", a->z);
        knum(j, &af, "diameter_m", a->footing.diameter);
        knum(j, &af, "depth_m", a->footing.depth);
        knum(j, &af, "length_m", a->length > 0 ? a->length : a->footing.diameter);
        kopt(j, &af, "mass_kg", a->mass > 0 ? a->mass : NAN);
        kcapacity(j, &af, "pullout_capacity_n", a->pullout_capacity, "its weight and skin friction");
        kstr(j, &af, "width_scaling", cs_width_scaling_word(a->footing.width_scaling));
        fputc('}', f);
    }
    fputs("]}", f);
}

/* "cablesim": {version, command, overrides, model_hash} and "designations_as_run": [{standard, label,
 * text}]. */
static void write_info(jw *j, int *first, const cs_run_info *info) {
    FILE *f = j->w.f;
    key(j, first, "cablesim");
    json_object *provenance = cs_json_provenance(info);
    if (!provenance || cs_json_write(f, provenance, 1, "") != 0) cs_w_oom(&j->w, "cablesim");
    json_object_put(provenance);
    key(j, first, "designations_as_run");
    fputc('[', f);
    for (int i = 0; info && i < info->rating_count; i++) {
        char text[256];
        int rf = 1;
        cs_rating_text(&info->ratings[i], text, sizeof text);
        fputs(i ? ",{" : "{", f);
        kstr(j, &rf, "standard", cs_standard_name(info->ratings[i].standard));
        kstr(j, &rf, "label", info->ratings[i].label);
        kstr(j, &rf, "vehicle_class", info->ratings[i].vehicle_class);
        kstr(j, &rf, "text", text);
        fputc('}', f);
    }
    fputc(']', f);
}

/* Each cable's peak tension and work on the vehicle, and the sudden losses, as summary.json has them. */
static void cables_and_losses(jw *j, int *first, const cs_state *state, const cs_summary *s) {
    key(j, first, "cables");
    fputc('[', j->w.f);
    for (int c = 0; c < s->cable_count; c++) {
        cs_cable_summary cb = {.size = sizeof cb};
        cs_state_cable_summary(state, c, &cb, NULL);
        int cf = 1;
        fprintf(j->w.f, "%s{", c ? "," : "");
        kint(j, &cf, "index", c);
        knum(j, &cf, "peak_tension_n", cb.peak_tension_n);
        knum(j, &cf, "peak_tension_time_s", cb.peak_tension_time_s);
        knum(j, &cf, "work_on_vehicle_j", cb.work_on_vehicle_j);
        knum(j, &cf, "energy_share", cb.energy_share);
        fputc('}', j->w.f);
    }
    fputc(']', j->w.f);
    kint(j, first, "sudden_loss_count", s->sudden_loss_count);
    key(j, first, "sudden_losses");
    fputc('[', j->w.f);
    cs_sudden_loss losses[CS_SUDDEN_LOSS_KEPT] = {{.size = sizeof losses[0]}};
    int n = cs_state_sudden_losses(state, losses, CS_SUDDEN_LOSS_KEPT, NULL);
    for (int k = 0; k < n; k++) {
        int lf = 1;
        fprintf(j->w.f, "%s{", k ? "," : "");
        knum(j, &lf, "t_start_s", losses[k].t_start_s);
        knum(j, &lf, "t_end_s", losses[k].t_end_s);
        knum(j, &lf, "force_before_n", losses[k].force_before_n);
        knum(j, &lf, "force_after_n", losses[k].force_after_n);
        fputc('}', j->w.f);
    }
    fputc(']', j->w.f);
}

int cs_write_report_json(FILE *f, const cs_model_input *in, const cs_state *state, const cs_record *r,
                         const cs_run_info *info, char *why, size_t why_size) {
    jw j = {{f, 0, ""}, "", PAGE_DIGITS};
    cs_summary s = {.size = sizeof s};
    cs_state_summary(state, &s, NULL);
    const cs_scenario_def *sc = &in->scenario;
    const cs_vehicle_def *v = &in->vehicle;
    const cs_barrier_def *b = &in->barrier;
    int first = 1, sf = 1;
    fputc('{', f);
    kint(&j, &first, "format", 1);
    kstr(&j, &first, "name", in->name);
    kstr(&j, &first, "file", in->file);
    kstr(&j, &first, "version", CS_VERSION_STRING);
    write_info(&j, &first, info);
    key(&j, &first, "evaluation");
    json_object *evaluation = json_object_new_object();
    if (evaluation) cs_json_evaluation(&j.w, evaluation, info);
    if (!evaluation || cs_json_write(f, evaluation, 1, "") != 0) cs_w_oom(&j.w, "evaluation");
    json_object_put(evaluation);
    key(&j, &first, "summary");
    fputc('{', f);
    j.digits = SUMMARY_DIGITS;
    kstr(&j, &sf, "outcome", cs_outcome_name(s.outcome));
    knum(&j, &sf, "t_end_s", s.t_end_s);
    knum(&j, &sf, "max_50ms_decel_g", s.max_50ms_decel_g);
    knum(&j, &sf, "t_max_50ms_decel_s", s.t_max_50ms_decel_s);
    /* the penetration the vehicle stopped at (null if it got through or was still going), else how far
     * it had got when the run ended: beyond that */
    int final = cs_penetration_is_final(s.outcome);
    kopt(&j, &sf, "max_dynamic_penetration_m", final ? s.max_dynamic_penetration_m : NAN);
    kopt(&j, &sf, "penetration_beyond_m", final ? NAN : s.max_dynamic_penetration_m);
    knum(&j, &sf, "max_barrier_deflection_m", s.max_barrier_deflection_m);
    knum(&j, &sf, "working_width_m", s.working_width_m);
    kopt(&j, &sf, "stop_time_s", s.outcome == CS_STOPPED ? s.stop_time_s : NAN);
    kopt(&j, &sf, "exit_speed_mps", cs_outcome_exits(s.outcome) ? s.exit_speed_mps : NAN);
    kopt(&j, &sf, "exit_angle_deg", cs_outcome_exits(s.outcome) ? s.exit_angle_deg : NAN);
    kopt(&j, &sf, "first_contact_time_s", s.first_contact_time_s >= 0 ? s.first_contact_time_s : NAN);
    kint(&j, &sf, "posts_failed_left", s.posts_failed_left);
    kint(&j, &sf, "posts_failed_right", s.posts_failed_right);
    kint(&j, &sf, "posts_failed_rotation_left", s.posts_failed_rotation_left);
    kint(&j, &sf, "posts_failed_rotation_right", s.posts_failed_rotation_right);
    kint(&j, &sf, "posts_failed_shear_left", s.posts_failed_shear_left);
    kint(&j, &sf, "posts_failed_shear_right", s.posts_failed_shear_right);
    kint(&j, &sf, "posts_failed_pullout_left", s.posts_failed_pullout_left);
    kint(&j, &sf, "posts_failed_pullout_right", s.posts_failed_pullout_right);
    kint(&j, &sf, "cables_broken", s.cables_broken);
    knum(&j, &sf, "max_cable_tension_n", s.max_cable_tension_n);
    knum(&j, &sf, "initial_kinetic_energy_j", s.initial_kinetic_energy_j);
    knum(&j, &sf, "energy_balance_error", s.energy_balance_error);
    kint(&j, &sf, "solver_warnings", s.solver_warnings);
    knum(&j, &sf, "max_solver_residual", s.max_solver_residual);
    cables_and_losses(&j, &sf, state, &s);
    j.digits = PAGE_DIGITS;
    fputc('}', f);
    key(&j, &first, "scenario");
    fputc('{', f);
    sf = 1;
    knum(&j, &sf, "speed", sc->speed);
    knum(&j, &sf, "angle", sc->angle);
    knum(&j, &sf, "impact_x", sc->impact_x);
    kint(&j, &sf, "impact_at_corner", sc->impact_at_corner);
    knum(&j, &sf, "dt", sc->dt);
    knum(&j, &sf, "t_end", sc->t_end);
    knum(&j, &sf, "output_interval", sc->output_interval);
    fputc('}', f);
    key(&j, &first, "vehicle");
    fputc('{', f);
    sf = 1;
    knum(&j, &sf, "mass", v->mass);
    knum(&j, &sf, "cg_height", v->cg_height);
    knum(&j, &sf, "cg_to_front", v->cg_to_front);
    knum(&j, &sf, "front_width", v->front_width);
    knum(&j, &sf, "cg_to_rear", v->cg_to_rear);
    knum(&j, &sf, "face_bottom", v->face_bottom);
    knum(&j, &sf, "face_top", v->face_top);
    knum(&j, &sf, "wheelbase", v->wheelbase);
    knum(&j, &sf, "cg_to_front_axle", v->cg_to_front_axle);
    knum(&j, &sf, "track", v->track);
    fputc('}', f);
    /* barrier: posts [x, height, rotation limit], cables [height, Fu, pretension], anchors [x, z] */
    key(&j, &first, "barrier");
    fputs("{\"posts\":[", f);
    snprintf(j.what, sizeof j.what, "the barrier");
    for (int p = 0; p < b->post_count; p++) {
        fputs(p ? ",[" : "[", f);
        num(&j, b->posts[p].x);
        fputc(',', f);
        num(&j, b->posts[p].height);
        fputc(',', f);
        opt(&j, isfinite(b->posts[p].rotation_limit) ? b->posts[p].rotation_limit : NAN);
        fputc(']', f);
    }
    fputs("],\"cables\":[", f);
    for (int c = 0; c < b->cable_count; c++) {
        fputs(c ? ",[" : "[", f);
        num(&j, b->cables[c].height);
        fputc(',', f);
        num(&j, b->cables[c].rope.nominal_strength);
        fputc(',', f);
        num(&j, b->cables[c].pretension);
        fputc(']', f);
    }
    fputs("],\"anchors\":[[", f);
    num(&j, b->start_anchor.x);
    fputc(',', f);
    num(&j, b->start_anchor.z);
    fputs("],[", f);
    num(&j, b->end_anchor.x);
    fputc(',', f);
    num(&j, b->end_anchor.z);
    fputs("]]}", f);
    write_design(&j, &first, b);
    /* events: [t, type, element kind, element, value (SI)], then a termination event's cable end, the
     * cable a post let go and the post at whose hole a rope broke, as far as one of them is given */
    key(&j, &first, "events");
    fputc('[', f);
    for (int i = 0; i < cs_state_event_count(state); i++) {
        cs_event e_held = {.size = sizeof e_held};
        cs_state_event(state, i, &e_held, NULL);
        const cs_event *e = &e_held;
        fprintf(f, "%s\n[", i ? "," : "");
        snprintf(j.what, sizeof j.what, "an event's time or value");
        num(&j, e->t);
        fputc(',', f);
        cs_json_page_string(f, cs_event_type_name(e->type));
        fputc(',', f);
        cs_json_page_string(f, cs_element_kind_name(e->element_kind));
        fprintf(f, ",%d,", e->element);
        num(&j, e->value);
        if (e->cable_end >= 0 || e->cable >= 0 || e->post >= 0) fprintf(f, ",%d", e->cable_end);
        if (e->cable >= 0 || e->post >= 0) fprintf(f, ",%d", e->cable); /* the cable a post let go */
        if (e->post >= 0) fprintf(f, ",%d", e->post); /* the post at whose hole a rope broke */
        fputc(']', f);
    }
    fputc(']', f);
    int n = r->frame_count;
    int series_stride = n > CS_REPORT_SERIES_MAX ? (n + CS_REPORT_SERIES_MAX - 1) / CS_REPORT_SERIES_MAX : 1;
    double fit = CS_REPORT_REPLAY_BYTES / replay_frame_bytes(r);
    int replay_max = fit < CS_REPORT_REPLAY_MIN   ? CS_REPORT_REPLAY_MIN
                     : fit > CS_REPORT_REPLAY_MAX ? CS_REPORT_REPLAY_MAX
                                                  : (int)fit;
    int replay_stride = n > replay_max ? (n + replay_max - 1) / replay_max : 1;
    key(&j, &first, "series");
    write_series(&j, in, r, series_stride);
    kint(&j, &first, "replay_stride", replay_stride);
    key(&j, &first, "frames");
    write_frames(&j, r, replay_stride);
    fputs("}", f);
    if (j.w.bad) {
        snprintf(why, why_size, "report.html: %s", j.w.why);
        return -1;
    }
    if (ferror(f)) {
        snprintf(why, why_size, "report.html: write error");
        return -1;
    }
    return 0;
}

int cs_write_page(FILE *f, const unsigned char *page, size_t size, const char *title, const char *what,
                  cs_page_data_fn data, void *user, char *why, size_t why_size) {
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
            if (data(f, user, why, why_size) != 0) return -1;
            data_written = 1;
            i += nd;
        }
        from = i;
    }
    fwrite(page + from, 1, size - from, f);
    if (!data_written) {
        snprintf(why, why_size, "%s: the page has no %s marker (a broken build of report/)", what,
                 data_marker);
        return -1;
    }
    if (ferror(f)) {
        snprintf(why, why_size, "%s: write error", what);
        return -1;
    }
    return 0;
}

typedef struct report_data {
    const cs_model_input *in;
    const cs_state *state;
    const cs_record *rec;
    const cs_run_info *info;
} report_data;

static int write_report_data(FILE *f, void *user, char *why, size_t why_size) {
    const report_data *d = user;
    return cs_write_report_json(f, d->in, d->state, d->rec, d->info, why, why_size);
}

int cs_write_report_html(FILE *f, const unsigned char *page, size_t size, const cs_model_input *in,
                         const cs_state *state, const cs_record *rec, const cs_run_info *info, char *why,
                         size_t why_size) {
    report_data d = {in, state, rec, info};
    return cs_write_page(f, page, size, in->name, "report.html", write_report_data, &d, why, why_size);
}
