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
 * down: one still held above holds those below in. A released cable runs straight past the post, which
 * stands on, unloaded (its swing and set kept). */
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

int cs_attachment_check_release(const cs_model *model, cs_state *s, int p) {
    const cs_post_model *pm = &model->posts[p];
    const cs_post_state *ps = &s->posts[p];
    if ((pm->attach != CS_ATTACH_SLOT && pm->attach != CS_ATTACH_HOOK) || !cs_post_in_barrier(ps)) return 0;
    double base[3], top[3], axis[3];
    cs_post_attachment(model, p, ps->tilt, ps->pull, 0.0, base);
    cs_post_attachment(model, p, ps->tilt, ps->pull, 1.0, top);
    v3_sub(axis, top, base);
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
        double along = v3_dot(f, axis);
        v3_copy(across, f);
        v3_addto(across, axis, -along);
        if (along <= model->cables[c].mu_post * v3_norm(across) + pm->release_force) continue;
        cs_cable_remove_node(cs, i);
        cs_event *e = cs_event_add(model, s, CS_EVENT_CABLE_RELEASE, CS_ELEMENT_POST, p, along);
        if (e) e->cable = c;
        any = 1;
        if (pm->attach == CS_ATTACH_SLOT) c = model->cable_count; /* the ones below may follow */
    }
    return any;
}
