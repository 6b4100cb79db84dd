/* Where each node of a YAML file is: a list of document paths ("barrier.cables[0].height") with their
 * kind and line:column, made from libyaml's event stream. Used for messages and to check a file's
 * shape against the schema before libcyaml loads it; the values themselves come from libcyaml. */
#ifndef CS_YAMLPOS_H
#define CS_YAMLPOS_H

#include <stddef.h>

typedef enum cs_ykind { CS_Y_SCALAR, CS_Y_MAP, CS_Y_SEQ, CS_Y_ALIAS } cs_ykind;

typedef struct cs_ypos {
    char *path;
    cs_ykind kind;
    int line, col;         /* of the value, 1-based */
    int key_line, key_col; /* of its key in the parent mapping (= line, col for sequence items) */
    int duplicate;         /* the key occurs earlier in the same mapping */
    int odd_key;           /* its key is empty, 64 characters or longer, or holds '.', '[' or ']' */
    int bad;               /* its key or shape was reported wrong */
} cs_ypos;

typedef struct cs_yposmap {
    cs_ypos *items;
    int count, capacity;
    int error_line, error_col; /* YAML syntax error, if error[0] */
    char error[200];
} cs_yposmap;

/* Read the file. Returns 0, or -1 with map->error set (syntax error or unreadable file). */
int cs_yposmap_read(cs_yposmap *map, const char *filename);
/* The same for a file's contents held in memory. */
int cs_yposmap_read_data(cs_yposmap *map, const char *data, size_t size);
void cs_yposmap_free(cs_yposmap *map);
/* The node at path ("" is the root), or NULL. */
const cs_ypos *cs_yposmap_find(const cs_yposmap *map, const char *path);

#endif
