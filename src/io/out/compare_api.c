/* SPDX-License-Identifier: MIT */
/* cablesim/compare.h: the runs and the measured history read back (load/runread.h) and compared and
 * written (out/compare.h), behind an opaque handle. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cablesim/compare.h"
#include "load/runread.h"
#include "load/units.h"
#include "out/compare.h"
#include "out/outfile.h"
#include "out/plot.h"
#include "status.h"

struct cs_compare {
    int count, reference;
    cs_trace traces[CS_COMPARE_MAX_RUNS + 1];
    struct {
        dev_t dev;
        ino_t ino;
    } folders[CS_COMPARE_MAX_RUNS + 1]; /* the runs' folders and the measured file's: none is written into */
    char force[64]; /* the way to CS_COMPARE_FORCE a refusal of a folder names (the def's force_given) */
};

/* Keep the device and inode of the folder path (a run's), or of the one holding it (a measured file's)
 * when cablesim wrote it (it holds a manifest, whose files a comparison there would remove). */
static void keep_folder(cs_compare *c, int i, const char *path, int holding) {
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (holding && !slash)
        snprintf(dir, sizeof dir, ".");
    else if (holding)
        slash[slash == dir] = '\0'; /* "/f": "/" */
    char manifest[4200];
    snprintf(manifest, sizeof manifest, "%s/%s", dir, CS_OUT_MANIFEST);
    struct stat st;
    int known = (!holding || lstat(manifest, &st) == 0) && stat(dir, &st) == 0;
    c->folders[i].dev = known ? st.st_dev : 0;
    c->folders[i].ino = known ? st.st_ino : 0;
}

void cs_compare_free(cs_compare *c) {
    if (!c) return;
    for (int k = 0; k < c->count; k++)
        cs_trace_free(&c->traces[k]);
    free(c);
}

cs_status cs_compare_create(const cs_compare_def *given, cs_compare **out, cs_error *err) {
    if (out) *out = NULL;
    cs_compare_def def = cs_default_compare_def();
    if (cs_sized_take(&def, sizeof def, given, "cs_compare_def", err) != CS_OK) return CS_ERR_INVALID;
    if (!out) return cs_status_set(err, CS_ERR_INVALID, "cs_compare_create: no place for the comparison");
    if (def.run_count < 1 || !def.runs)
        return cs_status_set(err, CS_ERR_INVALID, "cs_compare_def: no run to compare");
    if (def.run_count > CS_COMPARE_MAX_RUNS)
        return cs_error_set(err, CS_ERR_INVALID, "cs_compare_def: %d runs, more than %d", def.run_count,
                            CS_COMPARE_MAX_RUNS);
    cs_compare *c = calloc(1, sizeof *c);
    if (!c) return cs_status_set(err, CS_ERR_MEMORY, "out of memory");
    cs_status rc = CS_OK;
    cs_error read; /* a file's failure, reported as CS_ERR_IO (cablesim/compare.h) */
    for (int i = 0; rc == CS_OK && i < def.run_count; i++, c->count++)
        if (!def.runs[i])
            rc = cs_error_set(err, CS_ERR_INVALID, "cs_compare_def: run %d is NULL", i);
        else if (cs_trace_load_run(def.runs[i], &c->traces[c->count], &read) != CS_OK)
            rc = cs_status_set(err, CS_ERR_IO, read.message);
        else
            keep_folder(c, i, def.runs[i], 0);
    if (rc == CS_OK && def.measured) {
        cs_units *units = cs_units_open(&read);
        if (!units || cs_trace_load_measured(def.measured, units, &c->traces[c->count], &read) != CS_OK)
            rc = cs_status_set(err, CS_ERR_IO, read.message);
        else
            keep_folder(c, c->count, def.measured, 1), c->reference = c->count++;
        cs_units_free(units);
    }
    if (rc != CS_OK) {
        cs_compare_free(c);
        return rc;
    }
    snprintf(c->force, sizeof c->force, "%s",
             def.force_given ? def.force_given : "the flag CS_COMPARE_FORCE");
    *out = c;
    return cs_status_set(err, CS_OK, "");
}

int cs_compare_count(const cs_compare *c) {
    return c ? c->count : 0;
}

int cs_compare_reference(const cs_compare *c) {
    return c ? c->reference : 0;
}

const char *cs_compare_label(const cs_compare *c, int i) {
    return c && i >= 0 && i < c->count ? c->traces[i].label : NULL;
}

const char *cs_compare_outcome(const cs_compare *c, int i) {
    if (!c || i < 0 || i >= c->count) return NULL;
    return c->traces[i].measured ? "" : c->traces[i].outcome;
}

int cs_compare_parameter_count(void) {
    return cs_compare_param_count();
}

cs_status cs_compare_get(const cs_compare *c, int k, int i, cs_compare_row *out, cs_error *err) {
    if (cs_status_sized(out, sizeof(cs_compare_row), "cs_compare_row", err) != CS_OK) return CS_ERR_INVALID;
    char why[96];
    if (!c || i < 0 || i >= c->count || k < 0 || k >= cs_compare_param_count()) {
        if (!c || i < 0 || i >= c->count)
            snprintf(why, sizeof why, "cs_compare_row: no history %d (the comparison has %d)", i,
                     cs_compare_count(c));
        else
            snprintf(why, sizeof why, "cs_compare_row: no parameter %d (there are %d)", k,
                     cs_compare_param_count());
        return cs_status_set(err, CS_ERR_INVALID, why);
    }
    const cs_trace *tr = &c->traces[i], *ref = &c->traces[c->reference];
    cs_compare_row full = {.size = sizeof full,
                           .name = cs_compare_param_name(k),
                           .unit = cs_compare_param_unit(k),
                           .value = cs_compare_param_value(tr, k),
                           .difference = i == c->reference ? NAN : cs_compare_param_difference(tr, ref, k)};
    return cs_status_put_sized(out, &full, sizeof full, "cs_compare_row", err);
}

cs_status cs_compare_write(const cs_compare *c, const char *dir, int flags, cs_error *err) {
    if (!c || !dir) return cs_status_set(err, CS_ERR_INVALID, "cs_compare_write: no comparison or no folder");
    /* a run's folder holds its manifest's files, which a comparison written there would remove */
    struct stat at;
    for (int i = 0; stat(dir, &at) == 0 && i < c->count; i++)
        if (c->folders[i].ino == at.st_ino && c->folders[i].dev == at.st_dev)
            return cs_error_set(err, CS_ERR_IO,
                                "nothing written: %s is the folder of %s %s compared: writing there would "
                                "remove a run's files; choose another folder",
                                dir, c->traces[i].measured ? "the measured history" : "the run",
                                c->traces[i].label);
    cs_error wrote;
    cs_outdir out;
    cs_status st =
        cs_out_open(&out, dir, "compare", flags & CS_COMPARE_FORCE ? CS_OUT_FORCE : 0, c->force, err);
    if (st == CS_OK && cs_compare_write_traces(&out, c->traces, c->count, c->reference, &wrote) != CS_OK)
        st = cs_status_set(err, CS_ERR_IO, wrote.message); /* the status cablesim/compare.h promises */
    if (st == CS_OK) st = cs_out_commit(&out, err);
    if (st != CS_OK) cs_out_fail(&out, st, err);
    cs_plot_release(); /* after the last plot (fontconfig's caches) */
    return st == CS_OK ? cs_status_set(err, CS_OK, "") : st;
}

void cs_compare_print_metrics(const cs_compare *c, FILE *f) {
    if (c && f) cs_compare_print_trace_metrics(f, c->traces, c->count, c->reference);
}
