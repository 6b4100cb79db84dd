/* SPDX-License-Identifier: MIT */
/* The loader's context: memory, errors, file references, parts, --set overrides. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "loader_int.h"
#include "status.h"

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
    if (!(l->units = cs_units_open(err))) {
        free(l);
        return NULL;
    }
    cs_status_set(err, CS_OK, "");
    return l;
}

cs_status cs_loader_allow_path(cs_loader *l, const char *dir, cs_error *err) {
    cs_status rc = cs_allow_add(&l->allow, dir, err);
    return rc == CS_OK ? cs_status_set(err, CS_OK, "") : rc;
}

const char *cs_loader_data_dir(const cs_loader *l) {
    return l->data_dir;
}

/* Free the overrides' texts (the array stays for the next ones). */
static void drop_sets(cs_loader *l) {
    for (int i = 0; i < l->set_count; i++) {
        free(l->sets[i].path);
        free(l->sets[i].value);
        free(l->sets[i].given);
    }
    l->set_count = 0;
}

void cs_loader_reset(cs_loader *l) {
    for (int i = 0; i < l->file_count; i++) {
        cs_ytree_free(&l->files[i].tree);
        for (int k = 0; k < CS_PART_KIND_COUNT; k++)
            free(l->files[i].named[k]);
    }
    free(l->files);
    for (int i = 0; i < l->error_count; i++)
        free(l->errors[i].text);
    free(l->errors);
    drop_sets(l);
    free(l->sets);
    cs_arena_drop_to(l, NULL);
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
    cs_arena_drop_to(l, l->files_end); /* the files' nodes are older; nothing of theirs points later */
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

/* ---- --set ---- */

cs_status cs_loader_set(cs_loader *l, const char *assignment) {
    return cs_loader_set_given(l, assignment, NULL);
}

cs_status cs_loader_set_given(cs_loader *l, const char *assignment, const char *given) {
    const char *eq = strchr(assignment, '=');
    if (cs_grow(&l->sets, &l->set_capacity, l->set_count, sizeof *l->sets) != 0) return CS_ERR_MEMORY;
    size_t n = eq ? (size_t)(eq - assignment) : strlen(assignment);
    cs_lset *s = &l->sets[l->set_count];
    s->path = malloc(n + 1);
    s->value = strdup(eq ? eq + 1 : "");
    s->given = given ? strdup(given) : NULL;
    if (!s->path || !s->value || (given && !s->given)) {
        free(s->path);
        free(s->value);
        free(s->given);
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
        cs_node *n = cs_node_clone(l, *ref);
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
            if (*ref && f->kind == CS_F_PART) *ref = (cs_node *)cs_resolve_top(l, *ref, f->key);
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
    char dir[PATH_MAX];
    const char *slash = strrchr(name, '/');
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - name) + 1 : 1, slash ? name : ".");
    cs_allow_free(&l->scope);
    cs_allow_copy(&l->scope, &l->allow);
    if (l->data_dir[0]) cs_allow_add(&l->scope, l->data_dir, NULL);
    cs_allow_add(&l->scope, dir, NULL); /* none: the file's own load reports why */
}

static int load(cs_loader *l, int f, cs_model_input *out) {
    cs_node *root = f >= 0 ? cs_resolve_model(l, f) : NULL;
    for (int k = 0; root && k < l->set_count; k++)
        if (!l->sets[k].bad) apply_set(l, &root, k);
    if (root) cs_convert_model(l, root, l->files[f].name, out);
    return l->error_count ? -1 : 0;
}

/* Hand a load's model (rc its result) back at the caller's size, recording why if the size is refused. */
static cs_status hand_back(cs_loader *l, int rc, const cs_model_input *full, cs_model_input *out) {
    cs_error err;
    if (cs_status_put_sized(out, full, sizeof *full, "cs_model_input", &err) != CS_OK) {
        cs_err_at(l, INT_MIN, 0, 0, "%s", err.message);
        return CS_ERR_INVALID;
    }
    return rc ? CS_ERR_INVALID : CS_OK;
}

cs_status cs_loader_load(cs_loader *l, const char *path, cs_model_input *out) {
    cs_model_input full = {.size = sizeof full};
    set_scope(l, path);
    return hand_back(l, load(l, cs_file_load(l, path, NULL), &full), &full, out);
}

cs_status cs_loader_load_buffer(cs_loader *l, const char *name, const char *data, size_t size,
                                cs_model_input *out) {
    cs_model_input full = {.size = sizeof full};
    set_scope(l, name);
    return hand_back(l, load(l, cs_data_load(l, name, data, size), &full), &full, out);
}

/* ---- the library ---- */

int cs_loader_library(cs_loader *l, cs_part_kind kind, const char ***names, const char ***descriptions) {
    if (cs_library_read(l) != 0) return -1;
    int count = 0;
    for (int pass = 0; pass < 2; pass++) {
        int n = 0;
        for (int f = l->library_first; f < l->library_end; f++) {
            const cs_node *seq = cs_node_get(cs_node_get(l->files[f].root, "parts"), cs_part_lists[kind]);
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
    const cs_node *part = cs_find_part(l, cs_main_file(l), kind, name, &at);
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

/* Within the element's node, the value the message names, where its words are a key ("cable 0: post friction
 * must be ..." is post_friction), or the element's node. */
static const cs_node *engine_value(const cs_node *place, const char *msg) {
    const char *from = strstr(msg, ": "), *to = from ? strstr(from, " must ") : NULL;
    char key[48];
    if (!place || place->kind != CS_Y_MAP || !to || (size_t)(to - from - 2) >= sizeof key) return place;
    size_t n = (size_t)(to - from - 2);
    for (size_t k = 0; k < n; k++)
        key[k] = from[2 + k] == ' ' ? '_' : from[2 + k];
    key[n] = '\0';
    const cs_node *value = cs_table_find(place->table, key) >= 0 ? cs_node_get(place, key) : NULL;
    return value ? value : place;
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
    if (cs_status_input(in, &err) != CS_OK) return cs_err_at(l, INT_MIN, 0, 0, "%s", err.message), NULL;
    cs_model *m = cs_model_create(&in->barrier, &in->vehicle, &in->scenario, &err);
    if (m) return m;
    long i = -1;
    int soil = strstr(err.message, "soil") != NULL;
    int w = engine_element(err.message, &i), set = w >= 0 ? engine_set(l, w, i, soil) : -1;
    const cs_node *place = soil && l->soil_node ? l->soil_node
                           : w >= 0             ? engine_value(engine_place(l, in, w, i), err.message)
                                                : NULL;
    if (set >= 0)
        cs_err_at(l, -1 - set, 0, 0, "%s (the engine's check of the model)", err.message);
    else if (place)
        cs_err_node(l, place, 0, "%s (the engine's check of the model)", err.message);
    else
        cs_err_at(l, 0, 1, 1, "%s (the engine's check of the model)", err.message);
    return NULL;
}
