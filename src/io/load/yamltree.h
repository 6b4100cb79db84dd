/* SPDX-License-Identifier: MIT */
/* The one YAML reader: a file as a tree of nodes, each with its kind, its text (a scalar's value), its key
 * in its mapping, its document path ("barrier.cables[0].height") and its line:column, from libyaml's
 * event stream read once. Model files (yamlload.c checks a tree against the schema and turns it into the
 * loader's nodes), the parts library and sweep specs (sweepspec.c) are all read through it. An alias
 * stays a node of its own that points at its anchor's node. */
#ifndef CS_YAMLTREE_H
#define CS_YAMLTREE_H

#include <stddef.h>

typedef enum cs_ykind { CS_Y_SCALAR, CS_Y_MAP, CS_Y_SEQ, CS_Y_ALIAS } cs_ykind;

typedef struct cs_ynode {
    char *path;
    char *key;  /* its key in the parent mapping (NULL: the root or a sequence item) */
    char *text; /* a scalar's value; an alias's anchor name */
    cs_ykind kind;
    int line, col;                /* of the value, 1-based */
    int key_line, key_col;        /* of its key in the parent mapping (= line, col for sequence items) */
    int end_line, end_col;        /* just past a scalar's value as written (its quotes included) */
    const struct cs_ynode *first; /* a key given twice: the node of its first place (NULL: the first) */
    int odd_key;                  /* its key is empty, 64 characters or longer, or holds '.', '[' or ']' */
    int bad;   /* its key or shape, or one under it, was reported wrong (set by the reader's user) */
    int count; /* mapping, sequence: its nodes, in file order */
    struct cs_ynode **kids;
    const struct cs_ynode *target; /* alias: the node its anchor named, NULL if no anchor of that name
                                    * was complete before it */
    int parent;                    /* its parent's index in the tree's items (-1: the root) */
} cs_ynode;

typedef struct cs_ytree {
    cs_ynode *items; /* every node in file order; items[0] is the root */
    int count, capacity;
    struct cs_ynode **kid_store;
    int error_line, error_col; /* YAML syntax error, if error[0] */
    int unreadable;            /* the file could not be read (error says why; no place in it) */
    int open_errno;            /* its errno, when the system refused it (0: cablesim refused it) */
    unsigned long work;        /* the reading's steps: nodes made, keys and anchors compared */
    char error[200];
} cs_ytree;

/* Read a file (data NULL) or a file's contents held in memory (size bytes), with collections nested at
 * most max_depth deep. Returns 0, or -1 with tree->error set (a syntax error, an unreadable file); the
 * nodes read before the error stay in the tree. Free it with cs_ytree_free in both cases. */
int cs_ytree_read(cs_ytree *tree, const char *filename, const char *data, size_t size, int max_depth);
void cs_ytree_free(cs_ytree *tree);
/* The first node at path ("" is the root), or NULL. */
const cs_ynode *cs_ytree_find(const cs_ytree *tree, const char *path);
/* The first node of a mapping with key, or NULL (also when map is NULL or not a mapping). */
const cs_ynode *cs_ynode_get(const cs_ynode *map, const char *key);
/* The same, adding the keys it compared to *work (the caller's count of its work; NULL: none). */
const cs_ynode *cs_ynode_get_counted(const cs_ynode *map, const char *key, unsigned long *work);
/* An alias's anchored node (NULL if none); any other node itself. */
const cs_ynode *cs_ynode_value(const cs_ynode *n);
/* "a single value", "a mapping", "a list" or "an alias": a kind in messages. */
const char *cs_ykind_name(cs_ykind kind);

#endif
