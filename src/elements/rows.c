/* SPDX-License-Identifier: MIT */
/* The row kit (rows.h): chaining a row's gradient on cable nodes to the unknowns' columns, and the
 * gradients and the rounded Coulomb clamp that several kinds of rows share. */
#include "elements/rows.h"

#include "core/vec3.h"

#include <math.h>

/* A column of the Jacobian and a 3-vector: how a node's position moves along it. */
typedef struct dep {
    int col;
    double v[3];
} dep;

/* The columns that move node j of cable c other than the crush (whose column is a difference quotient,
 * system.c): a post's two tilts (the attachment's arm times the axis' Jacobian) and its pull (the direction
 * it slides: cs_post_slide_direction), a contact's height (the body's z axis). */
static int position_columns(const cs_model *model, const cs_state *s, const cs_rows *rows, int c, int j,
                            dep *out) {
    const cs_cable_state *cs = &s->cables[c];
    int id = cs->node[j];
    if (id >= 0 && rows->tilt_index[id] >= 0) {
        const double *ja = rows->axes + 18 * id;
        double l = cs_post_arm(model, s, id, cs_post_cable_z(model, s, id, c));
        for (int k = 0; k < 2; k++)
            out[k] = (dep){rows->tilt_index[id] + k, {l * ja[k], l * ja[2 + k], l * ja[4 + k]}};
        if (rows->pull_index[id] < 0) return 2;
        out[2].col = rows->pull_index[id];
        cs_post_slide_direction(model, id, s->posts[id].tilt, out[2].v);
        return 3;
    }
    if (id == CS_NODE_START || id == CS_NODE_END) {
        int a = rows->anchor_index[id == CS_NODE_START ? 0 : 1],
            l = rows->lift_index[id == CS_NODE_START ? 0 : 1];
        if (a < 0) return 0;
        out[0] = (dep){a, {1.0, 0.0, 0.0}}, out[1] = (dep){a + 1, {0.0, 1.0, 0.0}};
        if (l < 0) return 2;
        out[2] = (dep){l, {0.0, 0.0, 1.0}};
        return 3;
    }
    if (cs_node_is_corner(id)) {
        int h = rows->height_index[CS_CORNERS * c + cs_node_corner(id)];
        if (h < 0) return 0;
        double ez[3] = {0.0, 0.0, 1.0};
        out[0].col = h;
        quat_rotate(out[0].v, s->quat, ez);
        return 1;
    }
    return 0;
}

void cs_rows_add_node_gradient(const cs_model *model, const cs_state *s, const cs_rows *rows, int row, int c,
                               int i, double gp[3][3], const double *gm) {
    for (int k = 0; k < 3; k++) {
        int j = i - 1 + k;
        if (j < 0 || j >= s->cables[c].node_count) continue;
        dep d[3];
        int count = position_columns(model, s, rows, c, j, d);
        for (int q = 0; q < count; q++)
            cs_rows_add(rows, row, d[q].col, v3_dot(gp[k], d[q].v));
        int m = rows->node_index[c * model->max_nodes + j];
        if (m >= 0) cs_rows_add(rows, row, m, gm[k]);
    }
}

/* d(T u)/dd = u dT/dd^T + T (I - u u^T) / l for each span, d_L = p_i - p_{i-1}, d_R = p_{i+1} - p_i. */
void cs_rows_force_gradient(const cs_span_grad *sp, const double *rho, double gp[3][3], double *gm) {
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

void cs_rows_end_force_gradient(const cs_span_grad *sp, int at_start, const double *rho, double gp[3][3],
                                double *gm) {
    double sign = at_start ? 1.0 : -1.0, ur = v3_dot(sp->u, rho), g[3];
    for (int e = 0; e < 3; e++)
        g[e] = sign * (sp->dt_dd[e] * ur + (sp->l > 1e-12 ? sp->t * (rho[e] - sp->u[e] * ur) / sp->l : 0.0));
    /* the span runs from its first node to its second: start (node 0 = gp[1], node 1 = gp[2]), end
     * (node n-2 = gp[0], node n-1 = gp[1]) */
    int first = at_start ? 1 : 0;
    v3_addto(gp[first + 1], g, 1.0);
    v3_addto(gp[first], g, -1.0);
    gm[first] += sign * ur * sp->dt_dm[0];
    gm[first + 1] += sign * ur * sp->dt_dm[1];
}

void cs_rows_length_gradient(const cs_span_grad *sp, double coef, double gp[3][3]) {
    for (int k = 0; k < 2; k++) {
        v3_addto(gp[k + 1], sp[k].u, coef);
        v3_addto(gp[k], sp[k].u, -coef);
    }
}

void cs_rows_angle_gradient(const cs_span_grad *sp, double coef, double gp[3][3]) {
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

/* Each corner is the ramp max(x, 0) (x in units of w) with the parabola (x + h)^2 / 4h over |x| < h,
 * h = 4 ln 2. */
#define RAMP_H 2.772588722239781
static double ramp(double x) {
    if (x <= -RAMP_H) return 0.0;
    if (x >= RAMP_H) return x;
    return (x + RAMP_H) * (x + RAMP_H) / (4.0 * RAMP_H);
}
static double ramp_slope(double x) {
    if (x <= -RAMP_H) return 0.0;
    return x >= RAMP_H ? 1.0 : (x + RAMP_H) / (2.0 * RAMP_H);
}

double cs_smooth_floor(double a, double w, double *slope) {
    double x = (a - w) / w;
    if (slope) *slope = ramp_slope(x);
    return w + w * ramp(x);
}

double cs_smooth_clamp(double y, double b, double w) {
    double iw = 1.0 / w;
    return y - w * ramp((y - b) * iw) + w * ramp((-y - b) * iw);
}

void cs_smooth_clamp_slopes(double y, double b, double w, double *dy, double *db) {
    double iw = 1.0 / w; /* as cs_smooth_clamp, so both see the same x */
    double s1 = ramp_slope((y - b) * iw), s2 = ramp_slope((-y - b) * iw);
    *dy = 1.0 - s1 - s2, *db = s1 - s2;
}
