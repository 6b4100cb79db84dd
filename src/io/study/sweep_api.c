/* SPDX-License-Identifier: MIT */
/* cablesim/sweep.h: a study on one process (study/sweepstudy.h) from a def, and its runs behind an opaque
 * handle. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/sweep.h"
#include "status.h"
#include "study/sweepstudy.h"

/* The def's ranks into o->ranks (to their size): CS_OK, or CS_ERR_INVALID with err filled saying why they
 * cannot be taken. */
static cs_status ranks_of(const cs_sweep_def *def, cs_sweep_options *o, cs_error *err) {
    o->ranks = cs_default_sweep_ranks();
    cs_error taken;
    if (def->ranks &&
        cs_sized_take(&o->ranks, sizeof o->ranks, def->ranks, "cs_sweep_ranks_def", &taken) != CS_OK)
        return cs_error_set(err, CS_ERR_INVALID, "%.150s", taken.message);
    if (o->ranks.ranks < 1 || o->ranks.rank < 0 || o->ranks.rank >= o->ranks.ranks)
        return cs_error_set(err, CS_ERR_INVALID, "cs_sweep_ranks_def: rank %d of %d ranks", o->ranks.rank,
                            o->ranks.ranks);
    if (o->ranks.ranks > 1 &&
        !(o->ranks.share && o->ranks.largest && o->ranks.receive_start && o->ranks.receive_end &&
          o->ranks.send_run && o->ranks.send_done && o->ranks.abort))
        return cs_error_set(err, CS_ERR_INVALID, "cs_sweep_ranks_def: %d ranks without every hook",
                            o->ranks.ranks);
    return CS_OK;
}

/* A public def (cablesim/sweep.h) as options into o (zeroed first; its strings and ranks are def's). CS_OK,
 * or CS_ERR_INVALID with err filled (too many sets or folders, runs out of range, ranks that cannot be
 * taken). */
static cs_status options_of(const cs_sweep_def *given, cs_sweep_options *o, cs_error *err) {
    cs_sweep_def def = cs_default_sweep_def();
    if (cs_sized_take(&def, sizeof def, given, "cs_sweep_def", err) != CS_OK) return CS_ERR_INVALID;
    memset(o, 0, sizeof *o);
    if (def.set_count < 0 || def.set_count > CS_SWEEP_MAX_SETS || (def.set_count > 0 && !def.sets))
        return cs_error_set(err, CS_ERR_INVALID, "cs_sweep_def: %d sets, where at most %d are taken",
                            def.set_count, CS_SWEEP_MAX_SETS);
    if (def.allow_count < 0 || def.allow_count > CS_SWEEP_MAX_ALLOW || (def.allow_count > 0 && !def.allow))
        return cs_error_set(err, CS_ERR_INVALID,
                            "cs_sweep_def: %d folders to allow, where at most %d are taken", def.allow_count,
                            CS_SWEEP_MAX_ALLOW);
    if (def.runs < 0 || def.runs > CS_SWEEP_MAX_RUNS)
        return cs_error_set(err, CS_ERR_INVALID, "cs_sweep_def: %ld runs, where 1 to %ld are taken", def.runs,
                            (long)CS_SWEEP_MAX_RUNS);
    if (!def.spec == !def.resume)
        return cs_error_set(err, CS_ERR_INVALID, "cs_sweep_def: %s",
                            def.spec ? "a spec and a folder to resume" : "no spec");
    if (def.resume && (def.out_dir || def.runs || def.seed || def.set_count || def.allow_count || def.netcdf))
        return cs_error_set(
            err, CS_ERR_INVALID,
            "cs_sweep_def: a folder to resume takes its study as its summary.json records it: "
            "no out_dir, runs, seed, sets, allow or netcdf");
    cs_status rc = ranks_of(&def, o, err);
    if (rc != CS_OK) return rc;
    o->spec = def.spec, o->out_dir = def.out_dir, o->resume = def.resume;
    o->threads = def.threads, o->parallel = def.parallel;
    o->netcdf = def.netcdf, o->force = def.force;
    o->runs = def.runs, o->seed = def.seed;
    for (int i = 0; i < def.allow_count; i++)
        o->allow[o->allow_count++] = def.allow[i];
    for (int i = 0; i < def.set_count; i++) {
        o->sets_given[o->set_count] = def.sets_given ? def.sets_given[i] : NULL;
        o->sets[o->set_count++] = def.sets[i];
    }
    o->errors = def.errors, o->progress = def.progress, o->closing = def.closing;
    o->force_given = def.force_given;
    return CS_OK;
}

/* The study of def run (check: checked alone) into *out, as cs_sweep_study and cs_sweep_check_study say. */
static cs_status study(const cs_sweep_def *def, int check, cs_sweep **out, cs_error *err) {
    if (out) *out = NULL;
    if (!out) return cs_status_set(err, CS_ERR_INVALID, "cablesim/sweep.h: no place for the study");
    cs_sweep_def full = cs_default_sweep_def(); /* the caller's, to its size */
    if (cs_sized_take(&full, sizeof full, def, "cs_sweep_def", err) != CS_OK) return CS_ERR_INVALID;
    cs_sweep_options *o = malloc(sizeof *o);
    if (!o) return cs_status_set(err, CS_ERR_MEMORY, "out of memory");
    cs_status st = options_of(&full, o, err);
    if (st != CS_OK) return free(o), st;
    if (check) o->ranks = cs_default_sweep_ranks(), o->progress = NULL, o->closing = NULL;
    int rc = check ? cs_sweep_study_check(o, out) : cs_sweep_study_keep(o, full.command, out);
    if (rc == 0 || rc > 128) {
        st = *out ? cs_status_set(err, CS_OK, "") : cs_status_set(err, CS_ERR_MEMORY, "out of memory");
    } else {
        if (*out) cs_sweep_free(*out), *out = NULL;
        st = cs_status_set(err, rc == CS_SWEEP_EXIT_USAGE ? CS_ERR_INVALID : CS_ERR_IO,
                           o->why[0] ? o->why : "the study failed");
    }
    free(o);
    return st;
}

cs_status cs_sweep_study(const cs_sweep_def *def, cs_sweep **out, cs_error *err) {
    return study(def, 0, out, err);
}

cs_status cs_sweep_check_study(const cs_sweep_def *def, cs_sweep **out, cs_error *err) {
    return study(def, 1, out, err);
}

void cs_sweep_free(cs_sweep *s) {
    if (!s) return;
    cs_sweep_spec_free(s->spec);
    free(s->x);
    free(s->all);
    free(s);
}

const char *cs_sweep_dir(const cs_sweep *s) {
    return s ? s->dir : NULL;
}

const char *cs_sweep_spec_file(const cs_sweep *s) {
    return s && s->spec ? s->spec->file : "";
}

const char *cs_sweep_model(const cs_sweep *s) {
    return s && s->spec ? s->spec->model : "";
}

cs_sweep_method cs_sweep_method_of(const cs_sweep *s) {
    return s && s->spec ? s->spec->method : CS_SWEEP_GRID;
}

long cs_sweep_run_count(const cs_sweep *s) {
    return s ? s->n : 0;
}

long cs_sweep_ran(const cs_sweep *s) {
    return s ? s->ran : 0;
}

int cs_sweep_stopped_by(const cs_sweep *s) {
    return s ? s->stopped_by : 0;
}

int cs_sweep_var_count(const cs_sweep *s) {
    return s && s->spec ? s->spec->var_count : 0;
}

const char *cs_sweep_var_path(const cs_sweep *s, int var) {
    return var >= 0 && var < cs_sweep_var_count(s) ? s->spec->vars[var].path : NULL;
}

const char *cs_sweep_var_unit(const cs_sweep *s, int var) {
    return var >= 0 && var < cs_sweep_var_count(s) ? s->spec->vars[var].unit : NULL;
}

double cs_sweep_input(const cs_sweep *s, long run, int var) {
    if (!s || run < 0 || run >= s->n || var < 0 || var >= cs_sweep_var_count(s)) return NAN;
    const cs_sweep_var *v = &s->spec->vars[var];
    double x = s->x[run * s->spec->var_count + var];
    return v->numeric ? cs_sweep_value_used(v, x) : x;
}

/* Run `run` of s, or NULL with err filled naming the struct. */
static const cs_sweep_result *run_of(const cs_sweep *s, long run, const char *name, cs_error *err) {
    if (s && run >= 0 && run < s->n) return &s->all[run];
    char why[96];
    snprintf(why, sizeof why, "no run %ld (the study has %ld)", run, cs_sweep_run_count(s));
    cs_sized_refuse(err, name, why);
    return NULL;
}

cs_status cs_sweep_run_of(const cs_sweep *s, long run, cs_sweep_run_info *out, cs_error *err) {
    if (cs_status_sized(out, sizeof *out, "cs_sweep_run_info", err) != CS_OK) return CS_ERR_INVALID;
    const cs_sweep_result *r = run_of(s, run, "cs_sweep_run_info", err);
    if (!r) return CS_ERR_INVALID;
    cs_sweep_run_info full = {.size = sizeof full,
                              .status = r->pending                      ? CS_SWEEP_RUN_PENDING
                                        : r->status == CS_RUN_BAD_MODEL ? CS_SWEEP_RUN_BAD_MODEL
                                        : r->status == CS_RUN_FAILED    ? CS_SWEEP_RUN_FAILED
                                                                        : CS_SWEEP_RUN_OK,
                              .astm_penetration = NAN};
    if (!r->pending) {
        snprintf(full.rating, sizeof full.rating, "%s", r->rating);
        snprintf(full.error, sizeof full.error, "%s", r->status == CS_RUN_OK ? "" : r->error);
        full.astm_penetration = r->astm_penetration;
        snprintf(full.sd_std_rating, sizeof full.sd_std_rating, "%s", r->sd_std_rating);
    }
    return cs_status_put_sized(out, &full, sizeof full, "cs_sweep_run_info", err);
}

cs_status cs_sweep_run_summary(const cs_sweep *s, long run, cs_summary *out, cs_error *err) {
    if (cs_status_sized(out, sizeof *out, "cs_summary", err) != CS_OK) return CS_ERR_INVALID;
    const cs_sweep_result *r = run_of(s, run, "cs_summary", err);
    if (!r) return CS_ERR_INVALID;
    if (r->pending || r->status == CS_RUN_BAD_MODEL) {
        char why[96];
        snprintf(why, sizeof why, "run %ld has none: %s", run,
                 r->pending ? "it was not run" : "its model was refused");
        return cs_sized_refuse(err, "cs_summary", why);
    }
    cs_summary full = r->summary;
    full.size = sizeof full;
    return cs_status_put_sized(out, &full, sizeof full, "cs_summary", err);
}
