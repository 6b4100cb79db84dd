/* SPDX-License-Identifier: MIT */
/* Slots, hooks, keyway bolts and brackets let a cable go at their documented limit (attachment.c). A cable
 * pulled sideways by F (horizontal, across the barrier) on a post leaning theta away from the pull bears on
 * it with F cos(theta) across the post and pulls it F sin(theta) along, toward the top; it leaves when F
 * sin(theta) > mu F cos(theta) + R, that is past theta* = atan(mu) + asin(R cos(atan(mu)) / F); a cable in a
 * slot only once it has reached the slot's open end, at cos(theta) = (z + d_p) / (h + d_p). Checked by hand
 * on a post leaning just short of and just past theta*, for the slot's and the hook's documented R (the
 * slot's post cut to 1.23 m, so that its upper cable, at 4 ft, is at the open end from 7.7 degrees); just
 * short of and past the open end on the 7-ft post; the slot's order: a cable held above keeps the ones below
 * in; and a keyway bolt's and a bracket's pull off their face (their component tests' lateral loads, or
 * a post group's), the face turning with a post that leans across the barrier, and which event says so. */
#include "check.h"
#include "core/vec3.h"
#include "fixture.h"
#include "run/run.h"

/* Two cables on one post at x = 0 between rigid anchors 10 m away; the post's height if given (else the
 * fixture's 7 ft). */
static void fill_one_post(cs_attachment kind, cs_face face, fixture *fx, double height) {
    fixture_aps3(fx);
    fx->barrier.post_count = 1;
    fx->posts[0].x = 0.0;
    if (height > 0.0) fx->posts[0].height = height;
    fx->posts[0].attachment = kind;
    fx->posts[0].face = face;
    fx->barrier.posts = fx->posts, fx->barrier.cables = fx->cables;
    fx->barrier.start_anchor.x = -10.0, fx->barrier.end_anchor.x = 10.0;
    fx->barrier.start_anchor.footing.diameter = fx->barrier.end_anchor.footing.diameter = 0.0;
    fx->scenario.impact_x = 5.0;
}

static cs_model *build(fixture *fx) {
    cs_error err;
    cs_model *m = cs_model_create(&fx->barrier, &fx->vehicle, &fx->scenario, &err);
    if (!m) fail_msg("%s", err.message);
    return m;
}

static cs_model *one_post_on(cs_attachment kind, cs_face face, fixture *fx, double height) {
    fill_one_post(kind, face, fx, height);
    return build(fx);
}

static cs_model *one_post(cs_attachment kind, fixture *fx, double height) {
    return one_post_on(kind, CS_FACE_ATTACK, fx, height);
}

static cs_state *new_state(const cs_model *m) {
    cs_error err;
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    return s;
}

/* The post leaning theta toward +y; cable c's node on it, its two spans running 10 m along x and 5 m
 * toward +y at tension t each: a pull of 2 t 5 / sqrt(125) across the barrier. Returns that pull. */
static double lean_and_pull_at(const cs_model *m, cs_state *s, double along_x, double theta, int c,
                               double t) {
    s->posts[0].tilt[0] = along_x, s->posts[0].tilt[1] = theta;
    cs_cable_state *cs = &s->cables[c];
    int i = cs->where[0];
    cs_post_attachment(m, 0, s->posts[0].tilt, 0.0, 0, cs_post_cable_z(m, s, 0, c), cs->pos + 3 * i);
    for (int k = -1; k <= 1; k += 2) {
        double *q = cs->pos + 3 * (i + k);
        v3_set(q, cs->pos[3 * i] + 10.0 * k, cs->pos[3 * i + 1] + 5.0, cs->pos[3 * i + 2]);
    }
    cs->tension[i - 1] = cs->tension[i] = t;
    return 2.0 * t * 5.0 / sqrt(125.0);
}

static double lean_and_pull(const cs_model *m, cs_state *s, double theta, int c, double t) {
    return lean_and_pull_at(m, s, 0.0, theta, c, t);
}

static double release_angle(double mu, double r, double f) {
    double phi = atan(mu);
    return phi + asin(r * cos(phi) / f);
}

#define SHORT_POST 1.23 /* m: the upper cable (1.2192 m) at a slot's open end from acos(1.2192 / 1.23) */

static void lets_go_at_its_limit(cs_attachment kind, double documented) {
    fixture fx;
    cs_model *m = one_post(kind, &fx, kind == CS_ATTACH_SLOT ? SHORT_POST : 0.0);
    cs_error err;
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    CHECK_REL(m->posts[0].release_force, documented, 1e-12);
    double mu = m->cables[1].mu_post, t = 10e3;
    double f = lean_and_pull(m, s, 0.0, 1, t), th = release_angle(mu, documented, f);
    for (int side = -1; side <= 1; side += 2) {
        cs_state_reset(m, s);
        if (kind == CS_ATTACH_SLOT)
            s->posts[0].lift = m->posts[0].height - m->cables[1].z; /* at the open end */
        lean_and_pull(m, s, th + side * 1e-3, 1, t);
        lean_and_pull(m, s, th + side * 1e-3, 0, 0.0); /* the lower cable, in the stack, not pulled */
        int before = s->event_count;
        assert_int_equal(cs_attachment_check_release(m, s, 0), side > 0);
        assert_int_equal(s->cables[1].where[0]<0, side> 0);
        if (side > 0) { /* the event's value: the pull along the post, F sin(theta) */
            assert_int_equal(s->events[before].type, CS_EVENT_CABLE_RELEASE);
            CHECK_REL(s->events[before].value, f * sin(th + 1e-3), 1e-9);
        }
    }
    cs_state_free(s);
    cs_model_free(m);
}

static void slot_lets_go_at_its_limit(void **state) {
    (void)state;
    lets_go_at_its_limit(CS_ATTACH_SLOT, 1.0e3);
}

static void hook_lets_go_at_its_limit(void **state) {
    (void)state;
    lets_go_at_its_limit(CS_ATTACH_HOOK, 1.5e3);
}

/* On the attack face the cable pulled toward +y bears on the post: a keyway bolt or a bracket lets it go
 * along the post as a hook does, at its component test's vertical load (1.00 kip, 346 lb). */
static void bolted_let_go_along_at_their_limit(void **state) {
    (void)state;
    lets_go_at_its_limit(CS_ATTACH_KEYWAY, 1.00 * CS_KIP);
    lets_go_at_its_limit(CS_ATTACH_BRACKET, 346.0 * CS_LBF);
}

/* Pulled off the protected face of an upright post by F across the barrier, a keyway bolt or a bracket
 * lets its cable go past its lateral load (8.00 and 6.10 kip), the event's value F; on the attack face
 * the same cable bears on the post and stays at 100 kN. Leaning theta toward the pull, the face turns
 * with the post: the cable, bearing on the fitting with F cos(theta), leaves along the post past theta*
 * as from a hook, F sin(theta) = mu F cos(theta) + R, its lateral pull F cos(theta) short of its own. */
static void bolted_let_go_off_their_face(void **state) {
    (void)state;
    const cs_attachment kinds[] = {CS_ATTACH_KEYWAY, CS_ATTACH_BRACKET};
    const double lateral[] = {8.00 * CS_KIP, 6.10 * CS_KIP}, vertical[] = {1.00 * CS_KIP, 346.0 * CS_LBF};
    for (int k = 0; k < 2; k++) {
        fixture fx;
        cs_model *m = one_post_on(kinds[k], CS_FACE_PROTECTED, &fx, 0.0);
        cs_error err;
        cs_state *s = cs_state_create(m, &err);
        assert_non_null(s);
        CHECK_REL(m->posts[0].lateral_release, lateral[k], 1e-12);
        double per_t = lean_and_pull(m, s, 0.0, 1, 1.0); /* the pull of a unit tension */
        for (int side = -1; side <= 1; side += 2) {
            cs_state_reset(m, s);
            double t = lateral[k] * (1.0 + side * 1e-6) / per_t;
            lean_and_pull(m, s, 0.0, 1, t);
            int before = s->event_count;
            assert_int_equal(cs_attachment_check_release(m, s, 0), side > 0);
            assert_int_equal(s->cables[1].where[0]<0, side> 0);
            if (side > 0) {
                assert_int_equal(s->events[before].type, CS_EVENT_CABLE_PULLED_OFF);
                assert_int_equal(s->events[before].cable, 1);
                CHECK_REL(s->events[before].value, t * per_t, 1e-9);
            }
        }
        const double th = 0.5;
        for (int side = -1; side <= 1; side += 2) {
            cs_state_reset(m, s);
            double mu = m->cables[1].mu_post;
            double t = vertical[k] * (1.0 + side * 1e-6) / (per_t * (sin(th) - mu * cos(th)));
            lean_and_pull(m, s, th, 1, t);
            assert_true(t * per_t * cos(th) < lateral[k]);
            int before = s->event_count;
            assert_int_equal(cs_attachment_check_release(m, s, 0), side > 0);
            assert_int_equal(s->cables[1].where[0]<0, side> 0);
            if (side > 0) assert_int_equal(s->events[before].type, CS_EVENT_CABLE_RELEASE);
        }
        cs_state_free(s);
        cs_model_free(m);
        m = one_post_on(kinds[k], CS_FACE_ATTACK, &fx, 0.0);
        s = cs_state_create(m, &err);
        lean_and_pull(m, s, 0.0, 1, 100e3 / per_t);
        assert_int_equal(cs_attachment_check_release(m, s, 0), 0);
        cs_state_free(s);
        cs_model_free(m);
    }
}

/* Pulled off the face by F across the barrier: leaning theta toward the pull, less than the lean at
 * which the pull along the post decides (tan(theta) < mu + R / R_off), the face turns with the post and
 * the cable leaves once F cos(theta) passes R_off; leaning along the barrier, the face keeps facing the
 * pull and it leaves once F passes R_off. A post group's loads replace the kind's. */
static void bolted_face_turns_with_the_post(void **state) {
    (void)state;
    fixture fx;
    fill_one_post(CS_ATTACH_BRACKET, CS_FACE_PROTECTED, &fx, 0.0);
    fx.posts[0].lateral_release_force = 10e3, fx.posts[0].release_force = 2e3;
    cs_model *m = build(&fx);
    cs_error err;
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    CHECK_REL(m->posts[0].lateral_release, 10e3, 1e-12);
    CHECK_REL(m->posts[0].release_force, 2e3, 1e-12);
    const double th = 0.1, per_t = lean_and_pull(m, s, 0.0, 1, 1.0);
    assert_true(tan(th) < m->cables[1].mu_post);
    for (int lean = 0; lean < 2; lean++) { /* across the barrier, then along it */
        double turn = lean == 0 ? cos(th) : 1.0;
        for (int side = -1; side <= 1; side += 2) {
            cs_state_reset(m, s);
            double t = 10e3 * (1.0 + side * 1e-6) / (per_t * turn);
            lean_and_pull_at(m, s, lean == 1 ? th : 0.0, lean == 0 ? th : 0.0, 1, t);
            int before = s->event_count;
            assert_int_equal(cs_attachment_check_release(m, s, 0), side > 0);
            if (side > 0) {
                assert_int_equal(s->events[before].type, CS_EVENT_CABLE_PULLED_OFF);
                CHECK_REL(s->events[before].value, t * per_t * turn, 1e-9);
            }
        }
    }
    cs_state_free(s);
    cs_model_free(m);
}

/* The post's unit axis as it stands. */
static void axis_of(const cs_model *m, const cs_state *s, double a[3]) {
    double base[3], top[3];
    cs_post_attachment(m, 0, s->posts[0].tilt, 0.0, 0, 0.0, base);
    cs_post_attachment(m, 0, s->posts[0].tilt, 0.0, 0, 1.0, top);
    v3_sub(a, top, base);
}

/* The slot's cables' pulls on the post, summed: along it into *fa, across it into *fn (each cable's). */
static void stack_pulls(const cs_model *m, const cs_state *s, double *fa, double *fn) {
    double a[3];
    axis_of(m, s, a);
    *fa = *fn = 0.0;
    for (int c = 0; c < m->cable_count; c++) {
        double f[3], across[3];
        cs_node_force(&s->cables[c], s->cables[c].where[0], NULL, f);
        double along = v3_dot(f, a);
        v3_copy(across, f);
        v3_addto(across, a, -along);
        *fa += along, *fn += v3_norm(across);
    }
}

static double ropes_stored(const cs_model *m, const cs_state *s) {
    double e = 0.0;
    for (int c = 0; c < m->cable_count; c++)
        e += cs_cable_stored_energy(&m->cables[c], &s->cables[c]);
    return e;
}

/* Both cables on the 7-ft post leaning theta toward +y, their anchors (10 m away along x) moved toward +y
 * to their cable's height, each span 0.2% longer than as laid: the spans pull the post toward its lean, and
 * back toward the cables' height. Leaning half of atan(mu), friction holds the stack where it is. Leaning 0.4
 * rad (past atan(mu) = 8.5 degrees) it rides up the slot, the tensions following the geometry, to where the
 * pull up the slot is spent on friction, sum F_a = mu sum F_n (to 1e-6 of the pulls); the ropes' stored
 * energy lost on the way is booked as friction (to 1e-9), and lies between what friction alone takes over the
 * lift, mu F_n u, and what the pull along did at its largest, F_a u. */
static void slot_stack_rides_until_friction_holds(void **state) {
    (void)state;
    fixture fx;
    cs_model *m = one_post(CS_ATTACH_SLOT, &fx, 0.0);
    cs_state *s = new_state(m);
    const double mu = m->cables[0].mu_post;
    for (int lean = 0; lean < 2; lean++) {
        cs_state_reset(m, s);
        s->posts[0].tilt[1] = lean ? 0.4 : 0.5 * atan(mu);
        cs_post_place_nodes(m, s, 0, s->posts[0].tilt, NULL);
        for (int c = 0; c < m->cable_count; c++) { /* each span 0.2% longer than as laid, toward +y */
            cs_cable_state *cs = &s->cables[c];
            const double *node = cs->pos + 3 * cs->where[0], z = m->cables[c].z;
            double laid = hypot(10.0, z) * 1.002, dz = node[2] - z;
            for (int k = -1; k <= 1; k += 2)
                v3_set(cs->pos + 3 * (cs->where[0] + k), node[0] + 10.0 * k,
                       node[1] + sqrt(laid * laid - 100.0 - dz * dz), z);
            cs_cable_update_tensions(&m->cables[c], cs, NULL);
        }
        double fa0, fn0, fa1, fn1, e0 = ropes_stored(m, s), friction0 = s->e_friction;
        stack_pulls(m, s, &fa0, &fn0);
        int rode = cs_attachment_ride(m, s, 0);
        stack_pulls(m, s, &fa1, &fn1);
        double u = s->posts[0].lift, spent = e0 - ropes_stored(m, s);
        if (!lean) {
            assert_true(fa0 < mu * fn0);
            assert_int_equal(rode, 0);
            assert_true(u == 0.0);
            continue;
        }
        assert_true(fa0 > mu * fn0);
        assert_int_equal(rode, 1);
        assert_true(u > 0.0 && u < m->posts[0].height - m->cables[1].z);
        assert_true(fabs(fa1 - mu * fn1) <= 1e-6 * (fa1 + mu * fn1));
        CHECK_REL(s->e_friction - friction0, spent, 1e-9);
        assert_true(spent >= mu * fmin(fn0, fn1) * u && spent <= fmax(fa0, fa1) * u);
    }
    cs_state_free(s);
    cs_model_free(m);
}

/* On the 7-ft post the upper cable, at 4 ft, is held in the slot however far the post leans until it has
 * ridden to the open end: pulled by 10 kN at 60 degrees (far past theta*, 14.9 degrees) it stays 1 mm short
 * of it; at it, the stack's pull along the post past friction presses the cap off and it leaves. */
static void slot_holds_until_its_open_end(void **state) {
    (void)state;
    fixture fx;
    cs_model *m = one_post(CS_ATTACH_SLOT, &fx, 0.0);
    cs_state *s = new_state(m);
    double open = m->posts[0].height - m->cables[1].z, th = 60.0 * CS_DEG;
    for (int side = -1; side <= 1; side += 2) {
        cs_state_reset(m, s);
        s->posts[0].lift = side < 0 ? open - 1e-3 : open;
        lean_and_pull(m, s, th, 1, 10e3);
        lean_and_pull(m, s, th, 0, 1.0); /* the lower cable barely pulled */
        assert_int_equal(cs_attachment_check_release(m, s, 0), side > 0);
        assert_int_equal(s->cables[1].where[0]<0, side> 0);
        assert_true(s->cables[0].where[0] > 0);
    }
    cs_state_free(s);
    cs_model_free(m);
}

/* The lower cable (0) pulled hard, the upper (1) barely (0.9 N, short of R on its own), the stack at the
 * short post's open end: in a slot the lower cable presses the upper out past the cap, and stays itself,
 * below the open end, until it rides there. A hook lets the lower cable go by its own pull, the upper
 * stays. */
static void slot_lets_go_from_the_top(void **state) {
    (void)state;
    for (int kind = CS_ATTACH_SLOT; kind <= CS_ATTACH_HOOK; kind++) {
        fixture fx;
        cs_model *m = one_post((cs_attachment)kind, &fx, SHORT_POST);
        cs_error err;
        cs_state *s = cs_state_create(m, &err);
        if (kind == CS_ATTACH_SLOT) s->posts[0].lift = m->posts[0].height - m->cables[1].z;
        double th = 0.85;
        lean_and_pull(m, s, th, 0, 40e3);
        lean_and_pull(m, s, th, 1, 1.0);
        assert_int_equal(cs_attachment_check_release(m, s, 0), 1);
        assert_int_equal(s->cables[1].where[0] < 0, kind == CS_ATTACH_SLOT);
        assert_int_equal(s->cables[0].where[0] < 0, kind == CS_ATTACH_HOOK);
        cs_state_free(s);
        cs_model_free(m);
    }
}

/* Threaded and clamped cables never let go, however far the post leans. */
static void through_and_clamped_hold(void **state) {
    (void)state;
    for (int kind = CS_ATTACH_THROUGH; kind <= CS_ATTACH_CLAMPED; kind++) {
        fixture fx;
        cs_model *m = one_post((cs_attachment)kind, &fx, 0.0);
        cs_error err;
        cs_state *s = cs_state_create(m, &err);
        lean_and_pull(m, s, 1.2, 1, 100e3);
        assert_int_equal(cs_attachment_check_release(m, s, 0), 0);
        cs_state_free(s);
        cs_model_free(m);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(slot_lets_go_at_its_limit),
                                       cmocka_unit_test(hook_lets_go_at_its_limit),
                                       cmocka_unit_test(slot_holds_until_its_open_end),
                                       cmocka_unit_test(slot_lets_go_from_the_top),
                                       cmocka_unit_test(slot_stack_rides_until_friction_holds),
                                       cmocka_unit_test(bolted_let_go_along_at_their_limit),
                                       cmocka_unit_test(bolted_let_go_off_their_face),
                                       cmocka_unit_test(bolted_face_turns_with_the_post),
                                       cmocka_unit_test(through_and_clamped_hold)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
