/* SPDX-License-Identifier: MIT */
/* References between a model's files and parts: the parts library (the YAML files of data/), a part
 * found by name from a file (its own parts first, then the library's), a part built on another
 * (`part:`), and a model's barrier, vehicle and scenario resolved from a part or another file. */
#include <dirent.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "loader_int.h"

enum { MAX_DEPTH = 16 };

cs_node *cs_node_clone(cs_loader *l, const cs_node *n) {
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
    cs_node *n = cs_node_clone(l, local);
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

const char *const cs_part_lists[CS_PART_KIND_COUNT] = {"vehicles", "ropes", "sections", "rails"};

static int by_name(const void *a, const void *b) {
    const cs_named *x = a, *y = b;
    int c = strcmp(x->name, y->name);
    return c ? c : (x->order > y->order) - (x->order < y->order);
}

/* A loaded file's parts of a kind sorted by name, then place, made once: a model naming n parts among m
 * costs m log m + n log m, not n m. 0, or -1 when memory is short. */
static int index_parts(cs_loader *l, cs_lfile *lf, cs_part_kind kind) {
    const cs_node *seq = cs_node_get(cs_node_get(lf->root, "parts"), cs_part_lists[kind]);
    int n = 0;
    cs_named *named = malloc(((size_t)(seq ? seq->count : 0) + 1) * sizeof *named);
    if (!named) return -1;
    for (int i = 0; seq && i < seq->count; i++, l->work++) {
        const cs_node *nm = cs_node_get(seq->items[i], "name");
        if (nm) named[n++] = (cs_named){nm->text, seq->items[i], i};
    }
    qsort(named, (size_t)n, sizeof *named, by_name);
    lf->named[kind] = named;
    lf->named_count[kind] = n;
    return 0;
}

/* The first part of a kind named name in a file's list, or NULL. */
static const cs_node *find_in_file(cs_loader *l, int file, cs_part_kind kind, const char *name) {
    if (file < 0 || file >= l->file_count || !l->files[file].root) return NULL;
    cs_lfile *lf = &l->files[file];
    if (!lf->named[kind] && index_parts(l, lf, kind) != 0) return NULL;
    int lo = 0, hi = lf->named_count[kind];
    while (lo < hi) { /* the first of name or after it */
        int mid = lo + (hi - lo) / 2;
        if (strcmp(lf->named[kind][mid].name, name) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    l->work++; /* one look-up (its log2 n probes not counted) */
    return lo < lf->named_count[kind] && strcmp(lf->named[kind][lo].name, name) == 0
               ? lf->named[kind][lo].part
               : NULL;
}

static void part_names(const cs_loader *l, int file, cs_part_kind kind, char *buf, size_t size) {
    size_t n = 0;
    buf[0] = '\0';
    for (int f = 0; f < l->file_count && n < size; f++) {
        if (f != file && (f < l->library_first || f >= l->library_end)) continue;
        const cs_node *seq = cs_node_get(cs_node_get(l->files[f].root, "parts"), cs_part_lists[kind]);
        for (int i = 0; seq && i < seq->count && n < size; i++) {
            const cs_node *nm = cs_node_get(seq->items[i], "name");
            if (nm) n += (size_t)snprintf(buf + n, size - n, "%s%s", n ? ", " : "", nm->text);
        }
    }
}

int cs_main_file(const cs_loader *l) {
    return l->library_state && l->library_first == 0 ? l->library_end : 0;
}

const cs_node *cs_find_part(cs_loader *l, int source, cs_part_kind kind, const char *name,
                            const cs_node *from) {
    int file = source >= 0 ? source : cs_main_file(l);
    const cs_node *found = find_in_file(l, file, kind, name);
    cs_library_read(l);
    for (int f = l->library_first; !found && f < l->library_end; f++)
        found = find_in_file(l, f, kind, name);
    if (!found) {
        const char *list = cs_part_lists[kind];
        char names[600];
        part_names(l, file, kind, names, sizeof names);
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
    const cs_node *base = cs_find_part(l, found->source, kind, base_name->text, base_name);
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

const cs_node *cs_resolve_top(cs_loader *l, const cs_node *node, const char *key) {
    if (node->kind == CS_Y_SCALAR) return cs_find_part(l, node->source, CS_PART_VEHICLE, node->text, node);
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
        base = cs_find_part(l, part->source, CS_PART_VEHICLE, part->text, part);
    } else if (file) {
        char path[PATH_MAX];
        relative_to(node->source >= 0 ? l->files[node->source].real : ".", file->text, path, sizeof path);
        int g = cs_file_load(l, path, file);
        const cs_node *theirs = g >= 0 ? cs_node_get(l->files[g].root, key) : NULL;
        if (g >= 0 && !theirs)
            cs_err_node(l, file, 0, "'%s' has no %s (expected a file with a %s)", file->text, key, key);
        base = theirs ? cs_resolve_top(l, theirs, key) : NULL;
    }
    l->depth--;
    if ((file || part) && !base) return NULL;
    return base ? merge(l, node, base) : node;
}

static const char *const top_keys[] = {"barrier", "vehicle", "scenario"};

cs_node *cs_resolve_model(cs_loader *l, int file) {
    cs_node *root = cs_node_clone(l, l->files[file].root);
    int ok = root != NULL;
    for (size_t k = 0; ok && k < sizeof top_keys / sizeof top_keys[0]; k++) {
        int i = cs_table_find(&cs_table_model, top_keys[k]);
        if (root->items[i] && !(root->items[i] = (cs_node *)cs_resolve_top(l, root->items[i], top_keys[k])))
            ok = 0;
    }
    return ok ? root : NULL;
}
