/* `cablesim validate [-o DIR] [--examples DIR] [--only crash,bogie,verification,convergence,sensitivity]`:
 * the validation suite, written to DIR/validation.md and DIR/validation.csv.
 * - the three crash tests (examples/aps*.yaml): APS1 beside the crash test and the paper's simulation
 *   (the paper's Table 3); APS3 and APS4 as blind predictions (their results are withheld);
 * - the ten bogie tests of W6x16 posts in soil (the paper's Table 2), each simulated as the 2,237-lb
 *   bogie striking the post, against the measured energy and failure mode;
 * - verification against closed forms (Eq. 21 against the paper's Table 4);
 * - time-step convergence of the crash tests (0.5, 0.25, 0.1, 0.05 ms);
 * - sensitivity to what the paper does not give: the range of each response over each input's range.
 * Every case uses the one parameter set of the model files and docs/assumptions.md. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "commands.h"
#include "loader.h"

#define MPH 0.44704
#define FT 0.3048
#define IN 0.0254
#define LB 0.45359237
#define FTLB 1.3558179483314

typedef struct result {
    int ok;
    cs_summary sm;
    double cable_break[2]; /* s, < 0 if not broken */
    double absorbed;       /* J: initial kinetic energy minus what is left */
    int post_failure;      /* the first post failure's event type, -1 if none */
    double post_failure_t; /* its time, s */
    double seconds;        /* wall time of the run */
} result;

static void collect(const cs_state *s, result *r) {
    cs_state_summary(s, &r->sm);
    r->cable_break[0] = r->cable_break[1] = -1.0;
    r->post_failure = -1;
    for (int i = 0; i < cs_state_event_count(s); i++) {
        const cs_event *e = cs_state_event(s, i);
        if (r->post_failure < 0 && (e->type == CS_EVENT_POST_ROTATION_LIMIT ||
                                    e->type == CS_EVENT_POST_PULLOUT || e->type == CS_EVENT_POST_SHEAR))
            r->post_failure = (int)e->type, r->post_failure_t = e->t;
        if (e->type == CS_EVENT_CABLE_BREAK && e->element < 2 && r->cable_break[e->element] < 0.0)
            r->cable_break[e->element] = e->t;
    }
    cs_energy en;
    cs_state_energy(s, &en);
    r->absorbed = en.initial_kinetic - en.vehicle_kinetic;
}

static int run_model(const cs_model *m, result *r) {
    cs_error err = {0};
    clock_t c0 = clock();
    cs_state *s = cs_state_create(m, &err);
    r->ok = s && cs_run(m, s, NULL, NULL, &err) == CS_OK;
    if (r->ok)
        collect(s, r);
    else
        fprintf(stderr, "cablesim validate: a run failed: %s\n", err.message);
    cs_state_free(s);
    r->seconds = (double)(clock() - c0) / CLOCKS_PER_SEC;
    return r->ok ? 0 : -1;
}

/* Load a model file with overrides ("PATH=VALUE", NULL-terminated) and run it. */
static int run_file(const char *path, const char *const *sets, result *r) {
    char why[256];
    memset(r, 0, sizeof *r);
    cs_loader *l = cs_loader_create(NULL, why, sizeof why);
    if (!l) {
        fprintf(stderr, "cablesim validate: %s\n", why);
        return -1;
    }
    for (int i = 0; sets && sets[i]; i++)
        cs_loader_set(l, sets[i]);
    cs_model_input in;
    cs_model *m = NULL;
    int rc = -1;
    if (cs_loader_load(l, path, &in) == 0 && (m = cs_loader_build(l, &in)) != NULL)
        rc = run_model(m, r);
    else
        cs_loader_print_errors(l, stderr);
    cs_model_free(m);
    cs_loader_free(l);
    return rc;
}

/* One CSV row: suite, case, variant, then the run's numbers; what does not apply is left empty. */
static void csv_row(FILE *csv, const char *suite, const char *name, const char *variant, const result *r) {
    char exit[32] = "", stop[32] = "", b1[32] = "", b2[32] = "";
    if (r->ok && r->sm.outcome == CS_BREAKTHROUGH) snprintf(exit, sizeof exit, "%.6g", r->sm.exit_speed);
    if (r->ok && r->sm.outcome == CS_STOPPED) snprintf(stop, sizeof stop, "%.6g", r->sm.stop_time);
    if (r->ok && r->cable_break[0] >= 0.0) snprintf(b1, sizeof b1, "%.6g", r->cable_break[0]);
    if (r->ok && r->cable_break[1] >= 0.0) snprintf(b2, sizeof b2, "%.6g", r->cable_break[1]);
    if (!r->ok) {
        fprintf(csv, "%s,%s,%s,0,failed,,,,,,,,,,\n", suite, name, variant);
        return;
    }
    fprintf(csv, "%s,%s,\"%s\",1,%s,%.6g,%.6g,%s,%s,%s,%s,%d,%d,%.6g,%.6g\n", suite, name, variant,
            cs_outcome_name(r->sm.outcome), r->sm.max_decel_50ms_g, r->sm.max_dynamic_penetration, exit, stop,
            b1, b2, r->sm.posts_failed_left, r->sm.posts_failed_right, r->sm.energy_balance_error,
            r->absorbed);
}

static const char *fmt_time(double t, char *buf, size_t n) {
    if (t < 0.0)
        snprintf(buf, n, "not broken");
    else
        snprintf(buf, n, "%.3f s", t);
    return buf;
}

static double rel_err(double model, double test) {
    return 100.0 * (model - test) / fabs(test);
}

/* ---- crash tests ---- */
static const char *const crash_names[3] = {"aps1", "aps3", "aps4"};

static void write_crash(FILE *md, FILE *csv, const char *examples, result *base) {
    char path[1024], a[32], b[32];
    fprintf(md,
            "## Crash tests\n\nThe three designs of `examples/aps*.yaml`, 15,000-lb truck at 40 mph head-on "
            "(assumed: docs/assumptions.md).\n\n");
    for (int k = 0; k < 3; k++) {
        snprintf(path, sizeof path, "%s/%s.yaml", examples, crash_names[k]);
        run_file(path, NULL, &base[k]);
        csv_row(csv, "crash", crash_names[k], "baseline", &base[k]);
    }
    const result *r = &base[0];
    fprintf(md, "### APS1 against the crash test and the paper's simulation (paper, Table 3)\n\n");
    fprintf(md, "| response | crash test | paper's simulation | cablesim | cablesim vs test "
                "|\n|---|---|---|---|---|\n");
    fprintf(md, "| max 50-ms average deceleration | 1.485 g | 1.247 g | %.3f g | %+.0f%% |\n",
            r->sm.max_decel_50ms_g, rel_err(r->sm.max_decel_50ms_g, 1.485));
    if (r->sm.outcome == CS_BREAKTHROUGH)
        fprintf(md, "| exit speed | 31.2 mph | 29.4 mph | %.1f mph | %+.0f%% |\n", r->sm.exit_speed / MPH,
                rel_err(r->sm.exit_speed / MPH, 31.2));
    else
        fprintf(md, "| exit speed | 31.2 mph | 29.4 mph | none: %s at %.3f s | the truck is not through |\n",
                cs_outcome_name(r->sm.outcome), r->sm.t);
    for (int c = 0; c < 2; c++) {
        const double test[2] = {0.088, 0.123}, paper[2] = {0.255, 0.295};
        fprintf(md, "| time when cable %d broke | %.3f s | %.3f s | %s | %s |\n", c + 1, test[c], paper[c],
                fmt_time(r->cable_break[c], a, sizeof a),
                r->cable_break[c] < 0.0
                    ? "no break"
                    : (snprintf(b, sizeof b, "%+.0f ms", 1e3 * (r->cable_break[c] - test[c])), b));
    }
    int dec_ok = r->ok && fabs(rel_err(r->sm.max_decel_50ms_g, 1.485)) <= 15.0;
    int exit_ok =
        r->ok && r->sm.outcome == CS_BREAKTHROUGH && fabs(rel_err(r->sm.exit_speed / MPH, 31.2)) <= 15.0;
    int brk_ok = r->ok && r->cable_break[0] >= 0.0 && r->cable_break[1] >= 0.0 &&
                 fabs(r->cable_break[0] - 0.088) <= 0.05 && fabs(r->cable_break[1] - 0.123) <= 0.05;
    fprintf(md,
            "\nTargets (issue 4): exit speed and deceleration within 15%%, both break times within 50 ms: "
            "deceleration %s, exit speed %s, break times %s.\n\n",
            dec_ok ? "met" : "NOT met", exit_ok ? "met" : "NOT met", brk_ok ? "met" : "NOT met");
    fprintf(md, "### APS3 and APS4: blind predictions (the measured results are withheld)\n\n");
    fprintf(md,
            "| response | APS3 cablesim | APS3 test | APS4 cablesim | APS4 test |\n|---|---|---|---|---|\n");
    const result *p3 = &base[1], *p4 = &base[2];
    fprintf(md, "| outcome | %s at %.3f s | withheld | %s at %.3f s | withheld |\n",
            cs_outcome_name(p3->sm.outcome), p3->sm.t, cs_outcome_name(p4->sm.outcome), p4->sm.t);
    fprintf(md, "| max 50-ms average deceleration | %.3f g | withheld | %.3f g | withheld |\n",
            p3->sm.max_decel_50ms_g, p4->sm.max_decel_50ms_g);
    fprintf(md, "| max dynamic penetration | %.2f m | withheld | %.2f m | withheld |\n",
            p3->sm.max_dynamic_penetration, p4->sm.max_dynamic_penetration);
    fprintf(
        md, "| exit speed | %s | withheld | %s | withheld |\n",
        p3->sm.outcome == CS_BREAKTHROUGH ? (snprintf(a, sizeof a, "%.1f mph", p3->sm.exit_speed / MPH), a)
                                          : "-",
        p4->sm.outcome == CS_BREAKTHROUGH ? (snprintf(b, sizeof b, "%.1f mph", p4->sm.exit_speed / MPH), b)
                                          : "-");
    fprintf(md, "| posts failed left / right | %d / %d | withheld | %d / %d | withheld |\n\n",
            p3->sm.posts_failed_left, p3->sm.posts_failed_right, p4->sm.posts_failed_left,
            p4->sm.posts_failed_right);
}

/* ---- bogie tests ---- */
typedef struct bogie_test {
    const char *name;
    double mph, embedment_mm, deflection_mm, energy_ftlb;
    int pullout; /* 1: pulled out of the ground; 0: rotated in the soil */
} bogie_test;

/* The paper's Table 2 (MwRSF tests of W6x16 posts in AASHTO M147-65 Grade B soil). */
static const bogie_test bogie_tests[10] = {
    {"NPGB-1", 20.00, 1092, 1045.3, 21994, 0}, {"NPGB-2", 21.00, 1016, 1152.9, 21500, 0},
    {"NPGB-3", 20.00, 1092, 1241.7, 20984, 0}, {"NPGB-4", 20.00, 1016, 1092.3, 21493, 0},
    {"NPGB-5", 20.00, 940, 1365.0, 20187, 1},  {"NPGB-6", 20.49, 864, 1340.1, 17849, 1},
    {"NPGB-7", 19.71, 940, 1326.3, 16595, 1},  {"NPGB-8", 20.69, 940, 1164.1, 18314, 1},
    {"NPGB-9", 20.76, 1016, 1221.5, 21507, 0}, {"NPGB-10", 21.50, 1016, 1185.6, 23440, 0}};

/* The bogie struck the post at speed mph: one W6x16 (library part) with the given footing, no cable. */
static cs_model *bogie_model(cs_loader *l, const cs_footing_def *footing, double mph, cs_error *err) {
    cs_post_def post = cs_default_post_def();
    if (cs_loader_part(l, CS_PART_SECTION, "W6x16", &post.section) != 0) return NULL;
    post.height = 1.0;
    post.footing = *footing;
    cs_barrier_def b = cs_default_barrier_def();
    b.cable_count = 0, b.post_count = 1, b.posts = &post;
    b.start_anchor.x = -10.0, b.end_anchor.x = 10.0;
    cs_vehicle_def v = cs_default_vehicle_def();
    v.mass = 2237 * LB;
    v.inertia[0] = v.mass * (1.5 * 1.5 + 1.0) / 12, v.inertia[1] = v.mass * (3.0 * 3.0 + 1.0) / 12;
    v.inertia[2] = v.mass * (3.0 * 3.0 + 1.5 * 1.5) / 12; /* a 3 x 1.5 x 1 m box */
    v.cg_height = 0.6, v.cg_to_front = 2.0, v.front_width = 8 * IN;
    v.face_bottom = 24.875 * IN - 4 * IN, v.face_top = 24.875 * IN + 4 * IN;
    v.wheelbase = 2.0, v.cg_to_front_axle = 1.0, v.track = 1.5;
    v.crush_point_count = 2, v.crush_deformation[1] = 0.001, v.crush_force[1] = 1e7; /* rigid head */
    cs_scenario_def sc = cs_default_scenario_def();
    sc.speed = mph * MPH, sc.impact_x = 0.0, sc.t_end = 1.0;
    return cs_model_create(&b, &v, &sc, err);
}

/* A footing of width b and depth d in the soil of docs/assumptions.md (S1 = 8000 psf, the default
 * dynamic factor and skin friction); no pullout capacity given: it pulls out at its skin friction's. */
static cs_footing_def soil_footing(double b, double d) {
    cs_footing_def f = cs_default_footing_def();
    f.diameter = b, f.depth = d, f.soil_pressure = 8000.0 * 47.88025898033584;
    return f;
}

/* The post driven in soil: Eq. 21 with the flange (4.03 in) as B, the default dynamic factor, and no
 * pullout capacity (its skin friction). */
static int run_bogie(cs_loader *l, const bogie_test *t, result *r) {
    cs_footing_def f = soil_footing(4.03 * IN, t->embedment_mm * 1e-3);
    cs_error err = {0};
    memset(r, 0, sizeof *r);
    cs_model *m = bogie_model(l, &f, t->mph, &err);
    if (!m) {
        fprintf(stderr, "cablesim validate: %s: %s\n", t->name, err.message);
        return -1;
    }
    int rc = run_model(m, r);
    cs_model_free(m);
    return rc;
}

static void write_bogie(FILE *md, FILE *csv) {
    char why[256];
    cs_loader *l = cs_loader_create(NULL, why, sizeof why);
    if (!l) return;
    const cs_footing_def soil = cs_default_footing_def();
    fprintf(
        md,
        "## Bogie tests of W6x16 posts in soil (paper, Table 2)\n\nThe 2,237-lb bogie strikes the post at "
        "24.875 in; the post rotates in the soil at %.3g x Eq. 21 (S1 = 8000 psf, B = the 4.03-in flange; "
        "%.3g the soil's dynamic factor) or hinges at Mp, and fails at 45 degrees, or pulls out earlier when "
        "the pull along the leaning post (push x sin(tilt)) reaches its skin friction q pi B D^2 / 2 "
        "(q = %.4g kPa/m). Energy absorbed = the bogie's loss of kinetic energy.\n\n"
        "**Calibration.** The dynamic factor and q are the model's two values fitted to these tests, "
        "on the odd ones (NPGB-1, 3, 5, 7, 9) only: the factor by least squares on log energy, q at the "
        "middle of the window that separates their modes; the even tests (NPGB-2, 4, 6, 8, 10) are the "
        "check. "
        "The mode window is narrow (q within about +-2.5%%): the lateral capacity grows nearly as fast with "
        "D as the skin friction (docs/theory.md).\n\n",
        soil.dynamic_factor, soil.dynamic_factor, soil.skin_friction / 1e3);
    fprintf(md,
            "| test | speed | embedment | energy measured | energy cablesim | error | deflection measured | "
            "failure measured | failure cablesim |\n|---|---|---|---|---|---|---|---|---|\n");
    int good = 0, good_even = 0;
    for (int i = 0; i < 10; i++) {
        const bogie_test *t = &bogie_tests[i];
        result r;
        if (run_bogie(l, t, &r) != 0) continue;
        double e = r.absorbed / FTLB, err = rel_err(e, t->energy_ftlb);
        const char *mode = r.post_failure == CS_EVENT_POST_PULLOUT          ? "pulled out"
                           : r.post_failure == CS_EVENT_POST_ROTATION_LIMIT ? "rotation (45 deg)"
                           : r.post_failure == CS_EVENT_POST_SHEAR          ? "shear"
                                                                            : "none (post stood)";
        int mode_ok = t->pullout ? r.post_failure == CS_EVENT_POST_PULLOUT
                                 : r.post_failure == CS_EVENT_POST_ROTATION_LIMIT;
        good += mode_ok && fabs(err) <= 20.0;
        good_even += mode_ok && fabs(err) <= 20.0 && i % 2 == 1; /* NPGB-2, 4, ...: the check half */
        fprintf(md, "| %s | %.2f mph | %.0f mm | %.0f ft-lb | %.0f ft-lb | %+.0f%% | %.0f mm | %s | %s |\n",
                t->name, t->mph, t->embedment_mm, t->energy_ftlb, e, err, t->deflection_mm,
                t->pullout ? "pulled out" : "rotation", mode);
        csv_row(csv, "bogie", t->name, "baseline", &r);
    }
    fprintf(
        md,
        "\nTarget (issue 4): right failure mode and energy within 20%% in at least 8 of 10: %d of 10, %s "
        "(%d of the 5 check tests, %d of the 5 fit tests). The model's travel to failure is the 45-degree "
        "limit (load point ~0.86 m), short of the measured 1.05-1.37 m: the energy comes out right with a "
        "force above the measured average; see docs/theory.md.\n\n",
        good, good >= 8 ? "met" : "NOT met", good_even, good - good_even);
    cs_loader_free(l);
}

/* ---- verification ---- */
/* Eq. 21 as the engine evaluates it (a one-post model's footing capacity) against the paper. */
static void write_verification(FILE *md) {
    fprintf(
        md,
        "## Verification against closed forms\n\nEq. 21 as the engine evaluates it (S1 = 8000 psf, H = 3 ft) "
        "against the P column of the paper's Table 4:\n\n| B | D | P paper | P cablesim "
        "|\n|---|---|---|---|\n");
    const double bft[] = {0.75, 1.5, 3, 3, 8}, dft[] = {3, 3, 5, 6, 4},
                 p[] = {3593, 7186, 30349, 39024, 58851};
    char why[256];
    cs_loader *l = cs_loader_create(NULL, why, sizeof why);
    for (int i = 0; l && i < 5; i++) {
        cs_footing_def f = soil_footing(bft[i] * FT, dft[i] * FT);
        cs_error err = {0};
        cs_model *m = bogie_model(l, &f, 20.0, &err);
        if (!m) continue;
        double pn = cs_model_footing_capacity(m, 0, 3 * FT);
        fprintf(md, "| %.2f ft | %.0f ft | %.0f lb | %.0f lb |\n", bft[i], dft[i], p[i], pn / (LB * 9.80665));
        cs_model_free(m);
    }
    cs_loader_free(l);
    fprintf(
        md,
        "\nThe engine's other closed-form checks run in `make test` (tests/test_*.c): rope law points, "
        "capstan "
        "ratio exp(mu theta), frictionless sliding EA(L/S - 1), cantilever deflection R z^3 / 3EI, hinge at "
        "Mp, shear onset, struck-post work M_cap x plastic rotation, free rolling, settling on the tyres, no "
        "yaw in a symmetric impact, the energy ledger within 1%%.\n\n");
}

/* ---- convergence and sensitivity ---- */
/* One table per refinement: each crash test run at every value of one scenario setting, and the change
 * of the max 50-ms deceleration and the penetration from the first value to the last. */
static void refinement_table(FILE *md, FILE *csv, const char *examples, const char *setting,
                             const char *label, const char *const *values, int count) {
    fprintf(md,
            "| test | %s | outcome | max 50-ms decel | penetration | exit speed | ledger error |\n"
            "|---|---|---|---|---|---|---|\n",
            label);
    for (int k = 0; k < 3; k++) {
        double first[2] = {0, 0}, last[2] = {0, 0};
        for (int d = 0; d < count; d++) {
            char path[1024], set[96];
            snprintf(path, sizeof path, "%s/%s.yaml", examples, crash_names[k]);
            snprintf(set, sizeof set, "scenario.%s=%s", setting, values[d]);
            const char *sets[] = {set, NULL};
            result r;
            if (run_file(path, sets, &r) != 0) continue;
            char exit[32] = "-";
            if (r.sm.outcome == CS_BREAKTHROUGH) snprintf(exit, sizeof exit, "%.2f m/s", r.sm.exit_speed);
            fprintf(md, "| %s | %s | %s | %.3f g | %.3f m | %s | %.2f%% |\n", crash_names[k], values[d],
                    cs_outcome_name(r.sm.outcome), r.sm.max_decel_50ms_g, r.sm.max_dynamic_penetration, exit,
                    100.0 * r.sm.energy_balance_error);
            double v[2] = {r.sm.max_decel_50ms_g, r.sm.max_dynamic_penetration};
            if (d == 0) memcpy(first, v, sizeof v);
            memcpy(last, v, sizeof v);
            char variant[64];
            snprintf(variant, sizeof variant, "%s %s", setting, values[d]);
            csv_row(csv, "convergence", crash_names[k], variant, &r);
        }
        fprintf(md, "| %s | %s -> %s | change | %+.1f%% | %+.1f%% | | |\n", crash_names[k], values[0],
                values[count - 1], rel_err(first[0], last[0]), rel_err(first[1], last[1]));
    }
}

static void write_convergence(FILE *md, FILE *csv, const char *examples) {
    static const char *const dts[] = {"0.5 ms", "0.25 ms", "0.1 ms", "0.05 ms"};
    static const char *const tols[] = {"1e-4", "1e-5", "1e-6"};
    fprintf(md, "## Time-step convergence\n\n");
    refinement_table(md, csv, examples, "dt", "dt", dts, 4);
    fprintf(md, "\nTarget (issue 4): changes under 2%%.\n\n## Solver-tolerance convergence\n\n"
                "The barrier solve stops when every relative residual is below solver_tolerance (default "
                "1e-4). A result that changes when the tolerance is tightened depends on the solver, not "
                "only on the model: read it as uncertain.\n\n");
    refinement_table(md, csv, examples, "solver_tolerance", "solver tolerance", tols, 3);
    fprintf(md, "\n");
}

static void write_sensitivity(FILE *md, FILE *csv, const char *examples) {
    static const struct {
        const char *what, *lo, *hi;
    } inputs[] = {
        {"impact speed 38-42 mph", "scenario.speed=38 mph", "scenario.speed=42 mph"},
        {"soil S1 6000-8000 psf", "barrier.soil.soil_pressure=6000 psf", NULL},
        {"line-post yield stress -10%/+10%", "barrier.posts[0].yield_stress=45 ksi",
         "barrier.posts[0].yield_stress=55 ksi"},
        {"cable-post friction 0.10-0.20", "barrier.cables[0].post_friction=0.1",
         "barrier.cables[0].post_friction=0.2"},
        {"pretension 2-8 kip", "barrier.cables[0].pretension=2 kip", "barrier.cables[0].pretension=8 kip"},
    };
    fprintf(
        md,
        "## Sensitivity to what the paper does not give\n\nEach input moved alone over its range (the other "
        "cable follows where a cable value is moved); the band of each response.\n\n| test | input | "
        "outcomes | "
        "max 50-ms decel | penetration |\n|---|---|---|---|---|\n");
    for (int k = 0; k < 3; k++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s.yaml", examples, crash_names[k]);
        for (size_t i = 0; i < sizeof inputs / sizeof inputs[0]; i++) {
            double dmin = HUGE_VAL, dmax = -HUGE_VAL, pmin = HUGE_VAL, pmax = -HUGE_VAL;
            char outcomes[96] = "";
            for (int side = 0; side < 2; side++) {
                const char *set = side ? inputs[i].hi : inputs[i].lo;
                if (!set) continue;
                char other[128];
                const char *sets[3] = {set, NULL, NULL};
                if (strstr(set, "cables[0]")) { /* the same value on the second cable */
                    snprintf(other, sizeof other, "%s", set);
                    other[strstr(set, "cables[0]") - set + 7] = '1';
                    sets[1] = other;
                }
                result r;
                if (run_file(path, sets, &r) != 0) continue;
                dmin = fmin(dmin, r.sm.max_decel_50ms_g), dmax = fmax(dmax, r.sm.max_decel_50ms_g);
                pmin = fmin(pmin, r.sm.max_dynamic_penetration),
                pmax = fmax(pmax, r.sm.max_dynamic_penetration);
                size_t n = strlen(outcomes);
                snprintf(outcomes + n, sizeof outcomes - n, "%s%s", n ? ", " : "",
                         cs_outcome_name(r.sm.outcome));
                csv_row(csv, "sensitivity", crash_names[k], set, &r);
            }
            fprintf(md, "| %s | %s | %s | %.2f-%.2f g | %.2f-%.2f m |\n", crash_names[k], inputs[i].what,
                    outcomes, dmin, dmax, pmin, pmax);
        }
    }
    fprintf(md, "\n");
}

static int wanted(const char *only, const char *part) {
    return !only || strstr(only, part) != NULL;
}

int cs_command_validate(int argc, char **argv) {
    const char *dir = "results/validation", *examples = "examples", *only = NULL;
    for (int i = 2; i < argc; i++) {
        const char **slot = strcmp(argv[i], "-o") == 0           ? &dir
                            : strcmp(argv[i], "--examples") == 0 ? &examples
                            : strcmp(argv[i], "--only") == 0     ? &only
                                                                 : NULL;
        if (!slot || i + 1 >= argc) {
            fprintf(stderr, "usage: cablesim validate [-o DIR] [--examples DIR] [--only "
                            "crash,bogie,verification,convergence,sensitivity]\n");
            return 2;
        }
        *slot = argv[++i];
    }
    char mdp[1024], csvp[1024], mdt[1040], csvt[1040];
    struct stat st;
    mkdir("results", 0777);
    if (mkdir(dir, 0777) != 0 && !(stat(dir, &st) == 0 && S_ISDIR(st.st_mode))) {
        fprintf(stderr, "cablesim validate: cannot create %s\n", dir);
        return 1;
    }
    snprintf(mdp, sizeof mdp, "%s/validation.md", dir);
    snprintf(csvp, sizeof csvp, "%s/validation.csv", dir);
    snprintf(mdt, sizeof mdt, "%s.tmp", mdp);
    snprintf(csvt, sizeof csvt, "%s.tmp", csvp);
    FILE *md = fopen(mdt, "w+"), *csv = fopen(csvt, "w");
    if (!md || !csv) {
        fprintf(stderr, "cablesim validate: cannot write in %s\n", dir);
        if (md) fclose(md), remove(mdt);
        if (csv) fclose(csv), remove(csvt);
        return 1;
    }
    time_t t0 = time(NULL);
    fprintf(md, "# cablesim validation\n\nOne parameter set for every case (docs/assumptions.md); nothing is "
                "tuned to "
                "a test. Written by `cablesim validate`.\n\n");
    fprintf(
        csv,
        "suite,case,variant,ok,outcome,max_50ms_decel_g,max_dynamic_penetration_m,exit_speed_mps,stop_time_s,"
        "cable1_break_s,cable2_break_s,posts_failed_left,posts_failed_right,energy_balance_error,"
        "energy_absorbed_j\n");
    result base[3];
    if (wanted(only, "crash")) write_crash(md, csv, examples, base);
    if (wanted(only, "bogie")) write_bogie(md, csv);
    if (wanted(only, "verification")) write_verification(md);
    if (wanted(only, "convergence")) write_convergence(md, csv, examples);
    if (wanted(only, "sensitivity")) write_sensitivity(md, csv, examples);
    fprintf(md, "Run time: %.0f s.\n", difftime(time(NULL), t0));
    int bad = ferror(md) || ferror(csv);
    bad |= fclose(md) != 0;
    bad |= fclose(csv) != 0;
    if (bad || rename(mdt, mdp) != 0 || rename(csvt, csvp) != 0) {
        remove(mdt), remove(csvt);
        fprintf(stderr, "cablesim validate: writing %s failed\n", dir);
        return 1;
    }
    printf("validation written to %s and %s (%.0f s)\n", mdp, csvp, difftime(time(NULL), t0));
    return 0;
}
