/* Footing in soil.
 * Lateral: the pole-foundation relation of the paper (Eq. 21),
 *   S1 B D^2 - c_d P D - c_h P H = 0   =>   P = S1 B D^2 / (c_d D + c_h H),
 * with S1 capped (paper: 8000 psf). The relation is dimensionally homogeneous (c_d, c_h are pure
 * numbers), so it holds in SI as written. Eq. 21 is a static design relation; under an impact the soil
 * resists more (rate and inertia effects in a dense, moist granular soil, and the three-dimensional
 * passive wedge ahead of a narrow member), which the dynamic factor carries: P_impact = f_d P. Past
 * P_impact the footing rotates in the soil at constant moment (post.c), and that work is the soil's
 * share of the energy ledger.
 * Axial: a footing without a given pullout capacity is held by shaft friction that grows linearly with
 * depth (K sigma_v tan delta, sigma_v = gamma z): q z on the perimeter pi B, so Q = q pi B D^2 / 2. */
#include "internal.h"

#include <math.h>

#define CS_PI 3.14159265358979323846

double cs_footing_capacity(const cs_footing_def *f, double load_height) {
    double s1 = fmin(f->soil_pressure, f->soil_pressure_cap);
    return s1 * f->diameter * f->depth * f->depth /
           (f->coeff_depth * f->depth + f->coeff_height * load_height);
}

double cs_footing_impact_capacity(const cs_footing_def *f, double load_height) {
    return f->dynamic_factor * cs_footing_capacity(f, load_height);
}

double cs_footing_pullout_capacity(const cs_footing_def *f) {
    if (f->pullout_capacity > 0.0) return f->pullout_capacity; /* design data (or HUGE_VAL: never) */
    return f->skin_friction * CS_PI * f->diameter * f->depth * f->depth / 2.0;
}
