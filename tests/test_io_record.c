/* A run's record stays within its size: when full it keeps every other frame and records every other
 * output from then on, and it always ends with the run's last state. A truck on the open road for 0.5 s,
 * an output every 0.5-ms step (outputs 0 to 1000), into a record of at most 100 frames: full at outputs
 * 100, 200, 400 and 800, it ends recording every 16th and holds the outputs 0, 16, ..., 992 (8 ms
 * apart) and the run's last, 1000. */
#include "check.h"
#include "fixture.h"
#include "out/record.h"

static void record_thins_and_keeps_the_end(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.start_gap = 1000.0; /* the barrier is far: nothing happens, the run goes to its end */
    fx.scenario.stop_speed = 0.0;
    fx.scenario.t_end = 0.5;
    fx.scenario.output_interval = 0.0; /* every step */
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    cs_record rec;
    assert_int_equal(cs_record_init(&rec, m), 0);
    rec.max_frames = 100;
    assert_int_equal(cs_run(m, s, cs_record_frame, &rec, &err), CS_OK);
    assert_int_equal(rec.failed, 0);
    assert_int_equal(rec.stride, 16);
    assert_int_equal(rec.frame_count, 64);
    assert_true(rec.capacity <= rec.max_frames);
    for (int f = 0; f + 1 < rec.frame_count; f++)
        CHECK_ABS(rec.vehicle[f].t, 16 * f * fx.scenario.dt, 1e-9);
    CHECK_ABS(rec.vehicle[rec.frame_count - 1].t, 0.5, 1e-9);
    cs_record_free(&rec);
    cs_state_free(s);
    cs_model_free(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(record_thins_and_keeps_the_end)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
