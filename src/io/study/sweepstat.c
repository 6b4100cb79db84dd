/* SPDX-License-Identifier: MIT */
/* The runs' inputs (counter-based random numbers, grids, Latin hypercubes; the distributions are the
 * spec's, load/sweepdist.c) and the statistics of the results (Wilson intervals, ranks, Spearman
 * correlation). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sweep.h"

/* ---- random numbers: a pure function of the key ---- */

static uint64_t mix64(uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

double cs_sweep_u01(uint64_t seed, uint64_t a, uint64_t b, uint64_t stream) {
    uint64_t h = mix64(mix64(mix64(mix64(seed) ^ a) ^ b) ^ stream);
    return ((double)(h >> 11) + 0.5) * 0x1p-53; /* in (0, 1): never 0 or 1 */
}

/* ---- the runs' inputs ---- */

double *cs_latin_hypercube(uint64_t seed, long n, int k) {
    double *u = malloc((size_t)(n > 0 ? n : 1) * (size_t)(k > 0 ? k : 1) * sizeof *u);
    long *perm = malloc((size_t)(n > 0 ? n : 1) * sizeof *perm);
    if (!u || !perm) {
        free(u);
        free(perm);
        return NULL;
    }
    for (int j = 0; j < k; j++) {
        /* Fisher-Yates with numbers keyed by (variable, step): stream 1 */
        for (long i = 0; i < n; i++)
            perm[i] = i;
        for (long i = n - 1; i > 0; i--) {
            long r = (long)(cs_sweep_u01(seed, (uint64_t)j, (uint64_t)i, 1) * (double)(i + 1));
            if (r > i) r = i;
            long t = perm[i];
            perm[i] = perm[r], perm[r] = t;
        }
        /* run i falls in stratum perm[i], at a point keyed by (run, variable): stream 2 */
        for (long i = 0; i < n; i++)
            u[i * k + j] = ((double)perm[i] + cs_sweep_u01(seed, (uint64_t)i, (uint64_t)j, 2)) / (double)n;
    }
    free(perm);
    return u;
}

int cs_sweep_grid_level(const cs_sweep_spec *s, long run, int var) {
    long rest = run;
    for (int j = s->var_count - 1; j > var; j--) /* the last variable varies fastest */
        rest /= s->vars[j].level_count;
    return (int)(rest % s->vars[var].level_count);
}

double *cs_sweep_samples(const cs_sweep_spec *s, long *run_count) {
    long n = s->runs;
    int k = s->var_count;
    *run_count = n;
    double *x = malloc((size_t)(n > 0 ? n : 1) * (size_t)(k > 0 ? k : 1) * sizeof *x);
    if (!x) return NULL;
    if (s->method == CS_SWEEP_GRID) {
        for (long i = 0; i < n; i++)
            for (int j = 0; j < k; j++) {
                const cs_sweep_var *v = &s->vars[j];
                int level = cs_sweep_grid_level(s, i, j);
                x[i * k + j] = v->numeric ? v->levels[level] : level;
            }
        return x;
    }
    double *u = NULL;
    if (s->method == CS_SWEEP_LATIN_HYPERCUBE && !(u = cs_latin_hypercube(s->seed, n, k))) {
        free(x);
        return NULL;
    }
    for (long i = 0; i < n; i++)
        for (int j = 0; j < k; j++) {
            double p = u ? u[i * k + j] : cs_sweep_u01(s->seed, (uint64_t)i, (uint64_t)j, 0);
            x[i * k + j] = cs_dist_quantile(&s->vars[j].dist, p);
        }
    free(u);
    return x;
}

void cs_sweep_value_text(const cs_sweep_var *v, double x, char *buf, size_t size) {
    if (!v->numeric)
        snprintf(buf, size, "%s", v->texts[(int)x]);
    else if (v->integer)
        snprintf(buf, size, "%.0f", x);
    else
        snprintf(buf, size, "%.12g", x);
}

double cs_sweep_value_used(const cs_sweep_var *v, double x) {
    if (!v->numeric) return x;
    char buf[64];
    cs_sweep_value_text(v, x, buf, sizeof buf);
    return strtod(buf, NULL);
}

/* ---- statistics ---- */

cs_interval cs_wilson(long k, long n, double z) {
    cs_interval r = {NAN, NAN, NAN};
    if (n <= 0) return r;
    double p = (double)k / (double)n, z2 = z * z, nn = (double)n;
    double centre = (p + z2 / (2 * nn)) / (1 + z2 / nn);
    double half = z / (1 + z2 / nn) * sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn));
    r.p = p;
    r.lo = k == 0 ? 0.0 : fmax(0.0, centre - half); /* exact at the ends (no rounding residue) */
    r.hi = k == n ? 1.0 : fmin(1.0, centre + half);
    return r;
}

typedef struct ranked {
    double v;
    long i;
} ranked;

static int by_value(const void *a, const void *b) {
    const ranked *x = a, *y = b;
    if (x->v < y->v) return -1;
    if (x->v > y->v) return 1;
    return x->i < y->i ? -1 : x->i > y->i; /* a total order: the same ranks on every machine */
}

int cs_ranks(const double *x, long n, double *rank) {
    ranked *r = malloc((size_t)(n > 0 ? n : 1) * sizeof *r);
    if (!r) return -1;
    for (long i = 0; i < n; i++)
        r[i] = (ranked){x[i], i};
    qsort(r, (size_t)n, sizeof *r, by_value);
    for (long i = 0; i < n;) {
        long j = i + 1;
        while (j < n && r[j].v == r[i].v)
            j++;
        double mean = 0.5 * (double)(i + 1 + j); /* ranks i+1 .. j */
        for (long t = i; t < j; t++)
            rank[r[t].i] = mean;
        i = j;
    }
    free(r);
    return 0;
}

double cs_spearman(const double *x, const double *y, long n) {
    if (n < 2) return NAN;
    double *rx = malloc((size_t)n * sizeof *rx), *ry = malloc((size_t)n * sizeof *ry);
    double rho = NAN;
    if (rx && ry && cs_ranks(x, n, rx) == 0 && cs_ranks(y, n, ry) == 0) {
        double mean = 0.5 * (double)(n + 1), sxy = 0, sxx = 0, syy = 0;
        for (long i = 0; i < n; i++) {
            double dx = rx[i] - mean, dy = ry[i] - mean;
            sxy += dx * dy, sxx += dx * dx, syy += dy * dy;
        }
        if (sxx > 0 && syy > 0) rho = sxy / sqrt(sxx * syy);
    }
    free(rx);
    free(ry);
    return rho;
}
