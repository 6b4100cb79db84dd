/* SPDX-License-Identifier: MIT */
/* A study's own figures and page, whatever its spec asks to plot: the probability of each outcome with
 * its 95% Wilson interval; for each response (the 50-ms deceleration, the penetration, the barrier's
 * deflection, the working width, the largest rope tension, the penetration beyond the runs not held, the
 * exit speed) that a run has a value of, a histogram of the runs, a tornado chart of the inputs' Spearman
 * rank correlations with it, and the runs against the input most correlated with it; and report.html,
 * one page that opens from disk with the study's tables and these figures. Only the runs that ran to their
 * end count. */
#ifndef CS_STUDYREPORT_H
#define CS_STUDYREPORT_H

#include <stdio.h>

#include "out/plot.h"
#include "study/sweep.h"

enum { CS_STUDY_RESPONSES = 7, CS_STUDY_FIGURES = 1 + 3 * CS_STUDY_RESPONSES };

/* Figure k's file, "plots/study-<what>.png". */
void cs_study_figure_file(int k, char *buf, size_t size);
/* Whether figure k is drawn: the outcomes always, a response's figures when a run has a value of it. */
int cs_study_figure_shown(int k, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                          long n);
/* Draw figure k of the runs to f. CS_OK, or CS_ERR_MEMORY or cs_plot_write's status with err filled. */
cs_status cs_study_write_figure(FILE *f, cs_plot_format format, int k, const cs_sweep_spec *spec,
                                const double *x, const cs_sweep_result *r, long n, cs_error *err);
/* report.html: the study's outcome and response tables and every figure inline. CS_OK, or CS_ERR_MEMORY or
 * cs_html_figure's status with err filled. */
cs_status cs_study_write_page(FILE *f, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                              long n, cs_error *err);

#endif
