/* SPDX-License-Identifier: MIT */
/* Checked values into the engine's definition structs: units, ranges, parts, post runs, and the
 * physical checks that need several fields, each reported at the field's place. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/units.h"
#include "loader_int.h"

enum { MAX_POSTS = 10000 };
static const double POS_TOL = 1e-3; /* m: two positions closer than this are the same */

static const cs_node *at(const cs_node *map, const char *key) {
    const cs_node *n = cs_node_get(map, key);
    return n ? n : map;
}

static const cs_field *field_of(const cs_node *map, const char *key) {
    return &map->table->fields[cs_table_find(map->table, key)];
}

/* Read one scalar as the field's quantity and check its range. */
static int read_value(cs_loader *l, const cs_node *n, const cs_field *f, double *out) {
    char hint[160];
    cs_error err;
    cs_field_hint(f, hint, sizeof hint);
    if ((f->flags & CS_NONE_OK) && strcmp(n->text, "none") == 0) {
        *out = INFINITY;
        return 0;
    }
    if (cs_units_read(l->units, n->text, f->q, out, &err) != CS_OK) {
        cs_err_node(l, n, 0, "%s (expected %s)", err.message, hint);
        return -1;
    }
    const char *bad = NULL;
    if ((f->flags & CS_POS) && !(*out > 0))
        bad = "must be above zero";
    else if ((f->flags & CS_NONNEG) && *out < 0)
        bad = "must not be negative";
    else if ((f->flags & CS_MAX1) && *out > 1)
        bad = "must be at most 1";
    else if ((f->flags & CS_MAX90) && *out > CS_PI / 2 + 1e-12)
        bad = "must be at most 90 deg";
    else if ((f->flags & CS_MAX180) && *out >= CS_PI)
        bad = "must be below 180 deg";
    if (bad) {
        cs_err_node(l, n, 0, "'%s' %s (expected %s)", n->text, bad, hint);
        return -1;
    }
    const cs_range *r = cs_field_range(f);
    double size = fabs(*out);
    if (size > r->hi || (size > 0 && size < r->lo)) {
        char lo[80], hi[80];
        cs_units_show(l->units, n->text, f->q, r->lo, lo, sizeof lo);
        cs_units_show(l->units, n->text, f->q, r->hi, hi, sizeof hi);
        cs_err_node(l, n, 0, "'%s' is %s for %s (expected %s%s%s to %s: %s)", n->text,
                    size > r->hi ? "too large" : "too small", f->key, f->flags & CS_POS ? "" : "0 or ",
                    f->flags & (CS_POS | CS_NONNEG) ? "" : "a size of ", lo, hi, r->basis);
        return -1;
    }
    return 0;
}

/* A quantity by key; 1 if read, 0 if absent, -1 if wrong. */
static int get_qty(cs_loader *l, const cs_node *map, const char *key, double *out) {
    const cs_node *n = cs_node_get(map, key);
    if (!n) return 0;
    return read_value(l, n, field_of(map, key), out) == 0 ? 1 : -1;
}

/* A list of quantities by key: count read, 0 if absent, -1 if wrong. */
static int get_list(cs_loader *l, const cs_node *map, const char *key, double *out, int max) {
    const cs_node *n = cs_node_get(map, key);
    if (!n) return 0;
    if (n->count > max) {
        cs_err_node(l, n, 0, "%d values (expected at most %d)", n->count, max);
        return -1;
    }
    int ok = 1;
    for (int i = 0; i < n->count; i++)
        ok &= read_value(l, n->items[i], field_of(map, key), &out[i]) == 0;
    return ok ? n->count : -1;
}

/* Was key written in the file but dropped for its wrong shape (already reported)? */
static int given_but_bad(cs_loader *l, const cs_node *map, const char *key) {
    return map->source >= 0 && cs_ynode_get_counted(map->at, key, &l->work) != NULL;
}

static void check_required(cs_loader *l, const cs_node *map) {
    for (int i = 0; i < map->table->count; i++) {
        const cs_field *f = &map->table->fields[i];
        if (!(f->flags & CS_REQ) || map->items[i] || given_but_bad(l, map, f->key)) continue;
        char hint[200];
        if (f->kind == CS_F_MAP || f->kind == CS_F_SEQ)
            snprintf(hint, sizeof hint, "%s %s", f->kind == CS_F_SEQ ? "a list of" : "a", f->sub->name);
        else
            cs_field_hint(f, hint, sizeof hint);
        cs_err_node(l, map, 0, "missing '%s' (expected %s)", f->key, hint);
    }
}

static int fields(cs_loader *l, const cs_node *map, void *target, int required) {
    int before = l->error_count;
    if (required) check_required(l, map);
    for (int i = 0; i < map->table->count; i++) {
        const cs_field *f = &map->table->fields[i];
        const cs_node *n = map->items[i];
        if (!n || f->offset < 0) continue;
        char *dst = (char *)target + f->offset;
        if (f->kind == CS_F_QTY) {
            double v;
            if (read_value(l, n, f, &v) == 0) memcpy(dst, &v, sizeof v);
        } else if (f->kind == CS_F_MAP) {
            fields(l, n, dst, required);
        } else if (f->kind == CS_F_INT) {
            char *end;
            errno = 0;
            long v = strtol(n->text, &end, 10);
            int iv = (int)v;
            if (end == n->text || *end || errno || v > INT_MAX || v < ((f->flags & CS_POS) ? 1 : 0))
                cs_err_node(l, n, 0, "'%s' is not a %swhole number (expected %s)", n->text,
                            (f->flags & CS_POS) ? "positive " : "", "e.g. 200");
            else
                memcpy(dst, &iv, sizeof iv);
        } else if (f->kind == CS_F_ENUM) {
            int k = 0;
            while (f->words[k] && strcmp(f->words[k], n->text) != 0)
                k++;
            char hint[100];
            cs_field_hint(f, hint, sizeof hint);
            if (f->words[k])
                memcpy(dst, &k, sizeof k);
            else
                cs_err_node(l, n, 0, "'%s' is not a choice (expected %s)", n->text, hint);
        }
    }
    return l->error_count - before;
}

int cs_convert_fields(cs_loader *l, const cs_node *map, void *target) {
    return fields(l, map, target, 1);
}

/* The node that holds a value the user changed with a --set, of two that a check involves: a problem of
 * the two is the --set's, not the library's or the file's line it was checked against. */
static const cs_node *blamed(const cs_node *first, const cs_node *second) {
    return second && second->source < 0 && first->source >= 0 ? second : first;
}

/* An SI value of key in map as its node was written ("1.45 m", "4.75 ft"; SI if it is not given). */
static void shown(const cs_loader *l, const cs_node *map, const char *key, double v, char *out, size_t size) {
    const cs_node *n = cs_node_get(map, key);
    cs_units_show(l->units, n && n->text ? n->text : "", field_of(map, key)->q, v, out, size);
}

/* Report key's value v at its place (or at other's, where a --set gave other) unless it is above other's
 * value lo. */
static void above(cs_loader *l, const cs_node *map, const char *key, double v, const char *other, double lo) {
    if (v > lo) return;
    char a[80], b[80];
    shown(l, map, key, v, a, sizeof a);
    shown(l, map, other, lo, b, sizeof b);
    cs_err_node(l, blamed(at(map, key), cs_node_get(map, other)), 0,
                "%s %s is not above %s, %s (expected %s > %s)", key, a, other, b, key, other);
}

/* ---- vehicle ---- */

static void crush_curve(cs_loader *l, const cs_node *v, cs_vehicle_def *out) {
    double def[CS_MAX_CRUSH_POINTS], force[CS_MAX_CRUSH_POINTS], speed, depth;
    int nd = get_list(l, v, "crush_deformation", def, CS_MAX_CRUSH_POINTS);
    int nf = get_list(l, v, "crush_force", force, CS_MAX_CRUSH_POINTS);
    int nr = get_list(l, v, "crush_force_fraction", force, CS_MAX_CRUSH_POINTS);
    int gs = get_qty(l, v, "crush_fit_speed", &speed), gd = get_qty(l, v, "crush_fit_depth", &depth);
    const cs_node *list = at(v, "crush_deformation");
    if (nd <= 0 || nf < 0 || nr < 0 || gs < 0 || gd < 0) return;
    if ((nf > 0) == (nr > 0)) {
        cs_err_node(l, v, 0, "give crush_force or crush_force_fraction (expected exactly one of them)");
        return;
    }
    int n = nf > 0 ? nf : nr;
    if (n != nd || nd < 2) {
        cs_err_node(l, list, 0, "%d deformations and %d forces (expected two or more pairs)", nd, n);
        return;
    }
    if (def[0] != 0 || force[0] != 0) {
        cs_err_node(l, list, 0, "the curve starts at (%g m, %g) (expected the point 0, 0 first)", def[0],
                    force[0]);
        return;
    }
    for (int i = 1; i < n; i++)
        if (!(def[i] > def[i - 1])) {
            cs_err_node(l, list->items[i], 0, "deformations must increase (expected above %g m)", def[i - 1]);
            return;
        }
    if (nr > 0) { /* Fmax: the area under the curve up to depth equals the test's kinetic energy */
        if (gs != 1 || gd != 1 || depth > def[n - 1]) {
            cs_err_node(l, v, 0,
                        "crush_force_fraction needs crush_fit_speed and crush_fit_depth (expected a "
                        "depth within the curve, up to %g m)",
                        def[n - 1]);
            return;
        }
        double area = 0;
        for (int i = 1; i < n && def[i - 1] < depth; i++) {
            double x1 = fmin(def[i], depth);
            double f1 = force[i - 1] + (force[i] - force[i - 1]) * (x1 - def[i - 1]) / (def[i] - def[i - 1]);
            area += 0.5 * (force[i - 1] + f1) * (x1 - def[i - 1]);
        }
        double fmax = 0.5 * out->mass * speed * speed / area;
        for (int i = 0; i < n; i++)
            force[i] *= fmax;
    }
    out->crush_point_count = n;
    memcpy(out->crush_deformation, def, (size_t)n * sizeof *def);
    memcpy(out->crush_force, force, (size_t)n * sizeof *force);
}

/* The least radius of gyration of a vehicle about any axis (docs/assumptions.md): 5 cm. */
#define CS_GYRATION_MIN 0.05

int cs_convert_vehicle(cs_loader *l, const cs_node *v, cs_vehicle_def *out) {
    int before = l->error_count;
    *out = cs_default_vehicle_def();
    fields(l, v, out, 1);
    const cs_node *box = cs_node_get(v, "inertia_box");
    static const char *const keys[] = {"roll_inertia", "pitch_inertia", "yaw_inertia"};
    if (box) { /* the box's moments, each replaced by one given on its own (a part's box, a --set) */
        double b[3];
        check_required(l, box);
        if (get_qty(l, box, "length", &b[0]) == 1 && get_qty(l, box, "width", &b[1]) == 1 &&
            get_qty(l, box, "height", &b[2]) == 1) {
            double m[3] = {out->mass * (b[1] * b[1] + b[2] * b[2]) / 12,
                           out->mass * (b[0] * b[0] + b[2] * b[2]) / 12,
                           out->mass * (b[0] * b[0] + b[1] * b[1]) / 12};
            for (int i = 0; i < 3; i++)
                if (!cs_node_get(v, keys[i])) out->inertia[i] = m[i];
        }
    } else {
        for (int i = 0; i < 3; i++)
            if (!cs_node_get(v, keys[i]))
                cs_err_node(l, v, 0,
                            "missing '%s' (expected a moment of inertia, e.g. \"35000 kg m2\", or "
                            "inertia_box)",
                            keys[i]);
    }
    for (int i = 0; i < 3 && l->error_count == before && out->mass > 0; i++) {
        const cs_node *at = cs_node_get(v, keys[i]) ? cs_node_get(v, keys[i]) : box;
        double k = sqrt(out->inertia[i] / out->mass); /* the radius of gyration */
        if (at && !(k >= CS_GYRATION_MIN))
            cs_err_node(l, blamed(at, cs_node_get(v, "mass")), 0,
                        "%s %.4g kg m^2 puts the vehicle's %.4g kg %.3g m from its centre, below %.0f cm "
                        "(expected at least %.4g kg m^2: a road vehicle's mass lies decimetres to metres "
                        "from its centre; less is a mistake of unit or typing)",
                        keys[i], out->inertia[i], out->mass, k, CS_GYRATION_MIN * 100,
                        out->mass * CS_GYRATION_MIN * CS_GYRATION_MIN);
    }
    crush_curve(l, v, out);
    if (l->error_count > before || cs_damaged(v)) return l->error_count - before;
    above(l, v, "face_top", out->face_top, "face_bottom", out->face_bottom);
    above(l, v, "side_top", out->side_top, "side_bottom", out->side_bottom);
    above(l, v, "wheelbase", out->wheelbase, "cg_to_front_axle", out->cg_to_front_axle);
    above(l, v, "cg_to_front", out->cg_to_front, "cg_to_front_axle", out->cg_to_front_axle);
    /* the front axle, where a front tyre's band starts, above the ground and below the side's top */
    above(l, v, "wheel_radius", out->wheel_radius, "tyre_static_deflection", out->tyre_static_deflection);
    double axle = out->wheel_radius - out->tyre_static_deflection;
    if (axle > 0 && !(axle < out->side_top)) {
        char a[80], b[80];
        shown(l, v, "wheel_radius", out->wheel_radius, a, sizeof a);
        shown(l, v, "side_top", out->side_top, b, sizeof b);
        cs_err_node(l, blamed(at(v, "wheel_radius"), cs_node_get(v, "side_top")), 0,
                    "wheel_radius %s puts the front axle %.4g m up, not below side_top, %s (expected "
                    "wheel_radius - tyre_static_deflection < side_top)",
                    a, axle, b);
    }
    if (out->rim_radius > 0.0 && axle > 0 && !(out->rim_radius < axle)) {
        char r[80], a[80];
        shown(l, v, "rim_radius", out->rim_radius, r, sizeof r);
        shown(l, v, "wheel_radius", out->wheel_radius, a, sizeof a);
        cs_err_node(l, blamed(at(v, "rim_radius"), cs_node_get(v, "wheel_radius")), 0,
                    "rim_radius %s is not below the axle's height at rest, %.4g m (wheel_radius %s less "
                    "tyre_static_deflection): the tyre would stand on its rim (expected rim_radius < "
                    "wheel_radius - tyre_static_deflection)",
                    r, axle, a);
    }
    return l->error_count - before;
}

/* ---- ropes, cables ---- */

int cs_convert_rope(cs_loader *l, const cs_node *rope, cs_rope_def *out, double *diameter) {
    int before = l->error_count;
    const cs_node *from = cs_node_get(rope, "scale_from");
    double d = 0, d0 = 0;
    int has_d = get_qty(l, rope, "diameter", &d);
    *out = cs_default_rope_def();
    if (from) {
        const cs_node *base =
            l->depth < 16 ? cs_find_part(l, from->source, CS_PART_ROPE, from->text, from) : NULL;
        l->depth++;
        int base_errors = base ? cs_convert_rope(l, base, out, &d0) : 1;
        l->depth--;
        if (base_errors) return l->error_count - before + (l->error_count == before);
        if (has_d != 1 || d0 <= 0) {
            cs_err_node(l, from, 0,
                        "scaling needs this rope's and '%s''s diameter (expected diameter in both)",
                        from->text);
            return l->error_count - before;
        }
        double r = (d / d0) * (d / d0);
        out->area *= r;
        out->nominal_strength *= r;
        out->mass_per_length *= r;
    }
    fields(l, rope, out, !from);
    if (has_d == 1) out->diameter = d; /* the efficiency of clips at its ends needs it */
    if (diameter) *diameter = has_d == 1 ? d : d0;
    return l->error_count - before;
}

static void convert_cable(cs_loader *l, const cs_node *c, cs_cable_def *out) {
    *out = cs_default_cable_def();
    const cs_node *name = cs_node_get(c, "rope");
    const cs_node *rope = name ? cs_find_part(l, name->source, CS_PART_ROPE, name->text, name) : NULL;
    if (rope && cs_convert_rope(l, rope, &out->rope, NULL) != 0) return;
    if (fields(l, c, out, 1) != 0 || !rope || cs_damaged(c)) return;
    const cs_rope_def *r = &out->rope;
    double fu = r->nominal_strength, strain_fu = cs_rope_strain_at_strength(r);
    if (r->breaking_strain <= strain_fu)
        cs_err_node(l, at(c, "breaking_strain"), 0,
                    "breaking strain %g is below the strain at nominal strength "
                    "%.4g (expected more, e.g. 0.03)",
                    r->breaking_strain, strain_fu);
    if (out->pretension >= r->elastic_limit_ratio * fu)
        cs_err_node(l, at(c, "pretension"), 0,
                    "pretension %.4g kN is beyond the rope's elastic limit %.4g kN "
                    "(expected less)",
                    out->pretension / 1e3, r->elastic_limit_ratio * fu / 1e3);
}

/* ---- rails ---- */

static void convert_rail(cs_loader *l, const cs_node *r, cs_rail_def *out) {
    *out = cs_default_rail_def();
    const cs_node *name = cs_node_get(r, "rail");
    const cs_node *part = name ? cs_find_part(l, name->source, CS_PART_RAIL, name->text, name) : NULL;
    if (part) fields(l, part, out, 1);
    fields(l, r, out, 1);
}

/* ---- posts ---- */

typedef struct post_slot {
    cs_post_def def;
    const cs_node *group;
} post_slot;

static int by_x(const void *a, const void *b) {
    const post_slot *p = a, *q = b;
    return (p->def.x > q->def.x) - (p->def.x < q->def.x);
}

/* The positions of a group: one by one (x) or a run. Returns the count, -1 on errors. */
static int positions(cs_loader *l, const cs_node *g, double *xs, int max) {
    int nx = get_list(l, g, "x", xs, max);
    double from = 0, to = 0, up_to = 0, spacing = 0, ex[256];
    int gf = get_qty(l, g, "from", &from), gt = get_qty(l, g, "to", &to), gu = get_qty(l, g, "up_to", &up_to),
        gs = get_qty(l, g, "spacing", &spacing);
    int ne = get_list(l, g, "except", ex, 256), before = l->error_count;
    const cs_node *count = cs_node_get(g, "count");
    if (nx < 0 || gf < 0 || gt < 0 || gu < 0 || gs < 0 || ne < 0) return -1;
    if (nx > 0) {
        if (gf || gt || gu || gs || count || ne) {
            cs_err_node(l, g, 0,
                        "posts given by x and as a run (expected x, or from/spacing/to, up_to or count)");
            return -1;
        }
        return nx;
    }
    if (cs_node_get(g, "x")) { /* given, with no position in it */
        cs_err_node(l, at(g, "x"), 0, "an empty list (expected x: [...] with at least one position)");
        return -1;
    }
    if (!gf || !gs || (gt != 0) + (gu != 0) + (count != NULL) != 1) {
        cs_err_node(l, g, 0, "%s (expected x: [...], or from, spacing and one of to, up_to or count)",
                    !gf   ? "missing 'from'"
                    : !gs ? "missing 'spacing'"
                          : "give one of to, up_to or count");
        return -1;
    }
    long n;
    if (gu) { /* as many spacings as fit */
        double steps = floor((up_to - from) / spacing + 1e-9);
        if (steps < 0.0 || steps > 1e6) {
            cs_err_node(l, at(g, "up_to"), 0, "%g m is before the run's first post at %g m", up_to, from);
            return -1;
        }
        n = (long)steps;
    } else if (count) {
        char *end;
        n = strtol(count->text, &end, 10); /* posts; n - 1 below, once n > 0 (LONG_MIN - 1 overflows) */
        if (end == count->text || *end || n < 1) {
            cs_err_node(l, count, 0, "'%s' is not a positive whole number (expected e.g. 19)", count->text);
            return -1;
        }
        n--;
    } else {
        double steps = (to - from) / spacing;
        n = lround(steps);
        if (steps < -1e-9 || fabs(from + (double)n * spacing - to) > POS_TOL) {
            cs_err_node(l, at(g, "to"), 0,
                        "the run does not end here: %g m is not %g m plus a whole number of "
                        "%g-m spacings (expected e.g. %g m)",
                        to, from, spacing, from + fmax((double)n, 0) * spacing);
            return -1;
        }
    }
    if (n + 1 > max) {
        cs_err_node(l, g, 0, "%ld posts (expected at most %d)", n + 1, max);
        return -1;
    }
    int k = 0, used[256] = {0};
    for (long i = 0; i <= n; i++) {
        double x = from + (double)i * spacing;
        int skip = 0;
        for (int e = 0; e < ne; e++)
            if (fabs(ex[e] - x) < POS_TOL) skip = used[e] = 1;
        if (!skip) xs[k++] = x;
    }
    for (int e = 0; e < ne; e++)
        if (!used[e])
            cs_err_node(l, cs_node_get(g, "except")->items[e], 0,
                        "no post of the run stands at %g m (expected one "
                        "of the run's positions)",
                        ex[e]);
    return l->error_count > before ? -1 : k;
}

static int convert_group(cs_loader *l, const cs_node *g, const cs_node *soil, cs_post_def *def) {
    int before = l->error_count;
    *def = cs_default_post_def();
    const cs_node *name = cs_node_get(g, "section");
    const cs_node *section = name ? cs_find_part(l, name->source, CS_PART_SECTION, name->text, name) : NULL;
    if (section) fields(l, section, &def->section, 1);
    if (soil) fields(l, soil, &def->footing, 0);
    fields(l, g, def, 1);
    const cs_node *face = cs_node_get(g, "face");
    if (face && l->error_count == before && cs_attachment_lateral_release_force(def->attachment) == 0.0)
        cs_err_node(l, face, 0,
                    "'%s' for posts whose attachment is %s, which is fixed to no face of the post "
                    "(expected face left out: only keyway bolts and brackets are fixed to one)",
                    face->text, cs_attachment_word(def->attachment));
    if (l->error_count == before && !(def->footing.soil_pressure > 0.0) &&
        (cs_node_get(g, "footing") || !given_but_bad(l, g, "footing")))
        cs_err_node(l, g, 0,
                    "no soil pressure for its footing (expected barrier.soil: {soil_pressure: ...}, the soil "
                    "of every footing, or the group's footing.soil_pressure; e.g. 8000 psf, the paper's)");
    return l->error_count - before;
}

static int convert_posts(cs_loader *l, const cs_node *barrier, cs_barrier_def *out) {
    const cs_node *groups = cs_node_get(barrier, "posts"), *soil = cs_node_get(barrier, "soil");
    int before = l->error_count, total = 0;
    double *xs = malloc(MAX_POSTS * sizeof *xs);
    post_slot *posts = malloc(MAX_POSTS * sizeof *posts);
    for (int gi = 0; xs && posts && groups && gi < groups->count; gi++) {
        const cs_node *g = groups->items[gi];
        if (total == MAX_POSTS) { /* one problem, not one a group past it */
            cs_err_node(l, g, 0, "more than %d posts (expected at most %d in a barrier)", MAX_POSTS,
                        MAX_POSTS);
            break;
        }
        cs_post_def def;
        int n = positions(l, g, xs, MAX_POSTS - total);
        if (convert_group(l, g, soil, &def) != 0 || n < 0) continue;
        for (int i = 0; i < n; i++) {
            posts[total] = (post_slot){def, g};
            posts[total++].def.x = xs[i];
        }
    }
    if (l->error_count == before && total == 0 && groups)
        cs_err_node(l, groups, 0, "no posts (expected at least one)");
    if (l->error_count == before && posts) {
        qsort(posts, (size_t)total, sizeof *posts, by_x);
        cs_post_def *defs = cs_arena_alloc(l, (size_t)total * sizeof *defs);
        l->post_origin = cs_arena_alloc(l, (size_t)total * sizeof *l->post_origin);
        for (int i = 0; defs && l->post_origin && i < total; i++) {
            defs[i] = posts[i].def;
            l->post_origin[i] = posts[i].group;
            if (i > 0 && defs[i].x - defs[i - 1].x < POS_TOL && posts[i - 1].group == posts[i].group)
                cs_err_node(l, posts[i].group, 0,
                            "two posts at x = %g m and %g m, both of %s, %g mm apart (expected one post per "
                            "position: positions at least %g mm apart)",
                            defs[i - 1].x, defs[i].x, posts[i].group->path, 1e3 * (defs[i].x - defs[i - 1].x),
                            1e3 * POS_TOL);
            else if (i > 0 && defs[i].x - defs[i - 1].x < POS_TOL)
                cs_err_node(l, posts[i].group, 0,
                            "two posts at x = %g m (%s and %s) (expected one post per "
                            "position: leave one out with except)",
                            defs[i].x, posts[i - 1].group->path, posts[i].group->path);
        }
        out->posts = defs;
        out->post_count = total;
    }
    free(xs);
    free(posts);
    return l->error_count - before;
}

/* ---- the model ---- */

/* A cable's fittings that slip: each slipping end with a travel and above the pretension, and no slip
 * load or travel given where it does nothing (a cable's slip_load every end replaces, a travel where
 * nothing slips). One error a cable. */
static void check_slip(cs_loader *l, const cs_node *cable, const cs_cable_def *d) {
    double slip[2], travel[2];
    for (int k = 0; k < 2; k++)
        slip[k] = cs_cable_end_slip(d, k, &travel[k]);
    for (int k = 0; k < 2; k++) {
        const cs_node *own = cs_node_get(cable, k ? "end" : "start");
        const char *which = k ? "end" : "start";
        if (slip[k] > 0.0) {
            const cs_node *given = own && cs_node_get(own, "slip_load") ? own : cable;
            if (!(travel[k] > 0.0)) {
                cs_err_node(l, at(given, "slip_load"), 0,
                            "the fitting at the %s anchor slips but has no slip_travel (expected the "
                            "rope it lets through before the rope runs out of it, e.g. \"18 in\")",
                            which);
                return;
            }
            if (slip[k] <= d->pretension) {
                cs_err_node(l, at(given, "slip_load"), 0,
                            "the fitting at the %s anchor slips at %g N, not above the pretension (%g "
                            "N) (expected a slip load the rope could be tensioned against)",
                            which, slip[k], d->pretension);
                return;
            }
        } else if (own && cs_node_get(own, "slip_travel")) {
            cs_err_node(l, cs_node_get(own, "slip_travel"), 0,
                        "the fitting at the %s anchor does not slip (expected slip_travel with a slip_load)",
                        which);
            return;
        }
    }
    if (d->slip_load > 0.0 && slip[0] != d->slip_load && slip[1] != d->slip_load) {
        cs_err_node(l, at(cable, "slip_load"), 0,
                    "no end takes the cable's slip_load (expected it where an end takes the cable's "
                    "termination; an end of its own kind, or with its own slip_load, does not)");
        return;
    }
    if (d->slip_travel > 0.0 && !(slip[0] > 0.0) && !(slip[1] > 0.0))
        cs_err_node(l, at(cable, "slip_travel"), 0,
                    "no fitting of this cable slips (expected slip_travel with a slip_load)");
}

/* Where a post of group stands, for a check against it: the value of its x or of its run's keys that a
 * --set gave (blamed() then names that --set), else the group. */
static const cs_node *post_position(const cs_node *group) {
    static const char *const keys[] = {"x", "from", "spacing", "to", "up_to", "count", "except"};
    for (size_t k = 0; k < sizeof keys / sizeof *keys; k++) {
        const cs_node *n = cs_node_get(group, keys[k]);
        int items = n && n->kind == CS_Y_SEQ;
        for (int i = 0; n && i < (items ? n->count : 1); i++)
            if ((items ? n->items[i] : n)->source < 0) return items ? n->items[i] : n;
    }
    return group;
}

/* The longest span of the ropes between two supports (docs/assumptions.md, "Ranges of the inputs"). */
#define CS_MAX_SPAN 100.0

/* The first post (in x order) lower than height, or n if none, from low[p], the lowest of posts 0 to p,
 * which never rises along p: a bisection, so that c cables against n posts cost n + c log n, not c n. */
static int first_below(cs_loader *l, const double *low, int n, double height) {
    int lo = 0, hi = n;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (low[mid] < height)
            hi = mid;
        else
            lo = mid + 1;
    }
    l->work++; /* one look-up (its log2 n probes not counted) */
    return lo;
}

static void check_barrier(cs_loader *l, const cs_node *barrier, const cs_barrier_def *b) {
    const cs_node *cables = cs_node_get(barrier, "cables"), *anchors = cs_node_get(barrier, "anchors");
    const cs_post_def *first = &b->posts[0], *last = &b->posts[b->post_count - 1];
    const cs_node *rails = cs_node_get(barrier, "rails");
    double *low = cs_arena_alloc(l, (size_t)b->post_count * sizeof *low);
    if (!low) {
        cs_err_at(l, INT_MIN, 0, 0, "out of memory");
        return;
    }
    for (int p = 0; p < b->post_count; p++, l->work++)
        low[p] = p && low[p - 1] < b->posts[p].height ? low[p - 1] : b->posts[p].height;
    for (int r = 0; r < b->rail_count; r++) {
        int p = first_below(l, low, b->post_count, b->rails[r].height);
        if (p < b->post_count)
            cs_err_node(
                l, blamed(at(rails->items[r], "height"), at(l->post_origin[p], "height")), 0,
                "the rail (%g m) is above the top of the post at x = %g m (%g m) (expected a height up "
                "to the posts' tops)",
                b->rails[r].height, b->posts[p].x, b->posts[p].height);
    }
    for (int c = 0; c < b->cable_count; c++) {
        int p = first_below(l, low, b->post_count, b->cables[c].height);
        if (p < b->post_count)
            cs_err_node(l, blamed(at(cables->items[c], "height"), at(l->post_origin[p], "height")), 0,
                        "the cable (%g m) is above the top of the post at "
                        "x = %g m (%g m) (expected a height up to the posts' tops)",
                        b->cables[c].height, b->posts[p].x, b->posts[p].height);
    }
    for (int c = 0; c < b->cable_count; c++)
        check_slip(l, cables->items[c], &b->cables[c]);
    const cs_node *start = at(anchors, "start"), *end = at(anchors, "end");
    for (int k = 0; k < 2; k++) {
        const cs_node *footing = cs_node_get(k ? end : start, "footing");
        const cs_node *limit = footing ? cs_node_get(footing, "rotation_limit") : NULL;
        if (limit)
            cs_err_node(
                l, limit, 0,
                "an anchor's footing has no rotation limit (expected none: a dead-man ploughs through "
                "the soil at its residual resistance and leaves it only when lifted past its uplift "
                "capacity)");
    }
    for (int p = 0; p <= b->post_count; p++) { /* the spans: anchor to post, post to post, post to anchor */
        double a = p ? b->posts[p - 1].x : b->start_anchor.x,
               z = p < b->post_count ? b->posts[p].x : b->end_anchor.x;
        if (z - a <= CS_MAX_SPAN) continue;
        const cs_node *place = p == 0 ? blamed(at(start, "x"), post_position(l->post_origin[0]))
                               : p == b->post_count
                                   ? blamed(at(end, "x"), post_position(l->post_origin[p - 1]))
                                   : l->post_origin[p];
        char span[80], from[80], to[80], most[80];
        const char *given = place->text ? place->text : "";
        cs_units_show(l->units, given, CS_Q_LENGTH, z - a, span, sizeof span);
        cs_units_show(l->units, given, CS_Q_LENGTH, a, from, sizeof from);
        cs_units_show(l->units, given, CS_Q_LENGTH, z, to, sizeof to);
        cs_units_show(l->units, given, CS_Q_LENGTH, CS_MAX_SPAN, most, sizeof most);
        cs_err_node(
            l, place, 0,
            "the ropes span %s unsupported from x = %s to %s (expected at most %s between an anchor and "
            "a post or two posts: a cable barrier's spans are a few metres, its end spans up to about 15 m)",
            span, from, to, most);
        break;
    }
    if (b->start_anchor.x >= first->x)
        cs_err_node(l, blamed(at(start, "x"), post_position(l->post_origin[0])), 0,
                    "the start anchor (x = %g m) is inside the barrier (expected it before "
                    "the first post at x = %g m, not at it or beyond)",
                    b->start_anchor.x, first->x);
    if (b->end_anchor.x <= last->x)
        cs_err_node(l, blamed(at(end, "x"), post_position(l->post_origin[b->post_count - 1])), 0,
                    "the end anchor (x = %g m) is inside the barrier (expected it after the "
                    "last post at x = %g m, not at it or before)",
                    b->end_anchor.x, last->x);
}

/* A run's frames (t_end / output_interval, or / dt for a frame every step): a million frames of a roadside
 * barrier are about 0.8 GB of timeseries.csv, and its record as much in memory. */
enum { CS_MAX_FRAMES = 1000000 };

/* The x of the anchor at the end of the barrier that x is beyond, for a check of where the impact falls:
 * blamed() names a --set of it. */
static const cs_node *anchor_x(const cs_loader *l, const cs_barrier_def *b, double x) {
    return cs_node_get(cs_node_get(l->anchors_node, x <= b->start_anchor.x ? "start" : "end"), "x");
}

static void check_scenario(cs_loader *l, const cs_node *sc, const cs_scenario_def *s, const cs_barrier_def *b,
                           const cs_vehicle_def *v) {
    if (b && (s->impact_x <= b->start_anchor.x || s->impact_x >= b->end_anchor.x))
        cs_err_node(l, blamed(at(sc, "impact_x"), anchor_x(l, b, s->impact_x)), 0,
                    "the impact point (%g m) is outside the barrier (expected between "
                    "the anchors, above %g m and below %g m)",
                    s->impact_x, b->start_anchor.x, b->end_anchor.x);
    else if (b && v && v->front_width > 0.0 && s->angle > 0.0 && s->angle < CS_PI) {
        double corner;
        cs_scenario_impact_points(s, v->front_width, NULL, &corner);
        const cs_node *width = l->vehicle_node ? cs_node_get(l->vehicle_node, "front_width") : NULL;
        if (corner <= b->start_anchor.x || corner >= b->end_anchor.x)
            cs_err_node(
                l,
                blamed(blamed(at(sc, at(sc, "angle") ? "angle" : "impact_x"), anchor_x(l, b, corner)), width),
                0,
                "at %g deg the leading front corner of the vehicle's %.2f-m face meets the cable line at x = "
                "%.2f m, %.2f m before the face's centre, outside the barrier (%.2f m to %.2f m): the "
                "vehicle would pass the barrier's end, not strike it (expected that corner between the "
                "anchors: move impact_x, or give impact_at: corner to place the corner there)",
                s->angle * 180.0 / CS_PI, v->front_width, corner, fabs(corner - s->impact_x),
                b->start_anchor.x, b->end_anchor.x);
    }
    if (b) return; /* the rest was checked without the barrier */
    above(l, sc, "t_end", s->t_end, "dt", s->dt);
    /* the default interval below the step is a frame every step, as the engine records it (step.c) */
    const cs_node *given = cs_node_get(sc, "output_interval"), *every = at(sc, "output_interval");
    double frames = s->t_end / (s->output_interval > s->dt ? s->output_interval : s->dt);
    if (given && s->output_interval > 0.0 && s->output_interval < s->dt)
        cs_err_node(
            l, blamed(given, cs_node_get(sc, "dt")), 0,
            "output_interval %g s is below the time step dt, %g s: no frame can come between two steps "
            "(expected output_interval at least dt, or 0 for a frame every step)",
            s->output_interval, s->dt);
    else if (every && frames > CS_MAX_FRAMES)
        cs_err_node(
            l, every, 0,
            "%.3g frames to the end time (t_end / output_interval, or / dt for 0) exceed the limit of %.0g "
            "(expected a longer interval)",
            frames, (double)CS_MAX_FRAMES);
    /* above a tenth of the impact speed, a vehicle still moving would count as stopped */
    if (!(s->stop_speed <= CS_STOP_SPEED_SHARE * s->speed)) {
        char a[80], b[80];
        shown(l, sc, "stop_speed", s->stop_speed, a, sizeof a);
        shown(l, sc, "speed", s->speed, b, sizeof b);
        cs_err_node(
            l, blamed(at(sc, "stop_speed"), cs_node_get(sc, "speed")), 0,
            "stop_speed %s is not small against the impact speed %s: a vehicle slower than it counts as "
            "stopped (expected at most a tenth of the speed)",
            a, b);
    }
}

static const cs_node *need(cs_loader *l, const cs_node *root, const char *key, const char *hint) {
    const cs_node *n = cs_node_get(root, key);
    if (!n && !given_but_bad(l, root, key)) cs_err_node(l, root, 0, "missing '%s' (expected %s)", key, hint);
    return n;
}

/* Why a model's name cannot name its output folder (results/NAME, results/NAME-designer), or NULL: a
 * name is one folder's name inside results/, shown on the terminal as it is. */
static const char *unfit_name(const char *s) {
    if (!s[0]) return "it is empty";
    if (s[0] == '.') return "it begins with '.'";
    if (strstr(s, "..")) return "it holds '..'";
    if (strchr(s, '/')) return "it holds '/'";
    for (const unsigned char *p = (const unsigned char *)s; *p; p++)
        if (*p < 0x20 || *p == 0x7f) return "it holds a control character";
    if (strlen(s) > 100) return "it is longer than 100 characters";
    return NULL;
}

int cs_convert_model(cs_loader *l, const cs_node *root, const char *file, cs_model_input *out) {
    int before = l->error_count;
    const cs_node *name = cs_node_get(root, "name");
    const char *base = strrchr(file, '/') ? strrchr(file, '/') + 1 : file, *why;
    char stem[256];
    snprintf(stem, sizeof stem, "%.*s", (int)strcspn(base, "."), base);
    if (unfit_name(stem)) snprintf(stem, sizeof stem, "model"); /* a file name that cannot name a folder */
    if (name && name->text && (why = unfit_name(name->text)) != NULL)
        cs_err_node(l, name, 0,
                    "not a name for the output folder results/NAME: %s (expected a name such as "
                    "aps3-6ft: no '/', '..', leading '.' or control character)",
                    why);
    out->name = cs_arena_strdup(l, name && name->text ? name->text : stem);
    out->file = file;
    const cs_node *barrier = need(l, root, "barrier", "a barrier mapping, or barrier: {file: other.yaml}");
    const cs_node *vehicle = need(l, root, "vehicle", "a vehicle part's name, e.g. vehicle: M");
    const cs_node *scenario = need(l, root, "scenario", "a scenario mapping with speed and impact_x");
    l->vehicle_node = vehicle;
    l->scenario_node = scenario;
    if (vehicle) cs_convert_vehicle(l, vehicle, &out->vehicle);
    out->scenario = cs_default_scenario_def();
    int scenario_ok = scenario && fields(l, scenario, &out->scenario, 1) == 0 && !cs_damaged(scenario);
    if (scenario_ok) check_scenario(l, scenario, &out->scenario, NULL, NULL);
    if (!barrier) return l->error_count - before;
    int barrier_before = l->error_count;
    out->barrier = cs_default_barrier_def();
    check_required(l, barrier);
    const cs_node *cables = cs_node_get(barrier, "cables"), *anchors = cs_node_get(barrier, "anchors");
    l->anchors_node = anchors;
    const cs_node *soil = cs_node_get(barrier, "soil");
    l->soil_node = soil;
    if (soil)
        fields(l, soil, &out->barrier.start_anchor.footing, 0),
            fields(l, soil, &out->barrier.end_anchor.footing, 0);
    if (anchors) fields(l, anchors, &out->barrier, 1);
    if (cables && cables->count == 0) cs_err_node(l, cables, 0, "no cables (expected at least one)");
    cs_cable_def *defs = cables ? cs_arena_alloc(l, (size_t)cables->count * sizeof *defs + 1) : NULL;
    l->cable_origin = cables ? cs_arena_alloc(l, (size_t)cables->count * sizeof *l->cable_origin + 1) : NULL;
    for (int c = 0; defs && l->cable_origin && c < cables->count; c++) {
        convert_cable(l, cables->items[c], &defs[c]);
        l->cable_origin[c] = cables->items[c];
    }
    out->barrier.cables = defs;
    out->barrier.cable_count = cables ? cables->count : 0;
    const cs_node *rails = cs_node_get(barrier, "rails");
    cs_rail_def *rail_defs = rails ? cs_arena_alloc(l, (size_t)rails->count * sizeof *rail_defs + 1) : NULL;
    for (int r = 0; rail_defs && r < rails->count; r++)
        convert_rail(l, rails->items[r], &rail_defs[r]);
    out->barrier.rails = rail_defs;
    out->barrier.rail_count = rails ? rails->count : 0;
    convert_posts(l, barrier, &out->barrier);
    if (l->error_count == barrier_before && !cs_damaged(barrier)) {
        check_barrier(l, barrier, &out->barrier);
        if (scenario_ok && l->error_count == barrier_before)
            check_scenario(l, scenario, &out->scenario, &out->barrier, vehicle ? &out->vehicle : NULL);
    }
    return l->error_count - before;
}
