/* Footing in soil: lateral capacity by the pole-foundation relation of the paper (Eq. 21),
 *   S1 B D^2 - c_d P D - c_h P H = 0   =>   P = S1 B D^2 / (c_d D + c_h H),
 * with S1 capped (paper: 8000 psf). The relation is dimensionally homogeneous (c_d, c_h are pure
 * numbers), so it holds in SI as written. Past P the footing rotates in the soil at constant
 * moment P H (post.c), and that work is the soil's share of the energy ledger. */
#include "internal.h"

#include <math.h>

double cs_footing_capacity(const cs_footing_def *f, double load_height) {
    double s1 = fmin(f->soil_pressure, f->soil_pressure_cap);
    return s1 * f->diameter * f->depth * f->depth /
           (f->coeff_depth * f->depth + f->coeff_height * load_height);
}
