/* SPDX-License-Identifier: MIT */
/* Building the immutable model: check every definition, then derive what the step needs: each element's
 * model by its own file (cs_rope_derive, cs_post_derive, cs_rail_derive, cs_anchor_derive,
 * cs_vehicle_derive), the cables' end strengths, the start pose, the budgets and the largest stable step. */
#include "core/vec3.h"
#include "run/run.h"
#include "run/sized.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { CS_MAX_POSTS = 20000, CS_MAX_CABLES = 64 };
#define CS_MAX_STEPS 5.0e7
/* a soil's unit weight, N/m^3: from a loose dry sand's to a dense saturated gravel's, with room */
#define CS_SOIL_UNIT_WEIGHT_MIN 5e3
#define CS_SOIL_UNIT_WEIGHT_MAX 30e3

static int fail(cs_error *err, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fail(cs_error *err, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    cs_error_vset(err, CS_ERR_INVALID, fmt, ap);
    va_end(ap);
    return 1;
}

static int positive(double v) {
    return isfinite(v) && v > 0.0;
}
static int non_negative(double v) {
    return isfinite(v) && v >= 0.0;
}

static int check_rope(const cs_rope_def *r, int c, cs_error *err) {
    if (!positive(r->area)) return fail(err, "cable %d: rope area must be > 0", c);
    if (!positive(r->modulus)) return fail(err, "cable %d: rope modulus must be > 0", c);
    if (!positive(r->nominal_strength)) return fail(err, "cable %d: rope nominal strength must be > 0", c);
    if (!non_negative(r->diameter)) return fail(err, "cable %d: rope diameter must be >= 0", c);
    if (!(r->elastic_limit_ratio > 0.0 && r->elastic_limit_ratio <= 1.0))
        return fail(err, "cable %d: elastic limit ratio must be in (0, 1]", c);
    if (!(r->secondary_modulus_ratio > 0.0 && r->secondary_modulus_ratio <= 1.0))
        return fail(err, "cable %d: secondary modulus ratio must be in (0, 1]", c);
    double e2 = cs_rope_strain_at_strength(r);
    if (!(r->breaking_strain > e2))
        return fail(err, "cable %d: breaking strain %.4g must exceed the strain at nominal strength %.4g", c,
                    r->breaking_strain, e2);
    return 0;
}

static int check_barrier(const cs_barrier_def *b, cs_error *err) {
    if (b->cable_count < 0 || b->cable_count > CS_MAX_CABLES)
        return fail(err, "barrier: %d cables (expected 0 to %d)", b->cable_count, CS_MAX_CABLES);
    if (b->cable_count == 0 && b->post_count == 0) return fail(err, "barrier: no cables and no posts");
    if (b->post_count < 0 || b->post_count > CS_MAX_POSTS)
        return fail(err, "barrier: %d posts (expected 0 to %d)", b->post_count, CS_MAX_POSTS);
    if ((b->cable_count > 0 && !b->cables) || (b->post_count > 0 && !b->posts))
        return fail(err, "barrier: missing cable or post array");
    double lo = b->start_anchor.x, hi = b->end_anchor.x;
    if (!isfinite(lo) || !isfinite(hi) || !(hi > lo))
        return fail(err, "barrier: end anchor x %.4g m must exceed start anchor x %.4g m", hi, lo);
    for (int k = 0; k < 2; k++) {
        const cs_anchor_def *a = k ? &b->end_anchor : &b->start_anchor;
        if (!non_negative(a->z)) return fail(err, "anchor %d: height must be >= 0", k);
        if (!(a->pullout_capacity >= 0.0))
            return fail(err, "anchor %d: pullout capacity must be >= 0 (0: its weight and skin friction)", k);
        if (!non_negative(a->length) || !non_negative(a->mass))
            return fail(err, "anchor %d: length and mass must be >= 0", k);
        const cs_footing_def *f = &a->footing;
        if (!non_negative(f->diameter)) return fail(err, "anchor %d: footing diameter must be >= 0", k);
        if (f->diameter > 0.0) {
            if (!positive(f->depth)) return fail(err, "anchor %d: footing depth must be > 0", k);
            if (!positive(f->soil_pressure) || !positive(f->soil_pressure_cap))
                return fail(err, "anchor %d: soil pressure must be > 0", k);
            if (!positive(f->coeff_depth) || !non_negative(f->coeff_height))
                return fail(err, "anchor %d: Eq. 21 coefficients must be > 0", k);
            if (!(f->dynamic_factor >= 1.0 && f->dynamic_factor <= 10.0))
                return fail(err, "anchor %d: soil dynamic factor %.4g must be in [1, 10]", k,
                            f->dynamic_factor);
            if (!(f->friction_angle > 0.0 && f->friction_angle < 1.2))
                return fail(err, "anchor %d: soil friction angle must be between 0 and 69 degrees", k);
            if (f->width_scaling < CS_WIDTH_WEDGE || f->width_scaling > CS_WIDTH_NONE)
                return fail(err, "anchor %d: unknown width scaling of the soil's dynamic factor", k);
            if (!(f->residual_friction_angle > 0.0 && f->residual_friction_angle < 1.2))
                return fail(err, "anchor %d: soil residual friction angle must be between 0 and 69 degrees",
                            k);
            if (!(f->unit_weight >= CS_SOIL_UNIT_WEIGHT_MIN && f->unit_weight <= CS_SOIL_UNIT_WEIGHT_MAX))
                return fail(
                    err, "anchor %d: soil unit weight %.4g kN/m^3 must be between %.0f and %.0f kN/m^3", k,
                    f->unit_weight / 1e3, CS_SOIL_UNIT_WEIGHT_MIN / 1e3, CS_SOIL_UNIT_WEIGHT_MAX / 1e3);
            if (a->pullout_capacity == 0.0 && f->pullout_capacity == 0.0 && !positive(f->skin_friction))
                return fail(err, "anchor %d: an anchor without a pullout capacity needs skin friction > 0",
                            k);
        }
    }
    for (int p = 0; p < b->post_count; p++) {
        const cs_post_def *d = &b->posts[p];
        if (!isfinite(d->x)) return fail(err, "post %d: position is not a number", p);
        if (!(d->x > lo && d->x < hi))
            return fail(err,
                        "post %d: x %.4g m is not between the anchors (%.4g to %.4g m): an anchor inside the "
                        "barrier",
                        p, d->x, lo, hi);
        if (p > 0 && !(d->x > b->posts[p - 1].x))
            return fail(err, "post %d: x %.4g m does not exceed post %d's %.4g m (zero or negative spacing)",
                        p, d->x, p - 1, b->posts[p - 1].x);
        if (!positive(d->height)) return fail(err, "post %d: height must be > 0", p);
        const cs_section_def *s = &d->section;
        if (!positive(s->plastic_modulus) || !positive(s->inertia) || !positive(s->web_area) ||
            !positive(s->yield_stress) || !positive(s->modulus))
            return fail(err, "post %d: section properties (Zx, Ix, Aw, Fy, E) must all be > 0", p);
        if (!non_negative(s->mass_per_length))
            return fail(err, "post %d: section mass per length must be >= 0", p);
        if (!non_negative(s->fill_strength) || !non_negative(s->width) || !non_negative(s->depth) ||
            !non_negative(s->wall))
            return fail(err, "post %d: section fill strength and tube geometry must be >= 0", p);
        char why[200];
        if (cs_section_fill_problem(s, why, sizeof why)) return fail(err, "post %d: %s", p, why);
        const cs_footing_def *f = &d->footing;
        if (!positive(f->diameter) || !positive(f->depth))
            return fail(err, "post %d: footing diameter and depth must be > 0", p);
        if (!positive(f->soil_pressure) || !positive(f->soil_pressure_cap))
            return fail(err, "post %d: soil pressure must be > 0", p);
        if (!positive(f->coeff_depth) || !non_negative(f->coeff_height))
            return fail(err, "post %d: Eq. 21 coefficients must be > 0", p);
        if (!(f->pullout_capacity >= 0.0)) /* HUGE_VAL: never pulls out; 0: skin friction */
            return fail(err, "post %d: pullout capacity must be > 0 (or omitted: skin friction)", p);
        if (!(f->dynamic_factor >= 1.0 && f->dynamic_factor <= 10.0))
            return fail(err, "post %d: soil dynamic factor %.4g must be in [1, 10]", p, f->dynamic_factor);
        if (!(f->friction_angle > 0.0 && f->friction_angle < 1.2))
            return fail(err, "post %d: soil friction angle must be between 0 and 69 degrees", p);
        if (f->width_scaling < CS_WIDTH_WEDGE || f->width_scaling > CS_WIDTH_NONE)
            return fail(err, "post %d: unknown width scaling of the soil's dynamic factor", p);
        if (f->pullout_capacity == 0.0 && !positive(f->skin_friction))
            return fail(err, "post %d: a footing without a pullout capacity needs skin friction > 0", p);
        if (!(d->rotation_limit > 0.0 && d->rotation_limit <= 0.5 * CS_PI + 1e-12) ||
            !(f->rotation_limit > 0.0 && f->rotation_limit < 1.5))
            return fail(err,
                        "post %d: rotation limits must be above 0 and at most 90 deg (a post's) or 1.5 rad "
                        "(its footing's)",
                        p);
        if (d->attachment < CS_ATTACH_THROUGH || d->attachment > CS_ATTACH_BRACKET)
            return fail(err, "post %d: unknown attachment %d", p, (int)d->attachment);
        if (!non_negative(d->release_force)) return fail(err, "post %d: release force must be >= 0", p);
        if (d->release_force > 0.0 && cs_attachment_release_force(d->attachment) == 0.0)
            return fail(
                err, "post %d: release force must be left out (threaded and clamped cables are never let go)",
                p);
        if (!non_negative(d->lateral_release_force))
            return fail(err, "post %d: lateral release force must be >= 0", p);
        if (d->lateral_release_force > 0.0 && cs_attachment_lateral_release_force(d->attachment) == 0.0)
            return fail(
                err,
                "post %d: lateral release force must be left out (only keyway bolts and brackets have one)",
                p);
        if (d->face != CS_FACE_ATTACK && d->face != CS_FACE_PROTECTED)
            return fail(err, "post %d: unknown face %d", p, (int)d->face);
        if (d->face != CS_FACE_ATTACK && cs_attachment_lateral_release_force(d->attachment) == 0.0)
            return fail(
                err, "post %d: face must be left out (only keyway bolts and brackets are fixed to one)", p);
    }
    if (b->rail_count < 0 || b->rail_count > CS_MAX_CABLES || (b->rail_count > 0 && !b->rails))
        return fail(err, "barrier: %d rails (expected 0 to %d)", b->rail_count, CS_MAX_CABLES);
    for (int r = 0; r < b->rail_count; r++) {
        const cs_rail_def *d = &b->rails[r];
        if (!positive(d->height)) return fail(err, "rail %d: height must be > 0", r);
        if (!positive(d->area) || !positive(d->inertia) || !positive(d->yield_stress) ||
            !positive(d->modulus))
            return fail(err, "rail %d: area, inertia, yield stress and modulus must be > 0", r);
        if (!non_negative(d->mass_per_length)) return fail(err, "rail %d: mass per length must be >= 0", r);
        for (int p = 0; p < b->post_count; p++)
            if (d->height > b->posts[p].height)
                return fail(err, "rail %d: height %.4g m is above the top of post %d (%.4g m)", r, d->height,
                            p, b->posts[p].height);
    }
    for (int c = 0; c < b->cable_count; c++) {
        const cs_cable_def *d = &b->cables[c];
        if (!positive(d->height)) return fail(err, "cable %d: height must be > 0", c);
        for (int p = 0; p < b->post_count; p++)
            if (d->height > b->posts[p].height)
                return fail(err, "cable %d: height %.4g m is above the top of post %d (%.4g m)", c, d->height,
                            p, b->posts[p].height);
        if (!non_negative(d->pretension)) return fail(err, "cable %d: pretension must be >= 0", c);
        if (!non_negative(d->post_friction) || d->post_friction > 2.0)
            return fail(err, "cable %d: post friction must be in [0, 2]", c);
        if (!(d->termination_efficiency >= 0.0 && d->termination_efficiency <= 1.0))
            return fail(err, "cable %d: termination efficiency must be in (0, 1] (0: the fitting's own)", c);
        if (!non_negative(d->slip_load) || !non_negative(d->slip_travel))
            return fail(err, "cable %d: slip load and travel must be >= 0", c);
        if (d->termination < CS_TERMINATION_CLIPS || d->termination > CS_TERMINATION_WEDGE)
            return fail(err, "cable %d: unknown termination", c);
        for (int k = 0; k < 2; k++) {
            const cs_cable_end_def *e = &d->ends[k];
            const char *at = k ? "end" : "start";
            if (!(e->termination_efficiency >= 0.0 && e->termination_efficiency <= 1.0))
                return fail(err,
                            "cable %d: termination efficiency at the %s anchor must be in (0, 1] (0: its "
                            "fitting's own)",
                            c, at);
            if (e->termination < CS_TERMINATION_AS_CABLE || e->termination > CS_TERMINATION_WEDGE)
                return fail(err, "cable %d: unknown termination at the %s anchor", c, at);
            if (!non_negative(e->slip_load) || !non_negative(e->slip_travel))
                return fail(err, "cable %d: slip load and travel at the %s anchor must be >= 0", c, at);
            double travel, slip = cs_cable_end_slip(d, k, &travel);
            if (slip > 0.0 && !(travel > 0.0))
                return fail(err, "cable %d: the fitting at the %s anchor slips but has no slip travel", c,
                            at);
            if (slip > 0.0 && slip <= d->pretension)
                return fail(
                    err,
                    "cable %d: the fitting at the %s anchor slips at %.4g N, not above the pretension "
                    "(%.4g N): it could not be tensioned",
                    c, at, slip, d->pretension);
        }
        if (check_rope(&d->rope, c, err)) return 1;
        if (d->pretension >= d->rope.elastic_limit_ratio * d->rope.nominal_strength)
            return fail(err, "cable %d: pretension exceeds the rope's elastic limit", c);
    }
    return 0;
}

/* The range of road vehicles, with room: a 10-kg cart to a 500-t load, no dimension over 50 m. */
#define CS_VEHICLE_MASS_MIN 10.0
#define CS_VEHICLE_MASS_MAX 5e5
#define CS_VEHICLE_SIZE_MAX 50.0

static int check_vehicle(const cs_vehicle_def *v, cs_error *err) {
    if (!(v->mass >= CS_VEHICLE_MASS_MIN && v->mass <= CS_VEHICLE_MASS_MAX))
        return fail(err, "vehicle: mass %.4g kg is outside %.0f kg to %.0f t, the range of road vehicles",
                    v->mass, CS_VEHICLE_MASS_MIN, CS_VEHICLE_MASS_MAX / 1e3);
    for (int i = 0; i < 3; i++)
        if (!positive(v->inertia[i]) || !isfinite(v->inertia[i]))
            return fail(err, "vehicle: inertia must be > 0");
    const double sizes[] = {v->cg_height, v->cg_to_front, v->front_width,
                            v->wheelbase, v->track,       v->cg_to_rear};
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; i++)
        if (!(sizes[i] > 0.0 && sizes[i] <= CS_VEHICLE_SIZE_MAX))
            return fail(
                err,
                "vehicle: CG height, CG to front and to rear, front width, wheelbase and track must be "
                "above 0 and at most %.0f m (one is %.4g m)",
                CS_VEHICLE_SIZE_MAX, sizes[i]);
    if (!non_negative(v->face_bottom) || !(v->face_top > v->face_bottom))
        return fail(err, "vehicle: face top must be above face bottom >= 0");
    if (!(v->cg_to_front_axle > 0.0 && v->cg_to_front_axle < v->wheelbase))
        return fail(err, "vehicle: CG must lie between the axles");
    if (!(v->cg_to_front > v->cg_to_front_axle))
        return fail(err, "vehicle: the front face must be ahead of the front axle");
    if (!(v->cg_to_rear >= v->wheelbase - v->cg_to_front_axle))
        return fail(
            err,
            "vehicle: the rear must be behind the rear axle (CG to rear >= wheelbase - CG to front axle)");
    if (!non_negative(v->side_bottom) || !(v->side_top > v->side_bottom))
        return fail(err, "vehicle: side top must be above side bottom >= 0");
    if (!positive(v->tyre_static_deflection) || !non_negative(v->tyre_damping_ratio) ||
        !non_negative(v->rolling_resistance) || !non_negative(v->tyre_friction) ||
        !non_negative(v->face_friction))
        return fail(err, "vehicle: tyre and friction parameters must be >= 0 (static deflection > 0)");
    if (!(v->wheel_radius > v->tyre_static_deflection &&
          v->wheel_radius - v->tyre_static_deflection < v->side_top))
        return fail(err, "vehicle: the wheel radius must exceed the tyre's static deflection, and the axle "
                         "(radius less deflection) lie below the side's top");
    if (!non_negative(v->rim_radius) || !(v->rim_radius < v->wheel_radius - v->tyre_static_deflection))
        return fail(err, "vehicle: the rim radius must be >= 0 (0: none) and below the axle's height at rest "
                         "(wheel radius less the tyre's static deflection)");
    if (v->crush_point_count < 2 || v->crush_point_count > CS_MAX_CRUSH_POINTS)
        return fail(err, "vehicle: crush curve needs 2 to %d points", CS_MAX_CRUSH_POINTS);
    if (v->crush_deformation[0] != 0.0 || v->crush_force[0] != 0.0)
        return fail(err, "vehicle: crush curve must start at (0 m, 0 N)");
    for (int i = 1; i < v->crush_point_count; i++) {
        if (!(v->crush_deformation[i] > v->crush_deformation[i - 1]))
            return fail(err, "vehicle: crush deformation must increase (point %d)", i);
        if (!(v->crush_force[i] >= v->crush_force[i - 1]) || !isfinite(v->crush_force[i]))
            return fail(err, "vehicle: crush force must not decrease (point %d)", i);
    }
    if (!(v->crush_force[v->crush_point_count - 1] > 0.0))
        return fail(err, "vehicle: crush force must rise above 0");
    if (!positive(v->crush_unload_stiffness))
        return fail(err, "vehicle: crush unloading stiffness must be > 0");
    return 0;
}

static int check_scenario(const cs_scenario_def *s, cs_error *err) {
    if (!non_negative(s->speed) || s->speed > 100.0)
        return fail(err, "scenario: speed must be in [0, 100] m/s");
    if (!(s->angle > 0.0 && s->angle < CS_PI))
        return fail(err, "scenario: angle must be between 0 and 180 degrees (exclusive)");
    if (!isfinite(s->impact_x)) return fail(err, "scenario: impact point is not a number");
    if (!non_negative(s->start_gap)) return fail(err, "scenario: start gap must be >= 0");
    if (!positive(s->dt) || s->dt > 0.01) return fail(err, "scenario: time step must be in (0, 10 ms]");
    if (!positive(s->t_end) || s->t_end < s->dt)
        return fail(err, "scenario: end time must be at least one step");
    if (s->t_end / s->dt > CS_MAX_STEPS)
        return fail(err, "scenario: %.3g steps (end time / time step) exceed the limit of %.0g",
                    s->t_end / s->dt, CS_MAX_STEPS);
    if (!non_negative(s->output_interval)) return fail(err, "scenario: output interval must be >= 0");
    if (!(s->crush_tolerance > 0.0 && s->crush_tolerance < 1.0))
        return fail(err, "scenario: crush tolerance must be in (0, 1)");
    if (!(s->solver_tolerance > 0.0 && s->solver_tolerance < 0.1))
        return fail(err, "scenario: solver tolerance must be in (0, 0.1)");
    if (!(s->solve_budget >= 0.0 && s->solve_budget <= 1e6))
        return fail(err, "scenario: solve budget %.4g must be between 0 (the default) and 1e6 a step",
                    s->solve_budget);
    if (!(s->max_steps >= 0.0 && s->max_steps <= 1e9))
        return fail(err, "scenario: max steps %.4g must be between 0 (the default, 1e7) and 1e9",
                    s->max_steps);
    if (s->solver_max_sweeps < 1 || s->solver_max_sweeps > 100000)
        return fail(err, "scenario: solver sweeps must be in [1, 100000]");
    if (!non_negative(s->stop_speed) ||
        (s->speed > 0.0 && !(s->stop_speed <= CS_STOP_SPEED_SHARE * s->speed)))
        return fail(err,
                    "scenario: stop speed %.4g m/s must be from 0 to a tenth of the impact speed, %.4g m/s",
                    s->stop_speed, CS_STOP_SPEED_SHARE * s->speed);
    if (!non_negative(s->gravity) || s->gravity > 100.0)
        return fail(err, "scenario: gravity must be in [0, 100]");
    return 0;
}

/* Largest stable step of the vehicle against the stiffest span a cable can offer it: half the
 * closest support spacing, all cables in parallel (explicit integration: dt < 2 / omega). */
static double critical_step(const cs_model *m, const cs_barrier_def *b) {
    double gap = b->end_anchor.x - b->start_anchor.x, prev = b->start_anchor.x;
    for (int p = 0; p <= b->post_count; p++) {
        double x = p < b->post_count ? b->posts[p].x : b->end_anchor.x;
        if (x - prev < gap) gap = x - prev;
        prev = x;
    }
    double k = 0.0;
    for (int c = 0; c < m->cable_count; c++)
        k += m->cables[c].rope.ea / (0.5 * gap);
    const cs_vehicle_def *v = &m->vehicle.def;
    double r = 0.5 * v->front_width, mass = v->mass;
    double rot[3] = {v->inertia[0] / (r * r), v->inertia[1] / (v->cg_to_front * v->cg_to_front),
                     v->inertia[2] / (r * r)};
    for (int i = 0; i < 3; i++)
        if (rot[i] < mass) mass = rot[i];
    return 2.0 * sqrt(mass / k);
}

static cs_model *model_create(const cs_barrier_def *barrier, const cs_vehicle_def *vehicle,
                              const cs_scenario_def *scenario, cs_error *err);

cs_model *cs_model_create(const cs_barrier_def *barrier, const cs_vehicle_def *vehicle,
                          const cs_scenario_def *scenario, cs_error *err) {
    if (err) err->status = CS_OK, err->message[0] = '\0';
    if (!barrier || !vehicle || !scenario) {
        fail(err, "missing barrier, vehicle or scenario definition");
        return NULL;
    }
    cs_defs defs; /* the caller's definitions at this library's sizes (def.h) */
    cs_model *m = NULL;
    if (cs_defs_take(&defs, barrier, vehicle, scenario, err) == 0)
        m = model_create(&defs.barrier, &defs.vehicle, &defs.scenario, err);
    cs_defs_free(&defs);
    return m;
}

static cs_model *model_create(const cs_barrier_def *barrier, const cs_vehicle_def *vehicle,
                              const cs_scenario_def *scenario, cs_error *err) {
    if (check_barrier(barrier, err) || check_vehicle(vehicle, err) || check_scenario(scenario, err))
        return NULL;

    cs_model *m = calloc(1, sizeof *m);
    if (!m) goto oom;
    m->cable_count = barrier->cable_count;
    m->post_count = barrier->post_count;
    m->max_nodes = m->post_count + 2 + CS_CORNERS; /* posts, anchors, corners */
    m->rail_count = barrier->rail_count;
    m->rails = calloc((size_t)(m->rail_count ? m->rail_count : 1), sizeof *m->rails);
    m->cables = calloc((size_t)(m->cable_count ? m->cable_count : 1), sizeof *m->cables);
    m->posts = calloc((size_t)(m->post_count ? m->post_count : 1), sizeof *m->posts);
    if (!m->cables || !m->posts || !m->rails) goto oom;
    for (int r = 0; r < m->rail_count; r++) {
        double shortest = HUGE_VAL;
        for (int p = 0; p + 1 < m->post_count; p++)
            shortest = fmin(shortest, barrier->posts[p + 1].x - barrier->posts[p].x);
        cs_rail_derive(&barrier->rails[r], shortest, &m->rails[r]);
    }

    for (int c = 0; c < m->cable_count; c++) {
        const cs_cable_def *d = &barrier->cables[c];
        cs_cable_model *cm = &m->cables[c];
        cm->z = d->height;
        cm->pretension = d->pretension;
        cm->mu_post = d->post_friction;
        cs_rope_derive(&d->rope, scenario->gravity, &cm->rope);
        cm->hole_strength = d->hole_efficiency * cm->rope.fu;
        cm->diameter = d->rope.diameter > 0.0 ? d->rope.diameter : sqrt(4.0 * d->rope.area / CS_PI);
        for (int k = 0; k < 2; k++) {
            cm->termination_strength[k] = cs_cable_end_efficiency(d, k, NULL) * cm->rope.fu;
            cm->slip_load[k] = cs_cable_end_slip(d, k, &cm->slip_travel[k]);
        }
    }
    /* the load height of every post: its cables' mean height, or for a barrier of posts alone
     * (bollards, a bogie test) the height where the vehicle's face strikes them */
    double mean_z = 0.0;
    for (int c = 0; c < m->cable_count; c++)
        mean_z += m->cables[c].z / m->cable_count;
    if (m->cable_count == 0) mean_z = vehicle->face_bottom > 0.05 ? vehicle->face_bottom : 0.05;
    for (int p = 0; p < m->post_count; p++) {
        cs_post_derive(barrier, p, mean_z, m, &m->posts[p]);
    }
    cs_anchor_derive(&barrier->start_anchor, scenario->gravity, &m->anchors[0]);
    cs_anchor_derive(&barrier->end_anchor, scenario->gravity, &m->anchors[1]);
    m->scenario = *scenario;
    cs_vehicle_derive(vehicle, scenario->gravity, &m->vehicle);

    double dt_crit = critical_step(m, barrier);
    if (scenario->dt > dt_crit) {
        fail(err, "scenario: time step %.3g ms is too large for the stiffest cable span; use at most %.3g ms",
             scenario->dt * 1e3, dt_crit * 1e3);
        cs_model_free(m);
        return NULL;
    }

    /* Start pose: the face centre travels along dir to (impact_x, 0) (or the leading corner does, at the
     * face centre's offset (w/2)/sin(theta) before it along the line); every face corner starts
     * start_gap short of the cable line. */
    double th = scenario->angle;
    v3_set(m->dir, cos(th), sin(th), 0.0);
    m->start_yaw = th;
    double yc = -scenario->start_gap - 0.5 * vehicle->front_width * fabs(cos(th));
    double centre_x;
    cs_scenario_impact_points(scenario, vehicle->front_width, &centre_x, NULL);
    double xc = centre_x + m->dir[0] * yc / m->dir[1];
    v3_set(m->start_pos, xc - m->dir[0] * vehicle->cg_to_front, yc - m->dir[1] * vehicle->cg_to_front,
           vehicle->cg_height);
    m->solve_budget = (scenario->solve_budget > 0.0 ? scenario->solve_budget : CS_SOLVE_BUDGET) *
                      ceil(scenario->t_end / scenario->dt);
    m->work_rows = 2.0 * m->post_count + (double)m->cable_count * m->post_count + 4.0 + 1.0;
    m->work_budget = m->solve_budget * CS_SOLVE_WORK * m->work_rows;
    m->max_steps = scenario->max_steps > 0.0 ? floor(scenario->max_steps) : CS_MAX_STEPS_DEFAULT;
    m->window_steps = (int)lround(0.05 / scenario->dt);
    if (m->window_steps < 1) m->window_steps = 1;
    /* every step within the window of the newest: floor(W / dt) steps back, and the newest */
    m->loss_steps = (int)floor(CS_SUDDEN_LOSS_WINDOW / scenario->dt * (1.0 + 1e-9)) + 1;
    /* each post and cable fails in a few ways, once; slots and hooks let each cable go once per post */
    m->event_capacity = 4 * m->post_count + 6 * m->cable_count + m->post_count * m->cable_count + 16;
    return m;

oom:
    cs_model_free(m);
    cs_out_of_memory(err);
    return NULL;
}

void cs_model_free(cs_model *m) {
    if (!m) return;
    free(m->rails);
    free(m->cables);
    free(m->posts);
    free(m);
}

int cs_model_cable_count(const cs_model *m) {
    return m->cable_count;
}
int cs_model_post_count(const cs_model *m) {
    return m->post_count;
}
int cs_model_path_capacity(const cs_model *m) {
    return m->max_nodes;
}
double cs_model_post_x(const cs_model *m, int p) {
    return m->posts[p].x;
}
double cs_model_cable_height(const cs_model *m, int c) {
    return m->cables[c].z;
}
double cs_model_footing_capacity(const cs_model *m, int p, double h) {
    return cs_footing_capacity(&m->posts[p].footing, h);
}
const cs_vehicle_def *cs_model_vehicle(const cs_model *m) {
    return &m->vehicle.def;
}
const cs_scenario_def *cs_model_scenario(const cs_model *m) {
    return &m->scenario;
}
