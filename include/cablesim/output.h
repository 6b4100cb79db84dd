/* SPDX-License-Identifier: MIT */
/** @file
 * A run's time histories and its output files. A record collects the state at every output of cs_run
 * (pass cs_record_frame and the record to it); the writers turn a record, a state and a loaded model into
 * the files `cablesim run` writes: timeseries.csv, events.csv, summary.json and the plots. A writer never
 * prints NaN or infinity: it stops at the first one and says where it was (CS_ERR_IO). */
#ifndef CABLESIM_OUTPUT_H
#define CABLESIM_OUTPUT_H

#include <stddef.h>
#include <stdio.h>

#include "cablesim/loader.h"
#include "cablesim/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A run's recorded frames (opaque). It holds at most 256 MB: when full it keeps every other frame and
 * records every other output from then on (the run's end is always kept), so its memory is bounded by
 * the model, not by the run's length. */
typedef struct cs_record cs_record;

/** An empty record for a model's runs.
 * @return the record, or NULL with err filled (CS_ERR_MEMORY). */
CS_API cs_record *cs_record_create(const cs_model *model, cs_error *err);
/** Free a record. NULL is allowed. */
CS_API void cs_record_free(cs_record *rec);
/** A cs_output_fn for cs_run: append the state as a frame; user is the cs_record. */
CS_API void cs_record_frame(const cs_model *model, const cs_state *state, void *user);
/** 1 if every frame offered was kept or thinned as designed, 0 if memory ran short and frames were lost
 * (the writers then should not be trusted). */
CS_API int cs_record_ok(const cs_record *rec);
/** The number of frames held, in time order. */
CS_API int cs_record_frame_count(const cs_record *rec);
/** The vehicle at a frame (its t is the frame's time), or NULL if frame is out of range. */
CS_API const cs_vehicle_view *cs_record_vehicle(const cs_record *rec, int frame);
/** The energy ledger at a frame, or NULL if frame is out of range. */
CS_API const cs_energy *cs_record_energy(const cs_record *rec, int frame);
/** A cable at a frame, or NULL if frame or cable is out of range. */
CS_API const cs_cable_view *cs_record_cable(const cs_record *rec, int frame, int cable);
/** A post at a frame, or NULL if frame or post is out of range. */
CS_API const cs_post_view *cs_record_post(const cs_record *rec, int frame, int post);
/** An anchor at a frame (0 the start, 1 the end), or NULL if out of range. */
CS_API const cs_anchor_view *cs_record_anchor(const cs_record *rec, int frame, int anchor);
/** A cable's path at a frame.
 * @param rec the record
 * @param frame the frame
 * @param cable the cable
 * @param xyz set to its points, x, y and z each, m
 * @param tension set to its spans' tensions (one fewer than the points), N
 * @return the number of points, or -1 if frame or cable is out of range. */
CS_API int cs_record_cable_path(const cs_record *rec, int frame, int cable, const double **xyz,
                                const double **tension);

/** timeseries.csv: a row per frame, the vehicle, cables, posts, anchors and the ledger, units in the
 * header's names (t_s, x_m, decel_50ms_g, cable0_max_tension_n ...).
 * @return CS_OK, or CS_ERR_IO with err filled. */
CS_API cs_status cs_write_timeseries(FILE *f, const cs_record *rec, cs_error *err);
/** events.csv: the failure sequence, a row per event (t_s, type, element_kind, element, value_si).
 * @return CS_OK, or CS_ERR_IO with err filled. */
CS_API cs_status cs_write_events(FILE *f, const cs_state *state, cs_error *err);
/** summary.json: the response parameters (the fields of cs_summary by the same names), the anchors, the
 * events and the resolved inputs in SI under "inputs".
 * @return CS_OK, or CS_ERR_IO with err filled (CS_ERR_INVALID: an input whose size does not reach its
 *         scenario; CS_ERR_MEMORY: memory ran out). */
CS_API cs_status cs_write_summary_json(FILE *f, const cs_model_input *in, const cs_model *model,
                                       const cs_state *state, cs_error *err);
/** The readable summary `cablesim run` prints: the outcome, the response parameters in SI with US units
 * beside, and the first events (for an input whose size does not reach its scenario, the line saying so). */
CS_API void cs_write_summary_text(FILE *f, const cs_model_input *in, const cs_model *model,
                                  const cs_state *state);

/** Flags of cs_write_outputs. */
enum cs_output_flags {
    CS_OUTPUT_PLOTS = 1 /**< also plots/NAME.png and plots/NAME.svg: the run's figures (cairo) */
};

/** Write a run's outputs into a folder, as `cablesim run -o DIR` does: timeseries.csv, events.csv,
 * summary.json and, with CS_OUTPUT_PLOTS, the plots. The folder (and its parents) are created; every file
 * is written beside its final name and renamed once all are complete, so a failure leaves nothing new (but
 * for an earlier run's file that cannot be removed once they are in place: see the return).
 * The folder keeps the rule of `cablesim run` without --force: a folder holding a file that no run's
 * DIR/.cablesim-manifest lists (with the size and hash it was written with) is refused, and only the files
 * of the earlier manifest, as written, are removed.
 * @param dir the folder
 * @param in the loaded model
 * @param model the model that ran
 * @param state the state at the run's end
 * @param rec its record
 * @param flags 0 or CS_OUTPUT_PLOTS
 * @param err filled on failure (may be NULL)
 * @return CS_OK, or CS_ERR_IO with err filled: "nothing written: " and why (a record that lost frames, a
 *         folder refused, a file that could not be written), or, when the files are in place but an earlier
 *         run's file there could not be removed, "the new results are in DIR, but ..." naming it and why (it
 *         stays in the manifest, for the next run there to remove), or, when a rename failed and the system
 *         refused to take back those before it, "DIR/NAME: why; DIR holds this run's NAME2 (and N more), the
 *         rest as before the command: run it again to write them all";
 *         CS_ERR_INVALID for an input whose size does not reach its scenario or a folder's path too long;
 *         CS_ERR_MEMORY when memory runs out. */
CS_API cs_status cs_write_outputs(const char *dir, const cs_model_input *in, const cs_model *model,
                                  const cs_state *state, const cs_record *rec, int flags, cs_error *err);

#ifdef __cplusplus
}
#endif
#endif
