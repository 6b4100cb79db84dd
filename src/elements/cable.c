/* SPDX-License-Identifier: MIT */
/* Cables: the path of each cable (anchors, standing posts, face corners), its spans' tensions, their
 * plastic flow and friction work at the end of a step, and breaks. This file owns the spans' tensions:
 * everything else asks it to bring them up to date.
 *
 * Across a support that turns the cable by theta with friction mu the tensions may differ at most by
 * exp(mu theta) (Eq. 3; support.c); rope slides through it otherwise. Sliding moves the material
 * coordinate m_i of the node only, so the total rope between the anchors is conserved. */
#include "core/vec3.h"
#include "elements/elements.h"

#include <math.h>
#include <string.h>

void cs_cable_update_span(const cs_cable_model *cm, cs_cable_state *cs, int i, double *chord) {
    double own[4];
    cs->tension[i] = cs_span_tension_chord(cm, cs, i, chord ? chord : own);
}

void cs_cable_hold_tension(cs_cable_state *cs, double t) {
    for (int i = 0; i + 1 < cs->node_count; i++)
        cs->tension[i] = t;
}

int cs_cable_find_node(const cs_cable_state *cs, int id) {
    for (int i = 0; i < cs->node_count; i++)
        if (cs->node[i] == id) return i;
    return -1;
}

void cs_cable_update_tensions(const cs_cable_model *cm, cs_cable_state *cs, double *chords) {
    for (int i = 0; i + 1 < cs->node_count; i++) {
        double own[4], *d = chords ? chords + 4 * i : own;
        cs->tension[i] = cs->status == CS_CABLE_INTACT ? cs_span_tension_chord(cm, cs, i, d) : 0.0;
    }
}

/* Keep where[] (post -> node index) in step with node[] from index `from` on. */
static void reindex(cs_cable_state *cs, int from) {
    for (int i = from; i < cs->node_count; i++)
        if (cs->node[i] >= 0) cs->where[cs->node[i]] = i;
}

void cs_cable_insert_node(cs_cable_state *cs, int at, int id, const double *p) {
    int n = cs->node_count;
    double l1 = v3_dist(cs->pos + 3 * (at - 1), p), l2 = v3_dist(p, cs->pos + 3 * at);
    double f = (l1 + l2) > 0.0 ? l1 / (l1 + l2) : 0.5;
    double m_new = cs->m[at - 1] + f * (cs->m[at] - cs->m[at - 1]);
    double mc_new = cs->m_commit[at - 1] + f * (cs->m_commit[at] - cs->m_commit[at - 1]);
    memmove(cs->node + at + 1, cs->node + at, (size_t)(n - at) * sizeof *cs->node);
    memmove(cs->m + at + 1, cs->m + at, (size_t)(n - at) * sizeof *cs->m);
    memmove(cs->m_commit + at + 1, cs->m_commit + at, (size_t)(n - at) * sizeof *cs->m_commit);
    memmove(cs->pos + 3 * (at + 1), cs->pos + 3 * at, (size_t)(n - at) * 3 * sizeof *cs->pos);
    /* span at-1 splits into at-1 and at, both keeping its plastic strain */
    memmove(cs->ep + at, cs->ep + at - 1, (size_t)(n - at) * sizeof *cs->ep);
    memmove(cs->tension + at, cs->tension + at - 1, (size_t)(n - at) * sizeof *cs->tension);
    cs->node[at] = id;
    cs->m[at] = m_new;
    cs->m_commit[at] = mc_new;
    v3_copy(cs->pos + 3 * at, p);
    cs->node_count = n + 1;
    reindex(cs, at);
}

void cs_cable_remove_node(cs_cable_state *cs, int at) {
    int n = cs->node_count;
    if (cs->node[at] >= 0) cs->where[cs->node[at]] = -1;
    double s1 = cs->m[at] - cs->m[at - 1], s2 = cs->m[at + 1] - cs->m[at];
    double ep = (s1 + s2) > 0.0 ? (cs->ep[at - 1] * s1 + cs->ep[at] * s2) / (s1 + s2) : cs->ep[at - 1];
    cs->ep[at - 1] = ep;
    memmove(cs->ep + at, cs->ep + at + 1, (size_t)(n - 2 - at) * sizeof *cs->ep);
    memmove(cs->tension + at, cs->tension + at + 1, (size_t)(n - 2 - at) * sizeof *cs->tension);
    memmove(cs->node + at, cs->node + at + 1, (size_t)(n - 1 - at) * sizeof *cs->node);
    memmove(cs->m + at, cs->m + at + 1, (size_t)(n - 1 - at) * sizeof *cs->m);
    memmove(cs->m_commit + at, cs->m_commit + at + 1, (size_t)(n - 1 - at) * sizeof *cs->m_commit);
    memmove(cs->pos + 3 * at, cs->pos + 3 * (at + 1), (size_t)(n - 1 - at) * 3 * sizeof *cs->pos);
    cs->node_count = n - 1;
    reindex(cs, at);
}

/* Force the cable's two spans put on node i (toward its neighbours), N. */
void cs_node_force(const cs_cable_state *cs, int i, const double *chords, double *f) {
    v3_set(f, 0.0, 0.0, 0.0);
    for (int span = i - 1; span <= i; span++) {
        if (span < 0 || span + 1 >= cs->node_count) continue;
        double own[4];
        const double *d = chords ? chords + 4 * span : (cs_span_chord(cs, span, own), own);
        if (d[3] > 1e-12) v3_addto(f, d, (span < i ? -cs->tension[span] : cs->tension[span]) / d[3]);
    }
}

double cs_span_stored_energy(const cs_cable_model *cm, const cs_cable_state *cs, int i) {
    double t = cs->tension[i], e = cs_rope_elastic_energy(&cm->rope, t, cs->m[i + 1] - cs->m[i]);
    if (t > 0.0) { /* the sag's weight below the chord */
        double d[4];
        cs_span_chord(cs, i, d);
        e -= cs_span_sag(&cm->rope, d) / (12.0 * t);
    }
    return e;
}

double cs_cable_stored_energy(const cs_cable_model *cm, const cs_cable_state *cs) {
    if (cs->status != CS_CABLE_INTACT) return 0.0;
    double e = 0.0;
    for (int i = 0; i + 1 < cs->node_count; i++)
        e += cs_span_stored_energy(cm, cs, i);
    return e;
}

/* End of step: plastic flow of each span (work T dep s) and friction work of rope that slid over each
 * support (|slide| |T_left - T_right| measured along the stretched rope). */
void cs_cable_commit(const cs_model *model, int c, cs_state *s) {
    const cs_cable_model *cm = &model->cables[c];
    cs_cable_state *cs = &s->cables[c];
    if (cs->status != CS_CABLE_INTACT) return;
    const cs_rope *r = &cm->rope;
    double worst = 0.0, tmax = 0.0;
    double left = 0.0; /* carry the plastic strain with the rope that slid: in place, span i - 1's kept */
    for (int i = 0; i + 1 < cs->node_count; i++) {
        double own = cs->ep[i], right = i + 2 < cs->node_count ? cs->ep[i + 1] : 0.0;
        cs->ep[i] = cs_span_plastic_of(cs, i, cs->m[i], cs->m[i + 1], left, own, right);
        left = own;
    }
    for (int i = 0; i + 1 < cs->node_count; i++) {
        double sm = cs->m[i + 1] - cs->m[i], e;
        int yields;
        double d[4];
        cs_span_chord(cs, i, d);
        double t = cs_span_tension_law(r, d[3], sm, cs->ep[i], cs_span_sag(r, d), &e, &yields);
        cs->tension[i] = t;
        if (yields && sm > 1e-12) {
            /* plastic flow up to the breaking strain at most: a span the step has carried past it breaks
             * there (cs_cable_check_break), and does no plastic work beyond it */
            double ep = fmin(e, r->e_break) - t / r->ea;
            if (ep > cs->ep[i]) s->e_cable_plastic += t * (ep - cs->ep[i]) * sm;
            cs->ep[i] = fmax(cs->ep[i], ep);
        }
        if (e > worst) worst = e;
        if (t > tmax) tmax = t;
    }
    for (int i = 1; i + 1 < cs->node_count; i++) {
        double slide = cs->m[i] - cs->m_commit[i];
        if (slide == 0.0) continue;
        double sl = cs->m[i] - cs->m[i - 1], sr = cs->m[i + 1] - cs->m[i];
        double stretch = 0.5 * (cs_span_length(cs, i - 1) / sl + cs_span_length(cs, i) / sr);
        /* with its sign: the rounded stick/slip switch lets a nearly straight support carry a small
         * difference of either sign while rope runs across it (docs/theory.md, Capstan friction) */
        s->e_friction += slide * (cs->tension[i - 1] - cs->tension[i]) * stretch;
    }
    cs_termination_commit(model, c, s); /* rope slipped through the end fittings */
    memcpy(cs->m_commit, cs->m, (size_t)cs->node_count * sizeof *cs->m);
    if (tmax > cs->max_tension_seen) cs->max_tension_seen = tmax, cs->max_tension_time = s->t;
    cs->max_strain = worst;
    cs->end_load = cs_termination_load(cm, cs, NULL);
}

/* The threaded post whose hole bears the largest tension (the larger of the two spans on it), if that passes
 * the rope's strength there, with that tension in *t; -1 if none does, or if the rope keeps its whole
 * strength at the holes. */
static int hole_break(const cs_model *model, const cs_cable_model *cm, const cs_cable_state *cs, double *t) {
    if (cm->hole_strength <= 0.0) return -1;
    int worst = -1;
    *t = 0.0;
    for (int i = 1; i + 1 < cs->node_count; i++) {
        int p = cs->node[i];
        if (p < 0 || model->posts[p].attach != CS_ATTACH_THROUGH) continue;
        double ti = fmax(cs->tension[i - 1], cs->tension[i]);
        if (ti > *t) *t = ti, worst = p;
    }
    return *t > cm->hole_strength ? worst : -1;
}

/* A span strained to the breaking strain breaks the cable (cable_break, with its largest span tension);
 * so does a span over a threaded post's hole whose tension passes the rope's strength there (cable_break
 * at that post, with that tension); an end whose rope has slipped through its fitting by the slip travel,
 * or else an end span whose tension exceeds its fitting's strength, breaks it at that fitting
 * (termination_break, with the end and that span's tension); from then on it carries nothing. */
int cs_cable_check_break(const cs_model *model, int c, cs_state *s) {
    const cs_cable_model *cm = &model->cables[c];
    cs_cable_state *cs = &s->cables[c];
    if (cs->status != CS_CABLE_INTACT) return 0;
    double t_hole = 0.0;
    int hole = hole_break(model, cm, cs, &t_hole);
    if (hole >= 0) {
        cs_cable_release(cs, CS_CABLE_BROKEN);
        cs_event *e = cs_event_add(model, s, CS_EVENT_CABLE_BREAK, CS_ELEMENT_CABLE, c, t_hole);
        if (e) e->post = hole;
        return 1;
    }
    int strained = cs->max_strain >= cm->rope.e_break, end = cs_termination_run_out(cm, cs);
    if (!strained && end < 0 && cs->end_load <= 1.0) return 0;
    double tmax = 0.0;
    for (int i = 0; i + 1 < cs->node_count; i++)
        tmax = fmax(tmax, cs->tension[i]);
    if (end < 0) cs_termination_load(cm, cs, &end);
    double t_end = cs->tension[end ? cs->node_count - 2 : 0];
    cs_cable_release(cs, CS_CABLE_BROKEN);
    cs_event *e = cs_event_add(model, s, strained ? CS_EVENT_CABLE_BREAK : CS_EVENT_TERMINATION_BREAK,
                               CS_ELEMENT_CABLE, c, strained ? tmax : t_end);
    if (e && !strained) e->cable_end = end;
    return 1;
}

void cs_cable_release(cs_cable_state *cs, cs_cable_status status) {
    cs->status = status;
    cs->engaged = 0;
    for (int i = 0; i + 1 < cs->node_count; i++)
        cs->tension[i] = 0.0;
}
