/* SPDX-License-Identifier: MIT */
/* The loader's context: memory, errors, file references, parts, --set overrides. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <limits.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "loader_int.h"
#include "out/htmltext.h"
#include "status.h"

enum { MAX_DEPTH = 16 };

struct cs_chunk {
    struct cs_chunk *next;
    max_align_t data[];
};

void *cs_arena_alloc(cs_loader *l, size_t size) {
    struct cs_chunk *c = calloc(1, sizeof *c + size);
    if (!c) return NULL;
    c->next = l->arena;
    l->arena = c;
    return c->data;
}

char *cs_arena_strdup(cs_loader *l, const char *s) {
    size_t n = strlen(s) + 1;
    char *d = cs_arena_alloc(l, n);
    if (d) memcpy(d, s, n);
    return d;
}

cs_loader *cs_loader_create(const char *data_dir, cs_error *err) {
    cs_loader *l = calloc(1, sizeof *l);
    if (!l) {
        cs_status_set(err, CS_ERR_MEMORY, "out of memory");
        return NULL;
    }
    if (data_dir)
        snprintf(l->data_dir, sizeof l->data_dir, "%s", data_dir);
    else
        cs_data_dir_find(l->data_dir, sizeof l->data_dir, l->data_note, sizeof l->data_note);
    char why[CS_MESSAGE_SIZE];
    if (!(l->units = cs_units_create(why, sizeof why))) {
        free(l);
        cs_status_set(err, CS_ERR_IO, why);
        return NULL;
    }
    cs_status_set(err, CS_OK, "");
    return l;
}

cs_status cs_loader_allow_path(cs_loader *l, const char *dir, cs_error *err) {
    char why[CS_MESSAGE_SIZE];
    return cs_status_set(err, cs_allow_add(&l->allow, dir, why, sizeof why) ? CS_ERR_INVALID : CS_OK, why);
}

const char *cs_loader_data_dir(const cs_loader *l) {
    return l->data_dir;
}

/* Free the overrides' texts (the array stays for the next ones). */
static void drop_sets(cs_loader *l) {
    for (int i = 0; i < l->set_count; i++) {
        free(l->sets[i].path);
        free(l->sets[i].value);
    }
    l->set_count = 0;
}

/* Free the arena's allocations newer than keep (NULL: all). */
static void drop_arena_to(cs_loader *l, struct cs_chunk *keep) {
    while (l->arena != keep) {
        struct cs_chunk *next = l->arena->next;
        free(l->arena);
        l->arena = next;
    }
}

void cs_loader_reset(cs_loader *l) {
    for (int i = 0; i < l->file_count; i++)
        cs_ytree_free(&l->files[i].tree);
    free(l->files);
    for (int i = 0; i < l->error_count; i++)
        free(l->errors[i].text);
    free(l->errors);
    drop_sets(l);
    free(l->sets);
    drop_arena_to(l, NULL);
    cs_allow_free(&l->scope);
    cs_units *units = l->units;
    cs_allow allow = l->allow;
    char data_dir[sizeof l->data_dir], data_note[sizeof l->data_note];
    memcpy(data_dir, l->data_dir, sizeof data_dir);
    memcpy(data_note, l->data_note, sizeof data_note);
    memset(l, 0, sizeof *l);
    l->units = units;
    l->allow = allow;
    memcpy(l->data_dir, data_dir, sizeof data_dir);
    memcpy(l->data_note, data_note, sizeof data_note);
}

void cs_loader_reuse(cs_loader *l) {
    if (l->error_count) {
        cs_loader_reset(l);
        return;
    }
    drop_sets(l);
    drop_arena_to(l, l->files_end); /* the files' nodes are older; nothing of theirs points later */
    l->depth = 0;
    l->post_origin = l->cable_origin = NULL;
    l->vehicle_node = l->scenario_node = l->anchors_node = l->soil_node = NULL;
}

void cs_loader_free(cs_loader *l) {
    if (!l) return;
    cs_loader_reset(l);
    cs_allow_free(&l->allow);
    cs_units_free(l->units);
    free(l);
}

/* ---- errors ---- */

static void add_error(cs_loader *l, int source, int line, int col, const char *fmt, va_list ap) {
    char msg[1024], where[600] = "";
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (source >= 0 && source < l->file_count)
        snprintf(where, sizeof where, "%s:%d:%d: ", l->files[source].name, line, col);
    else if (source < 0 && source != INT_MIN && -1 - source < l->set_count)
        snprintf(where, sizeof where, "--set %s%s%s: ", l->sets[-1 - source].path,
                 l->sets[-1 - source].bad ? "" : "=", l->sets[-1 - source].value);
    if (cs_grow(&l->errors, &l->error_capacity, l->error_count, sizeof *l->errors) != 0) return;
    size_t n = strlen(where) + strlen(msg) + 1;
    char *text = malloc(n);
    if (!text) return;
    snprintf(text, n, "%s%s", where, msg);
    /* a --set sorts after the files; a message with no place first */
    int key = source == INT_MIN ? -1 : source < 0 ? INT_MAX / 2 - source : source;
    l->errors[l->error_count] = (cs_lerror){key, line, col, l->error_count, text};
    l->error_count++;
    l->errors_sorted = 0;
}

void cs_err_at(cs_loader *l, int source, int line, int col, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    add_error(l, source, line, col, fmt, ap);
    va_end(ap);
}

void cs_err_node(cs_loader *l, const cs_node *at, int at_key, const char *fmt, ...) {
    char msg[900];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    int line = 1, col = 1;
    if (at->source >= 0) {
        const cs_ynode *p = at->at;
        if (p) {
            line = at_key ? p->key_line : p->line;
            col = at_key ? p->key_col : p->col;
        }
        if (at->path[0]) {
            cs_err_at(l, at->source, line, col, "%s: %s", at->path, msg);
            return;
        }
    }
    cs_err_at(l, at->source, line, col, "%s", msg);
}

void cs_field_hint(const cs_field *f, char *buf, size_t size) {
    const cs_quantity_info *q = cs_quantity_get(f->q);
    switch (f->kind) {
    case CS_F_QTY:
    case CS_F_LIST:
        if (f->q == CS_Q_NUMBER)
            snprintf(buf, size, "%s, e.g. %s", f->kind == CS_F_LIST ? "a list of numbers" : "a number",
                     q->example);
        else
            snprintf(buf, size, "%s%s, e.g. \"%s\"%s",
                     f->kind == CS_F_LIST          ? "a list of values of "
                     : strchr("aeiou", q->name[0]) ? "an "
                                                   : "a ",
                     q->name, q->example, f->flags & CS_NONE_OK ? " or none" : "");
        break;
    case CS_F_INT:
        snprintf(buf, size, "a whole number");
        break;
    case CS_F_ENUM: {
        size_t n = 0;
        buf[0] = '\0';
        for (int k = 0; f->words[k] && n < size; k++) {
            const char *sep = k == 0 ? "" : (f->words[k + 1] ? ", " : " or ");
            int w = snprintf(buf + n, size - n, "%s%s", sep, f->words[k]);
            n += w > 0 ? (size_t)w : 0;
        }
        break;
    }
    default:
        snprintf(buf, size, "text");
        break;
    }
}

static int error_order(const void *a, const void *b) {
    const cs_lerror *x = a, *y = b;
    if (x->source != y->source) return x->source < y->source ? -1 : 1;
    if (x->line != y->line) return x->line < y->line ? -1 : 1;
    if (x->col != y->col) return x->col < y->col ? -1 : 1;
    return (x->seq > y->seq) - (x->seq < y->seq);
}

/* Sort the problems by place and keep each once (a value used twice is wrong once). */
static void sort_errors(cs_loader *l) {
    if (l->errors_sorted) return;
    if (l->error_count > 1) /* none: errors may be NULL, which qsort must not be given */
        qsort(l->errors, (size_t)l->error_count, sizeof *l->errors, error_order);
    int kept = 0;
    for (int k = 0; k < l->error_count; k++) {
        if (kept > 0 && strcmp(l->errors[kept - 1].text, l->errors[k].text) == 0) {
            free(l->errors[k].text);
            continue;
        }
        l->errors[kept++] = l->errors[k];
    }
    l->error_count = kept;
    l->errors_sorted = 1;
}

int cs_loader_error_count(cs_loader *l) {
    sort_errors(l);
    return l->error_count;
}

const char *cs_loader_error(cs_loader *l, int i) {
    sort_errors(l);
    return i >= 0 && i < l->error_count ? l->errors[i].text : NULL;
}

void cs_loader_print_errors(cs_loader *l, FILE *out) {
    for (int i = 0; i < l->error_count; i++) {
        const char *e = cs_loader_error(l, i);
        if (e) cs_term_text(out, e), fputc('\n', out); /* a value echoed as the file gave it */
    }
}

/* ---- references ---- */

static cs_node *clone(cs_loader *l, const cs_node *n) {
    cs_node *c = cs_arena_alloc(l, sizeof *c);
    if (!c) return NULL;
    *c = *n;
    if (n->items) {
        size_t size = (size_t)n->count * sizeof *c->items;
        if (!(c->items = cs_arena_alloc(l, size + sizeof *c->items))) return NULL;
        memcpy(c->items, n->items, size);
    }
    return c;
}

/* local's fields over base's (a field given replaces the base's whole). */
static const cs_node *merge(cs_loader *l, const cs_node *local, const cs_node *base) {
    cs_node *n = clone(l, local);
    if (!n) return NULL;
    for (int i = 0; i < n->count; i++)
        if (!n->items[i]) n->items[i] = base->items[i];
    return n;
}

int cs_library_read(cs_loader *l) {
    if (l->library_state) return l->library_state > 0 ? 0 : -1;
    l->library_state = -1;
    DIR *d = l->data_dir[0] ? opendir(l->data_dir) : NULL;
    if (!l->data_dir[0]) {
        cs_err_at(l, INT_MIN, 0, 0,
                  "cannot find the parts library: %s (set CABLESIM_DATA to the folder of its YAML files)",
                  l->data_note);
        return -1;
    }
    if (!d) {
        cs_err_at(l, INT_MIN, 0, 0, "%s: cannot read the parts library (%s%sexpected a folder of YAML files)",
                  l->data_dir, l->data_note, l->data_note[0] ? "; " : "");
        return -1;
    }
    char names[64][PATH_MAX];
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)) && count < 64) {
        size_t n = strlen(e->d_name);
        if (n > 5 && n < 256 && strcmp(e->d_name + n - 5, ".yaml") == 0)
            snprintf(names[count++], sizeof names[0], "%.1024s/%.255s", l->data_dir, e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)count, sizeof names[0], (int (*)(const void *, const void *))strcmp);
    int ok = 1;
    l->library_first = l->file_count;
    for (int i = 0; i < count; i++)
        ok &= cs_file_load(l, names[i], NULL) >= 0;
    l->library_end = l->file_count;
    l->library_state = ok ? 1 : -1;
    return ok ? 0 : -1;
}

static const cs_node *find_in_file(const cs_loader *l, int file, const char *list, const char *name) {
    if (file < 0 || file >= l->file_count) return NULL;
    const cs_node *seq = cs_node_get(cs_node_get(l->files[file].root, "parts"), list);
    for (int i = 0; seq && i < seq->count; i++) {
        const cs_node *n = cs_node_get(seq->items[i], "name");
        if (n && strcmp(n->text, name) == 0) return seq->items[i];
    }
    return NULL;
}

static void part_names(const cs_loader *l, int file, const char *list, char *buf, size_t size) {
    size_t n = 0;
    buf[0] = '\0';
    for (int f = 0; f < l->file_count && n < size; f++) {
        if (f != file && (f < l->library_first || f >= l->library_end)) continue;
        const cs_node *seq = cs_node_get(cs_node_get(l->files[f].root, "parts"), list);
        for (int i = 0; seq && i < seq->count && n < size; i++) {
            const cs_node *nm = cs_node_get(seq->items[i], "name");
            if (nm) n += (size_t)snprintf(buf + n, size - n, "%s%s", n ? ", " : "", nm->text);
        }
    }
}

static int main_file(const cs_loader *l) {
    return l->library_state && l->library_first == 0 ? l->library_end : 0;
}

const cs_node *cs_find_part(cs_loader *l, int source, const char *list, const char *name,
                            const cs_node *from) {
    int file = source >= 0 ? source : main_file(l);
    const cs_node *found = find_in_file(l, file, list, name);
    cs_library_read(l);
    for (int f = l->library_first; !found && f < l->library_end; f++)
        if (l->files[f].root) found = find_in_file(l, f, list, name);
    if (!found) {
        char names[600];
        part_names(l, file, list, names, sizeof names);
        cs_err_node(l, from, 0, "no %.*s part named '%s' (expected one of: %s)", (int)strlen(list) - 1, list,
                    name, names);
        return NULL;
    }
    const cs_node *base_name = cs_node_get(found, "part");
    if (!base_name) return found;
    if (l->depth >= MAX_DEPTH) {
        cs_err_node(l, base_name, 0, "parts refer to each other in a cycle (expected a chain that ends)");
        return NULL;
    }
    l->depth++;
    const cs_node *base = cs_find_part(l, found->source, list, base_name->text, base_name);
    l->depth--;
    return base ? merge(l, found, base) : NULL;
}

/* A copy of path's folder joined to name (name as is when absolute). */
static void relative_to(const char *path, const char *name, char *out, size_t size) {
    const char *slash = strrchr(path, '/');
    if (name[0] == '/' || !slash)
        snprintf(out, size, "%s", name);
    else
        snprintf(out, size, "%.*s/%s", (int)(slash - path), path, name);
}

/* barrier, vehicle or scenario of a model: a part name, or a mapping with file or part underneath. */
static const cs_node *resolve_top(cs_loader *l, const cs_node *node, const char *key) {
    if (node->kind == CS_Y_SCALAR) return cs_find_part(l, node->source, "vehicles", node->text, node);
    const cs_node *file = cs_node_get(node, "file"), *part = cs_node_get(node, "part"), *base = NULL;
    if (file && part) {
        cs_err_node(l, part, 1, "give file or part, not both (expected one source for the %s)", key);
        return NULL;
    }
    if (l->depth >= MAX_DEPTH) {
        cs_err_node(l, node, 0, "files refer to each other in a cycle (expected a chain that ends)");
        return NULL;
    }
    l->depth++;
    if (part) {
        base = cs_find_part(l, part->source, "vehicles", part->text, part);
    } else if (file) {
        char path[PATH_MAX];
        relative_to(node->source >= 0 ? l->files[node->source].real : ".", file->text, path, sizeof path);
        int g = cs_file_load(l, path, file);
        const cs_node *theirs = g >= 0 ? cs_node_get(l->files[g].root, key) : NULL;
        if (g >= 0 && !theirs)
            cs_err_node(l, file, 0, "'%s' has no %s (expected a file with a %s)", file->text, key, key);
        base = theirs ? resolve_top(l, theirs, key) : NULL;
    }
    l->depth--;
    if ((file || part) && !base) return NULL;
    return base ? merge(l, node, base) : node;
}

static const char *const top_keys[] = {"barrier", "vehicle", "scenario"};

cs_node *cs_resolve_model(cs_loader *l, int file) {
    cs_node *root = clone(l, l->files[file].root);
    int ok = root != NULL;
    for (size_t k = 0; ok && k < sizeof top_keys / sizeof top_keys[0]; k++) {
        int i = cs_table_find(&cs_table_model, top_keys[k]);
        if (root->items[i] && !(root->items[i] = (cs_node *)resolve_top(l, root->items[i], top_keys[k])))
            ok = 0;
    }
    return ok ? root : NULL;
}

/* ---- --set ---- */

cs_status cs_loader_set(cs_loader *l, const char *assignment) {
    const char *eq = strchr(assignment, '=');
    if (cs_grow(&l->sets, &l->set_capacity, l->set_count, sizeof *l->sets) != 0) return CS_ERR_MEMORY;
    size_t n = eq ? (size_t)(eq - assignment) : strlen(assignment);
    cs_lset *s = &l->sets[l->set_count];
    s->path = malloc(n + 1);
    s->value = strdup(eq ? eq + 1 : "");
    if (!s->path || !s->value) {
        free(s->path);
        free(s->value);
        return CS_ERR_MEMORY;
    }
    memcpy(s->path, assignment, n);
    s->path[n] = '\0';
    s->bad = !eq || n == 0;
    l->set_count++;
    if (s->bad) {
        cs_err_at(l, -l->set_count, 0, 0, "expected PATH=VALUE, e.g. scenario.speed=\"35 mph\"");
        return CS_ERR_INVALID;
    }
    return CS_OK;
}

static cs_node *set_node(cs_loader *l, int k, cs_ykind kind, const cs_table *t) {
    cs_node *n = cs_arena_alloc(l, sizeof *n);
    if (!n) return NULL;
    n->kind = kind;
    n->source = -1 - k;
    n->path = l->sets[k].path;
    n->text = l->sets[k].value;
    if (t && !(n->items = cs_arena_alloc(l, (size_t)t->count * sizeof *n->items))) return NULL;
    n->table = t;
    n->count = t ? t->count : 0;
    return n;
}

/* Apply the k-th --set to the resolved model, copying every node on the way (files stay as read). */
static void apply_set(cs_loader *l, cs_node **root, int k) {
    const char *p = l->sets[k].path;
    cs_node **ref = root;
    const cs_field *f = NULL;
    char key[64];
    long index;
    int rc, src = -1 - k;
    while ((rc = cs_path_next(&p, key, sizeof key, &index)) > 0) {
        cs_node *n = clone(l, *ref);
        if (!n) return;
        *ref = n;
        int i = rc == 1 && n->kind == CS_Y_MAP ? cs_table_find(n->table, key) : -1;
        if (rc == 1 && i < 0) {
            cs_err_at(l, src, 0, 0, "unknown key '%s'%s%s", key, n->kind == CS_Y_MAP ? " in " : "",
                      n->kind == CS_Y_MAP ? n->table->name : " (expected a path to a value)");
            return;
        }
        if (rc == 2 && (n->kind != CS_Y_SEQ || index >= n->count)) {
            cs_err_at(l, src, 0, 0, "no entry [%ld] (expected an index below %d)", index,
                      n->kind == CS_Y_SEQ ? n->count : 0);
            return;
        }
        if (rc == 1) f = &n->table->fields[i];
        ref = rc == 1 ? &n->items[i] : &n->items[index];
        int last = *p == '\0', item = rc == 2;
        int scalar = f->kind != CS_F_MAP && f->kind != CS_F_SEQ && (item || f->kind != CS_F_LIST);
        if (last && !scalar) {
            cs_err_at(l, src, 0, 0, "'%s' is not a single value (expected a path to one value)", key);
            return;
        }
        if (last && (strcmp(key, "file") == 0 || strcmp(key, "part") == 0)) {
            cs_err_at(l, src, 0, 0,
                      "'%s' is followed when the model file is read, not after (expected a value of the "
                      "model, or the file edited to name another %s)",
                      key, key);
            return;
        }
        if (last) {
            *ref = set_node(l, k, CS_Y_SCALAR, NULL);
            if (*ref && f->kind == CS_F_PART) *ref = (cs_node *)resolve_top(l, *ref, f->key);
            return;
        }
        if (!*ref && (f->kind == CS_F_MAP || f->kind == CS_F_PART)) *ref = set_node(l, k, CS_Y_MAP, f->sub);
        if (!*ref) {
            cs_err_at(l, src, 0, 0, "the model has no %s (expected a path to a value)", key);
            return;
        }
    }
    if (rc < 0)
        cs_err_at(l, src, 0, 0, "malformed path (expected keys and [index], e.g. barrier.cables[0].height)");
}

/* The folders the references of the model file named may be in: its own folder (as named), the parts
 * library's and those the user allowed. */
static void set_scope(cs_loader *l, const char *name) {
    char why[PATH_MAX + 64], dir[PATH_MAX];
    const char *slash = strrchr(name, '/');
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - name) + 1 : 1, slash ? name : ".");
    cs_allow_free(&l->scope);
    cs_allow_copy(&l->scope, &l->allow);
    if (l->data_dir[0]) cs_allow_add(&l->scope, l->data_dir, why, sizeof why);
    cs_allow_add(&l->scope, dir, why, sizeof why); /* none: the file's own load reports why */
}

static int load(cs_loader *l, int f, cs_model_input *out) {
    cs_node *root = f >= 0 ? cs_resolve_model(l, f) : NULL;
    for (int k = 0; root && k < l->set_count; k++)
        if (!l->sets[k].bad) apply_set(l, &root, k);
    if (root) cs_convert_model(l, root, l->files[f].name, out);
    return l->error_count ? -1 : 0;
}

cs_status cs_loader_load(cs_loader *l, const char *path, cs_model_input *out) {
    memset(out, 0, sizeof *out);
    set_scope(l, path);
    return load(l, cs_file_load(l, path, NULL), out) ? CS_ERR_INVALID : CS_OK;
}

cs_status cs_loader_load_buffer(cs_loader *l, const char *name, const char *data, size_t size,
                                cs_model_input *out) {
    memset(out, 0, sizeof *out);
    set_scope(l, name);
    return load(l, cs_data_load(l, name, data, size), out) ? CS_ERR_INVALID : CS_OK;
}

/* ---- the library ---- */

static const char *const part_lists[CS_PART_KIND_COUNT] = {"vehicles", "ropes", "sections", "rails"};

int cs_loader_library(cs_loader *l, cs_part_kind kind, const char ***names, const char ***descriptions) {
    if (cs_library_read(l) != 0) return -1;
    int count = 0;
    for (int pass = 0; pass < 2; pass++) {
        int n = 0;
        for (int f = l->library_first; f < l->library_end; f++) {
            const cs_node *seq = cs_node_get(cs_node_get(l->files[f].root, "parts"), part_lists[kind]);
            for (int i = 0; seq && i < seq->count; i++, n++) {
                const cs_node *nm = cs_node_get(seq->items[i], "name"),
                              *d = cs_node_get(seq->items[i], "description");
                if (pass == 0) continue;
                (*names)[n] = nm ? nm->text : "";
                (*descriptions)[n] = d ? d->text : "";
            }
        }
        count = n;
        if (pass == 0) {
            *names = cs_arena_alloc(l, (size_t)(n + 1) * sizeof **names);
            *descriptions = cs_arena_alloc(l, (size_t)(n + 1) * sizeof **descriptions);
            if (!*names || !*descriptions) return -1;
        }
    }
    return count;
}

cs_status cs_loader_part(cs_loader *l, cs_part_kind kind, const char *name, void *def) {
    if (cs_library_read(l) != 0) return CS_ERR_INVALID;
    cs_node at = {.kind = CS_Y_SCALAR, .text = name, .source = INT_MIN, .path = name};
    const cs_node *part = cs_find_part(l, main_file(l), part_lists[kind], name, &at);
    if (!part) return CS_ERR_INVALID;
    int errors = 0;
    if (kind == CS_PART_VEHICLE)
        errors = cs_convert_vehicle(l, part, def);
    else if (kind == CS_PART_ROPE)
        errors = cs_convert_rope(l, part, def, NULL);
    else if (kind == CS_PART_RAIL) {
        *(cs_rail_def *)def = cs_default_rail_def();
        errors = cs_convert_fields(l, part, def);
    } else {
        *(cs_section_def *)def = cs_default_section_def();
        errors = cs_convert_fields(l, part, def);
    }
    return errors ? CS_ERR_INVALID : CS_OK;
}

/* ---- the engine's own check ---- */

/* The engine's messages start with the element they are about: "cable 1: ...", "post 3: ...", "anchor
 * 0: ...", "vehicle: ...", "scenario: ...". Its kind (an index of words) and number, or -1. */
static const char *const element_words[] = {"cable", "post", "anchor", "vehicle", "scenario"};

static int engine_element(const char *msg, long *index) {
    for (int w = 0; w < (int)(sizeof element_words / sizeof element_words[0]); w++) {
        size_t n = strlen(element_words[w]);
        if (strncmp(msg, element_words[w], n) != 0) continue;
        *index = strtol(msg + n, NULL, 10);
        return w;
    }
    return -1;
}

/* The node of that element in the files. */
static const cs_node *engine_place(const cs_loader *l, const cs_model_input *in, int w, long i) {
    if (w == 0 && l->cable_origin && i >= 0 && i < in->barrier.cable_count) return l->cable_origin[i];
    if (w == 1 && l->post_origin && i >= 0 && i < in->barrier.post_count) return l->post_origin[i];
    if (w == 2) return l->anchors_node;
    if (w == 3) return l->vehicle_node;
    if (w == 4) return l->scenario_node;
    return NULL;
}

/* The --set that changed that element, if one did: the value the engine refuses most likely came from
 * it, not from the file. A message about the soil (an anchor's or a footing's, which take the barrier's
 * soil) looks for a --set of barrier.soil first. Its index, or -1. */
static int engine_set(const cs_loader *l, int w, long i, int soil) {
    char prefix[64];
    for (int k = l->set_count - 1; soil && k >= 0; k--)
        if (!l->sets[k].bad && strncmp(l->sets[k].path, "barrier.soil", 12) == 0) return k;
    if (w == 0)
        snprintf(prefix, sizeof prefix, "barrier.cables[%ld]", i);
    else if (w == 1)
        snprintf(prefix, sizeof prefix, "barrier.posts");
    else if (w == 2)
        snprintf(prefix, sizeof prefix, "barrier.anchors");
    else if (w >= 3)
        snprintf(prefix, sizeof prefix, "%s", element_words[w]);
    else
        return -1;
    for (int k = l->set_count - 1; k >= 0; k--)
        if (!l->sets[k].bad && strncmp(l->sets[k].path, prefix, strlen(prefix)) == 0) return k;
    return -1;
}

cs_model *cs_loader_build(cs_loader *l, const cs_model_input *in) {
    cs_error err = {0};
    cs_model *m = cs_model_create(&in->barrier, &in->vehicle, &in->scenario, &err);
    if (m) return m;
    long i = -1;
    int soil = strstr(err.message, "soil") != NULL;
    int w = engine_element(err.message, &i), set = w >= 0 ? engine_set(l, w, i, soil) : -1;
    const cs_node *place = soil && l->soil_node ? l->soil_node : w >= 0 ? engine_place(l, in, w, i) : NULL;
    if (set >= 0)
        cs_err_at(l, -1 - set, 0, 0, "%s (the engine's check of the model)", err.message);
    else if (place)
        cs_err_node(l, place, 0, "%s (the engine's check of the model)", err.message);
    else
        cs_err_at(l, 0, 1, 1, "%s (the engine's check of the model)", err.message);
    return NULL;
}
