/* SPDX-License-Identifier: MIT */
/* The energy ledger. Each term is computed on its own: kinetic and potential energy from the
 * vehicle's state, elastic energy from the cables' and posts' current forces, and dissipations
 * accumulated where they happen (cable.c, post.c, vehicle.c, barrier.c, step.c). The balance error
 * compares their sum with its value at t = 0, as a fraction of the energy scale (cs_energy_scale: the
 * initial kinetic energy, or m g h for a vehicle that starts at rest). */
#include "elements/elements.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* The energy the balance error is a fraction of: the initial kinetic energy, or for a vehicle that
 * starts at rest the work of lifting it by its CG height (m g h), so the fraction stays meaningful. */
double cs_energy_scale(const cs_model *model, const cs_state *s) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double lift = v->mass * model->scenario.gravity * v->cg_height;
    return s->e_initial_kinetic > lift ? s->e_initial_kinetic : (lift > 0.0 ? lift : 1.0);
}

double cs_energy_total(const cs_energy *e) {
    double sum = 0.0;
    for (int k = 0; k < CS_ENERGY_TERMS; k++)
        sum += cs_energy_term(e, k);
    return sum;
}

void cs_energy_update(const cs_model *model, cs_state *s) {
    cs_energy *e = &s->energy;
    e->size = sizeof *e;
    e->vehicle_kinetic = cs_vehicle_kinetic_energy(model, s);
    e->vehicle_potential = cs_vehicle_potential_energy(model, s) - s->e_initial_potential_ref;
    e->cable_elastic = 0.0;
    for (int c = 0; c < model->cable_count; c++)
        e->cable_elastic += cs_cable_stored_energy(&model->cables[c], &s->cables[c]);
    e->post_elastic = e->post_kinetic = 0.0;
    for (int p = 0; p < model->post_count; p++) {
        e->post_elastic += cs_post_elastic_energy(model, s, p);
        e->post_kinetic += cs_post_kinetic_energy(model, s, p);
    }
    e->anchor_elastic = e->anchor_kinetic = 0.0;
    for (int a = 0; a < 2; a++) {
        double kinetic;
        e->anchor_elastic += cs_anchor_stored_energy(model, s, a, &kinetic);
        e->anchor_kinetic += kinetic;
    }
    e->rail_elastic = s->e_rail_elastic;
    e->rail_plastic = s->e_rail_plastic;
    e->cable_plastic = s->e_cable_plastic;
    e->post_plastic = s->e_post_plastic;
    e->post_damping = s->e_post_damping;
    e->soil = s->e_soil;
    e->crush = s->e_crush;
    e->friction = s->e_friction + s->e_tyre;
    e->released = s->e_released;
    e->initial_total = s->e_initial_total;
    e->initial_kinetic = s->e_initial_kinetic;
    double ref = cs_energy_scale(model, s);
    e->balance_error = (cs_energy_total(e) - s->e_initial_total) / ref;
    if (fabs(e->balance_error) > fabs(s->summary.energy_balance_error))
        s->summary.energy_balance_error = e->balance_error;
}

static const char *const term_names[CS_ENERGY_TERMS] = {
    "ke",           "pe",           "cable_elastic",  "cable_plastic",  "post_elastic", "post_kinetic",
    "post_plastic", "post_damping", "anchor_elastic", "anchor_kinetic", "rail_elastic", "rail_plastic",
    "soil",         "crush",        "friction",       "released"};

const char *cs_energy_term_name(int k) {
    return k >= 0 && k < CS_ENERGY_TERMS ? term_names[k] : "?";
}

/* The terms' places in cs_energy, in their order. */
static const size_t term_offsets[CS_ENERGY_TERMS] = {offsetof(cs_energy, vehicle_kinetic),
                                                     offsetof(cs_energy, vehicle_potential),
                                                     offsetof(cs_energy, cable_elastic),
                                                     offsetof(cs_energy, cable_plastic),
                                                     offsetof(cs_energy, post_elastic),
                                                     offsetof(cs_energy, post_kinetic),
                                                     offsetof(cs_energy, post_plastic),
                                                     offsetof(cs_energy, post_damping),
                                                     offsetof(cs_energy, anchor_elastic),
                                                     offsetof(cs_energy, anchor_kinetic),
                                                     offsetof(cs_energy, rail_elastic),
                                                     offsetof(cs_energy, rail_plastic),
                                                     offsetof(cs_energy, soil),
                                                     offsetof(cs_energy, crush),
                                                     offsetof(cs_energy, friction),
                                                     offsetof(cs_energy, released)};

double cs_energy_term(const cs_energy *e, int k) {
    if (!e || k < 0 || k >= CS_ENERGY_TERMS || term_offsets[k] + sizeof(double) > e->size) return 0.0;
    double v;
    memcpy(&v, (const char *)e + term_offsets[k], sizeof v);
    return v;
}
