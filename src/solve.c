/* The barrier's quasi-static equilibrium as one nonlinear system, solved by semi-smooth Newton.
 *
 * Unknowns: the tilt (2) of every standing post on a cable path, the material coordinate m of every
 * support node the rope can slide through (posts that do not clamp, face corners), and the crush.
 * Residuals (each scaled by its element's capacity):
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
 *           would, and any dz with eps c |dz| below the tolerance, up to ~0.4 m at 1e-4, would pass).
 *   crush:  N(crush) - C(crush)                                             (barrier.c)
 * The clamp's corners are rounded over w = CS_FRICTION_FLOOR Fu (softplus) so that Newton sees a smooth
 * switch between sticking and sliding (docs/assumptions.md).
 * Unknowns are ordered along the barrier, so the Jacobian is banded: finite differences perturb
 * columns 2w + 1 apart together, and a banded LU with partial pivoting solves each Newton step. Cost
 * is linear in the number of posts; the solution does not depend on any sweep order, so a symmetric
 * impact stays symmetric. */
#include "internal.h"
#include "vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CS_STICK_EPS 1e-4
#define CS_NEWTON_GIVE_UP 1e-2 /* residual above which the step goes to Gauss-Seidel instead */

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
    w->tilt_index = calloc(np ? np : 1, sizeof *w->tilt_index);
    w->node_index = calloc(nc ? nc * nn : 1, sizeof *w->node_index);
    w->height_index = calloc(nc ? 2 * nc : 1, sizeof *w->height_index);
    w->x = calloc(6 * n, sizeof *w->x);
    w->band_capacity = n * per_row;
    w->band = calloc(w->band_capacity, sizeof *w->band);
    w->pivot = calloc(n, sizeof *w->pivot);
    w->rows = calloc(n, sizeof *w->rows);
    w->row_column = calloc(n, sizeof *w->row_column);
    w->key_count = 2 * np + nc * (np + 2) + 2 * nc + 1; /* see slot_key */
    w->last = calloc(w->key_count, sizeof *w->last);
    w->last_step = calloc(w->key_count, sizeof *w->last_step);
    if (!w->slots || !w->slots_lu || !w->slots_kept || !w->last || !w->last_step || !w->tilt_index ||
        !w->node_index || !w->height_index || !w->x || !w->band || !w->pivot || !w->rows || !w->row_column)
        return -1;
    w->r = w->x + n, w->dx = w->x + 2 * n, w->xt = w->x + 3 * n, w->rt = w->x + 4 * n, w->kept = w->x + 5 * n;
    return 0;
}

/* Forget the history of the predictor (a new run). */
void cs_solver_reset(cs_solver *w) {
    for (size_t k = 0; k < w->key_count; k++)
        w->last_step[k] = -2, w->last[k] = 0.0;
    w->lu_valid = 0;
}

void cs_solver_free(cs_solver *w) {
    free(w->slots), free(w->slots_lu), free(w->slots_kept), free(w->tilt_index), free(w->node_index),
        free(w->height_index), free(w->x), free(w->band), free(w->pivot), free(w->last), free(w->last_step),
        free(w->rows), free(w->row_column);
    memset(w, 0, sizeof *w);
}

static int cmp_slot(const void *pa, const void *pb) {
    const slot *a = pa, *b = pb;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->kind != b->kind) return a->kind - b->kind;
    if (a->a != b->a) return a->a - b->a;
    return a->b - b->b;
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
    qsort(sl, (size_t)n, sizeof *sl, cmp_slot);
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

/* Put x into the state and bring every node position and span tension in line with it. */
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
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        for (int i = 1; i + 1 < cs->node_count; i++)
            if (cs->node[i] >= 0)
                cs_post_attachment(model, cs->node[i], s->posts[cs->node[i]].tilt, model->cables[c].z,
                                   cs->pos + 3 * i);
        cs_cable_update_tensions(&model->cables[c], cs);
    }
}

/* ---- residuals ---- */
/* clamp(y, -b, b) with its corners rounded over a width w (softplus), so Newton sees a smooth switch
 * between sticking and sliding; it departs from the exact clamp by at most w ln 2. */
static double softplus(double x) {
    if (x < -40.0) return 0.0; /* below exp(-40) = 4e-18 of the width: round-off beside y */
    return x > 30.0 ? x : log1p(exp(x));
}
static double smooth_clamp(double y, double b, double w) {
    return y - w * softplus((y - b) / w) + w * softplus((-y - b) / w);
}

static double node_residual(const cs_model *model, const cs_state *s, int c, int i) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    double tl = cs->tension[i - 1], tr = cs->tension[i];
    double mu_theta = cs_node_capstan_exponent(model, cm, cs, i);
    double lambda = tl - tr, b = tanh(0.5 * mu_theta) * (tl + tr);
    double cstiff = cm->rope.ea / (cs_span_length(cs, i - 1) + cs_span_length(cs, i) + 1e-9);
    double dm = cs->m[i] - cs->m_commit[i], y = lambda + cstiff * dm;
    double proj = smooth_clamp(y, b, CS_FRICTION_FLOOR * cm->rope.fu);
    return (lambda - proj - CS_STICK_EPS * cstiff * dm) / cm->rope.fu;
}

/* The contact of corner k on the face: Coulomb friction along the vertical face, as for a support
 * (lambda = the spans' pull up the face, b = mu times their pull into it, dz from the last step). */
static double height_residual(const cs_model *model, const cs_state *s, int c, int k) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    int i = corner_node(cs, k);
    double fz, fn;
    cs_contact_face_force(model, s, c, i, &fz, &fn);
    double b = model->vehicle.def.face_friction * fn;
    double cstiff = cm->rope.ea / (cs_span_length(cs, i - 1) + cs_span_length(cs, i) + 1e-9);
    double dz = cs->corner_z[k] - cs->corner_z_commit[k];
    double w = CS_FRICTION_FLOOR * cm->rope.fu, proj = smooth_clamp(fz + cstiff * dz, b + w, w);
    return (fz - proj - CS_STICK_EPS * cstiff * dz) / cm->rope.fu;
}

/* Residual row k; a post's two rows come together, from its first. */
static void residual_row(const cs_model *model, cs_state *s, const cs_solver *w, int k, double *r) {
    const slot *u = &w->slots[k];
    if (u->kind == U_HEIGHT) {
        r[k] = height_residual(model, s, u->a, u->b);
    } else if (u->kind == U_NODE) {
        r[k] = node_residual(model, s, u->a, u->b);
    } else if (u->kind == U_TILT && u->b == 0) {
        double q[2];
        cs_post_residual_now(model, s, u->a, q);
        double scale = model->posts[u->a].moment_cap;
        r[k] = q[0] / scale, r[k + 1] = q[1] / scale;
    } else if (u->kind == U_CRUSH) {
        const cs_vehicle_def *v = &model->vehicle.def;
        double nf = cs_face_normal_force_now(model, s);
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
        m = fmax(m, fabs(r[k]));
    return m;
}

/* Finite-difference step of unknown u: 1e-8 for a tilt (rad) or the crush (m); for a node or a contact
 * height, a thousandth of the length over which its stick/slip switch is rounded (the friction floor
 * over the rope's stiffness there, w / c), so that the quotient takes the switch's slope instead of
 * straddling it. Until session 10 it was 1e-8 of m: 7 um at 700 m along a 300-post barrier, wider than
 * the switch, and Newton stalled there with a Jacobian averaged across it (docs/performance.md). */
static double fd_step(const cs_model *model, const cs_state *s, const slot *u) {
    if (u->kind != U_NODE && u->kind != U_HEIGHT) return 1e-8;
    const cs_cable_state *cs = &s->cables[u->a];
    const cs_rope *r = &model->cables[u->a].rope;
    int i = u->kind == U_NODE ? u->b : corner_node(cs, u->b);
    double l = cs_span_length(cs, i - 1) + cs_span_length(cs, i) + 1e-9;
    return 1e-3 * CS_FRICTION_FLOOR * r->fu * l / r->ea;
}

/* ---- banded LU with partial pivoting: row i keeps columns i-kl .. i+ku+kl ---- */
#define BAND(w, i, j) ((w)->band[(size_t)(i) * (size_t)(w)->band_width + (size_t)((j) - (i) + (w)->kl)])

static int band_factor(cs_solver *w, int n) {
    int kl = w->kl, ku = w->ku;
    for (int k = 0; k < n; k++) {
        int last = k + kl < n - 1 ? k + kl : n - 1, p = k;
        double best = fabs(BAND(w, k, k));
        for (int i = k + 1; i <= last; i++)
            if (fabs(BAND(w, i, k)) > best) best = fabs(BAND(w, i, k)), p = i;
        w->pivot[k] = p;
        if (best == 0.0) return -1;
        int jend = k + ku + kl < n - 1 ? k + ku + kl : n - 1;
        if (p != k)
            for (int j = k; j <= jend; j++) {
                double t = BAND(w, k, j);
                BAND(w, k, j) = BAND(w, p, j);
                BAND(w, p, j) = t;
            }
        for (int i = k + 1; i <= last; i++) {
            double f = BAND(w, i, k) / BAND(w, k, k);
            BAND(w, i, k) = f;
            if (f != 0.0)
                for (int j = k + 1; j <= jend; j++)
                    BAND(w, i, j) -= f * BAND(w, k, j);
        }
    }
    return 0;
}

static void band_solve(const cs_solver *w, int n, double *b) {
    int kl = w->kl, ku = w->ku;
    for (int k = 0; k < n; k++) {
        int p = w->pivot[k];
        if (p != k) {
            double t = b[k];
            b[k] = b[p];
            b[p] = t;
        }
        int last = k + kl < n - 1 ? k + kl : n - 1;
        for (int i = k + 1; i <= last; i++)
            b[i] -= BAND(w, i, k) * b[k];
    }
    for (int k = n - 1; k >= 0; k--) {
        int jend = k + ku + kl < n - 1 ? k + ku + kl : n - 1;
        double sum = b[k];
        for (int j = k + 1; j <= jend; j++)
            sum -= BAND(w, k, j) * b[j];
        b[k] = sum / BAND(w, k, k);
    }
}

/* ---- finite-difference Jacobian ----
 * Columns kl + ku + 1 apart share no row, so they are perturbed together. A column moves few nodes:
 * a post's tilt its cables' nodes at the post, a node's material the spans either side of it, a
 * contact height its corner; only the rows that see those nodes change (the nodes next to them, the
 * posts and contacts there, the crush through a face corner). A group is found from those rows alone,
 * with the state as scatter would leave it: the same numbers as a full residual, from a fraction of
 * its rows and spans. The crush moves every corner and captured post: its group takes the full
 * residual. */

/* Set unknown j to v and bring the node positions and span tensions it moves in line; lists the
 * nodes it moves in nodes (cable, index) and returns how many. */
static int move_unknown(const cs_model *model, cs_state *s, const cs_solver *w, int j, double v, int *nodes) {
    const slot *u = &w->slots[j];
    int count = 0;
    if (u->kind == U_TILT) {
        s->posts[u->a].tilt[u->b] = v;
        for (int c = 0; c < model->cable_count; c++) {
            cs_cable_state *cs = &s->cables[c];
            if (cs->status != CS_CABLE_INTACT || cs->where[u->a] <= 0) continue;
            int i = cs->where[u->a];
            cs_post_attachment(model, u->a, s->posts[u->a].tilt, model->cables[c].z, cs->pos + 3 * i);
            nodes[2 * count] = c, nodes[2 * count + 1] = i, count++;
        }
    } else if (u->kind == U_NODE) {
        s->cables[u->a].m[u->b] = v;
        nodes[0] = u->a, nodes[1] = u->b, count = 1;
    } else if (u->kind == U_HEIGHT) {
        s->cables[u->a].corner_z[u->b] = v;
        cs_contact_place_corners(model, s, s->crush);
        nodes[0] = u->a, nodes[1] = corner_node(&s->cables[u->a], u->b), count = 1;
    }
    for (int k = 0; k < count; k++) {
        const cs_cable_model *cm = &model->cables[nodes[2 * k]];
        cs_cable_state *cs = &s->cables[nodes[2 * k]];
        int i = nodes[2 * k + 1];
        cs->tension[i - 1] = cs_span_tension(cm, cs, i - 1);
        cs->tension[i] = cs_span_tension(cm, cs, i);
    }
    return count;
}

/* Add to w->rows (count so far in *count) the rows that see node i of cable c, owned by column j; a
 * row already listed for this group (a column j' with j' = j mod stride) is not listed again. */
static void rows_near(const cs_model *model, const cs_state *s, cs_solver *w, int c, int i, int j, int stride,
                      int *count) {
    const cs_cable_state *cs = &s->cables[c];
    for (int q = i - 1; q <= i + 1; q++) {
        if (q < 1 || q + 1 >= cs->node_count) continue;
        int id = cs->node[q], row[4] = {w->node_index[c * model->max_nodes + q], -1, -1, -1};
        if (id >= 0) row[1] = w->tilt_index[id];
        if (is_corner(id))
            row[2] = w->height_index[2 * c + (id == CS_NODE_LEFT ? 0 : 1)], row[3] = w->crush_index;
        for (int k = 0; k < 4; k++) {
            int owner = row[k] >= 0 ? w->row_column[row[k]] : -1;
            if (row[k] >= 0 && (owner < 0 || owner % stride != j % stride))
                w->row_column[row[k]] = j, w->rows[(*count)++] = row[k];
        }
    }
}

/* Column j's entry in row i, if i lies in its band. */
static void put_entry(cs_solver *w, int n, int i, int j, double value) {
    if (i >= 0 && i < n && i >= j - w->ku && i <= j + w->kl) BAND(w, i, j) = value;
}

/* The FD Jacobian at x, r its residual. Each group's steps (fd_step) are sized from the state the group
 * before left, the first group's from the state on entry, as when every group took the full residual:
 * the numbers stay those. */
static void jacobian(const cs_model *model, cs_state *s, cs_solver *w, int n, const double *x,
                     const double *r) {
    int kl = w->kl, ku = w->ku, stride = kl + ku + 1, nodes[2 * CS_MAX_CABLES_PER_POST];
    memset(w->band, 0, (size_t)n * (size_t)w->band_width * sizeof *w->band);
    for (int k = 0; k < n; k++)
        w->row_column[k] = -1;
    memcpy(w->xt, x, (size_t)n * sizeof *x);
    for (int j = 0; j < n; j += stride) /* the first group's steps, from the state on entry */
        w->xt[j] += fd_step(model, s, &w->slots[j]);
    scatter(model, s, w, n, x);
    for (int g = 0; g < stride && g < n; g++) {
        int full = w->crush_index >= 0 && w->crush_index % stride == g, count = 0;
        if (full) {
            scatter(model, s, w, n, w->xt);
            residual(model, s, w, n, w->rt);
            for (int j = g; j < n; j += stride)
                for (int i = j - ku; i <= j + kl; i++)
                    put_entry(w, n, i, j, (w->rt[i] - r[i]) / (w->xt[j] - x[j]));
        } else {
            for (int j = g; j < n; j += stride) {
                int moved = move_unknown(model, s, w, j, w->xt[j], nodes);
                for (int k = 0; k < moved; k++)
                    rows_near(model, s, w, nodes[2 * k], nodes[2 * k + 1], j, stride, &count);
            }
            for (int k = 0; k < count; k++) { /* a post is listed by its first row and has two */
                int i = w->rows[k], j = w->row_column[i], last = w->slots[i].kind == U_TILT ? i + 1 : i;
                residual_row(model, s, w, i, w->rt);
                for (int q = i; q <= last; q++)
                    put_entry(w, n, q, j, (w->rt[q] - r[q]) / (w->xt[j] - x[j]));
            }
        }
        /* the next group's steps, from this group's state (as a full scatter of it would leave it) */
        for (int j = g + 1; j < n && g + 1 < stride; j += stride)
            w->xt[j] = x[j] + fd_step(model, s, &w->slots[j]);
        if (g + 1 == stride || g + 1 == n) break; /* the last group's state stays, as scatter leaves it */
        if (full) {
            scatter(model, s, w, n, x);
        } else {
            for (int j = g; j < n; j += stride)
                move_unknown(model, s, w, j, x[j], nodes);
        }
        for (int j = g; j < n; j += stride)
            w->xt[j] = x[j];
    }
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
        same = w->slots_lu[k].kind == w->slots[k].kind && w->slots_lu[k].a == w->slots[k].a &&
               w->slots_lu[k].b == w->slots[k].b;
    if (!same) {
        for (int k = 0; k < n; k++)
            w->slots_lu[k] = w->slots[k];
        w->lu_n = n, w->lu_kl = w->kl, w->lu_ku = w->ku;
    }
    return same;
}

/* ---- predictor ----
 * The barrier moves smoothly between failures, so each unknown starts from its committed value plus
 * the increment it took over the last step (a linear extrapolation in time). Unknowns are keyed by
 * element (post, cable node by its support, face contact, crush), so the memory survives nodes being
 * inserted or removed. A re-solve inside the same step (after a failure) does not extrapolate. */
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

/* Returns 1 if x was moved (a first solve of this step with a history to extrapolate). */
static int predict(const cs_model *model, cs_state *s, cs_solver *w, int n, double *x) {
    int moved = 0;
    for (int k = 0; k < n; k++) {
        size_t key = slot_key(model, s, &w->slots[k]);
        w->dx[k] = 0.0;
        if (w->last_step[key] == s->step) continue; /* a re-solve: the pose has not changed */
        if (w->last_step[key] == s->step - 1) w->dx[k] = x[k] - w->last[key], moved |= w->dx[k] != 0.0;
        w->last[key] = x[k], w->last_step[key] = s->step;
    }
    if (!moved) return 0;
    double t = max_step(model, s, w, n, w->dx);
    for (int k = 0; k < n; k++)
        x[k] += t * w->dx[k];
    return 1;
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
    memcpy(w->slots, w->slots_kept, (size_t)w->kept_n * sizeof *w->slots);
    scatter(model, s, w, w->kept_n, w->kept);
}

double cs_barrier_newton(const cs_model *model, cs_state *s) {
    cs_solver *w = &s->solver;
    int n = assemble(model, s, w);
    if (n <= 0) return 0.0;
    bandwidth(model, s, w, n, &w->kl, &w->ku);
    w->band_width = 2 * w->kl + w->ku + 1;
    if ((size_t)n * (size_t)w->band_width > w->band_capacity) return -1.0; /* caller falls back */
    double *x = w->x, *r = w->r, *dx = w->dx;
    gather(s, w, n, x);
    scatter(model, s, w, n, x);
    residual(model, s, w, n, r);
    double rn = norm_inf(r, n), tol = model->scenario.solver_tolerance;
    memcpy(w->xt, x, (size_t)n * sizeof *x);
    if (predict(model, s, w, n, w->xt) && rn > tol) { /* keep the extrapolation if it is closer */
        scatter(model, s, w, n, w->xt);
        residual(model, s, w, n, w->rt);
        double rp = norm_inf(w->rt, n);
        if (rp < rn) {
            memcpy(x, w->xt, (size_t)n * sizeof *x);
            memcpy(r, w->rt, (size_t)n * sizeof *r);
            rn = rp;
        } else {
            scatter(model, s, w, n, x);
        }
    }
    /* Chord Newton: the factored Jacobian is kept while it still cuts the residual at least by half
     * (within the step and across steps with the same unknowns); otherwise it is rebuilt. */
    int fresh = 0;
    if (!same_unknowns(w, n)) w->lu_valid = 0;
    for (int it = 0; it < 40 && rn > tol; it++) {
        if (!w->lu_valid) {
            jacobian(model, s, w, n, x, r);
            if (band_factor(w, n) != 0) break;
            w->lu_valid = 1, fresh = 1;
        }
        for (int k = 0; k < n; k++)
            dx[k] = -r[k];
        band_solve(w, n, dx);
        double t = max_step(model, s, w, n, dx), merit = 0.0, trial_merit = 0.0;
        for (int k = 0; k < n; k++)
            merit += r[k] * r[k];
        int accepted = 0;
        for (int ls = 0; ls < (fresh ? 30 : 1); ls++, t *= 0.5) {
            for (int k = 0; k < n; k++)
                w->xt[k] = x[k] + t * dx[k];
            scatter(model, s, w, n, w->xt);
            residual(model, s, w, n, w->rt);
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
        fresh = 0;
        memcpy(x, w->xt, (size_t)n * sizeof *x);
        memcpy(r, w->rt, (size_t)n * sizeof *r);
        rn = norm_inf(r, n);
    }
    if (rn > CS_NEWTON_GIVE_UP) { /* stalled far from a solution: Gauss-Seidel goes on from here */
        scatter(model, s, w, n, x);
        return -1.0;
    }
    scatter(model, s, w, n, x);
    return rn;
}
