/* SPDX-License-Identifier: MIT */
/* Inside the loader: the node tree every file is turned into, the file table, errors. */
#ifndef CS_LOADER_INT_H
#define CS_LOADER_INT_H

#include <limits.h>
#include <stdarg.h>

#include "cablesim/loader.h"
#include "confine.h"
#include "schema.h"
#include "units.h"
#include "yamltree.h"

/* A value of a model: a scalar, a mapping of a schema table, or a sequence. */
typedef struct cs_node {
    cs_ykind kind;
    const cs_table *table;  /* CS_Y_MAP */
    const char *text;       /* CS_Y_SCALAR */
    struct cs_node **items; /* CS_Y_MAP: [table->count] (NULL: absent); CS_Y_SEQ: [count] */
    int count;
    int source;         /* file index, or -1 - k for the k-th --set */
    const char *path;   /* document path in that source */
    const cs_ynode *at; /* where it is written in that file (NULL: not in a file) */
} cs_node;

/* A named part of a file's list, for its index by name. */
typedef struct cs_named {
    const char *name;
    const struct cs_node *part;
    int order; /* its place in the list */
} cs_named;

typedef struct cs_lfile {
    char *name;       /* as given, for messages */
    char *real;       /* canonical path, to find it again */
    const char *data; /* its contents, when loaded from memory (NULL: read real) */
    size_t size;
    cs_ytree tree;         /* its YAML, each value with its place */
    cs_node *root;         /* NULL if it failed to load */
    int loading;           /* being loaded (a reference cycle if met again) */
    int referenced;        /* named by another model's file: its text is not echoed when it is not a model */
    int odd_line, odd_col; /* referenced and not a model: where it shows (0: it is one) */
    cs_named *named[CS_PART_KIND_COUNT]; /* its parts of each kind by name, then place (parts.c): made at
                                          * the first look in a loaded file (NULL: not yet) */
    int named_count[CS_PART_KIND_COUNT];
} cs_lfile;

typedef struct cs_lerror {
    int source, line, col, seq;
    char *text;
} cs_lerror;

typedef struct cs_lset {
    char *path, *value;
    char *given; /* the command-line option it stands for, as given ("--dt 2 ms"), or NULL: a --set */
    int bad;     /* not PATH=VALUE */
} cs_lset;

struct cs_loader {
    char data_dir[1024];
    char data_note[PATH_MAX + 64]; /* where data_dir came from (cs_data_dir_find), or why none was found */
    cs_units *units;
    cs_allow allow; /* folders the user allowed (cs_loader_allow_path): kept by cs_loader_reset */
    cs_allow scope; /* the folders this load's references may be in: allow's, the library's, the model's */
    struct cs_chunk *arena;
    struct cs_chunk *files_end; /* the newest allocation of a file read: cs_loader_reuse keeps up to it */
    cs_lfile *files;
    int file_count, file_capacity;
    int library_state; /* 0 not read, 1 read, -1 failed */
    int library_first, library_end;
    cs_lerror *errors;
    int error_count, error_capacity, errors_sorted;
    cs_lset *sets;
    int set_count, set_capacity;
    int depth;                   /* nesting of part and file references */
    const cs_node **post_origin; /* group node of each loaded post */
    const cs_node **cable_origin;
    const cs_node *vehicle_node, *scenario_node, *anchors_node, *soil_node;
    unsigned long work; /* the steps of its reading and lookups since it was made or reset: nodes read,
                         * built and checked, keys and names compared (a test's measure of its cost) */
};

/* The arena (lstore.c). */
void *cs_arena_alloc(cs_loader *l, size_t size); /* zeroed; NULL when out of memory */
char *cs_arena_strdup(cs_loader *l, const char *s);
/* Free the arena's allocations newer than keep (NULL: all). */
void cs_arena_drop_to(cs_loader *l, struct cs_chunk *keep);

/* Record a problem at a node (its key if at_key) or at a place in a file (source < 0: a --set). */
void cs_err_node(cs_loader *l, const cs_node *at, int at_key, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
void cs_err_at(cs_loader *l, int source, int line, int col, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
/* The expected-value hint of a field: "a length, e.g. \"8 ft\"". */
void cs_field_hint(const cs_field *f, char *buf, size_t size);

/* Read a file into the file table (once). Returns its index, or -1 (errors recorded at from). */
int cs_file_load(cs_loader *l, const char *path, const cs_node *from);
/* The same for contents held in memory under a name (files it refers to are found from its folder). */
int cs_data_load(cs_loader *l, const char *name, const char *data, size_t size);
/* Does the node's subtree in its file hold a key or value whose shape was reported wrong? */
int cs_damaged(const cs_node *n);
/* The field of a mapping node by key (NULL if absent). */
const cs_node *cs_node_get(const cs_node *map, const char *key);

/* References (parts.c). A copy of a node in the arena, its items' array copied too (NULL: no memory). */
cs_node *cs_node_clone(cs_loader *l, const cs_node *n);
/* The file a part is looked for from when no file names it: the model's (the first after the library
 * when the library was read first). */
int cs_main_file(const cs_loader *l);
/* The barrier, vehicle or scenario (key) of a model, node: a part name, or a mapping with file or part
 * underneath, resolved (NULL: an error recorded). */
const cs_node *cs_resolve_top(cs_loader *l, const cs_node *node, const char *key);
/* Resolve references of a file's model (vehicle/barrier/scenario) into a fresh root. */
cs_node *cs_resolve_model(cs_loader *l, int file);
/* The lists of parts: "vehicles", "ropes", "sections", "rails", by kind. */
extern const char *const cs_part_lists[CS_PART_KIND_COUNT];
/* A named part of a kind seen from a source, resolved. NULL if absent (an error recorded at from). */
const cs_node *cs_find_part(cs_loader *l, int source, cs_part_kind kind, const char *name,
                            const cs_node *from);
int cs_library_read(cs_loader *l);
/* The parts library's folder by the lookup order of datadir.c into dir, and in note where it came from
 * ("CABLESIM_DATA", "installed beside PATH", "the build tree's"). Returns 0, or -1 (dir empty) with note
 * saying where it looked. */
int cs_data_dir_find(char *dir, size_t size, char *note, size_t note_size);

/* Convert checked values into definition structs. Each returns the errors it recorded. */
int cs_convert_fields(cs_loader *l, const cs_node *map, void *target);
int cs_convert_vehicle(cs_loader *l, const cs_node *vehicle, cs_vehicle_def *out);
int cs_convert_rope(cs_loader *l, const cs_node *rope, cs_rope_def *out, double *diameter);
int cs_convert_model(cs_loader *l, const cs_node *root, const char *file, cs_model_input *out);

#endif
