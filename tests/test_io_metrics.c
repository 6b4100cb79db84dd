/* SPDX-License-Identifier: MIT */
/* Validation metrics against closed forms: a trace against itself scaled by 1.1 (M = 0.1, P = 0, the
 * residuals 0.1 m: mean 0 over whole periods, std 0.1 sqrt(n / 2 (n - 1))); against itself shifted in
 * phase by phi (M = 0, P = phi / pi); a constant offset (mean its size over the peak, std 0); W179's
 * limits at their edges; pairing a computed history onto the measured times by interpolation. */
#include <stdlib.h>

#include "check.h"
#include "study/metrics.h"

#define PI 3.14159265358979323846

enum { N = 1000 };

/* m = sin over 5 whole periods in N samples */
static void sine(double *m, double phase, double scale) {
    for (int i = 0; i < N; i++)
        m[i] = scale * sin(2 * PI * 5 * i / (double)N + phase);
}

static void scaled(void **state) {
    (void)state;
    double m[N], c[N];
    sine(m, 0, 1), sine(c, 0, 1.1);
    cs_validation_metrics v;
    assert_int_equal(cs_validation_metrics_of(m, c, N, &v), 0);
    CHECK_REL(v.m, 0.1, 1e-12);
    CHECK_ABS(v.p, 0.0, 1e-7); /* acos near 1 loses half the digits */
    CHECK_REL(v.c, 0.1, 1e-6);
    CHECK_ABS(v.mean, 0.0, 1e-14);
    /* the peak of 5 periods in 1000 samples is 1 (at i = 50) */
    CHECK_REL(v.std, 0.1 * sqrt(N / (2.0 * (N - 1))), 1e-12);
    assert_true(cs_validation_metrics_pass(&v));
}

static void phase_shift(void **state) {
    (void)state;
    double m[N], c[N];
    const double phis[] = {0.1, 0.5, 1.0, PI / 2, 2.5};
    for (int k = 0; k < 5; k++) {
        sine(m, 0, 1), sine(c, phis[k], 1);
        cs_validation_metrics v;
        assert_int_equal(cs_validation_metrics_of(m, c, N, &v), 0);
        CHECK_ABS(v.m, 0.0, 1e-12);
        CHECK_REL(v.p, phis[k] / PI, 1e-9);
        CHECK_REL(v.c, phis[k] / PI, 1e-9);
    }
}

static void offset_and_limits(void **state) {
    (void)state;
    double m[N], c[N];
    sine(m, 0, 2.0);
    for (int i = 0; i < N; i++)
        c[i] = m[i] + 0.1;
    cs_validation_metrics v;
    assert_int_equal(cs_validation_metrics_of(m, c, N, &v), 0);
    CHECK_REL(v.mean, 0.1 / 2.0, 1e-12); /* over the peak 2 */
    CHECK_ABS(v.std, 0.0, 1e-12);
    /* W179's limits, each at its edge and past it */
    cs_validation_metrics ok = {N, 0.40, -0.40, 0.5, -0.05, 0.35};
    assert_true(cs_validation_metrics_pass(&ok));
    cs_validation_metrics bad[] = {
        {N, 0.41, 0, 0, 0, 0}, {N, 0, 0.41, 0, 0, 0}, {N, 0, 0, 0, 0.051, 0}, {N, 0, 0, 0, 0, 0.351}};
    for (int k = 0; k < 4; k++)
        assert_false(cs_validation_metrics_pass(&bad[k]));
    /* nothing to compare */
    for (int i = 0; i < N; i++)
        m[i] = 0.0;
    assert_int_equal(cs_validation_metrics_of(m, c, N, &v), -1);
    assert_int_equal(cs_validation_metrics_of(c, c, 1, &v), -1);
}

static void pairing(void **state) {
    (void)state;
    /* computed: y = 2 t at t = 0, 0.1, ..., 1; measured at 0.05, 0.15, ... 1.25: those past 1 s dropped */
    double tc[11], yc[11], tm[13], ym[13], mm[13], cm[13];
    for (int i = 0; i < 11; i++)
        tc[i] = 0.1 * i, yc[i] = 2 * tc[i];
    for (int i = 0; i < 13; i++)
        tm[i] = 0.05 + 0.1 * i, ym[i] = i;
    size_t n = cs_validation_pair(tm, ym, 13, tc, yc, 11, mm, cm);
    assert_int_equal(n, 10);
    for (size_t i = 0; i < n; i++) {
        CHECK_REL(cm[i], 2 * tm[i], 1e-12);
        CHECK_REL(mm[i], (double)i, 0);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(scaled), cmocka_unit_test(phase_shift),
                                       cmocka_unit_test(offset_and_limits), cmocka_unit_test(pairing)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
