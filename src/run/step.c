/* SPDX-License-Identifier: MIT */
/* The start of a run (the vehicle placed, the barrier as installed), one time step as named stages, and
 * the run loop. */
#include "core/vec3.h"
#include "run/run.h"
#include "run/sized.h"
#include "solver/work.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Rope laid in along the cable's path as it stands, every span at the pretension, its sag included
 * (s = l / (1 + T0 / EA) for a weightless rope). */
static void lay_in_pretension(const cs_model *model, int c, cs_cable_state *cs) {
    const cs_cable_model *cm = &model->cables[c];
    cs->m[0] = 0.0;
    for (int i = 0; i + 1 < cs->node_count; i++) {
        cs->m[i + 1] = cs->m[i] + cs_span_material_at(cm, cs, i, cm->pretension);
        cs->ep[i] = 0.0;
    }
    memcpy(cs->m_commit, cs->m, (size_t)cs->node_count * sizeof *cs->m);
    cs_cable_update_tensions(cm, cs, NULL);
}

/* A cable at t = 0: start anchor, every post, end anchor, straight at its height, rope laid in with
 * the pretension. */
static void reset_cable(const cs_model *model, int c, cs_cable_state *cs) {
    const cs_cable_model *cm = &model->cables[c];
    cs->status = CS_CABLE_INTACT;
    cs->engaged = 0;
    cs->passed = 0;
    cs->handover = cs->passing = 0;
    cs->node_count = model->post_count + 2;
    cs->node[0] = CS_NODE_START;
    v3_set(cs->pos, model->anchors[0].x, 0.0, model->anchors[0].z);
    for (int p = 0; p < model->post_count; p++) {
        cs->node[p + 1] = p;
        cs->where[p] = p + 1;
        v3_set(cs->pos + 3 * (p + 1), model->posts[p].x, 0.0, cm->z);
    }
    int last = cs->node_count - 1;
    cs->node[last] = CS_NODE_END;
    v3_set(cs->pos + 3 * last, model->anchors[1].x, 0.0, model->anchors[1].z);
    lay_in_pretension(model, c, cs);
    cs->max_tension_seen = cm->pretension;
    cs->max_tension_time = 0.0;
    cs->work_on_vehicle = 0.0;
    for (int k = 0; k < 6; k++)
        cs->push[k] = 0.0;
    cs->max_strain = cm->pretension / cm->rope.ea;
    cs->end_load = 0.0;
    cs->slip[0] = cs->slip[1] = 0.0;
    cs->slipping[0] = cs->slipping[1] = 0;
    for (int k = 0; k < CS_CORNERS; k++)
        cs->corner_z[k] = cs->corner_z_commit[k] = 0.0;
}

/* The barrier as installed, before the vehicle reaches it, as an installer tensions a rope on standing
 * posts: every span at the pretension, the posts leaning until each balances those tensions along its
 * spans' chords (settle.c: one Newton solve over every post's tilt), the rope laid in at the pretension
 * on that path, and the barrier solved and committed there at rest (h infinite: posts with mass settle
 * as massless ones). Each post sits in balance and every support sticks with equal tensions, so the
 * solve finds the laid-in state. Laying the rope in on the straight path and letting the posts settle
 * instead leaves the spans next to an end post 4-5% off the pretension (it leans toward the barrier, the
 * rope slides over it at the capstan limit), and re-laying it there and settling again creeps toward the
 * balance by about 1/60 a round (the rope is about 60 times stiffer than the post). What settling
 * dissipates belongs to the installation. */
static void settle_barrier(const cs_model *model, cs_state *s) {
    cs_contact_update(model, s);
    for (int c = 0; c < model->cable_count; c++)
        cs_cable_hold_tension(&s->cables[c], model->cables[c].pretension);
    s->h = HUGE_VAL;
    cs_settle_posts(model, s);
    cs_anchor_settle(model, s);
    for (int c = 0; c < model->cable_count; c++)
        lay_in_pretension(model, c, &s->cables[c]);
    cs_barrier_solve(model, s);
    cs_barrier_commit(model, s);
    s->e_cable_plastic = s->e_post_plastic = s->e_post_damping = s->e_soil = s->e_crush = s->e_friction = 0.0;
    s->e_rail_plastic = 0.0;
}

void cs_state_reset(const cs_model *model, cs_state *s) {
    s->t = 0.0;
    s->step = 0;
    s->outcome = CS_RUNNING;
    s->frozen = 0;
    v3_copy(s->pos, model->start_pos);
    v3_scale(s->vel, model->dir, model->scenario.speed);
    quat_from_yaw(s->quat, model->start_yaw);
    v3_set(s->omega, 0.0, 0.0, 0.0);
    v3_set(s->acc, 0.0, 0.0, 0.0);
    v3_set(s->ang_acc, 0.0, 0.0, 0.0);
    s->tyre_power = 0.0;
    v3_set(s->force, 0.0, 0.0, 0.0);
    v3_set(s->moment, 0.0, 0.0, 0.0);
    s->crush = s->crush_max = s->crush_committed = s->crush_force_committed = s->face_force = 0.0;
    s->contact_started = 0;
    for (int c = 0; c < model->cable_count; c++)
        reset_cable(model, c, &s->cables[c]);
    memset(s->posts, 0, (size_t)model->post_count * sizeof *s->posts);
    cs_system_reset(&s->work->sys);
    memset(&s->work->count, 0, sizeof s->work->count);
    memset(s->anchors, 0, sizeof s->anchors);
    memset(s->rail_plastic, 0,
           (size_t)model->rail_count * (size_t)model->post_count * sizeof *s->rail_plastic);
    for (int k = 0; k < 3 * model->post_count; k++)
        s->rail_tilt[k] = NAN; /* no rail point placed yet */
    s->e_rail_plastic = s->e_rail_elastic = 0.0;
    s->e_cable_plastic = s->e_post_plastic = s->e_post_damping = s->e_soil = s->e_crush = s->e_friction =
        s->e_released = s->e_tyre = 0.0;
    s->event_count = 0;
    s->speed_ring[0] = v3_dot(s->vel, model->dir); /* the speed the run starts with, at step 0 */
    s->ring_fill = 1;
    s->decel_50ms_g = 0.0;
    cs_loss_scan_start(&s->loss, s->loss_ring, s->loss_ring + model->loss_steps, model->loss_steps,
                       model->scenario.dt);
    s->work->solver_residual = 0.0;
    memset(&s->summary, 0, sizeof s->summary);
    s->summary.first_contact_time_s = -1.0;
    s->summary.stop_time_s = -1.0;
    s->summary.exit_speed_mps = -1.0;
    s->summary.exit_time_s = -1.0;
    s->exit_pending = 0;

    cs_vehicle_start(model, s);
    settle_barrier(model, s);
    s->e_initial_potential_ref = cs_vehicle_potential_energy(model, s);
    s->e_initial_kinetic = cs_vehicle_kinetic_energy(model, s);
    s->e_initial_total = 0.0;
    cs_energy_update(model, s);
    s->e_initial_total = cs_energy_total(&s->energy);
    cs_energy_update(model, s);
    s->summary.energy_balance_error = 0.0;
    s->summary.initial_kinetic_energy_j = s->e_initial_kinetic;
    s->summary.max_cable_tension_n = 0.0;
    s->summary.cable_count = model->cable_count;
    cs_summary_cables(model, s, &s->summary);
    s->work->stored_committed = cs_barrier_stored_energy(model, s);
}

/* Breaks, post failures, anchor pullouts and posts struck by the face, found after a commit, change the
 * barrier's topology with no work done on it: re-solve at the same vehicle pose until nothing more
 * changes, and book the stored energy that vanished (massless cable snapping, posts letting go, a
 * struck post leaving the ropes' paths) as released. */
static double resolve_failures(const cs_model *model, cs_state *s, int *changed) {
    /* what is released is the whole drop across the failures, whatever the loop booked on its way
     * (contact.c: the sag's reference of corners let go) */
    double before = cs_barrier_stored_energy(model, s), released = s->e_released;
    double worst = 0.0;
    *changed = 0;
    for (int round = 0; round <= model->cable_count + model->post_count + 2; round++) {
        int any = 0;
        for (int c = 0; c < model->cable_count; c++)
            any |= cs_cable_check_break(model, c, s) | cs_termination_check_post(model, c, s);
        for (int p = 0; p < model->post_count; p++)
            any |= cs_post_check_failure(model, s, p) | cs_attachment_check_release(model, s, p);
        any |= cs_anchor_check(model, s);
        any |= cs_post_capture(model, s, 0);
        any |= cs_contact_check_slip(model, s);
        if (!any) break;
        *changed = 1;
        cs_contact_drop_failed(model, s);
        cs_contact_update(model, s);
        worst = fmax(worst, cs_barrier_solve(model, s));
        cs_barrier_commit(model, s);
    }
    if (*changed) {
        s->e_released = released + before - cs_barrier_stored_energy(model, s);
        cs_system_jumped(&s->work->sys, s->step); /* the next step extrapolates no failure's jump */
    }
    return worst;
}

/* The barrier's side of the ledger: what it stores, has dissipated and has released. */
static double barrier_energy(const cs_model *model, const cs_state *s) {
    return cs_barrier_stored_energy(model, s) + s->e_released;
}

/* A pose of the vehicle and the barrier's force and moment on it there. */
typedef struct loaded_pose {
    double pos[3], quat[4], force[3], moment[3];
} loaded_pose;

static loaded_pose pose_of(const cs_state *s) {
    loaded_pose p;
    v3_copy(p.pos, s->pos), v3_copy(p.force, s->force), v3_copy(p.moment, s->moment);
    memcpy(p.quat, s->quat, sizeof p.quat);
    return p;
}

/* The work the vehicle does on the barrier from pose a to pose b: the trapezoid rule on the barrier's
 * force and moment, the rule by which the vehicle's own energy changes over a step. */
static double work_on_barrier(const loaded_pose *a, const loaded_pose *b) {
    double dx[3], turn[3], w = 0.0;
    v3_sub(dx, b->pos, a->pos);
    quat_turn(turn, a->quat, b->quat);
    for (int i = 0; i < 3; i++)
        w -= 0.5 * ((a->force[i] + b->force[i]) * dx[i] + (a->moment[i] + b->moment[i]) * turn[i]);
    return w;
}

/* Each rope's share of it, with the sign turned: the work the rope does on the vehicle, added to its cable's
 * work_on_vehicle (from: each cable's push at pose a, force and moment; at b, its push now). The rule is
 * linear in the force, so the cables' shares and the struck posts' make the whole. */
static void book_cable_work(const cs_model *model, cs_state *s, const loaded_pose *a, const loaded_pose *b,
                            const double (*from)[6]) {
    for (int c = 0; c < model->cable_count; c++) {
        loaded_pose ca = *a, cb = *b;
        v3_copy(ca.force, from[c]), v3_copy(ca.moment, from[c] + 3);
        v3_copy(cb.force, s->cables[c].push), v3_copy(cb.moment, s->cables[c].push + 3);
        double w = work_on_barrier(&ca, &cb);
        s->cables[c].work_on_vehicle -= w;
    }
}

/* Stages 2-5 at the vehicle's pose as it stands. A solve that ends further than CS_PATH_TRIGGER from
 * equilibrium is not committed unless told to (its slides and plastic flow would be booked from a state
 * that is not one). Nor at all, and -1 returned, if (with `allowed` given) it ends above the solver
 * tolerance where a commit would leave the barrier holding (stored and dissipated) more than `allowed`
 * plus the work done on it from `from`: an iterate the path does not reach, which the next solve must
 * not start from. A solve that met the tolerance is an equilibrium, and is committed, unless its commit
 * would hold more than that by CS_LEDGER_FAILURE of the energy scale, which no step of a run may make: an
 * equilibrium on a branch the path never reached (a rope stretched to its strength with no work done on
 * it), sent back as a failed one is. Returns 1 if it committed, with the largest residual of the solves
 * it committed kept in s->work->solver_residual, the barrier's push at the pose as committed in `end`
 * (before any failure found there) and whether a failure then changed the barrier in *failed. */
#define CS_PATH_TRIGGER 1e-2
/* Rides of the slots and solves in turn, at most, until the rides end: a ride lengthens the posts' arms,
 * the solve leans them further, and that rides the cables on, so the turns close on the balance of both
 * slowly; what is left after them rides at the next step. A ride starts only from a solve within
 * CS_PATH_TRIGGER of equilibrium: the pulls of an iterate the path does not commit are not the ropes'. */
#define CS_RIDE_ROUNDS 40

static int follow_pose(const cs_model *model, cs_state *s, int commit_anyway, double allowed,
                       const loaded_pose *from, loaded_pose *end, int *failed) {
    double before = cs_barrier_stored_energy(model, s); /* 2. posts the vehicle has reached are struck */
    if (cs_post_capture(model, s, 1)) /* kept until the gap of the stretch it falls in is booked */
        s->work->struck = 1, s->e_released += before - cs_barrier_stored_energy(model, s);
    cs_contact_update(model, s);               /* cables wrap onto or leave the face, or slip past it */
    double worst = cs_barrier_solve(model, s); /* 3. posts, sliding and crush in equilibrium */
    for (int round = 0; round < CS_RIDE_ROUNDS && worst <= CS_PATH_TRIGGER; round++) { /* slots ride */
        int rode = 0;
        for (int p = 0; p < model->post_count; p++)
            rode |= cs_attachment_ride(model, s, p);
        if (!rode) break;
        s->work->rode = 1, worst = cs_barrier_solve(model, s); /* settled around them (book_gap) */
    }
    if (allowed < HUGE_VAL) { /* the work done on it here */
        cs_barrier_force(model, s);
        loaded_pose to = pose_of(s);
        double excess = cs_barrier_trial_energy(model, s, s->work) - allowed - work_on_barrier(from, &to);
        double wild =
            worst > model->scenario.solver_tolerance ? 0.0 : CS_LEDGER_FAILURE * cs_energy_scale(model, s);
        if (excess > wild) return -1;
    }
    if (worst > CS_PATH_TRIGGER && !commit_anyway) return 0;
    cs_barrier_commit(model, s); /* 4. plastic flow, friction and crush work */
    cs_barrier_force(model, s);
    *end = pose_of(s);
    before = cs_barrier_stored_energy(model, s); /* the posts struck in 2 push from here, as a failure */
    int struck = cs_post_end_waiting(model, s);
    if (struck) s->e_released += before - cs_barrier_stored_energy(model, s);
    worst = fmax(worst, resolve_failures(model, s, failed)); /* 5. breaks, failures, posts struck */
    *failed |= struck;
    s->work->solver_residual = fmax(s->work->solver_residual, worst);
    return 1;
}

/* Stages 1-6 over a time h: the vehicle drifts, the barrier follows its pose (committed if its solve
 * converged, or if told to), pushes back, and the vehicle takes the second kick. Adds the vehicle's
 * work on the barrier to *work; returns 1 if the barrier was committed. A failed solve that would hold
 * more than `allowed` puts the barrier back to `last` (its last commit) before it pushes; the vehicle
 * goes on. */
static int advance(const cs_model *model, cs_state *s, double h, int commit_anyway, double allowed,
                   const cs_state *last, double *work) {
    loaded_pose from = pose_of(s), to;
    double pushes[CS_MAX_CABLES_PER_POST][6];
    for (int c = 0; c < model->cable_count; c++)
        memcpy(pushes[c], s->cables[c].push, sizeof pushes[c]);
    s->h += h;                  /* the posts swing over the time since the last commit */
    cs_vehicle_integrate(s, h); /* 1. half a kick and a drift */
    int failed = 0, committed = follow_pose(model, s, commit_anyway, allowed, &from, &to, &failed);
    if (committed < 0) { /* the barrier as last committed, the time since then kept */
        double since = s->h;
        cs_state_restore_barrier(model, s, last), committed = 0;
        s->h = since;
    }
    if (!committed) cs_barrier_force(model, s), to = pose_of(s); /* 6. the barrier's push */
    v3_copy(s->force, to.force), v3_copy(s->moment, to.moment);
    *work += work_on_barrier(&from, &to);
    book_cable_work(model, s, &from, &to, (const double(*)[6])pushes);
    cs_vehicle_finish(model, s, h); /* the second half kick */
    if (failed) {                   /* the next step starts from the push the failures left */
        cs_barrier_force(model, s);
        cs_vehicle_push_changed(model, s, to.force, to.moment);
    }
    return committed;
}

/* What the barrier took in less than the work done on it since it held e0; a gap above `snap` is
 * booked as released (the barrier snapped to a lower equilibrium: a jump, as a failure's). */
static double book_gap(const cs_model *model, cs_state *s, double work, double e0, double snap) {
    double gap = work - (barrier_energy(model, s) - e0);
    /* a post struck in stage 2 leaves the ropes' paths before the solve: their relaxation to the
     * equilibrium without it is a jump of its own, whatever its size, released; slotted cables that rode
     * up their slots in stage 2 leave the barrier out of balance, and what it loses settling is the
     * ride's: friction in the slot, which the real cables spend as they slide */
    if (s->work->struck ? gap > 0.0 : gap > snap && !s->work->rode)
        s->e_released += gap, cs_system_jumped(&s->work->sys, s->step);
    else if (s->work->rode && gap > 0.0)
        s->e_friction += gap;
    s->work->struck = s->work->rode = 0;
    return gap;
}

/* Following the path. The barrier is massless but for its posts' swing, so its state is a function of the
 * vehicle's pose (and the posts' last rates) only while the equilibrium it is on goes on existing; the ledger
 * tells when it stopped: over a step, the barrier's energy (stored, dissipated, released) must change by the
 * work the vehicle did on it.
 * - It changed by less (by more than CS_PATH_GAP of the energy scale): the barrier jumped to a lower
 *   equilibrium within the step, a post snapping over or a rope running over its supports. Real posts
 *   and ropes spend the difference in motion the model does not have; it is booked as released, as
 *   a failure's is.
 * - It changed by more, or the solve at the end pose failed: the barrier's force peaked within the
 *   step, or what the end state booked is not what the barrier did on the way (a post folding over
 *   onto a branch the path never reached). The step goes back to its start and is taken again as
 *   CS_PATH_PIECES steps, vehicle and barrier, each followed by the same rule; a piece that fails at
 *   the last of CS_PATH_LEVELS levels is taken as CS_PATH_PIECES steps again and cut no further: each
 *   committed if its solve converged (the last always), the gap of each stretch between commits
 *   booked as it falls (a snap as released, a negative gap left in the ledger). There, a piece whose
 *   solve failed where a commit would make more than CS_PATH_GAP of the scale per step (hold more than the
 * last commit plus the work since) is not committed, the last neither: the barrier goes back to its last
 *   commit.
 * The gap allowed scales with the stretch's length. docs/theory.md, "A step". */
#define CS_PATH_GAP 1e-3
#define CS_PATH_PIECES 8

/* Follows the path over a stretch h long that is cut `level` times already. */
static void follow_stretch(const cs_model *model, cs_state *s, double h, int level, double scale) {
    double e0 = barrier_energy(model, s), work = 0.0, snap = CS_PATH_GAP * scale * h / model->scenario.dt;
    s->work->stored_committed = e0 - s->e_released; /* a stretch starts from a commit */
    s->work->struck = s->work->rode = 0;
    cs_state *start = s->work->step_start[level];
    cs_state_copy(model, start, s);
    if (advance(model, s, h, 0, HUGE_VAL, NULL, &work) && book_gap(model, s, work, e0, snap) >= -snap) return;
    if (cs_work_spent(model, s->work)) return;                           /* the step is not taken (cs_step) */
    cs_state_copy(model, s, start), s->work->struck = s->work->rode = 0; /* its strikes taken back */
    s->work->count.pieces++;
    if (level + 1 < CS_PATH_LEVELS) {
        for (int j = 0; j < CS_PATH_PIECES && !cs_work_spent(model, s->work); j++)
            follow_stretch(model, s, h / CS_PATH_PIECES, level + 1, scale);
        return;
    }
    work = 0.0;
    for (int j = 1; j <= CS_PATH_PIECES && !cs_work_spent(model, s->work); j++) { /* start: the last commit */
        double allowed = s->work->stored_committed + work + CS_PATH_GAP * scale * h / model->scenario.dt;
        if (!advance(model, s, h / CS_PATH_PIECES, j == CS_PATH_PIECES, allowed, start, &work)) continue;
        book_gap(model, s, work, e0, snap / CS_PATH_PIECES);
        work = 0.0, e0 = barrier_energy(model, s);
        s->work->stored_committed = e0 - s->e_released;
        cs_state_copy(model, start, s);
    }
}

static void follow_path(const cs_model *model, cs_state *s) {
    s->work->solver_residual = 0.0;
    follow_stretch(model, s, model->scenario.dt, 0, cs_energy_scale(model, s));
}

static cs_status unstable(const cs_model *model, cs_state *s, cs_error *err, const char *what, int element) {
    s->frozen = 1;
    if (err) {
        char name[64];
        if (element >= 0)
            snprintf(name, sizeof name, "%s %d", what, element);
        else
            snprintf(name, sizeof name, "%s", what);
        cs_error_set(
            err, CS_ERR_UNSTABLE,
            "t = %.4f s: %s went unstable (a value became NaN or infinite); reduce the time step (now "
            "%.3g ms)",
            s->t, name, model->scenario.dt * 1e3);
    }
    return CS_ERR_UNSTABLE;
}

/* A step whose committed solves ended further from equilibrium than the tolerance is a warning. */
static void count_warning(const cs_model *model, cs_state *s) {
    if (s->work->solver_residual <= model->scenario.solver_tolerance) return;
    s->summary.solver_warnings++;
    if (s->work->solver_residual > s->summary.max_solver_residual)
        s->summary.max_solver_residual = s->work->solver_residual;
}

/* Guards: no NaN or Inf anywhere, and a ledger that closes (before: the ledger at the step's start). */
static cs_status check_numbers(const cs_model *model, cs_state *s, const cs_energy *before, cs_error *err) {
    for (int i = 0; i < 3; i++)
        if (!isfinite(s->pos[i]) || !isfinite(s->vel[i]) || !isfinite(s->omega[i]) || !isfinite(s->force[i]))
            return unstable(model, s, err, "the vehicle", -1);
    for (int c = 0; c < model->cable_count; c++) {
        const cs_cable_state *cs = &s->cables[c];
        for (int i = 0; i + 1 < cs->node_count; i++)
            if (!isfinite(cs->tension[i]) || !isfinite(cs->m[i])) return unstable(model, s, err, "cable", c);
    }
    for (int p = 0; p < model->post_count; p++)
        if (!isfinite(s->posts[p].tilt[0]) || !isfinite(s->posts[p].tilt[1]))
            return unstable(model, s, err, "post", p);
    if (!isfinite(s->energy.balance_error) || fabs(s->energy.balance_error) > CS_LEDGER_FAILURE) {
        s->frozen = 1;
        if (err) { /* the term that moved most this step */
            int worst = 0;
            for (int k = 1; k < CS_ENERGY_TERMS; k++)
                if (fabs(cs_energy_term(&s->energy, k) - cs_energy_term(before, k)) >
                    fabs(cs_energy_term(&s->energy, worst) - cs_energy_term(before, worst)))
                    worst = k;
            cs_error_set(
                err, CS_ERR_UNSTABLE,
                "t = %.4f s: the energy ledger is off by %+.1f%% of the initial kinetic energy (over the "
                "%.0f%% a run may be; the term that moved most this step: %s, %+.3g kJ): the state no "
                "longer follows the physics (docs/robustness.md)",
                s->t, 100.0 * s->energy.balance_error, 100.0 * CS_LEDGER_FAILURE, cs_energy_term_name(worst),
                (cs_energy_term(&s->energy, worst) - cs_energy_term(before, worst)) / 1e3);
        }
        return CS_ERR_UNSTABLE;
    }
    return CS_OK;
}

cs_status cs_step(const cs_model *model, cs_state *s, cs_error *err) {
    if (err) err->status = CS_OK, err->message[0] = '\0';
    if (s->frozen || s->outcome != CS_RUNNING) return CS_OK;
    double t0 = s->t;
    long step0 = s->step;
    s->t += model->scenario.dt;
    s->step++;
    cs_energy before = s->energy;
    follow_path(model, s);               /* 1-6. the vehicle moves, the barrier follows and pushes back */
    if (cs_work_spent(model, s->work)) { /* bounded work: the step under way is not taken */
        cs_state_copy(model, s, s->work->step_start[0]); /* the state this step started from */
        s->t = t0, s->step = step0;
        cs_response_give_up(model, s, CS_DID_NOT_CONVERGE);
        return CS_OK;
    }
    count_warning(model, s);
    cs_energy_update(model, s);   /* 7. the ledger */
    cs_response_update(model, s); /* 8. response parameters, end of the run */
    /* a step that spent the work budget was not taken, above; one that used up the count of solves was */
    if (s->outcome == CS_RUNNING && (double)s->work->count.solves > model->solve_budget)
        cs_response_give_up(model, s, CS_DID_NOT_CONVERGE); /* bounded effort: a run that cannot follow */
    if (s->outcome == CS_RUNNING && (double)s->step >= model->max_steps)
        cs_response_give_up(model, s, CS_STEP_LIMIT); /* and a bounded number of steps */
    return check_numbers(model, s, &before, err);
}

/* Frames at t0 + k interval, k counted as an integer (t0 + k interval always moves on, where a sum of
 * intervals below the rounding of t would not); an interval below the step is a frame every step. */
cs_status cs_run(const cs_model *model, cs_state *s, cs_output_fn on_output, void *user, cs_error *err) {
    double dt = model->scenario.dt, interval = model->scenario.output_interval, t0 = s->t;
    if (interval < dt) interval = 0.0;
    double k = 1.0; /* the next frame's number */
    if (on_output) on_output(model, s, user);
    int last_out = 1;
    while (s->outcome == CS_RUNNING) {
        cs_status st = cs_step(model, s, err);
        if (st != CS_OK) return st;
        last_out = 0;
        if (on_output && (interval <= 0.0 || s->t >= t0 + k * interval - 1e-9 * dt)) {
            on_output(model, s, user);
            last_out = 1;
            if (interval > 0.0) k = floor((s->t - t0 + 1e-9 * dt) / interval) + 1.0;
        }
    }
    if (on_output && !last_out) on_output(model, s, user);
    return CS_OK;
}
