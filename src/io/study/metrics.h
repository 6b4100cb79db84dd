/* SPDX-License-Identifier: MIT */
/* Validation metrics of a computed time history against a measured one, as NCHRP Web-Only Document 179
 * (and its program RSVVP) defines them: the Sprague-Geers magnitude, phase and comprehensive errors and
 * the ANOVA mean and standard deviation of the residuals, with W179's acceptance limits
 * (docs/ratings.md, "Validation metrics"). Pure functions of paired samples. */
#ifndef CS_METRICS_H
#define CS_METRICS_H

#include <stddef.h>

typedef struct cs_validation_metrics {
    size_t n;       /* samples paired */
    double m, p, c; /* Sprague-Geers magnitude, phase, comprehensive error (fractions: 0.1 is 10%) */
    double mean;    /* mean residual (computed - measured) over the measured's peak |value| */
    double std;     /* standard deviation of the residuals (n - 1) over the measured's peak |value| */
} cs_validation_metrics;

/* W179's acceptance limits: |M| and |P| at most 40%, |mean| at most 5%, std at most 35%. */
#define CS_W179_SG_LIMIT 0.40
#define CS_W179_MEAN_LIMIT 0.05
#define CS_W179_STD_LIMIT 0.35

/* The metrics of computed c against measured m, paired samples equally spaced in time. Returns 0, or -1
 * if n < 2 or either history is all zero (no magnitude to compare). */
int cs_validation_metrics_of(const double *m, const double *c, size_t n, cs_validation_metrics *out);

/* Whether metrics meet every W179 limit. */
int cs_validation_metrics_pass(const cs_validation_metrics *v);

/* The computed history (tc, yc: nc samples) at the measured's times tm (nm samples) by linear
 * interpolation, over the span both cover, into cm and the measured's own values into mm (each nm long
 * at most); the count paired. */
size_t cs_validation_pair(const double *tm, const double *ym, size_t nm, const double *tc, const double *yc,
                          size_t nc, double *mm, double *cm);

#endif
