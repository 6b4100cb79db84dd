/* SPDX-License-Identifier: MIT */
/* The loader: the examples and every library part load with the documented values; --set, file and
 * part references; YAML aliases; every problem reported with its place; two loaders in two threads. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "cablesim/loader.h"
#include "check.h"
#include "fnv.h"

static const double PI = 3.14159265358979323846, FT = 0.3048, IN = 0.0254, LB = 0.45359237,
                    LBF = 0.45359237 * 9.80665;

static void close_to(double got, double want) {
    if (!(fabs(got - want) <= 1e-9 * fabs(want) + 1e-12)) fail_msg("got %.17g, want %.17g", got, want);
}

static cs_loader *new_loader(void) {
    cs_error err;
    cs_loader *l = cs_loader_create(CS_SOURCE_DIR "/data", &err);
    if (!l) fail_msg("%s", err.message);
    return l;
}

/* Load a model (and build it with the engine); fail with the loader's messages. */
static cs_loader *load(const char *file, cs_model_input *in, const char *const *sets) {
    cs_loader *l = new_loader();
    for (int i = 0; sets && sets[i]; i++)
        cs_loader_set(l, sets[i]);
    cs_model *m = NULL;
    if (cs_loader_load(l, file, in) != 0 || !(m = cs_loader_build(l, in))) {
        cs_loader_print_errors(l, stderr);
        fail_msg("%s did not load", file);
    }
    cs_model_free(m);
    return l;
}

static void test_aps3(void **state) {
    (void)state;
    cs_model_input in = {.size = sizeof in};
    cs_loader *l = load(CS_SOURCE_DIR "/examples/aps3.yaml", &in, NULL);
    const cs_barrier_def *b = &in.barrier;
    assert_string_equal(in.name, "aps3");
    assert_int_equal(b->cable_count, 2);
    assert_int_equal(b->post_count, 16);
    for (int p = 0; p < 16; p++)
        close_to(b->posts[p].x, 8 * (p + 1) * FT);
    close_to(b->posts[6].x, 56 * FT); /* intermediate anchor posts at 56 and 80 ft */
    close_to(b->posts[6].section.plastic_modulus, 2.631 * pow(IN, 3));
    close_to(b->posts[9].footing.diameter, 3 * FT);
    close_to(b->posts[9].footing.depth, 5 * FT);
    close_to(b->posts[9].footing.pullout_capacity, 50000 * LBF);
    close_to(b->posts[0].section.plastic_modulus, 1.287 * pow(IN, 3));
    close_to(b->posts[0].section.yield_stress, 50e3 * LBF / (IN * IN));
    close_to(b->posts[0].footing.diameter, 9 * IN);
    close_to(b->posts[0].footing.soil_pressure, 8000 * LBF / (FT * FT));
    close_to(b->posts[0].footing.coeff_depth, 2.37);
    close_to(b->posts[0].rotation_limit, PI / 2); /* not given: none, the edge rides over its top */
    close_to(b->posts[0].footing.rotation_limit, PI / 4);
    assert_int_equal(b->posts[0].attachment, CS_ATTACH_THROUGH);
    close_to(b->posts[0].height, 7 * FT);
    close_to(b->cables[0].height, 2.83 * FT);
    close_to(b->cables[1].height, 4 * FT);
    close_to(b->cables[0].rope.area, 0.471 * 1.75 * 1.75 * IN * IN); /* the d^2 rule */
    close_to(b->cables[0].rope.nominal_strength, 91.4e3 * 1.75 * 1.75 * LBF);
    close_to(b->cables[0].rope.modulus, 20e6 * LBF / (IN * IN));
    close_to(b->cables[0].pretension, 5000 * LBF);
    close_to(b->cables[0].post_friction, 0.15);
    close_to(b->start_anchor.x, 0);
    close_to(b->end_anchor.x, 136 * FT);
    close_to(b->end_anchor.footing.diameter, 3 * FT); /* the dead-man, 3 x 5 ft, in the barrier's soil */
    close_to(b->end_anchor.footing.depth, 5 * FT);
    close_to(b->end_anchor.footing.soil_pressure, 8000 * 47.88025898033584);
    close_to(b->end_anchor.pullout_capacity, 0.0); /* not given: its weight and skin friction */
    assert_int_equal(b->cables[0].termination, CS_TERMINATION_CLIPS);
    close_to(in.scenario.speed, 17.8816);
    close_to(in.scenario.angle, PI / 2);
    close_to(in.scenario.impact_x, 68 * FT);
    close_to(in.scenario.dt, 0.5e-3);
    close_to(in.scenario.t_end, 3);
    close_to(in.vehicle.mass, 15000 * LB);
    cs_loader_free(l);
}

static void test_aps1_aps4_layouts(void **state) {
    (void)state;
    cs_model_input in = {.size = sizeof in};
    cs_loader *l = load(CS_SOURCE_DIR "/examples/aps1.yaml", &in, NULL);
    assert_int_equal(in.barrier.post_count, 19);
    for (int k = 0; k < 19; k++) {
        close_to(in.barrier.posts[k].x, (4 + 8 * k) * FT);
        int anchor = k % 6 == 0;
        close_to(in.barrier.posts[k].footing.diameter, anchor ? 8 * FT : 18 * IN);
        /* the anchor posts' tubes are filled with 3,000-psi concrete; the line posts are open sections */
        close_to(in.barrier.posts[k].section.fill_strength, anchor ? 3000 * LBF / (IN * IN) : 0.0);
        close_to(in.barrier.posts[k].section.wall, anchor ? 0.116 * IN : 0.0);
    }
    close_to(in.barrier.end_anchor.x, 152 * FT);
    close_to(in.barrier.cables[0].rope.area, 0.471 * 1.5 * 1.5 * IN * IN);
    close_to(in.scenario.impact_x, 72 * FT);
    cs_loader_free(l);
    l = load(CS_SOURCE_DIR "/examples/aps4.yaml", &in, NULL);
    assert_int_equal(in.barrier.post_count, 19);
    for (int k = 0; k < 19; k++) {
        close_to(in.barrier.posts[k].x, (7.635 + 8.17 * k) * FT);
        int anchor = k % 4 == 3;
        close_to(in.barrier.posts[k].footing.depth, anchor ? 6 * FT : 3 * FT);
    }
    close_to(in.barrier.cables[1].rope.nominal_strength, 91.4e3 * 1.1 * 1.1 * LBF);
    cs_loader_free(l);
}

static void test_library_parts(void **state) {
    (void)state;
    cs_loader *l = new_loader();
    int total = 0;
    for (int k = 0; k < CS_PART_KIND_COUNT; k++) {
        const char **names, **docs;
        int n = cs_loader_library(l, (cs_part_kind)k, &names, &docs);
        assert_true(n > 0);
        for (int i = 0; i < n; i++, total++) {
            union {
                cs_vehicle_def v;
                cs_rope_def r;
                cs_section_def s;
                cs_rail_def rl;
            } d;
            if (cs_loader_part(l, (cs_part_kind)k, names[i], &d) != 0) {
                cs_loader_print_errors(l, stderr);
                fail_msg("part %s", names[i]);
            }
            assert_true(strlen(docs[i]) > 0);
        }
    }
    assert_int_equal(total, 11 + 8 + 9 + 1);
    cs_section_def holed;
    assert_int_equal(cs_loader_part(l, CS_PART_SECTION, "S4x7.7-holes", &holed), 0);
    /* Zx less the four holes' strips at their flange's centre: 3.50 - 4 (0.6875 x 0.293) (4.00 - 0.293) / 2
     */
    CHECK_REL(holed.plastic_modulus, (3.50 - 4 * 0.6875 * 0.293 * (4.00 - 0.293) / 2) * IN * IN * IN, 1e-4);
    cs_rail_def rail;
    assert_int_equal(cs_loader_part(l, CS_PART_RAIL, "TRAP2.5x2x12ga", &rail), 0);
    close_to(rail.area, 0.693 * IN * IN);
    close_to(rail.mass_per_length, 2.36 * LB / 0.3048);
    cs_vehicle_def m;
    assert_int_equal(cs_loader_part(l, CS_PART_VEHICLE, "SD-STD-02.01", &m), 0);
    double mass = 15000 * LB, v = 39.25 * 0.44704, fmax = 0.5 * mass * v * v / 0.6;
    close_to(m.mass, mass);
    close_to(m.inertia[0], mass * (2.4 * 2.4 + 2.5 * 2.5) / 12);
    close_to(m.inertia[1], mass * (7.5 * 7.5 + 2.5 * 2.5) / 12);
    close_to(m.inertia[2], mass * (7.5 * 7.5 + 2.4 * 2.4) / 12);
    assert_int_equal(m.crush_point_count, 6);
    close_to(m.crush_force[4], fmax); /* 1.7456 MN */
    close_to(m.crush_force[5], 3 * fmax);
    close_to(m.crush_deformation[5], 1.0);
    close_to(m.crush_unload_stiffness, 2e7);
    cs_rope_def r;
    assert_int_equal(cs_loader_part(l, CS_PART_ROPE, "A603-0.75in", &r), 0);
    close_to(r.nominal_strength, 52000 * LBF);
    close_to(r.mass_per_length, 0.95 * LB / FT);
    assert_int_equal(cs_loader_part(l, CS_PART_ROPE, "no-such-rope", &r), CS_ERR_INVALID);
    assert_non_null(strstr(cs_loader_error(l, 0), "no rope part named 'no-such-rope'"));
    cs_loader_free(l);
}

static void test_set(void **state) {
    (void)state;
    static const char *const sets[] = {"scenario.speed=35 mph",
                                       "barrier.cables[0].pretension=8 kip",
                                       "barrier.posts[0].footing.depth=4 ft",
                                       "barrier.posts[1].x[0]=32 ft",
                                       "scenario.dt=0.2 ms",
                                       "vehicle.mass=16000 lb",
                                       "barrier.soil.coeff_depth=2.34",
                                       NULL};
    cs_model_input in = {.size = sizeof in};
    cs_loader *l = load(CS_SOURCE_DIR "/tests/good/base.yaml", &in, sets);
    close_to(in.scenario.speed, 35 * 0.44704);
    close_to(in.barrier.cables[0].pretension, 8000 * LBF);
    close_to(in.barrier.cables[1].pretension, 5000 * LBF);
    close_to(in.barrier.posts[0].footing.depth, 4 * FT);
    close_to(in.barrier.posts[3].footing.depth, 5 * FT); /* the anchor post at 32 ft */
    close_to(in.barrier.posts[0].footing.coeff_depth, 2.34);
    close_to(in.scenario.dt, 0.2e-3);
    close_to(in.vehicle.mass, 16000 * LB);
    cs_loader_free(l);
    static const char *const swap[] = {"vehicle=H", NULL};
    l = load(CS_SOURCE_DIR "/tests/good/base.yaml", &in, swap);
    close_to(in.vehicle.mass, 65000 * LB);
    cs_loader_free(l);
}

/* A moment given on its own replaces that moment of the part's inertia box; the other two stay the box's. */
static void test_inertia_override(void **state) {
    (void)state;
    static const char *const sets[] = {"vehicle.yaw_inertia=50000 kg m^2", NULL};
    cs_model_input in = {.size = sizeof in};
    cs_loader *l = load(CS_SOURCE_DIR "/tests/good/base.yaml", &in, sets);
    const double m = 15000 * LB, L = 7.5, W = 2.4, H = 2.5; /* vehicle M of data/vehicles.yaml */
    close_to(in.vehicle.inertia[0], m * (W * W + H * H) / 12);
    close_to(in.vehicle.inertia[1], m * (L * L + H * H) / 12);
    close_to(in.vehicle.inertia[2], 50000);
    cs_loader_free(l);
}

static void expect_problems(const char *file, const char *const *sets, const char *const *want) {
    cs_loader *l = new_loader();
    for (int i = 0; sets && sets[i]; i++)
        cs_loader_set(l, sets[i]);
    cs_model_input in = {.size = sizeof in};
    assert_int_equal(cs_loader_load(l, file, &in), CS_ERR_INVALID);
    int n = 0;
    while (want[n])
        n++;
    if (cs_loader_error_count(l) != n) {
        cs_loader_print_errors(l, stderr);
        fail_msg("%d problems, %d expected", cs_loader_error_count(l), n);
    }
    for (int i = 0; i < n; i++)
        if (strncmp(cs_loader_error(l, i), want[i], strlen(want[i])) != 0)
            fail_msg("problem %d: '%s', expected '%s...'", i, cs_loader_error(l, i), want[i]);
    cs_loader_free(l);
}

static void test_set_errors(void **state) {
    (void)state;
    static const char *const sets[] = {"scenario.sped=35 mph",
                                       "barrier.cables[5].height=1 m",
                                       "barrier.posts=3",
                                       "scenario.speed=35 kg",
                                       "no equals sign",
                                       "barrier..x=1",
                                       "barrier.file=other.yaml",
                                       "vehicle.part=C",
                                       NULL};
    static const char *const want[] = {
        "--set scenario.sped=35 mph: unknown key 'sped' in scenario",
        "--set barrier.cables[5].height=1 m: no entry [5] (expected an index below 2)",
        "--set barrier.posts=3: 'posts' is not a single value",
        "--set scenario.speed=35 kg: 'kg' is a unit of mass, not of speed",
        "--set no equals sign: expected PATH=VALUE",
        "--set barrier..x=1: malformed path",
        "--set barrier.file=other.yaml: 'file' is followed when the model file is read, not after",
        "--set vehicle.part=C: 'part' is followed when the model file is read, not after",
        NULL};
    expect_problems(CS_SOURCE_DIR "/tests/good/base.yaml", sets, want);
}

/* A value the engine refuses is reported at the --set that gave it, once. */
static void test_engine_check_names_set(void **state) {
    (void)state;
    cs_loader *l = new_loader();
    cs_loader_set(l, "vehicle.cg_height=60 m");
    cs_model_input in = {.size = sizeof in};
    assert_int_equal(cs_loader_load(l, CS_SOURCE_DIR "/tests/good/base.yaml", &in), 0);
    assert_null(cs_loader_build(l, &in));
    assert_int_equal(cs_loader_error_count(l), 1);
    const char *want =
        "--set vehicle.cg_height=60 m: vehicle: CG height, CG to front and to rear, front width, "
        "wheelbase and track must be above 0 and at most 50 m (one is 60 m)";
    if (strncmp(cs_loader_error(l, 0), want, strlen(want)) != 0)
        fail_msg("got '%s', expected '%s...'", cs_loader_error(l, 0), want);
    cs_loader_free(l);
}

/* A check between two values of the model (a cable's or a rail's height against a post's, an anchor's x
 * against where the posts stand, the impact point against the anchors) names the --set that changed
 * either value, not the file's line of the other: the file was fine before the --set. */
static void test_cross_checks_name_set(void **state) {
    (void)state;
    static const struct {
        const char *file;
        const char *sets[5]; /* NULL-terminated */
        const char *want;
    } cases[] = {
        {"tests/good/base.yaml",
         {"barrier.posts[0].height=3 ft"},
         "--set barrier.posts[0].height=3 ft: the cable (1.2192 m) is above the top of the post at x = "
         "2.4384 m (0.9144 m)"},
        {"tests/good/base.yaml",
         {"barrier.posts[0].from=-8 ft"},
         "--set barrier.posts[0].from=-8 ft: the start anchor (x = 0 m) is inside the barrier (expected it "
         "before the first post at x = -2.4384 m, not at it or beyond)"},
        {"tests/good/base.yaml",
         {"barrier.posts[1].x[0]=70 ft"},
         "--set barrier.posts[1].x[0]=70 ft: the end anchor (x = 19.5072 m) is inside the barrier (expected "
         "it after the last post at x = 21.336 m, not at it or before)"},
        {"examples/aps3.yaml",
         {"barrier.posts[1].height=6 ft"},
         "--set barrier.posts[1].height=6 ft: the rail (2.1336 m) is above the top of the post at x = "
         "17.0688 m (1.8288 m)"},
        /* posts at 8 and 20 ft, the end anchor at 24 ft: the file's impact point, 28 ft, lies beyond it */
        {"tests/good/base.yaml",
         {"barrier.posts[0].to=16 ft", "barrier.posts[0].except[0]=16 ft", "barrier.posts[1].x[0]=20 ft",
          "barrier.anchors.end.x=24 ft"},
         "--set barrier.anchors.end.x=24 ft: the impact point (8.5344 m) is outside the barrier (expected "
         "between the anchors, above 0 m and below 7.3152 m)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char file[512];
        snprintf(file, sizeof file, "%s/%s", CS_SOURCE_DIR, cases[i].file);
        const char *const want[] = {cases[i].want, NULL};
        expect_problems(file, cases[i].sets, want);
    }
}

static void test_references(void **state) {
    (void)state;
    cs_model_input in = {.size = sizeof in};
    cs_loader *l = load(CS_SOURCE_DIR "/tests/good/split.yaml", &in, NULL);
    assert_string_equal(in.name, "split");
    close_to(in.vehicle.mass, 16000 * LB);      /* heavy-M: M with its own mass */
    close_to(in.vehicle.cg_height, 1.0);        /* ... and the rest of M */
    close_to(in.scenario.speed, 30 * 0.44704);  /* replaced beside file: */
    close_to(in.scenario.impact_x, 28 * FT);    /* from base.yaml */
    assert_int_equal(in.barrier.post_count, 7); /* from base.yaml */
    close_to(in.barrier.end_anchor.pullout_capacity, 100000 * LBF);
    assert_int_equal(in.barrier.posts[3].attachment, CS_ATTACH_CLAMPED);
    cs_loader_free(l);
    static const char *const thin[] = {"barrier.cables[0].rope=thin", NULL};
    l = load(CS_SOURCE_DIR "/tests/good/split.yaml", &in, thin);
    close_to(in.barrier.cables[0].rope.area, 0.471 * 0.25 * IN * IN); /* a rope of this file, scaled */
    close_to(in.barrier.cables[0].rope.breaking_strain, 0.04);
    cs_loader_free(l);
}

/* YAML aliases stand for their anchors' values: tests/good/anchors.yaml, base.yaml written with them,
 * loads to the same definitions, and a --set through an aliased value changes that place only. */
static void test_aliases(void **state) {
    (void)state;
    cs_model_input in = {.size = sizeof in}, base = {.size = sizeof base};
    cs_loader *l = load(CS_SOURCE_DIR "/tests/good/anchors.yaml", &in, NULL);
    cs_loader *b = load(CS_SOURCE_DIR "/tests/good/base.yaml", &base, NULL);
    assert_int_equal(in.barrier.cable_count, base.barrier.cable_count);
    for (int i = 0; i < in.barrier.cable_count; i++) {
        close_to(in.barrier.cables[i].pretension, base.barrier.cables[i].pretension);
        close_to(in.barrier.cables[i].height, base.barrier.cables[i].height);
    }
    assert_int_equal(in.barrier.post_count, base.barrier.post_count);
    for (int i = 0; i < in.barrier.post_count; i++) {
        close_to(in.barrier.posts[i].x, base.barrier.posts[i].x);
        close_to(in.barrier.posts[i].height, base.barrier.posts[i].height);
        close_to(in.barrier.posts[i].footing.depth, base.barrier.posts[i].footing.depth);
    }
    cs_loader_free(l);
    cs_loader_free(b);
    static const char *const sets[] = {"barrier.cables[1].pretension=8 kip", NULL};
    l = load(CS_SOURCE_DIR "/tests/good/anchors.yaml", &in, sets);
    close_to(in.barrier.cables[0].pretension, 5000 * LBF);
    close_to(in.barrier.cables[1].pretension, 8000 * LBF);
    cs_loader_free(l);
}

/* One loader reused for loads with other overrides (a sweep's runs) gives what a fresh loader gives,
 * also for a model split over files; a load with errors leaves it to a full reset, and the next load
 * works. */
static void test_reuse(void **state) {
    (void)state;
    cs_model_input in = {.size = sizeof in};
    cs_loader *l = new_loader();
    static const char *const file = CS_SOURCE_DIR "/tests/good/split.yaml";
    for (int round = 0; round < 4; round++) {
        cs_loader_reuse(l);
        if (round == 1) cs_loader_set(l, "barrier.cables[0].rope=thin");
        if (round == 2) cs_loader_set(l, "scenario.colour=red");
        if (round == 3) cs_loader_set(l, "scenario.speed=35 mph");
        int rc = cs_loader_load(l, file, &in);
        assert_int_equal(rc, round == 2 ? CS_ERR_INVALID : CS_OK);
        if (round == 2) continue;
        assert_int_equal(in.barrier.post_count, 7);
        close_to(in.vehicle.mass, 16000 * LB);
        close_to(in.scenario.speed, (round == 3 ? 35 : 30) * 0.44704);
        close_to(in.barrier.cables[0].rope.area, (round == 1 ? 0.471 * 0.25 : 0.471) * IN * IN);
        cs_model *m = cs_loader_build(l, &in);
        assert_non_null(m);
        cs_model_free(m);
    }
    cs_loader_free(l);
}

/* Each rope end's own fitting (tests/good/ends.yaml) into ends[0] (start anchor) and ends[1] (end anchor),
 * an end not given left to the cable's, and as the engine takes them; a --set of an end's kind; a slip
 * load and travel by the cable and by an end (with units), and none at an end with a kind of its own. An end
 * left to the cable's adds nothing to the model's hash: base.yaml's is the hash of its other values alone,
 * 0xd2aade023bc081e7; an end of its own changes it. */
static void test_cable_ends(void **state) {
    (void)state;
    cs_model_input in = {.size = sizeof in};
    cs_loader *l = load(CS_SOURCE_DIR "/tests/good/ends.yaml", &in, NULL);
    const cs_cable_def *c = in.barrier.cables;
    assert_int_equal(c[0].termination, CS_TERMINATION_CLIPS);
    assert_int_equal(c[0].ends[0].termination, CS_TERMINATION_SWAGED);
    CHECK_ABS(c[0].ends[0].termination_efficiency, 0.0, 0.0);
    assert_int_equal(c[0].ends[1].termination, CS_TERMINATION_AS_CABLE);
    close_to(c[0].ends[1].termination_efficiency, 0.85);
    assert_int_equal(c[1].termination, CS_TERMINATION_WEDGE);
    assert_int_equal(c[1].ends[0].termination, CS_TERMINATION_AS_CABLE);
    CHECK_ABS(c[1].ends[0].termination_efficiency, 0.0, 0.0);
    assert_int_equal(c[1].ends[1].termination, CS_TERMINATION_CLIPS);
    static const struct {
        int cable, end;
        cs_termination kind;
        double efficiency;
    } want[] = {{0, 0, CS_TERMINATION_SWAGED, 0.95},
                {0, 1, CS_TERMINATION_CLIPS, 0.85},
                {1, 0, CS_TERMINATION_WEDGE, 0.85},
                {1, 1, CS_TERMINATION_CLIPS, 0.90}}; /* clips on 1-in rope */
    for (size_t k = 0; k < sizeof want / sizeof want[0]; k++) {
        cs_termination kind;
        double e = cs_cable_end_efficiency(&c[want[k].cable], want[k].end, &kind);
        assert_int_equal(kind, want[k].kind);
        CHECK_REL(e, want[k].efficiency, 1e-15);
    }
    cs_loader_free(l);
    static const char *const spelter[] = {"barrier.cables[1].start.termination=spelter", NULL};
    l = load(CS_SOURCE_DIR "/tests/good/ends.yaml", &in, spelter);
    assert_int_equal(in.barrier.cables[1].ends[0].termination, CS_TERMINATION_SPELTER);
    CHECK_REL(cs_cable_end_efficiency(&in.barrier.cables[1], 0, NULL), 1.0, 1e-15);
    cs_loader_free(l);
    l = load(CS_SOURCE_DIR "/tests/good/base.yaml", &in, NULL);
    /* 64-bit FNV-1a (its published vectors: "a", "foobar") over the model's values */
    assert_true(cs_io_fnv(CS_IO_FNV_BASIS, "a", 1) == 0xaf63dc4c8601ec8cULL);
    assert_true(cs_io_fnv(CS_IO_FNV_BASIS, "foobar", 6) == 0x85944171f73967e8ULL);
    assert_true(cs_model_input_hash(&in) == 0xce2fc20606736d99ULL);
    cs_loader_free(l);
    static const char *const slip[] = {"barrier.cables[0].slip_load=30 kip",
                                       "barrier.cables[0].slip_travel=18 in",
                                       "barrier.cables[0].end.slip_load=40 kip", NULL};
    l = load(CS_SOURCE_DIR "/tests/good/base.yaml", &in, slip);
    double travel; /* the cable's slip at the start; the end's own load with the cable's travel */
    CHECK_REL(cs_cable_end_slip(&in.barrier.cables[0], 0, &travel), 30.0 * 4448.2216152605, 1e-12);
    CHECK_REL(travel, 18.0 * 0.0254, 1e-12);
    CHECK_REL(cs_cable_end_slip(&in.barrier.cables[0], 1, &travel), 40.0 * 4448.2216152605, 1e-12);
    CHECK_REL(travel, 18.0 * 0.0254, 1e-12);
    CHECK_ABS(cs_cable_end_slip(&in.barrier.cables[1], 0, NULL), 0.0, 0.0); /* none given: it holds */
    cs_loader_free(l);
    static const char *const swaged[] = {"barrier.cables[0].slip_load=30 kip",
                                         "barrier.cables[0].slip_travel=18 in",
                                         "barrier.cables[0].start.termination=swaged", NULL};
    l = load(CS_SOURCE_DIR "/tests/good/base.yaml", &in, swaged); /* a socket of its own does not slip */
    CHECK_ABS(cs_cable_end_slip(&in.barrier.cables[0], 0, NULL), 0.0, 0.0);
    CHECK_REL(cs_cable_end_slip(&in.barrier.cables[0], 1, NULL), 30.0 * 4448.2216152605, 1e-12);
    cs_loader_free(l);
    static const char *const own[] = {"barrier.cables[0].end.termination=clips", NULL};
    l = load(CS_SOURCE_DIR "/tests/good/base.yaml", &in, own);
    assert_true(cs_model_input_hash(&in) != 0x13a3bca2d2ef90c5ULL);
    cs_loader_free(l);
}

/* A rope end's bad kind, efficiency and key, and an end given as a word, each at its place. */
static void test_cable_end_problems(void **state) {
    (void)state;
    static const char *const want[] = {
        CS_SOURCE_DIR
        "/tests/bad/bad_cable_end.yaml:5:78: barrier.cables[0].start.termination: 'knot' is not a "
        "choice (expected clips, swaged, spelter or wedge)",
        CS_SOURCE_DIR
        "/tests/bad/bad_cable_end.yaml:9:58: barrier.cables[1].end.termination_efficiency: '1.2' "
        "must be at most 1",
        CS_SOURCE_DIR "/tests/bad/bad_cable_end.yaml:10:86: barrier.cables[2].start: unknown key 'colour' "
                      "(expected one of: termination, termination_efficiency, slip_load, slip_travel)",
        NULL};
    expect_problems(CS_SOURCE_DIR "/tests/bad/bad_cable_end.yaml", NULL, want);
    static const char *const word[] = {CS_SOURCE_DIR
                                       "/tests/bad/cable_end_word.yaml:5:62: barrier.cables[0].end "
                                       "is a single value (expected a mapping: the cable_end)",
                                       NULL};
    expect_problems(CS_SOURCE_DIR "/tests/bad/cable_end_word.yaml", NULL, word);
}

static void test_every_problem_reported(void **state) {
    (void)state;
    static const char *const want[] = {
        CS_SOURCE_DIR "/tests/bad/many_errors.yaml:5:57: barrier.cables[0]: unknown key 'colour'",
        CS_SOURCE_DIR "/tests/bad/many_errors.yaml:6:7: barrier.cables[1]: missing 'height'",
        CS_SOURCE_DIR
        "/tests/bad/many_errors.yaml:6:36: barrier.cables[1].pretension: 'kg' is a unit of mass",
        CS_SOURCE_DIR "/tests/bad/many_errors.yaml:8:29: barrier.posts[0].spacing: '0 ft' must be above zero",
        CS_SOURCE_DIR "/tests/bad/many_errors.yaml:12:26: vehicle.mass: '-1 lb' must be above zero",
        CS_SOURCE_DIR "/tests/bad/many_errors.yaml:13:19: scenario.speed: 'kg' is a unit of mass",
        CS_SOURCE_DIR "/tests/bad/many_errors.yaml:13:47: scenario.dt: 'fast' is not a number",
        NULL};
    expect_problems(CS_SOURCE_DIR "/tests/bad/many_errors.yaml", NULL, want);
}

/* Two loaders, each with its own units and files, at once. */
static void *load_aps3(void *arg) {
    cs_model_input in = {.size = sizeof in};
    cs_loader *l = cs_loader_create(CS_SOURCE_DIR "/data", NULL);
    *(double *)arg =
        l && cs_loader_load(l, CS_SOURCE_DIR "/examples/aps3.yaml", &in) == 0 ? in.barrier.posts[15].x : -1;
    cs_loader_free(l);
    return NULL;
}

static void test_two_threads(void **state) {
    (void)state;
    pthread_t t[2];
    double x[2];
    for (int i = 0; i < 2; i++)
        assert_int_equal(pthread_create(&t[i], NULL, load_aps3, &x[i]), 0);
    for (int i = 0; i < 2; i++)
        pthread_join(t[i], NULL);
    for (int i = 0; i < 2; i++)
        close_to(x[i], 128 * FT);
}

/* cs_model_input is filled to the caller's size (cablesim/loader.h): one without its last field (the
 * scenario) gets the same name, file, barrier and vehicle as a whole one and nothing past its size, and
 * cannot be built from or hashed; a size of 0 or larger than the library's is refused by name. */
static void test_model_input_sizes(void **state) {
    (void)state;
    cs_model_input in = {.size = sizeof in};
    cs_loader *whole = load(CS_SOURCE_DIR "/examples/aps3.yaml", &in, NULL), *l = new_loader();
    _Alignas(max_align_t) unsigned char b[sizeof in + 64];
    size_t n = offsetof(cs_model_input, scenario);
    memset(b, 0x5a, sizeof b);
    memcpy(b, &n, sizeof n);
    cs_model_input *shorter = (cs_model_input *)(void *)b;
    assert_int_equal(cs_loader_load(l, CS_SOURCE_DIR "/examples/aps3.yaml", shorter), CS_OK);
    assert_int_equal(shorter->size, n);
    assert_string_equal(shorter->name, in.name);
    assert_string_equal(shorter->file, in.file);
    assert_memory_equal(&shorter->vehicle, &in.vehicle, sizeof in.vehicle);
    assert_int_equal(shorter->barrier.post_count, in.barrier.post_count);
    for (int p = 0; p < in.barrier.post_count; p++)
        assert_memory_equal(&shorter->barrier.posts[p], &in.barrier.posts[p], sizeof in.barrier.posts[p]);
    for (int c = 0; c < in.barrier.cable_count; c++)
        assert_memory_equal(&shorter->barrier.cables[c], &in.barrier.cables[c], sizeof in.barrier.cables[c]);
    for (size_t k = n; k < sizeof b; k++) /* nothing past its size */
        assert_int_equal(b[k], 0x5a);
    /* it lacks the scenario: not built from, not hashed */
    assert_true(cs_model_input_hash(&in) != 0);
    assert_true(cs_model_input_hash(shorter) == 0);
    assert_null(cs_loader_build(l, shorter));
    assert_true(strstr(cs_loader_error(l, 0), "cs_model_input: size ") == cs_loader_error(l, 0));
    assert_non_null(strstr(cs_loader_error(l, 0), "needs"));
    /* sizes it does not know */
    size_t bad[2] = {0, sizeof in + 8};
    for (int k = 0; k < 2; k++) {
        cs_loader_reset(l);
        memset(b, 0x5a, sizeof b);
        memcpy(b, &bad[k], sizeof bad[k]);
        assert_int_equal(cs_loader_load(l, CS_SOURCE_DIR "/examples/aps3.yaml", shorter), CS_ERR_INVALID);
        char want[64];
        snprintf(want, sizeof want, "cs_model_input: size %zu, where this library's is %zu", bad[k],
                 sizeof in);
        assert_int_equal(cs_loader_error_count(l), 1);
        assert_true(strstr(cs_loader_error(l, 0), want) == cs_loader_error(l, 0));
        for (size_t j = sizeof(size_t); j < sizeof b; j++) /* nothing written */
            assert_int_equal(b[j], 0x5a);
    }
    cs_loader_free(l);
    cs_loader_free(whole);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_aps3),
        cmocka_unit_test(test_model_input_sizes),
        cmocka_unit_test(test_aps1_aps4_layouts),
        cmocka_unit_test(test_library_parts),
        cmocka_unit_test(test_set),
        cmocka_unit_test(test_set_errors),
        cmocka_unit_test(test_inertia_override),
        cmocka_unit_test(test_engine_check_names_set),
        cmocka_unit_test(test_cross_checks_name_set),
        cmocka_unit_test(test_references),
        cmocka_unit_test(test_reuse),
        cmocka_unit_test(test_every_problem_reported),
        cmocka_unit_test(test_cable_ends),
        cmocka_unit_test(test_cable_end_problems),
        cmocka_unit_test(test_two_threads),
        cmocka_unit_test(test_aliases),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
