/* SPDX-License-Identifier: MIT */
/* libFuzzer harness of the model loader: each input is a model file's contents, loaded through the public
 * API (cs_loader_load_buffer) and, when it loads, built by the engine, as `cablesim check` does. Lines of
 * the input that start with "#set " (YAML comments, so the model is unchanged) are queued first as
 * --set overrides, which takes the fuzzer down the override path too. The input stands for the file
 * tests/good/fuzz-input.yaml, so `file: base.yaml` finds tests/good/base.yaml as in the seeds.
 *
 * Build and run: make fuzz (FUZZ_SECONDS=60). A crashing input replays with `cablesim check FILE
 * --set ...` (tests/cli_fuzz_regressions.sh) or with build-fuzz/fuzz_loader FILE. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/loader.h"

#ifndef CS_SOURCE_DIR
#define CS_SOURCE_DIR "."
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* One loader for the whole run: creating one reads the unit database (milliseconds); a reset does not. */
static cs_loader *loader;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (!loader) {
        cs_error err;
        if (!(loader = cs_loader_create(CS_SOURCE_DIR "/data", &err))) {
            fprintf(stderr, "fuzz_loader: %s\n", err.message);
            abort();
        }
    }
    cs_loader_reset(loader);
    const char *p = (const char *)data, *end = p + size;
    while (p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p)), *eol = nl ? nl : end;
        char set[1024];
        size_t n = (size_t)(eol - p);
        if (n > 5 && memcmp(p, "#set ", 5) == 0) {
            n = n - 5 < sizeof set ? n - 5 : sizeof set - 1;
            memcpy(set, p + 5, n);
            set[n] = '\0';
            cs_loader_set(loader, set);
        }
        p = eol + 1;
    }
    cs_model_input in = {.size = sizeof in};
    cs_model *model = NULL;
    if (cs_loader_load_buffer(loader, CS_SOURCE_DIR "/tests/good/fuzz-input.yaml", (const char *)data, size,
                              &in) == 0)
        model = cs_loader_build(loader, &in);
    cs_model_free(model);
    size_t total = 0; /* read every message back, as the command prints them */
    for (int i = 0; i < cs_loader_error_count(loader); i++)
        total += strlen(cs_loader_error(loader, i));
    (void)total;
    return 0;
}
