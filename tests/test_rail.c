/* SPDX-License-Identifier: MIT */
/* Rails (src/elements/rail.c): each span an axial member between neighbouring posts, elastic, yielding
 * at A Fy in tension and buckling at the Euler load in compression, its pull entering the posts' moment
 * balance. */
#include "check.h"
#include "fixture.h"
#include "run/run.h"

/* APS3's first two line posts (8 and 16 ft, hinging at grade) tied by one rail at 4 ft. */
static cs_model *two_posts(fixture *fx) {
    fixture_aps3(fx);
    fixture_rails(fx);
    fx->rails[0] = fx->rails[2]; /* the rail at 4 ft */
    fx->barrier.rail_count = 1;
    cs_error err;
    cs_model *m = cs_model_create(&fx->barrier, &fx->vehicle, &fx->scenario, &err);
    if (!m) fail_msg("%s", err.message);
    return m;
}

/* With post 0 leaning away from post 1 by a (its base, the pivot, at grade) and post 1 upright, the rail
 * runs from (x0 - z sin a, 0, z cos a) to (x1, 0, z): N = EA / L0 (l - L0) up to A Fy = 154.1 kN in
 * tension and down to -pi^2 E I / L0^2 = -42.41 kN in compression (E = 29,000 ksi, I = 0.307 in4,
 * L0 = 8 ft); the moment on the upright post 1 about its base is -z N dx / l (its axis' Jacobian upright
 * is the identity); the span's stored energy N^2 L0 / (2 EA), the only span strained. */
static void rail_force_follows_its_law(void **state) {
    (void)state;
    fixture fx;
    cs_model *m = two_posts(&fx);
    cs_error err;
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    const cs_rail_def *d = &fx.rails[0];
    double z = d->height, l0 = 8.0 * FT, ea = d->modulus * d->area, py = d->area * d->yield_stress;
    double pcr = 9.869604401089358 * d->modulus * d->inertia / (l0 * l0);
    CHECK_REL(py, 154.1e3, 1e-3);
    CHECK_REL(pcr, 42.41e3, 1e-3);
    const double leans[] = {1e-4, 0.05, -1e-4, -0.01};
    const double expect_n[] = {NAN, py, NAN, -pcr}; /* NAN: elastic, EA / L0 (l - L0) */
    for (int k = 0; k < 4; k++) {
        double a = leans[k], dx = l0 + z * sin(a), dz = z * (1.0 - cos(a));
        double l = sqrt(dx * dx + dz * dz), n = isnan(expect_n[k]) ? ea / l0 * (l - l0) : expect_n[k];
        for (int p = 0; p < m->post_count; p++)
            s->posts[p].tilt[0] = s->posts[p].tilt[1] = 0.0;
        s->posts[0].tilt[0] = -a;
        double j[6], dj[12], up[2] = {0.0, 0.0}, q[2] = {0.0, 0.0};
        cs_post_axis_jacobian(up, j, dj);
        cs_rail_moment(m, s, 1, up, j, q);
        CHECK_REL(q[0], -z * n * dx / l, 1e-9);
        CHECK_ABS(q[1], 0.0, 1e-12);
        cs_rail_commit(m, s); /* the elastic energy as committed (a capped span keeps its force) */
        CHECK_REL(s->e_rail_elastic, n * n * l0 / (2.0 * ea), 1e-9);
        memset(s->rail_plastic, 0, (size_t)m->post_count * sizeof *s->rail_plastic);
    }
    cs_state_free(s);
    cs_model_free(m);
}

/* Stretched past its yield, a span keeps the stretch beyond N L0 / EA as its plastic set, and its plastic
 * work is A Fy times that set; let back to where it was, it is in compression by EA / L0 times the set,
 * capped at the buckling load. */
static void rail_yields_and_keeps_its_set(void **state) {
    (void)state;
    fixture fx;
    cs_model *m = two_posts(&fx);
    cs_error err;
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    const cs_rail_def *d = &fx.rails[0];
    double z = d->height, l0 = 8.0 * FT, ea = d->modulus * d->area, py = d->area * d->yield_stress, a = 0.05;
    for (int p = 0; p < m->post_count; p++)
        s->posts[p].tilt[0] = s->posts[p].tilt[1] = 0.0;
    s->posts[0].tilt[0] = -a;
    double dx = l0 + z * sin(a), dz = z * (1.0 - cos(a)), l = sqrt(dx * dx + dz * dz);
    double set = l - l0 - py * l0 / ea, work = s->e_rail_plastic;
    cs_rail_commit(m, s);
    CHECK_REL(s->rail_plastic[0], set, 1e-9);
    CHECK_REL(s->e_rail_plastic - work, py * set, 1e-9);
    s->posts[0].tilt[0] = 0.0; /* back upright: shortened by the set, it buckles */
    double j[6], dj[12], up[2] = {0.0, 0.0}, q[2] = {0.0, 0.0};
    cs_post_axis_jacobian(up, j, dj);
    cs_rail_moment(m, s, 1, up, j, q);
    double pcr = 9.869604401089358 * d->modulus * d->inertia / (l0 * l0);
    CHECK_REL(q[0], z * fmin(ea / l0 * set, pcr), 1e-9);
    cs_state_free(s);
    cs_model_free(m);
}

/* Half of each rail span's steel swings with each of its posts: a post between two 8-ft spans carries
 * 8 ft of the rail at its height, m z^2 added to its inertia about its base; the first post, with one
 * span, 4 ft. */
static void rails_add_their_mass_to_the_posts(void **state) {
    (void)state;
    fixture fx, bare;
    cs_model *m = two_posts(&fx);
    fixture_aps3(&bare);
    cs_error err;
    cs_model *b = cs_model_create(&bare.barrier, &bare.vehicle, &bare.scenario, &err);
    if (!b) fail_msg("%s", err.message);
    double z = fx.rails[0].height, mass = fx.rails[0].mass_per_length * 8.0 * FT;
    CHECK_REL(m->posts[1].inertia - b->posts[1].inertia, mass * z * z, 1e-12);
    CHECK_REL(m->posts[0].inertia - b->posts[0].inertia, 0.5 * mass * z * z, 1e-12);
    cs_model_free(b);
    cs_model_free(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(rail_force_follows_its_law),
                                       cmocka_unit_test(rail_yields_and_keeps_its_set),
                                       cmocka_unit_test(rails_add_their_mass_to_the_posts)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
