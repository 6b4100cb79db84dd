/* SPDX-License-Identifier: MIT */
/* Posts: a post tilts about its base by a rotation vector alpha = theta * u (u the horizontal
 * direction its top moves). A cable at height z sits at base + z a(alpha), with the post axis
 *   a = (u sin theta, cos theta)  (post_axis.c).
 * The cables' generalised moment on the post is Q = sum z J^T F, J = da/dalpha (virtual work), and the
 * post resists with an elastic-plastic rotational spring: k (alpha - alpha_p) up to the capacity
 * M_cap, then rotation at constant moment (the plastic hinge of Eqs. 13-20, or the footing rotating
 * in the soil past Eq. 21); past the tilt at which its top reaches grade the ground stops it (a post
 * down keeps its ropes). k is the cantilever of Eqs. 10-11 seen at the load height h in series with
 * the footing's elastic turn in the soil (cs_post_derive below, footing.c).
 * Whichever of post and footing holds the smaller pull at h yields: the post at Zx Fy about its base
 * (M_cap = Zx Fy), or the footing at P(h), turning about a pivot 2/3 of its depth down (M_cap = P(h) (h +
 * 2D/3) about that pivot, which may exceed Zx Fy while the base moment P h stays below it); the work goes
 * to post plastic or soil. Each step the tilt is solved so that Q = resistance, plus the inertial moment of
 * a post with mass (its swing, below); a massless post is in balance at once. */
#include "core/vec3.h"
#include "elements/rows.h"

#include <math.h>
#include <string.h>

/* ---- a post's model from its definition ---- */

/* The length of rail post p carries: half of each span beside it. */
static double rail_reach(const cs_barrier_def *b, int p) {
    double x = b->posts[p].x;
    return 0.5 *
           ((p > 0 ? x - b->posts[p - 1].x : 0.0) + (p + 1 < b->post_count ? b->posts[p + 1].x - x : 0.0));
}

/* Rotational inertia of post p about its pivot: its steel from its top down to grade if it hinges there
 * (pivot 0), the whole post down to the bottom of its embedment, turning with its footing, if the soil
 * yields; and half of each rail span it holds, a point mass at the rail's height. The footing's mass is
 * left out (docs/assumptions.md). */
static double post_inertia(const cs_barrier_def *b, int p, double pivot) {
    const cs_post_def *d = &b->posts[p];
    double above = d->height + pivot, below = pivot > 0.0 ? d->footing.depth - pivot : 0.0;
    double j = d->section.mass_per_length * (above * above * above + below * below * below) / 3.0;
    double reach = rail_reach(b, p);
    for (int r = 0; r < b->rail_count; r++) {
        double lever = b->rails[r].height + pivot;
        j += b->rails[r].mass_per_length * reach * lever * lever;
    }
    return j;
}

/* The mass of post p along its axis: its steel over its height and embedment and half of each rail span
 * it holds (not its footing's concrete: a footing's input does not say whether it is concrete or the post
 * driven in the soil). */
static double post_mass(const cs_barrier_def *b, int p) {
    const cs_post_def *d = &b->posts[p];
    double mass = d->section.mass_per_length * (d->height + d->footing.depth);
    double reach = rail_reach(b, p);
    for (int r = 0; r < b->rail_count; r++)
        mass += b->rails[r].mass_per_length * reach;
    return mass;
}

void cs_post_derive(const cs_barrier_def *b, int p, double load_height, const cs_model *m,
                    cs_post_model *pm) {
    const cs_post_def *d = &b->posts[p];
    pm->x = d->x;
    pm->height = d->height;
    pm->load_height = load_height;
    pm->mp = cs_section_plastic_moment(&d->section);
    pm->footing = d->footing;
    double p_soil = cs_footing_impact_capacity(&d->footing, load_height);
    pm->footing_moment = p_soil * load_height;
    pm->soil_yields = pm->footing_moment < pm->mp;
    /* a post whose footing yields turns about a point 2/3 of the embedment below grade (the paper,
     * "Kinetic energy dissipation due to post pullout"), resisting P(h) at its lever h + 2D/3 */
    pm->pivot = pm->soil_yields ? 2.0 * d->footing.depth / 3.0 : 0.0;
    double lever = load_height + pm->pivot;
    pm->moment_cap = pm->soil_yields ? p_soil * lever : pm->mp;
    /* the solve holds a post's balance to the tolerance of this moment: its strongest rope's
     * strength at that rope's lever, the ropes' own force unit (a post without ropes: its capacity) */
    pm->moment_scale = pm->moment_cap;
    for (int c = 0; c < m->cable_count; c++)
        pm->moment_scale = fmax(pm->moment_scale, m->cables[c].rope.fu * (m->cables[c].z + pm->pivot));
    /* the load point moves by the cantilever's bend (Eqs. 10-11: R h^3 / 3EI) plus the footing's
     * elastic turn in the soil about 2D/3 down (R (h + 2D/3)^2 / k_soil), springs in series; k_rot
     * is that compliance as a rotation about the pivot (lever h + pivot) */
    double soil_lever = load_height + 2.0 * d->footing.depth / 3.0,
           bend = load_height * load_height * load_height / (3.0 * cs_section_flexural_rigidity(&d->section)),
           turn = soil_lever * soil_lever / cs_footing_rotational_stiffness(&d->footing, load_height),
           compliance = bend + turn;
    pm->k_rot = lever * lever / compliance;
    double zeta = (CS_STEEL_DAMPING_RATIO * bend + CS_SOIL_DAMPING_RATIO * turn) / compliance;
    pm->shear_cap = cs_section_shear_capacity(&d->section);
    pm->pullout_cap = cs_footing_pullout_capacity(&d->footing);
    pm->embedment = d->footing.depth;
    pm->pull_stiffness = pm->pullout_cap / CS_SHAFT_MOBILISATION;
    pm->rot_limit = pm->soil_yields ? d->footing.rotation_limit : d->rotation_limit;
    pm->lie_angle = acos(pm->pivot / (d->height + pm->pivot));
    pm->clamped = d->attachment == CS_ATTACH_CLAMPED;
    pm->attach = d->attachment;
    pm->release_force = cs_post_release_force(d);
    pm->lateral_release = cs_post_lateral_release_force(d);
    pm->face_normal = d->face == CS_FACE_PROTECTED ? 1.0 : -1.0;
    pm->inertia = post_inertia(b, p, pm->pivot);
    pm->damping = 2.0 * zeta * sqrt(pm->k_rot * pm->inertia);
    pm->pull_mass = post_mass(b, p);
}

/* Whether the barrier's solve finds post p's tilt (and its pull while it slides out of its footing),
 * Newton and the fallback alike, whatever ropes it carries: a post the ropes have left still swings on its
 * spring and slides on its shaft. Not a struck post (the face moves it), nor one with mass at the instant
 * of a commit (a re-solve after a failure): it cannot move in no time. */
int cs_post_solved(const cs_model *model, const cs_state *s, int p) {
    const cs_post_state *ps = &s->posts[p];
    return cs_post_in_barrier(ps) && !ps->captured && !(model->posts[p].inertia > 0.0 && s->h <= 0.0);
}

/* Post p's cable nodes where a tilt puts them, and its axis' Jacobian into axis if not NULL. */
void cs_post_place_nodes(const cs_model *model, cs_state *s, int p, const double *tilt, double *axis) {
    int left, right, on_path = axis || cs_rail_ties(model, s, p, &left, &right); /* an unknown, or tied */
    for (int k = 0; k < model->cable_count; k++)
        on_path |= s->cables[k].status == CS_CABLE_INTACT && s->cables[k].where[p] > 0;
    if (!on_path) return; /* a post the ropes have left and no rail holds: nothing to place */
    double sn, g, c;
    cs_post_axis_terms(v2_norm(tilt[0], tilt[1]), &sn, &g, &c);
    if (axis) cs_post_axis_jacobian_from(tilt, sn, g, axis);
    double pull = s->posts[p].pull;
    int upright = cs_post_upright(&model->posts[p]);
    if (s->rail_pos && model->rail_count) { /* the rails' points, kept with the tilt and pull they are at */
        for (int r = 0; r < model->rail_count; r++)
            cs_post_attachment_from(model, p, tilt, pull, upright, sn, c, model->rails[r].z,
                                    s->rail_pos + 3 * ((size_t)p * (size_t)model->rail_count + (size_t)r));
        s->rail_tilt[3 * p] = tilt[0], s->rail_tilt[3 * p + 1] = tilt[1], s->rail_tilt[3 * p + 2] = pull;
    }
    for (int k = 0; k < model->cable_count; k++) {
        cs_cable_state *cs = &s->cables[k];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        if (i > 0)
            cs_post_attachment_from(model, p, tilt, pull, upright, sn, c, cs_post_cable_z(model, s, p, k),
                                    cs->pos + 3 * i);
    }
}

void cs_post_resistance(const cs_post_model *pm, const cs_post_state *ps, const double *tilt, double *q) {
    double tr[2] = {pm->k_rot * (tilt[0] - ps->plastic[0]), pm->k_rot * (tilt[1] - ps->plastic[1])};
    double n = v2_norm(tr[0], tr[1]), cap = cs_post_moment_cap(pm, ps);
    double f = n > cap ? cap / n : 1.0;
    q[0] = tr[0] * f, q[1] = tr[1] * f;
}

/* The ground under a post folded down: past the tilt at which its top reaches grade (cs_post_lie_angle) the
 * top bears on the ground, a one-sided stop `Q_g = k_g (|alpha| - lie) u` against the turn, stiff enough that
 * the post's own capacity presses it CS_GROUND_STOP_TURN past (k_g = M_cap / that turn). The ground, not
 * the base, carries it: it is not in the base moment or shear. A struck post never reaches it (it leaves
 * at its rotation limit). */
#define CS_GROUND_STOP_TURN 0.01 /* rad */
static double ground_stiffness(const cs_post_model *pm) {
    return pm->moment_cap / CS_GROUND_STOP_TURN;
}

/* The stop's moment at a tilt (added to q if not NULL), and, if k is not NULL, its derivative (2 x 2,
 * subtracted from k as the residual's); returns its penetration past the lie angle, rad (0 if clear). */
static double ground_stop(const cs_post_model *pm, const cs_post_state *ps, const double *tilt, double *q,
                          double *k) {
    double n = v2_norm(tilt[0], tilt[1]), lie = cs_post_lie_angle(pm, ps);
    if (ps->captured || !(n > lie)) return 0.0;
    double kg = ground_stiffness(pm), u[2] = {tilt[0] / n, tilt[1] / n}, over = n - lie;
    if (q) q[0] += kg * over * u[0], q[1] += kg * over * u[1];
    if (k) { /* d(kg (n - lie) u)/dalpha = kg (u u^T + (1 - lie / n)(I - u u^T)) */
        double a = 1.0 - lie / n;
        k[0] -= kg * (u[0] * u[0] + a * (1.0 - u[0] * u[0]));
        k[1] -= kg * (1.0 - a) * u[0] * u[1];
        k[2] -= kg * (1.0 - a) * u[0] * u[1];
        k[3] -= kg * (u[1] * u[1] + a * (1.0 - u[1] * u[1]));
    }
    return over;
}

/* The swing: a post of inertia J about its pivot (cs_post_derive) goes, over the time h since the last
 * commit, by the HHT-alpha method (elements.h), as a dead-man slides (anchor.c): with Q = Q_cables -
 * Q_resist the net generalised moment,
 *   J a = (1 + alpha) Q(alpha) - alpha Q_c,   alpha = alpha_c + h w_c + h^2 ((1/2 - beta) a_c + beta a),
 * so its residual carries the inertial moment. Second order: a post's lean converges with the step as
 * h^2 (backward Euler's damping, first order, left a plastic lean 5% short at 0.5 ms, RS1's post 7).
 * J / (beta h^2 (1 + alpha)) (about 2e8 N m/rad for 15 kg m^2 at 0.5 ms) dwarfs the slope of the
 * cables' pull that makes a post on its plateau fold (its P-delta), so the residual stays monotone in
 * the tilt and the post swings through where the massless one had no equilibrium near. What the method
 * takes out of the swing, the trapezoid rule's work of Q less the kinetic energy's change, is booked as
 * post damping (commit_swing below; docs/theory.md, "Posts with mass"). */
int cs_post_swings(const cs_post_model *pm, double h) {
    return pm->inertia > 0.0 && h > 0.0 && h < HUGE_VAL; /* not massless, held, or at rest */
}

/* The damper beside the post's elastic spring (a Kelvin-Voigt element in series with the plastic
 * slider): the spring and the damper carry k e + c de/dt, e = alpha - alpha_p the elastic turn, and the
 * slider turns only once that reaches the capacity, so a post folding at its capacity gains nothing
 * from the damper (de/dt = 0 on the plateau) while one ringing on its spring loses `1 - exp(-2 pi zeta /
 * sqrt(1 - zeta^2))` of its swing's amplitude a cycle (about 2 pi zeta), zeta the steel's and the soil's
 * damping by their shares of its compliance (c = 2 zeta sqrt(k J), cs_post_derive). Over the step de/dt is
 * (e - e_c) / h, which is `alpha - alpha_c` while the slider holds, so the trial moment is
 *   k (alpha - alpha_p) + (c / h)(alpha - alpha_c),
 * returned to the capacity as the undamped one. Only a post that swings has it (not a struck one, which
 * the face moves, nor a re-solve in no time). Returns c / h, 0 where there is none. */
static double damper_over_h(const cs_post_model *pm, const cs_post_state *ps, double h) {
    return !ps->captured && cs_post_swings(pm, h) ? pm->damping / h : 0.0;
}

static void damped_trial(const cs_post_model *pm, const cs_post_state *ps, const double *tilt, double h,
                         double *tr) {
    double g = damper_over_h(pm, ps, h);
    for (int k = 0; k < 2; k++)
        tr[k] = pm->k_rot * (tilt[k] - ps->plastic[k]) + g * (tilt[k] - ps->tilt_commit[k]);
}

/* The resistance of a post's spring, damper and slider at a tilt over the step h. */
static void damped_resistance(const cs_post_model *pm, const cs_post_state *ps, const double *tilt, double h,
                              double *q) {
    double tr[2];
    damped_trial(pm, ps, tilt, h, tr);
    double n = v2_norm(tr[0], tr[1]), cap = cs_post_moment_cap(pm, ps);
    double f = n > cap ? cap / n : 1.0;
    q[0] = tr[0] * f, q[1] = tr[1] * f;
}

/* The angular acceleration the step from the last commit to `tilt` over h gives (HHT-alpha). */
static double acceleration_to(const cs_post_state *ps, int k, double tilt, double h) {
    return cs_hht_acceleration(tilt, ps->tilt_commit[k], ps->rate[k], ps->acc[k], h);
}

static void subtract_inertia(const cs_post_model *pm, const cs_post_state *ps, const double *tilt, double h,
                             double *r) {
    if (!cs_post_swings(pm, h)) return;
    for (int k = 0; k < 2; k++)
        r[k] -= cs_hht_inertia(pm->inertia, acceleration_to(ps, k, tilt[k], h), ps->net[k]);
}

/* At a commit: the rate and acceleration the swing ended with, and what the method took out of it: the
 * trapezoid rule's work of the net generalised moment Q (the cables' and rails' less the resistance),
 * (Q_c + Q) . d alpha / 2, less the kinetic energy's change, booked as post damping, as an anchor's
 * (anchor.c). Q is read off the method's own identity, (1 + alpha) Q = J a + alpha Q_c (the solve has
 * balanced it, to its tolerance); at a commit with no time since the last (a failure's re-solve), where
 * the ropes' pull can have changed with no swing, it is evaluated and the acceleration starts again
 * from it, a = Q / J, as at the start of a motion. A captured post is moved by the face (no swing of
 * its own). */
static void commit_swing(const cs_model *model, cs_state *s, int p) {
    const cs_post_model *pm = &model->posts[p];
    cs_post_state *ps = &s->posts[p];
    double *net = ps->net;
    if (ps->captured || pm->inertia <= 0.0) {
        ps->rate[0] = ps->rate[1] = ps->acc[0] = ps->acc[1] = 0.0;
        net[0] = net[1] = 0.0;
    } else if (cs_post_swings(pm, s->h)) {
        double kinetic_before = 0.5 * pm->inertia * (ps->rate[0] * ps->rate[0] + ps->rate[1] * ps->rate[1]),
               work = 0.0;
        for (int k = 0; k < 2; k++) {
            double da = ps->tilt[k] - ps->tilt_commit[k], acc = acceleration_to(ps, k, ps->tilt[k], s->h);
            double q = cs_hht_inertia(pm->inertia, acc, net[k]);
            work += 0.5 * (net[k] + q) * da;
            ps->rate[k] = cs_hht_rate(ps->rate[k], ps->acc[k], acc, s->h);
            ps->acc[k] = acc, net[k] = q;
        }
        double kinetic = 0.5 * pm->inertia * (ps->rate[0] * ps->rate[0] + ps->rate[1] * ps->rate[1]);
        s->e_post_damping += work - (kinetic - kinetic_before);
    } else {
        if (s->h > 0.0) ps->rate[0] = ps->rate[1] = 0.0; /* h infinite, at rest: the rate is 0 */
        cs_post_residual_at(model, s, p, ps->tilt, NULL, NULL, NULL, net);
        ps->acc[0] = net[0] / pm->inertia, ps->acc[1] = net[1] / pm->inertia;
    }
    ps->tilt_commit[0] = ps->tilt[0], ps->tilt_commit[1] = ps->tilt[1];
}

/* Derivative of -(Q_resist + the inertial moment) of post p at its tilt, 2 x 2 row-major: the elastic
 * stiffness and the damper's c / h, or on the cap the radial projection's (its moment turns with the
 * tilt, its size held). */
static void resistance_slope(const cs_model *model, const cs_state *s, int p, double *k) {
    const cs_post_model *pm = &model->posts[p];
    const cs_post_state *ps = &s->posts[p];
    double tr[2], slope = pm->k_rot + damper_over_h(pm, ps, s->h);
    damped_trial(pm, ps, ps->tilt, s->h, tr);
    double n = v2_norm(tr[0], tr[1]), cap = cs_post_moment_cap(pm, ps);
    if (n > cap) {
        double f = cap * slope / n, u[2] = {tr[0] / n, tr[1] / n};
        k[0] = -f * (1.0 - u[0] * u[0]), k[1] = f * u[0] * u[1], k[2] = k[1], k[3] = -f * (1.0 - u[1] * u[1]);
    } else {
        k[0] = k[3] = -slope, k[1] = k[2] = 0.0;
    }
    if (cs_post_swings(pm, s->h)) {
        double inertia = cs_hht_inertia_slope(pm->inertia, s->h);
        k[0] -= inertia, k[3] -= inertia;
    }
    ground_stop(pm, ps, ps->tilt, NULL, k);
}

/* Residual of post p at a tilt, its cable nodes placed there and their tensions current:
 * r = Q_cables - Q_resist - Q_ground, less the swing's inertial moment. */
void cs_post_residual_at(const cs_model *model, const cs_state *s, int p, const double *tilt,
                         const double *chords, const double *axis, const double *rails, double *r) {
    double own[6], q[2] = {0.0, 0.0};
    if (!axis) cs_post_axis_jacobian_at(tilt, own);
    const double *j = axis ? axis : own;
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        if (i < 0) continue;
        double f[3], l = cs_post_arm(model, s, p, cs_post_cable_z(model, s, p, c));
        cs_node_force(cs, i, chords ? chords + 4 * (size_t)c * (size_t)model->max_nodes : NULL, f);
        q[0] += l * (j[0] * f[0] + j[2] * f[1] + j[4] * f[2]);
        q[1] += l * (j[1] * f[0] + j[3] * f[1] + j[5] * f[2]);
    }
    if (rails)
        for (int k = 0; k < 2 * model->rail_count; k++) /* each rail's span ending here, then starting */
            q[0] += rails[2 * k], q[1] += rails[2 * k + 1];
    else
        cs_rail_moment(model, s, p, tilt, j, q);
    double res[2];
    damped_resistance(&model->posts[p], &s->posts[p], tilt, s->h, res);
    ground_stop(&model->posts[p], &s->posts[p], tilt, res, NULL);
    r[0] = q[0] - res[0], r[1] = q[1] - res[1];
    subtract_inertia(&model->posts[p], &s->posts[p], tilt, s->h, r);
}

/* Residual at the state as it stands (nodes placed, tensions current); chords: every cable's (max_nodes
 * spans each), axis: the axis' Jacobian at the post's tilt; NULL forms them. */
static void residual_now(const cs_model *model, const cs_state *s, int p, const double *chords,
                         const double *axis, const double *rails, double *r) {
    cs_post_residual_at(model, s, p, s->posts[p].tilt, chords, axis, rails, r);
}

/* The friction of the edge sliding along a struck post hinged at grade: the face's (cs_vehicle_def
 * face_friction); none on a post whose footing turns, whose struck point stays put on it. */
static double edge_friction(const cs_model *model, const cs_post_model *pm) {
    return cs_post_upright(pm) ? model->vehicle.def.face_friction : 0.0;
}

/* Which way the edge slides along a struck post: up (+1) or down (-1) since the last commit, or as over the
 * last step where it has not moved yet (a step's first pose). */
static double slide_sense(const cs_post_state *ps) {
    return ps->arm > ps->arm_commit ? 1.0 : ps->arm < ps->arm_commit ? -1.0 : ps->sense;
}

/* The moment a plastic turn since the last commit is booked at, q the capacity now. A struck post sliding
 * out has its capacity fall over the step, from that at the last commit's slide to q, while the vehicle
 * pays for the turn at the trapezoid rule's mean of the two (step.c); booked at q alone the turn would
 * lose half the fall times the turn each step (14 J of a 10 kJ slide at 0.5 ms, tests/test_post.c). */
static double turn_moment(const cs_post_model *pm, const cs_post_state *ps, double q) {
    if (!ps->captured || !ps->withdrawing) return q;
    cs_post_state at = *ps;
    cs_post_struck_slide_set(pm, &at, ps->pull_commit);
    return 0.5 * (cs_post_moment_cap(pm, &at) + q);
}

/* A struck post's base shear, its push, and its pull out of the ground: the horizontal push on a post
 * whose footing turns, leaning by theta, has the component push sin(theta) along the post, out of the
 * ground: what pulls a short post out (its skin friction grows as D^2, its lateral capacity more slowly);
 * none up the upright stub of a post hinged at grade (docs/theory.md, "Posts struck by the vehicle"). */
static void struck_loads(const cs_post_model *pm, cs_post_state *ps) {
    ps->shear = ps->push;
    ps->axial = cs_post_upright(pm) ? 0.0 : ps->push * sin(v2_norm(ps->tilt[0], ps->tilt[1]));
}

/* End of step: plastic rotation (radial return) and its work, the damper's work, base shear and axial
 * pull. On the cap the spring and damper carry the capacity q u between them: the elastic turn e solves
 * `k e + (c / h)(e - e_c) = q u`. The damper's work over the step is the trapezoid rule's, `(D_c + D) .
 * (e - e_c) / 2` with D = q - k e, booked as post damping: with the slider's and the spring's it makes up
 * the resistance's share of the swing's trapezoid (commit_swing). */
static int edge_passed(const cs_model *model, const cs_state *s, int p);

void cs_post_commit(const cs_model *model, cs_state *s, int p) {
    cs_post_state *ps = &s->posts[p];
    if (!cs_post_in_barrier(ps)) return;
    const cs_post_model *pm = &model->posts[p];
    double g = damper_over_h(pm, ps, s->h), tr[2],
           was[2] = {ps->tilt_commit[0] - ps->plastic[0], ps->tilt_commit[1] - ps->plastic[1]};
    damped_trial(pm, ps, ps->tilt, s->h, tr);
    commit_swing(model, s, p);
    double n = v2_norm(tr[0], tr[1]), q = cs_post_moment_cap(pm, ps), e[2], d[2];
    if (n > q) { /* radial return to the capacity */
        double u[2] = {tr[0] / n, tr[1] / n};
        for (int k = 0; k < 2; k++)
            e[k] = (q * u[k] + g * was[k]) / (pm->k_rot + g), d[k] = q * u[k] - pm->k_rot * e[k];
        double np[2] = {ps->tilt[0] - e[0], ps->tilt[1] - e[1]};
        double w = turn_moment(pm, ps, q) * v2_norm(np[0] - ps->plastic[0], np[1] - ps->plastic[1]);
        int soil = pm->soil_yields || q < pm->moment_cap; /* a footing coming out turns in the soil */
        if (soil)
            s->e_soil += w;
        else
            s->e_post_plastic += w;
        ps->plastic[0] = np[0], ps->plastic[1] = np[1];
        if (!ps->yielded) {
            ps->yielded = 1;
            ps->status = soil ? CS_POST_SOIL : CS_POST_HINGED;
            cs_event_add(model, s, soil ? CS_EVENT_FOOTING_ROTATION : CS_EVENT_POST_HINGE, CS_ELEMENT_POST, p,
                         q);
        }
    } else {
        for (int k = 0; k < 2; k++)
            e[k] = ps->tilt[k] - ps->plastic[k], d[k] = tr[k] - pm->k_rot * e[k];
    }
    s->e_post_damping +=
        0.5 * ((ps->damper[0] + d[0]) * (e[0] - was[0]) + (ps->damper[1] + d[1]) * (e[1] - was[1]));
    ps->damper[0] = d[0], ps->damper[1] = d[1];
    for (int k = 0; k < 2; k++) /* what the post holds against its ropes: its spring's and damper's */
        ps->moment[k] = pm->k_rot * e[k] + d[k];
    if (ps->captured) {
        /* the edge's friction up a post hinged at grade, mu (M / arm) over the slide: mu M ln(arm /
         * arm_commit), M the moment along the push, the mean of the step's ends (the work
         * cs_post_captured_force took from the vehicle; exact for M steady, as at its capacity) */
        double mu = edge_friction(model, pm);
        if (mu > 0.0 && ps->bearing)
            s->e_friction += mu * 0.5 * (ps->bend_commit + ps->bend) * fabs(log(ps->arm / ps->arm_commit));
        ps->sense = slide_sense(ps);
        ps->arm_commit = ps->arm, ps->bend_commit = ps->bend;
        struck_loads(pm, ps);
        cs_post_struck_slide_commit(model, s, p);
        /* an edge that has passed it does not come back: the face's line swung back over it, or a side's
         * behind the rear, is no edge (edge_passed) */
        if (edge_passed(model, s, p)) ps->passed = 1;
        return;
    }
    cs_post_pull_commit(model, s, p);
    /* base shear from the post's own moment over the load height (what equilibrium allows), so a
     * step the solver left short of equilibrium cannot report a shear it never had */
    ps->shear = v2_norm(ps->moment[0], ps->moment[1]) / (pm->load_height + pm->pivot);
    ps->axial = cs_post_axial_pull(model, s, p); /* the ropes' and rails' pull out of it, as solved */
}

double cs_post_lie_angle(const cs_post_model *pm, const cs_post_state *ps) {
    if (!ps->withdrawing || !cs_post_upright(pm)) return pm->lie_angle;
    double c = (pm->pivot - ps->pull_commit) / (pm->height + pm->pivot);
    return acos(c > -1.0 ? c : -1.0);
}

double cs_post_fold_limit(const cs_post_model *pm, const cs_post_state *ps) {
    if (!ps->captured) return cs_post_lie_angle(pm, ps);
    if (!cs_post_upright(pm)) return pm->rot_limit;
    double c = ps->lever / pm->height; /* hinged at grade: its top down to the edge, which rides over it */
    return fmin(pm->rot_limit, acos(c < 1.0 ? c : 1.0));
}

/* Failure of a post in the barrier: a struck post turned to its rotation limit, base shear, pullout: a
 * struck post at once at its capacity (the bogie tests'), a post the ropes pull out once it has slid all the
 * way out (post_pullout.c; its slide starts here). A post the ropes fold down to grade lies there and keeps
 * them (*post_down*, once). Returns 1 if it failed. */
int cs_post_check_failure(const cs_model *model, cs_state *s, int p) {
    cs_post_state *ps = &s->posts[p];
    if (!cs_post_in_barrier(ps)) return 0;
    const cs_post_model *pm = &model->posts[p];
    double tilt = v2_norm(ps->tilt[0], ps->tilt[1]), cap = cs_post_pull_cap(pm, ps);
    cs_post_status st;
    cs_event_type ev;
    double value;
    if (ps->captured && tilt >= cs_post_fold_limit(pm, ps)) {
        st = CS_POST_FAILED_ROTATION, ev = CS_EVENT_POST_ROTATION_LIMIT, value = tilt;
    } else if (ps->shear >= pm->shear_cap) {
        st = CS_POST_FAILED_SHEAR, ev = CS_EVENT_POST_SHEAR, value = ps->shear;
    } else if (ps->withdrawing && !(cap > 0.0)) {
        st = CS_POST_FAILED_PULLOUT, ev = CS_EVENT_POST_PULLOUT, value = ps->axial;
    } else {
        if (ps->status != CS_POST_DOWN && tilt >= cs_post_fold_limit(pm, ps)) {
            ps->status = CS_POST_DOWN;
            cs_event_add(model, s, CS_EVENT_POST_DOWN, CS_ELEMENT_POST, p, tilt);
        }
        if (ps->captured && !ps->withdrawing && ps->axial >= cap)
            cs_post_struck_slide_start(model, s, p); /* dragged out by the edge from here */
        else
            cs_post_pull_start(model, s, p);
        return 0;
    }
    ps->status = st;
    cs_event_add(model, s, ev, CS_ELEMENT_POST, p, value);
    return 1;
}

/* The elastic energy of the post's spring. */
double cs_post_elastic_energy(const cs_model *model, const cs_state *s, int p) {
    const cs_post_state *ps = &s->posts[p];
    if (!cs_post_in_barrier(ps)) return 0.0;
    /* k |e|^2 / 2 with e the committed elastic turn: within the capacity after a return, except where the
     * capacity fell under a post sliding out and its damper holds the spring's relaxation back */
    double e[2] = {ps->tilt[0] - ps->plastic[0], ps->tilt[1] - ps->plastic[1]};
    double over = ground_stop(&model->posts[p], ps, ps->tilt, NULL, NULL);
    return 0.5 * model->posts[p].k_rot * (e[0] * e[0] + e[1] * e[1]) +
           0.5 * ground_stiffness(&model->posts[p]) * over * over + cs_post_pull_energy(model, s, p);
}

/* The kinetic energy of its swing, at the rate of the last commit. */
double cs_post_kinetic_energy(const cs_model *model, const cs_state *s, int p) {
    const cs_post_state *ps = &s->posts[p];
    if (!cs_post_in_barrier(ps)) return 0.0;
    return 0.5 * model->posts[p].inertia * (ps->rate[0] * ps->rate[0] + ps->rate[1] * ps->rate[1]) +
           cs_post_pull_kinetic_energy(model, s, p);
}

double cs_post_stored_energy(const cs_model *model, const cs_state *s, int p) {
    return cs_post_elastic_energy(model, s, p) + cs_post_kinetic_energy(model, s, p);
}

/* ---- posts struck by the vehicle ----
 * A standing post whose base the face's bottom edge reaches (within its width plus a margin) is
 * struck by the vehicle: it leaves the cable paths and is pushed over at the face's bottom edge. With the
 * face a distance d past the post's base (along the vehicle's heading f), a post hinged at grade leans by
 * theta = atan(d / z) toward f, z the edge's height above the hinge (the edge keeps its height and
 * slides up the post, with the face's friction), until its top comes down to the edge; a post whose
 * footing turns in the soil by theta = asin(d / (zb + pivot)), zb the edge's height at the strike, to its
 * footing's rotation limit (lean_at). Either resists with its moment M (elastic-plastic, as above). A
 * standing post that finds itself inside the body's outline in plan at the sides' bottom (the vehicle at
 * an angle has swept its side over it: the post let its cables go, or the rear swung in) is struck by
 * the nearer side the same way: d is how far the side's bottom edge is past the base along the side's
 * outward normal f, until the rear passes it. Its resistance acts on the vehicle as the gradient of its
 * work (Q . dtilt, and the edge's friction) with respect to the vehicle's pose, so the work the vehicle
 * does is exactly what the post stores and dissipates; along f that is the push (place_one), which also
 * loads the crush when the face pushes. */
#define CS_CAPTURE_MARGIN 0.1 /* m beyond each face corner that still strikes a post */

/* The face at a vehicle pose (pos, quat): the middle of its bottom edge, the heading f (horizontal,
 * unit), the body's left axis, and the edge's height (at least 5 cm). */
static void face_frame(const cs_model *model, const double *pos, const double *quat, double crush,
                       double *origin, double *f, double *left, double *zb) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double x[3], bx[3] = {1.0, 0.0, 0.0}, by[3] = {0.0, 1.0, 0.0};
    double mid[3] = {v->cg_to_front - crush, 0.0, v->face_bottom - v->cg_height};
    quat_rotate(origin, quat, mid);
    v3_add(origin, origin, pos);
    quat_rotate(x, quat, bx);
    x[2] = 0.0;
    double n = v3_norm(x);
    v3_scale(f, x, n > 0.0 ? 1.0 / n : 0.0);
    quat_rotate(left, quat, by);
    *zb = origin[2] > 0.05 ? origin[2] : 0.05;
}

/* The point of the pushing edge's bottom in line with post p, with the vehicle at a pose: where it
 * strikes and pushes the post; and the direction f it pushes (horizontal, unit): the face's heading,
 * or a side's outward normal. */
static void edge_point(const cs_model *model, int p, int pusher, const double *pos, const double *quat,
                       double crush, double *pt, double *f) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double base[3] = {model->posts[p].x, 0.0, 0.0}, rel[3];
    if (pusher == CS_PUSH_FACE) {
        double o[3], left[3], zb;
        face_frame(model, pos, quat, crush, o, f, left, &zb);
        v3_sub(rel, base, o);
        double edge[3] = {v->cg_to_front - crush, v3_dot(rel, left), v->face_bottom - v->cg_height};
        quat_rotate(pt, quat, edge);
    } else {
        double side = pusher == CS_PUSH_LEFT ? 1.0 : -1.0, out[3] = {0.0, side, 0.0}, b[3];
        quat_rotate(f, quat, out);
        f[2] = 0.0;
        double n = v3_norm(f);
        v3_scale(f, f, n > 0.0 ? 1.0 / n : 0.0);
        v3_sub(rel, base, pos);
        quat_unrotate(b, quat, rel);
        double edge[3] = {b[0], side * 0.5 * v->front_width, v->side_bottom - v->cg_height};
        quat_rotate(pt, quat, edge);
    }
    v3_add(pt, pt, pos);
}

/* A struck post's lean for an edge at dr along f (its reach added), zl above the pivot, the post slid out
 * by w. A post hinged at grade: the edge holds its height and slides up the post, tan(theta) = dr / zl,
 * the struck point hypot(dr, zl) from the hinge. A post whose footing turns in the soil: the struck point
 * stays where it was struck on the post, lever + w from the pivot (the slide carries it out), sin(theta) =
 * dr / (lever + w), the bogie tests' reading (docs/theory.md, "Posts struck by the vehicle"). The tilt is
 * theta along f and the permanent set across it (the edge pushes along f only, so it turns no tilt across).
 * Returns theta; *arm gets the struck point's distance from the pivot. */
static double lean_at(const cs_post_model *pm, const cs_post_state *ps, double dr, double zl, double w,
                      const double *f, double *tilt, double *arm) {
    double th;
    if (cs_post_upright(pm)) {
        th = atan2(dr, zl);
        *arm = hypot(dr, zl);
    } else {
        double sn = dr / (ps->lever + w);
        sn = sn < -0.999 ? -0.999 : (sn > 0.999 ? 0.999 : sn);
        th = asin(sn);
        *arm = ps->lever + w;
    }
    double along = ps->plastic[0] * f[0] + ps->plastic[1] * f[1];
    tilt[0] = ps->plastic[0] + (th - along) * f[0];
    tilt[1] = ps->plastic[1] + (th - along) * f[1];
    return th;
}

/* The slide-out balance of a struck post at a slide w, over the shaft's share x^2 (x = 1 - w / D) so that
 * it stays finite as x goes to 0: the push's pull along the post, M tan(theta) / (lever + w) with M its
 * moment along f (the footing's capacity at w), less what the shaft holds, Q0. An edge that has backed
 * off (M <= 0) pushes nothing, so it pulls nothing out, whatever the sign of theta; nor does the edge's
 * horizontal push draw out the upright stub of a post hinged at grade. */
static double slide_balance(const cs_post_model *pm, const cs_post_state *ps, double dr, double w,
                            const double *f) {
    if (cs_post_upright(pm)) return -pm->pullout_cap;
    cs_post_state at = *ps;
    double tilt[2], q[2], x = 1.0 - w / pm->embedment, arm;
    cs_post_struck_slide_set(pm, &at, w);
    double th = lean_at(pm, ps, dr, 0.0, w, f, tilt, &arm);
    cs_post_resistance(pm, &at, tilt, q);
    double m = q[0] * f[0] + q[1] * f[1];
    if (!(m > 0.0)) return -pm->pullout_cap;
    return m * tan(th) / ((ps->lever + w) * x * x) - pm->pullout_cap;
}

/* How far a struck post sliding out has come with the edge at dr: at least the slide of the last commit
 * (it does not go back), and beyond it where the push's pull along the post still exceeds what the shaft
 * holds there, to where they balance. The balance falls as w grows (the shaft and the footing's moment
 * both fall about as x^2, and the lever grows while theta falls: docs/theory.md), so bisection finds that
 * point to round-off; where the pull exceeds the shaft's hold all the way, the post is out (w = D). */
static double struck_slide(const cs_post_model *pm, const cs_post_state *ps, double dr, const double *f) {
    double lo = ps->pull_commit, hi = pm->embedment * (1.0 - 1e-12);
    if (!(slide_balance(pm, ps, dr, lo, f) > 0.0)) return lo;
    if (slide_balance(pm, ps, dr, hi, f) > 0.0) return pm->embedment;
    for (int k = 0; k < 200 && hi - lo > 1e-15 * pm->embedment; k++) {
        double mid = 0.5 * (lo + hi);
        if (slide_balance(pm, ps, dr, mid, f) > 0.0)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* The pushing edge's height above the hinge of a post hinged at grade, whose stub has carried the hinge up
 * by its slide (at least 5 cm). */
static double edge_height(const cs_post_state *ps, const double *pt) {
    return fmax(pt[2] - ps->pull, 0.05);
}

/* Where a captured post leans with the vehicle at a pose: the pushing edge's point in line with it is
 * a distance d past the base along f, and the post turns about its pivot as lean_at has it for d + reach,
 * reach set at the strike so that the post goes on from where it stood (theta < 0: it leaned toward the
 * edge when struck), w its slide out of the footing (struck_slide; the slide at the last commit unless it
 * is sliding out). Returns theta; f gets the direction, and if not NULL, slide the slide, arm the struck
 * point's distance from the pivot and zl the edge's height above a hinge at grade. */
static double captured_lean(const cs_model *model, const cs_post_state *ps, int p, const double *pos,
                            const double *quat, double crush, double *tilt, double *f, double *slide,
                            double *arm, double *zl) {
    double pt[3], rel[3], base[3] = {model->posts[p].x, 0.0, 0.0}, a;
    edge_point(model, p, ps->pusher, pos, quat, crush, pt, f);
    v3_sub(rel, pt, base);
    double dr = v3_dot(rel, f) + ps->reach, z = edge_height(ps, pt);
    double w = ps->withdrawing ? struck_slide(&model->posts[p], ps, dr, f) : ps->pull;
    if (slide) *slide = w;
    if (zl) *zl = z;
    double th = lean_at(&model->posts[p], ps, dr, z, w, f, tilt, &a);
    if (arm) *arm = a;
    return th;
}

/* Whether the edge that struck post p has passed it. A side's edge ends at the rear and at the face
 * (edge_point extends its line): it has passed once the post's base is behind the rear or ahead of the
 * face in the body frame. The face's edge ends at its corners: it has passed once the post, at the edge's
 * height, is further to the side than a corner by more than the margin that struck it (cs_post_capture). */
static int edge_passed(const cs_model *model, const cs_state *s, int p) {
    const cs_post_state *ps = &s->posts[p];
    const cs_vehicle_def *v = &model->vehicle.def;
    if (ps->pusher == CS_PUSH_FACE) {
        double o[3], f[3], left[3], zb, at[3], rel[3];
        face_frame(model, s->pos, s->quat, s->crush, o, f, left, &zb);
        cs_post_attachment(model, p, ps->tilt, ps->pull, cs_post_upright(&model->posts[p]), zb, at);
        v3_sub(rel, o, at);
        return fabs(v3_dot(rel, left)) > 0.5 * v->front_width + CS_CAPTURE_MARGIN;
    }
    double rel[3], b[3], base[3] = {model->posts[p].x, 0.0, 0.0};
    v3_sub(rel, base, s->pos);
    quat_unrotate(b, s->quat, rel);
    return b[0] < -v->cg_to_rear || b[0] > v->cg_to_front - s->crush;
}

/* Place captured post p for a crush; returns its push along the vehicle's heading if the face pushes it:
 * the normal force M / arm along f, cos(theta) + mu sin(theta) of it with the edge's friction up the post
 * (hinged at grade; the footing turning, M / (arm cos(theta)), the work's gradient along f). */
static double place_one(const cs_model *model, cs_state *s, int p, double crush) {
    cs_post_state *ps = &s->posts[p];
    const cs_post_model *pm = &model->posts[p];
    double q[2], f[3], w, arm, zl;
    double th = captured_lean(model, ps, p, s->pos, s->quat, crush, ps->tilt, f, &w, &arm, &zl);
    if (ps->withdrawing) cs_post_struck_slide_set(pm, ps, w);
    ps->arm = arm;
    cs_post_resistance(pm, ps, ps->tilt, q);
    double m = q[0] * f[0] + q[1] * f[1];
    ps->bearing = m >= 0.0 && !ps->passed && !edge_passed(model, s, p);
    ps->bend = ps->bearing ? m : 0.0;
    /* the edge's height over a hinge at grade, while it bears: where it rides over the post (the edge's
     * line taken on past the vehicle, or backed off, is no edge) */
    if (ps->bearing && cs_post_upright(pm)) ps->lever = zl;
    if (!ps->bearing) { /* the edge has backed off or passed it: the post stands at its set, free */
        ps->tilt[0] = ps->plastic[0], ps->tilt[1] = ps->plastic[1];
        ps->push = 0.0;
        return 0.0;
    }
    ps->push = cs_post_upright(pm)
                   ? m / arm * (cos(th) + edge_friction(model, pm) * slide_sense(ps) * sin(th))
                   : m / (arm * cos(th));
    return ps->pusher == CS_PUSH_FACE ? ps->push : 0.0;
}

double cs_post_place_captured(const cs_model *model, cs_state *s, double crush) {
    double total = 0.0;
    for (int p = 0; p < model->post_count; p++) {
        cs_post_state *ps = &s->posts[p];
        if (!ps->captured || !cs_post_in_barrier(ps)) continue;
        if (ps->waiting) { /* placed at its strike; it pushes from the step's end */
            ps->push = 0.0;
            continue;
        }
        total += place_one(model, s, p, crush);
    }
    return total;
}

/* The captured posts' resistance (as placed for this crush) on the vehicle, added to force and moment:
 * the gradient of the work Q . dtilt + R dw + mu N |ds| (R the shaft's hold as a post slides out; mu N the
 * friction of the edge sliding along a post hinged at grade by ds, N = M / arm its normal force, in the
 * sense of slide_sense) with respect to the vehicle's pose (central differences, 1e-6 m and
 * 1e-6 rad), so that the vehicle's work is exactly what the posts store and dissipate however the face
 * moves (pushing on, coming down, rolling, sliding along its edge). */
void cs_post_captured_force(const cs_model *model, const cs_state *s, double crush, int face_only,
                            double *force, double *moment) {
    for (int p = 0; p < model->post_count; p++) {
        const cs_post_state *ps = &s->posts[p];
        if (!ps->captured || !cs_post_in_barrier(ps) || !(ps->push > 0.0)) continue;
        if (face_only && ps->pusher != CS_PUSH_FACE) continue;
        const cs_post_model *pm = &model->posts[p];
        double q[2], hold = ps->withdrawing ? cs_post_struck_slide_cap(pm, ps->pull) : 0.0;
        cs_post_resistance(pm, ps, ps->tilt, q);
        double slip = edge_friction(model, pm) * ps->bend / ps->arm * slide_sense(ps);
        const double h = 1e-6;
        for (int k = 0; k < 6; k++) {
            double tp[2], tm[2], qp[4], qm[4], pos[3], turn[3] = {0.0, 0.0, 0.0}, w[3], fk[3], sp = 0.0,
                                                       sm = 0.0, ap = 0.0, am = 0.0;
            memcpy(qp, s->quat, sizeof qp), memcpy(qm, s->quat, sizeof qm);
            v3_copy(pos, s->pos);
            if (k < 3) {
                pos[k] += h;
                captured_lean(model, ps, p, pos, s->quat, crush, tp, fk, &sp, &ap, NULL);
                pos[k] -= 2.0 * h;
                captured_lean(model, ps, p, pos, s->quat, crush, tm, fk, &sm, &am, NULL);
            } else { /* a turn about world axis k - 3, applied in the body frame */
                turn[k - 3] = 1.0;
                quat_unrotate(w, s->quat, turn);
                quat_integrate(qp, w, h);
                quat_integrate(qm, w, -h);
                captured_lean(model, ps, p, pos, qp, crush, tp, fk, &sp, &ap, NULL);
                captured_lean(model, ps, p, pos, qm, crush, tm, fk, &sm, &am, NULL);
            }
            double g =
                -(q[0] * (tp[0] - tm[0]) + q[1] * (tp[1] - tm[1]) + hold * (sp - sm) + slip * (ap - am)) /
                (2.0 * h);
            if (k < 3)
                force[k] += g;
            else
                moment[k - 3] += g;
        }
    }
}

/* Post p struck by `pusher`: off the cable paths, its lever where the edge strikes it. Its swing ends
 * there: the kinetic energy it had leaves the barrier's stored energy at the strike, where the caller
 * books the drop as released. */
static void capture(const cs_model *model, cs_state *s, int p, int pusher, int waiting) {
    cs_post_state *ps = &s->posts[p];
    cs_post_struck_slide_take(model, s, p);
    ps->rate[0] = ps->rate[1] = ps->acc[0] = ps->acc[1] = ps->damper[0] = ps->damper[1] = 0.0;
    ps->captured = 1, ps->passed = 0;
    ps->waiting = waiting;
    ps->bearing = 1;
    ps->pusher = pusher;
    double pt[3], f[3];
    edge_point(model, p, pusher, s->pos, s->quat, s->crush, pt, f);
    /* the edge's height above the pivot: above the hinge a post hinged at grade carries up with its stub as
     * it slides (edge_height); for a post turning in the soil, where it strikes it (at least 5 cm above
     * grade) less the slide, which carries the struck point out with it (lean_at) */
    const cs_post_model *pm = &model->posts[p];
    double zb = pt[2] > 0.05 ? pt[2] : 0.05;
    ps->lever = cs_post_upright(pm) ? edge_height(ps, pt) : zb + pm->pivot - ps->pull;
    double rel[3], base[3] = {pm->x, 0.0, 0.0}, lean = ps->tilt[0] * f[0] + ps->tilt[1] * f[1];
    v3_sub(rel, pt, base);
    ps->reach =
        (cs_post_upright(pm) ? ps->lever * tan(lean) : (ps->lever + ps->pull) * sin(lean)) - v3_dot(rel, f);
    /* where the edge holds it now: a post sliding out takes the slide the push balances at once */
    place_one(model, s, p, s->crush);
    ps->arm_commit = ps->arm, ps->bend_commit = ps->bend, ps->sense = 1.0;
    if (waiting) ps->push = 0.0;
    if (!s->contact_started) {
        s->contact_started = 1;
        s->summary.first_contact_time_s = s->t;
    }
    for (int c = 0; c < model->cable_count; c++) { /* it leaves their paths: each let go, an event */
        cs_cable_state *cs = &s->cables[c];
        if (cs->status != CS_CABLE_INTACT || cs->where[p] <= 0) continue;
        double f[3];
        cs_node_force(cs, cs->where[p], NULL, f);
        cs_cable_remove_node(cs, cs->where[p]);
        cs_event *e = cs_event_add(model, s, CS_EVENT_CABLE_STRUCK_OFF, CS_ELEMENT_POST, p, v3_norm(f));
        if (e) e->cable = c;
    }
}

/* Whether a post at b in the body frame, past_face behind the face and in_side in from the nearer side,
 * came within the face's corner margin of the side after the face passed it (cs_post_capture). */
static int came_in_across_side(const cs_state *s, const double b[3], double past_face, double in_side) {
    double rate[3], spin[3]; /* the post moves in the body frame at -(R^T v + omega x b) */
    quat_unrotate(rate, s->quat, s->vel);
    v3_cross(spin, s->omega, b);
    double vf = fmax(rate[0] + spin[0], 0.0),
           vs = fmax((b[1] >= 0.0 ? 1.0 : -1.0) * (rate[1] + spin[1]), 0.0);
    if (vf == 0.0 && vs == 0.0) vf = vs = 1.0;
    return (in_side + CS_CAPTURE_MARGIN) * vf < past_face * vs;
}

/* Capture the standing posts the face has reached, and those a side has swept over: a post an edge has
 * passed (edge_passed) stands free at its set and is struck afresh by the next edge. A post inside the
 * outline near a front corner is inside both the face and a side. The face strikes what it passes within
 * CS_CAPTURE_MARGIN of its corners, so the side struck it only if it came within that margin of the side
 * after the face passed it: it did if, at the rates at which the post moves into the outline in the body
 * frame (v_f behind the face, v_s in from the side: the body's velocity and turn, the post held),
 * (in_side + margin) v_f < past_face v_s; or if it is further behind the face than the face's reach.
 * A body at rest takes v_f = v_s. Which edge strikes must not depend on the step's length, nor on the sign
 * of a round-off (a post on a corner's line, as an impact at a corner puts it: the face).
 * waiting: struck at a step's new pose before its solve, a post pushes nothing until the step's end
 * (cs_post_end_waiting), as a failure's change does (step.c). Returns 1 if any was captured. */
int cs_post_capture(const cs_model *model, cs_state *s, int waiting) {
    const cs_vehicle_def *v = &model->vehicle.def;
    double o[3], f[3], left[3], zb;
    face_frame(model, s->pos, s->quat, s->crush, o, f, left, &zb);
    int any = 0;
    for (int p = 0; p < model->post_count; p++) {
        cs_post_state *ps = &s->posts[p];
        if ((ps->captured && !ps->passed) || !cs_post_in_barrier(ps)) continue;
        double top[3], rel[3], b[3];
        int upright = cs_post_upright(&model->posts[p]);
        cs_post_attachment(model, p, ps->tilt, ps->pull, upright, zb, top);
        v3_sub(rel, o, top);
        double d = v3_dot(rel, f), lat = v3_dot(rel, left);
        int face = d >= 0.0 && fabs(lat) <= 0.5 * v->front_width + CS_CAPTURE_MARGIN && d <= zb;
        /* the post at the sides' bottom height, in the body frame: inside the outline by `past_face`
         * behind the face and `in_side` within the nearer side */
        double zs = v->side_bottom - v->cg_height, lo[3] = {0.0, 0.0, zs}, wl[3];
        quat_rotate(wl, s->quat, lo);
        cs_post_attachment(model, p, ps->tilt, ps->pull, upright, s->pos[2] + wl[2], top);
        v3_sub(rel, top, s->pos);
        quat_unrotate(b, s->quat, rel);
        double past_face = v->cg_to_front - s->crush - b[0], in_side = 0.5 * v->front_width - fabs(b[1]);
        int side = b[0] > -v->cg_to_rear && past_face > 0.0 && in_side > 0.0 &&
                   (past_face > zb || came_in_across_side(s, b, past_face, in_side));
        if (side) {
            capture(model, s, p, b[1] >= 0.0 ? CS_PUSH_LEFT : CS_PUSH_RIGHT, waiting);
            any = 1;
        } else if (face) {
            capture(model, s, p, CS_PUSH_FACE, waiting);
            any = 1;
        }
    }
    return any;
}

int cs_post_end_waiting(const cs_model *model, cs_state *s) {
    int any = 0;
    for (int p = 0; p < model->post_count; p++) {
        cs_post_state *ps = &s->posts[p];
        if (!ps->waiting) continue;
        ps->waiting = 0, any = 1;
        place_one(model, s, p, s->crush); /* at the crush solved; its push's shear and pull, as a commit's */
        ps->arm_commit = ps->arm, ps->bend_commit = ps->bend;
        struck_loads(&model->posts[p], ps);
    }
    return any;
}

/* ---- the post's rows of the barrier solve ----
 * Unknowns: the tilt alpha (2) (and, sliding out, the pull w: post_pullout.c, whose column the arms
 * z + d_p + w depend on where it slides along its axis). Rows: Q_cables(alpha) - Q_resist(alpha) - J (alpha -
 * alpha_c - h w_c) / h^2, in units of the post's moment_scale (its strongest rope's strength at that rope's
 * lever, cs_post_derive), so that one tolerance is one force everywhere. */
static void residual(const cs_model *model, const cs_state *s, const cs_rows *rows, const cs_slot *u,
                     double *r) {
    double q[2];
    residual_now(model, s, u->a, rows->chords, rows->axes + 18 * u->a,
                 rows->rails + 4 * (size_t)u->a * (size_t)model->rail_count, q);
    double inv = 1.0 / model->posts[u->a].moment_scale;
    r[0] = q[0] * inv, r[1] = q[1] * inv;
}

/* A post's two rows: Q = sum over its cables of l_c J(alpha)^T f_c, less resistance and inertia. */
static void jacobian(const cs_model *model, const cs_state *s, const cs_rows *rows, int row,
                     const cs_slot *u) {
    int p = u->a;
    const double *ja = rows->axes + 18 * p, *dj = ja + 6;
    double kr[4], unit = model->posts[p].moment_scale; /* as residual */
    resistance_slope(model, s, p, kr);
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            cs_rows_add(rows, row + a, row + b, kr[2 * a + b] / unit);
    int pc = cs_post_upright(&model->posts[p]) ? -1 : rows->pull_index[p]; /* the arms grow with w */
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        int i = cs->status == CS_CABLE_INTACT ? cs->where[p] : -1;
        if (i < 0) continue;
        const cs_span_grad *sp = cs_rows_spans(model, rows, c, i);
        double l = cs_post_arm(model, s, p, cs_post_cable_z(model, s, p, c)), f[3];
        cs_node_force(cs, i, cs_rows_chords(model, rows, c), f);
        for (int a = 0; a < 2; a++) {
            if (pc >= 0) /* the arm growing as the post slides out */
                cs_rows_add(rows, row + a, pc, (ja[a] * f[0] + ja[2 + a] * f[1] + ja[4 + a] * f[2]) / unit);
            double rho[3] = {l * ja[a] / unit, l * ja[2 + a] / unit, l * ja[4 + a] / unit};
            double gp[3][3] = {{0}}, gm[3] = {0};
            cs_rows_force_gradient(sp, rho, gp, gm);
            cs_rows_add_node_gradient(model, s, rows, row + a, c, i, gp, gm);
            for (int b = 0; b < 2; b++) /* the axis turning under the pull */
                cs_rows_add(rows, row + a, row + b,
                            l * (dj[6 * b + a] * f[0] + dj[6 * b + 2 + a] * f[1] + dj[6 * b + 4 + a] * f[2]) /
                                unit);
        }
    }
    cs_rail_jacobian(model, s, rows, row, p, unit);
}

const cs_row_kind cs_post_rows = {2, residual, jacobian};
