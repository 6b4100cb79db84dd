/* SPDX-License-Identifier: MIT */
/* The quasi-static barrier at the vehicle's pose: every standing post in moment equilibrium with its
 * cables (post.c), every support sticking or sliding by the capstan condition (support.c), every
 * contact on the face and the face's crush in balance (contact.c). The cables are massless (the
 * paper's assumption: wave travel along a 50-m barrier takes ~20 ms); a post's equilibrium includes the
 * inertial moment of its swing (post.c). Solved as one system by Newton (system.c); where Newton stalls,
 * the fallback's sweeps (relax.c) take it on, here and only here. Then the barrier's push on the
 * vehicle, and the commit of a solved state (plastic flow, friction and crush work). */
#include "core/vec3.h"
#include "solver/solver.h"
#include "solver/work.h"

#include <math.h>
#include <string.h>

/* Newton from the state as it stands, with rounds of the fallback's sweeps where it stalls far off; -1
 * if it still stalls. */
static double newton_or_sweeps(const cs_model *model, cs_state *s, int may_fall, int *swept) {
    double worst = cs_system_solve(model, s, &s->work->sys);
    for (int round = 0; worst < 0.0 && round < 6 && !cs_work_spent(model, s->work); round++) {
        *swept = 1;
        cs_relax(model, s, 3, may_fall); /* sweeps, then Newton again from there */
        worst = cs_system_solve(model, s, &s->work->sys);
    }
    return worst;
}

/* The solve at the vehicle's pose as it stands: Newton, with the fallback where Newton stalls. A solve
 * that still ends above CS_FALL_TRIGGER is taken again with sweeps that let a post with no equilibrium
 * near fall to the next one (relax.c). That is kept if it converges and, committed, the barrier would
 * hold no more energy (stored and dissipated) than at its last commit: a fall gives energy up, and a
 * "fall" that would book more is a branch the path cannot reach (a stress design fell onto a state whose
 * commit booked 11 kJ more than the ropes gave up). Only on a failed solve: a post whose local solve
 * stalls inside an ordinary sweep is usually waiting for its neighbours, not falling (falls there led
 * another design onto the rope at its strength). tests/test_solve.c reaches the fallback. Once the run's
 * work budget is spent (work.h) no round of the fallback, polish or fall is begun and the sweeps make
 * none: the solve ends as it stands, and the step that made it is not taken (step.c). */
#define CS_FALL_TRIGGER 1e-2
#define CS_POLISH_ROUNDS 7
#define CS_FALL_SLACK 1e-3 /* of the energy scale, as step.c's CS_PATH_GAP: a piece's work, round-off */

static double solve_at_pose(const cs_model *model, cs_state *s) {
    const cs_scenario_def *sc = &model->scenario;
    cs_work *w = s->work;
    w->count.solves++;
    if (!cs_face_loaded(model, s)) cs_relax_crush(model, s); /* an unloaded face springs back to its set */
    int swept = 0;
    double worst = newton_or_sweeps(model, s, 0, &swept);
    if (swept || worst < 0.0 || worst > sc->solver_tolerance) w->count.fallback++;
    /* Stalled near it: polish in rounds of a few sweeps and Newton again, each kept only if it ends
     * closer, until the tolerance is met (one round mostly does). */
    for (int round = 0; round < CS_POLISH_ROUNDS && worst > sc->solver_tolerance && !cs_work_spent(model, w);
         round++) {
        cs_system_keep(model, s, &w->sys);
        cs_relax(model, s, 3, 0);
        double polished = cs_system_solve(model, s, &w->sys);
        if (polished >= 0.0 && polished < worst) {
            worst = polished;
        } else {
            cs_system_go_back(model, s, &w->sys);
            break;
        }
    }
    if (worst < 0.0)
        worst = cs_relax(model, s, sc->solver_max_sweeps, 0); /* Newton stalled, or band too wide */
    if (worst > CS_FALL_TRIGGER && !cs_work_spent(model, w)) {
        w->count.fall_tries++;
        cs_system_keep(model, s, &w->sys);
        cs_relax(model, s, 3, 1);
        double fallen = newton_or_sweeps(model, s, 1, &swept);
        if (fallen < 0.0) fallen = cs_relax(model, s, sc->solver_max_sweeps, 1);
        double slack = CS_FALL_SLACK * cs_energy_scale(model, s);
        if (fallen <= CS_FALL_TRIGGER && cs_barrier_trial_energy(model, s, w) <= w->stored_committed + slack)
            worst = fallen, w->count.falls++, cs_system_jumped(&w->sys, s->step); /* a jump, as a failure's */
        else
            cs_system_go_back(model, s, &w->sys);
    }
    return worst;
}

double cs_barrier_solve(const cs_model *model, cs_state *s) {
    double worst = solve_at_pose(model, s);
    for (int c = 0; c < model->cable_count; c++)
        cs_cable_update_tensions(&model->cables[c], &s->cables[c], NULL);
    cs_post_place_captured(model, s, s->crush);
    s->face_force = cs_face_loaded(model, s) ? cs_face_normal_force(model, s, NULL) : 0.0;
    return worst;
}

/* Resultant force and moment (about the CG) of the cables on the vehicle, through the corners they wrap. */
void cs_barrier_force(const cs_model *model, cs_state *s) {
    v3_set(s->force, 0.0, 0.0, 0.0);
    v3_set(s->moment, 0.0, 0.0, 0.0);
    cs_post_place_captured(model, s, s->crush);
    cs_post_captured_force(model, s, s->crush, 0, s->force, s->moment);
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        v3_set(cs->push, 0.0, 0.0, 0.0), v3_set(cs->push + 3, 0.0, 0.0, 0.0);
        if (!cs->engaged || cs->status != CS_CABLE_INTACT) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (!cs_node_is_corner(cs->node[i])) continue;
            double f[3], r[3], t[3];
            cs_node_force(cs, i, NULL, f);
            v3_add(s->force, s->force, f); /* corner by corner: the sum as it always was, to the bit */
            v3_add(cs->push, cs->push, f);
            v3_sub(r, cs->pos + 3 * i, s->pos);
            v3_cross(t, r, f);
            v3_add(s->moment, s->moment, t);
            v3_add(cs->push + 3, cs->push + 3, t);
        }
    }
}

void cs_barrier_commit(const cs_model *model, cs_state *s) {
    cs_contact_commit(model, s);
    for (int c = 0; c < model->cable_count; c++)
        cs_cable_commit(model, c, s);
    for (int p = 0; p < model->post_count; p++)
        cs_post_commit(model, s, p);
    cs_anchor_commit(model, s);
    cs_rail_commit(model, s);
    s->h = 0.0; /* the posts' swing starts again from here */
    const cs_vehicle_def *v = &model->vehicle.def;
    double f = cs_crush_force(v, s->crush, s->crush_max);
    s->e_crush += 0.5 * (f + s->crush_force_committed) * (s->crush - s->crush_committed);
    if (s->crush > s->crush_max) s->crush_max = s->crush;
    s->crush_committed = s->crush;
    s->crush_force_committed = f;
}

/* The stored and dissipated energy the barrier would hold if committed as it stands (found on a trial
 * copy, which records no events). */
double cs_barrier_trial_energy(const cs_model *model, const cs_state *s, cs_work *work) {
    cs_state *t = work->trial;
    cs_state_copy(model, t, s);
    t->event_count = model->event_capacity;
    cs_barrier_commit(model, t);
    return cs_barrier_stored_energy(model, t);
}

/* Stored plus dissipated energy of the barrier side; a sudden failure changes it with no work done. */
double cs_barrier_stored_energy(const cs_model *model, const cs_state *s) {
    double e = s->e_cable_plastic + s->e_post_plastic + s->e_post_damping + s->e_soil + s->e_crush +
               s->e_friction + s->e_rail_plastic + s->e_rail_elastic;
    for (int c = 0; c < model->cable_count; c++)
        e += cs_cable_stored_energy(&model->cables[c], &s->cables[c]);
    for (int p = 0; p < model->post_count; p++)
        e += cs_post_stored_energy(model, s, p);
    for (int a = 0; a < 2; a++) {
        double kinetic;
        e += cs_anchor_stored_energy(model, s, a, &kinetic) + kinetic;
    }
    return e;
}
