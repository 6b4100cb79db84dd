/* The sweep spec: a YAML file read like the model files. libyaml's events give every node's place
 * (and the keys of `set` and `vary`, which are model paths); libcyaml loads the values through a schema
 * built for this file from those keys; the values are then checked, each error at its line:column. */
#define _POSIX_C_SOURCE 200809L
#include <cyaml/cyaml.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <yaml.h>

#include "grow.h"
#include "loader_int.h"
#include "study/sweep.h"
#include "sweepspec.h"

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

/* ---- the node tree of the file, from libyaml's events ---- */

typedef struct ynode {
    cs_ykind kind;
    int line, col, key_line, key_col;
    char *key;  /* in a mapping: the key it is the value of */
    char *text; /* scalar */
    struct ynode **kids;
    int count, capacity;
} ynode;

static void ynode_free(ynode *n) {
    if (!n) return;
    for (int i = 0; i < n->count; i++)
        ynode_free(n->kids[i]);
    free(n->kids);
    free(n->key);
    free(n->text);
    free(n);
}

static const ynode *yget(const ynode *map, const char *key) {
    if (!map || map->kind != CS_Y_MAP) return NULL;
    for (int i = 0; i < map->count; i++)
        if (strcmp(map->kids[i]->key, key) == 0) return map->kids[i];
    return NULL;
}

enum { MAX_DEPTH = 32 };

/* Read the file into a tree. NULL with an error recorded on a syntax error or an unreadable file. */
static ynode *read_tree(cs_sweep_spec *s, const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        cs_sweep_error(s, 0, 0, "%s: cannot open the file: %s (expected a readable sweep spec)", path,
                       strerror(errno));
        return NULL;
    }
    yaml_parser_t parser;
    yaml_parser_initialize(&parser);
    yaml_parser_set_input_file(&parser, f);
    ynode *stack[MAX_DEPTH], *root = NULL;
    int depth = 0, done = 0, failed = 0, docs = 0;
    char *pending_key = NULL;
    yaml_mark_t key_mark = {0, 0, 0};
    while (!done && !failed) {
        yaml_event_t ev;
        if (!yaml_parser_parse(&parser, &ev)) {
            cs_sweep_error(s, (int)parser.problem_mark.line + 1, (int)parser.problem_mark.column + 1,
                           "YAML syntax: %s%s%s", parser.problem ? parser.problem : "error",
                           parser.context ? " " : "", parser.context ? parser.context : "");
            failed = 1;
            break;
        }
        int line = (int)ev.start_mark.line + 1, col = (int)ev.start_mark.column + 1;
        ynode *parent = depth > 0 ? stack[depth - 1] : NULL;
        cs_ykind kind = CS_Y_SCALAR;
        int is_node = 0;
        switch (ev.type) {
        case YAML_STREAM_END_EVENT:
            done = 1;
            break;
        case YAML_DOCUMENT_START_EVENT:
            if (++docs > 1) {
                cs_sweep_error(s, line, col, "only one YAML document per file");
                failed = 1;
            }
            break;
        case YAML_SCALAR_EVENT:
            is_node = 1;
            break;
        case YAML_ALIAS_EVENT:
            is_node = 1, kind = CS_Y_ALIAS;
            break;
        case YAML_MAPPING_START_EVENT:
            is_node = 1, kind = CS_Y_MAP;
            break;
        case YAML_SEQUENCE_START_EVENT:
            is_node = 1, kind = CS_Y_SEQ;
            break;
        case YAML_MAPPING_END_EVENT:
        case YAML_SEQUENCE_END_EVENT:
            depth--;
            break;
        default:
            break;
        }
        if (is_node && parent && parent->kind == CS_Y_MAP && !pending_key) {
            if (ev.type != YAML_SCALAR_EVENT) {
                cs_sweep_error(s, line, col, "a mapping key must be a plain word");
                failed = 1;
            } else if (!(pending_key = strdup((const char *)ev.data.scalar.value))) {
                failed = 1;
            }
            key_mark = ev.start_mark;
            is_node = 0;
        }
        if (is_node) {
            ynode *n = calloc(1, sizeof *n);
            if (!n || (kind == CS_Y_SCALAR && !(n->text = strdup((const char *)ev.data.scalar.value)))) {
                free(n);
                failed = 1;
            } else {
                n->kind = kind;
                n->line = n->key_line = line;
                n->col = n->key_col = col;
                if (parent && parent->kind == CS_Y_MAP) {
                    n->key = pending_key;
                    pending_key = NULL;
                    n->key_line = (int)key_mark.line + 1;
                    n->key_col = (int)key_mark.column + 1;
                    const ynode *before = yget(parent, n->key);
                    if (before)
                        cs_sweep_error(s, n->key_line, n->key_col, "%s: given twice (first at %d:%d)", n->key,
                                       before->key_line, before->key_col);
                }
                if (!parent) {
                    root = n;
                } else if (cs_grow(&parent->kids, &parent->capacity, parent->count, sizeof *parent->kids) !=
                           0) {
                    ynode_free(n);
                    failed = 1;
                    n = NULL;
                } else {
                    parent->kids[parent->count++] = n;
                }
                if (n && (kind == CS_Y_MAP || kind == CS_Y_SEQ)) {
                    if (depth == MAX_DEPTH) {
                        cs_sweep_error(s, line, col, "nested too deeply");
                        failed = 1;
                    } else {
                        stack[depth++] = n;
                    }
                }
            }
        }
        yaml_event_delete(&ev);
    }
    free(pending_key);
    yaml_parser_delete(&parser);
    fclose(f);
    if (failed) {
        ynode_free(root);
        return NULL;
    }
    return root;
}

int cs_sweep_is_spec(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    yaml_parser_t parser;
    yaml_parser_initialize(&parser);
    yaml_parser_set_input_file(&parser, f);
    int depth = 0, want_key = 0, found = 0, done = 0;
    while (!done && !found) {
        yaml_event_t ev;
        if (!yaml_parser_parse(&parser, &ev)) break;
        switch (ev.type) {
        case YAML_STREAM_END_EVENT:
            done = 1;
            break;
        case YAML_MAPPING_START_EVENT:
        case YAML_SEQUENCE_START_EVENT:
            if (depth == 0) want_key = 1; /* the top mapping: its first node is a key */
            done = depth == 0 && ev.type == YAML_SEQUENCE_START_EVENT;
            depth++;
            break;
        case YAML_MAPPING_END_EVENT:
        case YAML_SEQUENCE_END_EVENT:
            depth--;
            if (depth == 1) want_key = 1;
            break;
        case YAML_SCALAR_EVENT:
        case YAML_ALIAS_EVENT:
            if (depth == 1 && want_key)
                found =
                    ev.type == YAML_SCALAR_EVENT && strcmp((const char *)ev.data.scalar.value, "vary") == 0;
            if (depth == 1) want_key = !want_key;
            break;
        default:
            break;
        }
        yaml_event_delete(&ev);
    }
    yaml_parser_delete(&parser);
    fclose(f);
    return found;
}

/* ---- the libcyaml schema of this file ---- */

static const char *const top_keys[] = {"model",         "method", "runs", "seed",
                                       "vehicle_class", "netcdf", "set",  "vary"};
enum { TOP_MODEL, TOP_METHOD, TOP_RUNS, TOP_SEED, TOP_CLASS, TOP_NETCDF, TOP_SET, TOP_VARY, TOP_COUNT };
static const char *const param_keys[] = {"dist", "mean", "sd", "min", "max", "from", "to", "step", "count"};
enum { P_DIST, P_MEAN, P_SD, P_MIN, P_MAX, P_FROM, P_TO, P_STEP, P_COUNT, P_N };

/* libcyaml's data: the top mapping, each vary entry, each entry's parameters. */
typedef struct yentry {
    char **params; /* [P_N] strings (a mapping entry) */
    char **list;   /* a list entry */
    uint64_t list_count;
} yentry;

typedef struct ytop {
    char *scalar[TOP_SET];
    char **set;   /* one string per key of `set` */
    yentry *vary; /* one per key of `vary` */
} ytop;

static const cyaml_schema_value_t string_value = {.type = CYAML_STRING,
                                                  .flags = CYAML_FLAG_POINTER,
                                                  .data_size = sizeof(char),
                                                  .string = {0, CYAML_UNLIMITED}};

static int scalar_map(const ynode *n) {
    if (!n || n->kind != CS_Y_MAP) return 0;
    for (int i = 0; i < n->count; i++)
        if (n->kids[i]->kind != CS_Y_SCALAR) return 0;
    return 1;
}

static int scalar_seq(const ynode *n) {
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

/* Schema memory: every allocation kept in one list, freed together. */
typedef struct smem {
    void **blocks;
    int count, capacity;
} smem;

static void *salloc(smem *m, size_t size) {
    if (cs_grow(&m->blocks, &m->capacity, m->count, sizeof *m->blocks) != 0) return NULL;
    void *p = calloc(1, size ? size : 1);
    if (p) m->blocks[m->count++] = p;
    return p;
}

static cyaml_schema_field_t ignore_field(const char *key) {
    return (cyaml_schema_field_t){.key = key, .value = {.type = CYAML_IGNORE, .flags = CYAML_FLAG_OPTIONAL}};
}

static cyaml_schema_field_t string_field(const char *key, size_t offset) {
    cyaml_schema_field_t f = {.key = key, .data_offset = (uint32_t)offset, .value = string_value};
    f.value.flags = CYAML_FLAG_POINTER | CYAML_FLAG_OPTIONAL;
    return f;
}

/* The schema of the top mapping; tree shapes that do not fit are ignored (reported by check_shapes). */
static int build_schema(smem *m, const ynode *root, cyaml_schema_value_t *top) {
    cyaml_schema_field_t *fields = salloc(m, (TOP_COUNT + 1) * sizeof *fields);
    if (!fields) return -1;
    for (int k = 0; k < TOP_SET; k++) {
        const ynode *n = yget(root, top_keys[k]);
        fields[k] = n && n->kind == CS_Y_SCALAR
                        ? string_field(top_keys[k], offsetof(ytop, scalar) + k * sizeof(char *))
                        : ignore_field(top_keys[k]);
    }
    const ynode *set = yget(root, "set");
    if (scalar_map(set) && set->count > 0) {
        cyaml_schema_field_t *sf = salloc(m, (size_t)(set->count + 1) * sizeof *sf);
        if (!sf) return -1;
        for (int i = 0; i < set->count; i++)
            sf[i] = string_field(set->kids[i]->key, (size_t)i * sizeof(char *));
        fields[TOP_SET] =
            (cyaml_schema_field_t){.key = "set",
                                   .data_offset = offsetof(ytop, set),
                                   .value = {.type = CYAML_MAPPING,
                                             .flags = CYAML_FLAG_POINTER | CYAML_FLAG_OPTIONAL,
                                             .data_size = (uint32_t)((size_t)set->count * sizeof(char *)),
                                             .mapping = {sf}}};
    } else {
        fields[TOP_SET] = ignore_field("set");
    }
    const ynode *vary = yget(root, "vary");
    if (vary && vary->kind == CS_Y_MAP && vary->count > 0) {
        cyaml_schema_field_t *vf = salloc(m, (size_t)(vary->count + 1) * sizeof *vf);
        if (!vf) return -1;
        for (int i = 0; i < vary->count; i++) {
            const ynode *e = vary->kids[i];
            size_t base = (size_t)i * sizeof(yentry);
            if (scalar_seq(e)) {
                cyaml_schema_value_t *item = salloc(m, sizeof *item);
                if (!item) return -1;
                *item = string_value;
                vf[i] =
                    (cyaml_schema_field_t){.key = e->key,
                                           .data_offset = (uint32_t)(base + offsetof(yentry, list)),
                                           .count_offset = (uint32_t)(base + offsetof(yentry, list_count)),
                                           .count_size = sizeof(uint64_t),
                                           .value = {.type = CYAML_SEQUENCE,
                                                     .flags = CYAML_FLAG_POINTER | CYAML_FLAG_OPTIONAL,
                                                     .data_size = sizeof(char *),
                                                     .sequence = {item, 0, CYAML_UNLIMITED}}};
            } else if (e->kind == CS_Y_MAP) {
                cyaml_schema_field_t *pf = salloc(m, (P_N + 1) * sizeof *pf);
                if (!pf) return -1;
                for (int p = 0; p < P_N; p++) {
                    const ynode *pv = yget(e, param_keys[p]);
                    pf[p] = pv && pv->kind == CS_Y_SCALAR
                                ? string_field(param_keys[p], (size_t)p * sizeof(char *))
                                : ignore_field(param_keys[p]);
                }
                vf[i] = (cyaml_schema_field_t){.key = e->key,
                                               .data_offset = (uint32_t)(base + offsetof(yentry, params)),
                                               .value = {.type = CYAML_MAPPING,
                                                         .flags = CYAML_FLAG_POINTER | CYAML_FLAG_OPTIONAL,
                                                         .data_size = P_N * sizeof(char *),
                                                         .mapping = {pf}}};
            } else {
                vf[i] = ignore_field(e->key);
            }
        }
        fields[TOP_VARY] =
            (cyaml_schema_field_t){.key = "vary",
                                   .data_offset = offsetof(ytop, vary),
                                   .value = {.type = CYAML_MAPPING,
                                             .flags = CYAML_FLAG_POINTER | CYAML_FLAG_OPTIONAL,
                                             .data_size = (uint32_t)((size_t)vary->count * sizeof(yentry)),
                                             .mapping = {vf}}};
    } else {
        fields[TOP_VARY] = ignore_field("vary");
    }
    *top = (cyaml_schema_value_t){
        .type = CYAML_MAPPING, .flags = CYAML_FLAG_POINTER, .data_size = sizeof(ytop), .mapping = {fields}};
    return 0;
}

/* ---- shapes ---- */

static const char *shape_name(cs_ykind k) {
    return k == CS_Y_SCALAR ? "a single value"
           : k == CS_Y_MAP  ? "a mapping"
           : k == CS_Y_SEQ  ? "a list"
                            : "an alias";
}

static void check_shapes(cs_sweep_spec *s, const ynode *root) {
    for (int i = 0; i < root->count; i++) {
        const ynode *n = root->kids[i];
        int k = 0;
        while (k < TOP_COUNT && strcmp(n->key, top_keys[k]) != 0)
            k++;
        if (k == TOP_COUNT) {
            cs_sweep_error(s, n->key_line, n->key_col,
                           "unknown key '%s' (expected one of: model, method, runs, seed, vehicle_class, "
                           "netcdf, set, vary)",
                           n->key);
        } else if (k < TOP_SET && n->kind != CS_Y_SCALAR) {
            cs_sweep_error(s, n->line, n->col, "%s is %s (expected a single value)", n->key,
                           shape_name(n->kind));
        } else if (k >= TOP_SET && n->kind != CS_Y_MAP) {
            cs_sweep_error(s, n->line, n->col, "%s is %s (expected a mapping of model paths, e.g. %s)",
                           n->key, shape_name(n->kind),
                           k == TOP_SET ? "scenario.t_end: 0.5 s" : "scenario.speed: [35 mph, 40 mph]");
        } else if (k == TOP_SET) {
            for (int j = 0; j < n->count; j++)
                if (n->kids[j]->kind != CS_Y_SCALAR)
                    cs_sweep_error(s, n->kids[j]->line, n->kids[j]->col,
                                   "set: %s is %s (expected a single value, as --set)", n->kids[j]->key,
                                   shape_name(n->kids[j]->kind));
        } else if (k == TOP_VARY) {
            for (int j = 0; j < n->count; j++) {
                const ynode *e = n->kids[j];
                if (e->kind == CS_Y_SEQ) {
                    for (int q = 0; q < e->count; q++)
                        if (e->kids[q]->kind != CS_Y_SCALAR)
                            cs_sweep_error(s, e->kids[q]->line, e->kids[q]->col,
                                           "vary: %s: a level is %s (expected a single value)", e->key,
                                           shape_name(e->kids[q]->kind));
                } else if (e->kind == CS_Y_MAP) {
                    for (int q = 0; q < e->count; q++) {
                        const ynode *p = e->kids[q];
                        if (known_param(p->key) < 0)
                            cs_sweep_error(
                                s, p->key_line, p->key_col,
                                "vary: %s: unknown key '%s' (expected one of: dist, mean, sd, min, "
                                "max; or from, to, step, count)",
                                e->key, p->key);
                        else if (p->kind != CS_Y_SCALAR)
                            cs_sweep_error(s, p->line, p->col, "vary: %s: %s is %s (expected a single value)",
                                           e->key, p->key, shape_name(p->kind));
                    }
                } else {
                    cs_sweep_error(
                        s, e->line, e->col,
                        "vary: %s is %s (expected a list of values, {from, to, step} or {dist: ...})", e->key,
                        shape_name(e->kind));
                }
            }
        }
    }
}

/* ---- model paths ---- */

/* Walk the schema along a --set path to one value. 0 with v's kind filled, or -1 with why filled. */
static int path_field(const char *path, cs_sweep_var *v, char *why, size_t why_size) {
    const cs_table *t = &cs_table_model;
    const cs_field *f = NULL;
    int item = 0, rc;
    char key[64];
    long index;
    const char *p = path;
    while ((rc = cs_path_next(&p, key, sizeof key, &index)) > 0) {
        if (rc == 1) {
            int i = t && (!f || item || f->kind != CS_F_SEQ) ? cs_table_find(t, key) : -1;
            if (i < 0) {
                if (t && f && f->kind == CS_F_SEQ && !item)
                    snprintf(why, why_size, "'%s' needs an index before '%s' (e.g. %s[0].%s)", f->key, key,
                             f->key, key);
                else
                    snprintf(why, why_size, "unknown key '%s'%s%s (expected a model path, as --set)", key,
                             t ? " in " : "", t ? t->name : "");
                return -1;
            }
            f = &t->fields[i];
            t = f->sub;
            item = 0;
        } else {
            if (!f || item || (f->kind != CS_F_SEQ && f->kind != CS_F_LIST)) {
                snprintf(why, why_size, "no list before [%ld] (expected a model path, as --set)", index);
                return -1;
            }
            item = 1;
        }
    }
    if (rc < 0 || !f) {
        snprintf(why, why_size, "malformed path (expected keys and [index], e.g. barrier.cables[0].height)");
        return -1;
    }
    int one = f->kind == CS_F_QTY || f->kind == CS_F_INT || f->kind == CS_F_TEXT || f->kind == CS_F_ENUM ||
              f->kind == CS_F_PART || (f->kind == CS_F_LIST && item);
    if (!one) {
        snprintf(why, why_size, "'%s' is not a single value (expected a path to one value, as --set)",
                 f->key);
        return -1;
    }
    v->numeric = f->kind == CS_F_QTY || f->kind == CS_F_INT || f->kind == CS_F_LIST;
    v->integer = f->kind == CS_F_INT;
    v->q = f->kind == CS_F_INT ? CS_Q_NUMBER : f->q;
    v->unit = v->numeric ? cs_quantity_get(v->q)->label : "";
    return 0;
}

/* ---- values ---- */

static int read_value(cs_sweep_spec *s, cs_units *u, const cs_sweep_var *v, const char *text, int line,
                      int col, const char *what, double *out) {
    char why[256];
    if (v->integer) {
        char *end;
        errno = 0;
        long n = strtol(text, &end, 10);
        while (*end == ' ')
            end++;
        if (end == text || *end || errno) {
            cs_sweep_error(s, line, col, "vary: %s: %s '%s' is not a whole number", v->path, what, text);
            return -1;
        }
        *out = (double)n;
        return 0;
    }
    if (cs_units_read(u, text, v->q, out, why, sizeof why) != 0) {
        cs_sweep_error(s, line, col, "vary: %s: %s: %s (expected a %s, e.g. \"%s\")", v->path, what, why,
                       cs_quantity_get(v->q)->name, cs_quantity_get(v->q)->example);
        return -1;
    }
    return 0;
}

static int add_level(cs_sweep_var *v, double x, const char *text, int line, int col) {
    int n = v->level_count;
    double *lv = realloc(v->levels, (size_t)(n + 1) * sizeof *lv);
    if (lv) v->levels = lv;
    char **tx = realloc(v->texts, (size_t)(n + 1) * sizeof *tx);
    if (tx) v->texts = tx;
    int *ll = realloc(v->level_line, (size_t)(n + 1) * sizeof *ll);
    if (ll) v->level_line = ll;
    int *lc = realloc(v->level_col, (size_t)(n + 1) * sizeof *lc);
    if (lc) v->level_col = lc;
    if (!lv || !tx || !ll || !lc || !(tx[n] = strdup(text))) return -1;
    lv[n] = x, ll[n] = line, lc[n] = col;
    v->level_count++;
    return 0;
}

enum { MAX_LEVELS = 100000 };

/* A grid entry: a list of values, or {from, to, step | count}. */
static void read_grid(cs_sweep_spec *s, cs_units *u, cs_sweep_var *v, const ynode *e, const yentry *d) {
    if (e->kind == CS_Y_SEQ) {
        size_t used = (size_t)snprintf(v->desc, sizeof v->desc, "levels:");
        for (uint64_t k = 0; k < d->list_count && used < sizeof v->desc; k++)
            used +=
                (size_t)snprintf(v->desc + used, sizeof v->desc - used, "%s %s", k ? "," : "", d->list[k]);
        if (d->list_count == 0)
            cs_sweep_error(s, e->line, e->col, "vary: %s: no values (expected a list of values)", v->path);
        for (uint64_t k = 0; k < d->list_count && (int)k < e->count; k++) {
            const ynode *it = e->kids[k];
            double x = 0;
            if (v->numeric && read_value(s, u, v, d->list[k], it->line, it->col, "value", &x) != 0) continue;
            if (add_level(v, x, d->list[k], it->line, it->col) != 0) return;
        }
        return;
    }
    const ynode *from = yget(e, "from"), *to = yget(e, "to"), *step = yget(e, "step"),
                *count = yget(e, "count");
    for (int p = P_DIST; p <= P_MAX; p++) {
        const ynode *bad = yget(e, param_keys[p]);
        if (bad)
            cs_sweep_error(s, bad->key_line, bad->key_col, "vary: %s: '%s' does not go with from/to", v->path,
                           bad->key);
    }
    if (!v->numeric) {
        cs_sweep_error(s, e->line, e->col, "vary: %s is text (expected a list of its values)", v->path);
        return;
    }
    if (!from || !to || (!step) == (!count)) {
        cs_sweep_error(s, e->line, e->col, "vary: %s: a range needs from, to and one of step or count",
                       v->path);
        return;
    }
    double a, b, h = 0;
    long n = 0;
    int ok = read_value(s, u, v, d->params[P_FROM], from->line, from->col, "from", &a) == 0;
    ok &= read_value(s, u, v, d->params[P_TO], to->line, to->col, "to", &b) == 0;
    if (step) {
        ok &= read_value(s, u, v, d->params[P_STEP], step->line, step->col, "step", &h) == 0;
        if (ok && !(h > 0)) {
            cs_sweep_error(s, step->line, step->col, "vary: %s: step must be above zero", v->path);
            ok = 0;
        }
        if (ok && b < a) {
            cs_sweep_error(s, to->line, to->col, "vary: %s: to is below from (expected from <= to)", v->path);
            ok = 0;
        }
        if (ok) {
            double span = (b - a) / h;
            if (span > MAX_LEVELS) {
                cs_sweep_error(s, step->line, step->col, "vary: %s: more than %d levels", v->path,
                               MAX_LEVELS);
                ok = 0;
            }
            n = ok ? (long)floor(span * (1 + 1e-12) + 1e-9) + 1 : 0;
        }
    } else {
        char *end;
        n = strtol(d->params[P_COUNT], &end, 10);
        if (*end || n < 1 || n > MAX_LEVELS) {
            cs_sweep_error(s, count->line, count->col, "vary: %s: count must be a whole number from 1 to %d",
                           v->path, MAX_LEVELS);
            ok = 0;
        }
    }
    snprintf(v->desc, sizeof v->desc, "from %s to %s, %s %s", d->params[P_FROM], d->params[P_TO],
             step ? "step" : "count", d->params[step ? P_STEP : P_COUNT]);
    for (long k = 0; ok && k < n; k++) {
        double x = step ? a + (double)k * h : n == 1 ? a : a + (b - a) * (double)k / (double)(n - 1);
        if (v->integer) x = round(x);
        char text[64];
        snprintf(text, sizeof text, "%.12g", x);
        if (add_level(v, x, text, from->line, from->col) != 0) return;
    }
}

/* A distribution entry {dist, mean, sd, min, max}. */
static void read_dist(cs_sweep_spec *s, cs_units *u, cs_sweep_var *v, const ynode *e, const yentry *d) {
    const ynode *dn = yget(e, "dist");
    for (int p = P_FROM; p < P_N; p++) {
        const ynode *bad = yget(e, param_keys[p]);
        if (bad)
            cs_sweep_error(s, bad->key_line, bad->key_col, "vary: %s: '%s' does not go with dist", v->path,
                           bad->key);
    }
    if (!v->numeric || v->integer) {
        cs_sweep_error(s, dn->line, dn->col, "vary: %s is %s (a distribution needs a quantity)", v->path,
                       v->integer ? "a whole number" : "text");
        return;
    }
    const char *name = d->params[P_DIST];
    int truncated = strcmp(name, "truncated_normal") == 0;
    cs_dist *t = &v->dist;
    if (strcmp(name, "uniform") == 0)
        t->kind = CS_DIST_UNIFORM;
    else if (strcmp(name, "normal") == 0 || truncated)
        t->kind = CS_DIST_NORMAL;
    else if (strcmp(name, "lognormal") == 0)
        t->kind = CS_DIST_LOGNORMAL;
    else {
        cs_sweep_error(
            s, dn->line, dn->col,
            "vary: %s: unknown dist '%s' (expected uniform, normal, lognormal or truncated_normal)", v->path,
            name);
        return;
    }
    double val[P_N];
    int given[P_N] = {0}, ok = 1;
    size_t used = (size_t)snprintf(v->desc, sizeof v->desc, "%s", name);
    for (int p = P_MEAN; p <= P_MAX; p++) {
        const ynode *pn = yget(e, param_keys[p]);
        if (!pn) continue;
        if (used < sizeof v->desc)
            used += (size_t)snprintf(v->desc + used, sizeof v->desc - used, "%s %s %s",
                                     used > strlen(name) ? "," : ":", param_keys[p], d->params[p]);
        given[p] = 1;
        if (read_value(s, u, v, d->params[p], pn->line, pn->col, param_keys[p], &val[p]) != 0) ok = 0;
    }
    static const char *const needs[] = {"min and max", "mean and sd", "mean and sd"};
    int need_ab = t->kind == CS_DIST_UNIFORM ? given[P_MIN] && given[P_MAX] : given[P_MEAN] && given[P_SD];
    if (!need_ab) {
        cs_sweep_error(s, dn->line, dn->col, "vary: %s: dist %s needs %s", v->path, name, needs[t->kind]);
        return;
    }
    if (t->kind == CS_DIST_UNIFORM && (given[P_MEAN] || given[P_SD])) {
        const ynode *bad = yget(e, given[P_MEAN] ? "mean" : "sd");
        cs_sweep_error(s, bad->key_line, bad->key_col, "vary: %s: dist uniform takes min and max only",
                       v->path);
        return;
    }
    if (truncated && !given[P_MIN] && !given[P_MAX]) {
        cs_sweep_error(s, dn->line, dn->col, "vary: %s: dist truncated_normal needs min, max or both",
                       v->path);
        return;
    }
    if (!ok) return;
    t->lo = given[P_MIN] ? val[P_MIN] : -HUGE_VAL;
    t->hi = given[P_MAX] ? val[P_MAX] : HUGE_VAL;
    const ynode *at = yget(e, given[P_MAX] ? "max" : "dist");
    if (t->kind == CS_DIST_UNIFORM) {
        t->a = val[P_MIN], t->b = val[P_MAX];
    } else if (!(val[P_SD] > 0)) {
        at = yget(e, "sd");
        cs_sweep_error(s, at->line, at->col, "vary: %s: sd must be above zero", v->path);
        return;
    } else if (t->kind == CS_DIST_NORMAL) {
        t->a = val[P_MEAN], t->b = val[P_SD];
    } else {
        if (!(val[P_MEAN] > 0)) {
            at = yget(e, "mean");
            cs_sweep_error(s, at->line, at->col, "vary: %s: a lognormal mean must be above zero", v->path);
            return;
        }
        double cv = val[P_SD] / val[P_MEAN], s2 = log1p(cv * cv);
        t->b = sqrt(s2);
        t->a = log(val[P_MEAN]) - 0.5 * s2;
    }
    if (!(t->lo < t->hi)) {
        cs_sweep_error(s, at->line, at->col, "vary: %s: max must be above min", v->path);
        return;
    }
    if (cs_dist_prepare(t) != 0)
        cs_sweep_error(s, at->line, at->col, "vary: %s: min and max leave no probability of the distribution",
                       v->path);
}

/* ---- the spec ---- */

static const char *const class_names[] = {"C", "PU", "M", "H"};

static void read_scalars(cs_sweep_spec *s, const ynode *root, const ytop *d) {
    const ynode *n;
    if (!(n = yget(root, "model")))
        cs_sweep_error(s, root->line, root->col, "no model (expected model: FILE, the base model file)");
    else if (d->scalar[TOP_MODEL]) {
        const char *m = d->scalar[TOP_MODEL];
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
    if (!(n = yget(root, "method"))) {
        cs_sweep_error(s, root->line, root->col,
                       "no method (expected method: grid, monte_carlo or latin_hypercube)");
    } else if (d->scalar[TOP_METHOD]) {
        int k = 0;
        while (k < 3 && strcmp(d->scalar[TOP_METHOD], methods[k]) != 0)
            k++;
        if (k == 3)
            cs_sweep_error(s, n->line, n->col,
                           "method: unknown '%s' (expected grid, monte_carlo or latin_hypercube)",
                           d->scalar[TOP_METHOD]);
        s->method = k == 3 ? CS_SWEEP_GRID : (cs_sweep_method)k;
    }
    n = yget(root, "runs");
    if (n && d->scalar[TOP_RUNS]) {
        char *end;
        errno = 0;
        long r = strtol(d->scalar[TOP_RUNS], &end, 10);
        if (*end || errno || r < 1 || r > CS_SWEEP_MAX_RUNS)
            cs_sweep_error(s, n->line, n->col, "runs: '%s' (expected a whole number from 1 to %d)",
                           d->scalar[TOP_RUNS], CS_SWEEP_MAX_RUNS);
        s->runs = r;
    }
    n = yget(root, "seed");
    s->seed = 1;
    if (n && d->scalar[TOP_SEED]) {
        char *end;
        errno = 0;
        const char *t = d->scalar[TOP_SEED];
        unsigned long long v = strtoull(t, &end, 10);
        if (*end || errno || end == t || t[0] == '-')
            cs_sweep_error(s, n->line, n->col, "seed: '%s' (expected a whole number from 0 to 2^64 - 1)", t);
        s->seed = (uint64_t)v;
    }
    n = yget(root, "vehicle_class");
    if (n && d->scalar[TOP_CLASS]) {
        int k = 0;
        while (k < 4 && strcmp(d->scalar[TOP_CLASS], class_names[k]) != 0)
            k++;
        if (k == 4)
            cs_sweep_error(s, n->line, n->col,
                           "vehicle_class: unknown '%s' (expected an ASTM F2656 class: C, PU, M or H)",
                           d->scalar[TOP_CLASS]);
        else
            snprintf(s->vehicle_class, sizeof s->vehicle_class, "%s", class_names[k]);
    }
    n = yget(root, "netcdf");
    if (n && d->scalar[TOP_NETCDF]) {
        const char *t = d->scalar[TOP_NETCDF];
        s->netcdf = strcmp(t, "true") == 0;
        if (!s->netcdf && strcmp(t, "false") != 0)
            cs_sweep_error(s, n->line, n->col, "netcdf: '%s' (expected true or false)", t);
    }
}

static int push_set(cs_sweep_spec *s, const char *path, const char *value, int line, int col) {
    int n = s->set_count;
    char **sets = realloc(s->sets, (size_t)(n + 1) * sizeof *sets);
    if (sets) s->sets = sets;
    int *sl = realloc(s->set_line, (size_t)(n + 1) * sizeof *sl);
    if (sl) s->set_line = sl;
    int *sc = realloc(s->set_col, (size_t)(n + 1) * sizeof *sc);
    if (sc) s->set_col = sc;
    size_t len = strlen(path) + strlen(value) + 2;
    if (!sets || !sl || !sc || !(sets[n] = malloc(len))) return -1;
    snprintf(sets[n], len, "%s=%s", path, value);
    sl[n] = line, sc[n] = col;
    s->set_count++;
    return 0;
}

int cs_sweep_spec_add_set(cs_sweep_spec *s, const char *assignment) {
    const char *eq = strchr(assignment, '=');
    if (!eq || eq == assignment) {
        cs_sweep_error(s, 0, 0, "--set %s: expected PATH=VALUE, e.g. scenario.speed=\"35 mph\"", assignment);
        return -1;
    }
    char path[512];
    snprintf(path, sizeof path, "%.*s", (int)(eq - assignment), assignment);
    return push_set(s, path, eq + 1, 0, 0);
}

static void read_vary(cs_sweep_spec *s, cs_units *u, const ynode *root, const ytop *d) {
    const ynode *vary = yget(root, "vary");
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
        const ynode *e = vary->kids[i];
        const yentry *de = d->vary ? &d->vary[i] : NULL;
        cs_sweep_var *v = &s->vars[s->var_count++];
        v->line = e->key_line, v->col = e->key_col;
        if (!(v->path = strdup(e->key))) return;
        char why[300];
        if (path_field(v->path, v, why, sizeof why) != 0) {
            cs_sweep_error(s, e->key_line, e->key_col, "vary: %s: %s", v->path, why);
            continue;
        }
        if (!de || (!de->list && !de->params) || (e->kind == CS_Y_MAP && !scalar_map(e))) continue;
        const ynode *dn = yget(e, "dist");
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
            read_dist(s, u, v, e, de);
        } else {
            read_grid(s, u, v, e, de);
        }
    }
}

static void check_runs(cs_sweep_spec *s, const ynode *root) {
    const ynode *runs = yget(root, "runs");
    if (s->method == CS_SWEEP_GRID) {
        if (runs)
            cs_sweep_error(s, runs->key_line, runs->key_col,
                           "runs: not used by a grid (its runs are every combination of the levels)");
        double n = 1;
        for (int i = 0; i < s->var_count; i++)
            n *= s->vars[i].level_count > 0 ? s->vars[i].level_count : 1;
        if (n > CS_SWEEP_MAX_RUNS) {
            const ynode *vary = yget(root, "vary");
            cs_sweep_error(s, vary->line, vary->col, "vary: the grid has %.0f runs (expected at most %d)", n,
                           CS_SWEEP_MAX_RUNS);
        }
        s->runs = (long)fmin(n, CS_SWEEP_MAX_RUNS);
    } else if (!runs) {
        cs_sweep_error(s, root->line, root->col, "no runs (expected runs: N for method %s)",
                       s->method == CS_SWEEP_MONTE_CARLO ? "monte_carlo" : "latin_hypercube");
    }
}

static void cyaml_log_capture(cyaml_log_t level, void *ctx, const char *fmt, va_list args) {
    char *buf = ctx;
    size_t n = strlen(buf);
    if (level >= CYAML_LOG_ERROR && n < 255) vsnprintf(buf + n, 256 - n, fmt, args);
}

cs_sweep_spec *cs_sweep_spec_read(const char *path, cs_units *units) {
    cs_sweep_spec *s = calloc(1, sizeof *s);
    if (!s || !(s->file = strdup(path))) {
        free(s);
        return NULL;
    }
    s->seed = 1;
    ynode *root = read_tree(s, path);
    if (!root) {
        if (s->error_count == 0)
            cs_sweep_error(s, 1, 1, "the file is empty (expected a mapping: model, method, vary...)");
        return s;
    }
    if (root->kind != CS_Y_MAP) {
        cs_sweep_error(s, root->line, root->col,
                       "the document is %s (expected a mapping: model, method, vary...)",
                       shape_name(root->kind));
        ynode_free(root);
        return s;
    }
    check_shapes(s, root);
    smem mem = {0};
    cyaml_schema_value_t top;
    ytop *data = NULL;
    char log[256] = "";
    cyaml_config_t config = {.log_fn = cyaml_log_capture,
                             .log_ctx = log,
                             .mem_fn = cyaml_mem,
                             .log_level = CYAML_LOG_ERROR,
                             .flags = CYAML_CFG_IGNORE_UNKNOWN_KEYS};
    if (build_schema(&mem, root, &top) != 0) {
        cs_sweep_error(s, 0, 0, "%s: out of memory", path);
    } else {
        cyaml_err_t rc = cyaml_load_file(path, &config, &top, (cyaml_data_t **)&data, NULL);
        if (rc != CYAML_OK && s->error_count > 0) { /* the shapes already reported say why */
            data = NULL;
        } else if (rc != CYAML_OK) {
            log[strcspn(log, "\n")] = '\0';
            cs_sweep_error(s, 1, 1, "cannot load the file: %s (%s)", cyaml_strerror(rc), log);
            data = NULL;
        }
    }
    if (data) {
        read_scalars(s, root, data);
        const ynode *set = yget(root, "set");
        for (int i = 0; data->set && i < set->count; i++)
            if (data->set[i] && push_set(s, set->kids[i]->key, data->set[i], set->kids[i]->key_line,
                                         set->kids[i]->key_col) != 0)
                break;
        read_vary(s, units, root, data);
        check_runs(s, root);
        cyaml_free(&config, &top, data, 0);
    }
    for (int i = 0; i < mem.count; i++)
        free(mem.blocks[i]);
    free(mem.blocks);
    ynode_free(root);
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
    for (int i = 0; i < s->set_count; i++)
        free(s->sets[i]);
    free(s->sets);
    free(s->set_line);
    free(s->set_col);
    for (int i = 0; i < s->error_count; i++)
        free(s->errors[i]);
    free(s->errors);
    free(s->model);
    free(s->file);
    free(s);
}
