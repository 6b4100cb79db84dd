/* `cablesim rate`: run a standard's test condition (its vehicle and speed, head-on, at the model's
 * impact point) against the barrier of a model file and print the rating, as the standard measures
 * penetration (src/io/study/rating.c, docs/ratings.md). Without --class it starts from the highest class
 * and stops at the first the barrier passes (vehicle stopped and rated). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "load/loader.h"
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
            "[--class M50|K8] [--set PATH=VALUE]...\n",
            what);
    return 2;
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
    const char *file = NULL, *std_name = NULL, *klass = NULL;
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
