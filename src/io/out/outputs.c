/* SPDX-License-Identifier: MIT */
/* A run's output folder: the data files, the plots and whatever the caller adds, written beside their
 * names and committed together (outfile.h), or none of them; and the interface's writers (output.h). */
#include <stdlib.h>

#include "figures.h"
#include "plot.h"
#include "status.h"
#include "writers.h"

/* DIR/plots/<figure>.png and .svg, begun on out. */
static int write_plots(cs_outdir *out, const cs_model_input *in, const cs_state *state, const cs_record *rec,
                       const cs_run_info *info, char *why, size_t why_size) {
    int n = cs_state_event_count(state);
    cs_event *events = malloc((size_t)(n > 0 ? n : 1) * sizeof *events);
    if (!events) {
        snprintf(why, why_size, "out of memory");
        return -1;
    }
    for (int i = 0; i < n; i++) {
        events[i].size = sizeof events[i];
        cs_state_event(state, i, &events[i], NULL);
    }
    static const cs_plot_format formats[] = {CS_PLOT_PNG, CS_PLOT_SVG};
    int box = info && info->motion && info->criteria_count > 0;
    cs_figure_data d = {
        in, rec, events, n, box ? &info->exit_box : NULL, box ? info->criteria_test.standard : NULL};
    int rc = cs_figures_write(out, "plots", formats, 2, &d, why, why_size);
    cs_plot_release();
    free(events);
    return rc;
}

int cs_write_run_files(cs_outdir *out, const cs_model_input *in, const cs_model *model, const cs_state *state,
                       const cs_record *rec, const cs_run_info *info, int flags, cs_more_outputs more,
                       void *user, char *why, size_t why_size) {
    if (rec->failed) {
        snprintf(why, why_size, "the record lost frames: memory ran short while recording");
        return -1;
    }
    static const char *const names[] = {"timeseries.csv", "events.csv", "summary.json"};
    int rc = 0;
    cs_error err = {CS_OK, ""};
    for (int k = 0; rc == 0 && k < 3; k++) {
        FILE *f = cs_out_begin(out, names[k], &err);
        if (!f) return cs_status_why(err.status, &err, why, why_size);
        rc = k == 0   ? cs_timeseries_csv(f, rec, why, why_size)
             : k == 1 ? cs_events_csv(f, state, why, why_size)
                      : cs_write_summary_json_with(f, in, model, state, info, why, why_size);
        if (cs_out_finish(out, f, rc ? CS_ERR_IO : CS_OK, &err) != CS_OK) {
            cs_status_why(err.status, &err, why, why_size); /* the file's error, else the writer's */
            rc = -1;
        }
    }
    if (rc == 0 && (flags & CS_OUTPUT_PLOTS)) rc = write_plots(out, in, state, rec, info, why, why_size);
    if (rc == 0 && more) rc = more(out, user, why, why_size);
    return rc;
}

cs_status cs_write_outputs(const char *dir, const cs_model_input *in, const cs_model *model,
                           const cs_state *state, const cs_record *rec, int flags, cs_error *err) {
    if (cs_status_input(in, err) != CS_OK) return CS_ERR_INVALID;
    char why[CS_MESSAGE_SIZE];
    size_t why_size = sizeof why;
    cs_outdir out;
    cs_run_info info;
    cs_run_info_of(&info, in, state);
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(state, &sm, NULL);
    cs_run_info_motion(&info, in, rec, &sm);
    cs_status st = cs_out_open(&out, dir, 0, err);
    if (st == CS_OK &&
        cs_write_run_files(&out, in, model, state, rec, &info, flags, NULL, NULL, why, why_size) != 0)
        st = cs_status_set(err, CS_ERR_IO, why);
    if (st == CS_OK) st = cs_out_commit(&out, err);
    if (st != CS_OK) cs_out_abort(&out);
    return st == CS_OK ? cs_status_set(err, CS_OK, NULL) : st;
}

cs_status cs_write_timeseries(FILE *f, const cs_record *rec, cs_error *err) {
    char why[CS_MESSAGE_SIZE];
    return cs_status_set(err, cs_timeseries_csv(f, rec, why, sizeof why) ? CS_ERR_IO : CS_OK, why);
}

cs_status cs_write_events(FILE *f, const cs_state *state, cs_error *err) {
    char why[CS_MESSAGE_SIZE];
    return cs_status_set(err, cs_events_csv(f, state, why, sizeof why) ? CS_ERR_IO : CS_OK, why);
}

cs_status cs_write_summary_json(FILE *f, const cs_model_input *in, const cs_model *model,
                                const cs_state *state, cs_error *err) {
    if (cs_status_input(in, err) != CS_OK) return CS_ERR_INVALID;
    cs_run_info info;
    cs_run_info_of(&info, in, state);
    char why[CS_MESSAGE_SIZE];
    int rc = cs_write_summary_json_with(f, in, model, state, &info, why, sizeof why);
    return cs_status_set(err, rc ? CS_ERR_IO : CS_OK, why);
}
