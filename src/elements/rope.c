/* SPDX-License-Identifier: MIT */
/* Rope: the rope law (Eqs. 1-2, Fig. 3) and the tension of a span, where a rope's tension is computed.
 *
 * A cable is a chain of straight spans between its supports (cable.c). Node i carries a material
 * coordinate m_i: the unstretched length of rope from the start anchor. Span i holds s_i = m_{i+1} - m_i
 * of rope over a chord of length l_i, so its strain is e_i = l_i / s_i - 1; its tension follows from the
 * rope law, with the span's sag under its own weight, and is given here with its gradient for the
 * barrier solve's Jacobian. */
#include "core/vec3.h"
#include "elements/elements.h"

#include <math.h>
#include <string.h>

void cs_rope_derive(const cs_rope_def *d, double g, cs_rope *r) {
    r->ea = d->modulus * d->area;
    r->fu = d->nominal_strength;
    r->t1 = d->elastic_limit_ratio * r->fu;
    r->e1 = r->t1 / r->ea;
    r->k2 = d->secondary_modulus_ratio * r->ea;
    r->e2 = cs_rope_strain_at_strength(d);
    r->e_break = d->breaking_strain;
    r->w = d->mass_per_length * g;
}

/* Backbone: elastic slope EA to T1, secondary slope to Fu, then constant Fu (plastic). */
static double rope_backbone(const cs_rope *r, double e) {
    if (e <= r->e1) return r->ea * e;
    if (e <= r->e2) return r->t1 + r->k2 * (e - r->e1);
    return r->fu;
}

/* Tension at total strain e with committed plastic strain ep: elastic from ep with slope EA, capped
 * by the backbone (the return map of an elastic-plastic law with hardening); zero when slack. */
double cs_rope_tension(const cs_rope *r, double e, double ep) {
    double trial = r->ea * (e - ep);
    if (trial <= 0.0) return 0.0;
    double b = rope_backbone(r, e);
    return trial < b ? trial : b;
}

/* Recoverable energy of a span of unstretched length s under tension T (unloading slope EA). */
double cs_rope_elastic_energy(const cs_rope *r, double t, double s) {
    return 0.5 * t * t / r->ea * s;
}

double cs_span_length(const cs_cable_state *cs, int i) {
    return v3_dist(cs->pos + 3 * i, cs->pos + 3 * (i + 1));
}

void cs_span_chord(const cs_cable_state *cs, int i, double *d) {
    v3_sub(d, cs->pos + 3 * (i + 1), cs->pos + 3 * i);
    d[3] = v3_norm(d);
}

/* Sag term of a span with chord d (cs_span_chord), w_n^2 l^3 = w^2 h^2 l: its weight across the chord
 * (w_n = w h / l, h the chord's length in plan) over its chord length cubed. */
double cs_span_sag(const cs_rope *r, const double *d) {
    return r->w * r->w * (d[0] * d[0] + d[1] * d[1]) * d[3];
}

/* The positive root T of g(T) = T^2 (T - a) - c (c > 0), a span's tension with its sag (below). Newton
 * from above the root converges monotonically (g is increasing and convex there); its error after a
 * step of relative size d is about 2 d^2 (g''/2g' = 1/T for a slack span, 2/T for a taut one), so a step
 * below 1e-8 T leaves the root to round-off. It starts from the least of the bounds that T^2 (T - a) = c
 * gives: T - a < c / a^2 and < c^(1/3) for a > 0 (a taut span: one or two steps), T < c^(1/3) and
 * < (c / -a)^(1/2) for a < 0. */
static double sag_root(double a, double c) {
    double t;
    if (a > 0.0)
        t = a + (c < a * a * a ? c / (a * a) : cbrt(c));
    else
        t = a < 0.0 && c < -a * a * a ? sqrt(-c / a) : cbrt(c);
    for (int it = 0; it < 100; it++) {
        double dt = (t * t * (t - a) - c) / (t * (3.0 * t - 2.0 * a));
        t -= dt;
        if (dt <= 1e-8 * t) break;
    }
    return t;
}

/* Tension of a span with `material` of rope (plastic strain ep) over a chord of `length`, hanging by its
 * own weight (sag term q = w_n^2 l^3). A shallow parabola of tension T is longer than its chord by
 * q / (24 T^2), so elastically s (1 + ep + T/EA) = l + q / (24 T^2), i.e. T^3 - a T^2 - c = 0 with
 * a = EA (l/s - 1 - ep) and c = EA q / (24 s): one positive root, smooth in l and s (no slack kink; a
 * weightless rope, q = 0, has T = max(a, 0)), found by sag_root. The backbone caps T at the arc's strain.
 * *arc (unless NULL) gets the arc's strain and *yields whether the backbone capped T (the rope yields). */
double cs_span_tension_law(const cs_rope *r, double length, double material, double ep, double q, double *arc,
                           int *yields) {
    *yields = 0;
    if (material <= 1e-12) { /* no rope left in the span: as taut as the rope gets */
        if (arc) *arc = r->e_break * 2.0;
        return r->fu;
    }
    double e = length / material - 1.0;
    if (q <= 0.0) {
        double t = cs_rope_tension(r, e, ep);
        *yields = t > 0.0 && r->ea * (e - ep) > t;
        if (arc) *arc = e;
        return t;
    }
    double a = r->ea * (e - ep), c = r->ea * q / (24.0 * material), t = sag_root(a, c);
    if (t <= r->t1 && ep >= 0.0) { /* below T1 no point of the backbone ahead of ep is lower: no cap (an
                                    * ulp of round-off in EA (t / EA) had capped, "yielding", before) */
        if (arc) *arc = ep + t / r->ea;
        return t;
    }
    double b = rope_backbone(r, ep + t / r->ea);
    if (t > b) {
        t = b;
        if (arc) *arc = e + c / (r->ea * t * t);
        *yields = 1;
    } else if (arc) {
        *arc = ep + t / r->ea;
    }
    return t;
}

double cs_span_tension_at(const cs_rope *r, double length, double material, double ep, double q) {
    int yields;
    return cs_span_tension_law(r, length, material, ep, q, NULL, &yields);
}

/* fmin(fmax(0, x), hi) without libm's calls (the same for hi >= 0). */
static double clamp_to(double x, double hi) {
    return x > 0.0 ? (x < hi ? x : hi) : 0.0;
}

/* Plastic strain of span i with its ends at material coordinates lo and hi: the rope it kept since the
 * last commit at its own plastic strain, plus the rope that slid in across either end at the plastic
 * strain of the span it came from (the permanent stretch travels with the rope; first-order upwind); at a
 * rope end, the rope that came out of its fitting at left or right, 0 (never loaded). */
double cs_span_plastic_of(const cs_cable_state *cs, int i, double lo, double hi, double left, double own,
                          double right) {
    double s = hi - lo;
    if (s <= 1e-12) return own;
    double gl = clamp_to(cs->m_commit[i] - lo, s), gr = clamp_to(hi - cs->m_commit[i + 1], s - gl);
    double e = own * (s - gl - gr);
    if (gl > 0.0) e += left * gl;
    if (gr > 0.0) e += right * gr;
    return e / s;
}

double cs_span_plastic(const cs_cable_state *cs, int i, double lo, double hi) {
    return cs_span_plastic_of(cs, i, lo, hi, i > 0 ? cs->ep[i - 1] : 0.0, cs->ep[i],
                              i + 2 < cs->node_count ? cs->ep[i + 1] : 0.0);
}

double cs_span_tension_chord(const cs_cable_model *cm, const cs_cable_state *cs, int i, double *d) {
    cs_span_chord(cs, i, d);
    return cs_span_tension_at(&cm->rope, d[3], cs->m[i + 1] - cs->m[i],
                              cs_span_plastic(cs, i, cs->m[i], cs->m[i + 1]), cs_span_sag(&cm->rope, d));
}

double cs_span_tension(const cs_cable_model *cm, const cs_cable_state *cs, int i) {
    double d[4];
    return cs_span_tension_chord(cm, cs, i, d);
}

/* Slope of the backbone at strain e (0 on the plastic plateau). */
static double backbone_slope(const cs_rope *r, double e) {
    return e <= r->e1 ? r->ea : (e <= r->e2 ? r->k2 : 0.0);
}

/* Partial derivatives of span_tension_sag's T (at its root t) with respect to the chord `length`, the
 * `material`, the plastic strain ep and the sag term q. Off the backbone, implicit differentiation of
 * g = T^3 - a T^2 - c = 0 gives dT = (T^2 da + dc) / (3 T^2 - 2 a T); capped by it, T = B(arc) with
 * arc = e + c / (EA T^2), so dT (1 + 2 B' c / (EA T^3)) = B' (de + dc / (EA T^2)). */
static void span_tension_partials(const cs_rope *r, double length, double material, double ep, double q,
                                  double t, int yields, double *d) {
    d[0] = d[1] = d[2] = d[3] = 0.0; /* d/dlength, d/dmaterial, d/dep, d/dq */
    if (material <= 1e-12 || t <= 0.0) return;
    double s = material, e = length / s - 1.0, de_dl = 1.0 / s, de_ds = -length / (s * s);
    double c = r->ea * q / (24.0 * s), dc_ds = -c / s, dc_dq = r->ea / (24.0 * s);
    if (yields) {
        double arc = e + (q > 0.0 ? c / (r->ea * t * t) : 0.0), slope = backbone_slope(r, arc);
        double k = slope / (1.0 + 2.0 * slope * c / (r->ea * t * t * t)), ct = 1.0 / (r->ea * t * t);
        d[0] = k * de_dl, d[1] = k * (de_ds + ct * dc_ds), d[3] = k * ct * dc_dq;
        return;
    }
    if (q <= 0.0) {
        d[0] = r->ea * de_dl, d[1] = r->ea * de_ds, d[2] = -r->ea;
        return;
    }
    double a = r->ea * (e - ep), den = t * (3.0 * t - 2.0 * a), t2 = t * t;
    d[0] = t2 * r->ea * de_dl / den;
    d[1] = (t2 * r->ea * de_ds + dc_ds) / den;
    d[2] = -t2 * r->ea / den;
    d[3] = dc_dq / den;
}

/* Tension of span i with chord dv (cs_span_chord) and its gradient (cs_span_grad). The plastic strain that
 * slides in with the rope (span_plastic) enters by a difference quotient over a nanometre. */
void cs_span_tension_grad(const cs_cable_model *cm, const cs_cable_state *cs, int i, const double *dv,
                          cs_span_grad *g) {
    const cs_rope *r = &cm->rope;
    double lo = cs->m[i], hi = cs->m[i + 1];
    double l = dv[3], q = cs_span_sag(r, dv), ep = cs_span_plastic(cs, i, lo, hi), arc, d[4];
    int yields;
    g->t = cs_span_tension_law(r, l, hi - lo, ep, q, &arc, &yields);
    g->l = l;
    span_tension_partials(r, l, hi - lo, ep, q, g->t, yields, d);
    /* q = w^2 (dx^2 + dy^2) l */
    double w2 = r->w * r->w, h2 = dv[0] * dv[0] + dv[1] * dv[1], inv = l > 1e-12 ? 1.0 / l : 0.0;
    for (int k = 0; k < 3; k++) {
        g->u[k] = dv[k] * inv;
        g->dt_dd[k] = d[0] * g->u[k] + d[3] * w2 * ((k < 2 ? 2.0 * dv[k] * l : 0.0) + h2 * g->u[k]);
    }
    double step = 1e-9, dep_lo = (cs_span_plastic(cs, i, lo + step, hi) - ep) / step,
           dep_hi = (cs_span_plastic(cs, i, lo, hi + step) - ep) / step;
    g->dt_dm[0] = -d[1] + d[2] * dep_lo;
    g->dt_dm[1] = d[1] + d[2] * dep_hi;
}

/* Rope (no plastic set) that span i holds at tension t: the inverse of the span law,
 * s (1 + t/EA) = l + q / (24 t^2); weightless or without tension, l / (1 + t/EA). */
double cs_span_material_at(const cs_cable_model *cm, const cs_cable_state *cs, int i, double t) {
    double d[4];
    cs_span_chord(cs, i, d);
    double l = d[3], q = cs_span_sag(&cm->rope, d);
    if (t > 0.0) l += q / (24.0 * t * t);
    return l / (1.0 + t / cm->rope.ea);
}
