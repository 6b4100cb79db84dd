/* SPDX-License-Identifier: MIT */
/* A run's output folder: the data files, the plots and whatever the caller adds, written beside their
 * names and committed together (outfile.h), or none of them; and the interface's writers (output.h). */
#include <stdlib.h>

#include "figures.h"
#include "plot.h"
#include "status.h"
#include "writers.h"

/* DIR/plots/<figure>.png and .svg, begun on out. */
static cs_status write_plots(cs_outdir *out, const cs_model_input *in, const cs_state *state,
                             const cs_record *rec, const cs_run_info *info, cs_error *err) {
    int n = cs_state_event_count(state);
    cs_event *events = malloc((size_t)(n > 0 ? n : 1) * sizeof *events);
    if (!events) return cs_status_set(err, CS_ERR_MEMORY, "out of memory");
    for (int i = 0; i < n; i++) {
        events[i].size = sizeof events[i];
        cs_state_event(state, i, &events[i], NULL);
    }
    static const cs_plot_format formats[] = {CS_PLOT_PNG, CS_PLOT_SVG};
    int box = info && info->motion && info->criteria_count > 0;
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(state, &sm, NULL);
    cs_figure_data d = {
        in, rec, events, n, box ? &info->exit_box : NULL, box ? info->criteria_test.standard : NULL, &sm};
    cs_status st = cs_figures_write(out, "plots", formats, 2, &d, err);
    cs_plot_release();
    free(events);
    return st;
}

cs_status cs_write_run_files(cs_outdir *out, const cs_model_input *in, const cs_model *model,
                             const cs_state *state, const cs_record *rec, const cs_run_info *info, int flags,
                             cs_more_outputs more, void *user, cs_error *err) {
    if (rec->failed)
        return cs_status_set(err, CS_ERR_IO, "the record lost frames: memory ran short while recording");
    static const char *const names[] = {"timeseries.csv", "events.csv", "summary.json"};
    cs_status st = CS_OK;
    for (int k = 0; st == CS_OK && k < 3; k++) {
        FILE *f = cs_out_begin(out, names[k], err);
        if (!f) return err ? err->status : CS_ERR_IO;
        st = k == 0   ? cs_timeseries_csv(f, rec, err)
             : k == 1 ? cs_events_csv(f, state, err)
                      : cs_write_summary_json_with(f, in, model, state, info, err);
        st = cs_out_finish(out, f, st, err);
    }
    if (st == CS_OK && (flags & CS_OUTPUT_PLOTS)) st = write_plots(out, in, state, rec, info, err);
    if (st == CS_OK && more) st = more(out, user, err);
    return st;
}

cs_status cs_write_outputs(const char *dir, const cs_model_input *in, const cs_model *model,
                           const cs_state *state, const cs_record *rec, int flags, cs_error *err) {
    if (cs_status_input(in, err) != CS_OK) return CS_ERR_INVALID;
    cs_outdir out;
    cs_run_info info;
    cs_run_info_of(&info, in, state);
    cs_summary sm = {.size = sizeof sm};
    cs_state_summary(state, &sm, NULL);
    cs_run_info_motion(&info, in, rec, state, &sm);
    cs_status st = cs_out_open(&out, dir, "run", 0, NULL, err); /* the interface has no way to force */
    if (st == CS_OK) st = cs_write_run_files(&out, in, model, state, rec, &info, flags, NULL, NULL, err);
    if (st == CS_OK) st = cs_out_commit(&out, err);
    if (st != CS_OK) cs_out_fail(&out, st, err);
    return st == CS_OK ? cs_status_set(err, CS_OK, NULL) : st;
}

cs_status cs_write_timeseries(FILE *f, const cs_record *rec, cs_error *err) {
    cs_status st = cs_timeseries_csv(f, rec, err);
    return st == CS_OK ? cs_status_set(err, CS_OK, NULL) : st;
}

cs_status cs_write_events(FILE *f, const cs_state *state, cs_error *err) {
    cs_status st = cs_events_csv(f, state, err);
    return st == CS_OK ? cs_status_set(err, CS_OK, NULL) : st;
}

cs_status cs_write_summary_json(FILE *f, const cs_model_input *in, const cs_model *model,
                                const cs_state *state, cs_error *err) {
    if (cs_status_input(in, err) != CS_OK) return CS_ERR_INVALID;
    cs_run_info info;
    cs_run_info_of(&info, in, state);
    cs_status st = cs_write_summary_json_with(f, in, model, state, &info, err);
    return st == CS_OK ? cs_status_set(err, CS_OK, NULL) : st;
}
