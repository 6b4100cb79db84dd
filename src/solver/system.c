/* SPDX-License-Identifier: MIT */
/* The barrier's quasi-static equilibrium as one nonlinear system (system.h), solved by Newton (newton.c).
 *
 * Unknowns: the tilt (2) of every standing post the solve finds (cs_post_solved: not struck, not held,
 * with or without ropes) and its pull while it slides out of its footing (post_pullout.c), the material
 * coordinate m of every support node the rope can slide through (posts that do not clamp, face corners)
 * and of every rope end that can slip through its fitting, each engaged contact's height on the face, the
 * crush, and each yielding anchor's slide (2). Each kind of element gives its rows (rows.h): post.c,
 * support.c (with termination.c for the ends), contact.c, anchor.c. Every row is scaled by its unit (Fu for
 * nodes and contacts; for a post, its strongest rope's Fu at that rope's lever; the crush curve's top), so
 * that one tolerance is one force everywhere. Unknowns are ordered along the barrier, so the Jacobian is
 * banded and its LU costs linear time in the number of posts; the solution does not depend on any sweep
 * order, so a symmetric impact stays symmetric. The Jacobian is formed from the spans' tension gradients; the
 * crush's column alone is a difference quotient (the crush moves every corner and captured post at once). */
#include "solver/system.h"
#include "solver/work.h"

#include "core/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const cs_row_kind *const kinds[CS_U_KIND_COUNT] = {&cs_post_rows,   &cs_support_rows, &cs_crush_rows,
                                                          &cs_height_rows, &cs_anchor_rows,  &cs_pull_rows,
                                                          &cs_lift_rows};

static int node_slides(const cs_model *model, const cs_cable_state *cs, int i) {
    int id = cs->node[i];
    return cs_node_is_corner(id) || (id >= 0 && !model->posts[id].clamped);
}

/* Storage for every unknown the model can have: three per post, one per rope node, a contact per corner
 * and cable, the crush and the anchors'. The band holds rows of up to 2 kl + ku + 1 entries; a post has
 * 2 + cables unknowns, and the vehicle adds its corners per cable and the crush, so this covers
 * neighbouring slots with room. */
int cs_system_init(const cs_model *model, cs_system *sys) {
    memset(sys, 0, sizeof *sys);
    size_t nc = (size_t)model->cable_count, np = (size_t)model->post_count, nn = (size_t)model->max_nodes;
    size_t n = 3 * np + nc * nn + CS_CORNERS * nc + 5, per_row = 3 * (12 + 12 * nc) + 1;
    cs_rows *rw = &sys->rows;
    rw->slots = calloc(n, sizeof *rw->slots);
    rw->tilt_index = calloc(np ? np : 1, sizeof *rw->tilt_index);
    rw->pull_index = calloc(np ? np : 1, sizeof *rw->pull_index);
    rw->node_index = calloc(nc ? nc * nn : 1, sizeof *rw->node_index);
    rw->height_index = calloc(nc ? CS_CORNERS * nc : 1, sizeof *rw->height_index);
    rw->spans = calloc(nc * nn + 1, sizeof *rw->spans);
    rw->chords = calloc(4 * nc * nn + 1, sizeof *rw->chords);
    rw->axes = calloc(18 * np + 1, sizeof *rw->axes);
    rw->rails = calloc(4 * np * (size_t)model->rail_count + 1, sizeof *rw->rails);
    sys->slots_kept = calloc(n, sizeof *sys->slots_kept);
    sys->gathered = calloc(n, sizeof *sys->gathered);
    sys->order = calloc(n, sizeof *sys->order);
    sys->kept = calloc(n, sizeof *sys->kept);
    sys->slots_lu = calloc(n, sizeof *sys->slots_lu);
    sys->slots_bw = calloc(n, sizeof *sys->slots_bw);
    sys->nodes_bw = calloc(nc * (nn + 1) + 1, sizeof *sys->nodes_bw);
    sys->scratch = calloc(n, sizeof *sys->scratch);
    sys->key_count = 3 * np + nc * (np + CS_CORNERS + 2) + CS_CORNERS * nc + 7; /* see slot_key */
    sys->last = calloc(sys->key_count, sizeof *sys->last);
    sys->last_step = calloc(sys->key_count, sizeof *sys->last_step);
    if (!rw->slots || !rw->tilt_index || !rw->pull_index || !rw->node_index || !rw->height_index ||
        !rw->spans || !rw->chords || !rw->axes || !rw->rails || !sys->slots_kept || !sys->gathered ||
        !sys->order || !sys->kept || !sys->slots_lu || !sys->slots_bw || !sys->nodes_bw || !sys->scratch ||
        !sys->last || !sys->last_step)
        return -1;
    if (cs_newton_init(&sys->newton, (int)n, n * per_row) != 0) return -1;
    rw->jac = &sys->newton.band;
    return 0;
}

void cs_system_free(cs_system *sys) {
    cs_rows *rw = &sys->rows;
    free(rw->slots), free(rw->tilt_index), free(rw->pull_index), free(rw->node_index), free(rw->height_index),
        free(rw->spans), free(rw->chords), free(rw->axes), free(rw->rails);
    free(sys->slots_kept), free(sys->gathered), free(sys->order), free(sys->kept), free(sys->slots_lu),
        free(sys->slots_bw), free(sys->nodes_bw), free(sys->scratch), free(sys->last), free(sys->last_step);
    cs_newton_free(&sys->newton);
    memset(sys, 0, sizeof *sys);
}

void cs_system_jumped(cs_system *sys, long step) {
    sys->still_step = step + 1;
}

void cs_system_reset(cs_system *sys) {
    for (size_t k = 0; k < sys->key_count; k++)
        sys->last_step[k] = -2, sys->last[k] = 0.0;
    sys->still_step = -1;
    cs_newton_forget(&sys->newton);
    sys->bw_valid = 0, sys->order_valid = 0;
}

/* ---- the unknowns in barrier order ---- */
/* The order of the unknowns: along the barrier, then by kind, element and component (a total order). */
static int slot_order(const void *pa, const void *pb) {
    const cs_slot *a = pa, *b = pb;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->kind != b->kind) return a->kind < b->kind ? -1 : 1;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    return (a->b > b->b) - (a->b < b->b);
}

/* Fill the unknown list (kind, a, b) sorted along x; returns the count. */
/* The unknowns sorted along the barrier. Between solves the same unknowns mostly keep their order: the
 * last sort's order is taken again when the same unknowns, in it, are still in order (checked in one
 * pass; qsort's result is the same, the order being total), which saves the sort's 5-10% of a run. */
static void sort_unknowns(cs_system *sys, int n) {
    cs_slot *g = sys->gathered, *sl = sys->rows.slots;
    int same = sys->order_valid && n == sys->gathered_n;
    for (int k = 0; same && k < n; k++) /* the previous gathering, by identity */
        same = sl[k].kind == g[k].kind && sl[k].a == g[k].a && sl[k].b == g[k].b;
    memcpy(g, sl, (size_t)n * sizeof *g);
    sys->gathered_n = n;
    if (same) {
        for (int k = 0; k < n; k++)
            sl[k] = g[sys->order[k]];
        int sorted = 1;
        for (int k = 1; sorted && k < n; k++)
            sorted = slot_order(&sl[k - 1], &sl[k]) < 0;
        if (sorted) return;
        memcpy(sl, g, (size_t)n * sizeof *g);
    }
    qsort(sl, (size_t)n, sizeof *sl, slot_order);
    for (int k = 0; k < n; k++)
        sys->order[k] = sl[k].id;
    sys->order_valid = 1;
}

/* Where post p's unknowns go in the order: at its x while a rope or a rail ties it to its neighbours;
 * past the barrier's end if nothing does (a post the ropes have left), so that its rows, which couple to
 * nothing but itself, do not widen the band of the ropes' rows it stood between (at their x, RS6's
 * released posts made its run 22% dearer than left out of the solve; last, 8%, its run 4.5% longer). */
static double post_place(const cs_model *model, const cs_state *s, int p) {
    int left, right;
    if (cs_rail_ties(model, s, p, &left, &right)) return model->posts[p].x;
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].status == CS_CABLE_INTACT && s->cables[c].where[p] > 0) return model->posts[p].x;
    return HUGE_VAL;
}

static int assemble(const cs_model *model, const cs_state *s, cs_system *sys) {
    cs_rows *w = &sys->rows;
    cs_slot *sl = w->slots;
    int n = 0;
    for (int p = 0; p < model->post_count; p++) {
        if (!cs_post_solved(model, s, p)) continue;
        double x = post_place(model, s, p);
        sl[n++] = (cs_slot){x, CS_U_TILT, p, 0, 0};
        sl[n++] = (cs_slot){x, CS_U_TILT, p, 1, 0};
        if (s->posts[p].withdrawing) sl[n++] = (cs_slot){x, CS_U_PULL, p, 0, 0};
    }
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        for (int end = 0; end < 2; end++) /* rope slipping through an end fitting */
            if (cs_termination_slips(&model->cables[c], cs, end)) {
                int i = end ? cs->node_count - 1 : 0;
                sl[n++] = (cs_slot){cs->pos[3 * i], CS_U_NODE, c, i, 0};
            }
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (node_slides(model, cs, i)) sl[n++] = (cs_slot){cs->pos[3 * i], CS_U_NODE, c, i, 0};
            if (cs_node_is_corner(cs->node[i]))
                sl[n++] = (cs_slot){cs->pos[3 * i], CS_U_HEIGHT, c, cs_node_corner(cs->node[i]), 0};
        }
    }
    if (cs_face_loaded(model, s)) sl[n++] = (cs_slot){s->pos[0], CS_U_CRUSH, 0, 0, 0};
    for (int a = 0; a < 2; a++)
        if (cs_anchor_active(model, s, a)) {
            sl[n++] = (cs_slot){model->anchors[a].x, CS_U_ANCHOR, a, 0, 0};
            sl[n++] = (cs_slot){model->anchors[a].x, CS_U_ANCHOR, a, 1, 0};
            if (s->anchors[a].lifting) sl[n++] = (cs_slot){model->anchors[a].x, CS_U_LIFT, a, 0, 0};
        }
    for (int k = 0; k < n; k++)
        sl[k].id = k;
    sort_unknowns(sys, n);
    /* index maps: tilt of post p, node i of cable c, crush */
    for (int p = 0; p < model->post_count; p++)
        w->tilt_index[p] = w->pull_index[p] = -1;
    for (int c = 0; c < model->cable_count; c++)
        for (int i = 0; i < model->max_nodes; i++)
            w->node_index[c * model->max_nodes + i] = -1;
    w->crush_index = -1;
    for (int i = 0; i < 2 * model->cable_count; i++)
        w->height_index[i] = -1;
    w->anchor_index[0] = w->anchor_index[1] = w->lift_index[0] = w->lift_index[1] = -1;
    for (int k = 0; k < n; k++) {
        if (sl[k].kind == CS_U_HEIGHT) w->height_index[CS_CORNERS * sl[k].a + sl[k].b] = k;
        if (sl[k].kind == CS_U_TILT && sl[k].b == 0) w->tilt_index[sl[k].a] = k;
        if (sl[k].kind == CS_U_PULL) w->pull_index[sl[k].a] = k;
        if (sl[k].kind == CS_U_NODE) w->node_index[sl[k].a * model->max_nodes + sl[k].b] = k;
        if (sl[k].kind == CS_U_CRUSH) w->crush_index = k;
        if (sl[k].kind == CS_U_ANCHOR && sl[k].b == 0) w->anchor_index[sl[k].a] = k;
        if (sl[k].kind == CS_U_LIFT) w->lift_index[sl[k].a] = k;
    }
    w->n = n;
    return n;
}

/* Unknowns a node's position depends on: its post's tilt, or the crush for a corner. */
static void widen(int k, int *lo, int *hi) {
    if (k < 0) return;
    if (k < *lo) *lo = k;
    if (k > *hi) *hi = k;
}

/* A post's columns: its two tilts and its pull. */
static void post_columns(const cs_rows *w, int p, int *lo, int *hi) {
    int t = w->tilt_index[p];
    if (t >= 0) widen(t, lo, hi), widen(t + 1, lo, hi);
    widen(w->pull_index[p], lo, hi);
}

static void position_deps(const cs_rows *w, const cs_cable_state *cs, int c, int i, int *lo, int *hi) {
    int id = cs->node[i], k = -1;
    if (id >= 0) {
        post_columns(w, id, lo, hi);
        return;
    }
    if (cs_node_is_corner(id)) {
        widen(w->height_index[CS_CORNERS * c + cs_node_corner(id)], lo, hi);
        k = w->crush_index;
    }
    int anchor = id == CS_NODE_START || id == CS_NODE_END;
    if (anchor) k = w->anchor_index[id == CS_NODE_START ? 0 : 1];
    if (k < 0) return;
    int k2 = anchor ? k + 1 : k; /* an anchor's two columns, and its rise's */
    if (anchor && w->lift_index[id == CS_NODE_START ? 0 : 1] > k2)
        k2 = w->lift_index[id == CS_NODE_START ? 0 : 1];
    if (k < *lo) *lo = k;
    if (k2 > *hi) *hi = k2;
}

/* Range of unknowns the residual of a node's neighbourhood (nodes i-1..i+1) depends on. */
static void neighbourhood(const cs_model *model, const cs_rows *w, const cs_cable_state *cs, int c, int i,
                          int *lo, int *hi) {
    for (int j = i - 1; j <= i + 1; j++) {
        if (j < 0 || j >= cs->node_count) continue;
        int k = w->node_index[c * model->max_nodes + j];
        if (k >= 0) {
            if (k < *lo) *lo = k;
            if (k > *hi) *hi = k;
        }
        position_deps(w, cs, c, j, lo, hi);
    }
}

/* Lower and upper bandwidth of the Jacobian from the structure of the residuals. */
static void bandwidth(const cs_model *model, const cs_state *s, const cs_rows *w, int n, int *kl, int *ku) {
    *kl = *ku = 0;
    for (int k = 0; k < n; k++) {
        const cs_slot *u = &w->slots[k];
        int lo = k, hi = k;
        if (u->kind == CS_U_NODE) {
            neighbourhood(model, w, &s->cables[u->a], u->a, u->b, &lo, &hi);
        } else if (u->kind == CS_U_HEIGHT) {
            neighbourhood(model, w, &s->cables[u->a], u->a,
                          cs_cable_find_node(&s->cables[u->a], cs_corner_node(u->b)), &lo, &hi);
        } else if (u->kind == CS_U_TILT || u->kind == CS_U_PULL) {
            for (int c = 0; c < model->cable_count; c++) {
                const cs_cable_state *cs = &s->cables[c];
                if (cs->status == CS_CABLE_INTACT && cs->where[u->a] > 0)
                    neighbourhood(model, w, cs, c, cs->where[u->a], &lo, &hi);
            }
            int left, right; /* the neighbours its rails tie it to */
            if (cs_rail_ties(model, s, u->a, &left, &right))
                for (int side = 0; side < 2; side++)
                    if ((side ? right : left) >= 0) post_columns(w, side ? right : left, &lo, &hi);
            post_columns(w, u->a, &lo, &hi); /* its own: a post's rows come together */
        } else if (u->kind == CS_U_ANCHOR || u->kind == CS_U_LIFT) {
            for (int c = 0; c < model->cable_count; c++) {
                const cs_cable_state *cs = &s->cables[c];
                if (cs->status == CS_CABLE_INTACT)
                    neighbourhood(model, w, cs, c, u->a == 0 ? 0 : cs->node_count - 1, &lo, &hi);
            }
            if (u->kind == CS_U_ANCHOR) { /* its two rows come together */
                hi = hi > k + 1 ? hi : k + 1;
                lo = lo < k - 1 ? lo : k - 1;
            }
        } else {
            for (int c = 0; c < model->cable_count; c++) {
                const cs_cable_state *cs = &s->cables[c];
                if (cs->status != CS_CABLE_INTACT) continue;
                for (int i = 1; i + 1 < cs->node_count; i++)
                    if (cs_node_is_corner(cs->node[i])) neighbourhood(model, w, cs, c, i, &lo, &hi);
            }
        }
        if (lo < 0) lo = 0;
        if (hi > n - 1) hi = n - 1;
        if (k - lo > *kl) *kl = k - lo; /* row k depends on column lo: below the diagonal */
        if (hi - k > *ku) *ku = hi - k;
    }
}

static int same_slot(const cs_slot *a, const cs_slot *b) {
    return a->kind == b->kind && a->a == b->a && a->b == b->b;
}

/* The Jacobian's lower and upper bandwidth into w->kl, w->ku. They depend on the unknowns in their order
 * and on every cable's nodes alone; while those are what they were at the last call (most solves),
 * the last answer stands. */
static void band_shape(const cs_model *model, const cs_state *s, cs_system *w, int n) {
    int same = w->bw_valid && n == w->bw_n, stride = model->max_nodes + 1;
    for (int k = 0; same && k < n; k++)
        same = same_slot(&w->slots_bw[k], &w->rows.slots[k]);
    for (int c = 0; same && c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        const int *rec = w->nodes_bw + c * stride;
        int count = cs->status == CS_CABLE_INTACT ? cs->node_count : -1;
        same = rec[0] == count && (count < 0 || memcmp(rec + 1, cs->node, (size_t)count * sizeof *rec) == 0);
    }
    if (same) return;
    bandwidth(model, s, &w->rows, n, &w->kl, &w->ku);
    memcpy(w->slots_bw, w->rows.slots, (size_t)n * sizeof *w->rows.slots);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        int *rec = w->nodes_bw + c * stride;
        rec[0] = cs->status == CS_CABLE_INTACT ? cs->node_count : -1;
        if (rec[0] > 0) memcpy(rec + 1, cs->node, (size_t)rec[0] * sizeof *rec);
    }
    w->bw_n = n, w->bw_valid = 1;
}

/* ---- state <-> vector ---- */
static void gather(const cs_state *s, const cs_rows *w, int n, double *x) {
    for (int k = 0; k < n; k++) {
        const cs_slot *u = &w->slots[k];
        if (u->kind == CS_U_TILT) x[k] = s->posts[u->a].tilt[u->b];
        if (u->kind == CS_U_NODE) x[k] = s->cables[u->a].m[u->b];
        if (u->kind == CS_U_CRUSH) x[k] = s->crush;
        if (u->kind == CS_U_HEIGHT) x[k] = s->cables[u->a].corner_z[u->b];
        if (u->kind == CS_U_ANCHOR) x[k] = s->anchors[u->a].u[u->b];
        if (u->kind == CS_U_PULL) x[k] = s->posts[u->a].pull;
        if (u->kind == CS_U_LIFT) x[k] = s->anchors[u->a].lift;
    }
}

/* Put x into the state and bring every node position, span chord and tension in line with it. */
static void scatter(const cs_model *model, cs_state *s, const cs_rows *w, int n, const double *x) {
    for (int k = 0; k < n; k++) {
        const cs_slot *u = &w->slots[k];
        if (u->kind == CS_U_TILT) s->posts[u->a].tilt[u->b] = x[k];
        if (u->kind == CS_U_NODE) s->cables[u->a].m[u->b] = x[k];
        if (u->kind == CS_U_CRUSH) s->crush = x[k];
        if (u->kind == CS_U_HEIGHT) s->cables[u->a].corner_z[u->b] = x[k];
        if (u->kind == CS_U_ANCHOR) s->anchors[u->a].u[u->b] = x[k];
        if (u->kind == CS_U_PULL) s->posts[u->a].pull = x[k];
        if (u->kind == CS_U_LIFT) s->anchors[u->a].lift = x[k];
    }
    for (int a = 0; a < 2; a++)
        if (w->anchor_index[a] >= 0) cs_anchor_place_nodes(model, s, a);
    cs_contact_place_corners(model, s, s->crush);
    cs_post_place_captured(model, s, s->crush);
    for (int p = 0; p < model->post_count; p++)
        cs_post_place_nodes(model, s, p, s->posts[p].tilt, w->tilt_index[p] >= 0 ? w->axes + 18 * p : NULL);
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].status == CS_CABLE_INTACT)
            cs_cable_update_tensions(&model->cables[c], &s->cables[c],
                                     w->chords + 4 * (size_t)c * (size_t)model->max_nodes);
    if (model->rail_count) cs_rail_moments(model, s, w->axes, w->rails);
}

/* The residual rows from..to (a kind of `width` rows gives them together, from its first slot). */
static void residual_rows(const cs_model *model, const cs_state *s, const cs_rows *w, int from, int to,
                          double *r) {
    for (int k = from; k <= to;) {
        const cs_slot *u = &w->slots[k];
        const cs_row_kind *kind = kinds[u->kind];
        kind->residual(model, s, w, u, r + k);
        k += kind->width;
    }
}

/* Set the crush and bring what it moves in line: the face's corners and the spans at them, and the
 * captured posts (scatter's work for the crush alone). */
static void move_crush(const cs_model *model, cs_state *s, const cs_rows *w, double crush) {
    s->crush = crush;
    cs_contact_place_corners(model, s, crush);
    cs_post_place_captured(model, s, crush);
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        double *ch = w->chords + 4 * (size_t)c * (size_t)model->max_nodes;
        for (int i = 1; i + 1 < cs->node_count; i++)
            if (cs_node_is_corner(cs->node[i]) && cs_corner_front(cs_node_corner(cs->node[i]))) {
                cs_cable_update_span(&model->cables[c], cs, i - 1, ch + 4 * (i - 1));
                cs_cable_update_span(&model->cables[c], cs, i, ch + 4 * i);
            }
    }
}

/* The Jacobian at x (the state there), r its residual: the spans' tension gradients and the posts' axes
 * at the placement, each element's rows, and the crush's column by a difference quotient over 1e-8 m. */
static void jacobian_at(const cs_model *model, cs_state *s, cs_system *sys, const double *x,
                        const double *r) {
    cs_rows *w = &sys->rows;
    int n = w->n;
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (cs->status == CS_CABLE_INTACT)
            for (int i = 0; i + 1 < cs->node_count; i++)
                cs_span_tension_grad(&model->cables[c], cs, i,
                                     w->chords + 4 * ((size_t)c * (size_t)model->max_nodes + (size_t)i),
                                     w->spans + c * model->max_nodes + i);
    }
    for (int p = 0; p < model->post_count; p++)
        if (w->tilt_index[p] >= 0)
            cs_post_axis_jacobian(s->posts[p].tilt, w->axes + 18 * p, w->axes + 18 * p + 6);
    for (int k = 0; k < n;) {
        const cs_slot *u = &w->slots[k];
        const cs_row_kind *kind = kinds[u->kind];
        kind->jacobian(model, s, w, k, u);
        k += kind->width;
    }
    int j = w->crush_index;
    if (j < 0) return;
    /* the crush's column: the rows in its band (a post's or an anchor's two rows come together, from the
     * first: its slot b = 0) */
    int lo = j - sys->ku > 0 ? j - sys->ku : 0, hi = j + sys->kl < n - 1 ? j + sys->kl : n - 1;
    if (kinds[w->slots[lo].kind]->width > 1) lo -= w->slots[lo].b;
    move_crush(model, s, w, x[j] + 1e-8);
    residual_rows(model, s, w, lo, hi, sys->scratch);
    for (int i = j - sys->ku; i <= hi; i++)
        if (i >= 0 && cs_band_holds(w->jac, i, j))
            *cs_band_entry(w->jac, i, j) = (sys->scratch[i] - r[i]) / 1e-8;
    move_crush(model, s, w, x[j]);
}

/* Largest fraction of a Newton step that keeps every span's rope at least half of what it has, turns
 * no post by more than 0.1 rad and moves the crush, a contact, an anchor or a post's pull by at most 5 cm. */
static double max_step(const cs_model *model, const cs_state *s, const cs_rows *w, const double *dx) {
    double t = 1.0;
    for (int k = 0; k < w->n; k++) {
        const cs_slot *u = &w->slots[k];
        if (u->kind == CS_U_TILT && fabs(dx[k]) * t > 0.1) t = 0.1 / fabs(dx[k]);
        if ((u->kind == CS_U_CRUSH || u->kind == CS_U_HEIGHT || u->kind == CS_U_ANCHOR ||
             u->kind == CS_U_PULL || u->kind == CS_U_LIFT) &&
            fabs(dx[k]) * t > 0.05)
            t = 0.05 / fabs(dx[k]);
    }
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        for (int i = 0; i + 1 < cs->node_count; i++) {
            int a = w->node_index[c * model->max_nodes + i], b = w->node_index[c * model->max_nodes + i + 1];
            double ds = (b >= 0 ? dx[b] : 0.0) - (a >= 0 ? dx[a] : 0.0), sm = cs->m[i + 1] - cs->m[i];
            if (ds < 0.0 && -ds * t > 0.5 * sm) t = 0.5 * sm / -ds;
        }
    }
    return t;
}

/* Whether the unknowns are those of the last factored Jacobian (same kinds, elements and band); if not,
 * they become the ones it will be built for. */
static int same_unknowns(cs_system *sys, int n) {
    const cs_slot *sl = sys->rows.slots;
    int same = sys->newton.factored && n == sys->lu_n && sys->kl == sys->lu_kl && sys->ku == sys->lu_ku;
    for (int k = 0; same && k < n; k++)
        same = same_slot(&sys->slots_lu[k], &sl[k]);
    if (!same) {
        memcpy(sys->slots_lu, sl, (size_t)n * sizeof *sl);
        sys->lu_n = n, sys->lu_kl = sys->kl, sys->lu_ku = sys->ku;
    }
    return same;
}

/* ---- predictor ----
 * The barrier moves smoothly between failures, so each unknown starts from its committed value plus
 * the increment it took over the last step (a linear extrapolation in time). Unknowns are keyed by
 * element (post, cable node by its support, face contact, crush), so the memory survives nodes being
 * inserted or removed. A re-solve inside the same step (after a failure) does not extrapolate, nor does
 * the step after a jump (a failure, a snap or a fall: cs_system_jumped): the last increment then holds
 * the jump, which the barrier does not repeat. */
static size_t slot_key(const cs_model *model, const cs_state *s, const cs_slot *u) {
    size_t np = (size_t)model->post_count, nc = (size_t)model->cable_count;
    if (u->kind == CS_U_TILT) return 2 * (size_t)u->a + (size_t)u->b;
    if (u->kind == CS_U_NODE) {
        int id = s->cables[u->a].node[u->b];
        size_t at = id >= 0                 ? (size_t)id
                    : cs_node_is_corner(id) ? np + (size_t)cs_node_corner(id)
                                            : np + CS_CORNERS + (id == CS_NODE_END); /* an end fitting */
        return 2 * np + (size_t)u->a * (np + CS_CORNERS + 2) + at;
    }
    size_t past = 2 * np + nc * (np + CS_CORNERS + 2); /* heights, the crush, anchors, pulls, rises */
    if (u->kind == CS_U_HEIGHT) return past + CS_CORNERS * (size_t)u->a + (size_t)u->b;
    if (u->kind == CS_U_ANCHOR) return past + CS_CORNERS * nc + 1 + 2 * (size_t)u->a + (size_t)u->b;
    if (u->kind == CS_U_PULL) return past + CS_CORNERS * nc + 5 + (size_t)u->a;
    if (u->kind == CS_U_LIFT) return past + CS_CORNERS * nc + 5 + np + (size_t)u->a;
    return past + CS_CORNERS * nc;
}

static void predict(const cs_model *model, const cs_state *s, cs_system *sys, int n, double *x) {
    int moved = 0;
    double *dx = sys->scratch;
    for (int k = 0; k < n; k++) {
        size_t key = slot_key(model, s, &sys->rows.slots[k]);
        dx[k] = 0.0;
        if (sys->last_step[key] == s->step) continue; /* a re-solve: the pose has not changed */
        if (sys->last_step[key] == s->step - 1 && s->step != sys->still_step)
            dx[k] = x[k] - sys->last[key], moved |= dx[k] != 0.0;
        sys->last[key] = x[k], sys->last_step[key] = s->step;
    }
    if (!moved) return;
    double t = max_step(model, s, &sys->rows, dx);
    for (int k = 0; k < n; k++)
        x[k] += t * dx[k];
}

/* ---- the problem Newton sees ---- */
typedef struct problem {
    const cs_model *model;
    cs_state *s;
    cs_system *sys;
} problem;

static void place(void *ctx, const double *x) {
    problem *p = ctx;
    scatter(p->model, p->s, &p->sys->rows, p->sys->rows.n, x);
}

static void residual(void *ctx, double *r) {
    problem *p = ctx;
    if (p->sys->rows.n > 0) residual_rows(p->model, p->s, &p->sys->rows, 0, p->sys->rows.n - 1, r);
}

static int jacobian(void *ctx, const double *x, const double *r, cs_band *jac) {
    problem *p = ctx;
    if (cs_band_shape(jac, p->sys->rows.n, p->sys->kl, p->sys->ku) != 0) return -1;
    jacobian_at(p->model, p->s, p->sys, x, r);
    return 0;
}

static double step_limit(void *ctx, const double *dx) {
    problem *p = ctx;
    return max_step(p->model, p->s, &p->sys->rows, dx);
}

static cs_newton_problem problem_of(problem *p) {
    return (cs_newton_problem){p, p->sys->rows.n, place, residual, jacobian, step_limit};
}

/* Assemble the unknowns and the band's shape; 0, or -1 if the band does not fit. */
static int prepare(const cs_model *model, const cs_state *s, cs_system *sys) {
    int n = assemble(model, s, sys);
    band_shape(model, s, sys, n);
    return (size_t)n * (size_t)(2 * sys->kl + sys->ku + 1) > sys->newton.band.capacity ? -1 : 0;
}

double cs_system_solve(const cs_model *model, cs_state *s, cs_system *sys) {
    if (prepare(model, s, sys) != 0) return -1.0; /* the caller falls back */
    int n = sys->rows.n;
    if (n <= 0) return 0.0;
    double *x = sys->newton.x;
    gather(s, &sys->rows, n, x);
    predict(model, s, sys, n, x);
    if (!same_unknowns(sys, n)) cs_newton_forget(&sys->newton);
    problem p = {model, s, sys};
    cs_newton_problem np = problem_of(&p);
    long before = sys->newton.evaluations;
    double rn = cs_newton_solve(&sys->newton, &np, model->scenario.solver_tolerance);
    long passes = sys->newton.evaluations - before; /* the work: each pass over its n rows */
    s->work->count.newton += passes;
    s->work->count.work += (double)passes * (double)n;
    return rn > CS_NEWTON_GIVE_UP || rn < 0.0 ? -1.0 : rn; /* stalled far off: the fallback goes on */
}

void cs_system_keep(const cs_model *model, cs_state *s, cs_system *sys) {
    sys->kept_n = assemble(model, s, sys);
    gather(s, &sys->rows, sys->kept_n, sys->kept);
    memcpy(sys->slots_kept, sys->rows.slots, (size_t)sys->kept_n * sizeof *sys->slots_kept);
}

void cs_system_go_back(const cs_model *model, cs_state *s, cs_system *sys) {
    memcpy(sys->rows.slots, sys->slots_kept, (size_t)sys->kept_n * sizeof *sys->slots_kept);
    scatter(model, s, &sys->rows, sys->kept_n, sys->kept);
}

int cs_system_linearize(const cs_model *model, cs_state *s, cs_system *sys, int cap, int *kind, double *x,
                        double *r, double *jac) {
    if (prepare(model, s, sys) != 0) return -1;
    int n = sys->rows.n;
    if (n > cap) return -1;
    gather(s, &sys->rows, n, x);
    for (int k = 0; k < n; k++)
        kind[k] = sys->rows.slots[k].kind;
    cs_system_residual(model, s, sys, n, x, r);
    cs_band *b = &sys->newton.band;
    cs_band_shape(b, n, sys->kl, sys->ku);
    jacobian_at(model, s, sys, x, r);
    cs_newton_forget(&sys->newton); /* the band now holds this Jacobian, not the factors */
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            jac[i * n + j] = cs_band_holds(b, i, j) ? *cs_band_entry(b, i, j) : 0.0;
    return n;
}

void cs_system_residual(const cs_model *model, cs_state *s, cs_system *sys, int n, const double *x,
                        double *r) {
    scatter(model, s, &sys->rows, n, x);
    if (n > 0) residual_rows(model, s, &sys->rows, 0, n - 1, r);
}
