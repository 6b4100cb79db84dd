/* SPDX-License-Identifier: MIT */
/* A rope's end fittings at the anchors: the load at which each lets go, and the slip of a fitting that
 * grips by friction (clips, clamps) before it does.
 *
 * Strength: an end span whose tension passes its fitting's strength (efficiency x Fu) breaks the rope
 * there (cable.c's check). Slip: a fitting given a slip load F_s holds the rope below it and lets it
 * through at it, as a support with one side dead (the turn-back carries no tension) and a friction band
 * of F_s that does not depend on the wrap. As a row of the barrier solve, with the end node's material
 * coordinate m its unknown (support.c's row with T_dead = 0 and b = F_s):
 *   r Fu = lambda - proj_[-F_s, F_s](lambda + c dm) - eps c dm,
 *   lambda = -T_0 at the start (m_0 falls as rope comes out), +T_last at the end, c = EA / l_end span.
 * Rope slips only outward (lambda never passes +F_s at the start, -F_s at the end), so what a fitting has
 * let through, slip = -(m_0 - m_0 laid in) or m_last - m_last laid in, only grows; the work is F_s times
 * it, along the stretched rope (booked as friction). When the slip reaches the fitting's slip travel (a
 * clip's turn-back) the rope runs out of it: a termination_break. */
#include "core/vec3.h"
#include "elements/rows.h"

#include <math.h>

static int end_node(const cs_cable_state *cs, int end) {
    return end ? cs->node_count - 1 : 0;
}

double cs_termination_load(const cs_cable_model *cm, const cs_cable_state *cs, int *end) {
    double r0 = cs->tension[0] / cm->termination_strength[0];
    double r1 = cs->tension[cs->node_count - 2] / cm->termination_strength[1];
    if (end) *end = r1 > r0;
    return fmax(r0, r1);
}

int cs_termination_slips(const cs_cable_model *cm, const cs_cable_state *cs, int end) {
    return cs->status == CS_CABLE_INTACT && cm->slip_load[end] > 0.0 && cs->slip[end] < cm->slip_travel[end];
}

int cs_termination_run_out(const cs_cable_model *cm, const cs_cable_state *cs) {
    for (int end = 0; end < 2; end++)
        if (cm->slip_load[end] > 0.0 && cs->slip[end] >= cm->slip_travel[end]) return end;
    return -1;
}

/* The row's lambda at end `end`: the end span's tension, signed (-T_0 at the start, +T_last at the end). */
static double slip_lambda(const cs_cable_state *cs, int end) {
    return end ? cs->tension[cs->node_count - 2] : -cs->tension[0];
}

double cs_termination_slip_residual(const cs_model *model, const cs_state *s, const cs_rows *rows, int c,
                                    int i) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    int end = i != 0, span = end ? i - 1 : 0;
    double lambda = slip_lambda(cs, end);
    double cstiff = cm->rope.ea / (cs_rows_chords(model, rows, c)[4 * span + 3] + 1e-9);
    double dm = cs->m[i] - cs->m_commit[i];
    double proj = cs_smooth_clamp(lambda + cstiff * dm, cm->slip_load[end], CS_FRICTION_FLOOR * cm->rope.fu);
    return (lambda - proj - CS_STICK_EPS * cstiff * dm) * (1.0 / cm->rope.fu);
}

void cs_termination_slip_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                                  int c, int i) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    int end = i != 0, span = end ? i - 1 : 0;
    /* gp[k] is node i - 1 + k: the span runs from gp[near] to gp[near + 1] */
    int near = end ? 0 : 1;
    const cs_span_grad *sp = &rows->spans[c * model->max_nodes + span];
    double fu = cm->rope.fu, len = sp->l + 1e-9, cstiff = cm->rope.ea / len, dm = cs->m[i] - cs->m_commit[i];
    double py, pb;
    cs_smooth_clamp_slopes(slip_lambda(cs, end) + cstiff * dm, cm->slip_load[end], CS_FRICTION_FLOOR * fu,
                           &py, &pb);
    /* r Fu = lambda - proj(lambda + c dm, F_s) - eps c dm: slopes on T, c and dm */
    double on_t = (end ? 1.0 : -1.0) * (1.0 - py), on_c = -(py + CS_STICK_EPS) * dm;
    double gp[3][3] = {{0}}, gm[3] = {0};
    v3_addto(gp[near + 1], sp->dt_dd, on_t);
    v3_addto(gp[near], sp->dt_dd, -on_t);
    gm[near] += on_t * sp->dt_dm[0], gm[near + 1] += on_t * sp->dt_dm[1];
    double on_l = on_c * -cm->rope.ea / (len * len); /* c = EA / l, l = |d| */
    v3_addto(gp[near + 1], sp->u, on_l);
    v3_addto(gp[near], sp->u, -on_l);
    gm[1] += -(py + CS_STICK_EPS) * cstiff;
    for (int k = 0; k < 3; k++) {
        v3_scale(gp[k], gp[k], 1.0 / fu);
        gm[k] /= fu;
    }
    cs_rows_add_node_gradient(model, s, rows, row, c, i, gp, gm);
}

void cs_termination_commit(const cs_model *model, int c, cs_state *s) {
    const cs_cable_model *cm = &model->cables[c];
    cs_cable_state *cs = &s->cables[c];
    for (int end = 0; end < 2; end++) {
        int i = end_node(cs, end), span = end ? i - 1 : 0;
        double out = end ? cs->m[i] - cs->m_commit[i] : cs->m_commit[i] - cs->m[i]; /* rope let through */
        if (out == 0.0) continue;
        /* along the stretched rope, as over a support (cable.c) whose other side, the turn-back, is slack */
        double stretch = 0.5 * (1.0 + cs_span_length(cs, span) / (cs->m[span + 1] - cs->m[span]));
        s->e_friction += out * cs->tension[span] * stretch;
        /* its start: the first rope let through at the slip load (within the clamp's rounding) */
        if (!cs->slipping[end] && out > 0.0 &&
            cs->tension[span] >= cm->slip_load[end] - 3.0 * CS_FRICTION_FLOOR * cm->rope.fu) {
            cs_event *e =
                cs_event_add(model, s, CS_EVENT_TERMINATION_SLIP, CS_ELEMENT_CABLE, c, cs->tension[span]);
            if (e) e->cable_end = end;
            cs->slipping[end] = 1;
        }
        cs->slip[end] += out;
    }
}

/* The rope's end at the post next to its anchor: a dead-man ploughing toward the barrier, or the post folded
 * down toward it, brings the rope's end, tied at the anchor, up to the post's hole. Within the rope's
 * diameter of it the end's fitting bears on the post: the rope runs from the anchor straight on, and the
 * post leaves its path (its node removed, the end span taking the rope and plastic strain of both). Left
 * there, the end span's chord shrinks to nothing under the rope's pull, its stiffness EA / l grows without
 * bound and its direction, and so the turn and the capstan band at the hole, flips: no solve converges
 * (docs/theory.md, Rope ends). A clamped post holds its rope (its end span only goes slack), and a face
 * corner is not a post: both stay. */
int cs_termination_check_post(const cs_model *model, int c, cs_state *s) {
    const cs_cable_model *cm = &model->cables[c];
    cs_cable_state *cs = &s->cables[c];
    int any = 0;
    for (int end = 0; end < 2 && cs->status == CS_CABLE_INTACT && cs->node_count > 2; end++) {
        int i = end ? cs->node_count - 2 : 1, p = cs->node[i];
        if (p < 0 || model->posts[p].clamped || cs_span_length(cs, end ? i : 0) >= cm->diameter) continue;
        cs_cable_remove_node(cs, i);
        const double *u = s->anchors[end].u;
        cs_event *e =
            cs_event_add(model, s, CS_EVENT_TERMINATION_AT_POST, CS_ELEMENT_POST, p, hypot(u[0], u[1]));
        if (e) e->cable_end = end, e->cable = c;
        any = 1;
    }
    return any;
}
