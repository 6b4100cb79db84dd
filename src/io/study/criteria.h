/* SPDX-License-Identifier: MIT */
/* The evaluation criteria of NCHRP Report 350 and MASH for a roadside test, each judged from a run where
 * the model can judge it and listed as "not judged" where it cannot (docs/ratings.md, "Criteria"). */
#ifndef CS_CRITERIA_H
#define CS_CRITERIA_H

#include "cablesim/output.h"
#include "study/occupant.h"
#include "study/rating.h"

typedef enum cs_verdict { CS_VERDICT_PASS = 0, CS_VERDICT_FAIL, CS_VERDICT_NOT_JUDGED } cs_verdict;

typedef struct cs_criterion {
    const char *id;   /* the standard's letter ("A", "H", ...), or "exit box" */
    const char *name; /* what it asks, in short */
    cs_verdict verdict;
    char detail[400]; /* the run's numbers against the limits, or why it is not judged */
} cs_criterion;

/* MASH's exit box for a vehicle (docs/ratings.md): A = 2.0 m + its width + 0.16 x its length from the
 * barrier's traffic face (y = 0), B = 10 m along from the point where the vehicle lost contact with the
 * barrier. */
typedef struct cs_exit_box {
    double a, b;        /* m */
    double start_x;     /* the loss of contact's point along the barrier (no loss of contact: the impact
                           point), m */
    double cross_along; /* how far along from start_x a wheel crosses y = -a, m; HUGE_VAL never */
    int crossed_in_run; /* 1 if it crossed within the run; 0 if on the path extrapolated past its end */
    double dir; /* +1 if the vehicle travels toward +x, -1 toward -x: the box runs from start_x that way */
    int heading_back; /* 1 if no wheel crossed in the run and the CG moves back toward the barrier at the
                         run's end: the path past it is a second impact, not followed (no verdict); a
                         run's outputs give it for a redirected run only */
} cs_exit_box;

/* The wheels' plan positions (x, y; front left, front right, rear left, rear right) of a frame: the
 * vehicle's track and wheelbase placed by the CG and its yaw. */
void cs_vehicle_wheels(const cs_vehicle_view *p, const cs_vehicle_def *v, double w[4][2]);

/* The exit box and the wheels' path of a run whose vehicle last lost contact with the barrier at t_exit
 * (s; negative: it did not): the box starts at the x of the vehicle's outline corner nearest the barrier
 * (largest y) then, the frames either side interpolated, and the wheels (track and wheelbase, from the
 * CG's place and yaw in each frame from then on) are followed to y = -a, in the run and past its end
 * straight along the CG's last velocity, if that leads away from the barrier (else heading_back). With no
 * loss of contact the box starts at impact_x and the wheels are followed from the first frame one is over
 * the barrier's face (y >= 0). */
void cs_exit_box_of_record(const cs_record *rec, const cs_vehicle_def *v, double impact_x, double t_exit,
                           cs_exit_box *out);

/* What a run gives the criteria. occupant NULL: not computed (the occupant criteria are then not judged,
 * occupant_why says why). state: the run at its end, whose override and underride events (a cable the
 * vehicle rode over or went under) criterion A names; NULL: none known. */
typedef struct cs_test_result {
    const cs_summary *summary;
    const cs_occupant_risk *occupant;
    const char *occupant_why;
    double roll_peak, pitch_peak; /* rad */
    const cs_exit_box *exit_box;  /* NULL: none */
    const cs_state *state;
} cs_test_result;

enum { CS_CRITERIA_MAX = 10 };

/* The criteria of a test (its standard's for its vehicle) judged on a result, into out[CS_CRITERIA_MAX];
 * the count. */
int cs_roadside_criteria(const cs_roadside_test *test, const cs_test_result *r, cs_criterion *out);

/* The roadside test a run as run stands for: the first of NCHRP Report 350's and then MASH's tests whose
 * vehicle (its mass the number in its name: 2000P, 2270P) the run's is within 5% by mass, impacted at an
 * angle under 45 deg; its speed and angle the run's. A car or pickup test is named at the test level
 * whose speed (50, 70 or 100 km/h: levels 1, 2 and 3) is nearest the run's: 2-11 for a 2000P at 70 km/h.
 * Returns 1 and fills out, or 0 if none. */
int cs_roadside_test_as_run(const cs_vehicle_def *v, double speed, double angle, cs_roadside_test *out);

/* "pass", "FAIL", "not judged". */
const char *cs_verdict_name(cs_verdict v);

#endif
