/* SPDX-License-Identifier: MIT */
/* Stress: random but valid designs and attacks, from a fixed seed, over realistic and extreme ranges
 * (rope sizes, post spacing, cables, vehicle sizes, speeds 5-60 mph, angles 15-90 degrees, impact
 * anywhere along the barrier including at an anchor and past its end). Every run must end without an
 * error, with finite response parameters and an energy ledger within 2%. CS_STRESS_RUNS in
 * the environment sets how many (default 24, short runs) and CS_STRESS_FROM the first design; the
 * generator gives design k the same whatever the run count. The default subset is designs 0-23, plus
 * the designs kept as regressions (docs/robustness.md). */
#include "check.h"
#include "design.h"

#include <stdlib.h>
#include <string.h>

/* Runs design k (with fittings that slip drawn for it if `slip`, their termination_slip events added to
 * *slipped); returns 1 (and says why) if it errs, leaves a non-finite response or a ledger off by more
 * than 2%. */
static int design_runs_badly(int k, int slip, int *slipped) {
    design d;
    design_numbered(k, &d);
    if (slip) {
        design_source src = {0x511b0000ULL + (unsigned long long)k, NULL, 0, 0};
        int ends = design_add_slip(&src, &d);
        size_t at = strlen(d.what);
        snprintf(d.what + at, sizeof d.what - at, ", %d ends slip", ends);
    }
    cs_error err;
    cs_model *m = cs_model_create(&d.fx.barrier, &d.fx.vehicle, &d.fx.scenario, &err);
    if (!m) {
        printf("FAIL %s: refused: %s\n", d.what, err.message);
        return 1;
    }
    cs_state *s = cs_state_create(m, &err);
    cs_status st = cs_run(m, s, NULL, NULL, &err);
    for (int i = 0; slipped && i < cs_state_event_count(s); i++) {
        cs_event e = {.size = sizeof e};
        cs_state_event(s, i, &e, NULL);
        *slipped += e.type == CS_EVENT_TERMINATION_SLIP;
    }
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(s, &sm, NULL);
    int finite = isfinite(sm.max_50ms_decel_g) && isfinite(sm.max_dynamic_penetration_m) &&
                 isfinite(sm.max_barrier_deflection_m) && isfinite(sm.energy_balance_error);
    int fails = st != CS_OK || !finite || fabs(sm.energy_balance_error) > 0.02;
    if (fails)
        printf("FAIL %s: %s, ledger %.4f, %s\n", d.what, st == CS_OK ? "ran" : err.message,
               sm.energy_balance_error, finite ? "finite" : "NOT finite");
    cs_state_free(s);
    cs_model_free(m);
    return fails;
}

static int design_fails(int k) {
    return design_runs_badly(k, 0, NULL);
}

/* Designs CS_STRESS_FROM (0) on, CS_STRESS_RUNS (24) of them, with fittings that slip if `slip` (their
 * slips counted in *slipped): how many run badly. */
static int random_designs_failing(int slip, int *slipped) {
    const char *env = getenv("CS_STRESS_RUNS"), *from_env = getenv("CS_STRESS_FROM");
    int runs = env ? atoi(env) : 24, from = from_env ? atoi(from_env) : 0, failures = 0;
    for (int k = from; k < from + runs; k++)
        failures += design_runs_badly(k, slip, slipped);
    printf("%d random designs%s, %d failures\n", runs, slip ? " with slipping fittings" : "", failures);
    return failures;
}

static void random_designs_run_clean(void **state) {
    (void)state;
    assert_int_equal(random_designs_failing(0, NULL), 0);
}

/* The same designs with fittings that slip at about half their rope ends (design_add_slip): every run
 * ends without an error, finite, its ledger within 2%; and fittings do slip in them (in designs 0-23, 8
 * termination_slip events). */
static void random_designs_with_slipping_fittings_run_clean(void **state) {
    (void)state;
    int slipped = 0;
    assert_int_equal(random_designs_failing(1, &slipped), 0);
    printf("%d fittings slipped\n", slipped);
    assert_true(slipped > 0);
}

/* Designs whose ledger once missed 2% and now balances, kept as regressions: 142 and 195, where a
 * struck post leaves the ropes' paths and the stored energy it releases once went unbooked
 * (docs/theory.md, "A step", 5); 76, 78 and 105, where the barrier snaps to a lower equilibrium within
 * one step (once -2.7% each), and 99, where a step's end state booked more friction and
 * plastic work than the barrier was given (+2.2%) (docs/theory.md, "A step", following the path);
 * 583, 4765 and 7855, small cars under the ropes pushing a post whose push did less work than the post
 * took (+10%, +24%, and the energy guard's error) until the push became the gradient of the post's work
 * (docs/theory.md, "posts struck by the face"); 3057 and 7839, rebounding vehicles whose ropes engaged
 * and released a corner of a pitched face every step (+3.4%, +6.4%) until both tests were made in 3D
 * (docs/theory.md, Contact); 1804, a car whose sliding tyres the path check took for barrier energy
 * (+4.9%) (docs/theory.md, Energy ledger); 6305 and 9637, where an eighth of a step converged onto a
 * branch the path never reached (+6.5%, +3.3%) until such an eighth was cut again into 64ths
 * (docs/theory.md, "A step", two levels); 2004, 2346, 5438 and 6270, where an end post on its plateau,
 * bent over by the ropes' pull down to the anchor, had no equilibrium near its tilt and every solve
 * stalled (+14%, +15%, +4.3%, +8.4%) until such a post was let fall to the next one (docs/theory.md,
 * "Posts", falling); 5498, where a fall kept because it stored less than the failed solve led to a
 * state whose commit booked 11 kJ more than the ropes gave up (+3.1%), and 1648, where 64ths starting
 * from a failed one converged onto the rope at its strength and the last was committed (the energy
 * guard's error at +262%), on the way there (docs/theory.md, "A step", no wild iterate); 7332, a
 * small car whose face corner reached the end anchor, a 2-cm span between them, where 64ths whose
 * solves failed each made up to 1e-3 of the energy scale (+2.9% over five steps) until that allowance
 * was scaled to the piece's length, and 64ths committed at residuals near 1e-3 made about 5 J each
 * (+2.6%) until every 64th that missed the solver tolerance was checked (docs/theory.md, "A step", no wild
 * iterate); 57, 525, 767 and 932, struck beside the start anchor, where the front corner nearer the
 * anchor was let go (the rope rising from the anchor at grade under the body turns out through the side
 * there) and taken up again at every update, each time from a contact set afresh, so that its slides
 * were booked from the wrong place (-3.0%, -3.6%, -4.4% and the 5% stop) until a corner taken up again
 * went on from where the rope was on it (docs/theory.md, Contact); 4824, 5358, 12245 and 20451, small cars
 * struck beside an anchor whose dead-man went on ringing between its soil and the ropes, part of what
 * backward Euler damped unbooked (-2.3% to -4.7%); the dead-men move by HHT-alpha, which keeps such a
 * slow ringing and books what it takes (docs/theory.md, Anchorage in the soil); 6169, 7624 and 14314, cars
 * sliding along a rope that runs nearly straight past a corner of the body, where the rounded friction switch
 * let the tension difference take either sign and its absolute value booked friction no tension paid for
 * (+2.4% to +3.7%) until it was booked with its sign (docs/theory.md, Capstan friction); 13527 and 90615,
 * small cars whose front corner took up a slack rope where it hangs, which splits its chord and moved the
 * sag's reference with no work done
 * (+8.1%, the 5% stop; +2.5%) until that was booked with the released energy (docs/theory.md, Contact);
 * 18787 and 54424, posts swinging hard against their rails or ropes, the end-point share of their
 * backward Euler damping unbooked (-2.2%, -2.0%) until it was booked; 59917, where the last 64th of a
 * step converged onto a rope stretched to its strength with no work done on it (+45%, the 5% stop) until
 * a converged piece that would make more than the ledger's failure threshold was sent back
 * (docs/theory.md, "A step", no wild iterate); 24487 and 39237, where an end post sliding out of its
 * footing was committed by the fallback solve with its pull where a stalled Newton had left it, out of
 * balance by the slide's inertial force, and the commit booked slides of 34-84 m/s as its motion and
 * damping (+4.05%, and the 5% stop at +10.2%) until the fallback solved the pull (docs/theory.md, The
 * barrier solve, Gauss-Seidel). */
static void kept_designs_balance(void **state) {
    (void)state;
    const int kept[] = {57,    76,    78,    99,    105,   142,   195,   525,   583,  767,
                        932,   1648,  1804,  2004,  2346,  3057,  4765,  4824,  5358, 5438,
                        5498,  6169,  6270,  6305,  7332,  7624,  7839,  7855,  9637, 12245,
                        13527, 14314, 18787, 20451, 24487, 39237, 54424, 59917, 90615};
    int failures = 0;
    for (size_t i = 0; i < sizeof kept / sizeof *kept; i++)
        failures += design_fails(kept[i]);
    assert_int_equal(failures, 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(random_designs_run_clean),
                                       cmocka_unit_test(random_designs_with_slipping_fittings_run_clean),
                                       cmocka_unit_test(kept_designs_balance)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
