/* SPDX-License-Identifier: MIT */
/* report.html's writer (src/io/out/report_html.c) on a short real run: the markers of a page are filled,
 * the title is HTML-escaped and the data (a command line with "</script>" in it included) cannot close its
 * <script>, the data has every part the page reads (provenance and designations as run too; a run cut at its
 * time limit has no penetration, only how far it got), the design as loaded (ropes, kinds of post, their
 * places, soil, anchors) carries the model's values, a page without its data marker is refused, and a long
 * record is subsampled to the budget. The page itself is tested in a browser (report/test/browser.mjs). */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "cablesim/loader.h"
#include "out/record.h"
#include "out/report_html.h"

typedef struct run {
    cs_loader *loader;
    cs_model_input in;
    cs_model *model;
    cs_state *state;
    cs_record rec;
} run;

static int setup(void **st) {
    run *r = calloc(1, sizeof *r);
    assert_non_null(r);
    r->loader = cs_loader_create(NULL, NULL);
    assert_non_null(r->loader);
    cs_loader_set(r->loader, "scenario.t_end=40 ms");
    r->in.size = sizeof r->in;
    if (cs_loader_load(r->loader, "examples/aps3.yaml", &r->in) != 0) {
        cs_loader_print_errors(r->loader, stderr);
        fail();
    }
    r->model = cs_loader_build(r->loader, &r->in);
    assert_non_null(r->model);
    cs_error err = {0};
    r->state = cs_state_create(r->model, &err);
    assert_non_null(r->state);
    assert_int_equal(cs_record_init(&r->rec, r->model), 0);
    assert_int_equal(cs_run(r->model, r->state, cs_record_frame, &r->rec, &err), CS_OK);
    assert_false(r->rec.failed);
    *st = r;
    return 0;
}

static int teardown(void **st) {
    run *r = *st;
    cs_record_release(&r->rec);
    cs_state_free(r->state);
    cs_model_free(r->model);
    cs_loader_free(r->loader);
    free(r);
    return 0;
}

/* The page written from template into a malloc'ed string; err the writer's. */
static char *page(run *r, const cs_record *rec, const char *template, cs_error *err) {
    static const char *const overrides[] = {"--set scenario.t_end=40 ms"};
    cs_run_info info = {.command = "cablesim run 'x</script>.yaml'",
                        .overrides = overrides,
                        .override_count = 1,
                        .model_hash = 0x0123456789abcdefULL};
    char *buf = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&buf, &size);
    assert_non_null(f);
    if (cs_write_report_html(f, (const unsigned char *)template, strlen(template), &r->in, r->state, rec,
                             &info, err) == CS_OK)
        *err = (cs_error){CS_OK, ""};
    fclose(f);
    char *out = strdup(buf); /* a copy: gcc -O3 otherwise takes buf for a pointer into this frame */
    free(buf);
    assert_non_null(out);
    return out;
}

static size_t count(const char *s, const char *what) {
    size_t n = 0;
    for (const char *p = strstr(s, what); p; p = strstr(p + 1, what))
        n++;
    return n;
}

/* Elements of the JSON array that follows "key": (numbers or nested arrays), counted at its own level. */
static int array_length(const char *json, const char *key) {
    const char *p = strstr(json, key);
    assert_non_null(p);
    p = strchr(p, '[');
    assert_non_null(p);
    int depth = 0, n = 0;
    for (; *p; p++) {
        if (*p == '[' && ++depth == 1 && p[1] != ']') n = 1;
        if (*p == ']' && --depth == 0) return n;
        if (*p == ',' && depth == 1) n++;
    }
    fail_msg("%s: unterminated array", key);
    return -1;
}

static void markers_filled(void **st) {
    run *r = *st;
    const char *name = r->in.name;
    r->in.name = "a<b>&\"c</script>";
    cs_error err;
    char *html =
        page(r, &r->rec, "<title>@CS_TITLE@</title><h1>@CS_TITLE@</h1><script>@CS_DATA@</script>!", &err);
    r->in.name = name;
    if (err.status != CS_OK) fail_msg("%s", err.message);
    assert_int_equal(count(html, "<title>a&lt;b&gt;&amp;&quot;c&lt;/script&gt;</title>"), 1);
    assert_int_equal(count(html, "<h1>a&lt;b&gt;&amp;&quot;c&lt;/script&gt;</h1>"), 1);
    assert_int_equal(count(html, "@CS_"), 0);
    /* the data holds the name escaped and nothing that ends its script early */
    assert_int_equal(count(html, "</script>"), 1);
    assert_int_equal(count(html, "<!--"), 0);
    assert_non_null(strstr(html, "\"name\":\"a\\u003cb\\u003e\\u0026\\\"c\\u003c/script\\u003e\""));
    assert_non_null(strstr(html, "</script>!"));
    assert_null(strstr(html, "nan"));
    assert_null(strstr(html, "inf"));
    free(html);
}

static void data_complete(void **st) {
    run *r = *st;
    cs_error err;
    char *json = page(r, &r->rec, "@CS_DATA@", &err);
    if (err.status != CS_OK) fail_msg("%s", err.message);
    assert_true(json[0] == '{' && json[strlen(json) - 1] == '}');
    static const char *const keys[] = {"\"cablesim\":{\"version\":\"" CS_VERSION_STRING "\"",
                                       "\"overrides\":[\"--set scenario.t_end=40 ms\"]",
                                       "\"model_hash\":\"0123456789abcdef\"",
                                       "\"designations_as_run\":[]",
                                       "\"summary\":",
                                       "\"outcome\":",
                                       "\"max_50ms_decel_g\":",
                                       "\"max_dynamic_penetration_m\":null",
                                       "\"penetration_beyond_m\":0.",
                                       "\"exit_speed_mps\":",
                                       "\"posts_failed_left\":",
                                       "\"energy_balance_error\":",
                                       "\"scenario\":",
                                       "\"vehicle\":",
                                       "\"barrier\":",
                                       "\"events\":",
                                       "\"series\":",
                                       "\"decel50\":",
                                       "\"tension\":",
                                       "\"near_posts\":",
                                       "\"post_tilt\":",
                                       "\"energy\":",
                                       "\"vehicle_kinetic\":",
                                       "\"frames\":",
                                       "\"units\":\n{\"format\":\"\",\"evaluation\":"};
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
        if (!strstr(json, keys[k])) fail_msg("no %s in the data", keys[k]);
    /* every recorded frame of a short run is kept, for the plots and the replay */
    assert_int_equal(array_length(json, "\"t\":"), r->rec.frame_count);
    assert_int_equal(array_length(json, "\"frames\":"), r->rec.frame_count);
    assert_int_equal(array_length(json, "\"tension\":"), r->rec.cable_count);
    assert_int_equal(array_length(json, "\"posts\":"), r->rec.post_count);
    assert_int_equal(array_length(json, "\"events\":"), cs_state_event_count(r->state));
    free(json);
}

/* A key's value as the data writes a number (%.6g). */
static void has_number(const char *json, const char *key, double v) {
    char want[96];
    snprintf(want, sizeof want, "\"%s\":%.6g", key, v);
    if (!strstr(json, want)) fail_msg("no %s in the design", want);
}

/* Each rope end's fitting as the engine takes it: swaged (0.95) at cable 0's end anchor, cable 1's start at
 * its own 0.7 of the cable's clips, the other two ends the cable's clips (0.90 on 1.75-in rope); cable 1's
 * end slips at 100 kN and runs out after 0.45 m, the rest do not slip. */
static void design_has_each_end(void **st) {
    run *r = *st;
    cs_cable_def cables[2] = {r->in.barrier.cables[0], r->in.barrier.cables[1]};
    const cs_cable_def *loaded = r->in.barrier.cables;
    cables[0].ends[1].termination = CS_TERMINATION_SWAGED;
    cables[1].ends[0].termination_efficiency = 0.7;
    cables[1].ends[1].slip_load = 1e5, cables[1].ends[1].slip_travel = 0.45;
    r->in.barrier.cables = cables;
    cs_error err;
    char *json = page(r, &r->rec, "@CS_DATA@", &err);
    r->in.barrier.cables = loaded;
    if (err.status != CS_OK) fail_msg("%s", err.message);
    assert_non_null(
        strstr(json, "\"pretension_n\":22241.1,\"ends\":[{\"termination\":\"clips\",\"termination_"
                     "efficiency\":0.9},{\"termination\":\"swaged\",\"termination_efficiency\":0.95}]}"));
    assert_non_null(strstr(json,
                           "\"pretension_n\":22241.1,\"ends\":[{\"termination\":\"clips\",\"termination_"
                           "efficiency\":0.7},{\"termination\":\"clips\",\"termination_efficiency\":0.9,"
                           "\"slip_load_n\":100000,\"slip_travel_m\":0.45}]}"));
    free(json);
}

/* The design table's data: every rope's size and pretension, the two kinds of APS3's posts (line and
 * intermediate anchor posts) with the posts of each, the posts' places, the soil and the anchors, each the
 * model's own value in SI. */
static void design_as_loaded(void **st) {
    run *r = *st;
    cs_error err;
    char *json = page(r, &r->rec, "@CS_DATA@", &err);
    if (err.status != CS_OK) fail_msg("%s", err.message);
    char *units = strstr(json, ",\"units\":\n{");
    assert_non_null(units);
    *units = '\0'; /* the design's keys, not those of their units (the data's last member) */
    const char *d = strstr(json, "\"design\":{\"ropes\":[");
    assert_non_null(d);
    const cs_barrier_def *b = &r->in.barrier;
    assert_int_equal(count(d, "\"pretension_n\":"), b->cable_count);
    for (int c = 0; c < b->cable_count; c++) {
        has_number(d, "pretension_n", b->cables[c].pretension);
        has_number(d, "diameter_m", b->cables[c].rope.diameter);
        has_number(d, "strength_n", b->cables[c].rope.nominal_strength);
    }
    has_number(d, "pretension_n", 5 * 4448.2216152605); /* 5 kip, as examples/aps3.yaml gives it */
    /* clips at both ends of APS3's 1.75-in ropes: 0.90 Fu */
    assert_int_equal(count(d, "\"ends\":[{\"termination\":\"clips\",\"termination_efficiency\":0.9},"
                              "{\"termination\":\"clips\",\"termination_efficiency\":0.9}]"),
                     b->cable_count);
    assert_int_equal(count(d, "{\"posts\":["), 2);
    assert_non_null(strstr(d, "{\"posts\":[0,1,2,3,4,5,7,8,10,11,12,13,14,15],\"height_m\":"));
    assert_non_null(strstr(d, "{\"posts\":[6,9],\"height_m\":"));
    has_number(d, "yield_stress_pa", b->posts[0].section.yield_stress);
    has_number(d, "yield_stress_pa", b->posts[6].section.yield_stress);
    assert_true(b->posts[0].section.yield_stress != b->posts[6].section.yield_stress);
    /* each kind's plastic moment as the engine takes it (APS3's HSS is hollow: no fill named) */
    has_number(d, "plastic_moment_nm", cs_section_plastic_moment(&b->posts[0].section));
    has_number(d, "plastic_moment_nm", cs_section_plastic_moment(&b->posts[6].section));
    assert_null(strstr(d, "fill_strength_pa"));
    assert_int_equal(array_length(d, "\"post_x_m\":"), b->post_count);
    has_number(d, "soil_pressure_pa", b->posts[0].footing.soil_pressure);
    has_number(d, "soil_pressure_pa", 8000 * 47.88025898033584); /* 8000 psf */
    assert_int_equal(count(d, "\"x_m\":"), 2);
    has_number(d, "x_m", b->end_anchor.x);
    assert_non_null(strstr(
        d, "\"pullout_capacity_n\":null,\"pullout_capacity_n_rule\":\"its weight and skin friction\""));
    free(json);
}

static void page_without_data_marker(void **st) {
    run *r = *st;
    cs_error err;
    char *html = page(r, &r->rec, "<title>@CS_TITLE@</title>", &err);
    assert_int_not_equal(err.status, CS_OK);
    assert_non_null(strstr(err.message, "@CS_DATA@"));
    free(html);
}

/* A record of many frames (the short run's frames repeated, time running on) is subsampled: the plots'
 * series to CS_REPORT_SERIES_MAX frames, the replay to its budget; the first and last frames stay. */
static void long_record_subsampled(void **st) {
    run *r = *st;
    const cs_record *s = &r->rec;
    enum { N = 9001 };
    cs_record big = *s;
    size_t nc = (size_t)s->cable_count, np = (size_t)s->post_count, nn = (size_t)s->max_nodes;
    big.frame_count = big.capacity = N;
    big.vehicle = malloc(N * sizeof *big.vehicle);
    big.energy = malloc(N * sizeof *big.energy);
    big.cables = malloc(N * nc * sizeof *big.cables);
    big.posts = malloc(N * np * sizeof *big.posts);
    big.anchors = malloc(N * 2 * sizeof *big.anchors);
    big.path_count = malloc(N * nc * sizeof *big.path_count);
    big.path_xyz = malloc(N * nc * nn * 3 * sizeof *big.path_xyz);
    big.path_tension = malloc(N * nc * nn * sizeof *big.path_tension);
    assert_true(big.vehicle && big.energy && big.cables && big.posts && big.anchors && big.path_count &&
                big.path_xyz && big.path_tension);
    for (size_t i = 0; i < N; i++) {
        size_t j = i % (size_t)s->frame_count;
        big.vehicle[i] = s->vehicle[j];
        big.vehicle[i].t = 1e-3 * (double)i;
        big.energy[i] = s->energy[j];
        memcpy(big.cables + i * nc, s->cables + j * nc, nc * sizeof *big.cables);
        memcpy(big.posts + i * np, s->posts + j * np, np * sizeof *big.posts);
        memcpy(big.anchors + i * 2, s->anchors + j * 2, 2 * sizeof *big.anchors);
        memcpy(big.path_count + i * nc, s->path_count + j * nc, nc * sizeof *big.path_count);
        memcpy(big.path_xyz + i * nc * nn * 3, s->path_xyz + j * nc * nn * 3,
               nc * nn * 3 * sizeof *big.path_xyz);
        memcpy(big.path_tension + i * nc * nn, s->path_tension + j * nc * nn,
               nc * nn * sizeof *big.path_tension);
    }
    cs_error err;
    char *json = page(r, &big, "@CS_DATA@", &err);
    if (err.status != CS_OK) fail_msg("%s", err.message);
    int series = array_length(json, "\"t\":"), frames = array_length(json, "\"frames\":");
    assert_in_range(series, CS_REPORT_SERIES_MAX / 2, CS_REPORT_SERIES_MAX + 1);
    assert_in_range(frames, CS_REPORT_REPLAY_MIN, CS_REPORT_REPLAY_MAX + 1);
    assert_true(strlen(json) < 8000000);
    /* the last frame's time closes both */
    assert_non_null(strstr(json, ",9]"));
    assert_non_null(strstr(json, "\n[9,["));
    free(json);
    cs_record_release(&big);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(markers_filled),         cmocka_unit_test(data_complete),
        cmocka_unit_test(design_as_loaded),       cmocka_unit_test(page_without_data_marker),
        cmocka_unit_test(long_record_subsampled), cmocka_unit_test(design_has_each_end),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
