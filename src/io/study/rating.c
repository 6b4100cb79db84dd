/* SPDX-License-Identifier: MIT */
#include "rating.h"
#include "cablesim/units.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define KMH (1.0 / 3.6)

cs_rating_rules cs_default_rating_rules(void) {
    cs_rating_rules r;
    const double lo[4] = {28.0, 38.0, 47.0, 57.0}, hi[4] = {37.9, 46.9, 56.9, HUGE_VAL};
    for (int i = 0; i < 4; i++)
        r.window_low[i] = lo[i] * CS_MPH, r.window_high[i] = hi[i] * CS_MPH;
    r.barrier_depth = 0.1;            /* 4-in posts and rails: docs/ratings.md */
    r.head_on_tolerance = 1 * CS_DEG; /* docs/ratings.md */
    return r;
}

static const char *const standard_names[CS_STANDARD_COUNT] = {"sd-std-02.01", "sd-std-02.01a", "astm-f2656"};
static const char *const standard_titles[CS_STANDARD_COUNT] = {"SD-STD-02.01", "SD-STD-02.01a", "ASTM F2656"};

const char *cs_standard_name(cs_standard s) {
    return (s >= 0 && s < CS_STANDARD_COUNT) ? standard_names[s] : "?";
}

const char *cs_standard_title(cs_standard s) {
    return (s >= 0 && s < CS_STANDARD_COUNT) ? standard_titles[s] : "?";
}

int cs_standard_parse(const char *name, cs_standard *out) {
    for (int i = 0; i < CS_STANDARD_COUNT; i++)
        if (strcmp(name, standard_names[i]) == 0) {
            *out = (cs_standard)i;
            return 0;
        }
    return -1;
}

/* ASTM F2656's vehicles (-07; PU was P there): the library part, the test mass, the speed designations
 * (C and PU: 40, 50, 60 mph, UNCONFIRMED; M and H: 30, 40, 50 mph). */
static const struct {
    const char *name;
    double kg;
    int mph[3];
} classes[] = {{"C", 1100.0, {60, 50, 40}},
               {"PU", 2300.0, {60, 50, 40}},
               {"M", 6800.0, {50, 40, 30}},
               {"H", 29500.0, {50, 40, 30}}};
enum { CLASS_COUNT = sizeof classes / sizeof classes[0] };

static int class_index(const char *vehicle_class) {
    for (int i = 0; vehicle_class && i < CLASS_COUNT; i++)
        if (strcmp(vehicle_class, classes[i].name) == 0) return i;
    return -1;
}

double cs_rating_class_mass(const char *vehicle_class) {
    int i = class_index(vehicle_class);
    return i < 0 ? 0.0 : classes[i].kg;
}

int cs_rating_class_speeds(const char *vehicle_class, int mph[3]) {
    int i = class_index(vehicle_class);
    if (i < 0) return 0;
    for (int k = 0; k < 3; k++)
        mph[k] = classes[i].mph[k];
    return 3;
}

int cs_standard_tests_class(cs_standard standard, const char *vehicle_class) {
    if (class_index(vehicle_class) < 0) return 0;
    return standard == CS_ASTM_F2656 || strcmp(vehicle_class, "M") == 0;
}

const char *cs_rating_vehicle_class(double mass) {
    for (int i = 0; i < CLASS_COUNT; i++)
        if (fabs(mass - classes[i].kg) <= 0.05 * classes[i].kg) return classes[i].name;
    return NULL;
}

int cs_rating_class_parse(cs_standard standard, const char *name, char *vehicle_class, size_t size,
                          int *mph) {
    for (int i = 0; i < CLASS_COUNT; i++) {
        if (!cs_standard_tests_class(standard, classes[i].name)) continue;
        for (int k = 0; k < 3; k++) {
            char want[16];
            int v = classes[i].mph[k];
            if (standard == CS_ASTM_F2656)
                snprintf(want, sizeof want, "%s%d", classes[i].name, v);
            else
                snprintf(want, sizeof want, "K%d", v == 30 ? 4 : v == 40 ? 8 : 12);
            if (strcmp(name, want) != 0) continue;
            snprintf(vehicle_class, size, "%s", classes[i].name);
            *mph = v;
            return 0;
        }
    }
    return -1;
}

/* The windows are read to the displayed 0.1 mph: 37.9 mph is still the 30 rating. */
int cs_rating_speed_for(const cs_rating_rules *rules, const char *vehicle_class, double speed) {
    int i = class_index(vehicle_class ? vehicle_class : "M");
    if (i < 0) return 0;
    double v = round(speed / CS_MPH * 10.0) * CS_MPH / 10.0;
    for (int k = 0; k < 3; k++) {
        int w = (classes[i].mph[k] - 30) / 10;
        double high = k == 0 ? HUGE_VAL : rules->window_high[w]; /* the highest designation is open */
        if (v >= rules->window_low[w] - 1e-9 && v <= high + 1e-9) return classes[i].mph[k];
    }
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

static cs_rating not_rated(cs_standard standard, const char *vehicle_class, const char *note) {
    cs_rating r;
    memset(&r, 0, sizeof r);
    r.standard = standard;
    snprintf(r.vehicle_class, sizeof r.vehicle_class, "%s", vehicle_class ? vehicle_class : "");
    r.penetration = NAN;
    r.reference = "";
    snprintf(r.label, sizeof r.label, "not rated");
    snprintf(r.note, sizeof r.note, "%s", note);
    return r;
}

/* Why a run's outcome is not a finished test, or NULL if it is one. */
static const char *unfinished(cs_outcome o) {
    switch (o) {
    case CS_TIME_LIMIT:
        return "the run ended at its time limit with the vehicle still moving";
    case CS_NO_CONTACT:
        return "the vehicle never touched the barrier";
    case CS_DID_NOT_CONVERGE:
        return "the run did not converge";
    case CS_STEP_LIMIT:
        return "the run took its scenario.max_steps steps before it ended";
    case CS_STOPPED:
    case CS_REDIRECTED:
        return NULL;
    default:
        return cs_outcome_through(o) ? NULL : "the run did not finish";
    }
}

cs_rating cs_rate_run(cs_standard standard, const char *vehicle_class, double speed,
                      const cs_summary *summary, const cs_vehicle_def *vehicle,
                      const cs_rating_rules *rules) {
    char note[160];
    if (!cs_standard_tests_class(standard, vehicle_class)) {
        snprintf(note, sizeof note, "%s has no %s test vehicle", cs_standard_title(standard),
                 vehicle_class ? vehicle_class : "such");
        return not_rated(standard, vehicle_class, note);
    }
    const char *open = unfinished(summary->outcome);
    if (open) return not_rated(standard, vehicle_class, open);
    cs_rating r;
    memset(&r, 0, sizeof r);
    r.standard = standard;
    r.tested = 1;
    snprintf(r.vehicle_class, sizeof r.vehicle_class, "%s", vehicle_class);
    r.speed_mph = cs_rating_speed_for(rules, vehicle_class, speed);
    r.through = cs_outcome_through(summary->outcome);
    double front = summary->max_dynamic_penetration_m;
    int cargo =
        standard == CS_SD_STD_02_01A ||
        (standard == CS_ASTM_F2656 && (strcmp(vehicle_class, "M") == 0 || strcmp(vehicle_class, "H") == 0));
    if (standard == CS_SD_STD_02_01) {
        r.reference = "vehicle front, from the attack face to where it stopped";
        r.penetration = r.through ? HUGE_VAL : front;
    } else if (cargo) {
        r.reference = "front of the cargo bed, from the barrier's protected-side face";
        r.penetration =
            r.through ? HUGE_VAL : fmax(0.0, front - vehicle->front_to_cargo_bed - rules->barrier_depth);
    } else {
        r.reference = "vehicle front, from the barrier's protected-side face";
        r.penetration = r.through ? HUGE_VAL : fmax(0.0, front - rules->barrier_depth);
    }
    const char *level = cs_rating_level(standard, r.penetration);
    r.rated = r.speed_mph > 0 && level != NULL;
    if (r.speed_mph == 0) {
        int mph[3] = {0, 0, 0}; /* the class's three speeds: a class the standard tests (checked above) */
        cs_rating_class_speeds(vehicle_class, mph);
        snprintf(r.note, sizeof r.note, "%.1f mph is below the lowest speed of its %s vehicle, %d mph",
                 round(speed / CS_MPH * 10.0) / 10.0, vehicle_class, mph[2]);
    } else if (r.through) {
        snprintf(r.note, sizeof r.note, "%s",
                 standard == CS_ASTM_F2656 ? "the vehicle got through"
                 : standard == CS_SD_STD_02_01
                     ? "the vehicle got through; L1 needs it stopped within 15 m"
                     : "the vehicle got through; the revision's one level needs it stopped within 1 m");
    } else if (!level) {
        snprintf(r.note, sizeof r.note, "penetration %.2f m, past the standard's last level", r.penetration);
    }
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

cs_rating cs_rate_as_run(cs_standard standard, const char *vehicle_class, const cs_vehicle_def *vehicle,
                         double speed, double angle, const cs_summary *summary,
                         const cs_rating_rules *rules) {
    const char *cls = vehicle_class ? vehicle_class : cs_rating_vehicle_class(vehicle->mass);
    char note[160];
    if (!cls || !cs_standard_tests_class(standard, cls)) {
        snprintf(note, sizeof note, "the vehicle, %.0f kg, is %s, within 5%%", vehicle->mass,
                 standard == CS_ASTM_F2656 ? "none of its test vehicles, C, PU, M and H"
                                           : "not its 15,000-lb truck");
        return not_rated(standard, cls, note);
    }
    if (fabs(angle - 90 * CS_DEG) > rules->head_on_tolerance) {
        snprintf(note, sizeof note, "the impact is at %.1f deg; its test is head-on, at 90 deg",
                 angle / CS_DEG);
        return not_rated(standard, cls, note);
    }
    return cs_rate_run(standard, cls, speed, summary, vehicle, rules);
}

double cs_rating_penetration(const cs_rating *r) {
    return r->rated && isfinite(r->penetration) ? r->penetration : NAN;
}

void cs_rating_text(const cs_rating *r, char *buf, size_t size) {
    char pen[192] = ""; /* a rating's penetration where it has one, as its standard measures it */
    double p = cs_rating_penetration(r);
    if (isfinite(p))
        snprintf(pen, sizeof pen, "penetration %.2f m (%.1f ft), %s", p, p / CS_FT, r->reference);
    int both = r->note[0] && pen[0], any = r->note[0] || pen[0];
    snprintf(buf, size, "%s %s%s%s%s%s%s", cs_standard_title(r->standard), r->label, any ? " (" : "", r->note,
             both ? "; " : "", pen, any ? ")" : "");
}

/* NCHRP Report 350 (1993) and MASH (2009): tests x-10 (small car), x-11 (pickup) at 100 km/h, 4-12 (single
 * unit truck); 4-10 and 4-11 repeat 3-10 and 3-11 (docs/ratings.md). */
static const cs_roadside_test roadside_tests[] = {
    {"nchrp-350", "3-10", "820C", 100 * KMH, 20 * CS_DEG},
    {"nchrp-350", "3-11", "2000P", 100 * KMH, 25 * CS_DEG},
    {"nchrp-350", "4-10", "820C", 100 * KMH, 20 * CS_DEG},
    {"nchrp-350", "4-11", "2000P", 100 * KMH, 25 * CS_DEG},
    {"nchrp-350", "4-12", "8000S", 80 * KMH, 15 * CS_DEG},
    {"mash", "3-10", "1100C", 100 * KMH, 25 * CS_DEG},
    {"mash", "3-11", "2270P", 100 * KMH, 25 * CS_DEG},
    {"mash", "4-10", "1100C", 100 * KMH, 25 * CS_DEG},
    {"mash", "4-11", "2270P", 100 * KMH, 25 * CS_DEG},
    {"mash", "4-12", "10000S", 90 * KMH, 15 * CS_DEG},
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

double cs_roadside_exit_angle_limit_deg(const cs_roadside_test *test) {
    return 0.6 * test->angle / CS_DEG;
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
        r.redirected && r.exit_angle_deg < cs_roadside_exit_angle_limit_deg(test); /* "less than" */
    return r;
}
