/* SPDX-License-Identifier: MIT */
/* cablesim sweep: read the spec, make every run's inputs (the same on every rank), share the runs to do
 * among MPI ranks (the k-th on rank k mod size) and, within a rank, among OpenMP threads (dynamic, one run
 * at a time), send each finished run to rank 0 as it ends (app/sweep_mpi.c), which journals it, and write
 * runs.csv, summary.md and summary.json there (and runs.nc and the spec's plots when asked). The inputs
 * depend only on the seed and the run index, and each run on nothing else, so the outputs are the same
 * for any thread or rank count.
 * SIGINT or SIGTERM during the runs lets the runs under way finish and starts no other: the outputs then
 * hold the runs done, marked partial, and `sweep --resume DIR` reads them back from runs.csv, runs the
 * rest and writes the whole study (runs.csv the same bytes as a sweep never stopped). */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <json-c/json.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
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

#include "sweep_mpi.h"
#endif

#include "cablesim/cablesim.h"
#include "cli.h"
#include "out/htmltext.h"
#include "out/outfile.h"
#include "out/plot.h"
#include "out/studyreport.h"
#include "out/sweepout.h"
#include "out/writers.h"
#include "study/sweep.h"
#include "sweepcmd.h"

enum { EXIT_RUN = CS_EXIT_RUN, EXIT_BAD = CS_EXIT_USAGE };

static const char sweep_usage[] =
    "Usage: cablesim sweep SPEC.yaml [-o DIR] [--threads N] [--runs N] [--seed S] [--set PATH=VALUE]...\n"
    "                      [--t-end T] [--dt T] [--netcdf] [--allow-path DIR]... [--quiet] [--force]\n"
    "  or:  cablesim sweep --resume DIR [--threads N] [--quiet] [--force]\n"
    "Runs the study of SPEC (a base model, the values to vary: grids, or Monte Carlo / Latin hypercube\n"
    "samples) and writes DIR/runs.csv, DIR/summary.md and DIR/summary.json (default DIR: results/<spec\n"
    "name>). --threads: OpenMP threads per process (default: OMP_NUM_THREADS or the cores, shared among\n"
    "the ranks of a machine). Under MPI (mpirun -n R cablesim-mpi sweep ...) the runs are shared among\n"
    "the R ranks. --runs and --seed replace the spec's; --set, --t-end and --dt apply to every run.\n"
    "--allow-path DIR: the model (SPEC's `model:`) and the files it names may be in DIR and its subfolders,\n"
    "beyond SPEC's folder (and its subfolders) and the parts library's.\n"
    "--netcdf (or `netcdf: true` in SPEC) also writes DIR/runs.nc: runs.csv's table as netCDF (CF-1.8).\n"
    "SPEC's `plot:` draws a response against a varied value in DIR/plots/<y>-vs-<x>.png (docs/sweep.md).\n"
    "DIR is checked and locked before any run; the files appear together at the end, listed in\n"
    "DIR/.cablesim-manifest, and an earlier study's files (its manifest's) that this one does not write\n"
    "are removed. A DIR holding a file no manifest lists is refused, unless --force: then the study is\n"
    "written beside such files, and none of them is removed. --quiet prints nothing but errors (no\n"
    "progress, no closing lines).\n"
    "SIGINT (Ctrl-C) or SIGTERM: the runs under way finish, no other starts, and DIR gets the runs done,\n"
    "marked partial (summary.md, summary.json \"partial\": true; exit status 130 or 143). --resume DIR\n"
    "reads them back from DIR/runs.csv, runs the others and writes the whole study; it refuses a DIR\n"
    "whose study changed (spec, model, values, cablesim).\n"
    "Exit status: 0 done, 1 the outputs failed, 2 a bad spec or command line, 128 + the signal: partial.\n";

static const cs_cli sweep_cli = {"sweep", sweep_usage};

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
    const char *spec, *out_dir, *resume;
    int threads, quiet, netcdf, force;
    long runs;
    const char *seed;
    const char *allow[64];
    int allow_count;
    const char *sets[256];
    int set_count;
    char set_text[256][1100]; /* --t-end and --dt as sets */
} sweep_opts;

static int sweep_bad_usage(int rank, const char *what, const char *arg) {
    if (rank == 0) cs_cli_usage_error(&sweep_cli, "%s%s%s", what, arg ? ": " : "", arg ? arg : "");
    return EXIT_BAD;
}

/* The command line into o. Returns 0, -1 after --help (exit 0), or EXIT_BAD. */
static int parse_opts(int argc, char **argv, sweep_opts *o, int rank) {
    enum { THREADS = 1000, RUNS, SEED, SET, T_END, DT, NETCDF, QUIET, RESUME, FORCE, ALLOW };
    static const struct option longopts[] = {
        {"out", required_argument, NULL, 'o'},   {"threads", required_argument, NULL, THREADS},
        {"runs", required_argument, NULL, RUNS}, {"seed", required_argument, NULL, SEED},
        {"set", required_argument, NULL, SET},   {"t-end", required_argument, NULL, T_END},
        {"dt", required_argument, NULL, DT},     {"netcdf", no_argument, NULL, NETCDF},
        {"quiet", no_argument, NULL, QUIET},     {"resume", required_argument, NULL, RESUME},
        {"force", no_argument, NULL, FORCE},     {"allow-path", required_argument, NULL, ALLOW},
        {"help", no_argument, NULL, 'h'},        {NULL, 0, NULL, 0}};
    int v, study = 0; /* options that define the study, which --resume takes from DIR */
    optind = 1;
    opterr = 0;
    while ((v = rank == 0 ? cs_cli_next(&sweep_cli, argc, argv, "ho:", longopts)
                          : getopt_long(argc - 1, argv + 1, ":ho:", longopts, NULL)) != -1) {
        char *end;
        switch (v) {
        case 'h':
            if (rank == 0) cs_cli_help(&sweep_cli);
            return -1;
        case 'o':
            o->out_dir = optarg;
            study = 1;
            break;
        case THREADS:
            o->threads = (int)strtol(optarg, &end, 10);
            if (*end || end == optarg || o->threads < 1 || o->threads > 1024)
                return sweep_bad_usage(rank, "--threads takes 1 to 1024", optarg);
            break;
        case RUNS:
            o->runs = strtol(optarg, &end, 10);
            if (*end || end == optarg || o->runs < 1 || o->runs > CS_SWEEP_MAX_RUNS)
                return sweep_bad_usage(rank, "--runs takes 1 to 1000000", optarg);
            study = 1;
            break;
        case SEED:
            o->seed = optarg;
            study = 1;
            break;
        case SET:
        case T_END:
        case DT:
            if (o->set_count == 256)
                return sweep_bad_usage(rank, "more than 256 --set, --t-end and --dt", optarg);
            if (v == SET) {
                o->sets[o->set_count] = optarg;
            } else {
                snprintf(o->set_text[o->set_count], sizeof o->set_text[0], "scenario.%s=%s",
                         v == T_END ? "t_end" : "dt", optarg);
                o->sets[o->set_count] = o->set_text[o->set_count];
            }
            o->set_count++;
            study = 1;
            break;
        case NETCDF:
            o->netcdf = 1;
            study = 1;
            break;
        case ALLOW:
            if (o->allow_count == 64) return sweep_bad_usage(rank, "more than 64 --allow-path", optarg);
            o->allow[o->allow_count++] = optarg;
            study = 1;
            break;
        case QUIET:
            o->quiet = 1;
            break;
        case FORCE:
            o->force = 1;
            break;
        case RESUME:
            o->resume = optarg;
            break;
        default:
            return EXIT_BAD;
        }
    }
    int operands = argc - 1 - optind;
    if (o->resume && (operands > 0 || study))
        return sweep_bad_usage(
            rank,
            "--resume DIR takes the study as DIR/summary.json records it: no SPEC, -o, --runs, "
            "--seed, --set, --t-end, --dt, --netcdf or --allow-path with it",
            operands > 0 ? argv[1 + optind] : NULL);
    if (o->resume) return 0;
    if (operands > 1) return sweep_bad_usage(rank, "more than one spec file", argv[2 + optind]);
    if (operands < 1) return sweep_bad_usage(rank, "no spec file", NULL);
    o->spec = argv[1 + optind];
    return 0;
}

/* ---- the record --resume reads back (summary.json's "resume") ---- */

/* {"spec": the spec's absolute path, "spec_as_given" and the "cwd" it was given in, "runs", "seed", "set":
 * the command line's fixed values, "netcdf", "allow": the --allow-path folders, absolute}. */
static char *resume_record(const sweep_opts *o, const char *as_given, const char *cwd) {
    char real[PATH_MAX], *buf = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&buf, &size);
    if (!f) return NULL;
    fputs("{\"spec\":", f);
    cs_json_string(f, realpath(o->spec, real) ? real : o->spec);
    fputs(",\"spec_as_given\":", f);
    cs_json_string(f, as_given);
    fputs(",\"cwd\":", f);
    cs_json_string(f, cwd);
    if (o->runs > 0)
        fprintf(f, ",\"runs\":%ld,\"seed\":", o->runs);
    else
        fputs(",\"runs\":null,\"seed\":", f);
    if (o->seed)
        cs_json_string(f, o->seed);
    else
        fputs("null", f);
    fputs(",\"set\":[", f);
    for (int i = 0; i < o->set_count; i++) {
        if (i) fputc(',', f);
        cs_json_string(f, o->sets[i]);
    }
    fprintf(f, "],\"netcdf\":%s,\"allow\":[", o->netcdf ? "true" : "false");
    for (int i = 0; i < o->allow_count; i++) {
        if (i) fputc(',', f);
        cs_json_string(f, realpath(o->allow[i], real) ? real : o->allow[i]);
    }
    fputs("]}", f);
    fclose(f);
    return buf;
}

/* The string at key of obj into out (NULL, or not a string: ""). 0, or -1 if it does not fit. */
static int json_text_at(json_object *obj, const char *key, char *out, size_t size) {
    json_object *v;
    out[0] = '\0';
    if (!json_object_object_get_ex(obj, key, &v) || !json_object_is_type(v, json_type_string)) return 0;
    return snprintf(out, size, "%s", json_object_get_string(v)) < (int)size ? 0 : -1;
}

/* The strings of a JSON array into store (slots of width bytes), each slot's address into to[*count],
 * up to max. 0, or -1 when an entry is not a string or does not fit. */
static int json_texts(json_object *list, char *store, size_t width, const char **to, int *count, int max) {
    for (size_t i = 0; i < json_object_array_length(list) && *count < max; i++) {
        json_object *e = json_object_array_get_idx(list, i);
        char *slot = store + (size_t)*count * width;
        if (!json_object_is_type(e, json_type_string) ||
            snprintf(slot, width, "%s", json_object_get_string(e)) >= (int)width)
            return -1;
        to[(*count)++] = slot;
    }
    return 0;
}

typedef struct resumed {
    char version[64], model_hash[20], inputs_hash[20];
    char spec_as_given[PATH_MAX], cwd[PATH_MAX]; /* the spec as the stopped sweep's command line gave it */
    int partial;
    char *journal;      /* DIR/.cablesim-journal, when a killed sweep left one (NULL: none) */
    const char *rows;   /* its runs.csv, after its first line */
    size_t rows_length; /* their length */
} resumed;

/* The record of the study into o (its strings kept in static storage) and r: the first line of
 * DIR/.cablesim-journal when a sweep killed before it wrote its outputs left one (r->journal), else
 * DIR/summary.json's. 0, or -1 with why filled. */
static int read_resume(const char *dir, sweep_opts *o, resumed *r, char *why, size_t why_size) {
    static char spec[PATH_MAX], seed[64], sets[256][1100], allow[64][PATH_MAX];
    char path[1200];
    size_t length = 0;
    if (!(r->journal = cs_out_journal_read(dir, &length, why, why_size)) && why[0]) return -1;
    char *eol = r->journal ? strchr(r->journal, '\n') : NULL;
    if (eol) { /* its first line is the record; runs.csv follows */
        *eol = '\0';
        r->rows = eol + 1;
        r->rows_length = length - (size_t)(eol + 1 - r->journal);
    }
    snprintf(path, sizeof path, "%s/%s", dir, r->journal ? CS_OUT_JOURNAL : "summary.json");
    FILE *probe = r->journal ? NULL : fopen(path, "r");
    if (!r->journal && !probe) {
        snprintf(why, why_size, "%s: %s (expected the summary of a sweep written there)", path,
                 strerror(errno));
        return -1;
    }
    if (probe) fclose(probe);
    json_object *root = r->journal ? json_tokener_parse(r->journal) : json_object_from_file(path),
                *rec = NULL, *about = NULL, *v;
    int bad = !root || !json_object_object_get_ex(root, "resume", &rec) ||
              !json_object_is_type(rec, json_type_object) ||
              json_text_at(rec, "spec", spec, sizeof spec) != 0 || !spec[0];
    char here[PATH_MAX];
    if (!bad && json_text_at(rec, "spec_as_given", r->spec_as_given, sizeof r->spec_as_given) == 0 &&
        json_text_at(rec, "cwd", r->cwd, sizeof r->cwd) == 0 && getcwd(here, sizeof here) &&
        strcmp(here, r->cwd) == 0)
        snprintf(spec, sizeof spec, "%s", r->spec_as_given); /* as it was given, where it was given */
    if (!bad && json_object_object_get_ex(rec, "runs", &v)) o->runs = v ? json_object_get_int64(v) : 0;
    if (!bad && json_object_object_get_ex(rec, "seed", &v) && v) {
        bad = json_text_at(rec, "seed", seed, sizeof seed) != 0;
        o->seed = seed;
    }
    json_object *list = NULL;
    bad = bad || !json_object_object_get_ex(rec, "set", &list) || !json_object_is_type(list, json_type_array);
    if (!bad) bad = json_texts(list, sets[0], sizeof sets[0], o->sets, &o->set_count, 256) != 0;
    if (!bad && json_object_object_get_ex(rec, "netcdf", &v)) o->netcdf = json_object_get_boolean(v);
    if (!bad && json_object_object_get_ex(rec, "allow", &list)) { /* none: a study that needed no leave */
        bad = !json_object_is_type(list, json_type_array) ||
              json_texts(list, allow[0], sizeof allow[0], o->allow, &o->allow_count, 64) != 0;
    }
    r->partial = !bad && json_object_object_get_ex(root, "partial", &v) && json_object_get_boolean(v);
    if (!bad && json_object_object_get_ex(root, "cablesim", &about)) {
        bad = json_text_at(about, "version", r->version, sizeof r->version) != 0 ||
              json_text_at(about, "model_hash", r->model_hash, sizeof r->model_hash) != 0;
    }
    if (!bad) bad = json_text_at(root, "inputs_hash", r->inputs_hash, sizeof r->inputs_hash) != 0;
    if (root) json_object_put(root);
    if (bad) {
        snprintf(why, why_size,
                 "%s: no record of the study to resume (written by an older cablesim, or not by "
                 "cablesim sweep)",
                 path);
        return -1;
    }
    o->spec = spec;
    o->out_dir = dir;
    return 0;
}

/* runs.csv, summary.md, summary.json, then the spec's plots (files 3 on), the study's own figures and
 * report.html, and runs.nc (not for a partial sweep), begun on out (opened before the runs) and renamed
 * together; nothing is left if one fails, and an earlier study's files (its manifest's) that this one
 * does not write are removed. */
static int write_all(cs_outdir *out, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                     long n, int partial) {
    char why[512] = "";
    int rc = 0;
    static const char *const names[] = {"runs.csv", "summary.md", "summary.json"};
    if (rc == 0) rc = cs_out_subdir(out, "plots", why, sizeof why);
    int study = 3 + spec->plot_count; /* then the study's figures, then its page */
    for (int k = 0; rc == 0 && k < study + CS_STUDY_FIGURES + 1; k++) {
        char name[256];
        if (k < 3)
            snprintf(name, sizeof name, "%s", names[k]);
        else if (k < study)
            cs_sweep_plot_file(spec, k - 3, name, sizeof name);
        else if (k < study + CS_STUDY_FIGURES) {
            if (!cs_study_figure_shown(k - study, spec, x, r, n)) continue;
            cs_study_figure_file(k - study, name, sizeof name);
        } else
            snprintf(name, sizeof name, "report.html");
        FILE *f = cs_out_begin(out, name, why, sizeof why);
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
        rc = cs_out_finish(out, f, rc, why, sizeof why);
    }
    cs_plot_release(); /* after the last plot */
    if (rc == 0 && spec->netcdf && !partial) {
        char path[1200], nc_why[200];
        rc = cs_out_begin_path(out, "runs.nc", path, sizeof path, why, sizeof why);
        if (rc == 0 && (rc = cs_sweep_write_netcdf(path, spec, x, r, n, nc_why, sizeof nc_why)) != 0)
            snprintf(why, sizeof why, "%.280s/runs.nc: %s", out->dir, nc_why);
        if (rc == 0) rc = cs_out_end_path(out, why, sizeof why);
    }
    if (rc == 0) rc = cs_out_commit(out, why, sizeof why);
    if (rc != 0) {
        cs_out_abort(out);
        fprintf(stderr,
                "cablesim sweep: nothing written: %s; the runs done are kept in %s/%s: `cablesim sweep "
                "--resume %s` writes the study once that is put right\n",
                why, out->dir, CS_OUT_JOURNAL, out->dir);
    }
    return rc;
}

/* ---- stopping on a signal ---- */

static volatile sig_atomic_t stop_signal = 0;

/* The first SIGINT or SIGTERM asks the sweep to stop starting runs; a second one does what it does by
 * default. */
static void on_signal(int sig) {
    if (stop_signal) {
        signal(sig, SIG_DFL);
        raise(sig); /* delivered when this handler returns */
        return;
    }
    stop_signal = sig;
}

static void catch_signals(int on) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on ? on_signal : SIG_DFL;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
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
    cs_sweep_spec_confine(spec, o->allow, o->allow_count);
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
        cs_term_text(stderr, spec->errors[i]), fputc('\n', stderr);
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

/* The file argument of `cablesim check FILE [--set PATH=VALUE]...`: the first word that is not an option or
 * an option's value. */
static const char *check_file(int argc, char **argv) {
    static const char *const valued[] = {"-o",    "--out",   "--threads", "--runs",   "--seed",
                                         "--set", "--t-end", "--dt",      "--resume", "--allow-path"};
    for (int i = 2; i < argc; i++) {
        if (argv[i][0] != '-') return argv[i];
        for (size_t k = 0; k < sizeof valued / sizeof valued[0]; k++)
            if (strcmp(argv[i], valued[k]) == 0) {
                i++; /* its value */
                break;
            }
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

/* The sweep's output folder: DIR, or results/<the spec's name>. */
static void out_dir_of(const sweep_opts *o, char *dir, size_t size) {
    if (o->out_dir) {
        snprintf(dir, size, "%s", o->out_dir);
    } else {
        const char *base = strrchr(o->spec, '/');
        base = base ? base + 1 : o->spec;
        int n = (int)strcspn(base, ".");
        snprintf(dir, size, "results/%.*s", n ? n : 5, n ? base : "study"); /* ".x.yaml": results/study */
    }
}

/* --resume: the runs of DIR/runs.csv, or of the journal a killed sweep left, into all (the others left
 * pending), after checking that the study is the one DIR holds. Returns how many were read, or -1 (why
 * printed). */
static long read_done(const char *dir, const cs_sweep_spec *spec, const resumed *was, const double *x,
                      cs_sweep_result *all, long n) {
    char hash[17], path[1200], why[600];
    if (strcmp(was->version, CS_VERSION_STRING) != 0) {
        fprintf(stderr,
                "cablesim sweep: %s was written by cablesim %s, this is %s: its runs may differ from this "
                "one's; run the study again without --resume\n",
                dir, was->version, CS_VERSION_STRING);
        return -1;
    }
    snprintf(hash, sizeof hash, "%016llx", spec->origin.model_hash);
    if (!spec->origin.has_model_hash || strcmp(hash, was->model_hash) != 0 ||
        strcmp((snprintf(hash, sizeof hash, "%016llx", spec->origin.inputs_hash), hash), was->inputs_hash) !=
            0) {
        fprintf(
            stderr,
            "cablesim sweep: %s: the study has changed since it was stopped (its model, %s, or its values): "
            "run it again without --resume\n",
            dir, spec->model);
        return -1;
    }
    snprintf(path, sizeof path, "%s/%s", dir, was->journal ? CS_OUT_JOURNAL : "runs.csv");
    FILE *f = was->journal ? fmemopen((void *)was->rows, was->rows_length ? was->rows_length : 1, "r")
                           : fopen(path, "r");
    if (!f) {
        fprintf(stderr, "cablesim sweep: %s: %s\n", path, strerror(errno));
        return -1;
    }
    long got = cs_sweep_read_runs(f, path, spec, x, all, n, was->journal != NULL, why, sizeof why);
    fclose(f);
    if (got < 0) fprintf(stderr, "cablesim sweep: %s\n", why);
    return got;
}

/* The journal of the runs (DIR/.cablesim-journal): the study's record and the runs done (a resumed
 * sweep's), before any run. */
static int start_journal(cs_outdir *out, const cs_sweep_spec *spec, const double *x,
                         const cs_sweep_result *all, long n, char *why, size_t why_size) {
    char *text = NULL;
    size_t length = 0;
    FILE *f = open_memstream(&text, &length);
    int rc = f ? cs_sweep_write_journal_start(f, spec, x, all, n, why, why_size) : -1;
    if (f) fclose(f);
    if (rc != 0 || !text) snprintf(why, why_size, "out of memory for the journal");
    if (rc == 0 && text) rc = cs_out_journal_start(out, text, length, why, why_size);
    free(text);
    return rc;
}

/* Append a finished run to the journal (append and fsync: a kill -9 after it keeps it). A journal that
 * cannot be written is said once; the runs go on, and the outputs at the end hold them. */
static void journal_run(cs_outdir *out, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                        long i) {
    static int failed;
    char *text = NULL, why[1600];
    size_t length = 0;
    FILE *f = failed ? NULL : open_memstream(&text, &length);
    if (!f) return;
    cs_sweep_write_run_row(f, spec, x, r, i);
    fclose(f);
    if (cs_out_journal_add(out, text, length, why, sizeof why) != 0) {
        failed = 1;
        fprintf(stderr, "cablesim sweep: %s: the runs from now on are not journalled (a kill loses them)\n",
                why);
    }
    free(text);
}

/* Rank 0's record of a finished run, its own or another rank's: its result and its journal row. An MPI
 * sweep's receiver thread takes the other ranks' runs beside rank 0's threads, hence the lock. */
typedef struct taker {
    cs_outdir *out;
    const cs_sweep_spec *spec;
    const double *x;
    cs_sweep_result *all;
} taker;

static void take_run(void *ctx, long i, const cs_sweep_result *r) {
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    taker *t = ctx;
    pthread_mutex_lock(&lock);
    t->all[i] = *r;
    journal_run(t->out, t->spec, t->x, r, i);
    pthread_mutex_unlock(&lock);
}

static const char *signal_name(int sig) {
    return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal";
}

int cs_sweep_command(int argc, char **argv) {
    int rank = 0, size = 1, local_ranks = 1;
    char command[8192];
    cs_cli_command_line(argc, argv, command, sizeof command); /* as typed: getopt_long reorders argv */
#ifdef CS_MPI
    int provided;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided); /* sweep_mpi.h */
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (provided < MPI_THREAD_SERIALIZED) {
        if (rank == 0)
            fprintf(stderr, "cablesim sweep: this MPI gives no MPI_THREAD_SERIALIZED, which the sweep's "
                            "journal of every rank's runs needs\n");
        MPI_Finalize();
        return EXIT_RUN;
    }
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
    static resumed was;
    char as_given[PATH_MAX] = "", cwd[PATH_MAX] = "";
    int rc = parse_opts(argc, argv, &o, rank);
    if (!getcwd(cwd, sizeof cwd)) cwd[0] = '\0';
    if (rc == 0 && !o.resume) snprintf(as_given, sizeof as_given, "%s", o.spec);
    if (rc == 0 && o.resume) {
        char why[1400];
        if (read_resume(o.resume, &o, &was, why, sizeof why) != 0) {
            if (rank == 0) fprintf(stderr, "cablesim sweep: --resume: %s\n", why);
            rc = EXIT_BAD;
        } else if (strcmp(was.cwd, cwd) == 0) {
            snprintf(as_given, sizeof as_given, "%s", was.spec_as_given);
        } else {
            snprintf(as_given, sizeof as_given, "%s", o.spec);
        }
    }
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
    /* rank 0: the output folder, checked before any run; --resume: the runs done */
    char dir[1024] = "", *record = NULL;
    cs_outdir out;
    int out_open = 0;
    cs_sweep_result *all = NULL;
    long done = 0;
    if (rc == 0 && rank == 0) {
        char why[600];
        out_dir_of(&o, dir, sizeof dir);
        spec->origin.command = command;
        spec->origin.dir = dir;
        spec->origin.resume = record = resume_record(&o, as_given, cwd);
        spec->origin.has_model_hash = cs_sweep_model_hash(spec, &spec->origin.model_hash) == 0;
        spec->origin.inputs_hash = cs_sweep_inputs_hash(spec, x, n);
        all = calloc((size_t)(n > 0 ? n : 1), sizeof *all);
        for (long i = 0; all && i < n; i++)
            all[i].pending = 1;
        if (!all || !record) {
            fprintf(stderr, "cablesim sweep: out of memory for %ld results\n", n);
            rc = EXIT_RUN;
        } else if (o.resume && !was.partial) {
            if (!o.quiet) printf("sweep: %s holds the whole study (%ld runs): nothing to run\n", dir, n);
            rc = -1;
        } else if (o.resume && (done = read_done(dir, spec, &was, x, all, n)) < 0) {
            rc = EXIT_BAD;
        } else if (cs_out_open(&out, dir, o.force ? CS_OUT_FORCE : 0, why, sizeof why) != 0) {
            fprintf(stderr, "cablesim sweep: nothing run: %s\n", why);
            rc = EXIT_RUN;
        } else if (out_open = 1, start_journal(&out, spec, x, all, n, why, sizeof why) != 0) {
            fprintf(stderr, "cablesim sweep: nothing run: %s\n", why);
            rc = EXIT_RUN;
        }
    }
    /* the runs to do, the same list on every rank */
    char *todo_mask = NULL;
    long *todo = NULL, todo_n = 0;
#ifdef CS_MPI
    MPI_Bcast(&rc, 1, MPI_INT, 0, MPI_COMM_WORLD); /* rank 0 checked the model and the folder */
    MPI_Bcast(&n, 1, MPI_LONG, 0, MPI_COMM_WORLD);
#endif
    if (rc == 0) {
        todo_mask = malloc((size_t)(n > 0 ? n : 1));
        todo = malloc((size_t)(n > 0 ? n : 1) * sizeof *todo);
        if (!todo_mask || !todo) {
            fprintf(stderr, "cablesim sweep: out of memory for %ld runs\n", n);
#ifdef CS_MPI
            MPI_Abort(MPI_COMM_WORLD, EXIT_RUN);
#endif
            rc = EXIT_RUN;
        }
        for (long i = 0; rc == 0 && rank == 0 && i < n; i++)
            todo_mask[i] = (char)all[i].pending;
#ifdef CS_MPI
        if (rc == 0) MPI_Bcast(todo_mask, (int)n, MPI_CHAR, 0, MPI_COMM_WORLD);
#endif
        for (long i = 0; rc == 0 && i < n; i++)
            if (todo_mask[i]) todo[todo_n++] = i;
    }
    if (rc != 0) {
        if (out_open) cs_out_abort(&out);
        free(x), free(all), free(todo), free(todo_mask), free(record);
        cs_sweep_spec_free(spec);
#ifdef CS_MPI
        MPI_Finalize();
#endif
        return rc < 0 ? 0 : rc;
    }
    int threads = thread_count(o.threads, local_ranks);
    long local_n = todo_n > rank ? (todo_n - rank + size - 1) / size : 0;
    cs_sweep_result *mine = calloc((size_t)(local_n > 0 ? local_n : 1), sizeof *mine);
    if (!mine) {
        fprintf(stderr, "cablesim sweep: out of memory for %ld results\n", todo_n);
#ifdef CS_MPI
        MPI_Abort(MPI_COMM_WORLD, EXIT_RUN);
#endif
        return EXIT_RUN;
    }
    for (long m = 0; m < local_n; m++)
        mine[m].pending = 1;
    progress p = {rank == 0 && !o.quiet, isatty(STDERR_FILENO), size, 0, local_n, now(), now()};
    if (rank == 0 && !o.quiet)
        fprintf(stderr, "sweep: %ld runs of %s on %d rank%s x %d thread%s%s\n", todo_n, spec->model, size,
                size == 1 ? "" : "s", threads, threads == 1 ? "" : "s",
                o.resume ? " (the rest of a stopped study)" : "");
    const char *stop_after_text = getenv("CABLESIM_SWEEP_STOP_AFTER");
    long stop_after = stop_after_text ? strtol(stop_after_text, NULL, 10) : 0;
    stop_signal = 0;
    catch_signals(1);
    double start = now();
    int k = spec->var_count;
    taker t = {&out, spec, x, all};
#ifdef CS_MPI
    cs_sweep_receiver rx = {0};
    if (rank == 0 && size > 1 && cs_sweep_receive_start(&rx, size, take_run, &t) != 0) {
        fprintf(stderr, "cablesim sweep: cannot start the thread that receives the other ranks' runs\n");
        MPI_Abort(MPI_COMM_WORLD, EXIT_RUN);
    }
#endif
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
#endif
    {
        char why[256];
        cs_loader *loader = cs_sweep_loader(spec, why, sizeof why); /* one per thread (NULL: one per run) */
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
        for (long m = 0; m < local_n; m++) {
            if (stop_signal) continue; /* stopped: start no other run */
            long i = todo[rank + m * size];
            cs_sweep_run(spec, &x[i * k], loader, &mine[m]);
#ifdef _OPENMP
#pragma omp critical(cs_sweep_progress)
#endif
            {
                p.done++;
#ifdef CS_MPI
                if (rank > 0) cs_sweep_send_run(i, &mine[m]);
#endif
                if (rank == 0) take_run(&t, i, &mine[m]);
                progress_show(&p, 0);
                if (stop_after > 0 && p.done == stop_after) raise(SIGINT); /* CABLESIM_SWEEP_STOP_AFTER */
            }
        }
        cs_loader_free(loader);
    }
    catch_signals(0);
    int stopped = stop_signal;
    if (!stopped)
        progress_show(&p, 1);
    else if (p.on && p.tty)
        fputc('\n', stderr);
#ifdef CS_MPI
    if (rank == 0 && size > 1)
        cs_sweep_receive_end(&rx);
    else if (rank > 0)
        cs_sweep_send_done();
    MPI_Allreduce(MPI_IN_PLACE, &stopped, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
#endif
    double wall = now() - start;
    if (rank == 0) {
        long bad = 0, pending = 0;
        for (long i = 0; i < n; i++) {
            pending += all[i].pending;
            bad += !all[i].pending && all[i].status != CS_RUN_OK;
        }
        spec->origin.stopped_by = pending ? signal_name(stopped) : NULL;
        if (write_all(&out, spec, x, all, n, pending > 0) != 0) {
            rc = EXIT_RUN;
        } else if (pending) {
            fprintf(stderr,
                    "cablesim sweep: stopped by %s: %ld of %ld runs done, written to %s (partial); `cablesim "
                    "sweep --resume %s` runs the other %ld\n",
                    signal_name(stopped), n - pending, n, dir, dir, pending);
            rc = 128 + (stopped ? stopped : SIGINT);
        } else if (!o.quiet) {
            printf("sweep: %ld runs in %.3f s (%.3f runs/s) on %d rank%s x %d thread%s; %ld did not run to "
                   "the end\n",
                   todo_n, wall, wall > 0 ? (double)todo_n / wall : 0, size, size == 1 ? "" : "s", threads,
                   threads == 1 ? "" : "s", bad);
            if (o.resume)
                printf("sweep: %ld runs read back from %s/runs.csv, %ld run now\n", done, dir, todo_n);
            printf("outputs: %s/{runs.csv,summary.md,summary.json,report.html,plots/study-*.png%s", dir,
                   spec->netcdf ? ",runs.nc" : "");
            for (int k = 0; k < spec->plot_count; k++) {
                char file[256];
                cs_sweep_plot_file(spec, k, file, sizeof file);
                printf(",%s", file);
            }
            printf("}\n");
        }
    } else if (stopped) {
        rc = 128 + stopped;
    }
    free(mine);
    free(all);
    free(x);
    free(todo), free(todo_mask), free(record), free(was.journal);
    cs_sweep_spec_free(spec);
#ifdef CS_MPI
    MPI_Bcast(&rc, 1, MPI_INT, 0, MPI_COMM_WORLD);
    MPI_Finalize();
#endif
    return rc;
}
