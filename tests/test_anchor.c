/* SPDX-License-Identifier: MIT */
/* Anchors as footings in the soil (src/elements/anchor.c): what they hold, how they slide, when they pull
 * out. */
#include "check.h"
#include "fixture.h"
#include "run/run.h"
#include "solver/work.h"

/* APS3's dead-man, a 3-ft diameter, 5-ft deep concrete shaft, at both ends. */
static void dead_men(fixture *fx, double b_ft, double d_ft) {
    for (int k = 0; k < 2; k++) {
        cs_anchor_def *a = k ? &fx->barrier.end_anchor : &fx->barrier.start_anchor;
        a->footing = fixture_footing(b_ft, d_ft, 0.0);
    }
}

/* What the model derives from the footing, by hand: Eq. 21 at the ropes' height (H = 0, grade) is
 * S1 B D / 2.37 = 8000 x 3 x 5 / 2.37 = 50,633 lb; times the dynamic factor for its width, 2.740 x
 * 2.151580 / 4.063222 = 1.450900 (test_footing.c), 73,463 lb = 326.78 kN. It reaches that over 2% of its
 * depth (30.48 mm), weighs 2300 kg/m^3 x pi/4 x 0.9144^2 x 1.524 m^3 = 2,301.7 kg, and is lifted out by
 * its weight plus its skin friction (177.5 kPa/m x pi x 0.9144 x 1.524^2 / 2 = 592.1 kN). Past the peak
 * the soil keeps the critical-state passive resistance: Kp R at 33 deg over Kp R at 42 deg, 3.392120 x
 * 1.853141 / (5.044681 x 2.151580) = 0.579146 of P, reached after a plastic slide of 5% of the depth.
 * It moves with the soil's passive wedge (Rankine, plane strain over its width): the slip plane at
 * 45 - 42/2 = 24 deg from its base to grade bounds a section D^2 / (2 tan 24) = 2.6083 m^2, which slides
 * up the plane at v / cos 24 as the shaft moves by v: 135 lbf/ft^3 / g = 2162.5 kg/m^3 x 2.6083 x 0.9144
 * / cos^2 24 = 6,180 kg at the shaft's speed. */
static void anchor_from_its_footing(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    dead_men(&fx, 3.0, 5.0);
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    const cs_anchor_model *am = &m->anchors[0];
    double p = 8000.0 * 3.0 * 5.0 / 2.37 * 2.740 * 2.151580 / 4.063222 * (KIP / 1000.0);
    CHECK_REL(am->capacity, p, 1e-6);
    CHECK_REL(am->stiffness, p / (0.02 * 5.0 * FT), 1e-6);
    double mass = 2300.0 * 0.25 * M_PI_2_VALUE * 2.0 * pow(3.0 * FT, 2) * 5.0 * FT;
    CHECK_REL(am->mass, mass, 1e-12);
    const double a = (45.0 - 21.0) * M_PI_2_VALUE / 90.0, rho = 135.0 * CS_LBF / pow(FT, 3) / CS_G0;
    double wedge = rho * pow(5.0 * FT, 2) / (2.0 * tan(a)) * 3.0 * FT / pow(cos(a), 2);
    CHECK_REL(am->moving_mass - am->mass, wedge, 1e-12);
    CHECK_REL(wedge, 6180.0, 1e-4);
    CHECK_REL(am->residual / am->capacity, 0.579146, 1e-6);
    CHECK_REL(am->softening, 0.05 * 5.0 * FT, 1e-12);
    double skin = 177.5e3 * 2.0 * M_PI_2_VALUE * 3.0 * FT * pow(5.0 * FT, 2) / 2.0;
    CHECK_REL(am->uplift_capacity, mass * fx.scenario.gravity + skin, 1e-12);
    assert_false(am->rigid);
    assert_true(m->anchors[1].capacity == am->capacity);
    cs_model_free(m);
    const double g = fx.scenario.gravity; /* the soil's mass is its weight at standard gravity, whatever */
    fx.scenario.gravity = 0.0;            /* the scenario's */
    m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    CHECK_REL(m->anchors[0].moving_mass - m->anchors[0].mass, wedge, 1e-12);
    cs_model_free(m);
    fx.scenario.gravity = g;
    /* a pullout capacity given for the footing, or for the anchor, is the uplift that lifts it out,
     * with nothing added for its weight or a block's perimeter (an 8 x 6-ft block: 20 kip) */
    for (int k = 0; k < 2; k++) {
        fx.barrier.start_anchor.length = 6.0 * FT;
        fx.barrier.start_anchor.footing = fixture_footing(8.0, 4.0, 0.0);
        fx.barrier.start_anchor.footing.pullout_capacity = k ? 0.0 : 20.0 * KIP;
        fx.barrier.start_anchor.pullout_capacity = k ? 20.0 * KIP : 0.0;
        m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
        if (!m) fail_msg("%s", err.message);
        CHECK_REL(m->anchors[0].uplift_capacity, 20.0 * KIP, 1e-15);
        cs_model_free(m);
    }
}

/* A rope pretensioned well beyond what its anchors hold pulls them in at installation until it holds just
 * what the soil holds after their slide. The installer tensions it against anchors already loaded: each
 * deflects to its elastic limit u_e = 0.999 P / k, L1 = L0 - 2 u_e apart, and a weightless rope laid in
 * with s_r = L1 / (1 + T0 / EA) holds T when they are s_r (1 + T / EA) apart. Each anchor moves by its slide
 * l plus T / k, with T = P - H l on the softening branch (H = (P - P_r) / s_soft), so
 *   L0 - 2 (l + (P - H l) / k) = s_r (1 + (P - H l) / EA),
 * linear in l; where that l passes s_soft, T = P_r and l = (L0 - s_r (1 + P_r / EA)) / 2 - P_r / k. */
static void pretension_beyond_the_anchor_pulls_it_in(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    dead_men(&fx, 1.0, 3.0); /* a small footing: P = 2.740 R(1/3) / R_ref x 8000 x 3 / 2.37 lb */
    fx.barrier.cable_count = 1, fx.barrier.post_count = 0;
    fx.cables[0].rope.mass_per_length = 0.0;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    double p = m->anchors[0].capacity, k = m->anchors[0].stiffness, ea = m->cables[0].rope.ea,
           l0 = 136.0 * FT;
    fx.cables[0].pretension = 4.0 * p;
    cs_model_free(m);
    m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    double l1 = l0 - 2.0 * 0.999 * p / k, sr = l1 / (1.0 + 4.0 * p / ea);
    double pr = m->anchors[0].residual, soft = m->anchors[0].softening, hard = (p - pr) / soft;
    double slide = (l0 - sr - sr * p / ea - 2.0 * p / k) / (2.0 - 2.0 * hard / k - sr * hard / ea);
    double t = p - hard * slide;
    if (slide > soft) t = pr, slide = 0.5 * (l0 - sr * (1.0 + pr / ea)) - pr / k;
    printf("slide %.5f m (softening over %.5f m), tension %.1f kN of P %.1f kN\n", slide, soft, t / 1e3,
           p / 1e3);
    CHECK_REL(s->cables[0].tension[0], t, 1e-3); /* the solve's tolerance: 1e-4 Fu = 125 N of 86 kN */
    CHECK_REL(s->anchors[0].u[0], slide + t / k, 1e-3);
    CHECK_REL(s->anchors[1].u[0], -(slide + t / k), 1e-3);
    CHECK_REL(s->anchors[0].plastic[0], slide, 2e-3);
    CHECK_REL(s->anchors[0].slide, slide, 2e-3);
    assert_true(s->anchors[0].yielded);
    cs_state_free(s);
    cs_model_free(m);
}

/* The truck of APS3 drags its dead-men through the soil: they yield at P and plough on, their resistance
 * falling to the residual P_r over the softening slide s_r and held there; nothing lifts them out. The
 * soil's work is the integral of that resistance along each plastic slide l, (P + P_r) s_r / 2 + P_r (l -
 * s_r), plus the drag of the soil their faces sweep (booked at each commit; over the steps, c |v| v
 * times each step's travel by the trapezoid rule, within 1%), to round-off, and the ledger closes within
 * 1%. The posts are held in their footings (a post coming out turns in the soil too: test_post.c). */
static void truck_drags_the_dead_men_through_the_soil(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    dead_men(&fx, 3.0, 5.0);
    for (int q = 0; q < fx.barrier.post_count; q++) /* no post's footing in the soil's work */
        fx.posts[q].footing.pullout_capacity = HUGE_VAL;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    int yielded = 0, pulled = 0;
    double swept = 0.0; /* the drag's work, -c |v| v . du by the trapezoid rule over each step */
    while (s->outcome == CS_RUNNING) {
        double u0[2][2], d0[2][2];
        for (int a = 0; a < 2; a++)
            for (int k = 0; k < 2; k++) {
                const cs_anchor_state *as = &s->anchors[a];
                u0[a][k] = as->u_commit[k];
                d0[a][k] = m->anchors[a].drag * hypot(as->rate[0], as->rate[1]) * as->rate[k];
            }
        assert_int_equal(cs_step(m, s, &err), CS_OK);
        for (int a = 0; a < 2; a++)
            for (int k = 0; k < 2; k++) {
                const cs_anchor_state *as = &s->anchors[a];
                double d = m->anchors[a].drag * hypot(as->rate[0], as->rate[1]) * as->rate[k];
                swept += 0.5 * (d0[a][k] + d) * (as->u_commit[k] - u0[a][k]);
            }
    }
    double booked = s->anchors[0].swept + s->anchors[1].swept;
    double slide[2], work = booked, p = m->anchors[0].capacity, pr = m->anchors[0].residual,
                     soft = m->anchors[0].softening;
    for (int a = 0; a < 2; a++) { /* the slide's length, at least its chord */
        slide[a] = s->anchors[a].slide;
        assert_true(slide[a] >= hypot(s->anchors[a].plastic[0], s->anchors[a].plastic[1]));
        assert_true(slide[a] > soft);
        work += 0.5 * (p + pr) * soft + pr * (slide[a] - soft);
    }
    for (int k = 0; k < cs_state_event_count(s); k++) {
        const cs_event *e = &s->events[k];
        yielded += e->type == CS_EVENT_ANCHOR_YIELD;
        pulled += e->type == CS_EVENT_ANCHOR_PULLOUT;
    }
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(s, &sm, NULL);
    printf("soil %.1f kJ, the cap's work over the slides and the drag's %.1f kJ (the drag %.1f kJ, over the "
           "steps %.1f), "
           "slides %.4f %.4f m, %s, ledger %.3g%%\n",
           s->e_soil / 1e3, work / 1e3, booked / 1e3, swept / 1e3, slide[0], slide[1],
           cs_outcome_name(sm.outcome), 100.0 * sm.energy_balance_error);
    assert_int_equal(yielded, 2);
    assert_int_equal(pulled, 0);
    CHECK_REL(s->e_soil, work, 1e-9);
    CHECK_REL(booked, swept, 0.01); /* the engine's over its commits, the test's over the steps */
    assert_true(fabs(sm.energy_balance_error) < 0.01);
    cs_state_free(s);
    cs_model_free(m);
}

/* The dead-men plough up to the end posts (termination.c, "the rope's end at the post next to its
 * anchor"): the APS3 fixture's truck at 80 mph, its posts' footings turning in the soil (the steel ten
 * times stronger: a hinged post's stub stays upright and holds its ropes down where it folds, post.c),
 * drags both dead-men through the soil up to the end posts lying on the ground, and then past them to the
 * posts next in. Each rope's end reaches each of those posts' holes in mirror pairs, within a step (a
 * termination_at_post at each, the post off that rope's path from then on), and the solves stay bounded:
 * no step is cut into pieces, none ends above the tolerance, at most 1% of the solves need the fallback,
 * and the ledger closes within 1%. Without the rule the end spans shrink to nanometres under the ropes'
 * pull and their stiffness EA / l stalls Newton. */
static void the_dead_men_plough_up_to_the_end_posts(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    dead_men(&fx, 3.0, 5.0);
    fx.scenario.speed = 80.0 * MPH;
    for (int p = 0; p < fx.barrier.post_count; p++) /* footings that turn in the soil */
        fx.posts[p].section.plastic_modulus *= 10.0;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    m->anchors[0].drag = m->anchors[1].drag = 0.0; /* the swept soil's drag would stop them short */
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    while (s->outcome == CS_RUNNING)
        assert_int_equal(cs_step(m, s, &err), CS_OK);
    int reached[2] = {0, 0};
    for (int k = 0; k < cs_state_event_count(s); k++) {
        const cs_event *e = &s->events[k];
        if (e->type != CS_EVENT_TERMINATION_AT_POST) continue;
        reached[e->cable_end]++;
        int mirror = m->post_count - 1 - e->element, twin = 0;
        for (int j = 0; j < cs_state_event_count(s); j++) /* its mirror image, within a step: the */
            twin |= s->events[j].type == e->type &&       /* sums are not bitwise mirror images */
                    fabs(s->events[j].t - e->t) <= 1.0001 * fx.scenario.dt &&
                    s->events[j].element == mirror && s->events[j].cable == e->cable &&
                    s->events[j].cable_end == 1 - e->cable_end;
        assert_true(twin);
        assert_true(e->value > 3.0);
        if (s->cables[e->cable].status == CS_CABLE_INTACT)
            assert_int_equal(s->cables[e->cable].where[e->element], -1);
    }
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(s, &sm, NULL);
    printf("%d and %d rope ends at a post; %ld solves, %ld through the fallback, %ld steps cut, %ld Newton "
           "passes; %d warnings, ledger %.3g%%, %s\n",
           reached[0], reached[1], s->work->count.solves, s->work->count.fallback, s->work->count.pieces,
           s->work->count.newton, sm.solver_warnings, 100.0 * sm.energy_balance_error,
           cs_outcome_name(sm.outcome));
    assert_true(reached[0] >= 2 && reached[1] == reached[0]);
    assert_int_equal(s->work->count.pieces, 0);
    assert_true(s->work->count.fallback <= s->work->count.solves / 100);
    assert_int_equal(sm.solver_warnings, 0);
    assert_true(fabs(sm.energy_balance_error) < 0.01);
    cs_state_free(s);
    cs_model_free(m);
}

/* A dead-man (APS3's 3 x 5 ft and its soil wedge, 8,482 kg; or moving the mass given) on one weightless
 * rope to a rigid anchor, the vehicle away, let go from `kick` off its balance: held there at an instant
 * (h = 0), the net force it starts from. */
static cs_state *kicked_dead_man(double mass, cs_model **m, double *balance, double *kick) {
    fixture fx;
    fixture_aps3(&fx);
    dead_men(&fx, 3.0, 5.0);
    fx.barrier.end_anchor.footing.diameter = 0.0; /* rigid */
    fx.barrier.cable_count = 1, fx.barrier.post_count = 0, fx.barrier.rail_count = 0;
    fx.cables[0].rope.mass_per_length = 0.0;
    fx.scenario.start_gap = 1000.0; /* the vehicle stays away */
    cs_error err;
    *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!*m) fail_msg("%s", err.message);
    if (mass > 0.0) (*m)->anchors[0].moving_mass = mass;
    cs_state *s = cs_state_create(*m, &err);
    assert_non_null(s);
    const cs_anchor_model *am = &(*m)->anchors[0];
    *kick = 0.2 * am->capacity / am->stiffness; /* well inside the soil's elastic range */
    *balance = s->anchors[0].u[0];
    s->anchors[0].u[0] = s->anchors[0].u_commit[0] = *balance + *kick;
    cs_anchor_place_nodes(*m, s, 0);
    cs_cable_update_tensions(&(*m)->cables[0], &s->cables[0], NULL);
    cs_anchor_commit(*m, s);
    return s;
}

/* A dead-man let go from off its balance rings between its soil and a weightless rope to a rigid anchor:
 * one degree of freedom, M u'' = -k u about the balance, k = k_soil + EA / L. The HHT-alpha recursion of
 * anchor.c for that oscillator, from u0 at rest with M a0 = -k u0 (the net force it is held at), is
 *   M a1 = -(1 + alpha) k u1 + alpha k u0,  u1 = u0 + h v0 + h^2 ((1/2 - beta) a0 + beta a1),
 *   v1 = v0 + h ((1 - gamma) a0 + gamma a1);
 * the run (the rope's tension law and the soil's spring solved by the barrier's Newton) must follow it
 * step by step. Returns the ringing's energy lost, relative, and checks that what the step took out of
 * the motion is booked as damping (the soil's, the rope's and the dead-man's energies and the damping
 * sum to what they were after the kick). mass 0: the dead-man's concrete and its wedge. */
static double ring_a_dead_man(double mass, int steps, double *wh_out) {
    cs_model *m;
    double balance, kick;
    cs_state *s = kicked_dead_man(mass, &m, &balance, &kick);
    cs_error err;
    m->anchors[0].drag = 0.0; /* the linear oscillator: the swept soil's drag is checked on its own below */
    const cs_anchor_model *am = &m->anchors[0];
    double l = m->anchors[1].x - am->x, k = am->stiffness + m->cables[0].rope.ea / l, h = m->scenario.dt;
    cs_energy_update(m, s);
    const cs_energy *e = &s->energy;
    double held0 = e->anchor_elastic + e->anchor_kinetic + e->cable_elastic;
    double total0 = held0 + e->post_damping, ringing0 = 0.5 * k * kick * kick;
    const double alpha = -0.1, beta = 0.25 * (1.0 - alpha) * (1.0 - alpha), gamma = 0.5 - alpha;
    double u = kick, v = 0.0, a = -k * kick / am->moving_mass, worst = 0.0;
    for (int n = 0; n < steps; n++) {
        double u1 =
            (alpha * k * u + am->moving_mass * ((u + h * v) / (beta * h * h) + (0.5 / beta - 1.0) * a)) /
            ((1.0 + alpha) * k + am->moving_mass / (beta * h * h));
        double a1 = (u1 - u - h * v) / (beta * h * h) - (0.5 / beta - 1.0) * a;
        v += h * ((1.0 - gamma) * a + gamma * a1), u = u1, a = a1;
        assert_int_equal(cs_step(m, s, &err), CS_OK);
        worst = fmax(worst, fabs(s->anchors[0].u[0] - balance - u));
    }
    double held = e->anchor_elastic + e->anchor_kinetic + e->cable_elastic;
    double ringing = 0.5 * k * u * u + 0.5 * am->moving_mass * v * v;
    *wh_out = sqrt(k / am->moving_mass) * h;
    printf("omega h %.4f: u after %d steps %.4f mm (the recursion %.4f mm, largest difference %.2e mm of a "
           "%.4f-mm kick), held %.3f J of %.3f J, damped %.3g J, ledger drift %.2e J\n",
           *wh_out, steps, 1e3 * (s->anchors[0].u[0] - balance), 1e3 * u, 1e3 * worst, 1e3 * kick, held,
           held0, e->post_damping, held + e->post_damping - total0);
    CHECK_ABS(worst, 0.0, 0.005 * kick); /* the solve's tolerance, 1e-4 Fu, on a 6-mm kick */
    CHECK_ABS(held + e->post_damping - total0, 0.0, 1e-6 * held0);
    cs_state_free(s);
    cs_model_free(m);
    return 1.0 - ringing / ringing0;
}

/* APS3's dead-man with its wedge (omega h 0.020) rings on for 200 steps with its energy: 1e-5 of it lost
 * by the recursion (backward Euler, keeping 1 / (1 + omega^2 h^2) of it a step, would have lost 7.8%).
 * One moving a 3600th of that mass on the same spring (omega h 1.2, a mode the step does not resolve) is
 * damped out, 98.7% in 200 steps: the trapezoidal rule (alpha = 0) would keep it ringing. */
static void a_ringing_dead_man_keeps_its_energy(void **state) {
    (void)state;
    double wh, lost = ring_a_dead_man(0.0, 200, &wh);
    printf("omega h %.4f: %.2e of the ringing lost\n", wh, lost);
    CHECK_ABS(lost, 0.0, 1e-4);
    lost = ring_a_dead_man(8482.0 / 3600.0, 200, &wh);
    printf("omega h %.2f: %.1f%% of the ringing lost\n", wh, 100.0 * lost);
    assert_true(lost > 0.9);
}

/* A dead-man ploughing at 5 m/s on its residual with its rope slack is stopped by the soil's residual and
 * by the drag of the soil its face sweeps: M dv/dt = -(P_r + c v^2), c = rho b D = 2162.5 x 0.9144 x
 * 1.524 = 3,013.5 kg/m for APS3's shaft. From v0 it stops after x = (M / 2c) ln(1 + c v0^2 / P_r) and t =
 * (M / sqrt(P_r c)) atan(v0 sqrt(c / P_r)): 0.4716 m in 0.200 s (the residual alone: M v0^2 / 2 P_r =
 * 0.560 m). The soil takes the whole of its kinetic energy, the drag's share `M v0^2 / 2 - P_r x`. */
static void a_ploughing_dead_man_sweeps_the_soil(void **state) {
    (void)state;
    cs_model *m;
    double balance, kick;
    cs_state *s = kicked_dead_man(0.0, &m, &balance, &kick);
    cs_error err;
    const cs_anchor_model *am = &m->anchors[0];
    cs_anchor_state *as = &s->anchors[0];
    const double v0 = 5.0, mass = am->moving_mass, c = am->drag, pr = am->residual;
    CHECK_REL(c, 2162.5 * 0.9144 * 1.524, 1e-3);
    /* on the residual, the rope slack (0.5 m nearer its rigid end than at its balance), moving at v0 */
    as->slide = am->softening;
    as->u[0] = as->u_commit[0] = balance + 0.5, as->plastic[0] = as->u[0] - pr / am->stiffness;
    as->rate[0] = v0, as->acc[0] = -(pr + c * v0 * v0) / mass, as->net[0] = -(pr + c * v0 * v0);
    cs_anchor_place_nodes(m, s, 0);
    cs_cable_update_tensions(&m->cables[0], &s->cables[0], NULL);
    cs_energy_update(m, s); /* the ledger from here, with the motion given */
    s->e_initial_total = cs_energy_total(&s->energy);
    double x0 = as->u[0], soil0 = s->e_soil, t = 0.0;
    while (as->rate[0] > 0.0) {
        assert_int_equal(cs_step(m, s, &err), CS_OK);
        t += m->scenario.dt;
        assert_true(t < 1.0);
    }
    double x = (mass / (2.0 * c)) * log(1.0 + c * v0 * v0 / pr),
           stop = mass / sqrt(pr * c) * atan(v0 * sqrt(c / pr));
    double kinetic = 0.5 * mass * v0 * v0, soil = s->e_soil - soil0;
    printf(
        "from %.1f m/s: stopped after %.4f m in %.4f s (by hand %.4f m in %.4f s); the soil took %.2f kJ of "
        "%.2f kJ, the drag %.2f kJ (by hand %.2f)\n",
        v0, as->u[0] - x0, t, x, stop, soil / 1e3, kinetic / 1e3, (soil - pr * (as->u[0] - x0)) / 1e3,
        (kinetic - pr * x) / 1e3);
    CHECK_REL(as->u[0] - x0, x, 0.005); /* the stop within a step's travel at the end */
    CHECK_ABS(t, stop, 2.0 * m->scenario.dt);
    CHECK_REL(soil, kinetic, 0.005); /* the slack rope holds none of it */
    CHECK_REL(soil - pr * (as->u[0] - x0), kinetic - pr * x, 0.05);
    cs_state_free(s);
    cs_model_free(m);
}

/* A dead-man whose last rope lets go while it moves leaves the solve: the soil stops it within the next
 * step, and its kinetic energy goes to the soil's work (it is not carried on, nor its rate flipped from
 * step to step by an update with no movement). */
static void a_dead_man_its_ropes_let_go_stops_in_the_soil(void **state) {
    (void)state;
    cs_model *m;
    double balance, kick;
    cs_state *s = kicked_dead_man(0.0, &m, &balance, &kick);
    cs_error err;
    const cs_anchor_model *am = &m->anchors[0];
    for (int n = 0; n < 5; n++) /* under way */
        assert_int_equal(cs_step(m, s, &err), CS_OK);
    double v = s->anchors[0].rate[0], kinetic = 0.5 * am->moving_mass * v * v, soil = s->e_soil;
    s->cables[0].status = CS_CABLE_BROKEN; /* let go at an instant (no release booked: not checked here) */
    for (int n = 0; n < 3; n++)
        assert_int_equal(cs_step(m, s, &err), CS_OK);
    printf("moving at %.3f m/s with %.2f J when its rope let go: rate %.3g m/s after, soil +%.2f J\n", v,
           kinetic, s->anchors[0].rate[0], s->e_soil - soil);
    assert_true(fabs(v) > 0.01);
    assert_true(s->anchors[0].rate[0] == 0.0 && s->anchors[0].rate[1] == 0.0);
    CHECK_REL(s->e_soil - soil, kinetic, 1e-12);
    cs_state_free(s);
    cs_model_free(m);
}

/* A dead-man that has ploughed has the soil it drove into ahead of it and its own trench behind it: the
 * soil pushes it back off its face and never pulls it on. APS3's dead-man slid 0.1 m along +x (its plastic
 * slide), at the elastic offsets e from it, with its rope held where it is (the soil's force is then what
 * the residual loses, h = 0: no inertia): pressed 5 mm into the soil ahead the soil holds k e, to 1e-12;
 * backed 5 mm off it and pushed 2 mm across, only its sides hold it, k (0, 2 mm), and its elastic energy is
 * k (2 mm)^2 / 2; a dead-man that has not slid is held all round, k e. Moving at v it sweeps the soil ahead
 * of it, -c |v| v, but none of its trench: at (1, 0.2) m/s the drag is -c |v| v, at (-1, 0.2) m/s only
 * the motion across, -c (0, 0.2^2), to 1e-9 c (the rate held over the step: no inertial force). */
static void a_dead_man_backed_off_its_soil_is_held_by_its_sides(void **state) {
    (void)state;
    cs_model *m;
    double balance, kick;
    cs_state *s = kicked_dead_man(0.0, &m, &balance, &kick);
    const cs_anchor_model *am = &m->anchors[0];
    cs_anchor_state *as = &s->anchors[0];
    s->h = 0.0;
    const double k = am->stiffness, slid[2] = {0.1, 0.0};
    const double e[3][2] = {{0.005, 0.0}, {-0.005, 0.002}, {-0.005, 0.002}};
    const double held[3][2] = {{k * 0.005, 0.0}, {0.0, k * 0.002}, {-k * 0.005, k * 0.002}};
    for (int c = 0; c < 3; c++) {
        double p = c < 2 ? slid[0] : 0.0, r0[2], r[2];
        as->slide = p, as->plastic[0] = p, as->plastic[1] = 0.0;
        as->u[0] = p, as->u[1] = 0.0;
        cs_anchor_residual(m, s, 0, NULL, r0);
        as->u[0] = p + e[c][0], as->u[1] = e[c][1];
        cs_anchor_residual(m, s, 0, NULL, r);
        double q[2] = {r0[0] - r[0], r0[1] - r[1]}, kinetic;
        double stored = cs_anchor_stored_energy(m, s, 0, &kinetic);
        printf("slid %.1f m, offset (%+.3f, %+.3f) m: the soil holds (%.1f, %.1f) N, stores %.3f J\n", p,
               e[c][0], e[c][1], q[0], q[1], stored);
        for (int i = 0; i < 2; i++)
            assert_true(fabs(q[i] - held[c][i]) <= 1e-12 * k * 0.005);
        CHECK_REL(stored, 0.5 * (q[0] * q[0] + q[1] * q[1]) / k, 1e-12);
    }
    const double rates[2][2] = {{1.0, 0.2}, {-1.0, 0.2}}, c = am->drag;
    const double swept[2][2] = {{-c * hypot(1.0, 0.2) * 1.0, -c * hypot(1.0, 0.2) * 0.2}, {0.0, -c * 0.04}};
    for (int k = 0; k < 2; k++) {
        double r[2], r1[2];
        as->slide = slid[0], as->plastic[0] = slid[0], as->plastic[1] = 0.0;
        as->u[0] = as->u_commit[0] = slid[0] + 0.005, as->u[1] = as->u_commit[1] = 0.0;
        s->h = 5e-4;
        for (int i = 0; i < 2; i++)
            as->rate[i] = rates[k][i], as->acc[i] = as->net[i] = 0.0, as->u[i] += s->h * rates[k][i];
        cs_anchor_residual(m, s, 0, NULL, r1);
        s->h = 0.0;
        cs_anchor_residual(m, s, 0, NULL, r);
        double d[2] = {r1[0] - r[0], r1[1] - r[1]};
        printf("moving at (%+.1f, %+.1f) m/s: the swept soil drags it with (%.3f, %.3f) N, by hand (%.3f, "
               "%.3f)\n",
               rates[k][0], rates[k][1], d[0], d[1], swept[k][0], swept[k][1]);
        for (int i = 0; i < 2; i++)
            assert_true(fabs(d[i] - swept[k][i]) <= 1e-9 * c);
    }
    cs_state_free(s);
    cs_model_free(m);
}

/* The ropes' horizontal pull on anchor a from their paths: each intact rope's end span, tension times the
 * horizontal part of its direction away from the anchor (weightless ropes: the span is straight). */
static double pull_by_the_paths(const cs_model *m, const cs_state *s, int a) {
    double f[2] = {0.0, 0.0}, xyz[3 * 512], t[512];
    for (int c = 0; c < cs_model_cable_count(m); c++) {
        cs_cable_view cv = {.size = sizeof cv};
        cs_state_cable(m, s, c, &cv, NULL);
        if (cv.status != CS_CABLE_INTACT) continue;
        int n = cs_state_cable_path(m, s, c, xyz, t, 512), i = a ? n - 1 : 0, j = a ? n - 2 : 1;
        assert_true(n < 512);
        double d[3] = {xyz[3 * j] - xyz[3 * i], xyz[3 * j + 1] - xyz[3 * i + 1],
                       xyz[3 * j + 2] - xyz[3 * i + 2]};
        double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), tension = t[a ? n - 2 : 0];
        f[0] += tension * d[0] / len, f[1] += tension * d[1] / len;
    }
    return hypot(f[0], f[1]);
}

/* A rigid anchor holds what its ropes pull: a weightless rope laid straight between rigid anchors at grade
 * pulls each with its pretension, along the barrier toward the other; struck by APS3's truck, every step's
 * reported force is the ropes' end spans' pull (tension times the span's horizontal direction), and the
 * peak is the largest pull at any commit. */
static void a_rigid_anchor_holds_the_ropes_pull(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    fx.barrier.start_anchor.footing.diameter = fx.barrier.end_anchor.footing.diameter = 0.0; /* rigid */
    for (int c = 0; c < 2; c++)
        fx.cables[c].rope.mass_per_length = 0.0;
    cs_error err;
    for (int posts = 0; posts < 2; posts++) {
        fx.barrier.cable_count = posts ? 2 : 1, fx.barrier.post_count = posts ? 16 : 0;
        cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
        if (!m) fail_msg("%s", err.message);
        cs_state *s = cs_state_create(m, &err);
        assert_non_null(s);
        cs_anchor_view av = {.size = sizeof av};
        if (!posts) {
            for (int a = 0; a < 2; a++) {
                assert_int_equal(cs_state_anchor(m, s, a, &av, &err), CS_OK);
                assert_true(av.rigid);
                CHECK_REL(av.force[0], a ? -fx.cables[0].pretension : fx.cables[0].pretension, 1e-9);
                assert_true(fabs(av.force[1]) < 1e-9 * fx.cables[0].pretension);
                CHECK_REL(av.peak_pull, fx.cables[0].pretension, 1e-9);
            }
        } else {
            double peak[2] = {0.0, 0.0}, reported[2] = {0.0, 0.0};
            while (s->outcome == CS_RUNNING) {
                assert_int_equal(cs_step(m, s, &err), CS_OK);
                for (int a = 0; a < 2; a++) {
                    double pull = pull_by_the_paths(m, s, a);
                    cs_state_anchor(m, s, a, &av, NULL);
                    CHECK_REL(hypot(av.force[0], av.force[1]), pull, 1e-9);
                    peak[a] = fmax(peak[a], pull);
                    /* the peak counts every commit, a failure's re-solve within a step too: never below a
                     * step's end, never falling */
                    assert_true(av.peak_pull >= peak[a] * (1.0 - 1e-9) && av.peak_pull >= reported[a]);
                    reported[a] = av.peak_pull;
                }
            }
            for (int a = 0; a < 2; a++) /* and above the steps' ends by no more than a step's change */
                CHECK_REL(reported[a], peak[a], 0.01);
            printf("the rigid anchors' peak pulls %.1f and %.1f kN (pretension 2 x %.1f kN)\n", peak[0] / 1e3,
                   peak[1] / 1e3, fx.cables[0].pretension / 1e3);
            assert_true(peak[0] > 2.0 * fx.cables[0].pretension);
        }
        cs_state_free(s);
        cs_model_free(m);
    }
}

/* A dead-man pulled up by a steep rope rises out of the soil instead of leaving it at once. APS3's 3 x
 * 5-ft shaft, its skin at the beta method's 25.4 kPa/m (S = q pi B D^2 / 2 = 84.8 kN, W = 22.6 kN), on
 * one weightless rope pretensioned to 180 kN and rising to a rigid anchor 20 m up and 2 m along: the
 * uplift, 179 kN, passes W + S at the first step (anchor_withdrawal) and the shaft rises, its rope giving
 * up its stretch, until the rope's pull no longer holds it up (at rest, F_z <= W + S x^2). With x = 1 - w
 * / D in the ground the skin holds S x^2 and takes S D (1 - x^3) / 3, to round-off (the rope's pull
 * along the ground stays inside the face's elastic range: the rest of the soil's work is the drag of
 * the soil its face sweeps as it gives along the ground, as booked). The rope's
 * elastic energy goes to lifting the weight, W w, to the skin (with its slip's elastic energy), to the
 * face's spring and to what backward Euler takes from the rise (about m |v - v_c|^2 / 2 a step, summed
 * here), within 2%; the ledger, which books as damping what each step takes from the motion, closes to
 * 1e-6. Not out
 * (x > 0): no anchor_pullout, the rope held. */
static void a_dead_man_rises_out_of_the_soil_by_its_skin(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    dead_men(&fx, 3.0, 5.0);
    fx.barrier.start_anchor.footing.skin_friction = 25.4e3;
    fx.barrier.end_anchor.footing.diameter = 0.0; /* rigid, 20 m up */
    fx.barrier.end_anchor.x = fx.barrier.start_anchor.x + 2.0, fx.barrier.end_anchor.z = 20.0;
    fx.barrier.cable_count = 1, fx.barrier.post_count = 0, fx.barrier.rail_count = 0;
    fx.cables[0].rope.mass_per_length = 0.0;
    fx.cables[0].pretension = 180e3;
    fx.scenario.start_gap = 1000.0; /* the vehicle stays away */
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    const cs_anchor_model *am = &m->anchors[0];
    const cs_anchor_state *as = &s->anchors[0];
    const double d = 5.0 * FT, skin = 25.4e3 * M_PI_2_VALUE * 2.0 * 3.0 * FT * d * d / 2.0,
                 weight = am->mass * fx.scenario.gravity;
    CHECK_REL(am->uplift_skin, skin, 1e-12);
    CHECK_REL(am->uplift_weight, weight, 1e-12);
    cs_energy_update(m, s);
    double soil0 = s->e_soil, rope0 = s->energy.cable_elastic, spring0 = s->energy.anchor_elastic,
           swept0 = as->swept, damped0 = s->energy.post_damping;
    int steps = 0;
    double euler = 0.0; /* backward Euler's take from the rise: m |v - v_c|^2 / 2 a step */
    while (steps < 4 || as->lift_rate > 0.0) {
        double v_c = as->lift_rate;
        assert_int_equal(cs_step(m, s, &err), CS_OK);
        euler += 0.5 * am->mass * (as->lift_rate - v_c) * (as->lift_rate - v_c);
        assert_true(++steps < 4000);
    }
    double w = as->lift, x = 1.0 - (as->lift_plastic + CS_SHAFT_MOBILISATION) / d, f[3],
           work = skin * d * (1.0 - x * x * x) / 3.0;
    cs_node_force(&s->cables[0], 0, NULL, f);
    cs_energy_update(m, s);
    double released = rope0 - s->energy.cable_elastic,
           spring = s->energy.anchor_elastic - weight * w - spring0; /* the face's spring */
    const cs_event *ev = NULL;
    int out = 0;
    for (int k = 0; k < s->event_count; k++) {
        if (s->events[k].type == CS_EVENT_ANCHOR_WITHDRAWAL && !ev) ev = &s->events[k];
        out += s->events[k].type == CS_EVENT_ANCHOR_PULLOUT;
    }
    assert_non_null(ev);
    printf("withdrawal at t = %.4f s with %.1f kN (W + S = %.1f kN); risen %.4f m (x = %.4f), at rest after "
           "%d steps with an uplift of %.1f kN against W + S x^2 = %.1f kN; the skin's work %.4f kJ (by hand "
           "%.4f); the rope gave %.3f kJ: the weight %.3f, the skin, the face's spring %.3f, backward Euler "
           "%.3f, the swept soil %.3f (damping booked %.3f); ledger %.2e\n",
           ev->t, ev->value / 1e3, (weight + skin) / 1e3, w, x, steps, f[2] / 1e3,
           (weight + skin * x * x) / 1e3, (s->e_soil - soil0 - (as->swept - swept0)) / 1e3, work / 1e3,
           released / 1e3, weight * w / 1e3, spring / 1e3, euler / 1e3, (as->swept - swept0) / 1e3,
           (s->energy.post_damping - damped0) / 1e3, s->energy.balance_error);
    assert_true(ev->value >= weight + skin);
    assert_true(w > 0.0 && x > 0.0 && !as->failed && out == 0);
    assert_true(f[2] <= weight + skin * x * x);
    CHECK_REL(s->e_soil - soil0 - (as->swept - swept0), work, 1e-9);
    CHECK_REL(weight * w + work + spring + euler + (as->swept - swept0), released, 0.02);
    CHECK_ABS(s->energy.balance_error, 0.0, 1e-6);
    cs_state_free(s);
    cs_model_free(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(anchor_from_its_footing),
                                       cmocka_unit_test(pretension_beyond_the_anchor_pulls_it_in),
                                       cmocka_unit_test(truck_drags_the_dead_men_through_the_soil),
                                       cmocka_unit_test(the_dead_men_plough_up_to_the_end_posts),
                                       cmocka_unit_test(a_ringing_dead_man_keeps_its_energy),
                                       cmocka_unit_test(a_ploughing_dead_man_sweeps_the_soil),
                                       cmocka_unit_test(a_dead_man_its_ropes_let_go_stops_in_the_soil),
                                       cmocka_unit_test(a_dead_man_backed_off_its_soil_is_held_by_its_sides),
                                       cmocka_unit_test(a_rigid_anchor_holds_the_ropes_pull),
                                       cmocka_unit_test(a_dead_man_rises_out_of_the_soil_by_its_skin)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
