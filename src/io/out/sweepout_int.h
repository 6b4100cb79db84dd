/* SPDX-License-Identifier: MIT */
/* Inside the sweep's outputs: what sweepout.c (runs.csv, the summaries) and sweepread.c (runs.csv read
 * back) share. */
#ifndef CS_SWEEPOUT_INT_H
#define CS_SWEEPOUT_INT_H

#include "sweepout.h"

/* What a column reads from a result: the summary's values in runs.csv's order, the error, then one
 * count per event type (C_EVENTS + type). */
enum {
    C_OUTCOME,
    C_RATING,
    C_ASTM_PEN,
    C_SD_STD,
    C_T,
    C_DECEL,
    C_T_DECEL,
    C_PEN,
    C_BEYOND,
    C_DEFL,
    C_WIDTH,
    C_STOP,
    C_EXIT,
    C_EXIT_ANGLE,
    C_CONTACT,
    C_POSTS_LEFT,
    C_POSTS_RIGHT,
    C_CABLES,
    C_TENSION,
    C_KE,
    C_ENERGY,
    C_WARNINGS,
    C_RESIDUAL,
    C_X,
    C_Y,
    C_Z,
    C_ERROR,
    C_EVENTS
};

/* A column's heading in runs.csv's header: its name, and its unit in brackets ("max_50ms_decel [g]"); its
 * length, as snprintf's. */
int cs_sweep_column_heading(const cs_sweep_column *c, char *buf, size_t size);

#endif
