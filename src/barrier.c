/* The quasi-static barrier: for the vehicle's pose at the end of a step, find the state in which
 *   - every standing post is in moment equilibrium with its cables (post.c),
 *   - every support satisfies the capstan condition, sticking or sliding (cable.c),
 *   - the face's crush balances the cables' push on it (the paper's crush correction),
 * by Gauss-Seidel over these local problems, each solved exactly with its neighbours held, until the
 * largest relative residual found in a sweep is below the solver tolerance. The cables are massless
 * (the paper's assumption): wave travel along a 50-m barrier takes ~20 ms. A post's equilibrium
 * includes the inertial moment of its swing (post.c). */
#include "internal.h"
#include "vec3.h"

#include <math.h>
#include <string.h>

static void face_axis(const cs_state *s, double *x) {
    double bx[3] = {1.0, 0.0, 0.0};
    quat_rotate(x, s->quat, bx);
}

/* Normal force on the face at the state as it stands: the cables through the corners plus the
 * pushes of captured posts, along the vehicle's heading. */
double cs_face_normal_force_now(const cs_model *model, cs_state *s, const double *chords) {
    double ax[3], f[3] = {0.0, 0.0, 0.0}, mo[3] = {0.0, 0.0, 0.0};
    face_axis(s, ax);
    double n = cs_post_place_captured(model, s, s->crush, f, mo) > 0.0 ? -v3_dot(f, ax) : 0.0;
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (!cs->engaged || cs->status != CS_CABLE_INTACT) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (cs->node[i] != CS_NODE_LEFT && cs->node[i] != CS_NODE_RIGHT) continue;
            double fc[3];
            cs_node_force(cs, i, chords ? chords + 4 * (size_t)c * (size_t)model->max_nodes : NULL, fc);
            n -= v3_dot(fc, ax);
        }
    }
    return n;
}

/* Normal force for a trial crush, with the corner nodes moved there. */
static double face_normal_force(const cs_model *model, cs_state *s, double crush) {
    cs_contact_place_corners(model, s, crush);
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (!cs->engaged || cs->status != CS_CABLE_INTACT) continue;
        const cs_cable_model *cm = &model->cables[c];
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (cs->node[i] != CS_NODE_LEFT && cs->node[i] != CS_NODE_RIGHT) continue;
            cs->tension[i - 1] = cs_span_tension(cm, cs, i - 1);
            cs->tension[i] = cs_span_tension(cm, cs, i);
        }
    }
    double saved = s->crush;
    s->crush = crush;
    double n = cs_face_normal_force_now(model, s, NULL);
    s->crush = saved;
    return n;
}

/* Whether anything pushes on the face: an intact cable wrapped on it or a standing captured post. */
int cs_face_loaded(const cs_model *model, const cs_state *s) {
    for (int c = 0; c < model->cable_count; c++)
        if (s->cables[c].engaged && s->cables[c].status == CS_CABLE_INTACT) return 1;
    for (int p = 0; p < model->post_count; p++)
        if (s->posts[p].captured && cs_post_standing(&s->posts[p])) return 1;
    return 0;
}

/* Crush correction: solve N(crush) = C(crush), N falling and C rising with crush (regula falsi),
 * stopping when the force changes by less than the crush tolerance; the sweep loop repeats it until
 * the barrier as a whole converges. Returns the relative residual found on entry. */
static double crush_solve(const cs_model *model, cs_state *s) {
    s->solver.settled = 0;
    const cs_vehicle_def *v = &model->vehicle.def;
    double lo = cs_crush_permanent(v, s->crush_max);
    double scale = v->crush_force[v->crush_point_count - 1];
    if (!cs_face_loaded(model, s)) {
        s->crush = lo;
        s->face_force = 0.0;
        return 0.0;
    }
    double x = s->crush < lo ? lo : s->crush;
    double n = face_normal_force(model, s, x), g = n - cs_crush_force(v, x, s->crush_max);
    double entry = fabs(g) / scale;
    double glo = face_normal_force(model, s, lo) - cs_crush_force(v, lo, s->crush_max);
    if (glo <= 0.0) { /* the cables do not even reach the permanent set */
        s->crush = lo;
        s->face_force = face_normal_force(model, s, lo);
        return glo < 0.0 ? 0.0 : entry;
    }
    double a = lo, ga = glo, b = x > lo ? x : lo + 1e-3,
           gb = face_normal_force(model, s, b) - cs_crush_force(v, b, s->crush_max);
    for (int k = 0; gb > 0.0 && k < 60; k++) {
        a = b, ga = gb;
        b = lo + 2.0 * (b - lo);
        gb = face_normal_force(model, s, b) - cs_crush_force(v, b, s->crush_max);
    }
    double tol = model->scenario.crush_tolerance, xr = a, last = n;
    int side = 0;
    for (int it = 0; it < 60; it++) {
        xr = (a * gb - b * ga) / (gb - ga);
        double nr = face_normal_force(model, s, xr), gr = nr - cs_crush_force(v, xr, s->crush_max);
        int done =
            fabs(nr - last) <= tol * fmax(fabs(nr), 1e-9 * scale) && fabs(gr) <= tol * fmax(nr, 1e-9 * scale);
        last = nr;
        if (done || fabs(gr) <= 1e-12 * scale || b - a < 1e-13) break;
        if (gr > 0.0) {
            a = xr, ga = gr;
            if (side == 1) gb *= 0.5;
            side = 1;
        } else {
            b = xr, gb = gr;
            if (side == -1) ga *= 0.5;
            side = -1;
        }
    }
    s->crush = xr;
    s->face_force = face_normal_force(model, s, xr);
    return entry;
}

/* Gauss-Seidel over the local problems, up to `sweeps` sweeps, or until CS_GS_STALL sweeps in a row
 * have not brought the residual below 0.9 of the best yet (a stalled sweep is pure cost: of APS3's two
 * 300-sweep fallbacks one had its best residual, 1.49e-2, at sweep 25 and ended at 1.88e-2). With
 * may_fall, a post with no equilibrium near falls to the next one (post.c). */
#define CS_GS_STALL 50

static double gauss_seidel(const cs_model *model, cs_state *s, int sweeps, int may_fall) {
    s->solver.settled = 0;
    const cs_scenario_def *sc = &model->scenario;
    double worst = 0.0, best = HUGE_VAL;
    for (int sweep = 0, last_gain = 0; sweep < sweeps && sweep - last_gain <= CS_GS_STALL; sweep++) {
        worst = 0.0;
        for (int k = 0; k < model->post_count; k++) {
            int p = (sweep % 2 == 0) ? k : model->post_count - 1 - k; /* alternate direction */
            worst = fmax(worst, cs_post_solve(model, s, p, sc->solver_tolerance, may_fall));
        }
        for (int c = 0; c < model->cable_count; c++) {
            cs_cable_state *cs = &s->cables[c];
            if (cs->status != CS_CABLE_INTACT) continue;
            const cs_cable_model *cm = &model->cables[c];
            int n = cs->node_count;
            for (int k = 1; k + 1 < n; k++) {
                int i = (sweep % 2 == 0) ? k : n - 1 - k;
                worst = fmax(worst, cs_cable_slide_node(model, cm, cs, i, sc->solver_tolerance));
            }
        }
        for (int c = 0; c < model->cable_count; c++) { /* contact heights on the face */
            cs_cable_state *cs = &s->cables[c];
            if (cs->status != CS_CABLE_INTACT || !cs->engaged) continue;
            for (int i = 1; i + 1 < cs->node_count; i++)
                if (cs->node[i] == CS_NODE_LEFT || cs->node[i] == CS_NODE_RIGHT)
                    worst = fmax(worst,
                                 cs_contact_solve_height(model, s, c, i, cs->node[i] == CS_NODE_LEFT ? 0 : 1,
                                                         sc->solver_tolerance));
        }
        worst = fmax(worst, crush_solve(model, s));
        if (worst <= sc->solver_tolerance) break;
        if (worst < 0.9 * best) best = worst, last_gain = sweep;
    }
    return worst;
}

/* Newton from the state as it stands, with rounds of Gauss-Seidel sweeps where it stalls far off;
 * -1 if it still stalls. */
static double newton_or_sweeps(const cs_model *model, cs_state *s, int may_fall) {
    double worst = cs_barrier_newton(model, s);
    for (int round = 0; worst < 0.0 && round < 6; round++) {
        gauss_seidel(model, s, 3, may_fall); /* sweeps, then Newton again from there */
        worst = cs_barrier_newton(model, s);
    }
    return worst;
}

/* The solve at the vehicle's pose as it stands: Newton, with Gauss-Seidel where Newton stalls. A solve
 * that still ends above CS_FALL_TRIGGER is taken again with sweeps that let a post with no equilibrium
 * near fall to the next one (post.c). That is kept if it converges and, committed, the barrier would
 * hold no more energy (stored and dissipated) than at its last commit: a fall gives energy up, and a
 * "fall" that would book more is a branch the path cannot reach (design 5498 fell onto a state whose
 * commit booked 11 kJ more than the ropes gave up). Only on a failed solve: a post whose local solve
 * stalls inside an ordinary sweep is usually waiting for its neighbours, not falling (falls there led
 * design 1648 onto the rope at its strength). */
#define CS_FALL_TRIGGER 1e-2
#define CS_POLISH_ROUNDS 7
#define CS_FALL_SLACK 1e-3 /* of the energy scale, as step.c's CS_PATH_GAP: a piece's work, round-off */

static double solve_at_pose(const cs_model *model, cs_state *s) {
    const cs_scenario_def *sc = &model->scenario;
    if (!cs_face_loaded(model, s)) crush_solve(model, s); /* an unloaded face springs back to its set */
    double worst = newton_or_sweeps(model, s, 0);
    /* Stalled near it: polish in rounds of a few sweeps and Newton again, each kept only if it ends
     * closer, until the tolerance is met (one round mostly does; 20 sweeps at once had cost APS3 a third
     * of its time for its four stalled solves). */
    for (int round = 0; round < CS_POLISH_ROUNDS && worst > sc->solver_tolerance; round++) {
        cs_solver_keep(model, s);
        gauss_seidel(model, s, 3, 0);
        double polished = cs_barrier_newton(model, s);
        if (polished >= 0.0 && polished < worst) {
            worst = polished;
        } else {
            cs_solver_go_back(model, s);
            break;
        }
    }
    if (worst < 0.0)
        worst = gauss_seidel(model, s, sc->solver_max_sweeps, 0); /* Newton stalled, or band too wide */
    if (worst > CS_FALL_TRIGGER) {
        cs_solver_keep(model, s);
        gauss_seidel(model, s, 3, 1);
        double fallen = newton_or_sweeps(model, s, 1);
        if (fallen < 0.0) fallen = gauss_seidel(model, s, sc->solver_max_sweeps, 1);
        double slack = CS_FALL_SLACK * cs_energy_scale(model, s);
        if (fallen <= CS_FALL_TRIGGER && cs_barrier_trial_energy(model, s) <= s->stored_committed + slack)
            worst = fallen;
        else
            cs_solver_go_back(model, s);
    }
    return worst;
}

double cs_barrier_solve(const cs_model *model, cs_state *s) {
    double worst = solve_at_pose(model, s);
    for (int c = 0; c < model->cable_count; c++) /* after Newton, only a broken cable's still to zero */
        if (!s->solver.settled || s->cables[c].status != CS_CABLE_INTACT)
            cs_cable_update_tensions(&model->cables[c], &s->cables[c], NULL);
    s->face_force = cs_face_loaded(model, s) ? cs_face_normal_force_now(model, s, NULL) : 0.0;
    return worst;
}

/* Resultant force and moment (about the CG) of the cables on the vehicle, through the face corners. */
void cs_barrier_force(const cs_model *model, cs_state *s) {
    v3_set(s->force, 0.0, 0.0, 0.0);
    v3_set(s->moment, 0.0, 0.0, 0.0);
    cs_post_place_captured(model, s, s->crush, s->force, s->moment);
    for (int c = 0; c < model->cable_count; c++) {
        cs_cable_state *cs = &s->cables[c];
        if (!cs->engaged || cs->status != CS_CABLE_INTACT) continue;
        for (int i = 1; i + 1 < cs->node_count; i++) {
            if (cs->node[i] != CS_NODE_LEFT && cs->node[i] != CS_NODE_RIGHT) continue;
            double f[3], r[3], t[3];
            cs_node_force(cs, i, NULL, f);
            v3_add(s->force, s->force, f);
            v3_sub(r, cs->pos + 3 * i, s->pos);
            v3_cross(t, r, f);
            v3_add(s->moment, s->moment, t);
        }
    }
}

void cs_barrier_commit(const cs_model *model, cs_state *s) {
    cs_contact_commit(model, s);
    for (int c = 0; c < model->cable_count; c++)
        cs_cable_commit(model, c, s);
    for (int p = 0; p < model->post_count; p++)
        cs_post_commit(model, s, p);
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
double cs_barrier_trial_energy(const cs_model *model, const cs_state *s) {
    cs_state *t = s->trial;
    cs_state_copy(model, t, s);
    t->event_count = model->event_capacity;
    cs_barrier_commit(model, t);
    return cs_barrier_stored_energy(model, t);
}

/* Stored plus dissipated energy of the barrier side; a sudden failure changes it with no work done. */
double cs_barrier_stored_energy(const cs_model *model, const cs_state *s) {
    double e =
        s->e_cable_plastic + s->e_post_plastic + s->e_post_damping + s->e_soil + s->e_crush + s->e_friction;
    for (int c = 0; c < model->cable_count; c++)
        e += cs_cable_stored_energy(&model->cables[c], &s->cables[c]);
    for (int p = 0; p < model->post_count; p++)
        e += cs_post_stored_energy(model, s, p);
    return e;
}
