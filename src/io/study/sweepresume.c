/* SPDX-License-Identifier: MIT */
/* A sweep's record of its study (summary.json's "resume", the journal's first line), written before the
 * runs and read back by --resume, and the runs done read back from runs.csv or the journal. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <json-c/json.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cablesim/cablesim.h"
#include "out/jsondoc.h"
#include "out/outfile.h"
#include "out/sweepout.h"
#include "out/writers.h"
#include "status.h"
#include "study/sweepresume.h"

/* {"spec": the spec's absolute path, "spec_as_given" and the "cwd" it was given in, "runs", "seed", "set":
 * the command line's fixed values, "netcdf", "allow": the --allow-path folders, absolute}. */
char *cs_sweep_resume_record(const cs_sweep_options *o, const char *as_given, const char *cwd) {
    char real[PATH_MAX];
    json_object *j = json_object_new_object(), *sets = json_object_new_array(),
                *allow = json_object_new_array();
    if (!j || !sets || !allow) {
        json_object_put(j), json_object_put(sets), json_object_put(allow);
        return NULL;
    }
    json_object_object_add(j, "spec", cs_jstr(realpath(o->spec, real) ? real : o->spec));
    json_object_object_add(j, "spec_as_given", cs_jstr(as_given));
    json_object_object_add(j, "cwd", cs_jstr(cwd));
    json_object_object_add(j, "runs", o->runs > 0 ? json_object_new_int64(o->runs) : NULL);
    json_object_object_add(j, "seed", cs_jstr(o->seed));
    for (int i = 0; i < o->set_count; i++)
        json_object_array_add(sets, cs_jstr(o->sets[i]));
    json_object_object_add(j, "set", sets);
    json_object_object_add(j, "netcdf", json_object_new_boolean(o->netcdf));
    for (int i = 0; i < o->allow_count; i++)
        json_object_array_add(allow, cs_jstr(realpath(o->allow[i], real) ? real : o->allow[i]));
    json_object_object_add(j, "allow", allow);
    char *text = cs_json_text(j);
    json_object_put(j);
    return text;
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

/* The record of the study into o (its strings kept in static storage) and r: the first line of
 * DIR/.cablesim-journal when a sweep killed before it wrote its outputs left one (r->journal), else
 * DIR/summary.json's. CS_OK, or CS_ERR_IO or CS_ERR_INVALID with err filled. */
cs_status cs_sweep_resume_read(const char *dir, cs_sweep_options *o, cs_sweep_resumed *r, cs_error *err) {
    static char spec[PATH_MAX], seed[64], sets[256][1100], allow[64][PATH_MAX];
    char path[1200];
    size_t length = 0;
    if (!(r->journal = cs_out_journal_read(dir, &length, err)) && err->status != CS_OK) return err->status;
    char *eol = r->journal ? strchr(r->journal, '\n') : NULL;
    if (eol) { /* its first line is the record; runs.csv follows */
        *eol = '\0';
        r->rows = eol + 1;
        r->rows_length = length - (size_t)(eol + 1 - r->journal);
    }
    snprintf(path, sizeof path, "%s/%s", dir, r->journal ? CS_OUT_JOURNAL : "summary.json");
    FILE *probe = r->journal ? NULL : fopen(path, "r");
    if (!r->journal && !probe)
        return cs_error_set(err, CS_ERR_IO, "%s: %s (expected the summary of a sweep written there)", path,
                            strerror(errno));
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
    if (bad)
        return cs_error_set(err, CS_ERR_INVALID,
                            "%s: no record of the study to resume (written by an older cablesim, or not by "
                            "cablesim sweep)",
                            path);
    o->spec = spec;
    o->out_dir = dir;
    return cs_status_set(err, CS_OK, "");
}

/* --resume: the runs of DIR/runs.csv, or of the journal a killed sweep left, into all (the others left
 * pending), after checking that the study is the one DIR holds. Returns how many were read, or -1 (why
 * printed). */
long cs_sweep_resume_runs(const char *dir, const cs_sweep_spec *spec, const cs_sweep_resumed *was,
                          const double *x, cs_sweep_result *all, long n, cs_sweep_options *o) {
    char hash[17], path[1200];
    cs_error err;
    if (strcmp(was->version, CS_VERSION_STRING) != 0) {
        cs_sweep_say(o,
                     "%s was written by cablesim %s, this is %s: its runs may differ from this "
                     "one's; run the study again without --resume",
                     dir, was->version, CS_VERSION_STRING);
        return -1;
    }
    snprintf(hash, sizeof hash, "%016llx", spec->origin.model_hash);
    if (!spec->origin.has_model_hash || strcmp(hash, was->model_hash) != 0 ||
        strcmp((snprintf(hash, sizeof hash, "%016llx", spec->origin.inputs_hash), hash), was->inputs_hash) !=
            0) {
        cs_sweep_say(o,
                     "%s: the study has changed since it was stopped (its model, %s, or its values): "
                     "run it again without --resume",
                     dir, spec->model);
        return -1;
    }
    snprintf(path, sizeof path, "%s/%s", dir, was->journal ? CS_OUT_JOURNAL : "runs.csv");
    FILE *f = was->journal ? fmemopen((void *)was->rows, was->rows_length ? was->rows_length : 1, "r")
                           : fopen(path, "r");
    if (!f) {
        cs_sweep_say(o, "%s: %s", path, strerror(errno));
        return -1;
    }
    long got = cs_sweep_read_runs(f, path, spec, x, all, n, was->journal != NULL, &err);
    fclose(f);
    if (got < 0) cs_sweep_say(o, "%s", err.message);
    return got;
}

/* The rows of a sweep's runs.csv text (its header first): its lines, quoted line breaks aside, less one. */
static long csv_rows(const char *text, size_t length) {
    long lines = 0;
    int quoted = 0;
    for (size_t i = 0; i < length; i++) {
        if (text[i] == '"')
            quoted = !quoted; /* a doubled quote inside a quoted cell turns it off and on again */
        else if (text[i] == '\n' && !quoted)
            lines++;
    }
    return lines > 0 ? lines - 1 : 0;
}

long cs_sweep_stopped_runs(const char *dir, const char **where) {
    size_t length = 0;
    cs_error err;
    *where = CS_OUT_JOURNAL;
    char *journal = cs_out_journal_read(dir, &length, &err);
    if (journal) { /* the study's record, then its runs.csv: the journal's runs are the study's */
        char *eol = strchr(journal, '\n');
        long rows = eol && strncmp(journal, CS_OUT_JOURNAL_HEAD, strlen(CS_OUT_JOURNAL_HEAD)) == 0
                        ? csv_rows(eol + 1, length - (size_t)(eol + 1 - journal))
                        : 0;
        free(journal);
        return rows;
    }
    char path[1200];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    *where = "runs.csv";
    if (access(path, F_OK) != 0) return 0;
    json_object *root = json_object_from_file(path), *v;
    long done = root && json_object_object_get_ex(root, "partial", &v) && json_object_get_boolean(v) &&
                        json_object_object_get_ex(root, "runs_done", &v) &&
                        json_object_is_type(v, json_type_int)
                    ? (long)json_object_get_int64(v)
                    : 0;
    json_object_put(root);
    return done > 0 ? done : 0;
}
