/* SPDX-License-Identifier: MIT */
/* A run's recorded frames (cablesim/output.h's cs_record), collected through cs_run's output callback;
 * the input of every writer (CSV, JSON, plots, report). Growing the arrays happens here, outside the
 * engine's step. The record holds at most CS_RECORD_BYTES: when it is full it keeps every other frame and
 * records every other output from then on (the last frame, the run's end, is always kept), so a long
 * run's memory is bounded by the model, not by the run. */
#ifndef CS_RECORD_H
#define CS_RECORD_H

#include "cablesim/output.h"

#define CS_RECORD_BYTES (256.0 * 1024 * 1024)

struct cs_record {
    int cable_count;
    int post_count;
    int max_nodes; /* path points kept per cable and frame */
    int frame_count;
    int capacity;
    int failed;               /* an allocation failed; frames after it were dropped */
    int max_frames;           /* frames CS_RECORD_BYTES holds */
    long stride;              /* outputs per frame kept (1, doubled each time the record fills) */
    long calls;               /* outputs offered so far */
    cs_vehicle_view *vehicle; /* [frame] */
    cs_energy *energy;        /* [frame] */
    cs_cable_view *cables;    /* [frame * cable_count + c] */
    cs_post_view *posts;      /* [frame * post_count + p] */
    cs_anchor_view *anchors;  /* [frame * 2 + a] */
    int *path_count;          /* [frame * cable_count + c] */
    double *path_xyz;         /* [(frame * cable_count + c) * max_nodes * 3] */
    double *path_tension;     /* [(frame * cable_count + c) * max_nodes] */
};

/* Prepare an empty record held by the caller (cs_record_create allocates one). Returns 0, or -1 if memory
 * is short. */
int cs_record_init(cs_record *rec, const cs_model *model);
/* Free the frames of a record from cs_record_init, leaving it empty. */
void cs_record_release(cs_record *rec);

#endif
