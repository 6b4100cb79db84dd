/* SPDX-License-Identifier: MIT */
/* The fillers of a cs_error (run/sized.h), on their own so that a program of the
 * unit files alone (cmake/units_table.c) links it without the engine. */
#include <stdarg.h>
#include <stdio.h>

#include "run/sized.h"

cs_status cs_error_vset(cs_error *err, cs_status status, const char *fmt, va_list ap) {
    if (err) {
        err->status = status;
        vsnprintf(err->message, sizeof err->message, fmt, ap);
    }
    return status;
}

cs_status cs_error_set(cs_error *err, cs_status status, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    cs_error_vset(err, status, fmt, ap);
    va_end(ap);
    return status;
}

void cs_out_of_memory(cs_error *err) {
    cs_error_set(err, CS_ERR_MEMORY, "out of memory");
}
