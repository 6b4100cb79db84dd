/* SPDX-License-Identifier: MIT */
/* A caller's definitions read at the sizes it gave them (def.h): whole structs of this library, the fields
 * the caller's lacked at their defaults, for cs_model_create to check and build from; and the structs the
 * engine fills for the caller (sim.h's views, cs_summary, cs_event, cs_energy, cs_cable_summary,
 * cs_sudden_loss; and the loaders' and writers' structs, through src/io/status.h) written at the caller's
 * size. src/io includes this one header of the engine's layers (tests/cli_layers.sh), so that there is one
 * size check; and one filler of a cs_error (cs_error_set). */
#ifndef CS_SIZED_H
#define CS_SIZED_H

#include <stdarg.h>

#include "cablesim/sim.h"

typedef struct cs_defs {
    cs_barrier_def barrier; /* its cables, posts and rails are the arrays below */
    cs_vehicle_def vehicle;
    cs_scenario_def scenario;
    cs_cable_def *cables;
    cs_post_def *posts;
    cs_rail_def *rails;
} cs_defs;

/* Read the caller's definitions into d. Returns 0, or -1 with err filled (CS_ERR_INVALID: a struct of size
 * 0 or larger than this library's, or of a layout it does not know; CS_ERR_MEMORY). Free d with
 * cs_defs_free either way. */
int cs_defs_take(cs_defs *d, const cs_barrier_def *barrier, const cs_vehicle_def *vehicle,
                 const cs_scenario_def *scenario, cs_error *err);
void cs_defs_free(cs_defs *d);

/* Whether the caller's struct at, that starts with its size, can take this library's of full_size bytes:
 * CS_OK, or CS_ERR_INVALID with err filled (may be NULL) naming the struct ("NAME: size N, where this
 * library's is M: ...") if at is NULL or its size is less than a size_t's or larger than full_size. The one
 * check of every struct the library fills or reads at its caller's size, the engine's and the loaders' and
 * writers' (src/io/status.h). */
cs_status cs_sized_check(const void *at, size_t full_size, const char *name, cs_error *err);
/* The same, with the size found in *n (0 for NULL). */
cs_status cs_sized_size(const void *at, size_t full_size, const char *name, size_t *n, cs_error *err);
/* Hand full (this library's struct, of full_size bytes, that starts with its size) to the caller's out at
 * out's size: CS_OK, or CS_ERR_INVALID with err filled (may be NULL) naming the struct if out is NULL or its
 * size is less than a size_t's or larger than full_size. */
cs_status cs_sized_put(void *out, const void *full, size_t full_size, const char *name, cs_error *err);
/* Hand count (0 or more) of this library's structs (an array of full_size strides) to the caller's array
 * out, each at the size of out's first and with that size: as cs_sized_put (out's first size checked even
 * for none), nothing written when it is refused. */
cs_status cs_sized_put_array(void *out, const void *full, size_t full_size, int count, const char *name,
                             cs_error *err);
/* Read the caller's struct given, of the size it starts with, over full (this library's, of full_size
 * bytes, holding the defaults of what the caller's lacks): CS_OK, or CS_ERR_INVALID as cs_sized_put. */
cs_status cs_sized_take(void *full, size_t full_size, const void *given, const char *name, cs_error *err);
/* Fill err (may be NULL) with status and the message that fmt and what follows make, as printf does, cut
 * to the message's room; return status. The one filler of a cs_error's message, the engine's and the
 * loaders' and writers' (src/io/status.h); it is in run/error.c. */
cs_status cs_error_set(cs_error *err, cs_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The same with the arguments in ap. */
cs_status cs_error_vset(cs_error *err, cs_status status, const char *fmt, va_list ap)
    __attribute__((format(printf, 3, 0)));
/* Fill err (may be NULL) with CS_ERR_MEMORY. */
void cs_out_of_memory(cs_error *err);
/* Refuse a fill of name: CS_ERR_INVALID with err filled (may be NULL): "name: reason". */
cs_status cs_sized_refuse(cs_error *err, const char *name, const char *reason);

#endif
