/* SPDX-License-Identifier: MIT */
/* The state as data: copied whole or barrier only, its summary, the names of its statuses and outcomes,
 * and its hash. Its memory and its views: run/state.c. */
#include "core/core.h"
#include "core/fnv.h"
#include "core/vec3.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* A copy of src in dst: everything but the memory that is dst's own (arrays, events, workspace, the rails'
 * cache),
 * with the cables' paths and the posts copied into dst's arrays. Events are appended only, so the ones
 * src holds are already in place when dst is the state and src its step-start copy. */
void cs_state_copy(const cs_model *model, cs_state *dst, const cs_state *src) {
    cs_state keep = *dst;
    *dst = *src;
    dst->cables = keep.cables, dst->posts = keep.posts, dst->events = keep.events;
    dst->speed_ring = keep.speed_ring, dst->work = keep.work, dst->rail_plastic = keep.rail_plastic;
    dst->rail_pos = keep.rail_pos, dst->rail_tilt = keep.rail_tilt;
    dst->loss_ring = keep.loss_ring, dst->loss.t = keep.loss.t, dst->loss.f = keep.loss.f;
    size_t nr = (size_t)model->rail_count, np = (size_t)model->post_count;
    memcpy(dst->rail_plastic, src->rail_plastic, nr * np * sizeof *dst->rail_plastic);
    dst->cable_count_alloc = keep.cable_count_alloc;
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *d = &dst->cables[c], k = *d;
        const cs_cable_state *o = &src->cables[c];
        size_t n = (size_t)o->node_count;
        *d = *o;
        d->node = k.node, d->where = k.where, d->m = k.m, d->m_commit = k.m_commit, d->ep = k.ep;
        d->tension = k.tension, d->pos = k.pos;
        memcpy(d->node, o->node, n * sizeof *d->node);
        memcpy(d->where, o->where, (size_t)model->post_count * sizeof *d->where);
        memcpy(d->m, o->m, n * sizeof *d->m);
        memcpy(d->m_commit, o->m_commit, n * sizeof *d->m_commit);
        memcpy(d->ep, o->ep, (n - 1) * sizeof *d->ep);
        memcpy(d->tension, o->tension, (n - 1) * sizeof *d->tension);
        memcpy(d->pos, o->pos, 3 * n * sizeof *d->pos);
    }
    memcpy(dst->posts, src->posts, (size_t)model->post_count * sizeof *dst->posts);
}

/* The barrier of `from` back into s (cables, posts, crush, ledger sums, events), s's vehicle kept, and
 * with it the work the ropes have done on it. */
void cs_state_restore_barrier(const cs_model *model, cs_state *s, const cs_state *from) {
    double pos[3], vel[3], quat[4], omega[3], acc[3], ang_acc[3], work[CS_MAX_CABLES_PER_POST];
    double tyre_power = s->tyre_power, e_tyre = s->e_tyre;
    for (int c = 0; c < model->cable_count; c++)
        work[c] = s->cables[c].work_on_vehicle;
    v3_copy(pos, s->pos), v3_copy(vel, s->vel), v3_copy(omega, s->omega);
    v3_copy(acc, s->acc), v3_copy(ang_acc, s->ang_acc);
    memcpy(quat, s->quat, sizeof quat);
    cs_state_copy(model, s, from);
    v3_copy(s->pos, pos), v3_copy(s->vel, vel), v3_copy(s->omega, omega);
    v3_copy(s->acc, acc), v3_copy(s->ang_acc, ang_acc);
    memcpy(s->quat, quat, sizeof quat);
    s->tyre_power = tyre_power, s->e_tyre = e_tyre;
    for (int c = 0; c < model->cable_count; c++)
        s->cables[c].work_on_vehicle = work[c];
}

const char *cs_outcome_name(cs_outcome o) {
    switch (o) {
    case CS_RUNNING:
        return "running";
    case CS_STOPPED:
        return "stopped";
    case CS_BREAKTHROUGH:
        return "breakthrough";
    case CS_TIME_LIMIT:
        return "time_limit";
    case CS_REDIRECTED:
        return "redirected";
    case CS_OVERRIDE:
        return "override";
    case CS_UNDERRIDE:
        return "underride";
    case CS_NO_CONTACT:
        return "no_contact";
    case CS_DID_NOT_CONVERGE:
        return "did_not_converge";
    case CS_STEP_LIMIT:
        return "step_limit";
    }
    return "unknown";
}

int cs_outcome_through(cs_outcome o) {
    return o == CS_BREAKTHROUGH || o == CS_OVERRIDE || o == CS_UNDERRIDE;
}

int cs_outcome_exits(cs_outcome o) {
    return cs_outcome_through(o) || o == CS_REDIRECTED;
}

int cs_penetration_is_final(cs_outcome o) {
    return o == CS_STOPPED || o == CS_REDIRECTED || o == CS_NO_CONTACT;
}

const char *cs_cable_status_name(cs_cable_status st) {
    switch (st) {
    case CS_CABLE_INTACT:
        return "intact";
    case CS_CABLE_BROKEN:
        return "broken";
    case CS_CABLE_RELEASED:
        return "released";
    case CS_CABLE_SLIPPED:
        return "slipped";
    }
    return "unknown";
}

int cs_cable_status_holds(cs_cable_status st) {
    return st == CS_CABLE_INTACT || st == CS_CABLE_SLIPPED;
}

const char *cs_post_status_name(cs_post_status st) {
    switch (st) {
    case CS_POST_ELASTIC:
        return "elastic";
    case CS_POST_HINGED:
        return "hinged";
    case CS_POST_SOIL:
        return "soil";
    case CS_POST_FAILED_ROTATION:
        return "failed_rotation";
    case CS_POST_FAILED_SHEAR:
        return "failed_shear";
    case CS_POST_FAILED_PULLOUT:
        return "failed_pullout";
    case CS_POST_DOWN:
        return "down";
    }
    return "unknown";
}

unsigned long long cs_fnv1a64(unsigned long long h, const void *data, size_t n) {
    const unsigned char *b = data;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 1099511628211ULL;
    return h;
}

static void hash_bytes(unsigned long long *h, const void *data, size_t n) {
    *h = cs_fnv1a64(*h, data, n);
}

/* FNV-1a over the bytes of every number that evolves: the vehicle, each cable's path, plastic strain,
 * status, engagement, whether the vehicle passed it, which corners and wheels pass it and its contacts on
 * the vehicle, each post's tilt, plastic
 * rotation, swing (rate, acceleration, net moment, damper), status, what pushes a struck one and its slide
 * out of its footing (with its rate and net pull), the rails, each anchor's movement, its rate, acceleration,
 * net force and status, the ledger and the events (field by field: no struct padding). */
unsigned long long cs_state_hash(const cs_model *model, const cs_state *s) {
    unsigned long long h = CS_FNV1A64_BASIS;
    hash_bytes(&h, &s->t, sizeof s->t);
    hash_bytes(&h, s->pos, sizeof s->pos);
    hash_bytes(&h, s->vel, sizeof s->vel);
    hash_bytes(&h, s->quat, sizeof s->quat);
    hash_bytes(&h, s->omega, sizeof s->omega);
    hash_bytes(&h, &s->crush, sizeof s->crush);
    hash_bytes(&h, &s->crush_max, sizeof s->crush_max);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        int flags[4] = {(int)cs->status, cs->engaged, cs->passed, cs->passing};
        hash_bytes(&h, flags, sizeof flags);
        hash_bytes(&h, cs->node, (size_t)cs->node_count * sizeof *cs->node);
        hash_bytes(&h, cs->m, (size_t)cs->node_count * sizeof *cs->m); /* the ends' m: their slip too */
        hash_bytes(&h, cs->pos, (size_t)cs->node_count * 3 * sizeof *cs->pos);
        if (cs->node_count > 1) hash_bytes(&h, cs->ep, (size_t)(cs->node_count - 1) * sizeof *cs->ep);
        hash_bytes(&h, cs->corner_z, sizeof cs->corner_z);
    }
    for (int p = 0; p < model->post_count; p++) {
        const cs_post_state *ps = &s->posts[p];
        int flags[7] = {(int)ps->status, ps->yielded,     ps->captured, ps->pusher,
                        ps->bearing,     ps->withdrawing, ps->passed};
        hash_bytes(&h, flags, sizeof flags);
        hash_bytes(&h, &ps->pull, sizeof ps->pull);
        hash_bytes(&h, &ps->pull_plastic, sizeof ps->pull_plastic);
        hash_bytes(&h, &ps->pull_rate, sizeof ps->pull_rate);
        hash_bytes(&h, &ps->pull_net, sizeof ps->pull_net);
        hash_bytes(&h, ps->tilt, sizeof ps->tilt);
        hash_bytes(&h, ps->plastic, sizeof ps->plastic);
        hash_bytes(&h, ps->rate, sizeof ps->rate);
        hash_bytes(&h, ps->acc, sizeof ps->acc);
        hash_bytes(&h, ps->net, sizeof ps->net);
        hash_bytes(&h, ps->damper, sizeof ps->damper);
        hash_bytes(&h, &ps->push, sizeof ps->push);
        if (model->posts[p].attach == CS_ATTACH_SLOT) hash_bytes(&h, &ps->lift, sizeof ps->lift);
    }
    hash_bytes(&h, s->rail_plastic,
               (size_t)model->rail_count * (size_t)model->post_count * sizeof *s->rail_plastic);
    for (int a = 0; a < 2; a++) {
        const cs_anchor_state *as = &s->anchors[a];
        int flags[2] = {as->failed, as->yielded};
        hash_bytes(&h, flags, sizeof flags);
        hash_bytes(&h, as->u, sizeof as->u);
        hash_bytes(&h, as->plastic, sizeof as->plastic);
        hash_bytes(&h, &as->slide, sizeof as->slide);
        hash_bytes(&h, as->rate, sizeof as->rate);
        hash_bytes(&h, as->acc, sizeof as->acc);
        hash_bytes(&h, as->net, sizeof as->net);
        if (as->lifting) {
            double lift[4] = {as->lift, as->lift_plastic, as->lift_rate, as->lift_net};
            hash_bytes(&h, lift, sizeof lift);
        }
    }
    /* the ledger's numbers, not its size (the hash of a state is the same as before cs_energy had one) */
    hash_bytes(&h, &s->energy.vehicle_kinetic, sizeof s->energy - offsetof(cs_energy, vehicle_kinetic));
    for (int k = 0; k < s->event_count; k++) {
        const cs_event *e = &s->events[k];
        int what[3] = {(int)e->type, (int)e->element_kind, e->element};
        hash_bytes(&h, &e->t, sizeof e->t);
        hash_bytes(&h, what, sizeof what);
        hash_bytes(&h, &e->value, sizeof e->value);
        if (e->cable_end >= 0) hash_bytes(&h, &e->cable_end, sizeof e->cable_end); /* a termination's */
    }
    return h;
}
