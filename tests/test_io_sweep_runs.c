/* A sweep's table of runs from fabricated results (a run that stopped, one that broke through, one that
 * failed, over a numeric and a text input): runs.csv to the byte. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "sweep.h"

enum { RUNS = 3 };

typedef struct fixture {
    cs_sweep_spec *spec;
    double *x;
    cs_sweep_result r[RUNS];
} fixture;

/* tests/sweep/grid.yaml's first three runs (pretension 4, 4, 5 kip; SD-STD-02.01, PU, SD-STD-02.01) with
 * results made up to the last digit; run 2 failed, and its summary's numbers must not show. */
static int setup(void **state) {
    fixture *f = calloc(1, sizeof *f);
    char why[256];
    cs_units *u = cs_units_create(why, sizeof why);
    if (!f || !u) return -1;
    f->spec = cs_sweep_spec_read("tests/sweep/grid.yaml", u);
    cs_units_free(u);
    long n;
    if (!f->spec || f->spec->error_count || !(f->x = cs_sweep_samples(f->spec, &n))) return -1;
    cs_sweep_result *r = f->r;
    r[0].summary = (cs_summary){.outcome = CS_STOPPED,
                                .t = 0.5,
                                .max_decel_50ms_g = 3.25,
                                .t_max_decel = 0.125,
                                .max_dynamic_penetration = 1.2345678901234567,
                                .max_barrier_deflection = 2.25,
                                .stop_time = 0.4375,
                                .exit_speed = 7,
                                .first_contact_time = 0.003,
                                .posts_failed_left = 2,
                                .posts_failed_right = 3,
                                .initial_kinetic_energy = 1087776.7091234,
                                .energy_balance_error = -4.2595107761234e-05,
                                .max_cable_tension = 38621.246851234,
                                .final_position = {20.5, -3.25, 1},
                                .solver_warnings = 1,
                                .max_solver_residual = 0.0023941431861234};
    r[0].event_counts[CS_EVENT_POST_HINGE] = 2;
    snprintf(r[0].rating, sizeof r[0].rating, "M40/P2");
    r[1].summary = (cs_summary){.outcome = CS_BREAKTHROUGH,
                                .t = 0.25,
                                .max_decel_50ms_g = 2.875,
                                .t_max_decel = 0.0625,
                                .max_dynamic_penetration = 4.03125,
                                .max_barrier_deflection = 4.5,
                                .stop_time = 0.1,
                                .exit_speed = 13.75,
                                .first_contact_time = -1,
                                .cables_broken = 2,
                                .initial_kinetic_energy = 367668.5275,
                                .max_cable_tension = 1.5e6,
                                .final_position = {25, 0.5, 0.75}};
    r[1].event_counts[CS_EVENT_CABLE_BREAK] = 2;
    r[1].event_counts[CS_EVENT_UNDERRIDE] = 1;
    snprintf(r[1].rating, sizeof r[1].rating, "PU40/P4");
    r[2].status = CS_RUN_FAILED;
    r[2].summary = r[0].summary;
    r[2].event_counts[CS_EVENT_CABLE_BREAK] = 5;
    snprintf(r[2].rating, sizeof r[2].rating, "none");
    snprintf(r[2].error, sizeof r[2].error, "the solve \"diverged\", at 0.1 s");
    *state = f;
    return 0;
}

static int teardown(void **state) {
    fixture *f = *state;
    free(f->x);
    cs_sweep_spec_free(f->spec);
    free(f);
    return 0;
}

static void test_runs_csv(void **state) {
    fixture *f = *state;
    char *text = NULL, why[256];
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    assert_non_null(out);
    assert_int_equal(cs_sweep_write_runs(out, f->spec, f->x, f->r, RUNS, why, sizeof why), 0);
    fclose(out);
    const char *want =
        "run,barrier.cables[0].pretension [N],vehicle,outcome,astm_f2656,time_reached [s],max_50ms_decel [g],"
        "t_max_50ms_decel [s],max_dynamic_penetration [m],max_barrier_deflection [m],stop_time [s],"
        "exit_speed [m/s],first_contact_time [s],posts_failed_left,posts_failed_right,cables_broken,"
        "max_cable_tension [N],initial_kinetic_energy [J],energy_balance_error [1],solver_warnings,"
        "max_solver_residual [1],final_x [m],final_y [m],final_z [m],events_cable_break,events_post_hinge,"
        "events_post_rotation_limit,events_post_shear,events_post_pullout,events_footing_rotation,"
        "events_anchor_pullout,events_override,events_underride,error\n"
        "0,17792.886461,SD-STD-02.01,stopped,M40/P2,0.5,3.25,0.125,1.23456789,2.25,0.4375,,0.003,2,3,0,"
        "38621.24685,1087776.709,-4.259510776e-05,1,0.002394143186,20.5,-3.25,1,0,2,0,0,0,0,0,0,0,\n"
        "1,17792.886461,PU,breakthrough,PU40/P4,0.25,2.875,0.0625,4.03125,4.5,,13.75,,0,0,2,1500000,"
        "367668.5275,0,0,0,25,0.5,0.75,2,0,0,0,0,0,0,0,1,\n"
        "2,22241.1080763,SD-STD-02.01,failed,,,,,,,,,,,,,,,,,,,,,,,,,,,,,,\"the solve \"\"diverged\"\", at "
        "0.1 s\"\n";
    assert_string_equal(text, want);
    free(text);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_runs_csv),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
