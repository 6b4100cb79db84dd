/* SPDX-License-Identifier: MIT */
/* Post sections in bending (src/elements/section.c): a hollow one at Zx Fy and E Ix; a tube filled with
 * concrete by AISC 360-16's plastic stress distribution, checked against a fibre model of the section and
 * the hand calculation of docs/theory.md ("A tube filled with concrete": APS1's anchor posts). */
#include "check.h"
#include "fixture.h"
#include "run/run.h"

#define PSI (KSI / 1000.0)

/* The fibre model: the square-cornered tube cut into n strips along its depth, each cut again where the
 * flanges end and where the neutral axis runs, each piece's steel at +-Fy and its core at 0.85 f'c in
 * compression; the axis found by bisection on the net force, the moment taken about it. Independent of
 * section.c's closed form. */
/* The forces (sign > 0: their net, compression positive) or the moment about a (sign 0) over [y0, y1]. */
static double pieces(const cs_section_def *s, double fc, double a, double y0, double y1, int moment) {
    double b = s->width, h = s->depth, t = s->wall, cuts[] = {y0, t, h - t, a, y1}, sum = 0.0;
    for (int i = 0; i < 2; i++) /* order the three inner cuts */
        for (int k = 1; k < 3; k++)
            if (cuts[k] > cuts[k + 1]) {
                double c = cuts[k];
                cuts[k] = cuts[k + 1], cuts[k + 1] = c;
            }
    for (int k = 0; k < 4; k++) {
        double lo = fmax(cuts[k], y0), hi = fmin(cuts[k + 1], y1);
        if (!(hi > lo)) continue;
        double y = 0.5 * (lo + hi), dy = hi - lo;
        int flange = y < t || y > h - t, above = y < a;
        double steel = (flange ? b : 2.0 * t) * dy * s->yield_stress,
               core = flange ? 0.0 : (b - 2.0 * t) * dy * 0.85 * fc;
        double f = above ? steel + core : -steel;
        sum += moment ? fabs(f) * fabs(y - a) : f;
    }
    return sum;
}

static double fibre_moment(const cs_section_def *s, double fc, int n) {
    double h = s->depth, lo = 0.0, hi = h, a = 0.5 * h;
    for (int it = 0; it < 200; it++) {
        a = 0.5 * (lo + hi);
        double net = 0.0;
        for (int k = 0; k < n; k++)
            net += pieces(s, fc, a, k * h / n, (k + 1) * h / n, 0);
        if (net > 0.0)
            hi = a;
        else
            lo = a;
    }
    double m = 0.0;
    for (int k = 0; k < n; k++)
        m += pieces(s, fc, a, k * h / n, (k + 1) * h / n, 1);
    return m;
}

static void a_hollow_section_bends_at_zx_fy(void **state) {
    (void)state;
    cs_section_def s = fixture_hss();
    CHECK_REL(cs_section_plastic_moment(&s), s.plastic_modulus * s.yield_stress, 1e-15);
    CHECK_REL(cs_section_flexural_rigidity(&s), s.modulus * s.inertia, 1e-15);
    /* the square-cornered tube's own Z = b t (h - t) + t (h - 2t)^2 / 2 (the fixture's Zx) from the fibres */
    CHECK_REL(fibre_moment(&s, 0.0, 400), s.plastic_modulus * s.yield_stress, 1e-10);
}

/* APS1's anchor posts: HSS 4 x 4 x 1/8 (t = 0.116 in, Fy 46 ksi) filled with 3,000-psi concrete. By hand:
 * a = (2 x 0.116 x 4 x 46 + 0.85 x 3 x 3.768 x 0.116) / (4 x 0.116 x 46 + 0.85 x 3 x 3.768) = 1.415 in;
 * the fill adds 11.76 kip-in to the tube's Z Fy (120.78 kip-in by square corners), so that the post
 * holds 2.631 x 46 + 11.76 = 132.79 kip-in (15.00 kN m) against 121.03 (13.67 kN m) hollow, 9.7% more. */
static void a_filled_tube_takes_the_plastic_stress_distribution(void **state) {
    (void)state;
    cs_section_def s = fixture_hss();
    s.plastic_modulus = 2.631 * IN * IN * IN; /* data/sections.yaml's HSS4x4x1/8, its design wall */
    s.wall = 0.116 * IN;
    s.fill_strength = 3000 * PSI;
    double kip_in = KIP * IN, added = fibre_moment(&s, s.fill_strength, 400) - fibre_moment(&s, 0.0, 400);
    CHECK_REL(cs_section_plastic_moment(&s) - s.plastic_modulus * s.yield_stress, added, 1e-10);
    CHECK_REL(added / kip_in, 11.76, 1e-3);
    CHECK_REL(cs_section_plastic_moment(&s) / kip_in, 132.79, 1e-4);
    /* stiffness: Ec = 0.043 x 2300^1.5 x sqrt(20.68 MPa) = 21,571 MPa; C3 = 0.45 + 3 As / Ag = 0.7879 with
     * As = 16 - 3.768^2 = 1.802 in^2; Ic = 3.768^4 / 12 = 16.80 in^4: C3 Ec Ic = 118.84 kN m^2 on the
     * steel's E Ix = 29,000 ksi x 4.544 in^4 = 378.17 kN m^2, 1.314 times */
    s.inertia = 4.544 * pow(IN, 4);
    CHECK_REL(cs_section_flexural_rigidity(&s) / (s.modulus * s.inertia), 1.31424, 1e-4);
    /* the fill carries no tension: a stronger concrete moves the axis up and adds less than in proportion */
    cs_section_def twice = s;
    twice.fill_strength = 6000 * PSI;
    double more = cs_section_plastic_moment(&twice) - s.plastic_modulus * s.yield_stress;
    assert_true(more > added && more < 2.0 * added);
    CHECK_REL(more, fibre_moment(&twice, twice.fill_strength, 400) - fibre_moment(&twice, 0.0, 400), 1e-10);
}

/* The model takes the filled post's moment, and refuses a fill the method does not cover. */
static void the_model_holds_a_filled_post_and_refuses_what_the_method_cannot(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    int p = 6; /* an intermediate anchor post (HSS) */
    fx.posts[p].section.fill_strength = 3000 * PSI;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    CHECK_REL(m->posts[p].mp, cs_section_plastic_moment(&fx.posts[p].section), 1e-15);
    assert_true(m->posts[p].mp >
                1.09 * fx.posts[p].section.plastic_modulus * fx.posts[p].section.yield_stress);
    cs_model_free(m);
    struct {
        double width, wall, fill;
        const char *why;
    } bad[] = {{0.0, 0.116, 3000, "needs its tube's width, depth and wall"},
               {4.0, 2.5, 3000, "needs its tube's width, depth and wall"},
               {4.0, 0.116, 2000, "outside 3-10 ksi"},
               {12.0, 0.116, 3000, "not compact (b/t 100"}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        fixture_aps3(&fx);
        cs_section_def *s = &fx.posts[p].section;
        s->width = s->depth = bad[k].width * IN;
        s->wall = bad[k].wall * IN;
        s->fill_strength = bad[k].fill * PSI;
        assert_null(cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err));
        assert_int_equal(err.status, CS_ERR_INVALID);
        if (!strstr(err.message, bad[k].why)) fail_msg("'%s' lacks '%s'", err.message, bad[k].why);
        if (!strstr(err.message, "post 6")) fail_msg("'%s' does not name post 6", err.message);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_hollow_section_bends_at_zx_fy),
        cmocka_unit_test(a_filled_tube_takes_the_plastic_stress_distribution),
        cmocka_unit_test(the_model_holds_a_filled_post_and_refuses_what_the_method_cannot),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
