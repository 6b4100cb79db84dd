/* SPDX-License-Identifier: MIT */
/* libFuzzer harness of the sweep spec: each input is a spec's contents, read as the file
 * examples/fuzz-spec.yaml (so `model: aps3.yaml` finds the example), then, as `cablesim check SPEC`
 * does, its runs' inputs drawn and each run's model checked by the loader and the engine (run 0 and every
 * grid level). Nothing is run. Studies whose inputs would take more than 10^6 numbers, or whose grids
 * have more than 64 levels (a model loaded for each), are read but not drawn, to keep each input fast.
 *
 * Build and run: make fuzz (FUZZ_SECONDS for each target). A kept input replays with `cablesim check
 * FILE` or build-fuzz/fuzz_sweep FILE. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "study/sweep.h"

#ifndef CS_SOURCE_DIR
#define CS_SOURCE_DIR "."
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static cs_units *units; /* read once: the unit database takes milliseconds */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (!units) {
        cs_error err;
        if (!(units = cs_units_open(&err))) {
            fprintf(stderr, "fuzz_sweep: %s\n", err.message);
            abort();
        }
    }
    cs_sweep_spec *spec =
        cs_sweep_spec_read_buffer(CS_SOURCE_DIR "/examples/fuzz-spec.yaml", (const char *)data, size, units);
    if (!spec) return 0; /* memory short */
    long n = 0;
    int levels = 0;
    for (int i = 0; i < spec->var_count; i++)
        levels += spec->vars[i].level_count;
    double *x = NULL;
    if (!spec->error_count && (double)spec->runs * (spec->var_count + 1) <= 1e6 && levels <= 64 &&
        (x = cs_sweep_samples(spec, &n)) != NULL)
        cs_sweep_check(spec, x);
    for (int i = 0; i < spec->error_count; i++) /* read every message back, as the command prints them */
        if (!spec->errors[i]) abort();
    free(x);
    cs_sweep_spec_free(spec);
    return 0;
}
