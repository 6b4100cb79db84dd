/* Cable: the rope law's points, the capstan ratio across a frictional support, frictionless tension
 * redistribution by sliding, and breaking. */
#include "check.h"
#include "fixture.h"
#include "internal.h"
#include "lay.h"

static world *make_world(double mu) {
    static world w;
    fixture_aps3(&w.fx);
    w.fx.cables[0].post_friction = mu;
    cs_error err;
    w.model = cs_model_create(&w.fx.barrier, &w.fx.vehicle, &w.fx.scenario, &err);
    assert_non_null(w.model);
    w.state = cs_state_create(w.model, &err);
    assert_non_null(w.state);
    return &w;
}

static void rope_law_points(void **state) {
    (void)state;
    world *w = make_world(0.15);
    const cs_rope *r = &w->model->cables[0].rope;
    double fu = 91.4 * 1.75 * 1.75 * KIP, ea = 20000 * KSI * 0.471 * 1.75 * 1.75 * IN * IN;
    CHECK_REL(r->fu, fu, 1e-12);
    CHECK_REL(cs_rope_tension(r, 0.6 * fu / ea, 0.0), 0.6 * fu, 1e-12); /* end of the elastic slope */
    double e2 = 0.6 * fu / ea + 0.4 * fu / (0.6 * ea);                  /* strain at nominal strength */
    CHECK_REL(r->e2, e2, 1e-12);
    CHECK_REL(cs_rope_tension(r, e2, 0.0), fu, 1e-12);
    double em = 0.5 * (r->e1 + e2); /* secondary slope 0.6 E */
    CHECK_REL(cs_rope_tension(r, em, 0.0), 0.6 * fu + 0.6 * ea * (em - r->e1), 1e-12);
    CHECK_REL(cs_rope_tension(r, 0.025, 0.0), fu, 1e-12);           /* plastic plateau */
    CHECK_REL(cs_rope_tension(r, 0.004, 0.003), ea * 0.001, 1e-12); /* elastic unloading from a set */
    CHECK_ABS(cs_rope_tension(r, 0.002, 0.003), 0.0, 0.0);          /* slack below the set */
    world_free(w);
}

static void capstan_ratio_on_frictional_support(void **state) {
    (void)state;
    world *w = make_world(0.15);
    const cs_cable_model *cm = &w->model->cables[0];
    double a[3] = {0, 0, 1}, b[3] = {1, 1, 1}, c[3] = {2, 0, 1}; /* the cable turns by 90 degrees at b */
    cs_cable_state *cs = lay_cable(w->state, a, b, c, 0.004, 0.001);
    double total = cs->m[2];
    double viol = cs_cable_slide_node(w->model, cm, cs, 1, 1e-9);
    assert_true(viol > 0.0);
    double tl = cs_span_tension(cm, cs, 0), tr = cs_span_tension(cm, cs, 1);
    CHECK_REL(tl / tr, exp(0.15 * M_PI_2_VALUE), 1e-6); /* Eq. 3: T_high = exp(mu theta) T_low */
    CHECK_REL(cs->m[2], total, 0.0);                    /* rope is conserved */
    assert_true(cs->m[1] > cs->m_commit[1]);            /* rope slid into the tauter span */

    cs = lay_cable(w->state, a, b, c, 0.0021, 0.0020); /* ratio 1.05 < exp(0.15 pi/2) = 1.27: sticks */
    double m1 = cs->m[1];
    CHECK_ABS(cs_cable_slide_node(w->model, cm, cs, 1, 1e-9), 0.0, 0.0);
    CHECK_ABS(cs->m[1], m1, 0.0);
    world_free(w);
}

static void frictionless_sliding_equalises_tension(void **state) {
    (void)state;
    world *w = make_world(0.0);
    const cs_cable_model *cm = &w->model->cables[0];
    double a[3] = {0, 0, 1}, b[3] = {3, 0, 1}, c[3] = {10, 0, 1};
    cs_cable_state *cs = lay_cable(w->state, a, b, c, 0.004, 0.001);
    double total = cs->m[2];
    cs_cable_slide_node(w->model, cm, cs, 1, 1e-12);
    double expect =
        cm->rope.ea * (10.0 / total - 1.0); /* one tension: EA (L / S - 1), Eqs. 1-6 with mu = 0 */
    CHECK_REL(cs_span_tension(cm, cs, 0), expect, 1e-8);
    CHECK_REL(cs_span_tension(cm, cs, 1), expect, 1e-8);
    world_free(w);
}

static void breaking_strain_breaks_the_cable(void **state) {
    (void)state;
    world *w = make_world(0.15);
    double a[3] = {0, 0, 1}, b[3] = {3, 0, 1}, c[3] = {10, 0, 1};
    lay_cable(w->state, a, b, c, 0.029, 0.010);
    cs_cable_commit(w->model, 0, w->state);
    assert_int_equal(cs_cable_check_break(w->model, 0, w->state), 0); /* 0.029 < 0.03: holds, at Fu */
    CHECK_REL(w->state->cables[0].tension[0], w->model->cables[0].rope.fu, 1e-12);
    /* plastic work from the virgin state: T times the plastic strain (e - T/EA) times the rope in the
     * span; span 0 is on the plateau (T = Fu), span 1 on the secondary slope */
    const cs_rope *r = &w->model->cables[0].rope;
    const double *m = w->state->cables[0].m;
    double t0 = r->fu, t1 = r->t1 + r->k2 * (0.010 - r->e1);
    double work = t0 * (0.029 - t0 / r->ea) * m[1] + t1 * (0.010 - t1 / r->ea) * (m[2] - m[1]);
    CHECK_REL(w->state->e_cable_plastic, work, 1e-9);
    lay_cable(w->state, a, b, c, 0.031, 0.010);
    cs_cable_commit(w->model, 0, w->state);
    assert_int_equal(cs_cable_check_break(w->model, 0, w->state), 1);
    assert_int_equal(w->state->cables[0].status, CS_CABLE_BROKEN);
    const cs_event *e = cs_state_event(w->state, cs_state_event_count(w->state) - 1);
    assert_int_equal(e->type, CS_EVENT_CABLE_BREAK);
    world_free(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rope_law_points),
        cmocka_unit_test(capstan_ratio_on_frictional_support),
        cmocka_unit_test(frictionless_sliding_equalises_tension),
        cmocka_unit_test(breaking_strain_breaks_the_cable),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
