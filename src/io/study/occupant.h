/* SPDX-License-Identifier: MIT */
/* Occupant risk from the vehicle's motion at its centre of gravity, as the crash-test standards compute
 * it (docs/ratings.md, "Occupant risk"): the channel frequency class filters of SAE J211/1 (ISO 6487),
 * the flail-space model of NCHRP Report 350 and MASH (occupant impact velocity, its time, ridedown
 * acceleration) and EN 1317-1's THIV, PHD and ASI. Pure functions over uniformly sampled series, and
 * one that reads a run's record. SI throughout (m, s, m/s, m/s^2), but ORA and PHD in g, as the
 * standards give them. Post-processing: no physics of the engine here. */
#ifndef CS_OCCUPANT_H
#define CS_OCCUPANT_H

#include <stddef.h>

#include "cablesim/output.h"

/* ---- SAE J211/1 (Appendix C) channel frequency class filter ----
 * A 2-pole Butterworth low-pass designed by the bilinear transform with J211's published coefficients
 * (wd = 2 pi CFC 2.0775, wa = tan(wd T / 2)), run forward then backward over the series: phaseless, and
 * 4-pole in magnitude. */
typedef struct cs_cfc_coeffs {
    double a0, a1, a2; /* on X[t], X[t-1], X[t-2] */
    double b1, b2;     /* on Y[t-1], Y[t-2] */
} cs_cfc_coeffs;

/* The coefficients of class cfc (60, 180, ...: any positive class) at sample interval dt (s). Returns 0,
 * or -1 if dt is too long for the class (wd dt / 2 at or past pi / 2: no filter exists). */
int cs_cfc_coefficients(double cfc, double dt, cs_cfc_coeffs *c);
/* Filter x[0..n-1] into y (y may be x): forward, then backward, each pass starting from its first value
 * held before it (a constant passes unchanged). Returns 0, or -1 as cs_cfc_coefficients. */
int cs_cfc_filter(double cfc, double dt, const double *x, double *y, int n);

/* ---- moving averages ---- */
/* The largest |mean| of x over any window of w samples starting at index from or later and before n;
 * a window running past the end takes the samples past it as zeros (the vehicle at constant velocity
 * after its record, as an occupant impact after the record takes it). The window's start index into *at;
 * -1 and 0 if from is not in the series. */
double cs_window_mean_max(const double *x, int n, int w, int from, int *at);

/* ---- occupant risk ---- */
/* The vehicle's motion at its CG, sampled every dt from the first contact (index 0): accelerations in the
 * vehicle's own axes (x forward, y to its left, z up), m/s^2, and its yaw rate, rad/s. */
typedef struct cs_vehicle_motion {
    int n;
    double dt;
    const double *ax, *ay, *az;
    const double *yaw_rate;
} cs_vehicle_motion;

/* The standards' constants (cs_default_occupant_rules: docs/ratings.md gives each one's source). */
typedef struct cs_occupant_rules {
    double cfc;              /* filter class of the accelerations (180) */
    double flail_x;          /* flail space, longitudinal, m (0.6) */
    double flail_y;          /* flail space, lateral, m (0.3) */
    double ora_window;       /* ridedown averaging, s (0.010) */
    double thiv_dx, thiv_dy; /* EN 1317-1's head to the interior, forward and to each side, m (0.6, 0.3) */
    double phd_window;       /* s (0.010) */
    double asi_window;       /* s (0.050) */
    double asi_limit[3];     /* ASI's limit accelerations, m/s^2 (12 g, 9 g, 10 g) */
} cs_occupant_rules;

cs_occupant_rules cs_default_occupant_rules(void);

/* Where an occupant (or head) meets the interior: in the record, after its end (the vehicle then taken
 * to go on at constant velocity: the occupant's relative velocity held), or never (no relative motion). */
typedef enum cs_flail_impact { CS_FLAIL_NONE = 0, CS_FLAIL_IN_RECORD, CS_FLAIL_AFTER_RECORD } cs_flail_impact;

typedef struct cs_occupant_risk {
    /* flail space (NCHRP Report 350, MASH) */
    cs_flail_impact impact;
    double t_impact;         /* s after the first contact */
    double oiv_x, oiv_y;     /* occupant impact velocity, m/s (magnitudes) */
    double ora_x, ora_y;     /* ridedown acceleration, g (magnitudes; 0 if the impact is after the record) */
    double t_ora_x, t_ora_y; /* start of the ridedown window, s after the first contact */
    /* EN 1317-1 */
    cs_flail_impact thiv_impact;
    double t_thiv; /* s after the first contact */
    double thiv;   /* theoretical head impact velocity, m/s */
    double phd;    /* post-impact head deceleration, g */
    double t_phd;  /* start of its window, s */
    double asi;    /* acceleration severity index (dimensionless) */
    double t_asi;  /* start of its window, s */
} cs_occupant_risk;

/* Occupant risk of a motion. CS_OK, or with err filled CS_ERR_INVALID (too few samples, a non-finite
 * sample, an interval too long for the filter) or CS_ERR_MEMORY. */
cs_status cs_occupant_risk_compute(const cs_vehicle_motion *m, const cs_occupant_rules *rules,
                                   cs_occupant_risk *out, cs_error *err);

/* The vehicle's motion of a run's record from its first contact (t_contact, s), resampled every dt by
 * linear interpolation, into arrays the caller frees with free(m->ax) (one block). Accelerations from the
 * world frame into the vehicle's by its roll, pitch and yaw; at point (x forward, y left, z up from the
 * CG in the vehicle's axes, m; NULL: the CG) the rigid body's a + alpha x r + omega x (omega x r), alpha
 * the change of the body-frame angular velocity between the frames either side. CS_OK, or with err filled
 * CS_ERR_INVALID (no contact, no frame after it) or CS_ERR_MEMORY. */
cs_status cs_vehicle_motion_of_record(const cs_record *rec, double t_contact, double dt, const double *point,
                                      cs_vehicle_motion *m, cs_error *err);

/* The largest |roll| and |pitch| of a record, rad. */
void cs_record_roll_pitch_peaks(const cs_record *rec, double *roll, double *pitch);

/* Occupant risk of a run (its record and first contact time) at point (NULL: the CG) with the default
 * rules, resampled at 0.1 ms. CS_OK, or as cs_vehicle_motion_of_record and cs_occupant_risk_compute (no
 * contact: the message says so). */
cs_status cs_occupant_risk_for_run(const cs_record *rec, double t_contact, const double *point,
                                   cs_occupant_risk *out, cs_error *err);

#endif
