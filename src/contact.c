/* Contact between the vehicle's front face and the cables.
 *
 * In plan the face is the segment between its two corners. A cable whose straight path the face has
 * crossed wraps the face: each corner that lies on the protected side of the path (to the left of the
 * path directed from the start anchor to the end anchor) becomes a support of the cable, with capstan
 * friction (cable.c). Between the vehicle and the nearest standing posts the cable stays straight.
 * Both tests are in 3D: a corner is tested where the rope runs at its abscissa (a pitched face is not
 * where it is at the CG's height), and released when the rope no longer pulls it into the face.
 *
 * Heights: a cable engages at its height on the span it runs on (the straight line between its
 * neighbouring supports); below the face's bottom edge at first contact the vehicle rides over it
 * (override), above the top edge it runs under it (underride). Once engaged, the contact's height on the
 * face is an unknown of the barrier solve with Coulomb friction on the vertical face: it sticks while the
 * spans' pull along the face is at most mu times their pull into it, else it slides with the pull
 * (solve.c, cs_contact_solve_height). A contact that slides past an edge slips off the same way. Either
 * way the cable leaves the contact for good. */
#include "internal.h"
#include "vec3.h"

#include <math.h>

static const int corner_id[2] = {CS_NODE_LEFT, CS_NODE_RIGHT};

static double corner_y(const cs_model *model, int k) {
    return (k == 0 ? 0.5 : -0.5) * model->vehicle.def.front_width;
}

static int is_corner(int id) {
    return id == CS_NODE_LEFT || id == CS_NODE_RIGHT;
}

static int find_node(const cs_cable_state *cs, int id) {
    for (int i = 0; i < cs->node_count; i++)
        if (cs->node[i] == id) return i;
    return -1;
}

/* > 0 if p lies to the left of the directed line a -> b in plan. */
static double left_of(const double *a, const double *b, const double *p) {
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
}

/* Height of the rope's straight span between nodes lo and hi at abscissa x. */
static double span_height(const cs_cable_state *cs, int lo, int hi, double x) {
    const double *a = cs->pos + 3 * lo, *b = cs->pos + 3 * hi;
    double f = (b[0] - a[0]) != 0.0 ? (x - a[0]) / (b[0] - a[0]) : 0.5;
    f = f < 0.0 ? 0.0 : (f > 1.0 ? 1.0 : f);
    return a[2] + f * (b[2] - a[2]);
}

/* World z of the face's bottom and top edges at a corner, and the body z that maps to world z. */
static void face_heights(const cs_model *model, const cs_state *s, int k, double *bottom, double *top) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double p[3];
    cs_vehicle_face_point(model, s, s->crush, corner_y(model, k), v->face_bottom - v->cg_height, p);
    *bottom = p[2];
    cs_vehicle_face_point(model, s, s->crush, corner_y(model, k), v->face_top - v->cg_height, p);
    *top = p[2];
}

static double body_z_for(const cs_model *model, const cs_state *s, int k, double zw) {
    double p0[3], p1[3];
    cs_vehicle_face_point(model, s, s->crush, corner_y(model, k), 0.0, p0);
    cs_vehicle_face_point(model, s, s->crush, corner_y(model, k), 1.0, p1);
    return (zw - p0[2]) / (p1[2] - p0[2]);
}

/* The cable's pull on contact node i in the vehicle frame: up the face (fz) and normal to it (fn). */
void cs_contact_face_force(const cs_model *model, const cs_state *s, int c, int i, const double *chords,
                           double *fz, double *fn) {
    double f[3], fb[3];
    cs_node_force(&s->cables[c], i, chords, f);
    quat_unrotate(fb, s->quat, f);
    *fz = fb[2];
    *fn = v2_norm(fb[0], fb[1]);
    (void)model;
}

/* dir * F_z - mu F_n - the friction floor with the contact of corner k at body height z (the rope in
 * the spans held). */
static double height_excess(const cs_model *model, cs_state *s, int c, int i, int k, double z, int dir) {
    cs_cable_state *cs = &s->cables[c];
    const cs_cable_model *cm = &model->cables[c];
    cs->corner_z[k] = z;
    cs_vehicle_face_point(model, s, s->crush, corner_y(model, k), z, cs->pos + 3 * i);
    cs->tension[i - 1] = cs_span_tension(cm, cs, i - 1);
    cs->tension[i] = cs_span_tension(cm, cs, i);
    double fz, fn;
    cs_contact_face_force(model, s, c, i, NULL, &fz, &fn);
    return dir * fz - model->vehicle.def.face_friction * fn - CS_FRICTION_FLOOR * cm->rope.fu;
}

/* Local solve of a contact's height (Coulomb friction on the vertical face, measured from where it was
 * at the end of the last step): it sticks while |F_z| <= mu F_n, else slides with the pull until
 * |F_z| = mu F_n (bisection over up to 2 m). Returns the relative violation found on entry. */
double cs_contact_solve_height(const cs_model *model, cs_state *s, int c, int i, int k, double tol) {
    cs_cable_state *cs = &s->cables[c];
    double z0 = cs->corner_z_commit[k], fu = model->cables[c].rope.fu;
    double up = height_excess(model, s, c, i, k, z0, 1), down = height_excess(model, s, c, i, k, z0, -1);
    int dir = up > 0.0 ? 1 : (down > 0.0 ? -1 : 0);
    double entry = 0.0;
    {
        double fz, fn;
        height_excess(model, s, c, i, k, cs->corner_z[k], 1);
        cs_contact_face_force(model, s, c, i, NULL, &fz, &fn);
        double b = model->vehicle.def.face_friction * fn + CS_FRICTION_FLOOR * fu, dz = cs->corner_z[k] - z0;
        entry =
            (fabs(fz) > b || (dz != 0.0 && fabs(fabs(fz) - b) > tol * fu)) ? fabs(fabs(fz) - b) / fu : 0.0;
    }
    if (dir == 0) {
        height_excess(model, s, c, i, k, z0, 1);
        return entry;
    }
    double a = z0, b = z0 + 2.0 * dir;
    if (height_excess(model, s, c, i, k, b, dir) > 0.0) return entry; /* pulled off the face */
    for (int it = 0; it < 60; it++) {
        double m = 0.5 * (a + b);
        if (height_excess(model, s, c, i, k, m, dir) > 0.0)
            a = m;
        else
            b = m;
    }
    height_excess(model, s, c, i, k, b, dir);
    return entry;
}

static void slip(const cs_model *model, cs_state *s, int c, cs_event_type why) {
    cs_cable_state *cs = &s->cables[c];
    s->e_released += cs_cable_stored_energy(&model->cables[c], cs);
    for (int i = cs->node_count - 2; i >= 1; i--)
        if (is_corner(cs->node[i])) cs_cable_remove_node(cs, i);
    cs->status = CS_CABLE_SLIPPED;
    cs->engaged = 0;
    cs_event_add(model, s, why, CS_ELEMENT_CABLE, c, s->t);
}

void cs_contact_place_corners(const cs_model *model, cs_state *s, double crush) {
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (!cs->engaged) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            int k = cs->node[i] == CS_NODE_LEFT ? 0 : (cs->node[i] == CS_NODE_RIGHT ? 1 : -1);
            if (k >= 0)
                cs_vehicle_face_point(model, s, crush, corner_y(model, k), cs->corner_z[k], cs->pos + 3 * i);
        }
    }
}

static void update_cable(const cs_model *model, cs_state *s, int c) {
    cs_cable_state *cs = &s->cables[c];
    cs_contact_place_corners(model, s, s->crush);
    /* release corners the rope no longer pulls into the face (its pull along the body's x, the face's
     * normal, is not backwards): tested in 3D, as a rope on a pitched face slides down it below the
     * line it runs on in plan while it still bears on the face */
    for (int i = cs->node_count - 2; i >= 1; i--) {
        if (!is_corner(cs->node[i])) continue;
        double f[3], fb[3];
        cs_node_force(cs, i, NULL, f);
        quat_unrotate(fb, s->quat, f);
        if (fb[0] >= 0.0) cs_cable_remove_node(cs, i);
    }
    /* engage corners that have crossed the path */
    for (int k = 0; k < 2; k++) {
        if (find_node(cs, corner_id[k]) >= 0) continue;
        double lo, hi, p[3], zn = 0.0, bz = 0.0;
        face_heights(model, s, k, &lo, &hi);
        int j = 1;
        /* the corner at the rope's own height: where the rope would touch it (a pitched or rolled face
         * is not where it is at the CG's height); the rope's height there found by two passes */
        for (int pass = 0; pass < 2; pass++) {
            cs_vehicle_face_point(model, s, s->crush, corner_y(model, k), bz, p);
            for (j = 1; j < cs->node_count - 1 && cs->pos[3 * j] <= p[0];)
                j++;
            zn = span_height(cs, j - 1, j, p[0]);
            bz = body_z_for(model, s, k, zn);
        }
        if (p[0] <= cs->pos[0] || p[0] >= cs->pos[3 * (cs->node_count - 1)])
            continue; /* beyond the anchors */
        if (left_of(cs->pos + 3 * (j - 1), cs->pos + 3 * j, p) <= 0.0) continue;
        if (zn < lo || zn > hi) {
            slip(model, s, c, zn < lo ? CS_EVENT_OVERRIDE : CS_EVENT_UNDERRIDE);
            return;
        }
        cs->corner_z[k] = cs->corner_z_commit[k] = bz;
        cs_vehicle_face_point(model, s, s->crush, corner_y(model, k), cs->corner_z[k], p);
        cs_cable_insert_node(cs, j, corner_id[k], p);
    }
    cs->engaged = find_node(cs, CS_NODE_LEFT) >= 0 || find_node(cs, CS_NODE_RIGHT) >= 0;
    if (cs->engaged && !s->contact_started) {
        s->contact_started = 1;
        s->summary.first_contact_time = s->t;
    }
}

/* Bring every intact cable's path in line with the vehicle's new pose. */
void cs_contact_update(const cs_model *model, cs_state *s) {
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].status == CS_CABLE_INTACT) update_cable(model, s, c);
}

/* End of step: friction work of contacts that slid along the face (|dz| |F_z|, F_z at the bound). */
void cs_contact_commit(const cs_model *model, cs_state *s) {
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT || !cs->engaged) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (!is_corner(cs->node[i])) continue;
            int k = cs->node[i] == CS_NODE_LEFT ? 0 : 1;
            double fz, fn;
            cs_contact_face_force(model, s, c, i, NULL, &fz, &fn);
            s->e_friction += fabs(cs->corner_z[k] - cs->corner_z_commit[k]) * fabs(fz);
            cs->corner_z_commit[k] = cs->corner_z[k];
        }
    }
}

/* A contact that slid past the face's edge leaves it: the cable slips off (below: the vehicle rides
 * over it; above: it runs under it). Returns 1 if any did. */
int cs_contact_check_slip(const cs_model *model, cs_state *s) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double lo = v->face_bottom - v->cg_height, hi = v->face_top - v->cg_height;
    int any = 0;
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT || !cs->engaged) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (!is_corner(cs->node[i])) continue;
            double z = cs->corner_z[cs->node[i] == CS_NODE_LEFT ? 0 : 1];
            if (z >= lo && z <= hi) continue;
            slip(model, s, c, z < lo ? CS_EVENT_OVERRIDE : CS_EVENT_UNDERRIDE);
            any = 1;
            break;
        }
    }
    return any;
}

/* Take failed posts out of every path and release the cables of failed anchors. */
void cs_contact_drop_failed(const cs_model *model, cs_state *s) {
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        if (s->anchor_failed[0] || s->anchor_failed[1]) {
            cs->status = CS_CABLE_RELEASED;
            cs->engaged = 0;
            continue;
        }
        for (int i = cs->node_count - 2; i >= 1; i--)
            if (cs->node[i] >= 0 && !cs_post_standing(&s->posts[cs->node[i]])) cs_cable_remove_node(cs, i);
    }
}
