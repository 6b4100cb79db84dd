/* SPDX-License-Identifier: MIT */
/* The loader's in-memory entry point: every example, good and bad model file loads from a buffer exactly as
 * from its path (same problems, same values), --set applies to a buffer and a reset loader is as new; a
 * model file edited in place (cs_yaml_edit, the designer page's download) loads as the original with the
 * same --set. */
#define _POSIX_C_SOURCE 200809L
#include <glob.h>
#include <malloc.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "cablesim/loader.h"
#include "load/grow.h"
#include "load/yamledit.h"

static const double MPH = 0.44704;

static cs_loader *new_loader(void) {
    cs_error err;
    cs_loader *l = cs_loader_create(CS_SOURCE_DIR "/data", &err);
    if (!l) fail_msg("%s", err.message);
    return l;
}

static char *slurp(const char *path, size_t *size) {
    FILE *f = fopen(path, "rb");
    if (!f) fail_msg("cannot open %s", path);
    char *buf = NULL;
    size_t cap = 0, n = 0, got;
    do {
        if (n == cap && !(buf = realloc(buf, cap = 2 * cap + 4096))) fail_msg("out of memory");
        got = fread(buf + n, 1, cap - n, f);
        n += got;
    } while (got > 0);
    fclose(f);
    *size = n;
    return buf;
}

/* The same problems, or the same model. */
static void same(const char *file, cs_loader *a, int rc_a, const cs_model_input *x, cs_loader *b, int rc_b,
                 const cs_model_input *y) {
    if (rc_a != rc_b || cs_loader_error_count(a) != cs_loader_error_count(b)) {
        cs_loader_print_errors(a, stderr);
        cs_loader_print_errors(b, stderr);
        fail_msg("%s: from its path %d (%d problems), from a buffer %d (%d problems)", file, rc_a,
                 cs_loader_error_count(a), rc_b, cs_loader_error_count(b));
    }
    for (int i = 0; i < cs_loader_error_count(a); i++)
        assert_string_equal(cs_loader_error(a, i), cs_loader_error(b, i));
    if (rc_a != 0) return;
    assert_string_equal(x->name, y->name);
    assert_int_equal(x->barrier.cable_count, y->barrier.cable_count);
    assert_int_equal(x->barrier.post_count, y->barrier.post_count);
    for (int i = 0; i < x->barrier.post_count; i++) {
        assert_true(x->barrier.posts[i].x == y->barrier.posts[i].x);
        assert_true(x->barrier.posts[i].section.plastic_modulus ==
                    y->barrier.posts[i].section.plastic_modulus);
    }
    for (int i = 0; i < x->barrier.cable_count; i++)
        assert_true(x->barrier.cables[i].pretension == y->barrier.cables[i].pretension);
    assert_true(x->vehicle.mass == y->vehicle.mass);
    assert_true(x->scenario.speed == y->scenario.speed);
}

/* cs_grow_one grows an array only when its count reaches the capacity that count implies (16, then
 * powers of two): 100,000 appends of a double take 14 allocations, 16 to 131,072 elements (log2 of
 * 131,072 / 16 is 13, plus the first). A realloc at every append, which copies the array whenever it
 * moves (always, under AddressSanitizer), made a 58,000-level sweep range take minutes to read. */
static void test_grow_one_doubles(void **state) {
    (void)state;
    double *a = NULL;
    size_t last = 0;
    int allocations = 0;
    for (int n = 0; n < 100000; n++) {
        assert_int_equal(cs_grow_one(&a, n, sizeof *a), 0);
        a[n] = n;
        size_t room = malloc_usable_size(a);
        assert_true(room >= ((size_t)n + 1) * sizeof *a);
        if (room != last) allocations++, last = room;
    }
    assert_int_equal(allocations, 14);
    assert_true(a[99999] == 99999.0 && a[16] == 16.0);
    free(a);
}

static void test_every_file(void **state) {
    (void)state;
    static const char *const patterns[] = {"examples/*.yaml", "tests/good/*.yaml", "tests/bad/*.yaml"};
    cs_loader *b = new_loader(); /* one loader, reset between files */
    int files = 0;
    for (size_t p = 0; p < sizeof patterns / sizeof patterns[0]; p++) {
        glob_t g;
        if (glob(patterns[p], 0, NULL, &g) != 0) fail_msg("no %s (run from the source tree)", patterns[p]);
        for (size_t i = 0; i < g.gl_pathc; i++, files++) {
            const char *file = g.gl_pathv[i];
            size_t size;
            char *data = slurp(file, &size);
            cs_model_input x = {.size = sizeof x}, y = {.size = sizeof y};
            cs_loader *a = new_loader();
            int rc_a = cs_loader_load(a, file, &x);
            cs_loader_reset(b);
            int rc_b = cs_loader_load_buffer(b, file, data, size, &y);
            free(data); /* needed only during the call */
            same(file, a, rc_a, &x, b, rc_b, &y);
            cs_loader_free(a);
        }
        globfree(&g);
    }
    assert_true(files >= 30);
    cs_loader_free(b);
}

static void test_set_and_reset(void **state) {
    (void)state;
    static const char model[] = "name: inline\nbarrier: {file: base.yaml}\nvehicle: M\n"
                                "scenario: {file: base.yaml}\n";
    cs_loader *l = new_loader();
    cs_model_input in = {.size = sizeof in};
    assert_int_equal(cs_loader_set(l, "scenario.speed=35 mph"), 0);
    assert_int_equal(cs_loader_load_buffer(l, "tests/good/inline.yaml", model, strlen(model), &in), 0);
    assert_string_equal(in.name, "inline");
    assert_true(fabs(in.scenario.speed - 35 * MPH) < 1e-9);
    cs_loader_reset(l);
    assert_int_equal(cs_loader_load_buffer(l, "tests/bad/inline.yaml", model, strlen(model), &in),
                     CS_ERR_INVALID);
    assert_int_equal(cs_loader_error_count(l), 1); /* no base.yaml there */
    assert_non_null(
        strstr(cs_loader_error(l, 0), "tests/bad/inline.yaml:2:17: barrier.file: cannot open 'base.yaml'"));
    cs_loader_reset(l); /* the --set and the problems are gone */
    assert_int_equal(cs_loader_error_count(l), 0);
    assert_int_equal(cs_loader_load_buffer(l, "tests/good/inline.yaml", model, strlen(model), &in), 0);
    assert_true(fabs(in.scenario.speed - 40 * MPH) < 1e-9); /* base.yaml's */
    assert_int_equal(cs_loader_load_buffer(l, "x.yaml", "", 0, &in),
                     CS_ERR_INVALID); /* empty: a problem, no crash */
    cs_loader_free(l);
}

/* Values in block and flow mappings, a named part, a value that needs quotes: the edited file gives the
 * engine the numbers its --set gives; paths the file does not hold are refused. */
static void test_edit_as_set(void **state) {
    (void)state;
    size_t size, edited_size = 0;
    char *text = slurp(CS_SOURCE_DIR "/examples/aps3.yaml", &size);
    cs_error err;
    const char *sets[] = {"barrier.posts[0].spacing=6 ft",
                          "scenario.speed=35 mph",
                          "vehicle=M",
                          "barrier.posts[0].footing.depth=4 ft",
                          "barrier.cables[1].pretension=7.5 kip",
                          "description=a: b, [c] # d \"e\""};
    int n = sizeof sets / sizeof sets[0];
    char *edited = cs_yaml_edit(text, size, sets, n, &edited_size, &err);
    if (!edited) fail_msg("%s", err.message);
    assert_non_null(strstr(edited, "footing: {diameter: 9 in, depth: 4 ft, rotation_limit"));
    assert_non_null(strstr(edited, "# the intermediate anchor posts stand there")); /* comments kept */
    cs_loader *a = new_loader(), *b = new_loader();
    for (int i = 0; i < n; i++)
        cs_loader_set(a, sets[i]);
    cs_model_input x = {.size = sizeof x}, y = {.size = sizeof y};
    assert_int_equal(cs_loader_load_buffer(a, "aps3.yaml", text, size, &x), 0);
    assert_int_equal(cs_loader_load_buffer(b, "aps3.yaml", edited, edited_size, &y), 0);
    assert_true(cs_model_input_hash(&x) == cs_model_input_hash(&y));
    assert_float_equal(y.scenario.speed, 35 * MPH, 1e-12);
    cs_loader_free(a);
    cs_loader_free(b);
    free(edited);
    const char *missing[] = {"scenario.no_such_value=1"}, *collection[] = {"barrier.soil=1"},
               *twice[] = {"vehicle=M", "vehicle=S"};
    assert_null(cs_yaml_edit(text, size, missing, 1, &edited_size, &err));
    assert_int_equal(err.status, CS_ERR_INVALID);
    assert_non_null(strstr(err.message, "scenario.no_such_value is not a single value written in the file"));
    assert_null(cs_yaml_edit(text, size, collection, 1, &edited_size, &err));
    assert_int_equal(err.status, CS_ERR_INVALID);
    assert_null(cs_yaml_edit(text, size, twice, 2, &edited_size, &err));
    assert_int_equal(err.status, CS_ERR_INVALID);
    assert_non_null(strstr(err.message, "vehicle is set twice"));
    free(text);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grow_one_doubles),
        cmocka_unit_test(test_every_file),
        cmocka_unit_test(test_set_and_reset),
        cmocka_unit_test(test_edit_as_set),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
