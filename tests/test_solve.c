/* SPDX-License-Identifier: MIT */
/* The barrier solve (src/solver/system.c). Its Jacobian, formed from the spans' tension gradients and the
 * posts' axes, must be the derivative of the solve's residual: checked against central difference
 * quotients of that residual at states along an APS3-like crash (tests/fixture.h), before and after
 * contact: posts elastic and hinged, supports sticking and sliding, the rope wrapped on the face's
 * corners, rope ends slipping through their fittings. Its fallback is reached and balances, and lets a post
 * with no equilibrium near fall; its predictor repeats no jump. */
#include "check.h"
#include "core/vec3.h"
#include "design.h"
#include "run/run.h"
#include "solver/work.h"

#include <stdlib.h>

enum { CAP = 256 };

/* Central difference steps: 1e-8 rad of tilt (and 1e-8 m of an anchor's or a pull's move, and of crush in
 * its row's entries); 1e-9 m of rope or contact height (far inside the width over which a support's
 * stick/slip switch is rounded, ~50 um here). A rope's slide row at a post next to its wrap on the
 * vehicle's corner curves sharply in the post's tilt: at the rigid-anchored APS3's step 40 the quotient
 * over 1e-6 rad is 8.5e-3 of the row off the Jacobian, over 1e-7 rad 4.8e-4, over 1e-8 rad within the
 * round-off (the Jacobian is the limit).
 * The crush's column is the solver's own forward quotient over 1e-8 m of the rows in its band (the crush
 * law has a kink where loading turns to unloading): it is checked against the same quotient of the whole
 * residual, which shows a row of the band evaluated out of place. An entry the band left out (a bandwidth
 * kept from another structure, system.c band_shape) would show here as a difference. */
static double step_of(int kind) {
    return kind == 1 || kind == 3 ? 1e-9 : 1e-8;
}
#define CRUSH_STEP 1e-8 /* system.c's */

typedef struct jac_check {
    int n;
    double worst; /* largest |J - D| relative to its row's largest |D| */
    int row, col;
} jac_check;

/* Whether unknown j is a post's tilt or pull, an anchor's displacement or a rope's material beside a span
 * that a commit's return map has left on its yield surface (a rope's: past T1, on its hardening branch; a
 * post's tilt or pull beside a rail segment on its cap, which it moves; a post's tilt or pull that moves a
 * rope's node beside such a span: APS3's end span from post 0 to its rigid anchor at step 215 takes
 * 21.36e6 N/rad of tilt backward and 12.94e6 forward, its kink 5e-10 rad away),
 * or a rope's material at a sticking node between spans of different plastic strain (the strain the rope
 * carries through the node switches from one side's to the other's at the committed material),
 * where a central difference straddles the kink between the elastic slope (which the Jacobian takes there)
 * and the plastic one. */
static int beside_a_yielding_span(const cs_model *m, const cs_state *s, int c, int node) {
    const cs_cable_state *cs = &s->cables[c];
    for (int i = node - 1; i <= node; i++) /* a span on the rope's hardening branch */
        if (i >= 0 && i + 1 < cs->node_count && cs->tension[i] >= m->cables[c].rope.t1) return 1;
    return 0;
}

/* A rail segment at post p left on its cap (yield or buckling) by a commit. */
static int beside_a_yielding_rail(const cs_model *m, const cs_state *s, int p) {
    for (int r = 0; r < m->rail_count; r++)
        for (int k = p - 1; k <= p; k++) {
            if (k < 0 || k + 1 >= m->post_count) continue;
            double a[3], b[3], l0 = m->posts[k + 1].x - m->posts[k].x;
            cs_post_attachment(m, k, s->posts[k].tilt, s->posts[k].pull, cs_post_upright(&m->posts[k]),
                               m->rails[r].z, a);
            cs_post_attachment(m, k + 1, s->posts[k + 1].tilt, s->posts[k + 1].pull,
                               cs_post_upright(&m->posts[k + 1]), m->rails[r].z, b);
            double d = sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                            (b[2] - a[2]) * (b[2] - a[2]));
            double n = m->rails[r].ea / l0 *
                       (d - l0 - s->rail_plastic[(size_t)r * (size_t)m->post_count + (size_t)k]);
            if (fabs(n - m->rails[r].yield_force) <= 1e-6 * m->rails[r].yield_force ||
                fabs(n + m->rails[r].buckling_load) <= 1e-6 * m->rails[r].buckling_load)
                return 1;
        }
    return 0;
}

static int on_the_yield_kink(const cs_model *m, const cs_state *s, int j) {
    const cs_slot *u = &s->work->sys.rows.slots[j];
    double k, cap, e[2];
    if (u->kind == CS_U_TILT || u->kind == CS_U_PULL) {
        if (beside_a_yielding_rail(m, s, u->a)) return 1;
        for (int c = 0; c < m->cable_count; c++) { /* it moves a node beside a span on its backbone */
            const cs_cable_state *cs = &s->cables[c];
            int i = cs->status == CS_CABLE_INTACT ? cs->where[u->a] : -1;
            if (i > 0 && beside_a_yielding_span(m, s, c, i)) return 1;
        }
    }
    if (u->kind == CS_U_TILT) {
        const cs_post_model *pm = &m->posts[u->a];
        const cs_post_state *ps = &s->posts[u->a];
        /* the spring's trial k e with its damper's (c / h)(alpha - alpha_c) (post.c), slope k + c / h,
         * against the cap the engine holds it to (a post sliding out holds less) */
        double g = !ps->captured && pm->inertia > 0.0 ? pm->damping / m->scenario.dt : 0.0;
        k = pm->k_rot + g, cap = cs_post_moment_cap(pm, ps);
        for (int i = 0; i < 2; i++)
            e[i] = (pm->k_rot * (ps->tilt[i] - ps->plastic[i]) + g * (ps->tilt[i] - ps->tilt_commit[i])) / k;
    } else if (u->kind == CS_U_ANCHOR) {
        const cs_anchor_model *am = &m->anchors[u->a];
        const cs_anchor_state *as = &s->anchors[u->a];
        k = am->stiffness, cap = cs_anchor_face_share(am, as) * cs_anchor_cap(am, as->slide);
        e[0] = as->u[0] - as->plastic[0], e[1] = as->u[1] - as->plastic[1];
    } else if (u->kind == CS_U_LIFT) { /* the skin at its hold, S x^2 */
        const cs_anchor_model *am = &m->anchors[u->a];
        const cs_anchor_state *as = &s->anchors[u->a];
        double x = 1.0 - (as->lift_plastic + CS_SHAFT_MOBILISATION) / am->depth;
        k = am->uplift_skin / CS_SHAFT_MOBILISATION, cap = am->uplift_skin * x * x;
        e[0] = as->lift - as->lift_plastic, e[1] = 0.0;
    } else if (u->kind == CS_U_NODE) { /* or the plastic strain the rope carries through it changes there */
        const cs_cable_state *cs = &s->cables[u->a];
        int carries = u->b > 0 && u->b + 1 < cs->node_count && cs->ep[u->b - 1] != cs->ep[u->b] &&
                      fabs(cs->m[u->b] - cs->m_commit[u->b]) <= 2.0 * step_of(u->kind);
        return carries || beside_a_yielding_span(m, s, u->a, u->b);
    } else if (u->kind == CS_U_HEIGHT) {
        return beside_a_yielding_span(m, s, u->a, cs_cable_find_node(&s->cables[u->a], cs_corner_node(u->b)));
    } else if (u->kind == CS_U_PULL) {
        const cs_post_model *pm = &m->posts[u->a];
        const cs_post_state *ps = &s->posts[u->a];
        k = pm->pull_stiffness, cap = cs_post_pull_cap(pm, ps);
        e[0] = ps->pull - ps->pull_plastic, e[1] = 0.0;
    } else {
        return 0;
    }
    return fabs(k * sqrt(e[0] * e[0] + e[1] * e[1]) - cap) <= 2.0 * k * step_of(u->kind);
}

/* The solver's Jacobian J against central difference quotients D of its residual at the state as it
 * stands, a step's time after its commit (so that posts and anchors with mass are unknowns, with their
 * inertia); the state is put back as it was solved. */
static jac_check check_jacobian(const cs_model *m, cs_state *s) {
    double h = s->h;
    s->h = m->scenario.dt;
    int *kind = calloc(CAP, sizeof *kind);
    double *x = calloc(CAP, sizeof *x), *r = calloc(CAP, sizeof *r), *jac = calloc(CAP * CAP, sizeof *jac);
    double *xp = calloc(CAP, sizeof *xp), *rp = calloc(CAP, sizeof *rp), *rm = calloc(CAP, sizeof *rm);
    double *d = calloc(CAP * CAP, sizeof *d), *row_max = calloc(CAP, sizeof *row_max);
    assert_true(kind && x && r && jac && xp && rp && rm && d && row_max);
    jac_check out = {cs_system_linearize(m, s, &s->work->sys, CAP, kind, x, r, jac), 0.0, -1, -1};
    int n = out.n;
    assert_true(n > 0);
    for (int j = 0; j < n; j++) {
        double step = step_of(kind[j]);
        memcpy(xp, x, (size_t)n * sizeof *x);
        xp[j] = x[j] + (kind[j] == 2 ? CRUSH_STEP : step);
        double span = xp[j]; /* the steps as represented: a rope's m is tens of metres */
        cs_system_residual(m, s, &s->work->sys, n, xp, rp);
        xp[j] = kind[j] == 2 ? x[j] : x[j] - step; /* the crush: forward, as the solver's */
        span -= xp[j];
        cs_system_residual(m, s, &s->work->sys, n, xp, rm);
        for (int i = 0; i < n; i++) {
            d[i * n + j] = (rp[i] - rm[i]) / span;
            row_max[i] = fmax(row_max[i], fabs(d[i * n + j]));
        }
    }
    cs_system_residual(m, s, &s->work->sys, n, x, r);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            if (kind[j] != 2 && on_the_yield_kink(m, s, j)) continue;
            double e = fabs(jac[i * n + j] - d[i * n + j]) / (row_max[i] + 1e-300);
            if (e > out.worst) out.worst = e, out.row = i, out.col = j;
        }
    free(kind), free(x), free(r), free(jac), free(xp), free(rp), free(rm), free(d), free(row_max);
    s->h = h;
    return out;
}

/* At the install (no contact), then every 40 steps through the crash until the ropes break: every
 * entry within 1e-4 of its row's largest, kinks aside (on_the_yield_kink). Measured: 1e-7 to 3e-6 of a
 * row (the quotients' round-off). Leaving out the turning angle's gradient makes 1.2e-4; terms under ~1e-6
 * of a row (the axis' own turning, the rope stiffness' change with the spans' length) are below what this
 * resolves. */
static int check_along_the_crash(fixture *fx, int *pulls);
static int lifts; /* checks that found an anchor rising out of the soil (check_along_the_crash) */

/* A fixture's model and its state as installed. */
static cs_state *start(const fixture *fx, cs_model **m) {
    cs_error err;
    *m = cs_model_create(&fx->barrier, &fx->vehicle, &fx->scenario, &err);
    if (!*m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(*m, &err);
    assert_non_null(s);
    return s;
}

static void jacobian_is_the_derivative_of_the_residual(void **state) {
    (void)state;
    fixture fx;
    int pulls = 0;
    fixture_aps3(&fx);
    fx.barrier.start_anchor.footing.diameter = fx.barrier.end_anchor.footing.diameter = 0.0; /* rigid */
    check_along_the_crash(&fx, &pulls);
}

/* The same with APS3's dead-men in the soil (3 x 5 ft): their rows and columns too, elastic and sliding. */
static void jacobian_with_anchors_in_the_soil(void **state) {
    (void)state;
    fixture fx;
    int pulls = 0;
    fixture_aps3(&fx);
    fx.barrier.start_anchor.footing = fx.barrier.end_anchor.footing = fixture_footing(3.0, 5.0, 0.0);
    check_along_the_crash(&fx, &pulls);
}

/* And with the dead-men rising out of the soil (anchor.c), their skin at the beta method's 25.4 kPa/m:
 * the rise's row and column, and its column in the anchors' rows and their spans', from 22 ms on (at
 * least 8 checks of the two). */
static void jacobian_with_a_dead_man_rising(void **state) {
    (void)state;
    fixture fx;
    int pulls = 0;
    fixture_aps3(&fx);
    fx.barrier.start_anchor.footing = fx.barrier.end_anchor.footing = fixture_footing(3.0, 5.0, 0.0);
    fx.barrier.start_anchor.footing.skin_friction = fx.barrier.end_anchor.footing.skin_friction = 25.4e3;
    lifts = 0;
    check_along_the_crash(&fx, &pulls);
    printf("%d checks of a rising dead-man\n", lifts);
    assert_true(lifts >= 2 * 8);
}

/* And with clips that slip (termination.c) at 30 kip at all four rope ends, 18 in of turn-back: the end
 * nodes' rows and columns, sticking at the install and sliding from 23 ms, at every check from step 40
 * (8 checks of 4 ends at least). */
static void jacobian_with_fittings_that_slip(void **state) {
    (void)state;
    fixture fx;
    int pulls = 0;
    fixture_aps3(&fx);
    for (int c = 0; c < 2; c++)
        fx.cables[c].slip_load = 30.0 * KIP, fx.cables[c].slip_travel = 18.0 * IN;
    assert_true(check_along_the_crash(&fx, &pulls) >= 4 * 8);
}

/* And with the four rails tying the posts (rail.c): their pull's slope on a post's own tilt and its
 * neighbours', and on the pull of a post sliding out of its footing (post_pullout.c) and its row. */
static void jacobian_with_rails(void **state) {
    (void)state;
    fixture fx;
    int pulls = 0;
    fixture_aps3(&fx);
    fixture_rails(&fx);
    for (int p = 0; p < fx.barrier.post_count; p++) /* held by 10 kip, posts the ropes lift out upright */
        fx.posts[p].footing.pullout_capacity = 10.0 * KIP;
    check_along_the_crash(&fx, &pulls);
    assert_true(pulls >= 2 * 2); /* two posts sliding out, at two checks at least */
}

/* And with a post down on the ground (post.c, the ground stop): APS3 as installed, line post 5 folded
 * 0.02 rad past its lie angle along the barrier and across it, on its plastic cap (its set 0.2 rad short of
 * the tilt), so the ground's stop and the cap's radial projection are both in its rows. */
static void jacobian_with_a_post_down(void **state) {
    (void)state;
    fixture fx = {0};
    fixture_aps3(&fx);
    fx.barrier.cables = fx.cables, fx.barrier.posts = fx.posts;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    cs_post_state *ps = &s->posts[5];
    double lie = m->posts[5].lie_angle + 0.02, u[2] = {0.6, 0.8};
    ps->tilt[0] = lie * u[0], ps->tilt[1] = lie * u[1];
    ps->plastic[0] = (lie - 0.2) * u[0], ps->plastic[1] = (lie - 0.2) * u[1];
    ps->tilt_commit[0] = ps->tilt[0], ps->tilt_commit[1] = ps->tilt[1];
    ps->status = CS_POST_DOWN;
    cs_post_place_nodes(m, s, 5, ps->tilt, NULL);
    jac_check c = check_jacobian(m, s);
    printf("post down: %d unknowns, largest difference %.2g of its row (row %d, column %d)\n", c.n, c.worst,
           c.row, c.col);
    assert_true(c.worst <= 1e-4);
    cs_state_free(s);
    cs_model_free(m);
}

/* The crush's column from a band that starts on an anchor's second row (system.c: an anchor's two rows,
 * as a post's, are evaluated together, from its first): APS3's truck with its dead-men in the soil, the
 * face loaded at step 100, the band widened up to the start anchor's second row (a band wider than the
 * structure needs holds zeros; the structure of a short or a broken barrier gives such bands). The
 * column is the forward quotient of the whole residual, within 1e-4 of its row as every entry. Evaluated
 * from the second row, the rows from the anchor's to the first post's came one row off: in APS1 at 80 mph
 * a post's pull row took 1.2e6 for 2.5, and 184 of its solves needed the fallback. */
static void crush_column_from_an_anchors_second_row(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    cs_model *m;
    cs_state *s = start(&fx, &m);
    cs_error err;
    for (int k = 0; k < 100 || !cs_face_loaded(m, s); k++)
        assert_int_equal(cs_step(m, s, &err), CS_OK);
    check_jacobian(m, s); /* the band's shape, kept while the structure stays */
    cs_system *sys = &s->work->sys;
    int j = sys->rows.crush_index;
    assert_true(sys->rows.slots[1].kind == CS_U_ANCHOR && sys->rows.slots[1].b == 1);
    assert_true(j - 1 >= sys->ku);
    sys->ku = j - 1;
    jac_check c = check_jacobian(m, s);
    assert_int_equal(sys->ku, j - 1);
    printf("crush column %d, band from row %d: largest difference %.2g of its row (row %d, column %d)\n", j,
           j - sys->ku, c.worst, c.row, c.col);
    assert_true(c.worst <= 1e-4);
    cs_state_free(s);
    cs_model_free(m);
}

/* Returns how many rope ends slipping through their fittings were unknowns at the states checked. */
static int check_along_the_crash(fixture *fx_in, int *pulls) {
    fixture fx = *fx_in;
    fx.barrier.cables = fx.cables, fx.barrier.posts = fx.posts;
    if (fx.barrier.rail_count) fx.barrier.rails = fx.rails;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    int checked = 0, ends = 0;
    for (int k = 0; k <= 400; k++) {
        if (k % 40 == 0) {
            jac_check c = check_jacobian(m, s);
            const cs_rows *rows = &s->work->sys.rows;
            for (int j = 0; j < rows->n; j++) /* a post sliding out of its footing, an anchor rising */
                *pulls += rows->slots[j].kind == CS_U_PULL, lifts += rows->slots[j].kind == CS_U_LIFT;
            for (int j = 0; j < rows->n; j++) /* an end node's m: its fitting slips */
                ends +=
                    rows->slots[j].kind == CS_U_NODE &&
                    (rows->slots[j].b == 0 || rows->slots[j].b == s->cables[rows->slots[j].a].node_count - 1);
            printf("step %3d: %d unknowns, largest difference %.2g of its row (row %d, column %d)\n", k, c.n,
                   c.worst, c.row, c.col);
            assert_true(c.worst <= 1e-4);
            checked++;
        }
        if (cs_step(m, s, &err) != CS_OK || s->outcome != CS_RUNNING) break;
    }
    assert_true(checked >= 6); /* through contact, the posts' hinges and the ropes' wrap */
    cs_state_free(s);
    cs_model_free(m);
    return ends;
}

/* The barrier as installed (step.c, settle.c) is the barrier's equilibrium at rest: APS3 with its rails and
 * its dead-men in the soil, the posts leaning under the pretension. Its scaled residual, every row of the
 * barrier's system at the installed state, is within the solver's tolerance; every span carries the
 * pretension (the ropes laid in on the settled path, every support sticking) within 1e-9 of it; and the
 * posts lean (the end posts toward the barrier, by the ropes' pull over them). */
static void the_installed_barrier_is_in_balance(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    fixture_rails(&fx);
    fx.barrier.start_anchor.footing = fx.barrier.end_anchor.footing = fixture_footing(3.0, 5.0, 0.0);
    fx.barrier.cables = fx.cables, fx.barrier.posts = fx.posts, fx.barrier.rails = fx.rails;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    int *kind = calloc(CAP, sizeof *kind);
    double *x = calloc(CAP, sizeof *x), *r = calloc(CAP, sizeof *r), *jac = calloc(CAP * CAP, sizeof *jac);
    assert_true(kind && x && r && jac);
    s->h = HUGE_VAL; /* at rest: the posts are unknowns, as massless ones */
    int n = cs_system_linearize(m, s, &s->work->sys, CAP, kind, x, r, jac);
    assert_true(n > 2 * m->post_count);
    double worst = 0.0;
    for (int i = 0; i < n; i++)
        worst = fmax(worst, fabs(r[i]));
    printf(
        "installed: %d unknowns, largest scaled residual %.2g (tolerance %.2g); end post leans %.3g mrad\n",
        n, worst, fx.scenario.solver_tolerance, 1e3 * v2_norm(s->posts[0].tilt[0], s->posts[0].tilt[1]));
    assert_true(worst <= fx.scenario.solver_tolerance);
    for (int c = 0; c < m->cable_count; c++)
        for (int i = 0; i + 1 < s->cables[c].node_count; i++)
            CHECK_REL(s->cables[c].tension[i], m->cables[c].pretension, 1e-9);
    assert_true(s->posts[0].tilt[0] > 0.0 && s->posts[m->post_count - 1].tilt[0] < 0.0);
    free(kind), free(x), free(r), free(jac);
    cs_state_free(s);
    cs_model_free(m);
}

/* A fixture's model and state run to the end (it must end without an error), its summary in sm. */
static cs_state *run_to_end(const fixture *fx, cs_model **m, cs_summary *sm) {
    cs_error err;
    cs_state *s = start(fx, m);
    assert_int_equal(cs_run(*m, s, NULL, NULL, &err), CS_OK);
    sm->size = sizeof *sm;
    cs_state_summary(s, sm, NULL);
    return s;
}

/* The fallback (relax.c) is reached and does its work: with rigid anchors and massless line posts (the
 * paper's), a post on its plastic plateau under the ropes' pull has no equilibrium that Newton's
 * linearisation finds, and the barrier's solve goes to the fallback's sweeps (109 of 519 solves: the
 * posts folded to the ground keep their ropes, their stubs upright). With them, 105 steps end above the
 * solver tolerance (at most 130 allowed): 16 at 0.0275-0.035 s, while the two struck posts fold on under
 * the truck's face, and the rest in stretches from 0.129 s, where the ropes alone hold the truck over
 * massless posts; one solve ends far enough off to try letting a post fall (at most one allowed; kept), and
 * the ledger balances within 1% (0.13% measured). No example has a step above the tolerance. */
static void fallback_is_reached_and_balances(void **state) {
    (void)state;
    fixture fx;
    fixture_aps3(&fx);
    for (int p = 0; p < fx.barrier.post_count; p++)
        fx.posts[p].section.mass_per_length = 0.0;
    fx.barrier.start_anchor.footing.diameter = fx.barrier.end_anchor.footing.diameter = 0.0; /* rigid */
    cs_model *m;
    cs_summary sm;
    cs_state *s = run_to_end(&fx, &m, &sm);
    printf(
        "%ld solves, %ld with the fallback, %ld tried a fall (%ld kept), %ld steps cut; %d warnings, ledger "
        "%.3g%%, %s\n",
        s->work->count.solves, s->work->count.fallback, s->work->count.fall_tries, s->work->count.falls,
        s->work->count.pieces, sm.solver_warnings, 100.0 * sm.energy_balance_error,
        cs_outcome_name(sm.outcome));
    assert_true(s->work->count.fallback > 0);
    assert_true(sm.solver_warnings <= 130);
    assert_true(s->work->count.fall_tries <= 1);
    assert_true(fabs(sm.energy_balance_error) < 0.01);
    cs_state_free(s);
    cs_model_free(m);
}

/* A post with no equilibrium near falls (barrier.c, relax.c): in stress design 13099 (two 1.54-in ropes on
 * eleven posts at 8.9 ft, rigid anchors, a 23,286-lb vehicle at 15.0 mph and 21 degrees) a solve still
 * ends above 1e-2 after Newton and the sweeps; the sweeps that let a post fall along its unbalanced
 * moment converge, and the fall is kept because, committed, the barrier holds no more energy than at its
 * last commit. Through it the run's energy ledger balances: within 0.5% of the initial kinetic energy
 * (0.015% measured). With the posts swinging by HHT-alpha, whose inertial slope is 3.7 times backward
 * Euler's, few designs reach it: 9 of designs 0-39,999, none below 8,000. */
static void a_post_with_no_equilibrium_near_falls(void **state) {
    (void)state;
    design d;
    design_numbered(13099, &d);
    cs_model *m;
    cs_summary sm;
    cs_state *s = run_to_end(&d.fx, &m, &sm);
    printf("%s: %ld tried a fall, %ld kept; ledger %.3g%%, %s\n", d.what, s->work->count.fall_tries,
           s->work->count.falls, 100.0 * sm.energy_balance_error, cs_outcome_name(sm.outcome));
    assert_true(s->work->count.falls >= 1);
    assert_true(s->work->count.fall_tries >= s->work->count.falls);
    assert_true(fabs(sm.energy_balance_error) < 0.005);
    cs_state_free(s);
    cs_model_free(m);
}

/* Where a solve starts: from the state as committed plus the increment of the last step (the
 * predictor), or, in the step after a jump (cs_system_jumped), from the state as committed. With a
 * tolerance above the residual there, Newton takes no iteration, so the state is left where it started.
 * Post 8's tilt is moved by 1e-6 rad between two solves a step apart: the third solve, a step later,
 * leaves it 1e-6 rad further on (the increment repeated), or where it stands if the barrier jumped. */
static double tilt_after_three_solves(int jumped) {
    fixture fx;
    fixture_aps3(&fx);
    fx.scenario.solver_tolerance = 0.099;
    cs_error err;
    cs_model *m = cs_model_create(&fx.barrier, &fx.vehicle, &fx.scenario, &err);
    if (!m) fail_msg("%s", err.message);
    cs_state *s = cs_state_create(m, &err);
    assert_non_null(s);
    cs_system *sys = &s->work->sys;
    s->h = m->scenario.dt; /* posts with mass are unknowns a step after a commit */
    const int p = 8;
    double *tilt = s->posts[p].tilt, t0 = tilt[0];
    s->step = 1;
    assert_true(cs_system_solve(m, s, sys) >= 0.0);
    assert_true(tilt[0] == t0); /* at rest: nothing to extrapolate */
    s->step = 2, tilt[0] += 1e-6;
    assert_true(cs_system_solve(m, s, sys) >= 0.0);
    if (jumped) cs_system_jumped(sys, s->step);
    s->step = 3;
    assert_true(cs_system_solve(m, s, sys) >= 0.0);
    double moved = tilt[0] - t0;
    cs_state_free(s);
    cs_model_free(m);
    return moved;
}

static void the_step_after_a_jump_starts_where_the_barrier_is(void **state) {
    (void)state;
    CHECK_REL(tilt_after_three_solves(0), 3e-6, 1e-9); /* 1e-6 moved, 1e-6 and 1e-6 extrapolated */
    CHECK_REL(tilt_after_three_solves(1), 2e-6, 1e-9); /* the step after the jump not extrapolated */
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(the_installed_barrier_is_in_balance),
                                       cmocka_unit_test(jacobian_is_the_derivative_of_the_residual),
                                       cmocka_unit_test(jacobian_with_a_post_down),
                                       cmocka_unit_test(jacobian_with_anchors_in_the_soil),
                                       cmocka_unit_test(jacobian_with_a_dead_man_rising),
                                       cmocka_unit_test(jacobian_with_fittings_that_slip),
                                       cmocka_unit_test(jacobian_with_rails),
                                       cmocka_unit_test(crush_column_from_an_anchors_second_row),
                                       cmocka_unit_test(fallback_is_reached_and_balances),
                                       cmocka_unit_test(a_post_with_no_equilibrium_near_falls),
                                       cmocka_unit_test(the_step_after_a_jump_starts_where_the_barrier_is)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
