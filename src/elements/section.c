/* SPDX-License-Identifier: MIT */
/* A post section's strength and stiffness in bending about its strong axis, and its shear capacity. A hollow
 * section yields at Zx Fy and bends with E Ix. A rectangular tube filled with concrete (b wide, h deep, wall
 * t, core b_i = b - 2t by h_i = h - 2t) is taken by AISC 360-16's plastic stress distribution (I1.2a): the
 * steel at Fy in tension and compression, the concrete at 0.85 f'c in compression and none in tension. With
 * the neutral axis a below the compression face (a >= t), the steel below it less the steel above it,
 * 2t (h - 2a) Fy, balances the core's compression 0.85 f'c b_i (a - t):
 *   a = (2 t h Fy + 0.85 f'c b_i t) / (4 t Fy + 0.85 f'c b_i),
 * and the moment is each block's force times its arm about that axis. Without concrete a = h / 2 and
 * the moment is the square-cornered tube's own Z Fy; the fill adds the difference of the two, so that a
 * section keeps the Zx its table gives. The concrete stiffens it by C3 Ec Ic (AISC 360-16 Eq. I2-15:
 * C3 = 0.45 + 3 As / Ag, at most 0.9; Ec = 0.043 w^1.5 sqrt(f'c) MPa, w the model's plain concrete,
 * CS_CONCRETE_DENSITY, in kg/m^3). docs/theory.md, "A tube filled with concrete". */
#include "cablesim/units.h"
#include "elements/elements.h"

#include <math.h>
#include <stdio.h>

/* The plastic moment of the square-cornered tube about its plastic neutral axis, the concrete at
 * 0.85 fc (0: hollow). */
static double tube_moment(const cs_section_def *s, double fc) {
    double b = s->width, h = s->depth, t = s->wall, fy = s->yield_stress, bi = b - 2.0 * t, c = 0.85 * fc;
    double a = (2.0 * t * h * fy + c * bi * t) / (4.0 * t * fy + c * bi);
    double above = a - t, below = h - t - a; /* the webs' lengths either side of the axis */
    return fy * b * t * (a - 0.5 * t + h - a - 0.5 * t) + fy * t * (above * above + below * below) +
           0.5 * c * bi * above * above;
}

double cs_section_plastic_moment(const cs_section_def *s) {
    double mp = s->plastic_modulus * s->yield_stress;
    if (!(s->fill_strength > 0.0)) return mp;
    return mp + tube_moment(s, s->fill_strength) - tube_moment(s, 0.0);
}

double cs_section_flexural_rigidity(const cs_section_def *s) {
    double ei = s->modulus * s->inertia;
    if (!(s->fill_strength > 0.0)) return ei;
    double b = s->width, h = s->depth, t = s->wall, bi = b - 2.0 * t, hi = h - 2.0 * t;
    double c3 = fmin(0.45 + 3.0 * (b * h - bi * hi) / (b * h), 0.9);
    double ec = 0.043 * pow(CS_CONCRETE_DENSITY, 1.5) * sqrt(s->fill_strength / 1e6) * 1e6;
    return ei + c3 * ec * bi * hi * hi * hi / 12.0;
}

double cs_section_shear_capacity(const cs_section_def *s) {
    return 0.6 * s->web_area * s->yield_stress;
}

/* The method holds for compact walls (AISC 360-16 Table I1.1b, filled members in flexure: the flanges'
 * b / t at most 2.26 sqrt(E / Fy), the webs' h / t at most 3.00 sqrt(E / Fy), b and h the flat widths,
 * the outer less 3t) and for normal-weight concrete of 3 to 10 ksi (I1.3). */
const char *cs_section_fill_problem(const cs_section_def *s, char *why, size_t n) {
    if (!(s->fill_strength > 0.0)) return NULL;
    if (!(s->width > 0.0 && s->depth > 0.0 && s->wall > 0.0 && 2.0 * s->wall < fmin(s->width, s->depth))) {
        snprintf(why, n,
                 "a filled section needs its tube's width, depth and wall (twice the wall under both)");
        return why;
    }
    double fc = s->fill_strength / CS_KSI;
    if (fc < 3.0 * (1.0 - 1e-9) || fc > 10.0 * (1.0 + 1e-9)) {
        snprintf(why, n, "fill strength %.4g ksi is outside 3-10 ksi, where AISC 360-16 takes a filled tube",
                 fc);
        return why;
    }
    double root = sqrt(s->modulus / s->yield_stress), t = s->wall;
    double flange = (s->width - 3.0 * t) / t, web = (s->depth - 3.0 * t) / t;
    if (flange > 2.26 * root || web > 3.00 * root) {
        snprintf(why, n,
                 "the filled tube's walls are not compact (b/t %.3g against %.3g, h/t %.3g against %.3g): "
                 "its plastic moment is not reached",
                 flange, 2.26 * root, web, 3.00 * root);
        return why;
    }
    return NULL;
}
