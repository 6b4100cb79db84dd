#include "rating.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MPH 0.44704
#define KMH (1.0 / 3.6)
#define DEG (3.14159265358979323846 / 180.0)

cs_rating_rules cs_default_rating_rules(void) {
    cs_rating_rules r;
    const double lo[3] = {28.0, 38.0, 47.0}, hi[3] = {37.9, 46.9, HUGE_VAL};
    for (int i = 0; i < 3; i++)
        r.window_low[i] = lo[i] * MPH, r.window_high[i] = hi[i] * MPH;
    r.barrier_depth = 0.1; /* 4-in posts and rails: docs/ratings.md */
    return r;
}

static const char *const standard_names[CS_STANDARD_COUNT] = {"sd-std-02.01", "sd-std-02.01a", "astm-f2656"};

const char *cs_standard_name(cs_standard s) {
    return (s >= 0 && s < CS_STANDARD_COUNT) ? standard_names[s] : "?";
}

int cs_standard_parse(const char *name, cs_standard *out) {
    for (int i = 0; i < CS_STANDARD_COUNT; i++)
        if (strcmp(name, standard_names[i]) == 0) {
            *out = (cs_standard)i;
            return 0;
        }
    return -1;
}

/* The windows are read to the displayed 0.1 mph: 37.9 mph is still the 30 rating. */
int cs_rating_speed_mph(const cs_rating_rules *rules, double speed) {
    double v = round(speed / MPH * 10.0) * MPH / 10.0;
    for (int i = 2; i >= 0; i--)
        if (v >= rules->window_low[i] - 1e-9 && v <= rules->window_high[i] + 1e-9) return 30 + 10 * i;
    return 0;
}

/* Penetration levels; a boundary value belongs to the better level (1.00 m is L3 and P1). */
const char *cs_rating_level(cs_standard standard, double p) {
    p = round(p * 100.0) / 100.0; /* the standards state limits to the centimetre */
    switch (standard) {
    case CS_SD_STD_02_01:
        return p <= 1.0 ? "L3" : p <= 6.0 ? "L2" : p <= 15.0 ? "L1" : NULL;
    case CS_SD_STD_02_01A:
        return p <= 1.0 ? "A" : NULL;
    case CS_ASTM_F2656:
        return p <= 1.0 ? "P1" : p <= 7.0 ? "P2" : p <= 30.0 ? "P3" : "P4";
    default:
        return NULL;
    }
}

cs_rating cs_rate_run(cs_standard standard, const char *vehicle_class, double speed,
                      const cs_summary *summary, const cs_vehicle_def *vehicle,
                      const cs_rating_rules *rules) {
    cs_rating r;
    memset(&r, 0, sizeof r);
    r.standard = standard;
    snprintf(r.vehicle_class, sizeof r.vehicle_class, "%s", vehicle_class);
    r.speed_mph = cs_rating_speed_mph(rules, speed);
    int through = cs_outcome_through(summary->outcome);
    double front = summary->max_dynamic_penetration_m;
    int cargo =
        standard == CS_SD_STD_02_01A ||
        (standard == CS_ASTM_F2656 && (strcmp(vehicle_class, "M") == 0 || strcmp(vehicle_class, "H") == 0));
    if (standard == CS_SD_STD_02_01) {
        r.reference = "vehicle front, from the attack face to where it stopped";
        r.penetration = through ? HUGE_VAL : front;
    } else if (cargo) {
        r.reference = "front of the cargo bed, from the barrier's protected-side face";
        r.penetration =
            through ? HUGE_VAL : fmax(0.0, front - vehicle->front_to_cargo_bed - rules->barrier_depth);
    } else {
        r.reference = "vehicle front, from the barrier's protected-side face";
        r.penetration = through ? HUGE_VAL : fmax(0.0, front - rules->barrier_depth);
    }
    const char *level = cs_rating_level(standard, r.penetration);
    r.rated = r.speed_mph > 0 && level != NULL;
    if (!r.rated) {
        snprintf(r.label, sizeof r.label, "none");
    } else if (standard == CS_ASTM_F2656) {
        snprintf(r.label, sizeof r.label, "%s%d/%s", vehicle_class, r.speed_mph, level);
    } else {
        int k = r.speed_mph == 30 ? 4 : r.speed_mph == 40 ? 8 : 12; /* K4 / K8 / K12 */
        snprintf(r.label, sizeof r.label, standard == CS_SD_STD_02_01 ? "K%d/%s" : "K%d (rev %s)", k, level);
    }
    return r;
}

const char *cs_rating_vehicle_class(double mass) {
    static const struct {
        const char *name;
        double kg;
    } classes[] = {{"C", 1100.0}, {"PU", 2300.0}, {"M", 6800.0}, {"H", 29500.0}}; /* ASTM F2656-07 */
    for (int i = 0; i < 4; i++)
        if (fabs(mass - classes[i].kg) <= 0.05 * classes[i].kg) return classes[i].name;
    return NULL;
}

/* NCHRP Report 350 (1993) and MASH (2009): tests x-10 (small car), x-11 (pickup) at 100 km/h, 4-12 (single
 * unit truck); 4-10 and 4-11 repeat 3-10 and 3-11 (docs/ratings.md). */
static const cs_roadside_test roadside_tests[] = {
    {"nchrp-350", "3-10", "820C", 100 * KMH, 20 * DEG}, {"nchrp-350", "3-11", "2000P", 100 * KMH, 25 * DEG},
    {"nchrp-350", "4-10", "820C", 100 * KMH, 20 * DEG}, {"nchrp-350", "4-11", "2000P", 100 * KMH, 25 * DEG},
    {"nchrp-350", "4-12", "8000S", 80 * KMH, 15 * DEG}, {"mash", "3-10", "1100C", 100 * KMH, 25 * DEG},
    {"mash", "3-11", "2270P", 100 * KMH, 25 * DEG},     {"mash", "4-10", "1100C", 100 * KMH, 25 * DEG},
    {"mash", "4-11", "2270P", 100 * KMH, 25 * DEG},     {"mash", "4-12", "10000S", 90 * KMH, 15 * DEG},
};

int cs_roadside_tests(const char *standard, int level, const char *name, cs_roadside_test *out) {
    int n = 0;
    for (size_t i = 0; i < sizeof roadside_tests / sizeof *roadside_tests; i++) {
        const cs_roadside_test *t = &roadside_tests[i];
        if (strcmp(t->standard, standard) != 0) continue;
        int in_level =
            level > 0 && t->name[0] == '0' + level && (level == 4 || strcmp(t->name + 1, "-12") != 0);
        if (in_level || (name && strcmp(t->name, name) == 0)) out[n++] = *t;
    }
    return n;
}

cs_roadside_result cs_roadside_read(const cs_roadside_test *test, const cs_summary *summary) {
    cs_roadside_result r;
    memset(&r, 0, sizeof r);
    r.redirected = summary->outcome == CS_REDIRECTED;
    r.contained = r.redirected || summary->outcome == CS_STOPPED;
    r.deflection = summary->max_barrier_deflection_m;
    r.working_width_m = summary->working_width_m;
    r.exit_speed_mps = cs_outcome_exits(summary->outcome) ? summary->exit_speed_mps : -1.0;
    r.exit_angle_deg = r.exit_speed_mps >= 0.0 ? summary->exit_angle_deg : 0.0;
    r.exit_angle_within =
        r.redirected && r.exit_angle_deg <= 0.6 * test->angle * 180 / 3.14159265358979323846;
    return r;
}
