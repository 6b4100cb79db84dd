/* SPDX-License-Identifier: MIT */
/* How a cable lets go of a post it is held on (the attachment kinds of def.h).
 *
 * A cable in a slot cut down the post's web from its top is held by the post itself: it comes out only
 * at the slot's open end. Its spans hold it near its height z while the post leans theta about its pivot
 * d_p below grade, so it sits (z + d_p) / cos(theta) from the pivot along the slot, and it reaches the
 * open end, the top h, once cos(theta) <= (z + d_p) / (h + d_p). There the strap and cap over the slot
 * hold it, as a hook bolt's bend holds a cable on the post's face; from there on (a hook from the start)
 * it bears on the post across it and is held along it by friction and by that retainer. With the post's unit
 * axis a (base to top) and the cable's pull f on the post, the pull along the post is F_a = f . a and across
 * it F_n = |f - F_a a|. A post bent over by its cables turns their pull up along it: a horizontal pull F on a
 * post leaning theta away from it has F_a = F sin(theta), F_n = F cos(theta). The cable rides up and out when
 *
 *     F_a > mu F_n + R,
 *
 * mu the cable's friction on the post and R the retainer's strength (a slot's strap and cap, a hook
 * bolt's opening; cs_attachment_release_force). With R small against F that is tan(theta) > mu: the
 * post's lean, not the cable's force, sets the release. Cables stacked in a slot leave from the top
 * down: one still held above holds those below in.
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

double cs_attachment_slot_open(const cs_post_model *pm, double z) {
    return (z + pm->pivot) / (pm->height + pm->pivot);
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

int cs_attachment_check_release(const cs_model *model, cs_state *s, int p) {
    const cs_post_model *pm = &model->posts[p];
    const cs_post_state *ps = &s->posts[p];
    if (pm->attach == CS_ATTACH_THROUGH || pm->attach == CS_ATTACH_CLAMPED || !cs_post_in_barrier(ps))
        return 0; /* never let go */
    double base[3], top[3], axis[3], normal[3];
    cs_post_attachment(model, p, ps->tilt, ps->pull, 0.0, base);
    cs_post_attachment(model, p, ps->tilt, ps->pull, 1.0, top);
    v3_sub(axis, top, base);
    int bolted = pm->lateral_release > 0.0 && face_normal(pm, axis, normal) > 0.0;
    int any = 0;
    for (int c = model->cable_count - 1; c >= 0; c--) {
        cs_cable_state *cs = &s->cables[c];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        if (i <= 0) continue;
        if (pm->attach == CS_ATTACH_SLOT &&
            (held_above(model, s, p, c) ||
             cos(v2_norm(ps->tilt[0], ps->tilt[1])) > cs_attachment_slot_open(pm, model->cables[c].z)))
            continue;
        double f[3], across[3];
        cs_node_force(cs, i, NULL, f);
        double along = v3_dot(f, axis), off = bolted ? v3_dot(f, normal) : 0.0;
        v3_copy(across, f);
        v3_addto(across, axis, -along);
        int pulled_off = bolted && off > pm->lateral_release;
        if (!pulled_off && along <= model->cables[c].mu_post * v3_norm(across) + pm->release_force) continue;
        cs_cable_remove_node(cs, i);
        cs_event *e = cs_event_add(model, s, pulled_off ? CS_EVENT_CABLE_PULLED_OFF : CS_EVENT_CABLE_RELEASE,
                                   CS_ELEMENT_POST, p, pulled_off ? off : along);
        if (e) e->cable = c;
        any = 1;
        if (pm->attach == CS_ATTACH_SLOT) c = model->cable_count; /* the ones below may follow */
    }
    return any;
}
