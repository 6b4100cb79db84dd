/* A full APS3-like crash (tests/fixture.h): the energy ledger balances, every response parameter is
 * finite, two runs hash to the same final state (determinism), and the run is converged in time. */
#include "check.h"
#include "fixture.h"

static unsigned long long run_aps3_dt(cs_summary *out, double dt) {
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.dt = dt;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_int_equal(cs_run(m, s, NULL, NULL, &err), CS_OK);
    cs_state_summary(s, out);
    unsigned long long h = cs_state_hash(m, s);
    cs_state_free(s);
    cs_model_free(m);
    return h;
}

static unsigned long long run_aps3(cs_summary *out) {
    return run_aps3_dt(out, 0.5e-3);
}

static void ledger_balances_and_run_is_deterministic(void **state) {
    (void)state;
    cs_summary a, b;
    unsigned long long ha = run_aps3(&a), hb = run_aps3(&b);
    assert_true(ha == hb);
    assert_true(a.outcome != CS_RUNNING);
    /* the largest imbalance over the whole run, as a fraction of the initial kinetic energy (issue 2:
     * 1%; measured 0.87%) */
    assert_true(fabs(a.energy_balance_error) <= 0.01);
    CHECK_REL(a.initial_kinetic_energy, 0.5 * 15000 * LB * pow(40 * MPH, 2), 1e-12);
    assert_true(isfinite(a.max_decel_50ms_g) && isfinite(a.max_dynamic_penetration));
    assert_true(a.first_contact_time > 0.0);
}

/* A time step ten times finer changes the response parameters by under 2% (issue 2): the run is
 * converged in time at the default 0.5 ms. */
static void refining_the_time_step_changes_little(void **state) {
    (void)state;
    cs_summary coarse, fine;
    run_aps3_dt(&coarse, 0.5e-3);
    run_aps3_dt(&fine, 0.05e-3);
    assert_int_equal(coarse.outcome, fine.outcome);
    CHECK_REL(coarse.max_dynamic_penetration, fine.max_dynamic_penetration, 0.02);
    CHECK_REL(coarse.max_decel_50ms_g, fine.max_decel_50ms_g, 0.02);
    assert_true(fabs(fine.energy_balance_error) <= 0.01);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(ledger_balances_and_run_is_deterministic),
                                       cmocka_unit_test(refining_the_time_step_changes_little)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
