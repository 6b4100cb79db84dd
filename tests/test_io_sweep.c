/* SPDX-License-Identifier: MIT */
/* Sweeps: Wilson intervals and Spearman's rho against values worked by hand, the normal quantile, the
 * Latin hypercube's strata, the counter-based inputs (the same whatever else runs), the spec reader
 * (values in SI, grid order) and its errors at line:column. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "study/sweep.h"

#define Z95 1.959963984540054

/* Wilson: centre (p + z^2/2n) / (1 + z^2/n), half-width z / (1 + z^2/n) * sqrt(p(1-p)/n + z^2/4n^2), with
 * z^2 = 3.841459. */
static void test_wilson(void **state) {
    (void)state;
    /* 0 of 10: centre = (0 + 0.1920729) / 1.3841459 = 0.1387664 = half-width: [0, 0.2775328] */
    cs_interval w = cs_wilson(0, 10, Z95);
    assert_true(w.p == 0 && w.lo == 0);
    assert_true(fabs(w.hi - 0.2775327998628892) < 1e-12);
    /* 5 of 10: centre 0.5; half = 1.4160 * sqrt(0.025 + 0.0096036) = 0.2634069: [0.2365931, 0.7634069] */
    w = cs_wilson(5, 10, Z95);
    assert_true(fabs(w.lo - 0.236593090512564) < 1e-12 && fabs(w.hi - 0.7634069094874361) < 1e-12);
    /* 3 of 20: centre (0.15 + 0.0960365) / 1.1920729 = 0.2063938; half = 1.6441575 * sqrt(0.006375 +
     * 0.0024009) = 0.1540251: [0.0523687, 0.3604189] */
    w = cs_wilson(3, 20, Z95);
    assert_true(fabs(w.p - 0.15) < 1e-15);
    assert_true(fabs(w.lo - 0.052368745896216595) < 1e-12 && fabs(w.hi - 0.36041886474075696) < 1e-12);
    /* 20 of 20: [1 - 0.1611252, 1] */
    w = cs_wilson(20, 20, Z95);
    assert_true(fabs(w.lo - 0.8388748419471806) < 1e-12 && w.hi == 1.0);
    w = cs_wilson(0, 64, Z95); /* 2 z^2/4n^2 ... = 0.0566241; the ends exact, no 3e-18 of rounding */
    assert_true(w.lo == 0.0 && fabs(w.hi - 0.05662405979280534) < 1e-12);
    w = cs_wilson(64, 64, Z95);
    assert_true(w.hi == 1.0 && fabs(w.lo - 0.9433759402071946) < 1e-12);
    w = cs_wilson(0, 0, Z95);
    assert_true(isnan(w.p));
}

static void test_spearman(void **state) {
    (void)state;
    /* y = 5 6 7 8 7: ranks 1 2 3.5 5 3.5; d(x) = -2 -1 0 1 2, d(y) = -2 -1 0.5 2 0.5:
     * sum dx dy = 8, sum dx^2 = 10, sum dy^2 = 9.5: rho = 8 / sqrt(95) */
    const double x[] = {1, 2, 3, 4, 5}, y[] = {5, 6, 7, 8, 7};
    double r[5];
    assert_int_equal(cs_ranks(y, 5, r), 0);
    const double want[] = {1, 2, 3.5, 5, 3.5};
    for (int i = 0; i < 5; i++)
        assert_true(r[i] == want[i]);
    assert_true(fabs(cs_spearman(x, y, 5) - 0.8207826816681233) < 1e-12);
    /* monotone but not linear: 1; reversed: -1 */
    const double cube[] = {-8, -1, 0, 27, 1000}, down[] = {9, 7, 3, 2, -4};
    assert_true(fabs(cs_spearman(x, cube, 5) - 1) < 1e-15);
    assert_true(fabs(cs_spearman(x, down, 5) + 1) < 1e-15);
    /* a constant column has no correlation */
    const double flat[] = {2, 2, 2, 2, 2};
    assert_true(isnan(cs_spearman(x, flat, 5)));
    assert_true(isnan(cs_spearman(x, y, 1)));
    /* x = 1..6, y = 2 1 4 3 6 5: d = 6 pairs each swapped, sum d^2 = 6: 1 - 6*6 / (6*35) = 0.8285714 */
    const double x6[] = {1, 2, 3, 4, 5, 6}, y6[] = {2, 1, 4, 3, 6, 5};
    assert_true(fabs(cs_spearman(x6, y6, 6) - (1 - 36.0 / 210.0)) < 1e-12);
}

static void test_normal(void **state) {
    (void)state;
    assert_true(fabs(cs_normal_quantile(0.975) - 1.959963984540054) < 1e-13);
    assert_true(fabs(cs_normal_quantile(0.5)) < 1e-15);
    assert_true(fabs(cs_normal_quantile(0.3) + 0.5244005127080407) < 1e-13);
    assert_true(fabs(cs_normal_quantile(1e-10) + 6.361340902404056) < 1e-10);
    for (double p = 1e-12; p < 1; p = p < 0.01 ? p * 7 : p + 0.0123) {
        double x = cs_normal_quantile(p);
        double back = p < 0.5 ? cs_normal_cdf(x) : 1 - 0.5 * erfc(x / sqrt(2.0));
        assert_true(fabs(back - p) <= 1e-14 * fmax(1.0, p / 1e-3) + 1e-15 * p);
    }
}

/* Each variable's column of an n-run hypercube has exactly one point in each of the n strata. */
static void test_latin_hypercube_strata(void **state) {
    (void)state;
    const long sizes[] = {1, 2, 7, 50, 1000};
    for (size_t t = 0; t < sizeof sizes / sizeof sizes[0]; t++) {
        long n = sizes[t];
        int k = 5;
        double *u = cs_latin_hypercube(42, n, k);
        assert_non_null(u);
        int *hit = calloc((size_t)n, sizeof *hit);
        for (int j = 0; j < k; j++) {
            memset(hit, 0, (size_t)n * sizeof *hit);
            for (long i = 0; i < n; i++) {
                double v = u[i * k + j];
                assert_true(v > 0 && v < 1);
                long s = (long)floor(v * (double)n);
                assert_true(s >= 0 && s < n);
                hit[s]++;
            }
            for (long s = 0; s < n; s++)
                assert_int_equal(hit[s], 1);
        }
        /* the same seed gives the same design; another seed another */
        double *again = cs_latin_hypercube(42, n, k), *other = cs_latin_hypercube(43, n, k);
        assert_memory_equal(u, again, (size_t)n * (size_t)k * sizeof *u);
        if (n > 1) assert_true(memcmp(u, other, (size_t)n * (size_t)k * sizeof *u) != 0);
        free(again);
        free(other);
        free(hit);
        free(u);
    }
}

static void test_counter_rng(void **state) {
    (void)state;
    double sum = 0;
    for (uint64_t i = 0; i < 100000; i++) {
        double u = cs_sweep_u01(7, i, 3, 0);
        assert_true(u > 0 && u < 1);
        assert_true(u == cs_sweep_u01(7, i, 3, 0));
        sum += u;
    }
    assert_true(fabs(sum / 100000 - 0.5) < 0.005);
    assert_true(cs_sweep_u01(7, 1, 3, 0) != cs_sweep_u01(8, 1, 3, 0));
    assert_true(cs_sweep_u01(7, 1, 3, 0) != cs_sweep_u01(7, 3, 1, 0));
}

static void test_distributions(void **state) {
    (void)state;
    cs_dist d = {CS_DIST_NORMAL, 10, 2, 9, HUGE_VAL, 0, 0};
    assert_int_equal(cs_dist_prepare(&d), 0);
    for (int i = 1; i < 1000; i++)
        assert_true(cs_dist_quantile(&d, i / 1000.0) >= 9);
    assert_true(fabs(cs_dist_quantile(&d, 1e-12) - 9) < 1e-6);
    /* lognormal of mean 50 and sd 5: sigma^2 = ln(1.01), mu = ln 50 - sigma^2/2; the sample mean is near 50
     */
    cs_dist l = {CS_DIST_LOGNORMAL, log(50) - 0.5 * log(1.01), sqrt(log(1.01)), -HUGE_VAL, HUGE_VAL, 0, 0};
    assert_int_equal(cs_dist_prepare(&l), 0);
    double sum = 0;
    for (int i = 0; i < 10000; i++)
        sum += cs_dist_quantile(&l, (i + 0.5) / 10000);
    assert_true(fabs(sum / 10000 - 50) < 0.01);
    cs_dist u = {CS_DIST_UNIFORM, 3, 5, 0, 0, 0, 0};
    assert_int_equal(cs_dist_prepare(&u), 0);
    assert_true(fabs(cs_dist_quantile(&u, 0.25) - 3.5) < 1e-15);
    /* bounds that leave nothing */
    cs_dist none = {CS_DIST_NORMAL, 0, 1, 40, 41, 0, 0};
    assert_int_equal(cs_dist_prepare(&none), -1);
}

static cs_sweep_spec *read(const char *path) {
    cs_units *u = cs_units_open(NULL);
    assert_non_null(u);
    cs_sweep_spec *s = cs_sweep_spec_read(path, u);
    cs_units_free(u);
    assert_non_null(s);
    return s;
}

static void test_spec(void **state) {
    (void)state;
    cs_sweep_spec *s = read("tests/sweep/lhs.yaml");
    for (int i = 0; i < s->error_count; i++)
        print_message("%s\n", s->errors[i]);
    assert_int_equal(s->error_count, 0);
    assert_int_equal(s->method, CS_SWEEP_LATIN_HYPERCUBE);
    assert_int_equal(s->runs, 4);
    assert_true(s->seed == 7);
    assert_int_equal(s->var_count, 3);
    assert_string_equal(s->vars[0].path, "barrier.soil.soil_pressure");
    assert_string_equal(s->vars[0].unit, "Pa");
    assert_int_equal(s->vars[0].dist.kind, CS_DIST_NORMAL);
    assert_true(fabs(s->vars[0].dist.a - 8000 * 47.88025898033584) < 1e-6); /* psf in Pa */
    assert_true(fabs(s->vars[0].dist.lo - 4000 * 47.88025898033584) < 1e-6);
    assert_true(isinf(s->vars[0].dist.hi));
    assert_true(fabs(s->vars[2].dist.a - 38 * 0.44704) < 1e-9 &&
                fabs(s->vars[2].dist.b - 42 * 0.44704) < 1e-9);
    assert_int_equal(s->set_count, 1);
    assert_string_equal(s->sets[0], "scenario.t_end=10 ms");
    long n;
    double *x = cs_sweep_samples(s, &n);
    assert_int_equal(n, 4);
    /* Latin hypercube on the inputs: each speed in its own quarter of 38-42 mph */
    int quarter[4] = {0};
    for (long i = 0; i < n; i++)
        quarter[(int)((x[i * 3 + 2] / 0.44704 - 38) / 1.0)]++;
    for (int q = 0; q < 4; q++)
        assert_int_equal(quarter[q], 1);
    free(x);
    cs_sweep_spec_free(s);

    /* a grid: the levels in SI, the last variable fastest; a Monte Carlo run's inputs do not depend on
     * how many runs there are */
    s = read("tests/sweep/grid.yaml");
    assert_int_equal(s->error_count, 0);
    assert_int_equal(s->runs, 6);
    assert_int_equal(s->vars[0].level_count, 3);
    assert_true(fabs(s->vars[0].levels[2] - 6000 * 4.4482216152605) < 1e-6);
    assert_false(s->vars[1].numeric);
    x = cs_sweep_samples(s, &n);
    const double vehicle[] = {0, 1, 0, 1, 0, 1}, level[] = {0, 0, 1, 1, 2, 2};
    for (long i = 0; i < n; i++) {
        assert_true(x[i * 2 + 1] == vehicle[i]);
        assert_true(x[i * 2] == s->vars[0].levels[(int)level[i]]);
    }
    free(x);
    cs_sweep_spec_free(s);
    s = read("tests/sweep/mc.yaml");
    assert_int_equal(s->error_count, 0);
    double *six = cs_sweep_samples(s, &n);
    s->runs = 1000;
    double *many = cs_sweep_samples(s, &n);
    assert_memory_equal(six, many, 6 * 2 * sizeof *six);
    for (long i = 0; i < n; i++)
        assert_true(many[i * 2] >= 4000 * 4.4482216152605 - 1e-6 &&
                    many[i * 2] <= 6500 * 4.4482216152605 + 1e-6);
    free(six);
    free(many);
    cs_sweep_spec_free(s);

    /* plots: x and lines by their index among the varied values, y as written, png unless asked */
    s = read("tests/sweep/plot.yaml");
    assert_int_equal(s->error_count, 0);
    assert_int_equal(s->plot_count, 2);
    assert_string_equal(s->vars[s->plots[0].x].path, "barrier.posts[0].spacing");
    assert_string_equal(s->vars[s->plots[0].lines].path, "vehicle");
    assert_string_equal(s->plots[0].y, "max_barrier_deflection");
    assert_string_equal(s->plots[0].format, "png");
    assert_true(s->plots[0].line == 12 && s->plots[0].col == 5 && s->plots[0].y_line == 13 &&
                s->plots[0].y_col == 8);
    assert_string_equal(s->plots[1].y, "exit_speed");
    assert_string_equal(s->plots[1].format, "svg");
    cs_sweep_spec_free(s);
    /* a Monte Carlo's plot has no lines */
    s = read("tests/sweep/bad/plot_lines_in_mc.yaml");
    assert_int_equal(s->error_count, 1);
    assert_int_equal(s->plot_count, 1);
    assert_int_equal(s->plots[0].lines, -1);
    assert_string_equal(s->vars[s->plots[0].x].path, "scenario.speed");
    cs_sweep_spec_free(s);
}

/* The level of each variable in each run of a grid: the first slowest, as cs_sweep_samples gives them. */
static void test_grid_levels(void **state) {
    (void)state;
    cs_sweep_spec *s = read("tests/sweep/plot.yaml"); /* 3 spacings x 2 vehicles */
    long n;
    double *x = cs_sweep_samples(s, &n);
    assert_int_equal(n, 6);
    const int spacing[] = {0, 0, 1, 1, 2, 2}, vehicle[] = {0, 1, 0, 1, 0, 1};
    for (long i = 0; i < n; i++) {
        assert_int_equal(cs_sweep_grid_level(s, i, 0), spacing[i]);
        assert_int_equal(cs_sweep_grid_level(s, i, 1), vehicle[i]);
        assert_true(x[i * 2] == s->vars[0].levels[spacing[i]] && x[i * 2 + 1] == vehicle[i]);
    }
    assert_true(x[0] == 4 && x[2 * 2] == 2 && x[4 * 2] == 6); /* the levels as listed: 4, 2, 6 m */
    free(x);
    cs_sweep_spec_free(s);
}

static void test_spec_errors(void **state) {
    (void)state;
    cs_sweep_spec *s = read("tests/sweep/bad/bad_unit.yaml");
    assert_int_equal(s->error_count, 1);
    assert_non_null(strstr(s->errors[0],
                           "tests/sweep/bad/bad_unit.yaml:8:63: vary: barrier.soil.soil_pressure: "
                           "mean: 'kg' is a unit of mass, not of pressure"));
    cs_sweep_spec_free(s);
    /* sorted by place */
    s = read("tests/sweep/bad/bad_range.yaml");
    assert_int_equal(s->error_count, 2);
    assert_non_null(strstr(s->errors[0], "bad_range.yaml:7:29: "));
    assert_non_null(strstr(s->errors[1], "bad_range.yaml:8:59: "));
    cs_sweep_spec_free(s);
    /* the model's own check of a level, at the level */
    s = read("tests/sweep/bad/bad_level.yaml");
    assert_int_equal(s->error_count, 0);
    long n;
    double *x = cs_sweep_samples(s, &n);
    assert_int_equal(cs_sweep_check(s, x), -1);
    assert_int_equal(s->error_count, 1);
    assert_non_null(
        strstr(s->errors[0], "bad_level.yaml:6:42: vary: barrier.soil.soil_pressure = -47.8802589803 Pa: "));
    free(x);
    cs_sweep_spec_free(s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_wilson),      cmocka_unit_test(test_spearman),
        cmocka_unit_test(test_normal),      cmocka_unit_test(test_latin_hypercube_strata),
        cmocka_unit_test(test_counter_rng), cmocka_unit_test(test_distributions),
        cmocka_unit_test(test_spec),        cmocka_unit_test(test_spec_errors),
        cmocka_unit_test(test_grid_levels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
