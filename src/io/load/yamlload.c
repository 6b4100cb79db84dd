/* SPDX-License-Identifier: MIT */
/* One model file into the loader's nodes: the YAML tree (yamltree.h) gives every value with its place,
 * the schema tables check each one's key and shape where it is written, and the values that fit become
 * the nodes the rest of the loader resolves, overrides and converts. */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "loader_int.h"

enum { MAX_DEPTH = 64 }; /* how deep a model file's collections may nest: far more than the schema's */

static int scalar_kind(cs_fkind k) {
    return k == CS_F_QTY || k == CS_F_INT || k == CS_F_TEXT || k == CS_F_ENUM;
}

/* Does a value of kind k fit where s says? */
static int fits(const cs_schema_place *s, cs_ykind k) {
    if (!s->field) return k == CS_Y_MAP;
    cs_fkind f = s->field->kind;
    if (s->item) return f == CS_F_SEQ ? k == CS_Y_MAP : k == CS_Y_SCALAR;
    if (scalar_kind(f)) return k == CS_Y_SCALAR;
    if (f == CS_F_LIST || f == CS_F_SEQ) return k == CS_Y_SEQ;
    if (f == CS_F_PART) return k == CS_Y_SCALAR || k == CS_Y_MAP;
    return k == CS_Y_MAP;
}

static void expected_shape(const cs_schema_place *s, char *buf, size_t size) {
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

/* Report a value at path (written at e) that does not fit where s says: an alias whose anchor was not
 * given before it, or a value of the wrong shape (an alias's: its anchor's). Returns 1 if reported. */
static int misfit(cs_loader *l, int file, const cs_ynode *e, const cs_schema_place *s, const char *path) {
    const cs_ynode *v = cs_ynode_value(e);
    char want[200];
    if (!v) {
        cs_err_at(l, file, e->line, e->col,
                  "%s: no anchor '%s' before this alias (expected &%s on a value above)",
                  path[0] ? path : "the document", e->text, e->text);
        return 1;
    }
    if (fits(s, v->kind)) return 0;
    expected_shape(s, want, sizeof want);
    cs_err_at(l, file, e->line, e->col, "%s is %s (expected %s)", path[0] ? path : "the document",
              cs_ykind_name(v->kind), want);
    return 1;
}

/* Schema paths whose values are left out of this file's nodes (their shape is wrong, already reported),
 * each once: at most the schema's paths, however many values of a path are wrong. */
typedef struct skips {
    char **path;
    int count, capacity;
} skips;

static int skipped(cs_loader *l, const skips *sk, const char *skey) {
    for (int i = 0; i < sk->count; i++) {
        l->work++;
        if (strcmp(sk->path[i], skey) == 0) return 1;
    }
    return 0;
}

static void skip(cs_loader *l, skips *sk, const char *skey) {
    if (!skipped(l, sk, skey) && cs_grow(&sk->path, &sk->capacity, sk->count, sizeof *sk->path) == 0 &&
        (sk->path[sk->count] = cs_arena_strdup(l, skey)))
        sk->count++;
}

static void table_keys(const cs_table *t, char *buf, size_t size) {
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < t->count && n < size; i++)
        n += (size_t)snprintf(buf + n, size - n, "%s%s", i ? ", " : "", t->fields[i].key);
}

/* Check every node's key and shape; report each problem at its place, and mark bad its node and those
 * above it (cs_damaged). */
static void check_shape(cs_loader *l, int file, skips *sk) {
    cs_ytree *tree = &l->files[file].tree;
    for (int i = 0; i < tree->count; i++) {
        cs_ynode *e = &tree->items[i];
        int before = l->error_count;
        l->work++;
        cs_schema_place s;
        cs_schema_walk(e->path, &s);
        int known = s.fault == CS_PATH_OK;
        if (e->odd_key) { /* its path would not name it: "speed.x" reads as speed, then x */
            cs_err_at(l, file, e->key_line, e->key_col,
                      "%s: a key must be a plain word (expected 1 to 63 characters, no '.', '[' or ']')",
                      e->path);
        } else if (s.fault == CS_PATH_UNKNOWN_KEY && s.last && s.table) {
            const char *dot = strrchr(e->path, '.');
            int plen = dot ? (int)(dot - e->path) : 0;
            char want[200];
            table_keys(s.table, want, sizeof want);
            cs_err_at(l, file, e->key_line, e->key_col, "%.*s%sunknown key '%s' (expected one of: %s)", plen,
                      e->path, plen ? ": " : "", s.key, want);
        } else if (known && misfit(l, file, e, &s, e->path)) {
            skip(l, sk, s.skey);
        } else if (known && e->first) {
            cs_err_at(l, file, e->key_line, e->key_col, "%s: given twice (first at %d:%d)", e->path,
                      e->first->key_line, e->first->key_col);
            skip(l, sk, s.skey);
        }
        e->bad = l->error_count > before;
    }
    for (int i = tree->count - 1; i > 0; i--) /* a node's parent comes before it */
        if (tree->items[i].bad) tree->items[tree->items[i].parent].bad = 1;
}

int cs_damaged(const cs_node *n) {
    return n->source >= 0 && n->at && n->at->bad;
}

/* ---- the tree's values into nodes ---- */

typedef struct build {
    cs_loader *l;
    int file;
    const skips *sk;
} build;

static int fill(const build *b, cs_node *n, const cs_ynode *y, const cs_field *f, const char *skey);

/* The node of the value written at y (an alias: its anchor's value) for field f (an entry of its list if
 * item; f NULL: the whole file), at parent.key or parent[index] (key NULL); skey is f's schema path.
 * Returns 0, 1 when the value is left out (*n stays NULL), or -1 when memory is short. Only an alias's
 * anchor can hold a value of the wrong shape here (elsewhere check_shape reported and skipped it): it is
 * reported at its place and left out. */
static int value(const build *b, cs_node **n, const cs_ynode *y, const cs_field *f, int item,
                 const char *parent, const char *key, long index, const char *skey) {
    char path[512];
    if (key)
        snprintf(path, sizeof path, "%s%s%s", parent, parent[0] ? "." : "", key);
    else
        snprintf(path, sizeof path, "%s[%ld]", parent, index);
    cs_schema_place s = {.field = f, .item = item};
    if (misfit(b->l, b->file, y, &s, path)) return 1;
    const cs_ynode *v = cs_ynode_value(y);
    cs_node *m = cs_arena_alloc(b->l, sizeof *m);
    b->l->work++;
    if (!m || !(m->path = cs_arena_strdup(b->l, path))) return -1;
    m->kind = v->kind;
    m->source = b->file;
    m->at = y;
    int rc = v->kind == CS_Y_SCALAR ? ((m->text = cs_arena_strdup(b->l, v->text)) ? 0 : -1)
                                    : fill(b, m, v, f, skey);
    if (rc == 0) *n = m;
    return rc;
}

/* The entries of a list node, or the fields of a mapping node (of field f's table; f NULL: the model's).
 * A list with an entry left out is left out whole (1). */
static int fill(const build *b, cs_node *n, const cs_ynode *y, const cs_field *f, const char *skey) {
    int seq = n->kind == CS_Y_SEQ;
    const cs_table *t = seq ? NULL : f ? f->sub : &cs_table_model;
    n->table = t;
    n->count = seq ? y->count : t->count;
    if (!(n->items = cs_arena_alloc(b->l, ((size_t)n->count + 1) * sizeof *n->items))) return -1;
    for (int i = 0; i < n->count; i++) {
        int rc = 0;
        if (seq) {
            rc = value(b, &n->items[i], y->kids[i], f, 1, n->path, NULL, i, skey);
        } else {
            const cs_field *g = &t->fields[i];
            char sub[256];
            snprintf(sub, sizeof sub, "%s%s%s", skey, skey[0] ? "." : "", g->key);
            const cs_ynode *kid = cs_ynode_get_counted(y, g->key, &b->l->work);
            if (kid && !skipped(b->l, b->sk, sub))
                rc = value(b, &n->items[i], kid, g, 0, n->path, g->key, 0, sub);
        }
        if (rc < 0 || (rc > 0 && seq)) return rc;
    }
    return 0;
}

/* The first node of a tree that a model file could not hold at its top: a root that is not a mapping, or a
 * key of the root that is not one of the model's. NULL: none (an empty file is a model's, wrong). */
static const cs_ynode *odd_top(const cs_ytree *t) {
    if (t->count == 0) return NULL;
    const cs_ynode *root = &t->items[0];
    if (root->kind != CS_Y_MAP) return root;
    for (int i = 0; i < root->count; i++)
        if (!root->kids[i]->key || cs_table_find(&cs_table_model, root->kids[i]->key) < 0)
            return root->kids[i];
    return NULL;
}

static int read_file(cs_loader *l, int file) {
    cs_lfile *lf = &l->files[file];
    if (cs_ytree_read(&lf->tree, lf->real, lf->data, lf->size, MAX_DEPTH) != 0) {
        if (lf->tree.unreadable) /* no place in a file it could not read */
            cs_err_at(l, INT_MIN, 0, 0, "%s: %s (expected a readable YAML file)", lf->name, lf->tree.error);
        else
            cs_err_at(l, file, lf->tree.error_line, lf->tree.error_col, "%s", lf->tree.error);
        return -1;
    }
    l->work += lf->tree.work;
    const cs_ynode *at = lf->referenced ? odd_top(&lf->tree) : NULL;
    if (at) { /* perhaps someone else's file: cs_file_load reports where, never what */
        lf->odd_line = at->key_line;
        lf->odd_col = at->key_col;
        return -1;
    }
    if (lf->tree.count == 0) {
        cs_err_at(l, file, 1, 1,
                  "the file is empty (expected a mapping of parts, barrier, vehicle, scenario)");
        return -1;
    }
    skips sk = {0};
    check_shape(l, file, &sk);
    cs_node *root = NULL;
    build b = {l, file, &sk};
    int rc =
        lf->tree.items[0].kind == CS_Y_MAP ? value(&b, &root, &lf->tree.items[0], NULL, 0, "", "", 0, "") : 1;
    free(sk.path);
    lf->root = root;
    return rc == 0 ? 0 : -1; /* shape errors are recorded; the rest is still checked */
}

/* A new entry of the file table, read. Returns its index, or -1. */
static int add_file(cs_loader *l, const char *name, const char *real, const char *data, size_t size,
                    int referenced) {
    if (cs_grow(&l->files, &l->file_capacity, l->file_count, sizeof *l->files) != 0) return -1;
    int f = l->file_count++;
    cs_lfile *lf = &l->files[f];
    memset(lf, 0, sizeof *lf);
    lf->name = cs_arena_strdup(l, name);
    lf->real = cs_arena_strdup(l, real);
    lf->data = data;
    lf->size = size;
    lf->referenced = referenced;
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
        int e = errno;
        if (from)
            cs_err_node(l, from, 0, "cannot open '%s': %s (expected a readable YAML file)",
                        from->kind == CS_Y_SCALAR ? from->text : path, strerror(e));
        else
            cs_err_at(l, INT_MIN, 0, 0, "%s: cannot open the file: %s (expected a readable YAML file)", path,
                      strerror(e));
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
    if (from && !cs_allow_has(&l->scope, real)) {
        char dirs[2048];
        cs_allow_list(&l->scope, dirs, sizeof dirs);
        cs_err_node(l, from, 0,
                    "'%s' is outside the folders a model may read (expected a file in %s or below; "
                    "--allow-path DIR allows another folder)",
                    from->kind == CS_Y_SCALAR ? from->text : path, dirs);
        return -1;
    }
    int f = add_file(l, path, real, NULL, 0, from != NULL);
    if (f < 0 && l->file_count > 0 && l->files[l->file_count - 1].odd_line)
        cs_err_node(l, from, 0,
                    "'%s' is not a model file (at its line %d, column %d; expected a mapping of name, "
                    "description, parts, barrier, vehicle, scenario; its text is not shown)",
                    from->kind == CS_Y_SCALAR ? from->text : path, l->files[l->file_count - 1].odd_line,
                    l->files[l->file_count - 1].odd_col);
    return f;
}

int cs_data_load(cs_loader *l, const char *name, const char *data, size_t size) {
    char real[PATH_MAX]; /* the file it stands for, if there is one */
    return add_file(l, name, realpath(name, real) ? real : name, data, size, 0);
}

const cs_node *cs_node_get(const cs_node *map, const char *key) {
    if (!map || map->kind != CS_Y_MAP) return NULL;
    int i = cs_table_find(map->table, key);
    return i < 0 ? NULL : map->items[i];
}
