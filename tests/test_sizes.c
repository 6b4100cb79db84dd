/* SPDX-License-Identifier: MIT */
/* The definitions' sizes (def.h): a program built against an earlier cablesim, whose structs are smaller,
 * gets the run of today's structs with the defaults for the fields it lacks; a struct not started from
 * its cs_default_*(), or larger than the library's, is refused with a sentence naming it. The earlier
 * structs are today's without their last field: a rope without its diameter (so a cable ending in that
 * smaller rope, read at its own stride in the barrier's array) and a scenario without max_steps; and
 * nested structs a field short in the middle of their owners (a post's section and footing, the start
 * anchor's footing), the owner's later fields read from where the earlier layout puts them.
 * The structs the engine fills (sim.h: cs_summary, the views, cs_event, cs_energy, cs_cable_summary,
 * cs_sudden_loss, the last in an array at its first one's size) the other way: one a field short
 * gets the leading values of a whole one from the same state and nothing past its size; a size of 0 or
 * larger than the library's is refused by the struct's name, nothing written. (cs_model_input, filled by
 * the loader: test_io_loader.c.) */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "check.h"
#include "fixture.h"

enum { OLD_ROPE = offsetof(cs_rope_def, diameter), OLD_CABLE = offsetof(cs_cable_def, rope) + OLD_ROPE };
enum { OLD_SCENARIO = offsetof(cs_scenario_def, max_steps) };

/* The state hash of a run of the model to t = 0.3 s. */
static unsigned long long run_hash(const cs_barrier_def *b, const cs_vehicle_def *v,
                                   const cs_scenario_def *s) {
    cs_error err;
    cs_model *m = cs_model_create(b, v, s, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *st = cs_state_create(m, &err);
    assert_non_null(st);
    assert_int_equal(cs_run(m, st, NULL, NULL, &err), CS_OK);
    unsigned long long h = cs_state_hash(m, st);
    cs_state_free(st);
    cs_model_free(m);
    return h;
}

static void earlier_structs_run_as_todays_with_defaults(void **state) {
    (void)state;
    /* the earlier layouts are today's cut before their last field */
    assert_int_equal(OLD_ROPE + sizeof(double), sizeof(cs_rope_def));
    assert_int_equal(OLD_CABLE + sizeof(double), sizeof(cs_cable_def));
    assert_int_equal(OLD_SCENARIO + sizeof(double), sizeof(cs_scenario_def));
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.t_end = 0.3;
    fx.scenario.max_steps = 123; /* beyond the earlier scenario: must not be read */
    unsigned char old_cables[2][OLD_CABLE], old_scenario[OLD_SCENARIO];
    for (int c = 0; c < 2; c++) {
        fx.cables[c].rope.diameter = 0.05; /* beyond the earlier rope: must not be read */
        memcpy(old_cables[c], &fx.cables[c], OLD_CABLE);
        size_t cable = OLD_CABLE, rope = OLD_ROPE;
        memcpy(old_cables[c], &cable, sizeof cable);
        memcpy(old_cables[c] + offsetof(cs_cable_def, rope), &rope, sizeof rope);
    }
    memcpy(old_scenario, &fx.scenario, OLD_SCENARIO);
    size_t scenario = OLD_SCENARIO;
    memcpy(old_scenario, &scenario, sizeof scenario);
    cs_barrier_def old_barrier = fx.barrier;
    old_barrier.cables = (const cs_cable_def *)(const void *)old_cables;

    /* today's structs with the defaults in the fields the earlier ones lack */
    fx.scenario.max_steps = cs_default_scenario_def().max_steps;
    for (int c = 0; c < 2; c++)
        fx.cables[c].rope.diameter = cs_default_rope_def().diameter;
    unsigned long long today = run_hash(&fx.barrier, &fx.vehicle, &fx.scenario);
    unsigned long long earlier =
        run_hash(&old_barrier, &fx.vehicle, (const cs_scenario_def *)(const void *)old_scenario);
    assert_true(today == earlier);
    /* the field the earlier scenario lacks is read from today's, and taken at its default from it */
    fx.scenario.max_steps = 123;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    assert_non_null(m);
    assert_true(cs_model_scenario(m)->max_steps == 123.0);
    cs_model_free(m);
    m = cs_model_create(&old_barrier, &fx.vehicle, (const cs_scenario_def *)(const void *)old_scenario, &err);
    assert_non_null(m);
    assert_true(cs_model_scenario(m)->max_steps == cs_default_scenario_def().max_steps);
    assert_int_equal(cs_model_scenario(m)->size, sizeof(cs_scenario_def));
    cs_model_free(m);
}

/* Cut the last field (8 bytes) of the nested struct at offset `at` of size `inner` out of an owner of
 * `size` bytes at src, into dst: the owner as a program built before that nested struct grew laid it out,
 * its size and the nested one's set to theirs. Returns the owner's earlier size. */
static size_t cut_nested(unsigned char *dst, const unsigned char *src, size_t size, size_t at, size_t inner) {
    memcpy(dst, src, at + inner - 8);
    memcpy(dst + at + inner - 8, src + at + inner, size - at - inner);
    size_t earlier = size - 8, nested = inner - 8;
    memcpy(dst, &earlier, sizeof earlier);
    memcpy(dst + at, &nested, sizeof nested);
    return earlier;
}

/* A program built before a post's section and footing grew (each a field short, in the middle of the
 * post) and before an anchor's footing grew (the start anchor's in the middle of the barrier): its posts
 * and anchors are read
 * at their own layout, the fields after each smaller nested struct from where that layout puts them. */
static void earlier_nested_structs_run_as_todays_with_defaults(void **state) {
    (void)state;
    enum { SEC = offsetof(cs_post_def, section), FOOT = offsetof(cs_post_def, footing) };
    enum { START = offsetof(cs_barrier_def, start_anchor), END = offsetof(cs_barrier_def, end_anchor) };
    enum { AFOOT = offsetof(cs_anchor_def, footing) };
    /* the earlier layouts are today's nested structs cut before their last field */
    assert_int_equal(offsetof(cs_section_def, fill_strength) + 8, sizeof(cs_section_def));
    assert_int_equal(offsetof(cs_footing_def, unit_weight) + 8, sizeof(cs_footing_def));
    assert_true(SEC < FOOT && FOOT + sizeof(cs_footing_def) < sizeof(cs_post_def)); /* both mid-post */
    assert_true(START + sizeof(cs_anchor_def) <= END); /* the start anchor mid-barrier */
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.t_end = 0.3;
    int np = fx.barrier.post_count;
    /* beyond the earlier structs: must not be read */
    for (int p = 0; p < np; p++)
        fx.posts[p].section.fill_strength = 1e9;
    fx.barrier.start_anchor.footing.unit_weight = fx.barrier.end_anchor.footing.unit_weight = 29e3;

    enum { POST = sizeof(cs_post_def), OLD_POST = POST - 16 };
    static _Alignas(cs_post_def) unsigned char old_posts[64][OLD_POST];
    for (int p = 0; p < np; p++) {
        unsigned char once[POST - 8];
        size_t n = cut_nested(once, (const unsigned char *)&fx.posts[p], POST, SEC, sizeof(cs_section_def));
        assert_int_equal(cut_nested(old_posts[p], once, n, FOOT - 8, sizeof(cs_footing_def)), OLD_POST);
    }
    enum { BARRIER = sizeof(cs_barrier_def), ANCHOR = sizeof(cs_anchor_def) };
    unsigned char anchor_once[2][ANCHOR];
    _Alignas(cs_barrier_def) unsigned char old_barrier[BARRIER - 16];
    cs_barrier_def b = fx.barrier;
    b.posts = (const cs_post_def *)(const void *)old_posts;
    cut_nested(anchor_once[0], (const unsigned char *)&b.start_anchor, ANCHOR, AFOOT, sizeof(cs_footing_def));
    cut_nested(anchor_once[1], (const unsigned char *)&b.end_anchor, ANCHOR, AFOOT, sizeof(cs_footing_def));
    /* the barrier with its anchors a field short: each anchor 8 bytes smaller, in place */
    unsigned char whole[BARRIER];
    memcpy(whole, &b, BARRIER);
    memcpy(whole + START, anchor_once[0], ANCHOR - 8);
    memcpy(whole + START + ANCHOR - 8, (const unsigned char *)&b + START + ANCHOR, END - START - ANCHOR);
    memcpy(whole + END - 8, anchor_once[1], ANCHOR - 8);
    memcpy(whole + END + ANCHOR - 16, (const unsigned char *)&b + END + ANCHOR, BARRIER - END - ANCHOR);
    size_t old_size = BARRIER - 16;
    memcpy(old_barrier, whole, BARRIER - 16);
    memcpy(old_barrier, &old_size, sizeof old_size);

    /* today's structs with the defaults in the fields the earlier ones lack */
    cs_section_def ds = cs_default_section_def();
    cs_footing_def df = cs_default_footing_def();
    for (int p = 0; p < np; p++)
        fx.posts[p].section.fill_strength = ds.fill_strength;
    fx.barrier.start_anchor.footing.unit_weight = fx.barrier.end_anchor.footing.unit_weight = df.unit_weight;
    unsigned long long today = run_hash(&fx.barrier, &fx.vehicle, &fx.scenario);
    unsigned long long earlier =
        run_hash((const cs_barrier_def *)(const void *)old_barrier, &fx.vehicle, &fx.scenario);
    assert_true(today == earlier);
    /* and the cut fields were not read: with them today's run differs (the anchors' wedge is heavier) */
    fx.barrier.start_anchor.footing.unit_weight = fx.barrier.end_anchor.footing.unit_weight = 29e3;
    assert_true(run_hash(&fx.barrier, &fx.vehicle, &fx.scenario) != today);
}

static void expect_refused(const cs_barrier_def *b, const cs_vehicle_def *v, const cs_scenario_def *s,
                           const char *want) {
    cs_error err;
    assert_null(cs_model_create(b, v, s, &err));
    assert_int_equal(err.status, CS_ERR_INVALID);
    if (!strstr(err.message, want)) fail_msg("'%s' lacks '%s'", err.message, want);
}

static void unknown_sizes_are_refused(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    cs_vehicle_def v = fx.vehicle;
    v.size = 0; /* not from cs_default_vehicle_def() */
    expect_refused(&fx.barrier, &v, &fx.scenario, "vehicle: size 0: start it from cs_default_vehicle_def()");
    v.size = sizeof v + 8; /* a program built for a later cablesim */
    expect_refused(&fx.barrier, &v, &fx.scenario, "where this library's is");
    fx.posts[3].footing.size = 0;
    expect_refused(&fx.barrier, &fx.vehicle, &fx.scenario, "post 3's footing: size 0");
    fx.posts[3].footing = cs_default_footing_def();
    fx.posts[3].footing.diameter = 0.75 * FT;
    fx.posts[3].footing.depth = 3 * FT;
    fx.posts[3].footing.soil_pressure = 8000 * PSF;
    /* a smaller section inside a post of today's size: the footing, read from where that section ends,
     * has no size there (the section's last field, 0) */
    fx.posts[3].section.size = sizeof(cs_section_def) - 8;
    expect_refused(
        &fx.barrier, &fx.vehicle, &fx.scenario,
        "post 3's footing: not readable after a smaller nested struct: a layout this library does not know");
    /* a size that is not a multiple of the struct's alignment is no struct's */
    fx.posts[3].section.size = sizeof(cs_section_def) - 4;
    expect_refused(&fx.barrier, &fx.vehicle, &fx.scenario, "not a multiple of its alignment");
    /* a smaller rope inside a cable of today's size: 8 bytes more cable than this library's */
    fx.posts[3].section.size = sizeof(cs_section_def);
    fx.cables[1].rope.size = sizeof(cs_rope_def) - 8;
    expect_refused(&fx.barrier, &fx.vehicle, &fx.scenario, "a layout this library does not know");
}

/* ---- the structs the engine fills ---- */

/* APS3 run to t = 0.3 s: posts hinged, ropes loaded, the vehicle slowed. */
static struct {
    fixture fx;
    cs_model *model;
    cs_state *state;
    int post; /* the post nearest the impact */
} run;

static int run_setup(void **state) {
    (void)state;
    fixture_aps3(&run.fx);
    run.fx.scenario.t_end = 0.3;
    cs_error err;
    run.model = cs_model_create(&run.fx.barrier, &run.fx.vehicle, &run.fx.scenario, &err);
    run.state = run.model ? cs_state_create(run.model, &err) : NULL;
    if (!run.state || cs_run(run.model, run.state, NULL, NULL, &err) != CS_OK) return -1;
    for (int p = 1; p < cs_model_post_count(run.model); p++)
        if (fabs(cs_model_post_x(run.model, p) - run.fx.scenario.impact_x) <
            fabs(cs_model_post_x(run.model, run.post) - run.fx.scenario.impact_x))
            run.post = p;
    return 0;
}

static int run_teardown(void **state) {
    (void)state;
    cs_state_free(run.state);
    cs_model_free(run.model);
    return 0;
}

static cs_status fill_summary(void *out, cs_error *err) {
    return cs_state_summary(run.state, out, err);
}
static cs_status fill_vehicle(void *out, cs_error *err) {
    return cs_state_vehicle(run.model, run.state, out, err);
}
static cs_status fill_cable(void *out, cs_error *err) {
    return cs_state_cable(run.model, run.state, 0, out, err);
}
static cs_status fill_post(void *out, cs_error *err) {
    return cs_state_post(run.model, run.state, run.post, out, err);
}
static cs_status fill_anchor(void *out, cs_error *err) {
    return cs_state_anchor(run.model, run.state, 0, out, err);
}
static cs_status fill_event(void *out, cs_error *err) {
    return cs_state_event(run.state, 0, out, err);
}
static cs_status fill_energy(void *out, cs_error *err) {
    return cs_state_energy(run.state, out, err);
}
static cs_status fill_cable_summary(void *out, cs_error *err) {
    return cs_state_cable_summary(run.state, 0, out, err);
}

/* A force history with two falls of 90% of its peak within 10 ms: two sudden losses. */
enum { FALL_SAMPLES = 40 };
static void two_falls(double *t, double *f) {
    for (int j = 0; j < FALL_SAMPLES; j++)
        t[j] = 1e-3 * j, f[j] = (j < 10 || (j >= 20 && j < 30)) ? 1e5 : 1e4;
}
static cs_status fill_sudden_loss(void *out, cs_error *err) {
    double t[FALL_SAMPLES], f[FALL_SAMPLES];
    two_falls(t, f);
    if (err) err->status = CS_OK;
    int n = cs_sudden_losses(t, f, FALL_SAMPLES, 1e-3, NULL, 0, out, 1, err);
    return n < 0 ? (err ? err->status : CS_ERR_INVALID) : n == 2 ? CS_OK : CS_ERR_UNSTABLE;
}

typedef struct filled {
    const char *name;
    cs_status (*fill)(void *out, cs_error *err);
    size_t size;   /* this library's */
    size_t short_; /* an earlier struct's: today's without its last field */
} filled;

static const filled summary_case = {"cs_summary", fill_summary, sizeof(cs_summary),
                                    offsetof(cs_summary, penetration_beyond_m)};
static const filled vehicle_case = {"cs_vehicle_view", fill_vehicle, sizeof(cs_vehicle_view),
                                    offsetof(cs_vehicle_view, rear_corners)};
static const filled cable_case = {"cs_cable_view", fill_cable, sizeof(cs_cable_view),
                                  offsetof(cs_cable_view, node_count)};
static const filled post_case = {"cs_post_view", fill_post, sizeof(cs_post_view),
                                 offsetof(cs_post_view, top)};
static const filled anchor_case = {"cs_anchor_view", fill_anchor, sizeof(cs_anchor_view),
                                   offsetof(cs_anchor_view, uplift_capacity)};
static const filled event_case = {"cs_event", fill_event, sizeof(cs_event), offsetof(cs_event, post)};
static const filled energy_case = {"cs_energy", fill_energy, sizeof(cs_energy),
                                   offsetof(cs_energy, balance_error)};
static const filled cable_summary_case = {"cs_cable_summary", fill_cable_summary, sizeof(cs_cable_summary),
                                          offsetof(cs_cable_summary, energy_share)};
static const filled sudden_loss_case = {"cs_sudden_loss", fill_sudden_loss, sizeof(cs_sudden_loss),
                                        offsetof(cs_sudden_loss, force_after_n)};

enum { ROOM = 1024, MARK = 0x5a };

static size_t size_of(const unsigned char *b) {
    size_t n;
    memcpy(&n, b, sizeof n);
    return n;
}

static void refused(const filled *c, size_t size) {
    _Alignas(max_align_t) unsigned char b[ROOM];
    memset(b, MARK, sizeof b);
    memcpy(b, &size, sizeof size);
    cs_error err;
    assert_int_equal(c->fill(b, &err), CS_ERR_INVALID);
    assert_int_equal(err.status, CS_ERR_INVALID);
    char want[64];
    snprintf(want, sizeof want, "%s: size %zu", c->name, size);
    if (strncmp(err.message, want, strlen(want)) != 0)
        fail_msg("'%s' does not begin '%s'", err.message, want);
    for (size_t k = sizeof size; k < sizeof b; k++) /* nothing written */
        assert_int_equal(b[k], MARK);
}

static void filled_to_the_callers_size(void **state) {
    const filled *c = *state;
    assert_true(c->size <= ROOM && c->short_ > sizeof(size_t) && c->short_ < c->size);
    _Alignas(max_align_t) unsigned char whole[ROOM], shorter[ROOM];
    memset(whole, 0, sizeof whole);
    memcpy(whole, &c->size, sizeof c->size);
    memset(shorter, MARK, sizeof shorter);
    memcpy(shorter, &c->short_, sizeof c->short_);
    cs_error err;
    assert_int_equal(c->fill(whole, &err), CS_OK);
    assert_int_equal(c->fill(shorter, &err), CS_OK);
    assert_int_equal(size_of(whole), c->size);
    assert_int_equal(size_of(shorter), c->short_);
    /* the same leading values, bit for bit, and none of them all zero */
    assert_memory_equal(whole + sizeof(size_t), shorter + sizeof(size_t), c->short_ - sizeof(size_t));
    size_t nonzero = 0;
    for (size_t k = sizeof(size_t); k < c->short_; k++)
        nonzero += whole[k] != 0;
    assert_true(nonzero > 0);
    for (size_t k = c->short_; k < sizeof shorter; k++) /* nothing past its size */
        assert_int_equal(shorter[k], MARK);
    refused(c, 0);
    refused(c, sizeof(size_t) - 1);
    refused(c, c->size + sizeof(double));
}

/* The values the views and the summary give agree with one another where they are the same quantity. */
static void views_agree_with_the_summary(void **state) {
    (void)state;
    cs_summary s = {.size = sizeof s};
    cs_vehicle_view v = {.size = sizeof v};
    cs_cable_view c = {.size = sizeof c};
    cs_event e = {.size = sizeof e};
    cs_error err;
    assert_int_equal(cs_state_summary(run.state, &s, &err), CS_OK);
    assert_int_equal(cs_state_vehicle(run.model, run.state, &v, &err), CS_OK);
    assert_int_equal(cs_state_cable(run.model, run.state, 0, &c, &err), CS_OK);
    assert_int_equal(cs_state_event(run.state, 0, &e, &err), CS_OK);
    assert_true(fabs(v.t - s.t_end_s) == 0.0 && fabs(s.t_end_s - 0.3) < 1e-3);
    assert_true(fabs(v.penetration - s.max_dynamic_penetration_m) == 0.0);
    assert_true(c.max_tension > 1e3 && c.max_tension <= s.max_cable_tension_n); /* loaded, under its peak */
    assert_true(e.t > 0.0 && e.t <= s.t_end_s);
    /* out of range: refused by name, saying which */
    assert_int_equal(cs_state_cable(run.model, run.state, 7, &c, &err), CS_ERR_INVALID);
    assert_string_equal(err.message, "cs_cable_view: no cable 7 (the model has 2)");
    assert_int_equal(cs_state_event(run.state, -1, &e, &err), CS_ERR_INVALID);
    assert_true(strstr(err.message, "cs_event: no event -1") == err.message);
}

/* cs_sudden_losses reads the caller's events at their own size, and refuses one it does not know. */
static void sudden_losses_read_events_at_their_size(void **state) {
    (void)state;
    double t[3] = {0.0, 0.005, 0.010}, f[3] = {1e5, 1e5, 1e4};
    cs_event e = {.size = sizeof e};
    assert_int_equal(cs_state_event(run.state, 0, &e, NULL), CS_OK);
    cs_sudden_loss w[1] = {{.size = sizeof w[0]}};
    cs_error err;
    e.t = 1.0; /* after the fall: it excuses nothing */
    assert_int_equal(cs_sudden_losses(t, f, 3, 0.005, &e, 1, w, 1, &err), 1);
    CHECK_ABS(w[0].force_before_n, 1e5, 0.0);
    CHECK_ABS(w[0].force_after_n, 1e4, 0.0);
    e.size = 0;
    assert_int_equal(cs_sudden_losses(t, f, 3, 0.005, &e, 1, w, 1, &err), -1);
    assert_true(strstr(err.message, "cs_event: size 0") == err.message);
    /* an array's events are read at the first one's size: one of another size is refused */
    cs_event two[2] = {e, e};
    two[0].size = sizeof two[0], two[1].size = sizeof two[1] - sizeof(double);
    assert_int_equal(cs_sudden_losses(t, f, 3, 0.005, two, 2, w, 1, &err), -1);
    assert_string_equal(err.message, "cs_event: an array's events must all have the first one's size");
}

/* The ledger, a cable's record and the sudden losses agree with the summary, whose arrays keep the first
 * layouts (cs_summary_cable, cs_summary_loss); a ledger of an earlier, smaller size gives no term past it. */
static void energy_cables_and_losses_agree_with_the_summary(void **state) {
    (void)state;
    cs_summary s = {.size = sizeof s};
    cs_energy e = {.size = sizeof e};
    cs_error err;
    assert_int_equal(cs_state_summary(run.state, &s, &err), CS_OK);
    assert_int_equal(cs_state_energy(run.state, &e, &err), CS_OK);
    assert_int_equal(e.size, sizeof e);
    CHECK_ABS(e.initial_kinetic, s.initial_kinetic_energy_j, 0.0);
    assert_true(fabs(e.balance_error) <= fabs(s.energy_balance_error));
    assert_true(cs_energy_term(&e, 0) == e.vehicle_kinetic && e.vehicle_kinetic > 0.0);
    assert_true(cs_energy_term(&e, CS_ENERGY_TERMS - 1) == e.released);
    cs_energy earlier = e;
    earlier.size = offsetof(cs_energy, released); /* an earlier ledger, without its last term */
    assert_true(cs_energy_term(&earlier, CS_ENERGY_TERMS - 1) == 0.0);
    assert_true(cs_energy_term(&earlier, CS_ENERGY_TERMS - 2) == e.friction);
    for (int c = 0; c < s.cable_count; c++) {
        cs_cable_summary cb = {.size = sizeof cb};
        assert_int_equal(cs_state_cable_summary(run.state, c, &cb, &err), CS_OK);
        assert_true(cb.peak_tension_n == s.cables[c].peak_tension_n && cb.peak_tension_n > 1e3);
        assert_true(cb.work_on_vehicle_j == s.cables[c].work_on_vehicle_j);
        assert_true(cb.energy_share == s.cables[c].energy_share);
    }
    cs_cable_summary cb = {.size = sizeof cb};
    assert_int_equal(cs_state_cable_summary(run.state, s.cable_count, &cb, &err), CS_ERR_INVALID);
    assert_string_equal(err.message, "cs_cable_summary: no cable 2 (the run has 2)");
    /* the summary's arrays have their first layout, which never changes */
    assert_int_equal(sizeof(cs_summary_cable), 4 * sizeof(double));
    assert_int_equal(sizeof(cs_summary_loss), 4 * sizeof(double));
    cs_sudden_loss w[CS_SUDDEN_LOSS_KEPT] = {{.size = sizeof w[0]}};
    int n = cs_state_sudden_losses(run.state, w, CS_SUDDEN_LOSS_KEPT, &err);
    assert_true(n >= 0 && n <= s.sudden_loss_count);
    for (int k = 0; k < n && k < CS_SUMMARY_SUDDEN_LOSSES; k++)
        assert_true(w[k].t_start_s == s.sudden_losses[k].t_start_s &&
                    w[k].force_after_n == s.sudden_losses[k].force_after_n);
    w[0].size = 0; /* refused even with nothing to give */
    assert_int_equal(cs_state_sudden_losses(run.state, w, CS_SUDDEN_LOSS_KEPT, &err), -1);
    assert_true(strstr(err.message, "cs_sudden_loss: size 0") == err.message);
}

/* An array of sudden losses of an earlier, smaller size is filled at the first one's size: each in its
 * place, with that size, and nothing past the last. */
static void sudden_losses_fill_an_array_at_its_first_size(void **state) {
    (void)state;
    double t[FALL_SAMPLES], f[FALL_SAMPLES];
    two_falls(t, f);
    cs_sudden_loss whole[2] = {{.size = sizeof whole[0]}};
    cs_error err;
    assert_int_equal(cs_sudden_losses(t, f, FALL_SAMPLES, 1e-3, NULL, 0, whole, 2, &err), 2);
    assert_int_equal(whole[1].size, sizeof whole[1]);
    CHECK_ABS(whole[0].force_before_n, 1e5, 0.0);
    CHECK_ABS(whole[1].force_after_n, 1e4, 0.0);
    assert_true(whole[1].t_start_s > whole[0].t_end_s);
    enum { SHORT = offsetof(cs_sudden_loss, force_after_n) };
    _Alignas(max_align_t) unsigned char b[3 * SHORT];
    memset(b, MARK, sizeof b);
    size_t n = SHORT;
    memcpy(b, &n, sizeof n);
    assert_int_equal(
        cs_sudden_losses(t, f, FALL_SAMPLES, 1e-3, NULL, 0, (cs_sudden_loss *)(void *)b, 2, &err), 2);
    for (int k = 0; k < 2; k++) {
        assert_int_equal(size_of(b + k * SHORT), SHORT);
        assert_memory_equal(b + k * SHORT + sizeof(size_t), (const char *)&whole[k] + sizeof(size_t),
                            SHORT - sizeof(size_t));
    }
    for (size_t k = 2 * SHORT; k < sizeof b; k++) /* nothing past the second */
        assert_int_equal(b[k], MARK);
    n = sizeof(cs_sudden_loss) + 8; /* a later cablesim's */
    memcpy(b, &n, sizeof n);
    assert_int_equal(
        cs_sudden_losses(t, f, FALL_SAMPLES, 1e-3, NULL, 0, (cs_sudden_loss *)(void *)b, 2, &err), -1);
    assert_true(strstr(err.message, "cs_sudden_loss: size ") == err.message);
    assert_non_null(strstr(err.message, "a program built for a later cablesim"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(earlier_structs_run_as_todays_with_defaults),
        cmocka_unit_test(earlier_nested_structs_run_as_todays_with_defaults),
        cmocka_unit_test(unknown_sizes_are_refused),
    };
    const struct CMUnitTest filled_tests[] = {
        cmocka_unit_test_prestate(filled_to_the_callers_size, (void *)&summary_case),
        cmocka_unit_test_prestate(filled_to_the_callers_size, (void *)&vehicle_case),
        cmocka_unit_test_prestate(filled_to_the_callers_size, (void *)&cable_case),
        cmocka_unit_test_prestate(filled_to_the_callers_size, (void *)&post_case),
        cmocka_unit_test_prestate(filled_to_the_callers_size, (void *)&anchor_case),
        cmocka_unit_test_prestate(filled_to_the_callers_size, (void *)&event_case),
        cmocka_unit_test_prestate(filled_to_the_callers_size, (void *)&energy_case),
        cmocka_unit_test_prestate(filled_to_the_callers_size, (void *)&cable_summary_case),
        cmocka_unit_test_prestate(filled_to_the_callers_size, (void *)&sudden_loss_case),
        cmocka_unit_test(energy_cables_and_losses_agree_with_the_summary),
        cmocka_unit_test(sudden_losses_fill_an_array_at_its_first_size),
        cmocka_unit_test(views_agree_with_the_summary),
        cmocka_unit_test(sudden_losses_read_events_at_their_size),
    };
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    return failed + cmocka_run_group_tests_name("filled", filled_tests, run_setup, run_teardown);
}
