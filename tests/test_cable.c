/* SPDX-License-Identifier: MIT */
/* Cable: the rope law's points, the capstan ratio across a frictional support, frictionless tension
 * redistribution by sliding, breaking at the breaking strain and at an end fitting, the rope's end at the
 * post next to its anchor. */
#include "check.h"
#include "core/vec3.h"
#include "fixture.h"
#include "lay.h"
#include "run/run.h"

/* The paper's closed forms (Eqs. 1-6) are for a weightless rope: the cable of these worlds weighs
 * `weighs` times its A603 weight (0 or 1). */
static world *make_world_ended(double mu, double weighs, double termination) {
    static world w;
    fixture_aps3(&w.fx);
    w.fx.cables[0].post_friction = mu;
    w.fx.cables[0].termination_efficiency = termination;
    w.fx.cables[0].rope.mass_per_length *= weighs;
    cs_error err;
    w.model = cs_model_create(&w.fx.barrier, &w.fx.vehicle, &w.fx.scenario, &err);
    assert_non_null(w.model);
    w.state = cs_state_create(w.model, &err);
    assert_non_null(w.state);
    return &w;
}

static world *make_world_weighing(double mu, double weighs) {
    return make_world_ended(mu, weighs, 0.90);
}

static world *make_world(double mu) {
    return make_world_weighing(mu, 0.0);
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
    double total = cs->m[2] - cs->m[0], l = sqrt(2.0), ratio = exp(0.15 * M_PI_2_VALUE);
    double viol = cs_relax_slide_node(w->model, cm, cs, 1, 1e-9);
    assert_true(viol > 0.0);
    double tl = cs_span_tension(cm, cs, 0), tr = cs_span_tension(cm, cs, 1);
    CHECK_REL(tl / tr, ratio, 1e-6); /* Eq. 3: T_high = exp(mu theta) T_low */
    /* where the rope ends up: the left span's share s1 of the rope meets l / s1 - 1 = R (l / (S - s1) - 1)
     * (Eqs. 1-3 for two spans of chord l), found here by bisection */
    double lo = l / 1.01, hi = l;
    for (int k = 0; k < 200; k++) {
        double s1 = 0.5 * (lo + hi), g = (l / s1 - 1.0) - ratio * (l / (total - s1) - 1.0);
        if (g > 0.0)
            lo = s1;
        else
            hi = s1;
    }
    CHECK_REL(cs->m[1] - cs->m[0], 0.5 * (lo + hi), 1e-9);
    assert_true(cs->m[1] > cs->m_commit[1]); /* rope slid into the tauter span */

    cs = lay_cable(w->state, a, b, c, 0.0021, 0.0020); /* ratio 1.05 < exp(0.15 pi/2) = 1.27: sticks */
    double m1 = cs->m[1];
    CHECK_ABS(cs_relax_slide_node(w->model, cm, cs, 1, 1e-9), 0.0, 0.0);
    CHECK_ABS(cs->m[1], m1, 0.0);
    world_free(w);
}

/* From the geometry alone, at turns from 1e-7 rad to nearly pi, the capstan ratio is exp(mu theta) and
 * the friction band's fraction tanh(mu theta / 2) to round-off (the turning angle is accurate near 0
 * and near pi). */
static void capstan_band_at_small_and_large_turns(void **state) {
    (void)state;
    world *w = make_world(0.15);
    const cs_cable_model *cm = &w->model->cables[0];
    static const double turns[] = {1e-7,  1e-3,  0.00999, 0.01001, 0.03,  0.0996, 0.0997, 0.1,
                                   0.133, 0.134, 0.5,     0.666,   0.667, 0.7,    2.0,    3.1};
    for (size_t k = 0; k < sizeof turns / sizeof turns[0]; k++) {
        double th = turns[k], a[3] = {0, 0, 1}, b[3] = {2, 0, 1}, c[3] = {2 + 3 * cos(th), 3 * sin(th), 1};
        lay_cable(w->state, a, b, c, 0.002, 0.002);
        CHECK_REL(exp(cs_node_capstan_exponent(w->model, cm, &w->state->cables[0], 1, NULL)), exp(0.15 * th),
                  1e-14);
        CHECK_REL(cs_node_band_fraction(w->model, cm, &w->state->cables[0], 1, NULL), tanh(0.075 * th),
                  1e-14);
    }
    world_free(w);
}

static void frictionless_sliding_equalises_tension(void **state) {
    (void)state;
    world *w = make_world(0.0);
    const cs_cable_model *cm = &w->model->cables[0];
    double a[3] = {0, 0, 1}, b[3] = {3, 0, 1}, c[3] = {10, 0, 1};
    cs_cable_state *cs = lay_cable(w->state, a, b, c, 0.004, 0.001);
    double total = cs->m[2];
    cs_relax_slide_node(w->model, cm, cs, 1, 1e-12);
    double expect =
        cm->rope.ea * (10.0 / total - 1.0); /* one tension: EA (L / S - 1), Eqs. 1-6 with mu = 0 */
    CHECK_REL(cs_span_tension(cm, cs, 0), expect, 1e-8);
    CHECK_REL(cs_span_tension(cm, cs, 1), expect, 1e-8);
    world_free(w);
}

/* Length of a catenary of horizontal tension h and weight w per length between level supports l apart. */
static double catenary_length(double h, double w, double l) {
    return 2.0 * h / w * sinh(w * l / (2.0 * h));
}

/* The horizontal tension at which a rope of s unstretched (axial stiffness ea) hangs as a catenary
 * between level supports l apart: its arc, stretched by h / ea, is the catenary's length (bisection). */
static double catenary_tension(double s, double ea, double w, double l) {
    double lo = 1e-3, hi = 1e9;
    for (int it = 0; it < 200; it++) {
        double h = sqrt(lo * hi);
        if (catenary_length(h, w, l) > s * (1.0 + h / ea))
            lo = h; /* too little tension: the catenary is longer than the rope */
        else
            hi = h;
    }
    return sqrt(lo * hi);
}

/* A rope hangs by its own weight: between level supports each span holds the tension of the catenary
 * its rope makes, slack or taut. The span law uses the parabola, which is off by about (w l / T)^2 / 80
 * of the tension: 3e-4 for the slackest span here (1.7 kN), so 1e-3 slack spans; a taut span's weight
 * moves its tension by about EA w^2 l^2 / (24 T^2) (11 N in 256 kN), which the 1e-6 check resolves. */
static void sagging_span_hangs_as_a_catenary(void **state) {
    (void)state;
    world *w = make_world_weighing(0.15, 1.0);
    const cs_cable_model *cm = &w->model->cables[0];
    double weight = w->fx.cables[0].rope.mass_per_length * w->fx.scenario.gravity;
    CHECK_REL(cm->rope.w, weight, 1e-12);
    double a[3] = {0, 0, 1}, b[3] = {5, 0, 1}, c[3] = {10, 0, 1};
    const double strain[3][2] = {{-0.002, -0.0005}, {0.002, 0.0}, {0.0, 0.0}};
    const double tol[3][2] = {{1e-3, 1e-3}, {1e-6, 1e-3}, {1e-3, 1e-3}};
    for (int k = 0; k < 3; k++) {
        cs_cable_state *cs = lay_cable(w->state, a, b, c, strain[k][0], strain[k][1]);
        for (int i = 0; i < 2; i++) {
            double s = cs->m[i + 1] - cs->m[i];
            double h = catenary_tension(s, cm->rope.ea, weight, 5.0);
            CHECK_REL(cs_span_tension(cm, cs, i), h, tol[k][i]);
        }
    }
    /* the pretension is the tension the spans hold at the start, their sag included */
    cs_state_reset(w->model, w->state);
    const cs_cable_state *c0 = &w->state->cables[0];
    for (int i = 0; i + 1 < c0->node_count; i++)
        CHECK_REL(c0->tension[i], w->fx.cables[0].pretension, 1e-9);
    /* a span laid exactly to its chord sags by l^2 w / (8 T) with T = (EA w^2 l^2 / 24)^(1/3) */
    cs_cable_state *cs = lay_cable(w->state, a, b, c, 0.0, 0.0);
    CHECK_REL(cs_span_tension(cm, cs, 0), cbrt(cm->rope.ea * weight * weight * 25.0 / 24.0), 1e-9);
    world_free(w);
}

/* A sagging span's tension is the root of T^2 (T - a) = c (a = EA e, c = EA q / 24 s): from each of its
 * starts (strains from 3e-3 to -1e-2 over a 5-m span start from every bound), the root is met to
 * round-off. */
static void sag_tension_solves_its_cubic(void **state) {
    (void)state;
    world *w = make_world_weighing(0.15, 1.0);
    const cs_cable_model *cm = &w->model->cables[0];
    double a[3] = {0, 0, 1}, b[3] = {5, 0, 1}, c[3] = {10, 0, 1};
    const double strains[] = {3e-3,  1e-3,  4e-4,  3.5e-4, 2e-4,  1e-4,  2e-5, 0.0,
                              -2e-5, -1e-4, -2e-4, -5e-4,  -1e-3, -2e-3, -1e-2};
    for (size_t k = 0; k < sizeof strains / sizeof strains[0]; k++) {
        cs_cable_state *cs = lay_cable(w->state, a, b, c, strains[k], 0.0);
        double s = cs->m[1] - cs->m[0], e = 5.0 / s - 1.0, ea = cm->rope.ea;
        double lin = ea * e, cub = ea * cm->rope.w * cm->rope.w * 125.0 / (24.0 * s);
        double t = cs_span_tension(cm, cs, 0);
        assert_true(t > 0.0 && t < cm->rope.t1); /* on the elastic slope */
        CHECK_ABS((t * t * (t - lin) - cub) / (t * t * (t + fabs(lin)) + cub), 0.0, 1e-14);
    }
    world_free(w);
}

/* With fittings as strong as the rope (a poured socket, 100%), the rope breaks where it is strained to
 * its breaking strain. */
static void breaking_strain_breaks_the_cable(void **state) {
    (void)state;
    world *w = make_world_ended(0.15, 0.0, 1.0);
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
    const cs_event *e = &w->state->events[cs_state_event_count(w->state) - 1];
    assert_int_equal(e->type, CS_EVENT_CABLE_BREAK);
    world_free(w);
}

/* Lay cable 0 as anchor, post, post, anchor (3-m spans along x) with the spans at strains e, and commit. */
static cs_cable_state *lay_ends(world *w, const double *e) {
    cs_cable_state *cs = &w->state->cables[0];
    double p[4][3] = {{0, 0, 1}, {3, 0, 1}, {6, 0, 1}, {9, 0, 1}};
    cs->status = CS_CABLE_INTACT, cs->node_count = 4;
    cs->node[0] = CS_NODE_START, cs->node[1] = 0, cs->node[2] = 1, cs->node[3] = CS_NODE_END;
    cs->where[0] = 1, cs->where[1] = 2;
    cs->m[0] = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 3; j++)
            cs->pos[3 * i + j] = p[i][j];
    for (int i = 0; i < 3; i++)
        cs->m[i + 1] = cs->m[i] + 3.0 / (1.0 + e[i]), cs->ep[i] = 0.0;
    for (int i = 0; i < 4; i++)
        cs->m_commit[i] = cs->m[i];
    cs_cable_commit(w->model, 0, w->state);
    return cs;
}

/* The strain of a tension on the rope's secondary slope (0.6 Fu < t < Fu). */
static double strain_of(const cs_rope *r, double t) {
    return r->e1 + (t - r->t1) / r->k2;
}

/* An end span (tied to an anchor) breaks the rope at its fitting when its tension reaches the fitting's
 * efficiency times Fu (0.90: wire rope clips on rope of 1 in or more); an inner span at the same tension
 * holds (a 4-node path: anchor, post, post, anchor). Tensions on the secondary slope: 0.9 Fu > 0.6 Fu. */
static void termination_breaks_at_its_efficiency(void **state) {
    (void)state;
    world *w = make_world(0.15);
    const cs_cable_model *cm = &w->model->cables[0];
    const cs_rope *r = &cm->rope;
    CHECK_REL(cm->termination_strength[0], 0.90 * r->fu, 1e-15);
    CHECK_REL(cm->termination_strength[1], 0.90 * r->fu, 1e-15);
    double lo = 0.0021; /* a low strain for the spans not under test */
    for (int k = 0; k < 3; k++) {
        double t = (k == 0 ? 0.99 : 1.01) * 0.90 * r->fu, strain[3] = {strain_of(r, t), lo, lo};
        if (k == 2) strain[0] = lo, strain[1] = strain_of(r, t); /* the inner span at 1.01 x 0.9 Fu */
        cs_cable_state *cs = lay_ends(w, strain);
        CHECK_REL(cs->tension[k == 2 ? 1 : 0], t, 1e-9);
        assert_int_equal(cs_cable_check_break(w->model, 0, w->state), k == 1);
        if (k == 1) {
            const cs_event *ev = &w->state->events[cs_state_event_count(w->state) - 1];
            assert_int_equal(ev->type, CS_EVENT_TERMINATION_BREAK);
            assert_int_equal(ev->cable_end, 0);
            CHECK_REL(ev->value, t, 1e-9);
            assert_int_equal(cs->status, CS_CABLE_BROKEN);
            CHECK_ABS(cs->tension[0], 0.0, 0.0); /* a broken rope carries nothing */
        }
    }
    world_free(w);
}

/* A world whose cable 0 has the fitting `kind` (efficiency eff) and its ends their own. */
/* Where the rope runs through a threaded post's hole it keeps hole_efficiency of its strength: a span on
 * such a post breaks the rope at that post once its tension passes 0.5 Fu, and holds just below it; at a
 * post the rope is not threaded through (a slot) the same span holds, and without the loss (the default)
 * it holds to its own strength. Fittings as strong as the rope, so that only the hole can break it. */
static void a_rope_breaks_at_its_strength_in_a_hole(void **state) {
    (void)state;
    static world w;
    for (int k = 0; k < 4; k++) {
        fixture_aps3(&w.fx);
        w.fx.cables[0].rope.mass_per_length = 0.0;
        w.fx.cables[0].termination_efficiency = 1.0;
        w.fx.cables[0].hole_efficiency = k == 3 ? 0.0 : 0.5;
        if (k == 2)
            for (int p = 0; p < w.fx.barrier.post_count; p++)
                w.fx.posts[p].attachment = CS_ATTACH_SLOT;
        cs_error err;
        w.model = cs_model_create(&w.fx.barrier, &w.fx.vehicle, &w.fx.scenario, &err);
        assert_non_null(w.model);
        w.state = cs_state_create(w.model, &err);
        assert_non_null(w.state);
        const cs_rope *r = &w.model->cables[0].rope;
        CHECK_REL(w.model->cables[0].hole_strength, k == 3 ? 0.0 : 0.5 * r->fu, 1e-15);
        double t = (k == 0 ? 0.49 : 0.51) * r->fu; /* on the elastic slope, below 0.6 Fu */
        double strain[3] = {0.0021, t / r->ea, 0.0021};
        cs_cable_state *cs = lay_ends(&w, strain);
        CHECK_REL(cs->tension[1], t, 1e-9);
        assert_int_equal(cs_cable_check_break(w.model, 0, w.state), k == 1);
        if (k == 1) {
            const cs_event *ev = &w.state->events[cs_state_event_count(w.state) - 1];
            assert_int_equal(ev->type, CS_EVENT_CABLE_BREAK);
            assert_int_equal(ev->post, 0); /* of the two posts the span rests on, the first bears the most */
            CHECK_REL(ev->value, t, 1e-9);
            assert_int_equal(cs->status, CS_CABLE_BROKEN);
        }
        world_free(&w);
    }
}

static world *make_world_ends(cs_termination kind, double eff, cs_cable_end_def start, cs_cable_end_def end,
                              cs_error *err) {
    static world w;
    fixture_aps3(&w.fx);
    w.fx.cables[0].rope.mass_per_length = 0.0;
    w.fx.cables[0].termination = kind;
    w.fx.cables[0].termination_efficiency = eff;
    w.fx.cables[0].ends[0] = start, w.fx.cables[0].ends[1] = end;
    w.model = cs_model_create(&w.fx.barrier, &w.fx.vehicle, &w.fx.scenario, err);
    w.state = w.model ? cs_state_create(w.model, err) : NULL;
    return &w;
}

/* Each end's strength: its own kind's published efficiency (swaged 0.95 at the start, clips 0.90 on the
 * 1.75-in rope at the end), the cable's efficiency where it takes the cable's kind, its own efficiency
 * over both; an efficiency above 1, an unknown kind, a slip with no travel, a slip load the pretension
 * would pass or a negative one at an end is refused, naming the end. */
static void each_end_has_its_own_strength(void **state) {
    (void)state;
    enum { AS = CS_TERMINATION_AS_CABLE, CLIPS = CS_TERMINATION_CLIPS, SWAGED = CS_TERMINATION_SWAGED };
    enum { SPELTER = CS_TERMINATION_SPELTER, WEDGE = CS_TERMINATION_WEDGE };
    static const struct {
        cs_termination kind;
        double eff;
        cs_cable_end_def ends[2];
        double want[2];
    } cases[] = {
        {CLIPS, 0.0, {{SWAGED, 0.0, 0.0, 0.0}, {CLIPS, 0.0, 0.0, 0.0}}, {0.95, 0.90}}, /* each its kind's */
        {SWAGED,
         0.0,
         {{AS, 0.0, 0.0, 0.0}, {WEDGE, 0.0, 0.0, 0.0}},
         {0.95, 0.85}}, /* the cable's kind at the start */
        {SWAGED,
         0.8,
         {{AS, 0.0, 0.0, 0.0}, {AS, 0.75, 0.0, 0.0}},
         {0.8, 0.75}}, /* the cable's efficiency; its own */
        {SWAGED,
         0.8,
         {{SPELTER, 0.0, 0.0, 0.0}, {CLIPS, 0.7, 0.0, 0.0}},
         {1.0, 0.7}}, /* its kind's, not the cable's 0.8 */
    };
    cs_error err;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        world *w = make_world_ends(cases[k].kind, cases[k].eff, cases[k].ends[0], cases[k].ends[1], &err);
        if (!w->state) fail_msg("case %zu: %s", k, err.message);
        const cs_cable_model *cm = &w->model->cables[0];
        CHECK_REL(cm->termination_strength[0], cases[k].want[0] * cm->rope.fu, 1e-15);
        CHECK_REL(cm->termination_strength[1], cases[k].want[1] * cm->rope.fu, 1e-15);
        world_free(w);
    }
    static const struct {
        cs_cable_end_def end;
        int at;
        const char *want;
    } bad[] = {
        {{CS_TERMINATION_AS_CABLE, 1.2, 0.0, 0.0},
         1,
         "cable 0: termination efficiency at the end anchor must be in (0, 1]"},
        {{(cs_termination)4, 0.0, 0.0, 0.0}, 0, "cable 0: unknown termination at the start anchor"},
        {{(cs_termination)-2, 0.0, 0.0, 0.0}, 1, "cable 0: unknown termination at the end anchor"},
        {{CS_TERMINATION_AS_CABLE, 0.0, 30.0 * KIP, 0.0},
         1,
         "cable 0: the fitting at the end anchor slips but has no slip travel"},
        {{CS_TERMINATION_AS_CABLE, 0.0, 4.0 * KIP, 0.5},
         0, /* the pretension is 5 kip */
         "cable 0: the fitting at the start anchor slips at 1.779e+04 N, not above the pretension"},
        {{CS_TERMINATION_AS_CABLE, 0.0, -1.0, 0.5}, 0, "cable 0: slip load and travel at the start anchor"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        cs_cable_end_def ends[2] = {{CS_TERMINATION_AS_CABLE, 0.0, 0.0, 0.0},
                                    {CS_TERMINATION_AS_CABLE, 0.0, 0.0, 0.0}};
        ends[bad[k].at] = bad[k].end;
        world *w = make_world_ends(CS_TERMINATION_CLIPS, 0.0, ends[0], ends[1], &err);
        assert_null(w->model);
        if (strncmp(err.message, bad[k].want, strlen(bad[k].want)) != 0)
            fail_msg("case %zu: '%s', expected '%s...'", k, err.message, bad[k].want);
    }
}

/* Swaged (0.95 Fu) at the start, clips (0.90 Fu) at the end: an end span at 0.93 Fu breaks the rope at the
 * clips only, with the end and that span's tension in the event; at the swaged start it holds, and at
 * 0.96 Fu there it breaks at the start. With both end spans past their fittings the end further past
 * lets go: 0.97 / 0.95 = 1.021 at the start against 0.91 / 0.90 = 1.011, then 0.955 / 0.95 = 1.005
 * against 0.93 / 0.90 = 1.033. */
static void each_end_breaks_at_its_own_fitting(void **state) {
    (void)state;
    cs_error err;
    cs_cable_end_def swaged = {CS_TERMINATION_SWAGED, 0.0, 0.0, 0.0},
                     clips = {CS_TERMINATION_CLIPS, 0.0, 0.0, 0.0};
    world *w = make_world_ends(CS_TERMINATION_CLIPS, 0.0, swaged, clips, &err);
    assert_non_null(w->state);
    const cs_rope *r = &w->model->cables[0].rope;
    double lo = 0.0021;
    static const struct {
        double load[2]; /* the end spans' tensions over Fu, at the start and at the end (0: low) */
        int end;        /* the end that lets go, -1 none */
    } cases[] = {{{0, 0.93}, 1}, {{0.93, 0}, -1}, {{0.96, 0}, 0}, {{0.97, 0.91}, 0}, {{0.955, 0.93}, 1}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double strain[3] = {lo, lo, lo};
        for (int e = 0; e < 2; e++)
            if (cases[k].load[e] > 0.0) strain[2 * e] = strain_of(r, cases[k].load[e] * r->fu);
        int events = cs_state_event_count(w->state);
        cs_cable_state *cs = lay_ends(w, strain);
        for (int e = 0; e < 2; e++) /* each end span at its load, or at lo as the inner span */
            CHECK_REL(cs->tension[2 * e], cases[k].load[e] > 0.0 ? cases[k].load[e] * r->fu : cs->tension[1],
                      1e-9);
        assert_true(cs->tension[1] < 0.25 * r->fu); /* 0.22 Fu */
        double t = cs->tension[cases[k].end > 0 ? 2 : 0];
        assert_int_equal(cs_cable_check_break(w->model, 0, w->state), cases[k].end >= 0);
        if (cases[k].end < 0) {
            assert_int_equal(cs_state_event_count(w->state), events);
            assert_int_equal(cs->status, CS_CABLE_INTACT);
            continue;
        }
        assert_int_equal(cs_state_event_count(w->state), events + 1);
        const cs_event *ev = &w->state->events[events];
        assert_int_equal(ev->type, CS_EVENT_TERMINATION_BREAK);
        assert_int_equal(ev->element_kind, CS_ELEMENT_CABLE);
        assert_int_equal(ev->element, 0);
        assert_int_equal(ev->cable_end, cases[k].end);
        assert_string_equal(cs_event_cable_end_name(ev), cases[k].end ? "end" : "start");
        CHECK_REL(ev->value, t, 1e-9);
        assert_int_equal(cs->status, CS_CABLE_BROKEN);
    }
    world_free(w);
}

/* Clips that slip: APS3's ropes with fittings that let the rope through at F_s = 30 kip (above the 5-kip
 * pretension, below the 0.90 Fu = 252 kip they break at) and run out after 18 in. The truck loads every
 * end past F_s: each starts to slip there (termination_slip, its end span no higher than F_s and the
 * solve's tolerance, 1e-4 Fu), no committed end span carries more than that, and each rope lets go
 * (termination_break, at F_s) once an end has let the 18 in through, within one step's slip (0.5 ms at
 * the rope's end speed, well under 5 cm); both ropes run out and the truck goes through; the ledger
 * closes within 1%. */
static void a_fitting_slips_at_its_load_and_runs_out(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    double fs = 30.0 * KIP, travel = 18.0 * IN;
    for (int c = 0; c < 2; c++)
        fx.cables[c].slip_load = fs, fx.cables[c].slip_travel = travel;
    /* dead-men that keep their peak (a soil at its critical state: no softening), 325.6 kN for both
     * ropes, so that the fittings are the weak link (at their residual, 189 kN, each end span would stay
     * below F_s once they plough) */
    for (int k = 0; k < 2; k++) {
        cs_footing_def *f = k ? &fx.barrier.end_anchor.footing : &fx.barrier.start_anchor.footing;
        f->residual_friction_angle = f->friction_angle;
    }
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    double fu = m->cables[0].rope.fu, most = 0.0, slip_at_break[2][2] = {{0}};
    while (s->outcome == CS_RUNNING) {
        assert_int_equal(cs_step(m, s, &err), CS_OK);
        for (int c = 0; c < 2; c++) {
            const cs_cable_state *cs = &s->cables[c];
            if (cs->status != CS_CABLE_INTACT) continue;
            most = fmax(most, fmax(cs->tension[0], cs->tension[cs->node_count - 2]));
            for (int end = 0; end < 2; end++)
                slip_at_break[c][end] = cs->slip[end];
        }
    }
    int slips = 0, breaks = 0;
    for (int k = 0; k < cs_state_event_count(s); k++) {
        const cs_event *e = &s->events[k];
        if (e->type == CS_EVENT_TERMINATION_SLIP) {
            slips++;
            assert_true(e->value > fs - 3e-3 * fu && e->value <= fs + 1e-4 * fu);
        }
        if (e->type == CS_EVENT_TERMINATION_BREAK) {
            breaks++;
            CHECK_REL(e->value, fs, 1e-4 * fu / fs);
            double through = s->cables[e->element].slip[e->cable_end];
            assert_true(through >= travel && through < travel + 0.05);
            assert_true(slip_at_break[e->element][e->cable_end] < travel); /* the step before, still held */
        }
    }
    printf("largest end span tension %.1f kN (F_s %.1f kN), %d slips, %d run out\n", most / 1e3, fs / 1e3,
           slips, breaks);
    assert_int_equal(slips, 4);
    assert_int_equal(breaks, 2); /* both ropes run out, and the truck is through */
    assert_int_equal(s->outcome, CS_BREAKTHROUGH);
    assert_true(most <= fs + 1e-4 * fu);
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(s, &sm, NULL);
    assert_true(fabs(sm.energy_balance_error) < 0.01);
    cs_state_free(s);
    cs_model_free(m);
}

/* The fallback's local problem at a slipping end (cs_relax_ends, relax.c): on the
 * weightless 4-node path, fittings at both ends slipping at F_s = 0.3 Fu (the elastic slope, T = EA (l/s -
 * 1)). The start span laid at 0.5 Fu takes the rope that holds it at F_s, s = l / (1 + F_s / EA), its
 * tension F_s to 1e-12, the change 0.2 Fu returned; the end span at 0.1 Fu sticks (its node where it was
 * committed). The commit then books the slip, l / (1 + F_s/EA) - l / (1 + 0.5 Fu/EA), its friction
 * F_s times it along the stretched rope, (1 + l/s) / 2, and the slip's start with its tension. An end
 * span with a plastic set comes to F_s too. */
static void the_fallback_lets_an_end_slip_at_its_load(void **state) {
    (void)state;
    double fu = 91.4 * 1.75 * 1.75 * KIP;
    cs_cable_end_def slips = {CS_TERMINATION_AS_CABLE, 0.0, 0.3 * fu, 1.0};
    cs_error err;
    world *w = make_world_ends(CS_TERMINATION_CLIPS, 0.0, slips, slips, &err);
    if (!w->state) fail_msg("%s", err.message);
    const cs_cable_model *cm = &w->model->cables[0];
    double ea = cm->rope.ea, strain[3] = {0.5 * fu / ea, 0.2 * fu / ea, 0.1 * fu / ea};
    cs_cable_state *cs = lay_ends(w, strain);
    double m3 = cs->m[3], s0 = 3.0 / (1.0 + 0.5 * fu / ea), held = 3.0 / (1.0 + 0.3 * fu / ea);
    w->state->e_friction = 0.0;
    CHECK_REL(cs_relax_ends(w->model, 0, w->state), 0.2, 1e-9);
    CHECK_REL(cs->tension[0], 0.3 * fu, 1e-12);
    CHECK_REL(cs->m[1] - cs->m[0], held, 1e-14);
    CHECK_ABS(cs->m[3], m3, 0.0);
    int events = cs_state_event_count(w->state);
    cs_cable_commit(w->model, 0, w->state);
    CHECK_REL(cs->slip[0], held - s0, 1e-9);
    CHECK_ABS(cs->slip[1], 0.0, 0.0);
    CHECK_REL(w->state->e_friction, (held - s0) * 0.3 * fu * 0.5 * (1.0 + 3.0 / held), 1e-9);
    assert_int_equal(cs_state_event_count(w->state), events + 1);
    const cs_event *ev = &w->state->events[events];
    assert_int_equal(ev->type, CS_EVENT_TERMINATION_SLIP);
    assert_int_equal(ev->cable_end, 0);
    CHECK_REL(ev->value, 0.3 * fu, 1e-9);
    /* a span with a plastic set keeps it on the rope it had; the rope out of the fitting brings none: the
     * end span at 0.5 Fu over a set of 2e-3 still comes to F_s, to 1e-9 Fu */
    cs = lay_ends(w, (double[3]){0.5 * fu / ea + 2e-3, 0.2 * fu / ea, 0.1 * fu / ea});
    cs->ep[0] = 2e-3;
    cs_cable_update_span(cm, cs, 0, NULL);
    CHECK_REL(cs->tension[0], 0.5 * fu, 1e-9);
    cs_relax_ends(w->model, 0, w->state);
    CHECK_ABS(cs->tension[0], 0.3 * fu, 1e-9 * fu);
    world_free(w);
}

/* Puts cable 0's end node at `end` `within` times the rope's diameter from the hole of the post beside it,
 * along the end span as it was laid. */
static void end_near_its_post(const world *w, int end, double within) {
    cs_cable_state *cs = &w->state->cables[0];
    int tie = end ? cs->node_count - 1 : 0, hole = end ? tie - 1 : 1;
    double d[3], *p = cs->pos + 3 * tie, *q = cs->pos + 3 * hole;
    v3_sub(d, p, q);
    v3_scale(d, d, within * w->model->cables[0].diameter / v3_norm(d));
    v3_add(p, q, d);
}

/* The rope's end at the post next to its anchor (termination.c): APS3 as installed, the lower rope's end
 * at the start anchor put 0.99 of the rope's diameter (1.75 in) from post 0's hole and its end at the end
 * anchor 1.01 of it from post 15's. Post 0 leaves the rope's path and post 15 stays: the event names post
 * 0, the cable, its end and how far the start anchor has moved; the rope is kept (the end nodes' m), the
 * merged end span holds the rope of both and their plastic strains by their rope. The end anchor's end
 * within 0.5 of the diameter of post 15 made clamped stays, and leaves once it is threaded. A rope
 * given without a diameter takes its metallic area's as a solid bar. */
static void a_rope_end_at_its_post_runs_straight_on(void **state) {
    (void)state;
    world *w = make_world(0.15);
    cs_state *s = w->state;
    cs_cable_state *cs = &s->cables[0];
    int n = cs->node_count;
    double m_end = cs->m[n - 1], s0 = cs->m[1], s1 = cs->m[2] - cs->m[1];
    cs->ep[0] = 2e-3, cs->ep[1] = 1e-3;
    s->anchors[0].u[0] = 0.3, s->anchors[0].u[1] = 0.4;
    end_near_its_post(w, 0, 0.99);
    end_near_its_post(w, 1, 1.01);
    int events = cs_state_event_count(s);
    assert_int_equal(cs_termination_check_post(w->model, 0, s), 1);
    assert_int_equal(cs->node_count, n - 1);
    assert_int_equal(cs->where[0], -1);
    assert_int_equal(cs->node[1], 1);
    assert_int_equal(cs->where[15], n - 3);
    CHECK_ABS(cs->m[0], 0.0, 0.0);
    CHECK_REL(cs->m[1], s0 + s1, 1e-15);
    CHECK_ABS(cs->m[n - 2], m_end, 0.0);
    CHECK_REL(cs->ep[0], (2e-3 * s0 + 1e-3 * s1) / (s0 + s1), 1e-12);
    assert_int_equal(cs_state_event_count(s), events + 1);
    const cs_event *ev = &s->events[events];
    assert_int_equal(ev->type, CS_EVENT_TERMINATION_AT_POST);
    assert_int_equal(ev->element_kind, CS_ELEMENT_POST);
    assert_int_equal(ev->element, 0);
    assert_int_equal(ev->cable, 0);
    assert_int_equal(ev->cable_end, 0);
    CHECK_REL(ev->value, 0.5, 1e-15);
    assert_string_equal(cs_event_value_unit(ev->type), "m");
    assert_int_equal(cs_termination_check_post(w->model, 0, s), 0); /* nothing more within reach */
    end_near_its_post(w, 1, 0.5);
    w->model->posts[15].clamped = 1;
    assert_int_equal(cs_termination_check_post(w->model, 0, s), 0);
    w->model->posts[15].clamped = 0;
    assert_int_equal(cs_termination_check_post(w->model, 0, s), 1);
    assert_int_equal(cs->where[15], -1);
    assert_int_equal(s->events[events + 1].cable_end, 1);
    world_free(w);

    fixture fx;
    fixture_aps3(&fx);
    fx.cables[0].rope.diameter = 0.0;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    assert_non_null(m);
    CHECK_REL(m->cables[0].diameter, sqrt(4.0 * fx.cables[0].rope.area / CS_PI), 1e-15);
    CHECK_REL(m->cables[1].diameter, 1.75 * IN, 1e-15);
    cs_model_free(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rope_law_points),
        cmocka_unit_test(capstan_ratio_on_frictional_support),
        cmocka_unit_test(capstan_band_at_small_and_large_turns),
        cmocka_unit_test(frictionless_sliding_equalises_tension),
        cmocka_unit_test(sagging_span_hangs_as_a_catenary),
        cmocka_unit_test(sag_tension_solves_its_cubic),
        cmocka_unit_test(breaking_strain_breaks_the_cable),
        cmocka_unit_test(termination_breaks_at_its_efficiency),
        cmocka_unit_test(a_rope_breaks_at_its_strength_in_a_hole),
        cmocka_unit_test(each_end_has_its_own_strength),
        cmocka_unit_test(each_end_breaks_at_its_own_fitting),
        cmocka_unit_test(a_fitting_slips_at_its_load_and_runs_out),
        cmocka_unit_test(the_fallback_lets_an_end_slip_at_its_load),
        cmocka_unit_test(a_rope_end_at_its_post_runs_straight_on),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
