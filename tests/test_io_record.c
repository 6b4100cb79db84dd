/* SPDX-License-Identifier: MIT */
/* A run's record stays within its size: when full it keeps every other frame and records every other
 * output from then on, and it always ends with the run's last state. A truck on the open road for 0.5 s,
 * an output every 0.5-ms step (outputs 0 to 1000), into a record of at most 100 frames: full at outputs
 * 100, 200, 400 and 800, it ends recording every 16th and holds the outputs 0, 16, ..., 992 (8 ms
 * apart) and the run's last, 1000. The public way (cablesim/output.h) reads the same frames, refuses what
 * is out of range, and writes the run's files into a folder, all or none. The record of the files alone
 * (cablesim run without plots or report) writes the same timeseries.csv. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cablesim/cablesim.h"
#include "check.h"
#include "fixture.h"
#include "out/record.h"
#include "out/writers.h"

static void record_thins_and_keeps_the_end(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.start_gap = 1000.0; /* the barrier is far: nothing happens, the run goes to its end */
    fx.scenario.stop_speed = 0.0;
    fx.scenario.t_end = 0.5;
    fx.scenario.output_interval = 0.0; /* every step */
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    cs_record rec;
    assert_int_equal(cs_record_init(&rec, m), 0);
    rec.max_frames = 100;
    assert_int_equal(cs_run(m, s, cs_record_frame, &rec, &err), CS_OK);
    assert_int_equal(rec.failed, 0);
    assert_int_equal(rec.stride, 16);
    assert_int_equal(rec.frame_count, 64);
    assert_true(rec.capacity <= rec.max_frames);
    for (int f = 0; f + 1 < rec.frame_count; f++)
        CHECK_ABS(rec.vehicle[f].t, 16 * f * fx.scenario.dt, 1e-9);
    CHECK_ABS(rec.vehicle[rec.frame_count - 1].t, 0.5, 1e-9);
    cs_record_release(&rec);
    cs_state_free(s);
    cs_model_free(m);
}

static int exists(const char *dir, const char *name) {
    char path[1024];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return stat(path, &st) == 0 && st.st_size > 0;
}

static void public_record_and_outputs(void **state) {
    (void)state;
    cs_error err;
    cs_loader *l = cs_loader_create(CS_SOURCE_DIR "/data", &err);
    if (!l) fail_msg("%s", err.message);
    assert_int_equal(cs_loader_set(l, "scenario.t_end=60 ms"), 0);
    cs_model_input in = {.size = sizeof in};
    cs_model *m = NULL;
    if (cs_loader_load(l, CS_SOURCE_DIR "/examples/aps3.yaml", &in) != 0 || !(m = cs_loader_build(l, &in))) {
        cs_loader_print_errors(l, stderr);
        fail_msg("examples/aps3.yaml did not load");
    }
    cs_state *s = cs_state_create(m, &err);
    cs_record *rec = cs_record_create(m, &err);
    assert_non_null(s), assert_non_null(rec);
    assert_int_equal(cs_run(m, s, cs_record_frame, rec, &err), CS_OK);
    assert_true(cs_record_ok(rec));
    int n = cs_record_frame_count(rec);
    assert_int_equal(n, 61); /* t = 0, every 1 ms to 60 ms */
    cs_vehicle_view now = {.size = sizeof now};
    cs_state_vehicle(m, s, &now, NULL);
    const cs_vehicle_view *last = cs_record_vehicle(rec, n - 1);
    assert_non_null(last);
    CHECK_ABS(last->t, 0.06, 1e-9);
    assert_memory_equal(last, &now, sizeof now); /* the last frame is the state at the end */
    CHECK_ABS(cs_record_vehicle(rec, 0)->t, 0.0, 0.0);
    assert_null(cs_record_vehicle(rec, n)), assert_null(cs_record_vehicle(rec, -1));
    assert_non_null(cs_record_energy(rec, 0));
    assert_non_null(cs_record_cable(rec, 0, 1)), assert_null(cs_record_cable(rec, 0, 2));
    assert_non_null(cs_record_post(rec, n - 1, cs_model_post_count(m) - 1));
    assert_null(cs_record_post(rec, 0, cs_model_post_count(m)));
    assert_non_null(cs_record_anchor(rec, 0, 1)), assert_null(cs_record_anchor(rec, 0, 2));
    const double *xyz, *tension;
    int points = cs_record_cable_path(rec, 0, 0, &xyz, &tension);
    assert_int_equal(points, cs_record_cable(rec, 0, 0)->node_count);
    assert_true(points >= 2);
    CHECK_ABS(xyz[0], in.barrier.start_anchor.x, 0.01); /* at t = 0 a path starts at the start anchor (the
                                                          pretension pulls it in a few mm) */
    CHECK_ABS(xyz[3 * (points - 1)], in.barrier.end_anchor.x, 0.01); /* and ends at the end anchor */
    assert_int_equal(cs_record_cable_path(rec, n, 0, &xyz, &tension), -1);

    char dir[] = "/tmp/cs-outputs-XXXXXX";
    assert_non_null(mkdtemp(dir));
    char out[64];
    snprintf(out, sizeof out, "%s/run", dir);
    assert_int_equal(cs_write_outputs(out, &in, m, s, rec, 0, &err), CS_OK);
    assert_true(exists(out, "timeseries.csv") && exists(out, "events.csv") && exists(out, "summary.json"));
    assert_false(exists(out, "plots"));
    char blocked[sizeof out + 20];
    snprintf(blocked, sizeof blocked, "%s/summary.json/run", out); /* a folder under a file: refused */
    assert_int_equal(cs_write_outputs(blocked, &in, m, s, rec, 0, &err), CS_ERR_IO);
    assert_int_equal(err.status, CS_ERR_IO);
    assert_true(strlen(err.message) > 0);
    /* a folder of the user's is refused naming what the interface allows: another folder, the file moved
     * (it takes no --force) */
    char user[sizeof out + 20], notes[sizeof user + 20];
    snprintf(user, sizeof user, "%s/user", dir);
    snprintf(notes, sizeof notes, "%s/notes.txt", user);
    assert_int_equal(mkdir(user, 0777), 0);
    FILE *f = fopen(notes, "w");
    assert_non_null(f);
    fputs("my notes\n", f);
    assert_int_equal(fclose(f), 0);
    assert_int_equal(cs_write_outputs(user, &in, m, s, rec, 0, &err), CS_ERR_IO);
    assert_non_null(strstr(err.message, "holds notes.txt, which no cablesim run wrote there"));
    assert_non_null(strstr(err.message, "choose another folder, or move such files out of it"));
    assert_null(strstr(err.message, "--force"));
    assert_true(exists(user, "notes.txt") && !exists(user, "summary.json"));
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    assert_int_equal(system(cmd), 0);
    cs_record_free(rec);
    cs_state_free(s);
    cs_model_free(m);
    cs_loader_free(l);
}

/* Both records of one run, fed each output. */
static void record_both(const cs_model *m, const cs_state *s, void *user) {
    cs_record *recs = user;
    cs_record_frame(m, s, &recs[0]);
    cs_record_frame(m, s, &recs[1]);
}

/* timeseries.csv as text from a record. */
static char *timeseries_text(const cs_record *rec) {
    char *text = NULL;
    cs_error err;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    assert_non_null(f);
    assert_int_equal(cs_timeseries_csv(f, rec, &err), CS_OK);
    fclose(f);
    return text;
}

/* The record of the files alone (no plots, no report.html: cablesim run's) writes the same
 * timeseries.csv as the whole record, to the byte, and holds neither paths nor posts' views. */
static void files_record_writes_the_same_timeseries(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.t_end = 0.08;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    cs_record recs[2];
    assert_int_equal(cs_record_init(&recs[0], m), 0);
    assert_int_equal(cs_record_init_for(&recs[1], m, CS_RECORD_FILES), 0);
    assert_int_equal(cs_run(m, s, record_both, recs, &err), CS_OK);
    assert_int_equal(recs[0].failed, 0), assert_int_equal(recs[1].failed, 0);
    assert_int_equal(recs[1].frame_count, recs[0].frame_count);
    assert_true(recs[1].capacity >= recs[1].frame_count && recs[1].capacity <= recs[1].max_frames);
    assert_null(cs_record_post(&recs[1], 0, 0)), assert_non_null(cs_record_post(&recs[0], 0, 0));
    const double *xyz = NULL;
    assert_int_equal(cs_record_cable_path(&recs[1], 0, 0, &xyz, NULL), 0);
    assert_null(xyz);
    char *all = timeseries_text(&recs[0]), *files = timeseries_text(&recs[1]);
    assert_string_equal(files, all);
    free(all), free(files);
    cs_record_release(&recs[0]), cs_record_release(&recs[1]);
    cs_state_free(s);
    cs_model_free(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(record_thins_and_keeps_the_end),
                                       cmocka_unit_test(files_record_writes_the_same_timeseries),
                                       cmocka_unit_test(public_record_and_outputs)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
