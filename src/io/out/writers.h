/* SPDX-License-Identifier: MIT */
/* Inside the writers of a run's outputs (cablesim/output.h): printing numbers that must be finite, the
 * JSON documents' parts, and the output folder with files added by the command (report.html). */
#ifndef CS_WRITERS_H
#define CS_WRITERS_H

#include <stdio.h>

#include "cablesim/loader.h"
#include "cablesim/output.h"
#include "outfile.h"
#include "record.h"
#include "study/criteria.h"
#include "study/occupant.h"
#include "study/rating.h"

/* What a run's outputs record beside its results: where they came from (this cablesim's version,
 * CS_VERSION_STRING, is written with them), and the run's designations as run. */
typedef struct cs_run_info {
    const char *command;          /* the command line, shell-quoted */
    const char *const *overrides; /* --set, --dt, --t-end as given, in order: "--set PATH=VALUE" */
    int override_count;
    unsigned long long model_hash; /* cs_model_input_hash */
    cs_rating ratings[2];          /* ASTM F2656, SD-STD-02.01: those whose test vehicle the run's is */
    int rating_count;
    /* from the run's record (cs_run_info_motion); motion 0 when there was none to read */
    int motion;
    int occupant_at; /* the occupant risk at occupant_point (m from the CG, the vehicle's axes), not
                        at the CG (set before cs_run_info_motion) */
    double occupant_point[3];
    int occupant_ok;           /* occupant computed; else occupant_error says why not */
    cs_occupant_risk occupant; /* at the CG (or occupant_point), from the first contact (study/occupant.h) */
    cs_error occupant_error;
    double roll_peak, pitch_peak; /* largest |roll| and |pitch| of the run, rad */
    int criteria_count; /* of the roadside test the run stands for (cs_roadside_test_as_run); 0 none */
    cs_roadside_test criteria_test;
    cs_criterion criteria[CS_CRITERIA_MAX];
    cs_exit_box exit_box; /* MASH's, of a run that stands for a roadside test (criteria_count > 0) */
} cs_run_info;

/* The ratings of a run as run into info (cs_rate_as_run): ASTM F2656 if its vehicle is one of that
 * standard's, and SD-STD-02.01 too for the 15,000-lb truck. */
void cs_run_info_rate(cs_run_info *info, const cs_model_input *in, const cs_summary *summary);
/* The occupant risk, the roll and pitch peaks and the roadside criteria as run (if the run stands for a
 * roadside test) of a run's record and its state at the end (its events) into info. */
void cs_run_info_motion(cs_run_info *info, const cs_model_input *in, const cs_record *rec,
                        const cs_state *state, const cs_summary *summary);
/* The record of a run written through the library (cs_write_outputs): no command line or overrides, its
 * model hash and its designations as run. */
void cs_run_info_of(cs_run_info *info, const cs_model_input *in, const cs_state *state);
/* The model hash as written: 16 hexadecimal digits. */
void cs_model_hash_text(unsigned long long hash, char buf[17]);
/* Up to max post indices of the model by distance from its impact point, nearest first; the count. */
int cs_nearest_posts(const cs_model_input *in, int *idx, int max);

typedef struct cs_wout {
    FILE *f;
    int bad;       /* a non-finite number was met */
    char why[256]; /* where */
} cs_wout;

/* Whether v is finite (and w not already bad): if not, w is marked bad, its why naming what. */
int cs_w_finite(cs_wout *w, double v, const char *what);
/* w marked bad (if it is not already), its why: what ran out of memory. */
void cs_w_oom(cs_wout *w, const char *what);
/* CS_OK if w is not bad, else CS_ERR_IO with err "FILE: what" (file names the output, "summary.json"). */
cs_status cs_w_status(const cs_wout *w, const char *file, cs_error *err);
/* Print v as %.10g would (cs_g10); a non-finite v is not printed and marks the output bad, naming what. */
void cs_w_num(cs_wout *w, double v, const char *what);
struct json_object;
/* The object of "cablesim" in summary.json and report.html: {"version", "command", "overrides",
 * "model_hash"} (info NULL: the version alone, the rest null or empty), made with json-c (jsondoc.h). */
struct json_object *cs_json_provenance(const cs_run_info *info);
/* The evaluation of a run as summary.json and report.html give it, as members added to to:
 * "occupant_risk" (or null and "occupant_risk_note"), "max_roll_deg", "max_pitch_deg" and
 * "roadside_criteria" (with MASH's "exit_box"; null for a run that is no roadside test), numbers as cs_w_num
 * (w marked bad by a non-finite one) (docs/ratings.md); with line_breaks (summary.json) a line break after
 * the occupant risk's members and after the criteria. report.html's data has none: its units are read off
 * its values, which a line break's wrapper hides (jsondoc.h). */
void cs_json_evaluation(cs_wout *w, struct json_object *to, const cs_run_info *info, int line_breaks);
/* A number of a JSON document as its writer writes them, what naming it; NULL (null) and w marked bad if
 * v is not finite. */
typedef struct json_object *(*cs_jnum_fn)(cs_wout *w, double v, const char *what);
/* Every cable's peak tension and work on the vehicle ("cables") and the sudden losses
 * ("sudden_loss_count", "sudden_losses"; cs_summary's, each of them) as members added to to, as
 * summary.json and report.html give them, each number made by number. */
void cs_json_cables_and_losses(cs_wout *w, struct json_object *to, const cs_state *state, const cs_summary *s,
                               cs_jnum_fn number);

/* More files to write into a run's folder before it commits (the command's report.html): each begun on
 * out. Returns CS_OK, or a failure's status with err filled. */
typedef cs_status (*cs_more_outputs)(cs_outdir *out, void *user, cs_error *err);
/* A run's files into out (opened, not yet committed): timeseries.csv, events.csv, summary.json (with
 * info), the plots with CS_OUTPUT_PLOTS, then more (may be NULL); the commit lists them in the folder's
 * manifest (outfile.h). Returns CS_OK, or a failure's status with err filled (out then to be aborted):
 * CS_ERR_IO for a file, a non-finite number or a record that lost frames, CS_ERR_MEMORY. */
cs_status cs_write_run_files(cs_outdir *out, const cs_model_input *in, const cs_model *model,
                             const cs_state *state, const cs_record *rec, const cs_run_info *info, int flags,
                             cs_more_outputs more, void *user, cs_error *err);
/* timeseries.csv and events.csv (output.h's cs_write_timeseries and cs_write_events), and summary.json
 * with info (may be NULL: no provenance, no ratings); each returns CS_OK, or CS_ERR_IO with err filled
 * naming the file and the first non-finite number, or CS_ERR_MEMORY. */
cs_status cs_timeseries_csv(FILE *f, const cs_record *rec, cs_error *err);
cs_status cs_events_csv(FILE *f, const cs_state *state, cs_error *err);
cs_status cs_write_summary_json_with(FILE *f, const cs_model_input *in, const cs_model *model,
                                     const cs_state *state, const cs_run_info *info, cs_error *err);
/* summary.json's document (json-c, jsondoc.h; to put), or NULL with err filled (CS_ERR_IO: a non-finite
 * number where one must be finite; CS_ERR_MEMORY). */
struct json_object *cs_summary_json(const cs_model_input *in, const cs_model *model, const cs_state *state,
                                    const cs_run_info *info, cs_error *err);
/* The readable summary (SI and US units side by side): the outcome, the model's hash, the response
 * parameters, the designations as run, the failure events in order and the yielding posts counted. */
void cs_write_summary_text_with(FILE *f, const cs_model_input *in, const cs_model *model,
                                const cs_state *state, const cs_run_info *info);

#endif
