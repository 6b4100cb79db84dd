/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include "yamltree.h"

#include "confine.h"
#include "grow.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

enum { MAX_DEPTH = 64 };

typedef struct frame {
    cs_ykind kind;
    int node;     /* its index in the tree */
    int index;    /* next sequence index */
    int want_key; /* mapping: the next node is a key */
    char *key;    /* mapping: the current key */
    yaml_mark_t key_mark;
    char *anchor; /* its anchor, named once it ends */
} frame;

/* An anchor: its name, its node, how many nodes were read when it was complete (an alias among them,
 * inside its own node, cannot name it) and how many anchors were complete before it. */
typedef struct anchor {
    char *name;
    int node, complete_at, order;
} anchor;

typedef struct reader {
    cs_ytree *tree;
    frame stack[MAX_DEPTH];
    int depth, max_depth;
    anchor *anchors;
    int anchor_count, anchor_capacity;
} reader;

static void fail(cs_ytree *t, const char *what, yaml_mark_t at) {
    snprintf(t->error, sizeof t->error, "%s", what);
    t->error_line = (int)at.line + 1;
    t->error_col = (int)at.column + 1;
}

static int add_anchor(reader *r, const char *name, int node) {
    if (!name) return 0;
    if (cs_grow(&r->anchors, &r->anchor_capacity, r->anchor_count, sizeof *r->anchors) != 0) return -1;
    anchor *a = &r->anchors[r->anchor_count];
    if (!(a->name = strdup(name))) return -1;
    a->node = node;
    a->complete_at = r->tree->count;
    a->order = r->anchor_count++;
    return 0;
}

static char *child_path(const cs_ytree *t, const frame *parent) {
    const char *pp = t->items[parent->node].path;
    size_t n = strlen(pp) + (parent->key ? strlen(parent->key) : 0) + 24;
    char *p = malloc(n);
    if (!p) return NULL;
    if (parent->kind == CS_Y_SEQ)
        snprintf(p, n, "%s[%d]", pp, parent->index);
    else
        snprintf(p, n, "%s%s%s", pp, pp[0] ? "." : "", parent->key);
    return p;
}

/* A new node for a value event, under its parent. Returns its index, or -1 when memory is short. */
static int add(cs_ytree *t, const frame *parent, cs_ykind kind, const yaml_event_t *ev) {
    if (cs_grow(&t->items, &t->capacity, t->count, sizeof *t->items) != 0) return -1;
    cs_ynode n = {.kind = kind, .parent = parent ? parent->node : -1};
    n.line = n.key_line = (int)ev->start_mark.line + 1;
    n.col = n.key_col = (int)ev->start_mark.column + 1;
    n.end_line = (int)ev->end_mark.line + 1;
    n.end_col = (int)ev->end_mark.column + 1;
    const char *text = kind == CS_Y_SCALAR  ? (const char *)ev->data.scalar.value
                       : kind == CS_Y_ALIAS ? (const char *)ev->data.alias.anchor
                                            : NULL;
    int ok = (n.path = parent ? child_path(t, parent) : strdup("")) != NULL;
    if (ok && text) ok = (n.text = strdup(text)) != NULL;
    if (ok && parent && parent->kind == CS_Y_MAP) {
        const char *k = parent->key;
        ok = (n.key = strdup(k)) != NULL;
        n.key_line = (int)parent->key_mark.line + 1;
        n.key_col = (int)parent->key_mark.column + 1;
        n.odd_key = !k[0] || strlen(k) >= 64 || strpbrk(k, ".[]") != NULL;
    }
    if (!ok) {
        free(n.path), free(n.text), free(n.key);
        return -1;
    }
    t->items[t->count] = n;
    t->work++;
    return t->count++;
}

/* Handle one node event: a mapping key, or a value added to the tree. Returns the value's index, -2 for
 * a key, -1 on failure (the tree's error set, or none when memory is short). */
static int node(reader *r, const yaml_event_t *ev, cs_ykind kind) {
    cs_ytree *t = r->tree;
    frame *parent = r->depth > 0 ? &r->stack[r->depth - 1] : NULL;
    if (parent && parent->kind == CS_Y_MAP && parent->want_key) {
        if (ev->type != YAML_SCALAR_EVENT) {
            fail(t, "a mapping key must be a plain word", ev->start_mark);
            return -1;
        }
        free(parent->key);
        parent->key = strdup((const char *)ev->data.scalar.value);
        parent->key_mark = ev->start_mark;
        parent->want_key = 0;
        return parent->key ? -2 : -1;
    }
    int i = add(t, parent, kind, ev);
    if (i < 0) return -1;
    if (parent && parent->kind == CS_Y_MAP) parent->want_key = 1;
    if (parent && parent->kind == CS_Y_SEQ) parent->index++;
    if (kind == CS_Y_SCALAR && add_anchor(r, (const char *)ev->data.scalar.anchor, i) != 0) return -1;
    if (kind != CS_Y_MAP && kind != CS_Y_SEQ) return i;
    if (r->depth == r->max_depth) {
        fail(t, "nested too deeply", ev->start_mark);
        return -1;
    }
    const yaml_char_t *anchor =
        kind == CS_Y_MAP ? ev->data.mapping_start.anchor : ev->data.sequence_start.anchor;
    frame *f = &r->stack[r->depth++];
    *f = (frame){kind, i, 0, 1, NULL, ev->start_mark, NULL};
    if (anchor && !(f->anchor = strdup((const char *)anchor))) return -1;
    return i;
}

/* The end of the innermost collection: its anchor, if any, now names it. */
static int end(reader *r) {
    frame *f = &r->stack[--r->depth];
    int rc = add_anchor(r, f->anchor, f->node);
    free(f->key);
    free(f->anchor);
    return rc;
}

/* Read the events of a parser whose input is set. */
static void read_events(reader *r, yaml_parser_t *parser) {
    cs_ytree *t = r->tree;
    int done = 0, docs = 0;
    while (!done && !t->error[0]) {
        yaml_event_t ev;
        if (!yaml_parser_parse(parser, &ev)) {
            snprintf(t->error, sizeof t->error, "YAML syntax: %s%s%s",
                     parser->problem ? parser->problem : "error", parser->context ? " " : "",
                     parser->context ? parser->context : "");
            t->error_line = (int)parser->problem_mark.line + 1;
            t->error_col = (int)parser->problem_mark.column + 1;
            break;
        }
        yaml_event_type_t e = ev.type;
        const yaml_char_t *tag = e == YAML_SCALAR_EVENT           ? ev.data.scalar.tag
                                 : e == YAML_MAPPING_START_EVENT  ? ev.data.mapping_start.tag
                                 : e == YAML_SEQUENCE_START_EVENT ? ev.data.sequence_start.tag
                                                                  : NULL;
        int rc = -2;
        if (tag) { /* a tag would change no value cablesim reads, so it would be ignored: refused */
            char what[160];
            snprintf(what, sizeof what, "a YAML tag ('%.60s') is not read (expected the value alone)",
                     (const char *)tag);
            fail(t, what, ev.start_mark);
        } else if (e == YAML_SCALAR_EVENT || e == YAML_ALIAS_EVENT || e == YAML_MAPPING_START_EVENT ||
                   e == YAML_SEQUENCE_START_EVENT)
            rc = node(r, &ev,
                      e == YAML_SCALAR_EVENT          ? CS_Y_SCALAR
                      : e == YAML_ALIAS_EVENT         ? CS_Y_ALIAS
                      : e == YAML_MAPPING_START_EVENT ? CS_Y_MAP
                                                      : CS_Y_SEQ);
        else if (e == YAML_MAPPING_END_EVENT || e == YAML_SEQUENCE_END_EVENT)
            rc = end(r) == 0 ? -2 : -1;
        else if (e == YAML_DOCUMENT_START_EVENT && ++docs > 1)
            fail(t, "only one YAML document per file", ev.start_mark);
        done = e == YAML_STREAM_END_EVENT;
        if (rc == -1 && !t->error[0]) fail(t, "out of memory", ev.start_mark);
        yaml_event_delete(&ev);
    }
    while (r->depth > 0) {
        frame *f = &r->stack[--r->depth];
        free(f->key);
        free(f->anchor);
    }
}

/* Order of a map's entries by key, then by place in the file. */
static int by_key(const void *a, const void *b) {
    const cs_ynode *x = *(const cs_ynode *const *)a, *y = *(const cs_ynode *const *)b;
    int c = strcmp(x->key, y->key);
    return c ? c : (x < y ? -1 : x > y);
}

/* Point each entry of a map whose key an earlier entry has (a key given twice) at that first entry: the
 * entries sorted by key, so that a map of n keys costs n log n, not n^2. 0, or -1 when memory is short. */
static int mark_duplicates(cs_ytree *t, cs_ynode *map) {
    if (map->count < 2) return 0;
    cs_ynode **sorted = malloc((size_t)map->count * sizeof *sorted);
    if (!sorted) return -1;
    memcpy(sorted, map->kids, (size_t)map->count * sizeof *sorted);
    qsort(sorted, (size_t)map->count, sizeof *sorted, by_key);
    for (int i = 1; i < map->count; i++)
        if (strcmp(sorted[i]->key, sorted[i - 1]->key) == 0)
            sorted[i]->first = sorted[i - 1]->first ? sorted[i - 1]->first : sorted[i - 1];
    t->work += (unsigned long)map->count;
    free(sorted);
    return 0;
}

/* Order of anchors by name, then by when they were complete. */
static int by_name(const void *a, const void *b) {
    const anchor *x = a, *y = b;
    int c = strcmp(x->name, y->name);
    return c ? c : (x->order > y->order) - (x->order < y->order);
}

/* The node an alias at node i names: of the anchors of its name complete before it (sorted by by_name),
 * the last; NULL if none. Two binary searches: a file of n aliases and anchors costs n log n. */
static const cs_ynode *anchored(cs_ytree *t, const anchor *sorted, int count, const char *name, int i) {
    int lo = 0, hi = count; /* the first anchor of name or after it */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (strcmp(sorted[mid].name, name) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    int first = lo;
    hi = count; /* past the last anchor of name complete by i */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (strcmp(sorted[mid].name, name) == 0 && sorted[mid].complete_at <= i)
            lo = mid + 1;
        else
            hi = mid;
    }
    t->work++; /* one look-up (its 2 log2 n probes not counted) */
    return lo > first ? &t->items[sorted[lo - 1].node] : NULL;
}

/* Link every node to its parent's list, a map's keys given twice to their first and every alias to its
 * anchor's node. */
static int link(reader *r) {
    cs_ytree *t = r->tree;
    if (t->count == 0) return 0;
    if (!(t->kid_store = calloc((size_t)t->count, sizeof *t->kid_store))) return -1; /* all but the root */
    for (int i = 1; i < t->count; i++)
        t->items[t->items[i].parent].count++;
    cs_ynode **next = t->kid_store;
    for (int i = 0; i < t->count; i++) {
        t->items[i].kids = next;
        next += t->items[i].count;
        t->items[i].count = 0;
    }
    for (int i = 1; i < t->count; i++) {
        cs_ynode *p = &t->items[t->items[i].parent];
        p->kids[p->count++] = &t->items[i];
    }
    for (int i = 0; i < t->count; i++)
        if (t->items[i].kind == CS_Y_MAP && mark_duplicates(t, &t->items[i]) != 0) return -1;
    if (r->anchor_count > 1) qsort(r->anchors, (size_t)r->anchor_count, sizeof *r->anchors, by_name);
    for (int i = 0; i < t->count; i++)
        if (t->items[i].kind == CS_Y_ALIAS)
            t->items[i].target = anchored(t, r->anchors, r->anchor_count, t->items[i].text, i);
    return 0;
}

int cs_ytree_read(cs_ytree *tree, const char *filename, const char *data, size_t size, int max_depth) {
    memset(tree, 0, sizeof *tree);
    reader r = {.tree = tree, .max_depth = max_depth < MAX_DEPTH ? max_depth : MAX_DEPTH};
    char *text = NULL;
    if (!data) { /* a regular file only, read whole: never a FIFO's or a device's wait */
        cs_error err;
        if (cs_input_load(filename, CS_INPUT_MAX, &text, &size, &tree->open_errno, &err) != CS_OK) {
            snprintf(tree->error, sizeof tree->error, "%.*s", (int)sizeof tree->error - 1, err.message);
            tree->unreadable = 1;
            return -1;
        }
        data = text;
    }
    yaml_parser_t parser;
    yaml_parser_initialize(&parser);
    yaml_parser_set_input_string(&parser, (const unsigned char *)data, size);
    read_events(&r, &parser);
    yaml_parser_delete(&parser);
    free(text);
    if (link(&r) != 0 && !tree->error[0]) snprintf(tree->error, sizeof tree->error, "out of memory");
    for (int a = 0; a < r.anchor_count; a++)
        free(r.anchors[a].name);
    free(r.anchors);
    return tree->error[0] ? -1 : 0;
}

void cs_ytree_free(cs_ytree *tree) {
    for (int i = 0; i < tree->count; i++) {
        free(tree->items[i].path);
        free(tree->items[i].key);
        free(tree->items[i].text);
    }
    free(tree->items);
    free(tree->kid_store);
    memset(tree, 0, sizeof *tree);
}

const cs_ynode *cs_ytree_find(const cs_ytree *tree, const char *path) {
    for (int i = 0; i < tree->count; i++)
        if (strcmp(tree->items[i].path, path) == 0) return &tree->items[i];
    return NULL;
}

const cs_ynode *cs_ynode_get_counted(const cs_ynode *map, const char *key, unsigned long *work) {
    if (!map || map->kind != CS_Y_MAP) return NULL;
    for (int i = 0; i < map->count; i++) {
        if (work) ++*work;
        if (strcmp(map->kids[i]->key, key) == 0) return map->kids[i];
    }
    return NULL;
}

const cs_ynode *cs_ynode_get(const cs_ynode *map, const char *key) {
    return cs_ynode_get_counted(map, key, NULL);
}

const cs_ynode *cs_ynode_value(const cs_ynode *n) {
    return n && n->kind == CS_Y_ALIAS ? n->target : n;
}

const char *cs_ykind_name(cs_ykind kind) {
    return kind == CS_Y_SCALAR ? "a single value"
           : kind == CS_Y_MAP  ? "a mapping"
           : kind == CS_Y_SEQ  ? "a list"
                               : "an alias";
}
