/* SPDX-License-Identifier: MIT */
/* The designer page's engine (WebAssembly, built by web/build.sh with emscripten): the model loader and
 * the engine of the command, called from the page's JavaScript (report/designer/). The page writes its
 * model file under /model and the parts library under /data in emscripten's in-memory file system, then
 * runs the model with the form's values as `--set` overrides. Units come from the table the command wrote
 * into the page (cs_units_from_table: udunits2's factors, the same bits); this file stands in for the two
 * functions of the command's loader that need the machine (udunits2's database, the installed data
 * folder). Each call returns JSON text that
 * stays valid until the next call. */
#define _POSIX_C_SOURCE 200809L
#include <emscripten.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cablesim/cablesim.h"
#include "cablesim/loader.h"
#include "load/loader_int.h"
#include "load/units.h"
#include "load/yamledit.h"
#include "load/yamltree.h"
#include "out/jsondoc.h"
#include "out/record.h"
#include "out/report_html.h"
#include "out/writers.h"
#include "status.h"

static char *units_table;     /* the page's units (cs_units_write_table) */
static cs_loader *loader;     /* its files parsed once: runs of one model reuse it */
static char loaded_path[256]; /* the model it last loaded, "" after a failed load */
static char *result;          /* the last call's JSON */

/* The loader's unit system: the page's table (udunits2 is not built for WebAssembly). */
cs_units *cs_units_open(cs_error *err) {
    if (!units_table) {
        cs_error_set(err, CS_ERR_IO, "the page holds no unit table");
        return NULL;
    }
    return cs_units_from_table(units_table, err);
}

/* The parts library is the page's /data (the loader is always given it: this is never asked). */
int cs_data_dir_find(char *dir, size_t size, char *note, size_t note_size) {
    snprintf(dir, size, "/data");
    snprintf(note, note_size, "the page's parts library");
    return 0;
}

/* A call's answer: {"ok": ok} and the members of more (may be NULL; taken) after it, as JSON text kept
 * until the next call. */
static const char *answer(int ok, json_object *more) {
    json_object *doc = json_object_new_object();
    free(result);
    result = NULL;
    if (doc) {
        json_object_object_add(doc, "ok", json_object_new_boolean(ok));
        if (more) {
            json_object_object_foreach(more, key, value)
                json_object_object_add(doc, key, json_object_get(value));
        }
        result = cs_json_text(doc);
    }
    json_object_put(doc), json_object_put(more);
    return result ? result : "{\"ok\":false,\"errors\":[\"out of memory\"]}";
}

/* {"ok":false,"errors":[...]}: the strings of list (taken). */
static const char *failed(json_object *list) {
    json_object *more = json_object_new_object();
    if (more)
        json_object_object_add(more, "errors", list);
    else
        json_object_put(list);
    return answer(0, more);
}

static const char *fail(const char *what) {
    json_object *list = json_object_new_array();
    if (list) json_object_array_add(list, cs_jstr(what));
    return failed(list);
}

/* {"ok":true} with member key: value (taken). */
static const char *succeeded(const char *key, json_object *value) {
    json_object *more = json_object_new_object();
    if (more)
        json_object_object_add(more, key, value);
    else
        json_object_put(value);
    return answer(1, more);
}

/* Keep the page's unit table and make the loader (parts library: data_dir). Returns JSON {"ok"}. */
EMSCRIPTEN_KEEPALIVE const char *cs_web_open(const char *table, const char *data_dir) {
    cs_error err;
    free(units_table);
    cs_loader_free(loader);
    loaded_path[0] = '\0';
    units_table = strdup(table);
    loader = units_table ? cs_loader_create(data_dir, &err) : NULL;
    if (!loader) return fail(units_table ? err.message : "out of memory");
    /* the page's file system holds only the files `cablesim designer` read under the rule of the folders
     * a model may read (its --allow-path folders included): all of it may be read */
    if (cs_loader_allow_path(loader, "/", &err) != CS_OK) return fail(err.message);
    return answer(1, NULL);
}

/* The loader's problems as {"ok":false,"errors":[...]}. */
static const char *problems(void) {
    json_object *list = json_object_new_array();
    for (int i = 0; list && i < cs_loader_error_count(loader); i++)
        json_object_array_add(list, cs_jstr(cs_loader_error(loader, i)));
    return failed(list);
}

/* Split sets ("PATH=VALUE" lines) in place into at most max lines. Returns the count, or -1 past max. */
static int split(char *sets, char **line, int max) {
    int n = 0;
    for (char *s = sets; s && *s;) {
        char *nl = strchr(s, '\n');
        if (nl) *nl = '\0';
        if (*s && n == max) return -1;
        if (*s) line[n++] = s;
        s = nl ? nl + 1 : NULL;
    }
    return n;
}

/* A time in ms as a JSON number to the microsecond. */
static json_object *fixed3(double ms) {
    char text[32];
    snprintf(text, sizeof text, "%.3f", ms);
    return json_object_new_double_s(ms, text);
}

static double ms_since(const struct timespec *t0) {
    struct timespec t1;
    clock_gettime(CLOCK_MONOTONIC, &t1);
    return (double)(t1.tv_sec - t0->tv_sec) * 1e3 + (double)(t1.tv_nsec - t0->tv_nsec) * 1e-6;
}

/* Run the model file at path with the overrides of sets (one "PATH=VALUE" a line). JSON: {"ok":true,
 * "ms": the run's time (cs_run), "load_ms": the model's (loaded and built), "summary": summary.json's object,
 * "text": the command's terminal summary, "report": report.html's data (with_report)} or
 * {"ok":false,"errors":[...]}, each problem as the command words it. */
EMSCRIPTEN_KEEPALIVE const char *cs_web_run(const char *path, const char *sets, int with_report) {
    if (!loader) return fail("cs_web_open was not called");
    if (strcmp(path, loaded_path) == 0)
        cs_loader_reuse(loader);
    else
        cs_loader_reset(loader);
    loaded_path[0] = '\0';
    char *copy = strdup(sets), *line[64], set_text[64][1100];
    if (!copy) return fail("out of memory");
    int n = split(copy, line, 64);
    if (n < 0) {
        free(copy);
        return fail("more than 64 values changed at once");
    }
    const char *overrides[64];
    for (int i = 0; i < n; i++) {
        cs_loader_set(loader, line[i]);
        snprintf(set_text[i], sizeof set_text[i], "--set %s", line[i]);
        overrides[i] = set_text[i];
    }
    free(copy);
    cs_model_input in = {.size = sizeof in};
    cs_model *model = NULL;
    struct timespec t_load;
    clock_gettime(CLOCK_MONOTONIC, &t_load);
    if (cs_loader_load(loader, path, &in) != 0 || !(model = cs_loader_build(loader, &in))) return problems();
    double load_ms = ms_since(&t_load);
    snprintf(loaded_path, sizeof loaded_path, "%s", path);
    cs_error err = {0};
    cs_state *state = cs_state_create(model, &err);
    cs_record rec;
    if (!state || cs_record_init(&rec, model) != 0) {
        cs_state_free(state);
        cs_model_free(model);
        return fail(state ? "out of memory" : err.message);
    }
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int rc = cs_run(model, state, cs_record_frame, &rec, &err);
    double ms = ms_since(&t0);
    const char *out;
    if (rc != CS_OK || rec.failed) {
        out = fail(rc != CS_OK ? err.message : "out of memory while recording");
    } else {
        cs_summary sm = {.size = sizeof sm};
        cs_state_summary(state, &sm, NULL);
        cs_run_info info = {.command = "cablesim designer",
                            .overrides = overrides,
                            .override_count = n,
                            .model_hash = cs_model_input_hash(&in)};
        cs_run_info_rate(&info, &in, &sm);
        cs_run_info_motion(&info, &in, &rec, state, &sm);
        char why[512] = "", *text = NULL;
        size_t text_size = 0;
        FILE *t = open_memstream(&text, &text_size);
        if (t) {
            cs_write_summary_text_with(t, &in, model, state, &info);
            fclose(t);
        }
        json_object *more = json_object_new_object(),
                    *summary = cs_summary_json(&in, model, state, &info, &err),
                    *report = summary && with_report ? cs_report_json(&in, state, &rec, &info, &err) : NULL;
        if (!summary || (with_report && !report)) snprintf(why, sizeof why, "%s", err.message);
        if (!more || !summary || (with_report && !report)) {
            json_object_put(more), json_object_put(summary), json_object_put(report);
            out = fail(why[0] ? why : "out of memory");
        } else {
            json_object_object_add(more, "ms", fixed3(ms));
            json_object_object_add(more, "load_ms", fixed3(load_ms));
            json_object_object_add(more, "summary", summary);
            json_object_object_add(more, "text", cs_jstr(text ? text : ""));
            json_object_object_add(more, "report", report);
            out = answer(1, more);
        }
        free(text);
    }
    cs_record_release(&rec);
    cs_state_free(state);
    cs_model_free(model);
    return out;
}

/* Every single value written in a YAML file, in file order: {"ok":true,"values":[{"path","text","line",
 * "col"}...]}. */
EMSCRIPTEN_KEEPALIVE const char *cs_web_values(const char *path) {
    cs_ytree t = {0};
    if (cs_ytree_read(&t, path, NULL, 0, 64) != 0) {
        char why[300];
        snprintf(why, sizeof why, "%s:%d:%d: %s", path, t.error_line, t.error_col, t.error);
        cs_ytree_free(&t);
        return fail(why);
    }
    json_object *values = json_object_new_array();
    for (int i = 0; values && i < t.count; i++) {
        const cs_ynode *n = &t.items[i];
        if (n->kind != CS_Y_SCALAR) continue;
        json_object *v = json_object_new_object();
        if (!v) break;
        json_object_object_add(v, "path", cs_jstr(n->path));
        json_object_object_add(v, "text", cs_jstr(n->text));
        json_object_object_add(v, "line", json_object_new_int(n->line));
        json_object_object_add(v, "col", json_object_new_int(n->col));
        json_object_array_add(values, v);
    }
    cs_ytree_free(&t);
    return succeeded("values", values);
}

/* The model file at path with the overrides of sets written into it (cs_yaml_edit): {"ok":true,"yaml"}. */
EMSCRIPTEN_KEEPALIVE const char *cs_web_edit(const char *path, const char *sets) {
    FILE *in = fopen(path, "rb");
    if (!in) return fail("cannot open the model file");
    char *text = NULL;
    size_t size = 0;
    FILE *buf = open_memstream(&text, &size);
    char chunk[4096];
    size_t got;
    while (buf && (got = fread(chunk, 1, sizeof chunk, in)) > 0)
        fwrite(chunk, 1, got, buf);
    fclose(in);
    if (!buf) return fail("out of memory");
    fclose(buf);
    char *copy = strdup(sets), *line[64];
    cs_error err = {CS_ERR_MEMORY, "out of memory"};
    int n = copy ? split(copy, line, 64) : 0;
    size_t edited_size = 0;
    if (n < 0) cs_error_set(&err, CS_ERR_INVALID, "more than 64 values changed at once");
    char *edited =
        copy && n >= 0 ? cs_yaml_edit(text, size, (const char *const *)line, n, &edited_size, &err) : NULL;
    free(copy);
    free(text);
    if (!edited) return fail(err.message);
    json_object *yaml = cs_jstr(edited);
    free(edited);
    return succeeded("yaml", yaml);
}

/* The parts library's names: {"ok":true,"vehicle":[...],"rope":[...],"section":[...],"rail":[...]}. */
EMSCRIPTEN_KEEPALIVE const char *cs_web_parts(void) {
    static const char *kinds[CS_PART_KIND_COUNT] = {"vehicle", "rope", "section", "rail"};
    if (!loader) return fail("cs_web_open was not called");
    json_object *more = json_object_new_object();
    for (int k = 0; more && k < CS_PART_KIND_COUNT; k++) {
        const char **names, **descriptions;
        int n = cs_loader_library(loader, (cs_part_kind)k, &names, &descriptions);
        json_object *list = json_object_new_array();
        for (int i = 0; list && i < n; i++)
            json_object_array_add(list, cs_jstr(names[i]));
        json_object_object_add(more, kinds[k], list);
    }
    return answer(1, more);
}
