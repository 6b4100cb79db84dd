/* SPDX-License-Identifier: MIT */
/* The command's outputs, pinned: `cablesim run` of examples/aps3.yaml and examples/roadside/rs1.yaml must
 * write summary.json, events.csv and the first rows of timeseries.csv as tests/golden/MATHS/NAME/ holds
 * them, field by field: each number within a relative 1e-9 of the pinned one (the files give 10 digits),
 * every string, key, column and row count exact. The crash tests' pins (test_io_crash_tests.c) hold the
 * engine's numbers; these hold what the writers make of them (src/io/out/): a value written under another
 * key, a column moved, a unit changed fails here. `make pin` rewrites them (CS_PIN_UPDATE=1); they are
 * musl's maths' or, built with glibc's, glibc's own on a processor with FMA and AVX2 (tests/example.h). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cmocka.h>
#include <json-c/json.h>

#include "example.h"

#define GOLDEN_TOLERANCE 1e-9
#define TIMESERIES_ROWS 40 /* the first rows of timeseries.csv pinned, after its header */

typedef struct golden_case {
    const char *name, *model; /* tests/golden/MATHS/NAME/ and the model, from the source tree */
} golden_case;

static const golden_case cases[] = {{"aps3", "examples/aps3.yaml"}, {"rs1", "examples/roadside/rs1.yaml"}};

static int mismatches;

static void mismatch(const char *file, const char *where, const char *got, const char *want) {
    printf("%s: %s: %s, pinned %s\n", file, where, got, want);
    mismatches++;
}

/* Whether two fields agree: both numbers within GOLDEN_TOLERANCE of each other, or the same text. */
static int same_field(const char *got, const char *want) {
    char *end_g, *end_w;
    double g = strtod(got, &end_g), w = strtod(want, &end_w);
    if (end_g != got && !*end_g && end_w != want && !*end_w)
        return g == w || fabs(g - w) <= GOLDEN_TOLERANCE * fmax(fabs(g), fabs(w));
    return strcmp(got, want) == 0;
}

static void same_json(const char *file, const char *where, json_object *got, json_object *want) {
    json_type tg = json_object_get_type(got), tw = json_object_get_type(want);
    int numbers =
        (tg == json_type_int || tg == json_type_double) && (tw == json_type_int || tw == json_type_double);
    if (tg != tw && !numbers) {
        mismatch(file, where, json_object_to_json_string(got), json_object_to_json_string(want));
        return;
    }
    char at[512];
    if (tw == json_type_object) {
        if (json_object_object_length(got) != json_object_object_length(want))
            mismatch(file, where, json_object_to_json_string(got), json_object_to_json_string(want));
        json_object_object_foreach(want, key, w) {
            json_object *g;
            snprintf(at, sizeof at, "%s.%s", where, key);
            if (!json_object_object_get_ex(got, key, &g))
                mismatch(file, at, "missing", json_object_to_json_string(w));
            else
                same_json(file, at, g, w);
        }
    } else if (tw == json_type_array) {
        size_t n = json_object_array_length(want);
        if (json_object_array_length(got) != n) {
            mismatch(file, where, json_object_to_json_string(got), json_object_to_json_string(want));
            return;
        }
        for (size_t i = 0; i < n; i++) {
            snprintf(at, sizeof at, "%s[%zu]", where, i);
            same_json(file, at, json_object_array_get_idx(got, i), json_object_array_get_idx(want, i));
        }
    } else if (numbers) {
        double g = json_object_get_double(got), w = json_object_get_double(want);
        if (!(g == w || fabs(g - w) <= GOLDEN_TOLERANCE * fmax(fabs(g), fabs(w))))
            mismatch(file, where, json_object_to_json_string(got), json_object_to_json_string(want));
    } else if (strcmp(json_object_to_json_string(got), json_object_to_json_string(want)) != 0) {
        mismatch(file, where, json_object_to_json_string(got), json_object_to_json_string(want));
    }
}

/* Splits LINE at its commas outside double quotes, in place; returns the count of fields. */
static int split(char *line, char **fields, int max) {
    int n = 0, quoted = 0;
    line[strcspn(line, "\r\n")] = '\0';
    fields[n++] = line;
    for (char *c = line; *c; c++) {
        if (*c == '"') quoted = !quoted;
        if (*c == ',' && !quoted && n < max) *c = '\0', fields[n++] = c + 1;
    }
    return n;
}

/* The run's CSV against the pinned one, over the pinned one's lines: WHOLE, the run's has no more. */
static void same_csv(const char *file, const char *got_path, const char *want_path, int whole) {
    FILE *g = fopen(got_path, "r"), *w = fopen(want_path, "r");
    if (!g || !w) fail_msg("%s: cannot read %s", file, g ? want_path : got_path);
    char gl[8192], wl[8192], *gf[256], *wf[256], where[128], *header[256] = {0}, head[8192];
    int line = 0, columns = 0;
    while (fgets(wl, sizeof wl, w)) {
        line++;
        if (!fgets(gl, sizeof gl, g)) {
            mismatch(file, "the end", "reached", wl);
            break;
        }
        int ng = split(gl, gf, 256), nw = split(wl, wf, 256);
        if (line == 1) { /* the header names the columns of the messages */
            memcpy(head, wl, sizeof head);
            columns = split(head, header, 256);
        }
        if (ng != nw) {
            snprintf(where, sizeof where, "line %d", line);
            char a[32], b[32];
            snprintf(a, sizeof a, "%d fields", ng), snprintf(b, sizeof b, "%d", nw);
            mismatch(file, where, a, b);
            continue;
        }
        for (int k = 0; k < nw; k++)
            if (!same_field(gf[k], wf[k])) {
                snprintf(where, sizeof where, "line %d, %s", line, k < columns ? header[k] : "?");
                mismatch(file, where, gf[k], wf[k]);
            }
    }
    if (whole && fgets(gl, sizeof gl, g)) mismatch(file, "the end", "more lines", "none");
    fclose(g);
    fclose(w);
}

/* Copies FROM to TO, its first LINES lines (all: -1). */
static void copy_lines(const char *from, const char *to, int lines) {
    FILE *in = fopen(from, "r"), *out = fopen(to, "w");
    if (!in || !out) fail_msg("cannot copy %s to %s: %s", from, to, strerror(errno));
    char line[8192];
    for (int n = 0; (lines < 0 || n < lines) && fgets(line, sizeof line, in); n++)
        fputs(line, out);
    fclose(in);
    if (fclose(out) != 0) fail_msg("cannot write %s", to);
    printf("pinned: %s\n", to);
}

/* Every number under "inputs" has its key in "input_units" (summary.json labels each of them). */
static void units_of(const char *file, json_object *o, const char *key, json_object *units) {
    json_type t = json_object_get_type(o);
    if (t == json_type_object) {
        json_object_object_foreach(o, k, v) units_of(file, v, k, units);
    } else if (t == json_type_array) {
        for (size_t i = 0; i < json_object_array_length(o); i++)
            units_of(file, json_object_array_get_idx(o, i), key, units);
    } else if ((t == json_type_double || t == json_type_int) &&
               !json_object_object_get_ex(units, key, NULL)) {
        mismatch(file, key, "a number of inputs with no unit", "one in input_units");
    }
}

static void outputs_as_pinned(void **state) {
    (void)state;
    if (!pin_comparable()) {
        printf("SKIPPED: the outputs of glibc's maths are pinned on a processor with FMA and AVX2, and this "
               "one lacks them\n");
        pin_skipped = 1;
        return;
    }
    char out[] = "/tmp/cablesim-golden-XXXXXX", cmd[2048], dir[512], got[640], want[640];
    assert_non_null(mkdtemp(out));
    /* in a folder of examples/ and build/cablesim, as a user types it (summary.json records the command) */
    snprintf(cmd, sizeof cmd,
             "cd '%s' && mkdir build && ln -s '%s/examples' examples && ln -s '%s/cablesim' build/", out,
             CS_SOURCE_DIR, CS_BINARY_DIR);
    if (system(cmd) != 0) fail_msg("%s failed", cmd);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const golden_case *k = &cases[c];
        snprintf(cmd, sizeof cmd, "cd '%s' && build/cablesim run %s -o %s >/dev/null", out, k->model,
                 k->name);
        if (system(cmd) != 0) fail_msg("%s failed", cmd);
        snprintf(dir, sizeof dir, CS_SOURCE_DIR "/tests/golden/" CS_PIN_MATHS "/%s", k->name);
        const char *files[] = {"summary.json", "events.csv", "timeseries.csv"};
        for (int f = 0; f < 3; f++) {
            snprintf(got, sizeof got, "%s/%s/%s", out, k->name, files[f]);
            snprintf(want, sizeof want, "%s/%s", dir, files[f]);
            if (pin_update()) {
                mkdir(CS_SOURCE_DIR "/tests/golden", 0777);
                mkdir(CS_SOURCE_DIR "/tests/golden/" CS_PIN_MATHS, 0777);
                mkdir(dir, 0777);
                copy_lines(got, want, f == 2 ? TIMESERIES_ROWS + 1 : -1);
                continue;
            }
            char file[64];
            snprintf(file, sizeof file, "%s/%s", k->name, files[f]);
            if (f == 0) {
                json_object *g = json_object_from_file(got), *w = json_object_from_file(want);
                if (!g || !w) fail_msg("%s: cannot read %s", file, g ? want : got);
                same_json(file, "summary", g, w);
                json_object *inputs = NULL, *units = NULL;
                if (!json_object_object_get_ex(g, "inputs", &inputs) ||
                    !json_object_object_get_ex(g, "input_units", &units))
                    fail_msg("%s: no inputs or input_units", file);
                units_of(file, inputs, "inputs", units);
                json_object_put(g), json_object_put(w);
            } else {
                same_csv(file, got, want, f == 1);
            }
        }
    }
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", out);
    assert_int_equal(system(cmd), 0);
    if (mismatches)
        fail_msg("%d fields differ from tests/golden/%s (make pin rewrites them)", mismatches, CS_PIN_MATHS);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(outputs_as_pinned)};
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    return failed ? failed : pin_skipped ? 77 : 0;
}
