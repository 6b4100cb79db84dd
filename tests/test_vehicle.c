/* SPDX-License-Identifier: MIT */
/* Vehicle: where it starts and where its wheels are, free rolling (speed kept, or lost at mu_r g), a sideways
 * slip against the tyres' cornering stiffness and friction, settling on the tyres after a drop (static
 * equilibrium at the design ride height), an undamped bounce against its closed form (second order in
 * dt), a centred head-on impact that makes no yaw, and the turn between two poses (the rotation
 * vector the step's work on the barrier is taken over). */
#include "check.h"
#include "core/vec3.h"
#include "fixture.h"
#include "run/run.h"

static double v3_norm_test(const double *v) {
    return v3_norm(v);
}

static cs_model *model_for(fixture *fx) {
    cs_error err;
    cs_model *m = cs_model_create(&fx->barrier, &fx->vehicle, &fx->scenario, &err);
    if (!m) fail_msg("%s", err.message);
    return m;
}

/* APS3's truck aimed far past the end anchor: it never touches a cable. */
static void open_road(fixture *fx) {
    fixture_aps3(fx);
    fx->scenario.impact_x = 1000.0;
}

static void run_until(const cs_model *m, cs_state *s, double t) {
    cs_error err;
    while (s->t < t - 1e-12 && s->outcome == CS_RUNNING)
        assert_int_equal(cs_step(m, s, &err), CS_OK);
}

/* Where the vehicle starts (cs_scenario_impact_points): at 25 degrees a 2.4-m face meets the cable line over
 * 1.2 / sin 25 = 2.839 m of it, its leading corner first; with impact_at: corner that corner is at impact_x.
 * The start pose puts the face's centre, carried on along the heading, at the centre's impact point, and
 * the wheels where cs_vehicle_wheel_points puts them (the axles a and b from the CG, half the track out,
 * the CG's height down). */
static void the_vehicle_starts_on_its_impact_points(void **state) {
    (void)state;
    for (int at_corner = 0; at_corner < 2; at_corner++) {
        fixture fx;
        fixture_aps3(&fx);
        const double th = 25.0 * CS_PI / 180.0, w = fx.vehicle.front_width, half = 0.5 * w / sin(th);
        fx.scenario.angle = th, fx.scenario.impact_x = 20.0, fx.scenario.impact_at_corner = at_corner;
        double centre, corner;
        cs_scenario_impact_points(&fx.scenario, w, &centre, &corner);
        CHECK_ABS(centre - corner, half, 1e-12);
        CHECK_ABS(at_corner ? corner : centre, 20.0, 1e-12);
        cs_model *m = model_for(&fx);
        double face[3]; /* the face's centre at t = 0, then on along the heading to y = 0 */
        for (int k = 0; k < 3; k++)
            face[k] = m->start_pos[k] + m->dir[k] * fx.vehicle.cg_to_front;
        CHECK_ABS(face[0] - face[1] * m->dir[0] / m->dir[1], centre, 1e-9);
        double wheel[4][3];
        cs_vehicle_wheel_points(&fx.vehicle, wheel);
        const double *fl = wheel[0], *rr = wheel[3];
        CHECK_ABS(fl[0], fx.vehicle.cg_to_front_axle, 0.0);
        CHECK_ABS(rr[0], fx.vehicle.cg_to_front_axle - fx.vehicle.wheelbase, 0.0);
        CHECK_ABS(fl[1] - rr[1], fx.vehicle.track, 1e-12);
        CHECK_ABS(fl[2], -fx.vehicle.cg_height, 0.0);
        for (int i = 0; i < 4; i++)
            for (int k = 0; k < 3; k++)
                CHECK_ABS(m->vehicle.wheel[i][k], wheel[i][k], 0.0);
        cs_model_free(m);
    }
}

static void rolling_freely_keeps_its_speed(void **state) {
    (void)state;
    fixture fx;
    open_road(&fx);
    fx.vehicle.rolling_resistance = 0.0;
    cs_model *m = model_for(&fx);
    cs_state *s = cs_state_create(m, NULL);
    run_until(m, s, 1.0);
    CHECK_REL(v3_norm_test(s->vel), fx.scenario.speed, 1e-9);
    CHECK_ABS(s->pos[2], fx.vehicle.cg_height, 1e-9);
    cs_state_free(s);
    cs_model_free(m);

    fx.vehicle.rolling_resistance = 0.01; /* v(t) = v0 - mu_r g t */
    m = model_for(&fx);
    s = cs_state_create(m, NULL);
    run_until(m, s, 1.0);
    CHECK_REL(fx.scenario.speed - v3_norm_test(s->vel), 0.01 * fx.scenario.gravity * 1.0, 1e-3);
    cs_state_free(s);
    cs_model_free(m);
}

/* The truck of open_road rolling at V with a sideways velocity v_s added across its heading (its ledger
 * told of the energy added). Over its second and third steps (the first kicks with the accelerations found
 * before v_s was added; later the body rolls on its tyres, which moves their contacts) the tyres push back
 * with the cornering force of their slip angle, in all mu m g v_s / sqrt(v_s^2 + (mu V / c)^2), c the
 * cornering stiffness over the load per radian (the loads sum to m g and their moments about the CG
 * cancel: no yaw). At a small angle that is c m g v_s / V, the stiffness; at 11 degrees most of mu m g,
 * saturating. With Coulomb friction alone (mu N at any slip over 0.05 m/s) both would be mu m g. */
static double sideways(fixture *fx, double vs0) {
    fx->vehicle.rolling_resistance = 0.0;
    cs_model *m = model_for(fx);
    cs_state *s = cs_state_create(m, NULL);
    double v = v3_norm_test(s->vel), side[3] = {-s->vel[1] / v, s->vel[0] / v, 0.0}, h = m->scenario.dt,
           at[2];
    for (int k = 0; k < 2; k++)
        s->vel[k] += vs0 * side[k];
    s->e_initial_kinetic += 0.5 * fx->vehicle.mass * vs0 * vs0;
    for (int k = 0; k < 2; k++) {
        run_until(m, s, (1 + 2 * k) * h);
        at[k] = s->vel[0] * side[0] + s->vel[1] * side[1];
    }
    cs_state_free(s);
    cs_model_free(m);
    return (at[0] - at[1]) / (2.0 * h);
}

static void a_rolling_tyre_corners_at_its_stiffness(void **state) {
    (void)state;
    fixture fx;
    open_road(&fx);
    const double c = 0.15 * 180.0 / CS_PI, mu = fx.vehicle.tyre_friction, g = fx.scenario.gravity,
                 v = fx.scenario.speed;
    const double across[2] = {0.1, 0.2 * v};
    for (int k = 0; k < 2; k++) {
        double got = sideways(&fx, across[k]);
        double want = mu * g * across[k] / sqrt(across[k] * across[k] + pow(mu * v / c, 2));
        printf("%.2f m/s across at %.2f m/s: %.4f m/s^2 (%.4f by hand; c g v_s / V %.4f, mu g %.3f)\n",
               across[k], v, got, want, c * g * across[k] / v, mu * g);
        CHECK_REL(got, want, 0.01);
    }
}

/* The 50-ms average deceleration of a run that ends before its first window is full: the window from
 * the run's start with the last speed held, (v_0 - v_end) / 50 ms; here v(t) = v0 - mu_r g t over the
 * run's 30.5 ms (0.61 mu_r g). A run long enough gives mu_r g itself. Without that window the short
 * run would report 0 g. */
static void short_run_has_its_window_average(void **state) {
    (void)state;
    fixture fx;
    open_road(&fx);
    fx.vehicle.rolling_resistance = 0.01;
    const double g_std = 9.80665, mu_g = 0.01 * fx.scenario.gravity;
    for (int k = 0; k < 2; k++) {
        fx.scenario.t_end = k == 0 ? 0.0305 : 0.2;
        cs_model *m = model_for(&fx);
        cs_state *s = cs_state_create(m, NULL);
        run_until(m, s, 1.0);
        cs_summary sm = {.size = sizeof sm};
        cs_state_summary(s, &sm, NULL);
        assert_int_equal(sm.outcome, CS_NO_CONTACT); /* on the open road */
        double span = k == 0 ? sm.t_end_s : 0.05;    /* from the speed at t = 0 */
        printf("t_end %.4f s: max 50-ms average %.6f g at %.4f s\n", fx.scenario.t_end, sm.max_50ms_decel_g,
               sm.t_max_50ms_decel_s);
        CHECK_REL(sm.max_50ms_decel_g, mu_g * span / 0.05 / g_std, 1e-3);
        cs_state_free(s);
        cs_model_free(m);
    }
}

static void dropped_vehicle_settles_on_its_tyres(void **state) {
    (void)state;
    fixture fx;
    open_road(&fx);
    fx.scenario.speed = 0.0;
    fx.scenario.t_end = 10.0;
    cs_model *m = model_for(&fx);
    cs_state *s = cs_state_create(m, NULL);
    s->pos[2] += 0.3; /* dropped from 0.3 m above its ride height: the ledger starts from there */
    cs_vehicle_start(m, s);
    cs_energy_update(m, s);
    s->e_initial_total = cs_energy_total(&s->energy);
    run_until(m, s, 6.0);
    CHECK_ABS(s->pos[2], fx.vehicle.cg_height, 1e-3); /* every tyre back at its static deflection */
    CHECK_ABS(s->vel[2], 0.0, 1e-3);
    cs_state_free(s);
    cs_model_free(m);
}

/* The truck at 40 mph dropped 0.3 m onto the road rolling at 0.2 rad/s, far from the barrier: rebounding, its
 * tyres extend faster than their springs can push, and each damper holds its tyre off the ground while its
 * spring is still compressed. The spring's energy the potential counts then goes to the damper, k comp v_z a
 * second, booked with the tyres: the ledger holds within 1e-4 of the truck's energy over 2 s (3.2e-5 at 0.5
 * ms, halving with the step; without that booking -3.3e-4 at any step). */
static void a_tyre_held_off_by_its_damper_keeps_the_ledger(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.impact_x = 1000.0, fx.scenario.t_end = 3.0;
    fx.vehicle.rolling_resistance = 0.01;
    cs_model *m = model_for(&fx);
    cs_state *s = cs_state_create(m, NULL);
    s->pos[2] += 0.3, s->omega[0] = 0.2; /* rolling as it drops: one side lands first */
    cs_vehicle_start(m, s);
    s->e_initial_kinetic = cs_vehicle_kinetic_energy(m, s);
    cs_energy_update(m, s);
    s->e_initial_total = cs_energy_total(&s->energy);
    double worst = 0.0;
    cs_error err;
    while (s->outcome == CS_RUNNING && s->t < 2.0 - 1e-12) {
        assert_int_equal(cs_step(m, s, &err), CS_OK);
        if (fabs(s->energy.balance_error) > fabs(worst)) worst = s->energy.balance_error;
    }
    printf("dropped at 40 mph: largest balance error %.2e\n", worst);
    CHECK_ABS(worst, 0.0, 1e-4);
    cs_state_free(s);
    cs_model_free(m);
}

/* Bounce on undamped tyres: the axle loads set each tyre's stiffness (k_i = N_i / delta), so heave does
 * not couple to pitch and the CG height is z_ride + a cos(w t) with w = sqrt(g / delta). The error at
 * t = 1 s against that closed form falls four times when the step halves (velocity Verlet, second
 * order; semi-implicit Euler's velocity error would only halve). */
static double bounce_error(double dt) {
    fixture fx;
    open_road(&fx);
    fx.scenario.speed = 0.0;
    fx.scenario.t_end = 10.0;
    fx.scenario.dt = dt;
    fx.vehicle.tyre_damping_ratio = 0.0;
    cs_model *m = model_for(&fx);
    cs_state *s = cs_state_create(m, NULL);
    double delta = fx.vehicle.tyre_static_deflection, a = 0.5 * delta, w = sqrt(fx.scenario.gravity / delta);
    s->pos[2] += a; /* the tyres stay in contact (a < delta) */
    cs_vehicle_start(m, s);
    run_until(m, s, 1.0);
    double z = fx.vehicle.cg_height + a * cos(w * s->t), v = -a * w * sin(w * s->t);
    double err = fabs(s->pos[2] - z) / a + fabs(s->vel[2] - v) / (a * w);
    cs_state_free(s);
    cs_model_free(m);
    return err;
}

static void undamped_bounce_converges_at_second_order(void **state) {
    (void)state;
    double coarse = bounce_error(1e-3), fine = bounce_error(0.5e-3);
    assert_true(coarse < 3e-4);          /* of the amplitude, after about 1.6 periods (measured 1.2e-4) */
    CHECK_REL(coarse / fine, 4.0, 0.02); /* measured 4.0003 */
}

/* A tyre pressed down past its section height bears on its rim. The fixture's truck (tyres undamped, 0.4-m
 * wheels, delta = 0.05 m) on rims of 0.3 m bottoms at a compression s = 0.1 m; sent down at v0 = 1.4 m/s
 * from its ride height it heaves level (each tyre's rate is its share of the weight over delta), so with
 * x = c - delta and the stop 50 times the tyres' rate, energy gives v0^2 delta / g = x^2 + 50 (x - (s -
 * delta))^2: x = 0.0612 m, a largest compression of 0.1112 m, against 0.15 m on tyres alone. The ledger
 * holds, the rims' spring counted with the tyres'. */
static void a_tyre_bottoms_on_its_rim(void **state) {
    (void)state;
    fixture fx;
    open_road(&fx);
    fx.scenario.speed = 0.0;
    fx.scenario.t_end = 10.0;
    fx.vehicle.tyre_damping_ratio = 0.0;
    fx.vehicle.wheel_radius = 0.4;
    const double delta = fx.vehicle.tyre_static_deflection, g = fx.scenario.gravity, v0 = 1.4;
    for (int rim = 0; rim < 2; rim++) {
        fx.vehicle.rim_radius = rim ? 0.3 : 0.0;
        cs_model *m = model_for(&fx);
        cs_state *s = cs_state_create(m, NULL);
        s->vel[2] = -v0;
        cs_vehicle_start(m, s);
        s->e_initial_kinetic = cs_vehicle_kinetic_energy(m, s);
        cs_energy_update(m, s);
        s->e_initial_total = cs_energy_total(&s->energy);
        double deepest = 0.0, worst = 0.0;
        cs_error err;
        while (s->t < 0.3 - 1e-12) {
            assert_int_equal(cs_step(m, s, &err), CS_OK);
            deepest = fmax(deepest, delta + fx.vehicle.cg_height - s->pos[2]);
            if (fabs(s->energy.balance_error) > fabs(worst)) worst = s->energy.balance_error;
        }
        double sp = 0.1 - delta, k = 50.0; /* x^2 + k (x - sp)^2 = v0^2 delta / g, the root past sp */
        double e = v0 * v0 * delta / g, qa = 1.0 + k, qb = -2.0 * k * sp, qc = k * sp * sp - e;
        double x = rim ? (-qb + sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa) : sqrt(e);
        printf("%s: largest compression %.4f m (by hand %.4f m), largest balance error %.1e\n",
               rim ? "on 0.3-m rims" : "no rims", deepest, delta + x, worst);
        CHECK_REL(deepest, delta + x, 0.01);
        CHECK_ABS(worst, 0.0, 1e-4);
        cs_state_free(s);
        cs_model_free(m);
    }
}

/* A centred head-on impact on APS3's two cables between its dead-men (no posts, anchors at face
 * height): mirror symmetry allows no yaw, roll or sideways speed. The barrier solve converges every
 * step to 1e-8 here; what is left is round-off of a solve whose unknowns are not mirror-ordered and
 * whose Jacobian (finite differences in column groups) is reused across steps. */
static void centred_head_on_impact_makes_no_yaw(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    fx.barrier.post_count = 0;
    fx.barrier.start_anchor.z = fx.barrier.end_anchor.z = 1.0;
    fx.scenario.solver_tolerance = 1e-8;
    cs_model *m = model_for(&fx);
    cs_state *s = cs_state_create(m, NULL);
    run_until(m, s, 0.12);
    assert_true(s->contact_started);
    assert_int_equal(s->summary.solver_warnings, 0);
    double roll, pitch, yaw;
    quat_to_euler(s->quat, &roll, &pitch, &yaw);
    CHECK_ABS(yaw, M_PI_2_VALUE, 1e-8);
    CHECK_ABS(roll, 0.0, 1e-8);
    CHECK_ABS(s->vel[0], 0.0, 1e-7); /* m/s after 0.12 s: 6e-9 of the impact speed */
    cs_state_free(s);
    cs_model_free(m);
}

/* A body turned by w dt in its own frame has turned by R(a) w dt in the world's: quat_turn gives that
 * vector back, for a large turn, a tiny one, and either sign of the quaternion. */
static void turn_between_poses_is_the_rotation_vector(void **state) {
    (void)state;
    double a[4], w[3] = {0.4, -1.1, 0.6}, tiny[3] = {3e-10, 1e-10, -2e-10};
    quat_from_yaw(a, 0.7);
    quat_integrate(a, (double[3]){0.2, 0.3, -0.1}, 1.0); /* a general attitude */
    for (int k = 0; k < 2; k++) {
        const double *wb = k ? tiny : w;
        double b[4], want[3], got[3];
        memcpy(b, a, sizeof b);
        quat_integrate(b, wb, 1.0);
        quat_rotate(want, a, wb);
        quat_turn(got, a, b);
        for (int i = 0; i < 3; i++)
            CHECK_ABS(got[i], want[i], 1e-14 + 1e-12 * v3_norm(want));
        for (int i = 0; i < 4; i++)
            b[i] = -b[i];
        quat_turn(got, a, b);
        for (int i = 0; i < 3; i++)
            CHECK_ABS(got[i], want[i], 1e-14 + 1e-12 * v3_norm(want));
    }
}

/* A push that changes at an instant (a failure at a step's end) changes the accelerations as they would be
 * found afresh with the new push: the same linear and angular parts (the moment taken into the body frame,
 * times the inverse inertia), the tyres and the gyroscopic term as they were. The body is pitched, rolled
 * and turning, so that each axis of the moment counts. */
static void a_changed_push_changes_the_accelerations_as_found_afresh(void **state) {
    (void)state;
    fixture fx;
    open_road(&fx);
    cs_model *m = model_for(&fx);
    cs_state *s = cs_state_create(m, NULL);
    double w[3] = {0.4, -0.3, 0.7};
    quat_integrate(s->quat, w, 0.5); /* pitched, rolled and yawed by a few tenths of a radian */
    v3_set(s->omega, 0.2, 0.5, -0.3);
    v3_set(s->force, 1.0e4, -2.0e4, 3.0e3);
    v3_set(s->moment, 2.0e3, 5.0e3, -4.0e3);
    cs_vehicle_start(m, s);
    double old_force[3], old_moment[3], acc[3], ang[3];
    v3_copy(old_force, s->force), v3_copy(old_moment, s->moment);
    v3_set(s->force, -3.0e4, 1.0e4, 8.0e3);
    v3_set(s->moment, -6.0e3, 1.0e3, 7.0e3);
    cs_vehicle_push_changed(m, s, old_force, old_moment);
    v3_copy(acc, s->acc), v3_copy(ang, s->ang_acc);
    cs_vehicle_start(m, s); /* afresh */
    for (int i = 0; i < 3; i++) {
        CHECK_ABS(acc[i], s->acc[i], 1e-12 * (1.0 + fabs(s->acc[i])));
        CHECK_ABS(ang[i], s->ang_acc[i], 1e-12 * (1.0 + fabs(s->ang_acc[i])));
    }
    cs_state_free(s);
    cs_model_free(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_vehicle_starts_on_its_impact_points),
        cmocka_unit_test(rolling_freely_keeps_its_speed),
        cmocka_unit_test(short_run_has_its_window_average),
        cmocka_unit_test(a_rolling_tyre_corners_at_its_stiffness),
        cmocka_unit_test(dropped_vehicle_settles_on_its_tyres),
        cmocka_unit_test(a_tyre_held_off_by_its_damper_keeps_the_ledger),
        cmocka_unit_test(undamped_bounce_converges_at_second_order),
        cmocka_unit_test(a_tyre_bottoms_on_its_rim),
        cmocka_unit_test(centred_head_on_impact_makes_no_yaw),
        cmocka_unit_test(a_changed_push_changes_the_accelerations_as_found_afresh),
        cmocka_unit_test(turn_between_poses_is_the_rotation_vector),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
