/* SPDX-License-Identifier: MIT */
/* Inside the sweep spec's reader: what sweepspec.c (the file's tree, the spec) and sweepvalues.c (the
 * varied values) share. */
#ifndef CS_SWEEPSPEC_INT_H
#define CS_SWEEPSPEC_INT_H

#include "sweepspec.h"
#include "yamltree.h"

/* The keys of a `vary:` entry's mapping. */
static const char *const param_keys[] = {"dist", "mean", "sd", "min", "max", "from", "to", "step", "count"};
enum { P_DIST, P_MEAN, P_SD, P_MIN, P_MAX, P_FROM, P_TO, P_STEP, P_COUNT, P_N };

/* A scalar's text; NULL for a node that is absent or not a scalar. */
static inline const char *text(const cs_ynode *n) {
    return n && n->kind == CS_Y_SCALAR ? n->text : NULL;
}

/* A grid entry of v: a list of values, or {from, to, step | count}; errors into s. */
void cs_sweep_read_grid(cs_sweep_spec *s, cs_units *u, cs_sweep_var *v, const cs_ynode *e);
/* A distribution entry of v {dist, mean, sd, min, max}; errors into s. */
void cs_sweep_read_dist(cs_sweep_spec *s, cs_units *u, cs_sweep_var *v, const cs_ynode *e);

#endif
