/* SPDX-License-Identifier: MIT */
/* The sweep spec: a YAML file read through the loader's YAML tree (yamltree.h), like the model files.
 * The keys of `set` and `vary` are model paths, a plot's x and lines are paths of `vary`; every value is
 * checked, each error at its line:column. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grow.h"
#include "loader_int.h"
#include "status.h"
#include "sweepspec.h"
#include "sweepspec_int.h"

/* ---- errors ---- */

/* The line and column an error names in the spec (LONG_MAX: none). */
static void error_place(const cs_sweep_spec *s, const char *e, long *line, long *col) {
    size_t n = strlen(s->file);
    *line = LONG_MAX, *col = 0;
    if (strncmp(e, s->file, n) != 0 || e[n] != ':') return;
    char *end;
    long l = strtol(e + n + 1, &end, 10);
    if (*end != ':') return;
    *line = l;
    *col = strtol(end + 1, NULL, 10);
}

static void add_error(cs_sweep_spec *s, int line, int col, const char *fmt, va_list ap) {
    char msg[900], text[1400];
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (line > 0)
        snprintf(text, sizeof text, "%s:%d:%d: %s", s->file, line, col, msg);
    else
        snprintf(text, sizeof text, "%s", msg);
    if (cs_grow(&s->errors, &s->error_capacity, s->error_count, sizeof *s->errors) != 0) return;
    char *copy = strdup(text);
    if (!copy) return;
    /* keep them in the order of their places in the spec; those with none last, as they came */
    long l, c, li, ci;
    error_place(s, copy, &l, &c);
    int at = s->error_count;
    while (at > 0 && (error_place(s, s->errors[at - 1], &li, &ci), li > l || (li == l && ci > c)))
        at--;
    memmove(&s->errors[at + 1], &s->errors[at], (size_t)(s->error_count - at) * sizeof *s->errors);
    s->errors[at] = copy;
    s->error_count++;
}

void cs_sweep_error(cs_sweep_spec *s, int line, int col, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    add_error(s, line, col, fmt, ap);
    va_end(ap);
}

/* ---- the file's tree ---- */

enum { MAX_DEPTH = 32 }; /* how deep a spec's collections may nest: far more than a spec's own */

static const char *const top_keys[] = {"model",  "method", "runs", "seed", "vehicle_class",
                                       "netcdf", "set",    "vary", "plot"};
enum {
    TOP_MODEL,
    TOP_METHOD,
    TOP_RUNS,
    TOP_SEED,
    TOP_CLASS,
    TOP_NETCDF,
    TOP_SET,
    TOP_VARY,
    TOP_PLOT,
    TOP_COUNT
};
static const char *const plot_keys[] = {"x", "y", "lines", "format"};
enum { PLOT_KEYS = 4 };

static int scalar_map(const cs_ynode *n) {
    if (!n || n->kind != CS_Y_MAP) return 0;
    for (int i = 0; i < n->count; i++)
        if (n->kids[i]->kind != CS_Y_SCALAR) return 0;
    return 1;
}

static int scalar_seq(const cs_ynode *n) {
    if (!n || n->kind != CS_Y_SEQ) return 0;
    for (int i = 0; i < n->count; i++)
        if (n->kids[i]->kind != CS_Y_SCALAR) return 0;
    return 1;
}

static int known_param(const char *key) {
    for (int p = 0; p < P_N; p++)
        if (strcmp(key, param_keys[p]) == 0) return p;
    return -1;
}

static int known_plot_key(const char *key) {
    for (int p = 0; p < PLOT_KEYS; p++)
        if (strcmp(key, plot_keys[p]) == 0) return 1;
    return 0;
}

/* `plot:` is one plot (a mapping) or a list of them: how many entries, and entry i. */
static int plot_entry_count(const cs_ynode *plot) {
    return !plot ? 0 : plot->kind == CS_Y_MAP ? 1 : plot->kind == CS_Y_SEQ ? plot->count : 0;
}

static const cs_ynode *plot_entry(const cs_ynode *plot, int i) {
    return plot->kind == CS_Y_MAP ? plot : plot->kids[i];
}

int cs_sweep_is_spec(const char *path) {
    cs_ytree tree;
    cs_ytree_read(&tree, path, NULL, 0, MAX_DEPTH); /* what was read before an error counts */
    int found = tree.count > 0 && cs_ynode_get(&tree.items[0], "vary") != NULL;
    cs_ytree_free(&tree);
    return found;
}

/* The value given earlier at the key of a mapping's value n, if there is one. */
static const cs_ynode *repeated(const cs_ynode *map, const cs_ynode *n) {
    const cs_ynode *first = n->key ? cs_ynode_get(map, n->key) : NULL;
    return first != n ? first : NULL;
}

/* Is the first value at a key of the spec's mapping one the spec reads (its shape right)? */
static int top_read(const cs_ynode *n) {
    if (!n) return 0;
    int k = 0;
    while (k < TOP_COUNT && strcmp(n->key, top_keys[k]) != 0)
        k++;
    if (k < TOP_SET) return n->kind == CS_Y_SCALAR;
    if (k == TOP_SET) return scalar_map(n) && n->count > 0;
    if (k == TOP_PLOT) return n->kind == CS_Y_MAP || n->kind == CS_Y_SEQ;
    return k == TOP_VARY && n->kind == CS_Y_MAP && n->count > 0;
}

/* A key given twice where its value is read (one of the spec's own values, an entry of `set` or `vary`, a
 * parameter of a `vary` entry, a key of a plot) leaves unclear which value is meant: the spec is then read no
 * further than its shapes. Keys repeated where nothing is read (an unknown key, a value whose shape was
 * refused) only have their messages. */
static int given_twice(const cs_ynode *root) {
    for (int i = 0; i < root->count; i++)
        if (top_read(repeated(root, root->kids[i]))) return 1;
    const cs_ynode *set = cs_ynode_get(root, "set"), *vary = cs_ynode_get(root, "vary");
    for (int i = 0; top_read(set) && i < set->count; i++)
        if (repeated(set, set->kids[i])) return 1;
    for (int i = 0; top_read(vary) && i < vary->count; i++) {
        const cs_ynode *e = vary->kids[i], *first = repeated(vary, e);
        if (first && (scalar_seq(first) || first->kind == CS_Y_MAP)) return 1;
        for (int q = 0; !first && e->kind == CS_Y_MAP && q < e->count; q++) {
            const cs_ynode *p = repeated(e, e->kids[q]);
            if (p && known_param(p->key) >= 0 && p->kind == CS_Y_SCALAR) return 1;
        }
    }
    const cs_ynode *plot = cs_ynode_get(root, "plot");
    for (int i = 0; top_read(plot) && i < plot_entry_count(plot); i++) {
        const cs_ynode *e = plot_entry(plot, i);
        for (int q = 0; e->kind == CS_Y_MAP && q < e->count; q++) {
            const cs_ynode *p = repeated(e, e->kids[q]);
            if (p && known_plot_key(p->key) && p->kind == CS_Y_SCALAR) return 1;
        }
    }
    return 0;
}

/* ---- shapes ---- */

static void check_plot_shapes(cs_sweep_spec *s, const cs_ynode *n) {
    int count = plot_entry_count(n);
    if (n->kind != CS_Y_MAP && n->kind != CS_Y_SEQ) {
        cs_sweep_error(s, n->line, n->col,
                       "plot is %s (expected a mapping {x: PATH, y: RESPONSE} or a list of them)",
                       cs_ykind_name(n->kind));
        return;
    }
    if (count == 0 || count > CS_SWEEP_MAX_PLOTS) {
        cs_sweep_error(s, n->line, n->col, "plot: %d plots (expected 1 to %d)", count, CS_SWEEP_MAX_PLOTS);
        return;
    }
    for (int i = 0; i < count; i++) {
        const cs_ynode *e = plot_entry(n, i);
        if (e->kind != CS_Y_MAP) {
            cs_sweep_error(s, e->line, e->col,
                           "plot: an entry is %s (expected a mapping {x: PATH, y: RESPONSE})",
                           cs_ykind_name(e->kind));
            continue;
        }
        for (int q = 0; q < e->count; q++) {
            const cs_ynode *p = e->kids[q];
            if (!known_plot_key(p->key))
                cs_sweep_error(s, p->key_line, p->key_col,
                               "plot: unknown key '%s' (expected one of: x, y, lines, format)", p->key);
            else if (p->kind != CS_Y_SCALAR)
                cs_sweep_error(s, p->line, p->col, "plot: %s is %s (expected a single value)", p->key,
                               cs_ykind_name(p->kind));
        }
    }
}

static void check_shapes(cs_sweep_spec *s, const cs_ynode *root) {
    for (int i = 0; i < root->count; i++) {
        const cs_ynode *n = root->kids[i];
        int k = 0;
        while (k < TOP_COUNT && strcmp(n->key, top_keys[k]) != 0)
            k++;
        if (k == TOP_COUNT) {
            cs_sweep_error(s, n->key_line, n->key_col,
                           "unknown key '%s' (expected one of: model, method, runs, seed, vehicle_class, "
                           "netcdf, set, vary, plot)",
                           n->key);
        } else if (k == TOP_PLOT) {
            check_plot_shapes(s, n);
        } else if (k < TOP_SET && n->kind != CS_Y_SCALAR) {
            cs_sweep_error(s, n->line, n->col, "%s is %s (expected a single value)", n->key,
                           cs_ykind_name(n->kind));
        } else if (k >= TOP_SET && n->kind != CS_Y_MAP) {
            cs_sweep_error(s, n->line, n->col, "%s is %s (expected a mapping of model paths, e.g. %s)",
                           n->key, cs_ykind_name(n->kind),
                           k == TOP_SET ? "scenario.t_end: 0.5 s" : "scenario.speed: [35 mph, 40 mph]");
        } else if (k == TOP_SET) {
            for (int j = 0; j < n->count; j++)
                if (n->kids[j]->kind != CS_Y_SCALAR)
                    cs_sweep_error(s, n->kids[j]->line, n->kids[j]->col,
                                   "set: %s is %s (expected a single value, as --set)", n->kids[j]->key,
                                   cs_ykind_name(n->kids[j]->kind));
        } else if (k == TOP_VARY) {
            for (int j = 0; j < n->count; j++) {
                const cs_ynode *e = n->kids[j];
                if (e->kind == CS_Y_SEQ) {
                    for (int q = 0; q < e->count; q++)
                        if (e->kids[q]->kind != CS_Y_SCALAR)
                            cs_sweep_error(s, e->kids[q]->line, e->kids[q]->col,
                                           "vary: %s: a level is %s (expected a single value)", e->key,
                                           cs_ykind_name(e->kids[q]->kind));
                } else if (e->kind == CS_Y_MAP) {
                    for (int q = 0; q < e->count; q++) {
                        const cs_ynode *p = e->kids[q];
                        if (known_param(p->key) < 0)
                            cs_sweep_error(
                                s, p->key_line, p->key_col,
                                "vary: %s: unknown key '%s' (expected one of: dist, mean, sd, min, "
                                "max; or from, to, step, count)",
                                e->key, p->key);
                        else if (p->kind != CS_Y_SCALAR)
                            cs_sweep_error(s, p->line, p->col, "vary: %s: %s is %s (expected a single value)",
                                           e->key, p->key, cs_ykind_name(p->kind));
                    }
                } else {
                    cs_sweep_error(
                        s, e->line, e->col,
                        "vary: %s is %s (expected a list of values, {from, to, step} or {dist: ...})", e->key,
                        cs_ykind_name(e->kind));
                }
            }
        }
    }
}

/* ---- model paths ---- */

/* Walk the schema along a --set path to one value: CS_OK with v's kind filled, or CS_ERR_INVALID with err
 * filled. */
static cs_status path_field(const char *path, cs_sweep_var *v, cs_error *err) {
    cs_schema_place at;
    cs_schema_walk(path, &at);
    const cs_field *f = at.field;
    if (at.fault == CS_PATH_NEEDS_INDEX)
        return cs_error_set(err, CS_ERR_INVALID, "'%s' needs an index before '%s' (e.g. %s[0].%s)", f->key,
                            at.key, f->key, at.key);
    if (at.fault == CS_PATH_UNKNOWN_KEY)
        return cs_error_set(err, CS_ERR_INVALID, "unknown key '%s'%s%s (expected a model path, as --set)",
                            at.key, at.table ? " in " : "", at.table ? at.table->name : "");
    if (at.fault == CS_PATH_NO_LIST)
        return cs_error_set(err, CS_ERR_INVALID, "no list before [%ld] (expected a model path, as --set)",
                            at.index);
    if (at.fault != CS_PATH_OK || !f)
        return cs_error_set(err, CS_ERR_INVALID,
                            "malformed path (expected keys and [index], e.g. barrier.cables[0].height)");
    int item = at.item;
    int one = f->kind == CS_F_QTY || f->kind == CS_F_INT || f->kind == CS_F_TEXT || f->kind == CS_F_ENUM ||
              f->kind == CS_F_PART || (f->kind == CS_F_LIST && item);
    if (!one)
        return cs_error_set(err, CS_ERR_INVALID,
                            "'%s' is not a single value (expected a path to one value, as --set)", f->key);
    v->numeric = f->kind == CS_F_QTY || f->kind == CS_F_INT || f->kind == CS_F_LIST;
    v->integer = f->kind == CS_F_INT;
    v->q = f->kind == CS_F_INT ? CS_Q_NUMBER : f->q;
    v->unit = v->numeric ? cs_quantity_get(v->q)->label : "";
    return CS_OK;
}

/* ---- the spec ---- */

static const char *const class_names[] = {"C", "PU", "M", "H"};

static void read_scalars(cs_sweep_spec *s, const cs_ynode *root) {
    const cs_ynode *n;
    if (!(n = cs_ynode_get(root, "model")))
        cs_sweep_error(s, root->line, root->col, "no model (expected model: FILE, the base model file)");
    else if (text(n)) {
        const char *m = text(n);
        const char *slash = strrchr(s->file, '/');
        size_t dir = m[0] == '/' || !slash ? 0 : (size_t)(slash - s->file) + 1;
        size_t len = dir + strlen(m) + 1;
        if ((s->model = malloc(len))) snprintf(s->model, len, "%.*s%s", (int)dir, s->file, m);
        s->model_line = n->line, s->model_col = n->col;
        if (s->model && access(s->model, R_OK) != 0)
            cs_sweep_error(s, n->line, n->col,
                           "model: cannot open '%s' (expected a readable model file, relative "
                           "to the spec's folder)",
                           m);
    }
    static const char *const methods[] = {"grid", "monte_carlo", "latin_hypercube"};
    if (!(n = cs_ynode_get(root, "method"))) {
        cs_sweep_error(s, root->line, root->col,
                       "no method (expected method: grid, monte_carlo or latin_hypercube)");
    } else if (text(n)) {
        int k = 0;
        while (k < 3 && strcmp(text(n), methods[k]) != 0)
            k++;
        if (k == 3)
            cs_sweep_error(s, n->line, n->col,
                           "method: unknown '%s' (expected grid, monte_carlo or latin_hypercube)", text(n));
        s->method = k == 3 ? CS_SWEEP_GRID : (cs_sweep_method)k;
    }
    n = cs_ynode_get(root, "runs");
    if (text(n)) {
        char *end;
        errno = 0;
        long r = strtol(text(n), &end, 10);
        if (*end || errno || r < 1 || r > CS_SWEEP_MAX_RUNS)
            cs_sweep_error(s, n->line, n->col, "runs: '%s' (expected a whole number from 1 to %d)", text(n),
                           CS_SWEEP_MAX_RUNS);
        s->runs = r;
    }
    n = cs_ynode_get(root, "seed");
    s->seed = 1;
    if (text(n)) {
        char *end;
        errno = 0;
        const char *t = text(n);
        unsigned long long v = strtoull(t, &end, 10);
        if (*end || errno || end == t || t[0] == '-')
            cs_sweep_error(s, n->line, n->col, "seed: '%s' (expected a whole number from 0 to 2^64 - 1)", t);
        s->seed = (uint64_t)v;
    }
    n = cs_ynode_get(root, "vehicle_class");
    if (text(n)) {
        int k = 0;
        while (k < 4 && strcmp(text(n), class_names[k]) != 0)
            k++;
        if (k == 4)
            cs_sweep_error(s, n->line, n->col,
                           "vehicle_class: unknown '%s' (expected an ASTM F2656 class: C, PU, M or H)",
                           text(n));
        else
            snprintf(s->vehicle_class, sizeof s->vehicle_class, "%s", class_names[k]);
    }
    n = cs_ynode_get(root, "netcdf");
    if (text(n)) {
        const char *t = text(n);
        s->netcdf = strcmp(t, "true") == 0;
        if (!s->netcdf && strcmp(t, "false") != 0)
            cs_sweep_error(s, n->line, n->col, "netcdf: '%s' (expected true or false)", t);
    }
}

static int push_set(cs_sweep_spec *s, const char *path, const char *value, const char *given, int line,
                    int col) {
    int n = s->set_count;
    size_t len = strlen(path) + strlen(value) + 2;
    if (cs_grow_one(&s->sets, n, sizeof *s->sets) != 0 ||
        cs_grow_one(&s->set_given, n, sizeof *s->set_given) != 0 ||
        cs_grow_one(&s->set_line, n, sizeof *s->set_line) != 0 ||
        cs_grow_one(&s->set_col, n, sizeof *s->set_col) != 0 || !(s->sets[n] = malloc(len)))
        return -1;
    if (!(s->set_given[n] = given ? strdup(given) : NULL) && given) {
        free(s->sets[n]);
        return -1;
    }
    snprintf(s->sets[n], len, "%s=%s", path, value);
    s->set_line[n] = line, s->set_col[n] = col;
    s->set_count++;
    return 0;
}

/* The study's varied path that a fixed path would meet (the same path, one inside it or one holding it),
 * or NULL: each run's level would replace the fixed value, or the fixed value the level. */
static const char *varied(const cs_sweep_spec *s, const char *path) {
    size_t n = strlen(path);
    for (int i = 0; i < s->var_count; i++) {
        const char *v = s->vars[i].path;
        size_t m = strlen(v), k = n < m ? n : m;
        if (strncmp(v, path, k) == 0 && (n == m || strchr(".[", n < m ? v[k] : path[k]))) return v;
    }
    return NULL;
}

/* A fixed value (set: or --set, its place line and col, 0 for --set; given: the option it stands for as
 * the user gave it, "--dt 2 ms", or NULL) on a path the study varies: an error, naming it as given. */
static void set_not_varied(cs_sweep_spec *s, const char *path, const char *value, const char *given, int line,
                           int col) {
    const char *v = varied(s, path);
    if (v && given)
        cs_sweep_error(s, line, col,
                       "%s: the study varies %s, so a fixed value would not be used (expected no %.*s)",
                       given, v, (int)strcspn(given, " "), given);
    else if (v)
        cs_sweep_error(
            s, line, col,
            "%s %s=%s: the study varies %s, so a fixed value would not be used (expected a path that "
            "vary does not hold)",
            line ? "set:" : "--set", path, value, v);
}

int cs_sweep_spec_add_set(cs_sweep_spec *s, const char *assignment, const char *given) {
    const char *eq = strchr(assignment, '=');
    if (!eq || eq == assignment) {
        cs_sweep_error(s, 0, 0, "--set %s: expected PATH=VALUE, e.g. scenario.speed=\"35 mph\"", assignment);
        return -1;
    }
    char path[512];
    snprintf(path, sizeof path, "%.*s", (int)(eq - assignment), assignment);
    set_not_varied(s, path, eq + 1, given, 0, 0);
    return push_set(s, path, eq + 1, given, 0, 0);
}

static void read_vary(cs_sweep_spec *s, cs_units *u, const cs_ynode *root) {
    const cs_ynode *vary = cs_ynode_get(root, "vary");
    if (!vary) {
        cs_sweep_error(s, root->line, root->col,
                       "no vary (expected vary: a mapping of model paths to values)");
        return;
    }
    if (vary->kind != CS_Y_MAP) return;
    if (vary->count == 0 || vary->count > CS_SWEEP_MAX_VARS) {
        cs_sweep_error(s, vary->line, vary->col, "vary: %d entries (expected 1 to %d)", vary->count,
                       CS_SWEEP_MAX_VARS);
        return;
    }
    if (!(s->vars = calloc((size_t)vary->count, sizeof *s->vars))) return;
    for (int i = 0; i < vary->count; i++) {
        const cs_ynode *e = vary->kids[i];
        cs_sweep_var *v = &s->vars[s->var_count++];
        v->line = e->key_line, v->col = e->key_col;
        if (!(v->path = strdup(e->key))) return;
        cs_error err;
        if (path_field(v->path, v, &err) != CS_OK) {
            cs_sweep_error(s, e->key_line, e->key_col, "vary: %s: %s", v->path, err.message);
            continue;
        }
        if (!scalar_seq(e) && !scalar_map(e)) continue; /* its shape was reported */
        const cs_ynode *dn = cs_ynode_get(e, "dist");
        if (dn && s->method == CS_SWEEP_GRID) {
            cs_sweep_error(s, dn->key_line, dn->key_col,
                           "vary: %s: a distribution needs method monte_carlo or "
                           "latin_hypercube (expected a list or from/to/step with method grid)",
                           v->path);
        } else if (!dn && s->method != CS_SWEEP_GRID) {
            cs_sweep_error(s, e->line, e->col,
                           "vary: %s: %s needs method grid (expected {dist: ...} with method %s)", v->path,
                           e->kind == CS_Y_SEQ ? "a list of values" : "a range",
                           s->method == CS_SWEEP_MONTE_CARLO ? "monte_carlo" : "latin_hypercube");
        } else if (dn) {
            cs_sweep_read_dist(s, u, v, e);
        } else {
            cs_sweep_read_grid(s, u, v, e);
        }
    }
}

static void check_runs(cs_sweep_spec *s, const cs_ynode *root) {
    const cs_ynode *runs = cs_ynode_get(root, "runs");
    if (s->method == CS_SWEEP_GRID) {
        if (runs)
            cs_sweep_error(s, runs->key_line, runs->key_col,
                           "runs: not used by a grid (its runs are every combination of the levels)");
        double n = 1;
        for (int i = 0; i < s->var_count; i++)
            n *= s->vars[i].level_count > 0 ? s->vars[i].level_count : 1;
        if (n > CS_SWEEP_MAX_RUNS) {
            const cs_ynode *vary = cs_ynode_get(root, "vary");
            cs_sweep_error(s, vary->line, vary->col, "vary: the grid has %.0f runs (expected at most %d)", n,
                           CS_SWEEP_MAX_RUNS);
        }
        s->runs = (long)fmin(n, CS_SWEEP_MAX_RUNS);
    } else if (!runs) {
        cs_sweep_error(s, root->line, root->col, "no runs (expected runs: N for method %s)",
                       s->method == CS_SWEEP_MONTE_CARLO ? "monte_carlo" : "latin_hypercube");
    }
}

/* ---- plots ---- */

/* The spec's varied paths, for messages: "a, b, c". */
static void varied_paths(const cs_sweep_spec *s, char *buf, size_t size) {
    size_t used = 0;
    buf[0] = '\0';
    for (int j = 0; j < s->var_count && used < size; j++)
        used += (size_t)snprintf(buf + used, size - used, "%s%s", j ? ", " : "", s->vars[j].path);
}

/* A plot's x or lines (key): the index of the varied value it names; -1 if it names none (error
 * recorded) or one whose path was refused. */
static int plot_var(cs_sweep_spec *s, const cs_ynode *e, const char *key) {
    const cs_ynode *n = cs_ynode_get(e, key);
    char paths[400];
    varied_paths(s, paths, sizeof paths);
    if (!n) {
        cs_sweep_error(s, e->line, e->col, "plot: no %s (expected %s: one of the varied paths: %s)", key, key,
                       paths);
        return -1;
    }
    for (int j = 0; j < s->var_count; j++) {
        const cs_sweep_var *v = &s->vars[j];
        if (strcmp(v->path, n->text) != 0) continue;
        if (!v->unit) return -1; /* its path was reported */
        if (!v->numeric && strcmp(key, "x") == 0) {
            cs_sweep_error(s, n->line, n->col,
                           "plot: x: %s is text (expected a varied value that is a number)", v->path);
            return -1;
        }
        return j;
    }
    cs_sweep_error(s, n->line, n->col, "plot: %s: '%s' is not varied by the spec (expected one of: %s)", key,
                   n->text, paths);
    return -1;
}

/* A plot's lines: a varied value of a grid other than x, with few enough levels for a colour each. */
static int plot_lines(cs_sweep_spec *s, const cs_ynode *e, int x) {
    const cs_ynode *n = cs_ynode_get(e, "lines");
    if (!n) return -1;
    if (s->method != CS_SWEEP_GRID) {
        cs_sweep_error(s, n->key_line, n->key_col,
                       "plot: lines needs method grid (expected no lines with method %s: its runs have no "
                       "levels, and the plot shows each run as a point)",
                       s->method == CS_SWEEP_MONTE_CARLO ? "monte_carlo" : "latin_hypercube");
        return -1;
    }
    int j = plot_var(s, e, "lines");
    if (j >= 0 && j == x) {
        cs_sweep_error(s, n->line, n->col, "plot: lines: %s is x already (expected another varied value)",
                       n->text);
        return -1;
    }
    if (j >= 0 && s->vars[j].level_count > CS_SWEEP_MAX_LINES) {
        cs_sweep_error(s, n->line, n->col,
                       "plot: lines: %s has %d levels (expected at most %d, a colour each)", n->text,
                       s->vars[j].level_count, CS_SWEEP_MAX_LINES);
        return -1;
    }
    return j;
}

static void read_plot(cs_sweep_spec *s, const cs_ynode *e, cs_sweep_plot *p) {
    p->line = e->line, p->col = e->col;
    snprintf(p->format, sizeof p->format, "png");
    p->x = plot_var(s, e, "x");
    const cs_ynode *y = cs_ynode_get(e, "y"), *format = cs_ynode_get(e, "format");
    if (!y)
        cs_sweep_error(s, e->line, e->col,
                       "plot: no y (expected y: a number column of runs.csv, e.g. max_barrier_deflection)");
    else if (!(p->y = strdup(y->text)))
        return;
    else
        p->y_line = y->line, p->y_col = y->col;
    if (format && strcmp(format->text, "png") != 0 && strcmp(format->text, "svg") != 0 &&
        strcmp(format->text, "pdf") != 0)
        cs_sweep_error(s, format->line, format->col, "plot: format: '%s' (expected png, svg or pdf)",
                       format->text);
    else if (format)
        snprintf(p->format, sizeof p->format, "%s", format->text);
    p->lines = plot_lines(s, e, p->x);
    if (p->x < 0 || (p->lines < 0 && cs_ynode_get(e, "lines")) || s->method != CS_SWEEP_GRID) return;
    /* a grid's line joins the runs that differ in x alone */
    for (int j = 0; j < s->var_count; j++)
        if (j != p->x && j != p->lines) {
            cs_sweep_error(s, e->line, e->col,
                           "plot: %s varies too (expected every varied value of a grid as x or lines; fix "
                           "the others with set:)",
                           s->vars[j].path);
            return;
        }
}

static void read_plots(cs_sweep_spec *s, const cs_ynode *root) {
    const cs_ynode *plot = cs_ynode_get(root, "plot");
    int count = plot_entry_count(plot);
    if (count == 0 || count > CS_SWEEP_MAX_PLOTS) return; /* reported with the shapes */
    if (!(s->plots = calloc((size_t)count, sizeof *s->plots))) return;
    for (int i = 0; i < count; i++) {
        const cs_ynode *e = plot_entry(plot, i);
        cs_sweep_plot *p = &s->plots[s->plot_count++];
        p->x = p->lines = -1;
        if (scalar_map(e)) read_plot(s, e, p); /* other shapes were reported */
    }
}

cs_sweep_spec *cs_sweep_spec_read(const char *path, cs_units *units) {
    return cs_sweep_spec_read_buffer(path, NULL, 0, units);
}

cs_sweep_spec *cs_sweep_spec_read_buffer(const char *path, const char *data, size_t size, cs_units *units) {
    cs_sweep_spec *s = calloc(1, sizeof *s);
    if (!s || !(s->file = strdup(path))) {
        free(s);
        return NULL;
    }
    s->seed = 1;
    cs_ytree tree;
    int rc = cs_ytree_read(&tree, path, data, size, MAX_DEPTH);
    for (int i = 1; i < tree.count; i++) {
        const cs_ynode *n = &tree.items[i], *first = repeated(&tree.items[n->parent], n);
        if (first)
            cs_sweep_error(s, n->key_line, n->key_col, "%s: given twice (first at %d:%d)", n->key,
                           first->key_line, first->key_col);
    }
    const cs_ynode *root = tree.count > 0 ? &tree.items[0] : NULL;
    if (rc != 0 && tree.unreadable)
        cs_sweep_error(s, 0, 0, "%s: %s (expected a readable sweep spec)", path, tree.error);
    else if (rc != 0)
        cs_sweep_error(s, tree.error_line, tree.error_col, "%s", tree.error);
    else if (!root)
        cs_sweep_error(s, 1, 1, "the file is empty (expected a mapping: model, method, vary...)");
    else if (root->kind != CS_Y_MAP)
        cs_sweep_error(s, root->line, root->col,
                       "the document is %s (expected a mapping: model, method, vary...)",
                       cs_ykind_name(root->kind));
    if (rc == 0 && root && root->kind == CS_Y_MAP) {
        check_shapes(s, root);
        if (!given_twice(root)) {
            read_scalars(s, root);
            const cs_ynode *set = cs_ynode_get(root, "set");
            for (int i = 0; top_read(set) && i < set->count; i++)
                if (push_set(s, set->kids[i]->key, set->kids[i]->text, NULL, set->kids[i]->key_line,
                             set->kids[i]->key_col) != 0)
                    break;
            read_vary(s, units, root);
            for (int i = 0; top_read(set) && i < set->count; i++)
                set_not_varied(s, set->kids[i]->key, set->kids[i]->text, NULL, set->kids[i]->key_line,
                               set->kids[i]->key_col);
            check_runs(s, root);
            read_plots(s, root);
        }
    }
    cs_ytree_free(&tree);
    return s;
}

void cs_sweep_spec_free(cs_sweep_spec *s) {
    if (!s) return;
    for (int i = 0; i < s->var_count; i++) {
        cs_sweep_var *v = &s->vars[i];
        for (int k = 0; k < v->level_count; k++)
            free(v->texts[k]);
        free(v->texts);
        free(v->levels);
        free(v->level_line);
        free(v->level_col);
        free(v->path);
    }
    free(s->vars);
    for (int i = 0; i < s->plot_count; i++)
        free(s->plots[i].y);
    free(s->plots);
    for (int i = 0; i < s->set_count; i++)
        free(s->sets[i]), free(s->set_given[i]);
    free(s->sets);
    free(s->set_given);
    free(s->set_line);
    free(s->set_col);
    for (int i = 0; i < s->error_count; i++)
        free(s->errors[i]);
    free(s->errors);
    free(s->model);
    free(s->file);
    cs_allow_free(&s->allow);
    free(s);
}

void cs_sweep_spec_confine(cs_sweep_spec *s, const char *const *allow, int count) {
    char data[1024], note[PATH_MAX + 64], real[PATH_MAX];
    cs_error err;
    for (int i = 0; i < count; i++)
        if (cs_allow_add(&s->allow, allow[i], &err) != CS_OK)
            cs_sweep_error(s, 0, 0, "--allow-path %s", err.message);
    if (cs_data_dir_find(data, sizeof data, note, sizeof note) == 0)
        cs_allow_add(&s->allow, data, NULL); /* none: the model's load says why */
    cs_allow_add_folder_of(&s->allow, s->file, NULL);
    if (!s->model || !realpath(s->model, real) || cs_allow_has(&s->allow, real)) return;
    char dirs[2048];
    cs_allow_list(&s->allow, dirs, sizeof dirs);
    cs_sweep_error(s, s->model_line, s->model_col,
                   "model: '%s' is outside the folders a study may read (expected a file in %s or below; "
                   "--allow-path DIR allows another folder)",
                   s->model, dirs);
}
