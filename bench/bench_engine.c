/* SPDX-License-Identifier: MIT */
/* The engine's cost on one model: load it once, then run it REPEAT times from t = 0 (cs_state_reset),
 * timing cs_run alone. Prints one line of key=value: load time, the best CPU time of settling the barrier
 * under its pretension (cs_state_create, made REPEAT times), the best and median engine time of a run
 * (wall clock, and the best CPU time: the machine may be shared), steps and steps per second, the time
 * per step and per post-step, and the process's peak memory (getrusage). Used by bench/run.sh (make bench).
 *
 * usage: bench_engine MODEL [--repeat R] [--t-end T] [--set PATH=VALUE]... */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "cablesim/loader.h"

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double cpu(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int by_value(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: bench_engine MODEL [--repeat R] [--t-end T] [--set PATH=VALUE]...\n");
        return 2;
    }
    char set[512];
    int repeat = 3;
    double t0 = now();
    cs_error err;
    cs_loader *l = cs_loader_create(NULL, &err);
    if (!l) {
        fprintf(stderr, "bench_engine: %s\n", err.message);
        return 1;
    }
    for (int i = 2; i < argc; i++) {
        if (strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
            repeat = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--t-end") == 0 && i + 1 < argc) {
            snprintf(set, sizeof set, "scenario.t_end=%s", argv[++i]);
            cs_loader_set(l, set);
        } else if (strcmp(argv[i], "--set") == 0 && i + 1 < argc) {
            cs_loader_set(l, argv[++i]);
        } else {
            fprintf(stderr, "bench_engine: unknown argument %s\n", argv[i]);
            return 2;
        }
    }
    if (repeat < 1 || repeat > 1000) repeat = 1;
    cs_model_input in = {.size = sizeof in};
    cs_model *m = NULL;
    if (cs_loader_load(l, argv[1], &in) != 0 || !(m = cs_loader_build(l, &in))) {
        cs_loader_print_errors(l, stderr);
        return 1;
    }
    double load = now() - t0, dt = in.scenario.dt;
    int posts = in.barrier.post_count, cables = in.barrier.cable_count;
    cs_loader_free(l);
    double *times = malloc((size_t)repeat * sizeof *times), *cpus = malloc((size_t)repeat * sizeof *cpus);
    double settle = 0.0; /* the best CPU time of a state made and settled, over REPEAT */
    cs_state *s = NULL;
    for (int r = 0; r < repeat; r++) {
        cs_state_free(s);
        err = (cs_error){0};
        double c = cpu();
        s = cs_state_create(m, &err);
        c = cpu() - c;
        if (!s) {
            fprintf(stderr, "bench_engine: %s\n", err.message);
            return 1;
        }
        if (r == 0 || c < settle) settle = c;
    }
    cs_summary sum = {.size = sizeof sum};
    for (int r = 0; r < repeat; r++) {
        cs_state_reset(m, s);
        double a = now(), c = cpu();
        cs_status st = cs_run(m, s, NULL, NULL, &err);
        times[r] = now() - a;
        cpus[r] = cpu() - c;
        if (st != CS_OK) {
            fprintf(stderr, "bench_engine: the run failed: %s\n", err.message);
            return 1;
        }
    }
    cs_state_summary(s, &sum, NULL);
    qsort(times, (size_t)repeat, sizeof *times, by_value);
    qsort(cpus, (size_t)repeat, sizeof *cpus, by_value);
    double best = times[0], median = times[repeat / 2];
    double steps = sum.t_end_s / dt;
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("model=%s posts=%d cables=%d repeat=%d load_ms=%.2f settle_cpu_ms_best=%.3f engine_ms_best=%.2f "
           "engine_ms_median=%.2f cpu_ms_best=%.2f "
           "t_reached_s=%.4f steps=%.0f steps_per_s=%.0f us_per_step=%.2f ns_per_post_step=%.1f outcome=%s "
           "solver_warnings=%d peak_rss_kb=%ld\n",
           argv[1], posts, cables, repeat, 1e3 * load, 1e3 * settle, 1e3 * best, 1e3 * median, 1e3 * cpus[0],
           sum.t_end_s, steps, steps / best, 1e6 * best / steps, 1e9 * best / steps / (posts > 0 ? posts : 1),
           cs_outcome_name(sum.outcome), sum.solver_warnings, ru.ru_maxrss);
    free(times);
    free(cpus);
    cs_state_free(s);
    cs_model_free(m);
    return 0;
}
