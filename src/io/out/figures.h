/* SPDX-License-Identifier: MIT */
/* The figures of a run, drawn from its recorded frames and its events with the plotting layer (plot.h):
 * deceleration, speed, penetration, cable tensions, the posts nearest the impact, the energy ledger, a
 * strip of top and side snapshots, the vehicle's roll, pitch and yaw, and its path in plan with MASH's
 * exit box. */
#ifndef CS_FIGURES_H
#define CS_FIGURES_H

#include "cablesim/loader.h"
#include "outfile.h"
#include "plot.h"
#include "record.h"
#include "study/criteria.h"

/* What a figure reads: the resolved model (name, barrier, vehicle, scenario), the frames, the events,
 * the exit box of a run that stands for a roadside test (NULL: none; the path is drawn without it), with
 * the standard that test is of ("mash", "nchrp-350"), and the run's summary (NULL: none), whose largest
 * 50-ms deceleration and its time the deceleration's figure marks, as every other output gives them (the
 * frames, every output interval, can miss the step it peaked at). */
typedef struct cs_figure_data {
    const cs_model_input *in;
    const cs_record *rec;
    const cs_event *events;
    int event_count;
    const cs_exit_box *exit_box;
    const char *standard;
    const cs_summary *summary;
} cs_figure_data;

typedef enum cs_figure {
    CS_FIG_DECELERATION = 0,
    CS_FIG_SPEED,
    CS_FIG_PENETRATION,
    CS_FIG_CABLES,
    CS_FIG_POSTS,
    CS_FIG_ENERGY,
    CS_FIG_SNAPSHOTS,
    CS_FIG_ANGLES,
    CS_FIG_PATH,
    CS_FIG_COUNT
} cs_figure;

/* The figure's file stem: "deceleration", "speed", "penetration", "cables", "posts", "energy",
 * "snapshots", "angles", "path". */
const char *cs_figure_name(cs_figure figure);
/* Its size in device units (the snapshots' height follows the geometry of the run). */
void cs_figure_size(cs_figure figure, const cs_figure_data *d, double *width, double *height);
/* Draw one figure to f. Returns CS_OK, or as cs_plot_write (CS_ERR_INVALID: no such figure, no file). */
cs_status cs_figure_write(FILE *f, cs_plot_format format, cs_figure figure, const cs_figure_data *d,
                          cs_error *err);
/* Draw one figure without writing it: log gets where its texts and panels went (cs_plot_trace). Returns
 * CS_OK, or as cs_plot_trace. */
cs_status cs_figure_trace(cs_figure figure, const cs_figure_data *d, cs_plot_log *log, cs_error *err);
/* Every figure in every format, as subdir/<name>.<ext> files begun and ended on out; cs_out_commit
 * then renames them together with the run's other outputs. Creates out's DIR/subdir. Returns CS_OK, or a
 * failure's status with err filled (a file's own error first: outfile.h's cs_out_finish). */
cs_status cs_figures_write(cs_outdir *out, const char *subdir, const cs_plot_format *formats,
                           int format_count, const cs_figure_data *d, cs_error *err);

#endif
