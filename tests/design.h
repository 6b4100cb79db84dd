/* SPDX-License-Identifier: MIT */
/* Random but valid designs and attacks for the stress test and the engine's fuzzer: rope sizes, post
 * spacing, cables, dead-men, rails, vehicle sizes, speeds 5-60 mph, angles 15-90 degrees, impact anywhere
 * along the barrier including at an anchor and past its end. Each value is drawn from a source: a
 * counter-based generator (design k is the same whatever the run count) or, for the fuzzer, the bytes of
 * its input (two a value, then the generator seeded by what was read). */
#ifndef CS_TEST_DESIGN_H
#define CS_TEST_DESIGN_H

#include "fixture.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifndef M_PI_2_VALUE /* as tests/check.h has it */
#define M_PI_2_VALUE 1.57079632679489661923
#endif

/* SplitMix64: a counter-based generator. */
static inline unsigned long long design_mix(unsigned long long x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

typedef struct design_source {
    unsigned long long s;
    const uint8_t *data; /* NULL: the generator alone */
    size_t size, at;
} design_source;

/* A value in [lo, hi): the next two input bytes while they last, else the generator. */
static inline double design_uniform(design_source *src, double lo, double hi) {
    if (src->data && src->at + 2 <= src->size) {
        unsigned v = (unsigned)src->data[src->at] << 8 | src->data[src->at + 1];
        src->at += 2;
        src->s = design_mix(src->s ^ v);
        return lo + (hi - lo) * (double)v / 65536.0;
    }
    src->s = design_mix(src->s);
    return lo + (hi - lo) * (double)(src->s >> 11) / 9007199254740992.0;
}

typedef struct design {
    fixture fx;
    char what[160];
} design;

/* Design k from a source (k names it in what). */
static inline void design_make(int k, design_source *src, design *d) {
    fixture *fx = &d->fx;
    fixture_aps3(fx);
    int cables = 1 + (int)design_uniform(src, 0.0, 2.0); /* 1 or 2 */
    double rope_in = design_uniform(src, 0.5, 1.75), spacing = design_uniform(src, 4.0, 12.0) * FT;
    int posts = 4 + (int)design_uniform(src, 0.0, 20.0);
    for (int c = 0; c < 2; c++) {
        fx->cables[c].rope = fixture_rope(rope_in);
        fx->cables[c].height = (c == 0 ? design_uniform(src, 0.6, 0.9) : design_uniform(src, 0.95, 1.3));
        fx->cables[c].pretension = design_uniform(src, 0.5, 8.0) * KIP;
    }
    for (int p = 0; p < posts; p++) {
        fx->posts[p] = fx->posts[0];
        fx->posts[p].x = spacing * (p + 1);
    }
    double length = spacing * (posts + 1);
    fx->barrier.cable_count = cables;
    fx->barrier.post_count = posts;
    fx->barrier.start_anchor.x = 0.0;
    fx->barrier.end_anchor.x = length;
    /* dead-men from rigid (a quarter of the designs) to a small footing that lets go early */
    double dead_man = design_uniform(src, -0.5, 1.5);
    fx->barrier.start_anchor.footing = fx->barrier.end_anchor.footing =
        fixture_footing(dead_man > 0.0 ? 1.0 + 2.0 * dead_man : 0.0, 3.0 + 2.0 * fabs(dead_man), 0.0);
    int rails = (int)design_uniform(src, -2.0, 5.0); /* none in about half, else 1 to 4 of the APS rails */
    if (rails > 0) fixture_rails(fx), fx->barrier.rail_count = rails;
    /* a vehicle between a small car and a heavy truck, scaled from the 15,000-lb truck */
    double scale = design_uniform(src, 0.35, 1.6);
    cs_vehicle_def *v = &fx->vehicle;
    v->mass *= scale * scale * scale;
    for (int i = 0; i < 3; i++)
        v->inertia[i] *= pow(scale, 5);
    v->cg_height *= scale, v->cg_to_front *= scale, v->front_width *= scale, v->face_bottom *= scale;
    v->face_top *= scale, v->wheelbase *= scale, v->cg_to_front_axle *= scale, v->track *= scale;
    v->cg_to_rear *= scale, v->side_bottom *= scale, v->side_top *= scale;
    for (int i = 0; i < v->crush_point_count; i++)
        v->crush_deformation[i] *= scale, v->crush_force[i] *= scale * scale;
    fx->scenario.speed = design_uniform(src, 5.0, 60.0) * MPH;
    fx->scenario.angle = design_uniform(src, 15.0, 90.0) * M_PI_2_VALUE / 90.0;
    fx->scenario.impact_x = design_uniform(src, -0.1, 1.1) * length; /* past either anchor too */
    fx->scenario.t_end = 0.15;
    snprintf(
        d->what, sizeof d->what,
        "design %d: %d cables of %.2f in, %d posts at %.1f ft, %d rails, dead-men %.1f ft wide, %.0f lb at "
        "%.1f mph, %.0f deg, x = %.1f of %.1f m",
        k, cables, rope_in, posts, spacing / FT, fx->barrier.rail_count,
        fx->barrier.start_anchor.footing.diameter / FT, v->mass / LB, fx->scenario.speed / MPH,
        fx->scenario.angle * 90.0 / M_PI_2_VALUE, fx->scenario.impact_x, length);
}

/* Fittings that slip (docs/theory.md, Slip), drawn after the rest of a design, which they leave unchanged:
 * at each rope end of about half of them a slip load from just above the cable's pretension to the rope's
 * strength and a turn-back of 1 to 40 in. Returns how many ends slip. */
static inline int design_add_slip(design_source *src, design *d) {
    int ends = 0;
    for (int c = 0; c < 2; c++)
        for (int e = 0; e < 2; e++) {
            cs_cable_def *cd = &d->fx.cables[c];
            double u = design_uniform(src, -1.0, 1.0);
            if (u <= 0.0) continue;
            cd->ends[e].slip_load = cd->pretension + u * (cd->rope.nominal_strength - cd->pretension);
            cd->ends[e].slip_travel = design_uniform(src, 1.0, 40.0) * IN;
            ends += c < d->fx.barrier.cable_count;
        }
    return ends;
}

/* Design k of the stress test. */
static inline void design_numbered(int k, design *d) {
    design_source src = {0x5eed0000ULL + (unsigned long long)k, NULL, 0, 0};
    design_make(k, &src, d);
}

#endif
