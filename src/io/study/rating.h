/* SPDX-License-Identifier: MIT */
/* Anti-ram ratings: how a run's result reads against SD-STD-02.01 (1985), its revision A (2003) and
 * ASTM F2656. Facts from shared/reference/data/standards.md; what could not be confirmed there is a
 * named field of cs_rating_rules with its documented default (docs/ratings.md), so a user can see and
 * override it. This is post-processing of a run's summary: no physics here. */
#ifndef CS_RATING_H
#define CS_RATING_H

#include "cablesim/cablesim.h"

typedef struct cs_rating_rules {
    /* speed windows of the 30, 40, 50 and 60 mph designations, m/s (UNCONFIRMED: 28.0-37.9, 38.0-46.9,
     * 47.0-56.9, >= 57.0 mph); a class's highest designation takes every speed above its window too */
    double window_low[4];
    double window_high[4];
    /* depth of the barrier from its attack face to its protected-side face, m (a cable barrier's posts
     * and rails; measured-from-the-inside rules subtract it) */
    double barrier_depth;
    /* how far from head-on (90 deg) a run's impact may be and still be the standards' test, rad
     * (UNCONFIRMED: 1 deg) */
    double head_on_tolerance;
} cs_rating_rules;

typedef struct cs_rating {
    cs_standard standard;
    char vehicle_class[8]; /* "C", "PU", "M", "H" (ASTM; SD-STD: "M", its one truck); "" if none */
    int speed_mph;         /* the speed designation: 30, 40, 50, 60; 0 if none */
    double penetration;    /* m, as the standard measures it (HUGE_VAL through the barrier; NAN unrated) */
    const char *reference; /* what the penetration is measured from and to */
    char label[24]; /* "K8/L2", "M40/P1", "K12 (rev A)"; "none" (a test, no rating earned); "not rated" */
    int rated;      /* 1 if label is a rating */
    int tested;     /* 0 if the run is not the standard's test ("not rated": note says why) */
    int through;    /* the vehicle got through the barrier */
    char note[160]; /* why not rated, why none, or "the vehicle got through"; "" if nothing to add */
} cs_rating;

cs_rating_rules cs_default_rating_rules(void);
const char *cs_standard_title(cs_standard s);              /* "SD-STD-02.01", "SD-STD-02.01a", "ASTM F2656" */
int cs_standard_parse(const char *name, cs_standard *out); /* 0 on success */

/* The rating a run of a test vehicle of class vehicle_class earns: its impact speed, and its summary's
 * outcome and penetration measured as the standard says (vehicle front, or front of the cargo bed). A
 * vehicle class the standard does not test, or a run that did not end stopped, redirected or through
 * (the time limit, no contact, not converged), is "not rated"; a speed below the class's designations
 * or a penetration past the standard's levels earns "none". The impact is taken to be head-on. */
cs_rating cs_rate_run(cs_standard standard, const char *vehicle_class, double speed,
                      const cs_summary *summary, const cs_vehicle_def *vehicle, const cs_rating_rules *rules);

/* The rating of a run as it was run: its vehicle's class by mass (cs_rating_vehicle_class), or
 * vehicle_class if not NULL; "not rated" if the vehicle is none of the standard's test vehicles or the
 * impact is not head-on (within rules->head_on_tolerance). */
cs_rating cs_rate_as_run(cs_standard standard, const char *vehicle_class, const cs_vehicle_def *vehicle,
                         double speed, double angle, const cs_summary *summary, const cs_rating_rules *rules);

/* The penetration a designation rests on, m, as its standard measures it: NaN where the label is no
 * designation with one ("none", "not rated", or a vehicle that got through). What cs_rating_text prints
 * and a sweep's runs.csv holds. */
double cs_rating_penetration(const cs_rating *r);

/* The one wording of a rating, for the terminal, summary.json, report.html and `rate`: the standard's
 * title, the label, and in brackets the note and the penetration it rests on ("ASTM F2656 M50/P4 (the
 * vehicle got through)"). */
void cs_rating_text(const cs_rating *r, char *buf, size_t size);

/* Pieces, for tests and for `cablesim rate`: the speed designation (mph) of an impact speed for a class
 * (0 if below every window the class has; NULL class: M's 30, 40 and 50), and the penetration level of a
 * measured penetration ("L3", "P2"...; NULL if none). */
int cs_rating_speed_for(const cs_rating_rules *rules, const char *vehicle_class, double speed);
const char *cs_rating_level(cs_standard standard, double penetration);

/* The standard test vehicle a vehicle of this mass stands for ("C", "PU", "M", "H"), within 5% of
 * the test mass; NULL if none. */
const char *cs_rating_vehicle_class(double mass);
/* A class's test mass (kg), and its speed designations in mph, highest first, into mph[3]; each returns 0
 * for a class ASTM F2656 does not have. A standard tests a class: ASTM F2656 all four, SD-STD-02.01 and
 * its revision A only M. */
double cs_rating_class_mass(const char *vehicle_class);
int cs_rating_class_speeds(const char *vehicle_class, int mph[3]);
int cs_standard_tests_class(cs_standard standard, const char *vehicle_class);
/* Split a --class argument ("M50", "PU60", "K8") into the class and its speed (mph) for a standard:
 * 0, or -1 if the standard has no such class and speed. */
int cs_rating_class_parse(cs_standard standard, const char *name, char *vehicle_class, size_t size, int *mph);

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
 * stopped, not broken through; the exit angle against NCHRP 350's preferred limit (criterion M: less
 * than 60% of the impact angle; docs/ratings.md). */
typedef struct cs_roadside_result {
    int contained;          /* redirected or stopped, not through */
    int redirected;         /* left the barrier on the traffic side */
    double deflection;      /* dynamic deflection, m */
    double working_width_m; /* m */
    double exit_speed_mps;  /* m/s, < 0 if it did not leave */
    double exit_angle_deg;  /* degrees */
    int exit_angle_within;  /* redirected, its exit angle less than 60% of the impact angle */
} cs_roadside_result;

cs_roadside_result cs_roadside_read(const cs_roadside_test *test, const cs_summary *summary);
/* NCHRP 350's preferred limit on the exit angle (criterion M): 60% of the test's impact angle, degrees. */
double cs_roadside_exit_angle_limit_deg(const cs_roadside_test *test);

#endif
