/* The barrier's quasi-static equilibrium as one nonlinear system, solved by semi-smooth Newton.
 *
 * Unknowns: the tilt (2) of every standing post on a cable path, the material coordinate m of every
 * support node the rope can slide through (posts that do not clamp, face corners), and the crush.
 * Residuals (each scaled by its unit: Fu for nodes and contacts; for a post, its strongest rope's Fu at
 * that rope's lever, so that one tolerance is one force everywhere; the crush curve's top):
 *   post:   Q_cables(alpha) - Q_resist(alpha) - J (alpha - alpha_c - h w_c) / h^2 (swing; post.c)
 *   node:   lambda - proj_[-b, b](lambda + c dm) - eps c dm,                (capstan, Eq. 3)
 *           lambda = T_L - T_R, b = tanh(mu theta / 2) (T_L + T_R), dm = m - m_commit, c = EA / l.
 *           |T_L - T_R| <= b is T_high <= exp(mu theta) T_low; the projection makes the node stick
 *           (dm = 0) inside the band and slide (lambda = +-b) outside it, as Coulomb friction.
 *           eps keeps a node between two slack spans sticking instead of undetermined; in a slide
 *           it adds eps c dm to the friction (with + it would take it off: a negative stiffness that
 *           a sagging rope's few kN/m cannot carry, and the rope shuttles from step to step).
 *   height: the same for a contact on the face, lambda = the pull up the face, b = mu F_n + w: the
 *           floor w holds the contact of a slack rope where it is (with b = 0 only the eps term
 *           would, and any dz with eps c |dz| below the tolerance, up to ~0.4 m at a tolerance of
 *           1e-4, would pass).
 *   crush:  N(crush) - C(crush)                                             (barrier.c)
 * The clamp's corners are rounded over w = CS_FRICTION_FLOOR Fu (parabolas) so that Newton sees a smooth
 * switch between sticking and sliding (docs/assumptions.md).
 * Unknowns are ordered along the barrier, so the Jacobian is banded: it is formed from the spans'
 * tension gradients (the crush's column by a difference quotient), and a banded LU with partial
 * pivoting solves each Newton step; between rebuilds, Broyden's updates keep the factored Jacobian in
 * step with the residual. Cost is linear in the number of posts; the solution does not
 * depend on any sweep order, so a symmetric impact stays symmetric. */
#include "internal.h"
#include "vec3.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#define CS_STICK_EPS 1e-4
#define CS_NEWTON_GIVE_UP 1e-2 /* residual above which the step goes to Gauss-Seidel instead */
#define CS_BROYDEN_MAX 8       /* rank-one updates kept on one factored Jacobian */

enum { U_TILT = 0, U_NODE = 1, U_CRUSH = 2, U_HEIGHT = 3 };

static int is_corner(int id) {
    return id == CS_NODE_LEFT || id == CS_NODE_RIGHT;
}

/* Index on the cable's path of face corner k (0 left, 1 right). */
static int corner_node(const cs_cable_state *cs, int k) {
    int id = k == 0 ? CS_NODE_LEFT : CS_NODE_RIGHT;
    for (int i = 1; i + 1 < cs->node_count; i++)
        if (cs->node[i] == id) return i;
    return -1;
}

static int node_slides(const cs_model *model, const cs_cable_state *cs, int i) {
    int id = cs->node[i];
    return is_corner(id) || (id >= 0 && !model->posts[id].clamped);
}

/* ---- assembling the unknowns in barrier order ---- */
typedef struct slot {
    double x;
    int kind, a, b;
} slot;

/* The band holds rows of up to 2 kl + ku + 1 entries; a post slot has 2 + cables unknowns, and the
 * face adds two corners per cable and the crush, so this covers neighbouring slots with room. */
int cs_solver_init(const cs_model *model, cs_solver *w) {
    memset(w, 0, sizeof *w);
    size_t nc = (size_t)model->cable_count, np = (size_t)model->post_count, nn = (size_t)model->max_nodes;
    size_t n = 2 * np + nc * nn + 2 * nc + 1, per_row = 3 * (12 + 8 * nc) + 1;
    w->slots = calloc(n, sizeof *w->slots);
    w->slots_lu = calloc(n, sizeof *w->slots_lu);
    w->slots_kept = calloc(n, sizeof *w->slots_kept);
    w->slots_sorted = calloc(n, sizeof *w->slots_sorted);
    w->slots_bw = calloc(n, sizeof *w->slots_bw);
    w->nodes_bw = calloc(nc * (nn + 1) + 1, sizeof *w->nodes_bw);
    w->tilt_index = calloc(np ? np : 1, sizeof *w->tilt_index);
    w->node_index = calloc(nc ? nc * nn : 1, sizeof *w->node_index);
    w->height_index = calloc(nc ? 2 * nc : 1, sizeof *w->height_index);
    w->x = calloc(6 * n, sizeof *w->x);
    w->updates = calloc(2 * CS_BROYDEN_MAX * n, sizeof *w->updates);
    w->band_capacity = n * per_row;
    w->band = calloc(w->band_capacity, sizeof *w->band);
    w->spans = calloc(nc * nn + 1, sizeof *w->spans);
    w->chords = calloc(4 * nc * nn + 1, sizeof *w->chords);
    w->axes = calloc(18 * np + 1, sizeof *w->axes);
    w->pivot = calloc(n, sizeof *w->pivot);
    w->key_count = 2 * np + nc * (np + 2) + 2 * nc + 1; /* see slot_key */
    w->last = calloc(w->key_count, sizeof *w->last);
    w->last_step = calloc(w->key_count, sizeof *w->last_step);
    if (!w->slots || !w->slots_lu || !w->slots_kept || !w->slots_sorted || !w->slots_bw || !w->nodes_bw ||
        !w->last || !w->last_step || !w->tilt_index || !w->node_index || !w->height_index || !w->x ||
        !w->updates || !w->band || !w->pivot || !w->spans || !w->chords || !w->axes)
        return -1;
    w->r = w->x + n, w->dx = w->x + 2 * n, w->xt = w->x + 3 * n, w->rt = w->x + 4 * n, w->kept = w->x + 5 * n;
    return 0;
}

/* Forget the history of the predictor (a new run). */
void cs_solver_reset(cs_solver *w) {
    for (size_t k = 0; k < w->key_count; k++)
        w->last_step[k] = -2, w->last[k] = 0.0;
    w->lu_valid = 0, w->bw_valid = 0;
}

void cs_solver_free(cs_solver *w) {
    free(w->slots), free(w->slots_lu), free(w->slots_kept), free(w->slots_sorted), free(w->slots_bw),
        free(w->nodes_bw), free(w->tilt_index), free(w->node_index), free(w->height_index), free(w->x),
        free(w->updates), free(w->band), free(w->pivot), free(w->last), free(w->last_step), free(w->spans),
        free(w->chords), free(w->axes);
    memset(w, 0, sizeof *w);
}

static int slot_before(const slot *a, const slot *b) {
    if (a->x != b->x) return a->x < b->x;
    if (a->kind != b->kind) return a->kind < b->kind;
    if (a->a != b->a) return a->a < b->a;
    return a->b < b->b;
}

/* End of the run in order that starts at lo. */
static int run_end(const slot *sl, int lo, int n) {
    while (lo + 1 < n && !slot_before(&sl[lo + 1], &sl[lo]))
        lo++;
    return lo + 1;
}

/* Natural merge sort: the list is built as a few runs already in order along x (the posts, each
 * cable's nodes), which passes of pairwise merges join in O(n log runs), with no calls through a
 * pointer as qsort's. The order is total, so the result is qsort's. */
static void sort_slots(slot *sl, slot *tmp, int n) {
    for (;;) {
        int lo = 0, runs = 0;
        while (lo < n) {
            int mid = run_end(sl, lo, n), hi = mid < n ? run_end(sl, mid, n) : n, i = lo, j = mid, k = lo;
            while (i < mid && j < hi)
                tmp[k++] = slot_before(&sl[j], &sl[i]) ? sl[j++] : sl[i++];
            while (i < mid)
                tmp[k++] = sl[i++];
            while (j < hi)
                tmp[k++] = sl[j++];
            lo = hi, runs++;
        }
        memcpy(sl, tmp, (size_t)n * sizeof *sl);
        if (runs <= 1) return;
    }
}

static int post_on_path(const cs_model *model, const cs_state *s, int p) {
    const cs_post_state *ps = &s->posts[p];
    if (!cs_post_standing(ps) || ps->captured || cs_post_held(model, s, p)) return 0;
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].status == CS_CABLE_INTACT && s->cables[c].where[p] > 0) return 1;
    return 0;
}

/* Fill the unknown list (kind, a, b) sorted along x; returns the count. */
static int assemble(const cs_model *model, cs_state *s, cs_solver *w) {
    slot *sl = w->slots;
    int n = 0;
    for (int p = 0; p < model->post_count; p++) {
        if (!post_on_path(model, s, p)) continue;
        sl[n++] = (slot){model->posts[p].x, U_TILT, p, 0};
        sl[n++] = (slot){model->posts[p].x, U_TILT, p, 1};
    }
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (node_slides(model, cs, i)) sl[n++] = (slot){cs->pos[3 * i], U_NODE, c, i};
            if (is_corner(cs->node[i]))
                sl[n++] = (slot){cs->pos[3 * i], U_HEIGHT, c, cs->node[i] == CS_NODE_LEFT ? 0 : 1};
        }
    }
    if (cs_face_loaded(model, s)) sl[n++] = (slot){s->pos[0], U_CRUSH, 0, 0};
    sort_slots(sl, w->slots_sorted, n);
    /* index maps: tilt of post p, node i of cable c, crush */
    for (int p = 0; p < model->post_count; p++)
        w->tilt_index[p] = -1;
    for (int c = 0; c < model->cable_count; c++)
        for (int i = 0; i < model->max_nodes; i++)
            w->node_index[c * model->max_nodes + i] = -1;
    w->crush_index = -1;
    for (int i = 0; i < 2 * model->cable_count; i++)
        w->height_index[i] = -1;
    for (int k = 0; k < n; k++) {
        if (sl[k].kind == U_HEIGHT) w->height_index[2 * sl[k].a + sl[k].b] = k;
        if (sl[k].kind == U_TILT && sl[k].b == 0) w->tilt_index[sl[k].a] = k;
        if (sl[k].kind == U_NODE) w->node_index[sl[k].a * model->max_nodes + sl[k].b] = k;
        if (sl[k].kind == U_CRUSH) w->crush_index = k;
    }
    return n;
}

/* Unknowns a node's position depends on: its post's tilt, or the crush for a corner. */
static void widen(int k, int *lo, int *hi) {
    if (k < 0) return;
    if (k < *lo) *lo = k;
    if (k > *hi) *hi = k;
}

static void position_deps(const cs_solver *w, const cs_cable_state *cs, int c, int i, int *lo, int *hi) {
    int id = cs->node[i], k = -1;
    if (id >= 0 && w->tilt_index[id] >= 0) k = w->tilt_index[id];
    if (is_corner(id)) {
        widen(w->height_index[2 * c + (id == CS_NODE_LEFT ? 0 : 1)], lo, hi);
        k = w->crush_index;
    }
    if (k < 0) return;
    int k2 = (id >= 0) ? k + 1 : k;
    if (k < *lo) *lo = k;
    if (k2 > *hi) *hi = k2;
}

/* Range of unknowns the residual of a node's neighbourhood (nodes i-1..i+1) depends on. */
static void neighbourhood(const cs_model *model, const cs_solver *w, const cs_cable_state *cs, int c, int i,
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
static void bandwidth(const cs_model *model, cs_state *s, cs_solver *w, int n, int *kl, int *ku) {
    *kl = *ku = 0;
    for (int k = 0; k < n; k++) {
        const slot *u = &w->slots[k];
        int lo = k, hi = k;
        if (u->kind == U_NODE) {
            neighbourhood(model, w, &s->cables[u->a], u->a, u->b, &lo, &hi);
        } else if (u->kind == U_HEIGHT) {
            neighbourhood(model, w, &s->cables[u->a], u->a, corner_node(&s->cables[u->a], u->b), &lo, &hi);
        } else if (u->kind == U_TILT) {
            for (int c = 0; c < model->cable_count; c++) {
                const cs_cable_state *cs = &s->cables[c];
                if (cs->status == CS_CABLE_INTACT && cs->where[u->a] > 0)
                    neighbourhood(model, w, cs, c, cs->where[u->a], &lo, &hi);
            }
            hi = hi > k + 1 ? hi : k + 1;
            lo = lo < k - 1 ? lo : k - 1;
        } else {
            for (int c = 0; c < model->cable_count; c++) {
                const cs_cable_state *cs = &s->cables[c];
                if (cs->status != CS_CABLE_INTACT) continue;
                for (int i = 1; i + 1 < cs->node_count; i++)
                    if (is_corner(cs->node[i])) neighbourhood(model, w, cs, c, i, &lo, &hi);
            }
        }
        if (lo < 0) lo = 0;
        if (hi > n - 1) hi = n - 1;
        if (k - lo > *kl) *kl = k - lo; /* row k depends on column lo: below the diagonal */
        if (hi - k > *ku) *ku = hi - k;
    }
}

static int same_slot(const slot *a, const slot *b) {
    return a->kind == b->kind && a->a == b->a && a->b == b->b;
}

/* The Jacobian's lower and upper bandwidth into w->kl, w->ku. They depend on the unknowns in their order
 * and on every cable's nodes alone; while those are what they were at the last call (most solves),
 * the last answer stands. */
static void band_shape(const cs_model *model, cs_state *s, cs_solver *w, int n) {
    int same = w->bw_valid && n == w->bw_n, stride = model->max_nodes + 1;
    for (int k = 0; same && k < n; k++)
        same = same_slot(&w->slots_bw[k], &w->slots[k]);
    for (int c = 0; same && c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        const int *rec = w->nodes_bw + c * stride;
        int count = cs->status == CS_CABLE_INTACT ? cs->node_count : -1;
        same = rec[0] == count && (count < 0 || memcmp(rec + 1, cs->node, (size_t)count * sizeof *rec) == 0);
    }
    if (same) return;
    bandwidth(model, s, w, n, &w->kl, &w->ku);
    memcpy(w->slots_bw, w->slots, (size_t)n * sizeof *w->slots);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        int *rec = w->nodes_bw + c * stride;
        rec[0] = cs->status == CS_CABLE_INTACT ? cs->node_count : -1;
        if (rec[0] > 0) memcpy(rec + 1, cs->node, (size_t)rec[0] * sizeof *rec);
    }
    w->bw_n = n, w->bw_valid = 1;
}

/* ---- state <-> vector ---- */
static void gather(const cs_state *s, const cs_solver *w, int n, double *x) {
    for (int k = 0; k < n; k++) {
        const slot *u = &w->slots[k];
        if (u->kind == U_TILT) x[k] = s->posts[u->a].tilt[u->b];
        if (u->kind == U_NODE) x[k] = s->cables[u->a].m[u->b];
        if (u->kind == U_CRUSH) x[k] = s->crush;
        if (u->kind == U_HEIGHT) x[k] = s->cables[u->a].corner_z[u->b];
    }
}

/* Cable c's span chords from the last placement. */
static double *chords_of(const cs_model *model, const cs_solver *w, int c) {
    return w->chords + 4 * (size_t)c * (size_t)model->max_nodes;
}

/* Put x into the state and bring every node position, span chord and tension in line with it. */
static void scatter(const cs_model *model, cs_state *s, const cs_solver *w, int n, const double *x) {
    for (int k = 0; k < n; k++) {
        const slot *u = &w->slots[k];
        if (u->kind == U_TILT) s->posts[u->a].tilt[u->b] = x[k];
        if (u->kind == U_NODE) s->cables[u->a].m[u->b] = x[k];
        if (u->kind == U_CRUSH) s->crush = x[k];
        if (u->kind == U_HEIGHT) s->cables[u->a].corner_z[u->b] = x[k];
    }
    cs_contact_place_corners(model, s, s->crush);
    cs_post_place_captured(model, s, s->crush, NULL, NULL);
    for (int p = 0; p < model->post_count; p++)
        cs_post_place_nodes(model, s, p, s->posts[p].tilt, w->tilt_index[p] >= 0 ? w->axes + 18 * p : NULL);
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].status == CS_CABLE_INTACT)
            cs_cable_update_tensions(&model->cables[c], &s->cables[c], chords_of(model, w, c));
}

/* ---- residuals ---- */
/* clamp(y, -b, b) with its corners rounded over a width w, so Newton sees a smooth switch between
 * sticking and sliding. Each corner is the ramp max(x, 0) (x in units of w) with a parabola over
 * |x| < h: C1, exact outside the band (a support well inside its friction band sticks exactly), at
 * most h/4 = w ln 2 off at the corner (h = 4 ln 2, as far off as softplus log(1 + e^x), used until
 * session 18, whose exp and log1p were 8% of a run's instructions). */
#define RAMP_H 2.772588722239781 /* 4 ln 2 */
static double ramp(double x) {
    if (x <= -RAMP_H) return 0.0;
    if (x >= RAMP_H) return x;
    return (x + RAMP_H) * (x + RAMP_H) / (4.0 * RAMP_H);
}
static double smooth_clamp(double y, double b, double w) {
    double iw = 1.0 / w; /* not on the chain from y: the division runs beside it */
    return y - w * ramp((y - b) * iw) + w * ramp((-y - b) * iw);
}

static double node_residual(const cs_model *model, const cs_state *s, const cs_solver *w, int c, int i) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    const double *ch = chords_of(model, w, c);
    double tl = cs->tension[i - 1], tr = cs->tension[i];
    double lambda = tl - tr, b = cs_node_band_fraction(model, cm, cs, i, ch) * (tl + tr);
    double cstiff = cm->rope.ea / (ch[4 * (i - 1) + 3] + ch[4 * i + 3] + 1e-9); /* the spans' lengths */
    double dm = cs->m[i] - cs->m_commit[i], y = lambda + cstiff * dm;
    double proj = smooth_clamp(y, b, CS_FRICTION_FLOOR * cm->rope.fu);
    return (lambda - proj - CS_STICK_EPS * cstiff * dm) * (1.0 / cm->rope.fu);
}

/* The contact of corner k on the face: Coulomb friction along the vertical face, as for a support
 * (lambda = the spans' pull up the face, b = mu times their pull into it, dz from the last step). */
static double height_residual(const cs_model *model, const cs_state *s, const cs_solver *w, int c, int k) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    const double *ch = chords_of(model, w, c);
    int i = corner_node(cs, k);
    double fz, fn;
    cs_contact_face_force(model, s, c, i, ch, &fz, &fn);
    double b = model->vehicle.def.face_friction * fn;
    double cstiff = cm->rope.ea / (ch[4 * (i - 1) + 3] + ch[4 * i + 3] + 1e-9);
    double dz = cs->corner_z[k] - cs->corner_z_commit[k];
    double wf = CS_FRICTION_FLOOR * cm->rope.fu, proj = smooth_clamp(fz + cstiff * dz, b + wf, wf);
    return (fz - proj - CS_STICK_EPS * cstiff * dz) * (1.0 / cm->rope.fu);
}

/* Residual row k; a post's two rows come together, from its first. */
static void residual_row(const cs_model *model, cs_state *s, const cs_solver *w, int k, double *r) {
    const slot *u = &w->slots[k];
    if (u->kind == U_HEIGHT) {
        r[k] = height_residual(model, s, w, u->a, u->b);
    } else if (u->kind == U_NODE) {
        r[k] = node_residual(model, s, w, u->a, u->b);
    } else if (u->kind == U_TILT && u->b == 0) {
        double q[2];
        cs_post_residual_now(model, s, u->a, w->chords, w->axes + 18 * u->a, q);
        double scale = model->posts[u->a].moment_scale;
        double inv = 1.0 / scale;
        r[k] = q[0] * inv, r[k + 1] = q[1] * inv;
    } else if (u->kind == U_CRUSH) {
        const cs_vehicle_def *v = &model->vehicle.def;
        double nf = cs_face_normal_force_now(model, s, w->chords);
        r[k] = (nf - cs_crush_force(v, s->crush, s->crush_max)) / v->crush_force[v->crush_point_count - 1];
    }
}

static void residual(const cs_model *model, cs_state *s, const cs_solver *w, int n, double *r) {
    for (int k = 0; k < n; k++)
        residual_row(model, s, w, k, r);
}

static double norm_inf(const double *r, int n) {
    double m = 0.0;
    for (int k = 0; k < n; k++)
        m = fabs(r[k]) > m ? fabs(r[k]) : m; /* fmax without its call: a NaN is skipped as by fmax */
    return m;
}

/* ---- banded LU with partial pivoting: row i keeps columns i-kl .. i+ku+kl ---- */
#define BAND(w, i, j) ((w)->band[(size_t)(i) * (size_t)(w)->band_width + (size_t)((j) - (i) + (w)->kl)])

/* The loops walk from the diagonal entry d = &BAND(w, k, k): along row k by d[j - k], down column k by
 * steps of band_width - 1 (one index per entry rather than BAND's). The factors keep U's diagonal as its
 * reciprocals. */
static int band_factor(cs_solver *w, int n) {
    int kl = w->kl, ku = w->ku;
    ptrdiff_t down = w->band_width - 1;
    for (int k = 0; k < n; k++) {
        int last = k + kl < n - 1 ? k + kl : n - 1, p = k;
        double *d = &BAND(w, k, k), best = fabs(d[0]);
        for (int i = k + 1; i <= last; i++)
            if (fabs(d[(i - k) * down]) > best) best = fabs(d[(i - k) * down]), p = i;
        w->pivot[k] = p;
        if (best == 0.0) return -1;
        int width = (k + ku + kl < n - 1 ? k + ku + kl : n - 1) - k; /* row k's entries right of d */
        if (p != k)
            for (double *dp = d + (p - k) * down, *e = d; e <= d + width; e++, dp++) {
                double t = *e;
                *e = *dp;
                *dp = t;
            }
        double inv = 1.0 / d[0];
        for (int i = k + 1; i <= last; i++) {
            double *di = d + (i - k) * down, f = di[0] * inv;
            di[0] = f;
            if (f != 0.0)
                for (int j = 1; j <= width; j++)
                    di[j] -= f * d[j];
        }
        d[0] = inv; /* the solve multiplies by it instead of dividing on each row's path */
    }
    return 0;
}

static void band_solve(const cs_solver *w, int n, double *b) {
    int kl = w->kl, ku = w->ku;
    ptrdiff_t down = w->band_width - 1;
    for (int k = 0; k < n; k++) {
        int p = w->pivot[k];
        if (p != k) {
            double t = b[k];
            b[k] = b[p];
            b[p] = t;
        }
        int last = k + kl < n - 1 ? k + kl : n - 1;
        const double *l = &BAND(w, k, k);
        double bk = b[k];
        for (int i = k + 1; i <= last; i++)
            b[i] -= *(l += down) * bk;
    }
    for (int k = n - 1; k >= 0; k--) {
        int width = (k + ku + kl < n - 1 ? k + ku + kl : n - 1) - k;
        const double *d = &BAND(w, k, k), *bk = b + k;
        /* four partial sums, so that the additions do not wait on one another one by one */
        double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
        int j = 1;
        for (; j + 3 <= width; j += 4)
            s0 += d[j] * bk[j], s1 += d[j + 1] * bk[j + 1], s2 += d[j + 2] * bk[j + 2],
                s3 += d[j + 3] * bk[j + 3];
        for (; j <= width; j++)
            s0 += d[j] * bk[j];
        b[k] = (b[k] - ((s0 + s1) + (s2 + s3))) * d[0];
    }
}

/* ---- the Jacobian ----
 * Every row is a function of a few cable nodes: their positions (moved by a post's tilt, a contact's
 * height or the crush) and their material coordinates. Each row's gradient with respect to those is
 * formed from the spans' tension gradients (cable.c) and chained to the columns that move them. The crush
 * moves every corner and captured post at once: its column alone is a difference quotient of the full
 * residual (a step of 1e-8 m). Until session 14 every column was a difference quotient (35% of APS3's
 * time). */

/* A column of the Jacobian and a 3-vector: how a node's position moves along it. */
typedef struct dep {
    int col;
    double v[3];
} dep;

/* The columns that move node j of cable c other than the crush (a post's two tilts: the attachment's
 * arm times the axis' Jacobian; a contact's height: the body's z axis). */
static int position_columns(const cs_model *model, const cs_state *s, const cs_solver *w, int c, int j,
                            dep *out) {
    const cs_cable_state *cs = &s->cables[c];
    int id = cs->node[j];
    if (id >= 0 && w->tilt_index[id] >= 0) {
        const double *ja = w->axes + 18 * id;
        double l = model->cables[c].z + model->posts[id].pivot;
        for (int k = 0; k < 2; k++)
            out[k] = (dep){w->tilt_index[id] + k, {l * ja[k], l * ja[2 + k], l * ja[4 + k]}};
        return 2;
    }
    if (is_corner(id)) {
        int h = w->height_index[2 * c + (id == CS_NODE_LEFT ? 0 : 1)];
        if (h < 0) return 0;
        double ez[3] = {0.0, 0.0, 1.0};
        out[0].col = h;
        quat_rotate(out[0].v, s->quat, ez);
        return 1;
    }
    return 0;
}

static void add_entry(cs_solver *w, int n, int i, int j, double value) {
    if (i >= 0 && i < n && j >= 0 && i >= j - w->ku && i <= j + w->kl) BAND(w, i, j) += value;
}

/* Row `row`'s gradient with respect to nodes i-1, i, i+1 of cable c (positions gp, materials gm), chained
 * to the columns. */
static void add_node_gradient(const cs_model *model, const cs_state *s, cs_solver *w, int n, int row, int c,
                              int i, double gp[3][3], const double *gm) {
    for (int k = 0; k < 3; k++) {
        int j = i - 1 + k;
        dep d[2];
        int count = position_columns(model, s, w, c, j, d);
        for (int q = 0; q < count; q++)
            add_entry(w, n, row, d[q].col, v3_dot(gp[k], d[q].v));
        int m = w->node_index[c * model->max_nodes + j];
        if (m >= 0) add_entry(w, n, row, m, gm[k]);
    }
}

/* The two spans at node i of cable c, from the Jacobian's cache. */
static const cs_span_grad *spans_at(const cs_model *model, const cs_solver *w, int c, int i) {
    return w->spans + c * model->max_nodes + i - 1;
}

/* Gradient of rho . f_i, f_i = T_R u_R - T_L u_L the spans' pull on node i, for a fixed 3-vector rho:
 * d(T u)/dd = u dT/dd^T + T (I - u u^T) / l, and d_L = p_i - p_{i-1}, d_R = p_{i+1} - p_i. Adds to gp
 * and gm (nodes i-1, i, i+1). */
static void force_gradient(const cs_span_grad *sp, const double *rho, double gp[3][3], double *gm) {
    for (int k = 0; k < 2; k++) {
        const cs_span_grad *a = &sp[k];
        double sign = k == 0 ? -1.0 : 1.0, ur = v3_dot(a->u, rho), g[3];
        for (int e = 0; e < 3; e++)
            g[e] = sign * (a->dt_dd[e] * ur + (a->l > 1e-12 ? a->t * (rho[e] - a->u[e] * ur) / a->l : 0.0));
        v3_addto(gp[k + 1], g, 1.0); /* the span's far end: node i-1 + k + 1 */
        v3_addto(gp[k], g, -1.0);
        gm[k] += sign * ur * a->dt_dm[0];
        gm[k + 1] += sign * ur * a->dt_dm[1];
    }
}

/* Derivatives of smooth_clamp(y, b, w) with respect to y and b. */
static double ramp_slope(double x) {
    if (x <= -RAMP_H) return 0.0;
    return x >= RAMP_H ? 1.0 : (x + RAMP_H) / (2.0 * RAMP_H);
}
static void smooth_clamp_slopes(double y, double b, double w, double *dy, double *db) {
    double iw = 1.0 / w; /* as smooth_clamp, so both see the same x */
    double s1 = ramp_slope((y - b) * iw), s2 = ramp_slope((-y - b) * iw);
    *dy = 1.0 - s1 - s2, *db = s1 - s2;
}

/* The gradient of the turning angle theta at node i (nodes i-1, i, i+1); 0 where the rope runs
 * straight (theta's kink). */
static void angle_gradient(const cs_span_grad *sp, double coef, double gp[3][3]) {
    const double *a = sp[0].u, *b = sp[1].u;
    double x[3], cth = v3_dot(a, b);
    v3_cross(x, a, b);
    double sth = v3_norm(x);
    if (sth < 1e-12 || sp[0].l <= 1e-12 || sp[1].l <= 1e-12) return;
    for (int e = 0; e < 3; e++) {
        double da = -(b[e] - cth * a[e]) / (sp[0].l * sth), db = -(a[e] - cth * b[e]) / (sp[1].l * sth);
        gp[0][e] -= coef * da, gp[1][e] += coef * (da - db), gp[2][e] += coef * db;
    }
}

/* Gradient of span lengths l_L + l_R (for the rope's stiffness c = EA / (l_L + l_R)). */
static void length_gradient(const cs_span_grad *sp, double coef, double gp[3][3]) {
    for (int k = 0; k < 2; k++) {
        v3_addto(gp[k + 1], sp[k].u, coef);
        v3_addto(gp[k], sp[k].u, -coef);
    }
}

static void node_row(const cs_model *model, const cs_state *s, cs_solver *w, int n, int row, int c, int i) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    const cs_span_grad *sp = spans_at(model, w, c, i);
    double gp[3][3] = {{0}}, gm[3] = {0};
    int id = cs->node[i];
    double mu = id >= 0 ? cm->mu_post : model->vehicle.def.face_friction, tl = sp[0].t, tr = sp[1].t;
    double th = cs_node_band_fraction(model, cm, cs, i, chords_of(model, w, c)), lam = tl - tr,
           b = th * (tl + tr);
    double len = sp[0].l + sp[1].l + 1e-9, cstiff = cm->rope.ea / len, dm = cs->m[i] - cs->m_commit[i];
    double py, pb, fu = cm->rope.fu;
    smooth_clamp_slopes(lam + cstiff * dm, b, CS_FRICTION_FLOOR * fu, &py, &pb);
    /* r Fu = lambda - proj(y, b) - eps c dm: its slopes on T_L, T_R, theta, c and dm */
    double on_tl = (1.0 - py) - pb * th, on_tr = -(1.0 - py) - pb * th;
    double on_theta = -pb * (1.0 - th * th) * 0.5 * mu * (tl + tr), on_c = -(py + CS_STICK_EPS) * dm;
    for (int k = 0; k < 2; k++) {
        double on_t = k == 0 ? on_tl : on_tr;
        v3_addto(gp[k + 1], sp[k].dt_dd, on_t);
        v3_addto(gp[k], sp[k].dt_dd, -on_t);
        gm[k] += on_t * sp[k].dt_dm[0], gm[k + 1] += on_t * sp[k].dt_dm[1];
    }
    angle_gradient(sp, on_theta, gp);
    length_gradient(sp, on_c * -cm->rope.ea / (len * len), gp);
    gm[1] += -(py + CS_STICK_EPS) * cstiff;
    for (int k = 0; k < 3; k++) {
        v3_scale(gp[k], gp[k], 1.0 / fu);
        gm[k] /= fu;
    }
    add_node_gradient(model, s, w, n, row, c, i, gp, gm);
}

/* The body's axes in the world. */
static void body_axes(const cs_state *s, double ax[3][3]) {
    for (int k = 0; k < 3; k++) {
        double e[3] = {k == 0, k == 1, k == 2};
        quat_rotate(ax[k], s->quat, e);
    }
}

/* A face contact's row (height_residual): r Fu = fz - proj(fz + c dz, mu fn + w, w) - eps c dz. */
static void height_row(const cs_model *model, const cs_state *s, cs_solver *w, int n, int row, int c, int k) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    int i = corner_node(cs, k);
    const cs_span_grad *sp = spans_at(model, w, c, i);
    double ax[3][3], f[3], fb[3], mu = model->vehicle.def.face_friction, fu = cm->rope.fu;
    body_axes(s, ax);
    cs_node_force(cs, i, chords_of(model, w, c), f);
    for (int e = 0; e < 3; e++)
        fb[e] = v3_dot(ax[e], f);
    double fn = v2_norm(fb[0], fb[1]), wf = CS_FRICTION_FLOOR * fu;
    double len = sp[0].l + sp[1].l + 1e-9, cstiff = cm->rope.ea / len,
           dz = cs->corner_z[k] - cs->corner_z_commit[k];
    double py, pb;
    smooth_clamp_slopes(fb[2] + cstiff * dz, mu * fn + wf, wf, &py, &pb);
    double rho[3], gp[3][3] = {{0}}, gm[3] = {0};
    for (int e = 0; e < 3; e++) {
        rho[e] = (1.0 - py) * ax[2][e];
        if (fn > 0.0) rho[e] -= pb * mu * (fb[0] * ax[0][e] + fb[1] * ax[1][e]) / fn;
        rho[e] /= fu;
    }
    force_gradient(sp, rho, gp, gm);
    length_gradient(sp, -(py + CS_STICK_EPS) * dz * -cm->rope.ea / (len * len) / fu, gp);
    add_node_gradient(model, s, w, n, row, c, i, gp, gm);
    add_entry(w, n, row, row, -(py + CS_STICK_EPS) * cstiff / fu); /* dz: the row's own unknown */
}

/* A post's two rows: Q = sum over its cables of l_c J(alpha)^T f_c, less resistance and inertia. */
static void post_rows(const cs_model *model, const cs_state *s, cs_solver *w, int n, int row, int p) {
    const double *ja = w->axes + 18 * p, *dj = ja + 6;
    double kr[4], unit = model->posts[p].moment_scale; /* as residual_row */
    cs_post_resistance_slope(model, s, p, kr);
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            add_entry(w, n, row + a, row + b, kr[2 * a + b] / unit);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        if (i < 0) continue;
        const cs_span_grad *sp = spans_at(model, w, c, i);
        double l = model->cables[c].z + model->posts[p].pivot, f[3];
        cs_node_force(cs, i, chords_of(model, w, c), f);
        for (int a = 0; a < 2; a++) {
            double rho[3] = {l * ja[a] / unit, l * ja[2 + a] / unit, l * ja[4 + a] / unit};
            double gp[3][3] = {{0}}, gm[3] = {0};
            force_gradient(sp, rho, gp, gm);
            add_node_gradient(model, s, w, n, row + a, c, i, gp, gm);
            for (int b = 0; b < 2; b++) /* the axis turning under the pull */
                add_entry(w, n, row + a, row + b,
                          l * (dj[6 * b + a] * f[0] + dj[6 * b + 2 + a] * f[1] + dj[6 * b + 4 + a] * f[2]) /
                              unit);
        }
    }
}

/* The crush row's dependence on everything but the crush: N = -sum of the corners' pulls along the
 * face's normal (the captured posts' pushes move with the crush alone). */
static void crush_row(const cs_model *model, const cs_state *s, cs_solver *w, int n, int row) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double ax[3][3], scale = v->crush_force[v->crush_point_count - 1];
    body_axes(s, ax);
    double rho[3] = {-ax[0][0] / scale, -ax[0][1] / scale, -ax[0][2] / scale};
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (!cs->engaged || cs->status != CS_CABLE_INTACT) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (!is_corner(cs->node[i])) continue;
            const cs_span_grad *sp = spans_at(model, w, c, i);
            double gp[3][3] = {{0}}, gm[3] = {0};
            force_gradient(sp, rho, gp, gm);
            add_node_gradient(model, s, w, n, row, c, i, gp, gm);
        }
    }
}

/* Set the crush and bring what it moves in line: the face's corners and the spans at them, and the
 * captured posts (scatter's work for the crush alone). */
static void move_crush(const cs_model *model, cs_state *s, const cs_solver *w, double crush) {
    s->crush = crush;
    cs_contact_place_corners(model, s, crush);
    cs_post_place_captured(model, s, crush, NULL, NULL);
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        for (int i = 1; i + 1 < cs->node_count; i++)
            if (is_corner(cs->node[i])) {
                double *ch = chords_of(model, w, c);
                cs->tension[i - 1] = cs_span_tension_chord(&model->cables[c], cs, i - 1, ch + 4 * (i - 1));
                cs->tension[i] = cs_span_tension_chord(&model->cables[c], cs, i, ch + 4 * i);
            }
    }
}

/* The Jacobian at x, r its residual, with the state at x (at_x) or put there. */
static void jacobian(const cs_model *model, cs_state *s, cs_solver *w, int n, const double *x,
                     const double *r, int at_x) {
    memset(w->band, 0, (size_t)n * (size_t)w->band_width * sizeof *w->band);
    if (!at_x) scatter(model, s, w, n, x);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (cs->status == CS_CABLE_INTACT)
            for (int i = 0; i + 1 < cs->node_count; i++)
                cs_span_tension_grad(&model->cables[c], cs, i, chords_of(model, w, c) + 4 * i,
                                     w->spans + c * model->max_nodes + i);
    }
    for (int p = 0; p < model->post_count; p++)
        if (w->tilt_index[p] >= 0)
            cs_post_axis_jacobian(s->posts[p].tilt, w->axes + 18 * p, w->axes + 18 * p + 6);
    for (int k = 0; k < n; k++) {
        const slot *u = &w->slots[k];
        if (u->kind == U_NODE) node_row(model, s, w, n, k, u->a, u->b);
        if (u->kind == U_HEIGHT) height_row(model, s, w, n, k, u->a, u->b);
        if (u->kind == U_TILT && u->b == 0) post_rows(model, s, w, n, k, u->a);
        if (u->kind == U_CRUSH) crush_row(model, s, w, n, k);
    }
    int j = w->crush_index;
    if (j < 0) return;
    /* the crush's column: the rows in its band (a post's two rows come together, from its first) */
    int lo = j - w->ku > 0 ? j - w->ku : 0, hi = j + w->kl < n - 1 ? j + w->kl : n - 1;
    if (w->slots[lo].kind == U_TILT && w->slots[lo].b == 1) lo--;
    move_crush(model, s, w, x[j] + 1e-8);
    for (int i = lo; i <= hi; i++)
        residual_row(model, s, w, i, w->rt);
    for (int i = j - w->ku; i <= hi; i++)
        if (i >= 0) BAND(w, i, j) = (w->rt[i] - r[i]) / 1e-8;
    move_crush(model, s, w, x[j]);
}

/* Largest fraction of a Newton step that keeps every span's rope at least half of what it has, turns
 * no post by more than 0.1 rad and moves the crush by at most 5 cm. */
static double max_step(const cs_model *model, const cs_state *s, const cs_solver *w, int n,
                       const double *dx) {
    double t = 1.0;
    for (int k = 0; k < n; k++) {
        const slot *u = &w->slots[k];
        if (u->kind == U_TILT && fabs(dx[k]) * t > 0.1) t = 0.1 / fabs(dx[k]);
        if ((u->kind == U_CRUSH || u->kind == U_HEIGHT) && fabs(dx[k]) * t > 0.05) t = 0.05 / fabs(dx[k]);
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

/* Whether the unknowns are those of the last factored Jacobian (same kinds, elements and band). */
static int same_unknowns(cs_solver *w, int n) {
    int same = w->lu_valid && n == w->lu_n && w->kl == w->lu_kl && w->ku == w->lu_ku;
    for (int k = 0; same && k < n; k++)
        same = same_slot(&w->slots_lu[k], &w->slots[k]);
    if (!same) {
        for (int k = 0; k < n; k++)
            w->slots_lu[k] = w->slots[k];
        w->lu_n = n, w->lu_kl = w->kl, w->lu_ku = w->ku;
    }
    return same;
}

/* ---- Broyden's updates ----
 * Between rebuilds the Jacobian B is the factored one, B0, plus rank-one updates (Broyden's "good"
 * method) that make it agree with what a step found: after a step s from residual r to r',
 * B' s = r' - r. In inverse form (Sherman-Morrison), B'^-1 = (I + u s^T) B^-1 with u = (s - v) / (s . v),
 * v = B^-1 (r' - r); the pairs (s, u) are stored and applied oldest first. Up to CS_BROYDEN_MAX of them
 * accumulate, across steps and solves while the unknowns stay the same; a rebuild, a step cut short by
 * the line search (it has most likely crossed a kink) or a full list clears them. Only a full step with
 * s . v > 0 adds one (with s . v <= 0 the residual turned against the model).
 * Measured (instructions, session 17, against one update at a time): 96 Monte Carlo runs -6%, APS1 -7%,
 * APS3 -4%, 1,000 posts -4%, 300 posts +0.1%. With the stick/slip switch rounded over 1e-4 Fu (until
 * session 17) many updates had cost 300 posts 50% more: there the steps they shaped were rejected and the
 * Jacobian rebuilt twice a step; one update at a time was kept then. */
static void apply_updates(const cs_solver *w, int n, double *v) {
    for (int j = 0; j < w->update_count; j++) {
        const double *sj = w->updates + (size_t)(2 * j) * (size_t)n, *uj = sj + n;
        double d = 0.0;
        for (int k = 0; k < n; k++)
            d += sj[k] * v[k];
        for (int k = 0; k < n; k++)
            v[k] += d * uj[k];
    }
}

/* dx = -B^-1 r. */
static void quasi_newton_solve(const cs_solver *w, int n, const double *r, double *dx) {
    for (int k = 0; k < n; k++)
        dx[k] = -r[k];
    band_solve(w, n, dx);
    apply_updates(w, n, dx);
}

/* After the step t dx (dx = -B^-1 r) that took the residual to r: update B and put the next step,
 * -B'^-1 r, into dx. B^-1 r and dx give v = B^-1 (r - r_before) without another solve. */
static void broyden_update(cs_solver *w, int n, double t, double *dx, const double *r) {
    if (t != 1.0 || w->update_count == CS_BROYDEN_MAX) {
        w->update_count = 0;
        quasi_newton_solve(w, n, r, dx);
        return;
    }
    double *sj = w->updates + (size_t)(2 * w->update_count) * (size_t)n, *uj = sj + n, sv = 0.0, sz = 0.0;
    memcpy(sj, dx, (size_t)n * sizeof *dx);
    quasi_newton_solve(w, n, r, dx); /* dx = -B^-1 r, so v = s - dx */
    for (int k = 0; k < n; k++) {
        uj[k] = sj[k] - dx[k]; /* v */
        sv += sj[k] * uj[k];
        sz -= sj[k] * dx[k];
    }
    if (!(sv > 0.0)) return;
    for (int k = 0; k < n; k++) {
        uj[k] = (sj[k] - uj[k]) / sv;
        dx[k] -= sz * uj[k]; /* -(I + u s^T) B^-1 r */
    }
    w->update_count++;
}

/* ---- predictor ----
 * The barrier moves smoothly between failures, so each unknown starts from its committed value plus
 * the increment it took over the last step (a linear extrapolation in time). Unknowns are keyed by
 * element (post, cable node by its support, face contact, crush), so the memory survives nodes being
 * inserted or removed. A re-solve inside the same step (after a failure) does not extrapolate. The
 * extrapolation is taken as it is: it was closer than the committed state in 509 of APS3's 512 solves,
 * and comparing the two cost a residual a solve (5% of the run). */
static size_t slot_key(const cs_model *model, const cs_state *s, const slot *u) {
    size_t np = (size_t)model->post_count, nc = (size_t)model->cable_count;
    if (u->kind == U_TILT) return 2 * (size_t)u->a + (size_t)u->b;
    if (u->kind == U_NODE) {
        int id = s->cables[u->a].node[u->b];
        size_t at = id >= 0 ? (size_t)id : np + (id == CS_NODE_LEFT ? 0 : 1);
        return 2 * np + (size_t)u->a * (np + 2) + at;
    }
    if (u->kind == U_HEIGHT) return 2 * np + nc * (np + 2) + 2 * (size_t)u->a + (size_t)u->b;
    return 2 * np + nc * (np + 2) + 2 * nc;
}

static void predict(const cs_model *model, cs_state *s, cs_solver *w, int n, double *x) {
    int moved = 0;
    for (int k = 0; k < n; k++) {
        size_t key = slot_key(model, s, &w->slots[k]);
        w->dx[k] = 0.0;
        if (w->last_step[key] == s->step) continue; /* a re-solve: the pose has not changed */
        if (w->last_step[key] == s->step - 1) w->dx[k] = x[k] - w->last[key], moved |= w->dx[k] != 0.0;
        w->last[key] = x[k], w->last_step[key] = s->step;
    }
    if (!moved) return;
    double t = max_step(model, s, w, n, w->dx);
    for (int k = 0; k < n; k++)
        x[k] += t * w->dx[k];
}

/* Remember the unknowns as they stand (with their slots: the order along x can change), to go back to
 * them if a later attempt ends further off. */
void cs_solver_keep(const cs_model *model, cs_state *s) {
    cs_solver *w = &s->solver;
    w->kept_n = assemble(model, s, w);
    gather(s, w, w->kept_n, w->kept);
    memcpy(w->slots_kept, w->slots, (size_t)w->kept_n * sizeof *w->slots);
}

void cs_solver_go_back(const cs_model *model, cs_state *s) {
    cs_solver *w = &s->solver;
    w->settled = 0;
    memcpy(w->slots, w->slots_kept, (size_t)w->kept_n * sizeof *w->slots);
    scatter(model, s, w, w->kept_n, w->kept);
}

/* The solve's linearisation at the state as it stands, for tests: the unknowns (their count returned,
 * -1 if more than cap or the band does not fit), their kinds (0 tilt, 1 rope at a support, 2 crush,
 * 3 contact height) and values x, the residual r and the Jacobian, dense and row-major. */
int cs_solver_linearize(const cs_model *model, cs_state *s, int cap, int *kind, double *x, double *r,
                        double *jac) {
    cs_solver *w = &s->solver;
    int n = assemble(model, s, w);
    band_shape(model, s, w, n);
    w->band_width = 2 * w->kl + w->ku + 1;
    if (n > cap || (size_t)n * (size_t)w->band_width > w->band_capacity) return -1;
    gather(s, w, n, x);
    for (int k = 0; k < n; k++)
        kind[k] = w->slots[k].kind;
    cs_solver_residual(model, s, n, x, r);
    jacobian(model, s, w, n, x, r, 1);
    w->lu_valid = 0; /* the band now holds this Jacobian, not the factors */
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            jac[i * n + j] = i >= j - w->ku && i <= j + w->kl ? BAND(w, i, j) : 0.0;
    return n;
}

/* The residual at x, for the n unknowns of the last cs_solver_linearize. */
void cs_solver_residual(const cs_model *model, cs_state *s, int n, const double *x, double *r) {
    scatter(model, s, &s->solver, n, x);
    residual(model, s, &s->solver, n, r);
}

double cs_barrier_newton(const cs_model *model, cs_state *s) {
    cs_solver *w = &s->solver;
    w->settled = 0;
    int n = assemble(model, s, w);
    if (n <= 0) return 0.0;
    band_shape(model, s, w, n);
    w->band_width = 2 * w->kl + w->ku + 1;
    if ((size_t)n * (size_t)w->band_width > w->band_capacity) return -1.0; /* caller falls back */
    double *x = w->x, *r = w->r, *dx = w->dx;
    gather(s, w, n, x);
    predict(model, s, w, n, x);
    scatter(model, s, w, n, x);
    residual(model, s, w, n, r);
    double rn = norm_inf(r, n), tol = model->scenario.solver_tolerance;
    /* Quasi-Newton: the factored Jacobian and Broyden's updates of it are kept while their step still
     * cuts the residual at least by half (within the step and across steps with the same unknowns);
     * otherwise the Jacobian is rebuilt. */
    int fresh = 0, at_x = 1, have_dx = 0; /* at_x: the state is at x (not at a rejected trial) */
    if (!same_unknowns(w, n)) w->lu_valid = 0;
    for (int it = 0; it < 40 && rn > tol; it++) {
        if (!w->lu_valid) {
            jacobian(model, s, w, n, x, r, at_x);
            if (band_factor(w, n) != 0) break;
            w->lu_valid = 1, fresh = 1, w->update_count = 0, have_dx = 0;
        }
        if (!have_dx) quasi_newton_solve(w, n, r, dx);
        have_dx = 0;
        double t = max_step(model, s, w, n, dx), merit = 0.0, trial_merit = 0.0;
        for (int k = 0; k < n; k++)
            merit += r[k] * r[k];
        int accepted = 0;
        for (int ls = 0; ls < (fresh ? 30 : 1); ls++, t *= 0.5) {
            for (int k = 0; k < n; k++)
                w->xt[k] = x[k] + t * dx[k];
            scatter(model, s, w, n, w->xt);
            residual(model, s, w, n, w->rt);
            at_x = 0;
            trial_merit = 0.0;
            for (int k = 0; k < n; k++)
                trial_merit += w->rt[k] * w->rt[k];
            if (trial_merit < (fresh ? (1.0 - 1e-4 * t) : 0.25) * merit) {
                accepted = 1;
                break;
            }
        }
        if (!accepted) {
            if (!fresh) { /* a stale Jacobian: rebuild it and try again from here */
                w->lu_valid = 0;
                continue;
            }
            break;
        }
        fresh = 0, at_x = 1;
        memcpy(x, w->xt, (size_t)n * sizeof *x);
        memcpy(r, w->rt, (size_t)n * sizeof *r);
        rn = norm_inf(r, n);
        if (rn > tol) broyden_update(w, n, t, dx, r), have_dx = 1;
    }
    if (!at_x) scatter(model, s, w, n, x);
    w->settled = 1;
    return rn > CS_NEWTON_GIVE_UP ? -1.0 : rn; /* stalled far off: Gauss-Seidel goes on from here */
}
