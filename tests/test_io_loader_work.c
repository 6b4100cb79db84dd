/* SPDX-License-Identifier: MIT */
/* The loader's work grows linearly with the model: generated models of 1,000, 10,000 and 100,000 posts,
 * cables and keys given twice, each item naming its own part (by an alias) among as many, loaded with the
 * loader's count of its steps (cs_loader.work: the nodes it reads, builds and checks, the entries its
 * scans pass, each look-up in a sorted index). A loader that looked for each item among all the others
 * (as the tree's search for a key given twice did, the parts' and anchors' searches, the check of a
 * subtree's shape and the cables against the posts) would count about N^2 / 2 steps: per item 50 times
 * more at 100,000 than at 1,000. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "io/load/loader_int.h"

/* The count of steps per item may not grow from 1,000 items to 100,000 by more than this (a linear
 * loader's falls: the parts library's reading, the same at every size, is spread over more items). */
static const double GROWTH_TOL = 1.1;

static const char *const FOOTING =
    "footing: {diameter: 9 in, depth: 3 ft, rotation_limit: 45 deg, pullout_capacity: 20 kip}";

/* A model of n posts, each a group of its own naming its own section (an alias of the section's name),
 * 2 cables; or of n cables, each naming its own rope so, on 10 posts. */
static char *model(int n, int cables, size_t *size) {
    char *text = NULL;
    FILE *f = open_memstream(&text, size);
    assert_non_null(f);
    fprintf(f, "name: work-%d\nparts:\n  %s:\n", n, cables ? "ropes" : "sections");
    for (int i = 0; i < n; i++)
        if (cables)
            fprintf(f, "    - {name: &p%d r%d, scale_from: A603-1in, diameter: 1.75 in}\n", i, i);
        else
            fprintf(f, "    - {name: &p%d s%d, part: CF-I4x1.75}\n", i, i);
    fprintf(f, "barrier:\n  soil: {soil_pressure: 8000 psf, coeff_depth: 2.37, coeff_height: 2.64}\n"
               "  cables:\n");
    int posts = cables ? 10 : n, spacing = cables ? 96 : 3; /* inches: 100,000 posts within 10 km */
    for (int i = 0; i < (cables ? n : 2); i++)
        if (cables)
            fprintf(f, "    - {rope: *p%d, height: 2.83 ft, pretension: 5 kip, post_friction: 0.15}\n", i);
        else
            fprintf(f, "    - {rope: A603-1.75in, height: %s ft, pretension: 5 kip, post_friction: 0.15}\n",
                    i ? "4" : "2.83");
    fprintf(f, "  posts:\n");
    for (int i = 0; i < posts; i++) {
        char section[32];
        snprintf(section, sizeof section, cables ? "CF-I4x1.75" : "*p%d", i);
        fprintf(f, "    - {x: [%d in], section: %s, height: 7 ft, attachment: through, %s}\n",
                spacing * (i + 1), section, FOOTING);
    }
    fprintf(f,
            "  anchors:\n    start: {x: 0 ft, z: 0 ft, pullout_capacity: none}\n"
            "    end: {x: %d in, z: 0 ft, pullout_capacity: none}\n"
            "vehicle: SD-STD-02.01\nscenario: {speed: 40 mph, angle: 90 deg, impact_x: %d in}\n",
            spacing * (posts + 1), spacing * posts / 2 + spacing / 2);
    assert_int_equal(fclose(f), 0);
    return text;
}

/* A valid model whose scenario gives its speed n times more: n problems, each at its place. */
static char *twice(int n, size_t *size) {
    char *text = NULL;
    FILE *f = open_memstream(&text, size);
    assert_non_null(f);
    fprintf(f,
            "name: twice-%d\nbarrier: {file: %s/examples/aps3.yaml}\nvehicle: SD-STD-02.01\n"
            "scenario:\n  impact_x: 44 ft\n  speed: 40 mph\n",
            n, CS_SOURCE_DIR);
    for (int i = 0; i < n; i++)
        fprintf(f, "  speed: %d mph\n", 40 + i % 20);
    assert_int_equal(fclose(f), 0);
    return text;
}

typedef enum family { POSTS, CABLES, TWICE } family;

/* The loader's steps for a model of the family with n items; checks that it loaded (or was refused) as
 * it should. */
static double work(family fam, int n) {
    size_t size = 0;
    char *text = fam == TWICE ? twice(n, &size) : model(n, fam == CABLES, &size);
    cs_error err;
    cs_loader *l = cs_loader_create(CS_SOURCE_DIR "/data", &err);
    assert_non_null(l);
    assert_int_equal(cs_loader_allow_path(l, CS_SOURCE_DIR "/examples", &err), CS_OK);
    cs_model_input in = {.size = sizeof in};
    cs_status rc = cs_loader_load_buffer(l, CS_SOURCE_DIR "/tests/work.yaml", text, size, &in);
    int errors = cs_loader_error_count(l);
    const char *first = errors ? cs_loader_error(l, 0) : "";
    if (fam == POSTS && n <= 10000) { /* the loader's limit: 10,000 posts */
        if (rc != CS_OK) fail_msg("%d posts: %s", n, first);
        assert_int_equal(in.barrier.post_count, n);
    } else if (fam == POSTS) { /* refused once, at the group past the limit */
        if (errors != 1 || !strstr(first, "posts[10000]: more than 10000 posts (expected at most 10000"))
            fail_msg("%d posts: %d problems, the first %s", n, errors, first);
    } else if (fam == CABLES) { /* the engine's limit of 64 cables is not the loader's */
        if (rc != CS_OK) fail_msg("%d cables: %s", n, first);
        assert_int_equal(in.barrier.cable_count, n);
    } else {
        assert_int_equal(errors, n);
        assert_non_null(strstr(first, "scenario.speed: given twice (first at 6:3)"));
    }
    double w = (double)l->work;
    fflush(stdout);
    printf("%-6s %6d items: %10.0f steps, %.2f an item\n",
           fam == POSTS    ? "posts"
           : fam == CABLES ? "cables"
                           : "twice",
           n, w, w / n);
    cs_loader_free(l);
    free(text);
    return w;
}

/* Each family at 1,000, 10,000 and 100,000 items: the steps an item may not grow by GROWTH_TOL. */
static void linear(family fam) {
    double first = work(fam, 1000) / 1000;
    assert_true(first > 0);
    for (int n = 10000; n <= 100000; n *= 10) { /* each size checked before the next is tried */
        double per = work(fam, n) / n;
        if (!(per <= GROWTH_TOL * first))
            fail_msg("%.2f steps an item at %d items, %.2f at 1,000: more than %g times", per, n, first,
                     GROWTH_TOL);
    }
}

static void test_posts(void **state) {
    (void)state;
    linear(POSTS);
}

static void test_cables(void **state) {
    (void)state;
    linear(CABLES);
}

static void test_keys_given_twice(void **state) {
    (void)state;
    linear(TWICE);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_posts),
        cmocka_unit_test(test_cables),
        cmocka_unit_test(test_keys_given_twice),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
