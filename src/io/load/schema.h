/* SPDX-License-Identifier: MIT */
/* The model-file schema: one table per YAML mapping, each field with its kind, quantity, checks, the
 * definition-struct member it fills and its documentation. The loader's shape check, its nodes, the
 * --set paths, the JSON echo of the inputs and docs/file-format.md all come from these tables. */
#ifndef CS_SCHEMA_H
#define CS_SCHEMA_H

#include <stddef.h>
#include <stdio.h>

#include "cablesim/def.h"
#include "units.h"

typedef enum cs_fkind {
    CS_F_QTY,  /* a quantity with a unit: "8 ft" */
    CS_F_INT,  /* a whole number */
    CS_F_TEXT, /* text or a part name */
    CS_F_ENUM, /* one of the field's words */
    CS_F_LIST, /* a list of quantities */
    CS_F_MAP,  /* a nested mapping (sub table) */
    CS_F_SEQ,  /* a list of mappings (sub table) */
    CS_F_PART  /* the name of a part, or a mapping (sub table) */
} cs_fkind;

enum cs_fflag {
    CS_REQ = 1u << 0,     /* must be given (after files and parts are merged) */
    CS_POS = 1u << 1,     /* > 0 */
    CS_NONNEG = 1u << 2,  /* >= 0 */
    CS_MAX1 = 1u << 3,    /* <= 1 */
    CS_NONE_OK = 1u << 4, /* "none": no limit (stored as infinity) */
    CS_MAX90 = 1u << 5,   /* an angle up to 90 deg */
    CS_MAX180 = 1u << 6,  /* an angle below 180 deg */
    CS_OWN = 1u << 7,     /* a map of a part's own values where not its parent's (a cable end's fitting):
                             not given (its enums < 0, its numbers 0), left out of the hash and the echo */
    CS_NEW0 = 1u << 8     /* a number added later, 0 by default: left out of the model's hash at 0, so that
                             a model that does not give it keeps its hash */
};

typedef enum cs_target {
    CS_T_NONE = 0,
    CS_T_VEHICLE,
    CS_T_ROPE,
    CS_T_SECTION,
    CS_T_CABLE,
    CS_T_POST,
    CS_T_FOOTING,
    CS_T_ANCHOR,
    CS_T_RAIL,
    CS_T_BARRIER,
    CS_T_SCENARIO
} cs_target;

typedef struct cs_table cs_table;

typedef struct cs_field {
    const char *key;
    cs_fkind kind;
    cs_quantity q;
    unsigned flags;
    long offset; /* member of the table's target struct (for MAP: the sub struct), or -1 */
    const cs_table *sub;
    const char *const *words; /* CS_F_ENUM: NULL-terminated */
    const char *doc;
} cs_field;

struct cs_table {
    const char *name;
    const char *doc;
    cs_target target;
    const cs_field *fields;
    int count;
};

/* Any definition struct, for defaults and generic field access. */
typedef union cs_any_def {
    cs_vehicle_def vehicle;
    cs_rope_def rope;
    cs_section_def section;
    cs_cable_def cable;
    cs_post_def post;
    cs_footing_def footing;
    cs_anchor_def anchor;
    cs_rail_def rail;
    cs_barrier_def barrier;
    cs_scenario_def scenario;
} cs_any_def;

extern const cs_table cs_table_model, cs_table_parts, cs_table_vehicle, cs_table_box, cs_table_rope,
    cs_table_section, cs_table_barrier, cs_table_soil, cs_table_cable, cs_table_cable_end, cs_table_posts,
    cs_table_footing, cs_table_anchors, cs_table_anchor, cs_table_rail_part, cs_table_rail, cs_table_scenario;

/* The range of a physical value, in SI: its size at most hi and, where it is not 0, at least lo. Each is an
 * assumption (docs/assumptions.md, "Ranges of the inputs"), wide: only a value that no barrier, vehicle
 * or run can have is refused. basis says what bounds it. */
typedef struct cs_range {
    double lo, hi;
    const char *basis;
} cs_range;

/* The range of a quantity field: its own, else its quantity's. */
const cs_range *cs_field_range(const cs_field *f);

/* 1 if f is a CS_OWN map that gives nothing at at (its values are its parent's). */
int cs_field_unset(const cs_field *f, const void *at);
/* The index of key in t, or -1. */
int cs_table_find(const cs_table *t, const char *key);

/* ---- model paths ("barrier.cables[0].height"): of --set, of sweep specs, of a file's values ---- */

/* Split the next component off a path: 1 key, 2 [index], 0 end, -1 malformed. */
int cs_path_next(const char **p, char *key, size_t key_size, long *index);

typedef enum cs_path_fault {
    CS_PATH_OK = 0,      /* every component walks the schema */
    CS_PATH_UNKNOWN_KEY, /* a key not in its table (or after a single value: no table) */
    CS_PATH_NEEDS_INDEX, /* a key right after a list of mappings, with no [index] between */
    CS_PATH_NO_LIST,     /* an [index] after what is not a list */
    CS_PATH_MALFORMED    /* not keys and [index] */
} cs_path_fault;

/* Where a path leads in the schema, as far as it walks it. */
typedef struct cs_schema_place {
    const cs_field *field; /* the field whose value the path names (NULL: the whole model) */
    int item;              /* an entry of that field's list */
    char skey[256];        /* the schema path: "barrier.cables.height" */
    cs_path_fault fault;
    int last;              /* the fault is at the path's last component */
    const cs_table *table; /* CS_PATH_UNKNOWN_KEY: the table without the key (NULL: none) */
    char key[64];          /* CS_PATH_UNKNOWN_KEY, CS_PATH_NEEDS_INDEX: that key */
    long index;            /* CS_PATH_NO_LIST: that index */
} cs_schema_place;

/* Walk the schema along a path. */
void cs_schema_walk(const char *path, cs_schema_place *out);
/* The word a model file gives a post's attachment or a cable's termination by ("through", "clips"); "?"
 * for a value that has none. */
const char *cs_attachment_word(cs_attachment kind);
const char *cs_face_word(cs_face face);
const char *cs_termination_word(cs_termination kind);
const char *cs_width_scaling_word(cs_width_scaling kind);
/* Print the file-format reference (docs/file-format.md). Returns 0 or -1 on a write error. */
int cs_schema_markdown(FILE *out);

#endif
