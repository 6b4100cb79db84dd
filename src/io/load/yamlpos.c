#define _POSIX_C_SOURCE 200809L
#include "yamlpos.h"

#include "grow.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

enum { MAX_DEPTH = 64 };

typedef struct frame {
    cs_ykind kind;
    char *path;
    int index;    /* next sequence index */
    int want_key; /* mapping: the next node is a key */
    char *key;    /* mapping: the current key */
    yaml_mark_t key_mark;
} frame;

static int add(cs_yposmap *map, char *path, cs_ykind kind, yaml_mark_t at, yaml_mark_t key_at) {
    if (cs_grow(&map->items, &map->capacity, map->count, sizeof *map->items) != 0) return -1;
    int duplicate = cs_yposmap_find(map, path) != NULL;
    map->items[map->count++] = (cs_ypos){path,
                                         kind,
                                         (int)at.line + 1,
                                         (int)at.column + 1,
                                         (int)key_at.line + 1,
                                         (int)key_at.column + 1,
                                         duplicate,
                                         0,
                                         0};
    return 0;
}

static char *child_path(const frame *parent) {
    size_t n = strlen(parent->path) + (parent->key ? strlen(parent->key) : 0) + 24;
    char *p = malloc(n);
    if (!p) return NULL;
    if (parent->kind == CS_Y_SEQ)
        snprintf(p, n, "%s[%d]", parent->path, parent->index);
    else
        snprintf(p, n, "%s%s%s", parent->path, parent->path[0] ? "." : "", parent->key);
    return p;
}

static void fail(cs_yposmap *map, const char *what, yaml_mark_t at) {
    snprintf(map->error, sizeof map->error, "%s", what);
    map->error_line = (int)at.line + 1;
    map->error_col = (int)at.column + 1;
}

/* Handle one node event: a mapping key, or a value recorded at its path. Returns the new node's
 * frame path for a collection start (owned by the map), "" for others, NULL on failure. */
static const char *node(cs_yposmap *map, frame *stack, int depth, const yaml_event_t *ev, cs_ykind kind) {
    frame *parent = depth > 0 ? &stack[depth - 1] : NULL;
    if (parent && parent->kind == CS_Y_MAP && parent->want_key) {
        if (ev->type != YAML_SCALAR_EVENT) {
            fail(map, "a mapping key must be a plain word", ev->start_mark);
            return NULL;
        }
        free(parent->key);
        parent->key = strdup((const char *)ev->data.scalar.value);
        parent->key_mark = ev->start_mark;
        parent->want_key = 0;
        return parent->key ? "" : NULL;
    }
    char *path = parent ? child_path(parent) : strdup("");
    if (!path) return NULL;
    yaml_mark_t key_at = parent && parent->kind == CS_Y_MAP ? parent->key_mark : ev->start_mark;
    if (add(map, path, kind, ev->start_mark, key_at) != 0) {
        free(path);
        return NULL;
    }
    if (parent && parent->kind == CS_Y_MAP) {
        const char *k = parent->key;
        map->items[map->count - 1].odd_key = !k[0] || strlen(k) >= 64 || strpbrk(k, ".[]") != NULL;
        parent->want_key = 1;
    }
    if (parent && parent->kind == CS_Y_SEQ) parent->index++;
    return path;
}

/* Read the events of a parser whose input is set. */
static int read_events(cs_yposmap *map, yaml_parser_t *parser) {
    frame stack[MAX_DEPTH];
    int depth = 0, done = 0, docs = 0;
    while (!done && !map->error[0]) {
        yaml_event_t ev;
        if (!yaml_parser_parse(parser, &ev)) {
            snprintf(map->error, sizeof map->error, "YAML syntax: %s%s%s",
                     parser->problem ? parser->problem : "error", parser->context ? " " : "",
                     parser->context ? parser->context : "");
            map->error_line = (int)parser->problem_mark.line + 1;
            map->error_col = (int)parser->problem_mark.column + 1;
            break;
        }
        const char *path = "";
        switch (ev.type) {
        case YAML_STREAM_END_EVENT:
            done = 1;
            break;
        case YAML_DOCUMENT_START_EVENT:
            if (++docs > 1) fail(map, "only one YAML document per file", ev.start_mark);
            break;
        case YAML_SCALAR_EVENT:
            path = node(map, stack, depth, &ev, CS_Y_SCALAR);
            break;
        case YAML_ALIAS_EVENT:
            path = node(map, stack, depth, &ev, CS_Y_ALIAS);
            break;
        case YAML_MAPPING_START_EVENT:
        case YAML_SEQUENCE_START_EVENT: {
            cs_ykind kind = ev.type == YAML_MAPPING_START_EVENT ? CS_Y_MAP : CS_Y_SEQ;
            path = node(map, stack, depth, &ev, kind);
            if (path && depth == MAX_DEPTH)
                fail(map, "nested too deeply", ev.start_mark);
            else if (path)
                stack[depth++] = (frame){kind, (char *)path, 0, 1, NULL, ev.start_mark};
            break;
        }
        case YAML_MAPPING_END_EVENT:
        case YAML_SEQUENCE_END_EVENT:
            free(stack[--depth].key);
            break;
        default:
            break;
        }
        if (!path && !map->error[0]) fail(map, "out of memory", ev.start_mark);
        yaml_event_delete(&ev);
    }
    while (depth > 0)
        free(stack[--depth].key);
    return map->error[0] ? -1 : 0;
}

int cs_yposmap_read(cs_yposmap *map, const char *filename) {
    memset(map, 0, sizeof *map);
    FILE *f = fopen(filename, "rb");
    if (!f) {
        snprintf(map->error, sizeof map->error, "cannot open the file");
        return -1;
    }
    yaml_parser_t parser;
    yaml_parser_initialize(&parser);
    yaml_parser_set_input_file(&parser, f);
    int rc = read_events(map, &parser);
    yaml_parser_delete(&parser);
    fclose(f);
    return rc;
}

int cs_yposmap_read_data(cs_yposmap *map, const char *data, size_t size) {
    memset(map, 0, sizeof *map);
    yaml_parser_t parser;
    yaml_parser_initialize(&parser);
    yaml_parser_set_input_string(&parser, (const unsigned char *)data, size);
    int rc = read_events(map, &parser);
    yaml_parser_delete(&parser);
    return rc;
}

void cs_yposmap_free(cs_yposmap *map) {
    for (int i = 0; i < map->count; i++)
        free(map->items[i].path);
    free(map->items);
    memset(map, 0, sizeof *map);
}

const cs_ypos *cs_yposmap_find(const cs_yposmap *map, const char *path) {
    for (int i = 0; i < map->count; i++)
        if (strcmp(map->items[i].path, path) == 0) return &map->items[i];
    return NULL;
}
