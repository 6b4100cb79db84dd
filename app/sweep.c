/* cablesim sweep: read the spec, make every run's inputs (the same on every rank), share the runs
 * among MPI ranks (run i on rank i mod size) and, within a rank, among OpenMP threads (dynamic, one run
 * at a time), gather the results on rank 0 and write runs.csv, summary.md and summary.json there (and
 * runs.nc and the spec's plots when asked). The inputs depend only on the seed and the run index, and
 * each run on nothing else, so the outputs are the same for any thread or rank count. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef CS_MPI
#include <mpi.h>
#endif

#include "out/outfile.h"
#include "out/plot.h"
#include "out/studyreport.h"
#include "out/sweepout.h"
#include "study/sweep.h"
#include "sweepcmd.h"

enum { EXIT_RUN = 1, EXIT_BAD = 2 };

static const char sweep_usage[] =
    "usage: cablesim sweep SPEC.yaml [-o DIR] [--threads N] [--runs N] [--seed S] [--set PATH=VALUE]...\n"
    "                      [--t-end T] [--dt T] [--netcdf] [--quiet]\n"
    "Runs the study of SPEC (a base model, the values to vary: grids, or Monte Carlo / Latin hypercube\n"
    "samples) and writes DIR/runs.csv, DIR/summary.md and DIR/summary.json (default DIR: results/<spec\n"
    "name>). --threads: OpenMP threads per process (default: OMP_NUM_THREADS or the cores, shared among\n"
    "the ranks of a machine). Under MPI (mpirun -n R cablesim-mpi sweep ...) the runs are shared among\n"
    "the R ranks. --runs and --seed replace the spec's; --set, --t-end and --dt apply to every run.\n"
    "--netcdf (or `netcdf: true` in SPEC) also writes DIR/runs.nc: runs.csv's table as netCDF (CF-1.8).\n"
    "SPEC's `plot:` draws a response against a varied value in DIR/plots/<y>-vs-<x>.png (docs/sweep.md).\n";

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* ---- progress: a bar on a terminal, plain lines every few seconds otherwise ---- */

typedef struct progress {
    int on, tty, ranks;
    long done, total;
    double start, last;
} progress;

static void fmt_time(double s, char *buf, size_t size) {
    long t = (long)(s + 0.5);
    if (t >= 3600)
        snprintf(buf, size, "%ldh%02ldm", t / 3600, t / 60 % 60);
    else if (t >= 60)
        snprintf(buf, size, "%ldm%02lds", t / 60, t % 60);
    else
        snprintf(buf, size, "%lds", t);
}

static void progress_show(progress *p, int final) {
    double t = now(), elapsed = t - p->start;
    if (!p->on || (!final && t - p->last < (p->tty ? 0.25 : 10.0))) return;
    p->last = t;
    double rate = elapsed > 0 ? (double)p->done / elapsed : 0;
    char left[32] = "?";
    if (rate > 0) fmt_time((double)(p->total - p->done) / rate, left, sizeof left);
    char who[48] = "";
    if (p->ranks > 1) snprintf(who, sizeof who, " on rank 0 (of %d)", p->ranks);
    if (p->tty) {
        char bar[31];
        int full = p->total ? (int)(30 * p->done / p->total) : 30;
        for (int i = 0; i < 30; i++)
            bar[i] = i < full ? '#' : '-';
        bar[30] = '\0';
        fprintf(stderr, "\r[%s] %ld/%ld runs%s  %.2f runs/s  %s left   ", bar, p->done, p->total, who, rate,
                left);
        if (final) fputc('\n', stderr);
    } else {
        fprintf(stderr, "sweep: %ld/%ld runs%s (%.0f%%), %.2f runs/s, about %s left\n", p->done, p->total,
                who, p->total ? 100.0 * (double)p->done / (double)p->total : 100.0, rate, left);
    }
    fflush(stderr);
}

/* ---- the command ---- */

typedef struct sweep_opts {
    const char *spec, *out_dir;
    int threads, quiet, netcdf;
    long runs;
    const char *seed;
    const char *sets[256];
    int set_count;
} sweep_opts;

static int sweep_bad_usage(int rank, const char *what, const char *arg) {
    if (rank == 0)
        fprintf(stderr, "cablesim sweep: %s%s%s\n%s", what, arg ? ": " : "", arg ? arg : "", sweep_usage);
    return EXIT_BAD;
}

static int parse_opts(int argc, char **argv, sweep_opts *o, int rank) {
    static char extra[2][300];
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--quiet") == 0) {
            o->quiet = 1;
            continue;
        }
        if (strcmp(a, "--netcdf") == 0) {
            o->netcdf = 1;
            continue;
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            if (rank == 0) fputs(sweep_usage, stdout);
            return -1;
        }
        static const char *const valued[] = {"-o",    "--threads", "--runs", "--seed",
                                             "--set", "--t-end",   "--dt"};
        int k = -1;
        const char *v = NULL;
        for (int j = 0; j < 7; j++) {
            size_t n = strlen(valued[j]);
            if (strncmp(a, valued[j], n) == 0 && (a[n] == '\0' || a[n] == '=')) {
                k = j;
                v = a[n] == '=' ? a + n + 1 : i + 1 < argc ? argv[++i] : NULL;
            }
        }
        if (k < 0 && a[0] == '-') return sweep_bad_usage(rank, "unknown option", a);
        if (k < 0 && o->spec) return sweep_bad_usage(rank, "more than one spec file", a);
        if (k < 0) {
            o->spec = a;
            continue;
        }
        if (!v) return sweep_bad_usage(rank, "an option lacks its value", a);
        char *end;
        switch (k) {
        case 0:
            o->out_dir = v;
            break;
        case 1:
            o->threads = (int)strtol(v, &end, 10);
            if (*end || o->threads < 1 || o->threads > 1024)
                return sweep_bad_usage(rank, "--threads takes 1 to 1024", v);
            break;
        case 2:
            o->runs = strtol(v, &end, 10);
            if (*end || o->runs < 1 || o->runs > CS_SWEEP_MAX_RUNS)
                return sweep_bad_usage(rank, "--runs takes 1 to 1000000", v);
            break;
        case 3:
            o->seed = v;
            break;
        default:
            if (o->set_count == 256) return sweep_bad_usage(rank, "too many --set", v);
            if (k == 4) {
                o->sets[o->set_count++] = v;
            } else {
                char *buf = extra[k - 5];
                snprintf(buf, sizeof extra[0], "scenario.%s=%s", k == 5 ? "t_end" : "dt", v);
                o->sets[o->set_count++] = buf;
            }
        }
    }
    return o->spec ? 0 : sweep_bad_usage(rank, "no spec file", NULL);
}

/* runs.csv, summary.md, summary.json, then the spec's plots (files 3 on), the study's own figures and
 * report.html, and runs.nc, begun on out and renamed together; nothing is left if one fails. */
static int write_all(const char *dir, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                     long n) {
    char why[512] = "";
    cs_outdir out;
    int rc = cs_out_open(&out, dir, why, sizeof why);
    static const char *const names[] = {"runs.csv", "summary.md", "summary.json"};
    if (rc == 0) rc = cs_out_subdir(&out, "plots", why, sizeof why);
    int files = 3 + spec->plot_count, study = files; /* then the study's figures, then its page */
    for (int k = 0; rc == 0 && k < study + CS_STUDY_FIGURES + 1; k++) {
        char name[256];
        if (k < 3)
            snprintf(name, sizeof name, "%s", names[k]);
        else if (k < study)
            cs_sweep_plot_file(spec, k - 3, name, sizeof name);
        else if (k < study + CS_STUDY_FIGURES)
            cs_study_figure_file(k - study, name, sizeof name);
        else
            snprintf(name, sizeof name, "report.html");
        FILE *f = cs_out_begin(&out, name, why, sizeof why);
        if (!f) {
            rc = -1;
            break;
        }
        rc = k == 0      ? cs_sweep_write_runs(f, spec, x, r, n, why, sizeof why)
             : k == 1    ? cs_sweep_write_summary_md(f, spec, x, r, n, why, sizeof why)
             : k == 2    ? cs_sweep_write_summary_json(f, spec, x, r, n, why, sizeof why)
             : k < study ? cs_sweep_write_plot(f, spec, k - 3, x, r, n, why, sizeof why)
             : k < study + CS_STUDY_FIGURES
                 ? cs_study_write_figure(f, CS_PLOT_PNG, k - study, spec, x, r, n, why, sizeof why)
                 : cs_study_write_page(f, spec, x, r, n, why, sizeof why);
        char end_why[512];
        if (cs_out_end(&out, f, end_why, sizeof end_why) != 0 && rc == 0) {
            snprintf(why, sizeof why, "%s", end_why);
            rc = -1;
        }
    }
    cs_plot_release(); /* after the last plot */
    if (rc == 0 && spec->netcdf) {
        char path[1200], nc_why[200];
        rc = cs_out_begin_path(&out, "runs.nc", path, sizeof path, why, sizeof why);
        if (rc == 0 && (rc = cs_sweep_write_netcdf(path, spec, x, r, n, nc_why, sizeof nc_why)) != 0)
            snprintf(why, sizeof why, "%.280s/runs.nc: %s", dir, nc_why);
        if (rc == 0) rc = cs_out_end_path(&out, why, sizeof why);
    }
    if (rc == 0) rc = cs_out_commit(&out, why, sizeof why);
    if (rc != 0) {
        cs_out_abort(&out);
        fprintf(stderr, "cablesim sweep: nothing written: %s\n", why);
    }
    return rc;
}

/* Read the spec with the command line's changes; errors printed by rank 0. */
static cs_sweep_spec *read_spec(const sweep_opts *o, int rank) {
    char why[256];
    cs_units *units = cs_units_create(why, sizeof why);
    if (!units) {
        if (rank == 0) fprintf(stderr, "cablesim sweep: %s\n", why);
        return NULL;
    }
    cs_sweep_spec *spec = cs_sweep_spec_read(o->spec, units);
    cs_units_free(units);
    if (!spec) {
        if (rank == 0) fprintf(stderr, "cablesim sweep: out of memory\n");
        return NULL;
    }
    cs_sweep_plots_check(spec);
    for (int i = 0; i < o->set_count; i++)
        cs_sweep_spec_add_set(spec, o->sets[i]);
    spec->netcdf |= o->netcdf;
    if (o->runs > 0 && spec->method == CS_SWEEP_GRID)
        cs_sweep_error(spec, 0, 0, "--runs: a grid's runs are every combination of its levels");
    else if (o->runs > 0)
        spec->runs = o->runs;
    if (o->seed) {
        char *end;
        unsigned long long s = strtoull(o->seed, &end, 10);
        if (*end || end == o->seed || o->seed[0] == '-')
            cs_sweep_error(spec, 0, 0, "--seed %s: expected a whole number from 0 to 2^64 - 1", o->seed);
        spec->seed = (uint64_t)s;
    }
    return spec;
}

static void print_errors(const cs_sweep_spec *spec) {
    for (int i = 0; i < spec->error_count; i++)
        fprintf(stderr, "%s\n", spec->errors[i]);
    fprintf(stderr, "cablesim sweep: %s: %d problem%s, nothing run\n", spec->file, spec->error_count,
            spec->error_count == 1 ? "" : "s");
}

/* The threads of this process: asked for, or the cores shared among the ranks of this machine. */
static int thread_count(int asked, int local_ranks) {
#ifdef _OPENMP
    if (asked > 0) return asked;
    int t = omp_get_max_threads() / (local_ranks > 0 ? local_ranks : 1);
    return t > 0 ? t : 1;
#else
    (void)local_ranks;
    if (asked > 1) fprintf(stderr, "cablesim sweep: built without OpenMP, running on 1 thread\n");
    return 1;
#endif
}

/* The file argument of `cablesim check FILE [--set PATH=VALUE]...`. */
static const char *check_file(int argc, char **argv) {
    for (int i = 2; i < argc; i++) {
        if (argv[i][0] != '-') return argv[i];
        if (strchr(argv[i], '=') == NULL && i + 1 < argc) i++; /* an option's value */
    }
    return NULL;
}

int cs_sweep_check_wanted(int argc, char **argv) {
    const char *f = check_file(argc, argv);
    return f && cs_sweep_is_spec(f);
}

int cs_sweep_check_command(int argc, char **argv) {
    sweep_opts o;
    memset(&o, 0, sizeof o);
    int rc = parse_opts(argc, argv, &o, 0);
    if (rc != 0) return rc < 0 ? 0 : rc;
    cs_sweep_spec *spec = read_spec(&o, 0);
    if (!spec) return EXIT_RUN;
    long n = 0;
    double *x = spec->error_count ? NULL : cs_sweep_samples(spec, &n);
    if (!spec->error_count && !x) cs_sweep_error(spec, 0, 0, "out of memory for %ld runs", spec->runs);
    if (!spec->error_count) cs_sweep_check(spec, x);
    if (spec->error_count) {
        print_errors(spec);
        rc = EXIT_BAD;
    } else {
        static const char *const methods[] = {"grid", "Monte Carlo", "Latin hypercube"};
        printf("%s: a valid sweep spec: %s of %ld runs over %d value%s of %s\n", spec->file,
               methods[spec->method], n, spec->var_count, spec->var_count == 1 ? "" : "s", spec->model);
    }
    free(x);
    cs_sweep_spec_free(spec);
    return rc;
}

int cs_sweep_command(int argc, char **argv) {
    int rank = 0, size = 1, local_ranks = 1;
#ifdef CS_MPI
    int provided;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
    MPI_Comm_size(node, &local_ranks);
    MPI_Comm_free(&node);
#else
    const char *world = getenv("OMPI_COMM_WORLD_SIZE");
    if (!world) world = getenv("PMI_SIZE");
    if (world && atoi(world) > 1) {
        const char *r = getenv("OMPI_COMM_WORLD_RANK");
        if (!r || atoi(r) == 0)
            fprintf(stderr,
                    "cablesim sweep: this cablesim is built without MPI, and %s copies of it would each "
                    "run the whole sweep: run cablesim-mpi under mpirun\n",
                    world);
        return EXIT_BAD;
    }
#endif
    sweep_opts o;
    memset(&o, 0, sizeof o);
    int rc = parse_opts(argc, argv, &o, rank);
    cs_sweep_spec *spec = NULL;
    double *x = NULL;
    long n = 0;
    if (rc == 0 && !(spec = read_spec(&o, rank))) rc = EXIT_RUN;
    if (rc == 0 && spec->error_count == 0 && !(x = cs_sweep_samples(spec, &n))) {
        cs_sweep_error(spec, 0, 0, "out of memory for %ld runs", spec->runs);
    }
    if (rc == 0 && rank == 0 && spec->error_count == 0) cs_sweep_check(spec, x);
    if (rc == 0 && spec->error_count) {
        if (rank == 0) print_errors(spec);
        rc = EXIT_BAD;
    }
#ifdef CS_MPI
    MPI_Bcast(&rc, 1, MPI_INT, 0, MPI_COMM_WORLD); /* rank 0 checked the model */
#endif
    if (rc != 0) {
        free(x);
        cs_sweep_spec_free(spec);
#ifdef CS_MPI
        MPI_Finalize();
#endif
        return rc < 0 ? 0 : rc;
    }
    int threads = thread_count(o.threads, local_ranks);
    long local_n = n > rank ? (n - rank + size - 1) / size : 0;
    cs_sweep_result *mine = calloc((size_t)(local_n > 0 ? local_n : 1), sizeof *mine);
    cs_sweep_result *all = rank == 0 ? calloc((size_t)(n > 0 ? n : 1), sizeof *all) : NULL;
    if (!mine || (rank == 0 && !all)) {
        fprintf(stderr, "cablesim sweep: out of memory for %ld results\n", n);
#ifdef CS_MPI
        MPI_Abort(MPI_COMM_WORLD, EXIT_RUN);
#endif
        return EXIT_RUN;
    }
    progress p = {rank == 0 && !o.quiet, isatty(STDERR_FILENO), size, 0, local_n, now(), now()};
    if (rank == 0 && !o.quiet)
        fprintf(stderr, "sweep: %ld runs of %s on %d rank%s x %d thread%s\n", n, spec->model, size,
                size == 1 ? "" : "s", threads, threads == 1 ? "" : "s");
    double start = now();
    int k = spec->var_count;
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
        char why[256];
        cs_loader *loader = cs_loader_create(NULL, why, sizeof why); /* one per thread (NULL: one per run) */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
        for (long m = 0; m < local_n; m++) {
            long i = rank + m * size;
            cs_sweep_run(spec, &x[i * k], loader, &mine[m]);
#ifdef _OPENMP
#pragma omp critical(cs_sweep_progress)
#endif
            {
                p.done++;
                progress_show(&p, 0);
            }
        }
        cs_loader_free(loader);
    }
    progress_show(&p, 1);
#ifdef CS_MPI
    int *counts = NULL, *displs = NULL;
    int bytes = (int)((size_t)local_n * sizeof *mine);
    cs_sweep_result *gathered = NULL;
    if (rank == 0) {
        counts = calloc((size_t)size, sizeof *counts);
        displs = calloc((size_t)size, sizeof *displs);
        gathered = calloc((size_t)(n > 0 ? n : 1), sizeof *gathered);
        if (!counts || !displs || !gathered) MPI_Abort(MPI_COMM_WORLD, EXIT_RUN);
    }
    MPI_Gather(&bytes, 1, MPI_INT, counts, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (rank == 0)
        for (int r = 1; r < size; r++)
            displs[r] = displs[r - 1] + counts[r - 1];
    MPI_Gatherv(mine, bytes, MPI_BYTE, gathered, counts, displs, MPI_BYTE, 0, MPI_COMM_WORLD);
    if (rank == 0) {
        for (int r = 0; r < size; r++) {
            const cs_sweep_result *from = (const cs_sweep_result *)((const char *)gathered + displs[r]);
            for (long m = 0; m < (long)((size_t)counts[r] / sizeof *mine); m++)
                all[r + m * size] = from[m];
        }
    }
    free(counts), free(displs), free(gathered);
#else
    for (long m = 0; m < local_n; m++)
        all[m] = mine[m];
#endif
    double wall = now() - start;
    if (rank == 0) {
        char dir[1024];
        if (o.out_dir) {
            snprintf(dir, sizeof dir, "%s", o.out_dir);
        } else {
            const char *base = strrchr(o.spec, '/');
            base = base ? base + 1 : o.spec;
            snprintf(dir, sizeof dir, "results/%.*s", (int)strcspn(base, "."), base);
        }
        long bad = 0;
        for (long i = 0; i < n; i++)
            bad += all[i].status != CS_RUN_OK;
        if (write_all(dir, spec, x, all, n) != 0) {
            rc = EXIT_RUN;
        } else {
            printf("sweep: %ld runs in %.3f s (%.3f runs/s) on %d rank%s x %d thread%s; %ld did not run to "
                   "the end\n",
                   n, wall, wall > 0 ? (double)n / wall : 0, size, size == 1 ? "" : "s", threads,
                   threads == 1 ? "" : "s", bad);
            printf("outputs: %s/{runs.csv,summary.md,summary.json,report.html,plots/study-*.png%s", dir,
                   spec->netcdf ? ",runs.nc" : "");
            for (int k = 0; k < spec->plot_count; k++) {
                char file[256];
                cs_sweep_plot_file(spec, k, file, sizeof file);
                printf(",%s", file);
            }
            printf("}\n");
        }
    }
    free(mine);
    free(all);
    free(x);
    cs_sweep_spec_free(spec);
#ifdef CS_MPI
    MPI_Bcast(&rc, 1, MPI_INT, 0, MPI_COMM_WORLD);
    MPI_Finalize();
#endif
    return rc;
}
