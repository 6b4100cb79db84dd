/* SPDX-License-Identifier: MIT */
/* Banded LU with partial pivoting (band.h). The loops walk from the diagonal entry d = A(k, k): along
 * row k by d[j - k], down column k by steps of width - 1. */
#include "core/band.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int cs_band_init(cs_band *b, size_t entries, int rows) {
    memset(b, 0, sizeof *b);
    b->a = calloc(entries ? entries : 1, sizeof *b->a);
    b->pivot = calloc((size_t)(rows > 0 ? rows : 1), sizeof *b->pivot);
    b->capacity = entries;
    return b->a && b->pivot ? 0 : -1;
}

void cs_band_free(cs_band *b) {
    free(b->a), free(b->pivot);
    memset(b, 0, sizeof *b);
}

int cs_band_shape(cs_band *b, int n, int kl, int ku) {
    int width = 2 * kl + ku + 1;
    if ((size_t)n * (size_t)width > b->capacity) return -1;
    b->n = n, b->kl = kl, b->ku = ku, b->width = width;
    memset(b->a, 0, (size_t)n * (size_t)width * sizeof *b->a);
    return 0;
}

int cs_band_factor(cs_band *b) {
    int n = b->n, kl = b->kl, ku = b->ku;
    ptrdiff_t down = b->width - 1;
    for (int k = 0; k < n; k++) {
        int last = k + kl < n - 1 ? k + kl : n - 1, p = k;
        double *d = cs_band_entry(b, k, k), best = fabs(d[0]);
        for (int i = k + 1; i <= last; i++)
            if (fabs(d[(i - k) * down]) > best) best = fabs(d[(i - k) * down]), p = i;
        b->pivot[k] = p;
        if (best == 0.0) return -1;
        int width = (k + ku + kl < n - 1 ? k + ku + kl : n - 1) - k; /* row k's entries right of d */
        if (p != k)
            for (double *dp = d + (p - k) * down, *e = d; e <= d + width; e++, dp++) {
                double t = *e;
                *e = *dp;
                *dp = t;
            }
        double inv = 1.0 / d[0];
        for (int i = k + 1; i <= last; i++) {
            double *di = d + (i - k) * down, f = di[0] * inv;
            di[0] = f;
            if (f != 0.0)
                for (int j = 1; j <= width; j++)
                    di[j] -= f * d[j];
        }
    }
    return 0;
}

void cs_band_solve(const cs_band *b, double *x) {
    int n = b->n, kl = b->kl, ku = b->ku;
    ptrdiff_t down = b->width - 1;
    for (int k = 0; k < n; k++) {
        int p = b->pivot[k];
        if (p != k) {
            double t = x[k];
            x[k] = x[p];
            x[p] = t;
        }
        int last = k + kl < n - 1 ? k + kl : n - 1;
        const double *l = b->a + (size_t)k * (size_t)b->width + (size_t)kl;
        double xk = x[k];
        for (int i = k + 1; i <= last; i++)
            x[i] -= *(l += down) * xk;
    }
    for (int k = n - 1; k >= 0; k--) {
        int width = (k + ku + kl < n - 1 ? k + ku + kl : n - 1) - k;
        const double *d = b->a + (size_t)k * (size_t)b->width + (size_t)kl;
        double sum = 0.0;
        for (int j = 1; j <= width; j++)
            sum += d[j] * x[k + j];
        x[k] = (x[k] - sum) / d[0];
    }
}
