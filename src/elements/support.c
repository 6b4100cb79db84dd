/* SPDX-License-Identifier: MIT */
/* A support of a cable: a post it is threaded through or a corner of the vehicle's face it wraps.
 * Across a support that turns the rope by theta with friction mu the tensions on its two sides may differ
 * at most by the capstan ratio exp(mu theta) (Eq. 3); within that the rope sticks, beyond it the rope
 * slides toward the higher tension until the ratio is met. Eqs. 5-6 are the two-span case of this.
 *
 * As a row of the barrier solve, with the node's material coordinate m its unknown:
 *   r Fu = lambda - proj_[-b, b](lambda + c dm) - eps c dm,
 *   lambda = T_L - T_R, b = tanh(mu theta / 2) (T_L + T_R), dm = m - m_commit, c = EA / (l_L + l_R),
 * since T_high <= exp(mu theta) T_low is |T_L - T_R| <= tanh(mu theta / 2) (T_L + T_R). The projection
 * makes the node stick (dm = 0) inside the band and slide (lambda = +-b) outside it, as Coulomb friction;
 * its corners are rounded over CS_FRICTION_FLOOR Fu so that Newton sees a smooth switch. eps keeps a node
 * between two slack spans sticking instead of undetermined; in a slide it adds eps c dm to the friction
 * (with + it would take it off: a negative stiffness that a sagging rope's few kN/m cannot carry). */
#include "core/vec3.h"
#include "elements/rows.h"

#include <math.h>

/* The capstan exponent mu theta at interior node i, theta the turning angle of the path; the ratio R is
 * exp(mu theta). */
double cs_node_capstan_exponent(const cs_model *model, const cs_cable_model *cm, const cs_cable_state *cs,
                                int i, const double *chords) {
    double own[8];
    if (!chords) {
        v3_sub(own, cs->pos + 3 * i, cs->pos + 3 * (i - 1));
        v3_sub(own + 4, cs->pos + 3 * (i + 1), cs->pos + 3 * i);
    }
    const double *a = chords ? chords + 4 * (i - 1) : own, *b = a + 4;
    double x[3];
    v3_cross(x, a, b);
    double theta = atan2(v3_norm(x), v3_dot(a, b));
    int id = cs->node[i];
    double mu = id >= 0 ? cm->mu_post : model->vehicle.def.face_friction;
    return mu * theta;
}

/* tanh(mu theta / 2) at interior node i: the friction band's half-width over T_L + T_R, since
 * T_high <= exp(mu theta) T_low is |T_L - T_R| <= tanh(mu theta / 2) (T_L + T_R). */
double cs_node_band_fraction(const cs_model *model, const cs_cable_model *cm, const cs_cable_state *cs, int i,
                             const double *chords) {
    return tanh(0.5 * cs_node_capstan_exponent(model, cm, cs, i, chords));
}

static double support_residual(const cs_model *model, const cs_state *s, const cs_rows *rows, int c, int i) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    const double *ch = cs_rows_chords(model, rows, c);
    double tl = cs->tension[i - 1], tr = cs->tension[i];
    double lambda = tl - tr, b = cs_node_band_fraction(model, cm, cs, i, ch) * (tl + tr);
    double cstiff = cm->rope.ea / (ch[4 * (i - 1) + 3] + ch[4 * i + 3] + 1e-9); /* the spans' lengths */
    double dm = cs->m[i] - cs->m_commit[i], y = lambda + cstiff * dm;
    double proj = cs_smooth_clamp(y, b, CS_FRICTION_FLOOR * cm->rope.fu);
    return (lambda - proj - CS_STICK_EPS * cstiff * dm) * (1.0 / cm->rope.fu);
}

static void support_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row, int c,
                             int i) {
    const cs_cable_model *cm = &model->cables[c];
    const cs_cable_state *cs = &s->cables[c];
    const cs_span_grad *sp = cs_rows_spans(model, rows, c, i);
    double gp[3][3] = {{0}}, gm[3] = {0};
    int id = cs->node[i];
    double mu = id >= 0 ? cm->mu_post : model->vehicle.def.face_friction, tl = sp[0].t, tr = sp[1].t;
    double th = cs_node_band_fraction(model, cm, cs, i, cs_rows_chords(model, rows, c)), lam = tl - tr,
           b = th * (tl + tr);
    double len = sp[0].l + sp[1].l + 1e-9, cstiff = cm->rope.ea / len, dm = cs->m[i] - cs->m_commit[i];
    double py, pb, fu = cm->rope.fu;
    cs_smooth_clamp_slopes(lam + cstiff * dm, b, CS_FRICTION_FLOOR * fu, &py, &pb);
    /* r Fu = lambda - proj(y, b) - eps c dm: its slopes on T_L, T_R, theta, c and dm */
    double on_tl = (1.0 - py) - pb * th, on_tr = -(1.0 - py) - pb * th;
    double on_theta = -pb * (1.0 - th * th) * 0.5 * mu * (tl + tr), on_c = -(py + CS_STICK_EPS) * dm;
    for (int k = 0; k < 2; k++) {
        double on_t = k == 0 ? on_tl : on_tr;
        v3_addto(gp[k + 1], sp[k].dt_dd, on_t);
        v3_addto(gp[k], sp[k].dt_dd, -on_t);
        gm[k] += on_t * sp[k].dt_dm[0], gm[k + 1] += on_t * sp[k].dt_dm[1];
    }
    cs_rows_angle_gradient(sp, on_theta, gp);
    cs_rows_length_gradient(sp, on_c * -cm->rope.ea / (len * len), gp);
    gm[1] += -(py + CS_STICK_EPS) * cstiff;
    for (int k = 0; k < 3; k++) {
        v3_scale(gp[k], gp[k], 1.0 / fu);
        gm[k] /= fu;
    }
    cs_rows_add_node_gradient(model, s, rows, row, c, i, gp, gm);
}

/* A node the rope slides through: a support (here), or an end of it slipping through its fitting
 * (termination.c). */
static int at_end(const cs_state *s, const cs_slot *u) {
    return u->b == 0 || u->b == s->cables[u->a].node_count - 1;
}

static void residual(const cs_model *model, const cs_state *s, const cs_rows *rows, const cs_slot *u,
                     double *r) {
    r[0] = at_end(s, u) ? cs_termination_slip_residual(model, s, rows, u->a, u->b)
                        : support_residual(model, s, rows, u->a, u->b);
}

static void jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                     const cs_slot *u) {
    if (at_end(s, u))
        cs_termination_slip_jacobian(model, s, rows, row, u->a, u->b);
    else
        support_jacobian(model, s, rows, row, u->a, u->b);
}

const cs_row_kind cs_support_rows = {1, residual, jacobian};
