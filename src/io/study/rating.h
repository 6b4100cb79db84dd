/* Anti-ram ratings: how a run's result reads against SD-STD-02.01 (1985), its revision A (2003) and
 * ASTM F2656. Facts from shared/reference/data/standards.md; what could not be confirmed there is a
 * named field of cs_rating_rules with its documented default (docs/ratings.md), so a user can see and
 * override it. This is post-processing of a run's summary: no physics here. */
#ifndef CS_RATING_H
#define CS_RATING_H

#include "cablesim/cablesim.h"

typedef enum cs_standard {
    CS_SD_STD_02_01 = 0,
    CS_SD_STD_02_01A,
    CS_ASTM_F2656,
    CS_STANDARD_COUNT
} cs_standard;

typedef struct cs_rating_rules {
    /* speed windows of the 30, 40 and 50 mph ratings, m/s (UNCONFIRMED: 28.0-37.9, 38.0-46.9, >= 47.0 mph) */
    double window_low[3];
    double window_high[3];
    /* depth of the barrier from its attack face to its protected-side face, m (a cable barrier's posts
     * and rails; measured-from-the-inside rules subtract it) */
    double barrier_depth;
} cs_rating_rules;

typedef struct cs_rating {
    cs_standard standard;
    char vehicle_class[8]; /* "M", "C", "PU", "H" (ASTM); "truck" (SD-STD) */
    int speed_mph;         /* 30, 40, 50 (60 for C/PU); 0 if below every window */
    double penetration;    /* m, as the standard measures it (HUGE_VAL through the barrier) */
    const char *reference; /* what the penetration is measured from and to */
    char label[24];        /* "K8/L2", "M40/P1", "K12 (A)", or "none" */
    int rated;             /* 0 if the run earns no rating */
} cs_rating;

cs_rating_rules cs_default_rating_rules(void);
const char *cs_standard_name(cs_standard s);               /* "sd-std-02.01", "sd-std-02.01a", "astm-f2656" */
int cs_standard_parse(const char *name, cs_standard *out); /* 0 on success */

/* The rating a run earns: its vehicle class and impact speed, and its summary's outcome and
 * penetration measured as the standard says (vehicle front, or front of the cargo bed). */
cs_rating cs_rate_run(cs_standard standard, const char *vehicle_class, double speed,
                      const cs_summary *summary, const cs_vehicle_def *vehicle, const cs_rating_rules *rules);

/* Pieces, for tests and for `cablesim rate`: the speed designation (mph) of an impact speed, and the
 * penetration level of a measured penetration ("L3", "P2"...; NULL if none). */
int cs_rating_speed_mph(const cs_rating_rules *rules, double speed);

/* The standard test vehicle a vehicle of this mass stands for ("C", "PU", "M", "H"), within 5% of
 * the test mass; NULL if none. */
const char *cs_rating_vehicle_class(double mass);
const char *cs_rating_level(cs_standard standard, double penetration);

/* ---- roadside test conditions: NCHRP Report 350 and AASHTO MASH (docs/ratings.md) ----
 * A test's vehicle (a part of the library), speed and angle; the impact point is the model's (neither
 * document's impact-point rule for cable barriers could be confirmed). */
typedef struct cs_roadside_test {
    const char *standard; /* "nchrp-350", "mash" */
    const char *name;     /* "3-10", "3-11", "4-10", "4-11", "4-12" */
    const char *vehicle;  /* part name */
    double speed;         /* m/s */
    double angle;         /* rad */
} cs_roadside_test;

/* The tests of a standard's test level (3: x-10 and x-11; 4: and 4-12), or the one named (level 0 and
 * name), into out (at most 3); returns the count, 0 if the standard or the test is unknown. */
int cs_roadside_tests(const char *standard, int level, const char *name, cs_roadside_test *out);

/* How a run of a roadside test reads: contained and redirected (it left on the traffic side) or
 * stopped, not broken through; the exit angle against NCHRP 350's preferred limit, 60% of the impact
 * angle (UNCONFIRMED). */
typedef struct cs_roadside_result {
    int contained;          /* redirected or stopped, not through */
    int redirected;         /* left the barrier on the traffic side */
    double deflection;      /* dynamic deflection, m */
    double working_width_m; /* m */
    double exit_speed_mps;  /* m/s, < 0 if it did not leave */
    double exit_angle_deg;  /* degrees */
    int exit_angle_within;  /* exit angle within 60% of the impact angle */
} cs_roadside_result;

cs_roadside_result cs_roadside_read(const cs_roadside_test *test, const cs_summary *summary);

#endif
