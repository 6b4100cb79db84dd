/* SPDX-License-Identifier: MIT */
/* Footing in soil.
 * Lateral: the pole-foundation relation of the paper (Eq. 21),
 *   S1 B D^2 - c_d P D - c_h P H = 0   =>   P = S1 B D^2 / (c_d D + c_h H),
 * with S1 capped (paper: 8000 psf). The relation is dimensionally homogeneous (c_d, c_h are pure
 * numbers), so it holds in SI as written. Eq. 21 is a static design relation, linear in the width B;
 * under an impact the soil resists more, which the dynamic factor f_d carries. f_d is calibrated on the
 * bogie tests of a 4.03-in post embedded about 40 in: for that member it holds the rate and inertia of
 * the soil struck at 9 m/s and the three-dimensional passive wedge ahead of a narrow member, which a
 * wide footing does not get in the same measure (a wedge spreads sideways by a width that grows with
 * depth, not with the member's width). The wedge's share scales with Ovesen and Brinch Hansen's
 * three-dimensional factor for a block at grade (no cover, alone in its row: Duncan and Mokwa 2001),
 *   R(b/D) = 1 + (Kp - Ka)^0.67 1.6 / (1 + 5 b / D),  Kp = tan^2(45 + phi/2), Ka = tan^2(45 - phi/2),
 * so a member of width b and depth D resists f_d R(b/D) / R(b_ref/D_ref) times Eq. 21's P, the bogie
 * post (b_ref, D_ref) being the reference. The rate effect is carried as the bogie's (docs/theory.md,
 * "Anchorage"). Past its capacity the footing rotates in the soil at constant moment (post.c) or slides
 * (anchor.c), and that work is the soil's share of the energy ledger.
 * Past the peak a dense soil's shear zone dilates to its critical state, so the passive resistance falls
 * to that of the critical-state friction angle phi_cv (Bolton 1986: about 33 deg for quartz sand, 40 for
 * feldspar): the residual ratio Kp(phi_cv) R(b/D; phi_cv) / (Kp(phi) R(b/D; phi)).
 * Axial: a footing without a given pullout capacity is held by shaft friction that grows linearly with
 * depth (K sigma_v tan delta, sigma_v = gamma z): q z on the perimeter pi B, so Q = q pi B D^2 / 2. */
#include "elements/elements.h"

#include <math.h>

#define CS_WEDGE_REF_WIDTH (4.03 * CS_IN) /* the bogie tests' W6x16 flange, m */
#define CS_WEDGE_REF_DEPTH (40.0 * CS_IN) /* their embedment, about 40 in (864-1092 mm), m */

double cs_footing_capacity(const cs_footing_def *f, double load_height) {
    double s1 = fmin(f->soil_pressure, f->soil_pressure_cap);
    return s1 * f->diameter * f->depth * f->depth /
           (f->coeff_depth * f->depth + f->coeff_height * load_height);
}

double cs_footing_wedge_factor(double friction_angle, double width, double depth) {
    double kp = pow(tan(0.25 * CS_PI + 0.5 * friction_angle), 2.0);
    double ka = pow(tan(0.25 * CS_PI - 0.5 * friction_angle), 2.0);
    return 1.0 + pow(kp - ka, 0.67) * 1.6 / (1.0 + 5.0 * width / depth);
}

/* Kp R of a member b x D: the three-dimensional passive coefficient at the friction angle phi. */
static double passive_3d(double phi, double width, double depth) {
    return pow(tan(0.25 * CS_PI + 0.5 * phi), 2.0) * cs_footing_wedge_factor(phi, width, depth);
}

double cs_footing_residual_ratio(const cs_footing_def *f) {
    if (!(f->residual_friction_angle < f->friction_angle)) return 1.0; /* no dilation to lose */
    return passive_3d(f->residual_friction_angle, f->diameter, f->depth) /
           passive_3d(f->friction_angle, f->diameter, f->depth);
}

/* The passive wedge a footing pushed through the soil carries (Rankine): bounded by the slip plane at
 * 45 - phi/2 to the horizontal from the footing's base to grade, D^2 tan(45 + phi/2) / 2 in section, it
 * slides up that plane as the footing moves by v, at v / cos(45 - phi/2); its kinetic energy is that of a
 * mass rho b D^2 tan(45 + phi/2) / (2 cos^2(45 - phi/2)) = rho b D^2 / cos(phi) at v (rho = gamma / g0),
 * over the footing's width b in plane strain: the 3-D wedge's flanks carry more. The unit weight is a
 * weight at standard gravity, whatever the scenario's. */
double cs_footing_wedge_mass(const cs_footing_def *f) {
    return f->unit_weight / CS_G0 * f->diameter * f->depth * f->depth / cos(f->friction_angle);
}

double cs_footing_dynamic_factor(const cs_footing_def *f) {
    if (f->width_scaling == CS_WIDTH_NONE) return f->dynamic_factor;
    double ref = cs_footing_wedge_factor(f->friction_angle, CS_WEDGE_REF_WIDTH, CS_WEDGE_REF_DEPTH);
    return f->dynamic_factor * cs_footing_wedge_factor(f->friction_angle, f->diameter, f->depth) / ref;
}

double cs_footing_impact_capacity(const cs_footing_def *f, double load_height) {
    return cs_footing_dynamic_factor(f) * cs_footing_capacity(f, load_height);
}

double cs_footing_rotational_stiffness(const cs_footing_def *f, double load_height) {
    if (!(f->diameter > 0.0 && f->depth > 0.0)) return HUGE_VAL;
    double lever = load_height + 2.0 * f->depth / 3.0;
    return cs_footing_impact_capacity(f, load_height) * lever / (1.5 * CS_PASSIVE_MOBILISATION);
}

double cs_footing_pullout_capacity(const cs_footing_def *f) {
    if (f->pullout_capacity > 0.0) return f->pullout_capacity; /* design data (or HUGE_VAL: never) */
    return f->skin_friction * CS_PI * f->diameter * f->depth * f->depth / 2.0;
}

/* What Eq. 21 holds with only x of the depth d left in the ground, the body risen (1 - x) d with the load
 * that much higher, against the whole depth: P(x) / P(1) = x^2 (c_d d + c_h h) / (c_d x d + c_h (h + (1 -
 * x) d)), about x^2. A post sliding out of its footing and a dead-man rising out of the soil. */
double cs_footing_remaining_share(double coeff_depth, double coeff_height, double depth, double height,
                                  double x) {
    return x * x * (coeff_depth * depth + coeff_height * height) /
           (coeff_depth * x * depth + coeff_height * (height + (1.0 - x) * depth));
}

/* A shaft sliding out of the soil, its friction growing linearly with depth: with x0 of its depth D in the
 * ground it holds Q0 x0^2, elastic at k below (the slip that mobilises it: CS_SHAFT_MOBILISATION). At the
 * trial n = k (w - w_p) above that it slides by l, n - k l = Q0 x^2 with x = x0 - l / D:
 *   Q0 x^2 - k D x + (k D x0 - n) = 0,   x = 2 (k D x0 - n) / (k D + sqrt(k^2 D^2 - 4 Q0 (k D x0 - n))),
 * the root at x0 when n = Q0 x0^2 (written so that it loses no digits: k D / Q0 is about 360 for the APS
 * posts). Returns the resistance, x into *x and dR/dn into *slope (1 elastic, 2 Q0 x / (2 Q0 x - k D)
 * sliding, 0 out of the ground, x <= 0). A post sliding out of its footing, a dead-man rising out of the
 * soil. */
double cs_shaft_return_map(double q0, double kd, double x0, double n, double *x, double *slope) {
    *x = x0, *slope = 1.0;
    if (x0 > 0.0 && n <= q0 * x0 * x0) return n;
    double cst = kd * x0 - n, disc = kd * kd - 4.0 * q0 * cst;
    if (x0 <= 0.0 || cst <= 0.0 || disc < 0.0) { /* out of the ground */
        *x = 0.0, *slope = 0.0;
        return 0.0;
    }
    *x = 2.0 * cst / (kd + sqrt(disc));
    *slope = 2.0 * q0 * *x / (2.0 * q0 * *x - kd);
    return q0 * *x * *x;
}
