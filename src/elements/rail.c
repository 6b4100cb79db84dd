/* SPDX-License-Identifier: MIT */
/* Rails: horizontal members tying neighbouring posts at one height (the APS barriers' open trapezoidal
 * rails), where a post's failure or the truck's fold of the end posts along the barrier pulls on its
 * neighbours.
 *
 * Segment k of a rail joins posts k and k+1 at the rail's height z: the points a = base_k + (z + d_k)
 * axis(alpha_k) and b likewise. It is an axial bar of rest length L0 (the posts' spacing as built): its
 * force N = (EA / L0) (|b - a| - L0 - delta_p), N > 0 in tension, is capped at A Fy in tension and at the
 * Euler load pi^2 E I / L^2 (pinned at the posts, its weak axis; L the barrier's shortest spacing)
 * in compression, where it then holds that force as it stretches or shortens further (delta_p its
 * plastic, or buckled, change of length, radial return at each commit, the work booked as the rails'
 * plastic work). Its pull on post k, N u (u
 * the unit vector from a to b), and -N u on post k+1, enter their moment balances through each post's
 * axis Jacobian: Q = (z + d) J^T F, as a cable's pull does (post.c). A segment acts while both its posts
 * stand and neither has been struck by the face; a post's failure ends it, its stored energy released.
 * Half of each segment's steel swings with each of its posts (post.c). */
#include "core/vec3.h"
#include "elements/rows.h"

#include <math.h>
#include <string.h>

void cs_rail_derive(const cs_rail_def *d, double shortest, cs_rail_model *rm) {
    rm->z = d->height;
    rm->ea = d->modulus * d->area;
    rm->yield_force = d->area * d->yield_stress;
    double euler = shortest < HUGE_VAL
                       ? 9.869604401089358 /* pi^2 */ * d->modulus * d->inertia / (shortest * shortest)
                       : rm->yield_force;
    rm->buckling_load = fmin(euler, rm->yield_force);
}

static int segment_acts(const cs_model *model, const cs_state *s, int k) {
    if (k < 0 || k + 1 >= model->post_count) return 0;
    const cs_post_state *a = &s->posts[k], *b = &s->posts[k + 1];
    return cs_post_in_barrier(a) && cs_post_in_barrier(b) && !a->captured && !b->captured;
}

/* Segment k of rail r with its posts at tilts ta and tb: the force on post k (N u), the force N, the
 * bar's chord length l and unit u, and whether N is on its cap. */
typedef struct bar {
    double f[3], n, l, u[3];
    int capped;
} bar;

/* Post p's point on rail r at a tilt (and its pull as it stands): as placed (cs_post_place_nodes, kept in
 * the state's cache) if it is the tilt and pull placed last, else found (the same numbers: a point is a
 * function of the tilt and pull alone). */
static void rail_point(const cs_model *model, const cs_state *s, int r, int p, const double *tilt,
                       double *out) {
    double pull = s->posts[p].pull;
    if (s->rail_pos && tilt[0] == s->rail_tilt[3 * p] && tilt[1] == s->rail_tilt[3 * p + 1] &&
        pull == s->rail_tilt[3 * p + 2])
        v3_copy(out, s->rail_pos + 3 * ((size_t)p * (size_t)model->rail_count + (size_t)r));
    else
        cs_post_attachment(model, p, tilt, pull, cs_post_upright(&model->posts[p]), model->rails[r].z, out);
}

static bar bar_at(const cs_model *model, const cs_state *s, int r, int k, const double *ta,
                  const double *tb) {
    const cs_rail_model *rm = &model->rails[r];
    double pa[3], pb[3], d[3];
    rail_point(model, s, r, k, ta, pa);
    rail_point(model, s, r, k + 1, tb, pb);
    v3_sub(d, pb, pa);
    bar b;
    b.l = v3_norm(d);
    v3_scale(b.u, d, b.l > 0.0 ? 1.0 / b.l : 0.0);
    size_t at = (size_t)r * (size_t)model->post_count + (size_t)k;
    double l0 = model->posts[k + 1].x - model->posts[k].x;
    double trial = rm->ea / l0 * (b.l - l0 - s->rail_plastic[at]);
    double lo = -rm->buckling_load, hi = rm->yield_force;
    b.n = trial > hi ? hi : (trial < lo ? lo : trial);
    b.capped = trial > hi || trial < lo;
    v3_scale(b.f, b.u, b.n);
    return b;
}

void cs_rail_moment(const cs_model *model, const cs_state *s, int p, const double *tilt, const double *axis,
                    double *q) {
    for (int r = 0; r < model->rail_count; r++) {
        double lever = cs_post_arm(model, s, p, model->rails[r].z);
        for (int side = 0; side < 2; side++) {
            int k = side == 0 ? p - 1 : p; /* the segment ending at p, the one starting there */
            if (!segment_acts(model, s, k)) continue;
            bar b = side == 0 ? bar_at(model, s, r, k, s->posts[k].tilt, tilt)
                              : bar_at(model, s, r, k, tilt, s->posts[k + 1].tilt);
            double sign = side == 0 ? -1.0 : 1.0; /* the force on p: -N u at the segment's end */
            q[0] += sign * lever * (axis[0] * b.f[0] + axis[2] * b.f[1] + axis[4] * b.f[2]);
            q[1] += sign * lever * (axis[1] * b.f[0] + axis[3] * b.f[1] + axis[5] * b.f[2]);
        }
    }
}

void cs_rail_moments(const cs_model *model, const cs_state *s, const double *axes, double *rails) {
    size_t nr = (size_t)model->rail_count;
    memset(rails, 0, 4 * nr * (size_t)model->post_count * sizeof *rails);
    for (int r = 0; r < model->rail_count; r++)
        for (int k = 0; k + 1 < model->post_count; k++) {
            if (!segment_acts(model, s, k)) continue;
            bar b = bar_at(model, s, r, k, s->posts[k].tilt, s->posts[k + 1].tilt);
            for (int side = 0; side < 2; side++) { /* post k + 1 at the span's end, post k at its start */
                int p = side == 0 ? k + 1 : k;
                const double *axis = axes + 18 * p;
                double sign = side == 0 ? -1.0 : 1.0, lever = cs_post_arm(model, s, p, model->rails[r].z);
                double *m = rails + 4 * ((size_t)p * nr + (size_t)r) + 2 * (size_t)side;
                m[0] = sign * lever * (axis[0] * b.f[0] + axis[2] * b.f[1] + axis[4] * b.f[2]);
                m[1] = sign * lever * (axis[1] * b.f[0] + axis[3] * b.f[1] + axis[5] * b.f[2]);
            }
        }
}

double cs_rail_pull(const cs_model *model, const cs_state *s, int p, const double *a) {
    double pull = 0.0;
    for (int r = 0; r < model->rail_count; r++)
        for (int side = 0; side < 2; side++) {
            int k = side == 0 ? p - 1 : p;
            if (!segment_acts(model, s, k)) continue;
            bar b = bar_at(model, s, r, k, s->posts[k].tilt, s->posts[k + 1].tilt);
            pull += (side == 0 ? -1.0 : 1.0) * v3_dot(b.f, a);
        }
    return pull;
}

/* Post p's rows (from `row`, its moment unit `unit`): the rails' moment's slope on its own tilt and on
 * its neighbours'. With G = dN/dl u u^T + N (I - u u^T) / l the derivative of N u along the chord, the
 * force on p moves by -G dP_p + G dP_o (o the other post), so with P = base + l a(alpha), l = z + d + w:
 * dQ_p/dalpha_p = -l_p^2 J_p^T G J_p + l_p dJ_p^T F_p and dQ_p/dalpha_o = l_p l_o J_p^T G J_o; a post
 * sliding out adds dQ_p/dw_p = J_p^T F_p - l_p J_p^T G a_p, dQ_p/dw_o = l_p J_p^T G a_o, and its pull's row
 * a_p . F_p (in the force unit U) has the slopes J_p^T F_p - l_p J_p^T G a_p on alpha_p, l_o J_o^T G a_p on
 * alpha_o, -a_p . G a_p on w_p and a_p . G a_o on w_o (G symmetric). a_p is the direction p slides: its
 * axis, or e_z for a post sliding upright, whose arm l_p does not grow with w_p and whose e_z does not
 * turn with its tilt, so that its two J_p^T F_p terms drop. */
void cs_rail_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row, int p,
                      double unit) {
    const double *ja = rows->axes + 18 * p, *dj = ja + 6;
    int pp = rows->pull_index[p], turns = !cs_post_upright(&model->posts[p]);
    double ap[3] = {0.0, 0.0, 0.0}, force_unit = cs_rows_force_unit(model);
    if (pp >= 0) cs_post_slide_direction(model, p, s->posts[p].tilt, ap); /* read only where p slides */
    for (int r = 0; r < model->rail_count; r++) {
        const cs_rail_model *rm = &model->rails[r];
        double lp = cs_post_arm(model, s, p, rm->z);
        for (int side = 0; side < 2; side++) {
            int k = side == 0 ? p - 1 : p, o = side == 0 ? p - 1 : p + 1;
            if (!segment_acts(model, s, k)) continue;
            bar b = bar_at(model, s, r, k, s->posts[k].tilt, s->posts[k + 1].tilt);
            double sign = side == 0 ? -1.0 : 1.0, f[3] = {sign * b.f[0], sign * b.f[1], sign * b.f[2]};
            double dn = b.capped ? 0.0 : rm->ea / (model->posts[k + 1].x - model->posts[k].x), g[3][3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    g[i][j] =
                        dn * b.u[i] * b.u[j] + (b.l > 0.0 ? b.n / b.l * ((i == j) - b.u[i] * b.u[j]) : 0.0);
            double lo = cs_post_arm(model, s, o, rm->z), ao[3] = {0.0, 0.0, 0.0}, gap[3], gao[3];
            int col_o = rows->tilt_index[o], po = rows->pull_index[o];
            const double *jo = rows->axes + 18 * o; /* placed with the unknowns (only read if o is one) */
            if (po >= 0) cs_post_slide_direction(model, o, s->posts[o].tilt, ao); /* read where o slides */
            for (int i = 0; i < 3; i++) /* G a_p and G a_o: the force's change with each pull */
                gap[i] = g[i][0] * ap[0] + g[i][1] * ap[1] + g[i][2] * ap[2],
                gao[i] = g[i][0] * ao[0] + g[i][1] * ao[1] + g[i][2] * ao[2];
            for (int a = 0; a < 2; a++) {
                double gj[3]; /* G J_p e_a, the force's change with p's own tilt (less its sign) */
                for (int i = 0; i < 3; i++)
                    gj[i] = g[i][0] * ja[a] + g[i][1] * ja[2 + a] + g[i][2] * ja[4 + a];
                /* J_p^T F_p: the arm growing along a leaned slide, the direction turning with the tilt */
                double jf = turns ? ja[a] * f[0] + ja[2 + a] * f[1] + ja[4 + a] * f[2] : 0.0;
                for (int m = 0; m < 2; m++) {
                    double jtg = ja[m] * gj[0] + ja[2 + m] * gj[1] + ja[4 + m] * gj[2];
                    double turn = dj[6 * a + m] * f[0] + dj[6 * a + 2 + m] * f[1] + dj[6 * a + 4 + m] * f[2];
                    cs_rows_add(rows, row + m, row + a, (-lp * lp * jtg + lp * turn) / unit);
                }
                if (pp >= 0) { /* p sliding out: its pull's row on its tilt, its tilt's rows on its pull */
                    cs_rows_add(rows, pp, row + a, (jf - lp * v3_dot(ap, gj)) / force_unit);
                    cs_rows_add(rows, row + a, pp,
                                (jf - lp * v3_dot(gap, (double[3]){ja[a], ja[2 + a], ja[4 + a]})) / unit);
                }
                if (po >= 0)
                    cs_rows_add(rows, row + a, po,
                                lp * (ja[a] * gao[0] + ja[2 + a] * gao[1] + ja[4 + a] * gao[2]) / unit);
                if (col_o < 0) continue;
                double go[3];
                for (int i = 0; i < 3; i++)
                    go[i] = g[i][0] * jo[a] + g[i][1] * jo[2 + a] + g[i][2] * jo[4 + a];
                for (int m = 0; m < 2; m++)
                    cs_rows_add(rows, row + m, col_o + a,
                                lp * lo * (ja[m] * go[0] + ja[2 + m] * go[1] + ja[4 + m] * go[2]) / unit);
                if (pp >= 0) cs_rows_add(rows, pp, col_o + a, lo * v3_dot(ap, go) / force_unit);
            }
            if (pp < 0) continue;
            cs_rows_add(rows, pp, pp, -v3_dot(ap, gap) / force_unit);
            if (po >= 0) cs_rows_add(rows, pp, po, v3_dot(ap, gao) / force_unit);
        }
    }
}

/* End of step: each acting segment's plastic (or buckled) change of length and its work, and the elastic
 * energy the rails hold as committed, sum N^2 L0 / (2 EA) (the return leaves N as it was, so it is taken
 * from the same bar). The ledger reads that sum only on committed states (step.c), so it is kept here
 * rather than found afresh from every segment at each of its four readings a step. */
void cs_rail_commit(const cs_model *model, cs_state *s) {
    s->e_rail_elastic = 0.0;
    for (int r = 0; r < model->rail_count; r++) {
        const cs_rail_model *rm = &model->rails[r];
        for (int k = 0; k + 1 < model->post_count; k++) {
            if (!segment_acts(model, s, k)) continue;
            bar b = bar_at(model, s, r, k, s->posts[k].tilt, s->posts[k + 1].tilt);
            double l0 = model->posts[k + 1].x - model->posts[k].x;
            s->e_rail_elastic += 0.5 * b.n * b.n * l0 / rm->ea;
            if (!b.capped) continue;
            size_t at = (size_t)r * (size_t)model->post_count + (size_t)k;
            double slip = b.l - l0 - s->rail_plastic[at] - b.n * l0 / rm->ea; /* beyond the elastic part */
            s->rail_plastic[at] += slip;
            s->e_rail_plastic += fabs(b.n * slip);
        }
    }
}

int cs_rail_ties(const cs_model *model, const cs_state *s, int p, int *left, int *right) {
    *left = model->rail_count > 0 && segment_acts(model, s, p - 1) ? p - 1 : -1;
    *right = model->rail_count > 0 && segment_acts(model, s, p) ? p + 1 : -1;
    return *left >= 0 || *right >= 0;
}
