/* SPDX-License-Identifier: MIT */
/* Contact between the vehicle's outline and the cables.
 *
 * In plan the vehicle is a rectangle: the front face between its two front corners, the sides back to
 * the two rear corners (vehicle.c). A cable whose straight path a corner has crossed wraps it: each corner
 * that lies on the protected side of the path (to the left of the path directed from the start anchor to
 * the end anchor) becomes a support of the cable, with capstan friction (cable.c), so a cable bears on
 * the face head-on, on the front corner and along a side at an angle (straight between the front and rear
 * corners: the side is flat), and on the rear corner as the rear swings in. The four tyres, at their axles
 * in the sides' planes, take what passes under the body: a rear wheel (from the ground to the side's top)
 * a rope that runs under the rear overhang, a front wheel (from its axle's height up) one that runs under
 * the bumper; a wheel takes no rope the corner on its side holds. Between the vehicle and the nearest
 * standing posts the cable stays straight. Both tests are in 3D: a corner is tested where the rope runs at
 * its abscissa (a pitched body is not where it is at the CG's height), and released when the rope no
 * longer presses it into the outline: when its pull has a component out through the face (or the rear)
 * or out through the side at that corner.
 *
 * Heights: a cable engages at its height on the span it runs on (the straight line between its
 * neighbouring supports). Above a front corner's band the vehicle runs under it (underride), below a front
 * tyre's axle the tyre climbs over it (override). A corner or wheel that finds the cable otherwise out of
 * its band passes below or above it and does not engage, and goes on passing it while it stays across it
 * (`passing`): below the bumper the front wheel meets it, below the sill the rear wheel. Once engaged, the
 * contact's height at the corner is an unknown of the barrier solve with Coulomb friction on the vertical
 * body: it sticks while the spans' pull along the body is at most mu times their pull into it, else it
 * slides with the pull (its row below). A contact that slides past an edge slips off the vehicle for good
 * (override or underride): the vehicle passes over or under the rope, which stays anchored and strung over
 * its posts, out of contact with the vehicle; one that slides down off a corner of the outline is handed to
 * its wheel. */
#include "core/vec3.h"
#include "elements/rows.h"

#include <math.h>

/* > 0 if p lies to the left of the directed line a -> b in plan. */
static double left_of(const double *a, const double *b, const double *p) {
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
}

/* Height of the rope on span i (nodes i and i + 1) at abscissa x: its chord less its sag there. The span
 * hangs as a shallow parabola under its weight across the chord, w h / l (h the chord's length in plan, l
 * its length), at tension T: at fraction f along it the rope is w h l f (1 - f) / (2 T) below the chord,
 * h / l of that straight down (the sag of cs_cable_stored_energy's term). A corner engages the rope where
 * it hangs, so the two spans it makes hang on the same curve: no weight is lifted at the engagement. */
static double span_height(const cs_cable_model *cm, const cs_cable_state *cs, int i, double x) {
    const double *a = cs->pos + 3 * i, *b = cs->pos + 3 * (i + 1);
    double f = (b[0] - a[0]) != 0.0 ? (x - a[0]) / (b[0] - a[0]) : 0.5;
    f = f < 0.0 ? 0.0 : (f > 1.0 ? 1.0 : f);
    double t = cs->tension[i], h2 = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
    double sag = t > 0.0 ? cm->rope.w * h2 * f * (1.0 - f) / (2.0 * t) : 0.0;
    return a[2] + f * (b[2] - a[2]) - sag;
}

/* World z of corner k's band's bottom and top edges, and the body z that maps to world z. */
static void corner_heights(const cs_model *model, const cs_state *s, int k, double *bottom, double *top) {
    double lo, hi, p[3];
    cs_vehicle_corner_band(model, k, &lo, &hi);
    cs_vehicle_corner_point(model, s, s->crush, k, lo, p);
    *bottom = p[2];
    cs_vehicle_corner_point(model, s, s->crush, k, hi, p);
    *top = p[2];
}

static double body_z_for(const cs_model *model, const cs_state *s, int k, double zw) {
    double p0[3], p1[3];
    cs_vehicle_corner_point(model, s, s->crush, k, 0.0, p0);
    cs_vehicle_corner_point(model, s, s->crush, k, 1.0, p1);
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

/* The sag term q of span i (cs_span_sag): the sag's weight below its chord is -q / (12 T). */
static double sag_of(const cs_cable_model *cm, const cs_cable_state *cs, int i) {
    double d[4];
    cs_span_chord(cs, i, d);
    return cs_span_sag(&cm->rope, d);
}

/* Let go the corner at node i of a rope: its two spans join. Returns the change of the sag's reference
 * this makes, to be booked with the released energy: the joined chord at the tension the left span had,
 * which the joined span keeps until the next solve (docs/theory.md, The vehicle's outline and contact at an
 * angle, "Engaging"). */
static double let_go(const cs_cable_model *cm, cs_cable_state *cs, int i) {
    double t = cs->tension[i - 1], split = sag_of(cm, cs, i - 1) + sag_of(cm, cs, i);
    cs_cable_remove_node(cs, i);
    return t > 0.0 ? (sag_of(cm, cs, i - 1) - split) / (12.0 * t) : 0.0;
}

/* The vehicle goes over or under cable c (why: override or underride), for good: every corner lets it go
 * and it stays in the barrier, anchored and strung over its posts, where the next solve finds its
 * tensions (docs/theory.md, Energy ledger, "A rope that slips off the face"). Returns the change of the
 * sag's reference the corners let go make. */
static double slip(const cs_model *model, cs_state *s, int c, cs_event_type why) {
    cs_cable_state *cs = &s->cables[c];
    double reference = 0.0;
    for (int i = cs->node_count - 2; i >= 1; i--)
        if (cs_node_is_corner(cs->node[i])) reference += let_go(&model->cables[c], cs, i);
    cs->engaged = 0;
    cs->passed = 1;
    cs_event_add(model, s, why, CS_ELEMENT_CABLE, c, s->t);
    if (!s->contact_started) { /* the vehicle met the cable, if only to pass it */
        s->contact_started = 1;
        s->summary.first_contact_time_s = s->t;
    }
    return reference;
}

void cs_contact_place_one(const cs_model *model, cs_state *s, int c, int i, int k, double z) {
    cs_cable_state *cs = &s->cables[c];
    cs->corner_z[k] = z;
    cs_vehicle_corner_point(model, s, s->crush, k, z, cs->pos + 3 * i);
}

void cs_contact_place_corners(const cs_model *model, cs_state *s, double crush) {
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (!cs->engaged) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (!cs_node_is_corner(cs->node[i])) continue;
            int k = cs_node_corner(cs->node[i]);
            cs_vehicle_corner_point(model, s, crush, k, cs->corner_z[k], cs->pos + 3 * i);
        }
    }
}

static void set_engaged(cs_cable_state *cs) {
    cs->engaged = 0;
    for (int i = 1; i + 1 < cs->node_count; i++)
        cs->engaged |= cs_node_is_corner(cs->node[i]);
}

/* Whether the rope at node i still wraps corner k: the sum of the unit vectors along its two spans (the
 * direction it would pull the corner with equal tensions: the geometry of the turn, whatever friction
 * does to the tensions) has no component out through the face (the rear, for a rear corner) or out
 * through the side at that corner. In the body frame, so a rope on a pitched face that slides down it
 * below the line it runs on in plan still bears on it. A rope that runs straight along the face or the
 * side turns neither in nor out there, and stays. */
static int wraps(const cs_state *s, const cs_cable_state *cs, int i, int k) {
    double a[3], b[3], g[3], gb[3];
    v3_sub(a, cs->pos + 3 * (i - 1), cs->pos + 3 * i);
    v3_sub(b, cs->pos + 3 * (i + 1), cs->pos + 3 * i);
    double la = v3_norm(a), lb = v3_norm(b);
    if (!(la > 0.0 && lb > 0.0)) return 1;
    for (int e = 0; e < 3; e++)
        g[e] = a[e] / la + b[e] / lb;
    quat_unrotate(gb, s->quat, g);
    double out_end = cs_corner_front(k) ? gb[0] : -gb[0], out_side = k % 2 == 0 ? gb[1] : -gb[1];
    return (cs_corner_wheel(k) || out_end < 0.0) && out_side <= 1e-12; /* a wheel is mid-side */
}

/* How far across a rope's path a rear corner can come in one step: three times the vehicle's travel in
 * it, at least 5 cm (a corner turning with the body moves little more than the body). */
static double rear_reach(const cs_model *model, const cs_state *s) {
    return fmax(0.05, 3.0 * v3_norm(s->vel) * model->scenario.dt);
}

/* How many corners and wheels hold the rope: a tyre that climbs over a rope another one holds passes it,
 * and the rope stays on the vehicle where it is held. */
static int holders(const cs_cable_state *cs) {
    int n = 0;
    for (int i = 1; i + 1 < cs->node_count; i++)
        n += cs_node_is_corner(cs->node[i]);
    return n;
}

/* Body z of the axle of the front wheel behind front corner k: its band's bottom. */
static double axle_z(const cs_model *model, int k) {
    double lo, hi;
    cs_vehicle_corner_band(model, cs_wheel_of(k), &lo, &hi);
    return lo;
}

static void update_cable(const cs_model *model, cs_state *s, int c) {
    cs_cable_state *cs = &s->cables[c];
    /* the changes of the sag's reference made below (a corner let go joins its two spans at one tension
     * until the next solve: joined at once they would release the spans' difference, (T_l^2 - T_r^2) s_r /
     * 2EA, more than the rope holds) */
    double reference = 0.0;
    cs_contact_place_corners(model, s, s->crush);
    /* release the corners it no longer wraps, keeping where the rope was on each: a corner taken up again
     * below (its turn can point out through the side and back within an update, as on a rope rising from
     * an anchor at grade under the body) goes on from there, not from a contact set afresh, whose move
     * back would be booked as a slide against friction that the rope never made (or a slide missed) */
    int released[CS_CORNERS] = {0};
    double was_m[CS_CORNERS], was_m_commit[CS_CORNERS];
    for (int i = cs->node_count - 2; i >= 1; i--) {
        if (!cs_node_is_corner(cs->node[i])) continue;
        int k = cs_node_corner(cs->node[i]);
        if (wraps(s, cs, i, k)) continue;
        released[k] = 1, was_m[k] = cs->m[i], was_m_commit[k] = cs->m_commit[i];
        reference += let_go(&model->cables[c], cs, i);
    }
    /* engage corners that have crossed the path */
    for (int k = 0; k < CS_CORNERS; k++) {
        if (cs_cable_find_node(cs, cs_corner_node(k)) >= 0) continue;
        /* a rope on a corner runs straight along the side past its wheel */
        if (cs_corner_wheel(k) && cs_cable_find_node(cs, cs_corner_node(cs_wheel_corner(k))) >= 0) {
            cs->passing &= ~(1 << k);
            continue;
        }
        double lo, hi, p[3], zn = 0.0, bz = 0.0;
        corner_heights(model, s, k, &lo, &hi);
        int j = 1;
        /* the corner at the rope's own height: where the rope would touch it (a pitched or rolled body
         * is not where it is at the CG's height); the rope's height there found by two passes */
        for (int pass = 0; pass < 2; pass++) {
            cs_vehicle_corner_point(model, s, s->crush, k, bz, p);
            for (j = 1; j < cs->node_count - 1 && cs->pos[3 * j] <= p[0];)
                j++;
            zn = span_height(&model->cables[c], cs, j - 1, p[0]);
            bz = body_z_for(model, s, k, zn);
        }
        if (p[0] <= cs->pos[0] || p[0] >= cs->pos[3 * (cs->node_count - 1)])
            continue; /* beyond the anchors */
        double across = left_of(cs->pos + 3 * (j - 1), cs->pos + 3 * j, p);
        int bit = 1 << k;
        if (across <= 0.0) {
            cs->passing &= ~bit;
            continue;
        }
        /* a corner (or wheel) that crossed the path with the rope out of its band has passed under or
         * over it, and a rear corner or wheel found deep across it did so while it was: the rope stays
         * there as long as the corner is across, however the rope's height moves. Only one that crosses it
         * within a step (its reach) with the rope in its band takes it up, or a wheel the rope was handed
         * to as it slid past the face's or the side's bottom */
        int fresh = !released[k] && !(cs->handover & bit);
        int deep = fresh && !(cs->passing & bit) && !cs_corner_front(k) && /* measured only if it decides */
                   across > rear_reach(model, s) * v2_norm(cs->pos[3 * j] - cs->pos[3 * (j - 1)],
                                                           cs->pos[3 * j + 1] - cs->pos[3 * (j - 1) + 1]);
        if (fresh && ((cs->passing & bit) || deep)) {
            cs->passing |= bit;
            continue;
        }
        /* a corner that let the rope go in this update and is across its path again takes it back where it
         * held it (its corner_z kept): the joined span's chord height there is no rope's height. Out of
         * its band: over the face's top the vehicle runs under the rope; below a front tyre's axle, met
         * at the wheel or already at the bumper, the tyre climbs over it, and the vehicle rides over the
         * rope unless another point holds it; otherwise the corner or wheel passes the rope, and below
         * the bumper or the sill the wheel behind it meets it next */
        if (!released[k] && (zn < lo || zn > hi)) {
            int under = cs_corner_front(k) && zn > hi;
            int over = zn < lo && (cs_corner_front_wheel(k) || (cs_corner_front(k) && bz < axle_z(model, k)));
            if (!under && (!over || holders(cs) > 0)) {
                cs->passing |= bit;
                continue;
            }
            s->e_released += reference + slip(model, s, c, over ? CS_EVENT_OVERRIDE : CS_EVENT_UNDERRIDE);
            return;
        }
        if (!released[k]) cs->corner_z[k] = cs->corner_z_commit[k] = bz;
        cs_vehicle_corner_point(model, s, s->crush, k, cs->corner_z[k], p);
        /* The sag's weight is measured from each span's chord (cs_cable_stored_energy): a corner that
         * takes up a hanging rope where it hangs changes nothing real, but splits a chord in two, and
         * with it that reference, by w^2 l^3 / (16 T) for a corner at mid-span. No work is done: the
         * difference is booked with the released energy (docs/theory.md, The vehicle's outline and
         * contact at an angle, "Engaging"). The release above books the chords joined again, at the
         * tension the joined span keeps (its tension is found at the next solve, and the ledger follows
         * it there). A corner taken up again goes on with the rope it had. */
        double before = cs_cable_stored_energy(&model->cables[c], cs);
        cs_cable_insert_node(cs, j, cs_corner_node(k), p);
        cs->passing &= ~bit;
        if (released[k] && was_m[k] > cs->m[j - 1] && was_m[k] < cs->m[j + 1] &&
            was_m_commit[k] > cs->m_commit[j - 1] && was_m_commit[k] < cs->m_commit[j + 1])
            cs->m[j] = was_m[k], cs->m_commit[j] = was_m_commit[k];
        reference += before - cs_cable_stored_energy(&model->cables[c], cs);
    }
    /* a corner that holds the rope holds it straight along the side past its wheel */
    for (int k = 0; k < CS_OUTLINE_CORNERS; k++) {
        int w = cs_cable_find_node(cs, cs_corner_node(cs_wheel_of(k)));
        if (w > 0 && cs_cable_find_node(cs, cs_corner_node(k)) > 0)
            reference += let_go(&model->cables[c], cs, w);
    }
    s->e_released += reference;
    cs->handover = 0;
    set_engaged(cs);
    if (cs->engaged && !s->contact_started) {
        s->contact_started = 1;
        s->summary.first_contact_time_s = s->t;
    }
}

/* Bring the path of every intact cable the vehicle has not passed in line with the vehicle's new pose. */
void cs_contact_update(const cs_model *model, cs_state *s) {
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].status == CS_CABLE_INTACT && !s->cables[c].passed) update_cable(model, s, c);
}

/* End of step: friction work of contacts that slid along the face (|dz| |F_z|, F_z at the bound). */
void cs_contact_commit(const cs_model *model, cs_state *s) {
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT || !cs->engaged) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (!cs_node_is_corner(cs->node[i])) continue;
            int k = cs_node_corner(cs->node[i]);
            double fz, fn;
            cs_contact_face_force(model, s, c, i, NULL, &fz, &fn);
            s->e_friction += (cs->corner_z[k] - cs->corner_z_commit[k]) * fz;
            cs->corner_z_commit[k] = cs->corner_z[k];
        }
    }
}

/* A contact that slid past its band's edge leaves the vehicle: the cable slips off (below: the vehicle
 * rides over it; above: it runs under it) and stays in the barrier, except below a corner of the outline: a
 * rope sliding down off the bumper or the rear overhang meets the tyre behind or ahead of it, so the corner
 * lets it go, passes it (`passing`) and hands it to its wheel, which takes it at the update that follows
 * (whatever its depth across the rope's path) or when it comes across it. A rope that slides down a front
 * tyre below its axle is ridden over, unless another corner or wheel holds it: then the one it slid off
 * passes it. The failures' re-solve that follows books what the rope lets go of (step.c). Returns 1 if any
 * did. */
int cs_contact_check_slip(const cs_model *model, cs_state *s) {
    int any = 0;
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT || !cs->engaged) continue;
        for (int i = cs->node_count - 2; i >= 1; i--) {
            if (!cs_node_is_corner(cs->node[i])) continue;
            int k = cs_node_corner(cs->node[i]);
            double z = cs->corner_z[k], lo, hi;
            cs_vehicle_corner_band(model, k, &lo, &hi);
            if (z >= lo && z <= hi) continue;
            any = 1;
            int to_wheel = !cs_corner_wheel(k) && z < lo && !(cs_corner_front(k) && z < axle_z(model, k));
            if (to_wheel || (z < lo && holders(cs) > 1)) { /* to its wheel, or held elsewhere */
                let_go(&model->cables[c], cs, i);
                cs->passing |= 1 << k;
                if (to_wheel) cs->handover |= 1 << cs_wheel_of(k);
                set_engaged(cs);
                continue;
            }
            slip(model, s, c, z < lo ? CS_EVENT_OVERRIDE : CS_EVENT_UNDERRIDE);
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
        if (s->anchors[0].failed || s->anchors[1].failed) {
            cs_cable_release(cs, CS_CABLE_RELEASED);
            continue;
        }
        for (int i = cs->node_count - 2; i >= 1; i--)
            if (cs->node[i] >= 0 && !cs_post_in_barrier(&s->posts[cs->node[i]])) cs_cable_remove_node(cs, i);
    }
}

/* The body's axes in the world. */
static void body_axes(const cs_state *s, double ax[3][3]) {
    for (int k = 0; k < 3; k++) {
        double e[3] = {k == 0, k == 1, k == 2};
        quat_rotate(ax[k], s->quat, e);
    }
}

/* ---- the face: what pushes on it, and its rows of the barrier solve ----
 * Unknowns: each engaged contact's height on the face (Coulomb friction along the vertical face, as for a
 * support: lambda = the spans' pull up the face, b = mu times their pull into it plus the floor w, dz from
 * the last step; the floor holds the contact of a slack rope where it is), and the crush, whose row
 * balances the face's normal force N against the crush curve C: N(crush) - C(crush) = 0 (the paper's
 * crush correction). */

/* Whether anything pushes on the face: an intact cable wrapped on it or a standing post it struck. */
int cs_face_loaded(const cs_model *model, const cs_state *s) {
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].engaged && s->cables[c].status == CS_CABLE_INTACT) return 1;
    for (int p = 0; p < model->post_count; p++)
        if (s->posts[p].captured && s->posts[p].pusher == CS_PUSH_FACE && cs_post_in_barrier(&s->posts[p]))
            return 1;
    return 0;
}

/* Normal force on the face at the state as placed: the cables through the front corners plus the pushes
 * of captured posts, along the vehicle's heading. chords: every cable's (max_nodes spans each), or NULL. */
double cs_face_normal_force(const cs_model *model, const cs_state *s, const double *chords) {
    double ax[3][3], f[3] = {0.0, 0.0, 0.0}, mo[3] = {0.0, 0.0, 0.0}, pushed = 0.0;
    body_axes(s, ax);
    for (int p = 0; p < model->post_count; p++)
        if (s->posts[p].captured && s->posts[p].pusher == CS_PUSH_FACE && cs_post_in_barrier(&s->posts[p]))
            pushed += s->posts[p].push;
    double n = 0.0;
    if (pushed > 0.0) {
        cs_post_captured_force(model, s, s->crush, 1, f, mo);
        n = -v3_dot(f, ax[0]);
    }
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (!cs->engaged || cs->status != CS_CABLE_INTACT) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (!cs_node_is_corner(cs->node[i]) || !cs_corner_front(cs_node_corner(cs->node[i]))) continue;
            double fc[3];
            cs_node_force(cs, i, chords ? chords + 4 * (size_t)c * (size_t)model->max_nodes : NULL, fc);
            n -= v3_dot(fc, ax[0]);
        }
    }
    return n;
}

/* The band of a face contact's Coulomb friction for a pull F_n into the body: mu F_n, held up to the
 * friction floor w where the rope pulls little or nothing into it (cs_smooth_floor: exactly mu F_n where
 * mu F_n is 3.77 w or more, 1.28 w at F_n = 0); its slope in F_n into *slope if not NULL. */
double cs_contact_band(const cs_model *model, int c, double fn, double *slope) {
    double mu = model->vehicle.def.face_friction, s;
    double b = cs_smooth_floor(mu * fn, CS_FRICTION_FLOOR * model->cables[c].rope.fu, &s);
    if (slope) *slope = mu * s;
    return b;
}

/* The contact at corner k: Coulomb friction along the vertical body, as for a support (lambda = the
 * spans' pull up the body, b the band of their pull into it, dz from the last step). */
static double height_residual(const cs_model *model, const cs_state *s, const cs_rows *rows, int c, int k) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    const double *ch = cs_rows_chords(model, rows, c);
    int i = cs_cable_find_node(cs, cs_corner_node(k));
    double fz, fn;
    cs_contact_face_force(model, s, c, i, ch, &fz, &fn);
    double cstiff = cm->rope.ea / (ch[4 * (i - 1) + 3] + ch[4 * i + 3] + 1e-9);
    double dz = cs->corner_z[k] - cs->corner_z_commit[k];
    double proj = cs_smooth_clamp(fz + cstiff * dz, cs_contact_band(model, c, fn, NULL),
                                  CS_FRICTION_FLOOR * cm->rope.fu);
    return (fz - proj - CS_STICK_EPS * cstiff * dz) * (1.0 / cm->rope.fu);
}

/* A face contact's row (height_residual): r Fu = fz - proj(fz + c dz, band(fn), w) - eps c dz. */
static void height_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row, int c,
                            int k) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    int i = cs_cable_find_node(cs, cs_corner_node(k));
    const cs_span_grad *sp = cs_rows_spans(model, rows, c, i);
    double ax[3][3], f[3], fb[3], fu = cm->rope.fu;
    body_axes(s, ax);
    cs_node_force(cs, i, cs_rows_chords(model, rows, c), f);
    for (int e = 0; e < 3; e++)
        fb[e] = v3_dot(ax[e], f);
    double fn = v2_norm(fb[0], fb[1]), wf = CS_FRICTION_FLOOR * fu;
    double len = sp[0].l + sp[1].l + 1e-9, cstiff = cm->rope.ea / len,
           dz = cs->corner_z[k] - cs->corner_z_commit[k];
    double py, pb, db, band = cs_contact_band(model, c, fn, &db);
    cs_smooth_clamp_slopes(fb[2] + cstiff * dz, band, wf, &py, &pb);
    double rho[3], gp[3][3] = {{0}}, gm[3] = {0};
    for (int e = 0; e < 3; e++) {
        rho[e] = (1.0 - py) * ax[2][e];
        if (fn > 0.0) rho[e] -= pb * db * (fb[0] * ax[0][e] + fb[1] * ax[1][e]) / fn;
        rho[e] /= fu;
    }
    cs_rows_force_gradient(sp, rho, gp, gm);
    cs_rows_length_gradient(sp, -(py + CS_STICK_EPS) * dz * -cm->rope.ea / (len * len) / fu, gp);
    cs_rows_add_node_gradient(model, s, rows, row, c, i, gp, gm);
    cs_rows_add(rows, row, row, -(py + CS_STICK_EPS) * cstiff / fu); /* dz: the row's own unknown */
}

/* The crush row's dependence on everything but the crush: N = -sum of the front corners' pulls along
 * the face's normal (the captured posts' pushes move with the crush alone). */
static void crush_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double ax[3][3], scale = v->crush_force[v->crush_point_count - 1];
    body_axes(s, ax);
    double rho[3] = {-ax[0][0] / scale, -ax[0][1] / scale, -ax[0][2] / scale};
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (!cs->engaged || cs->status != CS_CABLE_INTACT) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (!cs_node_is_corner(cs->node[i]) || !cs_corner_front(cs_node_corner(cs->node[i]))) continue;
            const cs_span_grad *sp = cs_rows_spans(model, rows, c, i);
            double gp[3][3] = {{0}}, gm[3] = {0};
            cs_rows_force_gradient(sp, rho, gp, gm);
            cs_rows_add_node_gradient(model, s, rows, row, c, i, gp, gm);
        }
    }
}

static void height_rows_residual(const cs_model *model, const cs_state *s, const cs_rows *rows,
                                 const cs_slot *u, double *r) {
    r[0] = height_residual(model, s, rows, u->a, u->b);
}

static void height_rows_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                                 const cs_slot *u) {
    height_jacobian(model, s, rows, row, u->a, u->b);
}

const cs_row_kind cs_height_rows = {1, height_rows_residual, height_rows_jacobian};

static void crush_residual(const cs_model *model, const cs_state *s, const cs_rows *rows, const cs_slot *u,
                           double *r) {
    (void)u;
    const cs_vehicle_def *v = &model->vehicle.def;
    double nf = cs_face_normal_force(model, s, rows->chords);
    r[0] = (nf - cs_crush_force(v, s->crush, s->crush_max)) / v->crush_force[v->crush_point_count - 1];
}

static void crush_rows_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                                const cs_slot *u) {
    (void)u;
    crush_jacobian(model, s, rows, row);
}

const cs_row_kind cs_crush_rows = {1, crush_residual, crush_rows_jacobian};
