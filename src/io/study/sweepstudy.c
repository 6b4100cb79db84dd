/* SPDX-License-Identifier: MIT */
/* A whole sweep (sweepstudy.h): the spec with the command line's changes, the output folder, the journal
 * of the runs, the runs shared among ranks and threads with their progress, and the outputs. */
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cablesim/cablesim.h"
#include "out/htmltext.h"
#include "out/outfile.h"
#include "out/plot.h"
#include "out/studyreport.h"
#include "out/sweepout.h"
#include "out/writers.h"
#include "status.h"
#include "study/sweepresume.h"
#include "study/sweepstudy.h"

enum { EXIT_RUN = CS_SWEEP_EXIT_RUN, EXIT_BAD = CS_SWEEP_EXIT_USAGE };

/* ---- the spec and the folder ---- */

/* The spec of o->spec with the command line's changes (--set, --runs, --seed, --netcdf, --allow-path);
 * its problems are in its errors. NULL if memory is short (said on stderr when loud). */
static cs_sweep_spec *study_spec(cs_sweep_options *o, int loud) {
    cs_error err;
    cs_units *units = cs_units_open(&err);
    if (!units) {
        if (loud) cs_sweep_say(o, "%s", err.message);
        return NULL;
    }
    cs_sweep_spec *spec = cs_sweep_spec_read(o->spec, units);
    cs_units_free(units);
    if (!spec) {
        if (loud) cs_sweep_say(o, "out of memory");
        return NULL;
    }
    cs_sweep_plots_check(spec);
    cs_sweep_spec_confine(spec, o->allow, o->allow_count);
    for (int i = 0; i < o->set_count; i++)
        cs_sweep_spec_add_set(spec, o->sets[i], o->sets_given[i]);
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

void cs_sweep_say(cs_sweep_options *o, const char *fmt, ...) {
    char text[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (o->errors) fprintf(o->errors, "cablesim sweep: %s\n", text), fflush(o->errors);
    if (!o->why[0]) snprintf(o->why, sizeof o->why, "%.511s", text);
}

/* The spec's errors on o->errors (NULL: none); the first into o->why. */
static void print_errors(const cs_sweep_spec *spec, cs_sweep_options *o) {
    for (int i = 0; o->errors && i < spec->error_count; i++)
        cs_term_text(o->errors, spec->errors[i]), fputc('\n', o->errors);
    if (spec->error_count > 0 && !o->why[0]) /* the first, for a cs_error */
        snprintf(o->why, sizeof o->why, "%.440s%s", spec->errors[0],
                 spec->error_count > 1 ? " (and more problems)" : "");
    cs_sweep_say(o, "%s: %d problem%s, nothing run", spec->file, spec->error_count,
                 spec->error_count == 1 ? "" : "s");
}

/* The sweep's output folder: DIR, or results/<the spec's name>. */
static void out_dir_of(const cs_sweep_options *o, char *dir, size_t size) {
    if (o->out_dir) {
        snprintf(dir, size, "%s", o->out_dir);
    } else {
        const char *base = strrchr(o->spec, '/');
        base = base ? base + 1 : o->spec;
        int n = (int)strcspn(base, ".");
        snprintf(dir, size, "results/%.*s", n ? n : 5, n ? base : "study"); /* ".x.yaml": results/study */
    }
}

/* A new study (not --resume, not force) into dir refused while dir holds a stopped study with runs saved,
 * which the new one's journal and outputs would replace: said (the folder, its runs, the two ways on) and
 * 1; else 0. */
static int stopped_study_kept(cs_sweep_options *o, const char *dir) {
    const char *where;
    long saved = o->resume || o->force ? 0 : cs_sweep_stopped_runs(dir, &where);
    if (saved <= 0) return 0;
    char resume[1100];
    if (o->force_given)
        snprintf(resume, sizeof resume, "`cablesim sweep --resume %s`", dir);
    else
        snprintf(resume, sizeof resume, "cs_sweep_def's resume set to %s", dir);
    cs_sweep_say(o,
                 "nothing run: %s holds a stopped study, %ld run%s done saved in %s/%s: %s runs the rest of "
                 "it, or %s starts this study afresh and replaces it",
                 dir, saved, saved == 1 ? "" : "s", dir, where, resume,
                 o->force_given ? o->force_given : "cs_sweep_def's force set to 1");
    return 1;
}

/* Whether dir holds a lock's file: a sweep may be writing its journal there (or one killed left it). */
static int lock_there(const char *dir) {
    char path[1200];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", dir, CS_OUT_LOCK);
    return lstat(path, &st) == 0;
}

/* ---- progress: a bar on a terminal, plain lines every few seconds otherwise ---- */

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct progress {
    FILE *f; /* NULL: none */
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
        fprintf(p->f, "\r[%s] %ld/%ld runs%s  %.2f runs/s  %s left   ", bar, p->done, p->total, who, rate,
                left);
        if (final) fputc('\n', p->f);
    } else {
        fprintf(p->f, "sweep: %ld/%ld runs%s (%.0f%%), %.2f runs/s, about %s left\n", p->done, p->total, who,
                p->total ? 100.0 * (double)p->done / (double)p->total : 100.0, rate, left);
    }
    fflush(p->f);
}

/* ---- the journal and the outputs ---- */

/* The journal of the runs (DIR/.cablesim-journal): the study's record and the runs done (a resumed
 * sweep's), before any run. CS_OK, or CS_ERR_MEMORY or cs_out_journal_start's status with err filled. */
static cs_status start_journal(cs_outdir *out, const cs_sweep_spec *spec, const double *x,
                               const cs_sweep_result *all, long n, cs_error *err) {
    char *text = NULL;
    size_t length = 0;
    FILE *f = open_memstream(&text, &length);
    cs_status rc = f ? cs_sweep_write_journal_start(f, spec, x, all, n, err) : CS_ERR_MEMORY;
    if (f) fclose(f);
    if (rc != CS_OK || !text)
        rc = cs_error_set(err, CS_ERR_MEMORY, "out of memory for the journal");
    else
        rc = cs_out_journal_start(out, text, length, err);
    free(text);
    return rc;
}

/* Append a finished run to the journal (append and fsync: a kill -9 after it keeps it). A journal that
 * cannot be written is said once (*failed, the study's own); the runs go on, and the outputs at the end
 * hold them. */
static void journal_run(cs_outdir *out, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                        long i, int *failed, cs_sweep_options *o) {
    char *text = NULL;
    cs_error err;
    size_t length = 0;
    FILE *f = *failed ? NULL : open_memstream(&text, &length);
    if (!f) return;
    cs_sweep_write_run_row(f, spec, x, r, i);
    fclose(f);
    if (cs_out_journal_add(out, text, length, &err) != CS_OK) {
        *failed = 1;
        cs_sweep_say(o, "%s: the runs from now on are not journalled (a kill loses them)", err.message);
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
    int journal_failed; /* the journal could not be written (said once) */
    cs_sweep_options *o;
} taker;

static void take_run(void *ctx, long i, const void *result) {
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    taker *t = ctx;
    const cs_sweep_result *r = result;
    pthread_mutex_lock(&lock);
    t->all[i] = *r;
    journal_run(t->out, t->spec, t->x, r, i, &t->journal_failed, t->o);
    pthread_mutex_unlock(&lock);
}

static const char *signal_name(int sig) {
    return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal";
}

/* runs.csv, summary.md, summary.json, then the spec's plots (files 3 on), the study's own figures and
 * report.html, and runs.nc (not for a partial sweep), begun on out (opened before the runs) and renamed
 * together; nothing is left if one fails, and an earlier study's files (its manifest's) that this one
 * does not write are removed. */
static int write_all(cs_outdir *out, const cs_sweep_spec *spec, const double *x, const cs_sweep_result *r,
                     long n, int partial, cs_sweep_options *o) {
    cs_error err = {CS_OK, ""};
    static const char *const names[] = {"runs.csv", "summary.md", "summary.json"};
    cs_status rc = cs_out_subdir(out, "plots", &err);
    int study = 3 + spec->plot_count; /* then the study's figures, then its page */
    for (int k = 0; rc == CS_OK && k < study + CS_STUDY_FIGURES + 1; k++) {
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
        FILE *f = cs_out_begin(out, name, &err);
        if (!f) {
            rc = err.status;
            break;
        }
        rc = k == 0      ? cs_sweep_write_runs(f, spec, x, r, n, &err)
             : k == 1    ? cs_sweep_write_summary_md(f, spec, x, r, n, &err)
             : k == 2    ? cs_sweep_write_summary_json(f, spec, x, r, n, &err)
             : k < study ? cs_sweep_write_plot(f, spec, k - 3, x, r, n, &err)
             : k < study + CS_STUDY_FIGURES
                 ? cs_study_write_figure(f, CS_PLOT_PNG, k - study, spec, x, r, n, &err)
                 : cs_study_write_page(f, spec, x, r, n, &err);
        rc = cs_out_finish(out, f, rc, &err); /* a failed end's reason replaces the writer's */
    }
    cs_plot_release(); /* after the last plot */
    if (rc == CS_OK && spec->netcdf && !partial) {
        char path[1200];
        rc = cs_out_begin_path(out, "runs.nc", path, sizeof path, &err);
        if (rc == CS_OK && (rc = cs_sweep_write_netcdf(path, spec, x, r, n, &err)) != CS_OK) {
            char nc_why[CS_MESSAGE_SIZE];
            snprintf(nc_why, sizeof nc_why, "%s", err.message);
            cs_error_set(&err, rc, "%.180s/runs.nc: %s", out->dir, nc_why);
        }
        if (rc == CS_OK) rc = cs_out_end_path(out, &err);
    }
    if (rc == CS_OK) rc = cs_out_commit(out, &err);
    if (rc != CS_OK) {
        cs_out_fail(out, rc, &err);
        if (out->in_place > 0) /* the journal's runs are in the outputs */
            cs_sweep_say(o, "%s", err.message);
        else
            cs_sweep_say(o,
                         "%s; the runs done are kept in %s/%s: `cablesim sweep --resume %s` writes the study "
                         "once that is put right",
                         err.message, out->dir, CS_OUT_JOURNAL, out->dir);
    }
    return rc == CS_OK ? 0 : -1;
}

/* ---- stopping on a signal ---- */

static volatile sig_atomic_t stop_signal = 0;

/* The first SIGINT or SIGTERM asks the sweep to stop starting runs; a second one ends it at once, its
 * folder as it was but for the journal, which keeps the runs done (cs_out_end_by_signal). */
static void on_signal(int sig) {
    if (stop_signal) {
        cs_out_end_by_signal(sig);
        return;
    }
    stop_signal = sig;
}

/* The program's own handlers, while the study has its own. */
static struct sigaction program_int, program_term;

/* During the runs (handler on_signal) and while the outputs are written (cs_out_end_by_signal: the
 * folder as it was, the journal kept) the study's handler, with the program's kept; NULL: the program's
 * back. */
static void catch_signals(void (*handler)(int)) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    if (!handler) {
        sigaction(SIGINT, &program_int, NULL);
        sigaction(SIGTERM, &program_term, NULL);
    } else if (handler == on_signal) {
        sigaction(SIGINT, &sa, &program_int);
        sigaction(SIGTERM, &sa, &program_term);
    } else {
        sigaction(SIGINT, &sa, NULL);
        sigaction(SIGTERM, &sa, NULL);
    }
}

/* ---- the runs ---- */

/* The runs of this process, todo[rank + m * size] for m < local_n, shared among its threads one at a time
 * (the next m to start under the lock): each thread runs on a loader of its own. */
typedef struct runner {
    const cs_sweep_spec *spec;
    const double *x;
    const long *todo;
    long local_n, next, stop_after;
    const cs_sweep_ranks_def *ranks;
    cs_sweep_result *mine;
    taker *t;
    progress *p;
    pthread_mutex_t lock;
    pthread_t writer; /* the thread of the study, which writes its folder */
} runner;

static void run_worker(void *arg) {
    runner *w = arg;
    int rank = w->ranks->rank, size = w->ranks->ranks;
    if (!pthread_equal(pthread_self(), w->writer)) {
        /* SIGINT and SIGTERM blocked here for good (a thread pool's threads outlive the runs): the
         * study's handlers run in the thread that writes the folder, so that the cleanup of a signal
         * during the outputs or their commit finds the record of that folder whole, or waits for the
         * commit's end (outfile.h) */
        sigset_t set;
        sigemptyset(&set);
        sigaddset(&set, SIGINT);
        sigaddset(&set, SIGTERM);
        pthread_sigmask(SIG_BLOCK, &set, NULL);
    }
    cs_loader *loader = cs_sweep_loader(w->spec, NULL); /* one per thread (NULL: one per run) */
    for (;;) {
        pthread_mutex_lock(&w->lock);
        long m = w->next++;
        pthread_mutex_unlock(&w->lock);
        if (m >= w->local_n || stop_signal) break; /* stopped: start no other run */
        long i = w->todo[rank + m * size];
        cs_sweep_run(w->spec, &w->x[i * w->spec->var_count], loader, &w->mine[m]);
        pthread_mutex_lock(&w->lock);
        w->p->done++;
        if (rank > 0) w->ranks->send_run(w->ranks->ctx, i, &w->mine[m], sizeof w->mine[m]);
        if (rank == 0) take_run(w->t, i, &w->mine[m]);
        progress_show(w->p, 0);
        if (w->stop_after > 0 && w->p->done == w->stop_after) /* CABLESIM_SWEEP_STOP_AFTER */
            kill(getpid(), SIGINT);                           /* to the process: this thread may block it */
        pthread_mutex_unlock(&w->lock);
    }
    cs_loader_free(loader);
}

static void share(const cs_sweep_ranks_def *ranks, void *data, size_t bytes) {
    if (ranks->share) ranks->share(ranks->ctx, data, bytes);
}

static void abort_ranks(const cs_sweep_ranks_def *ranks, int status) {
    if (ranks->abort) ranks->abort(ranks->ctx, status);
}

/* The study as a handle (cablesim/sweep.h), taking over spec, x and all: NULL if memory is short. */
static cs_sweep *handle(cs_sweep_spec *spec, double *x, cs_sweep_result *all, long n, long ran, int stopped,
                        const char *dir) {
    cs_sweep *h = calloc(1, sizeof *h);
    if (!h) return NULL;
    *h = (cs_sweep){spec, x, all, n, ran, stopped, ""};
    if (spec) spec->origin.command = NULL, spec->origin.dir = NULL, spec->origin.resume = NULL; /* freed */
    snprintf(h->dir, sizeof h->dir, "%s", dir);
    return h;
}

/* The spec of o read with its changes into *spec (NULL if memory is short), its runs' inputs into *x and *n,
 * and its model checked with them (on rank 0 alone: the other ranks read what rank 0 checked): 0, or the
 * exit status, its problems printed (rank 0). */
static int spec_checked(cs_sweep_options *o, int rank, cs_sweep_spec **spec, double **x, long *n) {
    *x = NULL, *n = 0;
    if (!(*spec = study_spec(o, rank == 0))) return EXIT_RUN;
    if ((*spec)->error_count == 0 && !(*x = cs_sweep_samples(*spec, n)))
        cs_sweep_error(*spec, 0, 0, "out of memory for %ld runs", (*spec)->runs);
    if (rank == 0 && (*spec)->error_count == 0) cs_sweep_check(*spec, *x);
    if (!(*spec)->error_count) return 0;
    if (rank == 0) print_errors(*spec, o);
    return EXIT_BAD;
}

int cs_sweep_study_check(cs_sweep_options *o, cs_sweep **keep) {
    *keep = NULL;
    if (o->resume) {
        cs_sweep_say(o, "a study's spec is checked, not a folder to resume (%s)", o->resume);
        return EXIT_BAD;
    }
    cs_sweep_spec *spec;
    double *x;
    long n;
    int rc = spec_checked(o, 0, &spec, &x, &n);
    cs_sweep_result *all = rc == 0 ? calloc((size_t)(n > 0 ? n : 1), sizeof *all) : NULL;
    for (long i = 0; all && i < n; i++)
        all[i].pending = 1;
    if (all && (*keep = handle(spec, x, all, n, 0, 0, ""))) return 0;
    if (rc == 0) cs_sweep_say(o, "out of memory for %ld runs", n), rc = EXIT_RUN;
    free(all), free(x);
    cs_sweep_spec_free(spec);
    return rc;
}

int cs_sweep_study_keep(cs_sweep_options *o, const char *command, cs_sweep **keep) {
    if (keep) *keep = NULL;
    const cs_sweep_ranks_def *ranks = &o->ranks;
    int rank = ranks->rank, size = ranks->ranks, rc = 0;
    static cs_sweep_resumed was;
    char as_given[PATH_MAX] = "", cwd[PATH_MAX] = "";
    memset(&was, 0, sizeof was); /* nothing of an earlier study's */
    if (!getcwd(cwd, sizeof cwd)) cwd[0] = '\0';
    if (!o->resume) snprintf(as_given, sizeof as_given, "%s", o->spec);
    if (o->resume) {
        cs_error err;
        if (cs_sweep_resume_read(o->resume, o, &was, &err) != CS_OK) {
            if (rank == 0) cs_sweep_say(o, "--resume: %s", err.message);
            rc = EXIT_BAD;
        } else if (strcmp(was.cwd, cwd) == 0) {
            snprintf(as_given, sizeof as_given, "%s", was.spec_as_given);
        } else {
            snprintf(as_given, sizeof as_given, "%s", o->spec);
        }
    }
    cs_sweep_spec *spec = NULL;
    double *x = NULL;
    long n = 0;
    if (rc == 0) rc = spec_checked(o, rank, &spec, &x, &n);
    /* rank 0: the output folder, checked before any run; --resume: the runs done */
    char dir[1024] = "", *record = NULL;
    cs_outdir out;
    int out_open = 0;
    cs_sweep_result *all = NULL;
    long done = 0;
    if (rc == 0 && rank == 0) {
        cs_error err;
        out_dir_of(o, dir, sizeof dir);
        spec->origin.command = command;
        spec->origin.dir = dir;
        spec->origin.resume = record = cs_sweep_resume_record(o, as_given, cwd);
        spec->origin.has_model_hash = cs_sweep_model_hash(spec, &spec->origin.model_hash) == 0;
        spec->origin.inputs_hash = cs_sweep_inputs_hash(spec, x, n);
        all = calloc((size_t)(n > 0 ? n : 1), sizeof *all);
        for (long i = 0; all && i < n; i++)
            all[i].pending = 1;
        if (!all || !record) {
            cs_sweep_say(o, "out of memory for %ld results", n);
            rc = EXIT_RUN;
        } else if (o->resume && !was.partial) {
            if (o->closing)
                fprintf(o->closing, "sweep: %s holds the whole study (%ld runs): nothing to run\n", dir, n);
            rc = -1;
        } else if (cs_sweep_outputs_loadable(spec, &err) != CS_OK) { /* not found after the runs */
            cs_sweep_say(o, "nothing run: %s", err.message);
            rc = EXIT_RUN;
        } else if (o->resume && (done = cs_sweep_resume_runs(dir, spec, &was, x, all, n, o)) < 0) {
            rc = EXIT_BAD;
        } else if (!lock_there(dir) && stopped_study_kept(o, dir)) {
            rc = EXIT_RUN; /* said before the folder is locked: it is left as it was, and this refusal
                              comes before that of a file of the user's there, which --force would pass */
        } else if (cs_out_open(&out, dir, "sweep", o->force ? CS_OUT_FORCE : 0,
                               o->force_given ? o->force_given : "cs_sweep_def's force set to 1",
                               &err) != CS_OK) {
            cs_sweep_say(o, "nothing run: %s", err.message);
            rc = EXIT_RUN;
        } else if (out_open = 1, stopped_study_kept(o, dir)) {
            rc = EXIT_RUN; /* under the lock: a journal left by a killed sweep whose lock was there */
        } else if (start_journal(&out, spec, x, all, n, &err) != CS_OK) {
            cs_sweep_say(o, "nothing run: %s", err.message);
            rc = EXIT_RUN;
        }
    }
    /* the runs to do, the same list on every rank */
    char *todo_mask = NULL;
    long *todo = NULL, todo_n = 0;
    share(ranks, &rc, sizeof rc); /* rank 0 checked the model and the folder */
    share(ranks, &n, sizeof n);
    if (rc == 0) {
        todo_mask = malloc((size_t)(n > 0 ? n : 1));
        todo = malloc((size_t)(n > 0 ? n : 1) * sizeof *todo);
        if (!todo_mask || !todo) {
            cs_sweep_say(o, "out of memory for %ld runs", n);
            abort_ranks(ranks, EXIT_RUN);
            rc = EXIT_RUN;
        }
        for (long i = 0; rc == 0 && rank == 0 && i < n; i++)
            todo_mask[i] = (char)all[i].pending;
        if (rc == 0) share(ranks, todo_mask, n);
        for (long i = 0; rc == 0 && i < n; i++)
            if (todo_mask[i]) todo[todo_n++] = i;
    }
    if (rc != 0) {
        if (out_open) cs_out_abort(&out);
        if (rc < 0 && keep && rank == 0 && (*keep = handle(spec, x, all, n, 0, 0, dir))) /* nothing to run */
            spec = NULL, x = NULL, all = NULL;
        else if (rc < 0 && keep && rank > 0)
            *keep = handle(NULL, NULL, NULL, 0, 0, 0, "");
        free(x), free(all), free(todo), free(todo_mask), free(record), free(was.journal);
        cs_sweep_spec_free(spec);
        return rc < 0 ? 0 : rc;
    }
    int threads = o->threads > 0 ? o->threads : 1;
    long local_n = todo_n > rank ? (todo_n - rank + size - 1) / size : 0;
    cs_sweep_result *mine = calloc((size_t)(local_n > 0 ? local_n : 1), sizeof *mine);
    if (!mine) {
        cs_sweep_say(o, "out of memory for %ld results", todo_n);
        abort_ranks(ranks, EXIT_RUN);
        return EXIT_RUN;
    }
    for (long m = 0; m < local_n; m++)
        mine[m].pending = 1;
    progress p = {o->progress,
                  rank == 0 && o->progress,
                  o->progress && isatty(fileno(o->progress)),
                  size,
                  0,
                  local_n,
                  now(),
                  now()};
    if (rank == 0 && o->progress)
        fprintf(o->progress, "sweep: %ld runs of %s on %d rank%s x %d thread%s%s\n", todo_n, spec->model,
                size, size == 1 ? "" : "s", threads, threads == 1 ? "" : "s",
                o->resume ? " (the rest of a stopped study)" : "");
    const char *stop_after_text = getenv("CABLESIM_SWEEP_STOP_AFTER");
    stop_signal = 0;
    catch_signals(on_signal);
    double start = now();
    taker t = {&out, spec, x, all, 0, o};
    if (rank == 0 && size > 1 &&
        ranks->receive_start(ranks->ctx, sizeof(cs_sweep_result), take_run, &t) != 0) {
        cs_sweep_say(o, "cannot start the thread that receives the other ranks' runs");
        abort_ranks(ranks, EXIT_RUN);
    }
    runner w = {spec,
                x,
                todo,
                local_n,
                0,
                stop_after_text ? strtol(stop_after_text, NULL, 10) : 0,
                ranks,
                mine,
                &t,
                &p,
                PTHREAD_MUTEX_INITIALIZER,
                pthread_self()};
    if (o->parallel)
        o->parallel(threads, run_worker, &w);
    else
        run_worker(&w);
    catch_signals(cs_out_end_by_signal);
    int stopped = stop_signal;
    if (!stopped)
        progress_show(&p, 1);
    else if (p.on && p.tty)
        fputc('\n', p.f);
    if (rank == 0 && size > 1)
        ranks->receive_end(ranks->ctx);
    else if (rank > 0)
        ranks->send_done(ranks->ctx);
    if (ranks->largest) stopped = ranks->largest(ranks->ctx, stopped);
    double wall = now() - start;
    if (rank == 0) {
        long bad = 0, pending = 0;
        for (long i = 0; i < n; i++) {
            pending += all[i].pending;
            bad += !all[i].pending && all[i].status != CS_RUN_OK;
        }
        spec->origin.stopped_by = pending ? signal_name(stopped) : NULL;
        if (write_all(&out, spec, x, all, n, pending > 0, o) != 0) {
            rc = EXIT_RUN;
        } else if (pending) {
            if (o->errors)
                fprintf(
                    o->errors,
                    "cablesim sweep: stopped by %s: %ld of %ld runs done, written to %s (partial); `cablesim "
                    "sweep --resume %s` runs the other %ld\n",
                    signal_name(stopped), n - pending, n, dir, dir, pending);
            rc = 128 + (stopped ? stopped : SIGINT);
        } else if (o->closing) {
            fprintf(o->closing,
                    "sweep: %ld runs in %.3f s (%.3f runs/s) on %d rank%s x %d thread%s; %ld did not run to "
                    "the end\n",
                    todo_n, wall, wall > 0 ? (double)todo_n / wall : 0, size, size == 1 ? "" : "s", threads,
                    threads == 1 ? "" : "s", bad);
            if (o->resume)
                fprintf(o->closing, "sweep: %ld runs read back from %s/runs.csv, %ld run now\n", done, dir,
                        todo_n);
            fprintf(o->closing,
                    "outputs: %s/{runs.csv,summary.md,summary.json,report.html,plots/study-*.png%s", dir,
                    spec->netcdf ? ",runs.nc" : "");
            for (int k = 0; k < spec->plot_count; k++) {
                char file[256];
                cs_sweep_plot_file(spec, k, file, sizeof file);
                fprintf(o->closing, ",%s", file);
            }
            fprintf(o->closing, "}\n");
        }
    } else if (stopped) {
        rc = 128 + stopped;
    }
    catch_signals(NULL); /* the outputs are in place, or removed */
    pthread_mutex_destroy(&w.lock);
    if (rank == 0 && keep && (rc == 0 || rc > 128) && (*keep = handle(spec, x, all, n, p.done, stopped, dir)))
        spec = NULL, x = NULL, all = NULL;
    free(mine);
    free(all);
    free(x);
    free(todo), free(todo_mask), free(record), free(was.journal);
    cs_sweep_spec_free(spec);
    share(ranks, &rc, sizeof rc);
    if (rank > 0 && keep && (rc == 0 || rc > 128)) /* rank 0's outcome, no runs */
        *keep = handle(NULL, NULL, NULL, 0, p.done, rc > 128 ? rc - 128 : 0, "");
    return rc;
}
