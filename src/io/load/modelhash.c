/* SPDX-License-Identifier: MIT */
/* cs_model_input_hash (cablesim/loader.h): 64-bit FNV-1a over a loaded model's definitions, field by field in
 * the schema's order (each key, then its value's bytes), with what the schema does not reach (each post's x,
 * a rope's diameter, the crush curve, the counts) hashed beside. Its name and the file it came from are
 * left out: the same model from another file has the same hash. */
#include <string.h>

#include "cablesim/loader.h"
#include "fnv.h"
#include "schema.h"
#include "status.h"

static unsigned long long bytes(unsigned long long h, const void *data, size_t n) {
    return cs_io_fnv(h, data, n);
}

static unsigned long long key(unsigned long long h, const char *k) {
    return bytes(h, k, strlen(k) + 1);
}

static unsigned long long num(unsigned long long h, const char *k, double v) {
    return bytes(key(h, k), &v, sizeof v);
}

static unsigned long long count(unsigned long long h, const char *k, int n) {
    return bytes(key(h, k), &n, sizeof n);
}

/* The fields of table t that fill members of def (summary.json's inputs walk the same). */
static unsigned long long fields(unsigned long long h, const cs_table *t, const void *def) {
    for (int i = 0; i < t->count; i++) {
        const cs_field *fd = &t->fields[i];
        if (fd->offset < 0) continue;
        const char *at = (const char *)def + fd->offset;
        if (cs_field_unset(fd, at)) continue;
        if ((fd->flags & CS_NEW0) && fd->kind == CS_F_QTY && memcmp(at, &(double){0.0}, sizeof(double)) == 0)
            continue;
        h = key(h, fd->key);
        if (fd->kind == CS_F_MAP) {
            h = fields(h, fd->sub, at);
        } else if (fd->kind == CS_F_INT || fd->kind == CS_F_ENUM) {
            int v;
            memcpy(&v, at, sizeof v);
            h = bytes(h, &v, sizeof v);
        } else {
            double v;
            memcpy(&v, at, sizeof v);
            h = bytes(h, &v, sizeof v);
        }
    }
    return h;
}

unsigned long long cs_model_input_hash(const cs_model_input *in) {
    if (cs_status_input(in, NULL) != CS_OK) return 0;
    unsigned long long h = CS_IO_FNV_BASIS;
    const cs_barrier_def *b = &in->barrier;
    h = count(h, "cables", b->cable_count);
    for (int c = 0; c < b->cable_count; c++) {
        h = fields(h, &cs_table_cable, &b->cables[c]);
        h = fields(h, &cs_table_rope, &b->cables[c].rope);
        h = num(h, "diameter", b->cables[c].rope.diameter);
    }
    h = count(h, "posts", b->post_count);
    for (int p = 0; p < b->post_count; p++) {
        h = num(h, "x", b->posts[p].x);
        h = fields(h, &cs_table_posts, &b->posts[p]);
        h = fields(h, &cs_table_section, &b->posts[p].section);
    }
    h = count(h, "rails", b->rail_count);
    for (int r = 0; r < b->rail_count; r++)
        h = fields(h, &cs_table_rail, &b->rails[r]);
    h = fields(h, &cs_table_anchors, b);
    h = fields(h, &cs_table_vehicle, &in->vehicle);
    h = count(h, "crush_points", in->vehicle.crush_point_count);
    for (int i = 0; i < in->vehicle.crush_point_count && i < CS_MAX_CRUSH_POINTS; i++) {
        h = num(h, "crush_deformation", in->vehicle.crush_deformation[i]);
        h = num(h, "crush_force", in->vehicle.crush_force[i]);
    }
    return fields(h, &cs_table_scenario, &in->scenario);
}
