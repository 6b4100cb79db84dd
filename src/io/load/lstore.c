/* SPDX-License-Identifier: MIT */
/* The loader's store: the arena its nodes and texts live in, and the problems it records (each at its
 * file, line and column, or at the --set it comes from), sorted and worded for the user. */
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "loader_int.h"
#include "out/htmltext.h"

struct cs_chunk {
    struct cs_chunk *next;
    max_align_t data[];
};

void *cs_arena_alloc(cs_loader *l, size_t size) {
    struct cs_chunk *c = calloc(1, sizeof *c + size);
    if (!c) return NULL;
    c->next = l->arena;
    l->arena = c;
    return c->data;
}

char *cs_arena_strdup(cs_loader *l, const char *s) {
    size_t n = strlen(s) + 1;
    char *d = cs_arena_alloc(l, n);
    if (d) memcpy(d, s, n);
    return d;
}

void cs_arena_drop_to(cs_loader *l, struct cs_chunk *keep) {
    while (l->arena != keep) {
        struct cs_chunk *next = l->arena->next;
        free(l->arena);
        l->arena = next;
    }
}

/* ---- errors ---- */

static void add_error(cs_loader *l, int source, int line, int col, const char *fmt, va_list ap) {
    char msg[1024], where[600] = "";
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (source >= 0 && source < l->file_count)
        snprintf(where, sizeof where, "%s:%d:%d: ", l->files[source].name, line, col);
    else if (source < 0 && source != INT_MIN && -1 - source < l->set_count) {
        const cs_lset *set = &l->sets[-1 - source]; /* named as the user gave it */
        if (set->given)
            snprintf(where, sizeof where, "%s: ", set->given);
        else
            snprintf(where, sizeof where, "--set %s%s%s: ", set->path, set->bad ? "" : "=", set->value);
    }
    if (cs_grow(&l->errors, &l->error_capacity, l->error_count, sizeof *l->errors) != 0) return;
    size_t n = strlen(where) + strlen(msg) + 1;
    char *text = malloc(n);
    if (!text) return;
    snprintf(text, n, "%s%s", where, msg);
    /* a --set sorts after the files; a message with no place first */
    int key = source == INT_MIN ? -1 : source < 0 ? INT_MAX / 2 - source : source;
    l->errors[l->error_count] = (cs_lerror){key, line, col, l->error_count, text};
    l->error_count++;
    l->errors_sorted = 0;
}

void cs_err_at(cs_loader *l, int source, int line, int col, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    add_error(l, source, line, col, fmt, ap);
    va_end(ap);
}

void cs_err_node(cs_loader *l, const cs_node *at, int at_key, const char *fmt, ...) {
    char msg[900];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    int line = 1, col = 1;
    if (at->source >= 0) {
        const cs_ynode *p = at->at;
        if (p) {
            line = at_key ? p->key_line : p->line;
            col = at_key ? p->key_col : p->col;
        }
        size_t n = strlen(at->path);
        if (at->path[0] && !(strncmp(msg, at->path, n) == 0 && msg[n] == ':')) { /* the path once */
            cs_err_at(l, at->source, line, col, "%s: %s", at->path, msg);
            return;
        }
    }
    cs_err_at(l, at->source, line, col, "%s", msg);
}

void cs_field_hint(const cs_field *f, char *buf, size_t size) {
    const cs_quantity_info *q = cs_quantity_get(f->q);
    switch (f->kind) {
    case CS_F_QTY:
    case CS_F_LIST:
        if (f->q == CS_Q_NUMBER)
            snprintf(buf, size, "%s, e.g. %s", f->kind == CS_F_LIST ? "a list of numbers" : "a number",
                     q->example);
        else
            snprintf(buf, size, "%s%s, e.g. \"%s\"%s",
                     f->kind == CS_F_LIST          ? "a list of values of "
                     : strchr("aeiou", q->name[0]) ? "an "
                                                   : "a ",
                     q->name, q->example, f->flags & CS_NONE_OK ? " or none" : "");
        break;
    case CS_F_INT:
        snprintf(buf, size, "a whole number");
        break;
    case CS_F_ENUM: {
        size_t n = 0;
        buf[0] = '\0';
        for (int k = 0; f->words[k] && n < size; k++) {
            const char *sep = k == 0 ? "" : (f->words[k + 1] ? ", " : " or ");
            int w = snprintf(buf + n, size - n, "%s%s", sep, f->words[k]);
            n += w > 0 ? (size_t)w : 0;
        }
        break;
    }
    default:
        snprintf(buf, size, "text");
        break;
    }
}

static int error_order(const void *a, const void *b) {
    const cs_lerror *x = a, *y = b;
    if (x->source != y->source) return x->source < y->source ? -1 : 1;
    if (x->line != y->line) return x->line < y->line ? -1 : 1;
    if (x->col != y->col) return x->col < y->col ? -1 : 1;
    return (x->seq > y->seq) - (x->seq < y->seq);
}

/* Sort the problems by place and keep each once (a value used twice is wrong once). */
static void sort_errors(cs_loader *l) {
    if (l->errors_sorted) return;
    if (l->error_count > 1) /* none: errors may be NULL, which qsort must not be given */
        qsort(l->errors, (size_t)l->error_count, sizeof *l->errors, error_order);
    int kept = 0;
    for (int k = 0; k < l->error_count; k++) {
        if (kept > 0 && strcmp(l->errors[kept - 1].text, l->errors[k].text) == 0) {
            free(l->errors[k].text);
            continue;
        }
        l->errors[kept++] = l->errors[k];
    }
    l->error_count = kept;
    l->errors_sorted = 1;
}

int cs_loader_error_count(cs_loader *l) {
    sort_errors(l);
    return l->error_count;
}

const char *cs_loader_error(cs_loader *l, int i) {
    sort_errors(l);
    return i >= 0 && i < l->error_count ? l->errors[i].text : NULL;
}

void cs_loader_print_errors(cs_loader *l, FILE *out) {
    for (int i = 0; i < l->error_count; i++) {
        const char *e = cs_loader_error(l, i);
        if (e) cs_term_text(out, e), fputc('\n', out); /* a value echoed as the file gave it */
    }
}
