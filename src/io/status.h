/* SPDX-License-Identifier: MIT */
/* The loaders' and writers' side of cs_error: their inner functions say why in a buffer; their entry points
 * hand it back as the interface's cs_status and cs_error. */
#ifndef CS_IO_STATUS_H
#define CS_IO_STATUS_H

#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "cablesim/loader.h"
#include "cablesim/sim.h"

/* Fill err (may be NULL) with status and message, and return status. */
static inline cs_status cs_status_set(cs_error *err, cs_status status, const char *message) {
    if (err) {
        err->status = status;
        snprintf(err->message, sizeof err->message, "%s", status == CS_OK ? "" : message);
    }
    return status;
}

/* Whether the caller's struct out, that starts with its size, can take this library's of full_size bytes
 * (cablesim/rating.h, cablesim/loader.h): CS_OK, or CS_ERR_INVALID with err filled naming the struct if out
 * is NULL or its size is less than a size_t's or larger than full_size. */
static inline cs_status cs_status_sized(const void *out, size_t full_size, const char *name, cs_error *err) {
    size_t n = 0;
    if (out) memcpy(&n, out, sizeof n);
    if (n >= sizeof n && n <= full_size) return CS_OK;
    char why[CS_MESSAGE_SIZE];
    snprintf(why, sizeof why, "%s: size %zu, where this library's is %zu: set it to sizeof the struct", name,
             n, full_size);
    return cs_status_set(err, CS_ERR_INVALID, why);
}

/* Hand full (this library's struct, of full_size bytes) to the caller's out at out's size: as
 * cs_status_sized, writing nothing when that refuses it. */
static inline cs_status cs_status_put_sized(void *out, const void *full, size_t full_size, const char *name,
                                            cs_error *err) {
    if (cs_status_sized(out, full_size, name, err) != CS_OK) return CS_ERR_INVALID;
    size_t n;
    memcpy(&n, out, sizeof n);
    memcpy(out, full, n);
    memcpy(out, &n, sizeof n);
    return cs_status_set(err, CS_OK, "");
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
