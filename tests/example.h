/* SPDX-License-Identifier: MIT */
/* Load examples/<name>.yaml (with --set style assignments, NULL-terminated, or NULL) and build its model;
 * fails the test if it does not load. The loader is returned for freeing with the model. */
#ifndef CS_TEST_EXAMPLE_H
#define CS_TEST_EXAMPLE_H

#include "cablesim/loader.h"

#include <math.h>
#include <stdio.h>

/* A pinned prediction (a row of tests/predictions/, 10 digits, and its final state's hash) and this
 * engine's. Built with musl's maths (CS_MATH_MUSL, CMake's default where emscripten is installed) the
 * engine gives the same bits on any x86-64: the numbers the same to 1e-6 and the hash equal. With the C
 * library's, whose last bits differ by processor (FMA or not) and reach the fourth digit of a crash run
 * (docs/designer.md), the numbers within 1% and the hash not compared. */
#ifndef CS_MATH_MUSL
#define CS_MATH_MUSL 0
#endif
#define CS_PIN_TOLERANCE (CS_MATH_MUSL ? 1e-6 : 1e-2)

static inline void pinned_close_to(const char *what, double got, double want) {
    if (!(fabs(got - want) <= CS_PIN_TOLERANCE * fabs(want) + 1e-9))
        fail_msg("%s: %.10g, pinned %.10g", what, got, want);
}

static inline void pinned_hash(const char *name, unsigned long long got, unsigned long long want) {
    if (CS_MATH_MUSL && got != want)
        fail_msg("%s: final state hash 0x%016llx, stored 0x%016llx", name, got, want);
}

static inline cs_model *example_model(const char *name, const char *const *sets, cs_loader **loader) {
    char why[256], path[512];
    cs_loader *l = cs_loader_create(CS_SOURCE_DIR "/data", why, sizeof why);
    if (!l) fail_msg("%s", why);
    snprintf(path, sizeof path, CS_SOURCE_DIR "/examples/%s.yaml", name);
    for (int k = 0; sets && sets[k]; k++)
        if (cs_loader_set(l, sets[k]) != 0) fail_msg("%s: bad assignment %s", name, sets[k]);
    cs_model_input in;
    cs_model *m = NULL;
    if (cs_loader_load(l, path, &in) != 0 || !(m = cs_loader_build(l, &in))) {
        cs_loader_print_errors(l, stderr);
        fail_msg("%s did not load", path);
    }
    *loader = l;
    return m;
}

#endif
