/* SPDX-License-Identifier: MIT */
/* A run's recorded frames (cablesim/output.h's cs_record), collected through cs_run's output callback;
 * the input of every writer (CSV, JSON, plots, report). Growing the arrays happens here, outside the
 * engine's step. The record holds at most CS_RECORD_BYTES: when it is full it keeps every other frame and
 * records every other output from then on (the last frame, the run's end, is always kept), so a long
 * run's memory is bounded by the model, not by the run. Its first arrays hold the frames the scenario can
 * give (t_end over the output interval, at most CS_RECORD_FIRST_BYTES), so that a run to its end is
 * recorded without copying the frames to larger arrays: memory that is not written costs nothing, and
 * a copy writes pages the process has not touched yet (each a page fault). */
#ifndef CS_RECORD_H
#define CS_RECORD_H

#include "cablesim/output.h"

#define CS_RECORD_BYTES (256.0 * 1024 * 1024)
#define CS_RECORD_FIRST_BYTES (64.0 * 1024 * 1024)

/* A post as timeseries.csv writes it. */
typedef struct cs_post_state {
    cs_post_status status;
    double tilt;
} cs_post_state;

struct cs_record {
    int cable_count;
    int post_count;
    int max_nodes; /* path points kept per cable and frame (0: no paths, CS_RECORD_FILES) */
    int frame_count;
    int capacity;
    int failed;                 /* an allocation failed; frames after it were dropped */
    int lean;                   /* CS_RECORD_FILES: no paths, posts as post_states */
    int max_frames;             /* frames CS_RECORD_BYTES holds */
    int first_frames;           /* the frames of the first arrays: the scenario's, up to max_frames */
    long stride;                /* outputs per frame kept (1, doubled each time the record fills) */
    long calls;                 /* outputs offered so far */
    cs_vehicle_view *vehicle;   /* [frame] */
    cs_energy *energy;          /* [frame] */
    cs_cable_view *cables;      /* [frame * cable_count + c] */
    cs_post_view *posts;        /* [frame * post_count + p]; NULL in a record of CS_RECORD_FILES */
    cs_post_state *post_states; /* [frame * post_count + p], in place of posts in one of CS_RECORD_FILES */
    cs_anchor_view *anchors;    /* [frame * 2 + a] */
    int *path_count;            /* [frame * cable_count + c]; with the two below NULL without paths */
    double *path_xyz;           /* [(frame * cable_count + c) * max_nodes * 3] */
    double *path_tension;       /* [(frame * cable_count + c) * max_nodes] */
};

/* What a record holds: CS_RECORD_ALL, every view of each frame (the plots and report.html draw from
 * them); CS_RECORD_FILES, only what timeseries.csv, events.csv and summary.json are written from: no
 * cables' paths (cs_record_cable_path gives 0 points) and of each post its status and tilt
 * (post_states; cs_record_post gives NULL): 976 of an APS3 frame's 3,800 bytes. */
typedef enum cs_record_kind { CS_RECORD_ALL, CS_RECORD_FILES } cs_record_kind;

/* Prepare an empty record held by the caller (cs_record_create allocates one): CS_RECORD_ALL. Returns 0,
 * or -1 if memory is short. */
int cs_record_init(cs_record *rec, const cs_model *model);
/* The same, of the kind given. */
int cs_record_init_for(cs_record *rec, const cs_model *model, cs_record_kind kind);

/* Frame f's post p as timeseries.csv writes it, from either kind of record. */
static inline cs_post_state cs_record_post_state(const cs_record *rec, int f, int p) {
    size_t k = (size_t)f * (size_t)rec->post_count + (size_t)p;
    if (rec->post_states) return rec->post_states[k];
    return (cs_post_state){rec->posts[k].status, rec->posts[k].tilt};
}
/* Free the frames of a record from cs_record_init, leaving it empty. */
void cs_record_release(cs_record *rec);

#endif
