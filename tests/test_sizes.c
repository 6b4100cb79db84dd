/* SPDX-License-Identifier: MIT */
/* The definitions' sizes (def.h): a program built against an earlier cablesim, whose structs are smaller,
 * gets the run of today's structs with the defaults for the fields it lacks; a struct not started from
 * its cs_default_*(), or larger than the library's, is refused with a sentence naming it. The earlier
 * structs are today's without their last field: a rope without its diameter (so a cable ending in that
 * smaller rope, read at its own stride in the barrier's array) and a scenario without max_steps. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "fixture.h"

enum { OLD_ROPE = offsetof(cs_rope_def, diameter), OLD_CABLE = offsetof(cs_cable_def, rope) + OLD_ROPE };
enum { OLD_SCENARIO = offsetof(cs_scenario_def, max_steps) };

/* The state hash of a run of the model to t = 0.3 s. */
static unsigned long long run_hash(const cs_barrier_def *b, const cs_vehicle_def *v,
                                   const cs_scenario_def *s) {
    cs_error err;
    cs_model *m = cs_model_create(b, v, s, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *st = cs_state_create(m, &err);
    assert_non_null(st);
    assert_int_equal(cs_run(m, st, NULL, NULL, &err), CS_OK);
    unsigned long long h = cs_state_hash(m, st);
    cs_state_free(st);
    cs_model_free(m);
    return h;
}

static void earlier_structs_run_as_todays_with_defaults(void **state) {
    (void)state;
    /* the earlier layouts are today's cut before their last field */
    assert_int_equal(OLD_ROPE + sizeof(double), sizeof(cs_rope_def));
    assert_int_equal(OLD_CABLE + sizeof(double), sizeof(cs_cable_def));
    assert_int_equal(OLD_SCENARIO + sizeof(double), sizeof(cs_scenario_def));
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.t_end = 0.3;
    fx.scenario.max_steps = 123; /* beyond the earlier scenario: must not be read */
    unsigned char old_cables[2][OLD_CABLE], old_scenario[OLD_SCENARIO];
    for (int c = 0; c < 2; c++) {
        fx.cables[c].rope.diameter = 0.05; /* beyond the earlier rope: must not be read */
        memcpy(old_cables[c], &fx.cables[c], OLD_CABLE);
        size_t cable = OLD_CABLE, rope = OLD_ROPE;
        memcpy(old_cables[c], &cable, sizeof cable);
        memcpy(old_cables[c] + offsetof(cs_cable_def, rope), &rope, sizeof rope);
    }
    memcpy(old_scenario, &fx.scenario, OLD_SCENARIO);
    size_t scenario = OLD_SCENARIO;
    memcpy(old_scenario, &scenario, sizeof scenario);
    cs_barrier_def old_barrier = fx.barrier;
    old_barrier.cables = (const cs_cable_def *)(const void *)old_cables;

    /* today's structs with the defaults in the fields the earlier ones lack */
    fx.scenario.max_steps = cs_default_scenario_def().max_steps;
    for (int c = 0; c < 2; c++)
        fx.cables[c].rope.diameter = cs_default_rope_def().diameter;
    unsigned long long today = run_hash(&fx.barrier, &fx.vehicle, &fx.scenario);
    unsigned long long earlier =
        run_hash(&old_barrier, &fx.vehicle, (const cs_scenario_def *)(const void *)old_scenario);
    assert_true(today == earlier);
    /* the field the earlier scenario lacks is read from today's, and taken at its default from it */
    fx.scenario.max_steps = 123;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    assert_non_null(m);
    assert_true(cs_model_scenario(m)->max_steps == 123.0);
    cs_model_free(m);
    m = cs_model_create(&old_barrier, &fx.vehicle, (const cs_scenario_def *)(const void *)old_scenario, &err);
    assert_non_null(m);
    assert_true(cs_model_scenario(m)->max_steps == cs_default_scenario_def().max_steps);
    assert_int_equal(cs_model_scenario(m)->size, sizeof(cs_scenario_def));
    cs_model_free(m);
}

static void expect_refused(const cs_barrier_def *b, const cs_vehicle_def *v, const cs_scenario_def *s,
                           const char *want) {
    cs_error err;
    assert_null(cs_model_create(b, v, s, &err));
    assert_int_equal(err.status, CS_ERR_INVALID);
    if (!strstr(err.message, want)) fail_msg("'%s' lacks '%s'", err.message, want);
}

static void unknown_sizes_are_refused(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    cs_vehicle_def v = fx.vehicle;
    v.size = 0; /* not from cs_default_vehicle_def() */
    expect_refused(&fx.barrier, &v, &fx.scenario, "vehicle: size 0: start it from cs_default_vehicle_def()");
    v.size = sizeof v + 8; /* a program built for a later cablesim */
    expect_refused(&fx.barrier, &v, &fx.scenario, "where this library's is");
    fx.posts[3].footing.size = 0;
    expect_refused(&fx.barrier, &fx.vehicle, &fx.scenario, "post 3's footing: size 0");
    fx.posts[3].footing = cs_default_footing_def();
    fx.posts[3].footing.diameter = 0.75 * FT;
    fx.posts[3].footing.depth = 3 * FT;
    fx.posts[3].footing.soil_pressure = 8000 * PSF;
    fx.posts[3].section.size = sizeof(cs_section_def) - 8; /* a smaller section inside a whole post */
    expect_refused(&fx.barrier, &fx.vehicle, &fx.scenario, "a layout this library does not know");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(earlier_structs_run_as_todays_with_defaults),
        cmocka_unit_test(unknown_sizes_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
