/* SPDX-License-Identifier: MIT */
/* The loaders' and writers' side of cs_error: their inner functions say why in a buffer; their entry points
 * hand it back as the interface's cs_status and cs_error. */
#ifndef CS_IO_STATUS_H
#define CS_IO_STATUS_H

#include <stdio.h>

#include "cablesim/sim.h"

/* Fill err (may be NULL) with status and message, and return status. */
static inline cs_status cs_status_set(cs_error *err, cs_status status, const char *message) {
    if (err) {
        err->status = status;
        snprintf(err->message, sizeof err->message, "%s", status == CS_OK ? "" : message);
    }
    return status;
}

#endif
