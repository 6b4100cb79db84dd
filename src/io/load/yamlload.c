/* One file into a node tree: libyaml events give the places, the schema tables check the shape, and
 * libcyaml loads the values through a schema built from the same tables for this file. */
#define _XOPEN_SOURCE 700
#include <cyaml/cyaml.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "loader_int.h"

/* libcyaml stores each mapping as slots: [2i] the value (string, mapping or array), [2i+1] the
 * sequence count, or the name when a part field is given as a name. */
typedef union slot {
    void *p;
    char *s;
    uint64_t n;
} slot;

int cs_path_next(const char **p, char *key, size_t key_size, long *index) {
    const char *s = *p;
    if (*s == '\0') return 0;
    if (*s == '[') {
        char *end;
        long i = strtol(s + 1, &end, 10);
        if (end == s + 1 || *end != ']' || i < 0) return -1;
        *index = i;
        *p = end + 1;
        if (**p == '.') ++*p;
        return 2;
    }
    size_t n = strcspn(s, ".[");
    if (n == 0 || n >= key_size) return -1;
    memcpy(key, s, n);
    key[n] = '\0';
    *p = s + n + (s[n] == '.');
    return 1;
}

static int scalar_kind(cs_fkind k) {
    return k == CS_F_QTY || k == CS_F_INT || k == CS_F_TEXT || k == CS_F_ENUM;
}

/* The schema path ("barrier.cables.height") of a document path; NULL table/field if unknown. */
typedef struct shape {
    const cs_field *field; /* the field the node is the value of (NULL: root) */
    int item;              /* the node is an entry of the field's list */
    int known;             /* the path walks the schema */
    char skey[256];        /* schema path */
    char bad_key[64];      /* the last component is an unknown key */
} shape;

static void walk(const char *path, shape *out) {
    memset(out, 0, sizeof *out);
    const cs_table *t = &cs_table_model;
    char key[64];
    long index;
    int rc;
    out->known = 1;
    while ((rc = cs_path_next(&path, key, sizeof key, &index)) > 0) {
        if (rc == 1) {
            int i = t ? cs_table_find(t, key) : -1;
            if (out->item == 0 && out->field && out->field->kind == CS_F_SEQ)
                i = -1, t = NULL; /* under a bad list */
            if (i < 0) {
                out->known = 0;
                if (*path == '\0' && t) snprintf(out->bad_key, sizeof out->bad_key, "%s", key);
                return;
            }
            out->field = &t->fields[i];
            out->item = 0;
            t = out->field->sub;
            size_t n = strlen(out->skey);
            snprintf(out->skey + n, sizeof out->skey - n, "%s%s", n ? "." : "", key);
        } else {
            if (!out->field || out->item || (out->field->kind != CS_F_SEQ && out->field->kind != CS_F_LIST)) {
                out->known = 0;
                return;
            }
            out->item = 1;
        }
    }
    if (rc < 0) out->known = 0;
}

static const char *kind_name(cs_ykind k) {
    return k == CS_Y_SCALAR ? "a single value"
           : k == CS_Y_MAP  ? "a mapping"
           : k == CS_Y_SEQ  ? "a list"
                            : "an alias";
}

/* Does a node of kind k fit where s says? */
static int fits(const shape *s, cs_ykind k) {
    if (k == CS_Y_ALIAS) return 1;
    if (!s->field) return k == CS_Y_MAP;
    cs_fkind f = s->field->kind;
    if (s->item) return f == CS_F_SEQ ? k == CS_Y_MAP : k == CS_Y_SCALAR;
    if (scalar_kind(f)) return k == CS_Y_SCALAR;
    if (f == CS_F_LIST || f == CS_F_SEQ) return k == CS_Y_SEQ;
    if (f == CS_F_PART) return k == CS_Y_SCALAR || k == CS_Y_MAP;
    return k == CS_Y_MAP;
}

static void expected_shape(const shape *s, char *buf, size_t size) {
    if (!s->field)
        snprintf(buf, size, "a mapping of name, parts, barrier, vehicle, scenario");
    else if (s->item && s->field->kind == CS_F_SEQ)
        snprintf(buf, size, "a mapping: one %s", s->field->sub->name);
    else if (s->field->kind == CS_F_MAP)
        snprintf(buf, size, "a mapping: the %s", s->field->sub->name);
    else if (s->field->kind == CS_F_SEQ)
        snprintf(buf, size, "a list of %s mappings", s->field->sub->name);
    else if (s->field->kind == CS_F_PART)
        snprintf(buf, size, "a part name or a %s mapping", s->field->sub->name);
    else
        cs_field_hint(s->field, buf, size);
}

/* Schema paths libcyaml must skip in this file (their shape is wrong, already reported). */
typedef struct skips {
    char (*path)[256];
    int count;
} skips;

static int skipped(const skips *sk, const char *skey) {
    for (int i = 0; i < sk->count; i++)
        if (strcmp(sk->path[i], skey) == 0) return 1;
    return 0;
}

static void table_keys(const cs_table *t, char *buf, size_t size) {
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < t->count && n < size; i++)
        n += (size_t)snprintf(buf + n, size - n, "%s%s", i ? ", " : "", t->fields[i].key);
}

/* Check every node's key and shape; report each problem at its place. */
static void check_shape(cs_loader *l, int file, skips *sk) {
    cs_yposmap *map = &l->files[file].map;
    for (int i = 0; i < map->count; i++) {
        cs_ypos *e = &map->items[i];
        int before = l->error_count;
        shape s;
        walk(e->path, &s);
        char want[200];
        if (e->odd_key) { /* its path would not name it: "speed.x" reads as speed, then x */
            cs_err_at(l, file, e->key_line, e->key_col,
                      "%s: a key must be a plain word (expected 1 to 63 characters, no '.', '[' or ']')",
                      e->path);
        } else if (s.bad_key[0]) {
            const char *dot = strrchr(e->path, '.');
            size_t plen = dot ? (size_t)(dot - e->path) : 0;
            shape parent;
            char ppath[256];
            snprintf(ppath, sizeof ppath, "%.*s", (int)plen, e->path);
            walk(ppath, &parent);
            const cs_table *t = parent.field ? parent.field->sub : &cs_table_model;
            table_keys(t, want, sizeof want);
            cs_err_at(l, file, e->key_line, e->key_col, "%s%sunknown key '%s' (expected one of: %s)", ppath,
                      plen ? ": " : "", s.bad_key, want);
        } else if (s.known && !fits(&s, e->kind)) {
            expected_shape(&s, want, sizeof want);
            cs_err_at(l, file, e->line, e->col, "%s is %s (expected %s)",
                      e->path[0] ? e->path : "the document", kind_name(e->kind), want);
            if (sk->count < 64) snprintf(sk->path[sk->count++], 256, "%s", s.skey);
        } else if (s.known && e->duplicate) {
            const cs_ypos *first = cs_yposmap_find(map, e->path);
            cs_err_at(l, file, e->key_line, e->key_col, "%s: given twice (first at %d:%d)", e->path,
                      first->key_line, first->key_col);
            if (sk->count < 64) snprintf(sk->path[sk->count++], 256, "%s", s.skey);
        }
        e->bad = l->error_count > before;
    }
}

int cs_damaged(const cs_loader *l, const cs_node *n) {
    if (n->source < 0) return 0;
    const cs_yposmap *map = &l->files[n->source].map;
    size_t len = strlen(n->path);
    for (int i = 0; i < map->count; i++)
        if (map->items[i].bad && strncmp(map->items[i].path, n->path, len) == 0) return 1;
    return 0;
}

/* ---- the libcyaml schema of a file ---- */

static const cyaml_schema_value_t string_value = {.type = CYAML_STRING,
                                                  .flags = CYAML_FLAG_POINTER,
                                                  .data_size = sizeof(char),
                                                  .string = {0, CYAML_UNLIMITED}};

static cyaml_schema_field_t *build_fields(cs_loader *l, int file, const cs_table *t, const char *skey,
                                          const skips *sk);

static int build_mapping(cs_loader *l, int file, const cs_table *t, const char *skey, const skips *sk,
                         cyaml_schema_value_t *v, cyaml_flag_e flags) {
    cyaml_schema_field_t *fields = build_fields(l, file, t, skey, sk);
    if (!fields) return -1;
    *v = (cyaml_schema_value_t){.type = CYAML_MAPPING,
                                .flags = flags,
                                .data_size = (uint32_t)(2 * (size_t)t->count * sizeof(slot)),
                                .mapping = {fields}};
    return 0;
}

static cyaml_schema_field_t *build_fields(cs_loader *l, int file, const cs_table *t, const char *skey,
                                          const skips *sk) {
    cyaml_schema_field_t *fields = cs_arena_alloc(l, (size_t)(t->count + 1) * sizeof *fields);
    if (!fields) return NULL;
    for (int i = 0; i < t->count; i++) {
        const cs_field *f = &t->fields[i];
        cyaml_schema_field_t *o = &fields[i];
        char sub[256];
        snprintf(sub, sizeof sub, "%s%s%s", skey, skey[0] ? "." : "", f->key);
        o->key = f->key;
        o->data_offset = (uint32_t)(2 * (size_t)i * sizeof(slot));
        o->count_offset = (uint32_t)((2 * (size_t)i + 1) * sizeof(slot));
        o->count_size = sizeof(uint64_t);
        cyaml_flag_e opt = CYAML_FLAG_OPTIONAL | CYAML_FLAG_POINTER;
        cs_ykind part_kind = CS_Y_MAP;
        if (f->kind == CS_F_PART) {
            const cs_ypos *at = cs_yposmap_find(&l->files[file].map, sub);
            if (at) part_kind = at->kind;
        }
        if (skipped(sk, sub)) {
            o->value = (cyaml_schema_value_t){.type = CYAML_IGNORE, .flags = CYAML_FLAG_OPTIONAL};
        } else if (scalar_kind(f->kind) || (f->kind == CS_F_PART && part_kind == CS_Y_SCALAR)) {
            o->value = string_value;
            o->value.flags = opt;
            if (f->kind == CS_F_PART) o->data_offset = o->count_offset;
        } else if (f->kind == CS_F_LIST || f->kind == CS_F_SEQ) {
            cyaml_schema_value_t *entry = cs_arena_alloc(l, sizeof *entry);
            if (!entry) return NULL;
            if (f->kind == CS_F_LIST)
                *entry = string_value;
            else if (build_mapping(l, file, f->sub, sub, sk, entry, CYAML_FLAG_DEFAULT) != 0)
                return NULL;
            o->value = (cyaml_schema_value_t){.type = CYAML_SEQUENCE,
                                              .flags = opt,
                                              .data_size = entry->data_size,
                                              .sequence = {entry, 0, CYAML_UNLIMITED}};
            if (f->kind == CS_F_LIST) o->value.data_size = sizeof(char *);
        } else if (build_mapping(l, file, f->sub, sub, sk, &o->value, opt) != 0) {
            return NULL;
        }
    }
    return fields;
}

/* ---- slots to nodes ---- */

static cs_node *new_node(cs_loader *l, cs_ykind kind, int file, const char *parent, const char *key,
                         long index) {
    cs_node *n = cs_arena_alloc(l, sizeof *n);
    char path[512];
    if (key)
        snprintf(path, sizeof path, "%s%s%s", parent, parent[0] ? "." : "", key);
    else
        snprintf(path, sizeof path, "%s[%ld]", parent, index);
    if (!n || !(n->path = cs_arena_strdup(l, path))) return NULL;
    n->kind = kind;
    n->source = file;
    return n;
}

static cs_node *scalar_node(cs_loader *l, const char *text, int file, const char *parent, const char *key,
                            long index) {
    cs_node *n = new_node(l, CS_Y_SCALAR, file, parent, key, index);
    if (n && !(n->text = cs_arena_strdup(l, text))) return NULL;
    return n;
}

static int fill_map(cs_loader *l, cs_node *n, const cs_table *t, const slot *s);

static cs_node *map_node(cs_loader *l, const cs_table *t, const slot *s, int file, const char *parent,
                         const char *key, long index) {
    cs_node *n = new_node(l, CS_Y_MAP, file, parent, key, index);
    if (!n) return NULL;
    n->table = t;
    n->count = t->count;
    n->items = cs_arena_alloc(l, (size_t)t->count * sizeof *n->items);
    return n->items && fill_map(l, n, t, s) == 0 ? n : NULL;
}

static int fill_map(cs_loader *l, cs_node *n, const cs_table *t, const slot *s) {
    for (int i = 0; i < t->count; i++) {
        const cs_field *f = &t->fields[i];
        const slot *v = &s[2 * i], *c = &s[2 * i + 1];
        cs_node *item = NULL;
        if (f->kind == CS_F_PART && c->s) {
            item = scalar_node(l, c->s, n->source, n->path, f->key, 0);
        } else if (!v->p) {
            continue;
        } else if (scalar_kind(f->kind)) {
            item = scalar_node(l, v->s, n->source, n->path, f->key, 0);
        } else if (f->kind == CS_F_MAP || f->kind == CS_F_PART) {
            item = map_node(l, f->sub, v->p, n->source, n->path, f->key, 0);
        } else {
            if (c->n > INT_MAX || !(item = new_node(l, CS_Y_SEQ, n->source, n->path, f->key, 0))) return -1;
            item->count = (int)c->n;
            item->items = cs_arena_alloc(l, (c->n + 1) * sizeof *item->items);
            if (!item->items) return -1;
            for (int k = 0; k < item->count; k++) {
                item->items[k] =
                    f->kind == CS_F_LIST
                        ? scalar_node(l, ((char **)v->p)[k], n->source, item->path, NULL, k)
                        : map_node(l, f->sub, (const slot *)v->p + 2 * (size_t)k * (size_t)f->sub->count,
                                   n->source, item->path, NULL, k);
                if (!item->items[k]) return -1;
            }
        }
        if (!item) return -1;
        n->items[i] = item;
    }
    return 0;
}

static void cyaml_log_capture(cyaml_log_t level, void *ctx, const char *fmt, va_list args) {
    char *buf = ctx;
    size_t n = strlen(buf);
    if (level >= CYAML_LOG_ERROR && n < 255) vsnprintf(buf + n, 256 - n, fmt, args);
}

static int read_file(cs_loader *l, int file) {
    cs_lfile *lf = &l->files[file];
    if ((lf->data ? cs_yposmap_read_data(&lf->map, lf->data, lf->size)
                  : cs_yposmap_read(&lf->map, lf->real)) != 0) {
        cs_err_at(l, file, lf->map.error_line, lf->map.error_col, "%s", lf->map.error);
        return -1;
    }
    if (lf->map.count == 0) {
        cs_err_at(l, file, 1, 1,
                  "the file is empty (expected a mapping of parts, barrier, vehicle, scenario)");
        return -1;
    }
    int before = l->error_count;
    skips sk = {cs_arena_alloc(l, 64 * sizeof *sk.path), 0};
    if (!sk.path) return -1;
    check_shape(l, file, &sk);
    if (lf->map.items[0].kind != CS_Y_MAP) return -1;
    cyaml_schema_value_t top;
    if (build_mapping(l, file, &cs_table_model, "", &sk, &top, CYAML_FLAG_POINTER) != 0) return -1;
    char log[256] = "";
    cyaml_config_t config = {.log_fn = cyaml_log_capture,
                             .log_ctx = log,
                             .mem_fn = cyaml_mem,
                             .log_level = CYAML_LOG_ERROR,
                             .flags = CYAML_CFG_IGNORE_UNKNOWN_KEYS};
    slot *data = NULL;
    cyaml_err_t rc = lf->data ? cyaml_load_data((const uint8_t *)lf->data, lf->size, &config, &top,
                                                (cyaml_data_t **)&data, NULL)
                              : cyaml_load_file(lf->real, &config, &top, (cyaml_data_t **)&data, NULL);
    if (rc != CYAML_OK) {
        if (l->error_count == before) {
            log[strcspn(log, "\n")] = '\0';
            cs_err_at(l, file, 1, 1, "cannot load the file: %s (%s)", cyaml_strerror(rc), log);
        }
        return -1;
    }
    lf->root = map_node(l, &cs_table_model, data, file, "", "", 0);
    cyaml_free(&config, &top, data, 0);
    return lf->root ? 0 : -1; /* shape errors are recorded; the rest is still checked */
}

/* A new entry of the file table, read. Returns its index, or -1. */
static int add_file(cs_loader *l, const char *name, const char *real, const char *data, size_t size) {
    if (cs_grow(&l->files, &l->file_capacity, l->file_count, sizeof *l->files) != 0) return -1;
    int f = l->file_count++;
    cs_lfile *lf = &l->files[f];
    memset(lf, 0, sizeof *lf);
    lf->name = cs_arena_strdup(l, name);
    lf->real = cs_arena_strdup(l, real);
    lf->data = data;
    lf->size = size;
    if (!lf->name || !lf->real) return -1;
    lf->loading = 1;
    int rc = read_file(l, f);
    l->files[f].loading = 0;
    l->files_end = l->arena;
    if (rc != 0) l->files[f].root = NULL;
    return rc == 0 ? f : -1;
}

int cs_file_load(cs_loader *l, const char *path, const cs_node *from) {
    char real[PATH_MAX];
    if (!realpath(path, real)) {
        if (from)
            cs_err_node(l, from, 0, "cannot open '%s' (expected a readable YAML file)",
                        from->kind == CS_Y_SCALAR ? from->text : path);
        else
            cs_err_at(l, INT_MIN, 0, 0, "%s: cannot open the file (expected a readable YAML file)", path);
        return -1;
    }
    for (int i = 0; i < l->file_count; i++) {
        if (strcmp(l->files[i].real, real) != 0) continue;
        if (l->files[i].loading) {
            cs_err_node(l, from, 0, "'%s' refers back to itself (expected no reference cycle)", path);
            return -1;
        }
        return l->files[i].root ? i : -1;
    }
    return add_file(l, path, real, NULL, 0);
}

int cs_data_load(cs_loader *l, const char *name, const char *data, size_t size) {
    char real[PATH_MAX]; /* the file it stands for, if there is one */
    return add_file(l, name, realpath(name, real) ? real : name, data, size);
}

const cs_node *cs_node_get(const cs_node *map, const char *key) {
    if (!map || map->kind != CS_Y_MAP) return NULL;
    int i = cs_table_find(map->table, key);
    return i < 0 ? NULL : map->items[i];
}
