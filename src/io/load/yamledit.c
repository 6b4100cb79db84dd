/* SPDX-License-Identifier: MIT */
#include "yamledit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "status.h"
#include "yamltree.h"

typedef struct edit {
    size_t from, to; /* the value's bytes in the text */
    const char *value;
    size_t value_len;
    const char *path;
    size_t path_len;
} edit;

/* The byte offset of 1-based line and column (libyaml counts characters), or (size_t)-1. */
static size_t offset_of(const char *text, size_t size, int line, int col) {
    size_t i = 0;
    for (int l = 1; l < line; l++) {
        const char *nl = memchr(text + i, '\n', size - i);
        if (!nl) return (size_t)-1;
        i = (size_t)(nl - text) + 1;
    }
    for (int c = 1; c < col; c++) {
        if (i >= size || text[i] == '\n') return (size_t)-1;
        i++;
        while (i < size && ((unsigned char)text[i] & 0xC0) == 0x80) /* a UTF-8 continuation byte */
            i++;
    }
    return i;
}

/* Whether s reads back as itself when written plain, in a block or a flow collection. */
static int plain_ok(const char *s, size_t n) {
    if (n == 0 || s[0] == ' ' || s[n - 1] == ' ' || strchr("-?:!&*#|>'\"%@`", s[0])) return 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c < 0x20 || c >= 0x7F || strchr(",[]{}#\"'\\", c)) return 0;
        if (c == ':' && (i + 1 == n || s[i + 1] == ' ')) return 0;
    }
    return 1;
}

/* The value as YAML into buf (plain or double-quoted). Returns its length, or -1 if it does not fit. */
static int write_value(char *buf, size_t cap, const char *s, size_t n) {
    if (plain_ok(s, n)) return n < cap ? (memcpy(buf, s, n), buf[n] = '\0', (int)n) : -1;
    size_t k = 0;
    buf[k++] = '"';
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if (k + 7 >= cap) return -1;
        if (c == '"' || c == '\\')
            buf[k++] = '\\', buf[k++] = (char)c;
        else if (c < 0x20)
            k += (size_t)snprintf(buf + k, cap - k, "\\x%02x", c);
        else
            buf[k++] = (char)c;
    }
    buf[k++] = '"';
    buf[k] = '\0';
    return (int)k;
}

static int by_offset(const void *a, const void *b) {
    const edit *x = a, *y = b;
    return x->from < y->from ? -1 : x->from > y->from;
}

/* Find each set's value in the tree of text into edits. CS_OK, or CS_ERR_INVALID with err filled. */
static cs_status locate(const cs_ytree *t, const char *text, size_t size, const char *const *sets, int count,
                        edit *edits, cs_error *err) {
    for (int i = 0; i < count; i++) {
        const char *eq = strchr(sets[i], '=');
        if (!eq || eq == sets[i]) {
            return cs_error_set(err, CS_ERR_INVALID, "'%s' is not PATH=VALUE", sets[i]);
        }
        char path[512];
        size_t plen = (size_t)(eq - sets[i]);
        if (plen >= sizeof path) {
            return cs_error_set(err, CS_ERR_INVALID, "the path of '%.40s...' is too long", sets[i]);
        }
        memcpy(path, sets[i], plen);
        path[plen] = '\0';
        const cs_ynode *n = cs_ytree_find(t, path);
        if (!n || n->kind != CS_Y_SCALAR) {
            return cs_error_set(err, CS_ERR_INVALID, "%s is not a single value written in the file", path);
        }
        edit *e = &edits[i];
        *e = (edit){offset_of(text, size, n->line, n->col),
                    offset_of(text, size, n->end_line, n->end_col),
                    eq + 1,
                    strlen(eq + 1),
                    sets[i],
                    plen};
        if (e->from == (size_t)-1 || e->to == (size_t)-1 || e->to < e->from) {
            return cs_error_set(err, CS_ERR_INVALID, "%s: its place in the file is not found", path);
        }
    }
    qsort(edits, (size_t)count, sizeof *edits, by_offset);
    for (int i = 1; i < count; i++)
        if (edits[i].from < edits[i - 1].to) {
            return cs_error_set(err, CS_ERR_INVALID, "%.*s is set twice", (int)edits[i].path_len,
                                edits[i].path);
        }
    return CS_OK;
}

/* Read back: every edited path holds its value. CS_OK, or CS_ERR_INVALID with err filled. */
static cs_status check(const char *text, size_t size, const edit *edits, int count, cs_error *err) {
    cs_ytree t = {0};
    cs_status rc = cs_ytree_read(&t, NULL, text, size, 64) == 0 ? CS_OK : CS_ERR_INVALID;
    for (int i = 0; rc == CS_OK && i < count; i++) {
        char path[512];
        snprintf(path, sizeof path, "%.*s", (int)edits[i].path_len, edits[i].path);
        const cs_ynode *n = cs_ytree_find(&t, path);
        if (!n || n->kind != CS_Y_SCALAR || strlen(n->text) != edits[i].value_len ||
            memcmp(n->text, edits[i].value, edits[i].value_len) != 0) {
            rc = cs_error_set(err, CS_ERR_INVALID, "%s does not read back as '%.*s'", path,
                              (int)edits[i].value_len, edits[i].value);
        }
    }
    if (rc != CS_OK && t.error[0])
        cs_error_set(err, CS_ERR_INVALID, "the edited file does not read: %s", t.error);
    cs_ytree_free(&t);
    return rc;
}

char *cs_yaml_edit(const char *text, size_t size, const char *const *sets, int count, size_t *out_size,
                   cs_error *err) {
    cs_ytree t = {0};
    edit *edits = calloc((size_t)(count > 0 ? count : 1), sizeof *edits);
    char *out = NULL;
    if (!edits) {
        cs_out_of_memory(err);
        return NULL;
    }
    if (cs_ytree_read(&t, NULL, text, size, 64) != 0) {
        cs_error_set(err, CS_ERR_INVALID, "%d:%d: %s", t.error_line, t.error_col, t.error);
    } else if (locate(&t, text, size, sets, count, edits, err) == CS_OK) {
        size_t cap = size + 1;
        for (int i = 0; i < count; i++)
            cap += edits[i].value_len * 4 + 2;
        if ((out = malloc(cap))) {
            size_t k = 0, at = 0;
            for (int i = 0; i < count && out; i++) {
                memcpy(out + k, text + at, edits[i].from - at);
                k += edits[i].from - at;
                int n = write_value(out + k, cap - k, edits[i].value, edits[i].value_len);
                if (n < 0) {
                    cs_error_set(err, CS_ERR_MEMORY, "no room for a value");
                    free(out), out = NULL;
                } else {
                    k += (size_t)n;
                    at = edits[i].to;
                }
            }
            if (out) {
                memcpy(out + k, text + at, size - at);
                k += size - at;
                out[k] = '\0';
                *out_size = k;
                if (check(out, k, edits, count, err) != CS_OK) free(out), out = NULL;
            }
        } else {
            cs_out_of_memory(err);
        }
    }
    cs_ytree_free(&t);
    free(edits);
    return out;
}
