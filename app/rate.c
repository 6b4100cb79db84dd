/* SPDX-License-Identifier: MIT */
/* `cablesim rate`: run a standard's test condition against the barrier of a model file.
 * - Anti-ram (sd-std-02.01, sd-std-02.01a, astm-f2656): the model's vehicle (after --set), which must be
 *   one the standard tests (ASTM F2656: C, PU, M, H by mass within 5%; SD-STD: the 15,000-lb truck, M), at
 *   its class's speeds, head-on at the model's impact point; the rating, as the standard measures
 *   penetration (src/io/study/rating.c, docs/ratings.md). Without --class it starts from the class's
 *   highest speed and stops at the first at which the vehicle is stopped (and rated).
 * - Roadside (nchrp-350, mash): the tests of a test level (--level 3 or 4) or one (--test 3-11): vehicle,
 *   speed and angle at the model's impact point; each test's outcome, dynamic deflection, working width,
 *   exit speed and angle, its occupant risk, and each evaluation criterion of its standard judged
 *   (study/criteria.c) or listed as not judged; then whether the barrier contained and redirected the
 *   vehicle in every test and which criteria failed or were not judged. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/loader.h"
#include "cablesim/output.h"
#include "cablesim/units.h"
#include "cli.h"
#include "commands.h"
#include "study/criteria.h"
#include "study/occupant.h"
#include "study/rating.h"

static const char rate_usage[] =
    "Usage: cablesim rate FILE --standard astm-f2656|sd-std-02.01|sd-std-02.01a [--class CLASS]\n"
    "                     [--set PATH=VALUE]... [--allow-path DIR]...\n"
    "  or:  cablesim rate FILE --standard nchrp-350|mash [--level 3|4 | --test 3-11] [--set PATH=VALUE]...\n"
    "                     [--allow-path DIR]...\n"
    "Runs a standard's test conditions against the barrier of FILE, at its impact point, and reads each\n"
    "result as the standard does (docs/ratings.md).\n"
    "Anti-ram: the test vehicle is the model's (after --set), head-on. ASTM F2656 tests C, PU, M and H (a\n"
    "vehicle within 5% of 1,100, 2,300, 6,800 or 29,500 kg), SD-STD-02.01 and its revision A the\n"
    "15,000-lb truck (M); --set vehicle=PU rates the library's PU. Without --class the class's speeds run\n"
    "from the highest and stop at the first at which the vehicle is stopped; --class runs one: C40 C50 C60\n"
    "PU40 PU50 PU60 M30 M40 M50 H30 H40 H50 (ASTM F2656), K4 K8 K12 (SD-STD).\n"
    "Each row gives its trial's designation as run; the last line, the rating: the first designation\n"
    "(from the highest speed) with the vehicle stopped, else the lowest speed's.\n"
    "Roadside: each test's own vehicle, speed and angle: --level 3 (the default: x-10 and x-11) or 4 (and\n"
    "4-12), or one --test (3-10, 3-11, 4-10, 4-11, 4-12); each test's occupant risk (OIV, ORA, THIV, PHD,\n"
    "ASI) and every evaluation criterion of the standard: pass, FAIL, or not judged where the model cannot\n"
    "tell (debris, compartment deformation, the path after the loss of contact).\n"
    "--allow-path DIR: the files FILE names may be in DIR, as for cablesim run.\n"
    "Exit status: 0 done, 1 a run failed, 2 a bad model or command line.\n";

static const cs_cli rate_cli = {"rate", rate_usage};

/* The tally of a test level's criteria: failed and not-judged letters, each once. */
typedef struct criteria_tally {
    int contained, redirected, through;
    const char *unfinished; /* how a run that ended mid-collision ended (its outcome), or NULL */
    char failed[96], not_judged[96];
} criteria_tally;

static void tally_add(char *buf, size_t size, const char *id) {
    char key[16];
    snprintf(key, sizeof key, "%s,", id);
    if (strstr(buf, key)) return;
    size_t n = strlen(buf);
    snprintf(buf + n, size - n, "%s", key);
}

/* One roadside test at the model's impact point; its row, its criteria and its occupant risk printed.
 * Returns 0, 1 if the run failed, 2 if its vehicle is not in the library. */
static int roadside_one(cs_loader *l, const cs_model_input *in, const cs_roadside_test *t,
                        criteria_tally *tl) {
    cs_vehicle_def v;
    if (cs_loader_part(l, CS_PART_VEHICLE, t->vehicle, &v) != 0) {
        cs_loader_print_errors(l, stderr);
        return 2;
    }
    cs_scenario_def sc = in->scenario;
    sc.speed = t->speed, sc.angle = t->angle;
    cs_error err = {0};
    cs_model *m = cs_model_create(&in->barrier, &v, &sc, &err);
    cs_state *s = m ? cs_state_create(m, &err) : NULL;
    cs_record *rec = s ? cs_record_create(m, &err) : NULL;
    int rc = (rec && cs_run(m, s, cs_record_frame, rec, &err) == CS_OK && cs_record_ok(rec)) ? 0 : 1;
    if (rc) {
        fprintf(stderr, "cablesim rate: test %s: %s\n", t->name,
                err.message[0] ? err.message : "out of memory");
    } else {
        cs_summary sm = {.size = sizeof sm};
        cs_state_summary(s, &sm, NULL);
        cs_roadside_result r = cs_roadside_read(t, &sm);
        char exit[128] = "no exit";
        if (r.exit_speed_mps >= 0.0)
            snprintf(exit, sizeof exit, "exit %.1f km/h (%.1f mph) at %.1f deg", r.exit_speed_mps * 3.6,
                     r.exit_speed_mps / CS_MPH, r.exit_angle_deg);
        printf(
            "  %-4s %-6s %3.0f km/h %2.0f deg  %-12s deflection %.2f m (%.1f ft)  working width %.2f m (%.1f "
            "ft)  %s\n",
            t->name, t->vehicle, t->speed * 3.6, t->angle * 180 / CS_PI, cs_outcome_name(sm.outcome),
            r.deflection, r.deflection / CS_FT, r.working_width_m, r.working_width_m / CS_FT, exit);
        cs_occupant_risk o;
        cs_error err = {CS_OK, ""};
        int have = cs_occupant_risk_for_run(rec, sm.first_contact_time_s, NULL, &o, &err) == CS_OK;
        cs_exit_box box;
        cs_exit_box_of_record(rec, &v, sc.impact_x, sm.outcome == CS_REDIRECTED ? sm.exit_time_s : -1.0,
                              &box);
        cs_test_result res = {&sm, have ? &o : NULL, err.message, 0.0, 0.0, &box, s};
        cs_record_roll_pitch_peaks(rec, &res.roll_peak, &res.pitch_peak);
        if (have)
            printf("       occupant risk (CG, CFC 180): OIV %.2f / %.2f m/s at %.3f s after first contact%s, "
                   "ORA %.2f / %.2f g (longitudinal / lateral); THIV %.1f km/h, PHD %.2f g, ASI %.2f\n",
                   o.oiv_x, o.oiv_y, o.t_impact,
                   o.impact == CS_FLAIL_AFTER_RECORD ? " (after the run's end)" : "", o.ora_x, o.ora_y,
                   o.thiv * 3.6, o.phd, o.asi);
        cs_criterion c[CS_CRITERIA_MAX];
        int n = cs_roadside_criteria(t, &res, c);
        for (int k = 0; k < n; k++) {
            printf("       %-8s %-10s %s: %s\n", c[k].id, cs_verdict_name(c[k].verdict), c[k].name,
                   c[k].detail);
            if (c[k].verdict == CS_VERDICT_FAIL) tally_add(tl->failed, sizeof tl->failed, c[k].id);
            if (c[k].verdict == CS_VERDICT_NOT_JUDGED)
                tally_add(tl->not_judged, sizeof tl->not_judged, c[k].id);
        }
        if (!r.contained) tl->contained = 0;
        if (cs_outcome_through(sm.outcome))
            tl->through = 1;
        else if (!r.contained && !tl->unfinished)
            tl->unfinished = cs_outcome_name(sm.outcome);
        if (!r.redirected) tl->redirected = 0;
    }
    cs_record_free(rec);
    cs_state_free(s);
    cs_model_free(m);
    return rc;
}

/* A tally's list "A,D," as "A, D". */
static const char *listed(char *buf) {
    size_t n = strlen(buf);
    if (n && buf[n - 1] == ',') buf[n - 1] = '\0';
    for (char *p = buf; (p = strchr(p, ',')) != NULL;) {
        memmove(p + 2, p + 1, strlen(p + 1) + 1);
        p[1] = ' ';
        p += 2;
    }
    return buf;
}

/* `rate` for nchrp-350 and mash. */
static int rate_roadside(cs_loader *l, const char *file, const char *standard, const char *level,
                         const char *test) {
    cs_roadside_test t[3];
    int lv = level ? atoi(level) : (test ? 0 : 3);
    int n = cs_roadside_tests(standard, lv, test, t);
    if (n == 0 || (level && lv != 3 && lv != 4))
        return cs_cli_usage_error(
            &rate_cli, "%s", test ? "unknown test (3-10, 3-11, 4-10, 4-11 or 4-12)" : "--level takes 3 or 4");
    cs_model_input in = {.size = sizeof in};
    if (cs_loader_load(l, file, &in) != 0) {
        cs_loader_print_errors(l, stderr);
        return 2;
    }
    printf("%s against %s (impact at x = %.2f m, the %s):\n", in.name, standard, in.scenario.impact_x,
           in.scenario.impact_at_corner ? "leading front corner" : "centre of the front face");
    criteria_tally tl = {1, 1, 0, NULL, "", ""};
    int rc = 0;
    for (int k = 0; k < n && rc == 0; k++)
        rc = roadside_one(l, &in, &t[k], &tl);
    if (rc == 0) {
        const char *what = test ? test : (lv == 4 ? "TL-4" : "TL-3");
        if (tl.through)
            printf("%s: NOT contained in every test (the vehicle got through)\n", what);
        else if (tl.unfinished) /* neither contained nor through: the run ended before the collision did */
            printf("%s: not known to be contained in every test (a run ended mid-collision: %s)\n", what,
                   tl.unfinished);
        else
            printf("%s: %s\n", what,
                   !tl.redirected
                       ? "contained in every test, NOT redirected in every test (the vehicle stopped)"
                       : "contained and redirected in every test");
        if (tl.failed[0])
            printf("%s: criteria failed: %s\n", what, listed(tl.failed));
        else
            printf("%s: every judged criterion passed\n", what);
        if (tl.not_judged[0])
            printf("%s: not judged (the model cannot tell; no pass implied): %s\n", what,
                   listed(tl.not_judged));
    }
    return rc;
}

/* One anti-ram trial: the model's barrier and vehicle, head-on at mph; its row printed. 0, or 1 if the run
 * failed. */
static int rate_one(const cs_model_input *in, cs_standard std, const char *klass, int mph, cs_rating *out) {
    cs_scenario_def sc = in->scenario;
    sc.speed = mph * CS_MPH;
    sc.angle = 0.5 * CS_PI; /* the standards' head-on impact */
    cs_error err = {0};
    cs_model *m = cs_model_create(&in->barrier, &in->vehicle, &sc, &err);
    cs_state *s = m ? cs_state_create(m, &err) : NULL;
    int rc = (s && cs_run(m, s, NULL, NULL, &err) == CS_OK) ? 0 : 1;
    if (rc) {
        fprintf(stderr, "cablesim rate: %s at %d mph: %s\n", klass, mph, err.message);
    } else {
        cs_summary sm = {.size = sizeof sm};
        cs_state_summary(s, &sm, NULL);
        cs_rating_rules rules = cs_default_rating_rules();
        *out = cs_rate_run(std, klass, sc.speed, &sm, &in->vehicle, &rules);
        char pen[64];
        if (out->through)
            snprintf(pen, sizeof pen, "through the barrier");
        else if (isnan(out->penetration))
            snprintf(pen, sizeof pen, "not measured");
        else
            snprintf(pen, sizeof pen, "%.2f m (%.1f ft)", out->penetration, out->penetration / CS_FT);
        printf("  %-4s %2d mph  %-12s penetration %-22s designation as run %s\n", klass, mph,
               cs_outcome_name(sm.outcome), pen, out->label);
    }
    cs_state_free(s);
    cs_model_free(m);
    return rc;
}

/* The classes a standard tests, as --class takes them, into buf: "C40, C50, ..., H50" or "K4, K8, K12". */
static void class_list(cs_standard std, char *buf, size_t size) {
    static const char *const classes[] = {"C", "PU", "M", "H"};
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < 4; i++) {
        int mph[3];
        if (!cs_standard_tests_class(std, classes[i]) || !cs_rating_class_speeds(classes[i], mph)) continue;
        for (int k = 2; k >= 0 && n < size; k--) {
            if (std == CS_ASTM_F2656)
                n += (size_t)snprintf(buf + n, size - n, "%s%s%d", n ? ", " : "", classes[i], mph[k]);
            else
                n += (size_t)snprintf(buf + n, size - n, "%sK%d", n ? ", " : "",
                                      mph[k] == 30   ? 4
                                      : mph[k] == 40 ? 8
                                                     : 12);
        }
    }
}

/* `rate` for the anti-ram standards. */
static int rate_antiram(cs_loader *l, const char *file, cs_standard std, const char *class_arg) {
    char klass[8] = "", list[200];
    int only_mph = 0;
    class_list(std, list, sizeof list);
    if (class_arg && cs_rating_class_parse(std, class_arg, klass, sizeof klass, &only_mph) != 0)
        return cs_cli_usage_error(&rate_cli, "--class %s: %s has no such class (expected one of %s)",
                                  class_arg, cs_standard_title(std), list);
    cs_model_input in = {.size = sizeof in};
    if (cs_loader_load(l, file, &in) != 0) {
        cs_loader_print_errors(l, stderr);
        return CS_EXIT_USAGE;
    }
    const char *vclass = cs_rating_vehicle_class(in.vehicle.mass);
    if (!vclass || !cs_standard_tests_class(std, vclass)) {
        fprintf(
            stderr,
            "cablesim rate: %s: the model's vehicle (%.0f kg) is not a test vehicle of %s (%s, within 5%% "
            "of the test mass): rate it with one, e.g. --set vehicle=%s\n",
            file, in.vehicle.mass, cs_standard_title(std),
            std == CS_ASTM_F2656 ? "C 1,100 kg, PU 2,300 kg, M 6,800 kg or H 29,500 kg"
                                 : "the 15,000-lb truck, M, 6,800 kg",
            klass[0] ? klass : "M");
        return CS_EXIT_USAGE;
    }
    if (klass[0] && strcmp(klass, vclass) != 0) {
        fprintf(
            stderr,
            "cablesim rate: %s: --class %s is for the %s vehicle (%.0f kg), but the model's vehicle is %s "
            "(%.0f kg): give --set vehicle=%s, or a class of %s\n",
            file, class_arg, klass, cs_rating_class_mass(klass), vclass, in.vehicle.mass, klass, vclass);
        return CS_EXIT_USAGE;
    }
    int mph[3];
    cs_rating_class_speeds(vclass, mph);
    printf("%s against %s (test vehicle %s, the model's %.0f kg; head-on at x = %.2f m):\n", in.name,
           cs_standard_name(std), vclass, in.vehicle.mass, in.scenario.impact_x);
    cs_rating best, last;
    int found = 0, rc = 0;
    for (int k = 0; k < 3 && rc == 0 && !found; k++) {
        if (only_mph && mph[k] != only_mph) continue;
        rc = rate_one(&in, std, vclass, mph[k], &last);
        if (rc == 0 && (only_mph || (last.rated && !last.through))) best = last, found = 1;
    }
    if (rc == 0) {
        char text[256];
        if (last.reference[0]) printf("  penetration as the standard measures it: %s\n", last.reference);
        cs_rating_text(found ? &best : &last, text, sizeof text);
        printf("rating: %s\n", text);
    }
    return rc;
}

/* Why a --set would not reach the standard's runs (they set it themselves), or NULL: the impact speed and
 * angle for every standard, and the vehicle for the roadside ones, which run their own test vehicles. */
static const char *set_overridden(const char *set, int roadside) {
    size_t n = strcspn(set, "=");
    if (n == strlen("scenario.speed") && strncmp(set, "scenario.speed", n) == 0)
        return "the standard's tests set the impact speed";
    if (n == strlen("scenario.angle") && strncmp(set, "scenario.angle", n) == 0)
        return "the standard's tests set the impact angle";
    if (roadside && strncmp(set, "vehicle", strlen("vehicle")) == 0 &&
        (n == strlen("vehicle") || set[strlen("vehicle")] == '.'))
        return "the standard's tests run their own vehicles";
    return NULL;
}

/* An option's value into *slot: -1 (go on), or a usage error if it was given before. */
static int take(const char **slot, const char *option, const char *value) {
    if (*slot) return cs_cli_usage_error(&rate_cli, "%s given twice (expected it once)", option);
    *slot = value;
    return -1;
}

int cs_command_rate(int argc, char **argv) {
    const char *file = NULL, *std_name = NULL, *klass = NULL, *level = NULL, *test = NULL, *why;
    cs_error err;
    cs_loader *l = cs_loader_create(NULL, &err);
    if (!l) {
        fprintf(stderr, "cablesim: %s\n", err.message);
        return CS_EXIT_RUN;
    }
    static const struct option longopts[] = {
        {"standard", required_argument, NULL, 's'}, {"class", required_argument, NULL, 'c'},
        {"level", required_argument, NULL, 'l'},    {"test", required_argument, NULL, 't'},
        {"set", required_argument, NULL, 'S'},      {"allow-path", required_argument, NULL, 'A'},
        {"help", no_argument, NULL, 'h'},           {NULL, 0, NULL, 0}};
    int rc = -1, v, set_count = 0;
    const char **sets = calloc((size_t)argc + 1, sizeof *sets); /* the --set given, to check */
    if (!sets) {
        cs_loader_free(l);
        fprintf(stderr, "cablesim rate: out of memory\n");
        return CS_EXIT_RUN;
    }
    optind = 1;
    while (rc < 0 && (v = cs_cli_next(&rate_cli, argc, argv, "h", longopts)) != -1) {
        if (v == 'h')
            rc = cs_cli_help(&rate_cli);
        else if (v == 's')
            rc = take(&std_name, "--standard", optarg);
        else if (v == 'c')
            rc = take(&klass, "--class", optarg);
        else if (v == 'l')
            rc = take(&level, "--level", optarg);
        else if (v == 't')
            rc = take(&test, "--test", optarg);
        else if (v == 'S')
            cs_loader_set(l, sets[set_count++] = optarg);
        else if (v == 'A' && cs_loader_allow_path(l, optarg, &err) != CS_OK)
            rc = cs_cli_usage_error(&rate_cli, "--allow-path %s", err.message);
        else if (v == 'A')
            continue;
        else
            rc = CS_EXIT_USAGE;
    }
    int roadside = std_name && (strcmp(std_name, "nchrp-350") == 0 || strcmp(std_name, "mash") == 0);
    for (int k = 0; rc < 0 && k < set_count; k++)
        if ((why = set_overridden(sets[k], roadside)))
            rc = cs_cli_usage_error(&rate_cli,
                                    "--set %s: %s, so it would not be used (rate runs each test as the "
                                    "standard gives it)",
                                    sets[k], why);
    free(sets);
    if (rc < 0) {
        int operands = argc - 1 - optind;
        file = operands > 0 ? argv[1 + optind] : NULL;
        cs_standard std;
        if (operands > 1)
            rc = cs_cli_usage_error(&rate_cli, "more than one model file ('%s' and '%s')", file,
                                    argv[2 + optind]);
        else if (!file || !std_name)
            rc = cs_cli_usage_error(&rate_cli, "%s", !file ? "no model file" : "no --standard");
        else if (roadside)
            rc = klass           ? cs_cli_usage_error(&rate_cli, "--class is for the anti-ram standards")
                 : level && test ? cs_cli_usage_error(&rate_cli, "give --level or --test, not both")
                                 : rate_roadside(l, file, std_name, level, test);
        else if (level || test)
            rc = cs_cli_usage_error(&rate_cli, "--level and --test are for nchrp-350 and mash");
        else if (cs_standard_parse(std_name, &std) != 0)
            rc =
                cs_cli_usage_error(&rate_cli,
                                   "unknown standard '%s' (expected astm-f2656, sd-std-02.01, sd-std-02.01a, "
                                   "nchrp-350 or mash)",
                                   std_name);
        else
            rc = rate_antiram(l, file, std, klass);
    }
    cs_loader_free(l);
    return rc;
}
