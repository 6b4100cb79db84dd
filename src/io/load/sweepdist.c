/* SPDX-License-Identifier: MIT */
/* A sweep spec's distributions (sweepspec.h's cs_dist): the normal CDF and its inverse, the truncated
 * distribution's bounds (checked when the spec is read) and its quantiles (the runs' inputs, study/). */
#include <math.h>

#include "sweepspec.h"

double cs_normal_cdf(double x) {
    return 0.5 * erfc(-x / sqrt(2.0));
}

double cs_normal_quantile(double p) {
    if (!(p > 0)) return -HUGE_VAL;
    if (!(p < 1)) return HUGE_VAL;
    static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                               1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
    static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                               6.680131188771972e+01, -1.328068155288572e+01};
    static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                               -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
    static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                               3.754408661907416e+00};
    const double low = 0.02425;
    double x;
    if (p < low || p > 1 - low) {
        double q = sqrt(-2 * log(p < low ? p : 1 - p));
        x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
            ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
        if (p > 1 - low) x = -x;
    } else {
        double q = p - 0.5, r = q * q;
        x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
            (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
    }
    /* one Halley step on the exact CDF (erfc keeps the tails accurate) */
    double e = p < 0.5 ? cs_normal_cdf(x) - p : (1 - p) - 0.5 * erfc(x / sqrt(2.0));
    double u = e * 2.5066282746310002 * exp(x * x / 2); /* sqrt(2 pi) */
    return x - u / (1 + x * u / 2);
}

/* the untruncated CDF and quantile in standard units */
static double dist_std(const cs_dist *d, double x) {
    return d->kind == CS_DIST_LOGNORMAL ? (x > 0 ? (log(x) - d->a) / d->b : -HUGE_VAL) : (x - d->a) / d->b;
}

int cs_dist_prepare(cs_dist *d) {
    if (d->kind == CS_DIST_UNIFORM) {
        d->lo = d->a, d->hi = d->b;
        d->p_lo = 0, d->p_hi = 1;
        return d->a < d->b ? 0 : -1;
    }
    d->p_lo = isinf(d->lo) ? 0 : cs_normal_cdf(dist_std(d, d->lo));
    d->p_hi = isinf(d->hi) ? 1 : cs_normal_cdf(dist_std(d, d->hi));
    return d->p_hi > d->p_lo ? 0 : -1;
}

double cs_dist_quantile(const cs_dist *d, double u) {
    if (d->kind == CS_DIST_UNIFORM) return d->a + u * (d->b - d->a);
    double z = cs_normal_quantile(d->p_lo + u * (d->p_hi - d->p_lo));
    double x = d->kind == CS_DIST_LOGNORMAL ? exp(d->a + d->b * z) : d->a + d->b * z;
    return fmin(fmax(x, d->lo), d->hi);
}
