/* SPDX-License-Identifier: MIT */
/* The loaders' and writers' side of cs_error: their functions return a cs_status (or NULL or -1 where that
 * is their natural result) and fill a cs_error, formatted by the engine's one filler (run/sized.h,
 * cs_error_set). */
#ifndef CS_IO_STATUS_H
#define CS_IO_STATUS_H

#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "../run/sized.h" /* the one size check: the engine's header src/io may include (tests/cli_layers.sh) */
#include "cablesim/loader.h"
#include "cablesim/sim.h"

/* Fill err (may be NULL) with status and message, and return status. */
static inline cs_status cs_status_set(cs_error *err, cs_status status, const char *message) {
    return cs_error_set(err, status, "%s", status == CS_OK || !message ? "" : message);
}

/* Whether the caller's struct out, that starts with its size, can take this library's of full_size bytes
 * (cablesim/rating.h, cablesim/loader.h, cablesim/sweep.h, cablesim/compare.h): the engine's one check
 * (run/sized.h), CS_OK or CS_ERR_INVALID with err filled naming the struct. */
static inline cs_status cs_status_sized(const void *out, size_t full_size, const char *name, cs_error *err) {
    return cs_sized_check(out, full_size, name, err);
}

/* Hand full (this library's struct, of full_size bytes) to the caller's out at out's size: as
 * cs_status_sized, writing nothing when that refuses it (run/sized.h's cs_sized_put). */
static inline cs_status cs_status_put_sized(void *out, const void *full, size_t full_size, const char *name,
                                            cs_error *err) {
    return cs_sized_put(out, full, full_size, name, err);
}

/* A loaded model handed back by the caller (cablesim/loader.h): CS_OK, or CS_ERR_INVALID with err filled if
 * its size does not reach its scenario or is larger than this library's. */
static inline cs_status cs_status_input(const cs_model_input *in, cs_error *err) {
    size_t need = offsetof(cs_model_input, scenario) + sizeof in->scenario;
    if (in && in->size >= need && in->size <= sizeof *in) return CS_OK;
    char why[CS_MESSAGE_SIZE];
    snprintf(why, sizeof why,
             "cs_model_input: size %zu, where this library needs %zu to %zu: fill it with "
             "cs_loader_load at its size",
             in ? in->size : 0, need, sizeof *in);
    return cs_status_set(err, CS_ERR_INVALID, why);
}

#endif
