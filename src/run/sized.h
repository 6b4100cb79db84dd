/* SPDX-License-Identifier: MIT */
/* A caller's definitions read at the sizes it gave them (def.h): whole structs of this library, the fields
 * the caller's lacked at their defaults, for cs_model_create to check and build from. */
#ifndef CS_SIZED_H
#define CS_SIZED_H

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

#endif
