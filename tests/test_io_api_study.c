/* SPDX-License-Identifier: MIT */
/* A sweep and a comparison through the public interface alone (cablesim/sweep.h, cablesim/compare.h), each
 * against the command's own outputs for the same study and runs:
 * - a Latin hypercube of 3 runs of examples/aps3-uncertain.yaml cut to 60 ms: the runs.csv it writes is the
 *   command's byte for byte, and the numbers the handle gives (each run's inputs, outcome, largest 50-ms
 *   deceleration, penetration, cable tension, the designations as run and the ASTM F2656 penetration)
 *   are the ones of the command's runs.csv;
 * - two runs of examples/aps3.yaml cut to 60 ms, 40 and 35 mph, written by `cablesim run`: the compare.csv
 *   the interface writes is the command's byte for byte, and its values and differences are the ones of
 *   that file (and each run's 50-ms deceleration its summary.json's);
 * - the same study checked without running (cs_sweep_check_study), from a def of the size before it had
 *   ranks: its runs' inputs are the study's, each run pending;
 * - a def, a row or ranks of a size the library does not know, or ranks that cannot share a study, are
 *   refused by name, and an earlier, smaller row or run info is filled to its size;
 * - a folder of the user's is refused naming the interface's way to write beside its files. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "cablesim/cablesim.h"

#define CS CS_BINARY_DIR "/cablesim"

static char tmp[256];

static int setup(void **state) {
    (void)state;
    snprintf(tmp, sizeof tmp, "/tmp/cs-api-study-XXXXXX");
    return mkdtemp(tmp) ? 0 : -1;
}

static int teardown(void **state) {
    (void)state;
    char cmd[400];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    return system(cmd) == 0 ? 0 : -1;
}

static void sh(const char *fmt, ...) {
    char cmd[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(cmd, sizeof cmd, fmt, ap);
    va_end(ap);
    if (system(cmd) != 0) fail_msg("failed: %s", cmd);
}

/* The whole of a file, NUL-terminated (freed by the caller). */
static char *slurp(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) fail_msg("%s: cannot be read", path);
    char *buf = calloc(1, 1 << 20);
    assert_non_null(buf);
    size_t n = fread(buf, 1, (1 << 20) - 1, f);
    fclose(f);
    buf[n] = '\0';
    return buf;
}

static void same_file(const char *a, const char *b) {
    char *x = slurp(a), *y = slurp(b);
    if (strcmp(x, y) != 0) fail_msg("%s and %s differ:\n%s\n---\n%s", a, b, x, y);
    free(x), free(y);
}

/* A CSV file of plain cells (no quotes in the cells read): rows[r][c] (row 0 the header). */
enum { ROWS = 32, COLS = 64, CELL = 160 };
typedef struct table {
    int rows, cols;
    char cell[ROWS][COLS][CELL];
} table;

static table *read_csv(const char *path) {
    table *t = calloc(1, sizeof *t);
    assert_non_null(t);
    char *text = slurp(path), *line = text;
    while (*line && t->rows < ROWS) {
        size_t len = strcspn(line, "\n");
        const char *p = line, *end = line + len;
        int c = 0;
        for (;;) { /* a cell, then a comma or the end */
            size_t k = 0;
            int quoted = p < end && *p == '"';
            p += quoted;
            while (p < end && (quoted ? *p != '"' : *p != ',')) {
                if (k + 1 < CELL && c < COLS) t->cell[t->rows][c][k] = *p, k++;
                p++;
            }
            p += quoted && p < end; /* the closing quote */
            c++;
            if (p >= end) break;
            p++; /* the comma */
        }
        if (c > t->cols) t->cols = c;
        t->rows++;
        line += len + (line[len] == '\n');
    }
    free(text);
    return t;
}

/* The column whose header is name (exactly), or fail. */
static int column(const table *t, const char *name) {
    for (int c = 0; c < t->cols; c++)
        if (strcmp(t->cell[0][c], name) == 0) return c;
    fail_msg("no column '%s'", name);
    return -1;
}

/* The table's number at row r, column c: NAN for an empty cell. */
static double number(const table *t, int r, int c) {
    const char *s = t->cell[r][c];
    return *s ? strtod(s, NULL) : NAN;
}

/* x as written with %.10g (runs.csv, compare.csv) is the cell's value. */
static void same_number(double x, double cell, const char *what) {
    if (isnan(x) && isnan(cell)) return;
    char a[64], b[64];
    snprintf(a, sizeof a, "%.10g", x);
    snprintf(b, sizeof b, "%.10g", cell);
    if (strcmp(a, b) != 0 && !(fabs(x - cell) <= 1e-9 * fabs(cell)))
        fail_msg("%s: the interface's %s, the command's %s", what, a, b);
}

static void sweep_is_the_commands(void **state) {
    (void)state;
    char api[300], cmd[300];
    snprintf(api, sizeof api, "%s/sweep-api", tmp);
    snprintf(cmd, sizeof cmd, "%s/sweep-cmd", tmp);
    static const char *const sets[] = {"scenario.t_end=60 ms"};
    cs_sweep_def def = cs_default_sweep_def();
    def.spec = CS_SOURCE_DIR "/examples/aps3-uncertain.yaml";
    def.out_dir = api;
    def.runs = 3;
    def.sets = sets;
    def.set_count = 1;
    def.threads = 1;
    cs_sweep *s = NULL;
    cs_error err;
    if (cs_sweep_study(&def, &s, &err) != CS_OK) fail_msg("%s", err.message);
    assert_non_null(s);
    assert_string_equal(cs_sweep_dir(s), api);
    assert_int_equal(cs_sweep_run_count(s), 3);
    assert_int_equal(cs_sweep_ran(s), 3);
    assert_int_equal(cs_sweep_stopped_by(s), 0);
    sh(CS " sweep " CS_SOURCE_DIR "/examples/aps3-uncertain.yaml --runs 3 --t-end '60 ms' -o '%s' --quiet",
       cmd);
    char a[400], b[400];
    snprintf(a, sizeof a, "%s/runs.csv", api);
    snprintf(b, sizeof b, "%s/runs.csv", cmd);
    same_file(a, b);

    table *t = read_csv(b);
    assert_int_equal(t->rows, 4);
    int vars = cs_sweep_var_count(s);
    assert_int_equal(vars, 4);
    for (long run = 0; run < 3; run++) {
        int r = (int)run + 1;
        assert_int_equal((int)number(t, r, column(t, "run")), run);
        for (int v = 0; v < vars; v++) {
            char head[200];
            const char *unit = cs_sweep_var_unit(s, v);
            snprintf(head, sizeof head, "%s%s%s%s", cs_sweep_var_path(s, v), *unit ? " [" : "", unit,
                     *unit ? "]" : "");
            same_number(cs_sweep_input(s, run, v), number(t, r, column(t, head)), head);
        }
        cs_sweep_run_info info = {.size = sizeof info};
        assert_int_equal(cs_sweep_run_of(s, run, &info, &err), CS_OK);
        assert_int_equal(info.status, CS_SWEEP_RUN_OK);
        assert_string_equal(info.rating, t->cell[r][column(t, "astm_f2656_as_run")]);
        same_number(info.astm_penetration, number(t, r, column(t, "astm_f2656_penetration [m]")),
                    "ASTM F2656 penetration");
        assert_string_equal(info.sd_std_rating, t->cell[r][column(t, "sd_std_02_01_as_run")]);
        cs_summary sm = {.size = sizeof sm};
        assert_int_equal(cs_sweep_run_summary(s, run, &sm, &err), CS_OK);
        assert_string_equal(cs_outcome_name(sm.outcome), t->cell[r][column(t, "outcome")]);
        assert_true(sm.outcome == CS_TIME_LIMIT && fabs(sm.t_end_s - 0.06) < 1e-9);
        assert_true(sm.max_50ms_decel_g > 0.5 && sm.max_cable_tension_n > 1e4); /* a real run */
        same_number(sm.t_end_s, number(t, r, column(t, "time_reached [s]")), "time reached");
        same_number(sm.max_50ms_decel_g, number(t, r, column(t, "max_50ms_decel [g]")), "50-ms deceleration");
        same_number(sm.max_cable_tension_n, number(t, r, column(t, "max_cable_tension [N]")), "tension");
        same_number(sm.initial_kinetic_energy_j, number(t, r, column(t, "initial_kinetic_energy [J]")),
                    "kinetic energy");
    }
    /* the study checked, not run: the same runs' inputs, each run pending, nothing written */
    cs_sweep *c = NULL;
    cs_sweep_def check = def;
    check.out_dir = NULL;
    /* as a program built before cs_sweep_def had ranks passes it: the ranks past its size are not read */
    cs_sweep_ranks_def unread = cs_default_sweep_ranks();
    unread.ranks = 2; /* refused, if it were read */
    check.ranks = &unread;
    check.size = offsetof(cs_sweep_def, ranks);
    if (cs_sweep_check_study(&check, &c, &err) != CS_OK) fail_msg("%s", err.message);
    assert_int_equal(cs_sweep_run_count(c), 3);
    assert_int_equal(cs_sweep_method_of(c), CS_SWEEP_LATIN_HYPERCUBE);
    assert_string_equal(cs_sweep_spec_file(c), def.spec);
    assert_string_equal(cs_sweep_model(c), CS_SOURCE_DIR "/examples/aps3.yaml");
    assert_string_equal(cs_sweep_dir(c), "");
    for (long run = 0; run < 3; run++) {
        for (int v = 0; v < vars; v++)
            assert_true(cs_sweep_input(c, run, v) == cs_sweep_input(s, run, v));
        cs_sweep_run_info info = {.size = sizeof info};
        assert_int_equal(cs_sweep_run_of(c, run, &info, &err), CS_OK);
        assert_int_equal(info.status, CS_SWEEP_RUN_PENDING);
    }
    cs_sweep_free(c);
    assert_int_equal(cs_sweep_is_spec(def.spec), 1);
    assert_int_equal(cs_sweep_is_spec(CS_SOURCE_DIR "/examples/aps3.yaml"), 0);
    assert_int_equal(cs_sweep_is_spec(CS_SOURCE_DIR "/no/such/file.yaml"), 0);
    /* the runs differ: their inputs are sampled */
    assert_true(cs_sweep_input(s, 0, 0) != cs_sweep_input(s, 1, 0));
    /* out of range, and sizes it does not know */
    cs_summary sm = {.size = sizeof sm};
    assert_int_equal(cs_sweep_run_summary(s, 3, &sm, &err), CS_ERR_INVALID);
    assert_string_equal(err.message, "cs_summary: no run 3 (the study has 3)");
    cs_sweep_run_info info = {.size = sizeof info + 8};
    assert_int_equal(cs_sweep_run_of(s, 0, &info, &err), CS_ERR_INVALID);
    assert_true(strstr(err.message, "cs_sweep_run_info: size ") == err.message);
    /* a run's info as a program built before it had the ASTM penetration passes it: filled to its size */
    _Alignas(max_align_t) unsigned char earlier[sizeof(cs_sweep_run_info)];
    memset(earlier, 0x5a, sizeof earlier);
    size_t before = offsetof(cs_sweep_run_info, astm_penetration);
    memcpy(earlier, &before, sizeof before);
    assert_int_equal(cs_sweep_run_of(s, 0, (cs_sweep_run_info *)(void *)earlier, &err), CS_OK);
    assert_string_equal(((cs_sweep_run_info *)(void *)earlier)->rating,
                        t->cell[1][column(t, "astm_f2656_as_run")]);
    for (size_t k = before; k < sizeof earlier; k++)
        assert_int_equal(earlier[k], 0x5a);
    assert_true(isnan(cs_sweep_input(s, 0, vars)) && !cs_sweep_var_path(s, vars));
    free(t);
    cs_sweep_free(s);

    cs_sweep_def bad = def;
    bad.size = sizeof bad + 8;
    assert_int_equal(cs_sweep_study(&bad, &s, &err), CS_ERR_INVALID);
    assert_null(s);
    assert_true(strstr(err.message, "cs_sweep_def: size ") == err.message);
    /* a spec with a problem: refused, nothing run, the problem in the error */
    bad = def;
    bad.seed = "minus one";
    assert_int_equal(cs_sweep_study(&bad, &s, &err), CS_ERR_INVALID);
    assert_null(s);
    assert_non_null(strstr(err.message, "--seed minus one: expected a whole number"));
    /* ranks that cannot share a study: refused by name before anything runs */
    cs_sweep_ranks_def ranks = cs_default_sweep_ranks();
    assert_true(ranks.size == sizeof ranks && ranks.rank == 0 && ranks.ranks == 1);
    ranks.ranks = 2; /* and no hooks */
    bad = def;
    bad.ranks = &ranks;
    assert_int_equal(cs_sweep_study(&bad, &s, &err), CS_ERR_INVALID);
    assert_null(s);
    assert_string_equal(err.message, "cs_sweep_ranks_def: 2 ranks without every hook");
    ranks.ranks = 1, ranks.rank = 1;
    assert_int_equal(cs_sweep_study(&bad, &s, &err), CS_ERR_INVALID);
    assert_string_equal(err.message, "cs_sweep_ranks_def: rank 1 of 1 ranks");
    ranks = cs_default_sweep_ranks();
    ranks.size += 8;
    assert_int_equal(cs_sweep_study(&bad, &s, &err), CS_ERR_INVALID);
    assert_true(strstr(err.message, "cs_sweep_ranks_def: size ") == err.message);
}

static void compare_is_the_commands(void **state) {
    (void)state;
    char run_a[300], run_b[300], api[300], cmd[300];
    snprintf(run_a, sizeof run_a, "%s/a", tmp);
    snprintf(run_b, sizeof run_b, "%s/b", tmp);
    snprintf(api, sizeof api, "%s/compare-api", tmp);
    snprintf(cmd, sizeof cmd, "%s/compare-cmd", tmp);
    sh(CS " run " CS_SOURCE_DIR "/examples/aps3.yaml --t-end '60 ms' -o '%s' >/dev/null", run_a);
    sh(CS " run " CS_SOURCE_DIR "/examples/aps3.yaml --t-end '60 ms' --set 'scenario.speed=35 mph' -o '%s' "
          ">/dev/null",
       run_b);
    const char *runs[] = {run_a, run_b};
    cs_compare_def def = cs_default_compare_def();
    def.runs = runs;
    def.run_count = 2;
    cs_compare *c = NULL;
    cs_error err;
    if (cs_compare_create(&def, &c, &err) != CS_OK) fail_msg("%s", err.message);
    assert_int_equal(cs_compare_count(c), 2);
    assert_int_equal(cs_compare_reference(c), 0);
    assert_string_equal(cs_compare_label(c, 1), run_b);
    assert_string_equal(cs_compare_outcome(c, 0), "time_limit");
    if (cs_compare_write(c, api, 0, &err) != CS_OK) fail_msg("%s", err.message);
    sh(CS " compare '%s' '%s' -o '%s' >/dev/null", run_a, run_b, cmd);
    char a[400], b[400];
    snprintf(a, sizeof a, "%s/compare.csv", api);
    snprintf(b, sizeof b, "%s/compare.csv", cmd);
    same_file(a, b);

    /* compare.csv: parameter, unit, run a, run b, b against a [%] */
    table *t = read_csv(b);
    int params = cs_compare_parameter_count();
    assert_int_equal(t->rows, 2 + params);
    int differ = 0;
    for (int k = 0; k < params; k++) {
        int r = 2 + k;
        cs_compare_row ra = {.size = sizeof ra}, rb = {.size = sizeof rb};
        assert_int_equal(cs_compare_get(c, k, 0, &ra, &err), CS_OK);
        assert_int_equal(cs_compare_get(c, k, 1, &rb, &err), CS_OK);
        assert_string_equal(ra.name, t->cell[r][0]);
        assert_string_equal(ra.unit, t->cell[r][1]);
        same_number(ra.value, number(t, r, 2), ra.name);
        same_number(rb.value, number(t, r, 3), rb.name);
        assert_true(isnan(ra.difference)); /* the reference */
        double d = number(t, r, 4);        /* written %.4g */
        if (isnan(d))
            assert_true(isnan(rb.difference));
        else
            assert_true(fabs(rb.difference - d) <= 5e-4 * fabs(d) + 1e-12);
        differ += isfinite(rb.difference) && fabs(rb.difference) > 1.0;
    }
    assert_true(differ >= 2); /* 35 mph is not 40 mph */
    /* the 50-ms deceleration is each run's summary.json's */
    cs_compare_row r0 = {.size = sizeof r0};
    assert_int_equal(cs_compare_get(c, 0, 0, &r0, &err), CS_OK);
    assert_string_equal(r0.name, "max 50-ms deceleration");
    char path[400];
    snprintf(path, sizeof path, "%s/summary.json", run_a);
    char *json = slurp(path), *at = strstr(json, "\"max_50ms_decel_g\":");
    assert_non_null(at);
    double g = strtod(at + strlen("\"max_50ms_decel_g\":"), NULL);
    assert_true(g > 0.5 && fabs(r0.value - g) <= 1e-9 * g);
    free(json);
    free(t);

    /* an earlier, smaller row: filled to its size; sizes and indices it does not know: refused */
    _Alignas(max_align_t) unsigned char earlier[offsetof(cs_compare_row, difference) + 8];
    memset(earlier, 0x5a, sizeof earlier);
    size_t n = offsetof(cs_compare_row, difference);
    memcpy(earlier, &n, sizeof n);
    assert_int_equal(cs_compare_get(c, 0, 0, (cs_compare_row *)(void *)earlier, &err), CS_OK);
    assert_true(((cs_compare_row *)(void *)earlier)->value == r0.value);
    for (size_t k = n; k < sizeof earlier; k++)
        assert_int_equal(earlier[k], 0x5a);
    cs_compare_row row = {.size = 0};
    assert_int_equal(cs_compare_get(c, 0, 0, &row, &err), CS_ERR_INVALID);
    assert_true(strstr(err.message, "cs_compare_row: size 0") == err.message);
    row.size = sizeof row;
    assert_int_equal(cs_compare_get(c, params, 0, &row, &err), CS_ERR_INVALID);
    assert_int_equal(cs_compare_get(c, 0, 2, &row, &err), CS_ERR_INVALID);
    assert_string_equal(err.message, "cs_compare_row: no history 2 (the comparison has 2)");
    cs_compare_free(c);

    /* a run folder that is not one: refused with the system's reason, nothing to free */
    snprintf(path, sizeof path, "%s/nothing", tmp);
    runs[1] = path;
    c = NULL;
    assert_int_equal(cs_compare_create(&def, &c, &err), CS_ERR_IO);
    assert_null(c);
    assert_non_null(strstr(err.message, "nothing/summary.json: No such file or directory"));
    def.run_count = CS_COMPARE_MAX_RUNS + 1;
    assert_int_equal(cs_compare_create(&def, &c, &err), CS_ERR_INVALID);
}

/* A folder of the user's is refused naming the interface's way to write beside its files (the flag, the
 * def's field), or the option its def says stands for it; the files are kept. */
static void refusals_name_the_interfaces_force(void **state) {
    (void)state;
    char user[300], run[300];
    snprintf(user, sizeof user, "%s/user", tmp);
    snprintf(run, sizeof run, "%s/run", tmp);
    sh("mkdir -p '%s' && echo 'my notes' >'%s/notes.txt'", user, user);
    sh(CS " run " CS_SOURCE_DIR "/examples/aps3.yaml --t-end '10 ms' -o '%s' >/dev/null", run);
    cs_error err;
    const char *runs[] = {run};
    cs_compare_def def = cs_default_compare_def();
    def.runs = runs;
    def.run_count = 1;
    for (int given = 0; given < 2; given++) {
        def.force_given = given ? "--force" : NULL;
        cs_compare *c = NULL;
        if (cs_compare_create(&def, &c, &err) != CS_OK) fail_msg("%s", err.message);
        assert_int_equal(cs_compare_write(c, user, 0, &err), CS_ERR_IO);
        assert_non_null(strstr(err.message, "holds notes.txt, which no cablesim run wrote there"));
        const char *named = given ? "or write beside such files with --force (none of them is removed)"
                                  : "or write beside such files with the flag CS_COMPARE_FORCE (none of them";
        if (!strstr(err.message, named)) fail_msg("%s", err.message);
        assert_true(given || !strstr(err.message, "--force"));
        cs_compare_free(c);
    }
    cs_sweep_def sweep = cs_default_sweep_def();
    sweep.spec = CS_SOURCE_DIR "/examples/aps3-uncertain.yaml";
    sweep.out_dir = user;
    sweep.runs = 1;
    cs_sweep *s = NULL;
    assert_int_equal(cs_sweep_study(&sweep, &s, &err), CS_ERR_IO);
    assert_null(s);
    if (!strstr(err.message, "or write beside such files with cs_sweep_def's force set to 1 (none of them"))
        fail_msg("%s", err.message);
    assert_null(strstr(err.message, "--force"));
    sh("[ \"$(cat '%s/notes.txt')\" = 'my notes' ] && [ ! -e '%s/runs.csv' ]", user, user);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sweep_is_the_commands),
        cmocka_unit_test(compare_is_the_commands),
        cmocka_unit_test(refusals_name_the_interfaces_force),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
