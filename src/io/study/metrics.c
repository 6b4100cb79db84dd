/* SPDX-License-Identifier: MIT */
/* Validation metrics (metrics.h): Sprague-Geers and ANOVA of the residuals, NCHRP W179. */
#include "metrics.h"

#include <math.h>

#include "cablesim/units.h"

int cs_validation_metrics_of(const double *m, const double *c, size_t n, cs_validation_metrics *out) {
    double mm = 0.0, cc = 0.0, mc = 0.0, peak = 0.0, sum = 0.0;
    out->n = n;
    if (n < 2) return -1;
    for (size_t i = 0; i < n; i++) {
        mm += m[i] * m[i], cc += c[i] * c[i], mc += m[i] * c[i];
        sum += c[i] - m[i];
        if (fabs(m[i]) > peak) peak = fabs(m[i]);
    }
    if (!(mm > 0.0) || !(cc > 0.0)) return -1;
    out->m = sqrt(cc / mm) - 1.0;
    double cosine = mc / sqrt(mm * cc);
    out->p = acos(cosine > 1.0 ? 1.0 : cosine < -1.0 ? -1.0 : cosine) / CS_PI;
    out->c = hypot(out->m, out->p);
    double mean = sum / (double)n, var = 0.0;
    for (size_t i = 0; i < n; i++)
        var += pow(c[i] - m[i] - mean, 2);
    out->mean = mean / peak;
    out->std = sqrt(var / (double)(n - 1)) / peak;
    return 0;
}

int cs_validation_metrics_pass(const cs_validation_metrics *v) {
    return fabs(v->m) <= CS_W179_SG_LIMIT && fabs(v->p) <= CS_W179_SG_LIMIT &&
           fabs(v->mean) <= CS_W179_MEAN_LIMIT && v->std <= CS_W179_STD_LIMIT;
}

size_t cs_validation_pair(const double *tm, const double *ym, size_t nm, const double *tc, const double *yc,
                          size_t nc, double *mm, double *cm) {
    size_t k = 0, j = 0;
    if (nc < 1) return 0;
    for (size_t i = 0; i < nm; i++) {
        double t = tm[i];
        if (t < tc[0] || t > tc[nc - 1]) continue;
        while (j + 1 < nc && tc[j + 1] < t)
            j++;
        double f = j + 1 < nc && tc[j + 1] > tc[j] ? (t - tc[j]) / (tc[j + 1] - tc[j]) : 0.0;
        f = f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f;
        mm[k] = ym[i];
        cm[k] = j + 1 < nc ? yc[j] + f * (yc[j + 1] - yc[j]) : yc[j];
        k++;
    }
    return k;
}
