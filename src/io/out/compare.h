/* SPDX-License-Identifier: MIT */
/* Several runs, and a measured history, side by side (`cablesim compare`): overlays of the deceleration
 * (raw and 50-ms), the speed, the penetration and the largest rope tension against time, and a table of
 * the response parameters with each one's difference from the reference (the measured history if there
 * is one, else the first run). */
#ifndef CS_COMPARE_H
#define CS_COMPARE_H

#include <stddef.h>
#include <stdio.h>

#include "load/runread.h"
#include "out/outfile.h"
#include "out/plot.h"

enum { CS_COMPARE_PLOTS = 5 };

/* Draw plot k (of CS_COMPARE_PLOTS) as a PNG would be drawn, writing nothing: log gets where every text
 * and panel went (cs_plot_trace). Each plot's time axis runs from 0 (or the earliest start) to the
 * latest end of the traces it shows, not rounded out to a tick. CS_OK, or cs_plot_trace's status with err
 * filled. */
cs_status cs_compare_trace(int k, const cs_trace *traces, int count, int reference, cs_plot_log *log,
                           cs_error *err);
/* Into out: compare.csv and compare.md (the table), plots/compare-<response>.png and .svg, and
 * compare.html (the table and the plots in one page that opens from disk). traces[reference] is the
 * reference. CS_OK, or a failure's status with err filled (a file's: which one and the system's reason). */
cs_status cs_compare_write_traces(cs_outdir *out, const cs_trace *traces, int count, int reference,
                                  cs_error *err);
/* With a measured reference, cs_compare_write_traces also writes metrics.csv and a "Validation metrics" table
 * in compare.md and compare.html: each run's Sprague-Geers M, P, C and ANOVA mean and std of the residuals
 * against it (study/metrics.h), per response both give, and W179's verdict. This prints the same to f
 * (nothing without a measured reference). */
void cs_compare_print_trace_metrics(FILE *f, const cs_trace *traces, int count, int reference);

/* The table's response parameters (compare.csv's rows after the outcome), in its order: their count, name
 * ("max 50-ms deceleration") and SI unit ("g", "m"; NULL out of range), trace tr's value (NAN: not given)
 * and its difference from ref in per cent (NAN: either not given, a lower bound, or ref's 0), as
 * compare.csv writes them. */
int cs_compare_param_count(void);
const char *cs_compare_param_name(int k);
const char *cs_compare_param_unit(int k);
double cs_compare_param_value(const cs_trace *tr, int k);
double cs_compare_param_difference(const cs_trace *tr, const cs_trace *ref, int k);

#endif
