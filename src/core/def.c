/* SPDX-License-Identifier: MIT */
/* What the definitions imply: a rope's strain at its strength, the end fittings' efficiencies and slip,
 * the attachments' release loads (docs/assumptions.md), the wheels' points and the impact points. The
 * defaults themselves are inline in def.h, so a program fills its structs at its own sizes. */
#include "cablesim/def.h"
#include "cablesim/units.h"

#include <math.h>

double cs_rope_strain_at_strength(const cs_rope_def *r) {
    double ea = r->modulus * r->area, t1 = r->elastic_limit_ratio * r->nominal_strength;
    return t1 / ea + (r->nominal_strength - t1) / (r->secondary_modulus_ratio * ea);
}

/* US Army TM 5-3810-305-10 Table 4 and Crosby's G-450 instructions (shared reference data: rope-fittings.md).
 */
double cs_termination_efficiency(cs_termination kind, double diameter) {
    switch (kind) {
    case CS_TERMINATION_CLIPS:
        return diameter > 0.0 && diameter < CS_IN - 1e-9 ? 0.80 : 0.90;
    case CS_TERMINATION_SWAGED:
        return 0.95;
    case CS_TERMINATION_SPELTER:
        return 1.0;
    case CS_TERMINATION_WEDGE:
        return 0.85;
    case CS_TERMINATION_AS_CABLE: /* no kind of its own */
        return 0.0;
    }
    return 0.80;
}

double cs_cable_end_efficiency(const cs_cable_def *cable, int end, cs_termination *kind) {
    const cs_cable_end_def *e = &cable->ends[end != 0];
    int own = e->termination != CS_TERMINATION_AS_CABLE;
    cs_termination k = own ? e->termination : cable->termination;
    if (kind) *kind = k;
    if (e->termination_efficiency > 0.0) return e->termination_efficiency;
    if (!own && cable->termination_efficiency > 0.0) return cable->termination_efficiency;
    return cs_termination_efficiency(k, cable->rope.diameter);
}

double cs_cable_end_slip(const cs_cable_def *cable, int end, double *travel) {
    const cs_cable_end_def *e = &cable->ends[end != 0];
    int own = e->termination != CS_TERMINATION_AS_CABLE; /* a fitting of its own slips only if told so */
    if (travel) *travel = e->slip_travel > 0.0 ? e->slip_travel : cable->slip_travel;
    return e->slip_load > 0.0 ? e->slip_load : own ? 0.0 : cable->slip_load;
}

/* docs/assumptions.md: a slot's strap and cap, taken as the vertical release of the cable-to-post
 * attachments designed for the same purpose (about 1 kN); a 5/16-in hook bolt opening at the plastic
 * moment of its bar (36 ksi) over the lever from the bar to the 3/4-in cable's centre (13.5 mm); the
 * keyway bolt's 1.00 kip (Dickey et al., MwRSF) and the tabbed bracket's 346 lb (Rosenbaugh et al., MwRSF)
 * measured in component tests. */
double cs_attachment_release_force(cs_attachment kind) {
    switch (kind) {
    case CS_ATTACH_SLOT:
        return 1.0e3;
    case CS_ATTACH_HOOK:
        return 1.5e3;
    case CS_ATTACH_KEYWAY:
        return 1.00 * CS_KIP;
    case CS_ATTACH_BRACKET:
        return 346.0 * CS_LBF;
    case CS_ATTACH_THROUGH:
    case CS_ATTACH_CLAMPED:
        break;
    }
    return 0.0;
}

/* docs/assumptions.md: the same component tests, pulled off the post's face: the keyway bolt's 8.00 kip,
 * the tabbed bracket's 6.10 kip. */
double cs_attachment_lateral_release_force(cs_attachment kind) {
    switch (kind) {
    case CS_ATTACH_KEYWAY:
        return 8.00 * CS_KIP;
    case CS_ATTACH_BRACKET:
        return 6.10 * CS_KIP;
    case CS_ATTACH_THROUGH:
    case CS_ATTACH_CLAMPED:
    case CS_ATTACH_SLOT:
    case CS_ATTACH_HOOK:
        break;
    }
    return 0.0;
}

double cs_post_release_force(const cs_post_def *post) {
    return post->release_force > 0.0 ? post->release_force : cs_attachment_release_force(post->attachment);
}

double cs_post_lateral_release_force(const cs_post_def *post) {
    return post->lateral_release_force > 0.0 ? post->lateral_release_force
                                             : cs_attachment_lateral_release_force(post->attachment);
}

void cs_vehicle_wheel_points(const cs_vehicle_def *v, double wheel[4][3]) {
    double a = v->cg_to_front_axle, b = v->wheelbase - a;
    for (int i = 0; i < 4; i++) {
        wheel[i][0] = i < 2 ? a : -b;
        wheel[i][1] = (i % 2 == 0 ? 0.5 : -0.5) * v->track; /* left wheels first */
        wheel[i][2] = -v->cg_height;
    }
}

void cs_scenario_impact_points(const cs_scenario_def *s, double front_width, double *centre, double *corner) {
    /* the leading corner lies on the side the vehicle travels from, along the line */
    double half = (cos(s->angle) >= 0.0 ? 0.5 : -0.5) * front_width / sin(s->angle);
    double c = s->impact_at_corner ? s->impact_x + half : s->impact_x;
    if (centre) *centre = c;
    if (corner) *corner = c - half;
}
