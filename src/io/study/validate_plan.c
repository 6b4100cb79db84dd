/* SPDX-License-Identifier: MIT */
/* The validation suite's cases and their queue: the crash tests as their files stand, under each reading
 * of what their design data leaves open, at each refinement and at each end of each uncertain input's
 * range and over all at once; the roadside tests and their readings; the bogie tests. Every simulation is
 * queued as a job, the costliest first (validate.h). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/loader.h"
#include "cablesim/units.h"
#include "status.h"
#include "study/sweep.h"
#include "study/validate.h"

const char *const cs_validate_crash_names[CS_VAL_CRASH] = {"aps1", "aps3", "aps4"};
const char *const cs_validate_road_names[CS_VAL_ROAD] = {"rs1", "rs2", "rs3", "rs4", "rs5", "rs6"};

/* Queue a run of m (NULL: not built); its cost: its steps to t_end times its posts. */
static int add_job(cs_validate_suite *s, cs_model *m) {
    cs_validate_job *j = &s->jobs[s->count];
    memset(j, 0, sizeof *j);
    j->model = m;
    if (m) {
        const cs_scenario_def *sc = cs_model_scenario(m);
        j->cost = sc->t_end / sc->dt * cs_model_post_count(m);
    }
    return s->count++;
}

/* Load examples/<name>.yaml with overrides ("PATH=VALUE", NULL-terminated). Returns 0, or -1 (errors
 * kept). */
static int load_example(cs_validate_suite *s, const char *name, const char *const *sets, cs_model_input *in) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.yaml", s->examples, name);
    cs_loader_reset(s->loader);
    for (int i = 0; sets && sets[i]; i++)
        cs_loader_set(s->loader, sets[i]);
    return cs_loader_load(s->loader, path, in);
}

static int load_crash(cs_validate_suite *s, int k, const char *const *sets, cs_model_input *in) {
    return load_example(s, cs_validate_crash_names[k], sets, in);
}

/* Queue a run of what load_crash returned rc and in for; the loader's errors printed if not built. */
static int add_loaded(cs_validate_suite *s, int rc, const cs_model_input *in) {
    cs_model *m = rc == 0 ? cs_loader_build(s->loader, in) : NULL;
    if (!m) cs_loader_print_errors(s->loader, s->opts.err);
    return add_job(s, m);
}

/* ---- bogie tests (the paper's Table 2: data/validation/post-bogie-tests.csv) ---- */

/* The rig's bogie struck the rig's post (a library part) at speed mph, with the given footing, no cable. */
cs_model *cs_validate_bogie_model(cs_loader *l, const cs_bogie_rig *rig, const cs_footing_def *footing,
                                  double mph, cs_error *err) {
    cs_post_def post = cs_default_post_def();
    cs_loader_reset(l); /* the library's section, not a loaded model file's */
    if (cs_loader_part(l, CS_PART_SECTION, rig->section, &post.section) != 0) {
        cs_error_set(err, CS_ERR_INVALID, "no section '%s' in the parts library", rig->section);
        return NULL;
    }
    post.height = 1.0;
    post.footing = *footing;
    cs_barrier_def b = cs_default_barrier_def();
    b.cable_count = 0, b.post_count = 1, b.posts = &post;
    b.start_anchor.x = -10.0, b.end_anchor.x = 10.0;
    cs_vehicle_def v = cs_default_vehicle_def();
    v.mass = rig->mass_lb * CS_LB;
    v.inertia[0] = v.mass * (1.5 * 1.5 + 1.0) / 12, v.inertia[1] = v.mass * (3.0 * 3.0 + 1.0) / 12;
    v.inertia[2] = v.mass * (3.0 * 3.0 + 1.5 * 1.5) / 12; /* a 3 x 1.5 x 1 m box */
    double head = rig->head_height_in * CS_IN, radius = 0.5 * rig->head_diameter_in * CS_IN;
    v.cg_height = 0.6, v.cg_to_front = 2.0, v.front_width = 2.0 * radius;
    v.face_bottom = head - radius, v.face_top = head + radius;
    v.wheelbase = 2.0, v.cg_to_front_axle = 1.0, v.track = 1.5, v.cg_to_rear = 1.0;
    v.side_bottom = v.face_bottom, v.side_top = v.face_top;
    v.crush_point_count = 2, v.crush_deformation[1] = 0.001, v.crush_force[1] = 1e7; /* rigid head */
    cs_scenario_def sc = cs_default_scenario_def();
    sc.speed = mph * CS_MPH, sc.impact_x = 0.0, sc.t_end = 1.0;
    return cs_model_create(&b, &v, &sc, err);
}

/* A footing of width b and depth d in soil of S1 = s1_psf (the default dynamic factor and skin friction,
 * docs/assumptions.md); no pullout capacity given: it pulls out at its skin friction's. */
cs_footing_def cs_validate_soil_footing(double b, double d, double s1_psf) {
    cs_footing_def f = cs_default_footing_def();
    f.diameter = b, f.depth = d, f.soil_pressure = s1_psf * CS_PSF;
    return f;
}

/* The post driven in soil: Eq. 21 with its flange as B, the default dynamic factor, and no pullout
 * capacity (its skin friction). */
static int add_bogie(cs_validate_suite *s, const cs_bogie_test *t) {
    const cs_bogie_rig *rig = &s->data.rig;
    cs_footing_def f =
        cs_validate_soil_footing(rig->flange_in * CS_IN, t->embedment_mm * 1e-3, rig->soil_psf);
    cs_error err = {0};
    cs_model *m = cs_validate_bogie_model(s->loader, rig, &f, t->mph, &err);
    if (!m) fprintf(s->opts.err, "cablesim validate: %s: %s\n", t->name, err.message);
    return add_job(s, m);
}

/* ---- convergence and sensitivity ---- */
/* A refinement: each crash test run at every value of one scenario setting (field: its offset in
 * cs_scenario_def, a double). */
const cs_validate_refinement cs_validate_refinements[CS_VAL_REFINE] = {
    {"dt", "dt", offsetof(cs_scenario_def, dt), 4, {"0.5 ms", "0.25 ms", "0.1 ms", "0.05 ms"}},
    {"solver_tolerance",
     "solver tolerance",
     offsetof(cs_scenario_def, solver_tolerance),
     4,
     {"1e-4", "1e-5", "1e-6", "1e-7"}},
};

static double scenario_value(const cs_scenario_def *sc, size_t field) {
    return *(const double *)((const char *)sc + field);
}

/* Queue refinement t of crash test k at every value; a value the file's scenario already has (compared
 * as loaded) reads the baseline job instead of running it again. */
static void add_refinement(cs_validate_suite *s, int t, int k) {
    for (int d = 0; d < cs_validate_refinements[t].count; d++) {
        char set[96];
        snprintf(set, sizeof set, "scenario.%s=%s", cs_validate_refinements[t].setting,
                 cs_validate_refinements[t].values[d]);
        const char *sets[] = {set, NULL};
        cs_model_input in = {.size = sizeof in};
        int rc = load_crash(s, k, sets, &in);
        size_t f = cs_validate_refinements[t].field;
        int same = rc == 0 && s->base_loaded[k] &&
                   scenario_value(&in.scenario, f) == scenario_value(&s->base_scenario[k], f);
        if (same && s->base[k] < 0) s->base[k] = add_loaded(s, rc, &in);
        s->refine[t][k][d] = same ? s->base[k] : add_loaded(s, rc, &in);
    }
}

/* The inputs the paper does not give, each over its range (in unit); a value of cables[0] is given to
 * cables[1] as well. */
const cs_validate_input cs_validate_inputs[CS_VAL_INPUTS] = {
    {"impact speed 38-42 mph", "scenario.speed", "mph", 38.0, 42.0},
    {"soil S1 6000-8000 psf", "barrier.soil.soil_pressure", "psf", 6000.0, 8000.0},
    {"line-post yield stress 45-55 ksi", "barrier.posts[0].yield_stress", "ksi", 45.0, 55.0},
    {"cable-post friction 0.10-0.20", "barrier.cables[0].post_friction", "", 0.10, 0.20},
    {"pretension 2-8 kip", "barrier.cables[0].pretension", "kip", 2.0, 8.0},
    {"line-post mass 0-15 lb/ft (massless to five times its steel)", "barrier.posts[0].mass_per_length",
     "lb/ft", 0.0, 15.0},
};

/* "PATH=VALUE UNIT" of input i at fraction u of its range. */
void cs_validate_input_text(int i, double u, char *buf, size_t n) {
    snprintf(buf, n, "%s=%.4g%s%s", cs_validate_inputs[i].path,
             cs_validate_inputs[i].lo + u * (cs_validate_inputs[i].hi - cs_validate_inputs[i].lo),
             *cs_validate_inputs[i].unit ? " " : "", cs_validate_inputs[i].unit);
}

/* Queue crash test k with input `only` at fraction u[only] of its range and the others as the file has
 * them, or (only < 0) every input i at once at its fraction u[i]. */
static int add_inputs(cs_validate_suite *s, int k, int only, const double *u) {
    char buf[2 * CS_VAL_INPUTS][96];
    const char *sets[2 * CS_VAL_INPUTS + 1];
    int n = 0;
    for (int i = 0; i < CS_VAL_INPUTS; i++) {
        if (only >= 0 && i != only) continue;
        cs_validate_input_text(i, u[i], buf[n], sizeof buf[n]);
        sets[n] = buf[n];
        n++;
        const char *cable = strstr(cs_validate_inputs[i].path, "cables[0]");
        if (cable) { /* the same value on the second cable */
            memcpy(buf[n], buf[n - 1], sizeof buf[n]);
            buf[n][cable - cs_validate_inputs[i].path + 7] = '1';
            sets[n] = buf[n];
            n++;
        }
    }
    sets[n] = NULL;
    cs_model_input in = {.size = sizeof in};
    int rc = load_crash(s, k, sets, &in);
    return add_loaded(s, rc, &in);
}

/* Queue crash test k at each end of each input's range, and at the CS_VAL_JOINT points of a Latin hypercube
 * over all of them at once (uniform over each range; its seed fixed, so the report is reproducible). */
static void add_sensitivity(cs_validate_suite *s, int k) {
    for (int i = 0; i < CS_VAL_INPUTS; i++)
        for (int side = 0; side < 2; side++) {
            double u[CS_VAL_INPUTS] = {0};
            u[i] = side;
            s->sensitivity[k][i][side] = add_inputs(s, k, i, u);
        }
    double *u = cs_latin_hypercube(CS_VAL_JOINT_SEED + (uint64_t)k, CS_VAL_JOINT, CS_VAL_INPUTS);
    if (!u) fprintf(s->opts.err, "cablesim validate: out of memory for the joint sample\n");
    for (int j = 0; j < CS_VAL_JOINT; j++) {
        if (u) memcpy(s->joint_u[k][j], u + j * CS_VAL_INPUTS, sizeof s->joint_u[k][j]);
        s->joint[k][j] = u ? add_inputs(s, k, -1, s->joint_u[k][j]) : add_job(s, NULL);
    }
    free(u);
}

/* ---- readings of what the design data leaves open ---- */
/* Each reading changes one part the paper's design data does not fix (docs/assumptions.md says which the
 * examples take and why), for the crash tests that have that part. */
const cs_validate_reading cs_validate_readings[CS_VAL_READINGS] = {
    {"no rails (the paper's model)", "aps1 aps3 aps4", 1, {NULL}},
    {"rails of 14 gauge (0.0747 in) instead of 12",
     "aps1 aps3 aps4",
     0,
     {"barrier.rails[0].area=0.495 in2", "barrier.rails[1].area=0.495 in2", "barrier.rails[2].area=0.495 in2",
      "barrier.rails[3].area=0.495 in2", "barrier.rails[0].inertia=0.219 in4",
      "barrier.rails[1].inertia=0.219 in4", "barrier.rails[2].inertia=0.219 in4",
      "barrier.rails[3].inertia=0.219 in4", "barrier.rails[0].mass_per_length=1.68 lb/ft",
      "barrier.rails[1].mass_per_length=1.68 lb/ft", "barrier.rails[2].mass_per_length=1.68 lb/ft",
      "barrier.rails[3].mass_per_length=1.68 lb/ft", NULL}},
    {"the intermediate anchor posts hold the ropes (clamped)",
     "aps1 aps3 aps4",
     0,
     {"barrier.posts[1].attachment=clamped", NULL}},
    {"the dead-men pulled on their 6-ft face",
     "aps1",
     0,
     {"barrier.anchors.start.footing.diameter=6 ft", "barrier.anchors.start.length=8 ft",
      "barrier.anchors.end.footing.diameter=6 ft", "barrier.anchors.end.length=8 ft", NULL}},
    {"the end dead-men 3 x 5 ft, as APS3's",
     "aps4",
     0,
     {"barrier.anchors.start.footing.depth=5 ft", "barrier.anchors.end.footing.depth=5 ft", NULL}},
    {"the dead-men at the bogie post's dynamic factor, not scaled to their width",
     "aps1 aps3 aps4",
     0,
     {"barrier.anchors.start.footing.width_scaling=none", "barrier.anchors.end.footing.width_scaling=none",
      NULL}},
    {"the dead-men at Eq. 21's static capacity (no rate or wedge factor)",
     "aps1 aps3 aps4",
     0,
     {"barrier.anchors.start.footing.dynamic_factor=1", "barrier.anchors.start.footing.width_scaling=none",
      "barrier.anchors.end.footing.dynamic_factor=1", "barrier.anchors.end.footing.width_scaling=none",
      NULL}},
    {"the line posts pull out at 50 kip instead of 20 (the paper's 20-50 kip)",
     "aps1 aps3 aps4",
     0,
     {"barrier.posts[0].footing.pullout_capacity=50 kip", NULL}},
    {"the ropes keep half their strength at the rails' holes (the D/d table's lowest row, D/d = 1)",
     "aps1 aps3 aps4",
     0,
     {"barrier.cables[0].hole_efficiency=0.5", "barrier.cables[1].hole_efficiency=0.5", NULL}},
    {"swaged end fittings (95%) instead of clips (90%)",
     "aps1 aps3 aps4",
     0,
     {"barrier.cables[0].termination=swaged", "barrier.cables[1].termination=swaged", NULL}},
    {"the soil's critical-state friction angle 30 deg (the lowest of siliceous sands) instead of 33",
     "aps1 aps3 aps4",
     0,
     {"barrier.anchors.start.footing.residual_friction_angle=30 deg",
      "barrier.anchors.end.footing.residual_friction_angle=30 deg", NULL}},
    {"the soil's critical-state friction angle 40 deg (feldspar's) instead of 33",
     "aps1 aps3 aps4",
     0,
     {"barrier.anchors.start.footing.residual_friction_angle=40 deg",
      "barrier.anchors.end.footing.residual_friction_angle=40 deg", NULL}},
    {"the dead-men's uplift at the beta method's shaft friction, 25.4 kPa/m, instead of the bogie-fitted "
     "177.5",
     "aps1 aps3 aps4",
     0,
     {"barrier.anchors.start.footing.skin_friction=25.4 kPa/m",
      "barrier.anchors.end.footing.skin_friction=25.4 kPa/m", NULL}},
};

static void add_readings(cs_validate_suite *s, int k) {
    for (int r = 0; r < CS_VAL_READINGS; r++) {
        s->reading[k][r] = -1;
        if (!strstr(cs_validate_readings[r].tests, cs_validate_crash_names[k])) continue;
        cs_model_input in = {.size = sizeof in};
        int rc = load_crash(s, k, cs_validate_readings[r].sets, &in);
        if (rc == 0 && cs_validate_readings[r].no_rails) in.barrier.rail_count = 0;
        s->reading[k][r] = add_loaded(s, rc, &in);
    }
}

/* ---- the roadside crash tests: blind predictions ---- */
/* Readings of what the roadside design data leaves open (docs/assumptions.md), for the tests that have
 * that part. */
const cs_validate_road_reading cs_validate_road_readings[CS_VAL_ROAD_READINGS] = {
    {"slot and hook retainers at 0.5 kN",
     "rs1 rs2 rs3 rs4 rs5 rs6",
     {"barrier.posts[0].release_force=0.5 kN", NULL}},
    {"slot and hook retainers at 4 kN",
     "rs1 rs2 rs3 rs4 rs5 rs6",
     {"barrier.posts[0].release_force=4 kN", NULL}},
    {"cable friction on the posts 0.3 (0.15)",
     "rs1 rs2 rs3 rs4 rs6",
     {"barrier.cables[0].post_friction=0.3", "barrier.cables[1].post_friction=0.3",
      "barrier.cables[2].post_friction=0.3", NULL}},
    {"cable friction on the posts 0.3 (0.15)",
     "rs5",
     {"barrier.cables[0].post_friction=0.3", "barrier.cables[1].post_friction=0.3",
      "barrier.cables[2].post_friction=0.3", "barrier.cables[3].post_friction=0.3", NULL}},
    {"ropes not pre-stretched as the pre-stretched high-tension rope",
     "rs3 rs4 rs6",
     {"barrier.cables[0].rope=3x7-0.75in-HT", "barrier.cables[1].rope=3x7-0.75in-HT",
      "barrier.cables[2].rope=3x7-0.75in-HT", NULL}},
    {"pretension 2.2 kN (500 lbf; 1,000 lbf taken)",
     "rs6",
     {"barrier.cables[0].pretension=500 lbf", "barrier.cables[1].pretension=500 lbf",
      "barrier.cables[2].pretension=500 lbf", NULL}},
    {"pretension 8.9 kN (2,000 lbf; 1,000 lbf taken)",
     "rs6",
     {"barrier.cables[0].pretension=2000 lbf", "barrier.cables[1].pretension=2000 lbf",
      "barrier.cables[2].pretension=2000 lbf", NULL}},
    {"impact at the middle (a third of the way in taken)", "rs3 rs4", {"scenario.impact_x=167 ft", NULL}},
    {"slotted cables let go by friction from the first lean, as from a hook with the cap's 1 kN (their ride "
     "up "
     "the slot taken)",
     "rs1 rs2 rs3 rs4 rs5",
     {"barrier.posts[0].attachment=hook", "barrier.posts[0].release_force=1 kN", NULL}},
    {"end anchors that give at their 40-kip design load (rigid taken): 0.35-m shafts 1.5 m deep",
     "rs1 rs2 rs3 rs4 rs5 rs6",
     {"barrier.anchors.start.footing.diameter=0.35 m", "barrier.anchors.start.footing.depth=1.5 m",
      "barrier.anchors.end.footing.diameter=0.35 m", "barrier.anchors.end.footing.depth=1.5 m", NULL}},
};

const double cs_validate_road_step_fractions[CS_VAL_ROAD_STEPS] = {0.5, 0.2};

/* Queue roadside test k as its file stands, under its readings and (convergence) at the finer steps. */
static void add_road(cs_validate_suite *s, int k, int convergence) {
    char name[64];
    snprintf(name, sizeof name, "roadside/%s", cs_validate_road_names[k]);
    cs_model_input in = {.size = sizeof in};
    int rc = load_example(s, name, NULL, &in);
    double dt = in.scenario.dt; /* its file's step, which the finer ones divide (a file that failed to load
                                   fails them too, and its convergence reads as failed) */
    s->road[k] = add_loaded(s, rc, &in);
    for (int d = 0; d < CS_VAL_ROAD_STEPS; d++) {
        char set[64];
        snprintf(set, sizeof set, "scenario.dt=%.17g s", dt * cs_validate_road_step_fractions[d]);
        const char *sets[] = {set, NULL};
        s->road_step[k][d] = convergence ? add_loaded(s, load_example(s, name, sets, &in), &in) : -1;
    }
    for (int r = 0; r < CS_VAL_ROAD_READINGS; r++) {
        s->road_reading[k][r] = -1;
        if (!strstr(cs_validate_road_readings[r].tests, cs_validate_road_names[k])) continue;
        s->road_reading[k][r] =
            add_loaded(s, load_example(s, name, cs_validate_road_readings[r].sets, &in), &in);
    }
}

int cs_validate_wanted(const char *only, const char *part) {
    return !only || strstr(only, part) != NULL;
}

void cs_validate_plan(cs_validate_suite *s) {
    const char *only = s->opts.only;
    int crash = cs_validate_wanted(only, "crash"), convergence = cs_validate_wanted(only, "convergence"),
        sensitivity = cs_validate_wanted(only, "sensitivity"), reads = cs_validate_wanted(only, "readings");
    for (int k = 0; k < CS_VAL_CRASH; k++) {
        cs_model_input in = {.size = sizeof in};
        int rc = crash || convergence || sensitivity || reads ? load_crash(s, k, NULL, &in) : -1;
        s->base_loaded[k] = rc == 0;
        if (rc == 0) s->base_scenario[k] = in.scenario;
        s->base[k] = crash || sensitivity || reads ? add_loaded(s, rc, &in) : -1;
    }
    for (int k = 0; k < CS_VAL_CRASH && reads; k++)
        add_readings(s, k);
    for (int i = 0; i < CS_VAL_BOGIE && cs_validate_wanted(only, "bogie"); i++)
        s->bogie[i] = add_bogie(s, &s->data.bogie[i]);
    for (int t = 0; t < CS_VAL_REFINE && convergence; t++)
        for (int k = 0; k < CS_VAL_CRASH; k++)
            add_refinement(s, t, k);
    for (int k = 0; k < CS_VAL_CRASH && sensitivity; k++)
        add_sensitivity(s, k);
    for (int k = 0; k < CS_VAL_ROAD; k++) {
        s->road[k] = -1;
        for (int d = 0; d < CS_VAL_ROAD_STEPS; d++)
            s->road_step[k][d] = -1;
    }
    for (int k = 0; k < CS_VAL_ROAD && cs_validate_wanted(only, "roadside"); k++)
        add_road(s, k, convergence);
}
