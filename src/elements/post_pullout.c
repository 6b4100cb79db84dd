/* SPDX-License-Identifier: MIT */
/* A post sliding out of its footing. Once the ropes' and rails' pull along the direction d a post slides
 * in reaches its pullout capacity Q0 (design data, or the shaft friction q pi B D^2 / 2 that grows linearly
 * with depth: footing.c), the post slides out by w, an unknown of the barrier's solve (rows.h) that moves
 * every point of it by w d (cs_post_slide_direction, post_axis.c): d = e_z for a post hinged at grade, whose
 * stub stays upright in its footing and carries the bent post up with it, so that only the pull's vertical
 * part draws the footing out, struck or not; d = a(alpha) for a post whose footing turns in the soil with
 * it. The shaft's friction is then what the length
 * still in the ground holds: with friction growing linearly with depth and mobilised all along the
 * shaft, a post slid out by w_p keeps D - w_p in the ground and holds
 *   c(w_p) = Q0 x^2,   x = 1 - w_p / D,
 * D its embedment. The shaft resists with k (w - w_p) up to c(w_p), k = Q0 / z_m, z_m the slip that
 * mobilises shaft friction in sand (API RP 2A: 0.1 in); in compression it bears without limit. With
 * the trial n = k (w - w_p) above c(w_p) the post slides by l, n - k l = c(w_p + l): with x0 = 1 - w_p / D
 * and x = 1 - (w_p + l) / D,
 *   Q0 x^2 - k D x + (k D x0 - n) = 0,   x = 2 (k D x0 - n) / (k D + sqrt(k^2 D^2 - 4 Q0 (k D x0 - n))),
 * the root at x0 when n = c(w_p) (written so that it loses no digits: k D / Q0 is about 360 for the APS
 * posts), and the resistance is Q0 x^2; at x <= 0 the post is out and resists nothing. The plastic work,
 * Q0 D (x0^3 - x^3) / 3, is the soil's; the whole withdrawal takes Q0 D / 3. The ropes at a post slid all
 * the way out have no pull left on it, and it leaves the barrier (post_pullout) with nothing to release.
 * The post was rigid along its axis until the slide started, so the slip's elastic energy is counted
 * from there: (R^2 - Q0^2) / 2k. The post slides with its mass m (its steel and half its rail spans) by
 * backward Euler over the time h since the last commit (its swing goes by HHT-alpha, post.c):
 *   m (w - w_c - h v_c) / h^2 = F - R(w),   v = (w - w_c) / h,
 * so that where the shaft softens faster than the ropes' pull falls as the post comes out (a rope
 * running across the post's axis pulls it out with little stiffness along it) the post is thrown out
 * at the pace its mass allows instead of having no equilibrium near; m / h^2 (4e7 N/m for 10 kg at 0.5
 * ms) keeps the row monotone. What backward Euler takes from the slide, m |v - v_c|^2 / 2 and its
 * end-point rule's share of the work, is booked as post damping (docs/theory.md, "Posts with mass"). */
#include "core/vec3.h"
#include "elements/rows.h"

#include <math.h>

/* The share of the embedment still in the ground after a plastic slip w_p, x = 1 - (w_p + z_m) / D: the
 * slide starts with w_p = -z_m (the shaft at its capacity where the post stands, post_pull_start). */
static double remaining(const cs_post_model *pm, double plastic) {
    return 1.0 - (plastic + pm->pullout_cap / pm->pull_stiffness) / pm->embedment;
}

double cs_post_pull_cap(const cs_post_model *pm, const cs_post_state *ps) {
    if (!ps->withdrawing) return pm->pullout_cap;
    double x = remaining(pm, ps->pull_plastic);
    return x > 0.0 ? pm->pullout_cap * x * x : 0.0;
}

/* The lateral capacity of a post sliding out: its footing keeps x D in the ground, with the ropes x' =
 * (1 - x) D higher above grade, so Eq. 21 (footing.c) holds P(x) = S1 B (x D)^2 / (c_d x D + c_h (h +
 * x' )) against P(1) at the whole embedment: the footing's moment falls by P(x) / P(1) (about x^2), the
 * post's steel keeps Zx Fy, and the weaker of the two holds. At x = 0 the post holds nothing: it leaves
 * the barrier with no load on it (docs/theory.md, "A post pulled out of its footing"). */
double cs_post_moment_cap(const cs_post_model *pm, const cs_post_state *ps) {
    if (!ps->withdrawing) return pm->moment_cap;
    double x = remaining(pm, ps->pull_plastic);
    if (!(x > 0.0)) return 0.0;
    const cs_footing_def *f = &pm->footing;
    double d = pm->embedment, h = pm->load_height,
           whole = pm->soil_yields ? pm->moment_cap : pm->footing_moment;
    return fmin(pm->moment_cap, whole * cs_footing_remaining_share(f->coeff_depth, f->coeff_height, d, h, x));
}

/* The return map at the trial n = k (w - w_p): the resistance, the x it leaves and the slope dR/dn (1
 * elastic, 2 Q0 x / (2 Q0 x - k D) sliding, 0 out). */
static double return_map(const cs_post_model *pm, const cs_post_state *ps, double n, double *x,
                         double *slope) {
    return cs_shaft_return_map(pm->pullout_cap, pm->pull_stiffness * pm->embedment,
                               remaining(pm, ps->pull_plastic), n, x, slope);
}

static double trial_of(const cs_post_model *pm, const cs_post_state *ps) {
    return pm->pull_stiffness * (ps->pull - ps->pull_plastic);
}

/* The ropes' and rails' pull on post p along the direction it slides, the spans' chords from the solve's
 * rows if given. */
static double axial_pull(const cs_model *model, const cs_state *s, int p, const cs_rows *rows) {
    double a[3], f = 0.0;
    cs_post_slide_direction(model, p, s->posts[p].tilt, a);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        if (i <= 0) continue;
        double fc[3];
        cs_node_force(cs, i, rows ? cs_rows_chords(model, rows, c) : NULL, fc);
        f += v3_dot(fc, a);
    }
    return f + cs_rail_pull(model, s, p, a);
}

double cs_post_axial_pull(const cs_model *model, const cs_state *s, int p) {
    return axial_pull(model, s, p, NULL);
}

/* Whether post p's slide has its mass over a time h (a re-solve at a commit holds it; h infinite: at rest).
 */
static int slides(const cs_post_model *pm, double h) {
    return pm->pull_mass > 0.0 && h > 0.0 && h < HUGE_VAL;
}

/* The slide's inertial force at a pull w: m (w - w_c - h v_c) / h^2, and its slope m / h^2. */
static double inertia(const cs_post_model *pm, const cs_post_state *ps, double h, double *slope) {
    if (!slides(pm, h)) {
        if (slope) *slope = 0.0;
        return 0.0;
    }
    double k = pm->pull_mass / (h * h);
    if (slope) *slope = k;
    return k * (ps->pull - ps->pull_commit - h * ps->pull_rate);
}

/* What the pull's row takes from the ropes' and rails' pull: the shaft's resistance and the slide's
 * inertial force, N. */
static double held_and_inertia(const cs_post_model *pm, const cs_post_state *ps, double h) {
    double x, slope;
    return return_map(pm, ps, trial_of(pm, ps), &x, &slope) + inertia(pm, ps, h, NULL);
}

double cs_post_pull_balance(const cs_model *model, const cs_state *s, int p) {
    return cs_post_axial_pull(model, s, p) - held_and_inertia(&model->posts[p], &s->posts[p], s->h);
}

int cs_post_pull_start(const cs_model *model, cs_state *s, int p) {
    const cs_post_model *pm = &model->posts[p];
    cs_post_state *ps = &s->posts[p];
    if (ps->withdrawing || ps->captured || !(pm->pullout_cap < HUGE_VAL) || ps->axial < pm->pullout_cap)
        return 0;
    /* the shaft at its capacity where the post stands: k (w - w_p) = Q0 at w = pull */
    ps->withdrawing = 1;
    ps->pull_plastic = ps->pull - pm->pullout_cap / pm->pull_stiffness;
    ps->pull_commit = ps->pull, ps->pull_rate = 0.0, ps->pull_net = ps->axial - pm->pullout_cap;
    cs_event_add(model, s, CS_EVENT_POST_WITHDRAWAL, CS_ELEMENT_POST, p, ps->axial);
    return 1;
}

/* The slide's rate and net force at a commit and what backward Euler took from it, as a swing's (post.c
 * commit_swing): the kinetic energy changes by Q dw - m |v - v_c|^2 / 2 while the forces' energies
 * change by about -(Q_c + Q) dw / 2, Q = m (v - v_c) / h the net force the solve balanced. At a commit
 * with no time since the last (a failure's re-solve) the net force is evaluated; at rest the rate is 0. */
static void commit_slide(const cs_model *model, cs_state *s, int p, double resistance) {
    const cs_post_model *pm = &model->posts[p];
    cs_post_state *ps = &s->posts[p];
    if (slides(pm, s->h)) {
        double dw = ps->pull - ps->pull_commit, v = dw / s->h, q = pm->pull_mass * (v - ps->pull_rate) / s->h;
        double kinetic = 0.5 * pm->pull_mass * (v * v - ps->pull_rate * ps->pull_rate);
        s->e_post_damping += 0.5 * (ps->pull_net + q) * dw - kinetic;
        ps->pull_rate = v, ps->pull_net = q;
    } else {
        if (s->h > 0.0) ps->pull_rate = 0.0;
        ps->pull_net = cs_post_axial_pull(model, s, p) - resistance;
    }
    ps->pull_commit = ps->pull;
}

void cs_post_pull_commit(const cs_model *model, cs_state *s, int p) {
    const cs_post_model *pm = &model->posts[p];
    cs_post_state *ps = &s->posts[p];
    if (!ps->withdrawing) return;
    double x0 = remaining(pm, ps->pull_plastic), x, slope;
    double r = return_map(pm, ps, trial_of(pm, ps), &x, &slope);
    commit_slide(model, s, p, r);
    if (x >= x0) return; /* elastic */
    s->e_soil += pm->pullout_cap * pm->embedment * (x0 * x0 * x0 - x * x * x) / 3.0;
    /* on the cap: k (w - w_p) = R; out: w_p where x = 0 */
    ps->pull_plastic =
        x > 0.0 ? ps->pull - r / pm->pull_stiffness : pm->embedment - pm->pullout_cap / pm->pull_stiffness;
}

double cs_post_pull_energy(const cs_model *model, const cs_state *s, int p) {
    const cs_post_model *pm = &model->posts[p];
    const cs_post_state *ps = &s->posts[p];
    if (!ps->withdrawing || ps->captured) return 0.0; /* a struck post's slide is all plastic */
    double x, slope, r = return_map(pm, ps, trial_of(pm, ps), &x, &slope);
    return 0.5 * (r * r - pm->pullout_cap * pm->pullout_cap) / pm->pull_stiffness;
}

double cs_post_pull_kinetic_energy(const cs_model *model, const cs_state *s, int p) {
    const cs_post_state *ps = &s->posts[p];
    return ps->withdrawing && !ps->captured ? 0.5 * model->posts[p].pull_mass * ps->pull_rate * ps->pull_rate
                                            : 0.0;
}

/* ---- a struck post dragged out of its footing ----
 * The edge that pushes a struck post over (post.c) pushes horizontally, so it pulls a post whose footing
 * turns with it along its axis by push sin(theta) (the upright stub of a post hinged at grade it does not
 * draw out). Once that reaches the shaft's capacity Q0 the post slides out with the edge,
 * rigid-plastic: its slide w is all plastic (x = 1 - w / D), the shaft holds Q0 x^2 and the footing's
 * moment falls by P(x) / P(1) (cs_post_moment_cap), and the edge's motion, not the shaft's slip or the
 * post's mass, sets how far it has come (post.c, struck_slide). Its work Q0 D (x0^3 - x^3) / 3 is the
 * soil's; out at x = 0 it holds nothing and fails by pullout. */

void cs_post_struck_slide_set(const cs_post_model *pm, cs_post_state *ps, double w) {
    ps->pull = w;
    ps->pull_plastic = w - pm->pullout_cap / pm->pull_stiffness;
}

double cs_post_struck_slide_cap(const cs_post_model *pm, double w) {
    double x = 1.0 - w / pm->embedment;
    return x > 0.0 ? pm->pullout_cap * x * x : 0.0;
}

void cs_post_struck_slide_start(const cs_model *model, cs_state *s, int p) {
    cs_post_state *ps = &s->posts[p];
    ps->withdrawing = 1;
    cs_post_struck_slide_set(&model->posts[p], ps, ps->pull);
    ps->pull_commit = ps->pull, ps->pull_rate = 0.0, ps->pull_net = 0.0;
    cs_event_add(model, s, CS_EVENT_POST_WITHDRAWAL, CS_ELEMENT_POST, p, ps->axial);
}

/* A post already sliding under its ropes when struck: from here the edge drags it, so the shaft's slip
 * and the slide's motion, which the rigid-plastic slide does not hold, go to post damping (what the
 * strike takes from them: -50 J to 0.45 kJ a post in the roadside examples, theory.md). Call before it is
 * captured. */
void cs_post_struck_slide_take(const cs_model *model, cs_state *s, int p) {
    cs_post_state *ps = &s->posts[p];
    if (!ps->withdrawing) return;
    s->e_post_damping += cs_post_pull_energy(model, s, p) + cs_post_pull_kinetic_energy(model, s, p);
    cs_post_struck_slide_set(&model->posts[p], ps, ps->pull);
    ps->pull_commit = ps->pull, ps->pull_rate = 0.0, ps->pull_net = 0.0;
}

void cs_post_struck_slide_commit(const cs_model *model, cs_state *s, int p) {
    const cs_post_model *pm = &model->posts[p];
    cs_post_state *ps = &s->posts[p];
    if (!ps->withdrawing) return;
    double d = pm->embedment, x0 = fmax(0.0, 1.0 - ps->pull_commit / d), x = fmax(0.0, 1.0 - ps->pull / d);
    s->e_soil += pm->pullout_cap * d * (x0 * x0 * x0 - x * x * x) / 3.0;
    ps->pull_commit = ps->pull;
}

/* ---- the pull's row of the barrier solve ----
 * Unknown: the pull w. Row: (d . sum f_c + the rails' pull along d - R(w) - the slide's inertial force) /
 * U, U the rows' force unit; its slopes: on the nodes' positions and materials (through the spans), on the
 * tilt (the axis turning under the pull, J^T f, where d = a(alpha)) and on w (the nodes carried along d,
 * and -dR/dw - m / h^2). */
static void residual(const cs_model *model, const cs_state *s, const cs_rows *rows, const cs_slot *u,
                     double *r) {
    int p = u->a;
    r[0] = (axial_pull(model, s, p, rows) - held_and_inertia(&model->posts[p], &s->posts[p], s->h)) /
           cs_rows_force_unit(model);
}

static void jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                     const cs_slot *u) {
    int p = u->a, tc = rows->tilt_index[p];
    const cs_post_model *pm = &model->posts[p];
    const cs_post_state *ps = &s->posts[p];
    const double *ja = rows->axes + 18 * p;
    double unit = cs_rows_force_unit(model), a[3], x, slope, mass;
    int turns = !cs_post_upright(&model->posts[p]); /* its direction turns with the tilt */
    cs_post_slide_direction(model, p, ps->tilt, a);
    return_map(pm, ps, trial_of(pm, ps), &x, &slope);
    inertia(pm, ps, s->h, &mass);
    cs_rows_add(rows, row, row, -(pm->pull_stiffness * slope + mass) / unit);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        if (i < 0) continue;
        const cs_span_grad *sp = cs_rows_spans(model, rows, c, i);
        double f[3], rho[3] = {a[0] / unit, a[1] / unit, a[2] / unit}, gp[3][3] = {{0}}, gm[3] = {0};
        cs_node_force(cs, i, cs_rows_chords(model, rows, c), f);
        cs_rows_force_gradient(sp, rho, gp, gm);
        cs_rows_add_node_gradient(model, s, rows, row, c, i, gp, gm);
        for (int b = 0; b < 2 && turns; b++) /* the axis turning under the pull */
            cs_rows_add(rows, row, tc + b, (ja[b] * f[0] + ja[2 + b] * f[1] + ja[4 + b] * f[2]) / unit);
    }
}

const cs_row_kind cs_pull_rows = {1, residual, jacobian};
