/* Stress: random but valid designs and attacks, from a fixed seed, over realistic and extreme ranges
 * (rope sizes, post spacing, cables, vehicle sizes, speeds 5-60 mph, angles 15-90 degrees, impact
 * anywhere along the barrier including at an anchor and past its end). Every run must end without an
 * error, with finite response parameters and an energy ledger within 2% (issue 7). CS_STRESS_RUNS in
 * the environment sets how many (default 24, short runs) and CS_STRESS_FROM the first design; the
 * generator gives design k the same whatever the run count. The default subset is designs 0-23, plus
 * the designs kept as regressions (docs/robustness.md). */
#include "check.h"
#include "fixture.h"

#include <stdlib.h>

/* SplitMix64: a counter-based generator, so design k is the same whatever the run count. */
static unsigned long long mix(unsigned long long x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

static double uniform(unsigned long long *s, double lo, double hi) {
    *s = mix(*s);
    return lo + (hi - lo) * (double)(*s >> 11) / 9007199254740992.0;
}

typedef struct design {
    fixture fx;
    char what[160];
} design;

static void make_design(int k, design *d) {
    unsigned long long s = 0x5eed0000ULL + (unsigned long long)k;
    fixture *fx = &d->fx;
    fixture_aps3(fx);
    int cables = 1 + (int)uniform(&s, 0.0, 2.0); /* 1 or 2 */
    double rope_in = uniform(&s, 0.5, 1.75), spacing = uniform(&s, 4.0, 12.0) * FT;
    int posts = 4 + (int)uniform(&s, 0.0, 20.0);
    for (int c = 0; c < 2; c++) {
        fx->cables[c].rope = fixture_rope(rope_in);
        fx->cables[c].height = (c == 0 ? uniform(&s, 0.6, 0.9) : uniform(&s, 0.95, 1.3));
        fx->cables[c].pretension = uniform(&s, 0.5, 8.0) * KIP;
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
    double dead_man = uniform(&s, -0.5, 1.5);
    fx->barrier.start_anchor.footing = fx->barrier.end_anchor.footing =
        fixture_footing(dead_man > 0.0 ? 1.0 + 2.0 * dead_man : 0.0, 3.0 + 2.0 * fabs(dead_man), 0.0);
    int rails = (int)uniform(&s, -2.0, 5.0); /* none in about half, else 1 to 4 of the APS rails */
    if (rails > 0) fixture_rails(fx), fx->barrier.rail_count = rails;
    /* a vehicle between a small car and a heavy truck, scaled from the 15,000-lb truck */
    double scale = uniform(&s, 0.35, 1.6);
    cs_vehicle_def *v = &fx->vehicle;
    v->mass *= scale * scale * scale;
    for (int i = 0; i < 3; i++)
        v->inertia[i] *= pow(scale, 5);
    v->cg_height *= scale, v->cg_to_front *= scale, v->front_width *= scale, v->face_bottom *= scale;
    v->face_top *= scale, v->wheelbase *= scale, v->cg_to_front_axle *= scale, v->track *= scale;
    v->cg_to_rear *= scale, v->side_bottom *= scale, v->side_top *= scale;
    for (int i = 0; i < v->crush_point_count; i++)
        v->crush_deformation[i] *= scale, v->crush_force[i] *= scale * scale;
    fx->scenario.speed = uniform(&s, 5.0, 60.0) * MPH;
    fx->scenario.angle = uniform(&s, 15.0, 90.0) * M_PI_2_VALUE / 90.0;
    fx->scenario.impact_x = uniform(&s, -0.1, 1.1) * length; /* past either anchor too */
    fx->scenario.t_end = 0.15;
    snprintf(
        d->what, sizeof d->what,
        "design %d: %d cables of %.2f in, %d posts at %.1f ft, %d rails, dead-men %.1f ft wide, %.0f lb at "
        "%.1f mph, %.0f deg, x = %.1f of %.1f m",
        k, cables, rope_in, posts, spacing / FT, fx->barrier.rail_count,
        fx->barrier.start_anchor.footing.diameter / FT, v->mass / LB, fx->scenario.speed / MPH,
        fx->scenario.angle * 90.0 / M_PI_2_VALUE, fx->scenario.impact_x, length);
}

/* Runs design k; returns 1 (and says why) if it errs, leaves a non-finite response or a ledger off by
 * more than 2%. */
static int design_fails(int k) {
    design d;
    make_design(k, &d);
    cs_error err;
    cs_model *m = cs_model_create(&d.fx.barrier, &d.fx.vehicle, &d.fx.scenario, &err);
    if (!m) {
        printf("FAIL %s: refused: %s\n", d.what, err.message);
        return 1;
    }
    cs_state *s = cs_state_create(m, &err);
    cs_status st = cs_run(m, s, NULL, NULL, &err);
    cs_summary sm;
    cs_state_summary(s, &sm);
    int finite = isfinite(sm.max_50ms_decel_g) && isfinite(sm.max_dynamic_penetration_m) &&
                 isfinite(sm.max_barrier_deflection_m) && isfinite(sm.energy_balance_error);
    int fails = st != CS_OK || !finite || fabs(sm.energy_balance_error) > 0.02;
    if (fails)
        printf("FAIL %s: %s, ledger %.4f, %s\n", d.what, st == CS_OK ? "ran" : err.message,
               sm.energy_balance_error, finite ? "finite" : "NOT finite");
    cs_state_free(s);
    cs_model_free(m);
    return fails;
}

static void random_designs_run_clean(void **state) {
    (void)state;
    const char *env = getenv("CS_STRESS_RUNS"), *from_env = getenv("CS_STRESS_FROM");
    int runs = env ? atoi(env) : 24, from = from_env ? atoi(from_env) : 0, failures = 0;
    for (int k = from; k < from + runs; k++)
        failures += design_fails(k);
    printf("%d random designs, %d failures\n", runs, failures);
    assert_int_equal(failures, 0);
}

/* Designs whose ledger once missed 2% and now balances, kept as regressions: 142 and 195, where a
 * struck post leaves the ropes' paths and the stored energy it releases once went unbooked
 * (docs/theory.md, "A step", 5); 76, 78 and 105, where the barrier snaps to a lower equilibrium within
 * one step (once -2.7% each), and 99, where a step's end state booked more friction and
 * plastic work than the barrier was given (+2.2%) (docs/theory.md, "A step", following the path);
 * 583, 4765 and 7855, small cars under the ropes pushing a post whose push did less work than the post
 * took (+10%, +24%, and the energy guard's error) until the push became the gradient of the post's work
 * (docs/theory.md, "posts struck by the face"); 3057 and 7839, rebounding vehicles whose ropes engaged
 * and released a corner of a pitched face every step (+3.4%, +6.4%) until both tests were made in 3D
 * (docs/theory.md, Contact); 1804, a car whose sliding tyres the path check took for barrier energy
 * (+4.9%) (docs/theory.md, Energy ledger); 6305 and 9637, where an eighth of a step converged onto a
 * branch the path never reached (+6.5%, +3.3%) until such an eighth was cut again into 64ths
 * (docs/theory.md, "A step", two levels); 2004, 2346, 5438 and 6270, where an end post on its plateau,
 * bent over by the ropes' pull down to the anchor, had no equilibrium near its tilt and every solve
 * stalled (+14%, +15%, +4.3%, +8.4%) until such a post was let fall to the next one (docs/theory.md,
 * "Posts", falling); 5498, where a fall kept because it stored less than the failed solve led to a
 * state whose commit booked 11 kJ more than the ropes gave up (+3.1%), and 1648, where 64ths starting
 * from a failed one converged onto the rope at its strength and the last was committed (the energy
 * guard's error at +262%), on the way there (docs/theory.md, "A step", no wild iterate); 7332, a
 * small car whose face corner reached the end anchor, a 2-cm span between them, where 64ths whose
 * solves failed each made up to 1e-3 of the energy scale (+2.9% over five steps) until that allowance
 * was scaled to the piece's length, and 64ths committed at residuals near 1e-3 made about 5 J each
 * (+2.6%) until every 64th that missed the solver tolerance was checked (docs/theory.md, "A step", no wild
 * iterate). */
static void kept_designs_balance(void **state) {
    (void)state;
    const int kept[] = {76,   78,   99,   105,  142,  195,  583,  1648, 1804, 2004, 2346,
                        3057, 4765, 5438, 5498, 6270, 6305, 7332, 7839, 7855, 9637};
    int failures = 0;
    for (size_t i = 0; i < sizeof kept / sizeof *kept; i++)
        failures += design_fails(kept[i]);
    assert_int_equal(failures, 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(random_designs_run_clean),
                                       cmocka_unit_test(kept_designs_balance)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
