/* `cablesim rate`: run a standard's test condition against the barrier of a model file.
 * - Anti-ram (sd-std-02.01, sd-std-02.01a, astm-f2656): its vehicle and speed, head-on, at the model's
 *   impact point; the rating, as the standard measures penetration (src/io/study/rating.c,
 *   docs/ratings.md). Without --class it starts from the highest class and stops at the first the
 *   barrier passes (vehicle stopped and rated).
 * - Roadside (nchrp-350, mash): the tests of a test level (--level 3 or 4) or one (--test 3-11): vehicle,
 *   speed and angle at the model's impact point; each test's outcome, dynamic deflection, working width,
 *   exit speed and angle, and whether the barrier contained and redirected the vehicle. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cablesim/loader.h"
#include "commands.h"
#include "study/rating.h"

#define MPH 0.44704
#define CS_PI 3.14159265358979323846

typedef struct trial {
    const char *part;  /* vehicle part of the library */
    const char *klass; /* rating class letter(s) */
    int mph;
} trial;

static int usage_error(const char *what) {
    fprintf(stderr,
            "cablesim rate: %s\nusage: cablesim rate FILE --standard sd-std-02.01|sd-std-02.01a|astm-f2656 "
            "[--class M50|K8] [--set PATH=VALUE]...\n"
            "       cablesim rate FILE --standard nchrp-350|mash [--level 3|4 | --test 3-11] "
            "[--set PATH=VALUE]...\n",
            what);
    return 2;
}

/* One roadside test at the model's impact point; its row printed. Returns 0, 1 if the run failed, 2 if
 * its vehicle is not in the library. contained, redirected: set to 0 if the barrier did not contain the
 * vehicle (it got through), did not redirect it (it got through or stopped). */
static int roadside_one(cs_loader *l, const cs_model_input *in, const cs_roadside_test *t, int *contained,
                        int *redirected) {
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
    int rc = (s && cs_run(m, s, NULL, NULL, &err) == CS_OK) ? 0 : 1;
    if (rc) {
        fprintf(stderr, "cablesim rate: test %s: %s\n", t->name, err.message);
    } else {
        cs_summary sm;
        cs_state_summary(s, &sm);
        cs_roadside_result r = cs_roadside_read(t, &sm);
        char exit[128] = "no exit";
        if (r.exit_speed_mps >= 0.0)
            snprintf(exit, sizeof exit, "exit %.1f km/h (%.1f mph) at %.1f deg%s", r.exit_speed_mps * 3.6,
                     r.exit_speed_mps / MPH, r.exit_angle_deg,
                     r.redirected && strcmp(t->standard, "nchrp-350") == 0
                         ? (r.exit_angle_within ? " (under 60% of the impact angle)"
                                                : " (60% of the impact angle or more)")
                         : "");
        printf(
            "  %-4s %-6s %3.0f km/h %2.0f deg  %-12s deflection %.2f m (%.1f ft)  working width %.2f m (%.1f "
            "ft)  %s\n",
            t->name, t->vehicle, t->speed * 3.6, t->angle * 180 / CS_PI, cs_outcome_name(sm.outcome),
            r.deflection, r.deflection / 0.3048, r.working_width_m, r.working_width_m / 0.3048, exit);
        if (!r.contained) *contained = 0;
        if (!r.redirected) *redirected = 0;
    }
    cs_state_free(s);
    cs_model_free(m);
    return rc;
}

/* `rate` for nchrp-350 and mash. */
static int rate_roadside(cs_loader *l, const char *file, const char *standard, const char *level,
                         const char *test) {
    cs_roadside_test t[3];
    int lv = level ? atoi(level) : (test ? 0 : 3);
    int n = cs_roadside_tests(standard, lv, test, t);
    if (n == 0 || (level && lv != 3 && lv != 4))
        return usage_error(test ? "unknown test (3-10, 3-11, 4-10, 4-11 or 4-12)" : "level must be 3 or 4");
    cs_model_input in;
    if (cs_loader_load(l, file, &in) != 0) {
        cs_loader_print_errors(l, stderr);
        return 2;
    }
    printf("%s against %s (impact at x = %.2f m, the %s):\n", in.name, standard, in.scenario.impact_x,
           in.scenario.impact_at_corner ? "leading front corner" : "centre of the front face");
    int contained = 1, redirected = 1, rc = 0;
    for (int k = 0; k < n && rc == 0; k++)
        rc = roadside_one(l, &in, &t[k], &contained, &redirected);
    if (rc == 0)
        printf("%s: %s\n", test ? test : (lv == 4 ? "TL-4" : "TL-3"),
               !contained    ? "NOT contained in every test (the vehicle got through)"
               : !redirected ? "contained in every test, NOT redirected in every test (the vehicle stopped)"
                             : "contained and redirected in every test");
    return rc;
}

/* The trials of a standard, highest first; --class keeps one. Returns the count. */
static int trials_for(cs_standard std, const char *klass, trial *t) {
    static const int speeds[] = {50, 40, 30};
    int n = 0;
    for (int i = 0; i < 3; i++) {
        trial x = {std == CS_ASTM_F2656 ? "M" : "SD-STD-02.01", "M", speeds[i]};
        char name[16];
        if (std == CS_ASTM_F2656)
            snprintf(name, sizeof name, "M%d", x.mph);
        else
            snprintf(name, sizeof name, "K%d", x.mph == 30 ? 4 : x.mph == 40 ? 8 : 12);
        if (!klass || strcmp(klass, name) == 0) t[n++] = x;
    }
    return n;
}

static int rate_one(const cs_model_input *in, const cs_vehicle_def *v, cs_standard std, const trial *t,
                    cs_rating *out) {
    cs_scenario_def sc = in->scenario;
    sc.speed = t->mph * MPH;
    sc.angle = 0.5 * CS_PI; /* the standards' head-on impact */
    cs_error err = {0};
    cs_model *m = cs_model_create(&in->barrier, v, &sc, &err);
    cs_state *s = m ? cs_state_create(m, &err) : NULL;
    int rc = (s && cs_run(m, s, NULL, NULL, &err) == CS_OK) ? 0 : 1;
    if (rc) {
        fprintf(stderr, "cablesim rate: %s at %d mph: %s\n", t->klass, t->mph, err.message);
    } else {
        cs_summary sm;
        cs_state_summary(s, &sm);
        cs_rating_rules rules = cs_default_rating_rules();
        *out = cs_rate_run(std, t->klass, sc.speed, &sm, v, &rules);
        char pen[64];
        if (out->penetration > 1e9)
            snprintf(pen, sizeof pen, "through the barrier");
        else
            snprintf(pen, sizeof pen, "%.2f m (%.1f ft)", out->penetration, out->penetration / 0.3048);
        printf("  %-4s %2d mph  %-12s penetration %-22s ->  %s\n", t->klass, t->mph,
               cs_outcome_name(sm.outcome), pen, out->label);
    }
    cs_state_free(s);
    cs_model_free(m);
    return rc;
}

int cs_command_rate(int argc, char **argv) {
    const char *file = NULL, *std_name = NULL, *klass = NULL, *level = NULL, *test = NULL;
    char why[256];
    cs_loader *l = cs_loader_create(NULL, why, sizeof why);
    if (!l) {
        fprintf(stderr, "cablesim: %s\n", why);
        return 1;
    }
    int rc = 0;
    for (int i = 2; i < argc && rc == 0; i++) {
        const char *a = argv[i];
        const char **slot = strcmp(a, "--standard") == 0 ? &std_name
                            : strcmp(a, "--class") == 0  ? &klass
                            : strcmp(a, "--level") == 0  ? &level
                            : strcmp(a, "--test") == 0   ? &test
                                                         : NULL;
        if (slot || strcmp(a, "--set") == 0) {
            if (i + 1 >= argc)
                rc = usage_error("an option lacks its value");
            else if (slot)
                *slot = argv[++i];
            else
                cs_loader_set(l, argv[++i]);
        } else if (a[0] == '-' || file) {
            rc = usage_error(a[0] == '-' ? "unknown option" : "more than one model file");
        } else {
            file = a;
        }
    }
    cs_standard std;
    if (rc == 0 && (!file || !std_name)) rc = usage_error(!file ? "no model file" : "no --standard");
    if (rc == 0 && (strcmp(std_name, "nchrp-350") == 0 || strcmp(std_name, "mash") == 0)) {
        rc = klass ? usage_error("--class is for the anti-ram standards")
                   : rate_roadside(l, file, std_name, level, test);
        cs_loader_free(l);
        return rc;
    }
    if (rc == 0 && (level || test)) rc = usage_error("--level and --test are for nchrp-350 and mash");
    if (rc == 0 && cs_standard_parse(std_name, &std) != 0) rc = usage_error("unknown standard");
    trial t[3];
    int n = rc == 0 ? trials_for(std, klass, t) : 0;
    if (rc == 0 && n == 0)
        rc = usage_error(std == CS_ASTM_F2656 ? "class must be M30, M40 or M50"
                                              : "class must be K4, K8 or K12");
    cs_model_input in;
    cs_vehicle_def v;
    if (rc == 0 &&
        (cs_loader_load(l, file, &in) != 0 || cs_loader_part(l, CS_PART_VEHICLE, t[0].part, &v) != 0)) {
        cs_loader_print_errors(l, stderr);
        rc = 2;
    }
    if (rc == 0) {
        printf("%s against %s (test vehicle %s, head-on at x = %.2f m):\n", in.name, cs_standard_name(std),
               t[0].part, in.scenario.impact_x);
        cs_rating best = {0};
        int found = 0;
        for (int k = 0; k < n && rc == 0; k++) {
            cs_rating r;
            rc = rate_one(&in, &v, std, &t[k], &r);
            int passes = rc == 0 && r.rated && r.penetration < 1e9;
            if (passes && !found) best = r, found = 1;
            if (found && !klass) break;
            if (klass && rc == 0) best = r, found = r.rated;
        }
        if (rc == 0)
            printf("rating: %s%s\n", found ? best.label : "none",
                   found ? "" : (klass ? " (not rated at this class)" : " (no class passed)"));
    }
    cs_loader_free(l);
    return rc;
}

void cs_print_run_rating(FILE *out, const cs_vehicle_def *vehicle, double speed, const cs_summary *summary) {
    const char *klass = cs_rating_vehicle_class(vehicle->mass);
    if (!klass) return;
    cs_rating_rules rules = cs_default_rating_rules();
    cs_rating a = cs_rate_run(CS_ASTM_F2656, klass, speed, summary, vehicle, &rules);
    fprintf(out, "  rating (as run)      ASTM F2656 %s", a.label);
    if (strcmp(klass, "M") == 0) {
        cs_rating sd = cs_rate_run(CS_SD_STD_02_01, klass, speed, summary, vehicle, &rules);
        fprintf(out, "; SD-STD-02.01 %s", sd.label);
    }
    fprintf(out, "  (docs/ratings.md)\n");
}
