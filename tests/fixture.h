/* SPDX-License-Identifier: MIT */
/* Test fixtures: an APS3-like barrier and the 15,000-lb truck, built in C from the design data of
 * data/aps-crash-tests.md and the assumptions of docs/assumptions.md (the same numbers as
 * examples/aps3.yaml and data/vehicles.yaml, so the engine tests need no loader). */
#ifndef CS_TEST_FIXTURE_H
#define CS_TEST_FIXTURE_H

#include "cablesim/cablesim.h"

#include <math.h>

#define FT 0.3048
#define IN 0.0254
#define KIP 4448.2216152605
#define KSI 6894757.293168
#define PSF 47.88025898033584
#define MPH 0.44704
#define LB 0.45359237
#define STEEL_DENSITY 7850.0 /* kg/m^3 */

typedef struct fixture {
    cs_cable_def cables[2];
    cs_post_def posts[64];
    cs_rail_def rails[4];
    cs_barrier_def barrier;
    cs_vehicle_def vehicle;
    cs_scenario_def scenario;
} fixture;

/* A603 structural wire rope by the diameter-squared rule of data/wire-rope.csv. */
static inline cs_rope_def fixture_rope(double diameter_in) {
    cs_rope_def r = cs_default_rope_def();
    r.area = 0.471 * diameter_in * diameter_in * IN * IN;
    r.nominal_strength = 91.4 * diameter_in * diameter_in * KIP;
    r.modulus = 20000.0 * KSI;
    r.diameter = diameter_in * IN;
    r.mass_per_length = 1.67 * diameter_in * diameter_in * LB / FT; /* 1.67 lb/ft at 1 in */
    return r;
}

/* Cold-formed 1.75 x 4 in I-beam (assumed 0.105-in plate, double web) and HSS 4x4x1/8. */
static inline cs_section_def fixture_ibeam(void) {
    cs_section_def s = cs_default_section_def();
    double b = 1.75, d = 4.0, tf = 0.105, tw = 0.21, h = d - 2 * tf;
    s.plastic_modulus = (2 * b * tf * (d - tf) / 2 + tw * h * h / 4) * IN * IN * IN;
    s.inertia = (b * d * d * d - (b - tw) * h * h * h) / 12 * pow(IN, 4);
    s.web_area = d * tw * IN * IN;
    s.yield_stress = 50 * KSI;
    s.modulus = 29000 * KSI;
    s.mass_per_length = (2 * b * tf + h * tw) * IN * IN * STEEL_DENSITY;
    return s;
}

static inline cs_section_def fixture_hss(void) {
    cs_section_def s = cs_default_section_def();
    double b = 4.0, t = 0.93 * 0.125, bi = b - 2 * t;
    s.plastic_modulus = (b * b * b - bi * bi * bi) / 4 * IN * IN * IN;
    s.inertia = (pow(b, 4) - pow(bi, 4)) / 12 * pow(IN, 4);
    s.web_area = 2 * b * t * IN * IN;
    s.yield_stress = 46 * KSI;
    s.modulus = 29000 * KSI;
    s.mass_per_length = (b * b - bi * bi) * IN * IN * STEEL_DENSITY;
    s.width = s.depth = b * IN;
    s.wall = t * IN;
    return s;
}

static inline cs_footing_def fixture_footing(double b_ft, double d_ft, double pullout_kip) {
    cs_footing_def f = cs_default_footing_def();
    f.diameter = b_ft * FT;
    f.depth = d_ft * FT;
    f.soil_pressure = 8000 * PSF;
    f.pullout_capacity = pullout_kip * KIP;
    return f;
}

/* The ASTM F2656 M / SD-STD-02.01 truck of data/vehicles.yaml. */
static inline cs_vehicle_def fixture_truck(void) {
    cs_vehicle_def v = cs_default_vehicle_def();
    v.mass = 15000 * LB;
    double L = 7.5, W = 2.4, H = 2.5;
    v.inertia[0] = v.mass * (W * W + H * H) / 12;
    v.inertia[1] = v.mass * (L * L + H * H) / 12;
    v.inertia[2] = v.mass * (L * L + W * W) / 12;
    v.cg_height = 1.0;
    v.cg_to_front = 3.4;
    v.front_width = 2.4;
    v.face_bottom = 0.45;
    v.face_top = 1.45;
    v.front_to_cargo_bed = 2.6;
    v.cg_to_rear = L - v.cg_to_front;
    v.side_bottom = 0.45;
    v.side_top = 2.5;
    v.wheelbase = 4.6;
    v.cg_to_front_axle = 2.3;
    v.track = 1.9;
    /* crush: shape scaled so the area to 0.9 m is the kinetic energy at 39.25 mph */
    double ke = 0.5 * v.mass * pow(39.25 * MPH, 2), shape_area = 0.6;
    double fmax = ke / shape_area;
    double d[] = {0, 0.1, 0.3, 0.6, 0.9, 1.0}, f[] = {0, 0.4, 0.6, 0.8, 1.0, 3.0};
    v.crush_point_count = 6;
    for (int i = 0; i < 6; i++)
        v.crush_deformation[i] = d[i], v.crush_force[i] = f[i] * fmax;
    return v;
}

/* The APS barriers' four rails (data/rails.yaml: open trapezoid 2.5 x 2 in, 12 gauge, Fy 50 ksi) at 1,
 * 2.83, 4 and 7 ft. */
static inline void fixture_rails(fixture *fx) {
    const double z[4] = {1.0, 2.83, 4.0, 7.0};
    for (int r = 0; r < 4; r++) {
        cs_rail_def *d = &fx->rails[r];
        *d = cs_default_rail_def();
        d->height = z[r] * FT;
        d->area = 0.693 * IN * IN;
        d->inertia = 0.307 * IN * IN * IN * IN;
        d->yield_stress = 50 * KSI;
        d->modulus = 29000 * KSI;
        d->mass_per_length = 2.36 * LB / FT;
    }
    fx->barrier.rails = fx->rails;
    fx->barrier.rail_count = 4;
}

/* APS3: 136 ft, dead-men (3 x 5 ft concrete shafts, the ropes tied at grade) at both ends, posts every 8 ft
 * from 8 to 128 ft, intermediate anchor posts (HSS in 3 x 5 ft footings) at 56 and 80 ft, line posts in 9-in
 * x 3-ft footings, two 1.75-in cables at 2.83 and 4 ft, impact 40 mph head-on at mid-barrier (68 ft). */
static inline void fixture_aps3(fixture *fx) {
    for (int c = 0; c < 2; c++) {
        cs_cable_def *cd = &fx->cables[c];
        *cd = cs_default_cable_def();
        cd->height = (c == 0 ? 2.83 : 4.0) * FT;
        cd->pretension = 5 * KIP;
        cd->rope = fixture_rope(1.75);
    }
    int n = 0;
    for (int k = 1; k <= 16; k++) {
        cs_post_def *p = &fx->posts[n++];
        *p = cs_default_post_def();
        p->x = 8.0 * k * FT;
        p->height = 7.0 * FT;
        int anchor = (k == 7 || k == 10);
        p->section = anchor ? fixture_hss() : fixture_ibeam();
        p->footing = anchor ? fixture_footing(3.0, 5.0, 50.0) : fixture_footing(0.75, 3.0, 20.0);
    }
    fx->barrier = cs_default_barrier_def();
    fx->barrier.cable_count = 2;
    fx->barrier.cables = fx->cables;
    fx->barrier.post_count = n;
    fx->barrier.posts = fx->posts;
    fx->barrier.start_anchor.x = 0.0;
    fx->barrier.end_anchor.x = 136.0 * FT;
    fx->barrier.start_anchor.footing = fx->barrier.end_anchor.footing = fixture_footing(3.0, 5.0, 0.0);
    fx->vehicle = fixture_truck();
    fx->scenario = cs_default_scenario_def();
    fx->scenario.speed = 40 * MPH;
    fx->scenario.impact_x = 68 * FT;
}

#endif
