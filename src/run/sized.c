/* SPDX-License-Identifier: MIT */
/* The definitions' sizes (def.h): a struct from a program built against an earlier, smaller version is
 * read to its size, the rest taken from its cs_default_*(); a struct nested in another is read the same
 * way at its own size, and the owner's fields after it from where the caller's layout puts them. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/sized.h"

typedef struct kind kind;
typedef struct member {
    size_t offset;
    const kind *kind;
    const char *name;
} member;
struct kind {
    size_t size;
    size_t align;            /* every size of it is a multiple of this */
    void (*fill)(void *def); /* the defaults */
    const char *name;        /* cs_default_NAME() */
    member members[3];       /* nested definitions, in the order of their offsets */
};

static void rope(void *d) {
    *(cs_rope_def *)d = cs_default_rope_def();
}
static void cable(void *d) {
    *(cs_cable_def *)d = cs_default_cable_def();
}
static void section(void *d) {
    *(cs_section_def *)d = cs_default_section_def();
}
static void footing(void *d) {
    *(cs_footing_def *)d = cs_default_footing_def();
}
static void post(void *d) {
    *(cs_post_def *)d = cs_default_post_def();
}
static void anchor(void *d) {
    *(cs_anchor_def *)d = cs_default_anchor_def();
}
static void rail(void *d) {
    *(cs_rail_def *)d = cs_default_rail_def();
}
static void barrier(void *d) {
    *(cs_barrier_def *)d = cs_default_barrier_def();
}
static void vehicle(void *d) {
    *(cs_vehicle_def *)d = cs_default_vehicle_def();
}
static void scenario(void *d) {
    *(cs_scenario_def *)d = cs_default_scenario_def();
}

/* The layout read below: one alignment for every definition (a nested struct a multiple of it smaller
 * moves its owner's later fields by that, which no field's alignment minds), nested members in the order
 * of their offsets. */
#define SAME_ALIGN(a, b) _Static_assert(_Alignof(a) == _Alignof(b), #a " and " #b " align alike")
SAME_ALIGN(cs_cable_def, cs_rope_def);
SAME_ALIGN(cs_post_def, cs_section_def);
SAME_ALIGN(cs_post_def, cs_footing_def);
SAME_ALIGN(cs_anchor_def, cs_footing_def);
SAME_ALIGN(cs_barrier_def, cs_anchor_def);
_Static_assert(offsetof(cs_post_def, section) + sizeof(cs_section_def) <= offsetof(cs_post_def, footing),
               "a post's nested structs in order");
_Static_assert(offsetof(cs_barrier_def, start_anchor) + sizeof(cs_anchor_def) <=
                   offsetof(cs_barrier_def, end_anchor),
               "a barrier's anchors in order");

#define KIND(t) sizeof(t), _Alignof(t)
static const kind rope_kind = {KIND(cs_rope_def), rope, "rope_def", {{0}}};
static const kind section_kind = {KIND(cs_section_def), section, "section_def", {{0}}};
static const kind footing_kind = {KIND(cs_footing_def), footing, "footing_def", {{0}}};
static const kind rail_kind = {KIND(cs_rail_def), rail, "rail_def", {{0}}};
static const kind vehicle_kind = {KIND(cs_vehicle_def), vehicle, "vehicle_def", {{0}}};
static const kind scenario_kind = {KIND(cs_scenario_def), scenario, "scenario_def", {{0}}};
static const kind cable_kind = {
    KIND(cs_cable_def), cable, "cable_def", {{offsetof(cs_cable_def, rope), &rope_kind, "rope"}}};
static const kind post_kind = {KIND(cs_post_def),
                               post,
                               "post_def",
                               {{offsetof(cs_post_def, section), &section_kind, "section"},
                                {offsetof(cs_post_def, footing), &footing_kind, "footing"}}};
static const kind anchor_kind = {KIND(cs_anchor_def),
                                 anchor,
                                 "anchor_def",
                                 {{offsetof(cs_anchor_def, footing), &footing_kind, "footing"}}};
static const kind barrier_kind = {KIND(cs_barrier_def),
                                  barrier,
                                  "barrier_def",
                                  {{offsetof(cs_barrier_def, start_anchor), &anchor_kind, "start anchor"},
                                   {offsetof(cs_barrier_def, end_anchor), &anchor_kind, "end anchor"}}};

static int bad(cs_error *err, const char *what, const kind *k, size_t given) {
    if (given >= sizeof given && given <= k->size && given % k->align != 0)
        cs_error_set(err, CS_ERR_INVALID,
                     "%s: size %zu, not a multiple of its alignment %zu: not a %s's size", what, given,
                     k->align, k->name);
    else if (given < sizeof given)
        cs_error_set(err, CS_ERR_INVALID, "%s: size %zu: start it from cs_default_%s(), which sets its size",
                     what, given, k->name);
    else
        cs_error_set(
            err, CS_ERR_INVALID,
            "%s: size %zu, where this library's is %zu: a program built for a later cablesim, or not "
            "started from cs_default_%s()",
            what, given, k->size, k->name);
    return -1;
}

/* Read the caller's struct at given (room bytes of it at most) into full; *used gets its size. A version
 * adds fields only at a struct's end, so the caller's struct is this library's with each nested struct
 * ending where the caller's own size says and the owner's fields after it moved by what that one lacks
 * (every definition has one alignment, its sizes multiples of it: above): it is read piece by piece, the
 * owner's own fields between the nested ones, and the defaults kept for whatever the caller's version
 * lacks. A nested struct that cannot be read after a smaller one is a layout this library does not know. */
static int take(const kind *k, void *full, const void *given, size_t room, const char *what, cs_error *err,
                size_t *used) {
    size_t n = 0;
    if (room >= sizeof n) memcpy(&n, given, sizeof n);
    k->fill(full);
    if (n < sizeof n || n > k->size || n > room || n % k->align != 0) return bad(err, what, k, n);
    const char *g = given;
    char *f = full;
    size_t at = 0, to = 0; /* the next byte to read in the caller's struct, and where it goes in full */
    for (int i = 0; i < 3 && k->members[i].kind; i++) {
        const member *m = &k->members[i];
        size_t own = m->offset - to; /* the owner's fields before this nested one */
        if (n <= at + own) break;    /* the caller's has none of it: its defaults */
        memcpy(f + to, g + at, own);
        char sub[128];
        snprintf(sub, sizeof sub, "%s's %s", what, m->name);
        size_t inner;
        if (take(m->kind, f + m->offset, g + at + own, n - at - own, sub, err, &inner) != 0) {
            if (at != to) /* read where a smaller nested struct before it put it */
                cs_error_set(
                    err, CS_ERR_INVALID,
                    "%s: not readable after a smaller nested struct: a layout this library does not know",
                    sub);
            return -1;
        }
        at += own + inner, to = m->offset + m->kind->size;
    }
    if (at < n) {
        if (to + (n - at) > k->size) {
            cs_error_set(err, CS_ERR_INVALID,
                         "%s: size %zu with its nested structs as given: a layout this library does not know",
                         what, n);
            return -1;
        }
        memcpy(f + to, g + at, n - at);
    }
    memcpy(full, &k->size, sizeof k->size);
    *used = n;
    return 0;
}

/* count elements of the caller's array given, each of the first one's size, into out (count of this
 * library's size, or 1 for none). */
static int take_array(const kind *k, void *out, const void *given, int count, const char *what,
                      cs_error *err) {
    if (!out) return cs_out_of_memory(err), -1;
    if (count <= 0 || !given) return 0;
    size_t stride;
    memcpy(&stride, given, sizeof stride);
    for (int i = 0; i < count; i++) {
        char at[64];
        snprintf(at, sizeof at, "%s %d", what, i);
        const char *g = (const char *)given + (size_t)i * stride;
        size_t used;
        if (take(k, (char *)out + (size_t)i * k->size, g, stride, at, err, &used) != 0) return -1;
    }
    return 0;
}

static void *room_for(int count, size_t size) {
    return calloc((size_t)(count > 0 ? count : 1), size);
}

int cs_defs_take(cs_defs *d, const cs_barrier_def *b, const cs_vehicle_def *v, const cs_scenario_def *s,
                 cs_error *err) {
    memset(d, 0, sizeof *d);
    size_t used;
    if (take(&barrier_kind, &d->barrier, b, SIZE_MAX, "barrier", err, &used) != 0 ||
        take(&vehicle_kind, &d->vehicle, v, SIZE_MAX, "vehicle", err, &used) != 0 ||
        take(&scenario_kind, &d->scenario, s, SIZE_MAX, "scenario", err, &used) != 0)
        return -1;
    int nc = d->barrier.cable_count, np = d->barrier.post_count, nr = d->barrier.rail_count;
    d->cables = room_for(nc, sizeof *d->cables);
    d->posts = room_for(np, sizeof *d->posts);
    d->rails = room_for(nr, sizeof *d->rails);
    if (take_array(&cable_kind, d->cables, d->barrier.cables, nc, "cable", err) ||
        take_array(&post_kind, d->posts, d->barrier.posts, np, "post", err) ||
        take_array(&rail_kind, d->rails, d->barrier.rails, nr, "rail", err))
        return -1;
    d->barrier.cables = d->cables;
    d->barrier.posts = d->posts;
    d->barrier.rails = d->rails;
    return 0;
}

void cs_defs_free(cs_defs *d) {
    free(d->cables);
    free(d->posts);
    free(d->rails);
}

cs_status cs_sized_refuse(cs_error *err, const char *name, const char *reason) {
    return cs_error_set(err, CS_ERR_INVALID, "%s: %s", name, reason);
}

/* The size at the start of the caller's struct at: CS_OK, or CS_ERR_INVALID naming it if that size is not
 * one a struct of this library's full_size can be. */
cs_status cs_sized_check(const void *at, size_t full_size, const char *name, cs_error *err) {
    size_t n;
    return cs_sized_size(at, full_size, name, &n, err);
}

cs_status cs_sized_size(const void *at, size_t full_size, const char *name, size_t *n, cs_error *err) {
    *n = 0;
    if (!at) return cs_sized_refuse(err, name, "no struct (NULL)");
    memcpy(n, at, sizeof *n);
    char why[160];
    if (*n < sizeof *n)
        snprintf(why, sizeof why,
                 "size %zu, where this library's is %zu: set it to sizeof the struct (%s x = {.size = "
                 "sizeof x})",
                 *n, full_size, name);
    else if (*n > full_size)
        snprintf(
            why, sizeof why,
            "size %zu, where this library's is %zu: a program built for a later cablesim, or size not set",
            *n, full_size);
    else
        return CS_OK;
    return cs_sized_refuse(err, name, why);
}

cs_status cs_sized_put(void *out, const void *full, size_t full_size, const char *name, cs_error *err) {
    size_t n;
    if (cs_sized_size(out, full_size, name, &n, err) != CS_OK) return CS_ERR_INVALID;
    memcpy(out, full, n);
    memcpy(out, &n, sizeof n);
    if (err) err->status = CS_OK, err->message[0] = '\0';
    return CS_OK;
}

cs_status cs_sized_put_array(void *out, const void *full, size_t full_size, int count, const char *name,
                             cs_error *err) {
    size_t n;
    if (cs_sized_size(out, full_size, name, &n, err) != CS_OK) return CS_ERR_INVALID;
    for (int i = 0; i < count; i++) {
        char *at = (char *)out + (size_t)i * n;
        memcpy(at, (const char *)full + (size_t)i * full_size, n);
        memcpy(at, &n, sizeof n);
    }
    if (err) err->status = CS_OK, err->message[0] = '\0';
    return CS_OK;
}

cs_status cs_sized_take(void *full, size_t full_size, const void *given, const char *name, cs_error *err) {
    size_t n;
    if (cs_sized_size(given, full_size, name, &n, err) != CS_OK) return CS_ERR_INVALID;
    memcpy(full, given, n);
    memcpy(full, &full_size, sizeof full_size);
    return CS_OK;
}
