/* SPDX-License-Identifier: MIT */
/* Anchors: the footings (dead-men) the ropes' ends are tied to, as bodies in the soil.
 *
 * An anchor moves horizontally by u (2 components); each rope's end rides on it at (x + u_x, u_y, z), so
 * ropes that share an anchor keep their own ends. The soil resists with k (u - u_p) up to the footing's
 * peak P (Eq. 21 at the height the ropes pull it, H = z, times the soil's dynamic factor for the
 * footing's width: footing.c); k reaches P over 2% of the footing's depth, the movement that mobilises a
 * medium-dense sand's passive resistance (Clough and Duncan 1991: 1% dense, 4% loose). Past the peak it
 * ploughs on through the soil (radial return), its resistance falling linearly with the plastic slide s
 * from P to the residual P_r = rho P over s_r = 5% of the depth, then held at P_r: a dense soil's shear
 * zone dilates to its critical state past the peak (passive tests: Wilson and Elgamal 2010), and rho is
 * the critical-state passive resistance over the peak's (footing.c). The plastic work, the integral of
 * the resistance over the slide, is booked as soil. With the trial force n = |k (u - u_p)| above the cap
 * c(s), the slide l solves n - k l = c(s + l): on the softening branch (slope H = (P - P_r) / s_r < k)
 * l = (n - c(s)) / (k - H), past it l = (n - P_r) / k.
 * The footing and the soil's passive wedge moving with it have mass M (its own and the wedge's:
 * footing.c). Moving at v it also sweeps the soil in front of its face, rho b D per metre of travel, which
 * must take on its speed: the momentum flux drags it back with c |v| v, c = rho b D (the inertial drag of
 * a body driven through a granular soil; docs/theory.md), booked as soil; backing off the soil it has
 * ploughed, into its own trench, it sweeps none, and only its sides hold it (trial_force). It is integrated
 * over the time h since the last commit by the HHT-alpha method (Hilber, Hughes and Taylor 1977): with
 * F = F_ropes - R(u) - c |v(u)| v(u) the net force,
 *   M a = (1 + alpha) F(u) - alpha F_c,
 *   u = u_c + h v_c + h^2 ((1/2 - beta) a_c + beta a),   v = v_c + h ((1 - gamma) a_c + gamma a),
 * beta = (1 - alpha)^2 / 4, gamma = 1/2 - alpha, so that its residual
 *   r = F(u) - (M a(u) + alpha F_c) / (1 + alpha)
 * is second order in h. At alpha = 0 it is the trapezoidal rule, which takes no energy from a linear
 * motion; alpha = -0.1 keeps that for the dead-man's own modes, which are slow (its mass on the soil and
 * the ropes' end spans: omega h <= 0.11 at 0.5 ms for the APS anchors, 3e-6 of their energy a step),
 * and damps modes the step does not resolve (1.2% a step at omega h = 1, 14% at 3: a light dead-man on
 * short stiff spans, rung by a failure). Backward Euler would take omega^2 h^2 / (1 + omega^2 h^2) of
 * every mode's energy each step (1.2% for APS3's). The posts swing by the same method (post.c;
 * docs/theory.md). The inertial M / (beta h^2 (1 + alpha)) keeps
 * the residual monotone where the resistance is flat or softens.
 * Once the ropes' uplift reaches its pullout capacity W + S (its weight plus the skin friction of its
 * whole depth D, unless given) it rises out of the soil by w, an unknown of the solve, as a post slides
 * out of its footing (post_pullout.c): with x of D still in the ground the skin holds S x^2 (friction
 * growing linearly with depth) and the face Eq. 21's share of its peak, residual and swept soil
 * (footing.c, cs_footing_remaining_share). Out of the ground (x = 0) it holds nothing, and every rope
 * tied to it is released. A rigid anchor (no footing) never moves. The anchor's rows of the barrier
 * solve are given here (rows.h). */
#include "core/vec3.h"
#include "elements/rows.h"

#include <math.h>

#define CS_ANCHOR_SOFTENING_STRAIN 0.05 /* plastic slide from the peak to the residual, over the depth */

/* The kinetic energy of its slide at the rate of the last commit. */
static double kinetic_energy(const cs_anchor_model *am, const cs_anchor_state *as) {
    return 0.5 * am->moving_mass * (as->rate[0] * as->rate[0] + as->rate[1] * as->rate[1]);
}

/* The share of its depth still in the ground, x = 1 - w / D. */
static double embedded(const cs_anchor_model *am, const cs_anchor_state *as) {
    return as->lift_commit > 0.0 ? fmax(0.0, 1.0 - as->lift_commit / am->depth) : 1.0;
}

/* What its face holds as it rises, over what it held in place: Eq. 21 with x D in the ground, x at the
 * last commit (the face's share moves at the commits, so the horizontal rows keep their slopes). */
double cs_anchor_face_share(const cs_anchor_model *am, const cs_anchor_state *as) {
    if (!(as->lift_commit > 0.0)) return 1.0;
    double x = embedded(am, as);
    return x > 0.0 ? cs_footing_remaining_share(am->coeff_depth, am->coeff_height, am->depth, am->z, x) : 0.0;
}

/* The acceleration the step from the last commit to u over h gives (the HHT-alpha update). */
static double acceleration_to(const cs_anchor_state *as, int k, double u, double h) {
    return cs_hht_acceleration(u, as->u_commit[k], as->rate[k], as->acc[k], h);
}

void cs_anchor_derive(const cs_anchor_def *d, double gravity, cs_anchor_model *am) {
    const cs_footing_def *f = &d->footing;
    am->x = d->x, am->z = d->z;
    am->rigid = !(f->diameter > 0.0);
    if (am->rigid) return;
    double b = f->diameter, len = d->length > 0.0 ? d->length : 0.0;
    double volume = len > 0.0 ? b * len * f->depth : 0.25 * CS_PI * b * b * f->depth;
    am->mass = d->mass > 0.0 ? d->mass : CS_CONCRETE_DENSITY * volume;
    am->moving_mass = am->mass + cs_footing_wedge_mass(f);
    am->capacity = cs_footing_impact_capacity(f, d->z);
    am->residual = cs_footing_residual_ratio(f) * am->capacity;
    am->softening = CS_ANCHOR_SOFTENING_STRAIN * f->depth;
    am->stiffness = am->capacity / (CS_PASSIVE_MOBILISATION * f->depth);
    am->drag = f->unit_weight / CS_G0 * b * f->depth;
    am->depth = f->depth, am->coeff_depth = f->coeff_depth, am->coeff_height = f->coeff_height;
    double perimeter_skin = len > 0.0 ? 2.0 * (b + len) / (CS_PI * b) : 1.0; /* a block's perimeter */
    /* a capacity given for the anchor, or for its footing, is design data and taken as it is */
    double given = d->pullout_capacity > 0.0 ? d->pullout_capacity : f->pullout_capacity;
    /* a capacity given holds its weight too: the weight (up to it) pulls the rising mass down, the skin
     * holds the rest */
    am->uplift_weight = given > 0.0 ? fmin(am->mass * gravity, given) : am->mass * gravity;
    am->uplift_skin =
        given > 0.0 ? given - am->uplift_weight : perimeter_skin * cs_footing_pullout_capacity(f);
    am->uplift_capacity = am->uplift_weight + am->uplift_skin;
}

int cs_anchor_active(const cs_model *model, const cs_state *s, int a) {
    if (model->anchors[a].rigid || s->anchors[a].failed || !(s->h > 0.0)) return 0;
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].status == CS_CABLE_INTACT) return 1;
    return 0;
}

static int end_node(const cs_cable_state *cs, int a) {
    return a == 0 ? 0 : cs->node_count - 1;
}

void cs_anchor_place_nodes(const cs_model *model, cs_state *s, int a) {
    const cs_anchor_model *am = &model->anchors[a];
    const double *u = s->anchors[a].u;
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        v3_set(cs->pos + 3 * end_node(cs, a), am->x + u[0], u[1], am->z + s->anchors[a].lift);
    }
}

/* The barrier as installed: each anchor deflected elastically by the ropes' pull as they stand (the
 * pretension along each end span), no further than its elastic limit; the ropes are then laid in on it
 * (step.c), as an installer tensions them against the anchors already loaded. */
void cs_anchor_settle(const cs_model *model, cs_state *s) {
    for (int a = 0; a < 2; a++) {
        const cs_anchor_model *am = &model->anchors[a];
        if (am->rigid) continue;
        double f[3] = {0.0, 0.0, 0.0};
        for (int c = 0; c < model->cable_count; c++) {
            const cs_cable_state *cs = &s->cables[c];
            if (cs->status != CS_CABLE_INTACT) continue;
            double fc[3];
            cs_node_force(cs, end_node(cs, a), NULL, fc);
            v3_add(f, f, fc);
        }
        double n = v2_norm(f[0], f[1]), cap = 0.999 * am->capacity, scale = n > cap ? cap / n : 1.0;
        s->anchors[a].u[0] = s->anchors[a].u_commit[0] = scale * f[0] / am->stiffness;
        s->anchors[a].u[1] = s->anchors[a].u_commit[1] = scale * f[1] / am->stiffness;
        cs_anchor_place_nodes(model, s, a);
    }
}

/* The cap on the soil's resistance after a plastic slide s: P falling linearly to P_r over s_r. */
double cs_anchor_cap(const cs_anchor_model *am, double s) {
    return s >= am->softening ? am->residual
                              : am->capacity - (am->capacity - am->residual) * s / am->softening;
}

/* The work of the cap, times the face's share f, over the slide from s0 to s1 (the soil's plastic work), J.
 */
static double cap_work(const cs_anchor_model *am, double f, double s0, double s1) {
    double m = fmin(fmax(am->softening, s0), s1); /* where the softening branch ends inside [s0, s1] */
    return f * (0.5 * (m - s0) * (cs_anchor_cap(am, s0) + cs_anchor_cap(am, m)) + (s1 - m) * am->residual);
}

/* The return map at the trial force's magnitude n after the committed slide s, on the cap times the face's
 * share f: the resistance's magnitude, the slide it takes into *slide and its slope d|R|/dn into *slope (1
 * elastic, -H/(k - H) softening, 0 on the residual). */
static double return_map(const cs_anchor_model *am, double f, double s, double n, double *slide,
                         double *slope) {
    double c = f * cs_anchor_cap(am, s), k = am->stiffness, residual = f * am->residual;
    *slide = 0.0, *slope = 1.0;
    if (n <= c) return n;
    if (s < am->softening) {
        double hard = f * (am->capacity - am->residual) / am->softening, l = (n - c) / (k - hard);
        if (s + l <= am->softening) {
            *slide = l, *slope = -hard / (k - hard);
            return c - hard * l;
        }
    }
    *slide = (n - residual) / k, *slope = 0.0;
    return residual;
}

/* x less its part back along the footing's plastic slide u_p (n = u_p / |u_p|) once it has slid, into out:
 * the part of an offset or a motion that bears on the soil it ploughed and not into its own trench behind
 * it. Into proj (2 x 2, row major), if given, d out / dx: I, or I - n n^T where x . n < 0. */
static void toward_soil(const cs_anchor_state *as, const double *x, double *out, double *proj) {
    double p = v2_norm(as->plastic[0], as->plastic[1]), n[2] = {0.0, 0.0}, xn = 0.0;
    if (as->slide > 0.0 && p > 0.0) {
        n[0] = as->plastic[0] / p, n[1] = as->plastic[1] / p;
        xn = x[0] * n[0] + x[1] * n[1];
        if (!(xn < 0.0)) n[0] = n[1] = xn = 0.0;
    }
    out[0] = x[0] - xn * n[0], out[1] = x[1] - xn * n[1];
    if (proj)
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                proj[2 * i + j] = (i == j) - n[i] * n[j];
}

/* The soil's trial force at displacement u into tr: k (u - u_p), on a footing that has ploughed only the
 * part toward the soil ahead of it. Backed off that soil ((u - u_p) . n < 0) its face bears on nothing and
 * its sides alone hold it, k (e - (e . n) n): the soil pushes and never pulls, and the potential |tr|^2 /
 * 2k stays continuous. Into proj, if given, d tr / du over k (toward_soil). */
static void trial_force(const cs_anchor_model *am, const cs_anchor_state *as, const double *u, double *tr,
                        double *proj) {
    double e[2] = {u[0] - as->plastic[0], u[1] - as->plastic[1]};
    toward_soil(as, e, tr, proj);
    tr[0] *= am->stiffness, tr[1] *= am->stiffness;
}

/* The soil's resistance at displacement u (the trial force returned radially onto the cap), its
 * magnitude's slope into *slope and the trial's magnitude into *trial (either may be NULL). */
static void resistance(const cs_anchor_model *am, const cs_anchor_state *as, const double *u, double *q,
                       double *slope, double *trial) {
    double tr[2];
    trial_force(am, as, u, tr, NULL);
    double n = v2_norm(tr[0], tr[1]), slide, dq;
    double m = return_map(am, cs_anchor_face_share(am, as), as->slide, n, &slide, &dq),
           f = n > m ? m / n : 1.0;
    q[0] = tr[0] * f, q[1] = tr[1] * f;
    if (slope) *slope = dq;
    if (trial) *trial = n;
}

/* The soil's inertial drag at the rate v, -c |v| v, into d, and its slope on the rate into dv (2 x 2, row
 * major) if given: the soil the face sweeps, c = rho b x D per metre of travel (x D the face still in the
 * ground), brought to the footing's speed (the momentum flux through the face). A footing that has
 * ploughed sweeps none with the part of its motion back into its own trench (toward_soil). */
static void drag(const cs_anchor_model *am, const cs_anchor_state *as, const double *v, double *d,
                 double *dv) {
    double w[2], proj[4], c = am->drag * embedded(am, as);
    toward_soil(as, v, w, proj);
    double speed = v2_norm(w[0], w[1]);
    d[0] = -c * speed * w[0], d[1] = -c * speed * w[1];
    if (!dv) return;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            dv[2 * i + j] = 0.0;
            for (int k = 0; k < 2; k++)
                dv[2 * i + j] -=
                    c * (speed * (i == k) + (speed > 0.0 ? w[i] * w[k] / speed : 0.0)) * proj[2 * k + j];
        }
}

/* The rate the step from the last commit to u over h gives (the HHT-alpha update). */
static void rate_to(const cs_anchor_state *as, const double *u, double h, double *v) {
    for (int k = 0; k < 2; k++)
        v[k] = cs_hht_rate(as->rate[k], as->acc[k], acceleration_to(as, k, u[k], h), h);
}

/* The ropes' pull on the anchor (every intact rope's end span), N; chords as in cs_node_force. */
static void ropes_pull(const cs_model *model, const cs_state *s, int a, const double *chords, double *f) {
    v3_set(f, 0.0, 0.0, 0.0);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        double fc[3];
        cs_node_force(cs, end_node(cs, a), chords ? chords + 4 * (size_t)c * (size_t)model->max_nodes : NULL,
                      fc);
        v3_add(f, f, fc);
    }
}

void cs_anchor_residual(const cs_model *model, const cs_state *s, int a, const double *chords, double *r) {
    const cs_anchor_model *am = &model->anchors[a];
    const cs_anchor_state *as = &s->anchors[a];
    double f[3], q[2];
    ropes_pull(model, s, a, chords, f);
    resistance(am, as, as->u, q, NULL, NULL);
    r[0] = f[0] - q[0], r[1] = f[1] - q[1];
    if (s->h > 0.0 && s->h < HUGE_VAL) {
        double acc[2], v[2], d[2];
        for (int k = 0; k < 2; k++)
            acc[k] = acceleration_to(as, k, as->u[k], s->h),
            v[k] = cs_hht_rate(as->rate[k], as->acc[k], acc[k], s->h);
        drag(am, as, v, d, NULL);
        for (int k = 0; k < 2; k++)
            r[k] += d[k] - cs_hht_inertia(am->moving_mass, acc[k], as->net[k]);
    }
}

static void residual(const cs_model *model, const cs_state *s, const cs_rows *rows, const cs_slot *u,
                     double *r) {
    cs_anchor_residual(model, s, u->a, rows->chords, r);
    double inv = 1.0 / cs_rows_force_unit(model);
    r[0] *= inv, r[1] *= inv;
}

/* Rows a, a+1: the ropes' pull through their end spans (chained to the nodes), less the resistance's slope
 * (k P elastic; past the peak k ((|R| / n) (P - e e^T) + d|R|/dn e e^T), e the trial's direction and P the
 * trial's projection, I or I - n n^T backed off its soil, which e lies in), the
 * inertial M / (beta h^2 (1 + alpha)) and the drag's c (|v| I + v v^T / |v|) gamma / (beta h) on the
 * anchor's own columns. */
static void jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                     const cs_slot *u) {
    int a = u->a;
    const cs_anchor_model *am = &model->anchors[a];
    const cs_anchor_state *as = &s->anchors[a];
    double unit = cs_rows_force_unit(model), k[4], q[2], slope, n, tr[2], proj[4];
    resistance(am, as, as->u, q, &slope, &n);
    trial_force(am, as, as->u, tr, proj);
    double qn = v2_norm(q[0], q[1]), t = n > 0.0 ? qn / n : 1.0, e[2] = {0.0, 0.0};
    if (n > 0.0) e[0] = tr[0] / n, e[1] = tr[1] / n;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            k[2 * i + j] = -am->stiffness * (t * (proj[2 * i + j] - e[i] * e[j]) + slope * e[i] * e[j]);
    double inertia = cs_hht_inertia_slope(am->moving_mass, s->h);
    k[0] -= inertia, k[3] -= inertia;
    if (s->h < HUGE_VAL) { /* the drag's slope on the rate, times dv/du = gamma / (beta h) */
        double v[2], d[2], dv[4];
        rate_to(as, as->u, s->h, v);
        drag(am, as, v, d, dv);
        for (int i = 0; i < 4; i++)
            k[i] += dv[i] * CS_HHT_GAMMA / (CS_HHT_BETA * s->h);
    }
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            cs_rows_add(rows, row + i, row + j, k[2 * i + j] / unit);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        int i = end_node(cs, a);
        const cs_span_grad *sp = rows->spans + (size_t)c * (size_t)model->max_nodes + (a == 0 ? 0 : i - 1);
        for (int e = 0; e < 2; e++) {
            double rho[3] = {e == 0 ? 1.0 / unit : 0.0, e == 1 ? 1.0 / unit : 0.0, 0.0};
            double gp[3][3] = {{0}}, gm[3] = {0};
            cs_rows_end_force_gradient(sp, a == 0, rho, gp, gm);
            cs_rows_add_node_gradient(model, s, rows, row + e, c, i, gp, gm);
        }
    }
}

const cs_row_kind cs_anchor_rows = {2, residual, jacobian};

/* ---- rising out of the soil ----
 * Once the ropes' uplift F_z reaches W + S the rise w is an unknown of the barrier's solve (rows.h), a row
 * like a post's pull (post_pullout.c): the skin holds R(w), k_s (w - w_p) up to S x^2 with x = 1 - (w_p +
 * S / k_s) / D still in the ground (cs_shaft_return_map, k_s = S / CS_SHAFT_MOBILISATION), the weight W
 * is a load, and the concrete's mass m rises by backward Euler over the time h since the last commit:
 *   F_z(w) - W - R(w) - m (w - w_c - h v_c) / h^2 = 0.
 * Its ropes' ends ride at the anchor's height plus w. The skin's plastic work S D (x_c^3 - x^3) / 3 is the
 * soil's, its slip's elastic energy (R^2 - S^2) / 2 k_s and the weight lifted W w are stored with the
 * anchor, and what backward Euler takes from the rise is damping. Out of the ground (x = 0) it holds
 * nothing and leaves the soil (cs_anchor_check). */

/* The share of its depth the skin still holds over after its plastic slip (committed). */
static double skin_remaining(const cs_anchor_model *am, const cs_anchor_state *as) {
    return 1.0 - (as->lift_plastic + CS_SHAFT_MOBILISATION) / am->depth;
}

/* The skin's resistance at the rise as it stands, x into *x and dR/dw into *slope (either may be NULL). */
static double skin(const cs_anchor_model *am, const cs_anchor_state *as, double *x, double *slope) {
    if (!(am->uplift_skin > 0.0)) { /* no skin (a capacity given as its weight alone) */
        if (x) *x = skin_remaining(am, as);
        if (slope) *slope = 0.0;
        return 0.0;
    }
    double k = am->uplift_skin / CS_SHAFT_MOBILISATION, xs, dn;
    double r = cs_shaft_return_map(am->uplift_skin, k * am->depth, skin_remaining(am, as),
                                   k * (as->lift - as->lift_plastic), &xs, &dn);
    if (x) *x = xs;
    if (slope) *slope = k * dn;
    return r;
}

/* The rise's inertial force m (w - w_c - h v_c) / h^2 and its slope (0 at an instant or at rest). */
static double lift_inertia(const cs_anchor_model *am, const cs_anchor_state *as, double h, double *slope) {
    int moving = h > 0.0 && h < HUGE_VAL;
    if (slope) *slope = moving ? am->mass / (h * h) : 0.0;
    return moving ? am->mass * (as->lift - as->lift_commit - h * as->lift_rate) / (h * h) : 0.0;
}

double cs_anchor_lift_balance(const cs_model *model, const cs_state *s, int a, const double *chords) {
    const cs_anchor_model *am = &model->anchors[a];
    const cs_anchor_state *as = &s->anchors[a];
    double f[3];
    ropes_pull(model, s, a, chords, f);
    return f[2] - am->uplift_weight - skin(am, as, NULL, NULL) - lift_inertia(am, as, s->h, NULL);
}

static void lift_residual(const cs_model *model, const cs_state *s, const cs_rows *rows, const cs_slot *u,
                          double *r) {
    r[0] = cs_anchor_lift_balance(model, s, u->a, rows->chords) / cs_rows_force_unit(model);
}

/* Row: the ropes' uplift through their end spans (chained to the nodes, the rise's own column among
 * them), less the skin's slope and m / h^2 on its own column. */
static void lift_jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                          const cs_slot *u) {
    int a = u->a;
    const cs_anchor_model *am = &model->anchors[a];
    double unit = cs_rows_force_unit(model), ds, dm;
    skin(am, &s->anchors[a], NULL, &ds);
    lift_inertia(am, &s->anchors[a], s->h, &dm);
    cs_rows_add(rows, row, row, -(ds + dm) / unit);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT) continue;
        int i = end_node(cs, a);
        const cs_span_grad *sp = rows->spans + (size_t)c * (size_t)model->max_nodes + (a == 0 ? 0 : i - 1);
        double rho[3] = {0.0, 0.0, 1.0 / unit}, gp[3][3] = {{0}}, gm[3] = {0};
        cs_rows_end_force_gradient(sp, a == 0, rho, gp, gm);
        cs_rows_add_node_gradient(model, s, rows, row, c, i, gp, gm);
    }
}

const cs_row_kind cs_lift_rows = {1, lift_residual, lift_jacobian};

/* The soil's elastic energy, held at the resistance R = k (u - u_p) on the cap: |R|^2 / 2k. */
static double elastic_energy(const cs_anchor_model *am, const cs_anchor_state *as) {
    double q[2];
    resistance(am, as, as->u, q, NULL, NULL);
    return 0.5 * (q[0] * q[0] + q[1] * q[1]) / am->stiffness;
}

/* The ropes' uplift has reached W + S: from here the rise is an unknown of the solve, the skin at its
 * hold where it stands (k_s (w - w_p) = S at w = 0). */
static void start_lift(const cs_model *model, cs_state *s, int a) {
    const cs_anchor_model *am = &model->anchors[a];
    cs_anchor_state *as = &s->anchors[a];
    as->lifting = 1;
    as->lift_plastic = as->lift - CS_SHAFT_MOBILISATION;
    as->lift_commit = as->lift, as->lift_rate = 0.0, as->lift_net = as->uplift - am->uplift_capacity;
    cs_event_add(model, s, CS_EVENT_ANCHOR_WITHDRAWAL, CS_ELEMENT_ANCHOR, a, as->uplift);
}

/* The rise at a commit: its rate and net force, what backward Euler took from it (the forces' energies
 * change by about -(Q_c + Q) dw / 2, Q = m (v - v_c) / h the net force the solve balanced, the kinetic
 * energy by Q dw - m |v - v_c|^2 / 2), the skin's plastic slip and its work. The face's share falls with
 * the rise: the face slides on to its lower cap and the elastic energy it no longer holds is the soil's.
 * fz: the ropes' uplift as solved. */
static void commit_lift(const cs_model *model, cs_state *s, int a, double fz) {
    const cs_anchor_model *am = &model->anchors[a];
    cs_anchor_state *as = &s->anchors[a];
    double dw = as->lift - as->lift_commit, x, r = skin(am, as, &x, NULL), x0 = skin_remaining(am, as);
    if (s->h > 0.0 && s->h < HUGE_VAL) {
        double v = dw / s->h, q = am->mass * (v - as->lift_rate) / s->h;
        s->e_post_damping +=
            0.5 * (as->lift_net + q) * dw - 0.5 * am->mass * (v * v - as->lift_rate * as->lift_rate);
        as->lift_rate = v, as->lift_net = q;
    } else {
        if (s->h > 0.0) as->lift_rate = 0.0;
        as->lift_net = fz - am->uplift_weight - r;
    }
    if (x < x0 &&
        am->uplift_skin > 0.0) { /* the skin slipped on: its work, and the slip from where it holds */
        s->e_soil += am->uplift_skin * am->depth * (x0 * x0 * x0 - x * x * x) / 3.0;
        as->lift_plastic = x > 0.0 ? as->lift - r * CS_SHAFT_MOBILISATION / am->uplift_skin
                                   : am->depth - CS_SHAFT_MOBILISATION;
    }
    double e0 = elastic_energy(am, as);
    as->lift_commit = as->lift;
    double tr[2];
    trial_force(am, as, as->u, tr, NULL);
    double n = v2_norm(tr[0], tr[1]), slide, slope;
    return_map(am, cs_anchor_face_share(am, as), as->slide, n, &slide, &slope);
    if (slide > 0.0) {
        as->plastic[0] += slide * tr[0] / n, as->plastic[1] += slide * tr[1] / n;
        as->slide += slide;
    }
    s->e_soil += e0 - elastic_energy(am, as);
}

/* End of step: the ropes' pull and its peak so far (a rigid anchor holds that pull, its force), the
 * slide's rate, acceleration and what its integration dissipates, the plastic slide (radial return) and
 * its work, the resistance, and the ropes' uplift; a rising anchor's rise (commit_lift), or the start
 * of one once the uplift reaches W + S (start_lift).
 * Over the step the forces' energies (the ropes' and the soil's, state functions and the soil's plastic
 * work) change by about -(F_c + F(u)) . du / 2, F the net force (the ropes' pull less the soil's
 * resistance); what the step takes out of the motion, that trapezoid rule's work of F less the kinetic
 * energy's change, is booked as damping: the HHT-alpha method's dissipation (none at alpha = 0, where
 * the kinetic energy changes by exactly that work) and the solve's residual. An anchor no rope pulls
 * any more (the last let go) is out of the solve: the soil stops it within the step, and its kinetic
 * energy goes to the soil. A re-solve at an instant (h = 0, after a failure) keeps its rate and starts
 * its acceleration again from the net force there, as at the start of a motion. */
void cs_anchor_commit(const cs_model *model, cs_state *s) {
    for (int a = 0; a < 2; a++) {
        const cs_anchor_model *am = &model->anchors[a];
        cs_anchor_state *as = &s->anchors[a];
        if (as->failed) continue;
        double f[3], q[2];
        ropes_pull(model, s, a, NULL, f);
        as->peak_pull = fmax(as->peak_pull, hypot(f[0], f[1]));
        if (am->rigid) { /* it holds what the ropes pull */
            as->force[0] = f[0], as->force[1] = f[1];
            as->uplift = f[2] > 0.0 ? f[2] : 0.0;
            continue;
        }
        resistance(am, as, as->u, q, NULL, NULL);
        double net[2] = {f[0] - q[0], f[1] - q[1]}, d_c[2], d[2];
        double kinetic_before = kinetic_energy(am, as);
        drag(am, as, as->rate, d_c, NULL);
        if (s->h > 0.0 && s->h < HUGE_VAL && !cs_anchor_active(model, s, a)) {
            s->e_soil += kinetic_before; /* no rope pulls it: the soil stops it */
            as->rate[0] = as->rate[1] = as->acc[0] = as->acc[1] = 0.0;
            d[0] = d[1] = 0.0;
        } else if (s->h > 0.0 && s->h < HUGE_VAL) {
            double work = 0.0, swept = 0.0;
            for (int k = 0; k < 2; k++) {
                double acc = acceleration_to(as, k, as->u[k], s->h);
                as->rate[k] = cs_hht_rate(as->rate[k], as->acc[k], acc, s->h);
                as->acc[k] = acc;
            }
            drag(am, as, as->rate, d, NULL);
            for (int k = 0; k < 2; k++) { /* the trapezoid rule's work of the net force, and the drag's */
                double du = as->u[k] - as->u_commit[k];
                work += 0.5 * (as->net[k] + net[k] + d[k]) * du;
                swept -= 0.5 * (d_c[k] + d[k]) * du;
            }
            s->e_soil += swept, as->swept += swept; /* the swept soil's motion, dissipated in the soil */
            s->e_post_damping += work - (kinetic_energy(am, as) - kinetic_before);
        } else { /* h infinite: settled at rest; h = 0: it keeps the rate it had, as a post does */
            if (s->h > 0.0) as->rate[0] = as->rate[1] = 0.0;
            drag(am, as, as->rate, d, NULL);
            as->acc[0] = (net[0] + d[0]) / am->moving_mass, as->acc[1] = (net[1] + d[1]) / am->moving_mass;
        }
        as->net[0] = net[0] + d[0], as->net[1] = net[1] + d[1];
        as->u_commit[0] = as->u[0], as->u_commit[1] = as->u[1];
        double tr[2];
        trial_force(am, as, as->u, tr, NULL);
        double n = v2_norm(tr[0], tr[1]), slide, slope;
        double share = cs_anchor_face_share(am, as);
        return_map(am, share, as->slide, n, &slide, &slope);
        if (slide > 0.0) {
            double e[2] = {tr[0] / n, tr[1] / n};
            s->e_soil += cap_work(am, share, as->slide, as->slide + slide);
            as->plastic[0] += slide * e[0], as->plastic[1] += slide * e[1];
            as->slide += slide;
            if (!as->yielded) {
                as->yielded = 1;
                cs_event_add(model, s, CS_EVENT_ANCHOR_YIELD, CS_ELEMENT_ANCHOR, a, am->capacity);
            }
        }
        as->uplift = f[2] > 0.0 ? f[2] : 0.0;
        if (as->lifting) {
            commit_lift(model, s, a, f[2]);
            double q1[2], d1[2]; /* the net force the next step starts from, on the face's share now */
            resistance(am, as, as->u, q1, NULL, NULL);
            drag(am, as, as->rate, d1, NULL);
            as->net[0] = f[0] - q1[0] + d1[0], as->net[1] = f[1] - q1[1] + d1[1];
        } else if (s->h > 0.0 && s->h < HUGE_VAL && as->uplift >= am->uplift_capacity)
            start_lift(model, s, a);
        resistance(am, as, as->u, as->force, NULL, NULL);
    }
}

/* An anchor risen all the way out of the ground holds nothing: it leaves the soil, and every rope tied to
 * it is released (contact.c). Returns 1 if one did. */
int cs_anchor_check(const cs_model *model, cs_state *s) {
    int failed = 0;
    for (int a = 0; a < 2; a++) {
        const cs_anchor_model *am = &model->anchors[a];
        cs_anchor_state *as = &s->anchors[a];
        if (am->rigid || as->failed || !as->lifting ||
            (skin_remaining(am, as) > 0.0 && as->lift < am->depth)) /* the skin slipped out, or the body */
            continue;
        as->failed = 1;
        cs_event_add(model, s, CS_EVENT_ANCHOR_PULLOUT, CS_ELEMENT_ANCHOR, a, as->uplift);
        failed = 1;
    }
    return failed;
}

double cs_anchor_stored_energy(const cs_model *model, const cs_state *s, int a, double *kinetic) {
    const cs_anchor_model *am = &model->anchors[a];
    const cs_anchor_state *as = &s->anchors[a];
    *kinetic = 0.0;
    if (am->rigid || as->failed) return 0.0;
    *kinetic = kinetic_energy(am, as) + 0.5 * am->mass * as->lift_rate * as->lift_rate;
    double e =
        elastic_energy(am, as) + am->uplift_weight * as->lift; /* the soil's spring, the weight lifted */
    if (as->lifting && am->uplift_skin > 0.0) { /* the skin's slip, counted from where it started (at S) */
        double r = skin(am, as, NULL, NULL);
        e += 0.5 * (r * r - am->uplift_skin * am->uplift_skin) * CS_SHAFT_MOBILISATION / am->uplift_skin;
    }
    return e;
}
