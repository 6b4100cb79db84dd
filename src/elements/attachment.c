/* SPDX-License-Identifier: MIT */
/* How a cable rides along and lets go of a post it is held on (the attachment kinds of def.h).
 *
 * With the post's unit axis a (base to top) and a cable's pull f on the post, the pull along the post is
 * F_a = f . a and across it F_n = |f - F_a a|. A post bent over by its cables turns their pull up along it:
 * a horizontal pull F on a post leaning theta away from it has F_a = F sin(theta), F_n = F cos(theta).
 *
 * A cable in a slot cut down the post's web from its top is held by the post itself: it comes out only at
 * the slot's open end. The cables in a slot ride up it together (kept apart by their spacers) by their
 * lift u along the post, against friction on the slot's faces: they slide while the stack's net pull up
 * the slot
 *
 *     N(u) = sum (F_a - mu F_n)
 *
 * is positive, and stop where it is nil, since each cable's spans pull it back toward its height as it
 * rides (the spans' stiffness against a move along the post is at least sum T / L). With R small that is
 * tan(theta) > mu: the post's lean, not the force, starts the ride. The ride is taken from the pulls the
 * solve left, the rest of the barrier held (the solve holds u as it stands), by regula falsi on N over
 * [0, h - z_top - u]; the solve then settles the barrier around it, and the two go in turn until the ride
 * ends (step.c). What the ropes' stored energy loses on a ride (mu F_n u and the excess of N, which the
 * real cables spend in motion the model does not have) is booked as friction, and so is what the barrier
 * loses settling around it. A stack pulled down the slot stays where it is. Once the highest cable
 * reaches the open end, the top h, the strap and cap over the slot hold it, as a hook bolt's bend holds a
 * cable on the post's face: it leaves when the stack's net pull passes their strength R, and the ones
 * below ride on to the open end after it. A hook lets its cable go when its own
 *
 *     F_a > mu F_n + R,
 *
 * mu the cable's friction on the post and R the retainer's strength (a slot's strap and cap, a hook
 * bolt's opening; cs_attachment_release_force).
 *
 * A keyway bolt or a bracket is bolted to one face of the post, whose outward normal n is the barrier's
 * -y (the attack face) or +y (the protected one) turned with the post (its part normal to the axis). A
 * cable pulled into the face bears on the post, as in a hook; one pulled off it by F_off = f . n > 0
 * bears on the fitting, which lets go past its lateral strength R_off (the component tests'). Along the
 * post it lets go as a hook does: it bears across the post on the one or the other, so friction acts on
 * F_n either way. A released cable runs straight past the post, which stands on, unloaded (its swing and
 * set kept). */
#include "core/vec3.h"
#include "elements/elements.h"

/* Whether cable c still has a cable held above it in post p's slot. */
static int held_above(const cs_model *model, const cs_state *s, int p, int c) {
    for (int k = 0; k < model->cable_count; k++)
        if (k != c && model->cables[k].z > model->cables[c].z && s->cables[k].status == CS_CABLE_INTACT &&
            s->cables[k].where[p] > 0)
            return 1;
    return 0;
}

/* Post p's unit axis, base to top, as it stands. */
static void post_axis(const cs_model *model, const cs_state *s, int p, double axis[3]) {
    const cs_post_state *ps = &s->posts[p];
    double base[3], top[3];
    int upright = cs_post_upright(&model->posts[p]);
    cs_post_attachment(model, p, ps->tilt, ps->pull, upright, 0.0, base);
    cs_post_attachment(model, p, ps->tilt, ps->pull, upright, 1.0, top);
    v3_sub(axis, top, base);
}

/* Cable c's pull on post p: along the axis into *along, across it returned. */
static double pull_on(const cs_state *s, int p, int c, const double axis[3], double *along) {
    const cs_cable_state *cs = &s->cables[c];
    double f[3], across[3];
    cs_node_force(cs, cs->where[p], NULL, f);
    *along = v3_dot(f, axis);
    v3_copy(across, f);
    v3_addto(across, axis, -*along);
    return v3_norm(across);
}

static int in_slot(const cs_state *s, int p, int c) {
    return s->cables[c].status == CS_CABLE_INTACT && s->cables[c].where[p] > 0;
}

/* Post p's slot stack: its net pull up the slot N (returned), the pull along the post sum F_a into *along
 * and the highest cable's height as built into *top (-1 if the slot is empty). */
static double stack_pull(const cs_model *model, const cs_state *s, int p, const double axis[3], double *along,
                         double *top) {
    double net = 0.0;
    *along = 0.0, *top = -1.0;
    for (int c = 0; c < model->cable_count; c++) {
        if (!in_slot(s, p, c)) continue;
        double fa, fn = pull_on(s, p, c, axis, &fa);
        net += fa - model->cables[c].mu_post * fn, *along += fa;
        *top = fmax(*top, model->cables[c].z);
    }
    return net;
}

/* The stack's spans' geometric stiffness against a move along the post, sum T / L, N/m. */
static double stack_stiffness(const cs_model *model, const cs_state *s, int p) {
    double k = 0.0;
    for (int c = 0; c < model->cable_count; c++) {
        if (!in_slot(s, p, c)) continue;
        const cs_cable_state *cs = &s->cables[c];
        for (int sp = cs->where[p] - 1; sp <= cs->where[p]; sp++) {
            double len = cs_span_length(cs, sp);
            if (len > 1e-9) k += fmax(cs->tension[sp], 0.0) / len;
        }
    }
    return k;
}

/* The stored energy of the spans on either side of the stack's cables: the only spans a ride moves. */
static double stack_energy(const cs_model *model, const cs_state *s, int p) {
    double e = 0.0;
    for (int c = 0; c < model->cable_count; c++)
        if (in_slot(s, p, c))
            for (int i = s->cables[c].where[p] - 1; i <= s->cables[c].where[p]; i++)
                e += cs_span_stored_energy(&model->cables[c], &s->cables[c], i);
    return e;
}

/* The stack at lift u, its spans' tensions with it; returns its net pull. */
static double stack_at(const cs_model *model, cs_state *s, int p, const double axis[3], double u) {
    s->posts[p].lift = u;
    cs_post_place_nodes(model, s, p, s->posts[p].tilt, NULL);
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (!in_slot(s, p, c)) continue;
        for (int i = cs->where[p] - 1; i <= cs->where[p]; i++) {
            double d[4];
            cs->tension[i] = cs_span_tension_chord(&model->cables[c], cs, i, d);
        }
    }
    double along, top;
    return stack_pull(model, s, p, axis, &along, &top);
}

#define CS_RIDE_TOL 1e-9   /* m: the ride's bracket at which it stops */
#define CS_RIDE_MOVED 1e-6 /* m: a ride shorter than this leaves the barrier as it was, to the solve */
#define CS_RIDE_ITERATIONS 60

int cs_attachment_ride(const cs_model *model, cs_state *s, int p) {
    const cs_post_model *pm = &model->posts[p];
    cs_post_state *ps = &s->posts[p];
    if (pm->attach != CS_ATTACH_SLOT || !cs_post_in_barrier(ps)) return 0;
    double axis[3], along, top;
    post_axis(model, s, p, axis);
    double g = stack_pull(model, s, p, axis, &along, &top), u0 = ps->lift, room = pm->height - top - u0;
    if (top < 0.0 || g <= 0.0 || room <= 0.0) return 0;
    double e0 = stack_energy(model, s, p), k = stack_stiffness(model, s, p);
    /* N falls as the stack rides; the spans' T / L is below their stiffness, so its step overshoots the
     * root and brackets it, which regula falsi (Illinois) then closes */
    double lo = 0.0, glo = g, hi = room, ghi = 0.0, d = k > 0.0 ? fmin(room, g / k) : room;
    int bracketed = 0, side = 0;
    for (int it = 0; it < CS_RIDE_ITERATIONS; it++) {
        g = stack_at(model, s, p, axis, u0 + d);
        if (g > 0.0) {
            lo = d, glo = g;
            if (side > 0) ghi *= 0.5;
            side = 1;
            if (d >= room) break; /* the highest cable at the open end */
        } else {
            hi = d, ghi = g, bracketed = 1;
            if (side < 0) glo *= 0.5;
            side = -1;
        }
        if (bracketed && hi - lo < CS_RIDE_TOL) break;
        d = bracketed ? lo + glo * (hi - lo) / (glo - ghi) : fmin(room, lo + glo / fmax(k, 1e-300));
    }
    s->e_friction += e0 - stack_energy(model, s, p);
    return ps->lift - u0 > CS_RIDE_MOVED;
}

/* The outward normal of the face a keyway bolt or bracket is fixed to, normal to the post's unit axis;
 * 0 if there is none (the axis along y). */
static double face_normal(const cs_post_model *pm, const double axis[3], double n[3]) {
    double n0[3] = {0.0, pm->face_normal, 0.0};
    v3_copy(n, n0);
    v3_addto(n, axis, -v3_dot(n0, axis));
    double len = v3_norm(n);
    if (len < 1e-9) return 0.0;
    v3_scale(n, n, 1.0 / len);
    return len;
}

#define CS_SLOT_OPEN_TOL 1e-9 /* m: a cable this close to the slot's top is at its open end */

int cs_attachment_check_release(const cs_model *model, cs_state *s, int p) {
    const cs_post_model *pm = &model->posts[p];
    if (pm->attach == CS_ATTACH_THROUGH || pm->attach == CS_ATTACH_CLAMPED ||
        !cs_post_in_barrier(&s->posts[p]))
        return 0; /* never let go */
    double axis[3], normal[3];
    post_axis(model, s, p, axis);
    int bolted = pm->lateral_release > 0.0 && face_normal(pm, axis, normal) > 0.0;
    int any = 0;
    for (int c = model->cable_count - 1; c >= 0; c--) {
        cs_cable_state *cs = &s->cables[c];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        if (i <= 0) continue;
        double along, loose, off = 0.0; /* loose: the pull along the post past friction */
        if (pm->attach == CS_ATTACH_SLOT) {
            if (held_above(model, s, p, c) || cs_post_cable_z(model, s, p, c) < pm->height - CS_SLOT_OPEN_TOL)
                continue;
            double top;
            loose = stack_pull(model, s, p, axis, &along, &top); /* the stack presses on the cap */
        } else {
            double f[3], fn = pull_on(s, p, c, axis, &along);
            cs_node_force(cs, i, NULL, f);
            off = bolted ? v3_dot(f, normal) : 0.0;
            loose = along - model->cables[c].mu_post * fn;
        }
        int pulled_off = bolted && off > pm->lateral_release;
        if (!pulled_off && loose <= pm->release_force) continue;
        cs_cable_remove_node(cs, i);
        cs_event *e = cs_event_add(model, s, pulled_off ? CS_EVENT_CABLE_PULLED_OFF : CS_EVENT_CABLE_RELEASE,
                                   CS_ELEMENT_POST, p, pulled_off ? off : along);
        if (e) e->cable = c;
        any = 1;
        if (pm->attach == CS_ATTACH_SLOT) c = model->cable_count; /* the ones below may follow */
    }
    return any;
}
