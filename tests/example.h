/* SPDX-License-Identifier: MIT */
/* Load examples/<name>.yaml (with --set style assignments, NULL-terminated, or NULL) and build its model;
 * fails the test if it does not load. The loader is returned for freeing with the model. */
#ifndef CS_TEST_EXAMPLE_H
#define CS_TEST_EXAMPLE_H

#include "cablesim/loader.h"
#include "cablesim/sim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Pinned predictions (tests/predictions/): a row of numbers of each run (NAME.csv, 10 digits) and the
 * hash of its final state (NAME-hashes.csv), rewritten by `make pin` (CS_PIN_UPDATE=1) and only by it.
 * Built with musl's maths (CS_MATH_MUSL, CMake's default where emscripten is installed) the engine gives
 * the same bits on any x86-64: the numbers the same to 1e-6 and the hash equal to musl's. With the C
 * library's (glibc), whose last bits differ by processor and reach the fourth digit of a crash run
 * (docs/designer.md), the numbers (musl's) within 1% and the hash equal to glibc's own, pinned on a
 * processor with FMA and AVX2 (the versions glibc then picks); on one without them the hash cannot be
 * compared, and the test says so and exits 77, which CTest reports as skipped. */
#ifndef CS_MATH_MUSL
#define CS_MATH_MUSL 0
#endif
#define CS_PIN_TOLERANCE (CS_MATH_MUSL ? 1e-6 : 1e-2)
#if CS_MATH_MUSL
#define CS_PIN_MATHS "musl"
#else
#define CS_PIN_MATHS "glibc"
#endif

static int pin_skipped; /* a hash not compared: main exits 77 */

static inline int pin_update(void) {
    return getenv("CS_PIN_UPDATE") != NULL;
}

/* Whether this processor gives the bits pinned for this build's maths. */
static inline int pin_comparable(void) {
    if (CS_MATH_MUSL) return 1;
    __builtin_cpu_init();
    return __builtin_cpu_supports("fma") && __builtin_cpu_supports("avx2");
}

static inline void pinned_close_to(const char *what, double got, double want) {
    if (!(fabs(got - want) <= CS_PIN_TOLERANCE * fabs(want) + 1e-9))
        fail_msg("%s: %.10g, pinned %.10g", what, got, want);
}

/* The final state's hash of a run against FILE's row for this build's maths. */
static inline void pinned_hash(const char *file, const char *name, unsigned long long got) {
    if (!pin_comparable()) {
        printf("SKIPPED: %s's final state: glibc's maths are pinned on a processor with FMA and AVX2, and "
               "this one lacks them\n",
               name);
        pin_skipped = 1;
        return;
    }
    FILE *f = fopen(file, "r");
    if (!f) fail_msg("%s: cannot read (make pin writes it)", file);
    char line[256], maths[16], test[32];
    unsigned long long want = 0;
    int found = 0;
    while (!found && fgets(line, sizeof line, f))
        found = sscanf(line, "%15[^,],%31[^,],%llx", maths, test, &want) == 3 &&
                strcmp(maths, CS_PIN_MATHS) == 0 && strcmp(test, name) == 0;
    fclose(f);
    if (!found) fail_msg("%s: no %s hash of %s (make pin writes it)", file, CS_PIN_MATHS, name);
    if (got != want) fail_msg("%s: final state hash 0x%016llx, pinned 0x%016llx", name, got, want);
}

/* Rewrites FILE with ROWS in place of its rows whose text begins with DROP (all of them: DROP ""),
 * keeping its comment lines, its header and its other rows. */
static inline void pin_store(const char *file, const char *drop, const char *rows) {
    FILE *f = fopen(file, "r");
    if (!f) fail_msg("%s: cannot read", file);
    char line[512], *kept = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&kept, &size);
    int header = 0, placed = 0;
    while (fgets(line, sizeof line, f)) {
        int row = line[0] != '#' && header++ > 0;
        if (row && strncmp(line, drop, strlen(drop)) == 0) {
            if (!placed++) fputs(rows, out);
            continue;
        }
        fputs(line, out);
    }
    if (!placed) fputs(rows, out);
    fclose(out);
    fclose(f);
    if (!(f = fopen(file, "w")) || fputs(kept, f) == EOF || fclose(f) != 0)
        fail_msg("%s: cannot write", file);
    free(kept);
    printf("pinned: %s\n", file);
}

/* `make pin`: the runs' ROWS in place of those of CSV (musl's maths only: the numbers are theirs), and
 * their hashes HASHES in place of those of this build's maths in HASH_FILE. */
static inline void pin_write(const char *csv, const char *hash_file, const char *rows, const char *hashes) {
    if (!pin_comparable()) fail_msg("glibc's hashes are pinned on a processor with FMA and AVX2 only");
    if (CS_MATH_MUSL) pin_store(csv, "", rows);
    pin_store(hash_file, CS_PIN_MATHS ",", hashes);
}

/* Example NAME with the assignments SETS (NULL-terminated, or NULL), its input edited by EDIT (or NULL)
 * before it is built: what an assignment cannot say, as validate's "no rails" reading drops the rails. */
static inline cs_model *example_model_edited(const char *name, const char *const *sets,
                                             void (*edit)(cs_model_input *), cs_loader **loader) {
    char path[512];
    cs_error err;
    cs_loader *l = cs_loader_create(CS_SOURCE_DIR "/data", &err);
    if (!l) fail_msg("%s", err.message);
    snprintf(path, sizeof path, CS_SOURCE_DIR "/examples/%s.yaml", name);
    for (int k = 0; sets && sets[k]; k++)
        if (cs_loader_set(l, sets[k]) != 0) fail_msg("%s: bad assignment %s", name, sets[k]);
    cs_model_input in = {.size = sizeof in};
    cs_model *m = NULL;
    int loaded = cs_loader_load(l, path, &in) == 0;
    if (loaded && edit) edit(&in);
    if (!loaded || !(m = cs_loader_build(l, &in))) {
        cs_loader_print_errors(l, stderr);
        fail_msg("%s did not load", path);
    }
    *loader = l;
    return m;
}

static inline cs_model *example_model(const char *name, const char *const *sets, cs_loader **loader) {
    return example_model_edited(name, sets, NULL, loader);
}

/* Run model m from its settled state to its end and fill sm; fails the test if the run fails or if an element
 * dropped its load with no rope, fitting or attachment letting go to explain it (the summary's sudden
 * losses). Returns the final state, for the caller to free. */
static inline cs_state *example_run(const char *name, const cs_model *m, cs_summary *sm) {
    cs_error err;
    cs_state *s = cs_state_create(m, &err);
    if (!s) fail_msg("%s: %s", name, err.message);
    if (cs_run(m, s, NULL, NULL, &err) != CS_OK) fail_msg("%s: %s", name, err.message);
    *sm = (cs_summary){.size = sizeof *sm};
    cs_state_summary(s, sm, NULL);
    if (sm->sudden_loss_count)
        fail_msg("%s: %d sudden losses of the force on the vehicle with no rope, fitting or attachment to "
                 "explain them",
                 name, sm->sudden_loss_count);
    return s;
}

#endif
