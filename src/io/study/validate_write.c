/* SPDX-License-Identifier: MIT */
/* The validation report's CSV rows and its other parts: the readings of what the design data leaves
 * open, the roadside predictions, the convergence tables and the sensitivity bands. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "cablesim/units.h"
#include "study/validate.h"

/* One CSV row: suite, case, variant, then the run's numbers; what does not apply is left empty (the
 * penetration of a vehicle through the barrier, or still going, is its penetration_beyond, as in
 * summary.json and runs.csv). */
void cs_validate_csv_row(FILE *csv, const char *suite, const char *name, const char *variant,
                         const cs_validate_result *r) {
    char exit[32] = "", stop[32] = "", b1[32] = "", b2[32] = "", pen[32] = "", beyond[32] = "";
    if (r->ok && cs_outcome_exits(r->sm.outcome)) snprintf(exit, sizeof exit, "%.6g", r->sm.exit_speed_mps);
    if (r->ok && r->sm.outcome == CS_STOPPED) snprintf(stop, sizeof stop, "%.6g", r->sm.stop_time_s);
    if (r->ok && r->cable_break[0] >= 0.0) snprintf(b1, sizeof b1, "%.6g", r->cable_break[0]);
    if (r->ok && r->cable_break[1] >= 0.0) snprintf(b2, sizeof b2, "%.6g", r->cable_break[1]);
    if (r->ok)
        snprintf(cs_penetration_is_final(r->sm.outcome) ? pen : beyond, sizeof pen, "%.6g",
                 r->sm.max_dynamic_penetration_m);
    if (!r->ok) {
        fprintf(csv, "%s,%s,\"%s\",0,failed,,,,,,,,,,,,,,,,,,,,\n", suite, name, variant);
        return;
    }
    char angle[32] = "";
    if (cs_outcome_exits(r->sm.outcome)) snprintf(angle, sizeof angle, "%.6g", r->sm.exit_angle_deg);
    const cs_summary *m = &r->sm;
    fprintf(csv, "%s,%s,\"%s\",1,%s,%.6g,%s,%s,%s,%s,%s,%d,%d,%d,%d,%d,%d,%d,%d,%.6g,%.6g,%.6g,%.6g,%s,%s\n",
            suite, name, variant, cs_outcome_name(m->outcome), m->max_50ms_decel_g, pen, exit, stop, b1, b2,
            m->posts_failed_left, m->posts_failed_right, m->posts_failed_rotation_left,
            m->posts_failed_rotation_right, m->posts_failed_shear_left, m->posts_failed_shear_right,
            m->posts_failed_pullout_left, m->posts_failed_pullout_right, m->energy_balance_error, r->absorbed,
            m->max_barrier_deflection_m, m->working_width_m, angle, beyond);
}

/* The largest penetration; for a run that got through or ended still going (its time limit, its solve
 * budget), how far it had got when the run ended: the penetration is beyond it (summary.json's
 * max_dynamic_penetration_m is null there, its penetration_beyond_m that value). */
const char *cs_validate_penetration_text(const cs_summary *m, char *buf, size_t n) {
    snprintf(buf, n, "%s%.2f m", cs_penetration_is_final(m->outcome) ? "" : "beyond ",
             m->max_dynamic_penetration_m);
    return buf;
}

double cs_validate_rel_err(double model, double test) {
    return 100.0 * (model - test) / fabs(test);
}

/* One table per refinement, and the change of the max 50-ms deceleration and the penetration from the
 * first value to the last. A run that failed has no row. Returns the largest change in magnitude, %
 * (HUGE_VAL if a test has no first or last run to compare). */
static double refinement_table(FILE *md, FILE *csv, const cs_validate_suite *s, int t) {
    double worst = 0.0;
    const char *const *values = cs_validate_refinements[t].values;
    int count = cs_validate_refinements[t].count;
    fprintf(md,
            "| test | %s | outcome | max 50-ms decel | penetration | exit speed | ledger error |\n"
            "|---|---|---|---|---|---|---|\n",
            cs_validate_refinements[t].label);
    for (int k = 0; k < CS_VAL_CRASH; k++) {
        for (int d = 0; d < count; d++) {
            const cs_validate_result *r = &s->jobs[s->refine[t][k][d]].r;
            if (!r->ok) continue;
            char exit[32] = "-";
            if (cs_outcome_through(r->sm.outcome))
                snprintf(exit, sizeof exit, "%.2f m/s", r->sm.exit_speed_mps);
            fprintf(md, "| %s | %s | %s | %.3f g | %s%.3f m | %s | %.2f%% |\n", cs_validate_crash_names[k],
                    values[d], cs_outcome_name(r->sm.outcome), r->sm.max_50ms_decel_g,
                    cs_penetration_is_final(r->sm.outcome) ? "" : "beyond ", r->sm.max_dynamic_penetration_m,
                    exit, 100.0 * r->sm.energy_balance_error);
            char variant[64];
            snprintf(variant, sizeof variant, "%s %s", cs_validate_refinements[t].setting, values[d]);
            cs_validate_csv_row(csv, "convergence", cs_validate_crash_names[k], variant, r);
        }
        const cs_validate_result *a = &s->jobs[s->refine[t][k][0]].r,
                                 *b = &s->jobs[s->refine[t][k][count - 1]].r;
        if (!a->ok || !b->ok) {
            worst = HUGE_VAL;
            continue;
        }
        /* the change on refining, as the arrow reads: the finest value against the coarsest */
        double decel = cs_validate_rel_err(b->sm.max_50ms_decel_g, a->sm.max_50ms_decel_g),
               pen = cs_validate_rel_err(b->sm.max_dynamic_penetration_m, a->sm.max_dynamic_penetration_m);
        fprintf(md, "| %s | %s -> %s | change | %+.1f%% | %+.1f%% | | |\n", cs_validate_crash_names[k],
                values[0], values[count - 1], decel, pen);
        worst = fmax(worst, fmax(fabs(decel), fabs(pen)));
    }
    return worst;
}

/* The largest change of each roadside response over the tests, in %, and the test of each. */
typedef struct road_worst {
    double change[3]; /* deflection, exit speed, exit angle */
    const char *test[3];
} road_worst;

/* The change in deflection, exit speed and exit angle from run a to run b, as a row of the table, kept in
 * w where it is the largest yet; the largest of the three, in %. */
static double road_change(FILE *md, const char *name, const char *to, const cs_summary *a,
                          const cs_summary *b, road_worst *w) {
    double c[3] = {cs_validate_rel_err(b->max_barrier_deflection_m, a->max_barrier_deflection_m),
                   cs_validate_rel_err(b->exit_speed_mps, a->exit_speed_mps),
                   cs_validate_rel_err(b->exit_angle_deg, a->exit_angle_deg)};
    fprintf(md, "| %s | its file's -> %s | change | %+.1f%% | %+.1f%% | %+.1f%% | |\n", name, to, c[0], c[1],
            c[2]);
    for (int i = 0; i < 3; i++)
        if (fabs(c[i]) >= w->change[i]) w->change[i] = fabs(c[i]), w->test[i] = name;
    return fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2])));
}

/* The roadside tests at their file's step and the finer ones: deflection, exit speed and angle, and their
 * change from the file's step to the first finer one (half of it) and to the finest (a fifth of it).
 * The largest change to the first, or HUGE_VAL if a run failed, -1 if none ran, each response's in *half;
 * *finest the largest to the finest, each response's in *fine. */
static double road_step_table(FILE *md, FILE *csv, const cs_validate_suite *s, double *finest,
                              road_worst *half, road_worst *fine) {
    double worst = -1.0;
    *finest = -1.0;
    for (int k = 0; k < CS_VAL_ROAD; k++) {
        if (s->road[k] < 0 || s->road_step[k][0] < 0) continue;
        if (worst < 0.0)
            fprintf(md,
                    "\nThe roadside tests (the exit at the last loss of contact):\n\n"
                    "| test | dt | outcome | max dynamic deflection | exit speed | exit angle | ledger error "
                    "|\n|---|---|---|---|---|---|---|\n");
        worst = fmax(worst, 0.0);
        const cs_validate_result *r[1 + CS_VAL_ROAD_STEPS];
        r[0] = &s->jobs[s->road[k]].r;
        for (int d = 0; d < CS_VAL_ROAD_STEPS; d++)
            r[1 + d] = &s->jobs[s->road_step[k][d]].r;
        int ok = 1;
        for (int d = 0; d <= CS_VAL_ROAD_STEPS; d++) {
            char dt[32], exit[32] = "-", angle[32] = "-";
            if (d == 0)
                snprintf(dt, sizeof dt, "%.4g ms (its file's)", 1e3 * r[0]->dt);
            else
                snprintf(dt, sizeof dt, "%.4g ms", 1e3 * r[d]->dt);
            ok &= r[d]->ok && cs_outcome_exits(r[d]->sm.outcome);
            if (!r[d]->ok) {
                fprintf(md, "| %s | %s | failed | | | | |\n", cs_validate_road_names[k], dt);
                continue;
            }
            if (cs_outcome_exits(r[d]->sm.outcome)) {
                snprintf(exit, sizeof exit, "%.2f m/s", r[d]->sm.exit_speed_mps);
                snprintf(angle, sizeof angle, "%.2f deg", r[d]->sm.exit_angle_deg);
            }
            fprintf(md, "| %s | %s | %s | %.3f m | %s | %s | %.2f%% |\n", cs_validate_road_names[k], dt,
                    cs_outcome_name(r[d]->sm.outcome), r[d]->sm.max_barrier_deflection_m, exit, angle,
                    100.0 * r[d]->sm.energy_balance_error);
            char variant[64];
            snprintf(variant, sizeof variant, "dt %s", dt);
            cs_validate_csv_row(csv, "convergence", cs_validate_road_names[k], variant, r[d]);
        }
        if (!ok) {
            worst = *finest = HUGE_VAL;
            continue;
        }
        char to[2][32];
        snprintf(to[0], sizeof to[0], "%.4g ms", 1e3 * r[1]->dt);
        snprintf(to[1], sizeof to[1], "%.4g ms", 1e3 * r[CS_VAL_ROAD_STEPS]->dt);
        worst = fmax(worst, road_change(md, cs_validate_road_names[k], to[0], &r[0]->sm, &r[1]->sm, half));
        *finest = fmax(*finest, road_change(md, cs_validate_road_names[k], to[1], &r[0]->sm,
                                            &r[CS_VAL_ROAD_STEPS]->sm, fine));
    }
    return worst;
}

/* " Largest by response: deflection x% (test), exit speed ..., exit angle ...", ending the line. */
static void by_response(FILE *md, const road_worst *w) {
    static const char *const what[3] = {"deflection", "exit speed", "exit angle"};
    for (int i = 0; i < 3; i++)
        fprintf(md, "%s %s %.1f%% (%s)%s", i ? "," : " Largest by response:", what[i],
                round(10.0 * w->change[i]) / 10.0, w->test[i] ? w->test[i] : "-", i == 2 ? ".\n" : "");
}

void cs_validate_write_convergence(FILE *md, FILE *csv, const cs_validate_suite *s) {
    fprintf(md, "## Time-step convergence\n\n");
    double worst = refinement_table(md, csv, s, 0);
    if (worst < HUGE_VAL)
        fprintf(md, "\nTarget: changes under 2%%: %s (largest %.1f%%).%s\n", worst < 2.0 ? "met" : "NOT met",
                worst,
                worst < 2.0
                    ? ""
                    : " A change much larger than its neighbours' may be a failure that the barrier can meet "
                      "in two ways (e.g. an end post folding or not), taken differently at one step: "
                      "docs/theory.md, the barrier solve's known limitations.");
    else
        fprintf(md, "\nTarget: changes under 2%%: NOT met (a run failed).\n");
    road_worst half = {{0.0}, {NULL}}, by_fine = {{0.0}, {NULL}};
    double fine, road = road_step_table(md, csv, s, &fine, &half, &by_fine);
    if (road >= 0.0 && road < HUGE_VAL) {
        road = round(10.0 * road) / 10.0, fine = round(10.0 * fine) / 10.0; /* judged as printed */
        fprintf(md, "\nTarget: changes under 2%% as each file's step halves: %s (largest %.1f%%).",
                road < 2.0 ? "met" : "NOT met", road);
        by_response(md, &half);
        fprintf(md, "On to a fifth of each file's step: largest change %.1f%%.", fine);
        by_response(md, &by_fine);
        /* judged as printed, each response */
        double exit = fmax(fmax(half.change[1], half.change[2]), fmax(by_fine.change[1], by_fine.change[2])),
               defl = fmax(half.change[0], by_fine.change[0]);
        if (round(10.0 * exit) / 10.0 >= 2.0)
            fprintf(md,
                    "An exit that moves more follows a change in which ropes the slots and hooks let go, and "
                    "when: each release is a threshold of a post's lean or a rope's pull, which a run near "
                    "it takes or misses as the step changes, and the releases after it follow: "
                    "docs/theory.md, Known limitations: the roadside tests.\n");
        if (round(10.0 * defl) / 10.0 >= 2.0)
            fprintf(md, "A deflection that moves more with the step is not converged: read it as uncertain "
                        "(docs/theory.md, Known limitations: the roadside tests).\n");
    } else if (road == HUGE_VAL)
        fprintf(md, "\nTarget: changes under 2%%: NOT met (a run failed or did not leave the barrier).\n");
    fprintf(md, "\n## Solver-tolerance convergence\n\n"
                "The barrier solve stops when every relative residual is below solver_tolerance (default "
                "1e-4). A result that changes when the tolerance is tightened depends on the solver, not "
                "only on the model: read it as uncertain.\n\n");
    refinement_table(md, csv, s, 1);
    fprintf(md, "\n");
}

/* The least and greatest of a response over some runs, and how many runs had none (a rope that did not
 * break, an exit speed of a truck that stopped). */
typedef struct band {
    double lo, hi;
    int none;
} band;

static band band_empty(void) {
    return (band){HUGE_VAL, -HUGE_VAL, 0};
}

static void band_add(band *b, double v, int has) {
    if (!has) {
        b->none++;
        return;
    }
    b->lo = fmin(b->lo, v), b->hi = fmax(b->hi, v);
}

static const char *band_text(const band *b, double scale, const char *fmt, const char *unit, const char *none,
                             char *buf, size_t n) {
    char lo[32], hi[32];
    if (b->lo > b->hi) {
        snprintf(buf, n, "%s", none);
        return buf;
    }
    snprintf(lo, sizeof lo, fmt, b->lo / scale);
    snprintf(hi, sizeof hi, fmt, b->hi / scale);
    snprintf(buf, n, "%s-%s %s%s%s", lo, hi, unit, b->none ? "; " : "", b->none ? none : "");
    return buf;
}

/* The bands of the response parameters over a set of runs. */
typedef struct bands {
    band decel, pen, exit, brk[2];
    int runs, through;
} bands;

static void bands_add(bands *b, const cs_validate_result *r) {
    if (!r->ok) return;
    b->runs++;
    b->through += cs_outcome_through(r->sm.outcome);
    band_add(&b->decel, r->sm.max_50ms_decel_g, 1);
    band_add(&b->pen, r->sm.max_dynamic_penetration_m, 1);
    band_add(&b->exit, r->sm.exit_speed_mps, cs_outcome_through(r->sm.outcome));
    for (int c = 0; c < 2; c++)
        band_add(&b->brk[c], r->cable_break[c], r->cable_break[c] >= 0.0);
}

static bands bands_empty(void) {
    return (bands){band_empty(), band_empty(), band_empty(), {band_empty(), band_empty()}, 0, 0};
}

/* "| decel | penetration | exit speed | cable 0 | cable 1 |" of a table row. */
static void write_bands(FILE *md, const bands *b) {
    char t[5][96];
    fprintf(md, " %s | %s | %s | %s | %s |\n", band_text(&b->decel, 1.0, "%.2f", "g", "-", t[0], sizeof t[0]),
            band_text(&b->pen, 1.0, "%.2f", "m", "-", t[1], sizeof t[1]),
            band_text(&b->exit, CS_MPH, "%.1f", "mph", "stopped", t[2], sizeof t[2]),
            band_text(&b->brk[0], 1.0, "%.3f", "s", "unbroken", t[3], sizeof t[3]),
            band_text(&b->brk[1], 1.0, "%.3f", "s", "unbroken", t[4], sizeof t[4]));
}

/* Is the measured value v inside band b (scaled to the measured unit)? */
static const char *inside(const band *b, double scale, double v) {
    return b->lo <= b->hi && v >= b->lo / scale && v <= b->hi / scale ? "inside" : "OUTSIDE";
}

void cs_validate_write_sensitivity(FILE *md, FILE *csv, const cs_validate_suite *s) {
    const cs_crash_values *t = &s->data.aps1_test;
    char variant[512];
    fprintf(md,
            "## Sensitivity to what the paper does not give\n\nEach input moved alone to either end of its "
            "range (the other cable follows where a cable value is moved); the band of each response over "
            "the two ends and the file's own value (a response need not be monotone in an input). "
            "Exit speeds are those of the runs that broke through; \"unbroken\": some runs kept that "
            "rope.\n\n| test | input | outcomes (low, high) | max 50-ms decel | penetration | exit speed | "
            "cable 0 broke | cable 1 broke |\n|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < CS_VAL_CRASH; k++) {
        const cs_validate_result *base = s->base[k] >= 0 ? &s->jobs[s->base[k]].r : NULL;
        for (int i = 0; i < CS_VAL_INPUTS; i++) {
            bands b = bands_empty();
            if (base) bands_add(&b, base);
            char outcomes[96] = "";
            for (int side = 0; side < 2; side++) {
                const cs_validate_result *r = &s->jobs[s->sensitivity[k][i][side]].r;
                size_t n = strlen(outcomes);
                snprintf(outcomes + n, sizeof outcomes - n, "%s%s", n ? ", " : "",
                         r->ok ? cs_outcome_name(r->sm.outcome) : "failed");
                bands_add(&b, r);
                cs_validate_input_text(i, side, variant, sizeof variant);
                cs_validate_csv_row(csv, "sensitivity", cs_validate_crash_names[k], variant, r);
            }
            fprintf(md, "| %s | %s | %s |", cs_validate_crash_names[k], cs_validate_inputs[i].what, outcomes);
            write_bands(md, &b);
        }
    }
    fprintf(md,
            "\nAll six inputs at once: a %d-run Latin hypercube per test, each input uniform over its range "
            "(seed %d + the test's index). The band of each response over those runs:\n\n"
            "| test | runs | broke through | max 50-ms decel | penetration | exit speed | cable 0 broke | "
            "cable 1 broke |\n|---|---|---|---|---|---|---|---|\n",
            CS_VAL_JOINT, CS_VAL_JOINT_SEED);
    bands aps1 = bands_empty();
    for (int k = 0; k < CS_VAL_CRASH; k++) {
        bands b = bands_empty();
        for (int j = 0; j < CS_VAL_JOINT; j++) {
            const cs_validate_result *r = &s->jobs[s->joint[k][j]].r;
            bands_add(&b, r);
            variant[0] = '\0';
            for (int i = 0; i < CS_VAL_INPUTS; i++) { /* the overrides of the run, "; "-separated */
                size_t len = strlen(variant);
                if (len) snprintf(variant + len, sizeof variant - len, "; ");
                len = strlen(variant);
                cs_validate_input_text(i, s->joint_u[k][j][i], variant + len, sizeof variant - len);
            }
            cs_validate_csv_row(csv, "joint", cs_validate_crash_names[k], variant, r);
        }
        if (k == 0) aps1 = b;
        fprintf(md, "| %s | %d | %d |", cs_validate_crash_names[k], b.runs, b.through);
        write_bands(md, &b);
    }
    fprintf(md,
            "\nAPS1's crash test against its joint band: deceleration %.3f g %s, exit speed %.1f mph %s, "
            "the test's cable 1 broke at %.3f s %s (the model's cable 0), its cable 2 at %.3f s %s (the "
            "model's cable 1). A measured value well outside the sampled "
            "band is a miss that these inputs, within their ranges, do not explain: it lies in the model "
            "(docs/theory.md, \"APS1's miss\").\n\n",
            t->decel_g, inside(&aps1.decel, 1.0, t->decel_g), t->exit_mph,
            inside(&aps1.exit, CS_MPH, t->exit_mph), t->brk[0], inside(&aps1.brk[0], 1.0, t->brk[0]),
            t->brk[1], inside(&aps1.brk[1], 1.0, t->brk[1]));
}

/* A row of the readings' table: outcome, deceleration, penetration, exit speed, breaks, anchors, posts. */
static void reading_row(FILE *md, const char *name, const char *what, const cs_validate_result *r) {
    if (!r->ok) {
        fprintf(md, "| %s | %s | failed | | | | | | | |\n", name, what);
        return;
    }
    char exit[32] = "-", pen[32], slid[48] = "rigid";
    if (cs_outcome_through(r->sm.outcome))
        snprintf(exit, sizeof exit, "%.1f mph", r->sm.exit_speed_mps / CS_MPH);
    if (r->slide[0] >= 0.0) snprintf(slid, sizeof slid, "%.2f, %.2f m", r->slide[0], r->slide[1]);
    const cs_summary *m = &r->sm;
    fprintf(md, "| %s | %s | %s | %.2f g | %s | %s | %s; %s | %s | %d + %d / %d + %d / %d + %d |\n", name,
            what, cs_outcome_name(m->outcome), m->max_50ms_decel_g,
            cs_validate_penetration_text(m, pen, sizeof pen), exit, r->how[0], r->how[1], slid,
            m->posts_failed_rotation_left, m->posts_failed_rotation_right, m->posts_failed_shear_left,
            m->posts_failed_shear_right, m->posts_failed_pullout_left, m->posts_failed_pullout_right);
}

void cs_validate_write_readings(FILE *md, FILE *csv, const cs_validate_suite *s) {
    fprintf(md, "## Readings of what the design data leaves open\n\n"
                "Each crash test as its file reads the design (docs/assumptions.md) and under each other "
                "documented reading of a part the paper leaves open, one at a time; then the band of each "
                "response over all of them. APS3 and APS4 stay blind predictions.\n\n"
                "| test | reading | outcome | max 50-ms decel | penetration | exit speed | cable 0; cable 1 "
                "(broke where "
                "and when, or held at its peak tension) | dead-men's plastic slide (start, end) | posts "
                "failed, left + "
                "right: rotation / shear / pullout |\n|---|---|---|---|---|---|---|---|---|\n");
    bands all[CS_VAL_CRASH];
    for (int k = 0; k < CS_VAL_CRASH; k++) {
        all[k] = bands_empty();
        const cs_validate_result *base = &s->jobs[s->base[k]].r;
        bands_add(&all[k], base);
        reading_row(md, cs_validate_crash_names[k], "as the file reads the design", base);
        for (int r = 0; r < CS_VAL_READINGS; r++) {
            if (s->reading[k][r] < 0) continue;
            const cs_validate_result *rr = &s->jobs[s->reading[k][r]].r;
            bands_add(&all[k], rr);
            reading_row(md, cs_validate_crash_names[k], cs_validate_readings[r].what, rr);
            cs_validate_csv_row(csv, "reading", cs_validate_crash_names[k], cs_validate_readings[r].what, rr);
        }
    }
    fprintf(
        md,
        "\nThe band over the readings (the penetration of a run that got through is where it was when the "
        "run ended, less than the real one):\n\n| test | runs | broke through | max 50-ms decel | "
        "penetration | "
        "exit speed | cable 0 broke | cable 1 broke |\n|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < CS_VAL_CRASH; k++) {
        fprintf(md, "| %s | %d | %d |", cs_validate_crash_names[k], all[k].runs, all[k].through);
        write_bands(md, &all[k]);
    }
    const cs_crash_values *t = &s->data.aps1_test;
    fprintf(
        md,
        "\nAPS1's crash test against the band of its readings: deceleration %.3f g %s, exit speed %.1f mph "
        "%s, the test's cable 1 broke at %.3f s %s (the model's cable 0), its cable 2 at %.3f s %s (the "
        "model's "
        "cable 1).\n\n",
        t->decel_g, inside(&all[0].decel, 1.0, t->decel_g), t->exit_mph,
        inside(&all[0].exit, CS_MPH, t->exit_mph), t->brk[0], inside(&all[0].brk[0], 1.0, t->brk[0]),
        t->brk[1], inside(&all[0].brk[1], 1.0, t->brk[1]));
}

/* A roadside run's row: outcome, deflection, working width, exit speed and angle, releases, posts; then
 * `more` (further columns, each ending in "|"). */
static void road_row(FILE *md, const char *name, const char *what, const cs_validate_result *r,
                     const char *more) {
    if (!r->ok) {
        fprintf(md, "| %s | %s | failed | | | | | |%s\n", name, what, more);
        return;
    }
    const cs_summary *m = &r->sm;
    char exit[48] = "-";
    if (cs_outcome_exits(m->outcome))
        snprintf(exit, sizeof exit, "%.1f km/h at %.1f deg", m->exit_speed_mps * 3.6, m->exit_angle_deg);
    fprintf(md, "| %s | %s | %s | %.2f m (%.1f ft) | %.2f m (%.1f ft) | %s | %d | %d |%s\n", name, what,
            cs_outcome_name(m->outcome), m->max_barrier_deflection_m, m->max_barrier_deflection_m / CS_FT,
            m->working_width_m, m->working_width_m / CS_FT, exit, r->released,
            m->posts_failed_left + m->posts_failed_right, more);
}

void cs_validate_write_roadside(FILE *md, FILE *csv, const cs_validate_suite *s) {
    fprintf(
        md,
        "## Roadside crash tests: blind predictions\n\n"
        "Six NCHRP Report 350 test 3-11 crash tests (2000-kg pickup, about 100 km/h and 25 degrees) of "
        "roadside cable barriers, `examples/roadside/rs*.yaml`, each built from its design data "
        "(shared/reference/data/roadside-tests.md) with the readings of docs/assumptions.md. The "
        "measured deflections are withheld: each prediction stands beside an empty column. Deflection is "
        "the largest lateral displacement of any cable from its line; the working width adds the "
        "vehicle's and the posts' reach. RS6 stands 1.22 m from the break of a 1.5H:1V slope: the "
        "model's ground is flat.\n\n"
        "| test | reading | outcome | max dynamic deflection | working width | exit | cables let go | posts "
        "failed | measured deflection |\n|---|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < CS_VAL_ROAD; k++) {
        if (s->road[k] < 0) continue;
        const cs_validate_result *r = &s->jobs[s->road[k]].r;
        road_row(md, cs_validate_road_names[k], "as the file reads the design", r, " withheld |");
        cs_validate_csv_row(csv, "roadside", cs_validate_road_names[k], "", r);
    }
    fprintf(md,
            "\nUnder each other documented reading of what the data leaves open, one at a time, and the band "
            "of the deflection over all of them:\n\n| test | reading | outcome | max dynamic deflection | "
            "working width | exit | cables let go | posts failed |\n|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < CS_VAL_ROAD; k++) {
        if (s->road[k] < 0) continue;
        const cs_validate_result *base = &s->jobs[s->road[k]].r;
        double lo = base->ok ? base->sm.max_barrier_deflection_m : HUGE_VAL, hi = base->ok ? lo : -HUGE_VAL;
        for (int r = 0; r < CS_VAL_ROAD_READINGS; r++) {
            if (s->road_reading[k][r] < 0) continue;
            const cs_validate_result *rr = &s->jobs[s->road_reading[k][r]].r;
            road_row(md, cs_validate_road_names[k], cs_validate_road_readings[r].what, rr, "");
            cs_validate_csv_row(csv, "roadside reading", cs_validate_road_names[k],
                                cs_validate_road_readings[r].what, rr);
            if (rr->ok)
                lo = fmin(lo, rr->sm.max_barrier_deflection_m),
                hi = fmax(hi, rr->sm.max_barrier_deflection_m);
        }
        if (lo <= hi)
            fprintf(md, "| %s | **band** | | %.2f-%.2f m | | | | |\n", cs_validate_road_names[k], lo, hi);
    }
    fprintf(md, "\n");
}
