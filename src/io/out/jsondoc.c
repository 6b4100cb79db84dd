/* SPDX-License-Identifier: MIT */
/* JSON documents with json-c (jsondoc.h). */
#include "jsondoc.h"

#include <json-c/printbuf.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "numtext.h"

enum { FLAGS = JSON_C_TO_STRING_PLAIN | JSON_C_TO_STRING_NOSLASHESCAPE };

json_object *cs_jnum(double v) {
    if (!isfinite(v)) return NULL;
    char text[CS_G10_SIZE];
    cs_g10(v, text);
    return json_object_new_double_s(v, text);
}

/* A list of numbers (cs_jnums): its length, digits and whether NaN is null, and the numbers. */
typedef struct numbers {
    int n, digits, nan_null;
    double v[];
} numbers;

static int numbers_text(json_object *jso, struct printbuf *pb, int level, int flags) {
    (void)level, (void)flags;
    const numbers *l = json_object_get_userdata(jso);
    if (printbuf_memappend(pb, "[", 1) < 0) return -1;
    for (int i = 0; i < l->n; i++) {
        char text[40];
        double v = l->v[i];
        int len = l->nan_null && isnan(v) ? snprintf(text, sizeof text, "null")
                                          : snprintf(text, sizeof text, "%.*g", l->digits, v == 0 ? 0.0 : v);
        if ((i && printbuf_memappend(pb, ",", 1) < 0) || printbuf_memappend(pb, text, len) < 0) return -1;
    }
    return printbuf_memappend(pb, "]", 1) < 0 ? -1 : 0;
}

json_object *cs_jnums(const double *v, int n, int digits, int nan_null) {
    json_object *list = json_object_new_array();
    numbers *l = malloc(sizeof *l + (size_t)(n > 0 ? n : 0) * sizeof l->v[0]);
    if (!list || !l) {
        json_object_put(list);
        free(l);
        return NULL;
    }
    l->n = n > 0 ? n : 0, l->digits = digits, l->nan_null = nan_null;
    if (n > 0) memcpy(l->v, v, (size_t)n * sizeof v[0]);
    json_object_set_serializer(list, numbers_text, l, json_object_free_userdata);
    return list;
}

json_object *cs_jstr(const char *s) {
    return s ? json_object_new_string(s) : NULL;
}

/* A wrapper's text: its value's (the wrapper's user data), and a line break after or before it. */
static int wrapped(json_object *jso, struct printbuf *pb, int after) {
    json_object *v = json_object_get_userdata(jso);
    size_t n = 4;
    const char *text = v ? json_object_to_json_string_length(v, FLAGS, &n) : "null";
    if (!text) return -1;
    if (!after && printbuf_memappend(pb, "\n", 1) < 0) return -1;
    if (printbuf_memappend(pb, text, (int)n) < 0) return -1;
    return after ? printbuf_memappend(pb, "\n", 1) : 0;
}

static int text_after(json_object *jso, struct printbuf *pb, int level, int flags) {
    (void)level, (void)flags;
    return wrapped(jso, pb, 1);
}

static int text_before(json_object *jso, struct printbuf *pb, int level, int flags) {
    (void)level, (void)flags;
    return wrapped(jso, pb, 0);
}

static void put_wrapped(json_object *jso, void *userdata) {
    (void)jso;
    json_object_put(userdata);
}

static json_object *wrap(json_object *v, json_object_to_json_string_fn *fn) {
    json_object *w = json_object_new_object();
    if (!w) {
        json_object_put(v);
        return NULL;
    }
    json_object_set_serializer(w, fn, v, put_wrapped);
    return w;
}

json_object *cs_jline_after(json_object *v) {
    return wrap(v, text_after);
}

json_object *cs_jline_before(json_object *v) {
    return wrap(v, text_before);
}

/* An object's text with some of its members on a new line: each member written by json-c as the one member
 * of an object of its own, less that object's braces. */
static int members_on_lines(json_object *jso, struct printbuf *pb, int level, int flags) {
    (void)level;
    const char *const *keys = json_object_get_userdata(jso);
    int first = 1;
    if (printbuf_memappend(pb, "{", 1) < 0) return -1;
    json_object_object_foreach(jso, key, value) {
        if (!first && printbuf_memappend(pb, ",", 1) < 0) return -1;
        first = 0;
        for (const char *const *k = keys; *k; k++)
            if (strcmp(*k, key) == 0 && printbuf_memappend(pb, "\n", 1) < 0) return -1;
        json_object *one = json_object_new_object();
        if (!one) return -1;
        json_object_object_add(one, key, json_object_get(value));
        size_t n = 0;
        const char *text = json_object_to_json_string_length(one, flags, &n);
        int bad = !text || n < 2 || printbuf_memappend(pb, text + 1, (int)n - 2) < 0;
        json_object_put(one);
        if (bad) return -1;
    }
    return printbuf_memappend(pb, "}", 1) < 0 ? -1 : 0;
}

void cs_jkeys_on_new_line(json_object *obj, const char *const *keys) {
    json_object_set_serializer(obj, members_on_lines, (void *)keys, NULL);
}

int cs_jline_after_last(json_object *obj) {
    const char *last = NULL;
    json_object *value = NULL;
    json_object_object_foreach(obj, k, v) {
        last = k;
        value = v;
    }
    if (!last) return 0;
    json_object *w = cs_jline_after(json_object_get(value));
    return w ? json_object_object_add(obj, last, w) : -1;
}

int cs_json_write(FILE *f, json_object *doc, int page, const char *end) {
    size_t n = 0;
    const char *text = json_object_to_json_string_length(doc, FLAGS, &n);
    if (!text) return -1;
    if (!page) {
        fwrite(text, 1, n, f);
    } else {
        /* the runs between them written whole (a page's data is megabytes) */
        for (const char *s = text; *s;) {
            size_t run = strcspn(s, "<>&"); /* only ever inside a string */
            fwrite(s, 1, run, f);
            s += run;
            if (*s) fprintf(f, "\\u%04x", (unsigned)*s++);
        }
    }
    fputs(end, f);
    return 0;
}

char *cs_json_text(json_object *doc) {
    const char *text = json_object_to_json_string_ext(doc, FLAGS);
    return text ? strdup(text) : NULL;
}
