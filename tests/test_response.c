/* SPDX-License-Identifier: MIT */
/* Response parameters of src/run/response.c: each cable's peak tension and work on the vehicle (on the
 * APS3-like fixture: the cables' work makes the vehicle's change of energy, and each peak is the largest of
 * its cable's tension as recorded at every step), and the sudden-loss check on synthetic force histories. */
#include "check.h"
#include "fixture.h"
#include "run/run.h"

#include <stdlib.h>

/* ---- each cable's peak tension and work on the vehicle ---- */

typedef struct tension_series {
    int cables;
    double peak[2], t_peak[2]; /* the largest tension recorded, N, and when, s */
    int frames;
    int struck; /* posts struck by the vehicle, summed over the frames */
} tension_series;

static void record_tensions(const cs_model *model, const cs_state *s, void *user) {
    tension_series *ts = user;
    ts->frames++;
    for (int p = 0; p < model->post_count; p++)
        ts->struck += s->posts[p].captured;
    for (int c = 0; c < ts->cables; c++) {
        cs_cable_view v = {.size = sizeof v};
        cs_state_cable(model, s, c, &v, NULL);
        if (v.max_tension > ts->peak[c]) ts->peak[c] = v.max_tension, ts->t_peak[c] = s->t;
    }
}

/* APS3's truck on the fixture without the two posts either side of the impact (which it strikes), its
 * output at every step. The barrier's work on the vehicle over the run is the vehicle's change of kinetic
 * and potential energy plus its tyres' dissipation (the ledger's vehicle side); no post is struck, so it is
 * the ropes' alone, and the cables' shares must sum to it: within 1e-4 of the initial kinetic energy (they
 * are 2.1e-6 apart: the shares are booked by the trapezoid rule of the ledger's path check, and the
 * vehicle's integrator closes with it to the ledger's balance). Each cable's peak is its largest tension at
 * a commit, so the largest of the series recorded at every step's end, to the bit, when no rope breaks
 * (none does: a break's tension is a peak the series, which has the rope broken, does not hold), no post
 * fails (the posts are given no pullout: a failure's re-solve is a commit inside a step) and no step cut
 * into pieces peaks inside it. */
static void cables_work_sums_to_the_vehicles_loss(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.output_interval = 0.0;
    int n = 0; /* without the posts at 4 ft either side of the impact, which the truck strikes */
    for (int p = 0; p < fx.barrier.post_count; p++)
        if (fabs(fx.posts[p].x - fx.scenario.impact_x) > 10 * FT) fx.posts[n++] = fx.posts[p];
    assert_int_equal(n, fx.barrier.post_count - 2);
    fx.barrier.post_count = n;
    for (int p = 0; p < n; p++) /* no post pulls out: a failure's re-solve inside a step is a commit the */
        fx.posts[p].footing.pullout_capacity = HUGE_VAL; /* series, recorded at steps' ends, does not see */
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    assert_non_null(m);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    double vehicle0 = cs_vehicle_kinetic_energy(m, s) + cs_vehicle_potential_energy(m, s) + s->e_tyre;
    tension_series ts = {.cables = 2};
    assert_int_equal(cs_run(m, s, record_tensions, &ts, &err), CS_OK);
    double vehicle = cs_vehicle_kinetic_energy(m, s) + cs_vehicle_potential_energy(m, s) + s->e_tyre;
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(s, &sm, NULL);
    assert_int_equal(sm.cable_count, 2);
    assert_int_equal(ts.struck, 0);
    double work = 0.0, ke0 = sm.initial_kinetic_energy_j;
    for (int c = 0; c < 2; c++) {
        cs_cable_summary cb = {.size = sizeof cb};
        assert_int_equal(cs_state_cable_summary(s, c, &cb, NULL), CS_OK);
        assert_memory_equal(&cb.peak_tension_n, &sm.cables[c], sizeof sm.cables[c]); /* its first layout */
        printf("cable %d: peak %.1f kN at %.4f s (recorded %.1f kN at %.4f s), work %.1f kJ, share %.4f\n", c,
               cb.peak_tension_n / 1e3, cb.peak_tension_time_s, ts.peak[c] / 1e3, ts.t_peak[c],
               cb.work_on_vehicle_j / 1e3, cb.energy_share);
        assert_true(cb.peak_tension_n == ts.peak[c]);
        assert_true(cb.peak_tension_time_s == ts.t_peak[c]);
        CHECK_REL(cb.energy_share, -cb.work_on_vehicle_j / ke0, 1e-15);
        assert_true(cb.work_on_vehicle_j < 0.0); /* each rope slows the truck */
        work += cb.work_on_vehicle_j;
    }
    CHECK_REL(fmax(sm.cables[0].peak_tension_n, sm.cables[1].peak_tension_n), sm.max_cable_tension_n, 0.0);
    printf("ropes' work %.3f kJ, the vehicle's change %.3f kJ: %.2g of the initial kinetic energy apart\n",
           work / 1e3, (vehicle - vehicle0) / 1e3, (work - (vehicle - vehicle0)) / ke0);
    CHECK_ABS(work, vehicle - vehicle0, 1e-4 * ke0);
    cs_error err2;
    assert_int_equal(
        cs_state_cable_summary(s, 2, &(cs_cable_summary){.size = sizeof(cs_cable_summary)}, &err2),
        CS_ERR_INVALID);
    assert_string_equal(err2.message, "cs_cable_summary: no cable 2 (the run has 2)");
    cs_state_free(s);
    cs_model_free(m);
}

/* ---- the sudden-loss check ---- */

enum { SAMPLES = 401 }; /* 0 to 0.2 s, every 0.5 ms */
#define STEP 0.5e-3
#define PEAK 100e3

/* A force that rises to PEAK by 50 ms, holds it to 100 ms, then falls by `fall` of it over `over` s and
 * holds what is left. */
static void history(double *t, double *f, double fall, double over) {
    int n = (int)lround(over / STEP);
    for (int j = 0; j < SAMPLES; j++) {
        t[j] = j * STEP;
        double x = j <= 100   ? j / 100.0
                   : j <= 200 ? 1.0
                              : 1.0 - fall * (j - 200 < n ? (j - 200) / (double)n : 1.0);
        f[j] = PEAK * x;
    }
}

/* How many windows the check flags in the history of a fall of `fall` of the peak over `over` s, with
 * these events. */
static int losses_in(double fall, double over, const cs_event *events, int n) {
    double t[SAMPLES], f[SAMPLES];
    history(t, f, fall, over);
    cs_sudden_loss w[4] = {{.size = sizeof w[0]}};
    return cs_sudden_losses(t, f, SAMPLES, STEP, events, n, w, 4, NULL);
}

static cs_event event_at(cs_event_type type, double t) {
    return (cs_event){
        .size = sizeof(cs_event), .t = t, .type = type, .element_kind = CS_ELEMENT_CABLE, .cable_end = -1};
}

/* 60% of the peak lost over 5 ms: one window, from the last sample at the peak (100 ms) to the first at
 * 40 kN (105 ms). The windows ending from 104.5 ms (a fall of 54%) to 110.5 ms (54% again, from 100.5 ms)
 * are flagged, one stretch, given by its largest fall (the first to reach it: those after it to 110 ms are
 * as large, no larger). */
static void a_fall_of_60_percent_in_10_ms_is_flagged(void **state) {
    (void)state;
    double t[SAMPLES], f[SAMPLES];
    history(t, f, 0.6, 5e-3);
    cs_sudden_loss w[4] = {{.size = sizeof w[0]}};
    assert_int_equal(cs_sudden_losses(t, f, SAMPLES, STEP, NULL, 0, w, 4, NULL), 1);
    assert_true(w[0].t_start_s == t[200]);
    assert_true(w[0].t_end_s == t[210]);
    assert_true(w[0].force_before_n == PEAK);
    assert_true(w[0].force_after_n == f[210]);
    CHECK_REL(w[0].force_after_n, 0.4 * PEAK, 1e-12);
    /* the events that do not excuse it: a post down in the window, a rope breaking long before */
    cs_event events[2] = {event_at(CS_EVENT_CABLE_BREAK, 0.05),
                          event_at(CS_EVENT_POST_ROTATION_LIMIT, 0.102)};
    assert_int_equal(cs_sudden_losses(t, f, SAMPLES, STEP, events, 2, w, 4, NULL), 1);
    assert_true(w[0].t_start_s == t[200] && w[0].t_end_s == t[210]);
}

/* The same fall over 30 ms: at most 20% of the peak in any 10 ms. */
static void the_same_fall_over_30_ms_is_not(void **state) {
    (void)state;
    assert_int_equal(losses_in(0.6, 30e-3, NULL, 0), 0);
}

/* The 5-ms fall with a rope breaking in its window, or an end fitting or a slot letting go a step past its
 * end, or an anchor pulling out its ropes, or the vehicle riding over or running under a rope: excused. */
static void a_fall_with_a_rope_breaking_is_not(void **state) {
    (void)state;
    const cs_event excusing[] = {
        event_at(CS_EVENT_CABLE_BREAK, 0.1025), event_at(CS_EVENT_TERMINATION_BREAK, 0.1005),
        event_at(CS_EVENT_CABLE_RELEASE, 0.1),  event_at(CS_EVENT_ANCHOR_PULLOUT, 0.101),
        event_at(CS_EVENT_OVERRIDE, 0.102),     event_at(CS_EVENT_UNDERRIDE, 0.103)};
    for (int k = 0; k < 6; k++)
        assert_int_equal(losses_in(0.6, 5e-3, &excusing[k], 1), 0);
    /* the windows flagged end from 104.5 to 110.5 ms: a break at 115 ms is more than a step past them */
    cs_event late = event_at(CS_EVENT_CABLE_BREAK, 0.115);
    assert_int_equal(losses_in(0.6, 5e-3, &late, 1), 1);
}

/* 40% of the peak lost in 5 ms: under half of it. */
static void a_fall_of_40_percent_is_not(void **state) {
    (void)state;
    assert_int_equal(losses_in(0.4, 5e-3, NULL, 0), 0);
}

/* Two falls of 60% (the force rising again between them) are two windows; a fall flagged against the
 * largest force so far but not against the run's (which comes later) is not. */
static void falls_are_judged_against_the_runs_peak(void **state) {
    (void)state;
    double t[SAMPLES], f[SAMPLES];
    for (int j = 0; j < SAMPLES; j++) {
        t[j] = j * STEP;
        f[j] = j < 40 ? PEAK : j < 100 ? 0.4 * PEAK : j < 200 ? PEAK : 0.4 * PEAK;
    }
    cs_sudden_loss w[4] = {{.size = sizeof w[0]}};
    assert_int_equal(cs_sudden_losses(t, f, SAMPLES, STEP, NULL, 0, w, 4, NULL), 2);
    assert_true(w[0].t_start_s == t[39] && w[0].t_end_s == t[40]);
    assert_true(w[1].t_start_s == t[199] && w[1].t_end_s == t[200]);
    for (int j = 300; j < SAMPLES; j++)
        f[j] = 2.5 * PEAK; /* the run's peak, at 150 ms: the falls of 60 kN are 24% of it */
    assert_int_equal(cs_sudden_losses(t, f, SAMPLES, STEP, NULL, 0, w, 4, NULL), 0);
}

/* A stop speed above a tenth of the impact speed would call a vehicle still moving stopped: refused. */
static void a_stop_speed_near_the_impact_speed_is_refused(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    cs_error err;
    fx.scenario.stop_speed = 0.1 * fx.scenario.speed;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    assert_non_null(m);
    cs_model_free(m);
    fx.scenario.stop_speed = 0.11 * fx.scenario.speed;
    assert_null(cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err));
    assert_int_equal(err.status, CS_ERR_INVALID);
    assert_non_null(strstr(err.message, "a tenth of the impact speed"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cables_work_sums_to_the_vehicles_loss),
        cmocka_unit_test(a_fall_of_60_percent_in_10_ms_is_flagged),
        cmocka_unit_test(the_same_fall_over_30_ms_is_not),
        cmocka_unit_test(a_fall_with_a_rope_breaking_is_not),
        cmocka_unit_test(a_fall_of_40_percent_is_not),
        cmocka_unit_test(falls_are_judged_against_the_runs_peak),
        cmocka_unit_test(a_stop_speed_near_the_impact_speed_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
